//! Distances, optimal feature pairs, Hausdorff/CMMR: hand cases, the
//! all-pairs convention checked exhaustively, and agreement with plain `f64`
//! computations on well-conditioned random inputs.

use std::collections::BTreeSet;

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
use polydist_oracle::{
    Feature, SplitMix64, boundary_distance, cmmr, convex_distance, directed_hausdorff_filled,
    feature_sq_dist, hausdorff_filled, min_vertex_distance, per_vertex_sq_dist, random_convex,
    sq_dist_point_filled_convex, sq_dist_ps, star, to_f64_nearest,
};

use Feature::{Edge as E, Vertex as V};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fn unit_square() -> Vec<DVec2> {
    vec![v(0., 0.), v(1., 0.), v(1., 1.), v(0., 1.)]
}

fn shifted(p: &[DVec2], d: DVec2) -> Vec<DVec2> {
    p.iter().map(|&x| x + d).collect()
}

fn edge_count(n: usize) -> usize {
    match n {
        0 | 1 => 0,
        2 => 1,
        _ => n,
    }
}

fn all_features(n: usize) -> Vec<Feature> {
    (0..n).map(V).chain((0..edge_count(n)).map(E)).collect()
}

/// The all-pairs convention, checked exhaustively: a pair is listed iff its
/// exact feature distance equals the optimum, and nothing is below it.
fn check_convention(p: &[DVec2], qq: &[DVec2]) {
    let d = boundary_distance(p, qq);
    let listed: BTreeSet<_> = d.pairs.iter().copied().collect();
    assert_eq!(listed.len(), d.pairs.len(), "no duplicates");
    for f in all_features(p.len()) {
        for g in all_features(qq.len()) {
            let s = feature_sq_dist(p, qq, f, g).unwrap();
            assert!(s >= d.sq, "{f:?} {g:?} below the optimum");
            assert_eq!(s == d.sq, d.is_optimal_pair(f, g), "{f:?} {g:?}");
        }
    }
    assert!(!d.pairs.is_empty());
}

#[test]
fn squares_side_by_side() {
    let p = unit_square();
    let qq = shifted(&p, v(3.0, 0.5));
    let d = boundary_distance(&p, &qq);
    assert_eq!(d.sq, q(4, 1));
    assert_eq!(d.distance_nearest(), 2.0);
    let want: BTreeSet<_> = [
        (V(2), E(3)),
        (E(1), V(0)),
        (E(1), E(0)),
        (E(1), E(3)),
        (E(2), E(3)),
    ]
    .into_iter()
    .collect();
    assert_eq!(d.pairs.iter().copied().collect::<BTreeSet<_>>(), want);
    assert!(!d.is_optimal_pair(V(1), E(3)));
    assert!(!d.is_optimal_pair(V(9), E(3)), "out of range");
    check_convention(&p, &qq);
    assert_eq!(convex_distance(&p, &qq), d);
    // Diagonal placement: a vertex–vertex optimum, 2² + 2² = 8.
    let qq = shifted(&p, v(3.0, 3.0));
    let d = boundary_distance(&p, &qq);
    assert_eq!(d.sq, q(8, 1));
    let want: BTreeSet<_> = [
        (V(2), V(0)),
        (V(2), E(0)),
        (V(2), E(3)),
        (E(1), V(0)),
        (E(2), V(0)),
        (E(1), E(0)),
        (E(1), E(3)),
        (E(2), E(0)),
        (E(2), E(3)),
    ]
    .into_iter()
    .collect();
    assert_eq!(d.pairs.iter().copied().collect::<BTreeSet<_>>(), want);
    check_convention(&p, &qq);
}

#[test]
fn degenerate_polygons() {
    let p = unit_square();
    // A point on an edge.
    let d = boundary_distance(&p, &[v(1.0, 0.5)]);
    assert!(d.sq.is_zero());
    assert_eq!(d.pairs, vec![(E(1), V(0))]);
    // A point inside: boundary distance 0.25², filled distance 0.
    let d = boundary_distance(&p, &[v(0.75, 0.5)]);
    assert_eq!(d.sq, q(1, 16));
    assert_eq!(d.pairs, vec![(E(1), V(0))]);
    let c = convex_distance(&p, &[v(0.75, 0.5)]);
    assert!(c.sq.is_zero() && c.pairs.is_empty());
    // A crossing segment: only the crossed edges realise 0.
    let seg = [v(0.5, 0.5), v(2.0, 0.25)];
    let d = boundary_distance(&p, &seg);
    assert!(d.sq.is_zero());
    assert_eq!(d.pairs, vec![(E(1), E(0))]);
    check_convention(&p, &seg);
    // Segment against segment, point against point.
    let d = boundary_distance(&[v(0., 0.), v(4., 0.)], &[v(1., 2.), v(3., 1.)]);
    assert_eq!(d.sq, q(1, 1));
    assert_eq!(d.pairs, vec![(E(0), V(1)), (E(0), E(0))]);
    let d = boundary_distance(&[v(0.125, 0.25)], &[v(0.5, 0.75)]);
    assert_eq!(d.pairs, vec![(V(0), V(0))]);
    assert_eq!(d.sq, q(25, 64));
    assert_eq!(d.distance_nearest(), 0.625);
    // Non-dyadic inputs are taken exactly as the doubles they are.
    let d = boundary_distance(&[v(0.1, 0.2)], &[v(0.4, 0.6)]);
    assert_ne!(d.sq, q(1, 4));
    assert_eq!(to_f64_nearest(&d.sq), 0.24999999999999997);
    check_convention(&[v(0., 0.), v(4., 0.)], &[v(1., 2.), v(3., 1.)]);
    check_convention(&[v(1., 1.)], &p);
}

#[test]
fn nested_and_overlapping_filled() {
    let big = vec![v(-2., -2.), v(2., -2.), v(2., 2.), v(-2., 2.)];
    let small = unit_square();
    let b = boundary_distance(&big, &small);
    assert_eq!(b.sq, q(1, 1));
    let c = convex_distance(&big, &small);
    assert!(c.sq.is_zero());
    assert!(c.pairs.is_empty());
    // Squares sharing an edge: filled distance 0 with the boundary pairs.
    let right = shifted(&small, v(1.0, 0.0));
    let c = convex_distance(&small, &right);
    assert!(c.sq.is_zero());
    assert!(c.is_optimal_pair(E(1), E(3)));
    assert!(c.is_optimal_pair(V(1), V(0)));
    // Clockwise input and collinear extra vertices are accepted.
    let cw: Vec<DVec2> = big.iter().rev().copied().collect();
    assert!(convex_distance(&cw, &small).sq.is_zero());
    let with_collinear = vec![v(0., 0.), v(0.5, 0.), v(1., 0.), v(1., 1.), v(0., 1.)];
    let d = convex_distance(&with_collinear, &shifted(&small, v(0.25, -3.0)));
    assert_eq!(d.sq, q(4, 1));
    assert!(d.is_optimal_pair(V(1), E(2)));
}

#[test]
#[should_panic(expected = "convex position")]
fn convex_distance_rejects_non_convex() {
    let l_shape = vec![
        v(0., 0.),
        v(2., 0.),
        v(2., 1.),
        v(1., 1.),
        v(1., 2.),
        v(0., 2.),
    ];
    let _ = convex_distance(&l_shape, &[v(5., 5.)]);
}

#[test]
fn vertex_distance_ties() {
    let p = unit_square();
    let qq = shifted(&p, v(2.0, 0.0));
    let (sq, pairs) = min_vertex_distance(&p, &qq);
    assert_eq!(sq, q(1, 1));
    assert_eq!(pairs, vec![(1, 0), (2, 3)]);
}

#[test]
fn hausdorff_and_cmmr_by_hand() {
    let small = unit_square();
    let big = vec![v(-1., -1.), v(2., -1.), v(2., 2.), v(-1., 2.)];
    // Every corner of `big` is at distance² 2 from the unit square.
    let (h, arg) = directed_hausdorff_filled(&big, &small);
    assert_eq!(h, q(2, 1));
    assert_eq!(arg, vec![0, 1, 2, 3]);
    let (h, arg) = directed_hausdorff_filled(&small, &big);
    assert!(h.is_zero());
    assert_eq!(arg, vec![0, 1, 2, 3]);
    assert_eq!(hausdorff_filled(&small, &big), q(2, 1));
    assert_eq!(cmmr(&small, &big), q(8, 1));
    assert_eq!(per_vertex_sq_dist(&big, &small), vec![q(2, 1); 4]);
    assert_eq!(sq_dist_point_filled_convex(v(0.5, 3.0), &small), q(4, 1));
    assert_eq!(sq_dist_point_filled_convex(v(0.5, 0.5), &small), q(0, 1));
    assert_eq!(sq_dist_point_filled_convex(v(1.0, 0.5), &small), q(0, 1));
    // Degenerate filled "polygons": segment and point.
    let seg = [v(0., 0.), v(2., 0.)];
    assert_eq!(sq_dist_point_filled_convex(v(1., 1.), &seg), q(1, 1));
    assert_eq!(
        sq_dist_point_filled_convex(v(3., 0.), &[v(0., 4.)]),
        q(25, 1)
    );
    // Unique argmax.
    let tri = [v(0., 0.), v(10., 0.), v(0., 1.)];
    let (h, arg) = directed_hausdorff_filled(&tri, &small);
    assert_eq!(h, q(81, 1));
    assert_eq!(arg, vec![1]);
}

// ---------- agreement with f64 on well-conditioned inputs ----------

fn f64_sq_ps(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    (a + d * t - p).length_squared()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()) + 1e-300
}

fn random_points(rng: &mut SplitMix64, n: usize, c: DVec2) -> Vec<DVec2> {
    (0..n)
        .map(|_| c + v(rng.unit_f64() * 2.0 - 1.0, rng.unit_f64() * 2.0 - 1.0))
        .collect()
}

#[test]
fn point_segment_against_f64() {
    let mut rng = SplitMix64::new(10);
    for _ in 0..500 {
        let pts = random_points(&mut rng, 3, DVec2::ZERO);
        let exact = to_f64_nearest(&sq_dist_ps(pts[0], pts[1], pts[2]));
        let approx = f64_sq_ps(pts[0], pts[1], pts[2]);
        assert!(close(exact, approx), "{exact} {approx}");
    }
}

#[test]
fn boundary_distance_against_f64() {
    let mut rng = SplitMix64::new(11);
    for round in 0..40 {
        let n = 3 + round % 9;
        let m = 1 + round % 7;
        // Separated boxes: boundaries cannot meet.
        let p = random_points(&mut rng, n, v(0.0, 0.0));
        let c = v(3.0 + rng.unit_f64(), rng.unit_f64());
        let qq = random_points(&mut rng, m, c);
        let d = boundary_distance(&p, &qq);
        let mut best = f64::INFINITY;
        for &a in &p {
            for j in 0..edge_count(m) {
                best = best.min(f64_sq_ps(a, qq[j], qq[(j + 1) % m]));
            }
            for &b in &qq {
                best = best.min((a - b).length_squared());
            }
        }
        for i in 0..edge_count(n) {
            for &b in &qq {
                best = best.min(f64_sq_ps(b, p[i], p[(i + 1) % n]));
            }
        }
        assert!(close(to_f64_nearest(&d.sq), best));
        for &(f, g) in &d.pairs {
            assert_eq!(feature_sq_dist(&p, &qq, f, g).unwrap(), d.sq);
        }
    }
}

#[test]
fn convention_on_random_and_star_inputs() {
    let mut rng = SplitMix64::new(12);
    for round in 0..12 {
        let p = random_convex(&mut rng, 3 + round % 5, DVec2::ZERO, 1.0);
        let qq = random_convex(&mut rng, 3 + round % 4, v(2.5, 0.5), 1.0);
        check_convention(&p, &qq);
        let s = star(&mut rng, 5 + round % 4, 2);
        let t = star(&mut rng, 4 + round % 3, 1);
        let t = shifted(&t, v(0.5, 0.25));
        check_convention(&s, &t);
    }
}

#[test]
fn hausdorff_against_f64() {
    let mut rng = SplitMix64::new(13);
    for _ in 0..20 {
        let p = random_convex(&mut rng, 6, v(0.3, 0.2), 1.0);
        let qq = random_convex(&mut rng, 7, DVec2::ZERO, 1.0);
        // f64: distance to filled convex ccw q (strict inside test).
        let f = |x: DVec2| -> f64 {
            let m = qq.len();
            let inside = (0..m).all(|j| (qq[(j + 1) % m] - qq[j]).perp_dot(x - qq[j]) >= 0.0);
            if inside {
                0.0
            } else {
                (0..m)
                    .map(|j| f64_sq_ps(x, qq[j], qq[(j + 1) % m]))
                    .fold(f64::INFINITY, f64::min)
            }
        };
        let per = per_vertex_sq_dist(&p, &qq);
        for (i, &x) in p.iter().enumerate() {
            assert!(close(to_f64_nearest(&per[i]), f(x)));
        }
        let (h, arg) = directed_hausdorff_filled(&p, &qq);
        let hf = p.iter().map(|&x| f(x)).fold(0.0, f64::max);
        assert!(close(to_f64_nearest(&h), hf));
        for i in arg {
            assert_eq!(per[i], h);
        }
        let total: f64 = p.iter().map(|&x| f(x)).sum();
        let back: BigRational = per_vertex_sq_dist(&qq, &p).into_iter().sum();
        let c = cmmr(&p, &qq);
        assert_eq!(c, per.iter().sum::<BigRational>() + back);
        assert!(to_f64_nearest(&c) >= total * (1.0 - 1e-9));
    }
}
