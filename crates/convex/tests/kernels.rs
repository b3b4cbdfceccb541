//! Inexact kernels: the Fast kernel may pick wrong features on hard input; a kernel answering random
//! signs must still terminate within the loop bound, without panicking.

use core::cell::Cell;

use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Fast, Kernel, Polynomial, Sign};
use polydist_convex::{
    Separation, distance_brute, distance_to_point, distance_with, distance_yang_with,
    reset_search_stats, search_stats,
};
use polydist_oracle::{
    Contact, Relation, SplitMix64, contact_status_convex, convex_distance, convex_pair,
};

std::thread_local! {
    static CHAOS: Cell<u64> = const { Cell::new(0x9e37_79b9_7f4a_7c15) };
}

/// A kernel whose every sign is pseudo-random (SplitMix64 on a thread-local state).
#[derive(Clone, Copy, Debug, Default)]
struct Chaos;

impl Kernel for Chaos {
    const NAME: &'static str = "chaos";
    const EXACT_DECISIONS: bool = false;
    fn sign<const N: usize, P: Polynomial<N> + ?Sized>(_: &P, _: &[f64; N]) -> Sign {
        CHAOS.with(|c| {
            let mut z = c.get().wrapping_add(0x9e37_79b9_7f4a_7c15);
            c.set(z);
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            match (z ^ (z >> 31)) % 3 {
                0 => Sign::Negative,
                1 => Sign::Zero,
                _ => Sign::Positive,
            }
        })
    }
}

#[test]
fn chaos_kernel_terminates_within_the_bound_without_panicking() {
    let mut rng = SplitMix64::new(5);
    let mut searches = 0;
    for round in 0..3000 {
        let n = 3 + rng.index(if round % 10 == 0 { 2000 } else { 40 });
        let m = 3 + rng.index(40);
        let rel = [
            Relation::Far,
            Relation::Overlapping,
            Relation::TouchingEdge,
            Relation::ParallelFacing,
        ][round % 4];
        let pair = convex_pair(&mut rng, n, m, rel);
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

fn to_oracle(f: polydist_convex::polygon::Feature) -> polydist_oracle::Feature {
    match f {
        polydist_convex::polygon::Feature::Vertex(i) => polydist_oracle::Feature::Vertex(i),
        polydist_convex::polygon::Feature::Edge(i) => polydist_oracle::Feature::Edge(i),
    }
}
