//! The coordinate range polydist accepts, and why.
//!
//! **Predicates** are exact for every finite `f64` input under the Robust and Exact kernels: each exact
//! evaluation rescales its inputs by a power of two (overflow is impossible after rescaling) and falls
//! back to integer arithmetic when the inputs' dynamic range is too wide for expansions (underflow is
//! impossible there). See `docs/ROBUSTNESS.md`.
//!
//! **Constructions** (distances, witness points) are `f64` and must not overflow: a squared distance
//! between two points with coordinates of magnitude at most `R` is at most `8R²`. Polygon constructors
//! therefore accept coordinates with `|x| ≤` [`MAX_COORDINATE`] `= 2^500` (about `3.3e150`), which keeps
//! every squared distance below `2^1004`, far from overflow. Subnormal and tiny coordinates are accepted.

/// The largest coordinate magnitude polygon constructors accept: `2^500`.
pub const MAX_COORDINATE: f64 = f64::from_bits((1023 + 500) << 52);

/// `true` when `x` is finite and `|x| ≤` [`MAX_COORDINATE`].
#[inline]
#[must_use]
pub fn is_valid_coordinate(x: f64) -> bool {
    x.abs() <= MAX_COORDINATE
}
