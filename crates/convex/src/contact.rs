//! The intersection test in `O(log n + log m)`: does the origin lie in `Z = P ⊖ Q`, on its boundary or
//! inside, found by a simultaneous prune-and-search on the two polygons' chains.
//!
//! `P` and `Q` meet iff `0 ∈ Z`, and their relative interiors meet iff `0 ∈ relint Z = int Z` when `Z`
//! has area (`relint(A + B) = relint A + relint B` for convex sets). `Z` is never formed. Its
//! ascending chain (right side, from the lowest vertex to the highest, rightmost on ties) is the merge
//! by angle of the ascending chains of `P` and of `−Q`; its descending chain is the ascending chain of
//! `−Z = Q ⊖ P`. A vertex of the chain is a lattice state `(i, j)`, `z = p_i − q_j`.
//!
//! **The crossing.** Let `V* = (i*, j*)` be the first chain vertex (in merge order) not below the
//! horizontal line through the origin. The height `y(p_i) − y(q_j)` grows with `i` and with `j` over
//! the whole lattice, not only along the chain, because both chains ascend strictly. Take a middle edge
//! `e` of `P`'s chain and a middle edge `f` of `−Q`'s, and compare their angles (one exact cross sign).
//! If `e` comes first in the merge, the vertex just after `e` is `(e + 1, c)` with `c ≤ f`, and the
//! vertex just before `f` is `(a, f)` with `a ≥ e + 1`. So one height test at `(e + 1, f)` decides:
//! below the line means `i* > e`, and otherwise `j* ≤ f`. If `f` comes first, the same holds with the
//! roles exchanged. Each test halves one of the two ranges, so at most `⌈log₂ n⌉ + ⌈log₂ m⌉ + 2` passes
//! run. Once one range is a single index, `V*` is the first state of that column (or row) that is on
//! the chain and not below the line: one binary search on two monotone predicates. The chain side
//! ending at `V*` crosses the line, and one orientation sign of the origin against it (degree 2 in the
//! inputs) tells right of it (outside), on it (boundary), or left of it.
//!
//! Every test is the sign of a polynomial in the input coordinates: heights and the bottom face's `x`
//! range are coordinate comparisons, angle order is `cross_sign`, the side test is Schwartz's `ZCross`.
//! With an inexact kernel the answer may be wrong, but every loop is bounded by its ranges.

use glam::DVec2;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Robust, Sign};

use crate::meet::{Contact, classify, contact_point};
use crate::pair::{at, caller_on_edge, caller_vertex};
use crate::schwartz::{Chain, Side, ZCross, coord_sign};

impl<K: Kernel> Chain<'_, K> {
    /// Edge `e` of `A` comes before edge `s` of `−B` in the merged chain (ties: `A` first):
    /// `(a_{e+1} − a_e) × (b_s − b_{s+1}) ≥ 0`.
    fn a_first(&self, e: usize, s: usize) -> bool {
        K::cross_sign(
            at(self.a, e),
            at(self.a, e + 1),
            at(self.b, s + 1),
            at(self.b, s),
        ) != Sign::Negative
    }

    /// The state `(i, j)` is not below the horizontal line through the origin.
    fn not_below(&self, state: (usize, usize)) -> bool {
        self.height(state) != Sign::Negative
    }

    /// The chain side crossing the horizontal line through the origin, in `O(log n + log m)` exact
    /// predicates: the side ending at the first vertex not below the line (see the module docs).
    /// Requires the bottom strictly below the line; `None` only under inconsistent signs.
    pub(crate) fn crossing_log(&self) -> Option<Side> {
        let (bottom, top) = (self.bottom, self.top);
        let (mut alo, mut ahi) = (bottom.0, top.0);
        let (mut blo, mut bhi) = (bottom.1, top.1);
        // Each pass shrinks one of the ranges: the loop stops whatever the signs.
        while alo < ahi && blo < bhi {
            let (e, f) = (alo + (ahi - alo) / 2, blo + (bhi - blo) / 2);
            if self.a_first(e, f) {
                if self.not_below((e + 1, f)) {
                    bhi = f;
                } else {
                    alo = e + 1;
                }
            } else if self.not_below((e, f + 1)) {
                ahi = e;
            } else {
                blo = f + 1;
            }
        }
        let (i, j) = if alo == ahi {
            // Column i: the first j on the chain (edge i − 1 of A already taken) and not below.
            let i = alo;
            let on_chain = |j: usize| i == bottom.0 || j == top.1 || self.a_first(i - 1, j);
            (
                i,
                first_true(blo, bhi, |j| on_chain(j) && self.not_below((i, j))),
            )
        } else {
            // Row j: the first i on the chain (edge j − 1 of −B already taken) and not below.
            let j = blo;
            let on_chain = |i: usize| j == bottom.1 || i == top.0 || !self.a_first(i, j - 1);
            (
                first_true(alo, ahi, |i| on_chain(i) && self.not_below((i, j))),
                j,
            )
        };
        // The side into (i, j): the later in the merge of edge i − 1 of A and edge j − 1 of −B.
        if i > bottom.0 && (j == bottom.1 || !self.a_first(i - 1, j - 1)) {
            Some(Side {
                from_a: true,
                e: i - 1,
                c: j,
            })
        } else if j > bottom.1 {
            Some(Side {
                from_a: false,
                e: j - 1,
                c: i,
            })
        } else {
            None
        }
    }
}

/// The smallest `x` in `[lo, hi]` with `pred(x)`, for a predicate false then true (`hi` if none).
fn first_true(mut lo: usize, mut hi: usize, pred: impl Fn(usize) -> bool) -> usize {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if pred(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// The contact of `A` and `B` given that the origin lies on the side `s` of `Z = A ⊖ B`: a vertex of one
/// polygon on an edge of the other, as `(point, feature of A, feature of B)`.
fn on_side<K: Kernel>(
    ap: &ConvexPolygon,
    bp: &ConvexPolygon,
    s: Side,
) -> (DVec2, polydist_polygon::Feature, polydist_polygon::Feature) {
    let (n, m) = (ap.len(), bp.len());
    if s.from_a {
        // Edge e of A at the corner −b_c: b_c lies on edge e, whose line supports B.
        contact_point::<K>(ap, s.e % n, bp, s.c % m)
    } else {
        // Edge e of −B at the corner a_c: a_c lies on edge e of B.
        let (point, fb, fa) = contact_point::<K>(bp, s.e % m, ap, s.c % n);
        (point, fa, fb)
    }
}

/// The origin is on the line of `Z`'s bottom face (the lowest vertices of `A` against the highest of
/// `B`, at the same height). `z` is the chain of `A ⊖ B`, `w` that of `B ⊖ A`.
fn bottom_face<K: Kernel>(
    ap: &ConvexPolygon,
    bp: &ConvexPolygon,
    z: &Chain<'_, K>,
    w: &Chain<'_, K>,
) -> Contact {
    let (a, b) = (ap.vertices(), bp.vertices());
    // A's lowest piece runs (CCW, left to right) from a_l to a_r; B's highest piece (CCW, right to
    // left) from b_r to b_l. The bottom face of Z is [a_l − b_r, a_r − b_l].
    let (ia_r, ib_l) = (z.bottom.0, z.bottom.1);
    let (ib_r, ia_l) = (w.top.0, w.top.1);
    let (a_l, a_r, b_l, b_r) = (at(a, ia_l), at(a, ia_r), at(b, ib_l), at(b, ib_r));
    if coord_sign::<K>(a_l.x, b_r.x) == Sign::Positive
        || coord_sign::<K>(a_r.x, b_l.x) == Sign::Negative
    {
        return Contact::Disjoint;
    }
    // The pieces overlap: the larger left end is on both.
    let in_piece = |poly: &ConvexPolygon, lo: usize, hi: usize, x: DVec2, edge: usize| {
        let v = poly.vertices();
        if x == at(v, lo) {
            caller_vertex(poly, lo)
        } else if x == at(v, hi) {
            caller_vertex(poly, hi)
        } else {
            caller_on_edge::<K>(poly, edge, x)
        }
    };
    let (point, fa, fb) = if coord_sign::<K>(a_l.x, b_l.x) != Sign::Negative {
        (
            a_l,
            caller_vertex(ap, ia_l),
            in_piece(bp, ib_r, ib_l, a_l, ib_r),
        )
    } else {
        (
            b_l,
            in_piece(ap, ia_l, ia_r, b_l, ia_l),
            caller_vertex(bp, ib_l),
        )
    };
    Contact::Touching {
        point,
        feature_p: fa,
        feature_q: fb,
    }
}

/// [`Contact`] with the roles of `P` and `Q` exchanged back.
fn swapped(c: Contact) -> Contact {
    match c {
        Contact::Touching {
            point,
            feature_p,
            feature_q,
        } => Contact::Touching {
            point,
            feature_p: feature_q,
            feature_q: feature_p,
        },
        other => other,
    }
}

/// Whether two convex polygons (points and segments included) meet, and how, in
/// `O(log n + log m)` exact predicates, deciding everything with the kernel `K`.
///
/// The test locates the origin in the Minkowski difference `Z = P ⊖ Q` without forming it: four
/// lexicographic extreme searches give the ends of `Z`'s two chains, and a simultaneous
/// prune-and-search on the ascending chains of `P` and `−Q` (each pass compares one edge angle and one
/// height, and halves one of the two ranges) finds the side of `Z` that crosses the horizontal line
/// through the origin; one orientation sign against it, and one against the crossing side of the
/// descending chain, classify the origin as outside, on the boundary (touching; the contact is read
/// from that side: a vertex of one polygon on an edge of the other) or inside (overlapping). Two
/// inputs with at most two vertices each take the `O(1)` separating-axis test.
///
/// Under the Robust and Exact kernels the answer is exact, and a touching contact point is an input
/// vertex lying on the other polygon. Under [`Fast`](polydist_polygon::predicates::Fast) it may be
/// wrong near degeneracy; every loop is bounded by its ranges.
///
/// # Complexity
/// `O(log n + log m)` exact predicates, at most `2(⌈log₂ n⌉ + ⌈log₂ m⌉) + 8` passes in all; no allocation.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::polygon::{ConvexPolygon, Feature};
/// use polydist_convex::polygon::predicates::Robust;
/// use polydist_convex::{Contact, contact_with};
///
/// let square = |x: f64| ConvexPolygon::try_new(&[
///     DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0),
/// ]);
/// let (a, b, c) = (square(0.0)?, square(1.0)?, square(0.5)?);
/// assert!(matches!(contact_with::<Robust>(&a, &b), Contact::Touching { .. }));
/// assert_eq!(contact_with::<Robust>(&a, &c), Contact::Overlapping);
/// assert_eq!(contact_with::<Robust>(&a, &square(1.5)?), Contact::Disjoint);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// The Minkowski-difference view and the chain split follow J. T. Schwartz, "Finding the minimum
/// distance between two convex polygons", Information Processing Letters 13(4–5), 1981; the
/// simultaneous halving of two sorted sequences is the classical prune-and-search (as in
/// B. Chazelle, D. P. Dobkin, "Intersection of convex objects in two and three dimensions", J. ACM
/// 34(1), 1987, which reaches the same `O(log n + log m)` bound by another route).
#[must_use]
pub fn contact_with<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Contact {
    let (p, q) = (pp.vertices(), qq.vertices());
    if p.len() <= 2 && q.len() <= 2 {
        return classify::<K>(pp, qq, false);
    }
    let z = Chain::<K>::new(p, q);
    let w = Chain::<K>::new(q, p);
    // The lowest vertex of Z and the lowest of −Z (minus the highest of Z).
    match (z.height(z.bottom), w.height(w.bottom)) {
        (Sign::Positive, _) | (_, Sign::Positive) => return Contact::Disjoint,
        (Sign::Zero, _) => return bottom_face::<K>(pp, qq, &z, &w),
        (_, Sign::Zero) => return swapped(bottom_face::<K>(qq, pp, &w, &z)),
        _ => {}
    }
    let (Some(sz), Some(sw)) = (z.crossing_log(), w.crossing_log()) else {
        // Only under inconsistent signs: the exact separating-axis test.
        return classify::<K>(pp, qq, true);
    };
    let side_z = K::sign(&ZCross, &z.side_inputs(sz));
    let side_w = K::sign(&ZCross, &w.side_inputs(sw));
    match (side_z, side_w) {
        (Sign::Negative, _) | (_, Sign::Negative) => Contact::Disjoint,
        (Sign::Positive, Sign::Positive) => Contact::Overlapping,
        (Sign::Zero, _) => {
            let (point, feature_p, feature_q) = on_side::<K>(pp, qq, sz);
            Contact::Touching {
                point,
                feature_p,
                feature_q,
            }
        }
        (_, Sign::Zero) => {
            let (point, feature_q, feature_p) = on_side::<K>(qq, pp, sw);
            Contact::Touching {
                point,
                feature_p,
                feature_q,
            }
        }
    }
}

/// [`contact_with`] under the default [`Robust`] kernel.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{Contact, contact, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(1.0, 3.0)])?;
/// let Contact::Touching { point, .. } = contact(&p, &q) else { panic!("touching") };
/// assert_eq!(point, DVec2::new(1.0, 1.0));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
#[must_use]
pub fn contact(p: &ConvexPolygon, q: &ConvexPolygon) -> Contact {
    contact_with::<Robust>(p, q)
}

/// Whether two convex polygons (points and segments included) have a common point, exactly, in
/// `O(log n + log m)`: [`contact_with`] is not [`Contact::Disjoint`].
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{intersects, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])?;
/// let touching = ConvexPolygon::try_new(&[DVec2::new(0.5, 0.5), DVec2::new(1.0, 1.0)])?;
/// assert!(intersects::<Robust>(&p, &touching));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
#[must_use]
pub fn intersects<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    contact_with::<K>(p, q) != Contact::Disjoint
}
