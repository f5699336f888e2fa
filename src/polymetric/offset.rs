//! Trimmed inner offsets from the axis under a polygon ball.
//!
//! Which offset: the axis gives every centre `c` the radius `r(c)` of the
//! largest ball `c + r·B` inside the shape, so the level set `r = d` is
//! the path of the reference point of a tool shaped `d·B` that stays
//! inside and touches the boundary: the erosion of the shape by `d·B`. In
//! the thesis's words (Observation 13) that is the trimmed offset of the
//! boundary under the mirrored ball B* = −B (the boundary grown by `d·B*`);
//! for a symmetric ball the two are the same.
//!
//! How: `r` is affine on the face of each contact class, so the level set
//! is straight inside a face and bends only where it passes from one face
//! to the next, at the meeting point of the two classes' level lines. The
//! faces of the axis graph are walked as a planar map (each edge as two
//! sides, the side's class on its left); where a side crosses the level,
//! the offset crosses the axis and continues on the other side of the same
//! edge. Faces whose whole cycle lies above the level (round a hole) give
//! a ring of bends only. Linear in the axis size.

use super::classes::{ContactClass, ShapeFeature};
use super::graph::BallAxis;
use super::BallAxisError;
use crate::kernel::Point;
use crate::shape::{Feature, Shape2d};

/// One closed offset loop: straight elements between its points.
#[derive(Debug, Clone, PartialEq)]
pub struct BallOffsetLoop {
    /// The corners; element `i` runs from point `i` to point `i + 1`
    /// (cyclically). Outer loops counter-clockwise, holes clockwise.
    pub points: Vec<Point>,
    /// Signed area: positive for an outer loop, negative for a hole.
    pub area: f64,
    /// Index of the region (in [`BallOffsetLayer::regions`]) it bounds.
    pub region: usize,
}

/// A connected part of the offset region: an outer loop and its holes.
#[derive(Debug, Clone, PartialEq)]
pub struct BallOffsetRegion {
    /// Index of the outer loop in [`BallOffsetLayer::loops`].
    pub outer: usize,
    /// Indices of the hole loops.
    pub holes: Vec<usize>,
}

/// The inner offset at one distance under a polygon ball.
#[derive(Debug, Clone, PartialEq)]
pub struct BallOffsetLayer {
    /// The distance, model units: positive inwards, negative outwards.
    pub distance: f64,
    /// Every loop of the offset boundary.
    pub loops: Vec<BallOffsetLoop>,
    /// The connected regions the loops bound.
    pub regions: Vec<BallOffsetRegion>,
}

impl BallOffsetLayer {
    /// Area of the offset region (outer loops less holes).
    pub fn area(&self) -> f64 {
        self.loops.iter().map(|l| l.area).sum()
    }
}

/// The level line of a class at distance `d`: `n·c = k`.
struct Level {
    n: Point,
    k: f64,
}

/// Walking the axis as a planar map: sides `2e` (edge `e` from `from` to
/// `to`, class `left`) and `2e + 1` (back, class `right`).
struct Map<'a> {
    axis: &'a BallAxis,
    /// Outgoing sides at each node, counter-clockwise.
    around: Vec<Vec<usize>>,
    /// The position of each side in its origin's `around`.
    slot: Vec<usize>,
}

impl<'a> Map<'a> {
    fn new(axis: &'a BallAxis) -> Map<'a> {
        let mut around = vec![Vec::new(); axis.nodes.len()];
        for s in 0..2 * axis.edges.len() {
            around[Self::origin_of(axis, s)].push(s);
        }
        let mut slot = vec![0; 2 * axis.edges.len()];
        for (v, sides) in around.iter_mut().enumerate() {
            let at = axis.nodes[v].at;
            let angle = |s: usize| {
                let d = axis.nodes[Self::dest_of(axis, s)].at - at;
                d.y.atan2(d.x)
            };
            sides.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
            for (i, &s) in sides.iter().enumerate() {
                slot[s] = i;
            }
        }
        Map { axis, around, slot }
    }

    fn origin_of(axis: &BallAxis, s: usize) -> usize {
        let e = &axis.edges[s / 2];
        if s % 2 == 0 {
            e.from
        } else {
            e.to
        }
    }

    fn dest_of(axis: &BallAxis, s: usize) -> usize {
        Self::origin_of(axis, s ^ 1)
    }

    fn origin(&self, s: usize) -> usize {
        Self::origin_of(self.axis, s)
    }

    fn dest(&self, s: usize) -> usize {
        Self::dest_of(self.axis, s)
    }

    fn class(&self, s: usize) -> &ContactClass {
        let e = &self.axis.edges[s / 2];
        if s % 2 == 0 {
            &e.left
        } else {
            &e.right
        }
    }

    /// The side after `s` round the face on its left: at `s`'s end, the
    /// first side clockwise from the way back.
    fn next(&self, s: usize) -> usize {
        let back = s ^ 1;
        let sides = &self.around[self.origin(back)];
        let i = self.slot[back];
        sides[(i + sides.len() - 1) % sides.len()]
    }

    /// Direction of side `s` from its origin.
    fn direction(&self, s: usize) -> Point {
        self.axis.nodes[self.dest(s)].at - self.axis.nodes[self.origin(s)].at
    }
}

/// The angle turned clockwise from direction `u` to direction `w`, in
/// [0, 2π).
fn clockwise(u: Point, w: Point) -> f64 {
    let a = u.y.atan2(u.x) - w.y.atan2(w.x);
    a.rem_euclid(std::f64::consts::TAU)
}

impl BallAxis {
    /// The level line `r = d` of class `c` (module docs).
    fn level(&self, shape: &Shape2d, c: &ContactClass, d: f64) -> Level {
        let ball = self.ball.vertices();
        let k = ball.len();
        let (l, i) = self.locate(c.shape);
        let lp = &shape.loops()[l];
        let vertex = |j: usize| lp.vertices()[j % lp.len()].p;
        // Outward normal of a direction with the inside on its left.
        let outward = |dir: Point| Point::new(dir.y, -dir.x);
        match (c.shape, c.ball) {
            (ShapeFeature::Vertex(_), Feature::Edge(b)) => {
                // c + d·x = p for x on ball edge b: m·c = m·p − d·m·v_b.
                let m = outward(ball[(b + 1) % k] - ball[b]);
                let p = vertex(i);
                Level { n: m, k: m.dot(p) - d * m.dot(ball[b]) }
            }
            (ShapeFeature::Edge(_), f) => {
                // c + d·v on the edge's line: n·c = n·a − d·n·v.
                let v = match f {
                    Feature::Vertex(b) | Feature::Edge(b) => ball[b],
                };
                let a = vertex(i);
                let n = outward(vertex(i + 1) - a);
                Level { n, k: n.dot(a) - d * n.dot(v) }
            }
            (ShapeFeature::Vertex(_), Feature::Vertex(b)) => {
                // Not a class the tracing makes (a VV contact is a
                // boundary between classes); the point p − d·v.
                let p = vertex(i) - ball[b] * d;
                Level { n: Point::new(1.0, 0.0), k: p.x }
            }
        }
    }

    /// Where class `c` touches the ball of node `v` (a representative
    /// point for an edge-on-edge contact): on `c + r·∂B`, so the order of
    /// these points round the centre is the ball boundary's.
    fn contact_point(&self, shape: &Shape2d, v: usize, c: &ContactClass) -> Point {
        let (at, r) = (self.nodes[v].at, self.nodes[v].r);
        let ball = self.ball.vertices();
        match (c.shape, c.ball) {
            (ShapeFeature::Vertex(_), _) => {
                let (l, i) = self.locate(c.shape);
                shape.loops()[l].vertices()[i].p
            }
            (ShapeFeature::Edge(_), Feature::Vertex(b)) => at + ball[b] * r,
            (ShapeFeature::Edge(_), Feature::Edge(b)) => at + (ball[b] + ball[(b + 1) % ball.len()]) * (0.5 * r),
        }
    }

    /// The classes the offset passes through at node `dest(s)` going from
    /// side `s` to side `t` (= `next(s)`): `s`'s, the node's contacts in
    /// the sector between them in the order the walk meets them, `t`'s.
    /// A class that no axis edge at the node carries (a corner the ball
    /// prunes, Figure 3.3) is met only here.
    fn classes_between(&self, shape: &Shape2d, map: &Map, s: usize, t: usize) -> Vec<ContactClass> {
        let v = map.dest(s);
        let (a, b) = (*map.class(s), *map.class(t));
        let back = map.direction(s ^ 1);
        let span = if t == s ^ 1 { std::f64::consts::TAU } else { clockwise(back, map.direction(t)) };
        let at = self.nodes[v].at;
        // Classes on the sides of the node's edges are met on those sides:
        // their contact can lie along an edge (a jump edge runs along the
        // spoke to a ball vertex), where the angle test is rounding.
        // So can a class no edge here carries: where a ball vertex sits on
        // a shape vertex all along a jump edge, the other edge at that
        // vertex touches the ball there too, a face of no width along the
        // edge; the offset meets it at the edge's other end.
        let carried: Vec<ContactClass> =
            map.around[v].iter().flat_map(|&o| [*map.class(o), *map.class(o ^ 1)]).collect();
        let along_an_edge = |w: Point| {
            map.around[v].iter().any(|&o| {
                let u = map.direction(o);
                u.dot(w) > 0.0 && u.cross(w).abs() <= 1e-9 * u.norm() * w.norm()
            })
        };
        let mut inside: Vec<(f64, ContactClass)> = self.nodes[v]
            .contacts
            .iter()
            .filter(|c| !carried.contains(c))
            .map(|c| (self.contact_point(shape, v, c) - at, *c))
            .filter(|&(w, _)| !along_an_edge(w))
            .map(|(w, c)| (clockwise(back, w), c))
            .filter(|&(angle, _)| angle < span)
            .collect();
        inside.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut out = vec![a];
        out.extend(inside.into_iter().map(|x| x.1));
        out.push(b);
        out.dedup();
        out
    }

    /// The inner offset at distance `d` > 0 (model units; the module docs
    /// say which offset): loops of straight elements with regions, empty
    /// past the largest radius. `shape` is the shape the axis is of.
    pub fn offset(&self, shape: &Shape2d, d: f64) -> Result<BallOffsetLayer, BallAxisError> {
        // The level set of a point or curve site's distance is a loop
        // round the site, not a ring the walk below builds.
        if let Some(l) = shape.loops().iter().position(|lp| lp.kind() != crate::shape::LoopKind::Region) {
            return Err(BallAxisError::NotRegion { l });
        }
        let empty = BallOffsetLayer { distance: d, loops: Vec::new(), regions: Vec::new() };
        if self.edges.is_empty() || d.is_nan() || d <= 0.0 {
            return Ok(empty);
        }
        let map = Map::new(self);
        let above = |v: usize| self.nodes[v].r > d;
        let up = |s: usize| !above(map.origin(s)) && above(map.dest(s));
        let crossing = |s: usize| {
            let (a, b) = (&self.nodes[map.origin(s)], &self.nodes[map.dest(s)]);
            let t = ((d - a.r) / (b.r - a.r)).clamp(0.0, 1.0);
            a.at + (b.at - a.at) * t
        };
        let bend = |a: &ContactClass, b: &ContactClass| -> Option<Point> {
            let (p, q) = (self.level(shape, a, d), self.level(shape, b, d));
            let det = p.n.cross(q.n);
            // Parallel level lines of neighbouring faces are one line (an
            // EE class beside its edge's VE): no bend.
            if det.abs() <= 1e-12 * p.n.norm() * q.n.norm() {
                return None;
            }
            Some(Point::new((p.k * q.n.y - q.k * p.n.y) / det, (p.n.x * q.k - q.n.x * p.k) / det))
        };
        let sides = 2 * self.edges.len();
        let mut walked = vec![false; sides];
        let mut rings: Vec<Vec<Point>> = Vec::new();
        let stuck = |s: usize| BallAxisError::Inconsistent {
            at: self.nodes[map.origin(s)].at,
            what: "an offset ring under the ball does not close",
        };
        // Rings that cross the axis.
        for start in 0..sides {
            if walked[start] || !up(start) {
                continue;
            }
            let mut ring = Vec::new();
            let mut cur = start;
            let mut steps = 0;
            loop {
                walked[cur] = true;
                ring.push(crossing(cur));
                let mut s = cur;
                loop {
                    let t = map.next(s);
                    steps += 1;
                    if steps > 2 * sides {
                        return Err(stuck(start));
                    }
                    for w in self.classes_between(shape, &map, s, t).windows(2) {
                        ring.extend(bend(&w[0], &w[1]));
                    }
                    walked[t] = true;
                    if !above(map.dest(t)) {
                        // Down through side t: on across the edge.
                        cur = t ^ 1;
                        break;
                    }
                    s = t;
                }
                if cur == start {
                    break;
                }
                if walked[cur] {
                    return Err(stuck(cur));
                }
            }
            rings.push(ring);
        }
        // Faces entirely above the level (round a hole): bends only.
        for start in 0..sides {
            if walked[start] || !above(map.origin(start)) || !above(map.dest(start)) {
                continue;
            }
            let mut ring = Vec::new();
            let mut s = start;
            loop {
                walked[s] = true;
                let t = map.next(s);
                for w in self.classes_between(shape, &map, s, t).windows(2) {
                    ring.extend(bend(&w[0], &w[1]));
                }
                if t == start {
                    break;
                }
                if walked[t] {
                    return Err(stuck(t));
                }
                s = t;
            }
            rings.push(ring);
        }
        // Walked with the boundary on their left: turned, outer loops run
        // counter-clockwise.
        let rings = rings.into_iter().map(|r| r.into_iter().rev().collect()).collect();
        Ok(layer_of(d, rings, shape.tolerance()))
    }
}

/// The rings (outer loops counter-clockwise, holes clockwise) as a layer:
/// repeated points dropped, holes given to the smallest outer loop round
/// them.
pub(super) fn layer_of(d: f64, rings: Vec<Vec<Point>>, tol: f64) -> BallOffsetLayer {
    let mut loops: Vec<BallOffsetLoop> = Vec::new();
    for ring in rings {
        let mut points: Vec<Point> = Vec::with_capacity(ring.len());
        for p in ring {
            if points.last().is_none_or(|q: &Point| q.dist(p) > tol) {
                points.push(p);
            }
        }
        while points.len() > 1 && points[0].dist(points[points.len() - 1]) <= tol {
            points.pop();
        }
        if points.len() < 3 {
            continue;
        }
        let area = signed_area(&points);
        loops.push(BallOffsetLoop { points, area, region: usize::MAX });
    }
    let mut regions = Vec::new();
    for (i, lp) in loops.iter_mut().enumerate() {
        if lp.area > 0.0 {
            lp.region = regions.len();
            regions.push(BallOffsetRegion { outer: i, holes: Vec::new() });
        }
    }
    for i in 0..loops.len() {
        if loops[i].area > 0.0 {
            continue;
        }
        let p = loops[i].points[0];
        let around = regions
            .iter()
            .enumerate()
            .filter(|(_, r)| contains(&loops[r.outer].points, p))
            .min_by(|a, b| loops[a.1.outer].area.total_cmp(&loops[b.1.outer].area))
            .map(|(k, _)| k);
        if let Some(k) = around {
            loops[i].region = k;
            regions[k].holes.push(i);
        }
    }
    // A hole with no outer loop round it cannot bound anything.
    let kept: Vec<usize> = (0..loops.len()).filter(|&i| loops[i].region != usize::MAX).collect();
    if kept.len() < loops.len() {
        let mut index = vec![usize::MAX; loops.len()];
        for (new, &old) in kept.iter().enumerate() {
            index[old] = new;
        }
        for r in &mut regions {
            r.outer = index[r.outer];
            r.holes.iter_mut().for_each(|h| *h = index[*h]);
        }
        loops = kept.into_iter().map(|i| loops[i].clone()).collect();
    }
    BallOffsetLayer { distance: d, loops, regions }
}

fn signed_area(p: &[Point]) -> f64 {
    (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum::<f64>() / 2.0
}

/// Even-odd test of `q` against the polygon `p`.
fn contains(p: &[Point], q: Point) -> bool {
    let mut inside = false;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}
