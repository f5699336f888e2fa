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

impl BoxTree {
    /// The item with the smallest `hit` key among those whose boxes meet the
    /// rightward ray from `p` (the half-line y = p.y, x ≥ p.x), visiting
    /// nodes in order of their distance along the ray and stopping once no
    /// closer hit is possible. `hit` returns `(x, tie_break)` of the item's
    /// first crossing with the ray, or `None`; `x` must be ≥ the item box's
    /// `min.x`, which is what makes the early stop exact.
    pub fn first_hit_right(
        &self,
        p: crate::kernel::Point,
        mut hit: impl FnMut(usize) -> Option<(f64, f64)>,
    ) -> Option<(usize, f64)> {
        let meets = |b: &BBox| b.min.y <= p.y && p.y <= b.max.y && b.max.x >= p.x;
        let mut best: Option<(usize, (f64, f64))> = None;
        let beaten = |b: &BBox, best: &Option<(usize, (f64, f64))>| best.is_some_and(|(_, (bx, _))| b.min.x > bx);
        if !self.nodes.first().is_some_and(|n| meets(&n.bbox)) {
            return None;
        }
        // Depth-first, nearer child first, skipping subtrees that start
        // beyond the best hit so far; a fixed stack as in `visit_overlapping`.
        // Entries carry their node's min.x, so a subtree beaten while it
        // waited on the stack is dropped without touching its node.
        let mut stack = [(0u32, f64::NEG_INFINITY); 72];
        let mut top = 1;
        let beaten_at = |min_x: f64, best: &Option<(usize, (f64, f64))>| best.is_some_and(|(_, (bx, _))| min_x > bx);
        while top > 0 {
            top -= 1;
            let (id, min_x) = stack[top];
            if beaten_at(min_x, &best) {
                continue;
            }
            let node = self.nodes[id as usize];
            if node.leaf {
                for k in node.start as usize..node.end as usize {
                    let (b, i) = (&self.boxes[k], self.ids[k]);
                    if !meets(b) || beaten(b, &best) {
                        continue;
                    }
                    if let Some(h) = hit(i as usize) {
                        if best.is_none_or(|(_, bh)| h.0 < bh.0 || (h.0 == bh.0 && h.1 < bh.1)) {
                            best = Some((i as usize, h));
                        }
                    }
                }
            } else {
                let (l, r) = (node.start, node.end);
                let (lb, rb) = (&self.nodes[l as usize].bbox, &self.nodes[r as usize].bbox);
                // Push the farther child first so the nearer one is popped first.
                let ((near, nb), (far, fb)) =
                    if lb.min.x.max(p.x) <= rb.min.x.max(p.x) { ((l, lb), (r, rb)) } else { ((r, rb), (l, lb)) };
                for (c, b) in [(far, fb), (near, nb)] {
                    if meets(b) && !beaten(b, &best) {
                        stack[top] = (c, b.min.x);
                        top += 1;
                    }
                }
            }
        }
        best.map(|(i, (x, _))| (i, x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use rand::{Rng, SeedableRng};

    #[test]
    fn finds_exactly_the_overlapping_boxes() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(7);
        let boxes: Vec<BBox> = (0..2000)
            .map(|_| {
                let p = Point::new(rng.gen_range(0.0..100.0), rng.gen_range(0.0..100.0));
                BBox::of_points(p, p + Point::new(rng.gen_range(0.0..3.0), rng.gen_range(0.0..3.0)))
            })
            .collect();
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
}
