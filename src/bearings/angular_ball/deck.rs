//! The deck of `type = "angular-contact-ball"`: its [`Schema`] over [`BallInput`] for the
//! generic deck reader (`crate::deck::form`). Key names are a contract (issue 16).

use super::input::*;
use crate::deck::form::{
    material_fields, FieldKind, FieldMeta, FieldSpec, MaterialAccess, Presence, Schema,
};
use crate::physics::contact::point::HertzMethod;
use crate::units::{Quantity, Units};

const HERTZ: &[&str] = &["exact", "brewe-hamrock"];
const PRELOAD: &[&str] = &["displacement", "force"];
const RACE: &[&str] = &["outer", "inner", "auto"];
const GYRO: &[&str] = &["resisting", "seed"];
const CURVES: &[&str] = &["constant", "curve-1", "curve-2", "curve-3"];
const METHODS: &[&str] = &["race-control", "quasi-static", "time-simulation"];

const BALL: [FieldSpec<BallInput>; 5] =
    material_fields!(BallInput, "ball", "Ball", |b| b.materials.ball);
const RINGS: [FieldSpec<BallInput>; 5] =
    material_fields!(BallInput, "rings", "Rings", |b| b.materials.rings);

static FIELDS: [FieldSpec<BallInput>; 39] = [
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.ball_count",
            "geometry",
            "Ball count Z",
            Quantity::Count,
            FieldKind::Integer,
            (1.0, false),
            (500.0, false),
            Presence::Required,
            "number of balls",
        ),
        get: |b| b.geometry.ball_count as f64,
        set: |b, v| b.geometry.ball_count = v as usize,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.ball_diameter",
            "geometry",
            "Ball diameter D",
            Quantity::Length,
            FieldKind::Real,
            (0.0, true),
            (1.0, false),
            Presence::Required,
            "ball diameter",
        ),
        get: |b| b.geometry.ball_diameter_m,
        set: |b, v| b.geometry.ball_diameter_m = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.pitch_diameter",
            "geometry",
            "Pitch diameter d_m",
            Quantity::Length,
            FieldKind::Real,
            (0.0, true),
            (10.0, false),
            Presence::Required,
            "pitch diameter",
        ),
        get: |b| b.geometry.pitch_diameter_m,
        set: |b, v| b.geometry.pitch_diameter_m = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.inner_groove_curvature",
            "geometry",
            "Inner groove curvature f_i",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.5, true),
            (1.0, false),
            Presence::Required,
            "inner groove radius / ball diameter",
        ),
        get: |b| b.geometry.inner_groove_curvature,
        set: |b, v| b.geometry.inner_groove_curvature = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.outer_groove_curvature",
            "geometry",
            "Outer groove curvature f_o",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.5, true),
            (1.0, false),
            Presence::Required,
            "outer groove radius / ball diameter",
        ),
        get: |b| b.geometry.outer_groove_curvature,
        set: |b, v| b.geometry.outer_groove_curvature = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.free_contact_angle",
            "geometry",
            "Free contact angle α₀",
            Quantity::Angle,
            FieldKind::Real,
            (0.0, false),
            (std::f64::consts::FRAC_PI_2, true),
            Presence::Required,
            "unloaded contact angle (sets the clearance 2(f_i+f_o−1)D(1−cos α₀))",
        ),
        get: |b| b.geometry.free_contact_angle_rad,
        set: |b, v| b.geometry.free_contact_angle_rad = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.hertz_method",
            "geometry",
            "Hertz method",
            Quantity::Dimensionless,
            FieldKind::Choice(HERTZ),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "exact elliptic integrals, or the Brewe–Hamrock fits A-17",
        ),
        get: |b| match b.geometry.hertz_method { HertzMethod::Exact => 0.0, HertzMethod::BreweHamrock => 1.0 },
        set: |b, v| b.geometry.hertz_method = if v == 1.0 { HertzMethod::BreweHamrock } else { HertzMethod::Exact },
    },
    BALL[0],
    BALL[1],
    BALL[2],
    BALL[3],
    BALL[4],
    RINGS[0],
    RINGS[1],
    RINGS[2],
    RINGS[3],
    RINGS[4],
    FieldSpec {
        meta: FieldMeta::new(
            "operating.inner_speed",
            "operating",
            "Inner ring speed",
            Quantity::Speed,
            FieldKind::Real,
            (-1e5, false),
            (1e5, false),
            Presence::Required,
            "inner ring speed",
        ),
        get: |b| b.operating.inner_speed_rad_s,
        set: |b, v| b.operating.inner_speed_rad_s = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "operating.outer_speed",
            "operating",
            "Outer ring speed",
            Quantity::Speed,
            FieldKind::Real,
            (-1e5, false),
            (1e5, false),
            Presence::Default(0.0),
            "outer ring speed",
        ),
        get: |b| b.operating.outer_speed_rad_s,
        set: |b, v| b.operating.outer_speed_rad_s = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "operating.axial_load",
            "operating",
            "Axial load (preload) F_a",
            Quantity::Force,
            FieldKind::Real,
            (0.0, true),
            (1e7, false),
            Presence::Required,
            "axial load on the inner ring (the preload)",
        ),
        get: |b| b.operating.axial_load_n,
        set: |b, v| b.operating.axial_load_n = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "operating.preload_mode",
            "operating",
            "Preload held as",
            Quantity::Dimensionless,
            FieldKind::Choice(PRELOAD),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "\"displacement\": the axial displacement the load produces at rest is held (the seed's reading); \"force\": the force is held",
        ),
        get: |b| match b.operating.preload_mode { PreloadMode::Displacement => 0.0, PreloadMode::Force => 1.0 },
        set: |b, v| b.operating.preload_mode = if v == 1.0 { PreloadMode::Force } else { PreloadMode::Displacement },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "operating.radial_load",
            "operating",
            "Radial load F_r",
            Quantity::Force,
            FieldKind::Real,
            (0.0, false),
            (1e7, false),
            Presence::Default(0.0),
            "radial load on the inner ring",
        ),
        get: |b| b.operating.radial_load_n,
        set: |b, v| b.operating.radial_load_n = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "kinematics.race_control",
            "kinematics",
            "Controlling race",
            Quantity::Dimensionless,
            FieldKind::Choice(RACE),
            (0.0, false),
            (2.0, false),
            Presence::Default(0.0),
            "race without spin (2-9): outer, inner, or auto (Jones/Harris criterion)",
        ),
        get: |b| match b.kinematics.race_control { RaceControl::Outer => 0.0, RaceControl::Inner => 1.0, RaceControl::Auto => 2.0 },
        set: |b, v| b.kinematics.race_control = if v == 1.0 { RaceControl::Inner } else if v == 2.0 { RaceControl::Auto } else { RaceControl::Outer },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "kinematics.gyroscopic_friction",
            "kinematics",
            "Gyroscopic friction sign",
            Quantity::Dimensionless,
            FieldKind::Choice(GYRO),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "\"resisting\": friction couple equal to J·ω_m·ω_r (physical); \"seed\": the signs printed in eq. 2-5 (reproduces the seed's ch. 6 numbers)",
        ),
        get: |b| match b.kinematics.gyroscopic_friction { GyroscopicFriction::Resisting => 0.0, GyroscopicFriction::SeedSign => 1.0 },
        set: |b, v| b.kinematics.gyroscopic_friction = if v == 1.0 { GyroscopicFriction::SeedSign } else { GyroscopicFriction::Resisting },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "traction.curve",
            "traction",
            "Traction curve",
            Quantity::Dimensionless,
            FieldKind::Choice(CURVES),
            (0.0, false),
            (3.0, false),
            Presence::Default(1.0),
            "constant µ, or the seed's curves 1–3 (piecewise linear between the printed points)",
        ),
        get: |b| match b.traction.preset { TractionPreset::Constant => 0.0, TractionPreset::Curve1 => 1.0, TractionPreset::Curve2 => 2.0, TractionPreset::Curve3 => 3.0 },
        set: |b, v| b.traction.preset = match v as usize { 0 => TractionPreset::Constant, 2 => TractionPreset::Curve2, 3 => TractionPreset::Curve3, _ => TractionPreset::Curve1 },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "traction.mu",
            "traction",
            "Traction coefficient µ",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (1.0, false),
            Presence::Default(0.054),
            "µ of the constant law",
        ),
        get: |b| b.traction.mu,
        set: |b, v| b.traction.mu = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.viscosity",
            "lubricant",
            "Viscosity η₀",
            Quantity::Viscosity,
            FieldKind::Real,
            (0.0, true),
            (1e3, false),
            Presence::Required,
            "viscosity at the supply temperature, ambient pressure",
        ),
        get: |b| b.lubricant.viscosity_pa_s,
        set: |b, v| b.lubricant.viscosity_pa_s = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.pressure_viscosity",
            "lubricant",
            "Pressure–viscosity α",
            Quantity::PressureViscosity,
            FieldKind::Real,
            (0.0, false),
            (1e-6, false),
            Presence::Required,
            "Barus pressure–viscosity coefficient",
        ),
        get: |b| b.lubricant.pressure_viscosity_pa_inv,
        set: |b, v| b.lubricant.pressure_viscosity_pa_inv = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.temperature_viscosity",
            "lubricant",
            "Temperature–viscosity β",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (1.0, false),
            Presence::Default(0.008),
            "viscosity–temperature coefficient β of eq. 4-18, 1/°C in both unit systems",
        ),
        get: |b| b.lubricant.temperature_viscosity_per_k,
        set: |b, v| b.lubricant.temperature_viscosity_per_k = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.density",
            "lubricant",
            "Oil density",
            Quantity::Density,
            FieldKind::Real,
            (0.0, true),
            (1e5, false),
            Presence::Required,
            "oil density",
        ),
        get: |b| b.lubricant.density_kg_m3,
        set: |b, v| b.lubricant.density_kg_m3 = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.specific_heat",
            "lubricant",
            "Oil specific heat",
            Quantity::SpecificHeat,
            FieldKind::Real,
            (0.0, true),
            (1e5, false),
            Presence::Required,
            "oil specific heat",
        ),
        get: |b| b.lubricant.specific_heat_j_kg_k,
        set: |b, v| b.lubricant.specific_heat_j_kg_k = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.conductivity",
            "lubricant",
            "Oil conductivity",
            Quantity::Conductivity,
            FieldKind::Real,
            (0.0, true),
            (1e3, false),
            Presence::Default(0.14),
            "oil thermal conductivity",
        ),
        get: |b| b.lubricant.conductivity_w_m_k,
        set: |b, v| b.lubricant.conductivity_w_m_k = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.flow_rate_l_min",
            "lubricant",
            "Oil flow rate",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, true),
            (1e4, false),
            Presence::Required,
            "oil flow through the bearing, litre/min in both unit systems (eq. 4-1)",
        ),
        get: |b| b.lubricant.flow_rate_m3_s * 60_000.0,
        set: |b, v| b.lubricant.flow_rate_m3_s = v / 60_000.0,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.supply_temperature",
            "lubricant",
            "Oil supply temperature",
            Quantity::Temperature,
            FieldKind::Real,
            (0.0, true),
            (1000.0, false),
            Presence::Required,
            "oil supply temperature",
        ),
        get: |b| b.lubricant.supply_temperature_k,
        set: |b, v| b.lubricant.supply_temperature_k = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.method",
            "dynamics",
            "Method",
            Quantity::Dimensionless,
            FieldKind::Choice(METHODS),
            (0.0, false),
            (2.0, false),
            Presence::Default(0.0),
            "race-control, quasi-static (ball moment balance per position) or time-simulation (ball motion over its orbits)",
        ),
        get: |b| match b.dynamics.method { Method::RaceControl => 0.0, Method::QuasiStatic => 1.0, Method::TimeSimulation => 2.0 },
        set: |b, v| b.dynamics.method = match v as usize { 1 => Method::QuasiStatic, 2 => Method::TimeSimulation, _ => Method::RaceControl },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.skid_search_limit",
            "dynamics",
            "Skid search limit",
            Quantity::Speed,
            FieldKind::Real,
            (0.0, true),
            (1e5, false),
            Presence::Default(1570.7963267948967),
            "highest relative ring speed searched for the skidding threshold",
        ),
        get: |b| b.dynamics.skid_search_limit_rad_s,
        set: |b, v| b.dynamics.skid_search_limit_rad_s = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.slices",
            "dynamics",
            "Slices per contact",
            Quantity::Count,
            FieldKind::Integer,
            (1.0, false),
            (2001.0, false),
            Presence::Default(41.0),
            "slices across each contact ellipse for the ball dynamics",
        ),
        get: |b| b.dynamics.slices as f64,
        set: |b, v| b.dynamics.slices = v as usize,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.orbits",
            "dynamics",
            "Orbits simulated",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, true),
            (1000.0, false),
            Presence::Default(5.0),
            "orbits of each ball in the time simulation",
        ),
        get: |b| b.dynamics.orbits,
        set: |b, v| b.dynamics.orbits = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.tolerance",
            "dynamics",
            "Integrator tolerance",
            Quantity::Dimensionless,
            FieldKind::Real,
            (1e-13, false),
            (1e-2, false),
            Presence::Default(1e-8),
            "relative tolerance of the ball-dynamics integrator",
        ),
        get: |b| b.dynamics.tolerance,
        set: |b, v| b.dynamics.tolerance = v,
    },
];

fn cross_checks(b: &BallInput, _units: Units) -> Vec<(&'static str, String)> {
    let mut v = Vec::new();
    if b.geometry.pitch_diameter_m <= b.geometry.ball_diameter_m {
        v.push((
            "geometry.pitch_diameter",
            "must exceed geometry.ball_diameter".to_string(),
        ));
    }
    v
}

/// The deck schema of the angular-contact ball bearing.
pub static SCHEMA: Schema<BallInput> = Schema {
    system: super::system::SYSTEM_ID,
    groups: &[
        "geometry",
        "materials",
        "operating",
        "kinematics",
        "traction",
        "lubricant",
        "dynamics",
    ],
    required_groups: &["geometry", "materials", "operating", "lubricant"],
    fields: &FIELDS,
    material_bodies: &["ball", "rings"],
    material: Some(MaterialAccess {
        get: |b, i| {
            if i == 0 {
                b.materials.ball
            } else {
                b.materials.rings
            }
        },
        set: |b, i, m| {
            if i == 0 {
                b.materials.ball = m
            } else {
                b.materials.rings = m
            }
        },
    }),
    opaque_tables: &[],
    defaults: BallInput::chen_a,
    cross_checks,
    template_header: "rollbench deck: angular-contact ball bearing (seed 001, S.-H. Chen 1989)\nLoad distribution with centrifugal force and gyroscopic moment, race-control\nkinematics, spin heat, EHD film and the skidding threshold.",
};
