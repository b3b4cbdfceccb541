//! Benchmarks live in benches/benches. This library holds the input families that more than one
//! target uses: the separation benchmarks (`benches/separation_polygons.rs`) and the profiling example
//! (`examples/separation_profile.rs`), so that a profile is taken on exactly the benchmarked input.

use std::f64::consts::TAU;

use glam::DVec2;
use polydist_oracle::{Contact, SplitMix64, contact_status_convex, star_in_range};
use polydist_polygon::SimplePolygon;
use polydist_polygon::predicates::Robust;
use polydist_separation::intersection;

/// Two combs with interleaved teeth (`polydist_oracle::interleaved_combs`), clearance 1/8.
pub fn interlocked_combs(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let pair = polydist_oracle::interleaved_combs((n / 8).max(1), 5, 0.125);
    (pair.a, pair.b)
}

/// [`interlocked_combs`] with every vertex moved by a random multiple of `2^−12` below `1/64` in
/// each coordinate: still simple and disjoint (edges are at least 1 long, clearances stay above
/// 1/8 − 1/32), but no two clearances tie.
pub fn interlocked_combs_jittered(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let (a, b) = interlocked_combs(n);
    let mut rng = SplitMix64::new(0x1177 ^ n as u64);
    let mut jitter = |v: &[DVec2]| -> Vec<DVec2> {
        v.iter()
            .map(|&x| {
                let d = DVec2::new(rng.range_i64(-63, 64) as f64, rng.range_i64(-63, 64) as f64);
                x + d * 2f64.powi(-12)
            })
            .collect()
    };
    (jitter(&a), jitter(&b))
}

/// Two interleaved spiral arms, `n` vertices in all: arm `A` is a strip of half-width 1/4 around
/// the spiral `r = θ/π`, `θ` from `π` over up to six turns (fewer at small `n`, so that every turn
/// keeps at least 24 vertices a side), and arm `B` is `A` turned by half a turn, so the arms nest one
/// unit apart radially (clearance 1/2) and each lies in the other's hull: an interlocked pair whose
/// region between the facing chains is a long spiral corridor.
pub fn interlocked_spirals(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let m = (n / 4).max(8);
    let turns = (m as f64 / 24.0).clamp(0.75, 6.0);
    let (t0, t1) = (
        std::f64::consts::PI,
        std::f64::consts::PI * (1.0 + 2.0 * turns),
    );
    let at = |t: f64, w: f64| DVec2::new(t.cos(), t.sin()) * (t / std::f64::consts::PI + w);
    let theta = |k: usize| t0 + (t1 - t0) * k as f64 / (m - 1) as f64;
    let mut a: Vec<DVec2> = (0..m).map(|k| at(theta(k), 0.25)).collect();
    a.extend((0..m).rev().map(|k| at(theta(k), -0.25)));
    let b = a.iter().map(|&v| -v).collect();
    (a, b)
}

/// Two random stars (`polydist_oracle::star`: integer directions, every fourth vertex a spike 8 to
/// 64 times farther out), `n/2` vertices each, the second moved until the two are disjoint while
/// their hulls meet: spikes in each other's notches. The lines of their separators pass through
/// many spikes, so some subproblems cross their line too often for pairs of runs and go to section 3
/// on clipped chains (Step G, `docs/algorithms/separator.md`). The first seed and placement (32 a
/// seed: a random direction, the centres 30 to 90 % of the sum of the radii apart) that interlocks.
/// Up to 131,072 vertices the directions come from `[−2^16, 2^16]²` (`star`); beyond, two random
/// directions of one angle (which fail a draw) become likely there, so the range grows with `n`
/// (`star_in_range`, one bit per doubling and two to spare): the same shape, other draws.
pub fn interlocked_stars(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let half = (n / 2).max(8);
    let bits = if half <= 1 << 16 {
        16
    } else {
        18 + (half - 1).ilog2() - 15
    };
    let radius = |v: &[DVec2]| v.iter().map(|x| x.length()).fold(0.0, f64::max);
    (0u64..)
        .find_map(|seed| {
            let mut rng = SplitMix64::new(seed);
            let p = star_in_range(&mut rng, half, half / 4, bits);
            let q = star_in_range(&mut rng, half, half / 4, bits);
            let sp = SimplePolygon::try_new(&p).ok()?;
            (0..32).find_map(|_| {
                let t = 0.3 + 0.6 * rng.unit_f64();
                let a = TAU * rng.unit_f64();
                let d = DVec2::new(a.cos(), a.sin()) * (radius(&p) + radius(&q)) * t;
                let q: Vec<DVec2> = q.iter().map(|&v| v + d).collect();
                let sq = SimplePolygon::try_new(&q).ok()?;
                let hulls = [sp.convex_hull(), sq.convex_hull()];
                let meet = contact_status_convex(hulls[0].vertices(), hulls[1].vertices())
                    != Contact::Disjoint;
                (meet && intersection::<Robust>(&sp, &sq).is_none()).then(|| (p.clone(), q))
            })
        })
        .expect("some placement interlocks")
}

/// A spiky star in the pocket of a "C" (see the module docs), `n` vertices in all.
pub fn pocket(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let half = (n / 2).max(8);
    let (n_out, n_in) = (half / 4, half - half / 4);
    let gap = 0.5;
    let at = |a: f64, r: f64| DVec2::new(a.cos(), a.sin()) * r;
    let span = TAU - gap;
    let mut c: Vec<DVec2> = (0..n_out)
        .map(|k| at(gap / 2.0 + span * k as f64 / (n_out - 1) as f64, 4.0))
        .collect();
    c.extend((0..n_in).map(|k| {
        let r = if k % 2 == 0 { 2.0 } else { 2.5 };
        at(
            gap / 2.0 + span * (n_in - 1 - k) as f64 / (n_in - 1) as f64,
            r,
        )
    }));
    let star: Vec<DVec2> = (0..half)
        .map(|k| {
            at(
                TAU * k as f64 / half as f64,
                if k % 2 == 0 { 1.0 } else { 0.5 },
            )
        })
        .collect();
    (star, c)
}

/// Two hooked saw-tooth slabs facing each other (`polydist_oracle::hooked_teeth_facing`, `N/6`
/// teeth each): disjoint hulls whose facing chains are not monotone along the separating line, so
/// the disjoint-hull route goes to section 3.
pub fn hooked_teeth(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    polydist_oracle::hooked_teeth_facing((n / 6).max(1))
}

/// A slab `[0, 4] × [0, h]` with `t` saw teeth on its right side (tips at `x = 5`), and its mirror
/// image right of it, shifted by half a tooth so that tips face notches, `1/4` beyond the tips.
pub fn sawteeth(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    polydist_oracle::sawteeth_facing((n / 4).max(1))
}

/// [`polydist_oracle::stars_notch_facing_tip`] with about `n/2` vertices a star (rounded up to
/// even), one unit apart, a notch facing a tip. Wider than the gap: every window along the
/// separating line holds the whole facing side.
pub fn stars_lid(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    polydist_oracle::stars_notch_facing_tip(((n / 2).max(8) + 1) & !1)
}

/// [`polydist_oracle::zigzag_under_arc`] with `n/2` vertices a chain, `width` wide: a zigzag
/// along `y = 0` (on top of a triangle below it) facing an arc of radius 1 around the origin, from
/// 120° to 60° (the bottom of a cap).
pub fn zigzag_under_arc(n: usize, width: f64) -> (Vec<DVec2>, Vec<DVec2>) {
    let h = (n / 2).max(8);
    polydist_oracle::zigzag_under_arc(h, width / h as f64)
}

/// [`zigzag_under_arc`] 0.6 wide: the clearance (the zigzag's ends to the arc's, 0.89) exceeds
/// both chains' extents along the line, so the windows hold everything and only depth thins them.
pub fn bowl(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    zigzag_under_arc(n, 0.6)
}

/// [`zigzag_under_arc`] `2⁻³⁰` per vertex wide (`n = 131,072`: `6·10⁻⁵`): every arc vertex is
/// within a hair of the clearance from every zigzag vertex. No box of keys, and no bounding box,
/// rules out anything.
pub fn cluster(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    zigzag_under_arc(n, 2f64.powi(-30) * (n / 2).max(8) as f64)
}
