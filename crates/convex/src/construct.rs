//! Accurate constructions from exactly chosen features: "compute the intermediates exactly, round once".
//!
//! Every value here is a ratio of small polynomials in the input coordinates. Each polynomial is
//! evaluated exactly by [`round_value`] and rounded once (relative error at most `u = 2⁻⁵³`); the ratio
//! and the square root add one rounding each. With `|v|·u < ulp(v)`, a relative error `k·u` is less
//! than `k` ulps. Budgets (first order in `u`, normal ranges, no overflow):
//! - vertex–vertex: `s = fl(|p − q|²)` (≤ 0.5 ulp); `d = fl(√s)` (≤ 0.25·2 + 0.5 < 1 ulp).
//! - vertex–edge (foot strictly inside edge `ab`): `c² = ((b − a) × (x − a))²` and `L = |b − a|²`,
//!   each exact then rounded once; `s = fl(fl(c²)/fl(L))` (3 roundings: < 3 ulps);
//!   `d = fl(√s)` (1.5u + one rounding: < 2.5 ulps).
//! - the foot `f = a + t(b − a)`, per coordinate `f.x = N_x / L` with `N_x = a.x·L + ((x − a)·(b − a))(b.x − a.x)`
//!   (degree 3): a first quotient `g = fl(N_x)/fl(L)`, then the exact residual `R = N_x − g·L` (degree 3
//!   again, with `g` as an input) corrects it: `f.x ≈ g + fl(R)/fl(L)`. The correction is `O(u)·|g|`
//!   with relative error `O(u)`, so the result is within `0.5 + O(2⁻⁵⁰)` ulp: under 1 ulp per coordinate.
//!
//! If `c²` overflows (coordinates near `2^500`), the fallback `s = (c/L)·c`, `d = |c|/√L` costs at
//! most 5u and 3.5u instead; subnormal intermediates void the bounds (not met in practice: they need
//! distances below `2^-500`).

use glam::DVec2;
use polydist_predicates::{Polynomial, Ring, estimate_value, round_value};

/// `|p − q|²` (degree 2). Inputs `[px, py, qx, qy]`.
struct SqDist;
impl Polynomial<4> for SqDist {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 4]) -> R {
        let dx = x[0].sub(&x[2]);
        let dy = x[1].sub(&x[3]);
        dx.square().add(&dy.square())
    }
}

/// `(b − a) × (x − a)` (degree 2). Inputs `[ax, ay, bx, by, xx, xy]`.
struct Cross;
impl Polynomial<6> for Cross {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let (ex, ey) = (x[2].sub(&x[0]), x[3].sub(&x[1]));
        ex.mul(&x[5].sub(&x[1])).sub(&ey.mul(&x[4].sub(&x[0])))
    }
}

/// `((b − a) × (x − a))²` (degree 4). Inputs as [`Cross`].
struct CrossSquared;
impl Polynomial<6> for CrossSquared {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        Cross.eval(x).square()
    }
}

/// `|b − a|²` (degree 2). Inputs `[ax, ay, bx, by]`.
struct Len2;
impl Polynomial<4> for Len2 {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 4]) -> R {
        SqDist.eval(x)
    }
}

/// `N − g·L` for one coordinate of the foot: `N = a_k·L + ((x − a)·(b − a))(b_k − a_k)`, `L = |b − a|²`
/// (degree 3; `g` is an input of degree 1). Inputs `[ax, ay, bx, by, xx, xy, g]`; `K = 0` for the
/// x-coordinate, `1` for y.
struct FootResidual<const K: usize>;
impl<const K: usize> Polynomial<7> for FootResidual<K> {
    const DEGREE: u32 = 3;
    fn eval<R: Ring>(&self, x: &[R; 7]) -> R {
        let (ex, ey) = (x[2].sub(&x[0]), x[3].sub(&x[1]));
        let l = ex.square().add(&ey.square());
        let t = x[4].sub(&x[0]).mul(&ex).add(&x[5].sub(&x[1]).mul(&ey));
        let (ak, ek) = if K == 0 { (&x[0], &ex) } else { (&x[1], &ey) };
        ak.mul(&l).add(&t.mul(ek)).sub(&x[6].mul(&l))
    }
}

/// A constructed distance and the realizing points.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Built {
    pub(crate) distance: f64,
    pub(crate) squared: f64,
    /// The point on the vertex side.
    pub(crate) vertex: DVec2,
    /// The point on the other side (a vertex or a foot).
    pub(crate) other: DVec2,
}

/// Distance between two vertices.
pub(crate) fn vertex_vertex(p: DVec2, q: DVec2) -> Built {
    let squared = round_value(&SqDist, &[p.x, p.y, q.x, q.y]);
    Built {
        distance: squared.sqrt(),
        squared,
        vertex: p,
        other: q,
    }
}

/// Distance from vertex `x` to edge `ab` whose foot is strictly inside the edge, and the foot.
pub(crate) fn vertex_edge(x: DVec2, a: DVec2, b: DVec2) -> Built {
    let input = [a.x, a.y, b.x, b.y, x.x, x.y];
    let l = round_value(&Len2, &[a.x, a.y, b.x, b.y]);
    let c2 = round_value(&CrossSquared, &input);
    let (distance, squared) = if c2.is_finite() && c2 >= f64::MIN_POSITIVE {
        let s = c2 / l;
        (s.sqrt(), s)
    } else {
        let c = round_value(&Cross, &input).abs();
        (c / l.sqrt(), (c / l) * c)
    };
    Built {
        distance,
        squared,
        vertex: x,
        other: foot(x, a, b, l),
    }
}

/// The foot of `x` on the line `ab` (`l = fl(|b − a|²)`), each coordinate within 1 ulp.
pub(crate) fn foot(x: DVec2, a: DVec2, b: DVec2, l: f64) -> DVec2 {
    // First quotient: g = fl(N)/fl(L) with N evaluated exactly (the residual with g = 0 is N).
    let coord = |k: usize| {
        let mut input = [a.x, a.y, b.x, b.y, x.x, x.y, 0.0];
        let n = if k == 0 {
            round_value(&FootResidual::<0>, &input)
        } else {
            round_value(&FootResidual::<1>, &input)
        };
        let g = n / l;
        if !g.is_finite() {
            return g;
        }
        input[6] = g;
        // The residual only needs a few correct bits: take the double-double estimate when its bound is
        // below 2^-10 ulp(g) after division by L, else evaluate it exactly.
        let est = if k == 0 {
            estimate_value(&FootResidual::<0>, &input)
        } else {
            estimate_value(&FootResidual::<1>, &input)
        };
        let ulp_g = (g.next_up() - g).abs();
        let r = if est.error / l <= ulp_g / 1024.0 {
            est.value
        } else if k == 0 {
            round_value(&FootResidual::<0>, &input)
        } else {
            round_value(&FootResidual::<1>, &input)
        };
        let corr = r / l;
        if corr.is_finite() { g + corr } else { g }
    };
    DVec2::new(coord(0), coord(1))
}
