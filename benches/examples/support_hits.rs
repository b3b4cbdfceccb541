//! How often the small-input path answers (the support guess, or the walk below `n + m = 64`) on the
//! convex benchmark's random pairs: `support_hits <n> <pairs>`. Prints the share per workload.

use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::Robust;
use polydist_convex::{distance_with, reset_search_stats, search_stats};
use polydist_oracle::{SplitMix64, random_convex};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args[1].parse().expect("n");
    let pairs: usize = args[2].parse().expect("pairs");
    for plus_x in [false, true] {
        let mut rng = SplitMix64::new(5 ^ n as u64);
        reset_search_stats();
        for _ in 0..pairs {
            let dir = if plus_x {
                DVec2::X
            } else {
                let t = rng.unit_f64() * core::f64::consts::TAU;
                DVec2::new(t.cos(), t.sin())
            };
            let gap = 0.05 + 0.5 * rng.unit_f64();
            let p =
                ConvexPolygon::try_new(&random_convex(&mut rng, n, DVec2::ZERO, 1.0)).expect("P");
            let q = ConvexPolygon::try_new(&random_convex(&mut rng, n, dir * (3.0 + gap), 1.0))
                .expect("Q");
            let _ = distance_with::<Robust>(&p, &q);
        }
        let s = search_stats();
        println!(
            "n = {n}, plus_x = {plus_x}: {} of {pairs} answered by the small-input path",
            s.linear_walks
        );
    }
}
