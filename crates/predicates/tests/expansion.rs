//! `Expansion`'s sum, difference and product against exact rationals: the value is exact and the
//! representation keeps its invariants (components nonzero, increasing in magnitude, nonoverlapping),
//! on random expression trees whose intermediates grow to long expansions, with cancellation.

mod common;

use common::q;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use polydist_predicates::{Expansion, Ring};
use proptest::prelude::*;

/// The exponents of the highest and lowest set bits of a nonzero finite double.
fn bit_range(x: f64) -> (i64, i64) {
    let b = x.abs().to_bits();
    let (field, frac) = ((b >> 52) as i64, b & ((1 << 52) - 1));
    let (m, ex) = if field == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), field - 1075)
    };
    (
        ex + 63 - i64::from(m.leading_zeros()),
        ex + i64::from(m.trailing_zeros()),
    )
}

/// Nonzero, increasing in magnitude, and nonoverlapping: the lowest set bit of each component lies
/// above the highest set bit of the one before (Shewchuk's definition).
fn assert_invariants(e: &Expansion) {
    let c = e.components();
    assert!(c.iter().all(|&x| x != 0.0 && x.is_finite()), "{c:?}");
    for w in c.windows(2) {
        assert!(
            bit_range(w[0]).0 < bit_range(w[1]).1,
            "overlapping components {c:?}"
        );
    }
}

/// Within the expansions' contract: the exact value's bits lie in `[2^-900, 2^900]`, so no
/// partial product underflows and nothing overflows.
fn in_contract(v: &BigRational) -> bool {
    v.is_zero() || (v.denom().bits() <= 900 && (v.numer().abs() / v.denom()).bits() <= 900)
}

fn value(e: &Expansion) -> BigRational {
    e.components()
        .iter()
        .fold(BigRational::zero(), |acc, &x| acc + q(x))
}

/// Moderate magnitudes (the expansions' contract: no overflow, no underflow of products), many
/// sharing bits so that sums cancel.
fn input() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1.0..1.0f64, -60i32..60).prop_map(|(m, e)| m * 2f64.powi(e)),
        (-1000i64..1000).prop_map(|k| k as f64 * 0.1),
        (-64i64..64).prop_map(|k| k as f64),
        Just(0.0),
    ]
}

/// An expression over the inputs: `(op, i, j)` combines intermediate `i` and `j` into a new one.
fn program() -> impl Strategy<Value = (Vec<f64>, Vec<(u8, usize, usize)>)> {
    (
        prop::collection::vec(input(), 2..8),
        prop::collection::vec((0u8..4, 0usize..64, 0usize..64), 1..14),
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    #[test]
    fn operations_are_exact_and_keep_the_invariants((xs, ops) in program()) {
        let mut vals: Vec<(Expansion, BigRational)> =
            xs.iter().map(|&x| (Expansion::input(x), q(x))).collect();
        for (op, i, j) in ops {
            let (a, b) = (&vals[i % vals.len()], &vals[j % vals.len()]);
            let next = match op {
                0 => (a.0.add(&b.0), &a.1 + &b.1),
                1 => (a.0.sub(&b.0), &a.1 - &b.1),
                2 => (a.0.mul(&b.0), &a.1 * &b.1),
                _ => (a.0.neg(), -a.1.clone()),
            };
            if !in_contract(&next.1) {
                continue;
            }
            assert_invariants(&next.0);
            prop_assert_eq!(value(&next.0), next.1.clone());
            // x − x is exactly zero, with no components.
            prop_assert!(next.0.sub(&next.0).is_empty());
            vals.push(next);
        }
    }
}
