//! Separation of simple polygons (Amato 1992): the distance between two boundaries with a realizing
//! pair, decided with exact predicates and SMAWK.
//!
//! # Examples
//! ```
//! use glam::DVec2;
//! use polydist_polygon::{Feature, SimplePolygon, predicates::Robust};
//! use polydist_separation::{PolygonSeparation, Route, separation};
//!
//! // A U-shaped lot opening to the west and an L-shaped lot west of it: the U's pocket faces the L,
//! // so its hull edge there is a lid and section 3 runs across a line through a hull edge.
//! let u = [[50.0, 0.0], [90.0, 0.0], [90.0, 40.0], [50.0, 40.0], [50.0, 30.0], [75.0, 30.0], [75.0, 10.0], [50.0, 10.0]];
//! let l = [[0.0, 0.0], [40.0, 0.0], [40.0, 15.0], [15.0, 15.0], [15.0, 40.0], [0.0, 40.0]];
//! let (u, l) = (SimplePolygon::try_from(&u[..])?, SimplePolygon::try_from(&l[..])?);
//! let PolygonSeparation::Separated { pair, route, .. } = separation::<Robust>(&l, &u).unwrap() else {
//!     panic!("the lots are disjoint");
//! };
//! assert_eq!(pair.distance, 10.0);
//! assert!(matches!(route, Route::HullFeatures | Route::MonotoneSweep | Route::SeparableChains));
//! # Ok::<(), polydist_polygon::PolygonError>(())
//! ```
//!
//! # Status
//! This crate holds the parts of N. M. Amato, "An optimal algorithm for determining the separation
//! of two nonintersecting simple polygons" (UIUC report UILU-ENG-92-2248, 1992) built so far:
//!
//! | item | what it is | status |
//! |---|---|---|
//! | [`separation_of_chains`] | σ of two simple chains separated by a line, open or closed (a whole polygon boundary is passed with its first vertex repeated at the end), with a realizing pair and caller features: Lemma 2's envelope, then CVV + CVE (both ways) | done; `O(n)` (the on-line pair's sort aside: `O(k log k)` for the `k` vertices on the line); agrees with the exact oracle, every test matrix checked for total monotonicity |
//! | [`separation_of_chains_with`] with [`ChainMethod::Auto`] (the method of every polygon route) | our addition before section 3's matrices: the exact windowed scan of the monotone sweep on Lemma 2's two envelopes, which are monotone along the line whatever the chains are (visible vertices against the whole edges carrying the envelope: no constructed point), within `96N + 1024` candidates | done (2026-12-01); `O(N)`, the matrices when the budget runs out (`docs/algorithms/separation.md`, "The envelope sweep"); [`Route::EnvelopeSweep`] on the disjoint-hull route |
//! | [`perpendicular_envelope`] | Lemma 2: the part of a simple chain perpendicularly visible from the line (visible vertices, edges, symbolic shadow points), by one walk along the chain | done; `O(n)` |
//! | [`closest_visible_vertices`] | CVV of two chains separated by a line and monotone along it (edges perpendicular to the line allowed): Lemma 2, `W()` by hull scans, Lemma 3, `R()`, the tagged matrix `M` and SMAWK, `O(n_p + n_q)` | done (monotone chains only: the CVV of general chains is not that of their envelopes) |
//! | [`CvvMatrix`], [`CveMatrix`], [`MatrixEntry`], [`EdgeEntry`], [`compare_entries`], [`compare_edge_entries`] | the matrices `M` themselves, for verification with `monotone_minima::check_totally_monotone_by` | done |
//! | [`closest_visible_vertices_brute`], [`separation_brute`], [`perpendicular_envelope_brute`] | brute-force twins (test references, benchmark baselines) | done |
//! | [`separation`], [`separation_of_disjoint`], [`intersection`], [`polygon_separation_brute`] | whole simple polygons: the exact intersection check (`O(N log N)`, only when the hulls meet), the disjoint-hull route (hull features, or section 3 on both boundaries across a line through a hull edge) | done for disjoint hulls |
//! | [`Route::MonotoneSweep`] (inside [`separation`], [`separation_of_disjoint`], [`polyline_to_polygon`]) | our addition before section 3 on the disjoint-hull route: when both facing chains are monotone along the separating line, an exact windowed scan, thinned by depth across the line, answers within `96N + 1024` candidates (also on the separator's subproblems whose parts are monotone along their line); [`separation_of_disjoint_with`] with [`HullRouteMethod::Section3`] skips it | done; `O(N)`, section 3 when it declines (`docs/algorithms/separation-polygons.md`, "The monotone sweep") |
//! | [`Route::Separators`] (inside [`separation`]) | section 2's separator `S(P, Q)` when the hulls meet: facing chains, the pockets of each wall that the other never enters cut off, the reduced region's triangulation, the geodesic, two-sided extensions, greedy pruning, report 001's subchains, then `σ(P_i, Q_i)` | done for the non-containing case, the pinched channel and the containing case (two passes over the annulus cut open, at its top and at its bottom, sharing their triangulated halves, each answering for the pairs whose `Q` point lies on its side of `P`'s top level), checked against properties (i)–(iv), (v) for vertices, monotone cuts and Lemma 1 (for every vertex–vertex sight on small cases) by an `O(N²)` checker; each subproblem goes to section 3 across its line (crossing end edges peeled, or pairs of runs when there are at most 4 runs and 8 crossing edges per chain, otherwise section 3 once per assignment of sides on the subchains clipped to the line: gapped chains, run last with the best answer of all the others as their cut); small ones (at most 256 vertex pairs) are scanned, and so is a subproblem section 3 rejects (only under the Fast kernel in our tests); end edges deeper than the best answer so far are trimmed first and the scans skip pairs that cannot beat it, and the pairs the previous subproblem's scan took |
//! | [`triangulate`](fn@triangulate), [`shortest_path`], [`first_hit`], [`extensions`] | exact triangulation of a simple polygon with collinear vertices (`O(n log n)`), geodesics by the funnel, ray-shooting arms (one walk each, or every arm of a shortest-path tree in `O(n)`) | done (`docs/algorithms/triangulation.md`) |
//! | [`point_to_polygon`], [`segment_to_polygon`] | a point or a segment against a simple polygon, `O(n)` | done |
//! | [`polyline_to_polygon`] | an open simple polyline (a toolpath) against a simple polygon | done when the hulls are disjoint (section 3 on the open chain); hulls that meet are [`SeparationError::PolylineHullsMeet`] (the separator needs two polygons) |
//! | lines touched by both chains | section 3 adds the nearest pair of vertices on the line (a sort) to the wedges' candidates | done (2026-11-26) |
//! | chains with gaps (Step G: runs clipped to a line, ending at symbolic clip points) | section 3 on two gapped chains inside the separator's subproblems: every predicate at a clip point decided exactly by `polydist_predicates::sign_at`, pairs with a clip point handed back as pairs of the crossing edge | done (2026-11-28), crate-internal; `O(n log k)` for `k` runs (the runs' envelopes merged in a balanced tree; a linear merge is not built): `docs/algorithms/separator.md`, "Step G" |
//!
//! Lemma 2 reduces general chains to the setting in which the paper states Lemmas 4–7: a chain
//! monotone along the line (the envelope, with perpendicular jumps at shadow points).
//!
//! # Chains
//! Edge `i` joins vertices `i` and `i + 1`. Repeated consecutive vertices are dropped (reported
//! indices are the first of a repeat). A chain whose last vertex equals its first (at least three
//! distinct vertices) is closed: a polygon `v_0, …, v_{n−1}` is passed as `v_0, …, v_{n−1}, v_0`; its
//! closing edge is reported as `Edge(n − 1)` and the repeated vertex as `Vertex(0)`. Chains must be
//! simple (the caller's duty; violations met on the way are [`SeparationError::NotSimple`]).
//!
//! # Numbers
//! Every decision is the sign of a polynomial of degree at most 10 in the input coordinates,
//! decided by the kernel `K`: degree 2 for orientation, dot and cross signs, the envelope and
//! vertex–vertex comparisons; 4 for the order of two constructed points on an edge and for the
//! discriminant of the `α ≥ 90°` arc; 6 for a constructed point against an arc end and for
//! vertex–edge distance comparisons; 6 to 10 for distances to an edge's part ending at a shadow point
//! (rows of the CVE matrix whose edge passes behind a visible vertex). Constructed points (shadow
//! points, edge breakpoints, arc ends, the points `u^±` on edges) are never rounded to floats for a
//! decision. The matrix entries are tagged ([`MatrixEntry`]) and compared exactly; no `f64` sentinel is used. Distances
//! are constructed once the pair is chosen: the exact squared distance rounded once, then its square
//! root (within 1 ulp).
#![forbid(unsafe_code)]

mod brute;
mod chain;
mod clipped;
mod construct;
mod cve;
mod cvv;
mod envelope;
mod error;
mod frame;
mod gapped;
mod geodesic;
mod monotone;
mod param;
mod pieces;
mod pockets;
mod polygon;
mod polyline;
mod region;
mod result;
mod separator;
mod sigma;
mod simple_distance;
mod site;
mod spm;
mod triangulate;
mod wedge;

pub use brute::{closest_visible_vertices_brute, separation_brute};
pub use clipped::EdgePart;
pub use cve::{CveMatrix, EdgeEntry, compare_edge_entries};
pub use cvv::{CvvMatrix, MatrixEntry, closest_visible_vertices, compare_entries};
pub use envelope::{Envelope, perpendicular_envelope, perpendicular_envelope_brute};
pub use error::{Chain, SeparationError};
pub use geodesic::{
    Hit, first_hit, first_hit_brute, segment_in_polygon, shortest_path, shortest_path_brute,
};
pub use polygon::{
    BoundaryPiece, HullRouteMethod, Intersection, PolygonSeparation, Route, intersection,
    polygon_separation_brute, separation, separation_of_disjoint, separation_of_disjoint_with,
};
pub use polyline::polyline_to_polygon;
pub use result::{ChainSeparation, ClosestPair, Cvv, CvvStats, SeparationStats};
pub use sigma::{ChainMethod, separation_of_chains, separation_of_chains_with};
pub use simple_distance::{BoundaryPoint, PointToPolygon, point_to_polygon, segment_to_polygon};
pub use site::Vertex;
pub use spm::{Extensions, extensions};
pub use triangulate::{
    Neighbor, Triangulation, TriangulationError, triangulate, triangulate_brute,
};
