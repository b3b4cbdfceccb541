//! `Expansion::to_f64` rounds the exact value once, to nearest (ties to even), checked against the
//! oracle's independent correctly rounded rational-to-double conversion.

mod common;

use common::q;
use polydist_oracle::to_f64_nearest;
use polydist_predicates::{Expansion, Polynomial, Ring, round_value};
use proptest::prelude::*;

fn check(e: &Expansion, exact: &num_rational::BigRational) {
    assert_eq!(
        e.to_f64().to_bits(),
        to_f64_nearest(exact).to_bits(),
        "{e:?}"
    );
}

/// Magnitudes whose triple products neither overflow nor underflow (Expansion's own contract).
fn moderate() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1.0..1.0f64, -300i32..300).prop_map(|(m, e)| m * 2f64.powi(e)),
        (-1e3..1e3f64).prop_map(|x| x),
        Just(0.0),
    ]
}

struct Cross2;
impl Polynomial<4> for Cross2 {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 4]) -> R {
        x[0].mul(&x[1]).sub(&x[2].mul(&x[3]))
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn round_value_decides_ties_and_near_ties(m in 1u64..(1 << 52), e in -500i32..500, k in -3i32..=3, z in 40u32..70) {
        // x·1 − c·1 with c = half an ulp of x, nudged by k·2^-z relative: exact ties and values a hair
        // from a midpoint, where the double-double stage must defer to exact arithmetic.
        let x = (m as f64 + (1u64 << 52) as f64) * 2f64.powi(e);
        let half = (x.next_up() - x) / 2.0;
        let c = half + f64::from(k) * half * 2f64.powi(-(z as i32));
        let exact = q(x) - q(c);
        prop_assert_eq!(round_value(&Cross2, &[x, 1.0, c, 1.0]).to_bits(), to_f64_nearest(&exact).to_bits());
        let exact = q(x) + q(c);
        prop_assert_eq!(round_value(&Cross2, &[x, 1.0, -c, 1.0]).to_bits(), to_f64_nearest(&exact).to_bits());
    }

    #[test]
    fn round_value_is_correctly_rounded_over_the_whole_range(a in common::any_coord(), b in common::any_coord(), c in common::any_coord(), d in common::any_coord()) {
        let exact = q(a) * q(b) - q(c) * q(d);
        let want = to_f64_nearest(&exact);
        let got = round_value(&Cross2, &[a, b, c, d]);
        // Outside the subnormal range the rounding is correct; inside it, within one subnormal step.
        if want.abs() >= f64::MIN_POSITIVE || want == 0.0 && got == 0.0 {
            prop_assert_eq!(got.to_bits(), want.to_bits());
        } else {
            prop_assert!((got - want).abs() <= f64::from_bits(1), "{} vs {}", got, want);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn products_and_sums_round_correctly(a in moderate(), b in moderate(), c in moderate(), d in moderate()) {
        let (ea, eb, ec, ed) = (Expansion::input(a), Expansion::input(b), Expansion::input(c), Expansion::input(d));
        // a·b − c·d: the cross-product shape every construction rounds once.
        let v = ea.mul(&eb).sub(&ec.mul(&ed));
        check(&v, &(q(a) * q(b) - q(c) * q(d)));
        // a + b + c + d and a·b·c (wide exponent spreads, subnormal results, exact ties).
        check(&ea.add(&eb).add(&ec).add(&ed), &(q(a) + q(b) + q(c) + q(d)));
        check(&ea.mul(&eb).mul(&ec), &(q(a) * q(b) * q(c)));
    }

    #[test]
    fn halfway_cases_round_to_even(m in 1u64..(1 << 52), e in -60i32..60) {
        // x + half an ulp of x: an exact tie.
        let x = (m as f64 + (1u64 << 52) as f64) * 2f64.powi(e);
        let half = (x.next_up() - x) / 2.0;
        let v = Expansion::input(x).add(&Expansion::input(half));
        check(&v, &(q(x) + q(half)));
        let v = Expansion::input(x).sub(&Expansion::input(half / 2.0));
        check(&v, &(q(x) - q(half / 2.0)));
    }
}
