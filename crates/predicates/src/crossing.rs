//! Exact signs of any predicate at points where a segment crosses a line.
//!
//! Clipping a chain to a half-plane ends it at *crossing points*: `c = (a, b) ∩ line(l₀, l₁)` for an
//! edge whose ends lie strictly on opposite sides. Such a point is rarely representable in `f64`, so an
//! algorithm that must decide exactly keeps it symbolic (the edge and the line) and asks its
//! predicates through [`sign_at`], which takes [`Site`]s: input points or crossing points.
//!
//! # The construction
//! With `X(z) = (l₁ − l₀) × (z − l₀)` (degree 2) and `D = X(a) − X(b) ≠ 0`,
//!
//! ```text
//! c = (X(a)·b − X(b)·a) / D,
//! ```
//!
//! each coordinate a homogeneous cubic over a homogeneous quadratic (degree 1 as a rational
//! function, like an input coordinate). A predicate `F`, written once as a [`Polynomial`] in point
//! coordinates, is evaluated at such points in a ring of fractions whose denominators are products of
//! the sites' `D`s (`Cut`): a sum brings both terms to the larger power of each `D`, a product adds
//! the powers. The numerator that results is `F(c, …)·Π Dₖ^eₖ`, a homogeneous polynomial in the input
//! coordinates; one more factor `Dₖ` where `eₖ` is odd makes every power even, so its sign is the
//! sign of `F` at the sites. [`AtSites`] is that numerator as a [`Polynomial`] of its own, so every
//! kernel decides it as it decides any other: the Robust kernel's filter first, exact arithmetic when
//! the filter cannot decide. Nothing is rounded before a decision.
//!
//! # Degree
//! If `F` has degree `m` and adds only terms of equal degree (every predicate of this crate does),
//! each `eₖ ≤ m`, so the numerator has degree at most `m + 2M(m + 1)` for `M` sites. That bound is
//! [`AtSites`]'s declared degree: the kernels' exact stage uses the degree only to choose between
//! expansions and integers, and an upper bound only makes that choice more cautious. In practice
//! the degrees are lower: an orientation with one crossing point is `X(a)·orient(p, b, z) −
//! X(b)·orient(p, a, z)` times `D`, degree 6 here (4 after cancelling `D`, which a generic evaluation
//! cannot do); two crossing points on the same line are collinear with every point on it.

use core::array;
use core::cmp::Ordering;

use glam::DVec2;

use crate::{
    Cross, Dist4, Dot, Kernel, Nearer, Orient, Orientation, PerpVsPerp, PointsVsPerp, Polynomial,
    Ring, Sign, round_value,
};

/// A point a predicate is asked about: an input point, or the crossing of a segment with a line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Site {
    /// An input point.
    Input(DVec2),
    /// The point where the segment `(a, b)` crosses the line through `l0` and `l1`. The caller
    /// guarantees that `a` and `b` lie strictly on opposite sides of the line (decided exactly, for
    /// example by [`Kernel::orient`]); otherwise the point is not defined and the signs are
    /// meaningless (never a panic).
    Crossing {
        /// The segment's first end.
        a: DVec2,
        /// The segment's second end.
        b: DVec2,
        /// A point of the line.
        l0: DVec2,
        /// A second point of the line.
        l1: DVec2,
    },
}

impl Site {
    /// Whether this is a crossing point.
    #[must_use]
    pub fn is_crossing(self) -> bool {
        matches!(self, Site::Crossing { .. })
    }

    /// The point, rounded (for constructions and reports, never for decisions): an input point as it
    /// is, a crossing point as `a + t(b − a)` with `t = X(a)/(X(a) − X(b))` from correctly rounded
    /// `X(a)`, `X(b)`, clamped to the segment.
    #[must_use]
    pub fn approx(self) -> DVec2 {
        match self {
            Site::Input(p) => p,
            Site::Crossing { a, b, l0, l1 } => {
                let xa = round_value(&Orient, &[l0.x, l0.y, l1.x, l1.y, a.x, a.y]);
                let xb = round_value(&Orient, &[l0.x, l0.y, l1.x, l1.y, b.x, b.y]);
                let t = xa / (xa - xb);
                if t.is_finite() {
                    a + (b - a) * t.clamp(0.0, 1.0)
                } else {
                    (a + b) * 0.5
                }
            }
        }
    }
}

/// A value `num / Π den[k]^exp[k]` of the ring of fractions [`sign_at`] evaluates predicates in.
#[derive(Clone)]
struct Cut<'d, R, const M: usize> {
    num: R,
    exp: [u32; M],
    /// The sites' denominators (`None` only for constants made by [`Ring::input`], whose powers are
    /// all zero).
    den: Option<&'d [R; M]>,
}

impl<R: Ring, const M: usize> Cut<'_, R, M> {
    /// `num · Π den[k]^(to[k] − exp[k])`: the numerator over the larger powers `to`.
    fn lifted(&self, to: &[u32; M], den: &[R; M]) -> R {
        let mut n = self.num.clone();
        for k in 0..M {
            for _ in self.exp[k]..to[k] {
                n = n.mul(&den[k]);
            }
        }
        n
    }

    /// `self ± rhs` over the common denominator.
    fn sum(&self, rhs: &Self, minus: bool) -> Self {
        let den = self.den.or(rhs.den);
        let combine = |a: &R, b: &R| if minus { a.sub(b) } else { a.add(b) };
        match den {
            Some(d) if self.exp != rhs.exp => {
                let exp = array::from_fn(|k| self.exp[k].max(rhs.exp[k]));
                let num = combine(&self.lifted(&exp, d), &rhs.lifted(&exp, d));
                Cut { num, exp, den }
            }
            // Equal powers (or no denominators at all: both are constants).
            _ => Cut {
                num: combine(&self.num, &rhs.num),
                exp: self.exp,
                den,
            },
        }
    }
}

impl<R: Ring, const M: usize> Ring for Cut<'_, R, M> {
    fn input(x: f64) -> Self {
        Cut {
            num: R::input(x),
            exp: [0; M],
            den: None,
        }
    }
    fn add(&self, rhs: &Self) -> Self {
        self.sum(rhs, false)
    }
    fn sub(&self, rhs: &Self) -> Self {
        self.sum(rhs, true)
    }
    fn mul(&self, rhs: &Self) -> Self {
        Cut {
            num: self.num.mul(&rhs.num),
            exp: array::from_fn(|k| self.exp[k] + rhs.exp[k]),
            den: self.den.or(rhs.den),
        }
    }
    fn neg(&self) -> Self {
        Cut {
            num: self.num.neg(),
            exp: self.exp,
            den: self.den,
        }
    }
}

/// The predicate `F` (`N = 2M` inputs: `M` points) at `M` sites, some of them crossing points, as a
/// polynomial in `NI = 8M` inputs, eight per site: an input point's coordinates and six zeros, or a
/// crossing point's `a`, `b`, `l0`, `l1`. Its sign is the sign of `F` at the sites (module docs);
/// [`sign_at`] builds and decides it. For signs only: its declared degree is an upper bound, so
/// [`round_value`] of it would scale by the wrong power.
#[derive(Clone, Copy, Debug)]
pub struct AtSites<'f, F: ?Sized, const N: usize, const M: usize> {
    f: &'f F,
    crossing: [bool; M],
}

impl<F, const N: usize, const M: usize, const NI: usize> Polynomial<NI> for AtSites<'_, F, N, M>
where
    F: Polynomial<N> + ?Sized,
{
    #[allow(
        clippy::cast_possible_truncation,
        reason = "M is the number of a predicate's points, a handful"
    )]
    const DEGREE: u32 = F::DEGREE + 2 * (M as u32) * (F::DEGREE + 1);

    fn eval<R: Ring>(&self, x: &[R; NI]) -> R {
        const { assert!(N == 2 * M && NI == 8 * M) };
        let mut den: [R; M] = array::from_fn(|_| R::input(0.0));
        let mut num: [(R, R); M] = array::from_fn(|k| (x[8 * k].clone(), x[8 * k + 1].clone()));
        for k in 0..M {
            if self.crossing[k] {
                let v = |i: usize| &x[8 * k + i];
                let (ax, ay, bx, by) = (v(0), v(1), v(2), v(3));
                let (l0x, l0y) = (v(4), v(5));
                let (dx, dy) = (v(6).sub(l0x), v(7).sub(l0y));
                // X(z) = d × (z − l₀).
                let side = |zx: &R, zy: &R| dx.mul(&zy.sub(l0y)).sub(&dy.mul(&zx.sub(l0x)));
                let (xa, xb) = (side(ax, ay), side(bx, by));
                num[k] = (xa.mul(bx).sub(&xb.mul(ax)), xa.mul(by).sub(&xb.mul(ay)));
                den[k] = xa.sub(&xb);
            }
        }
        let coords: [Cut<'_, R, M>; N] = array::from_fn(|i| {
            let k = i / 2;
            let mut exp = [0; M];
            if self.crossing[k] {
                exp[k] = 1;
            }
            Cut {
                num: if i % 2 == 0 {
                    num[k].0.clone()
                } else {
                    num[k].1.clone()
                },
                exp,
                den: Some(&den),
            }
        });
        let v = self.f.eval(&coords);
        // Even powers only: the numerator then has the sign of F at the sites.
        let mut out = v.num;
        for (e, d) in v.exp.iter().zip(&den) {
            if e % 2 == 1 {
                out = out.mul(d);
            }
        }
        out
    }
}

/// The sign of the predicate `F` at `M` sites (its `N = 2M` inputs are their coordinates in order);
/// `NI = 8M` (checked at compile time). With no crossing point among the sites this is
/// `K::sign(f, …)` on their coordinates. Exact under the Robust and Exact kernels.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_predicates::{Orient, Robust, Sign, Site, sign_at};
///
/// // The segment (0, 1)–(1, −2) crosses the x-axis at (1/3, 0), which no f64 represents.
/// let (l0, l1) = (DVec2::ZERO, DVec2::X);
/// let c = Site::Crossing { a: DVec2::new(0.0, 1.0), b: DVec2::new(1.0, -2.0), l0, l1 };
/// // With two more points of the x-axis: exactly collinear.
/// let s = sign_at::<Robust, _, 6, 3, 24>(&Orient, [c, Site::Input(DVec2::X), Site::Input(DVec2::NEG_X)]);
/// assert_eq!(s, Sign::Zero);
/// ```
#[must_use]
pub fn sign_at<K, F, const N: usize, const M: usize, const NI: usize>(
    f: &F,
    sites: [Site; M],
) -> Sign
where
    K: Kernel,
    F: Polynomial<N> + ?Sized,
{
    const { assert!(N == 2 * M && NI == 8 * M) };
    let coordinate = |i: usize| match sites[i / 2] {
        Site::Input(p) if i % 2 == 0 => p.x,
        Site::Input(p) => p.y,
        Site::Crossing { .. } => 0.0,
    };
    if sites.iter().all(|s| !s.is_crossing()) {
        let x: [f64; N] = array::from_fn(coordinate);
        return K::sign(f, &x);
    }
    let x: [f64; NI] = array::from_fn(|i| {
        let (k, j) = (i / 8, i % 8);
        match sites[k] {
            Site::Input(p) => match j {
                0 => p.x,
                1 => p.y,
                _ => 0.0,
            },
            Site::Crossing { a, b, l0, l1 } => [a.x, a.y, b.x, b.y, l0.x, l0.y, l1.x, l1.y][j],
        }
    });
    let at = AtSites::<F, N, M> {
        f,
        crossing: sites.map(Site::is_crossing),
    };
    K::sign(&at, &x)
}

/// [`Kernel::orient`] at sites.
#[must_use]
pub fn orient<K: Kernel>(a: Site, b: Site, c: Site) -> Orientation {
    Orientation::from_sign(sign_at::<K, _, 6, 3, 24>(&Orient, [a, b, c]))
}

/// [`Kernel::dot_sign`] at sites.
#[must_use]
pub fn dot_sign<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    sign_at::<K, _, 8, 4, 32>(&Dot, [a, b, c, d])
}

/// [`Kernel::cross_sign`] at sites.
#[must_use]
pub fn cross_sign<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    sign_at::<K, _, 8, 4, 32>(&Cross, [a, b, c, d])
}

/// [`Kernel::cmp_dist`] at sites: `|p − a|²` against `|p − b|²`.
#[must_use]
pub fn cmp_dist<K: Kernel>(p: Site, a: Site, b: Site) -> Ordering {
    sign_at::<K, _, 6, 3, 24>(&Nearer, [p, a, b]).to_ordering()
}

/// [`Kernel::cmp_dist4`] at sites: `|a − b|²` against `|c − d|²`.
#[must_use]
pub fn cmp_dist4<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Ordering {
    sign_at::<K, _, 8, 4, 32>(&Dist4, [a, b, c, d]).to_ordering()
}

/// `|p − q|²` against the squared distance from `r` to the line `ab`: the sign of [`PointsVsPerp`]
/// at sites.
#[must_use]
pub fn points_vs_perp<K: Kernel>(p: Site, q: Site, r: Site, a: Site, b: Site) -> Sign {
    sign_at::<K, _, 10, 5, 40>(&PointsVsPerp, [p, q, r, a, b])
}

/// The squared distance from `p` to the line `ab` against that from `q` to the line `cd`: the sign
/// of [`PerpVsPerp`] at sites.
#[must_use]
pub fn perp_vs_perp<K: Kernel>([p, a, b]: [Site; 3], [q, c, d]: [Site; 3]) -> Sign {
    sign_at::<K, _, 12, 6, 48>(&PerpVsPerp, [p, a, b, q, c, d])
}
