//! Why a vertex list is not a valid polygon: [`PolygonError`].

/// Why a vertex list was rejected by a polygon constructor.
///
/// Every index is the **caller's** index: a position in the slice given to the constructor (for a
/// `geo_types` polygon, a position in its exterior ring), never an index into the cleaned polygon.
/// Edge `j` joins the caller's vertex `j` and vertex `(j + 1) mod n`.
///
/// The checks run in a fixed order, so a list with several defects reports the first in this order:
/// [`Empty`](Self::Empty) and [`HasHoles`](Self::HasHoles), then coordinates
/// ([`NonFinite`](Self::NonFinite), [`OutOfRange`](Self::OutOfRange)), then the vertex count after
/// repeated vertices are merged ([`TooFewVertices`](Self::TooFewVertices)), then collinearity
/// ([`Degenerate`](Self::Degenerate), [`Spike`](Self::Spike)), then the shape
/// ([`NotConvex`](Self::NotConvex), [`WindsMoreThanOnce`](Self::WindsMoreThanOnce),
/// [`SelfIntersection`](Self::SelfIntersection)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
pub enum PolygonError {
    /// The vertex list is empty.
    #[error("the polygon has no vertices")]
    Empty,
    /// A coordinate of vertex `index` is NaN or infinite.
    #[error("vertex {index} has a non-finite coordinate (NaN or infinity)")]
    NonFinite {
        /// The caller's index of the offending vertex (the first one).
        index: usize,
    },
    /// A coordinate of vertex `index` exceeds
    /// [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE) `= 2^500` in magnitude.
    #[error(
        "vertex {index} has a coordinate beyond ±2^500, the range in which distances cannot overflow"
    )]
    OutOfRange {
        /// The caller's index of the offending vertex (the first one).
        index: usize,
    },
    /// The boundary turns back on itself by 180° at vertex `index`: the vertex is collinear with its
    /// two neighbours and both neighbours lie on the same side of it.
    #[error("vertex {index} is a spike: the boundary turns back on itself by 180° there")]
    Spike {
        /// The caller's index of the vertex where the boundary reverses.
        index: usize,
    },
    /// The turns are not all of one sign; vertex `index` is reflex (it turns against the polygon's
    /// orientation, which is the turn at the lexicographically lowest vertex).
    #[error("vertex {index} is reflex, so the polygon is not convex")]
    NotConvex {
        /// The caller's index of the first reflex vertex.
        index: usize,
    },
    /// Every turn has the same sign, but the boundary winds `turns` times around (a star polygon such
    /// as the pentagram winds twice); a convex polygon winds exactly once.
    #[error(
        "the boundary winds {turns} times around (a star polygon); a convex polygon winds once"
    )]
    WindsMoreThanOnce {
        /// How many full turns the edge direction makes along the boundary (at least 2).
        turns: usize,
    },
    /// Edges `edge_a < edge_b` meet, and they are not two neighbours meeting only at their shared vertex.
    /// It is the first such pair the sweep found, not necessarily the lowest-numbered one.
    #[error("edges {edge_a} and {edge_b} intersect, so the polygon is not simple")]
    SelfIntersection {
        /// The caller's index of one of the two edges (the smaller).
        edge_a: usize,
        /// The caller's index of the other edge (the larger).
        edge_b: usize,
    },
    /// Fewer distinct vertices (after merging exact repeats) than the polygon type needs.
    #[error("the polygon has {found} distinct vertices; at least {needed} are needed")]
    TooFewVertices {
        /// The number of distinct consecutive vertices found.
        found: usize,
        /// The number needed.
        needed: usize,
    },
    /// All vertices are collinear, but the polygon type needs a nonzero area.
    #[error("all vertices are collinear, so the polygon has no area")]
    Degenerate,
    /// The input polygon has interior rings (holes), which these polygon types cannot represent.
    #[error("the polygon has {holes} hole(s); only polygons without holes are supported")]
    HasHoles {
        /// The number of interior rings.
        holes: usize,
    },
}
