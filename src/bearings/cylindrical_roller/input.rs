//! The resolved cylindrical roller bearing description in SI units: what the model reads.
//! The deck (`super::deck`, US or SI units) fills a [`CylindricalInput`]; nothing below
//! the deck sees deck units. Field names carry their unit.

use crate::physics::material::Material;

/// The rollers' axial profile as the deck names it (`geometry.profile`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProfileKind {
    /// Flat middle and a circular dub-off at each end (seed 003 eq. 7): `dub_off_radius`,
    /// `dub_off_length`.
    DubOff,
    /// The ISO/TS 16281 logarithmic profile over the roller's length.
    Logarithmic,
}

/// Which ring carries ribs (roller-end contacts for axial load; issue 25 model item 1).
/// Axial load needs ribs on both rings (`Both`: an NJ/NUP arrangement, the load passing
/// inner rib → roller → outer rib); one ribbed ring alone (an N or NU bearing) locates
/// the rollers on that ring but carries no axial load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ribs {
    /// No ribs: the bearing carries radial load only.
    None,
    /// Ribs on the inner ring.
    Inner,
    /// Ribs on the outer ring.
    Outer,
    /// Ribs on both rings.
    Both,
}

/// The squeeze term of the film law (seed 003 eq. 4; issue 25 trap 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Squeeze {
    /// The physically consistent reading: at zero squeeze velocity the law gives the
    /// steady film of Pan–Hamrock magnitude (default).
    Normalised,
    /// Eq. (4) as printed (factor 0.25 at w = 0; kept for comparison).
    Printed,
    /// No squeeze term: the steady film throughout.
    None,
}

/// Internal geometry (seed 003 Table A1), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// m, number of rollers.
    pub roller_count: usize,
    /// Roller diameter, m.
    pub roller_diameter_m: f64,
    /// Roller length end to end, m.
    pub roller_length_m: f64,
    /// Inner raceway diameter, m.
    pub inner_raceway_diameter_m: f64,
    /// Outer raceway diameter, m.
    pub outer_raceway_diameter_m: f64,
    /// Dub-off radius R_d, m (eq. 7).
    pub dub_off_radius_m: f64,
    /// Dub-off length l_d at each end, m (eq. 7).
    pub dub_off_length_m: f64,
    /// Radial interference ρ, m; negative is a radial clearance (C = −ρ in eq. 3).
    pub radial_interference_m: f64,
    /// The axial profile.
    pub profile: ProfileKind,
    /// Ribs.
    pub ribs: Ribs,
    /// φ, the rib faces' lay-back from the radial plane, rad (the roller end–rib
    /// contact normal's angle to the bearing axis; `super::quasi_static_ribs`).
    pub rib_angle_rad: f64,
    /// h, the roller end–rib contact's height above the raceway, m; `None`: a quarter of
    /// the roller diameter ([`Geometry::rib_contact_height`]).
    pub rib_contact_height_m: Option<f64>,
}

/// Default rib lay-back angle, rad (0.5°: a slightly open rib, so the crowned roller end
/// touches it at a height set by the end's radius; a documented choice, not a standard).
pub const DEFAULT_RIB_ANGLE_RAD: f64 = 0.5 * std::f64::consts::PI / 180.0;

impl Geometry {
    /// The rib contact height in effect, m: the deck's, else d/4 (the contact halfway
    /// between the raceway and the roller axis).
    pub fn rib_contact_height(&self) -> f64 {
        self.rib_contact_height_m
            .unwrap_or(0.25 * self.roller_diameter_m)
    }
}

/// Roller and ring materials.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Materials {
    /// Roller.
    pub roller: Material,
    /// Inner ring.
    pub inner: Material,
    /// Outer ring.
    pub outer: Material,
}

/// Speeds and loads, SI. The outer ring is fixed; x, y in the plane of the bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Operating {
    /// ω_i, inner ring (shaft) speed, rad/s.
    pub inner_speed_rad_s: f64,
    /// ω_c, cage speed, rad/s; `None`: the kinematic ω_i·r_i/(r_i + r_o)
    /// ([`super::geometry::kinematic_cage_speed`]).
    pub cage_speed_rad_s: Option<f64>,
    /// The applied radial load's magnitude, N.
    pub radial_load_n: f64,
    /// Its direction, rad from +x (π: along −x, with gravity: the seed's 1 990.5 N).
    pub load_angle_rad: f64,
    /// The rotor's weight M·g along −x (g = 9.81 m/s², the seed's value).
    pub gravity: bool,
    /// Axial load on the inner ring, N, along +z (carried only with ribs on both rings).
    pub axial_load_n: f64,
}

/// The 2-DOF dynamics' settings (seed 003 eqs. 1–5); read by the dynamics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dynamics {
    /// M, the supported mass, kg.
    pub system_mass_kg: f64,
    /// k_n, N/m^n; `None`: from the slice law (issue 25 trap 3).
    pub contact_stiffness: Option<f64>,
    /// n, the load exponent (10/9).
    pub load_exponent: f64,
    /// Whether the film h_i enters the deflection (eq. 3).
    pub film_in_deflection: bool,
    /// The squeeze term of eq. (4).
    pub squeeze: Squeeze,
    /// Viscous damping ratio (0: the seed has none).
    pub damping_ratio: f64,
    /// Shaft revolutions simulated.
    pub revolutions: usize,
    /// Shaft revolutions dropped before the spectra (a count, not a convergence test).
    pub settle_revolutions: usize,
    /// Relative tolerance of the integrator.
    pub tolerance: f64,
}

/// Lubricant (seed 003 Table A2), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubricant {
    /// η₀, Pa·s.
    pub viscosity_pa_s: f64,
    /// α, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// β, 1/K.
    pub temperature_viscosity_k_inv: f64,
    /// ρ₀, kg/m³.
    pub density_kg_m3: f64,
    /// k, W/(m·K).
    pub conductivity_w_m_k: f64,
    /// c, J/(kg·K).
    pub specific_heat_j_kg_k: f64,
    /// τ₀, Pa.
    pub limiting_shear_pa: f64,
    /// γ, the pressure coefficient of the limiting shear.
    pub limiting_shear_slope: f64,
    /// Inlet temperature, K.
    pub inlet_temperature_k: f64,
    /// T₀, the temperature at which η₀ is given (eq. 10's reference; the seed names it
    /// without a value), K.
    pub reference_temperature_k: f64,
}

/// Surface topography (seed 003 Table 2), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surfaces {
    /// σ, composite rms roughness, m.
    pub composite_rms_m: f64,
    /// ξβσ, the roughness parameter.
    pub roughness_parameter: f64,
    /// σ/β, the asperity slope.
    pub asperity_slope: f64,
}

/// The contact report's settings (the deck's `[contact]` table).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactReport {
    /// ΔU, sliding speed, m/s.
    pub sliding_speed_m_s: f64,
    /// Cage angles reported, rad.
    pub positions_rad: Vec<f64>,
    /// The inlet(s) the workbench's Contact pane solves (`contact.inlet`: flooded,
    /// tipei or both; default flooded). `rollbench contact` takes `--inlet` instead.
    pub inlet: super::contact::InletChoice,
}

/// Solver settings of the lamina solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solver {
    /// Slices per roller.
    pub slices: usize,
    /// Force tolerance relative to the load.
    pub force_tolerance: f64,
    /// How the stiffness matrix is computed (`solver.stiffness`, issue 29).
    pub stiffness: crate::bearings::stiffness::Method,
}

/// A whole cylindrical roller bearing case, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct CylindricalInput {
    /// Geometry.
    pub geometry: Geometry,
    /// Materials.
    pub materials: Materials,
    /// Speeds and loads.
    pub operating: Operating,
    /// Dynamics settings.
    pub dynamics: Dynamics,
    /// Lubricant.
    pub lubricant: Lubricant,
    /// Surfaces.
    pub surfaces: Surfaces,
    /// Contact report.
    pub contact: ContactReport,
    /// Solver.
    pub solver: Solver,
}

/// Gravity, m/s²: the seed's 1 990.5 N = 1 500 N + 50 kg × 9.81 m/s² (not 9.80665).
pub const GRAVITY_M_S2: f64 = 9.81;

/// Default ΔU, m/s: Table 3's power over its friction force, 23.95 W / 40.67 N (the seed
/// does not state the sliding speed; issue 25 trap 5).
pub const DEFAULT_SLIDING_SPEED_M_S: f64 = 23.95 / 40.67;

/// Default inlet temperature, K (40 °C: the seed gives none; issue 25 trap 5).
pub const DEFAULT_INLET_TEMPERATURE_K: f64 = 313.15;

/// The temperature at which η₀ is given when the deck does not say, K: 40 °C, the ISO
/// viscosity grades' reference (Table A2's 0.0499 Pa·s at 829 kg/m³ is ν ≈ 60 mm²/s,
/// between ISO VG 46 and 68 at 40 °C).
pub const DEFAULT_REFERENCE_TEMPERATURE_K: f64 = 313.15;

/// The seed's steel (Table A2): E 210 GPa, ν 0.3, ρ 7 850 kg/m³, c 470 J/(kg·K),
/// k 46 W/(m·K).
pub const SEED_STEEL: Material = Material {
    youngs_modulus_pa: 210e9,
    poisson_ratio: 0.3,
    density_kg_m3: 7850.0,
    specific_heat_j_kg_k: 470.0,
    conductivity_w_m_k: 46.0,
};

impl CylindricalInput {
    /// The seed's truck-transmission bearing (Tables A1, A2, 2) with the documented
    /// defaults for what the seed leaves out.
    pub fn truck() -> CylindricalInput {
        CylindricalInput {
            geometry: Geometry {
                roller_count: 12,
                roller_diameter_m: 0.0127,
                roller_length_m: 0.022,
                inner_raceway_diameter_m: 0.050,
                outer_raceway_diameter_m: 0.0754,
                dub_off_radius_m: 0.050,
                dub_off_length_m: 0.003,
                radial_interference_m: 5e-6,
                profile: ProfileKind::DubOff,
                ribs: Ribs::None,
                rib_angle_rad: DEFAULT_RIB_ANGLE_RAD,
                rib_contact_height_m: None,
            },
            materials: Materials {
                roller: SEED_STEEL,
                inner: SEED_STEEL,
                outer: SEED_STEEL,
            },
            operating: Operating {
                inner_speed_rad_s: 209.0,
                cage_speed_rad_s: Some(83.26),
                radial_load_n: 1500.0,
                load_angle_rad: std::f64::consts::PI,
                gravity: true,
                axial_load_n: 0.0,
            },
            dynamics: Dynamics {
                system_mass_kg: 50.0,
                contact_stiffness: None,
                load_exponent: 10.0 / 9.0,
                film_in_deflection: true,
                squeeze: Squeeze::Normalised,
                damping_ratio: 0.0,
                revolutions: 100,
                settle_revolutions: 20,
                tolerance: 1e-8,
            },
            lubricant: Lubricant {
                viscosity_pa_s: 0.0499,
                pressure_viscosity_pa_inv: 1.39e-8,
                temperature_viscosity_k_inv: 0.026,
                density_kg_m3: 829.3,
                conductivity_w_m_k: 0.14,
                specific_heat_j_kg_k: 2000.0,
                limiting_shear_pa: 2.3e6,
                limiting_shear_slope: 0.047,
                // The shipped deck's documented choice: a 100 °C sump (decks/crb_truck.toml).
                inlet_temperature_k: 373.15,
                reference_temperature_k: DEFAULT_REFERENCE_TEMPERATURE_K,
            },
            surfaces: Surfaces {
                composite_rms_m: 0.6e-6,
                roughness_parameter: 0.055,
                asperity_slope: 1e-3,
            },
            contact: ContactReport {
                sliding_speed_m_s: DEFAULT_SLIDING_SPEED_M_S,
                positions_rad: vec![0.0, 30f64.to_radians(), 60f64.to_radians()],
                inlet: super::contact::InletChoice::Flooded,
            },
            solver: Solver {
                slices: 21,
                force_tolerance: 1e-9,
                stiffness: crate::bearings::stiffness::Method::Analytic,
            },
        }
    }

    /// The force on the inner ring, N: the radial load along `load_angle` plus the
    /// rotor's weight M·g along −x when `gravity` is on.
    pub fn load_vector_n(&self) -> [f64; 2] {
        let o = &self.operating;
        let (s, c) = o.load_angle_rad.sin_cos();
        let w = if o.gravity {
            self.dynamics.system_mass_kg * GRAVITY_M_S2
        } else {
            0.0
        };
        [o.radial_load_n * c - w, o.radial_load_n * s]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seed's total load: 1 500 N along −x plus 50 kg × 9.81 = 1 990.5 N (1e-9 N:
    /// cos π round-off only).
    #[test]
    fn truck_load_is_the_seeds_total() {
        let f = CylindricalInput::truck().load_vector_n();
        assert!((f[0] + 1990.5).abs() < 1e-9 && f[1].abs() < 1e-9, "{f:?}");
        let mut t = CylindricalInput::truck();
        t.operating.gravity = false;
        t.operating.load_angle_rad = std::f64::consts::FRAC_PI_2;
        let f = t.load_vector_n();
        assert!(f[0].abs() < 1e-9 && (f[1] - 1500.0).abs() < 1e-9, "{f:?}");
    }
}
