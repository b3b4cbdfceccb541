//! A certified enclosure of the CMMR distance of two large convex polygons (issue 8): two dyadic
//! rationals `lo ≤ CMMR ≤ hi`, with `hi − lo < 2⁻¹⁰⁰·CMMR`, computed from exact per-vertex squared
//! distances without ever forming the exact sum.
//!
//! CMMR (Atallah, Ribeiro and Lifschitz 1991, section 3) is `Σ δ(v)²` over the vertices `v` of
//! both polygons, `δ(v)` the distance from `v` to the other *filled* polygon (0 inside or on it),
//! as [`crate::cmmr`] defines it (the other polygon taken as the convex hull of its vertices).
//! Each term is an exact rational `N²/L` with its own denominator `L` (a squared edge length), so
//! the exact sum of 10⁵ terms has a common denominator of millions of bits; [`crate::cmmr`] forms
//! it, at `Θ(n²)` bit operations. A test of "within 6 ulps" only needs an interval around the sum
//! much narrower than one ulp of it, which this module computes in `O(N log N)` exact operations
//! on big integers. It uses only this crate's exact big-integer primitives, never polydist's
//! algorithms: the nearest edge is found by its own binary searches (exact signs, proofs at
//! [`fan_locate`] and [`sq_dist_outside`]) and each term is checked against the brute force in
//! the tests.
//!
//! # The enclosure and its proof
//! Work on the common grid of both polygons (every coordinate an integer times `2^e`, exact, as in
//! the rest of the oracle); squared lengths in grid units are multiplied by `4^e` at the end.
//!
//! 1. **Exact terms.** For a vertex `v` of one polygon, let `H` be the convex hull of the other's
//!    vertices (exact, counter-clockwise, strictly convex: [`crate::contact`]'s hull).
//!    * If `H` has 1 or 2 vertices, `δ(v)²` is the exact distance to that point or segment.
//!    * Otherwise `v ∈ H` is decided exactly by a binary search over the fan of triangles
//!      `(h₀, hᵢ, hᵢ₊₁)` ([`fan_locate`], proof at the function). Inside or on: `δ(v)² = 0`.
//!    * Outside: `δ(v)²` is the exact squared distance from `v` to `H`'s nearest edge, found by
//!      binary searches over the edges visible from `v`, on which the distance is unimodal
//!      ([`sq_dist_outside`], proof there): an exact fraction `n/d` in grid units (`n ≥ 0`, `d > 0`
//!      integers, `d` a squared edge length or 1).
//! 2. **Rounding each term, exactly.** For an integer `k` chosen below, each term is rounded to the
//!    grid `2^−k` downward and upward by exact big-integer division: `aᵢ = ⌊nᵢ·2^k / dᵢ⌋`,
//!    `bᵢ = ⌈nᵢ·2^k / dᵢ⌉` (for `k < 0`, dividing by `dᵢ·2^−k`). Then
//!    `aᵢ·2^−k ≤ nᵢ/dᵢ ≤ bᵢ·2^−k` and `bᵢ − aᵢ ∈ {0, 1}` (0 when the term is on the grid).
//! 3. **Summing exactly.** `A = Σ aᵢ` and `B = Σ bᵢ` are big-integer sums (no rounding), so
//!    `lo = A·2^−k·4^e ≤ CMMR ≤ B·2^−k·4^e = hi`, both returned as exact rationals.
//! 4. **Width.** Let `E = max(bits(nᵢ) − bits(dᵢ))` over the `N'` nonzero terms; the largest term
//!    exceeds `2^(E−1)` (as `nᵢ ≥ 2^(bits(nᵢ)−1)`, `dᵢ < 2^bits(dᵢ)`), so the sum `S` (grid units)
//!    does too. With `k = bits(N') + 101 − E`: `B − A ≤ N' < 2^bits(N')`, so
//!    `(B − A)·2^−k < 2^(E−101) < 2⁻¹⁰⁰·S`. One ulp of `S` is at least `2⁻⁵³·S` (normal range),
//!    so the interval is narrower than `2⁻⁴⁷` ulp of the exact CMMR; the tests check it
//!    (`< 10⁻³` ulp) on every case rather than trusting this arithmetic. All terms zero: `[0, 0]`.
//!
//! # Deciding "within `b` ulps"
//! [`CmmrEnclosure::ulps_error`] returns an upper bound of `|c − x| / ulp(x)` over every `x` in
//! `[lo, hi]` ([`crate::ulps_error_interval`]): a computed value passing `≤ b` against it is within
//! `b` ulps of the exact CMMR, whatever its position in the interval; an interval too wide to
//! decide makes the bound large and the check fail, never pass.
//!
//! # Complexity
//! `O(N log N)` exact operations for `N = |p| + |q|`: the hulls (a sort), then per vertex one fan
//! location and four binary searches (`O(log m)` orientations and dot products) and three exact
//! point–edge distances; then two big-integer divisions per term. Measured on the 9 large pairs
//! (10⁴–2·10⁵ vertices), debug test build on a shared 2-core machine: 0.02–0.2 s for the pairs of
//! about 10⁴ vertices, 2.3–2.6 s for the pairs of 2·10⁵, 6 s in all. (A first version took the
//! distance of each outside vertex from the pruned box search of [`crate::pruned`]: the same terms,
//! but `Θ(√n)` leaves per vertex on the dense circles, whose boxes near the nearest point all lie
//! within the optimum; 33 s per pair of 2·10⁵ vertices. The enclosures first stored in
//! `fixtures/hard/large_convex.txt` were computed by it, and the searches here give the same
//! intervals on all 9 pairs, which the suite recomputes: two methods, one answer.)

use core::cmp::Ordering;

use glam::DVec2;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::contact::convex_hull;
use crate::exact::{Frac, Grid, IPt, cross, dot, orient, sq_ps};
use crate::hausdorff::sq_to_hull;
use crate::rounding::{ulps_error_interval, width_ulps};

/// The relative width of the enclosure is below `2^−WIDTH_BITS` (module doc, step 4).
const WIDTH_BITS: i64 = 100;

/// Two exact rationals enclosing the CMMR distance of two polygons: `lo ≤ CMMR ≤ hi`, with
/// `hi − lo < 2⁻¹⁰⁰·CMMR` (both 0 when the CMMR is 0). Built by [`cmmr_enclosure`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CmmrEnclosure {
    /// A lower bound of the exact CMMR (a dyadic rational).
    pub lo: BigRational,
    /// An upper bound of the exact CMMR (a dyadic rational).
    pub hi: BigRational,
}

impl CmmrEnclosure {
    /// Whether `x` lies in `[lo, hi]`.
    #[must_use]
    pub fn contains(&self, x: &BigRational) -> bool {
        self.lo <= *x && *x <= self.hi
    }

    /// An upper bound, in ulps, of the error of `computed` against every point of `[lo, hi]`
    /// (hence against the exact CMMR): [`crate::ulps_error_interval`].
    #[must_use]
    pub fn ulps_error(&self, computed: f64) -> f64 {
        ulps_error_interval(computed, &self.lo, &self.hi)
    }

    /// The width `hi − lo` in units of `ulp(lo)`, rounded upward: how far the enclosure is from
    /// deciding an error bound exactly (0 for an exact value).
    #[must_use]
    pub fn width_ulps(&self) -> f64 {
        width_ulps(&self.lo, &self.hi)
    }
}

/// A certified enclosure of the CMMR distance of the filled convex polygons `p` and `q` (each taken
/// as the convex hull of its vertices; 1 vertex = a point, 2 = a segment): the sum over the
/// vertices of `p` of their squared distances to filled `q`, plus the same from `q` to `p`, exactly
/// as [`crate::cmmr`] defines it, enclosed in `[lo, hi]` with `hi − lo < 2⁻¹⁰⁰·CMMR`.
///
/// Paper: Atallah, Ribeiro and Lifschitz 1991, section 3 (the measure). The proof of the
/// enclosure is in the module doc (`cmmr_bound.rs`).
///
/// # Complexity
/// `O(N log N)` exact big-integer operations, `N = |p| + |q|` (module doc).
///
/// # Panics
/// Panics if `p` or `q` is empty or a coordinate is not finite.
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_oracle::{cmmr, cmmr_enclosure};
///
/// let p = [DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)];
/// let q = [DVec2::new(0.3, 0.3), DVec2::new(2.0, 0.1), DVec2::new(0.1, 2.0)];
/// let e = cmmr_enclosure(&p, &q);
/// assert!(e.contains(&cmmr(&p, &q)));
/// assert!(e.width_ulps() < 1e-3);
/// ```
#[must_use]
pub fn cmmr_enclosure(p: &[DVec2], q: &[DVec2]) -> CmmrEnclosure {
    assert!(
        !p.is_empty() && !q.is_empty(),
        "cmmr_enclosure: empty polygon"
    );
    let grid = Grid::for_points(p.iter().chain(q));
    let (pi, qi) = (grid.pts(p), grid.pts(q));
    let mut terms = sq_dists_to_filled(&pi, &qi);
    terms.extend(sq_dists_to_filled(&qi, &pi));
    enclose(&terms, &grid)
}

/// The exact `δ(v)²` (grid units) of every `v` in `vs` to the filled convex hull of `other`
/// (module doc, step 1).
fn sq_dists_to_filled(vs: &[IPt], other: &[IPt]) -> Vec<Frac> {
    let hull = convex_hull(other);
    if hull.len() < 3 {
        return vs.iter().map(|v| sq_to_hull(v, &hull)).collect();
    }
    vs.iter()
        .map(|v| match fan_locate(v, &hull) {
            Ok(()) => Frac::zero(),
            Err(j) => sq_dist_outside(v, &hull, j),
        })
        .collect()
}

/// Whether `v` lies in the closed strictly convex counter-clockwise polygon `h` (`n ≥ 3`): `Ok`,
/// or `Err(j)` with an edge `j` whose line has `v` strictly on its outer side
/// (`orient(hⱼ, hⱼ₊₁, v) < 0`, "edge `j` is visible from `v`"), in `O(log n)` exact orientations.
///
/// Proof. The triangles `Tᵢ = (h₀, hᵢ, hᵢ₊₁)`, `1 ≤ i ≤ n − 2`, cover `h`, and `Tᵢ` is `h`
/// intersected with the closed cone at `h₀` between `uᵢ = hᵢ − h₀` and `uᵢ₊₁`. The directions
/// `u₁, …, uₙ₋₁` turn strictly counter-clockwise within an angle below π (the interior angle at
/// `h₀`). If `v` is outside the cone between `u₁` and `uₙ₋₁` (first two tests), edge 0 or edge
/// `n − 1` is visible. Otherwise `w = v − h₀` lies in that cone, so `w` and every `uᵢ` are less
/// than π apart and `orient(h₀, hᵢ, v) ≥ 0` iff `angle(uᵢ) ≤ angle(w)`: true at `i = 1`, and
/// monotone (true, then false) in `i`, so the binary search finds the last `i*` where it holds
/// (`v = h₀` makes it hold everywhere). With `i = min(i*, n − 2)`,
/// `angle(uᵢ) ≤ angle(w) ≤ angle(uᵢ₊₁)`: `v` is in the cone of `Tᵢ`, so `v ∈ h` iff `v ∈ Tᵢ` iff
/// `orient(hᵢ, hᵢ₊₁, v) ≥ 0`; if not, edge `i` is visible.
fn fan_locate(v: &IPt, h: &[IPt]) -> Result<(), usize> {
    let n = h.len();
    if orient(&h[0], &h[1], v) == Ordering::Less {
        return Err(0);
    }
    if orient(&h[0], &h[n - 1], v) == Ordering::Greater {
        // orient(hₙ₋₁, h₀, v) = −orient(h₀, hₙ₋₁, v) < 0.
        return Err(n - 1);
    }
    // Invariant: the test holds at `lo`, fails beyond `hi`.
    let (mut lo, mut hi) = (1, n - 1);
    while lo < hi {
        let mid = (lo + hi).div_ceil(2);
        if orient(&h[0], &h[mid], v) == Ordering::Less {
            hi = mid - 1;
        } else {
            lo = mid;
        }
    }
    let i = lo.min(n - 2);
    if orient(&h[i], &h[i + 1], v) == Ordering::Less {
        Err(i)
    } else {
        Ok(())
    }
}

/// Whether `v` lies in the closed strictly convex counter-clockwise polygon `h` ([`fan_locate`]).
#[cfg(test)]
fn in_closed_convex(v: &IPt, h: &[IPt]) -> bool {
    fan_locate(v, h).is_ok()
}

/// The exact squared distance (grid units) from `v`, outside the closed strictly convex
/// counter-clockwise polygon `h` (`n ≥ 3`), to `h`, given an edge `j` visible from `v`; `O(log n)`
/// exact evaluations. Indices are taken mod `n`; `dᵢ = hᵢ₊₁ − hᵢ`, `nᵢ = (dᵢ.y, −dᵢ.x)` the outward
/// normal, so edge `i` is visible iff `nᵢ·(v − hᵢ) > 0` iff `orient(hᵢ, hᵢ₊₁, v) < 0`.
///
/// Proof, in four facts.
/// (a) *The visible edges form one nonempty cyclic run, not all edges.* `nᵢ·v > nᵢ·hᵢ` says that
///     the support line of `h` with normal `nᵢ` separates `v`; the normals of such lines form an
///     open arc of directions shorter than π (those `θ` with `θ·(x − v) < 0` for all `x ∈ h`, a
///     convex set not containing `v`), and the edge normals are in counter-clockwise order, so the
///     visible ones are consecutive; `j` is one; not all, since the normals of a closed polygon do
///     not lie in an open half-plane.
/// (b) *A non-visible edge `k`.* With `u = v − h₀`: `nᵢ·(v − hᵢ) = nᵢ·u + nᵢ·(h₀ − hᵢ) ≤ nᵢ·u`
///     (`h₀ ∈ h` is on the inner side of every edge line), so `nᵢ·u = cross(u, dᵢ) ≤ 0` makes edge
///     `i` non-visible. If it holds for `i = 0`, `k = 0`. Otherwise `−u` has turned from `d₀` by
///     `τ_w ∈ (0, π)`; the turn `τᵢ` of `dᵢ` from `d₀` increases strictly with `i` from 0 to
///     `τₙ₋₁ ∈ (π, 2π)`, each step below π (strict convexity). "`τᵢ < τ_w`" is exactly
///     `cross(d₀, dᵢ) ≥ 0 ∧ cross(dᵢ, −u) > 0` (for `τᵢ ≤ π`, the turn from `dᵢ` to `−u` is then
///     in `(−π, π)`, positive iff the cross product is; `τᵢ = π` makes the second factor
///     negative), true at 0 and false at `n − 1`; the first `k` where it fails has `τ_w ≤ τₖ < τ_w + π`, so `dₖ`
///     lies in the closed half-circle clockwise of `u`: `cross(u, dₖ) ≤ 0`, non-visible.
/// (c) *The run's ends.* From `k` (not visible) counter-clockwise to `j` (visible) the visibility
///     changes once (false, then true), and from `j` to `k + n` once (true, then false), by (a):
///     two binary searches give the run `j₀ ..= j₁`.
/// (d) *Unimodality on the run, and the minimum.* The nearest point of `h` lies on a visible
///     edge (at an edge's interior point, `v − π(v)` is that edge's outward normal; at a vertex, it
///     lies in the vertex's normal cone, and a nonzero vector `a·nₖ₋₁ + b·nₖ`, `a, b ≥ 0`, has a
///     positive dot product with `nₖ₋₁` or `nₖ` since they are less than π apart). Along edge `i`
///     the squared distance `F` has derivative sign `s = sign((x − v)·dᵢ)`, strictly increasing
///     along the edge. At a vertex `hᵢ₊₁` between visible edges `i`, `i + 1`:
///     `(hᵢ₊₁ − v)·dᵢ ≥ 0 ⇒ (hᵢ₊₁ − v)·dᵢ₊₁ > 0` (write `hᵢ₊₁ − v = α dᵢ + β dᵢ₊₁`; visibility of
///     both gives `β > 0 > α`, and the two dot-product signs would give
///     `|dᵢ|²|dᵢ₊₁|² ≤ (dᵢ·dᵢ₊₁)²`, contradicting Cauchy–Schwarz for non-parallel edges). So on
///     the run `F` decreases, then increases; "`F` rises at the end of edge `i`",
///     `(hᵢ₊₁ − v)·dᵢ > 0`, is false then true along the run, and at the first edge `i*` where it
///     holds (or `j₁` if none) `F`'s minimum over the run, hence `δ(v)²`, is `F`'s minimum over
///     edge `i*`: [`sq_ps`] of that edge, exact. The result is the minimum of [`sq_ps`] over edges
///     `i* − 1 ..= i* + 1`: every edge's value is at least `δ(v)²`, and `i*`'s equals it (the
///     neighbours are a cheap guard against an off-by-one in the search, not needed by the proof).
///
/// # Panics
/// Panics if a certificate of the proof fails (`j` not visible or `k` visible): a bug, not a
/// property of the input.
fn sq_dist_outside(v: &IPt, h: &[IPt], j: usize) -> Frac {
    let n = h.len();
    let at = |i: usize| &h[i % n];
    let dir = |i: usize| at(i + 1).sub(at(i));
    let visible = |i: usize| orient(at(i), at(i + 1), v) == Ordering::Less;
    assert!(visible(j), "sq_dist_outside: edge {j} is not visible");
    // (b) A non-visible edge.
    let u = v.sub(&h[0]);
    let d0 = dir(0);
    let k = if cross(&u, &d0).is_positive() {
        let w = (-&u.0, -&u.1);
        let before_w = |i: usize| {
            let di = dir(i);
            !cross(&d0, &di).is_negative() && cross(&di, &w).is_positive()
        };
        // Invariant: before_w(lo), !before_w(hi).
        let (mut lo, mut hi) = (0, n - 1);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if before_w(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    } else {
        0
    };
    assert!(!visible(k), "sq_dist_outside: edge {k} is visible");
    // (c) The run j₀ ..= j₁ (indices in k + 1 ..= k + n − 1, taken mod n).
    let jj = if j > k { j } else { j + n };
    // The last index of `lo..hi` where `holds` is true, given it holds at `lo` and not at `hi`.
    let last = |mut lo: usize, mut hi: usize, holds: &dyn Fn(usize) -> bool| {
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if holds(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    };
    let j0 = last(k, jj, &|i| !visible(i)) + 1;
    let j1 = last(jj, k + n, &|i| visible(i));
    // (d) The first edge of the run where F rises at its end (j₁ if none).
    let rises = |i: usize| dot(&at(i + 1).sub(v), &dir(i)).is_positive();
    let (mut lo, mut hi) = (j0, j1); // every edge before lo falls; rises(hi) or hi = j₁
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if rises(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    [lo + n - 1, lo, lo + 1]
        .into_iter()
        .map(|i| sq_ps(v, at(i), at(i + 1)))
        .min()
        .unwrap_or_else(Frac::zero)
}

/// Steps 2–4 of the module doc: every term rounded down and up to the grid `2^−k` by exact
/// integer division, both sums exact, scaled back to true units.
fn enclose(terms: &[Frac], grid: &Grid) -> CmmrEnclosure {
    let nonzero: Vec<&Frac> = terms.iter().filter(|t| !t.n.is_zero()).collect();
    let Some(e) = nonzero
        .iter()
        .map(|t| t.n.bits() as i64 - t.d.bits() as i64)
        .max()
    else {
        return CmmrEnclosure {
            lo: BigRational::zero(),
            hi: BigRational::zero(),
        };
    };
    let count_bits = i64::from(usize::BITS - nonzero.len().leading_zeros());
    let k = count_bits + WIDTH_BITS + 1 - e;
    let (mut a, mut b) = (BigInt::zero(), BigInt::zero());
    for t in nonzero {
        let (num, den) = if k >= 0 {
            (&t.n << k.unsigned_abs(), t.d.clone())
        } else {
            (t.n.clone(), &t.d << k.unsigned_abs())
        };
        let (floor, rem) = num.div_mod_floor(&den);
        if !rem.is_zero() {
            b += 1;
        }
        b += &floor;
        a += floor;
    }
    // x·2^−k in grid units, as the fraction the grid scales back.
    let scaled = |x: BigInt| {
        if k >= 0 {
            grid.sq_to_rat(&Frac {
                n: x,
                d: BigInt::from(1) << k.unsigned_abs(),
            })
        } else {
            grid.sq_to_rat(&Frac::int(x << k.unsigned_abs()))
        }
    };
    CmmrEnclosure {
        lo: scaled(a),
        hi: scaled(b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{
        Relation, SplitMix64, cmmr, cocircular, convex_pair, per_vertex_sq_dist, random_convex,
    };

    fn pts(v: &[(f64, f64)]) -> Vec<DVec2> {
        v.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
    }

    /// The exact per-vertex terms equal the brute force's, vertex for vertex, on every relation of
    /// the generators (disjoint, touching, overlapping, nested, huge offsets, collinear input),
    /// both orders, and on points and segments.
    #[test]
    fn terms_agree_with_the_brute_force() {
        let mut rng = SplitMix64::new(0xc33);
        let mut pairs: Vec<(Vec<DVec2>, Vec<DVec2>)> = Vec::new();
        for rel in Relation::EVERY {
            for (n, m) in [(3, 3), (4, 7), (13, 9), (40, 61)] {
                let pair = convex_pair(&mut rng, n, m, rel);
                pairs.push((pair.p, pair.q));
            }
        }
        let tri = pts(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]);
        pairs.push((tri.clone(), tri.clone()));
        pairs.push((tri.clone(), pts(&[(1.0, 1.0)])));
        pairs.push((tri.clone(), pts(&[(1.0, 1.0), (7.0, -2.0)])));
        pairs.push((tri.clone(), pts(&[(0.0, 0.0), (4.0, 0.0)])));
        pairs.push((pts(&[(5.0, 5.0)]), pts(&[(1.0, 1.0), (7.0, -2.0)])));
        for (p, q) in &pairs {
            for (a, b) in [(p, q), (q, p)] {
                let grid = Grid::for_points(a.iter().chain(b.iter()));
                let ours: Vec<BigRational> = sq_dists_to_filled(&grid.pts(a), &grid.pts(b))
                    .iter()
                    .map(|f| grid.sq_to_rat(f))
                    .collect();
                assert_eq!(ours, per_vertex_sq_dist(a, b));
            }
        }
    }

    /// The fan location agrees with the exact crossing-rule location, and the `O(log n)` distance
    /// of an outside point with the brute force over every edge, on a lattice of points in and
    /// around random convex polygons (3 to 200 vertices), co-circular lattice sets (exact ties) and
    /// on their vertices, on their edges' lines beyond the vertices and at twice their vertices.
    #[test]
    fn fan_location_and_nearest_edge_are_exact() {
        let mut rng = SplitMix64::new(7);
        for n in [3, 4, 5, 6, 12, 40, 200] {
            let poly = random_convex(&mut rng, n, DVec2::new(0.5, -0.25), 3.0);
            let grid = Grid::for_points(poly.iter());
            let hull = convex_hull(&grid.pts(&poly));
            for h in [hull, convex_hull(&grid.pts(&cocircular(2)))] {
                let xs: Vec<&BigInt> = h.iter().map(|p| &p.x).collect();
                let ys: Vec<&BigInt> = h.iter().map(|p| &p.y).collect();
                let span = |v: &[&BigInt]| {
                    let (lo, hi) = (v.iter().min().cloned(), v.iter().max().cloned());
                    (
                        lo.cloned().unwrap_or_default(),
                        hi.cloned().unwrap_or_default(),
                    )
                };
                let ((x0, x1), (y0, y1)) = (span(&xs), span(&ys));
                // A 41 × 41 lattice over the box grown by about its size, plus points on and
                // beside the boundary.
                let mut probes: Vec<IPt> = Vec::new();
                for i in 0..=40 {
                    for j in 0..=40 {
                        let x = &x0 - (&x1 - &x0) - 1 + (&x1 - &x0 + 1) * 3 * i / 40;
                        let y = &y0 - (&y1 - &y0) - 1 + (&y1 - &y0 + 1) * 3 * j / 40;
                        probes.push(IPt { x, y });
                    }
                }
                for (k, a) in h.iter().enumerate() {
                    let b = &h[(k + 1) % h.len()];
                    probes.push(a.clone());
                    probes.push(IPt {
                        x: &a.x + &b.x,
                        y: &a.y + &b.y,
                    });
                    // a − (b − a): on the edge's line, beyond a.
                    probes.push(IPt {
                        x: &a.x * 2 - &b.x,
                        y: &a.y * 2 - &b.y,
                    });
                }
                let doubled: Vec<IPt> = h
                    .iter()
                    .map(|p| IPt {
                        x: &p.x * 2,
                        y: &p.y * 2,
                    })
                    .collect();
                for v in &probes {
                    for poly in [&h, &doubled] {
                        let want = crate::exact::locate(&crate::exact::HPt::from_ipt(v), poly)
                            != crate::Location::Outside;
                        assert_eq!(in_closed_convex(v, poly), want);
                        // The O(log n) nearest-feature search against the brute force.
                        let ours = sq_dists_to_filled(core::slice::from_ref(v), poly);
                        assert_eq!(ours[0], sq_to_hull(v, poly));
                    }
                }
            }
        }
    }

    /// The enclosure contains the exact CMMR and is narrower than 2⁻¹⁰⁰ of it, on every relation
    /// (zero CMMR gives the exact interval [0, 0]).
    #[test]
    fn encloses_the_exact_sum_narrowly() {
        let mut rng = SplitMix64::new(0xe9c1);
        let tiny = BigRational::new(1.into(), BigInt::from(1) << 100u32);
        for rel in Relation::EVERY {
            for (n, m) in [(3, 3), (6, 5), (25, 31), (80, 70)] {
                let pair = convex_pair(&mut rng, n, m, rel);
                let exact = cmmr(&pair.p, &pair.q);
                let e = cmmr_enclosure(&pair.p, &pair.q);
                assert!(e.contains(&exact), "{rel:?}");
                assert!(&e.hi - &e.lo <= &exact * &tiny, "{rel:?}: too wide");
                if exact.is_zero() {
                    assert_eq!((e.lo.is_zero(), e.hi.is_zero()), (true, true));
                }
                let c = crate::to_f64_nearest(&exact);
                assert!(e.ulps_error(c) <= 0.5 + 1e-9, "{rel:?}");
                assert!(e.width_ulps() < 1e-3, "{rel:?}");
            }
        }
        let p = random_convex(&mut rng, 10, DVec2::ZERO, 1.0);
        assert_eq!(
            cmmr_enclosure(&p, &p),
            CmmrEnclosure {
                lo: BigRational::zero(),
                hi: BigRational::zero()
            }
        );
    }
}
