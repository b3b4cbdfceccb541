//! Online column minima of an upper-triangular totally monotone matrix, for dynamic programming
//! (Galil–Park, in the simplified form of D. Eppstein's PADS).

use alloc::vec::Vec;
use core::cmp::Ordering;

use crate::NanError;
use crate::engine::{self, Clean, Nan, Poison, Workspace};

/// The result of a search with nothing poisoned.
fn clean<T>(result: Result<OnlineMinima<T>, (usize, usize)>) -> OnlineMinima<T> {
    // `Clean` poisons nothing, so this is always `Ok`; the fallback keeps the code panic-free.
    result.unwrap_or_else(|_| OnlineMinima {
        values: Vec::new(),
        rows: Vec::new(),
    })
}

/// The result of the online column minima functions: the minimum of each column and the row that
/// attains it.
///
/// For `size` columns, both vectors have length `size`. Column 0 has no candidate rows: its value
/// is the `initial` value passed in and its row is 0 by convention.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct OnlineMinima<T> {
    /// `values[0]` is the initial value; `values[j]`, for `j >= 1`, is the minimum of column `j`,
    /// `min { entry(i, j) : i < j }`.
    pub values: Vec<T>,
    /// `rows[j]`, for `j >= 1`, is the topmost row `i < j` attaining `values[j]` (in dynamic
    /// programming, the predecessor of `j`); `rows[0] == 0`.
    pub rows: Vec<usize>,
}

/// Galil–Park / Eppstein. State, with `finished` the last final column:
///
/// - `values[..=finished]` are final and are what `entry` may read;
/// - `values[j]` for `finished < j <= tentative` (and possibly beyond) are tentative minima over
///   some of the rows `<= finished`: correct whenever the true minimum of column `j` comes from a
///   row below `base`, or when `j <= tentative` and it comes from a row `<= finished`;
/// - every step finishes one column, with one SMAWK call on the square block of rows
///   `base..=finished` and the next columns when the tentative ones are used up, else with at
///   most two lookups.
///
/// Amortisation: a block of `k` rows costs `O(k)` lookups and is paid either by the `k` columns it
/// makes tentative (if they all get finished without a reset) or by the `>= k - 1` increase of
/// `base` in the reset that discards it.
///
/// Stops at the first entry that `P` finds poisoned, returning its `(row, column)`.
fn online<T, P: Poison<T>>(
    size: usize,
    initial: T,
    entry: &mut impl FnMut(&[T], usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
) -> Result<OnlineMinima<T>, (usize, usize)> {
    let mut values = Vec::with_capacity(size);
    let mut rows = Vec::with_capacity(size);
    if size == 0 {
        return Ok(OnlineMinima { values, rows });
    }
    values.push(initial);
    rows.push(0);
    let (mut finished, mut base, mut tentative) = (0_usize, 0_usize, 0_usize);
    let mut ws = Workspace::new();
    let mut argmin: Vec<usize> = Vec::new();
    let mut slots: Vec<Option<T>> = Vec::new();
    while finished + 1 < size {
        let i = finished + 1;
        if i > tentative {
            // Case 1: no tentative column left. Search the square block of rows base..=finished
            // and the next columns (fewer at the end), as column minima: row minima of the
            // transpose, topmost row on ties.
            let block_rows = finished + 1 - base;
            tentative = (finished + block_rows).min(size - 1);
            let block_columns = tentative - finished;
            argmin.clear();
            argmin.resize(block_columns, 0);
            slots.clear();
            slots.resize_with(block_columns, || None);
            let done = &values[..=finished];
            let mut poisoned = None;
            engine::smawk_into::<_, Clean, true>(
                block_columns,
                block_rows,
                &mut |c, r| {
                    let (row, column) = (base + r, finished + 1 + c);
                    let value = entry(done, row, column);
                    if P::test(&value) && poisoned.is_none() {
                        poisoned = Some((row, column));
                    }
                    value
                },
                less,
                &mut argmin,
                &mut |c, value| slots[c] = Some(value),
                &mut ws,
            );
            if let Some(at) = poisoned {
                return Err(at);
            }
            for (c, (slot, &r)) in slots.iter_mut().zip(&argmin).enumerate() {
                // The engine fills every slot; `take` avoids requiring `T: Clone`.
                let Some(value) = slot.take() else { continue };
                let column = finished + 1 + c;
                if column < values.len() {
                    // An older tentative value, from rows above this block: keep it on ties.
                    if less(&value, &values[column]) {
                        values[column] = value;
                        rows[column] = base + r;
                    }
                } else {
                    values.push(value);
                    rows.push(base + r);
                }
            }
            finished = i;
            continue;
        }
        // Case 2: the new row i - 1 gives column i a new minimum. It then beats every older row
        // in every later column, so all tentative work is discarded and the base moves up.
        let diagonal = entry(&values[..=finished], i - 1, i);
        if P::test(&diagonal) {
            return Err((i - 1, i));
        }
        if less(&diagonal, &values[i]) {
            values[i] = diagonal;
            rows[i] = i - 1;
            base = i - 1;
            tentative = i;
            finished = i;
            continue;
        }
        // Case 3: row i - 1 does not beat the tentative minimum of the last tentative column, so
        // (total monotonicity) it beats none before it either: column i is final.
        if tentative == i || {
            let last = entry(&values[..=finished], i - 1, tentative);
            if P::test(&last) {
                return Err((i - 1, tentative));
            }
            !less(&last, &values[tentative])
        } {
            finished = i;
            continue;
        }
        // Case 4: row i - 1 beats the last tentative column. Rows before it cannot give any later
        // column its minimum; restart the blocks from row i - 1.
        base = i - 1;
        tentative = i;
        finished = i;
    }
    Ok(OnlineMinima { values, rows })
}

/// Online column minima of an upper-triangular matrix whose entries may depend on the minima of
/// earlier columns (concave one-dimensional dynamic programming), under the order `cmp`.
///
/// Computes, for `j` in `0..size`,
///
/// ```text
/// values[0] = initial
/// values[j] = min { entry(values[..=f], i, j) : 0 <= i < j },   rows[j] = the topmost such i,
/// ```
///
/// where `entry(done, i, j)` is called only for `i < j`, and only once `values[..=i]` are final:
/// `done` is `values[..=f]` for some `f >= i`. This is the dynamic program `f(j) = min_{i<j} f(i) +
/// w(i, j)`: `entry` is `|done, i, j| done[i] + w(i, j)`.
///
/// The matrix `entry(i, j)` (`i < j`) must have column minima moving down: for rows `i < i'` and
/// columns `j < j'` with `i' < j`, if column `j` strictly prefers row `i'`, so does column `j'`.
/// This holds when `w` satisfies the (concave) quadrangle inequality `w(i, j) + w(i', j') <= w(i,
/// j') + w(i', j)` for `i < i' < j < j'`, e.g. `w(i, j) = g(x_j - x_i)` with `g` convex and `x`
/// increasing (squared slack in line breaking, least-squares segment costs). Entries that must
/// stay exactly ordered (infeasible lines ordered by overflow, penalties) need an exact tagged
/// type, as for [`row_minima_by`](crate::row_minima_by); see the line-breaking example.
///
/// If the requirement does not hold the result is unspecified (but has the right length, and
/// `rows[j] < j`), without panics.
///
/// # Panics
///
/// Never, except for allocation failure; panics in `entry` or `cmp` propagate.
///
/// # Complexity
///
/// `O(size)` entry lookups and time, amortized over the whole run (not per column): each column
/// is finished with at most two lookups, or by a SMAWK search on a block of `k` earlier rows and
/// at most `k` columns, which costs at most `15k` lookups and is paid for either by the `k`
/// columns it finishes or by the increase, by at least `k - 1`, of the first row still in play
/// when a reset discards it. That argument bounds the total by about `80 * size`; measured on the
/// programs in `tests/complexity.rs`: 2.5 lookups per column when every minimum is on the
/// diagonal, at most 11.6 otherwise. Memory `O(size)`.
///
/// # Examples
///
/// Cheapest way to cut `0..=n` into segments of cost `(length - 3)² + 1`:
///
/// ```
/// use monotone_minima::online_column_minima_by;
///
/// let n = 10;
/// let cost = |i: usize, j: usize| (j as i64 - i as i64 - 3).pow(2) + 1;
/// let result = online_column_minima_by(n + 1, 0, |done: &[i64], i, j| done[i] + cost(i, j), Ord::cmp);
/// assert_eq!(result.values[n], 4); // 3 + 3 + 4, 3 + 4 + 3 or 4 + 3 + 3
///
/// // Walk the predecessors back from n.
/// let (mut j, mut cuts) = (n, vec![n]);
/// while j > 0 {
///     j = result.rows[j];
///     cuts.push(j);
/// }
/// assert_eq!(cuts, [10, 6, 3, 0]); // 3 + 3 + 4: the topmost predecessor wins ties
/// ```
///
/// # References
///
/// - Z. Galil, K. Park, "A linear-time algorithm for concave one-dimensional dynamic programming",
///   *Information Processing Letters* 33 (1990) 309–311 (the algorithm; this is D. Eppstein's
///   simplified formulation from the PADS library).
/// - A. Aggarwal, M. M. Klawe, S. Moran, P. Shor, R. Wilber, "Geometric applications of a
///   matrix-searching algorithm", *Algorithmica* 2 (1987) 195–208 (SMAWK, used on the blocks).
/// - L. L. Larmore, B. Schieber, "On-line dynamic programming with applications to the prediction
///   of RNA secondary structure", *Journal of Algorithms* 12 (1991) 490–515 (LARSCH, the same bound
///   for a more general online setting).
pub fn online_column_minima_by<T, F, C>(
    size: usize,
    initial: T,
    mut entry: F,
    mut cmp: C,
) -> OnlineMinima<T>
where
    F: FnMut(&[T], usize, usize) -> T,
    C: FnMut(&T, &T) -> Ordering,
{
    let result = online::<T, Clean>(
        size,
        initial,
        &mut |done, i, j| entry(done, i, j),
        &mut |a, b| cmp(a, b) == Ordering::Less,
    );
    clean(result)
}

/// Online column minima for [`Ord`] entries; see [`online_column_minima_by`].
///
/// # Panics
///
/// Never, except for allocation failure; panics in `entry` propagate.
///
/// # Complexity
///
/// `O(size)` entry lookups and time, amortized; see [`online_column_minima_by`].
///
/// # Examples
///
/// ```
/// use monotone_minima::online_column_minima;
///
/// // Cheapest walk 0 -> 6 where a hop i -> j costs (j - i)² + 4: hops of 2 are best. Reaching 3
/// // costs 13 from 0, 1 or 2 alike, and the topmost row, 0, wins the tie.
/// let result = online_column_minima(7, 0_u32, |done: &[u32], i, j| done[i] + ((j - i) * (j - i)) as u32 + 4);
/// assert_eq!(result.values, [0, 5, 8, 13, 16, 21, 24]);
/// assert_eq!(result.rows, [0, 0, 0, 0, 2, 2, 4]);
/// ```
///
/// # References
///
/// Z. Galil, K. Park, "A linear-time algorithm for concave one-dimensional dynamic programming",
/// *Information Processing Letters* 33 (1990) 309–311; A. Aggarwal, M. M. Klawe, S. Moran, P. Shor,
/// R. Wilber, *Algorithmica* 2 (1987) 195–208.
pub fn online_column_minima<T, F>(size: usize, initial: T, mut entry: F) -> OnlineMinima<T>
where
    T: Ord,
    F: FnMut(&[T], usize, usize) -> T,
{
    let result = online::<T, Clean>(
        size,
        initial,
        &mut |done, i, j| entry(done, i, j),
        &mut |a, b| a < b,
    );
    clean(result)
}

/// Online column minima for `f64` entries (IEEE order); a NaN entry is an error. See
/// [`online_column_minima_by`].
///
/// # Errors
///
/// [`NanError`] with the row and column of the first NaN entry looked up; the computation stops
/// there. `initial` is not an entry and is not checked (entries computed from a NaN `initial`
/// are typically NaN and are reported).
///
/// # Panics
///
/// Never, except for allocation failure; panics in `entry` propagate.
///
/// # Complexity
///
/// `O(size)` entry lookups and time, amortized; see [`online_column_minima_by`].
///
/// # Examples
///
/// ```
/// use monotone_minima::online_column_minima_f64;
///
/// // Least-squares-like segmentation: cost of segment (i, j] is (j - i - 2.5)².
/// let result = online_column_minima_f64(6, 0.0, |done, i, j| done[i] + (j as f64 - i as f64 - 2.5).powi(2)).unwrap();
/// assert_eq!(result.values[5], 0.5);
///
/// let err = online_column_minima_f64(6, 0.0, |_, i, j| if j == 4 { f64::NAN } else { (j - i) as f64 }).unwrap_err();
/// assert_eq!(err.column(), 4);
/// ```
///
/// # References
///
/// Z. Galil, K. Park, "A linear-time algorithm for concave one-dimensional dynamic programming",
/// *Information Processing Letters* 33 (1990) 309–311; A. Aggarwal, M. M. Klawe, S. Moran, P. Shor,
/// R. Wilber, *Algorithmica* 2 (1987) 195–208.
pub fn online_column_minima_f64<F>(
    size: usize,
    initial: f64,
    mut entry: F,
) -> Result<OnlineMinima<f64>, NanError>
where
    F: FnMut(&[f64], usize, usize) -> f64,
{
    online::<f64, Nan>(
        size,
        initial,
        &mut |done, i, j| entry(done, i, j),
        &mut |a, b| a < b,
    )
    .map_err(|(row, column)| NanError::new(row, column))
}
