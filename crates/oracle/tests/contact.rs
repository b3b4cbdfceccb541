//! Contact classification: the relative-interior definitions on points and
//! segments, convex polygons, and simple polygons; the two independent
//! methods (convex: intersection-vertex centroid; simple: arrangement pieces)
//! must agree on convex inputs with area.

use glam::DVec2;
use polydist_oracle::{
    Contact, SplitMix64, comb, contact_status_convex, contact_status_simple, random_convex, star,
    step_ulps,
};

use Contact::{Disjoint as D, Overlapping as O, Touching as T};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

fn square(x: f64, y: f64, s: f64) -> Vec<DVec2> {
    vec![v(x, y), v(x + s, y), v(x + s, y + s), v(x, y + s)]
}

fn both(p: &[DVec2], q: &[DVec2]) -> Contact {
    let a = contact_status_convex(p, q);
    let b = contact_status_convex(q, p);
    assert_eq!(a, b, "symmetry");
    a
}

#[test]
fn points() {
    let p = [v(1.0, 2.0)];
    assert_eq!(both(&p, &p), O, "equal points: relints are the points");
    assert_eq!(both(&p, &[v(1.0, 2.5)]), D);
}

#[test]
fn point_and_segment() {
    let s = [v(0., 0.), v(2., 2.)];
    assert_eq!(both(&[v(1., 1.)], &s), O, "point in the open segment");
    assert_eq!(both(&[v(0., 0.)], &s), T, "point at an endpoint");
    assert_eq!(both(&[v(2., 2.)], &s), T);
    assert_eq!(both(&[v(3., 3.)], &s), D, "on the line, outside");
    assert_eq!(both(&[v(1., step_ulps(1., 1))], &s), D);
}

#[test]
fn segments() {
    let s = [v(0., 0.), v(2., 0.)];
    assert_eq!(both(&s, &[v(1., 0.), v(3., 0.)]), O, "collinear overlap");
    assert_eq!(
        both(&s, &[v(2., 0.), v(3., 0.)]),
        T,
        "collinear, end to end"
    );
    assert_eq!(both(&s, &[v(3., 0.), v(4., 0.)]), D, "collinear apart");
    assert_eq!(both(&s, &s), O, "identical");
    assert_eq!(both(&s, &[v(2., 0.), v(0., 0.)]), O, "identical reversed");
    assert_eq!(both(&s, &[v(0.5, 0.), v(1.5, 0.)]), O, "contained");
    assert_eq!(both(&s, &[v(1., -1.), v(1., 1.)]), O, "proper crossing");
    assert_eq!(both(&s, &[v(1., 0.), v(1., 1.)]), T, "T junction");
    assert_eq!(both(&s, &[v(2., 0.), v(3., 1.)]), T, "L corner");
    assert_eq!(both(&s, &[v(0., 1.), v(2., 1.)]), D, "parallel");
    assert_eq!(
        both(&s, &[v(1., 1.), v(1., 1.)]),
        D,
        "segment vs repeated point"
    );
    assert_eq!(
        both(&s, &[v(1., 0.), v(1., 0.)]),
        O,
        "repeated point inside"
    );
    // Three collinear vertices form a segment.
    assert_eq!(both(&[v(0., 0.), v(1., 0.), v(2., 0.)], &[v(1., 0.)]), O);
}

#[test]
fn polygon_and_lower_dimensions() {
    let sq = square(0., 0., 2.);
    assert_eq!(both(&sq, &[v(1., 1.)]), O, "point inside");
    assert_eq!(both(&sq, &[v(2., 1.)]), T, "point on an edge");
    assert_eq!(both(&sq, &[v(2., 2.)]), T, "point at a vertex");
    assert_eq!(both(&sq, &[v(3., 1.)]), D);
    assert_eq!(
        both(&sq, &[v(2., 0.5), v(2., 1.5)]),
        T,
        "segment along an edge"
    );
    assert_eq!(
        both(&sq, &[v(2., -1.), v(2., 3.)]),
        T,
        "segment covering an edge"
    );
    assert_eq!(
        both(&sq, &[v(2., 1.), v(3., 1.)]),
        T,
        "segment leaving from an edge"
    );
    assert_eq!(both(&sq, &[v(1., 1.), v(3., 1.)]), O, "segment entering");
    assert_eq!(both(&sq, &[v(-1., 1.), v(3., 1.)]), O, "segment through");
    assert_eq!(both(&sq, &[v(0.5, 0.5), v(1., 1.)]), O, "segment inside");
    assert_eq!(both(&sq, &[v(-1., 1.), v(1., 3.)]), T, "through a corner");
    assert_eq!(both(&sq, &[v(-1., 1.5), v(1.5, 4.)]), D);
}

#[test]
fn squares() {
    let a = square(0., 0., 1.);
    assert_eq!(both(&a, &square(1., 0., 1.)), T, "shared edge");
    assert_eq!(both(&a, &square(1., 0.5, 1.)), T, "partially shared edge");
    assert_eq!(both(&a, &square(1., 1., 1.)), T, "shared vertex");
    assert_eq!(both(&a, &square(0.5, 0.5, 1.)), O);
    assert_eq!(both(&a, &square(0.25, 0.25, 0.5)), O, "nested");
    assert_eq!(both(&a, &a), O, "identical");
    assert_eq!(both(&a, &square(step_ulps(1., 1), 0., 1.)), D);
    assert_eq!(both(&a, &square(step_ulps(1., -1), 0., 1.)), O);
    // Orientation and collinear vertices do not matter.
    let cw: Vec<DVec2> = square(1., 0., 1.).into_iter().rev().collect();
    assert_eq!(both(&a, &cw), T);
    let collinear = vec![
        v(1., 0.),
        v(1.5, 0.),
        v(2., 0.),
        v(2., 1.),
        v(1., 1.),
        v(1., 0.5),
    ];
    assert_eq!(both(&a, &collinear), T);
    // A diamond touching the square's edge with its vertex.
    let diamond = vec![v(1., 0.5), v(1.5, 0.), v(2., 0.5), v(1.5, 1.)];
    assert_eq!(both(&a, &diamond), T);
}

#[test]
fn simple_polygons_by_hand() {
    let a = square(0., 0., 1.);
    assert_eq!(contact_status_simple(&a, &square(1., 0., 1.)), T);
    assert_eq!(contact_status_simple(&a, &square(1., 1., 1.)), T);
    assert_eq!(contact_status_simple(&a, &square(0.5, 0.5, 1.)), O);
    assert_eq!(contact_status_simple(&a, &square(0.25, 0.25, 0.5)), O);
    assert_eq!(contact_status_simple(&square(0.25, 0.25, 0.5), &a), O);
    assert_eq!(contact_status_simple(&a, &a), O);
    assert_eq!(contact_status_simple(&a, &square(3., 0., 1.)), D);
    // Combs: teeth in each other's gaps, touching along tooth sides.
    let c1 = comb(3, 4, 1);
    let flipped: Vec<DVec2> = c1.iter().map(|p| v(p.x + 1.0, 4.0 - p.y)).collect();
    assert_eq!(contact_status_simple(&c1, &flipped), T);
    let lifted: Vec<DVec2> = flipped.iter().map(|p| v(p.x, p.y + 0.5)).collect();
    assert_eq!(
        contact_status_simple(&c1, &lifted),
        T,
        "tooth sides still touch"
    );
    let lowered: Vec<DVec2> = flipped.iter().map(|p| v(p.x, p.y - 0.5)).collect();
    assert_eq!(
        contact_status_simple(&c1, &lowered),
        O,
        "tips dig into the spine"
    );
    let apart: Vec<DVec2> = c1.iter().map(|p| v(p.x + 1.25, 4.5 - p.y)).collect();
    assert_eq!(contact_status_simple(&c1, &apart), O);
    // A square inside the gap between two teeth (a pocket), not touching.
    let in_gap = square(1.25, 1.0, 0.5);
    assert_eq!(contact_status_simple(&c1, &in_gap), D);
    assert_eq!(contact_status_simple(&c1, &square(1.0, 1.0, 0.5)), T);
    assert_eq!(
        contact_status_simple(&c1, &square(1.0, 0.0, 1.0)),
        T,
        "fills the gap"
    );
    assert_eq!(contact_status_simple(&c1, &square(0.75, 0.0, 1.0)), O);
    // Clockwise input.
    let cw: Vec<DVec2> = in_gap.iter().rev().copied().collect();
    assert_eq!(contact_status_simple(&c1, &cw), D);
    // Overlap only along collinear edges of opposite interiors.
    let l_shape = vec![
        v(0., 0.),
        v(2., 0.),
        v(2., 1.),
        v(1., 1.),
        v(1., 2.),
        v(0., 2.),
    ];
    assert_eq!(contact_status_simple(&l_shape, &square(1., 1., 1.)), T);
    assert_eq!(contact_status_simple(&l_shape, &square(1., 1., 0.5)), T);
    assert_eq!(contact_status_simple(&l_shape, &square(0.5, 0.5, 1.)), O);
}

#[test]
#[should_panic(expected = "not simple")]
fn simple_rejects_bow_tie() {
    let bow = vec![v(0., 0.), v(1., 1.), v(1., 0.), v(0., 1.)];
    let _ = contact_status_simple(&bow, &square(5., 5., 1.));
}

#[test]
fn convex_and_simple_methods_agree_on_random_pairs() {
    let mut rng = SplitMix64::new(21);
    let mut seen = [0usize; 3];
    for round in 0..60 {
        let p = random_convex(&mut rng, 3 + round % 6, DVec2::ZERO, 1.0);
        let c = v(rng.unit_f64() * 3.0 - 1.5, rng.unit_f64() * 3.0 - 1.5);
        let radius = 0.5 + rng.unit_f64();
        let q = random_convex(&mut rng, 3 + round % 5, c, radius);
        let a = contact_status_convex(&p, &q);
        let b = contact_status_simple(&p, &q);
        assert_eq!(a, b);
        seen[a as usize] += 1;
    }
    // Lattice polygons touching in many ways: exact ties are common.
    for round in 0..80 {
        let p = polydist_oracle::random_convex_lattice(&mut rng, 3 + round % 4, 4);
        let d = v(rng.range_i64(-6, 6) as f64, rng.range_i64(-6, 6) as f64);
        let q: Vec<DVec2> = polydist_oracle::random_convex_lattice(&mut rng, 3 + round % 3, 4)
            .into_iter()
            .map(|x| x + d)
            .collect();
        let a = contact_status_convex(&p, &q);
        assert_eq!(a, contact_status_simple(&p, &q));
        seen[a as usize] += 1;
    }
    assert!(seen.iter().all(|&k| k >= 5), "{seen:?}");
}

#[test]
fn stars_are_classified_consistently() {
    let mut rng = SplitMix64::new(22);
    for round in 0..10 {
        let s = star(&mut rng, 6 + round, 2);
        // Scaled copy inside (the kernel contains the origin): overlapping.
        let inner: Vec<DVec2> = s.iter().map(|&p| p * 0.5).collect();
        assert_eq!(contact_status_simple(&s, &inner), O);
        // Far copy: disjoint.
        let far: Vec<DVec2> = s.iter().map(|&p| p + v(10.0, 0.0)).collect();
        assert_eq!(contact_status_simple(&s, &far), D);
        // Vertex touching: translate a copy so that its leftmost vertex lands
        // on the rightmost vertex of s; the line x = r.x separates them.
        // (Coordinates are multiples of 2^-24 below 4: translation is exact.)
        let r = s
            .iter()
            .copied()
            .fold(v(f64::MIN, 0.), |a, b| if b.x > a.x { b } else { a });
        let l = s
            .iter()
            .copied()
            .fold(v(f64::MAX, 0.), |a, b| if b.x < a.x { b } else { a });
        let moved: Vec<DVec2> = s.iter().map(|&p| p + (r - l)).collect();
        assert!(s.iter().zip(&moved).all(|(a, b)| *b - *a == r - l));
        assert_eq!(contact_status_simple(&s, &moved), T);
    }
}
