//! Kinematic viscosity against temperature from two measured points: the Ubbelohde–
//! Walther equation of ASTM D341 (seed 002 §3: "the lubricant temperature measurements
//! … are requested in order to evaluate its viscosity"), SI at the interface.
//!
//! # The law
//! ASTM D341 (Walther):
//!
//! log₁₀ log₁₀(ν + 0.7) = A − B·log₁₀ T,
//!
//! with ν in mm²/s (cSt) and T the absolute temperature in K. Two points (ν₁, T₁),
//! (ν₂, T₂) fix A and B; the law is then a straight line on the D341 chart. The constant
//! 0.7 is the classic D341 one; D341-09 adds a small term exp(−1.47 − 1.84ν − 0.51ν²) that
//! matters only below about 2 mm²/s (7.5·10⁻⁴ mm²/s at ν = 2), so anchors below
//! 2 mm²/s are refused ([`WaltherError::AnchorOutOfRange`]) and values the line gives
//! below 2 mm²/s at high temperature are extrapolation.
//!
//! Dynamic viscosity η = ρ·ν with the density ρ *at the same temperature* (the caller's
//! input: no thermal-expansion model is assumed here).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Absolute zero in °C.
const ABSOLUTE_ZERO_C: f64 = -273.15;
/// Smallest anchor viscosity for the classic D341 constant 0.7, mm²/s.
pub const MIN_ANCHOR_MM2_S: f64 = 2.0;

/// Why two viscosity points, a temperature or a density do not define a viscosity.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum WaltherError {
    /// An anchor viscosity is not finite or below the D341 range.
    #[error(
        "{name} = {value} mm²/s is outside the ASTM D341 range: it must be finite and at least {min} mm²/s"
    )]
    AnchorOutOfRange {
        /// The deck key of the anchor (`viscosity_40`, `viscosity_100`, …).
        name: &'static str,
        /// Its value, mm²/s.
        value: f64,
        /// The smallest allowed value, mm²/s.
        min: f64,
    },
    /// The hotter anchor is not thinner than the colder one: a mineral or synthetic oil
    /// thins as it warms, and the line would have a non-positive slope B.
    #[error(
        "the viscosity must fall with temperature: {cold_mm2_s} mm²/s at {cold_c} °C but {hot_mm2_s} mm²/s at {hot_c} °C"
    )]
    NotThinning {
        /// Colder anchor temperature, °C.
        cold_c: f64,
        /// Its viscosity, mm²/s.
        cold_mm2_s: f64,
        /// Hotter anchor temperature, °C.
        hot_c: f64,
        /// Its viscosity, mm²/s.
        hot_mm2_s: f64,
    },
    /// A temperature is not finite, at or below absolute zero, or the two anchor
    /// temperatures coincide.
    #[error("temperature {value} °C is not usable: {why}")]
    BadTemperature {
        /// The temperature, °C.
        value: f64,
        /// What is wrong with it.
        why: &'static str,
    },
    /// The density is not positive and finite.
    #[error("lubricant density {0} kg/m³ must be positive and finite")]
    BadDensity(f64),
}

/// A Walther (ASTM D341) line: log₁₀ log₁₀(ν + 0.7) = A − B·log₁₀ T, ν in mm²/s, T in K.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Walther {
    /// A, dimensionless.
    pub a: f64,
    /// B > 0, dimensionless.
    pub b: f64,
}

fn walther_z(nu_mm2_s: f64) -> f64 {
    (nu_mm2_s + 0.7).log10().log10()
}

fn kelvin(name_c: f64) -> Result<f64, WaltherError> {
    if !name_c.is_finite() {
        return Err(WaltherError::BadTemperature {
            value: name_c,
            why: "not a finite number",
        });
    }
    if name_c <= ABSOLUTE_ZERO_C {
        return Err(WaltherError::BadTemperature {
            value: name_c,
            why: "at or below absolute zero (−273.15 °C)",
        });
    }
    Ok(name_c - ABSOLUTE_ZERO_C)
}

fn anchor(name: &'static str, value: f64) -> Result<f64, WaltherError> {
    if value.is_finite() && value >= MIN_ANCHOR_MM2_S {
        Ok(value)
    } else {
        Err(WaltherError::AnchorOutOfRange {
            name,
            value,
            min: MIN_ANCHOR_MM2_S,
        })
    }
}

impl Walther {
    /// The line through the deck's `viscosity_40` (ν at 40 °C) and `viscosity_100`
    /// (ν at 100 °C), both in mm²/s.
    ///
    /// # Errors
    /// As [`Walther::through`].
    pub fn from_40_100(
        viscosity_40_mm2_s: f64,
        viscosity_100_mm2_s: f64,
    ) -> Result<Self, WaltherError> {
        let nu40 = anchor("viscosity_40", viscosity_40_mm2_s)?;
        let nu100 = anchor("viscosity_100", viscosity_100_mm2_s)?;
        Self::through((40.0, nu40), (100.0, nu100))
    }

    /// The line through two points (temperature °C, ν mm²/s), in either order.
    ///
    /// # Errors
    /// [`WaltherError::AnchorOutOfRange`] for ν < 2 mm²/s or non-finite,
    /// [`WaltherError::BadTemperature`] for unusable or equal temperatures,
    /// [`WaltherError::NotThinning`] if the hotter point is not the thinner one.
    pub fn through(p1: (f64, f64), p2: (f64, f64)) -> Result<Self, WaltherError> {
        let (cold, hot) = if p1.0 <= p2.0 { (p1, p2) } else { (p2, p1) };
        let nu_c = anchor("viscosity of the colder point", cold.1)?;
        let nu_h = anchor("viscosity of the hotter point", hot.1)?;
        let (tc, th) = (kelvin(cold.0)?, kelvin(hot.0)?);
        if tc == th {
            return Err(WaltherError::BadTemperature {
                value: cold.0,
                why: "the two anchor temperatures must differ",
            });
        }
        if nu_h >= nu_c {
            return Err(WaltherError::NotThinning {
                cold_c: cold.0,
                cold_mm2_s: nu_c,
                hot_c: hot.0,
                hot_mm2_s: nu_h,
            });
        }
        let (zc, zh) = (walther_z(nu_c), walther_z(nu_h));
        let (lc, lh) = (tc.log10(), th.log10());
        let b = (zc - zh) / (lh - lc);
        Ok(Walther { a: zc + b * lc, b })
    }

    /// Kinematic viscosity at `temperature_c` (°C), mm²/s: ν = 10^(10^(A − B·log₁₀T)) − 0.7.
    ///
    /// # Errors
    /// [`WaltherError::BadTemperature`] for a non-finite temperature or one at or below
    /// absolute zero.
    pub fn kinematic_mm2_s(&self, temperature_c: f64) -> Result<f64, WaltherError> {
        let t = kelvin(temperature_c)?;
        let z = self.a - self.b * t.log10();
        Ok(10f64.powf(10f64.powf(z)) - 0.7)
    }

    /// Kinematic viscosity at `temperature_c` (°C), m²/s.
    ///
    /// # Errors
    /// As [`Walther::kinematic_mm2_s`].
    pub fn kinematic_m2_s(&self, temperature_c: f64) -> Result<f64, WaltherError> {
        Ok(self.kinematic_mm2_s(temperature_c)? * 1e-6)
    }

    /// Dynamic viscosity η = ρ·ν at `temperature_c` (°C), Pa·s, with `density_kg_m3` the
    /// density at that temperature (kg/m³).
    ///
    /// # Errors
    /// As [`Walther::kinematic_mm2_s`], and [`WaltherError::BadDensity`].
    pub fn dynamic_pa_s(
        &self,
        temperature_c: f64,
        density_kg_m3: f64,
    ) -> Result<f64, WaltherError> {
        if !(density_kg_m3.is_finite() && density_kg_m3 > 0.0) {
            return Err(WaltherError::BadDensity(density_kg_m3));
        }
        Ok(density_kg_m3 * self.kinematic_m2_s(temperature_c)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both anchors are reproduced to round-off (the line passes through them by
    /// construction; 1e-12 relative allows the two nested powers of ten).
    #[test]
    fn reproduces_both_anchor_points() {
        for (n40, n100) in [(68.0, 8.7), (32.0, 5.4), (220.0, 19.0), (2.5, 2.0 + 1e-9)] {
            let w = Walther::from_40_100(n40, n100).expect("valid pair");
            let a = w.kinematic_mm2_s(40.0).expect("T");
            let b = w.kinematic_mm2_s(100.0).expect("T");
            assert!((a / n40 - 1.0).abs() < 1e-12, "{a} vs {n40}");
            assert!((b / n100 - 1.0).abs() < 1e-12, "{b} vs {n100}");
        }
    }

    /// ISO VG 68 of VI ≈ 100: ν40 = 68 mm²/s and ν100 = 8.7 mm²/s (ASTM D2270's VI
    /// table: VI 100 at ν40 = 68 gives ν100 ≈ 8.6–8.8). The ISO-grade viscosity–
    /// temperature diagrams of the bearing catalogues (SKF, Schaeffler; VI 95–100 oils)
    /// read ≈ 20 mm²/s at 70 °C. Tolerance 3 %: the chart's reading precision and the
    /// ±0.1 mm²/s spread of ν100 at VI 100 (which moves ν70 by ±0.8 %).
    #[test]
    fn iso_vg_68_at_70_c() {
        let w = Walther::from_40_100(68.0, 8.7).expect("valid pair");
        let nu = w.kinematic_mm2_s(70.0).expect("T");
        assert!((nu / 20.0 - 1.0).abs() < 0.03, "{nu}");
        // Monotone between and beyond the anchors.
        assert!(nu < 68.0 && nu > 8.7);
        assert!(w.kinematic_mm2_s(20.0).expect("T") > 68.0);
    }

    /// An independent published data set: Stachowiak & Batchelor, *Engineering
    /// Tribology*, Table 2.3 (dynamic viscosities at 30, 60 and 100 °C of 13 oils). The
    /// line through the 30 and 100 °C values predicts the 60 °C one. The table gives
    /// dynamic viscosities without densities; they are turned into kinematic ones with
    /// one density, 880 kg/m³ (the density's thermal change, ~5 % over 70 K, is part of
    /// the error budget). Criteria: median |error| ≤ 3 % and every oil but the first
    /// within 7 % (the first, "light machine oil" 38/12.1/5.3 mPa·s, is off by 11 %: its
    /// three values do not lie on any D341 line, a row misprint or an unusual oil).
    #[test]
    fn stachowiak_table_middle_points() {
        let rows: [(f64, f64, f64); 13] = [
            (38.0, 12.1, 5.3),
            (153.0, 34.0, 9.1),
            (250.0, 50.5, 12.6),
            (810.0, 135.0, 26.8),
            (18.6, 6.3, 2.4),
            (45.0, 12.0, 3.9),
            (107.0, 23.3, 6.4),
            (122.0, 26.3, 7.3),
            (171.0, 31.0, 7.5),
            (30.7, 8.6, 3.1),
            (165.0, 30.0, 6.8),
            (310.0, 44.2, 9.4),
            (2000.0, 180.0, 24.0),
        ];
        let rho = 0.88; // mPa·s → mm²/s with ρ = 880 kg/m³
        let mut errs: Vec<f64> = rows
            .iter()
            .map(|&(e30, e60, e100)| {
                let w = Walther::through((30.0, e30 / rho), (100.0, e100 / rho)).expect("pair");
                let nu60 = w.kinematic_mm2_s(60.0).expect("T");
                (nu60 / (e60 / rho) - 1.0).abs()
            })
            .collect();
        assert!(errs[0] > 0.07 && errs[0] < 0.13, "{}", errs[0]);
        assert!(errs[1..].iter().all(|&e| e < 0.07), "{errs:?}");
        errs.sort_by(f64::total_cmp);
        assert!(errs[6] < 0.03, "median {}", errs[6]);
    }

    /// η = ρ·ν in SI: 20 mm²/s at 860 kg/m³ is 0.0172 Pa·s (to round-off).
    #[test]
    fn dynamic_is_density_times_kinematic() {
        let w = Walther::from_40_100(68.0, 8.7).expect("valid pair");
        let nu = w.kinematic_m2_s(70.0).expect("T");
        let eta = w.dynamic_pa_s(70.0, 860.0).expect("valid");
        assert!((eta - 860.0 * nu).abs() < 1e-15);
        assert!(matches!(
            w.dynamic_pa_s(70.0, 0.0),
            Err(WaltherError::BadDensity(_))
        ));
    }

    /// Errors name the key and the range, and the messages read as sentences.
    #[test]
    fn rejects_bad_inputs_with_messages() {
        let e = Walther::from_40_100(1.5, 1.0).expect_err("below range");
        assert!(matches!(
            e,
            WaltherError::AnchorOutOfRange {
                name: "viscosity_40",
                ..
            }
        ));
        assert!(e.to_string().contains("viscosity_40 = 1.5"), "{e}");
        let e = Walther::from_40_100(8.0, 9.0).expect_err("thickening");
        assert!(matches!(e, WaltherError::NotThinning { .. }), "{e}");
        let e = Walther::from_40_100(f64::NAN, 9.0).expect_err("nan");
        assert!(matches!(e, WaltherError::AnchorOutOfRange { .. }));
        let w = Walther::from_40_100(68.0, 8.7).expect("valid pair");
        assert!(matches!(
            w.kinematic_mm2_s(-300.0),
            Err(WaltherError::BadTemperature { .. })
        ));
        assert!(matches!(
            Walther::through((40.0, 10.0), (40.0, 5.0)),
            Err(WaltherError::BadTemperature { .. })
        ));
    }
}
