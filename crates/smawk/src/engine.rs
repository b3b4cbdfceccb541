//! The SMAWK engine: row minima of a totally monotone matrix, iteratively and without per-level
//! allocation.
//!
//! The engine sees the matrix as a lookup `(row, column) -> T` and a strict order `less(a, b)`,
//! plus a [`Poison`] test for entries that invalidate the search (NaN for `f64`). Poisoned entries
//! are not reported where they are met: each function ORs the test into a local flag and returns
//! it, so the hot loops stay free of early exits (which would stop the compiler from pairing
//! independent lookups, e.g. two square roots in one instruction). The `f64` functions run the
//! search again to locate the first NaN in the rare case the flag is set.
//!
//! SMAWK(R, C) reduces the columns C to at most |R| candidates C' (REDUCE), recurses on the odd
//! rows of R with C', and then fills in the even rows by scanning C' between the minima of their
//! odd neighbours (INTERPOLATE). Here the recursion is unrolled into levels:
//!
//! - The rows of level `l` are never stored: they are `2^l - 1`, `2 * 2^l - 1`, ... (the odd rows
//!   of level `l - 1`), `rows >> l` of them.
//! - Each level has a list of candidate columns. Level 0 starts with all the columns, unstored.
//!   A level whose inherited list is more than `SLACK` times longer than its row count REDUCEs
//!   it; the others share their parent's list (skipping REDUCE where it would remove few columns
//!   saves more lookups than it costs in INTERPOLATE). The reduced lists are stored one after the
//!   other in one buffer, preallocated once, with, for each candidate, its position in the
//!   previous list; REDUCE uses the free end of the buffer as its stack.
//! - Going up, minima are positions in the current level's list, so each even row knows the exact
//!   range of candidates to scan; positions are mapped to the parent list level by level, and to
//!   columns at the end.

use alloc::vec::Vec;

/// Levels with at most this many rows are scanned directly instead of being split further.
const BASE_ROWS: usize = 1;

/// A level REDUCEs its inherited candidate list only if the list has more than `SLACK` times as
/// many columns as the level has rows; 1 is plain SMAWK. Measured (see `docs/algorithms/smawk.md`):
/// against 1, 2 saves 10% of the lookups and 20% of the time when the rows' minima are all
/// distinct, and 15% of the time (for 10% more lookups) when REDUCE eliminates most columns; 4 is
/// a little faster again at large sizes but looks at more entries, which costly entries pay for.
const SLACK: usize = 2;

/// Matrices with at most this many entries are searched by a plain scan, without allocating any
/// scratch space. Measured (see `docs/algorithms/smawk.md`): square matrices break even at about
/// 10 × 10 with a square-root distance entry and 22 × 22 with a subtract-and-square entry; the
/// cutoff leans towards costlier entries.
pub(crate) const SCAN_AREA: usize = 64;

/// Scratch space for [`smawk_into`], reusable across calls.
pub(crate) struct Workspace<T> {
    /// The stored candidate lists, one after the other, then the REDUCE stack: each candidate's
    /// column and its position in the previous level's list. (One allocation rather than two
    /// halves the allocator traffic of one-shot calls.)
    entries: Vec<(usize, usize)>,
    /// During REDUCE, `values[k]` is the entry of the stack's `k`-th column in the `k`-th row.
    values: Vec<T>,
}

impl<T> Workspace<T> {
    pub(crate) const fn new() -> Self {
        Self {
            entries: Vec::new(),
            values: Vec::new(),
        }
    }
}

/// A level's candidate list.
#[derive(Clone, Copy, Default)]
struct Level {
    /// Where the list starts in the buffer (if stored).
    start: usize,
    /// Its length.
    len: usize,
    /// Whether it is stored; if not, it is all the columns `0..len`.
    stored: bool,
    /// Whether this level made it by REDUCE (so `parents` map it to the previous list); if not,
    /// it is the previous level's list.
    reduced: bool,
}

/// The `k`-th row of level `level`: `(k + 1) * 2^level - 1`.
///
/// Callers keep `k < rows >> level`, so the result is below `rows` and cannot overflow.
#[inline(always)]
const fn row_of(level: u32, k: usize) -> usize {
    ((k + 1) << level) - 1
}

/// A candidate list: position to column.
trait List {
    fn column(&self, buffer: &[(usize, usize)], position: usize) -> usize;
}

/// All the columns, never stored.
struct AllColumns;

impl List for AllColumns {
    #[inline(always)]
    fn column(&self, _buffer: &[(usize, usize)], position: usize) -> usize {
        position
    }
}

/// A list stored in the buffer from `.0` on.
struct Stored(usize);

impl List for Stored {
    #[inline(always)]
    fn column(&self, buffer: &[(usize, usize)], position: usize) -> usize {
        buffer[self.0 + position].0
    }
}

/// Entries that invalidate a search when looked up.
pub(crate) trait Poison<T> {
    /// Whether `value` is poisoned.
    fn test(value: &T) -> bool;
}

/// No entry is poisoned.
pub(crate) struct Clean;

impl<T> Poison<T> for Clean {
    #[inline(always)]
    fn test(_value: &T) -> bool {
        false
    }
}

/// NaN is poisoned.
pub(crate) struct Nan;

impl Poison<f64> for Nan {
    #[inline(always)]
    fn test(value: &f64) -> bool {
        value.is_nan()
    }
}

/// Row minima of the `rows` × `columns` matrix `lookup`, leftmost on ties, written to
/// `argmin[..rows]`. With `VALUES`, `sink(row, value)` receives each row's minimum value once;
/// without, `sink` is never called, and a row whose minimum is forced (a single candidate left)
/// costs no lookup. Returns whether any entry looked up was poisoned (then the result is
/// meaningless, but still one valid column per row).
///
/// Requires `argmin.len() >= rows`. For a totally monotone matrix the result is exact; for any
/// other matrix it is some column index per row, without panics.
///
/// Lookups: at most `3 * columns + 12 * rows` for any matrix (see `docs/algorithms/smawk.md`).
pub(crate) fn smawk_into<T, P: Poison<T>, const VALUES: bool>(
    rows: usize,
    columns: usize,
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
    argmin: &mut [usize],
    sink: &mut impl FnMut(usize, T),
    ws: &mut Workspace<T>,
) -> bool {
    if rows == 0 || columns == 0 {
        return false;
    }
    if rows
        .checked_mul(columns)
        .is_some_and(|area| area <= SCAN_AREA)
    {
        return scan_into::<T, P>(rows, columns, lookup, less, argmin, sink);
    }
    // A list REDUCEd at level l has at most min(rows >> l, columns) candidates, and each level
    // stores at most one.
    let stored = (0..usize::BITS)
        .map(|l| (rows >> l).min(columns))
        .fold(0, usize::saturating_add);
    ws.entries.clear();
    ws.entries.reserve(stored);
    ws.values.clear();
    ws.values.reserve(rows);

    let mut poisoned = false;
    let mut levels = [Level::default(); usize::BITS as usize + 1];
    levels[0] = if columns > rows.saturating_mul(SLACK) {
        poisoned |= reduce::<T, P>(&AllColumns, columns, 0, rows, lookup, less, ws);
        Level {
            start: 0,
            len: ws.entries.len(),
            stored: true,
            reduced: true,
        }
    } else {
        Level {
            start: 0,
            len: columns,
            stored: false,
            reduced: false,
        }
    };

    // Down: reduce where worthwhile.
    let mut level: u32 = 0;
    while rows >> level > BASE_ROWS {
        let parent = levels[level as usize];
        level += 1;
        let level_rows = rows >> level;
        levels[level as usize] = if parent.len > level_rows * SLACK {
            let start = ws.entries.len();
            poisoned |= if parent.stored {
                reduce::<T, P>(
                    &Stored(parent.start),
                    parent.len,
                    level,
                    level_rows,
                    lookup,
                    less,
                    ws,
                )
            } else {
                reduce::<T, P>(&AllColumns, parent.len, level, level_rows, lookup, less, ws)
            };
            Level {
                start,
                len: ws.entries.len() - start,
                stored: true,
                reduced: true,
            }
        } else {
            Level {
                reduced: false,
                ..parent
            }
        };
    }

    // The last level: scan each row from the previous row's minimum on.
    let last = levels[level as usize];
    let mut from = 0;
    for k in 0..rows >> level {
        let row = row_of(level, k);
        let (pos, bad) = if last.stored {
            scan::<T, P, VALUES>(
                row,
                &Stored(last.start),
                &ws.entries,
                from,
                last.len - 1,
                lookup,
                less,
                sink,
            )
        } else {
            scan::<T, P, VALUES>(
                row,
                &AllColumns,
                &ws.entries,
                from,
                last.len - 1,
                lookup,
                less,
                sink,
            )
        };
        poisoned |= bad;
        argmin[row] = pos;
        from = pos;
    }

    // Up: the even rows of each level, between the minima of the odd ones.
    while level > 0 {
        let child = levels[level as usize];
        level -= 1;
        let list = levels[level as usize];
        let parents = if child.reduced {
            &ws.entries[child.start..child.start + child.len]
        } else {
            &[]
        };
        poisoned |= if list.stored {
            interpolate::<T, P, VALUES>(
                level,
                rows,
                list.len,
                &Stored(list.start),
                &ws.entries,
                parents,
                lookup,
                less,
                argmin,
                sink,
            )
        } else {
            interpolate::<T, P, VALUES>(
                level,
                rows,
                list.len,
                &AllColumns,
                &ws.entries,
                parents,
                lookup,
                less,
                argmin,
                sink,
            )
        };
    }

    // Positions in the level-0 list to columns.
    let top = levels[0];
    if top.stored {
        let list = &ws.entries[top.start..top.start + top.len];
        for slot in &mut argmin[..rows] {
            *slot = list.get(*slot).map_or(0, |&(column, _)| column);
        }
    }
    poisoned
}

/// Row minima by a plain scan of every entry, for small matrices; returns whether an entry was
/// poisoned.
fn scan_into<T, P: Poison<T>>(
    rows: usize,
    columns: usize,
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
    argmin: &mut [usize],
    sink: &mut impl FnMut(usize, T),
) -> bool {
    let mut poisoned = false;
    for (row, slot) in argmin.iter_mut().enumerate().take(rows) {
        let mut best = lookup(row, 0);
        poisoned |= P::test(&best);
        let mut best_column = 0;
        for column in 1..columns {
            let value = lookup(row, column);
            poisoned |= P::test(&value);
            if less(&value, &best) {
                best = value;
                best_column = column;
            }
        }
        *slot = best_column;
        sink(row, best);
    }
    poisoned
}

/// The position of the leftmost minimum of `row` over the list positions `from..=to`
/// (`from <= to`, both in bounds), and whether a poisoned entry was met; with `VALUES`, the
/// minimum goes to `sink`. Without `VALUES` a single candidate costs no lookup.
#[inline(always)]
#[expect(
    clippy::too_many_arguments,
    reason = "an internal helper, inlined into its three callers"
)]
fn scan<T, P: Poison<T>, const VALUES: bool>(
    row: usize,
    list: &impl List,
    buffer: &[(usize, usize)],
    from: usize,
    to: usize,
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
    sink: &mut impl FnMut(usize, T),
) -> (usize, bool) {
    if !VALUES && from == to {
        return (from, false);
    }
    let mut best_pos = from;
    let mut best = lookup(row, list.column(buffer, from));
    let mut poisoned = P::test(&best);
    let mut pos = from + 1;
    if to - from >= 8 {
        // Long ranges: two interleaved running minima, so that each comparison waits for the
        // previous-but-one instead of the previous one (and the two lookups can be paired);
        // then the better of the two, the leftmost on a tie.
        let mut other_pos = pos;
        let mut other = lookup(row, list.column(buffer, pos));
        poisoned |= P::test(&other);
        pos += 1;
        while pos < to {
            let value = lookup(row, list.column(buffer, pos));
            let next = lookup(row, list.column(buffer, pos + 1));
            poisoned |= P::test(&value) | P::test(&next);
            if less(&value, &best) {
                best = value;
                best_pos = pos;
            }
            if less(&next, &other) {
                other = next;
                other_pos = pos + 1;
            }
            pos += 2;
        }
        if less(&other, &best) || (!less(&best, &other) && other_pos < best_pos) {
            best = other;
            best_pos = other_pos;
        }
    }
    for pos in pos..to + 1 {
        let value = lookup(row, list.column(buffer, pos));
        poisoned |= P::test(&value);
        if less(&value, &best) {
            best = value;
            best_pos = pos;
        }
    }
    if VALUES {
        sink(row, best);
    }
    (best_pos, poisoned)
}

/// REDUCE: pushes onto the buffer the at most `level_rows` columns of the input list (with their
/// input positions) that can still hold the leftmost minimum of some row of `level` (all of them,
/// in a totally monotone matrix); returns whether a poisoned entry was met.
///
/// The stack's `k`-th column is the only candidate left for the `k`-th row among the columns
/// popped or discarded so far; `ws.values[k]` caches its entry in that row, so each comparison
/// costs one lookup, and a column that pops is pushed with the entry its last comparison looked
/// up.
fn reduce<T, P: Poison<T>>(
    input: &impl List,
    input_len: usize,
    level: u32,
    level_rows: usize,
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
    ws: &mut Workspace<T>,
) -> bool {
    let base = ws.entries.len();
    let capacity = level_rows.min(input_len);
    ws.entries.resize(base + capacity, (0, 0));
    let (inputs, stack) = ws.entries.split_at_mut(base);
    // `values[..depth]` are the stack's entries; anything after them is stale.
    let values = &mut ws.values;
    values.clear();
    // The stack's k-th row is (k + 1) * step - 1.
    let step = 1_usize << level;
    let mut depth: usize = 0;
    let mut poisoned = false;
    for index in 0..input_len {
        let column = input.column(inputs, index);
        let value = match depth.checked_sub(1).and_then(|top| values.get(top)) {
            None => lookup(step - 1, column),
            Some(top) => {
                let mut row = depth * step - 1;
                let value = lookup(row, column);
                poisoned |= P::test(&value);
                if !less(&value, top) {
                    // The top keeps its row; `column` goes above it if there is a row left.
                    if depth == capacity {
                        continue;
                    }
                    lookup(row + step, column)
                } else {
                    // `column` is strictly better in the top's row, hence in every later row:
                    // the top is dead for its own row and all later ones (earlier rows are
                    // covered below it). Pop until `column` stops winning; it takes the last
                    // freed row, with the entry already looked up.
                    let mut value = value;
                    depth -= 1;
                    while let Some(top) = depth.checked_sub(1).and_then(|k| values.get(k)) {
                        row -= step;
                        let above = lookup(row, column);
                        poisoned |= P::test(&above);
                        if !less(&above, top) {
                            break;
                        }
                        value = above;
                        depth -= 1;
                    }
                    value
                }
            }
        };
        poisoned |= P::test(&value);
        if let Some(slot) = stack.get_mut(depth) {
            *slot = (column, index);
            if let Some(old) = values.get_mut(depth) {
                *old = value;
            } else {
                values.push(value);
            }
            depth += 1;
        }
    }
    ws.entries.truncate(base + depth);
    poisoned
}

/// INTERPOLATE at `level`: on entry the odd rows hold their minima as positions in the child
/// level's list (mapped to this level's list through `parents`, or the same list if `parents` is
/// empty); on exit every row of the level holds its minimum as a position in this level's list.
/// Returns whether a poisoned entry was met.
#[expect(
    clippy::too_many_arguments,
    reason = "an internal helper with two call sites"
)]
fn interpolate<T, P: Poison<T>, const VALUES: bool>(
    level: u32,
    rows: usize,
    len: usize,
    list: &impl List,
    buffer: &[(usize, usize)],
    parents: &[(usize, usize)],
    lookup: &mut impl FnMut(usize, usize) -> T,
    less: &mut impl FnMut(&T, &T) -> bool,
    argmin: &mut [usize],
    sink: &mut impl FnMut(usize, T),
) -> bool {
    let level_rows = rows >> level;
    let mut from = 0;
    let mut poisoned = false;
    for k in (0..level_rows).step_by(2) {
        // The odd successor's minimum, in this list (the end for the last row). Never before
        // `from`, so that scans stay in bounds and move forward even if the matrix is not
        // totally monotone.
        let to = if k + 1 < level_rows {
            let odd = row_of(level, k + 1);
            let child = argmin[odd];
            let here = if parents.is_empty() {
                child
            } else {
                parents.get(child).map_or(0, |&(_, parent)| parent)
            };
            argmin[odd] = here.max(from);
            argmin[odd]
        } else {
            len - 1
        };
        let row = row_of(level, k);
        let (pos, bad) = scan::<T, P, VALUES>(row, list, buffer, from, to, lookup, less, sink);
        poisoned |= bad;
        argmin[row] = pos;
        from = to;
    }
    poisoned
}
