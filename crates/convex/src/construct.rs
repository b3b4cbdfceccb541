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
//! These are the budgets of the second stage. The first, lean stage (`vertex_vertex_lean`,
//! `vertex_edge_lean`, at the end of this file) evaluates the same quantities with error-free
//! transformations in a fixed order under a hand-derived a-priori bound, and answers only when that bound
//! certifies its result: the same correctly rounded value for vertex–vertex; for vertex–edge the squared
//! distance and the foot within 0.625 ulp and the distance within 1.2 ulps (tighter than the budgets
//! above). It refuses near-total cancellation and extreme ranges, which go to the second stage.
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

/// Distance between two vertices: the squared distance correctly rounded (the lean certified stage
/// [`vertex_vertex_lean`], else the double-double stage, else exact evaluation: the same value on
/// every path), the distance its rounded square root.
pub(crate) fn vertex_vertex(p: DVec2, q: DVec2) -> Built {
    let squared = vertex_vertex_lean(p, q).unwrap_or_else(|| vertex_vertex_squared_dd(p, q));
    Built {
        distance: squared.sqrt(),
        squared,
        vertex: p,
        other: q,
    }
}

/// `fl(|p − q|²)` by the double-double ring with its running bound, exact evaluation where the bound
/// cannot certify the rounding (the fallback of [`vertex_vertex_lean`]).
pub(crate) fn vertex_vertex_squared_dd(p: DVec2, q: DVec2) -> f64 {
    let (dx, dy) = (
        DoubleDouble::difference(p.x, q.x),
        DoubleDouble::difference(p.y, q.y),
    );
    dx.square()
        .add(&dy.square())
        .certain_rounding()
        .unwrap_or_else(|| round_value(&SqDist, &[p.x, p.y, q.x, q.y]))
}

/// Distance from vertex `x` to edge `ab` whose foot is strictly inside the edge, and the foot: the
/// lean certified stage [`vertex_edge_lean`] (squared distance and foot within 0.625 ulp, distance
/// within 1.2 ulps), else the double-double stage [`vertex_edge_dd`] (the budgets of the module doc).
pub(crate) fn vertex_edge(x: DVec2, a: DVec2, b: DVec2) -> Built {
    vertex_edge_lean(x, a, b).unwrap_or_else(|| vertex_edge_dd(x, a, b))
}

/// [`vertex_edge`]'s fallback stage.
///
/// The shared subexpressions (the exact differences `b − a`, `x − a`, then `L` and the cross product)
/// are evaluated once in double-double with a rigorous bound; `L` and `c²` are the bound-certified
/// correct roundings of their exact values (exact evaluation, [`round_value`], only where the bound
/// cannot certify), so the distance budgets above hold unchanged. The foot is refined from a plain
/// estimate by exactly bounded residuals (see [`foot_coordinate`]).
pub(crate) fn vertex_edge_dd(x: DVec2, a: DVec2, b: DVec2) -> Built {
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

// ---------------------------------------------------------------------------------------------------
// The lean certified stage: error-free transformations with a-priori error bounds.
//
// The double-double ring above carries a running error bound through every operation; here the
// operations are fixed, so the bound is derived once, by hand, and evaluated at the end in a few
// multiplications. Standard model: every rounded operation `fl(a ∘ b) = (a ∘ b)(1 + δ)`, `|δ| ≤ u`;
// Two-Sum is exact; Dekker's Two-Product (and Two-Square) is exact unless a partial product
// underflows, when it errs by at most a few `2⁻¹⁰⁷⁵`. Underflow anywhere is covered by the absolute
// slack `SLACK` (see [`vertex_edge_lean`] for the ranges that make it valid). Every result is accepted
// only when its bound is at most an eighth of `u·|result|` (at most an eighth of the smaller gap around
// it), so it is within `0.5 + 0.125` of a gap of the exact value, below 1 ulp.

/// `u = 2⁻⁵³`.
const U: f64 = f64::EPSILON / 2.0;
/// `u²`.
const U2: f64 = U * U;
/// Absolute slack for underflow in the lean stage, `2⁻⁴⁰⁰`: every operation that underflows errs by at
/// most `2⁻¹⁰⁷⁵`, and within the accepted ranges no such error is magnified beyond `2⁻⁶⁶⁰`.
const SLACK: f64 = f64::from_bits((1023 - 400) << 52);
/// Absolute slack for underflow in [`vertex_vertex_lean`], `2⁻¹⁰⁶⁰`: at most a dozen operations, each
/// erring by at most `2⁻¹⁰⁷⁵` when it underflows, none magnified.
const VV_SLACK: f64 = f64::from_bits(1 << 14);
/// Differences beyond `2²⁰⁰` (or squared edge lengths below `2⁻²⁰⁰`) leave the lean stage's ranges.
const BIG: f64 = f64::from_bits((1023 + 200) << 52);
/// `2⁻²⁰⁰`.
const SMALL: f64 = f64::from_bits((1023 - 200) << 52);
/// Results below this are left to the fallback (their gaps could be subnormal).
const NORMAL: f64 = f64::from_bits((1023 - 900) << 52);

/// `s + e = a + b` exactly (Knuth's Two-Sum).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// `s + e = a + b` exactly when `|a| ≥ |b|` (Dekker's Fast-Two-Sum).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a = hi + lo` with halves of at most 26 significant bits (Veltkamp; `|a| < 2⁹⁹⁶`).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `p + e = a·b` exactly, `p = fl(a·b)` (Dekker's Two-Product, no FMA needed).
#[inline(always)]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// `p + e = a²` exactly (Two-Product with one split).
#[inline(always)]
fn two_square(a: f64) -> (f64, f64) {
    let p = a * a;
    let (h, l) = split(a);
    (p, ((h * h - p) + 2.0 * (h * l)) + l * l)
}

/// The squared length `hi + lo` of `(xh + xl, yh + yl)`, with `|exact − (hi + lo)| ≤ 26u²·hi` (plus
/// underflow slack) and `|lo| ≤ u·hi`.
///
/// `x² = xh² + 2·xh·xl + xl²`: the squares of the high parts are exact pairs; the tail `r` sums six
/// terms each below `u·A` (`A = fl(xh²) + fl(yh²)`, in total below `4u·A`) with six roundings (each
/// below `u·4.01u·A`) and drops `xl² + yl² ≤ u²·A`: at most `25.1u²·A`.
#[inline(always)]
fn square_length(xh: f64, xl: f64, yh: f64, yl: f64) -> (f64, f64) {
    let (p1, e1) = two_square(xh);
    let (p2, e2) = two_square(yh);
    let (s, t) = two_sum(p1, p2);
    let r = t + ((e1 + e2) + 2.0 * (xh * xl + yh * yl));
    fast_two_sum(s, r)
}

/// Where the exact value `hi + lo ± err` lies strictly inside the rounding cell of `hi > 0`: then `hi`
/// is its correct rounding. The gap above `hi` is `2^(e−52)` for `hi ∈ [2^e, 2^(e+1))`, the gap below
/// the same except at `hi = 2^e` (half of it).
#[inline(always)]
fn rounds_to_hi(hi: f64, lo: f64, err: f64) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
    if !(hi.is_finite() && hi >= NORMAL) {
        return false;
    }
    let bits = hi.to_bits();
    let up = f64::from_bits(bits & EXPONENT) * U; // half the gap above (exact: a power of two)
    let down = if bits & MANTISSA == 0 { up * 0.5 } else { up };
    // fl(lo ± err) errs by at most u relative; the factor 1 + 2⁻⁵⁰ covers it.
    let widen = 1.0 + 1.0 / 1_125_899_906_842_624.0;
    (lo + err) * widen < up && (err - lo) * widen < down
}

/// The lean stage of [`vertex_vertex`]: `fl(|p − q|²)`, correctly rounded, or `None` when the a-priori
/// bound cannot certify the rounding (then the double-double stage decides; the value is the same).
///
/// The differences are exact pairs (Two-Sum); [`square_length`] gives `hi + lo` within `26u²·hi`;
/// `hi` is accepted when the exact value lies strictly inside its rounding cell ([`rounds_to_hi`]).
/// No range restriction is needed: overflow gives non-finite values (rejected), underflow errs by less
/// than `VV_SLACK` in all, and results below `2⁻⁹⁰⁰` are rejected.
pub(crate) fn vertex_vertex_lean(p: DVec2, q: DVec2) -> Option<f64> {
    let (xh, xl) = two_sum(p.x, -q.x);
    let (yh, yl) = two_sum(p.y, -q.y);
    let (hi, lo) = square_length(xh, xl, yh, yl);
    rounds_to_hi(hi, lo, 26.0 * U2 * hi + VV_SLACK).then_some(hi)
}

/// The lean stage of [`vertex_edge`], or `None` when its ranges or its certificate fail.
///
/// With `e = b − a`, `w = x − a` (exact pairs by Two-Sum), `L = |e|²`, `C = e × w`, `t = C/L`: the
/// foot is `(x_x + t·e_y, x_y − t·e_x)` and the squared distance `C·t`.
/// 1. `L ≈ lh + ll` within `26u²·lh` ([`square_length`]); `C ≈ ch + cl` within `42u²·M`,
///    `M = |fl(e_x·w_y)| + |fl(e_y·w_x)|` (the two high products as exact pairs, a tail of eight terms
///    each at most `u·M`, `4u·M` in all, ten roundings, the dropped products of the tails `u²·M`),
///    normalised by Two-Sum so `|cl| ≤ u|ch|`.
/// 2. `t ≈ th + tl`: `th = fl(ch/lh)`, the residual `ch + cl − th·(lh + ll)` with `th·lh` an exact pair
///    (`ch − r` is exact by Sterbenz), below `5.1u|ch|` in size and evaluated within `11.2u²|ch|`;
///    `tl` its quotient by `lh`. Then `|t − (th + tl)| ≤ E_t = u²·(48M + 64|ch|)/lh` (`21.4u²|ch|/lh`
///    from the quotient, `42u²M/L` and `26u²|t|` from `C` and `L`, with margin).
/// 3. A foot coordinate `x_k ± t·e_j`: `g + ge = th·e_jh` exactly, `s + se = x_k ± g` exactly, the tail
///    `se ± (ge + th·e_jl + tl·e_jh)` (terms below `u|s| + 7.4u|g|`, five roundings, the dropped
///    `tl·e_jl ≤ 5.3u²|g|`): error at most `u²·(8|s| + 64|g|) + 1.1·E_t·|e_jh|`.
/// 4. `S = C·t`: `v + ve = ch·th` exactly, the tail `ve + ch·tl + cl·th` (below `7.4u|v|`, four
///    roundings, dropped `cl·tl`), then `C`'s and `t`'s errors: at most
///    `u²·(40|v| + 48M·|th|) + 1.1·|ch|·E_t`.
///
/// Each result is accepted when its bound (plus `SLACK`) is at most `u·|result|/8` and the result is
/// at least `2⁻⁹⁰⁰`: then it is within `0.625` of a gap of the exact value (under 1 ulp; the squared
/// distance and the foot within 0.625 ulp). The distance `fl(√s)` is then within
/// `0.5 + 0.625·(1 + u) < 1.2` ulps. Ranges: every difference at most `2²⁰⁰` and `lh ≥ 2⁻²⁰⁰` (so every
/// split is below `2⁹⁹⁶`, no product overflows, and an underflowed operation, at most `2⁻¹⁰⁷⁵`, is
/// magnified at most by `|t| ≤ 2³⁰¹`, `1/L ≤ 2²⁰¹`: far below `SLACK`). Otherwise `None`.
pub(crate) fn vertex_edge_lean(x: DVec2, a: DVec2, b: DVec2) -> Option<Built> {
    let (exh, exl) = two_sum(b.x, -a.x);
    let (eyh, eyl) = two_sum(b.y, -a.y);
    let (wxh, wxl) = two_sum(x.x, -a.x);
    let (wyh, wyl) = two_sum(x.y, -a.y);
    let big = exh.abs().max(eyh.abs()).max(wxh.abs()).max(wyh.abs());
    let (lh, ll) = square_length(exh, exl, eyh, eyl);
    // Written so that NaN is out of range too.
    let in_range = big <= BIG && lh >= SMALL;
    if !in_range {
        return None;
    }
    // C = e × w.
    let (q1, f1) = two_product(exh, wyh);
    let (q2, f2) = two_product(eyh, wxh);
    let (c0, c1) = two_sum(q1, -q2);
    let tail = c1 + (f1 - f2) + ((exh * wyl + exl * wyh) - (eyh * wxl + eyl * wxh));
    let (ch, cl) = two_sum(c0, tail);
    let m = q1.abs() + q2.abs();
    // t = C/L.
    let th = ch / lh;
    let (r, re) = two_product(th, lh);
    let tl = (((ch - r) - re) + (cl - th * ll)) / lh;
    let et = U2 * (48.0 * m + 64.0 * ch.abs()) / lh;
    // The foot.
    let coordinate = |xk: f64, ejh: f64, ejl: f64, plus: bool| -> Option<f64> {
        let (g, ge) = two_product(th, ejh);
        let rest = ge + (th * ejl + tl * ejh);
        let (s, se, rest) = if plus {
            let (s, se) = two_sum(xk, g);
            (s, se, rest)
        } else {
            let (s, se) = two_sum(xk, -g);
            (s, se, -rest)
        };
        let f = s + (se + rest);
        let bound = U2 * (8.0 * s.abs() + 64.0 * g.abs()) + 1.1 * et * ejh.abs() + SLACK;
        (f.abs() >= NORMAL && 8.0 * bound <= U * f.abs()).then_some(f)
    };
    let fx = coordinate(x.x, eyh, eyl, true)?;
    let fy = coordinate(x.y, exh, exl, false)?;
    // S = C·t.
    let (v, ve) = two_product(ch, th);
    let squared = v + (ve + (ch * tl + cl * th));
    let bound = U2 * (40.0 * v.abs() + 48.0 * m * th.abs()) + 1.1 * ch.abs() * et + SLACK;
    if !(squared >= NORMAL && 8.0 * bound <= U * squared) {
        return None;
    }
    Some(Built {
        distance: squared.sqrt(),
        squared,
        vertex: x,
        other: DVec2::new(fx, fy),
    })
}

#[cfg(test)]
mod tests {
    //! Both stages of the constructions against exact rational answers (the oracle): the lean stage
    //! where it certifies (its own, tighter bounds), the fallback where it refuses (the module budgets),
    //! with inputs chosen to force each branch.

    use polydist_oracle::{SplitMix64, rat, to_f64_nearest, ulps_error, ulps_error_sqrt};
    use polydist_predicates::BigRational;

    use super::*;

    fn r(x: f64) -> BigRational {
        rat(x).expect("finite")
    }

    /// The exact squared distance from `x` to the line `ab` and the exact foot.
    fn exact(x: DVec2, a: DVec2, b: DVec2) -> (BigRational, BigRational, BigRational) {
        let (ex, ey) = (r(b.x) - r(a.x), r(b.y) - r(a.y));
        let (wx, wy) = (r(x.x) - r(a.x), r(x.y) - r(a.y));
        let l = &ex * &ex + &ey * &ey;
        let c = &ex * &wy - &ey * &wx;
        let t = &c / &l;
        let fx = r(x.x) + &t * &ey;
        let fy = r(x.y) - &t * &ex;
        (&c * &t, fx, fy)
    }

    /// The errors (squared, distance, worst foot coordinate) of a construction, in ulps.
    fn errors(built: &Built, x: DVec2, a: DVec2, b: DVec2) -> (f64, f64, f64) {
        let (s, fx, fy) = exact(x, a, b);
        let foot = ulps_error(built.other.x, &fx).max(ulps_error(built.other.y, &fy));
        (
            ulps_error(built.squared, &s),
            ulps_error_sqrt(built.distance, &s),
            foot,
        )
    }

    /// Checks the fallback stage's documented budgets (3 ulps, 2.5 ulps, 1 ulp).
    fn check_fallback(x: DVec2, a: DVec2, b: DVec2) {
        let built = vertex_edge(x, a, b);
        let (s, d, f) = errors(&built, x, a, b);
        assert!(s <= 3.0 && d <= 2.5 && f <= 1.0, "{x} {a} {b}: {s} {d} {f}");
    }

    /// A random vertex strictly right of a random edge, its foot inside the edge, at the scale `scale`
    /// and the offset `offset`.
    fn vertex_and_edge(rng: &mut SplitMix64, scale: f64, offset: DVec2) -> (DVec2, DVec2, DVec2) {
        let mut p = || DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5);
        let (a, b) = (p(), p());
        let e = b - a;
        let t = 0.05 + 0.9 * (p().x + 0.5);
        let h = 0.01 + (p().y + 0.5);
        let x = a + t * e + h * DVec2::new(e.y, -e.x);
        (x * scale + offset, a * scale + offset, b * scale + offset)
    }

    #[test]
    fn lean_vertex_edge_certifies_ordinary_input_within_its_bounds() {
        let mut rng = SplitMix64::new(11);
        let (mut certified, mut total) = (0, 0);
        let mut worst = (0.0f64, 0.0f64, 0.0f64);
        for round in 0..3000 {
            // Within the lean stage's ranges (differences up to 2^200, squared edges from 2^-200).
            let scale = [1.0, 1e-6, 1e9, 3.0e-25, 7.0e50][round % 5];
            let offset =
                [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(-1e3, 2e3)][round % 3] * scale;
            let (x, a, b) = vertex_and_edge(&mut rng, scale, offset);
            total += 1;
            if let Some(built) = vertex_edge_lean(x, a, b) {
                certified += 1;
                let (s, d, f) = errors(&built, x, a, b);
                assert!(
                    s <= 0.625 && d <= 1.2 && f <= 0.625,
                    "{x} {a} {b}: {s} {d} {f}"
                );
                worst = (worst.0.max(s), worst.1.max(d), worst.2.max(f));
            }
            check_fallback(x, a, b);
            let dd = vertex_edge_dd(x, a, b);
            let (s, d, f) = errors(&dd, x, a, b);
            assert!(
                s <= 3.0 && d <= 2.5 && f <= 1.0,
                "dd {x} {a} {b}: {s} {d} {f}"
            );
        }
        println!("lean vertex-edge: {certified} of {total} certified; worst {worst:?}");
        // The lean stage is the common path on ordinary input (it refuses only near cancellation).
        assert!(certified * 10 >= total * 9, "{certified} of {total}");
    }

    #[test]
    fn lean_vertex_edge_refuses_cancellation_and_extreme_ranges() {
        let cases = [
            // The foot's x-coordinate cancels: x_x = 1e12, the edge on the line x = 1e-30.
            (
                DVec2::new(1e12, 1.0),
                DVec2::new(1e-30, -1.0),
                DVec2::new(1e-30, 5.0),
            ),
            // The foot is at y = 0 exactly: a zero coordinate is not certified.
            (
                DVec2::new(1.0, 0.0),
                DVec2::new(0.0, -1.0),
                DVec2::new(0.0, 1.0),
            ),
            // The vertex is ~1e-15 off the edge's line: C = 3·w_y − 1.5 cancels (3·w_y is inexact).
            (
                DVec2::new(1.5, 0.5 + 1e-15),
                DVec2::new(0.0, 0.0),
                DVec2::new(3.0, 1.0),
            ),
            // Differences beyond 2^200 (ordinary input otherwise).
            (
                DVec2::new(1e70, -3e70),
                DVec2::new(-2e70, 0.0),
                DVec2::new(2e70, 1e70),
            ),
            // A squared edge length below 2^-200.
            (
                DVec2::new(1e-31, -3e-31),
                DVec2::new(-2e-31, 0.0),
                DVec2::new(2e-31, 1e-31),
            ),
        ];
        for (x, a, b) in cases {
            assert!(vertex_edge_lean(x, a, b).is_none(), "{x} {a} {b}");
            check_fallback(x, a, b);
        }
        // Out of the ranges at random: refused, and the fallback keeps the budgets.
        let mut rng = SplitMix64::new(14);
        for round in 0..400 {
            let scale = [3.0e-100, 7.0e80][round % 2];
            let (x, a, b) = vertex_and_edge(&mut rng, scale, DVec2::new(0.5, -2.0) * scale);
            assert!(vertex_edge_lean(x, a, b).is_none(), "{x} {a} {b}");
            check_fallback(x, a, b);
        }
        // Sliver-near cancellation at random: whatever the lean stage does, both stages keep their bounds.
        let mut rng = SplitMix64::new(12);
        let mut refused = 0;
        for _ in 0..2000 {
            let (x, a, b) = vertex_and_edge(&mut rng, 1.0, DVec2::ZERO);
            // Move the vertex to within a few ulps of the line, far from the origin.
            let shift = DVec2::new(1e8, -1e8);
            let (a, b) = (a + shift, b + shift);
            let t = 0.5;
            let x = a + t * (b - a) + (x - a).normalize() * 1e-7;
            match vertex_edge_lean(x, a, b) {
                Some(built) => {
                    let (s, d, f) = errors(&built, x, a, b);
                    assert!(
                        s <= 0.625 && d <= 1.2 && f <= 0.625,
                        "{x} {a} {b}: {s} {d} {f}"
                    );
                }
                None => refused += 1,
            }
            check_fallback(x, a, b);
        }
        println!("near-line vertices: {refused} of 2000 refused by the lean stage");
    }

    #[test]
    fn lean_vertex_vertex_is_the_correct_rounding_or_refuses() {
        let mut rng = SplitMix64::new(13);
        let mut certified = 0;
        for round in 0..4000 {
            let scale = [1.0, 1e-130, 1e150, 1e-3][round % 4];
            let mut p = || DVec2::new(rng.unit_f64() - 0.3, rng.unit_f64() * 3.0) * scale;
            let (p, q) = (p(), p());
            let s = r(p.x) - r(q.x);
            let t = r(p.y) - r(q.y);
            let nearest = to_f64_nearest(&(&s * &s + &t * &t));
            assert_eq!(vertex_vertex(p, q).squared, nearest);
            assert_eq!(vertex_vertex_squared_dd(p, q), nearest);
            if let Some(v) = vertex_vertex_lean(p, q) {
                assert_eq!(v, nearest);
                certified += 1;
            }
        }
        assert!(certified >= 3900, "{certified} of 4000");
        // An exact tie: |p − q|² = 9 + 2⁻⁵⁰, halfway between 9 and its successor (to even: 9).
        let (p, q) = (DVec2::ZERO, DVec2::new(3.0, 2f64.powi(-25)));
        let s = r(q.x) * r(q.x) + r(q.y) * r(q.y);
        let nearest = to_f64_nearest(&s);
        assert_eq!(nearest, 9.0);
        assert!(vertex_vertex_lean(p, q).is_none());
        assert_eq!(vertex_vertex(p, q).squared, nearest);
        // Results below 2^-900 are left to the fallback.
        let (p, q) = (DVec2::ZERO, DVec2::new(1e-280, 0.0));
        assert!(vertex_vertex_lean(p, q).is_none());
        assert_eq!(
            vertex_vertex(p, q).squared,
            to_f64_nearest(&(r(1e-280) * r(1e-280)))
        );
    }
}
