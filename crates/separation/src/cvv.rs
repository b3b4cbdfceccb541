//! CVV of two chains separated by a line (Amato 1992, section 3, the algorithm of \[A92\] sketched
//! there): Lemma 2, the wedges and Lemma 3, the regions `R()`, and the totally monotone matrix `M`
//! searched with SMAWK on exactly compared tagged entries.

use core::cell::Cell;
use core::cmp::Ordering;

use glam::DVec2;
use monotone_minima::{Matrix, row_minima_by};
use polydist_polygon::Feature;
use polydist_predicates::Kernel;

use crate::chain::{Frames, Prepared, check_monotone, validate, validate_touching};
use crate::construct::vertex_vertex;
use crate::envelope::prepare;
use crate::error::{Chain, SeparationError};
use crate::region::{Place, Region, band, regions};
use crate::result::{Cvv, CvvStats};
use crate::site::Vertex;
use crate::wedge::{Apex, apexes};

/// An entry of Amato's matrix `M`, compared exactly by [`compare_entries`]: every `Dist` is smaller
/// than every `Penalty`, every `Penalty` smaller than `Infinity`; `Penalty(a) < Penalty(b)` iff
/// `a < b`; two `Dist` compare by their exact squared lengths. This replaces the text's `B + n_q − j`
/// with `B` "greater than every distance", which in `f64` collapses for large `B` and breaks total
/// monotonicity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MatrixEntry<V = DVec2> {
    /// The distance between the row vertex `p` and the column vertex `q` (a candidate pair).
    Dist {
        /// The vertex of `P`.
        p: V,
        /// The vertex of `Q`.
        q: V,
    },
    /// `B + n_q − j`: the column vertex is below the row's region or the row vertex above the
    /// column's region. Holds `n_q − j`.
    Penalty(usize),
    /// Not a candidate, and no penalty.
    Infinity,
}

/// The exact order of [`MatrixEntry`] under kernel `K` (one `cmp_dist4`, degree 2, for two `Dist`).
#[must_use]
pub fn compare_entries<K: Kernel, V: Vertex>(a: &MatrixEntry<V>, b: &MatrixEntry<V>) -> Ordering {
    use MatrixEntry::{Dist, Infinity, Penalty};
    match (a, b) {
        (Dist { p, q }, Dist { p: r, q: s }) => V::cmp_dist4::<K>(*p, *q, *r, *s),
        (Penalty(x), Penalty(y)) => x.cmp(y),
        (Infinity, Infinity) => Ordering::Equal,
        (Dist { .. }, _) | (Penalty(_), Infinity) => Ordering::Less,
        _ => Ordering::Greater,
    }
}

/// The matrix `M` of the CVV step for two validated chains: rows are the vertices of `P` that
/// survive Lemmas 2–3 in increasing height, columns those of `Q`. Entries are computed on demand in
/// `O(1)` exact tests each (the regions are precomputed); [`Matrix::entry`] counts its calls.
#[derive(Clone, Debug)]
pub struct CvvMatrix<K: Kernel, V: Vertex = DVec2> {
    frames: Frames,
    rows: Vec<Apex<V>>,
    columns: Vec<Apex<V>>,
    /// `R(p_i)`, with `u^±` vertices of `Q`.
    row_regions: Vec<Region<V>>,
    /// `R(q_j)`, with `u^±` vertices of `P`.
    column_regions: Vec<Region<V>>,
    lookups: Cell<usize>,
    stats: CvvStats,
    kernel: core::marker::PhantomData<K>,
}

impl<K: Kernel> CvvMatrix<K> {
    /// Validates the input and builds the matrix: Lemma 2 (the perpendicular-visibility envelope of
    /// each chain; chains need not be monotone: this is the matrix of the CVV step of
    /// [`separation_of_chains`](crate::separation_of_chains)), the wedges by two hull scans per
    /// chain, Lemma 3, and the regions by two pointer scans per chain. `O(n_p + n_q)` exact degree-2
    /// tests, the envelope's included.
    ///
    /// # Errors
    /// See [`separation_of_chains`](crate::separation_of_chains).
    pub fn new(p: &[DVec2], q: &[DVec2], a: DVec2, b: DVec2) -> Result<Self, SeparationError> {
        // Both chains may touch the line, as in `separation_of_chains`; not both lie on it.
        let frames = validate_touching::<K>(p, q, a, b)?
            .frames
            .ok_or(SeparationError::BothChainsTouchLine)?;
        let pp = prepare::<K, _>(p, frames.p, Chain::P)?;
        let qq = prepare::<K, _>(q, frames.q, Chain::Q)?;
        let rows = apexes::<K, _>(&pp, frames.p);
        let columns = apexes::<K, _>(&qq, frames.q);
        Ok(Self::from_parts(frames, &pp, &qq, rows, columns))
    }
}

impl<K: Kernel, V: Vertex> CvvMatrix<K, V> {
    /// The matrix for prepared chains and their Lemma-3 survivors.
    pub(crate) fn from_parts(
        frames: Frames,
        pp: &Prepared<V>,
        qq: &Prepared<V>,
        rows: Vec<Apex<V>>,
        columns: Vec<Apex<V>>,
    ) -> Self {
        let row_regions = regions::<K, _>(&rows, frames.p, &columns, frames.q);
        let column_regions = regions::<K, _>(&columns, frames.q, &rows, frames.p);
        let stats = CvvStats {
            p_after_lemma2: pp.pts.len(),
            q_after_lemma2: qq.pts.len(),
            p_after_lemma3: rows.len(),
            q_after_lemma3: columns.len(),
            entries_evaluated: 0,
        };
        CvvMatrix {
            frames,
            rows,
            columns,
            row_regions,
            column_regions,
            lookups: Cell::new(0),
            stats,
            kernel: core::marker::PhantomData,
        }
    }

    /// SMAWK's row minima, then the least `Dist` among them: `(row, column)`, or `None` when no
    /// row minimum is a candidate.
    pub(crate) fn best(&self) -> Option<(usize, usize)> {
        let minima = row_minima_by(self, compare_entries::<K, V>);
        let mut best: Option<(usize, usize, MatrixEntry<V>)> = None;
        for (i, &j) in minima.iter().enumerate() {
            let e = self.entry(i, j);
            if !matches!(e, MatrixEntry::Dist { .. }) {
                continue;
            }
            if best
                .as_ref()
                .is_none_or(|(_, _, b)| compare_entries::<K, V>(&e, b) == Ordering::Less)
            {
                best = Some((i, j, e));
            }
        }
        best.map(|(i, j, _)| (i, j))
    }

    /// The row apex `i` and column apex `j`.
    pub(crate) fn apexes_at(&self, i: usize, j: usize) -> (&Apex<V>, &Apex<V>) {
        (&self.rows[i], &self.columns[j])
    }

    /// The statistics so far (lookups included).
    pub(crate) fn stats(&self) -> CvvStats {
        CvvStats {
            entries_evaluated: self.lookups.get(),
            ..self.stats
        }
    }

    /// The caller's index in `P` of row `i`.
    #[must_use]
    pub fn row_vertex(&self, i: usize) -> usize {
        self.rows[i].idx
    }

    /// The caller's index in `Q` of column `j`.
    #[must_use]
    pub fn column_vertex(&self, j: usize) -> usize {
        self.columns[j].idx
    }

    /// How many entries have been looked up so far.
    #[must_use]
    pub fn lookups(&self) -> usize {
        self.lookups.get()
    }
}

impl<K: Kernel, V: Vertex> Matrix for CvvMatrix<K, V> {
    type Entry = MatrixEntry<V>;

    fn rows(&self) -> usize {
        self.rows.len()
    }

    fn columns(&self) -> usize {
        self.columns.len()
    }

    fn entry(&self, i: usize, j: usize) -> MatrixEntry<V> {
        self.lookups.set(self.lookups.get() + 1);
        let (p, q) = (self.rows[i].pt, self.columns[j].pt);
        // q_j relative to R(p_i) (its u^± are vertices of Q), p_i relative to R(q_j); by height
        // bands, which are the regions for apexes (`region::band`).
        let q_in_rp = band::<K, _>(self.frames.q, p, &self.row_regions[i], q);
        let p_in_rq = band::<K, _>(self.frames.p, q, &self.column_regions[j], p);
        if q_in_rp == Place::Below || p_in_rq == Place::Above {
            MatrixEntry::Penalty(self.columns.len() - j)
        } else if q_in_rp == Place::Inside && p_in_rq == Place::Inside {
            MatrixEntry::Dist { p, q }
        } else {
            MatrixEntry::Infinity
        }
    }
}

/// The closest visible vertex pair (CVV) of two polygonal chains `p` and `q` separated by the line
/// through `a` and `b`, both chains monotone along that line (Amato 1992, section 3, the CVV
/// algorithm of \[A92\]; Aggarwal–Klawe–Moran–Shor–Wilber 1987 for the matrix search).
///
/// Two vertices are visible when the open segment between them meets neither chain. Steps: Lemma 2
/// (keep the perpendicularly visible vertices; for monotone chains, the nearest of each run at equal
/// height), the wedges `W()` by two hull scans per chain and Lemma 3 (drop `α < 90°`), the regions
/// `R()` by two pointer scans, and the row minima of the tagged matrix `M` by SMAWK.
///
/// Every decision is the sign of a degree-2 polynomial in the input coordinates, decided by `K`.
/// This is the *vertex* part of the separation only: CVV of two chains is not the separation
/// (vertex–edge pairs are missing) and CVV of two polygons can not be assembled from a separator
/// decomposition (Amato 1992, section 2).
///
/// # Complexity
/// `O(n_p + n_q)` time and predicate calls: at most `2n` orientation tests per hull scan, `2(n_p +
/// n_q)` candidate tests per region scan, and at most `3 n_q + 12 n_p` matrix entries of a constant
/// number of tests each.
///
/// # Errors
/// [`SeparationError`]: empty chains, invalid coordinates or line, a line that does not separate
/// the chains or that both chains touch, chains that are not monotone along the line, and (Fast
/// kernel only) [`SeparationError::Inconsistent`].
///
/// # Examples
/// ```
/// use glam::DVec2;
/// use polydist_polygon::Feature;
/// use polydist_predicates::Robust;
/// use polydist_separation::closest_visible_vertices;
///
/// // Two zig-zags facing each other across the y-axis.
/// let p = [DVec2::new(1.0, 0.0), DVec2::new(3.0, 1.0), DVec2::new(1.5, 2.0)];
/// let q = [DVec2::new(-2.0, 0.5), DVec2::new(-0.5, 1.5), DVec2::new(-3.0, 3.0)];
/// let cvv = closest_visible_vertices::<Robust>(&p, &q, DVec2::ZERO, DVec2::Y)?;
/// assert_eq!((cvv.pair.feature_p, cvv.pair.feature_q), (Feature::Vertex(2), Feature::Vertex(1)));
/// assert_eq!(cvv.pair.squared_distance, 4.25);
/// # Ok::<(), polydist_separation::SeparationError>(())
/// ```
pub fn closest_visible_vertices<K: Kernel>(
    p: &[DVec2],
    q: &[DVec2],
    a: DVec2,
    b: DVec2,
) -> Result<Cvv, SeparationError> {
    let frames = validate::<K>(p, q, a, b)?;
    check_monotone::<K>(p, frames.p, Chain::P)?;
    check_monotone::<K>(q, frames.q, Chain::Q)?;
    let m = CvvMatrix::<K>::new(p, q, a, b)?;
    let (i, j) = m.best().ok_or(SeparationError::Inconsistent)?;
    let (r, c) = m.apexes_at(i, j);
    let pair = vertex_vertex(r.pt, c.pt, Feature::Vertex(r.idx), Feature::Vertex(c.idx));
    let stats = m.stats();
    Ok(Cvv { pair, stats })
}
