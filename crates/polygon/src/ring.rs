//! Cleaning a caller's vertex ring: coordinate validation, exact repeats, collinear vertices, spikes.
//!
//! Both polygon constructors run the same three steps on the caller's list `p[0..n]`, read as a closed
//! ring (the edge `j` joins `p[j]` and `p[(j + 1) mod n]`):
//!
//! 1. [`validate`]: every coordinate finite and within [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE).
//! 2. [`Dedup::new`]: merge runs of exactly equal consecutive vertices, cyclically (so the closing
//!    duplicate of a closed ring merges into vertex 0). Each distinct vertex is named by the smallest
//!    caller index of its run.
//! 3. [`classify`]: the exact turn at every distinct vertex: left, right, straight (collinear with its
//!    neighbours and strictly between them; dropped) or a reversal (collinear, both neighbours on the
//!    same side: a spike).
//!
//! Dropping straight vertices never changes another vertex's turn: `orient(u, v, w)` keeps its sign
//! when `u` or `w` moves along its ray from `v`, and a maximal run of straight vertices lies, in order,
//! on the segment between the two turning vertices around it (each is strictly between its neighbours,
//! so the run is monotone along one line).

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust, Sign, is_valid_coordinate};

use crate::PolygonError;

/// Checks the caller's list: non-empty, every coordinate finite and within range.
pub(crate) fn validate(points: &[DVec2]) -> Result<(), PolygonError> {
    if points.is_empty() {
        return Err(PolygonError::Empty);
    }
    for (index, p) in points.iter().enumerate() {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Err(PolygonError::NonFinite { index });
        }
        if !(is_valid_coordinate(p.x) && is_valid_coordinate(p.y)) {
            return Err(PolygonError::OutOfRange { index });
        }
    }
    Ok(())
}

/// Whether both coordinates are finite and within [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE).
pub(crate) fn is_valid_point(p: DVec2) -> bool {
    is_valid_coordinate(p.x) && is_valid_coordinate(p.y)
}

/// `a` compared with `b` for finite `a`, `b`, with `−0 = +0`; `Equal` when either is NaN.
#[inline]
fn cmp_coordinate(a: f64, b: f64) -> Ordering {
    if a < b {
        Ordering::Less
    } else if a > b {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// The lexicographic order of points: by `x`, then by `y`.
///
/// Exact: it compares input coordinates, never computed values. It is a total order on points with
/// finite coordinates (validated inputs), with `−0 = +0` as for geometric equality.
#[inline]
pub(crate) fn lex_cmp(a: DVec2, b: DVec2) -> Ordering {
    cmp_coordinate(a.x, b.x).then_with(|| cmp_coordinate(a.y, b.y))
}

/// The caller's ring with exact repeats merged.
#[derive(Debug)]
pub(crate) struct Dedup {
    /// The distinct vertices, in the caller's cyclic order; no two consecutive ones equal (cyclically).
    pub(crate) points: Vec<DVec2>,
    /// For each distinct vertex, the smallest caller index of its run of repeats (its name).
    pub(crate) rep: Vec<usize>,
    /// For each distinct vertex, the caller's edge leaving it toward the next distinct vertex: the
    /// cyclically last caller index of its run.
    pub(crate) out_edge: Vec<usize>,
}

impl Dedup {
    /// Merges runs of equal consecutive vertices of a non-empty ring.
    ///
    /// A run that ends the list and equals `points[0]` (the closing duplicate of a closed ring) merges
    /// into vertex 0's run, which is then named 0 and left by the edge out of its last index.
    pub(crate) fn new(points: &[DVec2]) -> Dedup {
        let n = points.len();
        // Indices `end..n` repeat points[0] (the closing duplicates) and belong to vertex 0's run.
        let mut end = n;
        while end > 1 && points[end - 1] == points[0] {
            end -= 1;
        }
        let mut out = Dedup {
            points: Vec::new(),
            rep: Vec::new(),
            out_edge: Vec::new(),
        };
        let mut start = 0;
        while start < end {
            let mut last = start;
            while last + 1 < end && points[last + 1] == points[start] {
                last += 1;
            }
            out.points.push(points[start]);
            out.rep.push(start);
            out.out_edge.push(last);
            start = last + 1;
        }
        out
    }

    /// The number of distinct vertices.
    pub(crate) fn len(&self) -> usize {
        self.points.len()
    }
}

/// The exact turn of the boundary at a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Turn {
    /// Counter-clockwise.
    Left,
    /// Clockwise.
    Right,
    /// Collinear with its neighbours and strictly between them: the vertex is dropped.
    Straight,
    /// Collinear with its neighbours, which lie on the same side of it: a 180° spike.
    Reversal,
}

/// The turn at `v` from `u` to `w` (`u`, `w` distinct from `v`), decided exactly.
pub(crate) fn turn(u: DVec2, v: DVec2, w: DVec2) -> Turn {
    match Robust::orient(u, v, w) {
        Orientation::CounterClockwise => Turn::Left,
        Orientation::Clockwise => Turn::Right,
        // Collinear with nonzero u − v and w − v: they are parallel, so their dot product is nonzero;
        // negative means opposite directions (v strictly between u and w).
        Orientation::Collinear => {
            if Robust::dot_sign(v, u, v, w) == Sign::Negative {
                Turn::Straight
            } else {
                Turn::Reversal
            }
        }
    }
}

/// The turn at every vertex of a ring of at least two distinct vertices (cyclically distinct neighbours).
pub(crate) fn classify(points: &[DVec2]) -> Vec<Turn> {
    let m = points.len();
    (0..m)
        .map(|i| turn(points[(i + m - 1) % m], points[i], points[(i + 1) % m]))
        .collect()
}

/// The index of the lexicographically smallest point (the first one on ties).
pub(crate) fn lowest(points: &[DVec2]) -> usize {
    let mut best = 0;
    for (i, &p) in points.iter().enumerate().skip(1) {
        if lex_cmp(p, points[best]) == Ordering::Less {
            best = i;
        }
    }
    best
}

/// How many times the lexicographic direction of the edges changes along the closed ring `points`
/// (no two consecutive points equal).
///
/// An edge is *forward* when its end is lexicographically greater than its start: its direction lies
/// in the half-open half-circle `H` of angles `(−π/2, π/2]`. See [`crate::convex`] for why this count is
/// twice the winding of a ring whose turns are all strict and of one sign.
pub(crate) fn direction_changes(points: &[DVec2]) -> usize {
    let m = points.len();
    let forward = |i: usize| lex_cmp(points[i], points[(i + 1) % m]) == Ordering::Less;
    (0..m)
        .filter(|&i| forward(i) != forward((i + 1) % m))
        .count()
}

/// Whether the closed segments `[a, b]` and `[c, d]` (`a ≠ b`, `c ≠ d`) share a point, decided exactly
/// under an exact kernel.
pub(crate) fn segments_intersect<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let o1 = K::orient(a, b, c).sign();
    let o2 = K::orient(a, b, d).sign();
    if o1 == Sign::Zero && o2 == Sign::Zero {
        // All four points on the line through a ≠ b: compare the intervals the segments cover, in the
        // lexicographic order, which is monotone along any line.
        let (lo1, hi1) = ordered(a, b);
        let (lo2, hi2) = ordered(c, d);
        return lex_cmp(lo1, hi2) != Ordering::Greater && lex_cmp(lo2, hi1) != Ordering::Greater;
    }
    // Otherwise the segments meet iff neither has both endpoints strictly on one side of the other's
    // line (o3 = o4 = 0 would put a, b on line cd, hence c, d on line ab: excluded above).
    let o3 = K::orient(c, d, a).sign();
    let o4 = K::orient(c, d, b).sign();
    straddles(o1, o2) && straddles(o3, o4)
}

/// `s · t ≤ 0`: the two points are not strictly on the same side.
#[inline]
fn straddles(s: Sign, t: Sign) -> bool {
    !matches!(
        (s, t),
        (Sign::Positive, Sign::Positive) | (Sign::Negative, Sign::Negative)
    )
}

/// The two points in lexicographic order.
#[inline]
pub(crate) fn ordered(a: DVec2, b: DVec2) -> (DVec2, DVec2) {
    if lex_cmp(a, b) == Ordering::Greater {
        (b, a)
    } else {
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn segments_intersect_in_every_degenerate_case() {
        let meet = |a, b, c, d| segments_intersect::<Robust>(a, b, c, d);
        // Proper crossing, and segments apart.
        assert!(meet(p(0.0, 0.0), p(2.0, 2.0), p(0.0, 2.0), p(2.0, 0.0)));
        assert!(!meet(p(0.0, 0.0), p(1.0, 1.0), p(3.0, 0.0), p(2.0, 1.0)));
        // An end on the other's interior, and an end on the other's line beyond it.
        assert!(meet(p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0), p(1.0, 5.0)));
        assert!(!meet(p(0.0, 0.0), p(2.0, 0.0), p(3.0, 0.0), p(3.0, 5.0)));
        // Collinear: overlapping, touching end to end, disjoint; vertical too.
        assert!(meet(p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0), p(3.0, 0.0)));
        assert!(meet(p(0.0, 0.0), p(2.0, 0.0), p(3.0, 0.0), p(2.0, 0.0)));
        assert!(!meet(p(0.0, 0.0), p(2.0, 0.0), p(3.0, 0.0), p(2.5, 0.0)));
        assert!(meet(p(1.0, 0.0), p(1.0, 2.0), p(1.0, 3.0), p(1.0, 2.0)));
        assert!(!meet(p(1.0, 0.0), p(1.0, 2.0), p(1.0, 3.0), p(1.0, 2.5)));
        // One ulp decides.
        let up = f64::from_bits(1.0f64.to_bits() + 1);
        assert!(meet(p(0.0, 0.0), p(2.0, 2.0), p(1.0, 1.0), p(1.0, 3.0)));
        assert!(!meet(p(0.0, 0.0), p(2.0, 2.0), p(1.0, up), p(1.0, 3.0)));
    }

    #[test]
    fn dedup_merges_runs_and_the_closing_duplicate() {
        let ring = [
            p(0.0, 0.0),
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
            p(0.0, 0.0),
        ];
        let d = Dedup::new(&ring);
        assert_eq!(d.points, [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)]);
        assert_eq!(d.rep, [0, 2, 3]);
        assert_eq!(d.out_edge, [1, 2, 4]);
        // −0 equals +0.
        let d = Dedup::new(&[p(0.0, 0.0), p(-0.0, 0.0), p(1.0, 1.0)]);
        assert_eq!(d.rep, [0, 2]);
        let d = Dedup::new(&[p(3.0, 3.0); 4]);
        assert_eq!((d.rep, d.out_edge), (vec![0], vec![0]));
    }

    #[test]
    fn turns_and_direction_changes() {
        assert_eq!(turn(p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)), Turn::Left);
        assert_eq!(turn(p(0.0, 0.0), p(1.0, 0.0), p(1.0, -1.0)), Turn::Right);
        assert_eq!(turn(p(0.0, 0.0), p(1.0, 0.0), p(2.0, 0.0)), Turn::Straight);
        assert_eq!(turn(p(0.0, 0.0), p(1.0, 0.0), p(0.5, 0.0)), Turn::Reversal);
        let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
        assert_eq!(direction_changes(&square), 2);
        let pentagram = [
            p(0.0, 10.0),
            p(-6.0, -8.0),
            p(10.0, 3.0),
            p(-10.0, 3.0),
            p(6.0, -8.0),
        ];
        assert_eq!(direction_changes(&pentagram), 4);
    }
}
