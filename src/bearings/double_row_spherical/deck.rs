//! The double-row spherical roller deck (`type = "double-row-spherical-roller"`): its keys
//! as a [`crate::deck::form::Schema`] over [`DoubleRowInput`]. Key names are a contract
//! (issue 27 "Deck"). `[optimise]` holds an array of load cases, so it is an opaque table
//! read by [`optimise_table`].

use super::input::{
    CageKind, CageLand, CageSpeedSource, DoubleRowInput, LoadCase, Optimise, Traction,
    PITCH_CHECK_TOLERANCE,
};
use super::SYSTEM_ID;
use crate::deck::form::{
    material_fields, show, FieldKind, FieldMeta, FieldSpec, Form, MaterialAccess, Presence, Schema,
    TemplateNotes, BOOL,
};
use crate::deck::thermal::PathSeg;
use crate::deck::{DeckError, DeckErrors};
use crate::units::{Quantity, Units};

const LANDS: &[&str] = &["guide-ring", "inner-ring"];
const SPEEDS: &[&str] = &["measured", "computed"];
const TRACTIONS: &[&str] = &["atz", "newtonian-eq3"];
const KINDS: &[&str] = &["window", "prong"];

const DEG: f64 = std::f64::consts::PI / 180.0;
const RPM: f64 = std::f64::consts::PI / 30.0;

#[allow(clippy::too_many_arguments)]
const fn meta(
    key: &'static str,
    group: &'static str,
    label: &'static str,
    q: Quantity,
    kind: FieldKind,
    min: (f64, bool),
    max: (f64, bool),
    presence: Presence,
    help: &'static str,
) -> FieldMeta {
    FieldMeta::new(key, group, label, q, kind, min, max, presence, help)
}

const REAL: FieldKind = FieldKind::Real;
const INT: FieldKind = FieldKind::Integer;
const REQ: Presence = Presence::Required;
const fn def(v: f64) -> Presence {
    Presence::Default(v)
}

const ROLLER: [FieldSpec<DoubleRowInput>; 5] =
    material_fields!(DoubleRowInput, "roller", "Roller", |t| t.materials.roller);
const INNER: [FieldSpec<DoubleRowInput>; 5] =
    material_fields!(DoubleRowInput, "inner", "Inner ring", |t| t
        .materials
        .inner_ring);
const OUTER: [FieldSpec<DoubleRowInput>; 5] =
    material_fields!(DoubleRowInput, "outer", "Outer ring", |t| t
        .materials
        .outer_ring);

static FIELDS: [FieldSpec<DoubleRowInput>; 53] = [
    // [geometry]
    FieldSpec {
        meta: meta("geometry.rows", "geometry", "Rows", Quantity::Count, INT, (1.0, false), (2.0, false), def(2.0), "rows of rollers: 2 (1 is the single-row reduction used by the validation)"),
        get: |t| t.geometry.rows as f64,
        set: |t, v| t.geometry.rows = v as usize,
    },
    FieldSpec {
        meta: meta("geometry.roller_count", "geometry", "Rollers per row Z", Quantity::Count, INT, (3.0, false), (200.0, false), REQ, "rollers in each row"),
        get: |t| t.geometry.roller_count as f64,
        set: |t, v| t.geometry.roller_count = v as usize,
    },
    FieldSpec {
        meta: meta("geometry.roller_diameter", "geometry", "Roller diameter D_W", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "roller maximum diameter"),
        get: |t| t.geometry.roller_diameter_m,
        set: |t, v| t.geometry.roller_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.roller_length", "geometry", "Roller length L", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "roller overall length"),
        get: |t| t.geometry.roller_length_m,
        set: |t, v| t.geometry.roller_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.effective_length", "geometry", "Effective length", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "contacting length of the roller profile, sliced into laminae (≤ roller length)"),
        get: |t| t.geometry.effective_length_m,
        set: |t, v| t.geometry.effective_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.roller_crown_radius", "geometry", "Roller profile radius R_W", Quantity::Length, REAL, (0.0, true), (100.0, false), REQ, "curvature radius of the roller profile (< inner raceway radius < outer sphere radius)"),
        get: |t| t.geometry.roller_crown_radius_m,
        set: |t, v| t.geometry.roller_crown_radius_m = v,
    },
    FieldSpec {
        meta: meta("geometry.inner_raceway_radius", "geometry", "Inner raceway radius R_Ci", Quantity::Length, REAL, (0.0, true), (100.0, false), REQ, "curvature radius of the inner raceway profile (> roller profile radius)"),
        get: |t| t.geometry.inner_raceway_radius_m,
        set: |t, v| t.geometry.inner_raceway_radius_m = v,
    },
    FieldSpec {
        meta: meta("geometry.outer_sphere_radius", "geometry", "Outer sphere radius R_CE", Quantity::Length, REAL, (0.0, true), (100.0, false), REQ, "radius of the outer ring's spherical raceway, centred on the axis at the bearing's centre"),
        get: |t| t.geometry.outer_sphere_radius_m,
        set: |t, v| t.geometry.outer_sphere_radius_m = v,
    },
    FieldSpec {
        meta: meta("geometry.pitch_diameter", "geometry", "Pitch diameter d_m", Quantity::Length, REAL, (0.0, true), (10.0, false), REQ, "diameter of the roller centres' circle; must be 2(R_CE − D_W/2)·cos α⁰"),
        get: |t| t.geometry.pitch_diameter_m,
        set: |t, v| t.geometry.pitch_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.contact_angle", "geometry", "Free contact angle α⁰", Quantity::Angle, REAL, (0.0, true), (45.0 * DEG, false), REQ, "free contact angle of each row from the radial plane (row 2 at −α⁰)"),
        get: |t| t.geometry.contact_angle_rad,
        set: |t, v| t.geometry.contact_angle_rad = v,
    },
    FieldSpec {
        meta: meta("geometry.diametral_clearance", "geometry", "Radial clearance", Quantity::Length, REAL, (-0.001, false), (0.01, false), REQ, "diametral (radial internal) clearance; negative is a preload"),
        get: |t| t.geometry.diametral_clearance_m,
        set: |t, v| t.geometry.diametral_clearance_m = v,
    },
    FieldSpec {
        meta: meta("geometry.roller_end_radius", "geometry", "Roller end radius r_e", Quantity::Length, REAL, (0.0, true), (10.0, false), REQ, "radius of the roller's spherical end face that bears on the guide ring"),
        get: |t| t.geometry.roller_end_radius_m,
        set: |t, v| t.geometry.roller_end_radius_m = v,
    },
    // [guide_ring]
    FieldSpec {
        meta: meta("guide_ring.present", "guide_ring", "Guide ring", Quantity::Dimensionless, FieldKind::Choice(BOOL), (0.0, false), (1.0, false), def(1.0), "a guide ring between the rows on the inner ring (CC design)"),
        get: |t| if t.guide_ring.present { 1.0 } else { 0.0 },
        set: |t, v| t.guide_ring.present = v >= 0.5,
    },
    FieldSpec {
        meta: meta("guide_ring.width", "guide_ring", "Guide ring width", Quantity::Length, REAL, (0.0, false), (1.0, false), REQ, "axial width at the pitch circle; its faces are normal to each row's roller axis"),
        get: |t| t.guide_ring.width_m,
        set: |t, v| t.guide_ring.width_m = v,
    },
    FieldSpec {
        meta: meta("guide_ring.bore_clearance", "guide_ring", "Guide ring bore clearance", Quantity::Length, REAL, (0.0, true), (0.01, false), REQ, "diametral clearance of the guide ring on the inner ring (its hydrodynamic bore)"),
        get: |t| t.guide_ring.bore_clearance_m,
        set: |t, v| t.guide_ring.bore_clearance_m = v,
    },
    FieldSpec {
        meta: meta("guide_ring.mass", "guide_ring", "Guide ring mass", Quantity::Mass, REAL, (0.0, false), (1e3, false), REQ, "mass of the guide ring"),
        get: |t| t.guide_ring.mass_kg,
        set: |t, v| t.guide_ring.mass_kg = v,
    },
    // [cage]
    FieldSpec {
        meta: meta("cage.kind", "cage", "Cage kind", Quantity::Dimensionless, FieldKind::Choice(KINDS), (0.0, false), (1.0, false), def(0.0), "cage type: \"window\" (the only kind modelled; \"prong\" is refused)"),
        get: |t| match t.cage.kind {
            CageKind::Window => 0.0,
            CageKind::Prong => 1.0,
        },
        set: |t, v| {
            t.cage.kind = if v as usize == 1 {
                CageKind::Prong
            } else {
                CageKind::Window
            }
        },
    },
    FieldSpec {
        meta: meta("cage.pocket_clearance", "cage", "Pocket clearance", Quantity::Length, REAL, (0.0, true), (0.01, false), REQ, "clearance between roller and cage pocket"),
        get: |t| t.cage.pocket_clearance_m,
        set: |t, v| t.cage.pocket_clearance_m = v,
    },
    FieldSpec {
        meta: meta("cage.land", "cage", "Cage land", Quantity::Dimensionless, FieldKind::Choice(LANDS), (0.0, false), (1.0, false), def(0.0), "what pilots the cage: the guide ring or the inner ring"),
        get: |t| match t.cage.land {
            CageLand::GuideRing => 0.0,
            CageLand::InnerRing => 1.0,
        },
        set: |t, v| {
            t.cage.land = if v as usize == 1 {
                CageLand::InnerRing
            } else {
                CageLand::GuideRing
            }
        },
    },
    FieldSpec {
        meta: meta("cage.speed", "cage", "Cage speed from", Quantity::Dimensionless, FieldKind::Choice(SPEEDS), (0.0, false), (1.0, false), def(0.0), "\"measured\" (the seed's input: cage.measured_speed drives the centrifugal force) or \"computed\" (the spherical roller's kinematics iterated with the loads)"),
        get: |t| match t.cage.speed {
            CageSpeedSource::Measured => 0.0,
            CageSpeedSource::Computed => 1.0,
        },
        set: |t, v| {
            t.cage.speed = if v as usize == 1 {
                CageSpeedSource::Computed
            } else {
                CageSpeedSource::Measured
            }
        },
    },
    FieldSpec {
        meta: meta("cage.measured_speed", "cage", "Measured cage speed", Quantity::Speed, REAL, (-200_000.0 * RPM, false), (200_000.0 * RPM, false), def(0.0), "measured cage speed (read with cage.speed = \"measured\")"),
        get: |t| t.cage.measured_speed_rad_s,
        set: |t, v| t.cage.measured_speed_rad_s = v,
    },
    FieldSpec {
        meta: meta("cage.mass", "cage", "Cage mass", Quantity::Mass, REAL, (0.0, false), (1e4, false), def(0.0), "mass of the cage(s)"),
        get: |t| t.cage.mass_kg,
        set: |t, v| t.cage.mass_kg = v,
    },
    // [lubricant]
    FieldSpec {
        meta: meta("lubricant.viscosity_40", "lubricant", "Viscosity at 40 °C ν₄₀", Quantity::KinematicViscosityCst, REAL, (0.0, true), (1e-1, false), REQ, "kinematic viscosity at 40 °C (ASTM D341 / Walther)"),
        get: |t| t.lubricant.viscosity_40_m2_s,
        set: |t, v| t.lubricant.viscosity_40_m2_s = v,
    },
    FieldSpec {
        meta: meta("lubricant.viscosity_100", "lubricant", "Viscosity at 100 °C ν₁₀₀", Quantity::KinematicViscosityCst, REAL, (0.0, true), (1e-1, false), REQ, "kinematic viscosity at 100 °C (< ν₄₀)"),
        get: |t| t.lubricant.viscosity_100_m2_s,
        set: |t, v| t.lubricant.viscosity_100_m2_s = v,
    },
    FieldSpec {
        meta: meta("lubricant.temperature", "lubricant", "Oil temperature", Quantity::Temperature, REAL, (233.15, false), (473.15, false), REQ, "measured oil temperature (the seed's input): sets the viscosity by Walther"),
        get: |t| t.lubricant.temperature_k,
        set: |t, v| t.lubricant.temperature_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.pressure_viscosity", "lubricant", "Pressure-viscosity α", Quantity::PressureViscosity, REAL, (0.0, false), (1e-6, false), REQ, "pressure-viscosity coefficient"),
        get: |t| t.lubricant.pressure_viscosity_pa_inv,
        set: |t, v| t.lubricant.pressure_viscosity_pa_inv = v,
    },
    FieldSpec {
        meta: meta("lubricant.density", "lubricant", "Density ρ", Quantity::Density, REAL, (0.0, true), (1e5, false), def(870.0), "lubricant density (converts ν to η)"),
        get: |t| t.lubricant.density_kg_m3,
        set: |t, v| t.lubricant.density_kg_m3 = v,
    },
    FieldSpec {
        meta: meta("lubricant.traction", "lubricant", "Traction law", Quantity::Dimensionless, FieldKind::Choice(TRACTIONS), (0.0, false), (1.0, false), def(0.0), "\"atz\" (limiting-shear) or \"newtonian-eq3\" (the seed's eq. 3 as printed)"),
        get: |t| match t.lubricant.traction {
            Traction::Atz => 0.0,
            Traction::NewtonianEq3 => 1.0,
        },
        set: |t, v| {
            t.lubricant.traction = if v as usize == 1 {
                Traction::NewtonianEq3
            } else {
                Traction::Atz
            }
        },
    },
    ROLLER[0], ROLLER[1], ROLLER[2], ROLLER[3], ROLLER[4],
    INNER[0], INNER[1], INNER[2], INNER[3], INNER[4],
    OUTER[0], OUTER[1], OUTER[2], OUTER[3], OUTER[4],
    // [surfaces]
    FieldSpec {
        meta: meta("surfaces.roller_rms", "surfaces", "Roller RMS finish", Quantity::Roughness, REAL, (0.0, true), (1e-4, false), REQ, "rms roughness of the roller"),
        get: |t| t.surfaces.roller_rms_m,
        set: |t, v| t.surfaces.roller_rms_m = v,
    },
    FieldSpec {
        meta: meta("surfaces.inner_rms", "surfaces", "Inner raceway RMS finish", Quantity::Roughness, REAL, (0.0, true), (1e-4, false), REQ, "rms roughness of the inner raceway"),
        get: |t| t.surfaces.inner_rms_m,
        set: |t, v| t.surfaces.inner_rms_m = v,
    },
    FieldSpec {
        meta: meta("surfaces.outer_rms", "surfaces", "Outer raceway RMS finish", Quantity::Roughness, REAL, (0.0, true), (1e-4, false), REQ, "rms roughness of the outer sphere"),
        get: |t| t.surfaces.outer_rms_m,
        set: |t, v| t.surfaces.outer_rms_m = v,
    },
    // [operating]
    FieldSpec {
        meta: meta("operating.inner_speed", "operating", "Shaft speed", Quantity::Speed, REAL, (-200_000.0 * RPM, false), (200_000.0 * RPM, false), REQ, "inner ring speed; the outer ring is fixed"),
        get: |t| t.operating.inner_speed_rad_s,
        set: |t, v| t.operating.inner_speed_rad_s = v,
    },
    FieldSpec {
        meta: meta("operating.radial_load", "operating", "Radial load F_r", Quantity::Force, REAL, (0.0, false), (1e8, false), REQ, "radial load on the inner ring"),
        get: |t| t.operating.radial_load_n,
        set: |t, v| t.operating.radial_load_n = v,
    },
    FieldSpec {
        meta: meta("operating.axial_load", "operating", "Axial load F_a", Quantity::Force, REAL, (-1e8, false), (1e8, false), def(0.0), "axial load on the inner ring (positive toward row 1)"),
        get: |t| t.operating.axial_load_n,
        set: |t, v| t.operating.axial_load_n = v,
    },
    // [solver]
    FieldSpec {
        meta: meta("solver.laminae", "solver", "Laminae Γ", Quantity::Count, INT, (1.0, false), (2000.0, false), def(81.0), "laminae per roller (cosine spacing)"),
        get: |t| t.solver.laminae as f64,
        set: |t, v| t.solver.laminae = v as usize,
    },
    FieldSpec {
        meta: meta("solver.force_tolerance", "solver", "Force tolerance", Quantity::Dimensionless, REAL, (1e-16, false), (1e-4, false), def(1e-9), "equilibrium force residual relative to the load"),
        get: |t| t.solver.force_tolerance,
        set: |t, v| t.solver.force_tolerance = v,
    },
    FieldSpec {
        meta: meta("solver.max_iterations", "solver", "Ring iteration limit", Quantity::Count, INT, (1.0, false), (1e5, false), def(100.0), "Newton iterations of the ring equilibrium"),
        get: |t| t.solver.max_iterations as f64,
        set: |t, v| t.solver.max_iterations = v as usize,
    },
    FieldSpec {
        meta: meta("solver.stiffness", "solver", "Stiffness method", Quantity::Dimensionless, FieldKind::Choice(crate::bearings::stiffness::METHODS), (0.0, false), (2.0, false), def(0.0), "the stiffness matrix: \"analytic\" (the rollers' condensed Jacobians), \"finite-difference\" (central differences of the re-solved rollers, guide ring held) or \"both\" (analytic, checked: finite_difference_max_rel)"),
        get: |t| t.solver.stiffness.index(),
        set: |t, v| t.solver.stiffness = crate::bearings::stiffness::Method::from_index(v),
    },
];

/// Rules across keys: the pitch circle on the outer sphere, the crown order, the guide
/// ring clear of the rollers, a measured speed when measured, ν₁₀₀ < ν₄₀.
fn cross(t: &DoubleRowInput, units: Units) -> Vec<(&'static str, String)> {
    let g = &t.geometry;
    let mut v = Vec::new();
    let dm =
        2.0 * (g.outer_sphere_radius_m - 0.5 * g.roller_diameter_m) * g.contact_angle_rad.cos();
    if (dm / g.pitch_diameter_m - 1.0).abs() > PITCH_CHECK_TOLERANCE {
        v.push((
            "geometry.pitch_diameter",
            format!(
                "must be 2(R_CE − D_W/2)·cos α⁰ = {:.6} mm within {:.0e} relative (the roller centres lie on the outer sphere's pitch circle; from {}, {}, {})",
                dm * 1e3,
                PITCH_CHECK_TOLERANCE,
                show(&SCHEMA, t, "geometry.outer_sphere_radius", units),
                show(&SCHEMA, t, "geometry.roller_diameter", units),
                show(&SCHEMA, t, "geometry.contact_angle", units)
            ),
        ));
    }
    if g.roller_crown_radius_m >= g.inner_raceway_radius_m {
        v.push((
            "geometry.roller_crown_radius",
            format!(
                "must be less than the inner raceway radius ({}): R_Ci > R_W",
                show(&SCHEMA, t, "geometry.inner_raceway_radius", units)
            ),
        ));
    }
    if g.roller_crown_radius_m >= g.outer_sphere_radius_m {
        v.push((
            "geometry.roller_crown_radius",
            format!(
                "must be less than the outer sphere radius ({}): R_CE > R_W",
                show(&SCHEMA, t, "geometry.outer_sphere_radius", units)
            ),
        ));
    }
    if g.roller_crown_radius_m < 0.5 * g.effective_length_m {
        v.push((
            "geometry.roller_crown_radius",
            format!(
                "must be at least half the effective length ({})",
                show(&SCHEMA, t, "geometry.effective_length", units)
            ),
        ));
    }
    if g.effective_length_m > g.roller_length_m {
        v.push((
            "geometry.effective_length",
            format!(
                "must not exceed the roller length ({})",
                show(&SCHEMA, t, "geometry.roller_length", units)
            ),
        ));
    }
    if g.rows == 2 && t.guide_ring.present && t.guide_gap_m() < 0.0 {
        let a = g.contact_angle_rad;
        let xc = (g.outer_sphere_radius_m - 0.5 * g.roller_diameter_m) * a.sin();
        let w_max = 2.0 * (xc - 0.5 * g.roller_length_m / a.cos());
        v.push((
            "guide_ring.width",
            format!(
                "must leave the roller ends clear at rest: at most {:.4} mm for this geometry (the faces through (±width/2, d_m/2) normal to the roller axes)",
                w_max * 1e3
            ),
        ));
    }
    if t.cage.kind != CageKind::Window {
        v.push((
            "cage.kind",
            "only \"window\" is modelled (the seed's 22308 CC has window cages)".to_string(),
        ));
    }
    // ASTM D341's constant 0.7 holds from 2 mm²/s up (physics::lubrication::walther).
    for (key, nu) in [
        ("lubricant.viscosity_40", t.lubricant.viscosity_40_m2_s),
        ("lubricant.viscosity_100", t.lubricant.viscosity_100_m2_s),
    ] {
        if nu < crate::physics::lubrication::walther::MIN_ANCHOR_MM2_S * 1e-6 {
            v.push((
                key,
                format!(
                    "must be at least {} mm²/s (the range of ASTM D341's Walther line)",
                    crate::physics::lubrication::walther::MIN_ANCHOR_MM2_S
                ),
            ));
        }
    }
    // The losses run the cage on the guide ring's outer surface: there must be one.
    if t.cage.land == CageLand::GuideRing && !(t.guide_ring.present && g.rows == 2) {
        v.push((
            "cage.land",
            "\"guide-ring\" needs a guide ring (guide_ring.present = true and geometry.rows = 2); use \"inner-ring\"".to_string(),
        ));
    }
    if t.lubricant.viscosity_100_m2_s >= t.lubricant.viscosity_40_m2_s {
        v.push((
            "lubricant.viscosity_100",
            format!(
                "must be less than the viscosity at 40 °C ({})",
                show(&SCHEMA, t, "lubricant.viscosity_40", units)
            ),
        ));
    }
    v
}

/// The double-row spherical roller deck's schema.
pub static SCHEMA: Schema<DoubleRowInput> = Schema {
    system: SYSTEM_ID,
    groups: &[
        "geometry",
        "guide_ring",
        "cage",
        "lubricant",
        "materials",
        "surfaces",
        "operating",
        "solver",
        "optimise",
    ],
    required_groups: &[
        "geometry",
        "guide_ring",
        "cage",
        "lubricant",
        "materials",
        "surfaces",
        "operating",
    ],
    fields: &FIELDS,
    material_bodies: &["roller", "inner", "outer"],
    material: Some(MaterialAccess {
        get: |t, i| match i {
            0 => t.materials.roller,
            1 => t.materials.inner_ring,
            _ => t.materials.outer_ring,
        },
        set: |t, i, m| match i {
            0 => t.materials.roller = m,
            1 => t.materials.inner_ring = m,
            _ => t.materials.outer_ring = m,
        },
    }),
    opaque_tables: &["optimise", "thermal"],
    defaults: DoubleRowInput::example_22308,
    cross_checks: cross,
    one_holding: &[],
    template_header: "rollbench double-row spherical roller bearing deck (seed 002: Stirbu, Grigoras, Hanganu, combined spherical roller bearings functioning analysis)\nTwo rows mirrored at ±α⁰ sharing the inner ring and one outer sphere, a guide ring between them;\nlamina statics per roller, stresses, film and life per row.",
    template_notes: TemplateNotes {
        name: "",
        group_notes: &[],
        opaque_notes: &[
            (
                "optimise",
                "[optimise] (optional): variables = [\"k_ci\", \"k_w\"] (of k_ci, k_w, k_ce), relative_range = 0.005, grid = 21, min_lambda = 3.0, min_capacity_ratio = 1.0, load_cases = [{ radial_load = 20000, axial_load = 0, weight = 1 }] (loads in N/lbf as the deck's units)",
            ),
            (
                "thermal",
                crate::bearings::thermal_answer::thermal_template_note!(
                    "\"inner_contacts\", \"outer_contacts\", \"rollers\", \"cage_rails\", \"guide_ring\""
                ),
            ),
        ],
    },
};

/// The keys of `[optimise]` and of one load case.
pub const OPTIMISE_KEYS: &[&str] = &[
    "variables",
    "relative_range",
    "grid",
    "min_lambda",
    "min_capacity_ratio",
    "load_cases",
];
const CASE_KEYS: &[&str] = &["radial_load", "axial_load", "weight"];
const VARIABLES: &[&str] = &["k_ci", "k_w", "k_ce"];

/// Reads the deck's `[optimise]` table into `form.value.optimise` (defaults when absent):
/// `variables` (1–3 distinct of k_ci, k_w, k_ce), `relative_range` (0 < r ≤ 0.05),
/// `grid` (2–201), `min_lambda` (0–100), `min_capacity_ratio` (0–2), `load_cases`
/// (1–50 tables of radial_load ≥ 0, axial_load, weight > 0; loads in the deck's force
/// unit). Errors name the key with file:line and the allowed range.
pub fn optimise_table(form: &mut Form<DoubleRowInput>) -> Result<(), DeckErrors> {
    let mut opt = Optimise::default();
    let Some(table) = form.opaque.get("optimise").cloned() else {
        form.value.optimise = opt;
        return Ok(());
    };
    let force = Quantity::Force.factor(form.units);
    let loc = |form: &Form<DoubleRowInput>, key: &str| {
        form.location_in("optimise", &[PathSeg::Key(key.into())])
    };
    if let Some(other) = table.keys().find(|k| !OPTIMISE_KEYS.contains(&k.as_str())) {
        return Err(DeckError::UnknownKey {
            location: loc(form, other),
            key: format!("optimise.{other}"),
            hint: format!(" (allowed: {})", OPTIMISE_KEYS.join(", ")),
        }
        .into());
    }
    let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|n| n as f64));
    let range = |form: &Form<DoubleRowInput>,
                 key: &str,
                 lo: f64,
                 hi: f64,
                 allowed: &str|
     -> Result<Option<f64>, DeckErrors> {
        let Some(raw) = table.get(key) else {
            return Ok(None);
        };
        match num(raw) {
            Some(x) if x.is_finite() && x >= lo && x <= hi => Ok(Some(x)),
            Some(_) => Err(DeckError::OutOfRange {
                location: loc(form, key),
                key: format!("optimise.{key}"),
                value: raw.to_string(),
                allowed: allowed.into(),
            }
            .into()),
            None => Err(DeckError::WrongType {
                location: loc(form, key),
                key: format!("optimise.{key}"),
                value: raw.to_string(),
                expected: "a number".into(),
            }
            .into()),
        }
    };
    if let Some(r) = range(
        form,
        "relative_range",
        1e-6,
        0.05,
        "1e-6 ≤ value ≤ 0.05 (±5 %)",
    )? {
        opt.relative_range = r;
    }
    if let Some(n) = range(
        form,
        "grid",
        2.0,
        201.0,
        "2 ≤ value ≤ 201 points per variable",
    )? {
        opt.grid = n as usize;
    }
    if let Some(x) = range(form, "min_lambda", 0.0, 100.0, "0 ≤ value ≤ 100")? {
        opt.min_lambda = x;
    }
    if let Some(x) = range(form, "min_capacity_ratio", 0.0, 2.0, "0 ≤ value ≤ 2")? {
        opt.min_capacity_ratio = x;
    }
    if let Some(raw) = table.get("variables") {
        let list: Option<Vec<String>> = raw
            .as_array()
            .and_then(|a| a.iter().map(|v| v.as_str().map(str::to_string)).collect());
        let ok = list.as_ref().is_some_and(|l| {
            !l.is_empty()
                && l.len() <= 3
                && l.iter().all(|v| VARIABLES.contains(&v.as_str()))
                && l.iter().enumerate().all(|(i, v)| !l[..i].contains(v))
        });
        match (ok, list) {
            (true, Some(l)) => opt.variables = l,
            _ => {
                return Err(DeckError::Invalid {
                    location: loc(form, "variables"),
                    key: "optimise.variables".into(),
                    value: raw.to_string(),
                    rule: "1 to 3 distinct names of \"k_ci\", \"k_w\", \"k_ce\"".into(),
                }
                .into())
            }
        }
    }
    if let Some(raw) = table.get("load_cases") {
        let bad = |rule: String| -> DeckErrors {
            DeckError::Invalid {
                location: loc(form, "load_cases"),
                key: "optimise.load_cases".into(),
                value: raw.to_string(),
                rule,
            }
            .into()
        };
        let Some(items) = raw.as_array() else {
            return Err(bad(
                "an array of tables { radial_load, axial_load, weight }".into(),
            ));
        };
        if items.is_empty() || items.len() > 50 {
            return Err(bad("1 to 50 load cases".into()));
        }
        let mut cases = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let Some(t) = item.as_table() else {
                return Err(bad(format!(
                    "load case {} must be a table {{ radial_load, axial_load, weight }}",
                    i + 1
                )));
            };
            if let Some(k) = t.keys().find(|k| !CASE_KEYS.contains(&k.as_str())) {
                return Err(bad(format!(
                    "load case {}: unknown key {k} (allowed: {})",
                    i + 1,
                    CASE_KEYS.join(", ")
                )));
            }
            let get = |k: &str, default: Option<f64>| -> Result<f64, DeckErrors> {
                match t.get(k) {
                    Some(v) => num(v).filter(|x| x.is_finite()).ok_or_else(|| {
                        bad(format!("load case {}: {k} must be a finite number", i + 1))
                    }),
                    None => {
                        default.ok_or_else(|| bad(format!("load case {}: {k} is required", i + 1)))
                    }
                }
            };
            let radial = get("radial_load", None)?;
            let axial = get("axial_load", Some(0.0))?;
            let weight = get("weight", Some(1.0))?;
            if !(0.0..=1e8 / force).contains(&radial) || axial.abs() > 1e8 / force {
                return Err(bad(format!(
                    "load case {}: 0 ≤ radial_load, |axial_load| ≤ 1e8 N",
                    i + 1
                )));
            }
            if !(weight > 0.0 && weight <= 1e6) {
                return Err(bad(format!("load case {}: 0 < weight ≤ 1e6", i + 1)));
            }
            cases.push(LoadCase {
                radial_load_n: radial * force,
                axial_load_n: axial * force,
                weight,
            });
        }
        opt.load_cases = cases;
    }
    form.value.optimise = opt;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deck::form::{schema_problems, template};

    const DECK: &str = include_str!("../../../decks/srb_22308.toml");

    fn parse(text: &str) -> Result<Form<DoubleRowInput>, String> {
        let mut f = Form::parse(text, "d.toml", &SCHEMA).map_err(|e| e.to_string())?;
        optimise_table(&mut f).map_err(|e| e.to_string())?;
        Ok(f)
    }

    #[test]
    fn schema_is_sound() {
        assert_eq!(schema_problems(&SCHEMA), Vec::<String>::new());
    }

    /// The shipped deck is the example built in code (1e-12: unit conversion round-off;
    /// the speeds are in rpm and the temperature in °C, converted exactly to 1e-12).
    #[test]
    fn shipped_deck_is_the_example() {
        let f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
        let (a, b) = (&f.value, &DoubleRowInput::example_22308());
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs().max(1e-30);
        let ga = serde_json::to_value(a.geometry).unwrap_or_default();
        let gb = serde_json::to_value(b.geometry).unwrap_or_default();
        for (k, v) in gb.as_object().into_iter().flatten() {
            let (x, y) = (
                ga[k].as_f64().unwrap_or(f64::NAN),
                v.as_f64().unwrap_or(0.0),
            );
            assert!(close(x, y), "{k}: {x} vs {y}");
        }
        assert!(close(
            a.operating.inner_speed_rad_s,
            b.operating.inner_speed_rad_s
        ));
        assert!(close(
            a.cage.measured_speed_rad_s,
            b.cage.measured_speed_rad_s
        ));
        assert!(close(a.lubricant.temperature_k, b.lubricant.temperature_k));
        assert!(close(a.guide_ring.width_m, b.guide_ring.width_m));
        assert_eq!(a.optimise.load_cases.len(), 3);
    }

    /// Both unit systems' templates parse back; every bad value is refused naming its key
    /// and the rule.
    #[test]
    fn templates_and_bad_values() {
        for u in [Units::Us, Units::Si] {
            let t = template(&SCHEMA, u);
            parse(&t).unwrap_or_else(|e| panic!("{u:?}: {e}\n{t}"));
        }
        for (from, to, key, want) in [
            (
                "pitch_diameter = 0.065 ",
                "pitch_diameter = 0.066 ",
                "geometry.pitch_diameter",
                "2(R_CE − D_W/2)·cos α⁰",
            ),
            (
                "roller_crown_radius = 0.0385 ",
                "roller_crown_radius = 0.0392 ",
                "geometry.roller_crown_radius",
                "R_Ci > R_W",
            ),
            (
                "width = 0.00145 ",
                "width = 0.002 ",
                "guide_ring.width",
                "at most",
            ),
            (
                "viscosity_100 = 8.6",
                "viscosity_100 = 80.0",
                "lubricant.viscosity_100",
                "less than",
            ),
            (
                "roller_count = 13",
                "roller_count = 2",
                "roller_count",
                "3 ≤ value ≤ 200",
            ),
            ("rows = 2", "rows = 3", "rows", "1 ≤ value ≤ 2"),
            (
                "land = \"guide-ring\"",
                "land = \"outer-ring\"",
                "cage.land",
                "guide-ring",
            ),
            ("grid = 21", "grid = 1", "optimise.grid", "2 ≤ value ≤ 201"),
            (
                "relative_range = 0.005",
                "relative_range = 0.5",
                "optimise.relative_range",
                "0.05",
            ),
            (
                "variables = [\"k_ci\", \"k_w\"]",
                "variables = [\"k_ci\", \"k_x\"]",
                "optimise.variables",
                "k_ce",
            ),
            (
                "weight = 1.0 },",
                "weight = -1.0 },",
                "optimise.load_cases",
                "weight",
            ),
        ] {
            assert!(DECK.contains(from), "{from}");
            let e = parse(&DECK.replacen(from, to, 1)).err().unwrap_or_default();
            assert!(e.contains(key) && e.contains(want), "{to}: {e}");
        }
    }
}
