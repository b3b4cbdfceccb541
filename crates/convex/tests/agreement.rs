//! Agreement of `distance`, `distance_yang_with` and `distance_brute` with the exact oracle, on random
//! convex pairs in every relative position, points, segments, and exact ties.

mod common;

use common::{
    RELATIONS, Worst, check_all, facing_pair, huge_offset_pair, lattice_point, merge, sliver_pair,
};
use glam::DVec2;
use polydist_convex::polygon::predicates::{Exact, Robust};
use polydist_convex::{reset_search_stats, search_stats};
use polydist_oracle::{Relation, SplitMix64, cocircular, convex_pair};
use proptest::prelude::*;

fn report(name: &str, w: Worst) {
    let s = search_stats();
    println!(
        "{name}: max distance error {:.3} ulps, squared {:.3} ulps, foot {:.3} ulps; stats {s:?}",
        w.distance, w.squared, w.foot
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 160,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/agreement.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_pairs_every_relation(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..200, m in 3usize..200) {
        let mut rng = SplitMix64::new(seed);
        // Keep most cases small so the O(nm) oracle stays fast.
        let (n, m) = if seed % 4 == 0 { (n, m) } else { (3 + n % 20, 3 + m % 20) };
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        check_all::<Robust>(&pair.p, &pair.q, n * m <= 2500);
    }
}

#[test]
fn every_relation_small_sizes_robust_and_exact() {
    reset_search_stats();
    let mut worst = Worst::default();
    let mut rng = SplitMix64::new(7);
    for rel in RELATIONS {
        for n in 3..12 {
            for m in [3, 4, 5, 8, 13] {
                let pair = convex_pair(&mut rng, n, m, rel);
                merge(&mut worst, check_all::<Robust>(&pair.p, &pair.q, true));
                merge(&mut worst, check_all::<Exact>(&pair.p, &pair.q, true));
            }
        }
    }
    report("relations", worst);
    let s = search_stats();
    assert_eq!(
        s.brute_fallbacks, 0,
        "the search failed on a disjoint input: {s:?}"
    );
}

/// Points and segments (and their touching/overlapping cases) against polygons, and each other.
#[test]
fn points_and_segments() {
    reset_search_stats();
    let mut worst = Worst::default();
    let mut rng = SplitMix64::new(11);
    for round in 0..400 {
        let n = 3 + round % 30;
        let poly: Vec<DVec2> = polydist_oracle::random_convex_lattice(&mut rng, n.min(10), 40);
        let a = lattice_point(&mut rng);
        let b = lattice_point(&mut rng);
        let v = poly[rng.index(poly.len())];
        let w = poly[(rng.index(poly.len()) + 1) % poly.len()];
        let mid = (v + w) * 0.5;
        let mut shapes: Vec<Vec<DVec2>> = vec![
            vec![a],
            vec![v],
            vec![mid],
            vec![a, b],
            vec![v, a],
            vec![mid, a],
        ];
        if a != b {
            shapes.push(vec![a, b]);
        }
        if v != w {
            shapes.push(vec![v, w]);
            shapes.push(vec![v * 2.0 - w, v]);
        }
        for s in &shapes {
            if s.len() == 2 && s[0] == s[1] {
                continue;
            }
            merge(&mut worst, check_all::<Robust>(s, &poly, true));
            merge(&mut worst, check_all::<Exact>(s, &poly, true));
            for t in &shapes {
                if t.len() == 2 && t[0] == t[1] {
                    continue;
                }
                merge(&mut worst, check_all::<Robust>(s, t, true));
            }
        }
    }
    report("points and segments", worst);
    assert_eq!(search_stats().brute_fallbacks, 0);
}

/// Exact ties: parallel facing edges with integer directions, co-circular vertices, slivers, huge offsets.
#[test]
fn exact_ties_and_hard_numbers() {
    reset_search_stats();
    let mut worst = Worst::default();
    let mut rng = SplitMix64::new(3);
    for k in 0..60 {
        let Some(f) = facing_pair(&mut rng, k) else {
            continue;
        };
        merge(&mut worst, check_all::<Robust>(&f.p, &f.q, true));
    }
    // Co-circular vertices: two copies of a circle polygon, one shifted by an exact integer amount.
    for k in 1..5 {
        let c = cocircular(k);
        let r = c.iter().map(|p| p.x).fold(0.0, f64::max);
        for shift in [
            DVec2::new(2.0 * r + 1.0, 0.0),
            DVec2::new(2.0 * r, 2.0 * r),
            DVec2::new(2.0 * r, 0.0),
        ] {
            let moved: Vec<DVec2> = c.iter().map(|&p| p + shift).collect();
            merge(&mut worst, check_all::<Robust>(&c, &moved, c.len() < 40));
        }
    }
    // Slivers and huge offsets from the generators at larger sizes.
    for n in [16, 50, 120] {
        let (a, b) = sliver_pair(&mut rng, n);
        merge(&mut worst, check_all::<Robust>(&a, &b, false));
        let (c, d) = huge_offset_pair(&mut rng, n);
        merge(&mut worst, check_all::<Robust>(&c, &d, false));
        for rel in [
            Relation::HugeOffset,
            Relation::NearlyTouching { ulps: 2 },
            Relation::Sliver,
        ] {
            let pair = convex_pair(&mut rng, n, n / 2 + 3, rel);
            merge(&mut worst, check_all::<Robust>(&pair.p, &pair.q, false));
        }
    }
    report("ties and hard numbers", worst);
    assert_eq!(search_stats().brute_fallbacks, 0);
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 120,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/agreement.txt",
        ))),
        ..ProptestConfig::default()
    })]

    /// Under Exact, `distance_exact` returns the oracle's exact rational squared distance (zero when
    /// the polygons meet), in every relation, points and segments included.
    #[test]
    fn exact_rational_squared_distance(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 1usize..40, m in 1usize..40) {
        use polydist_convex::distance_exact;
        use polydist_convex::polygon::ConvexPolygon;
        let mut rng = SplitMix64::new(seed);
        let pair = convex_pair(&mut rng, 3 + n % 20, 3 + m % 20, RELATIONS[rel]);
        // Points and segments: prefixes of the generated rings.
        let p: Vec<DVec2> = pair.p.iter().copied().take(if n < 3 { n } else { pair.p.len() }).collect();
        let q: Vec<DVec2> = pair.q.iter().copied().take(if m < 3 { m } else { pair.q.len() }).collect();
        let (pp, qq) = (ConvexPolygon::try_new(&p).expect("valid"), ConvexPolygon::try_new(&q).expect("valid"));
        let (answer, sq) = distance_exact(&pp, &qq);
        let exact = polydist_oracle::convex_distance(&p, &q);
        match answer.closest() {
            Some(_) => prop_assert_eq!(&sq, &exact.sq),
            None => prop_assert_eq!(sq, polydist_oracle::rat(0.0).expect("zero")),
        }
    }
}

/// The small-input path of `distance_with` (a linear walk whose candidate the exact certificate
/// accepts) gives exactly the search's answer, in every relation; and it answers most separated pairs.
#[test]
fn linear_walk_equals_the_search() {
    use polydist_convex::polygon::ConvexPolygon;
    use polydist_convex::{distance_with, distance_yang_with};
    let mut rng = SplitMix64::new(41);
    let (mut disjoint, mut walked) = (0u64, 0u64);
    for rel in RELATIONS {
        for round in 0..120 {
            let (n, m) = (3 + round % 21, 3 + (round * 7) % 23);
            let pair = convex_pair(&mut rng, n, m, rel);
            let (pp, qq) = (
                ConvexPolygon::try_new(&pair.p).expect("valid"),
                ConvexPolygon::try_new(&pair.q).expect("valid"),
            );
            reset_search_stats();
            let got = distance_with::<Robust>(&pp, &qq);
            walked += search_stats().linear_walks;
            assert_eq!(
                got,
                distance_yang_with::<Robust>(&pp, &qq),
                "{rel:?}, n = {n}, m = {m}"
            );
            assert_eq!(got, distance_with::<Exact>(&pp, &qq), "{rel:?}, Exact");
            disjoint += u64::from(got.closest().is_some());
        }
    }
    println!("linear walk answered {walked} of {disjoint} disjoint small pairs");
    assert!(walked * 10 >= disjoint * 6, "{walked} of {disjoint}");
}
