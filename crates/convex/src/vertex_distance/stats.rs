//! Diagnostics: which paths of the algorithm ran on this thread (for tests that every case is
//! exercised, and for the complexity tests).

use core::cell::Cell;

/// What [`min_vertex_distance_with`](crate::min_vertex_distance_with) did on this thread since the last
/// [`reset_vertex_distance_case_counts`]. **Diagnostics only**: the fields may grow between releases.
///
/// Case numbers are the paper's (McKenna–Toussaint 1985, §5, Fig. 5), counted in the frame of the
/// input before any reduction; sub-cases 6.1–6.4 are counted separately for inputs in case 6 and for
/// inputs in case 8 (which the x-mirror reduces to case 6).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VertexDistanceCounts {
    /// Calls of the public functions (brute force excluded).
    pub calls: u64,
    /// Step 1 stopped: the bridge is realized by two vertices (Lemma 1).
    pub bridge_vertex_vertex: u64,
    /// The bridge's edge is on `P` (a vertex of `Q` faces an edge of `P`, or parallel edges).
    pub bridge_edge_on_p: u64,
    /// The bridge's edge is on `Q`.
    pub bridge_edge_on_q: u64,
    /// A point or a segment against a polygon: answered by one linear scan.
    pub small_scans: u64,
    /// Step 9 in case `c` of Fig. 5 increments `cases[c]` (`cases[0]` is unused).
    pub cases: [u64; 10],
    /// Sub-cases 6.1–6.4 (`[0]` is 6.1) reached from case 6.
    pub sub_cases_6: [u64; 4],
    /// Sub-cases 6.1–6.4 reached from case 8 through the x-mirror.
    pub sub_cases_8: [u64; 4],
    /// `P`'s top edge is horizontal in the bridge frame (the tie rule of step 4 applied), and the same
    /// for `P`'s bottom, `Q`'s top and `Q`'s bottom: `[v_max, v_min, w_max, w_min]`.
    pub horizontal_extremes: [u64; 4],
    /// Touching or overlapping inputs, answered by the recursive split.
    pub meeting_inputs: u64,
    /// Nodes of the recursive split that were split.
    pub split_nodes: u64,
    /// Sub-problems of the recursive split answered by TENSTEP (certified separated).
    pub separated_nodes: u64,
    /// Sub-problems of the recursive split answered by brute force (small ones).
    pub brute_nodes: u64,
    /// Strictly separated sub-problems whose `O(log)` search found no certified bridge (split further).
    pub uncertified_separated_nodes: u64,
}

std::thread_local! {
    static COUNTS: Cell<VertexDistanceCounts> = const { Cell::new(VertexDistanceCounts {
        calls: 0, bridge_vertex_vertex: 0, bridge_edge_on_p: 0, bridge_edge_on_q: 0, small_scans: 0,
        cases: [0; 10], sub_cases_6: [0; 4], sub_cases_8: [0; 4], horizontal_extremes: [0; 4],
        meeting_inputs: 0, split_nodes: 0, separated_nodes: 0, brute_nodes: 0,
        uncertified_separated_nodes: 0,
    }) };
}

/// The [`VertexDistanceCounts`] accumulated on this thread. **Diagnostics only.**
///
/// The case numbers are those of McKenna and Toussaint (1985), §5, as reconstructed in
/// `docs/algorithms/vertex-distance.md`.
///
/// # Complexity
/// `O(1)`.
#[must_use]
pub fn vertex_distance_case_counts() -> VertexDistanceCounts {
    COUNTS.with(Cell::get)
}

/// Sets this thread's [`VertexDistanceCounts`] to zero. **Diagnostics only.**
///
/// See [`vertex_distance_case_counts`] (McKenna and Toussaint 1985, §5).
///
/// # Complexity
/// `O(1)`.
pub fn reset_vertex_distance_case_counts() {
    COUNTS.with(|c| c.set(VertexDistanceCounts::default()));
}

/// Updates this thread's counts.
pub(super) fn bump(f: impl FnOnce(&mut VertexDistanceCounts)) {
    COUNTS.with(|c| {
        let mut v = c.get();
        f(&mut v);
        c.set(v);
    });
}
