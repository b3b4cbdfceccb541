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

use glam::DVec2;

use crate::{
    Cross, Dist4, Dot, Kernel, Nearer, Orient, Orientation, PerpVsPerp, PointsVsPerp, Polynomial,
    Ring, Sign, round_value,
};

/// A point a predicate is asked about: an input point, or the crossing of the segment `(a, b)` with
/// the line the call names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Site {
    /// An input point.
    Input(DVec2),
    /// The point where the segment `(a, b)` crosses the line. The caller guarantees that `a` and `b`
    /// lie strictly on opposite sides of it (decided exactly, for example by [`Kernel::orient`]);
    /// otherwise the point is not defined and the signs are meaningless (never a panic).
    Crossing(DVec2, DVec2),
}

impl Site {
    /// Whether this is a crossing point.
    #[must_use]
    pub fn is_crossing(self) -> bool {
        matches!(self, Site::Crossing(..))
    }

    /// The point, rounded (for constructions and reports, never for decisions): an input point as it
    /// is, a crossing point as `a + t(b − a)` with `t = X(a)/(X(a) − X(b))` from correctly rounded
    /// `X(a)`, `X(b)`, clamped to the segment.
    #[must_use]
    pub fn approx(self, l0: DVec2, l1: DVec2) -> DVec2 {
        match self {
            Site::Input(p) => p,
            Site::Crossing(a, b) => {
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
/// polynomial in `NI = 4 + 4M` inputs: the line `(l₀, l₁)`, then four per site (an input point's
/// coordinates and two zeros, or the crossing segment's `a` and `b`). Its sign is the sign of `F` at
/// the sites (module docs); build it with [`sign_at`].
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
        const { assert!(N == 2 * M && NI == 4 + 4 * M) };
        let (l0x, l0y) = (&x[0], &x[1]);
        let (dx, dy) = (x[2].sub(l0x), x[3].sub(l0y));
        // X(z) = d × (z − l₀).
        let side = |zx: &R, zy: &R| dx.mul(&zy.sub(l0y)).sub(&dy.mul(&zx.sub(l0x)));
        let mut den: [R; M] = array::from_fn(|_| R::input(0.0));
        let mut num: [(R, R); M] = array::from_fn(|k| (x[4 + 4 * k].clone(), x[5 + 4 * k].clone()));
        for k in 0..M {
            if self.crossing[k] {
                let (ax, ay, bx, by) = (&x[4 + 4 * k], &x[5 + 4 * k], &x[6 + 4 * k], &x[7 + 4 * k]);
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

/// The sign of the predicate `F` at `M` sites (its `N = 2M` inputs are their coordinates), crossing
/// points taken on the line `(l0, l1)`; `NI = 4 + 4M` (checked at compile time). With no crossing
/// point this is `K::sign(f, …)` on the coordinates. Exact under the Robust and Exact kernels.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_predicates::{Robust, Sign, Site, Orient, sign_at};
///
/// // The segment (0, 1)–(1, −2) crosses the x-axis at (1/3, 0), which no f64 represents.
/// let c = Site::Crossing(DVec2::new(0.0, 1.0), DVec2::new(1.0, -2.0));
/// let (l0, l1) = (DVec2::ZERO, DVec2::X);
/// // Two more points of the x-axis: exactly collinear.
/// let s = sign_at::<Robust, _, 6, 3, 16>(&Orient, l0, l1, [c, Site::Input(DVec2::X), Site::Input(DVec2::NEG_X)]);
/// assert_eq!(s, Sign::Zero);
/// ```
#[must_use]
pub fn sign_at<K, F, const N: usize, const M: usize, const NI: usize>(
    f: &F,
    l0: DVec2,
    l1: DVec2,
    sites: [Site; M],
) -> Sign
where
    K: Kernel,
    F: Polynomial<N> + ?Sized,
{
    const { assert!(N == 2 * M && NI == 4 + 4 * M) };
    let point = |k: usize| match sites[k] {
        Site::Input(p) => Some(p),
        Site::Crossing(..) => None,
    };
    if sites.iter().all(|s| !s.is_crossing()) {
        let x: [f64; N] = array::from_fn(|i| match point(i / 2) {
            Some(p) if i % 2 == 0 => p.x,
            Some(p) => p.y,
            None => 0.0,
        });
        return K::sign(f, &x);
    }
    let x: [f64; NI] = array::from_fn(|i| match i {
        0 => l0.x,
        1 => l0.y,
        2 => l1.x,
        3 => l1.y,
        _ => {
            let (k, j) = ((i - 4) / 4, (i - 4) % 4);
            match (sites[k], j) {
                (Site::Input(p), 0) => p.x,
                (Site::Input(p), 1) => p.y,
                (Site::Input(_), _) => 0.0,
                (Site::Crossing(a, _), 0) => a.x,
                (Site::Crossing(a, _), 1) => a.y,
                (Site::Crossing(_, b), 2) => b.x,
                (Site::Crossing(_, b), _) => b.y,
            }
        }
    });
    let at = AtSites::<F, N, M> {
        f,
        crossing: sites.map(Site::is_crossing),
    };
    K::sign(&at, &x)
}

/// The named predicates at sites, crossing points taken on the line `(l0, l1)`: the counterparts of
/// [`Kernel`]'s methods, with the same meaning.
#[derive(Clone, Copy, Debug)]
pub struct CrossingLine {
    /// A point of the line.
    pub l0: DVec2,
    /// A second point of the line.
    pub l1: DVec2,
}

impl CrossingLine {
    /// [`Kernel::orient`] at sites.
    #[must_use]
    pub fn orient<K: Kernel>(self, a: Site, b: Site, c: Site) -> Orientation {
        Orientation::from_sign(sign_at::<K, _, 6, 3, 16>(
            &Orient,
            self.l0,
            self.l1,
            [a, b, c],
        ))
    }

    /// [`Kernel::dot_sign`] at sites.
    #[must_use]
    pub fn dot_sign<K: Kernel>(self, a: Site, b: Site, c: Site, d: Site) -> Sign {
        sign_at::<K, _, 8, 4, 20>(&Dot, self.l0, self.l1, [a, b, c, d])
    }

    /// [`Kernel::cross_sign`] at sites.
    #[must_use]
    pub fn cross_sign<K: Kernel>(self, a: Site, b: Site, c: Site, d: Site) -> Sign {
        sign_at::<K, _, 8, 4, 20>(&Cross, self.l0, self.l1, [a, b, c, d])
    }

    /// [`Kernel::cmp_dist`] at sites: `|p − a|²` against `|p − b|²`.
    #[must_use]
    pub fn cmp_dist<K: Kernel>(self, p: Site, a: Site, b: Site) -> core::cmp::Ordering {
        sign_at::<K, _, 6, 3, 16>(&Nearer, self.l0, self.l1, [p, a, b]).to_ordering()
    }

    /// [`Kernel::cmp_dist4`] at sites: `|a − b|²` against `|c − d|²`.
    #[must_use]
    pub fn cmp_dist4<K: Kernel>(self, a: Site, b: Site, c: Site, d: Site) -> core::cmp::Ordering {
        sign_at::<K, _, 8, 4, 20>(&Dist4, self.l0, self.l1, [a, b, c, d]).to_ordering()
    }

    /// `|p − q|²` against the squared distance from `r` to the line `ab` (the sign of
    /// [`PointsVsPerp`]) at sites.
    #[must_use]
    pub fn points_vs_perp<K: Kernel>(self, p: Site, q: Site, r: Site, a: Site, b: Site) -> Sign {
        sign_at::<K, _, 10, 5, 24>(&PointsVsPerp, self.l0, self.l1, [p, q, r, a, b])
    }

    /// The squared distance from `p` to the line `ab` against that from `q` to the line `cd` (the
    /// sign of [`PerpVsPerp`]) at sites.
    #[must_use]
    pub fn perp_vs_perp<K: Kernel>(self, [p, a, b]: [Site; 3], [q, c, d]: [Site; 3]) -> Sign {
        sign_at::<K, _, 12, 6, 28>(&PerpVsPerp, self.l0, self.l1, [p, a, b, q, c, d])
    }
}
