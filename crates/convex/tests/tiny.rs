//! Tiny polygons on a 5×5 grid (points, segments, triangles, quadrilaterals): every degeneracy at once
//! (shared vertices, collinear edges, touching, crossing, containment), against the exact oracle.

mod common;

use common::check_all;
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Exact, Robust};
use polydist_convex::{reset_search_stats, search_stats};
use polydist_oracle::SplitMix64;

/// 1 to 4 random grid points forming a valid convex ring (retried until valid).
fn grid_polygon(rng: &mut SplitMix64) -> Vec<DVec2> {
    loop {
        let k = 1 + rng.index(4);
        let pts: Vec<DVec2> = (0..k)
            .map(|_| DVec2::new(rng.index(5) as f64, rng.index(5) as f64))
            .collect();
        // The oracle wants distinct points in convex position; our constructor validates the rest.
        let distinct = (0..k).all(|i| (0..i).all(|j| pts[i] != pts[j]));
        if distinct && ConvexPolygon::try_new(&pts).is_ok() && polydist_oracle::is_convex(&pts) {
            return pts;
        }
    }
}

#[test]
fn tiny_grid_polygons_agree_with_the_oracle() {
    reset_search_stats();
    let mut rng = SplitMix64::new(1);
    for _ in 0..6000 {
        let p = grid_polygon(&mut rng);
        let q = grid_polygon(&mut rng);
        check_all::<Robust>(&p, &q, true);
        check_all::<Exact>(&p, &q, true);
    }
    let s = search_stats();
    println!("{s:?}");
    assert_eq!(s.brute_fallbacks, 0, "{s:?}");
}
