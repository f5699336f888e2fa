//! A static bounding-volume hierarchy over axis-aligned boxes.
//!
//! Items are sorted along a Morton (Z-order) curve of their box centres and
//! the sorted range is split in halves, so the tree is balanced (depth
//! ⌈log2(n / LEAF)⌉) and building is one sort: O(n log n). A query visits the
//! nodes whose boxes overlap the query box; for the boundaries medax sees
//! (elements that are short relative to the shape) that is O(log n + k).

use crate::kernel::BBox;
use rayon::prelude::*;
use std::ops::ControlFlow;

const LEAF: usize = 8;

#[derive(Debug, Clone, Copy)]
pub(super) struct Node {
    pub bbox: BBox,
    /// Leaf: range [start, end) of tree positions. Inner: children at `start`, `end`.
    pub start: u32,
    pub end: u32,
    pub leaf: bool,
}

/// Bounding-volume hierarchy over item boxes; item ids are the indices of
/// the slice it was built from.
///
/// Boxes are stored in tree order (a leaf's boxes are contiguous), because
/// queries scan leaves and the scan should not jump around in memory.
#[derive(Debug, Clone, Default)]
pub struct BoxTree {
    pub(super) nodes: Vec<Node>,
    /// Item id at each tree position.
    pub(super) ids: Vec<u32>,
    /// Box at each tree position.
    pub(super) boxes: Vec<BBox>,
    /// Tree position of each item id.
    rank: Vec<u32>,
}

fn spread_bits(v: u32) -> u64 {
    let mut x = v as u64 & 0xffff_ffff;
    x = (x | (x << 16)) & 0x0000_ffff_0000_ffff;
    x = (x | (x << 8)) & 0x00ff_00ff_00ff_00ff;
    x = (x | (x << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
    x = (x | (x << 2)) & 0x3333_3333_3333_3333;
    x = (x | (x << 1)) & 0x5555_5555_5555_5555;
    x
}

impl BoxTree {
    /// Builds the tree. Item ids must fit in `u32` (at most 2^32 − 1 items).
    pub fn new(boxes: Vec<BBox>) -> BoxTree {
        let n = boxes.len();
        let all = boxes.iter().fold(BBox::EMPTY, |a, b| a.union(b));
        let (w, h) = (all.width().max(f64::MIN_POSITIVE), all.height().max(f64::MIN_POSITIVE));
        let scale = |v: f64, lo: f64, ext: f64| (((v - lo) / ext).clamp(0.0, 1.0) * 65535.0) as u32;
        let mut keyed: Vec<(u64, u32)> = boxes
            .par_iter()
            .enumerate()
            .map(|(i, b)| {
                let c = b.center();
                let key = spread_bits(scale(c.x, all.min.x, w)) | (spread_bits(scale(c.y, all.min.y, h)) << 1);
                (key, i as u32)
            })
            .collect();
        keyed.par_sort_unstable();
        let ids: Vec<u32> = keyed.par_iter().map(|&(_, i)| i).collect();
        let mut rank = vec![0u32; n];
        for (k, &i) in ids.iter().enumerate() {
            rank[i as usize] = k as u32;
        }
        let boxes = ids.par_iter().map(|&i| boxes[i as usize]).collect();
        let mut tree = BoxTree { nodes: Vec::with_capacity(2 * n / LEAF + 2), ids, boxes, rank };
        if n > 0 {
            tree.build(0, n);
        }
        tree
    }

    fn build(&mut self, start: usize, end: usize) -> u32 {
        let id = self.nodes.len() as u32;
        if end - start <= LEAF {
            let bbox = self.boxes[start..end].iter().fold(BBox::EMPTY, |a, b| a.union(b));
            self.nodes.push(Node { bbox, start: start as u32, end: end as u32, leaf: true });
            return id;
        }
        self.nodes.push(Node { bbox: BBox::EMPTY, start: 0, end: 0, leaf: false });
        let mid = start + (end - start) / 2;
        let l = self.build(start, mid);
        let r = self.build(mid, end);
        let bbox = self.nodes[l as usize].bbox.union(&self.nodes[r as usize].bbox);
        self.nodes[id as usize] = Node { bbox, start: l, end: r, leaf: false };
        id
    }

    /// Number of items.
    pub fn len(&self) -> usize {
        self.boxes.len()
    }

    /// True when the tree holds no item.
    pub fn is_empty(&self) -> bool {
        self.boxes.is_empty()
    }

    /// The box of item `i`.
    pub fn item_box(&self, i: usize) -> &BBox {
        &self.boxes[self.rank[i] as usize]
    }

    /// The leaves in tree order: each leaf's box and the ids of its items
    /// (at most 8, close together), for batching queries of nearby items.
    pub fn leaves(&self) -> impl Iterator<Item = (&BBox, &[u32])> + '_ {
        self.nodes.iter().filter(|n| n.leaf).map(|n| (&n.bbox, &self.ids[n.start as usize..n.end as usize]))
    }

    /// The box around all items (empty for an empty tree).
    pub fn bounds(&self) -> BBox {
        self.nodes.first().map(|n| n.bbox).unwrap_or(BBox::EMPTY)
    }

    /// Calls `f` with each item whose box overlaps `query` (closed boxes),
    /// in no particular order, until `f` breaks.
    pub fn visit_overlapping<B>(&self, query: &BBox, mut f: impl FnMut(usize) -> ControlFlow<B>) -> Option<B> {
        if self.nodes.is_empty() {
            return None;
        }
        // The tree is balanced (depth ≤ log2(n) + 1 < 64 for any u32 count)
        // and holds at most depth + 1 pending nodes, so a fixed array serves
        // as the stack: no allocation per query.
        let mut stack = [0u32; 72];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let id = stack[top];
            let node = &self.nodes[id as usize];
            if !node.bbox.overlaps(query) {
                continue;
            }
            if node.leaf {
                for k in node.start as usize..node.end as usize {
                    if self.boxes[k].overlaps(query) {
                        if let ControlFlow::Break(b) = f(self.ids[k] as usize) {
                            return Some(b);
                        }
                    }
                }
            } else {
                stack[top] = node.end;
                stack[top + 1] = node.start;
                top += 2;
            }
        }
        None
    }
}

/// A node waiting in a best-first search, ordered by its bound with the
/// smallest on top of a max-heap; incomparable bounds count as equal.
pub(super) struct Pending<K>(pub(super) K, pub(super) u32);

impl<K: PartialOrd> PartialEq for Pending<K> {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == std::cmp::Ordering::Equal
    }
}

impl<K: PartialOrd> Eq for Pending<K> {}

impl<K: PartialOrd> PartialOrd for Pending<K> {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}

impl<K: PartialOrd> Ord for Pending<K> {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        o.0.partial_cmp(&self.0).unwrap_or(std::cmp::Ordering::Equal)
    }
}

impl BoxTree {
    /// Branch and bound: the item with the smallest key, where `bound(box)`
    /// is a lower bound on the keys of all items inside the node box `box`
    /// (`None`: none of them can have a key) and `key(item, item_box)` is
    /// the item's key (`None`: no key); an item's own box is bounded first
    /// and the key computed only when that bound is below the best so far.
    /// Nodes are expanded best-first (smallest bound first, from a
    /// heap) and the search stops once the smallest pending bound is not
    /// below the best key found, so the answer is exact when the bounds are,
    /// and only nodes whose bound is below the answer are expanded. Ties
    /// keep the first item found.
    pub fn min_by_bound<K: PartialOrd + Copy>(
        &self,
        bound: impl Fn(&BBox) -> Option<K>,
        mut key: impl FnMut(usize, &BBox) -> Option<K>,
    ) -> Option<(usize, K)> {
        let root_bound = bound(&self.nodes.first()?.bbox)?;
        let mut best: Option<(usize, K)> = None;
        // Not below the best (incomparable keys count as not below).
        let beaten = |b: &K, best: &Option<(usize, K)>| {
            best.as_ref().is_some_and(|(_, k)| b.partial_cmp(k) != Some(std::cmp::Ordering::Less))
        };
        let mut heap = std::collections::BinaryHeap::with_capacity(64);
        heap.push(Pending(root_bound, 0));
        while let Some(Pending(b, id)) = heap.pop() {
            if beaten(&b, &best) {
                break;
            }
            let node = self.nodes[id as usize];
            if node.leaf {
                for k in node.start as usize..node.end as usize {
                    // An item lies in its own box: the bound holds for it
                    // too, and is much cheaper than most keys.
                    if bound(&self.boxes[k]).is_none_or(|b| beaten(&b, &best)) {
                        continue;
                    }
                    let i = self.ids[k] as usize;
                    if let Some(v) = key(i, &self.boxes[k]) {
                        if best.as_ref().is_none_or(|(_, k)| v < *k) {
                            best = Some((i, v));
                        }
                    }
                }
            } else {
                for c in [node.start, node.end] {
                    if let Some(b) = bound(&self.nodes[c as usize].bbox) {
                        if !beaten(&b, &best) {
                            heap.push(Pending(b, c));
                        }
                    }
                }
            }
        }
        best
    }

    /// The item with the smallest `hit` key among those whose boxes meet the
    /// rightward ray from `p` (the half-line y = p.y, x ≥ p.x). `hit` returns
    /// `(x, tie_break)` of the item's first crossing with the ray, or `None`;
    /// `x` must be ≥ the item box's `min.x`, which is what makes the early
    /// stop exact.
    pub fn first_hit_right(
        &self,
        p: crate::kernel::Point,
        mut hit: impl FnMut(usize) -> Option<(f64, f64)>,
    ) -> Option<(usize, f64)> {
        let meets = |b: &BBox| b.min.y <= p.y && p.y <= b.max.y && b.max.x >= p.x;
        let bound = |b: &BBox| meets(b).then_some((b.min.x.max(p.x), f64::NEG_INFINITY));
        self.min_by_bound(bound, |i, b| if meets(b) { hit(i) } else { None }).map(|(i, (x, _))| (i, x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use rand::{Rng, SeedableRng};

    /// `n` boxes in [0, 100]² with sides up to `size`.
    fn random_boxes(rng: &mut impl Rng, n: usize, size: f64) -> Vec<BBox> {
        (0..n)
            .map(|_| {
                let p = Point::new(rng.gen_range(0.0..100.0), rng.gen_range(0.0..100.0));
                BBox::of_points(p, p + Point::new(rng.gen_range(0.0..size), rng.gen_range(0.0..size)))
            })
            .collect()
    }

    #[test]
    fn finds_exactly_the_overlapping_boxes() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(7);
        let boxes = random_boxes(&mut rng, 2000, 3.0);
        let tree = BoxTree::new(boxes.clone());
        for _ in 0..200 {
            let p = Point::new(rng.gen_range(-5.0..100.0), rng.gen_range(-5.0..100.0));
            let q = BBox::of_points(p, p + Point::new(rng.gen_range(0.0..10.0), rng.gen_range(0.0..10.0)));
            let mut got = Vec::new();
            tree.visit_overlapping::<()>(&q, |i| {
                got.push(i);
                ControlFlow::Continue(())
            });
            got.sort_unstable();
            let want: Vec<usize> = (0..boxes.len()).filter(|&i| boxes[i].overlaps(&q)).collect();
            assert_eq!(got, want);
        }
    }

    #[test]
    fn branch_and_bound_finds_the_nearest_box_centre() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(5);
        let boxes = random_boxes(&mut rng, 3000, 2.0);
        let tree = BoxTree::new(boxes.clone());
        for _ in 0..300 {
            let q = Point::new(rng.gen_range(-10.0..110.0), rng.gen_range(-10.0..110.0));
            // Distance from q to a box: a lower bound on the distance to its centre.
            let to_box = |b: &BBox| Some(b.distance_to(q));
            let mut calls = 0;
            let got = tree.min_by_bound(to_box, |i, _| {
                calls += 1;
                Some(boxes[i].center().dist(q))
            });
            let want = (0..boxes.len()).map(|i| boxes[i].center().dist(q)).fold(f64::INFINITY, f64::min);
            assert_eq!(got.map(|g| g.1), Some(want));
            assert!(calls < 200, "{calls} keys computed: the bounds should prune");
        }
    }
}
