//! The monotone sweep of the disjoint-hull route (`src/monotone.rs`): terrains facing each other
//! (monotone facing chains, lattice ties, tiny and huge gaps, every axis direction, far from the
//! origin, rotated), against the exact oracle, section 3 and the brute force; facing chains that are
//! not monotone, and crowded windows, decline to section 3; the candidate count stays linear.
//!
//! An independent check runs with every answer: the facing chains of both polygons along every line
//! through a hull edge that separates the hulls, with exact signs. The sweep may only answer when
//! one such line has both facing chains monotone, so it must decline when none has; and it must
//! answer when every such line has both chains monotone and so few facing vertices that its budget
//! cannot run out.

use glam::DVec2;
use polydist_oracle::{
    Contact, SplitMix64, boundary_distance, contact_status_convex, feature_sq_dist,
    hooked_teeth_facing, sawteeth_facing, star, stars_notch_facing_tip, zigzag_under_arc,
};
use polydist_polygon::SimplePolygon;
use polydist_polygon::predicates::{Exact, Fast, Kernel, Orientation, Robust, Sign};
use polydist_separation::{
    ClosestPair, HullRouteMethod, PolygonSeparation, Route, SeparationStats, intersection,
    polygon_separation_brute, separation, separation_of_disjoint, separation_of_disjoint_with,
};
use proptest::prelude::*;

mod common;
use common::pairs::{bbox, check_optimal, oracle_feature, place_beside};

// ------------------------------------------------------------------------------------------------
// Helpers.

fn ring_str(v: &[DVec2]) -> String {
    let pts: Vec<String> = v
        .iter()
        .map(|p| format!("({:?}, {:?})", p.x, p.y))
        .collect();
    format!("[{}]", pts.join(", "))
}

// ------------------------------------------------------------------------------------------------
// The independent facing-chain check.

/// The facing chain of the counter-clockwise ring `v` toward the side of the line `a → b` where the
/// other polygon lies (`other_left`: to the left), when it is monotone along the line: its number of
/// vertices; `None` when it is not monotone. The facing chain runs between the vertex of least `t`
/// and the vertex of greatest `t` (`t` the position along `a → b`, ties to the vertex nearest the
/// other side), along the boundary on the other polygon's side. Exact signs.
fn monotone_facing(v: &[DVec2], a: DVec2, b: DVec2, other_left: bool) -> Option<usize> {
    let n = v.len();
    // `y` is strictly nearer the other side than `x`.
    let nearer = |x: DVec2, y: DVec2| {
        let s = Exact::cross_sign(a, b, x, y);
        if other_left {
            s == Sign::Positive
        } else {
            s == Sign::Negative
        }
    };
    // sign(t(y) − t(x)).
    let dt = |x: DVec2, y: DVec2| Exact::dot_sign(x, y, a, b);
    let (mut lo, mut hi) = (0, 0);
    for k in 1..n {
        match dt(v[lo], v[k]) {
            Sign::Negative => lo = k,
            Sign::Zero if nearer(v[lo], v[k]) => lo = k,
            _ => {}
        }
        match dt(v[hi], v[k]) {
            Sign::Positive => hi = k,
            Sign::Zero if nearer(v[hi], v[k]) => hi = k,
            _ => {}
        }
    }
    if lo == hi {
        return None;
    }
    // The interior lies left of the direction of travel: with the other side to the left, the top
    // is walked counter-clockwise from the greatest `t` down to the least, otherwise from the least
    // up to the greatest.
    let (start, end, bad) = if other_left {
        (hi, lo, Sign::Positive)
    } else {
        (lo, hi, Sign::Negative)
    };
    let (mut i, mut len) = (start, 1);
    while i != end {
        let j = (i + 1) % n;
        if dt(v[i], v[j]) == bad {
            return None;
        }
        i = j;
        len += 1;
    }
    Some(len)
}

/// What the independent check says about two polygons with disjoint hulls, over the lines through a
/// hull edge with the other hull strictly beyond (the lines the disjoint-hull route chooses from).
#[derive(Clone, Copy, Debug, Default)]
struct Lines {
    /// How many such lines.
    lines: usize,
    /// How many of them have both facing chains monotone.
    monotone: usize,
    /// Every line has both facing chains monotone, and so few facing vertices that the sweep's
    /// scan cannot exceed its budget whichever line is chosen: the sweep must answer.
    must_sweep: bool,
}

fn sweepable_lines(sp: &SimplePolygon, sq: &SimplePolygon) -> Lines {
    let (hp, hq) = (sp.convex_hull(), sq.convex_hull());
    let mut out = Lines {
        must_sweep: true,
        ..Lines::default()
    };
    for (own, other, own_is_p) in [(&hp, &hq, true), (&hq, &hp, false)] {
        let h = own.vertices();
        for i in 0..h.len() {
            let (a, b) = (h[i], h[(i + 1) % h.len()]);
            if a == b
                || !other
                    .vertices()
                    .iter()
                    .all(|&y| Exact::orient(a, b, y) == Orientation::Clockwise)
            {
                continue;
            }
            out.lines += 1;
            // The own polygon is left of `a → b` (counter-clockwise hull), the other right.
            let chains = (
                monotone_facing(sp.vertices(), a, b, !own_is_p),
                monotone_facing(sq.vertices(), a, b, own_is_p),
            );
            if let (Some(fp), Some(fq)) = chains {
                out.monotone += 1;
                // The scan tries `2|F_P|` neighbours, then counts its windows before trying them:
                // at most `2|F_Q| + 1` per vertex of `F_P` and `2|F_P| + 1` per vertex of `F_Q`.
                out.must_sweep &= 3 * fp + fq + 4 * fp * fq <= 96 * (fp + fq) + 1024;
            } else {
                out.must_sweep = false;
            }
        }
    }
    out.must_sweep &= out.lines >= 1;
    out
}

fn hulls_disjoint(sp: &SimplePolygon, sq: &SimplePolygon) -> bool {
    contact_status_convex(sp.convex_hull().vertices(), sq.convex_hull().vertices())
        == Contact::Disjoint
}

// ------------------------------------------------------------------------------------------------
// One pair, every check.

/// The outcome of [`check_case`]: the route of `separation_of_disjoint`, the sweep's candidates,
/// whether the hulls are disjoint, and the independent check's `(lines, monotone lines)`.
#[derive(Clone, Copy, Debug)]
struct Outcome {
    route: Route,
    stats: SeparationStats,
    hulls_disjoint: bool,
    lines: Lines,
}

/// Checks one pair of disjoint polygons (caller rings `p`, `q`) under `K`: `separation_of_disjoint`
/// answers `Separated` with an exact optimum of the oracle on the caller rings; so do the `Section3`
/// method (which never sweeps, and otherwise takes the same route), `separation` and the brute
/// force. The sweep answers only with disjoint hulls and where a separating hull-edge line has both
/// facing chains monotone ([`sweepable_lines`]), so it declines where none has; its candidate count
/// is within its budget, and zero on every other route.
/// `None` when a ring is refused or the polygons meet.
fn check_case<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Result<Option<Outcome>, TestCaseError> {
    let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(p), SimplePolygon::try_new(q)) else {
        return Ok(None);
    };
    if intersection::<Robust>(&sp, &sq).is_some() {
        return Ok(None);
    }
    let ctx = || format!("p = {}\nq = {}", ring_str(p), ring_str(q));
    let exact = boundary_distance(p, q);
    let auto = separation_of_disjoint::<K>(&sp, &sq);
    let Ok(PolygonSeparation::Separated { pair, route, stats }) = auto else {
        return Err(TestCaseError::fail(format!(
            "separation_of_disjoint: {auto:?}\n{}",
            ctx()
        )));
    };
    check_optimal(&exact, &pair)
        .map_err(|e| TestCaseError::fail(format!("{e} (route {route:?}, {stats:?})\n{}", ctx())))?;
    let disjoint = hulls_disjoint(&sp, &sq);
    let lines = if disjoint {
        sweepable_lines(&sp, &sq)
    } else {
        Lines::default()
    };
    let n = sp.len() + sq.len();
    if route == Route::MonotoneSweep {
        prop_assert!(disjoint, "swept with meeting hulls\n{}", ctx());
        prop_assert!(
            lines.monotone >= 1,
            "swept though no separating line has monotone facing chains {lines:?}\n{}",
            ctx()
        );
        prop_assert!(
            stats.sweep_candidates >= 1 && stats.sweep_candidates <= 96 * n + 1024,
            "candidates {} for N = {n}",
            stats.sweep_candidates
        );
    } else if route == Route::EnvelopeSweep {
        // Section 3's envelope sweep: on the envelopes, at most the visible vertices' budget.
        prop_assert!(disjoint, "enveloped with meeting hulls\n{}", ctx());
        prop_assert!(
            stats.sweep_candidates >= 1 && stats.sweep_candidates <= 96 * n + 1024,
            "candidates {} for N = {n}",
            stats.sweep_candidates
        );
    } else {
        prop_assert_eq!(stats.sweep_candidates, 0);
    }
    if lines.must_sweep {
        prop_assert!(
            matches!(route, Route::MonotoneSweep | Route::HullFeatures),
            "the sweep declined though every separating line has monotone facing chains and the \
             budget cannot run out: {route:?} {lines:?}\n{}",
            ctx()
        );
    }
    if !disjoint {
        prop_assert_eq!(route, Route::Separators);
    }
    let s3 = separation_of_disjoint_with::<K>(&sp, &sq, HullRouteMethod::Section3);
    let Ok(PolygonSeparation::Separated {
        pair: pair3,
        route: route3,
        stats: stats3,
    }) = s3
    else {
        return Err(TestCaseError::fail(format!("section 3: {s3:?}\n{}", ctx())));
    };
    check_optimal(&exact, &pair3)
        .map_err(|e| TestCaseError::fail(format!("section 3: {e}\n{}", ctx())))?;
    prop_assert_eq!(stats3.sweep_candidates, 0);
    // Both methods share the hull step: the sweeps replace section 3's matrices and nothing else.
    let expected3 = match route {
        Route::MonotoneSweep | Route::EnvelopeSweep | Route::SeparableChains => {
            Route::SeparableChains
        }
        r => r,
    };
    prop_assert_eq!(route3, expected3);
    let Ok(PolygonSeparation::Separated { pair: full, .. }) = separation::<K>(&sp, &sq) else {
        return Err(TestCaseError::fail(format!(
            "separation refused\n{}",
            ctx()
        )));
    };
    check_optimal(&exact, &full)?;
    let Ok(PolygonSeparation::Separated { pair: brute, .. }) =
        polygon_separation_brute::<K>(&sp, &sq)
    else {
        return Err(TestCaseError::fail(format!(
            "brute force refused\n{}",
            ctx()
        )));
    };
    check_optimal(&exact, &brute)?;
    Ok(Some(Outcome {
        route,
        stats,
        hulls_disjoint: disjoint,
        lines,
    }))
}

// ------------------------------------------------------------------------------------------------
// Terrains.

#[derive(Clone, Copy, Debug, PartialEq)]
enum Grid {
    /// Integer coordinates.
    Integer,
    /// Integers scaled by `2^−sx` and `2^−sy` (exact).
    Dyadic(i32, i32),
    /// Random floats.
    Float,
}

impl Grid {
    fn unit(self) -> DVec2 {
        match self {
            Grid::Dyadic(sx, sy) => DVec2::new(2f64.powi(-sx), 2f64.powi(-sy)),
            Grid::Integer | Grid::Float => DVec2::ONE,
        }
    }
}

/// The top chain of a terrain, left to right, in lattice units (integers, or floats for
/// `Grid::Float`): `k` vertices, `x` non-decreasing (a zero step now and then, never two in a row nor
/// at either end: vertical edges; a long step now and then), heights in `[0, hmax]` with repeats (horizontal edges, collinear
/// runs).
fn terrain_top(rng: &mut SplitMix64, k: usize, float: bool) -> Vec<DVec2> {
    let hmax = 1 + rng.range_i64(0, 6);
    let tie = rng.below(3);
    let zero = rng.below(3);
    let (mut x, mut h) = (0.0, 0.0);
    let mut prev_zero = true;
    let mut top = Vec::with_capacity(k);
    for i in 0..k {
        if i > 0 {
            let zero_ok = !prev_zero && i + 1 < k;
            let dx = if zero_ok && rng.below(8) < zero {
                0.0
            } else if float {
                0.0625 + 3.0 * rng.unit_f64()
            } else {
                rng.range_i64(1, 4) as f64
            };
            // Now and then a long step: an edge spanning many windows.
            let dx = if rng.below(16) == 0 { 64.0 * dx } else { dx };
            prev_zero = dx == 0.0;
            x += dx;
        }
        if i == 0 || rng.below(3) >= tie {
            h = if float {
                hmax as f64 * rng.unit_f64()
            } else {
                rng.range_i64(0, hmax) as f64
            };
        }
        top.push(DVec2::new(x, h));
    }
    top
}

/// A terrain ring, counter-clockwise, in lattice units: the top chain of [`terrain_top`] closed by a
/// flat bottom or a random one, `depth` below the lowest top vertex.
fn terrain_ring(rng: &mut SplitMix64, k: usize, float: bool) -> Vec<DVec2> {
    let top = terrain_top(rng, k, float);
    let (x0, x1) = (top[0].x, top[k - 1].x);
    let hmin = top.iter().map(|v| v.y).fold(f64::INFINITY, f64::min);
    let depth = rng.range_i64(1, 12) as f64;
    let base = hmin - depth;
    let mut ring = vec![DVec2::new(x0, base)];
    if rng.coin() {
        // A random bottom: up to five vertices strictly between the walls, no higher than the
        // corners.
        let m = 1 + rng.index(5);
        let mut xs: Vec<f64> = (0..m)
            .map(|_| {
                if float {
                    x0 + (x1 - x0) * rng.unit_f64()
                } else {
                    x0 + rng.range_i64(0, (x1 - x0) as i64) as f64
                }
            })
            .filter(|&x| x > x0 && x < x1)
            .collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        for x in xs {
            let d = if float {
                depth * rng.unit_f64()
            } else {
                rng.range_i64(0, 2 * depth as i64) as f64
            };
            ring.push(DVec2::new(x, base - d));
        }
    }
    ring.push(DVec2::new(x1, base));
    ring.extend(top.iter().rev());
    ring
}

/// A generated pair with how it was made.
#[derive(Clone, Debug)]
struct Pair {
    p: Vec<DVec2>,
    q: Vec<DVec2>,
    what: String,
}

fn rot90(v: DVec2, k: u64, mirror: bool) -> DVec2 {
    let v = if mirror { DVec2::new(-v.x, v.y) } else { v };
    match k % 4 {
        0 => v,
        1 => DVec2::new(-v.y, v.x),
        2 => DVec2::new(-v.x, -v.y),
        _ => DVec2::new(v.y, -v.x),
    }
}

/// A terrain `P` and an upside-down terrain `Q` above it (its bottom chain facing `P`), `Q`'s lowest
/// point `gap` above `P`'s highest, so that a horizontal line separates the hulls; then an exact
/// lattice symmetry of both (a quarter turn, a mirror), a swap, sometimes a translation far from the
/// origin (exact on the dyadic grids), sometimes a rotation by a random angle (inexact).
fn terrain_pair(seed: u64) -> Pair {
    terrain_pair_sized(seed, 26)
}

/// [`terrain_pair`] with top chains of 3 to `kmax + 2` vertices.
fn terrain_pair_sized(seed: u64, kmax: usize) -> Pair {
    let mut rng = SplitMix64::new(seed);
    let grid = match rng.below(8) {
        0..=2 => Grid::Integer,
        3..=5 => Grid::Dyadic(rng.range_i64(-3, 6) as i32, rng.range_i64(-3, 6) as i32),
        _ => Grid::Float,
    };
    let float = grid == Grid::Float;
    let u = grid.unit();
    let kp = 3 + rng.index(kmax);
    let kq = 3 + rng.index(kmax);
    let kind = rng.below(9);
    let mut p: Vec<DVec2> = terrain_ring(&mut rng, kp, float)
        .into_iter()
        .map(|v| v * u)
        .collect();
    let mut t: Vec<DVec2> = terrain_ring(&mut rng, kq, float)
        .into_iter()
        .map(|v| v * u)
        .collect();
    if kind == 8 {
        // Far from the origin before the gap is chosen, so that it can be a few ulps there (the
        // dyadic grids stay exact: their spacing is at least `2^−6`, the ulp of `10^12` is `2^−13`).
        let o = DVec2::new(-3e12, 1e12);
        p.iter_mut().for_each(|z| *z += o);
        t.iter_mut().for_each(|z| *z += o);
    }
    let ((plo, phi), (tlo, thi)) = (bbox(&p), bbox(&t));
    let extent = (phi - plo).max(thi - tlo).max_element();
    let (gap_kind, gap) = match kind {
        0..=2 => ("lattice", rng.range_i64(1, 3) as f64 * u.y),
        3 => ("half-lattice", 0.5 * u.y),
        4 => ("ulps", rng.range_i64(1, 6) as f64 * extent * f64::EPSILON),
        5 => ("1e-9", extent * 1e-9),
        6 => ("large", rng.range_i64(1, 4) as f64 * extent),
        7 => ("huge", 1024.0 * extent),
        _ => (
            "far-ulps",
            rng.range_i64(1, 4) as f64 * (phi.y.next_up() - phi.y),
        ),
    };
    // `Q`'s lowest point is exactly `base`, strictly above `P`'s highest; the others round upward
    // from it (rounding is monotone), so the horizontal line through `P`'s top separates.
    let base = (phi.y + gap).max(phi.y.next_up());
    let slide = rng.range_i64(
        -((thi.x - tlo.x) / u.x) as i64,
        ((phi.x - plo.x) / u.x) as i64,
    ) as f64
        * u.x;
    let dx = plo.x - tlo.x + slide;
    let mut q: Vec<DVec2> = t
        .iter()
        .map(|v| DVec2::new(v.x + dx, (thi.y - v.y) + base))
        .collect();
    // The flip turned `Q` clockwise; give it counter-clockwise most of the time (the caller's
    // indices are mapped either way).
    if rng.below(4) != 0 {
        q.reverse();
    }
    let (mut p, mut q) = (p, q);
    let swap = rng.coin();
    if swap {
        std::mem::swap(&mut p, &mut q);
    }
    let (turn, mirror) = (rng.below(4), rng.coin());
    let sym = |v: &mut Vec<DVec2>| v.iter_mut().for_each(|z| *z = rot90(*z, turn, mirror));
    sym(&mut p);
    sym(&mut q);
    let mut what = format!(
        "seed {seed}: {grid:?} kp={kp} kq={kq} gap={gap_kind} ({gap:e}) swap={swap} turn={turn} mirror={mirror}"
    );
    if rng.below(6) == 0 {
        let ang = core::f64::consts::TAU * rng.unit_f64();
        let (s, c) = ang.sin_cos();
        let r = |v: &mut Vec<DVec2>| {
            v.iter_mut()
                .for_each(|z| *z = DVec2::new(c * z.x - s * z.y, s * z.x + c * z.y));
        };
        r(&mut p);
        r(&mut q);
        what += &format!(" angle={ang}");
    }
    if rng.below(4) == 0 {
        let o = DVec2::new(
            if rng.coin() { 1e12 } else { -1e12 },
            if rng.coin() { 1e12 } else { -2e12 },
        );
        p.iter_mut().for_each(|z| *z += o);
        q.iter_mut().for_each(|z| *z += o);
        what += &format!(" far={o}");
    }
    Pair { p, q, what }
}

fn check_terrain<K: Kernel>(seed: u64) -> Result<Option<Outcome>, TestCaseError> {
    let pair = terrain_pair(seed);
    check_case::<K>(&pair.p, &pair.q)
        .map_err(|e| TestCaseError::fail(format!("{}: {e}", pair.what)))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn terrains_robust(seed in any::<u64>()) {
        check_terrain::<Robust>(seed)?;
    }

    #[test]
    fn terrains_exact(seed in any::<u64>()) {
        check_terrain::<Exact>(seed)?;
    }
}

/// A fixed run of terrains: every check of [`check_case`], and the sweep answers a substantial
/// share of the pairs with disjoint hulls (so that the file keeps exercising it).
#[test]
fn terrains_deterministic_and_route_shares() {
    let (mut sweep, mut chains, mut hull, mut sep, mut skipped, mut disjoint) = (0, 0, 0, 0, 0, 0);
    let (mut forced_decline, mut declined_with_line, mut enveloped) = (0, 0, 0);
    let mut per_vertex = 0.0f64;
    for seed in 0..300 {
        let pair = terrain_pair(seed);
        let out = match check_case::<Robust>(&pair.p, &pair.q) {
            Ok(Some(o)) => o,
            Ok(None) => {
                skipped += 1;
                continue;
            }
            Err(e) => panic!("{}: {e}", pair.what),
        };
        if out.hulls_disjoint {
            disjoint += 1;
        }
        match out.route {
            Route::MonotoneSweep => {
                sweep += 1;
                let n = (pair.p.len() + pair.q.len()) as f64;
                per_vertex = per_vertex.max(out.stats.sweep_candidates as f64 / n);
            }
            Route::SeparableChains | Route::EnvelopeSweep => {
                chains += 1;
                enveloped += usize::from(out.route == Route::EnvelopeSweep);
                if out.lines.monotone == 0 {
                    forced_decline += 1;
                } else {
                    declined_with_line += 1;
                }
            }
            Route::HullFeatures => hull += 1,
            Route::Separators => sep += 1,
            r => panic!("{}: route {r:?}", pair.what),
        }
    }
    eprintln!(
        "terrains: disjoint hulls {disjoint}, sweep {sweep}, section 3 {chains} (no monotone line \
         {forced_decline}, declined with one {declined_with_line}; its envelope sweep answered \
         {enveloped}), hull features {hull}, separators {sep}, skipped {skipped}; max candidates \
         per vertex {per_vertex:.2}"
    );
    assert!(disjoint >= 250, "only {disjoint} pairs with disjoint hulls");
    assert!(
        5 * sweep >= 2 * disjoint,
        "the sweep answered {sweep} of {disjoint} disjoint-hull pairs"
    );
    assert!(chains >= 10, "section 3 answered only {chains}");
    assert!(
        2 * enveloped >= chains,
        "section 3's envelope sweep answered only {enveloped} of {chains}"
    );
}

/// Larger terrains (top chains of up to 122 vertices): longer windows, more candidates, the same
/// checks.
#[test]
fn larger_terrains() {
    let mut sweep = 0;
    for seed in 0..40 {
        let pair = terrain_pair_sized(seed ^ 0xb16, 120);
        match check_case::<Robust>(&pair.p, &pair.q) {
            Ok(Some(o)) if o.route == Route::MonotoneSweep => sweep += 1,
            Ok(_) => {}
            Err(e) => panic!("{}: {e}", pair.what),
        }
    }
    eprintln!("larger terrains: swept {sweep} of 40");
    assert!(sweep >= 10, "swept only {sweep} of 40");
}

// ------------------------------------------------------------------------------------------------
// Facing chains that are not monotone.

/// Two star polygons with disjoint hulls (bounding boxes a gap apart along an axis).
fn star_pair(seed: u64) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(seed ^ 0x57a2);
    let n = 5 + rng.index(30);
    let m = 5 + rng.index(30);
    let (sp, sq) = (1 + rng.index(n / 2), 1 + rng.index(m / 2));
    let p = star(&mut rng, n, sp);
    let q = star(&mut rng, m, sq);
    let (lo, hi) = bbox(&p);
    let extent = (hi - lo).max_element();
    let gap = match rng.below(3) {
        0 => 1.0,
        1 => extent * 0.125,
        _ => extent,
    };
    let slide = rng.range_i64(-4, 4) as f64 * 0.25;
    let q = place_beside(
        &p,
        &q,
        rng.index(2),
        if rng.coin() { 1.0 } else { -1.0 },
        gap,
        slide,
    );
    (p, q)
}

/// Star polygons: wherever no separating hull-edge line has monotone facing chains, the route is
/// section 3 or the hull features, never the sweep; every answer is optimal.
#[test]
fn stars_with_non_monotone_facing_chains_decline() {
    let (mut forced, mut sweep, mut total) = (0, 0, 0);
    for seed in 0..120 {
        let (p, q) = star_pair(seed);
        let out = check_case::<Robust>(&p, &q)
            .unwrap_or_else(|e| panic!("star seed {seed}: {e}"))
            .expect("stars are simple and apart");
        assert!(out.hulls_disjoint);
        total += 1;
        if out.lines.monotone == 0 {
            forced += 1;
            assert!(
                matches!(
                    out.route,
                    Route::SeparableChains | Route::EnvelopeSweep | Route::HullFeatures
                ),
                "star seed {seed}: {:?}",
                out.route
            );
        }
        if out.route == Route::MonotoneSweep {
            sweep += 1;
        }
    }
    eprintln!("stars: {total} pairs, no monotone line in {forced}, swept {sweep}");
    assert!(
        forced >= 30,
        "only {forced} star pairs without a monotone line"
    );
}

/// A terrain whose top chain holds an overhang (up, back left, up, forward right) between two
/// higher peaks at its ends, closed by a bottom with a bump (`Λ`), and an upside-down terrain `Q`
/// above it within the peaks' span. With `facing`, `Q` faces the top: `P`'s closest hull feature is
/// the lid between the peaks, every separating line is close to horizontal, and the facing chain
/// steps both ways along it. Without, `P` is turned upside down first (`y ↦ −y`), so that the
/// overhang points away from `Q` and the bump's two sides (a `V`, its corners joined by a lid) face
/// it: the facing chains are monotone along the lid's line.
fn overhang_pair(seed: u64, facing: bool) -> (Vec<DVec2>, Vec<DVec2>) {
    let mut rng = SplitMix64::new(seed ^ 0x0e7a);
    let k = 4 + rng.index(12);
    let mut mid = terrain_top(&mut rng, k, false);
    // The valley starts right of the left peak.
    for v in &mut mid {
        v.x += 2.0;
    }
    let mut at = 1 + rng.index(k - 2);
    if mid[at - 1].x == mid[at].x {
        // A vertical edge into `mid[at]` would fold back on the overhang's first edge (no two zero
        // steps in a row, and never the first: `at − 1 ≥ 1` then).
        at -= 1;
    }
    let hm = mid[..=at].iter().map(|v| v.y).fold(0.0, f64::max);
    let xm = mid[at].x;
    let d = (rng.range_i64(1, 3) as f64).min(xm - mid[0].x);
    let e = rng.range_i64(1, 3) as f64;
    // The overhang at `mid[at]`: the ledge lies above everything left of it (heights up to `hm`),
    // no further left than `mid[0]`; whatever follows is moved right beyond the ledge's end.
    let mut top = vec![DVec2::ZERO];
    top.extend_from_slice(&mid[..=at]);
    top.extend_from_slice(&[
        DVec2::new(xm, hm + 1.0),
        DVec2::new(xm - d, hm + 1.0),
        DVec2::new(xm - d, hm + 2.0),
        DVec2::new(xm + e, hm + 2.0),
    ]);
    top.extend(mid[at + 1..].iter().map(|v| DVec2::new(v.x + e + 1.0, v.y)));
    let peak = top.iter().map(|v| v.y).fold(0.0, f64::max) + 1.0 + rng.range_i64(0, 2) as f64;
    let right = top.last().unwrap().x + 2.0;
    top[0] = DVec2::new(0.0, peak);
    top.push(DVec2::new(right, peak));
    let mut p = vec![
        DVec2::new(0.0, -2.0),
        DVec2::new(right * 0.5, -1.0),
        DVec2::new(right, -2.0),
    ];
    p.extend(top.iter().rev());
    if !facing {
        p = p.iter().rev().map(|v| DVec2::new(v.x, -v.y)).collect();
    }
    let ptop = bbox(&p).1.y;
    // `Q`: an upside-down terrain inside `[1, right − 1]` (scaled by a power of two to fit: exact),
    // `gap` above `P`.
    let kq = 3 + rng.index(8);
    let t = terrain_ring(&mut rng, kq, false);
    let (tlo, thi) = bbox(&t);
    let mut scale = 1.0;
    while (thi.x - tlo.x) * scale > right - 2.0 {
        scale *= 0.5;
    }
    let gap = rng.range_i64(1, 4) as f64 * 0.5;
    let mut q: Vec<DVec2> = t
        .iter()
        .map(|v| DVec2::new(1.0 + (v.x - tlo.x) * scale, ptop + gap + (thi.y - v.y)))
        .collect();
    q.reverse();
    let (turn, mirror) = (rng.below(4), rng.coin());
    let sym = |v: &[DVec2]| {
        v.iter()
            .map(|&z| rot90(z, turn, mirror))
            .collect::<Vec<_>>()
    };
    let (p, q) = (sym(&p), sym(&q));
    if rng.coin() { (p, q) } else { (q, p) }
}

/// The overhang on the facing side: no separating line has monotone facing chains, and section 3
/// answers, optimally.
#[test]
fn overhang_on_the_facing_side_declines() {
    for seed in 0..60 {
        let (p, q) = overhang_pair(seed, true);
        let out = check_case::<Robust>(&p, &q)
            .unwrap_or_else(|e| panic!("overhang seed {seed}: {e}"))
            .unwrap_or_else(|| panic!("overhang seed {seed} refused: {p:?} {q:?}"));
        assert!(out.hulls_disjoint);
        assert!(out.lines.lines >= 1);
        assert_eq!(out.lines.monotone, 0, "seed {seed}: {:?}", out.lines);
        // The monotone sweep declines; section 3's envelopes are monotone, and its sweep answers.
        assert_eq!(out.route, Route::EnvelopeSweep, "overhang seed {seed}");
        if seed % 4 == 0 {
            check_case::<Exact>(&p, &q).unwrap();
        }
    }
}

/// The same overhang on the far side (`P` upside down, the overhang pointing away from `Q`) leaves
/// `P`'s facing chain monotone along its lid: the sweep answers (optimally) unless the line chosen
/// runs through a hull edge of `Q`, along which `Q`'s facing chain may fold (`check_case` requires
/// the sweep wherever every separating line is monotone).
#[test]
fn overhang_on_the_back_side_is_swept() {
    let mut swept = 0;
    for seed in 0..60 {
        let (p, q) = overhang_pair(seed, false);
        let out = check_case::<Robust>(&p, &q)
            .unwrap_or_else(|e| panic!("back overhang seed {seed}: {e}"))
            .unwrap_or_else(|| panic!("back overhang seed {seed} refused: {p:?} {q:?}"));
        assert!(out.hulls_disjoint);
        assert!(out.lines.monotone >= 1, "seed {seed}: {:?}", out.lines);
        if out.route == Route::MonotoneSweep {
            swept += 1;
        }
    }
    eprintln!("back-side overhangs: swept {swept} of 60");
    assert!(swept >= 54, "swept only {swept} of 60");
}

// ------------------------------------------------------------------------------------------------
// The budget.

/// Two dense zigzags facing each other across a gap far wider than their spacing: `n` teeth of
/// width `2^−10` and amplitude `2^−13` each, `Q` one unit above `P` and within its span. The chains
/// are monotone along the horizontal line, but every window holds about two thousand candidates.
fn zigzags(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let s = 2f64.powi(-10);
    let amp = 2f64.powi(-13);
    let width = n as f64 * s;
    let mut p = vec![DVec2::new(0.0, -1.0), DVec2::new(width, -1.0)];
    p.extend(
        (0..=n)
            .rev()
            .map(|i| DVec2::new(i as f64 * s, (i % 2) as f64 * amp)),
    );
    // `Q` covers the middle half of `P`'s span, shifted by a quarter tooth; its lowest vertices are
    // one unit above `P`'s highest.
    let (a, b) = (n / 4, 3 * n / 4);
    let mut q: Vec<DVec2> = (a..=b)
        .map(|i| DVec2::new((i as f64 + 0.25) * s, 1.0 + amp + (i % 2) as f64 * amp))
        .collect();
    q.push(DVec2::new((b as f64 + 0.25) * s, 3.0));
    q.push(DVec2::new((a as f64 + 0.25) * s, 3.0));
    (p, q)
}

/// A tiny zigzag cluster of `n` vertices (`2^−30` apart) at the origin, on top of a triangle, and
/// an arc of `n` vertices of radius 1 around it (from 120° to 60°), the bottom of a cap: every arc
/// vertex is within about `10^−8` of the clearance from every cluster vertex, so no depth or block
/// test can thin the windows, which hold the whole arc.
fn cluster_and_arc(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    zigzag_under_arc(n, 2f64.powi(-30))
}

/// σ by the route and by the brute force: the same exact distance of their features.
fn agrees_with_brute(p: &[DVec2], q: &[DVec2]) -> (Route, SeparationStats) {
    let (sp, sq) = (
        SimplePolygon::try_new(p).unwrap(),
        SimplePolygon::try_new(q).unwrap(),
    );
    assert!(hulls_disjoint(&sp, &sq));
    let lines = sweepable_lines(&sp, &sq);
    assert!(
        lines.lines >= 1 && lines.monotone == lines.lines,
        "the facing chains are monotone: {lines:?}"
    );
    let Ok(PolygonSeparation::Separated { pair, route, stats }) =
        separation_of_disjoint::<Robust>(&sp, &sq)
    else {
        panic!("disjoint")
    };
    let Ok(PolygonSeparation::Separated { pair: brute, .. }) =
        polygon_separation_brute::<Robust>(&sp, &sq)
    else {
        panic!("disjoint")
    };
    let sq_of = |c: &ClosestPair| {
        feature_sq_dist(
            p,
            q,
            oracle_feature(c.feature_p),
            oracle_feature(c.feature_q),
        )
        .expect("features in range")
    };
    assert_eq!(sq_of(&pair), sq_of(&brute), "{pair:?} vs {brute:?}");
    assert!((pair.distance - brute.distance).abs() <= 4.0 * f64::EPSILON * brute.distance);
    (route, stats)
}

/// Crowded windows: the sweep gives up within its budget and section 3 answers; the answer's
/// features realize the brute force's exact distance. Windows crowded along the line only (dense
/// zigzags one unit apart, about two thousand candidates a window) are thinned by the depth and
/// block tests and swept with a few candidates a vertex.
#[test]
fn crowded_windows_exhaust_the_budget() {
    let (p, q) = cluster_and_arc(200);
    let (route, stats) = agrees_with_brute(&p, &q);
    assert_eq!(route, Route::SeparableChains);
    assert_eq!(stats.sweep_candidates, 0);
    let (p, q) = zigzags(1600);
    let (far_route, far_stats) = agrees_with_brute(&p, &q);
    let n = (p.len() + q.len()) as f64;
    eprintln!(
        "cluster and arc -> {route:?}; zigzags one unit apart -> {far_route:?} with {} candidates \
         ({:.2} per vertex)",
        far_stats.sweep_candidates,
        far_stats.sweep_candidates as f64 / n
    );
    assert_eq!(far_route, Route::MonotoneSweep);
    assert!(
        far_stats.sweep_candidates as f64 <= 8.0 * n,
        "{} candidates for {n} vertices",
        far_stats.sweep_candidates
    );
    // The same zigzags a thousandth of the gap apart: the sweep answers.
    let (p2, mut q2) = zigzags(1600);
    for v in &mut q2 {
        v.y -= 1.0 - 2f64.powi(-12);
    }
    let (sp2, sq2) = (
        SimplePolygon::try_new(&p2).unwrap(),
        SimplePolygon::try_new(&q2).unwrap(),
    );
    let Ok(PolygonSeparation::Separated {
        pair: near,
        route: near_route,
        stats: near_stats,
    }) = separation_of_disjoint::<Robust>(&sp2, &sq2)
    else {
        panic!("disjoint")
    };
    let n2 = p2.len() + q2.len();
    eprintln!(
        "zigzags close -> {near_route:?} with {} candidates ({:.2} per vertex)",
        near_stats.sweep_candidates,
        near_stats.sweep_candidates as f64 / n2 as f64
    );
    assert_eq!(near_route, Route::MonotoneSweep);
    agrees_with_section3(&p2, &q2, &near);
}

/// Windows wider than the chains, thinned by depth alone (the vertices, and the other chain's
/// coarse blocks, whose depths are farther than the best from all of the other chain's are left
/// out of the count): a zigzag 0.6 wide facing the arc around it (clearance 0.89, the zigzag's
/// ends to the arc's, more than either chain's extent along the line) is swept, and so are two
/// stars a unit apart with a notch facing a tip (the envelope sweep: the envelopes' windows hold
/// the whole facing sides). Both used to exhaust the budget at these sizes and go to section 3's
/// matrices; both are as near as those, with a few candidates a vertex.
#[test]
fn depth_thins_windows_wider_than_the_chains() {
    let (p, q) = zigzag_under_arc(16_384, 0.6 / 16_384.0);
    let (sp, sq) = (
        SimplePolygon::try_new(&p).unwrap(),
        SimplePolygon::try_new(&q).unwrap(),
    );
    let (a, b) = stars_notch_facing_tip(16_384);
    let (sa, sb) = (
        SimplePolygon::try_new(&a).unwrap(),
        SimplePolygon::try_new(&b).unwrap(),
    );
    for ((p, q), (sp, sq), wanted) in [
        ((&p, &q), (&sp, &sq), Route::MonotoneSweep),
        ((&a, &b), (&sa, &sb), Route::EnvelopeSweep),
    ] {
        let Ok(PolygonSeparation::Separated { pair, route, stats }) =
            separation_of_disjoint::<Robust>(sp, sq)
        else {
            panic!("disjoint")
        };
        let n = p.len() + q.len();
        eprintln!(
            "{wanted:?}: {} candidates for {n} vertices, σ = {}",
            stats.sweep_candidates, pair.distance
        );
        assert_eq!(route, wanted);
        assert!(
            stats.sweep_candidates <= 4 * n,
            "{}",
            stats.sweep_candidates
        );
        agrees_with_section3(p, q, &pair);
    }
}

/// The pair `pair` found for `p` and `q` is as near as section 3's (exact squared distances of
/// their features).
fn agrees_with_section3(p: &[DVec2], q: &[DVec2], pair: &ClosestPair) {
    let (sp, sq) = (
        SimplePolygon::try_new(p).unwrap(),
        SimplePolygon::try_new(q).unwrap(),
    );
    let Ok(PolygonSeparation::Separated {
        pair: s3, route, ..
    }) = separation_of_disjoint_with::<Robust>(&sp, &sq, HullRouteMethod::Section3)
    else {
        panic!("disjoint")
    };
    assert_ne!(route, Route::MonotoneSweep);
    let sq_of = |c: &ClosestPair| {
        feature_sq_dist(
            p,
            q,
            oracle_feature(c.feature_p),
            oracle_feature(c.feature_q),
        )
        .expect("features in range")
    };
    assert_eq!(sq_of(pair), sq_of(&s3), "{pair:?} vs {s3:?}");
}

// ------------------------------------------------------------------------------------------------
// Linearity by counting.

/// The sweep answers the saw-teeth with a bounded number of candidates per vertex, not growing with
/// the number of teeth; its distance is the oracle's (small sizes) and section 3's (all sizes).
#[test]
fn sawteeth_candidates_per_vertex_stay_bounded() {
    candidates_per_vertex_stay_bounded("sawteeth", sawteeth_facing, Route::MonotoneSweep);
}

/// Hooked saw-teeth (no facing chain monotone): section 3's envelope sweep answers with a bounded
/// number of candidates per vertex, not growing with the number of teeth, and its distance is the
/// oracle's (small sizes) and that of section 3's matrices (all sizes).
#[test]
fn hooked_teeth_envelope_candidates_per_vertex_stay_bounded() {
    candidates_per_vertex_stay_bounded("hooked teeth", hooked_teeth_facing, Route::EnvelopeSweep);
}

/// The slabs `make(t)` for 16 to 4,096 teeth: answered by `route` with at most 6 candidates per
/// vertex, growing by at most 10% from 64 teeth on, as near as section 3's matrices (exactly the
/// oracle's optimum up to 64 teeth).
fn candidates_per_vertex_stay_bounded(
    name: &str,
    make: fn(usize) -> (Vec<DVec2>, Vec<DVec2>),
    route_wanted: Route,
) {
    let mut ratios = Vec::new();
    for t in [16usize, 64, 256, 1024, 4096] {
        let (p, q) = make(t);
        let (sp, sq) = (
            SimplePolygon::try_new(&p).unwrap(),
            SimplePolygon::try_new(&q).unwrap(),
        );
        let Ok(PolygonSeparation::Separated { pair, route, stats }) =
            separation_of_disjoint::<Robust>(&sp, &sq)
        else {
            panic!("disjoint")
        };
        assert_eq!(route, route_wanted, "{name} t = {t}");
        let n = p.len() + q.len();
        let ratio = stats.sweep_candidates as f64 / n as f64;
        eprintln!(
            "{name} t={t}: N={n}, candidates {} ({ratio:.3} per vertex)",
            stats.sweep_candidates
        );
        ratios.push((t, ratio));
        assert!(
            ratio <= 6.0,
            "{name} t = {t}: {ratio} candidates per vertex"
        );
        let Ok(PolygonSeparation::Separated {
            pair: s3,
            route: r3,
            ..
        }) = separation_of_disjoint_with::<Robust>(&sp, &sq, HullRouteMethod::Section3)
        else {
            panic!("disjoint")
        };
        assert_eq!(r3, Route::SeparableChains);
        assert!(
            (pair.distance - s3.distance).abs() <= 4.0 * f64::EPSILON * s3.distance,
            "{name} t = {t}: sweep {} vs section 3 {}",
            pair.distance,
            s3.distance
        );
        if t <= 64 {
            let exact = boundary_distance(&p, &q);
            check_optimal(&exact, &pair).unwrap();
            check_optimal(&exact, &s3).unwrap();
        }
    }
    let at64 = ratios.iter().find(|r| r.0 == 64).unwrap().1;
    let last = ratios.last().unwrap().1;
    assert!(
        last <= 1.1 * at64,
        "{name}: candidates per vertex grow: {ratios:?}"
    );
}

/// Two wavy walls one unit and a half apart (amplitude a quarter, a common period, a phase apart),
/// sampled `n` times over 32 units: from 16 to 512 vertices within the clearance along the line,
/// so the windows along it are crowded, but the walls' depths rule out all but a few candidates.
fn wavy_walls(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let w = 32.0;
    let x = |i: usize| w * i as f64 / n as f64;
    let wave = |x: f64, phase: f64| 0.25 * (x * 0.8 + phase).sin();
    let mut p = vec![DVec2::new(0.0, -2.0), DVec2::new(w, -2.0)];
    p.extend((0..=n).rev().map(|i| DVec2::new(x(i), wave(x(i), 0.0))));
    let mut q: Vec<DVec2> = (0..=n)
        .map(|i| DVec2::new(x(i), 1.5 + wave(x(i), 0.9)))
        .collect();
    q.push(DVec2::new(w, 4.5));
    q.push(DVec2::new(0.0, 4.5));
    (p, q)
}

/// Walls sampled far more finely than their clearance: the sweep answers them (not section 3),
/// with a bounded number of candidates a vertex that does not grow with the sampling, though the
/// windows along the line grow to hundreds of vertices; its distance is section 3's (all sizes)
/// and the oracle's (small sizes).
#[test]
fn corridor_candidates_per_vertex_stay_bounded() {
    let mut ratios = Vec::new();
    for n in [512usize, 2048, 8192, 16384] {
        let (p, q) = wavy_walls(n);
        let (sp, sq) = (
            SimplePolygon::try_new(&p).unwrap(),
            SimplePolygon::try_new(&q).unwrap(),
        );
        assert!(hulls_disjoint(&sp, &sq));
        let Ok(PolygonSeparation::Separated { pair, route, stats }) =
            separation_of_disjoint::<Robust>(&sp, &sq)
        else {
            panic!("disjoint")
        };
        assert_eq!(route, Route::MonotoneSweep, "n = {n}");
        let total = (p.len() + q.len()) as f64;
        let ratio = stats.sweep_candidates as f64 / total;
        eprintln!(
            "wavy walls n={n}: {} candidates ({ratio:.3} per vertex)",
            stats.sweep_candidates
        );
        assert!(ratio <= 8.0, "n = {n}: {ratio} candidates per vertex");
        ratios.push(ratio);
        agrees_with_section3(&p, &q, &pair);
        if n <= 512 {
            check_optimal(&boundary_distance(&p, &q), &pair).unwrap();
        }
    }
    assert!(
        ratios.last().unwrap() <= &(1.5 * ratios[1]),
        "candidates per vertex grow: {ratios:?}"
    );
}

// ------------------------------------------------------------------------------------------------
// The Fast kernel.

/// Under `Fast` the generators' pairs are answered without panicking (any result).
#[test]
fn fast_kernel_never_panics() {
    for seed in 0..150 {
        let pair = terrain_pair(seed);
        let (Ok(sp), Ok(sq)) = (
            SimplePolygon::try_new(&pair.p),
            SimplePolygon::try_new(&pair.q),
        ) else {
            continue;
        };
        let _ = separation_of_disjoint::<Fast>(&sp, &sq);
        let _ = separation_of_disjoint_with::<Fast>(&sp, &sq, HullRouteMethod::Section3);
        let _ = separation::<Fast>(&sp, &sq);
    }
    for seed in 0..40 {
        for (p, q) in [
            star_pair(seed),
            overhang_pair(seed, true),
            overhang_pair(seed, false),
        ] {
            let (sp, sq) = (
                SimplePolygon::try_new(&p).unwrap(),
                SimplePolygon::try_new(&q).unwrap(),
            );
            let _ = separation_of_disjoint::<Fast>(&sp, &sq);
            let _ = separation::<Fast>(&sp, &sq);
        }
    }
    let (p, q) = sawteeth_facing(256);
    let (sp, sq) = (
        SimplePolygon::try_new(&p).unwrap(),
        SimplePolygon::try_new(&q).unwrap(),
    );
    let _ = separation_of_disjoint::<Fast>(&sp, &sq);
}
