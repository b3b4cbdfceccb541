//! One separation query at a time, for profilers (`perf record --call-graph dwarf`): builds one of the
//! benchmark families of `benches/separation_polygons.rs` and times `separation_of_disjoint` under the
//! Robust and/or Fast kernel, printing each run's wall time and distance.
//!
//! `cargo run --release -p polydist-benches --example separation_profile -- <family> <N> <runs> <kernels>`
//! with family `combs` (interlocked, every clearance tied), `jit` (the same, jittered), `pocket` (a
//! star in a C's pocket, the containing case), `spir` (two interlocked spiral arms), `istar` (two random stars
//! pushed into each other), `saw` (saw-teeth tip to notch, the monotone sweep), `hook` (hooked
//! saw-teeth tip to notch: facing chains not monotone, section 3), `dec` (the tied
//! combs scaled by 0.1: decimal coordinates, whose ties the error-free stage cannot settle), `lid`
//! (two stars a unit apart, a notch facing a tip), `bowl` (a zigzag facing an arc around it, farther
//! than either is wide) and `cluster` (the same zigzag a hair wide: section 3's matrices), and kernels any of `r` (Robust), `s` (Robust, section 3's matrices only), `f` (Fast), `g` (geo's
//! distance, once per run, for sizes its criterion series skips) and `p` (parry2d-f64's build of both
//! polylines and its query) (default `combs 131072 5 rf`).
//! Figures only; the benchmarks are the reference.

use glam::DVec2;
use polydist_benches::{
    bowl, cluster, hooked_teeth, interlocked_combs, interlocked_combs_jittered,
    interlocked_spirals, interlocked_stars, pocket, sawteeth, stars_lid,
};
use polydist_polygon::SimplePolygon;
use polydist_predicates::{Fast, Robust};
use polydist_separation::{HullRouteMethod, separation_of_disjoint, separation_of_disjoint_with};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("combs");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(131_072);
    let reps: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(5);
    let (a, b): (Vec<DVec2>, Vec<DVec2>) = match which {
        "combs" => interlocked_combs(n),
        "jit" => interlocked_combs_jittered(n),
        "pocket" => pocket(n),
        "spir" => interlocked_spirals(n),
        "istar" => interlocked_stars(n),
        "saw" => sawteeth(n),
        "hook" => hooked_teeth(n),
        "lid" => stars_lid(n),
        "bowl" => bowl(n),
        "cluster" => cluster(n),
        "dec" => {
            let (a, b) = interlocked_combs(n);
            let s = |v: Vec<DVec2>| v.into_iter().map(|p| p * 0.1).collect();
            (s(a), s(b))
        }
        _ => panic!("unknown family {which}"),
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
            if let polydist_separation::PolygonSeparation::Separated { route, .. } = &r {
                println!("  {route:?}");
            }
            if let polydist_separation::PolygonSeparation::Separated { stats, .. } = &r {
                println!("  {stats:?}");
            }
        }
        if kern.contains('g') {
            // geo's `Euclidean.distance` between the two polygons, for the ratio at sizes the
            // criterion benchmark does not run geo at (it takes seconds there).
            use geo::{Distance, Euclidean, LineString, Polygon};
            let poly = |c: &[DVec2]| {
                Polygon::new(
                    LineString::from(c.iter().map(|v| (v.x, v.y)).collect::<Vec<_>>()),
                    vec![],
                )
            };
            let (gp, gq) = (poly(&a), poly(&b));
            let t = Instant::now();
            let d = Euclidean.distance(&gp, &gq);
            println!("{which} {n}: geo {:?} d={d}", t.elapsed());
        }
        if kern.contains('p') {
            // parry2d-f64's build of both closed polylines (BVH) and its query, as the criterion
            // series `parry_build_query` times them.
            use parry2d_f64::math::{Pose, Vector};
            use parry2d_f64::shape::Polyline;
            let line = |c: &[DVec2]| {
                let mut pts: Vec<Vector> = c.iter().map(|v| Vector::new(v.x, v.y)).collect();
                pts.push(pts[0]);
                Polyline::new(pts, None)
            };
            let t = Instant::now();
            let (lp, lq) = (line(&a), line(&b));
            let id = Pose::identity();
            let d = parry2d_f64::query::distance(&id, &lp, &id, &lq).expect("supported");
            println!("{which} {n}: parry build + query {:?} d={d}", t.elapsed());
        }
        if kern.contains('s') {
            // The disjoint-hull route with section 3's matrices only (the paper's algorithm).
            let t = Instant::now();
            let r =
                separation_of_disjoint_with::<Robust>(&p, &q, HullRouteMethod::Section3).unwrap();
            println!(
                "{which} {n}: robust section 3 {:?} d={}",
                t.elapsed(),
                r.distance()
            );
        }
        if kern.contains('f') {
            let t = Instant::now();
            let d = separation_of_disjoint::<Fast>(&p, &q).unwrap().distance();
            println!("{which} {n}: fast {:?} d={d}", t.elapsed());
        }
    }
}
