//! Separation of two polygonal chains separated by a line (Amato 1992, section 3), with exact
//! predicates and SMAWK.
//!
//! # Status
//! This crate holds the parts of N. M. Amato, "An optimal algorithm for determining the separation
//! of two nonintersecting simple polygons" (UIUC report UILU-ENG-92-2248, 1992) built so far:
//!
//! | item | what it is | status |
//! |---|---|---|
//! | [`closest_visible_vertices`] | CVV of two chains separated by a line and monotone along it: Lemma 2, `W()` by hull scans, Lemma 3, `R()`, the tagged matrix `M` and SMAWK, `O(n_p + n_q)` | done, tested against the brute force and the checker |
//! | [`CvvMatrix`], [`MatrixEntry`], [`compare_entries`] | the matrix `M` itself, for verification with `monotone_minima::check_totally_monotone_by` | done |
//! | [`closest_visible_vertices_brute`], [`separation_brute`] | brute-force twins (test references, benchmark baselines) | done |
//! | Lemma 2 for non-monotone chains (the perpendicular-visibility envelope), CVE, `σ` of two chains, chains with gaps, the disjoint-hull fast path for polygons | — | **not done**: see `docs/algorithms/separation.md` |
//!
//! # Numbers
//! Every decision is the sign of a degree-2 polynomial in the input coordinates (orientation,
//! dot and cross signs, squared-distance comparisons), decided by the kernel `K`. The matrix
//! entries are tagged ([`MatrixEntry`]) and compared exactly; no `f64` sentinel is used. Distances
//! are constructed once the pair is chosen: the exact squared distance rounded once, then its square
//! root (within 1 ulp).
#![forbid(unsafe_code)]

mod brute;
mod chain;
mod construct;
mod cve;
mod cvv;
mod error;
mod frame;
mod param;
mod pieces;
mod region;
mod result;
mod sigma;
mod wedge;

pub use brute::{closest_visible_vertices_brute, separation_brute};
pub use cve::{CveMatrix, EdgeEntry, compare_edge_entries};
pub use cvv::{CvvMatrix, MatrixEntry, closest_visible_vertices, compare_entries};
pub use error::{Chain, SeparationError};
pub use result::{ChainSeparation, ClosestPair, Cvv, CvvStats, SeparationStats};
pub use sigma::separation_of_chains;
