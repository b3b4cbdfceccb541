//! Melkman's on-line convex hull of a simple polygon, `O(n)`.
//!
//! Melkman (1987), "On-line construction of the convex hull of a simple polyline", Information
//! Processing Letters 25, 11–12. The hull is kept in a deque whose two ends are both the vertex added
//! last, `v_k`. A new vertex that is not strictly outside either hull edge at `v_k` lies in the current
//! hull (the polyline cannot reach any other hull edge without crossing itself), so it is skipped;
//! otherwise vertices are popped from each end while they stop being strictly convex, and the new
//! vertex is pushed on both ends.
//!
//! # What we changed
//! The paper assumes no three vertices collinear. We skip a vertex when it is *on or inside* both edges
//! at `v_k` (not strictly outside), and pop while the turn is *not strictly* left: a point on the
//! current hull's boundary is a convex combination of hull vertices and can never become a strict hull
//! vertex, and popping collinear vertices keeps the hull strictly convex. Both loops keep at least two
//! deque entries, so an inconsistent kernel (Fast) cannot empty the deque or index out of range.

use std::collections::VecDeque;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation};

use crate::ring::lowest;

/// The hull vertices of the counter-clockwise simple polygon `v` (at least 3 vertices, no three
/// consecutive collinear), as indices into `v`: counter-clockwise, strictly convex, starting at the
/// lexicographically lowest and increasing cyclically.
pub(crate) fn hull<K: Kernel>(v: &[DVec2]) -> Vec<usize> {
    let ccw =
        |a: usize, b: usize, c: DVec2| K::orient(v[a], v[b], c) == Orientation::CounterClockwise;
    let cw = |a: usize, b: usize, c: DVec2| K::orient(v[a], v[b], c) == Orientation::Clockwise;
    // Bottom → top is counter-clockwise, with the last added vertex at both ends.
    let mut d: VecDeque<usize> = if ccw(0, 1, v[2]) {
        [2, 0, 1, 2].into()
    } else {
        [2, 1, 0, 2].into()
    };
    for (i, &p) in v.iter().enumerate().skip(3) {
        let t = d.len() - 1;
        // Inside or on the hull: not strictly right of the top edge nor of the bottom edge.
        if !cw(d[t - 1], d[t], p) && !cw(d[0], d[1], p) {
            continue;
        }
        while d.len() > 2 && !ccw(d[d.len() - 2], d[d.len() - 1], p) {
            d.pop_back();
        }
        d.push_back(i);
        // The bottom edge d[0] → d[1] must turn strictly left from p → d[0].
        while d.len() > 2 && K::orient(p, v[d[0]], v[d[1]]) != Orientation::CounterClockwise {
            d.pop_front();
        }
        d.push_front(i);
    }
    d.pop_back();
    let mut hull: Vec<usize> = d.into();
    let points: Vec<DVec2> = hull.iter().map(|&i| v[i]).collect();
    hull.rotate_left(lowest(&points));
    hull
}
