//! Plain f64 decides wrongly where the Robust kernel is right (Kettner et al.'s classroom example).

mod common;

use common::{nudge, orient};
use glam::DVec2;
use polydist_predicates::{Fast, Kernel, Robust};

#[test]
fn fast_misjudges_near_collinear_points_that_robust_gets_right() {
    // Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in geometric
    // computations" (2008): p = (0.5 + i·ulp, 0.5 + j·ulp), q = (12, 12), r = (24, 24).
    let (q, r) = (DVec2::new(12.0, 12.0), DVec2::new(24.0, 24.0));
    let mut fast_wrong = 0;
    for i in 0..64 {
        for j in 0..64 {
            let p = DVec2::new(nudge(0.5, i), nudge(0.5, j));
            let exact = orient(p, q, r);
            assert_eq!(
                Robust::orient(p, q, r).sign().to_ordering() as i8,
                exact,
                "robust at ({i}, {j})"
            );
            if Fast::orient(p, q, r).sign().to_ordering() as i8 != exact {
                fast_wrong += 1;
            }
        }
    }
    assert!(fast_wrong > 0, "plain f64 was right on the whole grid");
}
