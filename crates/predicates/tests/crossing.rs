//! Signs at crossing points (`sign_at`) against exact rationals: every named predicate, with random
//! sites (each one a crossing point or an input point) and with crossing points that land exactly on
//! integer points, where ties and zeros are common.

mod common;

use common::{q, sgn};
use glam::DVec2;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use polydist_predicates::{
    Cross, Dist2, Dist4, Dot, Exact, Fast, Kernel, Nearer, Orient, PerpVsPerp, PointsVsPerp,
    Polynomial, Ring, Robust, Sign, Site, crossing, sign_at,
};
use proptest::prelude::*;

/// Rationals as a [`Ring`]: the reference arithmetic.
#[derive(Clone)]
struct Qr(BigRational);

impl Ring for Qr {
    fn input(x: f64) -> Self {
        Qr(q(x))
    }
    fn add(&self, rhs: &Self) -> Self {
        Qr(&self.0 + &rhs.0)
    }
    fn sub(&self, rhs: &Self) -> Self {
        Qr(&self.0 - &rhs.0)
    }
    fn mul(&self, rhs: &Self) -> Self {
        Qr(&self.0 * &rhs.0)
    }
    fn neg(&self) -> Self {
        Qr(-&self.0)
    }
}

/// `X(z) = (l1 − l0) × (z − l0)`, exactly.
fn side(l0: DVec2, l1: DVec2, z: DVec2) -> BigRational {
    (q(l1.x) - q(l0.x)) * (q(z.y) - q(l0.y)) - (q(l1.y) - q(l0.y)) * (q(z.x) - q(l0.x))
}

/// The site's exact coordinates (a crossing point from the rational formula).
fn exact_site(s: Site) -> (BigRational, BigRational) {
    match s {
        Site::Input(p) => (q(p.x), q(p.y)),
        Site::Crossing { a, b, l0, l1 } => {
            let (xa, xb) = (side(l0, l1, a), side(l0, l1, b));
            let d = &xa - &xb;
            (
                (&xa * q(b.x) - &xb * q(a.x)) / &d,
                (&xa * q(b.y) - &xb * q(a.y)) / &d,
            )
        }
    }
}

/// The sign of `f` at the sites, in rationals.
fn reference<F: Polynomial<N>, const N: usize, const M: usize>(f: &F, sites: [Site; M]) -> Sign {
    let c: Vec<(BigRational, BigRational)> = sites.iter().map(|&s| exact_site(s)).collect();
    let x: [Qr; N] = core::array::from_fn(|i| {
        let (cx, cy) = &c[i / 2];
        Qr(if i % 2 == 0 { cx.clone() } else { cy.clone() })
    });
    match sgn(&f.eval(&x).0) {
        1 => Sign::Positive,
        -1 => Sign::Negative,
        _ => Sign::Zero,
    }
}

/// `sign_at` under Robust and Exact against the reference; Fast only runs (it may be wrong).
fn check<F: Polynomial<N>, const N: usize, const M: usize, const NI: usize>(
    f: &F,
    sites: [Site; M],
) -> Sign {
    let want = reference(f, sites);
    assert_eq!(
        sign_at::<Robust, F, N, M, NI>(f, sites),
        want,
        "Robust, {sites:?}"
    );
    assert_eq!(
        sign_at::<Exact, F, N, M, NI>(f, sites),
        want,
        "Exact, {sites:?}"
    );
    let _ = sign_at::<Fast, F, N, M, NI>(f, sites);
    want
}

/// The exact squared distance a [`Dist2`] of sites measures.
fn exact_dist2(d: Dist2<Site>) -> BigRational {
    let pt = |s: Site| exact_site(s);
    let sq = |x: &BigRational| x * x;
    let pp = |p: &(BigRational, BigRational), q: &(BigRational, BigRational)| {
        sq(&(&p.0 - &q.0)) + sq(&(&p.1 - &q.1))
    };
    match d {
        Dist2::PointPoint(p, q) => pp(&pt(p), &pt(q)),
        Dist2::PointSegment(p, a, b) | Dist2::PointLine(p, a, b) => {
            let (p, a, b) = (pt(p), pt(a), pt(b));
            let (ex, ey) = (&b.0 - &a.0, &b.1 - &a.1);
            let len2 = sq(&ex) + sq(&ey);
            if len2.is_zero() {
                return pp(&p, &a);
            }
            let t = ((&p.0 - &a.0) * &ex + (&p.1 - &a.1) * &ey) / &len2;
            let t = if matches!(d, Dist2::PointSegment(..)) {
                t.clamp(BigRational::zero(), BigRational::one())
            } else {
                t
            };
            let foot = (&a.0 + &t * &ex, &a.1 + &t * &ey);
            pp(&p, &foot)
        }
    }
}

/// [`crossing::cmp_dist2`] against the exact squared distances, every pair of kinds.
fn check_dist2(s: &[Site; 6]) {
    let kinds = [
        Dist2::PointPoint(s[0], s[1]),
        Dist2::PointSegment(s[0], s[1], s[2]),
        Dist2::PointLine(s[0], s[1], s[2]),
        Dist2::PointPoint(s[3], s[4]),
        Dist2::PointSegment(s[3], s[4], s[5]),
        Dist2::PointLine(s[5], s[3], s[4]),
    ];
    for &x in &kinds {
        for &y in &kinds {
            let want = exact_dist2(x).cmp(&exact_dist2(y));
            assert_eq!(
                crossing::cmp_dist2::<Robust>(x, y),
                want,
                "Robust {x:?} {y:?}"
            );
            assert_eq!(
                crossing::cmp_dist2::<Exact>(x, y),
                want,
                "Exact {x:?} {y:?}"
            );
        }
    }
}

/// The named functions of [`crossing`] (with their structural rules for points on a line) against
/// the reference: every ordered triple of `s` and the line's two points for `orient`, every pair of
/// them against the line and against each other for `cross_sign` and `dot_sign`.
fn check_named(s: &[Site; 6], l0: DVec2, l1: DVec2) {
    let mut pts: Vec<Site> = s[..4].to_vec();
    pts.extend([Site::Input(l0), Site::Input(l1)]);
    let sign = |o: polydist_predicates::Orientation| o.sign();
    for &x in &pts {
        for &y in &pts {
            for &z in &pts {
                let want = reference(&Orient, [x, y, z]);
                assert_eq!(
                    sign(crossing::orient::<Robust>(x, y, z)),
                    want,
                    "{x:?} {y:?} {z:?}"
                );
                assert_eq!(
                    sign(crossing::orient::<Exact>(x, y, z)),
                    want,
                    "{x:?} {y:?} {z:?}"
                );
            }
            for (u, w) in [
                (Site::Input(l0), Site::Input(l1)),
                (pts[0], pts[1]),
                (pts[2], pts[3]),
            ] {
                for (a, b, c, d) in [(x, y, u, w), (u, w, x, y)] {
                    let want = reference(&Cross, [a, b, c, d]);
                    assert_eq!(
                        crossing::cross_sign::<Robust>(a, b, c, d),
                        want,
                        "{a:?} {b:?} {c:?} {d:?}"
                    );
                    assert_eq!(crossing::cross_sign::<Exact>(a, b, c, d), want);
                    let want = reference(&Dot, [a, b, c, d]);
                    assert_eq!(crossing::dot_sign::<Robust>(a, b, c, d), want);
                }
            }
        }
    }
}

/// All seven named predicates at the first sites of `s`; returns how many signs were zero.
fn check_all(s: &[Site; 6]) -> usize {
    let signs = [
        check::<_, 6, 3, 24>(&Orient, [s[0], s[1], s[2]]),
        check::<_, 8, 4, 32>(&Dot, [s[0], s[1], s[2], s[3]]),
        check::<_, 8, 4, 32>(&Cross, [s[0], s[1], s[2], s[3]]),
        check::<_, 6, 3, 24>(&Nearer, [s[0], s[1], s[2]]),
        check::<_, 8, 4, 32>(&Dist4, [s[0], s[1], s[2], s[3]]),
        check::<_, 10, 5, 40>(&PointsVsPerp, [s[0], s[1], s[2], s[3], s[4]]),
        check::<_, 12, 6, 48>(&PerpVsPerp, *s),
    ];
    signs.iter().filter(|s| **s == Sign::Zero).count()
}

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1.0e3..1.0e3,
        (-64i32..64).prop_map(f64::from),
        (-1.0..1.0f64).prop_map(|x| 1.0e12 + x),
    ]
}

fn point() -> impl Strategy<Value = DVec2> {
    (coord(), coord()).prop_map(|(x, y)| DVec2::new(x, y))
}

/// A crossing point of `(a, b)` when `a`, `b` are strictly on opposite sides of the line, else `a`.
fn site(l0: DVec2, l1: DVec2, a: DVec2, b: DVec2, crossing: bool) -> Site {
    let (xa, xb) = (side(l0, l1, a), side(l0, l1, b));
    if crossing && sgn(&xa) * sgn(&xb) < 0 {
        Site::Crossing { a, b, l0, l1 }
    } else {
        Site::Input(a)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Random lines and sites: any mix of input and crossing points, the crossing points on one
    /// line or each on its own.
    #[test]
    fn random_sites_agree_with_rationals(
        l0 in point(),
        l1 in point(),
        ends in proptest::array::uniform6((
            point(),
            point(),
            any::<bool>(),
            proptest::option::of((point(), point())),
        )),
    ) {
        prop_assume!(l0 != l1);
        let sites = ends.map(|(a, b, c, own)| match own {
            Some((m0, m1)) if m0 != m1 => site(m0, m1, a, b, c),
            _ => site(l0, l1, a, b, c),
        });
        check_all(&sites);
        check_dist2(&sites);
        check_named(&sites, l0, l1);
    }

    /// Crossing points that land exactly on integer points of an integer line, among small integer
    /// input points, optionally scaled by a power of two or moved far from the origin: exact ties,
    /// zeros, and several crossing points on the same line.
    #[test]
    fn integer_crossings_agree_with_rationals(
        o in (-20i32..20, -20i32..20),
        w in (-5i32..6, -5i32..6),
        picks in proptest::array::uniform6((
            -6i32..7,
            (-5i32..6, -5i32..6),
            (1i32..4, 1i32..4),
            (-8i32..9, -8i32..9),
            any::<bool>(),
        )),
        scale in prop_oneof![Just(0i32), Just(-30), Just(40)],
        far in any::<bool>(),
    ) {
        prop_assume!(w != (0, 0));
        let shift = if far { 1.0e12 } else { 0.0 };
        let at = |x: i32, y: i32| {
            DVec2::new(f64::from(x) + shift, f64::from(y) + shift) * 2f64.powi(scale)
        };
        let (l0, l1) = (at(o.0, o.1), at(o.0 + w.0, o.1 + w.1));
        let sites = picks.map(|(t, v, (s1, s2), p, crossing)| {
            // The crossing point c = o + t·w; a and b on the line through c with direction v.
            let c = (o.0 + t * w.0, o.1 + t * w.1);
            if crossing && v.0 * w.1 - v.1 * w.0 != 0 {
                Site::Crossing {
                    a: at(c.0 + s1 * v.0, c.1 + s1 * v.1),
                    b: at(c.0 - s2 * v.0, c.1 - s2 * v.1),
                    l0,
                    l1,
                }
            } else if crossing {
                Site::Input(at(c.0, c.1))
            } else if p.0 == 8 {
                // The line's own points: the structural rules of `crossing::orient` and
                // `crossing::cross_sign` apply.
                Site::Input(l0)
            } else if p.0 == -8 {
                Site::Input(l1)
            } else {
                Site::Input(at(p.0, p.1))
            }
        });
        check_all(&sites);
        check_dist2(&sites);
        check_named(&sites, l0, l1);
        // Every crossing point is on the line: three sites of it are collinear.
        let on: Vec<Site> = sites.iter().copied().filter(|s| s.is_crossing()).collect();
        if on.len() >= 2 {
            let third = Site::Input(l0);
            prop_assert_eq!(crossing::orient::<Robust>(on[0], on[1], third).sign(), Sign::Zero);
            prop_assert_eq!(crossing::orient::<Exact>(on[0], third, on[1]).sign(), Sign::Zero);
        }
    }
}

/// The integer family is degenerate enough to matter: across fixed seeds, a good share of its signs
/// are exact zeros, which a sign read from rounded coordinates would get wrong.
#[test]
fn integer_crossings_produce_zeros() {
    let (l0, l1) = (DVec2::new(0.0, 0.0), DVec2::new(3.0, 1.0));
    // c = (3, 1) from (4, 3)–(1, −3) (direction (1, 2)); c = (−3, −1) from (−3, 1)–(−3, −2).
    let crossing_of = |a, b| Site::Crossing { a, b, l0, l1 };
    let c1 = crossing_of(DVec2::new(4.0, 3.0), DVec2::new(1.0, -3.0));
    let c2 = crossing_of(DVec2::new(-3.0, 1.0), DVec2::new(-3.0, -2.0));
    let sites = [
        c1,
        c2,
        Site::Input(DVec2::new(0.0, 0.0)),
        Site::Input(DVec2::new(6.0, 2.0)),
        Site::Input(DVec2::new(3.0, 1.0)),
        Site::Input(DVec2::new(-3.0, -1.0)),
    ];
    // Zeros: Orient(c1, c2, (0, 0)) (all on the line), Cross(c1, c2, (0, 0), (6, 2)) (parallel),
    // Dist4(c1, c2, (0, 0), (6, 2)) (both 40), PerpVsPerp (both points on their lines).
    let zeros = check_all(&sites);
    assert_eq!(zeros, 4);
    // c1 is exactly the input point (3, 1): every predicate agrees with it.
    assert_eq!(
        crossing::cmp_dist4::<Robust>(c1, sites[4], c2, sites[5]),
        core::cmp::Ordering::Equal
    );
    assert_eq!(
        crossing::orient::<Robust>(c1, sites[3], Site::Input(DVec2::new(7.0, 2.0))),
        Robust::orient(
            DVec2::new(3.0, 1.0),
            DVec2::new(6.0, 2.0),
            DVec2::new(7.0, 2.0)
        )
    );
}

/// The rounded position of a crossing point lies within a few ulps of the exact one.
#[test]
fn approx_is_close() {
    let (l0, l1) = (DVec2::new(0.1, 0.2), DVec2::new(7.3, -1.9));
    let s = Site::Crossing {
        a: DVec2::new(1.0, 5.0),
        b: DVec2::new(2.5, -3.0),
        l0,
        l1,
    };
    let c = s.approx();
    let (ex, ey) = exact_site(s);
    let err = (q(c.x) - ex).abs() + (q(c.y) - ey).abs();
    assert!(err < q(1e-14), "{c:?}");
    assert_eq!(Site::Input(DVec2::X).approx(), DVec2::X);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// A crossing point lies exactly on its segment: orientations with the segment's ends are exact
    /// zeros, which no rounded coordinate reproduces (`t` is rarely a float), so only a filter whose
    /// error bound covers the construction declines them. Against a third point, the reference.
    #[test]
    fn a_crossing_point_is_on_its_segment(
        l0 in point(),
        l1 in point(),
        a in point(),
        b in point(),
        z in point(),
    ) {
        let (xa, xb) = (side(l0, l1, a), side(l0, l1, b));
        prop_assume!(l0 != l1 && sgn(&xa) * sgn(&xb) < 0);
        let c = Site::Crossing { a, b, l0, l1 };
        let (ia, ib) = (Site::Input(a), Site::Input(b));
        for (x, y, w) in [(c, ia, ib), (ia, c, ib), (ib, ia, c)] {
            prop_assert_eq!(crossing::orient::<Robust>(x, y, w).sign(), Sign::Zero);
            prop_assert_eq!(crossing::orient::<Exact>(x, y, w).sign(), Sign::Zero);
        }
        prop_assert_eq!(crossing::cross_sign::<Robust>(ia, c, ia, ib), Sign::Zero);
        prop_assert_eq!(crossing::cross_sign::<Robust>(c, ib, ib, ia), Sign::Zero);
        let iz = Site::Input(z);
        prop_assert_eq!(
            crossing::orient::<Robust>(c, ia, iz).sign(),
            reference(&Orient, [c, ia, iz])
        );
    }
}

/// A counting kernel sees every `sign_at` call exactly once, whichever stage decides it: the
/// coordinate filter (Robust, a clear sign), the exact stage (Robust, an exact zero), the rounded
/// coordinates (Fast), or plain input points.
#[test]
fn every_sign_at_call_is_counted_once() {
    use polydist_predicates::{Counted, predicate_counts, reset_predicate_counts};
    // The crossing of (−1, −1)–(1, 1) with the x axis is the origin.
    let c = Site::Crossing {
        a: DVec2::new(-1.0, -1.0),
        b: DVec2::new(1.0, 1.0),
        l0: DVec2::ZERO,
        l1: DVec2::X,
    };
    let (y, z) = (
        Site::Input(DVec2::new(0.0, 2.0)),
        Site::Input(DVec2::new(3.0, 1.0)),
    );
    let on = Site::Input(DVec2::new(0.0, 7.0));
    let cases: [([Site; 3], Sign); 3] = [
        ([c, y, z], Sign::Negative),
        ([c, y, on], Sign::Zero),
        ([Site::Input(DVec2::ZERO), y, z], Sign::Negative),
    ];
    for (sites, want) in cases {
        reset_predicate_counts();
        let got = sign_at::<Counted<Robust>, Orient, 6, 3, 24>(&Orient, sites);
        assert_eq!((got, predicate_counts().total()), (want, 1), "{sites:?}");
        reset_predicate_counts();
        let _ = sign_at::<Counted<Fast>, Orient, 6, 3, 24>(&Orient, sites);
        assert_eq!(predicate_counts().total(), 1, "Fast, {sites:?}");
        reset_predicate_counts();
        let got = sign_at::<Counted<Exact>, Orient, 6, 3, 24>(&Orient, sites);
        assert_eq!(
            (got, predicate_counts().total()),
            (want, 1),
            "Exact, {sites:?}"
        );
    }
}
