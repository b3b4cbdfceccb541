//! Accurate constructions from exactly chosen features: every polynomial evaluated exactly and
//! rounded once (the convex crate's `construct.rs` budget): vertex–vertex `|p − q|²` within 0.5 ulp
//! and its square root within 1 ulp; vertex–edge (foot strictly inside) `c²/L` within 3 ulps and its
//! square root within 2.5 ulps.

use glam::DVec2;
use polydist_polygon::Feature;
use polydist_predicates::{Polynomial, Ring, round_value};

use crate::result::ClosestPair;

/// `|p − q|²` (degree 2). Inputs `[px, py, qx, qy]`.
struct SqDist;
impl Polynomial<4> for SqDist {
    const DEGREE: u32 = 2;
    fn eval<R: Ring>(&self, x: &[R; 4]) -> R {
        x[0].sub(&x[2]).square().add(&x[1].sub(&x[3]).square())
    }
}

/// `((b − a) × (x − a))²` (degree 4). Inputs `[ax, ay, bx, by, xx, xy]`.
struct CrossSquared;
impl Polynomial<6> for CrossSquared {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 6]) -> R {
        let (ex, ey) = (x[2].sub(&x[0]), x[3].sub(&x[1]));
        ex.mul(&x[5].sub(&x[1]))
            .sub(&ey.mul(&x[4].sub(&x[0])))
            .square()
    }
}

/// The pair of vertices `p` (feature `fp`) and `q` (feature `fq`).
pub(crate) fn vertex_vertex(p: DVec2, q: DVec2, fp: Feature, fq: Feature) -> ClosestPair {
    let squared = round_value(&SqDist, &[p.x, p.y, q.x, q.y]);
    ClosestPair {
        distance: squared.sqrt(),
        squared_distance: squared,
        point_p: p,
        point_q: q,
        feature_p: fp,
        feature_q: fq,
    }
}

/// The vertex `x` and the edge `ab` whose closest point to `x` is strictly inside the edge.
/// Returns `(squared distance, distance, foot)`; the foot is `a + t(b − a)` in `f64` (no ulp bound).
pub(crate) fn vertex_edge(x: DVec2, a: DVec2, b: DVec2) -> (f64, f64, DVec2) {
    let l = round_value(&SqDist, &[a.x, a.y, b.x, b.y]);
    let c2 = round_value(&CrossSquared, &[a.x, a.y, b.x, b.y, x.x, x.y]);
    let squared = c2 / l;
    let e = b - a;
    let t = (x - a).dot(e) / e.length_squared();
    (squared, squared.sqrt(), a + e * t.clamp(0.0, 1.0))
}
