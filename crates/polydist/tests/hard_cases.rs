//! The hard-case suite (issue 8): every convex algorithm under every kernel on every case of
//! `fixtures/hard/convex.txt`, against the exact answers stored with the case (computed by the oracle
//! when the file was generated, never by an algorithm under test).
//!
//! Under Robust and Exact: exact optimal features and the documented bounds on every case, no
//! exceptions (distance within 3.5 ulps, squared distance within 5, Hausdorff within 3.5, CMMR within 6).
//! The large pairs (`fixtures/hard/large_convex.txt`) store a certified enclosure of the CMMR instead
//! of its exact value (`polydist_oracle::cmmr_enclosure`): the computed CMMR must be within 6 ulps of
//! every point of it, and the suite recomputes every stored enclosure.
//! Under Fast: the number of wrong answers is recorded and printed; only termination without a panic
//! is asserted.

use glam::DVec2;
use polydist::convex::{
    Separation, cmmr_with, distance_brute, distance_schwartz_with, distance_with,
    distance_yang_with, hausdorff_with, min_vertex_distance_with,
};
use polydist::polygon::{ConvexPolygon, Feature};
use polydist::predicates::{Exact, Fast, Kernel, Robust};
use polydist_fixtures::{HardCase, hard_cases};
use polydist_oracle::{HardAnswers, SimpleHardAnswers, ulps_error, ulps_error_sqrt};
use std::collections::BTreeMap;

/// The answers of a case, with the oracle's features as polydist's.
struct Answers {
    exact: HardAnswers,
    pairs: Vec<(Feature, Feature)>,
}

fn ours(f: polydist_oracle::Feature) -> Feature {
    match f {
        polydist_oracle::Feature::Vertex(i) => Feature::Vertex(i),
        polydist_oracle::Feature::Edge(i) => Feature::Edge(i),
    }
}

fn answers(c: &HardCase) -> Answers {
    let exact = HardAnswers::from_words(&c.answers).unwrap_or_else(|e| panic!("{}: {e}", c.name));
    let pairs = exact
        .pairs
        .iter()
        .map(|&(f, g)| (ours(f), ours(g)))
        .collect();
    Answers { exact, pairs }
}

fn points(v: &[[f64; 2]]) -> Vec<DVec2> {
    v.iter().map(|&[x, y]| DVec2::new(x, y)).collect()
}

/// What went wrong on one case, or `None`.
type Check = Option<String>;

fn check_distance(s: &Separation, a: &Answers) -> Check {
    match (s, a.exact.contact.as_str()) {
        (Separation::Disjoint(c), "disjoint") => {
            if !a.pairs.contains(&(c.feature_p, c.feature_q)) {
                return Some(format!(
                    "features {:?} {:?} not optimal",
                    c.feature_p, c.feature_q
                ));
            }
            let (e, e2) = (
                ulps_error_sqrt(c.distance, &a.exact.dist),
                ulps_error(c.squared_distance, &a.exact.dist),
            );
            (e > 3.5 || e2 > 5.0).then(|| format!("distance off by {e} ulps, squared by {e2}"))
        }
        (
            Separation::Touching {
                feature_p,
                feature_q,
                ..
            },
            "touching",
        ) => (!a.pairs.contains(&(*feature_p, *feature_q)))
            .then(|| format!("touching features {feature_p:?} {feature_q:?} do not meet")),
        (Separation::Overlapping, "overlapping") => None,
        (s, c) => Some(format!("outcome {s:?}, expected {c}")),
    }
}

/// Every algorithm of the convex crate on one case under `K`: (algorithm, failure) pairs.
fn run_case<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    a: &Answers,
) -> Vec<(&'static str, Check)> {
    let mut out = vec![
        (
            "distance (dispatch)",
            check_distance(&distance_with::<K>(p, q), a),
        ),
        (
            "distance Yang",
            check_distance(&distance_yang_with::<K>(p, q), a),
        ),
        (
            "distance Schwartz",
            check_distance(&distance_schwartz_with::<K>(p, q), a),
        ),
    ];
    // The O(nm) brute force only below 10⁶ feature pairs: the large cases leave it to the report.
    if p.len() * q.len() <= BRUTE_MAX {
        out.push((
            "distance brute force",
            check_distance(&distance_brute::<K>(p, q), a),
        ));
    }
    let v = min_vertex_distance_with::<K>(p, q);
    out.push((
        "vertex distance",
        if a.exact.vpairs.contains(&(v.vertex_p, v.vertex_q)) {
            let e = ulps_error_sqrt(v.distance, &a.exact.vdist);
            (e > 3.5).then(|| format!("vertex distance off by {e} ulps"))
        } else {
            Some(format!(
                "vertex pair {}:{} not optimal",
                v.vertex_p, v.vertex_q
            ))
        },
    ));
    let h = hausdorff_with::<K>(p, q);
    let hmax = if a.exact.hpq >= a.exact.hqp {
        &a.exact.hpq
    } else {
        &a.exact.hqp
    };
    out.push((
        "Hausdorff",
        if !a.exact.apq.contains(&h.p_to_q.vertex) || !a.exact.aqp.contains(&h.q_to_p.vertex) {
            Some(format!(
                "argmax {} / {} not optimal",
                h.p_to_q.vertex, h.q_to_p.vertex
            ))
        } else {
            let e = ulps_error_sqrt(h.distance, hmax);
            (e > 3.5).then(|| format!("Hausdorff off by {e} ulps"))
        },
    ));
    // CMMR against what the case stores: its exact value, or for the large cases a certified
    // enclosure [lo, hi] (`polydist_oracle::cmmr_enclosure`). The bound must hold against every point
    // of the interval; an interval too wide to decide fails the case instead of passing it.
    out.push((
        "CMMR",
        match a.exact.cmmr_bounds() {
            None => Some("no exact CMMR or enclosure stored".to_owned()),
            Some(b) if b.width_ulps() > ENCLOSURE_MAX_ULPS => Some(format!(
                "CMMR enclosure {} ulps wide: too wide to decide",
                b.width_ulps()
            )),
            Some(b) => {
                let e = b.ulps_error(cmmr_with::<K>(p, q).value);
                (e > 6.0).then(|| format!("CMMR off by {e} ulps"))
            }
        },
    ));
    out
}

/// The largest `n·m` at which the tests run the `O(nm)` brute forces.
const BRUTE_MAX: usize = 1_000_000;

/// The widest CMMR enclosure accepted, in ulps of its lower end (the oracle's are below `2⁻⁴⁷`).
const ENCLOSURE_MAX_ULPS: f64 = 1e-3;

/// The polygons of a case: its `p` and `q` lines, or for a large case its `gen` line rebuilt (and
/// checked against the stored fingerprint) by the oracle.
fn polygons(c: &HardCase) -> (Vec<DVec2>, Vec<DVec2>) {
    match c.answer("gen") {
        Some(words) => polydist_oracle::large_pair(words)
            .unwrap_or_else(|e| panic!("{}/{}: {e}", c.family, c.name)),
        None => (points(&c.p), points(&c.q)),
    }
}

#[test]
fn every_convex_algorithm_on_every_hard_case() {
    let cases = hard_cases("hard/convex.txt").expect("fixtures/hard/convex.txt");
    assert!(
        cases.len() >= 170,
        "the suite shrank: {} cases",
        cases.len()
    );
    convex_suite(&cases);
}

/// The large convex pairs (10⁴–10⁵ vertices, `fixtures/hard/large_convex.txt`, answers from the
/// oracle's pruned exact search, CMMR as a certified enclosure): every algorithm but the `O(nm)`
/// brute force, under every kernel.
#[test]
fn every_convex_algorithm_on_every_large_case() {
    let cases = hard_cases("hard/large_convex.txt").expect("fixtures/hard/large_convex.txt");
    assert!(cases.len() >= 9, "the suite shrank: {} cases", cases.len());
    for family in ["large_circle", "large_cocircular"] {
        assert!(
            cases.iter().any(|c| c.family == family),
            "no case of {family}"
        );
    }
    let sizes: Vec<usize> = cases.iter().map(|c| polygons(c).0.len()).collect();
    assert!(sizes.iter().any(|&n| n >= 10_000) && sizes.iter().any(|&n| n >= 75_000));
    for c in &cases {
        assert!(
            answers(c).exact.cmmr_enclosure.is_some(),
            "{}/{}: no CMMR enclosure stored",
            c.family,
            c.name
        );
    }
    convex_suite(&cases);
}

/// The stored CMMR enclosures of the large pairs are the oracle's: recomputed for every pair
/// (exact terms by an `O(log n)` exact nearest-edge search per vertex, rounded down and up,
/// summed exactly: about 6 s for the 9 pairs in a debug build) and equal to the stored interval.
#[test]
fn large_cmmr_enclosures_are_the_oracles() {
    let cases = hard_cases("hard/large_convex.txt").expect("fixtures/hard/large_convex.txt");
    let mut recomputed = Vec::new();
    for c in &cases {
        let (vp, vq) = polygons(c);
        let stored = answers(c).exact.cmmr_enclosure.expect("an enclosure");
        assert_eq!(
            polydist_oracle::cmmr_enclosure(&vp, &vq),
            stored,
            "{}/{}",
            c.family,
            c.name
        );
        recomputed.push(c.family.as_str());
    }
    assert_eq!(recomputed.len(), cases.len());
    for family in ["large_circle", "large_cocircular"] {
        assert!(recomputed.contains(&family), "no {family} pair recomputed");
    }
}

/// The oracle's CMMR enclosure is right where the exact value is known: on every case of
/// `fixtures/hard/convex.txt` (which stores the exact CMMR over the corners), the enclosure of the
/// corners contains it and is narrower than 10⁻³ ulp of it.
#[test]
fn cmmr_enclosure_contains_every_stored_exact_cmmr() {
    let cases = hard_cases("hard/convex.txt").expect("fixtures/hard/convex.txt");
    let mut nonzero = 0;
    for c in &cases {
        let exact = answers(c).exact.cmmr.expect("an exact CMMR");
        let (vp, vq) = polygons(c);
        let (p, q) = (
            ConvexPolygon::try_new(&vp).expect("convex"),
            ConvexPolygon::try_new(&vq).expect("convex"),
        );
        let e = polydist_oracle::cmmr_enclosure(p.vertices(), q.vertices());
        assert!(
            e.contains(&exact),
            "{}/{}: [{}, {}] misses {exact}",
            c.family,
            c.name,
            e.lo,
            e.hi
        );
        let width = e.width_ulps();
        assert!(width < 1e-3, "{}/{}: {width} ulps wide", c.family, c.name);
        nonzero += usize::from(e.lo != e.hi);
    }
    // Most cases have edge terms, whose rounding makes the interval nonzero: the test exercises it.
    assert!(nonzero >= 50, "only {nonzero} inexact enclosures");
}

/// Every convex algorithm under every kernel on `cases`: Robust and Exact must be exactly right on
/// every case; Fast's wrong answers are counted and printed.
fn convex_suite(cases: &[HardCase]) {
    let mut failures = Vec::new();
    let mut fast_wrong: BTreeMap<&str, usize> = BTreeMap::new();
    for c in cases {
        let a = answers(c);
        let (vp, vq) = polygons(c);
        let (p, q) = (
            ConvexPolygon::try_new(&vp).expect("convex"),
            ConvexPolygon::try_new(&vq).expect("convex"),
        );
        for (kernel, results) in [
            ("Robust", run_case::<Robust>(&p, &q, &a)),
            ("Exact", run_case::<Exact>(&p, &q, &a)),
        ] {
            for (alg, r) in results {
                if let Some(why) = r {
                    failures.push(format!("{kernel} {alg} {}/{}: {why}", c.family, c.name));
                }
            }
        }
        for (alg, r) in run_case::<Fast>(&p, &q, &a) {
            *fast_wrong.entry(alg).or_default() += usize::from(r.is_some());
        }
    }
    eprintln!(
        "Fast kernel, wrong answers of {} hard cases: {fast_wrong:?}",
        cases.len()
    );
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn the_suite_covers_every_family() {
    let cases = hard_cases("hard/convex.txt").expect("fixtures/hard/convex.txt");
    for family in [
        "nearly_touching",
        "relative_gap",
        "touching",
        "huge_offset",
        "parallel",
        "parallel_ulp_off",
        "cocircular",
        "cocircular_perturbed",
        "cocircular_far",
        "near_tie_far",
        "collinear_input",
        "sliver",
        "sliver_1e9",
        "overlapping",
        "nested",
        "identical",
        "far",
        "orient_1_far",
        "near_parallel_far",
        "cocircular_1e12",
    ] {
        assert!(
            cases.iter().any(|c| c.family == family),
            "no case of {family}"
        );
    }
}

/// The simple-polygon cases (`fixtures/hard/simple.txt`: hulls disjoint, interlocked combs whose
/// hulls meet, and a polygon in a pocket of the other, one hull inside the other): `separation` and
/// its brute-force twin under every kernel.
#[test]
fn polygon_separation_on_every_simple_hard_case() {
    let cases = hard_cases("hard/simple.txt").expect("fixtures/hard/simple.txt");
    assert!(
        cases.len() >= 170,
        "the suite shrank: {} cases",
        cases.len()
    );
    for family in [
        "side_by_side",
        "side_by_side_far",
        "sawteeth",
        "interlocked_combs",
        "interlocked_combs_far",
        "orient_1_far",
        "near_parallel_far",
        "pocket",
        "pocket_lid",
        "comb_notch",
        "pocket_far",
        "comb_notch_far",
        "pocket_orient_far",
    ] {
        assert!(
            cases.iter().any(|c| c.family == family),
            "no case of {family}"
        );
    }
    let (chains, separators) = simple_suite(&cases);
    assert!(chains >= 5, "section 3 ran on {chains} cases only");
    assert!(
        separators >= 16 + 70,
        "the separator route ran on {separators} cases only"
    );
}

/// The containing case is what the pocket families exercise: one hull inside the other, so every
/// disjoint pair of them (in both argument orders) goes through Amato's separators, never the
/// separable-chains fast path, and the touching (and, in `pocket_orient_far`, overlapping) ones come
/// out `Intersecting`.
#[test]
fn pocket_families_take_the_separator_route() {
    use polydist::polygon::SimplePolygon;
    use polydist::separation::{PolygonSeparation, Route, separation};

    let cases = hard_cases("hard/simple.txt").expect("fixtures/hard/simple.txt");
    let pockets: Vec<&HardCase> = cases
        .iter()
        .filter(|c| c.family.starts_with("pocket") || c.family.starts_with("comb_notch"))
        .collect();
    assert!(pockets.len() >= 80, "{} pocket cases", pockets.len());
    let (mut separated, mut touching, mut outer_q) = (0, 0, 0);
    for c in pockets {
        let (vp, vq) = polygons(c);
        let (p, q) = (
            SimplePolygon::try_new(&vp).expect("simple"),
            SimplePolygon::try_new(&vq).expect("simple"),
        );
        let contact = SimpleHardAnswers::from_words(&c.answers)
            .expect("answers")
            .contact;
        match (separation::<Robust>(&p, &q), contact.as_str()) {
            (
                Ok(PolygonSeparation::Separated {
                    route: Route::Separators,
                    ..
                }),
                "disjoint",
            ) => separated += 1,
            (Ok(PolygonSeparation::Intersecting(_)), "touching" | "overlapping") => touching += 1,
            (a, c2) => panic!(
                "{}/{}: {a:?}, expected {c2} by the separators",
                c.family, c.name
            ),
        }
        outer_q += usize::from(c.name.ends_with("_outer_q"));
    }
    assert!(
        separated >= 70 && touching >= 8,
        "{separated} separated, {touching} touching"
    );
    assert!(
        outer_q >= 40,
        "the outer polygon as Q in {outer_q} cases only"
    );
}

/// The large simple pairs (stars and combs of 10⁴ vertices, hulls disjoint,
/// `fixtures/hard/large_simple.txt`, answers from the oracle's pruned exact search): `separation`
/// under every kernel (the `O(nm)` brute force is left to the report).
#[test]
fn polygon_separation_on_every_large_simple_case() {
    let cases = hard_cases("hard/large_simple.txt").expect("fixtures/hard/large_simple.txt");
    assert!(cases.len() >= 4, "the suite shrank: {} cases", cases.len());
    for family in ["large_star", "large_comb"] {
        assert!(
            cases.iter().any(|c| c.family == family),
            "no case of {family}"
        );
    }
    simple_suite(&cases);
}

/// How [`simple_suite`] answers a case.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Method {
    /// `separation`, every route as shipped.
    Auto,
    /// `separation_of_disjoint_with(Section3)` on the disjoint cases: section 3's matrices
    /// wherever the disjoint-hull route does not end at the hull features.
    Matrices,
    /// The brute-force twin.
    Brute,
}

/// `separation` (and below [`BRUTE_MAX`] its brute-force twin) under every kernel on `cases`, and
/// section 3's matrices alone on the disjoint ones; returns how many cases took section 3 (its
/// envelope sweep or its matrices) and how many the separator route.
fn simple_suite(cases: &[HardCase]) -> (usize, usize) {
    use polydist::polygon::SimplePolygon;
    use polydist::separation::{
        HullRouteMethod, PolygonSeparation, Route, polygon_separation_brute, separation,
        separation_of_disjoint_with,
    };

    fn check<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon, c: &HardCase, how: Method) -> Check {
        let exact = SimpleHardAnswers::from_words(&c.answers).expect("answers");
        let (contact, sq) = (&exact.contact, &exact.dist);
        let pairs: Vec<(Feature, Feature)> = exact
            .pairs
            .iter()
            .map(|&(f, g)| (ours(f), ours(g)))
            .collect();
        let answer = match how {
            Method::Brute => polygon_separation_brute::<K>(p, q),
            Method::Auto => separation::<K>(p, q),
            Method::Matrices if contact == "disjoint" => {
                separation_of_disjoint_with::<K>(p, q, HullRouteMethod::Section3)
            }
            Method::Matrices => return None,
        };
        match (answer, contact.as_str()) {
            (Ok(PolygonSeparation::Separated { pair, .. }), "disjoint") => {
                if !pairs.contains(&(pair.feature_p, pair.feature_q)) {
                    return Some(format!(
                        "features {:?} {:?} not optimal",
                        pair.feature_p, pair.feature_q
                    ));
                }
                let e = ulps_error_sqrt(pair.distance, sq);
                (e > 3.5).then(|| format!("distance off by {e} ulps"))
            }
            (Ok(PolygonSeparation::Intersecting(_)), "touching" | "overlapping") => None,
            (a, c) => Some(format!("answer {a:?}, expected {c}")),
        }
    }
    let mut failures = Vec::new();
    let mut fast_wrong: BTreeMap<&str, usize> = BTreeMap::new();
    let (mut chains, mut separators) = (0, 0);
    for c in cases {
        let (vp, vq) = polygons(c);
        let (p, q) = (
            SimplePolygon::try_new(&vp).expect("simple"),
            SimplePolygon::try_new(&vq).expect("simple"),
        );
        match separation::<Robust>(&p, &q) {
            Ok(PolygonSeparation::Separated {
                route: Route::SeparableChains | Route::EnvelopeSweep,
                ..
            }) => chains += 1,
            Ok(PolygonSeparation::Separated {
                route: Route::Separators,
                ..
            }) => separators += 1,
            _ => {}
        }
        let mut results = vec![
            (
                "Robust separation",
                check::<Robust>(&p, &q, c, Method::Auto),
            ),
            ("Exact separation", check::<Exact>(&p, &q, c, Method::Auto)),
            (
                "Robust section 3's matrices",
                check::<Robust>(&p, &q, c, Method::Matrices),
            ),
        ];
        if vp.len() * vq.len() <= BRUTE_MAX {
            results.push((
                "Robust brute force",
                check::<Robust>(&p, &q, c, Method::Brute),
            ));
        }
        for (name, r) in results {
            if let Some(why) = r {
                failures.push(format!("{name} {}/{}: {why}", c.family, c.name));
            }
        }
        if check::<Fast>(&p, &q, c, Method::Auto).is_some() {
            *fast_wrong.entry(c.family.as_str()).or_default() += 1;
        }
    }
    eprintln!(
        "Fast kernel, wrong separations: {} of {}, by family: {fast_wrong:?}",
        fast_wrong.values().sum::<usize>(),
        cases.len()
    );
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    (chains, separators)
}
