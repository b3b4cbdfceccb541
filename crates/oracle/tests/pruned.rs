//! The pruned exact search (for large polygons) against the brute forces it replaces: the same
//! exact value and the same set of optimal pairs, on random and degenerate pairs drawn by proptest.

use glam::DVec2;
use polydist_oracle::{
    Relation, SplitMix64, boundary_distance, boundary_distance_pruned, convex_distance,
    convex_pair, directed_hausdorff_disjoint_pruned, directed_hausdorff_filled,
    filled_distance_pruned, min_vertex_distance, min_vertex_distance_pruned, star,
};
use proptest::prelude::*;

const RELATIONS: [Relation; 11] = [
    Relation::Far,
    Relation::NearlyTouching { ulps: 1 },
    Relation::NearlyTouching { ulps: 4 },
    Relation::TouchingVertex,
    Relation::VertexOnEdge,
    Relation::TouchingEdge,
    Relation::ParallelFacing,
    Relation::Overlapping,
    Relation::Nested,
    Relation::HugeOffset,
    Relation::CollinearInput,
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn convex_pairs_agree(seed in any::<u64>(), rel in 0..RELATIONS.len(), n in 3usize..40, m in 3usize..40) {
        let mut rng = SplitMix64::new(seed);
        let pair = convex_pair(&mut rng, n, m, RELATIONS[rel]);
        let (p, q) = (&pair.p, &pair.q);
        prop_assume!(p.len() >= 3 && q.len() >= 3);
        prop_assert_eq!(boundary_distance_pruned(p, q), boundary_distance(p, q));
        let filled = convex_distance(p, q);
        prop_assert_eq!(filled_distance_pruned(p, q), filled.clone());
        prop_assert_eq!(min_vertex_distance_pruned(p, q), min_vertex_distance(p, q));
        let h = directed_hausdorff_disjoint_pruned(q, p);
        if filled.sq == num_rational::BigRational::from_integer(0.into()) {
            prop_assert_eq!(h, None);
        } else {
            prop_assert_eq!(h, Some(directed_hausdorff_filled(q, p)));
        }
    }

    #[test]
    fn stars_agree(seed in any::<u64>(), n in 3usize..50, dx in -2.0f64..2.0, dy in -2.0f64..2.0) {
        let mut rng = SplitMix64::new(seed);
        let a = star(&mut rng, n, n / 3);
        let b: Vec<DVec2> = star(&mut rng, n, n / 4).iter().map(|&v| v + DVec2::new(dx, dy)).collect();
        prop_assert_eq!(boundary_distance_pruned(&a, &b), boundary_distance(&a, &b));
        prop_assert_eq!(min_vertex_distance_pruned(&a, &b), min_vertex_distance(&a, &b));
    }
}
