//! Double-double arithmetic with a rigorous running error bound: the fast first stage of
//! [`crate::round_value`].
//!
//! A value is `hi + lo` (an unevaluated sum of two doubles, `|lo| ≤ ulp(hi)/2`, about 106 bits) plus a
//! bound `err ≥ |exact − (hi + lo)|`. Additions and products use the error-free transformations
//! Two-Sum and Two-Product for the leading parts and plain `f64` for the trailing ones; the bound
//! accounts for every rounding and for the dropped `lo·lo` product. When the bound shows that the exact
//! value lies strictly inside the rounding cell of `hi`, `hi` is the correctly rounded value; otherwise
//! the caller falls back to exact arithmetic. Overflow makes the value or bound non-finite and the check
//! fails; underflow is covered by the absolute slack `2⁻¹⁰⁶⁰` per operation.

use crate::expansion::{two_product, two_sum};
use crate::ring::{Ring, U};

/// Absolute slack per operation (underflow of a product or of a bound term): 2⁻¹⁰⁶⁰.
const ETA: f64 = f64::from_bits(1 << 14);
/// Relative slack for the rounding of the bound's own arithmetic (at most ~20 roundings): 1 + 2⁻⁴⁸.
const GROW: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;

/// A double-double value with a rigorous running error bound: `hi + lo` (about 106 bits) and
/// `err ≥ |exact − (hi + lo)|`, where *exact* is the value of the same expression in exact arithmetic.
///
/// It is a [`Ring`]: evaluate any [`Polynomial`](crate::Polynomial) on it, or write a construction
/// that shares subexpressions (one `|b − a|²` for several outputs) directly with its operations. Inputs
/// enter exactly ([`Ring::input`]); [`certain_rounding`](Self::certain_rounding) then returns the
/// correctly rounded exact value when the bound proves it, and [`estimate`](Self::estimate) a value
/// with a bound. When neither is good enough, evaluate exactly with [`round_value`](crate::round_value).
/// Overflow makes the bound infinite; underflow is covered by an absolute slack of `2⁻¹⁰⁶⁰` per operation.
///
/// # Examples
/// ```
/// use polydist_predicates::{DoubleDouble, Ring};
///
/// // (0.1 + 0.2) − 0.3, in exact arithmetic on the three doubles, is exactly 2⁻⁵⁵: not 0.
/// let x = DoubleDouble::input(0.1).add(&DoubleDouble::input(0.2)).sub(&DoubleDouble::input(0.3));
/// let (value, error) = x.estimate();
/// assert!((value - 2f64.powi(-55)).abs() <= error);
/// // A product is certified at once: the double nearest to the exact 0.1·0.1.
/// let y = DoubleDouble::input(0.1).mul(&DoubleDouble::input(0.1));
/// assert_eq!(y.certain_rounding(), Some(0.1 * 0.1));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DoubleDouble {
    hi: f64,
    lo: f64,
    err: f64,
}

impl DoubleDouble {
    /// `a − b` exactly (Two-Sum: the difference of two doubles is a double-double), with a zero error
    /// bound. Overflow makes the value non-finite, which every check rejects.
    #[inline(always)]
    #[must_use]
    pub fn difference(a: f64, b: f64) -> Self {
        let (hi, lo) = two_sum(a, -b);
        DoubleDouble { hi, lo, err: 0.0 }
    }

    /// `hi` and a bound on `|exact − hi|` (`+∞` when anything overflowed).
    #[must_use]
    pub fn estimate(self) -> (f64, f64) {
        let bound = (self.err + self.lo.abs()) * GROW;
        if self.hi.is_finite() && bound.is_finite() {
            (self.hi, bound)
        } else {
            (self.hi, f64::INFINITY)
        }
    }

    /// The correctly rounded exact value, when the bound certifies it (`None` otherwise, and for zero,
    /// overflow and results below `2⁻⁹⁷⁰`).
    #[must_use]
    pub fn certain_rounding(self) -> Option<f64> {
        let DoubleDouble { hi, lo, err } = self;
        // hi = ±MAX has an infinite neighbour: leave overflow-adjacent roundings to the exact stage.
        if !(lo.is_finite() && err.is_finite()) || hi == 0.0 || hi.abs() >= f64::MAX || hi.is_nan()
        {
            return None;
        }
        // The rounding cell of hi: (hi − down, hi + up) with down, up half the gaps to the neighbours.
        // The halving is exact for normal hi far from the subnormal range (checked below).
        if hi.abs() < f64::MIN_POSITIVE * 4_503_599_627_370_496.0 {
            return None; // |hi| < 2^-970: gaps could be subnormal; leave it to the exact stage
        }
        let up = (hi.next_up() - hi) * 0.5;
        let down = (hi - hi.next_down()) * 0.5;
        // The exact value lies in [hi + lo − err, hi + lo + err]; require it strictly inside the cell.
        // fl(lo + err) and fl(lo − err) err by at most u relative; the factor (1 + 2⁻⁵⁰) covers it.
        let widen = 1.0 + 1.0 / 1_125_899_906_842_624.0;
        let top = (lo + err) * widen;
        let bottom = (lo - err) * widen;
        if top < up && -bottom < down {
            Some(hi)
        } else {
            None
        }
    }
}

impl Ring for DoubleDouble {
    #[inline(always)]
    fn input(x: f64) -> Self {
        DoubleDouble {
            hi: x,
            lo: 0.0,
            err: 0.0,
        }
    }

    #[inline(always)]
    fn add(&self, b: &Self) -> Self {
        let a = self;
        // s + t = a.hi + b.hi exactly; w = fl(t + fl(a.lo + b.lo)); hi + lo = s + w exactly.
        let (s, t) = two_sum(a.hi, b.hi);
        let los = a.lo + b.lo;
        let w = t + los;
        let (hi, lo) = two_sum(s, w);
        // |w − (t + a.lo + b.lo)| ≤ u·|los| + u·|w| (two roundings).
        let err = (a.err + b.err + U * (los.abs() + w.abs()) + ETA) * GROW;
        DoubleDouble { hi, lo, err }
    }

    #[inline(always)]
    fn sub(&self, b: &Self) -> Self {
        self.add(&b.neg())
    }

    #[inline(always)]
    fn mul(&self, b: &Self) -> Self {
        let a = self;
        // p + q = a.hi·b.hi exactly (no underflow; ETA otherwise). Cross terms in f64; lo·lo dropped.
        let (p, q) = two_product(a.hi, b.hi);
        let c1 = a.hi * b.lo;
        let c2 = a.lo * b.hi;
        let cross = c1 + c2;
        let w = q + cross;
        let (hi, lo) = two_sum(p, w);
        // Propagated: |AB − ab| ≤ |a|·eb + |b|·ea + ea·eb with |a| ≤ |a.hi| + |a.lo|.
        let (av, bv) = (a.hi.abs() + a.lo.abs(), b.hi.abs() + b.lo.abs());
        let propagated = av * b.err + bv * a.err + a.err * b.err;
        // Computed: the dropped |a.lo·b.lo|, the roundings of c1, c2 (u each), of cross (u), of w (u).
        let computed = (a.lo * b.lo).abs() + U * (c1.abs() + c2.abs() + cross.abs() + w.abs());
        let err = (propagated + computed + ETA) * GROW;
        DoubleDouble { hi, lo, err }
    }

    #[inline(always)]
    fn neg(&self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
            err: self.err,
        }
    }
}
