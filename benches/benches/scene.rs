//! The scene runner and `polydist batch` (polydist-scene):
//!
//! - `scene/thousand`: fixtures/scenes/thousand.toml (1,000 moving random convex 8-gons, all
//!   499,500 pairs, `distance`, 5 frames), one whole run per iteration (frames per second = 5 / time):
//!   - `within_broad`: the fixture as written (`within = 1.5`), broad phase on;
//!   - `within_no_broad`: the same without the broad phase (every pair-frame a `distance_within`);
//!   - `all_coherence` / `all_no_coherence`: the query without `within` (every pair's distance at
//!     every frame), temporal coherence on and off, on the first 2 frames only (the report holds
//!     one frame result per pair and frame: 999,000 of them);
//! - `scene/ten_thousand/within_broad`: the same construction with 10,000 bodies (a 100 x 100 grid,
//!   generated here: 49,995,000 pairs, `within = 1.5`, 5 frames), broad phase on. (Before the
//!   streamed plan this scene was refused by `MAX_PAIRS`; without the broad phase it would be 250
//!   million narrow-phase queries per run, not benchmarked.)
//! - `batch/pairs`: `batch_pairs` over 20,000 JSON lines of random convex pairs (8 to 64 vertices,
//!   `distance` and `closest_points`) on rayon pools of 1 and 2 threads (pairs per second =
//!   20,000 / time).
//!
//! Predicate counting is off. Run:
//! `cargo bench -p polydist-benches --bench scene -- --warm-up-time 1 --measurement-time 2`.
//! The figures are in docs/scene-format.md ("Benchmarks").
//! Figures only; nothing is asserted beyond the sanity checks before timing.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, Throughput, criterion_main};
use polydist_oracle::{SplitMix64, random_convex};
use polydist_scene::{
    BatchOptions, Origin, RunOptions, Scene, batch_pairs, load_file, load_str, run,
};

fn thousand() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/scenes/thousand.toml");
    load_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn options(broad_phase: bool, coherence: bool) -> RunOptions {
    RunOptions {
        count_predicates: false,
        broad_phase,
        coherence: Some(coherence),
        ..RunOptions::default()
    }
}

fn bench_thousand(c: &mut Criterion) {
    let scene = thousand();
    let mut all = scene.clone();
    all.queries[0].within = None;
    all.time.frames = 2;
    // Sanity: the broad phase changes nothing but the cost.
    let on = run(&scene, &options(true, true));
    let off = run(&scene, &options(false, true));
    assert_eq!(on.pairs, off.pairs);
    eprintln!(
        "thousand: {} pairs listed, {} narrow-phase queries with the broad phase, {} without",
        on.pairs.len(),
        on.costs.distance.calls,
        off.costs.distance.calls
    );

    let mut g = c.benchmark_group("scene/thousand");
    g.sample_size(10);
    g.throughput(Throughput::Elements(scene.time.frames as u64));
    g.bench_function("within_broad", |b| {
        b.iter(|| black_box(run(black_box(&scene), &options(true, true))));
    });
    g.bench_function("within_no_broad", |b| {
        b.iter(|| black_box(run(black_box(&scene), &options(false, true))));
    });
    g.throughput(Throughput::Elements(all.time.frames as u64));
    g.bench_function("all_coherence", |b| {
        b.iter(|| black_box(run(black_box(&all), &options(true, true))));
    });
    g.bench_function("all_no_coherence", |b| {
        b.iter(|| black_box(run(black_box(&all), &options(true, false))));
    });
    g.finish();
}

/// The thousand-body fixture's construction with `cols x rows` bodies: random convex 8-gons of
/// radius 1 on a grid of spacing 3, drifting and turning slowly, all pairs within 1.5, 5 frames.
fn grid_scene(cols: usize, rows: usize) -> Scene {
    let mut s = String::from("name = \"grid\"\ntime = { end = 1.0, step = 0.25 }\n");
    for k in 0..cols * rows {
        let (c, r) = (k % cols, k / cols);
        let v = |m: usize| (((k * m) % 11) as f64 - 5.0) / 10.0;
        s += &format!(
            "[[body]]\nid = \"b{k}\"\ngenerator = {{ type = \"random_convex\", n = 8, radius = 1.0, seed = {} }}\n\
             pose = {{ x = {}, y = {} }}\nmotion = {{ type = \"linear\", velocity = [{}, {}], angular = {} }}\n",
            k + 1,
            3 * c,
            3 * r,
            v(7),
            v(3),
            v(5) * 0.8,
        );
    }
    s += "[[query]]\npairs = \"all\"\neffects = [\"distance\"]\nwithin = 1.5\n";
    load_str(&s, &Origin::text("grid.toml")).unwrap_or_else(|e| panic!("{e}"))
}

fn bench_ten_thousand(c: &mut Criterion) {
    let scene = grid_scene(100, 100);
    let report = run(&scene, &options(true, true));
    eprintln!(
        "ten_thousand: {} pairs listed, {} narrow-phase queries, at most {} candidates in a frame, {} pair jobs",
        report.pairs.len(),
        report.costs.distance.calls,
        report.costs.max_frame_candidates,
        report.costs.pair_jobs
    );
    let mut g = c.benchmark_group("scene/ten_thousand");
    g.sample_size(10);
    g.throughput(Throughput::Elements(scene.time.frames as u64));
    g.bench_function("within_broad", |b| {
        b.iter(|| black_box(run(black_box(&scene), &options(true, true))));
    });
    g.finish();
}

/// `n` JSON lines of random convex pairs.
fn pair_lines(n: usize) -> String {
    let mut rng = SplitMix64::new(99);
    let mut s = String::new();
    let ring = |v: &[glam::DVec2]| {
        v.iter()
            .map(|p| format!("[{:?},{:?}]", p.x, p.y))
            .collect::<Vec<_>>()
            .join(",")
    };
    for k in 0..n {
        let na = 8 + (k % 57);
        let nb = 8 + (k * 7 % 57);
        let a = random_convex(&mut rng, na, glam::DVec2::ZERO, 1.0);
        let off = glam::DVec2::new(1.0 + (k % 5) as f64, (k % 3) as f64 - 1.0);
        let b = random_convex(&mut rng, nb, off, 1.0);
        s += &format!(
            "{{\"id\":{k},\"a\":[{}],\"b\":[{}],\"effects\":[\"distance\",\"closest_points\"]}}\n",
            ring(&a),
            ring(&b)
        );
    }
    s
}

fn bench_batch(c: &mut Criterion) {
    const N: usize = 20_000;
    let input = pair_lines(N);
    let mut g = c.benchmark_group("batch/pairs");
    g.sample_size(10);
    g.throughput(Throughput::Elements(N as u64));
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let check = pool.install(|| {
            batch_pairs(input.as_bytes(), std::io::sink(), &BatchOptions::default()).unwrap()
        });
        assert_eq!((check.lines, check.errors), (N as u64, 0));
        g.bench_function(format!("threads_{threads}"), |b| {
            b.iter(|| {
                pool.install(|| {
                    black_box(
                        batch_pairs(
                            black_box(input.as_bytes()),
                            std::io::sink(),
                            &BatchOptions::default(),
                        )
                        .unwrap(),
                    )
                })
            });
        });
    }
    g.finish();
}

/// Every group of this file (what `criterion_group!` would generate, documented).
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    bench_thousand(&mut c);
    bench_ten_thousand(&mut c);
    bench_batch(&mut c);
}

criterion_main!(benches);
