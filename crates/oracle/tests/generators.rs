//! Every generator's documented guarantee, checked with the exact oracle.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use polydist_oracle::{
    Axis, Contact, Feature, Location, OFFSETS, PocketLid, Relation, SplitMix64, boundary_distance,
    cocircular, cocircular_perturbed, collinear_triples, comb, contact_status_convex,
    contact_status_simple, convex_distance, convex_pair, interleaved_combs, interleaved_combs_ulps,
    is_convex, is_simple, is_strictly_convex, near_collinear, offset, offset_family,
    parallel_facing, pocket_around, pocket_pair, point_in_polygon, random_convex,
    random_convex_lattice, rat, short_dyadic, sign_orient, signed_area, sliver, spiral, star,
    star_in_range, step_ulps, two_opt, with_gap_ulps,
};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

fn r(x: f64) -> BigRational {
    rat(x).unwrap()
}

fn ccw(p: &[DVec2]) -> bool {
    signed_area(p).is_positive()
}

#[test]
fn splitmix64_reference_outputs() {
    let mut g = SplitMix64::new(0);
    assert_eq!(g.next_u64(), 0xe220_a839_7b1d_cdaf);
    assert_eq!(g.next_u64(), 0x6e78_9e6a_a1b9_65f4);
    assert_eq!(g.next_u64(), 0x06c4_5d18_8009_454f);
    let mut a = SplitMix64::new(42);
    let mut b = SplitMix64::new(42);
    for _ in 0..100 {
        assert_eq!(a.next_u64(), b.next_u64());
        let x = a.range_i64(-3, 3);
        assert_eq!(x, b.range_i64(-3, 3));
        assert!((-3..=3).contains(&x));
        let u = a.unit_f64();
        assert_eq!(u, b.unit_f64());
        assert!((0.0..1.0).contains(&u));
    }
    assert_eq!(
        a.range_i64(i64::MIN, i64::MAX),
        b.range_i64(i64::MIN, i64::MAX)
    );
}

#[test]
fn random_convex_guarantees() {
    let mut rng = SplitMix64::new(100);
    let centers = [
        v(0., 0.),
        v(1e8, -1e8),
        v(1e12, 3.0),
        v(-1e15, 1e15),
        v(0.5, 0.25),
    ];
    for (k, &c) in centers.iter().enumerate() {
        for n in [3usize, 4, 5, 8, 33, 200] {
            let radius = [1.0, 1e-3, 1e6, 1.0, 1e-9][k];
            let p = random_convex(&mut rng, n, c, radius);
            assert_eq!(p.len(), n);
            assert!(is_strictly_convex(&p), "n={n} c={c:?}");
            assert!(ccw(&p));
            // Inside the square of half-side radius around the centre, unless
            // the grid had to be coarsened (far centre, tiny radius).
            let ext = p
                .iter()
                .map(|x| (*x - c).abs().max_element())
                .fold(0.0, f64::max);
            if c.abs().max_element() / radius < 1e9 {
                assert!(ext <= radius * 1.01, "{ext} {radius}");
                assert!(ext >= radius * 0.25, "{ext} {radius}");
            }
        }
    }
    // Reproducible.
    let a = random_convex(&mut SplitMix64::new(7), 50, DVec2::ZERO, 1.0);
    let b = random_convex(&mut SplitMix64::new(7), 50, DVec2::ZERO, 1.0);
    assert_eq!(a, b);
}

/// Exact strict convexity of a huge ccw polygon with i128 arithmetic on the
/// integer lattice it lives on (the generic BigInt check is also run on a
/// smaller instance above).
fn strictly_convex_lattice_check(p: &[DVec2]) -> bool {
    // Scale back to integers: coordinates are multiples of a power of two.
    let step = p
        .iter()
        .flat_map(|q| [q.x, q.y])
        .filter(|&x| x != 0.0)
        .map(|x| {
            let bits = x.abs().to_bits();
            let e = ((bits >> 52) & 0x7ff) as i32 - 1075;
            let m = (bits & ((1 << 52) - 1)) | (1 << 52);
            e + m.trailing_zeros() as i32
        })
        .min()
        .unwrap();
    let s = 2f64.powi(-step);
    let w: Vec<(i128, i128)> = p
        .iter()
        .map(|q| ((q.x * s) as i128, (q.y * s) as i128))
        .collect();
    let n = w.len();
    let mut wraps = 0;
    for i in 0..n {
        let (a, b, c) = (w[i], w[(i + 1) % n], w[(i + 2) % n]);
        let (e1, e2) = ((b.0 - a.0, b.1 - a.1), (c.0 - b.0, c.1 - b.1));
        if e1.0 * e2.1 - e1.1 * e2.0 <= 0 {
            return false;
        }
        let up = |e: (i128, i128)| e.1 > 0 || (e.1 == 0 && e.0 > 0);
        if !up(e1) && up(e2) {
            wraps += 1;
        }
    }
    wraps == 1
}

#[test]
fn random_convex_large() {
    let mut rng = SplitMix64::new(101);
    let p = random_convex(&mut rng, 100_000, v(3.0, -2.0), 10.0);
    assert_eq!(p.len(), 100_000);
    assert!(strictly_convex_lattice_check(&p));
    // The i128 check agrees with the exact oracle on smaller inputs.
    let small = random_convex(&mut rng, 500, DVec2::ZERO, 1.0);
    assert!(strictly_convex_lattice_check(&small));
    assert!(is_strictly_convex(&small));
    let mut broken = small.clone();
    broken.swap(3, 4);
    assert!(!strictly_convex_lattice_check(&broken));
    assert!(!is_strictly_convex(&broken));
}

#[test]
fn lattice_convex_guarantees() {
    let mut rng = SplitMix64::new(102);
    // Within the documented practical range (n up to about max^(2/3)), plus
    // a few tight cases.
    for (n, max) in [
        (3usize, 2i64),
        (4, 2),
        (3, 4),
        (4, 4),
        (5, 4),
        (6, 20),
        (7, 20),
        (10, 1000),
        (60, 1000),
    ] {
        {
            let p = random_convex_lattice(&mut rng, n, max);
            assert_eq!(p.len(), n);
            assert!(is_strictly_convex(&p));
            assert!(ccw(&p));
            for q in &p {
                assert_eq!(q.x.fract(), 0.0);
                assert!(q.x.abs() <= max as f64 && q.y.abs() <= max as f64);
            }
        }
    }
}

#[test]
fn cocircular_guarantees() {
    for k in 0..=22u32 {
        let p = cocircular(k);
        assert_eq!(p.len(), 4 * (2 * k as usize + 1));
        let r2 = BigInt::from(25).pow(k);
        for q in &p {
            let (x, y) = (q.x as i128, q.y as i128);
            assert_eq!((x as f64, y as f64), (q.x, q.y));
            assert_eq!(BigInt::from(x * x + y * y), r2);
        }
        assert_eq!(p[0], v(5f64.powi(k as i32), 0.0));
        if k <= 12 {
            assert!(is_strictly_convex(&p), "k={k}");
            assert!(ccw(&p));
        }
    }
}

#[test]
fn cocircular_perturbed_guarantees() {
    for k in [1u32, 2, 3, 6, 10] {
        let base = cocircular(k);
        let r2 = BigRational::from_integer(BigInt::from(25).pow(k));
        let step = if k <= 3 { 1 } else { 7 };
        for index in (0..base.len()).step_by(step) {
            for steps in [-1i64, 1] {
                let p = cocircular_perturbed(k, index, steps);
                assert!(is_strictly_convex(&p), "k={k} i={index} s={steps}");
                for (i, (a, b)) in base.iter().zip(&p).enumerate() {
                    if i != index {
                        assert_eq!(a, b);
                    }
                }
                let m = p[index];
                let n2 = r(m.x) * r(m.x) + r(m.y) * r(m.y);
                assert_eq!(
                    n2.cmp(&r2),
                    if steps > 0 {
                        Ordering::Greater
                    } else {
                        Ordering::Less
                    }
                );
                // The larger-magnitude coordinate moved by one step away from
                // (or towards) zero; the other is unchanged.
                let b0 = base[index];
                let (old, new, other_old, other_new) = if b0.x.abs() > b0.y.abs() {
                    (b0.x, m.x, b0.y, m.y)
                } else {
                    (b0.y, m.y, b0.x, m.x)
                };
                assert_eq!(other_old, other_new);
                assert_eq!(new.abs(), step_ulps(old.abs(), steps));
                assert_eq!(new.signum(), old.signum());
            }
        }
    }
}

#[test]
fn sliver_guarantees() {
    let mut rng = SplitMix64::new(103);
    for aspect in [1.0, 1e3, 1e6, 1e9] {
        for n in [3usize, 5, 12] {
            let p = sliver(&mut rng, n, aspect);
            assert_eq!(p.len(), n);
            assert!(is_strictly_convex(&p));
            assert!(ccw(&p));
            // Width: minimum over edge normals of the extent; length: diameter.
            let mut width = f64::INFINITY;
            let mut diam: f64 = 0.0;
            for i in 0..n {
                let e = (p[(i + 1) % n] - p[i]).normalize();
                let nrm = e.perp();
                let ext = p
                    .iter()
                    .map(|q| nrm.dot(*q - p[i]).abs())
                    .fold(0.0, f64::max);
                width = width.min(ext);
                for q in &p {
                    diam = diam.max((*q - p[i]).length());
                }
            }
            let ratio = diam / width;
            if n >= 5 {
                assert!(
                    ratio > aspect / 64.0 && ratio < aspect * 64.0 + 64.0,
                    "{aspect} {ratio}"
                );
            }
        }
    }
}

#[test]
fn parallel_facing_guarantees() {
    let mut rng = SplitMix64::new(104);
    let dirs = [(1, 0), (0, 1), (3, 4), (-7, 2), (1000, -999), (1 << 16, 1)];
    let gaps = [
        2f64.powi(-30),
        3.0 * 2f64.powi(-40),
        0.5,
        1.0,
        0.0,
        short_dyadic(1e-9, 20),
    ];
    for (i, &d) in dirs.iter().enumerate() {
        for (j, &gap) in gaps.iter().enumerate() {
            let n = 3 + (i + j) % 5;
            let f = parallel_facing(&mut rng, n, d, gap);
            assert_eq!((f.p.len(), f.q.len()), (n, n));
            assert!(is_strictly_convex(&f.p) && is_strictly_convex(&f.q));
            assert!(ccw(&f.p) && ccw(&f.q));
            let dd = BigRational::from_integer(BigInt::from(d.0 * d.0 + d.1 * d.1));
            assert_eq!(f.sq_dist, r(gap) * r(gap) * dd);
            let b = boundary_distance(&f.p, &f.q);
            assert_eq!(b.sq, f.sq_dist, "d={d:?} gap={gap}");
            assert!(b.is_optimal_pair(Feature::Edge(n - 1), Feature::Edge(n - 1)));
            // Facing edges exactly parallel to d.
            let (a0, a1) = (f.p[n - 1], f.p[0]);
            let (b0, b1) = (f.q[n - 1], f.q[0]);
            assert_eq!(sign_orient(a0, a1, a0 + (b1 - b0)), Ordering::Equal);
            let dir_ok = sign_orient(v(0., 0.), a0 - a1, v(d.0 as f64, d.1 as f64));
            assert_eq!(dir_ok, Ordering::Equal);
            let want = if gap == 0.0 {
                Contact::Touching
            } else {
                Contact::Disjoint
            };
            assert_eq!(contact_status_convex(&f.p, &f.q), want);
        }
    }
}

#[test]
#[should_panic(expected = "significand")]
fn parallel_facing_rejects_long_significands() {
    let _ = parallel_facing(&mut SplitMix64::new(1), 4, (3, 4), 1e-9);
}

#[test]
fn with_gap_ulps_and_offsets() {
    // p on the negative side with coordinates on the 2^-53 grid near -0.75.
    let p = vec![v(-0.875, -0.125), v(-0.75, 0.0), v(-0.875, 0.125)];
    let q = vec![
        v(0.0, 0.0),
        v(0.0625, -0.0625),
        v(0.125, 0.0),
        v(0.0625, 0.0625),
    ];
    for ulps in [0u64, 1, 2, 17, 1 << 20] {
        let q2 = with_gap_ulps(&p, &q, ulps, Axis::X).unwrap();
        let min_x = q2.iter().map(|x| x.x).fold(f64::INFINITY, f64::min);
        assert_eq!(min_x, step_ulps(-0.75, ulps as i64));
        for (a, b) in q.iter().zip(&q2) {
            assert_eq!(a.y, b.y);
            assert_eq!(r(b.x) - r(a.x), r(min_x) - r(0.0));
        }
        let d = boundary_distance(&p, &q2);
        let gap = r(min_x) - r(-0.75);
        assert_eq!(d.sq, &gap * &gap);
        let want = if ulps == 0 {
            Contact::Touching
        } else {
            Contact::Disjoint
        };
        assert_eq!(contact_status_convex(&p, &q2), want);
    }
    // Along y, from a point.
    let q3 = with_gap_ulps(&[v(0.0, 1.0)], &q, 3, Axis::Y).unwrap();
    let min_y = q3.iter().map(|x| x.y).fold(f64::INFINITY, f64::min);
    assert_eq!(min_y, step_ulps(1.0, 3));
    // Refused when not exact: fine coordinates moved to a huge magnitude.
    let far = vec![v(1e15, 0.0)];
    let fine = vec![v(0.1, 0.0), v(0.3, 0.1)];
    assert_eq!(with_gap_ulps(&far, &fine, 1, Axis::X), None);

    // Exact offsets.
    let lat = random_convex_lattice(&mut SplitMix64::new(5), 12, 1 << 20);
    for &o in &OFFSETS {
        let moved = offset(&lat, o, -o).unwrap();
        for (a, b) in lat.iter().zip(&moved) {
            assert_eq!(r(b.x) - r(a.x), r(o));
            assert_eq!(r(b.y) - r(a.y), r(-o));
        }
        assert!(is_strictly_convex(&moved));
    }
    assert_eq!(offset(&[v(0.1, 0.0)], 1e15, 0.0), None);
    // Families of a pair: identical exact distances and contacts.
    let other: Vec<DVec2> = random_convex_lattice(&mut SplitMix64::new(6), 9, 1 << 20)
        .into_iter()
        .map(|x| x + v(1_500_000.0, 3.0))
        .collect();
    let (fp, fq) = (offset_family(&lat), offset_family(&other));
    assert_eq!((fp.len(), fq.len()), (4, 4));
    assert_eq!(fp[0], (0.0, lat.clone()));
    let d0 = boundary_distance(&lat, &other);
    for ((o1, a), (o2, b)) in fp.iter().zip(&fq) {
        assert_eq!(o1, o2);
        assert_eq!(boundary_distance(a, b), d0);
        assert_eq!(
            contact_status_convex(a, b),
            contact_status_convex(&lat, &other)
        );
    }
    assert_eq!(offset_family(&[v(0.1, 0.3)]).len(), 1);
    assert!(offset(&[v(0.5, 0.0)], 1e15, 0.0).is_some());
}

#[test]
fn collinear_and_near_collinear() {
    let mut rng = SplitMix64::new(105);
    for &o in [0.0].iter().chain(&OFFSETS) {
        for [a, b, c] in collinear_triples(&mut rng, 50, o) {
            assert!(a != b && b != c && a != c);
            assert_eq!(sign_orient(a, b, c), Ordering::Equal);
            if o > 0.0 {
                assert!((a.x - o).abs() < o * 0.01 + 1e6);
            }
        }
        for [a, b, c] in near_collinear(&mut rng, 50, o, 4) {
            let s = sign_orient(a, b, c);
            assert_ne!(s, Ordering::Equal);
            // Recover the move and check the documented sign formula: the
            // unmoved point is exactly on the line, one coordinate differs.
            let on_line = |x: DVec2| sign_orient(a, b, x) == Ordering::Equal;
            let mut found = false;
            for k in -4i64..=4 {
                if k == 0 {
                    continue;
                }
                let cx = v(step_ulps(c.x, -k), c.y);
                if a.y != b.y && on_line(cx) {
                    let want = if (b.y - a.y > 0.0) == (k > 0) {
                        Ordering::Less
                    } else {
                        Ordering::Greater
                    };
                    assert_eq!(s, want);
                    found = true;
                }
                let cy = v(c.x, step_ulps(c.y, -k));
                if a.x != b.x && on_line(cy) {
                    let want = if (b.x - a.x > 0.0) == (k > 0) {
                        Ordering::Greater
                    } else {
                        Ordering::Less
                    };
                    assert_eq!(s, want);
                    found = true;
                }
            }
            assert!(found);
        }
    }
}

#[test]
fn short_dyadic_values() {
    assert_eq!(short_dyadic(1.0, 1), 1.0);
    assert_eq!(short_dyadic(0.75, 1), 1.0);
    // 0.625 = 0.101₂ is a tie at 2 bits; ties round away from zero.
    assert_eq!(short_dyadic(0.625, 2), 0.75);
    assert_eq!(short_dyadic(-0.625, 2), -0.75);
    assert_eq!(short_dyadic(0.6875, 2), 0.75);
    let x = short_dyadic(1e-9, 20);
    assert!((x - 1e-9).abs() < 1e-9 * 2f64.powi(-19));
    let bits = x.to_bits() & ((1 << 52) - 1);
    assert!(bits.trailing_zeros() >= 33);
    assert_eq!(short_dyadic(-3.0, 53), -3.0);
}

#[test]
fn star_guarantees() {
    let mut rng = SplitMix64::new(106);
    let mut non_convex = 0;
    for n in [3usize, 4, 5, 8, 20, 60] {
        for spikes in [0usize, 1, 3] {
            if spikes > n {
                continue;
            }
            let p = star(&mut rng, n, spikes);
            assert_eq!(p.len(), n);
            assert!(is_simple(&p), "n={n}");
            assert!(ccw(&p));
            assert_eq!(point_in_polygon(DVec2::ZERO, &p), Location::Inside);
            non_convex += usize::from(!is_convex(&p));
        }
    }
    assert!(non_convex >= 8, "{non_convex}");
}

#[test]
fn star_in_range_guarantees() {
    // `bits = 16` is `star`, draw for draw.
    for seed in 0..20u64 {
        let (mut a, mut b) = (SplitMix64::new(seed), SplitMix64::new(seed));
        let n = 3 + (seed as usize) % 40;
        assert_eq!(star(&mut a, n, n / 4), star_in_range(&mut b, n, n / 4, 16));
        assert_eq!(a.next_u64(), b.next_u64(), "the same draws consumed");
    }
    // Other ranges: simple, ccw, around the origin, the same size as `star` (every coordinate
    // at most 1 in magnitude, the spikes reaching past 1/2 when their directions are long).
    let mut rng = SplitMix64::new(107);
    for bits in [6u32, 8, 20, 30, 40] {
        for n in [3usize, 7, 40] {
            let p = star_in_range(&mut rng, n, n / 3, bits);
            assert_eq!(p.len(), n);
            assert!(is_simple(&p), "bits={bits} n={n}");
            assert!(ccw(&p));
            assert_eq!(point_in_polygon(DVec2::ZERO, &p), Location::Inside);
            assert!(p.iter().all(|v| v.x.abs() <= 1.0 && v.y.abs() <= 1.0));
        }
    }
}

#[test]
fn comb_guarantees() {
    for (n, len, space) in [(1usize, 1u32, 1u32), (2, 3, 1), (5, 10, 2), (30, 1, 1)] {
        let c = comb(n, len, space);
        assert_eq!(c.len(), 4 * n);
        assert!(is_simple(&c));
        assert!(ccw(&c));
        let area = BigRational::from_integer(BigInt::from(
            (n as i64 + (n as i64 - 1) * i64::from(space)) + n as i64 * i64::from(len),
        ));
        assert_eq!(signed_area(&c), area);
    }
}

#[test]
fn interleaved_combs_guarantees() {
    for (n, len) in [(1usize, 1u32), (3, 5), (8, 40)] {
        let unit = interleaved_combs_ulps(n, len, 1).unit;
        let cases = [
            interleaved_combs_ulps(n, len, 1),
            interleaved_combs_ulps(n, len, 3),
            interleaved_combs(n, len, 1e-9),
            interleaved_combs(n, len, 0.125),
            interleaved_combs(n, len, 0.0),
        ];
        for (i, c) in cases.iter().enumerate() {
            assert!(is_simple(&c.a) && is_simple(&c.b));
            assert!(ccw(&c.a) && ccw(&c.b));
            assert_eq!(c.b.len(), 4 * n + 4);
            let d = boundary_distance(&c.a, &c.b);
            assert_eq!(d.sq, r(c.gap) * r(c.gap), "case {i}");
            let want = if c.gap == 0.0 {
                Contact::Touching
            } else {
                Contact::Disjoint
            };
            assert_eq!(contact_status_simple(&c.a, &c.b), want);
            // The gap is a whole number of grid steps, and the requested one.
            assert_eq!((c.gap / unit).fract(), 0.0);
            // Interleaved: the middle of b's first tooth is in a's hull box.
            assert!(c.b.iter().any(|p| p.y < f64::from(len)));
        }
        assert_eq!(cases[0].gap, unit);
        assert_eq!(cases[1].gap, 3.0 * unit);
        assert!(cases[2].gap >= 1e-9 && cases[2].gap < 1e-9 + unit);
        assert_eq!(cases[3].gap, 0.125);
    }
}

#[test]
fn spiral_guarantees() {
    for (per_turn, turns) in [(3u32, 1u32), (4, 3), (7, 2), (16, 5), (50, 3)] {
        let s = spiral(per_turn, turns);
        assert_eq!(s.len(), 2 * (per_turn * turns + 1) as usize);
        assert!(is_simple(&s), "{per_turn} {turns}");
        assert!(ccw(&s));
    }
}

#[test]
fn two_opt_guarantees() {
    let mut rng = SplitMix64::new(107);
    for n in [3usize, 4, 5, 10, 25, 60] {
        for _ in 0..3 {
            let p = two_opt(&mut rng, n);
            assert_eq!(p.len(), n);
            assert!(is_simple(&p), "n={n}");
            assert!(ccw(&p));
        }
    }
    let p = two_opt(&mut rng, 150);
    assert!(is_simple(&p));
}

#[test]
fn pocket_pair_guarantees() {
    let mut rng = SplitMix64::new(108);
    for (n, gap) in [(3usize, 1e-9), (8, 0.125), (20, 0.0), (5, 1e-300)] {
        let pp = pocket_pair(&mut rng, n, gap);
        assert!(is_simple(&pp.p) && ccw(&pp.p));
        assert!(is_strictly_convex(&pp.q) && ccw(&pp.q));
        assert_eq!(pp.q.len(), n);
        assert!(pp.gap >= gap);
        let d = boundary_distance(&pp.p, &pp.q);
        assert_eq!(d.sq, r(pp.gap) * r(pp.gap));
        let want = if pp.gap == 0.0 {
            Contact::Touching
        } else {
            Contact::Disjoint
        };
        assert_eq!(contact_status_simple(&pp.p, &pp.q), want);
        // q is inside the hull of p (the outer box), i.e. in the pocket.
        let hull = [pp.p[0], pp.p[1], pp.p[2], pp.p[7]];
        for x in &pp.q {
            assert_eq!(point_in_polygon(*x, &hull), Location::Inside);
            assert_ne!(point_in_polygon(*x, &pp.p), Location::Inside);
        }
    }
}

#[test]
fn pocket_around_guarantees() {
    let mut rng = SplitMix64::new(110);
    let shapes = [
        random_convex_lattice(&mut rng, 9, 1000),
        star(&mut rng, 14, 4),
        comb(3, 2, 1),
    ];
    let mut far = 0;
    for inner in &shapes {
        for o in [0.0, 1e8, 1e12] {
            let Some(inner) = offset(inner, o, -o) else {
                continue;
            };
            for ulps in [0u64, 1, 4, 1000] {
                for lid in [PocketLid::Clear, PocketLid::Touching] {
                    let Some(pp) = pocket_around(&inner, ulps, lid) else {
                        continue;
                    };
                    far += usize::from(o > 0.0);
                    assert!(is_simple(&pp.p) && ccw(&pp.p) && pp.p.len() == 8);
                    assert_eq!(pp.q, inner);
                    // The gap is `ulps` ulps of the block's largest coordinate.
                    let big =
                        pp.p.iter()
                            .map(|v| v.x.abs().max(v.y.abs()))
                            .fold(0.0, f64::max);
                    let ulp = step_ulps(big, 1) - big;
                    assert!(pp.gap == ulps as f64 * ulp || pp.gap == ulps as f64 * ulp / 2.0);
                    let d = boundary_distance(&pp.p, &pp.q);
                    assert_eq!(d.sq, r(pp.gap) * r(pp.gap));
                    let want = if ulps == 0 {
                        Contact::Touching
                    } else {
                        Contact::Disjoint
                    };
                    assert_eq!(contact_status_simple(&pp.p, &pp.q), want);
                    // Inside the hull (the outer box), outside the block.
                    let hull = [pp.p[0], pp.p[1], pp.p[2], pp.p[7]];
                    for x in &pp.q {
                        assert_ne!(point_in_polygon(*x, &hull), Location::Outside);
                        assert_ne!(point_in_polygon(*x, &pp.p), Location::Inside);
                    }
                    // On the lid's line exactly when asked to.
                    let top = pp.q.iter().map(|v| v.y).fold(f64::NEG_INFINITY, f64::max);
                    assert_eq!(top == pp.p[3].y, lid == PocketLid::Touching);
                }
            }
        }
    }
    assert!(far >= 16, "only {far} far pockets were exact");
}

#[test]
fn convex_pair_relations() {
    // Every kind, plus the extreme gaps (exactly touching, and the largest allowed).
    let extremes = [
        Relation::NearlyTouching { ulps: 0 },
        Relation::NearlyTouching { ulps: 1 << 40 },
    ];
    let relations: Vec<Relation> = Relation::EVERY.into_iter().chain(extremes).collect();
    let mut rng = SplitMix64::new(109);
    for relation in relations {
        for (n, m) in [(3usize, 3usize), (4, 7), (12, 5)] {
            let pair = convex_pair(&mut rng, n, m, relation);
            assert_eq!((pair.p.len(), pair.q.len()), (n, m));
            assert!(ccw(&pair.p) && ccw(&pair.q));
            if relation == Relation::CollinearInput {
                assert!(is_convex(&pair.p) && is_convex(&pair.q));
                if n > 3 {
                    assert!(!is_strictly_convex(&pair.p), "{relation:?}");
                }
            } else {
                assert!(is_strictly_convex(&pair.p), "{relation:?}");
                assert!(is_strictly_convex(&pair.q), "{relation:?}");
            }
            let c = contact_status_convex(&pair.p, &pair.q);
            assert_eq!(c, pair.contact, "{relation:?} {n} {m}");
            assert_eq!(contact_status_simple(&pair.p, &pair.q), pair.contact);
            let d = convex_distance(&pair.p, &pair.q);
            match &pair.sq_dist {
                Some(s) => assert_eq!(&d.sq, s, "{relation:?}"),
                None => assert!(!d.sq.is_zero()),
            }
            match relation {
                Relation::Nested => {
                    assert!(!boundary_distance(&pair.p, &pair.q).sq.is_zero());
                    for x in &pair.q {
                        assert_eq!(point_in_polygon(*x, &pair.p), Location::Inside);
                    }
                }
                Relation::TouchingVertex => {
                    // Exactly one vertex–vertex pair at distance 0.
                    let vv: Vec<_> = d
                        .pairs
                        .iter()
                        .filter(|(f, g)| matches!((f, g), (Feature::Vertex(_), Feature::Vertex(_))))
                        .collect();
                    assert_eq!(vv.len(), 1);
                }
                Relation::VertexOnEdge => {
                    assert!(
                        d.pairs
                            .iter()
                            .any(|pair| matches!(pair, (Feature::Edge(_), Feature::Vertex(_))))
                    );
                    assert!(
                        !d.pairs
                            .iter()
                            .any(|pair| matches!(pair, (Feature::Vertex(_), Feature::Vertex(_))))
                    );
                }
                Relation::HugeOffset => {
                    assert!(pair.p.iter().all(|x| x.x > 0.99e15 && x.y < -0.99e15));
                }
                Relation::NearlyTouching { .. } => {
                    assert!(
                        pair.p
                            .iter()
                            .chain(&pair.q)
                            .all(|x| x.x > -1.0 && x.x < -0.5)
                    );
                }
                _ => {}
            }
        }
    }
}
