//! Input validation, orientation of the separating line, and Lemma 2 for monotone chains.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign, is_valid_coordinate};

use crate::error::{Chain, SeparationError};
use crate::frame::Frame;
use crate::param::Param;
use crate::site::Vertex;

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

/// What a [`Prepared`] keeps of envelope interval `k` besides its edge's ends: the caller's
/// indices, and whether the edge's part on the envelope ends at a shadow point at either height.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Carry {
    /// The caller's indices of `a` and `b`.
    pub(crate) ia: usize,
    pub(crate) ib: usize,
    /// The caller's edge index.
    pub(crate) caller: usize,
    /// `lo` is the shadow root at the lower visible vertex's height (else `Start`).
    pub(crate) lo_root: bool,
    /// `hi` is the shadow root at the upper visible vertex's height (else `End`).
    pub(crate) hi_root: bool,
}

/// A chain after Lemma 2: the perpendicularly visible vertices, strictly increasing in height, with
/// their caller indices, and the envelope edge between each two consecutive ones.
///
/// Interval `k` (between `pts[k]` and `pts[k + 1]`) is stored lean: the ends `(a, b)` of the edge
/// carrying it in `segs[k]` (what the envelope sweep reads, borrowed as they are) and the rest in
/// `carry[k]`; [`Prepared::env_edge`] builds the [`EnvEdge`] with its symbolic range for section
/// 3's matrices. An [`EnvEdge`] holds two parameters of up to three points each, 112 bytes against
/// these 64: the two envelopes of a disjoint-hull query are alive together, and their size is most
/// of its peak memory (docs/algorithms/separation.md, "Memory").
#[derive(Clone, Debug)]
pub(crate) struct Prepared<V = DVec2> {
    /// The frame the envelope was computed in (the shadow roots are heights in it).
    pub(crate) frame: Frame,
    pub(crate) pts: Vec<V>,
    pub(crate) idx: Vec<usize>,
    /// `segs[k]`: the edge `(a, b)` carrying the envelope between `pts[k]` and `pts[k + 1]`,
    /// oriented upward; `(pts[k], pts[k + 1])` at a gap.
    pub(crate) segs: Vec<(V, V)>,
    /// `carry[k]`: `None` where no point of the chain lies between the two heights (a gap between
    /// the runs of a clipped chain: never for a connected chain).
    pub(crate) carry: Vec<Option<Carry>>,
}

impl<V: Vertex> Prepared<V> {
    /// An empty envelope in `frame`, with room for `n` visible vertices.
    pub(crate) fn with_capacity(frame: Frame, n: usize) -> Prepared<V> {
        Prepared {
            frame,
            pts: Vec::with_capacity(n),
            idx: Vec::with_capacity(n),
            segs: Vec::with_capacity(n.saturating_sub(1)),
            carry: Vec::with_capacity(n.saturating_sub(1)),
        }
    }

    /// The number of intervals (visible vertices minus one, or none).
    pub(crate) fn intervals(&self) -> usize {
        self.carry.len()
    }

    /// Whether some interval is a gap.
    pub(crate) fn has_gaps(&self) -> bool {
        self.carry.iter().any(Option::is_none)
    }

    /// The real edge between heights `k` and `k + 1`: `(a, b, caller index of a, of b)`.
    pub(crate) fn edge(&self, k: usize) -> Option<(V, V, usize, usize)> {
        let c = (*self.carry.get(k)?)?;
        let (a, b) = self.segs[k];
        Some((a, b, c.ia, c.ib))
    }

    /// The part of interval `k`'s edge on the envelope, `lo..hi` on `(a, b)`: a shadow end is the
    /// root of the height form of the visible vertex at that height, kept symbolic.
    pub(crate) fn range(&self, k: usize) -> Option<(Param<V>, Param<V>)> {
        let c = (*self.carry.get(k)?)?;
        let root = |v: V| Param::Root(self.frame.height_minus(v));
        let lo = if c.lo_root {
            root(self.pts[k])
        } else {
            Param::Start
        };
        let hi = if c.hi_root {
            root(self.pts[k + 1])
        } else {
            Param::End
        };
        Some((lo, hi))
    }

    /// Envelope interval `k` as an [`EnvEdge`], its range from [`Prepared::range`].
    pub(crate) fn env_edge(&self, k: usize) -> Option<EnvEdge<V>> {
        let c = (*self.carry.get(k)?)?;
        let (a, b) = self.segs[k];
        let (lo, hi) = self.range(k)?;
        Some(EnvEdge {
            a,
            b,
            ia: c.ia,
            ib: c.ib,
            caller: c.caller,
            lo,
            hi,
        })
    }

    /// Every interval as [`Prepared::env_edge`] gives it.
    pub(crate) fn env_edges(&self) -> Vec<Option<EnvEdge<V>>> {
        (0..self.intervals()).map(|k| self.env_edge(k)).collect()
    }
}

impl Prepared {
    /// A chain strictly increasing in height given as is (every vertex visible, each edge wholly
    /// on the envelope), for unit tests.
    #[cfg(test)]
    pub(crate) fn from_rising(pts: &[DVec2]) -> Prepared {
        let frame = Frame {
            l0: DVec2::ZERO,
            l1: DVec2::Y,
            mirror: false,
        };
        let mut out = Prepared::with_capacity(frame, pts.len());
        out.pts.extend_from_slice(pts);
        out.idx.extend(0..pts.len());
        for (k, w) in pts.windows(2).enumerate() {
            out.segs.push((w[0], w[1]));
            out.carry.push(Some(Carry {
                ia: k,
                ib: k + 1,
                caller: k,
                lo_root: false,
                hi_root: false,
            }));
        }
        out
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
    let Some(frames) = oriented::<K>(p, q, a, b) else {
        // Every vertex of both chains lies on the line.
        return Ok(Validated {
            frames: None,
            on_line: OnLine {
                p: (0..p.len()).collect(),
                q: (0..q.len()).collect(),
            },
        });
    };
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

/// [`validate_touching`] for the disjoint-hull route of two polygons (`polygon.rs`): the line
/// through `a` and `b` carries a hull edge of one polygon and has the other's hull strictly beyond
/// it, both decided by exact tests, so under a kernel with exact decisions every vertex is known to
/// lie on its side, and the `O(n)` check is skipped: only the line's orientation is read, from the
/// first vertex off it. The vertices on the line are not listed: the polygon beyond the line has
/// none, so there is no pair on the line to list them for. Under the Fast kernel, the full check.
pub(crate) fn validate_across_hull_edge<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Validated, SeparationError> {
    if !K::EXACT_DECISIONS || a == b {
        return validate_touching::<K>(p, q, a, b);
    }
    match oriented::<K>(p, q, a, b) {
        Some(frames) => Ok(Validated {
            frames: Some(frames),
            on_line: OnLine::default(),
        }),
        None => validate_touching::<K>(p, q, a, b),
    }
}

/// The frames of the line through `a` and `b` oriented so that `Q` is on its left, read from the
/// first vertex strictly off it (of `Q`, else of `P`); `None` when every vertex lies on the line.
fn oriented<K: Kernel>(p: &[DVec2], q: &[DVec2], a: DVec2, b: DVec2) -> Option<Frames> {
    let off = |pts: &[DVec2]| {
        pts.iter()
            .map(|&v| K::orient(a, b, v).sign())
            .find(|s| !s.is_zero())
    };
    let swap = match off(q) {
        Some(s) => s == Sign::Negative,
        None => off(p)? == Sign::Positive,
    };
    let (l0, l1) = if swap { (b, a) } else { (a, b) };
    Some(Frames::across(l0, l1))
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
