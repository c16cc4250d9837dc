//! The analytic Jacobian of a ball's equations of motion (the implicit integrator's
//! matrix; with steep traction curves the ball equations are stiff, seed 001 ch. 2 and
//! issue 16's eigenvalues to −4·10⁵ 1/s).

use nalgebra::{Matrix3, Matrix4, SMatrix, Vector3, Vector4};

use super::{BallModel, ContactLoads};
use crate::physics::lubrication::traction_curve::TractionCurve;

impl BallModel<'_> {
    /// ∂(M_a, M_r, M_t, F_t)/∂(ω_a, ω_r, ω_t, ω_m) of one contact's slices (analytic).
    ///
    /// Per strip (see [`BallModel::contact_at`]) M = −k (s_t G + s_x H), F_t = −k s_t with
    /// k = µ(u) q/u, G = (p_r, −p_a, 0), H = (0, 0, p·ν); s_t and s_x are linear in
    /// x = (ω, ω_m): ∇s_t = (p_r, −p_a, 0, R_b), ∇s_x = (0, 0, p·ν, 0), and
    /// ∇k = (dk/du)/u · (s_t ∇s_t + s_x ∇s_x) with dk/du = q (µ' − µ/u)/u.
    pub fn contact_jacobian4(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
        orbital_rad_s: f64,
    ) -> Matrix4<f64> {
        let mut jac = Matrix4::zeros();
        let r = self.centre_radius_m;
        let vc = orbital_rad_s * r;
        self.for_each_slice(inner, c, |sl| {
            let (s_t, s_x) = sl.sliding(vc, omega);
            let u2 = s_t * s_t + s_x * s_x;
            if u2 == 0.0 {
                return;
            }
            let u = u2.sqrt();
            let (mu, slope) = mu_and_slope(self.curve, u);
            let k = mu * sl.q / u;
            let dk_u = sl.q * (slope - mu / u) / u2;
            let (pa, pr, d) = (sl.p[0], sl.p[1], sl.d);
            // Outputs' directions (M_a, M_r, M_t, F_t) and inputs' gradients.
            let go = Vector4::new(pr, -pa, 0.0, 1.0);
            let ho = Vector4::new(0.0, 0.0, d, 0.0);
            let gx = Vector4::new(pr, -pa, 0.0, r);
            let hx = Vector4::new(0.0, 0.0, d, 0.0);
            let o = s_t * go + s_x * ho;
            let g = s_t * gx + s_x * hx;
            jac -= k * (go * gx.transpose() + ho * hx.transpose()) + dk_u * o * g.transpose();
        });
        jac
    }

    /// ∂M/∂ω of one contact at the held cage speed (the 3×3 block of
    /// [`Self::contact_jacobian4`]).
    pub fn contact_jacobian(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
    ) -> Matrix3<f64> {
        self.contact_jacobian4(inner, c, omega, self.cage_rad_s)
            .fixed_view::<3, 3>(0, 0)
            .into_owned()
    }

    /// ∂(dω/dt)/∂ω at time `t_s` with the held cage speed (analytic; the implicit
    /// integrator's Jacobian).
    pub fn omega_jacobian(&self, t_s: f64, omega: &Vector3<f64>) -> Matrix3<f64> {
        let l = self.track.at(self.azimuth(t_s));
        let m = self.contact_jacobian(true, &l.inner, omega)
            + self.contact_jacobian(false, &l.outer, omega);
        let a = Vector3::new(1.0, 0.0, 0.0);
        m / self.inertia_kg_m2 - self.cage_rad_s * a.cross_matrix()
    }
}

impl BallModel<'_> {
    /// The free orbit's Jacobian ∂f/∂y at y = (ω_a, ω_r, ω_t, ω_m, θ) (see
    /// [`BallModel::free_rates`]): the (ω, ω_m) block analytic from
    /// [`Self::contact_jacobian4`] and the frame's rotation (∂(ω_m a × ω)/∂ω = ω_m [a]×,
    /// ∂/∂ω_m = a × ω); dθ/dt = ω_m gives the last row. The θ column (how the loads
    /// move with the ball's azimuth, through the track's piecewise-linear loads and the
    /// ellipse's nonlinear geometry) by a central difference of step 1e-6 rad: exact on a
    /// linear piece of the track up to the O(h²) geometry term (relative ~1e-12), and
    /// the mean of the two slopes across a track point.
    pub fn free_jacobian(&self, y: &[f64; 5]) -> SMatrix<f64, 5, 5> {
        let omega = Vector3::new(y[0], y[1], y[2]);
        let wm = y[3];
        let l = self.track.at(y[4]);
        let j4 = self.contact_jacobian4(true, &l.inner, &omega, wm)
            + self.contact_jacobian4(false, &l.outer, &omega, wm);
        let mut jac = SMatrix::<f64, 5, 5>::zeros();
        let (inv_j, inv_mr) = (
            1.0 / self.inertia_kg_m2,
            1.0 / (self.mass_kg * self.centre_radius_m),
        );
        for c in 0..4 {
            for r in 0..3 {
                jac[(r, c)] = j4[(r, c)] * inv_j;
            }
            jac[(3, c)] = j4[(3, c)] * inv_mr;
        }
        // − ω_m a × ω = −ω_m (0, −ω_t, ω_r).
        jac[(1, 2)] += wm;
        jac[(2, 1)] -= wm;
        jac[(1, 3)] += y[2];
        jac[(2, 3)] -= y[1];
        jac[(4, 3)] = 1.0;
        let h = 1e-6;
        let (mut yp, mut ym) = (*y, *y);
        yp[4] += h;
        ym[4] -= h;
        let (fp, fm) = (self.free_rates(&yp), self.free_rates(&ym));
        for r in 0..5 {
            jac[(r, 4)] = (fp[r] - fm[r]) / (2.0 * h);
        }
        jac
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
