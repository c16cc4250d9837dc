//! The 2-DOF equations of motion (seed 003 eqs. 1–3), their static equilibrium with the
//! cage frozen, the analytic stiffness there, and the energy of the film-off model.

use super::angle::AngleTable;
use super::film::{Contact, ContactLaw};
use super::film_table::FastFilm;
use super::kernel::dry_sums_ten_ninths;
use super::DynamicsError;
#[cfg(test)]
use crate::numerics::ode::Event;
use crate::numerics::ode::{EventSet, FixedSystem, NystromEvents, NystromSystem, OdeSystem};
use std::cell::Cell;

/// The model reduced for the hot loop.
#[derive(Debug)]
pub(crate) struct Rhs {
    pub law: ContactLaw,
    pub mass_kg: f64,
    pub cage_speed_rad_s: f64,
    /// θ_i at t = 0: first_azimuth + 2π(i−1)/m.
    pub phases: Vec<f64>,
    /// (sin, cos) of `phases`: θ_i(t)'s sine and cosine by one rotation of ω_c t's
    /// instead of one `sin_cos` per roller per evaluation.
    pub phase_sin_cos: Vec<(f64, f64)>,
    /// The same as two arrays (the lane loop of [`super::kernel`]).
    pub phase_sin: Vec<f64>,
    /// See `phase_sin`.
    pub phase_cos: Vec<f64>,
    pub force_n: [f64; 2],
    /// Viscous damping coefficient c = 2ζ√(K_xx M), N·s/m (0 in the seed).
    pub damping_n_s_m: f64,
    /// Whether the state carries a 5th component q' = ∂V/∂t (film off: the energy check).
    pub energy_integral: bool,
    /// The state holds (x, y, ẋ/ω_ref, ẏ/ω_ref, q/E_ref): velocities and the energy
    /// integral scaled so that the integrator's one absolute tolerance (rtol × the
    /// static offset) means the same relative accuracy for every component; unscaled,
    /// a velocity near 0 would be held to 1e-14 m/s and force ~5× the steps.
    pub omega_ref: f64,
    /// E_ref, J (|F·r_s| + V(r_s)).
    pub energy_ref: f64,
    /// Film clamps at h = 0 seen by the right-hand side.
    pub clamps: Cell<usize>,
    /// The film solve tabulated for the hot loop (film on; `None`: Newton per roller).
    pub fast_film: Option<FastFilm>,
    /// sin, cos of ω_c t for the hot loop ([`AngleTable`]: a table and a short series
    /// instead of two libm calls per evaluation).
    pub cage_angle: AngleTable,
}

impl Rhs {
    /// θ_i(t) = ω_c t + θ_i(0).
    pub fn angle(&self, i: usize, t: f64) -> f64 {
        self.cage_speed_rad_s * t + self.phases.get(i).copied().unwrap_or(0.0)
    }

    /// Roller `i`'s approach p = x cos θ_i + y sin θ_i and its rate at time `t` in state
    /// `y` = (x, y, ẋ, ẏ, …).
    fn approach(&self, i: usize, t: f64, y: &[f64]) -> (f64, f64) {
        let (s, c) = self.angle(i, t).sin_cos();
        let (x, yy, vx, vy) = (y[0], y[1], y[2] * self.omega_ref, y[3] * self.omega_ref);
        let p = x * c + yy * s;
        // d/dt(x cos θ + y sin θ) includes θ̇ = ω_c (the rollers orbit the loaded shaft).
        let p_dot = vx * c + vy * s + self.cage_speed_rad_s * (yy * c - x * s);
        (p, p_dot)
    }

    /// Roller `i`'s event function alone ([`Contact::gap_m`] without the film solve).
    pub fn gap(&self, i: usize, t: f64, y: &[f64]) -> f64 {
        let (p, p_dot) = self.approach(i, t, y);
        self.law.gap(p, p_dot)
    }

    /// The contact force Σ W_i (cos θ_i, sin θ_i) at a frozen time `t` and position
    /// (x, y) with no motion, and its Jacobian ∂/∂(x, y) (for the static solve).
    pub fn static_reaction(&self, t: f64, x: f64, y: f64) -> ([f64; 2], [[f64; 2]; 2]) {
        let mut f = [0.0; 2];
        let mut k = [[0.0; 2]; 2];
        for i in 0..self.phases.len() {
            let (s, c) = self.angle(i, t).sin_cos();
            let ct = self.law.contact(x * c + y * s, 0.0);
            f[0] += ct.load_n * c;
            f[1] += ct.load_n * s;
            k[0][0] += ct.stiffness_n_m * c * c;
            k[0][1] += ct.stiffness_n_m * c * s;
            k[1][1] += ct.stiffness_n_m * s * s;
        }
        k[1][0] = k[0][1];
        (f, k)
    }

    /// V = Σ 2k_n δ₊^(n+1)/(n+1), the contacts' potential (film off), J. θ_i's sine and
    /// cosine by rotation, δ^(n+1) = δ·δ^n by [`ContactLaw::power`], as in the hot loop.
    pub fn potential(&self, t: f64, x: f64, y: f64) -> f64 {
        let (k, n) = (self.law.stiffness, self.law.exponent);
        let (s0, c0) = (self.cage_speed_rad_s * t).sin_cos();
        let mut v = 0.0;
        for &(sp, cp) in &self.phase_sin_cos {
            let (s, c) = (s0 * cp + c0 * sp, c0 * cp - s0 * sp);
            let d = 0.5 * (x * c + y * s) - self.law.clearance_m;
            if d > 0.0 {
                v += 2.0 * k * d * self.law.power(d) / (n + 1.0);
            }
        }
        v
    }

    /// Every roller's contact at time `t` in state `y` = (x, y, ẋ, ẏ, …), in roller
    /// order, θ_i's sine and cosine by rotating (sin ω_c t, cos ω_c t) by each roller's
    /// phase (one `sin_cos` per call, as the hot loop); with a film, from the tabulated
    /// solve ([`FastFilm::contact`]: within 1e-13 of the Newton solve's load and 1e-12
    /// of its film) instead of a Newton solve per roller and sample.
    pub fn rollers(&self, t: f64, y: &[f64], mut each: impl FnMut(usize, Contact)) {
        let (s0, c0) = (self.cage_speed_rad_s * t).sin_cos();
        let (x, yy, vx, vy) = (y[0], y[1], y[2] * self.omega_ref, y[3] * self.omega_ref);
        for (i, &(sp, cp)) in self.phase_sin_cos.iter().enumerate() {
            let (s, c) = (s0 * cp + c0 * sp, c0 * cp - s0 * sp);
            let p = x * c + yy * s;
            let p_dot = vx * c + vy * s + self.cage_speed_rad_s * (yy * c - x * s);
            each(
                i,
                match &self.fast_film {
                    Some(fast) => fast.contact(&self.law, p, p_dot),
                    None => self.law.contact(p, p_dot),
                },
            );
        }
    }

    /// E = ½M|v|² + V − F·r (film off), J (issue 25, Validation 3).
    pub fn energy(&self, t: f64, y: &[f64]) -> f64 {
        let (vx, vy) = (y[2] * self.omega_ref, y[3] * self.omega_ref);
        0.5 * self.mass_kg * (vx * vx + vy * vy) + self.potential(t, y[0], y[1])
            - self.force_n[0] * y[0]
            - self.force_n[1] * y[1]
    }
}

impl OdeSystem for Rhs {
    fn dim(&self) -> usize {
        if self.energy_integral {
            5
        } else {
            4
        }
    }

    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        self.eval(t, y, dydt);
    }
}

impl<const N: usize> FixedSystem<N> for Rhs {
    #[inline]
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N] {
        let mut out = [0.0; N];
        self.eval(t, y, &mut out);
        out
    }
}

/// Eq. (1) in the Nyström form q'' = f(t, q) for an undamped model whose force depends
/// on position and time only (film off, or the steady film `Squeeze::None`: its
/// squeeze factor is 1 whatever the approach rate): q = (x, y, P), f = (ẍ, ÿ, Q̇) with
/// Q = Ṗ the energy integral ∫∂V/∂t dt / E_ref (film off: its rate depends on x, y
/// and t only; P is not used). Without the energy integral the third component is 0.
impl NystromSystem<3> for Rhs {
    #[inline]
    fn acceleration(&self, t: f64, q: &[f64; 3]) -> [f64; 3] {
        let (s0, c0) = self.cage_angle.sin_cos(self.cage_speed_rad_s * t);
        let [fx, fy, dv] = if self.law.film.is_none() {
            self.dry_sums(q[0], q[1], s0, c0)
        } else {
            // The steady film: the approach rate enters only the squeeze factor (1).
            self.film_sums(q[0], q[1], 0.0, 0.0, s0, c0)
        };
        [
            (self.force_n[0] - fx) / self.mass_kg,
            (self.force_n[1] - fy) / self.mass_kg,
            if self.energy_integral {
                self.cage_speed_rad_s * dv / self.energy_ref
            } else {
                0.0
            },
        ]
    }
}

/// [`ContactEvents`] on the Nyström integrator's (q, v): the same functions of the
/// state (x, y, ẋ/ω_ref, ẏ/ω_ref).
pub(crate) struct NystromContactEvents<'e, 'a>(pub &'e ContactEvents<'a>);

impl NystromContactEvents<'_, '_> {
    #[inline]
    fn state(&self, q: &[f64; 3], v: &[f64; 3]) -> [f64; 4] {
        let w = self.0.rhs.omega_ref;
        [q[0], q[1], v[0] / w, v[1] / w]
    }
}

impl NystromEvents<3> for NystromContactEvents<'_, '_> {
    fn len(&self) -> usize {
        EventSet::<4>::len(self.0)
    }
    fn values(&self, t: f64, q: &[f64; 3], v: &[f64; 3], out: &mut [f64]) {
        self.0.values(t, &self.state(q, v), out);
    }
    fn value(&self, i: usize, t: f64, q: &[f64; 3], v: &[f64; 3]) -> f64 {
        self.0.value(i, t, &self.state(q, v))
    }
}

impl Rhs {
    /// Eqs. (1)–(3) (and the energy integral's rate) at (t, y) into `dydt`.
    #[inline(always)]
    fn eval(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let w = self.omega_ref;
        let (vx, vy) = (y[2] * w, y[3] * w);
        let (s0, c0) = self.cage_angle.sin_cos(self.cage_speed_rad_s * t);
        // Σ W_i cos θ_i, Σ W_i sin θ_i and Σ W_i (y cos θ_i − x sin θ_i).
        let [fx, fy, dv] = if self.law.film.is_none() {
            self.dry_sums(y[0], y[1], s0, c0)
        } else {
            self.film_sums(y[0], y[1], vx, vy, s0, c0)
        };
        // ∂V/∂t at fixed (x, y): Σ 2k δ^n ∂δ/∂t with ∂δ/∂t = ½ ω_c (y cos θ − x sin θ)
        // and 2k δ^n = 2W_i: Σ W_i ω_c (y cos θ − x sin θ).
        let dv_dt = self.cage_speed_rad_s * dv;
        // Eq. (1): M ẍ = −Σ W_i cos θ_i + F_x (F includes gravity), likewise y.
        dydt[0] = vx;
        dydt[1] = vy;
        dydt[2] = (self.force_n[0] - fx - self.damping_n_s_m * vx) / (self.mass_kg * w);
        dydt[3] = (self.force_n[1] - fy - self.damping_n_s_m * vy) / (self.mass_kg * w);
        if self.energy_integral {
            if let Some(q) = dydt.get_mut(4) {
                *q = dv_dt / self.energy_ref;
            }
        }
    }
}

impl Rhs {
    /// The hot loop of the dry contact (film off): eq. (3) with h = 0 and eq. (2), the
    /// load alone (no stiffness, no `Contact`), θ_i's sine and cosine by rotating
    /// (sin ω_c t, cos ω_c t) by each roller's phase; n = 10/9 in lanes of four
    /// ([`super::kernel`]), any other n by `powf`.
    #[inline]
    fn dry_sums(&self, x: f64, y: f64, s0: f64, c0: f64) -> [f64; 3] {
        let clearance = self.law.clearance_m;
        let k = self.law.stiffness;
        if self.law.exponent == 10.0 / 9.0 {
            return dry_sums_ten_ninths(
                &self.phase_sin,
                &self.phase_cos,
                k,
                clearance,
                x,
                y,
                s0,
                c0,
            );
        }
        let (mut fx, mut fy, mut dv) = (0.0, 0.0, 0.0);
        for &(sp, cp) in &self.phase_sin_cos {
            let (s, c) = (s0 * cp + c0 * sp, c0 * cp - s0 * sp);
            let d = 0.5 * (x * c + y * s) - clearance;
            if d > 0.0 {
                let load = k * d.powf(self.law.exponent);
                fx += load * c;
                fy += load * s;
                dv += load * (y * c - x * s);
            }
        }
        [fx, fy, dv]
    }

    /// The film-in-the-deflection loop: each roller's eqs. (2)–(4) from the tabulated
    /// solve, by the lane kernel [`FastFilm::sums`] where the reading has one (the
    /// normalised squeeze and the steady film), else roller by roller ([`FastFilm::load`];
    /// Newton by [`ContactLaw::contact`] without a table); clamps at h = 0 counted.
    #[inline]
    fn film_sums(&self, x: f64, y: f64, vx: f64, vy: f64, s0: f64, c0: f64) -> [f64; 3] {
        if let Some((sums, clamps)) = self.fast_film.as_ref().and_then(|fast| {
            fast.sums(
                &self.law,
                &self.phase_sin,
                &self.phase_cos,
                [x, y, vx, vy],
                self.cage_speed_rad_s,
                s0,
                c0,
            )
        }) {
            if clamps > 0 {
                self.clamps.set(self.clamps.get() + clamps);
            }
            return sums;
        }
        let (mut fx, mut fy, mut dv) = (0.0, 0.0, 0.0);
        let mut clamps = 0;
        for &(sp, cp) in &self.phase_sin_cos {
            let (s, c) = (s0 * cp + c0 * sp, c0 * cp - s0 * sp);
            let p = x * c + y * s;
            // d/dt(x cos θ + y sin θ) includes θ̇ = ω_c (the rollers orbit the loaded shaft).
            let p_dot = vx * c + vy * s + self.cage_speed_rad_s * (y * c - x * s);
            let (load, clamped) = match &self.fast_film {
                Some(fast) => fast.load(&self.law, p, p_dot),
                None => {
                    let ct = self.law.contact(p, p_dot);
                    (ct.load_n, ct.clamped)
                }
            };
            fx += load * c;
            fy += load * s;
            dv += load * (y * c - x * s);
            if clamped {
                clamps += 1;
            }
        }
        if clamps > 0 {
            self.clamps.set(self.clamps.get() + clamps);
        }
        [fx, fy, dv]
    }
}

/// Roller `roller`'s contact loss/regain: the gap crosses 0. At a restart the event
/// that just fired reads the side it crossed to, so that a root located a hair early
/// (Brent's 1e-13) is not found again at the restart.
#[cfg(test)]
pub(crate) struct ContactEvent<'a> {
    pub rhs: &'a Rhs,
    pub roller: usize,
    pub start: Option<(f64, f64)>,
}

#[cfg(test)]
impl Event for ContactEvent<'_> {
    fn value(&self, t: f64, y: &[f64]) -> f64 {
        if let Some((t0, sign)) = self.start {
            if t == t0 {
                return sign * f64::MIN_POSITIVE;
            }
        }
        // The gap is p/2 − C (+ a film ≥ 0) with |p| ≤ |r|: while −C − |r|/2 > 0 (an
        // interference larger than half the shaft's excursion, as ρ = 5 µm throughout)
        // no roller can lose contact, and that bound, of the gap's sign, is returned
        // without the roller's angle (a sin_cos per roller per step otherwise). The
        // event function's sign, and so every crossing, is unchanged; where the bound
        // is not positive the exact gap is returned.
        let lower = -self.rhs.law.clearance_m - 0.5 * (y[0] * y[0] + y[1] * y[1]).sqrt();
        if lower > 0.0 {
            return lower;
        }
        self.rhs.gap(self.roller, t, y)
    }
    fn terminal(&self) -> bool {
        true
    }
}

/// Every roller's contact loss/regain as one [`EventSet`] for the fixed-size DOP853
/// path: [`ContactEvent`]'s functions, with the interference bound (see there) tested
/// once per step for all rollers rather than once per roller: while it holds (ρ = 5 µm
/// throughout) the events cost one square root per step.
pub(crate) struct ContactEvents<'a> {
    pub rhs: &'a Rhs,
    /// Rollers whose event fired at `t0` (the segment's start) and the side each
    /// crossed to.
    pub forced: Vec<(usize, f64)>,
    pub t0: f64,
}

impl ContactEvents<'_> {
    /// −C − |r|/2: a lower bound of every roller's gap (> 0: none can cross).
    #[inline]
    fn lower_bound(&self, y: &[f64]) -> f64 {
        -self.rhs.law.clearance_m - 0.5 * (y[0] * y[0] + y[1] * y[1]).sqrt()
    }
}

impl<const N: usize> EventSet<N> for ContactEvents<'_> {
    fn len(&self) -> usize {
        self.rhs.phases.len()
    }
    fn values(&self, t: f64, y: &[f64; N], out: &mut [f64]) {
        let lower = self.lower_bound(y);
        if lower > 0.0 && (t != self.t0 || self.forced.is_empty()) {
            out.iter_mut().for_each(|o| *o = lower);
            return;
        }
        for (i, o) in out.iter_mut().enumerate() {
            *o = EventSet::<N>::value(self, i, t, y);
        }
    }
    fn value(&self, i: usize, t: f64, y: &[f64; N]) -> f64 {
        if t == self.t0 {
            if let Some(&(_, sign)) = self.forced.iter().find(|(j, _)| *j == i) {
                return sign * f64::MIN_POSITIVE;
            }
        }
        let lower = self.lower_bound(y);
        if lower > 0.0 {
            return lower;
        }
        self.rhs.gap(i, t, y)
    }
}

/// Static equilibrium with the cage frozen at t = 0: Σ W_i (cos θ_i, sin θ_i) = F, by
/// damped Newton on the analytic Jacobian from a Stribeck-sized first guess. Returns
/// the offset and the stiffness matrix K = ∂(ΣW)/∂r there.
pub(crate) fn static_equilibrium(rhs: &Rhs) -> Result<([f64; 2], [[f64; 2]; 2]), DynamicsError> {
    let f = rhs.force_n;
    let fmag = f[0].hypot(f[1]);
    let m = rhs.phases.len() as f64;
    let (k, n) = (rhs.law.stiffness, rhs.law.exponent);
    // Stribeck: W_max ≈ 4.37 F/m; δ_max = (W_max/k)^(1/n); r ≈ 2(δ_max + C).
    let d_max = (4.37 * fmag / (m * k)).powf(1.0 / n);
    let r0 = 2.0 * (d_max + rhs.law.clearance_m).max(0.5 * d_max);
    let (ux, uy) = if fmag > 0.0 {
        (f[0] / fmag, f[1] / fmag)
    } else {
        (1.0, 0.0)
    };
    let mut r = [ux * r0, uy * r0];
    if fmag == 0.0 {
        r = [0.0, 0.0];
    }
    let residual = |r: &[f64; 2]| {
        let (w, _) = rhs.static_reaction(0.0, r[0], r[1]);
        [w[0] - f[0], w[1] - f[1]]
    };
    let scale = fmag.max(1e-9 * k.powf(1.0 / n));
    let mut res = residual(&r);
    for _ in 0..200 {
        let norm = res[0].hypot(res[1]);
        if norm <= 1e-12 * scale {
            break;
        }
        let (_, kk) = rhs.static_reaction(0.0, r[0], r[1]);
        let det = kk[0][0] * kk[1][1] - kk[0][1] * kk[1][0];
        if !(det.abs() > 0.0 && det.is_finite()) {
            // No contact yet (the clearance is open): step towards the load.
            r = [r[0] + ux * d_max, r[1] + uy * d_max];
            res = residual(&r);
            continue;
        }
        let dx = (kk[1][1] * res[0] - kk[0][1] * res[1]) / det;
        let dy = (kk[0][0] * res[1] - kk[1][0] * res[0]) / det;
        // Backtracking: halve until the residual falls (at most 30 halvings).
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let trial = [r[0] - lambda * dx, r[1] - lambda * dy];
            let rt = residual(&trial);
            if rt[0].hypot(rt[1]) < norm {
                r = trial;
                res = rt;
                accepted = true;
                break;
            }
            lambda *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    let norm = res[0].hypot(res[1]);
    if !(norm <= 1e-9 * scale) {
        return Err(DynamicsError::NoEquilibrium {
            residual_n: norm,
            load_n: fmag,
        });
    }
    let (_, kk) = rhs.static_reaction(0.0, r[0], r[1]);
    Ok((r, kk))
}
