//! The small-input path: a support guess (sampled supports, GJK's support mapping kept while it
//! helps, a local descent) for `n + m <` [`SUPPORT_BELOW`], else a linear walk around `Z = P ⊖ Q` for
//! `n + m <` [`LINEAR_BELOW`], both in plain `f64`, proposes a candidate pair, and the exact Theorem-1
//! certificate decides whether it is the answer.
//!
//! Nothing here decides anything: the guess and the walk only choose which pair to certify. Their
//! arithmetic is rounded and may pick a wrong pair on near-degenerate input; then the certificate
//! (exact predicates) fails and the caller runs the `O(log)` search. A certified pair that is not
//! `parallel` is the unique optimal canonical pair, so the answer is the one the search would give; a
//! `parallel` pair is left to the search, which decides which of the optimal pairs to report (so the
//! output never depends on the path taken). Every loop is bounded by a constant or by the ring's
//! length, whatever the arithmetic does.

use glam::DVec2;
use polydist_polygon::predicates::Kernel;

use crate::pair::{Pair, canonical_certified};

/// Below this total `n + m` of vertex counts (two polygons with area), [`distance_with`](crate::distance_with)
/// tries the linear walk when the support guess failed, before the search. The walk costs about 110
/// instructions per step and the support guess now answers every benchmark pair (1000 random pairs
/// per size, both workloads), so the walk only backs the guess up on small inputs; the cut is kept at
/// `n + m = 64`.
pub(crate) const LINEAR_BELOW: usize = 64;

/// Below this total `n + m` of vertex counts (two polygons with area), [`distance_with`](crate::distance_with)
/// tries the support guess ([`certified_support`]) before anything else. Measured (the benchmark's pair
/// generator, 1000 pairs per size and workload): it answers 100 % of the pairs at `n = m = 8 … 128`,
/// 92–97 % at `n = m = 512`, where a miss costs the guess plus the search (callgrind, `+x`, `n = 512`:
/// 24,875 instructions with the guess against 10,684 for the search alone); instructions per Robust
/// query with the guess at `n = m = 64`: 1,962 (`+x`) and 1,677 (random direction) against 8,336 and
/// 6,882 for the search. So the cut is `n + m = 512`.
pub(crate) const SUPPORT_BELOW: usize = 512;

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

/// How many evenly spaced vertices [`support_from_samples`] looks at before climbing.
const SAMPLES: usize = 8;
/// At most this many refinements of the support pair in [`certified_support`].
const REFINEMENTS: usize = 4;
/// At most this many local-descent moves in [`certified_support`].
const DESCENT: usize = 16;

/// `k − 1` on a ring of `len` indices.
#[inline(always)]
fn pred(k: usize, len: usize) -> usize {
    if k == 0 { len - 1 } else { k - 1 }
}

/// A vertex of the convex ring `v` maximizing `x·d`, found by climbing from `start`: along the ring
/// while the next vertex is strictly higher (`f64`; the heights along a convex ring are unimodal, so
/// the climb ends at the top or, on rounded ties, next to it). At most `len` steps.
#[inline]
fn climb(v: &[DVec2], d: DVec2, start: usize) -> usize {
    let len = v.len();
    let (mut k, mut h) = (start, v[start].dot(d));
    let forward = v[succ(k, len)].dot(d);
    if forward > h {
        (k, h) = (succ(k, len), forward);
        for _ in 0..len {
            let next = succ(k, len);
            let hn = v[next].dot(d);
            if hn <= h {
                break;
            }
            (k, h) = (next, hn);
        }
    } else {
        for _ in 0..len {
            let next = pred(k, len);
            let hn = v[next].dot(d);
            if hn <= h {
                break;
            }
            (k, h) = (next, hn);
        }
    }
    k
}

/// A support vertex of `v` along `d`: the highest of at most [`SAMPLES`] evenly spaced vertices (all
/// of them for small rings), then [`climb`]. `O(SAMPLES + len/SAMPLES)` dot products.
#[inline]
fn support_from_samples(v: &[DVec2], d: DVec2) -> usize {
    let len = v.len();
    let stride = len.div_ceil(SAMPLES);
    let (mut best, mut top) = (0, v[0].dot(d));
    let mut k = stride;
    while k < len {
        let h = v[k].dot(d);
        if h > top {
            (best, top) = (k, h);
        }
        k += stride;
    }
    if stride == 1 { best } else { climb(v, d, best) }
}

/// The mean of at most four evenly spaced vertices: a point inside the polygon.
#[inline]
fn inner_point(v: &[DVec2]) -> DVec2 {
    let len = v.len();
    (v[0] + v[len / 4] + v[len / 2] + v[3 * len / 4]) * 0.25
}

/// The nearest in `f64` of the five vertex–vertex and vertex–edge pairs at the vertices `p_i`, `q_j`,
/// with its squared distance.
fn nearest_of_five(p: &[DVec2], q: &[DVec2], i: usize, j: usize) -> (f64, Pair) {
    let (n, m) = (p.len(), q.len());
    let (ip, jp) = (pred(i, n), pred(j, m));
    let z = p[i] - q[j];
    let candidates = [
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
    let mut best = (z.length_squared(), Pair::Vv(i, j));
    for c in candidates {
        if c.0 < best.0 {
            best = c;
        }
    }
    best
}

/// The nearest point of the segment `[a, b]` to `x` (`f64`).
#[inline]
fn nearest_on_segment(x: DVec2, a: DVec2, b: DVec2) -> DVec2 {
    let e = b - a;
    let t = ((x - a).dot(e) / e.length_squared()).clamp(0.0, 1.0);
    if t.is_finite() { a + t * e } else { a }
}

/// The direction from `P` to `Q` that the pair suggests, as GJK takes it: the vector between the pair's
/// nearest points (`f64`; the edge's normal when the foot is inside the edge).
fn direction(p: &[DVec2], q: &[DVec2], pair: Pair) -> DVec2 {
    match pair {
        Pair::Vv(i, j) => q[j] - p[i],
        Pair::Ve(i, j) => nearest_on_segment(p[i], q[j], q[succ(j, q.len())]) - p[i],
        Pair::Ev(i, j) => q[j] - nearest_on_segment(q[j], p[i], p[succ(i, p.len())]),
    }
}

/// The cheapest guess, tried before the walk: support vertices of `P` and `Q` along the direction
/// between two inner points (the means of four vertices each), then steps of GJK's support mapping
/// along the vector between the current nearest pair's nearest points while they bring the pair
/// strictly nearer (at most [`REFINEMENTS`]; vertex supports alone can zigzag around the answer), then a
/// local descent: move one of the two vertices to a ring neighbour while that is strictly nearer (at
/// most [`DESCENT`] moves), only when the pair so far fails the certificate. The pair compared at two vertices is the nearest (in `f64`) of the five
/// vertex–vertex and vertex–edge pairs there; the final one is canonicalised and certified under `K`.
/// `O(SAMPLES + (n + m)/SAMPLES)` arithmetic when the supports move little; `None` when the
/// certificate fails, else the pair and whether it is `parallel`.
pub(crate) fn certified_support<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Option<(Pair, bool)> {
    let (n, m) = (p.len(), q.len());
    let d = inner_point(q) - inner_point(p);
    let (mut i, mut j) = (support_from_samples(p, d), support_from_samples(q, -d));
    let mut best = nearest_of_five(p, q, i, j);
    for _ in 0..REFINEMENTS {
        let d = direction(p, q, best.1);
        let (i2, j2) = (climb(p, d, i), climb(q, -d, j));
        if (i2, j2) == (i, j) {
            break;
        }
        let next = nearest_of_five(p, q, i2, j2);
        if next.0 >= best.0 {
            break;
        }
        (i, j, best) = (i2, j2, next);
    }
    if let Some(found) = canonical_certified::<K>(p, q, best.1) {
        return Some(found);
    }
    for _ in 0..DESCENT {
        let start = (i, j);
        for (a, b) in [
            (succ(i, n), j),
            (pred(i, n), j),
            (i, succ(j, m)),
            (i, pred(j, m)),
        ] {
            let next = nearest_of_five(p, q, a, b);
            if next.0 < best.0 {
                (i, j, best) = (a, b, next);
            }
        }
        if (i, j) == start {
            break;
        }
    }
    canonical_certified::<K>(p, q, best.1)
}

/// The certified canonical closest pair of two polygons with area found by the walk, or `None`
/// (the walk's candidate failed the certificate: meeting polygons, or a rounding-misled walk).
///
/// The walk merges the edges of `P` (from its lowest vertex) and of `−Q` (from `Q`'s highest) by
/// pseudo-angle: `n + m` steps, each side `p_i − q_j + [0, 1]·edge` of `Z` measured in `f64`, the
/// nearest to the origin proposed as the pair. `O(n + m)` arithmetic, then `O(1)` exact predicates.
pub(crate) fn certified_walk<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Option<(Pair, bool)> {
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
    canonical_certified::<K>(p, q, best.1)
}
