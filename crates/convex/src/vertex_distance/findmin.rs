//! FUNCTION FINDMIN (McKenna–Toussaint 1985, §4), with the errata applied: for every vertex `a_j` of a
//! chain `A`, its nearest vertex of a chain `B` on which `k ↦ |a_j − b_k|` is unimodal, in
//! `O(|A| + |B|)` nearer-of-two comparisons.
//!
//! Lemma 6 (general form, proof in `docs/algorithms/vertex-distance.md`): if every point of `A` lies
//! strictly on one side of a line, every vertex of `B` strictly on the other, and the edges of `B`
//! turn monotonically from pointing along the line's normal toward `A` to pointing away from it
//! (W_L listed from w_min to w_max, V_R listed from v_min to v_max), then for every `a ∈ A` the signs
//! of `|a − b_{k+1}|² − |a − b_k|²` read `(−)*(0)?(+)*`.

use core::cmp::Ordering;

use polydist_polygon::predicates::Kernel;

use super::chain::{Best, Chain};

/// Offers `(a_j, b_{k*(a_j)})` for every `a_j` of `a`, with `k*(a)` the smallest index minimizing
/// `|a − b_k|`. The paper's lines 6–12 with the errata (`k ← k − 1` in the first loop, `k ← k + 1`
/// in the second, `a_j` throughout).
pub(super) fn findmin<K: Kernel>(a: &Chain<'_>, b: &Chain<'_>, best: &mut Best) {
    let beta = b.len();
    if beta == 0 {
        return;
    }
    // Both loops move k monotonically inside [0, beta): they terminate whatever the kernel says. Under
    // exact predicates the total movement is at most 3·beta (a fixed bisector half-plane is entered and
    // left at most once each along the convex chain A: Lemmas 9–10).
    let mut k = 0;
    for j in 0..a.len() {
        let x = a.pt(j);
        // Lemma 6: while |a_j − b_{k−1}| ≤ |a_j − b_k|, the minimum is at or before k − 1.
        while k > 0 && K::cmp_dist(x, b.pt(k - 1), b.pt(k)) != Ordering::Greater {
            k -= 1;
        }
        // Lemma 6: while |a_j − b_{k+1}| < |a_j − b_k|, the minimum is after k.
        while k + 1 < beta && K::cmp_dist(x, b.pt(k + 1), b.pt(k)) == Ordering::Less {
            k += 1;
        }
        // Line 13: keep the best row minimum.
        best.offer_chains::<K>(a, j, b, k);
    }
}
