//! Exact point-to-filled-convex distances, Hausdorff and CMMR distances.

use core::cmp::Ordering;

use glam::DVec2;
use num_rational::BigRational;
use num_traits::Zero;

use crate::contact::convex_hull;
use crate::exact::{Frac, Grid, HPt, IPt, Location, edge, edge_count, locate, sq_pp, sq_ps};

/// Squared distance (grid units) from `v` to the filled hull `hull`.
pub(crate) fn sq_to_hull(v: &IPt, hull: &[IPt]) -> Frac {
    match hull.len() {
        0 => Frac::zero(),
        1 => Frac::int(sq_pp(v, &hull[0])),
        n => {
            if n >= 3 && locate(&HPt::from_ipt(v), hull) != Location::Outside {
                return Frac::zero();
            }
            (0..edge_count(n))
                .map(|i| {
                    let (a, b) = edge(hull, i);
                    sq_ps(v, a, b)
                })
                .min()
                .unwrap_or_else(Frac::zero)
        }
    }
}

/// Per-vertex squared distances of `p` to the filled convex hull of `q`, in
/// grid units, with the grid.
fn per_vertex_grid(p: &[DVec2], q: &[DVec2]) -> (Grid, Vec<Frac>) {
    assert!(!q.is_empty(), "the filled polygon must not be empty");
    let g = Grid::for_points(p.iter().chain(q));
    let hull = convex_hull(&g.pts(q));
    let d = g.pts(p).iter().map(|v| sq_to_hull(v, &hull)).collect();
    (g, d)
}

/// Exact squared distance from `v` to the filled convex polygon `q` (taken as
/// the convex hull of its vertices; 1 vertex = point, 2 = segment): 0 if `v`
/// is inside or on the boundary.
///
/// # Panics
/// Panics if `q` is empty or a coordinate is not finite.
pub fn sq_dist_point_filled_convex(v: DVec2, q: &[DVec2]) -> BigRational {
    let (g, d) = per_vertex_grid(&[v], q);
    g.sq_to_rat(&d[0])
}

/// For each vertex of `p`, the exact squared distance to the filled convex
/// polygon `q` (convex hull of its vertices).
///
/// # Panics
/// Panics if `q` is empty or a coordinate is not finite.
pub fn per_vertex_sq_dist(p: &[DVec2], q: &[DVec2]) -> Vec<BigRational> {
    let (g, d) = per_vertex_grid(p, q);
    d.iter().map(|f| g.sq_to_rat(f)).collect()
}

/// Directed squared Hausdorff distance from the filled convex polygon `p` to
/// the filled convex polygon `q`: `max over x in conv(p) of d(x, conv(q))²`,
/// with the indices of **all** vertices of `p` attaining the maximum (sorted).
///
/// The maximum over `conv(p)` is attained at a vertex because `d(·, conv q)`
/// is a convex function, so only vertices are examined. Result is 0 (with
/// every vertex listed) when `conv(p) ⊆ conv(q)`.
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn directed_hausdorff_filled(p: &[DVec2], q: &[DVec2]) -> (BigRational, Vec<usize>) {
    assert!(!p.is_empty(), "directed_hausdorff_filled: empty polygon");
    let (g, d) = per_vertex_grid(p, q);
    let mut best = Frac::zero();
    let mut arg = Vec::new();
    for (i, f) in d.iter().enumerate() {
        match f.cmp(&best) {
            Ordering::Greater => {
                best = f.clone();
                arg.clear();
                arg.push(i);
            }
            Ordering::Equal => arg.push(i),
            Ordering::Less => {}
        }
    }
    (g.sq_to_rat(&best), arg)
}

/// Squared Hausdorff distance between the filled convex polygons `p` and
/// `q`: the maximum of both directed distances.
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn hausdorff_filled(p: &[DVec2], q: &[DVec2]) -> BigRational {
    let (a, _) = directed_hausdorff_filled(p, q);
    let (b, _) = directed_hausdorff_filled(q, p);
    a.max(b)
}

/// The CMMR distance of Atallah, Ribeiro and Lifschitz (1991): the sum over
/// the vertices of `p` of their squared distances to filled `q`, plus the sum
/// over the vertices of `q` of their squared distances to filled `p` (filled =
/// convex hull of the vertices).
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
pub fn cmmr(p: &[DVec2], q: &[DVec2]) -> BigRational {
    let mut s = BigRational::zero();
    for r in per_vertex_sq_dist(p, q)
        .into_iter()
        .chain(per_vertex_sq_dist(q, p))
    {
        s += r;
    }
    s
}
