//! Exact contact classification of filled polygons.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::exact::{
    Frac, Grid, HPt, IPt, Location, cross, dot, edge, edge_count, locate, on_segment_h, orient,
    orient_h, seg_intersect, sign_of,
};
use crate::shape::{is_simple, signed_area2_grid};

/// How two filled polygons relate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Contact {
    /// The closed sets do not meet (positive distance).
    Disjoint,
    /// The closed sets meet, but their (relative) interiors do not.
    Touching,
    /// The (relative) interiors meet (this includes containment).
    Overlapping,
}

/// Exact convex hull, counter-clockwise, without repeated or collinear
/// vertices. Returns 1 point, 2 points (a segment) or a strictly convex
/// polygon; empty for empty input.
pub(crate) fn convex_hull(pts: &[IPt]) -> Vec<IPt> {
    let mut v: Vec<IPt> = pts.to_vec();
    v.sort_by(|a, b| a.x.cmp(&b.x).then_with(|| a.y.cmp(&b.y)));
    v.dedup();
    if v.len() <= 2 {
        return v;
    }
    fn chain<'a>(it: impl Iterator<Item = &'a IPt>) -> Vec<IPt> {
        let mut out: Vec<IPt> = Vec::new();
        for p in it {
            while out.len() >= 2
                && orient(&out[out.len() - 2], &out[out.len() - 1], p) != Ordering::Greater
            {
                out.pop();
            }
            out.push(p.clone());
        }
        out
    }
    let mut lower = chain(v.iter());
    let mut upper = chain(v.iter().rev());
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// Whether `x` lies in the closed convex set given by a hull from
/// [`convex_hull`].
fn in_closed_hull(x: &HPt, hull: &[IPt]) -> bool {
    match hull.len() {
        0 => false,
        1 => x.equals(&hull[0]),
        2 => on_segment_h(&hull[0], &hull[1], x),
        n => (0..n).all(|i| {
            let (a, b) = edge(hull, i);
            orient_h(a, b, x) != Ordering::Less
        }),
    }
}

/// Whether `x` lies in the relative interior of a hull from [`convex_hull`]:
/// the point itself, the open segment, or the open polygon.
fn in_relint_hull(x: &HPt, hull: &[IPt]) -> bool {
    match hull.len() {
        0 => false,
        1 => x.equals(&hull[0]),
        2 => on_segment_h(&hull[0], &hull[1], x) && !x.equals(&hull[0]) && !x.equals(&hull[1]),
        n => (0..n).all(|i| {
            let (a, b) = edge(hull, i);
            orient_h(a, b, x) == Ordering::Greater
        }),
    }
}

/// The single intersection point of two closed segments that meet and are
/// not collinear (so their supporting lines are not parallel).
fn crossing_point(a: &IPt, b: &IPt, c: &IPt, d: &IPt) -> HPt {
    let ab = b.sub(a);
    let cd = d.sub(c);
    let ac = c.sub(a);
    // a + t (b − a) with t = cross(c − a, d − c) / cross(b − a, d − c).
    let mut den = cross(&ab, &cd);
    let mut num = cross(&ac, &cd);
    if den.is_negative() {
        den = -den;
        num = -num;
    }
    HPt {
        x: &a.x * &den + &num * &ab.0,
        y: &a.y * &den + &num * &ab.1,
        w: den,
    }
}

/// Contact of the convex hulls `k` and `l` (from [`convex_hull`]).
///
/// Why this is right. Let `M = K ∩ L`. Let `V` be: the vertices of `K` in
/// `L`, the vertices of `L` in `K`, and the intersection point of every pair
/// (edge of `K`, edge of `L`) that meets and is not collinear. Every point of
/// `V` is in `M`, and every vertex `x` of `M` is in `V`: if `x` is a vertex of
/// neither hull it lies in the relative interior of a face `F` of `K` of
/// dimension ≥ 1 and of a face `G` of `L` of dimension ≥ 1; the cone of
/// feasible directions of `M` at `x` is the intersection of those of `K` and
/// `L` and contains the directions common to `F` and `G`; `x` being a vertex
/// of `M`, those have only 0 in common, which in the plane forces `F`, `G` to
/// be non-parallel edges crossing at `x`. So `M = conv V`, and `M = ∅` iff
/// `V = ∅`.
///
/// For the relative interiors: a strictly positive convex combination `c` of
/// a finite set spanning `M` lies in `relint M`. If `relint K ∩ relint L` is
/// nonempty, then `relint M = relint K ∩ relint L` (Rockafellar, Convex
/// Analysis, Thm 6.5), so `c` lies in both relative interiors; conversely if
/// `c` does, they meet. Hence: Overlapping iff `c ∈ relint K ∩ relint L`.
/// We take the weights proportional to the homogeneous denominators, so `c`
/// is just the coordinate-wise sum of the homogeneous points.
fn contact_hulls(k: &[IPt], l: &[IPt]) -> Contact {
    let mut v: Vec<HPt> = Vec::new();
    for x in k {
        let h = HPt::from_ipt(x);
        if in_closed_hull(&h, l) {
            v.push(h);
        }
    }
    for y in l {
        let h = HPt::from_ipt(y);
        if in_closed_hull(&h, k) {
            v.push(h);
        }
    }
    for i in 0..edge_count(k.len()) {
        let (a, b) = edge(k, i);
        for j in 0..edge_count(l.len()) {
            let (c, d) = edge(l, j);
            let collinear =
                orient(a, b, c) == Ordering::Equal && orient(a, b, d) == Ordering::Equal;
            if !collinear && seg_intersect(a, b, c, d) {
                v.push(crossing_point(a, b, c, d));
            }
        }
    }
    if v.is_empty() {
        return Contact::Disjoint;
    }
    let mut c = HPt {
        x: BigInt::zero(),
        y: BigInt::zero(),
        w: BigInt::zero(),
    };
    for h in &v {
        c.x += &h.x;
        c.y += &h.y;
        c.w += &h.w;
    }
    if in_relint_hull(&c, k) && in_relint_hull(&c, l) {
        Contact::Overlapping
    } else {
        Contact::Touching
    }
}

/// Exact contact status of two filled convex polygons.
///
/// Each polygon is taken as the convex hull of its vertices (any order or
/// orientation; collinear or repeated vertices are harmless; 1 vertex = a
/// point, 2 vertices = a segment, all-collinear = a segment). With relative
/// interiors `relint(point) = the point`, `relint(segment) = the open
/// segment`, `relint(polygon with area) = its open interior`:
/// - `Disjoint`: the filled sets do not meet;
/// - `Touching`: they meet but their relative interiors do not (two squares
///   sharing an edge or a corner; a point on a polygon's boundary or equal to
///   a segment endpoint; two segments meeting at an endpoint or crossing at
///   one segment's endpoint; a segment lying along a polygon edge);
/// - `Overlapping`: the relative interiors meet (a point inside a polygon or
///   in the open part of a segment; two equal points; two collinear segments
///   overlapping in more than a point; two segments crossing at interior
///   points; any containment of polygons with area).
///
/// Method: exact hulls, then the finite candidate argument documented in the
/// source (`contact_hulls`): the vertex set of `P ∩ Q` is computed exactly and
/// its centroid decides.
///
/// # Panics
/// Panics if a polygon is empty or a coordinate is not finite.
pub fn contact_status_convex(p: &[DVec2], q: &[DVec2]) -> Contact {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "contact_status_convex: empty polygon"
    );
    let g = Grid::for_points(p.iter().chain(q));
    let k = convex_hull(&g.pts(p));
    let l = convex_hull(&g.pts(q));
    contact_hulls(&k, &l)
}

/// Parameter `t` (as a fraction) of the point `c` on the line `a + t (b − a)`,
/// for `c` known to be on that line.
fn param_of(a: &IPt, b: &IPt, c: &IPt) -> Frac {
    let ab = b.sub(a);
    Frac {
        n: dot(&c.sub(a), &ab),
        d: dot(&ab, &ab),
    }
}

/// Whether some point just to the left or just to the right of a piece of
/// edge `a → b` of the simple polygon `own` (orientation `own_ccw`) lies in
/// the interiors of both `own` and `other` (orientation `other_ccw`).
///
/// The edge is cut at every parameter where an edge of `other` meets it; for
/// each piece its midpoint `m` meets no boundary other than this edge and,
/// possibly, one collinear edge of `other` containing the whole piece. So the
/// side classification near `m` is exact and local.
fn edge_sides_overlap(a: &IPt, b: &IPt, own_ccw: bool, other: &[IPt], other_ccw: bool) -> bool {
    let mut ts: Vec<Frac> = vec![Frac::zero(), Frac::int(BigInt::one())];
    let zero = Frac::zero();
    let one = Frac::int(BigInt::one());
    for j in 0..other.len() {
        let (c, d) = edge(other, j);
        let oc = orient(a, b, c);
        let od = orient(a, b, d);
        if oc == Ordering::Equal && od == Ordering::Equal {
            for e in [c, d] {
                let t = param_of(a, b, e);
                if t >= zero && t <= one {
                    ts.push(t);
                }
            }
        } else if seg_intersect(a, b, c, d) {
            let ab = b.sub(a);
            let cd = d.sub(c);
            let mut den = cross(&ab, &cd);
            let mut num = cross(&c.sub(a), &cd);
            if den.is_negative() {
                den = -den;
                num = -num;
            }
            ts.push(Frac { n: num, d: den });
        }
    }
    ts.sort();
    ts.dedup();
    let ab = b.sub(a);
    for w in ts.windows(2) {
        let (t0, t1) = (&w[0], &w[1]);
        // m = a + ((t0 + t1) / 2) (b − a), homogeneous with w = 2 d0 d1.
        let den = BigInt::from(2) * &t0.d * &t1.d;
        let num = &t0.n * &t1.d + &t1.n * &t0.d;
        let m = HPt {
            x: &a.x * &den + &num * &ab.0,
            y: &a.y * &den + &num * &ab.1,
            w: den,
        };
        let left_in_own = own_ccw;
        let right_in_own = !own_ccw;
        let mut on_edge: Option<bool> = None;
        for j in 0..other.len() {
            let (c, d) = edge(other, j);
            if on_segment_h(c, d, &m) {
                on_edge = Some(sign_of(&dot(&ab, &d.sub(c))) == Ordering::Greater);
                break;
            }
        }
        let (left_in_other, right_in_other) = match on_edge {
            Some(same_direction) => {
                let left = same_direction == other_ccw;
                (left, !left)
            }
            None => {
                let inside = locate(&m, other) == Location::Inside;
                (inside, inside)
            }
        };
        if (left_in_own && left_in_other) || (right_in_own && right_in_other) {
            return true;
        }
    }
    false
}

/// Exact contact status of two filled simple polygons (3 or more vertices,
/// either orientation, collinear vertices allowed):
/// - `Disjoint`: the closed regions do not meet (boundaries disjoint and
///   neither contains the other);
/// - `Touching`: the boundaries meet but the open interiors do not;
/// - `Overlapping`: the open interiors meet (including containment).
///
/// Method (brute force, `O((n + m + k)·(n + m))`): every face of the
/// arrangement of both boundaries that lies in both interiors has a boundary
/// piece (an edge cut at all intersection points); so the interiors meet iff
/// next to the midpoint of some piece, on its left or its right, both
/// interiors are present, which is decided exactly and locally. If they do
/// not, the regions meet iff the boundaries do (a common point in one
/// interior and the other's boundary would force interior overlap).
///
/// # Panics
/// Panics if a coordinate is not finite or a polygon is not simple
/// (checked with [`is_simple`]).
pub fn contact_status_simple(p: &[DVec2], q: &[DVec2]) -> Contact {
    assert!(
        is_simple(p),
        "contact_status_simple: first polygon is not simple"
    );
    assert!(
        is_simple(q),
        "contact_status_simple: second polygon is not simple"
    );
    let g = Grid::for_points(p.iter().chain(q));
    let (pi, qi) = (g.pts(p), g.pts(q));
    let p_ccw = signed_area2_grid(&pi).is_positive();
    let q_ccw = signed_area2_grid(&qi).is_positive();
    for i in 0..pi.len() {
        let (a, b) = edge(&pi, i);
        if edge_sides_overlap(a, b, p_ccw, &qi, q_ccw) {
            return Contact::Overlapping;
        }
    }
    for j in 0..qi.len() {
        let (a, b) = edge(&qi, j);
        if edge_sides_overlap(a, b, q_ccw, &pi, p_ccw) {
            return Contact::Overlapping;
        }
    }
    for i in 0..pi.len() {
        let (a, b) = edge(&pi, i);
        for j in 0..qi.len() {
            let (c, d) = edge(&qi, j);
            if seg_intersect(a, b, c, d) {
                return Contact::Touching;
            }
        }
    }
    Contact::Disjoint
}
