//! The oracle of the axis under a polygon ball, independent of the
//! algorithm's predicates: brute-force gauge distances to every edge
//! (`Ball2::distance_to_segment`), point-in-polygon by crossings, the
//! pieces in which a ball meets the boundary, and completeness probes
//! grown by bisection on those distances.

use medax::kernel::Point;
use medax::polymetric::BallAxis;
use medax::shape::{Ball2, Shape2d};
use rand::{Rng, SeedableRng};

pub fn edges_of(shape: &Shape2d) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    for l in shape.loops() {
        let v = l.vertices();
        for i in 0..v.len() {
            out.push((v[i].p, v[(i + 1) % v.len()].p));
        }
    }
    out
}

/// δ_B from `c` to the boundary, by brute force.
pub fn distance(ball: &Ball2, edges: &[(Point, Point)], c: Point) -> f64 {
    edges.iter().map(|&(a, b)| ball.distance_to_segment(c, a, b)).fold(f64::INFINITY, f64::min)
}

pub fn inside(edges: &[(Point, Point)], c: Point) -> bool {
    let mut w = false;
    for &(a, b) in edges {
        if (a.y > c.y) != (b.y > c.y) && c.x < a.x + (c.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            w = !w;
        }
    }
    w
}

/// The number of separate pieces in which the ball `c + r·B` meets the
/// boundary (each loop walked in order; touching within `tol`).
pub fn contact_components(shape: &Shape2d, ball: &Ball2, c: Point, r: f64, tol: f64) -> usize {
    let v = ball.vertices();
    let k = v.len();
    // Facet a_i: a_i·x = 1 on ball edge i.
    let facets: Vec<Point> = (0..k)
        .map(|i| {
            let (p, q) = (v[i], v[(i + 1) % k]);
            let d = q - p;
            Point::new(d.y, -d.x) * (1.0 / (d.y * p.x - d.x * p.y))
        })
        .collect();
    let mut total = 0;
    for l in shape.loops() {
        let vs = l.vertices();
        let m = vs.len();
        // Per edge: (touches, touches at start, touches at end).
        let hits: Vec<(bool, bool, bool)> = (0..m)
            .map(|i| {
                let (a, b) = (vs[i].p, vs[(i + 1) % m].p);
                let (mut s0, mut s1) = (0.0f64, 1.0f64);
                let len = (b - a).norm();
                for f in &facets {
                    // f·(a − c) + s·f·(b − a) ≤ r + tol·|f|
                    let base = f.dot(a - c) - r - tol * f.norm();
                    let rate = f.dot(b - a);
                    if rate.abs() < 1e-300 {
                        if base > 0.0 {
                            return (false, false, false);
                        }
                    } else if rate > 0.0 {
                        s1 = s1.min(-base / rate);
                    } else {
                        s0 = s0.max(-base / rate);
                    }
                }
                let slack = tol / len.max(1e-300);
                (s0 <= s1 + slack, s0 <= slack, s1 >= 1.0 - slack)
            })
            .collect();
        if hits.iter().all(|h| h.0) {
            total += 1;
            continue;
        }
        // Pieces: runs of touching edges joined where an edge's contact
        // reaches its end and the next one's reaches its start.
        for i in 0..m {
            let prev = hits[(i + m - 1) % m];
            if hits[i].0 && !(prev.0 && prev.2 && hits[i].1) {
                total += 1;
            }
        }
    }
    total
}

/// Soundness: every node and points along every edge are centres of balls
/// inside the shape that touch its boundary, with the radius the axis says
/// (at most `max_edges` edges, chosen at random with `seed` when the axis
/// has more: the brute force is linear in the shape per point).
pub fn check_sound(shape: &Shape2d, ball: &Ball2, axis: &BallAxis, max_edges: usize, seed: u64) {
    let edges = edges_of(shape);
    let tol = 1e-9 * shape.bbox().diagonal();
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let picked: Vec<usize> = if axis.edges.len() <= max_edges {
        (0..axis.edges.len()).collect()
    } else {
        (0..max_edges).map(|_| rng.gen_range(0..axis.edges.len())).collect()
    };
    for e in picked.iter().map(|&i| &axis.edges[i]) {
        let (a, b) = (&axis.nodes[e.from], &axis.nodes[e.to]);
        for s in [0.0, 0.25, 0.5, 0.75, 1.0] {
            let c = a.at + (b.at - a.at) * s;
            let r = a.r + (b.r - a.r) * s;
            let d = distance(ball, &edges, c);
            assert!((d - r).abs() <= tol, "edge {}→{} at {s}: radius {r} but distance {d} at {c:?}", e.from, e.to);
            if s > 0.0 && s < 1.0 {
                assert!(inside(&edges, c), "edge {}→{} leaves the shape at {c:?}", e.from, e.to);
                let pieces = contact_components(shape, ball, c, r, tol);
                assert!(pieces >= 2, "edge {}→{} at {s}: the ball at {c:?} touches the boundary once", e.from, e.to);
            }
        }
    }
}

pub fn dist_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let t = if d.norm2() > 0.0 { ((p - a).dot(d) / d.norm2()).clamp(0.0, 1.0) } else { 0.0 };
    (a + d * t).dist(p)
}

/// Completeness: from random boundary points, the ball touching there with
/// the ball vertex that supports the edge's outward normal, grown until it
/// touches elsewhere, is a maximal* ball; its centre lies on the axis.
pub fn check_complete(shape: &Shape2d, ball: &Ball2, axis: &BallAxis, probes: usize, seed: u64) {
    let edges = edges_of(shape);
    let diag = shape.bbox().diagonal();
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let verts = ball.vertices();
    for _ in 0..probes {
        let (a, b) = edges[rng.gen_range(0..edges.len())];
        let y = a + (b - a) * rng.gen_range(0.05..0.95);
        let n = Point::new((b - a).y, -(b - a).x);
        // The supporting vertex (the middle of the supporting edge where
        // the edge lies along a ball edge).
        let top = verts.iter().map(|p| p.dot(n)).fold(f64::NEG_INFINITY, f64::max);
        let sup: Vec<Point> = verts.iter().copied().filter(|p| p.dot(n) >= top - 1e-12 * n.norm()).collect();
        let v = sup.iter().fold(Point::new(0.0, 0.0), |s, p| s + *p) * (1.0 / sup.len() as f64);
        // Centres y − t·v; the ball of radius t touches y. Grown while it
        // stays empty: δ(c(t)) = t. Bisection on the first t where δ < t.
        let ok = |t: f64| distance(ball, &edges, y - v * t) >= t * (1.0 - 1e-12) - 1e-13 * diag;
        let (mut lo, mut hi) = (0.0, diag);
        while !ok(hi) || hi == diag {
            if !ok(hi) {
                break;
            }
            hi *= 2.0;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if ok(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let c = y - v * lo;
        // Only a ball touching the boundary in two separate places is
        // maximal* (outside general position a corner can hold a ball that
        // meets two edges in one connected piece).
        if contact_components(shape, ball, c, lo, 1e-9 * diag) < 2 {
            continue;
        }
        let near = axis
            .edges
            .iter()
            .map(|e| dist_to_segment(c, axis.nodes[e.from].at, axis.nodes[e.to].at))
            .fold(f64::INFINITY, f64::min);
        assert!(near <= 1e-7 * diag, "probe from {y:?}: maximal* ball centre {c:?} (r {lo}) is {near} off the axis");
    }
}
