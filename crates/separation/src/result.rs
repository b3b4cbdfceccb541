//! Result types.

use glam::DVec2;
use polydist_polygon::Feature;

/// A closest pair between the chains `P` and `Q`, in the caller's indices: `Feature::Vertex(i)` is
/// the caller's vertex `i` of that chain, `Feature::Edge(i)` the segment from vertex `i` to vertex
/// `i + 1`. A closed chain (last vertex = first) reports its repeated last vertex as `Vertex(0)`; its
/// closing edge, from vertex `n − 1` to the repeat at index `n`, is `Edge(n − 1)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestPair {
    /// The distance, rounded from the exact value (see `construct` error bounds in the crate docs).
    pub distance: f64,
    /// The squared distance, the exact value rounded once for vertex pairs.
    pub squared_distance: f64,
    /// The realizing point on `P`.
    pub point_p: DVec2,
    /// The realizing point on `Q`.
    pub point_q: DVec2,
    /// The feature of `P` realizing the distance (exact).
    pub feature_p: Feature,
    /// The feature of `Q` realizing the distance (exact).
    pub feature_q: Feature,
}

/// Operation counts of one run of [`closest_visible_vertices`](crate::closest_visible_vertices),
/// for complexity tests (predicate counts come from `polydist_predicates::Counted`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CvvStats {
    /// Vertices of `P` left after Lemma 2 (perpendicular visibility).
    pub p_after_lemma2: usize,
    /// Vertices of `Q` left after Lemma 2.
    pub q_after_lemma2: usize,
    /// Vertices of `P` left after Lemma 3 (`α ≥ 90°`): the rows of `M`.
    pub p_after_lemma3: usize,
    /// Vertices of `Q` left after Lemma 3: the columns of `M`.
    pub q_after_lemma3: usize,
    /// Entries of `M` evaluated by SMAWK.
    pub entries_evaluated: usize,
}

/// The closest visible vertex pair and the work done to find it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cvv {
    /// The pair, both features `Feature::Vertex`.
    pub pair: ClosestPair,
    /// Operation counts.
    pub stats: CvvStats,
}

/// Operation counts of one run of [`separation_of_chains`](crate::separation_of_chains).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SeparationStats {
    /// The CVV step.
    pub cvv: CvvStats,
    /// Edge pieces of `P` (rows of the first CVE matrix).
    pub pieces_p: usize,
    /// Edge pieces of `Q` (rows of the second CVE matrix).
    pub pieces_q: usize,
    /// Entries of the two CVE matrices evaluated by SMAWK.
    pub cve_entries_evaluated: usize,
    /// Separator route only: the kept segments `l_0 … l_{m−1}` of `S(P, Q)`.
    pub separator_segments: usize,
    /// Separator route only: `Σ (|P_i| + |Q_i|)`, the vertices handed to the subproblems.
    pub subproblem_vertices: usize,
    /// Separator route only: subproblems solved by section 3 across the line of `l_i`.
    pub subproblems_section3: usize,
    /// Separator route only: subproblems scanned exactly in `O(|P_i| · |Q_i|)`: small ones (at most
    /// 256 vertex pairs, where section 3's set-up costs more), and those section 3 rejects (its
    /// consistency checks, which fail only under the Fast kernel in our tests).
    pub subproblems_scanned: usize,
    /// Separator route only: of the scanned subproblems, those of more than 256 vertex pairs (none
    /// in the interlocked stars test since Step G, which asserts it). They are scanned last, pruned by bounding
    /// boxes against the best answer of all other subproblems and by their distance to `l_i`.
    pub subproblems_scanned_large: usize,
    /// Separator route only: cuts not found where the construction puts them (0 under the exact
    /// kernels in every test); the subchain then runs to the end of its wall, which is still sound.
    pub cut_fallbacks: usize,
    /// Separator route only: parts of subproblems (pairs of runs across the line of `l_i`) that
    /// the monotone sweep answered in place of section 3 (both monotone along the line, windows
    /// within the budget).
    pub subproblem_parts_swept: usize,
    /// Separator route only: parts of subproblems that section 3's envelope sweep answered
    /// (the parts not both monotone, or whose monotone sweep ran out of budget, with envelopes
    /// whose windows fit the budget; [`ChainMethod::Auto`](crate::ChainMethod::Auto)).
    pub subproblem_parts_enveloped: usize,
    /// Separator route only: side assignments of subproblems that cross the line of `l_i` more
    /// often than pairs of runs allow, solved by section 3 on the subchains clipped to the line
    /// (gapped chains with symbolic clip points: Step G).
    pub subproblem_parts_gapped: usize,
    /// [`Route::MonotoneSweep`](crate::Route::MonotoneSweep) and
    /// [`Route::EnvelopeSweep`](crate::Route::EnvelopeSweep) (and
    /// [`ChainMethod::Auto`](crate::ChainMethod::Auto) when its sweep answered) only: the
    /// candidate pairs the sweep tried (at most `96N + 1024`).
    pub sweep_candidates: usize,
}

/// The separation of two chains, a realizing pair, and the work done.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainSeparation {
    /// The pair; `feature_p`/`feature_q` are the caller's vertices or edges.
    pub pair: ClosestPair,
    /// Operation counts.
    pub stats: SeparationStats,
}
