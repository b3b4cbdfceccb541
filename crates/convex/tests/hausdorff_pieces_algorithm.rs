//! ARL's piece decomposition as an algorithm (`*_pieces_with`): equal to the walk and to the brute
//! force (whole records: features, numbers, indices) under Robust and Exact, in agreement with the
//! exact oracle, on intersecting pairs (every oracle relation, random overlapping pairs, regular n-gons
//! rotated half a step, lattice pairs with shared edges and vertex touches, identical and nested
//! pairs); linear by counting predicate calls; Fast and a random-sign kernel terminate.

mod common;

use common::Chaos;

use glam::DVec2;
use polydist_convex::polygon::predicates::{
    BigRational, Counted, Exact, Fast, Kernel, Robust, predicate_counts, reset_predicate_counts,
};
use polydist_convex::polygon::{ConvexPolygon, Location};
use polydist_convex::{
    boundary_crossings_with, cmmr_brute, cmmr_pieces_with, cmmr_with, hausdorff_brute,
    hausdorff_pieces_with, hausdorff_with, per_vertex_distances_brute,
    per_vertex_distances_pieces_with, per_vertex_distances_with, pieces_stats, reset_pieces_stats,
};
use polydist_oracle::{
    Relation, SplitMix64, cmmr as oracle_cmmr, convex_pair, directed_hausdorff_filled,
    per_vertex_sq_dist, random_convex, random_convex_lattice, ulps_error, ulps_error_sqrt,
};
use proptest::prelude::*;

fn polygon(v: &[DVec2]) -> ConvexPolygon {
    ConvexPolygon::try_new(v).unwrap_or_else(|e| panic!("{e}"))
}

fn zero() -> BigRational {
    BigRational::from_integer(0.into())
}

/// Everything checked on one pair under an exact-decision kernel; returns whether the boundaries
/// cross (the piece decomposition ran) in either order.
fn check<K: Kernel>(pv: &[DVec2], qv: &[DVec2]) -> bool {
    let (Ok(p), Ok(q)) = (ConvexPolygon::try_new(pv), ConvexPolygon::try_new(qv)) else {
        return false;
    };
    reset_pieces_stats();
    for (a, b) in [(&p, &q), (&q, &p)] {
        let pieces = per_vertex_distances_pieces_with::<K>(a, b);
        assert_eq!(
            pieces,
            per_vertex_distances_with::<K>(a, b),
            "pieces and walk disagree on {:?} / {:?}",
            a.vertices(),
            b.vertices()
        );
        assert_eq!(pieces, per_vertex_distances_brute::<K>(a, b));
        // The exact oracle, vertex by vertex.
        let exact = per_vertex_sq_dist(a.vertices(), b.vertices());
        for (r, e) in pieces.iter().zip(&exact) {
            if *e == zero() {
                assert_eq!(r.squared_distance, 0.0);
                assert_ne!(r.location, Location::Outside);
            } else {
                assert_eq!(r.location, Location::Outside);
                assert!(ulps_error(r.squared_distance, e) <= 0.51, "{r:?} {e}");
                assert!(ulps_error_sqrt(r.distance, e) <= 1.0, "{r:?} {e}");
            }
        }
        let (h, arg) = directed_hausdorff_filled(a.vertices(), b.vertices());
        let hp = hausdorff_pieces_with::<K>(a, b);
        assert!(arg.iter().any(|&i| a.vertices()[i] == hp.p_to_q.point));
        assert!(ulps_error_sqrt(hp.p_to_q.distance, &h) <= 3.5);
    }
    let h = hausdorff_pieces_with::<K>(&p, &q);
    assert_eq!(h, hausdorff_with::<K>(&p, &q));
    assert_eq!(h, hausdorff_brute::<K>(&p, &q));
    let c = cmmr_pieces_with::<K>(&p, &q);
    assert_eq!(c, cmmr_with::<K>(&p, &q));
    assert_eq!(c, cmmr_brute::<K>(&p, &q));
    let exact = oracle_cmmr(p.vertices(), q.vertices());
    assert!(ulps_error(c.value, &exact) <= 6.0, "{} {exact}", c.value);
    let s = pieces_stats();
    assert_eq!(s.fallbacks, 0, "{s:?}");
    assert_eq!(s.scans, 0, "{s:?}");
    // Two direction changes per external chain at most (the ray argument of Lemma 3 on an arc);
    // the notes' "at most one" is refuted by `two_reversals_on_one_external_chain`.
    assert!(s.max_reversals <= 2, "{s:?}");
    s.decompositions > 0
}

fn both(pv: &[DVec2], qv: &[DVec2]) -> bool {
    let a = check::<Robust>(pv, qv);
    let b = check::<Exact>(pv, qv);
    assert_eq!(a, b);
    a
}

fn overlapping(rng: &mut SplitMix64, n: usize, m: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let c = DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5);
    let r = 0.5 + rng.unit_f64();
    (
        random_convex(rng, n, DVec2::ZERO, 1.0),
        random_convex(rng, m, c, r),
    )
}

fn regular(n: usize, r: f64, phase: f64) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            let t = phase + core::f64::consts::TAU * i as f64 / n as f64;
            DVec2::new(r * t.cos(), r * t.sin())
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 40,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/hausdorff_pieces_algorithm.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_overlapping_pairs(seed in any::<u64>(), n in 3usize..200, m in 3usize..200) {
        let mut rng = SplitMix64::new(seed);
        let (p, q) = overlapping(&mut rng, n, m);
        check::<Robust>(&p, &q);
        if n + m <= 120 {
            check::<Exact>(&p, &q);
        }
    }

    #[test]
    fn lattice_pairs(seed in any::<u64>(), n in 3usize..12, m in 3usize..12, shift in -3i64..4) {
        let mut rng = SplitMix64::new(seed);
        let coord = 40;
        let p = random_convex_lattice(&mut rng, n, coord);
        let q: Vec<DVec2> = random_convex_lattice(&mut rng, m, coord)
            .into_iter()
            .map(|v| v + DVec2::new(shift as f64, -shift as f64))
            .collect();
        both(&p, &q);
    }
}

#[test]
fn every_oracle_relation() {
    // The relations as generated (mostly no crossing: disjoint, touching, nested; the walk's path),
    // then each with `q` blown up by 3 about its first vertex, which makes most boundaries cross.
    let mut rng = SplitMix64::new(5);
    let mut crossed = 0;
    for round in 0..6 {
        for rel in Relation::EVERY {
            let pair = convex_pair(&mut rng, 5 + 7 * round, 4 + 9 * round, rel);
            both(&pair.p, &pair.q);
            let q0 = pair.q[0];
            let big: Vec<DVec2> = pair.q.iter().map(|&v| q0 + 3.0 * (v - q0)).collect();
            if both(&pair.p, &big) {
                crossed += 1;
            }
        }
    }
    println!("blown-up relation pairs with crossing boundaries: {crossed} of 72");
    assert!(crossed >= 20);
}

/// The notes (§2.4) claim that the projection pointer changes direction at most once along one
/// external chain. This pair (an oracle `Overlapping` pair with `q` blown up by 3, one piece each way)
/// has an external chain of `P` whose nearest features on `Q` run `e11, e11, e11, q11, q12, q1, e1, q2,
/// e3, e3, e3, e2`: back, forward, back: two changes (walk, brute force and pieces agree exactly).
#[test]
fn two_reversals_on_one_external_chain() {
    let p = [
        (0.0, 0.0),
        (-0.020959507673978806, 0.029194016009569168),
        (-0.04201853275299072, 0.04191083088517189),
        (-0.10856280475854874, 0.07844882272183895),
        (-0.11609685234725475, -0.03812818601727486),
        (-0.09893185459077358, -0.14751200750470161),
        (-0.05013160966336727, -0.2340228520333767),
        (0.016618983820080757, -0.29852552711963654),
        (0.09722556546330452, -0.3221975415945053),
        (0.11839419044554234, -0.3248234484344721),
        (0.13058298453688622, -0.206279119476676),
        (0.11893977038562298, -0.1804603412747383),
    ];
    let q = [
        (0.026529536582529545, -0.03943194821476936),
        (0.038686336018145084, -0.06033603474497795),
        (0.10601317416876554, -0.11033345852047205),
        (0.1373703209683299, -0.11776527017354965),
        (0.1706860363483429, -0.12543946132063866),
        (0.27322681434452534, -0.05837948899716139),
        (0.2787931552156806, -0.04623298812657595),
        (0.28385413996875286, -0.031419357284903526),
        (0.25599782075732946, 0.01770743541419506),
        (0.08690541330724955, 0.1347522558644414),
        (0.07199231162667274, 0.1347012547776103),
        (0.014027450233697891, 0.06080291233956814),
        (0.014161622151732445, -0.007648559287190437),
    ];
    let p: Vec<DVec2> = p.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    let q: Vec<DVec2> = q.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    assert!(both(&p, &q));
    reset_pieces_stats();
    let _ = per_vertex_distances_pieces_with::<Exact>(&polygon(&p), &polygon(&q));
    assert_eq!(pieces_stats().max_reversals, 2);
}

#[test]
fn rotated_regular_polygons_two_n_crossings() {
    for n in [3usize, 4, 5, 8, 16, 33, 64, 100] {
        let p = regular(n, 1.0, 0.0);
        let q = regular(n, 1.0, core::f64::consts::PI / n as f64);
        let x = boundary_crossings_with::<Robust>(&polygon(&p), &polygon(&q));
        assert_eq!(x.len(), 2 * n);
        assert!(both(&p, &q));
        // Unequal sizes and radii around the same centre.
        let q2 = regular(n + 3, 1.05, 0.1);
        check::<Robust>(&p, &q2);
    }
}

#[test]
fn lattice_shared_edges_vertex_touches_identical_nested() {
    let sq = |x0: f64, y0: f64, s: f64| {
        vec![
            DVec2::new(x0, y0),
            DVec2::new(x0 + s, y0),
            DVec2::new(x0 + s, y0 + s),
            DVec2::new(x0, y0 + s),
        ]
    };
    let poly = |v: &[(f64, f64)]| v.iter().map(|&(x, y)| DVec2::new(x, y)).collect::<Vec<_>>();
    let big = sq(0.0, 0.0, 8.0);
    let cases: Vec<(Vec<DVec2>, Vec<DVec2>, &str, bool)> = vec![
        (big.clone(), big.clone(), "identical", false),
        (big.clone(), sq(2.0, 2.0, 3.0), "nested", false),
        (big.clone(), sq(0.0, 0.0, 3.0), "nested in a corner", false),
        (
            big.clone(),
            poly(&[(4.0, 0.0), (8.0, 4.0), (4.0, 8.0), (0.0, 4.0)]),
            "inscribed",
            false,
        ),
        (
            big.clone(),
            sq(8.0, 8.0, 2.0),
            "touching at a vertex",
            false,
        ),
        (big.clone(), sq(8.0, 0.0, 8.0), "shared edge outside", false),
        (
            big.clone(),
            sq(4.0, 4.0, 8.0),
            "overlapping corners, collinear edges",
            true,
        ),
        (
            big.clone(),
            sq(4.0, 0.0, 8.0),
            "overlap sharing two collinear edges",
            true,
        ),
        (
            big.clone(),
            sq(4.0, 2.0, 8.0),
            "overlap sharing one collinear edge",
            true,
        ),
        (
            big.clone(),
            poly(&[(4.0, -2.0), (10.0, 4.0), (4.0, 10.0), (-2.0, 4.0)]),
            "diamond through",
            true,
        ),
        (
            big.clone(),
            poly(&[(8.0, 4.0), (12.0, 0.0), (12.0, 8.0)]),
            "vertex on an edge, outside",
            false,
        ),
        (
            big.clone(),
            poly(&[(6.0, 4.0), (12.0, 0.0), (12.0, 8.0)]),
            "poking through an edge",
            true,
        ),
        (
            big.clone(),
            poly(&[(4.0, 4.0), (8.0, 0.0), (12.0, 4.0), (8.0, 8.0)]),
            "through two vertices",
            true,
        ),
        (
            big.clone(),
            poly(&[(8.0, 8.0), (4.0, 12.0), (0.0, 8.0), (4.0, 4.0)]),
            "crossing at shared vertices",
            true,
        ),
        (
            poly(&[(0.0, 0.0), (100.0, 0.0), (100.0, 10.0), (0.0, 10.0)]),
            poly(&[(2.0, 5.0), (4.0, 12.0), (0.0, 12.0)]),
            "notes §2.4 lobe",
            true,
        ),
    ];
    for (p, q, what, crosses) in &cases {
        let ran = both(p, q);
        assert_eq!(ran, *crosses, "{what}");
        both(q, p);
    }
    // Many random lattice pairs on a small grid: shared vertices, collinear edges, touches.
    let mut rng = SplitMix64::new(11);
    let mut crossed = 0;
    for round in 0..400 {
        let n = 3 + round % 8;
        let m = 3 + (round / 8) % 8;
        let s = DVec2::new(rng.range_i64(-2, 2) as f64, rng.range_i64(-2, 2) as f64);
        let p = random_convex_lattice(&mut rng, n, 30);
        let q: Vec<DVec2> = random_convex_lattice(&mut rng, m, 30)
            .into_iter()
            .map(|v| v + s)
            .collect();
        if check::<Robust>(&p, &q) {
            crossed += 1;
        }
        if round % 4 == 0 {
            check::<Exact>(&p, &q);
        }
    }
    println!("lattice pairs with crossings: {crossed} of 400");
    assert!(crossed > 100);
}

/// Predicate calls per vertex of per-vertex distances both ways, for the pieces and for the walk.
fn calls(n: usize, seed: u64, rotated: bool) -> (f64, f64) {
    let (p, q) = if rotated {
        (
            polygon(&regular(n, 1.0, 0.0)),
            polygon(&regular(n, 1.0, core::f64::consts::PI / n as f64)),
        )
    } else {
        let mut rng = SplitMix64::new(seed);
        let (p, q) = overlapping(&mut rng, n, n);
        (polygon(&p), polygon(&q))
    };
    reset_pieces_stats();
    reset_predicate_counts();
    let a = per_vertex_distances_pieces_with::<Counted<Robust>>(&p, &q);
    let b = per_vertex_distances_pieces_with::<Counted<Robust>>(&q, &p);
    let pieces = predicate_counts().total() as f64 / (2 * n) as f64;
    reset_predicate_counts();
    let c = per_vertex_distances_with::<Counted<Robust>>(&p, &q);
    let d = per_vertex_distances_with::<Counted<Robust>>(&q, &p);
    let walk = predicate_counts().total() as f64 / (2 * n) as f64;
    assert_eq!((a, b), (c, d));
    let s = pieces_stats();
    assert_eq!((s.fallbacks, s.scans), (0, 0), "{s:?}");
    (pieces, walk)
}

#[test]
fn linear_growth_by_counting_predicates() {
    for rotated in [false, true] {
        let sizes: &[usize] = if rotated {
            &[100, 1_000, 10_000, 50_000]
        } else {
            &[100, 1_000, 10_000, 100_000]
        };
        let mut per = Vec::new();
        for (i, &n) in sizes.iter().enumerate() {
            per.push((n, calls(n, 7 + i as u64, rotated)));
        }
        println!("rotated {rotated}: (n, (pieces, walk) calls per vertex) {per:?}");
        let first = per[0].1.0;
        for &(n, (c, _)) in &per {
            assert!(c <= 80.0, "n = {n}: {c} calls per vertex");
            assert!(c <= 1.5 * first + 10.0, "n = {n}: {c} against {first}");
        }
    }
}

#[test]
fn fast_and_random_signs_terminate() {
    let mut rng = SplitMix64::new(29);
    reset_pieces_stats();
    let mut wrong = 0;
    for round in 0..80 {
        let n = 3 + round % 60;
        let (p, q) = overlapping(&mut rng, n, n + 5);
        let (p, q) = (polygon(&p), polygon(&q));
        let c = cmmr_pieces_with::<Chaos>(&p, &q);
        assert_eq!((c.p_to_q.len(), c.q_to_p.len()), (p.len(), q.len()));
        let h = hausdorff_pieces_with::<Chaos>(&p, &q);
        assert!(h.distance >= 0.0);
        let f = cmmr_pieces_with::<Fast>(&p, &q);
        if f != cmmr_with::<Robust>(&p, &q) {
            wrong += 1;
        }
    }
    let s = pieces_stats();
    println!("chaos and fast: {s:?}; Fast records differing from Robust: {wrong} of 80");
    assert!(
        s.fallbacks > 0,
        "random signs should exhaust some budgets: {s:?}"
    );
}
