//! Exact intersection tests of the surface with a closed segment, a
//! closed triangle and a closed box, and first hits of many rays at once.
//!
//! Why the answers are exact: every decision is a comparison of input
//! coordinates, a sign of [`plane_side`] (exact: Shewchuk's filter, big
//! integers behind it) or a sign of a 2D orientation of points projected
//! onto a coordinate plane by dropping one coordinate (exact: the
//! projection rounds nothing and [`FilteredKernel`] decides exactly). No
//! point is ever constructed. The tree is pruned by the same exact tests
//! (a node's box against the query), so rounding cannot lose a triangle.
//!
//! The tree's triangles must be non-degenerate (corners not on one line),
//! as a validated solid's are; a query triangle may be degenerate (then
//! it is the segment or the point its corners span).

use super::{Hit, TriangleTree};
use crate::kernel::orient3::{collinear3, plane_side, PlaneSide};
use crate::kernel::tri_tri::{segment_meets_triangle, triangle_contains, triangles_intersect};
use crate::kernel::{BBox3, FilteredKernel, Kernel, Orientation, Point, Point3};
use std::ops::ControlFlow;

fn sign2(a: Point, b: Point, c: Point) -> i8 {
    match FilteredKernel.orientation(a, b, c) {
        Orientation::Left => 1,
        Orientation::Collinear => 0,
        Orientation::Right => -1,
    }
}

/// The projection dropping coordinate `axis`, in the cyclic order that
/// makes the orientation of a projected triangle the sign of component
/// `axis` of its normal `(b − a) × (c − a)`.
fn project(p: Point3, axis: usize) -> Point {
    match axis {
        0 => Point::new(p.y, p.z),
        1 => Point::new(p.z, p.x),
        _ => Point::new(p.x, p.y),
    }
}

/// −1, 0 or 1 as `a < b`, `a == b`, `a > b` (exact).
fn cmp(a: f64, b: f64) -> i8 {
    (a > b) as i8 - (a < b) as i8
}

/// Exactly whether the closed triangle `t` (possibly degenerate: a
/// segment or a point) meets the closed box `b` (finite, non-empty).
///
/// Separating axis theorem: two disjoint convex polytopes are strictly
/// separated along a face normal of one of them or along the cross
/// product of an edge of each. Here: the three box normals (coordinate
/// comparisons), the triangle's normal, and `e × u_k` for the triangle's
/// edges `e` and the axes `u_k`. An axis `e × u_k` is perpendicular to
/// `u_k`, so it separates exactly when, seen along `u_k` (coordinate `k`
/// dropped), the projected triangle and the box's rectangle are
/// separated; by the same theorem in the plane that happens along a side
/// of the rectangle (a box normal again) or along an edge line of the
/// projected triangle with the rectangle strictly outside. So the test
/// needs only signs, each of an extreme corner of the box: the corner
/// where a linear function is least or greatest is picked by the signs of
/// its gradient, which are exact (coordinate comparisons, or the
/// orientations of the projected triangle for the normal).
pub(crate) fn triangle_meets_box(t: [Point3; 3], b: &BBox3) -> bool {
    BoxTest::new(t).meets(b)
}

/// [`triangle_meets_box`] for one triangle against many boxes: the signs
/// that do not depend on the box are found once.
struct BoxTest {
    t: [Point3; 3],
    bbox: BBox3,
    /// Signs of the normal's components (the projected orientations).
    normal: [i8; 3],
    /// Per projection: its distinct edge lines `(p, q)` with the signs of
    /// the gradient of `orient(p, q, ·)`, and how many there are.
    edges: [[(Point, Point, i8, i8); 3]; 3],
    edge_count: [usize; 3],
}

impl BoxTest {
    fn new(t: [Point3; 3]) -> BoxTest {
        // Two equal corners (a segment asked as a triangle) need no
        // predicate to be flat; the exact zero is the slow case of one.
        let flat = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
        let normal =
            if flat { [0; 3] } else { [0, 1, 2].map(|k| sign2(project(t[0], k), project(t[1], k), project(t[2], k))) };
        let mut edges = [[(Point::new(0.0, 0.0), Point::new(0.0, 0.0), 0, 0); 3]; 3];
        let mut edge_count = [0; 3];
        for k in 0..3 {
            let t2 = t.map(|p| project(p, k));
            for i in 0..3 {
                let (p, q) = (t2[i], t2[(i + 1) % 3]);
                let known = edges[k][..edge_count[k]].iter().any(|e| (e.0, e.1) == (q, p) || (e.0, e.1) == (p, q));
                if p == q || (normal[k] == 0 && known) {
                    continue;
                }
                // orient(p, q, x) = (q − p) × (x − p) has gradient (p.y − q.y, q.x − p.x).
                edges[k][edge_count[k]] = (p, q, cmp(p.y, q.y), cmp(q.x, p.x));
                edge_count[k] += 1;
            }
        }
        BoxTest { t, bbox: BBox3::of(t), normal, edges, edge_count }
    }

    fn meets(&self, b: &BBox3) -> bool {
        if !self.bbox.overlaps(b) {
            return false;
        }
        let (t, n) = (self.t, self.normal);
        if n != [0, 0, 0] {
            // The corner where n · x is greatest (`toward` 1) or least (−1).
            let corner = |toward: i8| {
                let pick = |i: usize| if n[i] * toward > 0 { b.max.coord(i) } else { b.min.coord(i) };
                Point3::new(pick(0), pick(1), pick(2))
            };
            if plane_side(t[0], t[1], t[2], corner(-1)) == PlaneSide::Above
                || plane_side(t[0], t[1], t[2], corner(1)) == PlaneSide::Below
            {
                return false;
            }
        }
        for (k, &s) in n.iter().enumerate() {
            let (lo, hi) = (project(b.min, k), project(b.max, k));
            for &(p, q, gx, gy) in &self.edges[k][..self.edge_count[k]] {
                let corner = |toward: i8| {
                    Point::new(if gx * toward > 0 { hi.x } else { lo.x }, if gy * toward > 0 { hi.y } else { lo.y })
                };
                let separated = if s != 0 {
                    // The triangle lies on side s: the rectangle strictly on −s.
                    sign2(p, q, corner(s)) == -s
                } else {
                    // A flat projection: the rectangle strictly on either side.
                    sign2(p, q, corner(1)) == -1 || sign2(p, q, corner(-1)) == 1
                };
                if separated {
                    return false;
                }
            }
        }
        true
    }
}

/// What the corners of a query triangle span, exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Span {
    Triangle([Point3; 3]),
    Segment(Point3, Point3),
    Point(Point3),
}

impl Span {
    fn of(t: [Point3; 3]) -> Span {
        if !collinear3(t[0], t[1], t[2]) {
            return Span::Triangle(t);
        }
        // On one line: along a coordinate in which they differ the order
        // on the line is the order of that coordinate, so its least and
        // greatest corners are the ends.
        let Some(axis) = (0..3).find(|&k| t.iter().any(|p| p.coord(k) != t[0].coord(k))) else {
            return Span::Point(t[0]);
        };
        let key = |p: &&Point3| p.coord(axis);
        let lo = *t.iter().min_by(|a, b| key(a).total_cmp(&key(b))).unwrap_or(&t[0]);
        let hi = *t.iter().max_by(|a, b| key(a).total_cmp(&key(b))).unwrap_or(&t[0]);
        Span::Segment(lo, hi)
    }

    /// Exactly whether it meets the closed, non-degenerate triangle `c`.
    fn meets(&self, c: [Point3; 3]) -> bool {
        match *self {
            Span::Triangle(t) => triangles_intersect(t, c),
            Span::Segment(p, q) => segment_meets_triangle(p, q, c),
            Span::Point(p) => triangle_contains(c, p),
        }
    }
}

impl TriangleTree {
    /// True when some triangle passes `test`, visiting the leaves whose
    /// boxes pass `enter`.
    fn any_triangle(&self, enter: impl Fn(&BBox3) -> bool, test: impl Fn([Point3; 3]) -> bool) -> bool {
        self.visit(enter, |k| if test(self.corners(k)) { ControlFlow::Break(()) } else { ControlFlow::Continue(()) })
            .is_break()
    }

    /// Exactly whether the closed segment `ab` meets the surface (touching
    /// counts; `a == b` asks about a point). False when a coordinate is
    /// not finite.
    pub fn intersects_segment(&self, a: Point3, b: Point3) -> bool {
        if !a.is_finite() || !b.is_finite() {
            return false;
        }
        let s = BBox3::of([a, b]);
        let test = BoxTest::new([a, b, b]);
        self.any_triangle(|node| test.meets(node), |c| BBox3::of(c).overlaps(&s) && segment_meets_triangle(a, b, c))
    }

    /// Exactly whether the closed triangle `t` meets the surface (touching
    /// counts). `t` may be degenerate: corners on one line ask about the
    /// segment they span, three equal corners about a point. False when a
    /// coordinate is not finite.
    pub fn intersects_triangle(&self, t: [Point3; 3]) -> bool {
        if !t.iter().all(|p| p.is_finite()) {
            return false;
        }
        let span = Span::of(t);
        let (s, test) = (BBox3::of(t), BoxTest::new(t));
        self.any_triangle(|node| test.meets(node), |c| BBox3::of(c).overlaps(&s) && span.meets(c))
    }

    /// Exactly whether the closed box `b` meets the surface (touching
    /// counts). Bounds may be infinite; a box with `min > max` (or a NaN
    /// bound) in some coordinate is empty: false.
    pub fn intersects_box(&self, b: &BBox3) -> bool {
        // The surface lies in the tree's box, so the query may be cut to
        // it: the bounds stay input numbers, and become finite.
        let t = self.bbox();
        let (lo, hi) = (
            [0, 1, 2].map(|i| b.min.coord(i).max(t.min.coord(i))),
            [0, 1, 2].map(|i| b.max.coord(i).min(t.max.coord(i))),
        );
        // NaN bounds fail the comparisons: empty too.
        if !(0..3).all(|i| b.min.coord(i) <= b.max.coord(i) && lo[i] <= hi[i]) {
            return false;
        }
        let q = BBox3 { min: Point3::from_array(lo), max: Point3::from_array(hi) };
        self.any_triangle(|node| node.overlaps(&q), |c| triangle_meets_box(c, &q))
    }

    /// [`TriangleTree::first_hit`] of many rays `(origin, direction)`, in
    /// parallel, answered in the order of a Z-order curve through the
    /// origins (neighbouring rays walk the same top of the tree while it
    /// is in cache) and returned in the caller's order.
    pub fn first_hits(&self, rays: &[(Point3, Point3)]) -> Vec<Option<Hit>> {
        self.batch_by(rays, |r| r.0, |r| self.first_hit(r.0, r.1))
    }
}

#[cfg(test)]
mod tests {
    //! Two oracles that share nothing with the code: a triangle clipped
    //! by the box's six half-spaces in exact rationals (small integer
    //! inputs, many flat, touching and degenerate cases, also scaled and
    //! shifted exactly), and brute force over every triangle of a scene
    //! for the tree's queries (so the pruning must lose nothing).
    use super::*;
    use crate::shape::mesh::samples::{cuboid, sphere, torus, union};
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};
    use rayon::prelude::*;

    type Q = (i128, i128);

    fn q(n: i128, d: i128) -> Q {
        fn gcd(a: i128, b: i128) -> i128 {
            if b == 0 {
                a.abs()
            } else {
                gcd(b, a % b)
            }
        }
        let g = gcd(n, d).max(1) * d.signum();
        (n / g, d / g)
    }

    /// Sign of `a − c` for a rational `a` and an integer `c`.
    fn above(a: Q, c: i128) -> i128 {
        (a.0 - c * a.1).signum()
    }

    /// The part of the convex cycle `poly` with coordinate `axis` on the
    /// side `keep` (−1: ≤ c, 1: ≥ c) of `c`, closed.
    fn clip(poly: &[[Q; 3]], axis: usize, c: i128, keep: i128) -> Vec<[Q; 3]> {
        let mut out = Vec::new();
        for (i, &a) in poly.iter().enumerate() {
            let b = poly[(i + 1) % poly.len()];
            let (sa, sb) = (above(a[axis], c) * keep, above(b[axis], c) * keep);
            if sa >= 0 {
                out.push(a);
            }
            if sa * sb < 0 {
                // a + (b − a)·s with s = (c − a_axis) / (b_axis − a_axis).
                let sub = |x: Q, y: Q| q(x.0 * y.1 - y.0 * x.1, x.1 * y.1);
                let s = {
                    let (num, den) = (sub((c, 1), a[axis]), sub(b[axis], a[axis]));
                    q(num.0 * den.1, num.1 * den.0)
                };
                out.push([0, 1, 2].map(|k| {
                    let d = sub(b[k], a[k]);
                    let m = q(d.0 * s.0, d.1 * s.1);
                    q(a[k].0 * m.1 + m.0 * a[k].1, a[k].1 * m.1)
                }));
            }
        }
        out
    }

    fn meets_by_clipping(t: [[i128; 3]; 3], lo: [i128; 3], hi: [i128; 3]) -> bool {
        let mut poly: Vec<[Q; 3]> = t.iter().map(|p| p.map(|c| q(c, 1))).collect();
        for axis in 0..3 {
            poly = clip(&poly, axis, lo[axis], 1);
            poly = clip(&poly, axis, hi[axis], -1);
        }
        !poly.is_empty()
    }

    /// Integer coordinates as exact `f64`, scaled and shifted by `mode`.
    fn pt(p: [i128; 3], mode: u8) -> Point3 {
        let f = |c: i128| match mode {
            0 => c as f64,
            1 => c as f64 * 2f64.powi(-30) + 1024.0,
            _ => c as f64 * 2f64.powi(40) - 3.0 * 2f64.powi(44),
        };
        Point3::new(f(p[0]), f(p[1]), f(p[2]))
    }

    #[test]
    fn triangle_box_as_the_rational_clipping_says() {
        let mut rng = SmallRng::seed_from_u64(19);
        let mut seen = [0; 2];
        for case in 0..20_000usize {
            let r = 3 + (case % 3) as i128;
            let mut p = || [0; 3].map(|_| rng.gen_range(-r..=r));
            let mut t = [p(), p(), p()];
            match case % 5 {
                // Degenerate: a segment (third corner on it) or a point.
                0 => t[2] = [0, 1, 2].map(|k| 2 * t[1][k] - t[0][k]),
                1 if case % 10 == 1 => t = [t[0]; 3],
                _ => {}
            }
            let (a, b) = (p(), p());
            let (lo, mut hi) = ([0, 1, 2].map(|k| a[k].min(b[k])), [0, 1, 2].map(|k| a[k].max(b[k])));
            if case % 7 == 0 {
                hi[case % 3] = lo[case % 3]; // a flat box
            }
            let expected = meets_by_clipping(t, lo, hi);
            seen[expected as usize] += 1;
            let mode = (case % 3) as u8;
            let bx = BBox3 { min: pt(lo, mode), max: pt(hi, mode) };
            let t3 = t.map(|c| pt(c, mode));
            assert_eq!(triangle_meets_box(t3, &bx), expected, "{t:?} {lo:?} {hi:?} mode {mode}");
            assert_eq!(triangle_meets_box([t3[2], t3[0], t3[1]], &bx), expected);
            assert_eq!(triangle_meets_box([t3[1], t3[0], t3[2]], &bx), expected);
        }
        assert!(seen.iter().all(|&n| n > 5000), "{seen:?}");
    }

    /// A torus, a sphere in its hole and a box beside it, touching it.
    fn scene() -> (Vec<Point3>, Vec<[u32; 3]>, TriangleTree) {
        let soup = union(&[
            torus(3.0, 1.0, 24, 12),
            sphere([0.0, 0.0, 0.0], 1.5, 12, 12),
            cuboid([4.0, -1.0, -1.0], [6.0, 1.0, 1.0]),
        ]);
        let tree = TriangleTree::from_arrays(&soup.0, &soup.1);
        (soup.0.iter().map(|&p| Point3::from_array(p)).collect(), soup.1, tree)
    }

    fn random_in(rng: &mut SmallRng, b: BBox3, margin: f64) -> Point3 {
        let mut c = |lo: f64, hi: f64| rng.gen_range(lo - margin..hi + margin);
        Point3::new(c(b.min.x, b.max.x), c(b.min.y, b.max.y), c(b.min.z, b.max.z))
    }

    /// A query point: random, or exactly a vertex of the scene, or a
    /// vertex moved along one axis (touching and near-touching cases).
    fn query_point(rng: &mut SmallRng, v: &[Point3], b: BBox3) -> Point3 {
        match rng.gen_range(0..4) {
            0 => v[rng.gen_range(0..v.len())],
            1 => {
                let p = v[rng.gen_range(0..v.len())];
                p + Point3::new(0.0, 0.0, rng.gen_range(-0.5..0.5))
            }
            _ => random_in(rng, b, 1.0),
        }
    }

    #[test]
    fn tree_queries_match_brute_force() {
        let (v, t, tree) = scene();
        let corners: Vec<[Point3; 3]> = t.iter().map(|c| c.map(|i| v[i as usize])).collect();
        let mut rng = SmallRng::seed_from_u64(5);
        let b = tree.bbox();
        let mut seen = [[0; 2]; 3];
        for case in 0..3000 {
            let a = query_point(&mut rng, &v, b);
            let near = |rng: &mut SmallRng| {
                let s = if case % 2 == 0 { 0.3 } else { 3.0 };
                a + Point3::new(rng.gen_range(-s..s), rng.gen_range(-s..s), rng.gen_range(-s..s))
            };
            let (p, r) = (near(&mut rng), near(&mut rng));
            let expected = corners.par_iter().any(|&c| segment_meets_triangle(a, p, c));
            assert_eq!(tree.intersects_segment(a, p), expected, "{a:?} {p:?}");
            seen[0][expected as usize] += 1;
            let tri = match case % 6 {
                0 => [a, p, a + (p - a) * 0.5],
                1 => [a, a, a],
                _ => [a, p, r],
            };
            let span = Span::of(tri);
            let expected = corners.par_iter().any(|&c| span.meets(c));
            assert_eq!(tree.intersects_triangle(tri), expected, "{tri:?}");
            seen[1][expected as usize] += 1;
            let mut bx = BBox3::of([a, p]);
            if case % 5 == 0 {
                bx.max.z = bx.min.z; // flat
            }
            let expected = corners.par_iter().any(|&c| triangle_meets_box(c, &bx));
            assert_eq!(tree.intersects_box(&bx), expected, "{bx:?}");
            seen[2][expected as usize] += 1;
        }
        assert!(seen.iter().flatten().all(|&n| n > 300), "{seen:?}");
        // Corners of the scene's box touch; beyond it, an empty box, NaN.
        assert!(tree.intersects_box(&BBox3 { min: b.max, max: b.max * 2.0 }) || b.max.x == 6.0);
        assert!(tree.intersects_box(&BBox3 { min: Point3::new(6.0, -9.0, -9.0), max: Point3::new(9.0, 9.0, 9.0) }));
        let beyond = f64::from_bits(6f64.to_bits() + 1);
        assert!(!tree.intersects_box(&BBox3 { min: Point3::new(beyond, -9.0, -9.0), max: Point3::new(9.0, 9.0, 9.0) }));
        let inf = f64::INFINITY;
        assert!(tree.intersects_box(&BBox3 { min: Point3::new(-inf, -inf, -inf), max: Point3::new(inf, inf, inf) }));
        assert!(!tree.intersects_box(&BBox3::EMPTY));
        assert!(!tree.intersects_segment(Point3::new(f64::NAN, 0.0, 0.0), Point3::new(9.0, 0.0, 0.0)));
        assert!(tree.intersects_segment(Point3::new(9.0, 0.0, 0.0), Point3::new(6.0, 0.0, 0.0)));
        assert!(!tree.intersects_segment(Point3::new(9.0, 0.0, 0.0), Point3::new(beyond, 0.0, 0.0)));
    }

    #[test]
    fn first_hits_are_first_hit_for_any_direction_length() {
        let (v, _, tree) = scene();
        let mut rng = SmallRng::seed_from_u64(8);
        let rays: Vec<(Point3, Point3)> = (0..2000)
            .map(|_| {
                let o = random_in(&mut rng, tree.bbox(), 2.0);
                (o, query_point(&mut rng, &v, tree.bbox()) - o)
            })
            .collect();
        let hits = tree.first_hits(&rays);
        assert!(hits.iter().filter(|h| h.is_some()).count() > 1000);
        for (&(o, d), h) in rays.iter().zip(&hits) {
            assert_eq!(tree.first_hit(o, d), *h);
            // The same ray with a direction 2^-1000 or 2^1000 times as long
            // (both exact): the same point, the parameter scaled back.
            for k in [-1000, 1000] {
                let s = 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
                let g = tree.first_hit(o, d * s);
                assert_eq!(g.map(|g| (g.point, g.triangle)), h.map(|h| (h.point, h.triangle)), "{o:?} {d:?} {k}");
                if let (Some(g), Some(h)) = (g, h) {
                    assert_eq!(g.t, h.t / s);
                }
            }
        }
        let o = Point3::new(9.0, 0.0, 0.0);
        assert_eq!(
            tree.first_hit(o, Point3::new(-1e-310, 0.0, 0.0)).map(|h| h.point),
            Some(Point3::new(6.0, 0.0, 0.0))
        );
        assert_eq!(tree.first_hit(o, Point3::new(-1e300, 0.0, 0.0)).map(|h| h.t), Some(3e-300));
        assert_eq!(tree.first_hit(o, Point3::new(0.0, 0.0, 0.0)), None);
        assert_eq!(tree.first_hit(o, Point3::new(-1.0, f64::NAN, 0.0)), None);
    }
}
