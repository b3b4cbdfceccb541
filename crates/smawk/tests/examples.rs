//! The examples' algorithms, compiled from the example sources themselves, against brute force.

#[path = "../examples/line_breaking/breaking.rs"]
mod breaking;

#[path = "../examples/farthest_neighbours/farthest.rs"]
mod farthest;

use core::f64::consts::PI;

use monotone_minima::check_totally_monotone_by;
use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::subsequence;
use proptest::test_runner::FileFailurePersistence;

fn config() -> ProptestConfig {
    ProptestConfig {
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/examples.txt",
        ))),
        ..ProptestConfig::default()
    }
}

/// Quadratic dynamic program over feasible lines only, plain integers, topmost predecessor on
/// ties: the cost and the first word of each line.
fn break_lines_quadratic(widths: &[u64], width: u64) -> Option<(u64, Vec<usize>)> {
    let n = widths.len();
    let mut best: Vec<Option<(u64, usize)>> = vec![None; n + 1];
    best[0] = Some((0, 0));
    for j in 1..=n {
        for i in 0..j {
            let Some((cost, _)) = best[i] else { continue };
            let length: u64 = widths[i..j].iter().sum::<u64>() + (j - i - 1) as u64;
            if length > width {
                continue;
            }
            let total = cost + (width - length).pow(2);
            if best[j].is_none_or(|(b, _)| total < b) {
                best[j] = Some((total, i));
            }
        }
    }
    let (total, _) = best[n]?;
    let mut starts = Vec::new();
    let mut j = n;
    while j > 0 {
        j = best[j]?.1;
        starts.push(j);
    }
    starts.reverse();
    Some((total, starts))
}

/// The farthest other vertex of each vertex, scanning counterclockwise from it, first one on ties.
fn farthest_brute_force(polygon: &[(f64, f64)]) -> Vec<usize> {
    let n = polygon.len();
    if n < 2 {
        return Vec::new();
    }
    (0..n)
        .map(|i| {
            let distance =
                |j: usize| f64::hypot(polygon[i].0 - polygon[j].0, polygon[i].1 - polygon[j].1);
            let mut best = (i + 1) % n;
            for k in 2..n {
                let j = (i + k) % n;
                if distance(j) > distance(best) {
                    best = j;
                }
            }
            best
        })
        .collect()
}

/// Vertices of an ellipse (random center, axes, rotation) at distinct grid angles, in
/// counterclockwise order: a strictly convex polygon whose quadrilaterals are far from
/// degenerate, so the Monge inequalities hold in floating point too.
fn convex_polygon() -> impl Strategy<Value = Vec<(f64, f64)>> {
    let grid: Vec<u32> = (0..720).collect();
    prop_oneof![1 => 0..=3_usize, 4 => 4..=60_usize]
        .prop_flat_map(move |size| {
            (
                subsequence(grid.clone(), size),
                0.5_f64..10.0,
                0.5_f64..10.0,
                0.0_f64..PI,
                -5.0_f64..5.0,
                -5.0_f64..5.0,
            )
        })
        .prop_map(|(steps, a, b, rotation, cx, cy)| {
            let (sin, cos) = rotation.sin_cos();
            steps
                .into_iter()
                .map(|k| {
                    let t = f64::from(k) * 2.0 * PI / 720.0;
                    let (x, y) = (a * t.cos(), b * t.sin());
                    (cx + cos * x - sin * y, cy + sin * x + cos * y)
                })
                .collect()
        })
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn line_breaking_is_optimal(
        widths in prop_oneof![vec(1_u64..10, 0..5), vec(1_u64..10, 0..120)],
        width in 1_u64..40,
    ) {
        prop_assert_eq!(breaking::break_lines(&widths, width), break_lines_quadratic(&widths, width));
    }

    #[test]
    fn farthest_neighbours_match_brute_force(polygon in convex_polygon()) {
        prop_assert_eq!(
            check_totally_monotone_by(&farthest::matrix(&polygon), farthest::compare),
            Ok(()),
            "the search matrix must be totally monotone: {:?}",
            polygon
        );
        prop_assert_eq!(farthest::farthest_neighbours(&polygon), farthest_brute_force(&polygon));
    }
}

#[test]
fn line_breaking_edge_cases() {
    assert_eq!(breaking::break_lines(&[], 10), Some((0, vec![])));
    assert_eq!(breaking::break_lines(&[11], 10), None);
    assert_eq!(breaking::break_lines(&[10], 10), Some((0, vec![0])));
    // "aaa bb cc" in width 6: "aaa" + "bb cc" (9 + 1) beats "aaa bb" + "cc" (0 + 16).
    assert_eq!(breaking::break_lines(&[3, 2, 2], 6), Some((10, vec![0, 1])));
}

#[test]
fn farthest_neighbours_of_a_square_and_degenerate_polygons() {
    let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    assert_eq!(farthest::farthest_neighbours(&square), [2, 3, 0, 1]);
    assert_eq!(
        farthest::farthest_neighbours(&[(0.0, 0.0), (3.0, 4.0)]),
        [1, 0]
    );
    assert!(farthest::farthest_neighbours(&[(1.0, 1.0)]).is_empty());
    assert!(farthest::farthest_neighbours(&[]).is_empty());
}
