//! Validated polygon types for polydist: convex and simple polygons, Melkman's hull, exact point location.
//!
//! This is layer 1 of polydist. It turns a caller's vertex list into a polygon the distance algorithms
//! can trust, once, at the edge:
//!
//! - [`ConvexPolygon::try_new`]: a point, a segment or a strictly convex polygon, `O(n)`; rejects
//!   reflex vertices, spikes and star polygons (a pentagram turns one way at every vertex).
//! - [`SimplePolygon::try_new`]: a polygon whose edges meet only at shared vertices, checked by the
//!   Shamos–Hoey sweep, `O(n log n)`.
//! - [`SimplePolygon::convex_hull`] (Melkman, `O(n)`) and [`convex_hull`] of any point set (Andrew's
//!   monotone chain, `O(n log n)`); [`convex_hull_of_two_with`], the hull of two convex polygons by
//!   the same scan over their merged lexicographic runs, `O(n)`.
//! - [`ConvexPolygon::locate`] in `O(log n)` and [`SimplePolygon::locate`] in `O(n)`: inside, on the
//!   boundary, or outside, decided exactly.
//!
//! Both constructors accept either orientation (the result is counter-clockwise), closed or open rings,
//! exact repeats and collinear vertices, and keep a map to the caller's indices
//! ([`ConvexPolygon::source_index`], [`ConvexPolygon::caller_feature_on_edge`]) so that later results
//! name the caller's own vertices and edges. Invalid input is a [`PolygonError`] saying what and where;
//! nothing panics on any input.
//!
//! # Numbers
//! Every geometric decision is an exact predicate of [`predicates`] (the [`predicates::Robust`] kernel
//! for validation; the hulls and point location take any [`predicates::Kernel`], Robust by default).
//! No epsilon anywhere. Coordinates must be finite with magnitude at most
//! [`predicates::MAX_COORDINATE`] `= 2^500`, so that later distance computations cannot overflow; the
//! predicates themselves are exact for every finite input.
//!
//! # The layer below
//! The predicates crate is re-exported as the module [`predicates`]: `polydist_polygon::predicates::Robust`
//! is the same item as `polydist_predicates::Robust`.
//!
//! # Examples
//! ```
//! use glam::DVec2;
//! use polydist_polygon::predicates::Robust;
//! use polydist_polygon::{ConvexPolygon, Feature, Location, PolygonError, SimplePolygon};
//!
//! // A clockwise, closed ring with a repeated vertex.
//! let ring = [[0.0, 0.0], [0.0, 3.0], [0.0, 3.0], [3.0, 3.0], [3.0, 0.0], [0.0, 0.0]];
//! let square = ConvexPolygon::try_from(&ring[..])?;
//! assert_eq!(square.len(), 4);
//! assert_eq!(square.locate(DVec2::new(1.0, 1.0)), Location::Inside);
//!
//! // Internal vertex 1 is the caller's vertex 4 (the ring was reversed to counter-clockwise) ...
//! assert_eq!(square.source_index(1), 4);
//! // ... and the nearest point of internal edge 2 to (1, 9) is inside the caller's edge 2.
//! assert_eq!(square.caller_feature_on_edge::<Robust>(2, DVec2::new(1.0, 9.0)), Some(Feature::Edge(2)));
//!
//! // Validation says what is wrong and where.
//! let bow_tie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
//! assert_eq!(ConvexPolygon::try_from(&bow_tie[..]), Err(PolygonError::NotConvex { index: 1 }));
//! assert_eq!(
//!     SimplePolygon::try_from(&bow_tie[..]),
//!     Err(PolygonError::SelfIntersection { edge_a: 0, edge_b: 2 })
//! );
//! # Ok::<(), PolygonError>(())
//! ```
//!
//! # Features
//! - `serde`: `Serialize`/`Deserialize` for the public types; polygons serialize as their vertex list
//!   `[[x, y], …]` and deserialization validates (through `TryFrom<Vec<[f64; 2]>>`).
//! - `geo-types`: `TryFrom<&geo_types::Polygon<f64>>` and `TryFrom<&geo_types::LineString<f64>>`; the
//!   closing duplicate is dropped, and a polygon with holes is [`PolygonError::HasHoles`].

pub use polydist_predicates as predicates;

mod andrew;
mod brute;
mod conversions;
mod convex;
mod error;
mod feature;
mod melkman;
pub mod order;
mod ring;
mod simple;
mod source_map;
mod sweep;
pub mod treap;

pub use andrew::{convex_hull, convex_hull_of_two_with, convex_hull_with};
pub use convex::ConvexPolygon;
pub use error::PolygonError;
pub use feature::{Feature, Location, Segment};
pub use simple::SimplePolygon;
