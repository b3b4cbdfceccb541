//! Andrew's monotone chain: the convex hull of any finite point set, `O(n log n)`.
//!
//! Andrew (1979), "Another efficient algorithm for convex hulls in two dimensions", Information
//! Processing Letters 9(5), 216–219. Sort the points lexicographically, then build the lower and the
//! upper chain with a stack, popping while the last turn is not strictly left; the lexicographic order
//! (rather than by `x` alone) makes vertical ties need no special case.

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust};

use crate::ring::{self, lex_cmp};
use crate::source_map::SourceMap;
use crate::{ConvexPolygon, PolygonError};

/// The convex hull of the point set `points`, decided exactly (the [`Robust`] kernel).
///
/// See [`convex_hull_with`].
///
/// # Errors
/// [`PolygonError::Empty`], [`PolygonError::NonFinite`], [`PolygonError::OutOfRange`].
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::convex_hull;
///
/// let soup = [DVec2::new(1.0, 1.0), DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(0.0, 2.0)];
/// let hull = convex_hull(&soup)?;
/// assert_eq!(hull.vertices(), [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)]);
/// assert_eq!(hull.source_index(1), 2);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn convex_hull(points: &[DVec2]) -> Result<ConvexPolygon, PolygonError> {
    convex_hull_with::<Robust>(points)
}

/// The convex hull of the point set `points` (any order, repeats and collinear points allowed), by
/// Andrew's monotone chain with the kernel `K`.
///
/// The result is a point, a segment (all points collinear) or a strictly convex polygon,
/// counter-clockwise from the lexicographically lowest point; points on hull edges are not vertices.
/// [`ConvexPolygon::source_index`] gives each vertex's index in `points` (the first of equal points);
/// every edge is a lid ([`ConvexPolygon::is_lid`]). With [`Fast`](polydist_predicates::Fast) the
/// result may keep or miss near-collinear points, but it terminates and never panics.
///
/// # Errors
/// [`PolygonError::Empty`], [`PolygonError::NonFinite`], [`PolygonError::OutOfRange`] (beyond
/// `±2^500`), with the index of the first offending point. Never panics.
///
/// # Complexity
/// `O(n log n)` time for the sort, then at most `4n` orientation tests; `O(n)` space.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::convex_hull_with;
/// use polydist_polygon::predicates::Exact;
///
/// let collinear = [DVec2::new(1.0, 1.0), DVec2::ZERO, DVec2::new(3.0, 3.0)];
/// let hull = convex_hull_with::<Exact>(&collinear)?;
/// assert_eq!(hull.vertices(), [DVec2::ZERO, DVec2::new(3.0, 3.0)]);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
///
/// # References
/// A. M. Andrew, "Another efficient algorithm for convex hulls in two dimensions", Information
/// Processing Letters 9(5) (1979), 216–219.
pub fn convex_hull_with<K: Kernel>(points: &[DVec2]) -> Result<ConvexPolygon, PolygonError> {
    ring::validate(points)?;
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by(|&i, &j| lex_cmp(points[i], points[j]).then(i.cmp(&j)));
    order.dedup_by(|later, earlier| points[*later] == points[*earlier]);
    let source = if order.len() == 1 {
        order
    } else {
        let mut lower = chain::<K>(points, order.iter().copied());
        let mut upper = chain::<K>(points, order.iter().rev().copied());
        // Each chain ends where the other begins.
        lower.pop();
        upper.pop();
        lower.extend(upper);
        lower
    };
    let vertices = source.iter().map(|&i| points[i]).collect();
    Ok(ConvexPolygon::from_hull(
        vertices,
        SourceMap::point_set(points.len(), source),
    ))
}

/// One monotone chain over the sorted indices: a stack that keeps only strict left turns.
fn chain<K: Kernel>(points: &[DVec2], sorted: impl Iterator<Item = usize>) -> Vec<usize> {
    let mut stack: Vec<usize> = Vec::new();
    for i in sorted {
        while let [.., a, b] = stack[..] {
            if K::orient(points[a], points[b], points[i]) == Orientation::CounterClockwise {
                break;
            }
            stack.pop();
        }
        stack.push(i);
    }
    stack
}
