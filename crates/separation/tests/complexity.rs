//! Linear work, by counting predicate calls (Counted<Robust>) and matrix lookups, never by timing.

mod common;

use common::{combs, random_case};
use polydist_oracle::SplitMix64;
use polydist_predicates::{Counted, Robust, predicate_counts, reset_predicate_counts};
use polydist_separation::closest_visible_vertices;

/// Predicate calls per input vertex, measured once (see docs/algorithms/separation.md) and fixed.
const PER_VERTEX: u64 = 40; // measured: at most 31.3 (random and interleaved combs, n ≤ 65,536)

#[test]
fn predicate_calls_are_linear() {
    let mut rng = SplitMix64::new(4);
    for n in [16usize, 256, 4096, 32768] {
        for c in [
            random_case(&mut rng, n, false),
            combs(n / 2, 1, 1, true, (3, 4)),
        ] {
            let total = (c.p.len() + c.q.len()) as u64;
            reset_predicate_counts();
            let r = closest_visible_vertices::<Counted<Robust>>(&c.p, &c.q, c.a, c.b).unwrap();
            let calls = predicate_counts().total();
            assert!(
                calls <= PER_VERTEX * total,
                "{}: {calls} predicate calls for {total} vertices",
                c.name
            );
            let s = r.stats;
            assert!(s.entries_evaluated <= 3 * s.q_after_lemma3 + 12 * s.p_after_lemma3 + 1);
        }
    }
}

/// σ (CVV + two CVE searches): predicate calls per vertex, measured at most 281 (random chains,
/// n = 256) and about 186 on interleaved combs, flat from n = 16 to 65,536.
const SIGMA_PER_VERTEX: u64 = 400;

#[test]
fn sigma_predicate_calls_are_linear() {
    use polydist_separation::separation_of_chains;
    let mut rng = SplitMix64::new(5);
    let mut ran = 0;
    for n in [16usize, 256, 4096, 32768] {
        for c in [
            random_case(&mut rng, n, false),
            combs(n / 2, 1, 1, true, (3, 4)),
        ] {
            let total = (c.p.len() + c.q.len()) as u64;
            reset_predicate_counts();
            let r = separation_of_chains::<Counted<Robust>>(&c.p, &c.q, c.a, c.b).unwrap();
            ran += 1;
            let calls = predicate_counts().total();
            assert!(
                calls <= SIGMA_PER_VERTEX * total,
                "{}: {calls} predicate calls for {total} vertices",
                c.name
            );
            let s = r.stats;
            assert!(
                s.pieces_p <= 4 * c.p.len() && s.pieces_q <= 4 * c.q.len(),
                "{s:?}"
            );
            assert!(
                s.cve_entries_evaluated
                    <= 3 * (s.cvv.q_after_lemma3 + s.cvv.p_after_lemma3)
                        + 12 * (s.pieces_p + s.pieces_q)
                        + 2
            );
        }
    }
    assert!(ran >= 6, "{ran}");
}

/// Chains made of runs perpendicular to the line (three vertices per height, walked alternately
/// toward and away from it): hidden run ends are walked by the edge scans; still linear.
#[test]
fn sigma_with_perpendicular_runs_is_linear() {
    use glam::DVec2;
    use polydist_separation::separation_of_chains;
    for n in [64usize, 1024, 16384] {
        let side = |sign: f64| {
            let mut v = Vec::new();
            for k in 0..n / 3 {
                let y = k as f64;
                let depths = if k % 2 == 0 {
                    [5.0, 3.0, 1.0 + (k % 5) as f64 * 0.25]
                } else {
                    [1.5, 4.0, 6.0]
                };
                v.extend(depths.iter().map(|&d| DVec2::new(sign * d, y)));
            }
            v
        };
        let (p, q) = (side(1.0), side(-1.0));
        let total = (p.len() + q.len()) as u64;
        reset_predicate_counts();
        separation_of_chains::<Counted<Robust>>(&p, &q, DVec2::ZERO, DVec2::Y).unwrap();
        let calls = predicate_counts().total();
        assert!(
            calls <= SIGMA_PER_VERTEX * total,
            "n = {n}: {calls} calls for {total} vertices"
        );
    }
}
