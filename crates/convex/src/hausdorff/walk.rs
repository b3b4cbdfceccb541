//! The walk: the nearest feature of every vertex of `P` on the filled convex polygon `Q`, in one pass.
//!
//! Atallah (1983) and Atallah, Ribeiro, Lifschitz (1991, §3) walk along `P` and move a pointer along
//! `Q`'s features in the direction given by "is `v_{k+1}` left of the line `y_k → v_k`". We walk the
//! segments `[v_k, v_{k+1}]` of `P` through the subdivision of the plane formed by `Q`'s interior and
//! its outer Voronoi regions `V(i)` (vertex `q_i`) and `E(i)` (edge `e_i = q_i q_{i+1}`):
//!
//! - on disjoint polygons this is Atallah's walk exactly: leaving `V(i)` towards `E(i)` iff
//!   `orient(q_i, v_k, v_{k+1}) > 0` is his test at a vertex projection (the projection `y_k = q_i`), and
//!   leaving `E(i)` after `q_{i+1}` iff `(v_{k+1} − q_{i+1})·d_i ≥ 0` is, for `v_k` in the strip, his test
//!   at a foot (`sign(d_i·(v_{k+1} − v_k))`); no projection is ever constructed;
//! - on intersecting polygons the same walk passes through `Q`'s interior: it enters through an edge and
//!   leaves through the exit edge of the line `v_k v_{k+1}`, found by a forward scan (the scan index is
//!   kept from one segment to the next). Where the walk changes side (strictly inside ↔ outside) it
//!   records a boundary crossing of `∂P` with `∂Q`, symbolically as (edge of `P`, feature of `Q`):
//!   these delimit the pieces of `(P ∪ Q) − int(P ∩ Q)` (ARL §4); touching and shared boundary
//!   stretches are no crossings;
//! - a segment that starts on `∂Q` or passes exactly through a vertex of `Q` is relocated by `O(1)`
//!   local signs at that vertex or edge (following the boundary along a collinear edge).
//!
//! Every stop at an outer region is certified by the exact region test, so a stop can never be at a
//! wrong feature; a global step budget of `10(n + m) + 16` (never reached under exact predicates, see
//! the tests) makes every run finite under the Fast kernel, with the brute force answering the rest.

use core::cell::Cell;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Sign};

use super::brute::locate_brute;

/// The nearest feature of filled `Q` to a point, in `Q`'s internal indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Near {
    /// Strictly inside `Q`: distance 0.
    Inside,
    /// Equal to vertex `i` of `Q`: distance 0.
    OnVertex(usize),
    /// On the open edge `i` of `Q`: distance 0.
    OnEdge(usize),
    /// Outside `Q`, nearest to vertex `i` (in the closed region `V(i)`).
    Vertex(usize),
    /// Outside `Q`, nearest to the open edge `i` (the foot is strictly inside the edge).
    Edge(usize),
}

/// A boundary crossing of `∂P` with `∂Q`, symbolic: the edge `k` of `P` (from `v_k` to `v_{k+1}`) and
/// the feature of `Q` it passes through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Crossing {
    /// The edge of `P`.
    pub(crate) p_edge: usize,
    /// The feature of `Q` (an edge, or a vertex when the crossing is exactly at it).
    pub(crate) q: Near,
    /// `true` when `∂P` enters `Q` here, `false` when it leaves.
    pub(crate) entering: bool,
}

/// What one run of the walk did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Run {
    /// Steps taken (region moves, scan advances, vertex passes).
    pub(crate) steps: u64,
    /// The budget, `10(n + m) + 16`.
    pub(crate) budget: u64,
    /// Whether the budget ran out and the brute force answered the remaining vertices.
    pub(crate) fell_back: bool,
}

std::thread_local! {
    static LAST: Cell<Run> = const { Cell::new(Run { steps: 0, budget: 0, fell_back: false }) };
    static FALLBACKS: Cell<u64> = const { Cell::new(0) };
}

/// The last run on this thread and the number of fallbacks since the last reset.
pub(crate) fn last_run() -> (Run, u64) {
    (LAST.with(Cell::get), FALLBACKS.with(Cell::get))
}

/// Resets the fallback counter.
pub(crate) fn reset_fallbacks() {
    FALLBACKS.with(|c| c.set(0));
}

/// Where the walk is: the region of `Q`'s subdivision holding the current point of the segment.
#[derive(Clone, Copy, Debug)]
enum State {
    /// In the closed vertex region `V(i)`.
    V(usize),
    /// In the edge region `E(i)` (closure).
    E(usize),
    /// In `Q`; the exit edge of the segment's line is found by scanning forward from edge `j`.
    I(usize),
}

/// The outcome of a local decision: an answer for `b`, a region to continue from, or an entry into
/// `Q` (the scan start and the feature crossed).
enum Step {
    Done(Near),
    Go(State),
    Enter(usize, Near),
}

/// `Q`'s vertices with cyclic index helpers.
struct Ring<'a> {
    q: &'a [DVec2],
}

impl Ring<'_> {
    #[inline]
    fn nx(&self, i: usize) -> usize {
        if i + 1 == self.q.len() { 0 } else { i + 1 }
    }
    #[inline]
    fn pv(&self, i: usize) -> usize {
        if i == 0 { self.q.len() - 1 } else { i - 1 }
    }
    #[inline]
    fn at(&self, i: usize) -> DVec2 {
        self.q[i]
    }
}

/// Normal cone of `Q` at `q_i`: `(b − q_i)·d_i ≤ 0` and `(b − q_i)·d_{i−1} ≥ 0` (closed `V(i)`).
#[inline]
pub(crate) fn in_vertex_region<K: Kernel>(q: &[DVec2], i: usize, b: DVec2) -> bool {
    let r = Ring { q };
    let (qi, qn, qp) = (r.at(i), r.at(r.nx(i)), r.at(r.pv(i)));
    K::dot_sign(qi, b, qi, qn) != Sign::Positive && K::dot_sign(qi, b, qp, qi) != Sign::Negative
}

/// The nearest feature of every vertex of `p` on filled `q` (strictly convex, counter-clockwise), and
/// the symbolic boundary crossings. `O(n + m)` predicates under exact decisions.
///
/// With `closing`, the closing segment `[v_{n−1}, v_0]` is walked too, so that `crossings` holds every
/// crossing of the closed boundary (its answer for `v_0` is dropped).
pub(crate) fn walk<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    crossings: &mut Vec<Crossing>,
    closing: bool,
) -> Vec<Near> {
    let mut out = Vec::with_capacity(p.len() + 1);
    match q.len() {
        0 => {}
        1 | 2 => out.extend(p.iter().map(|&v| small::<K>(q, v))),
        _ => walk_polygon::<K>(p, q, &mut out, crossings, closing && p.len() >= 2),
    }
    out.truncate(p.len());
    out
}

/// `Q` a point or a segment: `O(1)` exact tests per vertex.
pub(crate) fn small<K: Kernel>(q: &[DVec2], v: DVec2) -> Near {
    if q.len() == 1 {
        return if v == q[0] {
            Near::OnVertex(0)
        } else {
            Near::Vertex(0)
        };
    }
    let (a, b) = (q[0], q[1]);
    if K::dot_sign(a, v, a, b) != Sign::Positive {
        if v == a {
            Near::OnVertex(0)
        } else {
            Near::Vertex(0)
        }
    } else if K::dot_sign(b, v, a, b) != Sign::Negative {
        if v == b {
            Near::OnVertex(1)
        } else {
            Near::Vertex(1)
        }
    } else if K::orient(a, b, v) == Orientation::Collinear {
        Near::OnEdge(0)
    } else {
        Near::Edge(0)
    }
}

/// The side of `Q`'s boundary the walk was last on (strictly inside or outside), to record a crossing
/// only where the side changes: runs along `∂Q` (touching, shared edges) are no crossings.
struct Sides {
    /// The current side: `Some(true)` inside, `Some(false)` outside, `None` before any.
    side: Option<bool>,
    /// Whether the first recorded crossing was recorded with no side before it.
    first_unknown: bool,
}

impl Sides {
    /// The walk is now on side `inside` after passing `q` on edge `k` of `P`.
    fn note(&mut self, inside: bool, p_edge: usize, q: Near, crossings: &mut Vec<Crossing>) {
        if self.side != Some(inside) {
            if self.side.is_none() && crossings.is_empty() {
                self.first_unknown = true;
            }
            crossings.push(Crossing {
                p_edge,
                q,
                entering: inside,
            });
        }
        self.side = Some(inside);
    }
}

/// The walk for `m ≥ 3`.
fn walk_polygon<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    out: &mut Vec<Near>,
    crossings: &mut Vec<Crossing>,
    closing: bool,
) {
    let r = Ring { q };
    let n = p.len();
    let segments = if closing { n } else { n.saturating_sub(1) };
    let budget = 10 * (n as u64 + q.len() as u64) + 16;
    let mut run = Run {
        steps: 0,
        budget,
        fell_back: false,
    };
    if n == 0 {
        LAST.with(|c| c.set(run));
        return;
    }
    out.push(locate_first::<K>(&r, p[0]));
    let mut sides = Sides {
        side: match out[0] {
            Near::Inside => Some(true),
            Near::Vertex(_) | Near::Edge(_) => Some(false),
            Near::OnVertex(_) | Near::OnEdge(_) => None,
        },
        first_unknown: false,
    };
    // The exit edge of the last segment when it ended strictly inside `Q`.
    let mut exit: Option<usize> = None;
    for k in 0..segments {
        let (a, b) = (p[k], p[if k + 1 == n { 0 } else { k + 1 }]);
        let start = out[k];
        let step = match start {
            Near::Vertex(i) => Step::Go(State::V(i)),
            Near::Edge(i) => Step::Go(State::E(i)),
            Near::Inside => match exit {
                Some(j) => Step::Go(State::I(j)),
                None => match first_exit::<K>(&r, a, b) {
                    Some(j) => Step::Go(State::I(j)),
                    None => Step::Done(locate_brute::<K>(q, b)),
                },
            },
            Near::OnVertex(i) => through_vertex::<K>(&r, i, b, &mut run.steps),
            Near::OnEdge(i) => leave_edge::<K>(&r, i, b, &mut run.steps),
        };
        // Leaving a boundary point of Q: to the outside, or into the interior.
        if matches!(start, Near::OnVertex(_) | Near::OnEdge(_)) {
            match step {
                Step::Go(State::V(_) | State::E(_))
                | Step::Done(Near::Vertex(_) | Near::Edge(_)) => {
                    sides.note(false, k, start, crossings);
                }
                Step::Enter(_, f) => sides.note(true, k, f, crossings),
                _ => {}
            }
        }
        let mut state = match step {
            Step::Done(near) => {
                exit = None;
                out.push(near);
                continue;
            }
            Step::Go(s) => s,
            Step::Enter(j, _) => State::I(j),
        };
        let near = loop {
            run.steps += 1;
            if run.steps > budget {
                break None;
            }
            let next = match state {
                State::V(i) => from_vertex_region::<K>(&r, i, a, b, &mut run.steps),
                State::E(i) => from_edge_region::<K>(&r, i, a, b, &mut run.steps),
                State::I(j) => {
                    let (s, j) = from_inside::<K>(&r, j, a, b, &mut run.steps, budget);
                    match s {
                        Step::Done(Near::Inside) => exit = Some(j),
                        Step::Go(_) => sides.note(false, k, Near::Edge(j), crossings),
                        _ => {}
                    }
                    s
                }
            };
            match next {
                Step::Done(near) => break Some(near),
                Step::Go(s) => state = s,
                Step::Enter(j, f) => {
                    sides.note(true, k, f, crossings);
                    state = State::I(j);
                }
            }
        };
        match near {
            Some(near) => {
                if !matches!(near, Near::Inside) {
                    exit = None;
                }
                out.push(near);
            }
            None => {
                // Budget exhausted (inconsistent predicates): the brute force answers the rest.
                run.fell_back = true;
                FALLBACKS.with(|c| c.set(c.get() + 1));
                out.extend(p[(k + 1).min(n)..].iter().map(|&v| locate_brute::<K>(q, v)));
                break;
            }
        }
    }
    // Around the closed boundary the side before the first crossing is the side at the end.
    if closing && sides.first_unknown {
        if let Some(first) = crossings.first() {
            if sides.side == Some(first.entering) {
                crossings.remove(0);
            }
        }
    }
    LAST.with(|c| c.set(run));
}

/// The nearest feature of the first vertex: in `Q` iff on or left of every edge line, else the outer
/// region whose certified test passes (`O(m)` cheap signs); the brute force if none does (possible
/// only with inconsistent signs).
fn locate_first<K: Kernel>(r: &Ring<'_>, v: DVec2) -> Near {
    let m = r.q.len();
    let mut outside = false;
    let mut on = None;
    for i in 0..m {
        match K::orient(r.at(i), r.at(r.nx(i)), v) {
            Orientation::Clockwise => {
                outside = true;
                break;
            }
            Orientation::Collinear => on = on.or(Some(i)),
            Orientation::CounterClockwise => {}
        }
    }
    if !outside {
        return match on {
            None => Near::Inside,
            Some(_) => locate_brute::<K>(r.q, v),
        };
    }
    for i in 0..m {
        if in_vertex_region::<K>(r.q, i, v) {
            return Near::Vertex(i);
        }
        let (qi, qj) = (r.at(i), r.at(r.nx(i)));
        if K::dot_sign(qi, v, qi, qj) == Sign::Positive
            && K::dot_sign(qj, v, qi, qj) == Sign::Negative
            && K::orient(qi, qj, v) == Orientation::Clockwise
        {
            return Near::Edge(i);
        }
    }
    locate_brute::<K>(r.q, v)
}

/// The exit edge of the line `a → b` through `a` strictly inside `Q`, by one `O(m)` scan: the edge
/// `e_j` with `q_j` strictly right of the line and `q_{j+1}` left of or on it.
fn first_exit<K: Kernel>(r: &Ring<'_>, a: DVec2, b: DVec2) -> Option<usize> {
    let m = r.q.len();
    (0..m).find(|&j| {
        K::orient(a, b, r.at(j)) == Orientation::Clockwise
            && K::orient(a, b, r.at(r.nx(j))) != Orientation::Clockwise
    })
}

/// The current point is in `V(i)`: stop if `b` is there, else leave through the ray the segment turns
/// to (`orient(q_i, a, b)`, Atallah's test at a vertex projection), or pass through `q_i` itself.
fn from_vertex_region<K: Kernel>(
    r: &Ring<'_>,
    i: usize,
    a: DVec2,
    b: DVec2,
    steps: &mut u64,
) -> Step {
    if in_vertex_region::<K>(r.q, i, b) {
        return Step::Done(if b == r.at(i) {
            Near::OnVertex(i)
        } else {
            Near::Vertex(i)
        });
    }
    match K::orient(r.at(i), a, b) {
        Orientation::CounterClockwise => Step::Go(State::E(i)),
        Orientation::Clockwise => Step::Go(State::E(r.pv(i))),
        // The line through the current point (in V(i)) and b passes through q_i; b is not in the cone
        // V(i), so it lies beyond q_i.
        Orientation::Collinear => through_vertex::<K>(r, i, b, steps),
    }
}

/// The current point is in (the closure of) `E(i)`.
fn from_edge_region<K: Kernel>(
    r: &Ring<'_>,
    i: usize,
    a: DVec2,
    b: DVec2,
    steps: &mut u64,
) -> Step {
    let j = r.nx(i);
    let (qi, qj) = (r.at(i), r.at(j));
    let bf = K::dot_sign(qi, b, qi, qj); // (b − q_i)·d_i
    let af = K::dot_sign(qj, b, qi, qj); // (b − q_{i+1})·d_i
    let o = K::orient(qi, qj, b);
    match o {
        Orientation::Clockwise if bf == Sign::Positive && af == Sign::Negative => {
            return Step::Done(Near::Edge(i));
        }
        Orientation::Collinear if bf != Sign::Negative && af != Sign::Positive => {
            return Step::Done(if bf == Sign::Zero {
                Near::OnVertex(i)
            } else if af == Sign::Zero {
                Near::OnVertex(j)
            } else {
                Near::OnEdge(i)
            });
        }
        _ => {}
    }
    let before = bf != Sign::Positive;
    let after = af != Sign::Negative;
    if o == Orientation::Clockwise {
        // b is beyond the edge line: the segment leaves the strip through the perpendicular at q_i or
        // at q_{i+1} (Atallah's direction at a foot: sign(d_i·(b − a))).
        return Step::Go(State::V(if before { i } else { j }));
    }
    // b is on the inner side of the edge line: the segment enters Q through e_i unless it leaves the
    // strip first. With the crossing c of the two lines and q_{i+1} − c = μ d_i,
    // orient(a, b, q_{i+1}) = −μ·cross(d_i, b − a) and cross(d_i, b − a) > 0 for an inward segment.
    if before {
        match K::orient(a, b, qi) {
            Orientation::CounterClockwise => Step::Enter(i, Near::Edge(i)),
            Orientation::Collinear => through_vertex::<K>(r, i, b, steps),
            Orientation::Clockwise => Step::Go(State::V(i)),
        }
    } else if after {
        match K::orient(a, b, qj) {
            Orientation::Clockwise => Step::Enter(i, Near::Edge(i)),
            Orientation::Collinear => through_vertex::<K>(r, j, b, steps),
            Orientation::CounterClockwise => Step::Go(State::V(j)),
        }
    } else {
        Step::Enter(i, Near::Edge(i))
    }
}

/// The current point is in `Q` (on the line `a b`, at or after `a`), and the segment's exit edge is
/// at or after edge `j`: scan forward while `q_{j+1}` is strictly right of the line, then decide `b`
/// against the exit edge. Returns the step and the exit edge.
fn from_inside<K: Kernel>(
    r: &Ring<'_>,
    mut j: usize,
    a: DVec2,
    b: DVec2,
    steps: &mut u64,
    budget: u64,
) -> (Step, usize) {
    let m = r.q.len();
    let mut scanned = 0;
    while scanned < m
        && *steps <= budget
        && K::orient(a, b, r.at(r.nx(j))) == Orientation::Clockwise
    {
        j = r.nx(j);
        scanned += 1;
        *steps += 1;
    }
    let (qj, qn) = (r.at(j), r.at(r.nx(j)));
    let step = match K::orient(qj, qn, b) {
        Orientation::CounterClockwise => Step::Done(Near::Inside),
        Orientation::Collinear => Step::Done(if b == qj {
            Near::OnVertex(j)
        } else if b == qn {
            Near::OnVertex(r.nx(j))
        } else {
            Near::OnEdge(j)
        }),
        // The segment leaves Q through e_j (at q_{j+1} when the line passes through it: the edge
        // region's tests then move on to V(j+1)).
        Orientation::Clockwise => Step::Go(State::E(j)),
    };
    (step, j)
}

/// The segment passes through (or starts at) vertex `q_i` heading for `b`: decide locally from the
/// two edges at `q_i`, following the boundary when the segment runs along an edge.
fn through_vertex<K: Kernel>(r: &Ring<'_>, mut i: usize, b: DVec2, steps: &mut u64) -> Step {
    let m = r.q.len();
    for _ in 0..m {
        *steps += 1;
        let (qi, qn, qp) = (r.at(i), r.at(r.nx(i)), r.at(r.pv(i)));
        if b == qi {
            return Step::Done(Near::OnVertex(i));
        }
        if in_vertex_region::<K>(r.q, i, b) {
            return Step::Done(Near::Vertex(i));
        }
        let l1 = K::orient(qi, qn, b);
        let l0 = K::orient(qp, qi, b);
        if l1 == Orientation::CounterClockwise && l0 == Orientation::CounterClockwise {
            // Into the interior at q_i: the scan for the exit starts at edge i (q_{i+1} is strictly
            // right of the line).
            return Step::Enter(i, Near::Vertex(i));
        }
        let fwd = K::dot_sign(qi, b, qi, qn); // (b − q_i)·d_i
        if l1 == Orientation::Collinear && fwd == Sign::Positive {
            // Along e_i.
            match K::dot_sign(qn, b, qi, qn) {
                Sign::Negative => return Step::Done(Near::OnEdge(i)),
                Sign::Zero => return Step::Done(Near::OnVertex(r.nx(i))),
                Sign::Positive => {
                    i = r.nx(i);
                    continue;
                }
            }
        }
        if l0 == Orientation::Collinear && K::dot_sign(qi, b, qp, qi) == Sign::Negative {
            // Backwards along e_{i−1}.
            match K::dot_sign(qp, b, qp, qi) {
                Sign::Positive => return Step::Done(Near::OnEdge(r.pv(i))),
                Sign::Zero => return Step::Done(Near::OnVertex(r.pv(i))),
                Sign::Negative => {
                    i = r.pv(i);
                    continue;
                }
            }
        }
        // Outside and not in V(i): just past q_i the segment is in E(i) when it heads along d_i,
        // else in E(i−1).
        return Step::Go(State::E(if fwd == Sign::Positive { i } else { r.pv(i) }));
    }
    Step::Go(State::E(i))
}

/// The segment starts on the open edge `e_i` and heads for `b`.
fn leave_edge<K: Kernel>(r: &Ring<'_>, i: usize, b: DVec2, steps: &mut u64) -> Step {
    let j = r.nx(i);
    let (qi, qj) = (r.at(i), r.at(j));
    match K::orient(qi, qj, b) {
        // Inward: the scan starts at edge i (q_{i+1} is strictly right of the line).
        Orientation::CounterClockwise => Step::Enter(i, Near::Edge(i)),
        Orientation::Clockwise => Step::Go(State::E(i)),
        Orientation::Collinear => {
            let bf = K::dot_sign(qi, b, qi, qj);
            let af = K::dot_sign(qj, b, qi, qj);
            if bf == Sign::Zero {
                Step::Done(Near::OnVertex(i))
            } else if af == Sign::Zero {
                Step::Done(Near::OnVertex(j))
            } else if bf == Sign::Positive && af == Sign::Negative {
                Step::Done(Near::OnEdge(i))
            } else if af == Sign::Positive {
                through_vertex::<K>(r, j, b, steps)
            } else {
                through_vertex::<K>(r, i, b, steps)
            }
        }
    }
}
