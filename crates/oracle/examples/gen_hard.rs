//! Writes the hard-case suite `fixtures/hard/convex.txt` (issue 8): pairs of convex polygons from the
//! oracle's seeded generators, each with its exact answers computed by this crate (the independent
//! exact rational brute force), never by an algorithm under test.
//!
//! Also writes `fixtures/hard/simple.txt` (simple polygons: hulls disjoint, interlocked combs, and a
//! polygon in a pocket of the other, see `pocket_cases`) and the large pairs,
//! `large_convex.txt` and `large_simple.txt` (10⁴–10⁵ vertices, stored as a `gen` line that
//! `polydist_oracle::large_pair` rebuilds, answers from the oracle's pruned exact search).
//!
//! Run from the workspace root: `cargo run -p polydist-oracle --example gen_hard --release`.
//! The output is deterministic (fixed seeds, shortest round-trip decimals); the file is committed
//! and read by `polydist_fixtures::hard`.
//!
//! Format, one case per block:
//! ```text
//! case FAMILY NAME
//! p x y x y …          (P's vertices, shortest round-trip decimals, exact)
//! q x y …
//! contact C           (disjoint, touching or overlapping: relative interiors, filled polygons)
//! dist SQ PAIRS        (filled convex P, Q: exact squared distance, 0 when they meet; every optimal
//!                       feature pair as V3:E1 = vertex 3 of P with edge 1 of Q)
//! vdist SQ I:J …       (minimum vertex distance, squared, with every optimal index pair; vertices are
//!                       the corners polydist keeps: input vertices collinear with their neighbours
//!                       are not vertices, as `ConvexPolygon::try_new` documents)
//! hpq SQ I …           (directed Hausdorff h(P, Q) of the filled polygons, squared, every argmax)
//! hqp SQ J …           (h(Q, P))
//! cmmr SQ              (Σ dist(v, Q)² + Σ dist(w, P)² over the corners, exact)
//! end
//! ```
//!
//! The large convex cases (`large_convex.txt`) have a `gen` line instead of `p`/`q`, and instead of
//! `cmmr` a certified enclosure `cmmr_enclosure LO HI` (`LO ≤ CMMR ≤ HI`, exact dyadic rationals,
//! `HI − LO < 2⁻¹⁰⁰·CMMR`) from `polydist_oracle::cmmr_enclosure`: the exact sum is out of reach.

use std::fmt::Write as _;
use std::path::PathBuf;

use glam::DVec2;
use polydist_oracle::{
    Axis, Contact, Feature, PocketLid, Relation, SplitMix64, boundary_distance,
    boundary_distance_pruned, cmmr, cmmr_enclosure, cocircular, cocircular_perturbed, comb,
    contact_status_convex, contact_status_simple, convex_distance, convex_pair,
    directed_hausdorff_disjoint_pruned, directed_hausdorff_filled, filled_distance_pruned,
    fingerprint, interleaved_combs, interleaved_combs_ulps, large_pair_from, min_vertex_distance,
    min_vertex_distance_pruned, offset, parallel_facing, pocket_around, pocket_pair,
    random_convex_lattice, rat, sawtooth, sign_orient, sliver, spiral, star, step_ulps, two_opt,
    with_gap_ulps,
};

fn feature(f: Feature) -> String {
    match f {
        Feature::Vertex(i) => format!("V{i}"),
        Feature::Edge(i) => format!("E{i}"),
    }
}

/// Optimal feature pairs as `F:G` words.
fn feature_pairs(pairs: &[(Feature, Feature)]) -> String {
    let words: Vec<String> = pairs
        .iter()
        .map(|&(f, g)| format!("{}:{}", feature(f), feature(g)))
        .collect();
    words.join(" ")
}

/// Optimal vertex pairs as `i:j` words.
fn index_pairs(pairs: &[(usize, usize)]) -> String {
    let words: Vec<String> = pairs.iter().map(|(i, j)| format!("{i}:{j}")).collect();
    words.join(" ")
}

/// Vertex indices separated by spaces.
fn list(a: &[usize]) -> String {
    a.iter().map(usize::to_string).collect::<Vec<_>>().join(" ")
}

fn coords(v: &[DVec2]) -> String {
    v.iter()
        .map(|p| format!("{:?} {:?}", p.x, p.y))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The caller indices of the vertices `ConvexPolygon::try_new` keeps: the corners (first of a run of
/// repeats; vertices collinear with their neighbours dropped), decided exactly. The vertex-based
/// answers (`vdist`, `cmmr`) are defined on these, as polydist documents.
fn corners(v: &[DVec2]) -> Vec<usize> {
    let n = v.len();
    if n <= 2 {
        return (0..n).collect();
    }
    // The nearest distinct vertex before and after `i` (repeats are skipped).
    let distinct = |i: usize, step: usize| {
        (1..n)
            .map(|k| v[(i + k * step) % n])
            .find(|&w| w != v[i])
            .unwrap_or(v[i])
    };
    (0..n)
        .filter(|&i| {
            let (a, b, c) = (distinct(i, n - 1), v[i], distinct(i, 1));
            v[(i + n - 1) % n] != b && sign_orient(a, b, c) != std::cmp::Ordering::Equal
        })
        .collect()
}

/// One case with every answer.
fn case(out: &mut String, family: &str, name: &str, p: &[DVec2], q: &[DVec2]) {
    let d = convex_distance(p, q);
    let (kp, kq) = (corners(p), corners(q));
    let pick = |v: &[DVec2], k: &[usize]| -> Vec<DVec2> { k.iter().map(|&i| v[i]).collect() };
    let (cp, cq) = (pick(p, &kp), pick(q, &kq));
    let (vsq, vpairs) = min_vertex_distance(&cp, &cq);
    let vpairs: Vec<(usize, usize)> = vpairs.iter().map(|&(i, j)| (kp[i], kq[j])).collect();
    let (hpq, apq) = directed_hausdorff_filled(p, q);
    let (hqp, aqp) = directed_hausdorff_filled(q, p);
    let c = cmmr(&cp, &cq);
    let contact = match contact_status_convex(p, q) {
        Contact::Disjoint => "disjoint",
        Contact::Touching => "touching",
        Contact::Overlapping => "overlapping",
    };
    let _ = writeln!(out, "case {family} {name}");
    let _ = writeln!(out, "p {}", coords(p));
    let _ = writeln!(out, "q {}", coords(q));
    let _ = writeln!(out, "contact {contact}");
    let _ = writeln!(out, "dist {} {}", d.sq, feature_pairs(&d.pairs));
    let _ = writeln!(out, "vdist {} {}", vsq, index_pairs(&vpairs));
    let _ = writeln!(out, "hpq {} {}", hpq, list(&apq));
    let _ = writeln!(out, "hqp {} {}", hqp, list(&aqp));
    let _ = writeln!(out, "cmmr {c}");
    let _ = writeln!(out, "end");
}

fn moved(v: &[DVec2], dx: f64, dy: f64) -> Option<Vec<DVec2>> {
    offset(v, dx, dy)
}

fn main() {
    let mut out = String::new();
    out.push_str(
        "# polydist hard-case suite: pairs of convex polygons with exact answers from the oracle.\n\
         # Generated by `cargo run -p polydist-oracle --example gen_hard --release`: do not edit.\n\
         # Format: see crates/oracle/examples/gen_hard.rs.\n",
    );
    let mut rng = SplitMix64::new(0x4a7d_ca5e);
    let sizes = [(3, 3), (5, 7), (12, 9), (40, 33)];

    // Nearly touching: 1, 4 and 1000 ulps of the coordinates.
    for ulps in [1u64, 4, 1000] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            let pair = convex_pair(&mut rng, n, m, Relation::NearlyTouching { ulps });
            case(
                &mut out,
                "nearly_touching",
                &format!("{ulps}ulp-{k}"),
                &pair.p,
                &pair.q,
            );
        }
    }
    // Relative gaps about 1e-9 (2^-30) and 1e-12 (2^-40) of unit-size polygons, along x and y.
    for (label, ulps) in [("1e-9", 1u64 << 22), ("1e-12", 1u64 << 12)] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            let pair = convex_pair(&mut rng, n, m, Relation::NearlyTouching { ulps: 1 });
            let axis = if k % 2 == 0 { Axis::X } else { Axis::Y };
            if let Some(q) = with_gap_ulps(&pair.p, &pair.q, ulps, axis) {
                case(
                    &mut out,
                    "relative_gap",
                    &format!("{label}-{k}"),
                    &pair.p,
                    &q,
                );
            }
        }
    }
    // Exactly touching: vertex on vertex, vertex on edge, edge along edge.
    for (label, rel) in [
        ("vertex", Relation::TouchingVertex),
        ("vertex_on_edge", Relation::VertexOnEdge),
        ("edge", Relation::TouchingEdge),
    ] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            let pair = convex_pair(&mut rng, n, m, rel);
            case(
                &mut out,
                "touching",
                &format!("{label}-{k}"),
                &pair.p,
                &pair.q,
            );
        }
    }
    // Huge offsets with representable gaps: the generator's own 1e15 pairs, and nearly touching pairs
    // moved by 1e8 and 1e12 (exact moves only).
    for (k, &(n, m)) in sizes.iter().enumerate() {
        let pair = convex_pair(&mut rng, n, m, Relation::HugeOffset);
        case(
            &mut out,
            "huge_offset",
            &format!("1e15-{k}"),
            &pair.p,
            &pair.q,
        );
    }
    for off in [1e8f64, 1e12] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            // The pair lives in (−1, −0.5) on the grid 2^−53; scaled by 2^e (exact) it lies in
            // (−2^e, −2^(e−1)) on the grid 2^(e−53), where adding `off < 2^(e−1)` is exact.
            let pair = convex_pair(&mut rng, n, m, Relation::NearlyTouching { ulps: 4 });
            let e = (off.log2().ceil() as i32) + 1;
            let scale =
                |v: &[DVec2]| -> Vec<DVec2> { v.iter().map(|&x| x * 2f64.powi(e)).collect() };
            let (sp, sq) = (scale(&pair.p), scale(&pair.q));
            if let (Some(p), Some(q)) = (moved(&sp, off, off), moved(&sq, off, off)) {
                case(&mut out, "huge_offset", &format!("{off:e}-{k}"), &p, &q);
            }
        }
    }
    // Exactly parallel facing edges in integer directions, and one ulp off parallel.
    for (k, dir) in [(1, 0), (3, 4), (7, -2), (1, 1), (-5, 12)]
        .into_iter()
        .enumerate()
    {
        let n = [4, 6, 9, 5, 16][k];
        let f = parallel_facing(&mut rng, n, dir, 2f64.powi(-20));
        case(
            &mut out,
            "parallel",
            &format!("{}_{}", dir.0, dir.1),
            &f.p,
            &f.q,
        );
        // One ulp off: the last vertex of q (an end of its facing edge) moved by one ulp in x.
        let mut q = f.q.clone();
        let last = q.len() - 1;
        q[last].x = step_ulps(q[last].x, 1);
        if polydist_oracle::is_convex(&q) {
            case(
                &mut out,
                "parallel_ulp_off",
                &format!("{}_{}", dir.0, dir.1),
                &f.p,
                &q,
            );
        }
    }
    // Near-ties beyond f64's reach: parallel facing pairs moved far from the origin (scaled by a power
    // of two so that the move is exact), then one end of Q's facing edge moved 1–3 ulps *at that
    // magnitude*: which end of the facing edges is nearer is decided by less than the rounding error
    // of a plain f64 distance evaluation there.
    for (k, dir) in [(1, 0), (3, 4), (7, -2), (1, 1), (-5, 12), (2, 1)]
        .into_iter()
        .enumerate()
    {
        let f = parallel_facing(&mut rng, [4, 5, 7, 6, 9, 8][k], dir, 2f64.powi(-20));
        for off in [2f64.powi(27), 2f64.powi(40)] {
            let e = off.log2() as i32 - 20;
            let scale =
                |v: &[DVec2]| -> Vec<DVec2> { v.iter().map(|&x| x * 2f64.powi(e)).collect() };
            let (Some(p), Some(q)) = (moved(&scale(&f.p), off, off), moved(&scale(&f.q), off, off))
            else {
                continue;
            };
            for steps in [1i64, 2, 3] {
                let mut q = q.clone();
                let last = q.len() - 1;
                q[last].x = step_ulps(q[last].x, if k % 2 == 0 { steps } else { -steps });
                if polydist_oracle::is_convex(&q) && polydist_oracle::is_convex(&p) {
                    let name = format!("{}_{}_2^{}_{steps}ulp", dir.0, dir.1, off.log2());
                    case(&mut out, "near_tie_far", &name, &p, &q);
                }
            }
        }
    }
    // Co-circular vertex sets (McKenna–Toussaint): the lattice points of x² + y² = 5^(2k) with
    // x > 5^k / 2, every one at the same distance from Q's vertex at the origin; then one vertex moved
    // one ulp in or out.
    for k in [1u32, 2, 3] {
        let r = 5f64.powi(k as i32);
        let arc =
            |pts: Vec<DVec2>| -> Vec<DVec2> { pts.into_iter().filter(|v| v.x > r / 2.0).collect() };
        let q = vec![DVec2::ZERO, DVec2::new(-r, r), DVec2::new(-r, -r)];
        let p = arc(cocircular(k));
        if p.len() >= 3 {
            case(&mut out, "cocircular", &format!("k{k}"), &p, &q);
        }
        let full = cocircular(k);
        let index = full.iter().position(|v| v.x > r / 2.0).unwrap_or(0);
        for steps in [-1i64, 1] {
            let p = arc(cocircular_perturbed(k, index, steps));
            if p.len() >= 3 && polydist_oracle::is_convex(&p) {
                case(
                    &mut out,
                    "cocircular_perturbed",
                    &format!("k{k}_{steps}"),
                    &p,
                    &q,
                );
            }
        }
    }
    // The same sets far from the origin (integer moves, exact) with k up to 10: the squared
    // distances then exceed 2^53, so plain f64 cannot separate the near-ties a one-ulp move makes.
    for k in [6u32, 8, 10] {
        let r = 5f64.powi(k as i32);
        let arc =
            |pts: Vec<DVec2>| -> Vec<DVec2> { pts.into_iter().filter(|v| v.x > r / 2.0).collect() };
        let q = vec![DVec2::ZERO, DVec2::new(-r, r), DVec2::new(-r, -r)];
        let full = cocircular(k);
        let index = full.iter().position(|v| v.x > r / 2.0).unwrap_or(0);
        for off in [2f64.powi(26), 2f64.powi(40)] {
            for steps in [0i64, -1, 1] {
                let p = arc(if steps == 0 {
                    cocircular(k)
                } else {
                    cocircular_perturbed(k, index, steps)
                });
                let (Some(pm), Some(qm)) = (moved(&p, off, -off), moved(&q, off, -off)) else {
                    continue;
                };
                if pm.len() >= 3 && polydist_oracle::is_convex(&pm) {
                    case(
                        &mut out,
                        "cocircular_far",
                        &format!("k{k}_{steps}_2^{}", off.log2()),
                        &pm,
                        &qm,
                    );
                }
            }
        }
    }
    // Collinear input vertices, slivers, far apart.
    for (label, rel) in [
        ("collinear_input", Relation::CollinearInput),
        ("sliver", Relation::Sliver),
        ("far", Relation::Far),
    ] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            let pair = convex_pair(&mut rng, n, m, rel);
            case(&mut out, label, &format!("{k}"), &pair.p, &pair.q);
        }
    }
    // Slivers of aspect ratio about 1e9 (2^30) beside a unit triangle.
    for k in 0..3 {
        let s = sliver(&mut rng, 6 + 3 * k, 2f64.powi(30));
        let max_x = s.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
        let t = vec![
            DVec2::new(max_x + 0.5, 0.0),
            DVec2::new(max_x + 1.5, -0.5),
            DVec2::new(max_x + 1.5, 0.5),
        ];
        case(&mut out, "sliver_1e9", &format!("{k}"), &s, &t);
    }
    // Overlapping, nested and identical polygons (for Hausdorff and CMMR).
    for (label, rel) in [
        ("overlapping", Relation::Overlapping),
        ("nested", Relation::Nested),
    ] {
        for (k, &(n, m)) in sizes.iter().enumerate() {
            let pair = convex_pair(&mut rng, n, m, rel);
            case(&mut out, label, &format!("{k}"), &pair.p, &pair.q);
        }
    }
    for (k, &(n, m)) in sizes.iter().enumerate() {
        let pair = convex_pair(&mut rng, n, m, Relation::Far);
        case(&mut out, "identical", &format!("{k}"), &pair.p, &pair.p);
    }

    let hurting = fast_hurting(&mut rng);
    for (family, name, p, q) in &hurting {
        case(&mut out, family, name, p, q);
    }

    write("convex.txt", &out);
    write("simple.txt", &simple_cases(&hurting));
    let (large_convex, large_simple) = large_cases();
    write("large_convex.txt", &large_convex);
    write("large_simple.txt", &large_simple);
}

/// The large pairs (10⁴–10⁵ vertices): stored as their `gen` line (parameters and fingerprint,
/// rebuilt bit for bit by `polydist_oracle::large_pair`) with answers from the oracle's *pruned*
/// exact search (`polydist_oracle::boundary_distance_pruned` and friends, whose module doc proves
/// that the pruning never discards an optimal pair). CMMR as a certified enclosure
/// (`polydist_oracle::cmmr_enclosure`, proof in its module doc): its exact value, a sum of 10⁵
/// rationals with distinct denominators, is out of reach. The pairs are strictly convex, so every
/// vertex is a corner (the vertices CMMR is defined on).
fn large_cases() -> (String, String) {
    let mut convex = String::from(
        "# polydist hard-case suite: large convex pairs (10^4-10^5 vertices), answers from the oracle's\n\
         # pruned exact search. Generated by `cargo run -p polydist-oracle --example gen_hard --release`:\n\
         # do not edit. `gen KIND PARAMS FINGERPRINT` rebuilds the pair (polydist_oracle::large_pair);\n\
         # contact/dist/vdist/hpq/hqp as in convex.txt; cmmr_enclosure LO HI: LO <= CMMR <= HI, exact\n\
         # dyadic rationals, HI - LO < 2^-100 CMMR (polydist_oracle::cmmr_enclosure).\n",
    );
    for (family, name, spec) in [
        ("large_circle", "n1e4_1ulp", "circle 10000 30 1 0"),
        ("large_circle", "n1e4_3ulp_dy37", "circle 10000 30 3 37"),
        ("large_circle", "n1e5_2ulp", "circle 100000 30 2 0"),
        (
            "large_circle",
            "n1e5_1ulp_dy1001",
            "circle 100000 30 1 1001",
        ),
        ("large_cocircular", "k8", "cocircular 8 0"),
        ("large_cocircular", "k8_in", "cocircular 8 -1"),
        ("large_cocircular", "k8_out", "cocircular 8 1"),
        ("large_cocircular", "k10", "cocircular 10 0"),
        ("large_cocircular", "k10_in", "cocircular 10 -1"),
    ] {
        let (p, q, gen_line) = rebuild(spec);
        assert!(
            polydist_oracle::is_strictly_convex(&p) && polydist_oracle::is_strictly_convex(&q),
            "{spec}: not strictly convex"
        );
        let d = filled_distance_pruned(&p, &q);
        assert!(
            d.sq > num_zero(),
            "{spec}: the large families are disjoint by construction"
        );
        let (vsq, vpairs) = min_vertex_distance_pruned(&p, &q);
        let (hpq, apq) = directed_hausdorff_disjoint_pruned(&p, &q).expect("disjoint");
        let (hqp, aqp) = directed_hausdorff_disjoint_pruned(&q, &p).expect("disjoint");
        let enclosure = cmmr_enclosure(&p, &q);
        let _ = writeln!(convex, "case {family} {name}");
        let _ = writeln!(convex, "gen {gen_line}");
        let _ = writeln!(convex, "contact disjoint");
        let _ = writeln!(convex, "dist {} {}", d.sq, feature_pairs(&d.pairs));
        let _ = writeln!(convex, "vdist {} {}", vsq, index_pairs(&vpairs));
        let _ = writeln!(convex, "hpq {} {}", hpq, list(&apq));
        let _ = writeln!(convex, "hqp {} {}", hqp, list(&aqp));
        let _ = writeln!(convex, "cmmr_enclosure {} {}", enclosure.lo, enclosure.hi);
        let _ = writeln!(convex, "end");
        println!("{family}/{name}: {} and {} vertices", p.len(), q.len());
    }
    let mut simple = String::from(
        "# polydist hard-case suite: large simple pairs (10^4 vertices, hulls disjoint), answers from\n\
         # the oracle's pruned exact search. Generated by `cargo run -p polydist-oracle --example\n\
         # gen_hard --release`: do not edit. `gen` as in large_convex.txt; contact/dist as in simple.txt.\n",
    );
    for (family, name, spec) in [
        ("large_star", "n1e4_1ulp", "star 11 10000 2500 1"),
        ("large_star", "n1e4_4ulp", "star 12 10000 100 4"),
        ("large_comb", "t2500_aligned_1ulp", "comb 2500 3 1 1 0"),
        ("large_comb", "t2500_shifted_4ulp", "comb 2500 3 1 4 1"),
    ] {
        let (p, q, gen_line) = rebuild(spec);
        let d = boundary_distance_pruned(&p, &q);
        let contact = if filled_distance_pruned(&p, &q).sq > num_zero() {
            "disjoint"
        } else {
            panic!("{spec}: the large simple families are disjoint by construction")
        };
        let _ = writeln!(simple, "case {family} {name}");
        let _ = writeln!(simple, "gen {gen_line}");
        let _ = writeln!(simple, "contact {contact}");
        let _ = writeln!(simple, "dist {} {}", d.sq, feature_pairs(&d.pairs));
        let _ = writeln!(simple, "end");
        println!(
            "{family}/{name}: {} and {} vertices, {} optimal pairs",
            p.len(),
            q.len(),
            d.pairs.len()
        );
    }
    (convex, simple)
}

/// `(g, x, y)` with `g = gcd(a, b) = a·x + b·y` (extended Euclid, `i128`).
fn ext_gcd(a: i128, b: i128) -> (i128, i128, i128) {
    if b == 0 {
        (a, 1, 0)
    } else {
        let (g, x, y) = ext_gcd(b, a % b);
        (g, y, x - (a / b) * y)
    }
}

/// An integer vector `w` with `cross(d, w) = k` exactly (`d` primitive), shifted along `d` so that
/// its projection on `d` is about `t·|d|²`.
fn at_cross(d: (i128, i128), k: i128, t: f64) -> (i128, i128) {
    // cross(d, w) = d.0·w.1 − d.1·w.0 = 1 for w = (−y, x) with d.0·x + d.1·y = 1.
    let (g, x, y) = ext_gcd(d.0, d.1);
    assert!(g.abs() == 1, "direction not primitive");
    let w0 = (-y * g * k, x * g * k);
    let dd = (d.0 * d.0 + d.1 * d.1) as f64;
    let along = (w0.0 * d.0 + w0.1 * d.1) as f64 / dd;
    let shift = (t - along).round() as i128;
    (w0.0 + shift * d.0, w0.1 + shift * d.1)
}

fn world(v: (i128, i128)) -> DVec2 {
    assert!(v.0.abs() < 1 << 53 && v.1.abs() < 1 << 53, "not exact");
    DVec2::new(v.0 as f64, v.1 as f64)
}

/// A primitive direction `d` with components of about 43 bits and a base point `a` near
/// `(1e15, 1e15)`, drawn from `rng` (the far families' edge `a + M·d`).
fn far_direction(rng: &mut SplitMix64) -> ((i128, i128), (i128, i128)) {
    let d = loop {
        let d = (
            i128::from(rng.range_i64(1 << 42, 1 << 43)),
            i128::from(rng.range_i64(-(1 << 43), 1 << 43)),
        );
        if ext_gcd(d.0, d.1).0.abs() == 1 {
            break d;
        }
    };
    let a = (
        1_000_000_000_000_000 + i128::from(rng.range_i64(0, 1 << 30)),
        1_000_000_000_000_000 + i128::from(rng.range_i64(0, 1 << 30)),
    );
    (d, a)
}

/// Families built to defeat plain `f64` predicates (issue 8: measure the Fast kernel where it
/// hurts), every answer from the exact oracle as for the others:
///
/// - `orient_1_far`: a vertex `w` of Q at orientation exactly `k ∈ {−3, −1, 0, 1, 3}` (in units of
///   the integer grid) against a long edge `ab = 16·d` of P (`d` a primitive integer vector, `|b − a| ≈ 2^47`),
///   all near `(1e15, 1e15)`: `w` is `|k|/|d| ≈ 2^−43` off the edge's line (far below an ulp of
///   the coordinates, 0.125), on the outside (disjoint), on it (touching) or inside (overlapping), while a plain
///   `f64` cross product of those differences rounds by about `2^42`.
/// - `near_parallel_far`: Q's facing edge `cd` with its ends at orientations `(k_c, k_d)` against
///   P's long edge: nearly parallel edges whose nearer end is decided by a difference of
///   `1/|d|`.
/// - `cocircular_1e12`: the co-circular lattice sets scaled by `10^12` (exact integers, no longer
///   short significands, so `f64` squares round), and one vertex moved one ulp in or out.
fn fast_hurting(rng: &mut SplitMix64) -> Vec<Labelled> {
    let mut out = Vec::new();
    for case_k in 0..5 {
        // A primitive direction with ~43-bit components, a base point near (1e15, 1e15).
        let (d, a) = far_direction(rng);
        // The edge ab is M·d: the integer points at orientation k against the line (spaced by d)
        // fall M times along the edge.
        let m = 16;
        let b = (a.0 + m * d.0, a.1 + m * d.1);
        // P: a, b, then a far vertex on the left of ab (ccw), well inside the exact range.
        let left = (-d.1 * m / 2, d.0 * m / 2);
        let c = (a.0 + d.0 * m / 2 + left.0, a.1 + d.1 * m / 2 + left.1);
        let right = (d.1 * m / 4, -d.0 * m / 4);
        let p = vec![world(a), world(b), world(c)];
        for k in [-3i128, -1, 0, 1, 3] {
            // cross(b − a, w − a) = k: k < 0 is the right side of ab, outside P.
            let w = at_cross(d, k, (0.3 + 0.1 * case_k as f64) * m as f64);
            let w = (a.0 + w.0, a.1 + w.1);
            let q = vec![
                world(w),
                world((w.0 + right.0 - d.0 * m / 8, w.1 + right.1 - d.1 * m / 8)),
                world((w.0 + right.0 + d.0 * m / 8, w.1 + right.1 + d.1 * m / 8)),
            ];
            let q = if sign_orient(q[0], q[1], q[2]) == std::cmp::Ordering::Less {
                vec![q[0], q[2], q[1]]
            } else {
                q
            };
            if polydist_oracle::is_strictly_convex(&p) && polydist_oracle::is_strictly_convex(&q) {
                out.push(("orient_1_far", format!("{case_k}_k{k}"), p.clone(), q));
            }
        }
        // Nearly parallel facing edges: c at orientation kc, d at kd against ab (both outside).
        for (kc, kd) in [(-1i128, -2i128), (-2, -1), (-1, -1), (-3, -2)] {
            let wc = at_cross(d, kc, 0.65 * m as f64);
            let wd = at_cross(d, kd, 0.35 * m as f64);
            let (qc, qd) = ((a.0 + wc.0, a.1 + wc.1), (a.0 + wd.0, a.1 + wd.1));
            let e = ((qc.0 + qd.0) / 2 + right.0, (qc.1 + qd.1) / 2 + right.1);
            let q = vec![world(qc), world(qd), world(e)];
            let q = if sign_orient(q[0], q[1], q[2]) == std::cmp::Ordering::Less {
                vec![q[0], q[2], q[1]]
            } else {
                q
            };
            if polydist_oracle::is_strictly_convex(&q) {
                out.push((
                    "near_parallel_far",
                    format!("{case_k}_{kc}_{kd}"),
                    p.clone(),
                    q,
                ));
            }
        }
    }
    // Co-circular sets scaled by 10^12 (exact: integers below 2^53), ties exact or broken by one
    // ulp of the scaled coordinates.
    for k in [1u32, 2, 3] {
        let (r, s) = (5f64.powi(k as i32), 1e12);
        let arc: Vec<DVec2> = cocircular(k)
            .into_iter()
            .filter(|v| v.x > r / 2.0)
            .map(|v| v * s)
            .collect();
        let q = vec![
            DVec2::ZERO,
            DVec2::new(-r * s, r * s),
            DVec2::new(-r * s, -r * s),
        ];
        let mid = arc.len() / 2;
        for steps in [0i64, -1, 1] {
            let mut p = arc.clone();
            p[mid].x = step_ulps(p[mid].x, steps);
            if p.len() >= 3 && polydist_oracle::is_convex(&p) {
                out.push(("cocircular_1e12", format!("k{k}_{steps}"), p, q.clone()));
            }
        }
    }
    out
}

/// A pair with its family and name.
type Labelled = (&'static str, String, Vec<DVec2>, Vec<DVec2>);

/// The pair of a `gen` spec, and the spec with its fingerprint appended.
fn rebuild(spec: &str) -> (Vec<DVec2>, Vec<DVec2>, String) {
    let words: Vec<String> = spec.split_whitespace().map(str::to_owned).collect();
    let (p, q) = large_pair_from(&words).unwrap_or_else(|e| panic!("{e}"));
    let line = format!("{spec} {:x}", fingerprint(&p, &q));
    (p, q, line)
}

fn num_zero() -> num_rational::BigRational {
    num_rational::BigRational::new(0.into(), 1.into())
}

/// Writes `fixtures/hard/NAME`.
fn write(name: &str, text: &str) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/hard")
        .join(name);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).expect("create fixtures/hard");
    }
    std::fs::write(&path, text).expect("write a fixture");
    println!("wrote {}", path.display());
}

/// One pair of simple polygons: the contact status of the closed polygons and their exact boundary
/// distance with every optimal pair.
fn simple_case(out: &mut String, family: &str, name: &str, p: &[DVec2], q: &[DVec2]) {
    let contact = match contact_status_simple(p, q) {
        Contact::Disjoint => "disjoint",
        Contact::Touching => "touching",
        Contact::Overlapping => "overlapping",
    };
    let d = boundary_distance(p, q);
    let _ = writeln!(out, "case {family} {name}");
    let _ = writeln!(out, "p {}", coords(p));
    let _ = writeln!(out, "q {}", coords(q));
    let _ = writeln!(out, "contact {contact}");
    let _ = writeln!(out, "dist {} {}", d.sq, feature_pairs(&d.pairs));
    let _ = writeln!(out, "end");
}

/// The simple-polygon families: generated shapes side by side 1, 4 and 1000 ulps apart along x or
/// y, far from the origin, saw-teeth facing each other tip to notch (the hulls' closest features are
/// lids, so the separable-chains route runs), and interlocked combs (the hulls meet: Amato's
/// separator route).
///
/// Then the convex pairs built against plain `f64` near `(1e15, 1e15)` (`orient_1_far`,
/// `near_parallel_far`: convex polygons are simple; the touching and overlapping ones exercise the
/// intersection check), and last a polygon in a pocket of the other (one hull inside the other: the
/// separator's containing case, [`pocket_cases`], and one built against plain `f64`,
/// [`pocket_orient_far`]; appended with their own seeds, so the families before them do not
/// change).
fn simple_cases(hurting: &[Labelled]) -> String {
    let mut out = String::new();
    out.push_str(
        "# polydist hard-case suite: pairs of simple polygons with exact answers from the oracle.\n\
         # Generated by `cargo run -p polydist-oracle --example gen_hard --release`: do not edit.\n\
         # Format: case/p/q/contact/dist as in convex.txt (dist: exact squared boundary distance).\n",
    );
    let mut rng = SplitMix64::new(0x51_3b1e);
    let mut shapes: Vec<(String, Vec<DVec2>)> = Vec::new();
    for n in [6usize, 12, 30] {
        shapes.push((format!("star{n}"), star(&mut rng, n, n / 3)));
        shapes.push((format!("two_opt{n}"), two_opt(&mut rng, n)));
    }
    shapes.push(("spiral".to_owned(), spiral(6, 2)));
    shapes.push(("comb".to_owned(), comb(4, 3, 1)));
    for (k, (pn, p)) in shapes.iter().enumerate() {
        let (qn, q) = &shapes[(k + 3) % shapes.len()];
        for ulps in [1u64, 4, 1000] {
            let axis = if ulps == 4 { Axis::Y } else { Axis::X };
            if let Some(q) = with_gap_ulps(p, q, ulps, axis) {
                simple_case(
                    &mut out,
                    "side_by_side",
                    &format!("{pn}_{qn}_{ulps}ulp"),
                    p,
                    &q,
                );
                // Scaled by 2^41 (exact) so that adding 1e12 stays exact.
                let scale =
                    |v: &[DVec2]| -> Vec<DVec2> { v.iter().map(|&x| x * 2f64.powi(41)).collect() };
                if let (Some(pm), Some(qm)) = (
                    offset(&scale(p), 1e12, -1e12),
                    offset(&scale(&q), 1e12, -1e12),
                ) {
                    simple_case(
                        &mut out,
                        "side_by_side_far",
                        &format!("{pn}_{qn}_{ulps}ulp"),
                        &pm,
                        &qm,
                    );
                }
            }
        }
    }
    for t in [2usize, 5, 12] {
        let p = sawtooth(t);
        for gap_ulps in [1u64, 4, 1000] {
            // The mirror image moved up by one (tips opposite notches), `gap_ulps` ulps of 5 beyond the
            // tips: exact, the coordinates stay on the grid of ulp(5) = 2^-50 (below 8).
            let q: Vec<DVec2> = p
                .iter()
                .rev()
                .map(|v| DVec2::new(10.0 - v.x, v.y + 1.0))
                .collect();
            if let Some(q) = with_gap_ulps(&p, &q, gap_ulps, Axis::X) {
                simple_case(&mut out, "sawteeth", &format!("t{t}_{gap_ulps}ulp"), &p, &q);
            }
        }
    }
    // Interlocked combs: the hulls meet, so `separation` takes Amato's separator route. Clearances
    // of 1, 4 and 1000 grid steps (one ulp of the coordinates) and 1e-9, every clearance tying
    // exactly; the same scaled by 2^41 and moved to (1e12, -1e12) (exact).
    for (teeth, len) in [(3usize, 3u32), (8, 5)] {
        let mut pairs: Vec<(String, Vec<DVec2>, Vec<DVec2>)> = [1u64, 4, 1000]
            .iter()
            .map(|&ulps| {
                let c = interleaved_combs_ulps(teeth, len, ulps);
                (format!("t{teeth}_l{len}_{ulps}ulp"), c.a, c.b)
            })
            .collect();
        let c = interleaved_combs(teeth, len, 1e-9);
        pairs.push((format!("t{teeth}_l{len}_gap1e-9"), c.a, c.b));
        for (name, a, b) in pairs {
            simple_case(&mut out, "interlocked_combs", &name, &a, &b);
            let scale =
                |v: &[DVec2]| -> Vec<DVec2> { v.iter().map(|&x| x * 2f64.powi(41)).collect() };
            if let (Some(am), Some(bm)) = (
                offset(&scale(&a), 1e12, -1e12),
                offset(&scale(&b), 1e12, -1e12),
            ) {
                simple_case(&mut out, "interlocked_combs_far", &name, &am, &bm);
            }
        }
    }
    for (family, name, p, q) in hurting {
        if family.ends_with("_far") {
            simple_case(&mut out, family, name, p, q);
        }
    }
    pocket_cases(&mut out);
    pocket_orient_far(&mut out);
    out
}

/// Both argument orders of a containing-case pair (`outer` as P, then as Q), after checking the
/// construction's claims with the oracle: both simple, the exact distance is `gap`, the contact is
/// `Touching` exactly when `gap` is 0, and `inner` lies in `outer`'s bounding box, which is its hull
/// (blocks and combs are rectangles with notches).
fn pocket_case(
    out: &mut String,
    family: &str,
    name: &str,
    outer: &[DVec2],
    inner: &[DVec2],
    gap: f64,
) {
    let g = rat(gap).expect("a finite gap");
    let want = if gap == 0.0 {
        Contact::Touching
    } else {
        Contact::Disjoint
    };
    pocket_case_sq(out, family, name, (outer, inner), &(&g * &g), want);
}

/// [`pocket_case`] with the squared gap exact and the contact given.
fn pocket_case_sq(
    out: &mut String,
    family: &str,
    name: &str,
    (outer, inner): (&[DVec2], &[DVec2]),
    gap_sq: &num_rational::BigRational,
    want: Contact,
) {
    assert!(
        polydist_oracle::is_simple(outer) && polydist_oracle::is_simple(inner),
        "{family}/{name}: not simple"
    );
    assert_eq!(
        &boundary_distance(outer, inner).sq,
        gap_sq,
        "{family}/{name}: the squared gap is not {gap_sq}"
    );
    assert_eq!(contact_status_simple(outer, inner), want, "{family}/{name}");
    let bbox = |v: &[DVec2]| {
        v.iter().fold(
            (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ),
            |b, w| (b.0.min(w.x), b.1.max(w.x), b.2.min(w.y), b.3.max(w.y)),
        )
    };
    let (o, i) = (bbox(outer), bbox(inner));
    assert!(
        o.0 <= i.0 && i.1 <= o.1 && o.2 <= i.2 && i.3 <= o.3,
        "{family}/{name}: not in the outer hull"
    );
    simple_case(out, family, &format!("{name}_outer_p"), outer, inner);
    simple_case(out, family, &format!("{name}_outer_q"), inner, outer);
}

/// `v` scaled by `2^s` (exact).
fn scaled(v: &[DVec2], s: i32) -> Vec<DVec2> {
    v.iter().map(|&x| x * 2f64.powi(s)).collect()
}

/// `a + b` if exact.
fn exact_sum(a: f64, b: f64) -> Option<f64> {
    let s = a + b;
    (rat(s)? == rat(a)? + rat(b)?).then_some(s)
}

/// The ulp of the largest coordinate of `v` in magnitude.
fn ulp_of_largest(v: &[DVec2]) -> f64 {
    let big = v
        .iter()
        .map(|w| w.x.abs().max(w.y.abs()))
        .fold(0.0, f64::max);
    step_ulps(big, 1) - big
}

/// `v` with a unique topmost vertex (pinched on a lid line) or not.
fn unique_top(v: &[DVec2]) -> bool {
    let top = v.iter().map(|w| w.y).fold(f64::NEG_INFINITY, f64::max);
    v.iter().filter(|w| w.y == top).count() == 1
}

/// A convex lattice polygon cut flat on top: its lower chain from the lowest of its leftmost vertices
/// to the lowest of its rightmost, then straight up to one above its top and back across (integer
/// coordinates, exact): convex, with one horizontal top edge.
fn flat_top(v: &[DVec2]) -> Vec<DVec2> {
    let n = v.len();
    let key = |w: &DVec2| (w.x, w.y);
    let l = (0..n)
        .min_by(|&a, &b| key(&v[a]).partial_cmp(&key(&v[b])).expect("finite"))
        .expect("vertices");
    let r = (0..n)
        .min_by(|&a, &b| {
            (-v[a].x, v[a].y)
                .partial_cmp(&(-v[b].x, v[b].y))
                .expect("finite")
        })
        .expect("vertices");
    let top = v.iter().map(|w| w.y).fold(f64::NEG_INFINITY, f64::max) + 1.0;
    let mut out = Vec::new();
    let mut i = l;
    loop {
        out.push(v[i]);
        if i == r {
            break;
        }
        i = (i + 1) % n;
    }
    out.push(DVec2::new(v[r].x, top));
    out.push(DVec2::new(v[l].x, top));
    assert!(polydist_oracle::is_convex(&out), "flat_top: not convex");
    out
}

/// Which wall of a comb's notch a dropped polygon nearly touches.
#[derive(Clone, Copy)]
enum Wall {
    Left,
    Right,
    Floor,
}

/// A polygon to drop into a comb's notch (see [`in_notch`]).
struct Drop<'a> {
    name: &'static str,
    inner: &'a [DVec2],
    /// Notch `k` lies between teeth `k` and `k + 1`.
    notch: usize,
    wall: Wall,
    ulps: u64,
    on_lid: bool,
}

/// `d.inner` dropped into notch `d.notch` of `comb(teeth, len, space)`, both scaled by `2^s` and
/// moved by `origin` (exact or `None`): `d.ulps` ulps of the comb's largest coordinate from
/// `d.wall`, its top on the notch's lid line (the comb's top hull edge, which carries every tooth
/// tip) when `d.on_lid`, else a quarter of the way up (on a floor gap, an eighth of a unit from the
/// left wall). Returns the comb, the moved polygon and the gap.
fn in_notch(
    comb_shape: (usize, u32, u32),
    d: &Drop<'_>,
    s: i32,
    origin: (f64, f64),
) -> Option<(Vec<DVec2>, Vec<DVec2>, f64)> {
    let (teeth, len, space) = comb_shape;
    let (k, inner, wall, ulps, on_lid) = (d.notch, d.inner, d.wall, d.ulps, d.on_lid);
    assert!(k + 1 < teeth, "in_notch: no notch {k}");
    let c = offset(&scaled(&comb(teeth, len, space), s), origin.0, origin.1)?;
    let unit = 2f64.powi(s);
    let pitch = f64::from(1 + space);
    let a = exact_sum((k as f64 * pitch + 1.0) * unit, origin.0)?;
    let b = exact_sum((k as f64 + 1.0) * pitch * unit, origin.0)?;
    let (floor, lid) = (origin.1, exact_sum(f64::from(len) * unit, origin.1)?);
    let g = ulps as f64 * ulp_of_largest(&c);
    let inner = scaled(inner, s);
    let (x0, x1, y0, y1) = inner.iter().fold(
        (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ),
        |b, w| (b.0.min(w.x), b.1.max(w.x), b.2.min(w.y), b.3.max(w.y)),
    );
    // The translation taking `from` to `to`, if exact.
    let shift = |from: f64, to: f64| exact_sum(to, -from);
    let dx = match wall {
        Wall::Left => shift(x0, exact_sum(a, g)?)?,
        Wall::Right => shift(x1, exact_sum(b, -g)?)?,
        Wall::Floor => shift(x0, exact_sum(a, unit / 8.0)?)?,
    };
    let dy = match (wall, on_lid) {
        (Wall::Floor, false) => shift(y0, exact_sum(floor, g)?)?,
        (Wall::Floor, true) => panic!("in_notch: on the floor and on the lid"),
        (_, true) => shift(y1, lid)?,
        (_, false) => shift(y0, exact_sum(floor, exact_sum(lid, -floor)? / 4.0)?)?,
    };
    let moved = offset(&inner, dx, dy)?;
    Some((c, moved, g))
}

/// A polygon in a pocket of the other: Amato's separator, containing case (`CH(inner) ⊆
/// CH(outer)`), which `separation` answers through `Route::Separators`. Every pair in both argument
/// orders, its gap checked with the oracle before the oracle's answers are stored:
///
/// - `pocket`: `polydist_oracle::pocket_pair` (a block with a deep rectangular pocket, a tall convex
///   lattice polygon inside, clear of the lid) with gaps of 1, 4 and 1000 ulps of the coordinates,
///   relative gaps `2^−30 ≈ 1e-9` and `2^−40 ≈ 1e-12` (`2^22` and `2^12` ulps), and exactly touching
///   (gap 0: `Intersecting`); and a star and a comb in the open in a block built around them
///   (`polydist_oracle::pocket_around`).
/// - `pocket_lid`: the inner polygon's top on the lid's line (the hull edge across the opening),
///   without touching the block: pinched at one vertex (a star, a convex lattice polygon) or along an
///   edge (a convex polygon cut flat on top; a comb whose tooth tips all lie on the line), 1 and 4 ulps
///   from the walls, and once touching the walls.
/// - `comb_notch`: a star or a small comb (teeth up or down) dropped into a notch of a comb whose
///   notches all open on the one hull edge through every tooth tip, 0–4 ulps from a wall or the
///   floor, or pinched / along edges on the notch's lid line.
/// - `pocket_far`, `comb_notch_far`: the same built around polygons moved to `(1e8, −1e8)` and
///   `(1e12, −1e12)`, the gaps 1–4 ulps of the coordinates *there* (exact).
fn pocket_cases(out: &mut String) {
    let mut rng = SplitMix64::new(0x90c4_e7a1);
    // In the open: pocket_pair, its grid step learnt from a draw with the least positive gap (rounded
    // up to one step), then the same draw again with the gap wanted.
    let gaps: [(&str, u64); 6] = [
        ("1ulp", 1),
        ("4ulp", 4),
        ("1000ulp", 1000),
        ("1e-9", 1 << 22),
        ("1e-12", 1 << 12),
        ("touch", 0),
    ];
    let sizes = [12usize, 40, 100];
    for (k, (label, ulps)) in gaps.into_iter().enumerate() {
        for n in [sizes[k % 3], sizes[(k + 1) % 3]] {
            let u = pocket_pair(&mut rng.clone(), n, f64::MIN_POSITIVE).gap;
            let pp = pocket_pair(&mut rng, n, ulps as f64 * u);
            assert_eq!(pp.gap, ulps as f64 * u, "pocket_pair: gap");
            pocket_case(
                out,
                "pocket",
                &format!("n{n}_{label}"),
                &pp.p,
                &pp.q,
                pp.gap,
            );
        }
    }
    for (name, inner, ulps) in [
        ("star60_1ulp", star(&mut rng, 60, 12), 1u64),
        ("star150_4ulp", star(&mut rng, 150, 30), 4),
        ("comb5_1ulp", comb(5, 3, 2), 1),
    ] {
        let pp = pocket_around(&inner, ulps, PocketLid::Clear).expect("exact");
        pocket_case(out, "pocket", name, &pp.p, &pp.q, pp.gap);
    }

    // On the lid's line.
    let pinched_star = |rng: &mut SplitMix64, n: usize| loop {
        let s = star(rng, n, n / 4);
        if unique_top(&s) {
            break s;
        }
    };
    let pinched_convex = |rng: &mut SplitMix64, n: usize| loop {
        let c = random_convex_lattice(rng, n, 2000);
        if unique_top(&c) {
            break c;
        }
    };
    let lid_shapes: Vec<(&str, Vec<DVec2>)> = vec![
        ("pinched_star40", pinched_star(&mut rng, 40)),
        ("pinched_convex30", pinched_convex(&mut rng, 30)),
        (
            "edge_flat_convex30",
            flat_top(&random_convex_lattice(&mut rng, 30, 2000)),
        ),
        ("edges_comb6", comb(6, 4, 1)),
    ];
    for (name, inner) in &lid_shapes {
        for ulps in [1u64, 4] {
            let pp = pocket_around(inner, ulps, PocketLid::Touching).expect("exact");
            pocket_case(
                out,
                "pocket_lid",
                &format!("{name}_{ulps}ulp"),
                &pp.p,
                &pp.q,
                pp.gap,
            );
        }
    }
    let pp = pocket_around(&lid_shapes[0].1, 0, PocketLid::Touching).expect("exact");
    pocket_case(
        out,
        "pocket_lid",
        "pinched_star40_touch",
        &pp.p,
        &pp.q,
        pp.gap,
    );

    // Dropped into a comb's notch: six teeth of height 8 four apart (coordinates up to 26, grid
    // 2^-48); a star in [−1, 1]², a comb of three teeth halved (2.5 × 1.5), upright or upside down.
    let shape = (6usize, 8u32, 4u32);
    let little_comb: Vec<DVec2> = comb(3, 2, 1).iter().map(|&v| v * 0.5).collect();
    let upside_down: Vec<DVec2> = little_comb.iter().map(|&v| -v).collect();
    let notch_star = pinched_star(&mut rng, 24);
    let drop = |name, inner, notch, wall, ulps, on_lid| Drop {
        name,
        inner,
        notch,
        wall,
        ulps,
        on_lid,
    };
    let notch_cases = [
        drop("star_right_1ulp", &notch_star, 1, Wall::Right, 1, false),
        drop("star_floor_2ulp", &notch_star, 3, Wall::Floor, 2, false),
        drop(
            "comb_down_floor_4ulp",
            &upside_down,
            2,
            Wall::Floor,
            4,
            false,
        ),
        drop("comb_left_1ulp", &little_comb, 0, Wall::Left, 1, false),
        drop(
            "star_pinched_right_1ulp",
            &notch_star,
            2,
            Wall::Right,
            1,
            true,
        ),
        drop(
            "comb_on_lid_left_3ulp",
            &little_comb,
            4,
            Wall::Left,
            3,
            true,
        ),
        drop("star_right_touch", &notch_star, 1, Wall::Right, 0, false),
    ];
    for d in &notch_cases {
        let (c, moved, g) = in_notch(shape, d, 0, (0.0, 0.0)).expect("exact");
        let name = format!("n{}_{}", d.notch, d.name);
        pocket_case(out, "comb_notch", &name, &c, &moved, g);
    }

    // Far from the origin: the polygons moved first (exactly), the gaps counted in ulps there.
    let far_convex = random_convex_lattice(&mut rng, 40, 1 << 12);
    let far_star = scaled(&pinched_star(&mut rng, 30), 12);
    for (off, label) in [(1e8f64, "1e8"), (1e12, "1e12")] {
        for (name, inner, ulps, lid) in [
            ("convex40_1ulp", &far_convex, 1u64, PocketLid::Clear),
            ("convex40_4ulp", &far_convex, 4, PocketLid::Clear),
            ("pinched_star30_1ulp", &far_star, 1, PocketLid::Touching),
            ("star30_touch", &far_star, 0, PocketLid::Clear),
        ] {
            let moved = offset(inner, off, -off).expect("an exact move");
            let pp = pocket_around(&moved, ulps, lid).expect("exact");
            pocket_case(
                out,
                "pocket_far",
                &format!("{label}_{name}"),
                &pp.p,
                &pp.q,
                pp.gap,
            );
        }
        for d in &notch_cases[..5] {
            if matches!(d.name, "comb_left_1ulp" | "star_floor_2ulp") {
                continue;
            }
            let (c, moved, g) = in_notch(shape, d, 12, (off, -off)).expect("exact");
            let name = format!("{label}_n{}_{}", d.notch, d.name);
            pocket_case(out, "comb_notch_far", &name, &c, &moved, g);
        }
    }
}

/// `pocket_orient_far`: a pocket built against plain `f64`, like `orient_1_far`. Near
/// `(1e15, 1e15)`, with `d` a primitive integer direction of about 43 bits and `r = (d.1, −d.0)`, the
/// block is `a + s·d + t·r` over `s ∈ [0, 20]`, `t ∈ [−4, 12]` less the pocket `s ∈ (0, 16]`,
/// `t ∈ (0, 8)`, open at `s = 0`; its wall `t = 0` is 16 `d` long (about `2^47`). A triangle in the
/// pocket has its vertex `w` at orientation exactly `k ∈ {−3, −1, 0, 1}` grid units against that wall
/// (`k/|d| ≈ 2^−43` from its line: inside the pocket, on the wall, or through it), its other two
/// vertices 4 `r` deeper. Integer coordinates below `2^53` (exact); both argument orders.
fn pocket_orient_far(out: &mut String) {
    let mut rng = SplitMix64::new(0x90c4_e7a2);
    for case_k in 0..3 {
        let (d, a) = far_direction(&mut rng);
        let r = (d.1, -d.0);
        let at = |s: i128, t: i128| (a.0 + s * d.0 + t * r.0, a.1 + s * d.1 + t * r.1);
        let mut block: Vec<DVec2> = [
            (0, -4),
            (20, -4),
            (20, 12),
            (0, 12),
            (0, 8),
            (16, 8),
            (16, 0),
            (0, 0),
        ]
        .iter()
        .map(|&(s, t)| world(at(s, t)))
        .collect();
        if polydist_oracle::signed_area(&block) < num_zero() {
            block.reverse();
        }
        let dd = d.0 * d.0 + d.1 * d.1;
        for k in [-3i128, -1, 0, 1] {
            // cross(d, w − a) = k: k < 0 is t > 0, inside the pocket.
            let w = at_cross(d, k, (0.3 + 0.15 * case_k as f64) * 16.0);
            let w = (a.0 + w.0, a.1 + w.1);
            let tri = |sign: i128| {
                world((
                    w.0 + 4 * r.0 + sign * 2 * d.0,
                    w.1 + 4 * r.1 + sign * 2 * d.1,
                ))
            };
            let mut inner = vec![world(w), tri(-1), tri(1)];
            if sign_orient(inner[0], inner[1], inner[2]) == std::cmp::Ordering::Less {
                inner.swap(1, 2);
            }
            let (gap_sq, want) = match k.signum() {
                -1 => (
                    num_rational::BigRational::new((k * k).into(), dd.into()),
                    Contact::Disjoint,
                ),
                0 => (num_zero(), Contact::Touching),
                _ => (num_zero(), Contact::Overlapping),
            };
            pocket_case_sq(
                out,
                "pocket_orient_far",
                &format!("{case_k}_k{k}"),
                (&block, &inner),
                &gap_sq,
                want,
            );
        }
    }
}
