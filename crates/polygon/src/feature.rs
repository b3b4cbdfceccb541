//! Small value types shared by the polygon types: [`Feature`], [`Segment`], [`Location`].

use glam::DVec2;

/// A vertex or an edge of a polygon, named by index.
///
/// Edge `i` joins vertex `i` and vertex `(i + 1) mod n`. Whether the index is the polygon's own
/// (internal) index or the caller's is said by the function returning it; the polygon types map
/// internal features to the caller's with [`ConvexPolygon::source_index`](crate::ConvexPolygon::source_index)
/// and [`ConvexPolygon::caller_feature_on_edge`](crate::ConvexPolygon::caller_feature_on_edge).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Feature {
    /// Vertex `i`.
    Vertex(usize),
    /// Edge `i`, from vertex `i` to vertex `(i + 1) mod n`.
    Edge(usize),
}

/// A closed line segment from `a` to `b` (`a == b` is allowed and is a point).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Segment {
    /// The start point.
    pub a: DVec2,
    /// The end point.
    pub b: DVec2,
}

impl Segment {
    /// The segment from `a` to `b`.
    #[must_use]
    pub const fn new(a: DVec2, b: DVec2) -> Self {
        Segment { a, b }
    }
}

/// Where a point lies relative to a closed polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Location {
    /// In the interior (for a point or segment polygon, which has no interior: never).
    Inside,
    /// On the boundary: on an edge or at a vertex.
    Boundary,
    /// Outside the closed polygon.
    Outside,
}
