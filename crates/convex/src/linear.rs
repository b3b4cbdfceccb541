//! The small-input path: a support guess (two steps of GJK's support mapping), else a linear walk
//! around `Z = P ⊖ Q`, both in plain `f64`, proposes a candidate pair, and the exact Theorem-1
//! certificate decides whether it is the answer.
//!
//! Nothing here decides anything: the walk only chooses which pair to certify. Its arithmetic is
//! rounded and may pick a wrong pair on near-degenerate input; then the certificate (exact predicates)
//! fails and the caller runs the `O(log)` search. A certified pair that is not `parallel` is the unique
//! optimal canonical pair, so the answer is the one the search would give; a `parallel` pair is left to
//! the search, which decides which of the optimal pairs to report (so the output never depends on the
//! path taken).

use glam::DVec2;
use polydist_polygon::predicates::Kernel;

use crate::pair::{Pair, canonical, certify};

/// Below this total `n + m` of vertex counts (two polygons with area), [`distance_with`](crate::distance_with)
/// tries the support guess and then the linear walk before the search. Measured by instruction counts
/// per Robust query (callgrind, the benchmark's random separated pairs along a random direction and
/// along `+x`): the support guess answers in 1,620 (`+x`) and 2,822 (random) instructions at
/// `n = m = 8`, where the search costs 8,665 unguided and about 5,900 guided; at `n = m = 32`, 4,096 and
/// 2,868 against 7,363 and 5,875. At 64 the guess misses often and a miss costs more than the search
/// saves (13,006 against 9,155 along `+x`); the walk alone costs about 110 instructions per step. So the
/// cut is `n + m = 64`.
pub(crate) const LINEAR_BELOW: usize = 64;

/// A pseudo-angle of the direction `d` in `[0, 4)`, increasing with the angle from `+x` (counter-
/// clockwise); `f64`, only for ordering heuristically.
#[inline]
fn pseudo_angle(d: DVec2) -> f64 {
    let s = d.x.abs() + d.y.abs();
    if s == 0.0 || !s.is_finite() {
        return 0.0;
    }
    let t = d.y / s; // in [−1, 1]
    if d.x >= 0.0 {
        if t >= 0.0 { t } else { 4.0 + t }
    } else {
        2.0 - t
    }
}

/// `angle`, moved past a full turn when the sequence wrapped (it is below the previous one).
#[inline]
fn unwrap(angle: f64, previous: f64) -> f64 {
    if angle < previous { angle + 4.0 } else { angle }
}

/// The index of the lowest vertex of `v` (`y` minimal, then `x` maximal), or with `top` the highest
/// (`y` maximal, then `x` minimal: the lowest-rightmost vertex of `−v`).
fn lowest(v: &[DVec2], top: bool) -> usize {
    let key = |x: DVec2| if top { (-x.y, x.x) } else { (x.y, -x.x) };
    let mut best = 0;
    for i in 1..v.len() {
        let (a, b) = (key(v[i]), key(v[best]));
        if a.0 < b.0 || (a.0 == b.0 && a.1 < b.1) {
            best = i;
        }
    }
    best
}

/// `|o − s|²` for the segment `s = [z, z + d]`, in `f64` (a heuristic: it only ranks candidates).
#[inline]
fn dist2_to_segment(z: DVec2, d: DVec2) -> f64 {
    let zd = z.dot(d);
    if zd >= 0.0 {
        return z.length_squared();
    }
    let len2 = d.length_squared();
    if -zd >= len2 {
        return (z + d).length_squared();
    }
    z.length_squared() - zd * zd / len2
}

/// `k + 1` on a ring of `len` indices.
#[inline(always)]
fn succ(k: usize, len: usize) -> usize {
    if k + 1 == len { 0 } else { k + 1 }
}

/// The vertex of `v` maximizing `x·d` (`f64`, first on ties): a support point.
#[inline]
fn support(v: &[DVec2], d: DVec2) -> usize {
    let mut best = (f64::NEG_INFINITY, 0);
    for (i, x) in v.iter().enumerate() {
        let h = x.dot(d);
        if h > best.0 {
            best = (h, i);
        }
    }
    best.1
}

/// The cheapest guess, tried before the walk: support points of `P` and `Q` along the direction between
/// the vertex centroids, refined once along the direction between those supports (two steps of GJK's
/// support mapping), then the nearest (in `f64`) of the five vertex–vertex and vertex–edge pairs at the
/// two support vertices, canonicalised and certified under `K`. `O(n + m)` arithmetic with a small
/// constant; `None` when the certificate fails.
pub(crate) fn certified_support<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Option<Pair> {
    let (n, m) = (p.len(), q.len());
    let centroid = |v: &[DVec2]| v.iter().copied().sum::<DVec2>() / v.len() as f64;
    let mut d = centroid(q) - centroid(p);
    let (mut i, mut j) = (0, 0);
    for _ in 0..2 {
        i = support(p, d);
        j = support(q, -d);
        d = q[j] - p[i];
    }
    let (ip, jp) = ((i + n - 1) % n, (j + m - 1) % m);
    let z = p[i] - q[j];
    let candidates = [
        (z.length_squared(), Pair::Vv(i, j)),
        (dist2_to_segment(z, q[j] - q[succ(j, m)]), Pair::Ve(i, j)),
        (
            dist2_to_segment(p[i] - q[jp], q[jp] - q[j]),
            Pair::Ve(i, jp),
        ),
        (dist2_to_segment(z, p[succ(i, n)] - p[i]), Pair::Ev(i, j)),
        (
            dist2_to_segment(p[ip] - q[j], p[i] - p[ip]),
            Pair::Ev(ip, j),
        ),
    ];
    let mut best = candidates[0];
    for c in &candidates[1..] {
        if c.0 < best.0 {
            best = *c;
        }
    }
    let pair = canonical::<K>(p, q, best.1);
    certify::<K>(p, q, pair).then_some(pair)
}

/// The certified canonical closest pair of two polygons with area found by the walk, or `None`
/// (the walk's candidate failed the certificate: meeting polygons, or a rounding-misled walk).
///
/// The walk merges the edges of `P` (from its lowest vertex) and of `−Q` (from `Q`'s highest) by
/// pseudo-angle: `n + m` steps, each side `p_i − q_j + [0, 1]·edge` of `Z` measured in `f64`, the
/// nearest to the origin proposed as the pair. `O(n + m)` arithmetic, then `O(1)` exact predicates.
pub(crate) fn certified_walk<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Option<Pair> {
    let (n, m) = (p.len(), q.len());
    let (mut i, mut j) = (lowest(p, false), lowest(q, true));
    let (mut i1, mut j1) = (succ(i, n), succ(j, m));
    let (mut dp, mut dq) = (p[i1] - p[i], q[j] - q[j1]);
    let (mut ang_p, mut ang_q) = (pseudo_angle(dp), pseudo_angle(dq));
    let (mut a, mut b) = (0, 0);
    let mut best = (f64::INFINITY, Pair::Vv(i, j));
    while a < n || b < m {
        let z = p[i] - q[j];
        if b == m || (a < n && ang_p <= ang_q) {
            let d2 = dist2_to_segment(z, dp);
            if d2 < best.0 {
                best = (d2, Pair::Ev(i, j));
            }
            a += 1;
            (i, i1) = (i1, succ(i1, n));
            dp = p[i1] - p[i];
            // The angles wrap once the walk passes a full turn: keep them increasing.
            ang_p = if a == n {
                f64::INFINITY
            } else {
                unwrap(pseudo_angle(dp), ang_p)
            };
        } else {
            let d2 = dist2_to_segment(z, dq);
            if d2 < best.0 {
                best = (d2, Pair::Ve(i, j));
            }
            b += 1;
            (j, j1) = (j1, succ(j1, m));
            dq = q[j] - q[j1];
            ang_q = if b == m {
                f64::INFINITY
            } else {
                unwrap(pseudo_angle(dq), ang_q)
            };
        }
    }
    let pair = canonical::<K>(p, q, best.1);
    certify::<K>(p, q, pair).then_some(pair)
}
