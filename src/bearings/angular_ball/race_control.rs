//! Jones's race-control kinematics (seed 001 eqs. 2-9 … 2-13), written in vectors.
//!
//! # Frame
//! At the ball centre: `a` along the bearing axis, `r` radially outward, `t = a × r` the
//! direction of orbital motion (right-handed (a, r, t)). The outer contact lies at
//! p_o = (D/2)(sin α_o, cos α_o, 0) and the inner at p_i = −(D/2)(sin α_i, cos α_i, 0):
//! the inner contact is the outer one turned by 180° (the seed's "α_i + 180°" of
//! 2-9b/c). The ball's absolute angular velocity is ω = (ω_a, ω_r, ω_t); race control
//! has no gyroscopic pivoting, ω_t = 0 (Chen's ω_y).
//!
//! # Equations
//! Sliding of the ball on race j (speed Ω_j about `a`) at the point p of the ball, with the
//! ball centre orbiting at ω_m on the radius R_b:
//! ```text
//! s = ω_m R_b t − Ω_j (R_b + p_r) t + ω × p.
//! ```
//! * No gross sliding at each contact centre (2-9b, c): s_t(p_j) = 0, i.e.
//!   ω_m R_b + ω_a p_r − ω_r p_a = Ω_j (R_b + p_r).
//! * No spin on the controlling race c (2-9a): (ω − Ω_c a)·n_c = 0, n the outward normal
//!   from the ball centre to the contact.
//!
//! Three linear equations in (ω_a, ω_r, ω_m). Then, per contact:
//! * spin ω_s = (ω − Ω_j a)·n_j (2-10), signed;
//! * roll ω_roll = |(ω − Ω_j a)·τ_j|, τ_j the in-plane tangent ⟂ n_j (2-11);
//! * spin-to-roll ω_s/ω_roll (2-12);
//! * rolling (entrainment) speed: the mean of the race and ball surface speeds relative to
//!   the contact, which moves with the cage.
//!
//! The gyroscopic moment the contacts must supply is M_g = J ω_m ω_r along t (the
//! precession of the ball's angular momentum about the bearing axis).

use nalgebra::{Matrix3, Vector3};

use super::error::BallError;
use crate::physics::contact::point::Race;

/// Kinematics at one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactKinematics {
    /// ω_s, spin of the ball relative to the race about the contact normal (outward from the
    /// ball centre), rad/s (2-10).
    pub spin_rad_s: f64,
    /// |ω_roll|, rolling angular velocity of the ball relative to the race, rad/s (2-11).
    pub roll_rad_s: f64,
    /// ω_s/ω_roll (2-12).
    pub spin_to_roll: f64,
    /// Entrainment speed: mean surface speed in the rolling direction relative to the
    /// contact, m/s.
    pub rolling_speed_m_s: f64,
    /// Surface speed of the race relative to the contact (rolling direction), m/s.
    pub race_surface_speed_m_s: f64,
}

/// The race-control solution for one ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RaceKinematics {
    /// The race that does not spin.
    pub control: Race,
    /// ω_m, orbital (cage) speed, rad/s.
    pub cage_rad_s: f64,
    /// ω_a, axial component of the ball's absolute angular velocity, rad/s.
    pub ball_axial_rad_s: f64,
    /// ω_r, radial component, rad/s (Chen's ω_z).
    pub ball_radial_rad_s: f64,
    /// |ω − ω_m a|, the ball's rotation speed relative to the cage, rad/s.
    pub ball_spin_rad_s: f64,
    /// Inner contact.
    pub inner: ContactKinematics,
    /// Outer contact.
    pub outer: ContactKinematics,
}

impl RaceKinematics {
    /// M_g = J·ω_m·ω_r, N·m (along the rolling direction t), for the ball inertia J (kg·m²).
    pub fn gyroscopic_moment_nm(&self, inertia_kg_m2: f64) -> f64 {
        inertia_kg_m2 * self.cage_rad_s * self.ball_radial_rad_s
    }
}

/// Inputs of [`race_control`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinematicsInput {
    /// D, m.
    pub ball_diameter_m: f64,
    /// R_b, radius of the ball centre, m.
    pub ball_centre_radius_m: f64,
    /// α_i, rad.
    pub inner_angle_rad: f64,
    /// α_o, rad.
    pub outer_angle_rad: f64,
    /// Ω_i, rad/s.
    pub inner_speed_rad_s: f64,
    /// Ω_o, rad/s.
    pub outer_speed_rad_s: f64,
}

/// Solve eqs. 2-9a…c with `control` as the controlling race.
pub fn race_control(k: &KinematicsInput, control: Race) -> Result<RaceKinematics, BallError> {
    let h = 0.5 * k.ball_diameter_m;
    let rb = k.ball_centre_radius_m;
    let (si, ci) = k.inner_angle_rad.sin_cos();
    let (so, co) = k.outer_angle_rad.sin_cos();
    let n_i = [-si, -ci];
    let n_o = [so, co];
    let p_i = [h * n_i[0], h * n_i[1]];
    let p_o = [h * n_o[0], h * n_o[1]];
    let (wi, wo) = (k.inner_speed_rad_s, k.outer_speed_rad_s);
    let (n_c, w_c) = match control {
        Race::Inner => (n_i, wi),
        Race::Outer => (n_o, wo),
    };
    let m = Matrix3::new(
        p_i[1], -p_i[0], rb, //
        p_o[1], -p_o[0], rb, //
        n_c[0], n_c[1], 0.0,
    );
    let rhs = Vector3::new(wi * (rb + p_i[1]), wo * (rb + p_o[1]), w_c * n_c[0]);
    let singular = || BallError::SingularKinematics {
        inner_deg: k.inner_angle_rad.to_degrees(),
        outer_deg: k.outer_angle_rad.to_degrees(),
    };
    let x = m.lu().solve(&rhs).ok_or_else(singular)?;
    if !x.iter().all(|v| v.is_finite()) {
        return Err(singular());
    }
    let (wa, wr, wm) = (x[0], x[1], x[2]);
    let contact = |n: [f64; 2], p: [f64; 2], w: f64, race: Race| {
        let rel = [wa - w, wr];
        // The controlling race does not spin: (2-9a) is one of the three equations solved,
        // so its spin is zero by construction; the LU answer meets it only to round-off
        // (~1e-13 rad/s against spins of 10³ rad/s), which would otherwise show in the
        // reports as noise whose sign and size depend on the last bit of the angles.
        let spin = if race == control {
            0.0
        } else {
            rel[0] * n[0] + rel[1] * n[1]
        };
        // In-plane tangent ⟂ n: τ = (n_r, −n_a).
        let roll = (rel[0] * n[1] - rel[1] * n[0]).abs();
        let race_t = (w - wm) * (rb + p[1]);
        let ball_t = (wa - wm) * p[1] - wr * p[0];
        ContactKinematics {
            spin_rad_s: spin,
            roll_rad_s: roll,
            spin_to_roll: if roll > 0.0 { spin / roll } else { 0.0 },
            rolling_speed_m_s: (0.5 * (race_t + ball_t)).abs(),
            race_surface_speed_m_s: race_t.abs(),
        }
    };
    Ok(RaceKinematics {
        control,
        cage_rad_s: wm,
        ball_axial_rad_s: wa,
        ball_radial_rad_s: wr,
        ball_spin_rad_s: (wa - wm).hypot(wr),
        inner: contact(n_i, p_i, wi, Race::Inner),
        outer: contact(n_o, p_o, wo, Race::Outer),
    })
}

/// The spinning-friction moment of a contact with Hertzian pressure and Coulomb
/// coefficient µ: M_s = (3/8)·µ·Q·a·E(k), N·m (2-13a; a the semi-major axis, m, E the
/// complete elliptic integral of the second kind, Chen's E₂).
pub fn spin_moment_nm(mu: f64, load_n: f64, semi_major_m: f64, second_kind: f64) -> f64 {
    0.375 * mu * load_n * semi_major_m * second_kind
}

/// Jones/Harris choice of the controlling race: the outer race controls when
/// Q_o·a_o·E_o·cos(α_i − α_o) > Q_i·a_i·E_i (it resists spinning more), else the inner.
pub fn controlling_race(
    inner: (f64, f64, f64),
    outer: (f64, f64, f64),
    inner_angle_rad: f64,
    outer_angle_rad: f64,
) -> Race {
    let (qi, ai, ei) = inner;
    let (qo, ao, eo) = outer;
    if qo * ao * eo * (inner_angle_rad - outer_angle_rad).cos() > qi * ai * ei {
        Race::Outer
    } else {
        Race::Inner
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::angular_ball::input::rpm;

    const D: f64 = 12e-3;
    const DM: f64 = 115e-3;

    fn input(ai_deg: f64, ao_deg: f64, n_rpm: f64) -> KinematicsInput {
        KinematicsInput {
            ball_diameter_m: D,
            ball_centre_radius_m: DM / 2.0,
            inner_angle_rad: ai_deg.to_radians(),
            outer_angle_rad: ao_deg.to_radians(),
            inner_speed_rad_s: rpm(n_rpm),
            outer_speed_rad_s: 0.0,
        }
    }

    /// Seed ch. 6: Bearing A at 10 000 rpm with the printed operating angles α_i 21.06°,
    /// α_o 13.96°, outer race control: inner spin 938.1 rad/s (±0.1 %, the brief's band;
    /// we get 938.28, +0.02 %), no outer spin (1e-9 rad/s), and the spin heat
    /// M_s·ω_s = 2.62 W per ball (±1 %) with µ = 0.054, Q_i = 163.7 N, a = 0.8259 mm and
    /// E₂ = 1.0209 as printed (2-13a, b).
    #[test]
    fn chen_bearing_a_inner_spin_and_heat() {
        let k = race_control(&input(21.06, 13.96, 10_000.0), Race::Outer).unwrap();
        assert!(
            (k.inner.spin_rad_s / 938.1 - 1.0).abs() < 1e-3,
            "{}",
            k.inner.spin_rad_s
        );
        assert!(k.outer.spin_rad_s.abs() < 1e-9);
        let heat = spin_moment_nm(0.054, 163.7, 0.8259e-3, 1.0209) * k.inner.spin_rad_s;
        assert!((heat / 2.62 - 1.0).abs() < 0.01, "{heat}");
        // The rolling speed: 29.73 m/s at the inner contact (race and ball agree: no
        // gross sliding). Chen's 29.8 m/s comes from his ch. 6 formula
        // u = Ω(d_m² − D²cos²α₀)/(4d_m), the simple cage speed at the free angle, which
        // gives 29.80 (tested to 0.1 %); the race-control value is 0.25 % lower
        // (tolerance 0.5 %).
        let simple =
            rpm(10_000.0) * (DM * DM - (D * 15f64.to_radians().cos()).powi(2)) / (4.0 * DM);
        assert!((simple / 29.8 - 1.0).abs() < 1e-3, "{simple}");
        assert!((k.inner.rolling_speed_m_s / 29.8 - 1.0).abs() < 5e-3);
        assert!(
            (k.inner.rolling_speed_m_s - k.inner.race_surface_speed_m_s).abs() < 1e-9,
            "no gross sliding at the contact centre"
        );
    }

    /// Equal contact angles α: the cage runs at ω_i(1 − γ)/2, γ = D cos α/d_m (1e-12
    /// relative), whichever race controls; at α = 0 there is no spin on either race
    /// (1e-9 rad/s) and the ball rolls about the axis only.
    #[test]
    fn equal_angles_and_zero_angle_limits() {
        for alpha in [0.0, 15.0, 40.0] {
            for control in [Race::Outer, Race::Inner] {
                let k = race_control(&input(alpha, alpha, 6_000.0), control).unwrap();
                let gamma = D * f64::to_radians(alpha).cos() / DM;
                let want = rpm(6_000.0) * (1.0 - gamma) / 2.0;
                assert!(
                    (k.cage_rad_s / want - 1.0).abs() < 1e-12,
                    "{alpha} {control:?}"
                );
            }
        }
        let k = race_control(&input(0.0, 0.0, 10_000.0), Race::Outer).unwrap();
        assert!(k.inner.spin_rad_s.abs() < 1e-9 && k.outer.spin_rad_s.abs() < 1e-9);
        assert!(k.ball_radial_rad_s.abs() < 1e-9);
        // Inner race control: no inner spin, outer spins.
        let k = race_control(&input(21.06, 13.96, 10_000.0), Race::Inner).unwrap();
        assert!(k.inner.spin_rad_s.abs() < 1e-9 && k.outer.spin_rad_s.abs() > 100.0);
    }

    /// The controlling race's spin is reported as exactly zero, (2-9a) being one of the
    /// equations solved: here the solved ω meets (2-9a), (ω − Ω_c a)·n_c = 0, to 1e-13 of
    /// |ω − Ω_c a| (round-off of the 3×3 LU), and the non-controlling race's spin equals
    /// (ω − Ω_j a)·n_j formed from the same ω bit for bit, over angles from 0° to 80°,
    /// both races controlling, inner and outer ring turning.
    #[test]
    fn controlling_race_meets_2_9a() {
        for (ai, ao) in [(0.0, 0.0), (21.06, 13.96), (68.73, 51.7), (80.0, 30.0)] {
            for control in [Race::Outer, Race::Inner] {
                for (wi, wo) in [(rpm(10_000.0), 0.0), (0.0, rpm(8_000.0))] {
                    let mut inp = input(ai, ao, 0.0);
                    inp.inner_speed_rad_s = wi;
                    inp.outer_speed_rad_s = wo;
                    let k = race_control(&inp, control).unwrap();
                    let (si, ci) = f64::to_radians(ai).sin_cos();
                    let (so, co) = f64::to_radians(ao).sin_cos();
                    let spin = |n: [f64; 2], w: f64| {
                        let rel = [k.ball_axial_rad_s - w, k.ball_radial_rad_s];
                        (rel[0] * n[0] + rel[1] * n[1], rel[0].hypot(rel[1]))
                    };
                    let (inner, outer) = (spin([-si, -ci], wi), spin([so, co], wo));
                    let (c, free, got) = match control {
                        Race::Inner => (inner, outer, (k.inner, k.outer)),
                        Race::Outer => (outer, inner, (k.outer, k.inner)),
                    };
                    assert!(c.0.abs() <= 1e-13 * c.1, "{ai} {ao} {control:?}: {c:?}");
                    assert_eq!(got.0.spin_rad_s, 0.0);
                    assert_eq!(got.1.spin_rad_s, free.0);
                }
            }
        }
    }

    /// The spin moment (2-13a) equals the integral of µ·p·r over the Hertz ellipse
    /// (p = p₀√(1 − x²/a² − y²/b²), r the distance from the centre), computed here by a
    /// midpoint rule on a 2000 × 2000 grid in elliptic polar coordinates: 1e-4 relative.
    #[test]
    fn spin_moment_is_the_integral_of_mu_p_r() {
        let (mu, q, a, b): (f64, f64, f64, f64) = (0.054, 163.7, 0.8259e-3, 0.0938e-3);
        let e2 = 1.0 - (b / a).powi(2);
        let n = 2000;
        let p0 = 1.5 * q / (std::f64::consts::PI * a * b);
        let mut m = 0.0;
        for i in 0..n {
            let rho = (i as f64 + 0.5) / n as f64;
            for j in 0..n {
                let th = (j as f64 + 0.5) / n as f64 * 2.0 * std::f64::consts::PI;
                let (x, y) = (a * rho * th.cos(), b * rho * th.sin());
                let p = p0 * (1.0 - rho * rho).sqrt();
                let da = a * b * rho / n as f64 * 2.0 * std::f64::consts::PI / n as f64;
                m += mu * p * x.hypot(y) * da;
            }
        }
        // E(e²) by the AGM-free series is overkill: compare against the formula with the
        // exact E from the crate's elliptic integrals.
        let e = crate::physics::contact::elliptic::complete_integrals_with_complement(e2, 1.0 - e2)
            .unwrap()
            .second_kind;
        let formula = spin_moment_nm(mu, q, a, e);
        assert!((m / formula - 1.0).abs() < 1e-4, "{m} vs {formula}");
    }

    #[test]
    fn auto_choice_follows_spin_resistance() {
        let a = (21f64.to_radians(), 14f64.to_radians());
        assert_eq!(
            controlling_race((160.0, 0.8e-3, 1.02), (250.0, 0.9e-3, 1.02), a.0, a.1),
            Race::Outer
        );
        assert_eq!(
            controlling_race((400.0, 0.9e-3, 1.02), (250.0, 0.9e-3, 1.02), a.0, a.1),
            Race::Inner
        );
    }
}
