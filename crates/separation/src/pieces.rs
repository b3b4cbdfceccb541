//! The partition of the edges of a chain (monotone along the line) into pieces on which
//! `h()` and `l()` are constant (Amato's Figure 8), and the clipping of each piece to the arc where
//! `α ≥ 90°` (the disk with diameter `[l, h]`, Figure 5).

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign};

use crate::chain::Prepared;
use crate::frame::Frame;
use crate::param::{Affine, Edge, Param};
use crate::site::Vertex;

/// A piece of edge `edge` (from prepared vertex `edge` to `edge + 1`), from `bot` to `top`, with
/// constant tangent points `hi = h(x)` and `lo = l(x)` (`None`: the ray is parallel to the line)
/// and `α(x) ≥ 90°` on all of it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Piece<V = DVec2> {
    pub(crate) edge: usize,
    pub(crate) bot: Param<V>,
    pub(crate) top: Param<V>,
    pub(crate) hi: Option<V>,
    pub(crate) lo: Option<V>,
}

/// One interval of an edge with one tangent point.
#[derive(Clone, Copy, Debug)]
struct Span<V = DVec2> {
    bot: Param<V>,
    top: Param<V>,
    tangent: Option<V>,
}

/// The orientation form whose root on an edge is where the hull pair `(c, c')` stops or starts
/// being popped: `x ↦ orient(x, c, c')`.
fn pair_form<V: Vertex>(c: V, c2: V) -> Affine<V> {
    Affine {
        cross: true,
        c,
        v0: c,
        v1: c2,
        neg: true,
    }
}

/// Splits `spans` (with tangent candidates, ascending) where the tangent stops being strictly
/// nearer to the line than the point: `h(x) = t` only where `depth(t) < depth(x)`. Appends the
/// result to `out`.
fn depth_rule<K: Kernel, V: Vertex>(
    e: &Edge<V>,
    frame: Frame,
    spans: impl Iterator<Item = Span<V>>,
    out: &mut Vec<Span<V>>,
) {
    for s in spans {
        let Some(t) = s.tangent else {
            out.push(s);
            continue;
        };
        let g = frame.depth_minus(t);
        let (gb, gt) = e.eval_pair_within::<K>(&g, &s.bot, &s.top);
        // Split only where the sign strictly changes; a zero at one end is that end itself, and a
        // single point keeps the tangent of the rest of the piece (it is also a piece end of the
        // neighbour or a vertex, tested there).
        match (gb, gt) {
            (Sign::Positive, Sign::Negative) | (Sign::Negative, Sign::Positive) => {
                let w = Param::Root(g);
                let (lower, upper) = if gb == Sign::Positive {
                    (Some(t), None)
                } else {
                    (None, Some(t))
                };
                out.push(Span {
                    bot: s.bot,
                    top: w,
                    tangent: lower,
                });
                out.push(Span {
                    bot: w,
                    top: s.top,
                    tangent: upper,
                });
            }
            _ if gb == Sign::Positive || gt == Sign::Positive => out.push(s),
            _ => out.push(Span { tangent: None, ..s }),
        }
    }
}

/// The pieces of every edge of `pts` (strictly increasing in height), in height order.
///
/// Two hull scans as in `wedge::tangents`; when vertex `p_i` pops the hull pairs
/// `(c_1, c_2), …, (c_r, c_{r+1})` (`c_1 = p_{i+1}`), the edge `(p_i, p_{i+1})` changes tangent where
/// it crosses the line of each popped pair `m ≥ 2` (Amato's breakpoints; at most one per popped hull
/// edge, so `O(n)` in all), and where the tangent point's depth is reached. The two partitions are
/// merged and each piece is clipped to `F(t) ≤ 0`. `O(n)` predicates of degree ≤ 6.
///
/// The top-to-bottom scan stores every edge's upper spans back to back in one array; the
/// bottom-to-top scan merges each edge's lower spans with them as soon as they are known (edges
/// in increasing order, as the pieces are numbered), in reused scratch space.
pub(crate) fn pieces<K: Kernel, V: Vertex>(prep: &Prepared<V>, frame: Frame) -> Vec<Piece<V>> {
    let pts = &prep.pts[..];
    let n = pts.len();
    if n < 2 {
        return Vec::new();
    }
    // The real edges; an end may be a vertex hidden behind the nearest vertex of a run at its
    // height (an edge perpendicular to the line).
    // (`None` at a gap between the runs of a clipped chain: no edge, no pieces.)
    let edge = |k: usize| prep.edge(k).map(|(a, b, _, _)| Edge { a, b });
    // The part of each edge on the envelope: a shadow point or hidden run vertex at either end is
    // at the height of the visible vertex and deeper.
    let range = |k: usize| prep.range(k);
    // Upper spans per edge (ascending), from the top-to-bottom scan: edge `k`'s are
    // `upper[upper_at[k].0..upper_at[k].1]`. For the edge below vertex i, the hull pairs popped at
    // its bottom end are walked before vertex i pops: when that end is a hidden run vertex (deeper
    // than `pts[i]` at the same height) they are a prefix of the pairs `pts[i]` pops (a pair pops
    // for points on its line's side toward `l`), so the walk is amortized.
    let mut upper: Vec<Span<V>> = Vec::with_capacity(2 * n);
    let mut upper_at: Vec<(usize, usize)> = vec![(0, 0); n - 1];
    let mut scratch: Vec<Span<V>> = Vec::new();
    let mut stack: Vec<usize> = Vec::with_capacity(n);
    for i in (0..n).rev() {
        if let Some((Some(e), Some((lo, hi)))) = (i + 1 < n).then(|| (edge(i), range(i))) {
            let e = &e;
            scratch.clear();
            let mut top = hi;
            let mut cur = stack.last().map(|&c| pts[c]);
            for t in (1..stack.len()).rev() {
                let (cm, cm1) = (pts[stack[t]], pts[stack[t - 1]]);
                let pops = frame.orient_x_first(cm, cm1);
                let sa = e.eval_within::<K>(&pops, &lo);
                if sa == Sign::Negative {
                    break; // the pair does not pop at the bottom end
                }
                let sb = e.eval_within::<K>(&pops, &hi);
                if sb != Sign::Negative {
                    cur = Some(cm1); // pops on all of the current range
                    continue;
                }
                if sa == Sign::Zero {
                    break; // pops at the bottom end only
                }
                let w = Param::Root(pair_form(cm, cm1));
                scratch.push(Span {
                    bot: w,
                    top,
                    tangent: cur,
                });
                top = w;
                cur = Some(cm1);
            }
            scratch.push(Span {
                bot: lo,
                top,
                tangent: cur,
            });
            // `scratch` is descending.
            let start = upper.len();
            depth_rule::<K, V>(e, frame, scratch.iter().rev().copied(), &mut upper);
            upper_at[i] = (start, upper.len());
        }
        let p = pts[i];
        while let [.., c2, c1] = stack[..] {
            if frame.orient::<K, _>(p, pts[c1], pts[c2]) == Sign::Negative {
                break;
            }
            stack.pop();
        }
        stack.push(i);
    }
    // Lower spans per edge (ascending), from the bottom-to-top scan (the mirror image), each merged
    // with the edge's upper spans and clipped at once.
    let mut lower: Vec<Span<V>> = Vec::new();
    // Typically about one piece per edge.
    let mut out: Vec<Piece<V>> = Vec::with_capacity(n - 1);
    stack.clear();
    for i in 0..n {
        if let Some((k, Some(e), Some((lo, hi)))) = i.checked_sub(1).map(|k| (k, edge(k), range(k)))
        {
            let e = &e;
            scratch.clear();
            let mut bot = lo;
            let mut cur = stack.last().map(|&d| pts[d]);
            for t in (1..stack.len()).rev() {
                let (dm, dm1) = (pts[stack[t]], pts[stack[t - 1]]);
                let pops = frame.orient_x_first(dm, dm1);
                let sb = e.eval_within::<K>(&pops, &hi);
                if sb == Sign::Positive {
                    break;
                }
                let sa = e.eval_within::<K>(&pops, &lo);
                if sa != Sign::Positive {
                    cur = Some(dm1);
                    continue;
                }
                if sb == Sign::Zero {
                    break;
                }
                let w = Param::Root(pair_form(dm, dm1));
                scratch.push(Span {
                    bot,
                    top: w,
                    tangent: cur,
                });
                bot = w;
                cur = Some(dm1);
            }
            scratch.push(Span {
                bot,
                top: hi,
                tangent: cur,
            });
            lower.clear();
            depth_rule::<K, V>(e, frame, scratch.iter().copied(), &mut lower);
            let (u0, u1) = upper_at[k];
            merge_and_clip::<K, V>(&mut out, k, e, (lo, hi), &upper[u0..u1], &lower);
        }
        let p = pts[i];
        while let [.., d2, d1] = stack[..] {
            if frame.orient::<K, _>(p, pts[d1], pts[d2]) == Sign::Positive {
                break;
            }
            stack.pop();
        }
        stack.push(i);
    }
    out
}

/// Merges the upper spans `us` and lower spans `ls` of edge `k` (each ascending, covering `range`)
/// into the pieces where both tangents are constant, clipped and pushed.
fn merge_and_clip<K: Kernel, V: Vertex>(
    out: &mut Vec<Piece<V>>,
    k: usize,
    e: &Edge<V>,
    range: (Param<V>, Param<V>),
    us: &[Span<V>],
    ls: &[Span<V>],
) {
    let (mut iu, mut il) = (0, 0);
    let mut bot = range.0;
    // Each step advances at least one list: at most |us| + |ls| steps.
    while iu < us.len() && il < ls.len() {
        let (tu, tl) = (us[iu].top, ls[il].top);
        let o = e.cmp::<K>(&tu, &tl);
        let top = if o == Ordering::Greater { tl } else { tu };
        if e.cmp::<K>(&bot, &top) == Ordering::Less {
            clip_and_push::<K, V>(
                out,
                k,
                e,
                range,
                (bot, top),
                (us[iu].tangent, ls[il].tangent),
            );
            bot = top;
        }
        if o != Ordering::Greater {
            iu += 1;
        }
        if o != Ordering::Less {
            il += 1;
        }
    }
}

/// Clips the piece `[bot, top]` of edge `k` to the arc `F ≤ 0` and pushes what is left.
fn clip_and_push<K: Kernel, V: Vertex>(
    out: &mut Vec<Piece<V>>,
    k: usize,
    e: &Edge<V>,
    range: (Param<V>, Param<V>),
    (bot, top): (Param<V>, Param<V>),
    (hi, lo): (Option<V>, Option<V>),
) {
    let piece = out.len();
    let (Some(h), Some(l)) = (hi, lo) else {
        out.push(Piece {
            edge: k,
            bot,
            top,
            hi,
            lo,
        });
        return;
    };
    let clipped = match end_tangent(e, h, l) {
        Some((v_is_b, w)) => clip_from_end::<K, V>(e, (bot, top), v_is_b, w),
        None => clip_to_arc::<K, V>(e, (bot, top), h, l, piece),
    };
    let Some((new_bot, new_top)) = clipped else {
        return;
    };
    // A piece clipped down to one end of its edge is that vertex alone (typically `F` vanishing at
    // the edge's top because the top is its own tangent point `h`). The vertex is a CVV candidate, and
    // the piece's wedge (built from the tangents of the edge's interior) is not the vertex's own: as a
    // row it would reject admissible `u` and, through the cap of the `R()` scan, starve the rows
    // below (found by the soak test, see docs). Dropped.
    // The same holds at a shadow point or hidden vertex ending the edge's part on the envelope: it
    // is strictly dominated by the visible vertex at its height.
    if e.cmp::<K>(&new_bot, &new_top) == Ordering::Equal
        && (e.cmp::<K>(&new_bot, &range.0) == Ordering::Equal
            || e.cmp::<K>(&new_top, &range.1) == Ordering::Equal)
    {
        return;
    }
    out.push(Piece {
        edge: k,
        bot: new_bot,
        top: new_top,
        hi,
        lo,
    });
}

/// A tangent point at an end `v` of the edge (on a convex corner of the envelope, the rule): whether
/// `v` is the edge's end `b`, and the other tangent point `w`.
fn end_tangent<V: Vertex>(e: &Edge<V>, h: V, l: V) -> Option<(bool, V)> {
    [(h, l), (l, h)].into_iter().find_map(|(z, w)| {
        (z == e.a)
            .then_some((false, w))
            .or_else(|| (z == e.b).then_some((true, w)))
    })
}

/// [`clip_and_push`] with a tangent point at an end `v` of the edge: `F(x) = (v − x)·(w − x)` with
/// `v − x = −λu`, `u` from `v` to the other end, `λ ≥ 0`, so on the edge `F ≤ 0` exactly at `v` and
/// where the affine `g(x) = (w − x)·u ≥ 0`: an interval from `v`, whose far end is the rational root
/// of `g` (degree 2) instead of an irrational arc end (the degree-6 placements and the
/// discriminant, which the star in a pocket drove into the exact stage at 131,072 vertices). `None`
/// when only `v` itself (a vertex, a CVV candidate) or nothing is left.
fn clip_from_end<K: Kernel, V: Vertex>(
    e: &Edge<V>,
    (bot, top): (Param<V>, Param<V>),
    v_is_b: bool,
    w: V,
) -> Option<(Param<V>, Param<V>)> {
    let (v, other) = if v_is_b { (e.b, e.a) } else { (e.a, e.b) };
    let g = Affine {
        cross: false,
        c: w,
        v0: v,
        v1: other,
        neg: true,
    };
    let (gb, gt) = e.eval_pair_within::<K>(&g, &bot, &top);
    let inside = |s: Sign| s != Sign::Negative;
    // `g` decreases away from `v`: the piece's end nearer `v` is tested first.
    match (v_is_b, inside(gb), inside(gt)) {
        (false, _, true) | (true, true, _) => Some((bot, top)),
        (false, true, false) if gb == Sign::Zero => Some((bot, bot)),
        (false, true, false) => Some((bot, Param::Root(g))),
        (true, false, true) if gt == Sign::Zero => Some((top, top)),
        (true, false, true) => Some((Param::Root(g), top)),
        _ => None,
    }
}

/// [`clip_and_push`] in general: the piece clipped to `[r_1, r_2]`, the roots of `F` for `(h, l)`
/// kept symbolic (`Param::Clip` of piece `piece`); `None` when the discriminant is negative or the
/// piece misses the arc.
fn clip_to_arc<K: Kernel, V: Vertex>(
    e: &Edge<V>,
    (bot, top): (Param<V>, Param<V>),
    h: V,
    l: V,
    piece: usize,
) -> Option<(Param<V>, Param<V>)> {
    if e.disc::<K>(h, l) == Sign::Negative {
        return None; // α < 90° on the whole line of the edge
    }
    let arc = |t: &Param<V>| e.against_arc_ends::<K>(t, h, l, piece);
    let (b1, b2) = arc(&bot);
    let (t1, t2) = arc(&top);
    if b2 == Ordering::Greater || t1 == Ordering::Less {
        return None; // the piece misses the arc
    }
    let end = |hi| Param::Clip { h, l, hi, piece };
    let new_bot = match (b1, t1) {
        (Ordering::Less, Ordering::Equal) => top,
        (Ordering::Less, _) => end(false),
        _ => bot,
    };
    let new_top = match (t2, b2) {
        (Ordering::Greater, Ordering::Equal) => bot,
        (Ordering::Greater, _) => end(true),
        _ => top,
    };
    Some((new_bot, new_top))
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::Exact;

    const P: Frame = Frame {
        l0: DVec2::ZERO,
        l1: DVec2::new(0.0, 1.0),
        mirror: false,
    };

    fn chain(rng: &mut SplitMix64, n: usize) -> Vec<DVec2> {
        let mut ys: Vec<i64> = (0..n).map(|_| rng.range_i64(0, 3 * n as i64)).collect();
        ys.sort_unstable();
        ys.dedup();
        ys.into_iter()
            .map(|y| DVec2::new(rng.range_i64(0, 9) as f64, y as f64))
            .collect()
    }

    /// An `f64` approximation of a parameter, for sampling only.
    fn approx(e: &Edge, t: &Param) -> f64 {
        let val = |g: &Affine, x: DVec2| {
            let (d, w) = (x - g.c, g.v1 - g.v0);
            if g.cross { d.perp_dot(w) } else { d.dot(w) }
        };
        match t {
            Param::Start => 0.0,
            Param::End => 1.0,
            Param::Root(f) => {
                let (fa, fb) = (val(f, e.a), val(f, e.b));
                fa / (fa - fb)
            }
            Param::Clip { h, l, hi, .. } => {
                let d = e.b - e.a;
                let a = d.dot(d);
                let b = (2.0 * e.a - *h - *l).dot(d);
                let c = (e.a - *h).dot(e.a - *l);
                let s = (b * b - 4.0 * a * c).max(0.0).sqrt();
                if *hi {
                    (-b + s) / (2.0 * a)
                } else {
                    (-b - s) / (2.0 * a)
                }
            }
        }
    }

    /// Brute-force tangents from a point `x` of edge `k`: the extreme point above (below) by polar
    /// angle, farthest on ties, when strictly nearer to the line.
    fn brute(pts: &[DVec2], k: usize, x: DVec2, up: bool) -> Option<DVec2> {
        let cands: Vec<DVec2> = if up {
            pts[k + 1..].to_vec()
        } else {
            pts[..=k].to_vec()
        };
        let want = if up { Sign::Positive } else { Sign::Negative };
        let mut best = cands[0];
        for &c in &cands[1..] {
            let s = Exact::orient(x, best, c).sign();
            if s == want || (s == Sign::Zero && (c - x).length() > (best - x).length()) {
                best = c;
            }
        }
        (best.x < x.x).then_some(best)
    }

    #[test]
    fn pieces_have_constant_tangents_and_cover_the_arc() {
        let mut rng = SplitMix64::new(31);
        let mut checked = 0;
        for n in [2usize, 3, 5, 9, 16, 30] {
            for _ in 0..200 {
                let pts = chain(&mut rng, n);
                let prep = Prepared::<DVec2>::from_rising(&pts);
                let ps = pieces::<Exact, _>(&prep, P);
                // Pieces are in order along the chain and well formed.
                for w in ps.windows(2) {
                    assert!(w[0].edge <= w[1].edge);
                }
                for pc in &ps {
                    let e = Edge {
                        a: pts[pc.edge],
                        b: pts[pc.edge + 1],
                    };
                    assert_ne!(e.cmp::<Exact>(&pc.bot, &pc.top), Ordering::Greater);
                    let (t0, t1) = (approx(&e, &pc.bot), approx(&e, &pc.top));
                    if t1 - t0 < 1e-6 {
                        continue;
                    }
                    for f in [0.25, 0.5, 0.75] {
                        // A dyadic parameter keeps the sample exactly on the edge (integer ends).
                        let t = ((t0 + f * (t1 - t0)) * 1024.0).round() / 1024.0;
                        if t <= t0 + 1e-9 || t >= t1 - 1e-9 {
                            continue;
                        }
                        let x = e.a + (e.b - e.a) * t;
                        assert_eq!(
                            pc.hi,
                            brute(&pts, pc.edge, x, true),
                            "h at t={t} of {pc:?} in {pts:?}"
                        );
                        assert_eq!(
                            pc.lo,
                            brute(&pts, pc.edge, x, false),
                            "l at t={t} of {pc:?} in {pts:?}"
                        );
                        if let (Some(h), Some(l)) = (pc.hi, pc.lo) {
                            assert!((h - x).dot(l - x) <= 1e-9, "α < 90° inside {pc:?}");
                        }
                        checked += 1;
                    }
                }
                // Every sampled edge point with α clearly ≥ 90° lies in some piece.
                for k in 0..pts.len().saturating_sub(1) {
                    let e = Edge {
                        a: pts[k],
                        b: pts[k + 1],
                    };
                    for s in 1..32 {
                        let t = s as f64 / 32.0;
                        let x = e.a + (e.b - e.a) * t;
                        let (h, l) = (brute(&pts, k, x, true), brute(&pts, k, x, false));
                        let keep = match (h, l) {
                            (Some(h), Some(l)) => (h - x).dot(l - x) < -1e-9,
                            _ => true,
                        };
                        if keep {
                            assert!(
                                ps.iter().any(|pc| pc.edge == k
                                    && approx(&e, &pc.bot) <= t + 1e-9
                                    && t <= approx(&e, &pc.top) + 1e-9),
                                "t={t} on edge {k} of {pts:?} is in no piece: {ps:?}"
                            );
                        }
                    }
                }
            }
        }
        assert!(checked > 2000, "{checked}");
    }

    /// The same checks on the envelopes of general simple chains (random 2-opt polygons, closed or
    /// cut into open sub-chains): pieces lie in the envelope's parts of edges (which may end at
    /// shadow points), with the brute-force tangents among the visible vertices.
    #[test]
    fn pieces_of_envelopes_of_general_chains() {
        use crate::envelope::prepare;
        use crate::error::Chain;
        let mut rng = SplitMix64::new(32);
        let mut checked = 0;
        let mut shadows = 0;
        for n in [3usize, 5, 8, 13, 21] {
            for _ in 0..60 {
                let poly: Vec<DVec2> = polydist_oracle::two_opt(&mut rng, n)
                    .into_iter()
                    .map(|v| DVec2::new(v.x + 1.0, v.y))
                    .collect();
                let chain: Vec<DVec2> = if rng.coin() {
                    let mut c = poly.clone();
                    c.push(poly[0]);
                    c
                } else {
                    let (s0, len) = (rng.index(n), 1 + rng.index(n));
                    (0..len).map(|t| poly[(s0 + t) % n]).collect()
                };
                let prep = prepare::<Exact, _>(&chain, P, Chain::P).unwrap();
                let pts = &prep.pts;
                let ps = pieces::<Exact, _>(&prep, P);
                for w in ps.windows(2) {
                    assert!(w[0].edge <= w[1].edge);
                }
                let edge = |k: usize| {
                    let (a, b, _, _) = prep.edge(k).unwrap();
                    Edge { a, b }
                };
                for k in 0..prep.intervals() {
                    let r = prep.env_edge(k).unwrap();
                    shadows += usize::from(matches!(r.lo, Param::Root(_)))
                        + usize::from(matches!(r.hi, Param::Root(_)));
                }
                for pc in &ps {
                    let e = edge(pc.edge);
                    let r = prep.env_edge(pc.edge).unwrap();
                    assert_ne!(e.cmp::<Exact>(&pc.bot, &pc.top), Ordering::Greater);
                    assert_ne!(e.cmp::<Exact>(&r.lo, &pc.bot), Ordering::Greater);
                    assert_ne!(e.cmp::<Exact>(&pc.top, &r.hi), Ordering::Greater);
                    let (t0, t1) = (approx(&e, &pc.bot), approx(&e, &pc.top));
                    if t1 - t0 < 1e-6 {
                        continue;
                    }
                    for f in [0.25, 0.5, 0.75] {
                        let t = ((t0 + f * (t1 - t0)) * 1024.0).round() / 1024.0;
                        if t <= t0 + 1e-9 || t >= t1 - 1e-9 {
                            continue;
                        }
                        let x = e.a + (e.b - e.a) * t;
                        assert_eq!(
                            pc.hi,
                            brute(pts, pc.edge, x, true),
                            "h of {pc:?} in {chain:?}"
                        );
                        assert_eq!(
                            pc.lo,
                            brute(pts, pc.edge, x, false),
                            "l of {pc:?} in {chain:?}"
                        );
                        checked += 1;
                    }
                }
                // Every sampled envelope point with α clearly ≥ 90° lies in some piece.
                for k in 0..prep.intervals() {
                    let e = edge(k);
                    let r = prep.env_edge(k).unwrap();
                    let (t0, t1) = (approx(&e, &r.lo), approx(&e, &r.hi));
                    for s in 1..32 {
                        let t = ((t0 + (t1 - t0) * s as f64 / 32.0) * 1024.0).round() / 1024.0;
                        if t <= t0 + 1e-9 || t >= t1 - 1e-9 {
                            continue;
                        }
                        let x = e.a + (e.b - e.a) * t;
                        let (h, l) = (brute(pts, k, x, true), brute(pts, k, x, false));
                        let keep = match (h, l) {
                            (Some(h), Some(l)) => (h - x).dot(l - x) < -1e-9,
                            _ => true,
                        };
                        if keep {
                            assert!(
                                ps.iter().any(|pc| pc.edge == k
                                    && approx(&e, &pc.bot) <= t + 1e-9
                                    && t <= approx(&e, &pc.top) + 1e-9),
                                "t={t} on edge {k} of {chain:?} is in no piece: {ps:?}"
                            );
                        }
                    }
                }
            }
        }
        assert!(
            checked > 500 && shadows > 50,
            "{checked} samples, {shadows} shadow ends"
        );
    }
}
