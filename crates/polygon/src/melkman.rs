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
    let ccw = |a: DVec2, b: DVec2, c: DVec2| K::orient(a, b, c) == Orientation::CounterClockwise;
    // The deque holds each vertex's index with its point (the tests read only the points). It
    // grows with the hull, not with `n`: a buffer of `2n + 1` slots started in the middle, as we
    // had it, was zeroed whole (three words a vertex) for a hull that is often a handful of
    // vertices, and its pages faulted in at every call.
    let mut d: VecDeque<(usize, DVec2)> = VecDeque::with_capacity(16);
    let first = if ccw(v[0], v[1], v[2]) {
        [2, 0, 1, 2]
    } else {
        [2, 1, 0, 2]
    };
    d.extend(first.iter().map(|&i| (i, v[i])));
    // The points of the top edge (the last two entries) and of the bottom edge (the first two).
    let top = |d: &VecDeque<(usize, DVec2)>| (d[d.len() - 2].1, d[d.len() - 1].1);
    let bot = |d: &VecDeque<(usize, DVec2)>| (d[0].1, d[1].1);
    for (i, &p) in v.iter().enumerate().skip(3) {
        // Inside or on the hull: not strictly right of the top edge nor of the bottom edge. The two
        // turns tested are the first ones the pops below test (the top pops leave the bottom
        // edge alone, and a turn is the same read from any of its three points), so they are
        // kept, not asked again. The deque has at least three entries here and at least two
        // wherever it is read below (both loops stop at two; each push makes three).
        let (a, b) = top(&d);
        let mut at_top = Some(K::orient(a, b, p));
        let mut at_bot = None;
        if at_top != Some(Orientation::Clockwise) {
            let (a, b) = bot(&d);
            let o = K::orient(a, b, p);
            if o != Orientation::Clockwise {
                continue;
            }
            at_bot = Some(o);
        }
        let ccw_or = |known: &mut Option<Orientation>, (a, b): (DVec2, DVec2)| {
            known.take().unwrap_or_else(|| K::orient(a, b, p)) == Orientation::CounterClockwise
        };
        while d.len() > 2 && !ccw_or(&mut at_top, top(&d)) {
            d.pop_back();
        }
        d.push_back((i, p));
        // The bottom edge d[0] → d[1] must turn strictly left from p → d[0].
        while d.len() > 2 && !ccw_or(&mut at_bot, bot(&d)) {
            d.pop_front();
        }
        d.push_front((i, p));
    }
    // Both ends hold the vertex added last: drop one.
    d.pop_back();
    let pts: Vec<DVec2> = d.iter().map(|x| x.1).collect();
    let mut hull: Vec<usize> = d.iter().map(|x| x.0).collect();
    hull.rotate_left(lowest(&pts));
    hull
}
