//! Offline row and column minima (SMAWK).

use alloc::vec;
use alloc::vec::Vec;
use core::cmp::Ordering;
use core::convert::Infallible;

use crate::engine::{self, Clean, Nan, Poison, Workspace};
use crate::{Matrix, NanError};

/// Row minima of a `rows` × `columns` lookup, leftmost on ties; empty if either size is zero.
/// Also returns whether a poisoned entry was looked up.
fn run<T, P: Poison<T>>(
    rows: usize,
    columns: usize,
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
) -> (Vec<usize>, bool) {
    if rows == 0 || columns == 0 {
        return (Vec::new(), false);
    }
    let mut argmin = vec![0; rows];
    let poisoned = engine::smawk_into::<_, P, false>(
        rows,
        columns,
        lookup,
        less,
        &mut argmin,
        &mut |_, _| {},
        &mut Workspace::new(),
    );
    (argmin, poisoned)
}

/// Unwraps a result that cannot be an error.
pub(crate) fn infallible<T>(result: Result<T, Infallible>) -> T {
    match result {
        Ok(value) => value,
        Err(never) => match never {},
    }
}

/// The entry as a `Result`, an error if it is NaN.
#[inline(always)]
pub(crate) fn check_nan(value: f64, row: usize, column: usize) -> Result<f64, NanError> {
    if value.is_nan() {
        Err(NanError::new(row, column))
    } else {
        Ok(value)
    }
}

/// Row minima of an `f64` lookup in the IEEE order, NaN being an error: `entry(i, j)` is the
/// searched matrix, `position(i, j)` the caller's coordinates of that entry.
///
/// The search runs with a branch-free NaN flag. If the flag is set it runs again, recording the
/// first NaN it looks up (the same one, the search being deterministic). Minima forced by their
/// neighbours were never looked at, so the last pass checks every returned minimum.
fn run_f64(
    rows: usize,
    columns: usize,
    entry: impl Fn(usize, usize) -> f64,
    position: impl Fn(usize, usize) -> (usize, usize),
) -> Result<Vec<usize>, NanError> {
    let nan = |(i, j)| {
        let (row, column) = position(i, j);
        NanError::new(row, column)
    };
    let (mut minima, poisoned) =
        run::<f64, Nan>(rows, columns, &mut |i, j| entry(i, j), &mut |a, b| a < b);
    if poisoned {
        let mut first = None;
        let (again, _) = run::<f64, Clean>(
            rows,
            columns,
            &mut |i, j| {
                let value = entry(i, j);
                if value.is_nan() && first.is_none() {
                    first = Some((i, j));
                }
                value
            },
            &mut |a, b| a < b,
        );
        if let Some(at) = first {
            return Err(nan(at));
        }
        // Only an inconsistent matrix gets here; keep the run that met no NaN.
        minima = again;
    }
    // A branch-free pass first (it vectorises), the position only if needed.
    if !minima
        .iter()
        .enumerate()
        .fold(false, |any, (i, &j)| any | entry(i, j).is_nan())
    {
        return Ok(minima);
    }
    match minima
        .iter()
        .enumerate()
        .find(|&(i, &j)| entry(i, j).is_nan())
    {
        Some((i, &j)) => Err(nan((i, j))),
        // Only an inconsistent matrix gets here.
        None => Ok(minima),
    }
}

/// The column of the leftmost minimum of each row of a totally monotone matrix, under the order
/// `cmp`.
///
/// The matrix must be *totally monotone* under `cmp`: in every 2×2 submatrix (rows `i < i'`,
/// columns `j < j'`), if row `i` strictly prefers column `j'` (`M[i][j'] < M[i][j]`) then so does
/// row `i'` (`M[i'][j'] < M[i'][j]`). Equivalently, in every submatrix the leftmost row minima
/// move right (weakly) from top to bottom. Monge matrices (`M[i][j] + M[i'][j'] <= M[i][j'] +
/// M[i'][j]`) are totally monotone. `cmp` must be a total order (a total preorder: ties allowed)
/// on the entries that are compared.
///
/// Returns one column index per row: entry `i` is the **leftmost** column holding the minimum of
/// row `i`. If the matrix has no columns, no row has a minimum and the result is empty (for any
/// number of rows); a matrix with no rows gives an empty result too.
///
/// If the matrix is not totally monotone the result is unspecified (but still one valid column
/// index per row); use [`check_totally_monotone_by`](crate::check_totally_monotone_by) in tests.
///
/// # Panics
///
/// Never, for any shape, except for allocation failure (the result and the scratch space take
/// at most `5 * rows` machine words, plus `rows` entries). Panics in `cmp` or in the matrix
/// propagate.
///
/// # Complexity
///
/// At most `3 * columns + 12 * rows` entry lookups, for any matrix and shape, and
/// `O(rows + columns)` time and comparisons. Measured on square matrices: 2.4 to 3.2 lookups per
/// row and column (`tests/complexity.rs`); far fewer when there are many more rows than columns,
/// because a row whose minimum is forced by its neighbours' is not looked at. Matrices with at
/// most 64 entries are scanned directly. Allocations: the result, and scratch space of at most
/// `4 * rows` indices and `rows` entries.
///
/// # Examples
///
/// Entries that need an exact order beyond `f64`: in Amato's separation matrix a row is
/// distances, then penalties `B + n - j` that must decrease to the right, then `+∞`. In `f64`,
/// `B + n - j` rounds to `B` once `B` is large, the penalties tie, and the matrix stops being
/// totally monotone. A tagged entry compared exactly keeps every penalty distinct:
///
/// ```
/// use core::cmp::Ordering;
/// use monotone_minima::{
///     check_totally_monotone_by, check_totally_monotone_f64, from_fn, row_minima_by, Matrix,
/// };
///
/// #[derive(Clone, Copy, Debug)]
/// enum Entry {
///     Dist(f64),
///     Penalty(usize), // stands for B + n - j: smaller to the right
///     Infinity,
/// }
///
/// fn cmp(a: &Entry, b: &Entry) -> Ordering {
///     use Entry::*;
///     match (a, b) {
///         (Dist(x), Dist(y)) => x.total_cmp(y), // never NaN here
///         (Penalty(x), Penalty(y)) => x.cmp(y),
///         (Infinity, Infinity) => Ordering::Equal,
///         (Dist(_), _) | (Penalty(_), Infinity) => Ordering::Less,
///         _ => Ordering::Greater,
///     }
/// }
///
/// // Row i: penalties before column i, distances |x_i - y_j| up to column i + 2, then infinity.
/// let (x, y): ([f64; 4], [f64; 6]) = ([0.5, 2.5, 3.0, 7.0], [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
/// let n = y.len();
/// let m = from_fn(x.len(), n, |i, j| {
///     if j < i {
///         Entry::Penalty(n - j)
///     } else if j <= i + 2 {
///         Entry::Dist((x[i] - y[j]).abs())
///     } else {
///         Entry::Infinity
///     }
/// });
/// assert_eq!(check_totally_monotone_by(&m, cmp), Ok(()));
/// assert_eq!(row_minima_by(&m, cmp), [0, 2, 3, 5]);
///
/// // The same matrix in f64, with B = 1e300: every penalty collapses to B.
/// let collapsed = from_fn(x.len(), n, |i, j| match m.entry(i, j) {
///     Entry::Dist(d) => d,
///     Entry::Penalty(p) => 1e300 + p as f64,
///     Entry::Infinity => f64::INFINITY,
/// });
/// assert!(check_totally_monotone_f64(&collapsed).is_err());
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn row_minima_by<M, C>(matrix: &M, mut cmp: C) -> Vec<usize>
where
    M: Matrix + ?Sized,
    C: FnMut(&M::Entry, &M::Entry) -> Ordering,
{
    run::<_, Clean>(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| matrix.entry(i, j),
        &mut |a, b| cmp(a, b) == Ordering::Less,
    )
    .0
}

/// The column of the leftmost minimum of each row of a totally monotone matrix of [`Ord`]
/// entries.
///
/// [`row_minima_by`] with `Ord::cmp`; see there for the requirements, the result (leftmost on
/// ties; empty if there are no columns) and the complexity.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// At most `3 * columns + 12 * rows` entry lookups and `O(rows + columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::row_minima;
///
/// // Row minima move right; row 1 has a tie between columns 1 and 2 and gets the leftmost.
/// let m = [
///     [3, 4, 6, 9],
///     [5, 2, 2, 4],
///     [8, 6, 3, 1],
/// ];
/// assert_eq!(row_minima(&m), [0, 1, 3]);
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn row_minima<M>(matrix: &M) -> Vec<usize>
where
    M: Matrix + ?Sized,
    M::Entry: Ord,
{
    run::<_, Clean>(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| matrix.entry(i, j),
        &mut |a, b| a < b,
    )
    .0
}

/// The column of the leftmost minimum of each row of a totally monotone `f64` matrix; a NaN
/// entry is an error.
///
/// [`row_minima_by`] with the IEEE order (`-0.0 == 0.0`; infinities allowed); see there for the
/// requirements, the result and the complexity.
///
/// # Errors
///
/// [`NanError`] with the row and column of the first NaN entry the search looks up. The search
/// looks up only `O(rows + columns)` entries, so a NaN elsewhere goes unnoticed, but every
/// returned minimum has been looked up: `Ok` guarantees that no returned minimum is NaN.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// At most `3 * columns + 13 * rows` entry lookups and `O(rows + columns)` time: the search (at
/// most `3 * columns + 12 * rows`), then one lookup per row to check the returned minimum, since
/// a minimum forced by the neighbouring rows' is not looked at during the search. NaN checks
/// are branch-free flags in the search; if the search meets a NaN, it runs a second time to
/// locate the first one.
///
/// # Examples
///
/// ```
/// use monotone_minima::{from_fn, row_minima_f64};
///
/// // Distances between sorted points on two lines: a Monge matrix.
/// let x = [0.0, 1.5, 4.0];
/// let y = [0.0, 1.0, 2.0, 3.0, 4.0];
/// let m = from_fn(3, 5, |i, j| f64::hypot(x[i] - y[j], 1.0));
/// assert_eq!(row_minima_f64(&m), Ok(vec![0, 1, 4]));
///
/// let nan = from_fn(3, 5, |i, j| if (i, j) == (1, 2) { f64::NAN } else { 1.0 });
/// let err = row_minima_f64(&nan).unwrap_err();
/// assert_eq!((err.row(), err.column()), (1, 2));
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn row_minima_f64<M>(matrix: &M) -> Result<Vec<usize>, NanError>
where
    M: Matrix<Entry = f64> + ?Sized,
{
    run_f64(
        matrix.rows(),
        matrix.columns(),
        |i, j| matrix.entry(i, j),
        |i, j| (i, j),
    )
}

/// The row of the topmost minimum of each column, for a matrix whose **transpose** is totally
/// monotone under the order `cmp`.
///
/// This is [`row_minima_by`] applied to the transpose: the requirement is that in every 2×2
/// submatrix (rows `i < i'`, columns `j < j'`), if column `j` strictly prefers row `i'`
/// (`M[i'][j] < M[i][j]`) then so does column `j'` (`M[i'][j'] < M[i][j']`); the column minima then
/// move down from left to right. Monge matrices satisfy this as well as row total monotonicity.
///
/// Total monotonicity by rows is **not** enough: `[[2, 3], [1, 5]]` is totally monotone (its row
/// minima are both in column 0), yet its column minima move up (row 1 for column 0, row 0 for
/// column 1). Check with
/// [`check_totally_monotone_by`](crate::check_totally_monotone_by)`(&`[`Transpose`](crate::Transpose)`(&m), cmp)`.
///
/// Returns one row index per column (the topmost on ties); empty if the matrix has no rows or no
/// columns.
///
/// # Panics
///
/// Never, except for allocation failure; panics in `cmp` or in the matrix propagate.
///
/// # Complexity
///
/// At most `3 * rows + 12 * columns` entry lookups and `O(rows + columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::{check_totally_monotone, column_minima, row_minima, Transpose};
///
/// let m = [[2, 3], [1, 5]];
/// assert_eq!(check_totally_monotone(&m), Ok(()));
/// assert_eq!(row_minima(&m), [0, 0]);
/// // Not a valid input for column_minima: the column minima move up.
/// assert!(check_totally_monotone(&Transpose(&m)).is_err());
///
/// let m = [[2, 3, 9], [1, 2, 4], [3, 2, 1]];
/// assert_eq!(check_totally_monotone(&Transpose(&m)), Ok(()));
/// assert_eq!(monotone_minima::column_minima_by(&m, |a: &i32, b: &i32| a.cmp(b)), [1, 1, 2]);
/// assert_eq!(column_minima(&m), [1, 1, 2]);
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn column_minima_by<M, C>(matrix: &M, mut cmp: C) -> Vec<usize>
where
    M: Matrix + ?Sized,
    C: FnMut(&M::Entry, &M::Entry) -> Ordering,
{
    run::<_, Clean>(
        matrix.columns(),
        matrix.rows(),
        &mut |j, i| matrix.entry(i, j),
        &mut |a, b| cmp(a, b) == Ordering::Less,
    )
    .0
}

/// The row of the topmost minimum of each column, for a matrix of [`Ord`] entries whose
/// transpose is totally monotone.
///
/// [`column_minima_by`] with `Ord::cmp`; see there for the requirement (by columns, not by rows)
/// and the result.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// At most `3 * rows + 12 * columns` entry lookups and `O(rows + columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::column_minima;
///
/// let m = [
///     [3, 1, 4, 6],
///     [5, 2, 2, 5],
///     [7, 4, 3, 1],
/// ];
/// assert_eq!(column_minima(&m), [0, 0, 1, 2]);
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn column_minima<M>(matrix: &M) -> Vec<usize>
where
    M: Matrix + ?Sized,
    M::Entry: Ord,
{
    run::<_, Clean>(
        matrix.columns(),
        matrix.rows(),
        &mut |j, i| matrix.entry(i, j),
        &mut |a, b| a < b,
    )
    .0
}

/// The row of the topmost minimum of each column of an `f64` matrix whose transpose is totally
/// monotone; a NaN entry is an error.
///
/// [`column_minima_by`] with the IEEE order; see there for the requirement (by columns, not by
/// rows) and the result.
///
/// # Errors
///
/// [`NanError`] with the row and column (of `matrix`, not of its transpose) of the first NaN entry
/// the search looks up; entries the search never looks at are not checked, but every returned
/// minimum is.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// At most `3 * rows + 13 * columns` entry lookups and `O(rows + columns)` time: the search, then
/// a check of every returned minimum, as in [`row_minima_f64`].
///
/// # Examples
///
/// ```
/// use monotone_minima::{column_minima_f64, from_fn};
///
/// let m = from_fn(4, 2, |i, j| (i as f64 - 2.0 * j as f64).powi(2));
/// assert_eq!(column_minima_f64(&m), Ok(vec![0, 2]));
/// ```
///
/// # References
///
/// A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
/// matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208.
pub fn column_minima_f64<M>(matrix: &M) -> Result<Vec<usize>, NanError>
where
    M: Matrix<Entry = f64> + ?Sized,
{
    run_f64(
        matrix.columns(),
        matrix.rows(),
        |j, i| matrix.entry(i, j),
        |j, i| (i, j),
    )
}
