//! A hard family for the old seed-direction ranges: vertex subsets of two overlapping convex polygons,
//! cut by a line through a vertex of each (the subsets are strictly separated, with long "lid" edges).
//! With the old ranges 9.3 % of first searches missed the certificate and six pairs needed Schwartz's
//! `O(log² N)` search. With the proved bracket (docs, "The proved bracket") the first search under the
//! kernel is always certified: no certificate failure, no fallback, and the count stays within the
//! `O(log n + log m)` bound of `tests/complexity.rs`. Every answer equals the brute force.

mod common;

use common::{clipped_pair, counted};
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Counted, Exact, Robust};
use polydist_convex::{distance_brute, distance_yang_with, reset_search_stats, search_stats};
use polydist_oracle::SplitMix64;

#[test]
fn the_proved_bracket_never_misses() {
    let mut rng = SplitMix64::new(32);
    reset_search_stats();
    let (mut tried, mut worst): (u64, f64) = (0, 0.0);
    let mut exact_checked = 0;
    for round in 0..1200 {
        let n = 8 + rng.index(120);
        let Some((c, d)) = clipped_pair(&mut rng, n, round) else {
            continue;
        };
        let (pc, pd) = (
            ConvexPolygon::try_new(&c).expect("valid"),
            ConvexPolygon::try_new(&d).expect("valid"),
        );
        tried += 1;
        let (s, count) = counted(|| distance_yang_with::<Counted<Robust>>(&pc, &pd));
        let want = distance_brute::<Robust>(&pc, &pd);
        assert_eq!(s, distance_yang_with::<Robust>(&pc, &pd));
        assert_eq!(s.distance(), want.distance(), "round {round}");
        let c = s.closest().expect("strictly separated");
        let w = want.closest().expect("strictly separated");
        assert_eq!(c.squared_distance, w.squared_distance, "round {round}");
        let logs = (pc.len() as f64).log2() + (pd.len() as f64).log2();
        worst = worst.max((count as f64 - 60.0) / logs);
        if round % 4 == 0 {
            assert_eq!(s, distance_yang_with::<Exact>(&pc, &pd), "round {round}");
            exact_checked += 1;
        }
    }
    let s = search_stats();
    println!(
        "{tried} clipped pairs ({exact_checked} also under Exact); worst (predicates − 60) / (log₂n + log₂m) = {worst:.1}; {s:?}"
    );
    assert!(tried >= 800, "{tried}");
    // The proved bracket: under Robust and Exact the first search is always certified.
    assert_eq!(s.certificate_failures, 0, "{s:?}");
    assert_eq!(s.schwartz_fallbacks, 0, "{s:?}");
    assert_eq!(s.brute_fallbacks, 0, "{s:?}");
    // Within the O(log n + log m) bound of tests/complexity.rs.
    assert!(worst <= 13.0, "{worst}");
}
