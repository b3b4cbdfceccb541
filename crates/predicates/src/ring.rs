//! The number types a predicate's polynomial is evaluated in: one definition, four arithmetics.
//!
//! A predicate is written once, generic over [`Ring`]; the kernels evaluate it in plain `f64` (Fast),
//! in [`Bounded`] (the Robust kernel's filter), in [`Expansion`] (exact, floating-point expansions) and
//! in [`BigInt`] (exact, for inputs whose dynamic range is too wide for expansions).

use num_bigint::BigInt;

use crate::expansion::Expansion;

/// A commutative ring the kernels can evaluate a polynomial in.
///
/// Implementors: `f64` (rounded), [`Bounded`] (rounded with a rigorous error bound), [`Expansion`]
/// and [`BigInt`] (exact).
pub trait Ring: Clone {
    /// The value of the input coordinate `x` (exact for every implementor but `f64` and `Bounded`,
    /// where it is exact too: an input is representable by definition).
    fn input(x: f64) -> Self;
    /// `self + rhs`.
    #[must_use]
    fn add(&self, rhs: &Self) -> Self;
    /// `self − rhs`.
    #[must_use]
    fn sub(&self, rhs: &Self) -> Self;
    /// `self · rhs`.
    #[must_use]
    fn mul(&self, rhs: &Self) -> Self;
    /// `−self`.
    #[must_use]
    fn neg(&self) -> Self;
    /// `self²`.
    #[must_use]
    fn square(&self) -> Self {
        self.mul(self)
    }
}

impl Ring for f64 {
    #[inline(always)]
    fn input(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn add(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline(always)]
    fn sub(&self, rhs: &Self) -> Self {
        self - rhs
    }
    #[inline(always)]
    fn mul(&self, rhs: &Self) -> Self {
        self * rhs
    }
    #[inline(always)]
    fn neg(&self) -> Self {
        -self
    }
}

/// Unit roundoff of `f64` round-to-nearest: 2⁻⁵³.
pub(crate) const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// Absolute slack added by every [`Bounded`] operation: covers underflow (at most 2⁻¹⁰⁷⁵ per rounded
/// operation) and the rounding of the bound's own arithmetic near the subnormal range.
const ETA: f64 = f64::from_bits(1 << 14); // 2^-1060, a subnormal

/// Relative slack multiplying every [`Bounded`] error bound: 1 + 2⁻⁴⁸ = 1 + 32u covers the rounding
/// of the at most five additions and three products that compute one bound (each a factor ≥ 1 − u).
const GROW: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;

/// A rounded value with a rigorous bound on its distance from the exact value: `|exact − value| ≤ err`.
///
/// This is the Robust kernel's dynamic filter (running error analysis): each operation rounds once
/// (relative error ≤ u = 2⁻⁵³, plus at most 2⁻¹⁰⁷⁵ on underflow) and propagates the operands' bounds.
/// The bound arithmetic is itself rounded; the factor `1 + 2⁻⁴⁸` and the slack `2⁻¹⁰⁶⁰` make the computed
/// bound an upper bound of the true one (proof in `docs/ROBUSTNESS.md`). Overflow makes `value` or
/// `err` non-finite, and the filter then declines (a NaN or infinite bound never certifies a sign).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounded {
    /// The rounded value.
    pub value: f64,
    /// An upper bound on `|exact − value|`.
    pub err: f64,
}

impl Bounded {
    /// The sign of the exact value when the bound certifies it, else `None`.
    #[inline(always)]
    #[must_use]
    pub fn certain_sign(self) -> Option<crate::Sign> {
        // A NaN or infinite err, or |value| ≤ err, leaves the sign undecided.
        if self.value.abs() > self.err {
            Some(crate::Sign::of_f64(self.value))
        } else {
            None
        }
    }
}

impl Ring for Bounded {
    #[inline(always)]
    fn input(x: f64) -> Self {
        Bounded { value: x, err: 0.0 }
    }
    #[inline(always)]
    fn add(&self, rhs: &Self) -> Self {
        let value = self.value + rhs.value;
        // |exact − value| ≤ err_a + err_b + u·|value| (+ underflow, inside ETA).
        let err = (self.err + rhs.err + U * value.abs() + ETA) * GROW;
        Bounded { value, err }
    }
    #[inline(always)]
    fn sub(&self, rhs: &Self) -> Self {
        let value = self.value - rhs.value;
        let err = (self.err + rhs.err + U * value.abs() + ETA) * GROW;
        Bounded { value, err }
    }
    #[inline(always)]
    fn mul(&self, rhs: &Self) -> Self {
        let value = self.value * rhs.value;
        // |XaXb − vavb| ≤ |va|·eb + |vb|·ea + ea·eb, then one rounding u·|value| (+ underflow, inside ETA).
        let err = (self.value.abs() * rhs.err
            + rhs.value.abs() * self.err
            + self.err * rhs.err
            + U * value.abs()
            + ETA)
            * GROW;
        Bounded { value, err }
    }
    #[inline(always)]
    fn neg(&self) -> Self {
        Bounded {
            value: -self.value,
            err: self.err,
        }
    }
}

impl Ring for Expansion {
    fn input(x: f64) -> Self {
        Expansion::from_f64(x)
    }
    fn add(&self, rhs: &Self) -> Self {
        Expansion::add(self, rhs)
    }
    fn sub(&self, rhs: &Self) -> Self {
        Expansion::sub(self, rhs)
    }
    fn mul(&self, rhs: &Self) -> Self {
        Expansion::mul(self, rhs)
    }
    fn neg(&self) -> Self {
        Expansion::neg(self)
    }
}

/// Integers: the last-resort exact arithmetic. Inputs reach it already scaled to integers by an exact
/// power of two (see the crate docs on `Polynomial`), so `input` is only called with integral values.
impl Ring for BigInt {
    fn input(x: f64) -> Self {
        crate::poly::integral_f64_to_bigint(x)
    }
    fn add(&self, rhs: &Self) -> Self {
        self + rhs
    }
    fn sub(&self, rhs: &Self) -> Self {
        self - rhs
    }
    fn mul(&self, rhs: &Self) -> Self {
        self * rhs
    }
    fn neg(&self) -> Self {
        -self
    }
}
