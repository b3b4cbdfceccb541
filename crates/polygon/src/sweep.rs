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

use crate::order::lex_order;
use crate::ring::{lex_cmp, segments_intersect};
use crate::treap::Treap;

/// The first intersecting pair of non-neighbour edges `(i, j)`, `i < j`, found by the sweep, or `None`
/// when the ring is simple.
///
/// Edge `i` joins `points[i]` and `points[(i + 1) mod m]`. Precondition: `m ≥ 3`, no two cyclically
/// consecutive points equal, and no vertex a reversal (collinear with both neighbours on one side).
pub(crate) fn first_intersection(points: &[DVec2]) -> Option<(usize, usize)> {
    let rings = Rings::new(&[points]);
    sweep(&rings).err()
}

/// The first pair of edges `(i, j)`, edge `i` of ring `a` and edge `j` of ring `b`, that meet (a shared
/// point, touching included), or `None` when the two closed rings have no common point.
///
/// Precondition: each ring is simple (as [`first_intersection`] would say) with at least 3 vertices.
/// The sweep runs over both rings at once: a bad contact is then a contact between the rings, since
/// neither ring touches itself; the proof in the module docs applies unchanged (ring neighbours are
/// pairs of consecutive edges of one ring).
pub(crate) fn first_contact_between(a: &[DVec2], b: &[DVec2]) -> Option<(usize, usize)> {
    let rings = Rings::new(&[a, b]);
    let (s, t) = sweep(&rings).err()?;
    // A contact is between the rings (each ring is simple), so `s` is in `a` and `t` in `b` (`s < t`).
    Some((s, t.checked_sub(a.len())?))
}

/// The sweep; `Err((i, j))` carries the first intersecting pair found (global edge ids, `i < j`), so
/// that `?` stops it.
fn sweep(ring: &Rings) -> Result<(), (usize, usize)> {
    let m = ring.points.len();
    let order = lex_order(&ring.points);
    if let Some(w) = order
        .windows(2)
        .find(|w| ring.point(w[0]) == ring.point(w[1]))
    {
        // The rings pass twice through one point; the edges leaving the two visits are not neighbours.
        return Err(sorted(w[0], w[1]));
    }
    let mut status = Treap::new(m);
    for &v in &order {
        let incident = [ring.prev(v), v];
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

/// The rings being swept (one or two), flattened: vertices and edges have global ids, ring `r`'s
/// vertex `k` being the sum of the earlier rings' lengths plus `k`, and edge `v` joins vertex `v`
/// and the next vertex of its ring. Each vertex's ring neighbours and each edge's lexicographically
/// smaller and larger ends are found once here (the status comparisons ask for them about
/// `log n` times an insertion).
struct Rings {
    /// Every ring's points, one ring after the other.
    points: Vec<DVec2>,
    /// The next vertex around its ring.
    next: Vec<usize>,
    /// The previous vertex around its ring (the edge ending at the vertex).
    prev: Vec<usize>,
    /// Edge `e`'s lexicographically smaller end.
    left: Vec<usize>,
    /// Edge `e`'s lexicographically larger end.
    right: Vec<usize>,
}

impl Rings {
    fn new(rings: &[&[DVec2]]) -> Rings {
        let total: usize = rings.iter().map(|r| r.len()).sum();
        let mut points = Vec::with_capacity(total);
        let (mut next, mut prev) = (Vec::with_capacity(total), Vec::with_capacity(total));
        for ring in rings {
            let (start, len) = (points.len(), ring.len());
            points.extend_from_slice(ring);
            next.extend((0..len).map(|k| start + (k + 1) % len));
            prev.extend((0..len).map(|k| start + (k + len - 1) % len));
        }
        let (left, right) = (0..total)
            .map(|e| {
                let f = next[e];
                if lex_cmp(points[e], points[f]) == Ordering::Less {
                    (e, f)
                } else {
                    (f, e)
                }
            })
            .unzip();
        Rings {
            points,
            next,
            prev,
            left,
            right,
        }
    }

    #[inline]
    fn point(&self, v: usize) -> DVec2 {
        self.points[v]
    }

    /// The next vertex of `v` around its ring.
    #[inline]
    fn next_vertex(&self, v: usize) -> usize {
        self.next[v]
    }

    /// The edge ending at vertex `v` (the previous vertex around its ring).
    #[inline]
    fn prev(&self, v: usize) -> usize {
        self.prev[v]
    }

    /// The vertex id of edge `e`'s lexicographically smaller end.
    #[inline]
    fn left(&self, e: usize) -> usize {
        self.left[e]
    }

    /// The vertex id of edge `e`'s lexicographically larger end.
    #[inline]
    fn right(&self, e: usize) -> usize {
        self.right[e]
    }

    /// Where edge `s`, inserted at its left end `p`, goes relative to status edge `t` (`Less`: below).
    /// `Err` when they meet: `p` lies on `t`, or the two edges starting at `p` overlap.
    fn compare(&self, s: usize, t: usize) -> Result<Ordering, (usize, usize)> {
        let p = self.point(self.left(s));
        let (tl, tr) = (self.point(self.left(t)), self.point(self.right(t)));
        let o = if self.left(t) == self.left(s) {
            // Both start at p: s is above t when its right end is left of p → right(t).
            Robust::orient(p, tr, self.point(self.right(s)))
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

    /// Whether edges `a` and `b` are the same or consecutive around one ring.
    fn neighbours(&self, a: usize, b: usize) -> bool {
        a == b || self.next_vertex(a) == b || self.next_vertex(b) == a
    }

    /// Whether the closed edges `a` and `b` share a point.
    fn meet(&self, a: usize, b: usize) -> bool {
        segments_intersect::<Robust>(
            self.point(a),
            self.point(self.next_vertex(a)),
            self.point(b),
            self.point(self.next_vertex(b)),
        )
    }
}
