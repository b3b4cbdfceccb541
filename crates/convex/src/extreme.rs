//! Binary searches on a convex ring: the extreme vertex for a unimodal order (notes §4.2) and the
//! nearest feature to an outside point (notes §4.1).

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Orientation, Sign};

use crate::pair::{at, prev};

/// A vertex maximizing a function `f` that is unimodal along the ring `v` (rises, then falls), given
/// only the comparator `cmp(x, y) = sign(f(x) − f(y))`. For a linear `f(x) = x·c` on a strictly convex
/// ring, and for the angle seen from a point outside the polygon, `f` is unimodal.
///
/// Invariant (exact signs): the maximum lies in `(a, b]` and the ring rises on leaving `v_a` iff
/// `up_a`. Every pass shrinks `b − a`, so the loop stops after `⌈log₂ n⌉` passes whatever the signs.
/// Ties (an edge where `f` is constant) return one of the two maximizers.
pub(crate) fn extreme(v: &[DVec2], cmp: impl Fn(DVec2, DVec2) -> Sign) -> usize {
    let n = v.len();
    if n <= 1 {
        return 0;
    }
    let up = |j: usize| cmp(at(v, j + 1), at(v, j)) == Sign::Positive;
    let above = |i: usize, j: usize| cmp(at(v, i), at(v, j)) == Sign::Positive;
    let below = |i: usize, j: usize| cmp(at(v, i), at(v, j)) == Sign::Negative;
    let up0 = up(0);
    if !up0 && !above(n - 1, 0) {
        return 0;
    }
    let (mut a, mut b, mut up_a) = (0, n, up0);
    while b - a >= 2 {
        let k = a + (b - a) / 2;
        let up_k = up(k);
        // Edge k not rising and edge k − 1 not falling into k: v_k is a maximum.
        if !up_k && !above(k - 1, k) {
            return k;
        }
        if up_a {
            if !up_k || above(a, k) {
                b = k;
            } else {
                a = k;
                up_a = up_k;
            }
        } else if up_k {
            a = k;
            up_a = up_k;
        } else if below(a, k) {
            b = k;
        } else {
            a = k;
            up_a = up_k;
        }
    }
    // Reached only with b − a = 1: the better of the two (the invariant says b).
    if above(a, b) { a } else { b % n }
}

/// The vertex of `v` maximizing `x·(t − o)` (exact dot signs).
#[cfg(test)]
pub(crate) fn extreme_along<K: Kernel>(v: &[DVec2], o: DVec2, t: DVec2) -> usize {
    extreme(v, |x, y| K::dot_sign(y, x, o, t))
}

/// The vertex of `v` maximizing `x·rot90(t − o)` (exact cross signs: `(t − o) × (x − y)`).
pub(crate) fn extreme_left_of<K: Kernel>(v: &[DVec2], o: DVec2, t: DVec2) -> usize {
    extreme(v, |x, y| K::cross_sign(o, t, y, x))
}

/// The vertex of `v` minimizing `x·rot90(t − o)`.
pub(crate) fn extreme_right_of<K: Kernel>(v: &[DVec2], o: DVec2, t: DVec2) -> usize {
    extreme(v, |x, y| K::cross_sign(o, t, x, y))
}

/// The nearest feature of a convex polygon to a point outside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Nearest {
    /// Vertex `j` is nearest.
    Vertex(usize),
    /// The foot of the point on edge `j` is strictly inside the edge.
    Edge(usize),
}

/// One edge `j` of the polygon `v` (`n ≥ 3`, CCW) with `s` strictly to its right (visible from `s`),
/// or `None` when `s` is in the closed polygon. The fan search of point location: `O(log n)` orients.
fn visible_edge<K: Kernel>(v: &[DVec2], s: DVec2) -> Option<usize> {
    let n = v.len();
    if K::orient(v[0], v[1], s) == Orientation::Clockwise {
        return Some(0);
    }
    if K::orient(v[n - 1], v[0], s) == Orientation::Clockwise {
        return Some(n - 1);
    }
    // s is in the wedge at v_0: the largest i in [1, n − 2] with orient(v_0, v_i, s) not clockwise.
    let (mut i, mut hi) = (1, n - 1);
    while hi - i > 1 {
        let mid = i + (hi - i) / 2;
        if K::orient(v[0], v[mid], s) == Orientation::Clockwise {
            hi = mid;
        } else {
            i = mid;
        }
    }
    (K::orient(v[i], v[i + 1], s) == Orientation::Clockwise).then_some(i)
}

/// The nearest feature of the polygon `v` (`n ≥ 3`) to `s`, or `None` when `s` is in the closed polygon.
///
/// The two tangent vertices from `s` bound the chain visible from `s` (the extreme search with the
/// angular order `orient(s, y, x)`); along it the distance is convex, so the nearest vertex is the first
/// `j` with `g(j) = sign((s − v_j)·(v_{j+1} − v_j)) ≤ 0`, or the edge before it when the foot falls
/// inside. `O(log n)` exact predicates.
pub(crate) fn nearest_feature<K: Kernel>(v: &[DVec2], s: DVec2) -> Option<Nearest> {
    let n = v.len();
    visible_edge::<K>(v, s)?;
    // Visible chain: CCW from the most counter-clockwise vertex around s to the most clockwise.
    let start = extreme(v, |x, y| K::orient(s, y, x).sign());
    let end = extreme(v, |x, y| K::orient(s, x, y).sign());
    let end = if end >= start { end } else { end + n };
    // First j in [start, end) with g(j) ≤ 0, else end.
    let g_pos = |j: usize| K::dot_sign(at(v, j), s, at(v, j), at(v, j + 1)) == Sign::Positive;
    let (mut lo, mut hi) = (start, end);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if g_pos(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    let j = lo;
    // The foot on edge j − 1 is inside when g(j − 1) > 0 (known for j > start) and (s − v_j)·(v_{j−1} − v_j) > 0.
    if j > start && K::dot_sign(at(v, j), s, at(v, j), prev(v, j)) == Sign::Positive {
        Some(Nearest::Edge((j + n - 1) % n))
    } else {
        Some(Nearest::Vertex(j % n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_polygon::predicates::Exact;

    /// Small strictly convex polygons with exact ties: a square, a regular-ish hexagon on the lattice,
    /// a triangle, a pentagon with a long edge.
    fn shapes() -> Vec<Vec<DVec2>> {
        let v = |pts: &[(f64, f64)]| {
            pts.iter()
                .map(|&(x, y)| DVec2::new(x, y))
                .collect::<Vec<_>>()
        };
        vec![
            v(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]),
            v(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]),
            v(&[
                (2.0, 0.0),
                (4.0, 1.0),
                (4.0, 3.0),
                (2.0, 4.0),
                (0.0, 3.0),
                (0.0, 1.0),
            ]),
            v(&[(0.0, 0.0), (8.0, 0.0), (9.0, 1.0), (4.0, 5.0), (-1.0, 1.0)]),
            v(&[
                (0.0, 0.0),
                (5.0, -1.0),
                (9.0, 0.0),
                (11.0, 3.0),
                (9.0, 6.0),
                (5.0, 7.0),
                (0.0, 6.0),
                (-2.0, 3.0),
            ]),
        ]
    }

    #[test]
    fn extreme_is_a_maximizer_for_every_rotation_and_direction() {
        for shape in shapes() {
            let n = shape.len();
            for r in 0..n {
                let ring: Vec<DVec2> = (0..n).map(|i| shape[(i + r) % n]).collect();
                for e in 0..n {
                    let (a, b) = (ring[e], ring[(e + 1) % n]);
                    let d = b - a;
                    let normal = DVec2::new(d.y, -d.x);
                    for c in [d, -d, normal, -normal, DVec2::X, DVec2::new(1.0, 3.0)] {
                        let k = extreme_along::<Exact>(&ring, DVec2::ZERO, c);
                        let best = ring
                            .iter()
                            .map(|x| x.dot(c))
                            .fold(f64::NEG_INFINITY, f64::max);
                        // Small integers: the dot products are exact in f64.
                        assert_eq!(ring[k].dot(c), best, "rotation {r}, direction {c}");
                    }
                }
            }
        }
    }

    #[test]
    fn nearest_feature_matches_a_scan_for_every_rotation() {
        for shape in shapes() {
            let n = shape.len();
            for r in 0..n {
                let ring: Vec<DVec2> = (0..n).map(|i| shape[(i + r) % n]).collect();
                for xi in -6..=16 {
                    for yi in -6..=12 {
                        let s = DVec2::new(f64::from(xi), f64::from(yi));
                        let got = nearest_feature::<Exact>(&ring, s);
                        let inside = (0..n).all(|j| {
                            Exact::orient(ring[j], ring[(j + 1) % n], s) != Orientation::Clockwise
                        });
                        let Some(f) = got else {
                            assert!(inside, "{s} reported inside");
                            continue;
                        };
                        assert!(!inside, "{s} is inside");
                        // Exact squared distance of the reported feature equals the minimum over edges
                        // (rational arithmetic via the oracle).
                        let sq =
                            |j: usize| polydist_oracle::sq_dist_ps(s, ring[j], ring[(j + 1) % n]);
                        let best = (0..n).map(sq).min().expect("edges");
                        let got_sq = match f {
                            Nearest::Vertex(j) => polydist_oracle::sq_dist_pp(s, ring[j]),
                            Nearest::Edge(j) => sq(j),
                        };
                        assert_eq!(got_sq, best, "point {s}, rotation {r}, got {f:?}");
                        if let Nearest::Edge(j) = f {
                            // The foot is strictly inside the edge.
                            let (a, b) = (ring[j], ring[(j + 1) % n]);
                            assert_eq!(Exact::dot_sign(a, s, a, b), Sign::Positive);
                            assert_eq!(Exact::dot_sign(b, s, b, a), Sign::Positive);
                        }
                    }
                }
            }
        }
    }
}
