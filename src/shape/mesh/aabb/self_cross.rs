//! Exact self-intersections of a surface: every pair of triangles that
//! meet other than where a closed surface's triangles must (at the
//! corners they share), found by descending the tree against itself over
//! overlapping boxes, the independent subtrees in parallel.
//!
//! A node against itself splits into its two children against
//! themselves and against each other; two nodes whose boxes overlap
//! split the larger one. So only pairs of nearby triangles are ever
//! tested: for a surface of well-shaped triangles, O(n log n) box tests
//! and O(n) triangle tests.

use super::{Node, TriangleTree};
use crate::kernel::tri_tri::surface_triangles_overlap;
use crate::kernel::BBox3;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Splits above this depth run as parallel tasks: a few thousand tasks
/// balance two to a few dozen threads without drowning in task overhead.
const PARALLEL_DEPTH: u32 = 10;

/// The pairs found so far, shared by the tasks.
struct Found {
    pairs: Mutex<Vec<(u32, u32)>>,
    count: AtomicUsize,
    limit: usize,
}

impl Found {
    fn full(&self) -> bool {
        self.count.load(Ordering::Relaxed) >= self.limit
    }

    fn add(&self, a: u32, b: u32) {
        self.count.fetch_add(1, Ordering::Relaxed);
        self.pairs.lock().unwrap_or_else(|e| e.into_inner()).push((a.min(b), a.max(b)));
    }
}

impl TriangleTree {
    /// The pairs of triangles that meet, exactly, up to `limit` of them:
    /// triangles sharing no vertex when they touch at all
    /// ([`crate::kernel::tri_tri::triangles_intersect`]); triangles
    /// sharing one or two vertices (by index) when they meet anywhere
    /// else ([`crate::kernel::tri_tri::adjacent_triangles_overlap`]).
    /// Each pair is `(smaller index, larger index)`, sorted. When more
    /// than `limit` pairs exist, which ones are returned is unspecified.
    /// A closed surface without self-intersections gives none.
    pub fn self_intersections(&self, limit: usize) -> Vec<(u32, u32)> {
        if self.nodes.is_empty() || limit == 0 {
            return Vec::new();
        }
        let found = Found { pairs: Mutex::new(Vec::new()), count: AtomicUsize::new(0), limit };
        self.within(0, 0, &found);
        let mut pairs = found.pairs.into_inner().unwrap_or_else(|e| e.into_inner());
        pairs.sort_unstable();
        pairs.truncate(limit);
        pairs
    }

    /// Pairs inside the subtree at `at`.
    fn within(&self, at: u32, depth: u32, found: &Found) {
        if found.full() {
            return;
        }
        let node = &self.nodes[at as usize];
        if node.is_leaf() {
            let boxes = self.leaf_boxes(node);
            let range = node.range();
            for (i, k) in range.clone().enumerate() {
                for (j, l) in range.clone().enumerate().skip(i + 1) {
                    if boxes[i].overlaps(&boxes[j]) {
                        self.test(k, l, found);
                    }
                }
            }
            return;
        }
        let (left, right) = (at + 1, node.index);
        if depth < PARALLEL_DEPTH {
            rayon::join(
                || rayon::join(|| self.within(left, depth + 1, found), || self.within(right, depth + 1, found)),
                || self.between(left, right, depth + 1, found),
            );
        } else {
            self.within(left, depth + 1, found);
            self.within(right, depth + 1, found);
            self.between(left, right, depth + 1, found);
        }
    }

    /// Pairs with one triangle under node `a`, the other under node `b`
    /// (disjoint subtrees).
    fn between(&self, a: u32, b: u32, depth: u32, found: &Found) {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        if found.full() || !na.bbox.overlaps(&nb.bbox) {
            return;
        }
        if na.is_leaf() && nb.is_leaf() {
            self.leaf_pairs(na, nb, found);
            return;
        }
        let size = |n: &Node| (n.bbox.max - n.bbox.min).norm2();
        // Split the inner node, the larger one when both are.
        let (split, other) = if nb.is_leaf() || (!na.is_leaf() && size(na) >= size(nb)) { (a, b) } else { (b, a) };
        let (first, second) = (split + 1, self.nodes[split as usize].index);
        if depth < PARALLEL_DEPTH {
            rayon::join(
                || self.between(first, other, depth + 1, found),
                || self.between(second, other, depth + 1, found),
            );
        } else {
            self.between(first, other, depth + 1, found);
            self.between(second, other, depth + 1, found);
        }
    }

    fn leaf_boxes(&self, leaf: &Node) -> [BBox3; super::LEAF] {
        let mut boxes = [BBox3::EMPTY; super::LEAF];
        for (b, k) in boxes.iter_mut().zip(leaf.range()) {
            *b = BBox3::of(self.corners(k));
        }
        boxes
    }

    fn leaf_pairs(&self, a: &Node, b: &Node, found: &Found) {
        let boxes = self.leaf_boxes(b);
        for k in a.range() {
            let bk = BBox3::of(self.corners(k));
            if !bk.overlaps(&b.bbox) {
                continue;
            }
            for (j, l) in b.range().enumerate() {
                if bk.overlaps(&boxes[j]) {
                    self.test(k, l, found);
                }
            }
        }
    }

    /// Tests the triangles at tree positions `k` and `l`.
    fn test(&self, k: usize, l: usize, found: &Found) {
        let (tk, tl) = (self.triangles[k], self.triangles[l]);
        if surface_triangles_overlap(self.corners(k), tk, self.corners(l), tl) {
            found.add(self.ids[k], self.ids[l]);
        }
    }
}
