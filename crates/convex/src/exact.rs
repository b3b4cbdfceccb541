//! The exact squared distance as a rational, from the exactly chosen features.

use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::exact::{
    squared_distance_point_point, squared_distance_point_segment,
};
use polydist_polygon::predicates::{BigRational, Exact};

use crate::hint::{Solved, solve};
use crate::pair::{Pair, at};
use crate::result::Separation;

/// The answer of [`distance_with::<Exact>`](crate::distance_with) together with the **exact** squared
/// distance as a rational number (`0` when the polygons touch or overlap).
///
/// Every decision is exact (the [`Exact`] kernel: no floating-point filter), and the squared distance is
/// computed from the realizing pair with rational arithmetic: `|p − q|²` for a vertex pair, and
/// `((b − a) × (x − a))² / |b − a|²` for a vertex `x` against an edge `ab` whose foot is inside it. The
/// `f64` fields of the returned [`Separation`] are the usual correctly rounded constructions; the
/// rational is what they approximate.
///
/// # Complexity
/// That of [`distance_with`](crate::distance_with) (`O(log n + log m)` exact predicates for disjoint
/// polygons), with every predicate evaluated in exact arithmetic, plus `O(1)` rational operations on
/// numbers of at most a few thousand bits. Allocates (big integers).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_exact, polygon::ConvexPolygon, polygon::predicates::BigRational};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(1.0, 1.0), DVec2::new(2.0, 1.0), DVec2::new(1.0, 2.0)])?;
/// let (answer, sq) = distance_exact(&p, &q);
/// // The foot of (1, 1) on the hypotenuse is (1/2, 1/2): squared distance exactly 1/2.
/// assert_eq!(sq, BigRational::new(1.into(), 2.into()));
/// assert_eq!(answer.closest().map(|c| c.squared_distance), Some(0.5));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
#[must_use]
pub fn distance_exact(p: &ConvexPolygon, q: &ConvexPolygon) -> (Separation, BigRational) {
    let solved = solve::<Exact>(p, q);
    let sq = match &solved {
        Solved::Meeting(_) => BigRational::default(),
        Solved::Disjoint(_, pair) => {
            let (pv, qv) = (p.vertices(), q.vertices());
            let exact = match *pair {
                Pair::Vv(i, j) => squared_distance_point_point(at(pv, i), at(qv, j)),
                Pair::Ve(i, j) => {
                    squared_distance_point_segment(at(pv, i), at(qv, j), at(qv, j + 1))
                }
                Pair::Ev(i, j) => {
                    squared_distance_point_segment(at(qv, j), at(pv, i), at(pv, i + 1))
                }
            };
            // Validated polygons have finite coordinates, so the rational always exists.
            exact.unwrap_or_default()
        }
    };
    (solved.separation(), sq)
}
