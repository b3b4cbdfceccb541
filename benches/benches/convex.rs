//! Convex–convex distance: polydist's `O(log m + log n)` search (Yang 2006, exact predicates) beside
//! its brute-force twin and two peers, on two disjoint random convex `n`-gons (`m = n`):
//!
//! - W1 (`convex/random_dir`): the second polygon's centre along a random direction;
//! - W2 (`convex/plus_x`): along `+x`.
//!
//! Series, per `n` in 8 … 262,144:
//! - `polydist_{fast,robust,exact}`: `distance_with::<K>` (the scan below `SCAN_BELOW`, the certified
//!   support guess below `n + m = 512` and the linear walk below `n + m = 64`, else the search);
//! - `yang_{fast,robust,exact}`: `distance_yang_with::<K>` (Yang's search at every size);
//! - `schwartz_{fast,robust,exact}`: `distance_schwartz_with::<K>` (Schwartz's `O(log² N)` search);
//! - `brute_robust`: `distance_brute::<Robust>` (`Θ(nm)`, up to `n = 512`);
//! - `parry_distance`, `parry_closest_points`: parry2d-f64's `query::distance` / `closest_points`
//!   (GJK on the polygons' support maps);
//! - `geo_euclidean`: geo's `Euclidean.distance(&Polygon, &Polygon)` (up to `n = 4096`).
//!
//! A second group, `convex/crossover`, times the scan against the search for `n = m = 3 … 32` on
//! batches of random pairs, to place `SCAN_BELOW`.
//!
//! Before timing, every series' distance is checked against polydist's (relative 1e-9), so a peer that
//! answers another question (or a pair that is not disjoint) stops the run.
//!
//! Run: `cargo bench -p polydist-benches --bench convex`. Figures only; nothing else is asserted.
//! Instruction counts of single queries (exact, unlike timings on a shared machine): the example
//! `convex_callgrind` under `valgrind --tool=callgrind` (see its doc).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use geo::{Distance, Euclidean, LineString, Polygon};
use glam::DVec2;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{self, ClosestPoints};
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Kernel, Robust};
use polydist_convex::{
    Separation, distance_brute, distance_schwartz_with, distance_with, distance_yang_with,
};
use polydist_oracle::{SplitMix64, random_convex};

/// 8 … 262,144 vertices per polygon.
const SIZES: [usize; 8] = [8, 16, 32, 64, 512, 4096, 32_768, 262_144];
/// The largest size for the `Θ(nm)` brute force.
const BRUTE_MAX: usize = 512;
/// The largest size for geo (`O(nm)`).
const GEO_MAX: usize = 4096;
/// Pairs per iteration in the crossover sweep (averages over the geometry of small polygons).
const BATCH: usize = 16;

/// Small samples and short measurements: the whole file runs in a few minutes on two cores.
fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(1));
}

/// One disjoint pair in every representation.
struct Pair {
    p: ConvexPolygon,
    q: ConvexPolygon,
    parry_p: ParryPolygon,
    parry_q: ParryPolygon,
    geo_p: Polygon<f64>,
    geo_q: Polygon<f64>,
}

/// Where the second polygon goes.
#[derive(Clone, Copy)]
enum Workload {
    /// W1: along a random direction.
    RandomDir,
    /// W2: along `+x`.
    PlusX,
}

impl Workload {
    fn name(self) -> &'static str {
        match self {
            Workload::RandomDir => "convex/random_dir",
            Workload::PlusX => "convex/plus_x",
        }
    }
}

/// Two random convex `n`- and `m`-gons in squares of half-side 1 (within `√2` of their centres), the
/// centres `3 + gap` apart: disjoint.
fn rings(rng: &mut SplitMix64, n: usize, m: usize, w: Workload) -> (Vec<DVec2>, Vec<DVec2>) {
    let dir = match w {
        Workload::RandomDir => {
            let t = rng.unit_f64() * core::f64::consts::TAU;
            DVec2::new(t.cos(), t.sin())
        }
        Workload::PlusX => DVec2::X,
    };
    let gap = 0.05 + 0.5 * rng.unit_f64();
    let p = random_convex(rng, n, DVec2::ZERO, 1.0);
    let q = random_convex(rng, m, dir * (3.0 + gap), 1.0);
    (p, q)
}

fn parry_polygon(ring: &[DVec2]) -> ParryPolygon {
    let pts = ring.iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("a polygon with area")
}

fn geo_polygon(ring: &[DVec2]) -> Polygon<f64> {
    let pts: Vec<(f64, f64)> = ring.iter().map(|v| (v.x, v.y)).collect();
    Polygon::new(LineString::from(pts), vec![])
}

fn make_pair(n: usize, w: Workload) -> Pair {
    let mut rng = SplitMix64::new(0x00C0_FFEE ^ n as u64);
    let (p, q) = rings(&mut rng, n, n, w);
    Pair {
        parry_p: parry_polygon(&p),
        parry_q: parry_polygon(&q),
        geo_p: geo_polygon(&p),
        geo_q: geo_polygon(&q),
        p: ConvexPolygon::try_new(&p).expect("valid P"),
        q: ConvexPolygon::try_new(&q).expect("valid Q"),
    }
}

fn parry_distance(pair: &Pair) -> f64 {
    let id = Pose::identity();
    query::distance(&id, &pair.parry_p, &id, &pair.parry_q).expect("supported")
}

fn parry_closest(pair: &Pair) -> ClosestPoints {
    let id = Pose::identity();
    query::closest_points(&id, &pair.parry_p, &id, &pair.parry_q, f64::MAX).expect("supported")
}

fn geo_distance(pair: &Pair) -> f64 {
    Euclidean.distance(&pair.geo_p, &pair.geo_q)
}

/// Every series answers the same distance: polydist's to 4 ulps or so (relative 1e-15), the peers to a
/// relative 1e-6 (GJK stops at a tolerance; their relative errors are printed).
fn check(pair: &Pair, n: usize) {
    let Separation::Disjoint(c) = distance_with::<Robust>(&pair.p, &pair.q) else {
        panic!("n = {n}: the pair is not disjoint");
    };
    let d = c.distance;
    let close = |x: f64, tol: f64, what: &str| {
        let rel = (x - d).abs() / d;
        assert!(rel <= tol, "n = {n}: {what} = {x}, polydist = {d}");
        rel
    };
    close(
        distance_with::<Fast>(&pair.p, &pair.q).distance(),
        1e-15,
        "fast",
    );
    close(
        distance_with::<Exact>(&pair.p, &pair.q).distance(),
        1e-15,
        "exact",
    );
    close(
        distance_yang_with::<Robust>(&pair.p, &pair.q).distance(),
        1e-15,
        "yang",
    );
    if n <= BRUTE_MAX {
        close(
            distance_brute::<Robust>(&pair.p, &pair.q).distance(),
            1e-15,
            "brute",
        );
    }
    let parry = close(parry_distance(pair), 1e-6, "parry distance");
    let parry_cp = match parry_closest(pair) {
        ClosestPoints::WithinMargin(a, b) => close(a.distance(b), 1e-6, "parry closest_points"),
        other => panic!("n = {n}: parry closest_points = {other:?}"),
    };
    let geo = if n <= GEO_MAX {
        close(geo_distance(pair), 1e-6, "geo")
    } else {
        f64::NAN
    };
    eprintln!(
        "n = {n}: distance {d}; relative error: parry {parry:.1e}, parry closest_points {parry_cp:.1e}, geo {geo:.1e}"
    );
}

/// One polydist series: `query` on the pair's polygons.
fn polydist_series(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    n: usize,
    pair: &Pair,
    query: fn(&ConvexPolygon, &ConvexPolygon) -> Separation,
) {
    group.bench_with_input(BenchmarkId::new(name, n), pair, |b, s| {
        b.iter(|| query(black_box(&s.p), black_box(&s.q)))
    });
}

/// Every polydist series: `distance_with`, the search alone (`distance_yang_with`) and Schwartz's
/// search (`distance_schwartz_with`), each under the three kernels.
fn polydist_all(group: &mut BenchmarkGroup<'_, WallTime>, n: usize, pair: &Pair) {
    fn under<K: Kernel>() -> [fn(&ConvexPolygon, &ConvexPolygon) -> Separation; 3] {
        [
            distance_with::<K>,
            distance_yang_with::<K>,
            distance_schwartz_with::<K>,
        ]
    }
    for (kernel, queries) in [
        ("fast", under::<Fast>()),
        ("robust", under::<Robust>()),
        ("exact", under::<Exact>()),
    ] {
        for (algorithm, query) in ["polydist", "yang", "schwartz"].into_iter().zip(queries) {
            polydist_series(group, &format!("{algorithm}_{kernel}"), n, pair, query);
        }
    }
}

fn workload(c: &mut Criterion, w: Workload) {
    let mut group = c.benchmark_group(w.name());
    configure(&mut group);
    for n in SIZES {
        let pair = make_pair(n, w);
        check(&pair, n);
        polydist_all(&mut group, n, &pair);
        if n <= BRUTE_MAX {
            group.bench_with_input(BenchmarkId::new("brute_robust", n), &pair, |b, s| {
                b.iter(|| distance_brute::<Robust>(black_box(&s.p), black_box(&s.q)))
            });
        }
        group.bench_with_input(BenchmarkId::new("parry_distance", n), &pair, |b, s| {
            b.iter(|| parry_distance(black_box(s)))
        });
        group.bench_with_input(
            BenchmarkId::new("parry_closest_points", n),
            &pair,
            |b, s| b.iter(|| parry_closest(black_box(s))),
        );
        if n <= GEO_MAX {
            group.bench_with_input(BenchmarkId::new("geo_euclidean", n), &pair, |b, s| {
                b.iter(|| geo_distance(black_box(s)))
            });
        }
    }
    group.finish();
}

/// The scan (`distance_brute::<Robust>`) against the search (`distance_yang_with::<Robust>`) for
/// `n = m = 3 … 32`, each iteration over `BATCH` random disjoint pairs (half W1, half W2): divide the
/// time by `BATCH` for one query.
fn crossover(c: &mut Criterion) {
    let mut group = c.benchmark_group("convex/crossover");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(500));
    for n in 3..=32 {
        let mut rng = SplitMix64::new(0xC0_55 ^ n as u64);
        let pairs: Vec<(ConvexPolygon, ConvexPolygon)> = (0..BATCH)
            .map(|i| {
                let w = if i % 2 == 0 {
                    Workload::RandomDir
                } else {
                    Workload::PlusX
                };
                let (p, q) = rings(&mut rng, n, n, w);
                let p = ConvexPolygon::try_new(&p).expect("valid P");
                let q = ConvexPolygon::try_new(&q).expect("valid Q");
                assert_eq!(
                    distance_brute::<Robust>(&p, &q),
                    distance_yang_with::<Robust>(&p, &q),
                    "n = {n}: scan and search disagree"
                );
                (p, q)
            })
            .collect();
        group.bench_with_input(BenchmarkId::new("scan", n), &pairs, |b, s| {
            b.iter(|| {
                for (p, q) in s {
                    black_box(distance_brute::<Robust>(black_box(p), black_box(q)));
                }
            })
        });
        group.bench_with_input(BenchmarkId::new("yang", n), &pairs, |b, s| {
            b.iter(|| {
                for (p, q) in s {
                    black_box(distance_yang_with::<Robust>(black_box(p), black_box(q)));
                }
            })
        });
    }
    group.finish();
}

/// Every group of this file (what `criterion_group!` would generate, documented).
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    workload(&mut c, Workload::RandomDir);
    workload(&mut c, Workload::PlusX);
    crossover(&mut c);
}

criterion_main!(benches);
