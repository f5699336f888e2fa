//! Exact points, directions and lines of the plane over the integers, for
//! the polygon-ball medial axis (thesis 3.1–3.2), where every node is the
//! meeting point of two lines whose coefficients are polynomials of the
//! input: such a point has rational coordinates, kept here as homogeneous
//! integers `(X, Y, W)` (`W > 0`), so that no division ever rounds.
//!
//! Inputs enter through [`Units`]: a set of `f64` values expressed as
//! integers in units of one power of two (exact: every finite `f64` is an
//! integer times a power of two). Shape and ball coordinates may use
//! different units; every equation the axis builds is homogeneous in each
//! set on its own (a radius is a length divided by a ball coordinate), so
//! the signs it takes do not depend on the units.
//!
//! Sizes: coordinates of n bits make a node's coordinates of ~7n bits and
//! a comparison of two nodes ~14n bits; [`BigInt`] is schoolbook, so this
//! is the exact slow path, asked only where `f64` filters cannot decide or
//! where the combinatorics are fixed once (a node's contact classes).

use super::bigint::{lowest_bit_exponent, BigInt};
use super::xfloat::{sign_or, Fx};
use super::Point;
use std::cmp::Ordering;

/// A set of `f64` values written as integers in units of `2^e0`, `e0` the
/// exponent of the least significant bit among them (so each is an
/// integer, exactly).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Units {
    e0: i32,
}

impl Units {
    /// Units fine enough for every finite value of `values` (zeros and
    /// non-finite values are ignored).
    pub(crate) fn covering(values: impl IntoIterator<Item = f64>) -> Units {
        let e0 = values.into_iter().filter_map(lowest_bit_exponent).min().unwrap_or(0);
        Units { e0 }
    }

    /// `v` as an integer in these units (exact for values the units cover).
    pub(crate) fn int(&self, v: f64) -> BigInt {
        BigInt::from_f64_in_units(v, self.e0)
    }

    /// The point `p` as an integer vector in these units.
    pub(crate) fn vec(&self, p: Point) -> IVec {
        IVec::new(self.int(p.x), self.int(p.y))
    }

    /// `e0`: one unit is `2^e0`.
    pub(crate) fn exponent(&self) -> i32 {
        self.e0
    }
}

/// An integer vector: a direction, a normal or a point in some units.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub(crate) struct IVec {
    pub x: BigInt,
    pub y: BigInt,
}

impl IVec {
    pub(crate) fn new(x: BigInt, y: BigInt) -> IVec {
        IVec { x, y }
    }

    pub(crate) fn small(x: i64, y: i64) -> IVec {
        IVec::new(BigInt::from_i64(x), BigInt::from_i64(y))
    }

    pub(crate) fn dot(&self, o: &IVec) -> BigInt {
        &(&self.x * &o.x) + &(&self.y * &o.y)
    }

    /// `self × o`: positive when `o` is counter-clockwise of `self`.
    pub(crate) fn cross(&self, o: &IVec) -> BigInt {
        &(&self.x * &o.y) - &(&self.y * &o.x)
    }

    /// The sign of `self · o`, filtered.
    pub(crate) fn dot_sign(&self, o: &IVec) -> Ordering {
        let f = self.fx()[0] * o.fx()[0] + self.fx()[1] * o.fx()[1];
        sign_or(f, || self.dot(o).signum())
    }

    /// The sign of `self × o`, filtered.
    pub(crate) fn cross_sign(&self, o: &IVec) -> Ordering {
        let f = self.fx()[0] * o.fx()[1] - self.fx()[1] * o.fx()[0];
        sign_or(f, || self.cross(o).signum())
    }

    /// The components as filter values.
    pub(crate) fn fx(&self) -> [Fx; 2] {
        [Fx::of(&self.x), Fx::of(&self.y)]
    }

    pub(crate) fn add(&self, o: &IVec) -> IVec {
        IVec::new(&self.x + &o.x, &self.y + &o.y)
    }

    /// A direction strictly between the nonzero `self` and `o` (less than
    /// a half turn apart): their sum after scaling the shorter by a power
    /// of two to the other's size. A plain sum of a long and a short
    /// vector lies almost on the long one, where every comparison along
    /// it is nearly a tie and only the exact fallback decides.
    pub(crate) fn add_balanced(&self, o: &IVec) -> IVec {
        let (a, b) = (self.magnitude_bits(), o.magnitude_bits());
        let up = |v: &IVec, k: i64| if k > 0 { IVec::new(v.x.shl(k as u32), v.y.shl(k as u32)) } else { v.clone() };
        up(self, b - a).add(&up(o, a - b))
    }

    /// The exponent of the larger component's leading bit.
    fn magnitude_bits(&self) -> i64 {
        let bits = |b: &BigInt| if b.is_zero() { i64::MIN / 2 } else { b.approx().1 };
        bits(&self.x).max(bits(&self.y))
    }

    pub(crate) fn sub(&self, o: &IVec) -> IVec {
        IVec::new(&self.x - &o.x, &self.y - &o.y)
    }

    pub(crate) fn neg(&self) -> IVec {
        IVec::new(-&self.x, -&self.y)
    }

    pub(crate) fn scale(&self, s: &BigInt) -> IVec {
        IVec::new(&self.x * s, &self.y * s)
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero()
    }

    /// Approximate direction (any scale), for filters and pictures.
    pub(crate) fn approx(&self) -> Point {
        let (mx, ex) = self.x.approx();
        let (my, ey) = self.y.approx();
        let e = ex.max(ey);
        let f = |m: f64, ei: i64| if m == 0.0 { 0.0 } else { m * 2f64.powi((ei - e).max(-1100) as i32) };
        Point::new(f(mx, ex), f(my, ey))
    }
}

/// Total order of nonzero directions by angle in [0, 2π) from +x, exact.
pub(crate) fn cmp_angle(u: &IVec, v: &IVec) -> Ordering {
    let half = |w: &IVec| -> u8 {
        match (w.y.signum(), w.x.signum()) {
            (Ordering::Greater, _) | (Ordering::Equal, Ordering::Greater) => 0,
            _ => 1,
        }
    };
    half(u).cmp(&half(v)).then_with(|| Ordering::Equal.cmp(&u.cross_sign(v)))
}

/// The line `n · p + c = 0` (`n ≠ 0`); `n · p + c > 0` is its positive side.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct ILine {
    pub n: IVec,
    pub c: BigInt,
}

impl ILine {
    pub(crate) fn new(n: IVec, c: BigInt) -> ILine {
        ILine { n, c }
    }

    /// `W · (n · p + c)` for `p = (X/W, Y/W)`: the side, times `W > 0`.
    pub(crate) fn value(&self, p: &HPoint) -> BigInt {
        &(&(&self.n.x * &p.x) + &(&self.n.y * &p.y)) + &(&self.c * &p.w)
    }

    /// Which side of the line `p` lies on (`Equal`: on it).
    pub(crate) fn side(&self, p: &HPoint) -> Ordering {
        let [nx, ny] = self.n.fx();
        let f = nx * Fx::of(&p.x) + ny * Fx::of(&p.y) + Fx::of(&self.c) * Fx::of(&p.w);
        sign_or(f, || self.value(p).signum())
    }

    /// The point where the two lines meet; `None` when they are parallel.
    pub(crate) fn meet(&self, o: &ILine) -> Option<HPoint> {
        let w = self.n.cross(&o.n);
        if w.is_zero() {
            return None;
        }
        let x = &(&self.n.y * &o.c) - &(&o.n.y * &self.c);
        let y = &(&self.c * &o.n.x) - &(&o.c * &self.n.x);
        Some(HPoint::new(x, y, w))
    }

    /// The direction of the line (its normal turned a quarter clockwise).
    pub(crate) fn direction(&self) -> IVec {
        IVec::new(self.n.y.clone(), -&self.n.x)
    }
}

/// A point `(X/W, Y/W)` with integer coordinates and `W > 0`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct HPoint {
    pub x: BigInt,
    pub y: BigInt,
    pub w: BigInt,
}

impl HPoint {
    /// `(x/w, y/w)`; `w ≠ 0` of either sign.
    pub(crate) fn new(x: BigInt, y: BigInt, w: BigInt) -> HPoint {
        if w.signum() == Ordering::Less {
            HPoint { x: -&x, y: -&y, w: -&w }
        } else {
            HPoint { x, y, w }
        }
    }

    /// The integer point `v`.
    pub(crate) fn at(v: &IVec) -> HPoint {
        HPoint { x: v.x.clone(), y: v.y.clone(), w: BigInt::from_i64(1) }
    }

    /// Same point (exact).
    pub(crate) fn same(&self, o: &HPoint) -> bool {
        (&self.x * &o.w) == (&o.x * &self.w) && (&self.y * &o.w) == (&o.y * &self.w)
    }

    /// Sign of `(o − self) · d`: whether `o` lies ahead of `self` along `d`.
    pub(crate) fn along(&self, o: &HPoint, d: &IVec) -> Ordering {
        let [sx, sy, sw] = [&self.x, &self.y, &self.w].map(Fx::of);
        let [ox, oy, ow] = [&o.x, &o.y, &o.w].map(Fx::of);
        let [vx, vy] = d.fx();
        let f = (ox * sw - sx * ow) * vx + (oy * sw - sy * ow) * vy;
        sign_or(f, || self.along_exact(o, d))
    }

    fn along_exact(&self, o: &HPoint, d: &IVec) -> Ordering {
        let dx = &(&o.x * &self.w) - &(&self.x * &o.w);
        let dy = &(&o.y * &self.w) - &(&self.y * &o.w);
        (&(&dx * &d.x) + &(&dy * &d.y)).signum()
    }

    /// The point in model coordinates, for units `units` (rounded).
    pub(crate) fn approx(&self, units: Units) -> Point {
        let e = units.exponent() as i64;
        Point::new(BigInt::ratio_f64(&self.x, &self.w, e), BigInt::ratio_f64(&self.y, &self.w, e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_make_integers_and_lines_meet_exactly() {
        let u = Units::covering([0.5, 3.25, -1.0]);
        assert_eq!(u.exponent(), -2);
        assert_eq!(u.int(3.25), BigInt::from_i64(13));
        let a = Units::covering([1.0, 0.25]);
        // x − 1/4 = 0 and y − x = 0 meet at (1/4, 1/4).
        let x_line = ILine::new(IVec::small(1, 0), -&a.int(0.25));
        let diag = ILine::new(IVec::small(-1, 1), BigInt::from_i64(0));
        let p = x_line.meet(&diag).unwrap();
        let q = p.approx(a);
        assert_eq!((q.x, q.y), (0.25, 0.25));
        assert_eq!(x_line.side(&p), Ordering::Equal);
        assert!(x_line.meet(&ILine::new(IVec::small(2, 0), BigInt::from_i64(5))).is_none());
        let r = HPoint::new(BigInt::from_i64(-2), BigInt::from_i64(-2), BigInt::from_i64(-2));
        assert!(r.same(&p));
        assert_eq!(p.along(&HPoint::at(&IVec::small(3, 0)), &IVec::small(1, 0)), Ordering::Greater);
    }

    #[test]
    fn angles_sort_round_the_circle() {
        let mut dirs =
            [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)].map(|(x, y)| IVec::small(x, y));
        let want = dirs.clone();
        dirs.reverse();
        dirs.sort_by(cmp_angle);
        assert_eq!(dirs, want);
        assert_eq!(cmp_angle(&IVec::small(2, 2), &IVec::small(1, 1)), Ordering::Equal);
    }

    #[test]
    fn approx_of_huge_and_tiny_ratios() {
        let big = BigInt::from_shifted(false, 3, 2000);
        let one = BigInt::from_i64(1);
        let p = HPoint::new(big.clone(), one.clone(), big.clone());
        let q = p.approx(Units { e0: 0 });
        assert_eq!(q.x, 1.0);
        assert_eq!(q.y, 0.0);
        let d = IVec::new(big, BigInt::from_shifted(true, 3, 1999)).approx();
        assert_eq!(d.y / d.x, -0.5);
    }
}
