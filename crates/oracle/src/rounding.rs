//! Correct rounding of rationals to `f64` and error measurement in ulps.

use core::cmp::Ordering;

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::exact::{pow2_int, rat};

/// `2^k` as an `f64`, for `-1022 <= k <= 1023`.
pub(crate) fn pow2(k: i32) -> f64 {
    assert!((-1022..=1023).contains(&k), "pow2 out of range: {k}");
    f64::from_bits(u64::from((k + 1023).unsigned_abs()) << 52)
}

/// `x · 2^k`, multiplying by powers of two in range steps. Exact whenever the
/// result (and, for `k < -1000`, `x · 2^-1000`) is representable without
/// underflow, e.g. for an integer `x` below `2^53` and `k >= -1074`.
pub(crate) fn ldexp(mut x: f64, mut k: i32) -> f64 {
    while k > 1000 {
        x *= pow2(1000);
        k -= 1000;
    }
    while k < -1000 {
        x *= pow2(-1000);
        k += 1000;
    }
    x * pow2(k)
}

/// `floor(log2(n / d))` for positive big integers.
fn floor_log2_ratio(n: &BigUint, d: &BigUint) -> i64 {
    let mut e = n.bits() as i64 - d.bits() as i64;
    // Now 2^(e-1) < n/d < 2^(e+1); decide whether n/d >= 2^e.
    let ge = if e >= 0 {
        *n >= d << e.unsigned_abs()
    } else {
        (n << e.unsigned_abs()) >= *d
    };
    if !ge {
        e -= 1;
    }
    e
}

/// `floor(log2 |r|)` for a nonzero rational.
fn floor_log2(r: &BigRational) -> i64 {
    floor_log2_ratio(r.numer().magnitude(), r.denom().magnitude())
}

/// `2^k` as an exact rational (any integer `k`).
fn pow2_rat(k: i64) -> BigRational {
    if k >= 0 {
        BigRational::from_integer(pow2_int(k.unsigned_abs()))
    } else {
        BigRational::new(BigInt::one(), pow2_int(k.unsigned_abs()))
    }
}

/// Builds the double `q · 2^s` for `0 <= q <= 2^53`, `s >= -1074`, where
/// either `q >= 2^52` or `s == -1074`; overflow gives +∞.
fn compose(q: u64, s: i64) -> f64 {
    let (mut q, mut s) = (q, s);
    if q == 1 << 53 {
        q = 1 << 52;
        s += 1;
    }
    if q >= 1 << 52 {
        let biased = s + 52 + 1023;
        if biased >= 2047 {
            return f64::INFINITY;
        }
        f64::from_bits((biased.unsigned_abs() << 52) | (q - (1 << 52)))
    } else {
        debug_assert_eq!(s, -1074);
        f64::from_bits(q)
    }
}

/// The rational `r` correctly rounded to the nearest `f64`, ties to even,
/// exactly as IEEE 754 round-to-nearest would: gradual underflow into the
/// subnormal range, ±∞ for magnitudes at or beyond `f64::MAX + ulp/2`, and
/// `-0.0` for negative values that round to zero.
pub fn to_f64_nearest(r: &BigRational) -> f64 {
    if r.is_zero() {
        return 0.0;
    }
    let negative = r.is_negative();
    let n = r.numer().magnitude();
    let d = r.denom().magnitude();
    let e = floor_log2_ratio(n, d);
    let magnitude = if e > 1023 {
        f64::INFINITY
    } else {
        // Scale so the integer part has 53 significant bits (fewer in the
        // subnormal range), then round the remainder to nearest even.
        let s = (e - 52).max(-1074);
        let (num, den) = if s >= 0 {
            (n.clone(), d << s.unsigned_abs())
        } else {
            (n << s.unsigned_abs(), d.clone())
        };
        let (mut q, rem) = num.div_rem(&den);
        let twice: BigUint = rem << 1u32;
        match twice.cmp(&den) {
            Ordering::Greater => q += 1u32,
            Ordering::Equal if q.is_odd() => q += 1u32,
            _ => {}
        }
        // q <= 2^53 by construction, so the fallback is never taken.
        q.to_u64().map_or(f64::INFINITY, |q| compose(q, s))
    };
    if negative { -magnitude } else { magnitude }
}

/// The correctly rounded `f64` at or above the nonnegative rational `r`.
fn to_f64_up(r: &BigRational) -> f64 {
    let x = to_f64_nearest(r);
    match rat(x) {
        Some(xr) if xr < *r => step_ulps(x, 1),
        _ => x,
    }
}

/// Maps a double to an integer so that consecutive doubles map to
/// consecutive integers (±0 both map to 0). NaN must be excluded by callers.
fn ordered(x: f64) -> i64 {
    let bits = x.to_bits();
    let mag = (bits & !(1u64 << 63)) as i64;
    if bits >> 63 == 1 { -mag } else { mag }
}

/// Inverse of [`ordered`] on the range of ±∞.
fn from_ordered(o: i64) -> f64 {
    let inf = f64::INFINITY.to_bits() as i64;
    let o = o.clamp(-inf, inf);
    if o >= 0 {
        f64::from_bits(o.unsigned_abs())
    } else {
        f64::from_bits(o.unsigned_abs() | (1u64 << 63))
    }
}

/// Steps `k` representable doubles up (`k > 0`) or down (`k < 0`) from `x`:
/// bit-exact `next_up`/`next_down` iterated `|k|` times, in `O(1)`.
///
/// ±0 count as one point (stepping `+1` from either gives the smallest
/// positive subnormal; landing on zero gives `+0.0`); stepping past
/// `±f64::MAX` saturates at ±∞. NaN is returned unchanged.
pub fn step_ulps(x: f64, k: i64) -> f64 {
    if x.is_nan() {
        return x;
    }
    from_ordered(ordered(x).saturating_add(k))
}

/// Number of representable doubles between `a` and `b`: 0 iff `a == b`
/// (so `+0.0` and `-0.0` are at distance 0), `1` for neighbours, counted
/// across the sign change (`ulp_distance(-min_subnormal, min_subnormal) == 2`).
/// Infinities count as one step beyond `±f64::MAX`. Returns `u64::MAX` if
/// either argument is NaN.
pub fn ulp_distance(a: f64, b: f64) -> u64 {
    if a.is_nan() || b.is_nan() {
        return u64::MAX;
    }
    (i128::from(ordered(a)) - i128::from(ordered(b)))
        .unsigned_abs()
        .try_into()
        .unwrap_or(u64::MAX)
}

/// `ulp(x)` for a real `x` with `floor(log2 |x|) = e`: the spacing of the
/// doubles in the binade of `x`, `2^(max(e, −1022) − 52)`; for `x = 0` use
/// `e = i64::MIN`, giving the smallest subnormal `2^−1074`.
fn ulp_exp(e: i64) -> i64 {
    e.max(-1022) - 52
}

/// `floor(sqrt(r))` to within `2^w` from below: returns `L` with
/// `L <= sqrt(r) < L + 2^w`, for `r >= 0`.
fn sqrt_lower_bound(r: &BigRational, w: i64) -> BigRational {
    // floor(r / 4^w), then integer square root: floor(sqrt(floor(x))) equals
    // floor(sqrt(x)) for every real x >= 0.
    let scaled = r / pow2_rat(2 * w);
    let fl = scaled.numer().div_floor(scaled.denom());
    let root = fl.sqrt();
    BigRational::from_integer(root) * pow2_rat(w)
}

/// The square root of the nonnegative rational `r`, correctly rounded to the
/// nearest `f64` (ties to even; +∞ when the root reaches `f64::MAX + ulp/2`).
/// Returns NaN for negative `r`.
///
/// Method: a candidate from `f64::sqrt` of a scaled approximation, then
/// exact correction: `x` is the answer iff `r` lies between the squares of
/// the midpoints to its neighbours (with ties resolved to the even one).
pub fn sqrt_nearest(r: &BigRational) -> f64 {
    if r.is_negative() {
        return f64::NAN;
    }
    if r.is_zero() {
        return 0.0;
    }
    let k = floor_log2(r).div_euclid(2); // 2^k <= sqrt(r) < 2^(k+1)
    if k > 1023 {
        return f64::INFINITY;
    }
    let scaled = r / pow2_rat(2 * k); // in [1, 4)
    let y = to_f64_nearest(&scaled).sqrt();
    let mut x = ldexp(y, k.clamp(-1100, 1100) as i32);
    if x.is_infinite() {
        x = f64::MAX;
    }
    let two = BigRational::from_integer(BigInt::from(2));
    loop {
        let xr = rat(x).unwrap_or_else(BigRational::zero);
        let odd = x.to_bits() & 1 == 1;
        // Upper midpoint (x + next_up(x)) / 2; for MAX it is 2^1024 − 2^970.
        let hi = if x == f64::MAX {
            xr.clone() + pow2_rat(970)
        } else {
            (xr.clone() + rat(step_ulps(x, 1)).unwrap_or_else(BigRational::zero)) / &two
        };
        match r.cmp(&(&hi * &hi)) {
            Ordering::Greater => {
                if x == f64::MAX {
                    return f64::INFINITY;
                }
                x = step_ulps(x, 1);
                continue;
            }
            Ordering::Equal if odd => {
                if x == f64::MAX {
                    return f64::INFINITY;
                }
                x = step_ulps(x, 1);
                continue;
            }
            _ => {}
        }
        if x > 0.0 {
            let lo = (xr + rat(step_ulps(x, -1)).unwrap_or_else(BigRational::zero)) / &two;
            match r.cmp(&(&lo * &lo)) {
                Ordering::Less => {
                    x = step_ulps(x, -1);
                    continue;
                }
                Ordering::Equal if odd => {
                    x = step_ulps(x, -1);
                    continue;
                }
                _ => {}
            }
        }
        return x;
    }
}

/// How far `computed` is from the exact value `exact`, in units of
/// `ulp(exact)`: the exact ratio `|computed − exact| / ulp(exact)` rounded
/// **upward** to an `f64` (so it never understates the error).
///
/// `ulp(v)` is the spacing of doubles in the binade of `v`:
/// `2^(max(floor(log2 |v|), −1022) − 52)`, and `2^−1074` for `v = 0`. A
/// correctly rounded result therefore scores at most 0.5. Non-finite
/// `computed` gives +∞.
pub fn ulps_error(computed: f64, exact: &BigRational) -> f64 {
    let Some(c) = rat(computed) else {
        return f64::INFINITY;
    };
    let e = if exact.is_zero() {
        i64::MIN
    } else {
        floor_log2(exact)
    };
    let ulp = pow2_rat(ulp_exp(e));
    to_f64_up(&((c - exact).abs() / ulp))
}

/// How far `computed` is from `sqrt(exact_sq)` (an exact distance given by
/// its square), in units of `ulp(sqrt(exact_sq))`; an upper bound that
/// overstates the true ratio by at most `2^−64` (then rounded upward).
///
/// Method: the binade of the root is exact (`floor(log2 sqrt r) =
/// floor(floor(log2 r) / 2)`), giving the unit `u`; the root is bracketed
/// exactly as `L <= sqrt(r) < L + u·2^−64` by an integer square root, and the
/// bound is `max(|computed − L|, |computed − (L + u·2^−64)|) / u`. A correctly
/// rounded distance scores at most `0.5 + 2^−64`. Non-finite `computed` gives
/// +∞; negative `exact_sq` gives NaN (so `err <= budget` fails).
pub fn ulps_error_sqrt(computed: f64, exact_sq: &BigRational) -> f64 {
    if exact_sq.is_negative() {
        return f64::NAN;
    }
    let Some(c) = rat(computed) else {
        return f64::INFINITY;
    };
    let e = if exact_sq.is_zero() {
        i64::MIN
    } else {
        floor_log2(exact_sq).div_euclid(2)
    };
    let u_exp = ulp_exp(e);
    let w = u_exp - 64;
    let lo = sqrt_lower_bound(exact_sq, w);
    let hi = &lo + pow2_rat(w);
    let err = (&c - &lo).abs().max((&c - &hi).abs());
    to_f64_up(&(err / pow2_rat(u_exp)))
}

/// An upper bound of the error of `computed` against **every** point of the interval
/// `[lo, hi]`, in ulps: `max over x in [lo, hi] of |computed − x| / ulp(x)`, bounded by
/// `max(|computed − lo|, |computed − hi|) / ulp(m)` (`m` the point of the interval nearest 0) and
/// rounded upward. For `lo = hi` it is [`ulps_error`].
///
/// Why it bounds every point: `|computed − x|` is convex in `x`, so at most its value at an end;
/// `ulp(x)` does not decrease with `|x|`, so at least `ulp(m)`. Used to decide "within `b` ulps of
/// an exact value known only by an enclosure" (the CMMR of the large pairs,
/// [`crate::cmmr_enclosure`]): passing `≤ b` proves the bound for the exact value; an interval too
/// wide to decide gives a large bound, so the check fails rather than passes.
///
/// # Panics
/// Panics if `lo > hi`.
pub fn ulps_error_interval(computed: f64, lo: &BigRational, hi: &BigRational) -> f64 {
    assert!(lo <= hi, "ulps_error_interval: empty interval");
    let Some(c) = rat(computed) else {
        return f64::INFINITY;
    };
    let err = (&c - lo).abs().max((&c - hi).abs());
    to_f64_up(&(err / ulp_rat(&nearest_zero(lo, hi))))
}

/// The width `hi − lo` of an interval in units of `ulp(m)`, `m` its point nearest 0, rounded
/// upward: an upper bound of the width in ulps of any of its points.
pub(crate) fn width_ulps(lo: &BigRational, hi: &BigRational) -> f64 {
    to_f64_up(&((hi - lo).abs() / ulp_rat(&nearest_zero(lo, hi))))
}

/// The point of `[lo, hi]` nearest 0, as a magnitude.
fn nearest_zero(lo: &BigRational, hi: &BigRational) -> BigRational {
    if lo.is_positive() {
        lo.clone()
    } else if hi.is_negative() {
        -hi.clone()
    } else {
        BigRational::zero()
    }
}

/// `ulp(x)` as an exact rational (the smallest subnormal for 0).
fn ulp_rat(x: &BigRational) -> BigRational {
    let e = if x.is_zero() { i64::MIN } else { floor_log2(x) };
    pow2_rat(ulp_exp(e))
}
