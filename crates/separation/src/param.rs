//! Constructed points on edges, kept symbolic: a point of edge `(a, b)` is a parameter `t` on
//! `a + t(b − a)`, either the root of an affine function of the point (rational, degree 2/2) or an
//! end of the arc where `α ≥ 90°` (a root of the quadratic `F(t) = (h − x)·(l − x)`, irrational).
//! Every question about such a point is the sign of a polynomial in the input coordinates:
//!
//! | question | polynomial | degree |
//! |---|---|---|
//! | sign of an affine `g` at an edge end | `dot_sign` / `cross_sign` | 2 |
//! | sign of `g` at the root of `f`, order of two roots | `f(a)g(b) − f(b)g(a)` ([`RootPair`]) | 4 |
//! | discriminant of `F` | `B² − 4AC` ([`Disc`]) | 4 |
//! | `F` at the root of `g` | `A N² + B N D + C D²` ([`QuadAtRoot`]), `N = g(a)`, `D = g(a) − g(b)` | 6 |
//! | root of `g` against the vertex `−B/2A` of `F` | `2AN + BD` ([`VertexSide`]) | 4 |

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Polynomial, Ring, Sign};

use crate::site::Vertex;

/// `g(x) = ±op(x − c, v1 − v0)` with `op` the cross (`cross == true`) or dot product: an affine
/// function of the point `x` whose coefficients are input points. Degree 2 in the inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Affine<V = DVec2> {
    pub(crate) cross: bool,
    pub(crate) c: V,
    pub(crate) v0: V,
    pub(crate) v1: V,
    /// Negate the value (roots are unchanged).
    pub(crate) neg: bool,
}

impl<V: Vertex> Affine<V> {
    /// `true` when both are the same function up to sign (hence have the same root): a structural
    /// shortcut that spares an exact evaluation of a polynomial that is identically zero.
    fn same_root(&self, other: &Affine<V>) -> bool {
        self.cross == other.cross && self.c == other.c && self.v0 == other.v0 && self.v1 == other.v1
    }

    /// The form with the opposite sign.
    pub(crate) fn negated(self) -> Affine<V> {
        Affine {
            neg: !self.neg,
            ..self
        }
    }

    fn raw_at<K: Kernel>(&self, x: V) -> Sign {
        // Structural zeros (x − c = 0, v1 − v0 = 0, or x − c = v1 − v0 for a cross product) are
        // decided here: an exact zero is the one case the Robust filter cannot certify.
        if x == self.c || self.v0 == self.v1 || (self.cross && self.c == self.v0 && x == self.v1) {
            return Sign::Zero;
        }
        if self.cross {
            V::cross_sign::<K>(self.c, x, self.v0, self.v1)
        } else {
            V::dot_sign::<K>(self.c, x, self.v0, self.v1)
        }
    }

    /// `sign(g(a) − g(b))` without the negation: `op(a − b, v1 − v0)`.
    fn raw_drop<K: Kernel>(&self, a: V, b: V) -> Sign {
        if a == b || self.v0 == self.v1 {
            return Sign::Zero;
        }
        if self.cross {
            V::cross_sign::<K>(b, a, self.v0, self.v1)
        } else {
            V::dot_sign::<K>(b, a, self.v0, self.v1)
        }
    }
}

/// `op(x − c, w1 − w0)` in a ring.
#[inline(always)]
pub(crate) fn op<R: Ring>(cross: bool, x: (&R, &R), c: (&R, &R), w0: (&R, &R), w1: (&R, &R)) -> R {
    let (dx, dy) = (x.0.sub(c.0), x.1.sub(c.1));
    let (ex, ey) = (w1.0.sub(w0.0), w1.1.sub(w0.1));
    if cross {
        dx.mul(&ey).sub(&dy.mul(&ex))
    } else {
        dx.mul(&ex).add(&dy.mul(&ey))
    }
}

#[inline(always)]
pub(crate) fn pt<R>(x: &[R], i: usize) -> (&R, &R) {
    (&x[2 * i], &x[2 * i + 1])
}

/// `f(a)g(b) − f(b)g(a)` for two raw affine forms. Inputs `[a, b, f.c, f.v0, f.v1, g.c, g.v0, g.v1]`.
/// Degree 4.
pub(crate) struct RootPair {
    pub(crate) f_cross: bool,
    pub(crate) g_cross: bool,
}
impl Polynomial<16> for RootPair {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 16]) -> R {
        let (a, b) = (pt(x, 0), pt(x, 1));
        let f = |p| op(self.f_cross, p, pt(x, 2), pt(x, 3), pt(x, 4));
        let g = |p| op(self.g_cross, p, pt(x, 5), pt(x, 6), pt(x, 7));
        f(a).mul(&g(b)).sub(&f(b).mul(&g(a)))
    }
}

/// The coefficients of `F(t) = (h − x(t))·(l − x(t))`, `x(t) = a + t(b − a)`, in a ring:
/// `A = |b − a|²`, `B = (2a − h − l)·(b − a)`, `C = (a − h)·(a − l)`. Points `[a, b, h, l]` first.
#[inline(always)]
pub(crate) fn quad<R: Ring>(x: &[R]) -> (R, R, R) {
    let (a, b, h, l) = (pt(x, 0), pt(x, 1), pt(x, 2), pt(x, 3));
    let (ex, ey) = (b.0.sub(a.0), b.1.sub(a.1));
    let aa = ex.square().add(&ey.square());
    let bx = a.0.add(a.0).sub(h.0).sub(l.0);
    let by = a.1.add(a.1).sub(h.1).sub(l.1);
    let bb = bx.mul(&ex).add(&by.mul(&ey));
    let cc =
        a.0.sub(h.0)
            .mul(&a.0.sub(l.0))
            .add(&a.1.sub(h.1).mul(&a.1.sub(l.1)));
    (aa, bb, cc)
}

/// `B² − 4AC`. Inputs `[a, b, h, l]`. Degree 4.
pub(crate) struct Disc;
impl Polynomial<8> for Disc {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (aa, bb, cc) = quad(x);
        let four_ac = aa.mul(&cc);
        let four_ac = four_ac.add(&four_ac);
        bb.square().sub(&four_ac.add(&four_ac))
    }
}

/// `A N² + B N D + C D²` with `N = g(a)`, `D = g(a) − g(b)`: `F` at the root of `g`, times `D²`.
/// Inputs `[a, b, h, l, g.c, g.v0, g.v1]`. Degree 6.
pub(crate) struct QuadAtRoot {
    pub(crate) g_cross: bool,
}
impl Polynomial<14> for QuadAtRoot {
    const DEGREE: u32 = 6;
    fn eval<R: Ring>(&self, x: &[R; 14]) -> R {
        let (aa, bb, cc) = quad(x);
        let g = |p| op(self.g_cross, p, pt(x, 4), pt(x, 5), pt(x, 6));
        let n = g(pt(x, 0));
        let d = n.sub(&g(pt(x, 1)));
        aa.mul(&n.square())
            .add(&bb.mul(&n).mul(&d))
            .add(&cc.mul(&d.square()))
    }
}

/// `2AN + BD`: the root `N/D` of `g` against the vertex `−B/2A` of `F` (times `2AD`).
/// Inputs as [`QuadAtRoot`]. Degree 4.
pub(crate) struct VertexSide {
    pub(crate) g_cross: bool,
}
impl Polynomial<14> for VertexSide {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 14]) -> R {
        let (aa, bb, _) = quad(x);
        let g = |p| op(self.g_cross, p, pt(x, 4), pt(x, 5), pt(x, 6));
        let n = g(pt(x, 0));
        let d = n.sub(&g(pt(x, 1)));
        let an = aa.mul(&n);
        an.add(&an).add(&bb.mul(&d))
    }
}

/// `(2x − h − l)·(b − a)`: `B` for `x = a`, `2A + B` for `x = b` (the side of the vertex of `F`
/// an edge end is on). Inputs `[x, h, l, a, b]`. Degree 2.
pub(crate) struct EndSide;
impl Polynomial<10> for EndSide {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 10]) -> R {
        let (p, h, l, a, b) = (pt(x, 0), pt(x, 1), pt(x, 2), pt(x, 3), pt(x, 4));
        let sx = p.0.add(p.0).sub(h.0).sub(l.0);
        let sy = p.1.add(p.1).sub(h.1).sub(l.1);
        sx.mul(&b.0.sub(a.0)).add(&sy.mul(&b.1.sub(a.1)))
    }
}

/// A parameter on an edge `(a, b)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Param<V = DVec2> {
    /// `t = 0`, the edge's start `a`.
    Start,
    /// `t = 1`, the edge's end `b`.
    End,
    /// The root of the affine form (`f(a) ≠ f(b)`).
    Root(Affine<V>),
    /// The lower (`hi == false`) or upper root of `F` for the tangent points `h`, `l`; always
    /// strictly inside the rational range of its piece `piece`.
    Clip { h: V, l: V, hi: bool, piece: usize },
}

/// A point of an edge `(a, b)` of one chain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EdgePoint<V = DVec2> {
    /// The edge: from vertex `edge` to vertex `edge + 1` of the prepared chain.
    pub(crate) edge: usize,
    pub(crate) param: Param<V>,
}

/// Exact geometry of one edge `(a, b)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge<V = DVec2> {
    pub(crate) a: V,
    pub(crate) b: V,
}

/// `16u = 2⁻⁴⁹`: [`root_pair_filter`]'s error constant.
const ROOT_PAIR_ERR: f64 = 1.0 / 562_949_953_421_312.0;
/// `2⁻⁴⁸⁰` and `2⁴⁸⁰`: the magnitudes [`root_pair_filter`] accepts (no overflow, and underflow
/// only far below its slack).
const ROOT_PAIR_LO: f64 = f64::from_bits((1023 - 480) << 52);
const ROOT_PAIR_HI: f64 = f64::from_bits((1023 + 480) << 52);

/// A static filter for the sign of `E = f(a)g(b) − f(b)g(a)` ([`RootPair`]), in plain `f64`: the
/// value `r` and the magnitude `M = F(a)G(b) + F(b)G(a)`, where `F(p) = |t₁| + |t₂|` for the two
/// rounded products `t₁, t₂` whose difference is `f(p)` (and `G` for `g`). `Some(sign)` when
/// `|r| > 16u·M`, certain; `None` (the kernel decides) otherwise, or when some `F`, `G` lies outside
/// `[2⁻⁴⁸⁰, 2⁴⁸⁰]`.
///
/// Why `16u` suffices (`u = 2⁻⁵³`; `docs/ROBUSTNESS.md` has the general pattern): each product of two
/// rounded differences is within `γ₃ = (1 + u)³ − 1` of the exact one, relatively, so the rounded
/// `f(p)` is within `α·F(p)`, `α = (γ₃/(1 − γ₃) + u)/(1 − u) ≤ 4u + 20u²`, and `|f(p)| ≤ (1 + α)F(p)`
/// (the rounded `|t₁ ± t₂|` never exceeds the rounded `|t₁| + |t₂|`). A rounded product `f(a)g(b)` is
/// then within `(2α + α² + u)·F(a)G(b)` of the exact one, and the final difference adds
/// `u(1 + u)·M`: in all `|r − E| ≤ (10u + 57u²)·M`. The computed `M` is at least `(1 − 2u)` of the
/// exact one, so `16u·M̂` exceeds the error. Underflow: every `F`, `G` is at least `2⁻⁴⁸⁰`, so `M` is
/// at least `2⁻⁹⁶⁰` and the at most few absolute errors of `2⁻¹⁰⁷⁴` from an underflowing product are
/// below `2⁻⁵⁹⁰·M`, inside the slack `(16u(1 − 2u) − 10.1u)·M`. Overflow: every magnitude is at most
/// `2⁴⁸⁰`, so no product exceeds `2⁹⁶¹`; a non-finite `F` fails the range test.
#[inline]
fn root_pair_filter(a: DVec2, b: DVec2, f: &Affine, g: &Affine) -> Option<Sign> {
    let form = |p: DVec2, h: &Affine| {
        let (dx, dy) = (p.x - h.c.x, p.y - h.c.y);
        let (ex, ey) = (h.v1.x - h.v0.x, h.v1.y - h.v0.y);
        let (t1, t2) = if h.cross {
            (dx * ey, dy * ex)
        } else {
            (dx * ex, -(dy * ey))
        };
        (t1 - t2, t1.abs() + t2.abs())
    };
    let ((fa, fam), (fb, fbm)) = (form(a, f), form(b, f));
    let ((ga, gam), (gb, gbm)) = (form(a, g), form(b, g));
    let ok = |m: f64| (ROOT_PAIR_LO..=ROOT_PAIR_HI).contains(&m);
    if !(ok(fam) && ok(fbm) && ok(gam) && ok(gbm)) {
        return None;
    }
    let r = fa * gb - fb * ga;
    let m = fam * gbm + fbm * gam;
    (r.abs() > ROOT_PAIR_ERR * m).then(|| Sign::of_f64(r))
}

/// The edge and the two forms with input points, when every point is one.
#[inline(always)]
fn input_affines<V: Vertex>(
    e: &Edge<V>,
    f: &Affine<V>,
    g: &Affine<V>,
) -> Option<(Edge, Affine, Affine)> {
    let form = |h: &Affine<V>| {
        Some(Affine {
            cross: h.cross,
            c: h.c.as_input()?,
            v0: h.v0.as_input()?,
            v1: h.v1.as_input()?,
            neg: h.neg,
        })
    };
    let edge = Edge {
        a: e.a.as_input()?,
        b: e.b.as_input()?,
    };
    Some((edge, form(f)?, form(g)?))
}

impl<V: Vertex> Edge<V> {
    /// `sign(f(a)g(b) − f(b)g(a))` (raw forms). Under the exact kernels [`root_pair_filter`] first
    /// (on input points).
    fn root_pair<K: Kernel>(&self, f: &Affine<V>, g: &Affine<V>) -> Sign {
        if K::EXACT_DECISIONS && V::INPUT {
            if let Some(s) =
                input_affines(self, f, g).and_then(|(e, f, g)| root_pair_filter(e.a, e.b, &f, &g))
            {
                return s;
            }
        }
        V::sign::<K, _, 16, 8, 64>(
            &RootPair {
                f_cross: f.cross,
                g_cross: g.cross,
            },
            [self.a, self.b, f.c, f.v0, f.v1, g.c, g.v0, g.v1],
        )
    }

    /// Where the root of `g` lies relative to the roots `r1 ≤ r2` of `F` for `(h, l)`, which must
    /// exist (`B² − 4AC ≥ 0`): the orders `(root vs r1, root vs r2)`.
    fn against_arc<K: Kernel>(&self, g: &Affine<V>, h: V, l: V) -> (Ordering, Ordering) {
        let x = [self.a, self.b, h, l, g.c, g.v0, g.v1];
        let fv = V::sign::<K, _, 14, 7, 56>(&QuadAtRoot { g_cross: g.cross }, x);
        // sign(root − vertex) = sign(2AN + BD) · sign(D).
        let side = V::sign::<K, _, 14, 7, 56>(&VertexSide { g_cross: g.cross }, x);
        let d = g.raw_drop::<K>(self.a, self.b);
        let vs = if d == Sign::Negative {
            side.reversed()
        } else {
            side
        };
        arc_position(fv, vs)
    }

    /// [`Self::against_arc`], but a root that is exactly an edge end is placed by the degree-2 end
    /// test: at an end that is also a tangent point, `F` vanishes exactly there and the degree-6
    /// test would need exact arithmetic.
    fn root_against_arc<K: Kernel>(&self, g: &Affine<V>, h: V, l: V) -> (Ordering, Ordering) {
        if g.raw_at::<K>(self.a) == Sign::Zero {
            self.end_against_arc::<K>(false, h, l)
        } else if g.raw_at::<K>(self.b) == Sign::Zero {
            self.end_against_arc::<K>(true, h, l)
        } else {
            self.against_arc::<K>(g, h, l)
        }
    }

    /// [`Self::against_arc`] for the edge's start (`at_end == false`) or end.
    fn end_against_arc<K: Kernel>(&self, at_end: bool, h: V, l: V) -> (Ordering, Ordering) {
        let x = if at_end { self.b } else { self.a };
        // F(x) = (h − x)·(l − x); the side of the vertex: sign(B) at a, sign(2A + B) at b.
        // At a tangent point (`x` is `h` or `l`, the rule on a star's spikes) `F(x)` is exactly zero:
        // said without the kernel, whose filter cannot certify a zero (Robust would pay its exact
        // stage).
        let fv = if x == h || x == l {
            Sign::Zero
        } else {
            V::dot_sign::<K>(x, h, x, l)
        };
        let vs = V::sign::<K, _, 10, 5, 40>(&EndSide, [x, h, l, self.a, self.b]);
        arc_position(fv, vs)
    }
}

/// A parameter's place relative to the roots `r1 ≤ r2` of `F` from `sign(F(t))` and
/// `sign(t − vertex)`: `(t vs r1, t vs r2)`.
fn arc_position(fv: Sign, vs: Sign) -> (Ordering, Ordering) {
    match (fv, vs) {
        (Sign::Negative, _) => (Ordering::Greater, Ordering::Less),
        (Sign::Zero, Sign::Negative) => (Ordering::Equal, Ordering::Less),
        (Sign::Zero, Sign::Positive) => (Ordering::Greater, Ordering::Equal),
        (Sign::Zero, Sign::Zero) => (Ordering::Equal, Ordering::Equal),
        (Sign::Positive, Sign::Negative) => (Ordering::Less, Ordering::Less),
        // F > 0 at the vertex would mean no real roots; the caller checked B² − 4AC ≥ 0.
        (Sign::Positive, _) => (Ordering::Greater, Ordering::Greater),
    }
}

impl<V: Vertex> Edge<V> {
    /// `sign(B² − 4AC)` for the tangent points `(h, l)`.
    pub(crate) fn disc<K: Kernel>(&self, h: V, l: V) -> Sign {
        V::sign::<K, _, 8, 4, 32>(&Disc, [self.a, self.b, h, l])
    }

    /// `sign(g(x))` at the point with parameter `t` on this edge.
    pub(crate) fn eval<K: Kernel>(&self, g: &Affine<V>, t: &Param<V>) -> Sign {
        let raw = match t {
            Param::Start => g.raw_at::<K>(self.a),
            Param::End => g.raw_at::<K>(self.b),
            Param::Root(f) if f.same_root(g) => Sign::Zero,
            Param::Root(f) => {
                // g at the root of f: (f(a)g(b) − f(b)g(a)) / (f(a) − f(b)).
                let s = self.root_pair::<K>(f, g);
                if f.raw_drop::<K>(self.a, self.b) == Sign::Negative {
                    s.reversed()
                } else {
                    s
                }
            }
            Param::Clip { h, l, hi, .. } => {
                let d = g.raw_drop::<K>(self.a, self.b);
                if d == Sign::Zero {
                    g.raw_at::<K>(self.a)
                } else {
                    // g(t) = D (root_g − t): sign(D) · sign(root_g − r).
                    let (v1, v2) = self.root_against_arc::<K>(g, *h, *l);
                    let o = if *hi { v2 } else { v1 };
                    let s = Sign::from_ordering(o);
                    if d == Sign::Negative { s.reversed() } else { s }
                }
            }
        };
        if g.neg { raw.reversed() } else { raw }
    }

    /// [`Self::eval`] at a parameter that lies on the closed edge (every piece end, envelope range
    /// end and chain point does, every arc end too; the feet and the separator's lines do not): when
    /// `g` has one strict sign at both ends it has that sign on the whole edge (it is affine), so a
    /// root or an arc end is placed by two degree-2 signs instead of the degree-4 root comparison or
    /// the degree-6 arc placement.
    pub(crate) fn eval_within<K: Kernel>(&self, g: &Affine<V>, t: &Param<V>) -> Sign {
        let placed = match t {
            Param::Root(f) => !f.same_root(g),
            Param::Clip { .. } => true,
            Param::Start | Param::End => false,
        };
        if placed {
            let ends = (g.raw_at::<K>(self.a), g.raw_at::<K>(self.b));
            self.eval_given_ends::<K>(g, t, ends)
        } else {
            self.eval::<K>(g, t)
        }
    }

    /// [`Self::eval_within`] at two parameters of the closed edge, sharing the two degree-2 signs
    /// of `g` at the edge's ends: when they agree strictly, both answers are that sign with no
    /// further test (the pattern of every admissibility test and every piece split, which ask `g`
    /// at both ends of a piece).
    pub(crate) fn eval_pair_within<K: Kernel>(
        &self,
        g: &Affine<V>,
        s: &Param<V>,
        t: &Param<V>,
    ) -> (Sign, Sign) {
        let ends = (g.raw_at::<K>(self.a), g.raw_at::<K>(self.b));
        (
            self.eval_given_ends::<K>(g, s, ends),
            self.eval_given_ends::<K>(g, t, ends),
        )
    }

    /// [`Self::eval`] at a parameter of the closed edge, given `g`'s raw signs at the edge's ends:
    /// the one place of the rule that a strict sign shared by both ends holds on the whole edge.
    fn eval_given_ends<K: Kernel>(
        &self,
        g: &Affine<V>,
        t: &Param<V>,
        (ga, gb): (Sign, Sign),
    ) -> Sign {
        let raw = match t {
            Param::Start => ga,
            Param::End => gb,
            Param::Root(f) if f.same_root(g) => Sign::Zero,
            _ if ga != Sign::Zero && ga == gb => ga,
            // `eval` applies the negation itself.
            _ => return self.eval::<K>(g, t),
        };
        if g.neg { raw.reversed() } else { raw }
    }

    /// `sign(root_f − e)` for the edge end `e` (start: `t = 0`, end: `t = 1`): `sign(f(e)) ·
    /// sign(f(a) − f(b))`, negated for the start (degree 2).
    fn root_vs_end<K: Kernel>(&self, f: &Affine<V>, at_end: bool) -> Ordering {
        let fe = f.raw_at::<K>(if at_end { self.b } else { self.a });
        let d = f.raw_drop::<K>(self.a, self.b);
        // root − 0 = f(a)/D; root − 1 = f(b)/D.
        let s = if d == Sign::Negative {
            fe.reversed()
        } else {
            fe
        };
        s.to_ordering()
    }

    /// Compares two parameters on this edge (`Less`: `s` nearer to `a`).
    pub(crate) fn cmp<K: Kernel>(&self, s: &Param<V>, t: &Param<V>) -> Ordering {
        use Param::{Clip, End, Root, Start};
        match (s, t) {
            (Start, Start) | (End, End) => Ordering::Equal,
            (Start, End) => Ordering::Less,
            (End, Start) => Ordering::Greater,
            (Root(f), Start) => self.root_vs_end::<K>(f, false),
            (Root(f), End) => self.root_vs_end::<K>(f, true),
            (Start | End, Root(_)) => self.cmp::<K>(t, s).reverse(),
            (Start | End, Clip { h, l, hi, .. }) => {
                let (v1, v2) = self.end_against_arc::<K>(matches!(s, End), *h, *l);
                if *hi { v2 } else { v1 }
            }
            (Clip { .. }, Start | End) => self.cmp::<K>(t, s).reverse(),
            (Root(f), Root(g)) if f.same_root(g) => Ordering::Equal,
            (Root(f), Root(g)) => {
                // root_f − root_g = (g(a)f(b) − f(a)g(b)) / ((f(a) − f(b))(g(a) − g(b))).
                let mut r = self.root_pair::<K>(f, g).reversed();
                if f.raw_drop::<K>(self.a, self.b) == Sign::Negative {
                    r = r.reversed();
                }
                if g.raw_drop::<K>(self.a, self.b) == Sign::Negative {
                    r = r.reversed();
                }
                r.to_ordering()
            }
            (Root(f), Clip { h, l, hi, .. }) => {
                let (v1, v2) = self.root_against_arc::<K>(f, *h, *l);
                if *hi { v2 } else { v1 }
            }
            (Clip { .. }, Root(_)) => self.cmp::<K>(t, s).reverse(),
            (
                Clip {
                    h, l, hi, piece, ..
                },
                Clip {
                    hi: hi2,
                    piece: piece2,
                    ..
                },
            ) => {
                if piece != piece2 {
                    piece.cmp(piece2)
                } else if hi == hi2 || self.disc::<K>(*h, *l) == Sign::Zero {
                    Ordering::Equal
                } else {
                    hi.cmp(hi2)
                }
            }
        }
    }

    /// `(t vs r1, t vs r2)` for the roots `r1 ≤ r2` of `F` for `(h, l)` (which must exist): both
    /// orders from one placement, where two [`Self::cmp`] calls would place `t` twice.
    pub(crate) fn against_arc_ends<K: Kernel>(
        &self,
        t: &Param<V>,
        h: V,
        l: V,
        piece: usize,
    ) -> (Ordering, Ordering) {
        match t {
            Param::Start => self.end_against_arc::<K>(false, h, l),
            Param::End => self.end_against_arc::<K>(true, h, l),
            Param::Root(f) => self.root_against_arc::<K>(f, h, l),
            Param::Clip { .. } => {
                let end = |hi| Param::Clip { h, l, hi, piece };
                (self.cmp::<K>(t, &end(false)), self.cmp::<K>(t, &end(true)))
            }
        }
    }

    /// `true` when `t` is exactly the start (`at_end == false`) or the end of the edge.
    pub(crate) fn is_end<K: Kernel>(&self, t: &Param<V>, at_end: bool) -> bool {
        match t {
            Param::Start => !at_end,
            Param::End => at_end,
            Param::Root(f) => f.raw_at::<K>(if at_end { self.b } else { self.a }) == Sign::Zero,
            Param::Clip { .. } => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_polygon::predicates::Exact;

    fn flat<const N: usize>(pts: &[DVec2]) -> [f64; N] {
        core::array::from_fn(|i| {
            if i % 2 == 0 {
                pts[i / 2].x
            } else {
                pts[i / 2].y
            }
        })
    }

    /// The static filter of [`RootPair`] never disagrees with the exact sign, and certifies most
    /// calls: on random forms over points of every scale, on lattice points (exact zeros and near
    /// ties galore) and on points one ulp off a lattice.
    #[test]
    fn root_pair_filter_agrees_with_the_exact_sign() {
        let mut rng = SplitMix64::new(0x2007_f11e);
        let (mut certified, mut calls, mut zeros) = (0, 0, 0);
        for round in 0..60_000 {
            let class = round % 3;
            let scale = 2f64.powi(rng.index(80) as i32 - 40);
            let mut pt = || match class {
                0 => DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5) * scale,
                1 => DVec2::new(rng.index(7) as f64, rng.index(7) as f64) * scale,
                _ => {
                    let v = DVec2::new(rng.index(7) as f64, rng.index(7) as f64) * scale;
                    DVec2::new(v.x.next_up(), v.y)
                }
            };
            let (a, b) = (pt(), pt());
            let f = Affine {
                cross: round % 2 == 0,
                c: pt(),
                v0: pt(),
                v1: pt(),
                neg: false,
            };
            let g = Affine {
                cross: round % 5 < 2,
                c: pt(),
                v0: pt(),
                v1: pt(),
                neg: false,
            };
            let x: [f64; 16] = flat(&[a, b, f.c, f.v0, f.v1, g.c, g.v0, g.v1]);
            let exact = Exact::sign(
                &RootPair {
                    f_cross: f.cross,
                    g_cross: g.cross,
                },
                &x,
            );
            calls += 1;
            zeros += usize::from(exact == Sign::Zero);
            if let Some(s) = root_pair_filter(a, b, &f, &g) {
                certified += 1;
                assert_eq!(s, exact, "a {a:?} b {b:?} f {f:?} g {g:?}");
            }
        }
        assert!(zeros > 1_000, "{zeros} exact zeros");
        assert!(certified * 2 > calls, "{certified} of {calls} certified");
    }
}
