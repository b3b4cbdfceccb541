//! Constructors and queries never panic: every input gives `Ok` (passing the invariant checks) or a
//! typed error, whatever the coordinates (NaN, infinities, huge, subnormal) and whatever the shape
//! (empty, repeats, spikes, self-crossings, star polygons, point soups).

mod common;

use glam::DVec2;
use polydist_polygon::predicates::{Fast, Robust};
use polydist_polygon::{ConvexPolygon, PolygonError, SimplePolygon, convex_hull, convex_hull_with};
use proptest::prelude::*;

/// Coordinates that break naive code: signed zeros, subnormals, ulp neighbours, the range limit and
/// just beyond it, NaN and infinities.
fn nasty_coordinate() -> impl Strategy<Value = f64> {
    let max = polydist_polygon::predicates::MAX_COORDINATE;
    prop_oneof![
        4 => (-3i32..=3).prop_map(f64::from),
        1 => Just(-0.0),
        1 => Just(f64::from_bits(1)),
        1 => Just(-f64::MIN_POSITIVE),
        1 => Just(1.0 + f64::EPSILON),
        1 => Just(1.0 - f64::EPSILON / 2.0),
        1 => Just(max),
        1 => Just(-max),
        1 => Just(f64::from_bits(max.to_bits() + 1)),
        1 => Just(1e300),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        2 => any::<f64>(),
    ]
}

/// A ring of 0 to 12 points with nasty coordinates.
fn nasty_ring() -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(
        (nasty_coordinate(), nasty_coordinate()).prop_map(|(x, y)| DVec2::new(x, y)),
        0..12,
    )
}

/// A ring of 0 to 12 points on a 4 × 4 grid: repeats, collinear runs, spikes and crossings galore.
fn grid_ring() -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(
        (0..4i32, 0..4i32).prop_map(|(x, y)| DVec2::new(f64::from(x), f64::from(y))),
        0..12,
    )
}

/// Regular star polygons `{n/k}` (pentagrams, heptagrams, …), rounded to a lattice, either orientation.
fn star_polygon() -> impl Strategy<Value = Vec<DVec2>> {
    (3usize..12, 1usize..6, any::<bool>()).prop_map(|(n, k, ccw)| {
        let mut v: Vec<DVec2> = (0..n)
            .map(|i| {
                let a = (i * k) as f64 * std::f64::consts::TAU / n as f64;
                DVec2::new((1e6 * a.cos()).round(), (1e6 * a.sin()).round())
            })
            .collect();
        if !ccw {
            v.reverse();
        }
        v
    })
}

/// Runs every constructor and query on `ring`; fails on a broken invariant (a panic fails by itself).
fn exercise(ring: &[DVec2]) -> Result<(), TestCaseError> {
    let probes: Vec<DVec2> = ring
        .iter()
        .copied()
        .chain([DVec2::ZERO, DVec2::new(0.5, 1.5), DVec2::NAN])
        .collect();
    match ConvexPolygon::try_new(ring) {
        Ok(p) => {
            prop_assert_eq!(p.check_invariants(), Ok(()));
            for &q in &probes {
                let _ = p.locate(q);
                let _ = p.locate_with::<Fast>(q);
                for e in 0..p.len() {
                    let _ = p.caller_feature_on_edge::<Robust>(e, q);
                    let _ = p.caller_feature_on_edge::<Fast>(e, q);
                }
            }
        }
        Err(e) => prop_assert!(!e.to_string().is_empty()),
    }
    match SimplePolygon::try_new(ring) {
        Ok(p) => {
            prop_assert_eq!(p.check_invariants(), Ok(()));
            let hull = p.convex_hull();
            prop_assert_eq!(hull.check_invariants(), Ok(()));
            let _ = p.convex_hull_with::<Fast>();
            for &q in &probes {
                let _ = p.locate(q);
                let _ = p.locate_with::<Fast>(q);
                for e in 0..p.len() {
                    prop_assert!(p.caller_feature_on_edge::<Robust>(e, q).is_some());
                }
            }
        }
        Err(e) => prop_assert!(!e.to_string().is_empty()),
    }
    if let Ok(hull) = convex_hull(ring) {
        prop_assert_eq!(hull.check_invariants(), Ok(()));
    }
    let _ = convex_hull_with::<Fast>(ring);
    Ok(())
}

proptest! {
    #![proptest_config(common::config(2000, concat!(env!("CARGO_MANIFEST_DIR"), "/proptest-regressions/never_panics.txt")))]

    #[test]
    fn nasty_coordinates_never_panic(ring in nasty_ring()) {
        exercise(&ring)?;
        // Non-finite and out-of-range coordinates are always reported, with the first such index.
        let bad = ring.iter().position(|p| !(p.x.abs() <= polydist_polygon::predicates::MAX_COORDINATE && p.y.abs() <= polydist_polygon::predicates::MAX_COORDINATE));
        if let Some(index) = bad {
            let r = ConvexPolygon::try_new(&ring).err();
            let finite = ring[index].is_finite();
            prop_assert_eq!(r, Some(if finite { PolygonError::OutOfRange { index } } else { PolygonError::NonFinite { index } }));
        }
    }

    #[test]
    fn grid_rings_never_panic(ring in grid_ring()) {
        exercise(&ring)?;
    }

    #[test]
    fn star_polygons_never_panic(ring in star_polygon()) {
        exercise(&ring)?;
    }

    #[test]
    fn random_point_soups_never_panic(ring in prop::collection::vec((-1e3..1e3f64, -1e3..1e3f64).prop_map(DVec2::from), 0..40)) {
        exercise(&ring)?;
    }
}
