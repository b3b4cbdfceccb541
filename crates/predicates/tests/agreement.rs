//! Every named predicate under Robust, Exact and Counted agrees with rational evaluation, on random,
//! near-degenerate, tiny, huge and wide-dynamic-range inputs.

mod common;

use common::*;
use glam::DVec2;
use polydist_predicates::{Counted, Dist2, Exact, Kernel, Robust};
use proptest::prelude::*;

fn check_orient<K: Kernel>(a: DVec2, b: DVec2, c: DVec2) {
    let want = orient(a, b, c);
    let got = K::orient(a, b, c).sign().to_ordering() as i8;
    assert_eq!(got, want, "{} orient({a:?}, {b:?}, {c:?})", K::NAME);
}

fn check_all<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) {
    check_orient::<K>(a, b, c);
    assert_eq!(
        K::dot_sign(a, b, c, d).to_ordering() as i8,
        dot(a, b, c, d),
        "{} dot",
        K::NAME
    );
    assert_eq!(
        K::cross_sign(a, b, c, d).to_ordering() as i8,
        cross(a, b, c, d),
        "{} cross",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist(a, b, c),
        d2(a, b).cmp(&d2(a, c)),
        "{} cmp_dist",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist4(a, b, c, d),
        d2(a, b).cmp(&d2(c, d)),
        "{} cmp_dist4",
        K::NAME
    );
    // Every mix of point–point and point–segment squared distances.
    let pp = Dist2::PointPoint(a, b);
    let ps = Dist2::PointSegment(a, c, d);
    let ps2 = Dist2::PointSegment(b, c, d);
    let ps3 = Dist2::PointSegment(c, a, b);
    assert_eq!(
        K::cmp_dist2(pp, ps),
        d2(a, b).cmp(&d2_seg(a, c, d)),
        "{} pp/ps",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist2(ps, pp),
        d2_seg(a, c, d).cmp(&d2(a, b)),
        "{} ps/pp",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist2(ps, ps2),
        d2_seg(a, c, d).cmp(&d2_seg(b, c, d)),
        "{} ps/ps",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist2(ps2, ps3),
        d2_seg(b, c, d).cmp(&d2_seg(c, a, b)),
        "{} ps/ps'",
        K::NAME
    );
    // Line distances, against points, segments and lines.
    let pl = Dist2::PointLine(a, c, d);
    let pl2 = Dist2::PointLine(c, a, b);
    assert_eq!(
        K::cmp_dist2(pl, pp),
        d2_line(a, c, d).cmp(&d2(a, b)),
        "{} pl/pp",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist2(ps2, pl),
        d2_seg(b, c, d).cmp(&d2_line(a, c, d)),
        "{} ps/pl",
        K::NAME
    );
    assert_eq!(
        K::cmp_dist2(pl, pl2),
        d2_line(a, c, d).cmp(&d2_line(c, a, b)),
        "{} pl/pl",
        K::NAME
    );
}

/// The squared distance from `p` to the line through `a` and `b` (the point `a` when `a == b`).
fn d2_line(p: DVec2, a: DVec2, b: DVec2) -> num_rational::BigRational {
    use common::q;
    let (ex, ey) = (q(b.x) - q(a.x), q(b.y) - q(a.y));
    let (wx, wy) = (q(p.x) - q(a.x), q(p.y) - q(a.y));
    let l2 = &ex * &ex + &ey * &ey;
    if a == b {
        return d2(p, a);
    }
    let cr = &ex * &wy - &ey * &wx;
    &cr * &cr / l2
}

fn check_every_kernel(a: DVec2, b: DVec2, c: DVec2, d: DVec2) {
    check_all::<Robust>(a, b, c, d);
    check_all::<Exact>(a, b, c, d);
    check_all::<Counted<Robust>>(a, b, c, d);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 600, ..ProptestConfig::default() })]

    #[test]
    fn random_points_of_every_magnitude(a in any_point(), b in any_point(), c in any_point(), d in any_point()) {
        check_every_kernel(a, b, c, d);
    }

    #[test]
    fn points_in_one_frame((s, o) in frame(), seed in any::<u64>()) {
        let mut x = seed;
        let mut next = || { x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407); ((x >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0 };
        let mut pt = || DVec2::new(o + next() * s, o + next() * s);
        let (a, b, c, d) = (pt(), pt(), pt(), pt());
        check_every_kernel(a, b, c, d);
    }

    #[test]
    fn near_collinear_triples((a, b, c) in near_collinear(), k in -3i32..=3) {
        // d nudged off the perpendicular through c: near-zero dot products and near-ties of distances.
        let e = b - a;
        let d = DVec2::new(nudge(c.x - e.y, k), c.y + e.x);
        check_every_kernel(a, b, c, d);
        check_every_kernel(c, a, b, d);
        // Points nearly equidistant: the mirror image of b across a, nudged.
        let m = DVec2::new(nudge(2.0 * a.x - b.x, k), 2.0 * a.y - b.y);
        check_every_kernel(a, b, m, c);
    }

    #[test]
    fn axis_aligned_triples(a in any_point(), b in any_point(), c in any_point()) {
        // Three points on one horizontal or vertical line (an exact zero that Robust decides
        // without expansions), in every order, and two on such a line with the third anywhere.
        let h = |p: DVec2| DVec2::new(p.x, a.y);
        let v = |p: DVec2| DVec2::new(a.x, p.y);
        check_every_kernel(a, h(b), h(c), b);
        check_every_kernel(h(c), a, h(b), c);
        check_every_kernel(v(b), v(c), a, b);
        check_every_kernel(a, h(b), c, b);
        check_every_kernel(v(b), a, c, c);
    }

    #[test]
    fn tiny_lattice_points(xy in proptest::array::uniform8(-4i32..=4)) {
        // Points of a small lattice scaled by 2^-540: every product is below the static filters'
        // absolute slack, so every decision takes the exact stage (and its shortcut for points on one
        // horizontal or vertical line, which a third of these triples are).
        let s = 2f64.powi(-540);
        let p = |i: usize| DVec2::new(f64::from(xy[2 * i]), f64::from(xy[2 * i + 1])) * s;
        check_every_kernel(p(0), p(1), p(2), p(3));
    }

    #[test]
    fn exactly_degenerate(a in any_point(), b in any_point()) {
        // Repeated points and exact ties.
        check_every_kernel(a, a, a, a);
        check_every_kernel(a, b, a, b);
        check_every_kernel(a, b, b, a);
        check_every_kernel(b, a, a, b);
    }
}

#[test]
fn wide_dynamic_range_takes_the_integer_path_and_stays_exact() {
    // Inputs spanning 2^-1074 .. 2^1000 within one query: expansions would underflow, integers do not.
    let tiny = f64::from_bits(1);
    let huge = 2f64.powi(1000);
    let pts = [
        DVec2::new(tiny, 0.0),
        DVec2::new(huge, huge),
        DVec2::new(-huge, tiny),
        DVec2::new(3.0 * tiny, -tiny),
        DVec2::new(0.0, huge * 0.75),
    ];
    for &a in &pts {
        for &b in &pts {
            for &c in &pts {
                for &d in &pts {
                    check_every_kernel(a, b, c, d);
                }
            }
        }
    }
}
