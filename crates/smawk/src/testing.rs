//! Testing helpers: a brute-force twin of the row-minima search and an exact checker of total
//! monotonicity.

use alloc::vec;
use alloc::vec::Vec;
use core::cmp::Ordering;
use core::convert::Infallible;

use crate::search::{check_nan, infallible};
use crate::{CheckError, Matrix, NanError, NotTotallyMonotone};

/// Row minima by looking at every entry, in row-major order; empty if either size is zero.
fn brute_force<T, E>(
    rows: usize,
    columns: usize,
    lookup: &mut impl FnMut(usize, usize) -> Result<T, E>,
    less: &mut impl FnMut(&T, &T) -> bool,
) -> Result<Vec<usize>, E> {
    if columns == 0 {
        return Ok(Vec::new());
    }
    let mut argmin = Vec::with_capacity(rows);
    for row in 0..rows {
        let mut best = lookup(row, 0)?;
        let mut best_column = 0;
        for column in 1..columns {
            let value = lookup(row, column)?;
            if less(&value, &best) {
                best = value;
                best_column = column;
            }
        }
        argmin.push(best_column);
    }
    Ok(argmin)
}

/// For testing: the column of the leftmost minimum of each row under `cmp`, by looking at every
/// entry.
///
/// The brute-force twin of [`row_minima_by`](crate::row_minima_by): same result (leftmost on
/// ties; empty if the matrix has no rows or no columns) for every matrix, totally monotone or not,
/// and the two agree exactly whenever the matrix is totally monotone. Column minima:
/// `brute_force_row_minima_by(&Transpose(&m), cmp)`.
///
/// # Panics
///
/// Never, except for allocation failure; panics in `cmp` or in the matrix propagate.
///
/// # Complexity
///
/// Exactly `rows * columns` entry lookups (none if either is zero), `O(rows * columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::brute_force_row_minima_by;
///
/// let m = [[3.0, 1.0, 1.0], [2.0, 5.0, 0.5]];
/// assert_eq!(brute_force_row_minima_by(&m, f64::total_cmp), [1, 2]);
/// ```
pub fn brute_force_row_minima_by<M, C>(matrix: &M, mut cmp: C) -> Vec<usize>
where
    M: Matrix + ?Sized,
    C: FnMut(&M::Entry, &M::Entry) -> Ordering,
{
    infallible(brute_force(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| Ok(matrix.entry(i, j)),
        &mut |a, b| cmp(a, b) == Ordering::Less,
    ))
}

/// For testing: the column of the leftmost minimum of each row of a matrix of [`Ord`] entries, by
/// looking at every entry.
///
/// The brute-force twin of [`row_minima`](crate::row_minima); see
/// [`brute_force_row_minima_by`].
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// Exactly `rows * columns` entry lookups, `O(rows * columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::brute_force_row_minima;
///
/// assert_eq!(brute_force_row_minima(&[[3, 1, 1], [2, 5, 0]]), [1, 2]);
/// ```
pub fn brute_force_row_minima<M>(matrix: &M) -> Vec<usize>
where
    M: Matrix + ?Sized,
    M::Entry: Ord,
{
    infallible(brute_force(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| Ok(matrix.entry(i, j)),
        &mut |a, b| a < b,
    ))
}

/// For testing: the column of the leftmost minimum of each row of an `f64` matrix, by looking at
/// every entry; a NaN entry is an error.
///
/// The brute-force twin of [`row_minima_f64`](crate::row_minima_f64) (IEEE order,
/// `-0.0 == 0.0`); see [`brute_force_row_minima_by`].
///
/// # Errors
///
/// [`NanError`] for the first NaN entry in row-major order: unlike the fast search, this checks
/// every entry.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// At most `rows * columns` entry lookups (it stops at the first NaN), `O(rows * columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::{brute_force_row_minima_f64, from_fn};
///
/// let m = from_fn(2, 3, |i, j| (i as f64 - j as f64).abs());
/// assert_eq!(brute_force_row_minima_f64(&m), Ok(vec![0, 1]));
/// let nan = from_fn(2, 3, |i, j| if i + j == 2 { f64::NAN } else { 0.0 });
/// assert_eq!(brute_force_row_minima_f64(&nan).map_err(|e| (e.row(), e.column())), Err((0, 2)));
/// ```
pub fn brute_force_row_minima_f64<M>(matrix: &M) -> Result<Vec<usize>, NanError>
where
    M: Matrix<Entry = f64> + ?Sized,
{
    brute_force(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| check_nan(matrix.entry(i, j), i, j),
        &mut |a, b| a < b,
    )
}

/// For testing: whether a matrix is totally monotone under `cmp` (row minima moving right),
/// exactly, with a witness if it is not.
///
/// The definition: for all rows `i < i'` and columns `j < j'`, `M[i][j'] < M[i][j]` implies
/// `M[i'][j'] < M[i'][j]`; equivalently, the leftmost row minima of every submatrix move right
/// from top to bottom. This is exactly what [`row_minima_by`](crate::row_minima_by) needs. For
/// [`column_minima_by`](crate::column_minima_by), check the transpose:
/// `check_totally_monotone_by(&Transpose(&m), cmp)`.
///
/// What is checked, and why it is exact. For a fixed pair of columns the condition says that the
/// set of rows preferring `j'` to `j` is closed downwards, so it is enough to check **adjacent
/// rows** `i' = i + 1`. It is not enough to check adjacent columns (unlike the Monge property): in
/// `[[1, 2, 0], [0, 3, 1]]` every adjacent 2×2 submatrix is fine, but columns 0 and 2 are not.
/// So for each pair of adjacent rows `a = M[i]`, `b = M[i + 1]` the checker looks for columns
/// `j < j'` with `a[j'] < a[j]` and `b[j] <= b[j']`: a sweep over `j'` with a Fenwick tree,
/// indexed by the rank of `b[j]`, holding the largest `a[j]` so far. Ties are handled exactly.
///
/// `cmp` must be a total order (a total preorder) on the entries; otherwise the answer is
/// meaningless (but there is no panic).
///
/// # Errors
///
/// [`NotTotallyMonotone`], a violating 2×2 submatrix (on adjacent rows), if the matrix is not
/// totally monotone. Matrices with fewer than two rows or columns are always totally monotone.
///
/// # Panics
///
/// Never, except for allocation failure; panics in `cmp` or in the matrix propagate.
///
/// # Complexity
///
/// `rows * columns` entry lookups (each entry once), `O(rows * columns * log columns)`
/// comparisons and time, `O(columns)` memory (two rows of entries and some indices). This is
/// a testing tool; it is not meant for the fast path.
///
/// # Examples
///
/// ```
/// use monotone_minima::check_totally_monotone_by;
///
/// let good = [[4.0, 2.0, 3.0], [5.0, 2.0, 1.0]];
/// assert_eq!(check_totally_monotone_by(&good, f64::total_cmp), Ok(()));
///
/// // Only a non-adjacent pair of columns (0 and 2) is violated.
/// let bad = [[1.0, 2.0, 0.0], [0.0, 3.0, 1.0]];
/// let witness = check_totally_monotone_by(&bad, f64::total_cmp).unwrap_err();
/// assert_eq!((witness.rows(), witness.columns()), ((0, 1), (0, 2)));
/// ```
pub fn check_totally_monotone_by<M, C>(matrix: &M, mut cmp: C) -> Result<(), NotTotallyMonotone>
where
    M: Matrix + ?Sized,
    C: FnMut(&M::Entry, &M::Entry) -> Ordering,
{
    infallible(check(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| Ok::<_, Infallible>(matrix.entry(i, j)),
        &mut cmp,
    ))
}

/// For testing: whether a matrix of [`Ord`] entries is totally monotone (row minima moving
/// right), exactly, with a witness if it is not.
///
/// [`check_totally_monotone_by`] with `Ord::cmp`; see there for what is checked.
///
/// # Errors
///
/// [`NotTotallyMonotone`], a violating 2×2 submatrix (on adjacent rows).
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// `rows * columns` entry lookups, `O(rows * columns * log columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::check_totally_monotone;
///
/// assert_eq!(check_totally_monotone(&[[2, 1], [3, 1]]), Ok(()));
/// assert!(check_totally_monotone(&[[2, 1], [1, 1]]).is_err());
/// ```
pub fn check_totally_monotone<M>(matrix: &M) -> Result<(), NotTotallyMonotone>
where
    M: Matrix + ?Sized,
    M::Entry: Ord,
{
    check_totally_monotone_by(matrix, Ord::cmp)
}

/// For testing: whether an `f64` matrix has no NaN and is totally monotone in the IEEE order (row
/// minima moving right), exactly, with a witness if it is not.
///
/// [`check_totally_monotone_by`] with the IEEE order (`-0.0 == 0.0`), which is what
/// [`row_minima_f64`](crate::row_minima_f64) uses, after a first pass that looks for NaN.
///
/// # Errors
///
/// [`CheckError::Nan`] for the first NaN in row-major order, else
/// [`CheckError::NotTotallyMonotone`] with a violating 2×2 submatrix.
///
/// # Panics
///
/// Never, except for allocation failure; panics in the matrix propagate.
///
/// # Complexity
///
/// `2 * rows * columns` entry lookups (the NaN pass, then the check),
/// `O(rows * columns * log columns)` time.
///
/// # Examples
///
/// ```
/// use monotone_minima::{check_totally_monotone_f64, from_fn, CheckError};
///
/// // Distances between sorted points on two lines: Monge, hence totally monotone.
/// let m = from_fn(4, 5, |i, j| f64::hypot(i as f64 - 1.3 * j as f64, 2.0));
/// assert_eq!(check_totally_monotone_f64(&m), Ok(()));
///
/// let nan = from_fn(4, 5, |i, j| if (i, j) == (3, 1) { f64::NAN } else { 0.0 });
/// assert!(matches!(check_totally_monotone_f64(&nan), Err(CheckError::Nan(_))));
/// ```
pub fn check_totally_monotone_f64<M>(matrix: &M) -> Result<(), CheckError>
where
    M: Matrix<Entry = f64> + ?Sized,
{
    for i in 0..matrix.rows() {
        for j in 0..matrix.columns() {
            check_nan(matrix.entry(i, j), i, j)?;
        }
    }
    check(
        matrix.rows(),
        matrix.columns(),
        &mut |i, j| check_nan(matrix.entry(i, j), i, j),
        &mut |a: &f64, b: &f64| {
            if a < b {
                Ordering::Less
            } else if a > b {
                Ordering::Greater
            } else {
                Ordering::Equal
            }
        },
    )?
    .map_err(CheckError::from)
}

/// No column: the Fenwick tree slot is empty.
const NONE: usize = usize::MAX;

/// The exact check; the outer `Result` carries lookup errors, the inner one the verdict.
fn check<T, E>(
    rows: usize,
    columns: usize,
    lookup: &mut impl FnMut(usize, usize) -> Result<T, E>,
    cmp: &mut impl FnMut(&T, &T) -> Ordering,
) -> Result<Result<(), NotTotallyMonotone>, E> {
    if rows < 2 || columns < 2 {
        return Ok(Ok(()));
    }
    let mut upper = Vec::with_capacity(columns);
    let mut lower = Vec::with_capacity(columns);
    for j in 0..columns {
        upper.push(lookup(0, j)?);
    }
    let mut order: Vec<usize> = Vec::with_capacity(columns);
    let mut scratch = vec![0; columns];
    let mut rank = vec![0; columns];
    // tree[p], 1-based: the column with the largest `upper` entry among the columns inserted so
    // far whose rank lies in (p - lowbit(p), p].
    let mut tree = vec![NONE; columns + 1];
    for i in 1..rows {
        lower.clear();
        for j in 0..columns {
            lower.push(lookup(i, j)?);
        }
        // Dense ranks of the lower row, 1-based: equal entries share a rank.
        order.clear();
        order.extend(0..columns);
        merge_sort_by(&mut order, &mut scratch, &mut |&x, &y| {
            cmp(&lower[x], &lower[y])
        });
        let mut r = 1;
        for k in 0..columns {
            if k > 0 && cmp(&lower[order[k - 1]], &lower[order[k]]) == Ordering::Less {
                r += 1;
            }
            rank[order[k]] = r;
        }
        tree.fill(NONE);
        for right in 0..columns {
            // The column j < right with lower[j] <= lower[right] and the largest upper[j].
            let mut best = NONE;
            let mut p = rank[right];
            while p > 0 {
                let c = tree[p];
                if c != NONE && (best == NONE || cmp(&upper[c], &upper[best]) == Ordering::Greater)
                {
                    best = c;
                }
                p &= p - 1;
            }
            if best != NONE && cmp(&upper[right], &upper[best]) == Ordering::Less {
                return Ok(Err(NotTotallyMonotone::new((i - 1, i), (best, right))));
            }
            let mut p = rank[right];
            while p <= columns {
                if tree[p] == NONE || cmp(&upper[right], &upper[tree[p]]) == Ordering::Greater {
                    tree[p] = right;
                }
                p += p & p.wrapping_neg();
            }
        }
        core::mem::swap(&mut upper, &mut lower);
    }
    Ok(Ok(()))
}

/// Stable bottom-up merge sort of `v` by `cmp`, with `scratch.len() >= v.len()`.
///
/// Written out instead of `slice::sort_by` because the standard sorts may panic when the order is
/// not total, and the checker promises not to.
fn merge_sort_by(
    v: &mut [usize],
    scratch: &mut [usize],
    cmp: &mut impl FnMut(&usize, &usize) -> Ordering,
) {
    let n = v.len();
    let scratch = &mut scratch[..n];
    let mut width = 1;
    while width < n {
        let mut start = 0;
        while start < n {
            let mid = n.min(start + width);
            let end = n.min(mid + width);
            let (mut a, mut b) = (start, mid);
            for slot in &mut scratch[start..end] {
                // Take from the left run unless the right one is strictly smaller: stable.
                let take_left = b >= end || (a < mid && cmp(&v[b], &v[a]) != Ordering::Less);
                if take_left {
                    *slot = v[a];
                    a += 1;
                } else {
                    *slot = v[b];
                    b += 1;
                }
            }
            start = end;
        }
        v.copy_from_slice(scratch);
        width *= 2;
    }
}
