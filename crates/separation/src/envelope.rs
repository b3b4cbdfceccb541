//! Lemma 2 for general simple chains: the perpendicular-visibility envelope `P°` (Amato 1992,
//! section 3), by divide and conquer over the chain, and its `O(n²)` brute-force twin.
//!
//! In the frame of the line (depth `X`, height `H`), `P°` is the graph of
//! `f(y) = min{X(z) : z ∈ P, H(z) = y}` over the heights the chain covers. For a simple chain
//! (no two non-adjacent edges meet, adjacent edges meet only at their common vertex):
//!
//! * between two consecutive vertex heights, the edges crossing the open slab are pairwise disjoint,
//!   so their depth order is constant and one edge is nearest (an *elementary slab*);
//! * at a vertex height `y`, the nearest point at `y` is a vertex, or an interior point of an edge
//!   that is then nearest on both sides of `y` too (every other point at height `y` is strictly
//!   deeper, and so are, by continuity, the edges near it);
//! * hence the envelope is a list of *visible vertices* `v_0, …, v_m`, strictly increasing in height,
//!   and between `v_k` and `v_{k+1}` one edge `e_k`, whose part between the two heights is on `P°`;
//!   `e_k` may end at the two heights (at `v_k` or at a vertex hidden behind it) or pass behind `v_k`
//!   (a *shadow point*, kept as the symbolic root of `H(x) − H(v_k)` on `e_k`).
//!
//! The envelope of a sub-chain is merged from those of its two halves in time linear in their sizes
//! (a merge of two height-sorted lists; in a common open slab the two edges are disjoint, so one
//! orientation test orders them). Bottom-up over the chain this is `O(n log n)`; when the two halves
//! cover height ranges that meet in at most one point (e.g. along a monotone stretch) the merge is a
//! concatenation with `O(1)` predicates, so monotone chains cost `O(n)` predicates.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign, is_valid_coordinate};

use crate::chain::{EnvEdge, Prepared};
use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::param::Param;

/// The nearest point of the chain at the height of a breakpoint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum At {
    /// A vertex.
    Vertex(usize),
    /// The interior of an edge (at the height of the breakpoint's vertex).
    Edge(usize),
}

/// A breakpoint of an envelope: the vertex `y` giving its height, the nearest point `at` there, and
/// the nearest edge (or a gap) `gap` in the open interval just above it (`None` above the last).
#[derive(Clone, Copy, Debug)]
struct Bp {
    y: usize,
    at: At,
    gap: Option<usize>,
}

/// The envelope of a sub-chain, borrowed from a [`Level`]: breakpoints strictly increasing in
/// height.
#[derive(Clone, Copy)]
struct Env<'a> {
    bps: &'a [Bp],
}

impl Env<'_> {
    /// The edge over the open interval just below breakpoint `i` (`None` below the first and above
    /// the last).
    #[inline]
    fn open(&self, i: usize) -> Option<usize> {
        if i > 0 && i < self.bps.len() {
            self.bps[i - 1].gap
        } else {
            None
        }
    }
}

/// The envelopes of consecutive sub-chains stored back to back in one flat array (one round of the
/// divide and conquer): envelope `s` is the range `segs[s]` of breakpoints. Two levels are reused in
/// turn, so a round allocates nothing once the arrays have grown.
#[derive(Default)]
struct Level {
    bps: Vec<Bp>,
    segs: Vec<(usize, usize)>,
}

impl Level {
    fn with_capacity(n: usize) -> Level {
        Level {
            bps: Vec::with_capacity(n),
            segs: Vec::new(),
        }
    }

    fn clear(&mut self) {
        self.bps.clear();
        self.segs.clear();
    }

    #[inline]
    fn env(&self, s: usize) -> Env<'_> {
        let (lo, hi) = self.segs[s];
        Env {
            bps: &self.bps[lo..hi],
        }
    }

    #[inline]
    fn push(&mut self, y: usize, at: At, gap: Option<usize>) {
        self.bps.push(Bp { y, at, gap });
    }

    /// Closes the envelope begun at breakpoint `start`.
    #[inline]
    fn close(&mut self, start: usize) {
        self.segs.push((start, self.bps.len()));
    }
}

/// A chain without repeated consecutive vertices, with its edges oriented upward.
struct Ctx<'a> {
    frame: Frame,
    v: &'a [DVec2],
    /// Caller index of each vertex.
    idx: &'a [usize],
    /// Each edge's lower and upper vertex, `None` for an edge perpendicular to the line.
    lohi: &'a [Option<(usize, usize)>],
}

/// Where the envelope computation found the chain not simple (or the kernel inconsistent): the
/// vertex involved.
type Bad = usize;

impl Ctx<'_> {
    fn bad(&self, k: usize, which: Chain) -> SeparationError {
        SeparationError::NotSimple {
            chain: which,
            index: self.idx[k],
        }
    }

    fn ends(&self, e: usize) -> (usize, usize) {
        // Only non-perpendicular edges enter envelopes.
        self.lohi[e].unwrap_or((0, 0))
    }
}

/// Is vertex `w` nearer to the line than edge `e` at `w`'s height (strictly inside `e`'s range)?
fn vertex_vs_edge<K: Kernel>(c: &Ctx<'_>, w: usize, e: usize) -> Result<Ordering, Bad> {
    let (a, b) = c.ends(e);
    // With `e` pointing up, points nearer to the line are on its left in the frame.
    match c.frame.orient::<K>(c.v[a], c.v[b], c.v[w]) {
        Sign::Positive => Ok(Ordering::Less),
        Sign::Negative => Ok(Ordering::Greater),
        Sign::Zero => Err(w), // the vertex lies inside the edge: not simple
    }
}

/// Orders two edges over an open height interval both span (`Less`: `e1` nearer to the line).
/// Disjoint over that interval (simple chain), so one test at the higher of the two bottoms decides;
/// when that bottom lies on the other edge, they share it and the lower of the two tops decides.
/// At most four degree-2 tests.
fn edge_vs_edge<K: Kernel>(c: &Ctx<'_>, e1: usize, e2: usize) -> Result<Ordering, Bad> {
    if e1 == e2 {
        return Ok(Ordering::Equal);
    }
    let ((a1, b1), (a2, b2)) = (c.ends(e1), c.ends(e2));
    if c.frame.cmp_height::<K>(c.v[a1], c.v[a2]) == Ordering::Less {
        return edge_vs_edge::<K>(c, e2, e1).map(Ordering::reverse);
    }
    // a1 is at least as high as a2 and below the top of e2: it is within e2's height range.
    match c.frame.orient::<K>(c.v[a2], c.v[b2], c.v[a1]) {
        Sign::Positive => return Ok(Ordering::Less),
        Sign::Negative => return Ok(Ordering::Greater),
        Sign::Zero => {}
    }
    if a1 != a2 {
        return Err(a1); // a1 lies on e2 without being its end: not simple
    }
    // A common bottom vertex: the lower top lies within the other edge's range.
    if c.frame.cmp_height::<K>(c.v[b1], c.v[b2]) != Ordering::Greater {
        match c.frame.orient::<K>(c.v[a2], c.v[b2], c.v[b1]) {
            Sign::Positive => Ok(Ordering::Less),
            Sign::Negative => Ok(Ordering::Greater),
            Sign::Zero => Err(b1), // the edges overlap
        }
    } else {
        match c.frame.orient::<K>(c.v[a1], c.v[b1], c.v[b2]) {
            Sign::Positive => Ok(Ordering::Greater),
            Sign::Negative => Ok(Ordering::Less),
            Sign::Zero => Err(b2),
        }
    }
}

/// The nearer of two points of the chain at the same height.
fn nearer<K: Kernel>(c: &Ctx<'_>, x: At, y: At) -> Result<At, Bad> {
    let o = match (x, y) {
        (At::Vertex(u), At::Vertex(w)) => {
            if u == w {
                return Ok(x);
            }
            match c.frame.cmp_depth::<K>(c.v[u], c.v[w]) {
                Ordering::Equal => return Err(w), // two vertices at one point: not simple
                o => o,
            }
        }
        (At::Vertex(u), At::Edge(e)) => vertex_vs_edge::<K>(c, u, e)?,
        (At::Edge(e), At::Vertex(u)) => vertex_vs_edge::<K>(c, u, e)?.reverse(),
        (At::Edge(e), At::Edge(f)) => edge_vs_edge::<K>(c, e, f)?,
    };
    Ok(if o == Ordering::Greater { y } else { x })
}

/// Appends the envelope of a single edge.
fn leaf<K: Kernel>(c: &Ctx<'_>, e: usize, ends: (usize, usize), out: &mut Level) {
    let start = out.bps.len();
    match c.lohi[e] {
        Some((a, b)) => {
            out.push(a, At::Vertex(a), Some(e));
            out.push(b, At::Vertex(b), None);
        }
        None => {
            // Perpendicular to the line: only the nearer end is visible.
            let (u, w) = ends;
            let k = if c.frame.cmp_depth::<K>(c.v[w], c.v[u]) == Ordering::Less {
                w
            } else {
                u
            };
            out.push(k, At::Vertex(k), None);
        }
    }
    out.close(start);
}

/// Appends `lo` then `hi`, whose height ranges meet at most at `lo`'s top = `hi`'s bottom.
fn concat<K: Kernel>(c: &Ctx<'_>, lo: Env<'_>, hi: Env<'_>, out: &mut Level) -> Result<(), Bad> {
    out.bps.extend_from_slice(lo.bps);
    let (Some(top), Some(bot)) = (lo.bps.last(), hi.bps.first()) else {
        out.bps.extend_from_slice(hi.bps);
        return Ok(());
    };
    if c.frame.cmp_height::<K>(c.v[top.y], c.v[bot.y]) == Ordering::Equal {
        // One breakpoint at the common height, with `hi`'s gap above (`lo`'s last is `None`).
        let at = nearer::<K>(c, top.at, bot.at)?;
        if let Some(last) = out.bps.last_mut() {
            last.at = at;
            last.gap = bot.gap;
        }
        out.bps.extend_from_slice(&hi.bps[1..]);
    } else {
        // `lo`'s last gap (`None`) is the empty interval between the two.
        out.bps.extend_from_slice(hi.bps);
    }
    Ok(())
}

/// Appends the envelope of the union of two sub-chains. `O(|a| + |b|)` tests of degree 2.
fn merge<K: Kernel>(c: &Ctx<'_>, a: Env<'_>, b: Env<'_>, out: &mut Level) -> Result<(), Bad> {
    let start = out.bps.len();
    let (Some(a_top), Some(b_top)) = (a.bps.last(), b.bps.last()) else {
        out.bps
            .extend_from_slice(if a.bps.is_empty() { b.bps } else { a.bps });
        out.close(start);
        return Ok(());
    };
    let (a_top, b_top, a_bot, b_bot) = (a_top.y, b_top.y, a.bps[0].y, b.bps[0].y);
    if c.frame.cmp_height::<K>(c.v[a_top], c.v[b_bot]) != Ordering::Greater {
        concat::<K>(c, a, b, out)?;
        out.close(start);
        return Ok(());
    }
    if c.frame.cmp_height::<K>(c.v[b_top], c.v[a_bot]) != Ordering::Greater {
        concat::<K>(c, b, a, out)?;
        out.close(start);
        return Ok(());
    }
    let (na, nb) = (a.bps.len(), b.bps.len());
    // The last pair of edges compared and the result: the order of two disjoint edges is the same
    // over every interval they both span.
    let mut last: Option<(usize, usize, Ordering)> = None;
    let (mut i, mut j) = (0, 0);
    // Each step consumes at least one breakpoint: at most na + nb steps.
    while i < na || j < nb {
        let o = if i == na {
            Ordering::Greater
        } else if j == nb {
            Ordering::Less
        } else {
            c.frame.cmp_height::<K>(c.v[a.bps[i].y], c.v[b.bps[j].y])
        };
        let (y, pt) = match o {
            Ordering::Less => {
                let (y, p) = (a.bps[i].y, a.bps[i].at);
                i += 1;
                match b.open(j) {
                    Some(e) => (y, nearer::<K>(c, p, At::Edge(e))?),
                    None => (y, p),
                }
            }
            Ordering::Greater => {
                let (y, p) = (b.bps[j].y, b.bps[j].at);
                j += 1;
                match a.open(i) {
                    Some(e) => (y, nearer::<K>(c, At::Edge(e), p)?),
                    None => (y, p),
                }
            }
            Ordering::Equal => {
                let y = a.bps[i].y;
                let p = nearer::<K>(c, a.bps[i].at, b.bps[j].at)?;
                i += 1;
                j += 1;
                (y, p)
            }
        };
        let g = if i < na || j < nb {
            match (a.open(i), b.open(j)) {
                (Some(e), Some(f)) => {
                    let o = match last {
                        Some((x, z, o)) if (x, z) == (e, f) => o,
                        _ => {
                            let o = edge_vs_edge::<K>(c, e, f)?;
                            last = Some((e, f, o));
                            o
                        }
                    };
                    Some(if o == Ordering::Greater { f } else { e })
                }
                (e, None) => e,
                (None, f) => f,
            }
        } else {
            None
        };
        out.push(y, pt, g);
    }
    coalesce(out, start);
    out.close(start);
    Ok(())
}

/// Drops, from the breakpoints `start..` of `out`, those at interior points of an edge that is
/// nearest on both sides (they are not breakpoints of the envelope), in place. No predicate.
fn coalesce(out: &mut Level, start: usize) {
    let bps = &mut out.bps;
    let n = bps.len() - start;
    let mut w = start;
    for k in 0..n {
        let r = start + k;
        if let At::Edge(e) = bps[r].at {
            // `bps[r - 1]` is still the original: writes so far went below `w ≤ r`, or to `r - 1`
            // itself while nothing was dropped.
            if k > 0 && k + 1 < n && bps[r - 1].gap == Some(e) && bps[r].gap == Some(e) {
                continue; // the gap below (already kept) continues above
            }
        }
        bps[w] = bps[r];
        w += 1;
    }
    bps.truncate(w);
}

/// A chain with repeated consecutive vertices dropped and a closing repeat removed.
struct Clean {
    v: Vec<DVec2>,
    idx: Vec<usize>,
    /// `(from, to, caller edge index)`.
    edges: Vec<(usize, usize, usize)>,
}

/// Drops repeated consecutive vertices; a chain whose last vertex equals its first (with at least
/// three distinct vertices) is closed: the repeat is removed and the closing edge joins the last
/// vertex to vertex 0. The caller's edge index of the edge into vertex `k` is the caller index of
/// `k`'s first occurrence minus one.
fn clean(chain: &[DVec2], which: Chain) -> Result<Clean, SeparationError> {
    let mut v: Vec<DVec2> = Vec::with_capacity(chain.len());
    let mut idx: Vec<usize> = Vec::with_capacity(chain.len());
    for (i, &x) in chain.iter().enumerate() {
        if v.last() != Some(&x) {
            v.push(x);
            idx.push(i);
        }
    }
    let mut closed = false;
    let mut closing = 0;
    if v.len() >= 2 && v.first() == v.last() {
        let last = idx.pop().unwrap_or(0);
        v.pop();
        if v.len() < 3 {
            // A closed chain of two distinct vertices runs back over its edge.
            return Err(SeparationError::NotSimple {
                chain: which,
                index: last,
            });
        }
        closed = true;
        closing = last.saturating_sub(1);
    }
    let m = v.len();
    let mut edges: Vec<(usize, usize, usize)> = (1..m).map(|k| (k - 1, k, idx[k] - 1)).collect();
    if closed {
        edges.push((m - 1, 0, closing));
    }
    Ok(Clean { v, idx, edges })
}

/// The envelope of a cleaned chain, as visible vertices and one edge between each two.
fn to_prepared<K: Kernel>(
    c: &Ctx<'_>,
    cl: &Clean,
    env: Env<'_>,
    which: Chain,
) -> Result<Prepared, SeparationError> {
    let bps = env.bps;
    let mut out = Prepared {
        pts: Vec::with_capacity(bps.len()),
        idx: Vec::with_capacity(bps.len()),
        edges: Vec::with_capacity(bps.len().saturating_sub(1)),
    };
    for bp in bps {
        match bp.at {
            At::Vertex(w) => {
                out.pts.push(c.v[w]);
                out.idx.push(c.idx[w]);
            }
            // Only with a non-simple chain or inconsistent decisions.
            At::Edge(_) => return Err(c.bad(bp.y, which)),
        }
    }
    // The last breakpoint's gap (`None`) is not an interval.
    for pair in bps.windows(2) {
        let Some(e) = pair[0].gap else {
            return Err(c.bad(pair[0].y, which));
        };
        let (a, b) = c.ends(e);
        let (vk, vk1) = (pair[0].y, pair[1].y);
        let lo = if a == vk || c.frame.cmp_height::<K>(c.v[a], c.v[vk]) == Ordering::Equal {
            Param::Start
        } else {
            Param::Root(c.frame.height_minus(c.v[vk]))
        };
        let hi = if b == vk1 || c.frame.cmp_height::<K>(c.v[b], c.v[vk1]) == Ordering::Equal {
            Param::End
        } else {
            Param::Root(c.frame.height_minus(c.v[vk1]))
        };
        out.edges.push(EnvEdge {
            a: c.v[a],
            b: c.v[b],
            ia: c.idx[a],
            ib: c.idx[b],
            caller: cl.edges[e].2,
            lo,
            hi,
        });
    }
    Ok(out)
}

fn orient_edges<K: Kernel>(frame: Frame, cl: &Clean) -> Vec<Option<(usize, usize)>> {
    cl.edges
        .iter()
        .map(|&(u, w, _)| match frame.cmp_height::<K>(cl.v[u], cl.v[w]) {
            Ordering::Less => Some((u, w)),
            Ordering::Greater => Some((w, u)),
            Ordering::Equal => None,
        })
        .collect()
}

/// Lemma 2: the perpendicular-visibility envelope of a simple chain (open, or closed by repeating
/// its first vertex at the end) lying on its side of the line: the visible vertices bottom to top
/// and the edge carrying the envelope between each two, with symbolic shadow points.
///
/// Divide and conquer over the chain (bottom-up, adjacent sub-chains merged pairwise): `O(n log n)`
/// degree-2 tests in the worst case, `O(n)` when the sub-chains' height ranges meet only at their
/// ends (monotone stretches).
///
/// # Errors
/// [`SeparationError::NotSimple`] when the chain is seen not to be simple (a vertex on another
/// edge, overlapping edges, two vertices at one point, a closed chain of two vertices); under the
/// Fast kernel also for inconsistent decisions. Not every non-simple chain is detected.
pub(crate) fn prepare<K: Kernel>(
    chain: &[DVec2],
    frame: Frame,
    which: Chain,
) -> Result<Prepared, SeparationError> {
    let cl = clean(chain, which)?;
    let lohi = orient_edges::<K>(frame, &cl);
    let c = Ctx {
        frame,
        v: &cl.v,
        idx: &cl.idx,
        lohi: &lohi,
    };
    let mut level = Level::with_capacity(2 * cl.edges.len().max(1));
    if cl.edges.is_empty() {
        level.push(0, At::Vertex(0), None);
        level.close(0);
    } else {
        for (e, &(u, w, _)) in cl.edges.iter().enumerate() {
            leaf::<K>(&c, e, (u, w), &mut level);
        }
    }
    // log2(n) rounds, each halving the number of envelopes.
    let mut next = Level::with_capacity(level.bps.len());
    while level.segs.len() > 1 {
        next.clear();
        let m = level.segs.len();
        for s in (0..m).step_by(2) {
            if s + 1 < m {
                merge::<K>(&c, level.env(s), level.env(s + 1), &mut next)
                    .map_err(|w| c.bad(w, which))?;
            } else {
                let start = next.bps.len();
                next.bps.extend_from_slice(level.env(s).bps);
                next.close(start);
            }
        }
        core::mem::swap(&mut level, &mut next);
    }
    let env = if level.segs.is_empty() {
        Env { bps: &[] }
    } else {
        level.env(0)
    };
    to_prepared::<K>(&c, &cl, env, which)
}

/// The `O(n²)` twin of [`prepare`]: for every distinct vertex height, the nearest point of the
/// chain at that height by comparing all vertices and all edges crossing it; for every elementary
/// slab between consecutive heights, the nearest edge by comparing all edges spanning it.
pub(crate) fn prepare_brute<K: Kernel>(
    chain: &[DVec2],
    frame: Frame,
    which: Chain,
) -> Result<Prepared, SeparationError> {
    let cl = clean(chain, which)?;
    let lohi = orient_edges::<K>(frame, &cl);
    let c = Ctx {
        frame,
        v: &cl.v,
        idx: &cl.idx,
        lohi: &lohi,
    };
    let m = cl.v.len();
    // Distinct heights, each given by its first vertex, in increasing order (insertion sort by
    // exact comparisons: O(n²)).
    let mut hs: Vec<usize> = Vec::new();
    for w in 0..m {
        let pos = hs
            .iter()
            .position(|&h| frame.cmp_height::<K>(cl.v[w], cl.v[h]) != Ordering::Greater);
        match pos {
            Some(p) if frame.cmp_height::<K>(cl.v[w], cl.v[hs[p]]) == Ordering::Equal => {}
            Some(p) => hs.insert(p, w),
            None => hs.push(w),
        }
    }
    let spans = |e: usize, y: usize, strict_top: bool| {
        lohi[e].is_some_and(|(a, b)| {
            frame.cmp_height::<K>(cl.v[a], cl.v[y]) == Ordering::Less
                && if strict_top {
                    frame.cmp_height::<K>(cl.v[b], cl.v[y]) == Ordering::Greater
                } else {
                    frame.cmp_height::<K>(cl.v[b], cl.v[y]) != Ordering::Less
                }
        })
    };
    let bad = |w: Bad| c.bad(w, which);
    let mut env = Level::with_capacity(hs.len());
    for (k, &h) in hs.iter().enumerate() {
        let mut best: Option<At> = None;
        for w in 0..m {
            if frame.cmp_height::<K>(cl.v[w], cl.v[h]) == Ordering::Equal {
                best = Some(match best {
                    None => At::Vertex(w),
                    Some(x) => nearer::<K>(&c, x, At::Vertex(w)).map_err(bad)?,
                });
            }
        }
        for e in 0..cl.edges.len() {
            if spans(e, h, true) {
                best = Some(match best {
                    None => At::Edge(e),
                    Some(x) => nearer::<K>(&c, x, At::Edge(e)).map_err(bad)?,
                });
            }
        }
        let at = best.unwrap_or(At::Vertex(h));
        let gap = if k + 1 < hs.len() {
            // Edges spanning the slab above h: bottom at or below h, top above h.
            let mut g: Option<usize> = None;
            for (e, ends) in lohi.iter().enumerate() {
                let Some((a, b)) = *ends else { continue };
                if frame.cmp_height::<K>(cl.v[a], cl.v[h]) != Ordering::Greater
                    && frame.cmp_height::<K>(cl.v[b], cl.v[h]) == Ordering::Greater
                {
                    g = Some(match g {
                        None => e,
                        Some(f) => {
                            if edge_vs_edge::<K>(&c, e, f).map_err(bad)? == Ordering::Less {
                                e
                            } else {
                                f
                            }
                        }
                    });
                }
            }
            g
        } else {
            None
        };
        env.push(h, at, gap);
    }
    coalesce(&mut env, 0);
    env.close(0);
    to_prepared::<K>(&c, &cl, env.env(0), which)
}

/// The perpendicular-visibility envelope of one chain (Lemma 2), in the caller's indices: what
/// [`perpendicular_envelope`] returns.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Envelope {
    /// The caller's indices of the perpendicularly visible vertices, strictly increasing in height
    /// along the line (the oriented line: see [`perpendicular_envelope`]). For a closed chain the
    /// repeated last vertex is reported as vertex 0.
    pub vertices: Vec<usize>,
    /// `edges[k]`: the caller's index of the edge (from vertex `i` to `i + 1`; for a closed chain the
    /// closing edge is the index of the segment into the repeated last vertex) whose part between the
    /// heights of `vertices[k]` and `vertices[k + 1]` is the envelope there.
    pub edges: Vec<usize>,
    /// `shadows[k] = (below, above)`: the edge `edges[k]` passes behind `vertices[k]` (below) or
    /// `vertices[k + 1]` (above), so its part on the envelope ends at a shadow point, not at one of
    /// its own vertices. (An edge ending at a vertex hidden behind the visible one at the same
    /// height, an edge perpendicular to the line, is not a shadow.)
    pub shadows: Vec<(bool, bool)>,
}

fn public<K: Kernel>(
    chain: &[DVec2],
    a: DVec2,
    b: DVec2,
    brute: bool,
) -> Result<Envelope, SeparationError> {
    let valid = |v: DVec2| is_valid_coordinate(v.x) && is_valid_coordinate(v.y);
    if chain.is_empty() {
        return Err(SeparationError::EmptyChain { chain: Chain::P });
    }
    if let Some(index) = chain.iter().position(|&v| !valid(v)) {
        return Err(SeparationError::InvalidCoordinate {
            chain: Chain::P,
            index,
        });
    }
    if !valid(a) || !valid(b) {
        return Err(SeparationError::InvalidLine);
    }
    if a == b {
        return Err(SeparationError::DegenerateLine);
    }
    // The chain's side: from its first vertex strictly off the line (right of a → b: P's frame).
    let left = chain
        .iter()
        .map(|&v| K::orient(a, b, v).sign())
        .find(|s| !s.is_zero())
        == Some(Sign::Positive);
    let frame = Frame {
        l0: a,
        l1: b,
        mirror: left,
    };
    if let Some(index) = chain
        .iter()
        .position(|&v| frame.depth_sign::<K>(v) == Sign::Negative)
    {
        return Err(SeparationError::NotSeparated {
            chain: Chain::P,
            index,
        });
    }
    let prep = if brute {
        prepare_brute::<K>(chain, frame, Chain::P)?
    } else {
        prepare::<K>(chain, frame, Chain::P)?
    };
    Ok(Envelope {
        vertices: prep.idx.clone(),
        edges: prep.edges.iter().map(|e| e.caller).collect(),
        shadows: prep
            .edges
            .iter()
            .map(|e| {
                (
                    matches!(e.lo, Param::Root(_)),
                    matches!(e.hi, Param::Root(_)),
                )
            })
            .collect(),
    })
}

/// The perpendicular-visibility envelope `P°` of a simple chain lying in one closed half-plane of
/// the line through `a` and `b` (Amato 1992, section 3, Lemma 2): the points of the chain that no
/// other point of it hides from the line along the perpendicular, as visible vertices and the edge
/// carrying the envelope between each two. Heights are measured along `b − a`.
///
/// The chain is open (edge `i` joins vertices `i` and `i + 1`), or closed when its last vertex equals
/// its first (at least three distinct vertices): then the closing edge joins the last distinct
/// vertex to vertex 0. Repeated consecutive vertices are dropped (reported indices are the first of
/// a repeat). The chain must be simple (no two non-adjacent edges meet); violations met on the way
/// are reported, others give an envelope of the non-simple chain's own definition or an error.
///
/// This is the step [`separation_of_chains`](crate::separation_of_chains) runs on each chain; it is
/// public for verification against [`perpendicular_envelope_brute`].
///
/// # Complexity
/// `O(n log n)` degree-2 predicates in the worst case (divide and conquer over the chain), `O(n)`
/// for chains monotone along the line.
///
/// # Errors
/// [`SeparationError::EmptyChain`], [`SeparationError::InvalidCoordinate`],
/// [`SeparationError::InvalidLine`], [`SeparationError::DegenerateLine`],
/// [`SeparationError::NotSeparated`] (vertices on both sides of the line), and
/// [`SeparationError::NotSimple`]; errors name the chain `P`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_predicates::Robust;
/// use polydist_separation::perpendicular_envelope;
///
/// // A hook right of the y-axis: the vertex (3, 1) is hidden behind the edge from (1, 0) to (1, 2).
/// let chain = [DVec2::new(3.0, 1.0), DVec2::new(4.0, -1.0), DVec2::new(1.0, 0.0), DVec2::new(1.0, 2.0)];
/// let env = perpendicular_envelope::<Robust>(&chain, DVec2::ZERO, DVec2::Y)?;
/// assert_eq!(env.vertices, [1, 2, 3]);
/// assert_eq!(env.edges, [1, 2]);
/// # Ok::<(), polydist_separation::SeparationError>(())
/// ```
pub fn perpendicular_envelope<K: Kernel>(
    chain: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Envelope, SeparationError> {
    public::<K>(chain, a, b, false)
}

/// The brute-force twin of [`perpendicular_envelope`], for testing: for each distinct vertex height
/// the nearest point by comparing every vertex and edge there, for each slab between consecutive
/// heights the nearest edge by comparing every edge spanning it.
///
/// # Complexity
/// `O(n²)` degree-2 predicates.
///
/// # Errors
/// As [`perpendicular_envelope`].
pub fn perpendicular_envelope_brute<K: Kernel>(
    chain: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Envelope, SeparationError> {
    public::<K>(chain, a, b, true)
}
