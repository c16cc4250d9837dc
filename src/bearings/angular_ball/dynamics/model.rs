//! One ball's dynamic model ([`BallModel`]): the slices of its two contacts (2-16,
//! 2-17), their tractions, moments and powers (2-18), and the right-hand side of its
//! equations of motion (2-3, 2-14) that the integrator and the quasi-static Newton call.
//! The hot loop of the ball dynamics, apart from the drivers that call it (`simulate`,
//! `quasi_static`, `run` in `dynamics`); the frame, equations and slicing are described
//! in `dynamics`' module docs.

use nalgebra::Vector3;

use crate::bearings::angular_ball::input::Orbit;
use crate::bearings::angular_ball::load_track::{ContactLoads, LoadTrack};
use crate::numerics::ode::OdeSystem;
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
    pub(super) fn sliding(&self, centre_speed: f64, omega: &Vector3<f64>) -> (f64, f64) {
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
