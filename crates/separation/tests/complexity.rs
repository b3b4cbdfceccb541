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
