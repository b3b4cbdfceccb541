//! Hausdorff and CMMR distances (Atallah 1983; Atallah, Ribeiro, Lifschitz 1991): the linear walk
//! against its brute-force twin under the same kernel and against the exact oracle, on random convex
//! pairs in every relative position (disjoint, touching, shared edges, overlapping, nested, identical,
//! collinear input, near-degenerate, co-circular lattice sets), points and segments; exact argmax and
//! ulp bounds under Robust and Exact; the Fast kernel measured; linear growth by counting predicates.

mod common;

use common::Chaos;

use core::cmp::Ordering;

use glam::DVec2;
use polydist_convex::polygon::predicates::{
    BigRational, Counted, Exact, Fast, Kernel, Robust, predicate_counts, reset_predicate_counts,
};
use polydist_convex::polygon::{ConvexPolygon, Location};
use polydist_convex::{
    Direction, cmmr_brute, cmmr_with, directed_hausdorff_brute, directed_hausdorff_with,
    hausdorff_brute, hausdorff_squared_exact, hausdorff_with, per_vertex_distances_brute,
    per_vertex_distances_with, reset_walk_fallbacks, walk_fallbacks,
};
use polydist_oracle::{
    Relation, SplitMix64, cocircular, cocircular_perturbed, convex_pair, directed_hausdorff_filled,
    hausdorff_filled, per_vertex_sq_dist, random_convex, random_convex_lattice, sliver, ulps_error,
    ulps_error_sqrt,
};
use proptest::prelude::*;

/// Bounds of the contract (DESIGN.md and the brief): Hausdorff 3.5 ulps, CMMR 6 ulps.
const HAUSDORFF_ULPS: f64 = 3.5;
const CMMR_ULPS: f64 = 6.0;
/// What the implementation claims per vertex: the squared distance rounded once (0.5 ulp plus a
/// residual of 2⁻⁴⁰), the distance its square root.
const VERTEX_SQ_ULPS: f64 = 0.51;
const VERTEX_ULPS: f64 = 1.0;

/// The largest errors seen, in ulps.
#[derive(Clone, Copy, Debug, Default)]
struct Worst {
    vertex_sq: f64,
    vertex: f64,
    hausdorff: f64,
    hausdorff_sq: f64,
    cmmr: f64,
    cases: usize,
}

impl Worst {
    fn merge(&mut self, o: Worst) {
        self.vertex_sq = self.vertex_sq.max(o.vertex_sq);
        self.vertex = self.vertex.max(o.vertex);
        self.hausdorff = self.hausdorff.max(o.hausdorff);
        self.hausdorff_sq = self.hausdorff_sq.max(o.hausdorff_sq);
        self.cmmr = self.cmmr.max(o.cmmr);
        self.cases += o.cases;
    }
}

fn zero() -> BigRational {
    BigRational::from_integer(0.into())
}

/// Everything checked on one pair under an exact-decision kernel `K`; panics on any disagreement.
fn check<K: Kernel>(pv: &[DVec2], qv: &[DVec2]) -> Worst {
    let (Ok(p), Ok(q)) = (ConvexPolygon::try_new(pv), ConvexPolygon::try_new(qv)) else {
        return Worst::default();
    };
    let mut w = Worst {
        cases: 1,
        ..Worst::default()
    };
    reset_walk_fallbacks();
    for (a, b) in [(&p, &q), (&q, &p)] {
        let (av, bv) = (a.vertices(), b.vertices());
        // The twin: identical features and numbers.
        let fast = per_vertex_distances_with::<K>(a, b);
        let brute = per_vertex_distances_brute::<K>(a, b);
        assert_eq!(fast, brute, "walk and brute force disagree");
        // The oracle, vertex by vertex.
        let exact = per_vertex_sq_dist(av, bv);
        assert_eq!(exact.len(), fast.len());
        for (k, (r, e)) in fast.iter().zip(&exact).enumerate() {
            assert_eq!(r.point, av[k]);
            assert_eq!(r.vertex, a.source_index(k));
            if *e == zero() {
                assert_eq!(r.squared_distance, 0.0);
                assert_ne!(r.location, Location::Outside, "{r:?}");
                assert_eq!(r.projection, r.point);
            } else {
                assert_eq!(r.location, Location::Outside, "{r:?} exact {e}");
                assert!(r.feature.is_some());
                // The projection realizes the distance (its own bound is 0.5 ulp + 3u·distance).
                let back = (r.point - r.projection).length();
                assert!(
                    (back - r.distance).abs()
                        <= 1e-12 * r.distance.max(r.point.abs().max_element()),
                    "{r:?}"
                );
                w.vertex_sq = w.vertex_sq.max(ulps_error(r.squared_distance, e));
                w.vertex = w.vertex.max(ulps_error_sqrt(r.distance, e));
            }
            assert_eq!(r.location == Location::Inside, r.feature.is_none());
        }
        // Directed Hausdorff: exact argmax among the oracle's argmax set.
        let (h_exact, arg) = directed_hausdorff_filled(av, bv);
        let h = directed_hausdorff_with::<K>(a, b);
        assert_eq!(h, directed_hausdorff_brute::<K>(a, b));
        assert!(
            arg.iter().any(|&i| av[i] == h.point),
            "argmax {:?} not among the oracle's {arg:?}",
            h.point
        );
        w.hausdorff = w.hausdorff.max(ulps_error_sqrt(h.distance, &h_exact));
        w.hausdorff_sq = w.hausdorff_sq.max(ulps_error(h.squared_distance, &h_exact));
    }
    // Hausdorff both ways and its direction.
    let h = hausdorff_with::<K>(&p, &q);
    assert_eq!(h, hausdorff_brute::<K>(&p, &q));
    let (pv, qv) = (p.vertices(), q.vertices());
    let exact = hausdorff_filled(pv, qv);
    let (hp, _) = directed_hausdorff_filled(pv, qv);
    let (hq, _) = directed_hausdorff_filled(qv, pv);
    let expected = if hq > hp {
        Direction::QToP
    } else {
        Direction::PToQ
    };
    assert_eq!(h.direction, expected);
    w.hausdorff = w.hausdorff.max(ulps_error_sqrt(h.distance, &exact));
    w.hausdorff_sq = w.hausdorff_sq.max(ulps_error(h.squared_distance, &exact));
    // CMMR.
    let c = cmmr_with::<K>(&p, &q);
    assert_eq!(c, cmmr_brute::<K>(&p, &q));
    assert_eq!(c.value, polydist_convex::cmmr_value_with::<K>(&p, &q));
    let ce = polydist_oracle::cmmr(pv, qv);
    if ce == zero() {
        assert_eq!(c.value, 0.0);
    } else {
        w.cmmr = w.cmmr.max(ulps_error(c.value, &ce));
    }
    assert_eq!(walk_fallbacks(), 0, "the walk ran out of budget");
    assert!(w.vertex_sq <= VERTEX_SQ_ULPS, "{w:?}");
    assert!(w.vertex <= VERTEX_ULPS, "{w:?}");
    assert!(
        w.hausdorff <= HAUSDORFF_ULPS && w.hausdorff_sq <= HAUSDORFF_ULPS,
        "{w:?}"
    );
    assert!(w.cmmr <= CMMR_ULPS, "{w:?}");
    w
}

/// The pairs every sweep runs: every oracle relation, both orders.
fn relation_pairs(rng: &mut SplitMix64, n: usize, m: usize) -> Vec<(Vec<DVec2>, Vec<DVec2>)> {
    let mut out = Vec::new();
    for rel in Relation::EVERY {
        let pair = convex_pair(rng, n.max(3), m.max(3), rel);
        out.push((pair.p.clone(), pair.q.clone()));
        out.push((pair.q, pair.p));
    }
    out
}

/// Two random convex polygons around nearby centres: mostly overlapping with many crossings.
fn overlapping(rng: &mut SplitMix64, n: usize, m: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let c = DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5);
    let r = 0.5 + rng.unit_f64();
    (
        random_convex(rng, n.max(3), DVec2::ZERO, 1.0),
        random_convex(rng, m.max(3), c, r),
    )
}

/// Small-integer polygons sharing the lattice: shared vertices, collinear overlapping edges,
/// segments through vertices, exact ties.
fn lattice(rng: &mut SplitMix64, n: usize, m: usize, coord: i64) -> (Vec<DVec2>, Vec<DVec2>) {
    let n = n.clamp(3, 12);
    let m = m.clamp(3, 12);
    // Valtr's method needs about k^1.5 lattice steps for k vertices.
    let coord = coord.max((n.max(m) as f64).powf(1.5) as i64 * 2 + 4);
    let shift = DVec2::new(rng.range_i64(-3, 3) as f64, rng.range_i64(-3, 3) as f64);
    let p = random_convex_lattice(rng, n, coord);
    let q: Vec<DVec2> = random_convex_lattice(rng, m, coord)
        .into_iter()
        .map(|v| v + shift)
        .collect();
    (p, q)
}

/// Prefixes of a polygon: points, segments, triangles (sub-polygons of a convex polygon are convex).
fn prefix(v: &[DVec2], k: usize) -> Vec<DVec2> {
    v[..k.min(v.len())].to_vec()
}

fn sweep<K: Kernel>(seed: u64, n: usize, m: usize) -> Worst {
    let mut rng = SplitMix64::new(seed);
    let mut w = Worst::default();
    for (p, q) in relation_pairs(&mut rng, n, m) {
        w.merge(check::<K>(&p, &q));
    }
    let (p, q) = overlapping(&mut rng, n, m);
    w.merge(check::<K>(&p, &q));
    w.merge(check::<K>(&p, &p)); // identical
    let (p, q) = lattice(&mut rng, n, m, 8);
    w.merge(check::<K>(&p, &q));
    w.merge(check::<K>(&q, &p));
    w
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 48,
        failure_persistence: Some(Box::new(proptest::test_runner::FileFailurePersistence::Direct(
            "proptest-regressions/hausdorff.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn robust_agrees_in_every_relation(seed in any::<u64>(), n in 3usize..40, m in 3usize..40) {
        sweep::<Robust>(seed, n, m);
    }

    #[test]
    fn exact_agrees_in_every_relation(seed in any::<u64>(), n in 3usize..16, m in 3usize..16) {
        sweep::<Exact>(seed, n, m);
    }

    #[test]
    fn tiny_polygons_points_and_segments(seed in any::<u64>(), k in 1usize..4, l in 1usize..4) {
        let mut rng = SplitMix64::new(seed);
        for (p, q) in relation_pairs(&mut rng, 6, 6) {
            check::<Robust>(&prefix(&p, k), &prefix(&q, l));
            check::<Robust>(&prefix(&p, k), &q);
            check::<Robust>(&p, &prefix(&q, l));
        }
        let (p, q) = lattice(&mut rng, 6, 6, 4);
        check::<Robust>(&prefix(&p, k), &prefix(&q, l));
        check::<Robust>(&prefix(&p, k), &q);
    }

    #[test]
    fn lattice_degeneracies(seed in any::<u64>(), n in 3usize..12, m in 3usize..12, coord in 3i64..12) {
        let mut rng = SplitMix64::new(seed);
        let (p, q) = lattice(&mut rng, n, m, coord.max(2 * n.max(m) as i64));
        check::<Robust>(&p, &q);
        check::<Exact>(&q, &p);
    }
}

#[test]
fn sizes_up_to_200() {
    let mut w = Worst::default();
    for (i, &(n, m)) in [(200, 200), (200, 7), (5, 190), (120, 150)]
        .iter()
        .enumerate()
    {
        w.merge(sweep::<Robust>(1000 + i as u64, n, m));
    }
    println!("sizes up to 200: {w:?}");
}

#[test]
fn cocircular_lattice_sets() {
    // Every vertex at the same distance from the origin: maximal Hausdorff ties.
    let mut w = Worst::default();
    for k in 1..=3 {
        let c = cocircular(k);
        let r = 5f64.powi(k as i32);
        let shifts = [
            DVec2::ZERO,
            DVec2::new(r, 0.0),
            DVec2::new(2.0 * r + 1.0, 0.0),
            DVec2::new(3.0 * r, r),
            DVec2::new(0.5 * r, -0.5 * r),
        ];
        for s in shifts {
            let q: Vec<DVec2> = c.iter().map(|&v| v + s).collect();
            w.merge(check::<Robust>(&c, &q));
            w.merge(check::<Exact>(&q, &c));
            // A point at the centre: every vertex of c is an argmax.
            w.merge(check::<Robust>(&c, &[s]));
        }
        w.merge(check::<Robust>(&c, &cocircular_perturbed(k, 1, 1)));
        w.merge(check::<Robust>(&cocircular_perturbed(k, 2, -1), &c));
    }
    println!("cocircular: {w:?}");
}

#[test]
fn nested_touching_identical_and_shared_edges() {
    let sq = |x0: f64, y0: f64, s: f64| {
        vec![
            DVec2::new(x0, y0),
            DVec2::new(x0 + s, y0),
            DVec2::new(x0 + s, y0 + s),
            DVec2::new(x0, y0 + s),
        ]
    };
    let big = sq(0.0, 0.0, 8.0);
    let cases = [
        (big.clone(), big.clone()),         // identical
        (big.clone(), sq(2.0, 2.0, 3.0)),   // nested strictly
        (big.clone(), sq(0.0, 0.0, 3.0)),   // nested sharing a corner and two edges
        (big.clone(), sq(0.0, 2.0, 3.0)),   // nested touching one edge
        (big.clone(), sq(8.0, 0.0, 8.0)),   // sharing a whole edge outside
        (big.clone(), sq(8.0, 3.0, 2.0)),   // sharing part of an edge
        (big.clone(), sq(8.0, 8.0, 2.0)),   // touching at a vertex
        (big.clone(), sq(4.0, 4.0, 8.0)),   // overlapping corners
        (big.clone(), sq(-2.0, 2.0, 12.0)), // crossing, two edges each
        (
            big.clone(),
            vec![
                DVec2::new(4.0, -2.0),
                DVec2::new(10.0, 4.0),
                DVec2::new(4.0, 10.0),
                DVec2::new(-2.0, 4.0),
            ],
        ), // diamond through the sides
        (
            big.clone(),
            vec![
                DVec2::new(4.0, 0.0),
                DVec2::new(8.0, 4.0),
                DVec2::new(4.0, 8.0),
                DVec2::new(0.0, 4.0),
            ],
        ), // inscribed diamond: vertices on edges
        (
            big.clone(),
            vec![DVec2::new(-1.0, 8.0), DVec2::new(9.0, 8.0)],
        ), // segment along an edge, overhanging
        (
            big.clone(),
            vec![DVec2::new(-1.0, 4.0), DVec2::new(9.0, 4.0)],
        ), // segment through
        (big.clone(), vec![DVec2::new(8.0, 8.0)]), // point at a vertex
        (big.clone(), vec![DVec2::new(8.0, 3.0)]), // point on an edge
        (big.clone(), vec![DVec2::new(3.0, 3.0)]), // point inside
        (
            vec![
                DVec2::new(0.0, 0.0),
                DVec2::new(4.0, 0.0),
                DVec2::new(2.0, 1.0),
            ],
            vec![
                DVec2::new(2.0, 0.0),
                DVec2::new(6.0, 0.0),
                DVec2::new(4.0, -1.0),
            ],
        ), // collinear overlapping edges, opposite sides
        (
            vec![
                DVec2::new(0.0, 0.0),
                DVec2::new(100.0, 0.0),
                DVec2::new(100.0, 10.0),
                DVec2::new(0.0, 10.0),
            ],
            vec![
                DVec2::new(2.0, 5.0),
                DVec2::new(4.0, 12.0),
                DVec2::new(0.0, 12.0),
            ],
        ), // the notes' lobe with a reversal
    ];
    for (p, q) in &cases {
        check::<Robust>(p, q);
        check::<Robust>(q, p);
        check::<Exact>(p, q);
        check::<Exact>(q, p);
    }
}

#[test]
fn collinear_input_vertices_report_caller_indices() {
    // Caller vertices 1 and 3 are dropped (straight); results name caller indices.
    let p = [
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(4.0, 0.0),
        DVec2::new(4.0, 2.0),
        DVec2::new(4.0, 4.0),
        DVec2::new(0.0, 4.0),
    ];
    let q = [
        DVec2::new(6.0, 1.0),
        DVec2::new(9.0, 1.0),
        DVec2::new(9.0, 3.0),
        DVec2::new(6.0, 3.0),
    ];
    let (pp, qq) = (
        ConvexPolygon::try_new(&p).unwrap_or_else(|e| panic!("{e}")),
        ConvexPolygon::try_new(&q).unwrap_or_else(|e| panic!("{e}")),
    );
    let d = per_vertex_distances_with::<Robust>(&pp, &qq);
    let idx: Vec<usize> = d.iter().map(|r| r.vertex).collect();
    assert_eq!(idx, vec![0, 2, 4, 5]);
    let back = per_vertex_distances_with::<Robust>(&qq, &pp);
    // (6, 1) projects on the right edge of P, which is caller edge 2 (from (4,0) to (4,2)).
    assert_eq!(
        back[0].feature,
        Some(polydist_convex::polygon::Feature::Edge(2))
    );
    assert_eq!(
        back[3].feature,
        Some(polydist_convex::polygon::Feature::Edge(3))
    );
    check::<Robust>(&p, &q);
}

#[test]
fn near_degenerate_and_slivers() {
    let mut rng = SplitMix64::new(7);
    let mut w = Worst::default();
    for i in 0..24 {
        let n = 3 + i % 20;
        let s = sliver(&mut rng, n, 2f64.powi(10 + (i as i32 % 20)));
        let t = sliver(&mut rng, n + 3, 2f64.powi(12));
        w.merge(check::<Robust>(&s, &t));
        w.merge(check::<Robust>(&t, &s));
        for ulps in [1, 3] {
            let pair = convex_pair(&mut rng, n, n + 1, Relation::NearlyTouching { ulps });
            w.merge(check::<Robust>(&pair.p, &pair.q));
        }
    }
    println!("near-degenerate: {w:?}");
}

#[test]
fn exact_rational_hausdorff() {
    let mut rng = SplitMix64::new(11);
    for rel in Relation::EVERY {
        let pair = convex_pair(&mut rng, 9, 12, rel);
        let (Ok(p), Ok(q)) = (
            ConvexPolygon::try_new(&pair.p),
            ConvexPolygon::try_new(&pair.q),
        ) else {
            continue;
        };
        assert_eq!(
            hausdorff_squared_exact(&p, &q),
            hausdorff_filled(p.vertices(), q.vertices()),
            "{rel:?}"
        );
    }
}

#[test]
fn fast_kernel_terminates_and_is_measured() {
    let mut rng = SplitMix64::new(5);
    let (mut cases, mut wrong_h, mut wrong_c) = (0, 0, 0);
    for round in 0..40 {
        let n = 3 + round % 37;
        for (p, q) in relation_pairs(&mut rng, n, n + 2) {
            let (Ok(p), Ok(q)) = (ConvexPolygon::try_new(&p), ConvexPolygon::try_new(&q)) else {
                continue;
            };
            cases += 1;
            let h = hausdorff_with::<Fast>(&p, &q);
            let c = cmmr_with::<Fast>(&p, &q);
            let e = hausdorff_filled(p.vertices(), q.vertices());
            if ulps_error_sqrt(h.distance, &e).total_cmp(&HAUSDORFF_ULPS) == Ordering::Greater
                || h.distance.is_nan()
            {
                wrong_h += 1;
            }
            let ce = polydist_oracle::cmmr(p.vertices(), q.vertices());
            let bad = if ce == zero() {
                c.value != 0.0
            } else {
                ulps_error(c.value, &ce).total_cmp(&CMMR_ULPS) == Ordering::Greater
                    || c.value.is_nan()
            };
            if bad {
                wrong_c += 1;
            }
        }
    }
    println!(
        "fast: {cases} pairs, Hausdorff beyond 3.5 ulps in {wrong_h}, CMMR beyond 6 ulps in {wrong_c}"
    );
    assert!(cases > 0);
}

/// Predicate calls per vertex of `hausdorff` + `cmmr` (four walks) at size `n` (both polygons `n`-gons).
fn calls_per_vertex(seed: u64, n: usize, offset: DVec2) -> f64 {
    let mut rng = SplitMix64::new(seed);
    let p = ConvexPolygon::try_new(&random_convex(&mut rng, n, DVec2::ZERO, 1.0))
        .unwrap_or_else(|e| panic!("{e}"));
    let q = ConvexPolygon::try_new(&random_convex(&mut rng, n, offset, 1.0))
        .unwrap_or_else(|e| panic!("{e}"));
    reset_predicate_counts();
    reset_walk_fallbacks();
    let _ = hausdorff_with::<Counted<Robust>>(&p, &q);
    let _ = cmmr_with::<Counted<Robust>>(&p, &q);
    assert_eq!(walk_fallbacks(), 0);
    predicate_counts().total() as f64 / (2 * n) as f64
}

#[test]
fn linear_growth_by_counting_predicates() {
    for offset in [
        DVec2::ZERO,
        DVec2::new(0.7, 0.3),
        DVec2::new(5.0, 0.0),
        DVec2::new(1.9, 1.9),
    ] {
        let mut per = Vec::new();
        for (i, n) in [100usize, 1_000, 10_000, 100_000].into_iter().enumerate() {
            per.push((n, calls_per_vertex(i as u64 + 3, n, offset)));
        }
        println!("offset {offset}: predicate calls per vertex {per:?}");
        let first = per[0].1;
        for &(n, c) in &per {
            // A constant per vertex: the walk's proved bound is about 3 + 6m/n + m/n region tests of
            // at most 3 predicates, plus the argmax comparisons.
            assert!(c <= 60.0, "n = {n}: {c} calls per vertex");
            assert!(
                c <= 1.5 * first + 10.0,
                "n = {n}: {c} per vertex against {first} at n = 100"
            );
        }
    }
}

/// A regular `n`-gon of radius `r`, rotated by `phase` (float vertices; strictly convex for these `n`).
fn regular(n: usize, r: f64, phase: f64) -> ConvexPolygon {
    let v: Vec<DVec2> = (0..n)
        .map(|i| {
            let t = phase + core::f64::consts::TAU * i as f64 / n as f64;
            DVec2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    ConvexPolygon::try_new(&v).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn linear_growth_on_adversarial_families() {
    // Two regular n-gons, one rotated by half a step: 2n crossings, n pieces of one vertex each; and a
    // thin sliver inside a large polygon (the walk of the large one circles the sliver).
    for (name, make) in [
        (
            "rotated n-gons",
            (|n| {
                (
                    regular(n, 1.0, 0.0),
                    regular(n, 1.0, core::f64::consts::PI / n as f64),
                )
            }) as fn(usize) -> (ConvexPolygon, ConvexPolygon),
        ),
        ("sliver inside", |n| {
            let mut rng = SplitMix64::new(n as u64);
            let s = sliver(&mut rng, n, 2f64.powi(20));
            (
                regular(n, 1e6, 0.1),
                ConvexPolygon::try_new(&s).unwrap_or_else(|e| panic!("{e}")),
            )
        }),
    ] {
        let mut per = Vec::new();
        for n in [100usize, 1_000, 10_000] {
            let (p, q) = make(n);
            if name == "rotated n-gons" {
                assert_eq!(polydist_convex::boundary_crossings(&p, &q).len(), 2 * n);
            }
            reset_predicate_counts();
            reset_walk_fallbacks();
            let _ = hausdorff_with::<Counted<Robust>>(&p, &q);
            let _ = cmmr_with::<Counted<Robust>>(&p, &q);
            assert_eq!(walk_fallbacks(), 0);
            per.push((
                n,
                predicate_counts().total() as f64 / (p.len() + q.len()) as f64,
            ));
        }
        println!("{name}: predicate calls per vertex {per:?}");
        for &(n, c) in &per {
            assert!(c <= 60.0, "{name}, n = {n}: {c} calls per vertex");
            assert!(
                c <= 1.5 * per[0].1 + 10.0,
                "{name}, n = {n}: {c} against {}",
                per[0].1
            );
        }
    }
}

#[test]
fn brute_force_is_quadratic_by_count() {
    // The twin really is the O(nm) baseline (and the walk is not).
    let mut rng = SplitMix64::new(9);
    let p = ConvexPolygon::try_new(&random_convex(&mut rng, 400, DVec2::ZERO, 1.0))
        .unwrap_or_else(|e| panic!("{e}"));
    let q = ConvexPolygon::try_new(&random_convex(&mut rng, 400, DVec2::new(3.0, 0.0), 1.0))
        .unwrap_or_else(|e| panic!("{e}"));
    reset_predicate_counts();
    let _ = per_vertex_distances_brute::<Counted<Robust>>(&p, &q);
    let brute = predicate_counts().total();
    reset_predicate_counts();
    let _ = per_vertex_distances_with::<Counted<Robust>>(&p, &q);
    let walk = predicate_counts().total();
    assert!(brute > 400 * 400, "{brute}");
    assert!(walk < 20 * 800, "{walk}");
    assert_eq!(walk.cmp(&brute), Ordering::Less);
}

#[test]
fn random_signs_terminate_without_panic() {
    let mut rng = SplitMix64::new(23);
    reset_walk_fallbacks();
    let mut runs = 0;
    for round in 0..60 {
        let n = 3 + round % 50;
        let (p, q) = overlapping(&mut rng, n, n + 3);
        let (p, q) = (
            ConvexPolygon::try_new(&p).unwrap_or_else(|e| panic!("{e}")),
            ConvexPolygon::try_new(&q).unwrap_or_else(|e| panic!("{e}")),
        );
        let h = hausdorff_with::<Chaos>(&p, &q);
        let c = cmmr_with::<Chaos>(&p, &q);
        let x = polydist_convex::boundary_crossings_with::<Chaos>(&p, &q);
        assert_eq!(c.p_to_q.len(), p.len());
        assert_eq!(c.q_to_p.len(), q.len());
        assert!(h.distance >= 0.0 && x.len() <= 12 * (p.len() + q.len()) + 32);
        runs += 4;
    }
    println!(
        "chaos: {runs} walks, {} ran out of budget",
        walk_fallbacks()
    );
}

/// A kernel that answers "negative" to everything: no region test ever passes and the walk cycles
/// between regions until its step budget runs out; the brute force must then answer, in finite time.
#[derive(Clone, Copy, Debug, Default)]
struct AlwaysNegative;

impl Kernel for AlwaysNegative {
    const NAME: &'static str = "always-negative";
    const EXACT_DECISIONS: bool = false;
    type Guide = AlwaysNegative;
    fn sign<const N: usize, P: polydist_convex::polygon::predicates::Polynomial<N> + ?Sized>(
        _: &P,
        _: &[f64; N],
    ) -> polydist_convex::polygon::predicates::Sign {
        polydist_convex::polygon::predicates::Sign::Negative
    }
}

#[test]
fn exhausted_budget_falls_back_to_the_brute_force() {
    let mut rng = SplitMix64::new(29);
    reset_walk_fallbacks();
    for n in [3, 10, 100] {
        let (p, q) = overlapping(&mut rng, n, n + 5);
        let (p, q) = (
            ConvexPolygon::try_new(&p).unwrap_or_else(|e| panic!("{e}")),
            ConvexPolygon::try_new(&q).unwrap_or_else(|e| panic!("{e}")),
        );
        let c = cmmr_with::<AlwaysNegative>(&p, &q);
        assert_eq!((c.p_to_q.len(), c.q_to_p.len()), (p.len(), q.len()));
        let _ = hausdorff_with::<AlwaysNegative>(&p, &q);
    }
    assert!(walk_fallbacks() > 0, "the budget never ran out");
}

/// The exact nearest point of the boundary of `q` (strictly convex, CCW, ≥ 3 vertices) to `v` outside
/// it, as rationals `(x, y, squared distance)`: every edge, the foot clamped to it, the nearest kept.
fn exact_projection(v: DVec2, q: &[DVec2]) -> (BigRational, BigRational, BigRational) {
    use polydist_convex::polygon::predicates::exact::to_rational;
    let r = |x: f64| to_rational(x).unwrap_or_else(zero);
    let (vx, vy) = (r(v.x), r(v.y));
    let mut best: Option<(BigRational, BigRational, BigRational)> = None;
    for i in 0..q.len() {
        let (a, b) = (q[i], q[(i + 1) % q.len()]);
        let (ax, ay) = (r(a.x), r(a.y));
        let (ex, ey) = (r(b.x) - &ax, r(b.y) - &ay);
        let l = &ex * &ex + &ey * &ey;
        let mut t = ((&vx - &ax) * &ex + (&vy - &ay) * &ey) / &l;
        if t < zero() {
            t = zero();
        }
        let one = BigRational::from_integer(1.into());
        if t > one {
            t = one;
        }
        let (fx, fy) = (&ax + &t * &ex, &ay + &t * &ey);
        let d2 = (&vx - &fx) * (&vx - &fx) + (&vy - &fy) * (&vy - &fy);
        if best.as_ref().is_none_or(|b| d2 < b.2) {
            best = Some((fx, fy, d2));
        }
    }
    best.unwrap_or_else(|| (zero(), zero(), zero()))
}

#[test]
fn projections_within_their_bounds() {
    // Bulk lists: within 0.5 ulp + 16u·δ per coordinate; Hausdorff winners: within 1 ulp.
    const U: f64 = f64::EPSILON / 2.0;
    let mut rng = SplitMix64::new(31);
    let (mut worst_bulk, mut worst_winner) = (0.0f64, 0.0f64);
    for round in 0..6 {
        let n = 5 + 7 * round;
        let mut pairs = relation_pairs(&mut rng, n, n + 3);
        pairs.push(overlapping(&mut rng, n, n + 1));
        for (p, q) in pairs {
            let (Ok(p), Ok(q)) = (ConvexPolygon::try_new(&p), ConvexPolygon::try_new(&q)) else {
                continue;
            };
            if q.len() < 3 {
                continue;
            }
            for r in per_vertex_distances_with::<Robust>(&p, &q) {
                if r.location != Location::Outside {
                    continue;
                }
                let (fx, fy, _) = exact_projection(r.point, q.vertices());
                for (c, e) in [(r.projection.x, &fx), (r.projection.y, &fy)] {
                    let ulp = {
                        let a = polydist_oracle::to_f64_nearest(e).abs();
                        a.next_up() - a
                    };
                    let err = ulps_error(c, e);
                    let allowed = 0.5 + 16.0 * U * r.distance / ulp + 1e-9;
                    assert!(
                        err <= allowed.max(1.0),
                        "{r:?}: {err} ulps, allowed {allowed}"
                    );
                    worst_bulk = worst_bulk.max(err);
                }
            }
            let h = directed_hausdorff_with::<Robust>(&p, &q);
            if h.location == Location::Outside {
                let (fx, fy, _) = exact_projection(h.point, q.vertices());
                for (c, e) in [(h.projection.x, &fx), (h.projection.y, &fy)] {
                    let err = ulps_error(c, e);
                    assert!(err <= 1.0, "{h:?}: {err} ulps");
                    worst_winner = worst_winner.max(err);
                }
            }
        }
    }
    println!("projections: bulk worst {worst_bulk:.3} ulps, winners worst {worst_winner:.3} ulps");
}

#[test]
fn extreme_scales() {
    // Exact power-of-two scalings of every relation: the plain first values overflow or fall below
    // their threshold and the exactly rounded paths take over; the bounds still hold.
    let mut rng = SplitMix64::new(37);
    let mut w = Worst::default();
    for e in [-480, -400, 400, 480] {
        let s = 2f64.powi(e);
        for (p, q) in relation_pairs(&mut rng, 7, 9) {
            let p: Vec<DVec2> = p.iter().map(|&v| v * s).collect();
            let q: Vec<DVec2> = q.iter().map(|&v| v * s).collect();
            w.merge(check::<Robust>(&p, &q));
        }
    }
    println!("extreme scales: {w:?}");
}
