//! Seeded generators of chains separated by a line and monotone along it.
#![allow(dead_code, reason = "each test file uses a subset")]

pub(crate) mod pairs;

use glam::DVec2;
use polydist_oracle::SplitMix64;

/// A test case: chains `p` (right of the line) and `q`, and two points of the line.
#[derive(Clone, Debug)]
pub(crate) struct Case {
    pub(crate) p: Vec<DVec2>,
    pub(crate) q: Vec<DVec2>,
    pub(crate) a: DVec2,
    pub(crate) b: DVec2,
    pub(crate) name: String,
}

/// `pair`, found for case `c` by `what`, is an exact optimum of the oracle's answer `exact`, its
/// distance within 3.5 ulps; panics with the case otherwise.
pub(crate) fn assert_optimal(
    c: &Case,
    what: &str,
    exact: &polydist_oracle::ExactDistance,
    pair: &polydist_separation::ClosestPair,
) {
    let (fp, fq) = (
        pairs::oracle_feature(pair.feature_p),
        pairs::oracle_feature(pair.feature_q),
    );
    assert!(
        exact.is_optimal_pair(fp, fq),
        "{} ({what}): got {:?} ({} vs exact {:?}), optimal {:?}\np={:?}\nq={:?}\nline {:?} {:?}",
        c.name,
        (fp, fq),
        pair.squared_distance,
        polydist_oracle::to_f64_nearest(&exact.sq),
        exact.pairs,
        c.p,
        c.q,
        c.a,
        c.b
    );
    assert!(
        polydist_oracle::ulps_error_sqrt(pair.distance, &exact.sq) <= 3.5,
        "{} ({what})",
        c.name
    );
}

/// Strictly increasing random integer heights (`n` of them) in `[0, span)`, or with repeats when
/// `ties` (for runs perpendicular to the line).
fn heights(rng: &mut SplitMix64, n: usize, span: i64, ties: bool) -> Vec<i64> {
    let mut h: Vec<i64> = (0..n).map(|_| rng.range_i64(0, span)).collect();
    h.sort_unstable();
    if !ties {
        h.dedup();
    }
    h
}

/// Maps frame coordinates (depth `x` ≥ 0 for P, ≤ 0 for Q, height `y`) by the integer rotation-scale
/// `(c, −s; s, c)` and the offset `o`: exact while every value stays below 2^53.
fn place(pts: &[(i64, i64)], rot: (i64, i64), o: DVec2) -> Vec<DVec2> {
    pts.iter()
        .map(|&(x, y)| {
            let (c, s) = rot;
            DVec2::new((c * x - s * y) as f64 + o.x, (s * x + c * y) as f64 + o.y)
        })
        .collect()
}

fn frame_case(p: &[(i64, i64)], q: &[(i64, i64)], rot: (i64, i64), o: DVec2, name: String) -> Case {
    Case {
        p: place(p, rot, o),
        q: place(q, rot, o),
        a: place(&[(0, 0)], rot, o)[0],
        b: place(&[(0, 1)], rot, o)[0],
        name,
    }
}

/// A random monotone chain in frame coordinates on one side (`sign` = +1 for P, −1 for Q), depth in
/// `[min_depth, max_depth]`.
fn random_side(
    rng: &mut SplitMix64,
    n: usize,
    span: i64,
    min_depth: i64,
    max_depth: i64,
    sign: i64,
    ties: bool,
) -> Vec<(i64, i64)> {
    let hs = heights(rng, n, span, ties);
    let mut out: Vec<(i64, i64)> = Vec::new();
    let mut i = 0;
    while i < hs.len() {
        // a run of equal heights gets monotone depths
        let mut j = i;
        while j < hs.len() && hs[j] == hs[i] {
            j += 1;
        }
        let mut ds: Vec<i64> = (i..j)
            .map(|_| rng.range_i64(min_depth, max_depth + 1))
            .collect();
        ds.sort_unstable();
        ds.dedup();
        if rng.coin() {
            ds.reverse();
        }
        out.extend(ds.into_iter().map(|d| (sign * d, hs[i])));
        i = j;
    }
    if rng.coin() {
        out.reverse();
    }
    out
}

/// Random monotone separable chains: lattice coordinates, a random integer rotation, optional offset.
pub(crate) fn random_case(rng: &mut SplitMix64, n: usize, far: bool) -> Case {
    let span = 2 + rng.range_i64(0, 3 * n as i64 + 4);
    let ties = rng.below(4) == 0;
    let depth = 1 + rng.range_i64(0, 12);
    // At most one chain may touch the line.
    let (pmin, qmin) = match rng.below(3) {
        0 => (0, 1),
        1 => (1, 0),
        _ => (1, 1),
    };
    let np = 1 + rng.index(n);
    let nq = 1 + rng.index(n);
    let p = random_side(rng, np, span, pmin, pmin + depth, 1, ties);
    let q = random_side(rng, nq, span, qmin, qmin + depth, -1, ties);
    let rots = [(1, 0), (0, 1), (3, 4), (-4, 3), (5, -12), (1, 1), (-2, 7)];
    let rot = rots[rng.index(rots.len())];
    let o = if far {
        DVec2::new(1e12, -3e12)
    } else {
        DVec2::new(rng.range_i64(-50, 50) as f64, rng.range_i64(-50, 50) as f64)
    };
    frame_case(
        &p,
        &q,
        rot,
        o,
        format!("random n={n} rot={rot:?} far={far}"),
    )
}

/// Two saw-tooth combs whose tips face each other across the line (P's tips at depth `gap_p`, Q's at
/// `gap_q`, in frame units), `teeth` teeth each, interleaved or aligned.
pub(crate) fn combs(
    teeth: usize,
    gap_p: i64,
    gap_q: i64,
    interleave: bool,
    rot: (i64, i64),
) -> Case {
    let mut p = Vec::new();
    let mut q = Vec::new();
    for k in 0..teeth as i64 {
        p.push((gap_p + 10, 4 * k));
        p.push((gap_p, 4 * k + 2));
        let s = if interleave { 2 } else { 0 };
        q.push((-(gap_q + 10), 4 * k + s));
        q.push((-gap_q, 4 * k + 2 + s));
    }
    frame_case(
        &p,
        &q,
        rot,
        DVec2::ZERO,
        format!("combs teeth={teeth} gaps=({gap_p},{gap_q}) interleave={interleave}"),
    )
}

/// Chains with long collinear runs (parallel to the line and slanted) and exact right angles.
pub(crate) fn collinear(n: usize, rot: (i64, i64)) -> Case {
    let mut p = Vec::new();
    let mut q = Vec::new();
    for k in 0..n as i64 {
        // P: a staircase of collinear runs; Q: one slanted line then one parallel line.
        p.push((3 + (k / 4) % 2, k));
        q.push(if k < n as i64 / 2 {
            (-2 - k, k)
        } else {
            (-2 - n as i64 / 2, k)
        });
    }
    frame_case(&p, &q, rot, DVec2::ZERO, format!("collinear n={n}"))
}

/// `true` when the chain (repeated consecutive vertices ignored; closed when its last vertex equals
/// its first) is simple: non-adjacent edges do not meet and adjacent edges meet only at their common
/// vertex. Exact (oracle), `O(n²)`.
pub(crate) fn simple_chain(c: &[DVec2]) -> bool {
    use polydist_oracle::{segments_intersect, sign_orient};
    use polydist_predicates::Kernel;
    let mut v: Vec<DVec2> = Vec::new();
    for &x in c {
        if v.last() != Some(&x) {
            v.push(x);
        }
    }
    let closed = v.len() >= 2 && v.first() == v.last();
    if closed && v.len() < 4 {
        return false;
    }
    let m = v.len().saturating_sub(1); // edges
    for i in 0..m {
        for j in i + 1..m {
            let (a, b, c, d) = (v[i], v[i + 1], v[j], v[j + 1]);
            let adjacent = j == i + 1 || (closed && i == 0 && j == m - 1);
            if adjacent {
                // Shared vertex s; the two edges must not overlap (fold back over each other).
                let (s, x, y) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                if sign_orient(s, x, y) == core::cmp::Ordering::Equal
                    && polydist_predicates::Exact::dot_sign(s, x, s, y)
                        == polydist_predicates::Sign::Positive
                {
                    return false;
                }
            } else if segments_intersect(a, b, c, d) {
                return false;
            }
        }
    }
    true
}
