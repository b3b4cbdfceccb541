//! Error types.

use core::fmt;

/// A NaN entry found by one of the `f64` functions, with its position.
///
/// The position is always in the coordinates of the matrix the caller passed in (for
/// [`column_minima_f64`](crate::column_minima_f64) too, which searches the transpose internally).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NanError {
    row: usize,
    column: usize,
}

impl NanError {
    pub(crate) const fn new(row: usize, column: usize) -> Self {
        Self { row, column }
    }

    /// The row of the NaN entry.
    #[must_use]
    pub const fn row(&self) -> usize {
        self.row
    }

    /// The column of the NaN entry.
    #[must_use]
    pub const fn column(&self) -> usize {
        self.column
    }
}

impl fmt::Display for NanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "NaN matrix entry at row {}, column {}",
            self.row, self.column
        )
    }
}

impl core::error::Error for NanError {}

/// A witness that a matrix is not totally monotone: a 2×2 submatrix whose row minima move left.
///
/// With rows `i < i'` and columns `j < j'` (see [`rows`](Self::rows) and
/// [`columns`](Self::columns)), the witness satisfies `M[i][j'] < M[i][j]` (row `i` strictly
/// prefers the right column) and `M[i'][j] <= M[i'][j']` (row `i'`'s leftmost minimum is the left
/// column). The checker always reports adjacent rows, `i' = i + 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NotTotallyMonotone {
    rows: (usize, usize),
    columns: (usize, usize),
}

impl NotTotallyMonotone {
    pub(crate) const fn new(rows: (usize, usize), columns: (usize, usize)) -> Self {
        Self { rows, columns }
    }

    /// The two rows `(i, i')` of the violating submatrix, `i < i'`.
    #[must_use]
    pub const fn rows(&self) -> (usize, usize) {
        self.rows
    }

    /// The two columns `(j, j')` of the violating submatrix, `j < j'`.
    #[must_use]
    pub const fn columns(&self) -> (usize, usize) {
        self.columns
    }
}

impl fmt::Display for NotTotallyMonotone {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ((i, i2), (j, j2)) = (self.rows, self.columns);
        write!(
            f,
            "matrix is not totally monotone: row {i} prefers column {j2} to column {j}, \
             but row {i2} does not"
        )
    }
}

impl core::error::Error for NotTotallyMonotone {}

/// Why [`check_totally_monotone_f64`](crate::check_totally_monotone_f64) rejected a matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CheckError {
    /// The matrix has a NaN entry (the first one in row-major order).
    Nan(NanError),
    /// The matrix has no NaN but is not totally monotone.
    NotTotallyMonotone(NotTotallyMonotone),
}

impl fmt::Display for CheckError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Nan(e) => e.fmt(f),
            Self::NotTotallyMonotone(e) => e.fmt(f),
        }
    }
}

/// The message is the inner error's, so [`source`](core::error::Error::source) is `None`.
impl core::error::Error for CheckError {}

impl From<NanError> for CheckError {
    fn from(e: NanError) -> Self {
        Self::Nan(e)
    }
}

impl From<NotTotallyMonotone> for CheckError {
    fn from(e: NotTotallyMonotone) -> Self {
        Self::NotTotallyMonotone(e)
    }
}
