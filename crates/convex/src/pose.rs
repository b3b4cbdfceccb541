//! Posed queries: the distance between two convex polygons placed by rigid motions.

use glam::DVec2;
use polydist_polygon::predicates::Kernel;
use polydist_polygon::{ConvexPolygon, Feature, PolygonError};

use crate::pair::{at, caller_on_edge, caller_vertex};
use crate::result::Separation;
use crate::yang::distance_with;

/// A rigid motion: rotate by `rotation` radians (counter-clockwise) about the origin, then translate
/// by `translation`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pose {
    /// Added after the rotation.
    pub translation: DVec2,
    /// Counter-clockwise, in radians.
    pub rotation: f64,
}

impl Pose {
    /// The identity motion: `apply` returns its argument unchanged (`cos 0 = 1`, `sin 0 = 0` exactly).
    pub const IDENTITY: Pose = Pose {
        translation: DVec2::ZERO,
        rotation: 0.0,
    };

    /// The image of `x`, rounded: `(c·x − s·y + t_x, s·x + c·y + t_y)` in `f64` with
    /// `(s, c) = rotation.sin_cos()`.
    ///
    /// # Complexity
    /// `O(1)`.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_convex::Pose;
    ///
    /// let pose = Pose { translation: DVec2::new(1.0, 2.0), rotation: 0.0 };
    /// assert_eq!(pose.apply(DVec2::new(3.0, 4.0)), DVec2::new(4.0, 6.0));
    /// ```
    #[must_use]
    pub fn apply(&self, x: DVec2) -> DVec2 {
        let (s, c) = self.rotation.sin_cos();
        DVec2::new(c * x.x - s * x.y, s * x.x + c * x.y) + self.translation
    }

    /// The preimage of `x`, rounded (the inverse motion in `f64`; not exact).
    fn unapply(&self, x: DVec2) -> DVec2 {
        let (s, c) = self.rotation.sin_cos();
        let d = x - self.translation;
        DVec2::new(c * d.x + s * d.y, c * d.y - s * d.x)
    }
}

/// The polygon's internal vertices under `pose`, validated again: the posed polygon's caller
/// index `k` is the original's internal vertex `k`.
fn posed(poly: &ConvexPolygon, pose: Pose) -> Result<ConvexPolygon, PolygonError> {
    let moved: Vec<DVec2> = poly.vertices().iter().map(|&v| pose.apply(v)).collect();
    ConvexPolygon::try_new(&moved)
}

/// A feature of the posed polygon (in its caller's indices = the original's internal indices) as the
/// original polygon's caller feature. `x` is the world point that decides the caller edge along an
/// internal edge of the original (a realizing point of the other polygon, or the touching point).
fn original_feature<K: Kernel>(
    original: &ConvexPolygon,
    pose: Pose,
    feature: Feature,
    x: DVec2,
) -> Feature {
    let Feature::Edge(k) = feature else {
        return match feature {
            Feature::Vertex(k) | Feature::Edge(k) => caller_vertex(original, k),
        };
    };
    let found = caller_on_edge::<K>(original, k, pose.unapply(x));
    // The posed answer says the point is strictly inside the edge. If the back-moved point rounded
    // onto an end, the caller's feature is the sub-edge at that end: ask again at points strictly
    // inside the edge, ever farther from that end (a fraction `2^-20` of the edge first; farther when
    // that point rounds onto the end, as on short edges far from the origin).
    let (a, b) = (at(original.vertices(), k), at(original.vertices(), k + 1));
    let (end, other) = if found == caller_vertex(original, k) {
        (a, b)
    } else if found == caller_vertex(original, k + 1) {
        (b, a)
    } else {
        return found;
    };
    NEAR_END
        .iter()
        .map(|&t| caller_on_edge::<K>(original, k, end + (other - end) * t))
        .find(|f| matches!(f, Feature::Edge(_)))
        .unwrap_or(found)
}

/// The fractions of the edge from its end at which [`original_feature`] asks again.
const NEAR_END: [f64; 5] = [
    1.0 / 1_048_576.0,
    1.0 / 16_384.0,
    1.0 / 256.0,
    1.0 / 16.0,
    0.5,
];

/// The distance between `p` placed by `pose_p` and `q` placed by `pose_q`, with features in the
/// **original** polygons' caller indices.
///
/// Each polygon's vertices are moved by its pose ([`Pose::apply`], rounded to `f64`), validated again
/// by [`ConvexPolygon::try_new`] and passed to [`distance_with`]. The answer's points are in the world
/// (posed) frame; its features are mapped back: the posed polygon's caller vertex `k` is the original's
/// internal vertex `k`, reported as the original caller's vertex `p.source_index(k)`; a posed edge
/// `k` is the original's internal edge `k`, reported through
/// [`ConvexPolygon::caller_feature_on_edge`] at the other polygon's realizing point moved back by the
/// inverse pose.
///
/// **Exactness holds for the rounded posed coordinates**, not for the ideal rotated polygons: every
/// decision is exact for the vertices as rounded, and the numbers obey the crate's budget relative to
/// them. The rounding of a rotation moves a vertex by about one ulp of its coordinates. A posed edge
/// is always reported as a caller edge (never as a caller vertex): for polygons without dropped caller
/// vertices this mapping is exact. Along an internal edge that stands for several caller edges
/// (dropped collinear or repeated caller vertices) the caller edge is chosen at the back-moved,
/// rounded point (near an end, at a point `2^-20` of the edge from that end, or farther when that one rounds onto the end): not an exact decision
/// when the point lies within rounding of a dropped caller vertex.
///
/// # Errors
/// The [`PolygonError`] of [`ConvexPolygon::try_new`] on a posed vertex list: `NonFinite` for a
/// non-finite pose, `OutOfRange` when a posed coordinate leaves `±2^500`, `NotConvex`, `Spike` or
/// `WindsMoreThanOnce` when rounding broke convexity. Its indices are the original's **internal**
/// vertex indices. Rounding that only makes vertices collinear or equal is no error: they are dropped.
/// Never panics.
///
/// # Complexity
/// `O(n + m)` to move and validate the vertices, then [`distance_with`] (`O(log n + log m)` for
/// disjoint polygons).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{Pose, distance_posed, polygon::ConvexPolygon, polygon::Feature};
/// use polydist_convex::polygon::predicates::Robust;
///
/// // The caller gives the square clockwise: internal and caller indices differ.
/// let square = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X])?;
/// let left = Pose { translation: DVec2::new(-3.0, 0.0), rotation: 0.0 };
/// let right = Pose { translation: DVec2::new(3.0, 0.0), rotation: std::f64::consts::FRAC_PI_4 };
/// let s = distance_posed::<Robust>(&square, left, &square, right)?;
/// let c = s.closest().expect("disjoint");
/// assert_eq!(c.feature_p, Feature::Edge(2)); // the caller's edge from (1, 1) to (1, 0)
/// assert_eq!(c.feature_q, Feature::Vertex(1)); // (0, 1), rotated to the left corner of the diamond
/// assert!((c.distance - (5.0 - std::f64::consts::FRAC_1_SQRT_2)).abs() < 1e-12);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
pub fn distance_posed<K: Kernel>(
    p: &ConvexPolygon,
    pose_p: Pose,
    q: &ConvexPolygon,
    pose_q: Pose,
) -> Result<Separation, PolygonError> {
    let (pp, qq) = (posed(p, pose_p)?, posed(q, pose_q)?);
    Ok(match distance_with::<K>(&pp, &qq) {
        Separation::Disjoint(mut c) => {
            c.feature_p = original_feature::<K>(p, pose_p, c.feature_p, c.point_q);
            c.feature_q = original_feature::<K>(q, pose_q, c.feature_q, c.point_p);
            Separation::Disjoint(c)
        }
        Separation::Touching {
            point,
            feature_p,
            feature_q,
        } => Separation::Touching {
            point,
            feature_p: original_feature::<K>(p, pose_p, feature_p, point),
            feature_q: original_feature::<K>(q, pose_q, feature_q, point),
        },
        Separation::Overlapping => Separation::Overlapping,
    })
}
