//! A minimal signed big integer for the exact predicates in
//! [`super::exact_int`]: sign and magnitude, the magnitude as little-endian
//! `u64` limbs. Only what a determinant's sign needs (add, subtract,
//! multiply, shift left, sign), so no division and no formatting.
//!
//! Sizes stay small: a predicate's inputs are at most ~2100 bits after
//! shifting (the `f64` exponent range plus the 53-bit significand), and an
//! in-circle determinant, of degree 4, about 8500 bits (~135 limbs), so
//! schoolbook multiplication is the right algorithm.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// A signed integer of any size. Zero has an empty magnitude and is never
/// negative, so equal values have equal representations.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub(crate) struct BigInt {
    negative: bool,
    /// Little-endian limbs without trailing (most significant) zeros.
    mag: Vec<u64>,
}

impl BigInt {
    /// `(-1)^negative · magnitude · 2^shift`.
    pub(crate) fn from_shifted(negative: bool, magnitude: u64, shift: u32) -> Self {
        let (limbs, bits) = ((shift / 64) as usize, shift % 64);
        let mut mag = vec![0; limbs];
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

    fn normalized(negative: bool, mut mag: Vec<u64>) -> Self {
        while mag.last() == Some(&0) {
            mag.pop();
        }
        let negative = negative && !mag.is_empty();
        BigInt { negative, mag }
    }
}

fn cmp_mag(a: &[u64], b: &[u64]) -> Ordering {
    // Normalized magnitudes: more limbs means larger.
    a.len().cmp(&b.len()).then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    let (long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    let mut out = Vec::with_capacity(long.len() + 1);
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
fn sub_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    let mut out = Vec::with_capacity(a.len());
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

fn mul_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    let mut out = vec![0u64; a.len() + b.len()];
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

impl Add for &BigInt {
    type Output = BigInt;
    fn add(self, rhs: &BigInt) -> BigInt {
        if self.negative == rhs.negative {
            return BigInt::normalized(self.negative, add_mag(&self.mag, &rhs.mag));
        }
        // Opposite signs: the larger magnitude decides the sign.
        match cmp_mag(&self.mag, &rhs.mag) {
            Ordering::Less => BigInt::normalized(rhs.negative, sub_mag(&rhs.mag, &self.mag)),
            _ => BigInt::normalized(self.negative, sub_mag(&self.mag, &rhs.mag)),
        }
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
        self + &(-rhs)
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
        assert_eq!(ones.mag, vec![u64::MAX; 10]);
        let one = BigInt::from_shifted(false, 1, 0);
        assert_eq!(&ones + &one, BigInt::from_shifted(false, 1, 640));
        // (2^640 - 1)^2 = 2^1280 - 2^641 + 1.
        let square = &ones * &ones;
        let expected = &(&BigInt::from_shifted(false, 1, 1280) - &BigInt::from_shifted(false, 1, 641)) + &one;
        assert_eq!(square, expected);
        assert_eq!((&ones - &ones).signum(), Ordering::Equal);
        assert_eq!(-&BigInt::default(), BigInt::default());
    }
}
