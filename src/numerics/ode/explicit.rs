//! Dormand–Prince 5(4) explicit Runge–Kutta pair ("DOPRI5").
//!
//! Coefficients from J. R. Dormand and P. J. Prince, *A family of embedded
//! Runge–Kutta formulae*, J. Comput. Appl. Math. 6 (1980), and the continuous
//! extension and stiffness test from E. Hairer, S. P. Nørsett and G. Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., §II.5–II.6 and §IV.2 of
//! volume II. The fifth-order solution is propagated (local extrapolation) and the
//! last stage is f at the new point, so it doubles as the next step's first stage
//! (FSAL): six right-hand-side evaluations per step.

use super::dense::Interpolant;
use super::{lincomb, scaled_sum, Counted, OdeSystem, Tol, TrialError};

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;

const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// Row 7 equals the fifth-order weights b (FSAL property).
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;

// e = b − b̂: difference between the fifth- and fourth-order weights.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

// Quartic correction of the dense output (Hairer, Nørsett & Wanner I, §II.6).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Order of the embedded error estimate plus one: the step-size exponent is 1/5.
pub(crate) const ERROR_EXPONENT: f64 = 0.2;

/// Stage storage for DOPRI5. The first stage `k1 = f(t, y)` is owned by the
/// driver, which keeps it from the previous step's last stage.
#[derive(Debug, Clone)]
pub(crate) struct Dopri5 {
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    k5: Vec<f64>,
    k6: Vec<f64>,
    k7: Vec<f64>,
    /// Argument of stage 6; kept because the stiffness test compares it with y_new.
    ysti: Vec<f64>,
    yerr: Vec<f64>,
}

impl Dopri5 {
    pub(crate) fn new(n: usize) -> Self {
        Dopri5 {
            k2: vec![0.0; n],
            k3: vec![0.0; n],
            k4: vec![0.0; n],
            k5: vec![0.0; n],
            k6: vec![0.0; n],
            k7: vec![0.0; n],
            ysti: vec![0.0; n],
            yerr: vec![0.0; n],
        }
    }

    /// One trial step from `(t, y)` with `f0 = f(t, y)` and step `h`, landing at
    /// `t_new` (passed separately so the last step hits `t_end` bit-exactly).
    /// Writes the fifth-order solution to `y_new` and returns the scaled RMS norm
    /// of the local error estimate (≤ 1 means acceptable).
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
        let nonfinite = Err(TrialError::NonFinite);
        lincomb(&mut self.ysti, y, h, &[(A21, f0)]);
        if !rhs.eval(t + C2 * h, &self.ysti, &mut self.k2) {
            return nonfinite;
        }
        lincomb(&mut self.ysti, y, h, &[(A31, f0), (A32, &self.k2)]);
        if !rhs.eval(t + C3 * h, &self.ysti, &mut self.k3) {
            return nonfinite;
        }
        lincomb(
            &mut self.ysti,
            y,
            h,
            &[(A41, f0), (A42, &self.k2), (A43, &self.k3)],
        );
        if !rhs.eval(t + C4 * h, &self.ysti, &mut self.k4) {
            return nonfinite;
        }
        lincomb(
            &mut self.ysti,
            y,
            h,
            &[(A51, f0), (A52, &self.k2), (A53, &self.k3), (A54, &self.k4)],
        );
        if !rhs.eval(t + C5 * h, &self.ysti, &mut self.k5) {
            return nonfinite;
        }
        lincomb(
            &mut self.ysti,
            y,
            h,
            &[
                (A61, f0),
                (A62, &self.k2),
                (A63, &self.k3),
                (A64, &self.k4),
                (A65, &self.k5),
            ],
        );
        if !rhs.eval(t_new, &self.ysti, &mut self.k6) {
            return nonfinite;
        }
        lincomb(
            y_new,
            y,
            h,
            &[
                (A71, f0),
                (A73, &self.k3),
                (A74, &self.k4),
                (A75, &self.k5),
                (A76, &self.k6),
            ],
        );
        if !rhs.eval(t_new, y_new, &mut self.k7) {
            return nonfinite;
        }
        scaled_sum(
            &mut self.yerr,
            h,
            &[
                (E1, f0),
                (E3, &self.k3),
                (E4, &self.k4),
                (E5, &self.k5),
                (E6, &self.k6),
                (E7, &self.k7),
            ],
        );
        let err = tol.norm(y, y_new, &self.yerr);
        if err.is_finite() {
            Ok(err)
        } else {
            nonfinite
        }
    }

    /// `f(t_new, y_new)` from the last successful trial (the FSAL stage).
    pub(crate) fn f_new(&self) -> &[f64] {
        &self.k7
    }

    /// Hairer's stiffness indicator `|h|·ρ`, with ρ estimated from the two stages
    /// that share the abscissa `t + h`:
    /// `ρ ≈ ‖k7 − k6‖ / ‖y_new − y_stage6‖`. This is a Rayleigh-quotient-like
    /// estimate of the dominant Jacobian eigenvalue's modulus along the direction
    /// the step actually explored; DOPRI5's stability region meets the negative
    /// real axis near −3.3, so values ≥ 3.25 mean the step size is being limited by
    /// stability rather than accuracy. Returns `None` if the two points coincide.
    pub(crate) fn stiffness_indicator(&self, h: f64, y_new: &[f64]) -> Option<f64> {
        let mut num = 0.0;
        let mut den = 0.0;
        for (((&k7, &k6), &yn), &ys) in self.k7.iter().zip(&self.k6).zip(y_new).zip(&self.ysti) {
            num += (k7 - k6) * (k7 - k6);
            den += (yn - ys) * (yn - ys);
        }
        if den > 0.0 && num.is_finite() {
            Some(h.abs() * (num / den).sqrt())
        } else {
            None
        }
    }

    /// Fill `ip` with the fourth-order continuous extension of the last
    /// successful trial step.
    pub(crate) fn dense(
        &self,
        ip: &mut Interpolant,
        t: f64,
        h: f64,
        y: &[f64],
        y_new: &[f64],
        f0: &[f64],
    ) {
        ip.set_hermite(t, h, y, y_new, f0, &self.k7);
        scaled_sum(
            ip.r5_mut(),
            h,
            &[
                (D1, f0),
                (D3, &self.k3),
                (D4, &self.k4),
                (D5, &self.k5),
                (D6, &self.k6),
                (D7, &self.k7),
            ],
        );
    }
}
