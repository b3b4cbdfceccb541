//! Candidate realizing pairs in internal indices: canonical form, the Theorem-1 certificate, and the
//! finished [`Closest`] in the caller's indices.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::predicates::{Dist2, Kernel, Orientation, Sign};
use polydist_polygon::{ConvexPolygon, Feature};

use crate::construct;
use crate::result::Closest;

/// A vertex–vertex or vertex–edge pair of `P` and `Q`, in internal indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pair {
    /// Vertex `i` of `P`, vertex `j` of `Q`.
    Vv(usize, usize),
    /// Vertex `i` of `P`, edge `j` of `Q`.
    Ve(usize, usize),
    /// Edge `i` of `P`, vertex `j` of `Q`.
    Ev(usize, usize),
}

impl Pair {
    /// The same pair with the roles of `P` and `Q` exchanged.
    pub(crate) fn swapped(self) -> Pair {
        match self {
            Pair::Vv(i, j) => Pair::Vv(j, i),
            Pair::Ve(i, j) => Pair::Ev(j, i),
            Pair::Ev(i, j) => Pair::Ve(j, i),
        }
    }
}

/// `i mod n` without a division for the indices the searches produce (below `2n`; an integer
/// division costs tens of cycles, a noticeable part of a query at `n = 8`).
#[inline(always)]
fn wrap(i: usize, n: usize) -> usize {
    if i < n {
        i
    } else if i - n < n {
        i - n
    } else {
        i % n
    }
}

/// Vertex `i` of the ring `v` (indices taken mod `len`).
#[inline]
pub(crate) fn at(v: &[DVec2], i: usize) -> DVec2 {
    v[wrap(i, v.len())]
}

/// Vertex `i − 1` of the ring `v`.
#[inline]
pub(crate) fn prev(v: &[DVec2], i: usize) -> DVec2 {
    let n = v.len();
    v[wrap(wrap(i, n) + n - 1, n)]
}

/// The squared distance of a pair, for exact comparison.
pub(crate) fn dist2(p: &[DVec2], q: &[DVec2], pair: Pair) -> Dist2 {
    match pair {
        Pair::Vv(i, j) => Dist2::PointPoint(at(p, i), at(q, j)),
        Pair::Ve(i, j) => Dist2::PointSegment(at(p, i), at(q, j), at(q, j + 1)),
        Pair::Ev(i, j) => Dist2::PointSegment(at(q, j), at(p, i), at(p, i + 1)),
    }
}

/// The nearer of two pairs (the first on ties).
pub(crate) fn nearer<K: Kernel>(p: &[DVec2], q: &[DVec2], a: Pair, b: Pair) -> Pair {
    if K::cmp_dist2(dist2(p, q, b), dist2(p, q, a)) == Ordering::Less {
        b
    } else {
        a
    }
}

/// Where the foot of `x` on the closed segment `ab` falls: `Some(false)` at `a`, `Some(true)` at `b`,
/// `None` strictly inside (two exact dot signs).
fn clamp<K: Kernel>(x: DVec2, a: DVec2, b: DVec2) -> Option<bool> {
    if K::dot_sign(a, x, a, b) != Sign::Positive {
        Some(false)
    } else if K::dot_sign(b, x, b, a) != Sign::Positive {
        Some(true)
    } else {
        None
    }
}

/// The pair with a vertex–edge foot at an edge end replaced by the vertex–vertex pair.
pub(crate) fn canonical<K: Kernel>(p: &[DVec2], q: &[DVec2], pair: Pair) -> Pair {
    match pair {
        Pair::Vv(..) => pair,
        Pair::Ve(i, j) => match clamp::<K>(at(p, i), at(q, j), at(q, j + 1)) {
            Some(false) => Pair::Vv(i, wrap(j, q.len())),
            Some(true) => Pair::Vv(i, wrap(j + 1, q.len())),
            None => pair,
        },
        Pair::Ev(i, j) => match clamp::<K>(at(q, j), at(p, i), at(p, i + 1)) {
            Some(false) => Pair::Vv(wrap(i, p.len()), j),
            Some(true) => Pair::Vv(wrap(i + 1, p.len()), j),
            None => pair,
        },
    }
}

/// Edge `i` of `v` oriented so that `x` lies strictly to its right, or `None`. A segment's two edges
/// are its two directions, so either orientation is allowed there.
fn outer_edge<K: Kernel>(v: &[DVec2], i: usize, x: DVec2) -> Option<(DVec2, DVec2)> {
    let (a, b) = (at(v, i), at(v, i + 1));
    match K::orient(a, b, x) {
        Orientation::Clockwise => Some((a, b)),
        Orientation::CounterClockwise if v.len() == 2 => Some((b, a)),
        _ => None,
    }
}

/// Theorem 1 (Lin–Canny), exact: the canonical `pair` realizes the distance of disjoint `P` and `Q`
/// when `w = q* − p* ≠ 0`, `w ∈ N_P(p*)` and `−w ∈ N_Q(q*)`; then the lines through `p*` and `q*`
/// perpendicular to `w` separate the polygons, so they are disjoint at distance `|w|`.
pub(crate) fn certify<K: Kernel>(p: &[DVec2], q: &[DVec2], pair: Pair) -> bool {
    certify_parallel::<K>(p, q, pair).is_some()
}

/// [`certify`], returning for a certified pair whether it is `parallel` (both support faces are
/// edges) from the same signs: the same predicates in the same order as [`certify`], and `parallel`
/// equals what [`finish`] computes (a zero among the signs that certify the normal cones).
pub(crate) fn certify_parallel<K: Kernel>(p: &[DVec2], q: &[DVec2], pair: Pair) -> Option<bool> {
    use Sign::{Negative, Positive, Zero};
    let holds = |ok: bool| if ok { Some(()) } else { None };
    match pair {
        Pair::Vv(i, j) => {
            let (x, y) = (at(p, i), at(q, j));
            holds(x != y)?;
            let s1 = K::dot_sign(prev(p, i), x, x, y);
            holds(s1 != Negative)?;
            let s2 = K::dot_sign(x, at(p, i + 1), x, y);
            holds(s2 != Positive)?;
            let s3 = K::dot_sign(prev(q, j), y, x, y);
            holds(s3 != Positive)?;
            let s4 = K::dot_sign(y, at(q, j + 1), x, y);
            holds(s4 != Negative)?;
            let face_p = p.len() >= 2 && (s1 == Zero || s2 == Zero);
            let face_q = q.len() >= 2 && (s3 == Zero || s4 == Zero);
            Some(face_p && face_q)
        }
        Pair::Ve(i, j) => {
            let x = at(p, i);
            let (a, b) = outer_edge::<K>(q, j, x)?;
            // w ∝ rot90(b − a): (p_i − p_{i−1})·w ≥ 0 ⇔ (b − a) × (p_i − p_{i−1}) ≥ 0.
            holds(clamp::<K>(x, a, b).is_none())?;
            let s1 = K::cross_sign(a, b, prev(p, i), x);
            holds(s1 != Negative)?;
            let s2 = K::cross_sign(a, b, x, at(p, i + 1));
            holds(s2 != Positive)?;
            Some(p.len() >= 2 && (s1 == Zero || s2 == Zero))
        }
        Pair::Ev(i, j) => {
            let y = at(q, j);
            let (a, b) = outer_edge::<K>(p, i, y)?;
            // −w ∝ rot90(b − a) for the outward normal w of P's edge.
            holds(clamp::<K>(y, a, b).is_none())?;
            let s1 = K::cross_sign(a, b, prev(q, j), y);
            holds(s1 != Negative)?;
            let s2 = K::cross_sign(a, b, y, at(q, j + 1));
            holds(s2 != Positive)?;
            Some(q.len() >= 2 && (s1 == Zero || s2 == Zero))
        }
    }
}

/// `canonical` then [`certify_parallel`], sharing the foot test: for a vertex–edge pair of a polygon
/// (at least three vertices) whose foot `canonical` found strictly inside the edge, the certificate's
/// own foot test (the same two dot signs on the same edge) is not repeated. The same answer as the two
/// calls.
pub(crate) fn canonical_certified<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    pair: Pair,
) -> Option<(Pair, bool)> {
    use Sign::{Negative, Positive, Zero};
    // Vertex x against edge ab of a ring with at least three vertices, foot strictly inside: x must be
    // strictly right of ab (then ab is the edge `outer_edge` returns), then the two cross signs.
    let inside = |x: DVec2, a: DVec2, b: DVec2, before: DVec2, after: DVec2, other_len: usize| {
        if K::orient(a, b, x) != Orientation::Clockwise {
            return None;
        }
        let s1 = K::cross_sign(a, b, before, x);
        if s1 == Negative {
            return None;
        }
        let s2 = K::cross_sign(a, b, x, after);
        if s2 == Positive {
            return None;
        }
        Some(other_len >= 2 && (s1 == Zero || s2 == Zero))
    };
    let done = |c: Pair| certify_parallel::<K>(p, q, c).map(|parallel| (c, parallel));
    match pair {
        Pair::Vv(..) => done(pair),
        Pair::Ve(i, j) => {
            let (x, a, b) = (at(p, i), at(q, j), at(q, j + 1));
            match clamp::<K>(x, a, b) {
                Some(false) => done(Pair::Vv(i, wrap(j, q.len()))),
                Some(true) => done(Pair::Vv(i, wrap(j + 1, q.len()))),
                None if q.len() < 3 => done(pair),
                None => inside(x, a, b, prev(p, i), at(p, i + 1), p.len()).map(|par| (pair, par)),
            }
        }
        Pair::Ev(i, j) => {
            let (y, a, b) = (at(q, j), at(p, i), at(p, i + 1));
            match clamp::<K>(y, a, b) {
                Some(false) => done(Pair::Vv(wrap(i, p.len()), j)),
                Some(true) => done(Pair::Vv(wrap(i + 1, p.len()), j)),
                None if p.len() < 3 => done(pair),
                None => inside(y, a, b, prev(q, j), at(q, j + 1), q.len()).map(|par| (pair, par)),
            }
        }
    }
}

/// Whether both support faces are edges (parallel facing edges), for a certified canonical pair.
fn parallel<K: Kernel>(p: &[DVec2], q: &[DVec2], pair: Pair) -> bool {
    let zero = Sign::Zero;
    match pair {
        Pair::Vv(i, j) => {
            let (x, y) = (at(p, i), at(q, j));
            let face_p = p.len() >= 2
                && (K::dot_sign(prev(p, i), x, x, y) == zero
                    || K::dot_sign(x, at(p, i + 1), x, y) == zero);
            let face_q = q.len() >= 2
                && (K::dot_sign(prev(q, j), y, x, y) == zero
                    || K::dot_sign(y, at(q, j + 1), x, y) == zero);
            face_p && face_q
        }
        Pair::Ve(i, j) => {
            let (a, b, x) = (at(q, j), at(q, j + 1), at(p, i));
            p.len() >= 2
                && (K::cross_sign(a, b, prev(p, i), x) == zero
                    || K::cross_sign(a, b, x, at(p, i + 1)) == zero)
        }
        Pair::Ev(i, j) => {
            let (a, b, y) = (at(p, i), at(p, i + 1), at(q, j));
            q.len() >= 2
                && (K::cross_sign(a, b, prev(q, j), y) == zero
                    || K::cross_sign(a, b, y, at(q, j + 1)) == zero)
        }
    }
}

/// The caller's vertex for internal vertex `i`.
pub(crate) fn caller_vertex(poly: &ConvexPolygon, i: usize) -> Feature {
    Feature::Vertex(poly.source_index(wrap(i, poly.len())))
}

/// The caller's feature containing the point of internal edge `e` nearest to `x` (a segment's two
/// edges are one caller edge: use edge 0). A hull's lid is no caller feature; it is reported as the
/// caller's edge starting at the lid's first vertex (documented on [`Closest`]'s users).
///
/// Callers pass a point whose nearest point on the edge is strictly inside it (the foot of a canonical
/// vertex–edge pair, or a contact point that is no vertex): then a polygon that kept every caller vertex
/// maps the edge by indices alone, without predicates.
pub(crate) fn caller_on_edge<K: Kernel>(poly: &ConvexPolygon, e: usize, x: DVec2) -> Feature {
    let n = poly.len();
    if n >= 3 && poly.caller_len() == n && !poly.is_lid(wrap(e, n)) {
        // Internal edge e joins caller vertices s0 and s1, adjacent in the caller's ring (either order).
        let (s0, s1) = (
            poly.source_index(wrap(e, n)),
            poly.source_index(wrap(e + 1, n)),
        );
        return Feature::Edge(if s1 == wrap(s0 + 1, n) { s0 } else { s1 });
    }
    let e = if n == 2 { 0 } else { wrap(e, n) };
    poly.caller_feature_on_edge::<K>(e, x)
        .unwrap_or(Feature::Edge(poly.source_index(e)))
}

/// The finished [`Closest`] of a canonical pair (certified by the caller of this function).
pub(crate) fn finish<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon, pair: Pair) -> Closest {
    let parallel = parallel::<K>(pp.vertices(), qq.vertices(), pair);
    finish_with::<K>(pp, qq, pair, parallel)
}

/// [`finish`] with `parallel` already known (from [`certify_parallel`]).
pub(crate) fn finish_with<K: Kernel>(
    pp: &ConvexPolygon,
    qq: &ConvexPolygon,
    pair: Pair,
    parallel: bool,
) -> Closest {
    let (p, q) = (pp.vertices(), qq.vertices());
    // `b.vertex` is on `P` unless the pair is edge–vertex.
    let (b, vertex_on_p, feature_p, feature_q) = match pair {
        Pair::Vv(i, j) => (
            construct::vertex_vertex(at(p, i), at(q, j)),
            true,
            caller_vertex(pp, i),
            caller_vertex(qq, j),
        ),
        Pair::Ve(i, j) => {
            let x = at(p, i);
            (
                construct::vertex_edge(x, at(q, j), at(q, j + 1)),
                true,
                caller_vertex(pp, i),
                caller_on_edge::<K>(qq, j, x),
            )
        }
        Pair::Ev(i, j) => {
            let y = at(q, j);
            (
                construct::vertex_edge(y, at(p, i), at(p, i + 1)),
                false,
                caller_on_edge::<K>(pp, i, y),
                caller_vertex(qq, j),
            )
        }
    };
    let (point_p, point_q) = if vertex_on_p {
        (b.vertex, b.other)
    } else {
        (b.other, b.vertex)
    };
    Closest {
        distance: b.distance,
        squared_distance: b.squared,
        point_p,
        point_q,
        feature_p,
        feature_q,
        parallel,
    }
}

#[cfg(test)]
mod tests {
    use polydist_oracle::{SplitMix64, random_convex, random_convex_lattice};
    use polydist_polygon::predicates::{Exact, Robust};

    use super::*;

    /// `canonical_certified` is `canonical` then `certify_parallel`, for every vertex–vertex and
    /// vertex–edge pair of small lattice polygons (collinear and parallel edges, shared vertices,
    /// meeting polygons) and of random ones, both argument orders, under Robust and Exact.
    #[test]
    fn canonical_certified_is_canonical_then_certify() {
        fn check<K: Kernel>(p: &[DVec2], q: &[DVec2]) {
            for i in 0..p.len() {
                for j in 0..q.len() {
                    for pair in [Pair::Vv(i, j), Pair::Ve(i, j), Pair::Ev(i, j)] {
                        let c = canonical::<K>(p, q, pair);
                        let expected = certify_parallel::<K>(p, q, c).map(|par| (c, par));
                        assert_eq!(canonical_certified::<K>(p, q, pair), expected, "{pair:?}");
                    }
                }
            }
        }
        let mut rng = SplitMix64::new(3);
        for round in 0..300 {
            let (n, m) = (3 + round % 6, 3 + (round / 6) % 6);
            let (p, q) = if round % 3 == 0 {
                let shift = DVec2::new(2.0 + (round % 4) as f64, (round % 5) as f64 - 2.0);
                let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
                (p, random_convex(&mut rng, m, shift, 1.0))
            } else {
                let p = random_convex_lattice(&mut rng, n, 4);
                let q: Vec<DVec2> = random_convex_lattice(&mut rng, m, 4)
                    .into_iter()
                    .map(|v| v + DVec2::new((round % 9) as f64, 0.0))
                    .collect();
                (p, q)
            };
            let (Ok(pp), Ok(qq)) = (ConvexPolygon::try_new(&p), ConvexPolygon::try_new(&q)) else {
                continue;
            };
            let (p, q) = (pp.vertices(), qq.vertices());
            check::<Robust>(p, q);
            check::<Robust>(q, p);
            check::<Exact>(p, q);
        }
    }
}
