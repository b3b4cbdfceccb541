//! Correct rounding and ulp measurement, checked against IEEE hardware
//! arithmetic (which is correctly rounded for +, ×, ÷ and sqrt) and
//! hand-computed ties.

use num_bigint::BigInt;
use num_rational::BigRational;
use polydist_oracle::{
    SplitMix64, rat, sqrt_nearest, step_ulps, to_f64_nearest, ulp_distance, ulps_error,
    ulps_error_interval, ulps_error_sqrt,
};
use proptest::prelude::*;

fn pow2(k: i32) -> BigRational {
    if k >= 0 {
        BigRational::from_integer(BigInt::from(1) << k.unsigned_abs())
    } else {
        BigRational::new(BigInt::from(1), BigInt::from(1) << k.unsigned_abs())
    }
}

fn r(x: f64) -> BigRational {
    rat(x).unwrap()
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// A random finite double from raw bits (all binades, subnormals, signs).
fn any_finite(rng: &mut SplitMix64) -> f64 {
    loop {
        let x = f64::from_bits(rng.next_u64());
        if x.is_finite() {
            return x;
        }
    }
}

#[test]
fn round_trip_of_doubles() {
    let mut rng = SplitMix64::new(1);
    for _ in 0..2000 {
        let x = any_finite(&mut rng);
        assert!(same(to_f64_nearest(&r(x)), x), "{x:e}");
    }
    for x in [
        0.0,
        f64::MIN_POSITIVE,
        f64::MAX,
        -f64::MAX,
        f64::from_bits(1),
        1.0,
    ] {
        assert!(same(to_f64_nearest(&r(x)), x));
    }
}

#[test]
fn matches_hardware_arithmetic() {
    let mut rng = SplitMix64::new(2);
    for i in 0..3000 {
        let (a, b) = if i % 2 == 0 {
            (any_finite(&mut rng), any_finite(&mut rng))
        } else {
            // Nearby magnitudes so that sums and subnormal products are common.
            let a = any_finite(&mut rng);
            let e = rng.range_i64(-60, 60) as i32;
            (a, a * 2f64.powi(e) * (rng.unit_f64() + 0.5))
        };
        if !b.is_finite() {
            continue;
        }
        assert!(same(to_f64_nearest(&(r(a) + r(b))), a + b), "{a:e} + {b:e}");
        assert!(same(to_f64_nearest(&(r(a) * r(b))), a * b), "{a:e} * {b:e}");
        if b != 0.0 {
            let want = a / b;
            let got = to_f64_nearest(&(r(a) / r(b)));
            // Zero results: the sign of the rational is the sign of the true
            // quotient, which IEEE also uses.
            assert!(same(got, want), "{a:e} / {b:e}: {got:e} vs {want:e}");
        }
        if a >= 0.0 {
            assert!(same(sqrt_nearest(&r(a)), a.sqrt()), "sqrt {a:e}");
        }
    }
}

#[test]
fn ties_to_even_and_ranges() {
    let one = BigRational::from_integer(BigInt::from(1));
    // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: even is 1.
    assert_eq!(to_f64_nearest(&(&one + pow2(-53))), 1.0);
    // 1 + 3·2^-53 is halfway between 1 + 2^-52 (odd) and 1 + 2^-51 (even).
    let three = BigRational::from_integer(BigInt::from(3));
    assert_eq!(
        to_f64_nearest(&(&one + &three * pow2(-53))),
        1.0 + 2f64.powi(-51)
    );
    // Just above / below a tie.
    assert_eq!(
        to_f64_nearest(&(&one + pow2(-53) + pow2(-200))),
        1.0 + 2f64.powi(-52)
    );
    assert_eq!(to_f64_nearest(&(&one + pow2(-53) - pow2(-200))), 1.0);
    // Subnormal ties.
    assert!(same(to_f64_nearest(&pow2(-1075)), 0.0));
    assert!(same(to_f64_nearest(&-pow2(-1075)), -0.0));
    assert!(same(
        to_f64_nearest(&(&three * pow2(-1075))),
        f64::from_bits(2)
    ));
    assert!(same(
        to_f64_nearest(&(pow2(-1075) + pow2(-1200))),
        f64::from_bits(1)
    ));
    assert!(same(to_f64_nearest(&pow2(-5000)), 0.0));
    // Boundary between subnormal and normal.
    assert!(same(
        to_f64_nearest(&(pow2(-1022) - pow2(-1076))),
        f64::MIN_POSITIVE
    ));
    // Overflow: MAX + half an ulp is a tie with 2^1024, whose even side wins.
    let max = r(f64::MAX);
    assert_eq!(to_f64_nearest(&(&max + pow2(970))), f64::INFINITY);
    assert_eq!(to_f64_nearest(&(&max + pow2(970) - pow2(900))), f64::MAX);
    assert_eq!(to_f64_nearest(&-(&max + pow2(971))), f64::NEG_INFINITY);
    assert_eq!(to_f64_nearest(&pow2(5000)), f64::INFINITY);
    // Non-dyadic.
    let third = BigRational::new(BigInt::from(1), BigInt::from(3));
    assert_eq!(to_f64_nearest(&third), 1.0 / 3.0);
    let tenth = BigRational::new(BigInt::from(1), BigInt::from(10));
    assert_eq!(to_f64_nearest(&tenth), 0.1);
}

#[test]
fn sqrt_known_values() {
    let two = BigRational::from_integer(BigInt::from(2));
    #[expect(
        clippy::approx_constant,
        reason = "the hand-written decimal is the point of this check"
    )]
    let want = 1.4142135623730951;
    assert_eq!(sqrt_nearest(&two), want);
    assert_eq!(sqrt_nearest(&two).to_bits(), 0x3FF6_A09E_667F_3BCD);
    assert_eq!(sqrt_nearest(&two), core::f64::consts::SQRT_2);
    assert_eq!(
        sqrt_nearest(&BigRational::from_integer(BigInt::from(144))),
        12.0
    );
    assert_eq!(
        sqrt_nearest(&BigRational::new(BigInt::from(9), BigInt::from(16))),
        0.75
    );
    assert!(sqrt_nearest(&-two).is_nan());
    assert_eq!(
        sqrt_nearest(&BigRational::from_integer(BigInt::from(0))),
        0.0
    );
    // Squares of doubles come back exactly, far outside the f64 range of the
    // square itself.
    let mut rng = SplitMix64::new(3);
    for _ in 0..500 {
        let x = any_finite(&mut rng).abs();
        let sq = r(x) * r(x);
        assert!(same(sqrt_nearest(&sq), x), "{x:e}");
        // One part in 2^200 above or below still rounds to x.
        let eps = &sq * pow2(-200);
        assert!(same(sqrt_nearest(&(&sq + &eps)), x));
        if x > 0.0 {
            assert!(same(sqrt_nearest(&(&sq - &eps)), x));
        }
    }
    // Ties: sqrt exactly halfway between two doubles.
    let one = BigRational::from_integer(BigInt::from(1));
    let mid = &one + pow2(-53); // between 1 and 1 + 2^-52 → even is 1
    assert_eq!(sqrt_nearest(&(&mid * &mid)), 1.0);
    let three = BigRational::from_integer(BigInt::from(3));
    let mid = &one + &three * pow2(-53); // → 1 + 2^-51
    assert_eq!(sqrt_nearest(&(&mid * &mid)), 1.0 + 2f64.powi(-51));
    let mid = pow2(-1075); // between 0 and the smallest subnormal → 0
    assert!(same(sqrt_nearest(&(&mid * &mid)), 0.0));
    let mid = &three * pow2(-1075); // → 2^-1073
    assert!(same(sqrt_nearest(&(&mid * &mid)), f64::from_bits(2)));
    // Overflow threshold.
    let max = r(f64::MAX);
    let hi = &max + pow2(970);
    assert_eq!(sqrt_nearest(&(&hi * &hi)), f64::INFINITY);
    assert_eq!(sqrt_nearest(&(&hi * &hi - pow2(0))), f64::MAX);
    assert_eq!(sqrt_nearest(&pow2(2100)), f64::INFINITY);
}

#[test]
fn ulp_distances() {
    assert_eq!(ulp_distance(1.0, 1.0), 0);
    assert_eq!(ulp_distance(1.0, step_ulps(1.0, 1)), 1);
    assert_eq!(ulp_distance(step_ulps(1.0, -1), 1.0), 1);
    assert_eq!(ulp_distance(0.0, -0.0), 0);
    let s = f64::from_bits(1);
    assert_eq!(ulp_distance(-s, s), 2);
    assert_eq!(ulp_distance(-s, 0.0), 1);
    assert_eq!(ulp_distance(1.0, 2.0), 1 << 52);
    assert_eq!(ulp_distance(-1.0, 1.0), 2 * 0x3FF0_0000_0000_0000);
    assert_eq!(ulp_distance(f64::MAX, f64::INFINITY), 1);
    assert_eq!(ulp_distance(f64::NAN, 1.0), u64::MAX);
    assert_eq!(step_ulps(0.0, 1), s);
    assert_eq!(step_ulps(-0.0, 1), s);
    assert_eq!(step_ulps(s, -2), -s);
    assert_eq!(step_ulps(f64::MAX, 5), f64::INFINITY);
    assert_eq!(step_ulps(1.0, -1), 1.0 - 2f64.powi(-53));
    assert_eq!(step_ulps(-1.0, 1), -(1.0 - 2f64.powi(-53)));
    let mut rng = SplitMix64::new(4);
    for _ in 0..1000 {
        let x = any_finite(&mut rng);
        let k = rng.range_i64(-1000, 1000);
        let y = step_ulps(x, k);
        if y.is_finite() && !(x == 0.0 && k == 0) {
            assert_eq!(ulp_distance(x, y), k.unsigned_abs(), "{x:e} {k}");
        }
    }
}

#[test]
fn ulps_error_values() {
    let third = BigRational::new(BigInt::from(1), BigInt::from(3));
    let x = to_f64_nearest(&third);
    let e = ulps_error(x, &third);
    assert!(e > 0.3 && e <= 0.5, "{e}");
    assert_eq!(ulps_error(0.5, &r(0.5)), 0.0);
    assert_eq!(ulps_error(step_ulps(0.5, 3), &r(0.5)), 3.0);
    assert_eq!(ulps_error(step_ulps(0.5, -3), &r(0.5)), 1.5, "binade below");
    assert_eq!(ulps_error(f64::from_bits(7), &r(0.0)), 7.0);
    assert_eq!(ulps_error(f64::NAN, &r(0.5)), f64::INFINITY);
    // Rounding of the ratio is upward: tiny true errors never report 0.
    let exact = r(1.0) + pow2(-300);
    let e = ulps_error(1.0, &exact);
    assert!(e > 0.0 && e < 1e-70, "{e}");
}

/// The error against an interval bounds the error against each of its points, is exact for a
/// point interval, and grows with the interval (a wide one cannot pass a tight bound).
#[test]
fn ulps_error_interval_values() {
    let mut rng = SplitMix64::new(0x1e7);
    for _ in 0..2000 {
        let x = any_finite(&mut rng).abs();
        if x == 0.0 || x > 1e300 {
            continue;
        }
        let (a, b) = (step_ulps(x, -3), step_ulps(x, 5));
        let (lo, hi) = (r(a), r(b));
        // A point interval: the same as `ulps_error`.
        assert_eq!(ulps_error_interval(x, &lo, &lo), ulps_error(x, &lo));
        let bound = ulps_error_interval(x, &lo, &hi);
        // Every double in the interval, and points between doubles, are covered.
        for k in -3..=5 {
            let y = r(step_ulps(x, k));
            assert!(ulps_error(x, &y) <= bound, "{x:e} {k}");
            let mid = (&y + r(step_ulps(x, k + 1))) / BigRational::from_integer(2.into());
            if k < 5 {
                assert!(ulps_error(x, &mid) <= bound, "{x:e} {k}.5");
            }
        }
        assert!(bound >= 5.0, "{x:e}: {bound}");
    }
    // Across a power of two the smaller ulp (of the lower end) is used.
    let (lo, hi) = (r(step_ulps(1.0, -2)), r(step_ulps(1.0, 2)));
    assert_eq!(ulps_error_interval(1.0, &lo, &hi), 4.0);
    // An interval containing 0 measures in the smallest subnormal.
    assert_eq!(
        ulps_error_interval(0.0, &r(-0.0), &r(f64::from_bits(3))),
        3.0
    );
    assert_eq!(
        ulps_error_interval(f64::NAN, &lo, &hi),
        f64::INFINITY,
        "NaN never passes"
    );
}

#[test]
fn ulps_error_sqrt_values() {
    let four = r(4.0);
    let e = ulps_error_sqrt(2.0, &four);
    assert!((0.0..1e-18).contains(&e), "{e}");
    let e = ulps_error_sqrt(step_ulps(2.0, 1), &four);
    assert!((1.0..=1.0 + 1e-15).contains(&e), "{e}");
    let e = ulps_error_sqrt(step_ulps(2.0, -1), &four);
    assert!((0.5..=0.5 + 1e-15).contains(&e), "{e}");
    let two = r(2.0);
    let s = sqrt_nearest(&two);
    let e0 = ulps_error_sqrt(s, &two);
    assert!(e0 > 0.0 && e0 <= 0.5, "{e0}");
    for k in 1..6i64 {
        let e = ulps_error_sqrt(step_ulps(s, k), &two);
        let k = k as f64;
        assert!(e > k - 0.5 && e <= k + 0.5, "{k} {e}");
    }
    assert_eq!(ulps_error_sqrt(f64::INFINITY, &two), f64::INFINITY);
    assert!(ulps_error_sqrt(1.0, &-two).is_nan());
    let e = ulps_error_sqrt(f64::from_bits(3), &r(0.0));
    assert!((3.0..=3.0 + 1e-15).contains(&e), "{e}");
    // Far outside the f64 range of the square: distance 1e300 exactly.
    let big = r(1e300) * r(1e300);
    let e = ulps_error_sqrt(step_ulps(1e300, 2), &big);
    assert!((2.0..=2.0 + 1e-15).contains(&e), "{e}");
}

proptest! {
    #[test]
    fn sqrt_error_within_half_ulp(bits in any::<u64>()) {
        let x = f64::from_bits(bits >> 1); // nonnegative
        prop_assume!(x.is_finite());
        let sq = r(x) * r(x) + pow2(-1100);
        let s = sqrt_nearest(&sq);
        prop_assert!(ulps_error_sqrt(s, &sq) <= 0.5 + 1e-15);
        let s2 = step_ulps(s, 1);
        prop_assert!(ulps_error_sqrt(s2, &sq) >= 0.5);
    }

    #[test]
    fn nearest_error_within_half_ulp(n in any::<i64>(), d in 1i64..i64::MAX) {
        let q = BigRational::new(BigInt::from(n), BigInt::from(d));
        let x = to_f64_nearest(&q);
        prop_assert!(ulps_error(x, &q) <= 0.5);
        prop_assert!(ulps_error(step_ulps(x, 1), &q) >= 0.5);
        prop_assert!(ulps_error(step_ulps(x, -1), &q) >= 0.5);
    }
}
