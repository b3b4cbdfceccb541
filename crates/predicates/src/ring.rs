//! The number types a predicate's polynomial is evaluated in: one definition, four arithmetics.
//!
//! A predicate is written once, generic over [`Ring`]; the kernels evaluate it in plain `f64` (Fast),
//! in [`Bounded`] (the Robust kernel's filter), in [`ErrorFree`] (the Robust kernel's second stage: plain
//! `f64`, each operation checked exact), in [`Expansion`] (exact, floating-point expansions) and in
//! [`BigInt`] (exact, for inputs whose dynamic range is too wide for expansions).

use num_bigint::BigInt;

use crate::expansion::{Expansion, two_product, two_sum};

/// A commutative ring the kernels can evaluate a polynomial in.
///
/// Implementors: `f64` (rounded), [`Bounded`] (rounded with a rigorous error bound), [`ErrorFree`]
/// (rounded, with a proof of exactness when no operation rounded), [`Expansion`] and [`BigInt`] (exact).
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

impl Bounded {
    /// `self / d` with a rigorous bound, or `None` when `d`'s bound does not exclude zero (or
    /// something overflowed). For the filter of [`crate::sign_at`] (constructed points).
    ///
    /// With exact values `N`, `D` and `|N − n| ≤ e_n`, `|D − d| ≤ e_d < |d|` (so `D` has `d`'s
    /// sign and `|D| ≥ |d| − e_d > 0`):
    /// `|N/D − n/d| = |(N − n)d − n(D − d)| / |Dd| ≤ (e_n + |n/d|·e_d) / (|d| − e_d)`, and the
    /// rounded quotient `q` adds `u|n/d|` (plus at most `2⁻¹⁰⁷⁴` on underflow). With
    /// `|n/d| ≤ (1 + 2u)|q|`, the bound below, computed in seven rounded operations (each at worst
    /// a factor `1 − u` low, the denominator's subtraction a factor `1 + u` high), is an upper bound
    /// once multiplied by `GROW = 1 + 32u ≥ (1 + 2u)(1 + u)⁸`; `ETA` covers the underflows.
    pub(crate) fn div(&self, d: &Bounded) -> Option<Bounded> {
        // `certain_sign` is `None` on `|d| ≤ e_d` and on a NaN bound.
        d.certain_sign()?;
        let ad = d.value.abs();
        let q = self.value / d.value;
        let aq = q.abs();
        let err = ((self.err + aq * d.err) / (ad - d.err) + U * aq + ETA) * GROW;
        (q.is_finite() && err.is_finite()).then_some(Bounded { value: q, err })
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

/// A plain `f64` evaluation that knows whether it is exact: `exact` holds only when every operation
/// that produced `value` was performed without rounding, so `value` *is* the exact value.
///
/// The Robust kernel's second stage, between the filter and the expansions. It decides the degenerate
/// calls the filter cannot (an exact zero, or an exact tie between two distances) at nearly the cost of
/// `f64` whenever the inputs are coarse enough that the arithmetic happens to be exact: integer or dyadic
/// coordinates of moderate size, as in grids, snapped data, CAD models and every tie in our benchmarks.
/// Each operation checks its own rounding with an error-free transformation (Shewchuk 1997):
///
/// - `a ± b`: Two-Sum gives the rounding error `e` exactly (for every finite operand, subnormal ones
///   included); the result is exact iff `e = 0` and the sum is finite.
/// - `a · b`: Two-Product (Dekker's split) gives the error exactly when neither factor exceeds `2⁵⁰⁰` (the
///   split cannot overflow) and `|a·b| ≥ 2⁻⁹⁰⁰` (no partial product underflows: every one is a multiple
///   of `ulp(a)·ulp(b) ≥ 2⁻¹⁰⁰⁶`); outside that range the product counts as inexact. A zero product is
///   exact iff a factor is zero (otherwise it underflowed).
///
/// An inexact result only sends the call on to the exact stages; it is never wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorFree {
    /// The rounded value (the exact value when `exact`).
    pub value: f64,
    /// `true` when no operation rounded.
    pub exact: bool,
}

impl ErrorFree {
    /// The exact sign when the evaluation was exact, else `None`.
    #[inline(always)]
    #[must_use]
    pub fn exact_sign(self) -> Option<crate::Sign> {
        if self.exact {
            Some(crate::Sign::of_f64(self.value))
        } else {
            None
        }
    }
}

/// `2⁵⁰⁰`: the largest factor [`ErrorFree`] multiplies with a checked Two-Product.
const EF_HUGE: f64 = f64::from_bits((1023 + 500) << 52);
/// `2⁻⁹⁰⁰`: the smallest nonzero product [`ErrorFree`] checks.
const EF_TINY: f64 = f64::from_bits((1023 - 900) << 52);

impl Ring for ErrorFree {
    #[inline(always)]
    fn input(x: f64) -> Self {
        ErrorFree {
            value: x,
            exact: x.is_finite(),
        }
    }
    #[inline(always)]
    fn add(&self, rhs: &Self) -> Self {
        let (s, e) = two_sum(self.value, rhs.value);
        ErrorFree {
            value: s,
            exact: self.exact & rhs.exact & (e == 0.0) & s.is_finite(),
        }
    }
    #[inline(always)]
    fn sub(&self, rhs: &Self) -> Self {
        self.add(&rhs.neg())
    }
    #[inline(always)]
    fn mul(&self, rhs: &Self) -> Self {
        let (a, b) = (self.value, rhs.value);
        let p = a * b;
        let exact = if p == 0.0 {
            a == 0.0 || b == 0.0
        } else if a.abs() <= EF_HUGE && b.abs() <= EF_HUGE && p.abs() >= EF_TINY {
            two_product(a, b).1 == 0.0
        } else {
            false
        };
        ErrorFree {
            value: p,
            exact: self.exact & rhs.exact & exact,
        }
    }
    #[inline(always)]
    fn neg(&self) -> Self {
        ErrorFree {
            value: -self.value,
            exact: self.exact,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::to_rational;
    use num_traits::Signed;

    /// [`Bounded::div`]'s bound holds at the extremes of the operands' intervals (the quotient is
    /// monotone in each operand on an interval excluding zero, so its extremes are there), against
    /// exact rationals, over every scale.
    #[test]
    fn division_bound_holds() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut unit = || (next() >> 11) as f64 / (1u64 << 53) as f64;
        let mut checked = 0;
        for round in 0..20_000 {
            let scale = 2f64.powi((round % 200) as i32 - 100);
            let n = (unit() - 0.5) * scale;
            let d = (unit() - 0.5) * scale;
            let en = unit() * n.abs() * 1e-10;
            let ed = unit() * d.abs() * [1e-12, 1e-3, 0.5][round % 3];
            let (bn, bd) = (Bounded { value: n, err: en }, Bounded { value: d, err: ed });
            let Some(q) = bn.div(&bd) else { continue };
            let err = to_rational(q.err).unwrap();
            for sn in [-1.0, 1.0] {
                for sd in [-1.0, 1.0] {
                    let nn = to_rational(n).unwrap()
                        + to_rational(en).unwrap() * to_rational(sn).unwrap();
                    let dd = to_rational(d).unwrap()
                        + to_rational(ed).unwrap() * to_rational(sd).unwrap();
                    let dev = (nn / dd - to_rational(q.value).unwrap()).abs();
                    assert!(dev <= err, "n {n} ± {en}, d {d} ± {ed}: {q:?}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 50_000, "{checked}");
    }
}
