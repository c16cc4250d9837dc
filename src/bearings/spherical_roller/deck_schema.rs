//! The spherical roller's deck schema ([`SCHEMA`], read by the generic
//! [`crate::deck::form`]): one table of every editable scalar deck key, with its unit in
//! each system, its allowed range (SI) and how it maps onto [`Bearing`], and the rules
//! involving several keys ([`cross_checks`]). Parsing, validation, the template,
//! `Deck::get`/`set` and the TUI all read this table.
//!
//! Ranges (SI; shown to users in deck units):
//!
//! | key | allowed |
//! |---|---|
//! | geometry.roller_count | 3 ≤ Z ≤ 500 |
//! | geometry lengths (D, L, L_eff) | 0 < x ≤ 1 m |
//! | geometry crown radii | 0 < x ≤ 100 m |
//! | geometry.pitch_diameter | 0 < x ≤ 10 m |
//! | geometry.contact_angle | 0 ≤ β < 45° |
//! | geometry.diametral_clearance | −0.01 m ≤ c ≤ 0.01 m (and \|c\| < D) |
//! | materials.*.youngs_modulus | 0 < E ≤ 1e13 Pa |
//! | materials.*.poisson_ratio | 0 ≤ ν < 0.5 |
//! | materials.*.density | 0 < ρ ≤ 1e5 kg/m³ |
//! | materials.*.specific_heat | 0 < c ≤ 1e5 J/(kg·K) |
//! | materials.*.conductivity | 0 < k ≤ 1e4 W/(m·K) |
//! | operating speeds | −1e6 ≤ n ≤ 1e6 rpm |
//! | operating loads | 0 ≤ F ≤ 1e9 N |
//! | lubricant.viscosity | 0 < η ≤ 1e4 Pa·s |
//! | lubricant.pressure_viscosity | 0 < α ≤ 1e-6 1/Pa |
//! | lubricant.lubricant_parameter | 0 < LP ≤ 1e6 (s ×1e11) |
//! | lubricant density, specific heat | 0 < x ≤ 1e5 |
//! | lubricant.transition_shear_stress | 0 < τ ≤ 1e10 Pa |
//! | traction coefficients | 0 ≤ μ ≤ 1 |
//! | surfaces.*_rms | 0 < σ ≤ 100 µm |
//! | life.capacity_reduction | 0.3 ≤ ξ ≤ 1 |
//! | life.material_factor | 0 < x ≤ 100 |
//! | life.edge_stress_factor | 1 ≤ x ≤ 10 |
//! | life.iso_contamination_factor | 0 ≤ e_C ≤ 1 |
//! | life.iso_fatigue_load_limit | 0 ≤ C_u ≤ 1e9 N (> 0 needed for iso281) |
//! | life.iso_reference_viscosity | 0 ≤ ν₁ ≤ 1e5 cSt (0 = computed) |
//! | cage.rail_width | 0 < x ≤ 1 m |
//! | cage.mean_diameter | 0 < x ≤ 10 m |
//! | cage.diametral_clearance | 0 ≤ x ≤ 0.1 m |
//! | cage.drag_factor | 0 ≤ Ψ ≤ 100 |
//! | cage.mass | 0 ≤ m ≤ 1e4 kg |
//! | solver.laminae | 1 ≤ Γ ≤ 2000 |
//! | solver.force_tolerance | 1e-16 ≤ x ≤ 1e-4 |
//! | solver.max_iterations, max_roller_iterations | 1 ≤ n ≤ 100 000 |
//! | solver.cage_stiffness_ratio | 0 ≤ x ≤ 1 |

use super::{Bearing, DynamicLoads, FilmModel, GuidingRing, LifeMethod, Slicing, SolverSettings};
use crate::deck::form::{
    material_fields, show, FieldKind, FieldMeta, FieldSpec, MaterialAccess, Presence, Schema,
    TemplateNotes,
};
use crate::units::{Quantity, Units, PSI_PA};

/// Film-model choices, in [`FilmModel`] order.
pub const FILM_MODELS: &[&str] = &["grubin", "dowson-higginson", "pan-hamrock"];
/// Life-method choices, in [`LifeMethod`] order.
pub const LIFE_METHODS: &[&str] = &["asme", "iso281"];
/// Dynamic-load choices, in [`DynamicLoads`] order.
pub const DYNAMIC_LOADS: &[&str] = &["iterated", "estimate"];
/// Slicing choices, in [`Slicing`] order.
pub const SLICINGS: &[&str] = &["uniform", "cosine"];
/// Cage-guidance choices, in [`GuidingRing`] order.
pub const GUIDING_RINGS: &[&str] = &["inner", "outer"];
/// The bodies under `[materials]`.
pub const MATERIAL_BODIES: &[&str] = &["roller", "inner_ring", "outer_ring"];
/// Top-level tables, in file order: the required ones, then the optional `[solver]` and
/// `[thermal]`.
pub const GROUPS: &[&str] = &[
    "geometry",
    "materials",
    "operating",
    "lubricant",
    "surfaces",
    "life",
    "cage",
    "solver",
    "thermal",
];
/// Top-level tables every deck must have: all of [`GROUPS`] but the last two.
pub const REQUIRED_GROUPS: &[&str] = GROUPS.split_at(GROUPS.len() - 2).0;

fn film_index(m: FilmModel) -> f64 {
    match m {
        FilmModel::Grubin => 0.0,
        FilmModel::DowsonHigginson => 1.0,
        FilmModel::PanHamrock => 2.0,
    }
}
fn film_from(v: f64) -> FilmModel {
    match v as usize {
        1 => FilmModel::DowsonHigginson,
        2 => FilmModel::PanHamrock,
        _ => FilmModel::Grubin,
    }
}
fn method_index(m: LifeMethod) -> f64 {
    match m {
        LifeMethod::Asme => 0.0,
        LifeMethod::Iso281 => 1.0,
    }
}
fn method_from(v: f64) -> LifeMethod {
    if v as usize == 1 {
        LifeMethod::Iso281
    } else {
        LifeMethod::Asme
    }
}
fn dynamic_index(d: DynamicLoads) -> f64 {
    match d {
        DynamicLoads::Iterated => 0.0,
        DynamicLoads::Estimate => 1.0,
    }
}
fn dynamic_from(v: f64) -> DynamicLoads {
    if v as usize == 1 {
        DynamicLoads::Estimate
    } else {
        DynamicLoads::Iterated
    }
}
fn slicing_index(d: Slicing) -> f64 {
    match d {
        Slicing::Uniform => 0.0,
        Slicing::Cosine => 1.0,
    }
}
fn slicing_from(v: f64) -> Slicing {
    if v as usize == 1 {
        Slicing::Cosine
    } else {
        Slicing::Uniform
    }
}
fn guide_index(g: GuidingRing) -> f64 {
    match g {
        GuidingRing::Inner => 0.0,
        GuidingRing::Outer => 1.0,
    }
}
fn guide_from(v: f64) -> GuidingRing {
    if v as usize == 0 {
        GuidingRing::Inner
    } else {
        GuidingRing::Outer
    }
}
fn to_count(v: f64) -> usize {
    if v.is_finite() && v >= 0.0 {
        v.round() as usize
    } else {
        0
    }
}

const DEG: f64 = std::f64::consts::PI / 180.0;
const RPM: f64 = std::f64::consts::PI / 30.0;

macro_rules! field {
    ($key:expr, $group:expr, $label:expr, $q:ident, $kind:expr,
     $min:expr, $minx:expr, $max:expr, $maxx:expr, $pres:expr, $help:expr,
     get: $get:expr, set: $set:expr) => {
        FieldSpec {
            meta: FieldMeta::new(
                $key,
                $group,
                $label,
                Quantity::$q,
                $kind,
                ($min, $minx),
                ($max, $maxx),
                $pres,
                $help,
            ),
            get: $get,
            set: $set,
        }
    };
}

const R: FieldKind = FieldKind::Real;
const I: FieldKind = FieldKind::Integer;
const REQ: Presence = Presence::Required;

const MAT_ROLLER: [FieldSpec<Bearing>; 5] =
    material_fields!(Bearing, "roller", "Roller", |b| b.materials.roller);
const MAT_INNER: [FieldSpec<Bearing>; 5] =
    material_fields!(Bearing, "inner_ring", "Inner ring", |b| b
        .materials
        .inner_ring);
const MAT_OUTER: [FieldSpec<Bearing>; 5] =
    material_fields!(Bearing, "outer_ring", "Outer ring", |b| b
        .materials
        .outer_ring);

const SOLVER_DEFAULTS: SolverSettings = SolverSettings::DEFAULT;

/// Every editable scalar key of a spherical roller deck, in file order.
pub static FIELDS: [FieldSpec<Bearing>; 62] = [
    // --- geometry ---
    field!("geometry.roller_count", "geometry", "Roller count Z", Count, I, 3.0, false, 500.0, false, REQ,
        "number of rollers", get: |b| b.geometry.roller_count as f64, set: |b, v| b.geometry.roller_count = to_count(v)),
    field!("geometry.roller_diameter", "geometry", "Roller diameter D", Length, R, 0.0, true, 1.0, false, REQ,
        "roller maximum diameter", get: |b| b.geometry.roller_diameter_m, set: |b, v| b.geometry.roller_diameter_m = v),
    field!("geometry.roller_length", "geometry", "Roller length L", Length, R, 0.0, true, 1.0, false, REQ,
        "roller overall length", get: |b| b.geometry.roller_length_m, set: |b, v| b.geometry.roller_length_m = v),
    field!("geometry.effective_length", "geometry", "Effective length L_eff", Length, R, 0.0, true, 1.0, false, REQ,
        "roller contacting length (≤ roller_length, ≤ 2·roller_crown_radius)",
        get: |b| b.geometry.effective_length_m, set: |b, v| b.geometry.effective_length_m = v),
    field!("geometry.roller_crown_radius", "geometry", "Roller crown radius R_o", Length, R, 0.0, true, 100.0, false, REQ,
        "roller crown radius (≥ roller_diameter/2)",
        get: |b| b.geometry.roller_crown_radius_m, set: |b, v| b.geometry.roller_crown_radius_m = v),
    field!("geometry.inner_crown_radius", "geometry", "Inner raceway crown radius", Length, R, 0.0, true, 100.0, false, REQ,
        "inner raceway crown radius (≥ roller_crown_radius)",
        get: |b| b.geometry.inner_crown_radius_m, set: |b, v| b.geometry.inner_crown_radius_m = v),
    field!("geometry.outer_crown_radius", "geometry", "Outer raceway crown radius", Length, R, 0.0, true, 100.0, false, REQ,
        "outer raceway crown radius (≥ roller_crown_radius; spherical race: P_t/(2 cos β) + D/2)",
        get: |b| b.geometry.outer_crown_radius_m, set: |b, v| b.geometry.outer_crown_radius_m = v),
    field!("geometry.pitch_diameter", "geometry", "Pitch diameter P_t", Length, R, 0.0, true, 10.0, false, REQ,
        "pitch diameter (> roller_diameter; Z·D < π·P_t)",
        get: |b| b.geometry.pitch_diameter_m, set: |b, v| b.geometry.pitch_diameter_m = v),
    field!("geometry.contact_angle", "geometry", "Contact angle β", Angle, R, 0.0, false, 45.0 * DEG, true, REQ,
        "initial contact angle from the radial plane",
        get: |b| b.geometry.contact_angle_rad, set: |b, v| b.geometry.contact_angle_rad = v),
    field!("geometry.diametral_clearance", "geometry", "Diametral clearance", Length, R, -0.01, false, 0.01, false, REQ,
        "diametral clearance, negative = preload (|c| < roller_diameter)",
        get: |b| b.geometry.diametral_clearance_m, set: |b, v| b.geometry.diametral_clearance_m = v),
    // --- materials ---
    MAT_ROLLER[0],
    MAT_ROLLER[1],
    MAT_ROLLER[2],
    MAT_ROLLER[3],
    MAT_ROLLER[4],
    MAT_INNER[0],
    MAT_INNER[1],
    MAT_INNER[2],
    MAT_INNER[3],
    MAT_INNER[4],
    MAT_OUTER[0],
    MAT_OUTER[1],
    MAT_OUTER[2],
    MAT_OUTER[3],
    MAT_OUTER[4],
    // --- operating ---
    field!("operating.inner_speed", "operating", "Inner ring speed Ω₁", Speed, R, -1e6 * RPM, false, 1e6 * RPM, false, REQ,
        "inner ring speed", get: |b| b.operating.inner_speed_rad_s, set: |b, v| b.operating.inner_speed_rad_s = v),
    field!("operating.outer_speed", "operating", "Outer ring speed Ω₂", Speed, R, -1e6 * RPM, false, 1e6 * RPM, false, REQ,
        "outer ring speed", get: |b| b.operating.outer_speed_rad_s, set: |b, v| b.operating.outer_speed_rad_s = v),
    field!("operating.radial_load", "operating", "Radial load F_r", Force, R, 0.0, false, 1e9, false, REQ,
        "radial load", get: |b| b.operating.radial_load_n, set: |b, v| b.operating.radial_load_n = v),
    field!("operating.axial_load", "operating", "Axial load F_a", Force, R, 0.0, false, 1e9, false, REQ,
        "axial load (presses the rings together)", get: |b| b.operating.axial_load_n, set: |b, v| b.operating.axial_load_n = v),
    // --- lubricant ---
    field!("lubricant.viscosity", "lubricant", "Viscosity η₀", Viscosity, R, 0.0, true, 1e4, false, REQ,
        "absolute viscosity at operating temperature", get: |b| b.lubricant.viscosity_pa_s, set: |b, v| b.lubricant.viscosity_pa_s = v),
    field!("lubricant.pressure_viscosity", "lubricant", "Pressure-viscosity coefficient α", PressureViscosity, R, 0.0, true, 1e-6, false,
        Presence::OneOf("lubricant.lubricant_parameter"),
        "pressure-viscosity coefficient (give this OR lubricant_parameter)",
        get: |b| b.lubricant.pressure_viscosity_pa_inv, set: |b, v| b.lubricant.pressure_viscosity_pa_inv = v),
    field!("lubricant.lubricant_parameter", "lubricant", "Lubricant parameter LP = 1e11·η·α", Dimensionless, R, 0.0, true, 1e6, false,
        Presence::OneOf("lubricant.pressure_viscosity"),
        "LP = 1e11·η·α, η·α in s, same number in both unit systems (seed eq. 5.3; give this OR pressure_viscosity)",
        get: |b| 1e11 * b.lubricant.viscosity_pa_s * b.lubricant.pressure_viscosity_pa_inv,
        set: |b, v| b.lubricant.pressure_viscosity_pa_inv = if b.lubricant.viscosity_pa_s > 0.0 { v / (1e11 * b.lubricant.viscosity_pa_s) } else { 0.0 }),
    field!("lubricant.density", "lubricant", "Lubricant density", Density, R, 0.0, true, 1e5, false, REQ,
        "lubricant density", get: |b| b.lubricant.density_kg_m3, set: |b, v| b.lubricant.density_kg_m3 = v),
    field!("lubricant.specific_heat", "lubricant", "Lubricant specific heat", SpecificHeat, R, 0.0, true, 1e5, false, REQ,
        "lubricant specific heat", get: |b| b.lubricant.specific_heat_j_kg_k, set: |b, v| b.lubricant.specific_heat_j_kg_k = v),
    field!("lubricant.transition_shear_stress", "lubricant", "Transition shear stress τ_tr", Pressure, R, 0.0, true, 1e10, false,
        Presence::Default(1000.0 * PSI_PA),
        "Allen–Townsend–Zaretsky transition shear stress",
        get: |b| b.lubricant.transition_shear_stress_pa, set: |b, v| b.lubricant.transition_shear_stress_pa = v),
    field!("lubricant.limiting_traction_coefficient", "lubricant", "Limiting traction coefficient μ_fl", Dimensionless, R, 0.0, false, 1.0, false,
        Presence::Default(0.06), "limiting (pseudo) traction coefficient",
        get: |b| b.lubricant.limiting_traction_coefficient, set: |b, v| b.lubricant.limiting_traction_coefficient = v),
    field!("lubricant.lost_lubrication_traction_coefficient", "lubricant", "Lost-lubrication traction coefficient", Dimensionless, R, 0.0, false, 1.0, false,
        Presence::Default(0.1), "constant traction coefficient when lubrication is lost",
        get: |b| b.lubricant.lost_lubrication_traction_coefficient, set: |b, v| b.lubricant.lost_lubrication_traction_coefficient = v),
    field!("lubricant.film_model", "lubricant", "Film model", Dimensionless, FieldKind::Choice(FILM_MODELS), 0.0, false, 2.0, false,
        Presence::Default(0.0), "film-thickness formula",
        get: |b| film_index(b.lubricant.film_model), set: |b, v| b.lubricant.film_model = film_from(v)),
    // --- surfaces ---
    field!("surfaces.roller_rms", "surfaces", "Roller RMS finish", Roughness, R, 0.0, true, 1e-4, false, REQ,
        "roller RMS surface finish", get: |b| b.surfaces.roller_rms_m, set: |b, v| b.surfaces.roller_rms_m = v),
    field!("surfaces.inner_rms", "surfaces", "Inner race RMS finish", Roughness, R, 0.0, true, 1e-4, false, REQ,
        "inner raceway RMS surface finish", get: |b| b.surfaces.inner_rms_m, set: |b, v| b.surfaces.inner_rms_m = v),
    field!("surfaces.outer_rms", "surfaces", "Outer race RMS finish", Roughness, R, 0.0, true, 1e-4, false, REQ,
        "outer raceway RMS surface finish", get: |b| b.surfaces.outer_rms_m, set: |b, v| b.surfaces.outer_rms_m = v),
    // --- life ---
    field!("life.capacity_reduction", "life", "Capacity reduction ξ", Dimensionless, R, 0.3, false, 1.0, false, REQ,
        "basic dynamic capacity reduction factor", get: |b| b.life.capacity_reduction, set: |b, v| b.life.capacity_reduction = v),
    field!("life.material_factor", "life", "Material life factor", Dimensionless, R, 0.0, true, 100.0, false, REQ,
        "material life-adjustment factor", get: |b| b.life.material_factor, set: |b, v| b.life.material_factor = v),
    field!("life.edge_stress_factor", "life", "Edge stress factor", Dimensionless, R, 1.0, false, 10.0, false, REQ,
        "stress-concentration factor on loaded edge laminae", get: |b| b.life.edge_stress_factor, set: |b, v| b.life.edge_stress_factor = v),
    field!("life.method", "life", "Life method", Dimensionless, FieldKind::Choice(LIFE_METHODS), 0.0, false, 1.0, false,
        Presence::Default(0.0), "lubrication life-adjustment method",
        get: |b| method_index(b.life.method), set: |b, v| b.life.method = method_from(v)),
    field!("life.iso_contamination_factor", "life", "ISO contamination factor e_C", Dimensionless, R, 0.0, false, 1.0, false,
        Presence::Default(1.0), "ISO 281 contamination factor",
        get: |b| b.life.iso_contamination_factor, set: |b, v| b.life.iso_contamination_factor = v),
    field!("life.iso_fatigue_load_limit", "life", "ISO fatigue load limit C_u", Force, R, 0.0, false, 1e9, false,
        Presence::Default(0.0), "ISO 281 fatigue load limit (> 0 required when method = \"iso281\")",
        get: |b| b.life.iso_fatigue_load_limit_n, set: |b, v| b.life.iso_fatigue_load_limit_n = v),
    field!("life.iso_reference_viscosity", "life", "ISO reference viscosity ν₁", KinematicViscosityCst, R, 0.0, false, 0.1, false,
        Presence::Default(0.0), "ISO 281 reference kinematic viscosity, 0 = computed",
        get: |b| b.life.iso_reference_viscosity_m2_s, set: |b, v| b.life.iso_reference_viscosity_m2_s = v),
    // --- cage ---
    field!("cage.rail_width", "cage", "Cage rail width W_cr", Length, R, 0.0, true, 1.0, false, REQ,
        "total width of the cage rails", get: |b| b.cage.rail_width_m, set: |b, v| b.cage.rail_width_m = v),
    field!("cage.mean_diameter", "cage", "Cage rail diameter D_cr", Length, R, 0.0, true, 10.0, false, REQ,
        "mean rail/land interface diameter", get: |b| b.cage.mean_diameter_m, set: |b, v| b.cage.mean_diameter_m = v),
    field!("cage.diametral_clearance", "cage", "Cage rail clearance", Length, R, 0.0, false, 0.1, false, REQ,
        "diametral clearance between lands and rails", get: |b| b.cage.diametral_clearance_m, set: |b, v| b.cage.diametral_clearance_m = v),
    field!("cage.guided_by", "cage", "Guiding ring", Dimensionless, FieldKind::Choice(GUIDING_RINGS), 0.0, false, 1.0, false, REQ,
        "ring whose lands guide the cage", get: |b| guide_index(b.cage.guided_by), set: |b, v| b.cage.guided_by = guide_from(v)),
    field!("cage.drag_factor", "cage", "Drag factor Ψ", Dimensionless, R, 0.0, false, 100.0, false, Presence::Default(5.0),
        "viscous-drag factor of eq. 9.5", get: |b| b.cage.drag_factor, set: |b, v| b.cage.drag_factor = v),
    field!("cage.mass", "cage", "Cage mass", Mass, R, 0.0, false, 1e4, false, Presence::Default(0.0),
        "cage mass", get: |b| b.cage.mass_kg, set: |b, v| b.cage.mass_kg = v),
    // --- solver ---
    field!("solver.laminae", "solver", "Laminae Γ", Count, I, 1.0, false, 2000.0, false, Presence::Default(SOLVER_DEFAULTS.laminae as f64),
        "laminae per roller", get: |b| b.solver.laminae as f64, set: |b, v| b.solver.laminae = to_count(v)),
    field!("solver.force_tolerance", "solver", "Force tolerance", Dimensionless, R, 1e-16, false, 1e-4, false,
        Presence::Default(SOLVER_DEFAULTS.force_tolerance),
        "equilibrium force tolerance relative to the reference load",
        get: |b| b.solver.force_tolerance, set: |b, v| b.solver.force_tolerance = v),
    field!("solver.max_iterations", "solver", "Bearing iteration limit", Count, I, 1.0, false, 1e5, false,
        Presence::Default(SOLVER_DEFAULTS.max_iterations as f64), "Newton iteration limit of the bearing equilibrium",
        get: |b| b.solver.max_iterations as f64, set: |b, v| b.solver.max_iterations = to_count(v)),
    field!("solver.max_roller_iterations", "solver", "Roller iteration limit", Count, I, 1.0, false, 1e5, false,
        Presence::Default(SOLVER_DEFAULTS.max_roller_iterations as f64), "Newton iteration limit of one roller's equilibrium",
        get: |b| b.solver.max_roller_iterations as f64, set: |b, v| b.solver.max_roller_iterations = to_count(v)),
    field!("solver.cage_stiffness_ratio", "solver", "Cage stiffness ratio", Dimensionless, R, 0.0, false, 1.0, false,
        Presence::Default(SOLVER_DEFAULTS.cage_stiffness_ratio), "cage pocket stiffness as a fraction of contact stiffness",
        get: |b| b.solver.cage_stiffness_ratio, set: |b, v| b.solver.cage_stiffness_ratio = v),
    field!("solver.dynamic_loads", "solver", "Dynamic loads from", Dimensionless, FieldKind::Choice(DYNAMIC_LOADS), 0.0, false, 1.0, false,
        Presence::Default(0.0), "speeds for CF and gyroscopic moment: iterated with §7, or App. C estimate",
        get: |b| dynamic_index(b.solver.dynamic_loads), set: |b, v| b.solver.dynamic_loads = dynamic_from(v)),
    field!("solver.slicing", "solver", "Lamina slicing", Dimensionless, FieldKind::Choice(SLICINGS), 0.0, false, 1.0, false,
        Presence::Default(1.0), "lamina spacing: uniform (the seed's) or cosine (thin laminae at the roller ends)",
        get: |b| slicing_index(b.solver.slicing), set: |b, v| b.solver.slicing = slicing_from(v)),
    field!("solver.stiffness", "solver", "Stiffness method", Dimensionless, FieldKind::Choice(crate::bearings::stiffness::METHODS), 0.0, false, 2.0, false,
        Presence::Default(0.0), "the stiffness matrix: \"analytic\" (each roller's condensed Jacobian), \"finite-difference\" (central differences of the re-solved rollers) or \"both\" (analytic, checked: finite_difference_max_rel)",
        get: |b| b.solver.stiffness.index(), set: |b, v| b.solver.stiffness = crate::bearings::stiffness::Method::from_index(v)),
    // padding rows are not allowed: the array length is exact
];

/// The material of body `i` of [`MATERIAL_BODIES`].
fn material_of(b: &Bearing, i: usize) -> crate::physics::material::Material {
    match i {
        0 => b.materials.roller,
        1 => b.materials.inner_ring,
        _ => b.materials.outer_ring,
    }
}

fn set_material(b: &mut Bearing, i: usize, m: crate::physics::material::Material) {
    match i {
        0 => b.materials.roller = m,
        1 => b.materials.inner_ring = m,
        _ => b.materials.outer_ring = m,
    }
}

/// The value a deck starts from before its fields are applied: the aerospace example
/// (every required key is then overwritten, every optional one set to its default).
fn defaults() -> Bearing {
    Bearing::example_aerospace()
}

/// Rules that involve more than one key; each names the other keys it involves (so it
/// is only reported when those are valid, see [`crate::deck::form`]). The error points
/// at the first key.
pub fn cross_checks(b: &Bearing, units: Units) -> Vec<(&'static str, String)> {
    let g = &b.geometry;
    let show = |key: &str| show(&SCHEMA, b, key, units);
    let pi = std::f64::consts::PI;
    let rules: Vec<(&'static str, bool, String)> = vec![
        (
            "geometry.pitch_diameter",
            g.pitch_diameter_m > g.roller_diameter_m,
            format!("must be greater than {}", show("geometry.roller_diameter")),
        ),
        (
            "geometry.roller_crown_radius",
            g.roller_crown_radius_m >= g.roller_diameter_m / 2.0,
            format!(
                "must be at least half of {}",
                show("geometry.roller_diameter")
            ),
        ),
        (
            "geometry.inner_crown_radius",
            g.inner_crown_radius_m >= g.roller_crown_radius_m,
            format!("must be at least {}", show("geometry.roller_crown_radius")),
        ),
        (
            "geometry.outer_crown_radius",
            g.outer_crown_radius_m >= g.roller_crown_radius_m,
            format!("must be at least {}", show("geometry.roller_crown_radius")),
        ),
        (
            "geometry.effective_length",
            g.effective_length_m <= g.roller_length_m,
            format!("must not exceed {}", show("geometry.roller_length")),
        ),
        (
            "geometry.effective_length",
            g.effective_length_m <= 2.0 * g.roller_crown_radius_m,
            format!(
                "must not exceed twice {}",
                show("geometry.roller_crown_radius")
            ),
        ),
        (
            "geometry.roller_count",
            (g.roller_count as f64) * g.roller_diameter_m < pi * g.pitch_diameter_m,
            format!(
                "rollers do not fit around the pitch circle: need Z·D < π·P_t with {}, {}",
                show("geometry.roller_diameter"),
                show("geometry.pitch_diameter")
            ),
        ),
        (
            "geometry.diametral_clearance",
            g.diametral_clearance_m.abs() < g.roller_diameter_m,
            format!(
                "|clearance| must be less than {}",
                show("geometry.roller_diameter")
            ),
        ),
        (
            "life.method",
            b.life.method != LifeMethod::Iso281 || b.life.iso_fatigue_load_limit_n > 0.0,
            format!(
                "method \"iso281\" needs {} > 0",
                "life.iso_fatigue_load_limit"
            ),
        ),
    ];
    rules
        .into_iter()
        .filter(|(_, ok, _)| !ok)
        .map(|(key, _, rule)| (key, rule))
        .collect()
}

/// The spherical roller's deck.
pub static SCHEMA: Schema<Bearing> = Schema {
    system: super::SYSTEM_ID,
    groups: GROUPS,
    required_groups: REQUIRED_GROUPS,
    fields: &FIELDS,
    material_bodies: MATERIAL_BODIES,
    material: Some(MaterialAccess {
        get: material_of,
        set: set_material,
    }),
    opaque_tables: &["thermal"],
    defaults,
    cross_checks,
    one_holding: &[],
    template_header: "rollbench deck template: every key, its unit and allowed range.\nValues are the aerospace example bearing (decks/aerospace.toml).",
    template_notes: TEMPLATE_NOTES,
};

/// The template's name and its comment lines beyond the fields'.
/// The template's `[thermal]` section: a small working network, commented out (remove
/// the leading `# ` of its lines to use it; `decks/aerospace.toml` has an 18-node one).
/// Every heat source of the bearing (`inner_contacts`, `outer_contacts`, `rollers`,
/// `cage_rails`, `viscous_drag`) must go to a node. A test uncomments it and builds it.
pub const THERMAL_NOTE: &str =
    "[thermal]  # optional: a lumped thermal network (seed 000 §10), steady state and
# loss-of-oil transient. A small working example follows; uncomment it to use it.
# [thermal]
# units = \"si\"    # °C, J/K, W/K, m, m², kg/s, whatever the deck's units
#
# [[thermal.nodes]]
# name = \"rings_and_rollers\"
# capacity = 900.0            # J/K
# limit = 230.0               # °C: the transient reports when it is reached
# heat = [\"inner_contacts\", \"outer_contacts\", \"rollers\", \"cage_rails\"]
#
# [[thermal.nodes]]
# name = \"oil_in\"
# role = \"oil\"
# fixed_temperature = 80.0    # °C
#
# [[thermal.nodes]]
# name = \"oil_cavity\"
# role = \"oil\"
# capacity = 100.0
# air_capacity = 5.0          # J/K once the oil is lost
# heat = [\"viscous_drag\"]
#
# [[thermal.links]]
# from = \"oil_in\"
# to = \"oil_cavity\"
# kind = \"mass_transport\"
# mass_flow = 0.05            # kg/s
# specific_heat = 2000.0      # J/(kg·K)
#
# [[thermal.links]]
# from = \"oil_cavity\"
# to = \"rings_and_rollers\"
# kind = \"convection\"
# h = 2500.0                  # W/(m²·K)
# area = 0.02                 # m²
# h_loss_of_oil = 60.0
#
# [thermal.transient]
# duration = 600.0            # s
# step = 1.0
# integrator = \"implicit\"
# scenario = \"loss_of_oil\"
# oil_node = \"oil_cavity\"";

pub const TEMPLATE_NOTES: TemplateNotes = TemplateNotes {
    name: "template (aerospace example bearing)",
    group_notes: &[("solver", "Optional table: numerical settings.")],
    opaque_notes: &[("thermal", THERMAL_NOTE)],
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The template's commented `[thermal]` example works: uncommented, the deck reads and
    /// its network builds (issue 15: the template's thermal section was a stub).
    #[test]
    fn template_thermal_example_is_a_working_network() {
        let t = crate::bearings::spherical_roller::deck::template(crate::units::Units::Si);
        let start = t.find("# [thermal]\n").expect("the example");
        let (head, tail) = t.split_at(start);
        let example: String = tail
            .lines()
            .map(|l| {
                l.strip_prefix("# ")
                    .or_else(|| l.strip_prefix('#'))
                    .unwrap_or(l)
            })
            .map(|l| format!("{l}\n"))
            .collect();
        let deck =
            crate::bearings::spherical_roller::deck::parse(&format!("{head}{example}"), "t.toml")
                .unwrap_or_else(|e| panic!("{e}"));
        let model = deck.thermal_model().unwrap_or_else(|e| panic!("{e}"));
        assert!(model.is_some());
    }

    #[test]
    fn required_groups_are_all_but_solver_and_thermal() {
        assert_eq!(
            REQUIRED_GROUPS,
            [
                "geometry",
                "materials",
                "operating",
                "lubricant",
                "surfaces",
                "life",
                "cage"
            ]
        );
    }

    #[test]
    fn registry_is_consistent() {
        let mut keys: Vec<_> = FIELDS.iter().map(|f| f.key).collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), n, "duplicate keys");
        for f in &FIELDS {
            assert!(f.key.starts_with(f.group), "{}", f.key);
            assert_eq!(f.unit_si, f.quantity.unit(Units::Si));
            assert_eq!(f.unit_us, f.quantity.unit(Units::Us));
            assert!(f.min < f.max, "{}", f.key);
        }
        // get/set are inverse on the example bearing (exact: plain stores and loads,
        // except the derived lubricant parameter which divides by η: 1e-15 relative).
        let b = Bearing::example_aerospace();
        for f in &FIELDS {
            let mut c = b.clone();
            f.set_si(&mut c, f.get_si(&b));
            let (x, y) = (f.get_si(&c), f.get_si(&b));
            assert!((x - y).abs() <= 1e-15 * y.abs(), "{}", f.key);
        }
    }

    #[test]
    fn allowed_text() {
        let f = SCHEMA
            .field("geometry.roller_count")
            .map(|f| f.allowed(Units::Us));
        assert_eq!(f.as_deref(), Some("3 ≤ value ≤ 500"));
        let f = SCHEMA
            .field("geometry.contact_angle")
            .map(|f| f.allowed(Units::Si));
        assert_eq!(f.as_deref(), Some("0 ≤ value < 45 deg"));
        let f = SCHEMA
            .field("geometry.roller_diameter")
            .map(|f| f.allowed(Units::Us));
        assert_eq!(f.as_deref(), Some("0 < value ≤ 39.37 in"));
        assert_eq!(crate::deck::format_short(1.0e-6), "1e-6");
        assert_eq!(crate::deck::format_short(6894.757), "6894.76");
    }
}
