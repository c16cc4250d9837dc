//! Ball dynamics in EHD traction (seed 001 ch. 2, eqs. 2-3, 2-14…2-18): the ball's
//! angular velocity under the traction of every slice of its two contacts, either as a
//! time simulation over its orbits (integrated by `numerics::ode`, started from race
//! control) or quasi-statically (the moment balance solved at each ball position).
//!
//! # Frame and equations of motion (2-3, 2-14b…d in vector form)
//! The frame (a, r, t) of `race_control` (axis, radially out, orbital direction) at the
//! ball centre turns with the cage at ω_m about a. The ball is a sphere of inertia J, so
//! with ω its absolute angular velocity written in this frame,
//! ```text
//! J·dω/dt = M − J·ω_m a × ω,
//! ```
//! i.e. J ω̇_a = M_a, J ω̇_r = M_r + J ω_m ω_t, J ω̇_t = M_t − J ω_m ω_r: the last term is
//! Chen's gyroscopic term of (2-3)/(2-14c,d). M is the moment of the slice tractions
//! about the ball centre. The orbital speed ω_m (Chen's fourth unknown, 2-14a) is held at
//! race control's cage speed (a cage-guided ball set; the ball's orbital equation is not
//! integrated — the tangential force it would need is reported as the cage's share of
//! the power balance, see [`ContactPower`]).
//!
//! # Sliding velocities (derived here: the OCR of 2-15a…c is garbled)
//! A point p of the contact (from the ball centre) moves with the ball at
//! v_b = ω_m R_b t + ω × p, and with race j (speed Ω_j about the axis) at
//! v_j = Ω_j (R_b + p_r) t (p lies in the a–r plane). The sliding of the ball on the race
//! is s = v_b − v_j, taken in the tangent plane of the contact surface. Its rolling
//! component (along t) holds Chen's y-sliding (2-15b, c: spin and creep); its transverse
//! component Chen's x-sliding (2-15a, "caused by the gyroscopic moment").
//!
//! # Slices (2-16, 2-17)
//! Each ellipse (semi-major a across the groove, semi-minor b along t) is cut into N
//! strips across its major axis; strip k carries the Hertz load
//! q_k = Q·¾[ξ − ξ³/3] between its edges ξ = x/a (the exact integral of p₀√(1−ξ²−η²)),
//! and slides with the velocity of its centre line. Only the transverse curvature of
//! the contact surface is kept (the seed: the ellipse is narrow): the surface is the
//! arc of radius R_def = 2/(2/D + 1/(fD)) (2-17, the mean of the ball's and the groove's
//! curvatures), tangent to the undeformed ball at the contact centre.
//!
//! # Traction and heat (2-18)
//! Each strip carries the traction −µ(|s|)·q·s/|s| (µ from the traction curve); the heat
//! is µ·q·|s|, split into its rolling-direction part µ q s_t²/|s| and its lateral part
//! µ q s_x²/|s| (Fig. 6-13's sources; the two add up to the total exactly). Spin
//! slides along the rolling direction (ω_s n × x τ is parallel to t), so spin heat lands
//! in the rolling part; the lateral part is the gyroscopic skid (Chen's 2-15a). This
//! is Chen's split by sliding direction, not a split into "spin" and "rolling" causes.

use nalgebra::{Matrix3, Vector3};

use super::analysis::BallResult;
use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, Integrator, Method};
pub use super::load_track::{BallLoads, ContactLoads, LoadTrack};
use crate::numerics::cancel::Cancel;
use crate::numerics::ode::{self, OdeError, OdeOptions, OdeSystem, Output};
use crate::physics::lubrication::traction_curve::TractionCurve;

/// Forces, moment and powers of one contact's slices.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactPower {
    /// Moment of the tractions about the ball centre, N·m (a, r, t).
    pub moment: Vector3<f64>,
    /// Resultant traction on the ball, N (a, r, t).
    pub force: Vector3<f64>,
    /// Heat from sliding in the rolling direction, W.
    pub rolling_w: f64,
    /// Heat from lateral (transverse) sliding, W.
    pub lateral_w: f64,
    /// Power taken from the race by the tractions, Σ f·v_race (f the traction on the
    /// ball, v_race the race surface velocity), W.
    pub ring_power_w: f64,
}

/// One ball's dynamic model: everything the right-hand side needs.
pub struct BallModel<'a> {
    /// D, m.
    pub diameter_m: f64,
    /// R_b, radius of the ball centre, m.
    pub centre_radius_m: f64,
    /// J, kg·m².
    pub inertia_kg_m2: f64,
    /// ω_m, held orbital speed, rad/s.
    pub cage_rad_s: f64,
    /// Ω_i, Ω_o, rad/s.
    pub ring_speeds_rad_s: (f64, f64),
    /// f_i, f_o.
    pub groove_curvatures: (f64, f64),
    /// µ(u_s).
    pub curve: &'a TractionCurve,
    /// Slices per contact.
    pub slices: usize,
    /// Loads against azimuth.
    pub track: &'a LoadTrack,
    /// Azimuth at t = 0, rad.
    pub start_azimuth_rad: f64,
}

impl BallModel<'_> {
    /// The slices of one contact (module docs, "Slices"; 2-16, 2-17), in order across
    /// the ellipse: `each(q, ν, p, v_race)` with q the strip's Hertz load (N), ν its
    /// surface normal, p its centre line's point from the ball centre (m) and v_race the
    /// race surface velocity there (m/s). Shared by the moments ([`Self::contact`]) and
    /// their Jacobian, so the two cannot drift apart. Nothing for an unloaded contact.
    ///
    /// The strip angles φ_k = ξ_k a/R_def are equally spaced, so ν_k is turned from
    /// ν_{k−1} by the fixed rotation (cos Δφ, sin Δφ) instead of two trigonometric calls
    /// per strip (the right-hand side's main cost); the recurrence's rounding (≈ k·1e-16)
    /// is far below any tolerance used.
    #[inline]
    pub(super) fn for_each_slice(
        &self,
        inner: bool,
        c: &ContactLoads,
        mut each: impl FnMut(f64, &Vector3<f64>, &Vector3<f64>, &Vector3<f64>),
    ) {
        if c.load_n <= 0.0 || c.semi_major_m <= 0.0 {
            return;
        }
        let h = 0.5 * self.diameter_m;
        let (s, co) = c.angle_rad.sin_cos();
        // Outward normals: outer (sin α, cos α), inner turned by 180° (2-9b/c's α_i + 180°).
        let (n, f, w_race) = if inner {
            (
                Vector3::new(-s, -co, 0.0),
                self.groove_curvatures.0,
                self.ring_speeds_rad_s.0,
            )
        } else {
            (
                Vector3::new(s, co, 0.0),
                self.groove_curvatures.1,
                self.ring_speeds_rad_s.1,
            )
        };
        let tau = Vector3::new(n[1], -n[0], 0.0);
        let t = Vector3::new(0.0, 0.0, 1.0);
        // 2-17: the mean of the ball's and the groove's transverse curvatures.
        let r_def = 2.0 / (2.0 / self.diameter_m + 1.0 / (f * self.diameter_m));
        let cum = |xi: f64| 0.75 * (xi - xi * xi * xi / 3.0);
        let nsl = self.slices.max(1);
        let width = 2.0 / nsl as f64;
        let (ds, dc) = (width * c.semi_major_m / r_def).sin_cos();
        let (mut sp, mut cp) = ((0.5 * width - 1.0) * c.semi_major_m / r_def).sin_cos();
        for k in 0..nsl {
            let x0 = -1.0 + width * k as f64;
            let x1 = -1.0 + width * (k + 1) as f64;
            let q = c.load_n * (cum(x1) - cum(x0));
            let nu = cp * n + sp * tau;
            let p = (h - r_def) * n + r_def * nu;
            let v_race = w_race * (self.centre_radius_m + p[1]) * t;
            each(q, &nu, &p, &v_race);
            (sp, cp) = (sp * dc + cp * ds, cp * dc - sp * ds);
        }
    }

    /// One contact: `inner` selects the race; ω the ball's angular velocity.
    pub fn contact(&self, inner: bool, c: &ContactLoads, omega: &Vector3<f64>) -> ContactPower {
        let mut out = ContactPower::default();
        let vc = self.cage_rad_s * self.centre_radius_m * Vector3::new(0.0, 0.0, 1.0);
        self.for_each_slice(inner, c, |q, nu, p, v_race| {
            let sl = vc + omega.cross(p) - v_race;
            let sl = sl - sl.dot(nu) * nu;
            let u = sl.norm();
            if u == 0.0 {
                return;
            }
            let mu = self.curve.mu(u);
            let fv = -(mu * q / u) * sl;
            out.moment += p.cross(&fv);
            out.force += fv;
            let s_t = sl[2];
            out.rolling_w += mu * q * s_t * s_t / u;
            out.lateral_w += mu * q * (u * u - s_t * s_t) / u;
            out.ring_power_w += fv.dot(v_race);
        });
        out
    }

    /// The moment of one contact's tractions about the ball centre, N·m: what
    /// [`Self::contact`] gives as `moment`, without the forces and powers (the
    /// right-hand side needs only this; the integrator calls it thousands of times per
    /// orbit, the powers are evaluated at the recorded samples only).
    pub fn contact_moment(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
    ) -> Vector3<f64> {
        let mut m = Vector3::zeros();
        let vc = self.cage_rad_s * self.centre_radius_m * Vector3::new(0.0, 0.0, 1.0);
        self.for_each_slice(inner, c, |q, nu, p, v_race| {
            let sl = vc + omega.cross(p) - v_race;
            let sl = sl - sl.dot(nu) * nu;
            let u = sl.norm();
            if u == 0.0 {
                return;
            }
            m -= (self.curve.mu(u) * q / u) * p.cross(&sl);
        });
        m
    }

    /// Both contacts at time `t_s` with angular velocity ω.
    pub fn contacts(&self, t_s: f64, omega: &Vector3<f64>) -> (ContactPower, ContactPower) {
        let l = self.track.at(self.azimuth(t_s));
        (
            self.contact(true, &l.inner, omega),
            self.contact(false, &l.outer, omega),
        )
    }

    /// ψ(t), rad.
    pub fn azimuth(&self, t_s: f64) -> f64 {
        self.start_azimuth_rad + self.cage_rad_s * t_s
    }

    /// dω/dt = M/J − ω_m a × ω (module docs).
    pub fn omega_dot(&self, t_s: f64, omega: &Vector3<f64>) -> Vector3<f64> {
        let l = self.track.at(self.azimuth(t_s));
        let m = self.contact_moment(true, &l.inner, omega)
            + self.contact_moment(false, &l.outer, omega);
        let a = Vector3::new(1.0, 0.0, 0.0);
        m / self.inertia_kg_m2 - self.cage_rad_s * a.cross(omega)
    }
}

impl OdeSystem for BallModel<'_> {
    fn dim(&self) -> usize {
        3
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let d = self.omega_dot(t, &Vector3::new(y[0], y[1], y[2]));
        dydt.copy_from_slice(d.as_slice());
    }
    fn jacobian(&self, t: f64, y: &[f64], jac: &mut nalgebra::DMatrix<f64>) -> bool {
        let j = self.omega_jacobian(t, &Vector3::new(y[0], y[1], y[2]));
        for r in 0..3 {
            for c in 0..3 {
                jac[(r, c)] = j[(r, c)];
            }
        }
        true
    }
}

/// One sample of a ball's history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// t, s.
    pub time_s: f64,
    /// Orbit position travelled plus the start azimuth (unwrapped), degrees.
    pub orbit_deg: f64,
    /// ω (a, r, t), rad/s.
    pub omega_rad_s: [f64; 3],
    /// Heat of both contacts, W.
    pub heat_w: f64,
    /// Its lateral part, W.
    pub lateral_w: f64,
    /// Its rolling-direction part, W.
    pub rolling_w: f64,
}

/// One ball's dynamics.
#[derive(Debug, Clone, PartialEq)]
pub struct BallDynamics {
    /// Start azimuth, rad.
    pub start_azimuth_rad: f64,
    /// History (one sample for the quasi-static method).
    pub history: Vec<Sample>,
    /// Heat averaged over the last orbit (time simulation) or at the position, W.
    pub heat_w: f64,
    /// Its lateral part, W.
    pub lateral_w: f64,
    /// Its rolling part, W.
    pub rolling_w: f64,
    /// Half the peak-to-peak of the largest-varying ω component over the last orbit,
    /// rad/s (0 for quasi-static).
    pub oscillation_rad_s: f64,
}

/// The dynamics of every ball.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsResult {
    /// The method.
    pub method: Method,
    /// "dopri5", "dopri5→rodas4" (automatic switch) or "newton" (quasi-static).
    pub integrator: String,
    /// Accepted steps (Newton iterations), summed over the balls simulated.
    pub steps: usize,
    /// Right-hand-side evaluations, summed.
    pub rhs_evaluations: usize,
    /// Whether every ball reached a steady state (amplitude ≤ 1e-6·|ω| over the last
    /// orbit).
    pub steady: bool,
    /// Largest oscillation amplitude over the balls, rad/s.
    pub oscillation_amplitude_rad_s: f64,
    /// Per ball (in the analysis' ball order).
    pub balls: Vec<BallDynamics>,
}

impl DynamicsResult {
    /// Total heat, W.
    pub fn total_w(&self) -> f64 {
        self.balls.iter().map(|b| b.heat_w).sum()
    }
    /// Total lateral heat, W.
    pub fn lateral_w(&self) -> f64 {
        self.balls.iter().map(|b| b.lateral_w).sum()
    }
    /// Total rolling heat, W.
    pub fn rolling_w(&self) -> f64 {
        self.balls.iter().map(|b| b.rolling_w).sum()
    }
}

fn ode_error(ball: usize, e: OdeError) -> BallError {
    match e {
        OdeError::Cancelled { .. } => BallError::Cancelled,
        e => BallError::Dynamics(format!("ball {ball}: {e}")),
    }
}

/// Samples recorded per orbit.
const SAMPLES_PER_ORBIT: usize = 90;

fn sample(model: &BallModel, t: f64, w: &[f64]) -> Sample {
    let omega = Vector3::new(w[0], w[1], w[2]);
    let (i, o) = model.contacts(t, &omega);
    let (lat, roll) = (i.lateral_w + o.lateral_w, i.rolling_w + o.rolling_w);
    Sample {
        time_s: t,
        orbit_deg: model.azimuth(t).to_degrees(),
        omega_rad_s: [w[0], w[1], w[2]],
        heat_w: lat + roll,
        lateral_w: lat,
        rolling_w: roll,
    }
}

/// Simulate one ball over `orbits` orbits from ω₀ with the automatic integrator
/// (DOPRI5, switching to Rodas4 when the stiffness test fires); returns the dynamics and
/// the ODE stats.
pub fn simulate_ball(
    model: &BallModel,
    omega0: [f64; 3],
    orbits: f64,
    rtol: f64,
    ball: usize,
    cancel: Cancel,
) -> Result<(BallDynamics, ode::OdeStats), BallError> {
    simulate_ball_with(model, omega0, orbits, rtol, ode::Method::Auto, ball, cancel)
}

/// [`simulate_ball`] with a chosen integrator (benches and the one-ball example compare
/// them).
pub fn simulate_ball_with(
    model: &BallModel,
    omega0: [f64; 3],
    orbits: f64,
    rtol: f64,
    method: ode::Method,
    ball: usize,
    cancel: Cancel,
) -> Result<(BallDynamics, ode::OdeStats), BallError> {
    let wm = model.cage_rad_s.abs();
    if wm.is_nan() || wm <= 0.0 {
        return Err(BallError::Dynamics(format!(
            "ball {ball}: the cage does not turn (ω_m = {} rad/s): nothing to simulate",
            model.cage_rad_s
        )));
    }
    let period = std::f64::consts::TAU / wm;
    let t_end = orbits * period;
    let n = ((orbits * SAMPLES_PER_ORBIT as f64).ceil() as usize).max(2);
    // Clamped: t_end·k/n can round above t_end, which the ODE solver refuses.
    let times: Vec<f64> = (0..=n)
        .map(|k| (t_end * k as f64 / n as f64).min(t_end))
        .collect();
    let scale = Vector3::from(omega0).norm().max(1.0);
    let opts = OdeOptions {
        rtol,
        atol: rtol * scale,
        max_steps: 2_000_000,
        method,
        ..OdeOptions::default()
    };
    // Integrated piecewise between the times the ball passes a point of the load track:
    // the loads are linear in azimuth between those points, so the right-hand side has
    // a kink there, which an error-controlled step straddling it pays for with rejected
    // steps (measured on Bearing B under 500 N radial load: 194 rejections in 915
    // attempts). Each piece starts with the step size the previous one ended with; the
    // automatic integrator, once switched to Rodas4, stays there.
    let mut bounds = vec![0.0];
    if !model.track.is_uniform() {
        bounds.extend(kink_times(model, t_end));
    }
    bounds.push(t_end);
    let (mut out_t, mut out_y) = (
        Vec::with_capacity(times.len()),
        Vec::with_capacity(times.len()),
    );
    let mut stats = ode::OdeStats::default();
    let mut y = omega0.to_vec();
    let mut seg_opts = opts.clone();
    let mut next = 0;
    for seg in bounds.windows(2) {
        let (a, b) = (seg[0], seg[1]);
        let mut seg_times = Vec::new();
        while let Some(&tr) = times.get(next) {
            if tr > b {
                break;
            }
            seg_times.push(tr.max(a));
            next += 1;
        }
        let sol = ode::solve(
            model,
            a,
            &y,
            b,
            &seg_opts,
            &mut [],
            Output::Times(seg_times),
            cancel,
        )
        .map_err(|e| ode_error(ball, e))?;
        let st = sol.stats;
        stats.steps += st.steps;
        stats.rejected += st.rejected;
        stats.rhs_evaluations += st.rhs_evaluations;
        stats.jacobian_evaluations += st.jacobian_evaluations;
        stats.lu_decompositions += st.lu_decompositions;
        if let (None, Some(ts)) = (stats.switched_to_implicit_at, st.switched_to_implicit_at) {
            stats.switched_to_implicit_at = Some(ts);
            seg_opts.method = ode::Method::Sdirk;
        }
        if st.steps > 0 && b > a {
            seg_opts.h0 = Some((b - a) / st.steps as f64);
        }
        out_t.extend(sol.t);
        out_y.extend(sol.y);
        y = sol.y_final;
    }
    let history: Vec<Sample> = out_t
        .iter()
        .zip(&out_y)
        .map(|(&t, y)| sample(model, t, y))
        .collect();
    // The last orbit: mean heat, oscillation amplitude.
    let from = t_end - period * orbits.min(1.0);
    let last: Vec<&Sample> = history.iter().filter(|s| s.time_s >= from).collect();
    let m = last.len().max(1) as f64;
    let mean = |f: fn(&Sample) -> f64| last.iter().map(|s| f(s)).sum::<f64>() / m;
    let mut amp: f64 = 0.0;
    for c in 0..3 {
        let (lo, hi) = last
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, s| {
                (a.0.min(s.omega_rad_s[c]), a.1.max(s.omega_rad_s[c]))
            });
        amp = amp.max(0.5 * (hi - lo));
    }
    let (heat_w, lateral_w, rolling_w) = (
        mean(|s| s.heat_w),
        mean(|s| s.lateral_w),
        mean(|s| s.rolling_w),
    );
    Ok((
        BallDynamics {
            start_azimuth_rad: model.start_azimuth_rad,
            history,
            heat_w,
            lateral_w,
            rolling_w,
            oscillation_rad_s: amp,
        },
        stats,
    ))
}

/// The times in (0, t_end) at which the ball passes a point of the load track, ascending
/// (closer than 1e-9 of an orbit to each other or to the ends dropped).
fn kink_times(model: &BallModel, t_end: f64) -> Vec<f64> {
    let wm = model.cage_rad_s;
    let period = std::f64::consts::TAU / wm.abs();
    let eps = 1e-9 * period;
    let mut out = Vec::new();
    for psi in model.track.azimuths() {
        let mut t = ((psi - model.start_azimuth_rad) / wm).rem_euclid(period);
        while t < t_end - eps {
            if t > eps {
                out.push(t);
            }
            t += period;
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup_by(|b, a| *b - *a <= eps);
    out
}

/// The quasi-static angular velocity of a ball at fixed loads: dω/dt = 0 solved by a
/// damped Newton iteration (forward-difference Jacobian) from race control. Returns ω
/// and the iterations.
pub fn quasi_static_ball(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<([f64; 3], usize, usize), BallError> {
    let mut w = Vector3::from(omega0);
    let scale = w.norm().max(1.0);
    let mut f = model.omega_dot(0.0, &w);
    let mut evals = 1;
    for it in 1..=100 {
        let mut jac = Matrix3::zeros();
        for c in 0..3 {
            let h = 1e-7 * scale;
            let mut wp = w;
            wp[c] += h;
            let fp = model.omega_dot(0.0, &wp);
            evals += 1;
            jac.set_column(c, &((fp - f) / h));
        }
        let step = jac.lu().solve(&(-f)).ok_or_else(|| {
            BallError::Dynamics(format!(
                "ball {ball}: singular moment Jacobian at ω = ({:.6e}, {:.6e}, {:.6e}) rad/s",
                w[0], w[1], w[2]
            ))
        })?;
        // Backtrack on |dω/dt| (halving, at most 30 times).
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..30 {
            let wt = w + lambda * step;
            let ft = model.omega_dot(0.0, &wt);
            evals += 1;
            if ft.norm() < f.norm() || ft.norm() == 0.0 {
                accepted = Some((wt, ft));
                break;
            }
            lambda *= 0.5;
        }
        let Some((wn, fn_)) = accepted else {
            if (step.norm()) <= 1e-13 * scale {
                return Ok((w.into(), it, evals));
            }
            return Err(BallError::Dynamics(format!(
                "ball {ball}: quasi-static moment balance stalled after {it} iterations (|dω/dt| = {:.3e} rad/s², step {:.3e} rad/s)",
                f.norm(),
                step.norm()
            )));
        };
        let moved = (wn - w).norm();
        w = wn;
        f = fn_;
        if moved <= 1e-13 * scale {
            return Ok((w.into(), it, evals));
        }
    }
    Err(BallError::Dynamics(format!(
        "ball {ball}: quasi-static moment balance did not converge in 100 iterations (|dω/dt| = {:.3e} rad/s²)",
        f.norm()
    )))
}

/// The ball dynamics of a race-control analysis (`method` quasi-static or
/// time-simulation). Under an axisymmetric load (no radial load) every ball sees the
/// same loads at every position, so one ball is solved and its result shared (the balls
/// differ only by their start azimuth).
pub fn run(
    input: &BallInput,
    geom: &BallGeometry,
    balls: &[BallResult],
    cancel: Cancel,
) -> Result<DynamicsResult, BallError> {
    let d = &input.dynamics;
    if d.slices < 1
        || d.orbits.is_nan()
        || d.orbits <= 0.0
        || d.tolerance.is_nan()
        || d.tolerance <= 0.0
    {
        return Err(BallError::InvalidInput(format!(
            "dynamics: need slices ≥ 1, orbits > 0 and tolerance > 0 (got {}, {}, {})",
            d.slices, d.orbits, d.tolerance
        )));
    }
    let curve = input.traction.curve();
    let track = LoadTrack::new(balls);
    let cage = balls.iter().map(|b| b.cage_rad_s).sum::<f64>() / balls.len().max(1) as f64;
    let op = &input.operating;
    let axisymmetric = op.radial_load_n == 0.0;
    // One ball: its dynamics, steps, RHS evaluations and whether Rodas4 took over.
    let solve_one = |j: usize,
                     b: &BallResult|
     -> Result<(BallDynamics, usize, usize, bool), BallError> {
        let model = BallModel {
            diameter_m: geom.ball_diameter_m,
            centre_radius_m: 0.5 * geom.pitch_diameter_m,
            inertia_kg_m2: geom.ball_inertia_kg_m2,
            cage_rad_s: cage,
            ring_speeds_rad_s: (op.inner_speed_rad_s, op.outer_speed_rad_s),
            groove_curvatures: (geom.inner_groove_curvature, geom.outer_groove_curvature),
            curve: &curve,
            slices: d.slices,
            track: &track,
            start_azimuth_rad: b.azimuth_rad,
        };
        // Race control: ω = (ω_a, ω_r, 0) (no gyroscopic pivoting).
        let omega0 = [b.ball_axial_rad_s, b.ball_radial_rad_s, 0.0];
        match d.method {
            Method::TimeSimulation => {
                let method = match d.integrator {
                    Integrator::Auto => ode::Method::Auto,
                    Integrator::Dopri5 => ode::Method::DormandPrince45,
                    Integrator::Rodas4 => ode::Method::Sdirk,
                };
                let (bd, st) =
                    simulate_ball_with(&model, omega0, d.orbits, d.tolerance, method, j, cancel)?;
                Ok((
                    bd,
                    st.steps,
                    st.rhs_evaluations,
                    st.switched_to_implicit_at.is_some(),
                ))
            }
            _ => {
                if cancel.is_cancelled() {
                    return Err(BallError::Cancelled);
                }
                let (w, it, ev) = quasi_static_ball(&model, omega0, j)?;
                let s = sample(&model, 0.0, &w);
                Ok((
                    BallDynamics {
                        start_azimuth_rad: b.azimuth_rad,
                        history: vec![s],
                        heat_w: s.heat_w,
                        lateral_w: s.lateral_w,
                        rolling_w: s.rolling_w,
                        oscillation_rad_s: 0.0,
                    },
                    it,
                    ev,
                    false,
                ))
            }
        }
    };
    let solved: Vec<(BallDynamics, usize, usize, bool)> = if axisymmetric || balls.len() < 2 {
        // Every ball sees the same loads at every position: solve the first, shift its
        // copies to the others' start azimuths.
        let Some(b0) = balls.first() else {
            return Err(BallError::InvalidInput(
                "dynamics: the load distribution has no balls to simulate".to_string(),
            ));
        };
        let first = solve_one(0, b0)?;
        let mut v = Vec::with_capacity(balls.len());
        for b in &balls[1..] {
            let mut copy: BallDynamics = first.0.clone();
            let shift = b.azimuth_rad - copy.start_azimuth_rad;
            copy.start_azimuth_rad = b.azimuth_rad;
            for s in &mut copy.history {
                s.orbit_deg += shift.to_degrees();
            }
            v.push((copy, 0, 0, false));
        }
        v.insert(0, first);
        v
    } else {
        // Given the load track the balls are independent: solved in parallel (the order
        // and every number are those of a serial loop; each ball's integration is
        // deterministic and owns its state).
        use rayon::prelude::*;
        balls
            .par_iter()
            .enumerate()
            .map(|(j, b)| solve_one(j, b))
            .collect::<Result<Vec<_>, _>>()?
    };
    let (mut steps, mut evals, mut switched) = (0, 0, false);
    let mut out = Vec::with_capacity(solved.len());
    for (bd, st, ev, sw) in solved {
        steps += st;
        evals += ev;
        switched |= sw;
        out.push(bd);
    }
    let amp = out.iter().map(|b| b.oscillation_rad_s).fold(0.0, f64::max);
    let scale = out
        .iter()
        .filter_map(|b| b.history.last())
        .map(|s| Vector3::from(s.omega_rad_s).norm())
        .fold(1.0, f64::max);
    Ok(DynamicsResult {
        method: d.method,
        integrator: match (d.method, d.integrator) {
            (Method::TimeSimulation, Integrator::Rodas4) => "rodas4".to_string(),
            (Method::TimeSimulation, _) if switched => "dopri5→rodas4".to_string(),
            (Method::TimeSimulation, _) => "dopri5".to_string(),
            _ => "newton".to_string(),
        },
        steps,
        rhs_evaluations: evals,
        steady: amp <= 1e-6 * scale,
        oscillation_amplitude_rad_s: amp,
        balls: out,
    })
}

#[path = "dynamics_jacobian.rs"]
mod jacobian;

#[cfg(test)]
#[path = "dynamics_tests.rs"]
mod tests;
