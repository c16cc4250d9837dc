//! Solvers: load distribution (Newton on the lamina model), and the staged pipeline.

pub mod error;
pub mod load_distribution;

pub use error::SolveError;
