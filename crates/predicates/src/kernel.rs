//! The three precision kernels and the named predicates every algorithm uses.

use core::cmp::Ordering;
use core::fmt::Debug;

use glam::DVec2;

use crate::poly::{Polynomial, sign_adaptive, sign_exact, sign_fast, sign_robust};
use crate::ring::{Ring, U};
use crate::{Orientation, Sign};

/// A precision kernel: how the signs of predicate polynomials are decided.
///
/// Every algorithm of polydist is generic over a kernel, [`Robust`] by default. The kernels differ only
/// in how they evaluate signs; the algorithms are the same code.
///
/// | kernel | decisions | cost |
/// |---|---|---|
/// | [`Fast`] | plain `f64`; may be wrong on near-degenerate input | 1× |
/// | [`Robust`] | exact (filter with a proved error bound, exact arithmetic when it cannot decide) | ≈1.1× on random input |
/// | [`Exact`] | exact (always exact arithmetic) | much slower |
///
/// The named predicates have default implementations in terms of [`Kernel::sign`]; a kernel may
/// override them with a faster equivalent (the Robust kernel inlines hand-derived static filters).
pub trait Kernel: Copy + Default + Debug + Send + Sync + 'static {
    /// A short name for reports: `"fast"`, `"robust"`, `"exact"`.
    const NAME: &'static str;
    /// `true` when every decision is exact (Robust and Exact).
    const EXACT_DECISIONS: bool;
    /// `true` when an exact decision may be certified by a floating-point filter with a proved
    /// error bound before exact arithmetic (Robust); `false` for the reference kernel, which
    /// always computes exactly (Exact), and for Fast, which never certifies.
    const FILTERED: bool = false;

    /// The kernel that may *guide* a search whose result this kernel then certifies: an algorithm may
    /// run a search under `Guide` to propose a candidate and accept it only after a certificate
    /// evaluated under `Self` (for example Theorem 1 for a closest pair), falling back to the search
    /// under `Self` when the certificate fails. Nothing the guide decides reaches the output unchecked.
    /// [`Fast`] for the three kernels (the guidance is plain `f64`); a wrapper such as
    /// [`Counted`](crate::Counted) wraps the guide too, so counts include the guided work.
    type Guide: Kernel;

    /// The sign of the homogeneous polynomial `p` at the inputs `x` (see [`Polynomial`]).
    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign;

    /// Called once for each decision [`crate::sign_at`] takes without [`Kernel::sign`] (the
    /// coordinate filter at crossing points, or the Fast kernel's rounded coordinates), so that a
    /// counting wrapper sees every call: no effect in the three kernels.
    #[inline(always)]
    fn note_decided_at_sites() {}

    /// The orientation of `(a, b, c)`: the sign of `(b − a) × (c − a)` (degree 2).
    #[inline]
    fn orient(a: DVec2, b: DVec2, c: DVec2) -> Orientation {
        Orientation::from_sign(Self::sign(&Orient, &[a.x, a.y, b.x, b.y, c.x, c.y]))
    }

    /// `sign((b − a) · (d − c))` (degree 2).
    #[inline]
    fn dot_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Self::sign(&Dot, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y])
    }

    /// `sign((b − a) × (d − c))` (degree 2).
    #[inline]
    fn cross_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Self::sign(&Cross, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y])
    }

    /// `|p − a|²` compared with `|p − b|²`: which of `a`, `b` is nearer to `p` (degree 2).
    #[inline]
    fn cmp_dist(p: DVec2, a: DVec2, b: DVec2) -> Ordering {
        Self::sign(&Nearer, &[p.x, p.y, a.x, a.y, b.x, b.y]).to_ordering()
    }

    /// `|a − b|²` compared with `|c − d|²` (degree 2): the minimum over candidate vertex pairs.
    #[inline]
    fn cmp_dist4(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Ordering {
        Self::sign(&Dist4, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]).to_ordering()
    }

    /// Compares two squared distances, each between a point and a point or a closed segment
    /// (degree up to 6): the minimum over vertex–edge candidates, the Hausdorff argmax.
    #[inline]
    fn cmp_dist2(x: Dist2, y: Dist2) -> Ordering {
        cmp_dist2_with::<Self>(x, y)
    }
}

/// A squared distance between a point and a point or a closed segment, for [`Kernel::cmp_dist2`].
#[derive(Clone, Copy, Debug, PartialEq)]
///
/// The points are [`DVec2`]s for [`Kernel::cmp_dist2`]; [`crate::crossing::cmp_dist2`] takes
/// [`Site`](crate::Site)s.
pub enum Dist2<P = DVec2> {
    /// `|p − q|²`.
    PointPoint(P, P),
    /// The squared distance from `p` to the closed segment `[a, b]` (`a == b` allowed).
    PointSegment(P, P, P),
    /// The squared distance from `p` to the *line* through `a` and `b`. It equals the segment's when
    /// the foot of `p` is strictly inside `[a, b]`: a caller that has established that (a scan that
    /// admits only such vertex–edge pairs) saves the two dot signs that locate the foot, on every
    /// comparison. `a == b` is taken as the point `a`.
    PointLine(P, P, P),
}

/// A squared distance resolved to its polynomial form.
#[derive(Clone, Copy)]
enum Resolved {
    /// `|p − q|²`.
    Points(DVec2, DVec2),
    /// `((b − a) × (p − a))² / |b − a|²`, the foot of `p` strictly inside `[a, b]`.
    Perp(DVec2, DVec2, DVec2),
}

/// The piece of the segment distance function `p` falls in, decided by two exact dot signs.
#[inline]
fn resolve<K: Kernel>(d: Dist2) -> Resolved {
    match d {
        Dist2::PointPoint(p, q) => Resolved::Points(p, q),
        Dist2::PointLine(p, a, b) if a == b => Resolved::Points(p, a),
        Dist2::PointLine(p, a, b) => Resolved::Perp(p, a, b),
        Dist2::PointSegment(p, a, b) => {
            // (p − a)·(b − a) ≤ 0: the nearest point is a; (p − b)·(a − b) ≤ 0: it is b.
            if K::dot_sign(a, p, a, b) != Sign::Positive {
                Resolved::Points(p, a)
            } else if K::dot_sign(b, p, b, a) != Sign::Positive {
                Resolved::Points(p, b)
            } else {
                Resolved::Perp(p, a, b)
            }
        }
    }
}

/// [`Kernel::cmp_dist2`] in terms of a kernel's dot signs and polynomial signs.
fn cmp_dist2_with<K: Kernel>(x: Dist2, y: Dist2) -> Ordering {
    match (resolve::<K>(x), resolve::<K>(y)) {
        (Resolved::Points(p, q), Resolved::Points(r, s)) => K::cmp_dist4(p, q, r, s),
        (Resolved::Points(p, q), Resolved::Perp(r, a, b)) => {
            K::sign(&PointsVsPerp, &flat([p, q, r, a, b])).to_ordering()
        }
        (Resolved::Perp(r, a, b), Resolved::Points(p, q)) => {
            K::sign(&PointsVsPerp, &flat([p, q, r, a, b]))
                .to_ordering()
                .reverse()
        }
        (Resolved::Perp(p, a, b), Resolved::Perp(q, c, d)) => {
            K::sign(&PerpVsPerp, &flat([p, a, b, q, c, d])).to_ordering()
        }
    }
}

/// The coordinates of `K` points, in order.
#[inline(always)]
fn flat<const K: usize, const N: usize>(pts: [DVec2; K]) -> [f64; N] {
    core::array::from_fn(|i| {
        if i % 2 == 0 {
            pts[i / 2].x
        } else {
            pts[i / 2].y
        }
    })
}

// ---------------------------------------------------------------------------------------------------
// The predicate polynomials, each written once for every ring.

/// `(a − c) × (b − c)`: positive when `(a, b, c)` turns counter-clockwise. Degree 2.
#[derive(Clone, Copy, Debug)]
pub struct Orient;
impl Polynomial<6> for Orient {
    const DEGREE: u32 = 2;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let (ax, ay, bx, by, cx, cy) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
        ax.sub(cx)
            .mul(&by.sub(cy))
            .sub(&ay.sub(cy).mul(&bx.sub(cx)))
    }
}

/// `(b − a) · (d − c)`. Degree 2.
#[derive(Clone, Copy, Debug)]
pub struct Dot;
impl Polynomial<8> for Dot {
    const DEGREE: u32 = 2;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (ax, ay, bx, by, cx, cy, dx, dy) =
            (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7]);
        bx.sub(ax)
            .mul(&dx.sub(cx))
            .add(&by.sub(ay).mul(&dy.sub(cy)))
    }
}

/// `(b − a) × (d − c)`. Degree 2.
#[derive(Clone, Copy, Debug)]
pub struct Cross;
impl Polynomial<8> for Cross {
    const DEGREE: u32 = 2;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (ax, ay, bx, by, cx, cy, dx, dy) =
            (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7]);
        bx.sub(ax)
            .mul(&dy.sub(cy))
            .sub(&by.sub(ay).mul(&dx.sub(cx)))
    }
}

/// `|p − a|² − |p − b|²`. Degree 2.
#[derive(Clone, Copy, Debug)]
pub struct Nearer;
impl Polynomial<6> for Nearer {
    const DEGREE: u32 = 2;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let (px, py, ax, ay, bx, by) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
        let da = px.sub(ax).square().add(&py.sub(ay).square());
        let db = px.sub(bx).square().add(&py.sub(by).square());
        da.sub(&db)
    }
}

/// `|a − b|² − |c − d|²`. Degree 2.
#[derive(Clone, Copy, Debug)]
pub struct Dist4;
impl Polynomial<8> for Dist4 {
    const DEGREE: u32 = 2;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (ax, ay, bx, by, cx, cy, dx, dy) =
            (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7]);
        let d1 = ax.sub(bx).square().add(&ay.sub(by).square());
        let d2 = cx.sub(dx).square().add(&cy.sub(dy).square());
        d1.sub(&d2)
    }
}

/// `|p − q|²·|b − a|² − ((b − a) × (r − a))²`: a point–point squared distance against the
/// perpendicular distance from `r` to line `ab`, cleared of the positive denominator. Degree 4.
#[derive(Clone, Copy, Debug)]
pub struct PointsVsPerp;
impl Polynomial<10> for PointsVsPerp {
    const DEGREE: u32 = 4;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 10]) -> R {
        let (px, py, qx, qy, rx, ry) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
        let (ax, ay, bx, by) = (&x[6], &x[7], &x[8], &x[9]);
        let pq = px.sub(qx).square().add(&py.sub(qy).square());
        let (ex, ey) = (bx.sub(ax), by.sub(ay));
        let len2 = ex.square().add(&ey.square());
        let cr = ex.mul(&ry.sub(ay)).sub(&ey.mul(&rx.sub(ax)));
        pq.mul(&len2).sub(&cr.square())
    }
}

/// `((b − a) × (p − a))²·|d − c|² − ((d − c) × (q − c))²·|b − a|²`: two perpendicular distances
/// cleared of their positive denominators. Degree 6.
#[derive(Clone, Copy, Debug)]
pub struct PerpVsPerp;
impl Polynomial<12> for PerpVsPerp {
    const DEGREE: u32 = 6;
    #[inline(always)]
    fn eval<R: Ring>(&self, x: &[R; 12]) -> R {
        let (px, py, ax, ay, bx, by) = (&x[0], &x[1], &x[2], &x[3], &x[4], &x[5]);
        let (qx, qy, cx, cy, dx, dy) = (&x[6], &x[7], &x[8], &x[9], &x[10], &x[11]);
        let (ex, ey) = (bx.sub(ax), by.sub(ay));
        let (fx, fy) = (dx.sub(cx), dy.sub(cy));
        let c1 = ex.mul(&py.sub(ay)).sub(&ey.mul(&px.sub(ax)));
        let c2 = fx.mul(&qy.sub(cy)).sub(&fy.mul(&qx.sub(cx)));
        let l1 = ex.square().add(&ey.square());
        let l2 = fx.square().add(&fy.square());
        c1.square().mul(&l2).sub(&c2.square().mul(&l1))
    }
}

// ---------------------------------------------------------------------------------------------------
// The kernels.

/// Plain `f64` evaluation. The fastest kernel; it may decide wrongly on near-degenerate input (a point
/// a few ulps off a line can be reported on the wrong side), but every algorithm still terminates.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Fast;

impl Kernel for Fast {
    const NAME: &'static str = "fast";
    type Guide = Fast;
    const EXACT_DECISIONS: bool = false;
    #[inline(always)]
    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
        sign_fast(p, x)
    }

    // The hot predicates written out, so the baseline is the plain expression whatever the inliner does.
    #[inline(always)]
    fn orient(a: DVec2, b: DVec2, c: DVec2) -> Orientation {
        Orientation::from_sign(Sign::of_f64(
            (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x),
        ))
    }

    #[inline(always)]
    fn dot_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Sign::of_f64((b.x - a.x) * (d.x - c.x) + (b.y - a.y) * (d.y - c.y))
    }

    #[inline(always)]
    fn cross_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        Sign::of_f64((b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x))
    }

    #[inline(always)]
    fn cmp_dist(p: DVec2, a: DVec2, b: DVec2) -> Ordering {
        let (ax, ay, bx, by) = (p.x - a.x, p.y - a.y, p.x - b.x, p.y - b.y);
        Sign::of_f64((ax * ax + ay * ay) - (bx * bx + by * by)).to_ordering()
    }

    #[inline(always)]
    fn cmp_dist4(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Ordering {
        let (ex, ey, fx, fy) = (a.x - b.x, a.y - b.y, c.x - d.x, c.y - d.y);
        Sign::of_f64((ex * ex + ey * ey) - (fx * fx + fy * fy)).to_ordering()
    }
}

/// Exact decisions at nearly the cost of `f64`: a floating-point filter with a proved error bound,
/// exact expansion arithmetic only when the filter cannot decide. The default kernel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Robust;

/// Static filter constant for `t1 ± t2` with `t_i` products of two rounded differences:
/// `|computed − exact| < (3u + 32u²)·(|t1| + |t2|)` (derivation in `docs/ROBUSTNESS.md`).
const ERR_PRODUCTS: f64 = 3.0 * U + 32.0 * U * U;
/// Static filter constant for `(s1 + s2) − (s3 + s4)` with `s_i` squares of rounded differences:
/// `|computed − exact| < (4u + 64u²)·(Σ s_i)`.
const ERR_SQUARES: f64 = 4.0 * U + 64.0 * U * U;
/// Absolute slack for underflow in the static filters (each product loses at most 2⁻¹⁰⁷⁵ when it underflows).
const ERR_TINY: f64 = f64::from_bits(1 << 14); // 2^-1060

/// The static filter for `x1·y1 − x2·y2`: the sign when certified.
#[inline(always)]
fn filter_products(t1: f64, t2: f64) -> Option<Sign> {
    let det = t1 - t2;
    let bound = ERR_PRODUCTS * (t1.abs() + t2.abs()) + ERR_TINY;
    // NaN or infinite values fail the comparison and fall through to the exact stage.
    if det.abs() > bound {
        Some(Sign::of_f64(det))
    } else {
        None
    }
}

/// The static filter for `(s1 + s2) − (s3 + s4)` with nonnegative `s_i`.
#[inline(always)]
fn filter_squares(s12: f64, s34: f64) -> Option<Sign> {
    let det = s12 - s34;
    let bound = ERR_SQUARES * (s12 + s34) + ERR_TINY;
    if det.abs() > bound {
        Some(Sign::of_f64(det))
    } else {
        None
    }
}

impl Kernel for Robust {
    const NAME: &'static str = "robust";
    const FILTERED: bool = true;
    type Guide = Fast;
    const EXACT_DECISIONS: bool = true;

    #[inline(always)]
    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
        sign_robust(p, x)
    }

    #[inline(always)]
    fn orient(a: DVec2, b: DVec2, c: DVec2) -> Orientation {
        let t1 = (a.x - c.x) * (b.y - c.y);
        let t2 = (a.y - c.y) * (b.x - c.x);
        match filter_products(t1, t2) {
            Some(s) => Orientation::from_sign(s),
            None => orient_exact(a, b, c),
        }
    }

    #[inline(always)]
    fn dot_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        let t1 = (b.x - a.x) * (d.x - c.x);
        let t2 = -((b.y - a.y) * (d.y - c.y));
        match filter_products(t1, t2) {
            Some(s) => s,
            None => sign_adaptive(&Dot, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]),
        }
    }

    #[inline(always)]
    fn cross_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        let t1 = (b.x - a.x) * (d.y - c.y);
        let t2 = (b.y - a.y) * (d.x - c.x);
        match filter_products(t1, t2) {
            Some(s) => s,
            None => sign_adaptive(&Cross, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]),
        }
    }

    #[inline(always)]
    fn cmp_dist(p: DVec2, a: DVec2, b: DVec2) -> Ordering {
        let (ax, ay, bx, by) = (p.x - a.x, p.y - a.y, p.x - b.x, p.y - b.y);
        match filter_squares(ax * ax + ay * ay, bx * bx + by * by) {
            Some(s) => s.to_ordering(),
            None if a == b => Ordering::Equal,
            None => sign_adaptive(&Nearer, &[p.x, p.y, a.x, a.y, b.x, b.y]).to_ordering(),
        }
    }

    #[inline(always)]
    fn cmp_dist4(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Ordering {
        let (ex, ey, fx, fy) = (a.x - b.x, a.y - b.y, c.x - d.x, c.y - d.y);
        match filter_squares(ex * ex + ey * ey, fx * fx + fy * fy) {
            Some(s) => s.to_ordering(),
            // The same pair either way round (a candidate against itself): equal, with no exact stage.
            None if (a == c && b == d) || (a == d && b == c) => Ordering::Equal,
            None => sign_adaptive(&Dist4, &[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]).to_ordering(),
        }
    }
}

/// The exact orientation: Shewchuk's adaptive `orient2d` (the `robust` crate) where its no-overflow,
/// no-underflow assumptions provably hold, our rescaling pipeline everywhere else.
#[inline(never)]
fn orient_exact(a: DVec2, b: DVec2, c: DVec2) -> Orientation {
    // Three points on one horizontal or vertical line (rectilinear input: comb teeth, lot corners):
    // the determinant is zero because both of its products are, exactly; no expansion needed.
    if (a.y == c.y && b.y == c.y) || (a.x == c.x && b.x == c.x) {
        return Orientation::Collinear;
    }
    // Every coordinate zero or within [2^-400, 2^400]: differences have tails ≥ 2^-452, products of two
    // stay within [2^-957, 2^802], so no operation of Shewchuk's stages overflows or underflows.
    const LO: f64 = f64::from_bits((1023 - 400) << 52);
    const HI: f64 = f64::from_bits((1023 + 400) << 52);
    let safe = |v: f64| v == 0.0 || (LO..=HI).contains(&v.abs());
    if [a.x, a.y, b.x, b.y, c.x, c.y].into_iter().all(safe) {
        let det = robust::orient2d(
            robust::Coord { x: a.x, y: a.y },
            robust::Coord { x: b.x, y: b.y },
            robust::Coord { x: c.x, y: c.y },
        );
        Orientation::from_sign(Sign::of_f64(det))
    } else {
        Orientation::from_sign(sign_exact(&Orient, &[a.x, a.y, b.x, b.y, c.x, c.y]))
    }
}

/// Exact arithmetic for every decision (no filter), and exact rational constructions through
/// [`crate::exact`]. The reference kernel: slowest, and the one whose answers the others are
/// measured against.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Exact;

impl Kernel for Exact {
    const NAME: &'static str = "exact";
    type Guide = Fast;
    const EXACT_DECISIONS: bool = true;
    #[inline]
    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
        sign_exact(p, x)
    }
}
