//! Exact comparison of the distances from two vertices `q`, `q'` to one *part* of an edge: the row
//! piece of a CVE matrix (Amato 1992, section 3), `{x(t) : t₀ ≤ t ≤ t₁}` on `x(t) = a + t(b − a)`,
//! whose ends are kept symbolic ([`Param`]): the edge's own ends, roots of affine forms (breakpoints,
//! depth switches, shadow points: rational parameters) and ends of the `α ≥ 90°` arc (roots of the
//! quadratic `F(t) = (h − x)·(l − x)`: irrational). No end is ever constructed.
//!
//! The nearest point of the part to `q` is the foot of `q` on the line when the foot lies in the
//! part, else the end on the foot's side: the order of two parameters ([`Edge::cmp`], degree ≤ 6),
//! the foot being the root of `x ↦ (x − q)·(b − a)`. The squared distance is then one of
//!
//! | nearest point | squared distance | degrees |
//! |---|---|---|
//! | `a` or `b` | `|q − a|²` (a kernel [`Dist2`]) | 2 |
//! | the foot | `((b − a) × (q − a))² / A`, `A = |b − a|²` (a kernel [`Dist2`]) | 4 / 2 |
//! | the root `t = N/D` of `g`: `N = g(a)`, `D = g(a) − g(b)` | `S / D²`, `S = |(q − a)D − N(b − a)|²` | 6 / 4 |
//! | the arc end `t = (−B ± √Δ)/2A` | `(X ∓ 2(2P + B)√Δ) / 4A` | 4, 2 / 2 |
//!
//! with `B = (2a − h − l)·(b − a)`, `C = (a − h)·(a − l)`, `Δ = B² − 4AC ≥ 0` (the piece exists only
//! then), `P = (q − a)·(b − a)`, `W = |q − a|²` and `X = 4AW + 4PB + 2B² − 4AC`. (From
//! `|q − x(t)|² = W − 2tP + At²` and `2At = −B ± √Δ`.) Two values are compared by the sign of their
//! difference with the positive denominators cross-multiplied:
//!
//! | comparison | polynomial(s) | degree |
//! |---|---|---|
//! | input against input | the kernel's `cmp_dist2` | ≤ 6 |
//! | rational against `|q' − p|²` | `S − |q' − p|²·D²` | 6 |
//! | rational against the line | `S·A − ((b − a) × (q' − a))²·D²` | 8 |
//! | rational against rational | `S·D'² − S'·D²` | 10 |
//! | arc end against a point, the line or an arc end of the part | `U + V√Δ`: `U`, `V`, `U² − V²Δ` | 4, 2, 8 |
//! | arc end against a rational end | `U + V√Δ`: `U`, `V`, `U² − V²Δ` | 8, 6, 16 |
//!
//! The sign of `U + V√Δ` is `sign U` when `V = 0` or both signs agree, `sign V` when `U = 0` and
//! `Δ > 0`, and otherwise (`U`, `V` of opposite signs) `sign U · sign(U² − V²Δ)`. Every comparison is
//! between two distances to the *same* part, as SMAWK's are (it compares entries of one row): the two
//! arc ends of a part share `(h, l)`, hence `Δ`. Degree 16 is the predicates crate's `MAX_DEGREE`.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Dist2, Kernel, Polynomial, Ring, Sign};

use crate::param::{Affine, Edge, Param, op, pt, quad};
use crate::site::Vertex;

type P2<'a, R> = (&'a R, &'a R);

fn sub<R: Ring>(p: P2<'_, R>, q: P2<'_, R>) -> (R, R) {
    (p.0.sub(q.0), p.1.sub(q.1))
}

fn dot<R: Ring>(u: &(R, R), w: &(R, R)) -> R {
    u.0.mul(&w.0).add(&u.1.mul(&w.1))
}

fn cross<R: Ring>(u: &(R, R), w: &(R, R)) -> R {
    u.0.mul(&w.1).sub(&u.1.mul(&w.0))
}

fn times4<R: Ring>(v: &R) -> R {
    let v2 = v.add(v);
    v2.add(&v2)
}

/// `(S, D²)` for `q` and the root of `g(x) = op(x − c, v1 − v0)` on `(a, b)`.
fn rational<R: Ring>(
    q: P2<'_, R>,
    a: P2<'_, R>,
    b: P2<'_, R>,
    g: [P2<'_, R>; 3],
    cr: bool,
) -> (R, R) {
    let n = op(cr, a, g[0], g[1], g[2]);
    // g(a) − g(b) = op(a − b, v1 − v0).
    let d = op(cr, a, b, g[1], g[2]);
    let (ab, qa) = (sub(b, a), sub(q, a));
    let w = (
        qa.0.mul(&d).sub(&n.mul(&ab.0)),
        qa.1.mul(&d).sub(&n.mul(&ab.1)),
    );
    (dot(&w, &w), d.square())
}

/// `(S, D²)` for the points `[q, a, b, g.c, g.v0, g.v1]` starting at point index `k`.
fn rational_at<R: Ring>(x: &[R], k: usize, cr: bool) -> (R, R) {
    let g = [pt(x, k + 3), pt(x, k + 4), pt(x, k + 5)];
    rational(pt(x, k), pt(x, k + 1), pt(x, k + 2), g, cr)
}

/// `S − |p − r|²·D²`. Inputs `[q, a, b, g.c, g.v0, g.v1, p, r]`. Degree 6.
struct RatVsPoints {
    cr: bool,
}
impl Polynomial<16> for RatVsPoints {
    const DEGREE: u32 = 6;
    fn eval<R: Ring>(&self, x: &[R; 16]) -> R {
        let (s, d2) = rational_at(x, 0, self.cr);
        let pr = sub(pt(x, 6), pt(x, 7));
        s.sub(&dot(&pr, &pr).mul(&d2))
    }
}

/// `S·|b − a|² − ((b − a) × (p − a))²·D²`. Inputs `[q, a, b, g.c, g.v0, g.v1, p]`. Degree 8.
struct RatVsLine {
    cr: bool,
}
impl Polynomial<14> for RatVsLine {
    const DEGREE: u32 = 8;
    fn eval<R: Ring>(&self, x: &[R; 14]) -> R {
        let (s, d2) = rational_at(x, 0, self.cr);
        let (a, b, p) = (pt(x, 1), pt(x, 2), pt(x, 6));
        let ab = sub(b, a);
        s.mul(&dot(&ab, &ab))
            .sub(&cross(&ab, &sub(p, a)).square().mul(&d2))
    }
}

/// `S·D'² − S'·D²`. Inputs `[q, a, b, g.c, g.v0, g.v1, q', a, b, g'.c, g'.v0, g'.v1]`. Degree 10.
struct RatVsRat {
    cr: [bool; 2],
}
impl Polynomial<24> for RatVsRat {
    const DEGREE: u32 = 10;
    fn eval<R: Ring>(&self, x: &[R; 24]) -> R {
        let (s1, d1) = rational_at(x, 0, self.cr[0]);
        let (s2, d2) = rational_at(x, 6, self.cr[1]);
        s1.mul(&d2).sub(&s2.mul(&d1))
    }
}

/// `(X, Y)` with `4A|q − r|² = X + Y√Δ` for the lower (`hi == false`) or upper root `r` of `F`.
/// Points `[a, b, h, l]` at indices 0–3 and `q` at index `k`.
fn arc<R: Ring>(x: &[R], k: usize, hi: bool) -> (R, R) {
    let (aa, bb, cc) = quad(x);
    let e = sub(pt(x, 1), pt(x, 0));
    let qa = sub(pt(x, k), pt(x, 0));
    let (p, w) = (dot(&qa, &e), dot(&qa, &qa));
    let b2 = bb.square();
    let xx = times4(&aa.mul(&w).add(&p.mul(&bb)).sub(&aa.mul(&cc))).add(&b2.add(&b2));
    let y = p.add(&p).add(&bb);
    let y = y.add(&y);
    (xx, if hi { y.neg() } else { y })
}

/// What an arc end's distance is compared with.
#[derive(Clone, Copy, Debug)]
enum Other {
    /// `|q' − p|²`: inputs `q', p` at indices 4–5 (after `q`).
    Point,
    /// `q'`'s distance to the line `(a, b)`: `q'` at index 5.
    Line,
    /// `q'`'s distance to the part's lower (`false`) or upper arc end: `q'` at index 5.
    Arc(bool),
    /// `q'`'s distance to the root of `g` (`cross` flag): `q', g.c, g.v0, g.v1` at indices 5–8.
    Rat(bool),
}

/// Which polynomial of `U + V√Δ`.
#[derive(Clone, Copy, Debug)]
enum Part {
    U,
    V,
    /// `U² − V²Δ`.
    W,
}

/// `U`, `V` or `U² − V²Δ` for `4A·D'²(|q − r|² − d')`, where `r` is an arc end and `d'` the other
/// distance (`D' = 1` unless it is rational). Inputs `[a, b, h, l, q, …]` (see [`Other`]). `DEG`
/// is the degree of the chosen part for the chosen `other` (checked by a test).
struct ArcVs<const DEG: u32> {
    hi: bool,
    other: Other,
    part: Part,
}
impl<const DEG: u32> Polynomial<18> for ArcVs<DEG> {
    const DEGREE: u32 = DEG;
    fn eval<R: Ring>(&self, x: &[R; 18]) -> R {
        let (aa, bb, cc) = quad(x);
        let (x1, y1) = arc(x, 4, self.hi);
        let (u, v) = match self.other {
            Other::Point => {
                let pr = sub(pt(x, 5), pt(x, 6));
                (x1.sub(&times4(&aa.mul(&dot(&pr, &pr)))), y1)
            }
            Other::Line => {
                let (a, b, q2) = (pt(x, 0), pt(x, 1), pt(x, 5));
                let c = cross(&sub(b, a), &sub(q2, a));
                (x1.sub(&times4(&c.square())), y1)
            }
            Other::Arc(hi2) => {
                let (x2, y2) = arc(x, 5, hi2);
                (x1.sub(&x2), y1.sub(&y2))
            }
            Other::Rat(cr) => {
                let g = [pt(x, 6), pt(x, 7), pt(x, 8)];
                let (s, d2) = rational(pt(x, 5), pt(x, 0), pt(x, 1), g, cr);
                (x1.mul(&d2).sub(&times4(&aa.mul(&s))), y1.mul(&d2))
            }
        };
        match self.part {
            Part::U => u,
            Part::V => v,
            Part::W => {
                let four_ac = times4(&aa.mul(&cc));
                u.square().sub(&v.square().mul(&bb.square().sub(&four_ac)))
            }
        }
    }
}

/// `sign(U + V√Δ)` for [`ArcVs`] with the part degrees `DU`, `DV`, `DW`.
fn arc_sign<K: Kernel, V: Vertex, const DU: u32, const DV: u32, const DW: u32>(
    hi: bool,
    other: Other,
    x: [V; 9],
    disc: impl FnOnce() -> Sign,
) -> Sign {
    let su = V::sign::<K, _, 18, 9, 72>(
        &ArcVs::<DU> {
            hi,
            other,
            part: Part::U,
        },
        x,
    );
    let sv = V::sign::<K, _, 18, 9, 72>(
        &ArcVs::<DV> {
            hi,
            other,
            part: Part::V,
        },
        x,
    );
    match (su, sv) {
        (_, Sign::Zero) => su,
        (Sign::Zero, _) => {
            if disc() == Sign::Positive {
                sv
            } else {
                Sign::Zero
            }
        }
        _ if su == sv => su,
        _ => {
            let sw = V::sign::<K, _, 18, 9, 72>(
                &ArcVs::<DW> {
                    hi,
                    other,
                    part: Part::W,
                },
                x,
            );
            if su == Sign::Positive {
                sw
            } else {
                sw.reversed()
            }
        }
    }
}

/// A part of the edge `[a, b]`: the points `x(t)`, `bot ≤ t ≤ top`, of `x(t) = a + t(b − a)`. The
/// row piece of a CVE matrix entry; compared through
/// [`compare_edge_entries`](crate::compare_edge_entries).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgePart<V = DVec2> {
    pub(crate) a: V,
    pub(crate) b: V,
    pub(crate) bot: Param<V>,
    pub(crate) top: Param<V>,
}

/// The point of a part nearest to a vertex, as what its squared distance is.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Val<V> {
    /// An input point (`a` or `b`).
    Point(V),
    /// The foot on the line `(a, b)`.
    Line,
    /// The root of the affine form.
    Rat(Affine<V>),
    /// The lower (`hi == false`) or upper root of `F` for `(h, l)`.
    Arc { h: V, l: V, hi: bool },
}

impl<V: Vertex> EdgePart<V> {
    /// The edge's start `a` (the part lies on `[a, b]`).
    #[must_use]
    pub fn start(&self) -> V {
        self.a
    }

    /// The edge's end `b`.
    #[must_use]
    pub fn end(&self) -> V {
        self.b
    }

    fn edge(&self) -> Edge<V> {
        Edge {
            a: self.a,
            b: self.b,
        }
    }

    /// What the part's nearest point to `q` is: at most two parameter orders.
    fn nearest<K: Kernel>(&self, q: V) -> Val<V> {
        let e = self.edge();
        let foot = Param::Root(Affine {
            cross: false,
            c: q,
            v0: self.a,
            v1: self.b,
            neg: false,
        });
        // The foot against an edge end is one dot sign (the foot form's drop g(a) − g(b) = −|b − a|²
        // is negative, so `Edge::cmp` would spend a test on it).
        let below = |t: &Param<V>| match t {
            Param::Start => V::dot_sign::<K>(self.a, q, self.a, self.b) == Sign::Negative,
            _ => e.cmp::<K>(&foot, t) == Ordering::Less,
        };
        let above = |t: &Param<V>| match t {
            Param::End => V::dot_sign::<K>(self.b, q, self.a, self.b) == Sign::Positive,
            _ => e.cmp::<K>(&foot, t) == Ordering::Greater,
        };
        let end = if below(&self.bot) {
            self.bot
        } else if above(&self.top) {
            self.top
        } else {
            return Val::Line;
        };
        match end {
            Param::Start => Val::Point(self.a),
            Param::End => Val::Point(self.b),
            Param::Root(g) => Val::Rat(g),
            Param::Clip { h, l, hi, .. } => Val::Arc { h, l, hi },
        }
    }

    /// The exact order of `d(q1, part)` and `d(q2, part)`. `O(1)` signs of degree ≤ 16.
    pub(crate) fn cmp_dist<K: Kernel>(&self, q1: V, q2: V) -> Ordering {
        if q1 == q2 {
            return Ordering::Equal;
        }
        let (v1, v2) = (self.nearest::<K>(q1), self.nearest::<K>(q2));
        self.cmp_vals::<K>(q1, v1, q2, v2)
    }

    fn cmp_vals<K: Kernel>(&self, q1: V, v1: Val<V>, q2: V, v2: Val<V>) -> Ordering {
        let (a, b) = (self.a, self.b);
        match (v1, v2) {
            (Val::Rat(g), Val::Point(p)) => {
                let x = [q1, a, b, g.c, g.v0, g.v1, q2, p];
                V::sign::<K, _, 16, 8, 64>(&RatVsPoints { cr: g.cross }, x).to_ordering()
            }
            (Val::Rat(g), Val::Line) => {
                let x = [q1, a, b, g.c, g.v0, g.v1, q2];
                V::sign::<K, _, 14, 7, 56>(&RatVsLine { cr: g.cross }, x).to_ordering()
            }
            (Val::Rat(g), Val::Rat(f)) => {
                let x = [q1, a, b, g.c, g.v0, g.v1, q2, a, b, f.c, f.v0, f.v1];
                V::sign::<K, _, 24, 12, 96>(
                    &RatVsRat {
                        cr: [g.cross, f.cross],
                    },
                    x,
                )
                .to_ordering()
            }
            (Val::Arc { h, l, hi }, other) => {
                let disc = || self.edge().disc::<K>(h, l);
                let (o, rest) = match other {
                    Val::Point(p) => (Other::Point, [q2, p, q2, q2]),
                    Val::Line => (Other::Line, [q2; 4]),
                    Val::Arc { hi: hi2, .. } => (Other::Arc(hi2), [q2; 4]),
                    Val::Rat(g) => (Other::Rat(g.cross), [q2, g.c, g.v0, g.v1]),
                };
                let x = [a, b, h, l, q1, rest[0], rest[1], rest[2], rest[3]];
                let s = if let Other::Rat(_) = o {
                    arc_sign::<K, V, 8, 6, 16>(hi, o, x, disc)
                } else {
                    arc_sign::<K, V, 4, 2, 8>(hi, o, x, disc)
                };
                s.to_ordering()
            }
            (_, Val::Rat(_) | Val::Arc { .. }) => self.cmp_vals::<K>(q2, v2, q1, v1).reverse(),
            (Val::Point(_) | Val::Line, Val::Point(_) | Val::Line) => {
                // Both are input distances here: an edge end or the line.
                let input = |q, v| match v {
                    Val::Point(p) => Dist2::PointPoint(q, p),
                    _ => Dist2::PointLine(q, a, b),
                };
                V::cmp_dist2::<K>(input(q1, v1), input(q2, v2))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::{Exact, Robust};

    fn lattice(rng: &mut SplitMix64) -> DVec2 {
        DVec2::new(rng.range_i64(-40, 40) as f64, rng.range_i64(-40, 40) as f64)
    }

    /// The nearest point of `[x(t0), x(t1)]` to `q`, constructed in `f64`.
    fn nearest_f64(a: DVec2, b: DVec2, t0: f64, t1: f64, q: DVec2) -> DVec2 {
        let e = b - a;
        let t = ((q - a).dot(e) / e.length_squared()).clamp(t0, t1);
        a + e * t
    }

    /// Random parts with every kind of end (edge ends, rational roots, arc ends) and random vertices:
    /// the exact order of two distances against `f64` constructions where the gap is far above
    /// rounding. Covers every pair of value kinds, both ways round.
    #[test]
    fn part_distances_match_constructions() {
        let mut rng = SplitMix64::new(0x0c11);
        let mut checked = [[0usize; 4]; 4];
        for _ in 0..20_000 {
            let (a, b) = (lattice(&mut rng), lattice(&mut rng));
            if a == b {
                continue;
            }
            let e = Edge { a, b };
            let (h, l) = (lattice(&mut rng), lattice(&mut rng));
            // Candidate ends with their f64 parameters.
            let mut ends: Vec<(Param, f64)> = vec![(Param::Start, 0.0), (Param::End, 1.0)];
            let g = Affine {
                cross: rng.coin(),
                c: lattice(&mut rng),
                v0: lattice(&mut rng),
                v1: lattice(&mut rng),
                neg: false,
            };
            let val = |x: DVec2| {
                let (d, w) = (x - g.c, g.v1 - g.v0);
                if g.cross { d.perp_dot(w) } else { d.dot(w) }
            };
            let (ga, gb) = (val(a), val(b));
            if ga != gb {
                let t = ga / (ga - gb);
                if (0.0..=1.0).contains(&t) {
                    ends.push((Param::Root(g), t));
                }
            }
            if e.disc::<Exact>(h, l) == Sign::Positive {
                let ee = b - a;
                let (qa, qb) = (ee.length_squared(), (2.0 * a - h - l).dot(ee));
                let qc = (a - h).dot(a - l);
                let sd = (qb * qb - 4.0 * qa * qc).sqrt();
                for (hi, t) in [
                    (false, (-qb - sd) / (2.0 * qa)),
                    (true, (-qb + sd) / (2.0 * qa)),
                ] {
                    if (0.0..=1.0).contains(&t) {
                        ends.push((Param::Clip { h, l, hi, piece: 0 }, t));
                    }
                }
            }
            let (i, j) = (rng.index(ends.len()), rng.index(ends.len()));
            let ((bot, t0), (top, t1)) = if ends[i].1 <= ends[j].1 {
                (ends[i], ends[j])
            } else {
                (ends[j], ends[i])
            };
            let part = EdgePart { a, b, bot, top };
            let (q1, q2) = (lattice(&mut rng), lattice(&mut rng));
            let d1 = (q1 - nearest_f64(a, b, t0, t1, q1)).length_squared();
            let d2 = (q2 - nearest_f64(a, b, t0, t1, q2)).length_squared();
            if (d1 - d2).abs() <= 1e-6 * d1.max(d2).max(1.0) {
                continue;
            }
            for got in [
                part.cmp_dist::<Exact>(q1, q2),
                part.cmp_dist::<Robust>(q1, q2),
            ] {
                assert_eq!(got, d1.total_cmp(&d2), "{part:?} {q1} {q2}");
            }
            let kind = |v: Val<DVec2>| match v {
                Val::Point(_) => 0,
                Val::Line => 1,
                Val::Rat(_) => 2,
                Val::Arc { .. } => 3,
            };
            let (k1, k2) = (
                kind(part.nearest::<Exact>(q1)),
                kind(part.nearest::<Exact>(q2)),
            );
            checked[k1.min(k2)][k1.max(k2)] += 1;
        }
        for (k1, row) in checked.iter().enumerate() {
            for &n in &row[k1..] {
                assert!(n > 50, "{checked:?}");
            }
        }
    }

    /// Every [`ArcVs`] polynomial is homogeneous of its declared degree: doubling every input (exact
    /// in `f64`) multiplies the value by `2^DEG` exactly.
    #[test]
    fn arc_polynomials_have_their_declared_degrees() {
        fn check<const D: u32>(hi: bool, other: Other, part: Part, x: &[f64; 18]) -> bool {
            let p = ArcVs::<D> { hi, other, part };
            let v = p.eval(x);
            let v2 = p.eval(&x.map(|c| 2.0 * c));
            assert_eq!(v2, v * f64::from(1u32 << D), "{other:?} {part:?}");
            v != 0.0
        }
        let mut rng = SplitMix64::new(5);
        let mut nonzero = 0;
        for _ in 0..50 {
            let x: [f64; 18] = core::array::from_fn(|_| rng.range_i64(-9, 9) as f64);
            for hi in [false, true] {
                for o in [Other::Point, Other::Line, Other::Arc(!hi)] {
                    nonzero += usize::from(check::<4>(hi, o, Part::U, &x));
                    nonzero += usize::from(check::<2>(hi, o, Part::V, &x));
                    nonzero += usize::from(check::<8>(hi, o, Part::W, &x));
                }
                for cr in [false, true] {
                    nonzero += usize::from(check::<8>(hi, Other::Rat(cr), Part::U, &x));
                    nonzero += usize::from(check::<6>(hi, Other::Rat(cr), Part::V, &x));
                    nonzero += usize::from(check::<16>(hi, Other::Rat(cr), Part::W, &x));
                }
            }
        }
        // A test that only ever sees zeros checks nothing.
        assert!(nonzero > 1400, "{nonzero}");
    }
}
