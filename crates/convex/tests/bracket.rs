//! The proved bracket (docs/algorithms/convex-distance.md, "The proved bracket"): under the Robust and
//! Exact kernels the first search is certified on every disjoint pair, so neither the reseeds nor the
//! contact test nor Schwartz's search ever run for it; every answer agrees with the exact oracle and
//! with the brute force. The search runs at every size (`distance_yang_with`: no small-size switch).

mod common;

use common::{RELATIONS, check_all, clipped_pair, facing_pair, huge_offset_pair, sliver_pair};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Robust};
use polydist_convex::{SearchStats, distance_yang_with, reset_search_stats, search_stats};
use polydist_oracle::{
    Contact, SplitMix64, cocircular, contact_status_convex, convex_pair, random_convex_lattice,
};
use proptest::prelude::*;

/// The statistics of `f`, run from zero.
fn stats_of(f: impl FnOnce()) -> SearchStats {
    reset_search_stats();
    f();
    search_stats()
}

/// On a disjoint pair: the first search under the kernel was certified (no certificate failure, no
/// fallback). On any pair: no brute-force fallback.
fn assert_proved(s: SearchStats, disjoint: bool, what: &str) {
    if disjoint {
        assert_eq!(s.certificate_failures, 0, "{what}: {s:?}");
        assert_eq!(s.schwartz_fallbacks, 0, "{what}: {s:?}");
        assert_eq!(s.repaired_by_retry, 0, "{what}: {s:?}");
    }
    assert_eq!(s.brute_fallbacks, 0, "{what}: {s:?}");
}

/// `check_all` under Robust (and Exact when `exact`), with the bracket's guarantee asserted.
fn check_proved(p: &[DVec2], q: &[DVec2], exact: bool, what: &str) {
    let disjoint = contact_status_convex(p, q) == Contact::Disjoint;
    let brute = p.len() * q.len() <= 2500;
    let s = stats_of(|| {
        check_all::<Robust>(p, q, brute);
    });
    assert_proved(s, disjoint, what);
    if exact {
        let s = stats_of(|| {
            check_all::<Exact>(p, q, brute);
        });
        assert_proved(s, disjoint, what);
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 200,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/bracket.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn every_relation_first_search_certified(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..200, m in 3usize..200) {
        let mut rng = SplitMix64::new(seed);
        let (n, m) = if seed % 4 == 0 { (n, m) } else { (3 + n % 20, 3 + m % 20) };
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        check_proved(&pair.p, &pair.q, n * m <= 400, &format!("{:?} {n}×{m}", RELATIONS[rel]));
    }

    #[test]
    fn clipped_subsets_first_search_certified(seed in any::<u64>(), n in 8usize..160) {
        let mut rng = SplitMix64::new(seed);
        if let Some((c, d)) = clipped_pair(&mut rng, n, seed as usize) {
            check_proved(&c, &d, c.len() * d.len() <= 400, "clipped");
        }
    }

    #[test]
    fn lattice_ties_first_search_certified(seed in any::<u64>(), n in 3usize..10, m in 3usize..10, dx in -30i64..30, dy in -30i64..30) {
        // Coordinates ≤ 12: parallel edges, edges ⟂ the optimal vector and ν₀ along an edge are common.
        let mut rng = SplitMix64::new(seed);
        let p = random_convex_lattice(&mut rng, n, 12);
        let q: Vec<DVec2> = random_convex_lattice(&mut rng, m, 12)
            .iter()
            .map(|&v| v + DVec2::new(dx as f64, dy as f64))
            .collect();
        check_proved(&p, &q, true, "lattice");
    }
}

/// Exact ties and hard numbers: parallel facing edges along integer directions, co-circular
/// polygons, slivers, polygons near `1e12`.
#[test]
fn ties_and_hard_numbers_first_search_certified() {
    let mut rng = SplitMix64::new(77);
    for k in 0..120 {
        if let Some(f) = facing_pair(&mut rng, k) {
            check_proved(&f.p, &f.q, f.p.len() * f.q.len() <= 400, "facing");
        }
    }
    for k in [4, 5, 8, 13] {
        let c = cocircular(k);
        for shift in [(3.0, 0.0), (2.5, 2.5), (0.0, -4.0), (7.0, 1.0)] {
            let moved: Vec<DVec2> = c.iter().map(|&v| v + DVec2::from(shift) * 1e4).collect();
            check_proved(&c, &moved, c.len() < 20, "cocircular");
        }
    }
    for n in [3, 8, 40, 150] {
        let (a, b) = sliver_pair(&mut rng, n);
        check_proved(&a, &b, false, "sliver");
        let (c, d) = huge_offset_pair(&mut rng, n);
        check_proved(&c, &d, false, "huge offset");
    }
}

/// The inexact kernel keeps every bound on the same families (the ranges are index intervals of less
/// than one turn, the loop is counted) and never panics.
#[test]
fn fast_kernel_terminates_on_the_families() {
    let mut rng = SplitMix64::new(5);
    let run = |c: &[DVec2], d: &[DVec2]| {
        let (pc, pd) = (
            ConvexPolygon::try_new(c).expect("valid"),
            ConvexPolygon::try_new(d).expect("valid"),
        );
        reset_search_stats();
        let _ = distance_yang_with::<Fast>(&pc, &pd);
        let s = search_stats();
        assert!(s.last_iterations <= s.last_bound, "{s:?}");
    };
    for round in 0..300 {
        if let Some((c, d)) = clipped_pair(&mut rng, 8 + round % 200, round) {
            run(&c, &d);
        }
        let (a, b) = sliver_pair(&mut rng, 3 + round % 60);
        run(&a, &b);
        let rel = RELATIONS[round % RELATIONS.len()];
        let pair = convex_pair(&mut rng, 3 + round % 50, 3 + round % 37, rel);
        run(&pair.p, &pair.q);
    }
}
