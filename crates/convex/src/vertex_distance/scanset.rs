//! FUNCTION SCANSET and FUNCTION USERNG (McKenna–Toussaint 1985, §5), the two building blocks of
//! step 9.
//!
//! USERNG is a black box in the paper (the closest pair between two chains on the boundary of one
//! convex polygon, via Supowit's relative neighbourhood graph). We substitute SMAWK row minima
//! (`monotone-minima`) on the matrix `M[i][j] = |a_i − b_{q+1−j}|`, which is Monge when
//! `a_1 … a_p, b_1 … b_q` are in convex position in this cyclic order: for rows `i < i'` and columns
//! `j < j'` the four points `a_i, a_{i'}, b_{q+1−j'}, b_{q+1−j}` are in cyclic order, so the segments
//! `a_i b_{q+1−j'}` and `a_{i'} b_{q+1−j}` are the diagonals of a convex quadrilateral and meet at a
//! point `o`; the triangle inequality through `o` gives
//! `M[i][j'] + M[i'][j] ≥ M[i][j] + M[i'][j']` (the diagonals outweigh two opposite sides). A Monge
//! matrix is totally monotone, SMAWK's contract. SMAWK only ever compares two entries of one row, and
//! we compare them exactly with the kernel's four-point comparison `cmp_dist4`: no distance is rounded.

use polydist_polygon::predicates::Kernel;

use super::chain::{Best, Chain};

/// SCANSET(x, S): offers `(x, s)` for every `s ∈ S`. Used where `x` dominates its own set in a
/// quadrant and every point of `S` dominates that set (Lemma 12), so `x` is the nearest point of its
/// set to every `s`.
pub(super) fn scanset<K: Kernel>(x: &Chain<'_>, k: usize, s: &Chain<'_>, best: &mut Best) {
    if k >= x.len() {
        return;
    }
    for l in 0..s.len() {
        best.offer_chains::<K>(x, k, s, l);
    }
}

/// USERNG(A, B) by SMAWK: the closest pair between `rows` and `columns` when `rows` (listed in the
/// frame from top to bottom) and `columns` (listed from top to bottom as well) are in convex position
/// with cyclic order `rows, reversed columns`. `O(|rows| + |columns|)` comparisons.
pub(super) fn userng<K: Kernel>(rows: &Chain<'_>, columns: &Chain<'_>, best: &mut Best) {
    if rows.is_empty() || columns.is_empty() {
        return;
    }
    #[cfg(test)]
    record::push(rows, columns);
    let m = monotone_minima::from_fn(rows.len(), columns.len(), |i, j| {
        (rows.pt(i), columns.pt(j))
    });
    // Entries of one row share the row's point: `cmp_dist4` decides |a − b|² against |a − b'|² exactly.
    let minima = monotone_minima::row_minima_by(&m, |x, y| K::cmp_dist4(x.0, x.1, y.0, y.1));
    for (i, &j) in minima.iter().enumerate() {
        if j < columns.len() {
            best.offer_chains::<K>(rows, i, columns, j);
        }
    }
}

/// Test-only record of every USERNG block, to check each one is totally monotone.
#[cfg(test)]
pub(in crate::vertex_distance) mod record {
    use core::cell::RefCell;

    use glam::DVec2;

    use super::Chain;

    /// Rows and columns of one block, in the order given to SMAWK.
    pub(in crate::vertex_distance) type Block = (Vec<DVec2>, Vec<DVec2>);

    std::thread_local! {
        static BLOCKS: RefCell<Vec<Block>> = const { RefCell::new(Vec::new()) };
    }

    /// Records a block.
    pub(super) fn push(rows: &Chain<'_>, columns: &Chain<'_>) {
        let pts = |c: &Chain<'_>| (0..c.len()).map(|k| c.pt(k)).collect::<Vec<_>>();
        BLOCKS.with(|b| b.borrow_mut().push((pts(rows), pts(columns))));
    }

    /// The blocks recorded on this thread since the last call.
    pub(in crate::vertex_distance) fn take() -> Vec<Block> {
        BLOCKS.with(|b| core::mem::take(&mut *b.borrow_mut()))
    }
}
