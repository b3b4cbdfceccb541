//! Convex polygons: validation of a caller's ring, and point location in `O(log n)`.
//!
//! # What counts as convex
//! A ring is accepted when, after exact repeats and straight vertices (collinear and strictly between
//! their neighbours) are dropped, it is a point, a segment, or a polygon whose turns are all strict and
//! of one sign and whose boundary winds exactly once around. Either orientation is accepted; the
//! result is counter-clockwise.
//!
//! - One distinct vertex is a point; two are a segment.
//! - All vertices collinear: the ring is a segment when it goes from one extreme point to the other and
//!   back, turning back (180°) only at the two extremes: `[A, B, C]` with `B` between `A` and `C` is
//!   the segment `AC`, `B` dropped. A ring that turns back anywhere else is a [`PolygonError::Spike`].
//! - Otherwise a 180° turn anywhere is a [`PolygonError::Spike`], never silently removed.
//!
//! # Why one winding is checked by counting direction changes
//! Let the ring `w_0 … w_{k−1}` have only strict left turns (right turns are the mirror image). The edge
//! directions `d_i = w_{i+1} − w_i` are nonzero and the counter-clockwise angle from `d_i` to `d_{i+1}`
//! lies in `(0, π)` (strict, and not a reversal). These angles sum to the total turning, a positive
//! multiple `2πT` of `2π` because the ring closes; `T` is the winding (`T = 2` for a pentagram), and
//! the ring bounds a convex polygon exactly when `T = 1`.
//!
//! Call an edge *forward* when its end is lexicographically greater than its start, i.e. its direction
//! is in the half-open half-circle `H = (−π/2, π/2]`. As the direction turns counter-clockwise through
//! `2πT`, it leaves `H` (passing `π/2`) `T` times and re-enters it (passing `3π/2`) `T` times. One step
//! turns by less than `π`, the distance between the two boundaries of `H`, so it passes at most one of
//! them: the number of indices `i` where edges `i` and `i + 1` differ in being forward is exactly `2T`.
//! Being forward is decided by comparing input coordinates, so the count is exact. Every ring with
//! strict same-sign turns has `T ≥ 1`, hence at least two changes.
//!
//! # Point location
//! The vertices are angularly sorted around vertex 0. A binary search with `orient(v_0, v_i, p)` finds
//! the fan triangle `v_0 v_i v_{i+1}` whose wedge contains `p`, then one more orientation against the
//! edge `v_i v_{i+1}` decides the answer: `O(log n)` exact predicates (Preparata & Shamos 1985, §2.2.1).

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust, Sign};

use crate::ring::{self, Dedup, Turn, lex_cmp};
use crate::source_map::SourceMap;
use crate::{Feature, Location, PolygonError, Segment};

/// A validated convex polygon, stored counter-clockwise: a point, a segment, or a strictly convex polygon.
///
/// Built by [`ConvexPolygon::try_new`] from the caller's vertices (either orientation, with repeats
/// and straight vertices allowed), by the hulls [`SimplePolygon::convex_hull`](crate::SimplePolygon::convex_hull)
/// and [`convex_hull`](crate::convex_hull), or by deserialization (which validates).
///
/// # Invariants
/// - 1 vertex (a point), 2 distinct vertices (a segment), or at least 3 vertices with every turn
///   strictly counter-clockwise and the boundary winding once;
/// - every coordinate finite, with magnitude at most [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE);
/// - a map from its vertices and edges back to the caller's (see [`Self::source_index`]).
///
/// [`Self::check_invariants`] verifies all of them.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{ConvexPolygon, Location};
///
/// // A clockwise square, closed, with a collinear vertex on its top edge.
/// let ring = [[0.0, 0.0], [0.0, 2.0], [1.0, 2.0], [2.0, 2.0], [2.0, 0.0], [0.0, 0.0]];
/// let ring: Vec<DVec2> = ring.iter().map(|&p| DVec2::from(p)).collect();
/// let square = ConvexPolygon::try_new(&ring)?;
/// assert_eq!(square.len(), 4); // the collinear vertex and the closing duplicate are dropped
/// assert_eq!(square.vertices()[1], DVec2::new(2.0, 0.0)); // counter-clockwise from vertex 0
/// assert_eq!(square.locate(DVec2::new(1.0, 1.0)), Location::Inside);
/// assert_eq!(square.locate(DVec2::new(1.0, 2.0)), Location::Boundary);
/// # Ok::<(), polydist_polygon::PolygonError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(
    feature = "serde",
    serde(try_from = "Vec<[f64; 2]>", into = "Vec<[f64; 2]>")
)]
pub struct ConvexPolygon {
    vertices: Vec<DVec2>,
    map: SourceMap,
}

impl ConvexPolygon {
    /// Validates the caller's ring `points` as a convex polygon.
    ///
    /// `points[j]` and `points[(j + 1) mod n]` are joined by the caller's edge `j`; the ring may be
    /// closed (last vertex repeating the first) or not, in either orientation. The result is
    /// counter-clockwise and starts at the first vertex the caller gave that was kept. Dropped, with
    /// the caller's indices kept in a map:
    /// - exactly repeated consecutive vertices (the first of a run is kept; the closing duplicate
    ///   merges into vertex 0);
    /// - vertices collinear with their neighbours and strictly between them.
    ///
    /// All collinear input is a segment between the two extreme points if it turns back only there;
    /// one distinct point is a point. Decisions are exact (the [`Robust`] kernel).
    ///
    /// # Errors
    /// [`PolygonError::Empty`], [`PolygonError::NonFinite`], [`PolygonError::OutOfRange`] (beyond
    /// `±2^500`), [`PolygonError::Spike`] (a 180° turn), [`PolygonError::NotConvex`] (the first reflex
    /// vertex), [`PolygonError::WindsMoreThanOnce`] (a star polygon such as a pentagram). Indices are
    /// the caller's. Never panics.
    ///
    /// # Complexity
    /// `O(n)` time and space, `O(n)` exact predicates.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::{ConvexPolygon, PolygonError};
    ///
    /// let pentagram: Vec<DVec2> = (0..5)
    ///     .map(|i| {
    ///         let a = f64::from(i) * 4.0 * std::f64::consts::PI / 5.0;
    ///         DVec2::new(a.cos(), a.sin())
    ///     })
    ///     .collect();
    /// assert_eq!(ConvexPolygon::try_new(&pentagram), Err(PolygonError::WindsMoreThanOnce { turns: 2 }));
    ///
    /// let spike = [DVec2::ZERO, DVec2::X, DVec2::new(2.0, 0.0), DVec2::Y];
    /// assert!(ConvexPolygon::try_new(&spike).is_ok()); // (1, 0) is straight: dropped
    /// let spike = [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::X, DVec2::Y];
    /// assert_eq!(ConvexPolygon::try_new(&spike), Err(PolygonError::Spike { index: 1 }));
    /// ```
    ///
    /// # References
    /// The winding test is ours (proof in the source, module `convex`); see also Preparata & Shamos,
    /// *Computational Geometry: An Introduction* (1985), §3.
    pub fn try_new(points: &[DVec2]) -> Result<ConvexPolygon, PolygonError> {
        ring::validate(points)?;
        let dedup = Dedup::new(points);
        if dedup.len() == 1 {
            return Ok(ConvexPolygon {
                vertices: dedup.points,
                map: SourceMap::ring(points, vec![0], false),
            });
        }
        let turns = ring::classify(&dedup.points);
        if turns
            .iter()
            .all(|&t| matches!(t, Turn::Straight | Turn::Reversal))
        {
            return Self::collinear(points, &dedup, &turns);
        }
        if let Some(i) = turns.iter().position(|&t| t == Turn::Reversal) {
            return Err(PolygonError::Spike {
                index: dedup.rep[i],
            });
        }
        let kept: Vec<usize> = (0..dedup.len())
            .filter(|&i| turns[i] != Turn::Straight)
            .collect();
        let mut vertices: Vec<DVec2> = kept.iter().map(|&i| dedup.points[i]).collect();
        // The orientation is the turn at the lowest vertex, a vertex of the hull of the ring.
        let orientation = turns[kept[ring::lowest(&vertices)]];
        if let Some(&i) = kept.iter().find(|&&i| turns[i] != orientation) {
            return Err(PolygonError::NotConvex {
                index: dedup.rep[i],
            });
        }
        // Every turn is strict and of one sign: the ring winds `changes / 2 ≥ 1` times (module docs).
        let changes = ring::direction_changes(&vertices);
        if changes != 2 {
            return Err(PolygonError::WindsMoreThanOnce { turns: changes / 2 });
        }
        let mut source: Vec<usize> = kept.iter().map(|&i| dedup.rep[i]).collect();
        let reversed = orientation == Turn::Right;
        if reversed {
            // v_i = w_{(k − i) mod k}: counter-clockwise, still starting at the caller's first kept vertex.
            vertices[1..].reverse();
            source[1..].reverse();
        }
        Ok(ConvexPolygon {
            vertices,
            map: SourceMap::ring(points, source, reversed),
        })
    }

    /// An all-collinear ring of at least two distinct vertices: the segment between its extreme points
    /// when the ring turns back only there, otherwise a spike at another reversal.
    fn collinear(
        points: &[DVec2],
        dedup: &Dedup,
        turns: &[Turn],
    ) -> Result<ConvexPolygon, PolygonError> {
        let d = &dedup.points;
        let lo = ring::lowest(d);
        // The first occurrence of the greatest point.
        let hi = (0..d.len()).fold(0, |best, i| {
            if lex_cmp(d[i], d[best]).is_gt() {
                i
            } else {
                best
            }
        });
        // Both extremes turn back (their neighbours lie on one side); any other reversal is a spike.
        if let Some(i) = (0..d.len()).find(|&i| turns[i] == Turn::Reversal && i != lo && i != hi) {
            return Err(PolygonError::Spike {
                index: dedup.rep[i],
            });
        }
        let (a, b) = if lo < hi { (lo, hi) } else { (hi, lo) };
        let source = vec![dedup.rep[a], dedup.rep[b]];
        Ok(ConvexPolygon {
            vertices: vec![d[a], d[b]],
            map: SourceMap::ring(points, source, false),
        })
    }

    /// A hull built by this crate: `vertices` counter-clockwise and strictly convex (as decided by the
    /// hull's kernel), with its map.
    pub(crate) fn from_hull(vertices: Vec<DVec2>, map: SourceMap) -> ConvexPolygon {
        ConvexPolygon { vertices, map }
    }

    /// The vertices, counter-clockwise.
    #[must_use]
    pub fn vertices(&self) -> &[DVec2] {
        &self.vertices
    }

    /// The number of vertices: 1 for a point, 2 for a segment, at least 3 for a polygon with area.
    #[must_use]
    #[expect(
        clippy::len_without_is_empty,
        reason = "a polygon always has at least one vertex"
    )]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Edge `i`, from vertex `i` to vertex `(i + 1) mod n` (a point's only edge has `a == b`; a
    /// segment's two edges are its two directions).
    ///
    /// # Panics
    /// When `i >= self.len()`.
    #[must_use]
    pub fn edge(&self, i: usize) -> Segment {
        let n = self.vertices.len();
        Segment::new(self.vertices[i], self.vertices[(i + 1) % n])
    }

    /// The edges, in order.
    pub fn edges(&self) -> impl ExactSizeIterator<Item = Segment> + '_ {
        (0..self.vertices.len()).map(|i| self.edge(i))
    }

    /// Where `p` lies relative to the closed polygon, decided exactly (the [`Robust`] kernel).
    ///
    /// See [`Self::locate_with`].
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::{ConvexPolygon, Location};
    ///
    /// let t = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 4.0)])?;
    /// assert_eq!(t.locate(DVec2::new(1.0, 1.0)), Location::Inside);
    /// assert_eq!(t.locate(DVec2::new(2.0, 2.0)), Location::Boundary);
    /// // One ulp beyond the hypotenuse.
    /// assert_eq!(t.locate(DVec2::new(2.0, f64::from_bits(2.0f64.to_bits() + 1))), Location::Outside);
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn locate(&self, p: DVec2) -> Location {
        self.locate_with::<Robust>(p)
    }

    /// Where `p` lies relative to the closed polygon, decided by the kernel `K`.
    ///
    /// A point or a segment has no interior: `p` is on its boundary or outside. A query point with a
    /// non-finite coordinate is [`Location::Outside`]. With an exact kernel the answer is exact; with
    /// [`Fast`](polydist_predicates::Fast) it may be wrong for points very near the boundary.
    ///
    /// # Complexity
    /// `O(log n)`: at most `⌈log₂ n⌉ + 3` orientation tests (binary search on the fan around vertex 0).
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::predicates::Exact;
    /// use polydist_polygon::{ConvexPolygon, Location};
    ///
    /// let segment = ConvexPolygon::try_new(&[DVec2::ZERO, DVec2::new(2.0, 2.0)])?;
    /// assert_eq!(segment.locate_with::<Exact>(DVec2::ONE), Location::Boundary);
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    ///
    /// # References
    /// Preparata & Shamos, *Computational Geometry: An Introduction* (1985), §2.2.1.
    #[must_use]
    pub fn locate_with<K: Kernel>(&self, p: DVec2) -> Location {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Location::Outside;
        }
        let v = &self.vertices;
        let n = v.len();
        if n == 1 {
            return if p == v[0] {
                Location::Boundary
            } else {
                Location::Outside
            };
        }
        if n == 2 {
            // On the line, and (p − a)·(p − b) ≤ 0: between the ends.
            let on = K::orient(v[0], v[1], p) == Orientation::Collinear
                && K::dot_sign(v[0], p, v[1], p) != Sign::Positive;
            return if on {
                Location::Boundary
            } else {
                Location::Outside
            };
        }
        // p must be in the wedge at v_0 between the rays to v_1 and to v_{n−1}.
        let first = K::orient(v[0], v[1], p);
        if first == Orientation::Clockwise {
            return Location::Outside;
        }
        let last = K::orient(v[0], v[n - 1], p);
        if last == Orientation::CounterClockwise {
            return Location::Outside;
        }
        // The largest i in [1, n − 2] with orient(v_0, v_i, p) ≠ clockwise: p is in the wedge v_i v_0 v_{i+1}.
        let (mut i, mut hi) = (1, n - 1);
        while hi - i > 1 {
            let mid = i + (hi - i) / 2;
            if K::orient(v[0], v[mid], p) == Orientation::Clockwise {
                hi = mid;
            } else {
                i = mid;
            }
        }
        match K::orient(v[i], v[i + 1], p) {
            Orientation::Clockwise => Location::Outside,
            // The wedge meets the line v_i v_{i+1} in the edge itself.
            Orientation::Collinear => Location::Boundary,
            Orientation::CounterClockwise => {
                let on_first_edge = i == 1 && first == Orientation::Collinear;
                let on_last_edge = i == n - 2 && last == Orientation::Collinear;
                if on_first_edge || on_last_edge {
                    Location::Boundary
                } else {
                    Location::Inside
                }
            }
        }
    }

    /// The caller's index of internal vertex `v`: the position, in the slice given to the constructor,
    /// of the vertex kept as `v` (for a hull, the position in the hulled polygon's or point set's input).
    ///
    /// # Panics
    /// When `v >= self.len()`.
    #[must_use]
    #[doc(alias = "caller_vertex")]
    pub fn source_index(&self, v: usize) -> usize {
        self.map.source(v)
    }

    /// The number of vertices the caller gave (for a hull, of the hulled polygon's caller or point set).
    #[must_use]
    pub fn caller_len(&self) -> usize {
        self.map.caller_len()
    }

    /// Whether internal edge `e` is a *lid* of a hull: not part of the caller's boundary (every edge of
    /// a polygon built from a ring is part of it; every edge of the hull of a point set is a lid).
    ///
    /// `false` when `e` is out of range.
    #[must_use]
    pub fn is_lid(&self, e: usize) -> bool {
        self.map.is_lid(e)
    }

    /// The caller's feature containing the point of internal edge `e` nearest to `q`.
    ///
    /// Internal edge `e` may stand for several caller edges: it runs through dropped caller vertices
    /// (repeats, and collinear vertices between their neighbours). Let `f` be the point of the edge
    /// nearest to `q` (the foot of the perpendicular, clamped to the edge). The result is
    /// - `Vertex(j)` when `f` is the caller's vertex `j`: an end of the edge, or a dropped vertex on it
    ///   (among repeats, the first in the caller's order);
    /// - otherwise `Edge(j)`, the caller's edge whose relative interior contains `f` (a caller ring of
    ///   exactly two vertices is a segment with the single edge `Edge(0)`);
    /// - `None` when `f` is inside a lid (see [`Self::is_lid`]), which is no caller feature.
    ///
    /// Decided by dot-product signs of input points under `K` (`sign((q − c)·(b − a))` for caller
    /// vertices `c` on the edge `a → b`); the foot is never computed. For a polygon built by
    /// [`Self::try_new`] the result is always `Some`.
    ///
    /// # Panics
    /// When `e >= self.len()`.
    ///
    /// # Complexity
    /// `O(log m)` dot signs for an edge standing for `m` caller edges.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::predicates::Robust;
    /// use polydist_polygon::{ConvexPolygon, Feature};
    ///
    /// // Caller vertex 1 lies on the bottom edge and is dropped.
    /// let ring = [DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)];
    /// let t = ConvexPolygon::try_new(&ring)?;
    /// assert_eq!(t.len(), 3);
    /// let below = |x: f64| DVec2::new(x, -5.0);
    /// assert_eq!(t.caller_feature_on_edge::<Robust>(0, below(0.5)), Some(Feature::Edge(0)));
    /// assert_eq!(t.caller_feature_on_edge::<Robust>(0, below(1.0)), Some(Feature::Vertex(1)));
    /// assert_eq!(t.caller_feature_on_edge::<Robust>(0, below(1.5)), Some(Feature::Edge(1)));
    /// assert_eq!(t.caller_feature_on_edge::<Robust>(0, below(9.0)), Some(Feature::Vertex(2)));
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn caller_feature_on_edge<K: Kernel>(&self, e: usize, q: DVec2) -> Option<Feature> {
        self.map.feature_on_edge::<K>(&self.vertices, e, q)
    }

    /// Checks every invariant (see the type's docs) exactly, for tests: `Err` says which one fails.
    ///
    /// # Errors
    /// A description of the first violated invariant.
    ///
    /// # Complexity
    /// `O(n + L)` for `L` caller vertices.
    pub fn check_invariants(&self) -> Result<(), String> {
        let v = &self.vertices;
        let n = v.len();
        if n == 0 {
            return Err("no vertices".into());
        }
        if let Some(i) = v.iter().position(|&p| !ring::is_valid_point(p)) {
            return Err(format!("vertex {i} has an invalid coordinate"));
        }
        if let Some(i) = (0..n).find(|&i| n > 1 && v[i] == v[(i + 1) % n]) {
            return Err(format!("vertices {i} and {} repeat", (i + 1) % n));
        }
        if n >= 3 {
            if let Some(i) = (0..n).find(|&i| {
                Robust::orient(v[(i + n - 1) % n], v[i], v[(i + 1) % n])
                    != Orientation::CounterClockwise
            }) {
                return Err(format!(
                    "the turn at vertex {i} is not strictly counter-clockwise"
                ));
            }
            let changes = ring::direction_changes(v);
            if changes != 2 {
                return Err(format!("the boundary winds {} times", changes / 2));
            }
        }
        self.map.check(v)
    }
}
