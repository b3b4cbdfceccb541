//! Input validation, orientation of the separating line, and Lemma 2 for monotone chains.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign, is_valid_coordinate};

use crate::error::{Chain, SeparationError};
use crate::frame::Frame;

/// A chain after Lemma 2: the perpendicularly visible vertices, strictly increasing in height, with
/// their caller indices.
#[derive(Clone, Debug, Default)]
pub(crate) struct Prepared {
    pub(crate) pts: Vec<DVec2>,
    pub(crate) idx: Vec<usize>,
    /// The caller's chain runs upward (increasing height with increasing index).
    pub(crate) rising: bool,
    /// The caller's index of the first vertex dropped from a run perpendicular to the line.
    pub(crate) first_run: Option<usize>,
    /// For each kept vertex, the first and the last vertex of its run at that height in the order
    /// the chain is walked (both the vertex itself when it is alone at its height), with caller
    /// indices: the edge from `last[k]` to `first[k + 1]` is a real edge of the chain.
    pub(crate) first: Vec<(DVec2, usize)>,
    pub(crate) last: Vec<(DVec2, usize)>,
}

impl Prepared {
    /// The real edge between heights `k` and `k + 1`: `(a, b, caller index of a, of b)`.
    pub(crate) fn edge(&self, k: usize) -> (DVec2, DVec2, usize, usize) {
        let (a, ia) = self.last[k];
        let (b, ib) = self.first[k + 1];
        (a, b, ia, ib)
    }

    /// The caller's edge index of the real edge `k`.
    pub(crate) fn caller_edge(&self, k: usize) -> usize {
        let ib = self.first[k + 1].1;
        if self.rising { ib - 1 } else { ib }
    }
}

/// The two frames of a validated input: `P` right of the oriented line, `Q` left of it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frames {
    pub(crate) p: Frame,
    pub(crate) q: Frame,
}

fn valid(v: DVec2) -> bool {
    is_valid_coordinate(v.x) && is_valid_coordinate(v.y)
}

/// Checks emptiness, coordinates, the line, and that the line separates the chains with at most one
/// of them touching it; returns the two frames. `O(n_p + n_q)` orientation tests.
pub(crate) fn validate<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Frames, SeparationError> {
    if p.is_empty() {
        return Err(SeparationError::EmptyChain { chain: Chain::P });
    }
    if q.is_empty() {
        return Err(SeparationError::EmptyChain { chain: Chain::Q });
    }
    for (chain, pts) in [(Chain::P, p), (Chain::Q, q)] {
        if let Some(index) = pts.iter().position(|&v| !valid(v)) {
            return Err(SeparationError::InvalidCoordinate { chain, index });
        }
    }
    if !valid(a) || !valid(b) {
        return Err(SeparationError::InvalidLine);
    }
    if a == b {
        return Err(SeparationError::DegenerateLine);
    }
    // Orient the line so that Q is on its left: from the first vertex strictly off the line.
    let first_q = q
        .iter()
        .map(|&v| K::orient(a, b, v).sign())
        .find(|s| !s.is_zero());
    let swap = match first_q {
        Some(s) => s == Sign::Negative,
        None => match p
            .iter()
            .map(|&v| K::orient(a, b, v).sign())
            .find(|s| !s.is_zero())
        {
            Some(s) => s == Sign::Positive,
            // Every vertex of both chains lies on the line.
            None => return Err(SeparationError::BothChainsTouchLine),
        },
    };
    let (l0, l1) = if swap { (b, a) } else { (a, b) };
    let frames = Frames {
        p: Frame {
            l0,
            l1,
            mirror: false,
        },
        q: Frame {
            l0,
            l1,
            mirror: true,
        },
    };
    let mut touches = [false; 2];
    for (k, (chain, pts, frame)) in [(Chain::P, p, frames.p), (Chain::Q, q, frames.q)]
        .into_iter()
        .enumerate()
    {
        for (index, &v) in pts.iter().enumerate() {
            match frame.depth_sign::<K>(v) {
                Sign::Negative => return Err(SeparationError::NotSeparated { chain, index }),
                Sign::Zero => touches[k] = true,
                Sign::Positive => {}
            }
        }
    }
    if touches[0] && touches[1] {
        return Err(SeparationError::BothChainsTouchLine);
    }
    Ok(frames)
}

/// Lemma 2 for a chain monotone along the line: checks monotonicity, drops repeated consecutive
/// vertices, and keeps of each run of vertices at equal height (edges perpendicular to the line) only
/// the one nearest to the line; the others are not perpendicularly visible. The result is strictly
/// increasing in height. `O(n)` degree-2 tests.
pub(crate) fn prepare_monotone<K: Kernel>(
    chain: &[DVec2],
    frame: Frame,
    which: Chain,
) -> Result<Prepared, SeparationError> {
    let n = chain.len();
    // The direction of the chain: the first strict height change.
    let rising = (1..n)
        .map(|i| frame.cmp_height::<K>(chain[i], chain[i - 1]))
        .find(|o| o.is_ne())
        .is_none_or(|o| o.is_gt());
    let order: Vec<usize> = if rising {
        (0..n).collect()
    } else {
        (0..n).rev().collect()
    };
    let mut out = Prepared {
        rising,
        ..Prepared::default()
    };
    let mut prev = order[0];
    out.pts.push(chain[prev]);
    out.idx.push(prev);
    out.first.push((chain[prev], prev));
    out.last.push((chain[prev], prev));
    // Direction of depth within the current run of equal heights (None: run of one vertex).
    let mut run_dir: Option<Ordering> = None;
    for &i in &order[1..] {
        let v = chain[i];
        if v == chain[prev] {
            continue; // a repeated vertex (zero-length edge): nothing new
        }
        match frame.cmp_height::<K>(v, chain[prev]) {
            Ordering::Less => {
                return Err(SeparationError::NotMonotone {
                    chain: which,
                    index: i,
                });
            }
            Ordering::Greater => {
                run_dir = None;
                out.pts.push(v);
                out.idx.push(i);
                out.first.push((v, i));
                out.last.push((v, i));
            }
            Ordering::Equal => {
                // Equal height and distinct points: the depths differ (the frame is a similarity).
                let dir = frame.cmp_depth::<K>(v, chain[prev]);
                if run_dir.is_some_and(|d| d != dir) {
                    return Err(SeparationError::NotMonotone {
                        chain: which,
                        index: i,
                    });
                }
                run_dir = Some(dir);
                if out.first_run.is_none() {
                    out.first_run = Some(i);
                }
                if let Some(l) = out.last.last_mut() {
                    *l = (v, i);
                }
                // Keep the nearer of the run's vertices: the last kept one is the nearest so far.
                if dir == Ordering::Less {
                    if let (Some(pt), Some(ix)) = (out.pts.last_mut(), out.idx.last_mut()) {
                        *pt = v;
                        *ix = i;
                    }
                }
            }
        }
        prev = i;
    }
    Ok(out)
}
