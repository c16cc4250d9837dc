//! Typed solver failures: every one carries the numbers a user needs to judge it.

use thiserror::Error;

/// Why a solve stopped without a trustworthy answer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    /// The bearing (ring) equilibrium did not converge.
    #[error("load distribution did not converge after {iterations} iterations (residual {residual_n:.3e} N, tolerance {tolerance_n:.3e} N)")]
    NotConverged {
        iterations: usize,
        residual_n: f64,
        tolerance_n: f64,
    },
    /// One roller's equilibrium did not converge.
    #[error("roller {roller} equilibrium did not converge after {iterations} iterations (residual {residual:.3e} N, tolerance {tolerance:.3e} N); a roller that neither raceway holds rests on the soft cage spring, and a stiffer one (solver.cage_stiffness_ratio) or more iterations (solver.max_roller_iterations) may let it settle")]
    RollerNotConverged {
        roller: usize,
        iterations: usize,
        residual: f64,
        tolerance: f64,
    },
    /// The solver declared convergence but a residual exceeds the deck's tolerance
    /// relative to the applied load (see `spherical_roller::converged`).
    #[error("the solution does not meet its tolerance: {what} residual {residual_n:.3e} N exceeds {allowed_n:.3e} N (solver.force_tolerance {force_tolerance:.1e} of the applied load {applied_n:.1} N)")]
    ResidualAboveTolerance {
        what: &'static str,
        residual_n: f64,
        allowed_n: f64,
        applied_n: f64,
        force_tolerance: f64,
    },
    /// A linear system could not be solved.
    #[error("singular matrix in {stage}")]
    Singular { stage: &'static str },
    /// A number became NaN or infinite.
    #[error("non-finite value in {stage}: {what}")]
    NonFinite { stage: &'static str, what: String },
    /// The solve was cancelled (a newer job superseded it).
    #[error("cancelled")]
    Cancelled,
    /// A stage failed for a reason the model reports.
    #[error("{stage}: {message}")]
    Stage {
        stage: &'static str,
        message: String,
    },
    /// One of the above, worded for the user in the deck's units
    /// ([`crate::units::restate_si`]).
    #[error("{0}")]
    InDeckUnits(String),
}

impl SolveError {
    /// The error with its SI numbers restated in `units` (cancellation stays itself).
    pub fn in_units(self, units: crate::units::Units) -> SolveError {
        match (self, units) {
            (SolveError::Cancelled, _) => SolveError::Cancelled,
            (e, crate::units::Units::Si) => e,
            (e, u) => SolveError::InDeckUnits(crate::units::restate_si(&e.to_string(), u)),
        }
    }
}
