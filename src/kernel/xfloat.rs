//! A floating-point filter for signs of small polynomials in [`BigInt`]s.
//!
//! The polygon-ball axis decides everything exactly, on integers of a few
//! hundred bits (a node's homogeneous coordinates), which overflow `f64`.
//! [`Xf`] is an `f64` significand with its own `i64` exponent, so it holds
//! any [`BigInt`] to 53 bits without overflow. [`Fx`] carries a value and
//! the same expression evaluated on absolute values; each operation adds
//! at most one rounding of relative size 2⁻⁵³ of that magnitude, so after
//! a handful of operations the error is far below
//! 2⁻⁴⁰ × magnitude, and a value larger than that has the sign of
//! the exact one. Otherwise [`Fx::sign`] answers `None` and the caller
//! computes exactly. This is Shewchuk's static filter with a dynamic
//! magnitude, the same idea as the filtered kernel of chapter 2.

use super::bigint::BigInt;
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// Relative bound (as a power of two) of the accumulated rounding for
/// expressions of up to about twenty operations on converted inputs (each
/// conversion 2⁻⁵², each operation 2⁻⁵³): 2⁻⁴⁰ leaves a wide margin.
const REL_BITS: i64 = 40;

/// `m · 2^e` with `m` finite (not normalised: only the value matters).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Xf {
    m: f64,
    e: i64,
}

/// `2^d` for `d ≤ 0`, flushing to zero below the normal range (the lost
/// part is below 2⁻¹⁰²² of the larger term, inside the bound).
fn pow2_down(d: i64) -> f64 {
    if d < -1022 {
        0.0
    } else {
        f64::from_bits(((d + 1023) as u64) << 52)
    }
}

impl Xf {
    pub(crate) const ZERO: Xf = Xf { m: 0.0, e: 0 };

    /// `b` rounded to 53 bits.
    pub(crate) fn of(b: &BigInt) -> Xf {
        let (m, e) = b.approx();
        // |m| in [2^63, 2^64): keep it near 1 so products never overflow.
        Xf { m: m * pow2_down(-64), e: e + 64 }
    }

    fn abs(self) -> Xf {
        Xf { m: self.m.abs(), e: self.e }
    }

    /// The exponent of the leading bit, for alignment (0 for zero).
    fn scale(self) -> i64 {
        if self.m == 0.0 {
            i64::MIN / 4
        } else {
            self.e
        }
    }

    fn sum(self, o: Xf) -> Xf {
        let (a, b) = if self.scale() >= o.scale() { (self, o) } else { (o, self) };
        if b.m == 0.0 {
            return a;
        }
        // Renormalised so that |m| stays near 1 after cancellation.
        Xf { m: a.m + b.m * pow2_down(b.e - a.e), e: a.e }.norm()
    }

    /// The same value with |m| in [1, 2) (or zero).
    fn norm(self) -> Xf {
        if self.m == 0.0 {
            return Xf::ZERO;
        }
        let biased = ((self.m.to_bits() >> 52) & 0x7ff) as i64;
        let shift = if biased == 0 { self.m.abs().log2().floor() as i64 } else { biased - 1023 };
        Xf { m: self.m * pow2_signed(-shift), e: self.e + shift }
    }

    fn product(self, o: Xf) -> Xf {
        if self.m == 0.0 || o.m == 0.0 {
            return Xf::ZERO;
        }
        Xf { m: self.m * o.m, e: self.e + o.e }
    }

    /// `self > o` for non-negative values.
    fn exceeds(self, o: Xf) -> bool {
        if o.m == 0.0 {
            return self.m > 0.0;
        }
        if self.m == 0.0 {
            return false;
        }
        let (a, b) = (self.norm(), o.norm());
        a.e > b.e || (a.e == b.e && a.m > b.m)
    }
}

/// `2^d` for small |d| (both signs).
fn pow2_signed(d: i64) -> f64 {
    f64::from_bits(((d.clamp(-1022, 1023) + 1023) as u64) << 52)
}

/// A filtered value: the approximate value and its magnitude bound.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fx {
    v: Xf,
    mag: Xf,
}

impl Fx {
    /// The input `b` (its conversion error is covered by the bound).
    pub(crate) fn of(b: &BigInt) -> Fx {
        let v = Xf::of(b);
        Fx { v, mag: v.abs() }
    }

    /// The sign of the exact value when the filter certifies it.
    pub(crate) fn sign(self) -> Option<Ordering> {
        let bound = Xf { m: self.mag.m, e: self.mag.e - REL_BITS };
        if self.v.abs().exceeds(bound) {
            Some(if self.v.m > 0.0 { Ordering::Greater } else { Ordering::Less })
        } else if self.mag.m == 0.0 {
            // Every input was exactly zero.
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

impl Add for Fx {
    type Output = Fx;
    fn add(self, o: Fx) -> Fx {
        Fx { v: self.v.sum(o.v), mag: self.mag.sum(o.mag) }
    }
}

impl Sub for Fx {
    type Output = Fx;
    fn sub(self, o: Fx) -> Fx {
        self + (-o)
    }
}

impl Neg for Fx {
    type Output = Fx;
    fn neg(self) -> Fx {
        Fx { v: Xf { m: -self.v.m, e: self.v.e }, mag: self.mag }
    }
}

impl Mul for Fx {
    type Output = Fx;
    fn mul(self, o: Fx) -> Fx {
        Fx { v: self.v.product(o.v), mag: self.mag.product(o.mag) }
    }
}

/// The sign of an expression: the filter's when it is sure, else `exact()`.
pub(crate) fn sign_or(filtered: Fx, exact: impl FnOnce() -> Ordering) -> Ordering {
    filtered.sign().unwrap_or_else(exact)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn big(v: i64, shift: u32) -> BigInt {
        BigInt::from_shifted(v < 0, v.unsigned_abs(), shift)
    }

    #[test]
    fn certifies_clear_signs_and_defers_near_zero() {
        // (2^300 + 1)·(2^300 − 1) − 2^600 = −1: too close for the filter.
        let a = &big(1, 300) + &big(1, 0);
        let b = &big(1, 300) - &big(1, 0);
        let c = big(1, 600);
        let f = Fx::of(&a) * Fx::of(&b) - Fx::of(&c);
        assert_eq!(f.sign(), None);
        let exact = (&(&a * &b) - &c).signum();
        assert_eq!(sign_or(f, || exact), Ordering::Less);
        // 3·2^900 − 2^901 = 2^900 > 0, far from zero: certified.
        let g = Fx::of(&big(3, 900)) - Fx::of(&big(1, 901));
        assert_eq!(g.sign(), Some(Ordering::Greater));
        // Products beyond f64's range keep their sign.
        let h = Fx::of(&big(-5, 1000)) * Fx::of(&big(7, 1000)) + Fx::of(&big(1, 10));
        assert_eq!(h.sign(), Some(Ordering::Less));
        assert_eq!((Fx::of(&BigInt::default()) * Fx::of(&big(9, 3))).sign(), Some(Ordering::Equal));
    }

    #[test]
    fn agrees_with_exact_signs_on_random_dot_products() {
        let mut s = 0x9e3779b97f4a7c15u64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        let mut decided = 0;
        for i in 0..20_000 {
            let sh = (next() % 200) as u32;
            let v: Vec<BigInt> =
                (0..4).map(|_| big((next() >> 40) as i64 - (1 << 23), sh + (next() % 3) as u32)).collect();
            // Every fourth case is built to cancel exactly.
            let (a, b, c, d) = if i % 4 == 0 {
                (v[0].clone(), v[1].clone(), v[1].clone(), v[0].clone())
            } else {
                (v[0].clone(), v[1].clone(), v[2].clone(), v[3].clone())
            };
            let exact = (&(&a * &b) - &(&c * &d)).signum();
            let f = Fx::of(&a) * Fx::of(&b) - Fx::of(&c) * Fx::of(&d);
            if let Some(sg) = f.sign() {
                assert_eq!(sg, exact, "case {i}");
                decided += 1;
            }
        }
        assert!(decided > 14_000, "the filter decided only {decided}");
    }
}
