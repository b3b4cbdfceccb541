//! Shared test helpers: an independent rational reference and input strategies.
#![allow(
    dead_code,
    reason = "each test binary uses a different subset of the helpers"
)]

use core::cmp::Ordering;

use glam::DVec2;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

/// Exact rational value of a finite double (num-rational's own conversion, independent of ours).
pub(crate) fn q(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite test input")
}

pub(crate) fn sgn(v: &BigRational) -> i8 {
    if v.is_positive() {
        1
    } else if v.is_negative() {
        -1
    } else {
        0
    }
}

pub(crate) fn ord(v: &BigRational) -> Ordering {
    sgn(v).cmp(&0)
}

pub(crate) fn orient(a: DVec2, b: DVec2, c: DVec2) -> i8 {
    sgn(&((q(a.x) - q(c.x)) * (q(b.y) - q(c.y)) - (q(a.y) - q(c.y)) * (q(b.x) - q(c.x))))
}

pub(crate) fn dot(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> i8 {
    sgn(&((q(b.x) - q(a.x)) * (q(d.x) - q(c.x)) + (q(b.y) - q(a.y)) * (q(d.y) - q(c.y))))
}

pub(crate) fn cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> i8 {
    sgn(&((q(b.x) - q(a.x)) * (q(d.y) - q(c.y)) - (q(b.y) - q(a.y)) * (q(d.x) - q(c.x))))
}

pub(crate) fn d2(p: DVec2, a: DVec2) -> BigRational {
    let (dx, dy) = (q(p.x) - q(a.x), q(p.y) - q(a.y));
    &dx * &dx + &dy * &dy
}

/// Squared distance from p to the closed segment [a, b], by the textbook case split.
pub(crate) fn d2_seg(p: DVec2, a: DVec2, b: DVec2) -> BigRational {
    let (ex, ey) = (q(b.x) - q(a.x), q(b.y) - q(a.y));
    let (wx, wy) = (q(p.x) - q(a.x), q(p.y) - q(a.y));
    let l2 = &ex * &ex + &ey * &ey;
    let t = &wx * &ex + &wy * &ey;
    if l2.is_zero() || !t.is_positive() {
        return d2(p, a);
    }
    if t >= l2 {
        return d2(p, b);
    }
    let cr = &ex * &wy - &ey * &wx;
    &cr * &cr / l2
}

/// Moves `x` by `k` ulps.
pub(crate) fn nudge(mut x: f64, k: i32) -> f64 {
    for _ in 0..k.unsigned_abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

/// Doubles of every magnitude class: moderate, huge, tiny, subnormal, and exact zero.
pub(crate) fn any_coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -1e3..1e3f64,
        2 => (-1.0..1.0f64, -60i32..60).prop_map(|(m, e)| m * 2f64.powi(e)),
        1 => (-1.0..1.0f64, 900i32..1000).prop_map(|(m, e)| m * 2f64.powi(e)),
        1 => (-1.0..1.0f64, -1060i32..-960).prop_map(|(m, e)| m * 2f64.powi(e)),
        1 => (-1i64 << 52..1i64 << 52).prop_map(|m| m as f64 * f64::from_bits(1)),
        1 => Just(0.0),
    ]
}

pub(crate) fn any_point() -> impl Strategy<Value = DVec2> {
    (any_coord(), any_coord()).prop_map(|(x, y)| DVec2::new(x, y))
}

/// A point with both coordinates at a common scale and offset (the usual geometric situation).
pub(crate) fn scaled_point(scale: f64, offset: f64) -> impl Strategy<Value = DVec2> {
    (-1.0..1.0f64, -1.0..1.0f64)
        .prop_map(move |(x, y)| DVec2::new(offset + x * scale, offset + y * scale))
}

/// (scale, offset) pairs from tiny to huge, at the origin and far from it.
pub(crate) fn frame() -> impl Strategy<Value = (f64, f64)> {
    prop_oneof![
        Just((1.0, 0.0)),
        Just((1e-3, 1.0)),
        Just((1.0, 1e8)),
        Just((1.0, 1e12)),
        Just((1e3, 1e15)),
        Just((1e-250, 0.0)),
        Just((1e-300, 1e-290)),
        Just((1e140, 0.0)),
        Just((1e-310, 0.0)),
    ]
}

/// Three points, the third on the line of the first two up to a few ulps: orientation's hard case.
pub(crate) fn near_collinear() -> impl Strategy<Value = (DVec2, DVec2, DVec2)> {
    frame().prop_flat_map(|(s, o)| {
        (
            scaled_point(s, o),
            scaled_point(s, o),
            -2.0..3.0f64,
            -4i32..=4,
            -4i32..=4,
        )
            .prop_map(|(a, b, t, kx, ky)| {
                let c = a + (b - a) * t;
                (a, b, DVec2::new(nudge(c.x, kx), nudge(c.y, ky)))
            })
    })
}
