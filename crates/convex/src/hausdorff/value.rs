//! The numbers: each per-vertex squared distance from its exact feature, as an unevaluated sum
//! `hi + lo` of two doubles (the exact value to about 100 bits), and their compensated sum.
//!
//! - vertex `q`: a first value `hi` (plain `fl(dx² + dy²)`, within `4u`; exactly rounded by
//!   [`round_value`] near underflow), then `lo ≈ |v − q|² − hi`, the exact residual estimated in
//!   double-double with a rigorous bound (evaluated exactly when the bound is too wide);
//! - edge `ab` (foot strictly inside): `g = fl(c²/L)` from `c = (b − a) × (v − a)` and `L = |b − a|²`
//!   (plain `f64` when the enclosure shows no cancellation, within `7u` and `4u`; else each exact and
//!   rounded once), then `lo ≈ (c² − g·L)/L` with the residual `c² − g·L` evaluated exactly (a degree-4
//!   polynomial with `g` as an input).
//!
//! Either way `hi + lo` is the exact value to about `2⁻¹⁰⁰` relative (the first value only has to be
//! close; the residual carries the rest), and `fl(hi + lo)` is within `0.5 + 2⁻⁴⁰` ulp of it: the exact
//! value rounded once, up to the last bit.
//!
//! The CMMR sum adds all `hi` and `lo` parts with Neumaier's compensated summation: the terms are
//! nonnegative (`lo` is a tiny correction), so the result is within `u·S + O(n·u²)·S` of the exact sum
//! `S` plus the per-term `2⁻¹⁰⁰`: under 1.5 ulps for any `n` below `2⁴⁰`.

use glam::DVec2;
use polydist_predicates::{
    BigInt, BigRational, Polynomial, Ring, estimate_value, exact, round_value,
};

use super::walk::Near;
use crate::construct;

/// `|p − q|²` (degree 2). Inputs `[px, py, qx, qy]`.
struct SqDist;
impl Polynomial<4> for SqDist {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 4]) -> R {
        x[0].sub(&x[2]).square().add(&x[1].sub(&x[3]).square())
    }
}

/// `|p − q|² − g·one` (degree 2; `g` and `one = 1` are inputs so the polynomial stays homogeneous).
/// Inputs `[px, py, qx, qy, g, one]`.
struct SqDistResidual;
impl Polynomial<6> for SqDistResidual {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let d = x[0].sub(&x[2]).square().add(&x[1].sub(&x[3]).square());
        d.sub(&x[4].mul(&x[5]))
    }
}

/// `((b − a) × (v − a))² − g·one·|b − a|²` (degree 4). Inputs `[ax, ay, bx, by, vx, vy, g, one]`.
struct QuotientResidual;
impl Polynomial<8> for QuotientResidual {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (ex, ey) = (x[2].sub(&x[0]), x[3].sub(&x[1]));
        let c = ex.mul(&x[5].sub(&x[1])).sub(&ey.mul(&x[4].sub(&x[0])));
        let l = ex.square().add(&ey.square());
        c.square().sub(&x[6].mul(&x[7]).mul(&l))
    }
}

/// `(b − a) × (v − a)` (degree 2). Inputs `[ax, ay, bx, by, vx, vy]`.
struct Cross;
impl Polynomial<6> for Cross {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let (ex, ey) = (x[2].sub(&x[0]), x[3].sub(&x[1]));
        ex.mul(&x[5].sub(&x[1])).sub(&ey.mul(&x[4].sub(&x[0])))
    }
}

/// The foot of `v` on the line `ab` as `v − (c/L)·(b − a)^⊥`, with `c ≈ (b − a) × (v − a)` within 7u
/// and `L ≈ |b − a|²` within 4u (see [`term`]). Per coordinate the correction `k·e_⊥` carries a relative
/// error below `14u + O(u²)` (`c`, `L`, the quotient, the rounded difference `e`, the product) and the
/// sum one rounding: the result is within `0.5 ulp + 16u·δ` of the exact foot, `δ` the distance. With
/// `precise`, it is accepted only when that bound is at most 1 ulp, else the accurate construction
/// (`construct::foot`, within 1 ulp always, several exact evaluations) answers.
fn foot(v: DVec2, a: DVec2, b: DVec2, c: f64, l: f64, precise: bool) -> DVec2 {
    const U: f64 = f64::EPSILON / 2.0;
    let e = b - a;
    let k = c / l;
    let (dx, dy) = (k * e.y, -(k * e.x));
    let f = DVec2::new(v.x + dx, v.y + dy);
    let ok = |fc: f64, d: f64| {
        let ulp = fc.abs().next_up() - fc.abs();
        fc.is_finite() && 16.0 * U * d.abs() <= 0.5 * ulp
    };
    if !precise || (ok(f.x, dx) && ok(f.y, dy)) {
        f
    } else {
        construct::foot(v, a, b, l)
    }
}

/// Plain first values below this are recomputed exactly-rounded (far from underflow).
const NORMAL_ENOUGH: f64 = 1e-280;

/// The value of one vertex: squared distance as `hi + lo`, the distance, the nearest point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Term {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
    pub(crate) squared: f64,
    pub(crate) distance: f64,
    pub(crate) projection: DVec2,
}

/// A residual `r` known to `|r − est.value| ≤ est.error`, taken from the estimate when that is good
/// enough for a correction of size `|r|/scale` to `hi` (1/1024 ulp), else evaluated exactly.
fn residual<const N: usize, P: Polynomial<N>>(poly: &P, x: &[f64; N], hi: f64, scale: f64) -> f64 {
    let est = estimate_value(poly, x);
    let ulp = (hi.next_up() - hi).abs();
    if est.error / scale <= ulp / 1024.0 {
        est.value
    } else {
        round_value(poly, x)
    }
}

/// The term of vertex `v` with nearest feature `near` on `q`.
/// With `precise`, the projection is within 1 ulp per coordinate (for the few reported winners);
/// otherwise within `0.5 ulp + 16u·δ` (for bulk per-vertex records), see [`foot`].
pub(crate) fn term(q: &[DVec2], v: DVec2, near: Near, precise: bool) -> Term {
    // Scale-invariance: squared distances scale by 4^k when the coordinates scale by 2^k. Points whose
    // differences are far from 1 are scaled by a power of two (exact, unless a coordinate 1,000
    // binades below the others underflows, which moves no value above rounding) so that no product
    // of the plain first values or of the constructions overflows or underflows; the results are
    // scaled back exactly (unless the result itself is out of range).
    let (a, b) = match near {
        Near::Inside | Near::OnVertex(_) | Near::OnEdge(_) => {
            return term_unscaled(q, v, near, precise);
        }
        Near::Vertex(i) => (q[i], q[i]),
        Near::Edge(i) => (q[i], q[if i + 1 == q.len() { 0 } else { i + 1 }]),
    };
    let (e, w) = (b - a, v - a);
    let md = e.abs().max_element().max(w.abs().max_element());
    const LO: f64 = 1.0 / 1_267_650_600_228_229_401_496_703_205_376.0; // 2^-100
    const HI: f64 = 1_267_650_600_228_229_401_496_703_205_376.0; // 2^100
    if !(md.is_finite() && md > 0.0) || (LO..=HI).contains(&md) {
        return term_unscaled(q, v, near, precise);
    }
    let k = (-md.log2().floor()).clamp(-600.0, 600.0) as i32;
    let (up, down) = (2f64.powi(k), 2f64.powi(-k));
    let local: [DVec2; 2] = [a * up, b * up];
    let f = match near {
        Near::Vertex(_) => Near::Vertex(0),
        _ => Near::Edge(0),
    };
    let t = term_unscaled(&local, v * up, f, precise);
    let sq = |x: f64| x * down * down;
    Term {
        hi: sq(t.hi),
        lo: sq(t.lo),
        squared: sq(t.squared),
        distance: t.distance * down,
        projection: t.projection * down,
    }
}

/// [`term`] for points whose differences are within `2^±100`.
fn term_unscaled(q: &[DVec2], v: DVec2, near: Near, precise: bool) -> Term {
    let zero = Term {
        hi: 0.0,
        lo: 0.0,
        squared: 0.0,
        distance: 0.0,
        projection: v,
    };
    match near {
        Near::Inside | Near::OnVertex(_) | Near::OnEdge(_) => zero,
        Near::Vertex(i) => {
            let c = q[i];
            // A first value in plain f64 (within 4u: every term is positive), else rounded once; the
            // exact residual below corrects either to about 2^-100.
            let d = v - c;
            let plain = d.x * d.x + d.y * d.y;
            let hi = if plain.is_finite() && plain >= NORMAL_ENOUGH {
                plain
            } else {
                round_value(&SqDist, &[v.x, v.y, c.x, c.y])
            };
            let lo = if hi.is_finite() && hi > 0.0 {
                residual(&SqDistResidual, &[v.x, v.y, c.x, c.y, hi, 1.0], hi, 1.0)
            } else {
                0.0
            };
            let squared = hi + lo;
            Term {
                hi,
                lo,
                squared,
                distance: squared.sqrt(),
                projection: c,
            }
        }
        Near::Edge(i) => {
            let (a, b) = (q[i], q[if i + 1 == q.len() { 0 } else { i + 1 }]);
            // c = (b − a) × (v − a) and L = |b − a|²: in plain f64 when there is no cancellation
            // (|fl(c) − c| ≤ 3u(|t1| + |t2|) + u|fl(c)| ≤ 7u|fl(c)| when |t1| + |t2| ≤ 2|fl(c)|;
            // fl(L) within 4u), else each exact and rounded once. A first quotient within 20u; the
            // exact residual below corrects it.
            let (e, w) = (b - a, v - a);
            let (t1, t2) = (e.x * w.y, e.y * w.x);
            let (c0, l0) = (t1 - t2, e.x * e.x + e.y * e.y);
            let cheap = t1.abs() + t2.abs() <= 2.0 * c0.abs()
                && c0.abs() >= NORMAL_ENOUGH
                && l0.is_finite()
                && l0 >= NORMAL_ENOUGH
                && (c0 * c0).is_finite();
            let (c, l) = if cheap {
                (c0, l0)
            } else {
                (
                    round_value(&Cross, &[a.x, a.y, b.x, b.y, v.x, v.y]),
                    round_value(&SqDist, &[a.x, a.y, b.x, b.y]),
                )
            };
            let g = (c * c) / l;
            if !(g.is_finite() && g >= f64::MIN_POSITIVE && l.is_finite()) {
                // Out of the range of the corrected quotient: the construction's bounded values.
                let built = construct::vertex_edge(v, a, b);
                return Term {
                    hi: built.squared,
                    lo: 0.0,
                    squared: built.squared,
                    distance: built.distance,
                    projection: built.other,
                };
            }
            let x = [a.x, a.y, b.x, b.y, v.x, v.y, g, 1.0];
            let lo = residual(&QuotientResidual, &x, g, l) / l;
            let lo = if lo.is_finite() { lo } else { 0.0 };
            let squared = g + lo;
            Term {
                hi: g,
                lo,
                squared,
                distance: squared.sqrt(),
                projection: foot(v, a, b, c, l, precise),
            }
        }
    }
}

/// Neumaier's compensated sum of `hi` and `lo` parts.
pub(crate) fn compensated_sum(terms: impl Iterator<Item = (f64, f64)>) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    let mut add = |x: f64| {
        let t = s + x;
        // TwoSum's error term, ordered by magnitude (Neumaier 1974).
        c += if s.abs() >= x.abs() {
            (s - t) + x
        } else {
            (x - t) + s
        };
        s = t;
    };
    for (hi, lo) in terms {
        add(hi);
        add(lo);
    }
    s + c
}

/// The exact squared distance of `v` to its nearest feature `near` of `q`, as a rational.
pub(crate) fn exact_squared(q: &[DVec2], v: DVec2, near: Near) -> BigRational {
    let zero = || BigRational::from_integer(BigInt::from(0));
    let r = match near {
        Near::Inside | Near::OnVertex(_) | Near::OnEdge(_) => None,
        Near::Vertex(i) => exact::squared_distance_point_point(v, q[i]),
        Near::Edge(i) => {
            let j = if i + 1 == q.len() { 0 } else { i + 1 };
            exact::squared_distance_point_segment(v, q[i], q[j])
        }
    };
    r.unwrap_or_else(zero)
}
