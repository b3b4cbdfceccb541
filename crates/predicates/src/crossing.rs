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
    Bounded, Cross, Dist2, Dist4, Dot, Kernel, Nearer, Orient, Orientation, PerpVsPerp,
    PointsVsPerp, Polynomial, Ring, Sign, round_value,
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

/// A site's coordinates with rigorous error bounds: an input point exactly; a crossing point as
/// `a + t(b − a)`, `t = X(a)/(X(a) − X(b))`, in [`Bounded`] arithmetic (`None` when the bound of
/// `X(a) − X(b)` does not exclude zero).
fn bounded_coordinates(s: Site) -> Option<(Bounded, Bounded)> {
    match s {
        Site::Input(p) => Some((Bounded::input(p.x), Bounded::input(p.y))),
        Site::Crossing { a, b, l0, l1 } => {
            let i = Bounded::input;
            let (l0x, l0y) = (i(l0.x), i(l0.y));
            let (dx, dy) = (i(l1.x).sub(&l0x), i(l1.y).sub(&l0y));
            let side = |z: DVec2| dx.mul(&i(z.y).sub(&l0y)).sub(&dy.mul(&i(z.x).sub(&l0x)));
            let (xa, xb) = (side(a), side(b));
            let t = xa.div(&xa.sub(&xb))?;
            let (ax, ay) = (i(a.x), i(a.y));
            Some((
                ax.add(&t.mul(&i(b.x).sub(&ax))),
                ay.add(&t.mul(&i(b.y).sub(&ay))),
            ))
        }
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
    // The filter: the crossing points' coordinates with rigorous error bounds (one division
    // each), then the predicate in the same arithmetic as the Robust kernel's own filter. Fast
    // takes the rounded coordinates' sign as it is.
    if !K::EXACT_DECISIONS || K::FILTERED {
        let mut coords = [Bounded::input(0.0); N];
        let mut ok = true;
        for (k, s) in sites.iter().enumerate() {
            match bounded_coordinates(*s) {
                Some((x, y)) => {
                    coords[2 * k] = x;
                    coords[2 * k + 1] = y;
                }
                None => ok = false,
            }
        }
        if !K::EXACT_DECISIONS {
            K::note_decided_at_sites();
            return Sign::of_f64(f.eval(&coords.map(|c| c.value)));
        }
        if let Some(s) = ok.then(|| f.eval(&coords).certain_sign()).flatten() {
            K::note_decided_at_sites();
            return s;
        }
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

/// Whether `s` lies on the line through `l0`, `l1` by construction: a crossing point of that line
/// (given by the same two points, in either order), or one of the two points. No arithmetic: a
/// `false` only means "not known".
fn on_line(s: Site, l0: DVec2, l1: DVec2) -> bool {
    match s {
        Site::Input(p) => p == l0 || p == l1,
        Site::Crossing { l0: m0, l1: m1, .. } => (m0, m1) == (l0, l1) || (m0, m1) == (l1, l0),
    }
}

/// The line of the first crossing point among `sites`.
fn line_of(sites: &[Site]) -> Option<(DVec2, DVec2)> {
    sites.iter().find_map(|s| match *s {
        Site::Crossing { l0, l1, .. } => Some((l0, l1)),
        Site::Input(_) => None,
    })
}

/// [`Kernel::orient`] at sites.
///
/// Points known to lie on one line (crossing points of it, and the two points defining it) are
/// decided structurally, where the exact value is zero or factors, so the filter is never asked to
/// certify a zero: three of them are collinear; with two, `x` and `y`, and a third point `z`,
/// `orient(x, y, z) = sign((y − x)·d) · orient(l0, l1, z)` (`y − x` is a multiple of `d = l1 − l0`,
/// and `x` is on the line).
#[must_use]
pub fn orient<K: Kernel>(a: Site, b: Site, c: Site) -> Orientation {
    if let Some((l0, l1)) = line_of(&[a, b, c]) {
        let on = [a, b, c].map(|s| on_line(s, l0, l1));
        // Rotate (a cyclic shift keeps the orientation) so that the points on the line come first.
        let rotated = match on {
            [true, true, true] => return Orientation::Collinear,
            [true, true, false] => Some((a, b, c)),
            [false, true, true] => Some((b, c, a)),
            [true, false, true] => Some((c, a, b)),
            _ => None,
        };
        if let Some((x, y, z)) = rotated {
            let side = orient::<K>(Site::Input(l0), Site::Input(l1), z).sign();
            return Orientation::from_sign(times(side, along::<K>(x, y, l0, l1)));
        }
    }
    match (a, b, c) {
        (Site::Input(a), Site::Input(b), Site::Input(c)) => K::orient(a, b, c),
        _ => Orientation::from_sign(sign_at::<K, _, 6, 3, 24>(&Orient, [a, b, c])),
    }
}

/// `s · t` for signs.
fn times(s: Sign, t: Sign) -> Sign {
    match t {
        Sign::Positive => s,
        Sign::Negative => s.reversed(),
        Sign::Zero => Sign::Zero,
    }
}

/// The sign of `(d − c)·(l1 − l0)` when `c`, `d` lie on the line (`d − c = t(l1 − l0)`: the sign of
/// `t`), structurally when `(c, d)` is the line's own pair.
fn along<K: Kernel>(c: Site, d: Site, l0: DVec2, l1: DVec2) -> Sign {
    let (m0, m1) = (Site::Input(l0), Site::Input(l1));
    if c == d {
        Sign::Zero
    } else if (c, d) == (m0, m1) {
        Sign::Positive
    } else if (c, d) == (m1, m0) {
        Sign::Negative
    } else {
        dot_sign_plain::<K>(c, d, m0, m1)
    }
}

/// [`Kernel::dot_sign`] at sites.
///
/// A pair of points known to lie on one line (as in [`orient`]) differs by a multiple of the line's
/// direction: `(b − a)·(d − c) = t·(b − a)·(l1 − l0)` when `c`, `d` are on it, so the sign is
/// `sign t` times a dot sign against the line's own two points (and likewise for `a`, `b`).
#[must_use]
pub fn dot_sign<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    if let Some((l0, l1)) = line_of(&[a, b, c, d]) {
        let (m0, m1) = (Site::Input(l0), Site::Input(l1));
        let on = [a, b, c, d].map(|s| on_line(s, l0, l1));
        let own = |x: Site, y: Site| (x, y) == (m0, m1) || (x, y) == (m1, m0);
        if on[2] && on[3] && !own(c, d) {
            return times(dot_sign::<K>(a, b, m0, m1), along::<K>(c, d, l0, l1));
        }
        if on[0] && on[1] && !own(a, b) {
            return times(dot_sign::<K>(m0, m1, c, d), along::<K>(a, b, l0, l1));
        }
    }
    dot_sign_plain::<K>(a, b, c, d)
}

fn dot_sign_plain<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    match (a, b, c, d) {
        (Site::Input(a), Site::Input(b), Site::Input(c), Site::Input(d)) => K::dot_sign(a, b, c, d),
        _ if a == b || c == d => Sign::Zero,
        _ => sign_at::<K, _, 8, 4, 32>(&Dot, [a, b, c, d]),
    }
}

/// [`Kernel::cross_sign`] at sites.
///
/// Points known to lie on one line (as in [`orient`]) are decided structurally: when `c`, `d` lie
/// on it, `d − c = t(l1 − l0)`, so `(b − a) × (d − c) = t·(b − a) × (l1 − l0)`, and there a point of
/// the line among `a`, `b` may stand for `l0` (its own cross product with the direction is zero);
/// both on it give zero. The same with the roles of the two pairs exchanged. A depth across the
/// line of a subproblem, the common case, thus becomes an orientation of input points. Every rule
/// works with the one line chosen at the start, so the recursion is at most one level deep.
#[must_use]
pub fn cross_sign<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    if let Some((l0, l1)) = line_of(&[a, b, c, d]) {
        let (m0, m1) = (Site::Input(l0), Site::Input(l1));
        let on = [a, b, c, d].map(|s| on_line(s, l0, l1));
        if on[2] && on[3] {
            if (on[0] && on[1]) || c == d {
                return Sign::Zero;
            }
            let a2 = if on[0] { m0 } else { a };
            let b2 = if on[1] { m0 } else { b };
            return times(
                cross_sign_plain::<K>(a2, b2, m0, m1),
                along::<K>(c, d, l0, l1),
            );
        }
        if on[0] && on[1] {
            // b − a = s(l1 − l0): (b − a) × (d − c) = s·(l1 − l0) × (d − c), where a point of the
            // line among `c`, `d` may stand for `l0` (at most one is, after the case above).
            let c2 = if on[2] { m0 } else { c };
            let d2 = if on[3] { m0 } else { d };
            return times(
                cross_sign_plain::<K>(m0, m1, c2, d2),
                along::<K>(a, b, l0, l1),
            );
        }
    }
    cross_sign_plain::<K>(a, b, c, d)
}

fn cross_sign_plain<K: Kernel>(a: Site, b: Site, c: Site, d: Site) -> Sign {
    match (a, b, c, d) {
        (Site::Input(a), Site::Input(b), Site::Input(c), Site::Input(d)) => {
            K::cross_sign(a, b, c, d)
        }
        _ if a == b || c == d => Sign::Zero,
        _ => sign_at::<K, _, 8, 4, 32>(&Cross, [a, b, c, d]),
    }
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

/// A squared distance resolved to the polynomial that measures it.
#[derive(Clone, Copy)]
enum Measured {
    /// `|p − q|²`.
    Points(Site, Site),
    /// The squared distance from `p` to the line `ab`, the foot strictly inside `[a, b]`.
    Perp(Site, Site, Site),
}

fn measured<K: Kernel>(d: Dist2<Site>) -> Measured {
    match d {
        Dist2::PointPoint(p, q) => Measured::Points(p, q),
        // `a == b` is taken as the point `a`, as by the kernel: two different sites may be one point,
        // so equality is decided exactly (|a − b|² against 0).
        Dist2::PointLine(p, a, b) if a == b || cmp_dist4::<K>(a, b, a, a) == Ordering::Equal => {
            Measured::Points(p, a)
        }
        Dist2::PointLine(p, a, b) => Measured::Perp(p, a, b),
        Dist2::PointSegment(p, a, b) => {
            if dot_sign::<K>(a, p, a, b) != Sign::Positive {
                Measured::Points(p, a)
            } else if dot_sign::<K>(b, p, b, a) != Sign::Positive {
                Measured::Points(p, b)
            } else {
                Measured::Perp(p, a, b)
            }
        }
    }
}

/// [`Kernel::cmp_dist2`] at sites: the two squared distances compared exactly (the same
/// polynomials, degree up to 6 before the crossing points are substituted).
#[must_use]
pub fn cmp_dist2<K: Kernel>(x: Dist2<Site>, y: Dist2<Site>) -> Ordering {
    match (measured::<K>(x), measured::<K>(y)) {
        (Measured::Points(p, q), Measured::Points(r, s)) => cmp_dist4::<K>(p, q, r, s),
        (Measured::Points(p, q), Measured::Perp(r, a, b)) => {
            points_vs_perp::<K>(p, q, r, a, b).to_ordering()
        }
        (Measured::Perp(r, a, b), Measured::Points(p, q)) => {
            points_vs_perp::<K>(p, q, r, a, b).to_ordering().reverse()
        }
        (Measured::Perp(p, a, b), Measured::Perp(q, c, d)) => {
            perp_vs_perp::<K>([p, a, b], [q, c, d]).to_ordering()
        }
    }
}
