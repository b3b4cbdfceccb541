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

/// A candidate pair of the scans: vertex–vertex `(i, j)`, `P`-vertex `i` against `Q`-edge `j`,
/// `Q`-vertex `j` against `P`-edge `i` (stored as `(j, i)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Cand {
    Vv(usize, usize),
    PvQe(usize, usize),
    QvPe(usize, usize),
}

impl Cand {
    fn dist(self, p: &[DVec2], q: &[DVec2]) -> Dist2 {
        match self {
            Cand::Vv(i, j) => Dist2::PointPoint(p[i], q[j]),
            Cand::PvQe(i, j) => Dist2::PointSegment(p[i], q[j], q[j + 1]),
            Cand::QvPe(j, i) => Dist2::PointSegment(q[j], p[i], p[i + 1]),
        }
    }

    /// The pair, with its distance and nearest points constructed once.
    fn pair(self, p: &[DVec2], q: &[DVec2]) -> ClosestPair {
        match self {
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
}

/// Whether the vertex–edge candidate `c` is taken: always, or with `interior_only` when its vertex
/// projects strictly inside the edge (otherwise a vertex pair has its distance and comes first in
/// the scan's order, so it never wins).
fn admitted<K: Kernel>(c: Cand, p: &[DVec2], q: &[DVec2], interior_only: bool) -> bool {
    let inside = |v: DVec2, a: DVec2, b: DVec2| {
        K::dot_sign(a, v, a, b) == Sign::Positive && K::dot_sign(b, v, b, a) == Sign::Positive
    };
    !interior_only
        || match c {
            Cand::Vv(..) => true,
            Cand::PvQe(i, j) => inside(p[i], q[j], q[j + 1]),
            Cand::QvPe(j, i) => inside(q[j], p[i], p[i + 1]),
        }
}

/// The scan behind [`separation_brute`] on valid, non-empty chains: every vertex–vertex pair, then
/// `P`-vertex against `Q`-edges, then `Q`-vertex against `P`-edges, ties to the first found (the
/// least [`Cand`] in that order). With `interior_only`, vertex–edge pairs whose vertex does not
/// project strictly inside the edge are skipped (same answer, fewer comparisons: Amato's separator
/// scans its subproblems this way). `O(n_p · n_q)`.
pub(crate) fn scan<K: Kernel>(p: &[DVec2], q: &[DVec2], interior_only: bool) -> ClosestPair {
    let mut best = Cand::Vv(0, 0);
    let mut consider = |c: Cand| {
        if admitted::<K>(c, p, q, interior_only)
            && K::cmp_dist2(c.dist(p, q), best.dist(p, q)) == Ordering::Less
        {
            best = c;
        }
    };
    for i in 0..p.len() {
        for j in 0..q.len() {
            consider(Cand::Vv(i, j));
        }
    }
    for i in 0..p.len() {
        for j in 0..q.len().saturating_sub(1) {
            consider(Cand::PvQe(i, j));
        }
    }
    for j in 0..q.len() {
        for i in 0..p.len().saturating_sub(1) {
            consider(Cand::QvPe(j, i));
        }
    }
    // A vertex–edge candidate whose nearest point is an endpoint is never strictly better than that
    // vertex–vertex pair, which was considered first: so the winner's foot is strictly inside.
    best.pair(p, q)
}

/// A node of [`scan_pruned`]'s box hierarchy over a chain: it owns the vertices `s..e` and the
/// edges starting at them (edge `k` joins `k` and `k + 1`), and its box holds every vertex from `s`
/// to `e` (the far end of its last edge) included.
struct BoxNode {
    s: usize,
    e: usize,
    lo: DVec2,
    hi: DVec2,
    kids: Option<(usize, usize)>,
}

/// The box hierarchy of a chain: nodes of at most `LEAF` owned vertices, split in halves.
fn boxes(c: &[DVec2]) -> Vec<BoxNode> {
    const LEAF: usize = 8;
    fn build(c: &[DVec2], s: usize, e: usize, out: &mut Vec<BoxNode>) -> usize {
        let last = e.min(c.len() - 1);
        let (lo, hi) = c[s..=last]
            .iter()
            .fold((c[s], c[s]), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let id = out.len();
        out.push(BoxNode {
            s,
            e,
            lo,
            hi,
            kids: None,
        });
        if e - s > LEAF {
            let m = s + (e - s) / 2;
            let a = build(c, s, m, out);
            let b = build(c, m, e, out);
            out[id].kids = Some((a, b));
        }
        id
    }
    let mut out = Vec::with_capacity(c.len() / 4 + 2);
    build(c, 0, c.len(), &mut out);
    out
}

/// The squared distance between two boxes as an exact [`Dist2`]: a point pair whose coordinates
/// are box coordinates (no arithmetic), so the kernel compares it exactly.
fn box_gap(a: &BoxNode, b: &BoxNode) -> Dist2 {
    let axis = |alo: f64, ahi: f64, blo: f64, bhi: f64| {
        if ahi < blo {
            (ahi, blo)
        } else if bhi < alo {
            (alo, bhi)
        } else {
            (0.0, 0.0)
        }
    };
    let (xa, xb) = axis(a.lo.x, a.hi.x, b.lo.x, b.hi.x);
    let (ya, yb) = axis(a.lo.y, a.hi.y, b.lo.y, b.hi.y);
    Dist2::PointPoint(DVec2::new(xa, ya), DVec2::new(xb, yb))
}

/// [`scan`] with exact pruning: both chains get a hierarchy of bounding boxes, and a pair of nodes
/// is skipped when the squared distance between their boxes is exactly greater than the best
/// candidate's (every vertex and edge a node owns lies in its box, so none of its pairs can be
/// better). Ties are broken as in [`scan`] (the least [`Cand`] among the nearest), so the answer is
/// the scan's, feature for feature. The traversal order (nearer boxes first, by an `f64` estimate)
/// only affects speed. Worst case `O(n_p · n_q)` exact tests, like the scan; on subproblems whose
/// chains are long and mostly far from each other, far fewer. `O(n_p + n_q)` extra space.
pub(crate) fn scan_pruned<K: Kernel>(p: &[DVec2], q: &[DVec2], interior_only: bool) -> ClosestPair {
    let (bp, bq) = (boxes(p), boxes(q));
    let mut best = Cand::Vv(0, 0);
    let mut best_d = best.dist(p, q);
    let consider = |c: Cand, best: &mut Cand, best_d: &mut Dist2| {
        if !admitted::<K>(c, p, q, interior_only) {
            return;
        }
        let d = c.dist(p, q);
        match K::cmp_dist2(d, *best_d) {
            Ordering::Less => {
                *best = c;
                *best_d = d;
            }
            Ordering::Equal if c < *best => {
                *best = c;
                *best_d = d;
            }
            _ => {}
        }
    };
    let approx = |a: &BoxNode, b: &BoxNode| {
        let dx = (b.lo.x - a.hi.x).max(a.lo.x - b.hi.x).max(0.0);
        let dy = (b.lo.y - a.hi.y).max(a.lo.y - b.hi.y).max(0.0);
        dx * dx + dy * dy
    };
    let mut stack = vec![(0usize, 0usize)];
    while let Some((a, b)) = stack.pop() {
        let (na, nb) = (&bp[a], &bq[b]);
        if K::cmp_dist2(box_gap(na, nb), best_d) == Ordering::Greater {
            continue;
        }
        let split_a = match (na.kids, nb.kids) {
            (None, None) => {
                let pe = na.e.min(p.len() - 1);
                let qe = nb.e.min(q.len() - 1);
                for i in na.s..na.e {
                    for j in nb.s..nb.e {
                        consider(Cand::Vv(i, j), &mut best, &mut best_d);
                    }
                    for j in nb.s..qe {
                        consider(Cand::PvQe(i, j), &mut best, &mut best_d);
                    }
                }
                for j in nb.s..nb.e {
                    for i in na.s..pe {
                        consider(Cand::QvPe(j, i), &mut best, &mut best_d);
                    }
                }
                continue;
            }
            (Some(_), None) => true,
            (None, Some(_)) => false,
            (Some(_), Some(_)) => na.e - na.s >= nb.e - nb.s,
        };
        let mut next = match (split_a, na.kids, nb.kids) {
            (true, Some((x, y)), _) => [(x, b), (y, b)],
            (_, _, Some((x, y))) => [(a, x), (a, y)],
            _ => continue,
        };
        // Nearer pair popped first.
        if approx(&bp[next[0].0], &bq[next[0].1]) < approx(&bp[next[1].0], &bq[next[1].1]) {
            next.swap(0, 1);
        }
        stack.extend(next);
    }
    best.pair(p, q)
}
