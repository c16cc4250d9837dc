//! The result side of an ODE solve: the solution with its statistics and termination,
//! and the typed errors.

/// One located event crossing.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// Position of the event in the `events` slice passed to [`solve`].
    pub index: usize,
    /// Time of the crossing.
    pub t: f64,
    /// State at the crossing, from the dense output.
    pub y: Vec<f64>,
}

/// Why integration stopped successfully.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Termination {
    /// `t_end` was reached.
    ReachedEnd,
    /// Terminal event `index` fired at time `t`.
    Event {
        /// Position of the event in the `events` slice.
        index: usize,
        /// Time of the crossing.
        t: f64,
    },
}

/// Work counters of one [`solve`] call.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OdeStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts (error too large, non-finite trial, singular matrix).
    pub rejected: usize,
    /// Calls of [`OdeSystem::rhs`], including those for finite-difference Jacobians.
    pub rhs_evaluations: usize,
    /// Jacobians formed (analytic or finite-difference).
    pub jacobian_evaluations: usize,
    /// LU decompositions of the Rosenbrock iteration matrix.
    pub lu_decompositions: usize,
    /// Time at which [`Method::Auto`] switched to the implicit method, if it did.
    pub switched_to_implicit_at: Option<f64>,
}

/// Result of a successful [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct OdeSolution {
    /// Output times, as selected by [`Output`].
    pub t: Vec<f64>,
    /// States at [`OdeSolution::t`], one `Vec` of length `dim` per time.
    pub y: Vec<Vec<f64>>,
    /// Time where integration stopped (`t_end`, or the terminal event time).
    pub t_final: f64,
    /// State at [`OdeSolution::t_final`].
    pub y_final: Vec<f64>,
    /// Event crossings in the order they occurred.
    pub events: Vec<EventRecord>,
    /// Work counters.
    pub stats: OdeStats,
    /// Why integration stopped.
    pub termination: Termination,
}

/// Why [`solve`] failed. Every variant carries the time reached.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OdeError {
    /// [`OdeOptions::max_steps`] step attempts were made without reaching the end.
    #[error("maximum number of step attempts ({steps}) reached at t = {t}")]
    MaxSteps {
        /// Step attempts made.
        steps: usize,
        /// Time reached.
        t: f64,
    },
    /// The step size fell below what the time resolution at `t` can represent
    /// (about 16 ulps of `t`): a singularity or a discontinuity.
    #[error("step size {h} too small at t = {t}")]
    StepTooSmall {
        /// Time reached.
        t: f64,
        /// Step size that was too small.
        h: f64,
    },
    /// The right-hand side (or its Jacobian) produced NaN or infinity at `t`, and
    /// shrinking the step did not avoid it.
    #[error("non-finite value in the state or right-hand side at t = {t}")]
    NonFinite {
        /// Time reached.
        t: f64,
    },
    /// The implicit method's matrix `(1/(hγ)) I − J` stayed singular after
    /// repeatedly halving the step.
    #[error("singular iteration matrix at t = {t} with step size {h}")]
    SingularMatrix {
        /// Time reached.
        t: f64,
        /// Last step size tried.
        h: f64,
    },
    /// The cancellation flag was set.
    #[error("cancelled at t = {t}")]
    Cancelled {
        /// Time reached.
        t: f64,
    },
    /// The problem or the options are malformed; nothing was integrated.
    #[error("invalid input: {what}")]
    InvalidInput {
        /// What is wrong.
        what: String,
    },
}

// ---------------------------------------------------------------------------
// Shared internals of the steppers.
