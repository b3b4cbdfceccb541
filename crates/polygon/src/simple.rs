//! Simple polygons: validation (Shamos–Hoey sweep), point location by crossing number.
//!
//! A ring is accepted when, after exact repeats are merged, it has at least three vertices, not all
//! collinear, no 180° turn, and no two edges meet except ring neighbours at their shared vertex (decided
//! by the sweep in [`crate::sweep`], `O(n log n)`). Straight vertices (collinear and strictly between
//! their neighbours) are then dropped, and a clockwise ring is reversed: the orientation is the exact
//! turn at the lexicographically lowest vertex, which is convex in a simple polygon.
//!
//! Point location counts the crossings of a horizontal ray with the edges, with the half-open rule on
//! `y` (an edge counts when exactly one end is strictly above the point) and an exact orientation test
//! for the side: `O(n)` (Haines 1994, "Point in polygon strategies", Graphics Gems IV; the crossing test
//! with exact predicates as in O'Rourke, *Computational Geometry in C* (1998), §7.4).

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust, Sign};

use crate::ring::{self, Dedup, Turn};
use crate::source_map::SourceMap;
use crate::{ConvexPolygon, Feature, Location, PolygonError, Segment, brute, melkman, sweep};

/// A validated simple polygon with at least three vertices, stored counter-clockwise.
///
/// Built by [`SimplePolygon::try_new`] from the caller's vertices (either orientation, with repeats
/// and straight vertices allowed), or by deserialization (which validates).
///
/// # Invariants
/// - at least 3 vertices, no two consecutive equal, no three consecutive collinear;
/// - no two edges meet except consecutive edges at their shared vertex;
/// - counter-clockwise (positive area);
/// - every coordinate finite, with magnitude at most [`MAX_COORDINATE`](polydist_predicates::MAX_COORDINATE);
/// - a map from its vertices and edges back to the caller's (see [`Self::source_index`]).
///
/// [`Self::check_invariants`] verifies all of them (simplicity by brute force).
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::{Location, PolygonError, SimplePolygon};
///
/// // An L shape.
/// let l = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
/// let l: Vec<DVec2> = l.iter().map(|&p| DVec2::from(p)).collect();
/// let poly = SimplePolygon::try_new(&l)?;
/// assert_eq!(poly.locate(DVec2::new(1.5, 1.5)), Location::Outside);
/// assert_eq!(poly.convex_hull().len(), 5);
///
/// // A bow tie: edges 0 and 2 cross.
/// let bow = [DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)];
/// assert_eq!(SimplePolygon::try_new(&bow), Err(PolygonError::SelfIntersection { edge_a: 0, edge_b: 2 }));
/// # Ok::<(), PolygonError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(
    feature = "serde",
    serde(try_from = "Vec<[f64; 2]>", into = "Vec<[f64; 2]>")
)]
pub struct SimplePolygon {
    vertices: Vec<DVec2>,
    map: SourceMap,
}

/// A function returning the first intersecting pair of non-neighbour edges of a clean ring.
type IntersectionFinder = fn(&[DVec2]) -> Option<(usize, usize)>;

impl SimplePolygon {
    /// Validates the caller's ring `points` as a simple polygon.
    ///
    /// `points[j]` and `points[(j + 1) mod n]` are joined by the caller's edge `j`; the ring may be
    /// closed (last vertex repeating the first) or not, in either orientation. The result is
    /// counter-clockwise and starts at the first vertex the caller gave that was kept. Dropped, with
    /// the caller's indices kept in a map: exactly repeated consecutive vertices (the first of a run is
    /// kept; the closing duplicate merges into vertex 0) and vertices collinear with their neighbours
    /// and strictly between them. Decisions are exact (the [`Robust`] kernel).
    ///
    /// # Errors
    /// In this order: [`PolygonError::Empty`], [`PolygonError::NonFinite`],
    /// [`PolygonError::OutOfRange`] (beyond `±2^500`), [`PolygonError::TooFewVertices`] (fewer than
    /// three distinct vertices), [`PolygonError::Degenerate`] (all collinear), [`PolygonError::Spike`]
    /// (a 180° turn), [`PolygonError::SelfIntersection`] (the first pair of caller edges the sweep found
    /// meeting; touching at a vertex counts, so a figure 8 is rejected). Indices are the caller's.
    /// Never panics.
    ///
    /// # Complexity
    /// `O(n log n)` time (expected, for the sweep's randomized search tree), `O(n)` space.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::{PolygonError, SimplePolygon};
    ///
    /// // A figure 8: the ring passes twice through (1, 1).
    /// let eight = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1.0], [0.0, 2.0]];
    /// let eight: Vec<DVec2> = eight.iter().map(|&p| DVec2::from(p)).collect();
    /// assert_eq!(SimplePolygon::try_new(&eight), Err(PolygonError::SelfIntersection { edge_a: 1, edge_b: 4 }));
    /// ```
    ///
    /// # References
    /// M. I. Shamos and D. Hoey, "Geometric intersection problems", 17th FOCS (1976), 208–215.
    pub fn try_new(points: &[DVec2]) -> Result<SimplePolygon, PolygonError> {
        Self::build(points, sweep::first_intersection)
    }

    /// [`Self::try_new`] with the `O(n²)` all-pairs intersection test in place of the sweep: the
    /// brute-force twin, for testing. Same results, except that
    /// [`PolygonError::SelfIntersection`] names the lexicographically first intersecting pair.
    ///
    /// # Errors
    /// As [`Self::try_new`].
    ///
    /// # Complexity
    /// `O(n²)` time.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    /// assert_eq!(SimplePolygon::try_new_brute_force(&square), SimplePolygon::try_new(&square));
    /// ```
    pub fn try_new_brute_force(points: &[DVec2]) -> Result<SimplePolygon, PolygonError> {
        Self::build(points, brute::first_intersection)
    }

    /// Validation with the given intersection finder.
    fn build(points: &[DVec2], find: IntersectionFinder) -> Result<SimplePolygon, PolygonError> {
        ring::validate(points)?;
        let dedup = Dedup::new(points);
        let m = dedup.len();
        if m < 3 {
            return Err(PolygonError::TooFewVertices {
                found: m,
                needed: 3,
            });
        }
        let turns = ring::classify(&dedup.points);
        if turns
            .iter()
            .all(|&t| matches!(t, Turn::Straight | Turn::Reversal))
        {
            return Err(PolygonError::Degenerate);
        }
        if let Some(i) = turns.iter().position(|&t| t == Turn::Reversal) {
            return Err(PolygonError::Spike {
                index: dedup.rep[i],
            });
        }
        // The sweep runs on the ring with straight vertices kept: its edges are the caller's nonzero
        // edges, so an intersection names caller edges exactly.
        if let Some((i, j)) = find(&dedup.points) {
            let (a, b) = (dedup.out_edge[i], dedup.out_edge[j]);
            return Err(PolygonError::SelfIntersection {
                edge_a: a.min(b),
                edge_b: a.max(b),
            });
        }
        let kept: Vec<usize> = (0..m).filter(|&i| turns[i] != Turn::Straight).collect();
        let mut vertices: Vec<DVec2> = kept.iter().map(|&i| dedup.points[i]).collect();
        let mut source: Vec<usize> = kept.iter().map(|&i| dedup.rep[i]).collect();
        // The lowest vertex of a simple polygon is convex: its turn is the orientation.
        let reversed = turns[kept[ring::lowest(&vertices)]] == Turn::Right;
        if reversed {
            vertices[1..].reverse();
            source[1..].reverse();
        }
        Ok(SimplePolygon {
            vertices,
            map: SourceMap::ring(points, source, reversed),
        })
    }

    /// The vertices, counter-clockwise.
    #[must_use]
    pub fn vertices(&self) -> &[DVec2] {
        &self.vertices
    }

    /// The number of vertices (at least 3).
    #[must_use]
    #[expect(
        clippy::len_without_is_empty,
        reason = "a simple polygon always has at least three vertices"
    )]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Edge `i`, from vertex `i` to vertex `(i + 1) mod n`.
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
    /// use polydist_polygon::{Location, SimplePolygon};
    ///
    /// let l = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
    /// let l = SimplePolygon::try_from(&l[..])?;
    /// assert_eq!(l.locate(DVec2::new(0.5, 1.5)), Location::Inside);
    /// assert_eq!(l.locate(DVec2::new(1.0, 1.5)), Location::Boundary);
    /// assert_eq!(l.locate(DVec2::new(1.5, 1.5)), Location::Outside);
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn locate(&self, p: DVec2) -> Location {
        self.locate_with::<Robust>(p)
    }

    /// Where `p` lies relative to the closed polygon, decided by the kernel `K`: the crossing number of
    /// a horizontal ray from `p`, with exact on-boundary detection.
    ///
    /// An edge counts when exactly one of its ends is strictly above `p` (comparing input `y`
    /// coordinates) and `p` is on the side of it from which the ray crosses it (an orientation test).
    /// `p` is on the boundary when some edge has `orient = 0` and `(p − a)·(p − b) ≤ 0`. A query point
    /// with a non-finite coordinate is [`Location::Outside`].
    ///
    /// # Complexity
    /// `O(n)`: one orientation test per edge, plus a dot sign on the edges whose line contains `p`.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::predicates::Fast;
    /// use polydist_polygon::{Location, SimplePolygon};
    ///
    /// let t = SimplePolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::Y])?;
    /// assert_eq!(t.locate_with::<Fast>(DVec2::new(0.25, 0.25)), Location::Inside);
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    ///
    /// # References
    /// E. Haines, "Point in polygon strategies", Graphics Gems IV (1994), 24–46.
    #[must_use]
    pub fn locate_with<K: Kernel>(&self, p: DVec2) -> Location {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Location::Outside;
        }
        let v = &self.vertices;
        let n = v.len();
        let mut inside = false;
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let o = K::orient(a, b, p);
            if o == Orientation::Collinear && K::dot_sign(a, p, b, p) != Sign::Positive {
                return Location::Boundary;
            }
            let (a_above, b_above) = (a.y > p.y, b.y > p.y);
            // Upward edge (only b above): the ray crosses it when p is to its left; downward: to its right.
            if (b_above && !a_above && o == Orientation::CounterClockwise)
                || (a_above && !b_above && o == Orientation::Clockwise)
            {
                inside = !inside;
            }
        }
        if inside {
            Location::Inside
        } else {
            Location::Outside
        }
    }

    /// The convex hull, by Melkman's algorithm, with exact decisions (the [`Robust`] kernel).
    ///
    /// See [`Self::convex_hull_with`].
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// // An arrow head: vertex 2 is reflex.
    /// let arrow = [DVec2::ZERO, DVec2::new(2.0, 1.0), DVec2::new(0.0, 2.0), DVec2::new(0.5, 1.0)];
    /// let arrow = SimplePolygon::try_new(&arrow)?;
    /// let hull = arrow.convex_hull();
    /// assert_eq!(hull.len(), 3);
    /// assert_eq!((0..3).map(|i| hull.source_index(i)).collect::<Vec<_>>(), [0, 1, 2]);
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn convex_hull(&self) -> ConvexPolygon {
        self.convex_hull_with::<Robust>()
    }

    /// The convex hull, by Melkman's algorithm with the kernel `K`.
    ///
    /// The hull's vertices are vertices of this polygon, counter-clockwise from the lexicographically
    /// lowest, strictly convex (points on a hull edge are not vertices). Its vertex map names the
    /// caller's vertices of this polygon ([`ConvexPolygon::source_index`]); a hull edge that is an edge
    /// of this polygon keeps its caller edges, and the others are lids ([`ConvexPolygon::is_lid`]).
    /// With an exact kernel the result is exact; with [`Fast`](polydist_predicates::Fast) it may miss
    /// or keep near-collinear vertices, but the algorithm terminates and never panics.
    ///
    /// # Complexity
    /// `O(n)` time and at most `6n` orientation tests: two per vertex to test whether it is inside, and
    /// one per pop plus one to stop at each end (each vertex is pushed on each end at most once).
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::predicates::Exact;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// let square = SimplePolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y])?;
    /// assert_eq!(square.convex_hull_with::<Exact>().vertices(), square.vertices());
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    ///
    /// # References
    /// A. A. Melkman, "On-line construction of the convex hull of a simple polyline", Information
    /// Processing Letters 25 (1987), 11–12.
    #[must_use]
    pub fn convex_hull_with<K: Kernel>(&self) -> ConvexPolygon {
        self.convex_hull_and_indices_with::<K>().0
    }

    /// [`convex_hull_with`](Self::convex_hull_with), with the internal index of each hull vertex
    /// (the hull's vertex `i` is this polygon's vertex `indices[i]`), for callers that walk the
    /// polygon between hull vertices. Same complexity.
    ///
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::predicates::Exact;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// // A square with a notch: vertex 2 is reflex, so not on the hull.
    /// let v = [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(1.0, 1.0), DVec2::new(2.0, 2.0), DVec2::new(0.0, 2.0)];
    /// let p = SimplePolygon::try_new(&v)?;
    /// let (hull, indices) = p.convex_hull_and_indices_with::<Exact>();
    /// assert_eq!(indices, [0, 1, 3, 4]);
    /// assert!(indices.iter().zip(hull.vertices()).all(|(&i, h)| p.vertices()[i] == *h));
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn convex_hull_and_indices_with<K: Kernel>(&self) -> (ConvexPolygon, Vec<usize>) {
        let kept = melkman::hull::<K>(&self.vertices);
        let vertices = kept.iter().map(|&i| self.vertices[i]).collect();
        let hull = ConvexPolygon::from_hull(vertices, self.map.hull_of_ring(&kept));
        (hull, kept)
    }

    /// The caller's index of internal vertex `v`: the position, in the slice given to the constructor,
    /// of the vertex kept as `v`.
    ///
    /// # Panics
    /// When `v >= self.len()`.
    #[must_use]
    #[doc(alias = "caller_vertex")]
    pub fn source_index(&self, v: usize) -> usize {
        self.map.source(v)
    }

    /// The number of vertices the caller gave.
    #[must_use]
    pub fn caller_len(&self) -> usize {
        self.map.caller_len()
    }

    /// The caller's feature containing the point of internal edge `e` nearest to `q`: `Vertex(j)` when
    /// that point is the caller's vertex `j` (an end of the edge or a dropped vertex on it), otherwise
    /// the caller's `Edge(j)` containing it. Always `Some` for a simple polygon; see
    /// [`ConvexPolygon::caller_feature_on_edge`] for the rules.
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
    /// use polydist_polygon::{Feature, SimplePolygon};
    ///
    /// // A closed ring: caller vertex 4 repeats vertex 0.
    /// let ring = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y, DVec2::ZERO];
    /// let square = SimplePolygon::try_new(&ring)?;
    /// assert_eq!(square.caller_feature_on_edge::<Robust>(3, DVec2::new(-1.0, 0.5)), Some(Feature::Edge(3)));
    /// assert_eq!(square.caller_feature_on_edge::<Robust>(3, DVec2::new(-1.0, -1.0)), Some(Feature::Vertex(0)));
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn caller_feature_on_edge<K: Kernel>(&self, e: usize, q: DVec2) -> Option<Feature> {
        self.map.feature_on_edge::<K>(&self.vertices, e, q)
    }

    /// The first pair of internal edges `(e, f)`, edge `e` of `self` and edge `f` of `other`, that share
    /// a point (crossing, touching at a vertex, or overlapping along a line), or `None` when the two
    /// boundaries are disjoint. Internal edge `e` joins internal vertices `e` and `e + 1` (mod `len`);
    /// [`Self::source_index`] names their caller vertices.
    ///
    /// Both boundaries are swept together (Shamos–Hoey, as in [`Self::try_new`]); every decision is
    /// exact (the [`Robust`] kernel). Together with one point location each way this decides whether two
    /// simple polygons intersect: see `polydist_separation::intersection`.
    ///
    /// # Complexity
    /// `O(N log N)` expected time, `O(N)` space, for `N = self.len() + other.len()`.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// let square = SimplePolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y])?;
    /// let moved = |dx: f64| {
    ///     let ring: Vec<DVec2> = square.vertices().iter().map(|&v| v + DVec2::new(dx, 0.0)).collect();
    ///     SimplePolygon::try_new(&ring)
    /// };
    /// assert_eq!(square.first_boundary_contact(&moved(2.0)?), None);
    /// // Shifted by one unit, the squares share their edge x = 1 (edge 1 of the first, 3 of the second).
    /// assert!(square.first_boundary_contact(&moved(1.0)?).is_some());
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn first_boundary_contact(&self, other: &SimplePolygon) -> Option<(usize, usize)> {
        sweep::first_contact_between(&self.vertices, &other.vertices)
    }

    /// [`Self::first_boundary_contact`] by testing every pair of edges, in lexicographic order of
    /// `(e, f)`: the brute-force twin, for testing. It returns `Some` exactly when the sweep does (the
    /// pair may differ).
    ///
    /// # Complexity
    /// `O(n m)` exact segment tests.
    ///
    /// # Examples
    /// ```
    /// use glam::DVec2;
    /// use polydist_polygon::SimplePolygon;
    ///
    /// let a = SimplePolygon::try_new(&[DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y])?;
    /// let b = SimplePolygon::try_new(&[DVec2::new(0.5, 0.5), DVec2::new(3.0, 0.5), DVec2::new(3.0, 3.0)])?;
    /// assert_eq!(a.first_boundary_contact_brute(&b), Some((1, 0)));
    /// # Ok::<(), polydist_polygon::PolygonError>(())
    /// ```
    #[must_use]
    pub fn first_boundary_contact_brute(&self, other: &SimplePolygon) -> Option<(usize, usize)> {
        let (n, m) = (self.vertices.len(), other.vertices.len());
        let (p, q) = (&self.vertices, &other.vertices);
        (0..n)
            .flat_map(|e| (0..m).map(move |f| (e, f)))
            .find(|&(e, f)| {
                ring::segments_intersect::<Robust>(p[e], p[(e + 1) % n], q[f], q[(f + 1) % m])
            })
    }

    /// Checks every invariant (see the type's docs) exactly, for tests; simplicity by brute force.
    ///
    /// # Errors
    /// A description of the first violated invariant.
    ///
    /// # Complexity
    /// `O(n² + L)` for `L` caller vertices.
    pub fn check_invariants(&self) -> Result<(), String> {
        let v = &self.vertices;
        let n = v.len();
        if n < 3 {
            return Err(format!("{n} vertices"));
        }
        if let Some(i) = v.iter().position(|&p| !ring::is_valid_point(p)) {
            return Err(format!("vertex {i} has an invalid coordinate"));
        }
        if let Some(i) = (0..n).find(|&i| v[i] == v[(i + 1) % n]) {
            return Err(format!("vertices {i} and {} repeat", (i + 1) % n));
        }
        let turns = ring::classify(v);
        if let Some(i) = turns
            .iter()
            .position(|&t| matches!(t, Turn::Straight | Turn::Reversal))
        {
            return Err(format!("vertex {i} is collinear with its neighbours"));
        }
        if let Some((a, b)) = brute::first_intersection(v) {
            return Err(format!("edges {a} and {b} intersect"));
        }
        if turns[ring::lowest(v)] != Turn::Left {
            return Err("the polygon is clockwise".into());
        }
        self.map.check(v)
    }
}
