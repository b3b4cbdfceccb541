//! Index views of the chains TENSTEP works on, the bridge frame as exact predicates, and the running
//! best pair.
//!
//! Nothing here copies or transforms a coordinate: a chain is a range of ring indices walked in one
//! direction, the frame's "above" is the sign of a dot product of input differences, and the frame's
//! mirror images (the paper's negated coordinates) only flip the signs those predicates return.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Sign};

/// The caller's index of each vertex of a ring, looked up only when a candidate is offered.
#[derive(Clone, Copy, Debug)]
pub(super) enum Callers<'a> {
    /// A validated polygon's own map ([`ConvexPolygon::source_index`]): no copy, so a call that stops
    /// at step 1 stays `O(log)`.
    Polygon(&'a ConvexPolygon),
    /// A table (the vertex subsets of the recursive split).
    Table(&'a [usize]),
}

impl Callers<'_> {
    /// The caller's index of ring vertex `i`.
    #[inline]
    pub(super) fn get(&self, i: usize) -> usize {
        match self {
            Callers::Polygon(p) => p.source_index(i),
            Callers::Table(t) => t[i],
        }
    }
}

/// `len` consecutive vertices of a ring, the `k`-th at ring index `start ± k` (mod the ring's length).
#[derive(Clone, Copy, Debug)]
pub(super) struct Chain<'a> {
    /// The ring's vertices (counter-clockwise, strictly convex).
    ring: &'a [DVec2],
    /// The caller's index of each ring vertex.
    caller: Callers<'a>,
    /// Whether the ring is `P` (else `Q`).
    on_p: bool,
    /// Ring index of element 0.
    start: usize,
    /// Number of elements (at most the ring's length).
    len: usize,
    /// Counter-clockwise (`true`) or clockwise.
    ccw: bool,
}

impl<'a> Chain<'a> {
    /// The counter-clockwise chain from ring index `from` to ring index `to`, both included.
    pub(super) fn ccw(
        ring: &'a [DVec2],
        caller: Callers<'a>,
        on_p: bool,
        from: usize,
        to: usize,
    ) -> Self {
        let n = ring.len();
        Chain {
            ring,
            caller,
            on_p,
            start: from % n,
            len: (to % n + n - from % n) % n + 1,
            ccw: true,
        }
    }

    /// The number of vertices.
    pub(super) fn len(&self) -> usize {
        self.len
    }

    /// Whether the chain has no vertex.
    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether the chain's vertices belong to `P`.
    pub(super) fn on_p(&self) -> bool {
        self.on_p
    }

    /// The ring index of element `k` (`k ≤ len ≤ n`; larger `k` wrap around). No division on the
    /// hot path: `start < n` and `k < n` keep one conditional subtraction enough.
    #[inline]
    fn index(&self, k: usize) -> usize {
        let n = self.ring.len();
        let k = if k < n { k } else { k % n };
        if self.ccw {
            let i = self.start + k;
            if i >= n { i - n } else { i }
        } else if k <= self.start {
            self.start - k
        } else {
            self.start + n - k
        }
    }

    /// Element `k`.
    #[inline]
    pub(super) fn pt(&self, k: usize) -> DVec2 {
        self.ring[self.index(k)]
    }

    /// The caller's index of element `k`.
    pub(super) fn caller(&self, k: usize) -> usize {
        self.caller.get(self.index(k))
    }

    /// The last element (`len ≥ 1`).
    pub(super) fn last(&self) -> DVec2 {
        self.pt(self.len.saturating_sub(1))
    }

    /// The same vertices in the opposite order.
    pub(super) fn rev(self) -> Self {
        if self.len == 0 {
            return self;
        }
        Chain {
            start: self.index(self.len - 1),
            ccw: !self.ccw,
            ..self
        }
    }

    /// Elements `lo..hi` (clamped to the chain) as a chain.
    pub(super) fn sub(self, lo: usize, hi: usize) -> Self {
        let hi = hi.min(self.len);
        let lo = lo.min(hi);
        Chain {
            start: if lo < hi { self.index(lo) } else { self.start },
            len: hi - lo,
            ..self
        }
    }

    /// Elements `lo..=hi` (clamped) as a chain.
    pub(super) fn incl(self, lo: usize, hi: usize) -> Self {
        self.sub(lo, hi.saturating_add(1))
    }

    /// The number of leading elements satisfying `keep` (stops at the first that does not).
    pub(super) fn prefix(&self, mut keep: impl FnMut(DVec2) -> bool) -> usize {
        (0..self.len).take_while(|&k| keep(self.pt(k))).count()
    }

    /// The number of trailing elements satisfying `keep` (stops at the first that does not).
    pub(super) fn suffix(&self, mut keep: impl FnMut(DVec2) -> bool) -> usize {
        (0..self.len)
            .rev()
            .take_while(|&k| keep(self.pt(k)))
            .count()
    }
}

/// The bridge frame: "up" is the direction `t1 − t0` of the bridge's edge (oriented so that `P` is on
/// the left, `Q` on the right), possibly mirrored. All comparisons are exact predicates on input points.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    /// Tail of the up direction.
    pub(super) t0: DVec2,
    /// Head of the up direction.
    pub(super) t1: DVec2,
    /// Mirrored top to bottom (the paper's negated y).
    pub(super) flip_y: bool,
    /// Mirrored (an odd number of reflections): orientations reverse.
    pub(super) flip_o: bool,
}

impl Frame {
    /// `Y(a)` compared with `Y(b)`: `sign((a − b)·(t1 − t0))`, reversed when mirrored top to bottom.
    pub(super) fn ycmp<K: Kernel>(&self, a: DVec2, b: DVec2) -> Ordering {
        let o = K::dot_sign(b, a, self.t0, self.t1).to_ordering();
        if self.flip_y { o.reverse() } else { o }
    }

    /// The orientation of `(a, b, c)` as seen in the frame.
    pub(super) fn orient<K: Kernel>(&self, a: DVec2, b: DVec2, c: DVec2) -> Sign {
        let s = K::orient(a, b, c).sign();
        if self.flip_o { s.reversed() } else { s }
    }

    /// The x-mirror image (left and right exchanged).
    pub(super) fn mirror_x(self) -> Self {
        Frame {
            flip_o: !self.flip_o,
            ..self
        }
    }

    /// The y-mirror image (top and bottom exchanged).
    pub(super) fn mirror_y(self) -> Self {
        Frame {
            flip_y: !self.flip_y,
            flip_o: !self.flip_o,
            ..self
        }
    }

    /// The half-turn image (both exchanged; a rotation, so orientations are kept).
    pub(super) fn half_turn(self) -> Self {
        Frame {
            flip_y: !self.flip_y,
            ..self
        }
    }
}

/// A candidate pair: vertex `i` of `P` at `p`, vertex `j` of `Q` at `q` (caller indices).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Cand {
    pub(super) p: DVec2,
    pub(super) q: DVec2,
    pub(super) i: usize,
    pub(super) j: usize,
}

/// The best candidate so far: the smaller squared distance (`K::cmp_dist4`), then the smaller caller
/// pair `(i, j)` on exact ties.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Best {
    pub(super) cand: Option<Cand>,
}

impl Best {
    /// Offers `c`.
    pub(super) fn offer<K: Kernel>(&mut self, c: Cand) {
        let better = match self.cand {
            None => true,
            Some(b) => match K::cmp_dist4(c.p, c.q, b.p, b.q) {
                Ordering::Less => true,
                Ordering::Equal => (c.i, c.j) < (b.i, b.j),
                Ordering::Greater => false,
            },
        };
        if better {
            self.cand = Some(c);
        }
    }

    /// Offers element `k` of `x` with element `l` of `y` (one chain on `P`, the other on `Q`).
    pub(super) fn offer_chains<K: Kernel>(
        &mut self,
        x: &Chain<'_>,
        k: usize,
        y: &Chain<'_>,
        l: usize,
    ) {
        let (pc, pk, qc, qk) = if x.on_p() { (x, k, y, l) } else { (y, l, x, k) };
        self.offer::<K>(Cand {
            p: pc.pt(pk),
            q: qc.pt(qk),
            i: pc.caller(pk),
            j: qc.caller(qk),
        });
    }
}
