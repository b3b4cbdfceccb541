//! The `O(log)` intersection test `contact_with`: agreement with the exact oracle and with the
//! separating-axis twin (the scan path of `distance_brute`), a touching point that lies on both
//! reported features, a predicate count logarithmic in the sizes, and termination under random signs.

mod common;

use common::{Chaos, lattice_point, on_feature, seed_chaos};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{
    Counted, Exact, Fast, Kernel, Robust, predicate_counts, reset_predicate_counts,
};
use polydist_convex::{
    Contact, Separation, contact_with, distance_brute, distance_yang_with, intersects,
};
use polydist_oracle::{
    Contact as Oracle, Relation, SplitMix64, contact_status_convex, convex_pair, random_convex,
    random_convex_lattice,
};
use proptest::prelude::*;

/// The category of an answer, in the oracle's terms.
fn category(c: &Contact) -> Oracle {
    match c {
        Contact::Disjoint => Oracle::Disjoint,
        Contact::Touching { .. } => Oracle::Touching,
        Contact::Overlapping => Oracle::Overlapping,
    }
}

/// `contact_with::<K>` on the caller rings `p`, `q` agrees with the oracle and with the scan twin, and a
/// touching point lies on both reported features (both ways round).
fn check<K: Kernel>(p: &[DVec2], q: &[DVec2]) {
    let (pp, qq) = (
        ConvexPolygon::try_new(p).expect("valid P"),
        ConvexPolygon::try_new(q).expect("valid Q"),
    );
    let oracle = contact_status_convex(p, q);
    for (a, b, aa, bb) in [(p, q, &pp, &qq), (q, p, &qq, &pp)] {
        let got = contact_with::<K>(aa, bb);
        assert_eq!(
            category(&got),
            oracle,
            "{}: got {got:?}\np = {a:?}\nq = {b:?}",
            K::NAME
        );
        assert_eq!(intersects::<K>(aa, bb), oracle != Oracle::Disjoint);
        let twin = match distance_brute::<K>(aa, bb) {
            Separation::Disjoint(_) => Oracle::Disjoint,
            Separation::Touching { .. } => Oracle::Touching,
            Separation::Overlapping => Oracle::Overlapping,
        };
        assert_eq!(twin, oracle, "scan twin");
        if let Contact::Touching {
            point,
            feature_p,
            feature_q,
        } = got
        {
            assert!(
                on_feature(a, feature_p, point),
                "{point} not on {feature_p:?}\np = {a:?}\nq = {b:?}"
            );
            assert!(
                on_feature(b, feature_q, point),
                "{point} not on {feature_q:?}\np = {a:?}\nq = {b:?}"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 200,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/contact.txt",
        ))),
        ..ProptestConfig::default()
    })]

    /// Random pairs in every relative position the generators build (far, nearly touching by a few
    /// ulps, touching at a vertex, along an edge, vertex on edge, overlapping, nested, parallel
    /// facing edges, huge offsets, slivers, ...), of 3..200 vertices.
    #[test]
    fn random_pairs_every_relation(seed in any::<u64>(), rel in 0..Relation::EVERY.len(), n in 3usize..200, m in 3usize..200) {
        let mut rng = SplitMix64::new(seed);
        let (n, m) = if seed % 4 == 0 { (n, m) } else { (3 + n % 20, 3 + m % 20) };
        let pair = convex_pair(&mut rng, n, m, Relation::EVERY[rel]);
        check::<Robust>(&pair.p, &pair.q);
    }

    /// Small lattice polygons against each other, points and segments: many exact coincidences
    /// (shared vertices, collinear edges, vertices on edges, identical polygons).
    #[test]
    fn lattice_degenerate(seed in any::<u64>()) {
        let mut rng = SplitMix64::new(seed);
        let (na, nb) = (3 + rng.index(6), 3 + rng.index(6));
        let a = random_convex_lattice(&mut rng, na, 4);
        let b = random_convex_lattice(&mut rng, nb, 4);
        let (u, v) = (lattice_point(&mut rng) * 0.08, lattice_point(&mut rng) * 0.08);
        let (u, v) = (u.round(), v.round());
        check::<Robust>(&a, &b);
        check::<Exact>(&a, &b);
        check::<Robust>(&a, &a);
        check::<Robust>(&[u], &a);
        if u != v {
            check::<Robust>(&[u, v], &a);
            check::<Robust>(&[u, v], &[a[0], a[1 % a.len()]]);
        }
    }
}

/// Every relation at small sizes under both exact kernels, and the shared-vertex cases of the
/// bottom and top faces (the origin on the horizontal line through `Z`'s lowest or highest vertex).
#[test]
fn every_relation_and_horizontal_faces() {
    let mut rng = SplitMix64::new(5);
    for rel in Relation::EVERY {
        for n in 3..10 {
            for m in [3, 4, 7, 12] {
                let pair = convex_pair(&mut rng, n, m, rel);
                check::<Robust>(&pair.p, &pair.q);
                check::<Exact>(&pair.p, &pair.q);
            }
        }
    }
    let unit = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ];
    let tri = |dx: f64, dy: f64| {
        vec![
            DVec2::new(dx, dy),
            DVec2::new(dx + 1.0, dy),
            DVec2::new(dx + 0.5, dy + 0.5),
        ]
    };
    for dx in [-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5] {
        for dy in [-1.0, -0.5, 1.0, 2.0] {
            let t = tri(dx, dy);
            let flipped: Vec<DVec2> = t.iter().map(|&p| DVec2::new(p.x, 2.0 * dy - p.y)).collect();
            check::<Robust>(&unit, &t);
            check::<Robust>(&unit, &[flipped[0], flipped[2], flipped[1]]);
        }
    }
}

/// The predicate count grows with `log n + log m` on touching and overlapping pairs up to 2^17
/// vertices (the separating-axis twin would need `Θ(n log m)`), for the test and for the distance query.
#[test]
fn predicate_count_is_logarithmic() {
    let mut rng = SplitMix64::new(17);
    let (mut worst, mut worst_query): (f64, f64) = (0.0, 0.0);
    for k in 3..=17 {
        let n = 1usize << k;
        let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
        let pp = ConvexPolygon::try_new(&p).expect("valid");
        let shifted: Vec<DVec2> = p.iter().map(|&v| v + DVec2::new(0.7, 0.2)).collect();
        let qq = ConvexPolygon::try_new(&shifted).expect("valid");
        let small = ConvexPolygon::try_new(&random_convex(&mut rng, 5, DVec2::new(0.3, 0.1), 0.2))
            .expect("valid");
        let vertex = ConvexPolygon::try_new(&[p[n / 3]]).expect("valid");
        for (b, expect) in [
            (&qq, Oracle::Overlapping),
            (&small, Oracle::Overlapping),
            (&vertex, Oracle::Touching),
        ] {
            reset_predicate_counts();
            let got = contact_with::<Counted<Robust>>(&pp, b);
            let count = predicate_counts().total() as f64;
            assert_eq!(category(&got), expect, "n = {n}");
            let logs = (pp.len() as f64).log2() + (b.len() as f64).log2().max(1.0);
            worst = worst.max(count / logs);
            // The distance query on meeting input: search, reseeds, then this test; all O(log).
            reset_predicate_counts();
            let s = distance_yang_with::<Counted<Robust>>(&pp, b);
            let query = predicate_counts().total() as f64;
            assert!(s.closest().is_none(), "{s:?}");
            worst_query = worst_query.max(query / logs);
            assert!(
                query <= 64.0 * logs + 200.0,
                "distance on n = {n}, m = {}: {query} predicates",
                b.len()
            );
            assert!(
                count <= 16.0 * logs + 40.0,
                "n = {n}, m = {}: {count} predicates",
                b.len()
            );
        }
    }
    println!(
        "worst predicates / (log₂n + log₂m): contact {worst:.2}, distance on meeting input {worst_query:.2}"
    );
}

/// Random signs: the test stops within its bound and never panics; Fast on near-degenerate input too.
#[test]
fn terminates_under_any_signs() {
    let mut rng = SplitMix64::new(8);
    for round in 0..3000 {
        seed_chaos(round as u64);
        let (_, _, pair) = common::chaos_pair(&mut rng, round);
        let (pp, qq) = (
            ConvexPolygon::try_new(&pair.p).expect("valid"),
            ConvexPolygon::try_new(&pair.q).expect("valid"),
        );
        let _ = contact_with::<Chaos>(&pp, &qq);
        let _ = contact_with::<Fast>(&pp, &qq);
    }
}
