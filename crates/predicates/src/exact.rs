//! Exact rational constructions, for the Exact kernel's results and for checking the others.
//!
//! Every finite `f64` is a dyadic rational, so squared distances between input points and from an input
//! point to an input segment are rationals computed here without rounding.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use glam::DVec2;

use crate::poly::decompose;

/// The exact value of a finite `f64` as a rational; `None` for NaN and infinities.
#[must_use]
pub fn to_rational(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some(BigRational::zero());
    }
    let (mant, exp) = decompose(x);
    let m = if x < 0.0 {
        -BigInt::from(mant)
    } else {
        BigInt::from(mant)
    };
    Some(if exp >= 0 {
        BigRational::from_integer(m << (exp as u32))
    } else {
        BigRational::new(m, BigInt::from(1) << ((-exp) as u32))
    })
}

/// A rational point.
fn rat_point(p: DVec2) -> Option<(BigRational, BigRational)> {
    Some((to_rational(p.x)?, to_rational(p.y)?))
}

/// `|p − q|²` exactly; `None` if a coordinate is not finite.
#[must_use]
pub fn squared_distance_point_point(p: DVec2, q: DVec2) -> Option<BigRational> {
    let (px, py) = rat_point(p)?;
    let (qx, qy) = rat_point(q)?;
    let (dx, dy) = (px - qx, py - qy);
    Some(&dx * &dx + &dy * &dy)
}

/// The squared distance from `p` to the closed segment `[a, b]` exactly (`a == b` allowed);
/// `None` if a coordinate is not finite.
#[must_use]
pub fn squared_distance_point_segment(p: DVec2, a: DVec2, b: DVec2) -> Option<BigRational> {
    let (px, py) = rat_point(p)?;
    let (ax, ay) = rat_point(a)?;
    let (bx, by) = rat_point(b)?;
    let (ex, ey) = (&bx - &ax, &by - &ay);
    let (wx, wy) = (&px - &ax, &py - &ay);
    let t_num = &wx * &ex + &wy * &ey;
    let len2 = &ex * &ex + &ey * &ey;
    if !t_num.is_positive() || len2.is_zero() {
        return Some(&wx * &wx + &wy * &wy);
    }
    if t_num >= len2 {
        let (vx, vy) = (&px - &bx, &py - &by);
        return Some(&vx * &vx + &vy * &vy);
    }
    let cross = &ex * &wy - &ey * &wx;
    Some(&cross * &cross / len2)
}
