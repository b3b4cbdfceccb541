//! Integer-lattice building blocks shared by the generators. Everything here
//! is exact integer arithmetic; conversion to `f64` happens only in
//! [`to_world`] / [`place`], which check that every coordinate is exact.

use core::cmp::Ordering;

use glam::DVec2;

use super::rng::SplitMix64;
use crate::rounding::ldexp;

/// A lattice point or vector.
pub(crate) type L = (i64, i64);
/// A wide lattice point (for affine maps before the exactness check).
pub(crate) type W = (i128, i128);

/// Attempts before a randomized construction gives up.
const MAX_ATTEMPTS: usize = 10_000;

/// `2^53`: integers strictly below this in magnitude are exact doubles.
pub(crate) const EXACT_INT: i128 = 1 << 53;

pub(crate) fn cross_l(a: L, b: L) -> i128 {
    i128::from(a.0) * i128::from(b.1) - i128::from(a.1) * i128::from(b.0)
}

pub(crate) fn cross_w(a: W, b: W) -> i128 {
    a.0 * b.1 - a.1 * b.0
}

/// 0 for directions with angle in `[0, π)`, 1 for `[π, 2π)`.
fn half(v: L) -> u8 {
    if v.1 > 0 || (v.1 == 0 && v.0 > 0) {
        0
    } else {
        1
    }
}

/// Total order of nonzero vectors by polar angle in `[0, 2π)`; vectors with
/// the same direction compare equal.
pub(crate) fn angle_cmp(a: &L, b: &L) -> Ordering {
    half(*a)
        .cmp(&half(*b))
        .then_with(|| 0.cmp(&cross_l(*a, *b)))
}

/// Valtr's construction of `k >= 2` integers summing to zero: draw `k` values
/// in `[-rc, rc]`, sort, and split the inner ones randomly between the two
/// monotone chains from the minimum to the maximum; the consecutive
/// differences of both chains (one positive, one negative) are returned.
/// Both signs occur; magnitudes are at most `2 rc`.
pub(crate) fn zero_sum(rng: &mut SplitMix64, k: usize, rc: i64) -> Vec<i64> {
    assert!(k >= 2 && rc >= 1);
    loop {
        let mut xs: Vec<i64> = (0..k).map(|_| rng.range_i64(-rc, rc)).collect();
        xs.sort_unstable();
        let (min, max) = (xs[0], xs[k - 1]);
        if min == max {
            continue;
        }
        let mut out = Vec::with_capacity(k);
        let (mut last_a, mut last_b) = (min, min);
        for &x in &xs[1..k - 1] {
            if rng.coin() {
                out.push(x - last_a);
                last_a = x;
            } else {
                out.push(last_b - x);
                last_b = x;
            }
        }
        out.push(max - last_a);
        out.push(last_b - max);
        return out;
    }
}

/// Closes integer edge vectors into a polygon: sorts them by angle and takes
/// prefix sums from the origin. The vectors must sum to zero. Returns `None`
/// if a vector is zero or two have the same direction.
///
/// Why the result is strictly convex with exactly `len` vertices, ccw: with
/// pairwise distinct directions summing to zero (and at least 3 of them), no
/// closed half-plane of directions can contain them all unless all lie on its
/// boundary line, impossible for 3 distinct directions; so consecutive
/// directions (cyclically) differ by an angle in `(0, π)`, i.e. every turn is
/// strictly left, and the directions wind exactly once.
pub(crate) fn polygon_from_vectors(mut v: Vec<L>) -> Option<Vec<L>> {
    debug_assert_eq!(v.iter().map(|w| i128::from(w.0)).sum::<i128>(), 0);
    debug_assert_eq!(v.iter().map(|w| i128::from(w.1)).sum::<i128>(), 0);
    if v.len() < 3 || v.contains(&(0, 0)) {
        return None;
    }
    v.sort_by(angle_cmp);
    let n = v.len();
    if (0..n).any(|i| angle_cmp(&v[i], &v[(i + 1) % n]) == Ordering::Equal) {
        return None;
    }
    let mut out = Vec::with_capacity(n);
    let mut p: L = (0, 0);
    for w in &v {
        out.push(p);
        p = (p.0 + w.0, p.1 + w.1);
    }
    debug_assert_eq!(p, (0, 0));
    Some(out)
}

/// Translates so the bounding box is centred at the origin (up to rounding).
pub(crate) fn center_bbox(poly: &mut [L]) {
    let (mut x0, mut x1, mut y0, mut y1) = (i64::MAX, i64::MIN, i64::MAX, i64::MIN);
    for &(x, y) in poly.iter() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let cx = x0 + (x1 - x0) / 2;
    let cy = y0 + (y1 - y0) / 2;
    for p in poly.iter_mut() {
        *p = (p.0 - cx, p.1 - cy);
    }
}

/// A random strictly convex ccw lattice polygon with exactly `n >= 3`
/// vertices (Valtr's method with independent ranges per axis), bounding box
/// centred at the origin, random starting vertex. Each axis extent is at
/// most `2 rc_x` resp. `2 rc_y`.
///
/// # Panics
/// Panics if no valid polygon is found in many attempts (ranges far too
/// small for `n`).
pub(crate) fn lattice_convex_xy(rng: &mut SplitMix64, n: usize, rc_x: i64, rc_y: i64) -> Vec<L> {
    assert!(n >= 3, "a convex polygon needs at least 3 vertices");
    for _ in 0..MAX_ATTEMPTS {
        let xs = zero_sum(rng, n, rc_x);
        let mut ys = zero_sum(rng, n, rc_y);
        rng.shuffle(&mut ys);
        let vecs = xs.into_iter().zip(ys).collect();
        if let Some(mut poly) = polygon_from_vectors(vecs) {
            center_bbox(&mut poly);
            let r = rng.index(n);
            poly.rotate_left(r);
            return poly;
        }
    }
    panic!("lattice_convex: range too small for {n} vertices");
}

/// [`lattice_convex_xy`] with the same range on both axes.
pub(crate) fn lattice_convex(rng: &mut SplitMix64, n: usize, rc: i64) -> Vec<L> {
    lattice_convex_xy(rng, n, rc, rc)
}

/// A random strictly convex ccw lattice polygon with exactly `n >= 3`
/// vertices whose *top* edge is horizontal: vertex 0 is `(0, 0)`, vertex
/// `n − 1` is `(len, 0)` with `len >= 1`, edge `n − 1` runs from `(len, 0)`
/// to `(0, 0)`, and every other vertex has `y < 0`.
pub(crate) fn convex_with_top_edge(rng: &mut SplitMix64, n: usize, rc: i64) -> Vec<L> {
    assert!(n >= 3);
    let k = n - 1;
    for _ in 0..MAX_ATTEMPTS {
        let b = zero_sum(rng, k, rc);
        let mut a: Vec<i64> = (0..k).map(|_| rng.range_i64(-rc, rc)).collect();
        let s: i64 = a.iter().sum();
        if s < 1 {
            let j = rng.index(k);
            a[j] += 1 - s + rng.range_i64(0, rc);
        }
        let len: i64 = a.iter().sum();
        let mut vecs: Vec<L> = a.into_iter().zip(b).collect();
        vecs.push((-len, 0));
        let Some(poly) = polygon_from_vectors(vecs) else {
            continue;
        };
        // Find the edge (-len, 0) and rotate so it is edge n − 1.
        let Some(i) = (0..n).find(|&i| {
            let (p, q) = (poly[i], poly[(i + 1) % n]);
            q.1 == p.1 && q.0 - p.0 == -len
        }) else {
            continue;
        };
        let mut out = poly;
        out.rotate_left((i + 1) % n);
        let o = out[0];
        for p in &mut out {
            *p = (p.0 - o.0, p.1 - o.1);
        }
        return out;
    }
    panic!("convex_with_top_edge: range too small for {n} vertices");
}

/// Whether `p` is strictly inside the ccw convex lattice polygon `poly`.
pub(crate) fn strictly_inside(poly: &[W], p: W) -> bool {
    let n = poly.len();
    (0..n).all(|i| {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        cross_w((b.0 - a.0, b.1 - a.1), (p.0 - a.0, p.1 - a.1)) > 0
    })
}

/// Widens lattice points.
pub(crate) fn wide(pts: &[L]) -> Vec<W> {
    pts.iter()
        .map(|&(x, y)| (i128::from(x), i128::from(y)))
        .collect()
}

/// Maps wide lattice points to doubles `(x · 2^exp, y · 2^exp)`.
///
/// # Panics
/// Panics unless every coordinate is below `2^53` in magnitude and the
/// results are representable (which makes the map exact).
pub(crate) fn to_world(pts: &[W], exp: i32) -> Vec<DVec2> {
    assert!(
        (-1074..=1023 - 53).contains(&exp),
        "scale 2^{exp} out of range"
    );
    pts.iter()
        .map(|&(x, y)| {
            assert!(
                x.abs() < EXACT_INT && y.abs() < EXACT_INT,
                "lattice coordinate too large to be exact"
            );
            DVec2::new(ldexp(x as f64, exp), ldexp(y as f64, exp))
        })
        .collect()
}

/// Places a lattice polygon in the world: scale by the largest power of two
/// `2^k` with `max |coord| · 2^k <= radius`, and translate by `center`
/// snapped to a multiple of `2^k`. If the snapped centre is so far out that
/// some coordinate would need more than 53 bits, `k` is increased (the
/// polygon gets larger than `radius`) until every coordinate is exact.
pub(crate) fn place(pts: &[L], center: DVec2, radius: f64) -> Vec<DVec2> {
    assert!(
        radius.is_finite() && radius > 0.0 && center.is_finite(),
        "place: radius must be positive and finite, centre finite"
    );
    let ext = pts
        .iter()
        .map(|&(x, y)| x.unsigned_abs().max(y.unsigned_abs()))
        .max()
        .unwrap_or(0)
        .max(1);
    assert!(i128::from(ext) < EXACT_INT);
    let extf = ext as f64;
    let mut k = (radius / extf).log2().floor().clamp(-1074.0, 970.0) as i32;
    while k > -1074 && ldexp(extf, k) > radius {
        k -= 1;
    }
    while ldexp(extf, k + 1) <= radius && k < 970 {
        k += 1;
    }
    let limit = EXACT_INT as f64;
    let (cx, cy) = loop {
        let cx = ldexp(center.x, -k).round();
        let cy = ldexp(center.y, -k).round();
        if cx.abs() + extf < limit && cy.abs() + extf < limit {
            break (cx, cy);
        }
        k += 1;
    };
    let w: Vec<W> = pts
        .iter()
        .map(|&(x, y)| (i128::from(x) + cx as i128, i128::from(y) + cy as i128))
        .collect();
    to_world(&w, k)
}
