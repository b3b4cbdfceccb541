//! Minimum vertex distance between two convex polygons: the pair of vertices `(v_i, w_j)`, one of
//! each polygon, that minimizes `|v_i − w_j|`.
//!
//! M. McKenna and G. T. Toussaint, "Finding the minimum vertex distance between two disjoint convex
//! polygons in linear time", *Computers & Mathematics with Applications*, 1985: `O(m + n)` for
//! linearly separable polygons, optimal (their Theorem 3). The files follow the paper:
//!
//! - `tenstep`: PROCEDURE TENSTEP (§3) from the bridge of the `O(log m + log n)` distance
//!   ([`distance_with`](crate::distance_with)); the rotation of steps 2–3 is replaced by exact
//!   predicates on input points ("above" is the sign of a dot product with the bridge's edge).
//! - `findmin`: FUNCTION FINDMIN (§4, Lemma 6 unimodality) for steps 6–8, with the errata of lines
//!   6–12 applied.
//! - `cases`: step 9 (§5) through the nine cases of Fig. 5 and the sub-cases 6.1–6.4 of Fig. 8, which
//!   the paper's text conversion lacks: reconstructed (and proved) in
//!   `docs/algorithms/vertex-distance.md`.
//! - `scanset`: SCANSET (Lemma 12), and USERNG replaced by SMAWK row minima on a Monge matrix
//!   (the `monotone-minima` crate), entries compared exactly.
//! - `meeting`: touching or overlapping polygons (not in the paper): a recursive split into separated
//!   pairs, `O((m + n) log(m + n))`.
//! - `stats`: diagnostic counters (which case ran), for tests.
//!
//! Every decision is the sign of a polynomial in the input coordinates (orientation, dot-product
//! signs, the nearer-of-two comparison `cmp_dist` and the four-point comparison `cmp_dist4`, one
//! degree-2 side test in `meeting`); the only construction is the reported distance.

mod cases;
mod chain;
mod findmin;
mod meeting;
mod scanset;
mod stats;
mod tenstep;
#[cfg(test)]
mod tests;

use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Robust};

pub use stats::{
    VertexDistanceCounts, reset_vertex_distance_case_counts, vertex_distance_case_counts,
};

use self::chain::{Best, Callers, Cand};
use self::stats::bump;
use self::tenstep::{Ring, scan_all};
use crate::hint::{Solved, solve};

/// The nearest pair of vertices of two convex polygons, in the **caller's** indices.
///
/// The vertices are those of the validated polygons (collinear and repeated input vertices, dropped
/// by [`ConvexPolygon::try_new`], are not candidates); `vertex_p` and `vertex_q` are their positions in
/// the slices the caller gave (see [`ConvexPolygon::source_index`]). A point has the single vertex
/// `0`, a segment its two end vertices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexDistance {
    /// `|p − q|²`: the exact value rounded once (within 0.5 ulp).
    pub squared_distance: f64,
    /// `|p − q|`: the square root of `squared_distance`, rounded (within 1 ulp of the exact distance).
    pub distance: f64,
    /// The caller's index of the vertex of `P`.
    pub vertex_p: usize,
    /// The caller's index of the vertex of `Q`.
    pub vertex_q: usize,
}

/// The answer from the best candidate (every path offers at least one pair of non-empty polygons).
fn answer<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, best: Best) -> VertexDistance {
    let c = best.cand.unwrap_or_else(|| {
        // Unreachable for validated polygons (at least one vertex each); kept total without a panic.
        let mut b = Best::default();
        scan_all::<K>(ring(p), ring(q), &mut b);
        b.cand.unwrap_or(Cand {
            p: p.vertices()[0],
            q: q.vertices()[0],
            i: p.source_index(0),
            j: q.source_index(0),
        })
    });
    let built = crate::construct::vertex_vertex(c.p, c.q);
    VertexDistance {
        squared_distance: built.squared,
        distance: built.distance,
        vertex_p: c.i,
        vertex_q: c.j,
    }
}

/// A validated polygon as one side of the problem.
fn ring(poly: &ConvexPolygon) -> Ring<'_> {
    Ring {
        pts: poly.vertices(),
        caller: Callers::Polygon(poly),
    }
}

/// The minimum vertex distance of two convex polygons (points and segments included) and a realizing
/// vertex pair, every decision made by the kernel `K`.
///
/// - Disjoint polygons: McKenna and Toussaint's TENSTEP from the bridge of the `O(log m + log n)`
///   distance ([`distance_with`](crate::distance_with)): FINDMIN for three pairs of chains, the nine
///   cases of step 9 with SCANSET and USERNG (implemented as SMAWK on a Monge matrix). A point or a
///   segment against a polygon is one linear scan.
/// - Touching or overlapping polygons (the contact status is the exact one of
///   [`distance_with`](crate::distance_with)): a recursive split into strictly separated vertex
///   subsets, each answered by TENSTEP (see the crate's `docs/algorithms/vertex-distance.md`).
///
/// Under the Robust and Exact kernels the squared distance is the exact minimum rounded once and the
/// pair realizes it exactly. Under [`Fast`](polydist_polygon::predicates::Fast) the pair may be wrong
/// on near-degenerate input; the call still terminates within the same bounds and never panics.
///
/// **Ties.** Among equal candidates the algorithm keeps the smaller caller pair `(vertex_p, vertex_q)`
/// (lexicographically); candidates are the bridge pair, one nearest vertex per row of FINDMIN and of
/// each SMAWK block (the first in chain order on ties), and every pair of a SCANSET. The reported pair
/// is therefore a minimizing pair, the same for the same input and kernel, but not necessarily the
/// lexicographically smallest minimizing pair (that one is what
/// [`min_vertex_distance_brute`] reports). For a point or a segment against anything, and for inputs
/// answered by brute force inside the recursive split, it is the lexicographically smallest.
///
/// # Complexity
/// `O(m + n)` predicates for disjoint polygons (steps 6–8: at most `3β + 2α` nearer-of-two
/// comparisons per FINDMIN; step 9: linear walks and SMAWK). `O((m + n) log(m + n))` for touching or
/// overlapping polygons, plus the `O(m log n + n log m)` contact test of
/// [`distance_with`](crate::distance_with) that classified them. `O(m + n)` memory.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::min_vertex_distance_with;
/// use polydist_convex::polygon::{ConvexPolygon, predicates::Exact};
///
/// // A vertex–edge bridge: the nearest vertices are not the bridge's ends.
/// let p = ConvexPolygon::try_new(&[DVec2::new(0.0, -3.0), DVec2::new(1.0, 0.0), DVec2::new(0.0, 3.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(4.0, -2.0), DVec2::new(6.0, 0.0), DVec2::new(4.0, 2.0)])?;
/// let d = min_vertex_distance_with::<Exact>(&p, &q);
/// assert_eq!((d.vertex_p, d.vertex_q), (1, 0)); // (1, 0)–(4, −2): the first of two tied pairs
/// assert_eq!(d.squared_distance, 13.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// M. McKenna, G. T. Toussaint, "Finding the minimum vertex distance between two disjoint convex
/// polygons in linear time", Comp. & Maths. with Appls., 1985. USERNG's substitute:
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", Algorithmica 2, 1987.
#[must_use]
pub fn min_vertex_distance_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> VertexDistance {
    bump(|s| s.calls += 1);
    let (rp, rq) = (ring(p), ring(q));
    let mut best = Best::default();
    match solve::<K>(p, q) {
        Solved::Disjoint(_, pair) => tenstep::tenstep::<K>(rp, rq, pair, &mut best),
        Solved::Meeting(_) => meeting::meeting::<K>(rp, rq, &mut best),
    }
    answer::<K>(p, q, best)
}

/// [`min_vertex_distance_with`] under the default [`Robust`] kernel: exact decisions.
///
/// # Complexity
/// `O(m + n)` for disjoint polygons, `O((m + n) log(m + n))` otherwise (see
/// [`min_vertex_distance_with`]).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{min_vertex_distance, polygon::ConvexPolygon};
///
/// let square = |x: f64, y: f64| ConvexPolygon::try_new(&[
///     DVec2::new(x, y), DVec2::new(x + 1.0, y), DVec2::new(x + 1.0, y + 1.0), DVec2::new(x, y + 1.0),
/// ]);
/// let d = min_vertex_distance(&square(0.0, 0.0)?, &square(4.0, 5.0)?);
/// assert_eq!((d.vertex_p, d.vertex_q, d.distance), (2, 0, 5.0));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`min_vertex_distance_with`].
#[must_use]
pub fn min_vertex_distance(p: &ConvexPolygon, q: &ConvexPolygon) -> VertexDistance {
    min_vertex_distance_with::<Robust>(p, q)
}

/// The minimum vertex distance by brute force, **for testing** and as a baseline: every pair,
/// compared with the kernel's four-point comparison `cmp_dist4`.
///
/// Reports the lexicographically smallest caller pair `(vertex_p, vertex_q)` among the minimizing
/// pairs (exactly, under the Robust and Exact kernels).
///
/// # Complexity
/// `Θ(m·n)` predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{min_vertex_distance_brute, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::new(0.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, 4.0), DVec2::new(0.0, 5.0), DVec2::new(-5.0, 0.0)])?;
/// let d = min_vertex_distance_brute::<Robust>(&p, &q);
/// assert_eq!((d.vertex_p, d.vertex_q, d.distance), (0, 0, 5.0)); // all three tie: the first
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// The problem: McKenna and Toussaint (1985), see [`min_vertex_distance_with`].
#[must_use]
pub fn min_vertex_distance_brute<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> VertexDistance {
    let mut best = Best::default();
    scan_all::<K>(ring(p), ring(q), &mut best);
    answer::<K>(p, q, best)
}
