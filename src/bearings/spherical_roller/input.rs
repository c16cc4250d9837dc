//! The resolved bearing description in SI units: what every physics stage reads.
//!
//! A deck (TOML, SI or US customary) is parsed and validated by `crate::deck` into a
//! [`Bearing`]; nothing downstream ever sees deck units. Field names carry their unit.

use serde::{Deserialize, Serialize};

// The shared physics inputs a spherical roller bearing is made of, re-exported so the
// bearing's description reads as one module.
pub use crate::physics::heat::{Cage, GuidingRing};
pub use crate::physics::life::{LifeFactors, LifeMethod};
pub use crate::physics::lubrication::{FilmModel, Lubricant, Surfaces};
pub use crate::physics::material::Material;

/// Bearing internal geometry (seed 000 symbol list), SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Geometry {
    /// Z, number of rollers.
    pub roller_count: usize,
    /// D, roller maximum diameter, m.
    pub roller_diameter_m: f64,
    /// L, roller overall length, m (mass properties).
    pub roller_length_m: f64,
    /// L_eff, roller effective (contacting) length, m, sliced into Γ laminae.
    pub effective_length_m: f64,
    /// R_o, roller crown radius, m.
    pub roller_crown_radius_m: f64,
    /// Inner raceway crown radius, m (≥ roller crown radius).
    pub inner_crown_radius_m: f64,
    /// Outer raceway crown radius, m (≥ roller crown radius). A self-aligning
    /// spherical outer raceway has P_t/(2 cos β) + D/2.
    pub outer_crown_radius_m: f64,
    /// P_t, pitch diameter, m.
    pub pitch_diameter_m: f64,
    /// β, initial contact angle measured from the radial plane, rad.
    pub contact_angle_rad: f64,
    /// Diametral clearance, m (negative: preload interference).
    pub diametral_clearance_m: f64,
}

impl Geometry {
    /// The geometry entering the raceway capacities (seed eq. 6.2): shared life physics
    /// takes it as an argument and knows no bearing system.
    pub fn capacity_geometry(&self) -> crate::physics::life::CapacityGeometry {
        crate::physics::life::CapacityGeometry {
            theta: self.theta(),
            contact_angle_rad: self.contact_angle_rad,
            roller_diameter_m: self.roller_diameter_m,
            effective_length_m: self.effective_length_m,
            roller_count: self.roller_count,
            pitch_diameter_m: self.pitch_diameter_m,
        }
    }

    /// θ = D·cos β / P_t (seed 000 symbol list).
    pub fn theta(&self) -> f64 {
        self.roller_diameter_m * self.contact_angle_rad.cos() / self.pitch_diameter_m
    }
}

/// Roller and ring materials.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Materials {
    pub roller: Material,
    pub inner_ring: Material,
    pub outer_ring: Material,
}

/// Loads and speeds. Speeds are signed angular velocities about the bearing axis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Operating {
    /// Ω₁, inner ring angular velocity, rad/s.
    pub inner_speed_rad_s: f64,
    /// Ω₂, outer ring angular velocity, rad/s.
    pub outer_speed_rad_s: f64,
    /// F_r, radial load, N (acts toward roller 1, azimuth 0).
    pub radial_load_n: f64,
    /// F_a, axial load, N (positive presses the rings together).
    pub axial_load_n: f64,
}

/// Which speeds set the centrifugal force and gyroscopic moment (seed 000 §3, §7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum DynamicLoads {
    /// Re-solve with §7's cage and roller speeds until speeds and loads agree.
    #[default]
    Iterated,
    /// SASHBEAN's choice: App. C's first estimate only.
    Estimate,
}

/// How the effective length is cut into laminae.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Slicing {
    /// Γ equal laminae (the seed's slicing, d_l = w·(l − l_m)).
    Uniform,
    /// Boundaries at −(L/2)·cos(πk/Γ): thin laminae at the roller ends, where edge loading
    /// concentrates, so the edge stress and the life converge faster in Γ. The default.
    #[default]
    Cosine,
}

/// Numerical settings: one place for tolerances and iteration limits.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SolverSettings {
    /// Γ, number of laminae per roller.
    pub laminae: usize,
    /// Force tolerance of the equilibria, relative to the reference load (max of
    /// the applied load and the roller centrifugal force), dimensionless.
    pub force_tolerance: f64,
    /// Newton iteration limit of the bearing (ring) equilibrium.
    pub max_iterations: usize,
    /// Newton iteration limit of one roller's equilibrium.
    pub max_roller_iterations: usize,
    /// Stiffness of the cage pocket (roller held along its axis and in pitch) as a
    /// fraction of a roller's contact stiffness; see `solve::load_distribution`.
    pub cage_stiffness_ratio: f64,
    /// Which speeds drive the dynamic loads.
    pub dynamic_loads: DynamicLoads,
    /// Lamina spacing.
    pub slicing: Slicing,
    /// How the stiffness matrix is computed (`solver.stiffness`, issue 29): analytic
    /// (the rollers' condensed Jacobians), finite differences of the re-solved rollers,
    /// or both (analytic, checked).
    #[serde(default)]
    pub stiffness: crate::bearings::stiffness::Method,
}

impl SolverSettings {
    /// The defaults (one place for tolerances and iteration limits; decks override them).
    /// The cage ratio 1e-7 keeps the cage reaction of rollers loaded at both raceways below
    /// 1e-3 of their load while still holding one-sided rollers (see `solve::load_distribution`).
    ///
    /// Γ = 81 cosine-spaced laminae: the cheapest grid setting of the run-time/error front
    /// (`rollbench bench`) with max contact stress and L-10 within 0.1 % of a Γ = 400
    /// reference on the aerospace deck, there and at every finer Γ of the grid (its max-stress
    /// error fluctuates with Γ: 0.13 % at Γ = 61, 0.02–0.094 % from Γ = 63 to 101; uniform
    /// slicing converges only as ~1/Γ on the edge stress: 4 % off at Γ = 61).
    pub const DEFAULT: SolverSettings = SolverSettings {
        laminae: 81,
        force_tolerance: 1e-9,
        max_iterations: 100,
        max_roller_iterations: 60,
        cage_stiffness_ratio: 1e-7,
        dynamic_loads: DynamicLoads::Iterated,
        slicing: Slicing::Cosine,
        stiffness: crate::bearings::stiffness::Method::Analytic,
    };
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings::DEFAULT
    }
}

/// Everything the SASHBEAN pipeline needs, SI.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bearing {
    pub name: String,
    pub geometry: Geometry,
    pub materials: Materials,
    pub operating: Operating,
    pub lubricant: Lubricant,
    pub surfaces: Surfaces,
    pub life: LifeFactors,
    pub cage: Cage,
    pub solver: SolverSettings,
}

impl Bearing {
    /// A high-speed aerospace angular-contact spherical roller bearing near 1.1 million DN
    /// (65 mm bore at 17 000 rpm), the same bearing as `decks/aerospace.toml`. For unit tests
    /// and benchmarks that must not depend on the deck parser.
    pub fn example_aerospace() -> Bearing {
        use crate::units::{INCH_M, LBF_N, PSI_PA, RPM_RAD_S};
        let pitch = 3.3 * INCH_M;
        let beta = 12.0_f64.to_radians();
        let d = 0.5 * INCH_M;
        Bearing {
            name: "aerospace example".into(),
            geometry: Geometry {
                roller_count: 16,
                roller_diameter_m: d,
                roller_length_m: 0.5 * INCH_M,
                effective_length_m: 0.46 * INCH_M,
                roller_crown_radius_m: 1.90 * INCH_M,
                inner_crown_radius_m: 1.95 * INCH_M,
                outer_crown_radius_m: pitch / (2.0 * beta.cos()) + d / 2.0,
                pitch_diameter_m: pitch,
                contact_angle_rad: beta,
                diametral_clearance_m: 0.0008 * INCH_M,
            },
            materials: Materials {
                roller: Material::STEEL,
                inner_ring: Material::STEEL,
                outer_ring: Material::STEEL,
            },
            operating: Operating {
                inner_speed_rad_s: 17_000.0 * RPM_RAD_S,
                outer_speed_rad_s: 0.0,
                radial_load_n: 3_000.0 * LBF_N,
                axial_load_n: 1_000.0 * LBF_N,
            },
            lubricant: Lubricant {
                viscosity_pa_s: 0.0045,
                pressure_viscosity_pa_inv: 1.1e-8,
                density_kg_m3: 950.0,
                specific_heat_j_kg_k: 2_000.0,
                transition_shear_stress_pa: 1_000.0 * PSI_PA,
                limiting_traction_coefficient: 0.06,
                lost_lubrication_traction_coefficient: 0.1,
                film_model: FilmModel::Grubin,
            },
            surfaces: Surfaces {
                roller_rms_m: 2.0e-6 * INCH_M,
                inner_rms_m: 4.0e-6 * INCH_M,
                outer_rms_m: 4.0e-6 * INCH_M,
            },
            life: LifeFactors {
                capacity_reduction: 0.75,
                material_factor: 6.0,
                edge_stress_factor: 1.5,
                method: LifeMethod::Asme,
                iso_contamination_factor: 0.8,
                iso_fatigue_load_limit_n: 6_000.0,
                iso_reference_viscosity_m2_s: 0.0,
            },
            cage: Cage {
                rail_width_m: 0.25 * INCH_M,
                mean_diameter_m: 3.75 * INCH_M,
                diametral_clearance_m: 0.02 * INCH_M,
                guided_by: GuidingRing::Outer,
                drag_factor: 5.0,
                mass_kg: 0.15,
            },
            solver: SolverSettings::default(),
        }
    }
}
