//! Touching or overlapping polygons: recursive splitting into separated pairs, `O(N log N)` for
//! `N = m + n` vertices.
//!
//! A node holds two vertex subsets `C` (of `P`) and `D` (of `Q`), each in counter-clockwise order, so
//! each is a strictly convex polygon. If the `O(log)` search finds a certified bridge, TENSTEP answers
//! the node. Otherwise the larger set, say `C = c_0 … c_{k−1}`, is cut by the line `ℓ` through the
//! midpoints of the edges `(c_{k−1}, c_0)` and `(c_{h−1}, c_h)`, `h = ⌊k/2⌋`: `C_1 = c_0 … c_{h−1}` and
//! `C_2 = c_h … c_{k−1}` lie strictly on opposite sides of `ℓ` (strict convexity). `D` is partitioned
//! by the exact side of `ℓ` (`D_1` the closed side of `C_1`, `D_2` the open side of `C_2`). The four
//! products cover `C × D` once; in `C_1 × D_2` and `C_2 × D_1` the hulls are strictly separated by
//! `ℓ`, so TENSTEP applies at once; `C_1 × D_1` and `C_2 × D_2` recurse. A node of size `s` costs
//! `O(s)` and its recursing children have size at most `3s/4 + 1`: `O(N log N)` in all.

use glam::DVec2;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Kernel, Polynomial, Ring as Arith, Sign};

use super::chain::{Best, Callers};
use super::stats::bump;
use super::tenstep::{Ring, scan_all, tenstep};
use crate::pair::{Pair, canonical, certify};
use crate::yang::{RESEEDS, candidate, reseed};

/// Below this many vertex pairs (or with a point or a segment on one side) a node is scanned.
const SCAN_PAIRS: usize = 64;

/// `(c_{h−1} + c_h − c_{k−1} − c_0) × (2d − c_{k−1} − c_0)`: four times the orientation of `d`
/// against the line through the two edge midpoints (degree 2). Inputs
/// `[c_0, c_{k−1}, c_{h−1}, c_h, d]` flattened.
struct SplitSide;
impl Polynomial<10> for SplitSide {
    const DEGREE: u32 = 2;
    fn eval<R: Arith>(&self, x: &[R; 10]) -> R {
        let m1x = x[0].add(&x[2]);
        let m1y = x[1].add(&x[3]);
        let ux = x[4].add(&x[6]).sub(&m1x);
        let uy = x[5].add(&x[7]).sub(&m1y);
        let wx = x[8].add(&x[8]).sub(&m1x);
        let wy = x[9].add(&x[9]).sub(&m1y);
        ux.mul(&wy).sub(&uy.mul(&wx))
    }
}

/// A vertex subset of one polygon, counter-clockwise, with caller indices.
#[derive(Clone, Debug, Default)]
struct Part {
    pts: Vec<DVec2>,
    caller: Vec<usize>,
}

impl Part {
    fn ring(&self) -> Ring<'_> {
        Ring {
            pts: &self.pts,
            caller: Callers::Table(&self.caller),
        }
    }

    fn len(&self) -> usize {
        self.pts.len()
    }

    fn slice(&self, lo: usize, hi: usize) -> Part {
        Part {
            pts: self.pts[lo..hi].to_vec(),
            caller: self.caller[lo..hi].to_vec(),
        }
    }
}

/// The nearest vertex pair of meeting polygons `p`, `q` (either may be a point or a segment).
pub(super) fn meeting<K: Kernel>(p: Ring<'_>, q: Ring<'_>, best: &mut Best) {
    bump(|s| s.meeting_inputs += 1);
    let part = |r: Ring<'_>| Part {
        pts: r.pts.to_vec(),
        caller: (0..r.pts.len()).map(|i| r.caller.get(i)).collect(),
    };
    let (c, d) = (part(p), part(q));
    if c.len() <= 2 || d.len() <= 2 || c.len() * d.len() <= SCAN_PAIRS {
        bump(|s| s.brute_nodes += 1);
        scan_all::<K>(c.ring(), d.ring(), best);
    } else {
        split::<K>(c, d, false, best);
    }
}

/// The certified bridge of two parts, or `None`: the `O(log)` search and its `O(1)` Theorem-1
/// certificate, reseeded from its own answer like [`distance_yang_with`](crate::distance_yang_with)
/// does, but without its contact test and brute-force fallback (`O(s log s)` and `O(s²)`): a part
/// without a certified bridge is split instead.
fn bridge<K: Kernel>(c: &Part, d: &Part) -> Option<Pair> {
    let pc = ConvexPolygon::try_new(&c.pts).ok()?;
    let pd = ConvexPolygon::try_new(&d.pts).ok()?;
    // A subset of a strictly convex ring is kept whole, in order, from its first vertex.
    if pc.len() != c.len() || pd.len() != d.len() {
        return None;
    }
    let (p, q) = (&c.pts[..], &d.pts[..]);
    let mut pair = candidate::<K>(&pc, &pd)?;
    if certify::<K>(p, q, pair) {
        return Some(pair);
    }
    for _ in 0..RESEEDS {
        let again = canonical::<K>(p, q, reseed::<K>(p, q, pair));
        if certify::<K>(p, q, again) {
            return Some(again);
        }
        if again == pair {
            break;
        }
        pair = again;
    }
    None
}

/// Answers the node `(c, d)`; `separated` when a split line is known to separate them strictly.
fn node<K: Kernel>(c: Part, d: Part, separated: bool, best: &mut Best) {
    if c.len() <= 2 || d.len() <= 2 || c.len() * d.len() <= SCAN_PAIRS {
        bump(|s| s.brute_nodes += 1);
        scan_all::<K>(c.ring(), d.ring(), best);
        return;
    }
    match bridge::<K>(&c, &d) {
        Some(pair) => {
            bump(|s| s.separated_nodes += 1);
            tenstep::<K>(c.ring(), d.ring(), pair, best);
        }
        None => {
            if separated {
                bump(|s| s.uncertified_separated_nodes += 1);
            }
            split::<K>(c, d, separated, best);
        }
    }
}

/// Splits the larger part (at least 3 vertices) and answers the four products.
fn split<K: Kernel>(c: Part, d: Part, separated: bool, best: &mut Best) {
    bump(|s| s.split_nodes += 1);
    let c_larger = c.len() >= d.len();
    let (big, small) = if c_larger { (&c, &d) } else { (&d, &c) };
    let k = big.len();
    let h = k / 2;
    let b = &big.pts;
    let side = |x: DVec2| {
        let input = [
            b[0].x,
            b[0].y,
            b[k - 1].x,
            b[k - 1].y,
            b[h - 1].x,
            b[h - 1].y,
            b[h].x,
            b[h].y,
            x.x,
            x.y,
        ];
        K::sign(&SplitSide, &input)
    };
    // The side of b_0 (strictly off ℓ under exact predicates).
    let s0 = match side(b[0]) {
        Sign::Zero => Sign::Positive,
        s => s,
    };
    let (big1, big2) = (big.slice(0, h), big.slice(h, k));
    let (mut small1, mut small2) = (Part::default(), Part::default());
    for (&x, &i) in small.pts.iter().zip(&small.caller) {
        let part = if side(x) == s0.reversed() {
            &mut small2
        } else {
            &mut small1
        };
        part.pts.push(x);
        part.caller.push(i);
    }
    // Every child is strictly smaller than this node (big1, big2 are), so the recursion ends.
    let children = [
        (big1.clone(), small2.clone(), true),
        (big2.clone(), small1.clone(), true),
        (big1, small1, separated),
        (big2, small2, separated),
    ];
    for (x, y, separated) in children {
        if x.len() == 0 || y.len() == 0 {
            continue;
        }
        if c_larger {
            node::<K>(x, y, separated, best);
        } else {
            node::<K>(y, x, separated, best);
        }
    }
}
