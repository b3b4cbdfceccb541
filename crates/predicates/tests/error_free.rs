//! The Robust kernel's second stage, [`ErrorFree`]: a plain `f64` evaluation that claims exactness
//! only when no operation rounded. Every claim is checked against an independent rational evaluation
//! of the same polynomial, on coarse inputs (where the claim should be made) and on inputs of every
//! magnitude class, including the underflow and overflow ranges the stage must refuse.

mod common;

use common::{any_coord, q, sgn};
use num_rational::BigRational;
use num_traits::Zero;
use polydist_predicates::{
    Dist4, ErrorFree, Exact, Kernel, Nearer, Orient, PerpVsPerp, PointsVsPerp, Polynomial, Ring,
    Robust, Sign,
};
use proptest::prelude::*;

/// Rationals as a [`Ring`]: the reference evaluation of any predicate polynomial.
#[derive(Clone, Debug)]
struct Rat(BigRational);

impl Ring for Rat {
    fn input(x: f64) -> Self {
        Rat(q(x))
    }
    fn add(&self, rhs: &Self) -> Self {
        Rat(&self.0 + &rhs.0)
    }
    fn sub(&self, rhs: &Self) -> Self {
        Rat(&self.0 - &rhs.0)
    }
    fn mul(&self, rhs: &Self) -> Self {
        Rat(&self.0 * &rhs.0)
    }
    fn neg(&self) -> Self {
        Rat(-&self.0)
    }
}

/// The error-free evaluation and the exact value. When the former claims exactness its value must be
/// the exact value itself (not only of the same sign); the kernels must agree with the exact sign.
fn check<const N: usize, P: Polynomial<N>>(p: &P, x: &[f64; N]) -> Result<bool, TestCaseError> {
    let ef = p.eval(&x.map(ErrorFree::input));
    let exact = p.eval(&x.map(Rat::input)).0;
    if ef.exact {
        prop_assert!(ef.value.is_finite());
        prop_assert_eq!(q(ef.value), exact.clone(), "claimed exact at {:?}", x);
        prop_assert_eq!(
            ef.exact_sign().map(|s| s.to_ordering() as i8),
            Some(sgn(&exact))
        );
    } else {
        prop_assert_eq!(ef.exact_sign(), None);
    }
    let want = sgn(&exact);
    prop_assert_eq!(Robust::sign(p, x).to_ordering() as i8, want);
    prop_assert_eq!(Exact::sign(p, x).to_ordering() as i8, want);
    Ok(ef.exact)
}

/// Coarse coordinates: integers below `2^bits` in units of `2^unit`. For a polynomial of degree `D`
/// in differences of such inputs the exact value needs about `D·(bits + 1) + 4` bits, so with
/// `bits = 24, 10, 6` for degrees 2, 4 and 6 every intermediate fits in 53 bits and is exact.
fn coarse(bits: u32, unit: i32) -> impl Strategy<Value = f64> {
    let m = 1i64 << bits;
    (-m..m).prop_map(move |m| m as f64 * 2f64.powi(unit))
}

fn coarse_input<const N: usize>(bits: u32) -> impl Strategy<Value = [f64; N]> {
    (-40i32..40).prop_flat_map(move |unit| proptest::array::uniform(coarse(bits, unit)))
}

/// Coarse inputs that tie or cancel often: a few distinct values only.
fn tying_input<const N: usize>() -> impl Strategy<Value = [f64; N]> {
    (-40i32..40).prop_flat_map(|unit| {
        proptest::array::uniform((-3i64..=3).prop_map(move |m| m as f64 * 2f64.powi(unit)))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// On coarse inputs every polynomial up to degree 6 is evaluated without rounding: the stage decides,
    /// and its value is the exact value.
    #[test]
    fn coarse_inputs_are_decided_exactly(
        o in coarse_input::<6>(24), d in coarse_input::<8>(24),
        pp in coarse_input::<10>(10), p6 in coarse_input::<12>(6),
    ) {
        prop_assert!(check(&Orient, &o)?);
        prop_assert!(check(&Nearer, &o)?);
        prop_assert!(check(&Dist4, &d)?);
        prop_assert!(check(&PointsVsPerp, &pp)?);
        prop_assert!(check(&PerpVsPerp, &p6)?);
    }

    /// Ties and exact zeros on coarse inputs, the calls the filter cannot decide.
    #[test]
    fn coarse_ties_are_decided_exactly(
        d in tying_input::<8>(), pp in tying_input::<10>(), p6 in tying_input::<12>(),
    ) {
        prop_assert!(check(&Dist4, &d)?);
        prop_assert!(check(&PointsVsPerp, &pp)?);
        prop_assert!(check(&PerpVsPerp, &p6)?);
    }

    /// Inputs of every magnitude class (huge, tiny, subnormal, zero): every claim of exactness is true,
    /// and the kernels' signs are exact whether or not the stage decided.
    #[test]
    fn claims_are_true_at_every_magnitude(
        d in proptest::array::uniform8(any_coord()),
        pp in proptest::array::uniform10(any_coord()),
        p6 in proptest::array::uniform12(any_coord()),
    ) {
        check(&Dist4, &d)?;
        check(&PointsVsPerp, &pp)?;
        check(&PerpVsPerp, &p6)?;
    }
}

#[test]
fn a_product_that_underflows_is_not_exact() {
    let x = |v: f64| ErrorFree::input(v);
    // 2^-600 · 2^-600 rounds to zero: a zero product of nonzero factors is not the exact value.
    let z = x(2f64.powi(-600)).mul(&x(2f64.powi(-600)));
    assert_eq!(z.value, 0.0);
    assert!(!z.exact);
    // 2^-540 · 2^-540 = 2^-1080 is below the smallest subnormal's reach: rounded, refused.
    assert!(!x(2f64.powi(-540)).mul(&x(2f64.powi(-540))).exact);
    // A tiny exact product is still refused below 2^-900 (the Two-Product range), and accepted above.
    assert!(!x(2f64.powi(-460)).mul(&x(2f64.powi(-460))).exact);
    assert!(x(2f64.powi(-440)).mul(&x(2f64.powi(-440))).exact);
    // A zero factor gives an exact zero.
    let zero = x(0.0).mul(&x(2f64.powi(-600)));
    assert!(zero.exact && zero.value == 0.0);
}

#[test]
fn overflow_and_non_finite_inputs_are_not_exact() {
    let x = |v: f64| ErrorFree::input(v);
    assert!(!x(f64::MAX).add(&x(f64::MAX)).exact);
    assert!(!x(2f64.powi(501)).mul(&x(1.0)).exact, "factor beyond 2^500");
    assert!(!x(2f64.powi(520)).mul(&x(2f64.powi(520))).exact);
    assert!(!x(f64::NAN).exact && !x(f64::INFINITY).exact);
    assert!(!x(f64::NAN).add(&x(1.0)).exact);
}

#[test]
fn a_rounded_sum_or_product_is_not_exact() {
    let x = |v: f64| ErrorFree::input(v);
    assert!(!x(1.0).add(&x(2f64.powi(-60))).exact);
    assert!(!x(0.1).mul(&x(0.1)).exact);
    assert!(x(0.5).add(&x(0.25)).exact);
    assert!(x(3.0).mul(&x(0.125)).exact);
    // (1 + 2^-30)² needs 61 bits: rounded.
    let a = 1.0 + 2f64.powi(-30);
    assert!(!x(a).mul(&x(a)).exact);
}

#[test]
fn an_exact_tie_between_two_perpendicular_distances_is_decided_here() {
    // Two points at perpendicular distance 1/8 from two different edges: PerpVsPerp is exactly zero,
    // which no filter can certify; the error-free stage evaluates it without a rounding.
    let x = [
        1.0, 0.125, 0.0, 0.0, 4.0, 0.0, 7.0, 5.125, 6.0, 5.0, 9.0, 5.0,
    ];
    let ef = PerpVsPerp.eval(&x.map(ErrorFree::input));
    assert!(ef.exact);
    assert_eq!(ef.value, 0.0);
    assert!(PerpVsPerp.eval(&x.map(Rat::input)).0.is_zero());
    assert_eq!(Robust::sign(&PerpVsPerp, &x), Sign::Zero);
}
