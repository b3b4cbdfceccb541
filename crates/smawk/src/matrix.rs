//! The implicit matrix abstraction: a size and an entry lookup, never materialised.

/// A matrix whose entries are computed on demand.
///
/// The searches in this crate only ever ask for a matrix's size and for single entries, so a matrix
/// does not need to be stored: [`from_fn`] turns a closure into a matrix, and any type can implement
/// the trait directly. Entries are returned by value; the searches never ask for an entry outside
/// `0..rows()` × `0..columns()`.
///
/// Implementations must be consistent: the same `(row, column)` must give the same entry during a
/// search, and `rows()` and `columns()` must not change. (An inconsistent matrix gives meaningless
/// results but no panic and no undefined behaviour.)
///
/// # Examples
///
/// ```
/// use monotone_minima::{Matrix, row_minima};
///
/// /// `(x_i - y_j)²` for sorted `x` and `y`: a Monge matrix, hence totally monotone.
/// struct SquaredGaps<'a> {
///     x: &'a [i64],
///     y: &'a [i64],
/// }
///
/// impl Matrix for SquaredGaps<'_> {
///     type Entry = i64;
///     fn rows(&self) -> usize {
///         self.x.len()
///     }
///     fn columns(&self) -> usize {
///         self.y.len()
///     }
///     fn entry(&self, row: usize, column: usize) -> i64 {
///         (self.x[row] - self.y[column]).pow(2)
///     }
/// }
///
/// let m = SquaredGaps { x: &[0, 4, 9], y: &[1, 3, 5, 10] };
/// assert_eq!(row_minima(&m), [0, 1, 3]);
/// ```
pub trait Matrix {
    /// The type of the entries.
    type Entry;

    /// The number of rows.
    fn rows(&self) -> usize;

    /// The number of columns.
    fn columns(&self) -> usize;

    /// The entry at `row` and `column`, for `row < self.rows()` and `column < self.columns()`.
    fn entry(&self, row: usize, column: usize) -> Self::Entry;
}

impl<M: Matrix + ?Sized> Matrix for &M {
    type Entry = M::Entry;

    #[inline]
    fn rows(&self) -> usize {
        (**self).rows()
    }

    #[inline]
    fn columns(&self) -> usize {
        (**self).columns()
    }

    #[inline]
    fn entry(&self, row: usize, column: usize) -> M::Entry {
        (**self).entry(row, column)
    }
}

/// A dense matrix stored row by row; rows cannot be ragged. Mostly for examples and tests.
impl<T: Clone, const C: usize> Matrix for [[T; C]] {
    type Entry = T;

    #[inline]
    fn rows(&self) -> usize {
        self.len()
    }

    #[inline]
    fn columns(&self) -> usize {
        C
    }

    #[inline]
    fn entry(&self, row: usize, column: usize) -> T {
        self[row][column].clone()
    }
}

/// A dense matrix stored row by row. Mostly for examples and tests.
impl<T: Clone, const R: usize, const C: usize> Matrix for [[T; C]; R] {
    type Entry = T;

    #[inline]
    fn rows(&self) -> usize {
        R
    }

    #[inline]
    fn columns(&self) -> usize {
        C
    }

    #[inline]
    fn entry(&self, row: usize, column: usize) -> T {
        self[row][column].clone()
    }
}

/// An implicit `rows` × `columns` matrix whose entry `(i, j)` is `f(i, j)`; see [`from_fn`].
#[derive(Clone, Copy, Debug)]
pub struct FromFn<F> {
    rows: usize,
    columns: usize,
    f: F,
}

/// The implicit `rows` × `columns` matrix whose entry `(i, j)` is `f(i, j)`.
///
/// Nothing is stored and nothing is computed up front: the searches call `f` only for the entries
/// they look at. `f` is only called with `i < rows` and `j < columns`.
///
/// # Examples
///
/// ```
/// use monotone_minima::{from_fn, row_minima};
///
/// let x = [1, 5, 6];
/// let y = [0, 2, 5, 7];
/// let m = from_fn(x.len(), y.len(), |i, j| (x[i] - y[j]) * (x[i] - y[j]));
/// assert_eq!(row_minima(&m), [0, 2, 2]);
/// ```
pub fn from_fn<T, F: Fn(usize, usize) -> T>(rows: usize, columns: usize, f: F) -> FromFn<F> {
    FromFn { rows, columns, f }
}

impl<T, F: Fn(usize, usize) -> T> Matrix for FromFn<F> {
    type Entry = T;

    #[inline]
    fn rows(&self) -> usize {
        self.rows
    }

    #[inline]
    fn columns(&self) -> usize {
        self.columns
    }

    #[inline]
    fn entry(&self, row: usize, column: usize) -> T {
        (self.f)(row, column)
    }
}

/// The transpose of a matrix, computed on demand: entry `(i, j)` is the inner matrix's `(j, i)`.
///
/// Useful with the testing helpers: the column minima of `M` are the row minima of
/// `Transpose(&M)`, and [`column_minima`](crate::column_minima) requires
/// [`check_totally_monotone`](crate::check_totally_monotone)`(&Transpose(&m))` to pass.
///
/// # Examples
///
/// ```
/// use monotone_minima::{Matrix, Transpose};
///
/// let m = [[1, 2, 3], [4, 5, 6]];
/// let t = Transpose(&m);
/// assert_eq!((t.rows(), t.columns()), (3, 2));
/// assert_eq!(t.entry(2, 1), 6);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Transpose<M>(pub M);

impl<M: Matrix> Matrix for Transpose<M> {
    type Entry = M::Entry;

    #[inline]
    fn rows(&self) -> usize {
        self.0.columns()
    }

    #[inline]
    fn columns(&self) -> usize {
        self.0.rows()
    }

    #[inline]
    fn entry(&self, row: usize, column: usize) -> M::Entry {
        self.0.entry(column, row)
    }
}
