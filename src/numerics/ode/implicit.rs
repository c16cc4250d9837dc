//! Rodas4: a 6-stage, order 4(3), L-stable, stiffly accurate Rosenbrock method
//! (E. Hairer and G. Wanner, *Solving Ordinary Differential Equations II*, 2nd ed.,
//! §IV.7, Table 7.3 and the code RODAS; coefficients in Hairer's transformed form).
//!
//! A Rosenbrock method is a linearly implicit Runge–Kutta method: every stage
//! solves a linear system with the same matrix `(1/(hγ)) I − J`, so a step costs one
//! LU decomposition, six triangular solves and no Newton iteration. All diagonal
//! coefficients are the same `γ = 1/4`, which is what the public `Method::Sdirk`
//! name alludes to.
//!
//! The transformed stage equations are, for `i = 1..6`,
//!
//! ```text
//! ((1/(hγ)) I − J) k_i = f(t + c_i h, y + Σ_{j<i} a_ij k_j) + Σ_{j<i} (g_ij / h) k_j + h d_i ∂f/∂t
//! ```
//!
//! with `y_new = y + Σ a_5j k_j + k5 + k6` and embedded (third-order) solution
//! `y + Σ a_5j k_j + k5`, so the error estimate is just `k6`.

use nalgebra::{DMatrix, DVector};

use super::{lincomb, Counted, OdeSystem, Tol, TrialError};

const GAMMA: f64 = 0.25;

// Stage abscissae (c5 = c6 = 1).
const C2: f64 = 0.386;
const C3: f64 = 0.21;
const C4: f64 = 0.63;

// Coefficients of h·∂f/∂t (d5 = d6 = 0).
const D1: f64 = 0.25;
const D2: f64 = -0.1043;
const D3: f64 = 0.1035;
const D4: f64 = -0.3620000000000023e-01;

// Stage arguments a_ij (row 6 is row 5 plus k5, the embedded solution).
const A21: f64 = 1.544;
const A31: f64 = 0.9466785280815826;
const A32: f64 = 0.2557011698983284;
const A41: f64 = 3.314825187068521;
const A42: f64 = 2.896124015972201;
const A43: f64 = 0.9986419139977817;
const A51: f64 = 1.221224509226641;
const A52: f64 = 6.019134481288629;
const A53: f64 = 12.53708332932087;
const A54: f64 = -0.687886036105895;

// Stage couplings g_ij (Hairer's C21..C65).
const G21: f64 = -5.6688;
const G31: f64 = -2.430093356833875;
const G32: f64 = -0.2063599157091915;
const G41: f64 = -0.1073529058151375;
const G42: f64 = -9.594562251023355;
const G43: f64 = -20.47028614809616;
const G51: f64 = 7.496443313967647;
const G52: f64 = -10.24680431464352;
const G53: f64 = -33.99990352819905;
const G54: f64 = 11.7089089320616;
const G61: f64 = 8.083246795921522;
const G62: f64 = -7.981132988064893;
const G63: f64 = -31.52159432874371;
const G64: f64 = 16.31930543123136;
const G65: f64 = -6.058818238834054;

/// Order of the embedded solution plus one: the step-size exponent is 1/4.
pub(crate) const ERROR_EXPONENT: f64 = 0.25;

/// Jacobian, stage storage and work vectors for Rodas4.
#[derive(Debug, Clone)]
pub(crate) struct Rodas4 {
    n: usize,
    jac: DMatrix<f64>,
    /// ∂f/∂t at the point where `jac` was formed.
    fx: Vec<f64>,
    /// Whether `jac`/`fx` belong to the current base point. A rejected step keeps
    /// them (only h changes); an accepted one invalidates them.
    jac_current: bool,
    k1: Vec<f64>,
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    k5: Vec<f64>,
    k6: Vec<f64>,
    ytmp: Vec<f64>,
    dy: Vec<f64>,
    b: DVector<f64>,
    f_new: Vec<f64>,
}

impl Rodas4 {
    pub(crate) fn new(n: usize) -> Self {
        Rodas4 {
            n,
            jac: DMatrix::zeros(n, n),
            fx: vec![0.0; n],
            jac_current: false,
            k1: vec![0.0; n],
            k2: vec![0.0; n],
            k3: vec![0.0; n],
            k4: vec![0.0; n],
            k5: vec![0.0; n],
            k6: vec![0.0; n],
            ytmp: vec![0.0; n],
            dy: vec![0.0; n],
            b: DVector::zeros(n),
            f_new: vec![0.0; n],
        }
    }

    /// Mark the Jacobian stale; the driver calls this after every accepted step.
    pub(crate) fn invalidate_jacobian(&mut self) {
        self.jac_current = false;
    }

    /// Form `J = ∂f/∂y` (analytic if the system provides it, otherwise forward
    /// differences) and `∂f/∂t` (always a forward difference, one extra rhs call;
    /// exact for autonomous systems). Rosenbrock methods lose order with an
    /// inexact Jacobian, so it is refreshed at every new base point.
    fn update_jacobian<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        t: f64,
        y: &[f64],
        f0: &[f64],
    ) -> Result<(), TrialError> {
        rhs.jac_evals += 1;
        // Zero first so a system that only writes the non-zero entries is correct.
        self.jac.fill(0.0);
        let provided = rhs.sys.jacobian(t, y, &mut self.jac);
        if self.jac.shape() != (self.n, self.n) {
            // The callee may replace the matrix; a wrong shape would make the
            // matrix arithmetic below panic, so restore it and report.
            let (rows, cols) = self.jac.shape();
            self.jac = DMatrix::zeros(self.n, self.n);
            return Err(TrialError::JacobianShape { rows, cols });
        }
        if provided {
            if !self.jac.iter().all(|v| v.is_finite()) {
                return Err(TrialError::NonFinite);
            }
        } else {
            lincomb(&mut self.ytmp, y, 0.0, &[]);
            for j in 0..self.n {
                let (Some(&yj), Some(slot)) = (y.get(j), self.ytmp.get_mut(j)) else {
                    break;
                };
                // Hairer's increment sqrt(u·max(1e-5, |y_j|)) balances truncation
                // against cancellation; using the representable difference removes
                // the rounding of y_j + δ from the quotient.
                let delta = (f64::EPSILON * yj.abs().max(1e-5)).sqrt();
                let yp = yj + delta;
                let delta = yp - yj;
                *slot = yp;
                if !rhs.eval(t, &self.ytmp, &mut self.dy) {
                    return Err(TrialError::NonFinite);
                }
                if let Some(slot) = self.ytmp.get_mut(j) {
                    *slot = yj;
                }
                for (jij, (&fp, &f)) in self
                    .jac
                    .column_mut(j)
                    .iter_mut()
                    .zip(self.dy.iter().zip(f0))
                {
                    *jij = (fp - f) / delta;
                }
            }
        }
        let dt = (f64::EPSILON * t.abs().max(1e-5)).sqrt();
        let tp = t + dt;
        let dt = tp - t;
        if !rhs.eval(tp, y, &mut self.dy) {
            return Err(TrialError::NonFinite);
        }
        for ((fx, &fp), &f) in self.fx.iter_mut().zip(&self.dy).zip(f0) {
            *fx = (fp - f) / dt;
        }
        self.jac_current = true;
        Ok(())
    }

    /// One trial step from `(t, y)` with `f0 = f(t, y)`, landing at `t_new`.
    /// Writes the fourth-order solution to `y_new` and returns the scaled RMS norm
    /// of the error estimate `k6`.
    #[allow(clippy::too_many_arguments)] // all are distinct step inputs
    pub(crate) fn step<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        t: f64,
        y: &[f64],
        f0: &[f64],
        h: f64,
        t_new: f64,
        y_new: &mut [f64],
        tol: Tol,
    ) -> Result<f64, TrialError> {
        if !self.jac_current {
            self.update_jacobian(rhs, t, y, f0)?;
        }
        let mut e = DMatrix::from_diagonal_element(self.n, self.n, 1.0 / (h * GAMMA));
        e -= &self.jac;
        rhs.lu_decompositions += 1;
        let lu = e.lu();
        if !lu.is_invertible() {
            return Err(TrialError::Singular);
        }
        let inv_h = 1.0 / h;
        let nonfinite = Err(TrialError::NonFinite);

        // Stage 1: f(t, y) is already known.
        lincomb(self.b.as_mut_slice(), f0, 1.0, &[(h * D1, &self.fx)]);
        if !solve_into(&lu, &mut self.b, &mut self.k1) {
            return Err(TrialError::Singular);
        }

        // Stage 2.
        lincomb(&mut self.ytmp, y, 1.0, &[(A21, &self.k1)]);
        if !rhs.eval(t + C2 * h, &self.ytmp, &mut self.dy) {
            return nonfinite;
        }
        lincomb(
            self.b.as_mut_slice(),
            &self.dy,
            1.0,
            &[(G21 * inv_h, &self.k1), (h * D2, &self.fx)],
        );
        if !solve_into(&lu, &mut self.b, &mut self.k2) {
            return Err(TrialError::Singular);
        }

        // Stage 3.
        lincomb(&mut self.ytmp, y, 1.0, &[(A31, &self.k1), (A32, &self.k2)]);
        if !rhs.eval(t + C3 * h, &self.ytmp, &mut self.dy) {
            return nonfinite;
        }
        lincomb(
            self.b.as_mut_slice(),
            &self.dy,
            1.0,
            &[
                (G31 * inv_h, &self.k1),
                (G32 * inv_h, &self.k2),
                (h * D3, &self.fx),
            ],
        );
        if !solve_into(&lu, &mut self.b, &mut self.k3) {
            return Err(TrialError::Singular);
        }

        // Stage 4.
        lincomb(
            &mut self.ytmp,
            y,
            1.0,
            &[(A41, &self.k1), (A42, &self.k2), (A43, &self.k3)],
        );
        if !rhs.eval(t + C4 * h, &self.ytmp, &mut self.dy) {
            return nonfinite;
        }
        lincomb(
            self.b.as_mut_slice(),
            &self.dy,
            1.0,
            &[
                (G41 * inv_h, &self.k1),
                (G42 * inv_h, &self.k2),
                (G43 * inv_h, &self.k3),
                (h * D4, &self.fx),
            ],
        );
        if !solve_into(&lu, &mut self.b, &mut self.k4) {
            return Err(TrialError::Singular);
        }

        // Stage 5 (c5 = 1, d5 = 0).
        lincomb(
            &mut self.ytmp,
            y,
            1.0,
            &[
                (A51, &self.k1),
                (A52, &self.k2),
                (A53, &self.k3),
                (A54, &self.k4),
            ],
        );
        if !rhs.eval(t_new, &self.ytmp, &mut self.dy) {
            return nonfinite;
        }
        lincomb(
            self.b.as_mut_slice(),
            &self.dy,
            1.0,
            &[
                (G51 * inv_h, &self.k1),
                (G52 * inv_h, &self.k2),
                (G53 * inv_h, &self.k3),
                (G54 * inv_h, &self.k4),
            ],
        );
        if !solve_into(&lu, &mut self.b, &mut self.k5) {
            return Err(TrialError::Singular);
        }

        // Stage 6 is evaluated at the embedded solution ytmp + k5 (c6 = 1, d6 = 0).
        for (yt, &k5) in self.ytmp.iter_mut().zip(&self.k5) {
            *yt += k5;
        }
        if !rhs.eval(t_new, &self.ytmp, &mut self.dy) {
            return nonfinite;
        }
        lincomb(
            self.b.as_mut_slice(),
            &self.dy,
            1.0,
            &[
                (G61 * inv_h, &self.k1),
                (G62 * inv_h, &self.k2),
                (G63 * inv_h, &self.k3),
                (G64 * inv_h, &self.k4),
                (G65 * inv_h, &self.k5),
            ],
        );
        if !solve_into(&lu, &mut self.b, &mut self.k6) {
            return Err(TrialError::Singular);
        }

        lincomb(y_new, &self.ytmp, 1.0, &[(1.0, &self.k6)]);
        let err = tol.norm(y, y_new, &self.k6);
        if err.is_finite() {
            Ok(err)
        } else {
            nonfinite
        }
    }

    /// Evaluate `f(t_new, y_new)` for an accepted step; it is the Hermite end slope
    /// and the next step's first stage. Returns `false` if it is not finite.
    pub(crate) fn finish<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        t_new: f64,
        y_new: &[f64],
    ) -> bool {
        rhs.eval(t_new, y_new, &mut self.f_new)
    }

    /// `f(t_new, y_new)` computed by [`Rodas4::finish`].
    pub(crate) fn f_new(&self) -> &[f64] {
        &self.f_new
    }
}

/// Solve `LU x = b` in place and copy `x` to `out`; `false` if the factorization
/// turned out singular.
fn solve_into(
    lu: &nalgebra::linalg::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
    b: &mut DVector<f64>,
    out: &mut [f64],
) -> bool {
    if !lu.solve_mut(b) {
        return false;
    }
    for (o, &v) in out.iter_mut().zip(b.iter()) {
        *o = v;
    }
    true
}
