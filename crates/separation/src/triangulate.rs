//! Triangulation of a simple polygon whose vertices may be collinear, with exact predicates.
//!
//! The classical two-phase algorithm: a plane sweep cuts the polygon into monotone pieces (Lee &
//! Preparata 1977; Garey, Johnson, Preparata & Tarjan 1978; presented as in de Berg, Cheong, van
//! Kreveld & Overmars, *Computational Geometry*, 3rd ed., §3.2), and each monotone piece is
//! triangulated by the stack algorithm (§3.3). `O(n log n)` predicates and time (the sweep
//! status, a treap with `O(log n)` expected depth); the vertex order is a radix sort of the
//! coordinates' bits (`polydist_polygon::order`, `O(n)`) and the stack phase is `O(n)`.
//!
//! # Degeneracies (what we changed from the textbook)
//! The textbook assumes no two vertices on a sweep line and says nothing about collinear vertices.
//! Here:
//! * The sweep order is the lexicographic order of `(x, y)` (exact on the input coordinates). It is
//!   the order of an infinitesimally rotated sweep line, so "above/below" and the vertex types
//!   (start, split, end, merge, regular) are decided without ties; a vertex whose two neighbours lie
//!   on the same side in this order and on one line through it would make two edges overlap, which a
//!   simple polygon cannot do ([`TriangulationError::Degenerate`]).
//! * A 180° corner (consecutive collinear vertices) is a regular vertex: one neighbour is before it
//!   and one after it in the order.
//! * The stack algorithm pops a vertex only when it is a *strictly* convex corner of the remaining
//!   polygon (an exact orientation test); a collinear corner is treated as reflex and stays on the
//!   stack. So the "same chain" step never emits a zero-area triangle.
//! * The chain-switch fan and the final fan emit `(u_j, s_i, s_{i+1})` over the whole stack. Every
//!   stack vertex `s_2 … s_{k−1}` is a corner of angle `≥ π` of the remaining polygon (nothing else
//!   is ever left on the stack), so the remaining part `Q = (s_1, …, s_k, u_j)` is a polygon of
//!   `k + 1` vertices whose angles at `s_2 … s_{k−1}` are `≥ π`; its angles sum to `(k − 1)π`, so
//!   its three other corners `s_1, s_k, u_j` are each `< π` and together `≤ π`. If `u_j` lay on the
//!   line of a stack edge `s_i s_{i+1}` (a degenerate fan triangle), `u_j`, `s_{i+1}` and `s_i` would
//!   be collinear with `s_{i+1}` between (the lexicographic order is monotone along a line), and the
//!   segment `s_{i+1} u_j` would split `Q` into the polygon `(s_1, …, s_{i+1}, u_j)` whose angle at
//!   `s_{i+1}` is exactly `π`: its `i + 2` angles sum to `iπ`, its angles at `s_2 … s_{i+1}` alone
//!   already sum to `≥ iπ`, leaving zero for the corners `s_1` and `u_j` — impossible for a polygon
//!   of positive area. Hence every fan triangle has strictly positive area. Each emitted triangle is
//!   nevertheless re-checked with an exact orientation test, and a failure (only possible when the
//!   input is not simple or under the Fast kernel) is an [`TriangulationError::Inconsistent`] error.
//! * No vertex lies on a diagonal: all vertices of an emitted triangle are `≤` the current vertex
//!   `u_j` in the sweep order and `≥` the bottom of the stack, the closed triangle lies in that
//!   lexicographic slab, and the only vertices of the remaining polygon in the slab are the stack
//!   vertices, which the angle argument keeps off the triangle's sides. The tests check this by brute
//!   force on degenerate families (combs with aligned tips, lattice polygons, staircases, squares with
//!   collinear sides).
//!
//! Every decision is an orientation or a dot-product sign (degree 2) through the kernel `K`, or a
//! lexicographic comparison of input coordinates. Under the Fast kernel an inconsistent sign can
//! only produce an error (every loop is bounded by a count, never by a predicate).
//!
//! The brute-force twin [`triangulate_brute`] clips ears with exact predicates (`O(n³)`).

use core::cmp::Ordering;
use std::collections::HashMap;

use glam::DVec2;
use polydist_polygon::order::lex_order;
use polydist_polygon::predicates::{Kernel, Orientation, Sign, is_valid_coordinate};
use polydist_polygon::treap::Treap;

/// What lies across one side of a triangle of a [`Triangulation`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Neighbor {
    /// Another triangle (its index in [`Triangulation::triangles`]).
    Triangle(u32),
    /// The polygon's boundary: ring edge `k`, the side from vertex `k` to vertex `k + 1 (mod n)`.
    RingEdge(u32),
}

/// A triangulation of a simple polygon: `n − 2` triangles of ring indices with their adjacency.
///
/// Triangle `t` is `triangles()[t] = [a, b, c]`, counter-clockwise with strictly positive area; its
/// side `k` goes from corner `k` to corner `k + 1 (mod 3)`, and `neighbors()[t][k]` says what lies
/// across it. Built by [`triangulate`] or [`triangulate_brute`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Triangulation {
    triangles: Vec<[u32; 3]>,
    neighbors: Vec<[Neighbor; 3]>,
    vertex_triangle: Vec<u32>,
}

/// Why a ring could not be triangulated.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TriangulationError {
    /// Fewer than three vertices.
    #[error("a polygon needs at least 3 vertices, got {count}")]
    TooFewVertices {
        /// The number of vertices given.
        count: usize,
    },
    /// More vertices than `u32` triangle indices can address (`2^31`).
    #[error("{count} vertices are more than 2^31")]
    TooManyVertices {
        /// The number of vertices given.
        count: usize,
    },
    /// A coordinate is NaN, infinite or beyond `2^500` in magnitude.
    #[error("vertex {index} has a coordinate that is not finite or beyond 2^500")]
    InvalidCoordinate {
        /// The offending vertex.
        index: usize,
    },
    /// Two vertices are the same point.
    #[error("vertices {first} and {second} are the same point")]
    RepeatedVertex {
        /// One of them.
        first: usize,
        /// The other.
        second: usize,
    },
    /// Both edges at this vertex leave it in the same direction (they overlap).
    #[error("the two edges at vertex {index} overlap")]
    Degenerate {
        /// The vertex.
        index: usize,
    },
    /// The ring is clockwise (its lowest-leftmost corner turns right).
    #[error("the ring is clockwise; a counter-clockwise ring is required")]
    NotCounterClockwise,
    /// A sign contradicted the structure built so far: the polygon is not simple, or the kernel
    /// (Fast) decided inconsistently.
    #[error(
        "inconsistency near vertex {index}: {what} (the polygon is not simple, or the kernel is inexact)"
    )]
    Inconsistent {
        /// A vertex near which it was detected.
        index: usize,
        /// What was found.
        what: &'static str,
    },
}

impl Triangulation {
    /// The triangles, each `[a, b, c]` of ring indices, counter-clockwise, strictly positive area.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// For each triangle and each side `k` (corner `k` to corner `k + 1 mod 3`), what lies across.
    #[must_use]
    pub fn neighbors(&self) -> &[[Neighbor; 3]] {
        &self.neighbors
    }

    /// The number of ring vertices `n` (the triangulation has `n − 2` triangles).
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.vertex_triangle.len()
    }

    /// One triangle having ring vertex `v` as a corner (`v < n`).
    ///
    /// # Panics
    /// Panics if `v ≥ n`.
    #[must_use]
    pub fn triangle_at(&self, v: usize) -> usize {
        self.vertex_triangle[v] as usize
    }

    /// Checks the triangulation against `ring` in `O(n)` expected time: `n − 2` triangles of
    /// distinct in-range corners, each strictly counter-clockwise under `K`, every ring edge a side
    /// of exactly one triangle (as `k → k + 1`) with [`Neighbor::RingEdge`] across it, every other
    /// side shared by exactly two triangles in opposite directions with consistent [`Neighbor::Triangle`]
    /// links. (Together these make the triangles tile the polygon; the tests also compare areas
    /// exactly and check that no vertex lies on a diagonal.)
    ///
    /// # Errors
    /// A description of the first violation.
    pub fn check<K: Kernel>(&self, ring: &[DVec2]) -> Result<(), String> {
        let n = ring.len();
        if self.vertex_triangle.len() != n {
            return Err(format!(
                "built for {} vertices, ring has {n}",
                self.vertex_triangle.len()
            ));
        }
        if n < 3 || self.triangles.len() != n - 2 || self.neighbors.len() != n - 2 {
            return Err(format!(
                "{} triangles for {n} vertices",
                self.triangles.len()
            ));
        }
        let mut ring_seen = vec![false; n];
        let mut sides: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            if tri.iter().any(|&v| v as usize >= n)
                || tri[0] == tri[1]
                || tri[1] == tri[2]
                || tri[0] == tri[2]
            {
                return Err(format!("triangle {t} = {tri:?} has bad corners"));
            }
            let [a, b, c] = tri.map(|v| ring[v as usize]);
            if K::orient(a, b, c) != Orientation::CounterClockwise {
                return Err(format!("triangle {t} = {tri:?} is not strictly ccw"));
            }
            for k in 0..3 {
                let (u, w) = (tri[k], tri[(k + 1) % 3]);
                if (u as usize + 1) % n == w as usize {
                    if ring_seen[u as usize] {
                        return Err(format!("ring edge {u} in two triangles"));
                    }
                    ring_seen[u as usize] = true;
                    if self.neighbors[t][k] != Neighbor::RingEdge(u) {
                        return Err(format!("triangle {t} side {k}: ring edge {u} not linked"));
                    }
                } else if sides.insert((u, w), (t, k)).is_some() {
                    return Err(format!("side {u}->{w} appears twice"));
                }
            }
        }
        if let Some(k) = ring_seen.iter().position(|&s| !s) {
            return Err(format!("ring edge {k} is in no triangle"));
        }
        for (&(u, w), &(t, k)) in &sides {
            let Some(&(t2, k2)) = sides.get(&(w, u)) else {
                return Err(format!("diagonal {u}->{w} of triangle {t} has no twin"));
            };
            if self.neighbors[t][k] != Neighbor::Triangle(t2 as u32) {
                return Err(format!("triangle {t} side {k}: neighbour is not {t2}"));
            }
            if self.neighbors[t2][k2] != Neighbor::Triangle(t as u32) {
                return Err(format!("triangle {t2} side {k2}: neighbour is not {t}"));
            }
        }
        for (v, &t) in self.vertex_triangle.iter().enumerate() {
            if !self
                .triangles
                .get(t as usize)
                .is_some_and(|tri| tri.contains(&(v as u32)))
            {
                return Err(format!("vertex {v}: its triangle {t} does not contain it"));
            }
        }
        Ok(())
    }

    /// The same triangulation of the ring rotated by `off`: its vertex `i` is vertex `i + off`
    /// (mod `n`) of `self`'s ring. `O(n)`, no sorting (the adjacency is relabelled, not rebuilt).
    pub(crate) fn rotated(&self, off: usize) -> Triangulation {
        let n = self.vertex_triangle.len();
        let off = off % n.max(1);
        let relabel = |j: u32| {
            let i = j as usize + n - off;
            (if i >= n { i - n } else { i }) as u32
        };
        Triangulation {
            triangles: self.triangles.iter().map(|t| t.map(relabel)).collect(),
            neighbors: self
                .neighbors
                .iter()
                .map(|s| {
                    s.map(|x| match x {
                        Neighbor::RingEdge(k) => Neighbor::RingEdge(relabel(k)),
                        t => t,
                    })
                })
                .collect(),
            vertex_triangle: self.vertex_triangle[off..]
                .iter()
                .chain(&self.vertex_triangle[..off])
                .copied()
                .collect(),
        }
    }

    /// Two triangulated polygons glued along a common side into a triangulation of a ring of `n`
    /// vertices: each half is given with its vertices' ring indices `h` (consecutive around the
    /// ring, `h[k + 1] = h[k] + 1 mod n`), and each half's closing side (its last vertex to its
    /// first) is the cut, shared with the other half, so it becomes a diagonal. `O(n)`, without
    /// [`Triangulation::glue`]'s sort. `None` when the halves do not fit (sizes, or the cuts'
    /// ends differ).
    pub(crate) fn joined(
        n: usize,
        (h1, t1): (&[usize], &Triangulation),
        (h2, t2): (&[usize], &Triangulation),
    ) -> Option<Triangulation> {
        let (m1, m2) = (h1.len(), h2.len());
        let fits = m1 >= 3
            && m2 >= 3
            && m1 + m2 == n + 2
            && t1.vertex_count() == m1
            && t2.vertex_count() == m2
            && h1[0] == h2[m2 - 1]
            && h1[m1 - 1] == h2[0];
        if !fits {
            return None;
        }
        // The triangle of each half on its closing side.
        let on_cut = |t: &Triangulation, m: usize| {
            t.neighbors
                .iter()
                .position(|s| s.contains(&Neighbor::RingEdge((m - 1) as u32)))
        };
        let (c1, c2) = (on_cut(t1, m1)?, on_cut(t2, m2)?);
        let base = t1.triangles.len();
        let (c1, c2) = (c1 as u32, (c2 + base) as u32);
        let mut triangles = Vec::with_capacity(n - 2);
        let mut neighbors = Vec::with_capacity(n - 2);
        let mut vertex_triangle = vec![u32::MAX; n];
        for (h, t, off, across) in [(h1, t1, 0u32, c2), (h2, t2, base as u32, c1)] {
            let m = h.len();
            triangles.extend(t.triangles.iter().map(|c| c.map(|i| h[i as usize] as u32)));
            neighbors.extend(t.neighbors.iter().map(|s| {
                s.map(|x| match x {
                    Neighbor::Triangle(u) => Neighbor::Triangle(u + off),
                    Neighbor::RingEdge(k) if k as usize == m - 1 => Neighbor::Triangle(across),
                    Neighbor::RingEdge(k) => Neighbor::RingEdge(h[k as usize] as u32),
                })
            }));
            for (i, &v) in h.iter().enumerate() {
                vertex_triangle[v] = t.vertex_triangle[i] + off;
            }
        }
        if vertex_triangle.contains(&u32::MAX) {
            return None;
        }
        Some(Triangulation {
            triangles,
            neighbors,
            vertex_triangle,
        })
    }

    /// Builds the adjacency of `n − 2` triangles of a ring of `n` vertices.
    pub(crate) fn glue(n: usize, triangles: Vec<[u32; 3]>) -> Result<Self, TriangulationError> {
        let bad = |index: u32, what| TriangulationError::Inconsistent {
            index: index as usize,
            what,
        };
        if triangles.len() + 2 != n {
            return Err(bad(0, "wrong number of triangles"));
        }
        let mut neighbors = vec![[Neighbor::RingEdge(0); 3]; triangles.len()];
        let mut vertex_triangle = vec![u32::MAX; n];
        // Every diagonal is the side of exactly two triangles, once in each direction. The non-ring
        // sides are bucketed by their smaller end (a counting sort, `O(n)`: one pass counts, a
        // second places, so no list of sides is stored in between), each bucket of more than two
        // is sorted by the larger end (buckets hold a vertex's diagonals: small but for fans), and
        // equal keys are paired. A side is (larger end, triangle, corner << 1 | [runs smaller → larger]).
        let next = |k: usize| if k == 2 { 0 } else { k + 1 };
        // `start[lo + 1]` counts first; the prefix sums then make `start[lo]` bucket `lo`'s start.
        let mut start = vec![0usize; n + 1];
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                let (u, w) = (tri[k], tri[next(k)]);
                if u as usize >= n || w as usize >= n {
                    return Err(bad(u, "a corner is not a ring vertex"));
                }
                vertex_triangle[u as usize] = t as u32;
                if succ(u as usize, n) == w as usize {
                    neighbors[t][k] = Neighbor::RingEdge(u);
                } else {
                    start[u.min(w) as usize + 1] += 1;
                }
            }
        }
        offsets_in_place(&mut start);
        let mut fill: Vec<usize> = start[..n].to_vec();
        let mut bucketed = vec![(0u32, 0u32, 0u8); start[n]];
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                let (u, w) = (tri[k], tri[next(k)]);
                if succ(u as usize, n) != w as usize {
                    let lo = u.min(w) as usize;
                    bucketed[fill[lo]] = (u.max(w), t as u32, ((k as u8) << 1) | u8::from(u < w));
                    fill[lo] += 1;
                }
            }
        }
        drop(fill);
        for lo in 0..n {
            let bucket = &mut bucketed[start[lo]..start[lo + 1]];
            if bucket.len() > 2 {
                bucket.sort_unstable_by_key(|s| s.0);
            }
            let mut i = 0;
            while i < bucket.len() {
                let (hi, t, kd) = bucket[i];
                let Some(&(_, t2, kd2)) = bucket.get(i + 1).filter(|s| s.0 == hi) else {
                    return Err(bad(lo as u32, "a diagonal has no twin"));
                };
                if kd & 1 == kd2 & 1 || bucket.get(i + 2).is_some_and(|s| s.0 == hi) {
                    return Err(bad(lo as u32, "a side appears twice"));
                }
                neighbors[t as usize][usize::from(kd >> 1)] = Neighbor::Triangle(t2);
                neighbors[t2 as usize][usize::from(kd2 >> 1)] = Neighbor::Triangle(t);
                i += 2;
            }
        }
        if let Some(v) = vertex_triangle.iter().position(|&t| t == u32::MAX) {
            return Err(bad(v as u32, "a vertex is in no triangle"));
        }
        Ok(Triangulation {
            triangles,
            neighbors,
            vertex_triangle,
        })
    }
}

/// Turns `slots`, where `slots[k + 1]` counts the items of bucket `k` and `slots[0]` is 0, into the
/// start of each bucket in a flat array, with the total at the end (prefix sums, in place): the
/// layout of the counting sorts in `glue` and `pieces`.
fn offsets_in_place(slots: &mut [usize]) {
    for k in 1..slots.len() {
        slots[k] += slots[k - 1];
    }
}

/// `i + 1 mod n` for `i < n`, without a division (the sweeps' and the gluing's hot loops).
#[inline]
fn succ(i: usize, n: usize) -> usize {
    if i + 1 == n { 0 } else { i + 1 }
}

/// `i − 1 mod n` for `i < n`, without a division.
#[inline]
fn pred(i: usize, n: usize) -> usize {
    if i == 0 { n - 1 } else { i - 1 }
}

/// The sweep order: `(x, y)` lexicographically (exact; `−0 = +0`).
pub(crate) fn lex(a: DVec2, b: DVec2) -> Ordering {
    if a.x < b.x {
        Ordering::Less
    } else if a.x > b.x {
        Ordering::Greater
    } else if a.y < b.y {
        Ordering::Less
    } else if a.y > b.y {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// Validates a ring: size, coordinates, repeated points (sorted order), orientation.
/// Returns the vertex indices in sweep order.
fn validate<K: Kernel>(ring: &[DVec2]) -> Result<Vec<usize>, TriangulationError> {
    let n = ring.len();
    if n < 3 {
        return Err(TriangulationError::TooFewVertices { count: n });
    }
    if n > u32::MAX as usize / 2 {
        return Err(TriangulationError::TooManyVertices { count: n });
    }
    if let Some(index) = ring
        .iter()
        .position(|p| !(is_valid_coordinate(p.x) && is_valid_coordinate(p.y)))
    {
        return Err(TriangulationError::InvalidCoordinate { index });
    }
    // A total order (ties broken by index), by radix sort.
    let order = lex_order(ring);
    for w in order.windows(2) {
        if lex(ring[w[0]], ring[w[1]]) == Ordering::Equal {
            return Err(TriangulationError::RepeatedVertex {
                first: w[0].min(w[1]),
                second: w[0].max(w[1]),
            });
        }
    }
    // The lexicographically smallest vertex is a convex corner of a simple polygon: it turns left
    // exactly when the ring is counter-clockwise.
    let m = order[0];
    let (p, q) = (ring[(m + n - 1) % n], ring[(m + 1) % n]);
    match K::orient(p, ring[m], q) {
        Orientation::CounterClockwise => Ok(order),
        Orientation::Clockwise => Err(TriangulationError::NotCounterClockwise),
        Orientation::Collinear => Err(TriangulationError::Degenerate { index: m }),
    }
}

/// Triangulates the simple counter-clockwise polygon `ring` (consecutive and non-consecutive
/// collinear vertices allowed) into `n − 2` strictly counter-clockwise triangles, no diagonal passing
/// through a vertex, with their adjacency.
///
/// Monotone decomposition by a lexicographic sweep with an exactly ordered status (de Berg et al.,
/// *Computational Geometry*, §3.2), then the stack algorithm on each monotone piece (§3.3), with the
/// degeneracy rules and proof of the module docs (and `docs/algorithms/triangulation.md`).
///
/// # Complexity
/// `O(n log n)` time and predicates (expected, the status is a treap with hashed priorities);
/// `O(n)` space.
///
/// # Errors
/// [`TriangulationError`]: fewer than 3 vertices (or more than `2^31`), a bad coordinate, a repeated vertex, overlapping
/// edges, a clockwise ring, or an inconsistency (a polygon that is not simple, or the Fast kernel's
/// inconsistent signs). Never panics, always terminates, under every kernel.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::triangulate;
///
/// // A square with a 180° corner in the middle of its bottom side.
/// let ring = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]].map(DVec2::from);
/// let tri = triangulate::<Robust>(&ring).unwrap();
/// assert_eq!(tri.triangles().len(), 3);
/// assert!(tri.check::<Robust>(&ring).is_ok());
/// ```
pub fn triangulate<K: Kernel>(ring: &[DVec2]) -> Result<Triangulation, TriangulationError> {
    let order = validate::<K>(ring)?;
    let n = ring.len();
    let diagonals = monotone_diagonals::<K>(ring, &order)?;
    let faces = pieces::<K>(ring, &diagonals)?;
    let mut triangles = Vec::with_capacity(n - 2);
    let mut scratch = Scratch::default();
    for f in faces.starts.windows(2) {
        let piece = &faces.verts[f[0]..f[1]];
        triangulate_monotone::<K>(ring, piece, &mut scratch, &mut triangles)?;
    }
    Triangulation::glue(n, triangles)
}

// ---------------------------------------------------------------------------------------------------
// The sweep status is the polygon crate's treap of edge ids (Seidel & Aragon 1996), whose shape never
// depends on comparator consistency.

/// No vertex (the helper of an edge not yet set).
const NIL: usize = usize::MAX;

// ---------------------------------------------------------------------------------------------------
// Phase 1: monotone decomposition.

/// The diagonals that cut the polygon into pieces monotone in the lexicographic order (de Berg et
/// al. §3.2, with "downward sweep / left of" mapped to "rightward sweep / below").
///
/// The sweep line crosses the polygon in intervals, each bounded below by a *lower* edge `k → k + 1`
/// going forward in the order (interior above) and above by an *upper* edge going backward. The
/// status holds the lower edges, and `pair` links each interval's two edges both ways. The textbook
/// searches the status at split, merge and upper-chain vertices for "the edge below"; here it is
/// the partner of an edge ending at the vertex (merge, upper-chain) and only a split vertex, which
/// lies inside an interval, searches. A start vertex searches for its place; a lower-chain vertex
/// puts its outgoing edge in its incoming edge's place ([`Treap::replace`], `O(1)`), and a split
/// vertex's new interval goes right after the one it splits ([`Treap::insert_after`]): so only the
/// local minima in the order (start and split vertices) compare.
fn monotone_diagonals<K: Kernel>(
    ring: &[DVec2],
    order: &[usize],
) -> Result<Vec<(usize, usize)>, TriangulationError> {
    let n = ring.len();
    let mut status = Treap::new(n);
    let mut helper = vec![NIL; n];
    let mut pair = vec![NIL; n];
    let mut is_merge = vec![false; n];
    let mut diagonals = Vec::new();
    let bad = |index: usize, what| TriangulationError::Inconsistent { index, what };
    // Is the point `v` above the stored edge `e` (which spans it in the sweep order)?
    let above = |e: usize, v: usize| -> Result<bool, TriangulationError> {
        match K::orient(ring[e], ring[succ(e, n)], ring[v]) {
            Orientation::CounterClockwise => Ok(true),
            Orientation::Clockwise => Ok(false),
            Orientation::Collinear => Err(bad(v, "a vertex lies on an edge")),
        }
    };
    let diagonal = |a: usize, b: usize, diagonals: &mut Vec<(usize, usize)>| {
        if a == b || succ(a, n) == b || succ(b, n) == a {
            return Err(bad(a, "a diagonal joins neighbours"));
        }
        diagonals.push((a, b));
        Ok(())
    };
    // The helper of a lower edge in the status (set whenever it is inserted).
    let helper_of = |helper: &[usize], e: usize, v: usize| match helper.get(e) {
        Some(&h) if h != NIL => Ok(h),
        _ => Err(bad(v, "an edge of the sweep has no helper")),
    };
    for &v in order {
        let (p, q) = (pred(v, n), succ(v, n));
        let after_p = lex(ring[p], ring[v]) == Ordering::Greater;
        let after_q = lex(ring[q], ring[v]) == Ordering::Greater;
        let turn = K::orient(ring[p], ring[v], ring[q]);
        // Edge `p → v` is `p`, edge `v → q` is `v`.
        match (after_p, after_q) {
            (true, true) => match turn {
                Orientation::Collinear => return Err(TriangulationError::Degenerate { index: v }),
                Orientation::CounterClockwise => {
                    // Start vertex: a new interval, lower edge `v`, upper edge `p`.
                    status.insert(v, |e| {
                        above(e, v).map(|b| if b { Ordering::Greater } else { Ordering::Less })
                    })?;
                    (pair[v], pair[p], helper[v]) = (p, v, v);
                }
                Orientation::Clockwise => {
                    // Split vertex, inside the interval (l, u): join it to the helper of `l`; the
                    // interval becomes (l, p) below and (v, u) above.
                    let l = status
                        .last_where(|e| above(e, v))?
                        .ok_or_else(|| bad(v, "no edge below a split vertex"))?;
                    let u = pair[l];
                    diagonal(v, helper_of(&helper, l, v)?, &mut diagonals)?;
                    if u == NIL || !status.insert_after(l, v) {
                        return Err(bad(v, "a split vertex's interval is not in the status"));
                    }
                    (pair[l], pair[p], helper[l]) = (p, l, v);
                    (pair[v], pair[u], helper[v]) = (u, v, v);
                }
            },
            (false, false) => {
                if turn == Orientation::Collinear {
                    return Err(TriangulationError::Degenerate { index: v });
                }
                // Lower edge `p` ends (interval (p, pair[p])).
                let h = helper_of(&helper, p, v)?;
                if !status.remove(p) {
                    return Err(bad(v, "an ending edge is not in the status"));
                }
                if is_merge[h] {
                    diagonal(v, h, &mut diagonals)?;
                }
                if turn == Orientation::CounterClockwise {
                    // End vertex: the interval (p, v) closes.
                    if pair[p] != v {
                        return Err(bad(v, "an end vertex's edges bound different intervals"));
                    }
                } else {
                    // Merge vertex: (l, v) below and (p, u) above become (l, u).
                    is_merge[v] = true;
                    let (l, u) = (pair[v], pair[p]);
                    if l == NIL || u == NIL {
                        return Err(bad(v, "a merge vertex's intervals are not in the sweep"));
                    }
                    let hl = helper_of(&helper, l, v)?;
                    if is_merge[hl] {
                        diagonal(v, hl, &mut diagonals)?;
                    }
                    (pair[l], pair[u], helper[l]) = (u, l, v);
                }
            }
            (false, true) => {
                // Lower-chain vertex: edge `v` takes the place of edge `p` under the same upper edge.
                let h = helper_of(&helper, p, v)?;
                let u = pair[p];
                if u == NIL || !status.replace(p, v) {
                    return Err(bad(v, "an ending edge is not in the status"));
                }
                if is_merge[h] {
                    diagonal(v, h, &mut diagonals)?;
                }
                (pair[v], pair[u], helper[v]) = (u, v, v);
            }
            (true, false) => {
                // Upper-chain vertex: edge `p` takes the place of edge `v` above the lower edge `l`.
                let l = pair[v];
                if l == NIL {
                    return Err(bad(v, "an ending edge is not in the sweep"));
                }
                let hl = helper_of(&helper, l, v)?;
                if is_merge[hl] {
                    diagonal(v, hl, &mut diagonals)?;
                }
                (pair[l], pair[p], helper[l]) = (p, l, v);
            }
        }
    }
    Ok(diagonals)
}

/// The position of the direction `v → x` in the counter-clockwise turn from the direction `v → q`:
/// 0 for angles in `(0, π)`, 1 for `π`, 2 for `(π, 2π)` (angle 0 is an error: `x` on the edge).
fn half<K: Kernel>(v: DVec2, q: DVec2, x: DVec2) -> Option<u8> {
    match K::orient(v, q, x) {
        Orientation::CounterClockwise => Some(0),
        Orientation::Clockwise => Some(2),
        Orientation::Collinear => (K::dot_sign(v, q, v, x) == Sign::Negative).then_some(1),
    }
}

/// Faces stored back to back: face `f` is `verts[starts[f]..starts[f + 1]]`.
struct Faces {
    verts: Vec<usize>,
    starts: Vec<usize>,
}

/// Cuts the polygon along `diagonals` and returns the faces, each a counter-clockwise list of ring
/// indices. Around each vertex the outgoing sides are ordered counter-clockwise from the ring edge
/// `v → v + 1`; a face turns, at each vertex, to the side just clockwise of the one it came in by.
fn pieces<K: Kernel>(
    ring: &[DVec2],
    diagonals: &[(usize, usize)],
) -> Result<Faces, TriangulationError> {
    let n = ring.len();
    let bad = |index: usize, what| TriangulationError::Inconsistent { index, what };
    // Outgoing sides per vertex, in one flat array (vertex v owns out[offsets[v]..offsets[v + 1]]):
    // slot 0 is the ring edge to v + 1, then the diagonals by angle.
    let mut offsets = vec![1usize; n + 1];
    offsets[0] = 0;
    for &(a, b) in diagonals {
        if a >= n || b >= n {
            return Err(bad(a.min(b), "a diagonal end is not a ring vertex"));
        }
        offsets[a + 1] += 1;
        offsets[b + 1] += 1;
    }
    offsets_in_place(&mut offsets);
    let total = offsets[n];
    let mut out = vec![usize::MAX; total];
    let mut fill: Vec<usize> = offsets[..n].iter().map(|&o| o + 1).collect();
    for v in 0..n {
        out[offsets[v]] = succ(v, n);
    }
    for &(a, b) in diagonals {
        out[fill[a]] = b;
        fill[a] += 1;
        out[fill[b]] = a;
        fill[b] += 1;
    }
    let mut keys: Vec<(u8, usize)> = Vec::new();
    for v in 0..n {
        let list = &mut out[offsets[v]..offsets[v + 1]];
        if list.len() <= 2 {
            if list.len() == 2 && half::<K>(ring[v], ring[list[0]], ring[list[1]]).is_none() {
                return Err(bad(v, "a diagonal runs along an edge"));
            }
            continue;
        }
        // Insertion sort (a handful of diagonals): never panics on an inconsistent comparator.
        let (pv, q) = (ring[v], ring[list[0]]);
        keys.clear();
        for &x in &list[1..] {
            let h =
                half::<K>(pv, q, ring[x]).ok_or_else(|| bad(v, "a diagonal runs along an edge"))?;
            keys.push((h, x));
        }
        for i in 1..keys.len() {
            let mut j = i;
            while j > 0 {
                let (a, b) = (keys[j - 1], keys[j]);
                let before = match a.0.cmp(&b.0) {
                    Ordering::Less => true,
                    Ordering::Greater => false,
                    Ordering::Equal => match K::orient(pv, ring[a.1], ring[b.1]) {
                        Orientation::CounterClockwise => true,
                        Orientation::Clockwise => false,
                        Orientation::Collinear => {
                            return Err(bad(v, "two diagonals leave in one direction"));
                        }
                    },
                };
                if before {
                    break;
                }
                keys.swap(j - 1, j);
                j -= 1;
            }
        }
        for (slot, &(_, x)) in list[1..].iter_mut().zip(&keys) {
            *slot = x;
        }
    }
    let sides = |v: usize| &out[offsets[v]..offsets[v + 1]];
    let mut used = vec![false; total];
    // Each side is in exactly one face: `total` vertices in all.
    let mut faces = Faces {
        verts: Vec::with_capacity(total),
        starts: Vec::with_capacity(diagonals.len() + 2),
    };
    faces.starts.push(0);
    for start_v in 0..n {
        for start_slot in 0..sides(start_v).len() {
            if used[offsets[start_v] + start_slot] {
                continue;
            }
            let start = faces.verts.len();
            let (mut v, mut slot) = (start_v, start_slot);
            loop {
                let id = offsets[v] + slot;
                if used[id] {
                    if v == start_v && slot == start_slot {
                        break;
                    }
                    return Err(bad(v, "faces do not close"));
                }
                used[id] = true;
                faces.verts.push(v);
                if faces.verts.len() - start > n {
                    return Err(bad(v, "a face is longer than the ring"));
                }
                let w = out[id];
                // Coming into w from v: take the side just clockwise of w → v.
                slot = if pred(w, n) == v {
                    sides(w).len() - 1
                } else {
                    match sides(w).iter().position(|&x| x == v) {
                        Some(pos) if pos >= 1 => pos - 1,
                        _ => return Err(bad(w, "a diagonal is missing its twin")),
                    }
                };
                v = w;
            }
            if faces.verts.len() - start < 3 {
                return Err(bad(start_v, "a face with fewer than 3 vertices"));
            }
            faces.starts.push(faces.verts.len());
        }
    }
    Ok(faces)
}

// ---------------------------------------------------------------------------------------------------
// Phase 2: the stack algorithm on a monotone piece.

/// Which chain of a monotone piece a vertex is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Chain {
    /// The chain from the first to the last vertex counter-clockwise (interior above).
    Lower,
    /// The other chain (interior below).
    Upper,
    /// The first or last vertex.
    Both,
}

/// Working space of [`triangulate_monotone`], reused from piece to piece.
#[derive(Default)]
struct Scratch {
    lower: Vec<usize>,
    upper: Vec<usize>,
    seq: Vec<(usize, Chain)>,
    stack: Vec<(usize, Chain)>,
}

/// Triangulates a piece monotone in the lexicographic order (a counter-clockwise list of ring
/// indices), pushing strictly counter-clockwise triangles (de Berg et al. §3.3, strict pops).
fn triangulate_monotone<K: Kernel>(
    ring: &[DVec2],
    piece: &[usize],
    scratch: &mut Scratch,
    out: &mut Vec<[u32; 3]>,
) -> Result<(), TriangulationError> {
    let Scratch {
        lower,
        upper,
        seq,
        stack,
    } = scratch;
    let m = piece.len();
    let bad = |index: usize, what| TriangulationError::Inconsistent { index, what };
    let pt = |i: usize| ring[i];
    let lo = (0..m)
        .min_by(|&a, &b| lex(pt(piece[a]), pt(piece[b])))
        .unwrap_or(0);
    let hi = (0..m)
        .max_by(|&a, &b| lex(pt(piece[a]), pt(piece[b])))
        .unwrap_or(0);
    // The lower chain lo → hi (forward), the upper chain hi → lo (forward), reversed.
    lower.clear();
    let mut i = (lo + 1) % m;
    while i != hi {
        lower.push(piece[i]);
        i = (i + 1) % m;
    }
    upper.clear();
    let mut i = (hi + 1) % m;
    while i != lo {
        upper.push(piece[i]);
        i = (i + 1) % m;
    }
    upper.reverse();
    let monotone = |c: &[usize]| {
        c.windows(2)
            .all(|w| lex(pt(w[0]), pt(w[1])) == Ordering::Less)
    };
    if !monotone(lower) || !monotone(upper) {
        return Err(bad(piece[lo], "a piece is not monotone"));
    }
    // Merge the chains in sweep order.
    seq.clear();
    seq.push((piece[lo], Chain::Both));
    let (mut a, mut b) = (0, 0);
    while a < lower.len() || b < upper.len() {
        let take_lower = b == upper.len()
            || (a < lower.len() && lex(pt(lower[a]), pt(upper[b])) == Ordering::Less);
        if take_lower {
            seq.push((lower[a], Chain::Lower));
            a += 1;
        } else {
            seq.push((upper[b], Chain::Upper));
            b += 1;
        }
    }
    seq.push((piece[hi], Chain::Both));
    let mut emit = |x: usize, y: usize, z: usize| {
        if K::orient(pt(x), pt(y), pt(z)) != Orientation::CounterClockwise {
            return Err(bad(x, "a fan triangle is not strictly ccw"));
        }
        out.push([x as u32, y as u32, z as u32]);
        Ok(())
    };
    // Fan from `u` (on the chain opposite `side`) over the stack.
    let fan = |u: usize,
               side: Chain,
               stack: &[(usize, Chain)],
               emit: &mut dyn FnMut(usize, usize, usize) -> Result<(), TriangulationError>|
     -> Result<(), TriangulationError> {
        for w in stack.windows(2) {
            let (s0, s1) = (w[0].0, w[1].0);
            if side == Chain::Lower {
                emit(s0, s1, u)?;
            } else {
                emit(s0, u, s1)?;
            }
        }
        Ok(())
    };
    stack.clear();
    stack.extend_from_slice(&seq[..2]);
    for &(u, chain) in &seq[2..m - 1] {
        let (top, top_chain) = stack[stack.len() - 1];
        if chain != top_chain {
            fan(u, top_chain, stack, &mut emit)?;
            stack.clear();
            stack.push((top, top_chain));
            stack.push((u, chain));
        } else {
            let mut last = stack.pop().ok_or_else(|| bad(u, "empty stack"))?;
            while let Some(&below) = stack.last() {
                // Pop `last` only when it is a strictly convex corner of the remaining polygon.
                let turn = K::orient(pt(below.0), pt(last.0), pt(u));
                let convex = match chain {
                    Chain::Lower => turn == Orientation::CounterClockwise,
                    _ => turn == Orientation::Clockwise,
                };
                if !convex {
                    break;
                }
                if chain == Chain::Lower {
                    emit(below.0, last.0, u)?;
                } else {
                    emit(below.0, u, last.0)?;
                }
                last = below;
                stack.pop();
            }
            stack.push(last);
            stack.push((u, chain));
        }
    }
    let (last, _) = seq[m - 1];
    let top_chain = stack[stack.len() - 1].1;
    fan(last, top_chain, stack, &mut emit)?;
    Ok(())
}

// ---------------------------------------------------------------------------------------------------
// The brute-force twin.

/// Triangulates `ring` by ear clipping with exact predicates: repeatedly cuts off a strictly convex
/// corner whose closed triangle holds no other remaining vertex. For testing (the reference of
/// [`triangulate`]); same output conventions and errors.
///
/// # Complexity
/// `O(n³)` predicates worst case.
///
/// # Errors
/// As [`triangulate`]; a ring where no ear is found is [`TriangulationError::Inconsistent`].
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::triangulate_brute;
///
/// let ring = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 1.0], [0.0, 4.0]].map(DVec2::from);
/// let tri = triangulate_brute::<Robust>(&ring).unwrap();
/// assert!(tri.check::<Robust>(&ring).is_ok());
/// ```
pub fn triangulate_brute<K: Kernel>(ring: &[DVec2]) -> Result<Triangulation, TriangulationError> {
    validate::<K>(ring)?;
    let n = ring.len();
    let mut rest: Vec<usize> = (0..n).collect();
    let mut triangles = Vec::with_capacity(n - 2);
    while rest.len() > 3 {
        let r = rest.len();
        let ear = (0..r).find(|&i| {
            let (a, b, c) = (rest[(i + r - 1) % r], rest[i], rest[(i + 1) % r]);
            let (pa, pb, pc) = (ring[a], ring[b], ring[c]);
            K::orient(pa, pb, pc) == Orientation::CounterClockwise
                && rest.iter().all(|&x| {
                    x == a
                        || x == b
                        || x == c
                        || K::orient(pa, pb, ring[x]) == Orientation::Clockwise
                        || K::orient(pb, pc, ring[x]) == Orientation::Clockwise
                        || K::orient(pc, pa, ring[x]) == Orientation::Clockwise
                })
        });
        let Some(i) = ear else {
            return Err(TriangulationError::Inconsistent {
                index: rest[0],
                what: "no ear",
            });
        };
        triangles.push([
            rest[(i + r - 1) % r] as u32,
            rest[i] as u32,
            rest[(i + 1) % r] as u32,
        ]);
        rest.remove(i);
    }
    let [a, b, c] = [rest[0], rest[1], rest[2]].map(|i| ring[i]);
    if K::orient(a, b, c) != Orientation::CounterClockwise {
        return Err(TriangulationError::Inconsistent {
            index: rest[0],
            what: "the last triangle is not ccw",
        });
    }
    triangles.push([rest[0] as u32, rest[1] as u32, rest[2] as u32]);
    Triangulation::glue(n, triangles)
}

#[cfg(test)]
mod tests {
    //! `glue`'s pairing of diagonals, on hand-made triangle lists (the rest of this module is tested
    //! through `tests/geodesic.rs`).
    use super::*;

    #[test]
    fn glue_pairs_each_diagonal_with_its_twin() {
        // A hexagon fanned from vertex 0: diagonals 0–2, 0–3, 0–4.
        let t = Triangulation::glue(6, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]])
            .expect("a fan");
        assert_eq!(
            t.neighbors()[1],
            [
                Neighbor::Triangle(0),
                Neighbor::RingEdge(2),
                Neighbor::Triangle(2)
            ]
        );
        assert_eq!(t.neighbors()[0][2], Neighbor::Triangle(1));
        assert_eq!(t.neighbors()[3][0], Neighbor::Triangle(2));
        assert_eq!(t.neighbors()[3][2], Neighbor::RingEdge(5));
    }

    /// A star-shaped ring: `k` spikes of radius 3 between notches of radius 1 (counter-clockwise).
    fn star(k: usize) -> Vec<DVec2> {
        (0..2 * k)
            .map(|i| {
                let a = std::f64::consts::PI * i as f64 / k as f64;
                let r = if i % 2 == 0 { 3.0 } else { 1.0 };
                DVec2::new(r * a.cos(), r * a.sin())
            })
            .collect()
    }

    #[test]
    fn rotated_and_joined_match_glue() {
        use polydist_polygon::predicates::Robust;
        let ring = star(9);
        let n = ring.len();
        let t = triangulate::<Robust>(&ring).expect("a star");
        for off in [0, 1, 5, n - 1] {
            let rot: Vec<DVec2> = (0..n).map(|i| ring[(i + off) % n]).collect();
            let relabel = |j: u32| ((j as usize + n - off) % n) as u32;
            let tris = t.triangles().iter().map(|c| c.map(relabel)).collect();
            let glued = Triangulation::glue(n, tris).expect("relabelled");
            let r = t.rotated(off);
            assert_eq!(
                (r.triangles(), r.neighbors()),
                (glued.triangles(), glued.neighbors())
            );
            assert_eq!(r.check::<Robust>(&rot), Ok(()));
        }
        // Cut the star along chords between notches (inside the notches' convex 9-gon), one cutting off a single spike.
        for (w, u) in [(1usize, 11usize), (3, 9), (1, 3)] {
            let h1: Vec<usize> = (w..=u).collect();
            let h2: Vec<usize> = (u..n).chain(0..=w).collect();
            let pts = |h: &[usize]| h.iter().map(|&i| ring[i]).collect::<Vec<DVec2>>();
            let t1 = triangulate::<Robust>(&pts(&h1)).expect("a simple half");
            let t2 = triangulate::<Robust>(&pts(&h2)).expect("a simple half");
            let mut tris = Vec::new();
            for (h, tr) in [(&h1, &t1), (&h2, &t2)] {
                tris.extend(
                    tr.triangles()
                        .iter()
                        .map(|c| c.map(|i| h[i as usize] as u32)),
                );
            }
            let glued = Triangulation::glue(n, tris).expect("two halves");
            let j = Triangulation::joined(n, (&h1, &t1), (&h2, &t2)).expect("they fit");
            assert_eq!(
                (j.triangles(), j.neighbors()),
                (glued.triangles(), glued.neighbors())
            );
            assert_eq!(j.check::<Robust>(&ring), Ok(()));
            // Halves that do not share their closing side are refused.
            assert!(Triangulation::joined(n, (&h1, &t1), (&h1, &t1)).is_none());
        }
    }

    #[test]
    fn glue_rejects_inconsistent_triangle_lists() {
        let err = |tris: Vec<[u32; 3]>, n| match Triangulation::glue(n, tris) {
            Err(TriangulationError::Inconsistent { what, .. }) => what,
            other => panic!("expected an inconsistency, got {other:?}"),
        };
        // Diagonals 0–2 and 1–3, each on one side only.
        assert_eq!(err(vec![[0, 1, 2], [0, 1, 3]], 4), "a diagonal has no twin");
        // The same diagonal twice in one direction.
        assert_eq!(err(vec![[0, 1, 2], [2, 0, 1]], 4), "a side appears twice");
        assert_eq!(err(vec![[0, 1, 2]], 4), "wrong number of triangles");
        assert_eq!(
            err(vec![[0, 1, 9], [0, 2, 3]], 4),
            "a corner is not a ring vertex"
        );
    }
}
