//! Temporal coherence: a [`Hint`] carries the internal feature pair of the last answer, and
//! [`distance_with_hint`] first walks locally from it, certifying with Theorem 1, before searching.
//!
//! Identity with [`distance_with`](crate::distance_with): a certified canonical pair that is not
//! `parallel` is the only optimal canonical pair (for disjoint convex polygons the closest points are
//! unique unless both support faces are edges), so the walk and the search finish the same pair with
//! the same construction. A walk ending at a `parallel` pair is discarded: the search decides which of
//! the optimal pairs to report. The fallback ([`solve`]) is the plain query's own code (`yang::solve_yang`),
//! returning the pair as well.

use glam::DVec2;
use polydist_polygon::predicates::Kernel;
use polydist_polygon::{ConvexPolygon, Feature};

use crate::brute::brute_pair;
use crate::linear::{LINEAR_BELOW, SUPPORT_BELOW, certified_support, certified_walk};
use crate::meet::{Contact, classify, separation};
use crate::pair::{Pair, canonical, certify, finish, finish_with, nearer};
use crate::result::{Closest, Separation, bump};
use crate::yang::{SCAN_BELOW, solve_yang};

/// At most this many steps of the local walk before [`distance_with_hint`] falls back to the search.
pub(crate) const WALK_STEPS: usize = 8;

/// The internal feature pair of a previous answer, for [`distance_with_hint`].
///
/// It holds internal vertex indices (positions in [`ConvexPolygon::vertices`]), not the caller's.
/// A hint is only a starting point: any hint (also one from other polygons) gives the same answer,
/// only the running time changes. `Hint::default()` is the empty hint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hint {
    pair: Option<Pair>,
}

impl Hint {
    /// The recorded pair as internal features `(of P, of Q)`: a vertex–vertex or vertex–edge pair
    /// (internal edge `e` joins internal vertices `e` and `e + 1`), or `None` for the empty hint (after
    /// touching or overlapping polygons).
    ///
    /// # Complexity
    /// `O(1)`.
    ///
    /// # Examples
    /// ```
    /// use polydist_convex::Hint;
    ///
    /// assert_eq!(Hint::default().internal_pair(), None);
    /// ```
    #[must_use]
    pub fn internal_pair(&self) -> Option<(Feature, Feature)> {
        self.pair.map(|pair| match pair {
            Pair::Vv(i, j) => (Feature::Vertex(i), Feature::Vertex(j)),
            Pair::Ve(i, j) => (Feature::Vertex(i), Feature::Edge(j)),
            Pair::Ev(i, j) => (Feature::Edge(i), Feature::Vertex(j)),
        })
    }
}

/// The answer of [`distance_with`](crate::distance_with), with the certified canonical pair (internal
/// indices) when the polygons are disjoint.
pub(crate) enum Solved {
    /// Disjoint: the finished pair and the pair itself.
    Disjoint(Closest, Pair),
    /// Touching or overlapping.
    Meeting(Separation),
}

impl Solved {
    /// The answer from a contact status and a pair-finder called only when disjoint.
    pub(crate) fn from_meet<K: Kernel>(
        pp: &ConvexPolygon,
        qq: &ConvexPolygon,
        meet: Contact,
        pair: impl FnOnce() -> Pair,
    ) -> Solved {
        match meet {
            Contact::Disjoint => {
                let pair = pair();
                Solved::Disjoint(finish::<K>(pp, qq, pair), pair)
            }
            other => Solved::Meeting(separation(other, || {
                finish::<K>(pp, qq, brute_pair::<K>(pp, qq))
            })),
        }
    }

    /// The public answer.
    pub(crate) fn separation(&self) -> Separation {
        match self {
            Solved::Disjoint(c, _) => Separation::Disjoint(*c),
            Solved::Meeting(s) => *s,
        }
    }
}

/// [`distance_with`](crate::distance_with)'s code, also returning the pair: the scan below
/// [`SCAN_BELOW`]; for two polygons with `n + m <` `SUPPORT_BELOW`, the certified pair of the support
/// guess or else (`n + m <` `LINEAR_BELOW`) of the linear walk, when it is not `parallel`; else
/// `solve_yang`, shared with `distance_yang_with` (candidate, certificate, reseeds, contact test,
/// Schwartz, brute force, with the same statistics).
pub(crate) fn solve<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Solved {
    let (n, m) = (pp.len(), qq.len());
    if n * m < SCAN_BELOW {
        let meet = classify::<K>(pp, qq, false);
        return Solved::from_meet::<K>(pp, qq, meet, || brute_pair::<K>(pp, qq));
    }
    if n >= 3 && m >= 3 && n + m < SUPPORT_BELOW {
        let (p, q) = (pp.vertices(), qq.vertices());
        let walk = || {
            if n + m < LINEAR_BELOW {
                certified_walk::<K>(p, q)
            } else {
                None
            }
        };
        // A `parallel` pair is left to the search (which decides which optimal pair to report).
        if let Some((pair, false)) = certified_support::<K>(p, q).or_else(walk) {
            bump(|s| s.linear_walks += 1);
            return Solved::Disjoint(finish_with::<K>(pp, qq, pair, false), pair);
        }
    }
    solve_yang::<K>(pp, qq)
}

/// `pair` with its indices reduced into range (a hint may come from other polygons).
fn reduce(pair: Pair, n: usize, m: usize) -> Pair {
    match pair {
        Pair::Vv(i, j) => Pair::Vv(i % n, j % m),
        Pair::Ve(i, j) => Pair::Ve(i % n, j % m),
        Pair::Ev(i, j) => Pair::Ev(i % n, j % m),
    }
}

/// The neighbouring pairs of `pair`: one index moved by one, or a vertex replaced by an incident edge.
fn neighbours(pair: Pair, n: usize, m: usize) -> [Pair; 8] {
    let up_p = |i: usize| (i + 1) % n;
    let down_p = |i: usize| (i + n - 1) % n;
    let up_q = |j: usize| (j + 1) % m;
    let down_q = |j: usize| (j + m - 1) % m;
    match pair {
        Pair::Vv(i, j) => [
            Pair::Vv(up_p(i), j),
            Pair::Vv(down_p(i), j),
            Pair::Vv(i, up_q(j)),
            Pair::Vv(i, down_q(j)),
            Pair::Ve(i, j),
            Pair::Ve(i, down_q(j)),
            Pair::Ev(i, j),
            Pair::Ev(down_p(i), j),
        ],
        Pair::Ve(i, j) => [
            Pair::Ve(up_p(i), j),
            Pair::Ve(down_p(i), j),
            Pair::Ve(i, up_q(j)),
            Pair::Ve(i, down_q(j)),
            Pair::Ev(i, j),
            Pair::Ev(down_p(i), j),
            Pair::Ev(i, up_q(j)),
            Pair::Ev(down_p(i), up_q(j)),
        ],
        Pair::Ev(i, j) => [
            Pair::Ev(i, up_q(j)),
            Pair::Ev(i, down_q(j)),
            Pair::Ev(up_p(i), j),
            Pair::Ev(down_p(i), j),
            Pair::Ve(i, j),
            Pair::Ve(i, down_q(j)),
            Pair::Ve(up_p(i), j),
            Pair::Ve(up_p(i), down_q(j)),
        ],
    }
}

/// The local walk: from the hinted pair, certify (Theorem 1) or move to the exactly nearest
/// neighbouring pair when it is strictly nearer; at most [`WALK_STEPS`] moves. `Some` only for a
/// certified canonical pair.
fn walk<K: Kernel>(p: &[DVec2], q: &[DVec2], start: Pair) -> Option<Pair> {
    let (n, m) = (p.len(), q.len());
    let mut pair = reduce(start, n, m);
    for step in 0..=WALK_STEPS {
        let c = canonical::<K>(p, q, pair);
        if certify::<K>(p, q, c) {
            return Some(c);
        }
        if step == WALK_STEPS {
            break;
        }
        // `nearer` keeps its first argument on ties: only a strictly nearer pair moves the walk, so
        // the squared distance decreases strictly and no pair repeats.
        let best = neighbours(pair, n, m)
            .into_iter()
            .fold(pair, |best, x| nearer::<K>(p, q, best, x));
        if best == pair {
            return None;
        }
        pair = best;
    }
    None
}

/// [`solve`] preceded by the hinted walk (polygons with area only).
pub(crate) fn solve_with_hint<K: Kernel>(
    pp: &ConvexPolygon,
    qq: &ConvexPolygon,
    hint: Option<Hint>,
) -> Solved {
    if let Some(start) = hint.and_then(|h| h.pair) {
        if pp.len() >= 3 && qq.len() >= 3 {
            if let Some(pair) = walk::<K>(pp.vertices(), qq.vertices(), start) {
                let closest = finish::<K>(pp, qq, pair);
                if !closest.parallel {
                    return Solved::Disjoint(closest, pair);
                }
            }
        }
    }
    solve::<K>(pp, qq)
}

/// [`distance_with`](crate::distance_with) with a hint from a previous query (temporal coherence):
/// returns the answer and the hint for the next query.
///
/// With a hint and two polygons with area, a local walk starts at the hinted pair: at each of at most
/// 8 steps it certifies the current pair by Theorem 1 (`O(1)` exact tests, the same certificate the
/// search uses) or moves to the neighbouring vertex–vertex or vertex–edge pair that is strictly nearer
/// by the kernel's exact comparisons. A certified pair whose support faces are not both edges is the
/// unique optimal canonical pair, so it is the answer. Otherwise (no certificate within the cap, a
/// local minimum that is not certified, a `parallel` pair, meeting polygons, points and segments) the
/// call runs the normal search.
///
/// Under the Robust and Exact kernels the answer is **identical** to
/// [`distance_with`](crate::distance_with)`::<K>(p, q)` (same [`Separation`], features, numbers),
/// whatever the hint. Under an inexact kernel it is a valid answer of that kernel but may differ.
///
/// The returned hint records the answer's internal pair when disjoint, and is empty otherwise.
///
/// # Complexity
/// `O(1)` exact predicates when the hinted pair is within a few steps of the answer (small motions
/// between frames); otherwise `O(1)` more than [`distance_with`](crate::distance_with):
/// `O(log n + log m)` for disjoint polygons.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_with, distance_with_hint, polygon::ConvexPolygon};
/// use polydist_convex::polygon::predicates::Robust;
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(1.0, 2.0)])?;
/// let mut hint = None;
/// for frame in 0..3 {
///     let x = 4.0 + 0.25 * f64::from(frame);
///     let q = ConvexPolygon::try_new(&[DVec2::new(x, 0.0), DVec2::new(x + 2.0, 0.0), DVec2::new(x + 1.0, 2.0)])?;
///     let (answer, next) = distance_with_hint::<Robust>(&p, &q, hint);
///     assert_eq!(answer, distance_with::<Robust>(&p, &q));
///     hint = Some(next);
/// }
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
#[must_use]
pub fn distance_with_hint<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    hint: Option<Hint>,
) -> (Separation, Hint) {
    let solved = solve_with_hint::<K>(p, q, hint);
    let next = match solved {
        Solved::Disjoint(_, pair) => Hint { pair: Some(pair) },
        Solved::Meeting(_) => Hint::default(),
    };
    (solved.separation(), next)
}
