//! σ of two chains separated by a line (Amato 1992, section 3, Theorem 2):
//! `σ = min{σ(P_v, Q_v), σ(P_e, Q_v), σ(P_v, Q_e)}` from one CVV and two CVE searches.

use core::cmp::Ordering;

use glam::DVec2;
use monotone_minima::row_minima_by;
use polydist_polygon::Feature;
use polydist_predicates::{Dist2, Kernel, Sign};

use crate::chain::{Frames, Prepared};
use crate::chain::{OnLine, Validated, validate_touching};
use crate::construct::{vertex_edge, vertex_vertex};
use crate::cve::{CveMatrix, EdgeEntry, compare_edge_entries};
use crate::cvv::CvvMatrix;
use crate::envelope::prepare;
use crate::error::{Chain, SeparationError};
use crate::pieces::pieces;
use crate::result::{ChainSeparation, ClosestPair, SeparationStats};
use crate::site::Vertex;
use crate::wedge::apexes;

/// A candidate pair in caller features, before construction.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Cand<V = DVec2> {
    /// Vertex `p` (caller `i`) and vertex `q` (caller `j`).
    Vv(V, usize, V, usize),
    /// A vertex `v` (caller `j`) of one chain and the edge `(a, b)` of the other, with the caller
    /// indices of `a` and `b` and of the edge; `p_side` says the edge is `P`'s.
    Ve {
        v: V,
        j: usize,
        a: V,
        ia: usize,
        b: V,
        ib: usize,
        edge: usize,
        p_side: bool,
    },
}

impl<V: Vertex> Cand<V> {
    pub(crate) fn dist(&self) -> Dist2<V> {
        match *self {
            Cand::Vv(p, _, q, _) => Dist2::PointPoint(p, q),
            Cand::Ve { v, a, b, .. } => Dist2::PointSegment(v, a, b),
        }
    }
}

/// The best candidate of the CVE search of `m` (the edges of one chain against the vertices of the
/// other).
fn cve<K: Kernel, V: Vertex>(m: &CveMatrix<K, V>, p_side: bool) -> Option<Cand<V>> {
    let minima = row_minima_by(m, compare_edge_entries::<K, V>);
    let mut best: Option<(usize, usize, EdgeEntry<V>)> = None;
    for (i, &j) in minima.iter().enumerate() {
        let e = monotone_minima::Matrix::entry(m, i, j);
        if !matches!(e, EdgeEntry::Dist { .. }) {
            continue;
        }
        if best
            .as_ref()
            .is_none_or(|(_, _, b)| compare_edge_entries::<K, V>(&e, b) == Ordering::Less)
        {
            best = Some((i, j, e));
        }
    }
    let (i, j, _) = best?;
    let e = m.real_edge(m.row_edge(i));
    let col = m.column(j);
    Some(Cand::Ve {
        v: col.pt,
        j: col.idx,
        a: e.a,
        ia: e.ia,
        b: e.b,
        ib: e.ib,
        edge: e.caller,
        p_side,
    })
}

/// The separation `σ(P, Q)` of two simple polygonal chains `p` and `q` separated by the line
/// through `a` and `b`, with a realizing pair of points and their features in the caller's indices
/// (Amato 1992, section 3, Lemma 2 and Theorem 2; SMAWK: Aggarwal, Klawe, Moran, Shor, Wilber 1987).
///
/// Each chain is open (edge `i` joins vertices `i` and `i + 1`) or closed: a polygon boundary
/// `v_0, …, v_{n−1}` is passed as `v_0, …, v_{n−1}, v_0` (at least three distinct vertices); its
/// closing edge is reported as `Edge(n − 1)` and the repeated vertex as `Vertex(0)`. Chains need not
/// be monotone along the line. Repeated consecutive vertices are dropped (reported indices are the
/// first of a repeat).
///
/// Lemma 2 first reduces each chain to its perpendicular-visibility envelope (see
/// [`perpendicular_envelope`](crate::perpendicular_envelope)): the visible vertices and the parts of
/// edges between them, cut at symbolic shadow points where an edge passes behind a visible vertex.
/// Then `σ = min{CVV(P°, Q°), CVE(P°_e, Q°_v), CVE(Q°_e, P°_v)}`: the closest vertex pair by the
/// CVV search, and twice the vertex–edge search: the envelope's edges are cut into pieces on which
/// the tangent points `h()`, `l()` are constant (breakpoints found by the hull scans) and clipped to
/// the arc `α ≥ 90°`, their regions `R()` and those of the other chain's vertices are found by
/// pointer scans, and the tagged matrix `M` is searched with SMAWK. Constructed points (shadow points,
/// breakpoints, arc ends, the points `u^±` on edges) stay symbolic; every decision is the sign of a
/// polynomial of degree ≤ 10 in the input coordinates.
///
/// # Complexity
/// `O(n_p + n_q)` time and predicate calls: the envelope is one walk along each chain, and every
/// step after it is linear too; only the pair of vertices both lying on the line comes from a sort
/// of those vertices, `O(k log k)` for `k` of them (no predicate).
///
/// # Errors
/// [`SeparationError`]: empty chains, invalid coordinates or line, a line that does not separate
/// the chains (a vertex strictly on the wrong side; both chains may touch it, even lie on it),
/// [`SeparationError::NotSimple`] when a chain is found not to be simple (simplicity is the caller's
/// duty: not every violation is detected), and (Fast kernel only) [`SeparationError::Inconsistent`]
/// or `NotSimple` from inconsistent decisions.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::Feature;
/// use polydist_predicates::Robust;
/// use polydist_separation::separation_of_chains;
///
/// // Two zig-zags facing each other across the y-axis.
/// let p = [DVec2::new(1.0, 0.0), DVec2::new(3.0, 1.0), DVec2::new(0.5, 3.0)];
/// let q = [DVec2::new(-2.0, 0.5), DVec2::new(-0.5, 1.5), DVec2::new(-3.0, 3.0)];
/// let s = separation_of_chains::<Robust>(&p, &q, DVec2::ZERO, DVec2::Y)?;
/// // The vertex (-0.5, 1.5) of Q is nearest to the interior of P's edge from (3, 1) to (0.5, 3).
/// assert_eq!((s.pair.feature_p, s.pair.feature_q), (Feature::Edge(1), Feature::Vertex(1)));
/// assert_eq!(s.pair.point_q, DVec2::new(-0.5, 1.5));
///
/// // A closed square right of the line x = 0, against a vertex: the closing edge is Edge(3).
/// let square = [
///     DVec2::new(1.0, 0.0),
///     DVec2::new(3.0, 0.0),
///     DVec2::new(3.0, 2.0),
///     DVec2::new(1.0, 2.0),
///     DVec2::new(1.0, 0.0),
/// ];
/// let s = separation_of_chains::<Robust>(&square, &[DVec2::new(-1.0, 1.0)], DVec2::ZERO, DVec2::Y)?;
/// assert_eq!(s.pair.feature_p, Feature::Edge(3));
/// assert_eq!(s.pair.distance, 2.0);
/// # Ok::<(), polydist_separation::SeparationError>(())
/// ```
pub fn separation_of_chains<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<ChainSeparation, SeparationError> {
    let Validated { frames, on_line } = validate_touching::<K>(p, q, a, b)?;
    let on_line = if on_line.both() {
        on_the_line::<K>(p, q, &on_line)
    } else {
        None
    };
    let Some(frames) = frames else {
        // Every vertex on the line: the chains lie on it, and the on-line pair is the answer.
        let c = on_line.ok_or(SeparationError::Inconsistent)?;
        return Ok(ChainSeparation {
            pair: build::<K>(c),
            stats: SeparationStats::default(),
        });
    };
    let (best, stats) = solve::<K, DVec2>(p, q, frames, on_line)?;
    Ok(ChainSeparation {
        pair: build::<K>(best),
        stats,
    })
}

/// Section 3 on two validated chains (of input points, or of sites: runs clipped to the line's
/// half-planes, docs/algorithms/separator.md, "Step G"): Lemma 2's envelopes, then CVV and CVE both
/// ways, and the best of these and `extra` (the on-line pair). The candidate is in the chains' own
/// vertex and edge indices. `O(n_p + n_q)`.
pub(crate) fn solve<K: Kernel, V: Vertex>(
    p: &[V],
    q: &[V],
    frames: Frames,
    extra: Option<Cand<V>>,
) -> Result<(Cand<V>, SeparationStats), SeparationError> {
    let pp = prepare::<K, _>(p, frames.p, Chain::P)?;
    let qq = prepare::<K, _>(q, frames.q, Chain::Q)?;
    solve_prepared::<K, V>(pp, qq, frames, extra)
}

/// [`solve`] on envelopes already prepared (those of clipped chains may have gaps).
pub(crate) fn solve_prepared<K: Kernel, V: Vertex>(
    mut pp: Prepared<V>,
    mut qq: Prepared<V>,
    frames: Frames,
    extra: Option<Cand<V>>,
) -> Result<(Cand<V>, SeparationStats), SeparationError> {
    let pa = apexes::<K, _>(&pp, frames.p);
    let qa = apexes::<K, _>(&qq, frames.q);
    let cvv = CvvMatrix::<K, V>::from_parts(frames, &pp, &qq, pa.clone(), qa.clone());
    let vv = cvv.best().map(|(i, j)| {
        let (r, c) = cvv.apexes_at(i, j);
        Cand::Vv(r.pt, r.idx, c.pt, c.idx)
    });
    let p_pieces = pieces::<K, _>(&pp, frames.p);
    let q_pieces = pieces::<K, _>(&qq, frames.q);
    let stats_pieces = (p_pieces.len(), q_pieces.len());
    // The matrices take the envelope edges over: nothing else reads them from here on.
    let edges = core::mem::take(&mut pp.edges);
    let m_pq = CveMatrix::<K, V>::build(frames.p, frames.q, edges, p_pieces, qa);
    let pe_qv = cve(&m_pq, true);
    let edges = core::mem::take(&mut qq.edges);
    let m_qp = CveMatrix::<K, V>::build(frames.q, frames.p, edges, q_pieces, pa);
    let qe_pv = cve(&m_qp, false);
    let mut best: Option<Cand<V>> = None;
    for c in [vv, pe_qv, qe_pv, extra].into_iter().flatten() {
        if best.is_none_or(|b| V::cmp_dist2::<K>(c.dist(), b.dist()) == Ordering::Less) {
            best = Some(c);
        }
    }
    let best = best.ok_or(SeparationError::Inconsistent)?;
    Ok((
        best,
        SeparationStats {
            cvv: cvv.stats(),
            pieces_p: stats_pieces.0,
            pieces_q: stats_pieces.1,
            cve_entries_evaluated: m_pq.lookups() + m_qp.lookups(),
            ..SeparationStats::default()
        },
    ))
}

/// The nearest pair of a vertex of `P` and a vertex of `Q` both on the line through `a`, `b`: the
/// pairs section 3's wedges cannot hold when both chains touch the line (docs/algorithms/
/// separation.md, "Lines touched by both chains"). Points of one line are ordered along it as
/// their coordinates are lexicographically (a total order on `f64`, no predicate), and the nearest
/// pair of two sets of points of a line is adjacent in that order; two edges lying on the line are
/// disjoint segments, nearest at their ends, so vertices suffice. `O(k log k)` for the `k` vertices
/// on the line, which the validation listed.
fn on_the_line<K: Kernel>(p: &[DVec2], q: &[DVec2], on_line: &OnLine) -> Option<Cand> {
    let mut all = Vec::with_capacity(on_line.p.len() + on_line.q.len());
    for (c, idx, side) in [(p, &on_line.p, true), (q, &on_line.q, false)] {
        // The repeated last vertex of a closed chain is its vertex 0, listed already.
        let closed = c.len() > 1 && c[0] == c[c.len() - 1];
        all.extend(
            idx.iter()
                .filter(|&&i| !(closed && i == c.len() - 1))
                .map(|&i| (c[i], i, side)),
        );
    }
    // `+ 0.0` turns `-0.0` into `0.0`, which `total_cmp` would otherwise put first.
    all.sort_unstable_by(|x, y| {
        (x.0.x + 0.0)
            .total_cmp(&(y.0.x + 0.0))
            .then((x.0.y + 0.0).total_cmp(&(y.0.y + 0.0)))
    });
    nearest_adjacent::<K, DVec2>(&all)
}

/// The nearest pair of a `P` point and a `Q` point among points of one line sorted along it, each
/// with its index and whether it is `P`'s: the nearest such pair is adjacent in that order (the
/// first of equally near ones). `O(k)` exact distance comparisons.
pub(crate) fn nearest_adjacent<K: Kernel, V: Vertex>(
    sorted: &[(V, usize, bool)],
) -> Option<Cand<V>> {
    let mut best: Option<Cand<V>> = None;
    for w in sorted.windows(2) {
        let (x, y) = (w[0], w[1]);
        if x.2 == y.2 {
            continue;
        }
        let (u, v) = if x.2 { (x, y) } else { (y, x) };
        let c = Cand::Vv(u.0, u.1, v.0, v.1);
        if best.is_none_or(|b| V::cmp_dist2::<K>(c.dist(), b.dist()) == Ordering::Less) {
            best = Some(c);
        }
    }
    best
}

/// The realizing points and caller features of a candidate.
pub(crate) fn build<K: Kernel>(c: Cand) -> ClosestPair {
    match c {
        Cand::Vv(p, i, q, j) => vertex_vertex(p, q, Feature::Vertex(i), Feature::Vertex(j)),
        Cand::Ve {
            v,
            j,
            a,
            ia,
            b,
            ib,
            edge,
            p_side,
        } => {
            let (near, fe) = if K::dot_sign(a, v, a, b) != Sign::Positive {
                (Some(a), Feature::Vertex(ia))
            } else if K::dot_sign(b, v, b, a) != Sign::Positive {
                (Some(b), Feature::Vertex(ib))
            } else {
                (None, Feature::Edge(edge))
            };
            let (squared, distance, foot) = match near {
                Some(x) => {
                    let r = vertex_vertex(v, x, fe, fe);
                    (r.squared_distance, r.distance, x)
                }
                None => vertex_edge(v, a, b),
            };
            let fv = Feature::Vertex(j);
            let (point_p, point_q, feature_p, feature_q) = if p_side {
                (foot, v, fe, fv)
            } else {
                (v, foot, fv, fe)
            };
            ClosestPair {
                distance,
                squared_distance: squared,
                point_p,
                point_q,
                feature_p,
                feature_q,
            }
        }
    }
}
