//! The wedges `W(p)` by two hull scans (tangents, not visibility), Lemma 3's `α(p) ≥ 90°` test, and
//! wedge membership.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign};

use crate::chain::Prepared;
use crate::frame::Frame;
use crate::site::Vertex;

/// A vertex that survived Lemmas 2 and 3, with the points its wedge's rays pass through
/// (`None`: the ray is parallel to the line, `p^± = ±∞`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Apex<V = DVec2> {
    pub(crate) pt: V,
    /// The caller's index.
    pub(crate) idx: usize,
    /// `h(p)`: the upper ray of `W(p)` passes through it.
    pub(crate) hi: Option<V>,
    /// `l(p)`: the lower ray of `W(p)` passes through it.
    pub(crate) lo: Option<V>,
}

/// `h(p_i)` for every vertex of a chain strictly increasing in height: the point above `p_i` whose
/// direction from `p_i` makes the smallest angle with the direction toward the line, when that
/// angle is below 90° (else `None`). One top-to-bottom scan keeping the line-facing hull of the
/// vertices above as a stack (Andrew's monotone chain); collinear points are popped so the farthest
/// tangent point is kept. Every vertex is pushed and popped at most once: at most `2n` orientation
/// tests and `n` depth tests.
pub(crate) fn upper_tangents<K: Kernel, V: Vertex>(pts: &[V], frame: Frame) -> Vec<Option<usize>> {
    tangents::<K, V>(pts, frame, true)
}

/// `l(p_i)`, the mirror image of [`upper_tangents`] (bottom-to-top scan).
pub(crate) fn lower_tangents<K: Kernel, V: Vertex>(pts: &[V], frame: Frame) -> Vec<Option<usize>> {
    tangents::<K, V>(pts, frame, false)
}

fn tangents<K: Kernel, V: Vertex>(pts: &[V], frame: Frame, upper: bool) -> Vec<Option<usize>> {
    let n = pts.len();
    let mut out = vec![None; n];
    let mut stack: Vec<usize> = Vec::with_capacity(n);
    // Going down, a candidate further along the hull wins when it is counter-clockwise (or collinear,
    // hence farther) of the current one as seen from the new point; going up, when it is clockwise.
    let stop_on = if upper {
        Sign::Negative
    } else {
        Sign::Positive
    };
    let mut visit = |i: usize| {
        let p = pts[i];
        while let [.., c2, c1] = stack[..] {
            if frame.orient::<K, _>(p, pts[c1], pts[c2]) != stop_on {
                stack.pop();
            } else {
                break;
            }
        }
        if let Some(&t) = stack.last() {
            if cmp_depth::<K, V>(frame, pts[t], p) == Ordering::Less {
                out[i] = Some(t);
            }
        }
        stack.push(i);
    };
    if upper {
        (0..n).rev().for_each(&mut visit);
    } else {
        (0..n).for_each(&mut visit);
    }
    out
}

/// Lemmas 2–3: the wedges of a prepared chain and the vertices with `α(p) ≥ 90°`, i.e.
/// `(h − p)·(l − p) ≤ 0` (one degree-2 dot sign; `α ≥ 90°` when a ray is parallel to the line).
/// The wedges are those of the whole prepared chain. `O(n)`.
pub(crate) fn apexes<K: Kernel, V: Vertex>(prep: &Prepared<V>, frame: Frame) -> Vec<Apex<V>> {
    let hi = upper_tangents::<K, V>(&prep.pts, frame);
    let lo = lower_tangents::<K, V>(&prep.pts, frame);
    let mut out = Vec::with_capacity(prep.pts.len());
    for (i, &pt) in prep.pts.iter().enumerate() {
        let (h, l) = (hi[i].map(|k| prep.pts[k]), lo[i].map(|k| prep.pts[k]));
        let keep = match (h, l) {
            (Some(h), Some(l)) => V::dot_sign::<K>(pt, h, pt, l) != Sign::Positive,
            _ => true,
        };
        if keep {
            out.push(Apex {
                pt,
                idx: prep.idx[i],
                hi: h,
                lo: l,
            });
        }
    }
    out
}

/// `frame.cmp_depth(a, b)`, the sign of `±(a − b) × d` (`d` the line's direction), answered
/// `Equal` without the kernel when both products of the cross product have an exactly zero
/// difference as a factor (`a` and `b` on one line parallel to an axis-parallel separating line):
/// the exact value is then 0, the one case a floating-point filter cannot certify (Robust would
/// pay its exact stage), and every kernel answers `Equal`.
#[inline]
pub(crate) fn cmp_depth<K: Kernel, V: Vertex>(frame: Frame, a: V, b: V) -> Ordering {
    let (l0, l1) = (frame.l0, frame.l1);
    // (Only worth testing where the kernel has an exact stage to spare.)
    if K::EXACT_DECISIONS {
        if let (Some(a), Some(b)) = (a.as_input(), b.as_input()) {
            if (a.x == b.x || l1.y == l0.y) && (a.y == b.y || l1.x == l0.x) {
                return Ordering::Equal;
            }
        }
    }
    frame.cmp_depth::<K, _>(a, b)
}

/// `z ∈ W(a)`: `z` strictly inside the open wedge at `a` (frame of `a`'s chain), strictly below the
/// upper ray and strictly above the lower ray. Two degree-2 tests.
#[inline]
pub(crate) fn in_wedge<K: Kernel, V: Vertex>(frame: Frame, a: &Apex<V>, z: V) -> bool {
    let below_upper = match a.hi {
        Some(h) => frame.orient::<K, _>(a.pt, h, z) == Sign::Positive,
        None => cmp_depth::<K, V>(frame, z, a.pt) == Ordering::Less,
    };
    below_upper
        && match a.lo {
            Some(l) => frame.orient::<K, _>(a.pt, l, z) == Sign::Negative,
            None => cmp_depth::<K, V>(frame, z, a.pt) == Ordering::Less,
        }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::Exact;

    /// A random chain strictly increasing in height (frame = plain coordinates, line x = 0, P side
    /// x ≥ 0), integer coordinates so ties are frequent.
    fn chain(rng: &mut SplitMix64, n: usize) -> Vec<DVec2> {
        let mut ys: Vec<i64> = (0..n).map(|_| rng.range_i64(0, 3 * n as i64)).collect();
        ys.sort_unstable();
        ys.dedup();
        ys.into_iter()
            .map(|y| DVec2::new(rng.range_i64(0, 8) as f64, y as f64))
            .collect()
    }

    const P: Frame = Frame {
        l0: DVec2::ZERO,
        l1: DVec2::new(0.0, 1.0), // P = x ≥ 0 is on the right of this direction
        mirror: false,
    };

    /// The O(n²) definition of `h(p_i)`: the point above with the largest polar angle, the farthest
    /// on ties, kept only when strictly nearer to the line.
    fn upper_def(pts: &[DVec2], i: usize) -> Option<usize> {
        let p = pts[i];
        let mut best: Option<usize> = None;
        for j in i + 1..pts.len() {
            best = match best {
                None => Some(j),
                Some(b) => match Exact::orient(p, pts[b], pts[j]).sign() {
                    Sign::Positive => Some(j),
                    Sign::Zero if (pts[j] - p).length_squared() > (pts[b] - p).length_squared() => {
                        Some(j)
                    }
                    _ => Some(b),
                },
            };
        }
        best.filter(|&b| pts[b].x < p.x)
    }

    fn lower_def(pts: &[DVec2], i: usize) -> Option<usize> {
        let p = pts[i];
        let mut best: Option<usize> = None;
        for j in 0..i {
            best = match best {
                None => Some(j),
                Some(b) => match Exact::orient(p, pts[b], pts[j]).sign() {
                    Sign::Negative => Some(j),
                    Sign::Zero if (pts[j] - p).length_squared() > (pts[b] - p).length_squared() => {
                        Some(j)
                    }
                    _ => Some(b),
                },
            };
        }
        best.filter(|&b| pts[b].x < p.x)
    }

    #[test]
    fn frame_matches_plain_coordinates() {
        let (a, b) = (DVec2::new(3.0, 1.0), DVec2::new(1.0, 2.0));
        assert_eq!(P.cmp_depth::<Exact, _>(a, b), Ordering::Greater);
        assert_eq!(P.cmp_height::<Exact, _>(a, b), Ordering::Less);
        assert_eq!(P.depth_sign::<Exact, _>(a), Sign::Positive);
        assert_eq!(
            P.depth_sign::<Exact, _>(DVec2::new(-1.0, 0.0)),
            Sign::Negative
        );
    }

    #[test]
    fn hull_scans_match_the_definition() {
        let mut rng = SplitMix64::new(11);
        for n in [1usize, 2, 3, 5, 8, 13, 30, 60] {
            for _ in 0..200 {
                let pts = chain(&mut rng, n);
                let up = upper_tangents::<Exact, _>(&pts, P);
                let lo = lower_tangents::<Exact, _>(&pts, P);
                for i in 0..pts.len() {
                    assert_eq!(up[i], upper_def(&pts, i), "upper {i} of {pts:?}");
                    assert_eq!(lo[i], lower_def(&pts, i), "lower {i} of {pts:?}");
                }
            }
        }
    }

    /// Lemma 3 as dominance: every vertex dropped for `α < 90°` is strictly farther from every point
    /// on the other side of the line (sampled on a grid, including the line) than `h` or `l`.
    #[test]
    fn pruned_vertices_are_strictly_dominated() {
        let mut rng = SplitMix64::new(12);
        let mut pruned = 0;
        for n in [3usize, 6, 12, 25] {
            for _ in 0..150 {
                let pts = chain(&mut rng, n);
                let prep = Prepared::<DVec2>::from_rising(&pts);
                let kept: Vec<usize> = apexes::<Exact, _>(&prep, P).iter().map(|a| a.idx).collect();
                let up = upper_tangents::<Exact, _>(&pts, P);
                let lo = lower_tangents::<Exact, _>(&pts, P);
                for i in (0..pts.len()).filter(|i| !kept.contains(i)) {
                    pruned += 1;
                    let (h, l) = (pts[up[i].unwrap()], pts[lo[i].unwrap()]);
                    for qx in -6..=0 {
                        for qy in -4..3 * n as i64 + 4 {
                            let q = DVec2::new(qx as f64, qy as f64);
                            assert!(
                                Exact::cmp_dist(q, h, pts[i]) == Ordering::Less
                                    || Exact::cmp_dist(q, l, pts[i]) == Ordering::Less,
                                "vertex {i} of {pts:?} not dominated at {q}"
                            );
                        }
                    }
                }
            }
        }
        assert!(
            pruned > 100,
            "the generator must exercise Lemma 3 ({pruned})"
        );
    }
}
