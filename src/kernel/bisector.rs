//! The medial-axis curve of two sites: the centres of disks tangent to both
//! (thesis 2.2.3: lines, parabolas, ellipses and hyperbolas).
//!
//! Each site fixes the radius of a tangent disk as a function of its centre:
//! ρ = ε·|c − f| + k around a focus f (a point: ε = 1, k = 0; a circle of
//! radius R touched from outside: ε = 1, k = −R; nested with the disk:
//! ρ = |R − |c − f|| with the sign of R − ρ), or ρ = n·(c − a) for a line.
//! Equating two of them gives a difference of focal distances (hyperbola,
//! a line when it is zero), a sum (ellipse), a focal distance against a
//! line distance (parabola) or two line distances (line).
//!
//! Points are produced by the footpoint parametrisation: walk along the
//! first site, grow the disk tangent there until it touches the second
//! site. That is the maximal-disk construction of Figure 2.2 with a fixed
//! second site, it is closed form, and it covers every kind of curve
//! (radius parametrisations fail where the radius is constant, as between
//! parallel lines).

use super::apollonius::Site;
use super::direction::angle_of;
use super::growing_disk::GrowingDisk;
use super::Point;

/// The kind of conic the two sites' tangent-disk centres lie on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConicKind {
    /// A straight line.
    Line,
    /// A parabola.
    Parabola,
    /// An ellipse.
    Ellipse,
    /// A hyperbola branch.
    Hyperbola,
}

/// The focal sign ε of a site: +1 when the radius grows with the distance
/// from the focus, −1 when it shrinks (a disk inside a circle); `None`
/// for a line.
fn focal_sign(s: &Site, inside_circle: bool) -> Option<f64> {
    match s {
        Site::Line { .. } => None,
        Site::Point(_) => Some(1.0),
        Site::Circle { outside: true, .. } => Some(1.0),
        Site::Circle { outside: false, .. } => Some(if inside_circle { -1.0 } else { 1.0 }),
    }
}

/// The conic through the centres of disks tangent to `a` and `b`, for
/// disks that lie inside each nested circle when `inside` says so (ignored
/// for other sites). A hyperbola whose focal difference is zero is a line.
pub fn conic_kind(a: &Site, b: &Site, inside: [bool; 2]) -> ConicKind {
    let focal_k = |s: &Site| match *s {
        Site::Circle { r, outside: true, .. } => -r,
        // Nested: ρ = R − |c − o| (disk inside) or |c − o| + R (circle inside).
        Site::Circle { r, outside: false, .. } => r,
        _ => 0.0,
    };
    match (focal_sign(a, inside[0]), focal_sign(b, inside[1])) {
        (None, None) => ConicKind::Line,
        (Some(_), None) | (None, Some(_)) => ConicKind::Parabola,
        (Some(ea), Some(eb)) if ea == eb => {
            if focal_k(a) == focal_k(b) {
                ConicKind::Line
            } else {
                ConicKind::Hyperbola
            }
        }
        _ => ConicKind::Ellipse,
    }
}

/// A boundary point of site `a` at parameter `u` and the unit normal there
/// pointing to where `a`'s tangent disk centres lie: for a line, `u` is the
/// distance along it from its anchor (direction: the normal turned
/// clockwise); for a point or circle, `u` is the angle in radians of the
/// direction from the centre.
pub fn footpoint(a: &Site, u: f64) -> (Point, Point) {
    match *a {
        Site::Line { a, n } => (a + (-n.perp()) * u, n),
        Site::Point(q) => (q, Point::new(u.cos(), u.sin())),
        Site::Circle { o, r, outside } => {
            let dir = Point::new(u.cos(), u.sin());
            // Outside: the centre lies beyond the circle. Nested (either
            // way round): the centre lies on the other side of the centre.
            (o + dir * r, if outside { dir } else { -dir })
        }
    }
}

/// The footpoint parameter of the disk centred `c` of radius `r` tangent
/// to `a`: the inverse of [`footpoint`] (for a line the distance along it,
/// for a point or circle the angle of the centre's direction, radians in
/// (−π, π]: a caller with a range of angles unwraps it there). Radius 0
/// gives the parameter of the centre's projection on a line.
#[inline]
pub fn footpoint_param(a: &Site, c: Point, r: f64) -> f64 {
    match *a {
        Site::Line { a, n } => (c - n * r - a).dot(-n.perp()),
        Site::Point(q) => angle_of(c - q),
        Site::Circle { o, .. } => angle_of(c - o),
    }
}

/// The footpoint parameter of `foot`, a point of `a` where a disk centred
/// `c` touches it: the inverse of [`footpoint`] from the touching point
/// itself (only a point site needs the centre, whose direction is the
/// parameter).
#[inline]
pub fn footpoint_param_at(a: &Site, c: Point, foot: Point) -> f64 {
    match *a {
        Site::Line { a, n } => (foot - a).dot(-n.perp()),
        Site::Point(q) => angle_of(c - q),
        Site::Circle { o, .. } => angle_of(foot - o),
    }
}

impl GrowingDisk {
    /// The radius at which the disk touches `site` as the site's kind says:
    /// the unique solution of a linear equation in the radius, `None` when
    /// it is not positive.
    pub fn touch_site(&self, site: &Site) -> Option<f64> {
        let t = match *site {
            Site::Point(q) => return self.through_point(q),
            // m·(p + t·n − a) = t.
            Site::Line { a, n: m } => m.dot(self.p - a) / (1.0 - m.dot(self.n)),
            // |w + t·n| = t + σR, w = p − o.
            Site::Circle { o, r, outside } => {
                let s = if outside { 1.0 } else { -1.0 };
                let w = self.p - o;
                let wl = w.norm();
                (r - wl) * (r + wl) / (2.0 * (self.n.dot(w) - s * r))
            }
        };
        (t.is_finite() && t > 0.0).then_some(t)
    }
}

/// The centre and radius of the disk tangent to `a` at its footpoint `u`
/// (see [`footpoint`]) and tangent to `b`, if there is one.
pub fn bisector_point(a: &Site, b: &Site, u: f64) -> Option<(Point, f64)> {
    let (p, n) = footpoint(a, u);
    let g = GrowingDisk { p, n };
    let t = g.touch_site(b)?;
    Some((g.center(t), t))
}

/// The radius (model units) of the disk centred `c` tangent to `s` as its
/// kind says, a disk nested in a circle lying inside it; negative where
/// `c` lies on the wrong side.
pub fn site_radius(s: &Site, c: Point) -> f64 {
    match *s {
        Site::Point(q) => c.dist(q),
        Site::Line { a, n } => n.dot(c - a),
        Site::Circle { o, r, outside: true } => c.dist(o) - r,
        Site::Circle { o, r, outside: false } => r - c.dist(o),
    }
}

/// [`site_radius`] and its gradient in `c`; `None` at a point or circle
/// centre, where the gradient is undefined.
fn tangent_radius(s: &Site, c: Point) -> Option<(f64, Point)> {
    let away = |q: Point| {
        let d = c - q;
        let l = d.norm();
        (l > 0.0).then(|| d * (1.0 / l))
    };
    let gradient = match *s {
        Site::Line { n, .. } => n,
        Site::Point(q) | Site::Circle { o: q, outside: true, .. } => away(q)?,
        Site::Circle { o, outside: false, .. } => -away(o)?,
    };
    Some((site_radius(s, c), gradient))
}

/// The disk nearest to tangent to both `a` and `b` reached from `p` along
/// the bisector's normal: Newton steps on the difference of the two
/// tangent radii, each kept only when it shrinks that difference and moves
/// less than `reach` (model units), stopping at a step below 10^-15 of
/// `reach`; the radius is the mean of the two tangent radii, so the disk
/// misses each site by half their difference. Well conditioned where the
/// footpoint parametrisation is not: along a stretch where both footpoints
/// barely move (the disks slide along their normals, as near the axis of
/// two arcs of nearly one circle), the curve is nearly straight and a
/// point near it has one nearest bisector point; where the two sites are
/// circles tangent within rounding, the curve is their common normal and
/// the difference has no root, only a minimum there, which the kept steps
/// approach. `None` only when `p` is a focus.
pub fn bisector_point_near(a: &Site, b: &Site, p: Point, reach: f64) -> Option<(Point, f64)> {
    let (mut ra, mut ga) = tangent_radius(a, p)?;
    let (mut rb, mut gb) = tangent_radius(b, p)?;
    let mut c = p;
    for _ in 0..32 {
        let g = ga - gb;
        let g2 = g.norm2();
        if g2 == 0.0 {
            break;
        }
        let step = g * ((ra - rb) / g2);
        let len = step.norm();
        let next = c - step;
        let (Some((na, nga)), Some((nb, ngb))) = (tangent_radius(a, next), tangent_radius(b, next)) else { break };
        if len > reach || (na - nb).abs() >= (ra - rb).abs() {
            break;
        }
        (c, ra, ga, rb, gb) = (next, na, nga, nb, ngb);
        if len <= 1e-15 * reach {
            break;
        }
    }
    Some((c, 0.5 * (ra + rb)))
}

/// Samples the bisector of `a` and `b` between footpoint parameters `u0`
/// and `u1` so that the polyline through the samples deviates from the
/// curve by at most `tol` (checked at the middle of every span, after at
/// least `8` initial spans), as `(centre, radius, u)`. Stops refining a
/// span at 2^-40 of the parameter range. `None` if some parameter has no
/// tangent disk.
pub fn sample_bisector(a: &Site, b: &Site, u0: f64, u1: f64, tol: f64) -> Option<Vec<(Point, f64, f64)>> {
    let at = |u: f64| bisector_point(a, b, u).map(|(c, r)| (c, r, u));
    sample_between(a, b, at(u0)?, at(u1)?, tol)
}

/// [`sample_bisector`] between two given end samples `(centre, radius, u)`,
/// which are kept as they are: ends computed by better-conditioned
/// constructions (a branch point), or where the footpoint construction
/// degenerates (radius 0 at a convex corner). `None` if an inner parameter
/// has no tangent disk.
pub fn sample_between(a: &Site, b: &Site, start: Sample, end: Sample, tol: f64) -> Option<Vec<(Point, f64, f64)>> {
    sample_along(|u: f64| bisector_point(a, b, u).map(|(c, r)| (c, r, u)), start, end, tol)
}

/// [`sample_between`] for any parametrisation `at` of the curve (a sample
/// carries its parameter last).
pub fn sample_along(at: impl Fn(f64) -> Option<Sample>, start: Sample, end: Sample, tol: f64) -> Option<Vec<Sample>> {
    let (u0, u1) = (start.2, end.2);
    let mut out = vec![start];
    let spans = 8;
    let min_span = (u1 - u0).abs() * (2f64).powi(-40);
    for k in 0..spans {
        let lo = out.last().copied()?;
        let hi = if k + 1 == spans { end } else { at(u0 + (u1 - u0) * (k + 1) as f64 / spans as f64)? };
        refine(&at, lo, hi, tol, min_span, &mut out)?;
    }
    Some(out)
}

/// A sample: centre, radius, footpoint parameter.
pub type Sample = (Point, f64, f64);

/// Appends samples strictly after `lo` up to and including `hi`.
fn refine(
    at: &impl Fn(f64) -> Option<Sample>,
    lo: Sample,
    hi: Sample,
    tol: f64,
    min_span: f64,
    out: &mut Vec<Sample>,
) -> Option<()> {
    let mid = at(0.5 * (lo.2 + hi.2))?;
    let chord = hi.0 - lo.0;
    let len = chord.norm();
    let off = if len > 0.0 { chord.cross(mid.0 - lo.0).abs() / len } else { mid.0.dist(lo.0) };
    if off > tol && (hi.2 - lo.2).abs() > min_span {
        refine(at, lo, mid, tol, min_span, out)?;
        refine(at, mid, hi, tol, min_span, out)
    } else {
        out.push(hi);
        Some(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn random_site(rng: &mut impl Rng) -> Site {
        let p = Point::new(rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0));
        match rng.gen_range(0..3) {
            0 => Site::Point(p),
            1 => {
                let t: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
                Site::Line { a: p, n: Point::new(t.cos(), t.sin()) }
            }
            _ => Site::Circle { o: p, r: rng.gen_range(0.2..3.0), outside: rng.gen_bool(0.5) },
        }
    }

    #[test]
    fn every_bisector_point_is_tangent_to_both_sites() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(21);
        let mut points = 0;
        for _ in 0..3000 {
            let (a, b) = (random_site(&mut rng), random_site(&mut rng));
            for _ in 0..10 {
                let u = rng.gen_range(-6.0..6.0);
                let Some((c, r)) = bisector_point(&a, &b, u) else { continue };
                let scale = 1.0 + r + c.norm();
                assert!(a.defect(c, r).abs() < 1e-9 * scale, "{a:?} {b:?} {u}: {c:?} {r}");
                assert!(b.defect(c, r).abs() < 1e-9 * scale, "{a:?} {b:?} {u}: {c:?} {r}");
                // The disk touches `a` at the footpoint.
                let (p, _) = footpoint(&a, u);
                assert!((c.dist(p) - r).abs() < 1e-9 * scale);
                points += 1;
            }
        }
        assert!(points > 10_000, "{points}");
    }

    #[test]
    fn a_point_moved_off_the_bisector_comes_back_to_it() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(22);
        let (mut found, mut tried) = (0, 0);
        for _ in 0..3000 {
            let (a, b) = (random_site(&mut rng), random_site(&mut rng));
            let Some((c, r)) = bisector_point(&a, &b, rng.gen_range(-6.0..6.0)) else { continue };
            // Interior disks only: a nested circle holds its disk.
            let holds = |s: &Site| tangent_radius(s, c).is_some_and(|(t, _)| (t - r).abs() < 1e-9 * (1.0 + r));
            if !holds(&a) || !holds(&b) {
                continue;
            }
            tried += 1;
            // Off by 10^-4 of the radius in a random direction.
            let t: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
            let p = c + Point::new(t.cos(), t.sin()) * (1e-4 * r);
            let Some((q, rq)) = bisector_point_near(&a, &b, p, 1e-3 * r) else { continue };
            let scale = 1.0 + r + c.norm();
            if a.defect(q, rq).abs() > 1e-9 * scale || b.defect(q, rq).abs() > 1e-9 * scale {
                // A focus or a tangency too flat for Newton: the point
                // stays where it was, never further off.
                assert!(
                    (a.defect(q, rq) - b.defect(q, rq)).abs() <= (a.defect(p, 0.0) - b.defect(p, 0.0)).abs() + 1e-12
                );
                continue;
            }
            // Back within the move (the normal's foot, not the start).
            assert!(q.dist(c) <= 2e-4 * r + 1e-9 * scale, "{a:?} {b:?}: {c:?} {q:?}");
            found += 1;
        }
        assert!(found > 1000 && found * 100 >= tried * 99, "{found} of {tried}");
    }

    #[test]
    fn two_circles_tangent_within_rounding_give_their_common_normal() {
        // Nested circles whose radii differ by their centres' distance plus
        // 2.5·10^-16: no two tangent radii are equal anywhere, and the
        // disks of the common normal touch both within rounding.
        let o0 = Point::new(-0.0032626364042669387, -0.0007712945076202016);
        let o1 = Point::new(-0.0032739115383865203, -0.0007757008758929596);
        let a = Site::Circle { o: o0, r: 0.995297555461604, outside: false };
        let b = Site::Circle { o: o1, r: 0.9952854498954968, outside: false };
        let normal = (o1 - o0).unit();
        for along in [0.01, 0.1, 0.3] {
            // Start 10^-6 off the normal.
            let p = o1 + normal * along + normal.perp() * 1e-6;
            let (c, r) = bisector_point_near(&a, &b, p, 0.3).unwrap();
            assert!(a.defect(c, r).abs() < 1e-12 && b.defect(c, r).abs() < 1e-12, "{along}: {c:?} {r}");
            // Within 10^-5 of the normal: |c − o0| − |c − o1| is rounding
            // (10^-16 of the distance) that far off, about δ·φ²/2 at an
            // angle φ from the normal, δ = |o1 − o0| = 1.2·10^-5.
            assert!((c - o1).cross(normal).abs() < 1e-5, "{along}: {c:?}");
        }
    }

    #[test]
    fn samples_follow_the_curve_within_the_tolerance() {
        // Point (0, 1) and the x axis: the parabola y = (x² + 1) / 2.
        let a = Site::Line { a: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) };
        let b = Site::Point(Point::new(0.0, 1.0));
        assert_eq!(conic_kind(&a, &b, [false, false]), ConicKind::Parabola);
        let tol = 1e-4;
        let s = sample_bisector(&a, &b, -3.0, 3.0, tol).unwrap();
        assert!(s.len() > 20 && s.len() < 400, "{}", s.len());
        for w in s.windows(2) {
            // Check the true curve between samples against the chord.
            for k in 1..10 {
                let x = w[0].0.x + (w[1].0.x - w[0].0.x) * k as f64 / 10.0;
                let y = (x * x + 1.0) / 2.0;
                let chord = w[1].0 - w[0].0;
                let off = chord.cross(Point::new(x, y) - w[0].0).abs() / chord.norm();
                assert!(off <= 1.01 * tol, "{off}");
            }
        }
        // The footpoint parameter runs along the line: the vertex at u = 0.
        assert!(s.iter().any(|&(c, r, _)| c.dist(Point::new(0.0, 0.5)) < 1e-12 && (r - 0.5).abs() < 1e-12));
    }

    #[test]
    fn conic_kinds() {
        let p = |x: f64, y: f64| Site::Point(Point::new(x, y));
        let c = |x: f64, r: f64, outside: bool| Site::Circle { o: Point::new(x, 0.0), r, outside };
        let l = Site::Line { a: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) };
        assert_eq!(conic_kind(&p(0.0, 1.0), &p(2.0, 1.0), [false; 2]), ConicKind::Line);
        assert_eq!(conic_kind(&l, &l, [false; 2]), ConicKind::Line);
        assert_eq!(conic_kind(&c(0.0, 1.0, true), &l, [false; 2]), ConicKind::Parabola);
        // A point inside a circle whose disks lie inside it: an ellipse.
        assert_eq!(conic_kind(&c(0.0, 3.0, false), &p(1.0, 0.0), [true, false]), ConicKind::Ellipse);
        assert_eq!(conic_kind(&c(0.0, 1.0, true), &p(3.0, 0.0), [false; 2]), ConicKind::Hyperbola);
        assert_eq!(conic_kind(&c(0.0, 1.0, true), &c(4.0, 2.0, true), [false; 2]), ConicKind::Hyperbola);
        assert_eq!(conic_kind(&c(0.0, 1.0, true), &c(4.0, 1.0, true), [false; 2]), ConicKind::Line);
        assert_eq!(conic_kind(&c(0.0, 5.0, false), &c(1.0, 1.0, true), [true, false]), ConicKind::Ellipse);
    }
}
