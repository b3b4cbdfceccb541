//! Complexity of the minimum vertex distance by counting predicate calls (never timing): linear for
//! disjoint polygons up to 2¹⁷ vertices each, `O(N log N)` for overlapping ones.

mod common;

use common::disjoint_pair;
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{
    Counted, PredicateCounts, Robust, predicate_counts, reset_predicate_counts,
};
use polydist_convex::{
    min_vertex_distance_with, reset_vertex_distance_case_counts, vertex_distance_case_counts,
};
use polydist_oracle::{Relation, SplitMix64, convex_pair, random_convex};

/// Predicates per vertex allowed for disjoint polygons (measured: at most 11 at n = 16, about 5 from
/// n = 2¹⁰ to 2¹⁷).
const PER_VERTEX: f64 = 12.0;
/// Predicates per `N log₂ N` allowed for meeting polygons (measured: at most 7.7, about 4 at 2¹⁵).
const PER_N_LOG_N: f64 = 10.0;

/// The predicates `K = Counted<Robust>` evaluates for one call.
fn count(p: &ConvexPolygon, q: &ConvexPolygon) -> u64 {
    counts(p, q).total()
}

/// The predicates of each kind `K = Counted<Robust>` evaluates for one call.
fn counts(p: &ConvexPolygon, q: &ConvexPolygon) -> PredicateCounts {
    reset_predicate_counts();
    let _ = min_vertex_distance_with::<Counted<Robust>>(p, q);
    predicate_counts()
}

#[test]
fn disjoint_is_linear() {
    let mut rng = SplitMix64::new(31);
    for k in 4..=17 {
        let n = 1usize << k;
        let mut worst: f64 = 0.0;
        let trials = if k > 13 { 4 } else { 6 };
        reset_vertex_distance_case_counts();
        for t in 0..trials {
            let m = if t % 2 == 0 { n } else { 3 + rng.index(n) };
            // Large random polygons are mostly nearest at two vertices (Lemma 1's exit); a translated
            // copy faces itself along parallel edges, which forces the whole TENSTEP.
            let (p, q) = if t % 2 == 1 && k > 10 {
                let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
                let a = rng.unit_f64() * std::f64::consts::TAU;
                let q = p
                    .iter()
                    .map(|&x| x + DVec2::new(a.cos(), a.sin()) * 3.0)
                    .collect();
                (p, q)
            } else {
                disjoint_pair(&mut rng, n, m)
            };
            let (pp, qq) = (
                ConvexPolygon::try_new(&p).expect("valid"),
                ConvexPolygon::try_new(&q).expect("valid"),
            );
            let all = counts(&pp, &qq);
            let c = all.total();
            let ratio = c as f64 / (pp.len() + qq.len()) as f64;
            // FINDMIN is the only user of the nearer-of-two comparison: Lemmas 9–10 bound each call by
            // 3(β − 1) + 2α, and steps 6–8 sum to at most 8n + 5m + 4 (chains share end vertices).
            let (mm, nn) = (pp.len() as u64, qq.len() as u64);
            assert!(all.cmp_dist <= 8 * nn + 5 * mm + 4, "FINDMIN: {all:?}");
            worst = worst.max(ratio);
            assert!(
                ratio <= PER_VERTEX,
                "n = {n}, m = {m}: {c} predicates, {ratio:.2} per vertex"
            );
        }
        let c = vertex_distance_case_counts();
        // Some inputs of every size run the whole TENSTEP (not only Lemma 1's vertex–vertex exit).
        assert!(
            c.bridge_edge_on_p + c.bridge_edge_on_q > 0,
            "n = {n}: {c:?}"
        );
        println!(
            "n = 2^{k}: at most {worst:.2} predicates per vertex ({} of {trials} through steps 6–9)",
            c.bridge_edge_on_p + c.bridge_edge_on_q
        );
    }
}

#[test]
fn overlapping_is_n_log_n() {
    let mut rng = SplitMix64::new(32);
    for k in 4..=15 {
        let n = 1usize << k;
        let mut pairs = Vec::new();
        if k <= 10 {
            for rel in [
                Relation::Overlapping,
                Relation::Nested,
                Relation::TouchingEdge,
            ] {
                let pair = convex_pair(&mut rng, n, n, rel);
                pairs.push((pair.p, pair.q));
            }
        }
        // Crossing boundaries (two discs of radius 1, 0.6 apart) and nested (radius 0.2 inside).
        let p = random_convex(&mut rng, n, DVec2::ZERO, 1.0);
        pairs.push((
            p.clone(),
            random_convex(&mut rng, n, DVec2::new(0.6, 0.1), 1.0),
        ));
        pairs.push((p, random_convex(&mut rng, n / 2, DVec2::new(0.1, 0.0), 0.2)));
        let mut worst: f64 = 0.0;
        reset_vertex_distance_case_counts();
        for (p, q) in pairs {
            let (pp, qq) = (
                ConvexPolygon::try_new(&p).expect("valid"),
                ConvexPolygon::try_new(&q).expect("valid"),
            );
            let big_n = (pp.len() + qq.len()) as f64;
            let c = count(&pp, &qq);
            let ratio = c as f64 / (big_n * big_n.log2());
            worst = worst.max(ratio);
            assert!(
                ratio <= PER_N_LOG_N,
                "n = {n}: {c} predicates, {ratio:.2} per N log N"
            );
        }
        let c = vertex_distance_case_counts();
        println!(
            "n = 2^{k}: at most {worst:.2} predicates per N log₂ N ({} split nodes, {} separated parts \
             without a certified bridge)",
            c.split_nodes, c.uncertified_separated_nodes
        );
    }
}
