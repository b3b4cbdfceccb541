//! Complexity by counting predicate calls (never timing): the search costs at most
//! `C·(log₂n + log₂m) + K` predicates on disjoint polygons, and never falls back: with the proved
//! bracket the first search under the kernel is always certified, on random pairs and on the
//! adversarial families (clipped subsets, slivers, 1e12 offsets, parallel facing edges, 1-ulp gaps).

mod common;

use common::{clipped_pair, counted, disjoint_pair, huge_offset_pair, sliver_pair};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Counted, Robust};
use polydist_convex::{distance_yang_with, reset_search_stats, search_stats};
use polydist_oracle::SplitMix64;

/// Predicates per `log₂n + log₂m` (measured: see the test's output and the docs).
const C: f64 = 13.0;
/// Constant term.
const K: f64 = 60.0;

#[test]
fn predicate_count_is_logarithmic() {
    let mut rng = SplitMix64::new(99);
    reset_search_stats();
    let mut worst_ratio: f64 = 0.0;
    // n = 8 … 2^20 (about 1e6), fewer trials at the largest sizes.
    for k in 3..=20 {
        let n = 1usize << k;
        let mut max_count = 0;
        for trial in 0..(if k > 16 { 2 } else { 12 }) {
            let m = if trial % 2 == 0 { n } else { 8 + rng.index(n) };
            let (p, q) = disjoint_pair(&mut rng, n, m);
            let (pp, qq) = (
                ConvexPolygon::try_new(&p).expect("valid"),
                ConvexPolygon::try_new(&q).expect("valid"),
            );
            let (s, count) = counted(|| distance_yang_with::<Counted<Robust>>(&pp, &qq));
            let logs = (pp.len() as f64).log2() + (qq.len() as f64).log2();
            if s.closest().is_some() {
                assert!(
                    count as f64 <= C * logs + K,
                    "n = {n}, m = {m}: {count} predicates"
                );
                worst_ratio = worst_ratio.max((count as f64 - K) / logs);
            }
            max_count = max_count.max(count);
        }
        println!("n = 2^{k}: at most {max_count} predicates");
    }
    let s = search_stats();
    println!("worst (count − {K}) / (log₂n + log₂m) = {worst_ratio:.2}; {s:?}");
    assert_eq!(s.brute_fallbacks, 0, "{s:?}");
    assert_eq!(s.certificate_failures, 0, "{s:?}");
    assert_eq!(s.schwartz_fallbacks, 0, "{s:?}");
}

/// The adversarial families, `n = 8 … 2^20`: the count stays within `C·(log₂n + log₂m) + K` and the
/// first search is always certified (no reseed, no Schwartz, no brute force).
#[test]
fn adversarial_families_are_logarithmic() {
    use polydist_oracle::{Relation, convex_pair};
    let mut rng = SplitMix64::new(1985);
    let mut worst: Vec<(&str, f64)> = Vec::new();
    let mut check = |name: &'static str, p: &[DVec2], q: &[DVec2]| {
        let (pp, qq) = (
            ConvexPolygon::try_new(p).expect("valid"),
            ConvexPolygon::try_new(q).expect("valid"),
        );
        reset_search_stats();
        let (s, count) = counted(|| distance_yang_with::<Counted<Robust>>(&pp, &qq));
        let st = search_stats();
        let logs = (pp.len() as f64).log2() + (qq.len() as f64).log2();
        if s.closest().is_some() {
            assert!(
                count as f64 <= C * logs + K,
                "{name} {}×{}: {count} predicates",
                pp.len(),
                qq.len()
            );
            assert_eq!(st.certificate_failures, 0, "{name}: {st:?}");
            assert_eq!(st.schwartz_fallbacks, 0, "{name}: {st:?}");
            let ratio = (count as f64 - K) / logs;
            match worst.iter_mut().find(|(n, _)| *n == name) {
                Some(w) => w.1 = w.1.max(ratio),
                None => worst.push((name, ratio)),
            }
        }
        assert_eq!(st.brute_fallbacks, 0, "{name}: {st:?}");
    };
    let max_k: u32 = std::env::var("ADV_MAX_K")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(20);
    for k in 3..=max_k {
        let n = 1usize << k;
        let trials = if k > 14 { 2 } else { 6 };
        for round in 0..trials {
            // Clipping keeps about half of each polygon's vertices; retry until both sides are polygons.
            if let Some((c, d)) = (0..20).find_map(|r| clipped_pair(&mut rng, 2 * n, round + r)) {
                check("clipped subsets", &c, &d);
            }
            // The lattice sliver generator cannot build thin polygons beyond about 2^13 vertices.
            if k <= 13 {
                let (a, b) = sliver_pair(&mut rng, n);
                check("slivers", &a, &b);
            }
            let (c, d) = huge_offset_pair(&mut rng, n);
            check("1e12 offset", &c, &d);
            if k <= 8 {
                for (name, rel) in [
                    ("parallel facing", Relation::ParallelFacing),
                    ("1-ulp gap", Relation::NearlyTouching { ulps: 1 }),
                    ("collinear input", Relation::CollinearInput),
                ] {
                    let m = 3 + rng.index(n);
                    let pair = convex_pair(&mut rng, n, m, rel);
                    check(name, &pair.p, &pair.q);
                }
            }
        }
    }
    for (name, w) in &worst {
        println!("{name}: worst (count − {K}) / (log₂n + log₂m) = {w:.2}");
    }
    assert!(worst.len() >= 5, "{worst:?}");
}

/// Large pairs in every disjoint relation: the outcome matches the construction, and the count of
/// certificate failures (repaired by reseeding, or by the brute force) is reported.
#[test]
fn large_pairs_every_disjoint_relation() {
    use polydist_oracle::{Contact, Relation, convex_pair};
    let mut rng = SplitMix64::new(2024);
    reset_search_stats();
    let relations = [
        Relation::Far,
        Relation::NearlyTouching { ulps: 1 },
        Relation::ParallelFacing,
        Relation::HugeOffset,
        Relation::Sliver,
        Relation::CollinearInput,
    ];
    let mut disjoint = 0;
    for rel in relations {
        for &(n, m) in &[(50, 7), (300, 60), (400, 400), (17, 300)] {
            for _ in 0..4 {
                let pair = convex_pair(&mut rng, n, m, rel);
                let (pp, qq) = (
                    ConvexPolygon::try_new(&pair.p).expect("valid"),
                    ConvexPolygon::try_new(&pair.q).expect("valid"),
                );
                let s = distance_yang_with::<Robust>(&pp, &qq);
                assert_eq!(
                    s.closest().is_some(),
                    pair.contact == Contact::Disjoint,
                    "{rel:?} {n}×{m}"
                );
                disjoint += usize::from(pair.contact == Contact::Disjoint);
            }
        }
    }
    let s = search_stats();
    println!("{disjoint} disjoint large pairs; {s:?}");
    assert_eq!(s.brute_fallbacks, 0, "{s:?}");
}

/// Many disjoint pairs (3..300 vertices) per relation: the first search under the kernel never fails
/// its certificate (the proved bracket), so no reseed, Schwartz or brute force ever answers.
#[test]
fn fallback_counts_on_many_disjoint_pairs() {
    use polydist_oracle::{Contact, Relation, convex_pair};
    let relations = [
        Relation::Far,
        Relation::NearlyTouching { ulps: 1 },
        Relation::NearlyTouching { ulps: 3 },
        Relation::ParallelFacing,
        Relation::HugeOffset,
        Relation::Sliver,
        Relation::CollinearInput,
    ];
    let mut rng = SplitMix64::new(12345);
    for rel in relations {
        reset_search_stats();
        let mut disjoint = 0;
        for _ in 0..3000 {
            let cn = if rng.coin() { 12 } else { 300 };
            let n = 3 + rng.index(cn);
            let cm = if rng.coin() { 12 } else { 300 };
            let m = 3 + rng.index(cm);
            let pair = convex_pair(&mut rng, n, m, rel);
            if pair.contact != Contact::Disjoint {
                continue;
            }
            disjoint += 1;
            let pp = ConvexPolygon::try_new(&pair.p).expect("valid");
            let qq = ConvexPolygon::try_new(&pair.q).expect("valid");
            assert!(
                distance_yang_with::<Robust>(&pp, &qq).closest().is_some(),
                "{rel:?}"
            );
        }
        let s = search_stats();
        println!(
            "{rel:?}: {disjoint} disjoint; first search failed {}, repaired by reseed {}, brute force {}",
            s.certificate_failures, s.repaired_by_retry, s.brute_fallbacks
        );
        assert_eq!(s.brute_fallbacks, 0, "{rel:?}: {s:?}");
        // The proved bracket: the first search under the kernel is always certified.
        assert_eq!(s.certificate_failures, 0, "{rel:?}: {s:?}");
        assert_eq!(s.schwartz_fallbacks, 0, "{rel:?}: {s:?}");
    }
}
