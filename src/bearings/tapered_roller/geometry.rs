//! Roller geometry and mass properties (seed 004 eqs. 16–35) and the speeds, centrifugal
//! force and gyroscopic moment (eqs. 36–39), SI.
//!
//! Coordinates along the roller axis are measured from the apex of the roller cone (which
//! lies on the bearing axis); the big end is the far end. Misprints and OCR gaps resolved
//! here (each tested below):
//! * eq. 17 (garbled): H = √(R_c² − (l_F/2)²), the distance from the crown's centre to the
//!   roller element, so the crown arc meets the flat at ±l_F/2 (a fully crowned roller has
//!   H = R_c);
//! * eq. 18/34 are evaluated as (a² − c²)/(√(R_c² − c²) + √(R_c² − a²)), the same number
//!   without the cancellation of two 2.5 m lengths that differ by 10 µm;
//! * eq. 24–25: the roller is the big cone minus the small one, mass m₂ − m₁ (eq. 36's
//!   "(m₁ + m₂)" would give a centrifugal force larger than the roller load);
//! * eq. 27/29 use the standard solid-cone inertias about the centre of gravity,
//!   I = (3/20)mR² + (3/80)mH² (transverse) and (3/10)mR² (polar);
//! * eq. 31–32: R_E/l_s and r/R₂ are ratios (the sample's "0.8 in" and "0.75 in": R₂ is
//!   0.150 in, so r = 0.75 in would lie outside the roller);
//! * eq. 33: ℓ = [√(R_E² − r²) − H₂ + H₀]·sin α, the distance from the roller midpoint to
//!   the flange reaction's line, which passes through the big-end sphere's centre on the
//!   roller axis, √(R_E² − r²) in front of the flange contact point at H₂.

use thiserror::Error;

use super::input::{Crown, Geometry, GyroInertia, Operating};
use crate::physics::material::Material;

/// Why a geometry cannot be modelled.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GeometryError {
    /// A derived dimension came out impossible.
    #[error("roller geometry: {0}")]
    Invalid(String),
}

/// R_c of a crown given by its drop at the gauge point (eq. 35): with s = √(R² − c²),
/// u = √(R² − a²) (a = l_e/2 − G, c = l_F/2), s − u = V′ and s² − u² = a² − c², so
/// s = ½[(a² − c²)/V′ + V′] and R² = s² + c². `None` when the gauge point is not on the
/// crown or the drop is not positive.
pub fn crown_radius_from_drop(g: &Geometry, drop_m: f64) -> Option<f64> {
    let a = 0.5 * g.effective_length_m - g.crown_gauge_m;
    let c = 0.5 * g.flat_length_m;
    if !(drop_m > 0.0 && a > c) {
        return None;
    }
    let s = 0.5 * ((a * a - c * c) / drop_m + drop_m);
    Some((s * s + c * c).sqrt())
}

/// The crown radius of `g`, m (NaN when a drop cannot be converted).
pub fn crown_radius(g: &Geometry) -> f64 {
    match g.crown {
        Crown::Radius(r) => r,
        Crown::Drop(v) => crown_radius_from_drop(g, v).unwrap_or(f64::NAN),
    }
}

/// The crown drop at the gauge point of `g` (eq. 34), m; 0 on the flat, NaN for a radius
/// shorter than the gauge point's distance.
pub fn crown_drop_at_gauge(g: &Geometry) -> f64 {
    match g.crown {
        Crown::Drop(v) => v,
        Crown::Radius(rc) => {
            let a = 0.5 * g.effective_length_m - g.crown_gauge_m;
            let c = 0.5 * g.flat_length_m;
            if a <= c {
                return 0.0;
            }
            let h = ((rc - c) * (rc + c)).sqrt();
            (a * a - c * c) / (h + ((rc - a) * (rc + a)).sqrt())
        }
    }
}

/// Derived roller geometry, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerGeometry {
    /// τ/2, half the included cone angle, rad (eq. 16).
    pub half_cone_rad: f64,
    /// ψ = β − τ/2, angle of the roller axis to the bearing axis, rad.
    pub axis_angle_rad: f64,
    /// H₀, apex to the midpoint of the effective length, m (eq. 19).
    pub h0_m: f64,
    /// H, crown centre to the roller element, m (eq. 17).
    pub crown_offset_m: f64,
    /// R_c, crown radius, m (given or from eq. 35).
    pub crown_radius_m: f64,
    /// V, crown drop at the ends of the effective length, m (eq. 18).
    pub crown_drop_m: f64,
    /// H₁, H₂: apex to the small and big end faces, m (eqs. 20–21).
    pub h1_m: f64,
    /// H₂, m.
    pub h2_m: f64,
    /// R₁, small-end radius, m (eq. 22).
    pub r1_m: f64,
    /// R₂, big-end radius, m (eq. 23).
    pub r2_m: f64,
    /// m = m₂ − m₁, roller mass, kg (eqs. 24–25).
    pub mass_kg: f64,
    /// X′, big end to centre of gravity, m (eq. 28).
    pub cg_from_big_end_m: f64,
    /// X̄, midpoint of the effective length to the centre of gravity, positive toward the
    /// big end, m (eq. 30).
    pub cg_offset_m: f64,
    /// I_p, polar (spin-axis) inertia, kg·m².
    pub polar_inertia_kg_m2: f64,
    /// I_cg, transverse inertia about the centre of gravity, kg·m² (eq. 29).
    pub transverse_inertia_kg_m2: f64,
    /// l_s, slant height of the roller cone to the big end, m (eq. 31).
    pub slant_height_m: f64,
    /// R_E, big-end spherical radius, m.
    pub big_end_radius_m: f64,
    /// r, flange contact point from the roller axis, m.
    pub flange_contact_radius_m: f64,
    /// α, flange reaction's angle to the roller axis, rad (eq. 32).
    pub flange_angle_rad: f64,
    /// ℓ, lever arm of the flange reaction about the roller midpoint, m (eq. 33).
    pub flange_lever_arm_m: f64,
    /// R_m = ½(E·sin β + d·sin(τ/2)): lever of the cup load about the bearing centre
    /// (eqs. 40, 95–96, 117–118), m.
    pub moment_radius_m: f64,
    /// k = cos(α − τ/2)/cos(α + τ/2): cone approach per unit of unshared approach (eq. 43).
    pub approach_ratio: f64,
}

impl RollerGeometry {
    /// Derive the roller geometry from the bearing geometry and the roller's material.
    pub fn new(g: &Geometry, roller: &Material) -> Result<RollerGeometry, GeometryError> {
        let bad = |s: String| Err(GeometryError::Invalid(s));
        let (d, e, beta, le) = (
            g.roller_diameter_m,
            g.pitch_diameter_m,
            g.cup_angle_rad,
            g.effective_length_m,
        );
        if !(d > 0.0 && e > d && beta > 0.0 && beta < std::f64::consts::FRAC_PI_2 && le > 0.0) {
            return bad(format!(
                "need 0 < d < E, 0 < β < 90°, l_e > 0 (d = {d:e} m, E = {e:e} m, β = {:.4}°, l_e = {le:e} m)",
                beta.to_degrees()
            ));
        }
        // Eq. 16 by fixed-point iteration: the map's slope is (d/E)·cos(…)/(1 + …) ≤ d/E < 1.
        let mut t = 0.0_f64;
        for _ in 0..200 {
            let next = ((d / e) * (beta - t).sin()).atan();
            let done = (next - t).abs() <= 1e-16;
            t = next;
            if done {
                break;
            }
        }
        let h0 = d / (2.0 * t.tan()); // eq. 19
        let half_flat = 0.5 * g.flat_length_m;
        let half_le = 0.5 * le;
        if !(g.flat_length_m >= 0.0 && half_flat <= half_le) {
            return bad(format!(
                "flat length {:e} m must lie within the effective length {le:e} m",
                g.flat_length_m
            ));
        }
        let rc = match g.crown {
            Crown::Radius(r) => r,
            Crown::Drop(v) => match crown_radius_from_drop(g, v) {
                Some(r) => r,
                None => {
                    return bad(format!(
                        "crown drop {v:e} m must be positive and its gauge point ({:e} m from the end) must lie on the crown, outside the flat",
                        g.crown_gauge_m
                    ))
                }
            },
        };
        if !(rc > half_le) {
            return bad(format!(
                "crown radius {rc:e} m must exceed half the effective length {half_le:e} m"
            ));
        }
        let h = (rc * rc - half_flat * half_flat).sqrt(); // eq. 17
        let end = (rc * rc - half_le * half_le).sqrt();
        let v = (half_le * half_le - half_flat * half_flat) / (h + end); // eq. 18
        let (st, ct) = t.sin_cos();
        let h1 = h0 - half_le * ct + v * st - g.small_end_break_m; // eq. 20
        let h2 = h0 + half_le * ct + v * st + g.big_end_break_m; // eq. 21
        if !(h1 > 0.0) {
            return bad(format!("small end beyond the cone apex (H₁ = {h1:e} m)"));
        }
        let r1 = h1 * t.tan(); // eq. 22
        let r2 = h2 * t.tan(); // eq. 23
        let rho = roller.density_kg_m3;
        let pi = std::f64::consts::PI;
        let m1 = rho * pi * r1 * r1 * h1 / 3.0; // eq. 24
        let m2 = rho * pi * r2 * r2 * h2 / 3.0; // eq. 25
        let mass = m2 - m1;
        // Cone inertia about its own centre of gravity (eqs. 26–27, standard formula).
        let cone_t = |m: f64, r: f64, hh: f64| m * (0.15 * r * r + 0.0375 * hh * hh);
        let x_prime = (m2 * h2 / 4.0 - m1 * (h2 - 0.75 * h1)) / mass; // eq. 28
        let transverse = cone_t(m2, r2, h2) + m2 * (h2 / 4.0 - x_prime).powi(2)
            - cone_t(m1, r1, h1)
            - m1 * (h2 - 0.75 * h1 - x_prime).powi(2); // eq. 29

        // Mass and inertia are differences of two cones whose height is the apex distance:
        // the inertia's relative round-off grows as ε·(H₀/l_e)³, and a nearly cylindrical
        // roller (a cup angle of a few thousandths of a degree and below on the sample)
        // loses every digit (a negative inertia and NaN forces at geometry.cup_angle =
        // 1e-15, issue 24 item 15). H₀ ≤ 1e4·l_e keeps it to ~2e-4.
        if !(h0 <= 1e4 * le) || !(transverse > 0.0) || !(mass > 0.0) {
            return bad(format!(
                "the cone apex lies {h0:.3e} m from the roller, {:.3e} effective lengths (at most 10 000): the roller is nearly cylindrical and its mass and inertia, differences of two cones (eqs. 24–29), are lost to round-off; a larger geometry.cup_angle (or a roller less nearly cylindrical) is needed",
                h0 / le
            ));
        }
        let polar = 0.3 * (m2 * r2 * r2 - m1 * r1 * r1);
        let x_bar = h2 - x_prime - h0; // eq. 30
        let ls = r2 / st; // eq. 31
        let re = g.big_end_radius_ratio * ls;
        let r = g.flange_contact_ratio * r2;
        if !(r > 0.0 && r < re) {
            return bad(format!(
                "flange contact radius r = {r:e} m must lie between 0 and R_E = {re:e} m"
            ));
        }
        let alpha = (r / re).asin(); // eq. 32
        let lever = ((re * re - r * r).sqrt() - h2 + h0) * alpha.sin(); // eq. 33
        if !(lever > 0.0) {
            return bad(format!(
                "flange lever arm ℓ = {lever:e} m is not positive: the big-end sphere's centre (R_E = {re:e} m) lies behind the roller midpoint"
            ));
        }
        Ok(RollerGeometry {
            half_cone_rad: t,
            axis_angle_rad: beta - t,
            h0_m: h0,
            crown_offset_m: h,
            crown_radius_m: rc,
            crown_drop_m: v,
            h1_m: h1,
            h2_m: h2,
            r1_m: r1,
            r2_m: r2,
            mass_kg: mass,
            cg_from_big_end_m: x_prime,
            cg_offset_m: x_bar,
            polar_inertia_kg_m2: polar,
            transverse_inertia_kg_m2: transverse,
            slant_height_m: ls,
            big_end_radius_m: re,
            flange_contact_radius_m: r,
            flange_angle_rad: alpha,
            flange_lever_arm_m: lever,
            moment_radius_m: 0.5 * (e * beta.sin() + d * t.sin()),
            approach_ratio: (alpha - t).cos() / (alpha + t).cos(),
        })
    }

    /// Crown drop at the gauge distance `gauge_m` from the ends of the effective length
    /// (eq. 34), m; zero where the gauge point lies on the flat.
    pub fn drop_at(&self, g: &Geometry, gauge_m: f64) -> f64 {
        let a = 0.5 * g.effective_length_m - gauge_m;
        let c = 0.5 * g.flat_length_m;
        if a <= c {
            return 0.0;
        }
        let rc = self.crown_radius_m;
        (a * a - c * c) / (self.crown_offset_m + (rc * rc - a * a).sqrt())
    }
}

/// Speeds and inertia loads of every roller (eqs. 36–39), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dynamics {
    /// Ω_E, orbital (cage) speed, rad/s (eq. 38).
    pub cage_rad_s: f64,
    /// ω_R, roller spin about its own axis, rad/s, positive about the axis pointing to the
    /// big end (eq. 39 with its sign from rolling without slip on both races).
    pub roller_spin_rad_s: f64,
    /// F_c, centrifugal force, N (eq. 36 with mass m₂ − m₁).
    pub centrifugal_force_n: f64,
    /// M_G, gyroscopic moment the contacts must supply, N·m (eq. 37).
    pub gyroscopic_moment_nm: f64,
}

impl Dynamics {
    /// Speeds, centrifugal force and gyroscopic moment for the ring speeds of `op`.
    ///
    /// Rolling without slip at the cup contact (radius E/2 + (d/2)cos ψ) and the cone
    /// contact (E/2 − (d/2)cos ψ) gives eq. 38 for Ω_E and ω_R = (E/2d)(1 − c²)(Ω₂ − Ω₁),
    /// c = d·cos ψ/E. The rate of the roller's spin angular momentum as its axis precesses
    /// with the cage is I·ω_R·Ω_E·sin ψ about the tangential direction (eq. 37); with
    /// [`GyroInertia::Polar`] I is the spin-axis inertia, the physically correct one for
    /// that term (the printed I_cg, kept as [`GyroInertia::Transverse`], is the inertia about
    /// a transverse axis, which multiplies the much smaller Ω_E² term the seed omits).
    pub fn new(
        g: &Geometry,
        rg: &RollerGeometry,
        op: &Operating,
        inertia: GyroInertia,
    ) -> Dynamics {
        let (d, e) = (g.roller_diameter_m, g.pitch_diameter_m);
        let psi = rg.axis_angle_rad;
        let c = d * psi.cos() / e;
        let (w1, w2) = (op.outer_speed_rad_s, op.inner_speed_rad_s);
        let cage = 0.5 * (w1 * (1.0 + c) + w2 * (1.0 - c)); // eq. 38
        let spin = e / (2.0 * d) * (1.0 - c * c) * (w2 - w1); // eq. 39
        let fc = rg.mass_kg * cage * cage * (0.5 * e + rg.cg_offset_m * psi.sin()); // eq. 36
        let i = match inertia {
            GyroInertia::Polar => rg.polar_inertia_kg_m2,
            GyroInertia::Transverse => rg.transverse_inertia_kg_m2,
        };
        Dynamics {
            cage_rad_s: cage,
            roller_spin_rad_s: spin,
            centrifugal_force_n: fc,
            gyroscopic_moment_nm: i * spin * cage * psi.sin(), // eq. 37
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::tapered_roller::input::TaperedInput;
    use crate::units::{INCH_M, LBF_N};

    fn sample() -> (TaperedInput, RollerGeometry) {
        let s = TaperedInput::afapl_sample();
        let rg = RollerGeometry::new(&s.geometry, &s.materials.roller).unwrap();
        (s, rg)
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    /// The sample values (seed §3.1 geometry), to 1e-3 relative: the reference
    /// values are given to 3–4 significant digits.
    #[test]
    fn sample_geometry_matches_reference() {
        let (_, rg) = sample();
        assert!(
            rel(rg.half_cone_rad.to_degrees(), 0.800) < 1e-3,
            "{}",
            rg.half_cone_rad.to_degrees()
        );
        assert!(rel(rg.r1_m / INCH_M, 0.1412) < 1e-3, "{}", rg.r1_m / INCH_M);
        assert!(rel(rg.r2_m / INCH_M, 0.1503) < 1e-3, "{}", rg.r2_m / INCH_M);
        assert!(
            rel(rg.crown_drop_m / INCH_M, 4.50e-4) < 1e-3,
            "{}",
            rg.crown_drop_m / INCH_M
        );
        // Eq. 16 holds at the iterate to round-off.
        let g = TaperedInput::afapl_sample().geometry;
        let t = rg.half_cone_rad;
        let resid =
            t.tan() - g.roller_diameter_m / g.pitch_diameter_m * (g.cup_angle_rad - t).sin();
        assert!(resid.abs() < 1e-16);
        // The flange reaction's line and lever: α from r/R_E, ℓ positive and shorter than
        // the roller.
        assert!(rg.flange_lever_arm_m > 0.0 && rg.flange_lever_arm_m < g.effective_length_m);
        assert!(
            rel(
                rg.flange_angle_rad.sin(),
                rg.flange_contact_radius_m / rg.big_end_radius_m
            ) < 1e-15
        );
    }

    /// At 20 000 rpm of the cone: cage speed 988 rad/s and F_c = 77.6 lbf (issue, 1e-3).
    #[test]
    fn sample_speeds_and_centrifugal_force() {
        let (s, rg) = sample();
        let dy = Dynamics::new(&s.geometry, &rg, &s.operating, GyroInertia::Polar);
        assert!(rel(dy.cage_rad_s, 988.0) < 1e-3, "{}", dy.cage_rad_s);
        assert!(
            rel(dy.centrifugal_force_n / LBF_N, 77.6) < 1e-3,
            "{}",
            dy.centrifugal_force_n / LBF_N
        );
        // Rolling without slip: at both contacts the roller surface moves with the race
        // (cage frame), which is what eqs. 38–39 encode. Round-off tolerance.
        let (d, e) = (s.geometry.roller_diameter_m, s.geometry.pitch_diameter_m);
        let c = rg.axis_angle_rad.cos();
        let cone = (s.operating.inner_speed_rad_s - dy.cage_rad_s) * 0.5 * (e - d * c);
        assert!(rel(dy.roller_spin_rad_s * 0.5 * d, cone) < 1e-12);
        let cup = (s.operating.outer_speed_rad_s - dy.cage_rad_s) * 0.5 * (e + d * c);
        assert!(rel(-dy.roller_spin_rad_s * 0.5 * d, cup) < 1e-12);
        // F_c grows as the cage speed squared (exact in the model).
        let mut half = s.operating;
        half.inner_speed_rad_s *= 0.5;
        let dh = Dynamics::new(&s.geometry, &rg, &half, GyroInertia::Polar);
        assert!(rel(dy.centrifugal_force_n, 4.0 * dh.centrifugal_force_n) < 1e-12);
    }

    /// Mass properties against independent formulas: the mass as the frustum volume
    /// πh(R₁² + R₁R₂ + R₂²)/3, the polar inertia as (3/10)m(R₂⁵ − R₁⁵)/(R₂³ − R₁³), the
    /// centre of gravity and the transverse inertia by numerical integration of discs
    /// (midpoint rule, 20 000 discs: 1e-8).
    #[test]
    fn mass_properties_are_those_of_the_frustum() {
        let (s, rg) = sample();
        let rho = s.materials.roller.density_kg_m3;
        let (r1, r2, h1, h2) = (rg.r1_m, rg.r2_m, rg.h1_m, rg.h2_m);
        let len = h2 - h1;
        let pi = std::f64::consts::PI;
        let m = rho * pi * len * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
        assert!(rel(rg.mass_kg, m) < 1e-9);
        let ip = 0.3 * m * (r2.powi(5) - r1.powi(5)) / (r2.powi(3) - r1.powi(3));
        assert!(rel(rg.polar_inertia_kg_m2, ip) < 1e-9);
        let n = 20_000;
        let (mut mm, mut mz, mut mz2, mut mr2) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..n {
            let z = h1 + (i as f64 + 0.5) * len / n as f64;
            let r = z * rg.half_cone_rad.tan();
            let dm = rho * pi * r * r * len / n as f64;
            mm += dm;
            mz += dm * z;
            mz2 += dm * z * z;
            mr2 += dm * r * r / 4.0;
        }
        let zc = mz / mm;
        assert!(rel(h2 - rg.cg_from_big_end_m, zc) < 1e-8);
        let it = mr2 + mz2 - mm * zc * zc;
        assert!(rel(rg.transverse_inertia_kg_m2, it) < 1e-7);
    }

    /// Eq. 35 inverts eq. 34: a crown given by its drop at the gauge point gives back the
    /// radius that has that drop (round-off), with and without a flat.
    #[test]
    fn crown_drop_gauge_inverts_crown_radius() {
        let s = TaperedInput::afapl_sample();
        for flat in [0.0, 0.2 * INCH_M] {
            let mut g = s.geometry;
            g.flat_length_m = flat;
            let rg = RollerGeometry::new(&g, &s.materials.roller).unwrap();
            let gauge = 0.03 * INCH_M;
            let drop = rg.drop_at(&g, gauge);
            let mut g2 = g;
            g2.crown = Crown::Drop(drop);
            g2.crown_gauge_m = gauge;
            assert!(rel(crown_drop_at_gauge(&g), drop) < 1e-12);
            let rg2 = RollerGeometry::new(&g2, &s.materials.roller).unwrap();
            assert!(
                rel(rg2.crown_radius_m, 100.0 * INCH_M) < 1e-9,
                "{}",
                rg2.crown_radius_m / INCH_M
            );
        }
    }

    /// The OCR'd eq. 33/eq. 31 with r = 0.75 in (not a ratio) is rejected with a message:
    /// the flange contact would lie outside the big-end sphere's reach.
    #[test]
    fn impossible_geometry_is_a_typed_error() {
        let s = TaperedInput::afapl_sample();
        let mut g = s.geometry;
        g.flange_contact_ratio = 0.75 * INCH_M / 0.1503 / INCH_M * 12.0;
        assert!(RollerGeometry::new(&g, &s.materials.roller).is_err());
        let mut g = s.geometry;
        g.roller_diameter_m = 2.0 * g.pitch_diameter_m;
        assert!(RollerGeometry::new(&g, &s.materials.roller).is_err());
    }
}
