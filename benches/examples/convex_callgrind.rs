//! A driver for instruction counts (callgrind) of the convex benchmark's queries: one pair of the
//! `convex` bench (the same generator and seeds), one series, a given number of repetitions.
//!
//! Run `valgrind --tool=callgrind` on it twice, with `0` and with `k` repetitions: the difference of the
//! two totals divided by `k` is the instruction count of one query (exact, unlike timings on a shared
//! machine).
//!
//! Usage: `convex_callgrind <random_dir|plus_x> <n> <series> <repetitions>`, where `series` is one of
//! `polydist_fast`, `polydist_robust`, `polydist_exact`, `yang_robust`, `parry_distance`,
//! `parry_closest_points`.

use std::hint::black_box;

use glam::DVec2;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Fast, Robust};
use polydist_convex::{distance_with, distance_yang_with};
use polydist_oracle::{SplitMix64, random_convex};

/// The pair of `benches/convex.rs` (`make_pair`): two random convex `n`-gons, the second one's centre
/// `3 + gap` away along a random direction or along `+x`.
fn rings(n: usize, plus_x: bool) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(0x00C0_FFEE ^ n as u64);
    let dir = if plus_x {
        DVec2::X
    } else {
        let t = rng.unit_f64() * core::f64::consts::TAU;
        DVec2::new(t.cos(), t.sin())
    };
    let gap = 0.05 + 0.5 * rng.unit_f64();
    let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
    let q = random_convex(&mut rng, n, dir * (3.0 + gap), 1.0);
    (p, q)
}

fn parry_polygon(ring: &[DVec2]) -> ParryPolygon {
    let pts = ring.iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("a polygon with area")
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: convex_callgrind <random_dir|plus_x> <n> <series> <repetitions>";
    assert_eq!(args.len(), 5, "{usage}");
    let plus_x = match args[1].as_str() {
        "plus_x" => true,
        "random_dir" => false,
        other => panic!("unknown workload {other}; {usage}"),
    };
    let n: usize = args[2].parse().expect(usage);
    let reps: usize = args[4].parse().expect(usage);
    let (p, q) = rings(n, plus_x);
    let (pp, qq) = (
        ConvexPolygon::try_new(&p).expect("valid P"),
        ConvexPolygon::try_new(&q).expect("valid Q"),
    );
    let (parry_p, parry_q) = (parry_polygon(&p), parry_polygon(&q));
    let id = Pose::identity();
    let mut sink = 0.0;
    for _ in 0..reps {
        let (a, b) = (black_box(&pp), black_box(&qq));
        sink += match args[3].as_str() {
            "polydist_fast" => distance_with::<Fast>(a, b).distance(),
            "polydist_robust" => distance_with::<Robust>(a, b).distance(),
            "polydist_exact" => distance_with::<Exact>(a, b).distance(),
            "yang_robust" => distance_yang_with::<Robust>(a, b).distance(),
            "parry_distance" => query::distance(&id, black_box(&parry_p), &id, black_box(&parry_q))
                .expect("supported"),
            "parry_closest_points" => {
                match query::closest_points(
                    &id,
                    black_box(&parry_p),
                    &id,
                    black_box(&parry_q),
                    f64::MAX,
                )
                .expect("supported")
                {
                    query::ClosestPoints::WithinMargin(x, y) => x.distance(y),
                    _ => f64::NAN,
                }
            }
            other => panic!("unknown series {other}; {usage}"),
        };
    }
    println!("{sink}");
}
