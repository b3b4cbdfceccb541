//! Triangulation of a simple polygon (monotone pieces + stack algorithm, exact predicates), beside
//! its ear-clipping twin, and the geodesic and ray-shooting queries on the result:
//!
//! - `triangulate/{combs,stars,spirals}`: `triangulate::<K>` for the three kernels, and
//!   `triangulate_brute::<Robust>` (ear clipping, `O(n³)` worst case; up to 512 vertices);
//! - `geodesic/{combs,stars,spirals}`: `shortest_path::<Robust>` on a prebuilt triangulation between
//!   the pair with the most turns among `(0, n/2)`, `(1, n−2)`, `(n/3, 2n/3)`, `(n/4, 3n/4)`, and `first_hit::<Robust>` for every segment of that path (both ways).
//!
//! Combs have all tips on one line (collinear vertices everywhere). Run:
//! `cargo bench -p polydist-benches --bench triangulate -- --warm-up-time 1 --measurement-time 2`.
//! Figures only.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use glam::DVec2;
use polydist_oracle::{SplitMix64, comb, spiral, star};
use polydist_predicates::{Exact, Fast, Robust};
use polydist_separation::{first_hit, shortest_path, triangulate, triangulate_brute};

const SIZES: [usize; 3] = [512, 4096, 32_768];
const BRUTE_MAX: usize = 512;

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1500));
}

fn families(n: usize) -> [(&'static str, Vec<DVec2>); 3] {
    let mut rng = SplitMix64::new(n as u64);
    [
        ("combs", comb(n / 4, 5, 1)),
        ("stars", star(&mut rng, n, n / 4)),
        ("spirals", spiral(8, (n / 16) as u32)),
    ]
}

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    for family in 0..3 {
        let name = ["combs", "stars", "spirals"][family];
        let mut group = c.benchmark_group(format!("triangulate/{name}"));
        configure(&mut group);
        for n in SIZES {
            let ring = families(n)[family].1.clone();
            let m = ring.len();
            group.bench_with_input(BenchmarkId::new("fast", m), &ring, |b, r| {
                b.iter(|| triangulate::<Fast>(black_box(r)))
            });
            group.bench_with_input(BenchmarkId::new("robust", m), &ring, |b, r| {
                b.iter(|| triangulate::<Robust>(black_box(r)))
            });
            group.bench_with_input(BenchmarkId::new("exact", m), &ring, |b, r| {
                b.iter(|| triangulate::<Exact>(black_box(r)))
            });
            if m <= BRUTE_MAX {
                group.bench_with_input(BenchmarkId::new("brute_robust", m), &ring, |b, r| {
                    b.iter(|| triangulate_brute::<Robust>(black_box(r)))
                });
            }
        }
        group.finish();
        let mut group = c.benchmark_group(format!("geodesic/{name}"));
        configure(&mut group);
        for n in SIZES {
            let ring = families(n)[family].1.clone();
            let m = ring.len();
            let Ok(tri) = triangulate::<Robust>(&ring) else {
                continue;
            };
            // The pair with the most turns among a few candidates (a trivial pair measures nothing).
            let (s, t) = [
                (0, m / 2),
                (1, m - 2),
                (m / 3, 2 * m / 3),
                (m / 4, 3 * m / 4),
            ]
            .into_iter()
            .max_by_key(|&(s, t)| shortest_path::<Robust>(&tri, &ring, s, t).len())
            .unwrap_or((0, m / 2));
            group.bench_with_input(BenchmarkId::new("shortest_path", m), &ring, |b, r| {
                b.iter(|| shortest_path::<Robust>(&tri, black_box(r), s, t))
            });
            let path = shortest_path::<Robust>(&tri, &ring, s, t);
            println!("{name} n={m}: path {s}->{t} has {} vertices", path.len());
            group.bench_with_input(BenchmarkId::new("arms", m), &ring, |b, r| {
                b.iter(|| {
                    path.windows(2)
                        .map(|w| {
                            (
                                first_hit::<Robust>(&tri, black_box(r), w[0], w[1]),
                                first_hit::<Robust>(&tri, black_box(r), w[1], w[0]),
                            )
                        })
                        .collect::<Vec<_>>()
                })
            });
        }
        group.finish();
    }
    c.final_summary();
}

criterion_main!(benches);
