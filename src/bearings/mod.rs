//! Bearing systems. Each system is one folder: its input, geometry, solver, solution and
//! view; what systems share lives below them (`crate::physics`, `crate::numerics`).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod error;
pub mod spherical_roller;

pub use error::SolveError;
