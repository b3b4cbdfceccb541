//! Brute-force twins: test references and benchmark baselines, never the main path.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::Feature;
use polydist_predicates::{Dist2, Kernel, Sign, is_valid_coordinate};

use crate::chain::validate;
use crate::construct::{vertex_edge, vertex_vertex};
use crate::error::{Chain, SeparationError};
use crate::result::ClosestPair;

/// `true` when the open segment `(p, q)` meets the closed segment `[a, b]` (exact under `K`; eight
/// degree-2 tests at most).
fn open_meets_closed<K: Kernel>(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> bool {
    // x strictly between p and q, for x on line pq.
    let strictly_between = |x: DVec2| {
        K::dot_sign(p, x, p, q) == Sign::Positive && K::dot_sign(q, x, q, p) == Sign::Positive
    };
    let o1 = K::orient(p, q, a).sign();
    let o2 = K::orient(p, q, b).sign();
    if o1.is_zero() && o2.is_zero() {
        // Collinear: the open interval (p, q) meets [a, b] iff [a, b] is not entirely at or before p,
        // nor entirely at or after q (positions along q − p).
        let before_or_at_p = |x: DVec2| K::dot_sign(p, x, p, q) != Sign::Positive;
        let after_or_at_q = |x: DVec2| K::dot_sign(q, x, q, p) != Sign::Positive;
        return !((before_or_at_p(a) && before_or_at_p(b))
            || (after_or_at_q(a) && after_or_at_q(b)));
    }
    if o1.is_zero() {
        return strictly_between(a);
    }
    if o2.is_zero() {
        return strictly_between(b);
    }
    if o1 == o2 {
        return false;
    }
    // Line pq crosses the open segment (a, b); the crossing is in (p, q) iff p, q are strictly on
    // opposite sides of line ab.
    let o3 = K::orient(a, b, p).sign();
    let o4 = K::orient(a, b, q).sign();
    !o3.is_zero() && !o4.is_zero() && o3 != o4
}

/// `true` when the open segment `(p, q)` meets no vertex or edge of the chain.
fn clear_of<K: Kernel>(p: DVec2, q: DVec2, chain: &[DVec2]) -> bool {
    match chain {
        [v] => !open_meets_closed::<K>(p, q, *v, *v),
        _ => chain
            .windows(2)
            .all(|e| !open_meets_closed::<K>(p, q, e[0], e[1])),
    }
}

/// The closest visible vertex pair of two chains separated by the line through `a` and `b`, by
/// trying every vertex pair and testing visibility against every edge: the twin of
/// [`closest_visible_vertices`](crate::closest_visible_vertices) (no monotonicity needed).
///
/// # Complexity
/// `O(n_p · n_q · (n_p + n_q))` exact degree-2 tests.
///
/// # Errors
/// The validation errors of [`closest_visible_vertices`](crate::closest_visible_vertices) except
/// `NotMonotone`; [`SeparationError::Inconsistent`] when no pair is visible (impossible for
/// separated chains under an exact kernel).
pub fn closest_visible_vertices_brute<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<ClosestPair, SeparationError> {
    validate::<K>(p, q, a, b)?;
    let mut best: Option<(usize, usize)> = None;
    for (i, &pi) in p.iter().enumerate() {
        for (j, &qj) in q.iter().enumerate() {
            if let Some((k, l)) = best {
                if K::cmp_dist4(pi, qj, p[k], q[l]) != Ordering::Less {
                    continue;
                }
            }
            if clear_of::<K>(pi, qj, p) && clear_of::<K>(pi, qj, q) {
                best = Some((i, j));
            }
        }
    }
    let (i, j) = best.ok_or(SeparationError::Inconsistent)?;
    Ok(vertex_vertex(
        p[i],
        q[j],
        Feature::Vertex(i),
        Feature::Vertex(j),
    ))
}

/// The separation `σ(P, Q)` of two polygonal chains (minimum distance between them) by trying every
/// vertex–vertex and vertex–edge pair with exact comparisons (`cmp_dist2`, degree ≤ 6): the twin for
/// the section-3 solver. Ties go to the first pair found (vertex–vertex, then `P`-vertex against
/// `Q`-edges, then `Q`-vertex against `P`-edges, in index order). Chains may intersect; the result is
/// then 0 at some vertex–edge pair only if a vertex lies on the other chain (crossings are not
/// detected).
///
/// # Complexity
/// `O(n_p · n_q)` exact tests.
///
/// # Errors
/// [`SeparationError::EmptyChain`] and [`SeparationError::InvalidCoordinate`].
pub fn separation_brute<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
) -> Result<ClosestPair, SeparationError> {
    for (chain, pts) in [(Chain::P, p), (Chain::Q, q)] {
        if pts.is_empty() {
            return Err(SeparationError::EmptyChain { chain });
        }
        if let Some(index) = pts
            .iter()
            .position(|v| !is_valid_coordinate(v.x) || !is_valid_coordinate(v.y))
        {
            return Err(SeparationError::InvalidCoordinate { chain, index });
        }
    }
    Ok(scan::<K>(p, q, false))
}

/// The scan behind [`separation_brute`] on valid, non-empty chains: every vertex–vertex pair, then
/// `P`-vertex against `Q`-edges, then `Q`-vertex against `P`-edges, ties to the first found. With
/// `interior_only`, vertex–edge pairs whose vertex does not project strictly inside the edge are
/// skipped (same answer, fewer comparisons: Amato's separator scans its subproblems this way).
/// `O(n_p · n_q)`.
pub(crate) fn scan<K: Kernel>(p: &[DVec2], q: &[DVec2], interior_only: bool) -> ClosestPair {
    #[derive(Clone, Copy)]
    enum Cand {
        Vv(usize, usize),
        PvQe(usize, usize),
        QvPe(usize, usize),
    }
    let dist = |c: Cand| match c {
        Cand::Vv(i, j) => Dist2::PointPoint(p[i], q[j]),
        Cand::PvQe(i, j) => Dist2::PointSegment(p[i], q[j], q[j + 1]),
        Cand::QvPe(j, i) => Dist2::PointSegment(q[j], p[i], p[i + 1]),
    };
    let mut best = Cand::Vv(0, 0);
    let mut consider = |c: Cand| {
        if K::cmp_dist2(dist(c), dist(best)) == Ordering::Less {
            best = c;
        }
    };
    for i in 0..p.len() {
        for j in 0..q.len() {
            consider(Cand::Vv(i, j));
        }
    }
    // A vertex–edge pair whose vertex does not project strictly inside the edge has the distance of
    // a vertex pair already compared, so it is never strictly better: `interior_only` skips it
    // after two degree-2 dot signs instead of a degree-6 comparison (the answer is the same).
    let inside = |v: DVec2, a: DVec2, b: DVec2| {
        !interior_only
            || (K::dot_sign(a, v, a, b) == Sign::Positive
                && K::dot_sign(b, v, b, a) == Sign::Positive)
    };
    for (i, &v) in p.iter().enumerate() {
        for (j, e) in q.windows(2).enumerate() {
            if inside(v, e[0], e[1]) {
                consider(Cand::PvQe(i, j));
            }
        }
    }
    for (j, &v) in q.iter().enumerate() {
        for (i, e) in p.windows(2).enumerate() {
            if inside(v, e[0], e[1]) {
                consider(Cand::QvPe(j, i));
            }
        }
    }
    // A vertex–edge candidate whose nearest point is an endpoint is never strictly better than that
    // vertex–vertex pair, which was considered first: so the winner's foot is strictly inside.
    match best {
        Cand::Vv(i, j) => vertex_vertex(p[i], q[j], Feature::Vertex(i), Feature::Vertex(j)),
        Cand::PvQe(i, j) => {
            let (squared, distance, foot) = vertex_edge(p[i], q[j], q[j + 1]);
            ClosestPair {
                distance,
                squared_distance: squared,
                point_p: p[i],
                point_q: foot,
                feature_p: Feature::Vertex(i),
                feature_q: Feature::Edge(j),
            }
        }
        Cand::QvPe(j, i) => {
            let (squared, distance, foot) = vertex_edge(q[j], p[i], p[i + 1]);
            ClosestPair {
                distance,
                squared_distance: squared,
                point_p: foot,
                point_q: q[j],
                feature_p: Feature::Edge(i),
                feature_q: Feature::Vertex(j),
            }
        }
    }
}
