//! PROCEDURE TENSTEP (McKenna–Toussaint 1985, §3) for two convex polygons at positive distance, from
//! the bridge certified by the `O(log m + log n)` distance.
//!
//! Steps 2–3 (translate and rotate so the bridge is horizontal) are replaced by exact predicates: the
//! bridge is perpendicular to the edge `e` of its vertex–edge pair, so "up" is the direction of `e`
//! oriented with `P` on its left, and `Y(a)` against `Y(b)` is the sign of `(a − b)·(t1 − t0)`.
//! Left and right are never evaluated: Lemma 3 (the corridor) puts all of `P` left of all of `Q`.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Sign};

use super::cases::step9;
use super::chain::{Best, Callers, Cand, Chain, Frame};
use super::findmin::findmin;
use super::stats::bump;
use crate::pair::Pair;

/// One side of the problem: a strictly convex counter-clockwise ring and its caller indices.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ring<'a> {
    pub(super) pts: &'a [DVec2],
    pub(super) caller: Callers<'a>,
}

/// Offers every pair of `p × q` (the brute force, and the scan for a point or a segment).
pub(super) fn scan_all<K: Kernel>(p: Ring<'_>, q: Ring<'_>, best: &mut Best) {
    for (i, &a) in p.pts.iter().enumerate() {
        for (j, &b) in q.pts.iter().enumerate() {
            best.offer::<K>(Cand {
                p: a,
                q: b,
                i: p.caller.get(i),
                j: q.caller.get(j),
            });
        }
    }
}

/// The vertex of `ring` extreme in `Y` (the top when `top`), with the paper's tie rule for a
/// horizontal extreme edge `(r_i, r_{i+1})`: `r_{i+1}` when `later`, else `r_i`. Returns the index and
/// whether the tie rule applied. `Y` is linear, hence unimodal along a strictly convex ring: the
/// binary search of `extreme.rs` finds a maximizer in `O(log n)` (the paper scans, `O(n)`).
fn extreme<K: Kernel>(ring: &[DVec2], f: &Frame, top: bool, later: bool) -> (usize, bool) {
    let n = ring.len();
    let k = crate::extreme::extreme(ring, |x, y| {
        let o = f.ycmp::<K>(x, y);
        Sign::from_ordering(if top { o } else { o.reverse() })
    }) % n;
    // A tied neighbour (a horizontal edge) is k + 1 or k − 1. Of the edge (r_i, r_{i+1}) keep r_{i+1}
    // when `later`, else r_i.
    let (next, prev) = ((k + 1) % n, (k + n - 1) % n);
    if f.ycmp::<K>(ring[next], ring[k]) == Ordering::Equal {
        (if later { next } else { k }, true)
    } else if f.ycmp::<K>(ring[prev], ring[k]) == Ordering::Equal {
        (if later { k } else { prev }, true)
    } else {
        (k, false)
    }
}

/// The four chains of steps 4–5 and the frame.
#[derive(Clone, Copy, Debug)]
pub(super) struct Chains<'a> {
    /// `V_L`: `v_max` to `v_min` counter-clockwise (top to bottom).
    pub(super) v_l: Chain<'a>,
    /// `V_R`: `v_min` to `v_max` counter-clockwise (bottom to top).
    pub(super) v_r: Chain<'a>,
    /// `W_L`: `w_max` to `w_min` counter-clockwise (top to bottom).
    pub(super) w_l: Chain<'a>,
    /// `W_R`: `w_min` to `w_max` counter-clockwise (bottom to top).
    pub(super) w_r: Chain<'a>,
    /// The bridge frame.
    pub(super) f: Frame,
}

/// Steps 2–5 in the frame whose "up" is `t1 − t0`: the extremes with the paper's tie rules, and the
/// chains they delimit (`p`, `q` with at least 3 vertices each).
pub(super) fn chains<'a, K: Kernel>(p: Ring<'a>, q: Ring<'a>, t0: DVec2, t1: DVec2) -> Chains<'a> {
    let (v, w) = (p.pts, q.pts);
    let f = Frame {
        t0,
        t1,
        flip_y: false,
        flip_o: false,
    };
    // Steps 4–5 with the paper's tie rules: v_max, v_min the left ends of horizontal edges (counter-
    // clockwise runs right to left on top), w_max, w_min the right ends.
    let (v_max, h0) = extreme::<K>(v, &f, true, true);
    let (v_min, h1) = extreme::<K>(v, &f, false, false);
    let (w_max, h2) = extreme::<K>(w, &f, true, false);
    let (w_min, h3) = extreme::<K>(w, &f, false, true);
    bump(|s| {
        for (c, hit) in s.horizontal_extremes.iter_mut().zip([h0, h1, h2, h3]) {
            *c += u64::from(hit);
        }
    });
    Chains {
        v_l: Chain::ccw(v, p.caller, true, v_max, v_min),
        v_r: Chain::ccw(v, p.caller, true, v_min, v_max),
        w_l: Chain::ccw(w, q.caller, false, w_max, w_min),
        w_r: Chain::ccw(w, q.caller, false, w_min, w_max),
        f,
    }
}

/// The frame's up direction `(t0, t1)` from a canonical bridge pair, or `None` for a vertex–vertex
/// bridge. The bridge is perpendicular to its edge (first-order optimality at an edge-interior foot).
pub(super) fn bridge_up(v: &[DVec2], w: &[DVec2], pair: Pair) -> Option<(DVec2, DVec2)> {
    let (m, n) = (v.len(), w.len());
    match pair {
        Pair::Vv(..) => None,
        // P's edge (v_i, v_{i+1}) is counter-clockwise with Q on its right: up = v_{i+1} − v_i.
        Pair::Ev(i, _) => Some((v[i % m], v[(i + 1) % m])),
        // Q's edge (w_j, w_{j+1}) has P on its right: up = w_j − w_{j+1}.
        Pair::Ve(_, j) => Some((w[(j + 1) % n], w[j % n])),
    }
}

/// TENSTEP for `P` and `Q` at positive distance with the canonical certified bridge `pair` (internal
/// indices of `p.pts`, `q.pts`): offers the nearest vertex pair to `best`. `O(m + n)` predicates.
pub(super) fn tenstep<K: Kernel>(p: Ring<'_>, q: Ring<'_>, pair: Pair, best: &mut Best) {
    let (v, w) = (p.pts, q.pts);
    let (m, n) = (v.len(), w.len());
    if m == 0 || n == 0 {
        return;
    }
    if m <= 2 || n <= 2 {
        // A point or a segment: one linear scan (SCANSET over at most two points).
        bump(|s| s.small_scans += 1);
        scan_all::<K>(p, q, best);
        return;
    }
    // Step 1 and Lemma 1: a vertex–vertex bridge is the answer. Otherwise the bridge is perpendicular
    // to its edge, which gives the frame (steps 2–3).
    let Some((t0, t1)) = bridge_up(v, w, pair) else {
        bump(|s| s.bridge_vertex_vertex += 1);
        if let Pair::Vv(i, j) = pair {
            let (i, j) = (i % m, j % n);
            best.offer::<K>(Cand {
                p: v[i],
                q: w[j],
                i: p.caller.get(i),
                j: q.caller.get(j),
            });
        }
        return;
    };
    match pair {
        Pair::Ev(..) => bump(|s| s.bridge_edge_on_p += 1),
        _ => bump(|s| s.bridge_edge_on_q += 1),
    }
    let Chains {
        v_l,
        v_r,
        w_l,
        w_r,
        f,
    } = chains::<K>(p, q, t0, t1);
    // W_L listed upward (w_min, …, w_max) and V_R listed upward (v_min, …, v_max) satisfy Lemma 6.
    let w_l_up = w_l.rev();
    findmin::<K>(&v_l, &w_l_up, best); // step 6
    findmin::<K>(&v_r, &w_l_up, best); // step 7
    findmin::<K>(&w_r, &v_r, best); // step 8 (the paper's x-negation is this exchange of roles)
    step9::<K>(v_l, w_r, f, best); // step 9
    // Step 10 is `best` itself: every candidate was compared exactly on arrival.
}
