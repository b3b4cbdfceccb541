//! σ of general (non-monotone) simple chains and of whole closed polygon boundaries, separated by a
//! line through an edge of one polygon's hull: agreement with the exact oracle and the brute force,
//! the envelope against its `O(n²)` twin, every CVV/CVE matrix checked for total monotonicity.

mod common;

use common::pairs::oracle_feature;
use common::{Case, assert_optimal, simple_chain};
use glam::DVec2;
use monotone_minima::{brute_force_row_minima_by, check_totally_monotone_by, row_minima_by};
use polydist_oracle::{SplitMix64, chain_distance, comb, spiral, star, two_opt};
use polydist_predicates::{Exact, Fast, Kernel, Robust};
use polydist_separation::{
    ChainMethod, CveMatrix, CvvMatrix, compare_edge_entries, compare_entries,
    perpendicular_envelope, perpendicular_envelope_brute, separation_brute, separation_of_chains,
    separation_of_chains_with,
};
use proptest::prelude::*;

type I = (i64, i64);

/// Integer coordinates of a generator's polygon (its coordinates are multiples of `2^-bits`).
fn ints(poly: &[DVec2], bits: i32) -> Vec<I> {
    let s = 2f64.powi(bits);
    poly.iter()
        .map(|v| {
            let (x, y) = (v.x * s, v.y * s);
            assert!(x.fract() == 0.0 && y.fract() == 0.0, "not on the lattice");
            (x as i64, y as i64)
        })
        .collect()
}

fn cross(o: I, a: I, b: I) -> i128 {
    let (ax, ay) = (i128::from(a.0 - o.0), i128::from(a.1 - o.1));
    let (bx, by) = (i128::from(b.0 - o.0), i128::from(b.1 - o.1));
    ax * by - ay * bx
}

/// The strictly convex hull, counter-clockwise (Andrew).
fn hull(pts: &[I]) -> Vec<I> {
    let mut p = pts.to_vec();
    p.sort_unstable();
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut h: Vec<I> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let it: Vec<I> = if pass == 0 {
            p.clone()
        } else {
            p.iter().rev().copied().collect()
        };
        for x in it {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], x) <= 0 {
                h.pop();
            }
            h.push(x);
        }
        h.pop();
    }
    h
}

/// A random simple polygon of one of several kinds, as integers (counter-clockwise).
fn polygon(rng: &mut SplitMix64, size: usize) -> (Vec<I>, &'static str) {
    let n = size.max(3);
    match rng.below(5) {
        0 => (ints(&two_opt(rng, n.min(40)), 20), "two_opt"),
        1 => (ints(&star(rng, n, 1 + n / 4), 24), "star"),
        2 => {
            let per = 3 + rng.index(6) as u32;
            let turns = 1 + (n as u32 / (2 * per)).min(6);
            (ints(&spiral(per, turns), 20), "spiral")
        }
        3 => (
            ints(
                &comb(1 + n / 4, 1 + rng.below(4) as u32, 1 + rng.below(2) as u32),
                0,
            ),
            "comb",
        ),
        _ => {
            // A comb with every second vertex doubled into a collinear run (midpoints).
            let c = ints(
                &comb(1 + n / 6, 1 + rng.below(3) as u32, 1 + rng.below(2) as u32),
                0,
            );
            let mut out = Vec::new();
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                out.push((2 * a.0, 2 * a.1));
                if rng.coin() {
                    out.push((a.0 + b.0, a.1 + b.1));
                }
            }
            (out, "comb+collinear")
        }
    }
}

/// Where [`polygon_pair`] puts `Q`.
#[derive(Clone, Copy, Debug)]
enum Place {
    /// Along the outward normal of the line to the least integer step strictly beyond it, plus
    /// this many steps.
    Beyond(i64),
    /// Exactly onto the line (its extreme vertices on it: a lattice step along the line's primitive
    /// normal direction, by Bézout), then slid along the line so that the two touching sets are
    /// this many (≥ 1) lattice steps apart, above or below: both chains touch the line and the
    /// polygons are disjoint.
    Touching(i64),
}

/// Two polygons with disjoint hulls, the line through a random edge of `P`'s hull (`P` touches
/// it), `Q` placed as `place` says, then everything rotated by an integer rotation and offset,
/// cut into open sub-chains or closed, reversed and swapped at random.
fn polygon_pair(
    rng: &mut SplitMix64,
    (np, nq): (usize, usize),
    place: Place,
    rot: I,
    offset: DVec2,
    open: bool,
) -> Case {
    let (p, kp) = polygon(rng, np);
    let (q, kq) = polygon(rng, nq);
    let h = hull(&p);
    let i = rng.index(h.len());
    let (h1, h2) = (h[i], h[(i + 1) % h.len()]);
    let (q, how) = match place {
        Place::Beyond(extra) => (beyond(rng, q, (h1, h2), extra), format!("extra {extra}")),
        Place::Touching(gap) => (
            touching(rng, &p, q, (h1, h2), gap),
            format!("touching, gap {gap}"),
        ),
    };
    let name = format!("{kp}({}) vs {kq}({}) {how}", p.len(), q.len());
    finish(rng, &p, &q, (h1, h2), rot, offset, open, name)
}

/// `Q` moved beyond the line through `h1`, `h2` ([`Place::Beyond`]).
fn beyond(rng: &mut SplitMix64, q: Vec<I>, (h1, h2): (I, I), extra: i64) -> Vec<I> {
    let d = (h2.0 - h1.0, h2.1 - h1.1);
    let n = (d.1, -d.0); // right of h1 → h2: outside P
    let d2 = i128::from(d.0) * i128::from(d.0) + i128::from(d.1) * i128::from(d.1);
    // Move q[0] onto h1 plus a random slide along the edge, then step outward.
    let slide = rng.range_i64(-2, 3);
    let s0 = (h1.0 - q[0].0 + slide * d.0, h1.1 - q[0].1 + slide * d.1);
    let moved: Vec<I> = q.iter().map(|&v| (v.0 + s0.0, v.1 + s0.1)).collect();
    // orient(h1, h2, v + k n) = cross(h1, h2, v) − k |d|² < 0 for all v.
    let need = moved
        .iter()
        .map(|&v| cross(h1, h2, v).div_euclid(d2) + 1)
        .max()
        .unwrap_or(0);
    let k = (need.max(0) as i64) + extra;
    moved
        .iter()
        .map(|&v| (v.0 + k * n.0, v.1 + k * n.1))
        .collect()
}

/// Integers `(x, y)` with `a·y − b·x = gcd(a, b)` (extended Euclid), for `(a, b) ≠ (0, 0)`.
fn bezout(a: i64, b: i64) -> (i64, i64, i64) {
    // Invariants: r0 = a·u0 + b·v0 style on (a, −b): find u, w with a·u + b·w = g, then y = u, x = −w.
    let (mut r0, mut r1, mut u0, mut u1, mut w0, mut w1) = (a, b, 1i64, 0i64, 0i64, 1i64);
    while r1 != 0 {
        let t = r0.div_euclid(r1);
        (r0, r1) = (r1, r0 - t * r1);
        (u0, u1) = (u1, u0 - t * u1);
        (w0, w1) = (w1, w0 - t * w1);
    }
    if r0 < 0 {
        (r0, u0, w0) = (-r0, -u0, -w0);
    }
    (-w0, u0, r0)
}

/// `Q` moved onto the line through `h1`, `h2` of `P`'s hull and along it ([`Place::Touching`]).
fn touching(rng: &mut SplitMix64, p: &[I], q: Vec<I>, (h1, h2): (I, I), gap: i64) -> Vec<I> {
    let (t0, t1, g) = bezout(h2.0 - h1.0, h2.1 - h1.1);
    let dp = ((h2.0 - h1.0) / g, (h2.1 - h1.1) / g);
    // cross(dp, v − h1) ≥ 0 on P's side; Q's largest value is brought to 0.
    let side = |v: I| dp.0 * (v.1 - h1.1) - dp.1 * (v.0 - h1.0);
    let along = |v: I| dp.0 * (v.0 - h1.0) + dp.1 * (v.1 - h1.1);
    let q: Vec<I> = q
        .iter()
        .map(|&v| (v.0 - q[0].0 + h1.0, v.1 - q[0].1 + h1.1))
        .collect();
    let cmax = q.iter().map(|&v| side(v)).max().unwrap_or(0);
    // −cmax·(t0, t1), shortened by a multiple of `dp` (a move along the line) to stay small.
    // (In i128: `cmax · t` can exceed i64 before the shortening.)
    let w = |x: i64| i128::from(x);
    let tr = (-w(cmax) * w(t0), -w(cmax) * w(t1));
    let norm = w(dp.0) * w(dp.0) + w(dp.1) * w(dp.1);
    let k = -(tr.0 * w(dp.0) + tr.1 * w(dp.1)).div_euclid(norm);
    let tr = (
        i64::try_from(tr.0 + k * w(dp.0)).unwrap(),
        i64::try_from(tr.1 + k * w(dp.1)).unwrap(),
    );
    let q: Vec<I> = q.iter().map(|&v| (v.0 + tr.0, v.1 + tr.1)).collect();
    let range = |c: &[I]| {
        let on: Vec<i64> = c
            .iter()
            .filter(|&&v| side(v) == 0)
            .map(|&v| along(v))
            .collect();
        (*on.iter().min().unwrap(), *on.iter().max().unwrap())
    };
    let ((pmin, pmax), (qmin, qmax)) = (range(p), range(&q));
    let step = dp.0 * dp.0 + dp.1 * dp.1;
    // Slide by m·dp: `along` moves by m·step.
    let m = if rng.coin() {
        (pmax - qmin).div_euclid(step) + gap
    } else {
        -((qmax - pmin).div_euclid(step) + gap)
    };
    q.iter()
        .map(|&v| (v.0 + m * dp.0, v.1 + m * dp.1))
        .collect()
}

/// Places both polygons (integer rotation, offset), cuts open sub-chains or closes them, reverses
/// and swaps them at random, and orients the line through `h1`, `h2` at random.
#[allow(clippy::too_many_arguments, reason = "a test generator")]
fn finish(
    rng: &mut SplitMix64,
    p: &[I],
    q: &[I],
    (h1, h2): (I, I),
    rot: I,
    offset: DVec2,
    open: bool,
    mut name: String,
) -> Case {
    let place = |v: I| {
        let (c, s) = rot;
        DVec2::new(
            (c * v.0 - s * v.1) as f64 + offset.x,
            (s * v.0 + c * v.1) as f64 + offset.y,
        )
    };
    let mut pw: Vec<DVec2> = p.iter().map(|&v| place(v)).collect();
    let mut qw: Vec<DVec2> = q.iter().map(|&v| place(v)).collect();
    if open {
        // Contiguous sub-chains (cyclically), at least one vertex: open, simple.
        let cut = |rng: &mut SplitMix64, v: &[DVec2]| {
            let (s, len) = (rng.index(v.len()), 1 + rng.index(v.len()));
            (0..len).map(|t| v[(s + t) % v.len()]).collect::<Vec<_>>()
        };
        pw = cut(rng, &pw);
        qw = cut(rng, &qw);
        name.push_str(" open");
    } else {
        pw.push(pw[0]);
        qw.push(qw[0]);
    }
    if rng.coin() {
        pw.reverse();
    }
    if rng.coin() {
        qw.reverse();
    }
    let (a, b) = if rng.coin() {
        (place(h1), place(h2))
    } else {
        (place(h2), place(h1))
    };
    // Either chain may be the one touching the line.
    if rng.coin() {
        core::mem::swap(&mut pw, &mut qw);
        name.push_str(" swapped");
    }
    Case {
        p: pw,
        q: qw,
        a,
        b,
        name,
    }
}

/// Checks one case: σ and its features against the oracle, the brute force against the oracle, the
/// envelopes against their twins, and (small cases) every matrix.
fn agree<K: Kernel>(c: &Case, check_matrices: bool) {
    assert!(simple_chain(&c.p) && simple_chain(&c.q), "{}", c.name);
    let exact = chain_distance(&c.p, &c.q);
    // The paper's matrices, and the envelope sweep first (the default method of the polygon
    // routes): each an exact optimum.
    for method in [ChainMethod::Matrices, ChainMethod::Auto] {
        let got =
            separation_of_chains_with::<K>(&c.p, &c.q, c.a, c.b, method).unwrap_or_else(|e| {
                panic!(
                    "{} ({}, {method:?}): {e}\np={:?}\nq={:?}",
                    c.name,
                    K::NAME,
                    c.p,
                    c.q
                )
            });
        assert_optimal(c, &format!("{}, {method:?}", K::NAME), &exact, &got.pair);
    }
    let brute = separation_brute::<K>(&c.p, &c.q).unwrap();
    assert!(
        exact.is_optimal_pair(
            oracle_feature(brute.feature_p),
            oracle_feature(brute.feature_q)
        ),
        "{}: brute force",
        c.name
    );
    for ch in [&c.p, &c.q] {
        assert_eq!(
            perpendicular_envelope::<K>(ch, c.a, c.b).unwrap(),
            perpendicular_envelope_brute::<K>(ch, c.a, c.b).unwrap(),
            "{}: envelope of {ch:?}",
            c.name
        );
    }
    // With every vertex on the line (touching one-vertex sub-chains) there is no side, hence no
    // matrix: σ is the on-line pair alone.
    let all_on_line =
        c.p.iter()
            .chain(&c.q)
            .all(|&v| Exact::orient(c.a, c.b, v).sign().is_zero());
    if check_matrices && !all_on_line {
        let m = CvvMatrix::<K>::new(&c.p, &c.q, c.a, c.b).unwrap();
        check_totally_monotone_by(&m, compare_entries::<K, _>)
            .unwrap_or_else(|e| panic!("{}: CVV matrix not totally monotone: {e:?}", c.name));
        assert_eq!(
            row_minima_by(&m, compare_entries::<K, _>),
            brute_force_row_minima_by(&m, compare_entries::<K, _>),
            "{}",
            c.name
        );
        for (p, q) in [(&c.p, &c.q), (&c.q, &c.p)] {
            let m = CveMatrix::<K>::new(p, q, c.a, c.b).unwrap();
            check_totally_monotone_by(&m, compare_edge_entries::<K, _>).unwrap_or_else(|e| {
                panic!(
                    "{}: CVE matrix not totally monotone: {e:?}\np={p:?}\nq={q:?}\nline {:?} {:?}",
                    c.name, c.a, c.b
                )
            });
            assert_eq!(
                row_minima_by(&m, compare_edge_entries::<K, _>),
                brute_force_row_minima_by(&m, compare_edge_entries::<K, _>),
                "{}",
                c.name
            );
        }
    }
}

/// Both chains touching the line (`Place::Touching`), closed and open, every matrix checked on the
/// small ones: the pairs on the line come from `on_the_line`, every other pair from the wedges.
#[test]
fn chains_touching_the_line_from_both_sides() {
    let mut rng = SplitMix64::new(0x7007_c4ed);
    for round in 0..1200 {
        let size = 3 + rng.index(12);
        let rot = ROTS[rng.index(ROTS.len())];
        let far = round % 5 == 4;
        let off = if far {
            DVec2::new(-1e12, 4e12)
        } else {
            DVec2::ZERO
        };
        let gap = 1 + rng.range_i64(0, 3);
        let c = polygon_pair(
            &mut rng,
            (size, size),
            Place::Touching(gap),
            rot,
            off,
            round % 2 == 1,
        );
        agree::<Robust>(&c, size <= 10);
        if far {
            agree::<Exact>(&c, false);
        }
    }
}

const ROTS: [I; 6] = [(1, 0), (0, 1), (3, 4), (-4, 3), (5, -12), (1, 1)];

#[test]
fn closed_polygons_small_with_matrix_checks() {
    let mut rng = SplitMix64::new(0x601);
    let mut ran = 0;
    for size in [3usize, 4, 6, 9, 14] {
        for _ in 0..120 {
            let rot = ROTS[rng.index(ROTS.len())];
            let place = Place::Beyond(rng.range_i64(0, 3));
            let c = polygon_pair(&mut rng, (size, size), place, rot, DVec2::ZERO, false);
            agree::<Robust>(&c, c.p.len() + c.q.len() <= 60);
            ran += 1;
        }
    }
    assert!(ran >= 600);
}

#[test]
fn open_subchains_of_polygons() {
    let mut rng = SplitMix64::new(0x602);
    for size in [3usize, 5, 8, 12, 20] {
        for _ in 0..120 {
            let rot = ROTS[rng.index(ROTS.len())];
            let place = Place::Beyond(rng.range_i64(0, 3));
            let c = polygon_pair(&mut rng, (size, size), place, rot, DVec2::ZERO, true);
            agree::<Robust>(&c, c.p.len() + c.q.len() <= 50);
        }
    }
}

#[test]
fn exact_kernel_far_from_the_origin() {
    let mut rng = SplitMix64::new(0x603);
    for size in [3usize, 6, 10] {
        for _ in 0..30 {
            let rot = ROTS[rng.index(ROTS.len())];
            let open = rng.coin();
            let extra = rng.range_i64(0, 2);
            let c = polygon_pair(
                &mut rng,
                (size, size),
                Place::Beyond(extra),
                rot,
                DVec2::new(1e12, -3e12),
                open,
            );
            agree::<Exact>(&c, c.p.len() + c.q.len() <= 40);
            agree::<Robust>(&c, false);
        }
    }
}

/// A comb against a polygon, the line along the comb's spine (teeth perpendicular to the line,
/// many vertices at equal heights, shadow points at vertices) or along its first tooth's outer side
/// (teeth parallel to the line: the comb is far from monotone).
#[test]
fn combs_with_axis_aligned_lines() {
    let mut rng = SplitMix64::new(0x604);
    for teeth in [1usize, 2, 3, 5, 8] {
        for (len, space) in [(1u32, 1u32), (3, 1), (2, 2)] {
            let p = ints(&comb(teeth, len, space), 0);
            for along_spine in [true, false] {
                for _ in 0..4 {
                    let (q, kq) = polygon(&mut rng, 6);
                    // P is the comb: spine bottom y = -1 from x = 0; left side x = 0.
                    let (h1, h2, n): (I, I, I) = if along_spine {
                        ((0, -1), (1, -1), (0, -1))
                    } else {
                        ((0, 1), (0, 0), (-1, 0))
                    };
                    let qmin = |f: &dyn Fn(I) -> i64| q.iter().map(|&v| f(v)).min().unwrap();
                    let qmax = |f: &dyn Fn(I) -> i64| q.iter().map(|&v| f(v)).max().unwrap();
                    let gap = rng.range_i64(1, 3);
                    // Move Q beyond the line along n by `gap` past its extreme vertex.
                    let (dx, dy) = if along_spine {
                        (
                            rng.range_i64(-3, 5) - qmin(&|v| v.0),
                            -1 - gap - qmax(&|v| v.1),
                        )
                    } else {
                        (-gap - qmax(&|v| v.0), rng.range_i64(-3, 5) - qmin(&|v| v.1))
                    };
                    let _ = n;
                    let mut pw: Vec<DVec2> = p
                        .iter()
                        .map(|&v| DVec2::new(v.0 as f64, v.1 as f64))
                        .collect();
                    let mut qw: Vec<DVec2> = q
                        .iter()
                        .map(|&v| DVec2::new((v.0 + dx) as f64, (v.1 + dy) as f64))
                        .collect();
                    pw.push(pw[0]);
                    qw.push(qw[0]);
                    let c = Case {
                        p: pw,
                        q: qw,
                        a: DVec2::new(h1.0 as f64, h1.1 as f64),
                        b: DVec2::new(h2.0 as f64, h2.1 as f64),
                        name: format!("comb({teeth},{len},{space}) vs {kq} spine {along_spine}"),
                    };
                    agree::<Robust>(&c, c.p.len() + c.q.len() <= 60);
                }
            }
        }
    }
}

/// Q a few ulps from the line that P touches (coordinates below 2 in magnitude, multiples of
/// `2^-52`: exact).
#[test]
fn nearly_touching_by_ulps() {
    let mut rng = SplitMix64::new(0x605);
    for ulps in [1i64, 2, 3, 4] {
        for _ in 0..30 {
            let (p, _) = polygon(&mut rng, 6);
            let (q, kq) = polygon(&mut rng, 6);
            let scale = |v: &[I]| {
                let m = v
                    .iter()
                    .map(|w| w.0.abs().max(w.1.abs()))
                    .max()
                    .unwrap_or(1)
                    .max(1) as f64;
                v.iter()
                    .map(|w| DVec2::new(w.0 as f64 / m / 2.0, w.1 as f64 / m / 2.0))
                    .collect::<Vec<_>>()
            };
            // Scaling by a non-power of two may round: keep only exact simple results.
            let (mut p, mut q) = (scale(&p), scale(&q));
            let pmin = p.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
            let qmax = q.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
            let g = ulps as f64 * 2f64.powi(-52);
            p.iter_mut().for_each(|v| v.x -= pmin);
            q.iter_mut().for_each(|v| v.x = v.x - qmax - g);
            p.push(p[0]);
            q.push(q[0]);
            if !simple_chain(&p) || !simple_chain(&q) || q.iter().any(|v| v.x >= 0.0) {
                continue;
            }
            let c = Case {
                p,
                q,
                a: DVec2::ZERO,
                b: DVec2::Y,
                name: format!("ulps {ulps} vs {kq}"),
            };
            agree::<Robust>(&c, c.p.len() + c.q.len() <= 40);
        }
    }
}

/// Two combs facing tip to tip across the line through `P`'s tips (teeth perpendicular to the line,
/// every tip at one depth, shadow points at vertices), `Q`'s tips 0 to 4 ulps of its coordinates
/// beyond, teeth aligned or shifted by half a pitch.
#[test]
fn combs_tip_to_tip_few_ulps_apart() {
    for teeth in [1usize, 2, 5, 12] {
        for len in [1u32, 3] {
            let p = comb(teeth, len, 1);
            let top = f64::from(len);
            // One ulp of the largest coordinate of Q: every coordinate stays exact.
            let u = (2.0 * top + 2.0).max(2.0 * teeth as f64 + 2.0);
            let ulp = 2f64.powi(u.log2().floor() as i32 - 52);
            for k in 1..=4 {
                for shift in [0.0, 0.5, 1.0] {
                    let g = k as f64 * ulp;
                    let mut pw = p.clone();
                    pw.push(pw[0]);
                    let mut qw: Vec<DVec2> = p
                        .iter()
                        .map(|v| DVec2::new(v.x + shift, (2.0 * top - v.y) + g))
                        .collect();
                    qw.push(qw[0]);
                    let c = Case {
                        p: pw,
                        q: qw,
                        a: DVec2::new(0.0, top),
                        b: DVec2::new(1.0, top),
                        name: format!("combs({teeth},{len}) {k} ulps shift {shift}"),
                    };
                    agree::<Robust>(&c, teeth <= 5);
                    agree::<Exact>(&c, false);
                    let _ = separation_of_chains::<Fast>(&c.p, &c.q, c.a, c.b);
                }
            }
        }
    }
}

#[test]
fn larger_spirals_and_combs_against_the_brute_force() {
    let mut rng = SplitMix64::new(0x606);
    for _ in 0..12 {
        let c = polygon_pair(
            &mut rng,
            (60, 60),
            Place::Beyond(1),
            (3, 4),
            DVec2::new(1e12, 1e12),
            false,
        );
        agree::<Robust>(&c, false);
    }
}

#[test]
fn fast_kernel_terminates() {
    let mut rng = SplitMix64::new(0x607);
    for size in [3usize, 8, 20, 60] {
        for _ in 0..40 {
            let open = rng.coin();
            let c = polygon_pair(
                &mut rng,
                (size, size),
                Place::Beyond(0),
                (5, -12),
                DVec2::new(1e12, -1e12),
                open,
            );
            let _ = separation_of_chains::<Fast>(&c.p, &c.q, c.a, c.b);
            let _ = separation_of_chains_with::<Fast>(&c.p, &c.q, c.a, c.b, ChainMethod::Auto);
            let _ = perpendicular_envelope::<Fast>(&c.p, c.a, c.b);
        }
    }
}

/// The envelope of a spiral's outer chain (a closed polygon) against its twin, with a line through
/// each hull edge in turn.
#[test]
fn envelope_of_spirals_and_stars_matches_the_twin() {
    let mut rng = SplitMix64::new(0x608);
    for (poly, name) in [
        (ints(&spiral(5, 4), 20), "spiral"),
        (ints(&spiral(8, 3), 20), "spiral"),
        (ints(&star(&mut rng, 40, 7), 24), "star"),
        (ints(&comb(6, 3, 1), 0), "comb"),
    ] {
        let h = hull(&poly);
        let mut pw: Vec<DVec2> = poly
            .iter()
            .map(|&v| DVec2::new(v.0 as f64, v.1 as f64))
            .collect();
        pw.push(pw[0]);
        for i in 0..h.len() {
            let (a, b) = (h[i], h[(i + 1) % h.len()]);
            let (a, b) = (
                DVec2::new(a.0 as f64, a.1 as f64),
                DVec2::new(b.0 as f64, b.1 as f64),
            );
            let fast = perpendicular_envelope::<Robust>(&pw, a, b).unwrap();
            let brute = perpendicular_envelope_brute::<Robust>(&pw, a, b).unwrap();
            assert_eq!(fast, brute, "{name}, hull edge {i}");
            assert!(fast.vertices.len() >= 2);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    /// σ, its features, the brute force, the envelopes, and every matrix (total monotonicity,
    /// SMAWK's minima against the brute force's). It found
    /// `regression_whole_edge_entries_broke_total_monotonicity`.
    #[test]
    fn proptest_polygons_agree_with_oracle(seed in any::<u64>(), size in 3usize..16,
                                           open in any::<bool>(), far in any::<bool>(),
                                           extra in 0i64..3) {
        agree::<Robust>(&proptest_case(seed, size, open, far, Place::Beyond(extra)), true);
    }

    /// The envelope's scan against its twin on lattice chains (see
    /// `envelope_scan_matches_the_twin_on_lattice_chains`), longer ones included.
    #[test]
    fn proptest_envelope_scan_on_lattice_chains(seed in any::<u64>(), n in 3usize..24,
                                                closed in any::<bool>()) {
        if let Some((chain, a, b)) = lattice_envelope_case(seed, n, closed) {
            prop_assert_eq!(
                perpendicular_envelope::<Robust>(&chain, a, b).unwrap(),
                perpendicular_envelope_brute::<Robust>(&chain, a, b).unwrap()
            );
        }
    }

    /// The same with both chains touching the line.
    #[test]
    fn proptest_chains_touching_from_both_sides(seed in any::<u64>(), size in 3usize..16,
                                                open in any::<bool>(), far in any::<bool>(),
                                                gap in 1i64..4) {
        agree::<Robust>(&proptest_case(seed, size, open, far, Place::Touching(gap)), true);
    }
}

/// A lattice chain for the envelope's scan: `n` points of a `6 × 6` grid (open, or closed when
/// `closed`), so that many vertices share a height, edges run perpendicular to the line and
/// collinear runs meet; `None` when the draw is not simple. The line has a direction of small
/// integers and touches the chain (through its vertex of least depth), in either orientation.
fn lattice_envelope_case(seed: u64, n: usize, closed: bool) -> Option<(Vec<DVec2>, DVec2, DVec2)> {
    let mut rng = SplitMix64::new(seed);
    let mut chain: Vec<DVec2> = (0..n)
        .map(|_| DVec2::new(rng.range_i64(1, 6) as f64, rng.range_i64(0, 5) as f64))
        .collect();
    chain.dedup();
    if chain.len() < 3 {
        return None;
    }
    if closed {
        chain.push(chain[0]);
    }
    if !simple_chain(&chain) {
        return None;
    }
    let d = DVec2::new(rng.range_i64(-3, 3) as f64, rng.range_i64(-3, 3) as f64);
    if d == DVec2::ZERO {
        return None;
    }
    let a = *chain
        .iter()
        .min_by(|p, q| d.perp_dot(**p).total_cmp(&d.perp_dot(**q)))?;
    Some(if rng.coin() {
        (chain, a, a + d)
    } else {
        (chain, a + d, a)
    })
}

/// The envelope's linear scan against its twin on lattice chains (shared heights, perpendicular
/// edges, collinear runs, touching lines, both sides of the line), under Robust and Exact: the
/// degenerate inputs of the scan's symbolic shear (`docs/algorithms/separation.md`, "The linear
/// scan"). 40,000 draws, of which about a tenth are simple (3,764 in the first 20,000); the Fast
/// kernel runs on each too.
#[test]
fn envelope_scan_matches_the_twin_on_lattice_chains() {
    let mut checked = 0;
    for seed in 0..40_000u64 {
        let n = 3 + (seed % 11) as usize;
        let Some((chain, a, b)) = lattice_envelope_case(seed, n, seed % 3 == 0) else {
            continue;
        };
        let twin = perpendicular_envelope_brute::<Robust>(&chain, a, b).unwrap();
        assert_eq!(
            perpendicular_envelope::<Robust>(&chain, a, b).unwrap(),
            twin,
            "seed {seed}: {chain:?}, line {a} → {b}"
        );
        assert_eq!(
            perpendicular_envelope::<Exact>(&chain, a, b).unwrap(),
            twin,
            "seed {seed} (Exact)"
        );
        // Fast (exact on these small integers, but run for its own code path): no panic.
        let _ = perpendicular_envelope::<Fast>(&chain, a, b);
        checked += 1;
    }
    assert!(checked > 6_000, "{checked}");
}

/// The case the proptest draws for its parameters.
fn proptest_case(seed: u64, size: usize, open: bool, far: bool, place: Place) -> Case {
    let mut rng = SplitMix64::new(seed);
    let rot = ROTS[rng.index(ROTS.len())];
    let off = if far {
        DVec2::new(-1e12, 4e12)
    } else {
        DVec2::ZERO
    };
    polygon_pair(&mut rng, (size, size), place, rot, off, open)
}

/// The envelope against an independent exact definition (rationals, line `x = 0`, chains on
/// `x ≥ 0`): at every vertex height the reported visible vertex (or none) is the unique nearest
/// point, and at every height strictly between two consecutive visible vertices (all vertex heights
/// there and the midpoints between them) the reported edge is the nearest.
#[test]
fn envelope_matches_exact_definition() {
    use polydist_oracle::rat;
    use polydist_predicates::BigRational;
    let mut rng = SplitMix64::new(0x609);
    let mut checked = 0;
    for n in [3usize, 5, 8, 13, 20] {
        for _ in 0..40 {
            let poly: Vec<DVec2> = two_opt(&mut rng, n)
                .into_iter()
                .map(|v| DVec2::new(v.x + 1.0, v.y))
                .collect();
            let chain: Vec<DVec2> = if rng.coin() {
                let mut c = poly.clone();
                c.push(poly[0]);
                c
            } else {
                let (s0, len) = (rng.index(n), 1 + rng.index(n));
                (0..len).map(|t| poly[(s0 + t) % n]).collect()
            };
            let env = perpendicular_envelope::<Robust>(&chain, DVec2::ZERO, DVec2::Y).unwrap();
            let r = |x: f64| rat(x).unwrap();
            let segs: Vec<(DVec2, DVec2)> = chain.windows(2).map(|w| (w[0], w[1])).collect();
            // Depths of the chain at height y: vertices there and edges crossing y.
            let at = |y: &BigRational| -> Vec<(BigRational, Option<usize>)> {
                let mut out = Vec::new();
                for (i, v) in chain.iter().enumerate() {
                    if r(v.y) == *y {
                        out.push((r(v.x), Some(i)));
                    }
                }
                for (a, b) in &segs {
                    let (ya, yb) = (r(a.y), r(b.y));
                    if (ya < *y && *y < yb) || (yb < *y && *y < ya) {
                        let x = r(a.x) + (y - &ya) * (r(b.x) - r(a.x)) / (yb - ya);
                        out.push((x, None));
                    }
                }
                out
            };
            let nearest = |y: &BigRational| {
                at(y)
                    .into_iter()
                    .min_by(|p, q| p.0.cmp(&q.0))
                    .expect("a covered height")
            };
            // Visible vertices: exactly the vertex heights whose nearest point is a vertex.
            let mut heights: Vec<BigRational> = chain.iter().map(|v| r(v.y)).collect();
            heights.sort();
            heights.dedup();
            let vis: Vec<BigRational> = env.vertices.iter().map(|&i| r(chain[i].y)).collect();
            for y in &heights {
                let (x, who) = nearest(y);
                match vis.iter().position(|h| h == y) {
                    Some(k) => {
                        assert_eq!(r(chain[env.vertices[k]].x), x, "{chain:?}");
                        assert!(who.is_some(), "{chain:?}");
                    }
                    None => assert!(who.is_none(), "vertex at {y} missed in {chain:?}"),
                }
            }
            // Between consecutive visible vertices, the reported edge is nearest.
            for k in 0..env.edges.len() {
                let (a, b) = segs[env.edges[k]];
                let (lo, hi) = (&vis[k], &vis[k + 1]);
                let mut ys: Vec<BigRational> = heights
                    .iter()
                    .filter(|h| lo < *h && *h < hi)
                    .cloned()
                    .collect();
                ys.insert(0, lo.clone());
                ys.push(hi.clone());
                for w in ys.windows(2) {
                    let y = (&w[0] + &w[1]) / BigRational::from_integer(2.into());
                    let (x, _) = nearest(&y);
                    let (ya, yb) = (r(a.y), r(b.y));
                    let xe = r(a.x) + (&y - &ya) * (r(b.x) - r(a.x)) / (yb - ya);
                    assert_eq!(x, xe, "edge {} at {y} in {chain:?}", env.edges[k]);
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 1000, "{checked}");
}

/// A CVE matrix that was **not** totally monotone while `Dist` entries held the distance to the
/// row's *whole* edge (found by the proptest on closed polygons, seed in
/// `general.proptest-regressions`): the nearest point of that edge to the far, nearly coincident
/// columns is its start, outside the piece the `α` clip left (`t ∈ [0.769, 1]`), and the whole-edge
/// distances ordered the columns `q1 < q0 < q2` where the piece's own order `q1 < q2 < q0` is
/// consistent with the row below. The second case is the same configuration as a monotone chain with
/// a perpendicular run. The third case (an open 2-opt chain against a comb with collinear runs,
/// rows 2–3, columns 0–4) is the first failure of a 200,000-case run of the proptest against the
/// envelope-part entries that came between, after 54,159 cases. Entries now hold the distance to the
/// piece, its arc ends kept symbolic (`clipped.rs`): every matrix is totally monotone and SMAWK's
/// minima are the brute force's.
#[test]
fn regression_whole_edge_entries_broke_total_monotonicity() {
    let v = |x: f64, y: f64| DVec2::new(x, y);
    let polygon = vec![
        v(-805699.0, 140027.0),
        v(47128.0, -871327.0),
        v(1028187.0, -584971.0),
        v(416564.0, -296216.0),
        v(-64988.0, 501939.0),
        v(-168274.0, 746336.0),
        v(852559.0, 724435.0),
        v(-605291.0, 1026171.0),
        v(-805699.0, 140027.0),
    ];
    let comb = vec![
        v(1986337.0, 2209469.0),
        v(1986337.0, 2209474.0),
        v(1986338.0, 2209474.0),
        v(1986338.0, 2209470.0),
        v(1986339.0, 2209470.0),
        v(1986339.0, 2209474.0),
        v(1986340.0, 2209474.0),
        v(1986340.0, 2209470.0),
        v(1986341.0, 2209470.0),
        v(1986341.0, 2209474.0),
        v(1986342.0, 2209474.0),
        v(1986342.0, 2209469.0),
        v(1986337.0, 2209469.0),
    ];
    // The same configuration in the frame of the line x = 0, P monotone with a perpendicular run
    // (0, 0) → (965883, 0) walked away from the line.
    let run = vec![
        v(1404799.0, -492861.0),
        v(0.0, 0.0),
        v(965883.0, 0.0),
        v(938981.0, 98545.0),
        v(567808.0, 953632.0),
        v(0.0, 1321132.0),
        v(1010419.0, 1474527.0),
    ];
    let q3 = vec![
        v(-1321132.5, -1321136.75),
        v(-1321132.0, -1321132.0),
        v(-1321136.75, -1321131.0),
    ];
    for c in [
        Case {
            p: polygon,
            q: comb,
            a: v(852559.0, 724435.0),
            b: v(1028187.0, -584971.0),
            name: "polygon".into(),
        },
        Case {
            p: run,
            q: q3,
            a: DVec2::ZERO,
            b: DVec2::Y,
            name: "monotone with a run".into(),
        },
        proptest_case(
            14_620_136_695_611_095_605,
            10,
            true,
            false,
            Place::Beyond(2),
        ),
    ] {
        // σ (oracle), features, envelopes, and every matrix: totally monotone, SMAWK = brute force.
        agree::<Robust>(&c, true);
        agree::<Exact>(&c, true);
    }
}
