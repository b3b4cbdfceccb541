//! Hausdorff and CMMR distances of filled convex polygons: polydist's `O(n + m)` walk (Atallah 1983;
//! Atallah, Ribeiro, Lifschitz 1991, exact predicates) beside its `Θ(nm)` brute-force twin and geo's
//! discrete Hausdorff distance, on two random convex `n`-gons (`m = n`):
//!
//! - `hausdorff/overlapping`: the second polygon's centre at distance 0.5 (boundaries cross);
//! - `hausdorff/disjoint`: at distance 3 + gap.
//!
//! Series, per `n` in 64 … 1,048,576:
//! - `hausdorff_{fast,robust,exact}`: `hausdorff_with::<K>` (two walks and the exact argmax);
//! - `cmmr_{fast,robust,exact}`: `cmmr_with::<K>` (two walks, every per-vertex term and record,
//!   compensated sum); `cmmr_value_{fast,robust,exact}`: `cmmr_value_with::<K>` (the same value without
//!   the per-vertex records); the Exact kernel up to `n = 4,096`;
//! - `hausdorff_pieces_robust`, `cmmr_pieces_robust` (overlapping workload only): the same results by
//!   ARL's piece decomposition (`hausdorff_pieces_with::<Robust>`, `cmmr_pieces_with::<Robust>`);
//! - `brute_continuous`: `hausdorff_brute::<Robust>` (every vertex against every edge, `Θ(nm)`), up to
//!   `n = 4,096`;
//! - `geo_discrete`: geo 0.32's `HausdorffDistance::hausdorff_distance` (vertex to vertex, `O(nm)`), up to
//!   `n = 4,096`.
//!
//! Before timing, every pair is checked: the walk against the brute force (up to 4,096) and the three
//! kernels against each other; the relative difference between geo's discrete distance and the
//! continuous Hausdorff distance of the filled polygons is printed (the discrete one measures vertex
//! sets, so it is never smaller).
//!
//! Run: `cargo bench -p polydist-benches --bench hausdorff -- --warm-up-time 1 --measurement-time 2`.
//! Figures only; nothing else is asserted.

use std::hint::black_box;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use geo::{HausdorffDistance, LineString, Polygon};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Kernel, Robust};
use polydist_convex::{
    cmmr_pieces_with, cmmr_value_with, cmmr_with, hausdorff_brute, hausdorff_pieces_with,
    hausdorff_with,
};
use polydist_oracle::{SplitMix64, random_convex};

/// 64 … 1,048,576 vertices per polygon.
const SIZES: [usize; 6] = [64, 512, 4096, 32_768, 262_144, 1_048_576];
/// The largest size for the `Θ(nm)` series (the brute force and geo).
const QUADRATIC_MAX: usize = 4096;
/// The largest size for the Exact kernel (every sign in exact arithmetic: about 50 µs per vertex).
const EXACT_MAX: usize = 4096;

/// Small samples; the warm-up and measurement times come from the command line.
fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group.sample_size(10);
}

/// Where the second polygon goes.
#[derive(Clone, Copy)]
enum Workload {
    Overlapping,
    Disjoint,
}

impl Workload {
    fn name(self) -> &'static str {
        match self {
            Workload::Overlapping => "hausdorff/overlapping",
            Workload::Disjoint => "hausdorff/disjoint",
        }
    }
}

struct Pair {
    p: ConvexPolygon,
    q: ConvexPolygon,
    geo_p: Polygon<f64>,
    geo_q: Polygon<f64>,
}

fn geo_polygon(ring: &[DVec2]) -> Polygon<f64> {
    let pts: Vec<(f64, f64)> = ring.iter().map(|v| (v.x, v.y)).collect();
    Polygon::new(LineString::from(pts), vec![])
}

fn make_pair(n: usize, w: Workload) -> Pair {
    make_pair_seeded(n, w, 0)
}

fn make_pair_seeded(n: usize, w: Workload, seed: u64) -> Pair {
    let mut rng = SplitMix64::new(0x4A05_D0FF ^ n as u64 ^ (seed << 32));
    let t = rng.unit_f64() * core::f64::consts::TAU;
    let dist = match w {
        Workload::Overlapping => 0.5,
        Workload::Disjoint => 3.0 + 0.5 * rng.unit_f64(),
    };
    let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
    let q = random_convex(&mut rng, n, DVec2::new(t.cos(), t.sin()) * dist, 1.0);
    Pair {
        geo_p: geo_polygon(&p),
        geo_q: geo_polygon(&q),
        p: ConvexPolygon::try_new(&p).expect("valid P"),
        q: ConvexPolygon::try_new(&q).expect("valid Q"),
    }
}

fn geo_discrete(pair: &Pair) -> f64 {
    pair.geo_p.hausdorff_distance(&pair.geo_q)
}

/// Consistency before timing, and what the discrete distance misses.
fn check(pair: &Pair, n: usize, w: Workload) {
    let h = hausdorff_with::<Robust>(&pair.p, &pair.q);
    let d = h.distance;
    let close = |x: f64, what: &str| {
        let rel = if d == 0.0 { x } else { (x - d).abs() / d };
        assert!(rel <= 1e-15, "n = {n}: {what} = {x}, robust = {d}");
    };
    close(hausdorff_with::<Fast>(&pair.p, &pair.q).distance, "fast");
    if n <= EXACT_MAX {
        close(hausdorff_with::<Exact>(&pair.p, &pair.q).distance, "exact");
    }
    let c = cmmr_with::<Robust>(&pair.p, &pair.q).value;
    if let Workload::Overlapping = w {
        assert_eq!(
            hausdorff_pieces_with::<Robust>(&pair.p, &pair.q),
            h,
            "n = {n}: pieces"
        );
        assert_eq!(
            cmmr_pieces_with::<Robust>(&pair.p, &pair.q).value,
            c,
            "n = {n}: pieces"
        );
    }
    if n <= QUADRATIC_MAX {
        assert_eq!(
            hausdorff_brute::<Robust>(&pair.p, &pair.q),
            h,
            "n = {n}: walk and brute force disagree"
        );
        let g = geo_discrete(pair);
        eprintln!(
            "{} n = {n}: continuous Hausdorff {d:.6e}, geo discrete {g:.6e} (relative excess {:.3e}); CMMR {c:.6e}",
            w.name(),
            (g - d) / d
        );
    } else {
        eprintln!(
            "{} n = {n}: continuous Hausdorff {d:.6e}; CMMR {c:.6e}",
            w.name()
        );
    }
}

fn series<K: Kernel>(group: &mut BenchmarkGroup<'_, WallTime>, n: usize, pair: &Pair) {
    group.bench_with_input(
        BenchmarkId::new(format!("hausdorff_{}", K::NAME), n),
        pair,
        |b, s| b.iter(|| hausdorff_with::<K>(black_box(&s.p), black_box(&s.q))),
    );
    group.bench_with_input(
        BenchmarkId::new(format!("cmmr_{}", K::NAME), n),
        pair,
        |b, s| b.iter(|| cmmr_with::<K>(black_box(&s.p), black_box(&s.q))),
    );
    group.bench_with_input(
        BenchmarkId::new(format!("cmmr_value_{}", K::NAME), n),
        pair,
        |b, s| b.iter(|| cmmr_value_with::<K>(black_box(&s.p), black_box(&s.q))),
    );
}

fn workload(c: &mut Criterion, w: Workload) {
    let mut group = c.benchmark_group(w.name());
    configure(&mut group);
    for n in SIZES {
        let pair = make_pair(n, w);
        check(&pair, n, w);
        series::<Fast>(&mut group, n, &pair);
        series::<Robust>(&mut group, n, &pair);
        if n <= EXACT_MAX {
            series::<Exact>(&mut group, n, &pair);
        }
        if let Workload::Overlapping = w {
            group.bench_with_input(
                BenchmarkId::new("hausdorff_pieces_robust", n),
                &pair,
                |b, s| b.iter(|| hausdorff_pieces_with::<Robust>(black_box(&s.p), black_box(&s.q))),
            );
            group.bench_with_input(BenchmarkId::new("cmmr_pieces_robust", n), &pair, |b, s| {
                b.iter(|| cmmr_pieces_with::<Robust>(black_box(&s.p), black_box(&s.q)))
            });
        }
        if n <= QUADRATIC_MAX {
            group.bench_with_input(BenchmarkId::new("brute_continuous", n), &pair, |b, s| {
                b.iter(|| hausdorff_brute::<Robust>(black_box(&s.p), black_box(&s.q)))
            });
            group.bench_with_input(BenchmarkId::new("geo_discrete", n), &pair, |b, s| {
                b.iter(|| geo_discrete(black_box(s)))
            });
        }
    }
    group.finish();
}

/// What the discrete (vertex-to-vertex) Hausdorff distance misses: over 50 random pairs per size, the
/// mean and largest relative excess of geo's value over the continuous distance of the filled polygons.
fn discrete_vs_continuous() {
    for w in [Workload::Overlapping, Workload::Disjoint] {
        for n in [4usize, 8, 16, 64, 512] {
            let (mut sum, mut max) = (0.0f64, 0.0f64);
            for seed in 0..50u64 {
                let pair = make_pair_seeded(n, w, seed);
                let d = hausdorff_with::<Robust>(&pair.p, &pair.q).distance;
                let rel = (geo_discrete(&pair) - d) / d;
                sum += rel;
                max = max.max(rel);
            }
            eprintln!(
                "{} n = {n}: geo discrete over continuous, relative excess mean {:.3e}, max {max:.3e}",
                w.name(),
                sum / 50.0
            );
        }
    }
}

/// Every group of this file (what `criterion_group!` would generate, documented).
fn benches() {
    discrete_vs_continuous();
    let mut c = Criterion::default().configure_from_args();
    workload(&mut c, Workload::Overlapping);
    workload(&mut c, Workload::Disjoint);
}

criterion_main!(benches);
