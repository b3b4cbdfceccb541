//! Is a closed polygonal ring simple? The Shamos–Hoey sweep, on exact predicates.
//!
//! Shamos & Hoey (1976), "Geometric intersection problems", FOCS, §3: sweep a line across the segments,
//! keep the segments it crosses ordered along it, and test only segments that become neighbours in that
//! order; if any two segments intersect, some pair does when they first become neighbours.
//! `O(n log n)` time, `O(n)` space.
//!
//! # What we reconstructed
//! The paper assumes general position and reports any shared point. A polygon's edges always share
//! vertices with their two ring neighbours, and real inputs have vertical edges, many vertices on one
//! `x` and collinear overlaps. So:
//!
//! - **Sweep order.** Events are the ring's vertices in lexicographic order `(x, y)`: the sweep line is
//!   tilted by an infinitesimal angle (`x + εy = c`), so no edge is parallel to it and no two vertices
//!   are met at once. Each edge runs from its lexicographically smaller end (*left*) to its larger end.
//! - **Repeated vertices.** Two ring vertices at the same point make the ring touch itself there; sorting
//!   finds them first, and their outgoing edges (never ring neighbours) are reported.
//! - **Allowed contacts.** Ring-neighbour edges are never tested: the caller guarantees that no vertex is
//!   a reversal (spike), so two neighbours meet exactly at their shared vertex.
//! - **Events.** At vertex `v`, first the incident edges ending at `v` are removed (their two status
//!   neighbours are tested against each other), then the incident edges starting at `v` are inserted
//!   (each tested against its new neighbours).
//! - **Comparator.** An edge `s` inserted at its left end `p` is compared with a status edge `t` by
//!   `orient(left(t), right(t), p)` (left of `t` means above it on the sweep line), and with the other edge
//!   starting at `p` by `orient(p, right(t), right(s))`. A collinear answer means `p` lies on `t` (or the
//!   two new edges overlap): an intersection, reported at once.
//!
//! # Why it finds an intersection when there is one
//! Call a contact *bad* unless it is two ring neighbours at their shared vertex. Let `q` be the
//! lexicographically smallest point of a bad contact. Before the sweep reaches `q`, the status edges
//! meet only at shared vertices behind the sweep line, so their order along the line is a total order
//! that does not change between events; by induction, the tree's in-order is that order (insertion
//! compares against correctly ordered edges with exact answers; removal keeps order), and every pair of
//! status neighbours was tested when it became neighbours. Let `C` be the edges through `q`.
//!
//! - `q` is not a vertex: every edge of `C` has `q` in its relative interior, so all are in the status
//!   just before `q`, and near `q` nothing else is: `C` is a contiguous block of at least two edges, all
//!   pairs bad (neighbours meet only at vertices). Two of them are status neighbours, and were tested.
//! - `q` is a vertex `v` with other edges `C'` through it (their interiors: vertices are distinct).
//!   An edge of `C'` and an edge at `v`, or two edges of `C'`, are not ring neighbours (that would make
//!   them overlap along a line, a spike). If an edge at `v` ends at `v`, the edges of `C` in the status
//!   just before `v` form a block containing an edge of `C'` and one more, so a bad pair are neighbours
//!   and were tested. Otherwise both edges at `v` start there and are inserted into a correctly ordered
//!   status in which the edges below `v`, then `C'`, then the edges above `v` are contiguous. A binary
//!   search tree descent compares with both in-order neighbours of the slot it ends in; those cannot be
//!   one edge below and one above `v` with `C'` between them, so the descent meets an edge of `C'`,
//!   whose comparison is collinear: reported.
//!
//! Every reported pair really meets (each test is exact), so the sweep reports an intersection if and
//! only if there is one. On inputs outside the precondition the answer may be wrong, but the
//! [`Treap`] never panics or loops whatever the comparator says.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust};

use crate::ring::{lex_cmp, segments_intersect};
use crate::treap::Treap;

/// The first intersecting pair of non-neighbour edges `(i, j)`, `i < j`, found by the sweep, or `None`
/// when the ring is simple.
///
/// Edge `i` joins `points[i]` and `points[(i + 1) mod m]`. Precondition: `m ≥ 3`, no two cyclically
/// consecutive points equal, and no vertex a reversal (collinear with both neighbours on one side).
pub(crate) fn first_intersection(points: &[DVec2]) -> Option<(usize, usize)> {
    sweep(points).err()
}

/// The sweep; `Err((i, j))` carries the first intersecting pair found, so that `?` stops it.
fn sweep(points: &[DVec2]) -> Result<(), (usize, usize)> {
    let m = points.len();
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by(|&i, &j| lex_cmp(points[i], points[j]).then(i.cmp(&j)));
    if let Some(w) = order.windows(2).find(|w| points[w[0]] == points[w[1]]) {
        // The ring passes twice through one point; the edges leaving the two visits are not neighbours.
        return Err(sorted(w[0], w[1]));
    }
    let ring = Ring { points, m };
    let mut status = Treap::new(m);
    for &v in &order {
        let incident = [(v + m - 1) % m, v];
        for &e in &incident {
            if ring.right(e) == v {
                let (below, above) = (status.prev(e), status.next(e));
                status.remove(e);
                if let (Some(a), Some(b)) = (below, above) {
                    ring.test(a, b)?;
                }
            }
        }
        for &s in &incident {
            if ring.left(s) == v {
                status.insert(s, |t| ring.compare(s, t))?;
                for t in [status.prev(s), status.next(s)].into_iter().flatten() {
                    ring.test(s, t)?;
                }
            }
        }
    }
    Ok(())
}

/// The pair in increasing order.
fn sorted(i: usize, j: usize) -> (usize, usize) {
    if i < j { (i, j) } else { (j, i) }
}

/// The ring being swept.
struct Ring<'a> {
    points: &'a [DVec2],
    m: usize,
}

impl Ring<'_> {
    /// The vertex index of edge `e`'s lexicographically smaller end.
    fn left(&self, e: usize) -> usize {
        let f = (e + 1) % self.m;
        if lex_cmp(self.points[e], self.points[f]) == Ordering::Less {
            e
        } else {
            f
        }
    }

    /// The vertex index of edge `e`'s lexicographically larger end.
    fn right(&self, e: usize) -> usize {
        let f = (e + 1) % self.m;
        if lex_cmp(self.points[e], self.points[f]) == Ordering::Less {
            f
        } else {
            e
        }
    }

    /// Where edge `s`, inserted at its left end `p`, goes relative to status edge `t` (`Less`: below).
    /// `Err` when they meet: `p` lies on `t`, or the two edges starting at `p` overlap.
    fn compare(&self, s: usize, t: usize) -> Result<Ordering, (usize, usize)> {
        let p = self.points[self.left(s)];
        let (tl, tr) = (self.points[self.left(t)], self.points[self.right(t)]);
        let o = if self.left(t) == self.left(s) {
            // Both start at p: s is above t when its right end is left of p → right(t).
            Robust::orient(p, tr, self.points[self.right(s)])
        } else {
            // p is above t when it is left of t directed left → right.
            Robust::orient(tl, tr, p)
        };
        match o {
            Orientation::CounterClockwise => Ok(Ordering::Greater),
            Orientation::Clockwise => Ok(Ordering::Less),
            Orientation::Collinear => Err(sorted(s, t)),
        }
    }

    /// `Err((i, j))` when edges `a` and `b` are not ring neighbours and meet.
    fn test(&self, a: usize, b: usize) -> Result<(), (usize, usize)> {
        if self.neighbours(a, b) || !self.meet(a, b) {
            Ok(())
        } else {
            Err(sorted(a, b))
        }
    }

    /// Whether edges `a`, `b` are the same or consecutive around the ring.
    fn neighbours(&self, a: usize, b: usize) -> bool {
        a == b || (a + 1) % self.m == b || (b + 1) % self.m == a
    }

    /// Whether the closed edges `a` and `b` share a point.
    fn meet(&self, a: usize, b: usize) -> bool {
        let m = self.m;
        let p = self.points;
        segments_intersect::<Robust>(p[a], p[(a + 1) % m], p[b], p[(b + 1) % m])
    }
}
