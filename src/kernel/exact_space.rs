//! Vectors of space over a ring that answers signs: [`Fx`] (a floating
//! filter that may answer "unsure") or [`BigInt`] (exact, always sure).
//! A construction written once against [`Ring`] runs first on the filter
//! and, when some sign it needs is unsure, again on the integers: the
//! polytope-ball queries of chapter 3 decide that way, because their
//! answers are rational (thesis Lemma 8) and small linear systems give
//! them.
//!
//! Inputs enter as `f64`: exactly as [`Fx`] values, or as integers in
//! [`Units`] common to every value of one question (then every equation
//! is homogeneous in those units and its signs do not depend on them).

use super::bigint::BigInt;
use super::exact_line::Units;
use super::xfloat::Fx;
use super::Point3;
use std::cmp::Ordering;

/// A ring whose elements answer their sign, when sure.
pub(crate) trait Ring: Clone {
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn neg(&self) -> Self;
    /// The exact sign, or `None` when this ring cannot tell.
    fn sign(&self) -> Option<Ordering>;
    /// `num / den · 2^shift` rounded to `f64` (for reports, not decisions).
    fn ratio(num: &Self, den: &Self, shift: i64) -> f64;
}

impl Ring for Fx {
    fn add(&self, o: &Fx) -> Fx {
        *self + *o
    }
    fn sub(&self, o: &Fx) -> Fx {
        *self - *o
    }
    fn mul(&self, o: &Fx) -> Fx {
        *self * *o
    }
    fn neg(&self) -> Fx {
        -*self
    }
    fn sign(&self) -> Option<Ordering> {
        Fx::sign(*self)
    }
    fn ratio(num: &Fx, den: &Fx, shift: i64) -> f64 {
        Fx::ratio(*num, *den, shift)
    }
}

impl Ring for BigInt {
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

impl V3<Fx> {
    /// `p` exactly, as filter values.
    pub(crate) fn fx(p: Point3) -> V3<Fx> {
        V3 { x: Fx::of_f64(p.x), y: Fx::of_f64(p.y), z: Fx::of_f64(p.z) }
    }
}

impl V3<BigInt> {
    /// `p` as integers in `units` (exact when the units cover it).
    pub(crate) fn int(units: Units, p: Point3) -> V3<BigInt> {
        V3 { x: units.int(p.x), y: units.int(p.y), z: units.int(p.z) }
    }
}

impl<R: Ring> V3<R> {
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
        let f: Vec<V3<Fx>> = ps.iter().map(|&p| V3::fx(p)).collect();
        let b: Vec<V3<BigInt>> = ps.iter().map(|&p| V3::int(units, p)).collect();
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
        let rf = <Fx as Ring>::ratio(&df, &f[0].dot(&f[0]), 0);
        assert!((r - rf).abs() <= 1e-12 * rf.abs(), "{r} vs {rf}");
    }
}
