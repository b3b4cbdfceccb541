//! Shared checks against the exact oracle.

#![allow(dead_code, reason = "each test binary uses a subset")]

use core::cell::Cell;

use glam::DVec2;
use polydist_convex::polygon::predicates::{
    BigInt, BigRational, Kernel, Polynomial, Sign, predicate_counts, reset_predicate_counts,
};
use polydist_convex::polygon::{ConvexPolygon, Feature};
use polydist_convex::{Separation, distance_brute, distance_with, distance_yang_with};
use polydist_oracle::{
    Contact, ConvexPair, ExactDistance, FacingPair, Relation, SplitMix64, contact_status_convex,
    convex_distance, convex_pair, parallel_facing, random_convex, sliver, ulps_error,
    ulps_error_sqrt,
};

/// Every relation the generator builds.
pub(crate) const RELATIONS: [Relation; 12] = Relation::EVERY;

/// The worst numeric errors seen, in ulps.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Worst {
    pub(crate) distance: f64,
    pub(crate) squared: f64,
    pub(crate) foot: f64,
}

/// Keeps in `a` the worse of each error.
pub(crate) fn merge(a: &mut Worst, b: Worst) {
    a.distance = a.distance.max(b.distance);
    a.squared = a.squared.max(b.squared);
    a.foot = a.foot.max(b.foot);
}

/// The witness `x` on the caller's feature `f` of `v`: a vertex exactly, or the foot of `other` (a
/// vertex of the other polygon) on the edge within 1 ulp per coordinate. Returns the foot error.
fn check_witness(v: &[DVec2], f: Feature, x: DVec2, other: DVec2, what: &str) -> f64 {
    match f {
        Feature::Vertex(i) => {
            assert_eq!(v[i], x, "{what}: witness is not the vertex");
            0.0
        }
        Feature::Edge(i) => {
            let r = |t: f64| polydist_oracle::rat(t).expect("finite");
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let (ax, ay, bx, by, ox, oy) = (r(a.x), r(a.y), r(b.x), r(b.y), r(other.x), r(other.y));
            let (ex, ey) = (&bx - &ax, &by - &ay);
            let l = &ex * &ex + &ey * &ey;
            let t = ((&ox - &ax) * &ex + (&oy - &ay) * &ey) / l;
            let fx = &ax + &t * &ex;
            let fy = &ay + &t * &ey;
            let err = ulps_error(x.x, &fx).max(ulps_error(x.y, &fy));
            assert!(err <= 1.0, "{what}: foot off by {err} ulps");
            err
        }
    }
}

pub(crate) fn to_oracle(f: Feature) -> polydist_oracle::Feature {
    match f {
        Feature::Vertex(i) => polydist_oracle::Feature::Vertex(i),
        Feature::Edge(i) => polydist_oracle::Feature::Edge(i),
    }
}

/// `x` lies on the caller's feature `f` of the caller ring `v` (exactly).
pub(crate) fn on_feature(v: &[DVec2], f: Feature, x: DVec2) -> bool {
    match f {
        Feature::Vertex(i) => v[i] == x,
        Feature::Edge(i) => {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            polydist_oracle::sq_dist_ps(x, a, b) == BigRational::from_integer(BigInt::from(0))
        }
    }
}

/// Checks one answer against the exact oracle; returns its numeric errors.
pub(crate) fn check_answer(
    p: &[DVec2],
    q: &[DVec2],
    exact: &ExactDistance,
    contact: Contact,
    got: &Separation,
    what: &str,
) -> Worst {
    let mut worst = Worst::default();
    match (contact, got) {
        (Contact::Disjoint, Separation::Disjoint(c)) => {
            assert!(
                exact.is_optimal_pair(to_oracle(c.feature_p), to_oracle(c.feature_q)),
                "{what}: pair {:?}/{:?} not optimal; optimal: {:?}\np = {p:?}\nq = {q:?}",
                c.feature_p,
                c.feature_q,
                exact.pairs
            );
            worst.distance = ulps_error_sqrt(c.distance, &exact.sq);
            worst.squared = ulps_error(c.squared_distance, &exact.sq);
            assert!(
                worst.distance <= 2.5,
                "{what}: distance off by {} ulps",
                worst.distance
            );
            assert!(
                worst.squared <= 3.0,
                "{what}: squared distance off by {} ulps",
                worst.squared
            );
            worst.foot = check_witness(p, c.feature_p, c.point_p, c.point_q, what)
                .max(check_witness(q, c.feature_q, c.point_q, c.point_p, what));
        }
        (
            Contact::Touching,
            Separation::Touching {
                point,
                feature_p,
                feature_q,
            },
        ) => {
            assert!(
                on_feature(p, *feature_p, *point),
                "{what}: touching point {point} not on {feature_p:?}"
            );
            assert!(
                on_feature(q, *feature_q, *point),
                "{what}: touching point {point} not on {feature_q:?}"
            );
        }
        (Contact::Overlapping, Separation::Overlapping) => {}
        (c, g) => panic!("{what}: oracle says {c:?}, got {g:?}\np = {p:?}\nq = {q:?}"),
    }
    worst
}

/// Runs the three entry points under `K` (brute only when `brute`) and checks each against the oracle.
pub(crate) fn check_all<K: Kernel>(p: &[DVec2], q: &[DVec2], brute: bool) -> Worst {
    let pp = ConvexPolygon::try_new(p).expect("valid P");
    let qq = ConvexPolygon::try_new(q).expect("valid Q");
    let exact = convex_distance(p, q);
    let contact = contact_status_convex(p, q);
    let mut worst = Worst::default();
    let mut take = |w: Worst| merge(&mut worst, w);
    take(check_answer(
        p,
        q,
        &exact,
        contact,
        &distance_yang_with::<K>(&pp, &qq),
        "yang",
    ));
    take(check_answer(
        p,
        q,
        &exact,
        contact,
        &distance_with::<K>(&pp, &qq),
        "distance",
    ));
    if brute {
        take(check_answer(
            p,
            q,
            &exact,
            contact,
            &distance_brute::<K>(&pp, &qq),
            "brute",
        ));
    }
    // Symmetry: swapping the polygons swaps the answer's features.
    take(check_answer(
        q,
        p,
        &exact_swapped(&exact),
        contact,
        &distance_yang_with::<K>(&qq, &pp),
        "yang swapped",
    ));
    worst
}

/// `e` for the swapped polygons: every optimal pair swapped.
pub(crate) fn exact_swapped(e: &ExactDistance) -> ExactDistance {
    let mut pairs: Vec<_> = e.pairs.iter().map(|&(a, b)| (b, a)).collect();
    pairs.sort();
    ExactDistance {
        sq: e.sq.clone(),
        pairs,
    }
}

/// A point with integer coordinates in `[-50, 50]²`.
pub(crate) fn lattice_point(rng: &mut SplitMix64) -> DVec2 {
    DVec2::new(rng.range_i64(-50, 50) as f64, rng.range_i64(-50, 50) as f64)
}

/// A convex `n`-gon of radius 1 around the origin and a convex `m`-gon of radius `0.5..1.5` centred
/// `4..7` away in a random direction: disjoint by construction.
pub(crate) fn disjoint_pair(rng: &mut SplitMix64, n: usize, m: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let p = random_convex(rng, n, DVec2::ZERO, 1.0);
    let angle = rng.unit_f64() * std::f64::consts::TAU;
    let dist = 4.0 + 3.0 * rng.unit_f64();
    let center = DVec2::new(angle.cos(), angle.sin()) * dist;
    let radius = 0.5 + rng.unit_f64();
    let q = random_convex(rng, m, center, radius);
    (p, q)
}

/// `f`'s answer and how many predicates it evaluated (under a `Counted` kernel).
pub(crate) fn counted(f: impl FnOnce() -> Separation) -> (Separation, u64) {
    reset_predicate_counts();
    let s = f();
    (s, predicate_counts().total())
}

/// Parallel facing edges along a random integer direction (`None` for the zero direction), case `k`:
/// `3 + k % 40` vertices, gap `1 + k % 3`.
pub(crate) fn facing_pair(rng: &mut SplitMix64, k: usize) -> Option<FacingPair> {
    let d = (rng.range_i64(-40, 40), rng.range_i64(-40, 40));
    if d == (0, 0) {
        return None;
    }
    Some(parallel_facing(
        rng,
        3 + k % 40,
        d,
        f64::from(1 + k as u32 % 3),
    ))
}

/// The sizes and pair of round `round` of the random-sign tests: `n` up to 2002 every tenth round
/// (else up to 42), `m` up to 42, in one of four relations.
pub(crate) fn chaos_pair(rng: &mut SplitMix64, round: usize) -> (usize, usize, ConvexPair) {
    let n = 3 + rng.index(if round % 10 == 0 { 2000 } else { 40 });
    let m = 3 + rng.index(40);
    let rel = [
        Relation::Far,
        Relation::Overlapping,
        Relation::TouchingEdge,
        Relation::ParallelFacing,
    ][round % 4];
    (n, m, convex_pair(rng, n, m, rel))
}

/// Two `n`-vertex slivers (aspect `1e6` and `1e3`), the second shifted by `(0.5, 3)`.
pub(crate) fn sliver_pair(rng: &mut SplitMix64, n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let a = sliver(rng, n, 1e6);
    let b: Vec<DVec2> = sliver(rng, n, 1e3)
        .iter()
        .map(|&p| p + DVec2::new(0.5, 3.0))
        .collect();
    (a, b)
}

/// Two `n`-gons of radius `1e3` near `(1e12, -1e12)`, `(2500, 700)` apart.
pub(crate) fn huge_offset_pair(rng: &mut SplitMix64, n: usize) -> (Vec<DVec2>, Vec<DVec2>) {
    let c = random_convex(rng, n, DVec2::new(1e12, -1e12), 1e3);
    let d = random_convex(rng, n, DVec2::new(1e12 + 2500.0, -1e12 + 700.0), 1e3);
    (c, d)
}

std::thread_local! {
    static CHAOS: Cell<u64> = const { Cell::new(0x9e37_79b9_7f4a_7c15) };
}

/// Sets the state of [`Chaos`] on this thread.
pub(crate) fn seed_chaos(seed: u64) {
    CHAOS.with(|c| c.set(seed));
}

/// A kernel whose every sign is pseudo-random (SplitMix64 on a thread-local state, see
/// [`seed_chaos`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Chaos;

impl Kernel for Chaos {
    const NAME: &'static str = "chaos";
    const EXACT_DECISIONS: bool = false;
    type Guide = Chaos;
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

/// The strictly separated vertex subsets of `p` (left of `a → b`) and `q` (right of it), when both are
/// polygons with area: the "clipped subsets" family (long lid edges on both sides of the cut).
pub(crate) fn clipped(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Option<(Vec<DVec2>, Vec<DVec2>)> {
    use polydist_convex::polygon::predicates::Robust;
    let side = |s: Sign| move |x: &&DVec2| Robust::orient(a, b, **x).sign() == s;
    let c: Vec<DVec2> = p.iter().filter(side(Sign::Positive)).copied().collect();
    let d: Vec<DVec2> = q.iter().filter(side(Sign::Negative)).copied().collect();
    if c.len() < 3 || d.len() < 3 {
        return None;
    }
    ConvexPolygon::try_new(&c).ok()?;
    ConvexPolygon::try_new(&d).ok()?;
    Some((c, d))
}

/// A clipped-subsets pair (see [`clipped`]) cut from two overlapping `n`-gons, by a line through a
/// random vertex of each; `None` when a side keeps fewer than three vertices.
pub(crate) fn clipped_pair(
    rng: &mut SplitMix64,
    n: usize,
    round: usize,
) -> Option<(Vec<DVec2>, Vec<DVec2>)> {
    let (p, q) = if round % 2 == 0 && n <= 400 {
        let pair = convex_pair(rng, n, n, Relation::Overlapping);
        (pair.p, pair.q)
    } else {
        let p = random_convex(rng, n, DVec2::ZERO, 1.0);
        let q = random_convex(rng, n, DVec2::new(0.6, 0.1), 1.0);
        (p, q)
    };
    let (a, b) = (p[rng.index(p.len())], q[rng.index(q.len())]);
    (a != b).then(|| clipped(&p, &q, a, b)).flatten()
}
