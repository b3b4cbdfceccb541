//! All farthest neighbours of the vertices of a convex polygon in linear time, the first
//! application in Aggarwal, Klawe, Moran, Shor and Wilber (1987) (shared by the
//! `farthest_neighbours` example and `tests/examples.rs`).

use core::cmp::Ordering;

use monotone_minima::{Matrix, from_fn, row_minima_by};

/// An entry of the `n` × `2n - 1` search matrix.
///
/// Row `i` is vertex `i`; column `j` is vertex `j mod n`. The band `i < j < i + n` holds the
/// distances to the other vertices, in counterclockwise order from `i`. The rest must not hold a
/// minimum and must keep the matrix totally monotone: left of the band, `Left(j)` decreases to
/// the right; right of it, `Right(j)` increases; both rank above every distance. Compared
/// exactly, not as `f64` sentinels (`±inf` would tie and break total monotonicity).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Entry {
    /// Distance between the row's and the column's vertex; larger is better.
    Band(f64),
    /// Right of the band, at column `j`.
    Right(usize),
    /// Left of the band, at column `j`.
    Left(usize),
}

/// The search order: farther is smaller, then `Right` by increasing `j`, then `Left` by
/// decreasing `j`.
pub(crate) fn compare(a: &Entry, b: &Entry) -> Ordering {
    match (a, b) {
        (Entry::Band(x), Entry::Band(y)) => y.total_cmp(x),
        (Entry::Right(x), Entry::Right(y)) => x.cmp(y),
        (Entry::Left(x), Entry::Left(y)) => y.cmp(x),
        (Entry::Band(_), _) | (Entry::Right(_), Entry::Left(_)) => Ordering::Less,
        _ => Ordering::Greater,
    }
}

/// The implicit search matrix of a convex polygon (vertices in order, either orientation).
///
/// Inside the band it is totally monotone because for four vertices in convex position,
/// `p, p', q, q'` in order, the diagonals are longer than two opposite sides:
/// `d(p, q) + d(p', q') >= d(p, q') + d(p', q)`.
pub(crate) fn matrix(polygon: &[(f64, f64)]) -> impl Matrix<Entry = Entry> + '_ {
    let n = polygon.len();
    from_fn(n, (2 * n).saturating_sub(1), move |i, j| {
        if j <= i {
            Entry::Left(j)
        } else if j < i + n {
            let (p, q) = (polygon[i], polygon[j % n]);
            Entry::Band(f64::hypot(p.0 - q.0, p.1 - q.1))
        } else {
            Entry::Right(j)
        }
    })
}

/// For each vertex of a convex polygon, the farthest other vertex (the first one
/// counterclockwise from it on ties, for counterclockwise input); empty for fewer than two
/// vertices. `O(n)` distance evaluations.
pub(crate) fn farthest_neighbours(polygon: &[(f64, f64)]) -> Vec<usize> {
    let n = polygon.len();
    if n < 2 {
        return Vec::new();
    }
    row_minima_by(&matrix(polygon), compare)
        .into_iter()
        .map(|j| j % n)
        .collect()
}
