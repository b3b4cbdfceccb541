//! Exact distances between *large* polygons (10⁴–10⁵ vertices) by a pruned exact search: the same
//! answers, with the same conventions, as the brute forces [`crate::boundary_distance`],
//! [`crate::min_vertex_distance`], [`crate::convex_distance`] and
//! [`crate::directed_hausdorff_filled`], without their `O(nm)` cost (issue 8: "large polygons with
//! answers certified by a pruned exact search"). It never calls polydist's algorithms: only this
//! crate's exact big-integer primitives.
//!
//! # The search
//! Every feature of a polygon with `n ≥ 3` vertices belongs to exactly one *item*: item `i` holds
//! vertex `i` and edge `i` (from vertex `i` to vertex `i + 1`), and its box is the axis-aligned
//! bounding box of those two vertices, which contains both features. A binary tree over contiguous
//! item ranges stores each node's box (the union of its items' boxes). The search walks pairs of
//! nodes depth first, nearer box pair first, keeping `U`, the smallest exact squared distance of a
//! feature pair evaluated so far; a node pair whose exact box lower bound `L` satisfies `L > U` is
//! discarded, and at two leaves every surviving item pair's features are evaluated exactly.
//!
//! # Why the pruning never discards an optimal pair
//! Let `d*` be the optimum and `(f, g)` any optimal feature pair, in items `i` and `j`, in leaves
//! `A ∋ i`, `B ∋ j`, under nodes `A' ⊇ A`, `B' ⊇ B`. (1) `U ≥ d*` at every moment, because `U` is
//! the exact distance of some feature pair (or not yet set, and then nothing is pruned). (2) For
//! boxes `X ⊇ f`, `Y ⊇ g`: `L(X, Y) = dist(X, Y)² ≤ dist(f, g)² = d*`, since `f ⊂ X` and `g ⊂ Y`;
//! `L` is computed exactly ([`box_gap`]: a difference of exact grid integers, squared and summed in
//! big integers, compared with `U = n/d` by the exact cross-multiplication `L·d > n`). So for every
//! node pair `(A', B')` on the path to `(A, B)` and for the item pair `(i, j)`,
//! `L ≤ d* ≤ U`, the test `L > U` fails, and the pair is reached and evaluated exactly. (3) Every
//! evaluated pair with value `≤ U` (at its time) is remembered; at the end `U = d*` by (1)–(2), and
//! the pairs listed are exactly the remembered ones equal to `d*`: every optimal pair is among them
//! by (2), and no other pair equals `d*`. The result is therefore the brute force's, pair for pair.
//!
//! # Complexity
//! Building the trees: `O(n + m)` exact integer operations. The walk has no worst-case bound
//! better than the brute force's `O(nm)` (two concentric dense polygons keep every box pair within
//! `U`; a co-circular tie keeps every vertex of the arc), and none is claimed: on the suite's
//! families (disjoint polygons whose optimum sits in a small neighbourhood, or ties that must all
//! be listed anyway) it evaluates few pairs beyond the optimal ones, and `gen_hard` computes all
//! answers of the 13 large pairs in about a minute of a release build, Hausdorff included.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

use crate::distance::{ExactDistance, Feature, feature_frac};
use crate::exact::{Frac, Grid, HPt, IPt, Location, locate, ordered, sq_pp, sq_ps};

/// Items per leaf of the box tree.
const LEAF: usize = 8;

/// An axis-aligned box on the grid: `[x0, x1] × [y0, y1]`.
#[derive(Clone, Debug)]
struct GridBox {
    x0: BigInt,
    x1: BigInt,
    y0: BigInt,
    y1: BigInt,
}

impl GridBox {
    fn of(a: &IPt, b: &IPt) -> GridBox {
        let ((x0, x1), (y0, y1)) = (ordered(&a.x, &b.x), ordered(&a.y, &b.y));
        GridBox {
            x0: x0.clone(),
            x1: x1.clone(),
            y0: y0.clone(),
            y1: y1.clone(),
        }
    }

    fn union(&self, o: &GridBox) -> GridBox {
        GridBox {
            x0: (&self.x0).min(&o.x0).clone(),
            x1: (&self.x1).max(&o.x1).clone(),
            y0: (&self.y0).min(&o.y0).clone(),
            y1: (&self.y1).max(&o.y1).clone(),
        }
    }
}

/// The exact squared distance between two boxes (0 if they meet): with `dx = max(0, b.x0 − a.x1,
/// a.x0 − b.x1)` and `dy` alike, `dx² + dy²`. A lower bound of the squared distance of any point
/// of `a` to any point of `b`.
fn box_gap(a: &GridBox, b: &GridBox) -> BigInt {
    let gap = |lo_a: &BigInt, hi_a: &BigInt, lo_b: &BigInt, hi_b: &BigInt| -> BigInt {
        if lo_b > hi_a {
            lo_b - hi_a
        } else if lo_a > hi_b {
            lo_a - hi_b
        } else {
            BigInt::zero()
        }
    };
    let dx = gap(&a.x0, &a.x1, &b.x0, &b.x1);
    let dy = gap(&a.y0, &a.y1, &b.y0, &b.y1);
    &dx * &dx + &dy * &dy
}

/// `bound > u`, exactly (`u = n/d`, `d > 0`); nothing exceeds an unset `u`.
fn exceeds(bound: &BigInt, u: Option<&Frac>) -> bool {
    u.is_some_and(|u| bound * &u.d > u.n)
}

/// A node of the box tree: items `lo..hi`, their box, and its children (`None` for a leaf).
struct Node {
    lo: usize,
    hi: usize,
    bx: GridBox,
    kids: Option<(usize, usize)>,
}

/// A box tree over the items of one polygon (see the module doc); node 0 is the root.
struct BoxTree {
    nodes: Vec<Node>,
    items: Vec<GridBox>,
}

impl BoxTree {
    /// The tree of `items` (at least one).
    fn new(items: Vec<GridBox>) -> BoxTree {
        let mut t = BoxTree {
            nodes: Vec::new(),
            items,
        };
        t.build(0, t.items.len());
        t
    }

    /// Builds the node over `lo..hi` (children first) and returns its index.
    fn build(&mut self, lo: usize, hi: usize) -> usize {
        if hi - lo <= LEAF {
            let bx = self.items[lo + 1..hi]
                .iter()
                .fold(self.items[lo].clone(), |b, i| b.union(i));
            self.nodes.push(Node {
                lo,
                hi,
                bx,
                kids: None,
            });
        } else {
            let mid = lo + (hi - lo) / 2;
            let (l, r) = (self.build(lo, mid), self.build(mid, hi));
            let bx = self.nodes[l].bx.union(&self.nodes[r].bx);
            self.nodes.push(Node {
                lo,
                hi,
                bx,
                kids: Some((l, r)),
            });
        }
        self.nodes.len() - 1
    }

    fn root(&self) -> usize {
        self.nodes.len() - 1
    }
}

/// The item boxes of a polygon (`n ≥ 3`): item `i` = vertex `i` and edge `i`.
fn item_boxes(v: &[IPt]) -> Vec<GridBox> {
    (0..v.len())
        .map(|i| GridBox::of(&v[i], &v[(i + 1) % v.len()]))
        .collect()
}

/// The pruned walk (module doc): every candidate `(key, value)` that `eval(i, j)` returns for a
/// surviving item pair is compared with `U`; returns `U` and every key whose value equals it.
fn search<K>(
    tp: &BoxTree,
    tq: &BoxTree,
    mut eval: impl FnMut(usize, usize) -> Vec<(K, Frac)>,
) -> (Frac, Vec<K>) {
    let mut best: Option<Frac> = None;
    let mut kept: Vec<(K, Frac)> = Vec::new();
    let mut stack = vec![(tp.root(), tq.root())];
    while let Some((a, b)) = stack.pop() {
        let (na, nb) = (&tp.nodes[a], &tq.nodes[b]);
        if exceeds(&box_gap(&na.bx, &nb.bx), best.as_ref()) {
            continue; // L > U ≥ d*: no optimal pair below (module doc, step 2)
        }
        match (na.kids, nb.kids) {
            (None, None) => {
                for i in na.lo..na.hi {
                    for j in nb.lo..nb.hi {
                        if exceeds(&box_gap(&tp.items[i], &tq.items[j]), best.as_ref()) {
                            continue;
                        }
                        for (key, value) in eval(i, j) {
                            if best.as_ref().is_none_or(|u| value <= *u) {
                                if best.as_ref().is_none_or(|u| value < *u) {
                                    best = Some(value.clone());
                                }
                                kept.push((key, value));
                            }
                        }
                    }
                }
            }
            (kids_a, kids_b) => {
                // Split the node with more items (a leaf is never split); the nearer child pair
                // is pushed last, so it is walked first and `U` shrinks early.
                let split_a =
                    kids_b.is_none() || (kids_a.is_some() && na.hi - na.lo >= nb.hi - nb.lo);
                let mut pairs: Vec<(usize, usize)> = match (split_a, kids_a, kids_b) {
                    (true, Some((l, r)), _) => vec![(l, b), (r, b)],
                    (false, _, Some((l, r))) => vec![(a, l), (a, r)],
                    _ => Vec::new(),
                };
                pairs.sort_by_cached_key(|&(x, y)| {
                    core::cmp::Reverse(box_gap(&tp.nodes[x].bx, &tq.nodes[y].bx))
                });
                stack.extend(pairs);
            }
        }
    }
    let best = best.unwrap_or_else(Frac::zero);
    let keys = kept
        .into_iter()
        .filter(|(_, v)| *v == best)
        .map(|(k, _)| k)
        .collect();
    (best, keys)
}

/// The grid of both polygons, their grid points and box trees.
fn prepare(p: &[DVec2], q: &[DVec2]) -> (Grid, Vec<IPt>, Vec<IPt>, BoxTree, BoxTree) {
    assert!(
        p.len() >= 3 && q.len() >= 3,
        "the pruned search takes polygons of at least 3 vertices"
    );
    let grid = Grid::for_points(p.iter().chain(q));
    let (pi, qi) = (grid.pts(p), grid.pts(q));
    let (tp, tq) = (BoxTree::new(item_boxes(&pi)), BoxTree::new(item_boxes(&qi)));
    (grid, pi, qi, tp, tq)
}

/// Exact distance between the boundaries of two polygons (closed polylines of at least 3
/// vertices), with every optimal feature pair: the same result as [`crate::boundary_distance`]
/// (same conventions, pairs sorted), by the pruned search of this module (proof of exactness in
/// the module doc).
///
/// # Panics
/// Panics if a polygon has fewer than 3 vertices or a coordinate is not finite.
pub fn boundary_distance_pruned(p: &[DVec2], q: &[DVec2]) -> ExactDistance {
    let (grid, pi, qi, tp, tq) = prepare(p, q);
    let (best, mut pairs) = search(&tp, &tq, |i, j| {
        [
            (Feature::Vertex(i), Feature::Vertex(j)),
            (Feature::Vertex(i), Feature::Edge(j)),
            (Feature::Edge(i), Feature::Vertex(j)),
            (Feature::Edge(i), Feature::Edge(j)),
        ]
        .into_iter()
        .filter_map(|(f, g)| Some(((f, g), feature_frac(&pi, &qi, f, g)?)))
        .collect()
    });
    pairs.sort();
    ExactDistance {
        sq: grid.sq_to_rat(&best),
        pairs,
    }
}

/// Exact distance between two *filled* convex polygons, with the conventions of
/// [`crate::convex_distance`]: the boundary distance by [`boundary_distance_pruned`]; when it is
/// positive the boundaries are disjoint, so the filled polygons are either disjoint or one lies in
/// the other's interior, which one exact point location of a vertex of each decides (`O(n + m)`):
/// then `sq = 0` and no pair. Also correct for simple polygons (filled as the closed region the
/// boundary bounds), by the same argument.
///
/// # Panics
/// Panics if a polygon has fewer than 3 vertices or a coordinate is not finite.
pub fn filled_distance_pruned(p: &[DVec2], q: &[DVec2]) -> ExactDistance {
    let b = boundary_distance_pruned(p, q);
    if b.sq.is_zero() {
        return b;
    }
    let grid = Grid::for_points(p.iter().chain(q));
    let (pi, qi) = (grid.pts(p), grid.pts(q));
    let inside = |v: &IPt, poly: &[IPt]| locate(&HPt::from_ipt(v), poly) == Location::Inside;
    if inside(&pi[0], &qi) || inside(&qi[0], &pi) {
        ExactDistance {
            sq: BigRational::zero(),
            pairs: Vec::new(),
        }
    } else {
        b
    }
}

/// Minimum squared distance between the vertex sets of two polygons (at least 3 vertices each),
/// with every optimal index pair, sorted: [`crate::min_vertex_distance`]'s result by the pruned
/// search (a vertex lies in its item's box, so the module doc's proof applies unchanged).
///
/// # Panics
/// Panics if a polygon has fewer than 3 vertices or a coordinate is not finite.
pub fn min_vertex_distance_pruned(p: &[DVec2], q: &[DVec2]) -> (BigRational, Vec<(usize, usize)>) {
    let (grid, pi, qi, tp, tq) = prepare(p, q);
    let (best, mut pairs) = search(&tp, &tq, |i, j| {
        vec![((i, j), Frac::int(sq_pp(&pi[i], &qi[j])))]
    });
    pairs.sort_unstable();
    (grid.sq_to_rat(&best), pairs)
}

/// The squared distance from `v` to the boundary of the polygon of `tree` (points `poly`), by the
/// pruned walk of one point against the tree (the module doc's proof with `v`'s point box).
fn point_to_boundary(v: &IPt, poly: &[IPt], tree: &BoxTree) -> Frac {
    let pt = BoxTree::new(vec![GridBox::of(v, v)]);
    let (best, _) = search(&pt, tree, |_, j| {
        vec![((), sq_ps(v, &poly[j], &poly[(j + 1) % poly.len()]))]
    });
    best
}

/// The directed Hausdorff distance `h(P, Q)²` of two *disjoint* filled polygons (at least 3
/// vertices each; `Q` convex), with every vertex of `P` attaining it, sorted: the result of
/// [`crate::directed_hausdorff_filled`], in `O(n log m)`-ish instead of `O(nm)`. Every vertex of
/// `P` lies outside filled `Q`, so its distance to filled `Q` is its distance to `Q`'s boundary,
/// found by a pruned walk per vertex; the maximum over `P` is attained at a vertex because
/// `d(·, Q)` is convex for convex `Q`.
///
/// Returns `None` when the filled polygons are not disjoint ([`filled_distance_pruned`] is 0):
/// then some vertex may lie inside `Q`, which this shortcut does not handle.
///
/// # Panics
/// Panics if a polygon has fewer than 3 vertices or a coordinate is not finite.
pub fn directed_hausdorff_disjoint_pruned(
    p: &[DVec2],
    q: &[DVec2],
) -> Option<(BigRational, Vec<usize>)> {
    if filled_distance_pruned(p, q).sq.is_zero() {
        return None;
    }
    let (grid, pi, qi, _, tq) = prepare(p, q);
    let mut best = Frac::zero();
    let mut arg = Vec::new();
    for (i, v) in pi.iter().enumerate() {
        let d = point_to_boundary(v, &qi, &tq);
        match d.cmp(&best) {
            Ordering::Greater => {
                best = d;
                arg.clear();
                arg.push(i);
            }
            Ordering::Equal => arg.push(i),
            Ordering::Less => {}
        }
    }
    Some((grid.sq_to_rat(&best), arg))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        Relation, SplitMix64, boundary_distance, convex_distance, convex_pair,
        directed_hausdorff_filled, min_vertex_distance, star,
    };

    /// The pruned search agrees with the brute forces, pair for pair, on random and degenerate
    /// pairs (touching, parallel facing edges, nested, overlapping) and on non-convex stars.
    #[test]
    fn agrees_with_the_brute_forces() {
        let mut rng = SplitMix64::new(0x9e3);
        for rel in [
            Relation::Far,
            Relation::NearlyTouching { ulps: 1 },
            Relation::TouchingVertex,
            Relation::VertexOnEdge,
            Relation::TouchingEdge,
            Relation::ParallelFacing,
            Relation::Overlapping,
            Relation::Nested,
            Relation::HugeOffset,
            Relation::CollinearInput,
        ] {
            for (n, m) in [(3, 3), (5, 9), (17, 12), (40, 70)] {
                let pair = convex_pair(&mut rng, n, m, rel);
                let (p, q) = (&pair.p, &pair.q);
                if p.len() < 3 || q.len() < 3 {
                    continue;
                }
                assert_eq!(
                    boundary_distance_pruned(p, q),
                    boundary_distance(p, q),
                    "{rel:?}"
                );
                assert_eq!(
                    filled_distance_pruned(p, q),
                    convex_distance(p, q),
                    "{rel:?}"
                );
                assert_eq!(min_vertex_distance_pruned(p, q), min_vertex_distance(p, q));
                let h = directed_hausdorff_disjoint_pruned(p, q);
                if convex_distance(p, q).sq.is_zero() {
                    assert_eq!(h, None);
                } else {
                    assert_eq!(h, Some(directed_hausdorff_filled(p, q)), "{rel:?}");
                }
            }
        }
        // The large families at small sizes (ties: co-circular, aligned comb teeth).
        for g in [
            "circle 64 30 1 0",
            "circle 96 30 3 7",
            "cocircular 3 0",
            "cocircular 3 1",
            "cocircular 4 -1",
            "star 3 80 20 1",
            "comb 12 3 1 2 0",
            "comb 12 3 1 4 1",
        ] {
            let w: Vec<String> = g.split_whitespace().map(str::to_owned).collect();
            let (p, q) = crate::large_pair_from(&w).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(
                boundary_distance_pruned(&p, &q),
                boundary_distance(&p, &q),
                "{g}"
            );
            assert_eq!(
                min_vertex_distance_pruned(&p, &q),
                min_vertex_distance(&p, &q),
                "{g}"
            );
            if !g.starts_with("star") && !g.starts_with("comb") {
                assert_eq!(
                    filled_distance_pruned(&p, &q),
                    convex_distance(&p, &q),
                    "{g}"
                );
                assert_eq!(
                    directed_hausdorff_disjoint_pruned(&q, &p),
                    Some(directed_hausdorff_filled(&q, &p)),
                    "{g}"
                );
            }
        }
        for n in [6, 20, 60] {
            let a = star(&mut rng, n, n / 3);
            let b = star(&mut rng, n, n / 4);
            assert_eq!(boundary_distance_pruned(&a, &b), boundary_distance(&a, &b));
            let far: Vec<DVec2> = b.iter().map(|&v| v + DVec2::new(0.75, 0.25)).collect();
            assert_eq!(
                boundary_distance_pruned(&a, &far),
                boundary_distance(&a, &far)
            );
        }
    }
}
