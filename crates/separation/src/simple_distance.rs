//! Point–simple-polygon and segment–simple-polygon distances in `O(n)`.
//!
//! A point or a segment against a simple polygon with `n` edges: every edge is a candidate, and
//! `Ω(n)` time is needed in the worst case (any edge can be the nearest), so the linear scan is
//! optimal here; what matters is that every comparison is exact. Candidates are compared with
//! [`Kernel::cmp_dist2`] (squared distances of a point to a point or to a closed segment, degree 2 to
//! 6, decided exactly), never by rounded distances; ties keep the first candidate in scan order.
//! The distance is then constructed once from the chosen features (see the crate docs for the bound).

use core::cmp::Ordering;

use glam::DVec2;
use polydist_polygon::predicates::{Dist2, Kernel, Orientation, Sign, is_valid_coordinate};
use polydist_polygon::{Feature, Location, SimplePolygon};

use crate::construct::{vertex_edge, vertex_vertex};
use crate::error::{Chain, SeparationError};
use crate::polygon::{BoundaryPiece, Intersection, PolygonSeparation, Route};
use crate::result::{ClosestPair, SeparationStats};

/// The nearest point of a polygon's boundary to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundaryPoint {
    /// The distance from the query point to the boundary (`0` on the boundary).
    pub distance: f64,
    /// The squared distance.
    pub squared_distance: f64,
    /// The nearest point of the boundary: a vertex exactly, or the foot of a perpendicular.
    pub point: DVec2,
    /// The caller's feature of the polygon containing `point`.
    pub feature: Feature,
}

/// Where a point lies relative to a simple polygon and how far its boundary is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointToPolygon {
    /// Inside, on the boundary, or outside the closed polygon (exact).
    pub location: Location,
    /// The nearest boundary point. The distance from the point to the polygon as a region is
    /// `boundary.distance` when `location` is `Outside`, and `0` otherwise.
    pub boundary: BoundaryPoint,
}

impl PointToPolygon {
    /// The distance to the closed polygon as a region: `0` inside or on the boundary.
    #[must_use]
    pub fn distance(&self) -> f64 {
        if self.location == Location::Outside {
            self.boundary.distance
        } else {
            0.0
        }
    }
}

/// The distance from the point `x` to the simple polygon `p`: where `x` lies, and the nearest point of
/// the boundary with its caller feature.
///
/// # Errors
/// [`SeparationError::InvalidCoordinate`] (chain `P`, index 0) when `x` is not finite or out of range.
///
/// # Complexity
/// `O(n)`: one exact comparison per edge and one point location.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{Feature, Location, SimplePolygon, predicates::Robust};
/// use polydist_separation::point_to_polygon;
///
/// let l = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
/// let l = SimplePolygon::try_from(&l[..])?;
/// let d = point_to_polygon::<Robust>(DVec2::new(1.5, 1.5), &l).unwrap();
/// assert_eq!(d.location, Location::Outside);
/// // The edges y = 1 (edge 2) and x = 1 (edge 3) are both 0.5 away; the first in scan order wins.
/// assert_eq!(d.boundary.feature, Feature::Edge(2));
/// assert_eq!(d.distance(), 0.5);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn point_to_polygon<K: Kernel>(
    x: DVec2,
    p: &SimplePolygon,
) -> Result<PointToPolygon, SeparationError> {
    if !is_valid_coordinate(x.x) || !is_valid_coordinate(x.y) {
        return Err(SeparationError::InvalidCoordinate {
            chain: Chain::P,
            index: 0,
        });
    }
    let v = p.vertices();
    let n = v.len();
    let seg = |e: usize| Dist2::PointSegment(x, v[e], v[(e + 1) % n]);
    let mut best = 0;
    for e in 1..n {
        if K::cmp_dist2(seg(e), seg(best)) == Ordering::Less {
            best = e;
        }
    }
    let (a, b) = (v[best], v[(best + 1) % n]);
    let boundary = match foot::<K>(x, a, b) {
        Foot::Start => vertex_point(x, a, Feature::Vertex(p.source_index(best))),
        Foot::End => vertex_point(x, b, Feature::Vertex(p.source_index((best + 1) % n))),
        Foot::Inside => {
            let (squared_distance, distance, point) = vertex_edge(x, a, b);
            BoundaryPoint {
                distance,
                squared_distance,
                point,
                feature: p
                    .caller_feature_on_edge::<K>(best, x)
                    .unwrap_or(Feature::Edge(p.source_index(best))),
            }
        }
    };
    Ok(PointToPolygon {
        location: p.locate_with::<K>(x),
        boundary,
    })
}

/// The boundary point `v` (a vertex) for the query `x`.
fn vertex_point(x: DVec2, v: DVec2, feature: Feature) -> BoundaryPoint {
    let pair = vertex_vertex(x, v, Feature::Vertex(0), feature);
    BoundaryPoint {
        distance: pair.distance,
        squared_distance: pair.squared_distance,
        point: v,
        feature,
    }
}

/// Where the nearest point of the closed segment `[a, b]` to `x` is.
enum Foot {
    Start,
    End,
    Inside,
}

/// Two exact dot signs: `(x − a)·(b − a) ≤ 0` → `a`; `(x − b)·(a − b) ≤ 0` → `b`; else the foot.
fn foot<K: Kernel>(x: DVec2, a: DVec2, b: DVec2) -> Foot {
    if K::dot_sign(a, x, a, b) != Sign::Positive {
        Foot::Start
    } else if K::dot_sign(b, x, b, a) != Sign::Positive {
        Foot::End
    } else {
        Foot::Inside
    }
}

/// Whether the closed segments `[a, b]` and `[c, d]` share a point (exact under `K`).
fn segments_meet<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let (o1, o2) = (K::orient(a, b, c), K::orient(a, b, d));
    let (o3, o4) = (K::orient(c, d, a), K::orient(c, d, b));
    let on = |p: DVec2, s: DVec2, t: DVec2| {
        // p collinear with s, t: on the closed segment iff (p − s)·(p − t) ≤ 0.
        K::dot_sign(p, s, p, t) != Sign::Positive
    };
    let straddle = |u: Orientation, w: Orientation| {
        matches!(
            (u, w),
            (Orientation::CounterClockwise, Orientation::Clockwise)
                | (Orientation::Clockwise, Orientation::CounterClockwise)
        )
    };
    if straddle(o1, o2) && straddle(o3, o4) {
        return true;
    }
    (o1 == Orientation::Collinear && on(c, a, b))
        || (o2 == Orientation::Collinear && on(d, a, b))
        || (o3 == Orientation::Collinear && on(a, c, d))
        || (o4 == Orientation::Collinear && on(b, c, d))
}

/// The distance between the closed segment `[a, b]` (chain `P`: `Vertex(0) = a`, `Vertex(1) = b`,
/// `Edge(0)`) and the simple polygon `q` (chain `Q`, caller features), or how they meet: the segment
/// meets the boundary ([`Intersection::Boundaries`], with the segment's piece `0 → 1`), or lies inside
/// the polygon ([`Intersection::Contained`] with `inner = P`). `a == b` is a point.
///
/// # Errors
/// [`SeparationError::InvalidCoordinate`] (chain `P`) for a non-finite or out-of-range end.
///
/// # Complexity
/// `O(n)`: per edge one exact segment test and three exact comparisons, then one point location.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{Feature, SimplePolygon, predicates::Robust};
/// use polydist_separation::{PolygonSeparation, segment_to_polygon};
///
/// let sq = SimplePolygon::try_from(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][..])?;
/// let s = segment_to_polygon::<Robust>(DVec2::new(3.0, -1.0), DVec2::new(3.0, 2.0), &sq).unwrap();
/// let PolygonSeparation::Separated { pair, .. } = s else { panic!("disjoint") };
/// assert_eq!(pair.distance, 2.0);
/// assert_eq!(pair.feature_p, Feature::Edge(0)); // the segment's interior, against the edge x = 1
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
pub fn segment_to_polygon<K: Kernel>(
    a: DVec2,
    b: DVec2,
    q: &SimplePolygon,
) -> Result<PolygonSeparation, SeparationError> {
    for (index, z) in [a, b].into_iter().enumerate() {
        if !is_valid_coordinate(z.x) || !is_valid_coordinate(z.y) {
            return Err(SeparationError::InvalidCoordinate {
                chain: Chain::P,
                index,
            });
        }
    }
    let v = q.vertices();
    let n = v.len();
    let seg_piece = BoundaryPiece { from: 0, to: 1 };
    for e in 0..n {
        if segments_meet::<K>(a, b, v[e], v[(e + 1) % n]) {
            return Ok(PolygonSeparation::Intersecting(Intersection::Boundaries {
                p: seg_piece,
                q: BoundaryPiece {
                    from: q.source_index(e),
                    to: q.source_index((e + 1) % n),
                },
            }));
        }
    }
    if q.locate_with::<K>(a) != Location::Outside {
        return Ok(PolygonSeparation::Intersecting(Intersection::Contained {
            inner: Chain::P,
            vertex: 0,
        }));
    }
    #[derive(Clone, Copy)]
    enum Cand {
        /// Segment end `k` against polygon edge `e`.
        End(usize, usize),
        /// Polygon vertex `j` against the segment.
        Vertex(usize),
    }
    let ends = [a, b];
    let dist = |c: Cand| match c {
        Cand::End(k, e) => Dist2::PointSegment(ends[k], v[e], v[(e + 1) % n]),
        Cand::Vertex(j) => Dist2::PointSegment(v[j], a, b),
    };
    let mut best = Cand::End(0, 0);
    let candidates = (0..n)
        .flat_map(|e| [Cand::End(0, e), Cand::End(1, e)])
        .chain((0..n).map(Cand::Vertex));
    for c in candidates {
        if K::cmp_dist2(dist(c), dist(best)) == Ordering::Less {
            best = c;
        }
    }
    let pair = match best {
        Cand::End(k, e) => {
            let (s, t) = (v[e], v[(e + 1) % n]);
            let fp = Feature::Vertex(k);
            match foot::<K>(ends[k], s, t) {
                Foot::Start => vertex_vertex(ends[k], s, fp, Feature::Vertex(q.source_index(e))),
                Foot::End => {
                    vertex_vertex(ends[k], t, fp, Feature::Vertex(q.source_index((e + 1) % n)))
                }
                Foot::Inside => {
                    let (squared_distance, distance, foot) = vertex_edge(ends[k], s, t);
                    ClosestPair {
                        distance,
                        squared_distance,
                        point_p: ends[k],
                        point_q: foot,
                        feature_p: fp,
                        feature_q: q
                            .caller_feature_on_edge::<K>(e, ends[k])
                            .unwrap_or(Feature::Edge(q.source_index(e))),
                    }
                }
            }
        }
        Cand::Vertex(j) => {
            let fq = Feature::Vertex(q.source_index(j));
            match foot::<K>(v[j], a, b) {
                Foot::Start => vertex_vertex(a, v[j], Feature::Vertex(0), fq),
                Foot::End => vertex_vertex(b, v[j], Feature::Vertex(1), fq),
                Foot::Inside => {
                    let (squared_distance, distance, foot) = vertex_edge(v[j], a, b);
                    ClosestPair {
                        distance,
                        squared_distance,
                        point_p: foot,
                        point_q: v[j],
                        feature_p: Feature::Edge(0),
                        feature_q: fq,
                    }
                }
            }
        }
    };
    Ok(PolygonSeparation::Separated {
        pair,
        route: Route::Scan,
        stats: SeparationStats::default(),
    })
}
