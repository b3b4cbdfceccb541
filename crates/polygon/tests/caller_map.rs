//! The map back to the caller's indices: `source_index` names the caller's vertex, and
//! `caller_feature_on_edge` names the caller's feature nearest to a query, checked against exact
//! rational distances from the oracle.

mod common;

use glam::DVec2;
use polydist_oracle::{self as oracle, Relation, SplitMix64};
use polydist_polygon::predicates::{Exact, Robust};
use polydist_polygon::{ConvexPolygon, Feature, SimplePolygon};
use proptest::prelude::*;

/// Whether `r` lies on the closed segment `[a, b]`, exactly.
fn on_segment(r: DVec2, a: DVec2, b: DVec2) -> bool {
    oracle::sq_dist_ps(r, a, b) == oracle::sq_dist_pp(a, a)
}

/// Checks the feature named for internal edge `[a, b]` and query `q` against exact distances: a
/// caller vertex or a nonzero caller edge on `[a, b]` realizing the distance from `q` to `[a, b]`, an
/// edge only when neither of its ends does; `None` only for a lid, when neither end realizes it.
fn check_feature(
    ring: &[DVec2],
    a: DVec2,
    b: DVec2,
    q: DVec2,
    lid: bool,
    got: Option<Feature>,
) -> Result<(), String> {
    let n = ring.len();
    let best = oracle::sq_dist_ps(q, a, b);
    let ctx = || format!("edge {a}→{b}, q = {q}, got {got:?}, ring {ring:?}");
    match got {
        Some(Feature::Vertex(j)) => {
            let p = *ring
                .get(j)
                .ok_or_else(|| format!("vertex {j} out of range: {}", ctx()))?;
            if !on_segment(p, a, b) || oracle::sq_dist_pp(q, p) != best {
                return Err(format!(
                    "caller vertex {j} does not realize the distance: {}",
                    ctx()
                ));
            }
        }
        Some(Feature::Edge(j)) => {
            let (c, d) = (
                *ring
                    .get(j)
                    .ok_or_else(|| format!("edge {j} out of range: {}", ctx()))?,
                ring[(j + 1) % n],
            );
            if lid || c == d || !on_segment(c, a, b) || !on_segment(d, a, b) {
                return Err(format!(
                    "caller edge {j} is not a piece of the edge: {}",
                    ctx()
                ));
            }
            if oracle::sq_dist_ps(q, c, d) != best
                || oracle::sq_dist_pp(q, c) == best
                || oracle::sq_dist_pp(q, d) == best
            {
                return Err(format!(
                    "caller edge {j} does not realize the distance in its interior: {}",
                    ctx()
                ));
            }
        }
        None => {
            if !lid || oracle::sq_dist_pp(q, a) == best || oracle::sq_dist_pp(q, b) == best {
                return Err(format!("no feature named: {}", ctx()));
            }
        }
    }
    Ok(())
}

/// Query points around the polygon: vertices, the caller's points, and lattice points nearby.
fn queries(ring: &[DVec2]) -> Vec<DVec2> {
    let (lo, hi) = ring
        .iter()
        .fold((ring[0], ring[0]), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let step = (hi - lo) / 6.0;
    let mut out: Vec<DVec2> = ring.to_vec();
    for i in -1..=7 {
        for j in -1..=7 {
            out.push(lo + step * DVec2::new(f64::from(i), f64::from(j)));
        }
    }
    out
}

/// Every vertex and edge of `poly` (with its vertex map) checked against the caller's `ring`.
fn check_polygon(
    ring: &[DVec2],
    vertices: &[DVec2],
    source: impl Fn(usize) -> usize,
    lid: impl Fn(usize) -> bool,
    feature: impl Fn(usize, DVec2) -> Option<Feature>,
) -> Result<(), String> {
    let n = vertices.len();
    for (i, &v) in vertices.iter().enumerate() {
        if ring[source(i)] != v {
            return Err(format!("vertex {i} is not caller vertex {}", source(i)));
        }
    }
    for e in 0..n {
        for q in queries(ring) {
            check_feature(
                ring,
                vertices[e],
                vertices[(e + 1) % n],
                q,
                lid(e),
                feature(e, q),
            )?;
        }
    }
    Ok(())
}

fn check_convex(ring: &[DVec2]) -> Result<(), String> {
    let p = ConvexPolygon::try_new(ring).map_err(|e| e.to_string())?;
    check_polygon(
        ring,
        p.vertices(),
        |i| p.source_index(i),
        |e| p.is_lid(e),
        |e, q| {
            let f = p.caller_feature_on_edge::<Robust>(e, q);
            assert_eq!(f, p.caller_feature_on_edge::<Exact>(e, q));
            f
        },
    )
}

fn check_simple(ring: &[DVec2]) -> Result<(), String> {
    let p = SimplePolygon::try_new(ring).map_err(|e| e.to_string())?;
    check_polygon(
        ring,
        p.vertices(),
        |i| p.source_index(i),
        |_| false,
        |e, q| p.caller_feature_on_edge::<Robust>(e, q),
    )?;
    let hull = p.convex_hull();
    check_polygon(
        ring,
        hull.vertices(),
        |i| hull.source_index(i),
        |e| hull.is_lid(e),
        |e, q| hull.caller_feature_on_edge::<Robust>(e, q),
    )
}

/// `ring` as the caller may give it: with vertices repeated, closed, reversed.
fn messy(ring: &[DVec2], rng: &mut SplitMix64) -> Vec<DVec2> {
    let mut out = Vec::new();
    for &p in ring {
        for _ in 0..1 + usize::from(rng.index(4) == 0) {
            out.push(p);
        }
    }
    if rng.coin() {
        out.push(ring[0]);
    }
    if rng.coin() {
        out.reverse();
    }
    out
}

#[test]
fn convex_polygons_with_collinear_and_repeated_vertices() {
    let mut rng = SplitMix64::new(23);
    for (n, m) in [(3, 4), (5, 6), (8, 12)] {
        let pair = oracle::convex_pair(&mut rng, n, m, Relation::CollinearInput);
        for ring in [pair.p, pair.q] {
            for _ in 0..3 {
                let v = messy(&ring, &mut rng);
                check_convex(&v).unwrap_or_else(|e| panic!("{e}"));
                check_simple(&v).unwrap_or_else(|e| panic!("{e}"));
            }
        }
    }
}

#[test]
fn simple_polygons_and_their_hulls() {
    let mut rng = SplitMix64::new(29);
    let rings = [
        oracle::comb(4, 3, 1),
        oracle::star(&mut rng, 12, 3),
        oracle::two_opt(&mut rng, 15),
        oracle::spiral(5, 2),
    ];
    for ring in rings {
        for _ in 0..3 {
            let v = messy(&ring, &mut rng);
            check_simple(&v).unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

#[test]
fn degenerate_convex_polygons() {
    let p = |x: f64, y: f64| DVec2::new(x, y);
    for ring in [
        vec![p(1.0, 1.0)],
        vec![p(1.0, 1.0), p(1.0, 1.0)],
        vec![p(0.0, 0.0), p(3.0, 3.0)],
        vec![
            p(0.0, 0.0),
            p(1.0, 1.0),
            p(2.0, 2.0),
            p(3.0, 3.0),
            p(2.0, 2.0),
            p(1.0, 1.0),
        ],
        vec![
            p(2.0, 2.0),
            p(3.0, 3.0),
            p(3.0, 3.0),
            p(0.0, 0.0),
            p(1.0, 1.0),
        ],
    ] {
        check_convex(&ring).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// A convex lattice polygon with points inserted on its edges (at lattice fractions) and repeats.
fn convex_with_extras() -> impl Strategy<Value = (Vec<DVec2>, u64)> {
    (3usize..8, any::<u64>()).prop_map(|(n, seed)| {
        let mut rng = SplitMix64::new(seed);
        let base = oracle::random_convex_lattice(&mut rng, n, 64);
        let mut ring = Vec::new();
        for i in 0..base.len() {
            let (a, b) = (base[i], base[(i + 1) % base.len()]);
            ring.push(a);
            for k in 0..rng.index(3) {
                ring.push(a + (b - a) * (f64::from(k as u32 + 1) / 4.0));
            }
        }
        (ring, seed)
    })
}

proptest! {
    #![proptest_config(common::config(64, concat!(env!("CARGO_MANIFEST_DIR"), "/proptest-regressions/caller_map.txt")))]

    #[test]
    fn random_convex_rings_map_back(input in convex_with_extras()) {
        let (ring, seed) = input;
        let mut rng = SplitMix64::new(seed ^ 1);
        let v = messy(&ring, &mut rng);
        check_convex(&v).map_err(TestCaseError::fail)?;
        check_simple(&v).map_err(TestCaseError::fail)?;
    }
}
