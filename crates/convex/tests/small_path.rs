//! The small-input path of `distance_with` (two polygons with `n + m < 512`): the certified support
//! guess (sampled supports, GJK refinements, a local descent, then Theorem 1 under the kernel), else
//! the walk (`n + m < 64`), else the search. Its answers must be exactly the search's, whatever path
//! produced them, and agree with the exact oracle; on separated pairs it answers almost always.

mod common;

use common::{RELATIONS, Worst, check_answer, merge};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Robust};
use polydist_convex::{distance_with, distance_yang_with, reset_search_stats, search_stats};
use polydist_oracle::{
    Relation, SplitMix64, contact_status_convex, convex_distance, convex_pair, random_convex,
};

/// Every relation at sizes beyond the walk's (`n + m ≥ 64`, up to 511): the answer equals the search's
/// under Robust and Exact, and the exact oracle's (features, numbers within the budgets).
#[test]
fn support_guess_equals_the_search_every_relation() {
    let mut rng = SplitMix64::new(2026);
    let (mut disjoint, mut answered) = (0u64, 0u64);
    let mut worst = Worst::default();
    for rel in RELATIONS {
        for round in 0..24 {
            let n = [3, 8, 20, 33, 64, 127, 200, 255][round % 8];
            let m = [40, 64, 5, 31, 100, 128, 60, 255][(round / 3) % 8];
            let pair = convex_pair(&mut rng, n, m, rel);
            let (pp, qq) = (
                ConvexPolygon::try_new(&pair.p).expect("valid"),
                ConvexPolygon::try_new(&pair.q).expect("valid"),
            );
            reset_search_stats();
            let got = distance_with::<Robust>(&pp, &qq);
            answered += search_stats().linear_walks;
            assert_eq!(
                got,
                distance_yang_with::<Robust>(&pp, &qq),
                "{rel:?}, n = {n}, m = {m}"
            );
            assert_eq!(got, distance_with::<Exact>(&pp, &qq), "{rel:?}, Exact");
            if n * m <= 20_000 {
                let exact = convex_distance(&pair.p, &pair.q);
                let contact = contact_status_convex(&pair.p, &pair.q);
                merge(
                    &mut worst,
                    check_answer(&pair.p, &pair.q, &exact, contact, &got, "small"),
                );
            }
            disjoint += u64::from(got.closest().is_some());
        }
    }
    println!(
        "small path answered {answered} of {disjoint} disjoint pairs; worst {:.3} / {:.3} / {:.3} ulps",
        worst.distance, worst.squared, worst.foot
    );
    assert!(answered * 10 >= disjoint * 7, "{answered} of {disjoint}");
}

/// The benchmark's workloads (W1: along a random direction, W2: along `+x`) at `n = m = 8 … 255`: the
/// support guess answers at least 95 % of the pairs, always the search's answer.
#[test]
fn support_guess_answers_the_benchmark_workloads() {
    for plus_x in [false, true] {
        for n in [8, 16, 32, 64, 128, 255] {
            let mut rng = SplitMix64::new(n as u64 ^ 0xBE7C);
            reset_search_stats();
            let pairs = 60;
            for _ in 0..pairs {
                let dir = if plus_x {
                    DVec2::X
                } else {
                    let t = rng.unit_f64() * core::f64::consts::TAU;
                    DVec2::new(t.cos(), t.sin())
                };
                let gap = 0.05 + 0.5 * rng.unit_f64();
                let p = ConvexPolygon::try_new(&random_convex(&mut rng, n, DVec2::ZERO, 1.0))
                    .expect("P");
                let q = ConvexPolygon::try_new(&random_convex(&mut rng, n, dir * (3.0 + gap), 1.0))
                    .expect("Q");
                let got = distance_with::<Robust>(&p, &q);
                assert!(got.closest().is_some());
                assert_eq!(got, distance_yang_with::<Robust>(&p, &q), "n = {n}");
            }
            let answered = search_stats().linear_walks;
            println!("plus_x = {plus_x}, n = {n}: {answered} of {pairs}");
            assert!(
                answered * 100 >= pairs * 95,
                "plus_x = {plus_x}, n = {n}: {answered}"
            );
        }
    }
}

/// Under the Fast kernel (inexact signs) the small path terminates and answers on hard inputs.
#[test]
fn support_guess_terminates_under_fast() {
    let mut rng = SplitMix64::new(99);
    for rel in [
        Relation::NearlyTouching { ulps: 1 },
        Relation::ParallelFacing,
        Relation::HugeOffset,
        Relation::Sliver,
        Relation::CollinearInput,
        Relation::TouchingEdge,
    ] {
        for round in 0..40 {
            let (n, m) = (3 + round * 6, 40 + round * 5);
            let pair = convex_pair(&mut rng, n, m, rel);
            let (pp, qq) = (
                ConvexPolygon::try_new(&pair.p).expect("valid"),
                ConvexPolygon::try_new(&pair.q).expect("valid"),
            );
            let _ = distance_with::<Fast>(&pp, &qq);
        }
    }
}
