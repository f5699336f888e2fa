//! Nearest-element queries along a boundary: a hierarchy over runs of
//! consecutive elements, each run bounded by a capsule (its chord, widened
//! by how far the run strays from it), by its box, and by a box along its
//! principal direction.
//!
//! Why not boxes: the questions medax asks most are about maximal disks,
//! whose circles run tangent to the boundary at their footpoints. There
//! the boundary stays within x²·Δκ/2 of the circle for a stretch of
//! length x, so every box of nearby elements comes within its own size of
//! the disk and none can be pruned (measured: hundreds of elements per
//! query on smooth shapes of 10^5 arcs). A run's capsule comes within the
//! run's sagitta instead, which shrinks with the square of its length:
//! near a footpoint only a few short runs need opening. Among dense narrow
//! spikes (random star polygons, combs) a point lies in the boxes of a
//! fiftieth of all elements, and a run's capsule is as wide as its spikes
//! are long; but consecutive spikes lie side by side, so the run's box
//! along its principal direction is as thin as the run (measured: axes 3×
//! faster on stars of 3·10^4 vertices, 6× on combs of 2·10^4).

use crate::kernel::element::Element;
use crate::kernel::growing_disk::GrowingDisk;
use crate::kernel::{BBox, Point};
use crate::shape::index::box_tree::Pending;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ElementRef;
use crate::util::small_stack::SmallStack;

/// Elements per leaf run: short enough that a leaf's capsule is tight,
/// long enough that the tree costs little memory (a node is 144 bytes and
/// there are about n/4 of them: 36 bytes per element).
const LEAF: usize = 8;

/// Entries of a walk's stack kept inline: the tree's depth and more (a
/// shape of many loops pushes a root per loop, and spills).
const WALK_STACK: usize = 24;

#[derive(Debug, Clone, Copy)]
struct Node {
    /// Chord: the start of the run's first element and the end of its last.
    a: Point,
    b: Point,
    /// Every point of the run lies within this distance of the chord.
    reach: f64,
    /// And within this box.
    bbox: BBox,
    /// And within this oriented box: projections on the unit axis `u`
    /// (the run's principal direction) and on its normal. Where the
    /// boundary zigzags in narrow spikes, the spikes of a run lie side by
    /// side along one direction, and this box is as thin as the run.
    obb: Oriented,
    /// Loop and element range [lo, hi).
    lp: u32,
    lo: u32,
    hi: u32,
    /// Children (inner nodes), or `u32::MAX` for a leaf.
    left: u32,
    right: u32,
}

impl Node {
    /// A lower bound on the distance from `p` to every element of the run
    /// when it is below `d`, else `None`: decided with squares and the
    /// cheapest test first (most runs a query meets are pruned by their
    /// box), the square roots taken only for a run that stays.
    fn bound_below(&self, p: Point, d: f64) -> Option<f64> {
        if d <= 0.0 {
            return None;
        }
        let d2 = d * d;
        let b = self.bbox.distance2_to(p);
        if b >= d2 {
            return None;
        }
        let o = self.obb.distance2_to(p);
        if o >= d2 {
            return None;
        }
        let s = segment_distance2(p, self.a, self.b);
        let capsule = d + self.reach;
        (s < capsule * capsule).then(|| (s.sqrt() - self.reach).max(b.max(o).sqrt()))
    }

    /// True when some element of the run may come closer to `p` than
    /// `d`: [`bound_below`](Self::bound_below)'s tests without the square
    /// roots of the bound itself, for the walks that only ask whether to
    /// open a run (two square roots were a third of a test's cost).
    fn may_reach(&self, p: Point, d: f64) -> bool {
        if d <= 0.0 {
            return false;
        }
        let d2 = d * d;
        if self.bbox.distance2_to(p) >= d2 || self.obb.distance2_to(p) >= d2 {
            return false;
        }
        let capsule = d + self.reach;
        segment_distance2(p, self.a, self.b) < capsule * capsule
    }

    /// The elements of the run.
    fn elements(&self) -> impl Iterator<Item = ElementRef> {
        let loop_index = self.lp as usize;
        (self.lo as usize..self.hi as usize).map(move |element| ElementRef { loop_index, element })
    }
}

/// A box with sides along a unit axis `u` and its normal: the points `x`
/// with `u·x` in `[lo.x, hi.x]` and `u.perp()·x` in `[lo.y, hi.y]`.
#[derive(Debug, Clone, Copy)]
struct Oriented {
    u: Point,
    lo: Point,
    hi: Point,
}

impl Oriented {
    const EMPTY: Oriented = Oriented {
        u: Point { x: 1.0, y: 0.0 },
        lo: Point { x: f64::INFINITY, y: f64::INFINITY },
        hi: Point { x: f64::NEG_INFINITY, y: f64::NEG_INFINITY },
    };

    fn along(u: Point) -> Oriented {
        Oriented { u, ..Oriented::EMPTY }
    }

    /// Coordinates of `p` in the box's frame.
    fn frame(&self, p: Point) -> Point {
        Point::new(self.u.dot(p), self.u.perp().dot(p))
    }

    /// Widens the box to hold the disk (`p`, `r`).
    fn add(&mut self, p: Point, r: f64) {
        let q = self.frame(p);
        self.lo = Point::new(self.lo.x.min(q.x - r), self.lo.y.min(q.y - r));
        self.hi = Point::new(self.hi.x.max(q.x + r), self.hi.y.max(q.y + r));
    }

    /// Widens the box to hold element `e`: its end points, widened by its
    /// sagitta (an arc of at most a half turn lies within its sagitta of
    /// its chord), or the whole circle of a larger arc.
    fn add_element(&mut self, e: &Element) {
        match e {
            Element::Arc(arc) if arc.bulge.abs() > 1.0 => self.add(arc.center, arc.radius),
            _ => {
                let w = e.sagitta();
                self.add(e.start(), w);
                self.add(e.end(), w);
            }
        }
    }

    /// Widens the box to hold another one (its four corners).
    fn add_box(&mut self, o: &Oriented) {
        let (u, v) = (o.u, o.u.perp());
        for (x, y) in [(o.lo.x, o.lo.y), (o.lo.x, o.hi.y), (o.hi.x, o.lo.y), (o.hi.x, o.hi.y)] {
            self.add(u * x + v * y, 0.0);
        }
    }

    /// Squared distance from `p` to the box (0 inside).
    fn distance2_to(&self, p: Point) -> f64 {
        let q = self.frame(p);
        let dx = (self.lo.x - q.x).max(q.x - self.hi.x).max(0.0);
        let dy = (self.lo.y - q.y).max(q.y - self.hi.y).max(0.0);
        dx * dx + dy * dy
    }
}

/// Running sums of points, for their principal direction.
#[derive(Debug, Clone, Copy, Default)]
struct Spread {
    n: f64,
    s: Point,
    xx: f64,
    xy: f64,
    yy: f64,
}

impl Spread {
    fn add(&mut self, p: Point) {
        self.n += 1.0;
        self.s = self.s + p;
        self.xx += p.x * p.x;
        self.xy += p.x * p.y;
        self.yy += p.y * p.y;
    }

    fn merge(&self, o: &Spread) -> Spread {
        Spread { n: self.n + o.n, s: self.s + o.s, xx: self.xx + o.xx, xy: self.xy + o.xy, yy: self.yy + o.yy }
    }

    /// The unit direction of largest spread (any, for a single point).
    fn axis(&self) -> Point {
        if self.n < 2.0 {
            return Point::new(1.0, 0.0);
        }
        let m = self.s * (1.0 / self.n);
        let (cxx, cxy, cyy) =
            (self.xx / self.n - m.x * m.x, self.xy / self.n - m.x * m.y, self.yy / self.n - m.y * m.y);
        let t = 0.5 * (2.0 * cxy).atan2(cxx - cyy);
        Point::new(t.cos(), t.sin())
    }
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
    segment_distance2(p, a, b).sqrt()
}

/// Squared distance from `p` to the segment `a`–`b`.
fn segment_distance2(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let l2 = d.norm2();
    let t = if l2 > 0.0 { ((p - a).dot(d) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + d * t)).norm2()
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
            let (root, _) = t.build(lp, l as u32, 0, lp.len());
            t.roots.push(root);
        }
        // Many loops (a plate with 10^5 holes): one hierarchy over the
        // loops' roots, so that a query does not visit every loop.
        if t.roots.len() > 2 {
            let mut roots = std::mem::take(&mut t.roots);
            let top = t.group(&mut roots);
            t.roots.push(top);
        }
        t
    }

    /// A node over the loop roots `ids`, split at the median of their box
    /// centres along the wider side. Its chord is the point at its box's
    /// centre, its reach the distance to the farthest child point it
    /// bounds; it has no elements of its own.
    fn group(&mut self, ids: &mut [u32]) -> u32 {
        if ids.len() == 1 {
            return ids[0];
        }
        let bbox = ids.iter().fold(BBox::EMPTY, |bb, &i| bb.union(&self.nodes[i as usize].bbox));
        let centre = |n: &Node| (n.bbox.min + n.bbox.max) * 0.5;
        let wide = bbox.width() >= bbox.height();
        let coord = |n: &Node| if wide { centre(n).x } else { centre(n).y };
        let mid = ids.len() / 2;
        ids.select_nth_unstable_by(mid, |&a, &b| {
            coord(&self.nodes[a as usize]).total_cmp(&coord(&self.nodes[b as usize]))
        });
        let (lo, hi) = ids.split_at_mut(mid);
        let (left, right) = (self.group(lo), self.group(hi));
        let c = (bbox.min + bbox.max) * 0.5;
        let (l, r) = (self.nodes[left as usize], self.nodes[right as usize]);
        let around = |n: &Node| c.dist(n.a).max(c.dist(n.b)) + n.reach;
        let reach = around(&l).max(around(&r)).min(c.dist(bbox.max));
        let mut obb = Oriented::along(Point::new(1.0, 0.0));
        obb.add_box(&l.obb);
        obb.add_box(&r.obb);
        self.nodes.push(Node { a: c, b: c, reach, bbox, obb, lp: u32::MAX, lo: 0, hi: 0, left, right });
        (self.nodes.len() - 1) as u32
    }

    fn build(&mut self, lp: &Loop, l: u32, lo: usize, hi: usize) -> (u32, Spread) {
        let (a, b) = (lp.element(lo).start(), lp.element(hi - 1).end());
        let mut spread = Spread::default();
        let mut node = Node {
            a,
            b,
            reach: 0.0,
            bbox: BBox::EMPTY,
            obb: Oriented::EMPTY,
            lp: l,
            lo: lo as u32,
            hi: hi as u32,
            left: u32::MAX,
            right: u32::MAX,
        };
        if hi - lo <= LEAF {
            node.reach = (lo..hi).map(|i| element_reach(&lp.element(i), a, b)).fold(0.0, f64::max);
            node.bbox = (lo..hi).fold(BBox::EMPTY, |bb, i| bb.union(&lp.element(i).bbox()));
            for i in lo..hi {
                spread.add(lp.element(i).start());
            }
            spread.add(b);
            node.obb = Oriented::along(spread.axis());
            for i in lo..hi {
                node.obb.add_element(&lp.element(i));
            }
        } else {
            let mid = lo + (hi - lo) / 2;
            let ((left, sl), (right, sr)) = (self.build(lp, l, lo, mid), self.build(lp, l, mid, hi));
            spread = sl.merge(&sr);
            node.obb = Oriented::along(spread.axis());
            node.obb.add_box(&self.nodes[left as usize].obb);
            node.obb.add_box(&self.nodes[right as usize].obb);
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
        ((self.nodes.len() - 1) as u32, spread)
    }

    /// The element of `loops` (the ones the tree was built from) nearest
    /// to `p`, and its distance (model units); the first in loop and
    /// element order among equals. `None` for a shape without elements.
    pub fn nearest(&self, loops: &[Loop], p: Point) -> Option<(ElementRef, f64)> {
        let mut heap = std::collections::BinaryHeap::with_capacity(64);
        for &r in &self.roots {
            if let Some(b) = self.nodes[r as usize].bound_below(p, f64::INFINITY) {
                heap.push(Pending(b, r));
            }
        }
        let mut best: Option<(ElementRef, f64)> = None;
        while let Some(Pending(b, id)) = heap.pop() {
            if best.is_some_and(|(_, d)| b >= d) {
                break;
            }
            let n = self.nodes[id as usize];
            if n.left == u32::MAX {
                for r in n.elements() {
                    let d = loops[r.loop_index].element(r.element).closest_point(p).0;
                    if best.is_none_or(|(br, bd)| d < bd || (d == bd && r < br)) {
                        best = Some((r, d));
                    }
                }
            } else {
                let cutoff = best.map_or(f64::INFINITY, |(_, d)| d);
                for c in [n.left, n.right] {
                    if let Some(b) = self.nodes[c as usize].bound_below(p, cutoff) {
                        heap.push(Pending(b, c));
                    }
                }
            }
        }
        best
    }

    /// Some element closer to `p` than `d` whose distance `accept` agrees
    /// with, with that distance, or `None` when there is none (the search
    /// goes on past rejected elements): the emptiness test of a disk of
    /// radius `d` around `p`. Cheaper than [`nearest`](Self::nearest) when
    /// the answer is expected to be `None` (checking a disk believed
    /// maximal), as runs at `d` or more are never opened.
    pub fn closer_than(
        &self,
        loops: &[Loop],
        p: Point,
        d: f64,
        accept: impl Fn(&Element) -> bool,
    ) -> Option<(ElementRef, f64)> {
        let mut stack: SmallStack<u32, WALK_STACK> = SmallStack::new(0);
        stack.extend(self.roots.iter().rev().copied().filter(|&r| self.nodes[r as usize].may_reach(p, d)));
        while let Some(id) = stack.pop() {
            let n = &self.nodes[id as usize];
            if n.left == u32::MAX {
                for r in n.elements() {
                    let element = loops[r.loop_index].element(r.element);
                    let e = element.closest_point(p).0;
                    if e < d && accept(&element) {
                        return Some((r, e));
                    }
                }
            } else {
                // Left last, so it is opened first: an intruder anywhere
                // is found, and when there is none the order is moot.
                for c in [n.right, n.left] {
                    if self.nodes[c as usize].may_reach(p, d) {
                        stack.push(c);
                    }
                }
            }
        }
        None
    }

    /// [`closer_than`](Self::closer_than) for up to 32 disks at once
    /// (centre, radius `d`): the index of a disk with an accepted element
    /// closer to its centre than its `d`, with the element and distance;
    /// `None` when every disk is empty. One walk down the tree serves
    /// disks that lie close together (a node's disk and the disks of its
    /// edges, which touch the boundary at the same places): a run is
    /// opened while any disk may reach it, and tested against those only.
    pub fn any_closer_than(
        &self,
        loops: &[Loop],
        disks: &[(Point, f64)],
        accept: impl Fn(usize, &Element) -> bool,
    ) -> Option<(usize, ElementRef, f64)> {
        debug_assert!(disks.len() <= 32);
        let reaching = |n: &Node, mask: u32| {
            (0..disks.len())
                .filter(|&k| mask & (1 << k) != 0 && n.may_reach(disks[k].0, disks[k].1))
                .fold(0u32, |m, k| m | (1 << k))
        };
        let all = if disks.len() >= 32 { u32::MAX } else { (1u32 << disks.len()) - 1 };
        let mut stack: SmallStack<(u32, u32), WALK_STACK> = SmallStack::new((0, 0));
        for &r in self.roots.iter().rev() {
            let m = reaching(&self.nodes[r as usize], all);
            if m != 0 {
                stack.push((r, m));
            }
        }
        while let Some((id, mask)) = stack.pop() {
            let n = &self.nodes[id as usize];
            if n.left == u32::MAX {
                for r in n.elements() {
                    let element = loops[r.loop_index].element(r.element);
                    for k in (0..disks.len()).filter(|&k| mask & (1 << k) != 0) {
                        let e = element.closest_point(disks[k].0).0;
                        if e < disks[k].1 && accept(k, &element) {
                            return Some((k, r, e));
                        }
                    }
                }
            } else {
                for c in [n.right, n.left] {
                    let m = reaching(&self.nodes[c as usize], mask);
                    if m != 0 {
                        stack.push((c, m));
                    }
                }
            }
        }
        None
    }

    /// Calls `visit` on every element that may come closer to `p` than
    /// `d` (a superset: whole leaf runs whose bound is below `d`), in loop
    /// and element order within a run and runs in tree order. The disk's
    /// own box would hold every element of a boundary that its circle
    /// hugs (a nearly circular curve); the runs' capsules do not.
    pub fn visit_within(&self, p: Point, d: f64, mut visit: impl FnMut(ElementRef)) {
        let mut stack: SmallStack<u32, WALK_STACK> = SmallStack::new(0);
        stack.extend(self.roots.iter().rev().copied().filter(|&r| self.nodes[r as usize].may_reach(p, d)));
        while let Some(id) = stack.pop() {
            let n = &self.nodes[id as usize];
            if n.left == u32::MAX {
                n.elements().for_each(&mut visit);
            } else {
                for c in [n.right, n.left] {
                    if self.nodes[c as usize].may_reach(p, d) {
                        stack.push(c);
                    }
                }
            }
        }
    }

    /// The elements first touched by the disk growing at `g`: every one
    /// whose `key` (the radius of its first contact, `None` for none) is
    /// within `slack` of the smallest, as `(element, key)` in increasing
    /// key order (ties in loop and element order), found best-first. A
    /// run's bound is where the growing disk first meets its box or its
    /// oriented box (the latter by turning the disk into the box's frame).
    pub fn first_contacts(
        &self,
        g: &GrowingDisk,
        slack: f64,
        key: impl FnMut(ElementRef) -> Option<f64>,
    ) -> Vec<(ElementRef, f64)> {
        let bound = |n: RunBounds, cutoff: f64| -> Option<f64> {
            let b = g.box_bound_below(n.bbox().min, n.bbox().max, cutoff)?;
            if b >= cutoff {
                return Some(b);
            }
            let (u, lo, hi) = n.oriented();
            let frame = |p: Point| Point::new(u.dot(p), u.perp().dot(p));
            let turned = GrowingDisk { p: frame(g.p), n: frame(g.n) };
            Some(b.max(turned.box_bound_below(lo, hi, cutoff)?))
        };
        self.first_by_bound(f64::INFINITY, slack, bound, key)
    }

    /// Best-first search for the smallest keys: every element whose `key`
    /// is at most `cutoff` and within `slack` of the smallest, as
    /// `(element, key)` in increasing key order (ties in loop and element
    /// order). `bound(run, cutoff)` must not exceed the key of any element
    /// of the run (`None`: none has a key, or all exceed `cutoff`); runs
    /// whose bound is past the cutoff are never opened.
    pub fn first_by_bound(
        &self,
        cutoff: f64,
        slack: f64,
        bound: impl Fn(RunBounds, f64) -> Option<f64>,
        mut key: impl FnMut(ElementRef) -> Option<f64>,
    ) -> Vec<(ElementRef, f64)> {
        let mut found: Vec<(ElementRef, f64)> = Vec::new();
        let mut cutoff = cutoff;
        let mut heap = std::collections::BinaryHeap::with_capacity(64);
        for &r in &self.roots {
            if let Some(b) = bound(RunBounds(&self.nodes[r as usize]), cutoff).filter(|&b| b <= cutoff) {
                heap.push(Pending(b, r));
            }
        }
        while let Some(Pending(b, id)) = heap.pop() {
            if b > cutoff {
                break;
            }
            let n = self.nodes[id as usize];
            if n.left == u32::MAX {
                for r in n.elements() {
                    if let Some(v) = key(r).filter(|&v| v <= cutoff) {
                        found.push((r, v));
                        cutoff = cutoff.min(v + slack);
                    }
                }
            } else {
                for c in [n.left, n.right] {
                    if let Some(b) = bound(RunBounds(&self.nodes[c as usize]), cutoff).filter(|&b| b <= cutoff) {
                        heap.push(Pending(b, c));
                    }
                }
            }
        }
        found.retain(|&(_, v)| v <= cutoff);
        found.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
        found
    }
}

/// The bounds of one run of the hierarchy, for a caller's own search
/// ([`ChainTree::first_by_bound`]): every point of the run's elements lies
/// in each of them.
#[derive(Clone, Copy)]
pub struct RunBounds<'a>(&'a Node);

impl RunBounds<'_> {
    /// The run's box.
    pub fn bbox(&self) -> &BBox {
        &self.0.bbox
    }

    /// A lower bound on the distance from `p` to every point of the run:
    /// the largest of its distances to the run's box, oriented box and
    /// capsule.
    pub fn distance_to(&self, p: Point) -> f64 {
        let n = self.0;
        let boxes = n.bbox.distance2_to(p).max(n.obb.distance2_to(p)).sqrt();
        boxes.max(segment_distance(p, n.a, n.b) - n.reach)
    }

    /// The oriented box: unit axis `u`, and the ranges `[lo.x, hi.x]` of
    /// `u·x` and `[lo.y, hi.y]` of `u.perp()·x` over the run's points.
    pub fn oriented(&self) -> (Point, Point, Point) {
        (self.0.obb.u, self.0.obb.lo, self.0.obb.hi)
    }
}

#[cfg(test)]
mod tests;
