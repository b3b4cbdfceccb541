//! Seeded generators of hard inputs (the crate re-exports everything; the
//! brief's `gen` module name is a reserved keyword in edition 2024).

pub(crate) mod convex;
pub(crate) mod lattice;
pub(crate) mod pairs;
pub(crate) mod precision;
pub(crate) mod rng;
pub(crate) mod simple;
