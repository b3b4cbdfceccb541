//! Exact shape checks: simplicity, convexity, signed area.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::exact::{Grid, IPt, cross, dot, edge, orient, seg_intersect, sign_of};

/// Twice the signed area (shoelace sum) in grid units.
pub(crate) fn signed_area2_grid(v: &[IPt]) -> BigInt {
    let n = v.len();
    let mut s = BigInt::zero();
    for i in 0..n {
        let (a, b) = edge(v, i);
        s += &a.x * &b.y - &a.y * &b.x;
    }
    s
}

/// Exact signed area of the closed polyline `poly` (shoelace formula):
/// positive for counter-clockwise simple polygons, negative for clockwise,
/// 0 for fewer than 3 vertices.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn signed_area(poly: &[DVec2]) -> BigRational {
    let g = Grid::for_points(poly);
    let twice = signed_area2_grid(&g.pts(poly));
    g.deg_to_rat(&twice, 2) / BigRational::from_integer(BigInt::from(2))
}

/// Whether `poly` is a simple polygon, exactly: at least 3 vertices, no edge
/// of length zero, adjacent edges meet only at their shared vertex (no
/// fold-back onto each other), non-adjacent edges do not meet at all.
/// Either orientation; consecutive collinear vertices (a straight angle) are
/// allowed. A simple polygon always has nonzero area. `O(n²)`.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn is_simple(poly: &[DVec2]) -> bool {
    let n = poly.len();
    if n < 3 {
        return false;
    }
    let g = Grid::for_points(poly);
    let v = g.pts(poly);
    if (0..n).any(|i| v[i] == v[(i + 1) % n]) {
        return false;
    }
    for i in 0..n {
        for j in i + 1..n {
            let adjacent_next = j == i + 1;
            let adjacent_wrap = i == 0 && j == n - 1;
            if adjacent_next || adjacent_wrap {
                // Shared vertex s; other endpoints x (of one edge), y (other).
                let (x, s, y) = if adjacent_next {
                    (&v[i], &v[j], &v[(j + 1) % n])
                } else {
                    (&v[n - 1], &v[0], &v[1])
                };
                if orient(x, s, y) == Ordering::Equal
                    && sign_of(&dot(&x.sub(s), &y.sub(s))) == Ordering::Greater
                {
                    return false;
                }
            } else {
                let (a, b) = edge(&v, i);
                let (c, d) = edge(&v, j);
                if seg_intersect(a, b, c, d) {
                    return false;
                }
            }
        }
    }
    true
}

/// Shared convexity test; `strict` forbids straight angles.
fn convex_check(poly: &[DVec2], strict: bool) -> bool {
    let n = poly.len();
    if n < 3 {
        return false;
    }
    let g = Grid::for_points(poly);
    let v = g.pts(poly);
    let e: Vec<(BigInt, BigInt)> = (0..n).map(|i| v[(i + 1) % n].sub(&v[i])).collect();
    if e.iter().any(|w| w.0.is_zero() && w.1.is_zero()) {
        return false;
    }
    // turn[i] = turn from edge i to edge i + 1 (at vertex i + 1).
    let turn: Vec<Ordering> = (0..n)
        .map(|i| sign_of(&cross(&e[i], &e[(i + 1) % n])))
        .collect();
    let Some(&s) = turn.iter().find(|&&t| t != Ordering::Equal) else {
        return false; // all collinear
    };
    for i in 0..n {
        if turn[i] == s.reverse() {
            return false;
        }
        if turn[i] == Ordering::Equal
            && (strict || sign_of(&dot(&e[i], &e[(i + 1) % n])) != Ordering::Greater)
        {
            return false;
        }
    }
    // With every turn weakly to one side and in [0, π), the polygon is convex
    // iff the edge direction winds exactly once. Mirror clockwise input; then
    // count passages from the lower half-plane of directions to the upper.
    let mirror = s == Ordering::Less;
    let upper = |w: &(BigInt, BigInt)| -> bool {
        let y = if mirror { -&w.1 } else { w.1.clone() };
        y.is_positive() || (y.is_zero() && w.0.is_positive())
    };
    let winds = (0..n)
        .filter(|&i| !upper(&e[i]) && upper(&e[(i + 1) % n]))
        .count();
    winds == 1
}

/// Whether `poly` is a convex polygon, exactly, allowing straight angles:
/// at least 3 vertices, no zero-length edge, all turns to the same side or
/// straight (a straight angle must continue forward, not fold back), not all
/// collinear, and the boundary winds exactly once. Either orientation.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn is_convex(poly: &[DVec2]) -> bool {
    convex_check(poly, false)
}

/// Whether `poly` is a strictly convex polygon, exactly: [`is_convex`] with
/// no three consecutive vertices collinear. Either orientation.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn is_strictly_convex(poly: &[DVec2]) -> bool {
    convex_check(poly, true)
}

/// Panics unless the union of the edges of `poly` is the boundary of its
/// convex hull: 1 or 2 vertices, all vertices collinear, or (after dropping
/// consecutive duplicates) a convex polygon.
pub(crate) fn assert_convex_position(poly: &[DVec2]) {
    assert!(!poly.is_empty(), "empty polygon");
    let mut v: Vec<DVec2> = Vec::with_capacity(poly.len());
    for &p in poly {
        if v.last() != Some(&p) {
            v.push(p);
        }
    }
    while v.len() > 1 && v.first() == v.last() {
        v.pop();
    }
    if v.len() <= 2 {
        return;
    }
    let g = Grid::for_points(&v);
    let iv = g.pts(&v);
    let all_collinear = (2..iv.len()).all(|i| orient(&iv[0], &iv[1], &iv[i]) == Ordering::Equal);
    assert!(
        all_collinear || is_convex(&v),
        "polygon is not in convex position (convex, cyclic order)"
    );
}
