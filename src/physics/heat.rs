//! Heat generation other than at the contacts, and the bearing's heat breakdown
//! (seed 000 §9.3–9.4), SI; plus the one place where report units are converted.
//!
//! # Readings of the seed
//!
//! * Eq. 9.3 as printed, f = π·η·W·D·|ΔΩ|/dc, is not a force (it lacks a length).
//!   Petroff's film: shear stress η·v/h with v = |ΔΩ|·D/2 and h = dc/2 over the area
//!   π·D·W gives f = π·η·W·D²·|ΔΩ|/dc. Eq. 9.4, H = 0.1928·D·f·|ΔΩ| Btu/hr (D in in,
//!   f in lbf, ΔΩ in rad/s), is exactly the power f·|ΔΩ|·D/2 divided by 2.5933 in-lb/s
//!   per Btu/hr (0.5/2.5933 = 0.1928), which confirms the reading. Tested both ways.
//! * Eq. 9.5's "R" is the pitch *diameter*: Palmgren's viscous torque
//!   M = 10⁻⁷·f₀·(ν·n)^{2/3}·d_m³ N·mm (ν in cSt, n in rpm, d_m in mm) for ν·n ≥ 2000 and
//!   M = 160·10⁻⁷·f₀·d_m³ below; 1.42·10⁻⁵ is the in-lb form (it converts to
//!   1.4504·10⁻⁵, 2.1 % apart — tested). n is the relative ring speed; the power is M·ω
//!   with ω = |Ω₁ − Ω₂| in rad/s (eq. 9.6's 0.0404 is only (2π/60)/2.5933).
//!   The Palmgren law steps by 0.8 % at ν·n = 2000 ((2000)^{2/3} = 158.7 vs 160): the
//!   published form, kept as is.

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::physics::lubrication::Lubricant;
use crate::units::{BTU_PER_HOUR_PER_WATT, INCH_LBF_N_M};

/// Power in W → Btu/hr, for reporting in the seed's units.
pub fn watts_to_btu_per_hour(watts: f64) -> f64 {
    watts * BTU_PER_HOUR_PER_WATT
}

/// Power in Btu/hr → W.
pub fn btu_per_hour_to_watts(btu_per_hour: f64) -> f64 {
    btu_per_hour / BTU_PER_HOUR_PER_WATT
}

/// Torque in N·m → in·lbf, for reporting.
pub fn newton_metres_to_inch_pounds(nm: f64) -> f64 {
    nm / INCH_LBF_N_M
}

/// Relative ring speed below which the friction torque is reported as 0, rad/s.
pub const MIN_RELATIVE_SPEED_RAD_S: f64 = 1e-9;

/// Why a heat term cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum HeatError {
    /// A length or property that must be positive and finite is not.
    #[error("{name} must be positive and finite, got {value}")]
    NotPositive {
        /// The offending input.
        name: &'static str,
        /// Its value (SI).
        value: f64,
    },
}

fn positive(name: &'static str, value: f64) -> Result<f64, HeatError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(HeatError::NotPositive { name, value })
    }
}

/// Petroff friction force at the cage rails, N (seed 000 eq. 9.3, corrected
/// dimensionally): f = π·η·W·D²·|ΔΩ|/dc.
///
/// `viscosity_pa_s` η (Pa·s), `rail_width_m` W (total rail width, m), `mean_diameter_m`
/// D (mean rail/land diameter, m), `diametral_clearance_m` dc (m),
/// `relative_speed_rad_s` ΔΩ = Ω_cg − Ω_guide (rad/s, sign ignored).
///
/// # Errors
/// [`HeatError::NotPositive`] if dc ≤ 0 or D, W, η are not positive and finite (the
/// Petroff film needs a gap).
pub fn cage_rail_friction_force_n(
    viscosity_pa_s: f64,
    rail_width_m: f64,
    mean_diameter_m: f64,
    diametral_clearance_m: f64,
    relative_speed_rad_s: f64,
) -> Result<f64, HeatError> {
    let eta = positive("oil viscosity", viscosity_pa_s)?;
    let w = positive("cage rail width", rail_width_m)?;
    let d = positive("cage rail mean diameter", mean_diameter_m)?;
    let dc = positive("cage rail diametral clearance", diametral_clearance_m)?;
    let dw = if relative_speed_rad_s.is_finite() {
        relative_speed_rad_s.abs()
    } else {
        0.0
    };
    Ok(std::f64::consts::PI * eta * w * d * d * dw / dc)
}

/// Petroff power at the cage rails, W (seed 000 eq. 9.4 in SI): f·|ΔΩ|·D/2 with f from
/// [`cage_rail_friction_force_n`] (same arguments and errors).
pub fn cage_rail_power_w(
    viscosity_pa_s: f64,
    rail_width_m: f64,
    mean_diameter_m: f64,
    diametral_clearance_m: f64,
    relative_speed_rad_s: f64,
) -> Result<f64, HeatError> {
    let f = cage_rail_friction_force_n(
        viscosity_pa_s,
        rail_width_m,
        mean_diameter_m,
        diametral_clearance_m,
        relative_speed_rad_s,
    )?;
    Ok(f * relative_speed_rad_s.abs() * mean_diameter_m / 2.0)
}

/// Cage-rail power of a [`Cage`], W: [`cage_rail_power_w`] with ΔΩ = Ω_cg − Ω₁ for an
/// inner-guided and Ω_cg − Ω₂ for an outer-guided cage (seed 000 eqs. 9.3–9.4, i = 1, 2).
/// Speeds in rad/s, `viscosity_pa_s` η in Pa·s.
///
/// # Errors
/// As [`cage_rail_friction_force_n`].
pub fn cage_rail_power_for(
    cage: &Cage,
    viscosity_pa_s: f64,
    inner_speed_rad_s: f64,
    outer_speed_rad_s: f64,
    cage_speed_rad_s: f64,
) -> Result<f64, HeatError> {
    let guide = match cage.guided_by {
        GuidingRing::Inner => inner_speed_rad_s,
        GuidingRing::Outer => outer_speed_rad_s,
    };
    cage_rail_power_w(
        viscosity_pa_s,
        cage.rail_width_m,
        cage.mean_diameter_m,
        cage.diametral_clearance_m,
        cage_speed_rad_s - guide,
    )
}

/// Kinematic viscosity ν = η/ρ of the lubricant, m²/s; 0 if the density is not positive.
pub fn kinematic_viscosity_m2_s(lubricant: &Lubricant) -> f64 {
    if lubricant.density_kg_m3.is_finite() && lubricant.density_kg_m3 > 0.0 {
        lubricant.viscosity_pa_s / lubricant.density_kg_m3
    } else {
        0.0
    }
}

/// Palmgren's viscous (load-independent) friction torque, N·m (seed 000 eq. 9.5 in SI):
/// M = 10⁻⁷·f₀·(ν·n)^{2/3}·d_m³ N·mm for ν·n ≥ 2000, M = 160·10⁻⁷·f₀·d_m³ N·mm below,
/// with ν in cSt, n in rpm and d_m in mm.
///
/// `drag_factor` f₀ (seed's Ψ, dimensionless), `kinematic_viscosity_m2_s` ν (m²/s),
/// `relative_speed_rad_s` the relative ring speed Ω₁ − Ω₂ (rad/s, sign ignored),
/// `pitch_diameter_m` d_m (m; the seed's "R"). Negative or non-finite inputs count as 0.
pub fn viscous_drag_torque_nm(
    drag_factor: f64,
    kinematic_viscosity_m2_s: f64,
    relative_speed_rad_s: f64,
    pitch_diameter_m: f64,
) -> f64 {
    let clean = |x: f64| if x.is_finite() { x } else { 0.0 };
    let f0 = clean(drag_factor).max(0.0);
    let nu_cst = clean(kinematic_viscosity_m2_s).max(0.0) * 1e6;
    let n_rpm = clean(relative_speed_rad_s).abs() * 30.0 / std::f64::consts::PI;
    let dm_mm = clean(pitch_diameter_m).max(0.0) * 1e3;
    let nu_n = nu_cst * n_rpm;
    let m_nmm = if nu_n >= 2000.0 {
        1e-7 * f0 * nu_n.powf(2.0 / 3.0) * dm_mm.powi(3)
    } else {
        160e-7 * f0 * dm_mm.powi(3)
    };
    m_nmm * 1e-3
}

/// Viscous drag power, W (seed 000 eq. 9.6 in SI): M·|Ω₁ − Ω₂| with M from
/// [`viscous_drag_torque_nm`] (same arguments).
pub fn viscous_drag_power_w(
    drag_factor: f64,
    kinematic_viscosity_m2_s: f64,
    relative_speed_rad_s: f64,
    pitch_diameter_m: f64,
) -> f64 {
    let w = if relative_speed_rad_s.is_finite() {
        relative_speed_rad_s.abs()
    } else {
        0.0
    };
    viscous_drag_torque_nm(
        drag_factor,
        kinematic_viscosity_m2_s,
        relative_speed_rad_s,
        pitch_diameter_m,
    ) * w
}

/// Heat generated in the bearing by mechanism (seed 000 §9), W, and the equivalent
/// friction torque, N·m. Field names are the report contract.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct HeatBreakdown {
    /// Sliding at all inner-raceway lamina contacts (§9.1–9.2), W.
    pub inner_contacts_w: f64,
    /// Sliding at all outer-raceway lamina contacts (§9.1–9.2), W.
    pub outer_contacts_w: f64,
    /// Petroff shear at the cage rails (§9.3), W.
    pub cage_rails_w: f64,
    /// Viscous drag of the lubricant (§9.4), W.
    pub viscous_drag_w: f64,
    /// Sum of the four terms, W.
    pub total_w: f64,
    /// Friction torque total_w/|Ω₁ − Ω₂|, N·m; 0 when the rings turn together
    /// (|Ω₁ − Ω₂| < [`MIN_RELATIVE_SPEED_RAD_S`]): no relative rotation, no torque defined.
    pub friction_torque_nm: f64,
}

impl HeatBreakdown {
    /// Sums the four terms (W) and derives the friction torque from the ring speeds
    /// Ω₁, Ω₂ (rad/s): torque = total/|Ω₁ − Ω₂| (the power dissipated equals the torque
    /// times the relative speed), or 0 at zero relative speed.
    pub fn new(
        inner_contacts_w: f64,
        outer_contacts_w: f64,
        cage_rails_w: f64,
        viscous_drag_w: f64,
        inner_speed_rad_s: f64,
        outer_speed_rad_s: f64,
    ) -> HeatBreakdown {
        let total_w = inner_contacts_w + outer_contacts_w + cage_rails_w + viscous_drag_w;
        let rel = (inner_speed_rad_s - outer_speed_rad_s).abs();
        let friction_torque_nm = if rel.is_finite() && rel >= MIN_RELATIVE_SPEED_RAD_S {
            total_w / rel
        } else {
            0.0
        };
        HeatBreakdown {
            inner_contacts_w,
            outer_contacts_w,
            cage_rails_w,
            viscous_drag_w,
            total_w,
            friction_torque_nm,
        }
    }

    /// Total heat in Btu/hr (report units).
    pub fn total_btu_per_hour(&self) -> f64 {
        watts_to_btu_per_hour(self.total_w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::Bearing;

    use crate::units::{INCH_M, LBF_N, RPM_RAD_S};

    /// Petroff for the aerospace cage (W = 0.25 in, D = 3.75 in, dc = 0.02 in, outer
    /// guided, η = 0.0045 Pa·s), ΔΩ = 800 rad/s, by hand from the film: τ = η·v/h,
    /// v = ΔΩ·D/2, h = dc/2, area π·D·W; F = τ·A, P = F·v. Tolerance 1e-12: same physics,
    /// independent arithmetic.
    #[test]
    fn petroff_by_hand() {
        let (eta, w, d, dc, dw) = (0.0045, 0.25 * INCH_M, 3.75 * INCH_M, 0.02 * INCH_M, 800.0);
        let v = dw * d / 2.0;
        let tau = eta * v / (dc / 2.0);
        let force = tau * std::f64::consts::PI * d * w;
        let f = cage_rail_friction_force_n(eta, w, d, dc, -dw).expect("valid");
        assert!((f - force).abs() < 1e-12 * force);
        let p = cage_rail_power_w(eta, w, d, dc, dw).expect("valid");
        assert!((p - force * v).abs() < 1e-12 * force * v);
        // Hand number: F = π·0.0045·0.00635·0.09525²·800/0.000508 = 1.28260 N.
        assert!((f - 1.282_60).abs() < 1e-5, "{f}");
    }

    /// Eq. 9.4 in its own units: H = 0.1928·D[in]·f[lbf]·|ΔΩ| Btu/hr equals our power in
    /// Btu/hr. Tolerance 0.1 %: the seed's 2.5933 in-lb/s per Btu/hr vs 2.5939 today and
    /// the 4-digit 0.1928.
    #[test]
    fn petroff_matches_eq_9_4() {
        let b = Bearing::example_aerospace();
        let cage_speed = 780.0;
        let p = cage_rail_power_for(&b.cage, 0.0045, 1780.0, 0.0, cage_speed).expect("valid");
        let f = cage_rail_friction_force_n(
            0.0045,
            b.cage.rail_width_m,
            b.cage.mean_diameter_m,
            b.cage.diametral_clearance_m,
            cage_speed,
        )
        .expect("valid");
        let h_btu = 0.1928 * (b.cage.mean_diameter_m / INCH_M) * (f / LBF_N) * cage_speed;
        let ours = watts_to_btu_per_hour(p);
        assert!((ours - h_btu).abs() < 1e-3 * h_btu, "{ours} vs {h_btu}");
        // Inner guided: ΔΩ = Ω_cg − Ω₁.
        let mut inner = b.cage;
        inner.guided_by = GuidingRing::Inner;
        let pi = cage_rail_power_for(&inner, 0.0045, 1780.0, 0.0, cage_speed).expect("valid");
        let pi_want = cage_rail_power_w(
            0.0045,
            inner.rail_width_m,
            inner.mean_diameter_m,
            inner.diametral_clearance_m,
            1000.0,
        )
        .expect("valid");
        assert!((pi - pi_want).abs() < 1e-12 * pi_want);
    }

    /// A zero clearance is an error, not an infinite (or NaN) power.
    #[test]
    fn petroff_rejects_zero_clearance() {
        assert!(matches!(
            cage_rail_power_w(0.0045, 0.006, 0.09, 0.0, 100.0),
            Err(HeatError::NotPositive { .. })
        ));
        assert_eq!(cage_rail_power_w(0.0045, 0.006, 0.09, 5e-4, 0.0), Ok(0.0));
    }

    /// Palmgren SI form by hand: f₀ = 5, ν = 0.0045/950 m²/s (4.737 cSt), n = 17 000 rpm,
    /// d_m = 3.3 in = 83.82 mm → M = 10⁻⁷·5·(80 526)^{2/3}·83.82³ N·mm ≈ 0.549 N·m.
    /// Tolerance 1e-12 on the formula; 0.5 % on the rounded hand value.
    #[test]
    fn palmgren_by_hand() {
        let b = Bearing::example_aerospace();
        let nu = kinematic_viscosity_m2_s(&b.lubricant);
        let w = b.operating.inner_speed_rad_s;
        let m = viscous_drag_torque_nm(5.0, nu, w, b.geometry.pitch_diameter_m);
        let nu_n = (0.0045 / 950.0 * 1e6) * 17_000.0;
        let want = 1e-7 * 5.0 * f64::powf(nu_n, 2.0 / 3.0) * 83.82f64.powi(3) * 1e-3;
        assert!((m - want).abs() < 1e-12 * want);
        assert!((m - 0.549).abs() < 0.005 * 0.549, "{m}");
        let p = viscous_drag_power_w(5.0, nu, -w, b.geometry.pitch_diameter_m);
        assert!((p - m * w).abs() < 1e-12 * p);
        // Low νn branch: 160·10⁻⁷·f₀·d_m³; at rest the torque stays, the power is 0.
        let m0 = viscous_drag_torque_nm(5.0, nu, 0.0, 0.1);
        assert!((m0 - 160e-7 * 5.0 * 1e6 * 1e-3).abs() < 1e-15);
        assert_eq!(viscous_drag_power_w(5.0, nu, 0.0, 0.1), 0.0);
    }

    /// The SI form reproduces the seed's in-lb form T = 1.42·10⁻⁵·Ψ·(νN)^{2/3}·d³ (d in
    /// in, T in in·lbf): the SI constant converts to 1.4504·10⁻⁵, so tolerance 2.5 %
    /// (the seed's constant is 2.1 % low, presumably rounded from another unit set).
    /// Eq. 9.6 (H = 0.0404·N·T Btu/hr with N in rpm) against our power: 0.1 %.
    #[test]
    fn palmgren_matches_inch_form_and_eq_9_6() {
        let (psi, nu_cst, n_rpm, d_in): (f64, f64, f64, f64) = (5.0, 10.0, 12_000.0, 3.3);
        let t_inlb = 1.42e-5 * psi * f64::powf(nu_cst * n_rpm, 2.0 / 3.0) * d_in.powi(3);
        let m = viscous_drag_torque_nm(psi, nu_cst * 1e-6, n_rpm * RPM_RAD_S, d_in * INCH_M);
        let ours_inlb = newton_metres_to_inch_pounds(m);
        assert!(
            (ours_inlb - t_inlb).abs() < 0.025 * t_inlb,
            "{ours_inlb} vs {t_inlb}"
        );
        let h_btu = 0.0404 * n_rpm * ours_inlb;
        let p = viscous_drag_power_w(psi, nu_cst * 1e-6, n_rpm * RPM_RAD_S, d_in * INCH_M);
        assert!((watts_to_btu_per_hour(p) - h_btu).abs() < 1e-3 * h_btu);
    }

    /// Conversions: 1 W = 3.412141633 Btu/hr (exact constant), round trip to 1e-15;
    /// 1 in·lbf = 0.112 984 829 N·m.
    #[test]
    fn unit_conversions() {
        assert_eq!(watts_to_btu_per_hour(1.0), 3.412_141_633);
        assert!((btu_per_hour_to_watts(watts_to_btu_per_hour(123.4)) - 123.4).abs() < 1e-12);
        assert!((newton_metres_to_inch_pounds(0.112_984_829_027_616_7) - 1.0).abs() < 1e-15);
        // The seed's in-lb/s → Btu/hr factor 2.5933 is today's 2.5939 (0.02 % apart).
        let f = 1.0 / watts_to_btu_per_hour(INCH_LBF_N_M);
        assert!((f - 2.5933).abs() < 1e-3, "{f}");
    }

    /// Breakdown sums and torque by hand: 100 + 80 + 5 + 15 = 200 W at |Ω₁ − Ω₂| = 400
    /// rad/s → 0.5 N·m; zero relative speed → torque 0 (documented), total still summed.
    /// Serialises with the contract field names. Tolerance 1e-15.
    #[test]
    fn breakdown_sums_and_torque() {
        let h = HeatBreakdown::new(100.0, 80.0, 5.0, 15.0, 500.0, 100.0);
        assert_eq!(h.total_w, 200.0);
        assert!((h.friction_torque_nm - 0.5).abs() < 1e-15);
        let h0 = HeatBreakdown::new(1.0, 2.0, 3.0, 4.0, 300.0, 300.0);
        assert_eq!((h0.total_w, h0.friction_torque_nm), (10.0, 0.0));
        let json = serde_json::to_value(h).expect("serialises");
        for k in [
            "inner_contacts_w",
            "outer_contacts_w",
            "cage_rails_w",
            "viscous_drag_w",
            "total_w",
            "friction_torque_nm",
        ] {
            assert!(json.get(k).is_some(), "missing {k}");
        }
        assert!((h.total_btu_per_hour() - 200.0 * BTU_PER_HOUR_PER_WATT).abs() < 1e-12);
    }
}

/// Which ring guides the cage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum GuidingRing {
    Inner,
    #[default]
    Outer,
}

/// Cage rails (seed 000 §9.3) and drag factor (§9.4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Cage {
    /// W_cr, total width of the cage rails, m.
    pub rail_width_m: f64,
    /// D_cr, mean rail/land interface diameter, m.
    pub mean_diameter_m: f64,
    /// dc_cr, diametral clearance between lands and rails, m.
    pub diametral_clearance_m: f64,
    /// Guiding ring.
    pub guided_by: GuidingRing,
    /// Ψ (seed's f₀), viscous-drag factor of eq. 9.5 (5 for spherical roller bearings in oil bath).
    pub drag_factor: f64,
    /// Cage mass, kg (informational; thermal capacity of the cage node).
    pub mass_kg: f64,
}
