//! A distance query allocates nothing on the heap: `distance` and `distance_yang_with::<Robust>` on
//! disjoint pairs (and, on the same sizes, `distance` and `contact_with` on overlapping pairs and
//! `distance_within` on both sides of the threshold) of random convex polygons (3 … 4096 vertices), counted by a global allocator wrapper
//! (`stats_alloc`).
//!
//! Scope: **generic** inputs (random float coordinates, no exact ties), where the Robust kernel's
//! filters decide almost every sign and the constructions' exact evaluation stays in inline
//! expansions. Degenerate inputs may reach exact stages that can spill (`SmallVec` expansions, or
//! `BigInt` on a wide dynamic range); they are not claimed here.
//!
//! The counter is process-wide, so this file holds a single test (no other test thread allocates
//! while a region is open), and the polygons are built before each measured region. The test
//! harness's own thread can still allocate while a region is open (seen once in CI, 2026-12-07:
//! four allocations, 900 bytes, in one region of 270, not reproducible), so a region that counts
//! an allocation runs the same queries again in a fresh region, once per test run at most
//! ([`measured`]). An allocation of the queries themselves recurs on the same inputs and still
//! fails the test.

use std::alloc::System;

use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::Robust;
use polydist_convex::{
    Contact, Separation, Within, contact_with, distance, distance_within, distance_yang_with,
};
use polydist_oracle::{SplitMix64, random_convex};
use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

/// A disjoint pair: two random convex polygons in squares of half-side 1 (so within `√2` of their
/// centres), centres `3 + gap` apart along a random direction (or along +x when `along_x`).
fn pair(rng: &mut SplitMix64, n: usize, m: usize, along_x: bool) -> (ConvexPolygon, ConvexPolygon) {
    let dir = if along_x {
        DVec2::X
    } else {
        let t = rng.unit_f64() * core::f64::consts::TAU;
        DVec2::new(t.cos(), t.sin())
    };
    let gap = 0.01 + rng.unit_f64();
    let p = random_convex(rng, n, DVec2::ZERO, 1.0);
    let q = random_convex(rng, m, dir * (3.0 + gap), 1.0);
    (
        ConvexPolygon::try_new(&p).expect("valid P"),
        ConvexPolygon::try_new(&q).expect("valid Q"),
    )
}

/// Runs `queries` in a measured region and returns their answers. If the region counts an
/// allocation or a reallocation and no region has been run again yet (`retried` is false), the
/// same queries run again in a fresh region, which alone is then checked (see the module docs).
///
/// # Panics
/// Panics if the region checked counts an allocation or a reallocation.
fn measured<T>(what: &str, retried: &mut bool, queries: impl Fn() -> T) -> T {
    let region = Region::new(GLOBAL);
    let out = queries();
    let mut change = region.change();
    if (change.allocations, change.reallocations) != (0, 0) && !*retried {
        *retried = true;
        eprintln!("{what}: {change:?} in the first run; running the same queries again");
        let region = Region::new(GLOBAL);
        std::hint::black_box(queries());
        change = region.change();
    }
    assert_eq!(
        (change.allocations, change.reallocations),
        (0, 0),
        "{what}: {change:?}"
    );
    out
}

#[test]
fn robust_queries_do_not_allocate() {
    const SIZES: [usize; 9] = [3, 4, 5, 7, 8, 16, 64, 512, 4096];
    let mut rng = SplitMix64::new(2024);
    let mut queries = 0;
    let mut retried = false;
    for (k, &n) in SIZES.iter().enumerate() {
        for &m in &SIZES[k..] {
            for round in 0..6 {
                let (p, q) = pair(&mut rng, n, m, round % 3 == 0);
                let what = format!("n = {n}, m = {m}, round {round}");
                let (a, b, c, d) = measured(&what, &mut retried, || {
                    (
                        distance(&p, &q),
                        distance_yang_with::<Robust>(&p, &q),
                        distance(&q, &p),
                        distance_yang_with::<Robust>(&q, &p),
                    )
                });
                // The inputs are disjoint: a query that returned early would not test the search.
                for s in [a, b, c, d] {
                    assert!(
                        matches!(s, Separation::Disjoint(_)),
                        "n = {n}, m = {m}: {s:?}"
                    );
                }
                assert_eq!(a.distance(), b.distance());
                // Meeting inputs (the O(log) contact test after the search) and the threshold query.
                // A copy shrunk by half about the vertex centroid: inside P, so overlapping.
                let c = p.vertices().iter().copied().sum::<DVec2>() / p.len() as f64;
                let moved: Vec<DVec2> = p.vertices().iter().map(|&v| c + (v - c) * 0.5).collect();
                let overlapping = ConvexPolygon::try_new(&moved).expect("valid");
                let what = format!("meeting / within, n = {n}, m = {m}, round {round}");
                let (e, f, g, h) = measured(&what, &mut retried, || {
                    (
                        distance(&p, &overlapping),
                        contact_with::<Robust>(&p, &overlapping),
                        distance_within::<Robust>(&p, &q, 0.5 * a.distance()),
                        distance_within::<Robust>(&p, &q, 2.0 * a.distance()),
                    )
                });
                assert_eq!((e, f), (Separation::Overlapping, Contact::Overlapping));
                assert!(matches!(g, Within::Beyond { .. }) && matches!(h, Within::Inside(_)));
                queries += 4;
            }
        }
    }
    // The counter itself works: an allocation inside a region is seen.
    let region = Region::new(GLOBAL);
    let v = std::hint::black_box(vec![1u8; 32]);
    assert!(region.change().allocations >= 1);
    drop(v);
    assert_eq!(queries, 45 * 6 * 4);
}
