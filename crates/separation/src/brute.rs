//! Brute-force twins: test references and benchmark baselines, never the main path; and the
//! candidate scans the separator runs on its small subproblems ([`scan`] and
//! [`scan_pruned_winner_below`] with `interior_only`), which add an exact pre-filter
//! ([`bounds`]) to the same answer.

use core::cell::{Cell, OnceCell};
use core::cmp::Ordering;
use core::ops::Range;

use glam::DVec2;
use polydist_polygon::Feature;
use polydist_predicates::{Dist2, Kernel, Sign, is_valid_coordinate};

use crate::chain::validate;
use crate::construct::{vertex_edge, vertex_vertex};
use crate::error::{Chain, SeparationError};
use crate::monotone::{Chord, Lens, reached};
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
    /// The candidate's distance as a scan compares it. With `interior_only` the scan admits only
    /// vertex–edge pairs whose foot is strictly inside the edge, so the line distance is theirs and
    /// saves the dot signs that locate the foot.
    #[inline]
    fn scan_dist<C: Points + ?Sized>(self, p: &C, q: &C, interior_only: bool) -> Dist2 {
        match self {
            Cand::PvQe(i, j) if interior_only => {
                let (a, b) = q.seg(j);
                Dist2::PointLine(p.at(i), a, b)
            }
            Cand::QvPe(j, i) if interior_only => {
                let (a, b) = p.seg(i);
                Dist2::PointLine(q.at(j), a, b)
            }
            _ => self.dist(p, q),
        }
    }

    /// [`bounds`] for an `interior_only` scan; no bounds (`(0, ∞)`) otherwise.
    fn scan_bounds<C: Points + ?Sized>(self, p: &C, q: &C, interior_only: bool) -> (f64, f64) {
        if interior_only {
            bounds(self, p, q)
        } else {
            (0.0, f64::INFINITY)
        }
    }

    #[inline]
    fn dist<C: Points + ?Sized>(self, p: &C, q: &C) -> Dist2 {
        match self {
            Cand::Vv(i, j) => Dist2::PointPoint(p.at(i), q.at(j)),
            Cand::PvQe(i, j) => {
                let (a, b) = q.seg(j);
                Dist2::PointSegment(p.at(i), a, b)
            }
            Cand::QvPe(j, i) => {
                let (a, b) = p.seg(i);
                Dist2::PointSegment(q.at(j), a, b)
            }
        }
    }

    /// The pair, with its distance and nearest points constructed once.
    fn pair(self, p: &[DVec2], q: &[DVec2]) -> ClosestPair {
        self.winner(p, q).pair()
    }

    /// The candidate with the points that realize it copied out of the chains.
    fn winner<C: Points + ?Sized>(self, p: &C, q: &C) -> Winner {
        let pts = match self {
            Cand::Vv(i, j) => [p.at(i), q.at(j), q.at(j)],
            Cand::PvQe(i, j) => {
                let (a, b) = q.seg(j);
                [p.at(i), a, b]
            }
            Cand::QvPe(j, i) => {
                let (a, b) = p.seg(i);
                [q.at(j), a, b]
            }
        };
        Winner { cand: self, pts }
    }
}

/// A chain as the scans read it: vertex `i`, and edge `e` as the segment it stands for.
pub(crate) trait Points {
    /// Whether edge `e` is always the segment between vertices `e` and `e + 1` (a chain), so that
    /// the vertices alone bound a block's edges.
    const JOINS_VERTICES: bool;
    /// The number of vertices.
    fn count(&self) -> usize;
    /// Vertex `i`.
    fn at(&self, i: usize) -> DVec2;
    /// The segment of edge `e` (between vertices `e` and `e + 1` in the scans' order).
    fn seg(&self, e: usize) -> (DVec2, DVec2);
}

/// A polygonal chain: edge `e` joins vertices `e` and `e + 1`.
impl Points for [DVec2] {
    const JOINS_VERTICES: bool = true;
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn at(&self, i: usize) -> DVec2 {
        self[i]
    }
    #[inline]
    fn seg(&self, e: usize) -> (DVec2, DVec2) {
        (self[e], self[e + 1])
    }
}

/// An envelope of Lemma 2 as [`scan_windowed`] reads it (`monotone::sweep_envelopes`): the
/// visible vertices `v`, strictly increasing in height, and for each `k` the whole edge `e[k]`
/// of the chain whose part between the heights of `v[k]` and `v[k + 1]` is the envelope there.
/// The edge may reach beyond those heights (behind a visible vertex, to a hidden end): its points
/// there are still points of the chain, so every distance the scan evaluates is a true one.
///
/// The keys of edge `k` are those of `v[k]` and `v[k + 1]` ([`Keys::far`], [`Boxes`]), which
/// bound its part on the envelope from the side that matters: that part is a segment from a
/// point at `v[k]`'s height no nearer to the line than `v[k]` (`v[k]` itself, or a shadow point
/// behind it) to one at `v[k + 1]`'s height no nearer than `v[k + 1]`, so its positions `t` lie
/// between the two vertices' and its depths are at least the lesser of theirs. The other chain
/// lies on the other closed side of the line, so the gap across the line from any of its points
/// is at least the gap to that lesser depth, and the box's lower bound of the distance holds.
pub(crate) struct Carried<'a> {
    pub(crate) v: &'a [DVec2],
    pub(crate) e: &'a [(DVec2, DVec2)],
}

impl Points for Carried<'_> {
    const JOINS_VERTICES: bool = false;
    #[inline]
    fn count(&self) -> usize {
        self.v.len()
    }
    #[inline]
    fn at(&self, i: usize) -> DVec2 {
        self.v[i]
    }
    #[inline]
    fn seg(&self, e: usize) -> (DVec2, DVec2) {
        self.e[e]
    }
}

/// A scan's winner: the candidate and its points in chain order (a vertex, then the other vertex
/// or the edge's two ends), so that its pair can be constructed later, exactly as the scan would,
/// after the chains themselves are gone. The separator keeps one per subproblem and constructs the
/// pair of the overall winner only.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Winner {
    cand: Cand,
    pts: [DVec2; 3],
}

impl Winner {
    /// The same winner for the chains read backwards: `P` (when `p` holds its length) and/or `Q`
    /// reversed, vertex `k` becoming `n − 1 − k` and edge `k` becoming `n − 2 − k`.
    pub(crate) fn reversed(self, p: Option<usize>, q: Option<usize>) -> Winner {
        let v = |k: usize, n: Option<usize>| n.map_or(k, |n| n - 1 - k);
        let e = |k: usize, n: Option<usize>| n.map_or(k, |n| n - 2 - k);
        let cand = match self.cand {
            Cand::Vv(i, j) => Cand::Vv(v(i, p), v(j, q)),
            Cand::PvQe(i, j) => Cand::PvQe(v(i, p), e(j, q)),
            Cand::QvPe(j, i) => Cand::QvPe(v(j, q), e(i, p)),
        };
        Winner { cand, ..self }
    }

    /// The chain-local features: `P`'s, then `Q`'s.
    pub(crate) fn features(&self) -> (Feature, Feature) {
        match self.cand {
            Cand::Vv(i, j) => (Feature::Vertex(i), Feature::Vertex(j)),
            Cand::PvQe(i, j) => (Feature::Vertex(i), Feature::Edge(j)),
            Cand::QvPe(j, i) => (Feature::Edge(i), Feature::Vertex(j)),
        }
    }

    /// The pair with chain-local features, its distance and nearest points constructed.
    pub(crate) fn pair(&self) -> ClosestPair {
        let [x, a, b] = self.pts;
        let (feature_p, feature_q) = self.features();
        match self.cand {
            Cand::Vv(..) => vertex_vertex(x, a, feature_p, feature_q),
            Cand::PvQe(..) | Cand::QvPe(..) => {
                let (squared, distance, foot) = vertex_edge(x, a, b);
                let (point_p, point_q) = if matches!(self.cand, Cand::PvQe(..)) {
                    (x, foot)
                } else {
                    (foot, x)
                };
                ClosestPair {
                    distance,
                    squared_distance: squared,
                    point_p,
                    point_q,
                    feature_p,
                    feature_q,
                }
            }
        }
    }
}

/// The squared distance of a scan's winner, given as chain-local features (a vertex of `p` or
/// `q`, and a vertex or edge of the other), for the tests to compare exactly.
#[cfg(test)]
pub(crate) fn feature_dist(p: &[DVec2], q: &[DVec2], (f, g): (Feature, Feature)) -> Dist2 {
    match (f, g) {
        (Feature::Vertex(i), Feature::Vertex(j)) => Dist2::PointPoint(p[i], q[j]),
        (Feature::Vertex(i), Feature::Edge(j)) => Dist2::PointSegment(p[i], q[j], q[j + 1]),
        (Feature::Edge(i), Feature::Vertex(j)) => Dist2::PointSegment(q[j], p[i], p[i + 1]),
        (Feature::Edge(_), Feature::Edge(_)) => panic!("a scan's winner has a vertex"),
    }
}

/// The bounds of `c` ([`Cand::scan_bounds`]) unless a scan skips it: with `interior_only`, when its
/// lower bound is strictly above `u2` (the best's upper bound or the cut, whichever is smaller), or
/// when it is a vertex–edge pair whose vertex does not project strictly inside the edge (a vertex
/// pair then has its distance and comes first in the scan's order, so it never wins). Without
/// `interior_only` every candidate is kept, with no bounds (`(0, ∞)`).
///
/// Either test may come first (both are certain); the cheaper one does. The bounds of a point pair
/// or of a horizontal or vertical edge are a subtraction and a square, cheaper than the foot test's
/// two dot signs; the others cost two divisions, and on a star's tips facing a curved wall most
/// candidates fail the foot test (their edges' lines pass near the tip, the feet outside). With
/// `BOUNDS_FIRST` the bounds come first for every edge: in the plain scans of small subproblems
/// (the separator's comb teeth, jittered: both chains short and nearly parallel to each other) most
/// vertex–edge candidates lie farther from the edge's line than the best, and the bounds rule them
/// out where the foot test would not.
#[inline(always)]
fn filter<K: Kernel, C: Points + ?Sized, const BOUNDS_FIRST: bool>(
    c: Cand,
    p: &C,
    q: &C,
    interior_only: bool,
    u2: f64,
) -> Option<(f64, f64)> {
    if !interior_only {
        return Some((0.0, f64::INFINITY));
    }
    // Neither a lower bound nor `u2` is ever NaN (the bounds give up to `(0, ∞)`), so `lo <= u2`
    // is "not strictly above the best or the cut".
    let (v, s, t) = match c {
        Cand::Vv(i, j) => {
            let b = squared_bounds(p.at(i) - q.at(j));
            return (b.0 <= u2).then_some(b);
        }
        Cand::PvQe(i, j) => {
            let (s, t) = q.seg(j);
            (p.at(i), s, t)
        }
        Cand::QvPe(j, i) => {
            let (s, t) = p.seg(i);
            (q.at(j), s, t)
        }
    };
    if BOUNDS_FIRST || s.x == t.x || s.y == t.y {
        let b = edge_bounds(v, s, t);
        (b.0 <= u2 && foot_inside::<K>(v, s, t)).then_some(b)
    } else if foot_inside::<K>(v, s, t) {
        let b = edge_bounds(v, s, t);
        (b.0 <= u2).then_some(b)
    } else {
        None
    }
}

/// Whether the foot of `v` on the line through `a` and `b` lies strictly inside the segment: two
/// exact dot signs.
#[inline]
fn foot_inside<K: Kernel>(v: DVec2, a: DVec2, b: DVec2) -> bool {
    K::dot_sign(a, v, a, b) == Sign::Positive && K::dot_sign(b, v, b, a) == Sign::Positive
}

/// [`Kernel::cmp_dist2`] for the scans, with a shortcut under the exact kernels for the two
/// distances' common form on rectilinear input: when both are [`axis_gap`]s, their order is that of
/// the two gaps (exact, so the answer is the kernel's without its exact stage, which every tie
/// would otherwise pay). Out of line: only near ties get here, and the scans' loops stay small.
#[inline(never)]
pub(crate) fn cmp_scan<K: Kernel>(x: Dist2, y: Dist2) -> Ordering {
    cmp_scan_below::<K>(x, y, f64::INFINITY)
}

/// [`cmp_scan`] of a distance `x` against a best distance `y` whose square is at most `cut` (an
/// upper bound, [`upper_bound`]): under the exact kernels, after the shortcut for coordinate gaps,
/// an `x` whose lower bound ([`lower_bound`]) is strictly above `cut` is farther, with no exact
/// comparison (the separator's subproblem winners against the best so far: most are farther, and
/// few are gaps along an axis unless they tie). The same order as [`cmp_scan`].
#[inline(never)]
pub(crate) fn cmp_scan_cut<K: Kernel>(x: Dist2, y: Dist2, cut: f64) -> Ordering {
    cmp_scan_below::<K>(x, y, cut)
}

/// The body of [`cmp_scan`] and [`cmp_scan_cut`] (an infinite `cut` tests no bound).
#[inline(always)]
fn cmp_scan_below<K: Kernel>(x: Dist2, y: Dist2, cut: f64) -> Ordering {
    if K::EXACT_DECISIONS {
        if let (Some(gx), Some(gy)) = (axis_gap(x), axis_gap(y)) {
            return gx.total_cmp(&gy);
        }
        if cut < f64::INFINITY && lower_bound(x) > cut {
            return Ordering::Greater;
        }
        if congruent(x, y) {
            return Ordering::Equal;
        }
    }
    K::cmp_dist2(x, y)
}

/// Whether two distances are certainly equal because one configuration is the other moved by a
/// symmetry of the square lattice (a translation, then a signed permutation of the axes): both are
/// the same form, their difference vectors (`p − q`; or `v − a` and `b − a`, or for the second
/// distance also `v − b` and `a − b`, the segment read from its other end) are computed without
/// rounding, and one signed permutation maps the first's vectors onto the second's. A signed
/// permutation is an isometry, so the two distances are the same real number. Repeated shapes
/// (saw-teeth, comb teeth, any pattern copied along the axes) tie this way at every copy, and each
/// tie would otherwise pay the kernel's exact stage (about 870 instructions under Robust).
fn congruent(x: Dist2, y: Dist2) -> bool {
    // The maps are tested on the rounded differences first, and the differences they used are then
    // checked to be exact: exact differences are their own roundings, so a configuration that
    // fails the cheap test is never congruent (the common case on decimal input, where copies
    // moved along an axis round differently), and one that passes it is only when no difference
    // rounded.
    let exact =
        |a: DVec2, b: DVec2| exact_diff(a.x, b.x).is_some() && exact_diff(a.y, b.y).is_some();
    // Some signed permutation maps `d[0]` to `e[0]` and `d[1]` to `e[1]`: each axis of `e` is one
    // axis of `d` (both vectors' components), times one sign for both vectors. The eight maps in
    // two tests: the axes kept, or swapped.
    let maps = |d: [DVec2; 2], e: [DVec2; 2]| {
        let axis =
            |d0: f64, d1: f64, e0: f64, e1: f64| (e0 == d0 && e1 == d1) || (e0 == -d0 && e1 == -d1);
        (axis(d[0].x, d[1].x, e[0].x, e[1].x) && axis(d[0].y, d[1].y, e[0].y, e[1].y))
            || (axis(d[0].y, d[1].y, e[0].x, e[1].x) && axis(d[0].x, d[1].x, e[0].y, e[1].y))
    };
    match (x, y) {
        (Dist2::PointPoint(p, q), Dist2::PointPoint(r, s)) => {
            maps([p - q, DVec2::ZERO], [r - s, DVec2::ZERO]) && exact(p, q) && exact(r, s)
        }
        (Dist2::PointLine(v, a, b), Dist2::PointLine(w, c, e))
        | (Dist2::PointSegment(v, a, b), Dist2::PointSegment(w, c, e)) => {
            let (d0, d1, e1) = (v - a, b - a, e - c);
            let first = || exact(v, a) && exact(b, a);
            // The second segment read from either end: `w − c` and `e − c`, or `w − e` and
            // `c − e = −(e − c)`.
            (maps([d0, d1], [w - c, e1]) && first() && exact(w, c) && exact(e, c))
                || (maps([d0, d1], [w - e, -e1]) && first() && exact(w, e) && exact(e, c))
        }
        _ => false,
    }
}

/// `x − y` when it rounds to itself (Knuth's TwoSum error of `x + (−y)` is zero). `None` otherwise.
fn exact_diff(x: f64, y: f64) -> Option<f64> {
    let s = x - y;
    let yv = s - x;
    let xv = s - yv;
    let err = (x - xv) + (-y - yv);
    (err == 0.0 && s.is_finite()).then_some(s)
}

/// The distance `d ≥ 0` of a [`Dist2`], exactly, when it is the difference of two coordinates
/// computed without rounding: two points on a horizontal or vertical line, a point and the line
/// of a horizontal or vertical edge (`a ≠ b`), or a point and such a segment when the point's
/// projection falls on it (closed; exact coordinate comparisons). `None` otherwise.
fn axis_gap(d: Dist2) -> Option<f64> {
    match d {
        Dist2::PointPoint(p, q) if p.y == q.y => exact_gap(p.x, q.x),
        Dist2::PointPoint(p, q) if p.x == q.x => exact_gap(p.y, q.y),
        Dist2::PointLine(v, a, b) if a.x == b.x && a.y != b.y => exact_gap(v.x, a.x),
        Dist2::PointLine(v, a, b) if a.y == b.y && a.x != b.x => exact_gap(v.y, a.y),
        // A point and a horizontal or vertical segment, the point's projection on it.
        Dist2::PointSegment(v, a, b)
            if a.x == b.x && a.y != b.y && a.y.min(b.y) <= v.y && v.y <= a.y.max(b.y) =>
        {
            exact_gap(v.x, a.x)
        }
        Dist2::PointSegment(v, a, b)
            if a.y == b.y && a.x != b.x && a.x.min(b.x) <= v.x && v.x <= a.x.max(b.x) =>
        {
            exact_gap(v.y, a.y)
        }
        _ => None,
    }
}

/// `|x − y|` when `x − y` rounds to itself (Knuth's TwoSum error of `x + (−y)` is zero; no overflow
/// for valid coordinates, and sums are exact in the subnormal range). `None` otherwise.
fn exact_gap(x: f64, y: f64) -> Option<f64> {
    exact_diff(x, y).map(f64::abs)
}

/// `2⁻⁹⁰⁰`: below it [`bounds`] gives up (no underflow reasoning near the subnormal range).
const BOUNDS_TINY: f64 = f64::from_bits((1023 - 900) << 52);
/// Unit roundoff `u = 2⁻⁵³`.
const BOUNDS_U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// `4u + 64u²`: the relative error of a sum of two squares of rounded differences, and of a
/// difference of two products of rounded differences relative to the sum of the products' magnitudes
/// (the Robust kernel's static filter constants; derivation in `docs/ROBUSTNESS.md`).
const BOUNDS_ERR: f64 = 4.0 * BOUNDS_U + 64.0 * BOUNDS_U * BOUNDS_U;
/// `4u`, the slack for the at most three roundings of a bound's final arithmetic.
const BOUNDS_SLACK: f64 = 4.0 * BOUNDS_U;

/// Rigorous bounds `lo ≤ D ≤ hi` on a candidate's exact squared distance `D`, from plain `f64`
/// arithmetic and a static error bound (no decision is taken on a rounded value: the bounds only let
/// a scan skip a candidate that certainly loses, or take one that certainly wins).
///
/// For a vertex–edge candidate the bounds are those of the distance to the edge's *line*, which is
/// never larger than the distance to the segment (so `lo` bounds every candidate) and equals it when
/// the foot is strictly inside the edge (so `hi` bounds the admitted candidates of an
/// `interior_only` scan, the only ones that can become the best). For a vertical or horizontal
/// edge that line distance is one coordinate difference, bounded as a point pair's.
///
/// Why they hold. A sum of two squares of rounded differences `ŝ` is within `(4u + 20u²)ŝ` of the
/// exact value, and a difference of two products of rounded differences `ĉ = t̂₁ − t̂₂` within
/// `(4u + 12u²)(|t̂₁| + |t̂₂|)` (`docs/ROBUSTNESS.md`, the static filters); the computed error `e`, with
/// the constant `4u + 64u²`, is at least that after its own two roundings, and at least `u|v|` for
/// the value `v` it bounds. So `fl(v − 2e) ≤ v − e` and `fl(v + 2e) ≥ v + e` (one rounding costs at
/// most `u|v| ≤ e`). The quotient `a²/l` of the bounded numerator and denominator takes at most three
/// more roundings, covered by the factor `1 ∓ 4u`. Underflow: every quantity is at least `2⁻⁹⁰⁰` or
/// the bound gives up (`lo = 0`, or `(0, ∞)`), so an underflowed product (at most `2⁻¹⁰⁷⁴` off) is
/// inside the `64u²` slack. Non-finite values give `(0, ∞)`.
fn bounds<C: Points + ?Sized>(c: Cand, p: &C, q: &C) -> (f64, f64) {
    match c {
        Cand::Vv(i, j) => squared_bounds(p.at(i) - q.at(j)),
        Cand::PvQe(i, j) => {
            let (s, t) = q.seg(j);
            edge_bounds(p.at(i), s, t)
        }
        Cand::QvPe(j, i) => {
            let (s, t) = p.seg(i);
            edge_bounds(q.at(j), s, t)
        }
    }
}

/// [`bounds`] for a point pair: those of `|d|²` for the rounded difference vector `d`.
#[inline]
fn squared_bounds(d: DVec2) -> (f64, f64) {
    let sq = d.x * d.x + d.y * d.y;
    let e = BOUNDS_ERR * sq;
    let (lo, hi) = (sq - (e + e), sq + (e + e));
    if sq.is_finite() && lo >= BOUNDS_TINY {
        (lo, hi)
    } else {
        (0.0, f64::INFINITY)
    }
}

/// [`bounds`] for the point `v` and the edge from `s` to `t`: those of the distance to its line.
#[inline]
fn edge_bounds(v: DVec2, s: DVec2, t: DVec2) -> (f64, f64) {
    // A vertical or horizontal edge: the squared distance to its line is that of one coordinate
    // difference (rectilinear input: comb teeth), bounded as a point pair's.
    if s.x == t.x && s.y != t.y {
        return squared_bounds(DVec2::new(v.x - s.x, 0.0));
    }
    if s.y == t.y && s.x != t.x {
        return squared_bounds(DVec2::new(0.0, v.y - s.y));
    }
    let (e, w) = (t - s, v - s);
    quotient_bounds(e.x * w.y, e.y * w.x, e).map_or((0.0, f64::INFINITY), |(lo, hi, _)| (lo, hi))
}

/// Bounds `lo ≤ (t₁ − t₂)²/|e|² ≤ hi` for products `t₁`, `t₂` of rounded coordinate differences
/// (a cross or, with `t₂` negated, a dot product of two difference vectors) and a rounded
/// difference vector `e`, with the sign of `t₁ − t₂` when it is certain (else `Zero`); [`bounds`]
/// gives the analysis. `None` on overflow, for a tiny `e`, or for products small enough to have
/// underflowed.
fn quotient_bounds(t1: f64, t2: f64, e: DVec2) -> Option<(f64, f64, Sign)> {
    let cr = t1 - t2;
    let cr_err = BOUNDS_ERR * (t1.abs() + t2.abs());
    let len = e.x * e.x + e.y * e.y;
    let len_err = BOUNDS_ERR * len;
    let c_abs = cr.abs();
    let (c_lo, c_hi) = (c_abs - (cr_err + cr_err), c_abs + (cr_err + cr_err));
    let (l_lo, l_hi) = (len - (len_err + len_err), len + (len_err + len_err));
    if !(c_hi.is_finite() && l_hi.is_finite()) || l_lo < BOUNDS_TINY || cr_err < BOUNDS_TINY {
        // Overflow, a tiny edge, or products small enough to have underflowed: no bound.
        return None;
    }
    let (hi_num, lo_num) = (c_hi * c_hi, c_lo.max(0.0) * c_lo.max(0.0));
    if !hi_num.is_finite() {
        // An overflowing square (coordinates near 2^500): no bound.
        return None;
    }
    let hi = (hi_num / l_lo) * (1.0 + BOUNDS_SLACK);
    if hi < BOUNDS_TINY {
        // The quotient may have lost bits to underflow: no bound.
        return None;
    }
    // The computed difference is within `cr_err` of the exact one, so a margin of twice that
    // fixes the sign.
    let sign = if c_lo > 0.0 {
        Sign::of_f64(cr)
    } else {
        Sign::Zero
    };
    // A numerator or quotient below 2^-900 may have lost bits to underflow: the lower bound is 0.
    let lo = if lo_num < BOUNDS_TINY {
        0.0
    } else {
        (lo_num / l_hi) * (1.0 - BOUNDS_SLACK)
    };
    Some((if lo < BOUNDS_TINY { 0.0 } else { lo }, hi, sign))
}

/// Where the pairs of a separator subproblem lie. Lemma 1 gives subproblem `i` only pairs whose
/// segment meets its separator `l_i` (notes 4.8, `docs/algorithms/separator.md`), so each point of
/// such a pair lies within the pair's distance of `l_i`: a point farther from `l_i` than the best
/// distance known is in no pair the subproblem has to find. `l_i` lies on the line through `a` and
/// `c`, and its positions along that line, `t(x) = (x − a)·(c − a)`, are at least the lesser of the
/// two `before` points' and at most the greater of the two `after` points' (a separator's end
/// inside an edge lies between the edge's ends).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Near {
    pub(crate) a: DVec2,
    pub(crate) c: DVec2,
    pub(crate) before: [DVec2; 2],
    pub(crate) after: [DVec2; 2],
}

impl Near {
    /// A lower bound of the squared distance from every point of the box `lo..=hi` to `l_i`: the
    /// box lies wholly on one side of the line, before `l_i`'s start or after its end, by at least
    /// that much at each corner (and so everywhere in it: each is a half-plane). `0` when no such
    /// bound is certain. At most twenty [`quotient_bounds`].
    pub(crate) fn box_gap2(&self, lo: DVec2, hi: DVec2) -> f64 {
        let corners = [lo, DVec2::new(hi.x, lo.y), DVec2::new(lo.x, hi.y), hi];
        let d = self.c - self.a;
        // The least lower bound over the corners of a quantity that must have the sign `want` at
        // every corner; `None` when one corner's sign is not certainly `want`.
        let least = |f: &dyn Fn(DVec2) -> Option<(f64, f64, Sign)>, want: Sign| {
            corners.iter().try_fold(f64::INFINITY, |m, &x| match f(x) {
                Some((b, _, s)) if s == want => Some(m.min(b)),
                _ => None,
            })
        };
        // Depth: `d × (x − a)`; before `y`: `(y − x)·d`; after `y`: `(x − y)·d`.
        let depth = |x: DVec2| {
            let w = x - self.a;
            quotient_bounds(d.x * w.y, d.y * w.x, d)
        };
        let along = |w: DVec2| quotient_bounds(d.x * w.x, -(d.y * w.y), d);
        let sides = [
            least(&depth, Sign::Positive),
            least(&depth, Sign::Negative),
            least(&|x| along(self.before[0] - x), Sign::Positive)
                .zip(least(&|x| along(self.before[1] - x), Sign::Positive))
                .map(|(u, v)| u.min(v)),
            least(&|x| along(x - self.after[0]), Sign::Positive)
                .zip(least(&|x| along(x - self.after[1]), Sign::Positive))
                .map(|(u, v)| u.min(v)),
        ];
        sides.into_iter().flatten().fold(0.0, f64::max)
    }
}

/// The scan behind [`separation_brute`] on valid, non-empty chains: every vertex–vertex pair, then
/// `P`-vertex against `Q`-edges, then `Q`-vertex against `P`-edges, ties to the first found (the
/// least [`Cand`] in that order). With `interior_only`, vertex–edge pairs whose vertex does not
/// project strictly inside the edge are skipped (same answer, fewer comparisons: Amato's separator
/// scans its subproblems this way). `O(n_p · n_q)`.
pub(crate) fn scan<K: Kernel>(p: &[DVec2], q: &[DVec2], interior_only: bool) -> ClosestPair {
    scan_best::<K>(p, q, interior_only, f64::INFINITY, Seen::NONE)
        .0
        .pair(p, q)
}

/// An `interior_only` [`scan`] that need only beat a distance known elsewhere, whose square is at
/// most `cut`: candidates whose squared distance is bounded strictly above `cut` are skipped. The
/// winner, nothing constructed yet, and an upper bound of its squared distance (`∞` when unknown).
/// If some pair is strictly nearer than the known distance the winner is the scan's nearest pair;
/// otherwise it is some pair of the chains (a true distance, never below the nearest).
#[cfg(test)]
pub(crate) fn scan_winner_below<K: Kernel>(p: &[DVec2], q: &[DVec2], cut: f64) -> (Winner, f64) {
    scan_winner_below_except::<K>(p, q, cut, Seen::NONE)
}

/// `scan_winner_below` without the candidates of `seen`, pairs an earlier scan already took
/// (see [`Seen`]): the winner is then the nearest pair of the others when that is strictly nearer
/// than `√cut`, and some pair of the chains otherwise. Every candidate left out has both features
/// in `seen`'s ranges, so a caller that folds the two scans' winners finds the same minimum.
pub(crate) fn scan_winner_below_except<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    cut: f64,
    seen: Seen,
) -> (Winner, f64) {
    let (c, hi) = scan_best::<K>(p, q, true, cut, seen);
    (c.winner(p, q), hi)
}

/// Vertices of the two chains whose candidates an earlier scan took: every vertex–vertex pair
/// with its `P` vertex in `p` and its `Q` vertex in `q` (local indices, half-open), and every
/// vertex–edge pair whose vertex and both edge ends are in them. Consecutive subproblems of the
/// separator share an edge at each end (a cut falls inside it and both subchains keep it whole), and
/// on small subproblems these pairs are a quarter of the scan.
#[derive(Clone, Debug)]
pub(crate) struct Seen {
    pub(crate) p: Range<usize>,
    pub(crate) q: Range<usize>,
}

impl Seen {
    /// No candidate seen.
    pub(crate) const NONE: Seen = Seen { p: 0..0, q: 0..0 };
}

/// [`scan`]'s loop; candidates bounded strictly above `cut` (squared) are skipped (`interior_only`
/// only: the bounds are those of the line distances), and so are those of `seen`. The winner and
/// its squared distance's upper bound. With every candidate skipped the winner is `Vv(0, 0)`, a
/// pair of the chains (its vertex–vertex pair is never skipped by the bounds: it is the initial
/// best).
fn scan_best<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    interior_only: bool,
    cut: f64,
    seen: Seen,
) -> (Cand, f64) {
    // A candidate bounded strictly above the best cannot win, one bounded strictly below it wins:
    // only overlapping bounds (near ties) need the exact comparison.
    fn all<K: Kernel, const I: bool>(
        p: &[DVec2],
        q: &[DVec2],
        cut: f64,
        seen: Seen,
    ) -> (Cand, f64) {
        let mut best = Best::<K, I, [DVec2], true>::new(p, q, cut);
        let mut consider = |c: Cand| best.consider(c);
        let (sp, sq) = (&seen.p, &seen.q);
        // Edge `k` is seen when both its ends are.
        let edge_seen = |r: &Range<usize>, k: usize| r.start <= k && k + 1 < r.end;
        for i in 0..p.len() {
            let ip = sp.contains(&i);
            for j in 0..q.len() {
                // `Vv(0, 0)` is the initial best: against itself it is `Equal` under every kernel.
                if (i > 0 || j > 0) && !(ip && sq.contains(&j)) {
                    consider(Cand::Vv(i, j));
                }
            }
        }
        for i in 0..p.len() {
            let ip = sp.contains(&i);
            for j in 0..q.len().saturating_sub(1) {
                if !(ip && edge_seen(sq, j)) {
                    consider(Cand::PvQe(i, j));
                }
            }
        }
        for j in 0..q.len() {
            let jq = sq.contains(&j);
            for i in 0..p.len().saturating_sub(1) {
                if !(jq && edge_seen(sp, i)) {
                    consider(Cand::QvPe(j, i));
                }
            }
        }
        // A vertex–edge candidate whose nearest point is an endpoint is never strictly better than
        // that vertex–vertex pair, which was considered first (here or, for a seen edge, by the
        // scan that saw it): so the winner's foot is strictly inside.
        (best.best, best.b.1)
    }
    if interior_only {
        all::<K, true>(p, q, cut, seen)
    } else {
        all::<K, false>(p, q, cut, seen)
    }
}

/// A node of `scan_pruned`'s box hierarchy over a chain: it owns the vertices `s..e` and the
/// edges starting at them (edge `k` joins `k` and `k + 1`), and its box holds every vertex from `s`
/// to `e` (the far end of its last edge) included.
struct BoxNode {
    s: usize,
    e: usize,
    lo: DVec2,
    hi: DVec2,
    kids: Option<(usize, usize)>,
}

/// The box hierarchy of a chain: nodes of at most `LEAF` owned vertices, split in halves. A leaf's
/// box is its vertices' (the far end of its last edge included), an inner node's the union of its
/// kids' (which hold the same vertices): `O(n)`, not a pass over each level.
fn boxes(c: &[DVec2]) -> Vec<BoxNode> {
    const LEAF: usize = 8;
    fn build(c: &[DVec2], s: usize, e: usize, out: &mut Vec<BoxNode>) -> usize {
        let id = out.len();
        out.push(BoxNode {
            s,
            e,
            lo: c[s],
            hi: c[s],
            kids: None,
        });
        let (lo, hi) = if e - s > LEAF {
            let m = s + (e - s) / 2;
            let a = build(c, s, m, out);
            let b = build(c, m, e, out);
            out[id].kids = Some((a, b));
            (out[a].lo.min(out[b].lo), out[a].hi.max(out[b].hi))
        } else {
            let last = e.min(c.len() - 1);
            c[s..=last]
                .iter()
                .fold((c[s], c[s]), |(lo, hi), &v| (lo.min(v), hi.max(v)))
        };
        (out[id].lo, out[id].hi) = (lo, hi);
        id
    }
    let mut out = Vec::with_capacity(c.len() / 4 + 2);
    build(c, 0, c.len(), &mut out);
    out
}

/// The squared distance between two boxes as an exact [`Dist2`]: a point pair whose coordinates
/// are box coordinates (no arithmetic), so the kernel compares it exactly.
fn box_gap(a: &BoxNode, b: &BoxNode) -> Dist2 {
    corner_gap((a.lo, a.hi), (b.lo, b.hi))
}

/// [`box_gap`] of two boxes given by their corners `(lo, hi)`.
fn corner_gap(a: (DVec2, DVec2), b: (DVec2, DVec2)) -> Dist2 {
    let ((alo, ahi), (blo, bhi)) = (a, b);
    let axis = |alo: f64, ahi: f64, blo: f64, bhi: f64| {
        if ahi < blo {
            (ahi, blo)
        } else if bhi < alo {
            (alo, bhi)
        } else {
            (0.0, 0.0)
        }
    };
    let (xa, xb) = axis(alo.x, ahi.x, blo.x, bhi.x);
    let (ya, yb) = axis(alo.y, ahi.y, blo.y, bhi.y);
    Dist2::PointPoint(DVec2::new(xa, ya), DVec2::new(xb, yb))
}

/// Whether every point of the box with corners `a = (lo, hi)` is certainly farther than `√cut`
/// from every point of the box `b` (the filter's lower bound of the squared gap exceeds `cut`; no
/// arithmetic on the corners, [`box_gap`]). `false` for an infinite `cut`.
pub(crate) fn boxes_farther_than(a: (DVec2, DVec2), b: (DVec2, DVec2), cut: f64) -> bool {
    gap_beyond(corner_gap(a, b), cut)
}

/// Whether the squared length of a [`box_gap`] is certainly greater than `cut` ([`bounds`]' lower
/// bound of it is).
fn gap_beyond(gap: Dist2, cut: f64) -> bool {
    match gap {
        Dist2::PointPoint(x, y) => {
            cut.is_finite() && bounds::<[DVec2]>(Cand::Vv(0, 0), &[x], &[y]).0 > cut
        }
        _ => false,
    }
}

/// [`scan`] with exact pruning: both chains get a hierarchy of bounding boxes, and a pair of nodes
/// is skipped when the squared distance between their boxes is exactly greater than the best
/// candidate's (every vertex and edge a node owns lies in its box, so none of its pairs can be
/// better). Ties are broken as in [`scan`] (the least [`Cand`] among the nearest), so the answer is
/// the scan's, feature for feature. The traversal order (nearer boxes first, by an `f64` estimate)
/// only affects speed. Worst case `O(n_p · n_q)` exact tests, like the scan; on subproblems whose
/// chains are long and mostly far from each other, far fewer. `O(n_p + n_q)` extra space.
#[cfg(test)]
pub(crate) fn scan_pruned<K: Kernel>(p: &[DVec2], q: &[DVec2], interior_only: bool) -> ClosestPair {
    scan_pruned_best::<K>(p, q, interior_only, f64::INFINITY, None)
        .0
        .pair(p, q)
}

/// `scan_winner_below` (a test reference) with the exact pruning of `scan_pruned` (another),
/// which also skips the pairs of boxes certainly farther apart than `√cut` (their candidates
/// cannot beat `cut`). With `near`, the box nodes whose points are all certainly farther from
/// `l_i` than the best candidate so far (or than `√cut`) are skipped as well: the winner is then
/// no farther than every pair with both points within its own length of `l_i` that beats `cut`,
/// and some pair of the chains otherwise.
pub(crate) fn scan_pruned_winner_below<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    cut: f64,
    near: Option<&Near>,
) -> (Winner, f64) {
    let (c, hi) = scan_pruned_best::<K>(p, q, true, cut, near);
    (c.winner(p, q), hi)
}

fn scan_pruned_best<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    interior_only: bool,
    cut: f64,
    near: Option<&Near>,
) -> (Cand, f64) {
    let (bp, bq) = (boxes(p), boxes(q));
    // Each node's lower bound of its squared distance to `l_i`, found when the node is first
    // tested (`NaN` before; none without `near`).
    let unknown = |nodes: &[BoxNode]| vec![f64::NAN; if near.is_some() { nodes.len() } else { 0 }];
    let (mut gp, mut gq) = (unknown(&bp), unknown(&bq));
    let far = |gaps: &mut [f64], nodes: &[BoxNode], k: usize, u: f64| {
        let (Some(n), Some(g)) = (near, gaps.get_mut(k)) else {
            return false;
        };
        if g.is_nan() {
            *g = n.box_gap2(nodes[k].lo, nodes[k].hi);
        }
        *g > u
    };
    let mut best = Cand::Vv(0, 0);
    let dist = |c: Cand| c.scan_dist(p, q, interior_only);
    let mut best_d = dist(best);
    // As in `scan`: with `interior_only`, candidates bounded strictly above the best (or above
    // `cut`) are skipped and candidates bounded strictly below it are taken.
    let best_b = core::cell::Cell::new(best.scan_bounds(p, q, interior_only));
    let consider = |c: Cand, best: &mut Cand, best_d: &mut Dist2| {
        let Some(b) = filter::<K, _, false>(c, p, q, interior_only, cut.min(best_b.get().1)) else {
            return;
        };
        let d = dist(c);
        let order = if b.1 < best_b.get().0 {
            Ordering::Less
        } else {
            cmp_scan::<K>(d, *best_d)
        };
        if order == Ordering::Less || (order == Ordering::Equal && c < *best) {
            *best = c;
            *best_d = d;
            best_b.set(b);
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
        // Boxes certainly farther apart than `√cut` hold no candidate the scan would take; nor
        // do boxes farther apart than the best candidate.
        let gap = box_gap(na, nb);
        if gap_beyond(gap, cut) || K::cmp_dist2(gap, best_d) == Ordering::Greater {
            continue;
        }
        // A node certainly farther from `l_i` than the best so far holds no point of a pair the
        // subproblem must find (`Near`).
        let u = cut.min(best_b.get().1);
        if far(&mut gp, &bp, a, u) || far(&mut gq, &bq, b, u) {
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
    (best, best_b.get().1)
}

/// The least and greatest of the computed depths `d` (`(∞, −∞)` for none).
fn depths(d: &[f64]) -> (f64, f64) {
    d.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (if x < lo { x } else { lo }, if x > hi { x } else { hi })
        })
}

/// The window of [`scan_windowed`] over the other chain's keys `ty`: its ends only move forward,
/// for keys `t` visited in non-decreasing exact order.
#[derive(Default)]
struct Window {
    lo: usize,
    hi: usize,
}

impl Window {
    /// The vertices `lo..hi` of `ty` not certainly farther than `w` from `t`: those before `lo`
    /// were certainly left of an earlier window (so of this one), the one at `hi` is certainly
    /// right of this one (and so is every later one).
    fn around(&mut self, t: f64, ty: &[f64], w: f64) -> (usize, usize) {
        while self.lo < ty.len() && t - ty[self.lo] > w {
            self.lo += 1;
        }
        self.hi = self.hi.max(self.lo);
        while self.hi < ty.len() && t - ty[self.hi] >= -w {
            self.hi += 1;
        }
        (self.lo, self.hi)
    }
}

/// [`scan`] (`interior_only`) over lateral windows, for two chains whose vertices come in
/// non-decreasing order of an exact key `t` (the monotone sweep, `monotone.rs`): `kp` and `kq` hold
/// approximations `t̂` of the keys and `d̂` of the depths `d` across the line, and `lens` their error
/// analysis ([`Lens`]): a window `W` such that a pair whose computed key gap exceeds `W` is
/// certainly farther apart than `U`, and a test that two boxes of keys are certainly farther apart
/// than `U` (`|x − y|²·|b − a|² = Δt² + Δd²`, so the gaps of `t` and of `d` bound a distance
/// together). `U²` is the current best candidate's squared-distance upper bound, so a skipped
/// candidate certainly loses.
///
/// A first pass takes each `P` vertex against the `Q` vertices next to it in key order, and a
/// descent from its best to strictly nearer neighbouring vertex pairs ([`Best::descend`]), so the
/// windows start narrow; then each `P` vertex against the `Q` vertices and edges in its window, and
/// each `Q` vertex against the `P` edges in its window. The window's ends only move forward:
/// vertices left behind were certainly out of an earlier, wider window of a smaller key, so of this
/// one too (exact keys are sorted); the first vertex certainly beyond the right end has every
/// later one beyond it. Inside the window the other chain is taken in blocks of [`BLOCK`]
/// consecutive vertices (with the edges between them): a block whose box of keys is certainly
/// farther than `U` is skipped whole, and so is one whose box in its own chord's frame is
/// ([`Chord`]: blocks tilted against the line, zigzags, arcs), and each candidate of the other
/// blocks is skipped when its own keys put it certainly farther than `U`, before its distance is
/// bounded. In the count (below), consecutive vertices of the pass's own chain go in teams that
/// share their coarse box tests ([`Team`]). On inputs whose windows along the line are crowded but whose depths differ by about
/// the clearance (walls of a corridor, sampled far more finely than it is wide) this leaves a few
/// candidates a vertex; on a star whose tips all face a zigzag wall tilted against the line within
/// a hair of the clearance, a few dozen.
///
/// The answer is the nearest pair of the chains (ties to the first found) and the candidates tried,
/// or `Err` with the work counted so far once that exceeds `budget`: the count is what the caller
/// bounds the work by. After the first pass the work for the best so far is counted before any
/// candidate is evaluated: the coarse blocks the windows meet (their ends moved alone, `O(n_p +
/// n_q)`), then the candidates of the blocks not skipped whole; when those exceed the budget, `Err`
/// at once. A vertex whose depth is certainly farther than `U` from every depth of the other chain
/// is left out of the count and the scan, and so, when the blocks met exceed the budget, are the
/// other chain's coarse blocks whose depths are ([`Live`]: windows wider than the chains, where
/// only depth thins them). When the blocks met exceed the budget even so, the box tests are counted
/// with the candidates instead (each block met costs at most nine of them otherwise), and the count
/// gives up when the two together exceed it: a zigzag facing a wide bowl meets a constant share of
/// the bowl's blocks from every vertex, and its teams' wide boxes rule out nearly all of them. When
/// that count ran, its blocks are the ones tried (a block kept for the count's best is kept for any
/// later, nearer best; it is tested again only once the best has fallen by more than a
/// sixty-fourth), so the boxes are not tested twice ([`run_plan`], which tests each edge's foot
/// before its keys when the count kept more than [`FOOT_FIRST`] candidates a vertex). With a finite
/// `cut` (the square of a distance known elsewhere), candidates bounded strictly above it are
/// skipped and the windows are never wider than for `cut`, as in `scan_winner_below`: the winner is
/// the nearest pair when that is strictly nearer than the known distance, some pair of the chains
/// otherwise.
///
/// # Complexity
/// `O(n_p + n_q + budget)` key comparisons, bounds and exact tests.
pub(crate) fn scan_windowed<K: Kernel, C: Points + ?Sized>(
    p: &C,
    q: &C,
    kp: Keys<'_>,
    kq: Keys<'_>,
    lens: &Lens,
    cut: f64,
    budget: usize,
) -> Result<(Winner, usize), usize> {
    let (np, nq) = (p.count(), q.count());
    if np == 0
        || nq == 0
        || kp.t.len() != np
        || kq.t.len() != nq
        || kp.d.len() != np
        || kq.d.len() != nq
    {
        return Err(0);
    }
    let mut best = Best::<K, true, C>::new(p, q, cut);
    let mut tried = 0usize;
    // The neighbours in key order.
    let (tp, tq) = (kp.t, kq.t);
    let mut j = 0;
    for (i, &ti) in tp.iter().enumerate() {
        while j + 1 < nq && tq[j + 1] <= ti {
            j += 1;
        }
        for k in j..(j + 2).min(nq) {
            best.consider(Cand::Vv(i, k));
        }
    }
    tried += 2 * np;
    tried += best.descend(np, nq, np + nq);
    // `P` vertices against `Q` vertices and edges (pass 0), `Q` vertices against `P` edges (pass 1).
    let sides = |pass: usize| if pass == 0 { (kp, kq) } else { (kq, kp) };
    // The work for the best so far, counted before any candidate is evaluated: first the coarse
    // blocks the windows meet and all their candidates (their ends moved alone), then, unless those
    // candidates fit the budget, the candidates of the fine blocks not skipped.
    let u2 = best.u2();
    let w = lens.window(u2);
    // A vertex whose depth is certainly farther than the best from every depth of the other chain
    // has no candidate that could win: it is left out of the count and of the scan. (Depths within
    // the window of the other chain's are kept untested: only the work depends on that.)
    let reach = [depths(kq.d), depths(kp.d)];
    let dead = |pass: usize, (t, d): (f64, f64)| {
        let (lo, hi) = reach[pass];
        (d < lo - w || d > hi + w) && lens.apart((t, d), (t, t), reach[pass], u2)
    };
    let count = |live: Option<&[Live; 2]>| {
        let (mut coarse, mut whole) = (0usize, tried);
        for pass in 0..2 {
            let (kx, ky) = sides(pass);
            let mut window = Window::default();
            for (&t, &d) in kx.t.iter().zip(kx.d) {
                let span = Span::of(window.around(t, ky.t, w), ky.t.len());
                if dead(pass, (t, d)) {
                    continue;
                }
                let met = span.blocks(BLOCK * GROUP);
                coarse += live.map_or(met.len(), |l| l[pass].count(met));
                whole += span.es.len() + if pass == 0 { span.vs.len() } else { 0 };
            }
        }
        (coarse, whole)
    };
    let (mut coarse, whole) = count(None);
    // Windows wider than the chains (a small polygon facing a wide bowl as far away as it is
    // wide): the other chain's coarse blocks whose depths are certainly farther than the best from
    // every depth of the own chain are left out too, of the count and of the scan.
    let mut live = None;
    if coarse > budget {
        let l = [
            Live::of(kq.d, reach[1], lens, u2),
            Live::of(kp.d, reach[0], lens, u2),
        ];
        coarse = count(Some(&l)).0;
        live = Some(l);
    }
    // Windows that meet more coarse blocks than the budget even so (a zigzag facing a bowl of a
    // million vertices: both ends of the bowl within reach of the whole zigzag) may still rule out
    // nearly all of them by their boxes, a team's wide blocks first. The count then goes on, the
    // box tests themselves counted as candidates are, and gives up when the two together run
    // beyond the budget: the count costs `O(n_p + n_q)` besides what it counts either way.
    let tested = coarse > budget;
    // Windows of a few candidates a vertex (saw-teeth: about three and a half) are taken whole:
    // blocks and keys would cost more than they save.
    let blocks = (whole > SPARSE * (np + nq)).then(|| {
        let [lq, lp] = live.map_or([None, None], |[lq, lp]| [Some(lq), Some(lp)]);
        [Blocks::of(q, kq).with(lq), Blocks::of(p, kp).with(lp)]
    });
    // Vertex `x` of the pass's own chain.
    let own = |pass: usize, x: usize| if pass == 0 { p.at(x) } else { q.at(x) };
    // The parts of the current window to try, reused from vertex to vertex.
    let mut kept = Vec::new();
    let mut ahead = tried;
    // Vertices counted so far: every `EXTRAPOLATE` of them, a count heading beyond the budget
    // gives up early (crowded windows cost box tests a vertex by the dozen, and the count would
    // otherwise run most of the way first). Only the caller's choice of method depends on it.
    let mut done = 0usize;
    let mut plan: [Vec<Planned>; 2] = [Vec::new(), Vec::new()];
    let planned = whole > budget;
    for pass in (0..2).filter(|_| planned) {
        let ((kx, ky), by) = (sides(pass), blocks.as_ref().map(|b| &b[pass]));
        let mut window = Window::default();
        let mut team = Team::default();
        let mine = if pass == 0 { p } else { q };
        for (x, (&t, &d)) in kx.t.iter().zip(kx.d).enumerate() {
            let span = Span::of(window.around(t, ky.t, w), ky.t.len());
            done += 1;
            let out = dead(pass, (t, d));
            // A team is formed at its first member, for the members not left out (if any).
            let unformed = out
                && x % TEAM == 0
                && (x..(x + TEAM).min(kx.t.len())).all(|m| dead(pass, (kx.t[m], kx.d[m])));
            let near = match by {
                Some(by) if !unformed => team.at(
                    by,
                    mine,
                    (x, (span.vs.start, span.vs.end)),
                    (kx, ky.t),
                    lens,
                    (w, u2),
                ),
                _ => None,
            };
            if !out {
                match by {
                    Some(by) => {
                        by.survivors(&span, (own(pass, x), (t, d)), lens, u2, near, &mut kept);
                    }
                    None => kept.push((None, span.vs, span.es)),
                }
                for (k, vs, es) in kept.drain(..) {
                    ahead += es.len() + if pass == 0 { vs.len() } else { 0 };
                    plan[pass].push((x, k, vs, es));
                }
            }
            let work = match (tested, blocks.as_ref()) {
                (true, Some([bq, bp])) => ahead + bq.tests() + bp.tests(),
                _ => ahead,
            };
            let heading = done % EXTRAPOLATE == 0
                && (work - tried).saturating_mul(np + nq) > budget.saturating_mul(done);
            if work > budget || heading {
                return Err(work);
            }
        }
    }
    if planned {
        // Crowded windows: the edges' feet first (see `Best::span_foot_first`).
        let foot_first = ahead - tried > FOOT_FIRST * (np + nq);
        let sides = [sides(0), sides(1)];
        tried += run_plan(
            &mut best,
            plan,
            sides,
            blocks.as_ref(),
            lens,
            u2,
            foot_first,
        );
        return Ok((best.best.winner(p, q), tried));
    }
    for pass in 0..2 {
        let ((kx, ky), by) = (sides(pass), blocks.as_ref().map(|b| &b[pass]));
        let mut window = Window::default();
        for (x, (&t, &d)) in kx.t.iter().zip(kx.d).enumerate() {
            if dead(pass, (t, d)) {
                continue;
            }
            let u2 = best.u2();
            let span = Span::of(window.around(t, ky.t, lens.window(u2)), ky.t.len());
            let Some(by) = by else {
                tried += best.span(pass, x, (span.vs, span.es), |_, _| false);
                if tried > budget {
                    return Err(tried);
                }
                continue;
            };
            by.survivors(&span, (own(pass, x), (t, d)), lens, u2, None, &mut kept);
            for (_, vs, es) in kept.drain(..) {
                tried += best.span(pass, x, (vs, es), |item, u2| ky.far(item, (t, d), lens, u2));
            }
            if tried > budget {
                return Err(tried);
            }
        }
    }
    Ok((best.best.winner(p, q), tried))
}

/// The candidates of [`scan_windowed`]'s count (`plan`, for the best of upper bound `√u2` it
/// counted with): pass 0's vertices against the other chain's vertices and edges, then pass 1's
/// against the other's edges, each side's keys in `sides`, its blocks in `blocks`, the edges' feet
/// before their keys when `foot_first`. The candidates tried. Out of line: its loop and
/// `scan_windowed`'s own compile apart.
#[inline(never)]
fn run_plan<K: Kernel, C: Points + ?Sized>(
    best: &mut Best<'_, K, true, C>,
    plan: [Vec<Planned>; 2],
    sides: [(Keys<'_>, Keys<'_>); 2],
    blocks: Option<&[Blocks<'_, C>; 2]>,
    lens: &Lens,
    u2: f64,
    foot_first: bool,
) -> usize {
    let mut tried = 0;
    for (pass, plan) in plan.into_iter().enumerate() {
        let ((kx, ky), by) = (sides[pass], blocks.map(|b| &b[pass]));
        for (x, k, vs, es) in plan {
            let (t, d) = (kx.t[x], kx.d[x]);
            // A block kept for the count's best is tried again when the best has since
            // fallen by more than a sixty-fourth (only the work depends on it).
            let now = best.u2();
            let fallen = now * (1.0 + 1.0 / 64.0) < u2;
            let fine = by.zip(k).map(|(by, k)| (&by.fine, k));
            if fallen
                && fine.is_some_and(|(f, k)| {
                    let own = if pass == 0 {
                        best.p.at(x)
                    } else {
                        best.q.at(x)
                    };
                    f.beyond(k, own, (t, d), lens, now)
                })
            {
                continue;
            }
            let far = |item, u2| ky.far(item, (t, d), lens, u2);
            tried += if foot_first {
                best.span_foot_first(pass, x, (vs, es), far)
            } else {
                best.span(pass, x, (vs, es), far)
            };
        }
    }
    tried
}

/// A part of [`scan_windowed`]'s count: vertex `x` of the pass's own chain, the fine block `k` of
/// the other chain (`None` without blocks) and that block's vertices and edges in `x`'s window.
type Planned = (usize, Option<usize>, Range<usize>, Range<usize>);

/// The best candidate so far of a scan ([`scan`], [`scan_windowed`]), with its exact distance and
/// its bounds.
struct Best<'a, K, const INTERIOR_ONLY: bool, C: ?Sized = [DVec2], const BOUNDS_FIRST: bool = false>
{
    p: &'a C,
    q: &'a C,
    cut: f64,
    best: Cand,
    d: Dist2,
    b: (f64, f64),
    kernel: core::marker::PhantomData<K>,
}

impl<'a, K: Kernel, const INTERIOR_ONLY: bool, C: Points + ?Sized, const BOUNDS_FIRST: bool>
    Best<'a, K, INTERIOR_ONLY, C, BOUNDS_FIRST>
{
    fn new(p: &'a C, q: &'a C, cut: f64) -> Self {
        let best = Cand::Vv(0, 0);
        Best {
            p,
            q,
            cut,
            best,
            d: best.scan_dist(p, q, INTERIOR_ONLY),
            b: best.scan_bounds(p, q, INTERIOR_ONLY),
            kernel: core::marker::PhantomData,
        }
    }

    /// The squared distance a candidate must not be certainly above: the best's upper bound, or
    /// the cut.
    fn u2(&self) -> f64 {
        self.b.1.min(self.cut)
    }

    /// [`filter`] with the scan's `INTERIOR_ONLY` and [`Best::u2`].
    #[inline(always)]
    fn filter(&self, c: Cand) -> Option<(f64, f64)> {
        filter::<K, C, BOUNDS_FIRST>(c, self.p, self.q, INTERIOR_ONLY, self.u2())
    }

    /// Takes `c` when it is nearer than the best: skipped when bounded strictly above the best or
    /// the cut, taken when bounded strictly below the best, compared exactly otherwise.
    #[inline(always)]
    fn consider(&mut self, c: Cand) {
        if let Some(b) = self.filter(c) {
            self.take(c, b);
        }
    }

    /// [`Best::consider`] for a vertex–edge candidate `c` (vertex `v`, edge `s t`) of an
    /// `INTERIOR_ONLY` scan whose vertex is known to project strictly inside the edge: its bounds
    /// only.
    #[inline(always)]
    fn consider_inside(&mut self, c: Cand, (v, s, t): (DVec2, DVec2, DVec2)) {
        let b = edge_bounds(v, s, t);
        if b.0 <= self.u2() {
            self.take(c, b);
        }
    }

    /// Local descent from a vertex–vertex best over `np × nq` vertex pairs: while a neighbouring
    /// pair (one index moved by one) is strictly nearer, move there; at most `steps` moves.
    /// The candidates tried.
    fn descend(&mut self, np: usize, nq: usize, steps: usize) -> usize {
        let mut tried = 0;
        for _ in 0..steps {
            let Cand::Vv(i, j) = self.best else { break };
            let at = self.best;
            for c in [
                (i > 0).then(|| Cand::Vv(i - 1, j)),
                (i + 1 < np).then(|| Cand::Vv(i + 1, j)),
                (j > 0).then(|| Cand::Vv(i, j - 1)),
                (j + 1 < nq).then(|| Cand::Vv(i, j + 1)),
            ]
            .into_iter()
            .flatten()
            {
                self.consider(c);
                tried += 1;
            }
            if self.best == at {
                break;
            }
        }
        tried
    }

    /// Takes `c`, with bounds `b` not above [`Best::u2`], when it is nearer than the best: when
    /// bounded strictly below the best, otherwise by an exact comparison.
    #[inline(always)]
    fn take(&mut self, c: Cand, b: (f64, f64)) {
        let d = c.scan_dist(self.p, self.q, INTERIOR_ONLY);
        if b.1 < self.b.0 || cmp_scan::<K>(d, self.d) == Ordering::Less {
            self.best = c;
            self.d = d;
            self.b = b;
        }
    }

    /// Vertex `x` of the pass's own chain against the other chain's vertices `vs` (pass 0 only)
    /// and edges `es`, each skipped when `far(Item, u2)` says it is certainly farther than `√u2`.
    /// The candidates tried.
    #[inline]
    fn span(
        &mut self,
        pass: usize,
        x: usize,
        (vs, es): (Range<usize>, Range<usize>),
        far: impl Fn(Item, f64) -> bool,
    ) -> usize {
        let tried = es.len() + if pass == 0 { vs.len() } else { 0 };
        if pass == 0 {
            for y in vs {
                if !far(Item::Vertex(y), self.u2()) {
                    self.consider(Cand::Vv(x, y));
                }
            }
        }
        for e in es {
            if !far(Item::Edge(e), self.u2()) {
                self.consider(if pass == 0 {
                    Cand::PvQe(x, e)
                } else {
                    Cand::QvPe(x, e)
                });
            }
        }
        tried
    }

    /// [`Best::span`] with each edge's foot tested before its keys (`INTERIOR_ONLY`: a vertex that
    /// does not project strictly inside the edge leaves it to the vertex pairs, [`filter`]). An
    /// edge is evaluated only when it passes both, so only the work depends on the order, never a
    /// decision. The keys first suit most inputs (a window's edges mostly lie away from the
    /// vertex); the foot first suits crowded windows, where most candidates' keys come within the
    /// best (a star's tips facing a curved wall tilted against the line: in the star in a pocket
    /// the keys keep 98.6% of the edges, the foot test none).
    #[inline]
    fn span_foot_first(
        &mut self,
        pass: usize,
        x: usize,
        (vs, es): (Range<usize>, Range<usize>),
        far: impl Fn(Item, f64) -> bool,
    ) -> usize {
        const {
            assert!(
                INTERIOR_ONLY,
                "the foot test skips edges in interior-only scans only"
            )
        };
        // The vertices as `span` takes them.
        let tried = self.span(pass, x, (vs, es.start..es.start), &far) + es.len();
        for e in es {
            let (c, (v, (s, t))) = if pass == 0 {
                (Cand::PvQe(x, e), (self.p.at(x), self.q.seg(e)))
            } else {
                (Cand::QvPe(x, e), (self.q.at(x), self.p.seg(e)))
            };
            if foot_inside::<K>(v, s, t) && !far(Item::Edge(e), self.u2()) {
                self.consider_inside(c, (v, s, t));
            }
        }
        tried
    }
}

/// Candidates a vertex, counted for the crowded windows of [`scan_windowed`] after its block
/// tests, beyond which its edges' feet are tested before their keys ([`Best::span_foot_first`]):
/// the star in a pocket counts about 18 a vertex, the hooked teeth about 2.3.
const FOOT_FIRST: usize = 8;

/// The keys of a chain for [`scan_windowed`]: `t̂` along the line (non-decreasing up to rounding)
/// and `d̂` across it, one each a vertex.
#[derive(Clone, Copy)]
pub(crate) struct Keys<'a> {
    pub(crate) t: &'a [f64],
    pub(crate) d: &'a [f64],
}

/// A vertex or an edge of the other chain, for [`Keys::far`].
#[derive(Clone, Copy)]
enum Item {
    Vertex(usize),
    Edge(usize),
}

impl Keys<'_> {
    /// Whether vertex or edge `item` is certainly farther than `√u2` from the vertex with keys
    /// `x`, by its own keys: a vertex's, or an edge's between its two vertices' (`t` and `d` are
    /// affine along a chain's edge, so its points lie between them; for an envelope see
    /// [`Carried`]).
    #[inline]
    fn far(&self, item: Item, x: (f64, f64), lens: &Lens, u2: f64) -> bool {
        let (lo, hi) = match item {
            Item::Vertex(y) => (y, y),
            Item::Edge(e) => (e, e + 1),
        };
        lens.apart(
            x,
            hull(self.t[lo], self.t[hi]),
            hull(self.d[lo], self.d[hi]),
            u2,
        )
    }
}

/// Vertices between two extrapolations of [`scan_windowed`]'s count.
const EXTRAPOLATE: usize = 256;

/// Candidates a vertex up to which [`scan_windowed`] takes its windows whole.
const SPARSE: usize = 8;

/// Vertices a fine block of [`scan_windowed`]: small enough that a fine block that is not skipped
/// holds few candidates, large enough that skipping one saves several.
const BLOCK: usize = 8;
/// Fine blocks a coarse block: windows thousands of vertices wide (dense zigzags one unit apart)
/// cost a test per 64 vertices where the depths rule them out.
const GROUP: usize = 8;

/// `(lo, hi)` with `lo ≤ hi`, of two keys in either order.
fn hull(a: f64, b: f64) -> (f64, f64) {
    if a <= b { (a, b) } else { (b, a) }
}

/// The boxes of keys of a chain's blocks of `size` vertices: block `k` holds the vertices
/// `k·size ..= min((k + 1)·size, n − 1)` and so the edges `k·size .. min((k + 1)·size, n − 1)`
/// between them; its box is the least and greatest `t̂` and `d̂` of those vertices.
///
/// Each block also has a box in its own chord's frame ([`Chord`]), tried when the line's box
/// fails: it holds the block's vertices and the ends of its edges (for an envelope, the whole
/// carrying edges).
struct Boxes<'a, C: ?Sized> {
    c: &'a C,
    size: usize,
    t: Vec<(f64, f64)>,
    d: Vec<(f64, f64)>,
    /// Built when first needed: most blocks never get past the line's box.
    chords: Vec<OnceCell<Option<Chord>>>,
    /// The box tests made so far ([`Boxes::beyond`] calls).
    tests: Cell<usize>,
}

impl<'a, C: Points + ?Sized> Boxes<'a, C> {
    fn of(c: &'a C, k: Keys<'_>, size: usize) -> Self {
        let n = k.t.len();
        let count = n.div_ceil(size);
        let (mut t, mut d) = (Vec::with_capacity(count), Vec::with_capacity(count));
        for b in 0..count {
            let (first, last) = (b * size, ((b + 1) * size).min(n - 1));
            let (t0, d0) = (k.t[first], k.d[first]);
            let (mut bt, mut bd) = ((t0, t0), (d0, d0));
            for (&x, &y) in k.t[first..=last].iter().zip(&k.d[first..=last]) {
                bt = (bt.0.min(x), bt.1.max(x));
                bd = (bd.0.min(y), bd.1.max(y));
            }
            t.push(bt);
            d.push(bd);
        }
        let chords = (0..count).map(|_| OnceCell::new()).collect();
        Boxes {
            c,
            size,
            t,
            d,
            chords,
            tests: Cell::new(0),
        }
    }

    /// The boxes of the blocks `GROUP` times as large, from these: block `b`'s holds its children
    /// `b·GROUP .. (b + 1)·GROUP`, which hold the same vertices (each block's last vertex is the
    /// next one's first). `O(1)` a block.
    fn merged(&self) -> Self {
        let count = self.t.len().div_ceil(GROUP);
        let join = |a: (f64, f64), b: &(f64, f64)| (a.0.min(b.0), a.1.max(b.1));
        let union = |v: &[(f64, f64)], b: usize| {
            let kids = &v[b * GROUP..((b + 1) * GROUP).min(v.len())];
            kids[1..].iter().fold(kids[0], join)
        };
        Boxes {
            c: self.c,
            size: self.size * GROUP,
            t: (0..count).map(|b| union(&self.t, b)).collect(),
            d: (0..count).map(|b| union(&self.d, b)).collect(),
            chords: (0..count).map(|_| OnceCell::new()).collect(),
            tests: Cell::new(0),
        }
    }

    /// Block `k`'s box in its chord's frame: its vertices, and the ends of its edges unless the
    /// vertices are those ends.
    fn chord(&self, k: usize) -> Option<Chord> {
        let (c, n) = (self.c, self.c.count());
        let (first, last) = (k * self.size, ((k + 1) * self.size).min(n - 1));
        let vertices = (first..=last).map(|i| c.at(i));
        if C::JOINS_VERTICES {
            Chord::of(c.at(first), c.at(last), vertices)
        } else {
            let ends = (first..last).flat_map(|e| {
                let (a, b) = c.seg(e);
                [a, b]
            });
            Chord::of(c.at(first), c.at(last), vertices.chain(ends))
        }
    }

    /// Whether every vertex and edge of block `k` is certainly farther than `√u2` from the vertex
    /// `x` with keys `(t, d)`: by the line's box, then by the chord's.
    #[inline]
    fn beyond(&self, k: usize, x: DVec2, (t, d): (f64, f64), lens: &Lens, u2: f64) -> bool {
        self.tests.set(self.tests.get() + 1);
        lens.apart((t, d), self.t[k], self.d[k], u2)
            || self.chords[k]
                .get_or_init(|| self.chord(k))
                .is_some_and(|c| c.apart(x, u2))
    }
}

/// A chain's fine blocks ([`BLOCK`] vertices), coarse blocks ([`GROUP`] fine ones) and wide blocks
/// (`GROUP` coarse ones), and on long chains blocks `GROUP` times as large again, level after
/// level, until a level has at most [`WIDE`] blocks.
struct Blocks<'a, C: ?Sized> {
    fine: Boxes<'a, C>,
    coarse: Boxes<'a, C>,
    wide: Boxes<'a, C>,
    /// The levels above the wide blocks, from the lowest.
    above: Vec<Boxes<'a, C>>,
    /// The coarse blocks not left out, when some are ([`Live`]).
    live: Option<Live>,
}

impl<'a, C: Points + ?Sized> Blocks<'a, C> {
    fn of(c: &'a C, k: Keys<'_>) -> Self {
        let wide = Boxes::of(c, k, BLOCK * GROUP * GROUP);
        let mut above: Vec<Boxes<'a, C>> = Vec::new();
        while above.last().unwrap_or(&wide).t.len() > WIDE {
            above.push(above.last().unwrap_or(&wide).merged());
        }
        Blocks {
            fine: Boxes::of(c, k, BLOCK),
            coarse: Boxes::of(c, k, BLOCK * GROUP),
            wide,
            above,
            live: None,
        }
    }

    /// The same blocks, those left out by `live` skipped.
    fn with(self, live: Option<Live>) -> Self {
        Blocks { live, ..self }
    }

    /// The box tests made so far, at every level.
    fn tests(&self) -> usize {
        let above: usize = self.above.iter().map(|b| b.tests.get()).sum();
        self.fine.tests.get() + self.coarse.tests.get() + self.wide.tests.get() + above
    }

    /// The coarse blocks of `r` not left out, in order: `O(1)` each, and `O(1)` for none.
    #[inline(always)]
    fn live(&self, r: Range<usize>) -> impl Iterator<Item = usize> + '_ {
        let mut at = r.start;
        std::iter::from_fn(move || {
            if at >= r.end {
                return None;
            }
            let c = self.live.as_ref().map_or(at, |l| l.next[at]);
            at = c + 1;
            (c < r.end).then_some(c)
        })
    }

    /// Pushes onto `near` the coarse blocks of `span` (a team's joint window) not certainly
    /// farther than `√u2` from every vertex of the team: from its centre `v` with keys `x`, every
    /// member lies within a reach that `u2` already adds (so a block farther than `√u2` from `v`
    /// is ruled out for all of them). Wide blocks are tested first when the span holds more than
    /// [`WIDE`] coarse ones, and the blocks of the level above first when it holds more than
    /// `WIDE` wide ones, and so on up ([`Blocks::descend`]); a coarse block with at most two fine
    /// blocks in the span is kept untested. At most one box test per block of each level met:
    /// where the boxes rule out all but the blocks near a few places of the chain, `O(log n)`
    /// tests a place.
    fn near(
        &self,
        span: &Span,
        (v, x): (DVec2, (f64, f64)),
        lens: &Lens,
        u2: f64,
        near: &mut Vec<usize>,
    ) {
        near.clear();
        let fine = span.blocks(BLOCK);
        let coarse = span.blocks(BLOCK * GROUP);
        let mut in_coarse = |c: usize| {
            let inner = (c * GROUP).max(fine.start)..((c + 1) * GROUP).min(fine.end);
            if inner.len() <= 2 || !self.coarse.beyond(c, v, x, lens, u2) {
                near.push(c);
            }
        };
        if coarse.len() <= WIDE {
            self.live(coarse).for_each(in_coarse);
            return;
        }
        // The level to start from (0: the wide blocks, `l`: `above[l − 1]`): the lowest whose
        // blocks in the span are at most `WIDE`, or the top.
        let mut level = 0;
        while level < self.above.len() && coarse.len() > WIDE * GROUP.pow(level as u32 + 1) {
            level += 1;
        }
        self.descend(level, &coarse, (v, x), lens, u2, &mut in_coarse);
    }

    /// [`Blocks::near`] at `level` (0: the wide blocks, `l`: `above[l − 1]`), over the coarse
    /// blocks `coarse`: each block of the level holding a coarse block of `coarse` not left out is
    /// tested (a wide block only when it holds more than two of them), and the blocks below it
    /// taken in turn unless it is certainly farther than `√u2`.
    fn descend(
        &self,
        level: usize,
        coarse: &Range<usize>,
        (v, x): (DVec2, (f64, f64)),
        lens: &Lens,
        u2: f64,
        in_coarse: &mut impl FnMut(usize),
    ) {
        // Coarse blocks a block of the level.
        let per = GROUP.pow(level as u32 + 1);
        let mut from = coarse.start;
        while let Some(c) = self.live(from..coarse.end).next() {
            let b = c / per;
            let within = (b * per).max(coarse.start)..((b + 1) * per).min(coarse.end);
            from = within.end;
            if level == 0 {
                if within.len() > 2 && self.wide.beyond(b, v, x, lens, u2) {
                    continue;
                }
                self.live(within).for_each(&mut *in_coarse);
            } else if !self.above[level - 1].beyond(b, v, x, lens, u2) {
                self.descend(level - 1, &within, (v, x), lens, u2, in_coarse);
            }
        }
    }

    /// Pushes the vertices and edges of each fine block of `span` that is not certainly farther
    /// than `√u2` from the vertex `v` with keys `x` onto `out`, testing the coarse blocks first (a
    /// coarse block's box holds its fine blocks', and is tested only when the span holds more than
    /// two of them). Alone (`team` is `None`), every coarse block of the span; in a team
    /// ([`Team`]), only those `near` the team kept of those it tested, `covered`, and any of the
    /// span beyond `covered` (none when the keys are sorted: the team's window holds the
    /// vertex's). At most `GROUP + 1` box tests per coarse block taken.
    #[inline]
    fn survivors(
        &self,
        span: &Span,
        vx: (DVec2, (f64, f64)),
        lens: &Lens,
        u2: f64,
        team: Option<(&[usize], Range<usize>)>,
        out: &mut Vec<(Option<usize>, Range<usize>, Range<usize>)>,
    ) {
        let fine = span.blocks(BLOCK);
        let coarse = span.blocks(BLOCK * GROUP);
        let Some((near, covered)) = team else {
            for c in self.live(coarse) {
                self.in_coarse(c, (span, &fine), vx, lens, u2, out);
            }
            return;
        };
        for c in self.live(coarse.start..coarse.end.min(covered.start)) {
            self.in_coarse(c, (span, &fine), vx, lens, u2, out);
        }
        let from = near.partition_point(|&c| c < coarse.start);
        for &c in near[from..].iter().take_while(|&&c| c < coarse.end) {
            self.in_coarse(c, (span, &fine), vx, lens, u2, out);
        }
        for c in self.live(coarse.start.max(covered.end)..coarse.end) {
            self.in_coarse(c, (span, &fine), vx, lens, u2, out);
        }
    }

    /// [`Blocks::survivors`] in coarse block `c`, whose fine blocks in the span are those of
    /// `fine`.
    #[inline(always)]
    fn in_coarse(
        &self,
        c: usize,
        (span, fine): (&Span, &Range<usize>),
        (v, x): (DVec2, (f64, f64)),
        lens: &Lens,
        u2: f64,
        out: &mut Vec<(Option<usize>, Range<usize>, Range<usize>)>,
    ) {
        let inner = (c * GROUP).max(fine.start)..((c + 1) * GROUP).min(fine.end);
        if inner.len() > 2 && self.coarse.beyond(c, v, x, lens, u2) {
            return;
        }
        for k in inner {
            if !self.fine.beyond(k, v, x, lens, u2) {
                let (vs, es) = span.within(k);
                out.push((Some(k), vs, es));
            }
        }
    }
}

/// The coarse blocks ([`BLOCK`]` · `[`GROUP`] vertices, as [`Boxes`] takes them) of a chain of
/// computed depths `d` that [`scan_windowed`] keeps: those whose depths are not certainly farther
/// than `√u2` from every depth of the other chain (`reach`, its least and greatest). A point of a
/// block left out is farther than `√u2` from every point of the other chain (Lagrange's identity,
/// as for any box of keys: the gap across the line alone bounds the distance), so no candidate of
/// it can beat a best of upper bound `√u2`, nor any later, nearer best.
struct Live {
    /// `prefix[c]`: the blocks kept before block `c`.
    prefix: Vec<usize>,
    /// `next[c]`: the first block kept at or after `c` (the block count when none).
    next: Vec<usize>,
}

impl Live {
    fn of(d: &[f64], reach: (f64, f64), lens: &Lens, u2: f64) -> Live {
        let size = BLOCK * GROUP;
        let count = d.len().div_ceil(size);
        let mut prefix = Vec::with_capacity(count + 1);
        prefix.push(0);
        for c in 0..count {
            let (first, last) = (c * size, ((c + 1) * size).min(d.len() - 1));
            let kept = !lens.beyond(0.0, lens.gap(reach, depths(&d[first..=last])), u2);
            prefix.push(prefix[c] + usize::from(kept));
        }
        // Block `c` is kept when the prefix steps after it.
        let mut next = vec![count; count + 1];
        for c in (0..count).rev() {
            next[c] = if prefix[c + 1] > prefix[c] {
                c
            } else {
                next[c + 1]
            };
        }
        Live { prefix, next }
    }

    /// The blocks of `r` kept.
    fn count(&self, r: Range<usize>) -> usize {
        self.prefix[r.end] - self.prefix[r.start]
    }
}

/// Consecutive vertices of a pass's own chain in [`scan_windowed`]'s count that share their coarse
/// box tests ([`Team`]): on curved walls most coarse blocks of a vertex's window are ruled out for
/// its whole team at once. (The scan without a count, whose windows are sparser, takes its vertices
/// alone: teams there cost the spirals more than they saved.)
const TEAM: usize = 8;

/// The coarse blocks of the other chain that [`scan_windowed`]'s current team of [`TEAM`] own
/// vertices keeps ([`Blocks::near`]), and those it tested.
#[derive(Default)]
struct Team {
    near: Vec<usize>,
    covered: Range<usize>,
    /// Teams left to take alone, and how many the last back-off skipped.
    skip: usize,
    backoff: usize,
}

impl Team {
    /// The coarse blocks kept for vertex `x` of the own chain `own` (keys `kx`, window `lo..hi`
    /// over the other chain's keys `ky` for the window width `w`) and those tested, or `None`
    /// when the vertex is taken alone. At the first vertex of a team they are tested for all its
    /// members against `u2` (which only falls later), from its middle vertex.
    #[inline(always)]
    fn at<C: Points + ?Sized>(
        &mut self,
        by: &Blocks<'_, C>,
        own: &C,
        (x, window): (usize, (usize, usize)),
        (kx, ky): (Keys<'_>, &[f64]),
        lens: &Lens,
        (w, u2): (f64, f64),
    ) -> Option<(&[usize], Range<usize>)> {
        if x % TEAM == 0 {
            if self.skip > 0 {
                self.skip -= 1;
                self.covered = 0..0;
            } else {
                self.form(by, own, (x, window), (kx, ky), lens, (w, u2));
            }
        }
        (!self.covered.is_empty()).then(|| (self.near.as_slice(), self.covered.clone()))
    }

    /// [`Team::at`] at the first vertex `x` of a team that tests its blocks.
    #[inline(never)]
    fn form<C: Points + ?Sized>(
        &mut self,
        by: &Blocks<'_, C>,
        own: &C,
        (x, (lo, hi)): (usize, (usize, usize)),
        (kx, ky): (Keys<'_>, &[f64]),
        lens: &Lens,
        (w, u2): (f64, f64),
    ) {
        let end = (x + TEAM).min(kx.t.len());
        // The window of the team's greatest key, from the first member's, ends at or after each
        // member's (for sorted keys; [`Blocks::survivors`] tests what a member's window holds
        // beyond it).
        let top = kx.t[x..end]
            .iter()
            .fold(kx.t[x], |a, &t| if t > a { t } else { a });
        let hi = Window { lo, hi }.around(top, ky, w).1;
        let joint = Span::of((lo, hi.max(lo)), ky.len());
        let m = x + (end - x) / 2;
        let o = own.at(m);
        // A NaN distance makes `check` NaN, and the reach infinite: nothing is ruled out.
        let (mut reach, mut check) = (0.0f64, 0.0f64);
        for i in x..end {
            let r = own.at(i).distance(o);
            reach = if r > reach { r } else { reach };
            check += r;
        }
        let reach = if check.is_finite() {
            reach
        } else {
            f64::INFINITY
        };
        by.near(
            &joint,
            (o, (kx.t[m], kx.d[m])),
            lens,
            reached(u2, reach),
            &mut self.near,
        );
        self.covered = joint.blocks(BLOCK * GROUP);
        // Teams that rule out less than half their blocks (members far apart for the clearance:
        // spirals sampled coarsely) cost more than they save: back off, doubling the teams taken
        // alone up to 32 while they keep failing.
        if 2 * self.near.len() > self.covered.len() {
            self.backoff = (2 * self.backoff).clamp(1, 32);
            self.skip = self.backoff;
        } else {
            self.backoff = 0;
        }
    }
}

/// Coarse blocks of a window beyond which [`Blocks::survivors`] tests the wide blocks first: the
/// windows along a curved wall widen with the sampling (the star in a pocket: about 20 coarse
/// blocks a vertex at 32,768 vertices, 80 at 131,072), and a wide block the line's or its chord's
/// box rules out saves eight coarse tests; in narrower windows they seldom do.
const WIDE: usize = 32;

/// The vertices `lo..hi` and the edges `lo − 1 .. min(hi, n − 1)` of a window over a chain of `n`
/// vertices (edge `k` joins `k` and `k + 1`: the one before `lo` ends inside or beyond the window,
/// the one at `hi` starts beyond it).
struct Span {
    vs: Range<usize>,
    es: Range<usize>,
}

impl Span {
    fn of((lo, hi): (usize, usize), n: usize) -> Span {
        Span {
            vs: lo..hi,
            es: lo.saturating_sub(1)..hi.min(n - 1),
        }
    }

    /// The blocks of `size` vertices holding a vertex or an edge of the span.
    fn blocks(&self, size: usize) -> Range<usize> {
        let first = self.vs.start.min(self.es.start);
        let end = self.vs.end.max(self.es.end);
        if self.vs.is_empty() && self.es.is_empty() {
            0..0
        } else {
            first / size..(end - 1) / size + 1
        }
    }

    /// The span's vertices and edges in fine block `k`.
    fn within(&self, k: usize) -> (Range<usize>, Range<usize>) {
        let (s, e) = (k * BLOCK, (k + 1) * BLOCK);
        let cut = |r: &Range<usize>| r.start.max(s)..r.end.min(e).max(r.start.max(s));
        (cut(&self.vs), cut(&self.es))
    }
}

/// Whether the squared distance from `v` to the line through `a` and `c` is certainly greater than
/// `cut` ([`bounds`]' lower bound of it is).
pub(crate) fn farther_from_line_than(v: DVec2, a: DVec2, c: DVec2, cut: f64) -> bool {
    bounds::<[DVec2]>(Cand::QvPe(0, 0), &[a, c], &[v]).0 > cut
}

/// A lower bound of the squared distance `d`, from [`bounds`]: a point pair's, or for a point and a
/// segment (or a line) the line's, since a segment's points lie on its line. `0` when the bounds
/// give up (a tiny edge, overflow, underflow).
fn lower_bound(d: Dist2) -> f64 {
    match d {
        Dist2::PointPoint(v, w) => bounds::<[DVec2]>(Cand::Vv(0, 0), &[v], &[w]).0,
        Dist2::PointSegment(v, a, b) | Dist2::PointLine(v, a, b) => {
            bounds::<[DVec2]>(Cand::QvPe(0, 0), &[a, b], &[v]).0
        }
    }
}

/// An upper bound of the squared distance `d` (a point pair, or a point and a closed segment),
/// from [`bounds`]: the nearer end's, or the line's when the foot is strictly inside the segment
/// (exact dot signs). `∞` when the bounds give up.
pub(crate) fn upper_bound<K: Kernel>(d: Dist2) -> f64 {
    let pp = |v: DVec2, w: DVec2| bounds::<[DVec2]>(Cand::Vv(0, 0), &[v], &[w]).1;
    match d {
        Dist2::PointPoint(v, w) => pp(v, w),
        Dist2::PointSegment(v, a, b) => {
            let ends = pp(v, a).min(pp(v, b));
            if a != b
                && K::dot_sign(a, v, a, b) == Sign::Positive
                && K::dot_sign(b, v, b, a) == Sign::Positive
            {
                ends.min(bounds::<[DVec2]>(Cand::QvPe(0, 0), &[a, b], &[v]).1)
            } else {
                ends
            }
        }
        _ => f64::INFINITY,
    }
}

#[cfg(test)]
mod tests {
    //! The pre-filter's bounds against exact rational distances, and the filtered scan against the
    //! plain one.
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::exact::{
        squared_distance_point_point, squared_distance_point_segment, to_rational,
    };
    use polydist_predicates::{Exact, Robust};

    /// Points of one scale class: unit square, lattice (ties), huge, tiny, or far from the origin.
    fn point(rng: &mut SplitMix64, class: usize) -> DVec2 {
        let u = |rng: &mut SplitMix64| rng.unit_f64() - 0.5;
        match class {
            0 => DVec2::new(u(rng), u(rng)),
            1 => DVec2::new(rng.range_i64(-4, 5) as f64, rng.range_i64(-4, 5) as f64) / 8.0,
            2 => DVec2::new(u(rng), u(rng)) * 1e150,
            3 => DVec2::new(u(rng), u(rng)) * 1e-280,
            _ => DVec2::new(1e12 + u(rng), 1e12 + u(rng)),
        }
    }

    /// Two chains of 1 to `max` points of one scale class, `Q`'s moved right by `3/4`.
    fn chain_pair(rng: &mut SplitMix64, class: usize, max: usize) -> (Vec<DVec2>, Vec<DVec2>) {
        let p = (0..1 + rng.index(max)).map(|_| point(rng, class)).collect();
        let q = (0..1 + rng.index(max))
            .map(|_| point(rng, class) + DVec2::new(0.75, 0.0))
            .collect();
        (p, q)
    }

    /// The distance of a scan's pair, from its features in `p` and `q`.
    fn pair_dist(p: &[DVec2], q: &[DVec2], pair: &ClosestPair) -> Dist2 {
        match (pair.feature_p, pair.feature_q) {
            (Feature::Vertex(i), Feature::Vertex(j)) => Dist2::PointPoint(p[i], q[j]),
            (Feature::Vertex(i), Feature::Edge(j)) => Dist2::PointSegment(p[i], q[j], q[j + 1]),
            (Feature::Edge(i), Feature::Vertex(j)) => Dist2::PointSegment(q[j], p[i], p[i + 1]),
            _ => unreachable!("a scan reports a vertex"),
        }
    }

    #[test]
    fn bounds_bracket_the_exact_squared_distance() {
        let mut rng = SplitMix64::new(0xb0d5);
        let (mut bracketed, mut near) = (0, 0);
        for round in 0..32_000 {
            let class = round % 8;
            // Classes 6 and 7: vertical and horizontal edges, with points of every scale.
            let scale = if class < 6 { class % 5 } else { round / 8 % 5 };
            let mut p: Vec<DVec2> = (0..2).map(|_| point(&mut rng, scale)).collect();
            let mut q: Vec<DVec2> = (0..2).map(|_| point(&mut rng, scale)).collect();
            if class == 5 {
                // Near incidence: q[0] rounded onto P's edge, where the error bounds are all there is.
                q[0] = p[0] + (p[1] - p[0]) * rng.unit_f64();
            }
            if class == 6 {
                (p[1].x, q[1].x) = (p[0].x, q[0].x);
            }
            if class == 7 {
                (p[1].y, q[1].y) = (p[0].y, q[0].y);
            }
            for c in [Cand::Vv(0, 1), Cand::PvQe(1, 0), Cand::QvPe(0, 0)] {
                // (QvPe(0, 0) is q[0] against P's edge: the near-incident candidate of class 5.)
                let (lo, hi) = bounds(c, p.as_slice(), q.as_slice());
                assert!(lo <= hi, "{c:?} {p:?} {q:?}");
                let (v, s, t) = match c {
                    Cand::Vv(i, j) => (p[i], q[j], q[j]),
                    Cand::PvQe(i, j) => (p[i], q[j], q[j + 1]),
                    Cand::QvPe(j, i) => (q[j], p[i], p[i + 1]),
                };
                // The segment distance: `lo` bounds it always, `hi` when the foot is strictly inside.
                let inside = s == t
                    || (Exact::dot_sign(s, v, s, t) == Sign::Positive
                        && Exact::dot_sign(t, v, t, s) == Sign::Positive);
                let exact = if s == t {
                    squared_distance_point_point(v, s)
                } else {
                    squared_distance_point_segment(v, s, t)
                }
                .expect("finite");
                assert!(
                    to_rational(lo).expect("finite") <= exact,
                    "lo {c:?} {p:?} {q:?}"
                );
                if inside && hi.is_finite() {
                    assert!(
                        exact <= to_rational(hi).expect("finite"),
                        "hi {c:?} {p:?} {q:?}"
                    );
                    bracketed += 1;
                    near += usize::from(class == 5 && matches!(c, Cand::QvPe(..)));
                }
            }
        }
        assert!(bracketed > 20_000, "{bracketed}");
        assert!(near > 1_000, "{near}");
    }

    /// `upper_bound` is at least the exact squared distance of a point pair or a point and a closed
    /// segment, and finite on ordinary input.
    #[test]
    fn upper_bound_is_above_the_exact_squared_distance() {
        let mut rng = SplitMix64::new(0x0bb0);
        let mut finite = 0;
        for round in 0..24_000 {
            let class = round % 5;
            let (v, a) = (point(&mut rng, class), point(&mut rng, class));
            let b = if round % 7 == 0 {
                a
            } else {
                point(&mut rng, class)
            };
            for (d, exact) in [
                (Dist2::PointPoint(v, a), squared_distance_point_point(v, a)),
                (
                    Dist2::PointSegment(v, a, b),
                    squared_distance_point_segment(v, a, b),
                ),
            ] {
                let hi = upper_bound::<Robust>(d);
                if hi.is_finite() {
                    finite += 1;
                    assert!(
                        exact.expect("finite") <= to_rational(hi).expect("finite"),
                        "{d:?} {hi}"
                    );
                }
            }
        }
        assert!(finite > 35_000, "{finite}");
    }

    /// `farther_from_line_than` never claims a point farther from a line than it is (exact
    /// rationals: the squared line distance `cross² / len`), and does claim it when it is clearly so.
    #[test]
    fn farther_from_line_is_exact_when_it_says_so() {
        let mut rng = SplitMix64::new(0xdee9);
        let (mut claimed, mut refused) = (0, 0);
        for round in 0..24_000 {
            let class = round % 5;
            let (v, a, c) = (
                point(&mut rng, class),
                point(&mut rng, class),
                point(&mut rng, class),
            );
            if a == c {
                continue;
            }
            let r = |x: f64| to_rational(x).expect("finite");
            let (ex, ey) = (r(c.x) - r(a.x), r(c.y) - r(a.y));
            let (wx, wy) = (r(v.x) - r(a.x), r(v.y) - r(a.y));
            let cross = ex.clone() * wy - ey.clone() * wx;
            let exact = cross.clone() * cross / (ex.clone() * ex + ey.clone() * ey);
            // Cuts: zero, tiny, huge, and fractions of the squared distance to `a` (rounded).
            for cut in [0.0, 1e-300, 0.5, 1.0, 2.0, 1e300] {
                let cut = if cut == 0.5 || cut == 1.0 || cut == 2.0 {
                    let f: f64 = (v - a).length_squared() * cut;
                    if !f.is_finite() {
                        continue;
                    }
                    f
                } else {
                    cut
                };
                if farther_from_line_than(v, a, c, cut) {
                    claimed += 1;
                    assert!(exact > r(cut), "{v:?} {a:?} {c:?} {cut}");
                } else {
                    refused += 1;
                }
            }
        }
        assert!(claimed > 20_000 && refused > 20_000, "{claimed} {refused}");
    }

    /// A team's shared tests ([`Team`]) rule out only coarse blocks whose every vertex and edge is
    /// farther than `√u2` from every member (exact distances), and on the pocket benchmark in
    /// miniature (a star's tips, `1` from the wall, facing a dense zigzag wall) they rule out most:
    /// teams of far-apart members (tips `0.7` radians apart) back off.
    #[test]
    fn teams_rule_out_only_blocks_beyond_every_member() {
        use crate::monotone::keys;
        use polydist_predicates::exact::squared_distance_point_segment;
        let at = |a: f64, r: f64| DVec2::new(a.cos(), a.sin()) * r;
        // A C's wall all round (the pocket's mouth at angle 0), with more than `WIDE` coarse blocks.
        let wall: Vec<DVec2> = (0..2560)
            .map(|k| {
                at(
                    0.25 + 5.78 * k as f64 / 2559.0,
                    if k % 2 == 0 { 2.0 } else { 2.5 },
                )
            })
            .collect();
        let (mut ruled, mut tested, mut backed) = (0usize, 0usize, 0usize);
        for (round, spacing) in [4e-4, 4e-4, 0.7].into_iter().enumerate() {
            let star: Vec<DVec2> = (0..48)
                .map(|k| {
                    let r = if k % 2 == 0 || round == 2 { 1.0 } else { 0.5 };
                    at(1.0 + spacing * k as f64, r)
                })
                .collect();
            let (a, b) = (DVec2::new(-3.0, 0.0), DVec2::new(3.0, 0.5));
            let (kp, kq, lens) = keys(&star, &wall, a, b).expect("finite keys");
            let (kx, ky) = (Keys { t: &kp.0, d: &kp.1 }, Keys { t: &kq.0, d: &kq.1 });
            let by = Blocks::of(wall.as_slice(), ky);
            // Just above the clearance, and (round 1) just below it.
            let u2 = if round == 1 { 0.999 } else { 1.0 + 1e-9 };
            let mut team = Team::default();
            for x in 0..star.len() {
                let got = team.at(
                    &by,
                    star.as_slice(),
                    (x, (0, 0)),
                    (kx, ky.t),
                    &lens,
                    (f64::INFINITY, u2),
                );
                let Some((near, covered)) = got else {
                    backed += usize::from(x % TEAM == 0);
                    continue;
                };
                if x % TEAM != 0 {
                    continue;
                }
                tested += if round < 2 { covered.len() } else { 0 };
                let members = x..(x + TEAM).min(star.len());
                for c in covered.filter(|c| !near.contains(c)) {
                    ruled += usize::from(round < 2);
                    let edges = c * BLOCK * GROUP..((c + 1) * BLOCK * GROUP).min(wall.len() - 1);
                    for (i, e) in members
                        .clone()
                        .flat_map(|i| edges.clone().map(move |e| (i, e)))
                    {
                        // Far beyond by a rounded distance (a relative margin of 1% dwarfs its
                        // rounding), or beyond exactly.
                        let (v, s, t) = (star[i], wall[e], wall[e + 1]);
                        let h = ((v - s).dot(t - s) / (t - s).length_squared()).clamp(0.0, 1.0);
                        if (v - (s + (t - s) * h)).length_squared() > 1.01 * u2 {
                            continue;
                        }
                        let d = squared_distance_point_segment(v, s, t).expect("finite");
                        assert!(
                            d > to_rational(u2).expect("finite"),
                            "round {round}: member {i}, block {c}, edge {e}"
                        );
                    }
                }
            }
        }
        assert!(
            ruled * 2 > tested && backed > 0,
            "{ruled} of {tested}, {backed}"
        );
    }

    /// The levels above the wide blocks (an arc of 65,536 vertices: 128 wide blocks, 16 above
    /// them): from a vertex under the arc's end, whose window holds the whole arc, every coarse
    /// block left out of `near` is certainly farther than `√u2` (checked exactly near the
    /// threshold), the block holding the arc's end is kept, and the box tests are a few a level;
    /// from a vertex under the middle, farther than `√u2` from the whole arc, every block is left
    /// out by the sixteen boxes of the top level alone.
    #[test]
    fn levels_above_the_wide_blocks_rule_out_only_blocks_beyond() {
        use crate::monotone::keys;
        use polydist_predicates::exact::squared_distance_point_segment;
        let m = 65_536;
        let arc: Vec<DVec2> = (0..m)
            .map(|j| {
                let a = (120.0 - 60.0 * j as f64 / (m - 1) as f64).to_radians();
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        let (end, middle) = (DVec2::new(0.3, 0.0), DVec2::new(0.0, 0.0));
        let (a, b) = (DVec2::new(0.0, 0.5), DVec2::new(1.0, 0.5));
        let (kp, kq, lens) = keys(&[end, middle], &arc, a, b).expect("finite keys");
        let ky = Keys { t: &kq.0, d: &kq.1 };
        let by = Blocks::of(arc.as_slice(), ky);
        assert_eq!(
            (by.wide.t.len(), by.above.len(), by.above[0].t.len()),
            (128, 1, 16)
        );
        let span = Span::of((0, m), m);
        let covered = span.blocks(BLOCK * GROUP);
        // Just above the clearance from the end vertex to the arc's end.
        let u2 = end.distance_squared(arc[m - 1]) * (1.0 + 1e-9);
        let mut near = Vec::new();
        for (i, v) in [end, middle].into_iter().enumerate() {
            let before = by.tests();
            by.near(&span, (v, (kp.0[i], kp.1[i])), &lens, u2, &mut near);
            let tests = by.tests() - before;
            if i == 1 {
                assert!(near.is_empty() && tests == 16, "{near:?}, {tests} tests");
                continue;
            }
            assert!(near.contains(&(covered.end - 1)), "{near:?}");
            assert!(near.len() <= 4 && tests <= 64, "{near:?}, {tests} tests");
            for c in covered.clone().filter(|c| !near.contains(c)) {
                let edges = c * BLOCK * GROUP..((c + 1) * BLOCK * GROUP).min(m - 1);
                for e in edges {
                    let (s, t) = (arc[e], arc[e + 1]);
                    let h = ((v - s).dot(t - s) / (t - s).length_squared()).clamp(0.0, 1.0);
                    if (v - (s + (t - s) * h)).length_squared() > 1.01 * u2 {
                        continue;
                    }
                    let d = squared_distance_point_segment(v, s, t).expect("finite");
                    assert!(d > to_rational(u2).expect("finite"), "block {c}, edge {e}");
                }
            }
        }
    }

    /// `Near::box_gap2` never exceeds the exact squared distance from a point of the box to the
    /// part of the line between the `before` and `after` positions (checked at the corners and at
    /// random points inside, in rationals), and is positive often enough to prune.
    #[test]
    fn near_box_gaps_are_lower_bounds() {
        let mut rng = SplitMix64::new(0x9ea5);
        let (mut positive, mut zero) = (0, 0);
        let r = |x: f64| to_rational(x).expect("finite");
        for round in 0..6_000 {
            let class = round % 5;
            let mut pt = || point(&mut rng, class);
            let (a, c) = (pt(), pt());
            if a == c {
                continue;
            }
            let near = Near {
                a,
                c,
                before: [pt(), pt()],
                after: [pt(), pt()],
            };
            let (x0, x1) = (pt(), pt());
            let (lo, hi) = (x0.min(x1), x0.max(x1));
            let g = near.box_gap2(lo, hi);
            if g == 0.0 {
                zero += 1;
                continue;
            }
            positive += 1;
            let (dx, dy) = (r(c.x) - r(a.x), r(c.y) - r(a.y));
            let t = |y: DVec2| (r(y.x) - r(a.x)) * dx.clone() + (r(y.y) - r(a.y)) * dy.clone();
            let (t0, t1) = {
                let ts = near.before.iter().chain(&near.after).map(|&y| t(y));
                let ts: Vec<_> = ts.collect();
                let lo_t = ts[..2].iter().min().cloned().expect("two");
                let hi_t = ts[2..].iter().max().cloned().expect("two");
                (lo_t, hi_t)
            };
            if t0 > t1 {
                // No segment lies between such positions.
                continue;
            }
            let len = dx.clone() * dx.clone() + dy.clone() * dy.clone();
            let zero_r = r(0.0);
            let mut samples = vec![lo, hi, DVec2::new(lo.x, hi.y), DVec2::new(hi.x, lo.y)];
            samples.extend(
                (0..4).map(|_| lo + (hi - lo) * DVec2::new(rng.unit_f64(), rng.unit_f64())),
            );
            for x in samples
                .into_iter()
                .filter(|x| x.cmpge(lo).all() && x.cmple(hi).all())
            {
                let (wx, wy) = (r(x.x) - r(a.x), r(x.y) - r(a.y));
                let depth = dx.clone() * wy - dy.clone() * wx;
                let tx = t(x);
                let beyond = (t0.clone() - tx.clone())
                    .max(tx - t1.clone())
                    .max(zero_r.clone());
                // The squared distance to the points of the line with `t0 ≤ t ≤ t1`: `depth` and
                // `beyond` are that distance's two legs scaled by `|d|`.
                let exact = (depth.clone() * depth + beyond.clone() * beyond) / len.clone();
                assert!(exact >= r(g), "{near:?} box {lo} {hi} at {x}: gap {g}");
            }
        }
        assert!(positive > 2_000 && zero > 500, "{positive} {zero}");
    }

    /// The pruned scan with `Near` keeps a pair that meets the separator: on chains of up to 80
    /// points and a separator through a vertex of their nearest pair (in a random direction,
    /// stretched both ways), its winner is as near as the plain scan's, exactly.
    #[test]
    fn pruned_scan_near_the_separator_keeps_the_pair_meeting_it() {
        let mut rng = SplitMix64::new(0x5e9a);
        let mut pruned = 0;
        for round in 0..1_500 {
            let (p, q) = chain_pair(&mut rng, [0, 1, 4][round % 3], 80);
            let nearest = scan::<Robust>(&p, &q, true);
            let d = pair_dist(&p, &q, &nearest);
            let anchor = match (nearest.feature_p, nearest.feature_q) {
                (Feature::Vertex(i), _) => p[i],
                (_, Feature::Vertex(j)) => q[j],
                _ => unreachable!("a scan reports a vertex"),
            };
            let dir = DVec2::new(rng.range_i64(-3, 4) as f64, rng.range_i64(1, 4) as f64) / 64.0;
            let (s0, s1) = (rng.index(3) as f64, rng.index(3) as f64);
            let near = Near {
                a: anchor,
                c: anchor + dir,
                before: [anchor - dir * s0; 2],
                after: [anchor + dir * s1, anchor],
            };
            let boxes_far = boxes(&p)
                .iter()
                .chain(&boxes(&q))
                .filter(|b| near.box_gap2(b.lo, b.hi) > 0.0)
                .count();
            pruned += usize::from(boxes_far > 0);
            let (w, _) = scan_pruned_winner_below::<Robust>(&p, &q, f64::INFINITY, Some(&near));
            assert_eq!(
                Robust::cmp_dist2(w.cand.dist(p.as_slice(), q.as_slice()), d),
                Ordering::Equal,
                "{p:?} {q:?} {near:?}"
            );
        }
        assert!(pruned > 300, "{pruned}");
    }

    /// With a cut from the distance `G` of some pair, the scans skip what cannot beat `G`: when the
    /// nearest pair is strictly nearer than `G` they return the scan's features exactly; otherwise
    /// a pair no nearer than the nearest.
    #[test]
    fn scans_below_a_cut_keep_what_beats_it() {
        let mut rng = SplitMix64::new(0xc07);
        let (mut beaten, mut not) = (0, 0);
        for round in 0..3000 {
            let (p, q) = chain_pair(&mut rng, [0, 1, 4][round % 3], 12);
            let nearest = scan::<Robust>(&p, &q, true);
            let near = pair_dist(&p, &q, &nearest);
            // `G`: the nearest pair itself (a tie: nothing beats it), or a random vertex pair.
            let g = if round % 4 == 0 {
                near
            } else {
                Dist2::PointPoint(p[rng.index(p.len())], q[rng.index(q.len())])
            };
            let cut = upper_bound::<Robust>(g);
            for (w, hi) in [
                scan_winner_below::<Robust>(&p, &q, cut),
                scan_pruned_winner_below::<Robust>(&p, &q, cut, None),
            ] {
                let got = w.pair();
                let gd = w.cand.dist(p.as_slice(), q.as_slice());
                assert!(
                    to_rational(hi).is_none_or(|h| {
                        let e = match gd {
                            Dist2::PointPoint(x, y) => squared_distance_point_point(x, y),
                            Dist2::PointSegment(x, y, z) => squared_distance_point_segment(x, y, z),
                            _ => unreachable!(),
                        };
                        e.expect("finite") <= h
                    }),
                    "the returned bound is below the winner's distance"
                );
                if Robust::cmp_dist2(near, g) == Ordering::Less {
                    beaten += 1;
                    assert_eq!(
                        (got.feature_p, got.feature_q),
                        (nearest.feature_p, nearest.feature_q),
                        "{p:?} {q:?} cut {cut}"
                    );
                } else {
                    not += 1;
                    assert_ne!(Robust::cmp_dist2(gd, near), Ordering::Less);
                }
            }
        }
        assert!(beaten > 1000 && not > 1000, "{beaten} {not}");
    }

    /// A scan without the pairs of `seen`, folded with a scan of the seen vertices alone (which
    /// holds every seen candidate), finds the scan's distance exactly; and with nothing seen it is
    /// the scan, feature for feature.
    #[test]
    fn scans_without_seen_pairs_fold_to_the_scan() {
        let mut rng = SplitMix64::new(0x5ee);
        let mut skipped_the_winner = 0;
        for round in 0..3000 {
            let (p, q) = chain_pair(&mut rng, [0, 1, 4][round % 3], 10);
            let range = |rng: &mut SplitMix64, n: usize| {
                let a = rng.index(n + 1);
                let b = a + rng.index(n + 1 - a);
                a..b
            };
            let seen = Seen {
                p: range(&mut rng, p.len()),
                q: range(&mut rng, q.len()),
            };
            let whole = scan::<Robust>(&p, &q, true);
            let (w, _) = scan_winner_below_except::<Robust>(&p, &q, f64::INFINITY, seen.clone());
            let mut d = w.cand.dist(p.as_slice(), q.as_slice());
            if !seen.p.is_empty() && !seen.q.is_empty() {
                let (sp, sq) = (&p[seen.p.clone()], &q[seen.q.clone()]);
                let di = pair_dist(sp, sq, &scan::<Robust>(sp, sq, true));
                if Robust::cmp_dist2(di, d) == Ordering::Less {
                    skipped_the_winner += 1;
                    d = di;
                }
            }
            let dw = pair_dist(&p, &q, &whole);
            assert_eq!(
                Robust::cmp_dist2(d, dw),
                Ordering::Equal,
                "{p:?} {q:?} {seen:?}"
            );
            let (none, _) = scan_winner_below_except::<Robust>(&p, &q, f64::INFINITY, Seen::NONE);
            assert_eq!(
                none.features(),
                (whole.feature_p, whole.feature_q),
                "{p:?} {q:?}"
            );
        }
        // The seen ranges held the nearest pair often enough for the fold to matter.
        assert!(skipped_the_winner > 100, "{skipped_the_winner}");
    }

    #[test]
    fn box_nodes_hold_exactly_their_vertices() {
        // Each node's box is the least box of its vertices `s..=min(e, n − 1)` (inner nodes take the
        // union of their kids'), and its kids split its range at one vertex.
        let mut rng = SplitMix64::new(0xb0c5);
        for round in 0..400 {
            let n = 1 + rng.index(300);
            let c: Vec<DVec2> = (0..n).map(|_| point(&mut rng, round % 5)).collect();
            let nodes = boxes(&c);
            assert_eq!((nodes[0].s, nodes[0].e), (0, n));
            for node in &nodes {
                let own = &c[node.s..=node.e.min(n - 1)];
                let lo = own.iter().fold(own[0], |a, &v| a.min(v));
                let hi = own.iter().fold(own[0], |a, &v| a.max(v));
                assert_eq!((node.lo, node.hi), (lo, hi), "round {round}");
                if let Some((a, b)) = node.kids {
                    let (a, b) = (&nodes[a], &nodes[b]);
                    assert_eq!((a.s, a.e, b.e), (node.s, b.s, node.e), "round {round}");
                }
            }
        }
    }

    #[test]
    fn the_filtered_scan_is_the_plain_scan() {
        // `interior_only` scans (filtered) against the unfiltered scan over every candidate: the same
        // features, on random, lattice (exact ties) and far-away chains.
        let mut rng = SplitMix64::new(0x5ca7);
        for round in 0..3000 {
            let class = [0, 1, 4][round % 3];
            let n = 1 + rng.index(9);
            let m = 1 + rng.index(9);
            let p: Vec<DVec2> = (0..n).map(|_| point(&mut rng, class)).collect();
            let q: Vec<DVec2> = (0..m)
                .map(|_| point(&mut rng, class) + DVec2::new(0.75, 0.0))
                .collect();
            for (a, b) in [
                (scan::<Robust>(&p, &q, true), scan::<Robust>(&p, &q, false)),
                (scan::<Exact>(&p, &q, true), scan::<Exact>(&p, &q, false)),
                (
                    scan_pruned::<Robust>(&p, &q, true),
                    scan::<Robust>(&p, &q, false),
                ),
            ] {
                assert_eq!(
                    (a.feature_p, a.feature_q),
                    (b.feature_p, b.feature_q),
                    "{p:?} {q:?}"
                );
            }
        }
    }

    /// `cmp_scan_cut` orders as `cmp_scan` and the exact kernel, the best's cut its upper bound, on
    /// point pairs and point–segment distances of every scale class (lattice ties, near and far
    /// ones), and its bound decides often.
    #[test]
    fn the_cut_comparison_keeps_the_order() {
        let mut rng = SplitMix64::new(0xc07);
        let mut decided_by_bound = 0;
        for round in 0..30_000 {
            let class = round % 5;
            let dist = |rng: &mut SplitMix64| {
                let (v, a, b) = (point(rng, class), point(rng, class), point(rng, class));
                if rng.index(2) == 0 {
                    Dist2::PointPoint(v, a)
                } else {
                    Dist2::PointSegment(v, a, b)
                }
            };
            let (x, y) = (dist(&mut rng), dist(&mut rng));
            let cut = upper_bound::<Exact>(y);
            let order = cmp_scan_cut::<Robust>(x, y, cut);
            assert_eq!(order, cmp_scan::<Robust>(x, y), "{x:?} {y:?}");
            assert_eq!(order, Exact::cmp_dist2(x, y), "{x:?} {y:?}");
            assert_eq!(cmp_scan_cut::<Exact>(x, y, cut), order, "{x:?} {y:?}");
            decided_by_bound += usize::from(lower_bound(x) > cut);
        }
        assert!(decided_by_bound > 5_000, "{decided_by_bound}");
    }

    /// The scans' shortcut for axis-parallel distances agrees with the exact kernel, on lattice
    /// points (axis-parallel pairs, lines and segments galore, exact differences, projections
    /// inside, outside and at the ends of segments) and on points whose differences round (the
    /// shortcut must decline).
    #[test]
    fn axis_gaps_order_as_the_exact_kernel() {
        use polydist_predicates::Exact;
        let mut rng = SplitMix64::new(0xa815);
        let mut shortcut = 0;
        for round in 0..40_000 {
            let class = if round % 4 == 0 { 4 } else { 1 };
            let mut pt = || point(&mut rng, class);
            let (v, a, b, w, c, d) = (pt(), pt(), pt(), pt(), pt(), pt());
            let dist = |k: u64, v: DVec2, a: DVec2, b: DVec2| match k % 3 {
                0 => Dist2::PointPoint(v, a),
                1 => Dist2::PointLine(v, a, b),
                _ => Dist2::PointSegment(v, a, b),
            };
            let (x, y) = (dist(rng.below(3), v, a, b), dist(rng.below(3), w, c, d));
            shortcut += usize::from(axis_gap(x).is_some() && axis_gap(y).is_some());
            assert_eq!(
                cmp_scan::<Robust>(x, y),
                Exact::cmp_dist2(x, y),
                "{x:?} vs {y:?}"
            );
        }
        assert!(shortcut > 500, "{shortcut}");
        // A difference that rounds has no exact gap.
        assert_eq!(exact_gap(1.0, 1e-20), None);
        assert_eq!(exact_gap(5.0, 4.875), Some(0.125));
        assert_eq!(exact_gap(-0.0, 0.0), Some(0.0));
    }

    /// `congruent` claims a tie only where the exact kernel finds one: configurations moved by a
    /// translation and a signed permutation (the same one for both of a segment distance's vectors,
    /// the segment read from either end), decoys whose two vectors are moved by different maps or
    /// nudged by an ulp, and far-from-origin points whose differences round.
    #[test]
    fn congruent_distances_tie_as_the_exact_kernel() {
        let mut rng = SplitMix64::new(0xc06e);
        let (mut claimed, mut images) = (0, 0);
        let map = |s: u64, v: DVec2| {
            let v = if s & 4 != 0 { DVec2::new(v.y, v.x) } else { v };
            DVec2::new(
                if s & 1 != 0 { -v.x } else { v.x },
                if s & 2 != 0 { -v.y } else { v.y },
            )
        };
        for round in 0..30_000 {
            let class = [1, 1, 0, 4][round % 4];
            let (v, a, b) = (
                point(&mut rng, class),
                point(&mut rng, class),
                point(&mut rng, class),
            );
            let form = rng.below(3);
            let dist = |v: DVec2, a: DVec2, b: DVec2| match form {
                0 => Dist2::PointPoint(v, a),
                1 => Dist2::PointLine(v, a, b),
                _ => Dist2::PointSegment(v, a, b),
            };
            let x = dist(v, a, b);
            // The image: `a` moved by a lattice translation, `v − a` and `b − a` by a map each
            // (the same one unless this is a decoy), then possibly an ulp off, the ends swapped.
            let t = DVec2::new(rng.range_i64(-8, 9) as f64, rng.range_i64(-8, 9) as f64);
            let (s1, s2) = (rng.below(8), rng.below(8));
            let s2 = if rng.below(4) == 0 { s2 } else { s1 };
            let a2 = a + t;
            let mut v2 = a2 + map(s1, v - a);
            let b2 = a2 + map(s2, b - a);
            if rng.below(5) == 0 {
                v2.x = f64::from_bits(v2.x.to_bits() + 1);
            }
            let y = if rng.coin() {
                dist(v2, a2, b2)
            } else {
                dist(v2, b2, a2)
            };
            images += usize::from(s1 == s2);
            let exact = Exact::cmp_dist2(x, y);
            if congruent(x, y) {
                claimed += 1;
                assert_eq!(exact, Ordering::Equal, "{x:?} vs {y:?}");
            }
            assert_eq!(cmp_scan::<Robust>(x, y), exact, "{x:?} vs {y:?}");
        }
        assert!(claimed > 8_000, "{claimed} of {images} images claimed");
    }

    /// Windows that meet more coarse blocks than the budget, most of them ruled out by their
    /// boxes: a zigzag 0.6 wide facing an arc of radius 1 around it (the clearance, 0.89, exceeds
    /// both chains' extents along the line, so every window holds the whole arc). The blocks met
    /// exceed the budget (counted from below here: those whose first vertex is within the
    /// clearance of a zigzag vertex on both keys), yet the box tests and candidates fit it: the
    /// scan answers, with section 3's distance. With a budget below the box tests it declines,
    /// having counted them; and a zigzag a hair wide (every arc vertex within a hair of the
    /// clearance from every zigzag vertex, nothing ruled out) declines early, its work held to
    /// the budget.
    #[test]
    fn box_tests_count_when_the_blocks_met_exceed_the_budget() {
        use crate::monotone::keys;
        use crate::sigma::{ChainMethod, separation_of_chains_with};
        let h = 16_384;
        let (a, b) = (DVec2::new(0.0, 0.5), DVec2::new(1.0, 0.5));
        let chains = |s: f64| {
            let (p, q) = polydist_oracle::zigzag_under_arc(h, s);
            // The zigzag left to right (after the two corners below it), the arc as it is.
            let zig: Vec<DVec2> = p[2..].iter().rev().copied().collect();
            (zig, q[..h].to_vec())
        };
        let (zig, arc) = chains(0.6 / h as f64);
        let (kp, kq, lens) = keys(&zig, &arc, a, b).expect("finite keys");
        let (kx, ky) = (Keys { t: &kp.0, d: &kp.1 }, Keys { t: &kq.0, d: &kq.1 });
        let s3 = separation_of_chains_with::<Robust>(&zig, &arc, a, b, ChainMethod::Matrices)
            .expect("chains across the line");
        let sigma = s3.pair.distance * (1.0 - 1e-9);
        let size = BLOCK * GROUP;
        let met: usize = (0..h)
            .map(|x| {
                (0..h.div_ceil(size))
                    .filter(|c| {
                        let y = c * size;
                        (ky.t[y] - kx.t[x]).abs() <= sigma && (ky.d[y] - kx.d[x]).abs() <= sigma
                    })
                    .count()
            })
            .sum();
        let budget = 100_000;
        assert!(met > 2 * budget, "{met} blocks met");
        let scan = |zig: &[DVec2], arc: &[DVec2], kx, ky, lens, budget| {
            scan_windowed::<Robust, [DVec2]>(zig, arc, kx, ky, lens, f64::INFINITY, budget)
        };
        let (w, tried) = scan(&zig, &arc, kx, ky, &lens, budget).expect("within the budget");
        let dist = |f: (Feature, Feature)| feature_dist(&zig, &arc, f);
        let want = dist((s3.pair.feature_p, s3.pair.feature_q));
        assert_eq!(Robust::cmp_dist2(dist(w.features()), want), Ordering::Equal);
        assert!(tried <= budget, "{tried}");
        // Room for the candidates but not the box tests (some 8,500 here): declined, the tests
        // counted.
        let low = tried + 4_000;
        let work = scan(&zig, &arc, kx, ky, &lens, low).expect_err("beyond the budget");
        assert!((low..low + 16 * 2 * h).contains(&work), "{work} for {low}");
        // A hair wide: nothing ruled out, declined with the work held to the budget.
        let (zig, arc) = chains(2f64.powi(-30));
        let (kp, kq, lens) = keys(&zig, &arc, a, b).expect("finite keys");
        let (kx, ky) = (Keys { t: &kp.0, d: &kp.1 }, Keys { t: &kq.0, d: &kq.1 });
        let work = scan(&zig, &arc, kx, ky, &lens, budget).expect_err("beyond the budget");
        assert!(work <= budget + 16 * 2 * h, "{work}");
    }

    /// Any budget, from none to more than the windows hold: the windowed scan either answers with
    /// the exact scan's nearest pair or declines, on a zigzag facing an arc around it (random
    /// widths, from a hair to wider than the arc, random radii and arcs, ties on a dyadic grid or
    /// not) and on two dyadic corridors. Budgets below the first pass, below the blocks met, below
    /// the box tests or the candidates, and above them all are all drawn.
    #[test]
    fn any_budget_answers_exactly_or_declines() {
        use crate::monotone::keys;
        let mut rng = SplitMix64::new(0xb0d9);
        let (a, b) = (DVec2::new(0.0, -0.25), DVec2::new(1.0, -0.25));
        let (mut answered, mut declined) = (0usize, 0usize);
        for round in 0..400 {
            let (n, m) = (40 + rng.index(500), 40 + rng.index(500));
            let dyadic = |v: f64| (v * 1024.0).round() / 1024.0;
            let (p, q): (Vec<DVec2>, Vec<DVec2>) = if round % 4 < 3 {
                let width = [2f64.powi(-30), 0.05, 0.6, 1.5][rng.index(4)];
                let (r, from) = (0.5 + rng.unit_f64() * 1.5, 10.0 + rng.unit_f64() * 70.0);
                let p = (0..n)
                    .map(|i| {
                        let x = (i as f64 / (n - 1) as f64 - 0.5) * width;
                        DVec2::new(
                            x,
                            if i % 2 == 0 {
                                0.0
                            } else {
                                -width / (4.0 * n as f64)
                            },
                        )
                    })
                    .collect();
                let q = (0..m)
                    .map(|j| {
                        let a = (180.0 - from - (180.0 - 2.0 * from) * j as f64 / (m - 1) as f64)
                            .to_radians();
                        let v = DVec2::new(a.cos(), a.sin()) * r;
                        if round % 2 == 0 {
                            DVec2::new(dyadic(v.x), dyadic(v.y))
                        } else {
                            v
                        }
                    })
                    .collect();
                (p, q)
            } else {
                let wall = |rng: &mut SplitMix64, k: usize, side: f64| -> Vec<DVec2> {
                    (0..k)
                        .map(|i| {
                            DVec2::new(i as f64 / 64.0, side * (0.5 + rng.below(4) as f64 / 8.0))
                        })
                        .collect()
                };
                (wall(&mut rng, n, -1.0), wall(&mut rng, m, 1.0))
            };
            let (p, q): (Vec<DVec2>, Vec<DVec2>) = (
                p.into_iter().map(|v| v + DVec2::new(0.0, -0.5)).collect(),
                q.into_iter().map(|v| v + DVec2::new(0.0, 0.5)).collect(),
            );
            let mut p = p;
            p.dedup();
            let (kp, kq, lens) = keys(&p, &q, a, b).expect("finite keys");
            let (kx, ky) = (Keys { t: &kp.0, d: &kp.1 }, Keys { t: &kq.0, d: &kq.1 });
            // Log-uniform, from 1 to twice the pairs.
            let top = (2 * (p.len() + 1) * (q.len() + 1)) as f64;
            let budget = top.powf(rng.unit_f64()) as usize;
            let got =
                scan_windowed::<Robust, [DVec2]>(&p, &q, kx, ky, &lens, f64::INFINITY, budget);
            let Ok((w, _)) = got else {
                declined += 1;
                continue;
            };
            answered += 1;
            let want = scan::<Robust>(&p, &q, false);
            let dist = |f: (Feature, Feature)| feature_dist(&p, &q, f);
            assert_eq!(
                Robust::cmp_dist2(dist(w.features()), dist((want.feature_p, want.feature_q))),
                Ordering::Equal,
                "round {round}: budget {budget}"
            );
        }
        assert!(
            answered > 100 && declined > 50,
            "{answered} answered, {declined} declined"
        );
    }
}
