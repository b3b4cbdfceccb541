//! Filtered exact signs of small homogeneous polynomials in input coordinates.
//!
//! Every decision of polydist's algorithms is the sign of a polynomial in the input coordinates. This
//! module is the shared facility: write the polynomial once with [`Polynomial::eval`], generic over
//! [`Ring`], and ask any [`crate::Kernel`] for its sign with [`crate::Kernel::sign`].
//!
//! # The pipeline (Robust kernel)
//! 1. Filter: evaluate in [`Bounded`] (rounded value + rigorous error bound). If the bound certifies
//!    the sign, done. This settles almost every call on non-degenerate input.
//! 2. Error-free `f64`: evaluate in [`ErrorFree`] (plain `f64`, each operation checked exact by an
//!    error-free transformation). If nothing rounded, the value is exact and so is its sign. This settles
//!    the degenerate calls on coarse (integer or dyadic) inputs, where exact zeros and ties are common.
//! 3. Expansions: rescale the inputs by one exact power of two so the largest magnitude lies in
//!    `[1/2, 1)`, then evaluate exactly in [`Expansion`] arithmetic. A homogeneous polynomial of degree
//!    `D` only changes by the positive factor `2^(kD)`, so the sign is unchanged. Expansion arithmetic
//!    is exact when no product underflows, which the dynamic-range test below guarantees.
//! 4. Integers: if the inputs' dynamic range is too wide for step 3, every input is an integer multiple
//!    of `2^e_min`; scale them to integers and evaluate in [`BigInt`]. Exact for every finite input.
//!
//! The Exact kernel runs steps 3–4 only (it is the reference the others are tested against); the Fast
//! kernel evaluates in `f64` and takes the sign.
//!
//! # Degree and range
//! [`MAX_DEGREE`] = 16 bounds the degree accepted by [`Polynomial::DEGREE`]'s documentation contract;
//! the pipeline is exact for any degree, but step 3 is only taken when
//! `D · (e_min − 52) ≥ −1064`, where `e_min` is the binary exponent of the smallest nonzero scaled input:
//! then every exact intermediate is an integer multiple of `2^−1064`, so no Two-Product loses a bit.
//! For `D = 6` that admits a dynamic range of `2^125` within one query; wider ranges use step 4.

use num_bigint::BigInt;

use crate::Sign;
use crate::dd::DoubleDouble;
use crate::expansion::Expansion;
use crate::ring::{Bounded, ErrorFree, Ring};

/// The largest degree a [`Polynomial`] is documented to have (the pipeline stays exact beyond it, but
/// the filter and the expansion stage were sized for it).
pub const MAX_DEGREE: u32 = 16;

/// A homogeneous polynomial in `N` input coordinates, whose sign a [`crate::Kernel`] decides.
///
/// # Contract
/// - `eval` computes the polynomial with the [`Ring`] operations only (no comparisons, no branches on
///   values), and the same expression for every ring.
/// - The polynomial is homogeneous of degree [`Self::DEGREE`] in the inputs: scaling every input by
///   `λ > 0` multiplies it by `λ^DEGREE`. Geometric predicates built from coordinate differences are.
///   The kernels rely on this to rescale by powers of two; a non-homogeneous polynomial would get
///   wrong signs under the exact stages.
///
/// # Examples
/// The sign of `(b − a) · (c − a)` for points a, b, c (degree 2):
/// ```
/// use polydist_predicates::{Kernel, Polynomial, Ring, Robust, Sign};
///
/// struct DotAt;
/// impl Polynomial<6> for DotAt {
///     const DEGREE: u32 = 2;
///     fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
///         let (ax, ay, bx, by, cx, cy) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
///         bx.sub(ax).mul(&cx.sub(ax)).add(&by.sub(ay).mul(&cy.sub(ay)))
///     }
/// }
/// let s = Robust::sign(&DotAt, &[0.0, 0.0, 1.0, 0.0, 0.0, 1.0]);
/// assert_eq!(s, Sign::Zero);
/// ```
pub trait Polynomial<const N: usize> {
    /// The homogeneous degree (at most [`MAX_DEGREE`]).
    const DEGREE: u32;
    /// The polynomial's value at `x`, computed in the ring `R`.
    fn eval<R: Ring>(&self, x: &[R; N]) -> R;
}

/// Fast: plain `f64`, NaN counted as zero.
#[inline(always)]
pub(crate) fn sign_fast<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
    Sign::of_f64(p.eval(x))
}

/// Robust: the [`Bounded`] filter, then [`sign_adaptive`].
#[inline]
pub(crate) fn sign_robust<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
    let b: [Bounded; N] = x.map(Bounded::input);
    match p.eval(&b).certain_sign() {
        Some(s) => s,
        None => sign_adaptive(p, x),
    }
}

/// The Robust kernel's stages after its filter: the [`ErrorFree`] evaluation (plain `f64`, each
/// operation checked exact), then [`sign_exact`] when some operation rounded.
#[inline(never)]
pub(crate) fn sign_adaptive<const N: usize, P: Polynomial<N> + ?Sized>(
    p: &P,
    x: &[f64; N],
) -> Sign {
    let v: [ErrorFree; N] = x.map(ErrorFree::input);
    match p.eval(&v).exact_sign() {
        Some(s) => s,
        None => sign_exact(p, x),
    }
}

/// Exact: expansions on rescaled inputs, or integers when the dynamic range is too wide.
///
/// Non-finite inputs are outside every kernel's contract; they give [`Sign::Zero`] rather than a panic.
#[inline(never)]
pub(crate) fn sign_exact<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
    let Some(range) = Range::of(x) else {
        return Sign::Zero;
    };
    let Some(e_max) = range.e_max else {
        // Every input is zero: a homogeneous polynomial of positive degree vanishes; degree 0 is a constant.
        let zeros: [Expansion; N] = core::array::from_fn(|_| Expansion::default());
        return p.eval(&zeros).sign();
    };
    let e_min = range.e_min;
    // After scaling by 2^(-e_max - 1) the largest magnitude is in [1/2, 1) and the smallest nonzero one
    // has exponent e_min - e_max - 1.
    let shift = -(e_max + 1);
    let scaled_min = e_min + shift;
    let d = i64::from(P::DEGREE.max(1));
    if d * (i64::from(scaled_min) - 52) >= -1064 {
        let xs: [Expansion; N] =
            core::array::from_fn(|i| Expansion::from_f64(mul_pow2(x[i], shift)));
        p.eval(&xs).sign()
    } else {
        // Every nonzero input is an integer multiple of 2^(e_min − 52): scale to integers.
        let unit = e_min - 52;
        let xs: [BigInt; N] = core::array::from_fn(|i| exact_integer(x[i], unit));
        Sign::of_bigint(&p.eval(&xs))
    }
}

/// The value of the homogeneous polynomial `p` at `x`, rounded once to the nearest `f64`.
///
/// The constructions' building block ("compute the intermediates exactly, round once"). First the
/// polynomial is evaluated in double-double arithmetic with a rigorous error bound; when the bound
/// shows the exact value strictly inside one rounding cell, that rounding is returned (the common case,
/// tens of nanoseconds). Otherwise the inputs are rescaled by a power of two, the polynomial is
/// evaluated exactly (expansions, or integers when the dynamic range is too wide), rounded to
/// nearest-even, and scaled back. The result is the correctly
/// rounded value unless it lies in the subnormal range (then within one subnormal ulp) or overflows (±∞).
/// Non-finite inputs give NaN.
///
/// # Examples
/// ```
/// use polydist_predicates::{round_value, Orient};
/// // (a − c) × (b − c) for a = (1e16, 1), b = (1e16 + 2, 3), c = (0, 0): 3e16 − (1e16 + 2) = 2e16 − 2.
/// let v = round_value(&Orient, &[1e16, 1.0, 1e16 + 2.0, 3.0, 0.0, 0.0]);
/// assert_eq!(v, 2e16 - 2.0);
/// ```
#[must_use]
pub fn round_value<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> f64 {
    // Fast stage: double-double with a rigorous bound; exact whenever the bound certifies the rounding.
    let dd: [DoubleDouble; N] = x.map(DoubleDouble::input);
    if let Some(v) = p.eval(&dd).certain_rounding() {
        return v;
    }
    round_value_exact(p, x)
}

/// A value with a rigorous bound on its error: `|exact − value| ≤ error` (`error` may be `+∞`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// An approximation of the exact value (the leading part of a double-double evaluation).
    pub value: f64,
    /// An upper bound on `|exact − value|`; `+∞` (or NaN-free infinite) when nothing is certified.
    pub error: f64,
}

/// The value of the homogeneous polynomial `p` at `x`, about 106 bits accurate, with a rigorous error
/// bound: for corrections that need a small quantity to a few bits only (a residual), where
/// [`round_value`]'s correct rounding would be wasted work.
///
/// # Examples
/// ```
/// use polydist_predicates::{estimate_value, Orient};
/// let e = estimate_value(&Orient, &[1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
/// assert_eq!(e.value, 1.0);
/// assert!(e.error < 1e-300);
/// ```
#[must_use]
pub fn estimate_value<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Estimate {
    let dd: [DoubleDouble; N] = x.map(DoubleDouble::input);
    let (value, error) = p.eval(&dd).estimate();
    Estimate { value, error }
}

/// [`round_value`] without the double-double stage (always exact evaluation, then one rounding).
#[inline(never)]
fn round_value_exact<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> f64 {
    let Some(range) = Range::of(x) else {
        return f64::NAN;
    };
    let Some(e_max) = range.e_max else {
        let zeros: [Expansion; N] = core::array::from_fn(|_| Expansion::default());
        return p.eval(&zeros).to_f64();
    };
    let shift = -(e_max + 1);
    let scaled_min = range.e_min + shift;
    let d = P::DEGREE.max(1) as i32;
    if d * (scaled_min - 52) >= -1064 {
        let xs: [Expansion; N] =
            core::array::from_fn(|i| Expansion::from_f64(mul_pow2(x[i], shift)));
        // value(x) = value(x·2^shift) · 2^(−shift·D); the scaled value is far from under/overflow.
        mul_pow2(p.eval(&xs).to_f64(), -shift * d)
    } else {
        let unit = range.e_min - 52;
        let xs: [BigInt; N] = core::array::from_fn(|i| exact_integer(x[i], unit));
        // value(x) = value(x / 2^unit) · 2^(unit·D).
        bigint_times_pow2(&p.eval(&xs), unit * d)
    }
}

/// `v · 2^e` rounded to nearest: keep the top 64 bits of `|v|` with a sticky bit for the rest (so the
/// one rounding to 53 bits is correct), then scale by the remaining power of two.
fn bigint_times_pow2(v: &BigInt, e: i32) -> f64 {
    let mag = v.magnitude();
    let bits = mag.bits();
    let (top, dropped) = if bits > 64 {
        let s = bits - 64;
        let top = mag >> s;
        let sticky = mag.trailing_zeros().is_some_and(|tz| tz < s);
        let t = num_traits::ToPrimitive::to_u64(&top).unwrap_or(u64::MAX);
        (t | u64::from(sticky), s as i64)
    } else {
        (num_traits::ToPrimitive::to_u64(mag).unwrap_or(u64::MAX), 0)
    };
    // A u64 with a sticky low bit converts to f64 with one correct rounding (63+ significant bits).
    let m = top as f64;
    let total = i64::from(e) + dropped;
    let scaled = mul_pow2(m, total.clamp(-4000, 4000) as i32);
    if v.sign() == num_bigint::Sign::Minus {
        -scaled
    } else {
        scaled
    }
}

/// The binary exponents of the largest and smallest nonzero magnitudes among the inputs.
struct Range {
    e_max: Option<i32>,
    e_min: i32,
}

impl Range {
    /// `None` when some input is not finite.
    fn of(x: &[f64]) -> Option<Range> {
        let mut e_max: Option<i32> = None;
        let mut e_min = i32::MAX;
        for &v in x {
            if !v.is_finite() {
                return None;
            }
            if v != 0.0 {
                let e = exponent(v);
                e_max = Some(e_max.map_or(e, |m| m.max(e)));
                e_min = e_min.min(e);
            }
        }
        Some(Range { e_max, e_min })
    }
}

/// The binary exponent `e` of a finite nonzero `v`: `2^e ≤ |v| < 2^(e+1)` (subnormals included).
pub(crate) fn exponent(v: f64) -> i32 {
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: value = mantissa · 2^-1074.
        let mant = bits & ((1u64 << 52) - 1);
        -1074 + (63 - mant.leading_zeros() as i32)
    } else {
        biased - 1023
    }
}

/// `v · 2^k`, exact whenever the result is a normal number or zero (applied in steps that stay finite).
pub(crate) fn mul_pow2(mut v: f64, mut k: i32) -> f64 {
    // Each step multiplies by a representable power of two; intermediate results stay between the
    // input and the output in magnitude, so none underflows when the output does not.
    while k > 0 {
        let s = k.min(1000);
        v *= pow2(s);
        k -= s;
    }
    while k < 0 {
        let s = k.max(-1000);
        v *= pow2(s);
        k -= s;
    }
    v
}

/// `2^k` for `−1022 ≤ k ≤ 1023`.
fn pow2(k: i32) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The integer `v / 2^unit`, exact when `v` is a multiple of `2^unit` (true for `unit ≤ e − 52`, with `e`
/// the exponent of any nonzero input, and for subnormals since `unit ≥ −1074` is not required: the
/// mantissa is shifted left instead).
fn exact_integer(v: f64, unit: i32) -> BigInt {
    if v == 0.0 {
        return BigInt::from(0);
    }
    let (mant, exp) = decompose(v);
    // v = mant · 2^exp with exp ≥ unit.
    let shift = (exp - unit) as u32;
    let m = BigInt::from(mant) << shift;
    if v < 0.0 { -m } else { m }
}

/// `|v| = mant · 2^exp` with an integer mantissa, for finite nonzero `v`.
pub(crate) fn decompose(v: f64) -> (u64, i32) {
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), biased - 1075)
    }
}

/// `x` as an integer, for an `f64` known to be integral (used by `Ring for BigInt`).
pub(crate) fn integral_f64_to_bigint(x: f64) -> BigInt {
    if x == 0.0 || !x.is_finite() {
        return BigInt::from(0);
    }
    let (mant, exp) = decompose(x);
    let m = if exp >= 0 {
        BigInt::from(mant) << (exp as u32)
    } else {
        BigInt::from(mant >> ((-exp) as u32).min(63))
    };
    if x < 0.0 { -m } else { m }
}

impl Sign {
    /// The sign of an integer.
    #[must_use]
    pub fn of_bigint(v: &BigInt) -> Sign {
        match v.sign() {
            num_bigint::Sign::Minus => Sign::Negative,
            num_bigint::Sign::NoSign => Sign::Zero,
            num_bigint::Sign::Plus => Sign::Positive,
        }
    }
}
