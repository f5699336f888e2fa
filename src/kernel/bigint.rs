//! A minimal signed big integer for the exact predicates in
//! [`super::exact_int`]: sign and magnitude, the magnitude as little-endian
//! `u64` limbs. Only what a determinant's sign needs (add, subtract,
//! multiply, shift left, sign), so no division and no formatting.
//!
//! Sizes stay small: a predicate's inputs are at most ~2100 bits after
//! shifting (the `f64` exponent range plus the 53-bit significand), and an
//! in-circle determinant, of degree 4, about 8500 bits (~135 limbs), so
//! schoolbook multiplication is the right algorithm.

use super::limbs::Limbs;
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// A signed integer of any size. Zero has an empty magnitude and is never
/// negative, so equal values have equal representations.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub(crate) struct BigInt {
    negative: bool,
    /// Little-endian limbs without trailing (most significant) zeros.
    mag: Limbs,
}

impl BigInt {
    /// `(-1)^negative · magnitude · 2^shift`.
    pub(crate) fn from_shifted(negative: bool, magnitude: u64, shift: u32) -> Self {
        let (limbs, bits) = ((shift / 64) as usize, shift % 64);
        let mut mag = Limbs::zeroed(limbs);
        mag.push(magnitude << bits);
        if bits > 0 {
            mag.push(magnitude >> (64 - bits));
        }
        Self::normalized(negative, mag)
    }

    /// The sign: `Less` for negative, `Equal` for zero, `Greater` for positive.
    pub(crate) fn signum(&self) -> Ordering {
        match (self.mag.is_empty(), self.negative) {
            (true, _) => Ordering::Equal,
            (false, true) => Ordering::Less,
            (false, false) => Ordering::Greater,
        }
    }

    /// The integer `v`.
    pub(crate) fn from_i64(v: i64) -> Self {
        Self::from_shifted(v < 0, v.unsigned_abs(), 0)
    }

    /// `m · 2^(e − e0)` for the finite `v = ±m · 2^e` (`e ≥ e0` for every
    /// nonzero `v` given, so the result is an integer): the value of `v`
    /// in units of `2^e0`, exact. Zero and non-finite values give zero.
    pub(crate) fn from_f64_in_units(v: f64, e0: i32) -> Self {
        let (negative, m, e) = decompose(v);
        if m == 0 {
            return BigInt::default();
        }
        let tz = m.trailing_zeros();
        let (m, e) = (m >> tz, e + tz as i32);
        debug_assert!(e >= e0, "{v} is finer than 2^{e0}");
        Self::from_shifted(negative, m, (e - e0).max(0) as u32)
    }

    /// True for zero.
    pub(crate) fn is_zero(&self) -> bool {
        self.mag.is_empty()
    }

    /// The value as `(mantissa, exponent)` with `value ≈ mantissa · 2^exponent`
    /// and `|mantissa|` in [2^63, 2^64) (the top 64 bits, truncated; relative
    /// error below 2^-63), or `(0.0, 0)` for zero. Never overflows: the
    /// exponent is kept apart.
    pub(crate) fn approx(&self) -> (f64, i64) {
        let Some(&top) = self.mag.last() else {
            return (0.0, 0);
        };
        let len = self.mag.len();
        let lz = top.leading_zeros();
        let next = if len >= 2 { self.mag[len - 2] } else { 0 };
        let hi = if lz == 0 { top } else { (top << lz) | (next >> (64 - lz)) };
        let m = hi as f64 * if self.negative { -1.0 } else { 1.0 };
        (m, 64 * (len as i64 - 1) - lz as i64)
    }

    /// `num / den · 2^shift` rounded to `f64` (relative error ~2^-62 before
    /// the final rounding; ±inf or 0 only where the value leaves `f64`'s range).
    pub(crate) fn ratio_f64(num: &BigInt, den: &BigInt, shift: i64) -> f64 {
        let (mn, en) = num.approx();
        let (md, ed) = den.approx();
        if md == 0.0 {
            return f64::NAN;
        }
        let e = (en - ed + shift).clamp(-4000, 4000) as i32;
        // Two steps so that neither power of two overflows on its own.
        let half = e / 2;
        (mn / md) * 2f64.powi(half) * 2f64.powi(e - half)
    }

    /// `self · 2^k`, exact.
    pub(crate) fn shl(&self, k: u32) -> BigInt {
        if self.is_zero() {
            return BigInt::default();
        }
        let (limbs, bits) = ((k / 64) as usize, k % 64);
        let mut mag = Limbs::zeroed(limbs);
        let mut carry = 0u64;
        for &x in self.mag.iter() {
            mag.push(if bits == 0 { x } else { (x << bits) | carry });
            carry = if bits == 0 { 0 } else { x >> (64 - bits) };
        }
        mag.push(carry);
        Self::normalized(self.negative, mag)
    }

    fn normalized(negative: bool, mut mag: Limbs) -> Self {
        mag.trim();
        let negative = negative && !mag.is_empty();
        BigInt { negative, mag }
    }
}

/// `(negative, significand, exponent)` with `v = ±significand · 2^exponent`;
/// non-finite input counts as zero (callers validate finiteness first).
pub(crate) fn decompose(v: f64) -> (bool, u64, i32) {
    if !v.is_finite() {
        return (false, 0, 0);
    }
    let bits = v.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1u64 << 52) - 1);
    if biased == 0 {
        // Subnormal (or zero): no implicit leading bit, fixed exponent.
        (negative, fraction, -1074)
    } else {
        (negative, fraction | (1u64 << 52), biased - 1075)
    }
}

/// The exponent of the least significant bit of the finite nonzero `v`
/// after its trailing zeros are dropped (`v = odd · 2^e`); `None` for zero.
pub(crate) fn lowest_bit_exponent(v: f64) -> Option<i32> {
    let (_, m, e) = decompose(v);
    (m != 0).then(|| e + m.trailing_zeros() as i32)
}

fn cmp_mag(a: &[u64], b: &[u64]) -> Ordering {
    // Normalized magnitudes: more limbs means larger.
    a.len().cmp(&b.len()).then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_mag(a: &[u64], b: &[u64]) -> Limbs {
    let (long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    let mut out = Limbs::with_capacity(long.len() + 1);
    let mut carry = false;
    for (i, &x) in long.iter().enumerate() {
        let (s, c1) = x.overflowing_add(short.get(i).copied().unwrap_or(0));
        let (s, c2) = s.overflowing_add(carry as u64);
        out.push(s);
        carry = c1 || c2;
    }
    out.push(carry as u64);
    out
}

/// `a - b` for `|a| >= |b|`.
fn sub_mag(a: &[u64], b: &[u64]) -> Limbs {
    let mut out = Limbs::with_capacity(a.len());
    let mut borrow = false;
    for (i, &x) in a.iter().enumerate() {
        let (d, b1) = x.overflowing_sub(b.get(i).copied().unwrap_or(0));
        let (d, b2) = d.overflowing_sub(borrow as u64);
        out.push(d);
        borrow = b1 || b2;
    }
    debug_assert!(!borrow, "sub_mag needs |a| >= |b|");
    out
}

fn mul_mag(a: &[u64], b: &[u64]) -> Limbs {
    let mut out = Limbs::zeroed(a.len() + b.len());
    for (i, &x) in a.iter().enumerate() {
        let mut carry: u128 = 0;
        for (j, &y) in b.iter().enumerate() {
            // x·y + out + carry < 2^128: (2^64-1)^2 + 2·(2^64-1) = 2^128 - 1.
            let t = x as u128 * y as u128 + out[i + j] as u128 + carry;
            out[i + j] = t as u64;
            carry = t >> 64;
        }
        out[i + b.len()] = carry as u64;
    }
    out
}

/// `a + b` with `b` negated when `flip` (no copy of `b` for a difference).
fn add_signed(a: &BigInt, b: &BigInt, flip: bool) -> BigInt {
    let b_negative = b.negative != flip && !b.is_zero();
    if a.negative == b_negative {
        return BigInt::normalized(a.negative, add_mag(&a.mag, &b.mag));
    }
    // Opposite signs: the larger magnitude decides the sign.
    match cmp_mag(&a.mag, &b.mag) {
        Ordering::Less => BigInt::normalized(b_negative, sub_mag(&b.mag, &a.mag)),
        _ => BigInt::normalized(a.negative, sub_mag(&a.mag, &b.mag)),
    }
}

impl Add for &BigInt {
    type Output = BigInt;
    fn add(self, rhs: &BigInt) -> BigInt {
        add_signed(self, rhs, false)
    }
}

impl Neg for &BigInt {
    type Output = BigInt;
    fn neg(self) -> BigInt {
        BigInt::normalized(!self.negative, self.mag.clone())
    }
}

impl Sub for &BigInt {
    type Output = BigInt;
    fn sub(self, rhs: &BigInt) -> BigInt {
        add_signed(self, rhs, true)
    }
}

impl Mul for &BigInt {
    type Output = BigInt;
    fn mul(self, rhs: &BigInt) -> BigInt {
        BigInt::normalized(self.negative != rhs.negative, mul_mag(&self.mag, &rhs.mag))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{rngs::SmallRng, Rng, SeedableRng};

    fn big(v: i128) -> BigInt {
        let m = v.unsigned_abs();
        &BigInt::from_shifted(v < 0, m as u64, 0) + &BigInt::from_shifted(v < 0, (m >> 64) as u64, 64)
    }

    #[test]
    fn matches_i128_arithmetic() {
        let mut rng = SmallRng::seed_from_u64(7);
        for _ in 0..20_000 {
            // Operands below 2^62 in magnitude keep every product inside i128.
            let bits = rng.gen_range(0..63);
            let a: i64 = rng.gen_range(-(1i64 << bits)..=(1i64 << bits));
            let b: i64 = if rng.gen_bool(0.1) { a } else { rng.gen_range(-(1i64 << bits)..=(1i64 << bits)) };
            let (a, b) = (a as i128, b as i128);
            assert_eq!(&big(a) + &big(b), big(a + b), "{a} + {b}");
            assert_eq!(&big(a) - &big(b), big(a - b), "{a} - {b}");
            assert_eq!(&big(a) * &big(b), big(a * b), "{a} * {b}");
            assert_eq!(big(a - b).signum(), (a - b).cmp(&0));
        }
    }

    #[test]
    fn carries_and_borrows_across_many_limbs() {
        // (2^640 - 1) + 1 = 2^640 and back: every limb carries, then borrows.
        let ones = &BigInt::from_shifted(false, 1, 640) - &BigInt::from_shifted(false, 1, 0);
        assert_eq!(&ones.mag[..], &[u64::MAX; 10][..]);
        let one = BigInt::from_shifted(false, 1, 0);
        assert_eq!(&ones + &one, BigInt::from_shifted(false, 1, 640));
        // (2^640 - 1)^2 = 2^1280 - 2^641 + 1.
        let square = &ones * &ones;
        let expected = &(&BigInt::from_shifted(false, 1, 1280) - &BigInt::from_shifted(false, 1, 641)) + &one;
        assert_eq!(square, expected);
        assert_eq!((&ones - &ones).signum(), Ordering::Equal);
        assert_eq!(-&BigInt::default(), BigInt::default());
        assert_eq!(ones.shl(130), &ones * &BigInt::from_shifted(false, 1, 130));
        assert_eq!((-&ones).shl(64), -&(&ones * &BigInt::from_shifted(false, 1, 64)));
        assert_eq!(one.shl(0), one);
    }
}
