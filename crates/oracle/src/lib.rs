//! # polydist-oracle — exact reference oracle and hard-input generators
//!
//! **For testing only** (`publish = false`, used as a dev-dependency). It is
//! deliberately independent of `polydist-predicates` and `polydist-polygon`:
//! it is the reference those crates are checked against.
//!
//! ## Exact oracle
//! Brute force in exact arithmetic. Every finite `f64` is a dyadic rational,
//! so coordinates are converted exactly ([`rat`]); predicates and squared
//! distances are computed with big integers on a common power-of-two grid and
//! returned as [`num_rational::BigRational`]. Costs are the obvious ones
//! (`O(nm)` for pairs of polygons), fine up to a few hundred vertices.
//!
//! * primitives: [`sign_orient`], [`sq_dist_pp`], [`sq_dist_ps`],
//!   [`sq_dist_ss`], [`segments_intersect`], [`point_in_polygon`];
//! * shapes: [`is_simple`], [`is_convex`], [`is_strictly_convex`],
//!   [`signed_area`];
//! * distances with all optimal feature pairs: [`boundary_distance`],
//!   [`convex_distance`], [`feature_sq_dist`], [`min_vertex_distance`]
//!   (see [`ExactDistance`] for the feature-pair convention);
//! * contact: [`contact_status_convex`] (relative interiors),
//!   [`contact_status_simple`];
//! * filled-convex measures: [`sq_dist_point_filled_convex`],
//!   [`per_vertex_sq_dist`], [`directed_hausdorff_filled`],
//!   [`hausdorff_filled`], [`cmmr`];
//! * large polygons (10⁴–10⁵ vertices): the same answers by a pruned exact
//!   search (box tree, exact bounds; the proof that no optimal pair is
//!   discarded is in the module doc): [`boundary_distance_pruned`],
//!   [`filled_distance_pruned`], [`min_vertex_distance_pruned`],
//!   [`directed_hausdorff_disjoint_pruned`]; and a certified enclosure of the CMMR distance
//!   ([`cmmr_enclosure`], [`CmmrEnclosure`]: exact per-vertex terms rounded down and up, summed
//!   exactly; the proof is in the module doc), where the exact sum is out of reach;
//! * rounding and error measurement: [`to_f64_nearest`], [`sqrt_nearest`],
//!   [`step_ulps`], [`ulp_distance`], [`ulps_error`], [`ulps_error_sqrt`],
//!   [`ulps_error_interval`] (against every point of an enclosure).
//!
//! **Input convention:** geometric functions panic on non-finite
//! coordinates (a NaN in a test input is a bug in the test); [`rat`] itself
//! returns `None` for them.
//!
//! ## Generators
//! Deterministic functions of a [`SplitMix64`] seed (the PRNG is part of this
//! crate so fixtures stay reproducible). Every generator documents its
//! guarantee (strict convexity, simplicity, exact vertex count, exact
//! coordinates, exact gaps), and the crate's tests check each with the
//! oracle: [`random_convex`], [`random_convex_lattice`], [`cocircular`],
//! [`cocircular_perturbed`], [`sliver`], [`parallel_facing`],
//! [`with_gap_ulps`], [`offset`] / [`offset_family`] / [`OFFSETS`], [`collinear_triples`],
//! [`near_collinear`], [`short_dyadic`], [`star`] / [`star_in_range`], [`comb`],
//! [`interleaved_combs`], [`interleaved_combs_ulps`], [`spiral`],
//! [`two_opt`], [`pocket_pair`], [`pocket_around`], [`convex_pair`] with [`Relation`]; large
//! pairs rebuilt bit for bit from a fixture's `gen` line, without library
//! trigonometry: [`large_pair`] / [`large_pair_from`] (with [`fingerprint`]),
//! [`dense_circle`], [`cocircular_arc`].
//! (They live at the crate root: `gen`, the module name one might expect,
//! is a reserved keyword in edition 2024.)
//!
//! ## Typical use in a test
//! ```
//! use polydist_oracle::{
//!     Contact, Relation, SplitMix64, contact_status_convex, convex_distance, convex_pair,
//!     ulps_error_sqrt,
//! };
//!
//! let mut rng = SplitMix64::new(1);
//! let pair = convex_pair(&mut rng, 6, 5, Relation::ParallelFacing);
//! let exact = convex_distance(&pair.p, &pair.q);
//! assert_eq!(Some(&exact.sq), pair.sq_dist.as_ref());
//! assert_eq!(contact_status_convex(&pair.p, &pair.q), Contact::Disjoint);
//! // An algorithm under test reports a distance and a feature pair; check both.
//! let (reported_distance, reported_pair) = (exact.distance_nearest(), exact.pairs[0]);
//! assert!(ulps_error_sqrt(reported_distance, &exact.sq) <= 3.5);
//! assert!(exact.is_optimal_pair(reported_pair.0, reported_pair.1));
//! ```

mod cmmr_bound;
mod contact;
mod distance;
mod exact;
mod generators;
mod hard;
mod hausdorff;
mod large;
mod pruned;
mod rounding;
mod separation;
mod shape;

pub use crate::cmmr_bound::{CmmrEnclosure, cmmr_enclosure};
pub use crate::contact::{Contact, contact_status_convex, contact_status_simple};
pub use crate::distance::{
    ExactDistance, Feature, boundary_distance, convex_distance, feature_sq_dist,
    min_vertex_distance,
};
pub use crate::exact::{
    Location, point_in_polygon, rat, segments_intersect, sign_orient, sq_dist_pp, sq_dist_ps,
    sq_dist_ss,
};
pub use crate::generators::convex::{
    FacingPair, cocircular, cocircular_perturbed, parallel_facing, random_convex,
    random_convex_lattice, sliver,
};
pub use crate::generators::pairs::{ConvexPair, Relation, convex_pair};
pub use crate::generators::precision::{
    Axis, OFFSETS, collinear_triples, near_collinear, offset, offset_family, short_dyadic,
    with_gap_ulps,
};
pub use crate::generators::rng::SplitMix64;
pub use crate::generators::simple::{
    CombPair, PocketLid, PocketPair, comb, hooked_sawtooth, hooked_teeth_facing, interleaved_combs,
    interleaved_combs_ulps, pocket_around, pocket_pair, sawteeth_facing, sawtooth, spiral, star,
    star_in_range, stars_notch_facing_tip, two_opt, zigzag_under_arc,
};
pub use crate::hard::{HardAnswers, SimpleHardAnswers};
pub use crate::hausdorff::{
    cmmr, directed_hausdorff_filled, hausdorff_filled, per_vertex_sq_dist,
    sq_dist_point_filled_convex,
};
pub use crate::large::{cocircular_arc, dense_circle, fingerprint, large_pair, large_pair_from};
pub use crate::pruned::{
    boundary_distance_pruned, directed_hausdorff_disjoint_pruned, filled_distance_pruned,
    min_vertex_distance_pruned,
};
pub use crate::rounding::{
    sqrt_nearest, step_ulps, to_f64_nearest, ulp_distance, ulps_error, ulps_error_interval,
    ulps_error_sqrt,
};
pub use crate::separation::{chain_distance, closest_visible_vertices_exact, open_segment_meets};
pub use crate::shape::{is_convex, is_simple, is_strictly_convex, signed_area};
