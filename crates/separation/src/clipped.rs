//! Exact comparison of distances from a vertex to the part of an edge on the envelope `P°`, when that
//! part ends at a shadow point (the edge passes behind a visible vertex `v`: the point `s` of the
//! edge at `v`'s height). `s` is never constructed: with `d = l1 − l0`, `D = (b − a)·d > 0`,
//! `N = (v − a)·d`, `s = a + (N/D)(b − a)` and `|q − s|² = S/D²` with
//! `S = |(q − a)D − N(b − a)|²` (degree 6). Comparisons against the kernel's resolved squared
//! distances cross-multiply the positive denominators:
//!
//! | comparison | polynomial | degree |
//! |---|---|---|
//! | foot of `q` on `(a, b)` against `s` | `((q − a)·(b − a))·D − N·|b − a|²` | 4 |
//! | `|q − s|²` against `|p − r|²` | `S − |p − r|²·D²` | 6 |
//! | `|q − s|²` against `((e − c) × (p − c))²/|e − c|²` | `S·|e − c|² − ((e − c) × (p − c))²·D²` | 8 |
//! | `|q − s|²` against `|q' − s'|²` | `S·D'² − S'·D²` | 10 |

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Dist2, Kernel, Polynomial, Ring, Sign};

fn pt<R>(x: &[R], i: usize) -> (&R, &R) {
    (&x[2 * i], &x[2 * i + 1])
}

fn sub<R: Ring>(p: (&R, &R), q: (&R, &R)) -> (R, R) {
    (p.0.sub(q.0), p.1.sub(q.1))
}

fn dot<R: Ring>(u: &(R, R), w: &(R, R)) -> R {
    u.0.mul(&w.0).add(&u.1.mul(&w.1))
}

/// `(S, D²)` for the points `[q, a, b, v, l0, l1]` starting at point index `k`.
fn shadow<R: Ring>(x: &[R], k: usize) -> (R, R) {
    let (q, a, b, v, l0, l1) = (
        pt(x, k),
        pt(x, k + 1),
        pt(x, k + 2),
        pt(x, k + 3),
        pt(x, k + 4),
        pt(x, k + 5),
    );
    let d = sub(l1, l0);
    let ab = sub(b, a);
    let dd = dot(&ab, &d);
    let n = dot(&sub(v, a), &d);
    let qa = sub(q, a);
    let w = (
        qa.0.mul(&dd).sub(&n.mul(&ab.0)),
        qa.1.mul(&dd).sub(&n.mul(&ab.1)),
    );
    (dot(&w, &w), dd.square())
}

/// `((q − a)·(b − a))·D − N·|b − a|²`: the foot of `q` on line `(a, b)` against the shadow point
/// (positive: beyond it toward `b`). Inputs `[q, a, b, v, l0, l1]`. Degree 4.
struct FootVsShadow;
impl Polynomial<12> for FootVsShadow {
    const DEGREE: u32 = 4;
    fn eval<R: Ring>(&self, x: &[R; 12]) -> R {
        let (q, a, b, v, l0, l1) = (pt(x, 0), pt(x, 1), pt(x, 2), pt(x, 3), pt(x, 4), pt(x, 5));
        let d = sub(l1, l0);
        let ab = sub(b, a);
        let dd = dot(&ab, &d);
        let n = dot(&sub(v, a), &d);
        dot(&sub(q, a), &ab).mul(&dd).sub(&n.mul(&dot(&ab, &ab)))
    }
}

/// `S − |p − r|²·D²`. Inputs `[q, a, b, v, l0, l1, p, r]`. Degree 6.
struct ShadowVsPoints;
impl Polynomial<16> for ShadowVsPoints {
    const DEGREE: u32 = 6;
    fn eval<R: Ring>(&self, x: &[R; 16]) -> R {
        let (s, d2) = shadow(x, 0);
        let pr = sub(pt(x, 6), pt(x, 7));
        s.sub(&dot(&pr, &pr).mul(&d2))
    }
}

/// `S·|e − c|² − ((e − c) × (p − c))²·D²`. Inputs `[q, a, b, v, l0, l1, p, c, e]`. Degree 8.
struct ShadowVsPerp;
impl Polynomial<18> for ShadowVsPerp {
    const DEGREE: u32 = 8;
    fn eval<R: Ring>(&self, x: &[R; 18]) -> R {
        let (s, d2) = shadow(x, 0);
        let (p, c, e) = (pt(x, 6), pt(x, 7), pt(x, 8));
        let ec = sub(e, c);
        let pc = sub(p, c);
        let cr = ec.0.mul(&pc.1).sub(&ec.1.mul(&pc.0));
        s.mul(&dot(&ec, &ec)).sub(&cr.square().mul(&d2))
    }
}

/// `S·D'² − S'·D²`. Inputs `[q, a, b, v, l0, l1, q', a', b', v', l0', l1']`. Degree 10.
struct ShadowVsShadow;
impl Polynomial<24> for ShadowVsShadow {
    const DEGREE: u32 = 10;
    fn eval<R: Ring>(&self, x: &[R; 24]) -> R {
        let (s1, d1) = shadow(x, 0);
        let (s2, d2) = shadow(x, 6);
        s1.mul(&d2).sub(&s2.mul(&d1))
    }
}

fn flat<const N: usize>(pts: &[DVec2]) -> [f64; N] {
    core::array::from_fn(|i| {
        if i % 2 == 0 {
            pts[i / 2].x
        } else {
            pts[i / 2].y
        }
    })
}

/// A squared distance from a vertex to (part of) an edge, resolved for comparison.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Val {
    /// A distance between input features.
    Input(Dist2),
    /// `|q − s|²`, `s` the point of `(a, b)` at `v`'s height along `l1 − l0`: `[q, a, b, v, l0, l1]`.
    Shadow([DVec2; 6]),
}

/// The distance from `q` to the part of `[a, b]` (`a` lower along `l1 − l0`) between the heights of
/// `lo` and `hi` (`None`: the edge's own end). `O(1)` tests of degree ≤ 4.
pub(crate) fn resolve_clipped<K: Kernel>(
    q: DVec2,
    a: DVec2,
    b: DVec2,
    lo: Option<DVec2>,
    hi: Option<DVec2>,
    (l0, l1): (DVec2, DVec2),
) -> Val {
    if let Some(v) = lo {
        let pts = [q, a, b, v, l0, l1];
        if K::sign(&FootVsShadow, &flat::<12>(&pts)) == Sign::Negative {
            return Val::Shadow(pts);
        }
    }
    if let Some(v) = hi {
        let pts = [q, a, b, v, l0, l1];
        if K::sign(&FootVsShadow, &flat::<12>(&pts)) == Sign::Positive {
            return Val::Shadow(pts);
        }
    }
    Val::Input(Dist2::PointSegment(q, a, b))
}

/// A kernel's resolution of an input distance into point–point or perpendicular form.
enum Input {
    Points(DVec2, DVec2),
    Perp(DVec2, DVec2, DVec2),
}

fn input<K: Kernel>(d: Dist2) -> Input {
    match d {
        Dist2::PointPoint(p, q) => Input::Points(p, q),
        Dist2::PointLine(p, a, b) if a == b => Input::Points(p, a),
        Dist2::PointLine(p, a, b) => Input::Perp(p, a, b),
        Dist2::PointSegment(p, a, b) => {
            if K::dot_sign(a, p, a, b) != Sign::Positive {
                Input::Points(p, a)
            } else if K::dot_sign(b, p, b, a) != Sign::Positive {
                Input::Points(p, b)
            } else {
                Input::Perp(p, a, b)
            }
        }
    }
}

fn shadow_vs_input<K: Kernel>(s: &[DVec2; 6], d: Dist2) -> Ordering {
    match input::<K>(d) {
        Input::Points(p, r) => {
            let mut x = s.to_vec();
            x.extend([p, r]);
            K::sign(&ShadowVsPoints, &flat::<16>(&x)).to_ordering()
        }
        Input::Perp(p, c, e) => {
            let mut x = s.to_vec();
            x.extend([p, c, e]);
            K::sign(&ShadowVsPerp, &flat::<18>(&x)).to_ordering()
        }
    }
}

/// The exact order of two resolved distances.
pub(crate) fn cmp_val<K: Kernel>(x: &Val, y: &Val) -> Ordering {
    match (x, y) {
        (Val::Input(d), Val::Input(e)) => K::cmp_dist2(*d, *e),
        (Val::Shadow(s), Val::Input(d)) => shadow_vs_input::<K>(s, *d),
        (Val::Input(d), Val::Shadow(s)) => shadow_vs_input::<K>(s, *d).reverse(),
        (Val::Shadow(s), Val::Shadow(t)) => {
            if s == t {
                return Ordering::Equal;
            }
            let mut x = s.to_vec();
            x.extend(t);
            K::sign(&ShadowVsShadow, &flat::<24>(&x)).to_ordering()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::{Exact, Robust};

    /// The polynomials against `f64` constructions on well-separated random integer inputs (where
    /// rounding cannot flip a sign: differences are checked to be large).
    #[test]
    fn shadow_distances_match_constructions() {
        let mut rng = SplitMix64::new(77);
        let mut checked = 0;
        for _ in 0..3000 {
            let mut r = || DVec2::new(rng.range_i64(-40, 40) as f64, rng.range_i64(-40, 40) as f64);
            let (q, a, b, v, l0, l1, p, c) = (r(), r(), r(), r(), r(), r(), r(), r());
            let d = l1 - l0;
            let dd = (b - a).dot(d);
            if dd <= 0.0 || l0 == l1 {
                continue;
            }
            let s = a + (b - a) * ((v - a).dot(d) / dd);
            let ds = (q - s).length_squared();
            let dp = (p - c).length_squared();
            if (ds - dp).abs() > 1e-6 * ds.max(dp) {
                let got = cmp_val::<Exact>(
                    &Val::Shadow([q, a, b, v, l0, l1]),
                    &Val::Input(Dist2::PointPoint(p, c)),
                );
                assert_eq!(got, ds.total_cmp(&dp));
                checked += 1;
            }
            let t = (q - a).dot(b - a) / (b - a).length_squared();
            let ts = (v - a).dot(d) / dd;
            if (t - ts).abs() > 1e-9 {
                let lo = resolve_clipped::<Robust>(q, a, b, Some(v), None, (l0, l1));
                assert_eq!(matches!(lo, Val::Shadow(_)), t < ts);
            }
        }
        assert!(checked > 1000);
    }
}
