//! The deck of `type = "angular-contact-ball"`: its [`Schema`] over [`BallInput`] for the
//! generic deck reader (`crate::deck::form`). Key names are a contract (issue 16).

use super::input::*;
use crate::deck::form::Form;
use crate::deck::form::{
    material_fields, show, FieldKind, FieldMeta, FieldSpec, MaterialAccess, Presence, Schema,
};
use crate::deck::thermal::PathSeg;
use crate::deck::{DeckError, DeckErrors, Location};
use crate::physics::contact::point::HertzMethod;
use crate::physics::lubrication::rheology::ViscosityModel;
use crate::units::{Quantity, Units};

/// The `[cage]` section's keys (issue 28), shared with the other systems.
const CAGE: [FieldSpec<BallInput>; 5] =
    crate::bearings::friction::cage_loss_fields!(BallInput, |b| b.cage);
const HERTZ: &[&str] = &["exact", "brewe-hamrock"];
const PRELOAD: &[&str] = &["displacement", "force"];
const RACE: &[&str] = &["outer", "inner", "auto"];
const GYRO: &[&str] = &["resisting", "seed"];
const SPLIT: &[&str] = &["proportional", "controlling-race"];
const STIFFNESS: &[&str] = &["analytic", "finite-difference", "both"];
const CURVES: &[&str] = &[
    "constant", "curve-1", "curve-2", "curve-3", "table", "rheology",
];
const VISCOSITY: &[&str] = &["barus", "roelands"];
const METHODS: &[&str] = &["race-control", "quasi-static", "time-simulation"];
const INTEGRATORS: &[&str] = &["auto", "dopri5", "rodas4"];
const ORBITS: &[&str] = &["cage", "free"];

const BALL: [FieldSpec<BallInput>; 5] =
    material_fields!(BallInput, "ball", "Ball", |b| b.materials.ball);
const RINGS: [FieldSpec<BallInput>; 5] =
    material_fields!(BallInput, "rings", "Rings", |b| b.materials.rings);

static FIELDS: [FieldSpec<BallInput>; 56] = [
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
            Presence::OneOf("geometry.clearance"),
            "unloaded contact angle (sets the clearance 2(f_i+f_o−1)D(1−cos α₀)); give this OR clearance",
        ),
        get: |b| b.geometry.free_contact_angle(),
        set: |b, v| {
            b.geometry.free_contact_angle_rad = v;
            b.geometry.clearance_m = None;
        },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "geometry.clearance",
            "geometry",
            "Diametral clearance P_d",
            Quantity::Length,
            FieldKind::Real,
            (0.0, false),
            (0.1, false),
            Presence::OneOf("geometry.free_contact_angle"),
            "diametral clearance before loading: α₀ = acos(1 − P_d/(2(f_i+f_o−1)D)); give this OR free_contact_angle",
        ),
        get: |b| b.geometry.clearance(),
        set: |b, v| b.geometry.clearance_m = Some(v),
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
            (0.0, false),
            (1e7, false),
            Presence::Required,
            "axial load on the inner ring (the preload); 0 for a pure radial load (the ring then finds its axial place from the radial load)",
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
            "operating.moment",
            "operating",
            "Moment M",
            Quantity::Moment,
            FieldKind::RealOr("held"),
            (-1e6, false),
            (1e6, false),
            Presence::Default(f64::NAN),
            "moment on the inner ring about the axis across the radial load (positive tilts the ring's side under the radial load towards the axial load); \"held\": the tilt is held at operating.misalignment instead",
        ),
        get: |b| b.operating.moment_nm.unwrap_or(f64::NAN),
        set: |b, v| b.operating.moment_nm = (!v.is_nan()).then_some(v),
    },
    FieldSpec {
        meta: FieldMeta::new(
            "operating.misalignment",
            "operating",
            "Misalignment θ",
            Quantity::Angle,
            FieldKind::Real,
            (-0.05, false),
            (0.05, false),
            Presence::Default(0.0),
            "tilt of the inner ring about the axis across the radial load, held when no operating.moment is given (same sign as the moment's)",
        ),
        get: |b| b.operating.misalignment_rad,
        set: |b, v| b.operating.misalignment_rad = v,
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
            "kinematics.friction_split",
            "kinematics",
            "Gyroscopic friction split",
            Quantity::Dimensionless,
            FieldKind::Choice(SPLIT),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "how the friction resisting the gyroscopic moment is shared: \"proportional\" (Chen, 2-7: in proportion to the normal loads) or \"controlling-race\" (Harris, OpenJones: all at the controlling race, λ = 2, none at the other)",
        ),
        get: |b| match b.kinematics.friction_split { FrictionSplit::Proportional => 0.0, FrictionSplit::ControllingRace => 1.0 },
        set: |b, v| b.kinematics.friction_split = if v == 1.0 { FrictionSplit::ControllingRace } else { FrictionSplit::Proportional },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "solver.stiffness",
            "solver",
            "Stiffness matrix by",
            Quantity::Dimensionless,
            FieldKind::Choice(STIFFNESS),
            (0.0, false),
            (2.0, false),
            Presence::Default(0.0),
            "the 5×5 stiffness matrix: \"analytic\" (the ring Newton's Jacobian, the balls condensed), \"finite-difference\" (central differences of the re-solved ball equilibria) or \"both\" (analytic, checked: finite_difference_max_rel)",
        ),
        get: |b| match b.solver.stiffness { StiffnessMethod::Analytic => 0.0, StiffnessMethod::FiniteDifference => 1.0, StiffnessMethod::Both => 2.0 },
        set: |b, v| b.solver.stiffness = match v as usize { 1 => StiffnessMethod::FiniteDifference, 2 => StiffnessMethod::Both, _ => StiffnessMethod::Analytic },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "traction.curve",
            "traction",
            "Traction curve",
            Quantity::Dimensionless,
            FieldKind::Choice(CURVES),
            (0.0, false),
            (5.0, false),
            Presence::Default(1.0),
            "constant µ, the seed's curves 1–3 (piecewise linear between the printed points), a table ([traction_table] points = [[u_s m/s, µ], …]) or the ch. 4 rheology of [lubricant] tabulated at the contact before the run",
        ),
        get: |b| match b.traction.preset { TractionPreset::Constant => 0.0, TractionPreset::Curve1 => 1.0, TractionPreset::Curve2 => 2.0, TractionPreset::Curve3 => 3.0, TractionPreset::Table => 4.0, TractionPreset::Rheology => 5.0 },
        set: |b, v| b.traction.preset = match v as usize { 0 => TractionPreset::Constant, 2 => TractionPreset::Curve2, 3 => TractionPreset::Curve3, 4 => TractionPreset::Table, 5 => TractionPreset::Rheology, _ => TractionPreset::Curve1 },
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
            Quantity::PerDegreeCelsius,
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
            Quantity::VolumeFlowLMin,
            FieldKind::Real,
            (0.0, true),
            // 10 000 l/min, in m³/s.
            (1e4 * 1e-3 / 60.0, false),
            Presence::Required,
            "oil flow through the bearing, litre/min in both unit systems (eq. 4-1)",
        ),
        get: |b| b.lubricant.flow_rate_m3_s,
        set: |b, v| b.lubricant.flow_rate_m3_s = v,
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
            "lubricant.viscosity_model",
            "lubricant",
            "Pressure–viscosity law",
            Quantity::Dimensionless,
            FieldKind::Choice(VISCOSITY),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "Barus (4-18) or Roelands (4-22) viscosity of the rheology traction curve (traction.curve = \"rheology\")",
        ),
        get: |b| match b.lubricant.viscosity_model { ViscosityModel::Barus => 0.0, ViscosityModel::Roelands => 1.0 },
        set: |b, v| b.lubricant.viscosity_model = if v == 1.0 { ViscosityModel::Roelands } else { ViscosityModel::Barus },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.roelands_z",
            "lubricant",
            "Roelands Z",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (5.0, false),
            Presence::Default(0.0),
            "Roelands pressure index Z (4-19); 0: from α by (4-20) (SAE 30: 0.42)",
        ),
        get: |b| b.lubricant.roelands_z,
        set: |b, v| b.lubricant.roelands_z = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.limiting_shear_coefficient",
            "lubricant",
            "Limiting shear coeff. C",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (1.0, false),
            Presence::Default(0.054),
            "C of the limiting shear stress τ_L = τ₀ + C·p (4-17; Chen's Fig. 6-19: 0.054); C = τ₀ = 0: no limit",
        ),
        get: |b| b.lubricant.limiting_shear_coefficient,
        set: |b, v| b.lubricant.limiting_shear_coefficient = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "lubricant.limiting_shear_stress",
            "lubricant",
            "Limiting shear stress τ₀",
            Quantity::Pressure,
            FieldKind::Real,
            (0.0, false),
            (1e10, false),
            Presence::Default(0.0),
            "τ₀ of the limiting shear stress τ_L = τ₀ + C·p (4-17)",
        ),
        get: |b| b.lubricant.limiting_shear_stress_pa,
        set: |b, v| b.lubricant.limiting_shear_stress_pa = v,
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
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.integrator",
            "dynamics",
            "Integrator",
            Quantity::Dimensionless,
            FieldKind::Choice(INTEGRATORS),
            (0.0, false),
            (2.0, false),
            Presence::Default(0.0),
            "time simulation's integrator: auto (DOPRI5, Rodas4 once the stiffness test fires), dopri5 or rodas4",
        ),
        get: |b| match b.dynamics.integrator {
            Integrator::Auto => 0.0,
            Integrator::Dopri5 => 1.0,
            Integrator::Rodas4 => 2.0,
        },
        set: |b, v| {
            b.dynamics.integrator = match v as usize {
                1 => Integrator::Dopri5,
                2 => Integrator::Rodas4,
                _ => Integrator::Auto,
            }
        },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "dynamics.orbit",
            "dynamics",
            "Orbital speed",
            Quantity::Dimensionless,
            FieldKind::Choice(ORBITS),
            (0.0, false),
            (1.0, false),
            Presence::Default(1.0),
            "the ball's orbital speed: free (integrated per ball, 2-14a with no cage force; the default) or cage (held at race control's cage speed)",
        ),
        get: |b| match b.dynamics.orbit {
            Orbit::Cage => 0.0,
            Orbit::Free => 1.0,
        },
        set: |b, v| {
            b.dynamics.orbit = match v as usize {
                1 => Orbit::Free,
                _ => Orbit::Cage,
            }
        },
    },
    FieldSpec {
        meta: FieldMeta::new(
            "surfaces.composite_rms",
            "surfaces",
            "Composite roughness σ",
            Quantity::Roughness,
            FieldKind::RealOr("none"),
            (0.0, true),
            (1e-4, false),
            Presence::Default(f64::NAN),
            "composite rms roughness of ball and race, sqrt(σ_ball² + σ_race²), for the film parameter Λ = h_min/σ at every contact and in the life; \"none\" (the default): no Λ",
        ),
        get: |b| b.surfaces.composite_rms_m.unwrap_or(f64::NAN),
        set: |b, v| b.surfaces.composite_rms_m = (!v.is_nan()).then_some(v),
    },
    CAGE[0],
    CAGE[1],
    CAGE[2],
    CAGE[3],
    CAGE[4],
];

fn cross_checks(b: &BallInput, units: Units) -> Vec<(&'static str, String)> {
    let mut v = Vec::new();
    // A land-guided cage needs all its rail keys (one rule: `CageLosses::rail_key_problem`).
    v.extend(b.cage.rail_key_problem());
    if let Some(pd) = b.geometry.clearance_m {
        let two_a = 2.0 * b.geometry.centre_distance_m();
        if pd >= two_a {
            v.push((
                "geometry.clearance",
                format!(
                    "must be below 2(f_i+f_o−1)·D (where α₀ reaches 90°) for {}, {} and {}",
                    show(&SCHEMA, b, "geometry.ball_diameter", units),
                    show(&SCHEMA, b, "geometry.inner_groove_curvature", units),
                    show(&SCHEMA, b, "geometry.outer_groove_curvature", units),
                ),
            ));
        }
    }
    // One DOF, one holding (issue 29): a moment and a held tilt both given is refused,
    // naming both keys.
    if b.operating.moment_nm.is_some() && b.operating.misalignment_rad != 0.0 {
        v.push((
            "operating.moment",
            format!(
                "and operating.misalignment ({}) both hold the ring's tilt: give the moment (the tilt is solved) or the misalignment (the moment follows), not both",
                show(&SCHEMA, b, "operating.misalignment", units),
            ),
        ));
    }
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
    system: super::SYSTEM_ID,
    groups: &[
        "geometry",
        "materials",
        "operating",
        "kinematics",
        "traction",
        "traction_table",
        "lubricant",
        "dynamics",
        "solver",
        "surfaces",
        "cage",
        "thermal",
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
    opaque_tables: &["traction_table", "thermal"],
    defaults: BallInput::chen_a,
    cross_checks,
    one_holding: &[crate::deck::form::OneHolding {
        load: "operating.moment",
        displacement: "operating.misalignment",
        dof: "the ring's tilt",
    }],
    template_header: "rollbench deck: angular-contact ball bearing (seed 001, S.-H. Chen 1989)\nLoad distribution with centrifugal force and gyroscopic moment, race-control\nkinematics, spin heat, EHD film and the skidding threshold.",
    template_notes: crate::deck::form::TemplateNotes {
        opaque_notes: &[(
            "thermal",
            crate::bearings::thermal_answer::thermal_template_note!(
                "\"inner_contacts\", \"outer_contacts\", \"rollers\""
            ),
        )],
        ..crate::deck::form::TemplateNotes::NONE
    },
};

/// Reads the deck's `[traction_table] points = [[u_s, µ], …]` (sliding speed m/s and
/// µ, in both unit systems) into `form.value.traction.table`, checked: at least two
/// points, each two finite numbers, speeds ≥ 0 and strictly increasing, 0 ≤ µ ≤ 1.
/// `traction.curve = "table"` needs the table. Errors name the point with file:line.
/// The table is an opaque table of the generic form (arrays are not form fields).
pub fn traction_table(form: &mut Form<BallInput>) -> Result<(), DeckErrors> {
    const KEY: &str = "traction_table.points";
    let loc = |form: &Form<BallInput>, path: &[PathSeg]| form.location_in("traction_table", path);
    let points_path = vec![PathSeg::Key("points".into())];
    let Some(table) = form.opaque.get("traction_table") else {
        form.value.traction.table.clear();
        if form.value.traction.preset == TractionPreset::Table {
            return Err(DeckError::Missing {
                location: Location::start(form.source_name()),
                key: KEY.into(),
                hint: " (traction.curve = \"table\" needs [traction_table] points = [[u_s m/s, µ], …])".into(),
            }
            .into());
        }
        return Ok(());
    };
    let invalid = |location: Location, value: String, rule: String| -> DeckErrors {
        DeckError::Invalid {
            location,
            key: KEY.into(),
            value,
            rule,
        }
        .into()
    };
    if let Some(other) = table.keys().find(|k| k.as_str() != "points") {
        return Err(DeckError::UnknownKey {
            location: loc(form, &[PathSeg::Key(other.clone())]),
            key: format!("traction_table.{other}"),
            hint: " (allowed: points)".into(),
        }
        .into());
    }
    let Some(raw) = table.get("points") else {
        return Err(DeckError::Missing {
            location: loc(form, &[]),
            key: KEY.into(),
            hint: " ([[u_s m/s, µ], …])".into(),
        }
        .into());
    };
    let Some(list) = raw.as_array() else {
        return Err(DeckError::WrongType {
            location: loc(form, &points_path),
            key: KEY.into(),
            value: raw.to_string(),
            expected: "an array of [sliding speed m/s, µ] pairs".into(),
        }
        .into());
    };
    let mut points = Vec::with_capacity(list.len());
    for (i, p) in list.iter().enumerate() {
        let mut path = points_path.clone();
        path.push(PathSeg::Index(i));
        let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|n| n as f64));
        let pair = p
            .as_array()
            .filter(|a| a.len() == 2)
            .and_then(|a| Some((num(&a[0])?, num(&a[1])?)));
        let Some((u, mu)) = pair else {
            return Err(DeckError::WrongType {
                location: loc(form, &path),
                key: format!("{KEY}[{i}]"),
                value: p.to_string(),
                expected: "a pair [sliding speed m/s, µ] of numbers".into(),
            }
            .into());
        };
        if !(u.is_finite() && u >= 0.0) {
            return Err(invalid(
                loc(form, &path),
                p.to_string(),
                format!("point {}: the sliding speed must be ≥ 0 m/s", i + 1),
            ));
        }
        if !(mu.is_finite() && (0.0..=1.0).contains(&mu)) {
            return Err(invalid(
                loc(form, &path),
                p.to_string(),
                format!("point {}: µ must be in [0, 1]", i + 1),
            ));
        }
        if let Some(&(prev, _)) = points.last() {
            if u <= prev {
                return Err(invalid(
                    loc(form, &path),
                    p.to_string(),
                    format!(
                        "point {}: sliding speeds must increase strictly ({u} after {prev} m/s)",
                        i + 1
                    ),
                ));
            }
        }
        points.push((u, mu));
    }
    if points.len() < 2 {
        return Err(invalid(
            loc(form, &points_path),
            raw.to_string(),
            "at least two points are needed".into(),
        ));
    }
    // µ below the first point: the table starts at zero sliding with the first µ.
    if points[0].0 > 0.0 {
        return Err(invalid(
            loc(form, &points_path),
            raw.to_string(),
            "the first point must be at zero sliding speed (0 m/s)".into(),
        ));
    }
    form.value.traction.table = points;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::BearingSystem;

    const DECK: &str = include_str!("../../../decks/chen_b.toml");

    fn load(extra: &str, curve: &str) -> Result<Form<BallInput>, DeckErrors> {
        let text = DECK.replace("curve = \"curve-1\"", &format!("curve = \"{curve}\"")) + extra;
        let mut form = Form::parse(&text, "b.toml", &SCHEMA)?;
        traction_table(&mut form)?;
        Ok(form)
    }

    /// A table deck gives the points (exact) and the piecewise-linear curve through them;
    /// the system's `load` reads it too.
    #[test]
    fn table_is_read() {
        let f = load(
            "\n[traction_table]\npoints = [[0, 0.0], [0.5, 0.06], [3.0, 0.04]]\n",
            "table",
        )
        .unwrap();
        assert_eq!(f.value.traction.preset, TractionPreset::Table);
        assert_eq!(
            f.value.traction.table,
            vec![(0.0, 0.0), (0.5, 0.06), (3.0, 0.04)]
        );
        let c = f.value.traction.curve();
        assert!((c.mu(0.25) - 0.03).abs() < 1e-15);
        assert_eq!(c.max_mu(), 0.06);
        let text = DECK.replace("curve = \"curve-1\"", "curve = \"table\"")
            + "\n[traction_table]\npoints = [[0, 0.0], [0.5, 0.06]]\n";
        assert!(super::super::system::SYSTEM
            .load(&text, "b.toml", &[])
            .is_ok());
    }

    /// Bad tables are refused with file:line of the offending point and the rule.
    #[test]
    fn bad_tables_name_the_point() {
        let line = DECK.lines().count() + 3;
        let cases = [
            ("points = [[0, 0.0]]", "at least two points"),
            (
                "points = [[0, 0.0], [0.5, 0.06], [0.5, 0.07]]",
                "increase strictly",
            ),
            ("points = [[0, 0.0], [0.5, 1.5]]", "µ must be in [0, 1]"),
            ("points = [[0, 0.0], [0.5]]", "pair"),
            ("points = [[0.1, 0.0], [0.5, 0.06]]", "zero sliding"),
            ("points = 3", "array"),
        ];
        for (table, rule) in cases {
            let e = load(&format!("\n[traction_table]\n{table}\n"), "table")
                .unwrap_err()
                .to_string();
            assert!(e.contains(rule), "{table}: {e}");
            assert!(e.contains(&format!("b.toml:{line}:")), "{table}: {e}");
            assert!(e.contains("traction_table.points"), "{e}");
        }
        let e = load("", "table").unwrap_err().to_string();
        assert!(
            e.contains("traction_table.points") && e.contains("needs"),
            "{e}"
        );
        let e = load("\n[traction_table]\npointz = []\n", "table")
            .unwrap_err()
            .to_string();
        assert!(e.contains("unknown key") && e.contains("pointz"), "{e}");
        // Other curves ignore a table's absence; the deck as shipped has none.
        assert!(load("", "curve-2").unwrap().value.traction.table.is_empty());
    }

    /// The rheology keys: defaults (Barus, Z from α, C = 0.054, τ₀ = 0) and overrides.
    #[test]
    fn rheology_keys() {
        let f = load("", "rheology").unwrap();
        let l = &f.value.lubricant;
        assert_eq!(f.value.traction.preset, TractionPreset::Rheology);
        assert_eq!(l.viscosity_model, ViscosityModel::Barus);
        assert_eq!(
            (
                l.roelands_z,
                l.limiting_shear_coefficient,
                l.limiting_shear_stress_pa
            ),
            (0.0, 0.054, 0.0)
        );
        let text = DECK.replace(
            "supply_temperature = 40.0",
            "supply_temperature = 40.0\nviscosity_model = \"roelands\"\nroelands_z = 0.42\nlimiting_shear_coefficient = 0.07\nlimiting_shear_stress = 1e6",
        );
        let f = Form::parse(&text, "b.toml", &SCHEMA).unwrap();
        let r = f.value.lubricant.rheology();
        assert_eq!(r.model, ViscosityModel::Roelands);
        assert_eq!(r.roelands_z, Some(0.42));
        assert_eq!(r.limiting_shear_stress_pa(0.0), Some(1e6));
        assert!((r.limiting_shear_stress_pa(1e9).unwrap() - 7.1e7).abs() < 1e-6);
    }

    /// `dynamics.orbit`: free by default (a deck without the key), "cage" read,
    /// anything else refused with file:line, the key and the choices.
    #[test]
    fn orbit_key() {
        assert_eq!(
            load("", "curve-1").unwrap().value.dynamics.orbit,
            Orbit::Free
        );
        let with = |v: &str| {
            DECK.replace(
                "method = \"race-control\"",
                &format!("method = \"race-control\"\norbit = \"{v}\""),
            )
        };
        let f = Form::parse(&with("free"), "b.toml", &SCHEMA).unwrap();
        assert_eq!(f.value.dynamics.orbit, Orbit::Free);
        let f = Form::parse(&with("cage"), "b.toml", &SCHEMA).unwrap();
        assert_eq!(f.value.dynamics.orbit, Orbit::Cage);
        let line = DECK
            .lines()
            .position(|l| l.starts_with("method = \"race-control\""))
            .unwrap()
            + 2;
        let e = Form::parse(&with("loose"), "b.toml", &SCHEMA)
            .unwrap_err()
            .to_string();
        assert!(e.contains("dynamics.orbit"), "{e}");
        assert!(e.contains(&format!("b.toml:{line}:")), "{e}");
        assert!(e.contains("cage") && e.contains("free"), "{e}");
    }

    /// `geometry.clearance` instead of the free contact angle: read as P_d (SI), one of
    /// the pair only, and P_d ≥ 2(f_i+f_o−1)D refused by the cross-check.
    #[test]
    fn clearance_or_free_contact_angle() {
        let text = DECK.replace(
            "free_contact_angle = 60.0        # deg",
            "clearance = 50e-6",
        );
        let f = Form::parse(&text, "b.toml", &SCHEMA).unwrap();
        assert_eq!(f.value.geometry.clearance_m, Some(50e-6));
        assert!(
            (f.value.geometry.free_contact_angle() - (1.0 - 50e-6 / 0.96e-3f64).acos()).abs()
                < 1e-12
        );
        let both = DECK.replace(
            "free_contact_angle = 60.0",
            "clearance = 50e-6\nfree_contact_angle = 60.0",
        );
        let e = Form::parse(&both, "b.toml", &SCHEMA)
            .unwrap_err()
            .to_string();
        assert!(e.contains("exactly one"), "{e}");
        let big = DECK.replace(
            "free_contact_angle = 60.0        # deg",
            "clearance = 0.002",
        );
        let e = Form::parse(&big, "b.toml", &SCHEMA)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("geometry.clearance") && e.contains("must be below"),
            "{e}"
        );
        // The shipped deck: α₀ as given, no clearance.
        let f = Form::parse(DECK, "b.toml", &SCHEMA).unwrap();
        assert_eq!(f.value.geometry.clearance_m, None);
    }
}
