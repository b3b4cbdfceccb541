//! Pairs of convex polygons in prescribed relative positions.

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use super::convex::{facing_lattice, sliver_lattice};
use super::lattice::{W, convex_with_top_edge, lattice_convex, strictly_inside, to_world, wide};
use super::rng::SplitMix64;
use crate::contact::Contact;

/// Relative position requested from [`convex_pair`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Relation {
    /// Far apart (bounding boxes separated by more than their size).
    /// `Disjoint`; `sq_dist` not provided.
    Far,
    /// `q` a given number of ulps to the right of `p`: coordinates lie in
    /// `(−1, −0.5)` (ulp `2^−53`), `p`'s rightmost vertex and `q`'s leftmost
    /// vertex have the same y and x-coordinates `ulps` ulps apart. Exact
    /// squared distance `(ulps · 2^−53)²`; `Disjoint`, or `Touching` for
    /// `ulps == 0`. Requires `ulps <= 2^40`.
    NearlyTouching {
        /// Gap in ulps of the coordinates.
        ulps: u64,
    },
    /// The polygons meet in exactly one point, a vertex of both (`p`'s unique
    /// rightmost vertex equals `q`'s unique leftmost vertex). `Touching`.
    TouchingVertex,
    /// An edge of `q` lies along an edge of `p` (collinear, overlapping in a
    /// segment of positive length), in a random integer direction.
    /// `Touching`.
    TouchingEdge,
    /// The polygons meet in exactly one point: a vertex of `q` in the
    /// relative interior of an edge of `p` (random integer direction).
    /// `Touching`.
    VertexOnEdge,
    /// A vertex of `q` lies in the open interior of `p` (boundaries may or may
    /// not cross). `Overlapping`.
    Overlapping,
    /// `q` lies in the open interior of `p`. `Overlapping`, positive boundary
    /// distance.
    Nested,
    /// Facing edges exactly parallel to a random integer direction, at a small
    /// positive gap (a few lattice units). `Disjoint`, exact `sq_dist`.
    ParallelFacing,
    /// A nearly touching pair around `(1e15, −1e15)`: integer multiples of
    /// `2^−3` (the ulp there), the extreme vertices 1–3 ulps apart in x with
    /// equal y. `Disjoint`, exact `sq_dist`.
    HugeOffset,
    /// Two slivers (aspect ratios about `2^10`–`2^30`, generic directions)
    /// whose sharp extreme vertices are one lattice step apart. `Disjoint`,
    /// exact `sq_dist`.
    Sliver,
    /// Convex polygons **with extra collinear vertices** strictly between
    /// their neighbours (about half the vertices), including on the facing
    /// edges of a parallel-facing configuration with gap 0 (`Touching`) or
    /// one lattice step (`Disjoint`). Not strictly convex; `is_convex` holds.
    CollinearInput,
}

impl Relation {
    /// One instance of every relation kind (nearly touching at 1 and 5 ulps), for tests that sweep
    /// all relative positions.
    pub const EVERY: [Relation; 12] = [
        Relation::Far,
        Relation::NearlyTouching { ulps: 1 },
        Relation::NearlyTouching { ulps: 5 },
        Relation::TouchingVertex,
        Relation::TouchingEdge,
        Relation::VertexOnEdge,
        Relation::Overlapping,
        Relation::Nested,
        Relation::ParallelFacing,
        Relation::HugeOffset,
        Relation::Sliver,
        Relation::CollinearInput,
    ];
}

/// Two convex polygons produced by [`convex_pair`], with what the
/// construction guarantees about them.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexPair {
    /// First polygon (`n` vertices, ccw).
    pub p: Vec<DVec2>,
    /// Second polygon (`m` vertices, ccw).
    pub q: Vec<DVec2>,
    /// The contact status guaranteed by construction (filled polygons).
    pub contact: Contact,
    /// The exact squared distance between the filled polygons, when the
    /// construction determines it (0 for every touching/overlapping case).
    pub sq_dist: Option<BigRational>,
}

fn translate(poly: &mut [W], t: W) {
    for p in poly {
        *p = (p.0 + t.0, p.1 + t.1);
    }
}

/// Index of the vertex with extreme x (max if `max`), and whether it is the
/// only one.
fn x_extreme(poly: &[W], max: bool) -> (usize, bool) {
    let key = |w: &W| if max { w.0 } else { -w.0 };
    let best = poly.iter().map(key).max().unwrap_or(0);
    let idx: Vec<usize> = (0..poly.len()).filter(|&i| key(&poly[i]) == best).collect();
    (idx[0], idx.len() == 1)
}

/// `p` and `q` such that `p`'s rightmost vertex is at the origin and `q`'s
/// leftmost vertex is at `(gap, 0)`.
fn side_by_side(
    rng: &mut SplitMix64,
    make_p: &mut dyn FnMut(&mut SplitMix64) -> Vec<W>,
    make_q: &mut dyn FnMut(&mut SplitMix64) -> Vec<W>,
    gap: i128,
    unique: bool,
) -> (Vec<W>, Vec<W>) {
    loop {
        let mut p = make_p(rng);
        let mut q = make_q(rng);
        let (ip, up) = x_extreme(&p, true);
        let (iq, uq) = x_extreme(&q, false);
        if unique && !(up && uq) {
            continue;
        }
        let (tp, tq) = (p[ip], q[iq]);
        translate(&mut p, (-tp.0, -tp.1));
        translate(&mut q, (gap - tq.0, -tq.1));
        return (p, q);
    }
}

fn random_direction(rng: &mut SplitMix64) -> (i64, i64) {
    loop {
        let d = (rng.range_i64(-50, 50), rng.range_i64(-50, 50));
        if d != (0, 0) {
            return d;
        }
    }
}

fn sq_of(num: i128, exp: i32) -> BigRational {
    let v = BigInt::from(num);
    let v2 = &v * &v;
    if exp >= 0 {
        BigRational::from_integer(v2 << (2 * exp).unsigned_abs())
    } else {
        BigRational::new(v2, BigInt::from(1) << (2 * exp).unsigned_abs())
    }
}

/// Inserts collinear vertices (at 1/2, or 1/3 and 2/3, or 1/4, 1/2, 3/4 of
/// an edge) into a ×12-scaled copy of `poly` until it has `total` vertices.
fn insert_collinear(rng: &mut SplitMix64, poly: &[W], total: usize) -> Vec<W> {
    let c = poly.len();
    let mut count = vec![0usize; c];
    for _ in c..total {
        loop {
            let e = rng.index(c);
            if count[e] < 3 {
                count[e] += 1;
                break;
            }
        }
    }
    let mut out = Vec::with_capacity(total);
    for i in 0..c {
        let a = (poly[i].0 * 12, poly[i].1 * 12);
        let b = (poly[(i + 1) % c].0 * 12, poly[(i + 1) % c].1 * 12);
        out.push(a);
        let t = count[i] as i128;
        let step = 12 / (t + 1);
        for k in 1..=t {
            let s = k * step;
            out.push((a.0 + (b.0 - a.0) * s / 12, a.1 + (b.1 - a.1) * s / 12));
        }
    }
    out
}

/// Two convex polygons with exactly `n` and `m` vertices (`n, m >= 3`) in the
/// requested relative position; every coordinate is exact (lattice points
/// times a power of two) and every polygon is strictly convex and ccw except
/// for [`Relation::CollinearInput`] (convex with straight angles). The
/// guaranteed contact status and, when determined, the exact squared
/// distance come with the result.
///
/// # Panics
/// Panics if `n < 3` or `m < 3`, or for `NearlyTouching` with `ulps > 2^40`.
pub fn convex_pair(rng: &mut SplitMix64, n: usize, m: usize, relation: Relation) -> ConvexPair {
    assert!(n >= 3 && m >= 3, "convex_pair: n, m >= 3");
    let zero = || Some(BigRational::zero());
    match relation {
        Relation::Far => {
            let p = wide(&lattice_convex(rng, n, 1 << 30));
            let mut q = wide(&lattice_convex(rng, m, 1 << 30));
            let t = (
                (1i128 << 33) + i128::from(rng.range_i64(0, 1 << 32)),
                i128::from(rng.range_i64(-(1 << 32), 1 << 32)),
            );
            translate(&mut q, t);
            ConvexPair {
                p: to_world(&p, -30),
                q: to_world(&q, -30),
                contact: Contact::Disjoint,
                sq_dist: None,
            }
        }
        Relation::NearlyTouching { ulps } => {
            assert!(ulps <= 1 << 40, "NearlyTouching: ulps <= 2^40");
            let mk_p = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, n, 1 << 44));
            let mk_q = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, m, 1 << 44));
            let (mut p, mut q) = side_by_side(rng, mk_p, mk_q, i128::from(ulps), false);
            let x0 = -(3i128 << 51);
            translate(&mut p, (x0, 0));
            translate(&mut q, (x0, 0));
            ConvexPair {
                p: to_world(&p, -53),
                q: to_world(&q, -53),
                contact: if ulps == 0 {
                    Contact::Touching
                } else {
                    Contact::Disjoint
                },
                sq_dist: Some(sq_of(i128::from(ulps), -53)),
            }
        }
        Relation::TouchingVertex => {
            let mk_p = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, n, 1 << 40));
            let mk_q = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, m, 1 << 40));
            let (p, q) = side_by_side(rng, mk_p, mk_q, 0, true);
            ConvexPair {
                p: to_world(&p, -40),
                q: to_world(&q, -40),
                contact: Contact::Touching,
                sq_dist: zero(),
            }
        }
        Relation::TouchingEdge | Relation::ParallelFacing => {
            let d = random_direction(rng);
            let g = if relation == Relation::TouchingEdge {
                0
            } else {
                i128::from(rng.range_i64(1, 8))
            };
            let (p, q) = facing_lattice(rng, n, m, d, g, 1 << 20);
            let dd = BigRational::from_integer(BigInt::from(d.0 * d.0 + d.1 * d.1));
            ConvexPair {
                p: to_world(&p, -30),
                q: to_world(&q, -30),
                contact: if g == 0 {
                    Contact::Touching
                } else {
                    Contact::Disjoint
                },
                sq_dist: Some(sq_of(g, -30) * dd),
            }
        }
        Relation::VertexOnEdge => {
            let d = random_direction(rng);
            let (p, q) = loop {
                let p: Vec<W> = convex_with_top_edge(rng, n, 1 << 20)
                    .iter()
                    .map(|&(a, b)| (2 * i128::from(a), 2 * i128::from(b)))
                    .collect();
                let len = p[n - 1].0;
                let mut q = wide(&lattice_convex(rng, m, 1 << 20));
                let min_b = q.iter().map(|w| w.1).min().unwrap_or(0);
                let low: Vec<usize> = (0..m).filter(|&i| q[i].1 == min_b).collect();
                if low.len() != 1 {
                    continue;
                }
                let a_star = i128::from(rng.range_i64(1, (len - 1) as i64));
                let v = q[low[0]];
                translate(&mut q, (a_star - v.0, -v.1));
                break (p, q);
            };
            let frame = |w: &W| -> W {
                let (dx, dy) = (i128::from(d.0), i128::from(d.1));
                (w.0 * dx - w.1 * dy, w.0 * dy + w.1 * dx)
            };
            let p: Vec<W> = p.iter().map(frame).collect();
            let q: Vec<W> = q.iter().map(frame).collect();
            ConvexPair {
                p: to_world(&p, -30),
                q: to_world(&q, -30),
                contact: Contact::Touching,
                sq_dist: zero(),
            }
        }
        Relation::Overlapping => {
            let base = wide(&lattice_convex(rng, n, 1 << 40));
            let p: Vec<W> = base.iter().map(|w| (3 * w.0, 3 * w.1)).collect();
            let (a, b, c) = (base[0], base[n / 3], base[2 * n / 3]);
            let centroid = (a.0 + b.0 + c.0, a.1 + b.1 + c.1);
            let mut q = wide(&lattice_convex(rng, m, 1 << 40));
            let q0 = q[0];
            translate(&mut q, (centroid.0 - q0.0, centroid.1 - q0.1));
            ConvexPair {
                p: to_world(&p, -44),
                q: to_world(&q, -44),
                contact: Contact::Overlapping,
                sq_dist: zero(),
            }
        }
        Relation::Nested => {
            let base = wide(&lattice_convex(rng, n, 1 << 30));
            let q0 = wide(&lattice_convex(rng, m, 1 << 16));
            let (a, b, c) = (base[0], base[n / 3], base[2 * n / 3]);
            let mut scale: i128 = 3;
            loop {
                let p: Vec<W> = base.iter().map(|w| (scale * w.0, scale * w.1)).collect();
                let k = scale / 3;
                let centroid = (k * (a.0 + b.0 + c.0), k * (a.1 + b.1 + c.1));
                let mut q = q0.clone();
                translate(&mut q, centroid);
                if q.iter().all(|&v| strictly_inside(&p, v)) {
                    break ConvexPair {
                        p: to_world(&p, -52),
                        q: to_world(&q, -52),
                        contact: Contact::Overlapping,
                        sq_dist: zero(),
                    };
                }
                assert!(scale < 1 << 20, "Nested: could not fit q inside p");
                scale *= 2;
            }
        }
        Relation::HugeOffset => {
            let g = i128::from(rng.range_i64(1, 3));
            let mk_p = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, n, 1 << 20));
            let mk_q = &mut |r: &mut SplitMix64| wide(&lattice_convex(r, m, 1 << 20));
            let (mut p, mut q) = side_by_side(rng, mk_p, mk_q, g, false);
            // 1e15 / 2^-3 = 8e15 lattice units (< 2^53).
            let o: W = (8_000_000_000_000_000, -8_000_000_000_000_000);
            translate(&mut p, o);
            translate(&mut q, o);
            ConvexPair {
                p: to_world(&p, -3),
                q: to_world(&q, -3),
                contact: Contact::Disjoint,
                sq_dist: Some(sq_of(g, -3)),
            }
        }
        Relation::Sliver => {
            let ap = (1u64 << rng.range_i64(10, 30)) as f64;
            let aq = (1u64 << rng.range_i64(10, 30)) as f64;
            let mk_p = &mut |r: &mut SplitMix64| wide(&sliver_lattice(r, n, ap));
            let mk_q = &mut |r: &mut SplitMix64| wide(&sliver_lattice(r, m, aq));
            let (p, q) = side_by_side(rng, mk_p, mk_q, 1, false);
            ConvexPair {
                p: to_world(&p, -48),
                q: to_world(&q, -48),
                contact: Contact::Disjoint,
                sq_dist: Some(sq_of(1, -48)),
            }
        }
        Relation::CollinearInput => {
            let d = random_direction(rng);
            let g = i128::from(rng.range_i64(0, 1));
            let (cn, cm) = (n.div_ceil(2).max(3), m.div_ceil(2).max(3));
            let (p, q) = facing_lattice(rng, cn, cm, d, g, 1 << 16);
            let p = insert_collinear(rng, &p, n);
            let q = insert_collinear(rng, &q, m);
            let dd = BigRational::from_integer(BigInt::from(d.0 * d.0 + d.1 * d.1));
            ConvexPair {
                p: to_world(&p, -30),
                q: to_world(&q, -30),
                contact: if g == 0 {
                    Contact::Touching
                } else {
                    Contact::Disjoint
                },
                sq_dist: Some(sq_of(12 * g, -30) * dd),
            }
        }
    }
}
