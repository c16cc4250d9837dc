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
//! about the ball centre. The orbital speed ω_m (Chen's fourth unknown, 2-14a) is found
//! one of two ways (`dynamics.orbit`):
//!
//! - **cage** (the default): held at race control's cage speed (a cage-guided ball set;
//!   the ball's orbital equation is not integrated — the tangential force it would need
//!   is the cage's, and its power −F_t ω_m R_b enters the ball's energy balance);
//! - **free** (2-14a with F_cage = F_drag = 0): m R_b dω_m/dt = F_t, the resultant
//!   traction along t, and the ball's azimuth θ = ∫ω_m dt is integrated too, so the
//!   state is (ω_a, ω_r, ω_t, ω_m, θ) and the loads are those of the track at the
//!   ball's own θ. The frame now turns at the ball's own ω_m(t); J dω/dt = M − J ω_m a × ω
//!   holds as written (the frame's angular velocity enters only through ω_m a × ω). The
//!   rings' friction power then goes into heat and the ball's kinetic energy
//!   ½J|ω|² + ½m(ω_m R_b)² alone; at a steady state F_t = 0 (the quasi-static method
//!   solves that orbital balance with dω/dt = 0). Under Chen's 500 N radial load on
//!   Bearing B the free orbit brings the peak heat per ball from 176 W (3.0× the axial
//!   case) to 124 W (2.35×), against the seed's ≈ 100 W (≈ 2×): see
//!   `free_orbit_heat_against_the_seed`.
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

use nalgebra::{DMatrix, DVector, Vector3};

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, Integrator, Method, Orbit};
pub use super::load_track::{BallLoads, ContactLoads, LoadTrack};
use super::results::BallResult;
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
    /// ω_m, rad/s: the held orbital speed ([`Orbit::Cage`]) or the start of the
    /// integrated one ([`Orbit::Free`]).
    pub cage_rad_s: f64,
    /// How ω_m is found.
    pub orbit: Orbit,
    /// m, the ball's mass, kg (the orbital equation 2-14a of [`Orbit::Free`]).
    pub mass_kg: f64,
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

/// One strip of a contact (module docs, "Slices"), in the a–r plane of the frame
/// (every point of a contact's centre line has p_t = 0).
#[derive(Debug, Clone, Copy)]
pub(super) struct Slice {
    /// q, the strip's Hertz load, N.
    pub q: f64,
    /// p = (p_a, p_r), the centre line's point from the ball centre, m.
    pub p: [f64; 2],
    /// ν = (ν_a, ν_r), the strip's surface normal.
    pub nu: [f64; 2],
    /// d = p·ν, m: the lever of transverse sliding (see [`BallModel::contact`]).
    pub d: f64,
    /// The race surface speed there, Ω_j (R_b + p_r), m/s (along t).
    pub v_race: f64,
}

impl Slice {
    /// The sliding velocity's rolling (s_t, along t) and transverse (s_x, along
    /// e = t × ν) components for ball angular velocity ω and orbital speed ω_m:
    /// s_t = ω_m R_b + ω_a p_r − ω_r p_a − v_race, s_x = ω_t d (module docs, "Sliding").
    #[inline(always)]
    fn sliding(&self, centre_speed: f64, omega: &Vector3<f64>) -> (f64, f64) {
        (
            centre_speed + omega[0] * self.p[1] - omega[1] * self.p[0] - self.v_race,
            omega[2] * self.d,
        )
    }
}

impl BallModel<'_> {
    /// The slices of one contact (module docs, "Slices"; 2-16, 2-17), each handed to
    /// `each`, from the centre of the ellipse outwards in mirror pairs. Shared by the
    /// moments ([`Self::contact_at`]) and their Jacobian, so the two cannot drift apart.
    /// Nothing for an unloaded contact.
    ///
    /// The strip angles φ_k = ξ_k a/R_def are equally spaced and symmetric about the
    /// contact centre, so the strips come in pairs ±φ sharing cos φ, the load q (the
    /// Hertz weight ¾ξ − ¼ξ³ is odd) and p·ν; each pair's (cos φ, sin φ) is turned
    /// from the previous pair's by the fixed rotation (cos Δφ, sin Δφ) instead of
    /// trigonometric calls per strip (the right-hand side's main cost); the
    /// recurrence's rounding (≈ k·1e-16) is far below any tolerance used.
    #[inline(always)]
    pub(super) fn for_each_slice(
        &self,
        inner: bool,
        c: &ContactLoads,
        mut each: impl FnMut(&Slice),
    ) {
        if c.load_n <= 0.0 || c.semi_major_m <= 0.0 {
            return;
        }
        let h = 0.5 * self.diameter_m;
        let (s, co) = c.angle_rad.sin_cos();
        // Outward normals: outer (sin α, cos α), inner turned by 180° (2-9b/c's α_i + 180°).
        let (n, f, w_race) = if inner {
            (
                [-s, -co],
                self.groove_curvatures.0,
                self.ring_speeds_rad_s.0,
            )
        } else {
            ([s, co], self.groove_curvatures.1, self.ring_speeds_rad_s.1)
        };
        let tau = [n[1], -n[0]];
        // 2-17: the mean of the ball's and the groove's transverse curvatures.
        let r_def = 2.0 / (2.0 / self.diameter_m + 1.0 / (f * self.diameter_m));
        // The share of Q between −1 and ξ is ½ + ¾ξ − ¼ξ³ (¾(ξ − ξ³/3) written without
        // a division: the strip loop's divider is its bottleneck).
        let cum = |xi: f64| 0.75 * xi - 0.25 * (xi * xi * xi);
        let nsl = self.slices.max(1);
        let width = 2.0 / nsl as f64;
        let dphi = width * c.semi_major_m / r_def;
        let (ds, dc) = dphi.sin_cos();
        let off = h - r_def;
        // Pair j holds the strips centred on ξ = ±(j + ½)w (even count) or ±j w (odd,
        // j ≥ 1; j = 0 is the centre strip alone, φ = 0).
        let (mut cp, mut sp, first) = if nsl % 2 == 1 {
            each(&Slice {
                q: c.load_n * 2.0 * cum(0.5 * width),
                p: [h * n[0], h * n[1]],
                nu: n,
                d: h,
                v_race: w_race * (self.centre_radius_m + h * n[1]),
            });
            (dc, ds, 1)
        } else {
            let (s2, c2) = (0.5 * dphi).sin_cos();
            (c2, s2, 0)
        };
        let mut emit = |cp: f64, sp: f64, q: f64| {
            // p·ν = (h − R_def) n·ν + R_def, n·ν = cos φ.
            let d = off * cp + r_def;
            let cn = [cp * n[0], cp * n[1]];
            let st = [sp * tau[0], sp * tau[1]];
            for nu in [
                [cn[0] + st[0], cn[1] + st[1]],
                [cn[0] - st[0], cn[1] - st[1]],
            ] {
                let p = [off * n[0] + r_def * nu[0], off * n[1] + r_def * nu[1]];
                each(&Slice {
                    q,
                    p,
                    nu,
                    d,
                    v_race: w_race * (self.centre_radius_m + p[1]),
                });
            }
        };
        let centre = if nsl % 2 == 1 { 0.0 } else { 0.5 };
        for j in first..first + nsl / 2 {
            let xc = (j as f64 + centre) * width;
            let q = c.load_n * (cum(xc + 0.5 * width) - cum(xc - 0.5 * width));
            emit(cp, sp, q);
            (sp, cp) = (sp * dc + cp * ds, cp * dc - sp * ds);
        }
    }

    /// One contact: `inner` selects the race; ω the ball's angular velocity, ω_m the
    /// orbital speed.
    ///
    /// With p and ν in the a–r plane, the sliding s = ω_m R_b t + ω × p − v_race t, its
    /// normal part removed, has the rolling component s_t (along t) and the transverse
    /// s_x = ω_t (p·ν) along e = t × ν (from ω × p's in-plane part ω_t(−p_r, p_a)); the
    /// traction f = −(µq/u)(s_x e + s_t t), u = |s|, has the moment
    /// p × f = −(µq/u)(s_t p_r, −s_t p_a, s_x (p·ν)) (p × t = (p_r, −p_a, 0),
    /// p × e = (p·ν) a_t). The same vector algebra as before, written out per strip.
    pub fn contact_at(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
        orbital_rad_s: f64,
    ) -> ContactPower {
        let mut out = ContactPower::default();
        let vc = orbital_rad_s * self.centre_radius_m;
        self.for_each_slice(inner, c, |sl| {
            let (s_t, s_x) = sl.sliding(vc, omega);
            let u2 = s_t * s_t + s_x * s_x;
            if u2 == 0.0 {
                return;
            }
            let u = u2.sqrt();
            let mu = self.curve.mu(u);
            let k = mu * sl.q / u;
            out.moment += Vector3::new(-k * s_t * sl.p[1], k * s_t * sl.p[0], -k * s_x * sl.d);
            // f = −k (s_x e + s_t t), e = (−ν_r, ν_a, 0).
            out.force += Vector3::new(k * s_x * sl.nu[1], -k * s_x * sl.nu[0], -k * s_t);
            out.rolling_w += k * s_t * s_t;
            out.lateral_w += k * s_x * s_x;
            out.ring_power_w += -k * s_t * sl.v_race;
        });
        out
    }

    /// [`Self::contact_at`] at the held cage speed.
    pub fn contact(&self, inner: bool, c: &ContactLoads, omega: &Vector3<f64>) -> ContactPower {
        self.contact_at(inner, c, omega, self.cage_rad_s)
    }

    /// The moment of one contact's tractions about the ball centre and the traction
    /// force along t, (M, F_t) in N·m and N: what [`Self::contact_at`] gives as `moment`
    /// and `force[2]`, without the rest (the right-hand side needs only these; the
    /// integrator calls it thousands of times per orbit, the powers are evaluated at the
    /// recorded samples only).
    #[inline]
    pub fn contact_moment_force(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
        orbital_rad_s: f64,
    ) -> (Vector3<f64>, f64) {
        let (mut ma, mut mr, mut mt, mut ft) = (0.0, 0.0, 0.0, 0.0);
        let vc = orbital_rad_s * self.centre_radius_m;
        self.for_each_slice(inner, c, |sl| {
            let (s_t, s_x) = sl.sliding(vc, omega);
            let u2 = s_t * s_t + s_x * s_x;
            if u2 == 0.0 {
                return;
            }
            let u = u2.sqrt();
            let k = self.curve.mu(u) * sl.q / u;
            let ks = k * s_t;
            ma -= ks * sl.p[1];
            mr += ks * sl.p[0];
            mt -= k * s_x * sl.d;
            ft -= ks;
        });
        (Vector3::new(ma, mr, mt), ft)
    }

    /// The moment of one contact's tractions about the ball centre at the held cage
    /// speed, N·m.
    pub fn contact_moment(
        &self,
        inner: bool,
        c: &ContactLoads,
        omega: &Vector3<f64>,
    ) -> Vector3<f64> {
        self.contact_moment_force(inner, c, omega, self.cage_rad_s)
            .0
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

    /// dω/dt = M/J − ω_m a × ω (module docs), the cage's ω_m held.
    pub fn omega_dot(&self, t_s: f64, omega: &Vector3<f64>) -> Vector3<f64> {
        let l = self.track.at(self.azimuth(t_s));
        let m = self.contact_moment(true, &l.inner, omega)
            + self.contact_moment(false, &l.outer, omega);
        let a = Vector3::new(1.0, 0.0, 0.0);
        m / self.inertia_kg_m2 - self.cage_rad_s * a.cross(omega)
    }

    /// The free orbit's right-hand side (module docs, the free orbit) at the state
    /// y = (ω_a, ω_r, ω_t, ω_m, θ): (dω/dt, dω_m/dt, dθ/dt) with
    /// dω/dt = M/J − ω_m a × ω, m R_b dω_m/dt = F_t (2-14a, no cage, no drag),
    /// dθ/dt = ω_m; the loads are those of the track at the ball's own θ.
    pub fn free_rates(&self, y: &[f64; 5]) -> [f64; 5] {
        let omega = Vector3::new(y[0], y[1], y[2]);
        let wm = y[3];
        let l = self.track.at(y[4]);
        let (mi, fi) = self.contact_moment_force(true, &l.inner, &omega, wm);
        let (mo, fo) = self.contact_moment_force(false, &l.outer, &omega, wm);
        let a = Vector3::new(1.0, 0.0, 0.0);
        let d = (mi + mo) / self.inertia_kg_m2 - wm * a.cross(&omega);
        let dwm = (fi + fo) / (self.mass_kg * self.centre_radius_m);
        [d[0], d[1], d[2], dwm, wm]
    }

    /// The state dimension: 3 (ω) with the cage's orbit, 5 (ω, ω_m, θ) with the free one.
    pub fn state_dim(&self) -> usize {
        match self.orbit {
            Orbit::Cage => 3,
            Orbit::Free => 5,
        }
    }

    /// The start state from ω₀ at the model's start (ω_m = `cage_rad_s`, θ = the start
    /// azimuth for the free orbit).
    pub fn start_state(&self, omega0: [f64; 3]) -> Vec<f64> {
        match self.orbit {
            Orbit::Cage => omega0.to_vec(),
            Orbit::Free => vec![
                omega0[0],
                omega0[1],
                omega0[2],
                self.cage_rad_s,
                self.start_azimuth_rad,
            ],
        }
    }

    /// (ω, ω_m, θ) of a state at time t (the cage's ω_m and θ(t) for the held orbit).
    pub fn unpack(&self, t_s: f64, y: &[f64]) -> (Vector3<f64>, f64, f64) {
        let omega = Vector3::new(y[0], y[1], y[2]);
        match self.orbit {
            Orbit::Cage => (omega, self.cage_rad_s, self.azimuth(t_s)),
            Orbit::Free => (omega, y[3], y[4]),
        }
    }
}

impl OdeSystem for BallModel<'_> {
    fn dim(&self) -> usize {
        self.state_dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        match self.orbit {
            Orbit::Cage => {
                let d = self.omega_dot(t, &Vector3::new(y[0], y[1], y[2]));
                dydt.copy_from_slice(d.as_slice());
            }
            Orbit::Free => {
                let y5 = [y[0], y[1], y[2], y[3], y[4]];
                dydt.copy_from_slice(&self.free_rates(&y5));
            }
        }
    }
    fn jacobian(&self, t: f64, y: &[f64], jac: &mut nalgebra::DMatrix<f64>) -> bool {
        match self.orbit {
            Orbit::Cage => {
                let j = self.omega_jacobian(t, &Vector3::new(y[0], y[1], y[2]));
                for r in 0..3 {
                    for c in 0..3 {
                        jac[(r, c)] = j[(r, c)];
                    }
                }
            }
            Orbit::Free => {
                let j = self.free_jacobian(&[y[0], y[1], y[2], y[3], y[4]]);
                for r in 0..5 {
                    for c in 0..5 {
                        jac[(r, c)] = j[(r, c)];
                    }
                }
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
    /// ω_m, the orbital speed, rad/s (the cage's with [`Orbit::Cage`]).
    pub orbital_rad_s: f64,
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
    /// The orbital speed ω_m averaged over the last orbit (time simulation) or at the
    /// position, rad/s (the cage's with [`Orbit::Cage`]).
    pub orbital_rad_s: f64,
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
    let (omega, wm, theta) = model.unpack(t, w);
    let l = model.track.at(theta);
    let i = model.contact_at(true, &l.inner, &omega, wm);
    let o = model.contact_at(false, &l.outer, &omega, wm);
    let (lat, roll) = (i.lateral_w + o.lateral_w, i.rolling_w + o.rolling_w);
    Sample {
        time_s: t,
        orbit_deg: theta.to_degrees(),
        omega_rad_s: [w[0], w[1], w[2]],
        orbital_rad_s: wm,
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
    // With the held cage the kink times are known beforehand ([`kink_times`]). With the
    // free orbit the kinks lie at azimuths θ_k the ball reaches at times not known
    // beforehand: each piece ends at the time predicted from its start state
    // ([`FreeKinks`]); the prediction misses θ_k by a tiny angle, which leaves the
    // kink next to a piece's end or start, where a step pays for it with an error of
    // the order of the miss squared (Bearing B, 500 N radial, 5 orbits, rtol 1e-8:
    // rejected steps 178 → 18.5 per ball, RHS evaluations 5 000 → 4 206; every ball's
    // heat within 4e-7 of an rtol-1e-11 solution, where the one piece was off by up to
    // 1e-5: `free_orbit_pieces_between_kinks_are_accurate_and_cheap`).
    let kinky = !model.track.is_uniform();
    let mut cage_bounds = Vec::new();
    if model.orbit == Orbit::Cage && kinky {
        cage_bounds = kink_times(model, t_end);
    }
    cage_bounds.push(t_end);
    let mut cage_bounds = cage_bounds.into_iter();
    let mut free_kinks = FreeKinks::new(model, period, t_end);
    let (mut out_t, mut out_y) = (
        Vec::with_capacity(times.len()),
        Vec::with_capacity(times.len()),
    );
    let mut stats = ode::OdeStats::default();
    let mut y = model.start_state(omega0);
    let mut seg_opts = opts.clone();
    let mut next = 0;
    let mut a = 0.0;
    while a < t_end {
        let b = match model.orbit {
            Orbit::Free if kinky => free_kinks.next_end(a, &y),
            _ => cage_bounds.next().unwrap_or(t_end),
        };
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
        // The next piece's first step: this piece's mean step (with the free orbit not
        // from a piece shorter than the step already set, a sliver left by a missed
        // point, whose one step says nothing of the step size the error control allows).
        let sliver = model.orbit == Orbit::Free && seg_opts.h0.is_some_and(|h| b - a < h);
        if st.steps > 0 && b > a && !sliver {
            seg_opts.h0 = Some((b - a) / st.steps as f64);
        }
        out_t.extend(sol.t);
        out_y.extend(sol.y);
        free_kinks.piece_done(a, &y, b, &sol.y_final);
        y = sol.y_final;
        a = b;
    }
    let history: Vec<Sample> = out_t
        .iter()
        .zip(&out_y)
        .map(|(&t, y)| sample(model, t, y))
        .collect();
    // The last orbit: mean heat, oscillation amplitude, over its samples chosen by index,
    // half-open (t_end − period, t_end]: the orbit's start is the same position as its
    // end and is not counted twice. (A filter `t ≥ t_end − period` counted it or not as
    // t_end·k/n rounded, which moved a ball's mean under radial load by 1.6 %: the
    // equally spaced samples of one period, each once, are the rectangle rule, exact for
    // a periodic signal up to its aliasing.)
    let per_last = ((orbits.min(1.0) / orbits) * n as f64).round() as usize;
    let last: Vec<&Sample> = history
        .iter()
        .skip(history.len().saturating_sub(per_last.clamp(1, n)))
        .collect();
    let m = last.len().max(1) as f64;
    let mean = |f: fn(&Sample) -> f64| last.iter().map(|s| f(s)).sum::<f64>() / m;
    let mut amp: f64 = 0.0;
    let comp = |s: &Sample, c: usize| {
        if c < 3 {
            s.omega_rad_s[c]
        } else {
            s.orbital_rad_s
        }
    };
    // ω's components, and ω_m when it is integrated.
    for c in 0..model.state_dim().min(4) {
        let (lo, hi) = last
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, s| {
                (a.0.min(comp(s, c)), a.1.max(comp(s, c)))
            });
        amp = amp.max(0.5 * (hi - lo));
    }
    let (heat_w, lateral_w, rolling_w, orbital_rad_s) = (
        mean(|s| s.heat_w),
        mean(|s| s.lateral_w),
        mean(|s| s.rolling_w),
        mean(|s| s.orbital_rad_s),
    );
    Ok((
        BallDynamics {
            start_azimuth_rad: model.start_azimuth_rad,
            history,
            heat_w,
            lateral_w,
            rolling_w,
            orbital_rad_s,
            oscillation_rad_s: amp,
        },
        stats,
    ))
}

/// The free orbit's pieces (see [`simulate_ball_with`]): each ends when the ball is
/// predicted to reach the next point θ_k of the load track. From the piece's start
/// state (θ, ω_m) and the orbital acceleration α (the secant of the previous piece, no
/// extra evaluation: ω_m changes by < 1 % per orbit, so α's lag of one piece moves
/// the predicted end by little: measured misses ≤ 4e-4 rad of 0.314 rad pieces),
/// θ_k − θ = ω_m τ + ½ α τ² gives the
/// piece's length τ = 2Δθ/(ω_m + √(ω_m² + 2αΔθ)) (the root that tends to Δθ/ω_m, free
/// of cancellation), for either sense of rotation (ω_m and α taken along it).
struct FreeKinks<'m, 'a> {
    model: &'m BallModel<'a>,
    t_end: f64,
    /// Pieces closer than this to t_end are merged into the last piece, s.
    merge_s: f64,
    /// α, rad/s², from the previous piece (0 before the first).
    accel: f64,
    /// A track point closer than this ahead is not aimed at: the previous piece's end
    /// missed it by that much, rad. 1 % of the mean spacing of the track's points
    /// (2π/n). Measured on Bearing B under 500 N radial load (20 points, 0.314 rad
    /// apart), the misses are ≤ 4e-4 rad = 0.13 % of a piece; aiming at them again
    /// costs a piece of one step (7 evaluations) and then a first step grown from that
    /// sliver: with a gap of 1e-5 rad the ball took 933 steps and 5 838 evaluations,
    /// with 1e-3 rad or more 683 and 4 319. A point left ≤ 1 % of a piece ahead lies
    /// inside the next piece's first step (or the last of this one), whose polynomial
    /// misfits the right-hand side only over the miss: a local error of the order of
    /// the slope jump times the miss squared, which the error control absorbs (19
    /// rejected steps per 5 orbits against 180 integrating in one piece).
    min_gap_rad: f64,
}

impl<'m, 'a> FreeKinks<'m, 'a> {
    fn new(model: &'m BallModel<'a>, period: f64, t_end: f64) -> Self {
        FreeKinks {
            model,
            t_end,
            merge_s: 1e-9 * period,
            accel: 0.0,
            min_gap_rad: 1e-2 * std::f64::consts::TAU
                / model.track.azimuths().count().max(1) as f64,
        }
    }

    /// The end of the piece starting at time `a` in state `y` (ω, ω_m, θ): the predicted
    /// time of the next track point, or t_end when that is nearer (or within
    /// `merge_s` of it), or when the ball does not move along its orbit (ω_m = 0 or the
    /// prediction is not finite: no point will be reached, nothing to split).
    fn next_end(&self, a: f64, y: &[f64]) -> f64 {
        let (wm, theta) = (y[3], y[4]);
        let forward = wm >= 0.0;
        let Some(dtheta) = self
            .model
            .track
            .angle_to_next_point(theta, forward, self.min_gap_rad)
        else {
            return self.t_end;
        };
        let (w, acc) = if forward {
            (wm, self.accel)
        } else {
            (-wm, -self.accel)
        };
        let disc = w * w + 2.0 * acc * dtheta;
        let tau = 2.0 * dtheta / (w + disc.max(0.0).sqrt());
        let b = a + tau;
        // (`b > a` also guards against a piece lost to rounding, which would not advance.)
        if !(tau.is_finite() && b > a) || b >= self.t_end - self.merge_s {
            self.t_end
        } else {
            b
        }
    }

    /// Record the piece from (`a`, `y_a`) to (`b`, `y_b`): its mean orbital
    /// acceleration predicts the next one.
    fn piece_done(&mut self, a: f64, y_a: &[f64], b: f64, y_b: &[f64]) {
        if self.model.orbit == Orbit::Free && b > a {
            let acc = (y_b[3] - y_a[3]) / (b - a);
            if acc.is_finite() {
                self.accel = acc;
            }
        }
    }
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
/// damped Newton iteration (forward-difference Jacobian) from race control. With
/// [`Orbit::Free`] the orbital balance too (2-14a at rest: Σ rolling traction F_t = 0,
/// solved for ω_m together with ω; the ω_m found is [`quasi_static_state`]'s). Returns
/// ω, the iterations and the right-hand-side evaluations.
pub fn quasi_static_ball(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<([f64; 3], usize, usize), BallError> {
    let (y, it, ev) = quasi_static_state(model, omega0, ball)?;
    Ok(([y[0], y[1], y[2]], it, ev))
}

/// [`quasi_static_ball`]'s whole state: (ω_a, ω_r, ω_t) with the cage's orbit,
/// (ω_a, ω_r, ω_t, ω_m, θ) with the free one (θ the start azimuth, where the loads are).
pub fn quasi_static_state(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<(Vec<f64>, usize, usize), BallError> {
    match model.orbit {
        Orbit::Cage => {
            let (w, it, ev) = newton(
                |w: &DVector<f64>| {
                    let d = model.omega_dot(0.0, &Vector3::new(w[0], w[1], w[2]));
                    DVector::from_column_slice(d.as_slice())
                },
                DVector::from_column_slice(&omega0),
                ball,
            )?;
            Ok((w.as_slice().to_vec(), it, ev))
        }
        Orbit::Free => {
            // From the held cage's balance (ω at ω_m = the cage's speed), then ω and ω_m
            // together: from race control directly Newton can leave the basin under
            // radial load (Bearing B, 500 N, the most loaded ball: it stalled at a step
            // of 3e6 rad/s).
            let held = BallModel {
                orbit: Orbit::Cage,
                ..*model
            };
            let (w, it0, ev0) = quasi_static_state(&held, omega0, ball)?;
            let theta = model.start_azimuth_rad;
            let x0 = DVector::from_column_slice(&[w[0], w[1], w[2], model.cage_rad_s]);
            let (x, it, ev) = newton(
                |x: &DVector<f64>| {
                    let r = model.free_rates(&[x[0], x[1], x[2], x[3], theta]);
                    DVector::from_column_slice(&r[..4])
                },
                x0,
                ball,
            )?;
            Ok((vec![x[0], x[1], x[2], x[3], theta], it0 + it, ev0 + ev))
        }
    }
}

/// Damped Newton on f(x) = 0 (every component a rate in rad/s², so one scale): forward
/// differences of step 1e-7·|x₀|, backtracking on |f| (halving, at most 30 times), done
/// when the step moves x by ≤ 1e-13·|x₀|.
fn newton(
    f: impl Fn(&DVector<f64>) -> DVector<f64>,
    x0: DVector<f64>,
    ball: usize,
) -> Result<(DVector<f64>, usize, usize), BallError> {
    let n = x0.len();
    let mut w = x0;
    let scale = w.norm().max(1.0);
    let mut fw = f(&w);
    let mut evals = 1;
    for it in 1..=100 {
        let mut jac = DMatrix::<f64>::zeros(n, n);
        for c in 0..n {
            let h = 1e-7 * scale;
            let mut wp = w.clone();
            wp[c] += h;
            let fp = f(&wp);
            evals += 1;
            jac.set_column(c, &((fp - &fw) / h));
        }
        let step = jac.lu().solve(&(-&fw)).ok_or_else(|| {
            BallError::Dynamics(format!(
                "ball {ball}: singular Jacobian of the quasi-static balance at {:?} (rad/s)",
                w.as_slice()
            ))
        })?;
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..30 {
            let wt = &w + lambda * &step;
            let ft = f(&wt);
            evals += 1;
            if ft.norm() < fw.norm() || ft.norm() == 0.0 {
                accepted = Some((wt, ft));
                break;
            }
            lambda *= 0.5;
        }
        let Some((wn, fn_)) = accepted else {
            if (step.norm()) <= 1e-13 * scale {
                return Ok((w, it, evals));
            }
            return Err(BallError::Dynamics(format!(
                "ball {ball}: quasi-static balance stalled after {it} iterations (|rates| = {:.3e} rad/s², step {:.3e} rad/s)",
                fw.norm(),
                step.norm()
            )));
        };
        let moved = (&wn - &w).norm();
        w = wn;
        fw = fn_;
        if moved <= 1e-13 * scale {
            return Ok((w, it, evals));
        }
    }
    Err(BallError::Dynamics(format!(
        "ball {ball}: quasi-static balance did not converge in 100 iterations (|rates| = {:.3e} rad/s²)",
        fw.norm()
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
            // The free orbit starts from the cage's speed too (released at t = 0).
            cage_rad_s: cage,
            orbit: d.orbit,
            mass_kg: geom.ball_mass_kg,
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
                let (w, it, ev) = quasi_static_state(&model, omega0, j)?;
                let s = sample(&model, 0.0, &w);
                Ok((
                    BallDynamics {
                        start_azimuth_rad: b.azimuth_rad,
                        history: vec![s],
                        heat_w: s.heat_w,
                        lateral_w: s.lateral_w,
                        rolling_w: s.rolling_w,
                        orbital_rad_s: s.orbital_rad_s,
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
