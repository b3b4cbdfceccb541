//! Convex polygon generators.

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;

use super::lattice::{
    EXACT_INT, L, W, convex_with_top_edge, lattice_convex, lattice_convex_xy, place, to_world,
};
use super::rng::SplitMix64;
use crate::exact::{decode, rat_finite};
use crate::rounding::{ldexp, step_ulps};

/// A random **strictly convex** counter-clockwise polygon with **exactly**
/// `n` vertices (`n >= 3`), convex *exactly* (not just up to rounding).
///
/// Construction: Valtr's random convex lattice polygon (random integer edge
/// vectors with pairwise distinct directions summing to zero, sorted by
/// angle; `O(n log n)`, fine for `n = 10^6`), then scaled by a power of two
/// and translated by `center` snapped to the same power-of-two grid — both
/// exact, so exact convexity is preserved. The lattice is as fine as the
/// doubles allow: up to about `2^50` steps across, fewer when `center` is
/// large relative to `radius` (the polygon must share the f64 grid at
/// `|center|`), but never fewer than about `8 n²` (needed for `n` distinct
/// edge directions). Vertices lie in the square of half-side `radius` around
/// the snapped centre, filling it within a factor 2 — unless even `8 n²`
/// lattice steps do not fit, in which case the grid is coarsened and the
/// polygon is larger than `radius` (still exact). The starting vertex is
/// random.
///
/// # Panics
/// Panics if `n < 3`, `radius` is not positive and finite, or `center` is not
/// finite.
pub fn random_convex(rng: &mut SplitMix64, n: usize, center: DVec2, radius: f64) -> Vec<DVec2> {
    assert!(n >= 3, "random_convex: n >= 3");
    assert!(
        radius.is_finite() && radius > 0.0 && center.is_finite(),
        "random_convex: radius must be positive and finite, centre finite"
    );
    let m = center.x.abs().max(center.y.abs()) + radius;
    // Finest grid 2^e on which |center| + radius needs at most 51 bits.
    let e_min = floor_log2(m) - 50;
    let allowed = ldexp(radius, -e_min);
    let rc_min = (4.0 * (n as f64) * (n as f64)).max(64.0);
    let rc = (allowed / 2.0).clamp(rc_min, (1u64 << 49) as f64) as i64;
    let poly = lattice_convex(rng, n, rc);
    place(&poly, center, radius)
}

/// `floor(log2 x)` for a positive finite double.
fn floor_log2(x: f64) -> i32 {
    let (m, e) = decode(x);
    e + (63 - m.unsigned_abs().leading_zeros()) as i32
}

/// A random strictly convex ccw polygon with exactly `n >= 3` vertices and
/// small **integer** coordinates, `|x|, |y| <= max_coord`: many collinear
/// triples among non-consecutive vertices, many exact ties in distances.
/// Valtr's method with rejection; practical for `n` up to roughly
/// `max_coord^(2/3)`.
///
/// # Panics
/// Panics if `n < 3`, `max_coord < 2`, `max_coord >= 2^52`, or no polygon is
/// found (range too small for `n`).
pub fn random_convex_lattice(rng: &mut SplitMix64, n: usize, max_coord: i64) -> Vec<DVec2> {
    assert!(
        (2..1 << 52).contains(&max_coord),
        "max_coord must be in 2..2^52"
    );
    let poly = lattice_convex(rng, n, max_coord / 2);
    poly.iter()
        .map(|&(x, y)| DVec2::new(x as f64, y as f64))
        .collect()
}

/// All `4 (2k + 1)` lattice points on the circle `x² + y² = 5^(2k)`, sorted
/// counter-clockwise starting from `(5^k, 0)`: a strictly convex polygon with
/// every vertex at the same distance `5^k` from the origin (maximal ties for
/// Hausdorff, farthest-point and distance code).
///
/// Generated as `(2 + i)^a (2 − i)^b · u` for `a + b = 2k` and the four
/// units `u`; by unique factorisation in the Gaussian integers these are
/// exactly the lattice points of norm `5^(2k)`. Coordinates are exact
/// integers (`5^22 < 2^53`).
///
/// # Panics
/// Panics if `k > 22`.
pub fn cocircular(k: u32) -> Vec<DVec2> {
    assert!(k <= 22, "cocircular: 5^k must stay below 2^53 (k <= 22)");
    let mul = |a: (i128, i128), b: (i128, i128)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let mut pts: Vec<L> = Vec::new();
    for a in 0..=2 * k {
        let mut z = (1i128, 0i128);
        for _ in 0..a {
            z = mul(z, (2, 1));
        }
        for _ in 0..2 * k - a {
            z = mul(z, (2, -1));
        }
        for u in [(1, 0), (0, 1), (-1, 0), (0, -1)] {
            let w = mul(z, u);
            pts.push((w.0 as i64, w.1 as i64));
        }
    }
    pts.sort_by(super::lattice::angle_cmp);
    pts.iter()
        .map(|&(x, y)| DVec2::new(x as f64, y as f64))
        .collect()
}

/// [`cocircular`]`(k)` with vertex `index` moved off the circle: its
/// larger-magnitude coordinate is stepped `steps` representable doubles away
/// from zero (`steps > 0`: outward, `x² + y² > 5^(2k)`) or towards zero
/// (`steps < 0`: inward). One step is one ulp of that coordinate.
///
/// Guarantee: still strictly convex whenever `|steps| · 25^k < 2^51` (so for
/// `k <= 10` with one step): a lattice triangle has area at least 1/2, so each
/// affected turn has a margin far larger than the move. For larger `k` the
/// result may lose convexity (tests check what holds).
///
/// # Panics
/// Panics if `k > 22` or `index >= 4 (2k + 1)`.
pub fn cocircular_perturbed(k: u32, index: usize, steps: i64) -> Vec<DVec2> {
    let mut pts = cocircular(k);
    assert!(
        index < pts.len(),
        "cocircular_perturbed: index out of range"
    );
    let p = &mut pts[index];
    let c = if p.x.abs() > p.y.abs() {
        &mut p.x
    } else {
        &mut p.y
    };
    let moved = step_ulps(c.abs(), steps);
    *c = if *c < 0.0 { -moved } else { moved };
    pts
}

/// A thin strictly convex ccw polygon with exactly `n >= 3` vertices,
/// aspect ratio (long side over short side of its oriented bounding box)
/// approximately `aspect` (within a small factor), in a generic direction,
/// centred near the origin with extent about 1. Exact lattice construction:
/// Valtr with ranges `2^44` and `2^44 / aspect`, then an exact integer
/// similarity `[[p, −q], [q, p]]` with random small `p`, `q`, then a
/// power-of-two scale.
///
/// # Panics
/// Panics unless `1 <= aspect <= 2^40`, or if `n` is too large for the thin
/// range (roughly `n > 2^44 / aspect`).
pub fn sliver(rng: &mut SplitMix64, n: usize, aspect: f64) -> Vec<DVec2> {
    let lat = sliver_lattice(rng, n, aspect);
    place(&lat, DVec2::ZERO, 1.0)
}

/// Lattice part of [`sliver`].
pub(crate) fn sliver_lattice(rng: &mut SplitMix64, n: usize, aspect: f64) -> Vec<L> {
    assert!(
        (1.0..=(1u64 << 40) as f64).contains(&aspect),
        "sliver: aspect must be in [1, 2^40]"
    );
    let rc_x: i64 = 1 << 44;
    let rc_y = (((1u64 << 44) as f64 / aspect) as i64).max(1);
    let thin = lattice_convex_xy(rng, n, rc_x, rc_y);
    let (p, q) = loop {
        let p = rng.range_i64(-8, 8);
        let q = rng.range_i64(-8, 8);
        if p != 0 || q != 0 {
            break (p, q);
        }
    };
    thin.iter()
        .map(|&(x, y)| (p * x - q * y, q * x + p * y))
        .collect()
}

/// Two strictly convex polygons facing each other along exactly parallel
/// edges; see [`parallel_facing`].
#[derive(Clone, Debug, PartialEq)]
pub struct FacingPair {
    /// The lower polygon (to the right of the direction `d`).
    pub p: Vec<DVec2>,
    /// The upper polygon.
    pub q: Vec<DVec2>,
    /// Exact squared distance, `gap² · (dx² + dy²)`.
    pub sq_dist: BigRational,
}

/// Lattice construction shared by [`parallel_facing`] and the pair
/// enumerator: in the frame `(a, b) ↦ a·d + b·(−dy, dx)` (an exact
/// similarity), `P` lies in `b <= 0` with its top edge `Edge(n−1)` on `b = 0`,
/// and `Q` lies in `b >= g` with its bottom edge `Edge(m−1)` on `b = g`, the
/// two edges overlapping in a segment of positive length when projected.
/// Returns world-lattice points (before the power-of-two scale).
pub(crate) fn facing_lattice(
    rng: &mut SplitMix64,
    n: usize,
    m: usize,
    d: (i64, i64),
    g: i128,
    rc: i64,
) -> (Vec<W>, Vec<W>) {
    let p = convex_with_top_edge(rng, n, rc);
    let q0 = convex_with_top_edge(rng, m, rc);
    let len_p = i128::from(p[n - 1].0);
    let len_q = i128::from(q0[m - 1].0);
    // Q rotated by 180°: its facing edge spans a in [-len_q, 0] at b = 0;
    // shift by s in [1, len_p + len_q − 1] so the projections overlap.
    let s = i128::from(rng.range_i64(1, (len_p + len_q - 1) as i64));
    let frame = |a: i128, b: i128| -> W {
        let (dx, dy) = (i128::from(d.0), i128::from(d.1));
        (a * dx - b * dy, a * dy + b * dx)
    };
    let pw = p
        .iter()
        .map(|&(a, b)| frame(i128::from(a), i128::from(b)))
        .collect();
    let qw = q0
        .iter()
        .map(|&(a, b)| frame(s - i128::from(a), g - i128::from(b)))
        .collect();
    (pw, qw)
}

/// Two strictly convex ccw polygons with `n` vertices each whose facing
/// edges are **exactly parallel** to the integer direction `d = (dx, dy)` and
/// whose supporting lines are `gap · |d|` apart, measured along the normal
/// `(−dy, dx)`; the facing edges (`Edge(n−1)` of both) overlap in
/// projection, so the exact squared distance is `gap² (dx² + dy²)`
/// (reported in [`FacingPair::sq_dist`]); `gap = 0` gives touching, collinear
/// overlapping edges.
///
/// Exactness: with `gap = g · 2^j` (`g` odd) everything is built on the
/// lattice `2^j ℤ²`, so `gap` must have a short significand relative to the
/// polygon size (the polygons have extent about `min(1, 2^46 · 2^j / |d|)`
/// but at least `64 n` lattice steps).
///
/// # Panics
/// Panics if `n < 3`, `d == (0, 0)`, `|dx|` or `|dy| > 2^16`, `gap` is
/// negative or not finite, or `gap`'s significand is too long for exact
/// coordinates (e.g. `1e-9`; use a dyadic such as `2^-30` or `3 · 2^-40`,
/// or [`crate::short_dyadic`]).
pub fn parallel_facing(
    rng: &mut SplitMix64,
    n: usize,
    direction: (i64, i64),
    gap: f64,
) -> FacingPair {
    assert!(n >= 3, "parallel_facing: n >= 3");
    let (dx, dy) = direction;
    assert!(direction != (0, 0), "parallel_facing: zero direction");
    assert!(
        dx.abs() <= 1 << 16 && dy.abs() <= 1 << 16,
        "parallel_facing: direction components must be at most 2^16"
    );
    assert!(gap.is_finite() && gap >= 0.0, "parallel_facing: bad gap");
    let (g, j) = if gap == 0.0 { (0, -30) } else { decode(gap) };
    let g = i128::from(g);
    let dsum = i128::from(dx.abs() + dy.abs());
    // Lattice extent target: world extent 1, clamped to stay exact.
    let cap = ((1i128 << 50) / dsum - g) / 4;
    let want = if j <= -100 {
        cap
    } else if j >= 0 {
        0
    } else {
        1i128 << (-j).min(100)
    };
    let min_ext = 64 * n as i128;
    let ext = want.clamp(min_ext, cap.max(min_ext));
    assert!(
        ext <= cap,
        "parallel_facing: gap {gap} has too long a significand for direction {direction:?}"
    );
    let rc = (ext / n as i128).max(1) as i64;
    let (pw, qw) = facing_lattice(rng, n, n, direction, g, rc);
    assert!(
        pw.iter()
            .chain(&qw)
            .all(|w| w.0.abs() < EXACT_INT && w.1.abs() < EXACT_INT),
        "parallel_facing: coordinates not exact for this gap/direction"
    );
    let dd = BigRational::from_integer(BigInt::from(dx * dx + dy * dy));
    let gr = rat_finite(gap);
    FacingPair {
        p: to_world(&pw, j),
        q: to_world(&qw, j),
        sq_dist: &gr * &gr * dd,
    }
}
