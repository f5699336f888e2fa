//! Nearest-element queries along a boundary: a hierarchy over runs of
//! consecutive elements, each run bounded by a capsule (its chord, widened
//! by how far the run strays from it) and by its box.
//!
//! Why not boxes: the questions medax asks most are about maximal disks,
//! whose circles run tangent to the boundary at their footpoints. There
//! the boundary stays within x²·Δκ/2 of the circle for a stretch of
//! length x, so every box of nearby elements comes within its own size of
//! the disk and none can be pruned (measured: hundreds of elements per
//! query on smooth shapes of 10^5 arcs). A run's capsule comes within the
//! run's sagitta instead, which shrinks with the square of its length:
//! near a footpoint only a few short runs need opening.

use super::box_tree::Pending;
use super::bulge_loop::Loop;
use super::element::Element;
use super::error::ElementRef;
use crate::kernel::{BBox, Point};

/// Elements per leaf run: short enough that a leaf's capsule is tight,
/// long enough that the tree costs little memory (about 24 bytes per
/// element).
const LEAF: usize = 8;

#[derive(Debug, Clone, Copy)]
struct Node {
    /// Chord: the start of the run's first element and the end of its last.
    a: Point,
    b: Point,
    /// Every point of the run lies within this distance of the chord.
    reach: f64,
    /// And within this box (the better bound where the run zigzags).
    bbox: BBox,
    /// Loop and element range [lo, hi).
    lp: u32,
    lo: u32,
    hi: u32,
    /// Children (inner nodes), or `u32::MAX` for a leaf.
    left: u32,
    right: u32,
}

/// The hierarchy over every loop of a shape (one root per loop). Built in
/// O(n); immutable and `Sync`.
#[derive(Debug, Clone, Default)]
pub struct ChainTree {
    nodes: Vec<Node>,
    roots: Vec<u32>,
}

/// Distance from `p` to the segment `a`–`b`.
fn segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let l2 = d.norm2();
    let t = if l2 > 0.0 { ((p - a).dot(d) / l2).clamp(0.0, 1.0) } else { 0.0 };
    p.dist(a + d * t)
}

/// How far the element strays from the segment `a`–`b` at most: its
/// points lie within its sagitta of its own chord (for sweeps up to π;
/// within its diameter beyond), and distance to a segment is convex.
fn element_reach(e: &Element, a: Point, b: Point) -> f64 {
    let ends = segment_distance(e.start(), a, b).max(segment_distance(e.end(), a, b));
    let off = match e {
        Element::Segment(_) => 0.0,
        Element::Arc(arc) if arc.bulge.abs() <= 1.0 => e.sagitta(),
        Element::Arc(arc) => 2.0 * arc.radius,
    };
    ends + off
}

impl ChainTree {
    /// Builds the hierarchy over `loops`.
    pub fn new(loops: &[Loop]) -> ChainTree {
        let mut t = ChainTree::default();
        for (l, lp) in loops.iter().enumerate() {
            if lp.is_empty() {
                continue;
            }
            let root = t.build(lp, l as u32, 0, lp.len());
            t.roots.push(root);
        }
        t
    }

    /// How much wider than long the leaf runs are: the sum of their
    /// reaches over the sum of their chord lengths. Small (≪ 1) for smooth
    /// or straight boundaries, where capsules prune well; large where the
    /// boundary zigzags (dense spikes), where boxes do better.
    pub fn zigzag(&self) -> f64 {
        let (mut reach, mut chord) = (0.0, 0.0);
        for n in self.nodes.iter().filter(|n| n.left == u32::MAX) {
            reach += n.reach;
            chord += n.a.dist(n.b);
        }
        if chord > 0.0 {
            reach / chord
        } else {
            f64::INFINITY
        }
    }

    fn build(&mut self, lp: &Loop, l: u32, lo: usize, hi: usize) -> u32 {
        let (a, b) = (lp.element(lo).start(), lp.element(hi - 1).end());
        let mut node = Node {
            a,
            b,
            reach: 0.0,
            bbox: BBox::EMPTY,
            lp: l,
            lo: lo as u32,
            hi: hi as u32,
            left: u32::MAX,
            right: u32::MAX,
        };
        if hi - lo <= LEAF {
            node.reach = (lo..hi).map(|i| element_reach(&lp.element(i), a, b)).fold(0.0, f64::max);
            node.bbox = (lo..hi).fold(BBox::EMPTY, |bb, i| bb.union(&lp.element(i).bbox()));
        } else {
            let mid = lo + (hi - lo) / 2;
            let (left, right) = (self.build(lp, l, lo, mid), self.build(lp, l, mid, hi));
            // A child's points lie within its reach of its chord, whose
            // points lie within the larger end distance of this chord.
            let around = |c: &Node| segment_distance(c.a, a, b).max(segment_distance(c.b, a, b)) + c.reach;
            let (l, r) = (&self.nodes[left as usize], &self.nodes[right as usize]);
            node.reach = around(l).max(around(r));
            node.bbox = l.bbox.union(&r.bbox);
            node.left = left;
            node.right = right;
        }
        self.nodes.push(node);
        (self.nodes.len() - 1) as u32
    }

    /// The element of `loops` (the ones the tree was built from) nearest
    /// to `p`, and its distance (model units); the first in loop and
    /// element order among equals. `None` for a shape without elements.
    pub fn nearest(&self, loops: &[Loop], p: Point) -> Option<(ElementRef, f64)> {
        let bound = |n: &Node| (segment_distance(p, n.a, n.b) - n.reach).max(n.bbox.distance_to(p));
        let mut heap = std::collections::BinaryHeap::with_capacity(64);
        for &r in &self.roots {
            heap.push(Pending(bound(&self.nodes[r as usize]), r));
        }
        let mut best: Option<(ElementRef, f64)> = None;
        while let Some(Pending(b, id)) = heap.pop() {
            if best.is_some_and(|(_, d)| b >= d) {
                break;
            }
            let n = self.nodes[id as usize];
            if n.left == u32::MAX {
                let lp = &loops[n.lp as usize];
                for i in n.lo as usize..n.hi as usize {
                    let d = lp.element(i).closest_point(p).0;
                    let r = ElementRef { loop_index: n.lp as usize, element: i };
                    if best.is_none_or(|(br, bd)| d < bd || (d == bd && r < br)) {
                        best = Some((r, d));
                    }
                }
            } else {
                for c in [n.left, n.right] {
                    let cb = bound(&self.nodes[c as usize]);
                    if best.is_none_or(|(_, d)| cb < d) {
                        heap.push(Pending(cb, c));
                    }
                }
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{samples, Shape2d, ShapeOptions};

    #[test]
    fn nearest_agrees_with_a_scan() {
        let mut rng = samples::Mix(7);
        for loops in [samples::flower_arcs(500), samples::star_polygon(300, 2)] {
            let s = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
            let t = ChainTree::new(s.loops());
            let bb = s.bbox();
            for _ in 0..500 {
                let p = Point::new(
                    bb.min.x + rng.next() * (bb.max.x - bb.min.x),
                    bb.min.y + rng.next() * (bb.max.y - bb.min.y),
                );
                let scan = s.loops()[0].elements().map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min);
                let (_, d) = t.nearest(s.loops(), p).unwrap();
                assert_eq!(d, scan, "{p:?}");
            }
        }
    }
}
