//! CVV of separable monotone chains: agreement with the brute force (same kernel) and with the exact
//! oracle, total monotonicity of every matrix, SMAWK against a scan, features in caller indices.

mod common;

use common::{Case, collinear, combs, random_case};
use monotone_minima::Matrix;
use monotone_minima::{brute_force_row_minima_by, check_totally_monotone_by, row_minima_by};
use polydist_oracle::{SplitMix64, sq_dist_pp};
use polydist_polygon::Feature;
use polydist_predicates::{Exact, Kernel, Robust};
use polydist_separation::{
    ClosestPair, CvvMatrix, MatrixEntry, closest_visible_vertices, closest_visible_vertices_brute,
    compare_entries,
};

fn vertex(f: Feature) -> usize {
    match f {
        Feature::Vertex(i) => i,
        Feature::Edge(_) => panic!("CVV reports vertices"),
    }
}

fn exact_sq(c: &Case, r: &ClosestPair) -> polydist_predicates::BigRational {
    sq_dist_pp(c.p[vertex(r.feature_p)], c.q[vertex(r.feature_q)])
}

fn check_case<K: Kernel>(c: &Case, check_matrix: bool) {
    let fast = closest_visible_vertices::<K>(&c.p, &c.q, c.a, c.b)
        .unwrap_or_else(|e| panic!("{}: {e}", c.name));
    let brute = closest_visible_vertices_brute::<K>(&c.p, &c.q, c.a, c.b).unwrap();
    let (fp, fq) = (vertex(fast.pair.feature_p), vertex(fast.pair.feature_q));
    assert_eq!(fast.pair.point_p, c.p[fp], "{}", c.name);
    assert_eq!(fast.pair.point_q, c.q[fq], "{}", c.name);
    assert_eq!(
        exact_sq(c, &fast.pair),
        exact_sq(c, &brute),
        "{}: fast {:?} brute {:?}\np={:?}\nq={:?}",
        c.name,
        fast.pair,
        brute,
        c.p,
        c.q
    );
    // The reported pair is itself visible: the brute force restricted to it agrees.
    let only = closest_visible_vertices_brute::<K>(&[c.p[fp]], &[c.q[fq]], c.a, c.b);
    assert!(only.is_ok());
    if check_matrix {
        let m = CvvMatrix::<K>::new(&c.p, &c.q, c.a, c.b).unwrap();
        check_totally_monotone_by(&m, compare_entries::<K, _>)
            .unwrap_or_else(|e| panic!("{}: M not totally monotone: {e:?}", c.name));
        assert_eq!(
            row_minima_by(&m, compare_entries::<K, _>),
            brute_force_row_minima_by(&m, compare_entries::<K, _>),
            "{}",
            c.name
        );
    }
}

#[test]
fn random_small_with_matrix_checks() {
    let mut rng = SplitMix64::new(0x5e9a);
    for n in [1usize, 2, 3, 4, 6, 9, 14, 25] {
        for _ in 0..300 {
            let c = random_case(&mut rng, n, false);
            check_case::<Robust>(&c, true);
        }
    }
}

#[test]
fn random_exact_kernel_and_far() {
    let mut rng = SplitMix64::new(77);
    for n in [3usize, 8, 20] {
        for _ in 0..60 {
            let c = random_case(&mut rng, n, true);
            check_case::<Exact>(&c, true);
            check_case::<Robust>(&c, false);
        }
    }
}

#[test]
fn combs_facing() {
    for rot in [(1, 0), (3, 4), (-5, 12)] {
        for (gp, gq) in [(1, 1), (0, 1), (1, 0), (3, 2)] {
            for interleave in [false, true] {
                check_case::<Robust>(&combs(12, gp, gq, interleave, rot), true);
            }
        }
    }
}

#[test]
fn collinear_runs() {
    for rot in [(1, 0), (0, 1), (3, 4)] {
        for n in [2, 5, 16, 33] {
            check_case::<Robust>(&collinear(n, rot), true);
        }
    }
}

/// Lemma 5's two claims (the CVV version of Lemma 7's, with the erratum R(q_j)): down a column, a
/// penalty stays a penalty (i), and below a distance there is no infinity (ii).
fn check_claims(c: &Case) -> usize {
    let m = CvvMatrix::<Robust>::new(&c.p, &c.q, c.a, c.b).unwrap();
    let (rows, cols) = (m.rows(), m.columns());
    let mut dists = 0;
    for j in 0..cols {
        let mut seen_penalty = false;
        let mut seen_dist = false;
        for i in 0..rows {
            let e = m.entry(i, j);
            match e {
                MatrixEntry::Penalty(_) => seen_penalty = true,
                MatrixEntry::Dist { .. } => {
                    assert!(!seen_penalty, "{}: claim (i) fails at ({i}, {j})", c.name);
                    seen_dist = true;
                    dists += 1;
                }
                MatrixEntry::Infinity => {
                    assert!(!seen_penalty, "{}: claim (i) fails at ({i}, {j})", c.name);
                    assert!(!seen_dist, "{}: claim (ii) fails at ({i}, {j})", c.name);
                }
            }
        }
    }
    dists
}

#[test]
fn lemma5_claims_hold_on_every_matrix() {
    let mut rng = SplitMix64::new(99);
    let mut dists = 0;
    for n in [2usize, 5, 10, 30] {
        for _ in 0..200 {
            dists += check_claims(&random_case(&mut rng, n, false));
        }
    }
    for interleave in [false, true] {
        dists += check_claims(&combs(20, 1, 1, interleave, (3, 4)));
    }
    assert!(dists > 1000, "matrices must hold candidates ({dists})");
}
