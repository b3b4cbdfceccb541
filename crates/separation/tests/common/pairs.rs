//! The polygon tests' shared checks: the oracle's optimality and the placement of pairs.

use glam::DVec2;
use polydist_oracle::{ExactDistance, ulps_error_sqrt};
use polydist_polygon::Feature;
use polydist_separation::ClosestPair;
use proptest::prelude::*;

pub(crate) fn oracle_feature(f: Feature) -> polydist_oracle::Feature {
    match f {
        Feature::Vertex(i) => polydist_oracle::Feature::Vertex(i),
        Feature::Edge(i) => polydist_oracle::Feature::Edge(i),
    }
}

/// `pair` is an exact optimum of the oracle's answer, its distance within 3.5 ulps.
pub(crate) fn check_optimal(
    exact: &ExactDistance,
    pair: &ClosestPair,
) -> Result<(), TestCaseError> {
    prop_assert!(
        exact.is_optimal_pair(
            oracle_feature(pair.feature_p),
            oracle_feature(pair.feature_q)
        ),
        "not optimal: {:?} {:?}",
        pair.feature_p,
        pair.feature_q
    );
    prop_assert!(
        ulps_error_sqrt(pair.distance, &exact.sq) <= 3.5,
        "distance {} off by {} ulps",
        pair.distance,
        ulps_error_sqrt(pair.distance, &exact.sq)
    );
    Ok(())
}

pub(crate) fn bbox(p: &[DVec2]) -> (DVec2, DVec2) {
    let lo = p.iter().fold(DVec2::splat(f64::INFINITY), |a, &b| a.min(b));
    let hi = p
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, &b| a.max(b));
    (lo, hi)
}

/// `q` moved so that its bounding box is `gap` beyond `p`'s along the axis `axis` (0 = x, 1 = y) in
/// the direction `dir` (±1), and slid along the other axis by `slide` times `p`'s extent.
pub(crate) fn place_beside(
    p: &[DVec2],
    q: &[DVec2],
    axis: usize,
    dir: f64,
    gap: f64,
    slide: f64,
) -> Vec<DVec2> {
    let (plo, phi) = bbox(p);
    let (qlo, qhi) = bbox(q);
    let mut shift = DVec2::ZERO;
    if dir > 0.0 {
        shift[axis] = phi[axis] - qlo[axis] + gap;
    } else {
        shift[axis] = plo[axis] - qhi[axis] - gap;
    }
    let other = 1 - axis;
    shift[other] = plo[other] - qlo[other] + slide * (phi[other] - plo[other]);
    q.iter().map(|&v| v + shift).collect()
}
