//! σ of two chains separated by a line (Amato 1992, section 3, Theorem 2):
//! `σ = min{σ(P_v, Q_v), σ(P_e, Q_v), σ(P_v, Q_e)}` from one CVV and two CVE searches.

use core::cmp::Ordering;

use glam::DVec2;
use monotone_minima::row_minima_by;
use polydist_polygon::Feature;
use polydist_predicates::{Dist2, Kernel, Sign};

use crate::chain::{EnvEdge, Frames, Prepared};
use crate::chain::{OnLine, Validated, validate_across_hull_edge, validate_touching};
use crate::construct::{vertex_edge, vertex_vertex};
use crate::cve::{CveMatrix, EdgeEntry, compare_edge_entries};
use crate::cvv::CvvMatrix;
use crate::envelope::{Closing, prepare_closing};
use crate::error::{Chain, SeparationError};
use crate::monotone::sweep_envelopes;
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
    /// The vertex `v` (caller `j`) against the whole edge carrying envelope edge `e` of the other
    /// chain (`P`'s when `p_side`).
    pub(crate) fn on_edge(v: V, j: usize, e: &EnvEdge<V>, p_side: bool) -> Cand<V> {
        Cand::Ve {
            v,
            j,
            a: e.a,
            ia: e.ia,
            b: e.b,
            ib: e.ib,
            edge: e.caller,
            p_side,
        }
    }

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
    let col = m.column(j);
    Some(Cand::on_edge(
        col.pt,
        col.idx,
        m.real_edge(m.row_edge(i)),
        p_side,
    ))
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
    separation_of_chains_with::<K>(p, q, a, b, ChainMethod::Matrices)
}

/// How section 3 finds σ once Lemma 2's envelopes are built.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ChainMethod {
    /// The envelope sweep first (our addition, exact): the envelopes are monotone along the line,
    /// so the windowed scan of the monotone sweep answers on them within a budget of
    /// `96N + 1024` candidates, thinned by depth across the line; the matrices when the budget
    /// runs out (docs/algorithms/separation.md, "The envelope sweep").
    /// [`SeparationStats::sweep_candidates`] counts its candidates when it answered.
    #[default]
    Auto,
    /// CVV and CVE by SMAWK always: the paper's steps alone ([`separation_of_chains`]).
    Matrices,
}

/// [`separation_of_chains`] with the method chosen: [`ChainMethod::Matrices`] is
/// [`separation_of_chains`]; [`ChainMethod::Auto`] tries the envelope sweep first, whose answer is
/// the same exact minimum (possibly another pair at the same distance), usually several times
/// faster.
///
/// # Complexity
/// `O(n_p + n_q)` either way: the envelopes, at most `96(n_p + n_q) + 1024` candidates of the
/// sweep, then possibly the matrices.
///
/// # Errors
/// As [`separation_of_chains`].
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_predicates::Robust;
/// use polydist_separation::{ChainMethod, separation_of_chains_with};
///
/// // A hook right of the y-axis, whose tip (3, 1) is hidden from the line, and a point left of it.
/// let hook = [DVec2::new(3.0, 1.0), DVec2::new(4.0, -1.0), DVec2::new(1.0, 0.0), DVec2::new(1.0, 2.0)];
/// let point = [DVec2::new(-1.0, 1.0)];
/// for method in [ChainMethod::Auto, ChainMethod::Matrices] {
///     let s = separation_of_chains_with::<Robust>(&hook, &point, DVec2::ZERO, DVec2::Y, method)?;
///     assert_eq!(s.pair.distance, 2.0);
///     assert_eq!(s.pair.point_p, DVec2::new(1.0, 1.0));
/// }
/// # Ok::<(), polydist_separation::SeparationError>(())
/// ```
pub fn separation_of_chains_with<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
    method: ChainMethod,
) -> Result<ChainSeparation, SeparationError> {
    let (pair, stats, _) = chains::<K>(p, q, (a, b), method, f64::INFINITY)?;
    Ok(ChainSeparation { pair, stats })
}

/// [`separation_of_chains_with`] for the crate: the pair, the counts, and whether the envelope
/// sweep answered. With a finite `cut` (the square of a distance known elsewhere) the sweep skips
/// candidates bounded strictly above it: the pair is then the nearest when that beats the cut, and
/// some pair of the chains otherwise.
pub(crate) fn chains<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    (a, b): (DVec2, DVec2),
    method: ChainMethod,
    cut: f64,
) -> Result<(ClosestPair, SeparationStats, bool), SeparationError> {
    let validated = validate_touching::<K>(p, q, a, b)?;
    chains_validated::<K>(p, q, validated, method, cut, Closing::AtLeastExtent)
}

/// [`chains`] for the boundaries of two polygons across the line of a hull edge that has the other
/// hull strictly beyond it (the disjoint-hull route): the sides are not checked vertex by vertex
/// under an exact kernel ([`validate_across_hull_edge`]). Each closed chain comes rotated so that
/// its closing edge is its edge of least extent along the line (`envelope::least_extent_edge`), and
/// Lemma 2's envelope closes it there without searching again.
pub(crate) fn chains_across_hull_edge<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    (a, b): (DVec2, DVec2),
    method: ChainMethod,
) -> Result<(ClosestPair, SeparationStats, bool), SeparationError> {
    let validated = validate_across_hull_edge::<K>(p, q, a, b)?;
    chains_validated::<K>(p, q, validated, method, f64::INFINITY, Closing::AsGiven)
}

/// [`chains`] after the validation.
fn chains_validated<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    Validated { frames, on_line }: Validated,
    method: ChainMethod,
    cut: f64,
    closing: Closing,
) -> Result<(ClosestPair, SeparationStats, bool), SeparationError> {
    let on_line = if on_line.both() {
        on_the_line::<K>(p, q, &on_line)
    } else {
        None
    };
    let Some(frames) = frames else {
        // Every vertex on the line: the chains lie on it, and the on-line pair is the answer.
        let c = on_line.ok_or(SeparationError::Inconsistent)?;
        return Ok((build::<K>(c), SeparationStats::default(), false));
    };
    let pp = prepare_closing::<K, _>(p, frames.p, Chain::P, closing)?;
    let qq = prepare_closing::<K, _>(q, frames.q, Chain::Q, closing)?;
    if method == ChainMethod::Matrices {
        let (best, stats) = solve_prepared::<K, DVec2>(pp, qq, frames, on_line)?;
        return Ok((build::<K>(best), stats, false));
    }
    let Some((swept, tried)) = sweep_envelopes::<K>(&pp, &qq, frames, cut) else {
        let (best, stats) = solve_prepared::<K, DVec2>(pp, qq, frames, on_line)?;
        return Ok((build::<K>(best), stats, false));
    };
    let best = match on_line {
        Some(c) if DVec2::cmp_dist2::<K>(c.dist(), swept.dist()) == Ordering::Less => c,
        _ => swept,
    };
    let stats = SeparationStats {
        sweep_candidates: tried,
        ..SeparationStats::default()
    };
    Ok((build::<K>(best), stats, true))
}

/// Section 3 on two validated chains (of input points, or of sites: runs clipped to the line's
/// half-planes, docs/algorithms/separator.md, "Step G") whose Lemma 2 envelopes are prepared
/// (those of clipped chains may have gaps): CVV and CVE both ways, and the best of these and
/// `extra` (the on-line pair). The candidate is in the chains' own vertex and edge indices.
/// `O(n_p + n_q)`.
pub(crate) fn solve_prepared<K: Kernel, V: Vertex>(
    pp: Prepared<V>,
    qq: Prepared<V>,
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
    // The matrices take the envelope edges, their ranges made symbolic (`Prepared::env_edge`).
    let m_pq = CveMatrix::<K, V>::build(frames.p, frames.q, pp.env_edges(), p_pieces, qa);
    let pe_qv = cve(&m_pq, true);
    let m_qp = CveMatrix::<K, V>::build(frames.q, frames.p, qq.env_edges(), q_pieces, pa);
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

#[cfg(test)]
mod tests {
    //! The envelope sweep ([`ChainMethod::Auto`]) against the matrices and the exact scan, with and
    //! without a cut.
    use super::*;
    use crate::brute::scan;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::{Exact, Fast, Robust};

    /// The exact squared distance of a reported pair of the chains `p`, `q`.
    fn pair_dist(p: &[DVec2], q: &[DVec2], pair: &ClosestPair) -> Dist2 {
        let point = |c: &[DVec2], f: Feature, other: DVec2| match f {
            Feature::Vertex(i) => Dist2::PointPoint(other, c[i]),
            Feature::Edge(i) => Dist2::PointSegment(other, c[i], c[i + 1]),
        };
        match (pair.feature_p, pair.feature_q) {
            (Feature::Vertex(i), f) => point(q, f, p[i]),
            (f, Feature::Vertex(j)) => point(p, f, q[j]),
            _ => panic!("a pair has a vertex"),
        }
    }

    /// A random simple polygon of integer coordinates (a spiky star, a 2-opt polygon, a spiral or
    /// a comb: far from monotone along any line), a sub-chain of it or the closed boundary.
    fn shape(rng: &mut SplitMix64) -> Vec<DVec2> {
        let n = 4 + rng.index(40);
        let raw = match rng.below(4) {
            0 => polydist_oracle::star(rng, n, 1 + n / 4),
            1 => polydist_oracle::two_opt(rng, n.min(30)),
            2 => polydist_oracle::spiral(3 + rng.below(5) as u32, 1 + rng.below(3) as u32),
            _ => polydist_oracle::comb(1 + n / 6, 1 + rng.below(3) as u32, 1),
        };
        let mut v: Vec<DVec2> = raw.iter().map(|x| (*x * 65_536.0).round()).collect();
        v.dedup();
        if v.len() > 2 && v[0] == v[v.len() - 1] {
            v.pop();
        }
        if rng.coin() {
            let (s, len) = (rng.index(v.len()), 1 + rng.index(v.len()));
            (0..len).map(|k| v[(s + k) % v.len()]).collect()
        } else {
            v.push(v[0]);
            v
        }
    }

    /// Moves `c` so that its least `x` is `at` (integers: exact).
    fn to_x(c: &[DVec2], at: f64, dy: f64) -> Vec<DVec2> {
        let m = c.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
        c.iter()
            .map(|v| DVec2::new(v.x - m + at, v.y + dy))
            .collect()
    }

    /// Every answer of the envelope sweep is the exact minimum: on chains right and left of a
    /// line (touching it or not, both at once too, rotated by integer rotations, reversed), with no
    /// cut against the matrices and the exact scan, and with a cut the nearest pair when the scan's
    /// beats it, a pair no nearer otherwise. The sweep must answer most cases (the matrices the
    /// rest); under Fast, nothing panics or loops.
    #[test]
    fn envelope_sweep_is_the_exact_minimum() {
        let mut rng = SplitMix64::new(0xe2e1);
        let (mut swept, mut cut_below, mut cases) = (0, 0, 0);
        for round in 0..3_000 {
            let (p0, q0) = (shape(&mut rng), shape(&mut rng));
            let touch_p = rng.below(3) == 0;
            let touch_q = rng.below(3) == 0;
            let p = to_x(
                &p0,
                if touch_p {
                    0.0
                } else {
                    1.0 + rng.below(9) as f64
                },
                0.0,
            );
            // `Q` left of the line: mirrored, its greatest `x` at 0 or beyond; slid along the line
            // so that touching chains do not meet.
            let shift = rng.range_i64(-3_000, 3_000) as f64;
            let mut q: Vec<DVec2> = to_x(&q0, 0.0, shift)
                .iter()
                .map(|v| DVec2::new(-v.x, v.y))
                .collect();
            if !touch_q {
                let gap = 1.0 + rng.below(9) as f64;
                q.iter_mut().for_each(|v| v.x -= gap);
            }
            if touch_p && touch_q {
                let on = |c: &[DVec2]| c.iter().filter(|v| v.x == 0.0).map(|v| v.y).collect();
                let (a, b): (Vec<f64>, Vec<f64>) = (on(&p), on(&q));
                let (alo, ahi) = (
                    a.iter().copied().fold(f64::INFINITY, f64::min),
                    a.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                );
                if b.iter().any(|&y| y >= alo && y <= ahi) {
                    continue;
                }
            }
            // An integer rotation (scaled by 5 or 1) of everything, the line with it.
            let (c, s) = [(1.0, 0.0), (0.0, 1.0), (3.0, 4.0), (-4.0, 3.0)][rng.index(4)];
            let rot = |v: DVec2| DVec2::new(c * v.x - s * v.y, s * v.x + c * v.y);
            let (mut p, mut q): (Vec<DVec2>, Vec<DVec2>) = (
                p.into_iter().map(rot).collect(),
                q.into_iter().map(rot).collect(),
            );
            if rng.coin() {
                p.reverse();
            }
            if rng.coin() {
                q.reverse();
            }
            let (a, b) = (rot(DVec2::ZERO), rot(DVec2::new(0.0, 1.0)));
            let (a, b) = if rng.coin() { (a, b) } else { (b, a) };
            if round % 10 == 0 {
                // Fast: any answer or a typed error, never a panic or a loop.
                let _ = chains::<Fast>(&p, &q, (a, b), ChainMethod::Auto, f64::INFINITY);
            }
            // Rounding may have made a 2-opt polygon non-simple: both methods then say so.
            let auto = chains::<Robust>(&p, &q, (a, b), ChainMethod::Auto, f64::INFINITY);
            let matrices = chains::<Robust>(&p, &q, (a, b), ChainMethod::Matrices, f64::INFINITY);
            let (Ok((got, stats, was_swept)), Ok((m, _, _))) = (auto, matrices) else {
                continue;
            };
            cases += 1;
            swept += usize::from(was_swept);
            assert_eq!(was_swept, stats.sweep_candidates > 0, "round {round}");
            let want = scan::<Exact>(&p, &q, false);
            let d = |pair: &ClosestPair| pair_dist(&p, &q, pair);
            assert_eq!(
                Exact::cmp_dist2(d(&got), d(&want)),
                Ordering::Equal,
                "round {round}: {p:?} {q:?} {a:?} {b:?}"
            );
            assert_eq!(Exact::cmp_dist2(d(&m), d(&want)), Ordering::Equal);
            assert!((got.distance - want.distance).abs() <= 4.0 * f64::EPSILON * want.distance);
            // A cut at a multiple of 1/2 (exact squares).
            let cut = rng.range_i64(1, 400) as f64 * 0.5;
            let (below, _, _) = chains::<Robust>(&p, &q, (a, b), ChainMethod::Auto, cut * cut)
                .unwrap_or_else(|e| panic!("round {round}: {e}"));
            let beats = Exact::cmp_dist2(
                d(&want),
                Dist2::PointPoint(DVec2::ZERO, DVec2::new(cut, 0.0)),
            ) == Ordering::Less;
            let order = Exact::cmp_dist2(d(&below), d(&want));
            if beats {
                cut_below += 1;
                assert_eq!(order, Ordering::Equal, "round {round}: cut {cut}");
            } else {
                assert_ne!(order, Ordering::Less, "round {round}: cut {cut}");
            }
        }
        eprintln!("envelope sweep: {cases} cases, {swept} swept, {cut_below} below the cut");
        assert!(
            cases > 2_000 && swept * 10 > cases * 8 && cut_below > 300,
            "{cases} cases, {swept} swept, {cut_below} below the cut"
        );
    }
}
