//! Lemma 2 for general simple chains: the perpendicular-visibility envelope `P°` (Amato 1992,
//! section 3), by one walk along the chain in `O(n)`, and its `O(n²)` brute-force twin.
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
//! # The scan
//! Heights are compared lexicographically with depths (a symbolic shear `H' = H + εX`: orientation
//! is unchanged, distinct points get distinct heights, no edge is perpendicular to the line). The
//! walk keeps the envelope of the part walked so far as a linked list of its visible vertices, and
//! either stands on it (its current vertex is a node) or is hidden behind it. A hidden walk can only
//! come back into view where it went out of view:
//!
//! * it went behind a visible vertex `w` whose envelope edge `f` on one side passes behind `w`: the
//!   *gap* `g`, the open segment from `w` to `f`'s point at `w`'s height, is crossed from its
//!   visible side. The chain walked so far holds a path from `f`'s point to `w`; with `g` it bounds a
//!   Jordan curve `Γ`. The visible side of `g` is outside `Γ` (a point there sees the line down a
//!   ray that meets neither the chain nor `g`), so the walk, having crossed `g`, is inside `Γ`; it
//!   cannot cross the chain, so it leaves `Γ` only back across `g`. Every other gap has its visible
//!   side, hence itself, outside `Γ`. So the walk is hidden until an edge crosses `g` itself, one
//!   test per edge;
//! * or it went behind the top or bottom vertex from beyond the range (or turned back behind the
//!   walk's previous edge at an end): then it comes back past one of the two ends of the range.
//!
//! While the walk is in view, its edge replaces the envelope node by node until it ends in front
//! of it or goes behind a visible vertex (a new gap). Each edge costs `O(1)` tests plus one per node
//! it removes for good, so the walk is `O(n)`. Nodes at one true height are then collapsed to the
//! nearest (the first), and a closed chain's closing edge is merged in by a merge of two
//! height-sorted envelopes over the closing edge's height range only (the chain is first rotated so
//! that its closing edge is one of least height extent). `docs/algorithms/separation.md` ("The
//! linear scan") has the cases and the proofs.

use core::cmp::Ordering;
use std::borrow::Cow;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign, is_valid_coordinate};

use crate::chain::{Carry, Prepared};
use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::site::Vertex;

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

/// Envelopes stored back to back in one flat array: envelope `s` is the range `segs[s]` of
/// breakpoints (the scan's collapsed envelope and a closing edge's, merged into another).
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

/// How edge `e` of a chain, from position `e` to the next (`(e + 1) mod m` for a closed chain of
/// `m`), runs along the line: one byte an edge where the ends themselves took 24.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Dir {
    /// From lower to higher.
    Up,
    /// From higher to lower.
    Down,
    /// Perpendicular to the line (never under the scan's shear).
    Flat,
}

/// The positions edge `e` of a chain of `m` vertices joins: `e` and the next, `e + 1` or, for the
/// closing edge of a closed chain, 0 ([`Clean`]).
#[inline]
fn edge_ends(e: usize, m: usize) -> (usize, usize) {
    (e, if e + 1 == m { 0 } else { e + 1 })
}

/// A chain without repeated consecutive vertices, with its edges oriented upward.
struct Ctx<'a, V> {
    frame: Frame,
    v: &'a [V],
    /// Caller index of each vertex.
    idx: Ix<'a>,
    /// Each edge's direction along the line ([`Ctx::ends`] orients it upward).
    dirs: &'a [Dir],
    /// Heights compared lexicographically, (height, depth): the scan's symbolic shear (see
    /// [`scan`]), under which no two distinct points are at one height and no edge is
    /// perpendicular to the line.
    lex: bool,
}

/// Where the envelope computation found the chain not simple (or the kernel inconsistent): the
/// vertex involved.
type Bad = usize;

impl<'a, V: Vertex> Ctx<'a, V> {
    fn new(frame: Frame, cl: &'a Clean<'_, V>, dirs: &'a [Dir], lex: bool) -> Self {
        Ctx {
            frame,
            v: &cl.v,
            idx: cl.idx.as_ix(),
            dirs,
            lex,
        }
    }

    fn bad(&self, k: usize, which: Chain) -> SeparationError {
        SeparationError::NotSimple {
            chain: which,
            index: self.idx.at(k),
        }
    }

    /// Edge `e`'s lower and upper vertex; `None` for an edge perpendicular to the line.
    #[inline]
    fn lohi(&self, e: usize) -> Option<(usize, usize)> {
        let (u, w) = edge_ends(e, self.v.len());
        match self.dirs[e] {
            Dir::Up => Some((u, w)),
            Dir::Down => Some((w, u)),
            Dir::Flat => None,
        }
    }

    #[inline]
    fn ends(&self, e: usize) -> (usize, usize) {
        // Only non-perpendicular edges enter envelopes.
        self.lohi(e).unwrap_or((0, 0))
    }

    /// Compares the heights of vertices `p` and `q` (lexicographically with their depths under
    /// the shear). Degree 2.
    #[inline]
    fn cmp_h<K: Kernel>(&self, p: usize, q: usize) -> Ordering {
        cmp_heights::<K, V>(self.frame, self.v[p], self.v[q], self.lex)
    }
}

/// Compares the heights of two points, ties broken by depth (nearer first) when `lex`.
#[inline]
fn cmp_heights<K: Kernel, V: Vertex>(frame: Frame, p: V, q: V, lex: bool) -> Ordering {
    match frame.cmp_height::<K, _>(p, q) {
        Ordering::Equal if lex => frame.cmp_depth::<K, _>(p, q),
        o => o,
    }
}

/// Is vertex `w` nearer to the line than edge `e` at `w`'s height (strictly inside `e`'s range)?
fn vertex_vs_edge<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    w: usize,
    e: usize,
) -> Result<Ordering, Bad> {
    let (a, b) = c.ends(e);
    // With `e` pointing up, points nearer to the line are on its left in the frame.
    match c.frame.orient::<K, _>(c.v[a], c.v[b], c.v[w]) {
        Sign::Positive => Ok(Ordering::Less),
        Sign::Negative => Ok(Ordering::Greater),
        Sign::Zero => Err(w), // the vertex lies inside the edge: not simple
    }
}

/// Orders two edges over an open height interval both span (`Less`: `e1` nearer to the line).
/// Disjoint over that interval (simple chain), so one test at the higher of the two bottoms decides;
/// when that bottom lies on the other edge, they share it and the lower of the two tops decides.
/// At most four degree-2 tests.
fn edge_vs_edge<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    e1: usize,
    e2: usize,
) -> Result<Ordering, Bad> {
    if e1 == e2 {
        return Ok(Ordering::Equal);
    }
    let ((a1, b1), (a2, b2)) = (c.ends(e1), c.ends(e2));
    if c.cmp_h::<K>(a1, a2) == Ordering::Less {
        return edge_vs_edge::<K, V>(c, e2, e1).map(Ordering::reverse);
    }
    // a1 is at least as high as a2 and below the top of e2: it is within e2's height range.
    match c.frame.orient::<K, _>(c.v[a2], c.v[b2], c.v[a1]) {
        Sign::Positive => return Ok(Ordering::Less),
        Sign::Negative => return Ok(Ordering::Greater),
        Sign::Zero => {}
    }
    if a1 != a2 {
        return Err(a1); // a1 lies on e2 without being its end: not simple
    }
    // A common bottom vertex: the lower top lies within the other edge's range.
    if c.cmp_h::<K>(b1, b2) != Ordering::Greater {
        match c.frame.orient::<K, _>(c.v[a2], c.v[b2], c.v[b1]) {
            Sign::Positive => Ok(Ordering::Less),
            Sign::Negative => Ok(Ordering::Greater),
            Sign::Zero => Err(b1), // the edges overlap
        }
    } else {
        match c.frame.orient::<K, _>(c.v[a1], c.v[b1], c.v[b2]) {
            Sign::Positive => Ok(Ordering::Greater),
            Sign::Negative => Ok(Ordering::Less),
            Sign::Zero => Err(b2),
        }
    }
}

/// [`edge_vs_edge`]`(e, e − 1)` for the walk's edge `e` and the previous one, when both leave their
/// common vertex `a` (position `e`) upward (`up`) or both downward: near `a` the nearer edge is the
/// one on the left of the other, taken upward, so one orientation test decides (the general test
/// spends two height comparisons first). With `e` from `a` to `b` and `e − 1` from `p` to `a`:
/// upward, `e` is nearer when `b` is left of `a → p`; downward, when `b` is left of `p → a`.
/// Collinear edges overlap (the chain is not simple): the general test then names the vertex.
fn after_previous<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    e: usize,
    up: bool,
) -> Result<Ordering, Bad> {
    let (p, a, b) = (c.v[e - 1], c.v[e], c.v[e + 1]);
    let s = if up {
        c.frame.orient::<K, _>(a, p, b)
    } else {
        c.frame.orient::<K, _>(p, a, b)
    };
    match s {
        Sign::Positive => Ok(Ordering::Less),
        Sign::Negative => Ok(Ordering::Greater),
        Sign::Zero => edge_vs_edge::<K, V>(c, e, e - 1),
    }
}

/// The nearer of two points of the chain at the same height.
fn nearer<K: Kernel, V: Vertex>(c: &Ctx<'_, V>, x: At, y: At) -> Result<At, Bad> {
    let o = match (x, y) {
        (At::Vertex(u), At::Vertex(w)) => {
            if u == w {
                return Ok(x);
            }
            match c.frame.cmp_depth::<K, _>(c.v[u], c.v[w]) {
                Ordering::Equal => return Err(w), // two vertices at one point: not simple
                o => o,
            }
        }
        (At::Vertex(u), At::Edge(e)) => vertex_vs_edge::<K, V>(c, u, e)?,
        (At::Edge(e), At::Vertex(u)) => vertex_vs_edge::<K, V>(c, u, e)?.reverse(),
        (At::Edge(e), At::Edge(f)) => edge_vs_edge::<K, V>(c, e, f)?,
    };
    Ok(if o == Ordering::Greater { y } else { x })
}

/// Appends the envelope of a single edge.
fn leaf<K: Kernel, V: Vertex>(c: &Ctx<'_, V>, e: usize, ends: (usize, usize), out: &mut Level) {
    let start = out.bps.len();
    match c.lohi(e) {
        Some((a, b)) => {
            out.push(a, At::Vertex(a), Some(e));
            out.push(b, At::Vertex(b), None);
        }
        None => {
            // Perpendicular to the line: only the nearer end is visible.
            let (u, w) = ends;
            let k = if c.frame.cmp_depth::<K, _>(c.v[w], c.v[u]) == Ordering::Less {
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
fn concat<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    lo: Env<'_>,
    hi: Env<'_>,
    out: &mut Level,
) -> Result<(), Bad> {
    out.bps.extend_from_slice(lo.bps);
    let (Some(top), Some(bot)) = (lo.bps.last(), hi.bps.first()) else {
        out.bps.extend_from_slice(hi.bps);
        return Ok(());
    };
    if c.frame.cmp_height::<K, _>(c.v[top.y], c.v[bot.y]) == Ordering::Equal {
        // One breakpoint at the common height, with `hi`'s gap above (`lo`'s last is `None`).
        let at = nearer::<K, V>(c, top.at, bot.at)?;
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
fn merge<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    a: Env<'_>,
    b: Env<'_>,
    out: &mut Level,
) -> Result<(), Bad> {
    let start = out.bps.len();
    let (Some(a_top), Some(b_top)) = (a.bps.last(), b.bps.last()) else {
        out.bps
            .extend_from_slice(if a.bps.is_empty() { b.bps } else { a.bps });
        out.close(start);
        return Ok(());
    };
    let (a_top, b_top, a_bot, b_bot) = (a_top.y, b_top.y, a.bps[0].y, b.bps[0].y);
    if c.frame.cmp_height::<K, _>(c.v[a_top], c.v[b_bot]) != Ordering::Greater {
        concat::<K, V>(c, a, b, out)?;
        out.close(start);
        return Ok(());
    }
    if c.frame.cmp_height::<K, _>(c.v[b_top], c.v[a_bot]) != Ordering::Greater {
        concat::<K, V>(c, b, a, out)?;
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
            c.frame.cmp_height::<K, _>(c.v[a.bps[i].y], c.v[b.bps[j].y])
        };
        let (y, pt) = match o {
            Ordering::Less => {
                let (y, p) = (a.bps[i].y, a.bps[i].at);
                i += 1;
                match b.open(j) {
                    Some(e) => (y, nearer::<K, V>(c, p, At::Edge(e))?),
                    None => (y, p),
                }
            }
            Ordering::Greater => {
                let (y, p) = (b.bps[j].y, b.bps[j].at);
                j += 1;
                match a.open(i) {
                    Some(e) => (y, nearer::<K, V>(c, At::Edge(e), p)?),
                    None => (y, p),
                }
            }
            Ordering::Equal => {
                let y = a.bps[i].y;
                let p = nearer::<K, V>(c, a.bps[i].at, b.bps[j].at)?;
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
                            let o = edge_vs_edge::<K, V>(c, e, f)?;
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

/// A chain with repeated consecutive vertices dropped and a closing repeat removed. Edge `e` joins
/// positions `e` and `e + 1`, and for a closed chain the last one, `m − 1`, joins `m − 1` and 0.
struct Clean<'a, V: Clone> {
    /// The points, borrowed from the caller's chain when they are its own (no repeated vertex,
    /// no rotation yet).
    v: Cow<'a, [V]>,
    /// The caller's index of each position.
    idx: Index,
    /// The caller's index of each edge.
    callers: Index,
    /// As many edges as vertices for a closed chain, one fewer for an open one.
    edges: usize,
}

/// Caller indices of a cleaned chain's positions (or edges).
enum Index {
    /// Position `k` is the caller's `(k + shift) mod m`: a chain without repeated vertices, whose
    /// positions and edges are the caller's, rotated ([`Clean::close_at_shortest`]). No table is
    /// built or rotated for it (the common case: the boundary of a validated polygon).
    Rotated { shift: usize, m: usize },
    /// Position `k` is the caller's `table[k]`.
    Table(Vec<usize>),
}

impl Index {
    fn as_ix(&self) -> Ix<'_> {
        match *self {
            Index::Rotated { shift, m } => Ix::Rotated { shift, m },
            Index::Table(ref t) => Ix::Table(t),
        }
    }

    fn at(&self, k: usize) -> usize {
        self.as_ix().at(k)
    }

    /// Moves position `by` (`< m`) to position 0, as `rotate_left` on a table.
    fn rotate_left(&mut self, by: usize) {
        match self {
            Index::Rotated { shift, m } => {
                *shift += by;
                if *shift >= *m {
                    *shift -= *m;
                }
            }
            Index::Table(t) => t.rotate_left(by),
        }
    }
}

/// A borrowed [`Index`].
#[derive(Clone, Copy)]
enum Ix<'a> {
    Rotated { shift: usize, m: usize },
    Table(&'a [usize]),
}

impl Ix<'_> {
    #[inline]
    fn at(self, k: usize) -> usize {
        match self {
            Ix::Rotated { shift, m } => {
                let j = k + shift;
                if j >= m { j - m } else { j }
            }
            Ix::Table(t) => t[k],
        }
    }
}

/// Drops repeated consecutive vertices; a chain whose last vertex equals its first (with at least
/// three distinct vertices) is closed: the repeat is removed and the closing edge joins the last
/// vertex to vertex 0. The caller's edge index of the edge into vertex `k` is the caller index of
/// `k`'s first occurrence minus one.
fn clean<V: Vertex>(chain: &[V], which: Chain) -> Result<Clean<'_, V>, SeparationError> {
    // Without repeated consecutive vertices (a validated polygon's boundary), positions and edges
    // are the caller's: the points borrowed, no tables.
    if chain.windows(2).all(|w| w[0] != w[1]) {
        let n = chain.len();
        let closed = n >= 2 && chain[0] == chain[n - 1];
        if !closed || n >= 4 {
            let m = if closed { n - 1 } else { n };
            return Ok(Clean {
                v: Cow::Borrowed(&chain[..m]),
                idx: Index::Rotated { shift: 0, m },
                callers: Index::Rotated { shift: 0, m },
                edges: if closed { m } else { m.saturating_sub(1) },
            });
        }
    }
    let mut v: Vec<V> = Vec::with_capacity(chain.len());
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
    // Room for the closing edge too (a push past an exact-fit collect copies the whole vector).
    let mut callers: Vec<usize> = Vec::with_capacity(m);
    callers.extend((1..m).map(|k| idx[k] - 1));
    if closed {
        callers.push(closing);
    }
    Ok(Clean {
        v: Cow::Owned(v),
        idx: Index::Table(idx),
        edges: callers.len(),
        callers: Index::Table(callers),
    })
}

impl<V: Vertex> Clean<'_, V> {
    /// Rotates a closed chain so that its closing edge (merged in after the walk, [`prepare`]) is
    /// the edge of least height extent along the frame's line, as `f64` approximations estimate
    /// it: the merge then meets few breakpoints. Only the work depends on the choice (the
    /// envelope of a closed chain does not depend on where its walk starts); positions, caller
    /// indices and edges move together. `O(n)`, no predicate.
    fn close_at_shortest(&mut self, frame: Frame) {
        let m = self.v.len();
        let Some(z) = least_extent_edge(&self.v, frame.l1 - frame.l0) else {
            return;
        };
        if z + 1 == m {
            return;
        }
        // New position `k` is old position `z + 1 + k`: old edge `z` becomes the closing edge.
        let shift = z + 1;
        // One copy, rotated as it is made (a borrowed chain is copied here for the first time).
        self.v = Cow::Owned([&self.v[shift..], &self.v[..shift]].concat());
        self.idx.rotate_left(shift);
        // Edge `k` keeps joining positions `k` and `k + 1` (mod `m`): only its caller moves.
        self.callers.rotate_left(shift);
    }
}

/// The edge of least height extent along `d` of the closed chain `v` (edge `k` joins positions `k`
/// and `k + 1`, the last one `m − 1` and 0), as `f64` approximations estimate it: the closing edge
/// when it is among the least, otherwise the first of them. `None` for an empty chain. `O(m)`, no
/// predicate; each key computed once. [`Clean::close_at_shortest`] rotates a chain so that this edge
/// closes it, and a caller that hands over a chain rotated so already saves that copy.
pub(crate) fn least_extent_edge<V: Vertex>(v: &[V], d: DVec2) -> Option<usize> {
    let t = |x: V| x.approx().dot(d);
    let (&first, &last) = (v.first()?, v.last()?);
    let m = v.len();
    let (mut z, mut least) = (m - 1, (t(first) - t(last)).abs());
    let mut prev = t(first);
    for k in 0..m - 1 {
        let next = t(v[k + 1]);
        let extent = (next - prev).abs();
        // Strictly less than the least so far: the closing edge (`z = m − 1`) keeps its place
        // among equals, and so does the first of the others.
        if extent.total_cmp(&least).is_lt() {
            (z, least) = (k, extent);
        }
        prev = next;
    }
    Some(z)
}

/// The envelope of a cleaned chain, as visible vertices and one edge between each two.
fn to_prepared<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    cl: &Clean<'_, V>,
    env: Env<'_>,
    which: Chain,
    gapped: bool,
) -> Result<Prepared<V>, SeparationError> {
    let bps = env.bps;
    let mut out = Prepared::with_capacity(c.frame, bps.len());
    for bp in bps {
        match bp.at {
            At::Vertex(w) => {
                out.pts.push(c.v[w]);
                out.idx.push(c.idx.at(w));
            }
            // Only with a non-simple chain or inconsistent decisions.
            At::Edge(_) => return Err(c.bad(bp.y, which)),
        }
    }
    // The last breakpoint's gap (`None`) is not an interval.
    for (k, pair) in bps.windows(2).enumerate() {
        let Some(e) = pair[0].gap else {
            if gapped {
                // No point of the runs between the two heights.
                out.segs.push((out.pts[k], out.pts[k + 1]));
                out.carry.push(None);
                continue;
            }
            return Err(c.bad(pair[0].y, which));
        };
        let (a, b) = c.ends(e);
        // A shadow end is the edge's point at the visible vertex's height (`pts[k]`, whose height
        // is exactly that of the breakpoint's vertex): `Prepared::env_edge` keeps it symbolic.
        let (vk, vk1) = (pair[0].y, pair[1].y);
        let lo_root = a != vk && c.frame.cmp_height::<K, _>(c.v[a], c.v[vk]) != Ordering::Equal;
        let hi_root = b != vk1 && c.frame.cmp_height::<K, _>(c.v[b], c.v[vk1]) != Ordering::Equal;
        out.segs.push((c.v[a], c.v[b]));
        out.carry.push(Some(Carry {
            ia: c.idx.at(a),
            ib: c.idx.at(b),
            caller: cl.callers.at(e),
            lo_root,
            hi_root,
        }));
    }
    Ok(out)
}

/// Each edge's direction: by true height (`Flat` for an edge perpendicular to the line), and under
/// the scan's shear (a perpendicular edge then points away from the line). One height test per
/// edge, a depth test only on the perpendicular ones.
fn orient_edges<K: Kernel, V: Vertex>(frame: Frame, cl: &Clean<'_, V>) -> (Vec<Dir>, Vec<Dir>) {
    let m = cl.v.len();
    (0..cl.edges)
        .map(|e| {
            let (u, w) = edge_ends(e, m);
            let (u, w) = (cl.v[u], cl.v[w]);
            let dir = |o: Ordering| match o {
                Ordering::Less => Dir::Up,
                Ordering::Greater => Dir::Down,
                Ordering::Equal => Dir::Flat,
            };
            match frame.cmp_height::<K, _>(u, w) {
                Ordering::Equal => (Dir::Flat, dir(frame.cmp_depth::<K, _>(u, w))),
                o => (dir(o), dir(o)),
            }
        })
        .unzip()
}

/// No node: the end of the scan's list.
const NIL: usize = usize::MAX;

/// The envelope of the part of the chain walked so far, as a doubly linked list of its visible
/// vertices in increasing (sheared) height, `up[u]` the edge between `u` and `next[u]`.
struct List {
    next: Vec<usize>,
    prev: Vec<usize>,
    up: Vec<usize>,
    head: usize,
    tail: usize,
}

impl List {
    /// Makes `lo` and `hi` neighbours (either [`NIL`]: `hi` becomes the head, `lo` the tail).
    fn join(&mut self, lo: usize, hi: usize) {
        if lo == NIL {
            self.head = hi;
        } else {
            self.next[lo] = hi;
        }
        if hi == NIL {
            self.tail = lo;
        } else {
            self.prev[hi] = lo;
        }
    }

    /// Links `b` (not in the list) between the neighbours `lo` and `hi`.
    fn link(&mut self, lo: usize, b: usize, hi: usize) {
        self.join(lo, b);
        self.join(b, hi);
    }

    /// Unlinks `u`, keeping the edges of the others.
    fn unlink(&mut self, u: usize) {
        self.join(self.prev[u], self.next[u]);
    }

    /// Links the walk's vertex `b` next to node `cur`, above it when `up`, with the walk's edge
    /// `e` between them; the edge that was there (or none, at an end) now runs between `b` and
    /// the old neighbour.
    fn attach(&mut self, cur: usize, b: usize, e: usize, up: bool) {
        if up {
            let hi = self.next[cur];
            self.up[b] = self.up[cur];
            self.up[cur] = e;
            self.link(cur, b, hi);
        } else {
            let lo = self.prev[cur];
            self.up[b] = e;
            self.link(lo, b, cur);
        }
    }

    /// The edge just below node `u`, [`NIL`] at the bottom.
    fn down(&self, u: usize) -> usize {
        if self.prev[u] == NIL {
            NIL
        } else {
            self.up[self.prev[u]]
        }
    }
}

/// Where a hidden walk comes back into view.
#[derive(Clone, Copy, Debug)]
enum Exit {
    /// Through the open segment from the visible vertex `w` to the point of edge `f` at `w`'s
    /// height, `f` being the envelope's edge just above `w` (`up`) or just below it.
    Gap { w: usize, up: bool, f: usize },
    /// Past the top or the bottom of the envelope's height range.
    Ends,
}

/// The state of the walk at its current vertex.
#[derive(Clone, Copy, Debug)]
enum Walk {
    /// On the envelope, at this node.
    Visible(usize),
    /// Behind it.
    Hidden(Exit),
}

/// The walk's edge `e` from the visible node `cur` toward `b` (upward when `up`), known to be
/// nearer to the line than the envelope just beyond `cur` on that side: replaces the envelope
/// while it stays in front, stopping at `b` or behind the first visible vertex nearer than it.
/// Every step but the last removes a node for good.
fn sweep<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    list: &mut List,
    cur: usize,
    e: usize,
    b: usize,
    up: bool,
) -> Result<Walk, Bad> {
    loop {
        let nxt = if up { list.next[cur] } else { list.prev[cur] };
        if nxt == NIL {
            // Beyond the envelope's range: `e` alone there.
            list.attach(cur, b, e, up);
            return Ok(Walk::Visible(b));
        }
        let beyond = if up {
            Ordering::Greater
        } else {
            Ordering::Less
        };
        let o = c.cmp_h::<K>(b, nxt);
        if o != beyond {
            if o == Ordering::Equal {
                return Err(b); // two vertices at one point
            }
            // `e` ends before `nxt`, in front of the edge there, which passes behind `b`: one
            // test confirms it (a `b` on that edge is a chain that is not simple).
            let f = if up { list.up[cur] } else { list.up[nxt] };
            if vertex_vs_edge::<K, V>(c, b, f)? != Ordering::Less {
                return Err(b);
            }
            list.attach(cur, b, e, up);
            return Ok(Walk::Visible(b));
        }
        match vertex_vs_edge::<K, V>(c, nxt, e)? {
            Ordering::Less => {
                // `nxt` is nearer: `e` goes behind it, the gap at `nxt` faces `cur`.
                if up {
                    list.up[cur] = e;
                } else {
                    list.up[nxt] = e;
                }
                return Ok(Walk::Hidden(Exit::Gap {
                    w: nxt,
                    up: !up,
                    f: e,
                }));
            }
            _ => {
                // `nxt` is hidden, and `e` (nearer than `nxt` at its height) is nearer than the
                // edge beyond it too.
                if up {
                    list.up[cur] = list.up[nxt];
                }
                list.unlink(nxt);
                // Tentatively `cur` keeps the edge beyond the removed node (below it, that edge
                // is already `up` of `cur`'s new neighbour); `e` is written when the sweep stops.
            }
        }
    }
}

/// The walk's edge `e` toward `b`, behind the envelope and inside its height range at its start:
/// in view again beyond `b` if `b` is past the end of the range it moves toward.
fn past_the_ends<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    list: &mut List,
    e: usize,
    b: usize,
    up: bool,
) -> Walk {
    let (end, beyond) = if up {
        (list.tail, Ordering::Greater)
    } else {
        (list.head, Ordering::Less)
    };
    if c.cmp_h::<K>(b, end) == beyond {
        list.attach(end, b, e, up);
        Walk::Visible(b)
    } else {
        Walk::Hidden(Exit::Ends)
    }
}

/// Lemma 2 for an open chain, by one walk along it (the scan of `docs/algorithms/separation.md`,
/// "The linear scan"): the envelope of the part walked so far is kept as a linked list, with the
/// walk's current vertex either on it (a node) or hidden behind it together with the one gap (or
/// the two ends of the range) through which the walk can come back into view. Heights are
/// compared lexicographically with depths (`c.lex`): a symbolic shear, so distinct vertices have
/// distinct heights. `c.dirs` must be the edges' directions under that shear ([`orient_edges`]'s
/// second). Returns the nodes bottom to top and the edge between each two.
///
/// # Complexity
/// `O(n)`: each edge costs `O(1)` degree-2 tests plus one per node it removes, and a node is
/// removed at most once.
fn scan<K: Kernel, V: Vertex>(c: &Ctx<'_, V>, m: usize) -> Result<(Vec<usize>, Vec<usize>), Bad> {
    if m <= 1 {
        return Ok(((0..m).collect(), Vec::new()));
    }
    let mut list = List {
        next: vec![NIL; m],
        prev: vec![NIL; m],
        up: vec![NIL; m],
        head: NIL,
        tail: NIL,
    };
    // The first edge alone: its two ends, the lower first. Each edge's direction under the
    // shear was decided once, by `orient_edges` (`c.dirs`; `Flat` there is two vertices at one
    // point, or an inconsistent Fast kernel).
    let (lo, hi) = match c.dirs[0] {
        Dir::Up => (0, 1),
        Dir::Down => (1, 0),
        Dir::Flat => return Err(1),
    };
    list.link(NIL, lo, NIL);
    list.attach(lo, hi, 0, true);
    let mut walk = Walk::Visible(1);
    // Edge `e` runs from vertex `e` to vertex `e + 1`.
    for e in 1..m - 1 {
        let (a, b) = (e, e + 1);
        let up = match c.dirs[e] {
            Dir::Up => true,
            Dir::Down => false,
            Dir::Flat => return Err(b),
        };
        walk = match walk {
            Walk::Visible(u) => {
                // The edge beside `a` on the walk's side; only the walk's previous edge `e − 1`
                // (the one other edge at `a`) can start at `a` there and hide `e`.
                let side = if up { list.up[u] } else { list.down(u) };
                let behind =
                    side == e - 1 && after_previous::<K, V>(c, e, up)? == Ordering::Greater;
                if behind {
                    // Between `e − 1` and the edge passing behind `a` on the other side (or
                    // the end of the range there).
                    let other = if up { list.down(u) } else { list.up[u] };
                    if other == NIL {
                        // `e` may still pass the far end of the range.
                        past_the_ends::<K, V>(c, &mut list, e, b, up)
                    } else {
                        Walk::Hidden(Exit::Gap {
                            w: u,
                            up: !up,
                            f: other,
                        })
                    }
                } else {
                    sweep::<K, V>(c, &mut list, u, e, b, up)?
                }
            }
            Walk::Hidden(Exit::Ends) => past_the_ends::<K, V>(c, &mut list, e, b, up),
            Walk::Hidden(Exit::Gap { w, up: side, f }) => {
                // Out through the gap: across `w`'s height from its hidden side to its visible
                // side, between `w` and `f`.
                let (before, after) = if side {
                    (Ordering::Less, Ordering::Greater)
                } else {
                    (Ordering::Greater, Ordering::Less)
                };
                let out = up == side
                    && c.cmp_h::<K>(a, w) == before
                    && c.cmp_h::<K>(b, w) == after
                    && vertex_vs_edge::<K, V>(c, w, e)? == Ordering::Less
                    && edge_vs_edge::<K, V>(c, e, f)? == Ordering::Less;
                if out {
                    sweep::<K, V>(c, &mut list, w, e, b, up)?
                } else {
                    walk
                }
            }
        };
    }
    // At most `m` nodes: reserved, so the vectors never grow by copying.
    let mut nodes = Vec::with_capacity(m);
    let mut edges = Vec::with_capacity(m);
    let mut u = list.head;
    // At most `m` nodes; the bound keeps the loop finite on any list.
    while u != NIL && nodes.len() < m {
        nodes.push(u);
        if list.next[u] != NIL {
            edges.push(list.up[u]);
        }
        u = list.next[u];
    }
    Ok((nodes, edges))
}

/// Lemma 2: the perpendicular-visibility envelope of a simple chain (open, or closed by repeating
/// its first vertex at the end) lying on its side of the line: the visible vertices bottom to top
/// and the edge carrying the envelope between each two, with symbolic shadow points.
///
/// One walk along the open chain ([`scan`]) under the symbolic shear, whose breakpoints at one
/// true height are then collapsed to the nearest; a closed chain, rotated so that its closing edge
/// is one of least height extent, has that edge merged in afterwards ([`merge_leaf`]: the
/// breakpoints within its height range only).
///
/// # Complexity
/// `O(n)` degree-2 tests.
///
/// # Errors
/// [`SeparationError::NotSimple`] when the chain is seen not to be simple (a vertex on another
/// edge, overlapping edges, two vertices at one point, a closed chain of two vertices); under the
/// Fast kernel also for inconsistent decisions. Not every non-simple chain is detected.
pub(crate) fn prepare<K: Kernel, V: Vertex>(
    chain: &[V],
    frame: Frame,
    which: Chain,
) -> Result<Prepared<V>, SeparationError> {
    prepare_closing::<K, V>(chain, frame, which, Closing::AtLeastExtent)
}

/// Where [`prepare_closing`] closes a closed chain's walk.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Closing {
    /// At its edge of least extent along the line ([`least_extent_edge`]), found and rotated to.
    AtLeastExtent,
    /// At its last edge as given: the caller rotated the chain so already (the disjoint-hull
    /// route), and the `O(n)` search is not done again. Only the work depends on the edge, never
    /// the envelope.
    AsGiven,
}

/// [`prepare`], with the caller's choice of the closing edge of a closed chain.
pub(crate) fn prepare_closing<K: Kernel, V: Vertex>(
    chain: &[V],
    frame: Frame,
    which: Chain,
    closing: Closing,
) -> Result<Prepared<V>, SeparationError> {
    let mut cl = clean(chain, which)?;
    let m = cl.v.len();
    // A closed chain has as many edges as vertices, its closing edge (`m − 1` → 0) last.
    let closed = m > 0 && cl.edges == m;
    if closed && closing == Closing::AtLeastExtent {
        cl.close_at_shortest(frame);
    }
    // Each temporary is dropped as soon as it is read for the last time, so that the envelope
    // built last can take its memory (docs/algorithms/separation.md, "Memory").
    let (dirs, sheared) = orient_edges::<K, V>(frame, &cl);
    let c = Ctx::new(frame, &cl, &dirs, false);
    let (nodes, edges) = {
        let s = Ctx::new(frame, &cl, &sheared, true);
        scan::<K, V>(&s, m).map_err(|w| c.bad(w, which))?
    };
    drop(sheared);
    let mut level = Level::with_capacity(nodes.len() + 2);
    collapse::<K, V>(&c, &nodes, &edges, 0, &mut level);
    drop((nodes, edges));
    if !closed {
        return to_prepared::<K, V>(&c, &cl, level.env(0), which, false);
    }
    let z = m - 1;
    leaf::<K, V>(&c, z, edge_ends(z, m), &mut level);
    let mut out = Level::with_capacity(level.bps.len());
    merge_leaf::<K, V>(&c, level.env(0), level.env(1), &mut out).map_err(|w| c.bad(w, which))?;
    drop(level);
    to_prepared::<K, V>(&c, &cl, out.env(0), which, false)
}

/// [`merge`] of an envelope `a` with the envelope `leaf` of a single edge, touching only the
/// breakpoints of `a` within the edge's height range and one on either side: the others are
/// copied (the edge is no part of the union there, so their points and gaps stay). The range is
/// found by two binary searches of exact height comparisons. `O(log |a| + k)` degree-2 tests for
/// the `k` breakpoints of `a` within the edge's heights, plus the copy.
fn merge_leaf<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    a: Env<'_>,
    leaf: Env<'_>,
    out: &mut Level,
) -> Result<(), Bad> {
    let (Some(bot), Some(top)) = (leaf.bps.first(), leaf.bps.last()) else {
        return merge::<K, V>(c, a, leaf, out);
    };
    let (bot, top) = (c.v[bot.y], c.v[top.y]);
    let h = |bp: &Bp| c.v[bp.y];
    // `a`'s breakpoints strictly below the edge's bottom, and those at or below its top.
    let lo = a
        .bps
        .partition_point(|bp| c.frame.cmp_height::<K, _>(h(bp), bot) == Ordering::Less);
    let hi = a
        .bps
        .partition_point(|bp| c.frame.cmp_height::<K, _>(h(bp), top) != Ordering::Greater);
    let (from, to) = (lo.saturating_sub(1), (hi + 1).min(a.bps.len()));
    let start = out.bps.len();
    out.bps.extend_from_slice(&a.bps[..from]);
    let mut mid = Level::with_capacity(to - from + leaf.bps.len());
    merge::<K, V>(
        c,
        Env {
            bps: &a.bps[from..to],
        },
        leaf,
        &mut mid,
    )?;
    out.bps.extend_from_slice(&mid.bps);
    // The last breakpoint of the middle is `a`'s (its gap, the edge above, was cut off by the
    // slice) unless the middle reaches `a`'s top.
    if to < a.bps.len() {
        if let (Some(last), Some(orig)) = (out.bps.last_mut(), a.bps.get(to - 1)) {
            last.gap = orig.gap;
        }
    }
    out.bps.extend_from_slice(&a.bps[to..]);
    out.close(start);
    Ok(())
}

/// Appends the walk's nodes (`nodes`, with the edge above each in `edges`), offset by `off` into
/// the chain's positions, as one envelope of `level`, the nodes at one true height collapsed to
/// the first (the nearest): the edge below the group is the one below its first node, the edge
/// above it the one above its last. `O(nodes)` degree-2 tests.
fn collapse<K: Kernel, V: Vertex>(
    c: &Ctx<'_, V>,
    nodes: &[usize],
    edges: &[usize],
    off: usize,
    level: &mut Level,
) {
    let start = level.bps.len();
    for (k, &u) in nodes.iter().enumerate() {
        let (u, gap) = (u + off, edges.get(k).map(|&e| e + off));
        let same =
            k > 0 && c.frame.cmp_height::<K, _>(c.v[nodes[k - 1] + off], c.v[u]) == Ordering::Equal;
        if same {
            if let Some(last) = level.bps.last_mut() {
                last.gap = gap;
            }
        } else {
            level.push(u, At::Vertex(u), gap);
        }
    }
    level.close(start);
}

/// Lemma 2 for a chain clipped to its half-plane: the runs `runs` (inclusive position ranges of
/// `chain`, in order, disjoint; each a simple polyline, consecutive positions joined by an edge
/// only within a run) as one point set, whose envelope has gaps where no run covers a height
/// (docs/algorithms/separator.md, "Step G"). Each run's envelope by [`scan`], then the envelopes
/// merged pairwise in a balanced tree.
///
/// # Complexity
/// `O(n log k)` degree-2 tests for `k` runs (each round of merges is linear); `O(n)` for one run.
///
/// # Errors
/// As [`prepare`]: [`SeparationError::NotSimple`] when the runs are seen not to be simple or to
/// meet each other.
pub(crate) fn prepare_runs<K: Kernel, V: Vertex>(
    chain: &[V],
    runs: &[(usize, usize)],
    frame: Frame,
    which: Chain,
) -> Result<Prepared<V>, SeparationError> {
    let m = chain.len();
    // Every position its own index; edge `k` joins positions `k` and `k + 1` (those between runs
    // are never walked nor merged: no envelope names them).
    let cl = Clean {
        v: Cow::Borrowed(chain),
        idx: Index::Rotated { shift: 0, m },
        callers: Index::Rotated { shift: 0, m },
        edges: m.saturating_sub(1),
    };
    let (dirs, sheared) = orient_edges::<K, V>(frame, &cl);
    let c = Ctx::new(frame, &cl, &dirs, false);
    let mut level = Level::with_capacity(m + 2);
    for &(s, t) in runs {
        if s > t || t >= m {
            return Err(SeparationError::Inconsistent);
        }
        // The run's own walk, in its own positions (directions do not depend on them).
        let sc = Ctx {
            frame,
            v: &cl.v[s..=t],
            idx: Ix::Rotated { shift: s, m },
            dirs: &sheared[s..t],
            lex: true,
        };
        let (nodes, edges) = scan::<K, V>(&sc, t + 1 - s).map_err(|w| c.bad(w + s, which))?;
        collapse::<K, V>(&c, &nodes, &edges, s, &mut level);
    }
    // Balanced merging: each round halves the number of envelopes.
    while level.segs.len() > 1 {
        let count = level.segs.len();
        let mut next = Level::with_capacity(level.bps.len());
        for i in (0..count).step_by(2) {
            if i + 1 < count {
                merge::<K, V>(&c, level.env(i), level.env(i + 1), &mut next)
                    .map_err(|w| c.bad(w, which))?;
            } else {
                let start = next.bps.len();
                next.bps.extend_from_slice(level.env(i).bps);
                next.close(start);
            }
        }
        level = next;
    }
    if level.segs.is_empty() {
        level.close(0);
    }
    to_prepared::<K, V>(&c, &cl, level.env(0), which, true)
}

/// The `O(n²)` twin of [`prepare`]: for every distinct vertex height, the nearest point of the
/// chain at that height by comparing all vertices and all edges crossing it; for every elementary
/// slab between consecutive heights, the nearest edge by comparing all edges spanning it.
pub(crate) fn prepare_brute<K: Kernel, V: Vertex>(
    chain: &[V],
    frame: Frame,
    which: Chain,
) -> Result<Prepared<V>, SeparationError> {
    let cl = clean(chain, which)?;
    let (dirs, _) = orient_edges::<K, V>(frame, &cl);
    let c = Ctx::new(frame, &cl, &dirs, false);
    let m = cl.v.len();
    // Distinct heights, each given by its first vertex, in increasing order (insertion sort by
    // exact comparisons: O(n²)).
    let mut hs: Vec<usize> = Vec::new();
    for w in 0..m {
        let pos = hs
            .iter()
            .position(|&h| frame.cmp_height::<K, _>(cl.v[w], cl.v[h]) != Ordering::Greater);
        match pos {
            Some(p) if frame.cmp_height::<K, _>(cl.v[w], cl.v[hs[p]]) == Ordering::Equal => {}
            Some(p) => hs.insert(p, w),
            None => hs.push(w),
        }
    }
    let spans = |e: usize, y: usize, strict_top: bool| {
        c.lohi(e).is_some_and(|(a, b)| {
            frame.cmp_height::<K, _>(cl.v[a], cl.v[y]) == Ordering::Less
                && if strict_top {
                    frame.cmp_height::<K, _>(cl.v[b], cl.v[y]) == Ordering::Greater
                } else {
                    frame.cmp_height::<K, _>(cl.v[b], cl.v[y]) != Ordering::Less
                }
        })
    };
    let bad = |w: Bad| c.bad(w, which);
    let mut env = Level::with_capacity(hs.len());
    for (k, &h) in hs.iter().enumerate() {
        let mut best: Option<At> = None;
        for w in 0..m {
            if frame.cmp_height::<K, _>(cl.v[w], cl.v[h]) == Ordering::Equal {
                best = Some(match best {
                    None => At::Vertex(w),
                    Some(x) => nearer::<K, V>(&c, x, At::Vertex(w)).map_err(bad)?,
                });
            }
        }
        for e in 0..cl.edges {
            if spans(e, h, true) {
                best = Some(match best {
                    None => At::Edge(e),
                    Some(x) => nearer::<K, V>(&c, x, At::Edge(e)).map_err(bad)?,
                });
            }
        }
        let at = best.unwrap_or(At::Vertex(h));
        let gap = if k + 1 < hs.len() {
            // Edges spanning the slab above h: bottom at or below h, top above h.
            let mut g: Option<usize> = None;
            for e in 0..cl.edges {
                let Some((a, b)) = c.lohi(e) else { continue };
                if frame.cmp_height::<K, _>(cl.v[a], cl.v[h]) != Ordering::Greater
                    && frame.cmp_height::<K, _>(cl.v[b], cl.v[h]) == Ordering::Greater
                {
                    g = Some(match g {
                        None => e,
                        Some(f) => {
                            if edge_vs_edge::<K, V>(&c, e, f).map_err(bad)? == Ordering::Less {
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
    to_prepared::<K, V>(&c, &cl, env.env(0), which, false)
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
        .position(|&v| frame.depth_sign::<K, _>(v) == Sign::Negative)
    {
        return Err(SeparationError::NotSeparated {
            chain: Chain::P,
            index,
        });
    }
    let prep = if brute {
        prepare_brute::<K, _>(chain, frame, Chain::P)?
    } else {
        prepare::<K, _>(chain, frame, Chain::P)?
    };
    Ok(Envelope {
        vertices: prep.idx.clone(),
        edges: prep.carry.iter().flatten().map(|e| e.caller).collect(),
        shadows: prep
            .carry
            .iter()
            .flatten()
            .map(|e| (e.lo_root, e.hi_root))
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
/// `O(n)` degree-2 predicates: one walk along the chain (see the module documentation).
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

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_predicates::Robust;

    /// A star-shaped closed chain right of the y axis (first vertex repeated at the end), its
    /// coordinates rounded to multiples of `grain` (a coarse grain gives tied heights).
    fn star(m: usize, seed: u64, grain: f64) -> Vec<DVec2> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut v: Vec<DVec2> = (0..m)
            .map(|k| {
                let t = core::f64::consts::TAU * k as f64 / m as f64;
                let r = 2.0 + 6.0 * next();
                let p = DVec2::new(10.0 + r * t.cos(), r * t.sin());
                (p / grain).round() * grain
            })
            .collect();
        v.dedup();
        v.push(v[0]);
        v
    }

    /// The envelope as caller vertices and edges, shifted back by `r` of `m`.
    fn unrotated(p: &Prepared<DVec2>, r: usize, m: usize) -> (Vec<usize>, Vec<usize>) {
        let back = |i: usize| (i + r) % m;
        let vs = p.idx.iter().map(|&i| back(i)).collect();
        let es = p.carry.iter().flatten().map(|c| back(c.caller)).collect();
        (vs, es)
    }

    /// The disjoint-hull route hands over chains rotated to close at their least extent edge and
    /// skips the search (`Closing::AsGiven`); closing a chain at any other edge must give the same
    /// envelope too (only the work differs), on generic and on tied heights.
    #[test]
    fn a_chain_closed_as_given_has_the_envelope_of_the_least_extent_closing() {
        let frame = Frame {
            l0: DVec2::ZERO,
            l1: DVec2::Y,
            mirror: false,
        };
        for grain in [1e-9, 0.5, 1.0] {
            let mut tested = 0;
            for seed in 0..40 {
                let chain = star(40, seed, grain);
                let m = chain.len() - 1;
                // Rounding to a coarse grain can fold the star onto itself.
                if polydist_polygon::SimplePolygon::try_new(&chain[..m]).is_err() {
                    continue;
                }
                tested += 1;
                let want = prepare::<Robust, _>(&chain, frame, Chain::P).unwrap();
                let want = unrotated(&want, 0, m);
                for r in 0..m {
                    let mut rotated: Vec<DVec2> =
                        chain[r..m].iter().chain(&chain[..r]).copied().collect();
                    rotated.push(rotated[0]);
                    let got =
                        prepare_closing::<Robust, _>(&rotated, frame, Chain::P, Closing::AsGiven)
                            .unwrap();
                    let got = unrotated(&got, r, m);
                    assert_eq!(got, want, "seed {seed}, grain {grain}, rotation {r}");
                }
            }
            assert!(tested >= 10, "grain {grain}: {tested} simple stars");
        }
    }
}
