//! The broad phase: axis-aligned boxes and sweep-and-prune with a certified box gap.
//!
//! A query with `within = r` asks for its effects only on pairs whose distance is at most `r`
//! (decided exactly by the convex crate's `distance_within`); farther pairs are reported as
//! `beyond`. The gap between two bodies' bounding boxes is a lower bound on their distance, so a
//! pair whose box gap is **certainly** more than `r` is `beyond` without a narrow-phase query. The
//! box gap is never rounded into an answer: it is computed from the box coordinates with every
//! rounding directed down ([`Aabb::certainly_farther`]), and a pair is skipped only when that lower
//! bound exceeds `r` (rounded up when squared). A pair near the threshold goes to the narrow phase,
//! which decides it exactly. Results are therefore identical with and without the broad phase.
//!
//! Nothing else is skipped: `distance`, `closest_points`, `vertex_distance`, `hausdorff` and `cmmr`
//! without `within` need their value for every pair, and `first_contact` needs the distance at
//! every advancement step.
//!
//! [`sweep_and_prune`] picks the axis along which the box centres spread most, sorts the boxes by
//! their lower coordinate on it and scans, for each box, the boxes that start before its upper
//! coordinate plus `r`: `O(n log n + k)` for `n` boxes and `k` pairs whose intervals on that axis
//! come within `r` (Baraff 1992, "Dynamic simulation of non-penetrating rigid bodies", §6.4;
//! Cohen, Lin, Manocha, Ponamgi, I-COLLIDE, 1995, §4.2). The runner sweeps static and moving
//! boxes as two classes, so that after the first frame the static–static pairs are never walked.

use glam::DVec2;

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The lower-left corner.
    pub min: DVec2,
    /// The upper-right corner.
    pub max: DVec2,
}

/// A lower bound of `max(lo − hi, 0)` for floats `lo`, `hi`: the rounded difference moved down one
/// ulp (`RN(e)` is within half an ulp of `e`, so `next_down(RN(e)) ≤ e`).
fn gap_down(lo: f64, hi: f64) -> f64 {
    let g = lo - hi;
    if g > 0.0 { g.next_down().max(0.0) } else { 0.0 }
}

impl Aabb {
    /// The box of a set of points; `None` for no points.
    ///
    /// # Complexity
    /// `O(n)`.
    #[must_use]
    pub fn of(points: &[DVec2]) -> Option<Aabb> {
        let first = *points.first()?;
        let mut b = Aabb {
            min: first,
            max: first,
        };
        for &p in &points[1..] {
            b.min = b.min.min(p);
            b.max = b.max.max(p);
        }
        Some(b)
    }

    /// Lower bounds of the `x` and `y` gaps between the boxes (`0` where they overlap).
    fn gaps(&self, other: &Aabb) -> (f64, f64) {
        let gx = gap_down(other.min.x, self.max.x).max(gap_down(self.min.x, other.max.x));
        let gy = gap_down(other.min.y, self.max.y).max(gap_down(self.min.y, other.max.y));
        (gx, gy)
    }

    /// Whether the Euclidean gap between the boxes is certainly more than `r`: the gap's lower
    /// bound (every rounding down) exceeds `r` (its square rounded up). `false` for a NaN or
    /// infinite `r`. A `true` certifies that any two sets inside the boxes are more than `r` apart.
    ///
    /// # Complexity
    /// `O(1)`.
    #[must_use]
    pub fn certainly_farther(&self, other: &Aabb, r: f64) -> bool {
        if !(r >= 0.0 && r.is_finite()) {
            return false;
        }
        let (gx, gy) = self.gaps(other);
        if gx.max(gy) > r {
            return true;
        }
        let g2 = ((gx * gx).next_down().max(0.0) + (gy * gy).next_down().max(0.0)).next_down();
        g2 > (r * r).next_up()
    }
}

/// What [`sweep_and_prune`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SweepStats {
    /// Pairs whose intervals on the sweep axis came within `r` (examined with the full box test).
    pub examined: u64,
    /// Pairs returned.
    pub candidates: u64,
}

/// The sweep axis: `1` (`y`) when the centres of the present boxes spread more along `y` than
/// along `x` (their variance), else `0` (`x`). A choice of cost only: every axis gives the same
/// pairs. Rounded sums are fine here (no answer depends on them); a non-finite variance picks `x`.
///
/// # Complexity
/// `O(n)`.
pub(crate) fn sweep_axis(boxes: &[Option<Aabb>]) -> usize {
    let centres = || boxes.iter().flatten().map(|b| (b.min + b.max) * 0.5);
    let count = centres().count();
    if count < 2 {
        return 0;
    }
    let mean = centres().fold(DVec2::ZERO, |acc, c| acc + c) / count as f64;
    let var = centres().fold(DVec2::ZERO, |acc, c| acc + (c - mean) * (c - mean));
    usize::from(var.y > var.x)
}

/// Every pair `(i, j)`, `i < j`, of present boxes that is **not** [certainly
/// farther](Aabb::certainly_farther) than `r`, sorted.
///
/// Sweep-and-prune (Baraff 1992 §6.4; Cohen et al., I-COLLIDE 1995 §4.2) on the axis along which
/// the box centres spread most (their variance; bodies along a vertical line are swept on `y`):
/// the boxes sorted by their lower coordinate on that axis; for each, the following boxes until
/// one starts certainly more than `r` beyond its upper coordinate (all later ones do too). Absent
/// boxes (`None`) take part in no pair.
///
/// # Complexity
/// `O(n log n + k)` for `n` boxes and `k` pairs whose intervals on the sweep axis come within `r`
/// (those are counted in [`SweepStats::examined`]).
#[must_use]
pub fn sweep_and_prune(boxes: &[Option<Aabb>], r: f64) -> (Vec<(usize, usize)>, SweepStats) {
    let mut out = Vec::new();
    let (stats, _) = sweep_classes(
        boxes,
        |_| 0,
        [true, true],
        r,
        |i, j| {
            out.push((i, j));
            true
        },
    );
    out.sort_unstable();
    (out, stats)
}

/// The sweep of [`sweep_and_prune`] over boxes of two classes (`class(i)` is `0` or `1`): the
/// pairs of different classes, and the pairs within class `c` when `within_class[c]`; the other
/// pairs are never walked (each class is sorted apart, and a box scans the other class from its
/// own position, found by binary search). `emit(i, j)` (`i < j`) receives each pair not certainly
/// farther than `r`, in no particular order, and returns whether to go on: the sweep stops at the
/// first `false`, returning `true` (truncated).
///
/// Each pair is scanned once, from the box that comes first in the order (lower coordinate, then
/// index), so the result does not depend on the classes beyond which pairs are wanted.
///
/// # Complexity
/// `O(n log n + k)`, `k` the wanted pairs whose intervals on the sweep axis come within `r`.
pub(crate) fn sweep_classes(
    boxes: &[Option<Aabb>],
    class: impl Fn(usize) -> usize,
    within_class: [bool; 2],
    r: f64,
    mut emit: impl FnMut(usize, usize) -> bool,
) -> (SweepStats, bool) {
    let axis = sweep_axis(boxes);
    let lo = |i: usize| boxes[i].map_or(0.0, |b| b.min[axis]);
    let order = |i: usize, j: usize| lo(i).total_cmp(&lo(j)).then(i.cmp(&j));
    let mut lists: [Vec<usize>; 2] = [Vec::new(), Vec::new()];
    for (i, b) in boxes.iter().enumerate() {
        if b.is_some() {
            lists[class(i).min(1)].push(i);
        }
    }
    for list in &mut lists {
        list.sort_by(|&i, &j| order(i, j));
    }
    let mut stats = SweepStats::default();
    let finite = r >= 0.0 && r.is_finite();
    for c in 0..2 {
        for (p, &i) in lists[c].iter().enumerate() {
            let Some(bi) = boxes[i] else { continue };
            for (d, list) in lists.iter().enumerate() {
                if d == c && !within_class[c] {
                    continue;
                }
                let start = if d == c {
                    p + 1
                } else {
                    list.partition_point(|&j| order(j, i).is_lt())
                };
                for &j in &list[start..] {
                    let Some(bj) = boxes[j] else { continue };
                    if finite && gap_down(bj.min[axis], bi.max[axis]) > r {
                        break;
                    }
                    stats.examined += 1;
                    if !bi.certainly_farther(&bj, r) {
                        stats.candidates += 1;
                        if !emit(i.min(j), i.max(j)) {
                            return (stats, true);
                        }
                    }
                }
            }
        }
    }
    (stats, false)
}

/// The brute-force twin of [`sweep_and_prune`]: every pair tested. `O(n²)`; a test reference.
#[must_use]
pub fn all_pairs_not_farther(boxes: &[Option<Aabb>], r: f64) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            if let (Some(a), Some(b)) = (boxes[i], boxes[j]) {
                if !a.certainly_farther(&b, r) {
                    out.push((i, j));
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sq(x: f64, y: f64, s: f64) -> Option<Aabb> {
        Some(Aabb {
            min: DVec2::new(x, y),
            max: DVec2::new(x + s, y + s),
        })
    }

    #[test]
    fn certified_gap_is_conservative_at_the_threshold() {
        let a = sq(0.0, 0.0, 1.0).unwrap();
        let b = sq(3.0, 0.0, 1.0).unwrap();
        // The gap is exactly 2: not farther than 2, farther than anything certainly below 2.
        assert!(!a.certainly_farther(&b, 2.0));
        assert!(a.certainly_farther(&b, 1.999));
        // Diagonal: gap (2, 2), Euclidean 2√2 ≈ 2.83.
        let c = sq(3.0, 3.0, 1.0).unwrap();
        assert!(a.certainly_farther(&c, 2.8));
        assert!(!a.certainly_farther(&c, 2.83));
        // Overlapping boxes are never farther; NaN and infinite r never skip.
        assert!(!a.certainly_farther(&a, 0.0));
        assert!(!a.certainly_farther(&b, f64::NAN));
        assert!(!a.certainly_farther(&b, f64::INFINITY));
    }

    #[test]
    fn sweep_matches_brute_force() {
        let boxes = vec![
            sq(0.0, 0.0, 1.0),
            None,
            sq(1.5, 0.0, 1.0),
            sq(10.0, 10.0, 1.0),
            sq(0.0, 5.0, 1.0),
            sq(0.5, 0.5, 0.1),
        ];
        for r in [0.0, 0.4, 0.5, 1.0, 4.0, 100.0, f64::INFINITY] {
            let (got, stats) = sweep_and_prune(&boxes, r);
            assert_eq!(got, all_pairs_not_farther(&boxes, r), "r = {r}");
            assert_eq!(stats.candidates, got.len() as u64);
        }
    }

    #[test]
    fn the_axis_follows_the_spread_and_classes_filter_pairs() {
        // A vertical line: swept on y, each box examines its neighbour only.
        let column: Vec<Option<Aabb>> = (0..50).map(|k| sq(0.0, 2.0 * f64::from(k), 1.5)).collect();
        assert_eq!(sweep_axis(&column), 1);
        let (pairs, stats) = sweep_and_prune(&column, 0.6);
        assert_eq!(pairs, all_pairs_not_farther(&column, 0.6));
        assert_eq!((stats.examined, stats.candidates), (49, 49));
        let row: Vec<Option<Aabb>> = column
            .iter()
            .map(|b| {
                b.map(|b| Aabb {
                    min: DVec2::new(b.min.y, b.min.x),
                    max: DVec2::new(b.max.y, b.max.x),
                })
            })
            .collect();
        assert_eq!(sweep_axis(&row), 0);

        // Pseudo-random boxes in two classes: each wanted pair once, no other.
        let mut x = 7u64;
        let mut next = || {
            x = x
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let boxes: Vec<Option<Aabb>> = (0..120)
            .map(|k| {
                if k % 17 == 0 {
                    None
                } else {
                    sq(20.0 * next(), 60.0 * next(), 2.0 * next())
                }
            })
            .collect();
        let class = |i: usize| usize::from(i % 3 == 0);
        for within in [[true, true], [true, false], [false, false], [false, true]] {
            for r in [0.0, 0.5, 3.0] {
                let mut got = Vec::new();
                let (stats, stopped) = sweep_classes(&boxes, class, within, r, |i, j| {
                    got.push((i, j));
                    true
                });
                assert!(!stopped);
                got.sort_unstable();
                let want: Vec<(usize, usize)> = all_pairs_not_farther(&boxes, r)
                    .into_iter()
                    .filter(|&(i, j)| class(i) != class(j) || within[class(i)])
                    .collect();
                assert_eq!(got, want, "{within:?} {r}");
                assert_eq!(stats.candidates, want.len() as u64);
            }
        }
        // Stopping at the first refusal.
        let (stats, stopped) = sweep_classes(&boxes, |_| 0, [true, true], 3.0, |_, _| false);
        assert!(stopped);
        assert_eq!(stats.candidates, 1);
    }
}
