//! Elastic, inertial and thermal properties of a body (roller, ball or ring), SI.

use serde::{Deserialize, Serialize};

use crate::units::PSI_PA;

/// Elastic and inertial properties of one body (roller or ring).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Young's modulus, Pa.
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio, dimensionless.
    pub poisson_ratio: f64,
    /// Mass density, kg/m³.
    pub density_kg_m3: f64,
    /// Specific heat, J/(kg·K) (thermal network capacities).
    pub specific_heat_j_kg_k: f64,
    /// Thermal conductivity, W/(m·K).
    pub conductivity_w_m_k: f64,
}

impl Material {
    /// AISI 52100 / M50 bearing steel (E = 29.0 Mpsi, ν = 0.30, as in seed 000 App. E).
    pub const STEEL: Material = Material {
        youngs_modulus_pa: 29.0e6 * PSI_PA,
        poisson_ratio: 0.30,
        density_kg_m3: 7_833.0,
        specific_heat_j_kg_k: 460.0,
        conductivity_w_m_k: 43.0,
    };
    /// Hot-pressed silicon nitride (E = 43.0 Mpsi, ν = 0.27, as in seed 000 App. E).
    pub const SILICON_NITRIDE: Material = Material {
        youngs_modulus_pa: 43.0e6 * PSI_PA,
        poisson_ratio: 0.27,
        density_kg_m3: 3_200.0,
        specific_heat_j_kg_k: 680.0,
        conductivity_w_m_k: 30.0,
    };

    /// E/(1−ν²), Pa: the plane-strain modulus of this body.
    pub fn plane_strain_modulus_pa(&self) -> f64 {
        self.youngs_modulus_pa / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }
}
