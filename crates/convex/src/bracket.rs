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

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::{
        Contact, Feature, Relation, SplitMix64, contact_status_convex, convex_distance,
        convex_pair, random_convex_lattice, rat,
    };
    use polydist_polygon::predicates::{BigRational, Exact};

    type R2 = (BigRational, BigRational);

    fn r2(v: DVec2) -> R2 {
        (rat(v.x).expect("finite"), rat(v.y).expect("finite"))
    }

    /// The exact min vector `w = q* − p*` (a positive multiple of `u`) from a vertex–vertex or
    /// vertex–edge optimal pair of the oracle.
    fn min_vector(p: &[DVec2], q: &[DVec2]) -> R2 {
        let exact = convex_distance(p, q);
        let foot = |x: DVec2, a: DVec2, b: DVec2| {
            let ((xx, xy), (ax, ay), (bx, by)) = (r2(x), r2(a), r2(b));
            let (ex, ey) = (&bx - &ax, &by - &ay);
            let t = ((&xx - &ax) * &ex + (&xy - &ay) * &ey) / (&ex * &ex + &ey * &ey);
            (&ax + &t * &ex, &ay + &t * &ey)
        };
        let (ps, qs) = exact
            .pairs
            .iter()
            .find_map(|&(f, g)| match (f, g) {
                (Feature::Vertex(i), Feature::Vertex(j)) => Some((r2(p[i]), r2(q[j]))),
                (Feature::Vertex(i), Feature::Edge(j)) => {
                    Some((r2(p[i]), foot(p[i], q[j], q[(j + 1) % q.len()])))
                }
                (Feature::Edge(i), Feature::Vertex(j)) => {
                    Some((foot(q[j], p[i], p[(i + 1) % p.len()]), r2(q[j])))
                }
                (Feature::Edge(..), Feature::Edge(..)) => None,
            })
            .expect("the oracle lists vertex pairs");
        (&qs.0 - &ps.0, &qs.1 - &ps.1)
    }

    /// `⟨w, v⟩` exactly.
    fn dot(w: &R2, v: DVec2) -> BigRational {
        let (x, y) = r2(v);
        &w.0 * &x + &w.1 * &y
    }

    /// Checks Lemma B2's conclusions (R1), (R2) exactly for the bracket of `(p, q)` seeded at `(o, t)`.
    /// Returns the lengths of the two ranges.
    fn check(p: &[DVec2], q: &[DVec2], o: DVec2, t: DVec2) -> (usize, usize) {
        let w = min_vector(p, q);
        let b = bracket::<Exact>(p, q, o, t);
        let ctx = || format!("p = {p:?}\nq = {q:?}\nseed {o} → {t}\n{b:?}");
        let (n, m) = (p.len(), q.len());
        let zero = BigRational::from_integer(0.into());
        // (R2): every edge d of P's range has its outward normal strictly within 90° of u, i.e. rises
        // strictly along l_u = rot90(w): ⟨d, rot90(w)⟩ = w × d > 0; every edge of Q's range: w × d < 0.
        let cross = |a: DVec2, c: DVec2| {
            let (ax, ay) = r2(a);
            let (cx, cy) = r2(c);
            &w.0 * &(&cy - &ay) - &w.1 * &(&cx - &ax)
        };
        assert!(b.p.0 <= b.p.1 && b.p.1 < b.p.0 + n, "{}", ctx());
        assert!(b.q.0 <= b.q.1 && b.q.1 < b.q.0 + m, "{}", ctx());
        for k in b.p.0..b.p.1 {
            assert!(
                cross(at(p, k), at(p, k + 1)) > zero,
                "P edge {k}: {}",
                ctx()
            );
        }
        for k in b.q.0..b.q.1 {
            assert!(
                cross(at(q, k), at(q, k + 1)) < zero,
                "Q edge {k}: {}",
                ctx()
            );
        }
        // (R1): every vertex of the faces F_P(u) (max ⟨·, w⟩) and F_Q(−u) (min) is in its range.
        let in_range =
            |(lo, hi): (usize, usize), len: usize, i: usize| (lo..=hi).any(|k| k % len == i);
        let best_p = p.iter().map(|&v| dot(&w, v)).max().expect("vertices");
        let best_q = q.iter().map(|&v| dot(&w, v)).min().expect("vertices");
        for i in (0..n).filter(|&i| dot(&w, p[i]) == best_p) {
            assert!(in_range(b.p, n, i), "F_P(u) vertex {i}: {}", ctx());
        }
        for j in (0..m).filter(|&j| dot(&w, q[j]) == best_q) {
            assert!(in_range(b.q, m, j), "F_Q(−u) vertex {j}: {}", ctx());
        }
        (b.p.1 - b.p.0, b.q.1 - b.q.0)
    }

    /// Lemma B2 checked exactly: small lattice polygons (parallel edges, edges ⟂ u, seeds along edges
    /// and ⟂ edges are common), every seed pair of vertices, both argument orders; and generator
    /// pairs of every disjoint relation with a few seeds each.
    #[test]
    fn lemma_b2_holds_exactly() {
        let mut rng = SplitMix64::new(2006);
        let (mut pairs, mut seeds, mut single) = (0, 0, 0);
        for round in 0..700 {
            let p = random_convex_lattice(&mut rng, 3 + round % 6, 8);
            let shift = DVec2::new(rng.range_i64(-20, 20) as f64, rng.range_i64(-20, 20) as f64);
            let q: Vec<DVec2> = random_convex_lattice(&mut rng, 3 + (round / 6) % 6, 8)
                .iter()
                .map(|&v| v + shift)
                .collect();
            if contact_status_convex(&p, &q) != Contact::Disjoint {
                continue;
            }
            pairs += 1;
            for &o in &p {
                for &t in &q {
                    let (lp, lq) = check(&p, &q, o, t);
                    check(&q, &p, t, o);
                    seeds += 1;
                    single += usize::from(lp == 0 || lq == 0);
                }
            }
        }
        for rel in [
            Relation::Far,
            Relation::NearlyTouching { ulps: 1 },
            Relation::ParallelFacing,
            Relation::HugeOffset,
            Relation::Sliver,
        ] {
            for k in 0..40 {
                let pair = convex_pair(&mut rng, 3 + k % 17, 3 + k % 11, rel);
                if pair.contact != Contact::Disjoint {
                    continue;
                }
                pairs += 1;
                for s in 0..3 {
                    let (o, t) = (pair.p[s % pair.p.len()], pair.q[(5 * s) % pair.q.len()]);
                    check(&pair.p, &pair.q, o, t);
                    check(&pair.q, &pair.p, t, o);
                    seeds += 1;
                }
            }
        }
        println!("{pairs} disjoint pairs, {seeds} seeds, {single} with a one-vertex range");
        assert!(
            pairs > 300 && seeds > 5000 && single > 0,
            "{pairs} {seeds} {single}"
        );
    }
}
