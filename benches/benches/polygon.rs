//! Polygon layer: validation cost (convex O(n), simple O(n log n) sweep), Melkman's hull, and point
//! location, at sizes 64 … 65,536 on generated inputs, each beside a baseline:
//!
//! - `convex_try_new` beside Andrew's hull of the same points (building a convex polygon the other way);
//! - `simple_try_new` (Shamos–Hoey sweep) beside its `O(n²)` brute-force twin (small sizes only);
//! - `melkman` under the three kernels beside Andrew's monotone chain;
//! - `convex_locate` (`O(log n)`) under the three kernels beside the `O(n)` crossing number.
//!
//! Run: `cargo bench -p polydist-benches --bench polygon`. Figures only; nothing is asserted.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use glam::DVec2;
use polydist_oracle::{self as oracle, SplitMix64};
use polydist_polygon::predicates::{Exact, Fast, Kernel, Robust};
use polydist_polygon::{ConvexPolygon, Location, SimplePolygon, convex_hull};

/// 64, 256, …, 65,536.
const SIZES: [usize; 6] = [64, 256, 1024, 4096, 16_384, 65_536];
/// The largest size for the `O(n²)` brute force.
const BRUTE_MAX: usize = 4096;
/// Query points per `locate` iteration.
const QUERIES: usize = 1024;

/// Small samples and short measurements: the whole file runs in a few minutes on two cores.
fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
}

/// A star-shaped simple polygon with `n` vertices and deep notches.
fn star(n: usize) -> Vec<DVec2> {
    oracle::star(&mut SplitMix64::new(n as u64), n, n / 16)
}

/// A random strictly convex polygon with `n` vertices.
fn convex(n: usize) -> Vec<DVec2> {
    oracle::random_convex(&mut SplitMix64::new(n as u64), n, DVec2::ZERO, 1.0)
}

/// Query points spread over the bounding box of `poly` and a margin around it.
fn queries(poly: &[DVec2]) -> Vec<DVec2> {
    let (lo, hi) = poly
        .iter()
        .fold((poly[0], poly[0]), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let mut rng = SplitMix64::new(99);
    (0..QUERIES)
        .map(|_| lo + (hi - lo) * (DVec2::new(rng.unit_f64(), rng.unit_f64()) * 1.2 - 0.1))
        .collect()
}

fn validation(c: &mut Criterion) {
    let mut group = c.benchmark_group("convex_try_new");
    configure(&mut group);
    for n in SIZES {
        let ring = convex(n);
        group.bench_with_input(BenchmarkId::new("try_new", n), &ring, |b, r| {
            b.iter(|| ConvexPolygon::try_new(black_box(r)))
        });
        group.bench_with_input(BenchmarkId::new("andrew_hull", n), &ring, |b, r| {
            b.iter(|| convex_hull(black_box(r)))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("simple_try_new");
    configure(&mut group);
    for n in SIZES {
        let ring = star(n);
        group.bench_with_input(BenchmarkId::new("sweep", n), &ring, |b, r| {
            b.iter(|| SimplePolygon::try_new(black_box(r)))
        });
        if n <= BRUTE_MAX {
            group.bench_with_input(BenchmarkId::new("brute_force", n), &ring, |b, r| {
                b.iter(|| SimplePolygon::try_new_brute_force(black_box(r)))
            });
        }
    }
    group.finish();
}

fn melkman_with<K: Kernel>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    n: usize,
    poly: &SimplePolygon,
) {
    group.bench_with_input(
        BenchmarkId::new(format!("melkman_{}", K::NAME), n),
        poly,
        |b, p| b.iter(|| black_box(p).convex_hull_with::<K>()),
    );
}

fn hulls(c: &mut Criterion) {
    let mut group = c.benchmark_group("hull");
    configure(&mut group);
    for n in SIZES {
        let poly = SimplePolygon::try_new(&star(n)).expect("generated star polygons are simple");
        melkman_with::<Fast>(&mut group, n, &poly);
        melkman_with::<Robust>(&mut group, n, &poly);
        melkman_with::<Exact>(&mut group, n, &poly);
        group.bench_with_input(
            BenchmarkId::new("andrew_robust", n),
            poly.vertices(),
            |b, v| b.iter(|| convex_hull(black_box(v))),
        );
    }
    group.finish();
}

fn locate_with<K: Kernel>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    n: usize,
    poly: &ConvexPolygon,
    qs: &[DVec2],
) {
    group.bench_with_input(
        BenchmarkId::new(format!("convex_{}", K::NAME), n),
        qs,
        |b, qs| {
            b.iter(|| {
                qs.iter()
                    .filter(|&&q| poly.locate_with::<K>(black_box(q)) == Location::Inside)
                    .count()
            })
        },
    );
}

fn locate(c: &mut Criterion) {
    let mut group = c.benchmark_group("locate_1024_points");
    configure(&mut group);
    for n in SIZES {
        let ring = convex(n);
        let poly = ConvexPolygon::try_new(&ring).expect("generated convex polygons are convex");
        let qs = queries(&ring);
        locate_with::<Fast>(&mut group, n, &poly, &qs);
        locate_with::<Robust>(&mut group, n, &poly, &qs);
        locate_with::<Exact>(&mut group, n, &poly, &qs);
        if n <= 16_384 {
            let simple = SimplePolygon::try_new(&ring).expect("convex polygons are simple");
            group.bench_with_input(
                BenchmarkId::new("crossing_number_robust", n),
                &qs,
                |b, qs| {
                    b.iter(|| {
                        qs.iter()
                            .filter(|&&q| simple.locate(black_box(q)) == Location::Inside)
                            .count()
                    })
                },
            );
        }
    }
    group.finish();
}

/// Every group of this file (what `criterion_group!` would generate, documented).
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    validation(&mut c);
    hulls(&mut c);
    locate(&mut c);
}

criterion_main!(benches);
