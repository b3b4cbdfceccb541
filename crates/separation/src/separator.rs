//! Amato's separator `S(P, Q)` for two disjoint simple polygons whose convex hulls meet (N. M.
//! Amato, UIUC report UILU-ENG-92-2248, 1992, section 2; the construction of \[A92\] is only cited
//! there: this is the reconstruction of `docs/algorithms/separator.md`): the non-containing case,
//! the pinched channel, and the containing case (one polygon in a pocket of the other, see
//! [`regions`]).
//!
//! Steps (names as in the doc):
//! 1. **Facing chains.** The hull of `CH(P) ∪ CH(Q)` has exactly two *bridges* (hull edges joining a
//!    vertex of `P` to one of `Q`) when the polygons are disjoint and neither hull contains the
//!    other. Bridges are shrunk to the extreme collinear vertices. `P′` runs counter-clockwise on
//!    `P` from `p_b` to `p_t`, `Q′` clockwise on `Q` from `q_b` to `q_t`.
//! 2. **Region.** `R` is bounded by the ring `p_b, Q′, p_t, P′ reversed` (counter-clockwise).
//! 3. **Geodesic.** The shortest path `π` from `p_b` to `p_t` in `R` (triangulation, funnel).
//! 4. **Extensions.** Each run of `π` that step 5 asks for is prolonged both ways to the first
//!    boundary point of `R`, by a walk in the triangulation (or the shortest-path trees' extensions
//!    once the walks are long); endpoints keep their provenance (a ring vertex, or a ring edge with
//!    the line of the run: a symbolic point, never rounded).
//! 5. **Greedy pruning** (property (ii)): keep the first run; from the last kept, keep the
//!    largest-indexed extension that still meets it (found by a galloping search).
//! 6. **Cuts and subchains** (report 001's rule, with its sentinels), read from provenance.
//! 7. **Subproblems.** `σ(P, Q) = min σ(P_i, Q_i)`.
//!
//! Every decision is an exact sign of degree at most 4.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::predicates::{Dist2, Kernel, Orientation, Sign};
use polydist_polygon::{Feature, SimplePolygon, convex_hull_of_two_with};

#[cfg(test)]
use crate::brute::separation_brute;
use crate::brute::{
    Near, Seen, Winner, boxes_farther_than, cmp_scan_cut, farther_from_line_than,
    scan_pruned_winner_below, scan_winner_below_except, upper_bound,
};
use crate::error::SeparationError;
use crate::gapped::separation_of_gapped;
use crate::geodesic::{Hit, first_hit_within, merge_collinear, shortest_path};
use crate::monotone::sweep_chains;
use crate::param::{Affine, Edge, Param};
use crate::pockets::{Pruned, Wall, walls};
use crate::result::{ClosestPair, SeparationStats};
use crate::sigma::{ChainMethod, build as build_pair, chains};
use crate::spm::{Extensions, extensions};
use crate::triangulate::{Triangulation, triangulate};

/// Why [`facing`] did not build the region: the other constructions take over.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unsupported {
    /// One hull contains the other: `P`'s when `p_inside`, else `Q`'s (a polygon in a pocket of the
    /// other).
    Containing {
        /// Whether `CH(P) ⊆ CH(Q)`.
        p_inside: bool,
    },
    /// `Q` touches the hull of the union in a single vertex: the polygons are swapped.
    Pinched,
}

/// The region `R` between the facing chains: its ring and where each ring vertex comes from.
#[derive(Clone, Debug)]
pub(crate) struct Region {
    /// The ring, counter-clockwise: `p_b` (0), `Q′` from `q_b` (1) to `q_t` (`qt`), then `p_t`
    /// (`qt + 1`) and `P′` backwards down to the vertex after `p_b`.
    pub(crate) ring: Vec<DVec2>,
    /// The internal index, in its polygon, of each ring vertex.
    pub(crate) src: Vec<usize>,
    /// The ring index of `q_t`.
    pub(crate) qt: usize,
    /// `P`'s internal index of `p_b`.
    pub(crate) pb: usize,
    /// Vertices of `P`.
    pub(crate) np: usize,
    /// The position of `p_t` along the `P` wall: `np` when the wall is all of `P` (pinched and
    /// containing cases, where `p_b` and `p_t` are two copies of one vertex).
    pub(crate) top: usize,
    /// The ring edge of the `Q` wall that is no part of `Q` (the lid of the pocket holding `P`, in
    /// the containing case): subchains are split there.
    pub(crate) gap: Option<usize>,
    /// When `p_b` and `p_t` are one point: a diagonal (a ring vertex of the `P` wall, one of the `Q`
    /// wall) through a vertex of the geodesic that cuts the weakly simple ring into two strictly
    /// simple halves (triangulated apart and glued along it).
    pub(crate) cut: Option<(usize, usize)>,
    /// The containing case: the `Q` points whose pairs this pass answers for (see [`Share`]);
    /// `None`: every pair.
    pub(crate) share: Option<Share>,
}

/// In the containing case, the `Q` points whose closest pairs a pass answers for: those strictly
/// above `level` (`above`), or those at or below it, in direction `turn` (as in [`turned`]); `level`
/// is `P`'s top level. `Q` subchains are trimmed to the edges with an end in the share.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Share {
    pub(crate) turn: u8,
    pub(crate) level: f64,
    pub(crate) above: bool,
}

impl Share {
    /// Whether `v` is in the share (an exact comparison of input coordinates).
    fn holds(&self, v: DVec2) -> bool {
        (turned(v, self.turn).y > self.level) == self.above
    }
}

impl Region {
    /// The ring index of `p_t`.
    pub(crate) fn pt(&self) -> usize {
        self.qt + 1
    }

    /// Whether ring vertex `r` is a vertex of `P` (otherwise of `Q`).
    pub(crate) fn is_p(&self, r: usize) -> bool {
        r == 0 || r > self.qt
    }

    /// The position of `P`-ring vertex `r` along `P′`, from `p_b` (0) to `p_t`.
    pub(crate) fn pos_p(&self, r: usize) -> usize {
        if r == self.pt() {
            self.top
        } else {
            (self.src[r] + self.np - self.pb) % self.np
        }
    }

    /// The position of `p_t` along `P′`.
    pub(crate) fn top_p(&self) -> usize {
        self.top
    }

    /// The ring of `R` from the facing chains: `p_b`, `Q`'s vertices `qs` (clockwise on `Q`, from
    /// `q_b` to `q_t`), `p_t`, then `P` clockwise from `p_t` down to the vertex after `p_b` (all of
    /// `P` when `p_b = p_t`).
    fn from_chains(vp: &[DVec2], vq: &[DVec2], pb: usize, pt: usize, qs: &[usize]) -> Region {
        let np = vp.len();
        let mut ring = Vec::with_capacity(qs.len() + np + 1);
        let mut src = Vec::with_capacity(qs.len() + np + 1);
        ring.push(vp[pb]);
        src.push(pb);
        for &j in qs {
            ring.push(vq[j]);
            src.push(j);
        }
        let qt = ring.len() - 1;
        let mut i = pt;
        loop {
            ring.push(vp[i]);
            src.push(i);
            i = (i + np - 1) % np;
            if i == pb {
                break;
            }
        }
        let top = if pb == pt { np } else { (pt + np - pb) % np };
        Region {
            ring,
            src,
            qt,
            pb,
            np,
            top,
            gap: None,
            cut: None,
            share: None,
        }
    }

    /// The ring index of `P`'s vertex `v` (`v ≠ p_b` when `p_b = p_t`).
    fn ring_of_p(&self, v: usize) -> usize {
        if v == self.pb && self.top != self.np {
            0
        } else {
            self.pt() + (self.src[self.pt()] + self.np - v) % self.np
        }
    }

    /// The end points of ring edge `e`.
    fn edge(&self, e: usize) -> (DVec2, DVec2) {
        (self.ring[e], self.ring[(e + 1) % self.ring.len()])
    }
}

/// The indices `from, from − 1, …, to` (mod `n`): a polygon's vertices clockwise from `from` to `to`.
fn clockwise(n: usize, from: usize, to: usize) -> Vec<usize> {
    let steps = (from + n - to) % n;
    (0..=steps).map(|k| (from + n - k) % n).collect()
}

/// The internal indices of `p`'s hull vertices, counter-clockwise (Melkman's hull keeps the
/// polygon's order; a walk along the ring names each hull vertex). `O(n)`.
fn hull_indices<K: Kernel>(p: &SimplePolygon) -> Vec<usize> {
    p.convex_hull_and_indices_with::<K>().1
}

/// Step 1 and 2: the bridges of `CH(P ∪ Q)`, the facing chains and the ring of `R` (with its cut
/// when `P` is pinched). `Err` when one hull contains the other, or `Q` is the pinched polygon:
/// [`regions`] takes over.
///
/// `O(n + m)`: the hulls, the hull of the `h` hull vertices (`convex_hull_of_two_with`, a merge
/// of their lexicographic runs), the ring.
fn facing<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    hp: &[usize],
    hq: &[usize],
) -> Result<Result<Region, Unsupported>, SeparationError> {
    let (vp, vq) = (p.vertices(), q.vertices());
    let mut pts: Vec<DVec2> = hp.iter().map(|&i| vp[i]).collect();
    pts.extend(hq.iter().map(|&j| vq[j]));
    let uh =
        convex_hull_of_two_with::<K>(&pts, hp.len()).map_err(|_| SeparationError::Inconsistent)?;
    let h = uh.len();
    // (is P, position in its own hull list) of union-hull vertex i.
    let tag = |i: usize| {
        let s = uh.source_index(i % h);
        if s < hp.len() {
            (true, s)
        } else {
            (false, s - hp.len())
        }
    };
    let mut up = None; // P → Q bridge (union-hull order)
    let mut down = None; // Q → P bridge
    let mut bridges = 0;
    for i in 0..h {
        let (a, b) = (tag(i), tag(i + 1));
        if a.0 != b.0 {
            bridges += 1;
            if a.0 {
                up = Some((a.1, b.1));
            } else {
                down = Some((b.1, a.1));
            }
        }
    }
    if bridges == 0 {
        return Ok(Err(Unsupported::Containing {
            p_inside: (0..h).all(|i| !tag(i).0),
        }));
    }
    let (Some((px, qy)), Some((pw, qz)), 2) = (up, down, bridges) else {
        return Err(SeparationError::Inconsistent);
    };
    // Shrink a bridge (x on one hull, y on the other) to the extreme collinear vertices: a hull
    // neighbour of x strictly between x and y on the bridge's line replaces x.
    let shrink = |hull: &[usize], verts: &[DVec2], x: usize, y: DVec2| -> usize {
        let n = hull.len();
        if n < 2 {
            return x;
        }
        for nb in [(x + 1) % n, (x + n - 1) % n] {
            let (a, c) = (verts[hull[x]], verts[hull[nb]]);
            if K::orient(a, y, c) == Orientation::Collinear
                && K::dot_sign(c, a, c, y) == Sign::Negative
            {
                return nb;
            }
        }
        x
    };
    let (px, qy) = (
        shrink(hp, vp, px, vq[hq[qy]]),
        shrink(hq, vq, qy, vp[hp[px]]),
    );
    let (pw, qz) = (
        shrink(hp, vp, pw, vq[hq[qz]]),
        shrink(hq, vq, qz, vp[hp[pw]]),
    );
    let (pb, qb, qt, pt) = (hp[px], hq[qy], hq[qz], hp[pw]);
    if qb == qt {
        // Q touches the hull of the union at one vertex: the caller swaps the polygons.
        return Ok(Err(Unsupported::Pinched));
    }
    let nq = vq.len();
    let qs = clockwise(nq, qb, qt);
    let mut r = Region::from_chains(vp, vq, pb, pt, &qs);
    if pb == pt {
        // Pinched at p_b: cut the ring from a vertex of CH(P) other than p_b.
        r.cut = Some(pinch_cut::<K>(&r).ok_or(SeparationError::Inconsistent)?);
    }
    Ok(Ok(r))
}

/// The regions whose separators cover every sight between `P` and `Q`, and whether the polygons
/// were swapped to build them (the caller swaps the answer back).
///
/// - Non-containing case: one region (steps 1–2).
/// - Pinched channel (one polygon touches `CH(P ∪ Q)` at one vertex `v`): one weakly simple region,
///   `v` twice on its ring (notes 5.1); the polygons are swapped when `Q` is the pinched one.
/// - Containing case ([`pocket_regions`]): `P` in a pocket of `Q` (or the reverse, swapped).
///
/// `Ok(None)` when one polygon lies inside the other (no pocket holds it): the polygons meet, which
/// the callers rule out ([`separation_of_disjoint`](crate::separation_of_disjoint)'s precondition).
pub(crate) fn regions<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    hp: &[usize],
    hq: &[usize],
) -> Result<Option<(Vec<Region>, bool)>, SeparationError> {
    match facing::<K>(p, q, hp, hq)? {
        Ok(r) => Ok(Some((vec![r], false))),
        Err(Unsupported::Pinched) => match facing::<K>(q, p, hq, hp)? {
            Ok(r) => Ok(Some((vec![r], true))),
            Err(_) => Err(SeparationError::Inconsistent),
        },
        Err(Unsupported::Containing { p_inside: true }) => {
            Ok(pocket_regions::<K>(p, q, hq)?.map(|r| (r, false)))
        }
        Err(Unsupported::Containing { p_inside: false }) => {
            Ok(pocket_regions::<K>(q, p, hp)?.map(|r| (r, true)))
        }
    }
}

/// `v` turned by `turn` quarter turns so that direction `turn` becomes `+y` (0: `+y`, 1: `−x`,
/// 2: `−y`, 3: `+x`). Exact (negations and swaps), and orientation-preserving.
fn turned(v: DVec2, turn: u8) -> DVec2 {
    match turn % 4 {
        0 => v,
        1 => DVec2::new(v.y, -v.x),
        2 => -v,
        _ => DVec2::new(-v.y, v.x),
    }
}

/// The index of the point of `pts` (a non-empty iterator of `(index, point)`) that is greatest in
/// direction `turn`, ties broken by the turned `x`: a vertex of the points' convex hull.
fn extreme(pts: impl Iterator<Item = (usize, DVec2)>, turn: u8) -> Option<usize> {
    pts.map(|(i, v)| (i, turned(v, turn)))
        .max_by(|a, b| {
            a.1.y
                .total_cmp(&b.1.y)
                .then(a.1.x.total_cmp(&b.1.x))
                .then(b.0.cmp(&a.0))
        })
        .map(|(i, _)| i)
}

/// A vertex of the simple polygon `outer` that sees `u` (a point inside it, greatest of a set `S`
/// in direction `turn`, with `S` inside `outer` and its hull below `u`'s level) along an open
/// segment lying strictly beyond `u`'s level: the classical bridge of a hole to its outer boundary
/// (as in ear-clipping with holes). The ray from `u` in direction `turn` first meets `outer` at a
/// vertex (the answer) or inside an edge `(a, b)` at `h`; then the answer is, among `outer`'s vertices
/// in the closed triangle `(u, h, w)` (`w` the end of the edge farther along the ray), the one of
/// least angle to the ray, the nearest on ties. Every point of the triangle but `u` lies strictly
/// beyond `u`'s level, so `S` does not obstruct; no edge of `outer` crosses the chosen segment, since
/// such an edge would have an end inside the triangle at a smaller angle.
///
/// Every decision is an orientation or a comparison of input coordinates (turned exactly);
/// `h` is never constructed. `O(n)`. `None` only under inconsistent signs (Fast) or when `u` is
/// not inside `outer`.
fn cut_target<K: Kernel>(outer: &[DVec2], u: DVec2, turn: u8) -> Option<usize> {
    let n = outer.len();
    let t = |i: usize| turned(outer[i % n], turn);
    let u = turned(u, turn);
    #[derive(Clone, Copy)]
    enum Hit {
        Vertex(usize),
        // An edge (left end, right end) crossing the ray's line strictly between its ends.
        Edge(usize, usize),
    }
    let below = |a: Hit, b: Hit| -> bool {
        // Whether `a`'s point on the ray is strictly below `b`'s (they never cross).
        match (a, b) {
            (Hit::Vertex(i), Hit::Vertex(j)) => t(i).y < t(j).y,
            (Hit::Vertex(i), Hit::Edge(l, r)) => {
                K::orient(t(l), t(r), t(i)) == Orientation::Clockwise
            }
            (Hit::Edge(l, r), Hit::Vertex(j)) => {
                K::orient(t(l), t(r), t(j)) == Orientation::CounterClockwise
            }
            (Hit::Edge(l1, r1), Hit::Edge(l2, r2)) => {
                // Two edges of a simple polygon over a common x range do not cross: an end of one
                // inside the other's range decides, unless it is a shared end; then the right ends.
                let (a1, b1, a2, b2) = (t(l1), t(r1), t(l2), t(r2));
                let by_right_ends = || {
                    if b1.x <= b2.x {
                        K::orient(a2, b2, b1) == Orientation::Clockwise
                    } else {
                        K::orient(a1, b1, b2) == Orientation::CounterClockwise
                    }
                };
                if a1.x >= a2.x {
                    match K::orient(a2, b2, a1) {
                        Orientation::Clockwise => true,
                        Orientation::CounterClockwise => false,
                        Orientation::Collinear => by_right_ends(),
                    }
                } else {
                    match K::orient(a1, b1, a2) {
                        Orientation::CounterClockwise => true,
                        Orientation::Clockwise => false,
                        Orientation::Collinear => by_right_ends(),
                    }
                }
            }
        }
    };
    let mut first: Option<Hit> = None;
    for i in 0..n {
        let (a, b) = (t(i), t(i + 1));
        let mut cand = None;
        if a.x == u.x && a.y > u.y {
            cand = Some(Hit::Vertex(i));
        } else if (a.x < u.x) != (b.x < u.x) && a.x != u.x && b.x != u.x {
            let (l, r) = if a.x < b.x {
                (i, (i + 1) % n)
            } else {
                ((i + 1) % n, i)
            };
            if K::orient(t(l), t(r), u) == Orientation::Clockwise {
                cand = Some(Hit::Edge(l, r));
            }
        }
        if let Some(c) = cand
            && first.is_none_or(|f| below(c, f))
        {
            first = Some(c);
        }
    }
    let (l, r) = match first? {
        Hit::Vertex(i) => return Some(i),
        Hit::Edge(l, r) => (l, r),
    };
    let w = if t(r).y >= t(l).y { r } else { l };
    let right = t(w).x > u.x;
    let toward_h = if right {
        Orientation::CounterClockwise
    } else {
        Orientation::Clockwise
    };
    let mut best = w;
    for z in 0..n {
        let p = t(z);
        if z == w || (p.x > u.x) != right || p.x == u.x {
            continue;
        }
        if K::orient(t(l), t(r), p) == Orientation::CounterClockwise {
            continue;
        }
        let s = K::orient(u, t(w), p);
        let inside = s == toward_h || (s == Orientation::Collinear && p.y <= t(w).y);
        if !inside {
            continue;
        }
        let o = K::orient(u, t(best), p);
        // Nearer the ray (on `h`'s side of the line through `best`), or on that line and nearer.
        let better = o == toward_h || (o == Orientation::Collinear && p.y < t(best).y);
        if better {
            best = z;
        }
    }
    Some(best)
}

/// The cut of a pinched ring (`p_b = p_t = v`): from the vertex `u ≠ v` of `P` greatest in one of
/// the four axis directions (a vertex of `CH(P)`, so of the geodesic, which is the boundary of `P`'s
/// relative hull) to the vertex of the outer boundary `v, Q′, v` that [`cut_target`] finds. `v` is
/// not beyond `u`'s level, so the cut never ends there.
fn pinch_cut<K: Kernel>(r: &Region) -> Option<(usize, usize)> {
    let n = r.ring.len();
    let outer = &r.ring[..=r.qt];
    for turn in 0..4 {
        let u = extreme((r.pt()..n).map(|i| (i, r.ring[i])), turn)?;
        if u == r.pt() {
            continue;
        }
        let w = cut_target::<K>(outer, r.ring[u], turn)?;
        return (w != 0).then_some((u, w));
    }
    None
}

/// The containing case (notes 5.2): `CH(P) ⊆ CH(Q)`, so `P` lies in a pocket `K` of `Q` (closed by
/// a lid `(A, B)`, a hull edge of `Q` that is no edge of `Q`) or inside `Q` (`None`: the polygons
/// meet).
///
/// - `P` touches the lid (some vertices on it): the channel runs from the last of them along the
///   lid, `p_b`, to the first, `p_t`, with the bridges on the lid: the non-containing layout, pinched
///   when there is one such vertex.
/// - Otherwise `R = K \ P` is an annulus, and every sight from `P` to `∂K` misses one of two cuts:
///   `c_T` from `P`'s top vertex `p_top` up to a vertex of `∂K`, `c_B` from its bottom vertex down
///   (both by [`cut_target`]). `c_T` lies strictly above `P`'s top level but for `p_top`, `c_B`
///   strictly below its bottom level; a sight from `p ∈ P` meeting `c_T` at a point other than `p`
///   rises from then on, so it never comes back down to `c_B`. So two regions: the annulus cut along
///   `c_T` (a weakly simple ring: `p_top` and `c_T`'s other end twice) and the annulus cut along
///   `c_B`; each is triangulated in two halves split by the other cut, and `σ` is the least over the
///   subproblems of both. The lid is a ring edge of the `Q` wall, the region's `gap`. Each pass
///   answers for a share of `Q` ([`Share`]): a closest pair `(p, y)` whose sight meets `c_T` does so
///   at a point `z` other than `p` and other than `p_top` (a sight through a vertex of `P` is no
///   closest pair), strictly above `P`'s top level while `p` is not, so the sight rises and `y` lies
///   strictly above the top level. Conversely, when `y` lies strictly above it the sight stays at or
///   above `p`'s level, which is not below `P`'s bottom level, so it misses `c_B` (it could meet it
///   only at `p = p_bot`, its own start). So the `c_T` region answers for the `Q` points at or below
///   the top level, the `c_B` region for those strictly above (any level between `P`'s bottom and
///   top levels would do), and each `Q` subchain is trimmed to the edges with an end in its pass's
///   share (and dropped when it has none).
///
/// `O(n + m)`.
fn pocket_regions<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    hq: &[usize],
) -> Result<Option<Vec<Region>>, SeparationError> {
    let (vp, vq) = (p.vertices(), q.vertices());
    let (np, nq) = (vp.len(), vq.len());
    let top = extreme(vp.iter().copied().enumerate(), 0).ok_or(SeparationError::Inconsistent)?;
    let x = vp[top];
    // The pocket holding P: the lid whose pocket (A, A + 1, …, B, closed by the lid) holds `x`, by
    // the parity of the crossings of a rightward ray (half-open in y; exact side tests). `x` on the
    // lid puts P in that pocket.
    // The lids: consecutive vertices of Q on the hull's boundary (collinear ones included: Q's
    // edges along a hull edge are walls of Q, and a chain touching the hull edge between two
    // notches splits them into two pockets) that are not consecutive on Q.
    let h = hq.len();
    let mut lids = Vec::new();
    for i in 0..h {
        let (a0, b0) = (hq[i], hq[(i + 1) % h]);
        let mut last = a0;
        let mut j = a0;
        for _ in 0..nq {
            j = (j + 1) % nq;
            if j == b0 || K::orient(vq[a0], vq[b0], vq[j]) == Orientation::Collinear {
                if (last + 1) % nq != j {
                    lids.push((last, j));
                }
                last = j;
            }
            if j == b0 {
                break;
            }
        }
    }
    let mut lid = None;
    for (a, b) in lids {
        let mut inside = false;
        let mut j = a;
        for _ in 0..nq {
            let k = if j == b { a } else { (j + 1) % nq };
            let (c, d) = (vq[j], vq[k]);
            let o = K::orient(c, d, x);
            if o == Orientation::Collinear && K::dot_sign(x, c, x, d) != Sign::Positive {
                // On the pocket's boundary: on its lid, since P and Q are disjoint.
                inside = true;
                break;
            }
            if (c.y > x.y) != (d.y > x.y) {
                match (o, d.y > c.y) {
                    (Orientation::CounterClockwise, true) | (Orientation::Clockwise, false) => {
                        inside = !inside;
                    }
                    _ => {}
                }
            }
            if j == b {
                break;
            }
            j = k;
        }
        if inside {
            lid = Some((a, b));
            break;
        }
    }
    let Some((a, b)) = lid else {
        return Ok(None);
    };
    // Q clockwise from B to A: the pocket's wall, counter-clockwise around K.
    let chain = clockwise(nq, b, a);
    let on_lid: Vec<usize> = (0..np)
        .filter(|&i| K::orient(vq[a], vq[b], vp[i]) == Orientation::Collinear)
        .collect();
    if !on_lid.is_empty() {
        // Along the lid from A to B: p_t is the first of P's vertices on it, p_b the last.
        let along = |i: &usize, j: &usize| match K::dot_sign(vp[*i], vp[*j], vq[a], vq[b]) {
            Sign::Positive => Ordering::Less,
            Sign::Negative => Ordering::Greater,
            Sign::Zero => Ordering::Equal,
        };
        let pt = on_lid.iter().copied().min_by(along);
        let pb = on_lid.iter().copied().max_by(along);
        let (Some(pb), Some(pt)) = (pb, pt) else {
            return Err(SeparationError::Inconsistent);
        };
        let mut r = Region::from_chains(vp, vq, pb, pt, &chain);
        if pb == pt {
            r.cut = Some(pinch_cut::<K>(&r).ok_or(SeparationError::Inconsistent)?);
        }
        return Ok(Some(vec![r]));
    }
    // The annulus: K's ring counter-clockwise is the lid A → B, then the chain from B down to A + 1.
    let kq: Vec<usize> = core::iter::once(a)
        .chain(chain[..chain.len() - 1].iter().copied())
        .collect();
    let kp: Vec<DVec2> = kq.iter().map(|&j| vq[j]).collect();
    let bottom = extreme(vp.iter().copied().enumerate(), 2).ok_or(SeparationError::Inconsistent)?;
    let vt = cut_target::<K>(&kp, vp[top], 0).ok_or(SeparationError::Inconsistent)?;
    let vb = cut_target::<K>(&kp, vp[bottom], 2).ok_or(SeparationError::Inconsistent)?;
    if vt == vb || top == bottom {
        return Err(SeparationError::Inconsistent);
    }
    let make = |pv: usize, kv: usize, other_p: usize, other_k: usize| {
        let qs: Vec<usize> = (0..=kq.len()).map(|s| kq[(kv + s) % kq.len()]).collect();
        let mut r = Region::from_chains(vp, vq, pv, pv, &qs);
        r.gap = (1..r.qt).find(|&g| r.src[g] == a && r.src[g + 1] == b);
        let w = (2..r.qt).find(|&g| r.src[g] == kq[other_k]);
        r.cut = w.map(|w| (r.ring_of_p(other_p), w));
        r.cut.map(|_| r).ok_or(SeparationError::Inconsistent)
    };
    let (mut cut_t, mut cut_b) = (make(top, vt, bottom, vb)?, make(bottom, vb, top, vt)?);
    // A closest pair whose `Q` point lies strictly above `P`'s top level misses `c_B`, one whose
    // `Q` point does not misses `c_T`: each pass answers for one share.
    let level = turned(vp[top], 0).y;
    cut_t.share = Some(Share {
        turn: 0,
        level,
        above: false,
    });
    cut_b.share = Some(Share {
        turn: 0,
        level,
        above: true,
    });
    Ok(Some(vec![cut_t, cut_b]))
}

/// Triangulates the weakly simple ring of a pinched or containing region through its cut `(u, w)`:
/// the two strictly simple halves `w..=u` and `u..=w` (around the ring) are triangulated apart and
/// their triangles glued along the cut, which is then a diagonal. The geodesic from `p_b` (0) to
/// `p_t` passes through `u` (a vertex of `CH(P)`, on the boundary of `P`'s relative hull, which the
/// geodesic is; and the cut lies beyond `u`'s level, which the geodesic never passes): it is the
/// shortest path from `p_b` to `u` in the second half followed by the one from `u` to `p_t` in the
/// first. `O(N log N)` as [`triangulate`], `O(N)` for the paths.
fn halves<K: Kernel>(
    r: &Region,
    u: usize,
    w: usize,
    cache: &mut Halves,
) -> Option<(Triangulation, Vec<usize>)> {
    let (ring, n, t) = (&r.ring, r.ring.len(), r.pt());
    if !(1..=r.qt).contains(&w) || !(t + 1..n).contains(&u) {
        return None;
    }
    let h1: Vec<usize> = (w..=u).collect();
    let h2: Vec<usize> = (u..n).chain(0..=w).collect();
    let pts = |h: &[usize]| h.iter().map(|&i| ring[i]).collect::<Vec<DVec2>>();
    let (r1, r2) = (pts(&h1), pts(&h2));
    let (t1, t2) = (cache.triangulate::<K>(&r1)?, cache.triangulate::<K>(&r2)?);
    let tri = Triangulation::joined(n, (&h1, &t1), (&h2, &t2))?;
    let first = shortest_path::<K>(&t2, &r2, n - u, 0);
    let second = shortest_path::<K>(&t1, &r1, u - w, t - w);
    let path: Vec<usize> = first
        .iter()
        .map(|&i| h2[i])
        .chain(second.iter().skip(1).map(|&i| h1[i]))
        .collect();
    Some((tri, merge_collinear::<K>(ring, &path)))
}

/// Halves of weakly simple rings already triangulated, kept for the other pass of the containing
/// case: its ring is cut into the same two polygons, their vertex lists rotated (the annulus cut
/// along both `c_T` and `c_B`). A half is looked up by its vertex sequence (equal up to rotation,
/// checked point for point) and its triangles relabelled; otherwise it is triangulated and kept.
#[derive(Default)]
pub(crate) struct Halves {
    kept: Vec<(Vec<DVec2>, Triangulation)>,
}

impl Halves {
    /// A triangulation of the simple polygon `pts`. `O(n)` when a rotation of it is kept (the
    /// lookup and the relabelling), else [`triangulate`]'s `O(n log n)`.
    fn triangulate<K: Kernel>(&mut self, pts: &[DVec2]) -> Option<Triangulation> {
        let m = pts.len();
        for (c, tris) in &self.kept {
            let Some(off) = (c.len() == m)
                .then(|| c.iter().position(|&x| x == pts[0]))
                .flatten()
            else {
                continue;
            };
            if (0..m).all(|i| c[(i + off) % m] == pts[i]) {
                // Vertex `i` of `pts` is kept vertex `i + off` (mod m).
                return Some(tris.rotated(off));
            }
        }
        let t = triangulate::<K>(pts).ok()?;
        self.kept.push((pts.to_vec(), t.clone()));
        Some(t)
    }
}

/// An end of an extended run: the run's own vertex (no arm), or the first boundary point its arm
/// meets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// The arm has zero length: the end is the run's vertex.
    Run,
    /// The arm stops at ring vertex `r`.
    Vertex(usize),
    /// The arm stops inside ring edge `e` (at its crossing with the run's line).
    Edge(usize),
}

/// An extended run `ℓ_j`: the run from ring vertex `lo` to ring vertex `hi` of the geodesic, with
/// its two ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Seg {
    pub(crate) lo: usize,
    pub(crate) hi: usize,
    pub(crate) bottom: End,
    pub(crate) top: End,
}

/// A point of a segment's line, for exact comparisons along another line through it.
#[derive(Clone, Copy, Debug)]
enum Locus {
    Point(DVec2),
    /// The crossing of the segment's line with the line through these points.
    Cross(DVec2, DVec2),
}

impl Seg {
    fn line(&self, r: &Region) -> Edge {
        Edge {
            a: r.ring[self.lo],
            b: r.ring[self.hi],
        }
    }

    fn locus(&self, r: &Region, top: bool) -> Locus {
        match (if top { self.top } else { self.bottom }, top) {
            (End::Run, false) => Locus::Point(r.ring[self.lo]),
            (End::Run, true) => Locus::Point(r.ring[self.hi]),
            (End::Vertex(w), _) => Locus::Point(r.ring[w]),
            (End::Edge(e), _) => {
                let (c, d) = r.edge(e);
                Locus::Cross(c, d)
            }
        }
    }
}

/// The parameter on `line` of a point of it.
fn param(line: &Edge, x: Locus) -> Param {
    Param::Root(match x {
        Locus::Point(c) => Affine {
            cross: false,
            c,
            v0: line.a,
            v1: line.b,
            neg: false,
        },
        Locus::Cross(c, d) => Affine {
            cross: true,
            c,
            v0: c,
            v1: d,
            neg: false,
        },
    })
}

/// The closed parameter interval of `s` on its own line.
fn interval(r: &Region, s: &Seg, line: &Edge) -> (Param, Param) {
    let lo = match s.bottom {
        End::Run => Param::Start,
        _ => param(line, s.locus(r, false)),
    };
    let hi = match s.top {
        End::Run => Param::End,
        _ => param(line, s.locus(r, true)),
    };
    (lo, hi)
}

/// Which copy of the cut an end lies on, in a weakly simple region (`p_b` and `p_t` one point):
/// `Some(false)` on `p_b`'s side (`p_b` itself, and in the containing case the cut's other end
/// `q_b` and the ring edge `p_b → q_b`), `Some(true)` on `p_t`'s side; `None` elsewhere or when the
/// ring is strictly simple. Two such ends on opposite copies are different points of the cut
/// region even where they coincide in the plane.
fn copy_side(r: &Region, x: End, run_vertex: usize) -> Option<bool> {
    let pt = r.pt();
    if r.ring[0] != r.ring[pt] {
        return None;
    }
    let annulus = r.ring[1] == r.ring[r.qt];
    match x {
        End::Run if run_vertex == 0 => Some(false),
        End::Run if run_vertex == pt => Some(true),
        End::Vertex(0) => Some(false),
        End::Vertex(v) if v == pt => Some(true),
        End::Vertex(1) | End::Edge(0) if annulus => Some(false),
        End::Vertex(v) | End::Edge(v) if annulus && v == r.qt => Some(true),
        _ => None,
    }
}

/// Whether the extended runs `s` and `t` meet (closed segments) in the region `R` (cut open along
/// its cut when `R` is weakly simple: meeting only at a point of the cut reached from its two
/// copies is not meeting). Exact, degree ≤ 4.
pub(crate) fn meets<K: Kernel>(r: &Region, s: &Seg, t: &Seg) -> bool {
    matches!(meeting::<K>(r, s, t), Meeting::BelowTop | Meeting::AtTop)
}

/// How two extended runs meet ([`meets`]), and what a longer `t` (its top end moved on along its
/// line, as its top arm does) would change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Meeting {
    /// They do not meet, and would not with any longer `t`.
    Apart,
    /// They do not meet, but a longer `t` might.
    Short,
    /// They meet, and would with any longer `t`: they cross strictly below `t`'s top end, or
    /// overlap along a stretch of positive length.
    BelowTop,
    /// They meet in a way a longer `t` need not keep (at `t`'s top end, or at one point of a
    /// collinear overlap).
    AtTop,
}

/// [`meets`], and what a longer `t` would change: step 5 tests a run with its bottom arm only
/// first, and the top arm is walked only when the answer is [`Meeting::Short`] or
/// [`Meeting::AtTop`].
///
/// Why. Moving `t`'s top end on along its line only widens `t`'s interval upwards; its bottom end
/// stays. If the lines cross, the crossing stays where it is: outside `s`'s interval or below
/// `t`'s bottom it stays outside; strictly below the old top it stays inside and is no end of the
/// new `t` but the same bottom, so the copies of the cut found there are those found before (a
/// meeting, or a meeting across the cut, stays one). Parallel lines that are not one line never
/// meet. The rest (a crossing at or beyond the old top, a collinear pair) is left to the longer
/// `t` itself, but a collinear overlap of positive length, which keeps its length.
fn meeting<K: Kernel>(r: &Region, s: &Seg, t: &Seg) -> Meeting {
    let (ls, lt) = (s.line(r), t.line(r));
    let (is, it) = (interval(r, s, &ls), interval(r, t, &lt));
    let within = |line: &Edge, (lo, hi): (Param, Param), x: Param| {
        line.cmp::<K>(&lo, &x) != Ordering::Greater && line.cmp::<K>(&x, &hi) != Ordering::Greater
    };
    // The copy of the cut that an end of `x` at parameter `at` on `line` lies on, if any.
    let side_at = |x: &Seg, line: &Edge, at: &Param| {
        [(x.bottom, x.lo, false), (x.top, x.hi, true)]
            .into_iter()
            .find_map(|(e, v, top)| {
                let side = copy_side(r, e, v)?;
                let p = param(line, x.locus(r, top));
                (line.cmp::<K>(&p, at) == Ordering::Equal).then_some(side)
            })
    };
    let across = |a: Option<bool>, b: Option<bool>| matches!((a, b), (Some(x), Some(y)) if x != y);
    if K::cross_sign(ls.a, ls.b, lt.a, lt.b) != Sign::Zero {
        let on_s = param(&ls, Locus::Cross(lt.a, lt.b));
        let on_t = param(&lt, Locus::Cross(ls.a, ls.b));
        if !within(&ls, is, on_s) || lt.cmp::<K>(&it.0, &on_t) == Ordering::Greater {
            return Meeting::Apart;
        }
        let top = lt.cmp::<K>(&on_t, &it.1);
        if top == Ordering::Greater {
            return Meeting::Short;
        }
        let cut_apart = across(side_at(s, &ls, &on_s), side_at(t, &lt, &on_t));
        return match (cut_apart, top) {
            (false, Ordering::Less) => Meeting::BelowTop,
            (false, _) => Meeting::AtTop,
            (true, Ordering::Less) => Meeting::Apart,
            (true, _) => Meeting::Short,
        };
    }
    if K::orient(ls.a, ls.b, lt.a) != Orientation::Collinear {
        return Meeting::Apart;
    }
    // Collinear: compare the four ends on `s`'s line.
    let (mut a, mut b) = (param(&ls, t.locus(r, false)), param(&ls, t.locus(r, true)));
    if ls.cmp::<K>(&a, &b) == Ordering::Greater {
        core::mem::swap(&mut a, &mut b);
    }
    let lo = if ls.cmp::<K>(&is.0, &a) == Ordering::Less {
        a
    } else {
        is.0
    };
    let hi = if ls.cmp::<K>(&is.1, &b) == Ordering::Less {
        is.1
    } else {
        b
    };
    match ls.cmp::<K>(&lo, &hi) {
        Ordering::Greater => Meeting::Short,
        Ordering::Less => Meeting::BelowTop,
        Ordering::Equal if across(side_at(s, &ls, &lo), side_at(t, &ls, &lo)) => Meeting::Short,
        Ordering::Equal => Meeting::AtTop,
    }
}

/// A built separator: the region and the kept extended runs.
#[derive(Clone, Debug)]
pub(crate) struct Built {
    pub(crate) region: Region,
    /// Every extended run `ℓ_j` (the property checker's; the construction builds the arms of the
    /// runs step 5 tests only).
    #[cfg(test)]
    pub(crate) runs: Vec<Seg>,
    /// The kept segments `l_0 … l_{m−1}`.
    pub(crate) segs: Vec<Seg>,
    /// Their indices `j` among the runs.
    pub(crate) kept: Vec<usize>,
    /// Subchains: `P′` positions `[lo, hi]` and `Q′` ring positions `[lo, hi]` per kept segment.
    pub(crate) sub: Vec<((usize, usize), (usize, usize))>,
    /// The cuts `(p⁺(i), q⁺(i))` as `(low, high)` covers: `P′` positions and ring positions.
    #[cfg_attr(
        not(test),
        expect(dead_code, reason = "read by the property checker of the tests")
    )]
    pub(crate) cuts: Vec<((usize, usize), (usize, usize))>,
    /// Cuts that were not where the construction puts them (0 under exact kernels, checked in
    /// tests); the subchain then runs to the end of the wall (a superset, still sound).
    pub(crate) cut_fallbacks: usize,
}

/// `(low, high)` wall positions covering an end or a run vertex.
fn cover_p(r: &Region, x: End, run_vertex: usize) -> Option<(usize, usize)> {
    match x {
        End::Run => r
            .is_p(run_vertex)
            .then(|| (r.pos_p(run_vertex), r.pos_p(run_vertex))),
        End::Vertex(w) => r.is_p(w).then(|| (r.pos_p(w), r.pos_p(w))),
        // P ring edges are pt..n−1: from ring e (higher on P′) to ring e + 1 (lower).
        End::Edge(e) => (e >= r.pt()).then(|| {
            let n = r.ring.len();
            (r.pos_p((e + 1) % n), r.pos_p(e))
        }),
    }
}

fn cover_q(r: &Region, x: End, run_vertex: usize) -> Option<(usize, usize)> {
    match x {
        End::Run => (run_vertex <= r.pt()).then_some((run_vertex, run_vertex)),
        End::Vertex(w) => (w <= r.pt()).then_some((w, w)),
        End::Edge(e) => (e <= r.qt).then_some((e, e + 1)),
    }
}

/// The highest `(low, high)` cover among candidates (by high, then low).
fn highest(c: impl IntoIterator<Item = Option<(usize, usize)>>) -> Option<(usize, usize)> {
    c.into_iter()
        .flatten()
        .max_by(|x, y| x.1.cmp(&y.1).then(x.0.cmp(&y.0)))
}

/// The separators of every region of [`regions`], and whether the polygons were swapped.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    /// One pass per region: one, or two in the containing case.
    pub(crate) passes: Vec<Built>,
    /// Whether `P` and `Q` were swapped to build the regions.
    pub(crate) swapped: bool,
}

/// Steps 1–6 for every region. `None` when one polygon lies inside the other (they meet).
#[cfg_attr(
    not(test),
    expect(dead_code, reason = "the query passes the hulls it has built")
)]
pub(crate) fn build<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
) -> Result<Option<Plan>, SeparationError> {
    build_with_hulls::<K>(p, q, &hull_indices::<K>(p), &hull_indices::<K>(q))
}

/// [`build`], given each polygon's Melkman hull as internal vertex indices
/// ([`SimplePolygon::convex_hull_and_indices_with`]).
pub(crate) fn build_with_hulls<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    hp: &[usize],
    hq: &[usize],
) -> Result<Option<Plan>, SeparationError> {
    let Some((rs, swapped)) = regions::<K>(p, q, hp, hq)? else {
        return Ok(None);
    };
    let (wp, wq) = walls((p, hp), (q, hq), swapped);
    // The containing case's two regions are cut into the same two halves: triangulated once.
    let mut halves = Halves::default();
    let passes = rs
        .into_iter()
        .map(|r| build_region_pruned::<K>(r, &mut halves, wp, wq))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Some(Plan { passes, swapped }))
}

/// Step 4: the runs of the geodesic `path` with their arms (each run prolonged beyond its ends to
/// the first boundary point), each built when step 5 first asks for it (`Arms::seg_with`), so
/// that only the runs the greedy pruning tests get arms. An arm is walked in the triangulation
/// while the walks stay within `budget` triangle steps in all (`16n + 64`); past it, or as soon as
/// the steps of the first [`EXTRAPOLATE_AFTER`] or more arms, scaled from the part of the path
/// step 5 has settled (an eighth at least) to the whole path, exceed twice the budget, the
/// remaining arms are read from the extensions of the two shortest-path trees from `path`'s ends
/// ([`extensions`], `O(n)`), whose edges the runs are. So step 4 costs `O(n)` in all (the paper's
/// bound), where the walks alone cost `Θ(n²)` in the worst case. Both give the same hits (tested).
///
/// A walk step costs about 60 instructions, a tree about 700 a ring vertex. When step 5 keeps few
/// runs it asks for few arms (the star in a pocket at 32,768 vertices: 134 arms of its 8,192 runs,
/// some 2,000 steps each, `12.8n` steps in all), so the walks answer alone; on the spirals at
/// 131,072 vertices, whose arms cross ever more triangles as the walls are sampled finer, the
/// walks spend their budget and the trees are built after all. Only the work depends on the
/// choice.
struct Arms<'a, R, I> {
    tri: &'a Triangulation,
    ring: &'a [DVec2],
    path: &'a [usize],
    /// The walks' budget left, and the one they started with.
    budget: usize,
    total: usize,
    /// Arms walked so far.
    walked: usize,
    /// The trees from the path's start (forward arms) and end (backward arms), built on demand.
    trees: [Option<Extensions>; 2],
    resolve: R,
    index: I,
    /// The runs built so far, by index.
    memo: Vec<Option<Seg>>,
    /// The bottom arms walked so far, by run index (step 5 tries a run with it alone first).
    bottoms: Vec<Option<End>>,
    /// The run step 5 has settled the path up to (its last kept run).
    progress: usize,
}

impl<'a, R, I> Arms<'a, R, I>
where
    R: FnMut(usize, usize, Hit) -> Option<End>,
    I: Fn(usize) -> usize,
{
    fn new(
        tri: &'a Triangulation,
        ring: &'a [DVec2],
        path: &'a [usize],
        budget: usize,
        resolve: R,
        index: I,
    ) -> Self {
        Arms {
            tri,
            ring,
            path,
            budget,
            total: budget,
            walked: 0,
            trees: [None, None],
            resolve,
            index,
            memo: vec![None; path.len().saturating_sub(1)],
            bottoms: vec![None; path.len().saturating_sub(1)],
            progress: 0,
        }
    }

    /// The arm of the run from `path` vertex `from` through `through`, beyond `through`.
    fn arm<K: Kernel>(&mut self, from: usize, through: usize, forward: bool) -> Option<End> {
        // Once step 5 has settled an eighth of the path or more, and the steps walked so far,
        // scaled from that part to the whole path, would exceed twice the budget (the scaling
        // overestimates: the first kept runs' searches reach far), the walks stop early:
        // the trees will be built anyway, and the steps left would be spent for nothing (arms that
        // cross more triangles the finer the walls are sampled: the spirals at 131,072 vertices).
        // Only the work depends on it.
        let k = self.memo.len();
        if self.walked >= EXTRAPOLATE_AFTER
            && self.progress.saturating_mul(8) >= k
            && (self.total - self.budget).saturating_mul(k)
                > self.total.saturating_mul(2 * self.progress)
        {
            self.budget = 0;
        }
        self.walked += 1;
        let (tri, ring, path) = (self.tri, self.ring, self.path);
        // Once the budget is spent the walk is not even started (its first step turns around
        // `through`, `O(degree)`).
        let walked = (self.budget > 0)
            .then(|| first_hit_within::<K>(tri, ring, from, through, &mut self.budget))
            .flatten();
        let hit = walked.or_else(|| {
            let k = path.len() - 1;
            let (slot, s) = if forward { (0, path[0]) } else { (1, path[k]) };
            let tree = self.trees[slot].get_or_insert_with(|| extensions::<K>(tri, ring, s));
            tree.hit[through]
        });
        (self.resolve)(from, through, hit.unwrap_or(Hit::Immediate))
    }

    /// The bottom arm of run `j`, walked on first use.
    fn bottom<K: Kernel>(&mut self, j: usize) -> Option<End> {
        if let Some(b) = self.bottoms.get(j).copied().flatten() {
            return Some(b);
        }
        let path = self.path;
        if j >= self.memo.len() {
            return None;
        }
        let bottom = if j == 0 {
            End::Run
        } else {
            self.arm::<K>(path[j + 1], path[j], false)?
        };
        self.bottoms[j] = Some(bottom);
        Some(bottom)
    }

    /// Run `j` with its bottom arm and no top arm (its top end the run's vertex): a part of the
    /// extended run `ℓ_j`, for step 5's first test.
    fn seg_below<K: Kernel>(&mut self, j: usize) -> Option<Seg> {
        let bottom = self.bottom::<K>(j)?;
        Some(Seg {
            lo: (self.index)(self.path[j]),
            hi: (self.index)(self.path[j + 1]),
            bottom,
            top: End::Run,
        })
    }

    /// Run `j` with its arms, built on first use.
    fn seg_with<K: Kernel>(&mut self, j: usize) -> Option<Seg> {
        if let Some(s) = self.memo.get(j).copied().flatten() {
            return Some(s);
        }
        let (path, k) = (self.path, self.memo.len());
        let below = self.seg_below::<K>(j)?;
        let top = if j + 1 == k {
            End::Run
        } else {
            self.arm::<K>(path[j], path[j + 1], true)?
        };
        let s = Seg { top, ..below };
        self.memo[j] = Some(s);
        Some(s)
    }
}

/// Every run of `path` with its arms ([`Arms`], all of them asked for in order): the tests' list.
#[cfg(test)]
fn runs_with_arms<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    path: &[usize],
    budget: usize,
    resolve: impl FnMut(usize, usize, Hit) -> Option<End>,
    index: impl Fn(usize) -> usize,
) -> Option<Vec<Seg>> {
    let mut arms = Arms::new(tri, ring, path, budget, resolve, index);
    // Sized up front (collecting into an `Option` would grow it by doubling).
    let mut segs = Vec::with_capacity(arms.memo.len());
    for j in 0..arms.memo.len() {
        segs.push(arms.seg_with::<K>(j)?);
    }
    Some(segs)
}

/// Arms walked before [`Arms`] extrapolates their steps to all the runs.
const EXTRAPOLATE_AFTER: usize = 16;

/// A hit as an end on the ring walked (no pruned pockets).
fn plain(_: usize, _: usize, hit: Hit) -> Option<End> {
    Some(match hit {
        Hit::Vertex(w) => End::Vertex(w),
        Hit::Edge(e) => End::Edge(e),
        Hit::Immediate => End::Run,
    })
}

/// Step 3: the region's triangulation and the geodesic from `p_b` (ring vertex 0) to `p_t`.
fn geodesic_of<K: Kernel>(
    region: &Region,
    cache: &mut Halves,
) -> Result<(Triangulation, Vec<usize>), SeparationError> {
    let (tri, path) = match region.cut {
        None => {
            let tri = triangulate::<K>(&region.ring).map_err(|_| SeparationError::Inconsistent)?;
            let path = shortest_path::<K>(&tri, &region.ring, 0, region.pt());
            (tri, path)
        }
        Some((u, w)) => halves::<K>(region, u, w, cache).ok_or(SeparationError::Inconsistent)?,
    };
    if path.len() < 2 || path[0] != 0 || path[path.len() - 1] != region.pt() {
        return Err(SeparationError::Inconsistent);
    }
    Ok((tri, path))
}

/// Steps 3–6 in one region: the separator and the subchains.
pub(crate) fn build_region<K: Kernel>(
    region: Region,
    cache: &mut Halves,
) -> Result<Built, SeparationError> {
    let (tri, path) = geodesic_of::<K>(&region, cache)?;
    let budget = 16 * region.ring.len() + 64;
    let arms = Arms::new(&tri, &region.ring, &path, budget, plain, |i| i);
    let sel = select::<K, _, _>(&region, arms).ok_or(SeparationError::Inconsistent)?;
    Ok(finish(region, sel))
}

/// [`build_region`] with the unentered pockets of the walls cut off before triangulating
/// ([`pockets`](crate::pockets)): the geodesic of the reduced region, its arms carried on into the
/// pockets they enter, then steps 5–6 on the full region. Falls back to [`build_region`] when
/// nothing is pruned, or the walks in the pockets exceed their budget (`8N + 64` triangle steps:
/// so the pruning costs `O(N)` beyond the unpruned construction, `O(N log N)` in all).
fn build_region_pruned<K: Kernel>(
    region: Region,
    cache: &mut Halves,
    p: Wall<'_>,
    q: Wall<'_>,
) -> Result<Built, SeparationError> {
    let Some(pruned) = crate::pockets::prune::<K>(&region, p, q) else {
        return build_region::<K>(region, cache);
    };
    match pruned_selection::<K>(&region, &pruned, cache) {
        Some(sel) => Ok(finish(region, sel)),
        None => build_region::<K>(region, cache),
    }
}

/// Steps 3–5 on the reduced region, the runs and their ends read on the full ring (`region`);
/// `None` when the reduced region fails or the pocket walks exceed their budget (`8N + 64` steps,
/// `N` the full ring's size).
fn pruned_selection<K: Kernel>(
    region: &Region,
    pruned: &Pruned<'_>,
    cache: &mut Halves,
) -> Option<Selection> {
    let (tri, path) = geodesic_of::<K>(&pruned.region, cache).ok()?;
    let ring = &pruned.region.ring;
    let mut pocket_budget = 8 * pruned.full_len() + 64;
    let arms = Arms::new(
        &tri,
        ring,
        &path,
        16 * ring.len() + 64,
        |from, through, hit| pruned.resolve::<K>(from, through, hit, &mut pocket_budget),
        |i| pruned.keep[i],
    );
    select::<K, _, _>(region, arms)
}

/// Step 5's choice: the kept runs' indices and the runs themselves (and, in the tests, every run,
/// for the property checker).
pub(crate) struct Selection {
    kept: Vec<usize>,
    segs: Vec<Seg>,
    #[cfg(test)]
    runs: Vec<Seg>,
}

/// Step 5, greedy pruning: keep `ℓ_0`; from the last kept `ℓ_a`, keep the largest `j` with
/// `ℓ_j ∩ ℓ_a ≠ ∅`. The runs meeting `ℓ_a` form an interval after it (`ℓ_{a+1}` always meets it:
/// they share `v_{a+1}`; that the rest is an interval is the notes' belief, asserted on every case
/// by the checker), so its end is found by a galloping search — offsets 1, 2, 4, … from `a + 1`
/// until a miss, then bisection — in `O(log(j − a))` meeting tests, where the forward scan up to
/// the first miss took `j − a`: `O(m log(k/m))` tests and arms for `m` kept of `k` runs instead
/// of `O(k)` (the same `j` as the scan whenever the belief holds; where it would not, both keep
/// a run that meets `ℓ_a` followed by one that misses it). `None` when an arm fails.
fn select<K, R, I>(region: &Region, mut src: Arms<'_, R, I>) -> Option<Selection>
where
    K: Kernel,
    R: FnMut(usize, usize, Hit) -> Option<End>,
    I: Fn(usize) -> usize,
{
    let k = src.memo.len();
    let first = src.seg_with::<K>(0)?;
    // At most one kept run a run, reserved up front: growing by doubling would touch twice the
    // memory (the combs keep half their runs).
    let (mut kept, mut segs) = (Vec::with_capacity(k), Vec::with_capacity(k));
    kept.push(0);
    segs.push(first);
    let mut a = 0;
    while a + 1 < k {
        let la = segs[segs.len() - 1];
        // Run `x` with its bottom arm alone first ([`meeting`]): its top arm is walked only when
        // that leaves the answer open, or when the run is kept.
        let mut meets_a = |x: usize| -> Option<bool> {
            if let Some(whole) = src.memo.get(x).copied().flatten() {
                return Some(meets::<K>(region, &la, &whole));
            }
            let below = src.seg_below::<K>(x)?;
            let m = meeting::<K>(region, &la, &below);
            // The tests check the shortcut against the whole run on every case.
            #[cfg(test)]
            {
                let full = meets::<K>(region, &la, &src.seg_with::<K>(x)?);
                assert!(
                    !matches!(
                        (m, full),
                        (Meeting::BelowTop, false) | (Meeting::Apart, true)
                    ),
                    "step 5's shortcut {m:?} disagrees with the whole run ({full})"
                );
            }
            Some(match m {
                Meeting::BelowTop => true,
                Meeting::Apart => false,
                _ => meets::<K>(region, &la, &src.seg_with::<K>(x)?),
            })
        };
        let (mut lo, mut hi, mut step) = (a + 1, k, 1);
        while lo + step < k {
            if meets_a(lo + step)? {
                lo += step;
                step *= 2;
            } else {
                hi = lo + step;
                break;
            }
        }
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if meets_a(mid)? {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        kept.push(lo);
        segs.push(src.seg_with::<K>(lo)?);
        a = lo;
        src.progress = a;
    }
    Some(Selection {
        #[cfg(test)]
        runs: (0..k)
            .map(|j| src.seg_with::<K>(j))
            .collect::<Option<Vec<_>>>()?,
        kept,
        segs,
    })
}

/// Step 6: the cuts and the subchains of the kept runs.
fn finish(region: Region, sel: Selection) -> Built {
    let Selection {
        kept,
        segs,
        #[cfg(test)]
        runs,
    } = sel;
    // Step 6: cuts p⁺(i), q⁺(i) as (low, high) covers, then report 001's subchains.
    let m = kept.len();
    let top_p = region.top_p();
    let mut cut_fallbacks = 0;
    let mut pc = Vec::with_capacity(m);
    let mut qc = Vec::with_capacity(m);
    for (i, s) in segs.iter().enumerate() {
        if i + 1 == m {
            pc.push((top_p, top_p));
            qc.push((region.qt, region.qt));
            continue;
        }
        let cp = highest([
            cover_p(&region, s.top, s.hi),
            cover_p(&region, End::Run, s.hi),
            cover_p(&region, End::Run, s.lo),
            cover_p(&region, s.bottom, s.lo),
        ]);
        let cq = highest([
            cover_q(&region, s.top, s.hi),
            cover_q(&region, End::Run, s.hi),
            cover_q(&region, End::Run, s.lo),
            cover_q(&region, s.bottom, s.lo),
        ]);
        pc.push(cp.unwrap_or_else(|| {
            cut_fallbacks += 1;
            (0, top_p)
        }));
        qc.push(cq.unwrap_or_else(|| {
            cut_fallbacks += 1;
            (1, region.qt)
        }));
    }
    let p_cut = |i: isize| -> (usize, usize) {
        if i < 0 {
            (0, 0)
        } else {
            pc[(i as usize).min(m - 1)]
        }
    };
    let q_cut = |i: isize| -> (usize, usize) {
        if i < 0 {
            (1, 1)
        } else {
            qc[(i as usize).min(m - 1)]
        }
    };
    let mut sub = Vec::with_capacity(m);
    for (i, s) in segs.iter().enumerate() {
        let ii = i as isize;
        let last = i + 1 == m;
        let top_on_p = cover_p(&region, s.top, s.hi).is_some();
        let top_on_q = cover_q(&region, s.top, s.hi).is_some();
        let p_end = if top_on_p || last {
            p_cut(ii)
        } else {
            p_cut(ii + 1)
        };
        let q_end = if top_on_q || last {
            q_cut(ii)
        } else {
            q_cut(ii + 1)
        };
        let (plo, phi) = (p_cut(ii - 1).0, p_end.1);
        let (qlo, qhi) = (q_cut(ii - 1).0.max(1), q_end.1.min(region.qt));
        let prange = if plo <= phi {
            (plo, phi)
        } else {
            cut_fallbacks += 1;
            (phi, plo)
        };
        let qrange = if qlo <= qhi {
            (qlo, qhi)
        } else {
            cut_fallbacks += 1;
            (qhi, qlo)
        };
        sub.push((prange, qrange));
    }
    Built {
        region,
        #[cfg(test)]
        runs,
        segs,
        kept,
        sub,
        cuts: pc.iter().copied().zip(qc.iter().copied()).collect(),
        cut_fallbacks,
    }
}

/// A candidate pair in internal features of `P` and `Q`.
fn dist_of(p: &[DVec2], q: &[DVec2], fp: Feature, fq: Feature) -> Dist2 {
    let (np, nq) = (p.len(), q.len());
    match (fp, fq) {
        (Feature::Vertex(i), Feature::Vertex(j)) => Dist2::PointPoint(p[i % np], q[j % nq]),
        (Feature::Vertex(i), Feature::Edge(f)) => {
            Dist2::PointSegment(p[i % np], q[f % nq], q[(f + 1) % nq])
        }
        (Feature::Edge(e), Feature::Vertex(j)) => {
            Dist2::PointSegment(q[j % nq], p[e % np], p[(e + 1) % np])
        }
        // Two edges never realize a separation alone (a vertex–edge or vertex–vertex pair ties).
        (Feature::Edge(e), Feature::Edge(f)) => {
            Dist2::PointSegment(p[e % np], q[f % nq], q[(f + 1) % nq])
        }
    }
}

/// Step 7: `σ(P, Q) = min σ(P_i, Q_i)` over the subproblems of every pass, in `P`'s and `Q`'s
/// internal features, with the work done.
///
/// Each subproblem of more than [`SCAN_BELOW`] vertex pairs is given to section 3
/// ([`chains`]) across the line of its run, in the parts [`split`] hands it (peeled
/// ends, or runs for both assignments of sides, the rest scanned in linear time, or the subchains
/// clipped to the line, [`separation_of_gapped`]). Small subproblems, thin ones (a subchain of at
/// most [`THIN`] vertices: linear), and any that section 3
/// rejects (only under the Fast kernel in our tests), are scanned exactly in `O(|P_i| · |Q_i|)`,
/// pruned by bounding boxes when large. A `Q` subchain that spans the region's gap (a pocket's lid,
/// no part of `Q`) is split there.
pub(crate) fn solve<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    plan: &Plan,
) -> Result<(ClosestPair, SeparationStats), SeparationError> {
    solve_with::<K>(p, q, plan, SCAN_BELOW)
}

/// [`solve`], scanning the subproblems of at most `scan_below` vertex pairs without trying section 3
/// (the tests also run it with `0`, so that every subproblem is offered to section 3).
fn solve_with<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    plan: &Plan,
    scan_below: usize,
) -> Result<(ClosestPair, SeparationStats), SeparationError> {
    let (p, q) = if plan.swapped { (q, p) } else { (p, q) };
    let mut stats = SeparationStats::default();
    let mut best: Option<Best> = None;
    // The large subproblems that go to clipped chains (or must be scanned whole) wait for every
    // other one: the clipping and the scans skip what cannot beat the best answer, and the scans
    // what lies farther from their separator ([`Near`]).
    let mut later = vec![Vec::new(); plan.passes.len()];
    for (b, later) in plan.passes.iter().zip(&mut later) {
        solve_pass::<K>(
            p,
            q,
            b,
            scan_below,
            &mut stats,
            &mut best,
            Pick::Defer(later),
        );
    }
    for (b, later) in plan.passes.iter().zip(&later) {
        if !later.is_empty() {
            solve_pass::<K>(
                p,
                q,
                b,
                scan_below,
                &mut stats,
                &mut best,
                Pick::Only(later),
            );
        }
    }
    let Best { found, .. } = best.ok_or(SeparationError::Inconsistent)?;
    let pair = match found {
        Found::Pair(pair) => pair,
        Found::Scanned(w, feature_p, feature_q) => ClosestPair {
            feature_p,
            feature_q,
            ..w.pair()
        },
    };
    let pair = if plan.swapped {
        ClosestPair {
            point_p: pair.point_q,
            point_q: pair.point_p,
            feature_p: pair.feature_q,
            feature_q: pair.feature_p,
            ..pair
        }
    } else {
        pair
    };
    Ok((pair, stats))
}

/// The best subproblem answer so far: a pair section 3 constructed, or a scan's winner (constructed
/// once, for the final winner only) with its internal features.
enum Found {
    Pair(ClosestPair),
    Scanned(Winner, Feature, Feature),
}

/// The best answer so far, its squared distance, and an upper bound of that in `f64` (from the
/// scans' filter bounds): scans skip the candidates bounded strictly above it.
struct Best {
    found: Found,
    d: Dist2,
    cut: f64,
}

/// Which parts of a pass's subproblems [`solve_pass`] takes, as `(subproblem, part)`: a part is one
/// side of the region's gap.
enum Pick<'a> {
    /// Every part, except that those of more than [`PRUNE_ABOVE`] vertex pairs that go to clipped
    /// chains (or would be scanned whole) are left for later, in order.
    Defer(&'a mut Vec<(usize, usize)>),
    /// Only these (in order), whatever their size.
    Only(&'a [(usize, usize)]),
}

/// The subproblems of one pass, those `pick` takes, folded into `best`.
fn solve_pass<K: Kernel>(
    p: &SimplePolygon,
    q: &SimplePolygon,
    b: &Built,
    scan_below: usize,
    stats: &mut SeparationStats,
    best: &mut Option<Best>,
    mut pick: Pick<'_>,
) {
    let (vp, vq) = (p.vertices(), q.vertices());
    let r = &b.region;
    if let Pick::Defer(_) = pick {
        stats.separator_segments += b.kept.len();
        stats.cut_fallbacks += b.cut_fallbacks;
    }
    let (mut pcv, mut qcv) = (Vec::new(), Vec::new());
    // The positions `(plo, phi, qlo, qhi)` of the last subproblem scanned whole: the pairs it
    // shares with a later scanned subproblem are not scanned twice.
    let mut last_scanned: Option<(usize, usize, usize, usize)> = None;
    for (i, &((plo, phi), (qlo_all, qhi_all))) in b.sub.iter().enumerate() {
        let parts = match r.gap {
            Some(g) if qlo_all <= g && g < qhi_all => [(qlo_all, g), (g + 1, qhi_all)],
            _ => [(qlo_all, qhi_all), (1, 0)],
        };
        let s = &b.segs[i];
        let (a, c) = (r.ring[s.lo], r.ring[s.hi]);
        // Built for the scans that need it only (most subproblems are small).
        let near = || near_of(r, s);
        for (part, (qlo, qhi)) in parts.into_iter().enumerate() {
            if qlo > qhi || matches!(pick, Pick::Only(o) if o.binary_search(&(i, part)).is_err()) {
                continue;
            }
            let Some((qlo, qhi)) = trimmed(r, qlo, qhi) else {
                continue;
            };
            // Ends deeper than the best answer so far cannot hold a better pair (trimmed off the
            // subproblems that are not scanned anyway: the scans skip such pairs on their own).
            let cut = best.as_ref().map_or(f64::INFINITY, |b| b.cut);
            let trim = if (phi + 1 - plo) * (qhi + 1 - qlo) > scan_below {
                cut
            } else {
                f64::INFINITY
            };
            let at_p = |k: usize| vp[(r.pb + k) % r.np];
            let Some((plo, phi)) = shallow::<K>(plo, phi, at_p, a, c, trim) else {
                continue;
            };
            let Some((qlo, qhi)) = shallow::<K>(qlo, qhi, |k| r.ring[k], a, c, trim) else {
                continue;
            };
            // Ends far from the other subchain's box or from `l_i` cannot hold a better pair
            // either (not when every subproblem is offered whole to section 3, so that the tests
            // reach Step G on the stars: this trim leaves it little).
            let ends = if scan_below > 0 { trim } else { f64::INFINITY };
            let Some(((plo, phi), (qlo, qhi))) =
                near_ends(at_p, |k| r.ring[k], (plo, phi), (qlo, qhi), &near, ends)
            else {
                continue;
            };
            pcv.clear();
            pcv.extend((plo..=phi).map(at_p));
            qcv.clear();
            qcv.extend((qlo..=qhi).map(|k| r.ring[k]));
            // Candidates that cannot beat the best so far are skipped by the scans.
            let mut fold = |fp: Feature, fq: Feature, found| {
                // Subchain features to internal features.
                let fp = match fp {
                    Feature::Vertex(k) => Feature::Vertex((r.pb + plo + k) % r.np),
                    Feature::Edge(k) => Feature::Edge((r.pb + plo + k) % r.np),
                };
                let fq = match fq {
                    Feature::Vertex(k) => Feature::Vertex(r.src[qlo + k]),
                    Feature::Edge(k) => Feature::Edge(r.src[qlo + k + 1]),
                };
                let found = match found {
                    Ok(pair) => Found::Pair(ClosestPair {
                        feature_p: fp,
                        feature_q: fq,
                        ..pair
                    }),
                    Err(w) => Found::Scanned(w, fp, fq),
                };
                let d = dist_of(vp, vq, fp, fq);
                // Subproblem winners tie with the best on rectilinear input (combs): compared as
                // coordinate gaps there, as the scans compare them; others are first bounded
                // against the best's cut (most of the jittered combs' teeth are farther).
                if best
                    .as_ref()
                    .is_none_or(|b| cmp_scan_cut::<K>(d, b.d, b.cut) == Ordering::Less)
                {
                    *best = Some(Best {
                        found,
                        d,
                        cut: upper_bound::<K>(d),
                    });
                }
            };
            // Small subproblems are scanned: section 3's set-up costs more than the few pairs.
            // So are thin ones (one subchain of at most `THIN` vertices), in linear time: about
            // `3·THIN` candidates a vertex of the other, cheaper than section 3's work a vertex.
            let thin = scan_below > 0 && pcv.len().min(qcv.len()) <= THIN;
            let jobs = if thin || pcv.len() * qcv.len() <= scan_below {
                None
            } else {
                Some(split::<K>(&pcv, &qcv, a, c))
            };
            // A large part that goes to section 3 on clipped chains, or is scanned (pruned:
            // [`scan_part`]'s test), waits when deferring: the best answer of all the others then
            // trims it (only its parts near the line can beat that). A thin scan is linear and
            // goes first: its answer is a cut for the others.
            let large = pcv.len() * qcv.len() > PRUNE_ABOVE;
            if large && !thin && jobs.as_ref().is_none_or(|j| !j.gapped.is_empty()) {
                if let Pick::Defer(later) = &mut pick {
                    later.push((i, part));
                    continue;
                }
            }
            let found =
                jobs.and_then(|jobs| execute::<K>(&pcv, &qcv, (a, c), near, &jobs, cut, stats));
            stats.subproblem_vertices += pcv.len() + qcv.len();
            match found {
                Some(found) => {
                    stats.subproblems_section3 += 1;
                    for (fp, fq, f) in found {
                        fold(fp, fq, f);
                    }
                }
                None => {
                    stats.subproblems_scanned += 1;
                    stats.subproblems_scanned_large += usize::from(large);
                    let seen = last_scanned.map_or(Seen::NONE, |(p0, p1, q0, q1)| Seen {
                        p: overlap(plo, phi, p0, p1),
                        q: overlap(qlo, qhi, q0, q1),
                    });
                    let w = scan_part::<K>(&pcv, &qcv, cut, seen, near);
                    let (fp, fq) = w.features();
                    fold(fp, fq, Err(w));
                    // A pruned scan leaves out pairs far from `l_i`, which a later subproblem may
                    // have to find: it counts as seeing nothing.
                    last_scanned = (!large).then_some((plo, phi, qlo, qhi));
                }
            }
        }
    }
}

/// The subchain `lo..=hi` (positions; `at` gives the vertex) without its end edges that lie
/// certainly farther than `√cut` from the line through `a` and `c`, both ends on one side: every
/// point of such an edge is (depth is affine along it). A pair that Lemma 1 assigns to the
/// subproblem meets `l_i` (notes 4.8), so it is at least as long as either point's distance to the
/// line: no such pair has a point on a trimmed edge and beats a distance whose square is at most
/// `cut`. `None` when every edge is trimmed and the last vertex is too deep as well. Exact signs
/// and the scans' filter bounds; `O(trimmed + 1)`.
fn shallow<K: Kernel>(
    lo: usize,
    hi: usize,
    at: impl Fn(usize) -> DVec2,
    a: DVec2,
    c: DVec2,
    cut: f64,
) -> Option<(usize, usize)> {
    if !cut.is_finite() {
        return Some((lo, hi));
    }
    let deep = |k: usize| {
        let v = at(k);
        farther_from_line_than(v, a, c, cut).then(|| K::orient(a, c, v))
    };
    // An edge is deep when both ends are, on one side of the line; each end is decided once.
    let (mut lo, mut hi) = (lo, hi);
    let mut at_lo = deep(lo);
    while lo < hi && at_lo.is_some() {
        let next = deep(lo + 1);
        if next != at_lo {
            break;
        }
        lo += 1;
        at_lo = next;
    }
    let mut at_hi = if hi == lo { at_lo } else { deep(hi) };
    while hi > lo && at_hi.is_some() {
        let prev = if hi - 1 == lo { at_lo } else { deep(hi - 1) };
        if prev != at_hi {
            break;
        }
        hi -= 1;
        at_hi = prev;
    }
    (lo < hi || at_lo.is_none()).then_some((lo, hi))
}

/// The subchains `P_i = p..` and `Q_i = q..` (positions; `at_p`, `at_q` give the vertices) without
/// their end edges whose every point lies certainly farther than `√cut` from every point of the other
/// subchain (the box of the edges, tried [`NEAR_BOXES`] at a time and then one at a time, against
/// the boxes of [`NEAR_BOXES`] consecutive stretches of the other) or from `l_i` (the box against
/// [`Near`]): a pair that Lemma 1 assigns to the subproblem meets `l_i` (notes 4.8), so neither of its
/// points is farther from the other, or from `l_i`, than its length, and none on such an edge beats a
/// distance whose square is at most `cut`. `P_i` is trimmed first, against `Q_i`'s box, then `Q_i`
/// against what is left of `P_i`. Subchains stay contiguous. `None` when one subchain has nothing
/// left. Coordinate comparisons and the scans' filter bounds, no predicate;
/// `O(|P_i| + |Q_i|)` for the boxes and `O(NEAR_BOXES)` tests per trimmed stretch or edge, only when
/// `cut` is finite.
fn near_ends(
    at_p: impl Fn(usize) -> DVec2,
    at_q: impl Fn(usize) -> DVec2,
    p: (usize, usize),
    q: (usize, usize),
    near: &impl Fn() -> Near,
    cut: f64,
) -> Option<((usize, usize), (usize, usize))> {
    if !cut.is_finite() {
        return Some((p, q));
    }
    let near = near();
    // The boxes of up to `NEAR_BOXES` consecutive stretches of a subchain (each holds its
    // stretch's vertices and the edges between them; consecutive stretches share a vertex).
    let boxes = |at: &dyn Fn(usize) -> DVec2, (lo, hi): (usize, usize)| {
        let step = (hi - lo).div_ceil(NEAR_BOXES).max(1);
        (lo..hi.max(lo + 1))
            .step_by(step)
            .map(|s| {
                (s..=(s + step).min(hi))
                    .map(at)
                    .fold((at(s), at(s)), |(l, h), v| (l.min(v), h.max(v)))
            })
            .collect::<Vec<_>>()
    };
    let trim = |at: &dyn Fn(usize) -> DVec2, (mut lo, mut hi): (usize, usize), other: Vec<_>| {
        // Whether the stretch `k..=l` (its box) is certainly too far.
        let far = |k: usize, l: usize| {
            let b = (k..=l)
                .map(at)
                .fold((at(k), at(k)), |(lo, hi), v| (lo.min(v), hi.max(v)));
            other.iter().all(|&o| boxes_farther_than(b, o, cut)) || near.box_gap2(b.0, b.1) > cut
        };
        // Whole stretches of `NEAR_BOXES` edges first, then single edges.
        for step in [NEAR_BOXES, 1] {
            while lo + step <= hi && far(lo, lo + step) {
                lo += step;
            }
            while hi >= lo + step && far(hi - step, hi) {
                hi -= step;
            }
        }
        (lo < hi || !far(lo, lo)).then_some((lo, hi))
    };
    let p = trim(&at_p, p, boxes(&at_q, q))?;
    let q = trim(&at_q, q, boxes(&at_p, p))?;
    Some((p, q))
}

/// The `Q` subchain `qlo..=qhi` (ring positions) trimmed to the edges with an end in the pass's
/// [`Share`], if it has one: from the vertex before the first vertex in it to the one after the
/// last. Every point of the share lies on such an edge (an edge with both ends outside the share
/// lies outside it: each share is a half-plane). `None` when no vertex is in the share (no point of
/// the subchain is). `O(qhi − qlo)` coordinate comparisons.
fn trimmed(r: &Region, qlo: usize, qhi: usize) -> Option<(usize, usize)> {
    let Some(b) = r.share else {
        return Some((qlo, qhi));
    };
    let first = (qlo..=qhi).find(|&k| b.holds(r.ring[k]))?;
    let last = (first..=qhi).rev().find(|&k| b.holds(r.ring[k]))?;
    Some((first.saturating_sub(1).max(qlo), (last + 1).min(qhi)))
}

/// The exact scan of two parts of subproblem `i`: candidates whose squared distance is bounded
/// strictly above `cut` (the best answer so far's) are skipped, so the winner is the parts' nearest
/// pair when that beats the best so far, and some pair of the parts otherwise.
///
/// When large (the containing case's long subchains, subproblems that cross their line too often
/// for [`split`]) the scan is pruned by bounding boxes, and also by the distance to `l_i`
/// ([`Near`]): its winner is then no farther than every pair the subproblem must find (Lemma 1
/// assigns it only pairs meeting `l_i`) that beats the best so far. The plain scan leaves out the
/// pairs of `seen` (which an earlier scan took).
fn scan_part<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    cut: f64,
    seen: Seen,
    near: impl Fn() -> Near,
) -> Winner {
    if p.len() * q.len() > PRUNE_ABOVE {
        scan_pruned_winner_below::<K>(p, q, cut, Some(&near())).0
    } else {
        scan_winner_below_except::<K>(p, q, cut, seen).0
    }
}

/// Where `l_i = s` lies, for the scans ([`Near`]): on the line of its run, between the run's
/// vertices or its arms' ends (an arm ending inside a ring edge ends between that edge's ends).
fn near_of(r: &Region, s: &Seg) -> Near {
    let end = |x: End, run_vertex: usize| match x {
        End::Run => [r.ring[run_vertex]; 2],
        End::Vertex(w) => [r.ring[w]; 2],
        End::Edge(e) => {
            let (u, w) = r.edge(e);
            [u, w]
        }
    };
    Near {
        a: r.ring[s.lo],
        c: r.ring[s.hi],
        before: end(s.bottom, s.lo),
        after: end(s.top, s.hi),
    }
}

/// The positions `lo..=hi` that also lie in `lo0..=hi0`, as a half-open range of local indices
/// (counted from `lo`); empty when the two are disjoint.
fn overlap(lo: usize, hi: usize, lo0: usize, hi0: usize) -> core::ops::Range<usize> {
    let (a, b) = (lo.max(lo0), hi.min(hi0));
    if a > b { 0..0 } else { a - lo..b + 1 - lo }
}

/// A candidate of one subproblem, in features of its subchains: a pair section 3 built or a
/// scan's winner.
type Candidate = (Feature, Feature, Result<ClosestPair, Winner>);

/// Runs `jobs` on the subchains `p`, `q` of subproblem `i` (line through `a`, `c`; `near` says
/// where `l_i` lies, for the scans): every candidate, in the subchains' features; `None` when
/// section 3 rejects a part (the caller scans the subproblem). Parts the monotone sweep answers
/// instead of section 3 are counted in `swept`.
fn execute<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    (a, c): (DVec2, DVec2),
    near: impl Fn() -> Near,
    jobs: &Jobs,
    cut: f64,
    stats: &mut SeparationStats,
) -> Option<Vec<Candidate>> {
    let shift = |f: Feature, by: usize| match f {
        Feature::Vertex(k) => Feature::Vertex(k + by),
        Feature::Edge(k) => Feature::Edge(k + by),
    };
    let mut out = Vec::with_capacity(jobs.section3.len() + jobs.scans.len());
    for &((p0, p1), (q0, q1)) in &jobs.section3 {
        // Parts monotone along the line: the exact windowed sweep first (the parts' nearest pair,
        // or some pair no nearer than the cut), section 3 when it declines.
        if let Some(w) = sweep_chains::<K>(&p[p0..=p1], &q[q0..=q1], a, c, cut) {
            stats.subproblem_parts_swept += 1;
            let (fp, fq) = w.features();
            out.push((shift(fp, p0), shift(fq, q0), Err(w)));
            continue;
        }
        let (p_part, q_part) = (&p[p0..=p1], &q[q0..=q1]);
        let (pair, _, swept) = chains::<K>(p_part, q_part, (a, c), ChainMethod::Auto, cut).ok()?;
        if swept {
            stats.subproblem_parts_enveloped += 1;
        }
        let (fp, fq) = (shift(pair.feature_p, p0), shift(pair.feature_q, q0));
        out.push((fp, fq, Ok(pair)));
    }
    for &((p0, p1), (q0, q1)) in &jobs.scans {
        let w = scan_part::<K>(&p[p0..=p1], &q[q0..=q1], cut, Seen::NONE, &near);
        let (fp, fq) = w.features();
        out.push((shift(fp, p0), shift(fq, q0), Err(w)));
    }
    if let Some((sp, sq)) = &jobs.sides {
        for &wrong_p in &jobs.gapped {
            let found = separation_of_gapped::<K>(p, q, (a, c), (sp, sq), wrong_p, cut).ok()?;
            stats.subproblem_parts_gapped += 1;
            if let Some(cand) = found {
                let pair = build_pair::<K>(cand);
                out.push((pair.feature_p, pair.feature_q, Ok(pair)));
            }
        }
    }
    Some(out)
}

/// How one subproblem is solved without scanning it whole: section 3 on pairs of parts (`P` range,
/// `Q` range, inclusive, within the subchains) and exact scans of the rest.
struct Jobs {
    section3: Vec<((usize, usize), (usize, usize))>,
    scans: Vec<((usize, usize), (usize, usize))>,
    /// Side assignments (the side `P` must avoid) for section 3 on the clipped subchains
    /// ([`separation_of_gapped`]), with each vertex's side of the line.
    gapped: Vec<Orientation>,
    sides: Option<(Vec<Orientation>, Vec<Orientation>)>,
}

/// Step G (docs/algorithms/separator.md): how section 3 takes one subproblem across the line
/// through `a`, `c`, decided by `O(|P_i| + |Q_i|)` orientation tests.
///
/// 1. **Peeled ends.** When the only vertices across the line through `a`, `c` are ends of the
///    subchains (a subchain widened to the whole edge its cut falls in crosses the line there; see
///    [`peeled`]), section 3 takes the middles and the peeled ends are scanned against the other
///    subchain (`P`'s against all of `Q_i`, `Q`'s against `P`'s middle): every pair of edges is in one
///    of the five parts, whichever side each chain is on.
/// 2. **Runs.** Otherwise (a middle comes back across the line), for each of the two assignments
///    of sides: the maximal runs of vertices of each subchain not strictly on its wrong side, section
///    3 on every pair of runs, and every edge with exactly one end strictly on the wrong side scanned
///    against the whole other subchain (edges with both ends there lie wholly across the line). Every
///    pair Lemma 1 assigns to the subproblem meets `l_i` (notes 4.8), so its points lie in opposite
///    closed half-planes of the line: one of the two assignments holds it, in a pair of runs or a
///    crossing edge, and every pair either assignment evaluates is a pair of boundary points, so the
///    minimum is still `σ`. Runs are not joined across the gaps (no fake edges). Taken when each
///    chain has at most [`MAX_RUNS`] runs and [`MAX_CROSSINGS`] crossing edges per assignment, so the
///    work stays `O(|P_i| + |Q_i|)`.
/// 3. **Clipped chains.** For an assignment with more runs or crossing edges: one section 3 call
///    on the two subchains clipped to their closed half-planes ([`separation_of_gapped`]: the runs
///    end at symbolic clip points on the line and are not joined), `O((|P_i| + |Q_i|) log k)` for
///    `k` runs; the same argument holds, since the clipped chains hold every point of either chain
///    on its side.
fn split<K: Kernel>(p: &[DVec2], q: &[DVec2], a: DVec2, c: DVec2) -> Jobs {
    // Each vertex's side of the line, decided once for both routes and both assignments.
    let side = |chain: &[DVec2]| -> Vec<Orientation> {
        chain.iter().map(|&v| K::orient(a, c, v)).collect()
    };
    let (sp, sq) = (side(p), side(q));
    if let Some(((p0, p1), (q0, q1))) = peeled(&sp, &sq) {
        let (pl, ql) = (p.len() - 1, q.len() - 1);
        let mut scans = Vec::new();
        if p0 > 0 {
            scans.push(((0, p0), (0, ql)));
        }
        if p1 < pl {
            scans.push(((p1, pl), (0, ql)));
        }
        if q0 > 0 {
            scans.push(((p0, p1), (0, q0)));
        }
        if q1 < ql {
            scans.push(((p0, p1), (q1, ql)));
        }
        return Jobs {
            section3: vec![((p0, p1), (q0, q1))],
            scans,
            gapped: Vec::new(),
            sides: None,
        };
    }
    let mut jobs = Jobs {
        section3: Vec::new(),
        scans: Vec::new(),
        gapped: Vec::new(),
        sides: None,
    };
    for (wp, wq) in [
        (Orientation::Clockwise, Orientation::CounterClockwise),
        (Orientation::CounterClockwise, Orientation::Clockwise),
    ] {
        let (Some((rp, cp)), Some((rq, cq))) = (runs(&sp, wp), runs(&sq, wq)) else {
            // Too many runs for pairs of runs: section 3 on the clipped subchains.
            jobs.gapped.push(wp);
            continue;
        };
        for &x in &rp {
            for &y in &rq {
                jobs.section3.push((x, y));
            }
        }
        jobs.scans
            .extend(cp.iter().map(|&k| ((k, k + 1), (0, q.len() - 1))));
        jobs.scans
            .extend(cq.iter().map(|&k| ((0, p.len() - 1), (k, k + 1))));
    }
    if !jobs.gapped.is_empty() {
        jobs.sides = Some((sp, sq));
    }
    jobs
}

/// Runs per chain and side assignment that [`split`] gives to section 3.
const MAX_RUNS: usize = 4;
/// Crossing edges per chain and side assignment that [`split`] scans.
const MAX_CROSSINGS: usize = 8;

/// Inclusive index ranges of a chain's runs, and the first vertices of its crossing edges.
type Runs = (Vec<(usize, usize)>, Vec<usize>);

/// The maximal runs of a chain's vertices not strictly on the side `wrong` of the line (`sides`:
/// each vertex's side), and the edges (by their first vertex) with exactly one end strictly there;
/// `None` when there are more than [`MAX_RUNS`] runs or [`MAX_CROSSINGS`] such edges. `O(n)`.
fn runs(sides: &[Orientation], wrong: Orientation) -> Option<Runs> {
    let (mut runs, mut crossing) = (Vec::new(), Vec::new());
    let mut start: Option<usize> = None;
    let mut prev_bad = None;
    for (k, &s) in sides.iter().enumerate() {
        let bad = s == wrong;
        if prev_bad.is_some_and(|b| b != bad) {
            crossing.push(k - 1);
        }
        match (bad, start) {
            (false, None) => start = Some(k),
            (true, Some(s)) => {
                runs.push((s, k - 1));
                start = None;
            }
            _ => {}
        }
        prev_bad = Some(bad);
        if runs.len() > MAX_RUNS || crossing.len() > MAX_CROSSINGS {
            return None;
        }
    }
    if let Some(s) = start {
        runs.push((s, sides.len() - 1));
    }
    (runs.len() <= MAX_RUNS).then_some((runs, crossing))
}

/// Subproblems with at most this many vertex pairs are scanned without trying section 3.
const SCAN_BELOW: usize = 256;
/// Boxes of the other subchain that [`near_ends`] tests an end against, and the edges it tries
/// to trim at once before single edges.
const NEAR_BOXES: usize = 16;
/// Subproblems one of whose subchains has at most this many vertices are scanned without trying
/// section 3 (`O(THIN · (|P_i| + |Q_i|))`; not when every subproblem is offered to section 3).
const THIN: usize = 8;
/// Scans of more vertex pairs than this are pruned by bounding boxes.
const PRUNE_ABOVE: usize = 256;

/// Step G's first route (docs/algorithms/separator.md): the middle parts `P_i[p0..=p1]`,
/// `Q_i[q0..=q1]` of two subchains that lie in opposite closed half-planes of the line through `a`,
/// `c`, when the vertices outside them are the chains' ends and lie strictly on the wrong side (a
/// subchain widened to the whole edge its cut falls in crosses the line there). The peeled end
/// edges are scanned against the other chain in `O(|P_i| + |Q_i|)` each (cheaper than clipping them
/// at constructed points, [`separation_of_gapped`]). `None` when no side assignment works. `sp`,
/// `sq`: each vertex's side of the line. `O(|P_i| + |Q_i|)`.
fn peeled(sp: &[Orientation], sq: &[Orientation]) -> Option<((usize, usize), (usize, usize))> {
    let middle = |sides: &[Orientation], wrong: Orientation| {
        let bad = |s: &Orientation| *s == wrong;
        let lo = sides.iter().position(|s| !bad(s))?;
        let hi = sides.iter().rposition(|s| !bad(s))?;
        (!sides[lo..=hi].iter().any(bad)).then_some((lo, hi))
    };
    [
        (Orientation::Clockwise, Orientation::CounterClockwise),
        (Orientation::CounterClockwise, Orientation::Clockwise),
    ]
    .into_iter()
    .find_map(|(wp, wq)| Some((middle(sp, wp)?, middle(sq, wq)?)))
}

#[cfg(test)]
mod tests {
    //! The `O(N²)` checker of the separator: properties (i)–(iv) exactly, monotone cuts, Lemma 1's
    //! conclusion (the brute-force optimal pair lies in some `P_i × Q_i`), and `σ` against the
    //! brute force, on hull-meeting pairs of every generator family.

    use super::*;
    use crate::brute::{scan, scan_pruned};
    use crate::polygon::closed_chain;
    use polydist_oracle::SplitMix64;
    use polydist_polygon::predicates::{Exact, Fast, Robust};

    /// Where the extended segment `s` fails property (iii) or (iv), if it does: a boundary edge
    /// crossed transversally strictly inside `s`, a boundary vertex on `s` whose edges leave to both
    /// sides, or an end that is not on the boundary feature it names.
    fn check_iii_iv<K: Kernel>(
        r: &Region,
        s: &Seg,
        p: &[DVec2],
        q: &[DVec2],
    ) -> Result<(), String> {
        let line = s.line(r);
        let (lo, hi) = interval(r, s, &line);
        let inside = |x: Param| {
            line.cmp::<K>(&lo, &x) == Ordering::Less && line.cmp::<K>(&x, &hi) == Ordering::Less
        };
        for (name, poly) in [("P", p), ("Q", q)] {
            let n = poly.len();
            for e in 0..n {
                let (c, d, nx) = (poly[e], poly[(e + 1) % n], poly[(e + 2) % n]);
                let (oc, od) = (K::orient(line.a, line.b, c), K::orient(line.a, line.b, d));
                let opposite = |x: Orientation, y: Orientation| {
                    matches!(
                        (x, y),
                        (Orientation::Clockwise, Orientation::CounterClockwise)
                            | (Orientation::CounterClockwise, Orientation::Clockwise)
                    )
                };
                if opposite(oc, od) && inside(param(&line, Locus::Cross(c, d))) {
                    return Err(format!("(iii): crosses edge {e} of {name}"));
                }
                // Vertex d on the line with its two edges leaving to opposite sides.
                let on = K::orient(line.a, line.b, nx);
                if od == Orientation::Collinear
                    && opposite(oc, on)
                    && inside(param(&line, Locus::Point(d)))
                {
                    return Err(format!("(iii): crosses {name} at vertex {}", (e + 1) % n));
                }
            }
        }
        for (end, v) in [(s.bottom, s.lo), (s.top, s.hi)] {
            let ok = match end {
                End::Run => true,
                End::Vertex(w) => {
                    K::orient(r.ring[s.lo], r.ring[s.hi], r.ring[w]) == Orientation::Collinear
                }
                End::Edge(e) => {
                    let (c, d) = r.edge(e);
                    let (oc, od) = (K::orient(line.a, line.b, c), K::orient(line.a, line.b, d));
                    oc != od || oc == Orientation::Collinear
                }
            };
            if !ok {
                return Err(format!(
                    "(iv): the end beyond ring vertex {v} is not on the boundary"
                ));
            }
        }
        Ok(())
    }

    /// An affine function of a point, with its sign along a line: for the exact visibility test.
    fn cross_form(c: DVec2, v0: DVec2, v1: DVec2, neg: bool) -> Affine {
        Affine {
            cross: true,
            c,
            v0,
            v1,
            neg,
        }
    }

    fn dot_form(c: DVec2, v0: DVec2, v1: DVec2) -> Affine {
        Affine {
            cross: false,
            c,
            v0,
            v1,
            neg: false,
        }
    }

    /// The sign of `g` along `line` as the point moves from `a` to `b`.
    fn slope<K: Kernel>(line: &Edge, g: &Affine) -> Sign {
        let s = if g.cross {
            K::cross_sign(line.a, line.b, g.v0, g.v1)
        } else {
            K::dot_sign(line.a, line.b, g.v0, g.v1)
        };
        if g.neg { s.reversed() } else { s }
    }

    /// Where a point of the line is: at a breakpoint, or strictly between this breakpoint and the
    /// next one.
    #[derive(Clone, Copy)]
    enum Spot {
        At(Param),
        Between(Param),
    }

    fn sign_at<K: Kernel>(line: &Edge, g: &Affine, at: Spot) -> Sign {
        match at {
            Spot::At(t) => line.eval::<K>(g, &t),
            Spot::Between(lo) => {
                let sl = slope::<K>(line, g);
                if sl == Sign::Zero {
                    return line.eval::<K>(g, &Param::Start);
                }
                // The root of g is a breakpoint: the interval lies right of it iff root ≤ lo.
                let right = line.cmp::<K>(&Param::Root(*g), &lo) != Ordering::Greater;
                if right { sl } else { sl.reversed() }
            }
        }
    }

    /// Whether ring vertex `wr` of `R` sees a point of the open segment `s` inside `R`: a point `y`
    /// strictly between the segment's ends with the open segment `(w, y)` leaving `w` into the
    /// interior of `R` and meeting no edge of `R`'s ring (facing chains and bridges) other than
    /// those at `w`. Exact: every condition is the sign of an affine function of `y` on the
    /// segment's line, so the line is cut at the roots of all of them (compared exactly, degree 4)
    /// and each breakpoint and each open piece between consecutive breakpoints is tested.
    /// `O(E log E)` per call for `E` ring edges.
    fn sees<K: Kernel>(r: &Region, s: &Seg, wr: usize) -> bool {
        let n = r.ring.len();
        let (prev, w, next) = (r.ring[(wr + n - 1) % n], r.ring[wr], r.ring[(wr + 1) % n]);
        let edges: Vec<(DVec2, DVec2)> = (0..n)
            .filter(|&e| e != wr && (e + 1) % n != wr)
            .map(|e| r.edge(e))
            .collect();
        let edges = &edges[..];
        let line = s.line(r);
        let (lo, hi) = interval(r, s, &line);
        if K::orient(line.a, line.b, w) == Orientation::Collinear {
            let t = param(&line, Locus::Point(w));
            // In a weakly simple region, `w` at an end of `s` on the other copy of the cut is
            // another point of the cut region (seen, if at all, through its own copy's angle).
            let w_side = copy_side(r, End::Vertex(wr), wr);
            let other_copy =
                [(s.bottom, s.lo, lo), (s.top, s.hi, hi)]
                    .into_iter()
                    .any(|(e, v, at)| {
                        line.cmp::<K>(&at, &t) == Ordering::Equal
                            && matches!((copy_side(r, e, v), w_side), (Some(a), Some(b)) if a != b)
                    });
            return !other_copy
                && line.cmp::<K>(&lo, &t) != Ordering::Greater
                && line.cmp::<K>(&t, &hi) != Ordering::Greater;
        }
        // The cone at w: n(y) = cross(next − w, y − w), p(y) = cross(y − w, prev − w).
        let n_form = cross_form(w, w, next, true);
        let p_form = cross_form(w, w, prev, false);
        let convex = K::orient(prev, w, next) == Orientation::CounterClockwise;
        // Per edge (c, d): o2(y) = orient(c, d, y), o3(y) = orient(w, y, c), o4(y) = orient(w, y, d),
        // b3(y) = (y − c)·(c − w) (c strictly between w and y when o3 = 0 and b3 > 0), b4 likewise.
        let mut forms = vec![n_form, p_form];
        let per_edge: Vec<[Affine; 5]> = edges
            .iter()
            .map(|&(c, d)| {
                [
                    // orient(c, d, y) = cross(d − c, y − c) = −cross(y − c, d − c).
                    cross_form(c, c, d, true),
                    // orient(w, y, c) = cross(y − w, c − w).
                    cross_form(w, w, c, false),
                    cross_form(w, w, d, false),
                    dot_form(c, w, c),
                    dot_form(d, w, d),
                ]
            })
            .collect();
        for f in &per_edge {
            forms.extend_from_slice(f);
        }
        let mut pts: Vec<Param> = vec![lo, hi];
        for g in &forms {
            if slope::<K>(&line, g) != Sign::Zero {
                let t = Param::Root(*g);
                if line.cmp::<K>(&lo, &t) == Ordering::Less
                    && line.cmp::<K>(&t, &hi) == Ordering::Less
                {
                    pts.push(t);
                }
            }
        }
        pts.sort_by(|x, y| line.cmp::<K>(x, y));
        pts.dedup_by(|x, y| line.cmp::<K>(x, y) == Ordering::Equal);
        let mut spots: Vec<Spot> = pts.iter().map(|&t| Spot::At(t)).collect();
        spots.extend(pts.windows(2).map(|w| Spot::Between(w[0])));
        let o1: Vec<Sign> = edges
            .iter()
            .map(|&(c, d)| {
                Sign::from_ordering(match K::orient(c, d, w) {
                    Orientation::Clockwise => Ordering::Less,
                    Orientation::Collinear => Ordering::Equal,
                    Orientation::CounterClockwise => Ordering::Greater,
                })
            })
            .collect();
        // The open segment only: its ends are boundary points (or the geodesic's ends).
        spots.retain(|at| match at {
            Spot::At(t) => {
                line.cmp::<K>(&lo, t) == Ordering::Less && line.cmp::<K>(t, &hi) == Ordering::Less
            }
            Spot::Between(..) => true,
        });
        spots.into_iter().any(|at| {
            let n = sign_at::<K>(&line, &n_form, at);
            let p = sign_at::<K>(&line, &p_form, at);
            // Into the interior of R (counter-clockwise: interior on the left of its edges).
            let interior = if convex {
                n == Sign::Positive && p == Sign::Positive
            } else {
                n == Sign::Positive || p == Sign::Positive
            };
            interior
                && per_edge.iter().zip(&o1).all(|(f, &o1)| {
                    let o2 = sign_at::<K>(&line, &f[0], at);
                    let o3 = sign_at::<K>(&line, &f[1], at);
                    let o4 = sign_at::<K>(&line, &f[2], at);
                    let opposite = |x: Sign, y: Sign| {
                        matches!(
                            (x, y),
                            (Sign::Negative, Sign::Positive) | (Sign::Positive, Sign::Negative)
                        )
                    };
                    let proper = opposite(o1, o2) && opposite(o3, o4);
                    // The sight passes through c (or d): c on it, strictly between w and y.
                    let through_c =
                        o3 == Sign::Zero && sign_at::<K>(&line, &f[3], at) == Sign::Positive;
                    let through_d =
                        o4 == Sign::Zero && sign_at::<K>(&line, &f[4], at) == Sign::Positive;
                    !(proper || through_c || through_d)
                })
        })
    }

    /// The whole check of one pair; returns the number of kept segments.
    fn check_pair<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon) -> Result<usize, String> {
        check_pair_v::<K>(p, q, false)
    }

    /// [`check_pair`], with the exact checks of property (v) and of every vertex–vertex sight when
    /// `check_v`.
    fn check_pair_v<K: Kernel>(
        p: &SimplePolygon,
        q: &SimplePolygon,
        check_v: bool,
    ) -> Result<usize, String> {
        check_pair_cover::<K>(p, q, check_v).map(|(m, _)| m)
    }

    /// [`check_pair`], with the exact check of property (v) for vertices when `check_v`; returns
    /// the number of kept segments and, when `check_v`, per pass the number of vertex–vertex sights
    /// that only this pass holds.
    fn check_pair_cover<K: Kernel>(
        p: &SimplePolygon,
        q: &SimplePolygon,
        check_v: bool,
    ) -> Result<(usize, Vec<usize>), String> {
        let plan = build::<K>(p, q)
            .map_err(|e| format!("{e}"))?
            .ok_or("no region: one polygon inside the other")?;
        let (pp, qq) = if plan.swapped { (q, p) } else { (p, q) };
        let (cp, cq) = (closed_chain(pp), closed_chain(qq));
        let brute = separation_brute::<K>(&cp, &cq).map_err(|e| format!("{e}"))?;
        let mut m = 0;
        let mut cover = Vec::new();
        let mut sights_only = Vec::new();
        for (k, b) in plan.passes.iter().enumerate() {
            let (mk, cov) = check_pass::<K>(pp, qq, b, check_v, &brute)
                .map_err(|e| format!("pass {k}: {e}"))?;
            m += mk;
            cover.push(cov);
        }
        // Every vertex–vertex sight is held by some pass (in the containing case, each pass holds
        // those that miss its cut, and every sight misses one of the two cuts); `cover` counts, per
        // pass, the sights only that pass holds.
        if check_v {
            let (vp, vq) = (pp.vertices(), qq.vertices());
            let mut only = vec![0; plan.passes.len()];
            for i in 0..vp.len() {
                for j in 0..vq.len() {
                    if !sight::<K>(vp, vq, i, j) {
                        continue;
                    }
                    let held: Vec<usize> = (0..plan.passes.len())
                        .filter(|&k| {
                            pass_holds(
                                &plan.passes[k],
                                vp.len(),
                                vq.len(),
                                Feature::Vertex(i),
                                Feature::Vertex(j),
                            )
                        })
                        .collect();
                    match held[..] {
                        [] => return Err(format!("the sight from {i} to {j} is held by no pass")),
                        [k] => only[k] += 1,
                        _ => {}
                    }
                    // The pass answering for the sight's `Q` end must hold it.
                    for (k, b) in plan.passes.iter().enumerate() {
                        if let Some(share) = b.region.share
                            && share.holds(vq[j])
                            && !held.contains(&k)
                        {
                            return Err(format!(
                                "the sight from {i} to {j} ends in pass {k}'s share {share:?}, \
                                 which does not hold it"
                            ));
                        }
                    }
                }
            }
            sights_only = only;
        }
        // Lemma 1: the brute-force pair lies in some P_i × Q_i of some pass.
        if !cover.contains(&true) {
            let subs: Vec<_> = plan.passes.iter().map(|b| &b.sub).collect();
            return Err(format!(
                "Lemma 1: the optimal pair {:?}/{:?} is in no subproblem {subs:?}",
                brute.feature_p, brute.feature_q
            ));
        }
        // σ agrees with the brute force exactly, with small subproblems scanned (as shipped) and
        // with every subproblem offered to section 3 (peeled ends scanned).
        let (cp, cq) = (closed_chain(p), closed_chain(q));
        let brute = separation_brute::<K>(&cp, &cq).map_err(|e| format!("{e}"))?;
        let (vp, vq) = (p.vertices(), q.vertices());
        let bd = dist_of(vp, vq, brute.feature_p, brute.feature_q);
        for scan_below in [SCAN_BELOW, 0] {
            let (pair, _) = solve_with::<K>(p, q, &plan, scan_below).map_err(|e| format!("{e}"))?;
            let d = dist_of(vp, vq, pair.feature_p, pair.feature_q);
            if K::cmp_dist2(d, bd) != Ordering::Equal {
                return Err(format!(
                    "σ differs (scanning below {scan_below} pairs): {pair:?} against the brute \
                     force {brute:?}"
                ));
            }
        }
        let d = near_scans::<K>(p, q, &plan);
        if K::cmp_dist2(d, bd) != Ordering::Equal {
            return Err(format!(
                "σ differs with every subproblem scanned near its separator alone: {d:?} against \
                 the brute force {brute:?}"
            ));
        }
        Ok((m, sights_only))
    }

    /// `σ` as the least answer of every subproblem's scan pruned by its boxes and by its distance
    /// to `l_i` ([`Near`]), each with no cut from the others: Lemma 1 (notes 4.8) says that the
    /// subproblem holding the optimal pair finds it so.
    fn near_scans<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon, plan: &Plan) -> Dist2 {
        let vp = if plan.swapped { q } else { p }.vertices();
        let mut best: Option<Dist2> = None;
        for b in &plan.passes {
            let r = &b.region;
            for (i, &((plo, phi), (qlo, qhi))) in b.sub.iter().enumerate() {
                let parts = match r.gap {
                    Some(g) if qlo <= g && g < qhi => [(qlo, g), (g + 1, qhi)],
                    _ => [(qlo, qhi), (1, 0)],
                };
                let near = near_of(r, &b.segs[i]);
                let pc: Vec<DVec2> = (plo..=phi).map(|k| vp[(r.pb + k) % r.np]).collect();
                for (qlo, qhi) in parts.into_iter().filter(|(lo, hi)| lo <= hi) {
                    let qc: Vec<DVec2> = (qlo..=qhi).map(|k| r.ring[k]).collect();
                    let (w, _) =
                        scan_pruned_winner_below::<K>(&pc, &qc, f64::INFINITY, Some(&near));
                    let (fp, fq) = w.features();
                    let d = dist_of(&pc, &qc, fp, fq);
                    if best.is_none_or(|b| K::cmp_dist2(d, b) == Ordering::Less) {
                        best = Some(d);
                    }
                }
            }
        }
        best.expect("a pass has a subproblem")
    }

    /// The checks of one pass: (i)–(iv), the greedy's interval belief, cuts, monotone subchains,
    /// (v) when `check_v`; returns the number of kept segments and whether the brute-force pair
    /// lies in one of the pass's subproblems.
    fn check_pass<K: Kernel>(
        p: &SimplePolygon,
        q: &SimplePolygon,
        b: &Built,
        check_v: bool,
        brute: &ClosestPair,
    ) -> Result<(usize, bool), String> {
        let r = &b.region;
        let (vp, vq) = (p.vertices(), q.vertices());
        let m = b.kept.len();
        let segs = &b.segs;
        for i in 0..m {
            for j in i + 1..m {
                let meet = meets::<K>(r, &segs[i], &segs[j]);
                if j == i + 1 && !meet {
                    return Err(format!("(i): l_{i} and l_{j} do not meet"));
                }
                if j > i + 1 && meet {
                    return Err(format!("(ii): l_{i} meets l_{j}"));
                }
            }
            check_iii_iv::<K>(r, &segs[i], vp, vq).map_err(|e| format!("l_{i}: {e}"))?;
        }
        // The galloping search keeps what the forward scan to the first miss keeps.
        let mut scanned = vec![0];
        let (k, mut a) = (b.runs.len(), 0);
        while a + 1 < k {
            let mut j = a + 1;
            while j + 1 < k && meets::<K>(r, &b.runs[a], &b.runs[j + 1]) {
                j += 1;
            }
            scanned.push(j);
            a = j;
        }
        if scanned != b.kept {
            return Err(format!(
                "greedy: kept {:?}, the scan keeps {scanned:?}",
                b.kept
            ));
        }
        if b.kept.iter().zip(&b.segs).any(|(&j, s)| b.runs[j] != *s) {
            return Err("kept segments are not their runs".into());
        }
        // Step C's interval belief: the runs meeting a kept run form an interval after it.
        for w in b.kept.windows(2) {
            let (a, next) = (w[0], w[1]);
            for j in next + 1..b.runs.len() {
                if meets::<K>(r, &b.runs[a], &b.runs[j]) {
                    return Err(format!(
                        "greedy: run {j} meets kept run {a} beyond the kept {next}"
                    ));
                }
            }
        }
        if b.cut_fallbacks != 0 {
            return Err(format!("{} cut fallbacks", b.cut_fallbacks));
        }
        for w in b.sub.windows(2) {
            if w[1].0.0 < w[0].0.0 || w[1].1.0 < w[0].1.0 {
                return Err(format!("subchains not monotone: {:?}", b.sub));
            }
        }
        // (v), for vertices (notes 4.5, i ≤ m − 3): if l_i's top is on P′, no vertex of Q′ above
        // q⁺(i + 1) is visible from l_i; if it is on Q*, no vertex of P′ above p⁺(i + 1).
        if check_v {
            let ring_of_p = |pos: usize| if pos == 0 { 0 } else { r.ring.len() - pos };
            for (i, s) in segs.iter().enumerate().take(m.saturating_sub(2)) {
                if cover_p(r, s.top, s.hi).is_some() {
                    let above = b.cuts[i + 1].1.1 + 1;
                    for ring in above..=r.qt {
                        if sees::<K>(r, s, ring) {
                            return Err(format!(
                                "(v): l_{i} sees Q vertex {} above q⁺({})",
                                r.src[ring],
                                i + 1
                            ));
                        }
                    }
                } else {
                    let above = b.cuts[i + 1].0.1 + 1;
                    for pos in above..=r.top_p() {
                        let v = (r.pb + pos) % r.np;
                        if sees::<K>(r, s, ring_of_p(pos)) {
                            return Err(format!(
                                "(v): l_{i} sees P vertex {v} above p⁺({})",
                                i + 1
                            ));
                        }
                    }
                }
            }
        }
        let (np, nq) = (vp.len(), vq.len());
        let holds = |fp: Feature, fq: Feature| pass_holds(b, np, nq, fp, fq);
        // Lemma 1 (amended, notes 4.8) holds for every visible pair, not only the optimal one: on
        // small cases, every vertex–vertex sight of this pass's region (a free segment from `P` to
        // `Q` that does not cross the region's cut, in the containing case) must lie in a
        // subproblem.
        if check_v {
            let cut = (r.ring[1] == r.ring[r.qt]).then(|| (r.ring[0], r.ring[1]));
            for i in 0..np {
                for j in 0..nq {
                    let crosses_cut =
                        cut.is_some_and(|(a, c)| proper_cross::<K>(vp[i], vq[j], a, c));
                    if !crosses_cut
                        && sight::<K>(vp, vq, i, j)
                        && !holds(Feature::Vertex(i), Feature::Vertex(j))
                    {
                        return Err(format!(
                            "Lemma 1: the sight from P vertex {i} to Q vertex {j} is in no subproblem"
                        ));
                    }
                }
            }
        }
        Ok((m, holds(brute.feature_p, brute.feature_q)))
    }

    /// Whether a pair of features lies in some `P_i × Q_i` of pass `b` (positions along the
    /// walls; `Q`'s through the ring's sources, skipping the gap).
    fn pass_holds(b: &Built, np: usize, nq: usize, fp: Feature, fq: Feature) -> bool {
        let r = &b.region;
        let pos_p = |v: usize| (v % np + np - r.pb) % np;
        let p_in = |lo: usize, hi: usize| match fp {
            Feature::Vertex(v) => {
                (lo..=hi).contains(&pos_p(v)) || (pos_p(v) == 0 && (lo..=hi).contains(&r.top))
            }
            Feature::Edge(e) => pos_p(e) >= lo && pos_p(e) < hi,
        };
        let q_in = |lo: usize, hi: usize| match fq {
            Feature::Vertex(j) => (lo..=hi).any(|x| r.src[x] == j % nq),
            Feature::Edge(f) => (lo..hi)
                .any(|x| Some(x) != r.gap && r.src[x] == (f + 1) % nq && r.src[x + 1] == f % nq),
        };
        b.sub
            .iter()
            .any(|&((pl, ph), (ql, qh))| p_in(pl, ph) && q_in(ql, qh))
    }

    /// Whether segments `[a, b]` and `[c, d]` cross at a point interior to both (exact).
    fn proper_cross<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
        let opp = |x: Orientation, y: Orientation| {
            matches!(
                (x, y),
                (Orientation::Clockwise, Orientation::CounterClockwise)
                    | (Orientation::CounterClockwise, Orientation::Clockwise)
            )
        };
        opp(K::orient(a, b, c), K::orient(a, b, d)) && opp(K::orient(c, d, a), K::orient(c, d, b))
    }

    /// Whether the open segment from `P`'s vertex `i` to `Q`'s vertex `j` is free: it leaves each
    /// end strictly outside that polygon's angle, crosses no edge, passes through no vertex (exact).
    fn sight<K: Kernel>(vp: &[DVec2], vq: &[DVec2], i: usize, j: usize) -> bool {
        let (v, w) = (vp[i], vq[j]);
        let outside = |poly: &[DVec2], k: usize, from: DVec2, to: DVec2| {
            let n = poly.len();
            let (prev, next) = (poly[(k + n - 1) % n], poly[(k + 1) % n]);
            let o1 = K::orient(from, next, to);
            let o2 = K::orient(from, to, prev);
            match K::orient(prev, from, next) {
                Orientation::CounterClockwise => {
                    o1 == Orientation::Clockwise || o2 == Orientation::Clockwise
                }
                Orientation::Clockwise => {
                    o1 == Orientation::Clockwise && o2 == Orientation::Clockwise
                }
                Orientation::Collinear => o1 == Orientation::Clockwise,
            }
        };
        if !outside(vp, i, v, w) || !outside(vq, j, w, v) {
            return false;
        }
        for poly in [vp, vq] {
            let n = poly.len();
            for k in 0..n {
                let (c, d) = (poly[k], poly[(k + 1) % n]);
                if proper_cross::<K>(v, w, c, d) {
                    return false;
                }
                if c != v
                    && c != w
                    && K::orient(v, w, c) == Orientation::Collinear
                    && K::dot_sign(c, v, c, w) == Sign::Negative
                {
                    return false;
                }
            }
        }
        true
    }

    fn poly(v: &[DVec2]) -> SimplePolygon {
        SimplePolygon::try_new(v).expect("simple")
    }

    /// Two random stars pushed into each other until their hulls meet, kept when they are
    /// disjoint and neither hull contains the other.
    fn star_pair(seed: u64) -> Option<(SimplePolygon, SimplePolygon)> {
        let mut rng = SplitMix64::new(seed);
        let n = 3 + rng.index(40);
        let m = 3 + rng.index(40);
        let (sa, sb) = (rng.index(n + 1), rng.index(m + 1));
        let a = polydist_oracle::star(&mut rng, n, sa);
        let b = polydist_oracle::star(&mut rng, m, sb);
        let radius = |v: &[DVec2]| v.iter().map(|x| x.length()).fold(0.0, f64::max);
        let (ra, rb) = (radius(&a), radius(&b));
        let t = 0.35 + 0.6 * rng.unit_f64();
        let ang = core::f64::consts::TAU * rng.unit_f64();
        let d = DVec2::new(ang.cos(), ang.sin()) * (ra + rb) * t;
        let b: Vec<DVec2> = b.iter().map(|&x| x + d).collect();
        let (p, q) = (
            SimplePolygon::try_new(&a).ok()?,
            SimplePolygon::try_new(&b).ok()?,
        );
        if crate::polygon::intersection::<Robust>(&p, &q).is_some() {
            return None;
        }
        match facing::<Robust>(
            &p,
            &q,
            &hull_indices::<Robust>(&p),
            &hull_indices::<Robust>(&q),
        ) {
            Ok(Ok(_)) => Some((p, q)),
            _ => None,
        }
    }

    /// Two random stars of 400 vertices (a spike every fourth) pushed into each other, solved with
    /// every subproblem offered whole to section 3: their separators' lines pass through many
    /// spikes, so some subproblems cross their line too often for pairs of runs and go to section
    /// 3 on the subchains clipped to the line (Step G), end to end; `σ` as the brute force's,
    /// under Robust and Exact. (As shipped, [`near_ends`] trims most of those crossings away
    /// first.)
    #[test]
    fn interlocked_stars_reach_clipped_chains() {
        let (mut cases, mut gapped) = (0, 0);
        for seed in 0..12u64 {
            let mut rng = SplitMix64::new(seed);
            let a = polydist_oracle::star(&mut rng, 400, 100);
            let b0 = polydist_oracle::star(&mut rng, 400, 100);
            let radius = |v: &[DVec2]| v.iter().map(|x| x.length()).fold(0.0, f64::max);
            let p = poly(&a);
            for _ in 0..32 {
                let t = 0.3 + 0.6 * rng.unit_f64();
                let ang = core::f64::consts::TAU * rng.unit_f64();
                let d = DVec2::new(ang.cos(), ang.sin()) * (radius(&a) + radius(&b0)) * t;
                let q = poly(&b0.iter().map(|&v| v + d).collect::<Vec<_>>());
                if crate::polygon::intersection::<Robust>(&p, &q).is_some() {
                    continue;
                }
                let Ok(Some(plan)) = build::<Robust>(&p, &q) else {
                    continue;
                };
                cases += 1;
                let brute = separation_brute::<Robust>(&closed_chain(&p), &closed_chain(&q))
                    .expect("valid chains");
                let (vp, vq) = (p.vertices(), q.vertices());
                let want = dist_of(vp, vq, brute.feature_p, brute.feature_q);
                let (pair, stats) = solve_with::<Robust>(&p, &q, &plan, 0).unwrap();
                gapped += stats.subproblem_parts_gapped;
                let got = dist_of(vp, vq, pair.feature_p, pair.feature_q);
                assert_eq!(Robust::cmp_dist2(got, want), Ordering::Equal, "seed {seed}");
                let plan = build::<Exact>(&p, &q).unwrap().unwrap();
                let (pair, _) = solve_with::<Exact>(&p, &q, &plan, 0).unwrap();
                let got = dist_of(vp, vq, pair.feature_p, pair.feature_q);
                assert_eq!(
                    Exact::cmp_dist2(got, want),
                    Ordering::Equal,
                    "seed {seed}, Exact"
                );
                break;
            }
        }
        assert!(
            cases >= 6 && gapped >= 2,
            "{cases} cases, {gapped} gapped parts"
        );
    }

    #[test]
    fn random_star_pairs_satisfy_the_separator_properties() {
        let mut checked = 0;
        let mut segments = 0;
        for seed in 0..3000 {
            let Some((p, q)) = star_pair(seed) else {
                continue;
            };
            for (name, res) in [
                ("Robust", check_pair::<Robust>(&p, &q)),
                ("Exact", check_pair::<Exact>(&p, &q)),
            ] {
                match res {
                    Ok(m) => segments += m,
                    Err(e) => panic!(
                        "seed {seed} ({name}): {e}\nP = {:?}\nQ = {:?}",
                        p.vertices(),
                        q.vertices()
                    ),
                }
            }
            // Fast: terminates without panicking, also with every subproblem offered to section 3.
            if let Ok(Some(b)) = build::<Fast>(&p, &q) {
                let _ = solve::<Fast>(&p, &q, &b);
                let _ = solve_with::<Fast>(&p, &q, &b, 0);
            }
            checked += 1;
        }
        assert!(
            checked >= 300,
            "only {checked} hull-meeting pairs generated"
        );
        assert!(
            segments > 2 * checked,
            "separators too short: {segments} for {checked} pairs"
        );
    }

    /// Step 4 by the shortest-path trees (no walk budget) gives every arm the walks give, on the
    /// regions of random star pairs (both cases) and of interleaved combs.
    #[test]
    fn arms_from_the_trees_are_the_walked_arms() {
        let mut regions_checked = 0;
        let mut pairs: Vec<(SimplePolygon, SimplePolygon)> =
            (0..400).filter_map(star_pair).collect();
        for (teeth, len) in [(2, 3), (6, 5), (17, 9)] {
            let pair = polydist_oracle::interleaved_combs(teeth, len, 0.125);
            pairs.push((poly(&pair.a), poly(&pair.b)));
        }
        for (p, q) in &pairs {
            let Ok(Some((rs, _))) =
                regions::<Robust>(p, q, &hull_indices::<Robust>(p), &hull_indices::<Robust>(q))
            else {
                continue;
            };
            for region in rs {
                let Ok((tri, path)) = geodesic_of::<Robust>(&region, &mut Halves::default()) else {
                    continue;
                };
                let walked =
                    runs_with_arms::<Robust>(&tri, &region.ring, &path, usize::MAX, plain, |i| i);
                let trees = runs_with_arms::<Robust>(&tri, &region.ring, &path, 0, plain, |i| i);
                assert_eq!(
                    walked,
                    trees,
                    "P = {:?}\nQ = {:?}",
                    p.vertices(),
                    q.vertices()
                );
                regions_checked += 1;
            }
        }
        assert!(regions_checked > 200, "{regions_checked}");
    }

    #[test]
    fn interleaved_combs() {
        for (teeth, len) in [(1, 1), (2, 3), (6, 5), (17, 9)] {
            for gap in [0.125, 1e-9] {
                let pair = polydist_oracle::interleaved_combs(teeth, len, gap);
                let (p, q) = (poly(&pair.a), poly(&pair.b));
                let m = check_pair::<Robust>(&p, &q)
                    .unwrap_or_else(|e| panic!("{teeth}/{len}/{gap}: {e}"));
                assert!(m >= 1);
            }
            let pair = polydist_oracle::interleaved_combs_ulps(teeth, len, 3);
            let (p, q) = (poly(&pair.a), poly(&pair.b));
            check_pair::<Exact>(&p, &q).unwrap_or_else(|e| panic!("{teeth}/{len}/3 ulps: {e}"));
        }
    }

    /// Geo errata D3 ("grazing"): the hulls meet; σ ≈ 1.9100 between `Q`'s vertex (6, 8) and `P`'s
    /// edge (−1, 3)–(7, 12). Under the 1994 wording ("own cut when i = m − 1") the decomposition
    /// loses the pair; report 001's sentinels keep it.
    #[test]
    fn geo_errata_d3_grazing() {
        let p = poly(&[
            DVec2::new(2.0, -4.0),
            DVec2::new(-1.0, 3.0),
            DVec2::new(7.0, 12.0),
            DVec2::new(-4.0, 8.0),
            DVec2::new(-4.0, -4.0),
        ]);
        let q = poly(&[
            DVec2::new(12.0, 4.0),
            DVec2::new(6.0, 8.0),
            DVec2::new(4.0, 4.0),
            DVec2::new(8.0, 0.0),
        ]);
        check_pair::<Robust>(&p, &q).unwrap();
        check_pair::<Robust>(&q, &p).unwrap();
        let (pair, _) = solve::<Exact>(&p, &q, &build::<Exact>(&p, &q).unwrap().unwrap()).unwrap();
        assert_eq!(pair.point_q, DVec2::new(6.0, 8.0));
        assert!((pair.distance - 1.9100).abs() < 1e-4);
    }
    fn ring(v: &[[f64; 2]]) -> SimplePolygon {
        poly(&v.iter().map(|&a| DVec2::from(a)).collect::<Vec<_>>())
    }

    /// Geo errata D1 ("bridge landing") and D2 (orientation): the extension of the first run lands on
    /// a bridge and misses `Q`. The hulls are disjoint, so `separation` never builds a separator for
    /// them; the fast path is switched off here (the separator is built and checked directly).
    #[test]
    fn geo_errata_d1_d2_bridge_landing_without_the_fast_path() {
        let p = ring(&[[0.0, 2.0], [0.0, -2.0], [2.0, 0.0]]);
        let q = ring(&[[-6.0, -2.0], [-6.0, -6.0], [-2.0, -5.0]]);
        check_pair::<Robust>(&p, &q).unwrap();
        check_pair::<Exact>(&q, &p).unwrap();
    }

    /// Geo errata D4 ("wrapping cuts"): under the 1994 one-path reading a later cut lands below an
    /// earlier one. Our cuts are monotone here (asserted by the checker). Fast path off.
    #[test]
    fn geo_errata_d4_wrapping_cuts_without_the_fast_path() {
        let p = ring(&[[0.0, 0.0], [-1.0, -2.0], [2.0, -1.0]]);
        let q = ring(&[[-8.0, -4.0], [-8.0, -8.0], [4.0, -6.0]]);
        check_pair::<Robust>(&p, &q).unwrap();
        check_pair::<Exact>(&q, &p).unwrap();
    }

    /// Geo errata D5 ("pinched"): `P` touches the hull of the union at one vertex only, so `R` is
    /// weakly simple (that vertex twice on its ring): triangulated in two halves through a cut,
    /// checked in both orders (the second swaps the polygons).
    #[test]
    fn geo_errata_d5_pinched() {
        let p = ring(&[[3.0, 2.0], [0.0, -4.0], [4.0, 2.0]]);
        let q = ring(&[[0.0, 8.0], [2.0, 3.0], [8.0, 4.0]]);
        assert!(matches!(
            facing::<Robust>(
                &q,
                &p,
                &hull_indices::<Robust>(&q),
                &hull_indices::<Robust>(&p)
            ),
            Ok(Err(Unsupported::Pinched))
        ));
        for (a, b) in [(&p, &q), (&q, &p)] {
            let plan = build::<Robust>(a, b).unwrap().unwrap();
            assert_eq!(plan.passes.len(), 1);
            assert!(plan.passes[0].region.cut.is_some());
            check_pair_v::<Robust>(a, b, true).unwrap();
            check_pair_v::<Exact>(a, b, true).unwrap();
        }
    }

    /// The construction on pairs whose hulls are disjoint (the fast path switched off): the notes
    /// (5.3) say it works there too, bridge landings absorbed by `Q*`.
    #[test]
    fn hull_disjoint_pairs_without_the_fast_path() {
        let mut checked = 0;
        for seed in 0..400u64 {
            let mut rng = SplitMix64::new(seed ^ 0xd15c);
            let n = 3 + rng.index(30);
            let m = 3 + rng.index(30);
            let (sa, sb) = (rng.index(n + 1), rng.index(m + 1));
            let a = polydist_oracle::star(&mut rng, n, sa);
            let b = polydist_oracle::star(&mut rng, m, sb);
            let radius = |v: &[DVec2]| v.iter().map(|x| x.length()).fold(0.0, f64::max);
            let ang = core::f64::consts::TAU * rng.unit_f64();
            let d = DVec2::new(ang.cos(), ang.sin())
                * (radius(&a) + radius(&b))
                * (1.0 + rng.unit_f64());
            let b: Vec<DVec2> = b.iter().map(|&x| x + d).collect();
            let (Ok(p), Ok(q)) = (SimplePolygon::try_new(&a), SimplePolygon::try_new(&b)) else {
                continue;
            };
            match facing::<Robust>(
                &p,
                &q,
                &hull_indices::<Robust>(&p),
                &hull_indices::<Robust>(&q),
            ) {
                Ok(Ok(_)) => {}
                Ok(Err(Unsupported::Pinched)) => continue,
                other => panic!("seed {seed}: {other:?}"),
            }
            let v = p.len() + q.len() <= 40;
            check_pair_v::<Robust>(&p, &q, v).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            checked += 1;
        }
        assert!(checked >= 300, "{checked}");
    }
    /// Property (v) for vertices, exactly (`sees`), on the smaller random star pairs and the combs.
    /// The check fails when it should: measured against the cut `p⁺(i)` instead of `p⁺(i + 1)` it
    /// reports a visible vertex on the first hull-meeting seed.
    #[test]
    fn property_v_holds_for_vertices() {
        let mut checked = 0;
        for seed in 0..3000 {
            let Some((p, q)) = star_pair(seed) else {
                continue;
            };
            if p.len() + q.len() > 40 {
                continue;
            }
            check_pair_v::<Robust>(&p, &q, true).unwrap_or_else(|e| {
                panic!(
                    "seed {seed}: {e}\nP = {:?}\nQ = {:?}",
                    p.vertices(),
                    q.vertices()
                )
            });
            checked += 1;
        }
        assert!(checked >= 100, "{checked}");
        for teeth in [2, 5] {
            let pair = polydist_oracle::interleaved_combs(teeth, 4, 0.125);
            check_pair_v::<Robust>(&poly(&pair.a), &poly(&pair.b), true).unwrap();
        }
    }

    /// A shape of every generator family (stars, 2-opt polygons, spirals, combs), about `n` vertices.
    fn family_shape(rng: &mut SplitMix64, n: usize) -> Vec<DVec2> {
        match rng.below(4) {
            0 => polydist_oracle::star(rng, n, n / 4),
            1 => polydist_oracle::two_opt(rng, n.min(50)),
            2 => polydist_oracle::spiral((n as u32 / 4).clamp(3, 16), 1 + rng.below(2) as u32),
            _ => polydist_oracle::comb(
                (n / 4).clamp(1, 12),
                1 + rng.below(4) as u32,
                1 + rng.below(2) as u32,
            ),
        }
    }

    /// Two shapes of any family, the second scaled by `2^−k` and placed at random until the pair is
    /// disjoint with meeting hulls and neither hull contains the other (up to 40 placements).
    fn family_pair(seed: u64) -> Option<(SimplePolygon, SimplePolygon)> {
        let mut rng = SplitMix64::new(seed ^ 0xfa31);
        let (n, m) = (4 + rng.index(40), 4 + rng.index(40));
        let a = family_shape(&mut rng, n);
        let b = family_shape(&mut rng, m);
        let p = SimplePolygon::try_new(&a).ok()?;
        let centre = |v: &[DVec2]| {
            let lo = v.iter().fold(DVec2::splat(f64::INFINITY), |x, &y| x.min(y));
            let hi = v
                .iter()
                .fold(DVec2::splat(f64::NEG_INFINITY), |x, &y| x.max(y));
            ((lo + hi) * 0.5, (hi - lo).length() * 0.5)
        };
        let ((ca, ra), (cb, rb)) = (centre(&a), centre(&b));
        for _ in 0..40 {
            let scale = 0.5f64.powi(rng.below(3) as i32);
            let ang = core::f64::consts::TAU * rng.unit_f64();
            let d =
                DVec2::new(ang.cos(), ang.sin()) * (ra + rb * scale) * (0.1 + 0.7 * rng.unit_f64());
            let bq: Vec<DVec2> = b.iter().map(|&x| (x - cb) * scale + ca + d).collect();
            let Ok(q) = SimplePolygon::try_new(&bq) else {
                continue;
            };
            if crate::polygon::intersection::<Robust>(&p, &q).is_some() {
                continue;
            }
            if let Ok(Ok(r)) = facing::<Robust>(
                &p,
                &q,
                &hull_indices::<Robust>(&p),
                &hull_indices::<Robust>(&q),
            ) {
                // Skip hull-disjoint placements: they are tested apart.
                let disjoint_hulls = matches!(
                    polydist_convex::distance_with::<Robust>(&p.convex_hull(), &q.convex_hull()),
                    polydist_convex::Separation::Disjoint(_)
                );
                if !disjoint_hulls && !r.ring.is_empty() {
                    return Some((p, q));
                }
            }
        }
        None
    }

    /// Two sub-chains of a [`family_pair`], their brute-force closest pair, a vertex of it and a
    /// random lattice direction: a line through the vertex crosses the chains anywhere, but the
    /// closest pair lies in its opposite closed half-planes. `None` when the seed draws no pair.
    struct LineCase {
        pc: Vec<DVec2>,
        qc: Vec<DVec2>,
        brute: ClosestPair,
        anchor: DVec2,
        dir: DVec2,
    }

    fn line_case<K: Kernel>(seed: u64, salt: u64) -> Option<LineCase> {
        let (p, q) = family_pair(seed)?;
        line_case_of::<K>(p.vertices(), q.vertices(), seed ^ salt)
    }

    /// Two lattice shapes (combs and spirals) of integer coordinates, the second moved by an
    /// integer vector until the two are disjoint (up to 40 tries): the degenerate cases of the
    /// clipped chains, lines in lattice directions through lattice vertices running through
    /// vertices and along edges of both, and clip points at rational points that tie.
    fn lattice_case<K: Kernel>(seed: u64) -> Option<LineCase> {
        let mut rng = SplitMix64::new(seed ^ 0x1a77);
        let shape = |rng: &mut SplitMix64| {
            if rng.below(2) == 0 {
                polydist_oracle::spiral(3 + rng.below(6) as u32, 1 + rng.below(2) as u32)
            } else {
                polydist_oracle::comb(
                    1 + rng.index(8),
                    1 + rng.below(4) as u32,
                    1 + rng.below(2) as u32,
                )
            }
        };
        let a = shape(&mut rng);
        let b = shape(&mut rng);
        let p = SimplePolygon::try_new(&a).ok()?;
        for _ in 0..40 {
            let d = DVec2::new(rng.range_i64(-8, 9) as f64, rng.range_i64(-8, 9) as f64);
            let bq: Vec<DVec2> = b.iter().map(|&x| x + d).collect();
            let Ok(q) = SimplePolygon::try_new(&bq) else {
                continue;
            };
            if crate::polygon::intersection::<Robust>(&p, &q).is_none() {
                return line_case_of::<K>(&a, &bq, seed);
            }
        }
        None
    }

    /// [`LineCase`] of two disjoint polygons' vertices.
    fn line_case_of<K: Kernel>(p: &[DVec2], q: &[DVec2], seed: u64) -> Option<LineCase> {
        let mut rng = SplitMix64::new(seed);
        let sub = |rng: &mut SplitMix64, v: &[DVec2]| {
            let (s, len) = (rng.index(v.len()), 2 + rng.index(v.len() - 1));
            (0..len).map(|t| v[(s + t) % v.len()]).collect::<Vec<_>>()
        };
        let (pc, qc) = (sub(&mut rng, p), sub(&mut rng, q));
        let brute = separation_brute::<K>(&pc, &qc).unwrap();
        let anchor = match (brute.feature_p, brute.feature_q) {
            (Feature::Vertex(i), _) => pc[i],
            (_, Feature::Vertex(j)) => qc[j],
            _ => unreachable!("a closest pair has a vertex"),
        };
        let dir = loop {
            let d = DVec2::new(rng.range_i64(-3, 4) as f64, rng.range_i64(-3, 4) as f64);
            if d != DVec2::ZERO {
                break d;
            }
        };
        Some(LineCase {
            pc,
            qc,
            brute,
            anchor,
            dir,
        })
    }

    /// `split` on its own, for one seed: two disjoint sub-chains of an interlocked pair and a line
    /// through a vertex of their brute-force closest pair, in a random lattice direction, so that
    /// the chains cross the line anywhere but the closest pair is in opposite closed half-planes
    /// and meets the separator (here the vertex alone; the conditions Lemma 1 guarantees): the
    /// jobs' best candidate is `σ` exactly, under `K`.
    /// `None` when the seed draws no pair; else whether `split` made several parts of runs, and
    /// whether it clipped the chains for some assignment (section 3 on gapped chains).
    fn check_split<K: Kernel>(seed: u64) -> Option<(bool, bool)> {
        let LineCase {
            pc,
            qc,
            brute,
            anchor,
            dir,
        } = line_case::<K>(seed, 0x5b11)?;
        let jobs = split::<K>(&pc, &qc, anchor, anchor + dir);
        // The closest pair meets the line at `anchor`: a separator `l_i = {anchor}` on it.
        let near = Near {
            a: anchor,
            c: anchor + dir,
            before: [anchor; 2],
            after: [anchor; 2],
        };
        let found = execute::<K>(
            &pc,
            &qc,
            (near.a, near.c),
            || near,
            &jobs,
            f64::INFINITY,
            &mut SeparationStats::default(),
        )
        .unwrap_or_else(|| panic!("seed {seed}: section 3 refused a part split handed it"));
        let best = found
            .iter()
            .map(|(fp, fq, _)| dist_of(&pc, &qc, *fp, *fq))
            .min_by(|x, y| K::cmp_dist2(*x, *y))
            .unwrap();
        let bd = dist_of(&pc, &qc, brute.feature_p, brute.feature_q);
        assert_eq!(
            K::cmp_dist2(best, bd),
            Ordering::Equal,
            "seed {seed}: {pc:?} {qc:?} line {anchor:?} + {dir:?}"
        );
        Some((jobs.section3.len() > 1, !jobs.gapped.is_empty()))
    }

    /// [`check_split`] on 3,000 seeds under Robust and 300 under Exact; counts the multi-run splits
    /// and the clipped ones so that the second and third routes are exercised, not only the peeled
    /// one.
    #[test]
    fn split_keeps_every_pair_across_its_line() {
        let (mut tried, mut multi, mut clipped) = (0, 0, 0);
        for (m, g) in (0..3000u64).filter_map(check_split::<Robust>) {
            tried += 1;
            multi += usize::from(m);
            clipped += usize::from(g);
        }
        for seed in 0..300u64 {
            check_split::<Exact>(seed);
        }
        assert!(
            tried > 1000 && multi > 200 && clipped > 20,
            "{tried} split, {multi} multi-run, {clipped} clipped"
        );
    }

    /// The structure [`crate::gapped::clip_runs`] promises, with no cut: every vertex not strictly
    /// on the wrong side is a site exactly once, in order; every edge from the wrong side strictly
    /// to the kept side gives exactly one clip point; no site is strictly on the wrong side; and consecutive
    /// sites of a run are joined by a piece of one chain edge.
    fn check_clip_structure(chain: &[DVec2], sides: &[Orientation], wrong: Orientation) {
        use crate::gapped::{Origin, clip_runs};
        let g = clip_runs(chain, sides, wrong, (DVec2::ZERO, DVec2::X), f64::INFINITY);
        let n = chain.len();
        let vertices: Vec<usize> = (0..n).filter(|&k| sides[k] != wrong).collect();
        // An edge from the wrong side to the line ends on the line already: no clip point.
        let good = |k: usize| sides[k] != wrong && !sides[k].is_collinear();
        let clips: Vec<usize> = (0..n - 1)
            .filter(|&e| (sides[e] == wrong && good(e + 1)) || (good(e) && sides[e + 1] == wrong))
            .collect();
        let (mut got_v, mut got_c) = (Vec::new(), Vec::new());
        for o in &g.origin {
            match *o {
                Origin::Vertex(k) => got_v.push(k),
                Origin::Clip(e) => got_c.push(e),
            }
        }
        assert_eq!(got_v, vertices, "{sides:?}");
        assert_eq!(got_c, clips, "{sides:?}");
        let mut next = 0;
        for &(s, t) in &g.runs {
            assert_eq!(s, next, "runs cover the sites in order: {:?}", g.runs);
            next = t + 1;
            for k in s..t {
                let linked = match (g.origin[k], g.origin[k + 1]) {
                    (Origin::Vertex(i), Origin::Vertex(j)) => j == i + 1,
                    (Origin::Vertex(i), Origin::Clip(e)) => e == i,
                    (Origin::Clip(e), Origin::Vertex(j)) => j == e + 1,
                    (Origin::Clip(_), Origin::Clip(_)) => false,
                };
                assert!(linked, "sites {k}, {} of {:?}", k + 1, g.origin);
            }
        }
        assert_eq!(next, g.sites.len());
    }

    /// [`separation_of_gapped`] on its own, for one seed: two sub-chains of an interlocked pair and
    /// a line through a vertex of their closest pair in a random lattice direction (as
    /// [`check_split`]), under both assignments of sides, with no cut and with a cut just above
    /// `σ²`. Each answer is a true pair of the sub-chains, no nearer than `σ`, and the nearer of
    /// the two assignments is `σ` exactly (the closest pair lies in opposite closed half-planes).
    /// Under the Fast kernel (`exact == false`) only that nothing panics or loops: section 3 may
    /// then refuse the chains, or answer wrongly.
    fn check_gapped<K: Kernel>(seed: u64, exact: bool) -> Option<()> {
        check_gapped_on::<K>(line_case::<K>(seed, 0x9a9e)?, seed, exact)
    }

    /// [`check_gapped`] on a given case.
    fn check_gapped_on<K: Kernel>(case: LineCase, seed: u64, exact: bool) -> Option<()> {
        let LineCase {
            pc,
            qc,
            brute,
            anchor,
            dir,
        } = case;
        let (a, c) = (anchor, anchor + dir);
        let side = |v: &[DVec2]| v.iter().map(|&x| K::orient(a, c, x)).collect::<Vec<_>>();
        let (sp, sq) = (side(&pc), side(&qc));
        let bd = dist_of(&pc, &qc, brute.feature_p, brute.feature_q);
        for cut in [f64::INFINITY, brute.squared_distance * (1.0 + 1e-9)] {
            let mut best: Option<Dist2> = None;
            for wrong_p in [Orientation::Clockwise, Orientation::CounterClockwise] {
                if cut.is_infinite() {
                    check_clip_structure(&pc, &sp, wrong_p);
                    check_clip_structure(&qc, &sq, wrong_p.reversed());
                }
                let found = separation_of_gapped::<K>(&pc, &qc, (a, c), (&sp, &sq), wrong_p, cut);
                let found = match found {
                    Ok(found) => found,
                    Err(_) if !exact => continue,
                    Err(e) => panic!("seed {seed}: {e:?}"),
                };
                let Some(cand) = found else { continue };
                let pair = build_pair::<K>(cand);
                let d = dist_of(&pc, &qc, pair.feature_p, pair.feature_q);
                if !exact {
                    continue;
                }
                assert_ne!(K::cmp_dist2(d, bd), Ordering::Less, "seed {seed}: below σ");
                if best.is_none_or(|b| K::cmp_dist2(d, b) == Ordering::Less) {
                    best = Some(d);
                }
            }
            if !exact {
                continue;
            }
            let best = best.unwrap_or_else(|| panic!("seed {seed}: no answer"));
            assert_eq!(
                K::cmp_dist2(best, bd),
                Ordering::Equal,
                "seed {seed} cut {cut}: {pc:?} {qc:?} line {a:?} {c:?}"
            );
        }
        Some(())
    }

    /// [`check_gapped`] on 3,000 seeds under Robust, 200 under Exact and 1,000 under Fast.
    #[test]
    fn gapped_section_3_finds_the_pair_across_its_line() {
        let tried = (0..3000u64)
            .filter_map(|seed| check_gapped::<Robust>(seed, true))
            .count();
        for seed in 0..200u64 {
            check_gapped::<Exact>(seed, true);
        }
        for seed in 0..1000u64 {
            check_gapped::<Fast>(seed, false);
        }
        assert!(tried > 1200, "{tried} seeds drew a pair");
    }

    /// [`check_gapped`] on 2,000 lattice cases under Robust and 300 under Exact
    /// ([`lattice_case`]): vertices on the line, edges along it and tied clip points.
    #[test]
    fn gapped_section_3_on_lattice_shapes() {
        let tried = (0..2000u64)
            .filter_map(|seed| check_gapped_on::<Robust>(lattice_case::<Robust>(seed)?, seed, true))
            .count();
        for seed in 0..300u64 {
            if let Some(case) = lattice_case::<Exact>(seed) {
                check_gapped_on::<Exact>(case, seed, true);
            }
        }
        assert!(tried > 1000, "{tried} seeds drew a pair");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
        /// [`check_split`] on random seeds.
        #[test]
        fn proptest_split_keeps_every_pair_across_its_line(seed in proptest::prelude::any::<u64>()) {
            check_split::<Robust>(seed);
        }

        /// [`check_gapped`] on random seeds, random and lattice shapes.
        #[test]
        fn proptest_gapped_section_3(seed in proptest::prelude::any::<u64>()) {
            check_gapped::<Robust>(seed, true);
            if let Some(case) = lattice_case::<Robust>(seed) {
                check_gapped_on::<Robust>(case, seed, true);
            }
        }
    }

    /// Interlocked spiral arms (the benchmarks' corridor, small): the parts of their subproblems are
    /// monotone along their lines and sparse enough, so the windowed sweep answers some of them in
    /// place of section 3. The checker (σ against the brute force, as shipped and with every
    /// subproblem offered to section 3) passes under Robust and Exact, and the sweep is counted.
    #[test]
    fn monotone_parts_are_swept() {
        let spirals = |n: usize| {
            let m = (n / 4).max(8);
            let turns = (m as f64 / 24.0).clamp(0.75, 6.0);
            let pi = std::f64::consts::PI;
            let at = |t: f64, w: f64| DVec2::new(t.cos(), t.sin()) * (t / pi + w);
            let theta = |k: usize| pi + 2.0 * pi * turns * k as f64 / (m - 1) as f64;
            let mut a: Vec<DVec2> = (0..m).map(|k| at(theta(k), 0.25)).collect();
            a.extend((0..m).rev().map(|k| at(theta(k), -0.25)));
            let b: Vec<DVec2> = a.iter().map(|&v| -v).collect();
            (poly(&a), poly(&b))
        };
        let mut swept = 0;
        for n in [256, 512, 1024] {
            let (p, q) = spirals(n);
            check_pair::<Robust>(&p, &q).unwrap_or_else(|e| panic!("n = {n}: {e}"));
            if n <= 256 {
                check_pair::<Exact>(&p, &q).unwrap_or_else(|e| panic!("n = {n}: {e}"));
            }
            let plan = build::<Robust>(&p, &q).unwrap().expect("hulls meet");
            for scan_below in [SCAN_BELOW, 0] {
                let (_, stats) = solve_with::<Robust>(&p, &q, &plan, scan_below).unwrap();
                swept += stats.subproblem_parts_swept;
            }
        }
        eprintln!("{swept} parts swept");
        assert!(swept >= 100, "{swept} parts swept");
        // Walls 64 times denser (dozens of vertices within the clearance along a line): the parts'
        // windows along their lines are crowded, but their depths thin them, and the sweep still
        // answers most parts (counted; the sweep's answers are checked in `monotone.rs`). Windows
        // thinned along the line alone answered 58 of the 94.
        let (p, q) = spirals(65_536);
        let plan = build::<Robust>(&p, &q).unwrap().expect("hulls meet");
        let (_, stats) = solve_with::<Robust>(&p, &q, &plan, SCAN_BELOW).unwrap();
        eprintln!(
            "dense spirals: {} of {} parts swept",
            stats.subproblem_parts_swept, stats.subproblems_section3
        );
        assert!(
            stats.subproblem_parts_swept * 10 >= stats.subproblems_section3 * 8,
            "{stats:?}"
        );
    }

    /// The checker on interlocked pairs of every generator family (deep comb pockets, spirals, 2-opt
    /// polygons), property (v) on the smaller ones.
    #[test]
    fn every_family_satisfies_the_separator_properties() {
        let mut checked = 0;
        for seed in 0..1500 {
            let Some((p, q)) = family_pair(seed) else {
                continue;
            };
            let v = p.len() + q.len() <= 48;
            for res in [
                check_pair_v::<Robust>(&p, &q, v),
                check_pair::<Exact>(&p, &q),
            ] {
                if let Err(e) = res {
                    panic!(
                        "seed {seed}: {e}\nP = {:?}\nQ = {:?}",
                        p.vertices(),
                        q.vertices()
                    );
                }
            }
            // The same pair scaled by 2^60 (exact): the construction and its properties must not
            // change with the magnitude of the coordinates.
            let scaled =
                |v: &[DVec2]| -> Vec<DVec2> { v.iter().map(|&x| x * 2f64.powi(60)).collect() };
            let (ps, qs) = (poly(&scaled(p.vertices())), poly(&scaled(q.vertices())));
            let (a, b) = (check_pair::<Robust>(&p, &q), check_pair::<Robust>(&ps, &qs));
            assert_eq!(a, b, "seed {seed}: the scaled pair differs");
            checked += 1;
        }
        assert!(checked >= 300, "{checked}");
    }

    /// The subproblem scan gives exactly the brute-force twin's pair (features and tie-breaking) on
    /// random small chains, lattice chains full of ties included.
    #[test]
    fn scan_agrees_with_the_brute_force() {
        let mut rng = SplitMix64::new(0x5ca7);
        for _ in 0..4000 {
            let lattice = rng.coin();
            let pt = |rng: &mut SplitMix64| {
                if lattice {
                    DVec2::new(rng.range_i64(-4, 5) as f64, rng.range_i64(-4, 5) as f64)
                } else {
                    DVec2::new(rng.unit_f64(), rng.unit_f64())
                }
            };
            let p: Vec<DVec2> = (0..1 + rng.index(5)).map(|_| pt(&mut rng)).collect();
            let q: Vec<DVec2> = (0..1 + rng.index(5)).map(|_| pt(&mut rng)).collect();
            let a = scan::<Robust>(&p, &q, true);
            let b = separation_brute::<Robust>(&p, &q).unwrap();
            assert_eq!(
                (a.feature_p, a.feature_q),
                (b.feature_p, b.feature_q),
                "{p:?} {q:?}"
            );
            assert_eq!(a.squared_distance.to_bits(), b.squared_distance.to_bits());
        }
    }

    /// A "C": an outer arc of radius 2–2.5 and a spiky inner arc of radius 0.9–1.6 (clockwise),
    /// open over `gap` radians around `phi`: its inside is one pocket, closed by a lid across the
    /// mouth.
    pub(super) fn c_shape(rng: &mut SplitMix64, n_out: usize, n_in: usize, gap: f64) -> Vec<DVec2> {
        let phi = core::f64::consts::TAU * rng.unit_f64();
        let span = core::f64::consts::TAU - gap;
        let at = |a: f64, r: f64| DVec2::new(a.cos(), a.sin()) * r;
        let mut v: Vec<DVec2> = (0..n_out)
            .map(|k| {
                let a = phi + gap / 2.0 + span * k as f64 / (n_out - 1) as f64;
                at(a, 2.0 + 0.5 * rng.unit_f64())
            })
            .collect();
        v.extend((0..n_in).map(|k| {
            let a = phi + gap / 2.0 + span * (n_in - 1 - k) as f64 / (n_in - 1) as f64;
            at(a, 0.9 + 0.7 * rng.unit_f64())
        }));
        v
    }

    /// A random star placed inside a random C (or in its mouth), disjoint from it.
    fn pocket_pair(seed: u64) -> Option<(SimplePolygon, SimplePolygon)> {
        let mut rng = SplitMix64::new(seed ^ 0x90c4e7);
        let (n_out, n_in) = (3 + rng.index(12), 3 + rng.index(30));
        let gap = 0.2 + 1.2 * rng.unit_f64();
        let q = SimplePolygon::try_new(&c_shape(&mut rng, n_out, n_in, gap)).ok()?;
        let n = 3 + rng.index(30);
        let spikes = rng.index(n + 1);
        let star = polydist_oracle::star(&mut rng, n, spikes);
        let scale = 0.15 + 0.7 * rng.unit_f64();
        let ang = core::f64::consts::TAU * rng.unit_f64();
        let d = DVec2::new(ang.cos(), ang.sin()) * 1.2 * rng.unit_f64();
        let pv: Vec<DVec2> = star.iter().map(|&x| x * scale + d).collect();
        let p = SimplePolygon::try_new(&pv).ok()?;
        if crate::polygon::intersection::<Robust>(&p, &q).is_some() {
            return None;
        }
        Some((p, q))
    }

    /// The containing case: a star in the pocket of a C, in both orders (the second swaps the
    /// polygons), checked like every other case; the annulus (two passes) and the lid-touching
    /// layouts both occur.
    #[test]
    fn pocket_pairs_satisfy_the_separator_properties() {
        let (mut annulus, mut other) = (0, 0);
        // Sights that only one of the two passes holds: each pass is needed.
        let mut only = [0, 0];
        for seed in 0..1500 {
            let Some((p, q)) = pocket_pair(seed) else {
                continue;
            };
            let Some(plan) = build::<Robust>(&p, &q).unwrap() else {
                panic!("seed {seed}: no region");
            };
            if plan.passes.len() == 2 {
                annulus += 1;
            } else {
                other += 1;
            }
            let v = p.len() + q.len() <= 40;
            for (a, b) in [(&p, &q), (&q, &p)] {
                let robust = check_pair_cover::<Robust>(a, b, v);
                if let Ok((_, o)) = &robust
                    && o.len() == 2
                {
                    only[0] += o[0];
                    only[1] += o[1];
                }
                for (name, res) in [
                    ("Robust", robust.map(|(m, _)| m)),
                    ("Exact", check_pair_v::<Exact>(a, b, false)),
                ] {
                    if let Err(e) = res {
                        panic!(
                            "seed {seed} ({name}): {e}\nP = {:?}\nQ = {:?}",
                            a.vertices(),
                            b.vertices()
                        );
                    }
                }
            }
            if let Ok(Some(b)) = build::<Fast>(&p, &q) {
                let _ = solve::<Fast>(&p, &q, &b);
                let _ = solve_with::<Fast>(&p, &q, &b, 0);
            }
        }
        eprintln!("annulus {annulus} other {other} only {only:?}");
        assert!(only[0] > 0 && only[1] > 0, "{only:?}");
        assert!(
            annulus >= 300,
            "only {annulus} annulus cases ({other} others)"
        );
    }

    /// `P` in the pocket of a U touching the pocket's lid (the top side `y = 10`): at one vertex
    /// (pinched on the lid), along an edge, and at two vertices with a notch between them (the
    /// non-containing layout with both bridges on the lid); and in the open pocket (the annulus).
    /// In both orders, with every vertex–vertex sight checked.
    #[test]
    fn pocket_lid_touching_and_open() {
        let u = ring(&[
            [0.0, 0.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [8.0, 10.0],
            [8.0, 2.0],
            [2.0, 2.0],
            [2.0, 10.0],
            [0.0, 10.0],
        ]);
        let cases: [(&[[f64; 2]], usize, bool); 4] = [
            (&[[4.0, 5.0], [6.0, 5.0], [5.0, 10.0]], 1, true),
            (
                &[[3.0, 6.0], [7.0, 6.0], [7.0, 10.0], [3.0, 10.0]],
                1,
                false,
            ),
            (
                &[[3.0, 6.0], [7.0, 6.0], [7.0, 10.0], [5.0, 8.0], [3.0, 10.0]],
                1,
                false,
            ),
            (
                &[[3.0, 4.0], [7.0, 3.0], [6.0, 9.0], [5.0, 6.0], [4.0, 9.5]],
                2,
                false,
            ),
        ];
        for (k, &(pv, passes, cut)) in cases.iter().enumerate() {
            let p = ring(pv);
            let plan = build::<Robust>(&p, &u)
                .unwrap_or_else(|e| panic!("case {k}: {e}"))
                .unwrap();
            assert_eq!(plan.passes.len(), passes, "case {k}");
            assert_eq!(
                plan.passes.iter().all(|b| b.region.cut.is_some()),
                cut || passes == 2,
                "case {k}"
            );
            for (a, b) in [(&p, &u), (&u, &p)] {
                check_pair_v::<Robust>(a, b, true).unwrap_or_else(|e| panic!("case {k}: {e}"));
                check_pair_v::<Exact>(a, b, true).unwrap_or_else(|e| panic!("case {k}: {e}"));
            }
        }
        // Inside the U's wall, not in its pocket: no region (the polygons meet).
        let inner = ring(&[[0.5, 0.5], [1.5, 0.5], [1.0, 1.5]]);
        assert!(build::<Robust>(&inner, &u).unwrap().is_none());
        assert!(build::<Robust>(&u, &inner).unwrap().is_none());
    }

    /// A diamond in a notch of a comb whose tooth tips all lie on one hull edge: the notch is a
    /// pocket of its own (its lid runs between two tips, not along the whole hull edge), in the
    /// open and touching its lid at one vertex. Found by the proptests of `tests/polygons.rs`.
    #[test]
    fn pocket_in_a_comb_notch() {
        let comb = ring(&[
            [0.0, -1.0],
            [5.0, -1.0],
            [5.0, 3.0],
            [4.0, 3.0],
            [4.0, 0.0],
            [3.0, 0.0],
            [3.0, 3.0],
            [2.0, 3.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ]);
        for (tip, passes) in [(2.875, 2), (3.0, 1)] {
            let d = ring(&[[3.5, 0.5], [3.875, 1.5], [3.5, tip], [3.125, 1.5]]);
            let plan = build::<Robust>(&d, &comb).unwrap().unwrap();
            assert_eq!(plan.passes.len(), passes);
            for (a, b) in [(&d, &comb), (&comb, &d)] {
                check_pair_v::<Robust>(a, b, true).unwrap_or_else(|e| panic!("{tip}: {e}"));
                check_pair_v::<Exact>(a, b, true).unwrap_or_else(|e| panic!("{tip}: {e}"));
            }
        }
    }

    /// A kept half is found again under every rotation of its vertex list, and its relabelled
    /// triangles triangulate the rotated polygon; a different polygon is triangulated anew.
    #[test]
    fn kept_halves_serve_their_rotations() {
        let mut rng = SplitMix64::new(0x4a1f);
        for round in 0..300 {
            let n = 3 + rng.index(60);
            let spikes = rng.index(n + 1);
            let v = if round % 2 == 0 {
                polydist_oracle::star(&mut rng, n, spikes)
            } else {
                polydist_oracle::two_opt(&mut rng, n)
            };
            let mut cache = Halves::default();
            let t = cache.triangulate::<Robust>(&v).expect("simple");
            t.check::<Robust>(&v).expect("a triangulation");
            let off = rng.index(v.len());
            let rotated: Vec<DVec2> = (0..v.len()).map(|i| v[(i + off) % v.len()]).collect();
            let t = cache.triangulate::<Robust>(&rotated).expect("kept");
            assert_eq!(cache.kept.len(), 1, "a rotation is found again");
            t.check::<Robust>(&rotated)
                .unwrap_or_else(|e| panic!("round {round}, offset {off}: {e}"));
            // Reversed (another polygon: clockwise) or moved: not found.
            let moved: Vec<DVec2> = v.iter().map(|&x| x + DVec2::X).collect();
            cache.triangulate::<Robust>(&moved).expect("simple");
            assert_eq!(cache.kept.len(), 2);
        }
    }

    /// `trimmed` keeps exactly the edges of the subchain with an end in the share: on random small
    /// lattice rings, levels, subchains and shares (above or not, in both directions).
    #[test]
    fn trimming_keeps_every_edge_reaching_the_share() {
        let mut rng = SplitMix64::new(0x7e1);
        let mut dropped = 0;
        for _ in 0..4000 {
            let n = 2 + rng.below(12) as usize;
            let ring: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(rng.below(5) as f64, rng.below(5) as f64))
                .collect();
            let turn = if rng.below(2) == 0 { 0 } else { 2 };
            let level = rng.below(5) as f64 - if turn == 2 { 4.0 } else { 0.0 };
            let qlo = rng.below(n as u64) as usize;
            let qhi = qlo + rng.below((n - qlo) as u64) as usize;
            let share = Share {
                turn,
                level,
                above: rng.below(2) == 0,
            };
            let r = Region {
                ring: ring.clone(),
                src: (0..n).collect(),
                qt: n - 1,
                pb: 0,
                np: 1,
                top: 1,
                gap: None,
                cut: None,
                share: Some(share),
            };
            // The edges (k, k + 1) within the subchain with an end in the share, as first vertices.
            let reaching: Vec<usize> = (qlo..qhi)
                .filter(|&k| share.holds(ring[k]) || share.holds(ring[k + 1]))
                .collect();
            let any = (qlo..=qhi).any(|k| share.holds(ring[k]));
            match trimmed(&r, qlo, qhi) {
                None => {
                    assert!(!any, "{ring:?} {qlo}..={qhi} {share:?}: dropped");
                    dropped += 1;
                }
                Some((lo, hi)) => {
                    assert!(any && qlo <= lo && lo <= hi && hi <= qhi);
                    // Every vertex in the share and every edge reaching it is kept, and the ends are
                    // such a vertex or an edge's end (nothing more is kept at the ends).
                    assert!((qlo..=qhi).all(|k| !share.holds(ring[k]) || (lo..=hi).contains(&k)));
                    assert!(reaching.iter().all(|&k| lo <= k && k < hi));
                    assert!(share.holds(ring[lo]) || reaching.contains(&lo));
                    assert!(share.holds(ring[hi]) || (hi > 0 && reaching.contains(&(hi - 1))));
                }
            }
        }
        assert!(dropped > 0);
        // Without a restriction the subchain is kept whole.
        let r = Region {
            share: None,
            ..Region::from_chains(&[DVec2::ZERO], &[DVec2::X, DVec2::Y], 0, 0, &[0, 1])
        };
        assert_eq!(trimmed(&r, 1, 2), Some((1, 2)));
    }

    /// The pruned scan is the scan, feature for feature (ties included), on random and lattice
    /// chains of 1–80 vertices, with and without `interior_only`; and it prunes on far-apart chains.
    #[test]
    fn pruned_scan_is_the_scan() {
        let mut rng = SplitMix64::new(0xb0c5);
        for round in 0..500 {
            let lattice = rng.coin();
            let pt = |rng: &mut SplitMix64, dx: f64| {
                if lattice {
                    DVec2::new(
                        rng.range_i64(-6, 7) as f64 + dx,
                        rng.range_i64(-6, 7) as f64,
                    )
                } else {
                    DVec2::new(rng.unit_f64() + dx, rng.unit_f64())
                }
            };
            let dx = [0.0, 3.0, 40.0][round % 3];
            let p: Vec<DVec2> = (0..1 + rng.index(80)).map(|_| pt(&mut rng, 0.0)).collect();
            let q: Vec<DVec2> = (0..1 + rng.index(80)).map(|_| pt(&mut rng, dx)).collect();
            for interior in [true, false] {
                for (a, b) in [
                    (
                        scan::<Robust>(&p, &q, interior),
                        scan_pruned::<Robust>(&p, &q, interior),
                    ),
                    (
                        scan::<Exact>(&p, &q, interior),
                        scan_pruned::<Exact>(&p, &q, interior),
                    ),
                ] {
                    assert_eq!(
                        (a.feature_p, a.feature_q),
                        (b.feature_p, b.feature_q),
                        "{p:?} {q:?}"
                    );
                    assert_eq!(a.squared_distance.to_bits(), b.squared_distance.to_bits());
                }
            }
            let _ = scan_pruned::<Fast>(&p, &q, true);
        }
        // Pruning happens: two long chains far apart on a line compare far fewer pairs.
        use polydist_polygon::predicates::{Counted, predicate_counts, reset_predicate_counts};
        let p: Vec<DVec2> = (0..400).map(|k| DVec2::new(k as f64, 0.0)).collect();
        let q: Vec<DVec2> = (0..400).map(|k| DVec2::new(k as f64 + 0.5, 1.0)).collect();
        reset_predicate_counts();
        let _ = scan::<Counted<Robust>>(&p, &q, true);
        let full = predicate_counts().total();
        reset_predicate_counts();
        let _ = scan_pruned::<Counted<Robust>>(&p, &q, true);
        let pruned = predicate_counts().total();
        assert!(pruned * 20 < full, "{pruned} against {full}");
    }

    /// What [`check_pruned`] saw: regions pruned (of them in the containing case and in the
    /// pinched channel), ring vertices cut off, arms ending inside a pruned pocket.
    #[derive(Default)]
    struct PruneCounts {
        regions: usize,
        containing: usize,
        pinched: usize,
        removed: usize,
        arms_inside: usize,
    }

    /// Builds every region of `(p, q)` pruned and unpruned and asserts that the reduced region's
    /// runs, read on the full ring with their arms carried on into the pockets, are the unpruned
    /// runs (walked without budget), and so are the kept runs, cuts and subchains.
    fn check_pruned<K: Kernel>(p: &SimplePolygon, q: &SimplePolygon, counts: &mut PruneCounts) {
        let (hp, hq) = (hull_indices::<K>(p), hull_indices::<K>(q));
        let Ok(Some((rs, swapped))) = regions::<K>(p, q, &hp, &hq) else {
            return;
        };
        let (wp, wq) = walls((p, &hp), (q, &hq), swapped);
        for r in rs {
            let Some(pruned) = crate::pockets::prune::<K>(&r, wp, wq) else {
                continue;
            };
            let n = r.ring.len();
            let Ok((tri, path)) = geodesic_of::<K>(&r, &mut Halves::default()) else {
                continue;
            };
            let full = runs_with_arms::<K>(&tri, &r.ring, &path, usize::MAX, plain, |i| i).unwrap();
            let sel =
                pruned_selection::<K>(&r, &pruned, &mut Halves::default()).unwrap_or_else(|| {
                    panic!(
                        "no pruned runs: P = {:?}\nQ = {:?}",
                        p.vertices(),
                        q.vertices()
                    )
                });
            let runs = sel.runs.clone();
            assert_eq!(runs, full, "P = {:?}\nQ = {:?}", p.vertices(), q.vertices());
            let mut kept = vec![false; n];
            for &i in &pruned.keep {
                kept[i] = true;
            }
            counts.arms_inside += runs
                .iter()
                .flat_map(|s| [s.bottom, s.top])
                .filter(|e| match *e {
                    End::Vertex(v) => !kept[v],
                    End::Edge(e) => !kept[e] || !kept[(e + 1) % n],
                    End::Run => false,
                })
                .count();
            counts.regions += 1;
            counts.containing += usize::from(r.gap.is_some());
            counts.pinched += usize::from(r.cut.is_some() && r.gap.is_none());
            counts.removed += n - pruned.keep.len();
            let a = finish(r.clone(), sel);
            let b = build_region::<K>(r, &mut Halves::default()).unwrap();
            assert_eq!((&a.kept, &a.sub, &a.cuts), (&b.kept, &b.sub, &b.cuts));
        }
    }

    /// A star pair scaled by 32 or 64 and snapped to the integer lattice: vertices on the other
    /// polygon's hull lines, collinear hull vertices, lids touched (degenerate contacts).
    fn snapped_pair(seed: u64) -> Option<(SimplePolygon, SimplePolygon)> {
        let (p, q) = star_pair(seed)?;
        let scale = if seed % 2 == 0 { 32.0 } else { 64.0 };
        let snap = |x: &SimplePolygon| {
            let v: Vec<DVec2> = x.vertices().iter().map(|&v| (v * scale).round()).collect();
            SimplePolygon::try_new(&v).ok()
        };
        let (p, q) = (snap(&p)?, snap(&q)?);
        crate::polygon::intersection::<Robust>(&p, &q)
            .is_none()
            .then_some((p, q))
    }

    /// Cutting off the unentered pockets before triangulating changes no separator
    /// ([`check_pruned`]), on star pairs (whose hulls overlap), the interlocked families, stars in
    /// a pocket (both orders), interleaved combs and snapped star pairs. Some arms must end inside
    /// a pruned pocket, and regions must fall in every case (the pinched channel included).
    #[test]
    fn pruned_pockets_change_no_separator() {
        let mut pairs: Vec<(SimplePolygon, SimplePolygon)> =
            (0..400).filter_map(star_pair).collect();
        pairs.extend((0..300).filter_map(family_pair));
        pairs.extend((0..1000).filter_map(snapped_pair));
        for (teeth, len) in [(2, 3), (6, 5), (17, 9)] {
            let pair = polydist_oracle::interleaved_combs(teeth, len, 0.125);
            pairs.push((poly(&pair.a), poly(&pair.b)));
        }
        for seed in 0..400 {
            if let Some((p, q)) = pocket_pair(seed) {
                pairs.push((q.clone(), p.clone()));
                pairs.push((p, q));
            }
        }
        let mut counts = PruneCounts::default();
        for (p, q) in &pairs {
            check_pruned::<Robust>(p, q, &mut counts);
        }
        let c = counts;
        assert!(
            c.regions > c.containing + 100
                && c.containing > 100
                && c.pinched > 10
                && c.arms_inside > 100,
            "{} regions pruned ({} containing, {} pinched), {} vertices removed, {} arms end inside \
             a pocket",
            c.regions,
            c.containing,
            c.pinched,
            c.removed,
            c.arms_inside
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// [`check_pruned`] on random seeds of every generator, under Robust and Exact.
        #[test]
        fn proptest_pruned_pockets_change_no_separator(seed in proptest::prelude::any::<u64>()) {
            let mut counts = PruneCounts::default();
            let pairs = [star_pair(seed), family_pair(seed), snapped_pair(seed), pocket_pair(seed)];
            for (p, q) in pairs.into_iter().flatten() {
                check_pruned::<Robust>(&p, &q, &mut counts);
                check_pruned::<Exact>(&p, &q, &mut counts);
                check_pruned::<Robust>(&q, &p, &mut counts);
            }
        }
    }
}
