//! All farthest neighbours of a convex polygon's vertices, and its diameter, in linear time: the
//! geometric application that opens Aggarwal, Klawe, Moran, Shor and Wilber, "Geometric
//! applications of a matrix-searching algorithm" (Algorithmica 2, 1987). Points are plain
//! `(f64, f64)` tuples.
//!
//! Run with `cargo run -p monotone-minima --example farthest_neighbours`.

mod farthest;

use monotone_minima::check_totally_monotone_by;

fn main() {
    // A convex polygon: vertices of an ellipse at increasing, irregular angles.
    let angles = [
        0.0_f64, 0.4, 0.9, 1.3, 2.0, 2.2, 2.9, 3.5, 4.1, 4.4, 5.0, 5.8,
    ];
    let polygon: Vec<(f64, f64)> = angles
        .iter()
        .map(|&t| (3.0 * t.cos(), 1.5 * t.sin()))
        .collect();

    // The search requires total monotonicity; check it (an O(n² log n) test, for illustration).
    let verdict = check_totally_monotone_by(&farthest::matrix(&polygon), farthest::compare);
    println!("search matrix totally monotone: {}", verdict.is_ok());

    let farthest = farthest::farthest_neighbours(&polygon);
    let distance = |i: usize, j: usize| {
        let (p, q) = (polygon[i], polygon[j]);
        f64::hypot(p.0 - q.0, p.1 - q.1)
    };
    for (i, &j) in farthest.iter().enumerate() {
        println!(
            "vertex {i:2} -> farthest vertex {j:2} at distance {:.4}",
            distance(i, j)
        );
    }
    let diameter = farthest
        .iter()
        .enumerate()
        .map(|(i, &j)| distance(i, j))
        .fold(0.0, f64::max);
    println!("diameter: {diameter:.4}");
}
