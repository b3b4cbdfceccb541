//! The boundary crossings of two convex polygons, symbolic: the linear-time intersection structure
//! behind ARL's piece decomposition of `(P ∪ Q) − int(P ∩ Q)` (§4).
//!
//! The walk of `∂P` through `Q`'s subdivision (module `walk`) enters `Q` through an edge and leaves it
//! through the exit edge of the current segment's line; each entry and exit is a crossing, recorded as
//! the pair (edge of `P`, feature of `Q`) and never constructed. Between a crossing where `∂P` leaves
//! `Q` and the next one where it enters lies an external chain of `P` (ARL's `P₁-chain_k`); the
//! stretch of `∂Q` between the same two crossings is the internal chain of the same piece. Theorem 1
//! (the nearest point of a vertex of the external chain `k` lies on `∂Q` between the crossings `k − 1`
//! and `k + 1`) is checked on these chains in `tests/hausdorff_pieces.rs`.

use glam::DVec2;
use polydist_polygon::{ConvexPolygon, Feature};
use polydist_predicates::{Kernel, Orientation, Robust};

use super::walk::{Crossing, Near, walk};

/// A crossing of `∂P` with `∂Q`, kept symbolic.
///
/// Edges are those of the validated polygons (see [`ConvexPolygon::try_new`]), each named by the
/// caller's index of its first vertex (a validated edge may stand for several collinear caller edges).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BoundaryCrossing {
    /// The edge of `P`, from the vertex with this caller index to the next vertex of `P`.
    pub p_edge: usize,
    /// The feature of `Q` the crossing lies on: an edge (the crossing strictly inside it, or at one of
    /// its ends when the walk met the end first) or a vertex.
    pub q_feature: Feature,
    /// `true` when `∂P` enters `Q` here (counter-clockwise along `∂P`), `false` when it leaves.
    pub entering: bool,
}

fn public(p: &ConvexPolygon, q: &ConvexPolygon, c: Crossing) -> BoundaryCrossing {
    let q_feature = match c.q {
        Near::Vertex(i) | Near::OnVertex(i) => Feature::Vertex(q.source_index(i)),
        Near::Edge(i) | Near::OnEdge(i) => Feature::Edge(q.source_index(i)),
        // Never recorded (a crossing is on the boundary); named by vertex 0 to stay total.
        Near::Inside => Feature::Vertex(q.source_index(0)),
    };
    BoundaryCrossing {
        p_edge: p.source_index(c.p_edge),
        q_feature,
        entering: c.entering,
    }
}

/// Where the closed boundary of `P` crosses into and out of the filled convex polygon `Q`, in
/// counter-clockwise order along `∂P` from vertex 0, under the kernel `K`: the symbolic intersection
/// structure of ARL §4 (entries and exits alternate; none when the boundaries do not cross, e.g. for
/// disjoint or nested polygons, or when they only touch).
///
/// Empty when `Q` has fewer than 3 vertices (no interior to enter).
///
/// # Complexity
/// `O(n + m)` exact predicates (the walk of [`per_vertex_distances_with`](crate::per_vertex_distances_with)
/// around the closed boundary).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::polygon::{ConvexPolygon, Feature, predicates::Robust};
/// use polydist_convex::{BoundaryCrossing, boundary_crossings_with};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, 1.0), DVec2::new(6.0, 1.0), DVec2::new(6.0, 3.0), DVec2::new(2.0, 3.0)])?;
/// let x = boundary_crossings_with::<Robust>(&p, &q);
/// assert_eq!(x, vec![
///     BoundaryCrossing { p_edge: 1, q_feature: Feature::Edge(0), entering: true },
///     BoundaryCrossing { p_edge: 1, q_feature: Feature::Edge(2), entering: false },
/// ]);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, Ribeiro, Lifschitz, RAIRO Oper. Res. 25(4) (1991), §4 (piece decomposition, Theorem 1).
#[must_use]
pub fn boundary_crossings_with<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> Vec<BoundaryCrossing> {
    let mut raw = Vec::new();
    let _ = walk::<K>(p.vertices(), q.vertices(), &mut raw, true);
    raw.into_iter().map(|c| public(p, q, c)).collect()
}

/// [`boundary_crossings_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{boundary_crossings, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::Y])?;
/// assert!(boundary_crossings(&p, &ConvexPolygon::try_new(&[DVec2::new(5.0, 5.0)])?).is_empty());
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`boundary_crossings_with`].
#[must_use]
pub fn boundary_crossings(p: &ConvexPolygon, q: &ConvexPolygon) -> Vec<BoundaryCrossing> {
    boundary_crossings_with::<Robust>(p, q)
}

/// The brute-force twin of [`boundary_crossings_with`] for boundaries in general position, for testing:
/// every pair of edges tested for a proper crossing (four strict orientations), ordered along `∂P`
/// (on one edge of `P` the entry comes before the exit). Touching contacts (a vertex on the other
/// boundary, collinear overlaps) are not proper crossings and are not reported.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{boundary_crossings_brute, boundary_crossings_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, -1.0), DVec2::new(5.0, 2.0), DVec2::new(2.0, 5.0), DVec2::new(-1.0, 2.0)])?;
/// assert_eq!(boundary_crossings_brute::<Robust>(&p, &q).len(), 8);
/// assert_eq!(boundary_crossings_brute::<Robust>(&p, &q), boundary_crossings_with::<Robust>(&p, &q));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`boundary_crossings_with`].
#[must_use]
pub fn boundary_crossings_brute<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> Vec<BoundaryCrossing> {
    let (pv, qv) = (p.vertices(), q.vertices());
    let (n, m) = (pv.len(), qv.len());
    let mut out = Vec::new();
    if m < 3 || n < 2 {
        return out;
    }
    let opposite = |a: Orientation, b: Orientation| {
        matches!(
            (a, b),
            (Orientation::Clockwise, Orientation::CounterClockwise)
                | (Orientation::CounterClockwise, Orientation::Clockwise)
        )
    };
    let edges = if n == 2 { 2 } else { n };
    for i in 0..edges {
        let (a, b): (DVec2, DVec2) = (pv[i], pv[(i + 1) % n]);
        let mut enter = None;
        let mut leave = None;
        for j in 0..m {
            let (c, d) = (qv[j], qv[(j + 1) % m]);
            let (oc, od) = (K::orient(a, b, c), K::orient(a, b, d));
            let (oa, ob) = (K::orient(c, d, a), K::orient(c, d, b));
            if opposite(oc, od) && opposite(oa, ob) {
                if ob == Orientation::CounterClockwise {
                    enter = Some(j);
                } else {
                    leave = Some(j);
                }
            }
        }
        for (j, entering) in [(enter, true), (leave, false)] {
            if let Some(j) = j {
                out.push(BoundaryCrossing {
                    p_edge: p.source_index(i),
                    q_feature: Feature::Edge(q.source_index(j)),
                    entering,
                });
            }
        }
    }
    out
}
