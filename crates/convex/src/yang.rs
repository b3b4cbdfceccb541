//! Yang et al. (2006) rebuilt for exact predicates: the `O(log m + log n)` search for a closest pair of
//! two disjoint convex polygons, certified by Theorem 1.
//!
//! Paper: C.-L. Yang, M. Qi, X.-X. Meng, X.-Q. Li, J.-Y. Wang, J. Zhejiang Univ. SCIENCE A 7(9), 2006:
//! sections "Analysis of location relations" (Table 1, Theorems 1–4) and "Find initial searching ranges".
//!
//! What we changed and why (details in `docs/algorithms/convex-distance.md`):
//! - Table 1 is used in its weak reading (the midpoint is kept: the strict reading is false, and its
//!   Inner column omits `Q_m`), with strictly interior midpoints.
//! - Once a range is a single vertex or edge, a one-sided step (Lemma A of the design notes) shrinks the
//!   other range; the loop is bounded by `⌈log₂n⌉ + ⌈log₂m⌉ + 4` whatever the predicates answer.
//! - The paper's initial-range steps 3–5 are unproved; we replace them by a proved bracket
//!   (`bracket.rs`): one exact test tells on which side of `ν₀ = q_0 − p_0` the optimal direction `u`
//!   lies, and the ranges are the chains whose edge normals lie in that quarter-turn. They hold the
//!   support faces and lie inside the facing chains, the precondition of the proved main loop, so under
//!   an exact kernel the answer is always optimal.
//! - The Theorem-1 certificate (`O(1)` exact tests) stays as a safety net: under Robust and Exact it
//!   fails only when the polygons meet; then the `O(log)` exact contact test
//!   ([`contact_with`]) classifies them. Under an inexact kernel a failed
//!   certificate is followed by reseeded searches; a disjoint pair on which they all failed goes to
//!   Schwartz's `O(log² N)` search, and only an answer that fails the certificate there too to the
//!   brute force (these fallbacks never run under Robust or Exact on disjoint input: tested).
//!
//! Running time: `O(log n + log m)` exact predicates on every input (proved: docs, "The proved
//! bracket"), disjoint or meeting.

use core::any::TypeId;

use glam::DVec2;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Robust, Sign};

use crate::bracket::{Bracket, bracket};
use crate::brute::brute_pair;
use crate::contact::contact_with;
use crate::extreme::{Nearest, extreme_left_of, extreme_right_of, nearest_feature};
use crate::hint::Solved;
use crate::pair::{Pair, at, canonical, certify, finish, nearer, prev};
use crate::result::{Separation, bump};
use crate::schwartz::closest_candidate;

/// Below this product `n·m` of vertex counts, [`distance_with`] scans all pairs instead of searching.
///
/// Measured (`benches/benches/convex.rs`, group `convex/crossover`: `distance_brute::<Robust>` against
/// `distance_yang_with::<Robust>`, `n = m = 3 … 32`, 16 random disjoint pairs per size; 2-core machine,
/// noisy, medians of 10 samples): the search won at every size, by 1.6× at `n = m = 3` (≈ 10.0 µs
/// against 6.3 µs per query), 2.8× at 8 (14.7 against 5.4 µs), 5.7× at 16, 14× at 32. So the scan is
/// kept only below the smallest measured product, 9: a point or a segment against a polygon of at most
/// 4 vertices (unmeasured; `distance_yang_with` handles those sizes too). The earlier guess from the
/// predicate counts was 64.
pub const SCAN_BELOW: usize = 9;

/// How many reseeded searches follow a failed certificate under an inexact kernel (under an exact one
/// the search is proved, so a failure means the polygons meet).
pub(crate) const RESEEDS: usize = 2;

/// The search again (two polygons with area), seeded by the vertices of `pair`: `ν₀ = q_j − p_i`
/// (any `p ∈ P`, `q ∈ Q` is a valid seed). Returns the raw candidate.
pub(crate) fn reseed<K: Kernel>(p: &[DVec2], q: &[DVec2], pair: Pair) -> Pair {
    let (Pair::Vv(i, j) | Pair::Ve(i, j) | Pair::Ev(i, j)) = pair;
    search::<K>(p, q, bracket::<K>(p, q, at(p, i), at(q, j))).0
}

/// `⌈log₂ x⌉` for `x ≥ 1`.
fn ceil_log2(x: usize) -> u32 {
    if x <= 1 {
        0
    } else {
        usize::BITS - (x - 1).leading_zeros()
    }
}

/// `sign(a)·sign(b)`.
fn mul(a: Sign, b: Sign) -> Sign {
    match (a, b) {
        (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
        _ if a == b => Sign::Positive,
        _ => Sign::Negative,
    }
}

/// Where a point lies relative to the Voronoi region of a vertex (Table 1's rows and columns).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    /// Right of `VE_1`: `sign((v_b − v_{b−1})·(x − v_b)) < 0`.
    Right,
    /// In the closed region.
    Inner,
    /// Left of `VE_2`: `sign((v_{b+1} − v_b)·(x − v_b)) > 0` (and not right).
    Left,
}

/// The side of the point `x` relative to `VOR(v_b)`. "Both" (only behind the facing chain) maps to Right.
fn side_of_point<K: Kernel>(v: &[DVec2], b: usize, x: DVec2) -> Side {
    let vb = at(v, b);
    if K::dot_sign(prev(v, b), vb, vb, x) == Sign::Negative {
        Side::Right
    } else if K::dot_sign(vb, at(v, b + 1), vb, x) == Sign::Positive {
        Side::Left
    } else {
        Side::Inner
    }
}

/// The nearest point of the range piece `S` of ring `s` (vertex `lo`, or edge `lo` when `hi = lo + 1`)
/// to vertex `b` of ring `v`, and the side of that point relative to `VOR(v_b)`.
/// `found` is the piece of `S` holding the point: `(index, is_edge)`.
fn lemma_a<K: Kernel>(
    s: &[DVec2],
    lo: usize,
    hi: usize,
    v: &[DVec2],
    b: usize,
) -> (Side, (usize, bool)) {
    let vb = at(v, b);
    if hi == lo {
        return (side_of_point::<K>(v, b, at(s, lo)), (lo, false));
    }
    let (a0, a1) = (at(s, lo), at(s, lo + 1));
    if K::dot_sign(a0, vb, a0, a1) != Sign::Positive {
        return (side_of_point::<K>(v, b, a0), (lo, false));
    }
    if K::dot_sign(a1, vb, a1, a0) != Sign::Positive {
        return (side_of_point::<K>(v, b, a1), (lo + 1, false));
    }
    // The foot f = v_b − (c/L)·rot90(a1 − a0), c = orient(a0, a1, v_b): for any vector y,
    // sign(y·(f − v_b)) = −sign(c)·sign((a1 − a0) × y). Degree-2 signs only.
    let minus_c = K::orient(a0, a1, vb).sign().reversed();
    let side = if mul(minus_c, K::cross_sign(a0, a1, prev(v, b), vb)) == Sign::Negative {
        Side::Right
    } else if mul(minus_c, K::cross_sign(a0, a1, vb, at(v, b + 1))) == Sign::Positive {
        Side::Left
    } else {
        Side::Inner
    };
    (side, (lo, true))
}

/// Which part of a range a Table-1 cell keeps (the midpoint is always kept).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Keep {
    /// `[lo, mid]`: the range start up to the midpoint ("P_u" for `P`, "Q_d" for `Q`).
    Lower,
    /// `[mid, hi]` ("P_d" for `P`, "Q_u" for `Q`).
    Upper,
}

/// A Table-1 cell: the updates of both ranges, or `found` (cell (Inner, Inner)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Cell {
    p: Option<Keep>,
    q: Option<Keep>,
    found: bool,
}

/// Table 1 in its weak reading for the midpoints `p_a`, `q_b` (notes §2). Row: `q_b` vs `VOR(p_a)`;
/// column: `p_a` vs `VOR(q_b)`. Every cell but (Inner, Inner) shrinks at least one range.
fn table1<K: Kernel>(p: &[DVec2], q: &[DVec2], a: usize, b: usize) -> Cell {
    let (pa, qb) = (at(p, a), at(q, b));
    let row = side_of_point::<K>(p, a, qb);
    let col = side_of_point::<K>(q, b, pa);
    let cell = |p, q| Cell { p, q, found: false };
    use Keep::{Lower, Upper};
    match (row, col) {
        // Theorem 2 and cases 1.2, 2.1: P_u (or P_m), Q_u (or Q_m).
        (Side::Right, Side::Left) | (Side::Right, Side::Inner) | (Side::Inner, Side::Left) => {
            cell(Some(Lower), Some(Upper))
        }
        // Theorem 3: VE(p_a)_1 × VE(q_b)_1 ≥ 0 → P_u, else Q_d.
        (Side::Right, Side::Right) => {
            if K::cross_sign(prev(p, a), pa, prev(q, b), qb) != Sign::Negative {
                cell(Some(Lower), None)
            } else {
                cell(None, Some(Lower))
            }
        }
        // Theorem 1: an MDOP.
        (Side::Inner, Side::Inner) => Cell {
            p: None,
            q: None,
            found: true,
        },
        // Cases 2.3, 3.2, 3.3: P_d (or P_m), Q_d (or Q_m).
        (Side::Inner, Side::Right) | (Side::Left, Side::Inner) | (Side::Left, Side::Right) => {
            cell(Some(Upper), Some(Lower))
        }
        // Case 3.1: VE(q_b)_2 × VE(p_a)_2 > 0 → P_d, else Q_u.
        (Side::Left, Side::Left) => {
            if K::cross_sign(qb, at(q, b + 1), pa, at(p, a + 1)) == Sign::Positive {
                cell(Some(Upper), None)
            } else {
                cell(None, Some(Upper))
            }
        }
    }
}

/// The main search (notes §3) on the proved initial ranges `ranges` ([`bracket`], Lemma B2).
/// Returns a candidate pair (certified by the caller) and the iterations used.
pub(crate) fn search<K: Kernel>(p: &[DVec2], q: &[DVec2], ranges: Bracket) -> (Pair, u32) {
    let (n, m) = (p.len(), q.len());
    // Ranges (Lemma B2): every edge's normal is strictly within 90° of u (of −u for Q), so every
    // strictly interior vertex is interior to the facing chains P_1, Q_1, and the ranges hold the
    // support faces F_P(u), F_Q(−u): Table 1 and Lemma A apply at every midpoint.
    let (mut lp, mut hp) = ranges.p;
    let (mut lq, mut hq) = ranges.q;
    let bound = ceil_log2(n) + ceil_log2(m) + 4;
    let mut iterations = 0;
    // Each pass either returns or replaces a range of length L ≥ 2 by one of length ≤ ⌈L/2⌉ (the
    // midpoint is strictly interior): at most ⌈log₂n⌉ + ⌈log₂m⌉ + 2 passes whatever the signs say.
    while iterations < bound {
        iterations += 1;
        let (len_p, len_q) = (hp - lp, hq - lq);
        if len_p >= 2 && len_q >= 2 {
            let (a, b) = (lp + len_p / 2, lq + len_q / 2);
            let cell = table1::<K>(p, q, a, b);
            match cell.p {
                Some(Keep::Lower) => hp = a,
                Some(Keep::Upper) => lp = a,
                None => {}
            }
            match cell.q {
                Some(Keep::Lower) => hq = b,
                Some(Keep::Upper) => lq = b,
                None => {}
            }
            if cell.found {
                return (Pair::Vv(a % n, b % m), iterations);
            }
        } else if len_p <= 1 && len_q >= 2 {
            // Lemma A on Q: S = P's vertex or edge.
            let b = lq + len_q / 2;
            match lemma_a::<K>(p, lp, hp, q, b) {
                (Side::Left, _) => lq = b,
                (Side::Right, _) => hq = b,
                (Side::Inner, (i, false)) => return (Pair::Vv(i % n, b % m), iterations),
                (Side::Inner, (i, true)) => return (Pair::Ev(i % n, b % m), iterations),
            }
        } else if len_q <= 1 && len_p >= 2 {
            // Lemma A mirrored on P: S = Q's vertex or edge; right of VE(p_a)_1 → P_u, left of VE_2 → P_d.
            let a = lp + len_p / 2;
            match lemma_a::<K>(q, lq, hq, p, a) {
                (Side::Right, _) => hp = a,
                (Side::Left, _) => lp = a,
                (Side::Inner, (j, false)) => return (Pair::Vv(a % n, j % m), iterations),
                (Side::Inner, (j, true)) => return (Pair::Ve(a % n, j % m), iterations),
            }
        } else {
            break;
        }
    }
    // Both ranges are a vertex or an edge: brute force the ≤ 2×2 vertices against the ≤ 1×1 edges.
    let hp = hp.min(lp + 1);
    let hq = hq.min(lq + 1);
    let mut best = Pair::Vv(lp % n, lq % m);
    for i in lp..=hp {
        if hq > lq {
            best = nearer::<K>(p, q, best, Pair::Ve(i % n, lq % m));
        } else {
            best = nearer::<K>(p, q, best, Pair::Vv(i % n, lq % m));
        }
    }
    for j in lq..=hq {
        if hp > lp {
            best = nearer::<K>(p, q, best, Pair::Ev(lp % n, j % m));
        } else {
            best = nearer::<K>(p, q, best, Pair::Vv(lp % n, j % m));
        }
    }
    (best, iterations)
}

/// The pair of a point (vertex `i` of `P`) and its nearest feature of `Q`.
fn point_pair(i: usize, f: Nearest) -> Pair {
    match f {
        Nearest::Vertex(j) => Pair::Vv(i, j),
        Nearest::Edge(j) => Pair::Ve(i, j),
    }
}

/// Segment `s` against polygon `q` (`m ≥ 3`): the nearest features of both endpoints, and the extreme
/// vertices of `Q` on both sides of the segment's line against the segment. One of them realizes the
/// distance when disjoint. `None` when an endpoint is in `Q`.
fn segment_polygon<K: Kernel>(s: &[DVec2], q: &[DVec2]) -> Option<Pair> {
    let mut best = point_pair(0, nearest_feature::<K>(q, s[0])?);
    best = nearer::<K>(s, q, best, point_pair(1, nearest_feature::<K>(q, s[1])?));
    best = nearer::<K>(s, q, best, Pair::Ev(0, extreme_left_of::<K>(q, s[0], s[1])));
    best = nearer::<K>(
        s,
        q,
        best,
        Pair::Ev(0, extreme_right_of::<K>(q, s[0], s[1])),
    );
    Some(best)
}

/// The first candidate pair, or `None` when a seed point lies in the other polygon (they meet).
pub(crate) fn candidate<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Option<Pair> {
    let (p, q) = (pp.vertices(), qq.vertices());
    let (n, m) = (p.len(), q.len());
    let pair = match (n, m) {
        (1, 3..) => point_pair(0, nearest_feature::<K>(q, p[0])?),
        (3.., 1) => point_pair(0, nearest_feature::<K>(p, q[0])?).swapped(),
        (2, 3..) => segment_polygon::<K>(p, q)?,
        (3.., 2) => segment_polygon::<K>(q, p)?.swapped(),
        (3.., 3..) => {
            // The proved bracket (Lemma B2), seeded by ν₀ = q_0 − p_0: ⟨q − p, u⟩ > 0 for disjoint input.
            let (pair, iterations) = search::<K>(p, q, bracket::<K>(p, q, p[0], q[0]));
            bump(|s| {
                s.last_iterations = iterations;
                s.last_bound = ceil_log2(n) + ceil_log2(m) + 4;
            });
            pair
        }
        _ => brute_pair::<K>(pp, qq),
    };
    Some(canonical::<K>(p, q, pair))
}

/// The distance between two convex polygons by the `O(log m + log n)` search at every size (no scan
/// for small inputs): [`distance_with`] without its crossover, for tests and benchmarks.
///
/// The search (Yang et al. 2006 rebuilt with exact predicates, on a proved initial bracket: see the
/// crate docs) returns a candidate pair; Theorem 1 certifies it with `O(1)` exact tests. Under an exact
/// kernel the candidate of disjoint polygons is proved optimal, so the certificate fails only when the
/// polygons meet, and the exact `O(log)` contact test [`contact_with`] then
/// classifies them. Under an inexact kernel a failed certificate triggers up to two reseeded searches,
/// then the contact test; if that says disjoint, Schwartz's search answers
/// ([`distance_schwartz_with`](crate::distance_schwartz_with), certified the same way), and the brute
/// force only if that fails too. [`search_stats`](crate::search_stats) counts each event.
///
/// # Complexity
/// `O(log n + log m)` exact predicates under Robust and Exact, for every input (disjoint: four extreme
/// searches, five signs, at most `⌈log₂n⌉ + ⌈log₂m⌉ + 4` passes of the main loop and the certificate;
/// meeting: the same plus the contact test). Under an inexact kernel `O(log² (n + m))` when Schwartz's
/// search is needed and `O(nm)` only when it defeats both certified searches.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_yang_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let square = |x: f64| ConvexPolygon::try_new(&[
///     DVec2::new(x, 0.0), DVec2::new(x + 1.0, 0.0), DVec2::new(x + 1.0, 1.0), DVec2::new(x, 1.0),
/// ]);
/// let s = distance_yang_with::<Robust>(&square(0.0)?, &square(3.0)?);
/// let c = s.closest().expect("disjoint");
/// assert_eq!(c.distance, 2.0);
/// assert!(c.parallel);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// C.-L. Yang, M. Qi, X.-X. Meng, X.-Q. Li, J.-Y. Wang, "A new fast algorithm for computing the
/// distance between two disjoint convex polygons based on Voronoi diagram", J. Zhejiang Univ.
/// SCIENCE A 7(9), 2006. H. Edelsbrunner, "Computing the extreme distances between two convex
/// polygons", J. Algorithms 6, 1985.
#[must_use]
pub fn distance_yang_with<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Separation {
    solve_yang::<K>(pp, qq).separation()
}

/// [`distance_yang_with`], also returning the certified internal pair (for hints and `within`).
pub(crate) fn solve_yang<K: Kernel>(pp: &ConvexPolygon, qq: &ConvexPolygon) -> Solved {
    let (p, q) = (pp.vertices(), qq.vertices());
    bump(|s| s.calls += 1);
    // The search guided by `K::Guide` (plain f64 for the exact kernels) proposes; `K` certifies.
    let guided = candidate::<K::Guide>(pp, qq).map(|pair| canonical::<K>(p, q, pair));
    if let Some(pair) = guided {
        if certify::<K>(p, q, pair) {
            return Solved::Disjoint(finish::<K>(pp, qq, pair), pair);
        }
    }
    let first = if TypeId::of::<K>() == TypeId::of::<K::Guide>() {
        guided
    } else {
        // The guide was misled (near-degenerate input) or the polygons meet: the search under `K`.
        bump(|s| s.guide_failures += 1);
        let first = candidate::<K>(pp, qq);
        if let Some(pair) = first {
            if certify::<K>(p, q, pair) {
                return Solved::Disjoint(finish::<K>(pp, qq, pair), pair);
            }
        }
        first
    };
    bump(|s| s.certificate_failures += 1);
    // Under an exact kernel the search is proved (docs, "The proved bracket"): a failed certificate
    // means the polygons meet. Under an inexact one, search again seeded from the candidate's own
    // vertices (any p ∈ P, q ∈ Q give a valid ν₀), which may avoid the inconsistent signs.
    if let (Some(mut pair), true, true) = (first, !K::EXACT_DECISIONS, p.len() >= 3 && q.len() >= 3)
    {
        for _ in 0..RESEEDS {
            let again = canonical::<K>(p, q, reseed::<K>(p, q, pair));
            if certify::<K>(p, q, again) {
                bump(|s| s.repaired_by_retry += 1);
                return Solved::Disjoint(finish::<K>(pp, qq, again), again);
            }
            if again == pair {
                break;
            }
            pair = again;
        }
    }
    Solved::from_meet::<K>(pp, qq, contact_with::<K>(pp, qq), || {
        // Disjoint, yet both searches failed: Schwartz's search needs no initial ranges.
        if let Some(pair) = closest_candidate::<K>(p, q).filter(|&b| certify::<K>(p, q, b)) {
            bump(|s| s.schwartz_fallbacks += 1);
            return pair;
        }
        bump(|s| s.brute_fallbacks += 1);
        brute_pair::<K>(pp, qq)
    })
}

/// The distance between two convex polygons (points and segments included) and their closest pair,
/// or how they meet, deciding everything with the kernel `K`.
///
/// Tiny inputs (`n·m <` [`SCAN_BELOW`]) are scanned ([`distance_brute`](crate::distance_brute)). Two
/// small polygons (`n + m < 512`) first try a support guess (sampled supports refined while the pair
/// gets nearer, then a bounded local descent), and below `n + m < 64` a linear walk around the implicit
/// Minkowski difference, both in plain `f64`; a candidate pair must pass the exact Theorem-1
/// certificate (the guesses decide nothing; a `parallel` pair is left to the search, so the answer
/// never depends on the path). All other inputs use [`distance_yang_with`]. The answer is the same whichever path produced it. Under the Robust and Exact kernels the reported features
/// realize the distance exactly and the outcome is exact; the numbers obey the crate's error budget.
/// Under [`Fast`](polydist_polygon::predicates::Fast) the features may be wrong on near-degenerate
/// input, but the call terminates within the same bounds and never panics.
///
/// # Complexity
/// See [`distance_yang_with`]: `O(log n + log m)` for disjoint polygons.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{Separation, distance_with, polygon::ConvexPolygon, polygon::predicates::Exact};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(1.0, 3.0)])?;
/// assert!(matches!(distance_with::<Exact>(&p, &q), Separation::Touching { .. }));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`distance_yang_with`].
#[must_use]
pub fn distance_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Separation {
    crate::hint::solve::<K>(p, q).separation()
}

/// [`distance_with`] under the default [`Robust`] kernel: exact decisions, accurate numbers.
///
/// # Complexity
/// `O(log n + log m)` exact predicates for disjoint polygons (see [`distance_yang_with`]).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance, polygon::ConvexPolygon, polygon::Feature};
///
/// let p = ConvexPolygon::try_new(&[DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(7.0, 1.0)])?;
/// let c = *distance(&p, &q).closest().expect("disjoint");
/// assert_eq!(c.distance, 3.0);
/// assert_eq!(c.feature_p, Feature::Edge(1));
/// assert_eq!(c.point_p, DVec2::new(4.0, 1.0));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`distance_yang_with`].
#[must_use]
pub fn distance(p: &ConvexPolygon, q: &ConvexPolygon) -> Separation {
    distance_with::<Robust>(p, q)
}

/// The distance from the point `x` to a convex polygon, in `O(log n)`: [`distance_yang_with`] with `Q`
/// the point (its feature is `Vertex(0)`). Inside a polygon with area or in an open segment it is
/// [`Separation::Overlapping`]; on the boundary, [`Separation::Touching`].
///
/// # Errors
/// [`PolygonError`](polydist_polygon::PolygonError) when `x` is not finite or beyond the valid range.
///
/// # Complexity
/// `O(log n)` exact predicates (point location, two tangent searches, one binary search).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{distance_to_point, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let square = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y])?;
/// let s = distance_to_point::<Robust>(&square, DVec2::new(4.0, 5.0))?;
/// assert_eq!(s.distance(), 5.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`distance_yang_with`].
pub fn distance_to_point<K: Kernel>(
    polygon: &ConvexPolygon,
    x: DVec2,
) -> Result<Separation, polydist_polygon::PolygonError> {
    let point = ConvexPolygon::try_new(&[x])?;
    Ok(distance_yang_with::<K>(polygon, &point))
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::{
        Contact, Feature, SplitMix64, contact_status_convex, convex_distance,
        random_convex_lattice, rat,
    };
    use polydist_polygon::predicates::{BigRational, Exact};

    /// Exact rational point.
    fn r2(v: DVec2) -> (BigRational, BigRational) {
        (rat(v.x).expect("finite"), rat(v.y).expect("finite"))
    }

    /// The exact min vector `w = q* − p*` from one optimal feature pair of the oracle.
    fn min_vector(p: &[DVec2], q: &[DVec2], f: Feature, g: Feature) -> (BigRational, BigRational) {
        // The realizing points: a vertex, or the foot of the other side's vertex.
        let foot = |x: DVec2, a: DVec2, b: DVec2| {
            let ((xx, xy), (ax, ay), (bx, by)) = (r2(x), r2(a), r2(b));
            let (ex, ey) = (&bx - &ax, &by - &ay);
            let t = ((&xx - &ax) * &ex + (&xy - &ay) * &ey) / (&ex * &ex + &ey * &ey);
            (&ax + &t * &ex, &ay + &t * &ey)
        };
        let (ps, qs) = match (f, g) {
            (Feature::Vertex(i), Feature::Vertex(j)) => (r2(p[i]), r2(q[j])),
            (Feature::Vertex(i), Feature::Edge(j)) => {
                (r2(p[i]), foot(p[i], q[j], q[(j + 1) % q.len()]))
            }
            (Feature::Edge(i), Feature::Vertex(j)) => {
                (foot(q[j], p[i], p[(i + 1) % p.len()]), r2(q[j]))
            }
            (Feature::Edge(..), Feature::Edge(..)) => {
                unreachable!("the oracle lists vertex pairs too")
            }
        };
        (&qs.0 - &ps.0, &qs.1 - &ps.1)
    }

    /// `sign(w·d)` and `sign(w × d)` for the edge vector `d = b − a`.
    fn signs(
        w: &(BigRational, BigRational),
        a: DVec2,
        b: DVec2,
    ) -> (core::cmp::Ordering, core::cmp::Ordering) {
        let ((ax, ay), (bx, by)) = (r2(a), r2(b));
        let (dx, dy) = (&bx - &ax, &by - &ay);
        let zero = BigRational::from_integer(0.into());
        let dot = &w.0 * &dx + &w.1 * &dy;
        let cross = &w.0 * &dy - &w.1 * &dx;
        (dot.cmp(&zero), cross.cmp(&zero))
    }

    /// Notes §8: for random disjoint small-integer pairs (many ties), every pair of interior vertices of
    /// the facing chains `P_1`, `Q_1` gets a Table-1 cell whose updates keep the support faces.
    #[test]
    fn table1_cells_keep_the_faces() {
        use core::cmp::Ordering::{Greater, Less};
        let mut rng = SplitMix64::new(8);
        let (mut cells, mut found) = (0, 0);
        for round in 0..1500 {
            let p = random_convex_lattice(&mut rng, 3 + round % 7, 12);
            let mut q = random_convex_lattice(&mut rng, 3 + (round / 7) % 7, 12);
            let shift = DVec2::new(rng.range_i64(-30, 30) as f64, rng.range_i64(-30, 30) as f64);
            q.iter_mut().for_each(|v| *v += shift);
            if contact_status_convex(&p, &q) != Contact::Disjoint {
                continue;
            }
            let exact = convex_distance(&p, &q);
            let &(f, g) = exact
                .pairs
                .iter()
                .find(|(f, g)| !matches!((f, g), (Feature::Edge(_), Feature::Edge(_))))
                .expect("a pair");
            let w = min_vector(&p, &q, f, g);
            let (n, m) = (p.len(), q.len());
            let d = |v: &[DVec2], i: usize| (v[i % v.len()], v[(i + 1) % v.len()]);
            // Interior vertices of P_1: both incident edges go up along l_u (w × d > 0); of Q_1: down.
            let p_in: Vec<usize> = (0..n)
                .filter(|&i| {
                    let (a0, a1) = d(&p, i + n - 1);
                    let (b0, b1) = d(&p, i);
                    signs(&w, a0, a1).1 == Greater && signs(&w, b0, b1).1 == Greater
                })
                .collect();
            let q_in: Vec<usize> = (0..m)
                .filter(|&j| {
                    let (a0, a1) = d(&q, j + m - 1);
                    let (b0, b1) = d(&q, j);
                    signs(&w, a0, a1).1 == Less && signs(&w, b0, b1).1 == Less
                })
                .collect();
            for &a in &p_in {
                for &b in &q_in {
                    let cell = table1::<Exact>(&p, &q, a, b);
                    cells += 1;
                    // Safe updates (notes §1, strict: the whole face is kept): P keep-lower ⇔ θ_2 > 0 ⇔ w·d_a < 0;
                    // keep-upper ⇔ θ_1 < 0 ⇔ w·d_{a−1} > 0.
                    // Q (mirror, −u): keep-lower ⇔ w·d_b > 0; keep-upper ⇔ w·d_{b−1} < 0.
                    let (pa0, pa1) = d(&p, a);
                    let (pp0, pp1) = d(&p, a + n - 1);
                    let (qb0, qb1) = d(&q, b);
                    let (qp0, qp1) = d(&q, b + m - 1);
                    let ctx = || format!("p = {p:?}\nq = {q:?}\na = {a}, b = {b}, cell {cell:?}");
                    match cell.p {
                        Some(Keep::Lower) => assert!(signs(&w, pa0, pa1).0 == Less, "{}", ctx()),
                        Some(Keep::Upper) => assert!(signs(&w, pp0, pp1).0 == Greater, "{}", ctx()),
                        None => {}
                    }
                    match cell.q {
                        Some(Keep::Lower) => assert!(signs(&w, qb0, qb1).0 == Greater, "{}", ctx()),
                        Some(Keep::Upper) => assert!(signs(&w, qp0, qp1).0 == Less, "{}", ctx()),
                        None => {}
                    }
                    if cell.found {
                        found += 1;
                        assert!(
                            crate::pair::certify::<Exact>(&p, &q, Pair::Vv(a, b)),
                            "{}",
                            ctx()
                        );
                    } else {
                        assert!(cell.p.is_some() || cell.q.is_some(), "{}", ctx());
                    }
                }
            }
        }
        println!("{cells} cells checked, {found} MDOP cells");
        assert!(cells > 1000);
    }
}
