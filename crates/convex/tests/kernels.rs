//! Inexact kernels: the Fast kernel may pick wrong features on hard input; a kernel answering random
//! signs must still terminate within the loop bound, without panicking.

mod common;

use common::{Chaos, chaos_pair, seed_chaos, to_oracle};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::Fast;
use polydist_convex::{
    Separation, distance_brute, distance_to_point, distance_with, distance_yang_with,
    reset_search_stats, search_stats,
};
use polydist_oracle::{
    Contact, Relation, SplitMix64, contact_status_convex, convex_distance, convex_pair,
};

#[test]
fn chaos_kernel_terminates_within_the_bound_without_panicking() {
    seed_chaos(0x9e37_79b9_7f4a_7c15);
    let mut rng = SplitMix64::new(5);
    let mut searches = 0;
    for round in 0..3000 {
        let (n, m, pair) = chaos_pair(&mut rng, round);
        let p = ConvexPolygon::try_new(&pair.p).expect("valid");
        let q = ConvexPolygon::try_new(&pair.q).expect("valid");
        reset_search_stats();
        let _ = distance_yang_with::<Chaos>(&p, &q);
        let s = search_stats();
        assert!(s.last_iterations <= s.last_bound, "{s:?}");
        searches += u64::from(s.last_bound > 0);
        let _ = distance_with::<Chaos>(&p, &q);
        if n * m < 400 {
            let _ = distance_brute::<Chaos>(&p, &q);
        }
        let _ = distance_to_point::<Chaos>(&p, pair.q[0]).expect("finite point");
        // Points and segments.
        let s1 = ConvexPolygon::try_new(&pair.q[..2]).expect("segment");
        let s0 = ConvexPolygon::try_new(&pair.q[..1]).expect("point");
        let _ = distance_yang_with::<Chaos>(&p, &s1);
        let _ = distance_yang_with::<Chaos>(&s1, &p);
        let _ = distance_yang_with::<Chaos>(&s0, &s1);
        let _ = distance_yang_with::<Chaos>(&s1, &s1);
    }
    assert!(
        searches > 1000,
        "the O(log) search ran only {searches} times"
    );
}

#[test]
fn fast_kernel_on_hard_cases_terminates() {
    let mut rng = SplitMix64::new(17);
    let (mut wrong, mut total) = (0, 0);
    for round in 0..600 {
        let rel = [
            Relation::NearlyTouching { ulps: 1 },
            Relation::HugeOffset,
            Relation::Sliver,
            Relation::ParallelFacing,
            Relation::CollinearInput,
            Relation::TouchingVertex,
        ][round % 6];
        let (n, m) = (3 + rng.index(30), 3 + rng.index(30));
        let pair = convex_pair(&mut rng, n, m, rel);
        let p = ConvexPolygon::try_new(&pair.p).expect("valid");
        let q = ConvexPolygon::try_new(&pair.q).expect("valid");
        let got = distance_yang_with::<Fast>(&p, &q);
        total += 1;
        let exact = convex_distance(&pair.p, &pair.q);
        let right = match (contact_status_convex(&pair.p, &pair.q), got) {
            (Contact::Disjoint, Separation::Disjoint(c)) => {
                exact.is_optimal_pair(to_oracle(c.feature_p), to_oracle(c.feature_q))
            }
            (Contact::Touching, Separation::Touching { .. })
            | (Contact::Overlapping, Separation::Overlapping) => true,
            _ => false,
        };
        wrong += usize::from(!right);
    }
    println!("fast kernel: {wrong} wrong answers out of {total} hard cases");
    let _ = DVec2::ZERO;
}
