//! Hausdorff and CMMR distances between filled convex polygons in `O(n + m)`, with exact decisions.
//!
//! Atallah, Ribeiro, Lifschitz, "A linear time algorithm for the computation of some distance functions
//! between convex polygons", RAIRO Oper. Res. 25(4), 1991 (ARL), after Atallah, "A linear time
//! algorithm for the Hausdorff distance between convex polygons", IPL 17, 1983. For filled polygons
//! (a point inside has distance 0) both distances are functions of the per-vertex distances
//! `δ(v) = dist(v, Q)`: the directed Hausdorff distance `h(P, Q)` is the largest `δ` over the vertices of
//! `P` (the distance to a convex set is convex, so its maximum over `P` is at a vertex), the Hausdorff
//! distance is `max(h(P, Q), h(Q, P))`, and the CMMR distance (Cox, Maître, Minoux, Ribeiro 1989) is
//! `Σ_{v ∈ P} δ_Q(v)² + Σ_{w ∈ Q} δ_P(w)²`.
//!
//! # The algorithm
//! One walk per direction finds the nearest feature of every vertex (module `walk`): Atallah's walk
//! (ARL §3) for disjoint polygons, extended through `Q`'s interior for intersecting ones. On
//! intersecting polygons ARL (§4) decompose `(P ∪ Q) − int(P ∩ Q)` into pieces between consecutive
//! boundary crossings and prove (Theorem 1) that the nearest point of a vertex on an external chain lies
//! on the three neighbouring chains of the other polygon; our walk meets the crossings in order (it
//! finds them as the entries into and exits from `Q`, kept symbolically as pairs of edges, every decision
//! an exact predicate) and its pointer stays on exactly those chains. What we reconstructed and changed
//! is written up in `docs/algorithms/hausdorff-cmmr.md`.
//!
//! # Numbers
//! Every decision is the sign of a polynomial in the input coordinates, decided by the kernel
//! (Robust by default); the walk never constructs a projection to decide anything. The Hausdorff argmax
//! is decided by exact comparisons of squared point–feature distances (`K::cmp_dist2`). Each squared
//! distance is computed from its exact feature as the exact value rounded once (module `value`), the
//! distance is its square root (within 1 ulp), and CMMR is a compensated sum (within 1.5 ulps).

mod brute;
mod crossings;
mod pieces;
mod value;
mod walk;

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::{ConvexPolygon, Feature, Location};
use polydist_predicates::{BigRational, Dist2, Exact, Kernel, Robust};

use brute::locate_brute;
pub use crossings::{
    BoundaryCrossing, boundary_crossings, boundary_crossings_brute, boundary_crossings_with,
};
pub use pieces::{PiecesStats, pieces_stats, reset_pieces_stats};
use value::{Term, compensated_sum, exact_squared, term};
use walk::{Crossing, Near, walk};

/// One vertex of `P` and its distance to the filled convex polygon `Q`.
///
/// Indices are the caller's (positions in the slices given to
/// [`ConvexPolygon::try_new`]); vertices dropped by validation (repeats, collinear vertices) have no
/// entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexToPolygon {
    /// The caller's index of the vertex in `P`.
    pub vertex: usize,
    /// The vertex.
    pub point: DVec2,
    /// Where the vertex lies relative to filled `Q`.
    pub location: Location,
    /// The caller's feature of `Q` holding [`Self::projection`]; `None` when the vertex is strictly
    /// inside `Q`.
    pub feature: Option<Feature>,
    /// The point of filled `Q` nearest to the vertex: the vertex itself when it is in `Q`, a vertex of
    /// `Q` exactly, or the foot of the perpendicular on an edge: within 1 ulp per coordinate in the
    /// results of the Hausdorff functions; within `0.5 ulp + 16u·distance` per coordinate (`u = 2⁻⁵³`) in
    /// the bulk per-vertex lists of [`per_vertex_distances_with`] and [`cmmr_with`], where the
    /// 1-ulp construction would cost several exact evaluations per vertex.
    pub projection: DVec2,
    /// The squared distance: the exact value rounded once (within `0.5 + 2⁻⁴⁰` ulp).
    pub squared_distance: f64,
    /// The distance, within 1 ulp.
    pub distance: f64,
}

/// Which directed distance realizes the Hausdorff distance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// `h(P, Q)`: a vertex of `P` is farthest from `Q` (also on exact ties).
    PToQ,
    /// `h(Q, P)`: a vertex of `Q` is strictly farther from `P` than every vertex of `P` from `Q`.
    QToP,
}

/// The Hausdorff distance of two filled convex polygons, with both directed distances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hausdorff {
    /// `max(h(P, Q), h(Q, P))`, within 1 ulp.
    pub distance: f64,
    /// Its square, within `0.5 + 2⁻⁴⁰` ulp.
    pub squared_distance: f64,
    /// Which directed distance is the larger.
    pub direction: Direction,
    /// `h(P, Q)`: the realizing vertex of `P`, its projection and feature on `Q`.
    pub p_to_q: VertexToPolygon,
    /// `h(Q, P)`: the realizing vertex of `Q`, its projection and feature on `P`.
    pub q_to_p: VertexToPolygon,
}

/// The CMMR distance with its per-vertex breakdown.
#[derive(Clone, Debug, PartialEq)]
pub struct Cmmr {
    /// `Σ_{v ∈ P} dist(v, Q)² + Σ_{w ∈ Q} dist(w, P)²`, compensated sum of exactly-featured terms
    /// (within 1.5 ulps).
    pub value: f64,
    /// Every vertex of `P` with its distance to `Q`.
    pub p_to_q: Vec<VertexToPolygon>,
    /// Every vertex of `Q` with its distance to `P`.
    pub q_to_p: Vec<VertexToPolygon>,
}

/// Which algorithm finds the per-vertex features.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum How {
    /// The walk through `Q`'s subdivision (module `walk`).
    Walk,
    /// Every vertex against every edge (module `brute`).
    Brute,
    /// ARL's piece decomposition (module `pieces`).
    Pieces,
}

/// Per-vertex features, by the walk, the brute force or the piece decomposition.
fn features<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, how: How) -> Vec<Near> {
    let (pv, qv) = (p.vertices(), q.vertices());
    match how {
        How::Brute => pv.iter().map(|&v| locate_brute::<K>(qv, v)).collect(),
        How::Walk => {
            let mut crossings: Vec<Crossing> = Vec::new();
            walk::<K>(pv, qv, &mut crossings, false)
        }
        How::Pieces => pieces::features_pieces::<K>(pv, qv),
    }
}

/// The public record of vertex `k` of `p` with feature `near` on `q`.
fn record<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    k: usize,
    near: Near,
    t: Term,
) -> VertexToPolygon {
    let v = p.vertices()[k];
    let on_edge = |i: usize| {
        Some(
            q.caller_feature_on_edge::<K>(i, v)
                .unwrap_or(Feature::Edge(q.source_index(i))),
        )
    };
    let (location, feature) = match near {
        Near::Inside => (Location::Inside, None),
        Near::OnVertex(i) => (Location::Boundary, Some(Feature::Vertex(q.source_index(i)))),
        Near::OnEdge(i) => (Location::Boundary, on_edge(i)),
        Near::Vertex(i) => (Location::Outside, Some(Feature::Vertex(q.source_index(i)))),
        Near::Edge(i) => (Location::Outside, on_edge(i)),
    };
    VertexToPolygon {
        vertex: p.source_index(k),
        point: v,
        location,
        feature,
        projection: t.projection,
        squared_distance: t.squared,
        distance: t.distance,
    }
}

/// The squared distance of `v` to its feature, for exact comparisons.
fn dist2(q: &[DVec2], v: DVec2, near: Near) -> Dist2 {
    match near {
        Near::Inside | Near::OnVertex(_) | Near::OnEdge(_) => Dist2::PointPoint(v, v),
        Near::Vertex(i) => Dist2::PointPoint(v, q[i]),
        Near::Edge(i) => Dist2::PointSegment(v, q[i], q[if i + 1 == q.len() { 0 } else { i + 1 }]),
    }
}

/// An enclosure `[lo, hi]` of the exact squared distance of `v` to its feature, in plain `f64` with a
/// rigorous error bound (a static filter, as in the Robust kernel's predicates): it only discards
/// vertices that are certainly not the argmax; the remaining ones are compared exactly.
fn enclosure(q: &[DVec2], v: DVec2, near: Near) -> (f64, f64) {
    const U: f64 = f64::EPSILON / 2.0;
    // Slack for underflow of the products (each loses at most 2^-1074).
    const TINY: f64 = 1e-300;
    let (lo, hi) = match near {
        Near::Inside | Near::OnVertex(_) | Near::OnEdge(_) => (0.0, 0.0),
        Near::Vertex(i) => {
            // fl(dx² + dy²) = S(1 + θ), |θ| ≤ 4u + O(u²): every term is positive.
            let d = v - q[i];
            let s = d.x * d.x + d.y * d.y;
            (s * (1.0 - 8.0 * U) - TINY, s * (1.0 + 8.0 * U) + TINY)
        }
        Near::Edge(i) => {
            // S = c²/L with c = (b − a) × (v − a), L = |b − a|²: |fl(c) − c| ≤ (3u + O(u²))(|t1| + |t2|),
            // fl(L) = L(1 + θ) with |θ| ≤ 4u + O(u²); the bounds' own roundings are in the 16u.
            let (a, b) = (q[i], q[if i + 1 == q.len() { 0 } else { i + 1 }]);
            let (e, w) = (b - a, v - a);
            let (t1, t2) = (e.x * w.y, e.y * w.x);
            let c = (t1 - t2).abs();
            let err = 8.0 * U * (t1.abs() + t2.abs()) + TINY;
            let l = e.x * e.x + e.y * e.y;
            let (cl, ch) = ((c - err).max(0.0), c + err);
            // (c/L)·c rather than c²/L: the degree-4 intermediate would underflow or overflow at
            // extreme scales.
            (
                (cl / l * cl) * (1.0 - 16.0 * U),
                (ch / l * ch) * (1.0 + 16.0 * U) + TINY,
            )
        }
    };
    if lo.is_finite() && hi.is_finite() {
        (lo.max(0.0), hi)
    } else {
        (0.0, f64::INFINITY)
    }
}

/// The exact argmax of the per-vertex distances (the lowest index among exact ties): a filter keeps
/// the vertices whose enclosure reaches the largest lower bound (the argmax is always among them),
/// then exact comparisons `K::cmp_dist2` decide among those.
fn argmax<K: Kernel>(p: &[DVec2], q: &[DVec2], near: &[Near]) -> usize {
    let boxes: Vec<(f64, f64)> = near
        .iter()
        .zip(p)
        .map(|(&f, &v)| enclosure(q, v, f))
        .collect();
    let floor = boxes.iter().fold(0.0f64, |m, b| m.max(b.0));
    let mut best: Option<usize> = None;
    for (k, b) in boxes.iter().enumerate() {
        if b.1 < floor {
            continue; // certainly below the maximum
        }
        best = Some(match best {
            None => k,
            Some(j) => {
                if K::cmp_dist2(dist2(q, p[k], near[k]), dist2(q, p[j], near[j]))
                    == Ordering::Greater
                {
                    k
                } else {
                    j
                }
            }
        });
    }
    best.unwrap_or(0)
}

/// The directed Hausdorff winner: its internal index and feature.
fn directed_core<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, how: How) -> (usize, Near) {
    let near = features::<K>(p, q, how);
    let k = argmax::<K>(p.vertices(), q.vertices(), &near);
    (k, near[k])
}

fn directed_impl<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, how: How) -> VertexToPolygon {
    let (k, near) = directed_core::<K>(p, q, how);
    record::<K>(
        p,
        q,
        k,
        near,
        term(q.vertices(), p.vertices()[k], near, true),
    )
}

/// Both directions and the larger one.
fn hausdorff_core<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    how: How,
) -> (Direction, (usize, Near), (usize, Near)) {
    let a = directed_core::<K>(p, q, how);
    let b = directed_core::<K>(q, p, how);
    let da = dist2(q.vertices(), p.vertices()[a.0], a.1);
    let db = dist2(p.vertices(), q.vertices()[b.0], b.1);
    let dir = if K::cmp_dist2(db, da) == Ordering::Greater {
        Direction::QToP
    } else {
        Direction::PToQ
    };
    (dir, a, b)
}

fn hausdorff_impl<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, how: How) -> Hausdorff {
    let (direction, (ka, na), (kb, nb)) = hausdorff_core::<K>(p, q, how);
    let p_to_q = record::<K>(p, q, ka, na, term(q.vertices(), p.vertices()[ka], na, true));
    let q_to_p = record::<K>(q, p, kb, nb, term(p.vertices(), q.vertices()[kb], nb, true));
    let win = match direction {
        Direction::PToQ => &p_to_q,
        Direction::QToP => &q_to_p,
    };
    Hausdorff {
        distance: win.distance,
        squared_distance: win.squared_distance,
        direction,
        p_to_q,
        q_to_p,
    }
}

fn per_vertex_impl<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    how: How,
) -> (Vec<VertexToPolygon>, Vec<(f64, f64)>) {
    let near = features::<K>(p, q, how);
    let (pv, qv) = (p.vertices(), q.vertices());
    let mut parts = Vec::with_capacity(near.len());
    let rows = near
        .iter()
        .enumerate()
        .map(|(k, &f)| {
            let t = term(qv, pv[k], f, false);
            parts.push((t.hi, t.lo));
            record::<K>(p, q, k, f, t)
        })
        .collect();
    (rows, parts)
}

fn cmmr_impl<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon, how: How) -> Cmmr {
    let (p_to_q, a) = per_vertex_impl::<K>(p, q, how);
    let (q_to_p, b) = per_vertex_impl::<K>(q, p, how);
    Cmmr {
        value: compensated_sum(a.into_iter().chain(b)),
        p_to_q,
        q_to_p,
    }
}

/// Every vertex of `P` with its distance, projection and nearest feature on the filled convex polygon
/// `Q`, under the kernel `K`: the inner step of the CMMR matching loop (ARL §3–4).
///
/// Points and segments are polygons too (a segment's edge is `Edge(0)`). A vertex in `Q` (inside or on
/// the boundary) has distance 0 and is its own projection.
///
/// # Complexity
/// `O(n + m)` exact predicates: Atallah's walk (Lemma 3: the projection sequence changes direction at
/// most twice) extended through `Q`'s interior for intersecting polygons; plus one `O(m)` location of
/// the first vertex. Under the Fast kernel the walk stops after `10(n + m) + 16` steps and the brute
/// force answers the rest (never reached under exact decisions on any test input).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::polygon::{ConvexPolygon, Feature, Location, predicates::Robust};
/// use polydist_convex::per_vertex_distances_with;
///
/// let p = ConvexPolygon::try_new(&[DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(4.0, 3.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, -1.0), DVec2::new(6.0, -1.0), DVec2::new(6.0, 1.0), DVec2::new(3.0, 1.0)])?;
/// let d = per_vertex_distances_with::<Robust>(&p, &q);
/// assert_eq!(d[0].distance, 3.0);
/// assert_eq!(d[0].feature, Some(Feature::Edge(3)));
/// assert_eq!(d[0].projection, DVec2::new(3.0, 0.0));
/// assert_eq!(d[1].location, Location::Inside);
/// assert_eq!(d[2].distance, 2.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, IPL 17 (1983); Atallah, Ribeiro, Lifschitz, RAIRO Oper. Res. 25(4) (1991), §3–4.
#[must_use]
pub fn per_vertex_distances_with<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> Vec<VertexToPolygon> {
    per_vertex_impl::<K>(p, q, How::Walk).0
}

/// [`per_vertex_distances_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{per_vertex_distances, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::new(5.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])?;
/// assert_eq!(per_vertex_distances(&p, &q)[0].distance, 4.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`per_vertex_distances_with`].
#[must_use]
pub fn per_vertex_distances(p: &ConvexPolygon, q: &ConvexPolygon) -> Vec<VertexToPolygon> {
    per_vertex_distances_with::<Robust>(p, q)
}

/// The directed Hausdorff distance `h(P, Q) = max_{x ∈ P} dist(x, Q)` of filled convex polygons under
/// the kernel `K`: the realizing vertex of `P` (an exact argmax, the lowest internal index among exact
/// ties), its distance, projection and feature on `Q`.
///
/// # Complexity
/// `O(n + m)` exact predicates (the walk of [`per_vertex_distances_with`], then `n − 1` exact
/// comparisons `K::cmp_dist2`).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{directed_hausdorff_with, polygon::ConvexPolygon, polygon::Feature, polygon::predicates::Exact};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, 0.0), DVec2::new(5.0, 0.0), DVec2::new(5.0, 2.0), DVec2::new(3.0, 2.0)])?;
/// let h = directed_hausdorff_with::<Exact>(&p, &q);
/// assert_eq!((h.vertex, h.distance, h.feature), (0, 3.0, Some(Feature::Vertex(0))));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, IPL 17 (1983); ARL (1991), §2 (`D_H` as a maximum of vertex distances).
#[must_use]
pub fn directed_hausdorff_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> VertexToPolygon {
    directed_impl::<K>(p, q, How::Walk)
}

/// [`directed_hausdorff_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{directed_hausdorff, polygon::ConvexPolygon};
///
/// let small = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::Y])?;
/// let big = ConvexPolygon::try_new(&[DVec2::new(-1.0, -1.0), DVec2::new(3.0, -1.0), DVec2::new(-1.0, 3.0)])?;
/// assert_eq!(directed_hausdorff(&small, &big).distance, 0.0); // nested
/// assert_eq!(directed_hausdorff(&big, &small).distance, 5.0f64.sqrt()); // (3, −1) to (1, 0)
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`directed_hausdorff_with`].
#[must_use]
pub fn directed_hausdorff(p: &ConvexPolygon, q: &ConvexPolygon) -> VertexToPolygon {
    directed_hausdorff_with::<Robust>(p, q)
}

/// The Hausdorff distance `max(h(P, Q), h(Q, P))` of filled convex polygons under the kernel `K`, with
/// both directed distances and which one is larger (decided exactly; `P → Q` on ties).
///
/// # Complexity
/// `O(n + m)` exact predicates (two walks).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{Direction, hausdorff_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, 0.0), DVec2::new(5.0, 0.0), DVec2::new(5.0, 2.0), DVec2::new(3.0, 2.0)])?;
/// let h = hausdorff_with::<Robust>(&p, &q);
/// assert_eq!((h.distance, h.direction), (3.0, Direction::PToQ));
/// assert_eq!(h.q_to_p.vertex, 1);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, IPL 17 (1983); ARL (1991), §2–4.
#[must_use]
pub fn hausdorff_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Hausdorff {
    hausdorff_impl::<K>(p, q, How::Walk)
}

/// [`hausdorff_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 4.0)])?;
/// assert_eq!(hausdorff(&p, &p).distance, 0.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`hausdorff_with`].
#[must_use]
pub fn hausdorff(p: &ConvexPolygon, q: &ConvexPolygon) -> Hausdorff {
    hausdorff_with::<Robust>(p, q)
}

/// The CMMR distance of Cox, Maître, Minoux, Ribeiro (1989) under the kernel `K`: the sum over the
/// vertices of each filled convex polygon of the squared distance to the other one, with the per-vertex
/// breakdown. Vertices are those of the validated polygons (see [`ConvexPolygon::try_new`]).
///
/// # Complexity
/// `O(n + m)` exact predicates (two walks) and `O(n + m)` accurate constructions.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(3.0, 0.0), DVec2::new(5.0, 0.0), DVec2::new(5.0, 2.0), DVec2::new(3.0, 2.0)])?;
/// let c = cmmr_with::<Robust>(&p, &q);
/// assert_eq!(c.value, 40.0); // (9 + 1 + 1 + 9) twice
/// assert_eq!(c.p_to_q[1].squared_distance, 1.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §2 (definition), §3 (disjoint), §4 (intersecting); P. Cox, H. Maître, M. Minoux,
/// C. C. Ribeiro, "Optimal matching of convex polygons", Pattern Recognition Letters 9 (1989).
#[must_use]
pub fn cmmr_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Cmmr {
    cmmr_impl::<K>(p, q, How::Walk)
}

/// [`cmmr_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)])?;
/// assert_eq!(cmmr(&p, &p).value, 0.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`cmmr_with`].
#[must_use]
pub fn cmmr(p: &ConvexPolygon, q: &ConvexPolygon) -> Cmmr {
    cmmr_with::<Robust>(p, q)
}

/// The CMMR distance alone, under the kernel `K`: the value of [`cmmr_with`] (the same terms summed in
/// the same order, so the same `f64`) without building the per-vertex records (at a million vertices
/// per polygon those are 160 MB per call).
///
/// # Complexity
/// `O(n + m)` exact predicates and accurate constructions, `O(n + m)` words of memory.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr_value_with, cmmr_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(1.0, 1.0), DVec2::new(5.0, 1.0), DVec2::new(5.0, 3.0)])?;
/// assert_eq!(cmmr_value_with::<Robust>(&p, &q), cmmr_with::<Robust>(&p, &q).value);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`cmmr_with`].
#[must_use]
pub fn cmmr_value_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let a = features::<K>(p, q, How::Walk);
    let b = features::<K>(q, p, How::Walk);
    compensated_sum(
        value_parts(a, p.vertices(), q.vertices()).chain(value_parts(
            b,
            q.vertices(),
            p.vertices(),
        )),
    )
}

/// The `(hi, lo)` parts of the terms of `from`'s vertices with features `near` on `to`.
fn value_parts<'a>(
    near: Vec<Near>,
    from: &'a [DVec2],
    to: &'a [DVec2],
) -> impl Iterator<Item = (f64, f64)> + 'a {
    near.into_iter().enumerate().map(move |(k, f)| {
        let t = term(to, from[k], f, false);
        (t.hi, t.lo)
    })
}

/// [`cmmr_value_with`] under the default [`Robust`] kernel.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr_value, polygon::ConvexPolygon};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(3.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(0.0, 4.0)])?;
/// assert_eq!(cmmr_value(&p, &q), 16.0 + 25.0 + 16.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`cmmr_with`].
#[must_use]
pub fn cmmr_value(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    cmmr_value_with::<Robust>(p, q)
}

/// The squared Hausdorff distance as an exact rational: the features chosen under the [`Exact`]
/// kernel, the squared distance of the winning vertex–feature pair computed without rounding
/// (`polydist_predicates::exact`).
///
/// # Complexity
/// `O(n + m)` exact predicates and one rational evaluation.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff_squared_exact, polygon::ConvexPolygon, polygon::predicates::BigRational};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(0.0, 3.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(0.0, -1.0)])?;
/// // The vertex of P farthest from the point is (0, 3): squared distance 16; the point is 1 below P.
/// assert_eq!(hausdorff_squared_exact(&p, &q), BigRational::from_integer(16.into()));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// See [`hausdorff_with`].
#[must_use]
pub fn hausdorff_squared_exact(p: &ConvexPolygon, q: &ConvexPolygon) -> BigRational {
    let (direction, (ka, na), (kb, nb)) = hausdorff_core::<Exact>(p, q, How::Walk);
    match direction {
        Direction::PToQ => exact_squared(q.vertices(), p.vertices()[ka], na),
        Direction::QToP => exact_squared(p.vertices(), q.vertices()[kb], nb),
    }
}

/// The brute-force twin of [`per_vertex_distances_with`], for testing and as a baseline: every vertex
/// against every edge of `Q` (inside test by all edge orientations, nearest edge by exact comparisons
/// `K::cmp_dist2`), the same numbers.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{per_vertex_distances_brute, per_vertex_distances_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 1.0), DVec2::new(1.0, 5.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, 2.0), DVec2::new(7.0, 2.0), DVec2::new(3.0, 6.0)])?;
/// assert_eq!(per_vertex_distances_brute::<Robust>(&p, &q), per_vertex_distances_with::<Robust>(&p, &q));
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §1 (the trivial `O(n₁n₂)` algorithm).
#[must_use]
pub fn per_vertex_distances_brute<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> Vec<VertexToPolygon> {
    per_vertex_impl::<K>(p, q, How::Brute).0
}

/// The brute-force twin of [`directed_hausdorff_with`] (same tie rule), for testing.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{directed_hausdorff_brute, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(3.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(0.0, 4.0)])?;
/// assert_eq!(directed_hausdorff_brute::<Robust>(&p, &q).distance, 5.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §1.
#[must_use]
pub fn directed_hausdorff_brute<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> VertexToPolygon {
    directed_impl::<K>(p, q, How::Brute)
}

/// The brute-force twin of [`hausdorff_with`] (same tie rules), for testing.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff_brute, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(3.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(0.0, 4.0)])?;
/// assert_eq!(hausdorff_brute::<Robust>(&p, &q).distance, 5.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §1.
#[must_use]
pub fn hausdorff_brute<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Hausdorff {
    hausdorff_impl::<K>(p, q, How::Brute)
}

/// The brute-force twin of [`cmmr_with`] (same numbers), for testing.
///
/// # Complexity
/// `Θ(n·m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr_brute, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(3.0, 0.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(0.0, 4.0)])?;
/// assert_eq!(cmmr_brute::<Robust>(&p, &q).value, 16.0 + 25.0 + 16.0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §1.
#[must_use]
pub fn cmmr_brute<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Cmmr {
    cmmr_impl::<K>(p, q, How::Brute)
}

/// How many walks on this thread ran out of their step budget and let the brute force finish (since
/// the last [`reset_walk_fallbacks`]): always 0 under exact decisions on every input we test; the
/// budget exists so the Fast kernel terminates.
///
/// # Complexity
/// `O(1)`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff, polygon::ConvexPolygon, reset_walk_fallbacks, walk_fallbacks};
///
/// reset_walk_fallbacks();
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::Y])?;
/// let _ = hausdorff(&p, &p);
/// assert_eq!(walk_fallbacks(), 0);
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Ours (the step budget of the walk, module docs).
#[must_use]
pub fn walk_fallbacks() -> u64 {
    walk::last_run().1
}

/// Sets this thread's [`walk_fallbacks`] counter to zero.
///
/// # Complexity
/// `O(1)`.
///
/// # Examples
/// See [`walk_fallbacks`].
///
/// # References
/// Ours.
pub fn reset_walk_fallbacks() {
    walk::reset_fallbacks();
}

/// [`per_vertex_distances_with`] by ARL's piece decomposition, under the kernel `K`: the same records
/// (features, numbers, caller indices), computed as Atallah, Ribeiro and Lifschitz compute them for
/// intersecting polygons.
///
/// The symbolic crossings of `∂P` with `∂Q` ([`boundary_crossings_with`]) split
/// `(P ∪ Q) − int(P ∩ Q)` into pieces. A vertex of an internal chain of `P` (in `Q`) has distance 0; one
/// merge of edge directions per chain finds those on `∂Q`. For a vertex of an external chain `A_k`,
/// Theorem 1 puts its nearest point on the internal chain `C_k` of `Q` or on the neighbouring external
/// chains `B_{k−1}`, `B_{k+1}`; one pointer walks the features of that arc with Atallah's direction test,
/// and the minimum of ARL's three distances is decided by the certified outer-Voronoi-region test of
/// `Q` (no distance to a crossing point is ever compared; every predicate is of degree 2 on input
/// points). When the boundaries do not cross (disjoint, nested, identical, touching) and for points and
/// segments, the walk of [`per_vertex_distances_with`] answers. What we reconstructed (Figure 3 is
/// missing) is in `docs/algorithms/hausdorff-cmmr.md`.
///
/// # Complexity
/// `O(n + m)` exact predicates: the crossings by one walk around `∂P`, then per piece
/// `O(|A_k| + |B_{k−1}| + |C_k| + |B_{k+1}|)` (ARL Theorem 2). Every loop is bounded by counts; on
/// budget exhaustion (inconsistent signs, e.g. the Fast kernel) the brute force answers the rest and
/// [`pieces_stats`] counts it.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::polygon::{ConvexPolygon, predicates::Robust};
/// use polydist_convex::{per_vertex_distances_pieces_with, per_vertex_distances_with};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, -1.0), DVec2::new(5.0, 2.0), DVec2::new(2.0, 5.0), DVec2::new(-1.0, 2.0)])?;
/// let d = per_vertex_distances_pieces_with::<Robust>(&p, &q);
/// assert_eq!(d, per_vertex_distances_with::<Robust>(&p, &q));
/// assert_eq!(d[0].squared_distance, 0.5); // (0, 0) to the edge from (−1, 2) to (2, −1)
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// Atallah, Ribeiro, Lifschitz, RAIRO Oper. Res. 25(4) (1991), §4 (piece decomposition, Theorems 1
/// and 2); Atallah, IPL 17 (1983) (the walk on each piece).
#[must_use]
pub fn per_vertex_distances_pieces_with<K: Kernel>(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
) -> Vec<VertexToPolygon> {
    per_vertex_impl::<K>(p, q, How::Pieces).0
}

/// [`hausdorff_with`] by ARL's piece decomposition ([`per_vertex_distances_pieces_with`] both ways,
/// then the same exact argmax and tie rules): the same result.
///
/// # Complexity
/// `O(n + m)` exact predicates.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{hausdorff_pieces_with, hausdorff_with, polygon::ConvexPolygon, polygon::predicates::Exact};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, 1.0), DVec2::new(6.0, 1.0), DVec2::new(6.0, 3.0), DVec2::new(2.0, 3.0)])?;
/// let h = hausdorff_pieces_with::<Exact>(&p, &q);
/// assert_eq!(h, hausdorff_with::<Exact>(&p, &q));
/// assert_eq!(h.distance, 5.0f64.sqrt()); // (0, 0) to (2, 1)
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §2 (`D_H`), §4 (Theorem 1).
#[must_use]
pub fn hausdorff_pieces_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Hausdorff {
    hausdorff_impl::<K>(p, q, How::Pieces)
}

/// [`cmmr_with`] by ARL's piece decomposition ([`per_vertex_distances_pieces_with`] both ways, the
/// same terms and compensated sum): the same result.
///
/// # Complexity
/// `O(n + m)` exact predicates and accurate constructions.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_convex::{cmmr_pieces_with, cmmr_with, polygon::ConvexPolygon, polygon::predicates::Robust};
///
/// let p = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(4.0, 4.0), DVec2::new(0.0, 4.0)])?;
/// let q = ConvexPolygon::try_new(&[DVec2::new(2.0, 1.0), DVec2::new(6.0, 1.0), DVec2::new(6.0, 3.0), DVec2::new(2.0, 3.0)])?;
/// let c = cmmr_pieces_with::<Robust>(&p, &q);
/// assert_eq!(c, cmmr_with::<Robust>(&p, &q));
/// assert_eq!(c.value, 5.0 + 1.0 + 1.0 + 5.0 + 4.0 + 4.0); // P: (0, 0), (4, 0), (4, 4), (0, 4); Q: (6, 1), (6, 3)
/// # Ok::<(), polydist_convex::polygon::PolygonError>(())
/// ```
///
/// # References
/// ARL (1991), §2 (definition), §4 (the algorithm for intersecting polygons).
#[must_use]
pub fn cmmr_pieces_with<K: Kernel>(p: &ConvexPolygon, q: &ConvexPolygon) -> Cmmr {
    cmmr_impl::<K>(p, q, How::Pieces)
}
