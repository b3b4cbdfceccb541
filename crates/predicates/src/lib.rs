//! Exact geometric predicates for planar distance queries, behind three precision kernels.
//!
//! Every decision polydist's algorithms make (which side of a line, which of two points is nearer, which
//! of two vertex–edge distances is smaller) is the sign of a polynomial in the input coordinates. This
//! crate decides those signs under a [`Kernel`]:
//!
//! - [`Fast`]: plain `f64`. Fastest; may decide wrongly on near-degenerate input.
//! - [`Robust`] (the default everywhere): exact signs by adaptive evaluation. An inlined floating-point
//!   filter with a proved error bound decides almost every call; when it cannot (exact zeros and ties), an
//!   `f64` evaluation checked exact operation by operation ([`ErrorFree`]) decides on coarse inputs, and
//!   exact expansion arithmetic (Shewchuk 1997) runs only when that evaluation rounded.
//! - [`Exact`]: exact arithmetic for every sign, and exact rational constructions ([`exact`]).
//!
//! The named predicates are [`Kernel::orient`], [`Kernel::dot_sign`], [`Kernel::cross_sign`],
//! [`Kernel::cmp_dist`], [`Kernel::cmp_dist4`] and [`Kernel::cmp_dist2`]; algorithm-specific tests on
//! constructed points are written once as a [`Polynomial`] and decided by [`Kernel::sign`].
//! [`Counted`] wraps a kernel to count calls for complexity tests.
//!
//! Points are [`glam::DVec2`]. The Robust and Exact kernels are exact for every finite input (see
//! [`MAX_COORDINATE`] for the range polygons are validated against, which protects constructions).
//!
//! # Examples
//! ```
//! use glam::DVec2;
//! use polydist_predicates::{Fast, Kernel, Orientation, Robust};
//!
//! // Three points on the line y = x, the third one ulp above it: an exactly decidable left turn.
//! let a = DVec2::new(0.5, 0.5);
//! let b = DVec2::new(12.0, 12.0);
//! let c = DVec2::new(24.0, f64::from_bits(24.0f64.to_bits() + 1));
//! assert_eq!(Robust::orient(a, b, c), Orientation::CounterClockwise);
//! // Plain f64 evaluation is not guaranteed to see it.
//! let _maybe_wrong = Fast::orient(a, b, c);
//! ```

#![forbid(unsafe_code)]

mod counting;
pub mod crossing;
mod dd;
pub mod exact;
mod expansion;
mod kernel;
mod poly;
mod range;
mod ring;
mod sign;

pub use counting::{Counted, PredicateCounts, predicate_counts, reset_predicate_counts};
pub use crossing::{AtSites, Site, sign_at};
pub use dd::DoubleDouble;
pub use expansion::Expansion;
pub use kernel::{
    Cross, Dist2, Dist4, Dot, Exact, Fast, Kernel, Nearer, Orient, PerpVsPerp, PointsVsPerp, Robust,
};
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use poly::{Estimate, MAX_DEGREE, Polynomial, estimate_value, round_value};
pub use range::{MAX_COORDINATE, is_valid_coordinate};
pub use ring::{Bounded, ErrorFree, Ring};
pub use sign::{Orientation, Sign};
