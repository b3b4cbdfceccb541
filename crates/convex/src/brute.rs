//! The brute-force twin: every vertex–edge pair, exact comparisons, and the exact contact test.

use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::Kernel;

use crate::meet::{classify, separation};
use crate::pair::{Pair, canonical, finish, nearer};
use crate::result::Separation;

/// The closest pair of two convex polygons by brute force, for testing and as a baseline.
///
/// Every vertex of one polygon against every edge of the other (against the vertex when the other is a
/// point), the minimum chosen by exact squared-distance comparisons (`K::cmp_dist2`); the contact
/// status by the exact separating-axis test over every edge normal (see [`Separation`] for the
/// definitions). Under the Robust and Exact kernels the answer is exact: the features realize the
/// distance, the outcome is the right one.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_brute, polygon::ConvexPolygon, polygon::Feature, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 1.0)])?;
/// let c = *distance_brute::<Robust>(&p, &q).closest().expect("disjoint");
/// assert_eq!(c.distance, 2.0);
/// assert_eq!((c.feature_p, c.feature_q), (Feature::Vertex(1), Feature::Vertex(0)));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// The feature-pair characterization: Yang, Qi, Meng, Li, Wang, "A new fast algorithm for computing the
/// distance between two disjoint convex polygons based on Voronoi diagram", J. Zhejiang Univ. SCIENCE A
/// 7(9), 2006 (Definition 1, Theorem 1).
#[must_use]
pub fn distance_brute<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Separation {
    separation(classify::<K>(p, q, false), || {
        finish::<K>(p, q, brute_pair::<K>(p, q))
    })
}

/// The nearest canonical vertex–vertex / vertex–edge pair over all pairs (meaningful when disjoint).
pub(crate) fn brute_pair<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Pair {
    let (p, q) = (pp.vertices(), qq.vertices());
    let edges = |len: usize| match len {
        1 => 0,
        2 => 1,
        l => l,
    };
    let mut best = Pair::Vv(0, 0);
    for i in 0..p.len() {
        if q.len() == 1 {
            best = nearer::<K>(p, q, best, Pair::Vv(i, 0));
        }
        for j in 0..edges(q.len()) {
            best = nearer::<K>(p, q, best, Pair::Ve(i, j));
        }
    }
    for j in 0..q.len() {
        for i in 0..edges(p.len()) {
            best = nearer::<K>(p, q, best, Pair::Ev(i, j));
        }
    }
    canonical::<K>(p, q, best)
}
