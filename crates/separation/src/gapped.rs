//! Section 3 on gapped chains (Step G, docs/algorithms/separator.md): a subproblem whose subchains
//! cross its line many times, each clipped to its half-plane. A subchain becomes its *runs* (the
//! maximal stretches of vertices not strictly on its wrong side), each extended along its crossing
//! edges to the symbolic clip points where they meet the line; the runs are not joined (no fake
//! links along the line), so the chain has gaps. Section 3 then runs once on the two gapped chains,
//! its predicates deciding at clip points through [`polydist_predicates::sign_at`].
//!
//! What comes back is re-expressed in the subchains' own vertices and edges: a pair with a clip
//! point is replaced by the vertex–edge pairs of the crossing edge it lies on, whose distance is no
//! larger and is still a distance between the two polygons (the clip point is a point of that
//! edge). The true nearest pair of a subproblem never needs a clip point (an optimal pair is a
//! vertex and a point of the other boundary whose foot or vertex realizes it; a clip point is
//! neither), so the subproblem's answer is unchanged where it matters, and never below `σ`.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Sign, Site};

use crate::brute::{boxes_farther_than, farther_from_line_than};
use crate::chain::Frames;
use crate::envelope::prepare_runs;
use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::sigma::{Cand, nearest_adjacent, solve_prepared};

/// Where a site of a gapped chain comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Origin {
    /// The subchain's vertex.
    Vertex(usize),
    /// The clip point on the subchain's edge from this vertex to the next.
    Clip(usize),
}

/// A subchain clipped to one closed half-plane of a line: its sites (input vertices and clip
/// points), the runs as inclusive position ranges, and each site's origin.
#[derive(Clone, Debug, Default)]
pub(crate) struct Gapped {
    pub(crate) sites: Vec<Site>,
    pub(crate) runs: Vec<(usize, usize)>,
    pub(crate) origin: Vec<Origin>,
}

impl Gapped {
    /// The subchain's vertices `lo..=hi` whose edges hold run `r` (a clip point's edge counts whole,
    /// its end on the wrong side included).
    fn vertex_span(&self, (s, t): (usize, usize)) -> (usize, usize) {
        let lo = match self.origin[s] {
            Origin::Vertex(k) | Origin::Clip(k) => k,
        };
        let hi = match self.origin[t] {
            Origin::Vertex(k) => k,
            Origin::Clip(e) => e + 1,
        };
        (lo, hi)
    }

    /// Keeps the runs whose vertex spans ([`Gapped::vertex_span`]) `keep` accepts, renumbering the
    /// sites. `O(sites)`.
    fn retain_runs(&mut self, mut keep: impl FnMut((usize, usize)) -> bool) {
        let mut out = Gapped::default();
        for &(s, t) in &self.runs {
            if keep(self.vertex_span((s, t))) {
                let start = out.sites.len();
                out.sites.extend_from_slice(&self.sites[s..=t]);
                out.origin.extend_from_slice(&self.origin[s..=t]);
                out.runs.push((start, out.sites.len() - 1));
            }
        }
        *self = out;
    }

    /// The bounding box of the vertices spanned by the runs (every point of the clipped chain lies
    /// in it), `None` without runs.
    fn bbox(&self, chain: &[DVec2]) -> Option<(DVec2, DVec2)> {
        self.runs
            .iter()
            .map(|&r| span_box(chain, self.vertex_span(r)))
            .reduce(|(lo, hi), (l, h)| (lo.min(l), hi.max(h)))
    }

    /// The subchain's edge that the edge from site `k` to site `k + 1` (of one run) lies on.
    fn edge_origin(&self, k: usize) -> usize {
        match (self.origin[k], self.origin.get(k + 1).copied()) {
            (Origin::Clip(e), _) | (_, Some(Origin::Clip(e))) => e,
            (Origin::Vertex(i), _) => i,
        }
    }
}

/// Where a vertex lies for the clipping: strictly on the wrong side, on the line, or strictly on
/// the kept side (`deep`: certainly farther from the line than the cut allows).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Bad,
    On,
    Good { deep: bool },
}

/// The runs of `chain` clipped to the closed half-plane of the line `(a, c)` that avoids the side
/// `wrong` (`sides[k] = K::orient(a, c, chain[k])`), extended along their crossing edges to the
/// clip points where they meet the line (an end on the line needs no cut), without the edges that
/// cannot hold a pair beating `cut` (both ends on the kept side and certainly farther than `√cut`
/// from the line: every point of the edge is, and a pair that a subproblem must find meets the
/// line, so it is at least as long as either point's distance to it; notes 4.8).
///
/// An edge is kept when it crosses the line, touches it and reaches into the kept side, or lies in
/// the kept side with an end within the cut; consecutive kept edges form a run; a vertex on the
/// line or near it with no kept edge is a run of its own. `O(n)` certified `f64` bounds, no
/// predicate.
pub(crate) fn clip_runs(
    chain: &[DVec2],
    sides: &[Orientation],
    wrong: Orientation,
    (a, c): (DVec2, DVec2),
    cut: f64,
) -> Gapped {
    let n = chain.len().min(sides.len());
    let class = |k: usize| {
        if sides[k] == wrong {
            Class::Bad
        } else if sides[k].is_collinear() {
            Class::On
        } else {
            Class::Good {
                deep: cut.is_finite() && farther_from_line_than(chain[k], a, c, cut),
            }
        }
    };
    let cls: Vec<Class> = (0..n).map(class).collect();
    let kept = |e: usize| match (cls[e], cls[e + 1]) {
        (Class::Bad, Class::Good { .. }) | (Class::Good { .. }, Class::Bad) => true,
        (Class::Bad, _) | (_, Class::Bad) => false,
        (Class::Good { deep: true }, Class::Good { deep: true }) => false,
        _ => true,
    };
    let clip = |e: usize| Site::Crossing {
        a: chain[e],
        b: chain[e + 1],
        l0: a,
        l1: c,
    };
    let mut g = Gapped::default();
    let push = |g: &mut Gapped, k: usize| {
        g.sites.push(Site::Input(chain[k]));
        g.origin.push(Origin::Vertex(k));
    };
    let mut covered = false; // whether vertex k is the end of a kept edge already handled
    let mut e = 0;
    while e < n {
        if e + 1 < n && kept(e) {
            // A run of kept edges e..=t, ended by a vertex on the wrong side (its edges on
            // either side are clipped there, in two runs).
            let mut t = e;
            while t + 2 < n && cls[t + 1] != Class::Bad && kept(t + 1) {
                t += 1;
            }
            let start = g.sites.len();
            if cls[e] == Class::Bad {
                g.sites.push(clip(e));
                g.origin.push(Origin::Clip(e));
            } else {
                push(&mut g, e);
            }
            for k in e + 1..=t {
                push(&mut g, k);
            }
            if cls[t + 1] == Class::Bad {
                g.sites.push(clip(t));
                g.origin.push(Origin::Clip(t));
            } else {
                push(&mut g, t + 1);
            }
            g.runs.push((start, g.sites.len() - 1));
            covered = true;
            e = t + 1;
            continue;
        }
        // Vertex e with no kept edge after it (and none before it unless covered).
        if !covered && matches!(cls[e], Class::On | Class::Good { deep: false }) {
            let start = g.sites.len();
            push(&mut g, e);
            g.runs.push((start, start));
        }
        covered = false;
        e += 1;
    }
    g
}

/// The bounding box of `chain[lo..=hi]`.
fn span_box(chain: &[DVec2], (lo, hi): (usize, usize)) -> (DVec2, DVec2) {
    chain[lo..=hi]
        .iter()
        .fold((chain[lo], chain[lo]), |(l, h), &v| (l.min(v), h.max(v)))
}

/// Drops the runs of each clipped chain whose box is certainly farther than `√cut` from the box of
/// the other chain's runs: no pair beating the cut has a point on them (every point of a run lies
/// in its box). `Q`'s runs are tested against `P`'s box, then `P`'s against what is left of `Q`'s.
/// `O(n)` coordinate comparisons and filter bounds, no predicate.
fn drop_far_runs(gp: &mut Gapped, gq: &mut Gapped, p: &[DVec2], q: &[DVec2], cut: f64) {
    if !cut.is_finite() {
        return;
    }
    if let Some(pb) = gp.bbox(p) {
        gq.retain_runs(|span| !boxes_farther_than(span_box(q, span), pb, cut));
    }
    if let Some(qb) = gq.bbox(q) {
        gp.retain_runs(|span| !boxes_farther_than(span_box(p, span), qb, cut));
    }
}

/// Sorts `xs` by `cmp` with a merge sort that never panics, whatever `cmp` answers (an
/// inconsistent comparator, possible under the Fast kernel, gives some order). `O(k log k)` calls.
fn merge_sort_by<T: Copy>(xs: &mut Vec<T>, cmp: &impl Fn(&T, &T) -> Ordering) {
    if xs.len() < 2 {
        return;
    }
    let mut right = xs.split_off(xs.len() / 2);
    merge_sort_by(xs, cmp);
    merge_sort_by(&mut right, cmp);
    let left = core::mem::take(xs);
    let (mut i, mut j) = (0, 0);
    xs.reserve(left.len() + right.len());
    while i < left.len() && j < right.len() {
        if cmp(&right[j], &left[i]) == Ordering::Less {
            xs.push(right[j]);
            j += 1;
        } else {
            xs.push(left[i]);
            i += 1;
        }
    }
    xs.extend_from_slice(&left[i..]);
    xs.extend_from_slice(&right[j..]);
}

/// The nearest pair of a site of `P` and a site of `Q` both on the line (clip points always are):
/// the pairs section 3's wedges cannot hold. Points of one line, ordered exactly by height; the
/// nearest pair of two sets of points on a line is adjacent in that order. `O(k log k)` for the
/// `k` sites on the line.
fn on_the_line<K: Kernel>(p: &Gapped, q: &Gapped, frame: Frame) -> Option<Cand<Site>> {
    let mut all: Vec<(Site, usize, bool)> = Vec::new();
    for (g, side) in [(p, true), (q, false)] {
        all.extend(
            g.sites
                .iter()
                .enumerate()
                .filter(|(_, s)| s.is_crossing() || frame.depth_sign::<K, _>(**s) == Sign::Zero)
                .map(|(k, &s)| (s, k, side)),
        );
    }
    merge_sort_by(&mut all, &|x, y| frame.cmp_height::<K, _>(x.0, y.0));
    nearest_adjacent::<K, Site>(&all)
}

/// A vertex–edge candidate between the subchains: vertex `j` of one (`p_side`: the edge is
/// `P`'s), edge `e` (from `e` to `e + 1`) of the other.
fn vertex_edge(p: &[DVec2], q: &[DVec2], j: usize, e: usize, p_side: bool) -> Cand {
    let (vs, es) = if p_side { (q, p) } else { (p, q) };
    Cand::Ve {
        v: vs[j],
        j,
        a: es[e],
        ia: e,
        b: es[e + 1],
        ib: e + 1,
        edge: e,
        p_side,
    }
}

/// The nearest of the four vertex–edge pairs of `P`'s edge `ep` and `Q`'s edge `eq` (the distance
/// of the two segments, which do not cross).
fn edge_edge<K: Kernel>(p: &[DVec2], q: &[DVec2], ep: usize, eq: usize) -> Option<Cand> {
    [
        vertex_edge(p, q, ep, eq, false),
        vertex_edge(p, q, ep + 1, eq, false),
        vertex_edge(p, q, eq, ep, true),
        vertex_edge(p, q, eq + 1, ep, true),
    ]
    .into_iter()
    .reduce(|b, c| {
        if K::cmp_dist2(c.dist(), b.dist()) == Ordering::Less {
            c
        } else {
            b
        }
    })
}

/// A candidate between the gapped chains, re-expressed between the subchains `p`, `q` (module
/// docs): no farther, and a true distance between them.
fn unclip<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    gp: &Gapped,
    gq: &Gapped,
    c: Cand<Site>,
) -> Option<Cand> {
    match c {
        Cand::Vv(_, i, _, j) => match (gp.origin[i], gq.origin[j]) {
            (Origin::Vertex(i), Origin::Vertex(j)) => Some(Cand::Vv(p[i], i, q[j], j)),
            (Origin::Vertex(i), Origin::Clip(f)) => Some(vertex_edge(p, q, i, f, false)),
            (Origin::Clip(e), Origin::Vertex(j)) => Some(vertex_edge(p, q, j, e, true)),
            (Origin::Clip(e), Origin::Clip(f)) => edge_edge::<K>(p, q, e, f),
        },
        Cand::Ve {
            j, edge, p_side, ..
        } => {
            // The vertex's chain and the edge's chain, in sites and in the subchains.
            let (gv, ge) = if p_side { (gq, gp) } else { (gp, gq) };
            let e = ge.edge_origin(edge);
            match gv.origin[j] {
                Origin::Vertex(j) => Some(vertex_edge(p, q, j, e, p_side)),
                Origin::Clip(f) if p_side => edge_edge::<K>(p, q, e, f),
                Origin::Clip(f) => edge_edge::<K>(p, q, f, e),
            }
        }
    }
}

/// Section 3 on the subchains `p`, `q` clipped to opposite closed half-planes of the line through
/// `a`, `c`: `P` keeps the side opposite `wrong_p` (sides in `sp`, `sq` as `K::orient(a, c, ·)`),
/// `Q` the other. The best candidate between the subchains (`None`: nothing of one subchain is on
/// its side). Parts that cannot hold a pair whose squared length is at most
/// `cut` are left out ([`clip_runs`]): the candidate is then some pair of the subchains when none
/// beats the cut.
///
/// # Complexity
/// `O(n log k)` for `n = |P_i| + |Q_i|` vertices in `k` runs (the runs' envelopes are merged in a
/// balanced tree; every later step of section 3 is linear), plus `O(k' log k')` for the `k'` sites
/// on the line.
///
/// # Errors
/// As section 3's (for example [`SeparationError::NotSimple`], or inconsistent decisions under the
/// Fast kernel); the caller then scans the subproblem.
pub(crate) fn separation_of_gapped<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    (a, c): (DVec2, DVec2),
    (sp, sq): (&[Orientation], &[Orientation]),
    wrong_p: Orientation,
    cut: f64,
) -> Result<Option<Cand>, SeparationError> {
    let wrong_q = wrong_p.reversed();
    let mut gp = clip_runs(p, sp, wrong_p, (a, c), cut);
    let mut gq = clip_runs(q, sq, wrong_q, (a, c), cut);
    drop_far_runs(&mut gp, &mut gq, p, q, cut);
    if gp.sites.is_empty() || gq.sites.is_empty() {
        return Ok(None);
    }
    // `P` right of the oriented line, as in `chain::validate_touching`: its good side is the
    // clockwise one of `(a, c)` unless that is the wrong one.
    let (l0, l1) = if wrong_p == Orientation::Clockwise {
        (c, a)
    } else {
        (a, c)
    };
    let frames = Frames::across(l0, l1);
    let on_line = on_the_line::<K>(&gp, &gq, frames.p);
    let off = |g: &Gapped, f: Frame| {
        g.sites
            .iter()
            .any(|s| !s.is_crossing() && f.depth_sign::<K, _>(*s) == Sign::Positive)
    };
    let best = if off(&gp, frames.p) || off(&gq, frames.q) {
        let pp = prepare_runs::<K, Site>(&gp.sites, &gp.runs, frames.p, Chain::P)?;
        let qq = prepare_runs::<K, Site>(&gq.sites, &gq.runs, frames.q, Chain::Q)?;
        solve_prepared::<K, Site>(pp, qq, frames, on_line)?.0
    } else {
        // Both clipped chains lie on the line: the on-line pair is the answer.
        on_line.ok_or(SeparationError::Inconsistent)?
    };
    Ok(unclip::<K>(p, q, &gp, &gq, best))
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_predicates::{Counted, Dist2, Robust, predicate_counts, reset_predicate_counts};

    /// Two interleaved combs of `t` teeth across the `x` axis, as open chains: `P`'s teeth hang
    /// down from `y = 2` to `y = −1`, `Q`'s rise from `y = −2` to `y = 1` between them. Clipped to
    /// `y ≥ 0` and `y ≤ 0`, each is about `t` runs ending at clip points.
    fn combs(t: usize) -> (Vec<DVec2>, Vec<DVec2>) {
        let v = |x: f64, y: f64| DVec2::new(x, y);
        let mut p = Vec::with_capacity(4 * t);
        let mut q = Vec::with_capacity(4 * t);
        for i in 0..t {
            let x = 4.0 * i as f64;
            p.extend([v(x, 2.0), v(x, -1.0), v(x + 1.0, -1.0), v(x + 1.0, 2.0)]);
            q.extend([
                v(x + 2.0, -2.0),
                v(x + 2.0, 1.0),
                v(x + 3.0, 1.0),
                v(x + 3.0, -2.0),
            ]);
        }
        (p, q)
    }

    /// Section 3 on clipped chains is `O(n log k)`, counted: the predicates per vertex, over
    /// `t = 16 … 4,096` teeth (as many runs per chain), stay within `32 + log₂ k` (measured 28.8 at
    /// 16 teeth, 34.2 at 4,096, 35.3 at 16,384: half a predicate per vertex per doubling of `k`,
    /// the balanced merge's rounds); a merge quadratic in the runs, or a rescan per run, would grow
    /// with `k` itself.
    #[test]
    fn gapped_section_3_counts_n_log_k_predicates() {
        let (a, c) = (DVec2::ZERO, DVec2::X);
        let mut seen = Vec::new();
        for t in [16usize, 64, 256, 1024, 4096] {
            let (p, q) = combs(t);
            let side = |v: &[DVec2]| {
                v.iter()
                    .map(|&x| Robust::orient(a, c, x))
                    .collect::<Vec<_>>()
            };
            let (sp, sq) = (side(&p), side(&q));
            reset_predicate_counts();
            let found = separation_of_gapped::<Counted<Robust>>(
                &p,
                &q,
                (a, c),
                (&sp, &sq),
                Orientation::Clockwise,
                f64::INFINITY,
            )
            .unwrap();
            let calls = predicate_counts().total() as f64;
            let cand = found.expect("both combs reach across the axis");
            // The nearest pairs are a tooth side of each at distance 1.
            assert_eq!(
                Robust::cmp_dist2(cand.dist(), Dist2::PointPoint(DVec2::ZERO, DVec2::X)),
                Ordering::Equal
            );
            let n = (p.len() + q.len()) as f64;
            let per = calls / n;
            seen.push((t, per));
            assert!(
                per <= 32.0 + (t as f64).log2(),
                "{t} teeth: {per:.1} predicates per vertex ({seen:?})"
            );
        }
    }
}
