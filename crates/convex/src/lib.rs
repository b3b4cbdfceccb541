//! Convex–convex polygon distance in `O(log m + log n)` with exact decisions.
//!
//! Layer 2 of polydist. Given two convex polygons (points and segments included) this crate decides
//! exactly whether they are disjoint, touching or overlapping, and for disjoint ones finds a closest
//! feature pair and computes the distance and the realizing points:
//!
//! - [`distance`] / [`distance_with`]: the answer ([`Separation`], with a [`Closest`] pair), by a scan
//!   for tiny inputs, a support guess in `f64` certified by Theorem 1 for small ones (`n + m < 512`;
//!   the same answer as the search), and otherwise by [`distance_yang_with`]: Yang, Qi, Meng, Li, Wang (2006)'s binary
//!   search on outer Voronoi regions, rebuilt for exact predicates (Table 1 in its weak reading, a
//!   one-sided step once a range is a single feature, a loop bound that holds whatever the predicates
//!   say) on a proved initial bracket (the chains whose normals lie in a quarter-turn around the optimal
//!   direction, found by one exact side test), so `O(log n + log m)` on every input; the answer is
//!   certified by Theorem 1 (Lin–Canny) in `O(1)` exact tests, a safety net that never fails under the
//!   exact kernels on disjoint input.
//! - [`distance_schwartz_with`]: Schwartz (1981)'s `O(log² N)` search on the implicit Minkowski
//!   difference, a second algorithm with the same result type (and the Yang path's last resort under
//!   an inexact kernel).
//! - [`contact_with`] / [`intersects`]: the intersection test in `O(log n + log m)` (disjoint, touching
//!   with an exact contact point, overlapping), by prune-and-search on the Minkowski chains.
//! - [`distance_to_point`]: a point against a polygon in `O(log n)`.
//! - [`distance_within`] (exact threshold decisions, with an early exit), [`distance_with_hint`]
//!   (temporal coherence), [`distance_posed`] (rigid poses), [`distance_exact`] (the squared distance as
//!   an exact rational).
//! - [`distance_brute`]: the `O(nm)` brute-force twin, for testing and as a baseline.
//! - [`min_vertex_distance`] / [`min_vertex_distance_with`]: the nearest pair of *vertices*, McKenna and
//!   Toussaint (1985), `O(m + n)` for disjoint polygons (`O((m + n) log(m + n))` otherwise), with its
//!   brute-force twin [`min_vertex_distance_brute`].
//! - [`hausdorff`](fn@hausdorff), [`directed_hausdorff`], [`cmmr`], [`per_vertex_distances`] (and their `_with`
//!   and `_brute` forms, [`hausdorff_squared_exact`]): Hausdorff and CMMR distances of filled convex
//!   polygons in `O(n + m)` (Atallah 1983; Atallah, Ribeiro, Lifschitz 1991), disjoint or not, and
//!   [`boundary_crossings`]: where `∂P` enters and leaves `Q`, kept symbolic (the intersection structure
//!   behind their piece decomposition).
//!
//! # Numbers
//! Exact predicates, inexact constructions. Every decision is the sign of a polynomial in the input
//! coordinates, decided by the [`Kernel`](polygon::predicates::Kernel) (Robust by default). The numbers
//! are computed from the chosen features with every intermediate exact and rounded once: the distance
//! is within 2.5 ulps, the squared distance within 3 ulps, a foot of a perpendicular within 1 ulp per
//! coordinate, a vertex exactly (derivation in the `construct` module; measured in the tests).
//!
//! # The layer below
//! The polygon crate is re-exported as the module [`polygon`] (and the predicates as
//! [`polygon::predicates`]): `polydist_convex::polygon::ConvexPolygon` is `polydist_polygon::ConvexPolygon`.
//!
//! # Examples
//! ```
//! use glam::DVec2;
//! use polydist_convex::polygon::{ConvexPolygon, Feature};
//! use polydist_convex::{Separation, distance};
//!
//! let p = ConvexPolygon::try_new(&[DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(1.0, 2.0)])?;
//! let q = ConvexPolygon::try_new(&[DVec2::new(4.0, 0.0), DVec2::new(6.0, 0.0), DVec2::new(5.0, 2.0)])?;
//! let Separation::Disjoint(c) = distance(&p, &q) else { panic!("disjoint") };
//! assert_eq!(c.distance, 2.0);
//! assert_eq!((c.feature_p, c.feature_q), (Feature::Vertex(1), Feature::Vertex(0)));
//! # Ok::<(), polydist_convex::polygon::PolygonError>(())
//! ```

pub use polydist_polygon as polygon;

mod bracket;
mod brute;
mod construct;
mod contact;
mod exact;
mod extreme;
mod hausdorff;
mod hint;
mod linear;
mod meet;
mod pair;
mod pose;
mod result;
mod schwartz;
mod vertex_distance;
mod within;
mod yang;

pub use brute::distance_brute;
pub use contact::{contact, contact_with, intersects};
pub use exact::distance_exact;
pub use hausdorff::{
    BoundaryCrossing, Cmmr, Direction, Hausdorff, VertexToPolygon, boundary_crossings,
    boundary_crossings_brute, boundary_crossings_with, cmmr, cmmr_brute, cmmr_value,
    cmmr_value_with, cmmr_with, directed_hausdorff, directed_hausdorff_brute,
    directed_hausdorff_with, hausdorff, hausdorff_brute, hausdorff_squared_exact, hausdorff_with,
    per_vertex_distances, per_vertex_distances_brute, per_vertex_distances_with,
    reset_walk_fallbacks, walk_fallbacks,
};
pub use hausdorff::{
    PiecesStats, cmmr_pieces_with, hausdorff_pieces_with, per_vertex_distances_pieces_with,
    pieces_stats, reset_pieces_stats,
};
pub use hint::{Hint, distance_with_hint};
pub use meet::Contact;
pub use pose::{Pose, distance_posed};
pub use result::{Closest, SearchStats, Separation, reset_search_stats, search_stats};
pub use schwartz::{distance_schwartz, distance_schwartz_with};
pub use vertex_distance::{
    VertexDistance, VertexDistanceCounts, min_vertex_distance, min_vertex_distance_brute,
    min_vertex_distance_with, reset_vertex_distance_case_counts, vertex_distance_case_counts,
};
pub use within::{Within, distance_within};
pub use yang::{SCAN_BELOW, distance, distance_to_point, distance_with, distance_yang_with};
