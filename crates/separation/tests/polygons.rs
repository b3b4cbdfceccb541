//! Whole simple polygons: the intersection check, the disjoint-hull fast path of `separation`, and
//! point/segment–polygon distances, against the brute-force twins and the exact oracle.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_oracle::{
    Contact, SplitMix64, boundary_distance, chain_distance, comb, contact_status_convex,
    contact_status_simple, spiral, star, two_opt, ulps_error_sqrt,
};
use polydist_polygon::predicates::{Dist2, Exact, Fast, Kernel, Robust};
use polydist_polygon::{Feature, Location, SimplePolygon};
use polydist_separation::{
    Chain, HullRouteMethod, Intersection, PolygonSeparation, Route, SeparationError, intersection,
    point_to_polygon, polygon_separation_brute, polyline_to_polygon, segment_to_polygon,
    separation, separation_brute, separation_of_disjoint, separation_of_disjoint_with,
};
use proptest::prelude::*;

mod common;
use common::pairs::{bbox, check_optimal, oracle_feature, place_beside};

/// A random simple polygon of one of the generator families, scaled and moved by dyadic amounts
/// (exact), with about `n` vertices.
fn shape(rng: &mut SplitMix64, n: usize) -> Vec<DVec2> {
    let n = n.max(4);
    match rng.below(4) {
        0 => star(rng, n, n / 4),
        1 => two_opt(rng, n.min(60)),
        2 => {
            let turns = 1 + rng.below(2) as u32;
            let per_turn = (n as u32 / (2 * turns)).clamp(3, 64);
            spiral(per_turn, turns)
        }
        _ => {
            let teeth = (n / 4).clamp(1, 30);
            comb(teeth, 1 + rng.below(5) as u32, 1 + rng.below(3) as u32)
        }
    }
}

/// Checks one pair: the intersection check against the oracle and the brute force, and when the
/// polygons are disjoint, `separation` against the oracle (exact optimal features, distance within
/// 3.5 ulps), whatever the hulls do (disjoint, interlocked, nested, pinched).
fn check_pair<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Result<(), TestCaseError> {
    let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(p), SimplePolygon::try_new(q)) else {
        return Ok(());
    };
    // The oracle's simplicity check refuses repeated vertices: give it the cleaned rings.
    let meets = contact_status_simple(sp.vertices(), sq.vertices()) != Contact::Disjoint;
    prop_assert_eq!(intersection::<K>(&sp, &sq).is_some(), meets);
    prop_assert_eq!(
        sp.first_boundary_contact(&sq).is_some(),
        sp.first_boundary_contact_brute(&sq).is_some()
    );
    let brute = polygon_separation_brute::<K>(&sp, &sq).expect("brute force answers");
    match separation::<K>(&sp, &sq) {
        Ok(PolygonSeparation::Intersecting(_)) => {
            prop_assert!(meets);
            prop_assert!(matches!(brute, PolygonSeparation::Intersecting(_)));
        }
        Ok(PolygonSeparation::Separated { pair, .. }) => {
            prop_assert!(!meets);
            let exact = boundary_distance(p, q);
            check_optimal(&exact, &pair)?;
            let PolygonSeparation::Separated { pair: b, .. } = brute else {
                return Err(TestCaseError::fail("brute force says intersecting"));
            };
            prop_assert!(
                exact.is_optimal_pair(oracle_feature(b.feature_p), oracle_feature(b.feature_q))
            );
        }
        Err(e) => return Err(TestCaseError::fail(format!("unexpected error {e}"))),
    }
    Ok(())
}

/// Random placements of random shapes: beside each other (disjoint hulls, gaps from 0 to large),
/// overlapping, and one inside the other.
fn random_case(seed: u64) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(seed);
    let n = 4 + rng.index(40);
    let m = 4 + rng.index(40);
    let p = shape(&mut rng, n);
    let q = shape(&mut rng, m);
    let axis = rng.index(2);
    let dir = if rng.coin() { 1.0 } else { -1.0 };
    let (lo, hi) = bbox(&p);
    let extent = (hi - lo).max_element();
    let gap = match rng.below(6) {
        0 => 0.0,
        1 => extent * 2f64.powi(-30),
        2 => extent * 0.125,
        3 => extent * 4.0,
        4 => -extent * 0.25,
        _ => -extent,
    };
    let slide = rng.range_i64(-4, 5) as f64 * 0.25;
    let q = place_beside(&p, &q, axis, dir, gap, slide);
    (p, q)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_pairs_robust(seed in any::<u64>()) {
        let (p, q) = random_case(seed);
        check_pair::<Robust>(&p, &q)?;
    }

    #[test]
    fn interlocked_pairs_robust(seed in any::<u64>()) {
        let (p, q) = interlocked_case(seed);
        check_pair::<Robust>(&p, &q)?;
    }

    #[test]
    fn interlocked_pairs_exact(seed in any::<u64>()) {
        let (p, q) = interlocked_case(seed);
        check_pair::<Exact>(&p, &q)?;
    }

    #[test]
    fn pocket_pairs_robust(seed in any::<u64>()) {
        if let Some((p, q)) = pocket_case(seed) {
            check_pair::<Robust>(&p, &q)?;
        }
    }

    #[test]
    fn pocket_pairs_exact(seed in any::<u64>()) {
        if let Some((p, q)) = pocket_case(seed) {
            check_pair::<Exact>(&p, &q)?;
        }
    }

    #[test]
    fn pocket_pairs_far_from_origin(seed in any::<u64>()) {
        if let Some((p, q)) = pocket_case(seed) {
            let o = DVec2::new(1e12, 1e12);
            let (p, q): (Vec<DVec2>, Vec<DVec2>) = (p.iter().map(|&v| v + o).collect(), q.iter().map(|&v| v + o).collect());
            check_pair::<Robust>(&p, &q)?;
        }
    }

    #[test]
    fn interlocked_pairs_far_from_origin(seed in any::<u64>()) {
        let (p, q) = interlocked_case(seed);
        let o = DVec2::new(-1e12, 1e12);
        let (p, q): (Vec<DVec2>, Vec<DVec2>) = (p.iter().map(|&v| v + o).collect(), q.iter().map(|&v| v + o).collect());
        check_pair::<Robust>(&p, &q)?;
    }

    #[test]
    fn random_pairs_far_from_origin(seed in any::<u64>()) {
        let (p, q) = random_case(seed);
        let o = DVec2::new(1e12, -1e12);
        let (p, q): (Vec<DVec2>, Vec<DVec2>) = (p.iter().map(|&v| v + o).collect(), q.iter().map(|&v| v + o).collect());
        check_pair::<Robust>(&p, &q)?;
    }

    #[test]
    fn point_against_random_polygons(seed in any::<u64>(), fx in -2.0f64..2.0, fy in -2.0f64..2.0) {
        let mut rng = SplitMix64::new(seed);
        let n = 4 + rng.index(40);
        let p = shape(&mut rng, n);
        let sp = SimplePolygon::try_new(&p).expect("generators are simple");
        let (lo, hi) = bbox(&p);
        // A point in or around the box, sometimes a vertex or an edge midpoint exactly.
        let x = match rng.below(4) {
            0 => p[rng.index(p.len())],
            1 => {
                let i = rng.index(p.len());
                (p[i] + p[(i + 1) % p.len()]) * 0.5
            }
            _ => lo + (hi - lo) * DVec2::new(fx, fy),
        };
        for d in [point_to_polygon::<Robust>(x, &sp).unwrap(), point_to_polygon::<Exact>(x, &sp).unwrap()] {
            let exact = boundary_distance(&[x], &p);
            prop_assert!(exact.is_optimal_pair(polydist_oracle::Feature::Vertex(0), oracle_feature(d.boundary.feature)));
            prop_assert!(ulps_error_sqrt(d.boundary.distance, &exact.sq) <= 3.5);
            prop_assert_eq!(d.location, sp.locate(x));
            prop_assert_eq!(d.location == Location::Boundary, d.boundary.distance == 0.0);
        }
    }

    #[test]
    fn segment_against_random_polygons(seed in any::<u64>(), f in proptest::array::uniform4(-2.0f64..3.0)) {
        let mut rng = SplitMix64::new(seed);
        let n = 4 + rng.index(40);
        let p = shape(&mut rng, n);
        let sp = SimplePolygon::try_new(&p).expect("generators are simple");
        let (lo, hi) = bbox(&p);
        let at = |u: f64, v: f64| lo + (hi - lo) * DVec2::new(u, v);
        let (a, b) = match rng.below(4) {
            0 => (p[rng.index(p.len())], at(f[2], f[3])),
            1 => (at(f[0], f[1]), at(f[0], f[1])),
            _ => (at(f[0], f[1]), at(f[2], f[3])),
        };
        let exact = boundary_distance(&[a, b], &p);
        for s in [segment_to_polygon::<Robust>(a, b, &sp).unwrap(), segment_to_polygon::<Exact>(a, b, &sp).unwrap()] {
            match s {
                PolygonSeparation::Separated { pair, .. } => {
                    prop_assert!(sp.locate(a) == Location::Outside);
                    prop_assert!(exact.is_optimal_pair(oracle_feature(pair.feature_p), oracle_feature(pair.feature_q)));
                    prop_assert!(ulps_error_sqrt(pair.distance, &exact.sq) <= 3.5);
                    prop_assert!(pair.distance > 0.0);
                }
                PolygonSeparation::Intersecting(Intersection::Boundaries { .. }) => {
                    prop_assert!(num_traits::Zero::is_zero(&exact.sq));
                }
                PolygonSeparation::Intersecting(Intersection::Contained { .. }) => {
                    prop_assert!(!num_traits::Zero::is_zero(&exact.sq));
                    prop_assert_eq!(sp.locate(a), Location::Inside);
                }
            }
        }
    }

    /// Random and degenerate polylines (repeats, collinear vertices, one or two vertices, far from
    /// the origin) against random polygons beside them.
    #[test]
    fn polylines_against_polygons_proptest(seed in any::<u64>()) {
        let (t, q, touching) = polyline_case(seed);
        check_polyline::<Robust>(&t, &q, touching)?;
    }

    /// Arbitrary coordinates never panic, under Robust and Fast.
    #[test]
    fn arbitrary_points_never_panic(x in proptest::num::f64::ANY, y in proptest::num::f64::ANY, seed in any::<u64>()) {
        let mut rng = SplitMix64::new(seed);
        let p = shape(&mut rng, 12);
        let sp = SimplePolygon::try_new(&p).expect("generators are simple");
        let z = DVec2::new(x, y);
        let _ = point_to_polygon::<Robust>(z, &sp);
        let _ = point_to_polygon::<Fast>(z, &sp);
        let _ = segment_to_polygon::<Robust>(z, p[0], &sp);
        let _ = segment_to_polygon::<Fast>(p[1], z, &sp);
        let _ = polyline_to_polygon::<Robust>(&[p[0], z, p[2], z], &sp);
        let _ = polyline_to_polygon::<Fast>(&[z, p[1], z], &sp);
    }
}

/// A random open simple polyline and a random polygon beside it (bounding boxes `gap` apart, the gap
/// 0 in one case of four, so that the hulls may touch), with the degenerate features section 3 must
/// take: repeated vertices, collinear vertices (edge midpoints, exact on these dyadic inputs), one or
/// two vertices; moved far from the origin in one case of four. Returns `(T, Q, the boxes touch)`.
fn polyline_case(seed: u64) -> (Vec<DVec2>, Vec<DVec2>, bool) {
    let mut rng = SplitMix64::new(seed);
    let n = 4 + rng.index(40);
    let ring = shape(&mut rng, n);
    // An open cyclic sub-chain of a simple ring is a simple polyline.
    let len = 1 + rng.index(ring.len());
    let start = rng.index(ring.len());
    let mut t: Vec<DVec2> = (0..len).map(|k| ring[(start + k) % ring.len()]).collect();
    match rng.below(4) {
        0 => {
            let k = rng.index(t.len());
            t.insert(k, t[k]);
        }
        1 if t.len() >= 2 => {
            let k = rng.index(t.len() - 1);
            t.insert(k + 1, (t[k] + t[k + 1]) * 0.5);
        }
        _ => {}
    }
    let m = 4 + rng.index(40);
    let mut q = shape(&mut rng, m);
    // The polygon's caller vertices differ from its internal ones (a collinear vertex or a repeat,
    // both dropped by `SimplePolygon`), so that features must be mapped back.
    let k = rng.index(q.len());
    match rng.below(3) {
        0 => q.insert(k + 1, (q[k] + q[(k + 1) % q.len()]) * 0.5),
        1 => q.insert(k, q[k]),
        _ => {}
    }
    let (lo, hi) = bbox(&t);
    let extent = (hi - lo).max_element().max(1.0);
    let gap = match rng.below(4) {
        0 => 0.0,
        1 => extent * 2f64.powi(-30),
        2 => extent * 0.125,
        _ => extent * 4.0,
    };
    let slide = rng.range_i64(-4, 5) as f64 * 0.25;
    let q = place_beside(
        &t,
        &q,
        rng.index(2),
        if rng.coin() { 1.0 } else { -1.0 },
        gap,
        slide,
    );
    let (t, q) = if rng.below(4) == 0 {
        let o = DVec2::new(1e12, -1e12);
        let far = |v: Vec<DVec2>| v.into_iter().map(|z| z + o).collect::<Vec<_>>();
        (far(t), far(q))
    } else {
        (t, q)
    };
    // Far from the origin a tiny gap rounds away: whether the boxes are apart is read off the
    // final coordinates.
    let ((tl, th), (ql, qh)) = (bbox(&t), bbox(&q));
    let apart = th.x < ql.x || qh.x < tl.x || th.y < ql.y || qh.y < tl.y;
    (t, q, !apart)
}

/// One polyline case under `K`: an exact optimum of the oracle's open-chain distance (the polygon
/// passed as the closed chain of its caller vertices, so that its caller features are the chain's),
/// the distance within 3.5 ulps, the brute-force twin optimal too; `PolylineHullsMeet` only where
/// the boxes touch. Returns the route that answered, `None` when refused.
fn check_polyline<K: Kernel>(
    t: &[DVec2],
    q: &[DVec2],
    touching: bool,
) -> Result<Option<Route>, TestCaseError> {
    let Ok(sq) = SimplePolygon::try_new(q) else {
        return Ok(None);
    };
    let mut closed = q.to_vec();
    closed.push(q[0]);
    match polyline_to_polygon::<K>(t, &sq) {
        Ok(PolygonSeparation::Separated { pair, route, .. }) => {
            prop_assert!(matches!(
                route,
                Route::SeparableChains
                    | Route::EnvelopeSweep
                    | Route::MonotoneSweep
                    | Route::HullFeatures
                    | Route::Scan
            ));
            let exact = chain_distance(t, &closed);
            check_optimal(&exact, &pair)?;
            let b = separation_brute::<K>(t, &closed).expect("brute force answers");
            prop_assert!(
                exact.is_optimal_pair(oracle_feature(b.feature_p), oracle_feature(b.feature_q))
            );
            Ok(Some(route))
        }
        Ok(PolygonSeparation::Intersecting(_)) => {
            // Only a segment is checked for contact, and only touching boxes can meet.
            prop_assert!(touching && t.len() == 2);
            prop_assert!(num_traits::Zero::is_zero(&chain_distance(t, &closed).sq));
            Ok(None)
        }
        Err(SeparationError::PolylineHullsMeet) => {
            prop_assert!(t.len() != 2, "a segment is always answered");
            prop_assert!(touching, "hulls of boxes apart said to meet");
            Ok(None)
        }
        other => Err(TestCaseError::fail(format!(
            "unexpected {other:?}: T = {t:?}, Q = {q:?}"
        ))),
    }
}

#[test]
fn polylines_against_polygons() {
    let (mut hull, mut chains, mut swept, mut refused) = (0, 0, 0, 0);
    for seed in 0..400 {
        let (t, q, touching) = polyline_case(seed);
        let got = check_polyline::<Robust>(&t, &q, touching)
            .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        check_polyline::<Exact>(&t, &q, touching).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        match got {
            Some(Route::HullFeatures) => hull += 1,
            Some(Route::MonotoneSweep) => swept += 1,
            Some(_) => chains += 1,
            None => refused += 1,
        }
        // The Fast kernel only has to terminate.
        if let Ok(sq) = SimplePolygon::try_new(&q) {
            let _ = polyline_to_polygon::<Fast>(&t, &sq);
        }
    }
    // Every outcome occurs: boxes apart are answered (by the hulls' pair, the monotone sweep or
    // section 3), and some touching boxes have meeting hulls.
    eprintln!("hull features {hull}, sweep {swept}, section 3 {chains}, refused {refused}");
    assert!(
        hull >= 50 && chains >= 50 && refused >= 10,
        "hull features {hull}, sweep {swept}, section 3 {chains}, refused {refused}"
    );
}

/// A monotone zig-zag toolpath (`x` non-decreasing, vertical steps included, heights on a lattice
/// of quarters) under a polygon whose bottom is another such zig-zag, `gap` above the path's top,
/// both turned by a lattice symmetry; the polyline possibly reversed.
fn monotone_polyline_case(seed: u64) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(seed);
    let zigzag = |rng: &mut SplitMix64, k: usize, lo: i64, hi: i64| -> Vec<DVec2> {
        // Never two vertical steps in a row (they could fold back over each other).
        let (mut x, mut step) = (0.0, 1.0);
        (0..k)
            .map(|_| {
                step = if step == 0.0 {
                    1.0
                } else {
                    rng.below(3) as f64
                };
                x += step * 0.5;
                DVec2::new(x, rng.range_i64(lo, hi) as f64 * 0.25)
            })
            .collect()
    };
    let k = 3 + rng.index(30);
    let mut t = zigzag(&mut rng, k, 0, 5);
    t.dedup();
    let gap = [0.25, 1.0, 0.0078125, 3.0][rng.index(4)];
    let m = 3 + rng.index(30);
    let mut bottom = zigzag(&mut rng, m, 0, 5);
    bottom.dedup();
    // Counter-clockwise: the bottom left to right, `gap` above the path (heights 0 to 1.25), then
    // the top right to left. (A vertical step at either end folds the ring back: refused, skipped.)
    let (x0, x1) = (bottom[0].x, bottom[bottom.len() - 1].x);
    let mut q: Vec<DVec2> = bottom
        .iter()
        .map(|v| DVec2::new(v.x, v.y + 1.25 + gap))
        .collect();
    q.push(DVec2::new(x1 + 1.0, 4.0 + gap));
    q.push(DVec2::new(x0 - 1.0, 4.0 + gap));
    let s = rng.below(8);
    let map = |v: DVec2| {
        let v = if s & 4 != 0 { DVec2::new(v.y, v.x) } else { v };
        DVec2::new(
            if s & 1 != 0 { -v.x } else { v.x },
            if s & 2 != 0 { -v.y } else { v.y },
        )
    };
    let mut t: Vec<DVec2> = t.into_iter().map(map).collect();
    let q: Vec<DVec2> = q.into_iter().map(map).collect();
    if rng.coin() {
        t.reverse();
    }
    (t, q)
}

/// Monotone toolpaths under zig-zag polygons: the monotone sweep answers most of them, exactly
/// optimal against the oracle under Robust and Exact (as every other route is checked).
#[test]
fn monotone_polylines_take_the_sweep() {
    let (mut swept, mut other) = (0, 0);
    for seed in 0..300 {
        let (t, q) = monotone_polyline_case(seed);
        match check_polyline::<Robust>(&t, &q, false).unwrap_or_else(|e| panic!("seed {seed}: {e}"))
        {
            Some(Route::MonotoneSweep) => swept += 1,
            _ => other += 1,
        }
        check_polyline::<Exact>(&t, &q, false).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
    }
    eprintln!("monotone sweep {swept}, other routes {other}");
    assert!(swept >= 120, "monotone sweep {swept}, other routes {other}");
}

#[test]
fn polyline_errors_say_what_and_where() {
    let sq =
        SimplePolygon::try_from(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][..]).unwrap();
    assert_eq!(
        polyline_to_polygon::<Robust>(&[], &sq),
        Err(SeparationError::EmptyChain { chain: Chain::P })
    );
    let bad = [
        DVec2::new(-2.0, 0.0),
        DVec2::new(-3.0, 0.0),
        DVec2::new(f64::NAN, 0.0),
    ];
    assert_eq!(
        polyline_to_polygon::<Robust>(&bad, &sq),
        Err(SeparationError::InvalidCoordinate {
            chain: Chain::P,
            index: 2
        })
    );
    // Around the square (hulls meet) and through it.
    let around = [
        DVec2::new(-1.0, -1.0),
        DVec2::new(2.0, -1.0),
        DVec2::new(2.0, 2.0),
        DVec2::new(-1.0, 2.0),
    ];
    assert_eq!(
        polyline_to_polygon::<Robust>(&around, &sq),
        Err(SeparationError::PolylineHullsMeet)
    );
    let through = [
        DVec2::new(-1.0, 0.5),
        DVec2::new(0.5, 0.5),
        DVec2::new(2.0, 0.5),
    ];
    assert_eq!(
        polyline_to_polygon::<Exact>(&through, &sq),
        Err(SeparationError::PolylineHullsMeet)
    );
    // A segment is always answered, through the segment scan.
    let segment = [DVec2::new(-1.0, 0.5), DVec2::new(2.0, 0.5)];
    assert!(matches!(
        polyline_to_polygon::<Robust>(&segment, &sq),
        Ok(PolygonSeparation::Intersecting(_))
    ));
    let beside = [DVec2::new(-1.0, 0.5), DVec2::new(0.5, 2.0)];
    let Ok(PolygonSeparation::Separated { route, .. }) =
        polyline_to_polygon::<Robust>(&beside, &sq)
    else {
        panic!("a segment beside the square");
    };
    assert_eq!(route, Route::Scan);
    // A polyline crossing itself is reported when section 3 meets the crossing.
    let bow = [
        DVec2::new(-3.0, 0.0),
        DVec2::new(-2.0, 1.0),
        DVec2::new(-2.0, 0.0),
        DVec2::new(-3.0, 1.0),
    ];
    assert!(matches!(
        polyline_to_polygon::<Robust>(&bow, &sq),
        Ok(PolygonSeparation::Separated { .. })
            | Err(SeparationError::NotSimple {
                chain: Chain::P,
                ..
            })
    ));
    // One vertex and a degenerate (collinear) polyline: hulls that are a point and a segment.
    let point = [DVec2::new(-1.0, 0.5)];
    assert_eq!(
        polyline_to_polygon::<Robust>(&point, &sq)
            .unwrap()
            .distance(),
        1.0
    );
    let line = [
        DVec2::new(-3.0, 0.25),
        DVec2::new(-2.0, 0.25),
        DVec2::new(-0.5, 0.25),
    ];
    let s = polyline_to_polygon::<Robust>(&line, &sq).unwrap();
    let PolygonSeparation::Separated { pair, .. } = s else {
        panic!("disjoint")
    };
    assert_eq!(
        (pair.distance, pair.feature_p, pair.feature_q),
        (0.5, Feature::Vertex(2), Feature::Edge(3))
    );
}

/// Both routes of the fast path run on the random family (a guard against a generator that never
/// reaches section 3), and where section 3 answers, its matrices alone
/// (`HullRouteMethod::Section3`) find the same exact distance as its envelope sweep.
#[test]
fn both_routes_are_exercised() {
    let (mut hulls, mut chains, mut swept) = (0, 0, 0);
    for seed in 0..200 {
        let (p, q) = random_case(seed);
        let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(&p), SimplePolygon::try_new(&q)) else {
            continue;
        };
        match separation::<Robust>(&sp, &sq) {
            Ok(PolygonSeparation::Separated {
                route: Route::HullFeatures,
                ..
            }) => hulls += 1,
            Ok(PolygonSeparation::Separated {
                pair,
                route: route @ (Route::SeparableChains | Route::EnvelopeSweep),
                ..
            }) => {
                chains += 1;
                swept += usize::from(route == Route::EnvelopeSweep);
                let Ok(PolygonSeparation::Separated {
                    pair: m,
                    route: Route::SeparableChains,
                    ..
                }) = separation_of_disjoint_with::<Robust>(&sp, &sq, HullRouteMethod::Section3)
                else {
                    panic!("seed {seed}: section 3's matrices")
                };
                let exact = boundary_distance(&p, &q);
                for (what, got) in [("swept", &pair), ("matrices", &m)] {
                    check_optimal(&exact, got)
                        .unwrap_or_else(|e| panic!("seed {seed} ({what}): {e}"));
                }
            }
            _ => {}
        }
    }
    assert!(
        hulls >= 10 && chains >= 10 && swept * 2 >= chains,
        "hull route {hulls}, section 3 {chains} (its envelope sweep {swept})"
    );
}

#[test]
fn exact_kernel_agrees_on_random_pairs() {
    for seed in 0..40 {
        let (p, q) = random_case(seed);
        check_pair::<Exact>(&p, &q).unwrap();
    }
}

/// `separation_of_disjoint` does not check its precondition: on polygons that meet (random
/// overlapping placements, one inside the other, interlocked shapes pushed through each other) its
/// answer is unspecified, but it returns under every kernel without panicking.
#[test]
fn separation_of_disjoint_on_meeting_polygons_never_panics() {
    let mut meeting = 0;
    for seed in 0..400 {
        for (p, q) in [random_case(seed), interlocked_case(seed)] {
            let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(&p), SimplePolygon::try_new(&q)) else {
                continue;
            };
            if intersection::<Robust>(&sp, &sq).is_none() {
                continue;
            }
            meeting += 1;
            let _ = separation_of_disjoint::<Robust>(&sp, &sq);
            let _ = separation_of_disjoint::<Exact>(&sp, &sq);
            let _ = separation_of_disjoint::<Fast>(&sp, &sq);
        }
    }
    assert!(meeting >= 100, "{meeting}");
}

#[test]
fn fast_kernel_terminates() {
    for seed in 0..200 {
        let (p, q) = random_case(seed);
        let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(&p), SimplePolygon::try_new(&q)) else {
            continue;
        };
        let _ = separation::<Fast>(&sp, &sq);
        let (p, q) = interlocked_case(seed);
        let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(&p), SimplePolygon::try_new(&q)) else {
            continue;
        };
        let _ = separation::<Fast>(&sp, &sq);
    }
}

/// Touching at a shared vertex, along an edge, one vertex on the other's edge, one polygon in the
/// other, and a gap of one ulp.
#[test]
fn touching_contained_and_nearly_touching() {
    let sq = |x: f64, y: f64, s: f64| {
        vec![
            DVec2::new(x, y),
            DVec2::new(x + s, y),
            DVec2::new(x + s, y + s),
            DVec2::new(x, y + s),
        ]
    };
    let a = sq(0.0, 0.0, 1.0);
    let cases: Vec<(Vec<DVec2>, bool)> = vec![
        (sq(1.0, 1.0, 1.0), true), // shared vertex
        (sq(1.0, 0.5, 1.0), true), // along an edge
        (
            vec![
                DVec2::new(1.0, 0.5),
                DVec2::new(2.0, 0.0),
                DVec2::new(2.0, 1.0),
            ],
            true,
        ), // vertex on an edge
        (sq(0.25, 0.25, 0.5), true), // inside
        (sq(-1.0, -1.0, 3.0), true), // around
        (sq(1.0f64.next_up(), 0.5, 1.0), false), // one ulp away
        (sq(1.0f64.next_up(), 1.0f64.next_up(), 1.0), false),
    ];
    for (b, meets) in cases {
        let (pa, pb) = (
            SimplePolygon::try_new(&a).unwrap(),
            SimplePolygon::try_new(&b).unwrap(),
        );
        assert_eq!(intersection::<Robust>(&pa, &pb).is_some(), meets, "{b:?}");
        assert_eq!(intersection::<Robust>(&pb, &pa).is_some(), meets, "{b:?}");
        assert_eq!(contact_status_simple(&a, &b) != Contact::Disjoint, meets);
        if !meets {
            check_pair::<Robust>(&a, &b).unwrap();
            check_pair::<Exact>(&b, &a).unwrap();
        }
    }
}

/// Interlocked shapes (hulls meet, polygons disjoint) are refused with the typed error, not answered
/// by a brute force.
#[test]
fn interlocked_combs_go_through_the_separator() {
    for (teeth, len, gap) in [(6, 5, 0.125), (1, 1, 0.2), (40, 3, 1e-9)] {
        let pair = polydist_oracle::interleaved_combs(teeth, len, gap);
        let (p, q) = (
            SimplePolygon::try_new(&pair.a).unwrap(),
            SimplePolygon::try_new(&pair.b).unwrap(),
        );
        assert_eq!(intersection::<Robust>(&p, &q), None);
        for (a, b) in [(&p, &q), (&q, &p)] {
            let Ok(PolygonSeparation::Separated {
                pair: s,
                route,
                stats,
            }) = separation::<Robust>(a, b)
            else {
                panic!("the combs are disjoint")
            };
            assert_eq!(route, Route::Separators);
            assert!(stats.separator_segments >= 1);
            assert_eq!(s.distance, pair.gap);
        }
        check_pair::<Robust>(&pair.a, &pair.b).unwrap();
        check_pair::<Exact>(&pair.b, &pair.a).unwrap();
    }
    for ulps in [1, 4, 1000] {
        let pair = polydist_oracle::interleaved_combs_ulps(9, 4, ulps);
        check_pair::<Robust>(&pair.a, &pair.b).unwrap();
    }
}

/// Two random stars of 400 vertices (a spike every fourth) pushed into each other: their
/// separators' lines pass through many spikes, so some subproblems cross their line many times.
/// As shipped, their ends far from the other subchain and from `l_i` are trimmed first
/// (`near_ends`), and what is left goes to pairs of runs, thin scans or section 3 on the clipped
/// subchains (Step G; reached end to end with every subproblem offered to section 3 in the
/// separator's `interlocked_stars_reach_clipped_chains`). The reported features are exactly as
/// near as the brute force's, under Robust and Exact.
#[test]
fn interlocked_stars_agree_with_the_brute_force() {
    let (mut cases, mut gapped, mut large) = (0, 0, 0);
    for seed in 0..12u64 {
        let mut rng = SplitMix64::new(seed);
        let p = star(&mut rng, 400, 100);
        let q0 = star(&mut rng, 400, 100);
        let radius = |v: &[DVec2]| v.iter().map(|x| x.length()).fold(0.0, f64::max);
        let sp = SimplePolygon::try_new(&p).unwrap();
        for _ in 0..32 {
            let t = 0.3 + 0.6 * rng.unit_f64();
            let ang = core::f64::consts::TAU * rng.unit_f64();
            let d = DVec2::new(ang.cos(), ang.sin()) * (radius(&p) + radius(&q0)) * t;
            let q: Vec<DVec2> = q0.iter().map(|&v| v + d).collect();
            let sq = SimplePolygon::try_new(&q).unwrap();
            let Ok(PolygonSeparation::Separated {
                pair,
                route: Route::Separators,
                stats,
            }) = separation::<Robust>(&sp, &sq)
            else {
                continue;
            };
            cases += 1;
            gapped += stats.subproblem_parts_gapped;
            large += stats.subproblems_scanned_large;
            let Ok(PolygonSeparation::Separated { pair: brute, .. }) =
                polygon_separation_brute::<Robust>(&sp, &sq)
            else {
                panic!("seed {seed}: the brute force says intersecting");
            };
            let dist = |fp: Feature, fq: Feature| match (fp, fq) {
                (Feature::Vertex(i), Feature::Vertex(j)) => Dist2::PointPoint(p[i], q[j]),
                (Feature::Vertex(i), Feature::Edge(j)) => {
                    Dist2::PointSegment(p[i], q[j], q[(j + 1) % q.len()])
                }
                (Feature::Edge(i), Feature::Vertex(j)) => {
                    Dist2::PointSegment(q[j], p[i], p[(i + 1) % p.len()])
                }
                _ => unreachable!("a closest pair has a vertex"),
            };
            let want = dist(brute.feature_p, brute.feature_q);
            assert_eq!(
                Robust::cmp_dist2(dist(pair.feature_p, pair.feature_q), want),
                Ordering::Equal,
                "seed {seed}"
            );
            let Ok(PolygonSeparation::Separated { pair, .. }) = separation::<Exact>(&sp, &sq)
            else {
                panic!("seed {seed}: Exact finds the stars intersecting");
            };
            assert_eq!(
                Exact::cmp_dist2(dist(pair.feature_p, pair.feature_q), want),
                Ordering::Equal,
                "seed {seed}, Exact"
            );
            break;
        }
    }
    // The trims leave these stars no subproblem for Step G and no large scan.
    assert!(
        cases >= 6 && gapped == 0 && large == 0,
        "{cases} cases, {gapped} gapped parts, {large} large scans"
    );
}

/// Two shapes of the generator families pushed into each other: `Q` scaled by `2^−k` (exact), its
/// centre put at a random direction and 10 to 70 % of the sum of the radii from `P`'s. Up to 32
/// placements are drawn; the first whose polygons are disjoint while their hulls meet is returned
/// (the separator's route, or `HullsIntersect` when one hull contains the other), else the last.
fn interlocked_case(seed: u64) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(seed);
    let n = 4 + rng.index(60);
    let m = 4 + rng.index(60);
    let p = shape(&mut rng, n);
    let q0 = shape(&mut rng, m);
    let centre = |v: &[DVec2]| {
        let (lo, hi) = bbox(v);
        (lo + hi) * 0.5
    };
    let radius = |v: &[DVec2], c: DVec2| v.iter().map(|&x| (x - c).length()).fold(0.0, f64::max);
    let cp = centre(&p);
    let sp = SimplePolygon::try_new(&p).ok();
    let mut q = Vec::new();
    for _ in 0..32 {
        let scale = 0.5f64.powi(rng.below(4) as i32);
        let cq = centre(&q0);
        let t = 0.1 + 0.6 * rng.unit_f64();
        let ang = core::f64::consts::TAU * rng.unit_f64();
        let d = DVec2::new(ang.cos(), ang.sin()) * (radius(&p, cp) + scale * radius(&q0, cq)) * t;
        let shift = cp + d;
        q = q0.iter().map(|&v| (v - cq) * scale + shift).collect();
        let (Some(sp), Ok(sq)) = (sp.as_ref(), SimplePolygon::try_new(&q)) else {
            continue;
        };
        let hulls_meet =
            contact_status_convex(sp.convex_hull().vertices(), sq.convex_hull().vertices())
                != Contact::Disjoint;
        if hulls_meet && intersection::<Robust>(sp, &sq).is_none() {
            break;
        }
    }
    (p, q)
}

/// A small shape dropped into a pocket of a comb or a spiral (its hull inside the other's), at a
/// random dyadic scale and place, retried until the two are disjoint; `None` when no try lands.
fn pocket_case(seed: u64) -> Option<(Vec<DVec2>, Vec<DVec2>)> {
    let mut rng = SplitMix64::new(seed ^ 0x70c4e7);
    let outer = if rng.coin() {
        comb(
            1 + rng.index(12),
            2 + rng.below(5) as u32,
            1 + rng.below(3) as u32,
        )
    } else {
        spiral(3 + rng.below(20) as u32, 1 + rng.below(3) as u32)
    };
    let n = 3 + rng.index(30);
    let spikes = rng.index(n + 1);
    let inner0 = star(&mut rng, n, spikes);
    let so = SimplePolygon::try_new(&outer).ok()?;
    let hull = so.convex_hull();
    let (lo, hi) = bbox(&outer);
    let (ilo, ihi) = bbox(&inner0);
    let ic = (ilo + ihi) * 0.5;
    for _ in 0..64 {
        let scale = (hi - lo).min_element() / (ihi - ilo).max_element()
            * 0.5f64.powi(2 + rng.below(5) as i32);
        let at = lo + (hi - lo) * DVec2::new(rng.unit_f64(), rng.unit_f64());
        let inner: Vec<DVec2> = inner0.iter().map(|&v| (v - ic) * scale + at).collect();
        let Ok(si) = SimplePolygon::try_new(&inner) else {
            continue;
        };
        let nested = inner
            .iter()
            .all(|&v| hull.locate_with::<Robust>(v) != Location::Outside);
        if nested && intersection::<Robust>(&si, &so).is_none() {
            return Some(if rng.coin() {
                (inner, outer)
            } else {
                (outer, inner)
            });
        }
    }
    None
}

/// The separator route is taken on most disjoint interlocked pairs.
#[test]
fn separator_route_is_exercised() {
    let (mut sep, mut other) = (0, 0);
    for seed in 0..300 {
        let (p, q) = interlocked_case(seed);
        let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(&p), SimplePolygon::try_new(&q)) else {
            continue;
        };
        match separation::<Robust>(&sp, &sq) {
            Ok(PolygonSeparation::Separated {
                route: Route::Separators,
                ..
            }) => sep += 1,
            Ok(PolygonSeparation::Separated { .. }) | Err(_) => other += 1,
            Ok(PolygonSeparation::Intersecting(_)) => {}
        }
    }
    assert!(sep >= 40, "separator route {sep}, other {other}");
}

/// Caller indices: a ring given clockwise, closed, with repeated and collinear vertices.
#[test]
fn caller_features_survive_cleaning() {
    // Clockwise square with a repeat at index 1 and a collinear vertex at index 3, closed at index 6.
    let p = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(0.0, 0.0),
        DVec2::new(0.0, 2.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(2.0, 2.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(0.0, 0.0),
    ];
    let q = vec![
        DVec2::new(1.5, 3.0),
        DVec2::new(3.0, 5.0),
        DVec2::new(0.0, 5.0),
    ];
    let (sp, sq) = (
        SimplePolygon::try_new(&p).unwrap(),
        SimplePolygon::try_new(&q).unwrap(),
    );
    let PolygonSeparation::Separated { pair, .. } = separation::<Robust>(&sp, &sq).unwrap() else {
        panic!("disjoint");
    };
    // Q's vertex (1.5, 3) is nearest to the caller's edge 3 (from (1, 2) to (2, 2)), at distance 1.
    assert_eq!(
        (pair.feature_p, pair.feature_q),
        (Feature::Edge(3), Feature::Vertex(0))
    );
    assert_eq!(pair.distance, 1.0);
    check_pair::<Robust>(&p, &q).unwrap();
}

/// Pocket cases land, and take the separator route.
#[test]
fn pocket_cases_are_generated_and_take_the_separator_route() {
    let mut landed = 0;
    for seed in 0..200 {
        let Some((p, q)) = pocket_case(seed) else {
            continue;
        };
        let (sp, sq) = (
            SimplePolygon::try_new(&p).unwrap(),
            SimplePolygon::try_new(&q).unwrap(),
        );
        let route = match separation::<Robust>(&sp, &sq) {
            Ok(PolygonSeparation::Separated { route, .. }) => route,
            other => panic!("seed {seed}: {other:?}"),
        };
        assert_eq!(route, Route::Separators, "seed {seed}");
        landed += 1;
    }
    assert!(landed >= 100, "only {landed} pocket cases");
}
