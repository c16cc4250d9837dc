//! Solvers: load distribution (Newton on the lamina model), and the staged pipeline.

pub mod contacts;
pub mod error;
pub mod load_distribution;
pub mod pipeline;
pub mod stages;

pub use error::SolveError;
