//! Predicate counts (`Counted<Robust>`) of σ on whole closed polygons (spirals, combs), never timing.

use glam::DVec2;
use polydist_oracle::{comb, spiral};
use polydist_predicates::{Counted, Robust, predicate_counts, reset_predicate_counts};
use polydist_separation::{perpendicular_envelope, separation_of_chains};

/// A closed polygon (last vertex repeating the first), mirrored through the line `y = y0` when
/// `mirror`, shifted by `dx`.
fn closed(poly: &[DVec2], mirror: Option<f64>, dx: f64) -> Vec<DVec2> {
    let mut v: Vec<DVec2> = poly
        .iter()
        .map(|p| match mirror {
            Some(y0) => DVec2::new(p.x + dx, 2.0 * y0 - p.y),
            None => DVec2::new(p.x + dx, p.y),
        })
        .collect();
    v.push(v[0]);
    v
}

/// `(name, P, Q, a, b)`.
type Pair = (String, Vec<DVec2>, Vec<DVec2>, DVec2, DVec2);

/// Two copies of one polygon facing across a line through an edge of the
/// first's hull.
fn cases(n: usize) -> Vec<Pair> {
    let mut out = Vec::new();
    // Spiral with 4 turns: its outer chain winds around; the line y = ymin is tangent at the bottom.
    let turns = 4;
    let per = (n / (2 * turns as usize)).max(3) as u32;
    let s = spiral(per, turns);
    let ymin = s.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
    out.push((
        format!("spiral({per},{turns})"),
        closed(&s, None, 0.0),
        closed(&s, Some(ymin - 0.5), 0.25),
        DVec2::new(0.0, ymin),
        DVec2::new(1.0, ymin),
    ));
    // Combs: teeth toward the line (line along the tips' side is not a hull edge; use the spine,
    // teeth pointing away) and teeth parallel to the line (line along the comb's left side).
    let teeth = (n / 4).max(1);
    let c = comb(teeth, 3, 1);
    out.push((
        format!("comb({teeth}) spine"),
        closed(&c, None, 0.0),
        closed(&c, Some(-1.5), 0.5),
        DVec2::new(0.0, -1.0),
        DVec2::new(1.0, -1.0),
    ));
    out.push((
        format!("comb({teeth}) tips"),
        closed(&c, None, 0.0),
        closed(&c, Some(3.5), 0.5),
        DVec2::new(0.0, 3.0),
        DVec2::new(1.0, 3.0),
    ));
    let left: Vec<DVec2> = c.iter().map(|p| DVec2::new(-p.x - 1.0, p.y)).collect();
    out.push((
        format!("comb({teeth}) side"),
        closed(&c, None, 0.0),
        closed(&left, None, -0.5),
        DVec2::new(0.0, 0.0),
        DVec2::new(0.0, 1.0),
    ));
    out
}

/// Envelope and σ predicate calls per vertex, measured (Robust): envelope at most 9.7, σ at most
/// 18.1 (spirals), 8.5 (combs, line along the spine or a side: two visible vertices) and 60.8
/// (combs facing tip to tip: a quarter of the vertices visible), flat from 130 to 131,074 vertices
/// in all. The envelope is `O(n log n)` in the worst case; these families stay linear because the
/// envelopes of sub-chains are small or meet in at most one height.
const ENVELOPE_PER_VERTEX: f64 = 16.0;
const SIGMA_PER_VERTEX: f64 = 100.0;

#[test]
fn closed_spirals_and_combs_are_linear() {
    let mut ran = 0;
    for n in [64usize, 1024, 16384, 65536] {
        for (name, p, q, a, b) in cases(n) {
            let total = (p.len() + q.len()) as f64;
            reset_predicate_counts();
            let e = perpendicular_envelope::<Counted<Robust>>(&p, a, b).unwrap();
            let env = predicate_counts().total() as f64 / p.len() as f64;
            reset_predicate_counts();
            separation_of_chains::<Counted<Robust>>(&p, &q, a, b).unwrap();
            let sigma = predicate_counts().total() as f64 / total;
            println!(
                "{name}: {total} vertices, envelope {env:.1}/vertex ({} visible), σ {sigma:.1}/vertex",
                e.vertices.len()
            );
            assert!(
                env <= ENVELOPE_PER_VERTEX && sigma <= SIGMA_PER_VERTEX,
                "{name}: envelope {env:.1}/vertex ({} visible), σ {sigma:.1}/vertex",
                e.vertices.len()
            );
            ran += 1;
        }
    }
    assert_eq!(ran, 16);
}
