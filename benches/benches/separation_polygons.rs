//! Separation of two whole simple polygons with disjoint convex hulls (Amato 1992, section 2's fast
//! path into section 3) beside the brute-force twin and the peers, `N` vertices in all:
//!
//! - `polygons/stars`: two spiky star-shaped polygons (alternating radii 1 and 0.35–0.65) side by side;
//! - `polygons/spirals`: two double-walled spirals side by side;
//! - `polygons/combs`: two combs whose teeth face each other tip to tip (not interleaved);
//! - `polygons/sawteeth`: two saw-tooth slabs facing each other, the tips of one opposite the notches
//!   of the other: the closest hull features are lids, and both facing chains are monotone along
//!   the separating line, so the monotone sweep answers (section 3 in `query_robust_section3`; the
//!   others mostly end at the hull shortcut);
//! - `polygons/hooked_teeth`: the same slabs with hooked teeth (each tip overhangs the notch behind
//!   it, `polydist_oracle::hooked_teeth_facing`): neither facing chain is monotone along the
//!   separating line, so the monotone sweep declines and section 3 answers, by its envelope sweep
//!   (Lemma 2's envelopes are monotone; `query_robust_section3` runs its matrices instead);
//! - `polygons/interlocked_combs`: two combs whose teeth interleave, clearance 1/8: the hulls meet,
//!   so the query goes through Amato's separator (triangulation of the region between the facing
//!   chains, geodesic, extensions, greedy pruning, subchains). Every clearance ties exactly;
//! - `polygons/interlocked_combs_jittered`: the same combs with every vertex moved by a random dyadic
//!   amount below 1/64 in x and y (clearances between 1/8 − 1/32 and 1/8 + 1/32, no exact ties);
//! - `polygons/pocket`: a spiky star (`N/2` vertices, radii 1 and 0.5) in the pocket of a "C" (an
//!   outer arc of radius 4 and a wavy inner arc of radii 2 and 2.5, `N/2` vertices, open over half a
//!   radian): one hull inside the other, the separator's containing case (two passes). Up to a
//!   million vertices (capped at 131,072 until 2026-12-07, when its largest subproblems went to
//!   section 3's matrices there: `docs/algorithms/separator.md`);
//! - `polygons/interlocked_spirals`: two spiral arms turned half a turn from each other, nested one
//!   unit apart (clearance 1/2, up to six turns): the separator's long spiral corridor.
//! - `polygons/interlocked_stars`: two random stars (a spike every fourth vertex) pushed into each
//!   other until disjoint with meeting hulls; the lines of their separators pass through many
//!   spikes, so some subproblems go to section 3 on clipped chains (Step G), trimmed by the best
//!   answer and by their distance to the separator. Up to a million vertices (the stars' directions
//!   come from a wider lattice range beyond 131,072, `interlocked_stars`).
//! - `polygons/stars_lid`: two stars (radii 1 and 1/2) one unit apart, a notch of one facing a tip
//!   of the other (the hulls' nearest features a tip and a lid): the envelope sweep, whose windows
//!   along the line hold whole facing sides, thinned by depth;
//! - `polygons/bowl`: a zigzag 0.6 wide facing an arc of radius 1 around it (the bottom of a
//!   cap), clearance 0.89: the monotone sweep, its windows thinned by depth alone;
//! - `polygons/cluster`: the same zigzag `2⁻³⁰` per vertex wide: every pair within a hair of the
//!   clearance, so nothing prunes: section 3's matrices answer, and parry's BVH visits every pair
//!   (timed up to 4,096 only).
//!
//! - `polylines/toolpath`: an open polyline (the tooth profile of the mirrored saw-tooth slab, `N/2`
//!   vertices, tips opposite notches `1/4` away) against the saw-tooth slab (`N/2` vertices):
//!   `polyline_to_polygon` (disjoint hulls, section 3 on the open chain) against parry2d-f64 (open
//!   against closed `Polyline`), geo (`LineString` against `Polygon`) and the chains' brute force.
//!
//! Series, per `N`:
//! - `validate`: building both `SimplePolygon`s (exact simplicity sweep), which a caller does once;
//! - `intersection`: the intersection check alone (`intersection::<Robust>`, `O(N log N)`);
//! - `query_fast`, `query_robust`, `query_exact`: `separation_of_disjoint::<K>` (the query alone;
//!   Exact up to 4,096);
//! - `query_robust_section3`: the same with `HullRouteMethod::Section3`: the disjoint-hull route
//!   without the monotone and envelope sweeps (section 3's matrices wherever the hull features do
//!   not answer), so the sweeps' gain and the paper's algorithm's own cost can be read apart;
//! - `brute_robust`: `polygon_separation_brute::<Robust>` (`Θ(nm)`, up to 4,096);
//! - `parry_query`: parry2d-f64 `query::distance` between two prebuilt closed `Polyline`s (BVH);
//! - `parry_build_query`: building both polylines and the query;
//! - `geo`: geo's `Euclidean.distance(&Polygon, &Polygon)` (up to 32,768, the size of the 100×
//!   target: about 1.5 s a query there, 35 s at 131,072).
//!
//! Before timing, every peer's distance is checked against polydist's (relative 1e-9). Run:
//! `cargo bench -p polydist-benches --bench separation_polygons`; with `POLYDIST_BENCH_ONLY=sawteeth`
//! (any part of a group name) only that family is set up and timed. Figures only.

use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use geo::{Distance, Euclidean, LineString, Polygon};
use glam::DVec2;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::Polyline;
use polydist_benches::{
    bowl, cluster, hooked_teeth, interlocked_combs, interlocked_combs_jittered,
    interlocked_spirals, interlocked_stars, pocket, sawteeth, stars_lid,
};
use polydist_oracle::SplitMix64;
use polydist_polygon::SimplePolygon;
use polydist_predicates::{Exact, Fast, Kernel, Robust};
use polydist_separation::{
    HullRouteMethod, intersection, polygon_separation_brute, polyline_to_polygon, separation_brute,
    separation_of_disjoint, separation_of_disjoint_with,
};

/// Total vertices.
const SIZES: [usize; 6] = [64, 512, 4096, 32_768, 131_072, 1_048_576];
const SMALL_MAX: usize = 4096;
/// geo up to the size of the target against it (100× at 32,768): about 1.5 s a query there.
const GEO_MAX: usize = 32_768;

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1500));
}

/// A spiky star of `n` vertices around `c`: angles `2πk/n`, radius 1 at even `k` and a random
/// radius in `[0.35, 0.65]` at odd `k` (star-shaped, hence simple).
fn star(rng: &mut SplitMix64, n: usize, c: DVec2) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let t = TAU * k as f64 / n as f64;
            let r = if k % 2 == 0 {
                1.0
            } else {
                0.35 + 0.3 * rng.unit_f64()
            };
            c + DVec2::new(t.cos(), t.sin()) * r
        })
        .collect()
}

/// Two polygons, the second moved right of the first's bounding box by `gap`.
fn side_by_side(p: Vec<DVec2>, q: &[DVec2], gap: f64) -> (Vec<DVec2>, Vec<DVec2>) {
    let max_x = p.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
    let min_x = q.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
    let dx = max_x - min_x + gap;
    (p, q.iter().map(|&v| v + DVec2::new(dx, 0.0)).collect())
}

fn stars(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(0x57a5 ^ n as u64);
    let p = star(&mut rng, n / 2, DVec2::ZERO);
    let q = star(&mut rng, n / 2, DVec2::ZERO);
    side_by_side(p, &q, 0.25)
}

fn spirals(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    // `spiral(per_turn, turns)` has 2 (per_turn · turns + 1) vertices.
    let turns = 4;
    let per_turn = ((n / 2) / (2 * turns as usize)).max(3) as u32;
    let s = polydist_oracle::spiral(per_turn, turns);
    side_by_side(s.clone(), &s, 0.5)
}

fn combs(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let teeth = (n / 8).max(1);
    let a = polydist_oracle::comb(teeth, 5, 1);
    // The second comb, teeth down, its tips one unit above the first's.
    let top = a.iter().map(|v| v.y).fold(f64::NEG_INFINITY, f64::max);
    let b: Vec<DVec2> = a
        .iter()
        .rev()
        .map(|v| DVec2::new(v.x, 2.0 * top + 1.0 - v.y))
        .collect();
    (a, b)
}

fn polyline(c: &[DVec2]) -> Polyline {
    let mut pts: Vec<Vector> = c.iter().map(|v| Vector::new(v.x, v.y)).collect();
    pts.push(pts[0]);
    Polyline::new(pts, None)
}

fn parry(p: &Polyline, q: &Polyline) -> f64 {
    let id = Pose::identity();
    query::distance(&id, p, &id, q).expect("supported")
}

fn geo_polygon(c: &[DVec2]) -> Polygon<f64> {
    Polygon::new(
        LineString::from(c.iter().map(|v| (v.x, v.y)).collect::<Vec<_>>()),
        vec![],
    )
}

fn query<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon) -> f64 {
    separation_of_disjoint::<K>(p, q)
        .expect("disjoint polygons")
        .distance()
}

fn run(c: &mut Criterion, name: &str, make: fn(usize) -> (Vec<DVec2>, Vec<DVec2>), max_n: usize) {
    run_capped(c, name, make, (max_n, usize::MAX));
}

/// [`run`] with parry2d timed up to `parry_max` vertices only (where its BVH prunes nothing, a
/// query is quadratic: 12 s at 32,768 on the crowded cluster).
fn run_capped(
    c: &mut Criterion,
    name: &str,
    make: fn(usize) -> (Vec<DVec2>, Vec<DVec2>),
    (max_n, parry_max): (usize, usize),
) {
    // The set-up (inputs, and the brute force, geo and parry checked against us) costs minutes in all:
    // `POLYDIST_BENCH_ONLY=<part of a group name>` skips the other families entirely.
    if std::env::var("POLYDIST_BENCH_ONLY").is_ok_and(|only| !name.contains(only.as_str())) {
        return;
    }
    let mut group = c.benchmark_group(name);
    configure(&mut group);
    for n in SIZES.into_iter().filter(|&n| n <= max_n) {
        let (a, b) = make(n);
        let (p, q) = (
            SimplePolygon::try_new(&a).expect("simple"),
            SimplePolygon::try_new(&b).expect("simple"),
        );
        assert!(intersection::<Robust>(&p, &q).is_none(), "{name}: disjoint");
        let d = query::<Robust>(&p, &q);
        let rel = |x: f64| ((x - d) / d).abs();
        let (pp, pq) = (polyline(&a), polyline(&b));
        if n <= parry_max {
            assert!(rel(parry(&pp, &pq)) < 1e-9, "{name} n={n}: parry disagrees");
        }
        if n <= SMALL_MAX {
            let brute = polygon_separation_brute::<Robust>(&p, &q)
                .expect("valid")
                .distance();
            assert!(rel(brute) < 1e-12, "{name} n={n}: brute disagrees");
        }
        if n <= GEO_MAX {
            let g = Euclidean.distance(&geo_polygon(&a), &geo_polygon(&b));
            assert!(rel(g) < 1e-9, "{name} n={n}: geo disagrees");
        }
        group.bench_with_input(BenchmarkId::new("validate", n), &(&a, &b), |bch, (a, b)| {
            bch.iter(|| {
                let p = SimplePolygon::try_new(black_box(a)).expect("simple");
                let q = SimplePolygon::try_new(black_box(b)).expect("simple");
                (p.len(), q.len())
            })
        });
        group.bench_with_input(
            BenchmarkId::new("intersection", n),
            &(&p, &q),
            |bch, (p, q)| bch.iter(|| intersection::<Robust>(black_box(p), black_box(q))),
        );
        group.bench_with_input(
            BenchmarkId::new("query_fast", n),
            &(&p, &q),
            |bch, (p, q)| bch.iter(|| query::<Fast>(black_box(p), black_box(q))),
        );
        group.bench_with_input(
            BenchmarkId::new("query_robust", n),
            &(&p, &q),
            |bch, (p, q)| bch.iter(|| query::<Robust>(black_box(p), black_box(q))),
        );
        group.bench_with_input(
            BenchmarkId::new("query_robust_section3", n),
            &(&p, &q),
            |bch, (p, q)| {
                bch.iter(|| {
                    separation_of_disjoint_with::<Robust>(
                        black_box(p),
                        black_box(q),
                        HullRouteMethod::Section3,
                    )
                    .expect("disjoint polygons")
                    .distance()
                })
            },
        );
        if n <= SMALL_MAX {
            group.bench_with_input(
                BenchmarkId::new("query_exact", n),
                &(&p, &q),
                |bch, (p, q)| bch.iter(|| query::<Exact>(black_box(p), black_box(q))),
            );
            group.bench_with_input(
                BenchmarkId::new("brute_robust", n),
                &(&p, &q),
                |bch, (p, q)| {
                    bch.iter(|| {
                        polygon_separation_brute::<Robust>(black_box(p), black_box(q))
                            .expect("valid")
                            .distance()
                    })
                },
            );
        }
        if n <= GEO_MAX {
            let (ga, gb) = (geo_polygon(&a), geo_polygon(&b));
            group.bench_with_input(BenchmarkId::new("geo", n), &(ga, gb), |bch, (p, q)| {
                bch.iter(|| Euclidean.distance(black_box(p), black_box(q)))
            });
        }
        if n > parry_max {
            continue;
        }
        group.bench_with_input(
            BenchmarkId::new("parry_query", n),
            &(pp, pq),
            |bch, (p, q)| bch.iter(|| parry(black_box(p), black_box(q))),
        );
        group.bench_with_input(
            BenchmarkId::new("parry_build_query", n),
            &(&a, &b),
            |bch, (a, b)| {
                bch.iter(|| {
                    let (p, q) = (polyline(black_box(a)), polyline(black_box(b)));
                    parry(&p, &q)
                })
            },
        );
    }
    group.finish();
}

/// The saw-tooth slab and, as an open polyline, the tooth profile of its mirror image (the mirror's
/// vertices left of its back, in order).
fn toolpath(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let (slab, mirror) = sawteeth(n);
    let back = mirror.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
    // The mirror's back corners are consecutive on its ring: rotate them to the end, then drop them.
    let k = mirror.len();
    let start = (0..k)
        .find(|&i| mirror[i].x == back && mirror[(i + k - 1) % k].x != back)
        .expect("a back corner");
    let path: Vec<DVec2> = (0..k)
        .map(|i| mirror[(start + i) % k])
        .filter(|v| v.x != back)
        .collect();
    (slab, path)
}

fn polylines(c: &mut Criterion) {
    let name = "polylines/toolpath";
    if std::env::var("POLYDIST_BENCH_ONLY").is_ok_and(|only| !name.contains(only.as_str())) {
        return;
    }
    let mut group = c.benchmark_group(name);
    configure(&mut group);
    let open = |c: &[DVec2]| Polyline::new(c.iter().map(|v| Vector::new(v.x, v.y)).collect(), None);
    let ours = |t: &[DVec2], q: &SimplePolygon, fast: bool| {
        let s = if fast {
            polyline_to_polygon::<Fast>(t, q)
        } else {
            polyline_to_polygon::<Robust>(t, q)
        };
        s.expect("disjoint hulls").distance()
    };
    for n in SIZES {
        let (slab, path) = toolpath(n);
        let q = SimplePolygon::try_new(&slab).expect("simple");
        let d = ours(&path, &q, false);
        let rel = |x: f64| ((x - d) / d).abs();
        let (pt, pq) = (open(&path), polyline(&slab));
        assert!(rel(parry(&pt, &pq)) < 1e-9, "{name} n={n}: parry disagrees");
        let mut closed = slab.clone();
        closed.push(slab[0]);
        let geo_path = LineString::from(path.iter().map(|v| (v.x, v.y)).collect::<Vec<_>>());
        if n <= SMALL_MAX {
            let brute = separation_brute::<Robust>(&path, &closed).expect("valid");
            assert!(rel(brute.distance) < 1e-12, "{name} n={n}: brute disagrees");
            let g = Euclidean.distance(&geo_path, &geo_polygon(&slab));
            assert!(rel(g) < 1e-9, "{name} n={n}: geo disagrees");
        }
        for (series, fast) in [("query_fast", true), ("query_robust", false)] {
            group.bench_with_input(BenchmarkId::new(series, n), &(&path, &q), |bch, (t, q)| {
                bch.iter(|| ours(black_box(t), black_box(q), fast))
            });
        }
        if n <= SMALL_MAX {
            group.bench_with_input(
                BenchmarkId::new("brute_robust", n),
                &(&path, &closed),
                |bch, (t, q)| {
                    bch.iter(|| {
                        separation_brute::<Robust>(black_box(t), black_box(q))
                            .expect("valid")
                            .distance
                    })
                },
            );
            let gq = geo_polygon(&slab);
            group.bench_with_input(
                BenchmarkId::new("geo", n),
                &(&geo_path, &gq),
                |bch, (t, q)| bch.iter(|| Euclidean.distance(black_box(*t), black_box(*q))),
            );
        }
        group.bench_with_input(
            BenchmarkId::new("parry_query", n),
            &(pt, pq),
            |bch, (t, q)| bch.iter(|| parry(black_box(t), black_box(q))),
        );
        group.bench_with_input(
            BenchmarkId::new("parry_build_query", n),
            &(&path, &slab),
            |bch, (t, q)| bch.iter(|| parry(&open(black_box(t)), &polyline(black_box(q)))),
        );
    }
    group.finish();
}

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    run(&mut c, "polygons/stars", stars, usize::MAX);
    run(&mut c, "polygons/spirals", spirals, usize::MAX);
    run(&mut c, "polygons/combs", combs, usize::MAX);
    run(&mut c, "polygons/sawteeth", sawteeth, usize::MAX);
    run(&mut c, "polygons/hooked_teeth", hooked_teeth, usize::MAX);
    run(
        &mut c,
        "polygons/interlocked_combs",
        interlocked_combs,
        usize::MAX,
    );
    run(
        &mut c,
        "polygons/interlocked_combs_jittered",
        interlocked_combs_jittered,
        usize::MAX,
    );
    run(
        &mut c,
        "polygons/interlocked_spirals",
        interlocked_spirals,
        usize::MAX,
    );
    run(
        &mut c,
        "polygons/interlocked_stars",
        interlocked_stars,
        usize::MAX,
    );
    run(&mut c, "polygons/pocket", pocket, usize::MAX);
    run(&mut c, "polygons/stars_lid", stars_lid, usize::MAX);
    run(&mut c, "polygons/bowl", bowl, usize::MAX);
    // Up to 131,072 (section 3's matrices: 0.5 s a Robust query there); parry up to 4,096.
    run_capped(&mut c, "polygons/cluster", cluster, (131_072, 4096));
    polylines(&mut c);
    c.final_summary();
}

criterion_main!(benches);
