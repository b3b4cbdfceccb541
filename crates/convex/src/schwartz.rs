//! Schwartz (1981): the `O(log² N)` distance by binary search on the implicit Minkowski difference
//! `Z = P ⊖ Q = P + (−Q)`, never formed.
//!
//! Paper: J. T. Schwartz, "Finding the minimum distance between two convex polygons", Inf. Proc.
//! Letters 13, 1981, section 2 (steps (i)–(v)); design notes §6.
//!
//! # The implicit polygon
//! A vertex of `Z` is `z_{i,j} = p_i − q_j`. Walking `Z`'s boundary counter-clockwise is a monotone
//! lattice path in `(i, j)`: a step `i → i + 1` is edge `i` of `P` translated by the corner `−q_j`, a
//! step `j → j + 1` is edge `j` of `−Q` (from `−q_j` to `−q_{j+1}`) translated by `p_i`. The edges are
//! merged by angle, ties `P` first. A side of `Z` is known by its source edge and its *matching corner*
//! (the vertex of the other polygon extreme in the edge's outward normal: the existing extreme search,
//! plus an `O(1)` tie fix for the `P`-first rule), and its rank on the path is `(i − i_0) + (j − j_0)`:
//! that is Schwartz's Δ′/Δ″ bookkeeping. Between two known sides, the source edge halfway through the
//! polygon with the larger remaining span gives a side between ¼ and ¾ of the way: `O(log N)` steps
//! of `O(log N)` each.
//!
//! # The steps
//! The ascending chain of `Z` runs from its lowest (rightmost on ties) vertex `B_P + B_R` to its highest
//! (rightmost) one `T_P + T_R`; every side on it rises strictly. The descending chain of `Z` is the
//! ascending chain of `−Z = Q ⊖ P`, so one routine serves both (the pairs are swapped back).
//! 1. The origin strictly below `B` or above `T` (a degree-1 sign): it is outside `Z`.
//! 2. Otherwise the ranked search finds the side of each chain crossing the horizontal line through the
//!    origin; the origin strictly right of neither means `0 ∈ Z`: the polygons meet, and the exact
//!    contact classification (`meet.rs`) gives the outcome.
//! 3. Outside: the nearest point lies on the chain the origin sees (proved for the in-range case: the
//!    nearest point's outward normal points towards the origin's side), on the part visible from the
//!    origin, where the distance is unimodal. Two ranked searches from the anchor (the crossing side,
//!    or the bottom or top) locate it with Schwartz's acute/obtuse test, restricted to visible sides.
//! 4. The few sides around the located spots (and the horizontal bottom or top face pieces) are vertex–
//!    edge pairs of `P` and `Q`; each is a subset of `Z`, so the exact minimum (`cmp_dist2`) over them
//!    realizes the distance. Theorem 1 certifies it; a failure (only with an inexact kernel) falls back
//!    to the exact contact test and the brute force, like the Yang path.
//!
//! Every test on a `z`-vertex is the sign of a polynomial in the input coordinates (`ZHeight`,
//! `ZCross`, `ZDot`), decided by `K::sign`: no difference `p_i − q_j` is ever rounded.

use glam::DVec2;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Polynomial, Ring, Robust, Sign};

use crate::brute::brute_pair;
use crate::contact::contact_with;
use crate::extreme::{extreme, extreme_left_of};
use crate::meet::separation;
use crate::pair::{Pair, at, canonical, certify, finish, nearer};
use crate::result::Separation;

/// `x_0 − x_1` (degree 1): the height of `z = a − b` from the inputs `[a_y, b_y]`, and every
/// coordinate comparison of the lexicographic extreme searches.
struct ZHeight;
impl Polynomial<2> for ZHeight {
    const DEGREE: u32 = 1;
    fn eval<R: Ring>(&self, x: &[R; 2]) -> R {
        x[0].sub(&x[1])
    }
}

/// `z_1 × z_2` for `z_1 = a_1 − b_1`, `z_2 = a_2 − b_2` (degree 2): `orient(z_1, z_2, 0)`, negative
/// when the origin is strictly right of the side `z_1 → z_2`. Inputs `[a_1, b_1, a_2, b_2]` (x, y each).
pub(crate) struct ZCross;
impl Polynomial<8> for ZCross {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (z1x, z1y) = (x[0].sub(&x[2]), x[1].sub(&x[3]));
        let (z2x, z2y) = (x[4].sub(&x[6]), x[5].sub(&x[7]));
        z1x.mul(&z2y).sub(&z1y.mul(&z2x))
    }
}

/// `(0 − z_1)·(z_2 − z_1)` (degree 2): Schwartz's acute/obtuse test at `z_1` (positive: moving from
/// `z_1` towards `z_2` brings the side nearer the origin). Inputs as `ZCross`.
struct ZDot;
impl Polynomial<8> for ZDot {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 8]) -> R {
        let (z1x, z1y) = (x[0].sub(&x[2]), x[1].sub(&x[3]));
        let (z2x, z2y) = (x[4].sub(&x[6]), x[5].sub(&x[7]));
        // (0 − z_1)·(z_2 − z_1) = z_1·(z_1 − z_2).
        z1x.mul(&z1x.sub(&z2x)).add(&z1y.mul(&z1y.sub(&z2y)))
    }
}

/// `⌈log₂ x⌉` for `x ≥ 1`.
fn ceil_log2(x: usize) -> u32 {
    if x <= 1 {
        0
    } else {
        usize::BITS - (x - 1).leading_zeros()
    }
}

/// `sign(x − y)` through the kernel.
pub(crate) fn coord_sign<K: Kernel>(x: f64, y: f64) -> Sign {
    K::sign(&ZHeight, &[x, y])
}

/// The vertex of `v` lowest in `y`, rightmost on ties (`lowest = true`), or highest in `y`, rightmost
/// on ties; `negate` looks at `−v` instead (the vertices of `−Q`).
fn lex_extreme<K: Kernel>(v: &[DVec2], lowest: bool, negate: bool) -> usize {
    // f(x) = (±y, x) lexicographically, maximized; for −v both coordinates flip.
    let ys = if lowest { -1 } else { 1 } * if negate { -1 } else { 1 };
    let xs = if negate { -1 } else { 1 };
    extreme(v, |x, y| {
        let s = coord_sign::<K>(x.y, y.y);
        let s = if ys < 0 { s.reversed() } else { s };
        if s != Sign::Zero {
            return s;
        }
        let t = coord_sign::<K>(x.x, y.x);
        if xs < 0 { t.reversed() } else { t }
    })
}

/// A side of the implicit `Z = A ⊖ B`: edge `e` of `A` at the corner `−b_c` (`from_a`), or edge `e` of
/// `−B` (from `−b_e` to `−b_{e+1}`) at the corner `a_c`. Indices are unrolled along the chain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Side {
    pub(crate) from_a: bool,
    pub(crate) e: usize,
    pub(crate) c: usize,
}

impl Side {
    /// The lattice state `(i, j)` of the side's first vertex `a_i − b_j`.
    fn start(self) -> (usize, usize) {
        if self.from_a {
            (self.e, self.c)
        } else {
            (self.c, self.e)
        }
    }

    /// The state of the side's last vertex.
    fn end(self) -> (usize, usize) {
        if self.from_a {
            (self.e + 1, self.c)
        } else {
            (self.c, self.e + 1)
        }
    }
}

/// The ascending chain of `Z = A ⊖ B`: from the state `bottom` (lowest, rightmost on ties) to `top`
/// (highest, rightmost on ties), unrolled so that `top ≥ bottom` in both indices.
pub(crate) struct Chain<'a, K> {
    pub(crate) a: &'a [DVec2],
    pub(crate) b: &'a [DVec2],
    pub(crate) bottom: (usize, usize),
    pub(crate) top: (usize, usize),
    kernel: core::marker::PhantomData<K>,
}

impl<'a, K: Kernel> Chain<'a, K> {
    /// The chain of `A ⊖ B`: four `O(log)` extreme searches.
    pub(crate) fn new(a: &'a [DVec2], b: &'a [DVec2]) -> Self {
        let (ba, ta) = (
            lex_extreme::<K>(a, true, false),
            lex_extreme::<K>(a, false, false),
        );
        let (bb, tb) = (
            lex_extreme::<K>(b, true, true),
            lex_extreme::<K>(b, false, true),
        );
        let unroll = |lo: usize, hi: usize, len: usize| if hi >= lo { hi } else { hi + len };
        Chain {
            a,
            b,
            bottom: (ba, bb),
            top: (unroll(ba, ta, a.len()), unroll(bb, tb, b.len())),
            kernel: core::marker::PhantomData,
        }
    }

    /// `sign(height of a_i − b_j)`.
    pub(crate) fn height(&self, (i, j): (usize, usize)) -> Sign {
        coord_sign::<K>(at(self.a, i).y, at(self.b, j).y)
    }

    /// The inputs `[a_1, b_1, a_2, b_2]` of a side's two vertices.
    pub(crate) fn side_inputs(&self, s: Side) -> [f64; 8] {
        let ((i1, j1), (i2, j2)) = (s.start(), s.end());
        let (a1, b1, a2, b2) = (
            at(self.a, i1),
            at(self.b, j1),
            at(self.a, i2),
            at(self.b, j2),
        );
        [a1.x, a1.y, b1.x, b1.y, a2.x, a2.y, b2.x, b2.y]
    }

    /// The inputs of a side read backwards (`z_2 → z_1`).
    fn side_inputs_reversed(&self, s: Side) -> [f64; 8] {
        let x = self.side_inputs(s);
        [x[4], x[5], x[6], x[7], x[0], x[1], x[2], x[3]]
    }

    /// The origin is strictly right of the side (the side is visible from it).
    fn visible(&self, s: Side) -> bool {
        K::sign(&ZCross, &self.side_inputs(s)) == Sign::Negative
    }

    /// Visible, and moving forward from its first vertex brings it nearer the origin.
    fn nearer_ahead(&self, s: Side) -> bool {
        self.visible(s) && K::sign(&ZDot, &self.side_inputs(s)) == Sign::Positive
    }

    /// Visible, and moving backward from its last vertex brings it nearer the origin.
    fn nearer_behind(&self, s: Side) -> bool {
        self.visible(s) && K::sign(&ZDot, &self.side_inputs_reversed(s)) == Sign::Positive
    }

    /// `i` unrolled into `[base, base + len)`.
    fn unroll(i: usize, base: usize, len: usize) -> usize {
        let b = base % len;
        base + (i % len + len - b) % len
    }

    /// The matching corner in `−B` of edge `t` of `A`: the vertex of `−B` extreme in the edge's
    /// outward normal (the `B` vertex maximizing `x·rot90(a_{t+1} − a_t)`), moved to the start of a
    /// parallel edge of `−B` (ties: `A` first).
    fn corner_in_b(&self, t: usize) -> usize {
        let (a0, a1) = (at(self.a, t), at(self.a, t + 1));
        let m = self.b.len();
        let k = extreme_left_of::<K>(self.b, a0, a1);
        // Edge k − 1 of −B runs from −b_{k−1} to −b_k: direction b_{k−1} − b_k.
        let (bk, bp) = (self.b[k], at(self.b, k + m - 1));
        let c = if m >= 2
            && K::cross_sign(a0, a1, bk, bp) == Sign::Zero
            && K::dot_sign(a0, a1, bk, bp) == Sign::Positive
        {
            k + m - 1
        } else {
            k
        };
        Self::unroll(c, self.bottom.1, m)
    }

    /// The matching corner in `A` of edge `s` of `−B` (direction `b_s − b_{s+1}`), moved past a
    /// parallel edge of `A` (ties: `A` first).
    fn corner_in_a(&self, s: usize) -> usize {
        let (b0, b1) = (at(self.b, s), at(self.b, s + 1));
        let n = self.a.len();
        let k = extreme_left_of::<K>(self.a, b0, b1);
        let (ak, an) = (self.a[k], at(self.a, k + 1));
        let c = if n >= 2
            && K::cross_sign(ak, an, b1, b0) == Sign::Zero
            && K::dot_sign(ak, an, b1, b0) == Sign::Positive
        {
            k + 1
        } else {
            k
        };
        Self::unroll(c, self.bottom.0, n)
    }

    /// Schwartz's ranked binary search over the sides between the states `from` and `to` (on the
    /// chain, `from ≤ to`) for a predicate true on a prefix: the last side known true and the first
    /// known false (adjacent when the search completes; `None` for an end of the range).
    ///
    /// Each pass takes the source edge halfway through the polygon with the larger remaining span and
    /// its matching corner (clamped into the remaining box, so the range shrinks whatever the signs);
    /// with exact signs that side lies between ¼ and ¾ of the way, so `⌈log_{4/3} N⌉ + 1` passes
    /// suffice; the loop is cut at `3⌈log₂N⌉ + 4`.
    fn search(
        &self,
        from: (usize, usize),
        to: (usize, usize),
        pred: impl Fn(&Self, Side) -> bool,
    ) -> (Option<Side>, Option<Side>) {
        let (mut lo, mut hi) = (None, None);
        let (mut lo_end, mut hi_start) = (from, to);
        let cap = 3 * ceil_log2(self.a.len() + self.b.len()) + 4;
        for _ in 0..cap {
            let ((i1, j1), (i2, j2)) = (lo_end, hi_start);
            if i2 < i1 || j2 < j1 {
                break;
            }
            let (sa, sb) = (i2 - i1, j2 - j1);
            if sa + sb == 0 {
                break;
            }
            let side = if sa >= sb {
                let t = (i1 + sa / 2).min(i2 - 1);
                Side {
                    from_a: true,
                    e: t,
                    c: self.corner_in_b(t).clamp(j1, j2),
                }
            } else {
                let s = (j1 + sb / 2).min(j2 - 1);
                Side {
                    from_a: false,
                    e: s,
                    c: self.corner_in_a(s).clamp(i1, i2),
                }
            };
            if pred(self, side) {
                lo = Some(side);
                lo_end = side.end();
            } else {
                hi = Some(side);
                hi_start = side.start();
            }
        }
        (lo, hi)
    }

    /// The pair of `A` and `B` whose distance is the origin's distance to the side.
    fn pair(&self, s: Side) -> Pair {
        let (n, m) = (self.a.len(), self.b.len());
        if s.from_a {
            Pair::Ev(s.e % n, s.c % m)
        } else {
            Pair::Ve(s.c % n, s.e % m)
        }
    }

    /// The pieces of the horizontal bottom face (edges of `A` and `−B` ending at the bottom vertex, at
    /// both candidate corners) and the bottom vertex: every one a subset of `Z`.
    fn bottom_pairs(&self) -> [Pair; 5] {
        let (n, m) = (self.a.len(), self.b.len());
        let (i, j) = (self.bottom.0 % n, self.bottom.1 % m);
        let (ip, jp) = ((i + n - 1) % n, (j + m - 1) % m);
        [
            Pair::Vv(i, j),
            Pair::Ev(ip, j),
            Pair::Ev(ip, jp),
            Pair::Ve(i, jp),
            Pair::Ve(ip, jp),
        ]
    }

    /// The sides around the nearest point, searched both ways from the state `anchor` (the start of a
    /// visible side, or an end of the chain): forward while the side ahead gets nearer, backward while
    /// the side behind does. Each located side goes to `offer` as a pair of `A` and `B`.
    fn around(&self, anchor: (usize, usize), offer: &mut impl FnMut(Pair)) {
        let (lo, hi) = self.search(anchor, self.top, Self::nearer_ahead);
        let (lo2, hi2) = self.search(self.bottom, anchor, |ch, s| !ch.nearer_behind(s));
        for s in [lo, hi, lo2, hi2].into_iter().flatten() {
            offer(self.pair(s));
        }
    }

    /// The side crossing the horizontal line through the origin (the first whose end is not below it).
    fn crossing(&self) -> Option<Side> {
        self.search(self.bottom, self.top, |ch, s| {
            ch.height(s.end()) == Sign::Negative
        })
        .1
    }
}

/// The nearest (canonical) of the candidate pairs of `P` and `Q`, a set that holds a closest pair;
/// `None` when the point location says `0 ∈ Z` (or an inexact kernel left no candidate).
pub(crate) fn closest_candidate<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Option<Pair> {
    let z = Chain::<K>::new(p, q);
    let w = Chain::<K>::new(q, p);
    let mut best: Option<Pair> = None;
    let mut offer = |x: Pair| {
        best = Some(best.map_or(x, |b| nearer::<K>(p, q, b, x)));
    };
    if z.height(z.bottom) == Sign::Positive {
        // Below Z: Z's ascending chain from its bottom, its descending chain (−Z's ascending one) up to
        // its end, and the bottom face.
        z.around(z.bottom, &mut offer);
        w.around(w.top, &mut |x| offer(x.swapped()));
        z.bottom_pairs().into_iter().for_each(&mut offer);
    } else if z.height(z.top) == Sign::Negative {
        z.around(z.top, &mut offer);
        w.around(w.bottom, &mut |x| offer(x.swapped()));
        w.bottom_pairs()
            .into_iter()
            .for_each(|x| offer(x.swapped()));
    } else if let Some(s) = z.crossing().filter(|&s| z.visible(s)) {
        // The horizontal line through the origin crosses both chains; the origin is right of Z.
        offer(z.pair(s));
        z.around(s.start(), &mut offer);
    } else if let Some(s) = w.crossing().filter(|&s| w.visible(s)) {
        offer(w.pair(s).swapped());
        w.around(s.start(), &mut |x| offer(x.swapped()));
    } else {
        return None;
    }
    best.map(|b| canonical::<K>(p, q, b))
}

/// The distance between two convex polygons by Schwartz's `O(log² N)` binary search on the implicit
/// Minkowski difference `Z = P ⊖ Q`: the same answer type and feature conventions as
/// [`distance_with`](crate::distance_with), by a second, independent search.
///
/// The ascending and descending chains of `Z` are searched by rank without forming `Z`: each probe is
/// an edge of `P` or `Q` and its matching corner, found by an `O(log)` extreme search (Schwartz's
/// Δ′/Δ″ trick picks the probe between ¼ and ¾ of the range). The side of each chain crossing the
/// horizontal line through the origin decides whether `0 ∈ Z` (the polygons meet: the exact contact
/// test then classifies them, as in the other paths); otherwise the nearest side on the part of `Z`
/// visible from the origin is located by a second ranked search with Schwartz's acute/obtuse test.
/// Every decision on a vertex `p_i − q_j` of `Z` is the sign of a polynomial in the input coordinates
/// decided by `K`; the chosen pair is certified by Theorem 1 (Lin–Canny) and the result built by the
/// same code as the other paths. Points and segments are allowed (two of them: the `O(1)` scan).
///
/// With an inexact kernel the answer may be wrong, but every loop is bounded and nothing panics; a
/// failed certificate falls back to the exact contact test and, if that says disjoint (possible only
/// with an inexact kernel), to the brute force.
///
/// # Complexity
/// `O(log² N)` exact predicates for disjoint polygons, `N = n + m` (`O(log N)` ranked steps of one
/// `O(log N)` extreme search each; Schwartz's bucket table, which would make the expected cost
/// `O(log N)` on random angles, is not built). Meeting polygons cost `O(log n + log m)` more (the
/// contact test [`contact_with`]).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::polygon::{ConvexPolygon, Feature};
/// use polydist_convex::{Separation, distance_schwartz_with, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(1.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(4.0, 0.0), DVec2::new(6.0, 0.0), DVec2::new(5.0, 2.0)])?;
/// let Separation::Disjoint(c) = distance_schwartz_with::<Robust>(&p, &q) else { panic!("disjoint") };
/// assert_eq!(c.distance, 2.0);
/// assert_eq!((c.feature_p, c.feature_q), (Feature::Vertex(1), Feature::Vertex(0)));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// J. T. Schwartz, "Finding the minimum distance between two convex polygons", Information Processing
/// Letters 13(4–5), 1981, 168–170. Errata: in the paper's motion bound (section 1) the translation
/// term `|x1(t) + x2(t) − x1(0) − x2(0)|` should be the relative translation
/// `|(x2(t) − x1(t)) − (x2(0) − x1(0))|`; the paper also leaves ties (parallel edges, horizontal
/// sides) and the restriction of step (v) to the visible chain implicit (see
/// `docs/algorithms/convex-distance.md`, "Schwartz 1981").
#[must_use]
pub fn distance_schwartz_with<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Separation {
    let (p, q) = (pp.vertices(), qq.vertices());
    if p.len() <= 2 && q.len() <= 2 {
        return crate::distance_brute::<K>(pp, qq);
    }
    if let Some(pair) = closest_candidate::<K>(p, q).filter(|&b| certify::<K>(p, q, b)) {
        return Separation::Disjoint(finish::<K>(pp, qq, pair));
    }
    separation(contact_with::<K>(pp, qq), || {
        finish::<K>(pp, qq, brute_pair::<K>(pp, qq))
    })
}

/// [`distance_schwartz_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(log² N)` exact predicates for disjoint polygons, `N = n + m`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_schwartz, polygon::ConvexPolygon};
///
/// let square = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y])?;
/// let point = ConvexPolygon::try_new(&[DVec2::new(4.0, 5.0)])?;
/// assert_eq!(distance_schwartz(&square, &point).distance(), 5.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`distance_schwartz_with`].
#[must_use]
pub fn distance_schwartz(p: &ConvexPolygon, q: &ConvexPolygon) -> Separation {
    distance_schwartz_with::<Robust>(p, q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::{
        Contact, Relation, SplitMix64, contact_status_convex, convex_pair, random_convex_lattice,
    };
    use polydist_polygon::predicates::Exact;

    /// The search alone (no fallback): on disjoint pairs its candidates hold a certified closest pair;
    /// on meeting pairs the point location says `0 ∈ Z` (`None`).
    fn check_search<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> bool {
        let disjoint = contact_status_convex(p, q) == Contact::Disjoint;
        // The search runs on validated rings (collinear input vertices dropped).
        let pp = ConvexPolygon::try_new(p).expect("valid P");
        let qq = ConvexPolygon::try_new(q).expect("valid Q");
        let (p, q) = (pp.vertices(), qq.vertices());
        for (a, b) in [(p, q), (q, p)] {
            match closest_candidate::<K>(a, b) {
                Some(best) => {
                    assert!(
                        disjoint,
                        "located outside Z but they meet\np = {a:?}\nq = {b:?}"
                    );
                    assert!(
                        certify::<K>(a, b, best),
                        "uncertified {best:?}\np = {a:?}\nq = {b:?}"
                    );
                }
                None => assert!(!disjoint, "located in Z but disjoint\np = {a:?}\nq = {b:?}"),
            }
        }
        disjoint
    }

    #[test]
    fn the_search_never_needs_the_fallback() {
        let mut rng = SplitMix64::new(77);
        let (mut disjoint, mut total) = (0, 0);
        // Small lattice polygons: many ties (parallel edges, horizontal sides on the origin's line).
        for round in 0..6000 {
            let p = random_convex_lattice(&mut rng, 3 + round % 7, 6);
            let mut q = random_convex_lattice(&mut rng, 3 + (round / 7) % 7, 6);
            let shift = DVec2::new(rng.range_i64(-12, 12) as f64, rng.range_i64(-12, 12) as f64);
            q.iter_mut().for_each(|v| *v += shift);
            disjoint += usize::from(check_search::<Robust>(&p, &q));
            total += 1;
            // A point and a segment of the lattice against the polygon.
            check_search::<Robust>(&q[..1], &p);
            if q[0] != q[1] {
                check_search::<Robust>(&q[..2], &p);
            }
        }
        let relations = Relation::EVERY;
        for rel in relations {
            for round in 0..60 {
                let (n, m) = (
                    3 + rng.index(if round % 5 == 0 { 150 } else { 15 }),
                    3 + rng.index(15),
                );
                let pair = convex_pair(&mut rng, n, m, rel);
                disjoint += usize::from(check_search::<Robust>(&pair.p, &pair.q));
                if round % 6 == 0 {
                    check_search::<Exact>(&pair.p, &pair.q);
                }
                total += 1;
            }
        }
        println!("{disjoint} disjoint of {total}");
        assert!(disjoint > 1000 && total - disjoint > 500);
    }
}
