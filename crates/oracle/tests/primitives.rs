//! Exact primitives against hand-computed values and independent references.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use polydist_oracle::{
    Location, point_in_polygon, rat, segments_intersect, sign_orient, sq_dist_pp, sq_dist_ps,
    sq_dist_ss, step_ulps,
};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

#[test]
fn rat_is_exact() {
    assert_eq!(rat(0.5), Some(q(1, 2)));
    assert_eq!(rat(-3.0), Some(q(-3, 1)));
    assert_eq!(rat(-0.0), Some(q(0, 1)));
    assert_eq!(
        rat(0.1),
        Some(q(3_602_879_701_896_397, 36_028_797_018_963_968))
    );
    let tiny = rat(f64::from_bits(1)).unwrap();
    assert_eq!(
        tiny,
        BigRational::new(BigInt::from(1), BigInt::from(1) << 1074u32)
    );
    let big = rat(f64::MAX).unwrap();
    let expect = (BigInt::from(1) << 1024u32) - (BigInt::from(1) << 971u32);
    assert_eq!(big, BigRational::from_integer(expect));
    assert_eq!(rat(f64::NAN), None);
    assert_eq!(rat(f64::INFINITY), None);
    assert_eq!(rat(f64::NEG_INFINITY), None);
}

#[test]
fn orientation_basic_and_near_degenerate() {
    let (a, b) = (v(0.0, 0.0), v(1.0, 0.0));
    assert_eq!(sign_orient(a, b, v(0.5, 1.0)), Ordering::Greater);
    assert_eq!(sign_orient(a, b, v(0.5, -1.0)), Ordering::Less);
    assert_eq!(sign_orient(a, b, v(7.0, 0.0)), Ordering::Equal);
    assert_eq!(sign_orient(a, a, a), Ordering::Equal);
    assert_eq!(sign_orient(a, a, b), Ordering::Equal);
    // One ulp above the diagonal at huge magnitude.
    let big = 1e15;
    let c = v(0.5 * big, step_ulps(0.5 * big, 1));
    assert_eq!(sign_orient(v(0.0, 0.0), v(big, big), c), Ordering::Greater);
    let c = v(0.5 * big, step_ulps(0.5 * big, -1));
    assert_eq!(sign_orient(v(0.0, 0.0), v(big, big), c), Ordering::Less);
    // Mixed scales: subnormal against large values.
    let s = f64::from_bits(1);
    assert_eq!(
        sign_orient(v(0.0, 0.0), v(1e300, 0.0), v(-1e300, s)),
        Ordering::Greater
    );
    // Famous f64 failure: points nearly on y = x with rounding noise.
    let p = v(0.5, 0.5);
    let r = v(12.0, 12.0);
    let t = v(24.0, 24.0);
    assert_eq!(sign_orient(p, r, t), Ordering::Equal);
    let p2 = v(step_ulps(0.5, 1), 0.5);
    assert_eq!(sign_orient(p2, r, t), Ordering::Less);
}

#[test]
fn squared_distances_by_hand() {
    assert_eq!(sq_dist_pp(v(0.0, 0.0), v(3.0, 4.0)), q(25, 1));
    assert_eq!(sq_dist_pp(v(0.1, 0.0), v(0.1, 0.0)), q(0, 1));
    // Projection inside: distance to the line.
    assert_eq!(sq_dist_ps(v(0.5, 2.0), v(0.0, 0.0), v(1.0, 0.0)), q(4, 1));
    // Projection beyond an endpoint.
    assert_eq!(sq_dist_ps(v(3.0, 4.0), v(-1.0, 0.0), v(0.0, 0.0)), q(25, 1));
    assert_eq!(sq_dist_ps(v(-4.0, 3.0), v(0.0, 0.0), v(1.0, 0.0)), q(25, 1));
    // Degenerate segment.
    assert_eq!(sq_dist_ps(v(1.0, 1.0), v(0.0, 0.0), v(0.0, 0.0)), q(2, 1));
    // Oblique: point (0, 1) to segment (0,0)-(2,1): cross² / |d|² = 4/5.
    assert_eq!(sq_dist_ps(v(0.0, 1.0), v(0.0, 0.0), v(2.0, 1.0)), q(4, 5));
    // Quarter-scaled values stay exact.
    assert_eq!(
        sq_dist_ps(v(0.0, 0.25), v(0.0, 0.0), v(0.5, 0.25)),
        q(1, 20)
    );
    // Segment–segment.
    assert_eq!(
        sq_dist_ss(v(0.0, 0.0), v(1.0, 1.0), v(0.0, 1.0), v(1.0, 0.0)),
        q(0, 1)
    );
    assert_eq!(
        sq_dist_ss(v(0.0, 0.0), v(1.0, 0.0), v(2.0, 1.0), v(3.0, 5.0)),
        q(2, 1)
    );
    assert_eq!(
        sq_dist_ss(v(0.0, 0.0), v(4.0, 0.0), v(1.0, 1.0), v(3.0, 1.0)),
        q(1, 1)
    );
}

#[test]
fn segment_intersection_cases() {
    let s = |a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)| {
        segments_intersect(v(a.0, a.1), v(b.0, b.1), v(c.0, c.1), v(d.0, d.1))
    };
    assert!(s((0., 0.), (2., 2.), (0., 2.), (2., 0.)), "proper crossing");
    assert!(s((0., 0.), (2., 0.), (1., 0.), (1., 5.)), "T junction");
    assert!(s((0., 0.), (2., 0.), (2., 0.), (3., 1.)), "shared endpoint");
    assert!(
        s((0., 0.), (2., 0.), (1., 0.), (3., 0.)),
        "collinear overlap"
    );
    assert!(
        s((0., 0.), (2., 0.), (2., 0.), (3., 0.)),
        "collinear touching"
    );
    assert!(
        s((0., 0.), (4., 0.), (1., 0.), (2., 0.)),
        "collinear containment"
    );
    assert!(
        !s((0., 0.), (1., 0.), (2., 0.), (3., 0.)),
        "collinear disjoint"
    );
    assert!(!s((0., 0.), (1., 0.), (0., 1.), (1., 1.)), "parallel");
    assert!(
        !s((0., 0.), (1., 1.), (3., 0.), (2., 1.)),
        "lines cross outside"
    );
    assert!(
        s((1., 1.), (1., 1.), (0., 0.), (2., 2.)),
        "point on segment"
    );
    assert!(
        !s((1., 1.), (1., 1.), (0., 0.), (2., 2.1)),
        "point off segment"
    );
    assert!(
        !s((3., 3.), (3., 3.), (0., 0.), (2., 2.)),
        "point on line, outside"
    );
    assert!(s((1., 1.), (1., 1.), (1., 1.), (1., 1.)), "equal points");
    assert!(
        !s((1., 1.), (1., 1.), (1., 2.), (1., 2.)),
        "distinct points"
    );
    // One ulp apart.
    let e = step_ulps(0.0, 1);
    assert!(!s((0., 0.), (1., 0.), (0.5, e), (0.7, 1.)));
    assert!(s((0., 0.), (1., 0.), (0.5, 0.0), (0.7, 1.)));
}

/// Independent reference with i64 arithmetic: do the closed segments share a
/// point? Solve `a + s (b − a) = c + t (d − c)` with `s, t ∈ [0, 1]`.
fn reference_intersect(a: (i64, i64), b: (i64, i64), c: (i64, i64), d: (i64, i64)) -> bool {
    let sub = |p: (i64, i64), q: (i64, i64)| (p.0 - q.0, p.1 - q.1);
    let cr = |u: (i64, i64), w: (i64, i64)| u.0 * w.1 - u.1 * w.0;
    let dt = |u: (i64, i64), w: (i64, i64)| u.0 * w.0 + u.1 * w.1;
    let r = sub(b, a);
    let s = sub(d, c);
    let on = |p: (i64, i64), a: (i64, i64), b: (i64, i64)| -> bool {
        // p on closed segment [a, b] (b may equal a)
        let ab = sub(b, a);
        let ap = sub(p, a);
        if ab == (0, 0) {
            return p == a;
        }
        cr(ab, ap) == 0 && dt(ab, ap) >= 0 && dt(ab, ap) <= dt(ab, ab)
    };
    if r == (0, 0) {
        return on(a, c, d);
    }
    if s == (0, 0) {
        return on(c, a, b);
    }
    let den = cr(r, s);
    let qp = sub(c, a);
    if den == 0 {
        if cr(qp, r) != 0 {
            return false; // parallel, distinct lines
        }
        // Collinear: project on r and compare intervals.
        let t0 = dt(qp, r);
        let t1 = dt(sub(d, a), r);
        let (lo, hi) = (t0.min(t1), t0.max(t1));
        return hi >= 0 && lo <= dt(r, r);
    }
    // s_num / den and t_num / den in [0, 1].
    let s_num = cr(qp, s);
    let t_num = cr(qp, r);
    let inside = |num: i64| {
        if den > 0 {
            num >= 0 && num <= den
        } else {
            num <= 0 && num >= den
        }
    };
    inside(s_num) && inside(t_num)
}

#[test]
fn segment_intersection_exhaustive_small_grid() {
    let coords: Vec<(i64, i64)> = (0..3).flat_map(|x| (0..3).map(move |y| (x, y))).collect();
    let mut hits = 0;
    for &a in &coords {
        for &b in &coords {
            for &c in &coords {
                for &d in &coords {
                    let f = |p: (i64, i64)| v(p.0 as f64 * 0.375, p.1 as f64 * 0.375);
                    let got = segments_intersect(f(a), f(b), f(c), f(d));
                    let want = reference_intersect(a, b, c, d);
                    assert_eq!(got, want, "{a:?}-{b:?} vs {c:?}-{d:?}");
                    hits += usize::from(got);
                }
            }
        }
    }
    // Both outcomes occur in bulk.
    assert!(hits > 1000 && hits < 6000, "{hits}");
}

#[test]
fn point_in_polygon_cases() {
    let sq = [v(0., 0.), v(1., 0.), v(1., 1.), v(0., 1.)];
    let mut cw = sq;
    cw.reverse();
    for poly in [&sq[..], &cw[..]] {
        assert_eq!(point_in_polygon(v(0.5, 0.5), poly), Location::Inside);
        assert_eq!(point_in_polygon(v(1.0, 0.5), poly), Location::Boundary);
        assert_eq!(point_in_polygon(v(0.0, 0.0), poly), Location::Boundary);
        assert_eq!(point_in_polygon(v(1.0, 1.0), poly), Location::Boundary);
        assert_eq!(point_in_polygon(v(1.5, 0.5), poly), Location::Outside);
        assert_eq!(point_in_polygon(v(-0.5, 1.0), poly), Location::Outside);
        assert_eq!(point_in_polygon(v(2.0, 0.0), poly), Location::Outside);
        assert_eq!(point_in_polygon(v(2.0, 1.0), poly), Location::Outside);
        let just_in = step_ulps(1.0, -1);
        assert_eq!(point_in_polygon(v(just_in, 0.5), poly), Location::Inside);
        let just_out = step_ulps(1.0, 1);
        assert_eq!(point_in_polygon(v(just_out, 0.5), poly), Location::Outside);
    }
    // Concave polygon with the ray through vertices: a "W" shape.
    let w = [
        v(0., 0.),
        v(4., 0.),
        v(4., 2.),
        v(3., 1.),
        v(2., 2.),
        v(1., 1.),
        v(0., 2.),
    ];
    assert_eq!(point_in_polygon(v(0.5, 1.0), &w), Location::Inside);
    assert_eq!(point_in_polygon(v(2.0, 1.0), &w), Location::Inside);
    assert_eq!(point_in_polygon(v(2.0, 1.5), &w), Location::Inside);
    assert_eq!(point_in_polygon(v(1.0, 1.5), &w), Location::Outside);
    assert_eq!(point_in_polygon(v(-1.0, 2.0), &w), Location::Outside);
    assert_eq!(point_in_polygon(v(3.0, 1.0), &w), Location::Boundary);
    assert_eq!(point_in_polygon(v(3.5, 1.5), &w), Location::Boundary);
    assert_eq!(point_in_polygon(v(-1.0, 1.0), &w), Location::Outside);
    // Degenerate polygons.
    assert_eq!(
        point_in_polygon(v(1., 1.), &[v(1., 1.)]),
        Location::Boundary
    );
    assert_eq!(point_in_polygon(v(1., 2.), &[v(1., 1.)]), Location::Outside);
    let seg = [v(0., 0.), v(2., 2.)];
    assert_eq!(point_in_polygon(v(1., 1.), &seg), Location::Boundary);
    assert_eq!(point_in_polygon(v(2., 2.), &seg), Location::Boundary);
    assert_eq!(point_in_polygon(v(3., 3.), &seg), Location::Outside);
    assert_eq!(point_in_polygon(v(1., 0.), &seg), Location::Outside);
    assert_eq!(point_in_polygon(v(1., 0.), &[]), Location::Outside);
}

#[test]
#[should_panic(expected = "finite")]
fn non_finite_coordinates_panic() {
    let _ = sign_orient(v(0.0, 0.0), v(1.0, f64::NAN), v(0.0, 1.0));
}

#[test]
fn simplicity_and_convexity_checks() {
    use polydist_oracle::{is_convex, is_simple, is_strictly_convex, signed_area};
    let sq = [v(0., 0.), v(1., 0.), v(1., 1.), v(0., 1.)];
    let cw: Vec<DVec2> = sq.iter().rev().copied().collect();
    for p in [&sq[..], &cw[..]] {
        assert!(is_simple(p) && is_convex(p) && is_strictly_convex(p));
    }
    assert_eq!(signed_area(&sq), q(1, 1));
    assert_eq!(signed_area(&cw), q(-1, 1));
    // Straight angle: convex, simple, not strictly convex.
    let straight = [v(0., 0.), v(0.5, 0.), v(1., 0.), v(1., 1.), v(0., 1.)];
    assert!(is_simple(&straight) && is_convex(&straight));
    assert!(!is_strictly_convex(&straight));
    // Fold-back spike (a → b → back along the same line).
    let spike = [v(0., 0.), v(2., 0.), v(1., 0.), v(1., 1.)];
    assert!(!is_simple(&spike) && !is_convex(&spike));
    // Bow tie: self-crossing.
    let bow = [v(0., 0.), v(1., 1.), v(1., 0.), v(0., 1.)];
    assert!(!is_simple(&bow) && !is_convex(&bow));
    // Pentagram: every turn has the same sign but it winds twice.
    let star5: Vec<DVec2> = (0..5)
        .map(|k| {
            let t = core::f64::consts::TAU * f64::from(k * 2 % 5) / 5.0;
            v((t.cos() * 1024.0).round(), (t.sin() * 1024.0).round())
        })
        .collect();
    assert!(!is_convex(&star5) && !is_simple(&star5));
    // A vertex touching a non-adjacent edge.
    let pinch = [v(0., 0.), v(4., 0.), v(4., 2.), v(2., 0.), v(0., 2.)];
    assert!(!is_simple(&pinch));
    // Repeated vertices.
    assert!(!is_simple(&[v(0., 0.), v(1., 0.), v(1., 0.), v(0., 1.)]));
    assert!(!is_convex(&[v(0., 0.), v(1., 0.), v(1., 0.), v(0., 1.)]));
    let eight = [
        v(0., 0.),
        v(1., 1.),
        v(2., 0.),
        v(2., 2.),
        v(1., 1.),
        v(0., 2.),
    ];
    assert!(!is_simple(&eight));
    // Degenerate sizes and collinear triangles.
    assert!(!is_simple(&[v(0., 0.), v(1., 0.)]));
    assert!(!is_simple(&[v(0., 0.), v(1., 0.), v(2., 0.)]));
    assert!(!is_convex(&[v(0., 0.), v(1., 0.), v(2., 0.)]));
    // Concave but simple.
    let l_shape = [
        v(0., 0.),
        v(2., 0.),
        v(2., 1.),
        v(1., 1.),
        v(1., 2.),
        v(0., 2.),
    ];
    assert!(is_simple(&l_shape) && !is_convex(&l_shape));
    // One ulp of concavity is detected.
    let dent = [v(0., 0.), v(1., 0.), v(2., 0.), v(2., 1.), v(0., 1.)];
    let mut dented = dent;
    dented[1].y = step_ulps(0.0, 1);
    assert!(is_convex(&dent) && !is_convex(&dented) && is_simple(&dented));
    dented[1].y = step_ulps(0.0, -1);
    assert!(is_strictly_convex(&dented));
}
