//! Vectors of space over a ring that answers signs: [`Fb`] (a floating
//! filter that may answer "unsure") or [`BigInt`] (exact, always sure).
//! A construction written once against [`Ring`] runs first on the filter
//! and, when some sign it needs is unsure, again on the integers: the
//! polytope-ball queries of chapter 3 decide that way, because their
//! answers are rational (thesis Lemma 8) and small linear systems give
//! them.
//!
//! Inputs enter as `f64`: exactly as [`Fb`] values, or as integers in
//! [`Units`] common to every value of one question (then every equation
//! is homogeneous in those units and its signs do not depend on them).

use super::bigint::BigInt;
use super::exact_line::Units;
use super::Point3;
use std::cmp::Ordering;

/// A ring whose elements answer their sign, when sure.
pub(crate) trait Ring: Clone {
    /// The finite `v`, exactly (in `units` where the ring needs them).
    fn of(v: f64, units: Units) -> Self;
    /// `a − b` for finite inputs `a`, `b`: one rounding in the filter
    /// (so its bound is relative to the difference, not to `|a| + |b|`:
    /// a question moved to its centre keeps bounds of its own size).
    fn diff(a: f64, b: f64, units: Units) -> Self;
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn neg(&self) -> Self;
    /// The exact sign, or `None` when this ring cannot tell.
    fn sign(&self) -> Option<Ordering>;
    /// `num / den · 2^shift` rounded to `f64` (for reports, not decisions).
    fn ratio(num: &Self, den: &Self, shift: i64) -> f64;
}

/// An `f64` with a bound on its rounding: `m` is the same expression
/// evaluated on absolute values, and each operation adds at most 2⁻⁵³·m
/// of error, so below 2¹³ operations the value is within 2⁻⁴⁰·m of the
/// exact one (Shewchuk's semi-static filter, the idea of
/// [`Fx`](super::xfloat::Fx) at plain `f64` speed). Unsure when the
/// magnitude left `f64`'s comfortable range (overflow, or below 2⁻⁹⁰⁰
/// where underflow could matter).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fb {
    v: f64,
    m: f64,
}

/// 2⁻⁴⁰ and 2⁻⁹⁰⁰.
const REL: f64 = 1.0 / (1u64 << 40) as f64;
const TINY: f64 = f64::from_bits((1023 - 900) << 52);

impl Ring for Fb {
    fn of(v: f64, _units: Units) -> Fb {
        Fb { v, m: v.abs() }
    }
    fn diff(a: f64, b: f64, _units: Units) -> Fb {
        // Correctly rounded: the error is at most 2⁻⁵³ of the result.
        let v = a - b;
        Fb { v, m: v.abs() }
    }
    fn add(&self, o: &Fb) -> Fb {
        Fb { v: self.v + o.v, m: self.m + o.m }
    }
    fn sub(&self, o: &Fb) -> Fb {
        Fb { v: self.v - o.v, m: self.m + o.m }
    }
    fn mul(&self, o: &Fb) -> Fb {
        Fb { v: self.v * o.v, m: self.m * o.m }
    }
    fn neg(&self) -> Fb {
        Fb { v: -self.v, m: self.m }
    }
    fn sign(&self) -> Option<Ordering> {
        if self.m == 0.0 {
            // Every input was exactly zero.
            return Some(Ordering::Equal);
        }
        if !(self.m.is_finite() && self.m > TINY && self.v.abs() > self.m * REL) {
            return None;
        }
        Some(if self.v > 0.0 { Ordering::Greater } else { Ordering::Less })
    }
    fn ratio(num: &Fb, den: &Fb, shift: i64) -> f64 {
        num.v / den.v * 2f64.powi(shift.clamp(-2000, 2000) as i32)
    }
}

impl Ring for BigInt {
    fn of(v: f64, units: Units) -> BigInt {
        units.int(v)
    }
    fn diff(a: f64, b: f64, units: Units) -> BigInt {
        &units.int(a) - &units.int(b)
    }
    fn add(&self, o: &BigInt) -> BigInt {
        self + o
    }
    fn sub(&self, o: &BigInt) -> BigInt {
        self - o
    }
    fn mul(&self, o: &BigInt) -> BigInt {
        self * o
    }
    fn neg(&self) -> BigInt {
        -self
    }
    fn sign(&self) -> Option<Ordering> {
        Some(self.signum())
    }
    fn ratio(num: &BigInt, den: &BigInt, shift: i64) -> f64 {
        BigInt::ratio_f64(num, den, shift)
    }
}

/// A vector of space over `R`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct V3<R> {
    pub x: R,
    pub y: R,
    pub z: R,
}

impl<R: Ring> V3<R> {
    /// `p` exactly (in `units` where the ring needs them).
    pub(crate) fn of(p: Point3, units: Units) -> V3<R> {
        V3 { x: R::of(p.x, units), y: R::of(p.y, units), z: R::of(p.z, units) }
    }

    /// `p − q` ([`Ring::diff`]).
    pub(crate) fn diff(p: Point3, q: Point3, units: Units) -> V3<R> {
        V3 { x: R::diff(p.x, q.x, units), y: R::diff(p.y, q.y, units), z: R::diff(p.z, q.z, units) }
    }

    pub(crate) fn add(&self, o: &V3<R>) -> V3<R> {
        V3 { x: self.x.add(&o.x), y: self.y.add(&o.y), z: self.z.add(&o.z) }
    }

    pub(crate) fn sub(&self, o: &V3<R>) -> V3<R> {
        V3 { x: self.x.sub(&o.x), y: self.y.sub(&o.y), z: self.z.sub(&o.z) }
    }

    pub(crate) fn scale(&self, s: &R) -> V3<R> {
        V3 { x: self.x.mul(s), y: self.y.mul(s), z: self.z.mul(s) }
    }

    pub(crate) fn dot(&self, o: &V3<R>) -> R {
        self.x.mul(&o.x).add(&self.y.mul(&o.y)).add(&self.z.mul(&o.z))
    }

    pub(crate) fn cross(&self, o: &V3<R>) -> V3<R> {
        V3 {
            x: self.y.mul(&o.z).sub(&self.z.mul(&o.y)),
            y: self.z.mul(&o.x).sub(&self.x.mul(&o.z)),
            z: self.x.mul(&o.y).sub(&self.y.mul(&o.x)),
        }
    }

    /// `self · (b × c)`: the determinant with these rows.
    pub(crate) fn det(&self, b: &V3<R>, c: &V3<R>) -> R {
        self.dot(&b.cross(c))
    }

    /// `self / w · 2^shift` rounded to `f64` (`w` nonzero).
    pub(crate) fn approx_over(&self, w: &R, shift: i64) -> Point3 {
        Point3::new(R::ratio(&self.x, w, shift), R::ratio(&self.y, w, shift), R::ratio(&self.z, w, shift))
    }
}

/// The sign of `a / b − c / d` for `b, d > 0`, when sure.
pub(crate) fn cmp_ratios<R: Ring>(a: &R, b: &R, c: &R, d: &R) -> Option<Ordering> {
    a.mul(d).sub(&c.mul(b)).sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filter_and_integers_agree_where_the_filter_is_sure() {
        let ps = [Point3::new(0.5, 3.0, -1.25), Point3::new(1e-3, 7.0, 2.0), Point3::new(-1.25, 0.5, 3.0)];
        let units = Units::covering(ps.iter().flat_map(|p| p.to_array()));
        let f: Vec<V3<Fb>> = ps.iter().map(|&p| V3::of(p, units)).collect();
        let b: Vec<V3<BigInt>> = ps.iter().map(|&p| V3::of(p, units)).collect();
        let df = f[0].det(&f[1], &f[2]);
        let db = b[0].det(&b[1], &b[2]);
        assert_eq!(Ring::sign(&df), Some(db.signum()));
        // A repeated row: the filter cannot be sure of zero, the integers are.
        let zf = f[0].det(&f[0].add(&f[1]), &f[1]);
        let zb = b[0].det(&b[0].add(&b[1]), &b[1]);
        assert_eq!(zb.signum(), Ordering::Equal);
        assert_ne!(Ring::sign(&zf), Some(Ordering::Greater));
        assert_ne!(Ring::sign(&zf), Some(Ordering::Less));
        let r = <BigInt as Ring>::ratio(&db, &b[0].dot(&b[0]), units.exponent() as i64);
        let rf = <Fb as Ring>::ratio(&df, &f[0].dot(&f[0]), 0);
        assert!((r - rf).abs() <= 1e-12 * rf.abs(), "{r} vs {rf}");
    }
}
