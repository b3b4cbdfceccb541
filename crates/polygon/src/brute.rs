//! The brute-force twin of the sweep: all pairs of edges, `O(n²)`, for tests and invariant checks.

use glam::DVec2;
use polydist_predicates::Robust;

use crate::ring::{Turn, segments_intersect, turn};

/// The lexicographically first pair of edges `(i, j)`, `i < j`, of the closed ring `points` that meet
/// other than as ring neighbours at their shared vertex, or `None`.
///
/// Neighbours are reported only when they overlap (the vertex between them is a reversal). Requires no
/// two cyclically consecutive points equal; rings of fewer than three points give `None`.
pub(crate) fn first_intersection(points: &[DVec2]) -> Option<(usize, usize)> {
    let m = points.len();
    if m < 3 {
        return None;
    }
    let edge = |i: usize| (points[i], points[(i + 1) % m]);
    for i in 0..m {
        for j in i + 1..m {
            let bad = if j == i + 1 {
                // Edges i and i + 1 share vertex i + 1.
                turn(points[i], points[j], points[(j + 1) % m]) == Turn::Reversal
            } else if i == 0 && j == m - 1 {
                // Edges m − 1 and 0 share vertex 0.
                turn(points[m - 1], points[0], points[1]) == Turn::Reversal
            } else {
                let ((a, b), (c, d)) = (edge(i), edge(j));
                segments_intersect::<Robust>(a, b, c, d)
            };
            if bad {
                return Some((i, j));
            }
        }
    }
    None
}
