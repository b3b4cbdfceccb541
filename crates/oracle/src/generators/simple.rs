//! Simple (non-convex) polygon generators.

use core::f64::consts::TAU;

use glam::DVec2;

use super::lattice::{L, W, angle_cmp, cross_l, lattice_convex_xy, to_world};
use super::rng::SplitMix64;
use crate::exact::rat_finite;
use crate::rounding::ldexp;

/// Attempts before a randomized construction gives up.
const MAX_ATTEMPTS: usize = 10_000;

/// A random star-shaped simple ccw polygon with exactly `n >= 3` vertices,
/// `spikes` of which (evenly spaced indices) reach 8–32 times further out
/// than the others, giving deep reflex notches.
///
/// Construction: `n` random integer directions sorted by angle, with every
/// cyclic angular gap in `(0, π)` (checked exactly); vertex `i` is
/// `λᵢ · uᵢ` with integer `λᵢ`. The fan triangles `(0, vᵢ, vᵢ₊₁)` are then
/// nondegenerate, ccw and wind once around the origin, which lies in the open
/// kernel: the polygon is simple by construction. Consecutive vertices may be
/// collinear. Integer coordinates up to `2^24` scaled by `2^−24`, exact.
///
/// # Panics
/// Panics if `n < 3` or `spikes > n`.
pub fn star(rng: &mut SplitMix64, n: usize, spikes: usize) -> Vec<DVec2> {
    star_in_range(rng, n, spikes, 16)
}

/// [`star`] with directions drawn from `[−2^bits, 2^bits]²` instead of `bits = 16` (which
/// [`star`] uses, draw for draw), and the result scaled by `2^−(bits + 8)`, so the star keeps the
/// same size. Two random directions of the same angle make a draw fail, and with `n` directions
/// about `n² / 2^(2·bits)` pairs do: beyond some 100,000 vertices `bits = 16` fails nearly every
/// draw, and a wider range keeps large stars cheap to generate.
///
/// # Panics
/// Panics if `n < 3`, `spikes > n`, or `bits` is not in `1..=40`.
pub fn star_in_range(rng: &mut SplitMix64, n: usize, spikes: usize, bits: u32) -> Vec<DVec2> {
    assert!(n >= 3, "star: n >= 3");
    assert!(spikes <= n, "star: spikes <= n");
    assert!((1..=40).contains(&bits), "star: bits in 1..=40");
    let r: i64 = 1 << bits;
    for _ in 0..MAX_ATTEMPTS {
        let mut dirs: Vec<L> = (0..n)
            .map(|_| (rng.range_i64(-r, r), rng.range_i64(-r, r)))
            .collect();
        if dirs.contains(&(0, 0)) {
            continue;
        }
        dirs.sort_by(angle_cmp);
        if (0..n).any(|i| cross_l(dirs[i], dirs[(i + 1) % n]) <= 0) {
            continue;
        }
        let spike_at = |i: usize| spikes > 0 && (i * spikes) % n < spikes;
        let pts: Vec<W> = dirs
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| {
                let lam = if spike_at(i) {
                    rng.range_i64(128, 256)
                } else {
                    rng.range_i64(4, 16)
                };
                (i128::from(x * lam), i128::from(y * lam))
            })
            .collect();
        let mut pts = pts;
        let k = rng.index(n);
        pts.rotate_left(k);
        return to_world(&pts, -(bits as i32) - 8);
    }
    panic!("star: failed to draw directions");
}

/// A comb: a spine `[0, W] × [−1, 0]` with `n_teeth` teeth of width 1 and
/// height `tooth_len` standing on it, separated by gaps of width `space`
/// (`W = n_teeth + (n_teeth − 1)·space`). Simple, ccw, `4 n_teeth`
/// vertices, integer coordinates (exact).
///
/// # Panics
/// Panics if `n_teeth`, `tooth_len` or `space` is 0.
pub fn comb(n_teeth: usize, tooth_len: u32, space: u32) -> Vec<DVec2> {
    assert!(
        n_teeth >= 1 && tooth_len >= 1 && space >= 1,
        "comb: positive sizes"
    );
    let pitch = 1.0 + f64::from(space);
    let len = f64::from(tooth_len);
    let xl = |i: usize| i as f64 * pitch;
    let xr = |i: usize| i as f64 * pitch + 1.0;
    let mut v = vec![DVec2::new(0.0, -1.0), DVec2::new(xr(n_teeth - 1), -1.0)];
    for i in (0..n_teeth).rev() {
        if i != n_teeth - 1 {
            v.push(DVec2::new(xr(i), 0.0));
        }
        v.push(DVec2::new(xr(i), len));
        v.push(DVec2::new(xl(i), len));
        if i != 0 {
            v.push(DVec2::new(xl(i), 0.0));
        }
    }
    v
}

/// Two interlocking combs; see [`interleaved_combs`].
#[derive(Clone, Debug, PartialEq)]
pub struct CombPair {
    /// Lower comb, teeth up: [`comb`]`(n_teeth + 1, tooth_len, 1)`.
    pub a: Vec<DVec2>,
    /// Upper comb, `n_teeth` teeth pointing down into the gaps of `a`.
    pub b: Vec<DVec2>,
    /// The exact clearance: distance between the combs (0 = touching).
    pub gap: f64,
    /// The grid step `u` all coordinates are multiples of; `gap` is a
    /// multiple of it.
    pub unit: f64,
}

/// Grid step for coordinates of magnitude at most `m`: `u = 2^(e−52)` with
/// `2^e >= m + 1`, so every multiple of `u` below `2^(e+1)` is exact.
fn unit_for(m: f64) -> f64 {
    let mut e = 0i32;
    while ldexp(1.0, e) < m + 1.0 {
        e += 1;
    }
    ldexp(1.0, e - 52)
}

fn combs_with(n_teeth: usize, tooth_len: u32, g: f64, u: f64) -> CombPair {
    assert!(
        (0.0..0.25).contains(&g),
        "interleaved_combs: gap must be below 0.25"
    );
    let a = comb(n_teeth + 1, tooth_len, 1);
    let len = f64::from(tooth_len);
    let w = 2.0 * n_teeth as f64 + 1.0;
    let mut b = vec![
        DVec2::new(w, len + g + 1.0),
        DVec2::new(0.0, len + g + 1.0),
        DVec2::new(0.0, len + g),
    ];
    for i in 0..n_teeth {
        let x0 = 2.0 * i as f64 + 1.0 + g;
        let x1 = 2.0 * i as f64 + 2.0 - g;
        b.push(DVec2::new(x0, len + g));
        b.push(DVec2::new(x0, g));
        b.push(DVec2::new(x1, g));
        b.push(DVec2::new(x1, len + g));
    }
    b.push(DVec2::new(w, len + g));
    CombPair {
        a,
        b,
        gap: g,
        unit: u,
    }
}

/// Two combs whose teeth interleave without touching: `a` has
/// `n_teeth + 1` teeth (width 1, at `x ∈ [2i, 2i+1]`, height `tooth_len`),
/// `b` has `n_teeth` downward teeth of width `1 − 2·gap` centred in the gaps
/// of `a`, its teeth tips `gap` above `a`'s spine and its spine `gap` above
/// `a`'s teeth. Every clearance (tooth side to tooth side, tip to spine) is
/// exactly `gap`, so the exact distance between the combs is `gap` (many
/// optimal feature pairs) and they are `Disjoint` (`Touching` for 0).
///
/// `gap` is rounded **up** to a multiple of the grid step `u = 2^(e−52)`
/// (`2^e` just above the largest coordinate), which makes every coordinate
/// exact; the realised gap is returned in [`CombPair::gap`]. So gaps from
/// one ulp of the coordinates up to about 0.25 are supported (`1e-9` becomes
/// the next multiple of `u` above it).
///
/// # Panics
/// Panics if `n_teeth` or `tooth_len` is 0, `gap` is negative or not
/// finite, or the snapped gap is at least 0.25.
pub fn interleaved_combs(n_teeth: usize, tooth_len: u32, gap: f64) -> CombPair {
    assert!(n_teeth >= 1 && tooth_len >= 1, "interleaved_combs: sizes");
    assert!(gap.is_finite() && gap >= 0.0, "interleaved_combs: gap");
    let u = unit_for((2.0 * n_teeth as f64 + 2.0).max(f64::from(tooth_len) + 2.0));
    let e = (u.log2().round()) as i32;
    let g = ldexp(ldexp(gap, -e).ceil(), e);
    combs_with(n_teeth, tooth_len, g, u)
}

/// [`interleaved_combs`] with the gap given as `ulps` grid steps `u`
/// (`u` = one ulp of the largest coordinates; `ulps = 0` gives touching).
///
/// # Panics
/// As [`interleaved_combs`].
pub fn interleaved_combs_ulps(n_teeth: usize, tooth_len: u32, ulps: u64) -> CombPair {
    assert!(n_teeth >= 1 && tooth_len >= 1, "interleaved_combs: sizes");
    let u = unit_for((2.0 * n_teeth as f64 + 2.0).max(f64::from(tooth_len) + 2.0));
    assert!(ulps < 1 << 50, "interleaved_combs_ulps: too many ulps");
    combs_with(n_teeth, tooth_len, ulps as f64 * u, u)
}

/// A spiral strip: an Archimedean arm of width 1/2 with gap 1/2 between
/// windings, making `turns` full turns, sampled at `per_turn` equally spaced
/// angles per turn on both of its sides; `2 (per_turn · turns + 1)` vertices,
/// ccw.
///
/// Simple because both sides are sampled on the same `per_turn` rays (angle
/// step `< π`), radii on each ray strictly increase across sides and
/// windings, and in a convex wedge two chords joining the bounding rays at
/// increasing radii never cross; coordinates are `f64` trigonometry rounded
/// to the integer lattice (pitch `2^20` lattice units, margins of `2^18`)
/// then scaled by `2^−20` (exact). Bit-reproducible where `sin`/`cos` are.
///
/// # Panics
/// Panics unless `3 <= per_turn <= 2^16` and `1 <= turns <= 4096`.
pub fn spiral(per_turn: u32, turns: u32) -> Vec<DVec2> {
    assert!(
        (3..=1 << 16).contains(&per_turn) && (1..=4096).contains(&turns),
        "spiral: sizes"
    );
    let pitch = f64::from(1u32 << 20);
    let k = per_turn * turns;
    let point = |i: u32, inner: bool| -> W {
        let theta = TAU * f64::from(i % per_turn) / f64::from(per_turn);
        let r_in = pitch * (1.0 + f64::from(i) / f64::from(per_turn));
        let r = if inner { r_in } else { r_in + pitch / 2.0 };
        (
            (r * theta.cos()).round() as i128,
            (r * theta.sin()).round() as i128,
        )
    };
    let mut pts: Vec<W> = (0..=k).map(|i| point(i, false)).collect();
    pts.extend((0..=k).rev().map(|i| point(i, true)));
    to_world(&pts, -20)
}

/// A random simple ccw polygon on `n >= 3` random lattice points in general
/// position (distinct, no three collinear; coordinates in `[−1, 1]`, exact
/// multiples of `2^−20`), obtained from a random permutation by 2-opt
/// untangling: while two non-adjacent edges cross, reverse the chain between
/// them. Each move strictly shortens the tour, so it terminates; with no
/// crossing left and general position the polygon is simple. Roughly
/// `O(n³)`; intended for `n <= 300`.
///
/// # Panics
/// Panics if `n < 3`.
pub fn two_opt(rng: &mut SplitMix64, n: usize) -> Vec<DVec2> {
    assert!(n >= 3, "two_opt: n >= 3");
    let r: i64 = 1 << 20;
    let mut pts: Vec<L> = Vec::with_capacity(n);
    while pts.len() < n {
        let p = (rng.range_i64(-r, r), rng.range_i64(-r, r));
        let ok = pts.iter().all(|&a| a != p)
            && (0..pts.len()).all(|i| {
                (i + 1..pts.len()).all(|j| {
                    let (a, b) = (pts[i], pts[j]);
                    cross_l((b.0 - a.0, b.1 - a.1), (p.0 - a.0, p.1 - a.1)) != 0
                })
            });
        if ok {
            pts.push(p);
        }
    }
    let mut order: Vec<usize> = (0..n).collect();
    rng.shuffle(&mut order);
    let crosses = |a: L, b: L, c: L, d: L| -> bool {
        let o = |p: L, q: L, s: L| cross_l((q.0 - p.0, q.1 - p.1), (s.0 - p.0, s.1 - p.1)).signum();
        o(a, b, c) * o(a, b, d) < 0 && o(c, d, a) * o(c, d, b) < 0
    };
    loop {
        let mut changed = false;
        for i in 0..n {
            for j in i + 2..n {
                if i == 0 && j == n - 1 {
                    continue;
                }
                let (a, b) = (pts[order[i]], pts[order[i + 1]]);
                let (c, d) = (pts[order[j]], pts[order[(j + 1) % n]]);
                if crosses(a, b, c, d) {
                    order[i + 1..=j].reverse();
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    let mut poly: Vec<W> = order
        .iter()
        .map(|&k| (i128::from(pts[k].0), i128::from(pts[k].1)))
        .collect();
    let area2: i128 = (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a.0 * b.1 - a.1 * b.0
        })
        .sum();
    if area2 < 0 {
        poly.reverse();
    }
    to_world(&poly, -20)
}

/// A pocketed polygon with a convex polygon inside its pocket; see
/// [`pocket_pair`].
#[derive(Clone, Debug, PartialEq)]
pub struct PocketPair {
    /// Simple ccw 8-vertex polygon: a block with a deep rectangular pocket
    /// open at the top.
    pub p: Vec<DVec2>,
    /// The polygon inside the pocket (inside the convex hull of `p`, outside
    /// `p`): strictly convex ccw for [`pocket_pair`], the caller's polygon
    /// for [`pocket_around`].
    pub q: Vec<DVec2>,
    /// Exact distance between `p` and `q` (the clearance to the pocket's
    /// walls and floor).
    pub gap: f64,
}

/// The 8-vertex block of the pocket generators, counter-clockwise: the outer box `[x0, x1] ×
/// [y0, top]` (`outer`) with a rectangular pocket `[xl, xr] × [yf, top]` (`pocket`) open at the top.
fn pocket_block(outer: [f64; 4], pocket: [f64; 3]) -> Vec<DVec2> {
    let ([x0, x1, y0, top], [xl, xr, yf]) = (outer, pocket);
    vec![
        DVec2::new(x0, y0),
        DVec2::new(x1, y0),
        DVec2::new(x1, top),
        DVec2::new(xr, top),
        DVec2::new(xr, yf),
        DVec2::new(xl, yf),
        DVec2::new(xl, top),
        DVec2::new(x0, top),
    ]
}

/// A polygon `p` with a deep pocket and a tall strictly convex polygon `q`
/// (`n_q >= 3` vertices) sitting in it without touching: `q`'s leftmost,
/// rightmost and lowest points are exactly `gap` from the pocket's left wall,
/// right wall and floor, and its top is below the opening. The exact distance
/// is `gap` (contact `Disjoint` for `gap > 0`, `Touching` for 0). As for
/// [`interleaved_combs`], `gap` is rounded up to a multiple of the ulp grid
/// of the (integer-sized) coordinates so everything is exact; the realised
/// value is returned.
///
/// # Panics
/// Panics if `n_q < 3` (or is too large for the lattice, about 10^3), or
/// `gap` is negative, not finite or at least 0.25 after rounding.
pub fn pocket_pair(rng: &mut SplitMix64, n_q: usize, gap: f64) -> PocketPair {
    assert!(gap.is_finite() && gap >= 0.0, "pocket_pair: gap");
    let lat = lattice_convex_xy(rng, n_q, 1 << 10, 1 << 14);
    let x0 = lat.iter().map(|p| p.0).min().unwrap_or(0);
    let y0 = lat.iter().map(|p| p.1).min().unwrap_or(0);
    let lat: Vec<L> = lat.iter().map(|&(x, y)| (x - x0, y - y0)).collect();
    let wq = lat.iter().map(|p| p.0).max().unwrap_or(0) as f64;
    let hq = lat.iter().map(|p| p.1).max().unwrap_or(0) as f64;
    let wall = 1.0 + (hq / 4.0).floor();
    let u = unit_for(wq.max(hq) + 2.0 * wall + 2.0);
    let e = (u.log2().round()) as i32;
    let g = ldexp(ldexp(gap, -e).ceil(), e);
    assert!(g < 0.25, "pocket_pair: gap must be below 0.25");
    let (xl, xr, yf) = (-g, wq + g, -g);
    let (x_out0, x_out1, y_out0, y_top) = (xl - wall, xr + wall, yf - wall, hq + wall);
    let p = pocket_block([x_out0, x_out1, y_out0, y_top], [xl, xr, yf]);
    let q = lat
        .iter()
        .map(|&(x, y)| DVec2::new(x as f64, y as f64))
        .collect();
    PocketPair { p, q, gap: g }
}

/// Where the polygon of [`pocket_around`] sits against its pocket's lid (the
/// hull edge across the pocket's opening).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PocketLid {
    /// The opening lies the wall thickness above the polygon's top.
    Clear,
    /// The opening lies at the polygon's top level: its topmost vertices are on
    /// the lid's line (one vertex: pinched; two: along an edge), strictly
    /// between the pocket's two upper corners.
    Touching,
}

/// An 8-vertex ccw block with a rectangular pocket open at the top, built
/// around the caller's simple polygon `inner`: the pocket's left and right
/// walls and its floor are exactly `ulps` grid steps `u` from `inner`'s
/// leftmost, rightmost and lowest points, the opening at `inner`'s top level
/// ([`PocketLid::Touching`]) or the wall thickness above it
/// ([`PocketLid::Clear`]). `u` is the ulp of the largest magnitude among the
/// block's coordinates before the gap (`inner`'s bounding box widened by the
/// wall), so a few `ulps` are a few ulps of the coordinates, also when
/// `inner` lies far from the origin. The wall thickness is a power of two
/// near a quarter of `inner`'s larger extent.
///
/// The exact distance between the two is `ulps · u` (returned in
/// [`PocketPair::gap`]): `Disjoint` for `ulps > 0`, `Touching` for 0; the
/// lid is no edge of the block, so touching its line is no contact. `inner`
/// lies in the block's convex hull (its bounding rectangle): Amato's
/// containing case.
///
/// Returns `None` if some coordinate of the block would not be exact (`inner`
/// off the grid of `u`, or the gap carrying a coordinate into the next
/// binade): nothing is rounded.
///
/// # Panics
/// Panics if `inner` has fewer than 3 vertices, a coordinate is not finite,
/// its bounding box is degenerate, or the gap exceeds a quarter of the wall.
pub fn pocket_around(inner: &[DVec2], ulps: u64, lid: PocketLid) -> Option<PocketPair> {
    assert!(inner.len() >= 3, "pocket_around: at least 3 vertices");
    assert!(
        inner.iter().all(|v| v.is_finite()),
        "pocket_around: finite coordinates"
    );
    let (x0, x1) = inner
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |a, v| {
            (a.0.min(v.x), a.1.max(v.x))
        });
    let (y0, y1) = inner
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |a, v| {
            (a.0.min(v.y), a.1.max(v.y))
        });
    let size = (x1 - x0).max(y1 - y0);
    assert!(size > 0.0, "pocket_around: degenerate polygon");
    // A power of two in (size/8, size/4].
    let mut k = 0i32;
    while ldexp(1.0, k) > size / 4.0 {
        k -= 1;
    }
    while ldexp(1.0, k + 1) <= size / 4.0 {
        k += 1;
    }
    let wall = ldexp(1.0, k);
    // The grid: one ulp of the largest magnitude the block reaches before the gap.
    let m = x0.abs().max(x1.abs()).max(y0.abs()).max(y1.abs()) + wall;
    let mut e = 0i32;
    while ldexp(1.0, e) > m {
        e -= 1;
    }
    while ldexp(1.0, e + 1) <= m {
        e += 1;
    }
    let u = ldexp(1.0, e - 52);
    assert!(ulps < 1 << 50, "pocket_around: too many ulps");
    let g = ulps as f64 * u;
    assert!(
        g <= wall / 4.0,
        "pocket_around: gap beyond a quarter of the wall"
    );
    // a + b, or None if the sum is not exact.
    let add = |a: f64, b: f64| -> Option<f64> {
        let s = a + b;
        (s.is_finite() && rat_finite(s) == rat_finite(a) + rat_finite(b)).then_some(s)
    };
    if inner
        .iter()
        .any(|v| ldexp(v.x, 52 - e).fract() != 0.0 || ldexp(v.y, 52 - e).fract() != 0.0)
    {
        return None;
    }
    let (xl, xr, yf) = (add(x0, -g)?, add(x1, g)?, add(y0, -g)?);
    let y_top = match lid {
        PocketLid::Clear => add(y1, wall)?,
        PocketLid::Touching => y1,
    };
    let (x_out0, x_out1, y_out0) = (add(xl, -wall)?, add(xr, wall)?, add(yf, -wall)?);
    let p = pocket_block([x_out0, x_out1, y_out0, y_top], [xl, xr, yf]);
    Some(PocketPair {
        p,
        q: inner.to_vec(),
        gap: g,
    })
}

/// A saw-tooth slab: the rectangle `[0, 4] × [0, 2t]` with `t` saw teeth on its right side, tips at
/// `x = 5`, `y = 2k + 1` (ccw, integer coordinates, exact). Two of them facing each other, tips
/// opposite notches, make the hull-disjoint pair whose closest hull features are lids.
///
/// # Panics
/// Panics if `t` is 0.
pub fn sawtooth(t: usize) -> Vec<DVec2> {
    assert!(t >= 1, "sawtooth: at least one tooth");
    let mut p = vec![DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0)];
    for k in 0..t {
        let y = 2.0 * k as f64;
        p.push(DVec2::new(5.0, y + 1.0));
        p.push(DVec2::new(4.0, y + 2.0));
    }
    p.push(DVec2::new(0.0, 2.0 * t as f64));
    p
}

/// [`sawtooth`] with hooked teeth: each tooth runs from its base `(4, y)` out to its tip
/// `(5, y + 1.4)`, then back down and in to `(4.6, y + 1.2)` (an overhang: the boundary runs
/// backwards along `y` there) and on to the next base `(4, y + 2)`. Counter-clockwise, simple, exact
/// in binary up to the decimal tips (all coordinates are the nearest doubles of the figures).
///
/// # Panics
/// Panics if `t` is 0.
pub fn hooked_sawtooth(t: usize) -> Vec<DVec2> {
    assert!(t >= 1, "hooked_sawtooth: at least one tooth");
    let mut p = vec![DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0)];
    for k in 0..t {
        let y = 2.0 * k as f64;
        p.push(DVec2::new(5.0, y + 1.4));
        p.push(DVec2::new(4.6, y + 1.2));
        p.push(DVec2::new(4.0, y + 2.0));
    }
    p.push(DVec2::new(0.0, 2.0 * t as f64));
    p
}

/// Two hooked saw-tooth slabs facing each other: [`hooked_sawtooth`]`(t)` and its mirror image
/// `x ↦ 10.25 − x` moved up by one (tips `1/4` beyond the other's tips, facing its notches). The
/// hulls are disjoint, their closest features are lids, and neither facing chain is monotone
/// along the separating line (the monotone sweep declines; section 3 answers).
///
/// # Panics
/// Panics if `t` is 0.
pub fn hooked_teeth_facing(t: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    facing_mirror(hooked_sawtooth(t))
}

/// A slab and its mirror image `x ↦ 10.25 − x` moved up by one, counter-clockwise (the order
/// reversed, as the reflection turns it).
fn facing_mirror(p: Vec<DVec2>) -> (Vec<DVec2>, Vec<DVec2>) {
    let q: Vec<DVec2> = p
        .iter()
        .rev()
        .map(|v| DVec2::new(10.25 - v.x, v.y + 1.0))
        .collect();
    (p, q)
}

/// Two stars of `h` vertices each (radii 1 and 1/2 alternating, a tip at angle 0), centred 3
/// apart on the `x`-axis: the second is turned by a half-turn and one vertex step, so that one of
/// its notches faces a tip of the first one unit away, and the hulls' nearest features are a tip
/// and a lid (no facing chain is monotone along the separating line).
///
/// # Panics
/// Panics if `h` is odd or below 8.
pub fn stars_notch_facing_tip(h: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    assert!(
        h >= 8 && h % 2 == 0,
        "an even number of vertices, at least 8"
    );
    let star = |c: DVec2, turn: f64| -> Vec<DVec2> {
        (0..h)
            .map(|k| {
                let a = TAU * k as f64 / h as f64 + turn;
                c + DVec2::new(a.cos(), a.sin()) * if k % 2 == 0 { 1.0 } else { 0.5 }
            })
            .collect()
    };
    (
        star(DVec2::ZERO, 0.0),
        star(DVec2::new(3.0, 0.0), TAU / 2.0 + TAU / h as f64),
    )
}

/// A zigzag of `h` vertices `s` apart along `y = 0` (every other one `s/4` up), centred on the
/// origin, on top of a triangle below it, and the bottom of a cap: an arc of `h` vertices of radius
/// 1 around the origin, from 120° to 60°, closed above. The hulls are disjoint and their closest
/// features are the zigzag's top and the arc's chord (a lid). The clearance is from the zigzag's
/// ends to the arc's, about `√(1 − x + x²)` for the half-width `x = s·h/2`, and every zigzag
/// vertex is within `1 ± x` of every arc vertex: a hair-wide zigzag (`s = 2⁻³⁰`) puts them all
/// within a hair of the clearance; a wide one (`s·h = 0.6`: clearance 0.89) makes the clearance
/// exceed both chains' extents along the separating line.
///
/// # Panics
/// Panics if `h` < 2.
pub fn zigzag_under_arc(h: usize, s: f64) -> (Vec<DVec2>, Vec<DVec2>) {
    assert!(h >= 2, "at least two vertices a chain");
    let mut p = vec![DVec2::new(-1.0, -3.0), DVec2::new(1.0, -3.0)];
    p.extend(
        (0..h)
            .rev()
            .map(|i| DVec2::new((i as f64 - h as f64 / 2.0) * s, (i % 2) as f64 * s / 4.0)),
    );
    let mut q: Vec<DVec2> = (0..h)
        .map(|i| {
            let a = (120.0 - 60.0 * i as f64 / (h - 1) as f64).to_radians();
            DVec2::new(a.cos(), a.sin())
        })
        .collect();
    q.push(DVec2::new(0.5, 3.0));
    q.push(DVec2::new(-0.5, 3.0));
    (p, q)
}

/// Two saw-tooth slabs facing each other: [`sawtooth`]`(t)` and its mirror image `x ↦ 10.25 − x`
/// moved up by one, so that tips face notches `1/4` beyond the tips (counter-clockwise, exact). The
/// convex hulls are disjoint and their closest features are lids.
///
/// # Panics
/// Panics if `t` is 0.
pub fn sawteeth_facing(t: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    facing_mirror(sawtooth(t))
}
