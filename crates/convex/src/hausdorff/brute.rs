//! The brute-force twin: the nearest feature of a point on filled `Q` by testing every edge.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Dist2, Kernel, Orientation, Sign};

use super::walk::{Near, small};

/// The nearest feature of filled `q` (strictly convex, counter-clockwise) to `v`, in `O(m)`
/// predicates: `v` is in `Q` iff it is left of or on every edge line; otherwise the edge nearest to
/// `v` by exact squared-distance comparisons (`K::cmp_dist2`, first edge on ties), and on that edge
/// the vertex or the open edge holding the foot (two dot signs).
pub(crate) fn locate_brute<K: Kernel>(q: &[DVec2], v: DVec2) -> Near {
    let m = q.len();
    if m <= 2 {
        return small::<K>(q, v);
    }
    let nx = |i: usize| if i + 1 == m { 0 } else { i + 1 };
    let mut on = None;
    let mut outside = false;
    for i in 0..m {
        match K::orient(q[i], q[nx(i)], v) {
            Orientation::Clockwise => {
                outside = true;
                break;
            }
            Orientation::Collinear => on = on.or(Some(i)),
            Orientation::CounterClockwise => {}
        }
    }
    if !outside {
        return match on {
            None => Near::Inside,
            Some(i) if v == q[i] => Near::OnVertex(i),
            Some(i) if v == q[nx(i)] => Near::OnVertex(nx(i)),
            Some(i) => Near::OnEdge(i),
        };
    }
    let mut best = 0;
    for i in 1..m {
        let cand = Dist2::PointSegment(v, q[i], q[nx(i)]);
        let cur = Dist2::PointSegment(v, q[best], q[nx(best)]);
        if K::cmp_dist2(cand, cur) == Ordering::Less {
            best = i;
        }
    }
    let (a, b) = (q[best], q[nx(best)]);
    if K::dot_sign(a, v, a, b) != Sign::Positive {
        Near::Vertex(best)
    } else if K::dot_sign(b, v, a, b) != Sign::Negative {
        Near::Vertex(nx(best))
    } else {
        Near::Edge(best)
    }
}
