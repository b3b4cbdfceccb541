//! A kernel wrapper that counts predicate calls, for complexity tests ("count, never time").

use core::cell::Cell;
use core::cmp::Ordering;
use core::marker::PhantomData;

use glam::DVec2;

use crate::kernel::{Dist2, Kernel};
use crate::poly::Polynomial;
use crate::{Orientation, Sign};

/// How many predicates of each kind the current thread has evaluated through a [`Counted`] kernel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PredicateCounts {
    /// [`Kernel::orient`] calls.
    pub orient: u64,
    /// [`Kernel::dot_sign`] calls.
    pub dot: u64,
    /// [`Kernel::cross_sign`] calls.
    pub cross: u64,
    /// [`Kernel::cmp_dist`] calls.
    pub cmp_dist: u64,
    /// [`Kernel::cmp_dist4`] calls.
    pub cmp_dist4: u64,
    /// [`Kernel::cmp_dist2`] calls.
    pub cmp_dist2: u64,
    /// [`Kernel::sign`] calls (algorithm-specific polynomials), and [`crate::sign_at`] calls decided
    /// before it ([`Kernel::note_decided_at_sites`]).
    pub sign: u64,
}

impl PredicateCounts {
    /// All calls, of every kind.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.orient
            + self.dot
            + self.cross
            + self.cmp_dist
            + self.cmp_dist4
            + self.cmp_dist2
            + self.sign
    }
}

std::thread_local! {
    static COUNTS: Cell<PredicateCounts> = const { Cell::new(PredicateCounts {
        orient: 0, dot: 0, cross: 0, cmp_dist: 0, cmp_dist4: 0, cmp_dist2: 0, sign: 0,
    }) };
}

fn bump(f: impl FnOnce(&mut PredicateCounts)) {
    COUNTS.with(|c| {
        let mut v = c.get();
        f(&mut v);
        c.set(v);
    });
}

/// The counts accumulated on this thread since the last [`reset_predicate_counts`].
#[must_use]
pub fn predicate_counts() -> PredicateCounts {
    COUNTS.with(Cell::get)
}

/// Sets this thread's counts to zero.
pub fn reset_predicate_counts() {
    COUNTS.with(|c| c.set(PredicateCounts::default()));
}

/// The kernel `K`, counting every top-level predicate call in a thread-local [`PredicateCounts`].
///
/// Decisions are exactly `K`'s. Calls a predicate makes internally (the dot signs inside
/// [`Kernel::cmp_dist2`]) are not counted separately: one call, one count.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_predicates::{predicate_counts, reset_predicate_counts, Counted, Kernel, Robust};
///
/// reset_predicate_counts();
/// let _ = Counted::<Robust>::orient(DVec2::ZERO, DVec2::X, DVec2::Y);
/// assert_eq!(predicate_counts().orient, 1);
/// ```
#[derive(Debug)]
pub struct Counted<K>(PhantomData<K>);

impl<K> Clone for Counted<K> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<K> Copy for Counted<K> {}
impl<K> Default for Counted<K> {
    fn default() -> Self {
        Counted(PhantomData)
    }
}

impl<K: Kernel> Kernel for Counted<K> {
    const NAME: &'static str = K::NAME;
    const EXACT_DECISIONS: bool = K::EXACT_DECISIONS;
    const FILTERED: bool = K::FILTERED;
    type Guide = Counted<K::Guide>;

    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(p: &P, x: &[f64; N]) -> Sign {
        bump(|c| c.sign += 1);
        K::sign(p, x)
    }
    fn note_decided_at_sites() {
        bump(|c| c.sign += 1);
    }
    fn orient(a: DVec2, b: DVec2, c: DVec2) -> Orientation {
        bump(|k| k.orient += 1);
        K::orient(a, b, c)
    }
    fn dot_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        bump(|k| k.dot += 1);
        K::dot_sign(a, b, c, d)
    }
    fn cross_sign(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Sign {
        bump(|k| k.cross += 1);
        K::cross_sign(a, b, c, d)
    }
    fn cmp_dist(p: DVec2, a: DVec2, b: DVec2) -> Ordering {
        bump(|k| k.cmp_dist += 1);
        K::cmp_dist(p, a, b)
    }
    fn cmp_dist4(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Ordering {
        bump(|k| k.cmp_dist4 += 1);
        K::cmp_dist4(a, b, c, d)
    }
    fn cmp_dist2(x: Dist2, y: Dist2) -> Ordering {
        bump(|k| k.cmp_dist2 += 1);
        K::cmp_dist2(x, y)
    }
}
