//! Newton's method for small dense systems (fixed dimension N, nalgebra `SVector<f64, N>`),
//! in the problem / solver / result style of argmin and diffsol:
//!
//! * the problem is a [`NewtonSystem`]: residual F(x), Jacobian J(x), and, where it has
//!   one, a potential whose gradient F is (then J is its Hessian and the line search
//!   decreases the potential itself);
//! * the solver is [`Newton`]: tolerance, iteration budget, a [`TrustRegion`] on the step
//!   and a [`Backtracking`] line search;
//! * the result is a [`NewtonResult`]: why it stopped ([`Termination`], with its numbers),
//!   the last accepted evaluation and the work done ([`NewtonStats`]).
//!
//! The pieces are usable on their own by iterations that do not fit the driver (an
//! evaluation that can fail, or that predicts the next state from the current one): the
//! safeguarded step solvers ([`newton_step2`], [`newton_step3`], [`ScaledCholesky`]), the
//! trust radius ([`TrustRegion`]) and the line search ([`Backtracking`]). They came out of
//! the spherical roller bearing's load distribution, whose results they must reproduce to
//! the last bit: the order of every floating-point operation is part of their contract.

// Every public item of this module must say what it computes.
#![warn(missing_docs)]

use nalgebra::{Cholesky, Const, Matrix2, Matrix3, SMatrix, SVector, Vector2, Vector3};

/// Cholesky factor of `m + μI` for the first shift μ of 0, μ₀, 10μ₀, 100μ₀, … (at most
/// `tries` shifts) that makes the matrix positive definite; `None` when none of them does.
///
/// The Newton step of an energy must descend it: where the Hessian is indefinite (a roller
/// lying across a raceway's crown) the shifted matrix gives a step between Newton's and
/// steepest descent.
#[inline]
pub fn shifted_cholesky<const N: usize>(
    m: &SMatrix<f64, N, N>,
    first_shift: f64,
    tries: usize,
) -> Option<Cholesky<f64, Const<N>>> {
    let mut mu = 0.0;
    for _ in 0..tries {
        let shifted = m + SMatrix::<f64, N, N>::identity() * mu;
        if let Some(ch) = shifted.cholesky() {
            return Some(ch);
        }
        mu = if mu == 0.0 { first_shift } else { mu * 10.0 };
    }
    None
}

/// Newton step −K⁻¹g for a 2×2 symmetric K, shifted to positive definite if needed.
///
/// Shifts start at 10⁻¹⁰·|tr K| (at least 10⁻³⁰), 60 tries; when none helps (K not
/// finite), steepest descent −g/|tr K| (|tr K| at least 10⁻³⁰).
#[inline]
pub fn newton_step2(k: &Matrix2<f64>, g: &Vector2<f64>) -> Vector2<f64> {
    let tr = k.trace().abs();
    match shifted_cholesky(k, (1e-10 * tr).max(1e-30), 60) {
        Some(ch) => -ch.solve(g),
        None => -g / tr.max(1e-30),
    }
}

/// Newton step −H⁻¹g for a symmetric H in scaled unknowns x = S·y, S = diag(`scale`), so
/// that unknowns of different units (a length and an angle) are compared on one footing;
/// shifted to positive definite if needed.
///
/// Shifts start at 10⁻¹⁰·|tr SHS| (|tr| at least 10⁻³⁰⁰), 40 tries; when none helps (H not
/// finite), steepest descent in the scaled unknowns, −S(Sg)/|tr SHS|.
#[inline]
pub fn scaled_newton_step<const N: usize>(
    h: &SMatrix<f64, N, N>,
    g: &SVector<f64, N>,
    scale: &SVector<f64, N>,
) -> SVector<f64, N> {
    let s = SMatrix::<f64, N, N>::from_diagonal(scale);
    let hs = s * h * s;
    let gs = s * g;
    let tr = hs.trace().abs().max(1e-300);
    match shifted_cholesky(&hs, 1e-10 * tr, 40) {
        Some(ch) => s * (-ch.solve(&gs)),
        // H indefinite beyond repair: steepest descent scaled by the trace.
        None => s * (-gs / tr),
    }
}

/// Newton step −H⁻¹g for a 3×3 symmetric H, shifted to positive definite if needed:
/// [`scaled_newton_step`] in three unknowns.
#[inline]
pub fn newton_step3(h: &Matrix3<f64>, g: &Vector3<f64>, scale: &Vector3<f64>) -> Vector3<f64> {
    scaled_newton_step(h, g, scale)
}

/// A symmetric N×N matrix factored once, in scaled unknowns and shifted to positive definite
/// like [`scaled_newton_step`], for several solves against it (a Schur complement's
/// condensation); `None` inside when no shift helps, and then every solve gives zero.
#[derive(Debug, Clone)]
pub struct ScaledCholesky<const N: usize>(Option<(Cholesky<f64, Const<N>>, SMatrix<f64, N, N>)>);

/// [`ScaledCholesky`] of a 3×3 matrix.
pub type Factor3 = ScaledCholesky<3>;

impl<const N: usize> ScaledCholesky<N> {
    /// Factor `h` in the unknowns scaled by `scale` (S = diag(`scale`)).
    #[inline]
    pub fn new(h: &SMatrix<f64, N, N>, scale: &SVector<f64, N>) -> Self {
        let s = SMatrix::<f64, N, N>::from_diagonal(scale);
        let hs = s * h * s;
        let tr = hs.trace().abs().max(1e-300);
        ScaledCholesky(shifted_cholesky(&hs, 1e-10 * tr, 40).map(|ch| (ch, s)))
    }

    /// Whether a (possibly shifted) factor exists; without one every solve gives zero.
    pub fn is_factored(&self) -> bool {
        self.0.is_some()
    }

    /// X = H⁻¹B (H as shifted), B with any number of columns (a vector is one).
    #[inline]
    pub fn solve<const M: usize>(&self, b: &SMatrix<f64, N, M>) -> SMatrix<f64, N, M> {
        match &self.0 {
            Some((ch, s)) => s * ch.solve(&(s * b)),
            None => SMatrix::<f64, N, M>::zeros(),
        }
    }
}

/// Step length limiter (trust radius) of a damped Newton iteration: a step longer than the
/// radius is cut back to it ([`TrustRegion::cap`]); after the line search, a full step that
/// had been cut grows the radius fourfold (up to `max_radius`), a backtracked step shrinks it
/// to the length actually taken (down to `min_radius`), and a full uncut step leaves it
/// ([`TrustRegion::update`]). The length is whatever norm the caller measures steps in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrustRegion {
    /// Current radius, in the caller's step norm.
    pub radius: f64,
    /// Smallest radius a backtracked step shrinks it to.
    pub min_radius: f64,
    /// Largest radius a full capped step grows it to.
    pub max_radius: f64,
}

impl TrustRegion {
    /// A trust region starting at `radius`, kept within [`min_radius`, `max_radius`] by
    /// [`TrustRegion::update`].
    ///
    /// [`min_radius`]: TrustRegion::min_radius
    /// [`max_radius`]: TrustRegion::max_radius
    pub fn new(radius: f64, min_radius: f64, max_radius: f64) -> Self {
        TrustRegion {
            radius,
            min_radius,
            max_radius,
        }
    }

    /// The step cut back to the radius when its length `len` exceeds it, and whether it was.
    #[inline]
    pub fn cap<const N: usize>(&self, step: SVector<f64, N>, len: f64) -> (SVector<f64, N>, bool) {
        cap_step(step, len, self.radius)
    }

    /// Adapt the radius to the line search's outcome: `lambda` the accepted fraction of the
    /// (capped) step, `len` the uncapped step's length, `capped` whether it was cut.
    #[inline]
    pub fn update(&mut self, lambda: f64, len: f64, capped: bool) {
        if lambda == 1.0 && capped {
            self.radius = (self.radius * 4.0).min(self.max_radius);
        } else if lambda < 1.0 {
            // Shrink to the step actually taken (len is the uncapped Newton length).
            self.radius = (lambda * len.min(self.radius)).max(self.min_radius);
        }
    }
}

/// `step` (of length `len`) scaled down to length `radius` if longer, and whether it was.
#[inline]
pub fn cap_step<const N: usize>(
    step: SVector<f64, N>,
    len: f64,
    radius: f64,
) -> (SVector<f64, N>, bool) {
    if len > radius {
        (step * (radius / len), true)
    } else {
        (step, false)
    }
}

/// Backtracking line search along a Newton step: trial fractions λ = 1, ½, ¼, … (at most
/// `max_trials`), the first acceptable one wins.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Backtracking {
    /// Largest number of trial fractions (40 reaches 2⁻³⁹ of the step).
    pub max_trials: usize,
    /// Armijo's sufficient-decrease constant c in merit(λ) < merit(0) + c·λ·slope.
    pub armijo: f64,
}

impl Default for Backtracking {
    /// 40 trials, c = 10⁻⁴.
    fn default() -> Self {
        Backtracking {
            max_trials: 40,
            armijo: 1e-4,
        }
    }
}

impl Backtracking {
    /// The acceptance test of a trial at fraction `lambda`: Armijo's sufficient decrease of
    /// the merit, without round-off slack, or the residual norm halved. Near convergence the
    /// merit's differences drown in round-off and the residual test decides.
    #[inline]
    pub fn accepts(
        &self,
        merit0: f64,
        slope: f64,
        residual0: f64,
        lambda: f64,
        merit: f64,
        residual: f64,
    ) -> bool {
        let ok_merit = merit < merit0 + self.armijo * lambda * slope;
        let ok_residual = residual < 0.5 * residual0;
        ok_merit || ok_residual
    }

    /// Try λ = 1, ½, ¼, …: `trial(λ)` evaluates the trial and returns it if acceptable.
    /// Returns the accepted λ and trial, `None` when no trial was acceptable.
    #[inline]
    pub fn search<T>(&self, mut trial: impl FnMut(f64) -> Option<T>) -> Option<(f64, T)> {
        let mut lambda = 1.0;
        for _ in 0..self.max_trials {
            if let Some(t) = trial(lambda) {
                return Some((lambda, t));
            }
            lambda *= 0.5;
        }
        None
    }

    /// [`Backtracking::search`] with an evaluation that can fail: the first error ends the
    /// search and is returned.
    #[inline]
    pub fn try_search<T, E>(
        &self,
        mut trial: impl FnMut(f64) -> Result<Option<T>, E>,
    ) -> Result<Option<(f64, T)>, E> {
        let mut lambda = 1.0;
        for _ in 0..self.max_trials {
            if let Some(t) = trial(lambda)? {
                return Ok(Some((lambda, t)));
            }
            lambda *= 0.5;
        }
        Ok(None)
    }
}

/// Why a Newton iteration stopped, with the numbers that say how far it got. Iterations
/// count Newton steps attempted; residuals are in the system's residual norm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Termination {
    /// The residual norm met the tolerance after `iterations` steps.
    Converged {
        /// Newton steps taken.
        iterations: usize,
        /// Residual norm at the solution.
        residual: f64,
    },
    /// The iteration budget ran out with the residual above the tolerance.
    NotConverged {
        /// Newton steps taken (the budget).
        iterations: usize,
        /// Residual norm of the last iterate.
        residual: f64,
        /// The tolerance it missed.
        tolerance: f64,
    },
    /// The line search accepted no fraction of the Newton step: no descent even at the
    /// smallest trial. Near convergence this means the residual is at round-off level.
    Stalled {
        /// Newton steps attempted, the failed one included.
        iterations: usize,
        /// Residual norm of the last accepted iterate.
        residual: f64,
    },
    /// The Newton step could not be solved for: J singular at this iteration (0-based).
    SingularJacobian {
        /// Iteration (0-based) whose Jacobian was singular.
        iteration: usize,
    },
    /// The residual norm became NaN or infinite at this iteration (0-based).
    NonFinite {
        /// Iteration (0-based) whose residual was not finite.
        iteration: usize,
    },
    /// The system asked to stop ([`NewtonSystem::cancelled`]) before this iteration (0-based).
    Cancelled {
        /// Iteration (0-based) at which the stop was seen.
        iteration: usize,
    },
}

impl Termination {
    /// Whether the residual met the tolerance.
    pub fn is_converged(&self) -> bool {
        matches!(self, Termination::Converged { .. })
    }

    /// Newton steps attempted (for the variants that stop at an iteration, that iteration).
    pub fn iterations(&self) -> usize {
        match *self {
            Termination::Converged { iterations, .. }
            | Termination::NotConverged { iterations, .. }
            | Termination::Stalled { iterations, .. } => iterations,
            Termination::SingularJacobian { iteration }
            | Termination::NonFinite { iteration }
            | Termination::Cancelled { iteration } => iteration,
        }
    }

    /// Residual norm of the last accepted iterate, where the variant records one.
    pub fn residual(&self) -> Option<f64> {
        match *self {
            Termination::Converged { residual, .. }
            | Termination::NotConverged { residual, .. }
            | Termination::Stalled { residual, .. } => Some(residual),
            _ => None,
        }
    }
}

/// Work counters of one Newton solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct NewtonStats {
    /// Newton steps attempted.
    pub iterations: usize,
    /// System evaluations (the initial one and every line-search trial).
    pub evaluations: usize,
}

/// A square nonlinear system F(x) = 0 in N unknowns, as [`Newton`] sees it.
///
/// The defaults treat a general system: merit ½|F|², its slope (JᵀF)·step, the step
/// through J⁻¹ (a singular J ends the solve), Euclidean step length, max-norm residual. A gradient system
/// F = ∇Π (an equilibrium as the minimum of a potential energy) overrides [`merit`] with Π
/// and [`slope`] with F·step, and usually [`newton_step`] with a shifted Cholesky step
/// ([`scaled_newton_step`]) that always descends.
///
/// [`merit`]: NewtonSystem::merit
/// [`slope`]: NewtonSystem::slope
/// [`newton_step`]: NewtonSystem::newton_step
pub trait NewtonSystem<const N: usize> {
    /// Everything one evaluation gives: at least F and J, and whatever the caller wants to
    /// keep from the accepted iterate (it is returned in [`NewtonResult::eval`]).
    type Eval;

    /// Evaluate the system at `x`.
    fn evaluate(&mut self, x: &SVector<f64, N>) -> Self::Eval;

    /// The residual F of an evaluation.
    fn residual<'e>(&self, e: &'e Self::Eval) -> &'e SVector<f64, N>;

    /// The Jacobian J = ∂F/∂x of an evaluation.
    fn jacobian<'e>(&self, e: &'e Self::Eval) -> &'e SMatrix<f64, N, N>;

    /// The norm the tolerance applies to; max |Fᵢ| by default.
    #[inline]
    fn residual_norm(&self, f: &SVector<f64, N>) -> f64 {
        f.amax()
    }

    /// The merit the line search decreases; ½|F|² by default.
    #[inline]
    fn merit(&self, e: &Self::Eval) -> f64 {
        0.5 * self.residual(e).norm_squared()
    }

    /// The merit's slope along `step` at `e`; (JᵀF)·step by default.
    #[inline]
    fn slope(&self, e: &Self::Eval, step: &SVector<f64, N>) -> f64 {
        (self.jacobian(e).transpose() * self.residual(e)).dot(step)
    }

    /// The Newton step, J·step = −F; `None` when J is singular. By default through J⁻¹
    /// (nalgebra's closed forms up to 4×4, LU beyond), `None` at a zero determinant.
    #[inline]
    fn newton_step(&self, e: &Self::Eval) -> Option<SVector<f64, N>> {
        let inverse = self.jacobian(e).try_inverse()?;
        Some(-(inverse * self.residual(e)))
    }

    /// A step's length as the trust region measures it; Euclidean by default.
    #[inline]
    fn step_length(&self, step: &SVector<f64, N>) -> f64 {
        step.norm()
    }

    /// Called at the start of every iteration (0-based) with the iterate and its
    /// evaluation, before the convergence test (traces, plots); does nothing by default.
    #[inline]
    fn observe(&mut self, _iteration: usize, _x: &SVector<f64, N>, _e: &Self::Eval) {}

    /// Polled at the start of every iteration: `true` stops with
    /// [`Termination::Cancelled`]. Never by default.
    #[inline]
    fn cancelled(&self) -> bool {
        false
    }
}

/// Damped Newton with a trust radius and a backtracking line search, for a
/// [`NewtonSystem`] of fixed small dimension.
///
/// Each iteration: stop if the residual norm is at most `tolerance`; else solve the Newton
/// step, cut it to the trust radius, backtrack along it until [`Backtracking::accepts`] a
/// trial (that trial's evaluation is the next iterate's: one evaluation per step when the
/// full step is taken), and adapt the radius ([`TrustRegion::update`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Newton {
    /// Largest number of Newton steps.
    pub max_iterations: usize,
    /// Residual norm at which the iterate is converged.
    pub tolerance: f64,
    /// The trust region each solve starts from.
    pub trust: TrustRegion,
    /// The line search.
    pub line_search: Backtracking,
}

/// What one [`Newton::solve`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct NewtonResult<E> {
    /// Why it stopped.
    pub termination: Termination,
    /// The evaluation at the last accepted iterate (the solution when converged).
    pub eval: E,
    /// Work done.
    pub stats: NewtonStats,
}

impl Newton {
    /// Solve `system` from `x`; `x` is left at the last accepted iterate, however the solve
    /// ended.
    ///
    /// `#[inline]`: a hot caller (the spherical roller's per-roller equilibrium, millions of
    /// solves in the benches) gets the driver and its system's evaluation optimised
    /// together; called out of line, the load distribution ran 3–7 % slower.
    #[inline]
    pub fn solve<const N: usize, S: NewtonSystem<N>>(
        &self,
        system: &mut S,
        x: &mut SVector<f64, N>,
    ) -> NewtonResult<S::Eval> {
        let mut stats = NewtonStats {
            iterations: 0,
            evaluations: 1,
        };
        let mut trust = self.trust;
        // The accepted trial of the line search is the next iterate's evaluation.
        let mut ev = system.evaluate(x);
        let done = |termination, eval, stats| NewtonResult {
            termination,
            eval,
            stats,
        };
        for it in 0..self.max_iterations {
            if system.cancelled() {
                return done(Termination::Cancelled { iteration: it }, ev, stats);
            }
            system.observe(it, x, &ev);
            let res = system.residual_norm(system.residual(&ev));
            if !res.is_finite() {
                return done(Termination::NonFinite { iteration: it }, ev, stats);
            }
            if res <= self.tolerance {
                let t = Termination::Converged {
                    iterations: it,
                    residual: res,
                };
                return done(t, ev, stats);
            }
            stats.iterations += 1;
            let Some(step) = system.newton_step(&ev) else {
                return done(Termination::SingularJacobian { iteration: it }, ev, stats);
            };
            let len = system.step_length(&step);
            let (step, capped) = trust.cap(step, len);
            let slope = system.slope(&ev, &step);
            let merit0 = system.merit(&ev);
            // The line search of `self.line_search`, written out so that the accepted trial's
            // evaluation moves straight into the iterate's (no Option wrapping per trial: the
            // evaluation can be large, and this loop runs millions of times).
            let mut lambda = 1.0;
            let mut accepted = false;
            for _ in 0..self.line_search.max_trials {
                let trial = *x + lambda * step;
                let e2 = system.evaluate(&trial);
                stats.evaluations += 1;
                let r2 = system.residual_norm(system.residual(&e2));
                let merit = system.merit(&e2);
                if self
                    .line_search
                    .accepts(merit0, slope, res, lambda, merit, r2)
                {
                    *x = trial;
                    ev = e2;
                    accepted = true;
                    break;
                }
                lambda *= 0.5;
            }
            if !accepted {
                let t = Termination::Stalled {
                    iterations: it + 1,
                    residual: res,
                };
                return done(t, ev, stats);
            }
            trust.update(lambda, len, capped);
        }
        let residual = system.residual_norm(system.residual(&ev));
        // The last step's iterate is tested like every other: one that meets the
        // tolerance is converged (before, it was reported as a failure whose residual was
        // below its own tolerance).
        if residual <= self.tolerance {
            let t = Termination::Converged {
                iterations: self.max_iterations,
                residual,
            };
            return done(t, ev, stats);
        }
        let t = Termination::NotConverged {
            iterations: self.max_iterations,
            residual,
            tolerance: self.tolerance,
        };
        done(t, ev, stats)
    }
}

#[cfg(test)]
mod tests;
