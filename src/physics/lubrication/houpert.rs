//! Lubricant viscosity and density with pressure and temperature as seed 003 uses them
//! (the mixed-regime friction of a cylindrical roller contact), SI:
//!
//! - **Houpert's form of Roelands's viscosity** (eq. 10):
//!   η = η₀ exp{(ln η₀ + 9.67)[−1 + (1 + 5.1·10⁻⁹ p)^Z ((T − 138)/(T₀ − 138))^(−S₀)]}
//!   with Z = α/(5.1·10⁻⁹ (ln η₀ + 9.67)) and S₀ = β(T₀ − 138)/(ln η₀ + 9.67), p in Pa and
//!   T in K. Z and S₀ are chosen so that at p = 0, T = T₀ the law has Barus's slopes:
//!   ∂ln η/∂p = α and ∂ln η/∂T = −β (both tested).
//! - **Dowson–Higginson density** (eq. 11):
//!   ρ = ρ₀ [1 + 0.6·10⁻⁹ p/(1 + 1.7·10⁻⁹ p)] [1 − 0.65·10⁻³ (T − T₀)].
//!   The print lost the exponents ("0.6x107%p"); these are Dowson & Higginson's constants
//!   for p in Pa (0.6 p/(1 + 1.7 p) with p in GPa), whose compression tends to 1.353 as
//!   p → ∞.
//!
//! `rheology::Rheology` with `ViscosityModel::Roelands` is the same law written with the
//! temperature in °C + 135 (seed 001); T − 138 K here is T(°C) + 135.15, so the two agree
//! exactly at T = T₀ and within 0.1 % at 100 K from it (tested). This module is the lean,
//! allocation-free form the friction integrates node by node: [`Houpert::at_temperature`]
//! does the temperature work once per contact and leaves one ln and two exp per pressure.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use thiserror::Error;

/// ln of Roelands's η_∞ = 6.31·10⁻⁵ Pa·s, negated.
const LN_ETA_INF: f64 = 9.67;
/// 1/p_r of Roelands, 1/Pa (p_r = 196 MPa).
const ROELANDS_P: f64 = 5.1e-9;
/// Roelands's temperature pole, K.
const ROELANDS_T: f64 = 138.0;

/// Why a lubricant's Houpert parameters are not usable.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HoupertError {
    /// A field outside its allowed range.
    #[error("lubricant {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The field's name (units in it).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
}

/// A lubricant for eqs. 10 and 11 (seed 003 Table A2), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Houpert {
    /// η₀, dynamic viscosity at ambient pressure and T₀, Pa·s (Table A2: 0.0499).
    pub viscosity_pa_s: f64,
    /// α, Barus pressure–viscosity coefficient, 1/Pa (Table A2: 1.39e-8).
    pub pressure_viscosity_pa_inv: f64,
    /// β, temperature–viscosity coefficient, 1/K (Table A2: 0.026).
    pub temperature_viscosity_per_k: f64,
    /// T₀, the temperature of η₀ and ρ₀, K.
    pub reference_temperature_k: f64,
    /// ρ₀, density at ambient pressure and T₀, kg/m³ (Table A2: 829.3).
    pub density_kg_m3: f64,
}

/// The viscosity law at one temperature: what is left to do per pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Isothermal {
    ln_eta0: f64,
    /// ln η₀ + 9.67.
    l: f64,
    z: f64,
    /// ((T − 138)/(T₀ − 138))^(−S₀).
    temperature_factor: f64,
}

impl Houpert {
    /// Check every field: η₀ above Roelands's η_∞ = 6.31e-5 Pa·s (so ln η₀ + 9.67 > 0),
    /// α ≥ 0, β ≥ 0, T₀ > 138 K, ρ₀ > 0, all finite.
    pub fn validate(&self) -> Result<(), HoupertError> {
        let check = |field, value: f64, ok: bool, allowed| {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(HoupertError::OutOfRange {
                    field,
                    value,
                    allowed,
                })
            }
        };
        check(
            "viscosity_pa_s",
            self.viscosity_pa_s,
            self.viscosity_pa_s > 0.0 && self.viscosity_pa_s.ln() + LN_ETA_INF > 0.0,
            "above 6.31e-5 Pa·s (Roelands's η∞)",
        )?;
        check(
            "pressure_viscosity_pa_inv",
            self.pressure_viscosity_pa_inv,
            self.pressure_viscosity_pa_inv >= 0.0,
            "≥ 0 1/Pa",
        )?;
        check(
            "temperature_viscosity_per_k",
            self.temperature_viscosity_per_k,
            self.temperature_viscosity_per_k >= 0.0,
            "≥ 0 1/K",
        )?;
        check(
            "reference_temperature_k",
            self.reference_temperature_k,
            self.reference_temperature_k > ROELANDS_T,
            "above 138 K (Roelands's pole)",
        )?;
        check(
            "density_kg_m3",
            self.density_kg_m3,
            self.density_kg_m3 > 0.0,
            "> 0 kg/m³",
        )
    }

    /// ln η₀ + 9.67, dimensionless.
    fn l(&self) -> f64 {
        self.viscosity_pa_s.ln() + LN_ETA_INF
    }

    /// Z = α/(5.1·10⁻⁹ (ln η₀ + 9.67)), the pressure index, dimensionless.
    pub fn z(&self) -> f64 {
        self.pressure_viscosity_pa_inv / (ROELANDS_P * self.l())
    }

    /// S₀ = β (T₀ − 138)/(ln η₀ + 9.67), the temperature index, dimensionless.
    pub fn s0(&self) -> f64 {
        self.temperature_viscosity_per_k * (self.reference_temperature_k - ROELANDS_T) / self.l()
    }

    /// The law at temperature T (K): the temperature factor computed once. T at or below
    /// Roelands's pole (138 K) is held just above it (the law's own limit, η → ∞).
    pub fn at_temperature(&self, temperature_k: f64) -> Isothermal {
        let ratio = ((temperature_k - ROELANDS_T) / (self.reference_temperature_k - ROELANDS_T))
            .max(f64::MIN_POSITIVE);
        Isothermal {
            ln_eta0: self.viscosity_pa_s.ln(),
            l: self.l(),
            z: self.z(),
            temperature_factor: ratio.powf(-self.s0()),
        }
    }

    /// η(p, T), Pa·s (eq. 10), at gauge pressure p (Pa; negative is taken as 0, a
    /// cavitated film) and temperature T (K).
    pub fn viscosity_pa_s(&self, pressure_pa: f64, temperature_k: f64) -> f64 {
        self.at_temperature(temperature_k)
            .viscosity_pa_s(pressure_pa)
    }

    /// ρ(p, T), kg/m³ (eq. 11, Dowson–Higginson), at gauge pressure p (Pa; negative taken
    /// as 0) and temperature T (K).
    pub fn density_kg_m3(&self, pressure_pa: f64, temperature_k: f64) -> f64 {
        let p = pressure_pa.max(0.0);
        self.density_kg_m3
            * (1.0 + 0.6e-9 * p / (1.0 + 1.7e-9 * p))
            * (1.0 - 0.65e-3 * (temperature_k - self.reference_temperature_k))
    }
}

impl Isothermal {
    /// ln η(p), with η in Pa·s; p in Pa, negative taken as 0.
    pub fn ln_viscosity(&self, pressure_pa: f64) -> f64 {
        let growth = (self.z * (ROELANDS_P * pressure_pa.max(0.0)).ln_1p()).exp();
        self.ln_eta0 + self.l * (-1.0 + growth * self.temperature_factor)
    }

    /// η(p), Pa·s; p in Pa, negative taken as 0. Overflows to +∞ only past
    /// ln η ≈ 709 (far beyond any contact pressure of a real oil).
    pub fn viscosity_pa_s(&self, pressure_pa: f64) -> f64 {
        self.ln_viscosity(pressure_pa).exp()
    }

    /// dη/dp, Pa·s/Pa: η · L · Z · 5.1·10⁻⁹ (1 + 5.1·10⁻⁹ p)^(Z−1) · temperature factor;
    /// α η₀ at p = 0, T = T₀.
    pub fn viscosity_slope_pa_s_per_pa(&self, pressure_pa: f64) -> f64 {
        let p = pressure_pa.max(0.0);
        let x = ROELANDS_P * p;
        let growth_slope = self.z * ROELANDS_P * ((self.z - 1.0) * x.ln_1p()).exp();
        self.viscosity_pa_s(p) * self.l * growth_slope * self.temperature_factor
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::lubrication::rheology::{Rheology, ViscosityModel};
    use proptest::prelude::*;

    /// Table A2's lubricant with T₀ = 40 °C (the seed does not state T₀; 40 °C is the
    /// ISO VG reference temperature at which η₀ = 0.0499 Pa·s is a VG 46–68 oil).
    fn table_a2() -> Houpert {
        Houpert {
            viscosity_pa_s: 0.0499,
            pressure_viscosity_pa_inv: 1.39e-8,
            temperature_viscosity_per_k: 0.026,
            reference_temperature_k: 313.15,
            density_kg_m3: 829.3,
        }
    }

    #[test]
    fn z_and_s0_of_table_a2() {
        // By hand: ln 0.0499 = −2.99773, L = 6.67227; Z = 1.39e-8/(5.1e-9 · 6.67227) =
        // 0.408480; S₀ = 0.026 · 175.15/6.67227 = 0.682512. Tolerance 1e-5 (hand rounding).
        let h = table_a2();
        assert!((h.z() - 0.408480).abs() < 1e-5, "{}", h.z());
        assert!((h.s0() - 0.682512).abs() < 1e-5, "{}", h.s0());
    }

    #[test]
    fn limits_at_ambient() {
        // p = 0, T = T₀: η = η₀ and ρ = ρ₀ to rounding (1e-15 relative).
        let h = table_a2();
        let t0 = h.reference_temperature_k;
        assert!((h.viscosity_pa_s(0.0, t0) / 0.0499 - 1.0).abs() < 1e-15);
        assert!((h.density_kg_m3(0.0, t0) / 829.3 - 1.0).abs() < 1e-15);
        // Negative gauge pressure reads as 0.
        assert_eq!(h.viscosity_pa_s(-1e6, t0), h.viscosity_pa_s(0.0, t0));
        // Density: 1 GPa → 1 + 0.6/2.7; the high-pressure limit 1 + 0.6/1.7 = 1.3529;
        // 10 K hotter → × (1 − 0.0065).
        assert!((h.density_kg_m3(1e9, t0) / 829.3 - (1.0 + 0.6 / 2.7)).abs() < 1e-14);
        assert!((h.density_kg_m3(1e15, t0) / 829.3 - 1.352_941).abs() < 1e-5);
        assert!((h.density_kg_m3(0.0, t0 + 10.0) / 829.3 - 0.9935).abs() < 1e-14);
    }

    #[test]
    fn slopes_are_barus_at_ambient() {
        // dη/dp at p = 0, T = T₀ equals α η₀ (1e-12 relative: analytic), and a central
        // difference of the law itself agrees within 1e-6 (step 1 kPa: truncation
        // ~(αh)² ≈ 2e-10, rounding ~1e-16/(αh) ≈ 1e-11).
        let h = table_a2();
        let t0 = h.reference_temperature_k;
        let iso = h.at_temperature(t0);
        let want = 1.39e-8 * 0.0499;
        let slope = iso.viscosity_slope_pa_s_per_pa(0.0);
        assert!((slope / want - 1.0).abs() < 1e-12, "{slope}");
        let d = 1e3;
        // One-sided at p = 0 would be first order: use the law's smooth extension by
        // evaluating the central difference at p = d and the analytic slope there.
        let fd = (iso.viscosity_pa_s(2.0 * d) - iso.viscosity_pa_s(0.0)) / (2.0 * d);
        let at_d = iso.viscosity_slope_pa_s_per_pa(d);
        assert!((fd / at_d - 1.0).abs() < 1e-6, "{fd} vs {at_d}");
        assert!((at_d / want - 1.0).abs() < 1e-4);
        // ∂ln η/∂T = −β at T₀, p = 0 (central difference, step 0.01 K, 1e-6).
        let dt = 0.01;
        let dl = (h.viscosity_pa_s(0.0, t0 + dt).ln() - h.viscosity_pa_s(0.0, t0 - dt).ln())
            / (2.0 * dt);
        assert!((dl / -0.026 - 1.0).abs() < 1e-6, "{dl}");
    }

    #[test]
    fn matches_rheology_roelands() {
        // Same law as seed 001's Roelands (rheology.rs) with 135 °C ↔ 138 K: exact at
        // T = T₀ (1e-12 relative), within 1e-3 relative at T₀ + 60 K (the 0.15 K
        // difference of the poles).
        let h = table_a2();
        let r = Rheology {
            viscosity_pa_s: h.viscosity_pa_s,
            pressure_viscosity_pa_inv: h.pressure_viscosity_pa_inv,
            temperature_viscosity_per_k: h.temperature_viscosity_per_k,
            reference_temperature_k: h.reference_temperature_k,
            model: ViscosityModel::Roelands,
            roelands_z: None,
            limiting_shear_coefficient: 0.0,
            limiting_shear_stress_pa: 0.0,
        };
        let t0 = h.reference_temperature_k;
        for p in [0.0, 1e8, 5e8, 1e9, 2e9] {
            let a = h.viscosity_pa_s(p, t0);
            let b = r.viscosity_pa_s(p, t0);
            assert!((a / b - 1.0).abs() < 1e-12, "p={p}: {a} vs {b}");
            let a = h.viscosity_pa_s(p, t0 + 60.0);
            let b = r.viscosity_pa_s(p, t0 + 60.0);
            assert!((a / b - 1.0).abs() < 1e-3, "p={p}: {a} vs {b}");
        }
    }

    #[test]
    fn bad_fields_are_named() {
        let mut h = table_a2();
        h.viscosity_pa_s = 1e-5;
        let e = h.validate().unwrap_err().to_string();
        assert!(e.contains("viscosity_pa_s") && e.contains("6.31e-5"), "{e}");
        let mut h = table_a2();
        h.reference_temperature_k = 100.0;
        let e = h.validate().unwrap_err().to_string();
        assert!(
            e.contains("reference_temperature_k") && e.contains("138"),
            "{e}"
        );
        assert!(table_a2().validate().is_ok());
    }

    proptest! {
        #[test]
        fn monotone_in_pressure_and_temperature(
            p in 0.0f64..3e9, dp in 0.0f64..1e9, t in 280.0f64..450.0, dt in 0.0f64..50.0,
        ) {
            let h = table_a2();
            // Viscosity rises with pressure, falls with temperature; density rises with
            // pressure, falls with temperature.
            prop_assert!(h.viscosity_pa_s(p + dp, t) >= h.viscosity_pa_s(p, t));
            prop_assert!(h.viscosity_pa_s(p, t + dt) <= h.viscosity_pa_s(p, t));
            prop_assert!(h.density_kg_m3(p + dp, t) >= h.density_kg_m3(p, t));
            prop_assert!(h.density_kg_m3(p, t + dt) <= h.density_kg_m3(p, t));
            prop_assert!(h.viscosity_pa_s(p, t).is_finite());
        }
    }
}
