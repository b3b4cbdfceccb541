//! Complexity by counting predicate calls, never by timing: convex point location is logarithmic,
//! both hulls are linear after sorting, the caller-feature map is logarithmic in the chain length.

use glam::DVec2;
use polydist_oracle::{self as oracle, SplitMix64};
use polydist_polygon::predicates::{Counted, Robust, predicate_counts, reset_predicate_counts};
use polydist_polygon::{ConvexPolygon, SimplePolygon, convex_hull_with};

type K = Counted<Robust>;

/// `⌈log₂ n⌉`.
fn log2_ceil(n: usize) -> u64 {
    u64::from(usize::BITS - (n - 1).leading_zeros())
}

#[test]
fn convex_locate_is_logarithmic() {
    let mut rng = SplitMix64::new(31);
    for n in [3, 4, 16, 100, 1000, 10_000] {
        let poly = ConvexPolygon::try_new(&oracle::random_convex(&mut rng, n, DVec2::ZERO, 1.0))
            .expect("convex");
        let mut worst = 0;
        for _ in 0..500 {
            let q = DVec2::new(rng.unit_f64(), rng.unit_f64()) * 2.4 - 1.2;
            reset_predicate_counts();
            let _ = poly.locate_with::<K>(q);
            worst = worst.max(predicate_counts().total());
        }
        for &v in poly.vertices() {
            reset_predicate_counts();
            let _ = poly.locate_with::<K>(v);
            worst = worst.max(predicate_counts().total());
        }
        assert!(worst <= log2_ceil(n) + 3, "n = {n}: {worst} predicates");
    }
}

#[test]
fn hulls_are_linear() {
    let mut rng = SplitMix64::new(37);
    let polygons = [
        oracle::star(&mut rng, 4000, 100),
        oracle::two_opt(&mut rng, 200),
        oracle::comb(1000, 50, 2),
        oracle::spiral(50, 40),
        oracle::random_convex(&mut rng, 3000, DVec2::ZERO, 1.0),
    ];
    for ring in polygons {
        let poly = SimplePolygon::try_new(&ring).expect("simple");
        let n = poly.len() as u64;
        reset_predicate_counts();
        let _ = poly.convex_hull_with::<K>();
        let melkman = predicate_counts();
        assert_eq!(melkman.total(), melkman.orient);
        assert!(
            melkman.orient <= 6 * n,
            "Melkman: {} orientations for n = {n}",
            melkman.orient
        );
        reset_predicate_counts();
        let _ = convex_hull_with::<K>(&ring);
        let andrew = predicate_counts();
        assert!(
            andrew.orient <= 4 * ring.len() as u64,
            "Andrew: {} orientations for n = {n}",
            andrew.orient
        );
    }
}

#[test]
fn caller_feature_is_logarithmic_in_the_chain() {
    // A triangle whose bottom edge carries 2^k − 1 collinear caller vertices.
    for k in [1u32, 4, 8, 12] {
        let m = 1usize << k;
        let mut ring: Vec<DVec2> = (0..=m).map(|i| DVec2::new(i as f64, 0.0)).collect();
        ring.push(DVec2::new(0.0, m as f64));
        let poly = ConvexPolygon::try_new(&ring).expect("triangle");
        assert_eq!(poly.len(), 3);
        let mut worst = 0;
        for i in 0..200 {
            let q = DVec2::new(
                (i as f64 * 0.37 * m as f64 / 73.0) % (m as f64 + 2.0) - 1.0,
                -1.0,
            );
            reset_predicate_counts();
            let _ = poly.caller_feature_on_edge::<K>(0, q);
            worst = worst.max(predicate_counts().total());
        }
        assert!(
            worst <= u64::from(k) + 3,
            "chain of {m}: {worst} predicates"
        );
    }
}
