//! Separation of two simple polygons (Amato 1992, section 2): the intersection check and the
//! disjoint-hull fast path.
//!
//! σ(P, Q), the minimum distance between the boundaries of two disjoint simple polygons, with a
//! realizing pair. N. M. Amato, "An optimal algorithm for determining the separation of two
//! nonintersecting simple polygons" (UIUC report UILU-ENG-92-2248, 1992), section 2: when the convex
//! hulls `CH(P)` and `CH(Q)` are disjoint, a line separates the polygons and section 3 (the separable
//! chains, [`separation_of_chains`](crate::separation_of_chains)) applies to the boundaries directly;
//! otherwise the report builds a separator `S(P, Q)` (`separator.rs`,
//! `docs/algorithms/separator.md`): in the non-containing case, the pinched channel, and the
//! containing case (one polygon in a pocket of the other).
//!
//! # What is built
//! - [`intersection`]: do the closed polygons meet? Boundaries swept together (Shamos–Hoey), then one
//!   point location each way for containment. `O(N log N)`; every decision exact.
//! - [`separation`] = [`intersection`], then [`separation_of_disjoint`]: the hulls by Melkman
//!   (`O(N)`), their distance in `O(log N)` (the convex crate), a separating line through an edge of
//!   one hull (`O(N)` exact side tests of at most four candidate edges), then section 3 on the two
//!   whole boundaries, each passed as a closed chain.
//! - [`separation_brute`](crate::polygon_separation_brute): the `O(nm)` twin.
//!
//! - hulls that meet, polygons disjoint: the separator route ([`Route::Separators`]), whether the
//!   channel between the facing chains is open, pinched at one vertex, or one polygon lies in a
//!   pocket of the other (two passes, one per cut of the annulus).

use glam::DVec2;
use polydist_convex::{Closest, Separation, distance_with_hint};
use polydist_polygon::predicates::{Kernel, Orientation};
use polydist_polygon::{ConvexPolygon, Feature, Location, SimplePolygon};

use crate::brute::separation_brute;
use crate::envelope::least_extent_edge;
use crate::error::{Chain, SeparationError};
use crate::monotone::monotone_sweep;
use crate::result::{ClosestPair, SeparationStats};
use crate::separator;
use crate::sigma::{ChainMethod, chains_across_hull_edge};

/// A straight piece of a polygon's boundary between two of the caller's vertices: internal edge `e`
/// of a [`SimplePolygon`] joins the caller's vertices `from = source_index(e)` and
/// `to = source_index(e + 1)` (it may run through caller vertices dropped as repeats or collinear).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BoundaryPiece {
    /// The caller's vertex at the start of the piece (counter-clockwise order).
    pub from: usize,
    /// The caller's vertex at its end.
    pub to: usize,
}

/// How two simple polygons meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Intersection {
    /// The boundaries share a point: the piece `p` of `P`'s boundary and the piece `q` of `Q`'s cross,
    /// touch, or overlap along a line.
    Boundaries {
        /// A piece of `P`'s boundary.
        p: BoundaryPiece,
        /// A piece of `Q`'s boundary meeting it.
        q: BoundaryPiece,
    },
    /// The boundaries are disjoint and the polygon `inner` lies inside the other one: its caller
    /// vertex `vertex` is strictly inside.
    Contained {
        /// The polygon that lies inside the other.
        inner: Chain,
        /// A caller vertex of `inner`, strictly inside the other polygon.
        vertex: usize,
    },
}

/// Which computation produced a separation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Route {
    /// The closest features of the two convex hulls are both on the boundaries (no lid): their pair
    /// is the answer (`O(N)` for the hulls, `O(log N)` for their distance).
    HullFeatures,
    /// Section 3 on the two boundaries, separated by a line through an edge of one hull.
    SeparableChains,
    /// The hulls are disjoint and both facing chains are monotone along the separating line: the
    /// exact windowed sweep answered within its linear budget (`docs/algorithms/separation-polygons.md`,
    /// "The monotone sweep"); [`SeparationStats::sweep_candidates`] counts its candidates.
    MonotoneSweep,
    /// The hulls are disjoint, a facing chain is not monotone, and section 3's envelope sweep
    /// answered: the same exact windowed scan on Lemma 2's envelopes, which are monotone along the
    /// line whatever the chains are (`docs/algorithms/separation.md`, "The envelope sweep");
    /// [`SeparationStats::sweep_candidates`] counts its candidates.
    EnvelopeSweep,
    /// The hulls meet: Amato's separator `S(P, Q)` (non-containing case), then the subproblems
    /// `σ(P_i, Q_i)`; see [`SeparationStats`] for the separator's counts.
    Separators,
    /// The brute-force twin.
    BruteForce,
    /// The `O(n)` scan of a segment against every edge and vertex
    /// ([`segment_to_polygon`](crate::segment_to_polygon)).
    Scan,
}

/// The answer for two simple polygons: their separation, or how they meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PolygonSeparation {
    /// The closed polygons are disjoint: σ(P, Q) with a realizing pair. Features are the caller's
    /// (`Feature::Edge(j)` joins the caller's vertices `j` and `j + 1`, cyclically).
    Separated {
        /// The closest pair of the boundaries.
        pair: ClosestPair,
        /// Which computation found it.
        route: Route,
        /// Operation counts of section 3 ([`Route::SeparableChains`]) or of the separator
        /// ([`Route::Separators`]); zero for the other routes.
        stats: SeparationStats,
    },
    /// The closed polygons meet (σ is 0 and no pair is reported).
    Intersecting(Intersection),
}

impl PolygonSeparation {
    /// The separation: `0` when the polygons meet.
    #[must_use]
    pub fn distance(&self) -> f64 {
        match self {
            PolygonSeparation::Separated { pair, .. } => pair.distance,
            PolygonSeparation::Intersecting(_) => 0.0,
        }
    }
}

/// Whether the closed simple polygons `P` and `Q` meet, with a witness.
///
/// First the two boundaries are swept together ([`SimplePolygon::first_boundary_contact`], exact);
/// if they are disjoint, one polygon lies inside the other iff a vertex of it is inside the other
/// ([`SimplePolygon::locate_with`] under `K`). `None`: the polygons are disjoint.
///
/// # Complexity
/// `O(N log N)` expected (the sweep), `N = n + m`; the point locations are `O(N)`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{SimplePolygon, predicates::Robust};
/// use polydist_separation::{Intersection, intersection};
/// use polydist_separation::Chain;
///
/// let big = SimplePolygon::try_new(&[DVec2::ZERO, DVec2::new(9.0, 0.0), DVec2::new(9.0, 9.0), DVec2::new(0.0, 9.0)])?;
/// let small = SimplePolygon::try_new(&[DVec2::ONE, DVec2::new(2.0, 1.0), DVec2::new(2.0, 2.0)])?;
/// assert_eq!(intersection::<Robust>(&small, &big), Some(Intersection::Contained { inner: Chain::P, vertex: 0 }));
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
#[must_use]
pub fn intersection<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon) -> Option<Intersection> {
    if let Some((e, f)) = p.first_boundary_contact(q) {
        return Some(Intersection::Boundaries {
            p: piece(p, e),
            q: piece(q, f),
        });
    }
    contained::<K>(p, q)
}

/// The containment half of [`intersection`], for boundaries known to be disjoint: a vertex of one
/// polygon inside the other.
fn contained<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon) -> Option<Intersection> {
    for (inner, a, b) in [(Chain::P, p, q), (Chain::Q, q, p)] {
        if b.locate_with::<K>(a.vertices()[0]) != Location::Outside {
            return Some(Intersection::Contained {
                inner,
                vertex: a.source_index(0),
            });
        }
    }
    None
}

/// The caller's piece of internal edge `e`.
fn piece(p: &SimplePolygon, e: usize) -> BoundaryPiece {
    BoundaryPiece {
        from: p.source_index(e),
        to: p.source_index((e + 1) % p.len()),
    }
}

/// The separation σ(P, Q) of two simple polygons with a realizing pair, or how they meet.
///
/// First the hulls (as in [`separation_of_disjoint`]): disjoint hulls hold disjoint polygons, and the
/// fast path answers. When the hulls meet, [`intersection`] decides whether the polygons meet
/// ([`PolygonSeparation::Intersecting`]); if they do not, Amato's separator `S(P, Q)` reduces σ to
/// subproblems ([`Route::Separators`]; `docs/algorithms/separator.md`). Every decision is exact under
/// `K` = `Robust` or `Exact`.
///
/// # Errors
/// [`SeparationError::Inconsistent`] (and the other errors of [`separation_of_disjoint`]) only under
/// the `Fast` kernel.
///
/// # Complexity
/// Disjoint hulls: as [`separation_of_disjoint`] (`O(N)` plus section 3). Hulls that meet:
/// `O(N log N)` for the intersection sweep and the triangulation of the region between the facing
/// chains (without the pockets the other polygon never enters, found in `O(N log N)` worst case and
/// usually `O(N)`), `O(N)` for the geodesic, the extension arms and the greedy pruning, and section 3 on each
/// subproblem, except `O(|P_i| · |Q_i|)` for a subproblem whose subchains cross its line more often
/// than section 3's runs allow (`docs/algorithms/separator.md`).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{Feature, SimplePolygon, predicates::Robust};
/// use polydist_separation::{PolygonSeparation, separation};
///
/// // An L and a square to its right: the L's corner (2, 1) is nearest to the square's left edge.
/// let l = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
/// let l = SimplePolygon::try_from(&l[..])?;
/// let sq = SimplePolygon::try_from(&[[3.0, -1.0], [4.0, -1.0], [4.0, 3.0], [3.0, 3.0]][..])?;
/// let PolygonSeparation::Separated { pair, .. } = separation::<Robust>(&l, &sq).unwrap() else {
///     panic!("disjoint")
/// };
/// assert_eq!(pair.distance, 1.0);
/// assert_eq!(pair.feature_q, Feature::Edge(3));
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
///
/// # References
/// N. M. Amato, "An optimal algorithm for determining the separation of two nonintersecting simple
/// polygons", UIUC report UILU-ENG-92-2248 (1992), sections 2–3.
pub fn separation<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
) -> Result<PolygonSeparation, SeparationError> {
    // Disjoint hulls contain disjoint polygons: the sweep is needed only when the hulls meet.
    match hull_route::<K>(p, q, HullRouteMethod::Auto)? {
        Ok(answer) => Ok(answer),
        Err((hp, hq)) => match intersection::<K>(p, q) {
            Some(meet) => Ok(PolygonSeparation::Intersecting(meet)),
            None => separator_route::<K>(p, q, &hp, &hq),
        },
    }
}

/// σ(P, Q) of two simple polygons the caller knows to be disjoint (for instance from
/// [`intersection`]), as [`PolygonSeparation::Separated`]: the query alone, so that the check and the
/// query can be timed apart.
///
/// Section 2's fast path: `CH(P)` and `CH(Q)` by Melkman's algorithm; their distance and closest
/// features by the convex crate's `O(log N)` search. When neither closest hull feature is a *lid* (a
/// hull edge that is not part of the boundary, closing a pocket), that pair is the answer: the
/// boundaries lie inside the hulls, so σ(P, Q) ≥ dist(CH(P), CH(Q)), which the pair attains.
/// Otherwise a separating line through an edge of one hull
/// (a hull edge adjacent to the closest features whose line has the other hull strictly beyond it —
/// one always exists: the nearest point of `Z = CH(P) ⊖ CH(Q)` to the origin lies on a `Z`-edge visible
/// from the origin, and that edge is a hull edge at one of the two closest features); then the
/// monotone sweep when both facing chains are monotone along the line ([`Route::MonotoneSweep`]),
/// else section 3 ([`separation_of_chains_with`](crate::separation_of_chains_with) with
/// [`ChainMethod::Auto`]: its envelope sweep, [`Route::EnvelopeSweep`],
/// then its matrices, [`Route::SeparableChains`]) on the two whole boundaries, each passed as the
/// closed chain `v_0, …, v_{n−1}, v_0` of its internal vertices. Features are mapped back to the
/// caller's.
///
/// When the hulls meet, Amato's separator (as in [`separation`], without the intersection sweep).
///
/// # Errors
/// [`SeparationError::HullsIntersect`] when one polygon lies inside the other (their disjointness
/// is not checked; on meeting polygons the answer is unspecified, this error or another, but no
/// panic); [`SeparationError::Inconsistent`] and any error of
/// [`separation_of_chains`](crate::separation_of_chains) only under the `Fast` kernel.
///
/// # Complexity
/// `O(N)`: `O(N)` for the hulls and the separating line, `O(log N)` for the hull distance, and
/// section 3 on the boundaries (see [`separation_of_chains`](crate::separation_of_chains) for its
/// bound on general chains).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{SimplePolygon, predicates::Robust};
/// use polydist_separation::separation_of_disjoint;
///
/// let a = SimplePolygon::try_from(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..])?;
/// let b = SimplePolygon::try_from(&[[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]][..])?;
/// assert_eq!(separation_of_disjoint::<Robust>(&a, &b).unwrap().distance(), 2.0);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn separation_of_disjoint<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
) -> Result<PolygonSeparation, SeparationError> {
    separation_of_disjoint_with::<K>(p, q, HullRouteMethod::Auto)
}

/// How the disjoint-hull route answers once the hulls have given a separating line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum HullRouteMethod {
    /// The monotone sweep ([`Route::MonotoneSweep`]) when both facing chains are monotone along the
    /// line and its budget of `96N + 1024` candidates holds; otherwise section 3 with its envelope
    /// sweep first ([`ChainMethod::Auto`], [`Route::EnvelopeSweep`]),
    /// and its matrices when that declines.
    #[default]
    Auto,
    /// Section 3's matrices always ([`Route::SeparableChains`],
    /// [`ChainMethod::Matrices`]): the paper's algorithm alone, for
    /// comparison.
    Section3,
}

/// [`separation_of_disjoint`] with the disjoint-hull route's method chosen: [`HullRouteMethod::Auto`]
/// is [`separation_of_disjoint`]; [`HullRouteMethod::Section3`] never tries the monotone sweep, so
/// its cost can be measured apart. Pairs whose hulls meet take the separator route either way.
///
/// # Errors
/// As [`separation_of_disjoint`].
pub fn separation_of_disjoint_with<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    method: HullRouteMethod,
) -> Result<PolygonSeparation, SeparationError> {
    match hull_route::<K>(p, q, method)? {
        Ok(answer) => Ok(answer),
        Err((hp, hq)) => separator_route::<K>(p, q, &hp, &hq),
    }
}

/// The hulls' vertices as internal indices of `P` and of `Q`.
type HullIndices = (Vec<usize>, Vec<usize>);

/// The disjoint-hull route; when the hulls meet, `Err` with their vertices' internal indices.
fn hull_route<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    method: HullRouteMethod,
) -> Result<Result<PolygonSeparation, HullIndices>, SeparationError> {
    let ((hp, ip), (hq, iq)) = (
        p.convex_hull_and_indices_with::<K>(),
        q.convex_hull_and_indices_with::<K>(),
    );
    let (sep, hint) = distance_with_hint::<K>(&hp, &hq, None);
    let Separation::Disjoint(closest) = sep else {
        return Ok(Err((ip, iq)));
    };
    let (fp, fq) = hint.internal_pair().ok_or(SeparationError::Inconsistent)?;
    let lid = |h: &ConvexPolygon, f: Feature| matches!(f, Feature::Edge(e) if h.is_lid(e));
    if !lid(&hp, fp) && !lid(&hq, fq) {
        // Both closest hull features lie on the boundaries: σ ≥ dist(CH(P), CH(Q)) (the boundaries lie
        // in the hulls) and this pair realizes it, so it is optimal. The hulls' caller maps name the
        // polygons' caller features.
        return Ok(Ok(PolygonSeparation::Separated {
            pair: hull_pair(&closest),
            route: Route::HullFeatures,
            stats: SeparationStats::default(),
        }));
    }
    let (a, b) = separating_edge::<K>(&hp, fp, &hq, fq).ok_or(SeparationError::Inconsistent)?;
    if method == HullRouteMethod::Auto {
        if let Some(s) = monotone_sweep::<K>((p, &ip), (q, &iq), a, b) {
            return Ok(Ok(PolygonSeparation::Separated {
                pair: to_caller::<K>(p, q, s.pair),
                route: Route::MonotoneSweep,
                stats: SeparationStats {
                    sweep_candidates: s.tried,
                    ..SeparationStats::default()
                },
            }));
        }
    }
    // Each boundary starts after its edge of least extent along the line, so that Lemma 2's scan
    // closes each chain with it without copying the chain again to rotate it
    // (`envelope::least_extent_edge`).
    let shift =
        |p: &SimplePolygon| least_extent_edge(p.vertices(), b - a).map_or(0, |z| (z + 1) % p.len());
    let (sp, sq) = (shift(p), shift(q));
    let (cp, cq) = (closed_chain_from(p, sp), closed_chain_from(q, sq));
    let how = match method {
        HullRouteMethod::Auto => ChainMethod::Auto,
        HullRouteMethod::Section3 => ChainMethod::Matrices,
    };
    let (pair, stats, swept) = chains_across_hull_edge::<K>(&cp, &cq, (a, b), how)?;
    let unrotate = |f: Feature, n: usize, s: usize| match f {
        Feature::Vertex(i) => Feature::Vertex((i % n + s) % n),
        Feature::Edge(e) => Feature::Edge((e % n + s) % n),
    };
    let pair = ClosestPair {
        feature_p: unrotate(pair.feature_p, p.len(), sp),
        feature_q: unrotate(pair.feature_q, q.len(), sq),
        ..pair
    };
    Ok(Ok(PolygonSeparation::Separated {
        pair: to_caller::<K>(p, q, pair),
        route: if swept {
            Route::EnvelopeSweep
        } else {
            Route::SeparableChains
        },
        stats,
    }))
}

/// The hulls' closest pair as the polygons' (features through the hulls' caller maps).
pub(crate) fn hull_pair(closest: &Closest) -> ClosestPair {
    ClosestPair {
        distance: closest.distance,
        squared_distance: closest.squared_distance,
        point_p: closest.point_p,
        point_q: closest.point_q,
        feature_p: closest.feature_p,
        feature_q: closest.feature_q,
    }
}

/// The hulls meet and the polygons are disjoint: Amato's separator, then the subproblems.
fn separator_route<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    hp: &[usize],
    hq: &[usize],
) -> Result<PolygonSeparation, SeparationError> {
    let Some(built) = separator::build_with_hulls::<K>(p, q, hp, hq)? else {
        return Err(SeparationError::HullsIntersect);
    };
    let (pair, stats) = separator::solve::<K>(p, q, &built)?;
    Ok(PolygonSeparation::Separated {
        pair: to_caller::<K>(p, q, pair),
        route: Route::Separators,
        stats,
    })
}

/// The internal vertices of `p` followed by its first vertex again: the boundary as a closed chain.
pub(crate) fn closed_chain(p: &SimplePolygon) -> Vec<DVec2> {
    closed_chain_from(p, 0)
}

/// [`closed_chain`] starting at internal vertex `s` (`< n`): chain position `i` is internal vertex
/// `(i + s) mod n`, chain edge `i` internal edge `(i + s) mod n`.
fn closed_chain_from(p: &SimplePolygon, s: usize) -> Vec<DVec2> {
    let v = p.vertices();
    let mut c = Vec::with_capacity(v.len() + 1);
    c.extend_from_slice(&v[s..]);
    c.extend_from_slice(&v[..s]);
    c.push(v[s]);
    c
}

/// A line `(a, b)` through an edge of one hull with the other hull strictly on its outer side, among
/// the hull edges at the closest features `fp` of `hp` and `fq` of `hq` (internal indices). Edges at
/// a feature: both edges at a vertex, the edge itself.
pub(crate) fn separating_edge<K: Kernel>(
    hp: &ConvexPolygon,
    fp: Feature,
    hq: &ConvexPolygon,
    fq: Feature,
) -> Option<(DVec2, DVec2)> {
    let edges_at = |h: &ConvexPolygon, f: Feature| -> [Option<usize>; 2] {
        let n = h.len();
        if n < 2 {
            return [None, None];
        }
        if n == 2 {
            // A segment (the hull of a collinear polyline): its edges 0 and 1 are the segment in
            // both directions, and the closest feature names either; the other hull is on the
            // outer side of one of them.
            return [Some(0), Some(1)];
        }
        match f {
            Feature::Edge(e) => [Some(e), None],
            Feature::Vertex(v) => [Some((v + n - 1) % n), Some(v)],
        }
    };
    for (own, f, other) in [(hp, fp, hq), (hq, fq, hp)] {
        for e in edges_at(own, f).into_iter().flatten() {
            let v = own.vertices();
            let (a, b) = (v[e], v[(e + 1) % v.len()]);
            if a != b
                && other
                    .vertices()
                    .iter()
                    .all(|&y| K::orient(a, b, y) == Orientation::Clockwise)
            {
                return Some((a, b));
            }
        }
    }
    None
}

/// The pair with features in the callers' indices of `p` and `q` (chains as built by
/// [`closed_chain`]: vertex `n` is vertex `0`, edge `i` is internal edge `i`).
fn to_caller<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon, pair: ClosestPair) -> ClosestPair {
    ClosestPair {
        feature_p: caller_feature::<K>(p, pair.feature_p, pair.point_q),
        feature_q: caller_feature::<K>(q, pair.feature_q, pair.point_p),
        ..pair
    }
}

/// The caller's feature of `p` for the chain feature `f`; `other` is the realizing point on the
/// other polygon (an input vertex whenever `f` is an edge).
pub(crate) fn caller_feature<K: Kernel>(p: &SimplePolygon, f: Feature, other: DVec2) -> Feature {
    let n = p.len();
    match f {
        Feature::Vertex(i) => Feature::Vertex(p.source_index(i % n)),
        Feature::Edge(e) => p
            .caller_feature_on_edge::<K>(e % n, other)
            .unwrap_or(Feature::Edge(p.source_index(e % n))),
    }
}

/// [`separation`] by brute force, for testing: [`SimplePolygon::first_boundary_contact_brute`] and
/// the point locations, then every vertex–vertex and vertex–edge pair of the two boundaries
/// ([`separation_brute`] on the closed chains). Polygons whose hulls meet are
/// answered too.
///
/// # Errors
/// None under `Robust` or `Exact` (the `Result` mirrors [`separation`]).
///
/// # Complexity
/// `O(n m)` exact tests.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{SimplePolygon, predicates::Robust};
/// use polydist_separation::{polygon_separation_brute, separation};
///
/// let a = SimplePolygon::try_from(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..])?;
/// let b = SimplePolygon::try_from(&[[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]][..])?;
/// let brute = polygon_separation_brute::<Robust>(&a, &b).unwrap();
/// assert_eq!(brute.distance(), separation::<Robust>(&a, &b).unwrap().distance());
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn polygon_separation_brute<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
) -> Result<PolygonSeparation, SeparationError> {
    if let Some((e, f)) = p.first_boundary_contact_brute(q) {
        return Ok(PolygonSeparation::Intersecting(Intersection::Boundaries {
            p: piece(p, e),
            q: piece(q, f),
        }));
    }
    if let Some(meet) = contained::<K>(p, q) {
        return Ok(PolygonSeparation::Intersecting(meet));
    }
    let (cp, cq) = (closed_chain(p), closed_chain(q));
    let pair = separation_brute::<K>(&cp, &cq)?;
    Ok(PolygonSeparation::Separated {
        pair: to_caller::<K>(p, q, pair),
        route: Route::BruteForce,
        stats: SeparationStats::default(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::{validate_across_hull_edge, validate_touching};
    use polydist_oracle::{SplitMix64, hooked_teeth_facing, sawteeth_facing, star};
    use polydist_polygon::predicates::Robust;

    /// The disjoint-hull route reads only the line's orientation and skips the side check
    /// (`validate_across_hull_edge`): wherever the route reaches that step, the full check on the
    /// same line passes, gives the same frames, and finds no pair of vertices on the line. Saw-teeth
    /// and hooked teeth facing each other (lids closest), turned by random angles and taken in both
    /// orders, and random stars side by side.
    #[test]
    fn the_separating_hull_edge_needs_no_side_check() {
        let mut rng = SplitMix64::new(0x51de);
        let turn = |v: &[DVec2], c: f64, s: f64| -> Vec<DVec2> {
            v.iter()
                .map(|p| DVec2::new(c * p.x - s * p.y, s * p.x + c * p.y))
                .collect()
        };
        let mut pairs: Vec<(Vec<DVec2>, Vec<DVec2>)> = Vec::new();
        for t in [1, 2, 7, 40] {
            for (a, b) in [sawteeth_facing(t), hooked_teeth_facing(t)] {
                let angle = rng.unit_f64() * core::f64::consts::TAU;
                let (s, c) = angle.sin_cos();
                pairs.push((turn(&a, c, s), turn(&b, c, s)));
                pairs.push((b.clone(), a.clone()));
                pairs.push((a, b));
            }
        }
        for _ in 0..40 {
            let a = star(&mut rng, 60, 9);
            let b = star(&mut rng, 60, 9);
            // `b` moved right of `a`'s box by up to a tenth of its width, and up or down a little.
            let right = a.iter().map(|v| v.x).fold(f64::MIN, f64::max);
            let left = b.iter().map(|v| v.x).fold(f64::MAX, f64::min);
            let width = right - a.iter().map(|v| v.x).fold(f64::MAX, f64::min);
            let shift = DVec2::new(
                right - left + width * (1e-9 + 0.1 * rng.unit_f64()),
                width * (rng.unit_f64() - 0.5),
            );
            pairs.push((a, b.iter().map(|&v| v + shift).collect()));
        }
        let mut checked = 0;
        for (a, b) in &pairs {
            let (Ok(p), Ok(q)) = (SimplePolygon::try_new(a), SimplePolygon::try_new(b)) else {
                continue;
            };
            let (hp, hq) = (
                p.convex_hull_with::<Robust>(),
                q.convex_hull_with::<Robust>(),
            );
            let (sep, hint) = distance_with_hint::<Robust>(&hp, &hq, None);
            let Separation::Disjoint(_) = sep else {
                continue;
            };
            let (fp, fq) = hint.internal_pair().expect("a certified pair");
            let (l0, l1) = separating_edge::<Robust>(&hp, fp, &hq, fq).expect("a separating edge");
            let (cp, cq) = (closed_chain(&p), closed_chain(&q));
            let full = validate_touching::<Robust>(&cp, &cq, l0, l1).expect("both on their sides");
            let quick = validate_across_hull_edge::<Robust>(&cp, &cq, l0, l1).expect("frames");
            assert!(!full.on_line.both(), "{a:?} {b:?}");
            let (Some(f), Some(g)) = (full.frames, quick.frames) else {
                panic!("no frames");
            };
            assert_eq!((f.p.l0, f.p.l1, f.p.mirror), (g.p.l0, g.p.l1, g.p.mirror));
            assert_eq!((f.q.l0, f.q.l1, f.q.mirror), (g.q.l0, g.q.l1, g.q.mirror));
            checked += 1;
        }
        assert!(checked >= 40, "only {checked} pairs had disjoint hulls");
    }
}
