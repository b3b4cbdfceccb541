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

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation};

use crate::ring::lowest;

/// The hull vertices of the counter-clockwise simple polygon `v` (at least 3 vertices, no three
/// consecutive collinear), as indices into `v`: counter-clockwise, strictly convex, starting at the
/// lexicographically lowest and increasing cyclically.
pub(crate) fn hull<K: Kernel>(v: &[DVec2]) -> Vec<usize> {
    let n = v.len();
    let ccw = |a: DVec2, b: DVec2, c: DVec2| K::orient(a, b, c) == Orientation::CounterClockwise;
    // The deque lives in `d[bot..=top]` of a buffer of `2n + 1` slots, started in the middle: each
    // vertex pushes at most once on each end, so neither end leaves the buffer. `d` holds indices,
    // `pts` the same vertices' points (the tests read only these).
    let mut d = vec![0usize; 2 * n + 1];
    let mut pts = vec![DVec2::ZERO; 2 * n + 1];
    let (mut bot, mut top) = (n - 2, n + 1);
    let first = if ccw(v[0], v[1], v[2]) {
        [2, 0, 1, 2]
    } else {
        [2, 1, 0, 2]
    };
    for (k, &i) in first.iter().enumerate() {
        d[bot + k] = i;
        pts[bot + k] = v[i];
    }
    for (i, &p) in v.iter().enumerate().skip(3) {
        // Inside or on the hull: not strictly right of the top edge nor of the bottom edge. The two
        // turns tested are the first ones the pops below test (the top pops leave the bottom
        // edge alone, and a turn is the same read from any of its three points), so they are
        // kept, not asked again.
        let mut at_top = Some(K::orient(pts[top - 1], pts[top], p));
        let mut at_bot = None;
        if at_top != Some(Orientation::Clockwise) {
            let o = K::orient(pts[bot], pts[bot + 1], p);
            if o != Orientation::Clockwise {
                continue;
            }
            at_bot = Some(o);
        }
        let ccw_or = |known: &mut Option<Orientation>, a: DVec2, b: DVec2| {
            known.take().unwrap_or_else(|| K::orient(a, b, p)) == Orientation::CounterClockwise
        };
        while top - bot > 1 && !ccw_or(&mut at_top, pts[top - 1], pts[top]) {
            top -= 1;
        }
        top += 1;
        d[top] = i;
        pts[top] = p;
        // The bottom edge d[bot] → d[bot + 1] must turn strictly left from p → d[bot].
        while top - bot > 1 && !ccw_or(&mut at_bot, pts[bot], pts[bot + 1]) {
            bot += 1;
        }
        bot -= 1;
        d[bot] = i;
        pts[bot] = p;
    }
    let mut hull = d[bot..top].to_vec();
    hull.rotate_left(lowest(&pts[bot..top]));
    hull
}
