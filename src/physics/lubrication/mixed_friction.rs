//! Friction of one lubricated line (roller–raceway) contact in the mixed regime, the
//! "formula" tier of seed 003 (eqs. 35–42), SI.
//!
//! A Hertz strip of half-width b over the effective length L carries the load W; the
//! film h (the central film, taken uniform over the strip) and the composite roughness σ
//! give Λ = h/σ. Then:
//!
//! 1. **Asperities** (Greenwood–Tripp, eqs. 35, 37; `greenwood_tripp`): load W_a and
//!    area A_a over the apparent area A = 2bL. Past Λ = [`ASPERITY_CUTOFF_LAMBDA`] = 4 the
//!    surfaces are taken as fully separated (W_a = A_a = 0): F_5/2(4) ≈ 1e-5, so the
//!    neglected load is below 2e-3 N for the truck bearing, and this is the conventional
//!    full-film limit (issue 25 Validation 6). If the asperities alone would carry more
//!    than W, the film given is too thin for the load: W_a is capped at W and
//!    `asperities_carry_all` says so.
//! 2. **Boundary shear** (eqs. 39–40): f_b = τ_L A_a with τ_L = τ₀ + γ p_m and the mean
//!    asperity pressure p_m = W_a/A_a, acting against the sliding: its sign is that of
//!    ΔU, and it is 0 without sliding (no kinetic friction at ΔU = 0).
//! 3. **Viscous shear** (eqs. 41–42, the text's "(7)" and "(6)"): over the fluid area
//!    A_v = A − A_a, τ = η(p) ΔU/h + (h/2) ∂p/∂x node by node, held at ±(τ₀ + γp) where
//!    it would exceed it (non-Newtonian limiting shear). η is Houpert's (eq. 10) at the
//!    film temperature T. The hydrodynamic pressure is the Hertz (semi-elliptical)
//!    profile scaled so that it carries W_h = W − W_a on A_v: Σ p_i ΔA_i = W_h over the
//!    N cell-centred nodes with ΔA_i = (2b/N) L (A_v/A). With that normalisation a fully
//!    limited contact gives exactly f = τ₀A + γW (tested): τ₀A_a + γW_a from the
//!    asperities and τ₀A_v + γW_h from the fluid.
//!
//! **The ± of eq. 41.** For a film between surfaces moving at U₁ (z = 0) and U₂ (z = h)
//! with ΔU = U₂ − U₁, Reynolds's velocity profile gives the shear η ΔU/h ∓ (h/2) ∂p/∂x at
//! z = 0 and z = h. We report the force on the z = h surface (the + sign). For the
//! symmetric strip used here ∂p/∂x is odd in x and the limit is even, so the two surfaces
//! see the same total, and with ΔU = 0 only the Poiseuille term is left, whose sum over
//! the strip is zero ((h/2)[p(b) − p(−b)] L = 0; tested): a symmetric Hertz strip has no
//! net rolling (Poiseuille) friction, only local shear. `poiseuille_n` reports that sum
//! (uncapped) so that a caller with an asymmetric pressure would see it.
//!
//! **Inputs the seed does not give (trap 5)**: T (the film temperature; the seed's
//! thermal solution raises it above the inlet), ΔU, h; see the `table_3_band` test for
//! the documented defaults and the sensitivity. The rolling speed U does not enter
//! eqs. 35–42 in this tier (the film h is an input); it is carried for the slide-to-roll
//! ratio ΔU/U in the output.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use super::greenwood_tripp::Roughness;
use super::houpert::{Houpert, HoupertError};
use crate::physics::contact::line::line_contact_reduced;
use thiserror::Error;

/// Past this film ratio Λ the surfaces are fully separated: no asperity load or area.
pub const ASPERITY_CUTOFF_LAMBDA: f64 = 4.0;

/// Nodes across the Hertz strip when the caller has no reason to choose.
pub const DEFAULT_NODES: usize = 41;

/// Largest node count accepted (bounded time per contact).
pub const MAX_NODES: usize = 100_000;

/// Why a contact's friction cannot be computed: the field, its value and the range.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MixedFrictionError {
    /// An input outside its allowed range.
    #[error("mixed friction: {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The input's name (units in it).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// The lubricant's Houpert parameters.
    #[error("mixed friction: {0}")]
    Lubricant(#[from] HoupertError),
}

/// One line contact's inputs (seed 003 Tables 2, A2 and the contact's kinematics), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MixedContact {
    /// W, the contact load, N (≥ 0; 0 is no contact and no friction).
    pub load_n: f64,
    /// L, the effective (loaded) length of the line, m.
    pub effective_length_m: f64,
    /// R_zx, reduced radius in the rolling direction, m (`line::reduced_radius`).
    pub reduced_radius_m: f64,
    /// E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹, Pa (`line::reduced_modulus`): both for the
    /// Hertz strip and as Greenwood–Tripp's E′ (= ½ the seed's E_r; see greenwood_tripp).
    pub reduced_modulus_pa: f64,
    /// h, the (central) film thickness, taken uniform over the strip, m (≥ 0).
    pub film_m: f64,
    /// σ, ξβσ and σ/β of the two surfaces.
    pub roughness: Roughness,
    /// η₀, α, β, T₀, ρ₀ of eqs. 10–11.
    pub lubricant: Houpert,
    /// T, the film temperature at which η is evaluated, K.
    pub temperature_k: f64,
    /// τ₀, the limiting shear stress at ambient pressure, Pa (Table 2: 2.3 MPa).
    pub limiting_shear_stress_pa: f64,
    /// γ, the limiting shear stress's pressure slope, dimensionless (Table 2: 0.047).
    pub limiting_shear_slope: f64,
    /// ΔU, the sliding speed U₂ − U₁ of the two surfaces, m/s (signed).
    pub sliding_speed_m_s: f64,
    /// U, the rolling (entrainment) speed, m/s (for ΔU/U only; module note).
    pub rolling_speed_m_s: f64,
    /// N, nodes across the strip (1 … [`MAX_NODES`]; [`DEFAULT_NODES`] = 41).
    pub nodes: usize,
}

/// The friction of one contact, SI. Forces are signed along ΔU (the force resisting the
/// sliding, on the z = h surface).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct MixedFriction {
    /// Λ = h/σ, dimensionless.
    pub film_parameter: f64,
    /// b, Hertz half-width, m.
    pub half_width_m: f64,
    /// p₀, Hertz maximum pressure of the whole load, Pa.
    pub max_pressure_pa: f64,
    /// A = 2bL, the apparent contact area, m².
    pub apparent_area_m2: f64,
    /// W_a, the load carried by the asperities (eq. 35), N.
    pub asperity_load_n: f64,
    /// A_a, the asperity contact area (eq. 37), m².
    pub asperity_area_m2: f64,
    /// p_m = W_a/A_a, the mean asperity pressure, Pa (0 without asperity contact).
    pub asperity_pressure_pa: f64,
    /// True when eq. 35 asked for more than W (W_a capped at W): the film is too thin.
    pub asperities_carry_all: bool,
    /// W_h = W − W_a, the load carried by the film, N.
    pub hydrodynamic_load_n: f64,
    /// f_b = (τ₀ + γ p_m) A_a, the boundary friction (eqs. 39–40), N.
    pub boundary_n: f64,
    /// f_v, the viscous friction over A_v (eqs. 41–42), N.
    pub viscous_n: f64,
    /// Σ (h/2)(∂p/∂x) ΔA_v, the Poiseuille part before limiting, N (0 for the symmetric
    /// strip up to rounding: module note).
    pub poiseuille_n: f64,
    /// Nodes where the shear reached the limit τ₀ + γp.
    pub limited_nodes: usize,
    /// f = f_b + f_v, N.
    pub total_n: f64,
    /// µ = |f|/W, dimensionless (0 for an unloaded contact).
    pub coefficient: f64,
    /// f·ΔU, the power lost, W.
    pub power_w: f64,
    /// ΔU/U, dimensionless (0 when U = 0).
    pub slide_roll_ratio: f64,
}

impl MixedContact {
    /// Check every input; the error names the field, its value and the allowed range.
    pub fn validate(&self) -> Result<(), MixedFrictionError> {
        fn check(
            field: &'static str,
            value: f64,
            ok: bool,
            allowed: &'static str,
        ) -> Result<(), MixedFrictionError> {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(MixedFrictionError::OutOfRange {
                    field,
                    value,
                    allowed,
                })
            }
        }
        let r = &self.roughness;
        check("load_n", self.load_n, self.load_n >= 0.0, "≥ 0 N")?;
        check(
            "effective_length_m",
            self.effective_length_m,
            self.effective_length_m > 0.0,
            "> 0 m",
        )?;
        check(
            "reduced_radius_m",
            self.reduced_radius_m,
            self.reduced_radius_m > 0.0,
            "> 0 m",
        )?;
        check(
            "reduced_modulus_pa",
            self.reduced_modulus_pa,
            self.reduced_modulus_pa > 0.0,
            "> 0 Pa",
        )?;
        check("film_m", self.film_m, self.film_m >= 0.0, "≥ 0 m")?;
        check(
            "composite_rms_m",
            r.composite_rms_m,
            r.composite_rms_m > 0.0,
            "> 0 m",
        )?;
        check(
            "roughness_parameter",
            r.roughness_parameter,
            r.roughness_parameter > 0.0 && r.roughness_parameter <= 0.25,
            "(0, 0.25] (steel: 0.03–0.07)",
        )?;
        check(
            "asperity_slope",
            r.asperity_slope,
            r.asperity_slope > 0.0 && r.asperity_slope <= 1.0,
            "(0, 1] (typical 1e-4–1e-2)",
        )?;
        check(
            "temperature_k",
            self.temperature_k,
            self.temperature_k > 138.0,
            "above 138 K (Roelands's pole)",
        )?;
        check(
            "limiting_shear_stress_pa",
            self.limiting_shear_stress_pa,
            self.limiting_shear_stress_pa >= 0.0,
            "≥ 0 Pa",
        )?;
        check(
            "limiting_shear_slope",
            self.limiting_shear_slope,
            self.limiting_shear_slope >= 0.0,
            "≥ 0",
        )?;
        check(
            "sliding_speed_m_s",
            self.sliding_speed_m_s,
            true,
            "a finite speed",
        )?;
        check(
            "rolling_speed_m_s",
            self.rolling_speed_m_s,
            true,
            "a finite speed",
        )?;
        let n = self.nodes as f64;
        check(
            "nodes",
            n,
            self.nodes >= 1 && self.nodes <= MAX_NODES,
            "1 … 100000",
        )?;
        self.lubricant.validate()?;
        Ok(())
    }
}

/// The friction of one contact (module note; seed 003 eqs. 35–42).
pub fn mixed_friction(c: &MixedContact) -> Result<MixedFriction, MixedFrictionError> {
    c.validate()?;
    let sigma = c.roughness.composite_rms_m;
    let lambda = c.film_m / sigma;
    let du = c.sliding_speed_m_s;
    let slide_roll_ratio = if c.rolling_speed_m_s != 0.0 {
        du / c.rolling_speed_m_s
    } else {
        0.0
    };
    let l = c.effective_length_m;
    let hertz = line_contact_reduced(c.load_n / l, c.reduced_radius_m, c.reduced_modulus_pa);
    let b = hertz.half_width_m;
    if b.is_nan() || b <= 0.0 {
        // Unloaded: no strip, no friction.
        return Ok(MixedFriction {
            film_parameter: lambda,
            slide_roll_ratio,
            ..MixedFriction::default()
        });
    }
    let area = 2.0 * b * l;

    // 1. Asperities (eqs. 35, 37), with the full-film cutoff.
    let (mut w_a, a_a) = if lambda > ASPERITY_CUTOFF_LAMBDA {
        (0.0, 0.0)
    } else {
        (
            c.roughness
                .asperity_load_n(c.reduced_modulus_pa, area, lambda),
            c.roughness.asperity_area_m2(area, lambda).min(area),
        )
    };
    let asperities_carry_all = w_a > c.load_n;
    if asperities_carry_all {
        w_a = c.load_n;
    }
    let p_m = if a_a > 0.0 { w_a / a_a } else { 0.0 };

    // 2. Boundary shear (eqs. 39–40), against the sliding.
    let tau0 = c.limiting_shear_stress_pa;
    let gamma = c.limiting_shear_slope;
    let sgn = if du > 0.0 {
        1.0
    } else if du < 0.0 {
        -1.0
    } else {
        0.0
    };
    let boundary_n = sgn * (tau0 + gamma * p_m) * a_a;

    // 3. Viscous shear (eqs. 41–42) over A_v with the Hertz profile carrying W_h.
    let w_h = c.load_n - w_a;
    let fluid_fraction = (1.0 - a_a / area).max(0.0);
    let n = c.nodes;
    let nf = n as f64;
    let cell_area = 2.0 * b / nf * l * fluid_fraction;
    // Cell-centred nodes ξ_k = x_k/b = (2k + 1 − N)/N: integer numerators, so the strip is
    // exactly antisymmetric and no node sits on an edge, where ∂p/∂x is infinite.
    let xi_exact = |k: usize| ((2 * k + 1) as i64 - n as i64) as f64 / nf;
    let shape_sum: f64 = (0..n)
        .map(|k| {
            let x = xi_exact(k);
            (1.0 - x * x).sqrt()
        })
        .sum();
    let scale = if cell_area > 0.0 {
        w_h / (shape_sum * cell_area)
    } else {
        0.0
    };
    let iso = c.lubricant.at_temperature(c.temperature_k);
    let h = c.film_m;
    // Couette stress per unit viscosity, 1/s: ΔU/h; h = 0 with sliding is an infinite
    // shear rate (every node limited), with ΔU = 0 no Couette stress at all.
    let rate = if du == 0.0 {
        0.0
    } else if h > 0.0 {
        du / h
    } else {
        sgn * f64::INFINITY
    };
    let (mut viscous, mut poiseuille, mut limited) = (0.0, 0.0, 0usize);
    for k in 0..n {
        let x = xi_exact(k);
        let s = (1.0 - x * x).sqrt();
        let p = scale * s;
        // ∂p/∂x = scale · d/dx √(1 − x²/b²) = −scale · ξ/(b s).
        let dpdx = -scale * x / (b * s);
        let pois = 0.5 * h * dpdx;
        let couette = if rate == 0.0 {
            0.0
        } else {
            iso.viscosity_pa_s(p) * rate
        };
        let tau = couette + pois;
        let limit = tau0 + gamma * p;
        let capped = if tau > limit {
            limited += 1;
            limit
        } else if tau < -limit {
            limited += 1;
            -limit
        } else {
            tau
        };
        viscous += capped;
        poiseuille += pois;
    }
    let viscous_n = viscous * cell_area;
    let poiseuille_n = poiseuille * cell_area;
    let total_n = boundary_n + viscous_n;
    Ok(MixedFriction {
        film_parameter: lambda,
        half_width_m: b,
        max_pressure_pa: hertz.max_pressure_pa,
        apparent_area_m2: area,
        asperity_load_n: w_a,
        asperity_area_m2: a_a,
        asperity_pressure_pa: p_m,
        asperities_carry_all,
        hydrodynamic_load_n: w_h,
        boundary_n,
        viscous_n,
        poiseuille_n,
        limited_nodes: limited,
        total_n,
        coefficient: total_n.abs() / c.load_n,
        power_w: total_n * du,
        slide_roll_ratio,
    })
}

#[cfg(test)]
#[path = "mixed_friction_tests.rs"]
mod tests;
