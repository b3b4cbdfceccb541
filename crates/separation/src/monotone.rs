//! The disjoint-hull route's first try: two boundaries whose facing chains are monotone along the
//! separating line, answered by an exact windowed sweep (`docs/algorithms/separation-polygons.md`,
//! "The monotone sweep").
//!
//! When `CH(P)` and `CH(Q)` are disjoint, a line `ℓ` through `a` and `b` separates the polygons.
//! Let `t(v) = (v − a)·(b − a)` be the position along `ℓ` and call *up* the side of `ℓ` where the
//! other polygon lies. The *facing chain* `F` of a polygon is its boundary path between its highest
//! vertex of least `t` and its highest vertex of greatest `t` that runs along the top: for a
//! counter-clockwise boundary, from greatest to least `t` when up is to the left of `a → b`, the
//! other way when it is to the right (the interior lies to the left of the direction of travel).
//!
//! **Why only the facing chains matter.** Suppose `F` is monotone (`t` never moves backwards along
//! it). `F` then crosses the strip `t(P)` from side to side, so it cuts the strip in two, and the rest
//! `B` of the boundary, which joins `F`'s ends without meeting `F` elsewhere, lies on one side of it.
//! Interior points lie just below `F` (left of travel), and `B` bounds the interior, so it lies below
//! `F`. A point `x` of `B` thus has a point `f` of `F` straight above it, at the same `t` and no lower.
//! Every point `y` of the other polygon lies on the far side of `ℓ`, so no lower than `f` in the up
//! direction, and `|f − y| ≤ |x − y|`. Hence `σ(P, Q) = σ(F_P, F_Q)`.
//!
//! **The sweep.** With both facing chains in order of `t`, a pair of points can only beat the best
//! candidate `U` found so far if their `t` differ by at most `U·|b − a|`; [`scan_windowed`] tries
//! each vertex against the other chain's vertices and edges in that window only, with the exact
//! comparisons of the scans (`f64` bounds first, the kernel on overlap). Inside the window, the
//! depth `d(v) = (v − a)×(b − a)` across the line thins the candidates: `|x − y|²·|b − a|² =
//! Δt² + Δd²` (Lagrange's identity), so blocks of the other chain, and then single candidates,
//! whose keys are too far apart in `t` and `d` together are skipped ([`Lens`]). The keys are `f64`
//! approximations with a proven error bound ([`keys`]); every test is widened by it, so nothing a
//! skipped pair could win is lost.
//!
//! **Linear, or section 3.** The sweep gives up when its work exceeds
//! `96·(|F_P| + |F_Q|) + 1024` candidates ([`budget`]; counted before any is tried: the blocks its
//! windows meet, then the candidates of the blocks not skipped; inputs whose candidates are nearly
//! all at the clearance), and when a facing chain is not monotone: section 3 then answers, so the
//! route stays `O(N)`. On saw-teeth facing each other the windows hold about three and a half
//! candidates a vertex; on walls sampled far more finely than their clearance, a few.

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Orientation, Sign};
use polydist_polygon::{Feature, SimplePolygon};

use std::borrow::Cow;

use crate::brute::{Carried, Keys, Winner, scan_windowed};
use crate::chain::{Frames, Prepared};
use crate::result::ClosestPair;
use crate::sigma::Cand;

/// The monotone sweep's answer: the pair, with internal features of `P` and `Q` (edge `e` joins
/// internal vertices `e` and `e + 1 mod n`), and the candidates tried.
pub(crate) struct Swept {
    pub(crate) pair: ClosestPair,
    pub(crate) tried: usize,
}

/// σ(P, Q) by the monotone sweep, for polygons on opposite closed sides of the line through `a`
/// and `b` (`a ≠ b`); `None` when a facing chain is not monotone along the line, when the keys
/// overflow, or when the budget runs out.
///
/// # Complexity
/// `O(N)`: `O(h)` exact degree-2 signs for the extreme vertices (sought among the `h` hull
/// vertices `hull_p`, `hull_q`: each polygon's hull, as internal indices), `O(N)` for the
/// monotonicity test and for the keys, and at most `96N + 1024` candidates ([`budget`]).
pub(crate) fn monotone_sweep<K: Kernel>(
    (p, hull_p): (&SimplePolygon, &[usize]),
    (q, hull_q): (&SimplePolygon, &[usize]),
    a: DVec2,
    b: DVec2,
) -> Option<Swept> {
    let (vp, vq) = (p.vertices(), q.vertices());
    let q_left = left_of::<K>(vq, a, b)?;
    let ip = facing::<K>(vp, Some(hull_p), a, b, q_left)?;
    let iq = facing::<K>(vq, Some(hull_q), a, b, !q_left)?;
    sweep::<K>((vp, &ip, vp.len()), (vq, &iq, vq.len()), a, b)
}

/// [`monotone_sweep`] for an open polyline `t` (no repeated consecutive vertices; edge `i` joins
/// vertices `i` and `i + 1`) against the polygon `q`, on opposite closed sides of the line through
/// `a` and `b`. An open chain bounds no interior, so the whole of `t` must be monotone along the
/// line (either way); `q` contributes its facing chain. `None` when either is not monotone, when
/// `t` repeats a vertex, or as [`monotone_sweep`].
pub(crate) fn monotone_sweep_polyline<K: Kernel>(
    t: &[DVec2],
    q: &SimplePolygon,
    a: DVec2,
    b: DVec2,
) -> Option<Swept> {
    let vq = q.vertices();
    let q_left = left_of::<K>(vq, a, b)?;
    let iq = facing::<K>(vq, None, a, b, !q_left)?;
    if t.len() < 2 || t.windows(2).any(|w| w[0] == w[1]) {
        return None;
    }
    let it: Vec<usize> = if backwards::<K>(t, a, b)? {
        (0..t.len()).rev().collect()
    } else {
        (0..t.len()).collect()
    };
    // No ring: an index past the end never wraps, so edge `k` is named by its lower end.
    sweep::<K>((t, &it, t.len() + 1), (vq, &iq, vq.len()), a, b)
}

/// The sweep's budget for `n` vertices in all: `96n + 1024` candidates. A candidate costs a few
/// dozen instructions (its `f64` bounds, rarely an exact sign), section 3 some 17,000 to 20,000 a
/// vertex on the inputs measured, so even a sweep that runs out first wastes a small share; and
/// crowded windows are found before any candidate is tried ([`scan_windowed`]). Box tests of
/// blocks are not candidates: the coarse blocks the windows meet are held to the same budget (each
/// costs at most nine box tests), or, when they exceed it, the box tests themselves, counted with
/// the candidates.
pub(crate) fn budget(n: usize) -> usize {
    96 * n + 1024
}

/// The windowed scan of two chains (edge `i` joins vertices `i` and `i + 1`) that are each
/// monotone along the line through `a` and `b`, either way: the separator's subproblems hand their
/// section-3 parts here first. No side of the line is needed: `|x − y| ≥ |t(x) − t(y)|/|b − a|`
/// holds for any two points, and the window rests on that alone. Candidates bounded above `cut`
/// are skipped ([`scan_windowed`]'s contract). `None` when a chain is not monotone, when the keys
/// overflow or when the [`budget`] runs out.
///
/// # Complexity
/// `O(n_p + n_q)`: one dot sign per edge, the keys, at most the budget's candidates.
pub(crate) fn sweep_chains<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
    cut: f64,
) -> Option<Winner> {
    if p.is_empty() || q.is_empty() {
        return None;
    }
    let (rp, rq) = (backwards::<K>(p, a, b)?, backwards::<K>(q, a, b)?);
    fn read(c: &[DVec2], back: bool) -> Cow<'_, [DVec2]> {
        if back {
            Cow::Owned(c.iter().rev().copied().collect())
        } else {
            Cow::Borrowed(c)
        }
    }
    let (fp, fq) = (read(p, rp), read(q, rq));
    let (winner, _) = keyed::<K>(&fp, &fq, a, b, cut)?;
    Some(winner.reversed(rp.then_some(p.len()), rq.then_some(q.len())))
}

/// Section 3's first try (our addition): [`scan_windowed`] on the two envelopes of Lemma 2, which
/// are monotone along the line whatever the chains are (docs/algorithms/separation.md, "The
/// envelope sweep"). `pp` and `qq` are the envelopes of chains `P` and `Q` in `frames` (visible
/// vertices strictly increasing in height, the edge carrying the envelope between each two); the
/// answer is a candidate of section 3 in the caller's features, and the candidates tried.
///
/// Why it is exact. A point of `P` with a point of `P` at its height strictly nearer to the line
/// is in no closest pair (Lemma 2's dominance), so some closest pair `(x, y)` has both points on
/// the envelopes, and one of them a visible vertex (a closest pair of two sets of segments has a
/// point at an end of one; the other ends of envelope pieces, shadow points and ends hidden at a
/// visible vertex's height, are dominated). Say `x` is a visible vertex and `y` lies on the
/// envelope part of edge `e`. The scan evaluates `x` against the whole edge `e`: a pair of points
/// of the chains, no farther than `|x − y|`, so exactly `σ`; and every distance it evaluates is a
/// true one. Its window and its boxes skip an edge only when the edge's part on the envelope is
/// certainly farther than the best so far (its keys are its visible vertices', which bound that
/// part from the other chain's side: [`Carried`]), so the pair `(x, e)` is never skipped. With `interior_only`, a
/// whole edge whose nearest point to `x` is an end `z` is left to the vertex pair `(x, z)`: then
/// `|x − z| = σ`, so `z` is dominated by no point of `Q`, hence a visible vertex, in `x`'s window.
///
/// `None` when an envelope has gaps (clipped chains: their runs end at symbolic points, which the
/// keys cannot hold), when a key overflows, or when the [`budget`] runs out.
///
/// # Complexity
/// `O(n_p + n_q)`: the keys of the visible vertices, then at most `96(n_p + n_q) + 1024`
/// candidates.
pub(crate) fn sweep_envelopes<K: Kernel>(
    pp: &Prepared,
    qq: &Prepared,
    frames: Frames,
    cut: f64,
) -> Option<(Cand, usize)> {
    if pp.has_gaps() || qq.has_gaps() {
        return None;
    }
    let (a, b) = (frames.p.l0, frames.p.l1);
    let (kp, kq, lens) = keys(&pp.pts, &qq.pts, a, b)?;
    let (cp, cq) = (
        Carried {
            v: &pp.pts,
            e: &pp.segs,
        },
        Carried {
            v: &qq.pts,
            e: &qq.segs,
        },
    );
    let n = pp.pts.len() + qq.pts.len();
    let (w, tried) = scan_windowed::<K, Carried<'_>>(
        &cp,
        &cq,
        Keys { t: &kp.0, d: &kp.1 },
        Keys { t: &kq.0, d: &kq.1 },
        &lens,
        cut,
        budget(n),
    )
    .ok()?;
    // Visible vertex `i` of `x` against envelope edge `k` of `y` (`P`'s edge when `p_side`).
    let ve = |x: &Prepared, i: usize, y: &Prepared, k: usize, p_side: bool| {
        let e = y.env_edge(k)?;
        Some(Cand::on_edge(x.pts[i], x.idx[i], &e, p_side))
    };
    let cand = match w.features() {
        (Feature::Vertex(i), Feature::Vertex(j)) => {
            Cand::Vv(pp.pts[i], pp.idx[i], qq.pts[j], qq.idx[j])
        }
        (Feature::Vertex(i), Feature::Edge(k)) => ve(pp, i, qq, k, false)?,
        (Feature::Edge(k), Feature::Vertex(j)) => ve(qq, j, pp, k, true)?,
        // A scan's winner has a vertex; declining is safe anyway.
        (Feature::Edge(_), Feature::Edge(_)) => return None,
    };
    Some((cand, tried))
}

/// [`scan_windowed`] on two chains listed in non-decreasing order of `t` along the line through
/// `a` and `b`: their keys, the [`Lens`], the [`budget`]. The winner and the candidates tried.
fn keyed<K: Kernel>(
    fp: &[DVec2],
    fq: &[DVec2],
    a: DVec2,
    b: DVec2,
    cut: f64,
) -> Option<(Winner, usize)> {
    let (kp, kq, lens) = keys(fp, fq, a, b)?;
    let (kp, kq) = (Keys { t: &kp.0, d: &kp.1 }, Keys { t: &kq.0, d: &kq.1 });
    scan_windowed::<K, [DVec2]>(fp, fq, kp, kq, &lens, cut, budget(fp.len() + fq.len())).ok()
}

/// How the chain `c` runs along the line through `a` and `b`: `Some(false)` when `t` never
/// decreases, `Some(true)` when it never increases (and does somewhere), `None` when neither. One
/// exact dot sign per edge, twice at most.
fn backwards<K: Kernel>(c: &[DVec2], a: DVec2, b: DVec2) -> Option<bool> {
    let along = |s: Sign| c.windows(2).all(|w| K::dot_sign(w[0], w[1], a, b) != s);
    if along(Sign::Negative) {
        Some(false)
    } else if along(Sign::Positive) {
        Some(true)
    } else {
        None
    }
}

/// Whether the ring `v` lies left of `a → b` (the sign of a vertex off the line; a simple polygon
/// has one).
fn left_of<K: Kernel>(v: &[DVec2], a: DVec2, b: DVec2) -> Option<bool> {
    let o = v
        .iter()
        .map(|&x| K::orient(a, b, x))
        .find(|&o| o != Orientation::Collinear)?;
    Some(o == Orientation::CounterClockwise)
}

/// A chain for the sweep: the points, the indices of its vertices in non-decreasing order of `t`,
/// and the ring length that names its edges ([`internal`]).
type Listed<'a> = (&'a [DVec2], &'a [usize], usize);

/// The windowed scan of two listed chains, features mapped back to the points' indices.
fn sweep<K: Kernel>(
    (vp, ip, np): Listed<'_>,
    (vq, iq, nq): Listed<'_>,
    a: DVec2,
    b: DVec2,
) -> Option<Swept> {
    let fp: Vec<DVec2> = ip.iter().map(|&i| vp[i]).collect();
    let fq: Vec<DVec2> = iq.iter().map(|&i| vq[i]).collect();
    let (winner, tried) = keyed::<K>(&fp, &fq, a, b, f64::INFINITY)?;
    let mut pair = winner.pair();
    pair.feature_p = internal(pair.feature_p, ip, np);
    pair.feature_q = internal(pair.feature_q, iq, nq);
    Some(Swept { pair, tried })
}

/// The error analysis of the sweep's keys ([`keys`]): with `len = fl(|û|)`, `len2 = fl(|û|²)` and
/// the keys' error bound `slack = E`, the tests [`scan_windowed`] skips candidates by.
pub(crate) struct Lens {
    len: f64,
    len2: f64,
    slack: f64,
}

impl Lens {
    /// The window `W` for a best candidate whose squared distance is at most `u2`:
    /// `fl(t̂_y − t̂_x) > W` implies `|t(y) − t(x)| > U·|b − a|` for `U = √u2`, so the pair is
    /// farther apart than the best.
    ///
    /// Why. `W ≥ U·|b − a| + 2E` after every rounding: the computed `√u2·len` is within a few `u`
    /// of `U·|b − a|` (`û = fl(b − a)` is within `u` of `b − a` in each coordinate), far inside the
    /// relative `2⁻⁴⁰`; `4E` covers the two keys' errors (`2E`) and the rounding of their difference
    /// (at most `u` of it, which `fl(t̂_y − t̂_x) > W` keeps below the spare `2E` and the relative
    /// widening); `2⁻¹⁰⁰⁰` covers underflow. `∞` when `u2` is not finite.
    pub(crate) fn window(&self, u2: f64) -> f64 {
        let w = u2.sqrt() * self.len * (1.0 + WIDEN) + 4.0 * self.slack + TINY;
        if w.is_nan() { f64::INFINITY } else { w }
    }

    /// A lower bound of the exact gap between two intervals of exact keys, given intervals of their
    /// computed keys `x` and `y` (each end within `E` of its exact key): `fl(gap − 4E)`, or 0.
    ///
    /// Why. The exact gap is at least the computed ends' gap less `2E`. That gap's rounding is at
    /// most `u` of it, and every key is at most about `max(|p̂ₓ| + |p̂ᵧ|)` in magnitude while
    /// `E ≥ 8u` times that, so the rounding is below `E/3`, and so is the rounding of the
    /// subtraction of `4E`: the result is at most the exact gap less `E`.
    #[inline]
    pub(crate) fn gap(&self, x: (f64, f64), y: (f64, f64)) -> f64 {
        // A NaN difference yields the other one, or 0 below: never a gap that is not certain.
        let g = greater(y.0 - x.1, x.0 - y.1) - 4.0 * self.slack;
        if g > 0.0 { g } else { 0.0 }
    }

    /// Whether two sets of points whose exact keys are at least `gt` apart along the line and `gd`
    /// apart across it (lower bounds from [`Lens::gap`]) are certainly farther apart than `√u2`.
    ///
    /// Why. For points `x`, `y` and `u = b − a`, `|x − y|²·|u|² = ((y − x)·u)² + ((y − x)×u)²
    /// = Δt² + Δd²` (Lagrange's identity), so the squared distance of any two points of the sets is
    /// at least `(gt² + gd²)/|u|²`. The computed `gt² + gd²` is within `3u` of the exact one and
    /// `2⁻¹⁰⁷³` of underflow, `len2` within `4u` of `|u|²`; the relative `2⁻⁴⁰` and the absolute
    /// `2⁻¹⁰⁰⁰` cover both, so `fl(gt² + gd²)·(1 − 2⁻⁴⁰) > fl(u2·len2)·(1 + 2⁻⁴⁰) + 2⁻¹⁰⁰⁰` implies
    /// `gt² + gd² > u2·|u|²`. Never when `u2` is not finite.
    #[inline]
    pub(crate) fn beyond(&self, gt: f64, gd: f64, u2: f64) -> bool {
        (gt * gt + gd * gd) * (1.0 - WIDEN) > u2 * self.len2 * (1.0 + WIDEN) + TINY
    }

    /// Whether the points whose computed keys lie in the box `t × d` are certainly farther than
    /// `√u2` from the point with computed keys `x` ([`Lens::gap`] along and across, then
    /// [`Lens::beyond`]).
    #[inline]
    pub(crate) fn apart(&self, x: (f64, f64), t: (f64, f64), d: (f64, f64), u2: f64) -> bool {
        self.beyond(self.gap((x.0, x.0), t), self.gap((x.1, x.1), d), u2)
    }
}

/// A box of keys in a frame of its own (our addition to the sweep, `docs/algorithms/
/// separation-polygons.md`, "Chord frames"): for a block of consecutive vertices and edges of a
/// chain, the keys `s(v) = (v − o)·c` and `n(v) = (v − o)×c` of the points that bound it, in the
/// frame of its first vertex `o` and its chord `c` (to its last vertex). The line's frame boxes a
/// block tilted against the line loosely (by about its extent times the sine of the tilt); the
/// chord's frame follows the block, so a point beside a zigzag or an arc sees the block's near
/// side.
///
/// Why it bounds distances. `o` and `c` are stored `f64` values, so they are exact inputs: every
/// point `y` of the block's vertices and edges lies in the exact box of its bounding points (the
/// keys are affine), and for any point `x`, `|x − y|²·|c|² = Δs² + Δn²` (Lagrange's identity). The
/// computed keys `fl(fl(v − o)·c)` and `fl(fl(v − o)×c)` are within `4.01u·(|p̂ₓ| + |p̂ᵧ|)` of the
/// exact ones (as for [`keys`], with one rounding fewer), so [`Lens`]'s gap and threshold tests
/// hold with `E = 8u·max fl(|p̂ₓ| + |p̂ᵧ|) + 2⁻¹⁰⁰⁰`, the maximum taken over the bounding points
/// and the point tested, and `|c|²` in place of `|b − a|²`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Chord {
    o: DVec2,
    c: DVec2,
    s: (f64, f64),
    n: (f64, f64),
    worst: f64,
    len2: f64,
}

impl Chord {
    /// The computed keys of `v` in the frame, and the magnitude their error bound grows with.
    #[inline]
    fn key(o: DVec2, c: DVec2, v: DVec2) -> (f64, f64, f64) {
        let d = v - o;
        let (x, y) = (d.x * c.x, d.y * c.y);
        let (p, q) = (d.x * c.y, d.y * c.x);
        // A NaN magnitude comes with a NaN key, which no test takes as apart and `of` rejects, so
        // which of the two `greater` keeps does not matter.
        (x + y, p - q, greater(x.abs() + y.abs(), p.abs() + q.abs()))
    }

    /// The frame from `first` along the chord to `last`, boxing `points` (which must hold every
    /// vertex and the ends of every edge of the block). `None` when a key or `|c|²` is not finite.
    pub(crate) fn of(
        first: DVec2,
        last: DVec2,
        points: impl IntoIterator<Item = DVec2>,
    ) -> Option<Chord> {
        let c = last - first;
        let (mut s, mut n, mut worst, mut check) =
            ((0.0f64, 0.0f64), (0.0f64, 0.0f64), 0.0f64, 0.0f64);
        for v in points {
            let (a, b, w) = Chord::key(first, c, v);
            s = (lesser(s.0, a), greater(s.1, a));
            n = (lesser(n.0, b), greater(n.1, b));
            worst = greater(worst, w);
            // Non-finite (NaN or infinite) once any key is, or on overflow: checked below.
            check += a + b;
        }
        let len2 = c.x * c.x + c.y * c.y;
        let finite = [s.0, s.1, n.0, n.1, worst, len2, check]
            .iter()
            .all(|x| x.is_finite());
        finite.then_some(Chord {
            o: first,
            c,
            s,
            n,
            worst,
            len2,
        })
    }

    /// Whether every point of the block is certainly farther than `√u2` from `x` ([`Lens::apart`]
    /// in the chord's frame). Never when `|c| = 0` or a key of `x` is not finite.
    #[inline]
    pub(crate) fn apart(&self, x: DVec2, u2: f64) -> bool {
        let (s, n, w) = Chord::key(self.o, self.c, x);
        let lens = Lens {
            len: 0.0,
            len2: self.len2,
            slack: EIGHT_U * greater(self.worst, w) + TINY,
        };
        // A NaN key or slack makes every comparison false: never apart.
        lens.apart((s, n), self.s, self.n, u2)
    }
}

/// A squared distance `u2′` with `√u2′ ≥ √u2 + r`, for `r` the distance that `reach` was computed
/// for as `fl(|v − o|)`: a set farther than `√u2′` from a point `o` is farther than `√u2` from
/// every point within `r` of `o` (the triangle inequality).
///
/// Why. `fl(√u2)`, the sum and the product are each within `u` of their exact values, and
/// `reach` within `3u` of `r` unless the squares in it underflow, which loses less than
/// `2⁻⁵³⁶` of `r` (the squares' sum is off by at most `2⁻¹⁰⁷³`); the relative `2⁻⁴⁰` covers the
/// roundings, the absolute `2⁻⁵⁰⁰` the underflow (and keeps the square normal, so its rounding is
/// relative too). Infinite (never ruling anything out) when `u2` or `reach` is; NaN (neither)
/// when either is NaN.
pub(crate) fn reached(u2: f64, reach: f64) -> f64 {
    let g = (u2.sqrt() + reach) * (1.0 + WIDEN) + REACH_TINY;
    g * g
}

/// `2⁻⁵⁰⁰`: [`reached`]'s allowance for a reach whose squares underflowed.
const REACH_TINY: f64 = f64::from_bits((1023 - 500) << 52);

/// `max(x, y)` by one strict comparison, which compiles to the processor's `maxsd` (`f64::max`
/// also orders NaNs, a few instructions more in the box tests' hot loop): `y` when either is NaN,
/// so a NaN `y` is kept where `f64::max` drops it.
#[inline(always)]
fn greater(x: f64, y: f64) -> f64 {
    if x > y { x } else { y }
}

/// `min(x, y)` by one strict comparison (`minsd`): `y` when either is NaN.
#[inline(always)]
fn lesser(x: f64, y: f64) -> f64 {
    if x < y { x } else { y }
}

/// `2⁻⁴⁰`: the relative widening of the window, far above the few roundings of its computation.
const WIDEN: f64 = 1.0 / 1_099_511_627_776.0;
/// `2⁻¹⁰⁰⁰`, above any absolute error from underflow in the keys.
const TINY: f64 = f64::from_bits((1023 - 1000) << 52);
/// `2⁻⁵⁰ = 8u`.
const EIGHT_U: f64 = 1.0 / 1_125_899_906_842_624.0;

/// The facing chain of the counter-clockwise ring `v` (internal vertex indices, in non-decreasing
/// order of `t`), for the other polygon to the left of `a → b` when `other_left`; `None` when it is
/// not monotone. `O(n)` exact degree-2 signs (`O(h)` of them for the extremes with `hull`).
///
/// The chain runs between the two extremes of `t`, ties to the vertex nearest the other polygon.
/// With `hull`, the indices of the ring's convex hull vertices, they are sought among those only:
/// a linear function's extreme over the ring is attained on its hull, the ring's vertices at that
/// extreme lie on a supporting line, and the one nearest the other polygon among them is an end of
/// the hull's part of that line (the maximum of a linear function over a segment is at an end),
/// hence a hull vertex. The answer is the same, in `O(h)` tests instead of `O(n)`.
fn facing<K: Kernel>(
    v: &[DVec2],
    hull: Option<&[usize]>,
    a: DVec2,
    b: DVec2,
    other_left: bool,
) -> Option<Vec<usize>> {
    let n = v.len();
    if n < 3 {
        return None;
    }
    // `w` is nearer the other polygon than `v` (same `t`): its cross with `b − a` has the other's
    // side's sign.
    let toward = |from: DVec2, to: DVec2| {
        let s = K::cross_sign(a, b, from, to);
        if other_left {
            s == Sign::Positive
        } else {
            s == Sign::Negative
        }
    };
    // The extremes of `t`, ties to the vertex nearest the other polygon.
    let start = match hull {
        Some(h) => *h.iter().find(|&&k| k < n)?,
        None => 0,
    };
    let (mut lo, mut hi) = (start, start);
    let mut step = |k: usize| {
        match K::dot_sign(v[lo], v[k], a, b) {
            Sign::Negative => lo = k,
            Sign::Zero if toward(v[lo], v[k]) => lo = k,
            _ => {}
        }
        match K::dot_sign(v[hi], v[k], a, b) {
            Sign::Positive => hi = k,
            Sign::Zero if toward(v[hi], v[k]) => hi = k,
            _ => {}
        }
    };
    match hull {
        Some(h) => h.iter().copied().filter(|&k| k < n).for_each(&mut step),
        None => (0..n).for_each(&mut step),
    }
    if lo == hi {
        return None;
    }
    // Counter-clockwise from `hi` to `lo` (up to the left) or from `lo` to `hi` (up to the right),
    // listed in order of increasing `t`.
    let (from, to) = if other_left { (hi, lo) } else { (lo, hi) };
    let steps = (to + n - from) % n;
    let mut chain: Vec<usize> = (0..=steps).map(|s| (from + s) % n).collect();
    if other_left {
        chain.reverse();
    }
    chain
        .windows(2)
        .all(|w| K::dot_sign(v[w[0]], v[w[1]], a, b) != Sign::Negative)
        .then_some(chain)
}

/// The keys of both chains, `t̂(v) = fl(fl(v − a)·fl(b − a))` along the line and
/// `d̂(v) = fl(fl(v − a)×fl(b − a))` across it, and their [`Lens`], whose `E` bounds
/// `|t̂(v) − t(v)|` and `|d̂(v) − d(v)|` for every vertex; `None` when a key, `E`, `|û|` or `|û|²`
/// is not finite.
///
/// Why `E` holds. With `d̂ = fl(v − a)`, `û = fl(b − a)` and the products `p̂ₓ = fl(d̂ₓûₓ)`,
/// `p̂ᵧ = fl(d̂ᵧûᵧ)` (for `t`; `fl(d̂ₓûᵧ)` and `fl(d̂ᵧûₓ)` for `d`), each product is within
/// `(1 + u)³ − 1` relative of the exact one (three roundings), and the sum or difference adds
/// `u(|p̂ₓ| + |p̂ᵧ|)`. So the error is at most `4.01u·(|p̂ₓ| + |p̂ᵧ|)`, and
/// `E = 8u·max fl(|p̂ₓ| + |p̂ᵧ|) + 2⁻¹⁰⁰⁰` (the maximum over both keys of every vertex) is above it
/// (the sum's own rounding is inside the factor two; a product that underflows is off by at most
/// `2⁻¹⁰⁷⁴`).
pub(crate) type KeyPair = (Vec<f64>, Vec<f64>);
pub(crate) fn keys(
    fp: &[DVec2],
    fq: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Option<(KeyPair, KeyPair, Lens)> {
    let u = b - a;
    let mut worst = 0.0f64;
    let mut key = |v: &DVec2| {
        let d = *v - a;
        let (x, y) = (d.x * u.x, d.y * u.y);
        let (c, e) = (d.x * u.y, d.y * u.x);
        worst = worst.max(x.abs() + y.abs()).max(c.abs() + e.abs());
        (x + y, c - e)
    };
    let kp: KeyPair = fp.iter().map(&mut key).unzip();
    let kq: KeyPair = fq.iter().map(&mut key).unzip();
    let slack = EIGHT_U * worst + TINY;
    let len2 = u.x * u.x + u.y * u.y;
    let lens = Lens {
        len: len2.sqrt(),
        len2,
        slack,
    };
    let finite = [&kp.0, &kp.1, &kq.0, &kq.1]
        .iter()
        .all(|k| k.iter().all(|t| t.is_finite()));
    (finite && slack.is_finite() && len2.is_finite()).then_some((kp, kq, lens))
}

/// The internal feature of a facing chain's local feature: vertex `k` is `chain[k]`, edge `k` the
/// ring edge between `chain[k]` and `chain[k + 1]` (consecutive on the ring, either way round).
fn internal(f: Feature, chain: &[usize], n: usize) -> Feature {
    match f {
        Feature::Vertex(k) => Feature::Vertex(chain[k]),
        Feature::Edge(k) => {
            let (x, y) = (chain[k], chain[k + 1]);
            Feature::Edge(if (x + 1) % n == y { x } else { y })
        }
    }
}

#[cfg(test)]
mod tests {
    //! The keys' error bound and the window against exact rationals.
    use super::*;
    use crate::brute::feature_dist;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::exact::to_rational;

    /// Points of one scale class: unit square, lattice, huge, tiny, far from the origin, mixed.
    fn point(rng: &mut SplitMix64, class: usize) -> DVec2 {
        let u = |rng: &mut SplitMix64| rng.unit_f64() - 0.5;
        match class {
            0 => DVec2::new(u(rng), u(rng)),
            1 => DVec2::new(rng.range_i64(-8, 9) as f64, rng.range_i64(-8, 9) as f64) / 4.0,
            2 => DVec2::new(u(rng), u(rng)) * 1e150,
            3 => DVec2::new(u(rng), u(rng)) * 1e-280,
            4 => DVec2::new(1e12 + u(rng), 1e12 + u(rng)),
            _ => DVec2::new(u(rng) * 1e9, u(rng) * 1e-9),
        }
    }

    /// `facing` finds the same chain when it seeks the extremes among the hull's vertices only:
    /// lattice polygons (collinear vertices and ties in `t` everywhere: combs, saw-teeth, lattice
    /// stars) and random stars, against lattice lines in every direction, both sides.
    #[test]
    fn facing_seeks_the_extremes_on_the_hull_alone() {
        use polydist_oracle::{comb, hooked_sawtooth, sawtooth, star, star_in_range};
        use polydist_predicates::Robust;
        let mut rng = SplitMix64::new(0xfac1);
        let mut rings = vec![comb(7, 3, 2), sawtooth(9), hooked_sawtooth(6)];
        for _ in 0..12 {
            rings.push(star(&mut rng, 40, 7));
            rings.push(star_in_range(&mut rng, 16, 4, 3));
        }
        let (mut same, mut found) = (0, 0);
        for ring in &rings {
            let Ok(poly) = SimplePolygon::try_new(ring) else {
                continue;
            };
            let v = poly.vertices();
            let (_, hull) = poly.convex_hull_and_indices_with::<Robust>();
            for _ in 0..60 {
                let (a, d, _) = lattice_line(&mut rng);
                for side in [false, true] {
                    let all = facing::<Robust>(v, None, a, a + d, side);
                    let on_hull = facing::<Robust>(v, Some(&hull), a, a + d, side);
                    assert_eq!(all, on_hull, "{ring:?} {a} {d} {side}");
                    same += 1;
                    found += usize::from(all.is_some());
                }
            }
        }
        assert!(
            same > 2_000 && found > 100,
            "{same} cases, {found} monotone"
        );
    }

    /// A line through a lattice point `a` along a non-zero lattice direction `d` (coordinates
    /// within ±3), and `d` turned a quarter counter-clockwise.
    fn lattice_line(rng: &mut SplitMix64) -> (DVec2, DVec2, DVec2) {
        let d = loop {
            let d = DVec2::new(rng.range_i64(-3, 4) as f64, rng.range_i64(-3, 4) as f64);
            if d != DVec2::ZERO {
                break d;
            }
        };
        let a = DVec2::new(rng.range_i64(-9, 10) as f64, rng.range_i64(-9, 10) as f64);
        (a, d, DVec2::new(-d.y, d.x))
    }

    /// `sweep_chains` against the exact scan on random chains monotone along a random lattice
    /// direction (either way, vertical steps and ties included, the chains free to overlap and
    /// cross), with and without a cut: the scan's nearest pair exactly when it beats the cut, a
    /// pair no nearer otherwise; the features are the reversed chains' mapped back.
    #[test]
    fn sweep_chains_is_the_exact_scan() {
        use crate::brute::scan_winner_below;
        use polydist_predicates::{Dist2, Exact, Robust};
        use std::cmp::Ordering;
        let mut rng = SplitMix64::new(0x5ee9);
        let (mut swept, mut below) = (0, 0);
        for round in 0..3_000 {
            let (a, d, perp) = lattice_line(&mut rng);
            let float = round % 4 == 3;
            let chain = |rng: &mut SplitMix64, shift: f64| -> Vec<DVec2> {
                let k = 1 + rng.index(12);
                let mut t = rng.range_i64(-6, 0) as f64;
                let mut c: Vec<DVec2> = (0..k)
                    .map(|_| {
                        t += rng.below(3) as f64;
                        let h = if float {
                            rng.unit_f64() * 4.0 - 2.0
                        } else {
                            rng.range_i64(-8, 9) as f64 * 0.25
                        };
                        a + d * t + perp * (h + shift)
                    })
                    .collect();
                c.dedup();
                if rng.coin() {
                    c.reverse();
                }
                c
            };
            let p = chain(&mut rng, 0.0);
            let shift = [0.0, 1.0, 3.0, -2.5][rng.index(4)];
            let q = chain(&mut rng, shift);
            // A cut `c²` with `c` a multiple of 1/4 (exact), or none.
            let c = if rng.below(3) == 0 {
                rng.range_i64(1, 33) as f64 * 0.25
            } else {
                f64::INFINITY
            };
            let cut = c * c;
            let Some(w) = sweep_chains::<Robust>(&p, &q, a, a + d, cut) else {
                continue;
            };
            swept += 1;
            let dist = |f: (Feature, Feature)| feature_dist(&p, &q, f);
            let got = dist(w.features());
            let scan = dist(
                scan_winner_below::<Exact>(&p, &q, f64::INFINITY)
                    .0
                    .features(),
            );
            let order = Exact::cmp_dist2(got, scan);
            // Strictly below the cut, the nearest pair; otherwise some pair.
            let beats = c.is_infinite()
                || Exact::cmp_dist2(scan, Dist2::PointPoint(DVec2::ZERO, DVec2::new(c, 0.0)))
                    == Ordering::Less;
            if beats {
                below += 1;
                assert_eq!(order, Ordering::Equal, "{p:?} {q:?} {a:?} {d:?} {cut}");
            } else {
                assert_ne!(order, Ordering::Less, "{p:?} {q:?} {a:?} {d:?} {cut}");
            }
        }
        assert!(
            swept > 2_000 && below > 1_500,
            "{swept} swept, {below} compared exactly"
        );
    }

    /// The sweep on dense chains, whose windows along the line hold dozens to hundreds of
    /// vertices and are thinned by the blocks' and the candidates' own boxes of keys: the exact
    /// scan's nearest pair, on corridors (walls a smooth curve apart, sampled far more finely than
    /// the clearance), on lattice walls with repeated depths and ties, and on crowded clusters
    /// (whose windows exceed the budget: the sweep must then decline). Most corridors are answered
    /// with far fewer candidates than their windows along the line hold.
    #[test]
    fn dense_chains_are_the_exact_scan() {
        use crate::brute::scan_winner_below;
        use polydist_predicates::{Exact, Robust};
        use std::cmp::Ordering;
        let mut rng = SplitMix64::new(0xb10c);
        let (mut swept, mut crowded, mut thinned, mut declined) = (0, 0, 0, 0);
        for round in 0..240 {
            let (a, d, perp) = lattice_line(&mut rng);
            let kind = round % 3;
            let n = 100 + rng.index(240);
            let step = [1.0 / 64.0, 1.0 / 16.0, 1.0 / 4.0][rng.index(3)];
            let (amp, phase) = (rng.unit_f64(), rng.unit_f64() * 6.0);
            let gap = [1.0, 2.0, 0.5][rng.index(3)];
            // Depth of the wall at position `s` along the line, on side `side`.
            let wall = |rng: &mut SplitMix64, s: f64, side: f64, shift: f64| -> f64 {
                match kind {
                    // A smooth corridor, gently rounded to a dyadic grid.
                    0 => {
                        let h = amp * (s * 0.7 + phase + shift).sin() * 0.5;
                        side * (gap / 2.0 + side * h)
                    }
                    // Lattice walls: depths on a quarter grid, repeated and tied (clusters, kind
                    // 2, are built below).
                    _ => side * (gap / 2.0 + rng.below(3) as f64 * 0.25),
                }
            };
            let chain = |rng: &mut SplitMix64, side: f64, shift: f64| -> Vec<DVec2> {
                let start = rng.range_i64(-4, 1) as f64;
                let mut c: Vec<DVec2> = (0..n)
                    .map(|i| {
                        let s = start + i as f64 * step;
                        a + d * s + perp * wall(rng, s, side, shift)
                    })
                    .collect();
                c.dedup();
                if rng.coin() {
                    c.reverse();
                }
                c
            };
            let (p, q) = if kind == 2 {
                // A cluster of `n` vertices 2⁻⁴⁰ apart along the line, and an arc of radius `gap`
                // around it from 60° to 120°: every pair is within about 10⁻¹⁰ of the clearance,
                // every block's box of keys reaches nearer than it, and the windows hold the whole
                // arc, so the count exceeds the budget.
                let (du, pu) = (d / d.length(), perp / perp.length());
                let p: Vec<DVec2> = (0..n)
                    .map(|i| a + du * (i as f64 * 2f64.powi(-40)))
                    .collect();
                let q: Vec<DVec2> = (0..n)
                    .map(|j| {
                        let th = (60.0 + 60.0 * j as f64 / (n - 1) as f64).to_radians();
                        a + du * (gap * th.cos()) - pu * (gap * th.sin())
                    })
                    .collect();
                (p, q)
            } else {
                (chain(&mut rng, 1.0, 0.0), chain(&mut rng, -1.0, 1.3))
            };
            let Some((kp, kq, _)) = keys(&p, &q, a, a + d) else {
                panic!("finite keys");
            };
            let read = |c: &[DVec2], k: &KeyPair| {
                if k.0.first() <= k.0.last() {
                    (c.to_vec(), false)
                } else {
                    (c.iter().rev().copied().collect(), true)
                }
            };
            let ((fp, rp), (fq, rq)) = (read(&p, &kp), read(&q, &kq));
            let Some((w, tried)) = keyed::<Robust>(&fp, &fq, a, a + d, f64::INFINITY) else {
                declined += 1;
                continue;
            };
            let w = w.reversed(rp.then_some(p.len()), rq.then_some(q.len()));
            swept += 1;
            let dist = |f: (Feature, Feature)| feature_dist(&p, &q, f);
            let scan = scan_winner_below::<Exact>(&p, &q, f64::INFINITY).0;
            let (got, want) = (dist(w.features()), dist(scan.features()));
            assert_eq!(
                Exact::cmp_dist2(got, want),
                Ordering::Equal,
                "round {round}: {p:?} {q:?} {a:?} {d:?}"
            );
            // The window along the line alone: every vertex pair within the clearance along it.
            let u = w.pair().distance;
            let along = p
                .iter()
                .map(|x| {
                    q.iter()
                        .filter(|y| ((*y - *x).dot(d) / d.length()).abs() <= u)
                        .count()
                })
                .sum::<usize>();
            if kind == 0 && along > 8 * (p.len() + q.len()) {
                crowded += 1;
                if tried * 2 < along {
                    thinned += 1;
                }
            }
        }
        eprintln!(
            "dense chains: {swept} swept ({crowded} corridors crowded along the line, {thinned} \
             of them with fewer than half those candidates), {declined} declined"
        );
        assert!(
            swept >= 120 && crowded >= 20 && thinned * 10 >= crowded * 9 && declined >= 60,
            "{swept} {crowded} {thinned} {declined}"
        );
    }

    /// The sweep where the windows along the line hold thousands of vertices, so that
    /// [`scan_windowed`]'s blocks are tested from the wide ones down (a star's tips facing a
    /// curved wall, as in the pocket benchmark, at a sampling where a window spans more than
    /// [`crate::brute`]'s `WIDE` coarse blocks): a sparse arc of radius 1 and a dense arc of radius
    /// 2 about the same centre (either one the dense one), separated by a horizontal line, with
    /// random radial jitter; the exact scan's nearest pair.
    #[test]
    fn wide_windows_are_the_exact_scan() {
        use crate::brute::scan_winner_below;
        use polydist_predicates::Robust;
        use std::cmp::Ordering;
        let mut rng = SplitMix64::new(0x3a1de);
        for round in 0..4 {
            let arc = |rng: &mut SplitMix64, r: f64, n: usize, jitter: f64| -> Vec<DVec2> {
                (0..n)
                    .map(|k| {
                        let th = (45.0 + 90.0 * k as f64 / (n - 1) as f64).to_radians();
                        let r = r + jitter * rng.unit_f64();
                        DVec2::new(r * th.cos(), r * th.sin())
                    })
                    .collect()
            };
            let dense_p = round % 2 == 1;
            let (np, nq) = if dense_p { (6000, 48) } else { (48, 6000) };
            // Radial jitter far below the angular step (the chains stay monotone along the line).
            let (p, q) = (arc(&mut rng, 1.0, np, 1e-7), arc(&mut rng, 2.0, nq, 1e-7));
            let (a, b) = (DVec2::new(0.0, 1.2), DVec2::new(1.0, 1.2));
            let Some((kp, kq, _)) = keys(&p, &q, a, b) else {
                panic!("finite keys");
            };
            // Both arcs run from right to left: read them in increasing `t`.
            assert!(kp.0[0] > kp.0[np - 1] && kq.0[0] > kq.0[nq - 1]);
            let (fp, fq): (Vec<DVec2>, Vec<DVec2>) = (
                p.iter().rev().copied().collect(),
                q.iter().rev().copied().collect(),
            );
            let (w, _) = keyed::<Robust>(&fp, &fq, a, b, f64::INFINITY).expect("within the budget");
            let w = w.reversed(Some(np), Some(nq));
            let scan = scan_winner_below::<Robust>(&p, &q, f64::INFINITY).0;
            let (got, want) = (
                feature_dist(&p, &q, w.features()),
                feature_dist(&p, &q, scan.features()),
            );
            assert_eq!(
                Robust::cmp_dist2(got, want),
                Ordering::Equal,
                "round {round}"
            );
            // The windows are wide: the dense arc's vertices within the clearance along the line
            // of a vertex of the sparse one, on average.
            let u = w.pair().distance;
            let (sparse, dense) = if dense_p { (&q, &p) } else { (&p, &q) };
            let along: usize = sparse
                .iter()
                .map(|x| dense.iter().filter(|y| (y.x - x.x).abs() <= u).count())
                .sum();
            assert!(along > 40 * 64 * sparse.len(), "round {round}: {along}");
        }
    }

    /// The sweep where the windows along the line hold both chains whole (chains a few units
    /// long, a clearance as large) and only depth thins them: vertices whose depth is farther than
    /// the best from every depth of the other chain, and the other chain's coarse blocks likewise,
    /// are left out of the count and of the scan: section 3's pair, exactly. Monotone chains of 15,000 to 19,000 vertices
    /// along lattice directions, each a slab with one tooth towards the line (two to eight units
    /// deep, on a quarter grid or not), the teeth facing each other, or one of them flat: their windows meet more coarse blocks than the budget
    /// allows, the blocks kept fit it.
    #[test]
    fn depth_cuts_keep_section_3s_answer() {
        use polydist_predicates::Robust;
        use std::cmp::Ordering;
        let mut rng = SplitMix64::new(0xdee9);
        for round in 0..6 {
            let (a, d, perp) = lattice_line(&mut rng);
            let float = round % 2 == 1;
            // The teeth face each other, up to a tenth apart along the line.
            let tip = 0.2 + rng.unit_f64() * 1.6;
            // Both toothed, or one of them flat (so that all of it is near the other's tooth).
            let flat = round % 3;
            let chain = |rng: &mut SplitMix64, side: f64| -> Vec<DVec2> {
                let n = 15_000 + rng.index(4000);
                // A tooth at `tip` towards the line, `swing` deep and `2·swing/slope` wide.
                let (swing, tip, slope) = (
                    if flat == (side > 0.0) as usize + 1 {
                        0.0
                    } else {
                        2.0 + rng.index(7) as f64
                    },
                    tip + rng.unit_f64() * 0.1,
                    1.0 + rng.index(8) as f64,
                );
                let gap = [0.5, 1.0, 2.0][rng.index(3)];
                let mut c: Vec<DVec2> = (0..n)
                    .map(|i| {
                        let s = 2.0 * i as f64 / n as f64;
                        let h = swing * ((s - tip).abs() * slope).min(1.0);
                        let h = if float { h } else { (h * 4.0).round() / 4.0 };
                        a + d * s + perp * (side * (gap + h))
                    })
                    .collect();
                c.dedup();
                c
            };
            let (p, q) = (chain(&mut rng, 1.0), chain(&mut rng, -1.0));
            let (w, tried) = keyed::<Robust>(&p, &q, a, a + d, f64::INFINITY)
                .unwrap_or_else(|| panic!("round {round}: declined"));
            // Section 3's matrices: exact, linear.
            let s3 = crate::sigma::separation_of_chains_with::<Robust>(
                &p,
                &q,
                a,
                a + d,
                crate::sigma::ChainMethod::Matrices,
            )
            .expect("chains across the line");
            let (got, want) = (
                feature_dist(&p, &q, w.features()),
                feature_dist(&p, &q, (s3.pair.feature_p, s3.pair.feature_q)),
            );
            assert_eq!(
                Robust::cmp_dist2(got, want),
                Ordering::Equal,
                "round {round}: {a:?} {d:?}"
            );
            let n = p.len() + q.len();
            assert!(tried <= 8 * n, "round {round}: {tried} candidates for {n}");
        }
    }

    /// Every key is within `E` of the exact `t(v)` and `d(v)`, a pair the window leaves out is
    /// farther apart along the line than `U·|b − a|` (squared: `(t(y) − t(x))² > U²·|b − a|²`,
    /// exactly), and a vertex and a vertex, an edge or a box of several vertices that
    /// [`Lens::beyond`] puts farther than `U` are (exact squared distances).
    #[test]
    fn keys_and_window_hold_their_bounds() {
        use num_traits::ToPrimitive;
        use polydist_predicates::exact::{
            squared_distance_point_point, squared_distance_point_segment,
        };
        let mut rng = SplitMix64::new(0x6e75);
        let r = |x: f64| to_rational(x).expect("finite");
        let exact_key = |v: DVec2, a: DVec2, b: DVec2| {
            (r(v.x) - r(a.x)) * (r(b.x) - r(a.x)) + (r(v.y) - r(a.y)) * (r(b.y) - r(a.y))
        };
        let exact_depth = |v: DVec2, a: DVec2, b: DVec2| {
            (r(v.x) - r(a.x)) * (r(b.y) - r(a.y)) - (r(v.y) - r(a.y)) * (r(b.x) - r(a.x))
        };
        let (mut skipped, mut kept) = (0, 0);
        let (mut beyond, mut near) = (0, 0);
        for round in 0..1_500 {
            let class = round % 6;
            let (a, b) = (point(&mut rng, class), point(&mut rng, class));
            if a == b {
                continue;
            }
            let fp: Vec<DVec2> = (0..4).map(|_| point(&mut rng, class)).collect();
            let fq: Vec<DVec2> = (0..4).map(|_| point(&mut rng, class)).collect();
            let Some((kp, kq, lens)) = keys(&fp, &fq, a, b) else {
                panic!("finite keys for {fp:?} {fq:?} {a:?} {b:?}");
            };
            let (tp, tq) = (&kp.0, &kq.0);
            let all = fp.iter().zip(kp.0.iter().zip(&kp.1));
            for (v, (t, d)) in all.chain(fq.iter().zip(kq.0.iter().zip(&kq.1))) {
                for err in [r(*t) - exact_key(*v, a, b), r(*d) - exact_depth(*v, a, b)] {
                    let e = r(lens.slack);
                    assert!(err <= e && -err <= e, "{v:?} {a:?} {b:?}");
                }
            }
            let u2exact =
                (r(b.x) - r(a.x)) * (r(b.x) - r(a.x)) + (r(b.y) - r(a.y)) * (r(b.y) - r(a.y));
            for (x, tx) in fp.iter().zip(tp) {
                for (y, ty) in fq.iter().zip(tq) {
                    // Candidate distances: a fraction of the key gap itself, so that both answers occur.
                    let gap = ((ty - tx) / lens.len).abs();
                    for f in [0.0, 0.5, 0.999_999, 1.0, 1.000_001, 2.0] {
                        let u2 = (gap * f) * (gap * f);
                        let w = lens.window(u2);
                        if ty - tx > w || tx - ty > w {
                            skipped += 1;
                            let d = exact_key(*y, a, b) - exact_key(*x, a, b);
                            assert!(d.clone() * d > r(u2) * u2exact.clone(), "{x:?} {y:?} {u2}");
                        } else {
                            kept += 1;
                        }
                    }
                }
            }
            // Boxes: a `P` vertex against one `Q` vertex, one `Q` edge, or all of `Q` (a block).
            let span = |ks: &[f64]| {
                ks.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &k| {
                        (lo.min(k), hi.max(k))
                    })
            };
            // Now and then `Q` a cluster within about `10⁻⁷` of a `P` vertex, far from `a` and `b`
            // compared with its size: the keys' errors are then a large share of the gaps.
            let (fq, kq) = if round % 3 == 0 {
                let c = fp[0];
                let s = 1e-7 * (c.x.abs() + c.y.abs()).max(1e-300);
                let fq: Vec<DVec2> = (0..4)
                    .map(|_| c + DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5) * s)
                    .collect();
                let Some((_, kq, _)) = keys(&fp, &fq, a, b) else {
                    panic!("finite keys for {fp:?} {fq:?} {a:?} {b:?}");
                };
                (fq, kq)
            } else {
                (fq, kq)
            };
            for (i, x) in fp.iter().enumerate() {
                let (tx, dx) = (kp.0[i], kp.1[i]);
                for (lo, hi) in [(0, 0), (1, 2), (2, 3), (0, 3)] {
                    let (bt, bd) = (span(&kq.0[lo..=hi]), span(&kq.1[lo..=hi]));
                    let (gt, gd) = (lens.gap((tx, tx), bt), lens.gap((dx, dx), bd));
                    // The nearest exact squared distance of the box's vertices and edges.
                    let nearest = (lo..=hi)
                        .map(|k| squared_distance_point_point(*x, fq[k]).expect("finite"))
                        .chain((lo..hi).map(|k| {
                            squared_distance_point_segment(*x, fq[k], fq[k + 1]).expect("finite")
                        }))
                        .min()
                        .expect("a vertex");
                    // Candidate distances around the gaps' own and next to the exact one, so that
                    // both answers occur.
                    let g2 = (gt * gt + gd * gd) / lens.len2;
                    let at = nearest.to_f64().expect("finite");
                    let next = |x: f64, up: bool| {
                        let bits = x.to_bits();
                        f64::from_bits(if up { bits + 1 } else { bits.saturating_sub(1) })
                    };
                    let around = [next(at, false), at, next(at, true)];
                    for u2 in [0.0, 0.25, 0.999_999, 1.0, 1.000_001, 4.0]
                        .map(|f| g2 * f)
                        .into_iter()
                        .chain(around)
                    {
                        if lens.beyond(gt, gd, u2) {
                            beyond += 1;
                            assert!(nearest > r(u2), "{x:?} {:?} {u2}", &fq[lo..=hi]);
                        } else {
                            near += 1;
                        }
                    }
                }
            }
        }
        assert!(skipped > 15_000 && kept > 15_000, "{skipped} {kept}");
        assert!(beyond > 20_000 && near > 20_000, "{beyond} {near}");
    }

    /// [`reached`] covers the exact reach: `√u2′ ≥ √u2 + |v − o|` for a reach computed as
    /// `fl(|v − o|)`, over every scale (checked in rationals: `A − B − R ≥ 0` and
    /// `(A − B − R)² ≥ 4BR` for `A = u2′`, `B = u2`, `R = |v − o|²`).
    #[test]
    fn reached_covers_the_reach() {
        use polydist_predicates::exact::squared_distance_point_point;
        let mut rng = SplitMix64::new(0x4eac);
        let r = |x: f64| to_rational(x).expect("finite");
        for round in 0..5_000 {
            let class = round % 6;
            let (o, v) = (point(&mut rng, class), point(&mut rng, class));
            let scale = [1.0, 1e-300, 1e300, 0.0, 1e-320][round % 5];
            let u2 = rng.unit_f64() * scale;
            let reach = v.distance(o);
            let got = reached(u2, reach);
            if !got.is_finite() {
                continue;
            }
            let (a, b) = (r(got), r(u2));
            let big_r = squared_distance_point_point(v, o).expect("finite");
            let lhs = &a - &b - &big_r;
            let four = r(4.0);
            assert!(
                lhs >= r(0.0) && &lhs * &lhs >= four * &b * &big_r,
                "{u2:e} {reach:e} {got:e}"
            );
        }
    }

    /// A block that [`Chord::apart`] puts farther than `√u2` from a point is: every vertex and
    /// every edge of it (exact squared distances), for blocks of every scale class, zigzags, long
    /// nearly straight blocks a hair from the point (cancelling keys), clusters within `10⁻⁷` of
    /// the point, chords of length zero, and thresholds around the exact nearest distance.
    #[test]
    fn chord_boxes_hold_their_bounds() {
        use num_traits::ToPrimitive;
        use polydist_predicates::exact::{
            squared_distance_point_point, squared_distance_point_segment,
        };
        let mut rng = SplitMix64::new(0xc40d);
        let r = |x: f64| to_rational(x).expect("finite");
        let (mut apart, mut near) = (0, 0);
        let next = |x: f64, up: bool| {
            let bits = x.to_bits();
            f64::from_bits(if up { bits + 1 } else { bits.saturating_sub(1) })
        };
        for round in 0..3_000 {
            let class = round % 6;
            let mut x = point(&mut rng, class);
            let n = 2 + round % 8;
            let block: Vec<DVec2> = match round % 5 {
                // A long, nearly straight block with `x` a hair from its middle: the keys cancel
                // (their errors are then a large share of the gap across the chord).
                4 => {
                    let (o, e) = (point(&mut rng, class), point(&mut rng, class) - x);
                    let side = DVec2::new(-e.y, e.x);
                    x = o + e * 0.5 + side * (1e-12 * (rng.unit_f64() + 0.5));
                    (0..n)
                        .map(|k| {
                            let jitter = 1e-13 * (rng.unit_f64() - 0.5);
                            o + e * (k as f64 / (n - 1) as f64) + side * jitter
                        })
                        .collect()
                }
                // Random points of the class.
                0 => (0..n).map(|_| point(&mut rng, class)).collect(),
                // A cluster next to `x`, far from the origin compared with its size.
                1 => {
                    let s = 1e-7 * (x.x.abs() + x.y.abs()).max(1e-300);
                    (0..n)
                        .map(|_| x + DVec2::new(rng.unit_f64() - 0.5, rng.unit_f64() - 0.5) * s)
                        .collect()
                }
                // A zigzag along a random direction, one unit from `x`'s scale.
                2 => {
                    let (o, e) = (point(&mut rng, class), point(&mut rng, class) - x);
                    let side = DVec2::new(-e.y, e.x) * 0.25;
                    (0..n)
                        .map(|k| o + e * (k as f64 / n as f64) + side * (k % 2) as f64)
                        .collect()
                }
                // A closed block (first and last vertex equal: a chord of length zero).
                _ => {
                    let mut b: Vec<DVec2> = (0..n).map(|_| point(&mut rng, class)).collect();
                    b.push(b[0]);
                    b
                }
            };
            let (first, last) = (block[0], block[block.len() - 1]);
            let chord = Chord::of(first, last, block.iter().copied()).expect("finite keys");
            let nearest = block
                .iter()
                .map(|&y| squared_distance_point_point(x, y).expect("finite"))
                .chain(
                    block
                        .windows(2)
                        .map(|w| squared_distance_point_segment(x, w[0], w[1]).expect("finite")),
                )
                .min()
                .expect("a vertex");
            let at = nearest.to_f64().expect("finite");
            let around = [next(at, false), at, next(at, true)];
            for u2 in [0.0, 0.25, 0.5, 0.9, 0.999_999, 1.0 - 1e-12]
                .map(|f| at * f)
                .into_iter()
                .chain(around)
            {
                if chord.apart(x, u2) {
                    apart += 1;
                    assert!(nearest > r(u2), "{x:?} {block:?} {u2}");
                } else {
                    near += 1;
                }
            }
        }
        assert!(apart > 3_000 && near > 8_000, "{apart} {near}");
    }
}
