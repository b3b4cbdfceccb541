//! Exact references for chains (open polylines): the distance between two chains and the closest
//! visible vertex pair, in rational arithmetic, independent of polydist's predicates.

use core::cmp::Ordering;

use glam::DVec2;
use num_rational::BigRational;

use crate::distance::{ExactDistance, Feature};
use crate::exact::{rat, sign_orient, sq_dist_pp, sq_dist_ps};

/// `(b − a) · (d − c)` exactly.
fn dot(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> BigRational {
    let r = |x: f64| rat(x).expect("polydist-oracle: coordinates must be finite");
    (r(b.x) - r(a.x)) * (r(d.x) - r(c.x)) + (r(b.y) - r(a.y)) * (r(d.y) - r(c.y))
}

fn positive(x: &BigRational) -> bool {
    *x > BigRational::from_integer(0.into())
}

/// Whether the open segment `(p, q)` shares a point with the closed segment `[a, b]`.
pub fn open_segment_meets(p: DVec2, q: DVec2, a: DVec2, b: DVec2) -> bool {
    let between = |x: DVec2| positive(&dot(p, x, p, q)) && positive(&dot(q, x, q, p));
    let (o1, o2) = (sign_orient(p, q, a), sign_orient(p, q, b));
    if o1 == Ordering::Equal && o2 == Ordering::Equal {
        let at_or_before_p = |x: DVec2| !positive(&dot(p, x, p, q));
        let at_or_after_q = |x: DVec2| !positive(&dot(q, x, q, p));
        return !((at_or_before_p(a) && at_or_before_p(b))
            || (at_or_after_q(a) && at_or_after_q(b)));
    }
    if o1 == Ordering::Equal {
        return between(a);
    }
    if o2 == Ordering::Equal {
        return between(b);
    }
    if o1 == o2 {
        return false;
    }
    let (o3, o4) = (sign_orient(a, b, p), sign_orient(a, b, q));
    o3 != Ordering::Equal && o4 != Ordering::Equal && o3 != o4
}

fn clear(p: DVec2, q: DVec2, chain: &[DVec2]) -> bool {
    if chain.len() == 1 {
        return !open_segment_meets(p, q, chain[0], chain[0]);
    }
    chain
        .windows(2)
        .all(|e| !open_segment_meets(p, q, e[0], e[1]))
}

/// The closest visible vertex pairs of two chains: the minimum of `|p_i − q_j|²` over vertex pairs
/// whose open segment meets neither chain, with every optimal `(i, j)` (sorted). `None` when no pair
/// is visible. Cost `O(n_p n_q (n_p + n_q))` rational operations.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn closest_visible_vertices_exact(
    p: &[DVec2],
    q: &[DVec2],
) -> Option<(BigRational, Vec<(usize, usize)>)> {
    let mut best: Option<(BigRational, Vec<(usize, usize)>)> = None;
    for (i, &a) in p.iter().enumerate() {
        for (j, &b) in q.iter().enumerate() {
            let d = sq_dist_pp(a, b);
            if best.as_ref().is_some_and(|(m, _)| d > *m) {
                continue;
            }
            if !(clear(a, b, p) && clear(a, b, q)) {
                continue;
            }
            match &mut best {
                Some((m, pairs)) if *m == d => pairs.push((i, j)),
                _ => best = Some((d, vec![(i, j)])),
            }
        }
    }
    best
}

/// The exact distance between two open chains (edge `i` joins vertices `i` and `i + 1`; no closing
/// edge), with every optimal feature pair among vertex–vertex and vertex–edge pairs (sorted).
///
/// # Panics
/// Panics if a chain is empty or a coordinate is not finite.
pub fn chain_distance(p: &[DVec2], q: &[DVec2]) -> ExactDistance {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "chain_distance: empty chain"
    );
    let mut cands: Vec<(BigRational, (Feature, Feature))> = Vec::new();
    for (i, &a) in p.iter().enumerate() {
        for (j, &b) in q.iter().enumerate() {
            cands.push((sq_dist_pp(a, b), (Feature::Vertex(i), Feature::Vertex(j))));
        }
        for (j, e) in q.windows(2).enumerate() {
            cands.push((
                sq_dist_ps(a, e[0], e[1]),
                (Feature::Vertex(i), Feature::Edge(j)),
            ));
        }
    }
    for (j, &b) in q.iter().enumerate() {
        for (i, e) in p.windows(2).enumerate() {
            cands.push((
                sq_dist_ps(b, e[0], e[1]),
                (Feature::Edge(i), Feature::Vertex(j)),
            ));
        }
    }
    let best = cands
        .iter()
        .map(|(d, _)| d)
        .min()
        .cloned()
        .expect("non-empty chains have a vertex pair");
    let mut pairs: Vec<(Feature, Feature)> = cands
        .into_iter()
        .filter(|(d, _)| *d == best)
        .map(|(_, f)| f)
        .collect();
    pairs.sort();
    ExactDistance { sq: best, pairs }
}
