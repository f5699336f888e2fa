//! Exact predicates on triangles of space: whether two closed triangles
//! meet, whether a segment crosses a triangle (for ray parity), and the
//! rules for triangles of one surface that share corners.
//!
//! Every decision is a sign of [`plane_side`] or of a 2D orientation of a
//! projection (both exact), so a self-intersection check or an inside test
//! built on them cannot be fooled by rounding. Triangles must be
//! non-degenerate (corners not on one line), as a validated solid's are.
//!
//! Two non-coplanar closed triangles meet exactly when an edge of one
//! meets the other: their intersection is a segment of the planes' common
//! line, and its ends lie on the triangles' boundaries. That reduces the
//! test to segment–triangle tests whose plane sides are shared with the
//! early rejection. Coplanar figures are separated, when they are, by the
//! line of one of their edges (separating axes of convex polygons), which
//! is again a set of orientation signs.

use super::orient3::{plane_side, PlaneSide};
use super::{FilteredKernel, Kernel, Orientation, Point, Point3};

/// How a segment meets a triangle, for counting crossings of a ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Crossing {
    /// They do not meet.
    None,
    /// The open segment passes through the open triangle from one side of
    /// its plane to the other: one crossing, unambiguously.
    Proper,
    /// They meet in another way (an edge, a corner, an endpoint on the
    /// triangle, the segment in its plane): a parity count must not rely
    /// on this segment.
    Degenerate,
}

fn sign3(a: Point3, b: Point3, c: Point3, d: Point3) -> i8 {
    match plane_side(a, b, c, d) {
        PlaneSide::Above => 1,
        PlaneSide::On => 0,
        PlaneSide::Below => -1,
    }
}

/// The sign of [`plane_side`] when its `f64` filter alone certifies it
/// (Shewchuk's bound, as there), else `None`. Cheap rejections ask this
/// first, so that a nearly coplanar corner whose exact sign is not needed
/// never reaches the big-integer fallback (surfaces of revolution and
/// flat faces are full of them).
fn certain_sign3(a: Point3, b: Point3, c: Point3, d: Point3) -> Option<i8> {
    const EPS: f64 = f64::EPSILON * 0.5;
    const BOUND: f64 = (7.0 + 56.0 * EPS) * EPS;
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let (bc1, bc2) = (bd.y * cd.z, bd.z * cd.y);
    let (ca1, ca2) = (cd.y * ad.z, cd.z * ad.y);
    let (ab1, ab2) = (ad.y * bd.z, ad.z * bd.y);
    let det = ad.x * (bc1 - bc2) + bd.x * (ca1 - ca2) + cd.x * (ab1 - ab2);
    let permanent = (bc1.abs() + bc2.abs()) * ad.x.abs()
        + (ca1.abs() + ca2.abs()) * bd.x.abs()
        + (ab1.abs() + ab2.abs()) * cd.x.abs();
    let certain = det.abs() > BOUND * permanent && permanent.is_finite() && permanent > f64::MIN_POSITIVE * 1e40;
    // det = −((b − a) × (c − a)) · (d − a): Above is a negative det.
    certain.then_some(if det < 0.0 { 1 } else { -1 })
}

/// True when the filter alone shows `p` and `q` strictly on one side of
/// the plane of `t`.
fn certainly_one_side(t: [Point3; 3], p: Point3, q: Point3) -> bool {
    matches!(
        (certain_sign3(t[0], t[1], t[2], p), certain_sign3(t[0], t[1], t[2], q)),
        (Some(x), Some(y)) if x == y
    )
}

fn sign2(a: Point, b: Point, c: Point) -> i8 {
    match FilteredKernel.orientation(a, b, c) {
        Orientation::Left => 1,
        Orientation::Collinear => 0,
        Orientation::Right => -1,
    }
}

/// The projection dropping coordinate `axis`, in the cyclic order that
/// makes its orientation the sign of normal component `axis` (as in
/// [`super::orient3::collinear3`]).
fn project(p: Point3, axis: usize) -> Point {
    match axis {
        0 => Point::new(p.y, p.z),
        1 => Point::new(p.z, p.x),
        _ => Point::new(p.x, p.y),
    }
}

/// A coordinate to drop so that `t` stays a proper triangle: one whose
/// normal component is exactly nonzero. The largest component in `f64`
/// is tried first because it is almost always right and keeps the
/// projection well shaped; the exact check makes the choice safe.
fn drop_axis(t: [Point3; 3]) -> usize {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let m = [n.x.abs(), n.y.abs(), n.z.abs()];
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| m[j].total_cmp(&m[i]));
    let proper = |axis: usize| sign2(project(t[0], axis), project(t[1], axis), project(t[2], axis)) != 0;
    // A degenerate triangle has no such axis; any answer is then as good.
    order.into_iter().find(|&axis| proper(axis)).unwrap_or(order[0])
}

/// True when some line through an edge of the triangle `t` has all of
/// `others` strictly on its far side (the side away from `t`).
fn triangle_separates(t: [Point; 3], others: &[Point]) -> bool {
    (0..3).any(|i| {
        let (p, q, r) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
        let inner = sign2(p, q, r);
        others.iter().all(|&o| sign2(p, q, o) == -inner)
    })
}

/// True when the line through `p`, `q` (distinct) has all of `others`
/// strictly on one side.
fn segment_separates(p: Point, q: Point, others: &[Point]) -> bool {
    if p == q {
        return false;
    }
    let s = sign2(p, q, others[0]);
    s != 0 && others.iter().all(|&o| sign2(p, q, o) == s)
}

/// Closed triangle `t` contains `p` (all in 2D).
fn contains2(t: [Point; 3], p: Point) -> bool {
    !triangle_separates(t, &[p])
}

/// Closed segment `pq` meets closed triangle `t` (2D): separated only by
/// an edge line of the triangle or by the segment's own line.
fn segment_meets2(p: Point, q: Point, t: [Point; 3]) -> bool {
    !triangle_separates(t, &[p, q]) && !segment_separates(p, q, &t)
}

fn project_all(t: [Point3; 3], axis: usize) -> [Point; 3] {
    t.map(|p| project(p, axis))
}

/// Exactly whether the closed triangle `t` contains `p`.
pub fn triangle_contains(t: [Point3; 3], p: Point3) -> bool {
    if sign3(t[0], t[1], t[2], p) != 0 {
        return false;
    }
    let axis = drop_axis(t);
    contains2(project_all(t, axis), project(p, axis))
}

/// Closed segment `pq` meets closed triangle `t`, given the sides `sp`,
/// `sq` of `p`, `q` relative to the plane of `t`.
fn segment_meets_with_sides(p: Point3, q: Point3, sp: i8, sq: i8, t: [Point3; 3]) -> bool {
    if sp == sq && sp != 0 {
        return false;
    }
    if sp == 0 || sq == 0 {
        let axis = drop_axis(t);
        let t2 = project_all(t, axis);
        return match (sp, sq) {
            (0, 0) => segment_meets2(project(p, axis), project(q, axis), t2),
            (0, _) => contains2(t2, project(p, axis)),
            _ => contains2(t2, project(q, axis)),
        };
    }
    // Strictly opposite sides: the line meets the plane inside the
    // segment, and inside the closed triangle unless it passes strictly
    // outside some edge.
    let s = edge_signs(p, q, t);
    !(s.contains(&1) && s.contains(&-1))
}

/// Sides of the edges of `t` seen along `p → q`: all equal and nonzero
/// when the line passes through the open triangle.
fn edge_signs(p: Point3, q: Point3, t: [Point3; 3]) -> [i8; 3] {
    [sign3(p, q, t[0], t[1]), sign3(p, q, t[1], t[2]), sign3(p, q, t[2], t[0])]
}

/// Exactly whether the closed segment `pq` meets the closed triangle `t`.
pub fn segment_meets_triangle(p: Point3, q: Point3, t: [Point3; 3]) -> bool {
    let (sp, sq) = (sign3(t[0], t[1], t[2], p), sign3(t[0], t[1], t[2], q));
    segment_meets_with_sides(p, q, sp, sq, t)
}

/// How the segment `pq` meets the triangle `t`, exactly; see [`Crossing`].
/// A ray parity count adds the [`Crossing::Proper`] ones and, on any
/// [`Crossing::Degenerate`], tries another ray.
pub fn segment_crosses_triangle(p: Point3, q: Point3, t: [Point3; 3]) -> Crossing {
    let (sp, sq) = (sign3(t[0], t[1], t[2], p), sign3(t[0], t[1], t[2], q));
    if sp != 0 && sq != 0 && sp != sq {
        let s = edge_signs(p, q, t);
        return if s[0] != 0 && s[0] == s[1] && s[1] == s[2] {
            Crossing::Proper
        } else if s.contains(&1) && s.contains(&-1) {
            Crossing::None
        } else {
            Crossing::Degenerate
        };
    }
    if segment_meets_with_sides(p, q, sp, sq, t) {
        Crossing::Degenerate
    } else {
        Crossing::None
    }
}

fn strictly_one_side(s: &[i8]) -> bool {
    s[0] != 0 && s.iter().all(|&x| x == s[0])
}

/// Exactly whether the closed, non-degenerate triangles `a` and `b` share
/// a point (touching counts).
pub fn triangles_intersect(a: [Point3; 3], b: [Point3; 3]) -> bool {
    let sb = b.map(|p| sign3(a[0], a[1], a[2], p));
    if strictly_one_side(&sb) {
        return false;
    }
    let sa = a.map(|p| sign3(b[0], b[1], b[2], p));
    if strictly_one_side(&sa) {
        return false;
    }
    if sb == [0, 0, 0] {
        let axis = drop_axis(a);
        let (a2, b2) = (project_all(a, axis), project_all(b, axis));
        return !triangle_separates(a2, &b2) && !triangle_separates(b2, &a2);
    }
    (0..3).any(|i| {
        let j = (i + 1) % 3;
        segment_meets_with_sides(a[i], a[j], sa[i], sa[j], b) || segment_meets_with_sides(b[i], b[j], sb[i], sb[j], a)
    })
}

/// Whether triangles of one surface that share corners meet anywhere
/// else: the first `shared` corners coincide (`a[k] == b[k]` for
/// `k < shared`). With one shared corner, true when they meet at another
/// point; with two (a shared edge), true when they meet off that edge,
/// which for distinct planes never happens and for one plane means they
/// are folded onto each other (third corners on the same side of the
/// edge). Three shared corners are the same triangle twice: true.
/// Both must be non-degenerate.
pub fn adjacent_triangles_overlap(a: [Point3; 3], b: [Point3; 3], shared: usize) -> bool {
    debug_assert!((0..shared.min(3)).all(|k| a[k] == b[k]), "shared corners must come first");
    match shared {
        0 => triangles_intersect(a, b),
        1 => shared_corner_overlap(a, b),
        2 => shared_edge_overlap(a, b),
        _ => true,
    }
}

/// Distinct planes meet only in the edge's line, and each triangle meets
/// that line only in the edge; in one plane they overlap when folded.
/// The folding is asked first, in a projection: for the surfaces of
/// solids the third corners almost always lie on opposite sides of the
/// edge there, which settles it without the exact coplanarity test (slow
/// exactly where it matters: adjacent triangles of one flat face).
fn shared_edge_overlap(a: [Point3; 3], b: [Point3; 3]) -> bool {
    let axis = drop_axis(a);
    let (u, v) = (project(a[0], axis), project(a[1], axis));
    let side = sign2(u, v, project(a[2], axis));
    side == sign2(u, v, project(b[2], axis)) && sign3(a[0], a[1], a[2], b[2]) == 0
}

/// The intersection is convex and holds the corner `s`. If it holds a
/// point `x` besides, the ray from `s` through `x` leaves each triangle
/// through its edge opposite `s`, and of the two exits the nearer one lies
/// in both triangles: so an opposite edge meets the other triangle, and
/// that edge cannot pass through `s`.
fn shared_corner_overlap(a: [Point3; 3], b: [Point3; 3]) -> bool {
    // Either pair of corners on one side of the other plane leaves only
    // `s` in common; on a smooth surface one of the two almost always
    // does, and the filter alone can tell.
    if certainly_one_side(b, a[1], a[2]) || certainly_one_side(a, b[1], b[2]) {
        return false;
    }
    let (a1, a2) = (sign3(b[0], b[1], b[2], a[1]), sign3(b[0], b[1], b[2], a[2]));
    let (b1, b2) = (sign3(a[0], a[1], a[2], b[1]), sign3(a[0], a[1], a[2], b[2]));
    segment_meets_with_sides(a[1], a[2], a1, a2, b) || segment_meets_with_sides(b[1], b[2], b1, b2, a)
}

/// Whether two triangles of one surface, given with their vertex indices,
/// meet anywhere other than at the corners they share by index: shared
/// corners are moved to the front and [`adjacent_triangles_overlap`]
/// decides; without shared corners, [`triangles_intersect`].
pub fn surface_triangles_overlap(a: [Point3; 3], ia: [u32; 3], b: [Point3; 3], ib: [u32; 3]) -> bool {
    let mut pairs = [(0usize, 0usize); 3];
    let mut n = 0;
    for (i, x) in ia.iter().enumerate() {
        if let Some(j) = ib.iter().position(|y| y == x) {
            if n < 3 {
                pairs[n] = (i, j);
            }
            n += 1;
        }
    }
    match n {
        0 => triangles_intersect(a, b),
        1 => {
            let (i, j) = pairs[0];
            let (ra, rb) = ([a[i], a[(i + 1) % 3], a[(i + 2) % 3]], [b[j], b[(j + 1) % 3], b[(j + 2) % 3]]);
            shared_corner_overlap(ra, rb)
        }
        2 => {
            let [(i0, j0), (i1, j1), _] = pairs;
            if j0 == j1 {
                // `b` names one vertex twice: degenerate, it touches `a`.
                return true;
            }
            shared_edge_overlap([a[i0], a[i1], a[3 - i0 - i1]], [b[j0], b[j1], b[3 - j0 - j1]])
        }
        _ => true,
    }
}

#[cfg(test)]
mod tests {
    //! The oracle is independent of the predicates: the points common to
    //! two figures are the solutions `x ≥ 0` of a linear system in their
    //! barycentric coordinates, a polytope whose corners (basic feasible
    //! solutions) are found by solving every square subsystem exactly in
    //! rationals. Inputs are small integers (many coplanar, touching and
    //! collinear configurations), also scaled and shifted exactly.
    use super::*;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

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
    fn sub(a: Q, b: Q) -> Q {
        q(a.0 * b.1 - b.0 * a.1, a.1 * b.1)
    }
    fn mul(a: Q, b: Q) -> Q {
        q(a.0 * b.0, a.1 * b.1)
    }
    fn div(a: Q, b: Q) -> Q {
        q(a.0 * b.1, a.1 * b.0)
    }

    /// The corners of `{x ≥ 0 : Σ x_j cols[j] = rhs}`.
    fn corners(cols: &[[i128; 5]], rhs: [i128; 5]) -> Vec<Vec<Q>> {
        let k = cols.len();
        let mut out = Vec::new();
        'subsets: for mask in 1u32..(1 << k) {
            let s: Vec<usize> = (0..k).filter(|&j| mask >> j & 1 == 1).collect();
            let mut m: Vec<Vec<Q>> =
                (0..5).map(|r| s.iter().map(|&j| q(cols[j][r], 1)).chain([q(rhs[r], 1)]).collect()).collect();
            for c in 0..s.len() {
                let Some(r) = (c..5).find(|&r| m[r][c].0 != 0) else { continue 'subsets };
                m.swap(c, r);
                let pivot = m[c][c];
                m[c] = m[c].iter().map(|&v| div(v, pivot)).collect();
                for r in (0..5).filter(|&r| r != c) {
                    let f = m[r][c];
                    m[r] = (0..=s.len()).map(|j| sub(m[r][j], mul(f, m[c][j]))).collect();
                }
            }
            if (s.len()..5).any(|r| m[r][s.len()].0 != 0) || (0..s.len()).any(|c| m[c][s.len()].0 < 0) {
                continue;
            }
            let mut x = vec![q(0, 1); k];
            for (c, &j) in s.iter().enumerate() {
                x[j] = m[c][s.len()];
            }
            out.push(x);
        }
        out
    }

    type I3 = [i128; 3];

    /// Corners of `Σ λ_i f_i = Σ μ_j g_j`, `Σ λ = 1`, `Σ μ = 1`.
    fn meet(f: &[I3], g: &[I3]) -> Vec<Vec<Q>> {
        let col =
            |p: I3, sign: i128, first: bool| [sign * p[0], sign * p[1], sign * p[2], first as i128, (!first) as i128];
        let cols: Vec<[i128; 5]> =
            f.iter().map(|&p| col(p, 1, true)).chain(g.iter().map(|&p| col(p, -1, false))).collect();
        corners(&cols, [0, 0, 0, 1, 1])
    }

    fn degenerate(t: [I3; 3]) -> bool {
        let (u, v) = ([0, 1, 2].map(|i| t[1][i] - t[0][i]), [0, 1, 2].map(|i| t[2][i] - t[0][i]));
        u[1] * v[2] == u[2] * v[1] && u[2] * v[0] == u[0] * v[2] && u[0] * v[1] == u[1] * v[0]
    }

    /// Integer coordinates as exact `f64`, scaled and shifted by `mode`.
    fn pt(p: I3, mode: u8) -> Point3 {
        let f = |c: i128| match mode {
            0 => c as f64,
            1 => c as f64 * 2f64.powi(-30) + 1024.0,
            _ => c as f64 * 2f64.powi(40) - 3.0 * 2f64.powi(44),
        };
        Point3::new(f(p[0]), f(p[1]), f(p[2]))
    }
    fn tri(t: [I3; 3], mode: u8) -> [Point3; 3] {
        t.map(|p| pt(p, mode))
    }

    fn random_point(rng: &mut SmallRng, r: i128) -> I3 {
        [0; 3].map(|_| rng.gen_range(-r..=r))
    }

    /// Points of one random integer plane `o + x u + y v`.
    fn planar(rng: &mut SmallRng, basis: &[I3; 3], r: i128) -> I3 {
        let (x, y) = (rng.gen_range(-r..=r), rng.gen_range(-r..=r));
        [0, 1, 2].map(|i| basis[0][i] + x * basis[1][i] + y * basis[2][i])
    }

    fn random_pair(rng: &mut SmallRng, case: usize) -> ([I3; 3], [I3; 3]) {
        loop {
            let basis = [random_point(rng, 2), random_point(rng, 2), random_point(rng, 2)];
            let gen = |rng: &mut SmallRng| match case % 3 {
                0 => random_point(rng, 2),
                1 => random_point(rng, 5),
                _ => planar(rng, &basis, 3),
            };
            let a = [gen(rng), gen(rng), gen(rng)];
            let b = [gen(rng), gen(rng), gen(rng)];
            if !degenerate(a) && !degenerate(b) {
                return (a, b);
            }
        }
    }

    #[test]
    fn triangles_intersect_as_the_rational_oracle_says() {
        let mut rng = SmallRng::seed_from_u64(19);
        let (mut hits, mut coplanar_hits) = (0, 0);
        for case in 0..3000 {
            let (a, b) = random_pair(&mut rng, case);
            let expected = !meet(&a, &b).is_empty();
            let mode = (case % 7 % 3) as u8;
            assert_eq!(triangles_intersect(tri(a, mode), tri(b, mode)), expected, "{a:?} {b:?} mode {mode}");
            assert_eq!(triangles_intersect(tri(b, mode), tri(a, mode)), expected, "{b:?} {a:?}");
            hits += expected as usize;
            coplanar_hits += (expected && case % 3 == 2) as usize;
        }
        assert!(hits > 500 && coplanar_hits > 200, "{hits} {coplanar_hits}");
    }

    #[test]
    fn segment_crossings_as_the_rational_oracle_says() {
        let mut rng = SmallRng::seed_from_u64(7);
        let mut seen = [0; 3];
        for case in 0..3000 {
            let (t, b) = random_pair(&mut rng, case);
            let (p, qq) = (b[0], if case % 5 == 0 { b[0] } else { b[1] });
            let c = meet(&[p, qq], &t);
            let expected = if c.is_empty() {
                Crossing::None
            } else if c.iter().all(|x| x == &c[0] && x.iter().all(|v| v.0 > 0)) {
                Crossing::Proper
            } else {
                Crossing::Degenerate
            };
            let mode = (case % 3) as u8;
            let (p3, q3) = (pt(p, mode), pt(qq, mode));
            if p != qq {
                assert_eq!(segment_crosses_triangle(p3, q3, tri(t, mode)), expected, "{p:?} {qq:?} {t:?}");
                assert_eq!(segment_crosses_triangle(q3, p3, tri(t, mode)), expected);
            }
            assert_eq!(segment_meets_triangle(p3, q3, tri(t, mode)), expected != Crossing::None);
            assert_eq!(triangle_contains(tri(t, mode), p3), !meet(&[p], &t).is_empty(), "{p:?} {t:?}");
            let t3 = tri(t, mode);
            let filtered = certain_sign3(t3[0], t3[1], t3[2], q3);
            assert!(filtered.is_none_or(|s| s == sign3(t3[0], t3[1], t3[2], q3)));
            seen[expected as usize] += 1;
        }
        assert!(seen.iter().all(|&n| n > 100), "{seen:?}");
    }

    #[test]
    fn adjacent_rules_as_the_rational_oracle_says() {
        let mut rng = SmallRng::seed_from_u64(3);
        let mut overlaps = [0; 2];
        for case in 0..3000 {
            let shared = 1 + case % 2;
            let (a, mut b) = random_pair(&mut rng, case / 2);
            b[..shared].copy_from_slice(&a[..shared]);
            if degenerate(b) || a[2] == b[2] || (shared == 1 && (a[1..].contains(&b[1]) || a[1..].contains(&b[2]))) {
                continue;
            }
            let c = meet(&a, &b);
            let expected = match shared {
                1 => c.iter().any(|x| x[0] != q(1, 1)),
                _ => c.iter().any(|x| x[2].0 > 0),
            };
            overlaps[shared - 1] += expected as usize;
            let mode = (case % 3) as u8;
            let (a3, b3) = (tri(a, mode), tri(b, mode));
            assert_eq!(adjacent_triangles_overlap(a3, b3, shared), expected, "{a:?} {b:?}");
            assert_eq!(adjacent_triangles_overlap(b3, a3, shared), expected, "{b:?} {a:?}");
            // The same pair named by indices, in rotated and reversed order.
            let (ia, ib) = ([0u32, 1, 2], if shared == 1 { [0u32, 3, 4] } else { [0u32, 1, 3] });
            let r = case % 3;
            let rot = |t: [Point3; 3], i: [u32; 3]| {
                ([t[r], t[(r + 2) % 3], t[(r + 1) % 3]], [i[r], i[(r + 2) % 3], i[(r + 1) % 3]])
            };
            let ((ra, ria), (rb, rib)) = (rot(a3, ia), rot(b3, ib));
            assert_eq!(surface_triangles_overlap(ra, ria, b3, ib), expected, "{a:?} {b:?}");
            assert_eq!(surface_triangles_overlap(rb, rib, a3, ia), expected, "{a:?} {b:?}");
        }
        assert!(overlaps.iter().all(|&n| n > 100), "{overlaps:?}");
    }

    #[test]
    fn named_configurations() {
        let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
        let a = [p(0.0, 0.0, 0.0), p(4.0, 0.0, 0.0), p(0.0, 4.0, 0.0)];
        // A corner of one lying inside the other: touching counts.
        assert!(triangles_intersect(a, [p(1.0, 1.0, 0.0), p(1.0, 1.0, 3.0), p(2.0, 1.0, 3.0)]));
        assert!(!triangles_intersect(a, [p(1.0, 1.0, 1e-300), p(1.0, 1.0, 3.0), p(2.0, 1.0, 3.0)]));
        // Coplanar and overlapping, coplanar and apart.
        assert!(triangles_intersect(a, [p(1.0, 1.0, 0.0), p(5.0, 1.0, 0.0), p(1.0, 5.0, 0.0)]));
        assert!(!triangles_intersect(a, [p(3.0, 3.0, 0.0), p(5.0, 3.0, 0.0), p(3.0, 5.0, 0.0)]));
        // Folded onto each other across a shared edge, and a proper fold.
        let folded = [p(0.0, 0.0, 0.0), p(4.0, 0.0, 0.0), p(1.0, 1.0, 0.0)];
        assert!(adjacent_triangles_overlap(a, folded, 2));
        assert!(!adjacent_triangles_overlap(a, [a[0], a[1], p(1.0, -1.0, 0.0)], 2));
        assert!(!adjacent_triangles_overlap(a, [a[0], a[1], p(1.0, 1.0, 1.0)], 2));
        // A shared corner with an edge of one through the other.
        assert!(adjacent_triangles_overlap(a, [a[0], p(2.0, 2.0, -1.0), p(2.0, 2.0, 1.0)], 1));
        assert!(!adjacent_triangles_overlap(a, [a[0], p(-2.0, 2.0, -1.0), p(-2.0, 2.0, 1.0)], 1));
        let s = segment_crosses_triangle(p(1.0, 1.0, -1.0), p(1.0, 1.0, 1.0), a);
        assert_eq!(s, Crossing::Proper);
        assert_eq!(segment_crosses_triangle(p(2.0, 0.0, -1.0), p(2.0, 0.0, 1.0), a), Crossing::Degenerate);
        assert_eq!(segment_crosses_triangle(p(5.0, 5.0, -1.0), p(5.0, 5.0, 1.0), a), Crossing::None);
    }
}
