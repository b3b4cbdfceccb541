//! Agreement with the independent exact oracle (rational arithmetic), under Robust and Exact, on
//! random, far-from-origin, nearly touching (a few ulps) and comb inputs; proptest on random cases.

mod common;

use common::{Case, combs, random_case};
use glam::DVec2;
use polydist_oracle::{
    SplitMix64, chain_distance, closest_visible_vertices_exact, step_ulps, ulps_error_sqrt,
};
use polydist_polygon::Feature;
use polydist_predicates::{Exact, Fast, Kernel, Robust};
use polydist_separation::{closest_visible_vertices, separation_brute};
use proptest::prelude::*;

fn vertex(f: Feature) -> usize {
    match f {
        Feature::Vertex(i) => i,
        Feature::Edge(_) => panic!("CVV reports vertices"),
    }
}

fn oracle_feature(f: Feature) -> polydist_oracle::Feature {
    match f {
        Feature::Vertex(i) => polydist_oracle::Feature::Vertex(i),
        Feature::Edge(i) => polydist_oracle::Feature::Edge(i),
    }
}

/// CVV against the oracle: an optimal pair (exactly), distance within 1 ulp of the exact value.
fn agree_cvv<K: Kernel>(c: &Case) {
    let got = closest_visible_vertices::<K>(&c.p, &c.q, c.a, c.b)
        .unwrap_or_else(|e| panic!("{}: {e}", c.name));
    let (sq, pairs) =
        closest_visible_vertices_exact(&c.p, &c.q).expect("separated chains see each other");
    let pair = (vertex(got.pair.feature_p), vertex(got.pair.feature_q));
    assert!(
        pairs.contains(&pair),
        "{} ({}): got {pair:?}, optimal {pairs:?}\np={:?}\nq={:?}",
        c.name,
        K::NAME,
        c.p,
        c.q
    );
    assert!(ulps_error_sqrt(got.pair.distance, &sq) <= 1.0, "{}", c.name);
}

/// The brute-force separation twin against the oracle's chain distance.
fn agree_sigma<K: Kernel>(c: &Case) {
    let got = separation_brute::<K>(&c.p, &c.q).unwrap();
    let exact = chain_distance(&c.p, &c.q);
    assert!(
        exact.is_optimal_pair(oracle_feature(got.feature_p), oracle_feature(got.feature_q)),
        "{}: {got:?} not in {:?}",
        c.name,
        exact.pairs
    );
    assert!(
        ulps_error_sqrt(got.distance, &exact.sq) <= 2.5,
        "{}",
        c.name
    );
}

#[test]
fn random_cases_agree_with_oracle() {
    let mut rng = SplitMix64::new(0xc0ffee);
    for n in [1usize, 2, 5, 10, 24] {
        for _ in 0..80 {
            let far = rng.below(3) == 0;
            let c = random_case(&mut rng, n, far);
            agree_cvv::<Robust>(&c);
            agree_sigma::<Robust>(&c);
        }
    }
    for _ in 0..40 {
        let c = random_case(&mut rng, 8, true);
        agree_cvv::<Exact>(&c);
        agree_sigma::<Exact>(&c);
    }
}

#[test]
fn combs_agree_with_oracle() {
    for rot in [(1, 0), (3, 4)] {
        for interleave in [false, true] {
            let c = combs(10, 1, 2, interleave, rot);
            agree_cvv::<Robust>(&c);
            agree_sigma::<Robust>(&c);
        }
    }
}

/// Nearly touching: P's tips a few ulps from the line x = 1 − ε, Q's on x ≤ 1 ... the line is the
/// vertical through 1.0, P's tips at 1 + k ulps, Q's vertices at 1 − k ulps, at nearby heights.
fn near_case(k: i64, n: usize, shift: f64) -> Case {
    let line = 1.0f64;
    let mut p = Vec::new();
    let mut q = Vec::new();
    for i in 0..n {
        let y = i as f64 * 0.25;
        p.push(DVec2::new(
            if i % 2 == 0 {
                step_ulps(line, k + i as i64 % 3)
            } else {
                line + 0.5
            },
            y,
        ));
        q.push(DVec2::new(
            if i % 2 == 1 {
                step_ulps(line, -k)
            } else {
                line - 0.5
            },
            y + shift,
        ));
    }
    Case {
        p,
        q,
        a: DVec2::new(line, 0.0),
        b: DVec2::new(line, 1.0),
        name: format!("near k={k} n={n} shift={shift}"),
    }
}

#[test]
fn nearly_touching() {
    for k in [1, 2, 4] {
        for n in [3, 8, 17] {
            for shift in [0.0, 0.125, 1e-9] {
                let c = near_case(k, n, shift);
                agree_cvv::<Robust>(&c);
                agree_cvv::<Exact>(&c);
                agree_sigma::<Robust>(&c);
                // Fast may be wrong here but must terminate and not panic.
                let _ = closest_visible_vertices::<Fast>(&c.p, &c.q, c.a, c.b);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn proptest_cvv_agrees_with_oracle(seed in any::<u64>(), n in 1usize..20, far in any::<bool>()) {
        let mut rng = SplitMix64::new(seed);
        let c = random_case(&mut rng, n, far);
        agree_cvv::<Robust>(&c);
    }

    /// Under Fast the search terminates on every input, valid or not, and never panics.
    #[test]
    fn proptest_fast_terminates(seed in any::<u64>(), n in 1usize..30) {
        let mut rng = SplitMix64::new(seed);
        let mut c = random_case(&mut rng, n, true);
        for v in c.p.iter_mut().chain(c.q.iter_mut()) {
            *v += DVec2::new(rng.unit_f64() * 1e-3, rng.unit_f64() * 1e-3);
        }
        let _ = closest_visible_vertices::<Fast>(&c.p, &c.q, c.a, c.b);
    }
}
