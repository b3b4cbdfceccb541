//! Exact minimum distances between polygon boundaries, with every optimal
//! feature pair.

use glam::DVec2;
use num_rational::BigRational;
use num_traits::Zero;

use crate::contact::{Contact, contact_status_convex};
use crate::exact::{Frac, Grid, IPt, edge, edge_count, seg_intersect, sq_pp, sq_ps, sq_ss};
use crate::rounding::sqrt_nearest;
use crate::shape::assert_convex_position;

/// A feature of a polygon given as a vertex list `v[0..n]`.
///
/// Edge `i` joins vertex `i` and vertex `(i + 1) mod n`. A 1-vertex polygon
/// (a point) has no edge; a 2-vertex polygon (a segment) has exactly one edge,
/// `Edge(0)`, joining vertex 0 and vertex 1; an `n >= 3`-vertex polygon has
/// `n` edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Feature {
    /// Vertex `i`.
    Vertex(usize),
    /// Closed edge `i`, from vertex `i` to vertex `(i + 1) mod n`.
    Edge(usize),
}

/// An exact minimum distance together with all feature pairs realising it.
///
/// **Convention.** `pairs` lists *every* pair `(f, g)` — `f` a feature of the
/// first polygon, `g` of the second, of any kinds (vertex–vertex,
/// vertex–edge, edge–vertex, edge–edge) — whose exact squared distance (as
/// closed point sets) equals `sq`. So a vertex–vertex optimum at vertex `i`
/// of `P` and `j` of `Q` also appears as `(Vertex(i), Edge(j))`,
/// `(Edge(i), Vertex(j))`, ... for every edge incident to those vertices that
/// attains the same distance, and an edge–edge pair is listed whenever the two
/// closed edges realise the optimum (in particular when they cross and the
/// optimum is 0). Pairs are sorted. Hence a tested algorithm's reported pair
/// is exactly optimal iff it is in the list: [`ExactDistance::is_optimal_pair`].
///
/// For [`convex_distance`] with `sq == 0` (filled polygons meet), `pairs`
/// lists the boundary feature pairs at distance 0; it is empty when one
/// polygon lies in the other's interior without touching its boundary.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactDistance {
    /// The exact squared distance.
    pub sq: BigRational,
    /// All optimal feature pairs `(feature of P, feature of Q)`, sorted.
    pub pairs: Vec<(Feature, Feature)>,
}

impl ExactDistance {
    /// Whether the reported pair `(f1 of P, f2 of Q)` realises the optimum
    /// exactly, i.e. its exact squared feature distance equals `sq`. (With the
    /// all-pairs convention of this type that is membership in `pairs`; an
    /// out-of-range feature is never optimal.)
    pub fn is_optimal_pair(&self, f1: Feature, f2: Feature) -> bool {
        self.pairs.contains(&(f1, f2))
    }

    /// The distance `sqrt(sq)` correctly rounded to the nearest `f64`.
    pub fn distance_nearest(&self) -> f64 {
        sqrt_nearest(&self.sq)
    }
}

/// Squared distance in grid units between feature `f` of `p` and `g` of `q`,
/// or `None` if an index is out of range.
pub(crate) fn feature_frac(p: &[IPt], q: &[IPt], f: Feature, g: Feature) -> Option<Frac> {
    let ep = edge_count(p.len());
    let eq = edge_count(q.len());
    Some(match (f, g) {
        (Feature::Vertex(i), Feature::Vertex(j)) => Frac::int(sq_pp(p.get(i)?, q.get(j)?)),
        (Feature::Vertex(i), Feature::Edge(j)) if j < eq => {
            let (c, d) = edge(q, j);
            sq_ps(p.get(i)?, c, d)
        }
        (Feature::Edge(i), Feature::Vertex(j)) if i < ep => {
            let (a, b) = edge(p, i);
            sq_ps(q.get(j)?, a, b)
        }
        (Feature::Edge(i), Feature::Edge(j)) if i < ep && j < eq => {
            let (a, b) = edge(p, i);
            let (c, d) = edge(q, j);
            sq_ss(a, b, c, d)
        }
        _ => return None,
    })
}

/// Exact squared distance between feature `f` of polygon `p` and feature `g`
/// of polygon `q` (closed point sets; edge–edge pairs use the exact
/// segment–segment distance, 0 if they meet). `None` if an index is out of
/// range (see [`Feature`] for how many edges a polygon has).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn feature_sq_dist(p: &[DVec2], q: &[DVec2], f: Feature, g: Feature) -> Option<BigRational> {
    let grid = Grid::for_points(p.iter().chain(q));
    let frac = feature_frac(&grid.pts(p), &grid.pts(q), f, g)?;
    Some(grid.sq_to_rat(&frac))
}

/// Brute force over all feature pairs, in grid units.
fn boundary_distance_grid(p: &[IPt], q: &[IPt]) -> (Frac, Vec<(Feature, Feature)>) {
    let (n, m) = (p.len(), q.len());
    let (ep, eq) = (edge_count(n), edge_count(m));
    // Tables of all vertex–vertex, vertex–edge and edge–vertex distances.
    let vv: Vec<Frac> = (0..n * m)
        .map(|k| Frac::int(sq_pp(&p[k / m], &q[k % m])))
        .collect();
    let ve: Vec<Frac> = (0..n * eq)
        .map(|k| {
            let (c, d) = edge(q, k % eq);
            sq_ps(&p[k / eq], c, d)
        })
        .collect();
    let ev: Vec<Frac> = (0..ep * m)
        .map(|k| {
            let (a, b) = edge(p, k / m);
            sq_ps(&q[k % m], a, b)
        })
        .collect();
    // Edge–edge distances: 0 if the closed edges meet, otherwise the minimum
    // of the four endpoint-to-edge distances already tabulated.
    let crossing: Vec<bool> = (0..ep * eq)
        .map(|k| {
            let (a, b) = edge(p, k / eq);
            let (c, d) = edge(q, k % eq);
            seg_intersect(a, b, c, d)
        })
        .collect();
    let ee = |i: usize, j: usize| -> Frac {
        if crossing[i * eq + j] {
            return Frac::zero();
        }
        let i1 = (i + 1) % n;
        let j1 = (j + 1) % m;
        [
            &ve[i * eq + j],
            &ve[i1 * eq + j],
            &ev[i * m + j],
            &ev[i * m + j1],
        ]
        .into_iter()
        .min()
        .cloned()
        .unwrap_or_else(Frac::zero)
    };
    let mut best = vv
        .iter()
        .chain(&ve)
        .chain(&ev)
        .min()
        .cloned()
        .unwrap_or_else(Frac::zero);
    if crossing.iter().any(|&c| c) {
        best = Frac::zero();
    }
    let mut pairs = Vec::new();
    for i in 0..n {
        for j in 0..m {
            if vv[i * m + j] == best {
                pairs.push((Feature::Vertex(i), Feature::Vertex(j)));
            }
        }
        for j in 0..eq {
            if ve[i * eq + j] == best {
                pairs.push((Feature::Vertex(i), Feature::Edge(j)));
            }
        }
    }
    for i in 0..ep {
        for j in 0..m {
            if ev[i * m + j] == best {
                pairs.push((Feature::Edge(i), Feature::Vertex(j)));
            }
        }
        for j in 0..eq {
            if ee(i, j) == best {
                pairs.push((Feature::Edge(i), Feature::Edge(j)));
            }
        }
    }
    pairs.sort();
    (best, pairs)
}

/// Exact distance between the boundaries of two polygons (closed polylines).
///
/// A 1-vertex polygon is a point, a 2-vertex polygon is the segment `Edge(0)`
/// (see [`Feature`]); `n >= 3` vertices form a closed polyline. The result is
/// 0 if the boundaries meet; interiors are ignored (use [`convex_distance`] or
/// [`crate::contact_status_simple`] for filled polygons). Any vertex order,
/// repeated vertices and self-intersections are allowed. Cost `O(nm)` big-
/// integer operations.
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn boundary_distance(p: &[DVec2], q: &[DVec2]) -> ExactDistance {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "boundary_distance: empty polygon"
    );
    let grid = Grid::for_points(p.iter().chain(q));
    let (best, pairs) = boundary_distance_grid(&grid.pts(p), &grid.pts(q));
    ExactDistance {
        sq: grid.sq_to_rat(&best),
        pairs,
    }
}

/// Exact distance between two *filled* convex polygons.
///
/// Each polygon is the convex hull of its vertices, given in convex position
/// and cyclic order (either orientation; collinear vertices strictly between
/// neighbours, 1-vertex points and 2-vertex segments allowed). `sq` is 0 when
/// the filled polygons meet ([`contact_status_convex`] is not `Disjoint`),
/// otherwise the boundary distance. See [`ExactDistance`] for `pairs` when
/// `sq == 0`.
///
/// # Panics
/// Panics if a polygon is empty, a coordinate is not finite, or a polygon
/// with 3 or more vertices is not in convex position (checked exactly).
pub fn convex_distance(p: &[DVec2], q: &[DVec2]) -> ExactDistance {
    assert_convex_position(p);
    assert_convex_position(q);
    let b = boundary_distance(p, q);
    if b.sq.is_zero() || contact_status_convex(p, q) == Contact::Disjoint {
        b
    } else {
        ExactDistance {
            sq: BigRational::zero(),
            pairs: Vec::new(),
        }
    }
}

/// Minimum squared distance between the vertex sets of `p` and `q`, with all
/// optimal index pairs `(i, j)` (sorted).
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn min_vertex_distance(p: &[DVec2], q: &[DVec2]) -> (BigRational, Vec<(usize, usize)>) {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "min_vertex_distance: empty polygon"
    );
    let grid = Grid::for_points(p.iter().chain(q));
    let (pi, qi) = (grid.pts(p), grid.pts(q));
    let mut best: Option<num_bigint::BigInt> = None;
    let mut pairs = Vec::new();
    for (i, a) in pi.iter().enumerate() {
        for (j, b) in qi.iter().enumerate() {
            let d = sq_pp(a, b);
            match &best {
                Some(cur) if d > *cur => {}
                Some(cur) if d == *cur => pairs.push((i, j)),
                _ => {
                    best = Some(d);
                    pairs.clear();
                    pairs.push((i, j));
                }
            }
        }
    }
    let best = best.unwrap_or_default();
    (grid.sq_to_rat(&Frac::int(best)), pairs)
}
