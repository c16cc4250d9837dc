//! Hertz line contact of one lamina (seed 000 §4.1, eqs. 4.1–4.3), SI units.
//!
//! Each lamina of a roller and the facing raceway lamina are two cylinders of equal
//! length `w` (the lamina width) pressed together by the lamina load `Q`. The contact is
//! a strip of half-width `b` with the elliptical (Hertz) pressure p(x) = p₀·√(1 − x²/b²).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use thiserror::Error;

/// Why a pair of lamina surfaces is not a Hertzian contact.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum HertzError {
    /// The summed curvature 1/r₁ + 1/r₂ is not positive: the concave body wraps the
    /// convex one at least as tightly as it is curved, so contact is conformal and
    /// Hertz theory does not apply.
    #[error("non-positive curvature sum {0} 1/m: conformal or separating surfaces")]
    NonPositiveCurvature(f64),
    /// An elastic constant, width or radius is zero, negative or not finite.
    #[error("invalid input: {0}")]
    InvalidInput(&'static str),
}

/// Elastic constants of one body: Young's modulus E (Pa) and Poisson's ratio ν.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Young's modulus, Pa.
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio, dimensionless.
    pub poisson_ratio: f64,
}

/// Reduced (contact) modulus E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹, Pa.
///
/// The seed's elastic constants ε̂ of eq. 4.1 are ε̂ = 4(1−ν²)/E (that is what makes
/// eq. 4.1 equal Johnson's b = √(4wR/(πE*))), so ε̂₀ + ε̂ᵢ = 4/E*.
pub fn reduced_modulus(body1: Elastic, body2: Elastic) -> f64 {
    let c1 = (1.0 - body1.poisson_ratio * body1.poisson_ratio) / body1.youngs_modulus_pa;
    let c2 = (1.0 - body2.poisson_ratio * body2.poisson_ratio) / body2.youngs_modulus_pa;
    1.0 / (c1 + c2)
}

/// E′ = 2E*, Pa: the modulus of the EHD groups of seed 000 eq. 5.1 (the seed's printed
/// Ē = ½[…] is the reciprocal of this; see `film`).
pub fn effective_modulus(body1: Elastic, body2: Elastic) -> f64 {
    2.0 * reduced_modulus(body1, body2)
}

/// Reduced radius R in the rolling direction, m: 1/R = 1/r₁ + 1/r₂ (seed eq. 4.1's
/// denominator r₀⁻¹ + rᵢ⁻¹; radii positive convex, negative concave). Errors when the
/// curvature sum is not positive (conformal contact) or a radius is zero/non-finite.
pub fn reduced_radius(r1_m: f64, r2_m: f64) -> Result<f64, HertzError> {
    if !(r1_m.is_finite() && r2_m.is_finite()) || r1_m == 0.0 || r2_m == 0.0 {
        return Err(HertzError::InvalidInput("radius zero or not finite"));
    }
    let curvature = 1.0 / r1_m + 1.0 / r2_m;
    // Exactly zero is rejected too: conformal surfaces have no Hertz strip.
    if curvature > 0.0 {
        Ok(1.0 / curvature)
    } else {
        Err(HertzError::NonPositiveCurvature(curvature))
    }
}

/// Result of a lamina's Hertz line contact (seed 000 eqs. 4.1–4.3), SI.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct LineContact {
    /// b, contact half-width in the rolling direction, m (eq. 4.1).
    pub half_width_m: f64,
    /// p₀ = S_max = 2Q/(πwb), maximum (centre) pressure, Pa (eq. 4.2).
    pub max_pressure_pa: f64,
    /// S_mean = Q/(2wb) = π·p₀/4, mean pressure over the strip, Pa (eq. 4.3).
    pub mean_pressure_pa: f64,
    /// Load per unit length Q/w, N/m.
    pub load_per_length_n_m: f64,
}

/// Hertz line contact from the load per unit length `q` (N/m), the reduced radius `R` (m)
/// and the reduced modulus E* (Pa): b = √(4qR/(πE*)), p₀ = 2q/(πb), mean = πp₀/4
/// (Johnson, *Contact Mechanics*, 1985, §4.2; seed eqs. 4.1–4.3).
///
/// A non-positive or non-finite `q` gives the all-zero contact (no tension, no NaN).
pub fn line_contact_reduced(q_n_m: f64, reduced_radius_m: f64, e_star_pa: f64) -> LineContact {
    if !(positive(q_n_m) && positive(reduced_radius_m) && positive(e_star_pa)) {
        return LineContact::default();
    }
    let b = (4.0 * q_n_m * reduced_radius_m / (std::f64::consts::PI * e_star_pa)).sqrt();
    let p0 = 2.0 * q_n_m / (std::f64::consts::PI * b);
    // Eq. 4.3 prints S_mean = Q/(2wb) = π·S_max/4. The two forms agree exactly:
    // π/4 · 2Q/(πwb) = Q/(2wb), the mean of an elliptical profile over the strip 2b.
    // We use π·p₀/4 to avoid a second division by w.
    LineContact {
        half_width_m: b,
        max_pressure_pa: p0,
        mean_pressure_pa: std::f64::consts::FRAC_PI_4 * p0,
        load_per_length_n_m: q_n_m,
    }
}

/// Hertz line contact of one lamina (seed 000 eqs. 4.1–4.3): lamina load `Q` (N), lamina
/// width `w` (m), the two radii in the rolling direction `r1`, `r2` (m; positive convex,
/// negative concave) and the two bodies' elastic constants. Returns b (m), p₀ (Pa) and
/// the mean pressure (Pa).
///
/// Zero (or negative) load gives the all-zero contact, never NaN. Errors only when the
/// geometry or elastic constants cannot form a Hertz contact.
pub fn line_contact(
    load_n: f64,
    width_m: f64,
    r1_m: f64,
    r2_m: f64,
    body1: Elastic,
    body2: Elastic,
) -> Result<LineContact, HertzError> {
    if !positive(width_m) {
        return Err(HertzError::InvalidInput("lamina width not positive"));
    }
    for b in [body1, body2] {
        if !positive(b.youngs_modulus_pa) {
            return Err(HertzError::InvalidInput("Young's modulus not positive"));
        }
        if !(b.poisson_ratio > -1.0 && b.poisson_ratio <= 0.5) {
            return Err(HertzError::InvalidInput(
                "Poisson's ratio outside (-1, 0.5]",
            ));
        }
    }
    let r = reduced_radius(r1_m, r2_m)?;
    Ok(line_contact_reduced(
        load_n / width_m,
        r,
        reduced_modulus(body1, body2),
    ))
}

/// True for a finite, strictly positive number (NaN is not positive).
fn positive(x: f64) -> bool {
    x > 0.0 && x.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL_206: Elastic = Elastic {
        youngs_modulus_pa: 206e9,
        poisson_ratio: 0.3,
    };

    #[test]
    fn hertz_worked_number_from_references() {
        // references.md: w = 104 167 N/m, R = 4.2308 mm, E = 206 GPa, ν = 0.3 on both
        // → b = 70.41 µm, p₀ = 941.8 MPa. Tolerance: half a unit of the last digit given
        // (0.005 µm, 0.05 MPa), since the reference is rounded to 4 digits.
        let e_star = reduced_modulus(STEEL_206, STEEL_206);
        let c = line_contact_reduced(104_167.0, 4.2308e-3, e_star);
        assert!(
            (c.half_width_m * 1e6 - 70.41).abs() < 0.005,
            "b = {}",
            c.half_width_m
        );
        assert!(
            (c.max_pressure_pa / 1e6 - 941.8).abs() < 0.05,
            "p0 = {}",
            c.max_pressure_pa
        );
    }

    #[test]
    fn hertz_lamina_form_matches_reduced_form() {
        // Same case through Q, w and two radii: a 1 mm lamina with Q = 104.167 N, a
        // convex roller r₁ = 5 mm on a convex race r₂ with 1/r₂ = 1/R − 1/r₁.
        // Tolerance 1e-12 relative: only round-off differs between the two paths.
        let r = 4.2308e-3;
        let r1 = 5e-3;
        let r2 = 1.0 / (1.0 / r - 1.0 / r1);
        let c = line_contact(104.167, 1e-3, r1, r2, STEEL_206, STEEL_206).unwrap();
        let d = line_contact_reduced(104_167.0, r, reduced_modulus(STEEL_206, STEEL_206));
        assert!((c.half_width_m / d.half_width_m - 1.0).abs() < 1e-12);
        // Eq. 4.2 and 4.3 literally: p₀ = 2Q/(πwb), mean = Q/(2wb). 1e-12 relative.
        let (q, w, b) = (104.167, 1e-3, c.half_width_m);
        assert!(
            (c.max_pressure_pa / (2.0 * q / (std::f64::consts::PI * w * b)) - 1.0).abs() < 1e-12
        );
        assert!((c.mean_pressure_pa / (q / (2.0 * w * b)) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn hertz_concave_outer_race_widens_contact() {
        // A concave raceway (negative radius) conforms more: larger b, lower p₀ than the
        // same load on a flat (very large radius) race. Strict inequalities.
        let flat = line_contact(100.0, 1e-3, 5e-3, 1e9, STEEL_206, STEEL_206).unwrap();
        let concave = line_contact(100.0, 1e-3, 5e-3, -40e-3, STEEL_206, STEEL_206).unwrap();
        assert!(concave.half_width_m > flat.half_width_m);
        assert!(concave.max_pressure_pa < flat.max_pressure_pa);
        // A concave race tighter than the roller is not a Hertz contact.
        assert!(matches!(
            line_contact(100.0, 1e-3, 5e-3, -4e-3, STEEL_206, STEEL_206),
            Err(HertzError::NonPositiveCurvature(_))
        ));
    }

    #[test]
    fn hertz_zero_load_is_zero_not_nan() {
        for q in [0.0, -5.0] {
            let c = line_contact(q, 1e-3, 5e-3, 20e-3, STEEL_206, STEEL_206).unwrap();
            assert_eq!(c, LineContact::default());
        }
    }

    #[test]
    fn hertz_moduli() {
        // E* for identical bodies is E/(2(1−ν²)); E′ = 2E*. Tolerance 1e-12 relative.
        let e_star = reduced_modulus(STEEL_206, STEEL_206);
        assert!((e_star / (206e9 / (2.0 * 0.91)) - 1.0).abs() < 1e-12);
        assert!((effective_modulus(STEEL_206, STEEL_206) / (2.0 * e_star) - 1.0).abs() < 1e-12);
    }
}
