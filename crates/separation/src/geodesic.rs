//! Geodesics (shortest paths inside a simple polygon) and ray shooting, on a [`Triangulation`].
//!
//! * [`shortest_path`]: the shortest path in the closed polygon between two ring vertices, by the
//!   dual-tree path between the two vertices' triangles (the *sleeve*) and the funnel algorithm
//!   (Lee & Preparata, "Euclidean shortest paths in the presence of rectilinear barriers", Networks
//!   14, 1984; Hershberger & Snoeyink, "Computing minimum length paths of a given homotopy class",
//!   CGTA 4, 1994, §2). `O(n)`.
//! * [`first_hit`]: the first boundary point met by the prolongation of a segment beyond a ring
//!   vertex, by walking the triangulation along the ray. `O(k)` for `k` triangles crossed (not
//!   linear in the worst case over all arms of a path: `Θ(n²)` in all; [`extensions`](crate::extensions)
//!   gives every arm of a shortest-path tree in `O(n)`, and the separator switches to it when
//!   its walks grow long).
//!
//! Every decision is the exact sign of a degree-2 polynomial of input coordinates through the kernel
//! `K`: orientations of three ring vertices, and the cross and dot signs of `(a − w)` against the ray
//! direction `(w − f)`. Lengths are never compared except in the brute-force twin
//! [`shortest_path_brute`] (Dijkstra on `f64` lengths, a test reference only).
//!
//! Degeneracies: the funnel keeps a chain vertex only on a strict turn, so a path that grazes
//! vertices on a line goes straight through them, and the output keeps only vertices where the path
//! turns strictly (a final pass drops the middle of any three collinear consecutive vertices). A ray
//! that passes exactly through a vertex stops there ([`Hit::Vertex`]); every triangulation vertex is
//! a boundary vertex, so the walk needs no other special case.

use std::collections::VecDeque;

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Orientation, Sign};

use crate::triangulate::{Neighbor, Triangulation};

/// The first boundary point met by an arm (see [`first_hit`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Hit {
    /// The ray passes exactly through ring vertex `v` (and meets no boundary point before it).
    Vertex(usize),
    /// The ray crosses the relative interior of ring edge `k` (from vertex `k` to `k + 1 mod n`).
    Edge(usize),
    /// The ray does not enter the open interior at its start (its direction points outside, or
    /// along one of the two edges at the vertex): the arm has zero length.
    Immediate,
}

/// The shortest path inside the closed polygon `ring` from ring vertex `s` to ring vertex `t`, as
/// the ring indices `s, …, t` of the vertices where it turns strictly (collinear runs merged).
///
/// Dual-tree path between a triangle at `s` and a triangle at `t` (breadth-first search over the
/// triangles), then the funnel algorithm over the diagonals crossed (Lee–Preparata 1984;
/// Hershberger–Snoeyink 1994 §2), deciding with exact orientations only. `tri` must be a
/// triangulation of `ring` (from [`triangulate`](fn@crate::triangulate)).
///
/// # Complexity
/// `O(n)` time and predicates.
///
/// # Panics
/// Panics if `s` or `t` is not a vertex index of `ring`, or `tri` was built for another ring size.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::{shortest_path, triangulate};
///
/// // A U: from the tip of the left arm to the tip of the right arm, around the notch's floor.
/// let ring = [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
///     .map(DVec2::from);
/// let tri = triangulate::<Robust>(&ring).unwrap();
/// assert_eq!(shortest_path::<Robust>(&tri, &ring, 6, 3), vec![6, 5, 4, 3]);
/// ```
#[must_use]
pub fn shortest_path<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    s: usize,
    t: usize,
) -> Vec<usize> {
    let n = ring.len();
    assert!(s < n && t < n, "shortest_path: vertex index out of range");
    assert_eq!(
        tri.vertex_count(),
        n,
        "shortest_path: triangulation of another ring"
    );
    if s == t {
        return vec![s];
    }
    let triangles = tri.triangles();
    let neighbors = tri.neighbors();
    // Breadth-first search from every triangle at s to the first triangle at t.
    let m = triangles.len();
    let mut parent = vec![usize::MAX; m];
    let mut queue = VecDeque::new();
    for (i, tr) in triangles.iter().enumerate() {
        if tr.contains(&(s as u32)) {
            parent[i] = i;
            queue.push_back(i);
        }
    }
    let mut goal = None;
    while let Some(i) = queue.pop_front() {
        if triangles[i].contains(&(t as u32)) {
            goal = Some(i);
            break;
        }
        for nb in neighbors[i] {
            if let Neighbor::Triangle(j) = nb {
                let j = j as usize;
                if parent[j] == usize::MAX {
                    parent[j] = i;
                    queue.push_back(j);
                }
            }
        }
    }
    let Some(mut cur) = goal else {
        // Unreachable for a triangulation of a simple polygon (its dual is a connected tree).
        return vec![s, t];
    };
    let mut sleeve = vec![cur];
    while parent[cur] != cur {
        cur = parent[cur];
        sleeve.push(cur);
    }
    sleeve.reverse();
    // Portals: the diagonal between consecutive sleeve triangles, (left, right) seen travelling.
    let mut portals = Vec::with_capacity(sleeve.len());
    for w in sleeve.windows(2) {
        let (a, b) = (w[0], w[1]);
        if let Some(k) = (0..3).find(|&k| neighbors[a][k] == Neighbor::Triangle(b as u32)) {
            let tr = triangles[a];
            portals.push((tr[(k + 1) % 3] as usize, tr[k] as usize));
        }
    }
    let mut funnel = Funnel::<K> {
        ring,
        dq: VecDeque::from([s]),
        apex: 0,
        path: vec![s],
        _k: core::marker::PhantomData,
    };
    for (l, r) in portals {
        if funnel.dq.front() != Some(&l) {
            funnel.add_left(l);
        }
        if funnel.dq.back() != Some(&r) {
            funnel.add_right(r);
        }
    }
    funnel.add_left(t);
    let Funnel {
        dq, apex, mut path, ..
    } = funnel;
    path.extend((0..apex).rev().map(|i| dq[i]));
    merge_collinear::<K>(ring, &path)
}

/// The funnel: a deque `[l_m, …, l_1, apex, r_1, …, r_k]` of ring indices, the left chain turning
/// left and the right chain turning right (strictly) going outward from the apex.
struct Funnel<'a, K> {
    ring: &'a [DVec2],
    dq: VecDeque<usize>,
    apex: usize,
    path: Vec<usize>,
    _k: core::marker::PhantomData<K>,
}

impl<K: Kernel> Funnel<'_, K> {
    fn orient(&self, a: usize, b: usize, c: usize) -> Orientation {
        K::orient(self.ring[a], self.ring[b], self.ring[c])
    }

    /// A new left portal end `v`. Each pass pops one deque entry, so at most `len` passes.
    fn add_left(&mut self, v: usize) {
        while !self.dq.is_empty() {
            if self.apex > 0 {
                // Keep the outer left vertex only if the chain turns strictly left at it.
                if self.orient(self.dq[1], self.dq[0], v) == Orientation::CounterClockwise {
                    break;
                }
                self.dq.pop_front();
                self.apex -= 1;
            } else if self.apex + 1 < self.dq.len() {
                // The left side crosses the right chain's first segment: the apex moves along it.
                let (a, r1) = (self.dq[0], self.dq[1]);
                if self.orient(a, r1, v) == Orientation::CounterClockwise {
                    break;
                }
                self.dq.pop_front();
                self.path.push(r1);
            } else {
                break;
            }
        }
        self.dq.push_front(v);
        self.apex += 1;
    }

    /// A new right portal end `v` (the mirror of [`Self::add_left`]).
    fn add_right(&mut self, v: usize) {
        while !self.dq.is_empty() {
            let len = self.dq.len();
            if self.apex + 1 < len {
                if self.orient(self.dq[len - 2], self.dq[len - 1], v) == Orientation::Clockwise {
                    break;
                }
                self.dq.pop_back();
            } else if self.apex > 0 {
                let (a, l1) = (self.dq[self.apex], self.dq[self.apex - 1]);
                if self.orient(a, l1, v) == Orientation::Clockwise {
                    break;
                }
                self.dq.pop_back();
                self.apex -= 1;
                self.path.push(l1);
            } else {
                break;
            }
        }
        self.dq.push_back(v);
    }
}

/// Drops the middle of every three consecutive collinear vertices (exact orientation).
pub(crate) fn merge_collinear<K: Kernel>(ring: &[DVec2], path: &[usize]) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::with_capacity(path.len());
    for &v in path {
        if out.last() == Some(&v) {
            continue;
        }
        while out.len() >= 2
            && K::orient(ring[out[out.len() - 2]], ring[out[out.len() - 1]], ring[v])
                == Orientation::Collinear
        {
            out.pop();
        }
        out.push(v);
    }
    out
}

/// `sign((a − w) × (w − f))`: positive when the ray direction `w − f` is counter-clockwise of
/// the direction `w → a`.
fn dir_cross<K: Kernel>(w: DVec2, a: DVec2, f: DVec2) -> Sign {
    // `a == f` (the corner is the segment's own start, common: the run is often a triangulation
    // side) is an exact zero, which the Robust filter cannot certify without exact arithmetic.
    if a == f {
        return Sign::Zero;
    }
    K::cross_sign(w, a, f, w)
}

/// Whether the direction `w − f` points strictly into the interior angle at ring vertex `v`
/// (from `v → v+1` counter-clockwise to `v → v−1`).
pub(crate) fn enters<K: Kernel>(ring: &[DVec2], f: DVec2, v: usize) -> bool {
    let n = ring.len();
    let (w, q, p) = (ring[v], ring[(v + 1) % n], ring[(v + n - 1) % n]);
    let (cq, cp) = (dir_cross::<K>(w, q, f), dir_cross::<K>(w, p, f));
    match K::orient(w, q, p) {
        Orientation::CounterClockwise => cq == Sign::Positive && cp == Sign::Negative,
        Orientation::Clockwise => !(cp != Sign::Negative && cq != Sign::Positive),
        Orientation::Collinear => cq == Sign::Positive,
    }
}

/// The prolongation ("arm") of the segment `from → through` beyond ring vertex `through`: the ray
/// from `ring[through]` in direction `ring[through] − ring[from]`, and the first point of the
/// polygon's boundary it meets strictly after `through`.
///
/// Walks the triangulation: the triangle at `through` whose angle holds the direction, then across
/// the side the ray leaves by, until a ring edge or a vertex on the ray. Decisions: `orient(from,
/// through, z)` for triangle corners `z`, and the cross and dot signs of corner directions against
/// the ray (degree 2). `from == through` has no direction and gives [`Hit::Immediate`].
///
/// # Complexity
/// `O(d + k)` for `d` triangles at `through` and `k` triangles crossed; `O(n)` worst case per call.
///
/// # Panics
/// Panics if `from` or `through` is not a vertex index of `ring`, or `tri` was built for another
/// ring size.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::{Hit, first_hit, triangulate};
///
/// let ring = [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
///     .map(DVec2::from);
/// let tri = triangulate::<Robust>(&ring).unwrap();
/// // The floor of the notch, prolonged to the left from (1, 1), runs into the left wall x = 0.
/// assert_eq!(first_hit::<Robust>(&tri, &ring, 4, 5), Hit::Edge(7));
/// // The left wall of the notch, prolonged downward beyond (1, 1), runs into the bottom edge.
/// assert_eq!(first_hit::<Robust>(&tri, &ring, 6, 5), Hit::Edge(0));
/// // Prolonged upward beyond the tip (1, 3), it leaves the polygon at once.
/// assert_eq!(first_hit::<Robust>(&tri, &ring, 5, 6), Hit::Immediate);
/// ```
#[must_use]
pub fn first_hit<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    from: usize,
    through: usize,
) -> Hit {
    let mut unlimited = usize::MAX;
    first_hit_within::<K>(tri, ring, from, through, &mut unlimited).unwrap_or(Hit::Immediate)
}

/// [`first_hit`] with a budget of triangle steps, decremented by the steps taken; `None` when the
/// walk would exceed it (the budget is then spent).
pub(crate) fn first_hit_within<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    from: usize,
    through: usize,
    budget: &mut usize,
) -> Option<Hit> {
    let n = ring.len();
    assert!(
        from < n && through < n,
        "first_hit: vertex index out of range"
    );
    assert_eq!(
        tri.vertex_count(),
        n,
        "first_hit: triangulation of another ring"
    );
    if from == through {
        return Some(Hit::Immediate);
    }
    hit_beyond::<K>(tri, ring, ring[from], through, budget)
}

/// [`first_hit_within`] for the ray from ring vertex `through` in direction `ring[through] − f`,
/// `f` any point other than `ring[through]` (a vertex of another ring, for the pockets of
/// [`crate::pockets`]).
pub(crate) fn hit_beyond<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    f: DVec2,
    through: usize,
    budget: &mut usize,
) -> Option<Hit> {
    let w = ring[through];
    if f == w || !enters::<K>(ring, f, through) {
        return Some(Hit::Immediate);
    }
    let triangles = tri.triangles();
    let neighbors = tri.neighbors();
    let v = through as u32;
    let corner = |t: usize| (0..3).find(|&c| triangles[t][c] == v).unwrap_or(0);
    // Rewind clockwise around `through` to the triangle on the ring edge through → through + 1.
    let mut cur = on_ring_edge(tri, through);
    // Forward counter-clockwise until the triangle whose angle [x, y) holds the direction.
    let mut found = None;
    for _ in 0..triangles.len() {
        let c = corner(cur);
        let (x, y) = (
            triangles[cur][(c + 1) % 3] as usize,
            triangles[cur][(c + 2) % 3] as usize,
        );
        let cx = dir_cross::<K>(w, ring[x], f);
        if cx == Sign::Zero && K::dot_sign(w, ring[x], f, w) == Sign::Positive {
            return Some(Hit::Vertex(x));
        }
        if cx == Sign::Positive && dir_cross::<K>(w, ring[y], f) == Sign::Negative {
            found = Some((cur, (c + 1) % 3, y));
            break;
        }
        match neighbors[cur][(c + 2) % 3] {
            Neighbor::Triangle(j) => cur = j as usize,
            Neighbor::RingEdge(_) => break,
        }
    }
    let Some((cur, side, l)) = found else {
        // Only under inconsistent signs (Fast): the direction entered but no triangle holds it.
        return Some(Hit::Immediate);
    };
    walk::<K>(tri, ring, (f, w), (cur, side, l), budget)
}

/// The first boundary point met by the line through `f` and `w` (`f ≠ w`), from the point where
/// it crosses ring edge `k` into the polygon onwards: the triangle on edge `k`, then across the
/// side the line leaves by, as [`first_hit_within`]. The caller knows that the line crosses edge
/// `k`'s relative interior, entering the polygon there in direction `w − f`. `None` when the walk
/// would exceed `budget` triangle steps.
///
/// # Complexity
/// `O(d + k)` for `d` triangles at vertex `k` and `k` triangles crossed.
pub(crate) fn hit_across<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    (f, w): (DVec2, DVec2),
    k: usize,
    budget: &mut usize,
) -> Option<Hit> {
    let triangles = tri.triangles();
    let neighbors = tri.neighbors();
    let cur = on_ring_edge(tri, k);
    let s = (0..3)
        .find(|&c| triangles[cur][c] as usize == k)
        .unwrap_or(0);
    if neighbors[cur][s] != Neighbor::RingEdge(k as u32) {
        return Some(Hit::Immediate);
    }
    // Entering across side `s` (from `k`, on the line's left, to `k + 1`): the third corner
    // decides the side the line leaves by, as in the walk.
    let tr = triangles[cur];
    let z = tr[(s + 2) % 3] as usize;
    match K::orient(f, w, ring[z]) {
        Orientation::Collinear => Some(Hit::Vertex(z)),
        Orientation::Clockwise => walk::<K>(tri, ring, (f, w), (cur, (s + 2) % 3, k), budget),
        Orientation::CounterClockwise => {
            walk::<K>(tri, ring, (f, w), (cur, (s + 1) % 3, z), budget)
        }
    }
}

/// The triangle whose side from ring vertex `v` to `v + 1` is that ring edge: clockwise around `v`
/// from any triangle at it. `O(d)` for the `d` triangles at `v` (bounded by the triangle count, so
/// it ends on an inconsistent triangulation too).
fn on_ring_edge(tri: &Triangulation, v: usize) -> usize {
    let (triangles, neighbors) = (tri.triangles(), tri.neighbors());
    let corner = |t: usize| (0..3).find(|&c| triangles[t][c] as usize == v).unwrap_or(0);
    let mut cur = tri.triangle_at(v);
    for _ in 0..triangles.len() {
        match neighbors[cur][corner(cur)] {
            Neighbor::Triangle(j) => cur = j as usize,
            Neighbor::RingEdge(_) => break,
        }
    }
    cur
}

/// The walk of [`first_hit_within`] from triangle `cur`, about to leave it across side `side`,
/// whose end `l` lies left of the line `f → w`.
fn walk<K: Kernel>(
    tri: &Triangulation,
    ring: &[DVec2],
    (f, w): (DVec2, DVec2),
    (mut cur, mut side, mut l): (usize, usize, usize),
    budget: &mut usize,
) -> Option<Hit> {
    let triangles = tri.triangles();
    let neighbors = tri.neighbors();
    // The dual graph is a tree and the walk never leaves by the side it came in, so it visits each
    // triangle at most once.
    for _ in 0..triangles.len() {
        if *budget == 0 {
            return None;
        }
        *budget -= 1;
        match neighbors[cur][side] {
            Neighbor::RingEdge(k) => return Some(Hit::Edge(k as usize)),
            Neighbor::Triangle(j) => {
                let j = j as usize;
                let tr = triangles[j];
                let i = (0..3).find(|&i| tr[i] as usize == l).unwrap_or(0);
                let z = tr[(i + 2) % 3] as usize;
                match K::orient(f, w, ring[z]) {
                    Orientation::Collinear => return Some(Hit::Vertex(z)),
                    Orientation::Clockwise => side = (i + 2) % 3,
                    Orientation::CounterClockwise => {
                        l = z;
                        side = (i + 1) % 3;
                    }
                }
                cur = j;
            }
        }
    }
    Some(Hit::Immediate)
}

// ---------------------------------------------------------------------------------------------------
// Brute-force twins (test references).

/// Whether the closed segment between ring vertices `a` and `b` lies in the closed polygon `ring`
/// (exact): split at the vertices lying on it, each piece must leave its first end into the closed
/// interior angle there and cross no edge properly. For testing.
///
/// # Complexity
/// `O(n²)` predicates worst case (`O(n)` pieces times `O(n)` edges), `O(n)` typically.
///
/// # Panics
/// Panics if `a` or `b` is not a vertex index of `ring`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::segment_in_polygon;
///
/// let ring = [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
///     .map(DVec2::from);
/// assert!(segment_in_polygon::<Robust>(&ring, 0, 4));
/// assert!(!segment_in_polygon::<Robust>(&ring, 6, 3));
/// ```
#[must_use]
pub fn segment_in_polygon<K: Kernel>(ring: &[DVec2], a: usize, b: usize) -> bool {
    let n = ring.len();
    assert!(
        a < n && b < n,
        "segment_in_polygon: vertex index out of range"
    );
    if a == b {
        return true;
    }
    let (pa, pb) = (ring[a], ring[b]);
    // Vertices on the open segment, ordered from a to b.
    let mut on: Vec<usize> = (0..n)
        .filter(|&x| {
            x != a
                && x != b
                && K::orient(pa, pb, ring[x]) == Orientation::Collinear
                && K::dot_sign(pa, ring[x], pa, pb) == Sign::Positive
                && K::dot_sign(pb, ring[x], pb, pa) == Sign::Positive
        })
        .collect();
    on.sort_by(|&x, &y| {
        let forward = K::dot_sign(ring[x], ring[y], pa, pb);
        match forward {
            Sign::Positive => core::cmp::Ordering::Less,
            Sign::Negative => core::cmp::Ordering::Greater,
            Sign::Zero => core::cmp::Ordering::Equal,
        }
    });
    let mut stops = vec![a];
    stops.extend(on);
    stops.push(b);
    stops
        .windows(2)
        .all(|w| piece_inside::<K>(ring, w[0], w[1]))
}

/// A segment between two vertices with no vertex on its open interior lies in the closed polygon
/// iff it leaves `u` into the closed interior angle at `u` and crosses no edge properly.
fn piece_inside<K: Kernel>(ring: &[DVec2], u: usize, v: usize) -> bool {
    let n = ring.len();
    let (pu, pv) = (ring[u], ring[v]);
    let (q, p) = (ring[(u + 1) % n], ring[(u + n - 1) % n]);
    // Direction d = v − u against the closed interior angle from u → q counter-clockwise to u → p.
    let cq = K::orient(pu, q, pv);
    let cp = K::orient(pu, p, pv);
    let along = |x: DVec2, c: Orientation| {
        c == Orientation::Collinear && K::dot_sign(pu, x, pu, pv) == Sign::Positive
    };
    let inside_angle = along(q, cq)
        || along(p, cp)
        || match K::orient(pu, q, p) {
            Orientation::CounterClockwise => {
                cq == Orientation::CounterClockwise && cp == Orientation::Clockwise
            }
            Orientation::Clockwise => {
                !(cp != Orientation::Clockwise && cq != Orientation::CounterClockwise)
            }
            Orientation::Collinear => cq == Orientation::CounterClockwise,
        };
    if !inside_angle {
        return false;
    }
    (0..n).all(|k| {
        let (c, d) = (ring[k], ring[(k + 1) % n]);
        let (o1, o2) = (K::orient(pu, pv, c), K::orient(pu, pv, d));
        let (o3, o4) = (K::orient(c, d, pu), K::orient(c, d, pv));
        let strict = |x: Orientation, y: Orientation| {
            matches!(
                (x, y),
                (Orientation::Clockwise, Orientation::CounterClockwise)
                    | (Orientation::CounterClockwise, Orientation::Clockwise)
            )
        };
        !(strict(o1, o2) && strict(o3, o4))
    })
}

/// The shortest path from ring vertex `s` to ring vertex `t` inside the closed polygon by brute
/// force: the exact visibility graph of the vertices ([`segment_in_polygon`]) and Dijkstra on `f64`
/// lengths, collinear runs merged as in [`shortest_path`]. For testing (a tie in length between two
/// paths is broken arbitrarily).
///
/// # Complexity
/// `O(n³)` predicates and more: small polygons only.
///
/// # Panics
/// Panics if `s` or `t` is not a vertex index of `ring`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::shortest_path_brute;
///
/// let ring = [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
///     .map(DVec2::from);
/// assert_eq!(shortest_path_brute::<Robust>(&ring, 6, 3), vec![6, 5, 4, 3]);
/// ```
#[must_use]
pub fn shortest_path_brute<K: Kernel>(ring: &[DVec2], s: usize, t: usize) -> Vec<usize> {
    let n = ring.len();
    assert!(
        s < n && t < n,
        "shortest_path_brute: vertex index out of range"
    );
    let mut dist = vec![f64::INFINITY; n];
    let mut prev = vec![usize::MAX; n];
    let mut done = vec![false; n];
    dist[s] = 0.0;
    for _ in 0..n {
        let Some(u) = (0..n)
            .filter(|&u| !done[u] && dist[u].is_finite())
            .min_by(|&a, &b| dist[a].total_cmp(&dist[b]))
        else {
            break;
        };
        done[u] = true;
        if u == t {
            break;
        }
        for v in 0..n {
            if !done[v] && segment_in_polygon::<K>(ring, u, v) {
                let d = dist[u] + (ring[u] - ring[v]).length();
                if d < dist[v] {
                    dist[v] = d;
                    prev[v] = u;
                }
            }
        }
    }
    let mut path = vec![t];
    let mut cur = t;
    while cur != s && prev[cur] != usize::MAX {
        cur = prev[cur];
        path.push(cur);
    }
    path.reverse();
    merge_collinear::<K>(ring, &path)
}

/// Where a candidate hit lies: a vertex on the ray, or an edge crossing it.
#[derive(Clone, Copy)]
enum Candidate {
    Vertex(usize),
    Edge(usize),
}

/// Which side of line `ab` the closed segment `cd` lies on (`None` when it straddles strictly).
fn segment_side<K: Kernel>(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> Option<Orientation> {
    let (o1, o2) = (K::orient(a, b, c), K::orient(a, b, d));
    let pos = |o| o == Orientation::CounterClockwise;
    let neg = |o| o == Orientation::Clockwise;
    if !neg(o1) && !neg(o2) && (pos(o1) || pos(o2)) {
        Some(Orientation::CounterClockwise)
    } else if !pos(o1) && !pos(o2) && (neg(o1) || neg(o2)) {
        Some(Orientation::Clockwise)
    } else {
        None
    }
}

/// [`first_hit`] by brute force: every vertex on the open ray and every edge crossing it strictly
/// is a candidate, and the nearest along the ray is chosen with exact comparisons (two vertices by
/// a dot sign; a vertex against an edge crossing by the vertex's side of the edge's line; two edge
/// crossings by the side of one segment with respect to the other's line). For testing.
///
/// # Complexity
/// `O(n)` predicates.
///
/// # Panics
/// Panics if `from` or `through` is not a vertex index of `ring`.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::predicates::Robust;
/// use polydist_separation::{Hit, first_hit_brute};
///
/// let ring = [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
///     .map(DVec2::from);
/// assert_eq!(first_hit_brute::<Robust>(&ring, 4, 5), Hit::Edge(7));
/// ```
#[must_use]
pub fn first_hit_brute<K: Kernel>(ring: &[DVec2], from: usize, through: usize) -> Hit {
    let n = ring.len();
    assert!(
        from < n && through < n,
        "first_hit_brute: vertex index out of range"
    );
    if from == through {
        return Hit::Immediate;
    }
    let (f, w) = (ring[from], ring[through]);
    if !enters::<K>(ring, f, through) {
        return Hit::Immediate;
    }
    let mut best: Option<Candidate> = None;
    // Is candidate x strictly nearer to w along the ray than candidate y?
    let nearer = |x: Candidate, y: Candidate| -> bool {
        match (x, y) {
            (Candidate::Vertex(a), Candidate::Vertex(b)) => {
                K::dot_sign(ring[a], ring[b], f, w) == Sign::Positive
            }
            (Candidate::Vertex(a), Candidate::Edge(k))
            | (Candidate::Edge(k), Candidate::Vertex(a)) => {
                let (c, d) = edge_right_left::<K>(ring, f, w, k);
                // The crossing is ahead of w: w is left of c → d. The vertex is nearer iff it is on
                // w's side of the edge's line.
                let vertex_first = K::orient(c, d, ring[a]) == Orientation::CounterClockwise;
                matches!(x, Candidate::Vertex(_)) == vertex_first
            }
            (Candidate::Edge(k1), Candidate::Edge(k2)) => {
                let (c1, d1) = edge_right_left::<K>(ring, f, w, k1);
                let (c2, d2) = edge_right_left::<K>(ring, f, w, k2);
                if let Some(side) = segment_side::<K>(c2, d2, c1, d1) {
                    // Segment 1 on w's side of line 2 (left of c2 → d2): crossing 1 comes first.
                    side == Orientation::CounterClockwise
                } else if let Some(side) = segment_side::<K>(c1, d1, c2, d2) {
                    side == Orientation::Clockwise
                } else {
                    false
                }
            }
        }
    };
    let offer = |c: Candidate, best: &mut Option<Candidate>| {
        if best.is_none_or(|b| nearer(c, b)) {
            *best = Some(c);
        }
    };
    for (z, &pz) in ring.iter().enumerate() {
        if z != through
            && K::orient(f, w, pz) == Orientation::Collinear
            && K::dot_sign(w, pz, f, w) == Sign::Positive
        {
            offer(Candidate::Vertex(z), &mut best);
        }
    }
    for k in 0..n {
        let k1 = (k + 1) % n;
        if k == through || k1 == through {
            continue;
        }
        let (o1, o2) = (K::orient(f, w, ring[k]), K::orient(f, w, ring[k1]));
        let straddle = matches!(
            (o1, o2),
            (Orientation::Clockwise, Orientation::CounterClockwise)
                | (Orientation::CounterClockwise, Orientation::Clockwise)
        );
        if !straddle {
            continue;
        }
        let (c, d) = edge_right_left::<K>(ring, f, w, k);
        if K::orient(c, d, w) == Orientation::CounterClockwise {
            offer(Candidate::Edge(k), &mut best);
        }
    }
    match best {
        Some(Candidate::Vertex(z)) => Hit::Vertex(z),
        Some(Candidate::Edge(k)) => Hit::Edge(k),
        None => Hit::Immediate,
    }
}

/// The endpoints of edge `k` ordered (right of the ray line, left of it).
fn edge_right_left<K: Kernel>(ring: &[DVec2], f: DVec2, w: DVec2, k: usize) -> (DVec2, DVec2) {
    let (c, d) = (ring[k], ring[(k + 1) % ring.len()]);
    if K::orient(f, w, c) == Orientation::Clockwise {
        (c, d)
    } else {
        (d, c)
    }
}
