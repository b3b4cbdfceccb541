//! The result types: what a distance query returns.

use core::cell::Cell;

use glam::DVec2;
use polydist_polygon::Feature;

/// The closest pair of two disjoint convex polygons.
///
/// Features are in the **caller's** indices (the positions in the slices given to
/// [`ConvexPolygon::try_new`](polydist_polygon::ConvexPolygon::try_new)); edge `j` joins the caller's
/// vertices `j` and `j + 1`. A segment's feature is `Edge(0)` (or a vertex), a point's is `Vertex(0)`.
///
/// The pair `(feature_p, feature_q)` always realizes the distance exactly (decided by exact predicates
/// under the Robust and Exact kernels): it is a vertex–vertex or a vertex–edge pair. When the contact is
/// between two parallel edges (`parallel == true`) the realizing points are not unique; we report one
/// realizing vertex–edge (or vertex–vertex) pair, the one the search stopped at, and its points.
///
/// A hull's *lid* edge (see [`ConvexPolygon::is_lid`](polydist_polygon::ConvexPolygon::is_lid)) is no
/// caller feature; a foot inside one is reported as `Edge(j)` with `j` the caller index of the lid's
/// first vertex. Polygons built by `try_new` have no lids.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closest {
    /// The distance, within 2.5 ulps of the exact value (see the crate docs for the budget).
    pub distance: f64,
    /// The squared distance, within 3 ulps of the exact value.
    pub squared_distance: f64,
    /// A realizing point on `P` (a vertex exactly, or the foot of a perpendicular within 1 ulp per coordinate).
    pub point_p: DVec2,
    /// A realizing point on `Q`.
    pub point_q: DVec2,
    /// The caller's feature of `P` containing `point_p`.
    pub feature_p: Feature,
    /// The caller's feature of `Q` containing `point_q`.
    pub feature_q: Feature,
    /// `true` when both support faces are edges: the polygons face each other along parallel edges.
    pub parallel: bool,
}

/// How two convex polygons (points and segments included) relate, with the closest pair when they are
/// disjoint.
///
/// With relative interiors `relint(point) = the point`, `relint(segment) = the open segment` and
/// `relint(polygon with area) = its open interior`:
/// - [`Separation::Disjoint`]: the closed sets do not meet;
/// - [`Separation::Touching`]: they meet, but their relative interiors do not;
/// - [`Separation::Overlapping`]: their relative interiors meet (containment included; two equal
///   points overlap).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Separation {
    /// The polygons do not meet: their closest pair.
    Disjoint(Closest),
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

impl Separation {
    /// The distance: `0` for touching or overlapping polygons.
    #[must_use]
    pub fn distance(&self) -> f64 {
        match self {
            Separation::Disjoint(c) => c.distance,
            _ => 0.0,
        }
    }

    /// The closest pair when disjoint.
    #[must_use]
    pub fn closest(&self) -> Option<&Closest> {
        match self {
            Separation::Disjoint(c) => Some(c),
            _ => None,
        }
    }
}

/// What the `O(log)` search did on this thread since the last [`reset_search_stats`]: how often its
/// answer failed the Theorem-1 certificate and what repaired it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SearchStats {
    /// Calls of the `O(log)` path ([`distance_yang_with`](crate::distance_yang_with)).
    pub calls: u64,
    /// Guided searches (under the kernel's [`Guide`](polydist_polygon::predicates::Kernel::Guide), when it
    /// differs from the kernel) whose candidate failed the certificate, so that the search ran again
    /// under the kernel itself (includes every meeting input).
    pub guide_failures: u64,
    /// Answers of the first search under the kernel itself that failed the certificate (includes every
    /// meeting input).
    pub certificate_failures: u64,
    /// Failures repaired by the second search, seeded from the first answer (still `O(log)`).
    pub repaired_by_retry: u64,
    /// Disjoint inputs on which both searches failed and Schwartz's `O(log² N)` search answered.
    pub schwartz_fallbacks: u64,
    /// Disjoint inputs on which Schwartz's answer failed the certificate too (possible only with an
    /// inexact kernel): the brute force answered.
    pub brute_fallbacks: u64,
    /// Queries of [`distance_with`](crate::distance_with) on small polygons answered by the linear
    /// walk's certified pair, without the search.
    pub linear_walks: u64,
    /// Calls of [`distance_within`](crate::distance_within) answered by its early exit (a supporting
    /// line of `P` with all of `Q` more than `r` beyond it), without the full search.
    pub within_early_exits: u64,
    /// Main-loop iterations of the last search.
    pub last_iterations: u32,
    /// The iteration bound `⌈log₂n⌉ + ⌈log₂m⌉ + 4` of the last search.
    pub last_bound: u32,
}

std::thread_local! {
    static STATS: Cell<SearchStats> = const { Cell::new(SearchStats {
        calls: 0, guide_failures: 0, certificate_failures: 0, repaired_by_retry: 0, schwartz_fallbacks: 0, brute_fallbacks: 0, linear_walks: 0, within_early_exits: 0,
        last_iterations: 0, last_bound: 0,
    }) };
}

/// The [`SearchStats`] accumulated on this thread.
#[must_use]
pub fn search_stats() -> SearchStats {
    STATS.with(Cell::get)
}

/// Sets this thread's [`SearchStats`] to zero.
pub fn reset_search_stats() {
    STATS.with(|c| c.set(SearchStats::default()));
}

/// Updates this thread's statistics.
pub(crate) fn bump(f: impl FnOnce(&mut SearchStats)) {
    STATS.with(|c| {
        let mut v = c.get();
        f(&mut v);
        c.set(v);
    });
}
