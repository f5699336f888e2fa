//! Exact orientation and in-circle signs of `f64` points in pure Rust: the
//! fallback of [`super::FilteredKernel`] when its error bound cannot decide.
//!
//! Why it is exact: every finite `f64` is `m · 2^e` with an integer
//! significand `|m| < 2^53` and `-1074 <= e <= 971` (subnormals included).
//! Take the smallest exponent `e0` among the nonzero inputs of one predicate;
//! then every input is the integer `m · 2^(e - e0)` times `2^e0`. Both
//! determinants are homogeneous polynomials of the coordinates (degree 2 for
//! orientation, 4 for in-circle), so dividing every coordinate by `2^e0`
//! multiplies the determinant by a positive power of two and leaves its sign
//! alone. The determinant of the integers is then evaluated with integer
//! additions, subtractions and multiplications in [`BigInt`], which never
//! round, overflow or underflow. So the sign is exact for every finite input,
//! without the exponent limits of floating-point expansion arithmetic.
//!
//! Cost: inputs span at most ~2100 bits (33 limbs), so even the worst case
//! is a few thousand limb multiplications; it only runs for nearly
//! degenerate input, where the filter cannot decide.
//!
//! With the `gmp` feature the kernel uses `super::exact` (GMP rationals)
//! instead and this module is built only for its tests, which cross-check
//! the two.

use super::bigint::{decompose, BigInt};
use super::{CircleSide, Orientation, Point};
use std::cmp::Ordering;

/// The coordinates as integers, all scaled by the same power of two.
fn scaled<const N: usize>(values: [f64; N]) -> [BigInt; N] {
    let parts = values.map(decompose);
    let e0 = parts.iter().filter(|p| p.1 != 0).map(|p| p.2).min().unwrap_or(0);
    // Zeros carry no exponent (e0 ignores them); for the others
    // 0 <= e - e0 <= 971 + 1074.
    parts.map(
        |(negative, m, e)| if m == 0 { BigInt::default() } else { BigInt::from_shifted(negative, m, (e - e0) as u32) },
    )
}

/// Exact orientation of `r` relative to the directed line `p → q`.
pub(crate) fn orientation(p: Point, q: Point, r: Point) -> Orientation {
    let [px, py, qx, qy, rx, ry] = scaled([p.x, p.y, q.x, q.y, r.x, r.y]);
    let l = &(&px - &rx) * &(&qy - &ry);
    let rr = &(&py - &ry) * &(&qx - &rx);
    match (&l - &rr).signum() {
        Ordering::Greater => Orientation::Left,
        Ordering::Less => Orientation::Right,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Exact sign of (q − p) × (s − r): homogeneous of degree 2, so the
/// common scaling leaves its sign alone.
pub(crate) fn cross_sign(p: Point, q: Point, r: Point, s: Point) -> Orientation {
    let [px, py, qx, qy, rx, ry, sx, sy] = scaled([p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y]);
    let l = &(&qx - &px) * &(&sy - &ry);
    let rr = &(&qy - &py) * &(&sx - &rx);
    match (&l - &rr).signum() {
        Ordering::Greater => Orientation::Left,
        Ordering::Less => Orientation::Right,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Exact side of `d` relative to the circle through counter-clockwise `a, b, c`.
pub(crate) fn circle_side(a: Point, b: Point, c: Point, d: Point) -> CircleSide {
    let [ax, ay, bx, by, cx, cy, dx, dy] = scaled([a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]);
    let rel = |x: &BigInt, y: &BigInt| {
        let (x, y) = (x - &dx, y - &dy);
        let lift = &(&x * &x) + &(&y * &y);
        (x, y, lift)
    };
    let (ax, ay, al) = rel(&ax, &ay);
    let (bx, by, bl) = rel(&bx, &by);
    let (cx, cy, cl) = rel(&cx, &cy);
    let bc = &(&bx * &cy) - &(&cx * &by);
    let ca = &(&cx * &ay) - &(&ax * &cy);
    let ab = &(&ax * &by) - &(&bx * &ay);
    let det = &(&(&al * &bc) + &(&bl * &ca)) + &(&cl * &ab);
    match det.signum() {
        Ordering::Greater => CircleSide::Inside,
        Ordering::Less => CircleSide::Outside,
        Ordering::Equal => CircleSide::On,
    }
}

/// `2^e` for `-1074 <= e <= 1023`, built from its bits: `powi` would
/// round through an overflowing or underflowing intermediate.
#[cfg(test)]
fn pow2(e: i32) -> f64 {
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::SmallRng, Rng, SeedableRng};

    // References computed independently in i128, exact for integer
    // coordinates below 2^60 (orientation) and 2^29 (in-circle).
    fn orientation_i128(p: [i128; 2], q: [i128; 2], r: [i128; 2]) -> Ordering {
        ((p[0] - r[0]) * (q[1] - r[1]) - (p[1] - r[1]) * (q[0] - r[0])).cmp(&0)
    }

    fn incircle_i128(pts: [[i128; 2]; 4]) -> Ordering {
        let d = pts[3];
        let [a, b, c] = [0, 1, 2].map(|i| [pts[i][0] - d[0], pts[i][1] - d[1]]);
        let lift = |v: [i128; 2]| v[0] * v[0] + v[1] * v[1];
        let det = lift(a) * (b[0] * c[1] - c[0] * b[1])
            + lift(b) * (c[0] * a[1] - a[0] * c[1])
            + lift(c) * (a[0] * b[1] - b[0] * a[1]);
        det.cmp(&0)
    }

    fn orient_sign(o: Orientation) -> Ordering {
        match o {
            Orientation::Left => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
            Orientation::Right => Ordering::Less,
        }
    }

    fn side_sign(s: CircleSide) -> Ordering {
        match s {
            CircleSide::Inside => Ordering::Greater,
            CircleSide::On => Ordering::Equal,
            CircleSide::Outside => Ordering::Less,
        }
    }

    /// Integer coordinates times `2^scale`: exact in `f64` (also when the
    /// product is subnormal, since the integers are multiples of a large
    /// enough power of two there) and the signs do not change.
    fn pt(v: [i128; 2], scale: i32) -> Point {
        Point::new(v[0] as f64 * pow2(scale), v[1] as f64 * pow2(scale))
    }

    #[test]
    fn decompose_is_exact() {
        for v in [0.0, -0.0, 1.0, -1.5, 0.1, f64::MAX, f64::MIN_POSITIVE, 5e-324, -2.5e-310, 1e300] {
            let (neg, m, e) = decompose(v);
            // Split the power so that neither factor leaves the normal range.
            let back = m as f64 * pow2(e.clamp(-1022, 971)) * pow2(e - e.clamp(-1022, 971));
            assert_eq!(if neg { -back } else { back }, v, "{v:e}");
        }
        assert_eq!(decompose(f64::NAN).1, 0);
    }

    #[test]
    fn orientation_matches_i128_on_near_collinear_grid() {
        // Kettner et al.'s grid (as in kernel::tests) scaled by 2^53: p near
        // (0.5, 0.5) moved by ulps, q, r on the diagonal; all integers.
        let q = [12i128 << 53, 12i128 << 53];
        let r = [24i128 << 53, 24i128 << 53];
        let (mut left, mut right, mut on) = (0, 0, 0);
        for i in 0..256 {
            for j in 0..256 {
                let p = [(1i128 << 52) + i, (1i128 << 52) + j];
                let expected = orientation_i128(p, q, r);
                let got = orient_sign(orientation(pt(p, -53), pt(q, -53), pt(r, -53)));
                assert_eq!(got, expected, "at {i},{j}");
                match got {
                    Ordering::Greater => left += 1,
                    Ordering::Less => right += 1,
                    Ordering::Equal => on += 1,
                }
            }
        }
        assert!(left > 0 && right > 0 && on > 0);
    }

    #[test]
    fn signs_match_i128_at_any_scale() {
        let mut rng = SmallRng::seed_from_u64(11);
        // Scales from far into the subnormals (integers below 2^29 times
        // 2^-1074 .. 2^-1045 are exact) to near overflow.
        let scales = [-1074, -1060, -1022, -600, -60, 0, 37, 500, 900, 990];
        for round in 0..4000 {
            // Small ranges make degenerate (collinear, cocircular) cases common.
            let range: i128 = if round % 2 == 0 { 6 } else { 1 << 28 };
            let mut v = || [rng.gen_range(-range..=range), rng.gen_range(-range..=range)];
            let pts = [v(), v(), v(), v()];
            let s = scales[round % scales.len()];
            let o = orientation(pt(pts[0], s), pt(pts[1], s), pt(pts[2], s));
            assert_eq!(orient_sign(o), orientation_i128(pts[0], pts[1], pts[2]), "{pts:?} at 2^{s}");
            let c = circle_side(pt(pts[0], s), pt(pts[1], s), pt(pts[2], s), pt(pts[3], s));
            assert_eq!(side_sign(c), incircle_i128(pts), "{pts:?} at 2^{s}");
            let x = cross_sign(pt(pts[0], s), pt(pts[1], s), pt(pts[2], s), pt(pts[3], s));
            let [p, q, r, t] = pts;
            let expected = ((q[0] - p[0]) * (t[1] - r[1])).cmp(&((q[1] - p[1]) * (t[0] - r[0])));
            assert_eq!(orient_sign(x), expected, "{pts:?} at 2^{s}");
        }
    }

    #[test]
    fn mixed_exponents_are_exact() {
        // A point 2^-1074 off a line through points of size 2^900: no
        // floating-point expansion survives this exponent spread.
        let tiny = 5e-324;
        let big = pow2(900);
        let (p, q) = (Point::new(-big, 0.0), Point::new(big, 0.0));
        assert_eq!(orientation(p, q, Point::new(0.0, tiny)), Orientation::Left);
        assert_eq!(orientation(p, q, Point::new(0.0, -tiny)), Orientation::Right);
        assert_eq!(orientation(p, q, Point::new(big * 0.5, 0.0)), Orientation::Collinear);
        // The unit circle scaled by 2^900; the fourth point 2^-1074 inside.
        let (a, b, c) = (Point::new(big, 0.0), Point::new(0.0, big), Point::new(-big, 0.0));
        assert_eq!(circle_side(a, b, c, Point::new(0.0, -big)), CircleSide::On);
        assert_eq!(circle_side(a, b, c, Point::new(tiny, 0.0)), CircleSide::Inside);
        // Pythagorean points (3,4,5) on a circle of radius 5·2^-1060.
        let s = pow2(-1060);
        let circle = [(5.0, 0.0), (3.0, 4.0), (-4.0, 3.0), (0.0, -5.0)].map(|(x, y)| Point::new(x * s, y * s));
        assert_eq!(circle_side(circle[0], circle[1], circle[2], circle[3]), CircleSide::On);
        let nudged = Point::new(circle[3].x, circle[3].y + tiny);
        assert_eq!(circle_side(circle[0], circle[1], circle[2], nudged), CircleSide::Inside);
    }
}

/// Cross-check with the GMP evaluation (`cargo test --features gmp --lib kernel`).
#[cfg(all(test, feature = "gmp"))]
mod gmp_crosscheck {
    use super::super::exact;
    use super::*;
    use rand::{rngs::SmallRng, Rng, SeedableRng};

    fn check(a: Point, b: Point, c: Point, d: Point) {
        assert_eq!(orientation(a, b, c), exact::orientation(a, b, c), "orientation {a:?} {b:?} {c:?}");
        assert_eq!(circle_side(a, b, c, d), exact::circle_side(a, b, c, d), "in-circle {a:?} {b:?} {c:?} {d:?}");
        assert_eq!(cross_sign(a, b, c, d), exact::cross_sign(a, b, c, d), "cross {a:?} {b:?} {c:?} {d:?}");
    }

    /// Any finite `f64`: random bits, retried when not finite.
    fn any_f64(rng: &mut SmallRng) -> f64 {
        loop {
            let v = f64::from_bits(rng.gen());
            if v.is_finite() {
                return v;
            }
        }
    }

    #[test]
    fn random_points_of_every_magnitude() {
        let mut rng = SmallRng::seed_from_u64(1);
        for _ in 0..20_000 {
            let mut p = || Point::new(any_f64(&mut rng), any_f64(&mut rng));
            check(p(), p(), p(), p());
        }
        // Moderate magnitudes, where the determinants are not dominated by one term.
        for _ in 0..20_000 {
            let mut p = || Point::new(rng.gen_range(-1e3..1e3), rng.gen_range(-1e3..1e3));
            check(p(), p(), p(), p());
        }
    }

    #[test]
    fn near_collinear_grids() {
        // Kettner et al.'s grid at several base points and scales.
        let mut rng = SmallRng::seed_from_u64(2);
        for &scale in &[1.0, pow2(-1000), pow2(-1060), pow2(700)] {
            for _ in 0..4 {
                let base = Point::new(rng.gen_range(0.1..1.0) * scale, rng.gen_range(0.1..1.0) * scale);
                let q = Point::new(12.0 * scale, 12.0 * scale);
                let r = Point::new(24.0 * scale, 24.0 * scale);
                let (ux, uy) = (ulp(base.x), ulp(base.y));
                for i in 0..64 {
                    for j in 0..64 {
                        let p = Point::new(base.x + i as f64 * ux, base.y + j as f64 * uy);
                        check(p, q, r, Point::new(base.y, base.x + i as f64 * ux));
                    }
                }
            }
        }
    }

    #[test]
    fn nearly_cocircular_points() {
        // Points rounded onto a circle, each moved by a few ulps: the
        // in-circle determinant is tiny and its sign hard.
        let mut rng = SmallRng::seed_from_u64(3);
        for &scale in &[1.0, 1e-300, 1e-310, 1e300] {
            for _ in 0..3000 {
                let (cx, cy, r) = (rng.gen_range(-10.0..10.0), rng.gen_range(-10.0..10.0), rng.gen_range(0.1..10.0));
                let mut on = || {
                    let t: f64 = rng.gen_range(0.0..std::f64::consts::TAU);
                    let k: i32 = rng.gen_range(-2..=2);
                    let x = (cx + r * t.cos()) * scale;
                    Point::new(x + k as f64 * ulp(x), (cy + r * t.sin()) * scale)
                };
                let (a, b, c, d) = (on(), on(), on(), on());
                check(a, b, c, d);
            }
        }
    }

    #[test]
    fn exactly_cocircular_and_collinear_points() {
        // Pythagorean triples give points exactly on circles centred at the origin.
        let triples = [(3.0, 4.0), (5.0, 12.0), (8.0, 15.0), (20.0, 21.0)];
        for &scale in &[1.0, pow2(-1070), pow2(-540), pow2(960)] {
            for &(x, y) in &triples {
                let pts = [(x, y), (-y, x), (-x, -y), (y, -x)].map(|(u, v)| Point::new(u * scale, v * scale));
                assert_eq!(circle_side(pts[0], pts[1], pts[2], pts[3]), CircleSide::On);
                check(pts[0], pts[1], pts[2], pts[3]);
                let mid = Point::new((pts[0].x + pts[2].x) / 2.0, (pts[0].y + pts[2].y) / 2.0);
                check(pts[0], mid, pts[2], pts[1]);
            }
        }
    }

    #[test]
    fn subnormals_and_mixed_exponents() {
        let mut rng = SmallRng::seed_from_u64(4);
        for _ in 0..20_000 {
            let mut v = || match rng.gen_range(0..4) {
                0 => f64::from_bits(rng.gen_range(0..1u64 << 52)) * if rng.gen() { 1.0 } else { -1.0 },
                1 => rng.gen_range(-1.0..1.0) * pow2(rng.gen_range(-1074..1000)),
                2 => 0.0,
                _ => rng.gen_range(-4i32..=4) as f64,
            };
            let mut p = || Point::new(v(), v());
            check(p(), p(), p(), p());
        }
    }

    fn ulp(x: f64) -> f64 {
        let x = x.abs();
        f64::from_bits(x.to_bits() + 1) - x
    }
}
