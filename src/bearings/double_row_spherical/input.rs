//! The resolved double-row spherical roller bearing in SI units (deck keys of issue 27),
//! and the single-row description each row is solved with.

use serde::Serialize;

use crate::bearings::spherical_roller::load_distribution::{GuideContact, Layout};
use crate::bearings::spherical_roller::{
    Bearing, Cage, DynamicLoads, FilmModel, Geometry, GuidingRing, LifeFactors, LifeMethod,
    Lubricant, Materials, Operating, Slicing, SolverSettings, Surfaces,
};
use crate::physics::lubrication::walther::{Walther, WaltherError};
use crate::physics::material::Material;

/// Internal geometry, SI. The 22308's is not published: the shipped deck is illustrative.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DrGeometry {
    /// Rows, 1 or 2 (1: the single-row reduction, for the validation).
    pub rows: usize,
    /// Z, rollers per row.
    pub roller_count: usize,
    /// D_W, roller maximum diameter, m.
    pub roller_diameter_m: f64,
    /// Roller overall length, m.
    pub roller_length_m: f64,
    /// Effective (contacting) length, m.
    pub effective_length_m: f64,
    /// R_W, roller crown (profile) radius, m.
    pub roller_crown_radius_m: f64,
    /// R_Ci, inner raceway crown radius, m.
    pub inner_raceway_radius_m: f64,
    /// R_CE, outer sphere radius (centred on the axis at the bearing's centre), m.
    ///
    /// Each row's outer raceway is the spherical roller's outer crown: radius R_CE, centred
    /// R_CE − D_W/2 from the roller centre along the free contact line. The deck check
    /// d_m = 2(R_CE − D_W/2)·cos α⁰ puts both rows' centres at one point on the axis (one
    /// sphere, the self-aligning outer ring), so a deck with R_CE changed alone is refused.
    /// The optimiser's k_CE (issue 27 §5) varies R_CE in the input directly ([`super::
    /// statics::analyse`] does not re-run the deck check) keeping d_m, α⁰ and D_W: the
    /// raceway osculation the seed's Fig. 3 varies; each row's crown centre then lies
    /// ΔR_CE beyond the bearing centre along its contact line (±0.2 mm at ±0.5 %, a
    /// negligible departure from one sphere), and the loads move smoothly (tested by
    /// `radius_perturbations_are_smooth`). Keeping one exact sphere instead means
    /// re-deriving α⁰ from cos α⁰ = d_m/(2(R_CE − D_W/2)) (≈ 1.5° at +0.5 %, which would
    /// swamp the osculation effect) or d_m (moving the inner ring); a deck written from a
    /// varied input must carry one of those or the check refuses it.
    pub outer_sphere_radius_m: f64,
    /// d_m, pitch diameter, m.
    pub pitch_diameter_m: f64,
    /// α⁰, free contact angle from the radial plane, rad.
    pub contact_angle_rad: f64,
    /// Diametral (radial internal) clearance, m.
    pub diametral_clearance_m: f64,
    /// r_e, radius of the roller's spherical end face, m.
    pub roller_end_radius_m: f64,
}

/// The guide ring between the rows (a body of its own, not the cage's piloting ring).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GuideRing {
    pub present: bool,
    /// Axial width at the pitch circle, m: its faces, normal to each row's roller axis, pass
    /// through (±width/2, d_m/2).
    pub width_m: f64,
    /// Diametral clearance of its bore on the inner ring, m (losses; later round).
    pub bore_clearance_m: f64,
    pub mass_kg: f64,
}

/// Cage land.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CageLand {
    GuideRing,
    InnerRing,
}

/// Where the cage speed comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CageSpeedSource {
    /// The seed's input: measured, drives the centrifugal force.
    Measured,
    /// The spherical roller's §7 kinematics iterated with the loads.
    Computed,
}

/// Cage design: window cages are modelled; prong cages are named so a deck can say so and
/// be refused with a reason.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CageKind {
    Window,
    Prong,
}

/// The window cage(s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DrCage {
    pub kind: CageKind,
    /// Pocket clearance, m (losses; later round).
    pub pocket_clearance_m: f64,
    pub land: CageLand,
    pub speed: CageSpeedSource,
    /// Measured cage speed, rad/s (used with `speed = "measured"`).
    pub measured_speed_rad_s: f64,
    pub mass_kg: f64,
}

/// Traction law of the raceway contacts (losses; later round).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Traction {
    Atz,
    NewtonianEq3,
}

/// Lubricant, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DrLubricant {
    /// Kinematic viscosity at 40 °C, m²/s.
    pub viscosity_40_m2_s: f64,
    /// Kinematic viscosity at 100 °C, m²/s.
    pub viscosity_100_m2_s: f64,
    /// Measured oil temperature, K.
    pub temperature_k: f64,
    pub pressure_viscosity_pa_inv: f64,
    pub density_kg_m3: f64,
    pub traction: Traction,
}

/// Loads and speed (outer ring fixed).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DrOperating {
    pub inner_speed_rad_s: f64,
    pub radial_load_n: f64,
    pub axial_load_n: f64,
}

/// One load case of the optimiser.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadCase {
    pub radial_load_n: f64,
    pub axial_load_n: f64,
    pub weight: f64,
}

/// `[optimise]`: read and validated now, used by the optimiser (a later round).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Optimise {
    /// Among "k_ci", "k_w", "k_ce".
    pub variables: Vec<String>,
    /// Half-width of the band of each relative radius (0.005 = ±0.5 %).
    pub relative_range: f64,
    /// Grid points per variable.
    pub grid: usize,
    pub min_lambda: f64,
    pub min_capacity_ratio: f64,
    pub load_cases: Vec<LoadCase>,
}

impl Default for Optimise {
    fn default() -> Self {
        Optimise {
            variables: vec!["k_ci".into(), "k_w".into()],
            relative_range: 0.005,
            grid: 21,
            min_lambda: 3.0,
            min_capacity_ratio: 1.0,
            load_cases: Vec::new(),
        }
    }
}

/// Numerical settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DrSolver {
    pub laminae: usize,
    pub force_tolerance: f64,
    pub max_iterations: usize,
    /// How the stiffness matrix is computed (`solver.stiffness`, issue 29).
    pub stiffness: crate::bearings::stiffness::Method,
}

/// Everything the double-row analysis reads, SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DoubleRowInput {
    pub geometry: DrGeometry,
    pub guide_ring: GuideRing,
    pub cage: DrCage,
    pub lubricant: DrLubricant,
    pub materials: Materials,
    pub surfaces: Surfaces,
    pub operating: DrOperating,
    pub solver: DrSolver,
    pub optimise: Optimise,
}

/// Through-hardened bearing steel (100Cr6 / AISI 52100, catalogue values).
const STEEL: Material = Material {
    youngs_modulus_pa: 208e9,
    poisson_ratio: 0.3,
    density_kg_m3: 7850.0,
    specific_heat_j_kg_k: 460.0,
    conductivity_w_m_k: 43.0,
};

/// Relative tolerance of the deck check d_m = 2(R_CE − D_W/2)·cos α⁰: 1e-4 (6.5 µm on the
/// 22308's 65 mm), below any clearance yet above a deck's rounding to 0.1 µm.
pub const PITCH_CHECK_TOLERANCE: f64 = 1e-4;

impl DoubleRowInput {
    /// An illustrative 22308 CC (40 × 90 × 33 mm), the same bearing as
    /// `decks/srb_22308.toml`: internal geometry assumed (not published).
    pub fn example_22308() -> Self {
        let d = 12.5e-3;
        let alpha = 12.0_f64.to_radians();
        let dm = 65.0e-3;
        // 2(R_CE − D/2)·cos α⁰ = 65.000 26 mm: the deck's four decimals in mm.
        let r_ce = 39.4762e-3;
        DoubleRowInput {
            geometry: DrGeometry {
                rows: 2,
                roller_count: 13,
                roller_diameter_m: d,
                roller_length_m: 12.0e-3,
                effective_length_m: 11.0e-3,
                roller_crown_radius_m: 38.5e-3,
                inner_raceway_radius_m: 39.0e-3,
                outer_sphere_radius_m: r_ce,
                pitch_diameter_m: dm,
                contact_angle_rad: alpha,
                diametral_clearance_m: 50e-6,
                roller_end_radius_m: 30e-3,
            },
            guide_ring: GuideRing {
                present: true,
                width_m: 1.45e-3,
                bore_clearance_m: 60e-6,
                mass_kg: 0.012,
            },
            cage: DrCage {
                kind: CageKind::Window,
                pocket_clearance_m: 0.2e-3,
                land: CageLand::GuideRing,
                speed: CageSpeedSource::Measured,
                measured_speed_rad_s: 1200.0 * crate::units::RPM_RAD_S,
                mass_kg: 0.04,
            },
            lubricant: DrLubricant {
                viscosity_40_m2_s: 68e-6,
                viscosity_100_m2_s: 8.6e-6,
                temperature_k: 333.15,
                pressure_viscosity_pa_inv: 2.0e-8,
                density_kg_m3: 870.0,
                traction: Traction::Atz,
            },
            materials: Materials {
                roller: STEEL,
                inner_ring: STEEL,
                outer_ring: STEEL,
            },
            surfaces: Surfaces {
                roller_rms_m: 0.1e-6,
                inner_rms_m: 0.15e-6,
                outer_rms_m: 0.2e-6,
            },
            operating: DrOperating {
                inner_speed_rad_s: 3000.0 * crate::units::RPM_RAD_S,
                radial_load_n: 20_000.0,
                axial_load_n: 2_000.0,
            },
            solver: DrSolver {
                laminae: 81,
                force_tolerance: 1e-9,
                max_iterations: 100,
                stiffness: crate::bearings::stiffness::Method::Analytic,
            },
            optimise: Optimise::default(),
        }
    }

    /// Dynamic viscosity at the measured oil temperature, Pa·s: the ASTM D341 (Walther)
    /// line through ν₄₀ and ν₁₀₀ ([`crate::physics::lubrication::walther`]) times the
    /// density.
    ///
    /// # Errors
    /// [`WaltherError`] for anchors outside D341's range (below 2 mm²/s), a hotter anchor
    /// not thinner, or an unusable temperature or density (the deck refuses all of them).
    pub fn try_viscosity_pa_s(&self) -> Result<f64, WaltherError> {
        let l = &self.lubricant;
        Walther::from_40_100(l.viscosity_40_m2_s * 1e6, l.viscosity_100_m2_s * 1e6)?
            .dynamic_pa_s(l.temperature_k - 273.15, l.density_kg_m3)
    }

    /// [`Self::try_viscosity_pa_s`] for a validated input (the deck's checks exclude its
    /// errors); NaN otherwise, so that a hand-built invalid input cannot pass for a
    /// lubricated one (the losses call the checked form and fail with its message).
    pub fn viscosity_pa_s(&self) -> f64 {
        self.try_viscosity_pa_s().unwrap_or(f64::NAN)
    }

    /// Nominal gap along the roller axis between a roller's inner end and the guide ring
    /// face, m: g₀ = (x_c − w/2)·cos α⁰ − L/2 with x_c = (R_CE − D_W/2)·sin α⁰ the roller
    /// centre's axial distance from the bearing's centre plane (the face through
    /// (w/2, d_m/2) normal to the roller axis a = (cos α⁰, −sin α⁰); the roller's end point
    /// lies L/2 along −a from its centre).
    pub fn guide_gap_m(&self) -> f64 {
        let g = &self.geometry;
        let a = g.contact_angle_rad;
        let xc = (g.outer_sphere_radius_m - 0.5 * g.roller_diameter_m) * a.sin();
        (xc - 0.5 * self.guide_ring.width_m) * a.cos() - 0.5 * g.roller_length_m
    }

    /// The guide ring contact of the statics (None without a guide ring or with one row).
    pub fn guide_contact(&self) -> Option<GuideContact> {
        if !self.guide_ring.present || self.geometry.rows < 2 {
            return None;
        }
        let (r, ring) = (&self.materials.roller, &self.materials.inner_ring);
        let e_star = 1.0
            / ((1.0 - r.poisson_ratio.powi(2)) / r.youngs_modulus_pa
                + (1.0 - ring.poisson_ratio.powi(2)) / ring.youngs_modulus_pa);
        let re = self.geometry.roller_end_radius_m;
        Some(GuideContact {
            gap_m: self.guide_gap_m(),
            hertz_constant: 4.0 / 3.0 * e_star * re.sqrt(),
            end_centre_offset_m: 0.5 * self.geometry.roller_length_m - re,
        })
    }

    /// The statics' layout: rows and guide ring.
    pub fn layout(&self) -> Layout {
        Layout {
            rows: self.geometry.rows,
            guide: self.guide_contact(),
        }
    }

    /// One row as the spherical roller's single-row bearing (row 1's frame), carrying the
    /// whole bearing's loads: what the shared lamina statics, stresses, film and life read.
    /// With `speed = "measured"` the dynamic loads are not iterated (the measured cage
    /// speed is the seed's input); with `"computed"` they are, as the spherical roller does.
    pub fn row_bearing(&self, name: &str) -> Bearing {
        let g = &self.geometry;
        let l = &self.lubricant;
        Bearing {
            name: name.to_string(),
            geometry: Geometry {
                roller_count: g.roller_count,
                roller_diameter_m: g.roller_diameter_m,
                roller_length_m: g.roller_length_m,
                effective_length_m: g.effective_length_m,
                roller_crown_radius_m: g.roller_crown_radius_m,
                inner_crown_radius_m: g.inner_raceway_radius_m,
                outer_crown_radius_m: g.outer_sphere_radius_m,
                pitch_diameter_m: g.pitch_diameter_m,
                contact_angle_rad: g.contact_angle_rad,
                diametral_clearance_m: g.diametral_clearance_m,
            },
            materials: self.materials,
            operating: Operating {
                inner_speed_rad_s: self.operating.inner_speed_rad_s,
                outer_speed_rad_s: 0.0,
                radial_load_n: self.operating.radial_load_n,
                axial_load_n: self.operating.axial_load_n,
            },
            lubricant: Lubricant {
                viscosity_pa_s: self.viscosity_pa_s(),
                pressure_viscosity_pa_inv: l.pressure_viscosity_pa_inv,
                density_kg_m3: l.density_kg_m3,
                // Not read by the statics, film or life (the traction is the losses').
                specific_heat_j_kg_k: 2000.0,
                transition_shear_stress_pa: 6.9e6,
                limiting_traction_coefficient: 0.06,
                lost_lubrication_traction_coefficient: 0.1,
                film_model: FilmModel::Grubin,
            },
            surfaces: self.surfaces,
            life: LifeFactors {
                capacity_reduction: 1.0,
                material_factor: 1.0,
                edge_stress_factor: 1.0,
                method: LifeMethod::Asme,
                iso_contamination_factor: 0.8,
                iso_fatigue_load_limit_n: 0.0,
                iso_reference_viscosity_m2_s: 0.0,
            },
            cage: Cage {
                rail_width_m: 0.0,
                mean_diameter_m: g.pitch_diameter_m,
                diametral_clearance_m: self.cage.pocket_clearance_m,
                guided_by: GuidingRing::Inner,
                drag_factor: 0.0,
                mass_kg: self.cage.mass_kg,
            },
            solver: SolverSettings {
                laminae: self.solver.laminae,
                force_tolerance: self.solver.force_tolerance,
                max_iterations: self.solver.max_iterations,
                dynamic_loads: match self.cage.speed {
                    CageSpeedSource::Measured => DynamicLoads::Estimate,
                    CageSpeedSource::Computed => DynamicLoads::Iterated,
                },
                slicing: Slicing::Cosine,
                stiffness: self.solver.stiffness,
                ..SolverSettings::DEFAULT
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The viscosity through `physics::lubrication::walther` equals the small in-file
    /// D341 formula it replaced (typed out here as the reference) to 1e-12 relative (the
    /// round-off of the nested powers of ten) at 20–120 °C, passes through its own two
    /// points, and gives ISO VG 68 with ν₁₀₀ = 8.6 at 60 °C near the ISO 3104 table's
    /// 28–30 mm²/s.
    #[test]
    fn walther_passes_through_its_points() {
        let replaced = |nu40_m2_s: f64, nu100_m2_s: f64, t_k: f64| -> f64 {
            let w = |nu_m2_s: f64| (nu_m2_s * 1e6 + 0.7).log10().log10();
            let (t1, t2) = (313.15_f64.log10(), 373.15_f64.log10());
            let b = (w(nu40_m2_s) - w(nu100_m2_s)) / (t2 - t1);
            let a = w(nu40_m2_s) + b * t1;
            let z = 10f64.powf(10f64.powf(a - b * t_k.log10()));
            (z - 0.7) * 1e-6
        };
        let mut i = DoubleRowInput::example_22308();
        let rho = i.lubricant.density_kg_m3;
        let (a, b) = (68e-6, 8.6e-6);
        for t_c in [20.0, 40.0, 60.0, 100.0, 120.0] {
            i.lubricant.temperature_k = t_c + 273.15;
            let new = i.try_viscosity_pa_s().expect("valid oil") / rho;
            let old = replaced(a, b, t_c + 273.15);
            assert!((new / old - 1.0).abs() < 1e-12, "{t_c} °C: {new} vs {old}");
            if t_c == 40.0 {
                assert!((new / a - 1.0).abs() < 1e-12);
            }
            if t_c == 100.0 {
                assert!((new / b - 1.0).abs() < 1e-12);
            }
            if t_c == 60.0 {
                assert!((25.0..32.0).contains(&(new * 1e6)), "{new}");
            }
        }
        // Outside D341's range the checked form says why.
        i.lubricant.viscosity_100_m2_s = 1.0e-6;
        let e = i.try_viscosity_pa_s().expect_err("below 2 mm²/s");
        assert!(e.to_string().contains("viscosity_100"), "{e}");
        assert!(i.viscosity_pa_s().is_nan());
    }

    /// The example's pitch circle satisfies the deck check exactly and its guide ring
    /// leaves a positive gap (the roller ends clear it at rest).
    #[test]
    fn example_is_consistent() {
        let b = DoubleRowInput::example_22308();
        let g = &b.geometry;
        let dm =
            2.0 * (g.outer_sphere_radius_m - 0.5 * g.roller_diameter_m) * g.contact_angle_rad.cos();
        assert!((dm / g.pitch_diameter_m - 1.0).abs() < PITCH_CHECK_TOLERANCE);
        let gap = b.guide_gap_m();
        assert!(gap > 0.0 && gap < 0.2e-3, "{gap}");
    }
}
