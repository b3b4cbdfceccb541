//! Row and column minima of implicit totally monotone matrices in linear time (the SMAWK algorithm
//! of Aggarwal, Klawe, Moran, Shor and Wilber), and online column minima for dynamic programming.
//!
//! A matrix is *totally monotone* (for row minima) when in every 2×2 submatrix, rows `i < i'`,
//! columns `j < j'`,
//!
//! ```text
//! M[i][j'] < M[i][j]  implies  M[i'][j'] < M[i'][j]
//! ```
//!
//! that is, once a row strictly prefers a later column, every later row does too. Then the
//! leftmost minimum of each row moves (weakly) right from top to bottom, in every submatrix, and
//! all `m` row minima of an `m` × `n` matrix can be found with `O(m + n)` entry lookups instead of
//! `m·n`. Monge matrices (`M[i][j] + M[i'][j'] <= M[i][j'] + M[i'][j]`) are totally monotone:
//! `(x_i - y_j)²` for sorted `x` and `y`, distances between points on two arcs of a convex curve
//! taken in opposite directions, `g(x_j - x_i)` with `g` convex, and so on.
//!
//! The matrix is never materialised: a [`Matrix`] is a size and an entry lookup (use [`from_fn`]
//! for a closure), and the searches look at `O(m + n)` entries.
//!
//! # What is here
//!
//! | | generic order | `Ord` | `f64` (NaN is an error) |
//! |---|---|---|---|
//! | row minima (leftmost) | [`row_minima_by`] | [`row_minima`] | [`row_minima_f64`] |
//! | column minima (topmost) | [`column_minima_by`] | [`column_minima`] | [`column_minima_f64`] |
//! | online column minima (dynamic programming) | [`online_column_minima_by`] | [`online_column_minima`] | [`online_column_minima_f64`] |
//! | for testing: brute-force row minima | [`brute_force_row_minima_by`] | [`brute_force_row_minima`] | [`brute_force_row_minima_f64`] |
//! | for testing: exact total-monotonicity check | [`check_totally_monotone_by`] | [`check_totally_monotone`] | [`check_totally_monotone_f64`] |
//!
//! Conventions, everywhere: ties go to the **leftmost** column (row minima) or the **topmost** row
//! (column minima); [`column_minima`] needs the **transpose** to be totally monotone
//! ([`Transpose`] adapts a matrix for the checker); every shape is accepted, including empty
//! matrices (a matrix without columns has no row minima: the result is empty); nothing panics
//! except allocation failure.
//!
//! # Exact orders, not `f64` sentinels
//!
//! The searches compare entries only through the order you give them, so entries can be any type.
//! This matters when a matrix mixes real values with sentinels that must stay ordered among
//! themselves: Amato's separation matrix holds distances, penalties `B + n_q - j` that must
//! decrease to the right, and `+∞`. In `f64`, `B + n_q - j` rounds to `B` once `B` is large; the
//! penalties tie, the matrix is no longer totally monotone, and SMAWK may return a wrong column. A
//! tagged entry compared exactly does not have the problem:
//!
//! ```
//! use core::cmp::Ordering;
//! use monotone_minima::{check_totally_monotone_by, from_fn, row_minima_by};
//!
//! #[derive(Clone, Copy, Debug)]
//! enum Entry {
//!     Dist(f64),
//!     Penalty(usize), // B + n_q - j, compared exactly
//!     Infinity,
//! }
//!
//! fn cmp(a: &Entry, b: &Entry) -> Ordering {
//!     use Entry::*;
//!     match (a, b) {
//!         (Dist(x), Dist(y)) => x.total_cmp(y), // distances are never NaN here
//!         (Penalty(x), Penalty(y)) => x.cmp(y),
//!         (Infinity, Infinity) => Ordering::Equal,
//!         (Dist(_), _) | (Penalty(_), Infinity) => Ordering::Less,
//!         _ => Ordering::Greater,
//!     }
//! }
//!
//! // Row i: penalties left of column i, distances in columns i..=i+1, infinity after.
//! let (p, q): ([f64; 3], [f64; 4]) = ([0.0, 1.0, 3.0], [0.5, 1.5, 2.0, 2.5]);
//! let n_q = q.len();
//! let m = from_fn(p.len(), n_q, |i, j| match j {
//!     j if j < i => Entry::Penalty(n_q - j),
//!     j if j <= i + 1 => Entry::Dist((p[i] - q[j]).abs()),
//!     _ => Entry::Infinity,
//! });
//! assert_eq!(check_totally_monotone_by(&m, cmp), Ok(()));
//! assert_eq!(row_minima_by(&m, cmp), [0, 1, 3]);
//! ```
//!
//! For plain `f64` matrices use the `_f64` functions: they compare in IEEE order and return a
//! [`NanError`] naming the row and column of a NaN entry instead of treating it as a minimum
//! (which is what `f64::total_cmp` would do with the negative NaN that `0.0 / 0.0` produces on
//! common hardware: it orders below `-∞`).
//!
//! # Online minima
//!
//! [`online_column_minima_by`] computes `f(j) = min_{i<j} entry(f, i, j)` where the entry may read
//! the already final `f(0..=i)`: concave one-dimensional dynamic programming (optimal line breaking
//! with squared slack, least-squares segmentation), in `O(n)` lookups amortized (Galil–Park).
//!
//! # `no_std`
//!
//! The crate is `#![no_std]` and needs only `alloc` (for the result and the scratch space); it has
//! no dependencies.
//!
//! # References
//!
//! - A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
//!   matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
//! - Z. Galil, K. Park, "A linear-time algorithm for concave one-dimensional dynamic programming",
//!   *Information Processing Letters* 33 (1990) 309–311.
//! - L. L. Larmore, B. Schieber, "On-line dynamic programming with applications to the prediction
//!   of RNA secondary structure", *Journal of Algorithms* 12 (1991) 490–515.
#![no_std]
#![forbid(unsafe_code)]

extern crate alloc;

mod engine;
mod error;
mod matrix;
mod online;
mod search;
mod testing;

pub use crate::error::{CheckError, NanError, NotTotallyMonotone};
pub use crate::matrix::{FromFn, Matrix, Transpose, from_fn};
pub use crate::online::{
    OnlineMinima, online_column_minima, online_column_minima_by, online_column_minima_f64,
};
pub use crate::search::{
    column_minima, column_minima_by, column_minima_f64, row_minima, row_minima_by, row_minima_f64,
};
pub use crate::testing::{
    brute_force_row_minima, brute_force_row_minima_by, brute_force_row_minima_f64,
    check_totally_monotone, check_totally_monotone_by, check_totally_monotone_f64,
};
