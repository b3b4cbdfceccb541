//! Precision-stress helpers: exact translations, gaps measured in ulps,
//! (nearly) collinear triples, huge offsets.

use glam::DVec2;
use num_rational::BigRational;

use super::rng::SplitMix64;
use crate::exact::{decode, rat_finite};
use crate::rounding::{ldexp, step_ulps, to_f64_nearest};

/// Offsets at which precision-sensitive families are replicated.
pub const OFFSETS: [f64; 3] = [1e8, 1e12, 1e15];

/// `x + t` if that sum is exactly representable, else `None`.
fn exact_add(x: f64, t: &BigRational) -> Option<f64> {
    let s = rat_finite(x) + t;
    let f = to_f64_nearest(&s);
    (f.is_finite() && rat_finite(f) == s).then_some(f)
}

/// `poly` translated by `(dx, dy)` if **every** translated coordinate is
/// exactly representable, else `None` (never rounds).
///
/// A sum `x + dx` of doubles is exact iff the exact sum is representable; a
/// convenient sufficient condition: both are integer multiples of `2^k` and
/// the sum is below `2^(53+k)` in magnitude. E.g. integer coordinates below
/// `2^52 − 1e15` stay exact at every offset in [`OFFSETS`].
///
/// # Panics
/// Panics if a coordinate or the offset is not finite.
pub fn offset(poly: &[DVec2], dx: f64, dy: f64) -> Option<Vec<DVec2>> {
    let tx = rat_finite(dx);
    let ty = rat_finite(dy);
    poly.iter()
        .map(|p| Some(DVec2::new(exact_add(p.x, &tx)?, exact_add(p.y, &ty)?)))
        .collect()
}

/// `poly` itself (offset 0) followed by its exact translations by `(o, o)`
/// for each `o` in [`OFFSETS`], skipping offsets where some coordinate would
/// not be exact. Relative geometry is identical across the family, so every
/// exact distance, predicate and contact must be identical too (distances
/// are between a polygon and its own translate here only if the caller
/// compares them; typically one translates both polygons of a pair).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn offset_family(poly: &[DVec2]) -> Vec<(f64, Vec<DVec2>)> {
    let mut out = vec![(0.0, poly.to_vec())];
    for o in OFFSETS {
        if let Some(moved) = offset(poly, o, o) {
            out.push((o, moved));
        }
    }
    out
}

/// A coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The x axis.
    X,
    /// The y axis.
    Y,
}

/// `q` translated along `axis` so that it lies on the positive side of `p`
/// with a slab of exactly `ulps` representable steps between them: along
/// `Axis::X`, `min_x(q') = step_ulps(max_x(p), ulps)` (so the x-projections
/// are separated by `ulps` ulps of `max_x(p)`, or touch for `ulps == 0`); the
/// other coordinate is unchanged. The translation is exact or refused:
/// `None` if some translated coordinate is not representable (e.g. `q` has
/// finer coordinates than the ulp grid at `max_x(p)`, or crosses into a
/// coarser binade). Always `Some` when all x-coordinates involved are
/// multiples of `ulp(max_x p)` and the translated `q` stays in magnitudes
/// below `2^(e+1)`, `e` the exponent of `max_x(p)` — e.g. place `p` at
/// negative x so that `q` moves towards zero.
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn with_gap_ulps(p: &[DVec2], q: &[DVec2], ulps: u64, axis: Axis) -> Option<Vec<DVec2>> {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "with_gap_ulps: empty polygon"
    );
    let coord = |v: &DVec2| match axis {
        Axis::X => v.x,
        Axis::Y => v.y,
    };
    let max_p = p.iter().map(coord).fold(f64::NEG_INFINITY, f64::max);
    let min_q = q.iter().map(coord).fold(f64::INFINITY, f64::min);
    let target = step_ulps(max_p, i64::try_from(ulps).ok()?);
    if !target.is_finite() {
        return None;
    }
    let t = rat_finite(target) - rat_finite(min_q);
    match axis {
        Axis::X => q
            .iter()
            .map(|v| Some(DVec2::new(exact_add(v.x, &t)?, v.y)))
            .collect(),
        Axis::Y => q
            .iter()
            .map(|v| Some(DVec2::new(v.x, exact_add(v.y, &t)?)))
            .collect(),
    }
}

/// `x` rounded to its `bits` leading significant bits (round to nearest,
/// ties away from zero):
/// a dyadic with a short significand, e.g. to turn `1e-9` into an exactly
/// realisable gap for [`crate::parallel_facing`].
///
/// # Panics
/// Panics if `x` is not finite or `bits` is not in `1..=53`.
pub fn short_dyadic(x: f64, bits: u32) -> f64 {
    assert!((1..=53).contains(&bits), "short_dyadic: bits in 1..=53");
    let (m, e) = decode(x);
    if m == 0 {
        return 0.0;
    }
    let len = 64 - m.unsigned_abs().leading_zeros();
    if len <= bits {
        return x;
    }
    let drop = len - bits;
    // Round m to a multiple of 2^drop via f64 arithmetic on exact integers.
    let scaled = ldexp(m as f64, -(drop as i32)).round();
    ldexp(scaled, e + drop as i32)
}

/// Grid step `2^e` for points near `offset`: fine enough for spread, coarse
/// enough that `|offset| + spread` stays below `2^51` steps.
fn grid_exp_for(offset: f64) -> i32 {
    let a = offset.abs();
    if a < 1.0 {
        return -30;
    }
    // floor(log2 a) from the decoded exponent and significand length.
    let (m, e) = decode(a);
    let top = e + (63 - m.unsigned_abs().leading_zeros()) as i32;
    (top + 1 - 50).max(-30)
}

/// `count` exactly collinear triples `[a, b, c]` on lines with random small
/// integer directions through points near `(offset, offset)`: all coordinates
/// are exact multiples of a power-of-two grid step chosen so that
/// `|offset| + spread` fits in 51 bits (so points at offset `1e15` are on an
/// integer grid). The three points are distinct; `c` may lie between `a` and
/// `b` or outside.
///
/// # Panics
/// Panics if `offset` is not finite or above `1e300`.
pub fn collinear_triples(rng: &mut SplitMix64, count: usize, offset: f64) -> Vec<[DVec2; 3]> {
    assert!(offset.is_finite() && offset.abs() <= 1e300);
    let e = grid_exp_for(offset);
    let o = ldexp(offset, -e).round();
    (0..count)
        .map(|_| {
            let d = loop {
                let d = (rng.range_i64(-1000, 1000), rng.range_i64(-1000, 1000));
                if d != (0, 0) {
                    break d;
                }
            };
            let base = (
                rng.range_i64(-(1 << 40), 1 << 40),
                rng.range_i64(-(1 << 40), 1 << 40),
            );
            let mut ts = [0i64; 3];
            loop {
                for t in &mut ts {
                    *t = rng.range_i64(-(1 << 20), 1 << 20);
                }
                if ts[0] != ts[1] && ts[1] != ts[2] && ts[0] != ts[2] {
                    break;
                }
            }
            ts.map(|t| {
                let x = o + (base.0 + t * d.0) as f64;
                let y = o + (base.1 + t * d.1) as f64;
                DVec2::new(ldexp(x, e), ldexp(y, e))
            })
        })
        .collect()
}

/// `count` nearly collinear triples: [`collinear_triples`] at `offset` with
/// one coordinate of `c` moved by `1..=max_ulps` representable steps (random
/// sign), along an axis the line is not parallel to. Never collinear, and the
/// exact orientation is known: moving `c.x` by `δ` gives
/// `sign(orient(a, b, c)) = −sign(b.y − a.y) · sign(δ)`, moving `c.y` by `δ`
/// gives `sign(b.x − a.x) · sign(δ)`.
///
/// # Panics
/// Panics if `max_ulps == 0` or `offset` is invalid as in
/// [`collinear_triples`].
pub fn near_collinear(
    rng: &mut SplitMix64,
    count: usize,
    offset: f64,
    max_ulps: u32,
) -> Vec<[DVec2; 3]> {
    assert!(max_ulps >= 1, "near_collinear: max_ulps >= 1");
    collinear_triples(rng, count, offset)
        .into_iter()
        .map(|[a, b, mut c]| {
            let k = i64::from(1 + rng.below(u64::from(max_ulps)) as u32);
            let k = if rng.coin() { k } else { -k };
            let use_x = if a.y == b.y {
                false
            } else if a.x == b.x {
                true
            } else {
                rng.coin()
            };
            if use_x {
                c.x = step_ulps(c.x, k);
            } else {
                c.y = step_ulps(c.y, k);
            }
            [a, b, c]
        })
        .collect()
}
