//! The proved initial bracket of Yang's search: one exact "which side of `ν₀` is `u`" test, then the
//! chains of `P` and `Q` whose edge normals lie in a quarter-turn around the optimal direction `u`.
//!
//! Yang et al. (2006), section "Find initial searching ranges", builds the ranges from a case analysis
//! that the paper does not prove (design notes §4). The main loop (Table 1, Lemma A) is proved once the
//! ranges hold the support faces `F_P(u)`, `F_Q(−u)` and every edge of the ranges has its outward
//! normal strictly within 90° of `u` (of `−u` for `Q`), so that every strictly interior vertex lies
//! inside the facing chains `P_1`, `Q_1`. This file builds such ranges with four extreme searches and
//! three more signs; the proof is in `docs/algorithms/convex-distance.md`, section "The proved bracket".
//!
//! **Lemma B1 (side oracle).** Let `P`, `Q` be disjoint, `z* = p* − q*` the point of `Z = P ⊖ Q`
//! nearest the origin, `u = −z*/|z*|`. For a direction `ν` with `⟨ν, u⟩ > 0` and any maximizer
//! `z = p_i − q_j` of `⟨·, ν⟩` on `Z` (`p_i` extreme in `P` along `ν`, `q_j` extreme in `Q` along
//! `−ν`), `sign(ν × z)` is positive if `ν` is strictly counter-clockwise of `u`, negative if strictly
//! clockwise; so `ν × z > 0` puts `u` in `(ν − 90°, ν]`, `< 0` in `[ν, ν + 90°)`, `= 0` at `ν`.
//!
//! **Lemma B2 (bracket).** With `ν₀ = q_0 − p_0` (`⟨q − p, u⟩ > 0` for all `p ∈ P`, `q ∈ Q`) and the
//! quarter-turn `A ∋ u` of Lemma B1, the CCW chain of `P` made of exactly the edges whose normals are
//! in `A` (or the single vertex whose normal cone contains `A`) holds `F_P(u)`, and all its normals are
//! strictly within 90° of `u`; the same for `Q` with `−A`. The chain ends are extreme vertices along
//! `±ν₀`, `±rot90(ν₀)`, moved to the right end of an edge face by one dot sign.
//!
//! Every decision is an exact sign of degree 2 in the input coordinates (`dot_sign`, `cross_sign`).
//! Under an inexact kernel the ranges may be wrong, but they are index intervals of at most one turn,
//! so the main loop's bound still applies.

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Sign};

use crate::extreme::extreme;
use crate::pair::{at, prev};

/// The initial ranges of the main loop: closed intervals of unwrapped CCW indices (`lo ≤ hi < lo + len`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Bracket {
    /// `P`'s range `[lo, hi]`.
    pub(crate) p: (usize, usize),
    /// `Q`'s range `[lo, hi]`.
    pub(crate) q: (usize, usize),
}

/// A direction given by two input points: `c = ±(t − o)` or `c = ±rot90(t − o)`.
#[derive(Clone, Copy, Debug)]
struct Dir {
    o: DVec2,
    t: DVec2,
    rot: bool,
    neg: bool,
}

impl Dir {
    /// `sign(⟨b − a, c⟩)`, exact (degree 2): `(b − a)·(t − o)`, or `(t − o) × (b − a)` for the rotated
    /// direction (`⟨x, rot90(y)⟩ = y × x`).
    fn dot<K: Kernel>(self, a: DVec2, b: DVec2) -> Sign {
        let s = if self.rot {
            K::cross_sign(self.o, self.t, a, b)
        } else {
            K::dot_sign(a, b, self.o, self.t)
        };
        if self.neg { s.reversed() } else { s }
    }

    /// `−c`.
    fn neg(self) -> Dir {
        Dir {
            neg: !self.neg,
            ..self
        }
    }

    /// `rot90(c)`.
    fn rot90(self) -> Dir {
        // rot90(rot90(d)) = −d.
        if self.rot {
            Dir {
                rot: false,
                neg: !self.neg,
                ..self
            }
        } else {
            Dir { rot: true, ..self }
        }
    }
}

/// A vertex of the ring `v` maximizing `⟨x, c⟩` (notes §4.2; one of the two on an edge face).
fn top<K: Kernel>(v: &[DVec2], c: Dir) -> usize {
    extreme(v, |x, y| c.dot::<K>(y, x))
}

/// The clockwise end of the face `F_v(c)` found at vertex `k`: `k − 1` when edge `k − 1` is
/// perpendicular to `c` (the face is that edge), else `k`. A strictly convex ring has at most one edge
/// perpendicular to `c` on its maximal side, so one sign suffices.
fn cw_end<K: Kernel>(v: &[DVec2], k: usize, c: Dir) -> usize {
    if c.dot::<K>(prev(v, k), at(v, k)) == Sign::Zero {
        (k + v.len() - 1) % v.len()
    } else {
        k
    }
}

/// The counter-clockwise end of the face `F_v(c)` found at vertex `k`.
fn ccw_end<K: Kernel>(v: &[DVec2], k: usize, c: Dir) -> usize {
    if c.dot::<K>(at(v, k), at(v, k + 1)) == Sign::Zero {
        (k + 1) % v.len()
    } else {
        k
    }
}

/// `[lo, hi]` unwrapped so that `lo ≤ hi < lo + len`.
fn unwrap(lo: usize, hi: usize, len: usize) -> (usize, usize) {
    (lo, if hi >= lo { hi } else { hi + len })
}

/// The proved initial ranges for two disjoint polygons with area (`n, m ≥ 3`), seeded by any vertex
/// `o` of `P` and any vertex `t` of `Q` (`ν₀ = t − o`). Four extreme searches and five signs:
/// `O(log n + log m)` exact predicates. On meeting polygons the ranges are meaningless (the certificate
/// then fails).
pub(crate) fn bracket<K: Kernel>(p: &[DVec2], q: &[DVec2], o: DVec2, t: DVec2) -> Bracket {
    let nu = Dir {
        o,
        t,
        rot: false,
        neg: false,
    };
    let l = nu.rot90();
    // Lemma B1 at ν₀: z = p_i − q_j maximizes ⟨·, ν₀⟩ on Z; the sign of ν₀ × z = (t − o) × (p_i − q_j).
    let i = top::<K>(p, nu);
    let j = top::<K>(q, nu.neg());
    let side = K::cross_sign(o, t, at(q, j), at(p, i));
    let (p_lo, p_hi, q_lo, q_hi) = if side == Sign::Positive {
        // u ∈ (ν₀ − 90°, ν₀]: P's normals in (−l, ν₀], Q's in (l, −ν₀] (l = rot90(ν₀)).
        (
            ccw_end::<K>(p, top::<K>(p, l.neg()), l.neg()),
            ccw_end::<K>(p, i, nu),
            ccw_end::<K>(q, top::<K>(q, l), l),
            ccw_end::<K>(q, j, nu.neg()),
        )
    } else {
        // u ∈ [ν₀, ν₀ + 90°): P's normals in [ν₀, l), Q's in [−ν₀, −l).
        (
            cw_end::<K>(p, i, nu),
            cw_end::<K>(p, top::<K>(p, l), l),
            cw_end::<K>(q, j, nu.neg()),
            cw_end::<K>(q, top::<K>(q, l.neg()), l.neg()),
        )
    };
    Bracket {
        p: unwrap(p_lo, p_hi, p.len()),
        q: unwrap(q_lo, q_hi, q.len()),
    }
}
