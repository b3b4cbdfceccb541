//! `SimplePolygon::first_boundary_contact` (both boundaries in one Shamos–Hoey sweep) against its
//! brute-force twin and the exact oracle, on generated polygons moved onto, against and away from
//! each other (shared vertices, shared edges, vertices on edges, crossings, gaps of one ulp).

use glam::DVec2;
use polydist_oracle::{self as oracle, SplitMix64};
use polydist_polygon::SimplePolygon;
use proptest::prelude::*;

fn shape(rng: &mut SplitMix64) -> Vec<DVec2> {
    let n = 3 + rng.index(30);
    match rng.below(4) {
        0 => oracle::star(rng, n, 2),
        1 => oracle::two_opt(rng, n),
        2 => oracle::spiral(3 + rng.below(6) as u32, 1 + rng.below(2) as u32),
        _ => oracle::comb(1 + rng.index(6), 1 + rng.below(4) as u32, 1),
    }
}

/// Whether the two closed boundaries share a point, exactly (the oracle's boundary distance is 0).
fn boundaries_meet(p: &[DVec2], q: &[DVec2]) -> bool {
    num_traits::Zero::is_zero(&oracle::boundary_distance(p, q).sq)
}

fn check(p: &[DVec2], q: &[DVec2]) -> Result<(), TestCaseError> {
    let (Ok(sp), Ok(sq)) = (SimplePolygon::try_new(p), SimplePolygon::try_new(q)) else {
        return Ok(());
    };
    let meet = boundaries_meet(sp.vertices(), sq.vertices());
    let sweep = sp.first_boundary_contact(&sq);
    prop_assert_eq!(sweep.is_some(), meet);
    prop_assert_eq!(sp.first_boundary_contact_brute(&sq).is_some(), meet);
    prop_assert_eq!(sq.first_boundary_contact(&sp).is_some(), meet);
    if let Some((e, f)) = sweep {
        // The reported edges really meet.
        let (v, w) = (sp.vertices(), sq.vertices());
        let (n, m) = (v.len(), w.len());
        prop_assert!(boundaries_meet(
            &[v[e], v[(e + 1) % n]],
            &[w[f], w[(f + 1) % m]]
        ));
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// `q` moved so that one of its vertices lands on a vertex or an edge point of `p`, or near it.
    #[test]
    fn sweep_equals_brute_and_oracle(seed in any::<u64>(), k in 0u32..6) {
        let mut rng = SplitMix64::new(seed);
        let p = shape(&mut rng);
        let q = shape(&mut rng);
        let (i, j) = (rng.index(p.len()), rng.index(q.len()));
        let target = match k {
            0 => p[i],
            1 => (p[i] + p[(i + 1) % p.len()]) * 0.5,
            2 => DVec2::new(p[i].x.next_up(), p[i].y),
            3 => p[i] + DVec2::new(0.3, -0.2),
            4 => p[i] + DVec2::new(3.0, 3.0),
            _ => p[i] * 1e12,
        };
        let shift = target - q[j];
        let moved: Vec<DVec2> = q.iter().map(|&v| v + shift).collect();
        check(&p, &moved)?;
    }
}

#[test]
fn shared_edge_and_nested() {
    let sq = |x: f64, y: f64, s: f64| {
        vec![
            DVec2::new(x, y),
            DVec2::new(x + s, y),
            DVec2::new(x + s, y + s),
            DVec2::new(x, y + s),
        ]
    };
    for (b, meet) in [
        (sq(1.0, 0.0, 1.0), true),
        (sq(1.0, 0.25, 0.5), true),
        (sq(0.25, 0.25, 0.5), false),
        (sq(-1.0, -1.0, 3.0), false),
        (sq(1.0f64.next_up(), 0.0, 1.0), false),
    ] {
        let (p, q) = (
            SimplePolygon::try_new(&sq(0.0, 0.0, 1.0)).unwrap(),
            SimplePolygon::try_new(&b).unwrap(),
        );
        assert_eq!(p.first_boundary_contact(&q).is_some(), meet, "{b:?}");
        assert_eq!(p.first_boundary_contact_brute(&q).is_some(), meet, "{b:?}");
    }
}
