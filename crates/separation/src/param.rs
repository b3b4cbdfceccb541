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

/// `g(x) = ±op(x − c, v1 − v0)` with `op` the cross (`cross == true`) or dot product: an affine
/// function of the point `x` whose coefficients are input points. Degree 2 in the inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Affine {
    pub(crate) cross: bool,
    pub(crate) c: DVec2,
    pub(crate) v0: DVec2,
    pub(crate) v1: DVec2,
    /// Negate the value (roots are unchanged).
    pub(crate) neg: bool,
}

impl Affine {
    /// The form with the opposite sign.
    pub(crate) fn negated(self) -> Affine {
        Affine {
            neg: !self.neg,
            ..self
        }
    }

    fn raw_at<K: Kernel>(&self, x: DVec2) -> Sign {
        if self.cross {
            K::cross_sign(self.c, x, self.v0, self.v1)
        } else {
            K::dot_sign(self.c, x, self.v0, self.v1)
        }
    }

    /// `sign(g(a) − g(b))` without the negation: `op(a − b, v1 − v0)`.
    fn raw_drop<K: Kernel>(&self, a: DVec2, b: DVec2) -> Sign {
        if self.cross {
            K::cross_sign(b, a, self.v0, self.v1)
        } else {
            K::dot_sign(b, a, self.v0, self.v1)
        }
    }
}

/// `op(x − c, w1 − w0)` in a ring.
fn op<R: Ring>(cross: bool, x: (&R, &R), c: (&R, &R), w0: (&R, &R), w1: (&R, &R)) -> R {
    let (dx, dy) = (x.0.sub(c.0), x.1.sub(c.1));
    let (ex, ey) = (w1.0.sub(w0.0), w1.1.sub(w0.1));
    if cross {
        dx.mul(&ey).sub(&dy.mul(&ex))
    } else {
        dx.mul(&ex).add(&dy.mul(&ey))
    }
}

fn pt<R>(x: &[R], i: usize) -> (&R, &R) {
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
fn quad<R: Ring>(x: &[R]) -> (R, R, R) {
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

fn flat<const N: usize>(pts: &[DVec2]) -> [f64; N] {
    core::array::from_fn(|i| {
        if i % 2 == 0 {
            pts[i / 2].x
        } else {
            pts[i / 2].y
        }
    })
}

/// A parameter on an edge `(a, b)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Param {
    /// The root of the affine form (`f(a) ≠ f(b)`).
    Root(Affine),
    /// The lower (`hi == false`) or upper root of `F` for the tangent points `h`, `l`; always
    /// strictly inside the rational range of its piece `piece`.
    Clip {
        h: DVec2,
        l: DVec2,
        hi: bool,
        piece: usize,
    },
}

/// A point of an edge `(a, b)` of one chain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EdgePoint {
    /// The edge: from vertex `edge` to vertex `edge + 1` of the prepared chain.
    pub(crate) edge: usize,
    pub(crate) param: Param,
}

/// The edge's start `t = 0`: the root of `(x − a)·(b − a)`.
pub(crate) fn start(a: DVec2, b: DVec2) -> Param {
    Param::Root(Affine {
        cross: false,
        c: a,
        v0: a,
        v1: b,
        neg: false,
    })
}

/// The edge's end `t = 1`: the root of `(x − b)·(b − a)`.
pub(crate) fn end(a: DVec2, b: DVec2) -> Param {
    Param::Root(Affine {
        cross: false,
        c: b,
        v0: a,
        v1: b,
        neg: false,
    })
}

/// Exact geometry of one edge `(a, b)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge {
    pub(crate) a: DVec2,
    pub(crate) b: DVec2,
}

impl Edge {
    /// `sign(f(a)g(b) − f(b)g(a))` (raw forms).
    fn root_pair<K: Kernel>(&self, f: &Affine, g: &Affine) -> Sign {
        let x: [f64; 16] = flat(&[self.a, self.b, f.c, f.v0, f.v1, g.c, g.v0, g.v1]);
        K::sign(
            &RootPair {
                f_cross: f.cross,
                g_cross: g.cross,
            },
            &x,
        )
    }

    /// Where the root of `g` lies relative to the roots `r1 ≤ r2` of `F` for `(h, l)`, which must
    /// exist (`B² − 4AC ≥ 0`): the orders `(root vs r1, root vs r2)`.
    fn against_arc<K: Kernel>(&self, g: &Affine, h: DVec2, l: DVec2) -> (Ordering, Ordering) {
        let x: [f64; 14] = flat(&[self.a, self.b, h, l, g.c, g.v0, g.v1]);
        let fv = K::sign(&QuadAtRoot { g_cross: g.cross }, &x);
        // sign(root − vertex) = sign(2AN + BD) · sign(D).
        let side = K::sign(&VertexSide { g_cross: g.cross }, &x);
        let d = g.raw_drop::<K>(self.a, self.b);
        let vs = if d == Sign::Negative {
            side.reversed()
        } else {
            side
        };
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

    /// `sign(B² − 4AC)` for the tangent points `(h, l)`.
    pub(crate) fn disc<K: Kernel>(&self, h: DVec2, l: DVec2) -> Sign {
        K::sign(&Disc, &flat::<8>(&[self.a, self.b, h, l]))
    }

    /// `sign(g(x))` at the point with parameter `t` on this edge.
    pub(crate) fn eval<K: Kernel>(&self, g: &Affine, t: &Param) -> Sign {
        let raw = match t {
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
                    let (v1, v2) = self.against_arc::<K>(g, *h, *l);
                    let o = if *hi { v2 } else { v1 };
                    let s = Sign::from_ordering(o);
                    if d == Sign::Negative { s.reversed() } else { s }
                }
            }
        };
        if g.neg { raw.reversed() } else { raw }
    }

    /// Compares two parameters on this edge (`Less`: `s` nearer to `a`).
    pub(crate) fn cmp<K: Kernel>(&self, s: &Param, t: &Param) -> Ordering {
        match (s, t) {
            (Param::Root(f), Param::Root(g)) => {
                // root_f − root_g = (g(a)f(b) − f(a)g(b)) / ((f(a) − f(b))(g(a) − g(b))).
                let num = self.root_pair::<K>(f, g).reversed();
                let mut s = num;
                if f.raw_drop::<K>(self.a, self.b) == Sign::Negative {
                    s = s.reversed();
                }
                if g.raw_drop::<K>(self.a, self.b) == Sign::Negative {
                    s = s.reversed();
                }
                s.to_ordering()
            }
            (Param::Root(f), Param::Clip { h, l, hi, .. }) => {
                let (v1, v2) = self.against_arc::<K>(f, *h, *l);
                if *hi { v2 } else { v1 }
            }
            (Param::Clip { .. }, Param::Root(_)) => self.cmp::<K>(t, s).reverse(),
            (
                Param::Clip {
                    h, l, hi, piece, ..
                },
                Param::Clip {
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

    /// `true` when `t` is exactly the start (`at_end == false`) or the end of the edge.
    pub(crate) fn is_end<K: Kernel>(&self, t: &Param, at_end: bool) -> bool {
        let e = if at_end {
            end(self.a, self.b)
        } else {
            start(self.a, self.b)
        };
        matches!(t, Param::Root(_)) && self.cmp::<K>(t, &e) == Ordering::Equal
    }
}
