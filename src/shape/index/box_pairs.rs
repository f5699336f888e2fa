//! All pairs of items whose boxes overlap, by descending the box tree
//! against itself.
//!
//! Querying the tree once per item costs a root-to-leaf descent per item;
//! descending pairs of nodes instead shares that work between all items of
//! a leaf, and a pair of nodes whose boxes are apart is dismissed with all
//! the item pairs below it. The descent runs in parallel.

use crate::kernel::BBox;
use crate::shape::index::box_tree::BoxTree;
use std::sync::atomic::{AtomicUsize, Ordering};

/// More candidate pairs than the budget allowed were found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BudgetExceeded;

/// The answer with the smallest `(i, j)`, `i < j`.
type Best<P> = Option<(u32, u32, P)>;

/// Node pairs are split into parallel tasks down to this depth (about
/// 3^depth tasks, plenty for any thread count).
const PARALLEL_DEPTH: u32 = 9;

struct Join<'a, F> {
    tree: &'a BoxTree,
    pad: f64,
    visit: &'a F,
    count: AtomicUsize,
    budget: usize,
}

fn smaller<P>(a: Best<P>, b: Best<P>) -> Best<P> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if (a.0, a.1) <= (b.0, b.1) { a } else { b }),
        (a, None) => a,
        (None, b) => b,
    }
}

type Found<P> = Result<Best<P>, BudgetExceeded>;

impl<P: Send, F: Fn(usize, usize) -> Option<P> + Sync> Join<'_, F> {
    fn over_budget(&self) -> bool {
        self.count.load(Ordering::Relaxed) > self.budget
    }

    fn both<A: Send, B: Send>(&self, depth: u32, a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
        if depth < PARALLEL_DEPTH {
            rayon::join(a, b)
        } else {
            (a(), b())
        }
    }

    /// Pairs of items both below node `n`.
    fn within(&self, n: u32, depth: u32) -> Found<P> {
        if self.over_budget() {
            return Err(BudgetExceeded);
        }
        let node = self.tree.nodes[n as usize];
        if node.leaf {
            return self.leaves(n, n);
        }
        let ((l, r), c) = self.both(
            depth,
            || self.both(depth, || self.within(node.start, depth + 1), || self.within(node.end, depth + 1)),
            || self.across(node.start, node.end, depth + 1),
        );
        Ok(smaller(smaller(l?, r?), c?))
    }

    /// Pairs with one item below `a` and the other below `b` (disjoint subtrees).
    fn across(&self, a: u32, b: u32, depth: u32) -> Found<P> {
        if self.over_budget() {
            return Err(BudgetExceeded);
        }
        let (na, nb) = (self.tree.nodes[a as usize], self.tree.nodes[b as usize]);
        if !na.bbox.inflate(self.pad).overlaps(&nb.bbox) {
            return Ok(None);
        }
        if na.leaf && nb.leaf {
            return self.leaves(a, b);
        }
        let size = |b: &BBox| b.width() + b.height();
        // Split the larger node, so that both sides shrink together.
        let (split, keep) = if nb.leaf || (!na.leaf && size(&na.bbox) >= size(&nb.bbox)) { (na, b) } else { (nb, a) };
        let (x, y) =
            self.both(depth, || self.across(split.start, keep, depth + 1), || self.across(split.end, keep, depth + 1));
        Ok(smaller(x?, y?))
    }

    /// Item pairs between two leaves (or within one when `a == b`).
    fn leaves(&self, a: u32, b: u32) -> Found<P> {
        let t = self.tree;
        let (na, nb) = (t.nodes[a as usize], t.nodes[b as usize]);
        let mut best: Best<P> = None;
        let mut count = 0;
        for ka in na.start as usize..na.end as usize {
            let boxa = t.boxes[ka].inflate(self.pad);
            let from = if a == b { ka + 1 } else { nb.start as usize };
            for kb in from..nb.end as usize {
                if !boxa.overlaps(&t.boxes[kb]) {
                    continue;
                }
                count += 1;
                let (i, j) = (t.ids[ka].min(t.ids[kb]), t.ids[ka].max(t.ids[kb]));
                // A pair that cannot beat the one in hand needs no test.
                if best.as_ref().is_some_and(|b| (b.0, b.1) < (i, j)) {
                    continue;
                }
                if let Some(p) = (self.visit)(i as usize, j as usize) {
                    best = Some((i, j, p));
                }
            }
        }
        if self.count.fetch_add(count, Ordering::Relaxed) + count > self.budget {
            return Err(BudgetExceeded);
        }
        Ok(best)
    }
}

impl BoxTree {
    /// Calls `visit(i, j)` with `i < j` for pairs of items whose boxes come
    /// within `pad` of each other (each box's gap to the other at most `pad`
    /// in x and in y), in parallel, and returns the answer with the smallest
    /// `(i, j)`; pairs that cannot beat an answer already found may be
    /// skipped.
    ///
    /// With a `budget`, gives up with `BudgetExceeded` once more than that
    /// many overlapping pairs were seen. The pair count is a property of the
    /// input, so whether the budget runs out does not depend on scheduling.
    pub fn min_overlapping_pair<P: Send>(
        &self,
        pad: f64,
        budget: Option<usize>,
        visit: impl Fn(usize, usize) -> Option<P> + Sync,
    ) -> Result<Option<(usize, usize, P)>, BudgetExceeded> {
        if self.nodes.is_empty() {
            return Ok(None);
        }
        let join =
            Join { tree: self, pad, visit: &visit, count: AtomicUsize::new(0), budget: budget.unwrap_or(usize::MAX) };
        Ok(join.within(0, 0)?.map(|(i, j, p)| (i as usize, j as usize, p)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use rand::{Rng, SeedableRng};

    fn near(a: &BBox, b: &BBox, pad: f64) -> bool {
        a.inflate(pad).overlaps(b)
    }

    #[test]
    fn finds_the_smallest_pair_and_counts_every_overlap() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(11);
        for round in 0..20 {
            let n = 50 + round * 150;
            let boxes: Vec<BBox> = (0..n)
                .map(|_| {
                    let p = Point::new(rng.gen_range(0.0..100.0), rng.gen_range(0.0..100.0));
                    BBox::of_points(p, p + Point::new(rng.gen_range(0.0..4.0), rng.gen_range(0.0..4.0)))
                })
                .collect();
            let tree = BoxTree::new(boxes.clone());
            let pad = 0.1;
            let mut all = Vec::new();
            for i in 0..n {
                for j in i + 1..n {
                    if near(&boxes[i], &boxes[j], pad) {
                        all.push((i, j));
                    }
                }
            }
            // Answer only for pairs whose ids sum to a multiple of 7.
            let pick = |i: usize, j: usize| ((i + j) % 7 == 0).then_some(i * n + j);
            let want = all.iter().copied().find(|&(i, j)| pick(i, j).is_some());
            let got = tree.min_overlapping_pair(pad, None, pick).unwrap();
            assert_eq!(got.map(|(i, j, _)| (i, j)), want);
            if let Some((i, j, p)) = got {
                assert_eq!(p, i * n + j);
            }
            // Every overlapping pair is visited exactly once when none answers.
            let seen = std::sync::Mutex::new(Vec::new());
            let none = tree.min_overlapping_pair::<()>(pad, None, |i, j| {
                seen.lock().unwrap().push((i, j));
                None
            });
            assert_eq!(none, Ok(None));
            let mut seen = seen.into_inner().unwrap();
            seen.sort_unstable();
            assert_eq!(seen, all);
            assert_eq!(tree.min_overlapping_pair::<()>(pad, Some(all.len()), |_, _| None), Ok(None));
            if !all.is_empty() {
                let short = tree.min_overlapping_pair::<()>(pad, Some(all.len() - 1), |_, _| None);
                assert_eq!(short, Err(BudgetExceeded));
            }
        }
    }
}
