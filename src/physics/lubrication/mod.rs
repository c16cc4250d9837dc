//! Lubrication shared by every bearing system: the lubricant and surface description,
//! EHD film thickness (line contact: `film`; elliptical point contact, Hamrock–Dowson:
//! `film_point`) and traction (`traction`).

use serde::{Deserialize, Serialize};

pub mod cage_film;
pub mod film;
pub mod film_point;
pub mod greenwood_tripp;
pub mod guide_ring;
pub mod houpert;
pub mod lamina_friction;
pub mod mixed_friction;
pub mod rheology;
pub mod rolling_resistance;
pub mod traction;
pub mod traction_curve;
pub mod walther;

/// Which film-thickness formula the EHD stage uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum FilmModel {
    /// Grubin, seed 000 eq. 5.1 (the seed's choice, and the basis of the ASME curve).
    #[default]
    Grubin,
    /// Dowson–Higginson minimum film.
    DowsonHigginson,
    /// Pan–Hamrock minimum film.
    PanHamrock,
}

/// Lubricant at operating temperature, and EHD traction parameters (seed 000 §5, §9).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Lubricant {
    /// η₀, absolute viscosity at operating temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// α (seed's ζ), pressure-viscosity coefficient, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// Lubricant density, kg/m³ (kinematic viscosity for the drag term).
    pub density_kg_m3: f64,
    /// Specific heat, J/(kg·K) (oil mass transport in the thermal network).
    pub specific_heat_j_kg_k: f64,
    /// τ_tr, transition shear stress of the Allen–Townsend–Zaretsky law, Pa.
    pub transition_shear_stress_pa: f64,
    /// μ_fl, limiting (pseudo) traction coefficient, dimensionless.
    pub limiting_traction_coefficient: f64,
    /// Constant traction coefficient in lost-lubrication mode, dimensionless.
    pub lost_lubrication_traction_coefficient: f64,
    /// Film formula.
    pub film_model: FilmModel,
}

/// RMS surface finishes (seed 000 eq. 6.7), m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Surfaces {
    pub roller_rms_m: f64,
    pub inner_rms_m: f64,
    pub outer_rms_m: f64,
}
