//! Motions: the pose of a body at time `t`, and Schwartz's bound on how fast the distance of a pair
//! can shrink over a time interval.
//!
//! # The motion bound (Schwartz 1981, §1, with the erratum)
//! A body `B` at time `t` occupies `R(θ(t))·B + x(t)` (rotation about the body frame's origin, then
//! translation). For two bodies `P`, `Q` and points `p ∈ P`, `q ∈ Q` (body frames),
//! `w(t) = R(θ_P)p + x_P − R(θ_Q)q − x_Q` has derivative
//! `ω_P·R'(θ_P)p − ω_Q·R'(θ_Q)q + (ẋ_P − ẋ_Q)`, of norm at most
//! `|ẋ_P − ẋ_Q| + |ω_P|·r_P + |ω_Q|·r_Q` with `r` the largest distance of a vertex from the body
//! frame's origin (the farthest point of a polygon from a point is a vertex). The distance
//! `d(t) = min |w(t)|` is therefore Lipschitz with that constant `V`: no contact can happen within
//! `d / V` of a time with distance `d`. The paper writes the translation term as
//! `|x₁(t) + x₂(t) − x₁(0) − x₂(0)|`; the erratum (papers/INDEX.md) corrects it to the **relative**
//! translation `|(x₂(t) − x₁(t)) − (x₂(0) − x₁(0))|`, whose rate is `|ẋ_P − ẋ_Q|` used here: two
//! bodies moving together have no translation term.
//!
//! Velocities are piecewise constant (linear motions: one piece; keyframes: one piece per segment,
//! zero before the first and after the last key), so the bound over `[a, b]` is the maximum of `V`
//! over the pieces of the merged breakpoints of both bodies. Every term is rounded **up** (see
//! [`up`]), so the bound holds for the exact motion despite rounding.

use glam::DVec2;
use polydist_convex::Pose;

/// A validated motion.
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// The body stays at `pose`.
    Static(Pose),
    /// `pose(t) = start + t·(velocity, angular)`.
    Linear {
        /// The pose at `t = 0`.
        start: Pose,
        /// The translation velocity.
        velocity: DVec2,
        /// The angular velocity (radians per time unit).
        angular: f64,
    },
    /// Keyframes with strictly increasing times (at least one), linearly interpolated.
    Keyframes(Vec<Keyframe>),
}

/// A key of [`Motion::Keyframes`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Keyframe {
    /// The time.
    pub t: f64,
    /// The pose at `t`.
    pub pose: Pose,
}

/// `x ≥ 0` rounded up with room for a few roundings: `x·(1 + 16ε)`, then the next float up (zero
/// stays zero: an exactly computed zero needs no room). Every quantity of the bound is computed
/// from exact inputs with at most a handful of correctly rounded operations, each off by at most
/// `ε/2` relatively, so `up` of the computed value bounds the exact one.
pub(crate) fn up(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        (x * (1.0 + 16.0 * f64::EPSILON)).next_up()
    }
}

/// `x` rounded down with the same room as [`up`], and never below zero.
pub(crate) fn down(x: f64) -> f64 {
    (x * (1.0 - 16.0 * f64::EPSILON)).next_down().max(0.0)
}

impl Motion {
    /// Whether the body never moves.
    #[must_use]
    pub fn is_static(&self) -> bool {
        match self {
            Motion::Static(_) => true,
            Motion::Linear {
                velocity, angular, ..
            } => *velocity == DVec2::ZERO && *angular == 0.0,
            Motion::Keyframes(keys) => keys.windows(2).all(|w| w[0].pose == w[1].pose),
        }
    }

    /// The pose at time `t` (computed in `f64`, a few ulps from the exact interpolation).
    ///
    /// # Complexity
    /// `O(1)`, or `O(log k)` for `k` keyframes (binary search).
    #[must_use]
    pub fn pose_at(&self, t: f64) -> Pose {
        match self {
            Motion::Static(p) => *p,
            Motion::Linear {
                start,
                velocity,
                angular,
            } => Pose {
                translation: start.translation + *velocity * t,
                rotation: start.rotation + angular * t,
            },
            Motion::Keyframes(keys) => {
                // The first key with time > t.
                let i = keys.partition_point(|k| k.t <= t);
                if i == 0 {
                    return keys[0].pose;
                }
                if i == keys.len() {
                    return keys[i - 1].pose;
                }
                let (a, b) = (keys[i - 1], keys[i]);
                let s = (t - a.t) / (b.t - a.t);
                Pose {
                    translation: a.pose.translation + (b.pose.translation - a.pose.translation) * s,
                    rotation: a.pose.rotation + (b.pose.rotation - a.pose.rotation) * s,
                }
            }
        }
    }

    /// The times in the open interval `(a, b)` where the velocity may change.
    fn breakpoints(&self, a: f64, b: f64, out: &mut Vec<f64>) {
        if let Motion::Keyframes(keys) = self {
            out.extend(keys.iter().map(|k| k.t).filter(|&t| a < t && t < b));
        }
    }

    /// The velocity `(ẋ, ω)` on the piece containing the open interval around `t` (`t` strictly
    /// between breakpoints), with an absolute error bound on `|ẋ|` from its computation.
    fn velocity_at(&self, t: f64) -> (DVec2, f64, f64) {
        match self {
            Motion::Static(_) => (DVec2::ZERO, 0.0, 0.0),
            Motion::Linear {
                velocity, angular, ..
            } => (*velocity, *angular, 0.0),
            Motion::Keyframes(keys) => {
                let i = keys.partition_point(|k| k.t <= t);
                if i == 0 || i == keys.len() {
                    return (DVec2::ZERO, 0.0, 0.0);
                }
                let (a, b) = (keys[i - 1], keys[i]);
                let dt = b.t - a.t;
                let v = (b.pose.translation - a.pose.translation) / dt;
                let w = (b.pose.rotation - a.pose.rotation) / dt;
                // Three roundings per component (difference, difference of times, quotient): the
                // computed vector is within 4ε|v| of the exact one (rounded up below). The angular
                // rate's relative error is absorbed by `up` of |ω|·r.
                let err = up(4.0 * f64::EPSILON * v.length());
                (v, w, err)
            }
        }
    }
}

/// An upper bound, rounded up, on `|d/dt (w(t))|` over `[a, b]` for two bodies (see the module
/// docs): `max over pieces of |ẋ_P − ẋ_Q| + |ω_P|·r_P + |ω_Q|·r_Q`. `r_p`, `r_q` are the bodies'
/// radii about their frames' origins (already rounded up).
///
/// # Complexity
/// `O(K + k log k)` for keyframed motions with `K` keys in all and `k` of them in `[a, b]`, else
/// `O(1)`.
///
/// # References
/// J. T. Schwartz, "Finding the minimum distance between two convex polygons", Information
/// Processing Letters 13(4–5), 1981, §1, with the erratum of papers/INDEX.md (relative translation).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::Pose;
/// use polydist_scene::{Motion, relative_speed_bound};
///
/// // Moving together: no relative translation, only the spin of the second body (|ω|·r = 2·1.5).
/// let p = Motion::Linear { start: Pose::IDENTITY, velocity: DVec2::new(3.0, 4.0), angular: 0.0 };
/// let q = Motion::Linear { start: Pose::IDENTITY, velocity: DVec2::new(3.0, 4.0), angular: 2.0 };
/// let v = relative_speed_bound(&p, 1.0, &q, 1.5, 0.0, 10.0);
/// assert!(v >= 3.0 && v < 3.0 + 1e-12);
/// ```
#[must_use]
pub fn relative_speed_bound(mp: &Motion, r_p: f64, mq: &Motion, r_q: f64, a: f64, b: f64) -> f64 {
    let mut cuts = vec![a];
    mp.breakpoints(a, b, &mut cuts);
    mq.breakpoints(a, b, &mut cuts);
    cuts.push(b);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut best = 0.0f64;
    let pieces = cuts.len().saturating_sub(1).max(1);
    for k in 0..pieces {
        let (lo, hi) = (cuts[k], cuts[(k + 1).min(cuts.len() - 1)]);
        // A time strictly inside the piece (or the single instant): the velocity is constant there.
        let mid = lo + (hi - lo) / 2.0;
        let (vp, wp, ep) = mp.velocity_at(mid);
        let (vq, wq, eq) = mq.velocity_at(mid);
        // The computed velocities are within ep, eq of the exact ones (0 for given velocities);
        // the difference and the norm of the computed ones are a few relative roundings.
        let trans = up((vp - vq).length()) + ep + eq;
        let rot = up(wp.abs() * r_p) + up(wq.abs() * r_q);
        best = best.max(up(up(trans) + rot));
    }
    best
}

/// The radius of a vertex set about the origin, rounded up: `max |v|`.
pub(crate) fn radius(vertices: &[DVec2]) -> f64 {
    up(vertices.iter().map(|v| v.length()).fold(0.0, f64::max))
}

/// A bound on how far [`Pose::apply`] may put a vertex of a body of radius `r` from its exact image
/// under the exact pose interpolated by [`Motion::pose_at`]: the rounding of the interpolation
/// (a few ulps of the translation and of the angle, the latter moving a vertex by `r·δθ`), of
/// `sin`/`cos` (an ulp each) and of the rotation and translation themselves.
pub(crate) fn pose_error(pose: Pose, r: f64) -> f64 {
    let e = 32.0 * f64::EPSILON;
    up(e * (pose.translation.length() + r * (2.0 + pose.rotation.abs())))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(x: f64, y: f64, a: f64) -> Pose {
        Pose {
            translation: DVec2::new(x, y),
            rotation: a,
        }
    }

    fn keys(k: &[(f64, f64, f64, f64)]) -> Motion {
        Motion::Keyframes(
            k.iter()
                .map(|&(t, x, y, a)| Keyframe {
                    t,
                    pose: pose(x, y, a),
                })
                .collect(),
        )
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * (1.0 + b.abs())
    }

    #[test]
    fn linear_pose() {
        let m = Motion::Linear {
            start: pose(1.0, 2.0, 0.5),
            velocity: DVec2::new(3.0, -1.0),
            angular: 0.25,
        };
        assert_eq!(m.pose_at(2.0), pose(7.0, 0.0, 1.0));
        assert!(!m.is_static());
    }

    #[test]
    fn keyframe_pose_interpolates_and_holds() {
        let m = keys(&[
            (1.0, 0.0, 0.0, 0.0),
            (3.0, 4.0, 2.0, 1.0),
            (4.0, 4.0, 2.0, 1.0),
        ]);
        assert_eq!(m.pose_at(0.0), pose(0.0, 0.0, 0.0));
        assert_eq!(m.pose_at(2.0), pose(2.0, 1.0, 0.5));
        assert_eq!(m.pose_at(3.0), pose(4.0, 2.0, 1.0));
        assert_eq!(m.pose_at(3.5), pose(4.0, 2.0, 1.0));
        assert_eq!(m.pose_at(9.0), pose(4.0, 2.0, 1.0));
    }

    #[test]
    fn speed_bound_analytic_linear() {
        // P: v = (3, 0), ω = 2, r = 1.5. Q: v = (0, 4), ω = −1, r = 2.
        // V = |(3, −4)| + 2·1.5 + 1·2 = 5 + 3 + 2 = 10.
        let p = Motion::Linear {
            start: Pose::IDENTITY,
            velocity: DVec2::new(3.0, 0.0),
            angular: 2.0,
        };
        let q = Motion::Linear {
            start: pose(10.0, 0.0, 0.0),
            velocity: DVec2::new(0.0, 4.0),
            angular: -1.0,
        };
        let v = relative_speed_bound(&p, 1.5, &q, 2.0, 0.0, 5.0);
        assert!(v >= 10.0 && close(v, 10.0), "{v}");
    }

    #[test]
    fn speed_bound_uses_relative_translation() {
        // The erratum: two bodies translating together have no translation term.
        let m = Motion::Linear {
            start: Pose::IDENTITY,
            velocity: DVec2::new(7.0, -3.0),
            angular: 0.0,
        };
        let v = relative_speed_bound(&m, 1.0, &m, 1.0, 0.0, 100.0);
        assert_eq!(v, 0.0);
        // With the paper's uncorrected |x1 + x2| term it would be 2·|(7, −3)| > 15.
    }

    #[test]
    fn speed_bound_keyframes_takes_the_fastest_overlapping_segment() {
        // Segments: [0, 1] speed 1 (x 0 → 1), [1, 2] speed 5 (x 1 → 4, y 0 → 4), [2, 3] with
        // angular rate 3 only.
        let p = keys(&[
            (0.0, 0.0, 0.0, 0.0),
            (1.0, 1.0, 0.0, 0.0),
            (2.0, 4.0, 4.0, 0.0),
            (3.0, 4.0, 4.0, 3.0),
        ]);
        let q = Motion::Static(Pose::IDENTITY);
        let r = 2.0;
        let b = |a, c| relative_speed_bound(&p, r, &q, 0.0, a, c);
        assert!(close(b(0.0, 0.5), 1.0) && b(0.0, 0.5) >= 1.0);
        assert!(close(b(0.0, 1.5), 5.0) && b(0.0, 1.5) >= 5.0);
        assert!(close(b(2.2, 2.8), 6.0) && b(2.2, 2.8) >= 6.0);
        assert!(close(b(0.5, 10.0), 6.0));
        // Before the first and after the last key the body holds still.
        assert_eq!(b(3.5, 9.0), 0.0);
        assert_eq!(b(-5.0, -1.0), 0.0);
        // At a single instant inside a segment.
        assert!(close(b(1.5, 1.5), 5.0));
    }

    #[test]
    fn speed_bound_merges_breakpoints_of_both_bodies() {
        // P moves right at speed 2 on [0, 2]; Q moves right at speed 2 on [1, 3]. On [1, 2] they
        // move together: the relative speed is 0 there, 2 elsewhere.
        let p = keys(&[(0.0, 0.0, 0.0, 0.0), (2.0, 4.0, 0.0, 0.0)]);
        let q = keys(&[(1.0, 10.0, 0.0, 0.0), (3.0, 14.0, 0.0, 0.0)]);
        let b = |a, c| relative_speed_bound(&p, 1.0, &q, 1.0, a, c);
        assert!(close(b(1.1, 1.9), 0.0));
        assert!(close(b(0.0, 3.0), 2.0) && b(0.0, 3.0) >= 2.0);
    }

    #[test]
    fn speed_bound_is_a_true_bound_on_sampled_point_speeds() {
        // Finite differences of the farthest vertex never exceed the bound.
        let p = Motion::Linear {
            start: pose(0.3, -0.2, 0.1),
            velocity: DVec2::new(-1.25, 0.5),
            angular: 1.7,
        };
        let q = keys(&[
            (0.0, 5.0, 0.0, 0.0),
            (2.0, 3.0, 1.0, -2.0),
            (4.0, 3.0, 1.0, 0.0),
        ]);
        let (vp, vq) = (DVec2::new(1.0, 1.0), DVec2::new(-2.0, 0.5));
        let (rp, rq) = (radius(&[vp]), radius(&[vq]));
        let v = relative_speed_bound(&p, rp, &q, rq, 0.0, 4.0);
        let h = 1e-6;
        for i in 0..400 {
            let t = f64::from(i) * 0.01;
            let w = |t: f64| p.pose_at(t).apply(vp) - q.pose_at(t).apply(vq);
            let speed = (w(t + h) - w(t)).length() / h;
            assert!(speed <= v * (1.0 + 1e-6), "t = {t}: {speed} > {v}");
        }
    }
}
