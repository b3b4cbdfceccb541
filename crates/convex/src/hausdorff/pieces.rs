//! ARL's piece decomposition (Atallah, Ribeiro, Lifschitz 1991, §4): the per-vertex distances of
//! `P` to filled `Q` for intersecting convex polygons, piece by piece.
//!
//! # The pieces
//! The symbolic boundary crossings of `∂P` with `∂Q` (module `crossings`: pairs (edge of `P`, feature
//! of `Q`), entries and exits alternating, in counter-clockwise order along `∂P`) cut `∂P` into chains.
//! Between an exit `L` and the next entry `E` lies an external chain `A` of `P` (outside `Q`, touching
//! `∂Q` at most at isolated points or along shared edges); between an entry and the next exit lies an
//! internal chain of `P` (in `Q`). Along `∂Q` the crossings appear in the same cyclic order (all of them
//! lie on the boundary of the convex `P ∩ Q`): the arc of `∂Q` from `L` to `E` is the internal chain `C`
//! of the piece bounded by `A`, the arcs from the entry `E⁻` before `L` to `L`, and from `E` to the exit
//! `L⁺` after `E`, are the neighbouring external chains `B⁻`, `B⁺` of `Q`.
//!
//! # Internal chains of `P`: distance 0
//! A vertex of an internal chain is in `Q`; it is on `∂Q` only where `∂P` touches `∂Q` (a crossing is
//! never inside a chain), and a touching point lies on the arc of `∂Q` between the chain's two crossings
//! (the common cyclic order). There the supporting line of `Q` also supports `P`, so the touching edge's
//! direction lies in the closed angle between the two edges of `P` at the vertex. One merge of the edge
//! directions of the `P` chain and of that `Q` arc (`cross_sign`, as in merging two slope sequences;
//! consecutive compared directions stay less than a half turn apart) tests each vertex against exactly
//! the `Q` edges whose direction lies in its angle: `orient = 0` puts it on that edge. A vertex where
//! `∂P` leaves `Q` carries its feature in the crossing (verified by one exact test).
//!
//! # External chains of `P`: Theorem 1 and the walk
//! Theorem 1: the nearest point of a vertex of `A` lies on `B⁻ ∪ C ∪ B⁺`, the arc `Γ` of `∂Q` from `E⁻` to
//! `L⁺`. ARL close `B⁻` and `B⁺` by chords and run three walks (Atallah's walk against each closed chain
//! and a merge against `C`), then take the smallest of the three distances. We run the three walks as
//! one pointer over the features of `Γ` (vertices and edges of `Q`, in order; `B⁻`, `C`, `B⁺` are
//! consecutive on it), with Atallah's direction test on input points, and replace "the smallest of the
//! three distances" by the certified outer-Voronoi-region test of the full `Q`: the feature whose region
//! holds the vertex is its nearest feature, so no distance to a chord end (a crossing point, whose
//! coordinates are ratios of `2 × 2` determinants) is ever compared. Every predicate is of degree 2
//! (`orient`, `dot_sign`, `cross_sign` on input points).
//!
//! # Bounds
//! Every loop is bounded by counts: the pointer of one vertex moves at most `|Γ|` positions before the
//! vertex is located by scanning `Γ` (counted in [`PiecesStats::scans`]); a global step budget of
//! `12(n + m) + 16` hands the remaining vertices to the brute force ([`PiecesStats::fallbacks`]).

use core::cell::Cell;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Sign};

use super::brute::locate_brute;
use super::walk::{Crossing, Near, in_vertex_region, last_run, walk};

/// What the piece algorithm did on this thread since the last [`reset_pieces_stats`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PiecesStats {
    /// Calls that found crossing boundaries and ran the piece decomposition.
    pub decompositions: u64,
    /// Calls answered by the walk (no crossing: disjoint, nested, identical, touching; or a point or
    /// segment).
    pub walk_paths: u64,
    /// External chains walked.
    pub external_chains: u64,
    /// Internal chains merged.
    pub internal_chains: u64,
    /// Pointer moves and tests (region tests, merge steps).
    pub steps: u64,
    /// The largest number of direction reversals of the pointer on one external chain.
    pub max_reversals: u64,
    /// Vertices whose pointer walk gave up and that were located by scanning their arc `Γ`.
    pub scans: u64,
    /// Runs that exhausted the step budget or met an inconsistent crossing structure (possible only
    /// with inconsistent signs, e.g. the Fast kernel) and let the brute force or the walk answer.
    pub fallbacks: u64,
}

std::thread_local! {
    static STATS: Cell<PiecesStats> = const { Cell::new(PiecesStats {
        decompositions: 0, walk_paths: 0, external_chains: 0, internal_chains: 0, steps: 0,
        max_reversals: 0, scans: 0, fallbacks: 0,
    }) };
}

fn bump(f: impl FnOnce(&mut PiecesStats)) {
    STATS.with(|c| {
        let mut s = c.get();
        f(&mut s);
        c.set(s);
    });
}

/// The counters of the piece algorithm ([`per_vertex_distances_pieces_with`](crate::per_vertex_distances_pieces_with)
/// and the functions built on it) on this thread since the last [`reset_pieces_stats`].
///
/// # Complexity
/// `O(1)`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff_pieces_with, pieces_stats, reset_pieces_stats, polygon::ConvexPolygon};
/// use polydist_convex::polygon::predicates::Robust;
///
/// reset_pieces_stats();
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, 1.0), DVec2::new(6.0, 1.0), DVec2::new(6.0, 3.0), DVec2::new(2.0, 3.0)])?;
/// let _ = hausdorff_pieces_with::<Robust>(&p, &q);
/// let s = pieces_stats();
/// assert_eq!((s.decompositions, s.scans, s.fallbacks), (2, 0, 0));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, Ribeiro, Lifschitz, RAIRO Oper. Res. 25(4) (1991), §4; the counters are ours.
#[must_use]
pub fn pieces_stats() -> PiecesStats {
    STATS.with(Cell::get)
}

/// Sets this thread's [`pieces_stats`] to zero.
///
/// # Complexity
/// `O(1)`.
///
/// # Examples
/// See [`pieces_stats`].
///
/// # References
/// Ours.
pub fn reset_pieces_stats() {
    STATS.with(|c| c.set(PiecesStats::default()));
}

/// The index of the `Q` feature named by a crossing.
fn q_index(c: &Crossing) -> usize {
    match c.q {
        Near::Edge(i) | Near::OnEdge(i) | Near::Vertex(i) | Near::OnVertex(i) => i,
        Near::Inside => 0,
    }
}

/// The nearest feature of every vertex of `p` on filled `q` by ARL's piece decomposition; the walk
/// answers when the boundaries do not cross (or for points and segments).
pub(crate) fn features_pieces<K: Kernel>(p: &[DVec2], q: &[DVec2]) -> Vec<Near> {
    let (n, m) = (p.len(), q.len());
    let by_walk = || {
        bump(|s| s.walk_paths += 1);
        walk::<K>(p, q, &mut Vec::new(), false)
    };
    if n < 3 || m < 3 {
        return by_walk();
    }
    // The intersection structure: the symbolic crossings of the closed boundary of P with ∂Q.
    let mut x: Vec<Crossing> = Vec::new();
    let _ = walk::<K>(p, q, &mut x, true);
    let crossing_walk_fell_back = last_run().0.fell_back;
    if x.is_empty() && !crossing_walk_fell_back {
        return by_walk();
    }
    let r = x.len();
    let consistent = !crossing_walk_fell_back
        && r % 2 == 0
        && (0..r).all(|t| x[t].entering != x[(t + 1) % r].entering && x[t].p_edge < n);
    if !consistent {
        bump(|s| s.fallbacks += 1);
        return p.iter().map(|&v| locate_brute::<K>(q, v)).collect();
    }
    // The chains: after crossing t, the vertices up to crossing t + 1 (a crossing at a vertex of P is
    // named by the edge leaving that vertex, so the vertex belongs to the chain before it).
    let count = |t: usize| {
        let c = (x[(t + 1) % r].p_edge + n - x[t].p_edge) % n;
        if c == 0 && r == 2 && t == 1 { n } else { c }
    };
    if (0..r).map(count).sum::<usize>() != n {
        bump(|s| s.fallbacks += 1);
        return p.iter().map(|&v| locate_brute::<K>(q, v)).collect();
    }
    bump(|s| s.decompositions += 1);
    let mut out: Vec<Option<Near>> = vec![None; n];
    let mut ctx = Ctx {
        p,
        q,
        steps: 0,
        budget: 12 * (n as u64 + m as u64) + 16,
    };
    for t in 0..r {
        let len = count(t);
        let first = (x[t].p_edge + 1) % n;
        let ks: Vec<usize> = (0..len).map(|d| (first + d) % n).collect();
        if ks.is_empty() {
            continue;
        }
        if x[t].entering {
            bump(|s| s.internal_chains += 1);
            internal::<K>(&mut ctx, &ks, &x[t], &x[(t + 1) % r], &mut out);
        } else {
            bump(|s| s.external_chains += 1);
            let before = &x[(t + r - 1) % r];
            let after = &x[(t + 2) % r];
            external::<K>(&mut ctx, &ks, before, after, r, &mut out);
        }
        if ctx.steps > ctx.budget {
            break;
        }
    }
    let steps = ctx.steps;
    bump(|s| s.steps += steps);
    let mut fell_back = false;
    let res = out
        .into_iter()
        .enumerate()
        .map(|(k, f)| {
            f.unwrap_or_else(|| {
                fell_back = true;
                locate_brute::<K>(q, p[k])
            })
        })
        .collect();
    if fell_back {
        bump(|s| s.fallbacks += 1);
    }
    res
}

/// The polygons and the step count.
struct Ctx<'a> {
    p: &'a [DVec2],
    q: &'a [DVec2],
    steps: u64,
    budget: u64,
}

impl Ctx<'_> {
    #[inline]
    fn qn(&self, i: usize) -> usize {
        if i + 1 == self.q.len() { 0 } else { i + 1 }
    }
    #[inline]
    fn pn(&self, k: usize) -> usize {
        if k + 1 == self.p.len() { 0 } else { k + 1 }
    }
    #[inline]
    fn pp(&self, k: usize) -> usize {
        if k == 0 { self.p.len() - 1 } else { k - 1 }
    }
    #[inline]
    fn tick(&mut self) -> bool {
        self.steps += 1;
        self.steps <= self.budget
    }
    /// `v` on the closed edge `e_i` (given that `v` is on its line and in `Q`), canonically named.
    fn on_edge(&self, i: usize, v: DVec2) -> Near {
        let j = self.qn(i);
        if v == self.q[i] {
            Near::OnVertex(i)
        } else if v == self.q[j] {
            Near::OnVertex(j)
        } else {
            Near::OnEdge(i)
        }
    }
}

/// An internal chain of `P` (the vertices `ks`, between the entry `from` and the exit `to`): every
/// vertex is in `Q`; the merge of edge directions finds those on `∂Q` (module docs).
fn internal<K: Kernel>(
    ctx: &mut Ctx<'_>,
    ks: &[usize],
    from: &Crossing,
    to: &Crossing,
    out: &mut [Option<Near>],
) {
    let (p, q, m) = (ctx.p, ctx.q, ctx.q.len());
    let (s, e) = (q_index(from), q_index(to));
    // The Q arc from the entry to the exit: its edges s, s+1, …, e (the long way round when both
    // crossings are on one edge: a chain of P inside Q that enters and leaves through one edge of Q
    // has all of ∂Q but part of that edge outside P).
    let edges = (e + m - s) % m + 1 + if s == e { m } else { 0 };
    let edge = |d: usize| (s + d) % m;
    let mut i = 0usize;
    let last = *ks.last().unwrap_or(&0);
    for &k in ks {
        let (a, v, b) = (p[ctx.pp(k)], p[k], p[ctx.pn(k)]);
        if k == last && !to.entering && matches!(to.q, Near::OnEdge(_) | Near::OnVertex(_)) {
            // ∂P leaves Q at this vertex: the crossing names its feature; verify it exactly.
            out[k] = Some(verified_on::<K>(ctx, to.q, v));
            continue;
        }
        // Skip the Q edges whose direction is strictly before the edge of P into v.
        while i < edges && ctx.tick() {
            let g = edge(i);
            if K::cross_sign(a, v, q[g], q[ctx.qn(g)]) == Sign::Negative {
                i += 1;
            } else {
                break;
            }
        }
        // Test the Q edges whose direction is in the closed angle of v (up to the edge out of v).
        let mut found = Near::Inside;
        let mut j = i;
        while j < edges && ctx.tick() {
            let g = edge(j);
            let (qa, qb) = (q[g], q[ctx.qn(g)]);
            let c = K::cross_sign(v, b, qa, qb);
            let within = c == Sign::Negative
                || (c == Sign::Zero && K::dot_sign(v, b, qa, qb) == Sign::Positive);
            if !within {
                break;
            }
            if K::orient(qa, qb, v) == Orientation::Collinear {
                found = ctx.on_edge(g, v);
                break;
            }
            j += 1;
        }
        if ctx.steps > ctx.budget {
            return;
        }
        out[k] = Some(found);
    }
}

/// The vertex `v` where `∂P` leaves `Q`, named `near` (on the boundary) by the crossing: checked by
/// exact tests; the brute force if the check fails (inconsistent signs).
fn verified_on<K: Kernel>(ctx: &Ctx<'_>, near: Near, v: DVec2) -> Near {
    let q = ctx.q;
    let ok = match near {
        Near::OnVertex(i) => v == q[i],
        Near::OnEdge(i) => {
            let j = ctx.qn(i);
            K::orient(q[i], q[j], v) == Orientation::Collinear
                && K::dot_sign(q[i], v, q[i], q[j]) == Sign::Positive
                && K::dot_sign(q[j], v, q[i], q[j]) == Sign::Negative
        }
        _ => false,
    };
    if ok { near } else { locate_brute::<K>(q, v) }
}

/// The features of the arc `Γ`: position `2d` is the vertex `q_{s+d}`, `2d + 1` the edge `e_{s+d}`;
/// `len` positions, cyclic when `Γ` is all of `∂Q`.
struct Arc {
    s: usize,
    len: usize,
    cyclic: bool,
}

impl Arc {
    /// The feature at position `pos` (`true` for an edge) and its index in `Q`.
    fn at(&self, pos: usize, m: usize) -> (bool, usize) {
        (pos % 2 == 1, (self.s + pos / 2) % m)
    }
    /// The position after moving one step in direction `dir`, or `None` past an end.
    fn step(&self, pos: usize, dir: i8) -> Option<usize> {
        if dir > 0 {
            if pos + 1 < self.len {
                Some(pos + 1)
            } else if self.cyclic {
                Some(0)
            } else {
                None
            }
        } else if pos > 0 {
            Some(pos - 1)
        } else if self.cyclic {
            Some(self.len - 1)
        } else {
            None
        }
    }
}

/// The certified test of the feature at `pos` for a point `w` outside `int Q`: the feature if `w` is in
/// its closed outer Voronoi region (vertex) or its open strip (edge), or on it.
fn test<K: Kernel>(ctx: &Ctx<'_>, arc: &Arc, pos: usize, w: DVec2) -> Option<Near> {
    let q = ctx.q;
    let (is_edge, i) = arc.at(pos, q.len());
    if !is_edge {
        if w == q[i] {
            return Some(Near::OnVertex(i));
        }
        return in_vertex_region::<K>(q, i, w).then_some(Near::Vertex(i));
    }
    let j = ctx.qn(i);
    if K::dot_sign(q[i], w, q[i], q[j]) != Sign::Positive
        || K::dot_sign(q[j], w, q[i], q[j]) != Sign::Negative
    {
        return None;
    }
    match K::orient(q[i], q[j], w) {
        Orientation::Clockwise => Some(Near::Edge(i)),
        Orientation::Collinear => Some(Near::OnEdge(i)),
        Orientation::CounterClockwise => None,
    }
}

/// Atallah's direction from the feature `prev` of `wk` to the next vertex `w`: `+1` counter-clockwise
/// along `∂Q`, `−1` clockwise, `0` stationary. At a vertex projection `orient(q_i, w_k, w)` ("w left of
/// the line y_k → w_k"); at a foot `sign(d_i·(w − w_k))` (notes §1.2); from a point of `∂Q`, or along a
/// line through `q_i`, the side of `w` beyond the vertex or edge (dot signs).
fn direction<K: Kernel>(ctx: &Ctx<'_>, prev: Near, wk: DVec2, w: DVec2) -> i8 {
    let q = ctx.q;
    let beyond = |i: usize| {
        if K::dot_sign(q[i], w, q[i], q[ctx.qn(i)]) == Sign::Positive {
            1
        } else {
            -1
        }
    };
    match prev {
        Near::Vertex(i) => match K::orient(q[i], wk, w) {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::Collinear => beyond(i),
        },
        Near::OnVertex(i) => beyond(i),
        Near::Edge(i) => match K::dot_sign(wk, w, q[i], q[ctx.qn(i)]) {
            Sign::Positive => 1,
            Sign::Negative => -1,
            Sign::Zero => 0,
        },
        Near::OnEdge(i) => {
            let j = ctx.qn(i);
            if K::dot_sign(q[j], w, q[i], q[j]) != Sign::Negative {
                1
            } else {
                -1
            }
        }
        Near::Inside => 0,
    }
}

/// An external chain of `P` (the vertices `ks`, between the exit `L` and the entry `E`), located on the
/// arc `Γ` of `∂Q` from the entry `before` (`E⁻`) to the exit `after` (`L⁺`), one edge of margin on
/// each side; all of `∂Q` when there is one piece each way (`r = 2`).
fn external<K: Kernel>(
    ctx: &mut Ctx<'_>,
    ks: &[usize],
    before: &Crossing,
    after: &Crossing,
    r: usize,
    out: &mut [Option<Near>],
) {
    let (p, m) = (ctx.p, ctx.q.len());
    let (s0, e0) = (q_index(before), q_index(after));
    let edges = (e0 + m - s0) % m + 3;
    let arc = if r == 2 || s0 == e0 || edges >= m {
        Arc {
            s: 0,
            len: 2 * m,
            cyclic: true,
        }
    } else {
        Arc {
            s: (s0 + m - 1) % m,
            len: 2 * edges + 1,
            cyclic: false,
        }
    };
    let scan = |ctx: &mut Ctx<'_>, w: DVec2| -> Option<(usize, Near)> {
        for pos in 0..arc.len {
            if !ctx.tick() {
                return None;
            }
            if let Some(f) = test::<K>(ctx, &arc, pos, w) {
                return Some((pos, f));
            }
        }
        None
    };
    let mut cur: Option<(usize, Near)> = None;
    let mut last_dir = 0i8;
    let mut reversals = 0u64;
    for (idx, &k) in ks.iter().enumerate() {
        if ctx.steps > ctx.budget {
            return;
        }
        let w = p[k];
        let found = match cur {
            None => scan(ctx, w),
            Some((pos, prev)) => {
                let wk = p[ks[idx - 1]];
                let walked = walk_to::<K>(ctx, &arc, pos, prev, wk, w);
                match walked {
                    Some((f, dir)) => {
                        if dir != 0 {
                            if last_dir != 0 && dir != last_dir {
                                reversals += 1;
                            }
                            last_dir = dir;
                        }
                        Some(f)
                    }
                    None => {
                        bump(|s| s.scans += 1);
                        scan(ctx, w)
                    }
                }
            }
        };
        match found {
            Some((pos, f)) => {
                out[k] = Some(f);
                cur = Some((pos, f));
            }
            None => return,
        }
    }
    bump(|s| s.max_reversals = s.max_reversals.max(reversals));
}

/// One step of the walk: from position `pos` (feature `prev` of `wk`) to the feature of `w`, moving in
/// Atallah's direction; `None` if the pointer leaves `Γ` or makes a full pass without a certified stop.
fn walk_to<K: Kernel>(
    ctx: &mut Ctx<'_>,
    arc: &Arc,
    pos: usize,
    prev: Near,
    wk: DVec2,
    w: DVec2,
) -> Option<((usize, Near), i8)> {
    if !ctx.tick() {
        return None;
    }
    if let Some(f) = test::<K>(ctx, arc, pos, w) {
        return Some(((pos, f), 0));
    }
    let dir = direction::<K>(ctx, prev, wk, w);
    if dir == 0 {
        return None;
    }
    let mut at = pos;
    for _ in 0..arc.len {
        if !ctx.tick() {
            return None;
        }
        at = arc.step(at, dir)?;
        if let Some(f) = test::<K>(ctx, arc, at, w) {
            return Some(((at, f), dir));
        }
    }
    None
}
