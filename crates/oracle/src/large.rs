//! Large pairs of polygons (10⁴–10⁵ vertices) for the hard-case suite (issue 8), rebuilt
//! deterministically from a few parameters, so that a fixture stores the parameters (a `gen` line)
//! and the exact answers, not megabytes of coordinates.
//!
//! Every construction uses only integer arithmetic and correctly rounded IEEE operations (`+ − × ÷`,
//! `round`, exact scalings by powers of two): no `sin`, `cos` or other library function whose last
//! bit may differ between platforms, so the same parameters give the same vertices bit for bit
//! everywhere. [`large_pair`] also checks a 64-bit FNV-1a fingerprint of the vertex bits that the
//! fixture stores with the parameters, so that a changed generator cannot silently pair old answers
//! with new vertices.

use glam::DVec2;

use crate::generators::precision::{Axis, offset, with_gap_ulps};
use crate::generators::rng::SplitMix64;
use crate::generators::simple::{comb, star};
use crate::rounding::step_ulps;

/// A dense, strictly convex, regular-ish polygon of `n` vertices (`n` even, at least 8), ccw, on the
/// circle of radius `2^e` about the origin, vertices rounded to the grid `2^(e−50)`.
///
/// Construction: the right half is the rational parametrisation `((1 − t²)/(1 + t²), 2t/(1 + t²))`
/// at `t_k = −1 + (2k + 1)/h`, `h = n/2`, `k = 0..h` (denser towards the poles), scaled by `2^e`;
/// the left half is its mirror image `x → −x` in reverse order. The rounding (at most `2^(e−51)`)
/// is far below the sagitta between neighbours (at least `2^e/(2h²)`, `2^(e−32)` for `n = 10⁵`), so
/// the polygon stays strictly convex (the suite checks it exactly). Coordinates are multiples of
/// `2^(e−50)` below `2^e` in magnitude, so translations by multiples of the grid keep them exact
/// up to magnitude `2^(e+3)`.
///
/// # Panics
/// Panics if `n` is odd or below 8, or `2^e` is not a normal number with room for the grid.
#[must_use]
pub fn dense_circle(n: usize, e: i32) -> Vec<DVec2> {
    assert!(n >= 8 && n % 2 == 0, "dense_circle: n even, at least 8");
    assert!(
        (-900..=900).contains(&e),
        "dense_circle: exponent out of range"
    );
    let h = n / 2;
    let (r, grid) = (2f64.powi(e), 2f64.powi(e - 50));
    let snap = |x: f64| (x / grid).round() * grid;
    let right: Vec<DVec2> = (0..h)
        .map(|k| {
            let t = -1.0 + (2 * k + 1) as f64 / h as f64;
            let w = 1.0 + t * t;
            DVec2::new(snap(r * ((1.0 - t * t) / w)), snap(r * (2.0 * t / w)))
        })
        .collect();
    let left = right.iter().rev().map(|v| DVec2::new(-v.x, v.y));
    right.iter().copied().chain(left).collect()
}

/// The lattice points of `x² + y² = r²`, `r` the product of `primes` (each `≡ 1 mod 4`, so a sum
/// of two squares), with `x > r/2` — McKenna and Toussaint's lower-bound construction of
/// co-circular vertex sets at a size of `4·3^k / 3` vertices for `k` primes — in ccw (increasing
/// angle) order, as a convex polygon (every vertex on the circle: strictly convex).
///
/// Construction: every Gaussian integer of norm `r²` is a unit times a product, over the primes
/// `p = ππ̄`, of `π²`, `ππ̄ = p` or `π̄²`; the points are sorted by the exact comparison of `y/x`
/// (all `x > 0`) in `i128`. Exact integer coordinates (need `r < 2^53`).
///
/// # Panics
/// Panics if a prime is not `≡ 1 mod 4` or `r ≥ 2^53`.
#[must_use]
pub fn cocircular_arc(primes: &[i64]) -> Vec<DVec2> {
    let r: i128 = primes.iter().map(|&p| i128::from(p)).product();
    assert!(r < 1 << 53, "cocircular_arc: radius too large to be exact");
    let mul = |a: (i128, i128), b: (i128, i128)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let mut zs: Vec<(i128, i128)> = vec![(1, 0)];
    for &p in primes {
        assert!(p % 4 == 1, "cocircular_arc: {p} is not 1 mod 4");
        let p = i128::from(p);
        let a = (1..p)
            .find(|a| {
                let b2 = p - a * a;
                b2 > 0 && (b2 as f64).sqrt() as i128 * ((b2 as f64).sqrt() as i128) == b2
            })
            .expect("a prime 1 mod 4 is a sum of two squares");
        let b = ((p - a * a) as f64).sqrt() as i128;
        let (pi, pibar) = ((a, b), (a, -b));
        let choices = [mul(pi, pi), mul(pi, pibar), mul(pibar, pibar)];
        zs = zs
            .iter()
            .flat_map(|&z| choices.iter().map(move |&c| mul(z, c)))
            .collect();
    }
    let mut pts: Vec<(i128, i128)> = zs
        .iter()
        .flat_map(|&(x, y)| [(x, y), (-y, x), (-x, -y), (y, -x)])
        .filter(|&(x, _)| 2 * x > r)
        .collect();
    pts.sort_by(|a, b| (a.1 * b.0).cmp(&(b.1 * a.0)));
    pts.dedup();
    pts.into_iter()
        .map(|(x, y)| DVec2::new(x as f64, y as f64))
        .collect()
}

/// FNV-1a over the bits of every coordinate of `p`, then of `q`.
#[must_use]
pub fn fingerprint(p: &[DVec2], q: &[DVec2]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for v in p.iter().chain(q) {
        for c in [v.x, v.y] {
            for byte in c.to_bits().to_le_bytes() {
                h ^= u64::from(byte);
                h = h.wrapping_mul(0x0100_0000_01b3);
            }
        }
    }
    h
}

/// Builds the pair a `gen` line describes (its words after `gen`, without the trailing
/// fingerprint):
///
/// - `circle N E GAP DY`: `P` = [`dense_circle`]`(N, E)` centred at `(−2^(E+2), 0)`, `Q` = its
///   mirror image `x → −x` moved up by `DY` grid units `2^(E−50)` and then along x to leave `GAP`
///   ulps between the x-extents ([`with_gap_ulps`]): two dense polygons nearly touching.
/// - `cocircular K STEPS`: `P` = [`cocircular_arc`] of the first `K` primes `≡ 1 mod 4`, with the
///   vertex nearest the x-axis moved by `STEPS` ulps in x (0: exact ties), `Q` = the triangle
///   `(0, 0), (−r, r), (−r, −r)`: every vertex of `P` (nearly) equidistant from `Q`'s vertex 0.
/// - `star SEED N SPIKES GAP`: two [`star`]s of `N` vertices drawn from `SplitMix64::new(SEED)`,
///   `P` moved by `(−4, 0)`, `Q` placed `GAP` ulps to its right: hulls disjoint.
/// - `comb TEETH LEN SPACE GAP SHIFT`: a [`comb`] and its image under the half-turn, teeth facing
///   teeth, `GAP` ulps apart along y, `Q` moved by `SHIFT/2` along x: hulls disjoint.
///
/// # Errors
/// A message when the words do not describe a pair, or when a construction cannot be exact.
pub fn large_pair_from(words: &[String]) -> Result<(Vec<DVec2>, Vec<DVec2>), String> {
    let num = |k: usize| -> Result<i64, String> {
        words
            .get(k)
            .and_then(|w| w.parse().ok())
            .ok_or_else(|| format!("bad or missing parameter {k} in `gen {}`", words.join(" ")))
    };
    let size = |k: usize| -> Result<usize, String> {
        usize::try_from(num(k)?).map_err(|_| format!("negative size in `gen {}`", words.join(" ")))
    };
    let inexact = || format!("`gen {}`: a move would round", words.join(" "));
    match words.first().map(String::as_str) {
        Some("circle") => {
            let (n, e) = (size(1)?, i32::try_from(num(2)?).map_err(|_| inexact())?);
            let (gap, dy) = (u64::try_from(num(3)?).map_err(|_| inexact())?, num(4)?);
            let c = dense_circle(n, e);
            let p = offset(&c, -(2f64.powi(e + 2)), 0.0).ok_or_else(inexact)?;
            let mirror: Vec<DVec2> = c.iter().rev().map(|v| DVec2::new(-v.x, v.y)).collect();
            let up = offset(&mirror, 0.0, dy as f64 * 2f64.powi(e - 50)).ok_or_else(inexact)?;
            let q = with_gap_ulps(&p, &up, gap, Axis::X).ok_or_else(inexact)?;
            Ok((p, q))
        }
        Some("cocircular") => {
            const PRIMES: [i64; 10] = [5, 13, 17, 29, 37, 41, 53, 61, 73, 89];
            let k = size(1)?.min(PRIMES.len());
            let steps = num(2)?;
            let mut p = cocircular_arc(&PRIMES[..k]);
            let r: f64 = PRIMES[..k].iter().map(|&p| p as f64).product();
            let mid = (0..p.len())
                .min_by(|&a, &b| p[a].y.abs().total_cmp(&p[b].y.abs()))
                .ok_or_else(inexact)?;
            p[mid].x = step_ulps(p[mid].x, steps);
            let q = vec![DVec2::ZERO, DVec2::new(-r, r), DVec2::new(-r, -r)];
            Ok((p, q))
        }
        Some("star") => {
            let seed = u64::try_from(num(1)?).map_err(|_| inexact())?;
            let (n, spikes, gap) = (size(2)?, size(3)?, size(4)?);
            let mut rng = SplitMix64::new(seed);
            let a = star(&mut rng, n, spikes);
            let b = star(&mut rng, n, spikes);
            let p = offset(&a, -4.0, 0.0).ok_or_else(inexact)?;
            let q = with_gap_ulps(&p, &b, gap as u64, Axis::X).ok_or_else(inexact)?;
            Ok((p, q))
        }
        Some("comb") => {
            let (teeth, len) = (size(1)?, u32::try_from(num(2)?).map_err(|_| inexact())?);
            let (space, gap) = (u32::try_from(num(3)?).map_err(|_| inexact())?, num(4)?);
            let shift = num(5)?;
            let c = comb(teeth, len, space);
            let width = c.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
            // Down by 2^(⌈log2 len⌉ + 2) so that the tips sit at negative y and Q, moving up
            // towards 0, stays in a binade whose grid holds both the gap and the integers.
            let down = 2f64.powi(f64::from(len).log2().ceil() as i32 + 2);
            let p = offset(&c, 0.0, -down).ok_or_else(inexact)?;
            let turned: Vec<DVec2> = c
                .iter()
                .map(|v| DVec2::new(width - v.x + shift as f64 * 0.5, -v.y))
                .collect();
            let q = with_gap_ulps(&p, &turned, gap as u64, Axis::Y).ok_or_else(inexact)?;
            Ok((p, q))
        }
        _ => Err(format!("unknown generator `gen {}`", words.join(" "))),
    }
}

/// [`large_pair_from`] for the words of a fixture's `gen` line whose last word is the
/// [`fingerprint`] of the pair in hexadecimal, checked.
///
/// # Errors
/// A message when the words are malformed or the rebuilt pair does not match the fingerprint.
pub fn large_pair(words: &[String]) -> Result<(Vec<DVec2>, Vec<DVec2>), String> {
    let (last, params) = words
        .split_last()
        .ok_or_else(|| "empty `gen` line".to_owned())?;
    let want = u64::from_str_radix(last, 16).map_err(|_| format!("bad fingerprint `{last}`"))?;
    let (p, q) = large_pair_from(params)?;
    let got = fingerprint(&p, &q);
    if got == want {
        Ok((p, q))
    } else {
        Err(format!(
            "`gen {}` rebuilt a different pair (fingerprint {got:x}, stored {want:x})",
            params.join(" ")
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{is_convex, is_strictly_convex, sign_orient};

    fn words(s: &str) -> Vec<String> {
        s.split_whitespace().map(str::to_owned).collect()
    }

    #[test]
    fn dense_circle_is_strictly_convex_and_symmetric() {
        for n in [8, 64, 1000] {
            let c = dense_circle(n, 30);
            assert_eq!(c.len(), n);
            assert!(is_strictly_convex(&c));
            assert_eq!(
                sign_orient(c[0], c[1], c[2]),
                core::cmp::Ordering::Greater,
                "ccw"
            );
        }
    }

    #[test]
    fn cocircular_arc_is_on_the_circle() {
        let primes = [5, 13, 17];
        let arc = cocircular_arc(&primes);
        let r: i64 = 5 * 13 * 17;
        // Every lattice point of the circle with x > r/2, by brute force over x.
        let brute = (r / 2 + 1..=r)
            .flat_map(|x| {
                let y = ((r * r - x * x) as f64).sqrt() as i64;
                (y * y == r * r - x * x).then_some(if y == 0 {
                    vec![(x, 0)]
                } else {
                    vec![(x, y), (x, -y)]
                })
            })
            .flatten()
            .count();
        assert_eq!(arc.len(), brute);
        for v in &arc {
            let (x, y) = (v.x as i64, v.y as i64);
            assert_eq!(x * x + y * y, r * r);
            assert!(2 * x > r);
        }
        assert!(is_strictly_convex(&arc));
    }

    #[test]
    fn every_generator_builds_and_checks_its_fingerprint() {
        for g in [
            "circle 64 30 1 0",
            "circle 64 30 3 5",
            "cocircular 3 0",
            "cocircular 3 1",
            "cocircular 3 -1",
            "star 7 60 20 1",
            "comb 10 3 1 2 0",
            "comb 10 3 1 2 1",
        ] {
            let (p, q) = large_pair_from(&words(g)).unwrap_or_else(|e| panic!("{e}"));
            if g.starts_with("circle") || g.starts_with("cocircular") {
                assert!(is_convex(&p) && is_convex(&q), "{g}");
            }
            let mut w = words(g);
            w.push(format!("{:x}", fingerprint(&p, &q)));
            assert_eq!(large_pair(&w), Ok((p.clone(), q.clone())));
            let last = w.len() - 1;
            w[last] = "0".to_owned();
            assert!(large_pair(&w).is_err(), "{g}: a wrong fingerprint passes");
        }
        assert!(large_pair_from(&words("torus 3")).is_err());
    }
}
