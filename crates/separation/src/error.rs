//! Why an input was rejected: [`SeparationError`].

/// Which of the two input chains an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Chain {
    /// The first chain, `P`.
    P,
    /// The second chain, `Q`.
    Q,
}

impl core::fmt::Display for Chain {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Chain::P => "P",
            Chain::Q => "Q",
        })
    }
}

/// Why two chains and a line were rejected, or why no answer could be given.
///
/// Every index is the **caller's** index into the slice it passed. The checks run in the order of the
/// variants below; the first failing one is reported.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, thiserror::Error)]
pub enum SeparationError {
    /// A chain has no vertices.
    #[error("chain {chain} has no vertices")]
    EmptyChain {
        /// The empty chain.
        chain: Chain,
    },
    /// A coordinate is NaN, infinite, or beyond
    /// [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE) in magnitude.
    #[error("vertex {index} of chain {chain} has a non-finite or out-of-range coordinate")]
    InvalidCoordinate {
        /// The chain holding the vertex.
        chain: Chain,
        /// The caller's index of the first offending vertex.
        index: usize,
    },
    /// A point of the separating line is NaN, infinite or out of range.
    #[error("the separating line has a non-finite or out-of-range point")]
    InvalidLine,
    /// The two points given for the separating line coincide.
    #[error("the two points of the separating line coincide")]
    DegenerateLine,
    /// Vertex `index` of `chain` lies strictly on the other chain's side of the line (decided
    /// exactly): the line does not separate the chains.
    #[error("vertex {index} of chain {chain} is strictly on the wrong side of the line")]
    NotSeparated {
        /// The chain holding the vertex.
        chain: Chain,
        /// The caller's index of the first vertex found on the wrong side.
        index: usize,
    },
    /// [`closest_visible_vertices`](crate::closest_visible_vertices) (and its brute force): both
    /// chains have a vertex on the separating line, whose perpendicular-visibility wedges are then
    /// ambiguous; pass a line that at most one of the chains touches. The matrix constructors
    /// (`CvvMatrix::new`, `CveMatrix::new`): every vertex of both chains lies on the line, so no
    /// side is defined. [`separation_of_chains`](crate::separation_of_chains) accepts both.
    #[error("both chains touch the separating line; at most one may")]
    BothChainsTouchLine,
    /// [`closest_visible_vertices`](crate::closest_visible_vertices) only: the chain is not monotone
    /// with respect to the separating line (its vertices' heights along the line neither never
    /// decrease nor never increase), or it doubles back on itself within a run of vertices at equal
    /// height. The closest *visible* vertices of general chains are not those of their envelopes;
    /// [`separation_of_chains`](crate::separation_of_chains) accepts general simple chains.
    #[error("chain {chain} is not monotone along the separating line at vertex {index}")]
    NotMonotone {
        /// The chain.
        chain: Chain,
        /// The caller's index of the first vertex where monotonicity fails.
        index: usize,
    },
    /// The chain was found not to be simple while computing its perpendicular-visibility envelope:
    /// a vertex lies on another edge, two edges overlap, two vertices coincide, or a closed chain has
    /// fewer than three distinct vertices. Not every non-simple chain is detected (simplicity is the
    /// caller's duty); under the `Fast` kernel, inconsistent decisions can also produce this error.
    #[error("chain {chain} is not simple (found at vertex {index})")]
    NotSimple {
        /// The chain.
        chain: Chain,
        /// The caller's index of a vertex where the violation was found.
        index: usize,
    },
    /// [`separation_of_disjoint`](crate::separation_of_disjoint) was given polygons that are not
    /// disjoint: one hull contains the other and no pocket of the outer polygon holds the inner
    /// one, so it lies inside the outer polygon. ([`separation`](crate::separation) checks first and
    /// reports meeting polygons as `Intersecting`.)
    #[error(
        "one polygon lies inside the other (no pocket of the outer one holds it): the polygons are not disjoint"
    )]
    HullsIntersect,
    /// [`polyline_to_polygon`](crate::polyline_to_polygon): the convex hulls of the polyline and of
    /// the polygon meet. Amato's separator is built from the region between two polygon boundaries,
    /// which an open polyline does not bound, so only polylines whose hull is disjoint from the
    /// polygon's are taken; [`separation_brute`](crate::separation_brute) answers the others in
    /// `O(nm)`.
    #[error(
        "the polyline's convex hull meets the polygon's: only polylines with disjoint hulls are supported"
    )]
    PolylineHullsMeet,
    /// The search found no admissible vertex pair. With an exact kernel this cannot happen (it would
    /// be a bug); with the `Fast` kernel inconsistent decisions can cause it.
    #[error(
        "inconsistent decisions: no candidate pair survived (only possible with the Fast kernel)"
    )]
    Inconsistent,
}
