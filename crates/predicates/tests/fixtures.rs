//! The predicates against fixture files whose exact signs were computed independently (Python fractions).

use glam::DVec2;
use polydist_fixtures::{SignCase, sign_cases};
use polydist_predicates::{Dist2, Exact, Fast, Kernel, Robust};

fn p(v: &[f64], i: usize) -> DVec2 {
    DVec2::new(v[2 * i], v[2 * i + 1])
}

fn load(name: &str, arity: usize) -> Vec<SignCase> {
    let cases = sign_cases(name, arity).unwrap_or_else(|e| panic!("{e}"));
    assert!(cases.len() > 100, "{name}: too few cases");
    cases
}

/// Runs `f` on every case; returns how many disagree with the exact sign.
fn wrong(cases: &[SignCase], f: impl Fn(&[f64]) -> i8) -> usize {
    cases.iter().filter(|c| f(&c.inputs) != c.sign).count()
}

fn orient<K: Kernel>(v: &[f64]) -> i8 {
    K::orient(p(v, 0), p(v, 1), p(v, 2)).sign().to_ordering() as i8
}
fn dot<K: Kernel>(v: &[f64]) -> i8 {
    K::dot_sign(p(v, 0), p(v, 1), p(v, 2), p(v, 3)).to_ordering() as i8
}
fn nearer<K: Kernel>(v: &[f64]) -> i8 {
    K::cmp_dist(p(v, 0), p(v, 1), p(v, 2)) as i8
}
fn point_segment<K: Kernel>(v: &[f64]) -> i8 {
    K::cmp_dist2(
        Dist2::PointSegment(p(v, 0), p(v, 1), p(v, 2)),
        Dist2::PointSegment(p(v, 3), p(v, 4), p(v, 5)),
    ) as i8
}

#[test]
fn exact_kernels_match_every_fixture_and_fast_does_not() {
    let orient_cases = load("predicates/orient.txt", 6);
    let dot_cases = load("predicates/dot.txt", 8);
    let nearer_cases = load("predicates/nearer.txt", 6);
    let seg_cases = load("predicates/point_segment.txt", 12);

    for (name, cases, r, e, f) in [
        (
            "orient",
            &orient_cases,
            wrong(&orient_cases, orient::<Robust>),
            wrong(&orient_cases, orient::<Exact>),
            wrong(&orient_cases, orient::<Fast>),
        ),
        (
            "dot",
            &dot_cases,
            wrong(&dot_cases, dot::<Robust>),
            wrong(&dot_cases, dot::<Exact>),
            wrong(&dot_cases, dot::<Fast>),
        ),
        (
            "nearer",
            &nearer_cases,
            wrong(&nearer_cases, nearer::<Robust>),
            wrong(&nearer_cases, nearer::<Exact>),
            wrong(&nearer_cases, nearer::<Fast>),
        ),
        (
            "point_segment",
            &seg_cases,
            wrong(&seg_cases, point_segment::<Robust>),
            wrong(&seg_cases, point_segment::<Exact>),
            wrong(&seg_cases, point_segment::<Fast>),
        ),
    ] {
        assert_eq!(r, 0, "{name}: Robust wrong on {r} of {} cases", cases.len());
        assert_eq!(e, 0, "{name}: Exact wrong on {e} of {} cases", cases.len());
        // The fixtures are hard on purpose: plain f64 must get some of them wrong, or they test nothing.
        assert!(
            f > 0,
            "{name}: Fast was never wrong: the fixture is not hard"
        );
        println!("{name}: Fast wrong on {f} of {} cases", cases.len());
    }
}
