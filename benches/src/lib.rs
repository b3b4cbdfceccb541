//! Benchmarks live in benches/benches. This library holds the input families that more than one
//! target uses: the separation benchmarks (`benches/separation_polygons.rs`) and the profiling example
//! (`examples/separation_profile.rs`), so that a profile is taken on exactly the benchmarked input.

use std::f64::consts::TAU;

use glam::DVec2;
use polydist_oracle::SplitMix64;

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

/// A slab `[0, 4] × [0, h]` with `t` saw teeth on its right side (tips at `x = 5`), and its mirror
/// image right of it, shifted by half a tooth so that tips face notches, `1/4` beyond the tips.
pub fn sawteeth(n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    polydist_oracle::sawteeth_facing((n / 4).max(1))
}
