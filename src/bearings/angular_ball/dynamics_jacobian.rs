//! The analytic Jacobian ∂(dω/dt)/∂ω of a ball's equations of motion (the implicit
//! integrator's matrix; with steep traction curves the ball equations are stiff, seed
//! 001 ch. 2 and issue 16's eigenvalues to −4·10⁵ 1/s).

use nalgebra::{Matrix3, Vector3};

use super::{BallModel, ContactLoads};
use crate::physics::lubrication::traction_curve::TractionCurve;

impl BallModel<'_> {
    /// ∂M/∂ω of one contact's slices (analytic): with s_t = P(ω × p + …), P = I − νν^T,
    /// and f = −q µ(u) s_t/u, ∂f/∂s_t = −q[(µ/u)·I + (µ' − µ/u)·ŝŝ^T], so
    /// ∂M/∂ω = Σ [p]× (∂f/∂s_t) P (−[p]×).
    pub fn contact_jacobian(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
    ) -> Matrix3<f64> {
        let mut jac = Matrix3::zeros();
        let vc = self.cage_rad_s * self.centre_radius_m * Vector3::new(0.0, 0.0, 1.0);
        self.for_each_slice(inner, c, |q, nu, p, v_race| {
            let sl = vc + omega.cross(p) - v_race;
            let proj = Matrix3::identity() - nu * nu.transpose();
            let sl = proj * sl;
            let u = sl.norm();
            if u == 0.0 {
                return;
            }
            let (mu, slope) = mu_and_slope(self.curve, u);
            let sh = sl / u;
            let dfds =
                -q * ((mu / u) * Matrix3::identity() + (slope - mu / u) * (sh * sh.transpose()));
            let px = p.cross_matrix();
            jac += px * dfds * proj * (-px);
        });
        jac
    }

    /// ∂(dω/dt)/∂ω at time `t_s` (analytic; the implicit integrator's Jacobian).
    pub fn omega_jacobian(&self, t_s: f64, omega: &Vector3<f64>) -> Matrix3<f64> {
        let l = self.track.at(self.azimuth(t_s));
        let m = self.contact_jacobian(true, &l.inner, omega)
            + self.contact_jacobian(false, &l.outer, omega);
        let a = Vector3::new(1.0, 0.0, 0.0);
        m / self.inertia_kg_m2 - self.cage_rad_s * a.cross_matrix()
    }
}

/// µ(u) and dµ/du of the traction curve (piecewise linear: the slope of the segment
/// holding u, the right-hand one at a break point; 0 beyond the last point and for
/// Coulomb friction).
pub(super) fn mu_and_slope(curve: &TractionCurve, u: f64) -> (f64, f64) {
    match curve {
        TractionCurve::Constant { mu } => (*mu, 0.0),
        TractionCurve::Table { points } => {
            for w in points.windows(2) {
                let ((u0, m0), (u1, m1)) = (w[0], w[1]);
                if u < u1 {
                    let k = (m1 - m0) / (u1 - u0);
                    return (m0 + k * (u - u0), k);
                }
            }
            (curve.mu(u), 0.0)
        }
    }
}
