//! Agreement with the exact oracle and between twins: the sweep against brute force and the oracle's
//! `is_simple`, convex validation against `is_convex`, both point locations against the oracle's
//! exact `point_in_polygon`, Melkman's hull against Andrew's and against a brute-force hull.

mod common;

use common::{boundary_probes, dedup_ring, hull_vertices_brute_force, oracle_locate, sorted};
use glam::DVec2;
use polydist_oracle::{self as oracle, SplitMix64};
use polydist_polygon::{ConvexPolygon, PolygonError, SimplePolygon, convex_hull};
use proptest::prelude::*;

/// Generated simple polygons of every family, with a label for messages.
fn simple_family(seed: u64) -> Vec<(String, Vec<DVec2>)> {
    let mut rng = SplitMix64::new(seed);
    let mut out = vec![
        ("comb(6, 5, 1)".to_string(), oracle::comb(6, 5, 1)),
        ("comb(9, 1, 2)".to_string(), oracle::comb(9, 1, 2)),
        ("spiral(7, 3)".to_string(), oracle::spiral(7, 3)),
        ("spiral(3, 5)".to_string(), oracle::spiral(3, 5)),
    ];
    let combs = oracle::interleaved_combs(4, 3, 0.125);
    out.push(("interleaved a".to_string(), combs.a));
    out.push(("interleaved b".to_string(), combs.b));
    for n in [3, 4, 5, 8, 13, 40] {
        out.push((format!("star({n}, 0)"), oracle::star(&mut rng, n, 0)));
        out.push((format!("star({n}, 2)"), oracle::star(&mut rng, n, 2.min(n))));
        out.push((format!("two_opt({n})"), oracle::two_opt(&mut rng, n)));
    }
    out
}

/// Reversed, rotated, closed and with a repeated vertex: the same polygon as the caller may give it.
fn variants(ring: &[DVec2], rng: &mut SplitMix64) -> Vec<Vec<DVec2>> {
    let mut rev = ring.to_vec();
    rev.reverse();
    let mut rot = ring.to_vec();
    rot.rotate_left(rng.index(ring.len()));
    let mut closed = ring.to_vec();
    closed.push(ring[0]);
    let mut repeated = ring.to_vec();
    let k = rng.index(ring.len());
    repeated.insert(k, ring[k]);
    vec![ring.to_vec(), rev, rot, closed, repeated]
}

/// `SimplePolygon::try_new` and its brute-force twin agree with the oracle on `ring`, and a reported
/// intersection names caller edges that really meet.
fn check_simple_agreement(ring: &[DVec2]) -> Result<(), String> {
    let sweep = SimplePolygon::try_new(ring);
    let brute = SimplePolygon::try_new_brute_force(ring);
    let clean = dedup_ring(ring);
    let expected = clean.len() >= 3 && oracle::is_simple(&clean);
    if sweep.is_ok() != expected {
        return Err(format!(
            "sweep says {sweep:?}, oracle says simple = {expected} for {ring:?}"
        ));
    }
    match (&sweep, &brute) {
        (Ok(a), Ok(b)) if a == b => {}
        (
            Err(PolygonError::SelfIntersection { .. }),
            Err(PolygonError::SelfIntersection { .. }),
        ) => {}
        (Err(a), Err(b)) if a == b => {}
        _ => {
            return Err(format!(
                "sweep {sweep:?} and brute force {brute:?} disagree on {ring:?}"
            ));
        }
    }
    if let Err(PolygonError::SelfIntersection { edge_a, edge_b }) = sweep {
        let n = ring.len();
        let (a, b, c, d) = (
            ring[edge_a],
            ring[(edge_a + 1) % n],
            ring[edge_b],
            ring[(edge_b + 1) % n],
        );
        if edge_a >= edge_b || a == b || c == d || !oracle::segments_intersect(a, b, c, d) {
            return Err(format!(
                "reported edges {edge_a}, {edge_b} do not meet in {ring:?}"
            ));
        }
    }
    if let Ok(p) = &sweep {
        p.check_invariants()?;
        if oracle::signed_area(p.vertices()) <= oracle::signed_area(&[]) {
            return Err("not counter-clockwise".into());
        }
    }
    Ok(())
}

/// For a ring of at least two distinct points, all collinear: how many times it turns back (where
/// the lexicographic direction of consecutive edges flips). `None` when not all collinear.
fn collinear_reversals(clean: &[DVec2]) -> Option<usize> {
    let m = clean.len();
    if m < 2
        || clean
            .iter()
            .any(|&r| oracle::sign_orient(clean[0], clean[1], r).is_ne())
    {
        return None;
    }
    let forward =
        |i: usize| (clean[i].x, clean[i].y) < (clean[(i + 1) % m].x, clean[(i + 1) % m].y);
    Some(
        (0..m)
            .filter(|&i| forward(i) != forward((i + 1) % m))
            .count(),
    )
}

/// `ConvexPolygon::try_new` agrees with the oracle's `is_convex` on `ring`, and all-collinear rings
/// are segments exactly when they turn back only twice.
fn check_convex_agreement(ring: &[DVec2]) -> Result<(), String> {
    let got = ConvexPolygon::try_new(ring);
    let clean = dedup_ring(ring);
    match (collinear_reversals(&clean), &got) {
        (Some(2), Ok(p)) if p.len() == 2 => {}
        (Some(2), _) => {
            return Err(format!(
                "a back-and-forth collinear ring is not a segment: {got:?}"
            ));
        }
        (Some(_), Err(PolygonError::Spike { .. })) => {}
        (Some(_), _) => {
            return Err(format!(
                "a collinear ring turning back 4+ times is not a spike: {got:?}"
            ));
        }
        (None, _) => {}
    }
    let polygon = clean.len() >= 3 && oracle::is_convex(&clean);
    match &got {
        Ok(p) => {
            p.check_invariants()?;
            if (p.len() >= 3) != polygon {
                return Err(format!(
                    "accepted with {} vertices, oracle is_convex = {polygon} for {ring:?}",
                    p.len()
                ));
            }
            if p.len() < 3 {
                // A point or a segment: every caller point lies on it.
                if let Some(q) = ring.iter().find(|&&q| {
                    oracle_locate(q, p.vertices()) != polydist_polygon::Location::Boundary
                }) {
                    return Err(format!(
                        "{q} is not on the degenerate polygon {:?}",
                        p.vertices()
                    ));
                }
            } else {
                // The kept vertices are the strict hull vertices (brute force when small).
                let hull = if ring.len() <= 30 {
                    hull_vertices_brute_force(ring)
                } else {
                    sorted(convex_hull(ring).map_err(|e| e.to_string())?.vertices())
                };
                if sorted(p.vertices()) != hull || !oracle::is_strictly_convex(p.vertices()) {
                    return Err(format!(
                        "vertices {:?} are not the strict hull of {ring:?}",
                        p.vertices()
                    ));
                }
            }
        }
        Err(e) => {
            if polygon {
                return Err(format!(
                    "rejected ({e}) but the oracle says convex: {ring:?}"
                ));
            }
        }
    }
    Ok(())
}

/// Both locations agree with the oracle on `probes`.
fn check_locate(poly: &[DVec2], probes: &[DVec2]) -> Result<(), String> {
    let simple = SimplePolygon::try_new(poly).map_err(|e| e.to_string())?;
    let convex = ConvexPolygon::try_new(poly).ok();
    for &q in probes {
        let expected = oracle_locate(q, poly);
        if simple.locate(q) != expected {
            return Err(format!(
                "simple locate {q:?}: {:?}, oracle {expected:?}",
                simple.locate(q)
            ));
        }
        if let Some(c) = &convex {
            if c.locate(q) != expected {
                return Err(format!(
                    "convex locate {q:?}: {:?}, oracle {expected:?}",
                    c.locate(q)
                ));
            }
        }
    }
    Ok(())
}

/// Melkman's hull of `poly` has the vertices of Andrew's hull of its points, in the same order, and
/// names the caller's vertices.
fn check_hulls(ring: &[DVec2]) -> Result<(), String> {
    let poly = SimplePolygon::try_new(ring).map_err(|e| e.to_string())?;
    let melkman = poly.convex_hull();
    melkman.check_invariants()?;
    let andrew = convex_hull(ring).map_err(|e| e.to_string())?;
    andrew.check_invariants()?;
    if melkman.vertices() != andrew.vertices() {
        return Err(format!(
            "Melkman {:?} and Andrew {:?} differ",
            melkman.vertices(),
            andrew.vertices()
        ));
    }
    for i in 0..melkman.len() {
        if ring[melkman.source_index(i)] != melkman.vertices()[i]
            || ring[andrew.source_index(i)] != andrew.vertices()[i]
        {
            return Err(format!(
                "hull vertex {i} is not the caller's vertex it names"
            ));
        }
    }
    if ring.len() <= 60 && sorted(andrew.vertices()) != hull_vertices_brute_force(ring) {
        return Err(format!(
            "Andrew's hull {:?} is not the brute-force hull",
            andrew.vertices()
        ));
    }
    Ok(())
}

#[test]
fn generated_simple_polygons_are_accepted_in_every_form() {
    let mut rng = SplitMix64::new(7);
    for seed in 0..4 {
        for (name, ring) in simple_family(seed) {
            for v in variants(&ring, &mut rng) {
                check_simple_agreement(&v).unwrap_or_else(|e| panic!("{name}: {e}"));
                assert!(SimplePolygon::try_new(&v).is_ok(), "{name} rejected");
            }
        }
    }
}

#[test]
fn perturbed_polygons_agree_with_the_oracle() {
    // Move one vertex onto another vertex, onto an edge midpoint, or anywhere; swap two vertices:
    // crossings, touchings and overlaps, most of them not simple.
    let mut rng = SplitMix64::new(11);
    let mut rejected = 0;
    let mut total = 0;
    for seed in 0..6 {
        for (name, ring) in simple_family(100 + seed) {
            let n = ring.len();
            for _ in 0..6 {
                let mut v = ring.clone();
                let (i, j) = (rng.index(n), rng.index(n));
                match rng.index(4) {
                    0 => v[i] = ring[j],
                    1 => v[i] = (ring[j] + ring[(j + 1) % n]) * 0.5,
                    2 => v.swap(i, j),
                    _ => v[i] = ring[j] + (ring[(j + 1) % n] - ring[j]) * 2.0,
                }
                check_simple_agreement(&v).unwrap_or_else(|e| panic!("{name}: {e}"));
                total += 1;
                rejected += usize::from(SimplePolygon::try_new(&v).is_err());
            }
        }
    }
    assert!(
        rejected * 4 > total,
        "only {rejected} of {total} perturbations were rejected"
    );
}

#[test]
fn sweep_agrees_with_brute_force_on_large_perturbed_polygons() {
    // Too large for the rational oracle; the O(n²) twin decides. One vertex moved onto another
    // vertex, an edge's midpoint or beyond an edge's end, or two vertices swapped.
    let mut rng = SplitMix64::new(41);
    let rings = [
        oracle::star(&mut rng, 600, 30),
        oracle::spiral(12, 20),
        oracle::comb(120, 40, 1),
    ];
    for ring in rings {
        let n = ring.len();
        for trial in 0..12 {
            let mut v = ring.clone();
            let (i, j) = (rng.index(n), rng.index(n));
            match trial % 4 {
                0 => v[i] = ring[j],
                1 => v[i] = (ring[j] + ring[(j + 1) % n]) * 0.5,
                2 => v.swap(i, j),
                _ => v[i] = ring[j] + (ring[(j + 1) % n] - ring[j]) * 2.0,
            }
            let sweep = SimplePolygon::try_new(&v);
            let brute = SimplePolygon::try_new_brute_force(&v);
            assert_eq!(
                sweep.is_ok(),
                brute.is_ok(),
                "sweep {sweep:?}, brute force {brute:?}"
            );
            if let Err(PolygonError::SelfIntersection { edge_a, edge_b }) = sweep {
                let (a, b, c, d) = (
                    v[edge_a],
                    v[(edge_a + 1) % n],
                    v[edge_b],
                    v[(edge_b + 1) % n],
                );
                assert!(
                    oracle::segments_intersect(a, b, c, d),
                    "edges {edge_a}, {edge_b} do not meet"
                );
            }
        }
    }
}

#[test]
fn random_permutations_before_two_opt_finishes_cross() {
    // A random order of points in general position almost always crosses.
    let mut rng = SplitMix64::new(3);
    for n in [4, 6, 10, 30] {
        for _ in 0..10 {
            let mut v = oracle::two_opt(&mut rng, n);
            rng.shuffle(&mut v);
            check_simple_agreement(&v).unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

#[test]
fn generated_convex_polygons_are_accepted_and_stars_are_not() {
    let mut rng = SplitMix64::new(5);
    for n in [3, 4, 7, 20, 100] {
        let c = oracle::random_convex(&mut rng, n, DVec2::new(1e6, -3.0), 10.0);
        let lattice = oracle::random_convex_lattice(&mut rng, n.min(30), 1000);
        let sliver = oracle::sliver(&mut rng, n, 1e9);
        for ring in [c, lattice, sliver] {
            for v in variants(&ring, &mut rng) {
                check_convex_agreement(&v).unwrap_or_else(|e| panic!("{e}"));
                let p = ConvexPolygon::try_new(&v).unwrap_or_else(|e| panic!("rejected: {e}"));
                assert_eq!(p.len(), ring.len());
            }
            // Swapping two neighbours of a convex polygon with at least 4 vertices makes two edges cross.
            if ring.len() >= 4 {
                let mut swapped = ring.clone();
                swapped.swap(0, 1);
                check_convex_agreement(&swapped).unwrap_or_else(|e| panic!("{e}"));
                assert!(ConvexPolygon::try_new(&swapped).is_err());
            }
        }
    }
    for k in 1..4 {
        let ring = oracle::cocircular(k);
        check_convex_agreement(&ring).unwrap_or_else(|e| panic!("{e}"));
        // Every second vertex, twice around: a star polygon with all turns left.
        let m = ring.len();
        let step = if m % 3 == 0 { 5 } else { 3 };
        let star: Vec<DVec2> = (0..m).map(|i| ring[(i * step) % m]).collect();
        check_convex_agreement(&star).unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(
            ConvexPolygon::try_new(&star),
            Err(PolygonError::WindsMoreThanOnce { .. })
        ));
        // One vertex pushed one ulp inward or outward.
        for steps in [-1, 1] {
            let ring = oracle::cocircular_perturbed(k, 1, steps);
            check_convex_agreement(&ring).unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

#[test]
fn near_collinear_triangles_agree() {
    let mut rng = SplitMix64::new(9);
    for offset in [0.0, 1.0, 1e15, -1e-200] {
        for [a, b, c] in oracle::near_collinear(&mut rng, 50, offset, 3) {
            check_convex_agreement(&[a, b, c]).unwrap_or_else(|e| panic!("{e}"));
            check_simple_agreement(&[a, b, c]).unwrap_or_else(|e| panic!("{e}"));
        }
        for [a, b, c] in oracle::collinear_triples(&mut rng, 50, offset) {
            check_convex_agreement(&[a, b, c]).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(
                SimplePolygon::try_new(&[a, b, c]),
                Err(PolygonError::Degenerate)
            );
        }
    }
}

#[test]
fn locate_agrees_with_the_oracle_on_and_near_the_boundary() {
    let mut rng = SplitMix64::new(13);
    let mut polys = vec![
        oracle::random_convex_lattice(&mut rng, 12, 1 << 20),
        oracle::cocircular(2),
    ];
    polys.extend(
        simple_family(21)
            .into_iter()
            .map(|(_, p)| p)
            .filter(|p| p.len() <= 60),
    );
    for poly in &polys {
        let mut probes = boundary_probes(poly);
        let (lo, hi) = poly
            .iter()
            .fold((poly[0], poly[0]), |(lo, hi), &p| (lo.min(p), hi.max(p)));
        for _ in 0..100 {
            let t = DVec2::new(rng.unit_f64(), rng.unit_f64()) * 1.2 - 0.1;
            probes.push(lo + (hi - lo) * t);
        }
        check_locate(poly, &probes).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn melkman_equals_monotone_chain_on_generated_polygons() {
    let mut rng = SplitMix64::new(17);
    for seed in 0..4 {
        for (name, ring) in simple_family(300 + seed) {
            for v in variants(&ring, &mut rng) {
                check_hulls(&v).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }
    // Larger ones, where deep pockets exercise the deque.
    check_hulls(&oracle::spiral(16, 40)).unwrap_or_else(|e| panic!("{e}"));
    check_hulls(&oracle::comb(500, 100, 1)).unwrap_or_else(|e| panic!("{e}"));
    check_hulls(&oracle::star(&mut rng, 2000, 40)).unwrap_or_else(|e| panic!("{e}"));
}

/// A ring of 3 to 9 points on a small grid.
fn grid_ring(size: i32) -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(
        (0..size, 0..size).prop_map(|(x, y)| DVec2::new(f64::from(x), f64::from(y))),
        3..10,
    )
}

proptest! {
    #![proptest_config(common::config(3000, concat!(env!("CARGO_MANIFEST_DIR"), "/proptest-regressions/agreement.txt")))]

    #[test]
    fn grid_rings_agree_with_the_oracle(ring in grid_ring(5)) {
        check_simple_agreement(&ring).map_err(TestCaseError::fail)?;
        check_convex_agreement(&ring).map_err(TestCaseError::fail)?;
        if SimplePolygon::try_new(&ring).is_ok() {
            check_hulls(&ring).map_err(TestCaseError::fail)?;
            let probes: Vec<DVec2> = (0..9).flat_map(|x| (0..9).map(move |y| DVec2::new(f64::from(x), f64::from(y)) * 0.5)).collect();
            check_locate(&ring, &probes).map_err(TestCaseError::fail)?;
        }
    }

    #[test]
    fn small_rings_agree_with_the_oracle(ring in prop::collection::vec((0..3i32, 0..3i32).prop_map(|(x, y)| DVec2::new(f64::from(x), f64::from(y))), 0..6)) {
        if !ring.is_empty() {
            check_simple_agreement(&ring).map_err(TestCaseError::fail)?;
            check_convex_agreement(&ring).map_err(TestCaseError::fail)?;
        }
    }

    #[test]
    fn point_soup_hulls_agree(points in prop::collection::vec((0..6i32, 0..6i32).prop_map(|(x, y)| DVec2::new(f64::from(x), f64::from(y))), 1..25)) {
        let hull = convex_hull(&points).map_err(|e| TestCaseError::fail(e.to_string()))?;
        hull.check_invariants().map_err(TestCaseError::fail)?;
        prop_assert_eq!(sorted(hull.vertices()), hull_vertices_brute_force(&points));
    }
}

/// `convex_hull_of_two_with` against Andrew's hull of the same points, vertex for vertex and name
/// for name: two lattice hulls that overlap, nest, share points, or are a point or a segment.
fn check_hull_of_two<K: polydist_polygon::predicates::Kernel>(seed: u64) -> Result<(), String> {
    use polydist_polygon::{convex_hull_of_two_with, convex_hull_with};
    let mut rng = SplitMix64::new(seed);
    let mut cloud = |k: usize, span: i64, o: i64| -> Vec<DVec2> {
        (0..k)
            .map(|_| {
                DVec2::new(
                    (o + rng.range_i64(0, span)) as f64,
                    (o + rng.range_i64(0, span)) as f64,
                )
            })
            .collect()
    };
    let a = cloud(1 + (seed % 12) as usize, 6, 0);
    let mut b = cloud(1 + (seed % 7) as usize, 8, (seed % 5) as i64 - 2);
    if seed % 3 == 0 {
        b.extend_from_slice(&a[..a.len().min(2)]);
    }
    let (ha, hb) = (
        convex_hull_with::<K>(&a).map_err(|e| e.to_string())?,
        convex_hull_with::<K>(&b).map_err(|e| e.to_string())?,
    );
    let mut pts = ha.vertices().to_vec();
    pts.extend_from_slice(hb.vertices());
    let want = convex_hull_with::<K>(&pts).map_err(|e| e.to_string())?;
    let got = convex_hull_of_two_with::<K>(&pts, ha.len()).map_err(|e| e.to_string())?;
    let names = |h: &ConvexPolygon| (0..h.len()).map(|i| h.source_index(i)).collect::<Vec<_>>();
    if got.vertices() != want.vertices() || names(&got) != names(&want) {
        return Err(format!(
            "seed {seed}: {pts:?}: {:?} against {:?}",
            names(&got),
            names(&want)
        ));
    }
    Ok(())
}

#[test]
fn hull_of_two_convex_polygons_is_andrews_hull() {
    use polydist_polygon::predicates::{Exact, Fast, Robust};
    for seed in 0..4000 {
        check_hull_of_two::<Robust>(seed).unwrap();
    }
    for seed in 0..400 {
        check_hull_of_two::<Exact>(seed).unwrap();
    }
    // Not two convex polygons (runs out of order): still the hull of the points.
    let pts = [
        DVec2::new(3.0, 0.0),
        DVec2::ZERO,
        DVec2::new(1.0, 5.0),
        DVec2::new(2.0, -1.0),
    ];
    let h = polydist_polygon::convex_hull_of_two_with::<Robust>(&pts, 3).unwrap();
    assert_eq!(h.vertices(), convex_hull(&pts).unwrap().vertices());
    let f = polydist_polygon::convex_hull_of_two_with::<Fast>(&pts, 9).unwrap();
    assert!((0..f.len()).all(|i| f.source_index(i) < pts.len()));
}

proptest! {
    #[test]
    fn hull_of_two_convex_polygons_proptest(seed in any::<u64>()) {
        check_hull_of_two::<polydist_polygon::predicates::Robust>(seed).map_err(TestCaseError::fail)?;
    }
}
