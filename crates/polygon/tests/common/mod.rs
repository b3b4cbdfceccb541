//! Helpers shared by the integration tests: exact references built on the oracle, and generators.

#![allow(
    dead_code,
    reason = "each test binary uses a different subset of the helpers"
)]

use std::cmp::Ordering;

use glam::DVec2;
use polydist_oracle as oracle;
use polydist_polygon::Location;
use proptest::test_runner::{Config, FileFailurePersistence};

/// A proptest configuration running `cases` cases and persisting failures in `regressions`, a path
/// under this crate's `proptest-regressions/` (pass `concat!(env!("CARGO_MANIFEST_DIR"), …)`).
pub(crate) fn config(cases: u32, regressions: &'static str) -> Config {
    Config {
        cases,
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(regressions))),
        ..Config::default()
    }
}

/// The ring with cyclically consecutive exact repeats removed (the oracle's shape tests reject
/// zero-length edges, which the constructors merge).
pub(crate) fn dedup_ring(ring: &[DVec2]) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::with_capacity(ring.len());
    for &p in ring {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

/// The oracle's location, in this crate's type.
pub(crate) fn oracle_locate(p: DVec2, poly: &[DVec2]) -> Location {
    match oracle::point_in_polygon(p, poly) {
        oracle::Location::Inside => Location::Inside,
        oracle::Location::Boundary => Location::Boundary,
        oracle::Location::Outside => Location::Outside,
    }
}

/// The strict vertices of the convex hull of `points` by brute force with the oracle's exact
/// orientation, sorted lexicographically: `p ≠ q` are hull vertices when every point is left of
/// `p → q` or on the closed segment `[p, q]`. `O(n³)`; for small inputs.
pub(crate) fn hull_vertices_brute_force(points: &[DVec2]) -> Vec<DVec2> {
    let mut pts: Vec<DVec2> = points.to_vec();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() <= 2 {
        return pts;
    }
    let between = |p: DVec2, q: DVec2, r: DVec2| {
        // r is on the line pq; along a line the lexicographic order is monotone.
        let lo = if (p.x, p.y) <= (q.x, q.y) { p } else { q };
        let hi = if lo == p { q } else { p };
        (lo.x, lo.y) <= (r.x, r.y) && (r.x, r.y) <= (hi.x, hi.y)
    };
    let mut out: Vec<DVec2> = Vec::new();
    for &p in &pts {
        for &q in &pts {
            if p == q {
                continue;
            }
            let edge = pts.iter().all(|&r| match oracle::sign_orient(p, q, r) {
                Ordering::Greater => true,
                Ordering::Less => false,
                Ordering::Equal => between(p, q, r),
            });
            if edge {
                out.push(p);
                out.push(q);
            }
        }
    }
    out.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    out.dedup();
    out
}

/// `v` sorted lexicographically (for comparing vertex sets).
pub(crate) fn sorted(v: &[DVec2]) -> Vec<DVec2> {
    let mut v = v.to_vec();
    v.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    v
}

/// `x` moved `k` representable doubles up (`k < 0`: down).
pub(crate) fn ulps(x: f64, k: i64) -> f64 {
    oracle::step_ulps(x, k)
}

/// Query points that stress a polygon's boundary: every vertex, every edge midpoint (exact for
/// lattice polygons whose coordinates have spare bits), both moved one ulp each way in x and in y,
/// and a few points far away.
pub(crate) fn boundary_probes(poly: &[DVec2]) -> Vec<DVec2> {
    let n = poly.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        for p in [a, (a + b) * 0.5] {
            out.push(p);
            for k in [-1, 1] {
                out.push(DVec2::new(ulps(p.x, k), p.y));
                out.push(DVec2::new(p.x, ulps(p.y, k)));
            }
        }
    }
    out.extend([
        DVec2::new(1e300, 0.0),
        DVec2::new(-1e300, -1e300),
        DVec2::ZERO,
    ]);
    out
}
