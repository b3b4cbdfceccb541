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
//! - the foot `f = a + t(b − a)`, per coordinate `f_k = N_k / L` with `N_k = a_k·L + ((x − a)·(b − a))(b_k − a_k)`
//!   (degree 3): from a plain estimate `g`, the residual `R = N_k − g·L` is evaluated in double-double
//!   with a rigorous bound and the step `g + fl(R)/fl(L)` is accepted once the bound shows it within
//!   0.625 of a gap of the result (at most three steps; else `g = fl(N_k)/fl(L)` and one exactly
//!   evaluated residual, within `0.5 + O(2⁻⁵⁰)` ulp). Under 1 ulp per coordinate either way.
//!
//! If `c²` overflows (coordinates near `2^500`), the fallback `s = (c/L)·c`, `d = |c|/√L` costs at
//! most 5u and 3.5u instead; subnormal intermediates void the bounds (not met in practice: they need
//! distances below `2^-500`).

use glam::DVec2;
use polydist_predicates::{DoubleDouble, Polynomial, Ring, round_value};

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
    // The exact differences, squared and summed in double-double; exact evaluation only where the
    // bound cannot certify the rounding (the same value either way).
    let (dx, dy) = (
        DoubleDouble::difference(p.x, q.x),
        DoubleDouble::difference(p.y, q.y),
    );
    let squared = dx
        .square()
        .add(&dy.square())
        .certain_rounding()
        .unwrap_or_else(|| round_value(&SqDist, &[p.x, p.y, q.x, q.y]));
    Built {
        distance: squared.sqrt(),
        squared,
        vertex: p,
        other: q,
    }
}

/// Distance from vertex `x` to edge `ab` whose foot is strictly inside the edge, and the foot.
///
/// The shared subexpressions (the exact differences `b − a`, `x − a`, then `L` and the cross product)
/// are evaluated once in double-double with a rigorous bound; `L` and `c²` are the bound-certified
/// correct roundings of their exact values (exact evaluation, [`round_value`], only where the bound
/// cannot certify), so the distance budgets above hold unchanged. The foot is refined from a plain
/// estimate by exactly bounded residuals (see [`foot_coordinate`]).
pub(crate) fn vertex_edge(x: DVec2, a: DVec2, b: DVec2) -> Built {
    let input = [a.x, a.y, b.x, b.y, x.x, x.y];
    let diff = DoubleDouble::difference;
    let (ex, ey) = (diff(b.x, a.x), diff(b.y, a.y));
    let (wx, wy) = (diff(x.x, a.x), diff(x.y, a.y));
    let len2 = ex.square().add(&ey.square());
    let cross = ex.mul(&wy).sub(&ey.mul(&wx));
    let l = len2
        .certain_rounding()
        .unwrap_or_else(|| round_value(&Len2, &[a.x, a.y, b.x, b.y]));
    let c2 = cross
        .square()
        .certain_rounding()
        .unwrap_or_else(|| round_value(&CrossSquared, &input));
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
        other: foot_from(
            x,
            a,
            b,
            Shared {
                ex,
                ey,
                len2,
                cross,
            },
            l,
        ),
    }
}

/// The double-double subexpressions of a vertex–edge construction: `e = b − a` (exact), `L = |e|²` and
/// the cross product `c = e × (x − a)`.
#[derive(Clone, Copy)]
struct Shared {
    ex: DoubleDouble,
    ey: DoubleDouble,
    len2: DoubleDouble,
    cross: DoubleDouble,
}

/// The foot of `x` on the line `ab` (`l = fl(|b − a|²)`), each coordinate within 1 ulp (see
/// [`foot_coordinate`]).
pub(crate) fn foot(x: DVec2, a: DVec2, b: DVec2, l: f64) -> DVec2 {
    let diff = DoubleDouble::difference;
    let (ex, ey) = (diff(b.x, a.x), diff(b.y, a.y));
    let (wx, wy) = (diff(x.x, a.x), diff(x.y, a.y));
    let len2 = ex.square().add(&ey.square());
    let cross = ex.mul(&wy).sub(&ey.mul(&wx));
    foot_from(
        x,
        a,
        b,
        Shared {
            ex,
            ey,
            len2,
            cross,
        },
        l,
    )
}

/// The foot from the shared subexpressions: `f = x − (c/L)·(−e_y, e_x)`, so `f_x·L = x_x·L + c·e_y` and
/// `f_y·L = x_y·L − c·e_x` (the same exact values as `a_k·L + ((x − a)·e)·e_k`, which `FootResidual`
/// evaluates for the exact fallback).
fn foot_from(x: DVec2, a: DVec2, b: DVec2, s: Shared, l: f64) -> DVec2 {
    let Shared {
        ex,
        ey,
        len2,
        cross,
    } = s;
    let ratio = cross.estimate().0 / l;
    let coord = |k: usize| {
        let (xk, start) = if k == 0 {
            (x.x, x.x + ratio * ey.estimate().0)
        } else {
            (x.y, x.y - ratio * ex.estimate().0)
        };
        let residual = |g: f64| {
            let moved = DoubleDouble::difference(xk, g).mul(&len2);
            if k == 0 {
                moved.add(&cross.mul(&ey))
            } else {
                moved.sub(&cross.mul(&ex))
            }
        };
        let exact_residual = |g: f64| {
            let xs = [a.x, a.y, b.x, b.y, x.x, x.y, g];
            if k == 0 {
                round_value(&FootResidual::<0>, &xs)
            } else {
                round_value(&FootResidual::<1>, &xs)
            }
        };
        foot_coordinate(start, residual, l, exact_residual)
    };
    DVec2::new(coord(0), coord(1))
}

/// One coordinate `N/L` of the foot, within 1 ulp, refined from the estimate `g`.
///
/// `residual(g)` is `R = N − g·L` in double-double with a rigorous bound `e`; `l = fl(L)`. The step
/// `g ← fl(g + fl(r/l))` has error at most `½·gap + 2.5u·|corr| + 1.25·e/l` (the roundings of `L`, of
/// the quotient and of `r`'s bound, to first order with margin); it is accepted when the last two
/// terms are below an eighth of the smaller gap around the result, so the result is within `0.625`
/// of a gap (under 1 ulp). At most three steps, then the former exact method: `g = fl(N)/fl(L)` and one
/// exactly evaluated residual (`exact_residual(g)`, rounded once), within `0.5 + O(2⁻⁵⁰)` ulp.
fn foot_coordinate(
    mut g: f64,
    residual: impl Fn(f64) -> DoubleDouble,
    l: f64,
    exact_residual: impl Fn(f64) -> f64,
) -> f64 {
    const U: f64 = f64::EPSILON / 2.0;
    for _ in 0..3 {
        if !g.is_finite() {
            break;
        }
        let (r, e) = residual(g).estimate();
        let corr = r / l;
        let next = g + corr;
        if !next.is_finite() {
            break;
        }
        let gap = (next.next_up() - next).min(next - next.next_down());
        if 2.5 * U * corr.abs() + 1.25 * e / l <= gap / 8.0 {
            return next;
        }
        g = next;
    }
    let g = exact_residual(0.0) / l;
    if !g.is_finite() {
        return g;
    }
    let corr = exact_residual(g) / l;
    if corr.is_finite() { g + corr } else { g }
}
