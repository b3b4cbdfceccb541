//! Minimum vertex distance (McKenna–Toussaint 1985): polydist's `O(m + n)` algorithm under the three
//! kernels beside its `Θ(nm)` brute-force twin under the same kernel and a plain-`f64` brute force, on
//! two disjoint random convex `n`-gons (`m = n`):
//!
//! - W1 (`vertex_distance/random`): the second polygon of radius `0.5 … 1.5` centred `4 … 7` away in a
//!   random direction. Large random polygons are mostly nearest at two vertices, where step 1
//!   (Lemma 1) stops after the `O(log)` bridge: the setup prints which bridge each size has.
//! - W2 (`vertex_distance/tenstep`): the second polygon a translate of the first, 3 away in a direction
//!   drawn (deterministically, from the seed) until the bridge is vertex–edge, so every size runs the
//!   whole TENSTEP (steps 2–10).
//!
//! Series, per `n` in 8 … 1,048,576:
//! - `fast`, `robust`, `exact`: `min_vertex_distance_with::<K>` (`exact` up to `n = 262,144`);
//! - `brute_fast`, `brute_robust`, `brute_exact`: `min_vertex_distance_brute::<K>` (up to `n = 512`);
//! - `brute_f64`: a plain `f64` double loop over `dx² + dy²` (up to `n = 4096`).
//!
//! Before timing, every series' squared distance is checked against the Robust answer (exactly for
//! the exact kernels, relative 1e-12 for the others).
//!
//! Run: `cargo bench -p polydist-benches --bench vertex_distance -- --warm-up-time 1 --measurement-time 2`.
//! Figures only; nothing is asserted about time.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_main, measurement::WallTime};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Kernel, Robust};
use polydist_convex::{
    VertexDistance, min_vertex_distance_brute, min_vertex_distance_with,
    reset_vertex_distance_case_counts, vertex_distance_case_counts,
};
use polydist_oracle::{SplitMix64, random_convex};

/// 8 … 1,048,576 vertices per polygon.
const SIZES: [usize; 7] = [8, 64, 512, 4096, 32_768, 262_144, 1_048_576];
/// The largest size for the Exact kernel (about 20 µs per vertex: 5 s per call at 262,144).
const EXACT_MAX: usize = 262_144;
/// The largest size for the `Θ(nm)` brute force under a kernel.
const BRUTE_MAX: usize = 512;
/// The largest size for the plain-`f64` brute force.
const F64_MAX: usize = 4096;

/// Small samples: the whole file runs in a few minutes on two cores.
fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(1));
}

/// The workloads.
#[derive(Clone, Copy)]
enum Workload {
    /// W1: a second random polygon in a random direction.
    Random,
    /// W2: a translate of the first polygon with a vertex–edge bridge.
    Tenstep,
}

impl Workload {
    fn name(self) -> &'static str {
        match self {
            Workload::Random => "vertex_distance/random",
            Workload::Tenstep => "vertex_distance/tenstep",
        }
    }

    fn pair(self, rng: &mut SplitMix64, n: usize) -> (ConvexPolygon, ConvexPolygon) {
        let p = random_convex(rng, n, DVec2::ZERO, 1.0);
        let pp = ConvexPolygon::try_new(&p).expect("valid");
        let direction = |rng: &mut SplitMix64| {
            let a = rng.unit_f64() * std::f64::consts::TAU;
            DVec2::new(a.cos(), a.sin())
        };
        match self {
            Workload::Random => {
                let dir = direction(rng);
                let d = 4.0 + 3.0 * rng.unit_f64();
                let r = 0.5 + rng.unit_f64();
                let q = random_convex(rng, n, dir * d, r);
                (pp, ConvexPolygon::try_new(&q).expect("valid"))
            }
            Workload::Tenstep => {
                let mut q = None;
                for _ in 0..64 {
                    let dir = direction(rng);
                    let t: Vec<DVec2> = p.iter().map(|&x| x + dir * 3.0).collect();
                    let qq = ConvexPolygon::try_new(&t).expect("valid");
                    reset_vertex_distance_case_counts();
                    let _ = min_vertex_distance_with::<Robust>(&pp, &qq);
                    q = Some(qq);
                    if vertex_distance_case_counts().bridge_vertex_vertex == 0 {
                        break;
                    }
                }
                (pp, q.expect("at least one try"))
            }
        }
    }
}

/// The plain-`f64` brute force: the baseline a user would write.
fn brute_f64(p: &[DVec2], q: &[DVec2]) -> f64 {
    let mut best = f64::INFINITY;
    for a in p {
        for b in q {
            let d = *a - *b;
            best = best.min(d.x * d.x + d.y * d.y);
        }
    }
    best
}

fn check(name: &str, got: f64, want: &VertexDistance, exact: bool) {
    let ok = if exact {
        got == want.squared_distance
    } else {
        (got - want.squared_distance).abs() <= 1e-12 * want.squared_distance
    };
    assert!(ok, "{name}: {got} against {}", want.squared_distance);
}

fn bench_kernel<K: Kernel>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    n: usize,
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    want: &VertexDistance,
) {
    let name = K::NAME;
    check(
        name,
        min_vertex_distance_with::<K>(p, q).squared_distance,
        want,
        K::EXACT_DECISIONS,
    );
    group.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
        b.iter(|| min_vertex_distance_with::<K>(black_box(p), black_box(q)));
    });
    if n <= BRUTE_MAX {
        let brute = format!("brute_{name}");
        check(
            &brute,
            min_vertex_distance_brute::<K>(p, q).squared_distance,
            want,
            K::EXACT_DECISIONS,
        );
        group.bench_with_input(BenchmarkId::new(brute, n), &n, |b, _| {
            b.iter(|| min_vertex_distance_brute::<K>(black_box(p), black_box(q)));
        });
    }
}

fn workload(c: &mut Criterion, w: Workload) {
    let mut group = c.benchmark_group(w.name());
    configure(&mut group);
    let mut rng = SplitMix64::new(2026);
    for n in SIZES {
        let (p, q) = w.pair(&mut rng, n);
        reset_vertex_distance_case_counts();
        let want = min_vertex_distance_with::<Robust>(&p, &q);
        let counts = vertex_distance_case_counts();
        let bridge = if counts.bridge_vertex_vertex > 0 {
            "vertex–vertex (step 1 stops)"
        } else {
            "vertex–edge (steps 2–10 run)"
        };
        eprintln!("{} n = {n}: bridge {bridge}", w.name());
        bench_kernel::<Fast>(&mut group, n, &p, &q, &want);
        bench_kernel::<Robust>(&mut group, n, &p, &q, &want);
        if n <= EXACT_MAX {
            bench_kernel::<Exact>(&mut group, n, &p, &q, &want);
        }
        if n <= F64_MAX {
            check(
                "brute_f64",
                brute_f64(p.vertices(), q.vertices()),
                &want,
                false,
            );
            group.bench_with_input(BenchmarkId::new("brute_f64", n), &n, |b, _| {
                b.iter(|| brute_f64(black_box(p.vertices()), black_box(q.vertices())));
            });
        }
    }
    group.finish();
}

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    workload(&mut c, Workload::Tenstep);
    workload(&mut c, Workload::Random);
    c.final_summary();
}

criterion_main!(benches);
