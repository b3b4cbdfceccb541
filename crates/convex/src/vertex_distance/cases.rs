//! Step 9 of TENSTEP (McKenna–Toussaint 1985, §5): the closest pair between the outer chains
//! `A = V_L` (listed from `v_max` down to `v_min`) and `B = W_R` (listed from `w_min` up to `w_max`),
//! through the nine cases of the missing Fig. 5 and the sub-cases 6.1–6.4 of the missing Fig. 8.
//!
//! `U = CH(A ∪ B)`. Each end of each chain may have a run of vertices that are not corners of `U`
//! ("hidden"); which of `v_max, w_max, v_min, w_min` are corners gives the case (reconstruction in
//! `docs/algorithms/vertex-distance.md`):
//!
//! | top \ bottom | both corners | `w_min` hidden | `v_min` hidden |
//! |---|---|---|---|
//! | both corners | 1 | 2 | 3 |
//! | `w_max` hidden | 4 | 5 | 6 |
//! | `v_max` hidden | 7 | 8 | 9 |
//!
//! Cases 3, 8, 9 reduce to 2, 6, 5 by the x-mirror, case 4 to 2 by the y-mirror, case 7 to 2 by the
//! half-turn (the paper's negated coordinates). A mirror here relabels the chains and flips the sign
//! of the frame's predicates: no coordinate is changed.

use core::cmp::Ordering;

use polydist_polygon::predicates::{Kernel, Sign};

use super::chain::{Best, Chain, Frame};
use super::scanset::{scanset, userng};
use super::stats::bump;

/// The number of hidden (non-corner of `U`) vertices at each end of `A` and `B`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Hidden {
    /// Leading vertices of `A` (from `v_max` down).
    pub(super) a_top: usize,
    /// Trailing vertices of `A` (up to `v_min`).
    pub(super) a_bot: usize,
    /// Leading vertices of `B` (from `w_min` up).
    pub(super) b_bot: usize,
    /// Trailing vertices of `B` (up to `w_max`).
    pub(super) b_top: usize,
}

impl Hidden {
    /// The case of Fig. 5: `3·T + Bo + 1`, with `T`, `Bo` = 0 (both extremes are corners of `U`),
    /// 1 (`Q`'s extreme is hidden), 2 (`P`'s extreme is hidden) at the top and at the bottom.
    pub(super) fn case(self) -> usize {
        let t = if self.b_top > 0 {
            1
        } else if self.a_top > 0 {
            2
        } else {
            0
        };
        let bo = if self.b_bot > 0 {
            1
        } else if self.a_bot > 0 {
            2
        } else {
            0
        };
        3 * t + bo + 1
    }
}

/// Finds the hidden runs by walking each chain from its extreme toward the other polygon's extreme,
/// with exact orientations in the frame (collinear counts as hidden). Only the chain whose extreme is
/// lower at the top (higher at the bottom) can be hidden there (the extreme of `U` in that direction
/// is `v_max` or `w_max`; equal heights put both on `U`).
pub(super) fn hidden<K: Kernel>(a: &Chain<'_>, b: &Chain<'_>, f: &Frame) -> Hidden {
    let (p, q) = (a.len(), b.len());
    let mut h = Hidden::default();
    if p == 0 || q == 0 {
        return h;
    }
    let (v_max, v_min, w_min, w_max) = (a.pt(0), a.last(), b.pt(0), b.last());
    match f.ycmp::<K>(v_max, w_max) {
        Ordering::Greater => {
            // b_j is hidden behind the segment from b_{j−1} to v_max.
            let mut j = q - 1;
            while j > 0 && f.orient::<K>(b.pt(j - 1), v_max, b.pt(j)) != Sign::Negative {
                j -= 1;
            }
            h.b_top = q - 1 - j;
        }
        Ordering::Less => {
            let mut i = 0;
            while i + 1 < p && f.orient::<K>(w_max, a.pt(i + 1), a.pt(i)) != Sign::Negative {
                i += 1;
            }
            h.a_top = i;
        }
        Ordering::Equal => {}
    }
    match f.ycmp::<K>(w_min, v_min) {
        Ordering::Greater => {
            let mut j = 0;
            while j + 1 < q && f.orient::<K>(v_min, b.pt(j + 1), b.pt(j)) != Sign::Negative {
                j += 1;
            }
            h.b_bot = j;
        }
        Ordering::Less => {
            let mut i = p - 1;
            while i > 0 && f.orient::<K>(a.pt(i - 1), w_min, a.pt(i)) != Sign::Negative {
                i -= 1;
            }
            h.a_bot = p - 1 - i;
        }
        Ordering::Equal => {}
    }
    // Each chain keeps at least one corner of U (its extreme toward the other polygon); this only
    // matters when a non-exact kernel contradicts itself.
    h.a_bot = h.a_bot.min(p - 1 - h.a_top);
    h.b_top = h.b_top.min(q - 1 - h.b_bot);
    h
}

/// One step-9 problem in some (possibly mirrored) frame.
#[derive(Clone, Copy, Debug)]
pub(super) struct Step9<'a> {
    /// `V_L` in the frame, from top to bottom.
    pub(super) a: Chain<'a>,
    /// `W_R` in the frame, from bottom to top.
    pub(super) b: Chain<'a>,
    /// The frame.
    pub(super) f: Frame,
    /// The hidden runs in this frame.
    pub(super) h: Hidden,
}

impl<'a> Step9<'a> {
    /// The x-mirror (the paper's "negate the x-coordinates"): the right chain becomes the left one.
    pub(super) fn mirror_x(self) -> Self {
        let h = self.h;
        Step9 {
            a: self.b.rev(),
            b: self.a.rev(),
            f: self.f.mirror_x(),
            h: Hidden {
                a_top: h.b_top,
                a_bot: h.b_bot,
                b_bot: h.a_bot,
                b_top: h.a_top,
            },
        }
    }

    /// The y-mirror (the paper's "negate the y-coordinates").
    pub(super) fn mirror_y(self) -> Self {
        let h = self.h;
        Step9 {
            a: self.a.rev(),
            b: self.b.rev(),
            f: self.f.mirror_y(),
            h: Hidden {
                a_top: h.a_bot,
                a_bot: h.a_top,
                b_bot: h.b_top,
                b_top: h.b_bot,
            },
        }
    }

    /// The half-turn (both coordinates negated).
    pub(super) fn half_turn(self) -> Self {
        let h = self.h;
        Step9 {
            a: self.b,
            b: self.a,
            f: self.f.half_turn(),
            h: Hidden {
                a_top: h.b_bot,
                a_bot: h.b_top,
                b_bot: h.a_top,
                b_top: h.a_bot,
            },
        }
    }

    /// Case 1: `V_L ∪ W_R` is in convex position: USERNG(V_L, W_R).
    fn case1<K: Kernel>(&self, best: &mut Best) {
        userng::<K>(&self.a, &self.b.rev(), best);
    }

    /// FUNCTION CASE2 (`w_min` hidden): `W' = B_U`, `W'' = B_bot`, `V'` above `w_min`, `V''` the rest;
    /// USERNG(V_L, W'), USERNG(V', W''), SCANSET(w_min, V'').
    fn case2<K: Kernel>(&self, best: &mut Best) {
        let (a, b, f) = (self.a, self.b, self.f);
        let (p, q) = (a.len(), b.len());
        let w_min = b.pt(0);
        let w1 = b.sub(self.h.b_bot, q);
        let w2 = b.sub(0, self.h.b_bot);
        let n1 = a.prefix(|x| f.ycmp::<K>(x, w_min) == Ordering::Greater);
        userng::<K>(&a, &w1.rev(), best);
        userng::<K>(&a.sub(0, n1), &w2.rev(), best);
        scanset::<K>(&b, 0, &a.sub(n1, p), best);
    }

    /// FUNCTION CASE5 (`w_max` and `w_min` hidden): `W' = B_top`, `W'' = B_U`, `W''' = B_bot`; `V'` not
    /// below `w_max`, `V'''` not above `w_min`, `V''` between. SCANSET(w_max, V'),
    /// USERNG(V'' ∪ V''', W'), USERNG(V_L, W''), USERNG(V' ∪ V'', W'''), SCANSET(w_min, V''').
    fn case5<K: Kernel>(&self, best: &mut Best) {
        let (a, b, f, h) = (self.a, self.b, self.f, self.h);
        let (p, q) = (a.len(), b.len());
        let (w_min, w_max) = (b.pt(0), b.last());
        let top = q.saturating_sub(h.b_top);
        let (w1, w2, w3) = (b.sub(top, q), b.sub(h.b_bot, top), b.sub(0, h.b_bot));
        let n1 = a.prefix(|x| f.ycmp::<K>(x, w_max) != Ordering::Less);
        let n3 = a
            .suffix(|x| f.ycmp::<K>(x, w_min) != Ordering::Greater)
            .min(p - n1);
        scanset::<K>(&b, q - 1, &a.sub(0, n1), best);
        userng::<K>(&a.sub(n1, p), &w1.rev(), best);
        userng::<K>(&a, &w2.rev(), best);
        userng::<K>(&a.sub(0, p - n3), &w3.rev(), best);
        scanset::<K>(&b, 0, &a.sub(p - n3, p), best);
    }

    /// Case 6 (`w_max` and `v_min` hidden), sub-cases 6.1–6.4; returns the sub-case (0 for 6.1).
    ///
    /// `v_c` = lowest corner of `U` on `A`, `w_c` = highest corner on `B`, `v_h` = lowest vertex of `A`
    /// above `w_max`, `w_h` = highest vertex of `B` below `v_min`. `v_c`, `v_h` cut `A` into `V'` (down
    /// to the higher cut, inclusive), `V''`, `V'''` (below the lower cut); `w_c`, `w_h` cut `B` into
    /// `W'''` (up to the lower cut, inclusive), `W''`, `W'` (above the higher cut).
    fn case6<K: Kernel>(&self, best: &mut Best) -> usize {
        let (a, b, f, h) = (self.a, self.b, self.f, self.h);
        let (p, q) = (a.len(), b.len());
        let (v_min, w_max) = (a.last(), b.last());
        let c_a = p - 1 - h.a_bot;
        let c_b = q - 1 - h.b_top;
        // v_max is above w_max and w_min below v_min in this case: both prefixes are non-empty
        // (`max(1)` only guards a non-exact kernel).
        let h_a = a
            .prefix(|x| f.ycmp::<K>(x, w_max) == Ordering::Greater)
            .max(1)
            - 1;
        let h_b = b.prefix(|x| f.ycmp::<K>(x, v_min) == Ordering::Less).max(1) - 1;
        let v_c_above = c_a < h_a;
        let w_c_above = c_b > h_b;
        let (a_hi, a_lo) = (c_a.min(h_a), c_a.max(h_a));
        let (b_lo, b_hi) = (c_b.min(h_b), c_b.max(h_b));
        let v1 = a.incl(0, a_hi);
        let v12 = a.incl(0, a_lo);
        let v23 = a.sub(a_hi + 1, p);
        let v3 = a.sub(a_lo + 1, p);
        let w3 = b.incl(0, b_lo);
        let w2 = b.incl(b_lo + 1, b_hi);
        let w1 = b.sub(b_hi + 1, q);
        let sub = match (v_c_above, w_c_above) {
            (true, true) => 0,
            (true, false) => 1,
            (false, true) => 2,
            (false, false) => 3,
        };
        // (i) SCANSET(w_max, ·): w_max 2-dominates W' and every vertex above w_max 2-dominates W'.
        scanset::<K>(&b, q - 1, if v_c_above { &v12 } else { &v1 }, best);
        // (ii) USERNG(·, W').
        userng::<K>(if v_c_above { &v3 } else { &v23 }, &w1.rev(), best);
        // (iii) USERNG(V_L, W'') when W'' is on U, else SCANSET(w_h, V_L): W'' lies below v_min.
        if w_c_above {
            userng::<K>(&a, &w2.rev(), best);
        } else {
            scanset::<K>(&b, h_b, &a, best);
        }
        // (iv) USERNG(·, W''').
        userng::<K>(if v_c_above { &v1 } else { &v12 }, &w3.rev(), best);
        // (v) SCANSET(v_min, W'''): v_min 4-dominates the hidden bottom of A, W''' lies below v_min.
        scanset::<K>(&a, p - 1, &w3, best);
        sub
    }
}

/// Step 9: the closest pair between `a = V_L` (top to bottom) and `b = W_R` (bottom to top).
pub(super) fn step9<K: Kernel>(a: Chain<'_>, b: Chain<'_>, f: Frame, best: &mut Best) {
    if a.is_empty() || b.is_empty() {
        return;
    }
    let h = hidden::<K>(&a, &b, &f);
    let case = h.case();
    bump(|s| s.cases[case] += 1);
    let s = Step9 { a, b, f, h };
    match case {
        2 => s.case2::<K>(best),
        3 => s.mirror_x().case2::<K>(best),
        4 => s.mirror_y().case2::<K>(best),
        5 => s.case5::<K>(best),
        6 => {
            let sub = s.case6::<K>(best);
            bump(|c| c.sub_cases_6[sub] += 1);
        }
        7 => s.half_turn().case2::<K>(best),
        8 => {
            let sub = s.mirror_x().case6::<K>(best);
            bump(|c| c.sub_cases_8[sub] += 1);
        }
        9 => s.mirror_x().case5::<K>(best),
        _ => s.case1::<K>(best),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(a_top: usize, a_bot: usize, b_bot: usize, b_top: usize) -> Hidden {
        Hidden {
            a_top,
            a_bot,
            b_bot,
            b_top,
        }
    }

    /// The paper's reductions (§5): 3 → 2, 9 → 5, 8 → 6 by the x-mirror, 4 → 2 by the y-mirror,
    /// 7 → 2 by the half-turn, read off the hidden runs.
    #[test]
    fn reductions_map_cases_as_the_paper_says() {
        let ring = [glam::DVec2::ZERO, glam::DVec2::X, glam::DVec2::Y];
        let caller = [0, 1, 2];
        let c = Chain::ccw(
            &ring,
            super::super::chain::Callers::Table(&caller),
            true,
            0,
            2,
        );
        let f = Frame {
            t0: glam::DVec2::ZERO,
            t1: glam::DVec2::Y,
            flip_y: false,
            flip_o: false,
        };
        let s = |h: Hidden| Step9 { a: c, b: c, f, h };
        assert_eq!(h(0, 0, 0, 0).case(), 1);
        assert_eq!(h(0, 0, 1, 0).case(), 2);
        assert_eq!(h(0, 1, 0, 0).case(), 3);
        assert_eq!(h(0, 0, 0, 1).case(), 4);
        assert_eq!(h(0, 0, 1, 1).case(), 5);
        assert_eq!(h(0, 1, 0, 1).case(), 6);
        assert_eq!(h(1, 0, 0, 0).case(), 7);
        assert_eq!(h(1, 0, 1, 0).case(), 8);
        assert_eq!(h(1, 1, 0, 0).case(), 9);
        assert_eq!(s(h(0, 1, 0, 0)).mirror_x().h.case(), 2);
        assert_eq!(s(h(1, 1, 0, 0)).mirror_x().h.case(), 5);
        assert_eq!(s(h(1, 0, 1, 0)).mirror_x().h.case(), 6);
        assert_eq!(s(h(0, 0, 0, 1)).mirror_y().h.case(), 2);
        assert_eq!(s(h(1, 0, 0, 0)).half_turn().h.case(), 2);
    }
}
