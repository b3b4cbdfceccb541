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
//! [`sweep_and_prune`] sorts the boxes by their lower `x` and scans, for each box, the boxes that
//! start before its upper `x` plus `r`: `O(n log n + k)` for `n` boxes and `k` pairs whose
//! `x`-intervals come within `r` (Baraff 1992, "Dynamic simulation of non-penetrating rigid
//! bodies", §6.4; Cohen, Lin, Manocha, Ponamgi, I-COLLIDE, 1995, §4.2).

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
    /// Pairs whose `x`-intervals came within `r` (examined with the full box test).
    pub examined: u64,
    /// Pairs returned.
    pub candidates: u64,
}

/// Every pair `(i, j)`, `i < j`, of present boxes that is **not** [certainly
/// farther](Aabb::certainly_farther) than `r`, sorted.
///
/// Sweep-and-prune on `x` (Baraff 1992 §6.4; Cohen et al., I-COLLIDE 1995 §4.2): the boxes sorted
/// by `min.x`; for each, the following boxes until one starts certainly more than `r` beyond its
/// `max.x` (all later ones do too). Absent boxes (`None`) take part in no pair.
///
/// # Complexity
/// `O(n log n + k)` for `n` boxes and `k` pairs whose `x`-intervals come within `r` (those are
/// counted in [`SweepStats::examined`]).
#[must_use]
pub fn sweep_and_prune(boxes: &[Option<Aabb>], r: f64) -> (Vec<(usize, usize)>, SweepStats) {
    sweep_pairs(boxes, r, |_, _| true)
}

/// [`sweep_and_prune`] restricted to the pairs `accept` takes (the two layers of a batch): the
/// others are passed over by the sweep without the box test.
pub(crate) fn sweep_pairs(
    boxes: &[Option<Aabb>],
    r: f64,
    accept: impl Fn(usize, usize) -> bool,
) -> (Vec<(usize, usize)>, SweepStats) {
    let mut order: Vec<usize> = (0..boxes.len()).filter(|&i| boxes[i].is_some()).collect();
    let lo = |i: usize| boxes[i].map_or(0.0, |b| b.min.x);
    order.sort_by(|&i, &j| lo(i).total_cmp(&lo(j)).then(i.cmp(&j)));
    let mut stats = SweepStats::default();
    let mut out = Vec::new();
    let finite = r >= 0.0 && r.is_finite();
    for (s, &i) in order.iter().enumerate() {
        let Some(bi) = boxes[i] else { continue };
        for &j in &order[s + 1..] {
            let Some(bj) = boxes[j] else { continue };
            if finite && gap_down(bj.min.x, bi.max.x) > r {
                break;
            }
            if !accept(i, j) {
                continue;
            }
            stats.examined += 1;
            if !bi.certainly_farther(&bj, r) {
                out.push((i.min(j), i.max(j)));
            }
        }
    }
    out.sort_unstable();
    stats.candidates = out.len() as u64;
    (out, stats)
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
}
