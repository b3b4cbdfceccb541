//! The frame of the separating line, without rotation: heights along the line and depths toward it,
//! both as exact signs of degree-2 polynomials in the input coordinates.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign};

use crate::param::Affine;
use crate::site::Vertex;

/// The oriented separating line `l` (through `l0`, `l1`, the chain `Q` on its left) seen from one
/// chain.
///
/// For chain `P` (right of `l`) the frame is `x = depth = (z − l0) × d`, `y = height = (z − l0) · d`
/// with `d = l1 − l0`: an orientation-preserving similarity. For `Q` the depth is `d × (z − l0)`, a
/// reflection, so every orientation sign is negated (`mirror`). Heights are the same for both chains.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    pub(crate) l0: DVec2,
    pub(crate) l1: DVec2,
    pub(crate) mirror: bool,
}

impl Frame {
    /// Compares the heights of `a` and `b` along the line: `sign((a − b) · d)` (degree 2).
    #[inline]
    pub(crate) fn cmp_height<K: Kernel, V: Vertex>(&self, a: V, b: V) -> Ordering {
        // Equal points: an exact zero, decided here rather than by the kernel's exact stage.
        if a == b {
            return Ordering::Equal;
        }
        V::dot_sign::<K>(b, a, V::input(self.l0), V::input(self.l1)).to_ordering()
    }

    /// Compares the depths (distances to the line, on this chain's side) of `a` and `b`:
    /// `sign((a − b) × d)`, negated for the mirrored chain (degree 2).
    #[inline]
    pub(crate) fn cmp_depth<K: Kernel, V: Vertex>(&self, a: V, b: V) -> Ordering {
        if a == b {
            return Ordering::Equal;
        }
        let s = V::cross_sign::<K>(b, a, V::input(self.l0), V::input(self.l1));
        if self.mirror { s.reversed() } else { s }.to_ordering()
    }

    /// The sign of the depth of `z`: positive on this chain's side, zero on the line (degree 2).
    #[inline]
    pub(crate) fn depth_sign<K: Kernel, V: Vertex>(&self, z: V) -> Sign {
        let s = V::orient::<K>(V::input(self.l0), V::input(self.l1), z).sign();
        // P is on the right (orient < 0 means positive depth); Q on the left.
        if self.mirror { s } else { s.reversed() }
    }

    /// The orientation of `(a, b, c)` in this frame: the real orientation, negated for the mirrored
    /// chain (degree 2).
    #[inline]
    pub(crate) fn orient<K: Kernel, V: Vertex>(&self, a: V, b: V, c: V) -> Sign {
        if a == b || b == c || a == c {
            return Sign::Zero;
        }
        let s = V::orient::<K>(a, b, c).sign();
        if self.mirror { s.reversed() } else { s }
    }
}

impl Frame {
    /// `x ↦ depth(x) − depth(t)` in this frame: `±(x − t) × d`.
    pub(crate) fn depth_minus<V: Vertex>(&self, t: V) -> Affine<V> {
        Affine {
            cross: true,
            c: t,
            v0: V::input(self.l0),
            v1: V::input(self.l1),
            neg: self.mirror,
        }
    }

    /// `x ↦ H(x) − H(t)`: `(x − t) · d`.
    pub(crate) fn height_minus<V: Vertex>(&self, t: V) -> Affine<V> {
        Affine {
            cross: false,
            c: t,
            v0: V::input(self.l0),
            v1: V::input(self.l1),
            neg: false,
        }
    }

    /// `x ↦ orient(x, h, u)` in this frame: `∓(x − h) × (u − h)`.
    pub(crate) fn orient_x_first<V: Vertex>(&self, h: V, u: V) -> Affine<V> {
        Affine {
            cross: true,
            c: h,
            v0: h,
            v1: u,
            neg: !self.mirror,
        }
    }

    /// `x ↦ orient(u, w, x)` in this frame: `∓(x − u) × (w − u)`.
    pub(crate) fn orient_x_last<V: Vertex>(&self, u: V, w: V) -> Affine<V> {
        Affine {
            cross: true,
            c: u,
            v0: u,
            v1: w,
            neg: !self.mirror,
        }
    }
}
