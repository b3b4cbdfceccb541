//! Shared checks against the exact oracle.

#![allow(dead_code, reason = "each test binary uses a subset")]

use glam::DVec2;
use polydist_convex::polygon::predicates::{BigInt, BigRational, Kernel};
use polydist_convex::polygon::{ConvexPolygon, Feature};
use polydist_convex::{Separation, distance_brute, distance_with, distance_yang_with};
use polydist_oracle::{
    Contact, ExactDistance, contact_status_convex, convex_distance, ulps_error, ulps_error_sqrt,
};

/// The worst numeric errors seen, in ulps.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Worst {
    pub(crate) distance: f64,
    pub(crate) squared: f64,
    pub(crate) foot: f64,
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
    let mut take = |w: Worst| {
        worst.distance = worst.distance.max(w.distance);
        worst.squared = worst.squared.max(w.squared);
        worst.foot = worst.foot.max(w.foot);
    };
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

fn exact_swapped(e: &ExactDistance) -> ExactDistance {
    let mut pairs: Vec<_> = e.pairs.iter().map(|&(a, b)| (b, a)).collect();
    pairs.sort();
    ExactDistance {
        sq: e.sq.clone(),
        pairs,
    }
}
