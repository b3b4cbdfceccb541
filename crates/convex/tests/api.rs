//! The query API around the distance: `distance_within` (exact threshold decisions),
//! `distance_with_hint` (temporal coherence, identical answers) and `distance_posed` (rigid motions,
//! features in the original caller's indices), checked against `distance_with` and the exact oracle.

mod common;

use common::{RELATIONS, check_answer, disjoint_pair, facing_pair, lattice_point, sliver_pair};
use glam::DVec2;
use polydist_convex::polygon::predicates::{
    BigRational, Counted, Exact, Kernel, Robust, predicate_counts, reset_predicate_counts,
};
use polydist_convex::polygon::{ConvexPolygon, Feature, PolygonError};
use polydist_convex::{
    Hint, Pose, Separation, Within, distance_posed, distance_with, distance_with_hint,
    distance_within,
};
use polydist_oracle::{
    SplitMix64, contact_status_convex, convex_distance, convex_pair, random_convex, rat,
    sqrt_nearest,
};
use proptest::prelude::*;

fn poly(v: &[DVec2]) -> ConvexPolygon {
    ConvexPolygon::try_new(v).expect("valid polygon")
}

// ---------------------------------------------------------------------------------------------
// distance_within

/// Checks `distance_within::<K>(p, q, r)` against the exact squared distance `sq`.
fn check_within<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon, sq: &BigRational, r: f64) {
    let got = distance_within::<K>(pp, qq, r);
    let inside = r >= 0.0
        && (r == f64::INFINITY || *sq <= rat(r).expect("finite") * rat(r).expect("finite"));
    match got {
        Within::Inside(s) => {
            assert!(inside, "r = {r:e}: reported inside, exact sq {sq}");
            assert_eq!(
                s,
                distance_with::<K>(pp, qq),
                "r = {r:e}: not the full answer"
            );
        }
        Within::Beyond { lower_bound } => {
            assert!(!inside, "r = {r:e}: reported beyond, exact sq {sq}");
            assert!(
                lower_bound >= r.max(0.0) || r.is_nan(),
                "lower bound {lower_bound} < r = {r}"
            );
            let lb = rat(lower_bound).expect("finite");
            assert!(
                &lb * &lb <= *sq,
                "lower bound {lower_bound:e} above the distance"
            );
        }
    }
}

/// Thresholds around the exact distance: the nearest double and its neighbours up to 3 ulps away.
fn thresholds(sq: &BigRational) -> Vec<f64> {
    let d = sqrt_nearest(sq);
    let mut v = vec![d, 0.0, -1.0, f64::NAN, f64::INFINITY, 1e300];
    let (mut up, mut down) = (d, d);
    for _ in 0..3 {
        up = up.next_up();
        down = down.next_down();
        v.push(up);
        v.push(down);
    }
    v
}

/// The early exit fires on separated pairs when `r` is well below the distance, saves predicates,
/// and never changes an answer (the thresholds test above runs the same code at the exact threshold).
#[test]
fn within_stops_early_when_a_seed_line_separates() {
    use polydist_convex::{reset_search_stats, search_stats};
    let mut rng = SplitMix64::new(77);
    reset_search_stats();
    let (mut early_cost, mut full_cost, mut cases) = (0u64, 0u64, 0u64);
    for round in 0..200 {
        // n + m ≥ 512: below that the full query's support guess is cheaper and no early check runs.
        let (n, m) = (450 + rng.index(200), 64 + rng.index(60));
        let (p, q) = disjoint_pair(&mut rng, n, m);
        let (pp, qq) = (poly(&p), poly(&q));
        let exact = convex_distance(&p, &q);
        let d = sqrt_nearest(&exact.sq);
        let r = d * [0.1, 0.5, 0.9][round % 3];
        check_within::<Robust>(&pp, &qq, &exact.sq, r);
        reset_predicate_counts();
        let before = search_stats().within_early_exits;
        let got = distance_within::<Counted<Robust>>(&pp, &qq, r);
        assert!(matches!(got, Within::Beyond { .. }));
        if search_stats().within_early_exits > before {
            early_cost += predicate_counts().total();
            reset_predicate_counts();
            let _ = distance_with::<Counted<Robust>>(&pp, &qq);
            full_cost += predicate_counts().total();
            cases += 1;
        }
    }
    println!(
        "early exits: {cases} of 200; predicates {early_cost} against {full_cost} for the full query"
    );
    assert!(cases >= 100, "only {cases} early exits");
    assert!(early_cost < full_cost, "{early_cost} >= {full_cost}");
}

#[test]
fn within_is_exact_at_the_threshold_every_relation() {
    let mut rng = SplitMix64::new(21);
    let (mut inside, mut beyond) = (0, 0);
    for rel in RELATIONS {
        for n in [3, 4, 7, 12] {
            for m in [3, 5, 9] {
                let pair = convex_pair(&mut rng, n, m, rel);
                let (pp, qq) = (poly(&pair.p), poly(&pair.q));
                let exact = convex_distance(&pair.p, &pair.q);
                for r in thresholds(&exact.sq) {
                    check_within::<Robust>(&pp, &qq, &exact.sq, r);
                    check_within::<Exact>(&pp, &qq, &exact.sq, r);
                    match distance_within::<Robust>(&pp, &qq, r) {
                        Within::Inside(_) => inside += 1,
                        Within::Beyond { .. } => beyond += 1,
                    }
                }
            }
        }
    }
    // Both answers occur at the threshold, so the test can tell them apart.
    assert!(
        inside > 100 && beyond > 100,
        "{inside} inside, {beyond} beyond"
    );
}

#[test]
fn within_exact_integer_distances_and_edge_cases() {
    let square = |x: f64, y: f64| {
        poly(&[
            DVec2::new(x, y),
            DVec2::new(x + 1.0, y),
            DVec2::new(x + 1.0, y + 1.0),
            DVec2::new(x, y + 1.0),
        ])
    };
    // Vertex–vertex 5 (3-4-5) and parallel edges 2.
    let p = square(0.0, 0.0);
    for (q, d) in [(square(4.0, 5.0), 5.0), (square(3.0, 0.5), 2.0)] {
        assert!(matches!(
            distance_within::<Robust>(&p, &q, d),
            Within::Inside(_)
        ));
        assert!(matches!(
            distance_within::<Robust>(&p, &q, d.next_down()),
            Within::Beyond { .. }
        ));
    }
    // A vertex against an edge at distance exactly 1/√2 · 2 = √2: with r = fl(√2) the decision
    // depends on the rounding direction of fl(√2), which the exact predicate gets right.
    let t = poly(&[
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(0.0, 2.0),
    ]);
    let x = poly(&[
        DVec2::new(2.0, 2.0),
        DVec2::new(4.0, 2.0),
        DVec2::new(2.0, 4.0),
    ]);
    let sq = BigRational::from_integer(2.into());
    for r in thresholds(&sq) {
        check_within::<Robust>(&t, &x, &sq, r);
    }
    // Beyond the predicates' range (r > 2^500): exact rationals. Gap 2.5·2^499 between big squares.
    let h = 2f64.powi(499);
    let rect = |a: f64, b: f64| {
        poly(&[
            DVec2::new(a, 0.0),
            DVec2::new(b, 0.0),
            DVec2::new(b, h),
            DVec2::new(a, h),
        ])
    };
    let (big_p, big_q) = (rect(-2.0 * h, -h), rect(1.5 * h, 2.0 * h));
    let sq_big = convex_distance(big_p.vertices(), big_q.vertices()).sq;
    assert!(matches!(
        distance_within::<Robust>(&big_p, &big_q, 2.5 * h),
        Within::Inside(_)
    ));
    for r in thresholds(&sq_big)
        .into_iter()
        .chain([f64::MAX, 2.0 * h, (2.0 * h).next_up()])
    {
        check_within::<Robust>(&big_p, &big_q, &sq_big, r);
    }
    // Meeting polygons are within every r ≥ 0, beyond every negative r.
    let q = square(0.5, 0.5);
    assert!(matches!(
        distance_within::<Robust>(&p, &q, 0.0),
        Within::Inside(Separation::Overlapping)
    ));
    assert_eq!(
        distance_within::<Robust>(&p, &q, -1.0),
        Within::Beyond { lower_bound: 0.0 }
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 96,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/api.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn within_random_pairs(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..40, m in 3usize..40, scale in -3.0f64..3.0) {
        let mut rng = SplitMix64::new(seed);
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        let (pp, qq) = (poly(&pair.p), poly(&pair.q));
        let exact = convex_distance(&pair.p, &pair.q);
        let d = sqrt_nearest(&exact.sq);
        check_within::<Robust>(&pp, &qq, &exact.sq, d * 2f64.powf(scale));
        check_within::<Robust>(&pp, &qq, &exact.sq, d);
        check_within::<Robust>(&pp, &qq, &exact.sq, d.next_down());
    }
}

// ---------------------------------------------------------------------------------------------
// distance_with_hint

/// The hinted answer under `K` equals `distance_with::<K>`; returns the next hint.
fn same_with_hint<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon, hint: Option<Hint>) -> Hint {
    let (got, next) = distance_with_hint::<K>(pp, qq, hint);
    assert_eq!(
        got,
        distance_with::<K>(pp, qq),
        "hint {hint:?}\np = {:?}\nq = {:?}",
        pp.vertices(),
        qq.vertices()
    );
    assert_eq!(
        next.internal_pair().is_some(),
        matches!(got, Separation::Disjoint(_))
    );
    next
}

/// Moves `q` by small random steps over `frames` frames, feeding each hint to the next query; checks
/// identity with `distance_with` (and the oracle every eighth frame).
fn frames<K: Kernel>(rng: &mut SplitMix64, p: &[DVec2], q: &[DVec2], step: f64, frames: usize) {
    let pp = poly(p);
    let mut q: Vec<DVec2> = q.to_vec();
    let mut hint = None;
    for frame in 0..frames {
        let d = DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5) * step;
        q.iter_mut().for_each(|v| *v += d);
        let Ok(qq) = ConvexPolygon::try_new(&q) else {
            continue;
        };
        hint = Some(same_with_hint::<K>(&pp, &qq, hint));
        if frame % 8 == 0 {
            let (got, _) = distance_with_hint::<K>(&pp, &qq, hint);
            check_answer(
                p,
                &q,
                &convex_distance(p, &q),
                contact_status_convex(p, &q),
                &got,
                "hinted",
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 64,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/api.txt",
        ))),
        ..ProptestConfig::default()
    })]

    /// Random pairs in every relation, with no hint, with a hint from the pair itself, and with a hint
    /// from an unrelated pair (indices possibly out of range).
    #[test]
    fn hint_identical_on_random_pairs(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..60, m in 3usize..60) {
        let mut rng = SplitMix64::new(seed);
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        let (pp, qq) = (poly(&pair.p), poly(&pair.q));
        let own = same_with_hint::<Robust>(&pp, &qq, None);
        same_with_hint::<Robust>(&pp, &qq, Some(own));
        let other = convex_pair(&mut rng, 3 + n % 7 * 13, 3 + m % 5 * 17, RELATIONS[(rel + 3) % RELATIONS.len()]);
        let foreign = same_with_hint::<Robust>(&poly(&other.p), &poly(&other.q), None);
        same_with_hint::<Robust>(&pp, &qq, Some(foreign));
        same_with_hint::<Robust>(&qq, &pp, Some(foreign));
    }

    /// Frames: one polygon translated by small random vectors, each hint fed to the next frame.
    #[test]
    fn hint_identical_over_frames(seed in any::<u64>(), n in 3usize..80, m in 3usize..80, step in 0.001f64..0.5) {
        let mut rng = SplitMix64::new(seed);
        let (p, q) = disjoint_pair(&mut rng, n, m);
        frames::<Robust>(&mut rng, &p, &q, step, 24);
    }
}

/// Frames that pass through touching and overlapping (a step towards the other polygon), parallel
/// facing edges (several optimal pairs: the walk must give way to the search), slivers, points and
/// segments, under Robust and Exact.
#[test]
fn hint_identical_through_contact_ties_and_degenerate_shapes() {
    let mut rng = SplitMix64::new(5);
    for k in 0..40 {
        let (p, q) = disjoint_pair(&mut rng, 3 + k % 30, 3 + (k * 7) % 30);
        // Drift towards P: from disjoint through contact into overlap.
        let pp = poly(&p);
        let mut hint = None;
        let c = q.iter().copied().sum::<DVec2>() / q.len() as f64;
        for t in 0..40 {
            let moved: Vec<DVec2> = q.iter().map(|&v| v - c * (f64::from(t) / 30.0)).collect();
            hint = Some(same_with_hint::<Robust>(&pp, &poly(&moved), hint));
        }
        if let Some(f) = facing_pair(&mut rng, k) {
            let (fp, fq) = (poly(&f.p), poly(&f.q));
            let h = same_with_hint::<Exact>(&fp, &fq, None);
            same_with_hint::<Exact>(&fp, &fq, Some(h));
            same_with_hint::<Robust>(&fq, &fp, Some(h));
            frames::<Robust>(&mut rng, &f.p, &f.q, 1e-9, 6);
        }
        let (a, b) = sliver_pair(&mut rng, 3 + k % 20);
        frames::<Robust>(&mut rng, &a, &b, 1e-3, 6);
        // Points and segments (no walk, still identical).
        let poly_v = random_convex(&mut rng, 5, DVec2::ZERO, 3.0);
        let shapes = [
            vec![lattice_point(&mut rng)],
            vec![lattice_point(&mut rng), lattice_point(&mut rng)],
        ];
        for s in &shapes {
            let Ok(ss) = ConvexPolygon::try_new(s) else {
                continue;
            };
            let h = same_with_hint::<Robust>(&ss, &poly(&poly_v), None);
            same_with_hint::<Robust>(&poly(&poly_v), &ss, Some(h));
        }
    }
}

/// The walk is actually used: on slowly moving large polygons the hinted queries evaluate fewer
/// predicates than the unhinted ones (a broken walk that always falls back would cost more).
#[test]
fn hint_saves_predicates_on_coherent_frames() {
    let mut rng = SplitMix64::new(77);
    let (mut hinted, mut plain) = (0u64, 0u64);
    for _ in 0..20 {
        let (p, q) = disjoint_pair(&mut rng, 2000, 2000);
        let pp = poly(&p);
        let mut q = q;
        let mut hint = None;
        for _ in 0..10 {
            let d = DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5) * 1e-3;
            q.iter_mut().for_each(|v| *v += d);
            let qq = poly(&q);
            reset_predicate_counts();
            let (got, next) = distance_with_hint::<Counted<Robust>>(&pp, &qq, hint);
            hinted += predicate_counts().total();
            reset_predicate_counts();
            let want = distance_with::<Counted<Robust>>(&pp, &qq);
            plain += predicate_counts().total();
            assert_eq!(got, want);
            hint = Some(next);
        }
    }
    println!("predicates: hinted {hinted}, plain {plain}");
    assert!(hinted * 2 < plain, "hinted {hinted}, plain {plain}");
}

// ---------------------------------------------------------------------------------------------
// distance_posed

/// `v` as a caller ring: reversed (clockwise) when `cw`, starting at `start`.
fn caller_ring(v: &[DVec2], cw: bool, start: usize) -> Vec<DVec2> {
    let mut r: Vec<DVec2> = v.to_vec();
    if cw {
        r.reverse();
    }
    let k = start % r.len();
    r.rotate_left(k);
    r
}

/// Checks a posed answer against the oracle on the posed caller rings (features in caller indices).
/// Returns `false` when a pose broke the polygon (an error, never a panic).
fn check_posed(p: &[DVec2], pose_p: Pose, q: &[DVec2], pose_q: Pose) -> bool {
    let (pp, qq) = (poly(p), poly(q));
    let got = match distance_posed::<Robust>(&pp, pose_p, &qq, pose_q) {
        Ok(s) => s,
        Err(e) => {
            // The error is the posed list's: rebuilding it gives the same error.
            let moved: Vec<DVec2> = pp.vertices().iter().map(|&v| pose_p.apply(v)).collect();
            let moved_q: Vec<DVec2> = qq.vertices().iter().map(|&v| pose_q.apply(v)).collect();
            assert!(
                ConvexPolygon::try_new(&moved).err() == Some(e)
                    || ConvexPolygon::try_new(&moved_q).err() == Some(e)
            );
            return false;
        }
    };
    // The posed caller rings: the caller's vertices moved by the poses. Their features are the
    // original caller's indices.
    let wp: Vec<DVec2> = p.iter().map(|&v| pose_p.apply(v)).collect();
    let wq: Vec<DVec2> = q.iter().map(|&v| pose_q.apply(v)).collect();
    if pp.len() == p.len() && qq.len() == q.len() {
        // No dropped caller vertex: the posed caller rings are the posed polygons' vertex lists.
        check_answer(
            &wp,
            &wq,
            &convex_distance(&wp, &wq),
            contact_status_convex(&wp, &wq),
            &got,
            "posed",
        );
    } else {
        // Dropped (collinear) caller vertices are no longer collinear once rotated and rounded: the
        // oracle cannot take those rings. Check the answer against the plain query on the posed
        // polygons, and the vertex witnesses against the posed caller vertices.
        let moved_p: Vec<DVec2> = pp.vertices().iter().map(|&v| pose_p.apply(v)).collect();
        let moved_q: Vec<DVec2> = qq.vertices().iter().map(|&v| pose_q.apply(v)).collect();
        let plain = distance_with::<Robust>(&poly(&moved_p), &poly(&moved_q));
        assert_eq!(got.distance(), plain.distance());
        if let Separation::Disjoint(c) = got {
            if let Feature::Vertex(i) = c.feature_p {
                assert_eq!(c.point_p, wp[i]);
            }
            if let Feature::Vertex(j) = c.feature_q {
                assert_eq!(c.point_q, wq[j]);
            }
        }
    }
    true
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 128,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/api.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn posed_random_pairs_map_to_caller_indices(
        seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..30, m in 3usize..30,
        cw in any::<(bool, bool)>(), start in any::<(usize, usize)>(),
        ap in -7.0f64..7.0, aq in -7.0f64..7.0, tx in -5.0f64..5.0, ty in -5.0f64..5.0,
    ) {
        let mut rng = SplitMix64::new(seed);
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        let p = caller_ring(&pair.p, cw.0, start.0);
        let q = caller_ring(&pair.q, cw.1, start.1);
        // Q keeps its place relative to P: the same rotation about the origin for both, then a shift.
        let pose_p = Pose { translation: DVec2::new(tx, ty), rotation: ap };
        check_posed(&p, pose_p, &q, pose_p);
        // Independent poses (mostly far apart or overlapping).
        let pose_q = Pose { translation: DVec2::new(ty * 2.0, tx), rotation: aq };
        check_posed(&p, pose_p, &q, pose_q);
    }
}

#[test]
fn posed_identity_equals_the_plain_query() {
    let mut rng = SplitMix64::new(3);
    for rel in RELATIONS {
        let pair = convex_pair(&mut rng, 9, 6, rel);
        let (pp, qq) = (
            poly(&caller_ring(&pair.p, true, 4)),
            poly(&caller_ring(&pair.q, false, 2)),
        );
        assert_eq!(
            distance_posed::<Robust>(&pp, Pose::IDENTITY, &qq, Pose::IDENTITY),
            Ok(distance_with::<Robust>(&pp, &qq))
        );
    }
}

/// Caller rings with dropped vertices (collinear and repeated, closed, clockwise), translated by exact
/// lattice vectors: the features name the caller's sub-edges and vertices.
#[test]
fn posed_features_through_dropped_caller_vertices() {
    // Clockwise, closed, with a repeat and collinear vertices on the bottom edge y = 0 (x = 0, 2, 4, 6).
    let ring: Vec<DVec2> = [
        (0.0, 0.0),
        (0.0, 4.0),
        (6.0, 4.0),
        (6.0, 0.0),
        (4.0, 0.0),
        (4.0, 0.0),
        (2.0, 0.0),
        (0.0, 0.0),
    ]
    .iter()
    .map(|&(x, y)| DVec2::new(x, y))
    .collect();
    let p = poly(&ring);
    assert_eq!(p.len(), 4);
    let shift = Pose {
        translation: DVec2::new(10.0, -20.0),
        rotation: 0.0,
    };
    for (x, want) in [
        (1.0, Feature::Edge(6)),
        (2.0, Feature::Vertex(6)),
        (3.0, Feature::Edge(5)),
        (4.0, Feature::Vertex(4)),
        (5.0, Feature::Edge(3)),
    ] {
        // A small triangle below the bottom edge, its top vertex at (x, −1), moved by the same shift.
        let tri = poly(&[
            DVec2::new(x, -1.0),
            DVec2::new(x - 1.0, -3.0),
            DVec2::new(x + 1.0, -3.0),
        ]);
        let s = distance_posed::<Robust>(&p, shift, &tri, shift).expect("valid");
        let c = s.closest().expect("disjoint");
        assert_eq!(
            (c.feature_p, c.feature_q),
            (want, Feature::Vertex(0)),
            "x = {x}"
        );
        assert_eq!(c.distance, 1.0);
        assert_eq!(c.point_q, DVec2::new(x + 10.0, -21.0));
        // Touching at the same place: the contact features map back the same way.
        let touch = poly(&[
            DVec2::new(x, 0.0),
            DVec2::new(x - 1.0, -2.0),
            DVec2::new(x + 1.0, -2.0),
        ]);
        match distance_posed::<Robust>(&p, shift, &touch, shift).expect("valid") {
            Separation::Touching {
                point,
                feature_p,
                feature_q,
            } => {
                assert_eq!(point, DVec2::new(x + 10.0, -20.0));
                assert_eq!(
                    (feature_p, feature_q),
                    (want, Feature::Vertex(0)),
                    "x = {x}"
                );
            }
            other => panic!("x = {x}: {other:?}"),
        }
    }
}

/// Non-finite and out-of-range poses, and rotations of slivers that rounding may break: an error or a
/// checked answer, never a panic.
#[test]
fn posed_errors_never_panic() {
    let square = poly(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y]);
    let bad = [
        Pose {
            translation: DVec2::ZERO,
            rotation: f64::NAN,
        },
        Pose {
            translation: DVec2::new(f64::INFINITY, 0.0),
            rotation: 0.0,
        },
        Pose {
            translation: DVec2::new(0.0, 2f64.powi(500) * 1.5),
            rotation: 0.0,
        },
    ];
    for pose in bad {
        let e = distance_posed::<Robust>(&square, pose, &square, Pose::IDENTITY);
        assert!(
            matches!(
                e,
                Err(PolygonError::NonFinite { .. } | PolygonError::OutOfRange { .. })
            ),
            "{e:?}"
        );
        let e = distance_posed::<Robust>(&square, Pose::IDENTITY, &square, pose);
        assert!(e.is_err(), "{e:?}");
    }
    let mut rng = SplitMix64::new(99);
    let (mut ok, mut errors) = (0, 0);
    for k in 0..300 {
        let (a, b) = sliver_pair(&mut rng, 3 + k % 40);
        let pose = Pose {
            translation: DVec2::new(rng.unit_f64(), 0.0),
            rotation: rng.unit_f64() * 7.0,
        };
        if check_posed(&a, pose, &b, pose) {
            ok += 1;
        } else {
            errors += 1;
        }
    }
    println!("slivers posed: {ok} answered, {errors} rejected");
    assert!(ok > 0);
    // A nearly flat convex chain (turns far below the rounding of a rotated coordinate) under a far apex: rotations round
    // its vertices off the chain, so some poses break convexity and must be errors.
    let chain: Vec<DVec2> = (0..60)
        .map(|i| {
            let x = f64::from(i);
            DVec2::new(x, -1e-16 * x * (59.0 - x))
        })
        .chain([DVec2::new(30.0, 10.0)])
        .collect();
    let far = poly(&[
        DVec2::new(100.0, 0.0),
        DVec2::new(101.0, 0.0),
        DVec2::new(100.0, 1.0),
    ]);
    let (mut ok, mut errors) = (0, 0);
    for k in 0..200 {
        let pose = Pose {
            translation: DVec2::new(0.1, 0.3),
            rotation: f64::from(k) * 0.031,
        };
        if check_posed(&chain, pose, far.vertices(), Pose::IDENTITY) {
            ok += 1;
        } else {
            errors += 1;
        }
    }
    println!("flat chain posed: {ok} answered, {errors} rejected");
    assert!(ok > 0 && errors > 0, "{ok} answered, {errors} rejected");
}
