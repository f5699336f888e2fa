//! Constructions: new points from existing geometry, rounded to `f64`.
//!
//! Results carry the rounding of a few floating-point operations (relative
//! error a small multiple of 2^-53 of the input magnitudes) except near
//! tangency or parallelism, where the problem itself is ill-conditioned;
//! callers compare results against a length tolerance, never for equality.

use super::Point;

/// Intersection points of two lines given as point + direction (directions
/// need not be unit). Returns `None` for parallel lines. The result is
/// `p + s·u` with the parameter `s` reported too.
pub fn line_line(p: Point, u: Point, q: Point, v: Point) -> Option<(Point, f64, f64)> {
    let den = u.cross(v);
    if den == 0.0 || !den.is_finite() {
        return None;
    }
    let w = q - p;
    let s = w.cross(v) / den;
    let t = w.cross(u) / den;
    Some((p + u * s, s, t))
}

/// The circle through three points (centre, radius); `None` when they are
/// collinear within rounding (the centre would be meaningless).
pub fn circumcircle(a: Point, b: Point, c: Point) -> Option<(Point, f64)> {
    let (ab, ac) = (b - a, c - a);
    let d = 2.0 * ab.cross(ac);
    if d.abs() <= f64::EPSILON * (ab.norm2() + ac.norm2()) {
        return None;
    }
    let (l1, l2) = (ab.norm2(), ac.norm2());
    let o = a + Point::new(ac.y * l1 - ab.y * l2, ab.x * l2 - ac.x * l1) * (1.0 / d);
    Some((o, o.dist(a)))
}

/// Intersection points of the line `p + s·u` with the circle (`c`, `r`), as
/// line parameters `s` in increasing order: zero, one (tangent within
/// rounding) or two.
pub fn line_circle(p: Point, u: Point, c: Point, r: f64) -> Vec<f64> {
    let uu = u.norm2();
    if uu == 0.0 {
        return Vec::new();
    }
    // Work from the foot of the perpendicular from c, and factor
    // r² − dist² = (r − dist)(r + dist): stable for huge nearly flat circles.
    let s0 = (c - p).dot(u) / uu;
    let foot = p + u * s0;
    let dist = (c - foot).norm();
    let h2 = (r - dist) * (r + dist);
    if h2 < 0.0 {
        return Vec::new();
    }
    if h2 == 0.0 {
        return vec![s0];
    }
    let ds = (h2 / uu).sqrt();
    vec![s0 - ds, s0 + ds]
}

/// Intersection points of two circles; empty when they do not meet or are
/// concentric. Tangent circles give one point.
pub fn circle_circle(c1: Point, r1: f64, c2: Point, r2: f64) -> Vec<Point> {
    // Measure from the smaller circle, and factor d² − R² = (d − R)(d + R):
    // with one huge radius the textbook form loses most of its digits.
    let (cs, rs, cb, rb) = if r1 <= r2 { (c1, r1, c2, r2) } else { (c2, r2, c1, r1) };
    let dv = cb - cs;
    let d = dv.norm();
    if d == 0.0 {
        return Vec::new();
    }
    let u = dv * (1.0 / d);
    let a = ((d - rb) * (d + rb) + rs * rs) / (2.0 * d);
    let h2 = (rs - a) * (rs + a);
    if h2 < 0.0 {
        return Vec::new();
    }
    let base = cs + u * a;
    if h2 == 0.0 {
        return vec![base];
    }
    let h = h2.sqrt();
    vec![base + u.perp() * h, base - u.perp() * h]
}

/// The angle `x` (radians) shifted by whole turns to within π of `mid`.
pub fn unwrap_near(x: f64, mid: f64) -> f64 {
    let y = x - mid + std::f64::consts::PI;
    // `rem_euclid` returns a value already in [0, 2π) unchanged: skip its
    // division there (this runs for every footpoint of every base case).
    let y = if (0.0..std::f64::consts::TAU).contains(&y) { y } else { y.rem_euclid(std::f64::consts::TAU) };
    mid + y - std::f64::consts::PI
}

/// Orthogonal projection parameter of `p` on the line `a + s·(b − a)`.
pub fn project_param(a: Point, b: Point, p: Point) -> f64 {
    let d = b - a;
    let dd = d.norm2();
    if dd == 0.0 {
        0.0
    } else {
        (p - a).dot(d) / dd
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_circle_meets_at_expected_points() {
        let pts = circle_circle(Point::new(0.0, 0.0), 5.0, Point::new(8.0, 0.0), 5.0);
        assert_eq!(pts.len(), 2);
        for p in pts {
            assert!((p.x - 4.0).abs() < 1e-12 && (p.y.abs() - 3.0).abs() < 1e-12);
        }
        assert!(circle_circle(Point::new(0.0, 0.0), 1.0, Point::new(3.0, 0.0), 1.0).is_empty());
    }

    #[test]
    fn circle_circle_keeps_digits_with_a_huge_radius() {
        // A circle of radius 1e6 through (0, 0) and (−60, −40) ... meets the
        // unit-scale circle at two points that must lie on both circles to
        // ~1e-10 (the textbook formula was off by ~1e-6 here).
        let (cb, rb) = (Point::new(0.0, 1e6), 1e6);
        let (cs, rs) = (Point::new(30.0, 0.0), 37.5);
        let pts = circle_circle(cb, rb, cs, rs);
        assert_eq!(pts.len(), 2);
        for p in pts {
            assert!((p.dist(cb) - rb).abs() < 1e-9, "{}", p.dist(cb) - rb);
            assert!((p.dist(cs) - rs).abs() < 1e-12);
        }
    }

    #[test]
    fn line_circle_finds_both_crossings() {
        let s = line_circle(Point::new(-10.0, 3.0), Point::new(1.0, 0.0), Point::new(0.0, 0.0), 5.0);
        assert_eq!(s.len(), 2);
        assert!((s[0] - 6.0).abs() < 1e-12 && (s[1] - 14.0).abs() < 1e-12);
    }

    #[test]
    fn parallel_lines_have_no_intersection() {
        assert!(
            line_line(Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(0.0, 1.0), Point::new(2.0, 2.0)).is_none()
        );
        let (p, _, _) =
            line_line(Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(2.0, -1.0), Point::new(0.0, 3.0)).unwrap();
        assert_eq!(p, Point::new(2.0, 0.0));
    }
}
