//! An open polyline (a toolpath, a wire, a road centre line) against a simple polygon: section 2's
//! disjoint-hull route, which carries over to an open chain unchanged, and a typed error where the
//! separator does not (`docs/algorithms/separation-polygons.md`, "Open polylines").

use glam::DVec2;
use polydist_convex::{Separation, distance_with_hint};
use polydist_polygon::predicates::Kernel;
use polydist_polygon::{Feature, PolygonError, SimplePolygon, convex_hull_with};

use crate::error::{Chain, SeparationError};
use crate::monotone::monotone_sweep_polyline;
use crate::polygon::{
    PolygonSeparation, Route, caller_feature, closed_chain, hull_pair, separating_edge,
};
use crate::result::{ClosestPair, SeparationStats};
use crate::sigma::{ChainMethod, chains};
use crate::simple_distance::segment_to_polygon;

/// σ(T, Q) of an open simple polyline `T` and a simple polygon `Q` whose convex hulls are disjoint:
/// the minimum distance between `T` and `Q`'s boundary, with a realizing pair.
///
/// Amato's section 2 fast path, for an open chain: the hulls (`CH(T)` by Andrew's monotone chain,
/// `CH(Q)` by Melkman's), their distance and closest features by the convex crate's `O(log N)`
/// search. When those features are a vertex of `CH(T)` (a vertex of `T`) and a feature of `CH(Q)`
/// on `Q`'s boundary (not a lid), that pair is the answer ([`Route::HullFeatures`]); otherwise a
/// separating line through an edge of one hull at those features; then, when `T` is monotone along
/// that line and so is `Q`'s facing chain, the exact windowed sweep ([`Route::MonotoneSweep`],
/// `docs/algorithms/separation-polygons.md`, "The monotone sweep"), otherwise section 3
/// ([`separation_of_chains`](crate::separation_of_chains)) on `T` (open) and `Q`'s boundary
/// (closed). Disjoint hulls hold disjoint sets, so no intersection check is needed.
///
/// When the hulls meet (the polyline reaches into a pocket of `Q`, or wraps around it) the
/// separator of [`separation`](crate::separation) does not carry over: it is built from the region
/// between two facing *boundaries*, and the rest of an open polyline, which encloses nothing, can
/// lie inside that region. That case is [`SeparationError::PolylineHullsMeet`];
/// [`separation_brute`](crate::separation_brute) answers it in `O(nm)`.
///
/// A polyline of two vertices is a segment and goes to
/// [`segment_to_polygon`], which answers every position ([`Route::Scan`],
/// or [`PolygonSeparation::Intersecting`]).
///
/// Edge `i` of `T` joins its vertices `i` and `i + 1`; repeated consecutive vertices are dropped
/// (features name the first of a repeat). `T` must be simple (no two non-adjacent edges meet): the
/// caller's duty, as for [`separation_of_chains`](crate::separation_of_chains); violations met on
/// the way are [`SeparationError::NotSimple`]. `Q`'s features are the caller's.
///
/// # Errors
/// [`SeparationError::EmptyChain`] (chain `P`) for an empty polyline,
/// [`SeparationError::InvalidCoordinate`] (chain `P`, the first offending index),
/// [`SeparationError::PolylineHullsMeet`], [`SeparationError::NotSimple`]; under the `Fast`
/// kernel also [`SeparationError::Inconsistent`] or any error of section 3.
///
/// # Complexity
/// `O(n log n)` for `T`'s hull (a sort), `O(m)` for `Q`'s, `O(log N)` for their distance, `O(N)` for
/// the separating line, and section 3 (`O(N log N)` in the worst case, for the envelope; `O(N)` on
/// chains monotone along the line).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{Feature, SimplePolygon, predicates::Robust};
/// use polydist_separation::{PolygonSeparation, SeparationError, polyline_to_polygon};
///
/// // A zig-zag toolpath left of a unit square: its vertex (−1, 0.5) is nearest to the edge x = 0.
/// let path = [DVec2::new(-3.0, 0.0), DVec2::new(-1.0, 0.5), DVec2::new(-3.0, 1.0), DVec2::new(-2.0, 2.0)];
/// let sq = SimplePolygon::try_from(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][..])?;
/// let PolygonSeparation::Separated { pair, .. } = polyline_to_polygon::<Robust>(&path, &sq)? else {
///     panic!("disjoint hulls hold disjoint sets");
/// };
/// assert_eq!(pair.distance, 1.0);
/// assert_eq!((pair.feature_p, pair.feature_q), (Feature::Vertex(1), Feature::Edge(3)));
///
/// // A path reaching into the square's hull is not taken.
/// let into = [DVec2::new(-1.0, 0.5), DVec2::new(-0.5, 0.5), DVec2::new(0.5, 0.5)];
/// assert_eq!(polyline_to_polygon::<Robust>(&into, &sq), Err(SeparationError::PolylineHullsMeet));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # References
/// N. M. Amato, "An optimal algorithm for determining the separation of two nonintersecting simple
/// polygons", UIUC report UILU-ENG-92-2248 (1992), sections 2–3.
pub fn polyline_to_polygon<K: Kernel>(
    t: &[DVec2],
    q: &SimplePolygon,
) -> Result<PolygonSeparation, SeparationError> {
    if let [a, b] = *t {
        // A segment: the `O(m)` scan answers every position, meeting hulls and contact included
        // (and validates both ends).
        return segment_to_polygon::<K>(a, b, q);
    }
    // The hull validates the polyline: emptiness and every coordinate, the first offender named.
    let ht = convex_hull_with::<K>(t).map_err(|e| match e {
        PolygonError::NonFinite { index } | PolygonError::OutOfRange { index } => {
            SeparationError::InvalidCoordinate {
                chain: Chain::P,
                index,
            }
        }
        PolygonError::Empty => SeparationError::EmptyChain { chain: Chain::P },
        // Andrew's hull of a validated point set reports nothing else.
        _ => SeparationError::Inconsistent,
    })?;
    let hq = q.convex_hull_with::<K>();
    let (sep, hint) = distance_with_hint::<K>(&ht, &hq, None);
    let Separation::Disjoint(closest) = sep else {
        return Err(SeparationError::PolylineHullsMeet);
    };
    let (ft, fq) = hint.internal_pair().ok_or(SeparationError::Inconsistent)?;
    if matches!(ft, Feature::Vertex(_)) && !matches!(fq, Feature::Edge(e) if hq.is_lid(e)) {
        // A hull vertex of `T` is a vertex of `T`, and `Q`'s closest hull feature lies on its
        // boundary: the pair realizes the hulls' distance, a lower bound of σ, so it is optimal.
        // (Every edge of `T`'s hull counts as a lid: an edge there goes to section 3.)
        return Ok(PolygonSeparation::Separated {
            pair: hull_pair(&closest),
            route: Route::HullFeatures,
            stats: SeparationStats::default(),
        });
    }
    let (a, b) = separating_edge::<K>(&ht, ft, &hq, fq).ok_or(SeparationError::Inconsistent)?;
    if let Some(s) = monotone_sweep_polyline::<K>(t, q, a, b) {
        return Ok(PolygonSeparation::Separated {
            pair: ClosestPair {
                feature_q: caller_feature::<K>(q, s.pair.feature_q, s.pair.point_p),
                ..s.pair
            },
            route: Route::MonotoneSweep,
            stats: SeparationStats {
                sweep_candidates: s.tried,
                ..SeparationStats::default()
            },
        });
    }
    let (pair, stats, swept) = chains::<K>(
        t,
        &closed_chain(q),
        (a, b),
        ChainMethod::Auto,
        f64::INFINITY,
    )?;
    Ok(PolygonSeparation::Separated {
        pair: ClosestPair {
            feature_q: caller_feature::<K>(q, pair.feature_q, pair.point_p),
            ..pair
        },
        route: if swept {
            Route::EnvelopeSweep
        } else {
            Route::SeparableChains
        },
        stats,
    })
}
