//! What accuracy costs in time, predicate by predicate: Fast, Robust and Exact kernels on random,
//! near-degenerate and coarse-grid (exactly tied, in eighths and in tenths) inputs, as a dependent chain (each sign picks the next input, so latency counts) and
//! as throughput (independent calls). `robust::orient2d` (Shewchuk's predicates, not inlined) is the
//! baseline for orientation.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_main};
use glam::DVec2;
use polydist_oracle::SplitMix64;
use polydist_predicates::{Dist2, Exact, Fast, Kernel, Robust};

const N: usize = 4096;

/// Random points in the unit square.
fn random_points(seed: u64) -> Vec<DVec2> {
    let mut rng = SplitMix64::new(seed);
    (0..N + 16)
        .map(|_| DVec2::new(rng.unit_f64(), rng.unit_f64()))
        .collect()
}

/// Points on the line y = x + 1e6 (offset, so rounding is real) moved a few ulps off it: almost every
/// orientation triple among consecutive points is within rounding of zero.
fn degenerate_points(seed: u64) -> Vec<DVec2> {
    let mut rng = SplitMix64::new(seed);
    (0..N + 16)
        .map(|_| {
            let t = 1e6 + rng.unit_f64();
            let mut y = t;
            for _ in 0..rng.below(5) {
                y = if rng.coin() {
                    y.next_up()
                } else {
                    y.next_down()
                };
            }
            DVec2::new(t, y)
        })
        .collect()
}

/// Points of a coarse grid far from the origin (`1000 + k/8`, `k < 8`): exact ties and zeros on almost
/// every call, which no filter certifies; the Robust kernel's error-free `f64` stage decides them, as the
/// arithmetic on such coordinates does not round.
fn grid_points(seed: u64) -> Vec<DVec2> {
    let mut rng = SplitMix64::new(seed);
    let mut at = || 1000.0 + rng.below(8) as f64 / 8.0;
    (0..N + 16).map(|_| DVec2::new(at(), at())).collect()
}

/// The same grid in tenths (`1000 + k/10`): the ties are as frequent, but the coordinates are not
/// dyadic, so their products round and the error-free stage declines: the ties fall to expansions.
/// Decimal coordinates are what GIS data looks like.
fn decimal_points(seed: u64) -> Vec<DVec2> {
    let mut rng = SplitMix64::new(seed);
    let mut at = || 1000.0 + rng.below(8) as f64 / 10.0;
    (0..N + 16).map(|_| DVec2::new(at(), at())).collect()
}

/// Each result decides which point the next call uses: the latency of the whole predicate counts.
fn chain(pts: &[DVec2], f: impl Fn(DVec2, DVec2, DVec2, DVec2) -> i8) -> usize {
    let mut k = 0usize;
    for i in 0..N {
        // The previous sign picks the first point among the next few (never one of the other three,
        // so random input stays free of exact ties).
        let s = f(pts[i + 3 + (k & 7)], pts[i], pts[i + 1], pts[i + 2]);
        k = k.wrapping_add(1 + (s + 1) as usize);
    }
    k
}

/// Independent calls: the predicate's throughput.
fn throughput(pts: &[DVec2], f: impl Fn(DVec2, DVec2, DVec2, DVec2) -> i8) -> i64 {
    let mut acc = 0i64;
    for i in 0..N {
        acc += i64::from(f(pts[i], pts[i + 1], pts[i + 2], pts[i + 3]));
    }
    acc
}

fn o(s: core::cmp::Ordering) -> i8 {
    s as i8
}

macro_rules! predicate_group {
    ($c:expr, $name:literal, $call:ident) => {{
        for (input, pts) in [
            ("random", random_points(1)),
            ("degenerate", degenerate_points(2)),
            ("grid", grid_points(3)),
            ("decimal", decimal_points(4)),
        ] {
            let mut g = $c.benchmark_group(format!("predicates/{}/{}", $name, input));
            g.throughput(Throughput::Elements(N as u64));
            g.sample_size(20);
            g.bench_function("fast/chain", |b| {
                b.iter(|| chain(black_box(&pts), $call::<Fast>))
            });
            g.bench_function("robust/chain", |b| {
                b.iter(|| chain(black_box(&pts), $call::<Robust>))
            });
            g.bench_function("exact/chain", |b| {
                b.iter(|| chain(black_box(&pts), $call::<Exact>))
            });
            g.bench_function("fast/throughput", |b| {
                b.iter(|| throughput(black_box(&pts), $call::<Fast>))
            });
            g.bench_function("robust/throughput", |b| {
                b.iter(|| throughput(black_box(&pts), $call::<Robust>))
            });
            g.bench_function("exact/throughput", |b| {
                b.iter(|| throughput(black_box(&pts), $call::<Exact>))
            });
            if $name == "orient" {
                g.bench_function("robust-crate/chain", |b| {
                    b.iter(|| chain(black_box(&pts), shewchuk))
                });
                g.bench_function("robust-crate/throughput", |b| {
                    b.iter(|| throughput(black_box(&pts), shewchuk))
                });
            }
            g.finish();
        }
    }};
}

fn orient<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, _d: DVec2) -> i8 {
    o(K::orient(a, b, c).sign().to_ordering())
}
fn dot<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> i8 {
    o(K::dot_sign(a, b, c, d).to_ordering())
}
fn nearer<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, _d: DVec2) -> i8 {
    o(K::cmp_dist(a, b, c))
}
fn dist4<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> i8 {
    o(K::cmp_dist4(a, b, c, d))
}
fn point_segment<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> i8 {
    o(K::cmp_dist2(
        Dist2::PointSegment(a, b, c),
        Dist2::PointSegment(d, b, c),
    ))
}
fn shewchuk(a: DVec2, b: DVec2, c: DVec2, _d: DVec2) -> i8 {
    let r = robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    );
    // robust's sign convention: positive for counter-clockwise.
    if r > 0.0 {
        1
    } else if r < 0.0 {
        -1
    } else {
        0
    }
}

fn bench(c: &mut Criterion) {
    predicate_group!(c, "orient", orient);
    predicate_group!(c, "dot", dot);
    predicate_group!(c, "nearer", nearer);
    predicate_group!(c, "dist4", dist4);
    predicate_group!(c, "point_segment", point_segment);
}

/// Every group of this file (what `criterion_group!` would generate, documented).
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
}

criterion_main!(benches);
