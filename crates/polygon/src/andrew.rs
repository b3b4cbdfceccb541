//! Andrew's monotone chain: the convex hull of any finite point set, `O(n log n)`.
//!
//! Andrew (1979), "Another efficient algorithm for convex hulls in two dimensions", Information
//! Processing Letters 9(5), 216–219. Sort the points lexicographically, then build the lower and the
//! upper chain with a stack, popping while the last turn is not strictly left; the lexicographic order
//! (rather than by `x` alone) makes vertical ties need no special case.

use core::cmp::Ordering;

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
    Ok(from_sorted::<K>(points, order))
}

/// The convex hull of two convex polygons, `points[..split]` and `points[split..]`, each given
/// counter-clockwise: what [`convex_hull_with`] returns on `points` (the same vertices, the same
/// [`ConvexPolygon::source_index`]), in `O(n)` instead of `O(n log n)`.
///
/// A convex polygon's vertices form two lexicographically ascending runs (counter-clockwise from its
/// lowest vertex to its highest, and clockwise between the same two), so merging the four runs
/// replaces the sort; the scan is Andrew's. The typical use: the hull of `P ∪ Q` from `CH(P)` and
/// `CH(Q)`. Input that is not two convex polygons (runs found out of order) is sorted instead, so the
/// result is the hull of the points whatever they are, at `O(n log n)`.
///
/// # Errors
/// As [`convex_hull_with`]. Never panics (`split` beyond the length is clamped).
///
/// # Complexity
/// `O(n)` time and at most `4n` orientation tests for two convex polygons.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::convex_hull_of_two_with;
/// use polydist_polygon::predicates::Robust;
///
/// // A unit square and a triangle to its right, both counter-clockwise.
/// let pts = [
///     DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y,
///     DVec2::new(3.0, 0.0), DVec2::new(4.0, 1.0), DVec2::new(3.0, 2.0),
/// ];
/// let hull = convex_hull_of_two_with::<Robust>(&pts, 4)?;
/// let names: Vec<usize> = (0..hull.len()).map(|i| hull.source_index(i)).collect();
/// assert_eq!(names, [0, 4, 5, 6, 3]);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn convex_hull_of_two_with<K: Kernel>(
    points: &[DVec2],
    split: usize,
) -> Result<ConvexPolygon, PolygonError> {
    ring::validate(points)?;
    let split = split.min(points.len());
    let lex = |i: usize, j: usize| lex_cmp(points[i], points[j]).then(i.cmp(&j));
    // Two ascending runs merged into one.
    let merge = |x: &[usize], y: &[usize]| {
        let mut out = Vec::with_capacity(x.len() + y.len());
        let (mut i, mut j) = (0, 0);
        while i < x.len() && j < y.len() {
            if lex(x[i], y[j]) == Ordering::Greater {
                out.push(y[j]);
                j += 1;
            } else {
                out.push(x[i]);
                i += 1;
            }
        }
        out.extend_from_slice(&x[i..]);
        out.extend_from_slice(&y[j..]);
        out
    };
    let mut order: Vec<usize> = Vec::new();
    for (s, e) in [(0, split), (split, points.len())] {
        if s == e {
            continue;
        }
        let n = e - s;
        let extreme = |want: Ordering| (s..e).fold(s, |x, i| if lex(i, x) == want { i } else { x });
        let (lo, hi) = (extreme(Ordering::Less) - s, extreme(Ordering::Greater) - s);
        // Counter-clockwise from the lowest vertex to the highest, and clockwise: both ascending.
        let ccw: Vec<usize> = (0..=(hi + n - lo) % n).map(|k| s + (lo + k) % n).collect();
        let cw: Vec<usize> = (0..=(lo + n - hi) % n)
            .map(|k| s + (lo + n - k) % n)
            .collect();
        order = merge(&order, &merge(&ccw, &cw));
    }
    if order
        .windows(2)
        .any(|w| lex(w[0], w[1]) == Ordering::Greater)
    {
        order.sort_by(|&i, &j| lex(i, j));
    }
    Ok(from_sorted::<K>(points, order))
}

/// Andrew's scan over indices sorted lexicographically (ties by index, each index at most twice):
/// equal points merged to the first, then the lower and the upper chain.
fn from_sorted<K: Kernel>(points: &[DVec2], mut order: Vec<usize>) -> ConvexPolygon {
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
    ConvexPolygon::from_hull(vertices, SourceMap::point_set(points.len(), source))
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
