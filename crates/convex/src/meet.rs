//! Exact contact classification of two convex polygons (points and segments included).
//!
//! With `Z = P ⊖ Q` (the Minkowski difference), `P` and `Q` meet iff `0 ∈ Z`, and their relative
//! interiors meet iff `0 ∈ relint Z` (`relint(A + B) = relint A + relint B` for convex sets).
//! - `Z` two-dimensional (some polygon has area, or two non-parallel segments): every edge normal of
//!   `Z` is an edge normal of `P` or of `Q` (a segment has both normals). For the edge `ab` of `P`,
//!   `h_Z` in its outward normal is positive iff some vertex of `Q` is strictly left of `ab`, zero iff
//!   the leftmost is on the line (exact orient signs). `0 ∉ Z` iff some candidate is negative (a
//!   separating axis); on the boundary iff some is zero; else in the interior.
//! - `Z` a segment (a point and a segment, or two parallel segments): on the line, then the intervals
//!   along it (exact dot signs). `Z` a point (two points): equal or not.
//!
//! The maximum over `Q` of `orient(a, b, q_j)` is a linear function's maximum: the extreme search
//! (`O(log m)`) when `fast`, a scan otherwise; in all `O(n log m + m log n)` or `O(nm)` exact predicates.

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Sign};
use polydist_polygon::{ConvexPolygon, Feature};

use crate::extreme::extreme_left_of;
use crate::pair::{at, caller_on_edge, caller_vertex};
use crate::result::{Closest, Separation};

/// Whether two convex polygons (points and segments included) meet, and how: the answer of
/// [`contact`](fn@crate::contact) and [`contact_with`](crate::contact_with).
///
/// The cases are those of [`Separation`] without the closest pair: with relative interiors
/// (`relint(point) = the point`, `relint(segment) = the open segment`, `relint(polygon) = its open
/// interior`), `Touching` means the closed sets meet but their relative interiors do not, and
/// `Overlapping` means the relative interiors meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Contact {
    /// The polygons do not meet.
    Disjoint,
    /// The polygons meet but their relative interiors do not.
    Touching {
        /// A common point: an input vertex of one polygon, so exact.
        point: DVec2,
        /// The caller's feature of `P` containing `point`.
        feature_p: Feature,
        /// The caller's feature of `Q` containing `point`.
        feature_q: Feature,
    },
    /// The relative interiors meet.
    Overlapping,
}

/// The answer for a contact status; `closest` (called only when disjoint) gives the closest pair.
pub(crate) fn separation(meet: Contact, closest: impl FnOnce() -> Closest) -> Separation {
    match meet {
        Contact::Disjoint => Separation::Disjoint(closest()),
        Contact::Touching {
            point,
            feature_p,
            feature_q,
        } => Separation::Touching {
            point,
            feature_p,
            feature_q,
        },
        Contact::Overlapping => Separation::Overlapping,
    }
}

/// The vertex of `v` with the largest `orient(a, b, ·)` and that sign.
fn max_left<K: Kernel>(v: &[DVec2], a: DVec2, b: DVec2, fast: bool) -> (usize, Sign) {
    let j = if fast && v.len() >= 3 {
        extreme_left_of::<K>(v, a, b)
    } else {
        let mut best = 0;
        for j in 1..v.len() {
            if K::cross_sign(a, b, v[best], v[j]) == Sign::Positive {
                best = j;
            }
        }
        best
    };
    (j, K::orient(a, b, v[j]).sign())
}

/// `x` lies on the closed segment `uv`, given that it is on its line.
fn on_collinear_segment<K: Kernel>(x: DVec2, u: DVec2, v: DVec2) -> bool {
    K::dot_sign(x, u, x, v) != Sign::Positive
}

/// The contact of a touching pair, found from the edge `e` of `A` whose line supports `B` at vertex `j`.
/// Returns `(point, feature of A, feature of B)`.
pub(crate) fn contact_point<K: Kernel>(
    a_poly: &ConvexPolygon,
    e: usize,
    b_poly: &ConvexPolygon,
    j: usize,
) -> (DVec2, Feature, Feature) {
    let (av, bv) = (a_poly.vertices(), b_poly.vertices());
    let (a0, a1) = (at(av, e), at(av, e + 1));
    let bj = bv[j];
    // B's piece on the line: vertex j, or an edge at j if its other end is on the line too.
    let m = bv.len();
    let mut piece = (j, j);
    if m >= 2 {
        if K::orient(a0, a1, at(bv, j + 1)).sign() == Sign::Zero {
            piece = (j, (j + 1) % m);
        } else if K::orient(a0, a1, at(bv, j + m - 1)).sign() == Sign::Zero {
            piece = ((j + m - 1) % m, j);
        }
    }
    let feature_in_a = |x: DVec2| {
        if x == a0 {
            caller_vertex(a_poly, e)
        } else if x == a1 {
            caller_vertex(a_poly, e + 1)
        } else {
            caller_on_edge::<K>(a_poly, e, x)
        }
    };
    let (u, v) = (bv[piece.0], bv[piece.1]);
    let feature_in_b = |x: DVec2| {
        if x == u {
            caller_vertex(b_poly, piece.0)
        } else if x == v {
            caller_vertex(b_poly, piece.1)
        } else {
            caller_on_edge::<K>(b_poly, piece.0, x)
        }
    };
    for x in [u, v] {
        if on_collinear_segment::<K>(x, a0, a1) {
            return (x, feature_in_a(x), feature_in_b(x));
        }
    }
    for x in [a0, a1] {
        if piece.0 != piece.1 && on_collinear_segment::<K>(x, u, v) {
            return (x, feature_in_a(x), feature_in_b(x));
        }
    }
    // Unreachable with exact signs (the pieces meet); an inexact kernel gets B's vertex.
    (bj, feature_in_a(bj), caller_vertex(b_poly, j))
}

/// Exact contact classification by separating axes (see the module docs): `O(n log m + m log n)`
/// when `fast`, `O(nm)` otherwise; `O(1)` for two points or segments. The `O(log)` test is
/// [`contact_with`](crate::contact_with); this one is its independent twin and the small-input path.
pub(crate) fn classify<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon, fast: bool) -> Contact {
    let (p, q) = (pp.vertices(), qq.vertices());
    let (n, m) = (p.len(), q.len());
    let two_d = n >= 3
        || m >= 3
        || (n == 2 && m == 2 && K::cross_sign(p[0], p[1], q[0], q[1]) != Sign::Zero);
    if two_d {
        // (edge of A, vertex of B, A is P) for a supporting line through both.
        let mut touch: Option<(usize, usize, bool)> = None;
        for (a, b, a_is_p) in [(p, q, true), (q, p, false)] {
            if a.len() < 2 {
                continue;
            }
            for e in 0..a.len() {
                let (j, s) = max_left::<K>(b, a[e], at(a, e + 1), fast);
                match s {
                    Sign::Negative => return Contact::Disjoint,
                    Sign::Zero => {
                        touch.get_or_insert((e, j, a_is_p));
                    }
                    Sign::Positive => {}
                }
            }
        }
        return match touch {
            None => Contact::Overlapping,
            Some((e, j, true)) => {
                let (point, feature_p, feature_q) = contact_point::<K>(pp, e, qq, j);
                Contact::Touching {
                    point,
                    feature_p,
                    feature_q,
                }
            }
            Some((e, j, false)) => {
                let (point, feature_q, feature_p) = contact_point::<K>(qq, e, pp, j);
                Contact::Touching {
                    point,
                    feature_p,
                    feature_q,
                }
            }
        };
    }
    if n == 1 && m == 1 {
        return if p[0] == q[0] {
            Contact::Overlapping
        } else {
            Contact::Disjoint
        };
    }
    // Z is a segment: a point and a segment, or two parallel segments. Its line is a segment's line.
    let (a, b) = if n == 2 { (p[0], p[1]) } else { (q[0], q[1]) };
    if p.iter()
        .chain(q)
        .any(|&x| K::orient(a, b, x).sign() != Sign::Zero)
    {
        return Contact::Disjoint;
    }
    // Along d = b − a: sign((p_i − q_j)·d).
    let mut p_reaches = Sign::Negative; // max over (i, j) of sign((p_i − q_j)·d)
    let mut q_reaches = Sign::Negative; // max over (i, j) of sign((q_j − p_i)·d)
    for &x in p {
        for &y in q {
            p_reaches = p_reaches.max(K::dot_sign(a, b, y, x));
            q_reaches = q_reaches.max(K::dot_sign(a, b, x, y));
        }
    }
    if p_reaches == Sign::Negative || q_reaches == Sign::Negative {
        return Contact::Disjoint;
    }
    if p_reaches == Sign::Positive && q_reaches == Sign::Positive {
        return Contact::Overlapping;
    }
    // They share an endpoint: collinear with the same projection.
    for (i, &x) in p.iter().enumerate() {
        for (j, &y) in q.iter().enumerate() {
            if x == y {
                return Contact::Touching {
                    point: x,
                    feature_p: caller_vertex(pp, i),
                    feature_q: caller_vertex(qq, j),
                };
            }
        }
    }
    // Unreachable with exact signs.
    Contact::Touching {
        point: p[0],
        feature_p: caller_vertex(pp, 0),
        feature_q: caller_vertex(qq, 0),
    }
}
