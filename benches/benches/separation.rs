//! Separation of two chains separated by a line (Amato 1992, section 3): polydist's `O(n)` solver
//! (CVV + two CVE searches with SMAWK) beside its brute-force twin and parry2d-f64's `Polyline`
//! (BVH) distance, on two chains monotone along the separating line `x = 0`, `N` vertices in all:
//!
//! - `separation/random`: random heights and depths (1 … 10 from the line);
//! - `separation/combs`: two saw-tooth combs whose tips face each other, interleaved, one unit
//!   from the line each (every tooth is a candidate).
//!
//! Series, per `N` in 64 … 131,072:
//! - `sigma_fast`, `sigma_robust`, `sigma_exact`: `separation_of_chains::<K>` (Exact up to 4,096);
//! - `cvv_robust`: `closest_visible_vertices::<Robust>` alone (the vertex part);
//! - `brute_robust`: `separation_brute::<Robust>` (`Θ(n_p n_q)`, up to 4,096);
//! - `parry_query`: `query::distance` between two prebuilt `Polyline`s (BVH built outside the loop);
//! - `parry_build_query`: building both polylines (their BVHs) and the query, what a one-shot
//!   query pays.
//!
//! Whole closed polygon boundaries (not monotone along the line; the envelope of Lemma 2 first),
//! `N` vertices in all, `N` in 64 … 4,096:
//!
//! - `separation/closed_spirals`: a 4-turn spiral polygon and its mirror image across a line
//!   tangent to its hull at the bottom;
//! - `separation/closed_combs`: two combs (teeth of width 1, length 3, gaps 1) facing tip to tip
//!   across the line through one comb's tips, half a unit apart, shifted by half a tooth.
//!
//! Series: `sigma_fast`, `sigma_robust`, `envelope_robust` (`perpendicular_envelope::<Robust>` of
//! one polygon), `brute_robust`, `parry_build_query` (the boundaries as closed `Polyline`s).
//!
//! Lemma 2's envelope alone on a closed spiky star (`N` vertices, tips at radius 1, valleys at 0.3,
//! seen from a line below it; a quarter of the vertices visible), `N` in 512 … 1,048,576:
//! `separation/envelope_stars`, series `envelope_fast`, `envelope_robust` (the linear walk of
//! `docs/algorithms/separation.md`) and `envelope_brute_robust` (its `O(n²)` twin, up to 4,096),
//! which must agree before timing. The time per vertex should stay flat.
//!
//! Before timing, parry's and the brute force's distances are checked against polydist's (relative
//! 1e-9). Run: `cargo bench -p polydist-benches --bench separation`. Figures only.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use glam::DVec2;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::Polyline;
use polydist_oracle::{SplitMix64, comb, spiral};
use polydist_predicates::{Exact, Fast, Kernel, Robust};
use polydist_separation::{
    closest_visible_vertices, perpendicular_envelope, perpendicular_envelope_brute,
    separation_brute, separation_of_chains,
};

/// Total vertices.
const SIZES: [usize; 5] = [64, 512, 4096, 32_768, 131_072];
const BRUTE_MAX: usize = 4096;
const EXACT_MAX: usize = 4096;

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1500));
}

/// Chains `p` (x > 0) and `q` (x < 0), strictly increasing in height.
struct Case {
    p: Vec<DVec2>,
    q: Vec<DVec2>,
}

fn side(rng: &mut SplitMix64, n: usize, sign: f64) -> Vec<DVec2> {
    let mut ys: Vec<f64> = (0..n).map(|_| rng.unit_f64() * n as f64).collect();
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    ys.into_iter()
        .map(|y| DVec2::new(sign * (1.0 + 9.0 * rng.unit_f64()), y))
        .collect()
}

fn random(n: usize) -> Case {
    let mut rng = SplitMix64::new(0x5e9a ^ n as u64);
    Case {
        p: side(&mut rng, n / 2, 1.0),
        q: side(&mut rng, n / 2, -1.0),
    }
}

fn combs(n: usize) -> Case {
    let teeth = n / 4;
    let (mut p, mut q) = (Vec::new(), Vec::new());
    for k in 0..teeth {
        let y = 4.0 * k as f64;
        p.push(DVec2::new(11.0, y));
        p.push(DVec2::new(1.0, y + 2.0));
        q.push(DVec2::new(-11.0, y + 2.0));
        q.push(DVec2::new(-1.0, y + 4.0));
    }
    Case { p, q }
}

fn polyline(c: &[DVec2]) -> Polyline {
    Polyline::new(c.iter().map(|v| Vector::new(v.x, v.y)).collect(), None)
}

fn parry(p: &Polyline, q: &Polyline) -> f64 {
    let id = Pose::identity();
    query::distance(&id, p, &id, q).expect("supported")
}

fn sigma<K: Kernel>(c: &Case) -> f64 {
    separation_of_chains::<K>(&c.p, &c.q, DVec2::ZERO, DVec2::Y)
        .expect("valid input")
        .pair
        .distance
}

fn run(c: &mut Criterion, name: &str, make: fn(usize) -> Case) {
    let mut group = c.benchmark_group(name);
    configure(&mut group);
    for n in SIZES {
        let case = make(n);
        let (pp, pq) = (polyline(&case.p), polyline(&case.q));
        let d = sigma::<Robust>(&case);
        let rel = |x: f64| ((x - d) / d).abs();
        assert!(rel(parry(&pp, &pq)) < 1e-9, "{name} n={n}: parry disagrees");
        if n <= BRUTE_MAX {
            let b = separation_brute::<Robust>(&case.p, &case.q)
                .expect("valid")
                .distance;
            assert!(rel(b) < 1e-12, "{name} n={n}: brute disagrees");
        }
        group.bench_with_input(BenchmarkId::new("sigma_fast", n), &case, |b, c| {
            b.iter(|| sigma::<Fast>(black_box(c)))
        });
        group.bench_with_input(BenchmarkId::new("sigma_robust", n), &case, |b, c| {
            b.iter(|| sigma::<Robust>(black_box(c)))
        });
        if n <= EXACT_MAX {
            group.bench_with_input(BenchmarkId::new("sigma_exact", n), &case, |b, c| {
                b.iter(|| sigma::<Exact>(black_box(c)))
            });
        }
        group.bench_with_input(BenchmarkId::new("cvv_robust", n), &case, |b, c| {
            b.iter(|| {
                closest_visible_vertices::<Robust>(black_box(&c.p), &c.q, DVec2::ZERO, DVec2::Y)
                    .expect("valid")
                    .pair
                    .distance
            })
        });
        if n <= BRUTE_MAX {
            group.bench_with_input(BenchmarkId::new("brute_robust", n), &case, |b, c| {
                b.iter(|| {
                    separation_brute::<Robust>(black_box(&c.p), &c.q)
                        .expect("valid")
                        .distance
                })
            });
        }
        group.bench_with_input(
            BenchmarkId::new("parry_query", n),
            &(pp, pq),
            |b, (p, q)| b.iter(|| parry(black_box(p), black_box(q))),
        );
        group.bench_with_input(BenchmarkId::new("parry_build_query", n), &case, |b, c| {
            b.iter(|| {
                let (p, q) = (polyline(black_box(&c.p)), polyline(&c.q));
                parry(&p, &q)
            })
        });
    }
    group.finish();
}

/// Two closed boundaries (last vertex repeating the first) and the separating line.
struct Closed {
    p: Vec<DVec2>,
    q: Vec<DVec2>,
    a: DVec2,
    b: DVec2,
}

/// `poly` closed, mirrored through `y = y0` and shifted by `dx` when `mirror` is given.
fn close(poly: &[DVec2], mirror: Option<(f64, f64)>) -> Vec<DVec2> {
    let mut v: Vec<DVec2> = poly
        .iter()
        .map(|p| match mirror {
            Some((y0, dx)) => DVec2::new(p.x + dx, 2.0 * y0 - p.y),
            None => *p,
        })
        .collect();
    v.push(v[0]);
    v
}

fn closed_spirals(n: usize) -> Closed {
    // 2(per · turns + 1) vertices per polygon.
    let per = (n / 16).max(3) as u32;
    let s = spiral(per, 4);
    let ymin = s.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    Closed {
        p: close(&s, None),
        q: close(&s, Some((ymin - 0.5, 0.25))),
        a: DVec2::new(0.0, ymin),
        b: DVec2::new(1.0, ymin),
    }
}

fn closed_combs(n: usize) -> Closed {
    // 4 vertices per tooth.
    let c = comb((n / 8).max(1), 3, 1);
    Closed {
        p: close(&c, None),
        q: close(&c, Some((3.25, 0.5))),
        a: DVec2::new(0.0, 3.0),
        b: DVec2::new(1.0, 3.0),
    }
}

fn closed_sigma<K: Kernel>(c: &Closed) -> f64 {
    separation_of_chains::<K>(&c.p, &c.q, c.a, c.b)
        .expect("valid input")
        .pair
        .distance
}

fn run_closed(c: &mut Criterion, name: &str, make: fn(usize) -> Closed) {
    let mut group = c.benchmark_group(name);
    configure(&mut group);
    for n in [64usize, 512, 4096] {
        let case = make(n);
        let total = case.p.len() + case.q.len();
        let d = closed_sigma::<Robust>(&case);
        let rel = |x: f64| ((x - d) / d).abs();
        let (pp, pq) = (polyline(&case.p), polyline(&case.q));
        assert!(rel(parry(&pp, &pq)) < 1e-9, "{name} n={n}: parry disagrees");
        let b = separation_brute::<Robust>(&case.p, &case.q)
            .expect("valid")
            .distance;
        assert!(rel(b) < 1e-12, "{name} n={n}: brute disagrees");
        group.bench_with_input(BenchmarkId::new("sigma_fast", total), &case, |b, c| {
            b.iter(|| closed_sigma::<Fast>(black_box(c)))
        });
        group.bench_with_input(BenchmarkId::new("sigma_robust", total), &case, |b, c| {
            b.iter(|| closed_sigma::<Robust>(black_box(c)))
        });
        group.bench_with_input(BenchmarkId::new("envelope_robust", total), &case, |b, c| {
            b.iter(|| {
                perpendicular_envelope::<Robust>(black_box(&c.p), c.a, c.b)
                    .expect("valid")
                    .vertices
                    .len()
            })
        });
        group.bench_with_input(BenchmarkId::new("brute_robust", total), &case, |b, c| {
            b.iter(|| {
                separation_brute::<Robust>(black_box(&c.p), &c.q)
                    .expect("valid")
                    .distance
            })
        });
        group.bench_with_input(
            BenchmarkId::new("parry_build_query", total),
            &case,
            |b, c| {
                b.iter(|| {
                    let (p, q) = (polyline(black_box(&c.p)), polyline(&c.q));
                    parry(&p, &q)
                })
            },
        );
    }
    group.finish();
}

/// A closed spiky star of `n` vertices (`n / 2` tips at radius 1, valleys at 0.3) centred at
/// `(0, 1.25)`, above the line `y = 0`; the last vertex repeats the first.
fn star_chain(n: usize) -> Vec<DVec2> {
    let k = (n / 2).max(3);
    let mut v: Vec<DVec2> = (0..2 * k)
        .map(|i| {
            let t = i as f64 * std::f64::consts::PI / k as f64;
            let r = if i % 2 == 0 { 1.0 } else { 0.3 };
            DVec2::new(r * t.cos(), 1.25 + r * t.sin())
        })
        .collect();
    v.push(v[0]);
    v
}

fn run_envelope_stars(c: &mut Criterion) {
    let mut group = c.benchmark_group("separation/envelope_stars");
    configure(&mut group);
    let (a, b) = (DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0));
    for n in [512usize, 4096, 32_768, 131_072, 1_048_576] {
        let star = star_chain(n);
        let env = perpendicular_envelope::<Robust>(&star, a, b).expect("valid");
        if n <= BRUTE_MAX {
            let twin = perpendicular_envelope_brute::<Robust>(&star, a, b).expect("valid");
            assert_eq!(env, twin, "envelope_stars n={n}: the twin disagrees");
        }
        for (name, run) in [
            (
                "envelope_fast",
                perpendicular_envelope::<Fast> as EnvelopeFn,
            ),
            ("envelope_robust", perpendicular_envelope::<Robust>),
        ] {
            group.bench_with_input(BenchmarkId::new(name, n), &star, |bench, s| {
                bench.iter(|| run(black_box(s), a, b).expect("valid").vertices.len())
            });
        }
        if n <= BRUTE_MAX {
            group.bench_with_input(
                BenchmarkId::new("envelope_brute_robust", n),
                &star,
                |bench, s| {
                    bench.iter(|| {
                        perpendicular_envelope_brute::<Robust>(black_box(s), a, b)
                            .expect("valid")
                            .vertices
                            .len()
                    })
                },
            );
        }
    }
    group.finish();
}

/// One envelope routine, for a table of them.
type EnvelopeFn = fn(
    &[DVec2],
    DVec2,
    DVec2,
)
    -> Result<polydist_separation::Envelope, polydist_separation::SeparationError>;

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    run_envelope_stars(&mut c);
    run_closed(&mut c, "separation/closed_spirals", closed_spirals);
    run_closed(&mut c, "separation/closed_combs", closed_combs);
    run(&mut c, "separation/random", random);
    run(&mut c, "separation/combs", combs);
    c.final_summary();
}

criterion_main!(benches);
