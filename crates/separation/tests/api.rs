//! Misuse is a typed error, never a panic or a silent answer; caller indices survive reversal.

mod common;

use glam::DVec2;
use polydist_polygon::Feature;
use polydist_predicates::{Fast, Robust};
use polydist_separation::{Chain, SeparationError, closest_visible_vertices};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

const A: DVec2 = DVec2::ZERO;
const B: DVec2 = DVec2::Y;

fn run(p: &[DVec2], q: &[DVec2], a: DVec2, b: DVec2) -> Result<(usize, usize), SeparationError> {
    closest_visible_vertices::<Robust>(p, q, a, b).map(|c| {
        match (c.pair.feature_p, c.pair.feature_q) {
            (Feature::Vertex(i), Feature::Vertex(j)) => (i, j),
            _ => panic!("vertices expected"),
        }
    })
}

#[test]
fn typed_errors() {
    let p = [v(1.0, 0.0), v(2.0, 1.0)];
    let q = [v(-1.0, 0.0), v(-2.0, 1.0)];
    assert_eq!(
        run(&[], &q, A, B),
        Err(SeparationError::EmptyChain { chain: Chain::P })
    );
    assert_eq!(
        run(&p, &[], A, B),
        Err(SeparationError::EmptyChain { chain: Chain::Q })
    );
    assert_eq!(
        run(&[v(1.0, f64::NAN)], &q, A, B),
        Err(SeparationError::InvalidCoordinate {
            chain: Chain::P,
            index: 0
        })
    );
    assert_eq!(
        run(&p, &[v(-1.0, 0.0), v(f64::INFINITY, 0.0)], A, B),
        Err(SeparationError::InvalidCoordinate {
            chain: Chain::Q,
            index: 1
        })
    );
    assert_eq!(
        run(&p, &[v(-1.0, 1e300)], A, B),
        Err(SeparationError::InvalidCoordinate {
            chain: Chain::Q,
            index: 0
        })
    );
    assert_eq!(
        run(&p, &q, v(0.0, f64::NAN), B),
        Err(SeparationError::InvalidLine)
    );
    assert_eq!(run(&p, &q, A, A), Err(SeparationError::DegenerateLine));
    // A vertex of P one ulp across the line.
    assert_eq!(
        run(&[v(1.0, 0.0), v(-f64::from_bits(1), 1.0)], &q, A, B),
        Err(SeparationError::NotSeparated {
            chain: Chain::P,
            index: 1
        })
    );
    assert_eq!(
        run(
            &[v(0.0, 0.0), v(1.0, 1.0)],
            &[v(0.0, 3.0), v(-1.0, 4.0)],
            A,
            B
        ),
        Err(SeparationError::BothChainsTouchLine)
    );
    assert_eq!(
        run(&[v(0.0, 0.0)], &[v(0.0, 3.0)], A, B),
        Err(SeparationError::BothChainsTouchLine)
    );
    assert_eq!(
        run(&[v(1.0, 0.0), v(2.0, 2.0), v(3.0, 1.0)], &q, A, B),
        Err(SeparationError::NotMonotone {
            chain: Chain::P,
            index: 2
        })
    );
    // Doubling back within a run perpendicular to the line.
    assert_eq!(
        run(&p, &[v(-1.0, 0.0), v(-3.0, 0.0), v(-2.0, 0.0)], A, B),
        Err(SeparationError::NotMonotone {
            chain: Chain::Q,
            index: 2
        })
    );
}

#[test]
fn line_orientation_and_chain_direction_do_not_matter() {
    let p = [v(3.0, 0.0), v(1.0, 1.0), v(4.0, 2.0), v(2.0, 3.0)];
    let q = [v(-2.0, 0.5), v(-1.5, 2.5), v(-4.0, 3.5)];
    let expect = run(&p, &q, A, B).unwrap();
    assert_eq!(run(&p, &q, B, A).unwrap(), expect);
    assert_eq!(run(&q, &p, A, B).unwrap(), (expect.1, expect.0));
    let mut pr = p;
    pr.reverse();
    assert_eq!(
        run(&pr, &q, A, B).unwrap(),
        (p.len() - 1 - expect.0, expect.1)
    );
}

#[test]
fn repeated_vertices_and_perpendicular_runs_report_caller_indices() {
    // P: a run perpendicular to the line at height 1 (depths 5, 3, 2): only (2, 1) is visible.
    let p = [
        v(4.0, 0.0),
        v(4.0, 0.0),
        v(5.0, 1.0),
        v(3.0, 1.0),
        v(2.0, 1.0),
        v(6.0, 2.0),
    ];
    let q = [v(-1.0, 1.0), v(-1.0, 1.0)];
    assert_eq!(run(&p, &q, A, B).unwrap(), (4, 0));
    // Fast also accepts it.
    assert!(closest_visible_vertices::<Fast>(&p, &q, A, B).is_ok());
}

#[test]
fn single_vertices() {
    assert_eq!(run(&[v(1.0, 5.0)], &[v(-1.0, -5.0)], A, B).unwrap(), (0, 0));
    // One chain on the line is allowed.
    assert_eq!(
        run(&[v(0.0, 5.0), v(0.0, 6.0)], &[v(-1.0, 5.5)], A, B).unwrap(),
        (0, 0)
    );
}

mod never_panics {
    use glam::DVec2;
    use polydist_predicates::{Fast, Robust};
    use polydist_separation::{
        ChainMethod, closest_visible_vertices, closest_visible_vertices_brute, separation_brute,
        separation_of_chains, separation_of_chains_with,
    };
    use proptest::prelude::*;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            (-8i32..8i32).prop_map(f64::from),
            any::<f64>(),
            Just(f64::NAN),
            Just(1e300),
            Just(-0.0),
        ]
    }

    fn chain() -> impl Strategy<Value = Vec<DVec2>> {
        prop::collection::vec((coord(), coord()).prop_map(|(x, y)| DVec2::new(x, y)), 0..8)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(600))]
        /// Any input, valid or not, gives an answer or a typed error under every kernel.
        #[test]
        fn no_input_panics(p in chain(), q in chain(), a in (coord(), coord()), b in (coord(), coord())) {
            let (a, b) = (DVec2::new(a.0, a.1), DVec2::new(b.0, b.1));
            let _ = separation_of_chains::<Robust>(&p, &q, a, b);
            let _ = separation_of_chains::<Fast>(&p, &q, a, b);
            let _ = separation_of_chains_with::<Robust>(&p, &q, a, b, ChainMethod::Auto);
            let _ = separation_of_chains_with::<Fast>(&p, &q, a, b, ChainMethod::Auto);
            let _ = closest_visible_vertices::<Robust>(&p, &q, a, b);
            let _ = closest_visible_vertices::<Fast>(&p, &q, a, b);
            let _ = closest_visible_vertices_brute::<Robust>(&p, &q, a, b);
            let _ = separation_brute::<Robust>(&p, &q);
        }

        /// Separated lattice chains that may be non-monotone or not simple: an answer or an error,
        /// never a panic; for simple chains, an answer equal to the brute force.
        #[test]
        fn lattice_inputs(p in prop::collection::vec((1i32..6, -6i32..6), 1..7),
                          q in prop::collection::vec((-6i32..0, -6i32..6), 1..7)) {
            let p: Vec<DVec2> = p.into_iter().map(|(x, y)| DVec2::new(x.into(), y.into())).collect();
            let q: Vec<DVec2> = q.into_iter().map(|(x, y)| DVec2::new(x.into(), y.into())).collect();
            let simple = crate::common::simple_chain(&p) && crate::common::simple_chain(&q);
            if let (true, Ok(s)) = (simple, separation_of_chains::<Robust>(&p, &q, DVec2::ZERO, DVec2::Y)) {
                let b = separation_brute::<Robust>(&p, &q).unwrap();
                prop_assert_eq!(s.pair.squared_distance, b.squared_distance);
                let swept = separation_of_chains_with::<Robust>(
                    &p, &q, DVec2::ZERO, DVec2::Y, ChainMethod::Auto,
                ).unwrap();
                prop_assert_eq!(swept.pair.squared_distance, b.squared_distance);
            }
        }
    }
}

/// σ on general chains: closed chains, the closing edge's index, `NotSimple` for the violations the
/// envelope meets, `NotMonotone` only from `closest_visible_vertices`.
#[test]
fn general_and_closed_chains() {
    use polydist_separation::separation_of_chains;
    let q = [v(-1.0, 1.0)];
    // A closed square right of x = 0; the nearest feature is its closing edge (x = 1).
    let square = [
        v(1.0, 0.0),
        v(3.0, 0.0),
        v(3.0, 2.0),
        v(1.0, 2.0),
        v(1.0, 0.0),
    ];
    let s = separation_of_chains::<Robust>(&square, &q, A, B).unwrap();
    assert_eq!(s.pair.feature_p, Feature::Edge(3));
    assert_eq!(s.pair.squared_distance, 4.0);
    // Repeats around the closing vertex keep the polygon's indices for vertices; the closing edge is
    // the caller's segment into the repeat.
    let square2 = [
        v(1.0, 0.0),
        v(3.0, 0.0),
        v(3.0, 2.0),
        v(1.0, 2.0),
        v(1.0, 2.0),
        v(1.0, 0.0),
        v(1.0, 0.0),
    ];
    let s = separation_of_chains::<Robust>(&square2, &q, A, B).unwrap();
    assert_eq!(s.pair.feature_p, Feature::Edge(4));
    // The nearest point is the repeated first vertex: reported as vertex 0.
    let s = separation_of_chains::<Robust>(&square, &[v(-1.0, -1.0)], A, B).unwrap();
    assert_eq!(s.pair.feature_p, Feature::Vertex(0));
    // A non-monotone open chain (a hook): accepted by σ, rejected by CVV.
    let hook = [v(3.0, 1.0), v(4.0, -1.0), v(1.0, 0.0), v(1.0, 2.0)];
    let s = separation_of_chains::<Robust>(&hook, &q, A, B).unwrap();
    assert_eq!(s.pair.feature_p, Feature::Edge(2));
    assert!(matches!(
        run(&hook, &q, A, B),
        Err(SeparationError::NotMonotone {
            chain: Chain::P,
            ..
        })
    ));
    // Not simple: a closed chain of two vertices; a vertex on another edge, reached from in front
    // of it; overlapping edges. (A vertex on an edge reached from behind it, as in (1, 0), (1, 4),
    // (3, 2), (1, 2), is not seen by the envelope's scan: the contract asks for simple chains.)
    for (bad, index) in [
        (vec![v(1.0, 0.0), v(2.0, 1.0), v(1.0, 0.0)], 2),
        (vec![v(1.0, 0.0), v(1.0, 4.0), v(0.5, 3.0), v(1.0, 2.0)], 3),
        (vec![v(1.0, 0.0), v(1.0, 4.0), v(1.0, 1.0)], 2),
    ] {
        let got = separation_of_chains::<Robust>(&bad, &q, A, B);
        assert!(
            matches!(got, Err(SeparationError::NotSimple { chain: Chain::P, index: i }) if i == index),
            "{bad:?}: {got:?}"
        );
    }
}
