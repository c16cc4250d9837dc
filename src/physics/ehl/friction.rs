//! The friction of a line contact node by node (seed 003 eqs. 35–42), SI, over plain
//! slices: x, the film pressure p(x), the film h(x) and the film temperature T(x) from
//! the EHL and thermal solutions.
//!
//! At each node, with the local film ratio λ = h/σ (Greenwood–Tripp, `greenwood_tripp`):
//!
//! - **Asperities** (eqs. 35, 37 per unit apparent area): the asperity pressure
//!   p_a = (16√2/15)π(ξβσ)²√(σ/β) E* F_5/2(λ) and the asperity area fraction
//!   a = π²(ξβσ)² F_2(λ) (≤ 1). Past λ = 4 (`mixed_friction::ASPERITY_CUTOFF_LAMBDA`) the
//!   surfaces are separated: p_a = a = 0, the same full-film limit as the formula tier.
//! - **Boundary shear** (eqs. 39–40): the adsorbed film on the asperity tips shears at its
//!   limiting stress τ₀ + γ p_m with p_m = p_a/a, so per unit apparent area
//!   τ_b = (τ₀ + γ p_m) a = τ₀ a + γ p_a, against the sliding. γ = 0.047 (Table 2; the
//!   text prints 0.04) and τ₀ = 2.3 MPa, Table 2's "atmospheric limiting shear stress" —
//!   the same τ₀ + γp caps the fluid shear (eq. 40 is the lubricant's limiting shear).
//! - **Viscous shear** (eqs. 41–42): the Couette stress η(p, T) Δu/h of the film over the
//!   fluid fraction 1 − a, held at τ₀ + γp where it would exceed it (non-Newtonian limit,
//!   `rheology`'s cap). The Poiseuille part (h/2)∂p/∂x is left out: over a contact it
//!   integrates to (h/2)Δp ≈ 0 between the ambient inlet and outlet (the formula tier's
//!   note in `mixed_friction`); it is rolling, not sliding, resistance. Where h = 0 there
//!   is no film and no viscous shear: the dry limit is boundary friction alone. (As
//!   h → 0⁺ the seed's model keeps τ₀ on the fluid fraction: the limiting stress of a
//!   vanishing film; only h = 0 removes it.)
//!
//! Forces are the trapezoid integrals over x times the effective length of the line,
//! signed along Δu = u₂ − u₁; µ = |F|/W with W = L∫(p + p_a) dx the load the film and
//! the asperities carry (eq. 45 plus eq. 35); power F·Δu.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use crate::physics::lubrication::greenwood_tripp::{f_2, f_5_2, Roughness};
use crate::physics::lubrication::houpert::{Houpert, HoupertError};
use crate::physics::lubrication::mixed_friction::ASPERITY_CUTOFF_LAMBDA;
use thiserror::Error;

/// Table 2's pressure coefficient of the boundary shear, dimensionless.
pub const SEED_BOUNDARY_SLOPE: f64 = 0.047;
/// Table 2's atmospheric limiting shear stress, Pa.
pub const SEED_LIMITING_SHEAR_PA: f64 = 2.3e6;

/// Why a contact's friction cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FrictionError {
    /// An input outside its allowed range.
    #[error("contact friction: {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The input's name (units in it).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// Slices of different lengths.
    #[error("contact friction: x_m has {x} nodes but {field} has {len}; give one value per node")]
    Length {
        /// The slice's name.
        field: &'static str,
        /// Its length.
        len: usize,
        /// The length of x_m.
        x: usize,
    },
    /// The lubricant's Houpert parameters.
    #[error("contact friction: {0}")]
    Lubricant(#[from] HoupertError),
}

/// One contact's inputs, SI.
#[derive(Debug, Clone, Copy)]
pub struct FrictionInput<'a> {
    /// Node positions, m, strictly increasing.
    pub x_m: &'a [f64],
    /// Film pressure, Pa (negative read as 0).
    pub pressure_pa: &'a [f64],
    /// Film thickness, m (≥ 0).
    pub film_m: &'a [f64],
    /// Film temperature at which η is taken, K (e.g. the thermal solution's mean).
    pub temperature_k: &'a [f64],
    /// u₁, speed of the lower surface, m/s.
    pub lower_speed_m_s: f64,
    /// u₂, speed of the upper surface, m/s.
    pub upper_speed_m_s: f64,
    /// η(p, T) (eq. 10).
    pub lubricant: Houpert,
    /// σ, ξβσ, σ/β.
    pub roughness: Roughness,
    /// E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹, Pa (Greenwood–Tripp's E′, see greenwood_tripp).
    pub reduced_modulus_pa: f64,
    /// τ₀, Pa ([`SEED_LIMITING_SHEAR_PA`]).
    pub limiting_shear_stress_pa: f64,
    /// γ, dimensionless ([`SEED_BOUNDARY_SLOPE`]).
    pub limiting_shear_slope: f64,
    /// L, the effective length of the line, m.
    pub effective_length_m: f64,
}

/// The friction of one contact, SI; forces signed along Δu = u₂ − u₁.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactFriction {
    /// λ = h/σ per node.
    pub lambda: Vec<f64>,
    /// Asperity pressure p_a per node, Pa.
    pub asperity_pressure_pa: Vec<f64>,
    /// Boundary shear per unit apparent area per node, Pa.
    pub boundary_shear_pa: Vec<f64>,
    /// Viscous shear per unit apparent area per node (after the cap), Pa.
    pub viscous_shear_pa: Vec<f64>,
    /// Nodes where the viscous shear reached τ₀ + γp.
    pub limited_nodes: usize,
    /// W_a = L∫p_a dx, N.
    pub asperity_load_n: f64,
    /// W_h = L∫p dx, N.
    pub hydrodynamic_load_n: f64,
    /// Boundary friction force, N.
    pub boundary_friction_n: f64,
    /// Viscous friction force, N.
    pub viscous_friction_n: f64,
    /// Total friction force, N.
    pub friction_n: f64,
    /// µ = |F|/(W_h + W_a), dimensionless (0 unloaded).
    pub friction_coefficient: f64,
    /// F·Δu, W.
    pub power_loss_w: f64,
}

fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    allowed: &'static str,
) -> Result<(), FrictionError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(FrictionError::OutOfRange {
            field,
            value,
            allowed,
        })
    }
}

/// The contact's friction (module note; seed eqs. 35–42).
pub fn contact_friction(c: &FrictionInput) -> Result<ContactFriction, FrictionError> {
    let n = c.x_m.len();
    check("x_m (node count)", n as f64, n >= 2, "at least 2 nodes")?;
    for (field, len) in [
        ("pressure_pa", c.pressure_pa.len()),
        ("film_m", c.film_m.len()),
        ("temperature_k", c.temperature_k.len()),
    ] {
        if len != n {
            return Err(FrictionError::Length { field, len, x: n });
        }
    }
    for w in c.x_m.windows(2) {
        check("x_m", w[1], w[1] > w[0], "strictly increasing")?;
    }
    for &p in c.pressure_pa {
        check("pressure_pa", p, true, "finite")?;
    }
    for &h in c.film_m {
        check("film_m", h, h >= 0.0, "≥ 0 m")?;
    }
    for &t in c.temperature_k {
        check(
            "temperature_k",
            t,
            t > 138.0,
            "above 138 K (Roelands's pole)",
        )?;
    }
    let r = &c.roughness;
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
        "reduced_modulus_pa",
        c.reduced_modulus_pa,
        c.reduced_modulus_pa > 0.0,
        "> 0 Pa",
    )?;
    check(
        "limiting_shear_stress_pa",
        c.limiting_shear_stress_pa,
        c.limiting_shear_stress_pa >= 0.0,
        "≥ 0 Pa",
    )?;
    check(
        "limiting_shear_slope",
        c.limiting_shear_slope,
        c.limiting_shear_slope >= 0.0,
        "≥ 0",
    )?;
    check(
        "effective_length_m",
        c.effective_length_m,
        c.effective_length_m > 0.0,
        "> 0 m",
    )?;
    check("lower_speed_m_s", c.lower_speed_m_s, true, "a finite speed")?;
    check("upper_speed_m_s", c.upper_speed_m_s, true, "a finite speed")?;
    c.lubricant.validate()?;

    let du = c.upper_speed_m_s - c.lower_speed_m_s;
    let sgn = if du > 0.0 {
        1.0
    } else if du < 0.0 {
        -1.0
    } else {
        0.0
    };
    let load_factor = r.load_factor_pa(c.reduced_modulus_pa);
    let area_factor = r.area_factor();
    let (tau0, gamma) = (c.limiting_shear_stress_pa, c.limiting_shear_slope);
    let mut out = ContactFriction::default();
    for i in 0..n {
        let h = c.film_m[i];
        let p = c.pressure_pa[i].max(0.0);
        let lambda = h / r.composite_rms_m;
        let (pa, a) = if lambda > ASPERITY_CUTOFF_LAMBDA {
            (0.0, 0.0)
        } else {
            (
                load_factor * f_5_2(lambda),
                (area_factor * f_2(lambda)).min(1.0),
            )
        };
        let boundary = sgn * (tau0 * a + gamma * pa);
        let viscous = if h > 0.0 && du != 0.0 {
            let eta = c.lubricant.viscosity_pa_s(p, c.temperature_k[i]);
            let tau = eta * du.abs() / h;
            let cap = tau0 + gamma * p;
            let capped = if tau > cap {
                out.limited_nodes += 1;
                cap
            } else {
                tau
            };
            sgn * capped * (1.0 - a)
        } else {
            0.0
        };
        out.lambda.push(lambda);
        out.asperity_pressure_pa.push(pa);
        out.boundary_shear_pa.push(boundary);
        out.viscous_shear_pa.push(viscous);
    }
    let trapz = |v: &[f64]| -> f64 {
        c.x_m
            .windows(2)
            .zip(v.windows(2))
            .map(|(x, y)| 0.5 * (y[0] + y[1]) * (x[1] - x[0]))
            .sum()
    };
    let pressure: Vec<f64> = c.pressure_pa.iter().map(|p| p.max(0.0)).collect();
    let l = c.effective_length_m;
    out.asperity_load_n = l * trapz(&out.asperity_pressure_pa);
    out.hydrodynamic_load_n = l * trapz(&pressure);
    out.boundary_friction_n = l * trapz(&out.boundary_shear_pa);
    out.viscous_friction_n = l * trapz(&out.viscous_shear_pa);
    out.friction_n = out.boundary_friction_n + out.viscous_friction_n;
    let w = out.asperity_load_n + out.hydrodynamic_load_n;
    out.friction_coefficient = if w > 0.0 {
        out.friction_n.abs() / w
    } else {
        0.0
    };
    out.power_loss_w = out.friction_n * du;
    Ok(out)
}

#[cfg(test)]
#[path = "friction_tests.rs"]
mod tests;
