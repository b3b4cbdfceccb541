//! Shewchuk's floating-point expansion arithmetic: exact sums and products of `f64` values.
//!
//! An expansion is a sum of `f64` components, nonoverlapping and ordered by increasing magnitude, whose
//! exact (unrounded) sum is the represented value. Its sign is the sign of its largest component.
//!
//! Exactness holds while no product underflows: the exact stage (see `Polynomial`) only calls these routines on inputs
//! rescaled by a power of two so that every intermediate value is far above the subnormal range
//! (see `docs/ROBUSTNESS.md`).
//!
//! # References
//! J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
//! Discrete & Computational Geometry 18 (1997) 305–363: Theorems 6 (Two-Sum), 17 (Two-Product with
//! Dekker's split), 13 (Fast-Expansion-Sum, here the linear-merge variant with zero elimination),
//! 19 (Scale-Expansion).

use smallvec::SmallVec;

/// `s + e = a + b` exactly, `s = fl(a + b)` (Knuth's branch-free Two-Sum, Shewchuk Theorem 7).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    let br = b - bv;
    let ar = a - av;
    (s, ar + br)
}

/// `s + e = a + b` exactly when `|a| ≥ |b|` or `a == 0` (Dekker's Fast-Two-Sum, Shewchuk Theorem 6).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Dekker's split: `a = hi + lo` with each half fitting in 26 bits (Shewchuk Theorem 17).
#[inline]
fn split(a: f64) -> (f64, f64) {
    // splitter = 2^27 + 1
    const SPLITTER: f64 = 134_217_729.0;
    let c = SPLITTER * a;
    let big = c - a;
    let hi = c - big;
    (hi, a - hi)
}

/// `p + e = a · b` exactly, `p = fl(a · b)` (Shewchuk's Two-Product; exact without underflow).
#[inline]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ahi, alo) = split(a);
    let (bhi, blo) = split(b);
    let err1 = p - ahi * bhi;
    let err2 = err1 - alo * bhi;
    let err3 = err2 - ahi * blo;
    (p, alo * blo - err3)
}

/// Inline capacity of an expansion: the compressed expansions our predicates produce are short.
const INLINE: usize = 16;

/// An exact real number represented as a nonoverlapping sum of `f64` components.
///
/// Used by the `Robust` kernel's exact stage and by the `Exact` kernel; it implements [`crate::Ring`].
/// Its operations are exact as long as nothing overflows and no product underflows; callers with
/// arbitrary inputs should go through [`crate::Kernel::sign`] or [`crate::round_value`], which rescale.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expansion {
    // Increasing magnitude, nonoverlapping, no zero components.
    comps: SmallVec<[f64; INLINE]>,
}

impl Expansion {
    /// The exact value `x`.
    #[must_use]
    pub fn from_f64(x: f64) -> Self {
        let mut comps = SmallVec::new();
        if x != 0.0 {
            comps.push(x);
        }
        Expansion { comps }
    }

    /// The sign of the represented value (the sign of its most significant component).
    #[must_use]
    pub fn sign(&self) -> crate::Sign {
        match self.comps.last() {
            None => crate::Sign::Zero,
            Some(&x) => crate::Sign::of_f64(x),
        }
    }

    /// An approximation of the value (the sum of the components, rounded).
    #[must_use]
    pub fn approx(&self) -> f64 {
        self.comps.iter().sum()
    }

    /// The value rounded to the nearest `f64` (ties to even): one correct rounding of the exact value.
    ///
    /// This is what "compute the intermediates exactly, round once" means for constructions. Overflow
    /// gives ±∞ as IEEE rounding would; values in the subnormal range round correctly too.
    #[must_use]
    pub fn to_f64(&self) -> f64 {
        // Renormalise: sweep from the top with Fast-Two-Sum so that `top` is fl-close to the value and
        // `rest` (exact) holds the remainder; then decide the rounding of top + rest exactly.
        let comps = &self.comps[..];
        let Some((&largest, lower)) = comps.split_last() else {
            return 0.0;
        };
        let mut top = largest;
        let mut rest = Expansion::default();
        for &c in lower.iter().rev() {
            let (s, e) = two_sum(top, c);
            top = s;
            rest = rest.add(&Expansion::from_f64(e));
        }
        if !top.is_finite() {
            return top;
        }
        // Now value = top + rest exactly. While |rest| exceeds half an ulp of top, move top one step.
        // A bounded number of steps suffices (|rest| ≤ a few ulps after the sweep); the loop is capped.
        for _ in 0..8 {
            let rs = rest.sign();
            if rs == crate::Sign::Zero {
                return top;
            }
            let toward = if rs == crate::Sign::Positive {
                top.next_up()
            } else {
                top.next_down()
            };
            if !toward.is_finite() {
                return toward;
            }
            // The midpoint between top and its neighbour lies at (toward − top)/2 from top; compare
            // 2·rest with the step (toward − top), both exact (halving could underflow, doubling cannot
            // overflow here: |rest| is a few ulps of a finite top).
            let step = toward - top;
            let diff = rest.scale(2.0).sub(&Expansion::from_f64(step));
            let beyond = match rs {
                crate::Sign::Positive => diff.sign(),
                _ => diff.sign().reversed(),
            };
            match beyond {
                crate::Sign::Negative => return top,
                crate::Sign::Zero => {
                    // A tie: the even one of top and toward.
                    return if top.to_bits() & 1 == 0 { top } else { toward };
                }
                crate::Sign::Positive => {
                    rest = rest.sub(&Expansion::from_f64(toward - top));
                    top = toward;
                }
            }
        }
        top
    }

    /// The number of nonzero components.
    #[must_use]
    pub fn len(&self) -> usize {
        self.comps.len()
    }

    /// `true` when the value is exactly zero.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.comps.is_empty()
    }

    /// The components, increasing in magnitude.
    #[must_use]
    pub fn components(&self) -> &[f64] {
        &self.comps
    }

    /// `self + other`, exactly (linear expansion sum with zero elimination, Shewchuk Theorem 13).
    #[must_use]
    pub fn add(&self, other: &Self) -> Self {
        self.sum(other, false)
    }

    /// `−self`, exactly.
    #[must_use]
    pub fn neg(&self) -> Self {
        Expansion {
            comps: self.comps.iter().map(|&x| -x).collect(),
        }
    }

    /// `self − other`, exactly (the sum with `other`'s components negated as they are merged).
    #[must_use]
    pub fn sub(&self, other: &Self) -> Self {
        self.sum(other, true)
    }

    /// `self ± other`: Shewchuk's Linear-Expansion-Sum (Theorem 13) with zero elimination, the two
    /// component sequences merged by magnitude as the sweep consumes them (no merged copy, no negated
    /// copy of `other`). The merged sequence is strongly nonoverlapping-compatible and the sweep exact.
    fn sum(&self, other: &Self, negate: bool) -> Self {
        let (e, f) = (&self.comps[..], &other.comps[..]);
        let sign = if negate { -1.0 } else { 1.0 };
        if e.is_empty() {
            return if negate { other.neg() } else { other.clone() };
        }
        if f.is_empty() {
            return self.clone();
        }
        let (mut i, mut j) = (0, 0);
        // The next component of the merge by increasing magnitude (ties take `f`'s first).
        let mut next = || {
            if i < e.len() && (j == f.len() || e[i].abs() < f[j].abs()) {
                i += 1;
                e[i - 1]
            } else {
                j += 1;
                sign * f[j - 1]
            }
        };
        let total = e.len() + f.len();
        let g0 = next();
        let g1 = next();
        // Built in place in the returned value (no move of the inline buffer on return).
        let mut res = Expansion::default();
        res.comps.reserve(total);
        let out = &mut res.comps;
        let (mut q, mut qq) = fast_two_sum(g1, g0);
        for _ in 2..total {
            let (r, h) = fast_two_sum(next(), qq);
            if h != 0.0 {
                out.push(h);
            }
            let (s, t) = two_sum(q, r);
            q = s;
            qq = t;
        }
        if qq != 0.0 {
            out.push(qq);
        }
        if q != 0.0 {
            out.push(q);
        }
        res
    }

    /// `self · b` for one `f64`, exactly (Scale-Expansion with zero elimination, Shewchuk Theorem 19).
    #[must_use]
    pub fn scale(&self, b: f64) -> Self {
        let e = &self.comps[..];
        let mut res = Expansion::default();
        if e.is_empty() || b == 0.0 {
            return res;
        }
        res.comps.reserve(2 * e.len());
        let out = &mut res.comps;
        let (mut q, h) = two_product(e[0], b);
        if h != 0.0 {
            out.push(h);
        }
        for &ei in &e[1..] {
            let (p1, p0) = two_product(ei, b);
            let (sum, h) = two_sum(q, p0);
            if h != 0.0 {
                out.push(h);
            }
            let (q2, h2) = fast_two_sum(p1, sum);
            if h2 != 0.0 {
                out.push(h2);
            }
            q = q2;
        }
        if q != 0.0 {
            out.push(q);
        }
        res
    }

    /// `self · other`, exactly: the sum of `self` scaled by each component of `other`.
    #[must_use]
    pub fn mul(&self, other: &Self) -> Self {
        let (short, long) = if self.len() <= other.len() {
            (self, other)
        } else {
            (other, self)
        };
        let Some((&first, rest)) = short.comps.split_first() else {
            return Expansion::default();
        };
        let mut acc = long.scale(first);
        for &c in rest {
            acc = acc.add(&long.scale(c));
        }
        acc
    }
}
