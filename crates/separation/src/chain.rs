//! Input validation, orientation of the separating line, and Lemma 2 for monotone chains.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign, is_valid_coordinate};

use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::param::Param;

/// An edge of the envelope `P°` between two consecutive visible vertices: the chain's edge `(a, b)`
/// oriented upward (`H(a) < H(b)`), of which only the part between the heights of the two visible
/// vertices, parameters `lo..hi` on `(a, b)`, is on the envelope. `lo` is `Start` when `a` is at the
/// lower visible vertex's height (it is that vertex, or a vertex hidden behind it), else the shadow
/// point `H(x) = H(v_k)` (a root, kept symbolic); `hi` likewise with `End`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EnvEdge<V = DVec2> {
    pub(crate) a: V,
    pub(crate) b: V,
    /// The caller's indices of `a` and `b`.
    pub(crate) ia: usize,
    pub(crate) ib: usize,
    /// The caller's edge index.
    pub(crate) caller: usize,
    pub(crate) lo: Param<V>,
    pub(crate) hi: Param<V>,
}

/// A chain after Lemma 2: the perpendicularly visible vertices, strictly increasing in height, with
/// their caller indices, and the envelope edge between each two consecutive ones.
#[derive(Clone, Debug, Default)]
pub(crate) struct Prepared<V = DVec2> {
    pub(crate) pts: Vec<V>,
    pub(crate) idx: Vec<usize>,
    /// `edges[k]` carries the envelope between `pts[k]` and `pts[k + 1]`; `None` where no point of
    /// the chain lies between their heights (a gap between the runs of a clipped chain: never for a
    /// connected chain).
    pub(crate) edges: Vec<Option<EnvEdge<V>>>,
}

impl<V: Copy> Prepared<V> {
    /// The real edge between heights `k` and `k + 1`: `(a, b, caller index of a, of b)`.
    pub(crate) fn edge(&self, k: usize) -> Option<(V, V, usize, usize)> {
        self.edges[k].as_ref().map(|e| (e.a, e.b, e.ia, e.ib))
    }

    /// A chain strictly increasing in height given as is (every vertex visible, each edge wholly
    /// on the envelope), for unit tests.
    #[cfg(test)]
    pub(crate) fn from_rising(pts: &[DVec2]) -> Prepared {
        Prepared {
            pts: pts.to_vec(),
            idx: (0..pts.len()).collect(),
            edges: pts
                .windows(2)
                .enumerate()
                .map(|(k, w)| {
                    Some(EnvEdge {
                        a: w[0],
                        b: w[1],
                        ia: k,
                        ib: k + 1,
                        caller: k,
                        lo: Param::Start,
                        hi: Param::End,
                    })
                })
                .collect(),
        }
    }
}

/// The two frames of a validated input: `P` right of the oriented line, `Q` left of it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frames {
    pub(crate) p: Frame,
    pub(crate) q: Frame,
}

impl Frames {
    /// `P` right of the line oriented from `l0` to `l1`, `Q` left of it.
    pub(crate) fn across(l0: DVec2, l1: DVec2) -> Frames {
        Frames {
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
        }
    }
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
    match validate_touching::<K>(p, q, a, b)? {
        Validated {
            frames: Some(frames),
            on_line,
        } if !on_line.both() => Ok(frames),
        _ => Err(SeparationError::BothChainsTouchLine),
    }
}

/// The indices of each chain's vertices that lie on the line, as the validation found them.
#[derive(Clone, Debug, Default)]
pub(crate) struct OnLine {
    pub(crate) p: Vec<usize>,
    pub(crate) q: Vec<usize>,
}

impl OnLine {
    /// Whether both chains touch the line.
    pub(crate) fn both(&self) -> bool {
        !self.p.is_empty() && !self.q.is_empty()
    }
}

/// What [`validate_touching`] found: the frames (`None` when every vertex of both chains lies on
/// the line, so that no side is defined) and the vertices on the line.
pub(crate) struct Validated {
    pub(crate) frames: Option<Frames>,
    pub(crate) on_line: OnLine,
}

/// [`validate`], but both chains may touch the line.
pub(crate) fn validate_touching<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Validated, SeparationError> {
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
            None => {
                return Ok(Validated {
                    frames: None,
                    on_line: OnLine {
                        p: (0..p.len()).collect(),
                        q: (0..q.len()).collect(),
                    },
                });
            }
        },
    };
    let (l0, l1) = if swap { (b, a) } else { (a, b) };
    let frames = Frames::across(l0, l1);
    let mut on_line = OnLine::default();
    for (chain, pts, frame, on) in [
        (Chain::P, p, frames.p, &mut on_line.p),
        (Chain::Q, q, frames.q, &mut on_line.q),
    ] {
        for (index, &v) in pts.iter().enumerate() {
            match frame.depth_sign::<K, _>(v) {
                Sign::Negative => return Err(SeparationError::NotSeparated { chain, index }),
                Sign::Zero => on.push(index),
                Sign::Positive => {}
            }
        }
    }
    Ok(Validated {
        frames: Some(frames),
        on_line,
    })
}

/// Checks that a chain is monotone along the line (heights never decrease, or never increase, along
/// it; repeated consecutive vertices ignored) and does not double back within a run of vertices at
/// equal height. Required by [`closest_visible_vertices`](crate::closest_visible_vertices) only.
/// `O(n)` degree-2 tests.
pub(crate) fn check_monotone<K: Kernel>(
    chain: &[DVec2],
    frame: Frame,
    which: Chain,
) -> Result<(), SeparationError> {
    let n = chain.len();
    // The direction of the chain: the first strict height change.
    let rising = (1..n)
        .map(|i| frame.cmp_height::<K, _>(chain[i], chain[i - 1]))
        .find(|o| o.is_ne())
        .is_none_or(|o| o.is_gt());
    let bad = |index| {
        Err(SeparationError::NotMonotone {
            chain: which,
            index,
        })
    };
    let mut prev = 0;
    // Direction of depth within the current run of equal heights (None: run of one vertex).
    let mut run_dir: Option<Ordering> = None;
    for i in 1..n {
        let v = chain[i];
        if v == chain[prev] {
            continue; // a repeated vertex (zero-length edge): nothing new
        }
        let mut o = frame.cmp_height::<K, _>(v, chain[prev]);
        if !rising {
            o = o.reverse();
        }
        match o {
            Ordering::Less => return bad(i),
            Ordering::Greater => run_dir = None,
            Ordering::Equal => {
                // Equal height and distinct points: the depths differ (the frame is a similarity).
                let dir = frame.cmp_depth::<K, _>(v, chain[prev]);
                if run_dir.is_some_and(|d| d != dir) {
                    return bad(i);
                }
                run_dir = Some(dir);
            }
        }
        prev = i;
    }
    Ok(())
}
