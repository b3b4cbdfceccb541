//! The shared facility for algorithm-specific polynomials: a degree-6 test on a constructed point, and
//! high-degree products that force every stage of the pipeline.

mod common;

use common::{q, sgn};
use glam::DVec2;
use num_rational::BigRational;
use polydist_predicates::{
    Counted, Exact, Fast, Kernel, Polynomial, Ring, Robust, Sign, predicate_counts,
    reset_predicate_counts,
};
use proptest::prelude::*;

/// sign((d − c) · (f − c)) where f is the foot of p on line ab, cleared of |b − a|² > 0:
/// (d − c) · (|e|²(a − c) + ((p − a)·e) e), e = b − a. Degree 5... times nothing: homogeneous degree 4
/// in coordinates (|e|² (a − c) is degree 3, ((p − a)·e) e is degree 3, dotted with (d − c): degree 4).
struct FootSide;
impl Polynomial<10> for FootSide {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 10]) -> R {
        let (px, py, ax, ay, bx, by) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
        let (cx, cy, dx, dy) = (&x[6], &x[7], &x[8], &x[9]);
        let (ex, ey) = (bx.sub(ax), by.sub(ay));
        let l2 = ex.square().add(&ey.square());
        let t = px.sub(ax).mul(&ex).add(&py.sub(ay).mul(&ey));
        let fx = l2.mul(&ax.sub(cx)).add(&t.mul(&ex));
        let fy = l2.mul(&ay.sub(cy)).add(&t.mul(&ey));
        dx.sub(cx).mul(&fx).add(&dy.sub(cy).mul(&fy))
    }
}

fn foot_side_exact(v: &[f64; 10]) -> i8 {
    let r: Vec<BigRational> = v.iter().map(|&x| q(x)).collect();
    let (ex, ey) = (&r[4] - &r[2], &r[5] - &r[3]);
    let l2 = &ex * &ex + &ey * &ey;
    let t = (&r[0] - &r[2]) * &ex + (&r[1] - &r[3]) * &ey;
    let fx = &l2 * (&r[2] - &r[6]) + &t * &ex;
    let fy = &l2 * (&r[3] - &r[7]) + &t * &ey;
    sgn(&((&r[8] - &r[6]) * fx + (&r[9] - &r[7]) * fy))
}

/// (x0 − x1)^k, a degree-k polynomial whose sign is known in closed form.
struct PowerOfDiff<const K: u32>;
impl<const K: u32> Polynomial<2> for PowerOfDiff<K> {
    const DEGREE: u32 = K;
    fn eval<R: Ring>(&self, x: &[R; 2]) -> R {
        let d = x[0].sub(&x[1]);
        let mut acc = d.clone();
        for _ in 1..K {
            acc = acc.mul(&d);
        }
        acc
    }
}

fn power_sign(a: f64, b: f64, k: u32) -> Sign {
    let d = q(a) - q(b);
    let s = sgn(&d);
    let s = if k % 2 == 0 { s * s } else { s };
    match s {
        1 => Sign::Positive,
        -1 => Sign::Negative,
        _ => Sign::Zero,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    #[test]
    fn foot_of_perpendicular_side_test_is_exact(
        a in common::scaled_point(1.0, 1e6), b in common::scaled_point(1.0, 1e6), p in common::scaled_point(1.0, 1e6),
        k in -2i32..=2,
    ) {
        // c = the foot rounded, d = c moved along the perpendicular: the exact answer is near zero.
        let e = b - a;
        let l2 = e.length_squared();
        prop_assume!(l2 > 0.0);
        let f = a + e * ((p - a).dot(e) / l2);
        let c = DVec2::new(common::nudge(f.x, k), f.y);
        let d = c + DVec2::new(e.x, e.y);
        let v = [p.x, p.y, a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y];
        let want = foot_side_exact(&v);
        prop_assert_eq!(Robust::sign(&FootSide, &v).to_ordering() as i8, want);
        prop_assert_eq!(Exact::sign(&FootSide, &v).to_ordering() as i8, want);
    }

    #[test]
    fn high_degree_signs_are_exact(a in common::any_coord(), k in -3i32..=3) {
        let b = common::nudge(a, k);
        prop_assert_eq!(Robust::sign(&PowerOfDiff::<7>, &[a, b]), power_sign(a, b, 7));
        prop_assert_eq!(Exact::sign(&PowerOfDiff::<7>, &[a, b]), power_sign(a, b, 7));
        prop_assert_eq!(Robust::sign(&PowerOfDiff::<16>, &[a, b]), power_sign(a, b, 16));
        prop_assert_eq!(Exact::sign(&PowerOfDiff::<16>, &[a, b]), power_sign(a, b, 16));
    }
}

#[test]
fn fast_underflows_where_robust_does_not() {
    // (a − b)^16 with a − b = 2^-70: the true value 2^-1120 underflows to 0 in f64.
    let b = 2f64.powi(-18);
    let a = b.next_up();
    assert_eq!(a - b, 2f64.powi(-70));
    assert_eq!(Fast::sign(&PowerOfDiff::<16>, &[a, b]), Sign::Zero);
    assert_eq!(Robust::sign(&PowerOfDiff::<16>, &[a, b]), Sign::Positive);
    assert_eq!(Exact::sign(&PowerOfDiff::<16>, &[b, a]), Sign::Positive);
    assert_eq!(Exact::sign(&PowerOfDiff::<7>, &[b, a]), Sign::Negative);
}

#[test]
fn non_finite_inputs_never_panic() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let _ = Robust::sign(&PowerOfDiff::<3>, &[bad, 1.0]);
        let _ = Exact::sign(&PowerOfDiff::<3>, &[1.0, bad]);
        let _ = Robust::orient(DVec2::new(bad, 0.0), DVec2::ZERO, DVec2::ONE);
        let _ = Exact::orient(DVec2::new(bad, 0.0), DVec2::ZERO, DVec2::ONE);
        let _ = Fast::orient(DVec2::new(bad, 0.0), DVec2::ZERO, DVec2::ONE);
    }
}

#[test]
fn counted_kernel_counts_each_call_once() {
    reset_predicate_counts();
    let (a, b, c) = (DVec2::ZERO, DVec2::X, DVec2::Y);
    for _ in 0..5 {
        let _ = Counted::<Robust>::orient(a, b, c);
    }
    let _ = Counted::<Exact>::dot_sign(a, b, c, a);
    let _ = Counted::<Fast>::sign(&PowerOfDiff::<3>, &[1.0, 2.0]);
    let _ = Counted::<Robust>::cmp_dist2(
        polydist_predicates::Dist2::PointSegment(a, b, c),
        polydist_predicates::Dist2::PointPoint(a, b),
    );
    let n = predicate_counts();
    assert_eq!(
        (n.orient, n.dot, n.sign, n.cmp_dist2, n.total()),
        (5, 1, 1, 1, 8)
    );
    reset_predicate_counts();
    assert_eq!(predicate_counts().total(), 0);
}
