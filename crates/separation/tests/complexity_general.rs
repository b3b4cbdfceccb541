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

/// Envelope and σ predicate calls per vertex, measured (Robust): envelope at most 9.0 (the linear
/// scan; the divide and conquer before it measured at most 9.7 on these families, which kept it
/// linear), σ at most 12.0 (spirals), 10.1 (combs, line along the spine or a side: two visible
/// vertices) and 54.5 (combs facing tip to tip: a quarter of the vertices visible), flat from 130
/// to 131,074 vertices in all.
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

/// A closed spiky star of `2k` vertices (tips at radius 1, valleys at radius 0.3) centred at
/// `(0, 1.25)`, above the line `y = 0`; `turn` rotates it by a fraction of a spike.
fn star(k: usize, turn: f64) -> Vec<DVec2> {
    let mut v: Vec<DVec2> = (0..2 * k)
        .map(|i| {
            let t = (i as f64 + turn) * std::f64::consts::PI / k as f64;
            let r = if i % 2 == 0 { 1.0 } else { 0.3 };
            DVec2::new(r * t.cos(), 1.25 + r * t.sin())
        })
        .collect();
    v.push(v[0]);
    v
}

/// The envelope's predicate calls per vertex on spiky stars seen from a line below them (and
/// beside them), measured (Robust): 8.7–8.8 (line below) and 7.1 (line beside) from 256 to
/// 65,536 vertices, flat, for the scan of `docs/algorithms/separation.md` ("The linear scan").
/// The divide and conquer it replaced grew with `log n` here (its sub-chains' envelopes overlap in
/// height and keep every tip): 16.4 at 256 vertices, 20.4, 24.2 and 26.7 at 65,536, which fails
/// this test. The test holds the scan to a bound and to flat growth.
#[test]
fn star_envelopes_are_linear() {
    let mut per: Vec<f64> = Vec::new();
    for k in [128usize, 1024, 8192, 32768] {
        let mut worst: f64 = 0.0;
        for (turn, (a, b)) in [
            (0.0, (DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0))),
            (0.37, (DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0))),
            (0.0, (DVec2::new(-1.0, 0.0), DVec2::new(-1.0, 1.0))),
        ] {
            let p = star(k, turn);
            reset_predicate_counts();
            let e = perpendicular_envelope::<Counted<Robust>>(&p, a, b).unwrap();
            let calls = predicate_counts().total() as f64 / p.len() as f64;
            println!(
                "star({k}) turn {turn} line {a} → {b}: {calls:.1} calls/vertex, {} visible",
                e.vertices.len()
            );
            worst = worst.max(calls);
        }
        per.push(worst);
    }
    let (first, last) = (per[0], per[per.len() - 1]);
    assert!(
        per.iter().all(|&c| c <= 12.0) && last <= 1.2 * first,
        "envelope calls per vertex {per:?}"
    );
}
