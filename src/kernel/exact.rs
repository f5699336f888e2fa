//! Exact predicate evaluation with GMP rationals (feature `gmp`): then the
//! fallback of `FilteredKernel` instead of the pure-Rust `exact_int`, and a
//! cross-check of it in tests. Every finite `f64` is a dyadic
//! rational, so converting inputs loses nothing and the sign is exact.

use super::{CircleSide, Orientation, Point};
use rug::Rational;

fn q(v: f64) -> Rational {
    // Non-finite input has no exact value; callers validate finiteness first,
    // and zero keeps this total instead of panicking.
    Rational::from_f64(v).unwrap_or_default()
}

/// Exact orientation of `r` relative to the directed line `p → q`.
pub(crate) fn orientation(p: Point, qq: Point, r: Point) -> Orientation {
    let (px, py, qx, qy, rx, ry) = (q(p.x), q(p.y), q(qq.x), q(qq.y), q(r.x), q(r.y));
    let l = Rational::from(&px - &rx) * Rational::from(&qy - &ry);
    let rr = Rational::from(&py - &ry) * Rational::from(&qx - &rx);
    match l.cmp(&rr) {
        std::cmp::Ordering::Greater => Orientation::Left,
        std::cmp::Ordering::Less => Orientation::Right,
        std::cmp::Ordering::Equal => Orientation::Collinear,
    }
}

/// Exact sign of (q − p) × (s − r).
pub(crate) fn cross_sign(p: Point, qq: Point, r: Point, s: Point) -> Orientation {
    let dx = q(qq.x) - q(p.x);
    let dy = q(qq.y) - q(p.y);
    let ex = q(s.x) - q(r.x);
    let ey = q(s.y) - q(r.y);
    match (dx * ey).cmp(&(dy * ex)) {
        std::cmp::Ordering::Greater => Orientation::Left,
        std::cmp::Ordering::Less => Orientation::Right,
        std::cmp::Ordering::Equal => Orientation::Collinear,
    }
}

/// Exact side of `d` relative to the circle through counter-clockwise `a, b, c`.
pub(crate) fn circle_side(a: Point, b: Point, c: Point, d: Point) -> CircleSide {
    let (dx, dy) = (q(d.x), q(d.y));
    let rel = |p: Point| {
        let x = q(p.x) - &dx;
        let y = q(p.y) - &dy;
        let lift = Rational::from(&x * &x) + Rational::from(&y * &y);
        (x, y, lift)
    };
    let (ax, ay, al) = rel(a);
    let (bx, by, bl) = rel(b);
    let (cx, cy, cl) = rel(c);
    let bc = Rational::from(&bx * &cy) - Rational::from(&cx * &by);
    let ca = Rational::from(&cx * &ay) - Rational::from(&ax * &cy);
    let ab = Rational::from(&ax * &by) - Rational::from(&bx * &ay);
    let det = al * bc + bl * ca + cl * ab;
    match det.cmp0() {
        std::cmp::Ordering::Greater => CircleSide::Inside,
        std::cmp::Ordering::Less => CircleSide::Outside,
        std::cmp::Ordering::Equal => CircleSide::On,
    }
}
