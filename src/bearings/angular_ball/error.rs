//! Typed failures of the ball bearing analysis; each carries the numbers a user needs.

use thiserror::Error;

use crate::physics::contact::point::PointContactError;

/// Why a ball bearing analysis stopped without a trustworthy answer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BallError {
    /// The input is outside the model's domain.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A Hertz contact could not be formed.
    #[error("Hertz contact ({race} race): {source}")]
    Contact {
        /// "inner" or "outer".
        race: &'static str,
        /// The contact model's reason.
        source: PointContactError,
    },
    /// One ball's force equilibrium (2-5a, b) did not converge.
    #[error("ball {number} equilibrium did not converge ({reason}) after {iterations} iterations (residual {residual_n:.3e} N, tolerance {tolerance_n:.3e} N)", number = .ball + 1)]
    BallNotConverged {
        /// 0-based ball index.
        ball: usize,
        /// How Newton stopped.
        reason: &'static str,
        /// Newton iterations.
        iterations: usize,
        /// Residual force, N.
        residual_n: f64,
        /// Tolerance, N.
        tolerance_n: f64,
    },
    /// The inner ring equilibrium (2-8) did not converge.
    #[error("ring equilibrium did not converge ({reason}) after {iterations} iterations (residual {residual_n:.3e} N, tolerance {tolerance_n:.3e} N)")]
    RingNotConverged {
        /// How Newton stopped.
        reason: &'static str,
        /// Newton iterations.
        iterations: usize,
        /// Residual force, N.
        residual_n: f64,
        /// Tolerance, N.
        tolerance_n: f64,
    },
    /// The fixed point between load distribution and race-control kinematics (centrifugal
    /// force, gyroscopic friction, contact stiffness at the operating angles) did not
    /// settle.
    #[error("load distribution and race control did not reach a fixed point after {iterations} iterations (last change {change:.3e} rad in a contact angle)")]
    FixedPointNotConverged {
        /// Fixed-point iterations.
        iterations: usize,
        /// Largest contact-angle change of the last iteration, rad.
        change: f64,
    },
    /// The race-control equations (2-9) are singular for these contact angles.
    #[error("race-control equations singular (contact angles {inner_deg:.3}° inner, {outer_deg:.3}° outer)")]
    SingularKinematics {
        /// Inner contact angle, degrees.
        inner_deg: f64,
        /// Outer contact angle, degrees.
        outer_deg: f64,
    },
    /// The skidding-threshold root search failed.
    #[error("skidding threshold: {0}")]
    Skid(String),
    /// The requested method is not implemented in this build.
    #[error("dynamics.method = \"{0}\" is not implemented yet (use \"race-control\")")]
    NotImplemented(&'static str),
    /// The ball dynamics (time simulation or quasi-static moment balance) failed.
    #[error("ball dynamics: {0}")]
    Dynamics(String),
    /// A result came out infinite or NaN (the inputs that made it are named).
    #[error("{0}")]
    NotFinite(String),
    /// Cancelled by the caller.
    #[error("cancelled")]
    Cancelled,
}
