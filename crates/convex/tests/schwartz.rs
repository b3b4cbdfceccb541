//! Schwartz's `O(log² N)` path (`distance_schwartz_with`): agreement with the exact oracle, with the
//! brute force and with the Yang path on random convex pairs in every relation, points and segments and
//! exact ties; predicate counts `≤ C·log₂n·log₂m + K` on disjoint pairs; termination under random signs.

mod common;

use common::{
    Chaos, RELATIONS, Worst, chaos_pair, check_answer, counted, disjoint_pair, exact_swapped,
    facing_pair, huge_offset_pair, lattice_point, merge, seed_chaos, sliver_pair,
};
use glam::DVec2;
use polydist_convex::polygon::ConvexPolygon;
use polydist_convex::polygon::predicates::{Counted, Exact, Kernel, Robust};
use polydist_convex::{
    Separation, distance_brute, distance_schwartz, distance_schwartz_with, distance_yang_with,
};
use polydist_oracle::{
    Contact, SplitMix64, cocircular, contact_status_convex, convex_distance, convex_pair,
    random_convex_lattice, ulp_distance,
};

/// Predicates per `log₂n·log₂m` on disjoint pairs (the measured worst is printed by the tests).
const C: f64 = 14.0;
/// Constant term.
const K: f64 = 150.0;

/// The count bound for sizes `n`, `m` (a point or a segment counts as `2`).
fn bound(n: usize, m: usize) -> f64 {
    let l = |x: usize| (x.max(2) as f64).log2();
    C * l(n) * l(m) + K
}

/// Agreement statistics.
#[derive(Debug, Default)]
struct Stats {
    pairs: u64,
    disjoint: u64,
    same_pair_as_yang: u64,
    same_pair_as_brute: u64,
    max_ulps_vs_yang: u64,
    max_ulps_vs_brute: u64,
    worst: Worst,
    max_count_ratio: f64,
}

impl Stats {
    fn merge(&mut self, w: Worst) {
        merge(&mut self.worst, w);
    }
}

/// Both answers have the same outcome; for disjoint ones the distances agree within the documented
/// bounds (each within 2.5 ulps of the exact value: at most 5 ulps apart). Returns (same pair, ulps).
fn compare(a: &Separation, b: &Separation, what: &str) -> (bool, u64) {
    match (a, b) {
        (Separation::Disjoint(x), Separation::Disjoint(y)) => {
            let ulps = ulp_distance(x.distance, y.distance);
            assert!(
                ulps <= 5,
                "{what}: {} vs {} ({ulps} ulps)",
                x.distance,
                y.distance
            );
            (
                (x.feature_p, x.feature_q) == (y.feature_p, y.feature_q),
                ulps,
            )
        }
        (Separation::Touching { .. }, Separation::Touching { .. })
        | (Separation::Overlapping, Separation::Overlapping) => (true, 0),
        _ => panic!("{what}: {a:?} vs {b:?}"),
    }
}

/// Checks Schwartz under `Kern` against the oracle (both orders), the brute force (when `brute`) and
/// Yang; checks the predicate count on disjoint answers.
fn check<Kern: Kernel>(p: &[DVec2], q: &[DVec2], brute: bool, stats: &mut Stats) {
    let pp = ConvexPolygon::try_new(p).expect("valid P");
    let qq = ConvexPolygon::try_new(q).expect("valid Q");
    let exact = convex_distance(p, q);
    let contact = contact_status_convex(p, q);
    let got = distance_schwartz_with::<Kern>(&pp, &qq);
    stats.merge(check_answer(p, q, &exact, contact, &got, "schwartz"));
    let swapped = distance_schwartz_with::<Kern>(&qq, &pp);
    stats.merge(check_answer(
        q,
        p,
        &exact_swapped(&exact),
        contact,
        &swapped,
        "schwartz swapped",
    ));
    let yang = distance_yang_with::<Kern>(&pp, &qq);
    let (same, ulps) = compare(&got, &yang, "schwartz vs yang");
    stats.same_pair_as_yang += u64::from(same);
    stats.max_ulps_vs_yang = stats.max_ulps_vs_yang.max(ulps);
    if brute {
        let b = distance_brute::<Kern>(&pp, &qq);
        let (same, ulps) = compare(&got, &b, "schwartz vs brute");
        stats.same_pair_as_brute += u64::from(same);
        stats.max_ulps_vs_brute = stats.max_ulps_vs_brute.max(ulps);
    }
    stats.pairs += 1;
    if contact == Contact::Disjoint {
        stats.disjoint += 1;
        let (_, count) = counted(|| distance_schwartz_with::<Counted<Robust>>(&pp, &qq));
        let count = count as f64;
        let limit = bound(pp.len(), qq.len());
        assert!(
            count <= limit,
            "{} × {}: {count} predicates > {limit}",
            pp.len(),
            qq.len()
        );
        stats.max_count_ratio = stats.max_count_ratio.max(count / limit);
    }
}

#[test]
fn every_relation_against_oracle_brute_and_yang() {
    let mut stats = Stats::default();
    let mut rng = SplitMix64::new(2026);
    for rel in RELATIONS {
        for round in 0..40 {
            // Mostly small (the O(nm) oracle), some up to 200 vertices.
            let (n, m) = if round % 8 == 0 {
                (3 + rng.index(198), 3 + rng.index(198))
            } else {
                (3 + rng.index(20), 3 + rng.index(20))
            };
            let pair = convex_pair(&mut rng, n, m, rel);
            check::<Robust>(&pair.p, &pair.q, n * m <= 2500, &mut stats);
            if round % 4 == 0 {
                check::<Exact>(&pair.p, &pair.q, false, &mut stats);
            }
        }
    }
    println!("relations: {stats:?}");
    assert!(stats.disjoint > 100);
}

/// Points and segments against polygons and each other, on a small lattice (touching and overlapping
/// cases included).
#[test]
fn points_and_segments() {
    let mut stats = Stats::default();
    let mut rng = SplitMix64::new(11);
    for round in 0..250 {
        let poly: Vec<DVec2> = random_convex_lattice(&mut rng, 3 + round % 8, 40);
        let (a, b) = (lattice_point(&mut rng), lattice_point(&mut rng));
        let v = poly[rng.index(poly.len())];
        let w = poly[(rng.index(poly.len()) + 1) % poly.len()];
        let mid = (v + w) * 0.5;
        let mut shapes: Vec<Vec<DVec2>> =
            vec![vec![a], vec![v], vec![mid], vec![v, a], vec![mid, a]];
        if a != b {
            shapes.push(vec![a, b]);
            shapes.push(vec![a, DVec2::new(b.x, a.y)]);
            shapes.push(vec![a, DVec2::new(a.x, b.y)]);
        }
        if v != w {
            shapes.push(vec![v, w]);
            shapes.push(vec![v * 2.0 - w, v]);
        }
        for s in &shapes {
            if s.len() == 2 && s[0] == s[1] {
                continue;
            }
            check::<Robust>(s, &poly, true, &mut stats);
            for t in &shapes {
                if !(t.len() == 2 && t[0] == t[1]) {
                    check::<Robust>(s, t, true, &mut stats);
                }
            }
        }
    }
    println!("points and segments: {stats:?}");
}

/// Exact ties: parallel facing edges, co-circular polygons, axis-parallel squares (horizontal sides of
/// `Z` on the line through the origin), slivers and huge offsets.
#[test]
fn exact_ties_and_hard_numbers() {
    let mut stats = Stats::default();
    let mut rng = SplitMix64::new(3);
    for k in 0..80 {
        let Some(f) = facing_pair(&mut rng, k) else {
            continue;
        };
        check::<Robust>(&f.p, &f.q, true, &mut stats);
    }
    for k in 1..5 {
        let c = cocircular(k);
        let r = c.iter().map(|p| p.x).fold(0.0, f64::max);
        for shift in [
            DVec2::new(2.0 * r + 1.0, 0.0),
            DVec2::new(2.0 * r, 2.0 * r),
            DVec2::new(2.0 * r, 0.0),
            DVec2::new(0.0, 2.0 * r + 3.0),
            DVec2::new(-2.0 * r - 1.0, -1.0),
        ] {
            let moved: Vec<DVec2> = c.iter().map(|&p| p + shift).collect();
            check::<Robust>(&c, &moved, c.len() < 40, &mut stats);
        }
    }
    // Unit squares on a grid of offsets: every horizontal/vertical tie of Z against the origin.
    let square = |x: f64, y: f64, s: f64| {
        vec![
            DVec2::new(x, y),
            DVec2::new(x + s, y),
            DVec2::new(x + s, y + s),
            DVec2::new(x, y + s),
        ]
    };
    for dx in -3..=3 {
        for dy in -3..=3 {
            let p = square(0.0, 0.0, 1.0);
            let q = square(f64::from(dx), f64::from(dy), 1.0);
            check::<Robust>(&p, &q, true, &mut stats);
            let q2 = square(f64::from(dx), f64::from(dy), 2.0);
            check::<Robust>(&p, &q2, true, &mut stats);
        }
    }
    for n in [16, 50, 120] {
        let (a, b) = sliver_pair(&mut rng, n);
        check::<Robust>(&a, &b, false, &mut stats);
        let (c, d) = huge_offset_pair(&mut rng, n);
        check::<Robust>(&c, &d, false, &mut stats);
    }
    println!("ties: {stats:?}");
}

/// Complexity by counting predicate calls (never timing), `n = 8..2^16`, disjoint pairs.
#[test]
fn predicate_count_is_log_squared() {
    let mut rng = SplitMix64::new(99);
    let mut worst: f64 = 0.0;
    // n = 8 … 2^20 (about 1e6), fewer trials at the largest sizes.
    for k in 3..=20 {
        let n = 1usize << k;
        let mut max_count = 0;
        for trial in 0..(if k > 16 { 2 } else { 8 }) {
            let m = if trial % 2 == 0 { n } else { 8 + rng.index(n) };
            let (p, q) = disjoint_pair(&mut rng, n, m);
            let (pp, qq) = (
                ConvexPolygon::try_new(&p).expect("valid"),
                ConvexPolygon::try_new(&q).expect("valid"),
            );
            let (s, count) = counted(|| distance_schwartz_with::<Counted<Robust>>(&pp, &qq));
            assert!(s.closest().is_some(), "disjoint by construction");
            let limit = bound(pp.len(), qq.len());
            assert!(
                count as f64 <= limit,
                "n = {n}, m = {m}: {count} predicates > {limit}"
            );
            let logs = (pp.len() as f64).log2() * (qq.len() as f64).log2();
            worst = worst.max((count as f64 - K) / logs);
            max_count = max_count.max(count);
            // The same answer as the Yang path.
            let y = distance_yang_with::<Robust>(&pp, &qq);
            compare(&distance_schwartz(&pp, &qq), &y, "large");
        }
        println!("n = 2^{k}: at most {max_count} predicates");
    }
    println!("worst (count − {K}) / (log₂n·log₂m) = {worst:.2} (C = {C})");
}

#[test]
fn random_sign_kernel_terminates_without_panicking() {
    seed_chaos(0x1234_5678_9abc_def0);
    let mut rng = SplitMix64::new(5);
    for round in 0..2000 {
        let (_, _, pair) = chaos_pair(&mut rng, round);
        let p = ConvexPolygon::try_new(&pair.p).expect("valid");
        let q = ConvexPolygon::try_new(&pair.q).expect("valid");
        let _ = distance_schwartz_with::<Chaos>(&p, &q);
        let s1 = ConvexPolygon::try_new(&pair.q[..2]).expect("segment");
        let s0 = ConvexPolygon::try_new(&pair.q[..1]).expect("point");
        let _ = distance_schwartz_with::<Chaos>(&p, &s1);
        let _ = distance_schwartz_with::<Chaos>(&s0, &p);
        let _ = distance_schwartz_with::<Chaos>(&s0, &s1);
    }
}
