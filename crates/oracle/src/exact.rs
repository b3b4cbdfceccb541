//! Exact arithmetic core.
//!
//! Every finite `f64` is a dyadic rational `m · 2^e`. For a computation on a
//! handful of points we pick the smallest exponent `e_min` among all their
//! coordinates (a [`Grid`]) and represent every coordinate as the big integer
//! `x · 2^(−e_min)`. Orientation tests, dot products and squared lengths are
//! then plain big-integer arithmetic, with no rounding anywhere; squared
//! distances are exact fractions that are scaled back by `2^(2·e_min)` only
//! when handed to the caller.

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Zero};

/// Decodes a finite `x` as `m · 2^e` with `m` odd, or returns `(0, 0)` for ±0.
///
/// # Panics
/// Panics if `x` is not finite.
pub(crate) fn decode(x: f64) -> (i64, i32) {
    assert!(
        x.is_finite(),
        "polydist-oracle: coordinates must be finite, got {x}"
    );
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let exp_field = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (mut m, mut e) = if exp_field == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp_field - 1075)
    };
    if m == 0 {
        return (0, 0);
    }
    let tz = m.trailing_zeros();
    m >>= tz;
    e += tz as i32;
    (if negative { -m } else { m }, e)
}

/// `2^k` as a big integer (`k >= 0`).
pub(crate) fn pow2_int(k: u64) -> BigInt {
    BigInt::one() << k
}

/// Exact conversion of an `f64` to a rational.
///
/// Returns `None` for NaN and ±∞; every finite double (including subnormals
/// and −0.0, which maps to 0) converts exactly.
pub fn rat(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    let (m, e) = decode(x);
    let m = BigInt::from(m);
    Some(if e >= 0 {
        BigRational::from_integer(m << e.unsigned_abs())
    } else {
        BigRational::new(m, pow2_int(u64::from(e.unsigned_abs())))
    })
}

/// [`rat`] for coordinates, which the crate requires to be finite.
pub(crate) fn rat_finite(x: f64) -> BigRational {
    match rat(x) {
        Some(r) => r,
        None => panic!("polydist-oracle: coordinates must be finite, got {x}"),
    }
}

/// Sign of a big integer as an `Ordering` against zero.
pub(crate) fn sign_of(v: &BigInt) -> Ordering {
    match v.sign() {
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
        Sign::Plus => Ordering::Greater,
    }
}

/// A point with big-integer coordinates on some [`Grid`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct IPt {
    pub(crate) x: BigInt,
    pub(crate) y: BigInt,
}

impl IPt {
    pub(crate) fn sub(&self, o: &IPt) -> (BigInt, BigInt) {
        (&self.x - &o.x, &self.y - &o.y)
    }
}

/// A rational point in homogeneous form `(x / w, y / w)` with `w > 0`, on the
/// same grid as the [`IPt`]s it is combined with.
#[derive(Clone, Debug)]
pub(crate) struct HPt {
    pub(crate) x: BigInt,
    pub(crate) y: BigInt,
    pub(crate) w: BigInt,
}

impl HPt {
    pub(crate) fn from_ipt(p: &IPt) -> HPt {
        HPt {
            x: p.x.clone(),
            y: p.y.clone(),
            w: BigInt::one(),
        }
    }

    /// Whether this rational point equals the grid point `p`.
    pub(crate) fn equals(&self, p: &IPt) -> bool {
        self.x == &p.x * &self.w && self.y == &p.y * &self.w
    }
}

/// Cross product of two integer vectors.
pub(crate) fn cross(u: &(BigInt, BigInt), v: &(BigInt, BigInt)) -> BigInt {
    &u.0 * &v.1 - &u.1 * &v.0
}

/// Dot product of two integer vectors.
pub(crate) fn dot(u: &(BigInt, BigInt), v: &(BigInt, BigInt)) -> BigInt {
    &u.0 * &v.0 + &u.1 * &v.1
}

/// A nonnegative-denominator fraction `n / d` (`d > 0`), compared by value.
/// Not normalised: only used for exact comparisons inside one computation.
#[derive(Clone, Debug)]
pub(crate) struct Frac {
    pub(crate) n: BigInt,
    pub(crate) d: BigInt,
}

impl Frac {
    pub(crate) fn int(n: BigInt) -> Frac {
        Frac {
            n,
            d: BigInt::one(),
        }
    }

    pub(crate) fn zero() -> Frac {
        Frac::int(BigInt::zero())
    }
}

impl PartialEq for Frac {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Frac {}

impl PartialOrd for Frac {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Frac {
    fn cmp(&self, other: &Self) -> Ordering {
        (&self.n * &other.d).cmp(&(&other.n * &self.d))
    }
}

/// The common dyadic grid of a set of points: value = integer · 2^exp.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid {
    exp: i32,
}

impl Grid {
    /// The coarsest grid on which all coordinates of `pts` are integers.
    ///
    /// # Panics
    /// Panics if a coordinate is not finite.
    pub(crate) fn for_points<'a>(pts: impl IntoIterator<Item = &'a DVec2>) -> Grid {
        let mut exp = i32::MAX;
        for p in pts {
            for c in [p.x, p.y] {
                let (m, e) = decode(c);
                if m != 0 {
                    exp = exp.min(e);
                }
            }
        }
        Grid {
            exp: if exp == i32::MAX { 0 } else { exp },
        }
    }

    /// The integer representing `x` on this grid (`x` must lie on it).
    pub(crate) fn int(&self, x: f64) -> BigInt {
        let (m, e) = decode(x);
        if m == 0 {
            return BigInt::zero();
        }
        debug_assert!(e >= self.exp);
        BigInt::from(m) << (e - self.exp).unsigned_abs()
    }

    pub(crate) fn pt(&self, p: DVec2) -> IPt {
        IPt {
            x: self.int(p.x),
            y: self.int(p.y),
        }
    }

    pub(crate) fn pts(&self, ps: &[DVec2]) -> Vec<IPt> {
        ps.iter().map(|&p| self.pt(p)).collect()
    }

    /// Converts a squared length measured in grid units to its true value.
    pub(crate) fn sq_to_rat(&self, f: &Frac) -> BigRational {
        let e2 = 2 * i64::from(self.exp);
        if e2 >= 0 {
            BigRational::new(&f.n << e2.unsigned_abs(), f.d.clone())
        } else {
            BigRational::new(f.n.clone(), &f.d << e2.unsigned_abs())
        }
    }

    /// Converts a squared-length-times-area-like quantity of degree `deg`
    /// (a polynomial of total degree `deg` in the coordinates) to its value.
    pub(crate) fn deg_to_rat(&self, v: &BigInt, deg: i64) -> BigRational {
        let e = deg * i64::from(self.exp);
        if e >= 0 {
            BigRational::from_integer(v << e.unsigned_abs())
        } else {
            BigRational::new(v.clone(), pow2_int(e.unsigned_abs()))
        }
    }
}

/// Exact orientation of `c` relative to the directed line `a → b`:
/// `Greater` = left turn (counter-clockwise), `Less` = right turn, `Equal` =
/// collinear (always `Equal` when `a == b`).
pub(crate) fn orient(a: &IPt, b: &IPt, c: &IPt) -> Ordering {
    sign_of(&cross(&b.sub(a), &c.sub(a)))
}

/// [`orient`] with a rational third point.
pub(crate) fn orient_h(a: &IPt, b: &IPt, c: &HPt) -> Ordering {
    let ab = b.sub(a);
    let ac = (&c.x - &a.x * &c.w, &c.y - &a.y * &c.w);
    sign_of(&cross(&ab, &ac))
}

/// The two values in increasing order.
pub(crate) fn ordered<'a>(a: &'a BigInt, b: &'a BigInt) -> (&'a BigInt, &'a BigInt) {
    if a <= b { (a, b) } else { (b, a) }
}

/// Whether `p` (assumed collinear with `a`, `b`) lies in the closed bounding
/// box of `a`, `b`, hence on the closed segment.
fn in_box(a: &IPt, b: &IPt, p: &IPt) -> bool {
    let ((x0, x1), (y0, y1)) = (ordered(&a.x, &b.x), ordered(&a.y, &b.y));
    *x0 <= p.x && p.x <= *x1 && *y0 <= p.y && p.y <= *y1
}

/// Whether the rational point `p` lies on the closed segment `[a, b]`.
pub(crate) fn on_segment_h(a: &IPt, b: &IPt, p: &HPt) -> bool {
    if orient_h(a, b, p) != Ordering::Equal {
        return false;
    }
    let (x0, x1) = if a.x <= b.x {
        (&a.x, &b.x)
    } else {
        (&b.x, &a.x)
    };
    let (y0, y1) = if a.y <= b.y {
        (&a.y, &b.y)
    } else {
        (&b.y, &a.y)
    };
    x0 * &p.w <= p.x && p.x <= x1 * &p.w && y0 * &p.w <= p.y && p.y <= y1 * &p.w
}

/// Whether the closed segments `[a, b]` and `[c, d]` share a point. Handles
/// every degenerate case: collinear overlap, touching endpoints, zero-length
/// segments. (Classic argument: if they meet and do not cross properly, an
/// endpoint of one lies on the other.)
pub(crate) fn seg_intersect(a: &IPt, b: &IPt, c: &IPt, d: &IPt) -> bool {
    use Ordering::Equal;
    let o1 = orient(a, b, c);
    let o2 = orient(a, b, d);
    let o3 = orient(c, d, a);
    let o4 = orient(c, d, b);
    if o1 != Equal && o2 != Equal && o1 != o2 && o3 != Equal && o4 != Equal && o3 != o4 {
        return true;
    }
    (o1 == Equal && in_box(a, b, c))
        || (o2 == Equal && in_box(a, b, d))
        || (o3 == Equal && in_box(c, d, a))
        || (o4 == Equal && in_box(c, d, b))
}

/// Squared distance between two grid points (grid units).
pub(crate) fn sq_pp(p: &IPt, q: &IPt) -> BigInt {
    let v = p.sub(q);
    dot(&v, &v)
}

/// Squared distance from `p` to the closed segment `[a, b]` (grid units).
/// If the projection of `p` falls strictly inside the segment the distance is
/// the distance to the line, `cross² / |b − a|²`; otherwise it is the distance
/// to the nearer endpoint.
pub(crate) fn sq_ps(p: &IPt, a: &IPt, b: &IPt) -> Frac {
    let d = b.sub(a);
    let w = p.sub(a);
    let dd = dot(&d, &d);
    if dd.is_zero() {
        return Frac::int(dot(&w, &w));
    }
    let t = dot(&w, &d);
    if t <= BigInt::zero() {
        Frac::int(dot(&w, &w))
    } else if t >= dd {
        Frac::int(sq_pp(p, b))
    } else {
        let c = cross(&d, &w);
        Frac { n: &c * &c, d: dd }
    }
}

/// Squared distance between closed segments (grid units): zero if they meet,
/// otherwise the minimum of the four endpoint-to-segment distances (for
/// disjoint segments the minimum is always attained at an endpoint).
pub(crate) fn sq_ss(a: &IPt, b: &IPt, c: &IPt, d: &IPt) -> Frac {
    if seg_intersect(a, b, c, d) {
        return Frac::zero();
    }
    [
        sq_ps(a, c, d),
        sq_ps(b, c, d),
        sq_ps(c, a, b),
        sq_ps(d, a, b),
    ]
    .into_iter()
    .min()
    .unwrap_or_else(Frac::zero)
}

/// Number of edges of a closed polyline with `n` vertices: none for 0 or 1
/// vertex, one for 2 vertices (a segment), `n` otherwise.
pub(crate) fn edge_count(n: usize) -> usize {
    match n {
        0 | 1 => 0,
        2 => 1,
        _ => n,
    }
}

/// Endpoints of edge `i` (joining vertex `i` and `(i + 1) mod n`).
pub(crate) fn edge<T>(poly: &[T], i: usize) -> (&T, &T) {
    (&poly[i], &poly[(i + 1) % poly.len()])
}

/// Where a point lies relative to a (filled) polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// In the open interior.
    Inside,
    /// On the boundary (an edge or a vertex).
    Boundary,
    /// In the open exterior.
    Outside,
}

/// Locates a rational point against a closed polyline on the same grid.
///
/// For 3 or more vertices the inside test is the even–odd crossing rule with
/// the half-open convention "a vertex is above the ray iff its y is greater",
/// evaluated with exact orientations, so it is exact for any vertex order.
pub(crate) fn locate(p: &HPt, poly: &[IPt]) -> Location {
    let n = poly.len();
    if n == 0 {
        return Location::Outside;
    }
    if n == 1 {
        return if p.equals(&poly[0]) {
            Location::Boundary
        } else {
            Location::Outside
        };
    }
    for i in 0..edge_count(n) {
        let (a, b) = edge(poly, i);
        if on_segment_h(a, b, p) {
            return Location::Boundary;
        }
    }
    if n == 2 {
        return Location::Outside;
    }
    let mut inside = false;
    for i in 0..n {
        let (a, b) = edge(poly, i);
        let a_above = &a.y * &p.w > p.y;
        let b_above = &b.y * &p.w > p.y;
        if a_above != b_above {
            // The edge crosses the horizontal line through p; the crossing is
            // to the right of p iff p is left of the upward-directed edge.
            let o = orient_h(a, b, p);
            if (b_above && o == Ordering::Greater) || (a_above && o == Ordering::Less) {
                inside = !inside;
            }
        }
    }
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// Exact orientation of three points: `Greater` if `a, b, c` turn
/// counter-clockwise (c strictly left of the directed line a → b), `Less` if
/// clockwise, `Equal` if collinear (including coincident points).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn sign_orient(a: DVec2, b: DVec2, c: DVec2) -> Ordering {
    let g = Grid::for_points([&a, &b, &c]);
    orient(&g.pt(a), &g.pt(b), &g.pt(c))
}

/// Exact squared Euclidean distance between two points.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn sq_dist_pp(p: DVec2, q: DVec2) -> BigRational {
    let g = Grid::for_points([&p, &q]);
    g.sq_to_rat(&Frac::int(sq_pp(&g.pt(p), &g.pt(q))))
}

/// Exact squared distance from `p` to the closed segment `[a, b]`
/// (`a == b` is allowed and gives the point distance).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn sq_dist_ps(p: DVec2, a: DVec2, b: DVec2) -> BigRational {
    let g = Grid::for_points([&p, &a, &b]);
    g.sq_to_rat(&sq_ps(&g.pt(p), &g.pt(a), &g.pt(b)))
}

/// Exact squared distance between the closed segments `[a, b]` and `[c, d]`
/// (0 if they meet; degenerate segments allowed).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn sq_dist_ss(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> BigRational {
    let g = Grid::for_points([&a, &b, &c, &d]);
    g.sq_to_rat(&sq_ss(&g.pt(a), &g.pt(b), &g.pt(c), &g.pt(d)))
}

/// Whether the closed segments `[a, b]` and `[c, d]` share at least one point,
/// exactly, in all degenerate cases (collinear overlap, an endpoint touching
/// the other segment, zero-length segments).
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn segments_intersect(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let g = Grid::for_points([&a, &b, &c, &d]);
    seg_intersect(&g.pt(a), &g.pt(b), &g.pt(c), &g.pt(d))
}

/// Exact location of `p` relative to the filled polygon `poly`.
///
/// `poly` may have either orientation. For 3 or more vertices it must be a
/// simple polygon for "Inside" to mean "in the bounded component" (for a
/// self-intersecting polyline the result is the even–odd rule, and Boundary
/// still means "on some edge"). With 1 or 2 vertices `poly` is a point or a
/// segment: the result is `Boundary` if `p` lies on it, else `Outside`. An
/// empty `poly` gives `Outside`.
///
/// # Panics
/// Panics if a coordinate is not finite.
pub fn point_in_polygon(p: DVec2, poly: &[DVec2]) -> Location {
    let g = Grid::for_points(poly.iter().chain([&p]));
    locate(&HPt::from_ipt(&g.pt(p)), &g.pts(poly))
}
