//! CVE of two chains separated by a line and monotone along it (Amato 1992, section 3): the
//! edges of one chain cut into pieces with constant `h()`, `l()` and `α ≥ 90°`, the regions `R()` of
//! pieces and of the other chain's vertices, and the tagged matrix `M` searched with SMAWK.

use core::cell::{Cell, OnceCell};
use core::cmp::Ordering;
use core::marker::PhantomData;

use glam::DVec2;
use monotone_minima::Matrix;
use polydist_predicates::{Dist2, Kernel, Sign};

use crate::chain::{EnvEdge, validate_touching};
use crate::clipped::EdgePart;
use crate::envelope::prepare;
use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::param::{Affine, Edge, EdgePoint, Param};
use crate::pieces::{Piece, pieces};
use crate::site::Vertex;
use crate::wedge::{Apex, apexes};

/// An entry of the CVE matrix: like [`MatrixEntry`](crate::MatrixEntry), with the distance from
/// the column vertex `q` to the row's piece of an edge.
///
/// Entries of one row (one piece) are ordered by the distance to the piece itself, its ends kept
/// symbolic ([`EdgePart`]): the order SMAWK needs (Lemma 7's matrix). Entries of different rows,
/// compared only to pick the least row minimum, are ordered by the distance to the whole edge: a
/// true distance between the chains, never below σ, and at most the piece's distance, so it equals
/// σ for the row whose piece realizes σ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EdgeEntry<V = DVec2> {
    /// `d(q, piece)`.
    Dist {
        /// The column vertex.
        q: V,
        /// The row's piece.
        piece: EdgePart<V>,
    },
    /// `B + n_q − j`, holding `n_q − j`.
    Penalty(usize),
    /// Not a candidate.
    Infinity,
}

/// The exact order of [`EdgeEntry`] under `K`: distances before penalties before infinities;
/// distances to one piece by [`EdgePart`]'s exact comparison (signs of degree ≤ 16), distances to
/// different pieces by `cmp_dist2` of the whole edges (degree ≤ 6); penalties by their integer.
#[must_use]
pub fn compare_edge_entries<K: Kernel, V: Vertex>(x: &EdgeEntry<V>, y: &EdgeEntry<V>) -> Ordering {
    use EdgeEntry::{Dist, Penalty};
    match (x, y) {
        (Dist { q: q1, piece: p1 }, Dist { q: q2, piece: p2 }) => {
            if p1 == p2 {
                p1.cmp_dist::<K>(*q1, *q2)
            } else {
                V::cmp_dist2::<K>(
                    Dist2::PointSegment(*q1, p1.a, p1.b),
                    Dist2::PointSegment(*q2, p2.a, p2.b),
                )
            }
        }
        (Dist { .. }, _) => Ordering::Less,
        (_, Dist { .. }) => Ordering::Greater,
        (Penalty(s), Penalty(t)) => s.cmp(t),
        (Penalty(_), _) => Ordering::Less,
        (_, Penalty(_)) => Ordering::Greater,
        _ => Ordering::Equal,
    }
}

/// A region `R()` bounded by heights: `up`/`down` the points `u^±` (`None`: the row's own end).
#[derive(Clone, Copy, Debug)]
struct Band<T> {
    up: Option<T>,
    down: Option<T>,
}

impl<T> Default for Band<T> {
    fn default() -> Self {
        Band {
            up: None,
            down: None,
        }
    }
}

/// Where the upper cap of a pointer scan lies.
#[derive(Clone, Copy, Debug)]
enum Cap<V> {
    Open,
    At(EdgePoint<V>),
    Height(V),
}

/// The CVE matrix for the edges of one chain (rows: pieces in height order) against the vertices
/// of the other (columns: the vertices left after Lemmas 2–3, in height order).
#[derive(Clone, Debug)]
pub struct CveMatrix<K: Kernel, V: Vertex = DVec2> {
    fp: Frame,
    fq: Frame,
    /// The envelope edges of the row chain in height order, the gaps of a clipped chain left out:
    /// the pieces' `edge` indexes this list.
    edges: Vec<EnvEdge<V>>,
    /// Each edge's position among the envelope's intervals (`pos[k] + 1 == pos[k + 1]` unless a
    /// gap lies between them).
    pos: Vec<usize>,
    pieces: Vec<Piece<V>>,
    cols: Vec<Apex<V>>,
    piece_bands: Vec<Band<V>>,
    col_bands: Vec<Band<EdgePoint<V>>>,
    lookups: Cell<usize>,
    kernel: PhantomData<K>,
}

impl<K: Kernel> CveMatrix<K> {
    /// Validates the input and builds the matrix for the edges of `p` (rows) against the vertices
    /// of `q` (columns), as [`separation_of_chains`](crate::separation_of_chains) does. `O(n_p + n_q)`.
    ///
    /// # Errors
    /// See [`separation_of_chains`](crate::separation_of_chains).
    pub fn new(p: &[DVec2], q: &[DVec2], a: DVec2, b: DVec2) -> Result<Self, SeparationError> {
        // Both chains may touch the line, as in `separation_of_chains`; not both lie on it.
        let frames = validate_touching::<K>(p, q, a, b)?
            .frames
            .ok_or(SeparationError::BothChainsTouchLine)?;
        let pp = prepare::<K, _>(p, frames.p, Chain::P)?;
        let qq = prepare::<K, _>(q, frames.q, Chain::Q)?;
        let cols = apexes::<K, _>(&qq, frames.q);
        let ps = pieces::<K, _>(&pp, frames.p);
        Ok(Self::build(frames.p, frames.q, pp.env_edges(), ps, cols))
    }
}

impl<K: Kernel, V: Vertex> CveMatrix<K, V> {
    pub(crate) fn build(
        fp: Frame,
        fq: Frame,
        edges: Vec<Option<EnvEdge<V>>>,
        mut pieces: Vec<Piece<V>>,
        cols: Vec<Apex<V>>,
    ) -> Self {
        // Pieces lie on edges only, never in a gap: renumbered to the edges without the gaps.
        let mut slot = vec![usize::MAX; edges.len()];
        let (mut dense, mut pos) = (
            Vec::with_capacity(edges.len()),
            Vec::with_capacity(edges.len()),
        );
        for (k, e) in edges.into_iter().enumerate() {
            if let Some(e) = e {
                slot[k] = dense.len();
                dense.push(e);
                pos.push(k);
            }
        }
        pieces.retain_mut(|pc| {
            pc.edge = slot.get(pc.edge).copied().unwrap_or(usize::MAX);
            pc.edge != usize::MAX
        });
        let mut m = CveMatrix {
            fp,
            fq,
            edges: dense,
            pos,
            pieces,
            cols,
            piece_bands: Vec::new(),
            col_bands: Vec::new(),
            lookups: Cell::new(0),
            kernel: PhantomData,
        };
        m.piece_bands = m.piece_regions();
        m.col_bands = m.column_regions();
        m
    }

    /// The edge of row `i`, as its index among the envelope's edges (the gaps of a clipped chain
    /// left out).
    pub(crate) fn row_edge(&self, i: usize) -> usize {
        self.pieces[i].edge
    }

    /// The envelope edge `k` of the row chain (between its heights `k` and `k + 1`).
    pub(crate) fn real_edge(&self, k: usize) -> &EnvEdge<V> {
        &self.edges[k]
    }

    /// The column apex `j`.
    pub(crate) fn column(&self, j: usize) -> &Apex<V> {
        &self.cols[j]
    }

    /// How many entries have been looked up.
    #[must_use]
    pub fn lookups(&self) -> usize {
        self.lookups.get()
    }

    fn edge(&self, k: usize) -> Edge<V> {
        Edge {
            a: self.edges[k].a,
            b: self.edges[k].b,
        }
    }

    /// `sign(g)` at a point of this chain.
    fn eval(&self, g: &Affine<V>, x: &EdgePoint<V>) -> Sign {
        self.edge(x.edge).eval_within::<K>(g, &x.param)
    }

    /// `H(x)` against `H(t)` for a point `x` of this chain and an input point `t`.
    fn cmp_height_with(&self, x: &EdgePoint<V>, t: V) -> Ordering {
        self.eval(&self.fp.height_minus(t), x).to_ordering()
    }

    fn is_end(&self, x: &EdgePoint<V>, at_end: bool) -> bool {
        self.edge(x.edge).is_end::<K>(&x.param, at_end)
    }

    /// `true` when `x` is the top (`at_top`) or bottom of its edge's part on the envelope.
    fn at_range_end(&self, x: &EdgePoint<V>, at_top: bool) -> bool {
        let r = &self.edges[x.edge];
        let end = if at_top { r.hi } else { r.lo };
        self.edge(x.edge).cmp::<K>(&x.param, &end) == Ordering::Equal
    }

    /// Compares the heights of two points of this chain. Heights increase along the rows' edges
    /// (within their parts on the envelope); the top of one edge's part and the bottom of the next
    /// are at the same height (the same vertex, or a visible vertex and a point hidden behind it:
    /// a vertex at the end of a run perpendicular to the line, or a shadow point) and compare equal.
    fn cmp_points(&self, x: &EdgePoint<V>, y: &EdgePoint<V>) -> Ordering {
        match x.edge.cmp(&y.edge) {
            Ordering::Equal => self.edge(x.edge).cmp::<K>(&x.param, &y.param),
            Ordering::Less => {
                if x.edge + 1 == y.edge
                    && self.pos[x.edge] + 1 == self.pos[y.edge]
                    && self.at_range_end(x, true)
                    && self.at_range_end(y, false)
                {
                    Ordering::Equal
                } else {
                    Ordering::Less
                }
            }
            Ordering::Greater => self.cmp_points(y, x).reverse(),
        }
    }

    fn bot(&self, pc: &Piece<V>) -> EdgePoint<V> {
        EdgePoint {
            edge: pc.edge,
            param: pc.bot,
        }
    }

    fn top(&self, pc: &Piece<V>) -> EdgePoint<V> {
        EdgePoint {
            edge: pc.edge,
            param: pc.top,
        }
    }

    /// `u` is admissible for the piece: `u ∈ W(pc)` (open wedge with apexes at the piece's ends) and
    /// the piece's top (`up`) or bottom end lies in `W(u)`.
    fn admissible_for_piece(&self, pc: &Piece<V>, u: &Apex<V>, up: bool) -> bool {
        let (fp, fq) = (self.fp, self.fq);
        let (top, bot) = (self.top(pc), self.bot(pc));
        let e = self.edge(pc.edge);
        // When the ray's apex is its own tangent point (the piece reaches the edge's end and the
        // tangent is that end), the ray runs along the edge.
        let below_upper = match pc.hi {
            Some(h) if h == e.b && self.is_end(&top, true) => {
                fp.orient::<K, _>(e.a, e.b, u.pt) == Sign::Positive
            }
            Some(h) => self.eval(&fp.orient_x_first(h, u.pt), &top) == Sign::Positive,
            None => self.eval(&fp.depth_minus(u.pt), &top) == Sign::Positive,
        };
        if !below_upper {
            return false;
        }
        let above_lower = match pc.lo {
            Some(l) if l == e.a && self.is_end(&bot, false) => {
                fp.orient::<K, _>(e.b, e.a, u.pt) == Sign::Negative
            }
            Some(l) => self.eval(&fp.orient_x_first(l, u.pt), &bot) == Sign::Negative,
            None => self.eval(&fp.depth_minus(u.pt), &bot) == Sign::Positive,
        };
        if !above_lower {
            return false;
        }
        let v = if up { top } else { bot };
        let in_upper = match u.hi {
            Some(hu) => self.eval(&fq.orient_x_last(u.pt, hu), &v) == Sign::Positive,
            None => self.eval(&fq.depth_minus(u.pt), &v) == Sign::Negative,
        };
        in_upper
            && match u.lo {
                Some(lu) => self.eval(&fq.orient_x_last(u.pt, lu), &v) == Sign::Negative,
                None => self.eval(&fq.depth_minus(u.pt), &v) == Sign::Negative,
            }
    }

    /// `R(e_i)` for every piece: `u_i^+` the highest column vertex with
    /// `H(v_i^+) ≤ H(u) ≤ H(u_{i+1}^+)`, admissible; `u_i^-` symmetrically. One pointer per scan.
    fn piece_regions(&self) -> Vec<Band<V>> {
        let (ps, us) = (&self.pieces, &self.cols);
        let mut out = vec![Band::default(); ps.len()];
        let mut k = us.len();
        for (i, pc) in ps.iter().enumerate().rev() {
            let top = self.top(pc);
            while k > 0 {
                let u = &us[k - 1];
                if self.cmp_height_with(&top, u.pt) == Ordering::Greater {
                    break;
                }
                if self.admissible_for_piece(pc, u, true) {
                    out[i].up = Some(u.pt);
                    break;
                }
                k -= 1;
            }
            if out[i].up.is_none()
                && k < us.len()
                && self.cmp_height_with(&top, us[k].pt) == Ordering::Equal
            {
                k += 1;
            }
        }
        let mut k = 0;
        for (i, pc) in ps.iter().enumerate() {
            let bot = self.bot(pc);
            while k < us.len() {
                let u = &us[k];
                if self.cmp_height_with(&bot, u.pt) == Ordering::Less {
                    break;
                }
                if self.admissible_for_piece(pc, u, false) {
                    out[i].down = Some(u.pt);
                    break;
                }
                k += 1;
            }
            if out[i].down.is_none()
                && k > 0
                && self.cmp_height_with(&bot, us[k - 1].pt) == Ordering::Equal
            {
                k -= 1;
            }
        }
        out
    }

    /// The highest (`up`) or lowest point of piece `pc` that is admissible for the column vertex
    /// `q`: height between `H(q)` and the cap, in the closed `W(q)`, and `q` in the closed wedge of
    /// the point. Each condition is an affine sign along the edge, so the admissible set is an
    /// interval whose ends are roots; `O(1)` predicates of degree ≤ 6.
    ///
    /// `further` says whether the next piece in the scan's direction (above for `up`) is on the
    /// same edge: only then can a cap on this edge lie beyond the piece.
    fn admissible_end(
        &self,
        pc: &Piece<V>,
        q: &Apex<V>,
        cap: Cap<V>,
        up: bool,
        further: bool,
    ) -> Option<Param<V>> {
        let (fp, fq) = (self.fp, self.fq);
        let e = self.edge(pc.edge);
        let (mut lb, mut ub) = (pc.bot, pc.top);
        // Every condition as g ≥ 0. `W(q)`'s two first: they are the ones that reject (on
        // saw-teeth every rejection of a column's pointer scan is theirs), and a rejection stops at
        // the first condition negative at both ends.
        let hq = fp.height_minus(q.pt);
        let mut conds: [Option<Affine<V>>; 6] = [None; 6];
        conds[0] = Some(match q.hi {
            Some(h) => fq.orient_x_last(q.pt, h),
            None => fq.depth_minus(q.pt).negated(),
        });
        conds[1] = Some(match q.lo {
            Some(l) => fq.orient_x_last(q.pt, l).negated(),
            None => fq.depth_minus(q.pt).negated(),
        });
        conds[2] = Some(if up { hq } else { hq.negated() });
        conds[3] = match cap {
            Cap::Height(t) => {
                let g = fp.height_minus(t);
                Some(if up { g.negated() } else { g })
            }
            _ => None,
        };
        conds[4] = Some(match pc.hi {
            Some(h) => fp.orient_x_first(h, q.pt),
            None => fp.depth_minus(q.pt),
        });
        conds[5] = Some(match pc.lo {
            Some(l) => fp.orient_x_first(l, q.pt).negated(),
            None => fp.depth_minus(q.pt),
        });
        if let Cap::At(c) = cap {
            let bound = if up { &mut ub } else { &mut lb };
            if c.edge == pc.edge {
                // The cap bounds the piece where it lies strictly before the far end; a cap on a
                // further piece of the same edge (an edge is cut into pieces where `h()`, `l()`
                // change) leaves the far end, as a cap on a further edge does. Without a further
                // piece on this edge the cap (a point of some piece, at or beyond this one's near
                // end: the scan skipped the pieces beyond it) lies on this piece. The debug
                // assertion below keeps every answer on its piece (history and counts:
                // docs/algorithms/separation.md, "CVE: regions and matrix").
                let far = if up { pc.top } else { pc.bot };
                let before = if up {
                    Ordering::Less
                } else {
                    Ordering::Greater
                };
                if !further || e.cmp::<K>(&c.param, &far) == before {
                    *bound = c.param;
                }
            } else {
                // The cap is on another edge: it bounds this piece only if it is the piece's
                // far end (then the admissible set is that single point).
                let (near, far) = if up {
                    (self.bot(pc), self.top(pc))
                } else {
                    (self.top(pc), self.bot(pc))
                };
                let beyond = |o: Ordering| {
                    if up {
                        o == Ordering::Greater
                    } else {
                        o == Ordering::Less
                    }
                };
                if beyond(self.cmp_points(&far, &c)) {
                    if self.cmp_points(&near, &c) == Ordering::Equal {
                        *bound = near.param;
                    } else {
                        return None;
                    }
                }
            }
        }
        for g in conds.iter().flatten() {
            let (gb, gt) = e.eval_pair_within::<K>(g, &pc.bot, &pc.top);
            let ok = |s: Sign| s != Sign::Negative;
            match (ok(gb), ok(gt)) {
                (true, true) => {}
                (false, false) => return None,
                (false, true) => {
                    // A zero at the top end is the top itself: no new root.
                    let r = if gt == Sign::Zero {
                        pc.top
                    } else {
                        Param::Root(*g)
                    };
                    if e.cmp::<K>(&r, &lb) == Ordering::Greater {
                        lb = r;
                    }
                }
                (true, false) => {
                    let r = if gb == Sign::Zero {
                        pc.bot
                    } else {
                        Param::Root(*g)
                    };
                    if e.cmp::<K>(&r, &ub) == Ordering::Less {
                        ub = r;
                    }
                }
            }
        }
        if e.cmp::<K>(&lb, &ub) == Ordering::Greater {
            return None;
        }
        let r = if up { ub } else { lb };
        debug_assert!(
            !K::EXACT_DECISIONS
                || (e.cmp::<K>(&r, &pc.bot) != Ordering::Less
                    && e.cmp::<K>(&r, &pc.top) != Ordering::Greater),
            "an admissible point off its piece"
        );
        Some(r)
    }

    /// `R(q_j)` for every column vertex: `u_j^+` the highest admissible point of the pieces between
    /// `H(q_j)` and `H(u_{j+1}^+)`, by one pointer over the pieces moving down (and one moving up
    /// for `u_j^-`); each column stops on at most one piece it does not pass.
    fn column_regions(&self) -> Vec<Band<EdgePoint<V>>> {
        let (ps, qs) = (&self.pieces, &self.cols);
        let mut out = vec![Band::default(); qs.len()];
        let mut k = ps.len();
        let mut cap = Cap::Open;
        for (j, q) in qs.iter().enumerate().rev() {
            while k > 0 {
                let pc = &ps[k - 1];
                let bot = self.bot(pc);
                let above_cap = match cap {
                    Cap::Open => false,
                    Cap::At(c) => self.cmp_points(&bot, &c) == Ordering::Greater,
                    Cap::Height(t) => self.cmp_height_with(&bot, t) == Ordering::Greater,
                };
                if above_cap {
                    k -= 1;
                    continue;
                }
                let further = ps.get(k).is_some_and(|n| n.edge == pc.edge);
                if let Some(t) = self.admissible_end(pc, q, cap, true, further) {
                    out[j].up = Some(EdgePoint {
                        edge: pc.edge,
                        param: t,
                    });
                    break;
                }
                if self.cmp_height_with(&bot, q.pt) == Ordering::Greater {
                    k -= 1;
                } else {
                    break;
                }
            }
            cap = out[j].up.map_or(Cap::Height(q.pt), Cap::At);
        }
        let mut k = 0;
        let mut cap = Cap::Open;
        for (j, q) in qs.iter().enumerate() {
            while k < ps.len() {
                let pc = &ps[k];
                let top = self.top(pc);
                let below_cap = match cap {
                    Cap::Open => false,
                    Cap::At(c) => self.cmp_points(&top, &c) == Ordering::Less,
                    Cap::Height(t) => self.cmp_height_with(&top, t) == Ordering::Less,
                };
                if below_cap {
                    k += 1;
                    continue;
                }
                let further = k > 0 && ps[k - 1].edge == pc.edge;
                if let Some(t) = self.admissible_end(pc, q, cap, false, further) {
                    out[j].down = Some(EdgePoint {
                        edge: pc.edge,
                        param: t,
                    });
                    break;
                }
                if self.cmp_height_with(&top, q.pt) == Ordering::Less {
                    k += 1;
                } else {
                    break;
                }
            }
            cap = out[j].down.map_or(Cap::Height(q.pt), Cap::At);
        }
        out
    }
}

impl<K: Kernel, V: Vertex> Matrix for CveMatrix<K, V> {
    type Entry = EdgeEntry<V>;

    fn rows(&self) -> usize {
        self.pieces.len()
    }

    fn columns(&self) -> usize {
        self.cols.len()
    }

    fn entry(&self, i: usize, j: usize) -> EdgeEntry<V> {
        self.lookups.set(self.lookups.get() + 1);
        let pc = &self.pieces[i];
        let q = self.cols[j].pt;
        let (pb, cb) = (&self.piece_bands[i], &self.col_bands[j]);
        let (bot, top) = (self.bot(pc), self.top(pc));
        // `H(x) − H(q)` at the piece's ends is needed only where a band has no point (at a root
        // end it costs a degree-4 sign): both ends are decided together, on first use, sharing the
        // form's signs at the edge's ends.
        let ends_vs_q = OnceCell::new();
        let vs_q = || {
            *ends_vs_q.get_or_init(|| {
                let (b, t) = self.edge(pc.edge).eval_pair_within::<K>(
                    &self.fp.height_minus(q),
                    &pc.bot,
                    &pc.top,
                );
                (b.to_ordering(), t.to_ordering())
            })
        };
        let q_below = match pb.down {
            Some(u) => self.fq.cmp_height::<K, _>(q, u) == Ordering::Less,
            None => vs_q().0 == Ordering::Greater,
        };
        // `q` below `R(e_i)`, or the piece above `R(q_j)`.
        let penalty = q_below
            || match cb.up {
                Some(c) => self.cmp_points(&bot, &c) == Ordering::Greater,
                None => vs_q().0 == Ordering::Greater,
            };
        if penalty {
            return EdgeEntry::Penalty(self.cols.len() - j);
        }
        let q_above = match pb.up {
            Some(u) => self.fq.cmp_height::<K, _>(q, u) == Ordering::Greater,
            None => vs_q().1 == Ordering::Less,
        };
        // `q` above `R(e_i)`, or the piece below `R(q_j)`.
        let infinite = q_above
            || match cb.down {
                Some(c) => self.cmp_points(&top, &c) == Ordering::Less,
                None => vs_q().1 == Ordering::Less,
            };
        if infinite {
            EdgeEntry::Infinity
        } else {
            let r = &self.edges[pc.edge];
            EdgeEntry::Dist {
                q,
                piece: EdgePart {
                    a: r.a,
                    b: r.b,
                    bot: pc.bot,
                    top: pc.top,
                },
            }
        }
    }
}
