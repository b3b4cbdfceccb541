//! The vertices section 3 works on: input points, or (for chains clipped to a half-plane) clip
//! points where an edge crosses the subproblem's line, kept symbolic.
//!
//! Section 3 is written once, generic over [`Vertex`]. With [`DVec2`] every predicate goes straight
//! to the kernel, exactly as before the abstraction (the static filters that read coordinates
//! included: [`Vertex::INPUT`]). With [`Site`] a predicate whose points are all input points does
//! the same, and one with a clip point among them is decided by
//! [`polydist_predicates::sign_at`]: the same polynomial, at the clip point's exact rational
//! coordinates, through the same kernel (docs/algorithms/separator.md, "Step G").

use core::cmp::Ordering;
use core::fmt::Debug;

use glam::DVec2;
use polydist_predicates::{Dist2, Kernel, Orientation, Polynomial, Sign, Site, crossing, sign_at};

mod sealed {
    pub trait Sealed {}
    impl Sealed for glam::DVec2 {}
    impl Sealed for polydist_predicates::Site {}
}

/// A point section 3 decides predicates about: an input point ([`DVec2`]) or a [`Site`], which may
/// be a clip point kept symbolic. Sealed: implemented for these two only. The matrices of section 3
/// ([`CvvMatrix`](crate::CvvMatrix), [`CveMatrix`](crate::CveMatrix)) take it as a parameter that
/// defaults to [`DVec2`].
pub trait Vertex: sealed::Sealed + Copy + PartialEq + Debug + 'static {
    /// `true` when every value is an input point (so coordinates may be read by static filters).
    const INPUT: bool;

    /// The input point `p`.
    fn input(p: DVec2) -> Self;

    /// The input point this is, if it is one.
    fn as_input(self) -> Option<DVec2>;

    /// The point, rounded (for constructions, never for decisions).
    fn approx(self) -> DVec2;

    /// [`Kernel::orient`].
    fn orient<K: Kernel>(a: Self, b: Self, c: Self) -> Orientation;

    /// [`Kernel::dot_sign`].
    fn dot_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign;

    /// [`Kernel::cross_sign`].
    fn cross_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign;

    /// [`Kernel::cmp_dist`].
    fn cmp_dist<K: Kernel>(p: Self, a: Self, b: Self) -> Ordering;

    /// [`Kernel::cmp_dist4`].
    fn cmp_dist4<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Ordering;

    /// [`Kernel::cmp_dist2`].
    fn cmp_dist2<K: Kernel>(x: Dist2<Self>, y: Dist2<Self>) -> Ordering;

    /// [`Kernel::sign`] of `f` at `M` points (`N = 2M` coordinates, `NI = 8M`: see
    /// [`polydist_predicates::sign_at`]).
    fn sign<K, F, const N: usize, const M: usize, const NI: usize>(f: &F, pts: [Self; M]) -> Sign
    where
        K: Kernel,
        F: Polynomial<N>;
}

/// The coordinates of input points, in order.
#[inline(always)]
fn flat<const N: usize, const M: usize>(pts: [DVec2; M]) -> [f64; N] {
    core::array::from_fn(|i| {
        if i % 2 == 0 {
            pts[i / 2].x
        } else {
            pts[i / 2].y
        }
    })
}

impl Vertex for DVec2 {
    const INPUT: bool = true;

    #[inline(always)]
    fn input(p: DVec2) -> Self {
        p
    }
    #[inline(always)]
    fn as_input(self) -> Option<DVec2> {
        Some(self)
    }
    #[inline(always)]
    fn approx(self) -> DVec2 {
        self
    }
    #[inline(always)]
    fn orient<K: Kernel>(a: Self, b: Self, c: Self) -> Orientation {
        K::orient(a, b, c)
    }
    #[inline(always)]
    fn dot_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign {
        K::dot_sign(a, b, c, d)
    }
    #[inline(always)]
    fn cross_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign {
        K::cross_sign(a, b, c, d)
    }
    #[inline(always)]
    fn cmp_dist<K: Kernel>(p: Self, a: Self, b: Self) -> Ordering {
        K::cmp_dist(p, a, b)
    }
    #[inline(always)]
    fn cmp_dist4<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        K::cmp_dist4(a, b, c, d)
    }
    #[inline(always)]
    fn cmp_dist2<K: Kernel>(x: Dist2<Self>, y: Dist2<Self>) -> Ordering {
        K::cmp_dist2(x, y)
    }
    #[inline(always)]
    fn sign<K, F, const N: usize, const M: usize, const NI: usize>(f: &F, pts: [Self; M]) -> Sign
    where
        K: Kernel,
        F: Polynomial<N>,
    {
        K::sign(f, &flat::<N, M>(pts))
    }
}

/// The input points of `sites`, when every one is an input point.
#[inline]
fn inputs<const M: usize>(sites: [Site; M]) -> Option<[DVec2; M]> {
    let mut out = [DVec2::ZERO; M];
    for (o, s) in out.iter_mut().zip(sites) {
        *o = s.as_input()?;
    }
    Some(out)
}

impl Vertex for Site {
    const INPUT: bool = false;

    fn input(p: DVec2) -> Self {
        Site::Input(p)
    }
    fn as_input(self) -> Option<DVec2> {
        match self {
            Site::Input(p) => Some(p),
            Site::Crossing { .. } => None,
        }
    }
    fn approx(self) -> DVec2 {
        Site::approx(self)
    }
    fn orient<K: Kernel>(a: Self, b: Self, c: Self) -> Orientation {
        match inputs([a, b, c]) {
            Some([a, b, c]) => K::orient(a, b, c),
            None => crossing::orient::<K>(a, b, c),
        }
    }
    fn dot_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign {
        match inputs([a, b, c, d]) {
            Some([a, b, c, d]) => K::dot_sign(a, b, c, d),
            None => crossing::dot_sign::<K>(a, b, c, d),
        }
    }
    fn cross_sign<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Sign {
        match inputs([a, b, c, d]) {
            Some([a, b, c, d]) => K::cross_sign(a, b, c, d),
            None => crossing::cross_sign::<K>(a, b, c, d),
        }
    }
    fn cmp_dist<K: Kernel>(p: Self, a: Self, b: Self) -> Ordering {
        match inputs([p, a, b]) {
            Some([p, a, b]) => K::cmp_dist(p, a, b),
            None => crossing::cmp_dist::<K>(p, a, b),
        }
    }
    fn cmp_dist4<K: Kernel>(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        match inputs([a, b, c, d]) {
            Some([a, b, c, d]) => K::cmp_dist4(a, b, c, d),
            None => crossing::cmp_dist4::<K>(a, b, c, d),
        }
    }
    fn cmp_dist2<K: Kernel>(x: Dist2<Self>, y: Dist2<Self>) -> Ordering {
        crossing::cmp_dist2::<K>(x, y)
    }
    fn sign<K, F, const N: usize, const M: usize, const NI: usize>(f: &F, pts: [Self; M]) -> Sign
    where
        K: Kernel,
        F: Polynomial<N>,
    {
        sign_at::<K, F, N, M, NI>(f, pts)
    }
}
