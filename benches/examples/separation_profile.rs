//! One separation query at a time, for profilers (`perf record --call-graph dwarf`): builds one of the
//! benchmark families of `benches/separation_polygons.rs` and times `separation_of_disjoint` under the
//! Robust and/or Fast kernel, printing each run's wall time and distance.
//!
//! `cargo run --release -p polydist-benches --example separation_profile -- <family> <N> <runs> <kernels>`
//! with family `combs` (interlocked, every clearance tied), `jit` (the same, jittered), `saw`
//! (saw-teeth tip to notch, section 3), and kernels `r`, `f` or `rf` (default `combs 131072 5 rf`).
//! Figures only; the benchmarks are the reference.

use glam::DVec2;
use polydist_polygon::SimplePolygon;
use polydist_predicates::{Fast, Robust};
use polydist_separation::separation_of_disjoint;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("combs");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(131_072);
    let reps: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(5);
    let (a, b): (Vec<DVec2>, Vec<DVec2>) = match which {
        "combs" => {
            let pair = polydist_oracle::interleaved_combs((n / 8).max(1), 5, 0.125);
            (pair.a, pair.b)
        }
        "jit" => {
            let pair = polydist_oracle::interleaved_combs((n / 8).max(1), 5, 0.125);
            let mut rng = polydist_oracle::SplitMix64::new(0x1177 ^ n as u64);
            let mut jitter = |v: &[DVec2]| -> Vec<DVec2> {
                v.iter()
                    .map(|&x| {
                        let d = DVec2::new(
                            rng.range_i64(-63, 64) as f64,
                            rng.range_i64(-63, 64) as f64,
                        );
                        x + d * 2f64.powi(-12)
                    })
                    .collect()
            };
            (jitter(&pair.a), jitter(&pair.b))
        }
        "saw" => {
            let p = polydist_oracle::sawtooth((n / 4).max(1));
            let q: Vec<DVec2> = p
                .iter()
                .rev()
                .map(|v| DVec2::new(10.25 - v.x, v.y + 1.0))
                .collect();
            (p, q)
        }
        _ => panic!(),
    };
    let p = SimplePolygon::try_new(&a).unwrap();
    let q = SimplePolygon::try_new(&b).unwrap();
    let kern = args.get(4).map(String::as_str).unwrap_or("rf");
    for _ in 0..reps {
        if kern.contains('r') {
            let t = Instant::now();
            let r = separation_of_disjoint::<Robust>(&p, &q).unwrap();
            let el = t.elapsed();
            println!("{which} {n}: robust {el:?} d={}", r.distance());
            if let polydist_separation::PolygonSeparation::Separated { stats, .. } = &r {
                println!("  {stats:?}");
            }
        }
        if kern.contains('f') {
            let t = Instant::now();
            let d = separation_of_disjoint::<Fast>(&p, &q).unwrap().distance();
            println!("{which} {n}: fast {:?} d={d}", t.elapsed());
        }
    }
}
