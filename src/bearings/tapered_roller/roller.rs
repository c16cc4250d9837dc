//! One roller's equilibrium between cup, cone and the cone's guide flange (seed 004
//! eqs. 43–44, 55–57, 74–83) or, having lost the cone, between cup and flange
//! (eqs. 121–130); and the derivatives of its cup load and moment in the ring approach
//! and misalignment at its azimuth (eqs. 88–91), which the stiffness needs.
//!
//! Unknowns u = (Δ₁, θ₁): the roller's approach to the cup at its midpoint and its
//! misalignment to the cup. The cone's follow from the flange kinematics (eq. 43,
//! Δ₂ = k(Δ − Δ₁), k = cos(α − τ/2)/cos(α + τ/2), the roller sliding along the rigid
//! flange) and eq. 44 (θ₂ = Θ − θ₁). Residuals: the radial (55) and axial (56) force
//! balances, with the flange reaction from the moment balance about the roller midpoint
//!
//! P₃·ℓ = −M₁ + M₂ + M_G + F_c·X̄·cos ψ − (d/2)(P₁ − P₂)·sin(τ/2).
//!
//! Sign readings, derived from the free body (cup force −P₁(cos β, sin β), cone force
//! P₂(cos(β−τ), sin(β−τ)), flange force P₃(−sin(ψ−α), cos(ψ−α)) through the big-end
//! sphere's centre, moments about the tangential direction): the wedge term is
//! −(d/2)(P₁ − P₂)·sin(τ/2) as in eq. 123 (eq. 57 prints (P₂ − P₁): a misprint, the two
//! equations must agree when P₂ = 0); M_G enters with the sign of the rate of the spin
//! angular momentum I·ω_R·Ω_E·sin ψ for ω_R about the axis toward the big end (eq. 39's
//! sign). The Jacobian is that of these residuals (so eq. 76–77's printed "+sin β" is
//! the −sin β of eq. 56), solved by the shared damped Newton.

use nalgebra::{Matrix2, Vector2};
use thiserror::Error;

use super::contact::{ContactError, ContactEval, RaceContact};
use super::geometry::{Dynamics, RollerGeometry};
use super::input::Geometry;
use crate::numerics::newton::{Backtracking, Newton, NewtonSystem, Termination, TrustRegion};

/// A roller's state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum RollerState {
    /// Loaded by cup, cone and flange.
    BothRaces,
    /// Off the cone: held by the cup and the flange (centrifugal and gyroscopic loads).
    CupAndFlange,
    /// Touching nothing (no speed, ring approach not positive).
    Free,
}

impl RollerState {
    /// The JSON name.
    pub fn as_str(self) -> &'static str {
        match self {
            RollerState::BothRaces => "both-races",
            RollerState::CupAndFlange => "cup-and-flange",
            RollerState::Free => "free",
        }
    }
}

/// Why a roller has no equilibrium.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RollerError {
    /// A slice left Lundberg's validity (L/(2b) ≤ 0.25, eq. 71).
    #[error("{0}")]
    Contact(#[from] ContactError),
    /// Newton did not converge.
    #[error("roller equilibrium ({state}) did not converge: {} (tolerance {tolerance:.3e} N) at ring approach Δ = {delta_m:.4e} m, misalignment Θ = {theta_rad:.3e} rad", stopped(.termination))]
    NotConverged {
        /// The branch being solved.
        state: &'static str,
        /// How Newton stopped.
        termination: Termination,
        /// Force tolerance, N.
        tolerance: f64,
        /// Ring approach at the roller, m.
        delta_m: f64,
        /// Ring misalignment at the roller, rad.
        theta_rad: f64,
    },
    /// The flange would have to pull the roller.
    #[error("the flange reaction is negative ({p3_n:.4e} N): the roller would leave the flange")]
    FlangePulls {
        /// P₃, N.
        p3_n: f64,
    },
}

/// How a force balance's Newton iteration stopped, in words, forces in N (restated in
/// the deck's units by the caller for a US deck).
pub(crate) fn stopped(t: &Termination) -> String {
    match *t {
        Termination::Converged {
            iterations,
            residual,
        } => format!("converged after {iterations} iterations (force residual {residual:.3e} N)"),
        Termination::NotConverged {
            iterations,
            residual,
            ..
        } => format!("after {iterations} iterations the force residual is still {residual:.3e} N"),
        Termination::Stalled {
            iterations,
            residual,
        } => format!(
            "no step reduced the force residual {residual:.3e} N any further (iteration {iterations})"
        ),
        Termination::SingularJacobian { iteration } => {
            format!("the balance's stiffness matrix is singular (iteration {iteration})")
        }
        Termination::NonFinite { iteration } => {
            format!("a force became NaN or infinite (iteration {iteration})")
        }
        Termination::Cancelled { .. } => "cancelled".to_string(),
    }
}

/// The model shared by every roller of a bearing.
#[derive(Debug, Clone)]
pub struct RollerModel {
    /// Cup contact.
    pub cup: RaceContact,
    /// Cone contact.
    pub cone: RaceContact,
    cb: f64,
    sb: f64,
    c_cone: f64,
    s_cone: f64,
    s_flange: f64,
    c_flange: f64,
    k: f64,
    lever: f64,
    wedge: f64,
    /// F_c, N.
    pub fc: f64,
    /// M_G + F_c·X̄·cos ψ: the speed terms of the moment balance, N·m.
    speed_moment: f64,
    /// Force scale of the tolerance, N.
    pub force_scale: f64,
    tolerance: f64,
    /// The force floor of the roller's balances, N: the force of an approach of 1e-15 of
    /// the roller diameter along the effective length of the cup contact (a few ulps of
    /// the roller's own dimensions: forces below it are round-off of the geometry, not a
    /// load); 1.9e-8 N on the AFAPL sample. The cup-and-flange tolerance is at least this.
    pub force_floor_n: f64,
    newton: Newton,
    /// Scales of Δ₁ (m) and θ₁ (rad) in the step length.
    scale: [f64; 2],
    /// The cup-and-flange equilibrium (independent of the ring), when the roller has speed.
    cup_flange: Option<Result<RollerSolution, RollerError>>,
}

/// One roller at equilibrium, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerSolution {
    /// State.
    pub state: RollerState,
    /// Δ₁, m.
    pub delta1_m: f64,
    /// θ₁, rad.
    pub theta1_rad: f64,
    /// Δ₂, m.
    pub delta2_m: f64,
    /// θ₂, rad.
    pub theta2_rad: f64,
    /// Cup contact.
    pub cup: ContactEval,
    /// Cone contact.
    pub cone: ContactEval,
    /// P₃, flange reaction, N.
    pub flange_n: f64,
    /// dP₁/dΔ (N/m) and dP₁/dΘ (N/rad) at equilibrium (eqs. 88–91).
    pub dp1: [f64; 2],
    /// dM₁/dΔ (N) and dM₁/dΘ (N·m/rad).
    pub dm1: [f64; 2],
    /// ∂(Δ₁, θ₁)/∂(Δ, Θ) at equilibrium (row i: unknown i, column j: ring variable j;
    /// zero off the both-races branch): the tangent a neighbouring solve is predicted by.
    pub du: [[f64; 2]; 2],
    /// Newton iterations.
    pub iterations: usize,
    /// Largest force residual, N.
    pub residual_n: f64,
}

/// Everything one evaluation gives.
#[derive(Debug, Clone)]
struct Eval {
    r: Vector2<f64>,
    j: Matrix2<f64>,
    /// ∂r/∂(Δ, Θ).
    jp: Matrix2<f64>,
    cup: ContactEval,
    cone: ContactEval,
    p3: f64,
    delta2: f64,
    theta2: f64,
}

/// The Newton system of one roller at ring approach Δ and misalignment Θ.
struct System<'a> {
    m: &'a RollerModel,
    delta: f64,
    big_theta: f64,
    /// Cone contact counted (both races) or not (cup and flange).
    with_cone: bool,
    error: Option<ContactError>,
}

impl System<'_> {
    fn eval(&self, x: &Vector2<f64>) -> Result<Eval, ContactError> {
        let m = self.m;
        let (d1, t1) = (x[0], x[1]);
        let cup = m.cup.eval(d1, t1, None)?;
        let (delta2, theta2) = (m.k * (self.delta - d1), self.big_theta - t1);
        let cone = if self.with_cone {
            m.cone.eval(delta2, theta2, None)?
        } else {
            ContactEval::default()
        };
        let (p1, p2) = (cup.load_n, cone.load_n);
        let p3 = (-cup.moment_nm + cone.moment_nm + m.speed_moment - m.wedge * (p1 - p2)) / m.lever;
        let r = Vector2::new(
            -p1 * m.cb + p2 * m.c_cone - p3 * m.s_flange + m.fc,
            -p1 * m.sb + p2 * m.s_cone + p3 * m.c_flange,
        );
        // Chain rule: ∂(P₂, M₂)/∂(Δ₁, θ₁) = (−k·∂/∂Δ₂, −∂/∂θ₂); ∂/∂(Δ, Θ) = (k·∂/∂Δ₂, ∂/∂θ₂).
        let col = |dp1: f64, dm1: f64, dp2: f64, dm2: f64| {
            let dp3 = (-dm1 + dm2 - m.wedge * (dp1 - dp2)) / m.lever;
            Vector2::new(
                -dp1 * m.cb + dp2 * m.c_cone - dp3 * m.s_flange,
                -dp1 * m.sb + dp2 * m.s_cone + dp3 * m.c_flange,
            )
        };
        let j = Matrix2::from_columns(&[
            col(
                cup.dload[0],
                cup.dmoment[0],
                -m.k * cone.dload[0],
                -m.k * cone.dmoment[0],
            ),
            col(
                cup.dload[1],
                cup.dmoment[1],
                -cone.dload[1],
                -cone.dmoment[1],
            ),
        ]);
        let jp = Matrix2::from_columns(&[
            col(0.0, 0.0, m.k * cone.dload[0], m.k * cone.dmoment[0]),
            col(0.0, 0.0, cone.dload[1], cone.dmoment[1]),
        ]);
        Ok(Eval {
            r,
            j,
            jp,
            cup,
            cone,
            p3,
            delta2,
            theta2,
        })
    }
}

impl NewtonSystem<2> for System<'_> {
    type Eval = Eval;

    fn evaluate(&mut self, x: &Vector2<f64>) -> Eval {
        match self.eval(x) {
            Ok(e) => e,
            Err(err) => {
                // A trial outside the slice law's range (eq. 71) is a NaN residual: the
                // line search rejects it and backtracks toward the accepted iterate. The
                // latest failure is kept as the reason should the solve not converge.
                self.error = Some(err);
                Eval {
                    r: Vector2::repeat(f64::NAN),
                    j: Matrix2::zeros(),
                    jp: Matrix2::zeros(),
                    cup: ContactEval::default(),
                    cone: ContactEval::default(),
                    p3: f64::NAN,
                    delta2: f64::NAN,
                    theta2: f64::NAN,
                }
            }
        }
    }

    fn residual<'e>(&self, e: &'e Eval) -> &'e Vector2<f64> {
        &e.r
    }

    fn jacobian<'e>(&self, e: &'e Eval) -> &'e Matrix2<f64> {
        &e.j
    }

    fn step_length(&self, step: &Vector2<f64>) -> f64 {
        (step[0] / self.m.scale[0]).hypot(step[1] / self.m.scale[1])
    }
}

impl RollerModel {
    /// The model of the bearing's rollers: contacts with `slices` slices, inertia loads
    /// `dy`, force scale `force_scale` (N) for the tolerance `rel_tol`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        g: &Geometry,
        rg: &RollerGeometry,
        cup: RaceContact,
        cone: RaceContact,
        dy: &Dynamics,
        force_scale: f64,
        rel_tol: f64,
        max_iterations: usize,
    ) -> RollerModel {
        let beta = g.cup_angle_rad;
        let t = rg.half_cone_rad;
        let psi = rg.axis_angle_rad;
        let alpha = rg.flange_angle_rad;
        let half_le = 0.5 * g.effective_length_m;
        let tolerance = rel_tol * force_scale;
        // The cup-and-flange roller carries only its inertia loads: near rest they are
        // tiny (F_c ∝ speed², 8.6e-11 N at 0.01 rpm on the sample) and a tolerance tied to
        // the bearing's load alone (3.6e-10 N) asks the Newton iteration to resolve forces
        // below the contact's round-off, which it did not within its budget (issue 24
        // item 11). Its tolerance has a floor from the bearing's own scale.
        let force_floor_n = cup.line_force_scale(g.effective_length_m, 1e-15 * g.roller_diameter_m);
        let mut m = RollerModel {
            cup,
            cone,
            cb: beta.cos(),
            sb: beta.sin(),
            c_cone: (beta - 2.0 * t).cos(),
            s_cone: (beta - 2.0 * t).sin(),
            s_flange: (psi - alpha).sin(),
            c_flange: (psi - alpha).cos(),
            k: rg.approach_ratio,
            lever: rg.flange_lever_arm_m,
            wedge: 0.5 * g.roller_diameter_m * t.sin(),
            fc: dy.centrifugal_force_n,
            speed_moment: dy.gyroscopic_moment_nm
                + dy.centrifugal_force_n * rg.cg_offset_m * psi.cos(),
            force_scale,
            tolerance,
            force_floor_n,
            newton: Newton {
                max_iterations,
                tolerance,
                trust: TrustRegion::new(20.0, 1e-9, 1e4),
                line_search: Backtracking::default(),
            },
            scale: [1e-7, 1e-7 / half_le],
            cup_flange: None,
        };
        if m.fc != 0.0 || m.speed_moment != 0.0 {
            let sol = m.solve_cup_flange();
            m.cup_flange = Some(sol);
        }
        m
    }

    /// The cup-and-flange equilibrium (eqs. 121–130): independent of the ring.
    fn solve_cup_flange(&self) -> Result<RollerSolution, RollerError> {
        // Start: P₁ from the force balance alone (eqs. 121–122 with P₃ eliminated), its
        // approach by one secant step of the aligned cup contact from Δ₁ = 1 µm.
        let p1 = self.fc / (self.cb + self.sb * self.s_flange / self.c_flange);
        let probe = self.cup.eval(1e-6, 0.0, None)?;
        let per_m = if probe.dload[0] > 0.0 {
            probe.dload[0]
        } else {
            1e8
        };
        let start = Vector2::new((1e-6 + (p1.abs() - probe.load_n) / per_m).max(1e-7), 0.0);
        self.newton_solve(0.0, 0.0, false, start)
    }

    fn newton_solve(
        &self,
        delta: f64,
        big_theta: f64,
        with_cone: bool,
        start: Vector2<f64>,
    ) -> Result<RollerSolution, RollerError> {
        let mut sys = System {
            m: self,
            delta,
            big_theta,
            with_cone,
            error: None,
        };
        let tolerance = if with_cone {
            self.tolerance
        } else {
            self.tolerance.max(self.force_floor_n)
        };
        let newton = Newton {
            tolerance,
            ..self.newton
        };
        let mut x = start;
        let res = newton.solve(&mut sys, &mut x);
        let state = if with_cone {
            RollerState::BothRaces
        } else {
            RollerState::CupAndFlange
        };
        // Near round-off the line search may find no decrease: accept a stall within 100×
        // the tolerance (the residual is then at round-off of the contact sums).
        let ok = match res.termination {
            Termination::Converged { .. } => true,
            Termination::Stalled { residual, .. } => residual <= 100.0 * tolerance,
            _ => false,
        };
        if !ok {
            // A slice beyond Lundberg's range (eq. 71) that stopped the iteration is the
            // reason to report; a trial that left it and was backtracked from is not: the
            // accepted iterates, the answer among them, were all evaluated inside the range.
            if let Some(err) = sys.error {
                return Err(err.into());
            }
            return Err(RollerError::NotConverged {
                state: state.as_str(),
                termination: res.termination,
                tolerance,
                delta_m: delta,
                theta_rad: big_theta,
            });
        }
        let e = res.eval;
        if e.p3 < -tolerance {
            return Err(RollerError::FlangePulls { p3_n: e.p3 });
        }
        // Eqs. 88–91: du/d(Δ, Θ) = −J⁻¹·∂r/∂(Δ, Θ); P₁, M₁ depend on u only.
        let (dp1, dm1, du) = if with_cone {
            let du =
                e.j.try_inverse()
                    .map(|inv| -(inv * e.jp))
                    .unwrap_or_else(Matrix2::zeros);
            let dp = Vector2::new(e.cup.dload[0], e.cup.dload[1]);
            let dm = Vector2::new(e.cup.dmoment[0], e.cup.dmoment[1]);
            let a = du.transpose() * dp;
            let b = du.transpose() * dm;
            (
                [a[0], a[1]],
                [b[0], b[1]],
                [[du[(0, 0)], du[(0, 1)]], [du[(1, 0)], du[(1, 1)]]],
            )
        } else {
            ([0.0; 2], [0.0; 2], [[0.0; 2]; 2])
        };
        Ok(RollerSolution {
            state,
            delta1_m: x[0],
            theta1_rad: x[1],
            delta2_m: e.delta2,
            theta2_rad: e.theta2,
            cup: e.cup,
            cone: e.cone,
            flange_n: e.p3,
            dp1,
            dm1,
            du,
            iterations: res.termination.iterations(),
            residual_n: e.r.amax(),
        })
    }

    /// Both-races Newton from the warm start, and from the cold one if that fails (a warm
    /// start from a far-away ring iterate may sit where the cone does not touch).
    fn solve_from(
        &self,
        delta: f64,
        big_theta: f64,
        warm: Option<(f64, f64)>,
        cold: (f64, f64),
    ) -> Result<RollerSolution, RollerError> {
        if let Some(w) = warm {
            // Any failure from the warm start (also a slice pushed beyond Lundberg's
            // validity by a far predicted start) is judged by the cold start, whose
            // error, if any, is the one reported.
            if let Ok(r) = self.newton_solve(delta, big_theta, true, Vector2::new(w.0, w.1)) {
                return Ok(r);
            }
        }
        match self.newton_solve(delta, big_theta, true, Vector2::new(cold.0, cold.1)) {
            Ok(r) => Ok(r),
            Err(e) => self.continuation(delta, big_theta, e),
        }
    }

    /// The both-races equilibrium at (Δ, Θ) by continuation, when Newton from the warm
    /// and cold starts failed: from the aligned roller at an approach Δ_a > 0 (Δ itself,
    /// or |Δ| when a tilt alone brings a ring that backs off, Δ ≤ 0, into contact; no edge
    /// contact's onset on the way in) along the straight path (Δ_a + s(Δ − Δ_a), s·Θ),
    /// s: 0 → 1. The contact condition (the largest intrusion positive, roughly
    /// Δ + c·|Θ| > 0 with the sign of Θ fixed along the path) holds at both ends and so
    /// along it. Each step starts on the previous solution's tangent (its exact
    /// ∂(Δ₁, θ₁)/∂(Δ, Θ) of eqs. 88–91). A step that fails is halved (a bracket on s: the
    /// last solved s below, the failed one above), one that converges is doubled; where
    /// an edge contact starts or stops along the path (the slice law's kink, eqs. 52–53)
    /// the steps shrink until the predicted start lies where Newton converges. The answer
    /// is an ordinary converged Newton solve at s = 1 (same tolerance, same acceptance);
    /// when a step falls below 1e-9 of the path, `first`, the direct solve's error, is
    /// returned (typed, with its numbers).
    fn continuation(
        &self,
        delta: f64,
        big_theta: f64,
        first: RollerError,
    ) -> Result<RollerSolution, RollerError> {
        let delta_a = if delta > 0.0 { delta } else { delta.abs() };
        if !(delta_a > 0.0) || (big_theta == 0.0 && delta_a == delta) {
            return Err(first);
        }
        let split = self.k * delta_a / (1.0 + self.k);
        let Ok(mut at) = self.newton_solve(delta_a, 0.0, true, Vector2::new(split, 0.0)) else {
            return Err(first);
        };
        let (mut s, mut h) = (0.0_f64, 0.25_f64);
        let mut solves = 0;
        while s < 1.0 {
            if h < 1e-9 || solves > 400 {
                return Err(first);
            }
            let next = (s + h).min(1.0);
            let (dd, dt) = ((next - s) * (delta - delta_a), (next - s) * big_theta);
            let start = Vector2::new(
                at.delta1_m + at.du[0][0] * dd + at.du[0][1] * dt,
                at.theta1_rad + at.du[1][0] * dd + at.du[1][1] * dt,
            );
            solves += 1;
            let (d_next, t_next) = if next == 1.0 {
                (delta, big_theta)
            } else {
                (delta_a + next * (delta - delta_a), next * big_theta)
            };
            match self.newton_solve(d_next, t_next, true, start) {
                Ok(r) => {
                    at = r;
                    s = next;
                    h *= 2.0;
                }
                Err(_) => h *= 0.5,
            }
        }
        Ok(at)
    }

    /// The roller's equilibrium at ring approach `delta` (m, eq. 40) and misalignment
    /// `big_theta` (rad, eq. 42), starting from `warm` (Δ₁, θ₁) if given.
    pub fn solve(
        &self,
        delta: f64,
        big_theta: f64,
        warm: Option<(f64, f64)>,
    ) -> Result<RollerSolution, RollerError> {
        match &self.cup_flange {
            Some(cf) => {
                let cf = cf.clone()?;
                // Does the roller, held where cup and flange put it, reach the cone?
                let d2 = self.k * (delta - cf.delta1_m);
                let t2 = big_theta - cf.theta1_rad;
                if !self.cone.touches(d2, t2) {
                    return Ok(RollerSolution {
                        delta2_m: d2,
                        theta2_rad: t2,
                        ..cf
                    });
                }
                let cold = (cf.delta1_m, cf.theta1_rad);
                self.solve_from(delta, big_theta, warm, cold)
            }
            None => {
                if delta <= 0.0 {
                    return Ok(RollerSolution {
                        state: RollerState::Free,
                        delta1_m: 0.0,
                        theta1_rad: 0.5 * big_theta,
                        delta2_m: 0.0,
                        theta2_rad: 0.5 * big_theta,
                        cup: ContactEval::default(),
                        cone: ContactEval::default(),
                        flange_n: 0.0,
                        dp1: [0.0; 2],
                        dm1: [0.0; 2],
                        du: [[0.0; 2]; 2],
                        iterations: 0,
                        residual_n: 0.0,
                    });
                }
                // Equal approaches at both races, misalignment shared: both in contact.
                let split = self.k * delta / (1.0 + self.k);
                self.solve_from(delta, big_theta, warm, (split, 0.5 * big_theta))
            }
        }
    }
}

#[cfg(test)]
mod tests;
