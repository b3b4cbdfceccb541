//! polydist: distances between planar polygons with the optimal algorithms from the literature and
//! exact decisions.
//!
//! This is the facade crate: it re-exports every layer as a module and a small flat API. Each module is
//! the same crate a user could depend on alone:
//!
//! | module | crate | what it holds |
//! |---|---|---|
//! | [`predicates`] | `polydist-predicates` | exact predicates behind the `Fast`, `Robust` and `Exact` kernels |
//! | [`polygon`] | `polydist-polygon` | validated `ConvexPolygon` and `SimplePolygon`, Melkman hull, point location |
//! | [`convex`] | `polydist-convex` | convex–convex distance in O(log m + log n) with exact features and closest points |
//! | [`separation`] | `polydist-separation` | separation of simple polygons (Amato 1992: section 3 when their hulls are disjoint, the separator when they meet), point/segment–polygon distances, open polylines against a polygon with a disjoint hull, and section 3 on its own (chains separated by a line, with SMAWK) |
//!
//! `polydist::polygon::ConvexPolygon` is the same item as `polydist_polygon::ConvexPolygon`. The row-minima
//! search polydist uses (SMAWK) is its own crate, `monotone-minima`, with no dependency on anything of ours.
//!
//! # Numbers
//! Every decision is the sign of a polynomial in the input coordinates, decided exactly by the default
//! [`Robust`] kernel (a filtered `f64` evaluation with exact arithmetic behind it); constructions are
//! `f64` with documented error bounds. See `docs/ROBUSTNESS.md`.
//!
//! # Examples
//! ```
//! use polydist::{ConvexPolygon, Location, SimplePolygon};
//! use glam::DVec2;
//!
//! // An L-shaped parcel and its convex hull (Melkman, linear time).
//! let l = SimplePolygon::try_new(&[
//!     DVec2::new(0.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0),
//!     DVec2::new(1.0, 1.0), DVec2::new(1.0, 2.0), DVec2::new(0.0, 2.0),
//! ])?;
//! let hull: ConvexPolygon = l.convex_hull();
//! assert_eq!(hull.len(), 5);
//! // The notch is inside the hull but outside the parcel, decided exactly.
//! let notch = DVec2::new(1.25, 1.25);
//! assert_eq!(hull.locate(notch), Location::Inside);
//! assert_eq!(l.locate(notch), Location::Outside);
//! # Ok::<(), polydist::PolygonError>(())
//! ```

pub use polydist_convex as convex;
pub use polydist_polygon as polygon;
pub use polydist_predicates as predicates;
pub use polydist_separation as separation;

pub use polydist_convex::{
    Cmmr, Hausdorff, VertexDistance, VertexToPolygon, cmmr, directed_hausdorff, hausdorff,
    min_vertex_distance, min_vertex_distance_with, per_vertex_distances,
};
pub use polydist_polygon::{
    ConvexPolygon, Feature, Location, PolygonError, Segment, SimplePolygon,
};
pub use polydist_predicates::{Exact, Fast, Kernel, Orientation, Robust, Sign};

/// The README's example, compiled and run as a doc test so the README stays true.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
