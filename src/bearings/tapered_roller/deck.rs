//! The tapered roller deck (`type = "tapered-roller"`): its keys as a
//! [`crate::deck::form::Schema`] over [`TaperedInput`]. Key names are a contract (issue 17).

use super::geometry::{crown_drop_at_gauge, crown_radius};
use super::input::{Clearance, Crown, GyroInertia, RollerProfile, StiffnessMethod, TaperedInput};
use crate::deck::form::{
    material_fields, show, FieldKind, FieldMeta, FieldSpec, MaterialAccess, Presence, Schema,
};
use crate::units::{Quantity, Units, INCH_M};

use super::SYSTEM_ID;

/// The `[cage]` section's keys (issue 28), shared with the other systems.
const CAGE: [FieldSpec<TaperedInput>; 5] =
    crate::bearings::friction::cage_loss_fields!(TaperedInput, |t| t.cage);
const STIFFNESS: &[&str] = &["analytic", "finite-difference", "both"];
const GYRO: &[&str] = &["polar", "transverse"];
const PROFILES: &[&str] = &["crowned", "logarithmic"];

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

const ROLLER: [FieldSpec<TaperedInput>; 5] =
    material_fields!(TaperedInput, "roller", "Roller", |t| t.materials.roller);
const CUP: [FieldSpec<TaperedInput>; 5] =
    material_fields!(TaperedInput, "cup", "Cup", |t| t.materials.cup);
const CONE: [FieldSpec<TaperedInput>; 5] =
    material_fields!(TaperedInput, "cone", "Cone", |t| t.materials.cone);

static FIELDS: [FieldSpec<TaperedInput>; 70] = [
    FieldSpec {
        meta: meta("geometry.roller_count", "geometry", "Rollers n", Quantity::Count, INT, (3.0, false), (500.0, false), REQ, "number of rollers"),
        get: |t| t.geometry.roller_count as f64,
        set: |t, v| t.geometry.roller_count = v as usize,
    },
    FieldSpec {
        meta: meta("geometry.roller_diameter", "geometry", "Roller diameter d", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "roller diameter at the midpoint of the effective length"),
        get: |t| t.geometry.roller_diameter_m,
        set: |t, v| t.geometry.roller_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.pitch_diameter", "geometry", "Pitch diameter E", Quantity::Length, REAL, (0.0, true), (10.0, false), REQ, "pitch diameter at the midpoint of the effective length"),
        get: |t| t.geometry.pitch_diameter_m,
        set: |t, v| t.geometry.pitch_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.cup_angle", "geometry", "Cup angle β", Quantity::Angle, REAL, (0.0, true), (60.0 * DEG, false), REQ, "cup (outer race) contact angle"),
        get: |t| t.geometry.cup_angle_rad,
        set: |t, v| t.geometry.cup_angle_rad = v,
    },
    FieldSpec {
        meta: meta("geometry.effective_length", "geometry", "Effective length l_e", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "effective (load-carrying) length of the roller"),
        get: |t| t.geometry.effective_length_m,
        set: |t, v| t.geometry.effective_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.flat_length", "geometry", "Flat length l_F", Quantity::Length, REAL, (0.0, false), (1.0, false), Presence::Default(0.0), "length of the flat (uncrowned) middle of the roller profile; 0: fully crowned"),
        get: |t| t.geometry.flat_length_m,
        set: |t, v| t.geometry.flat_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.crown_radius", "geometry", "Crown radius R_c", Quantity::Length, REAL, (0.0, true), (1000.0, false), Presence::OneOf("geometry.crown_drop"), "roller crown radius (give this OR crown_drop)"),
        get: |t| crown_radius(&t.geometry),
        set: |t, v| t.geometry.crown = Crown::Radius(v),
    },
    FieldSpec {
        meta: meta("geometry.crown_drop", "geometry", "Crown drop V′", Quantity::Length, REAL, (0.0, true), (0.01, false), Presence::OneOf("geometry.crown_radius"), "crown drop at the gauge point (give this OR crown_radius)"),
        get: |t| crown_drop_at_gauge(&t.geometry),
        set: |t, v| t.geometry.crown = Crown::Drop(v),
    },
    FieldSpec {
        meta: meta("geometry.crown_gauge", "geometry", "Crown drop gauge point G", Quantity::Length, REAL, (0.0, false), (1.0, false), Presence::Default(0.03 * INCH_M), "distance from each end of the effective length to where the crown drop is measured"),
        get: |t| t.geometry.crown_gauge_m,
        set: |t, v| t.geometry.crown_gauge_m = v,
    },
    FieldSpec {
        meta: meta("geometry.profile", "geometry", "Roller profile", Quantity::Dimensionless, FieldKind::Choice(PROFILES), (0.0, false), (1.0, false), Presence::Default(0.0), "the contacts' roller profile: crowned (flat middle and circular crowns, the crown keys; default) or logarithmic (ISO/TS 16281 eq. 44, 0.00045·d·ln[1/(1 − (2x/l_e)²)]; the crown keys then shape only the end faces)"),
        get: |t| match t.geometry.profile {
            RollerProfile::Crowned => 0.0,
            RollerProfile::Logarithmic => 1.0,
        },
        set: |t, v| {
            t.geometry.profile = if v as usize == 1 {
                RollerProfile::Logarithmic
            } else {
                RollerProfile::Crowned
            }
        },
    },
    FieldSpec {
        meta: meta("geometry.small_end_break", "geometry", "Small-end corner break B₁", Quantity::Length, REAL, (0.0, false), (0.1, false), Presence::Default(0.0), "corner break at the roller's small end"),
        get: |t| t.geometry.small_end_break_m,
        set: |t, v| t.geometry.small_end_break_m = v,
    },
    FieldSpec {
        meta: meta("geometry.big_end_break", "geometry", "Big-end corner break B₂", Quantity::Length, REAL, (0.0, false), (0.1, false), Presence::Default(0.0), "corner break at the roller's big end"),
        get: |t| t.geometry.big_end_break_m,
        set: |t, v| t.geometry.big_end_break_m = v,
    },
    FieldSpec {
        meta: meta("geometry.big_end_radius_ratio", "geometry", "Big-end radius R_E/l_s", Quantity::Dimensionless, REAL, (0.0, true), (10.0, false), REQ, "big-end spherical radius as a fraction of the roller cone's slant height (the seed's '0.8 in' is this ratio)"),
        get: |t| t.geometry.big_end_radius_ratio,
        set: |t, v| t.geometry.big_end_radius_ratio = v,
    },
    FieldSpec {
        meta: meta("geometry.flange_contact_ratio", "geometry", "Flange contact r/R₂", Quantity::Dimensionless, REAL, (0.0, true), (1.0, false), REQ, "radius of the flange contact point from the roller axis as a fraction of the big-end radius (the seed's '0.75 in')"),
        get: |t| t.geometry.flange_contact_ratio,
        set: |t, v| t.geometry.flange_contact_ratio = v,
    },
    FieldSpec {
        meta: meta("geometry.diametral_clearance", "geometry", "Diametral clearance P_D", Quantity::Length, REAL, (-0.01, false), (0.01, false), Presence::OneOf("geometry.end_play"), "diametral play before loading, negative for interference (give this OR end_play)"),
        get: |t| t.geometry.diametral_clearance_m(),
        set: |t, v| t.geometry.clearance = Clearance::Diametral(v),
    },
    FieldSpec {
        meta: meta("geometry.end_play", "geometry", "End play e", Quantity::Length, REAL, (-0.01, false), (0.01, false), Presence::OneOf("geometry.diametral_clearance"), "axial end play before loading, P_D = 2e·tan β (give this OR diametral_clearance)"),
        get: |t| t.geometry.end_play_m(),
        set: |t, v| t.geometry.clearance = Clearance::EndPlay(v),
    },
    ROLLER[0], ROLLER[1], ROLLER[2], ROLLER[3], ROLLER[4],
    CUP[0], CUP[1], CUP[2], CUP[3], CUP[4],
    CONE[0], CONE[1], CONE[2], CONE[3], CONE[4],
    FieldSpec {
        meta: meta("operating.inner_speed", "operating", "Cone speed Ω₂", Quantity::Speed, REAL, (-200_000.0 * RPM, false), (200_000.0 * RPM, false), Presence::Default(0.0), "inner ring (cone) speed"),
        get: |t| t.operating.inner_speed_rad_s,
        set: |t, v| t.operating.inner_speed_rad_s = v,
    },
    FieldSpec {
        meta: meta("operating.outer_speed", "operating", "Cup speed Ω₁", Quantity::Speed, REAL, (-200_000.0 * RPM, false), (200_000.0 * RPM, false), Presence::Default(0.0), "outer ring (cup) speed"),
        get: |t| t.operating.outer_speed_rad_s,
        set: |t, v| t.operating.outer_speed_rad_s = v,
    },
    FieldSpec {
        meta: meta("operating.axial_load", "operating", "Axial load F_z", Quantity::Force, REAL, (-1e8, false), (1e8, false), REQ, "thrust on the cone; positive seats the bearing (a single tapered bearing carries no other)"),
        get: |t| t.operating.axial_load_n,
        set: |t, v| t.operating.axial_load_n = v,
    },
    FieldSpec {
        meta: meta("operating.radial_load", "operating", "Radial load F_x", Quantity::Force, REAL, (0.0, false), (1e8, false), Presence::Default(0.0), "radial load on the cone along x (roller 1's azimuth)"),
        get: |t| t.operating.radial_load_n,
        set: |t, v| t.operating.radial_load_n = v,
    },
    FieldSpec {
        meta: meta("operating.initial_displacement_x", "operating", "Initial δx″", Quantity::Length, REAL, (-0.01, false), (0.01, false), Presence::Default(0.0), "initial displacement of the cone along x"),
        get: |t| t.operating.initial_displacement_m[0],
        set: |t, v| t.operating.initial_displacement_m[0] = v,
    },
    FieldSpec {
        meta: meta("operating.initial_displacement_y", "operating", "Initial δy″", Quantity::Length, REAL, (-0.01, false), (0.01, false), Presence::Default(0.0), "initial displacement of the cone along y"),
        get: |t| t.operating.initial_displacement_m[1],
        set: |t, v| t.operating.initial_displacement_m[1] = v,
    },
    FieldSpec {
        meta: meta("operating.initial_displacement_z", "operating", "Initial δz″", Quantity::Length, REAL, (-0.01, false), (0.01, false), Presence::Default(0.0), "initial axial displacement of the cone"),
        get: |t| t.operating.initial_displacement_m[2],
        set: |t, v| t.operating.initial_displacement_m[2] = v,
    },
    FieldSpec {
        meta: meta("operating.misalignment_x", "operating", "Misalignment θx", Quantity::Angle, REAL, (-5.0 * DEG, false), (5.0 * DEG, false), Presence::Default(0.0), "rotation of the cone about x, held by the shaft (its moment is reported)"),
        get: |t| t.operating.misalignment_rad[0],
        set: |t, v| t.operating.misalignment_rad[0] = v,
    },
    FieldSpec {
        meta: meta("operating.misalignment_y", "operating", "Misalignment θy", Quantity::Angle, REAL, (-5.0 * DEG, false), (5.0 * DEG, false), Presence::Default(0.0), "rotation of the cone about y, held by the shaft (its moment is reported)"),
        get: |t| t.operating.misalignment_rad[1],
        set: |t, v| t.operating.misalignment_rad[1] = v,
    },
    FieldSpec {
        meta: meta("operating.moment", "operating", "Moment M_y", Quantity::Moment, FieldKind::RealOr("held"), (-1e7, false), (1e7, false), Presence::Default(f64::NAN), "moment on the cone about y (perpendicular to the radial load; positive loads the rollers the radial load loads): the cone's tilt θy is then solved for it; \"held\" (the default): θy is held at operating.misalignment_y"),
        get: |t| t.operating.moment_nm,
        set: |t, v| t.operating.moment_nm = v,
    },
    FieldSpec {
        meta: meta("solver.slices", "solver", "Slices", Quantity::Count, INT, (3.0, false), (1001.0, false), Presence::Default(21.0), "slices per contact along the effective length"),
        get: |t| t.solver.slices as f64,
        set: |t, v| t.solver.slices = v as usize,
    },
    FieldSpec {
        meta: meta("solver.force_tolerance", "solver", "Force tolerance", Quantity::Dimensionless, REAL, (0.0, true), (1e-4, false), Presence::Default(1e-9), "equilibrium force residual relative to the applied load"),
        get: |t| t.solver.force_tolerance,
        set: |t, v| t.solver.force_tolerance = v,
    },
    FieldSpec {
        meta: meta("solver.max_iterations", "solver", "Bearing iterations", Quantity::Count, INT, (1.0, false), (1000.0, false), Presence::Default(60.0), "largest number of bearing Newton iterations"),
        get: |t| t.solver.max_iterations as f64,
        set: |t, v| t.solver.max_iterations = v as usize,
    },
    FieldSpec {
        meta: meta("solver.max_roller_iterations", "solver", "Roller iterations", Quantity::Count, INT, (1.0, false), (1000.0, false), Presence::Default(60.0), "largest number of Newton iterations of one roller"),
        get: |t| t.solver.max_roller_iterations as f64,
        set: |t, v| t.solver.max_roller_iterations = v as usize,
    },
    FieldSpec {
        meta: meta("solver.stiffness", "solver", "Stiffness", Quantity::Dimensionless, FieldKind::Choice(STIFFNESS), (0.0, false), (2.0, false), Presence::Default(0.0), "analytic, finite-difference (re-solved equilibria) or both (the difference reported)"),
        get: |t| match t.solver.stiffness {
            StiffnessMethod::Analytic => 0.0,
            StiffnessMethod::FiniteDifference => 1.0,
            StiffnessMethod::Both => 2.0,
        },
        set: |t, v| {
            t.solver.stiffness = match v as usize {
                1 => StiffnessMethod::FiniteDifference,
                2 => StiffnessMethod::Both,
                _ => StiffnessMethod::Analytic,
            }
        },
    },
    FieldSpec {
        meta: meta("solver.gyroscopic_inertia", "solver", "Gyroscopic inertia", Quantity::Dimensionless, FieldKind::Choice(GYRO), (0.0, false), (1.0, false), Presence::Default(0.0), "inertia of the gyroscopic moment (eq. 37): polar (spin axis, default) or transverse (as printed)"),
        get: |t| match t.solver.gyroscopic_inertia {
            GyroInertia::Polar => 0.0,
            GyroInertia::Transverse => 1.0,
        },
        set: |t, v| {
            t.solver.gyroscopic_inertia = if v as usize == 1 {
                GyroInertia::Transverse
            } else {
                GyroInertia::Polar
            }
        },
    },    FieldSpec {
        meta: meta("pedestal.stiffness_x", "pedestal", "Pedestal k_x", Quantity::LinearStiffness, REAL, (0.0, false), (1e15, false), Presence::Default(0.0), "pedestal stiffness in series with the bearing (eq. 9); 0 = rigid"),
        get: |t| t.pedestal.stiffness[0],
        set: |t, v| t.pedestal.stiffness[0] = v,
    },
    FieldSpec {
        meta: meta("pedestal.stiffness_y", "pedestal", "Pedestal k_y", Quantity::LinearStiffness, REAL, (0.0, false), (1e15, false), Presence::Default(0.0), "pedestal stiffness in series with the bearing (eq. 9); 0 = rigid"),
        get: |t| t.pedestal.stiffness[1],
        set: |t, v| t.pedestal.stiffness[1] = v,
    },
    FieldSpec {
        meta: meta("pedestal.stiffness_z", "pedestal", "Pedestal k_z", Quantity::LinearStiffness, REAL, (0.0, false), (1e15, false), Presence::Default(0.0), "pedestal stiffness in series with the bearing (eq. 9); 0 = rigid"),
        get: |t| t.pedestal.stiffness[2],
        set: |t, v| t.pedestal.stiffness[2] = v,
    },
    FieldSpec {
        meta: meta("pedestal.stiffness_thetax", "pedestal", "Pedestal k_θx", Quantity::AngularStiffness, REAL, (0.0, false), (1e15, false), Presence::Default(0.0), "pedestal stiffness in series with the bearing (eq. 9); 0 = rigid"),
        get: |t| t.pedestal.stiffness[3],
        set: |t, v| t.pedestal.stiffness[3] = v,
    },
    FieldSpec {
        meta: meta("pedestal.stiffness_thetay", "pedestal", "Pedestal k_θy", Quantity::AngularStiffness, REAL, (0.0, false), (1e15, false), Presence::Default(0.0), "pedestal stiffness in series with the bearing (eq. 9); 0 = rigid"),
        get: |t| t.pedestal.stiffness[4],
        set: |t, v| t.pedestal.stiffness[4] = v,
    },
    // [lubricant] (issue 28 item 3): optional; viscosity "none" (the default) keeps the
    // dry answer of loads, stresses, stiffness and life without κ. Key names and meanings
    // are the cylindrical deck's.
    FieldSpec {
        meta: meta("lubricant.viscosity", "lubricant", "Viscosity η₀", Quantity::Viscosity, FieldKind::RealOr("none"), (0.0, true), (1e3, false), Presence::Default(f64::NAN), "dynamic viscosity at the reference temperature and ambient pressure, or \"none\" for no lubricant (no film, friction or heat); a MIL-PRF-23699 turbine oil: 0.0248 Pa·s at 40 °C"),
        get: |t| t.lubricant.viscosity_pa_s,
        set: |t, v| t.lubricant.viscosity_pa_s = v,
    },
    FieldSpec {
        meta: meta("lubricant.reference_temperature", "lubricant", "Reference temperature T₀", Quantity::Temperature, REAL, (223.15, false), (573.15, false), Presence::Default(313.15), "temperature at which lubricant.viscosity is given"),
        get: |t| t.lubricant.reference_temperature_k,
        set: |t, v| t.lubricant.reference_temperature_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.pressure_viscosity", "lubricant", "Pressure-viscosity α", Quantity::PressureViscosity, REAL, (0.0, false), (1e-6, false), Presence::Default(1.1e-8), "pressure-viscosity coefficient (polyol-ester turbine oil ≈ 1.1e-8 1/Pa)"),
        get: |t| t.lubricant.pressure_viscosity_pa_inv,
        set: |t, v| t.lubricant.pressure_viscosity_pa_inv = v,
    },
    FieldSpec {
        meta: meta("lubricant.temperature_viscosity", "lubricant", "Temperature-viscosity β", Quantity::PerDegreeCelsius, REAL, (0.0, false), (1.0, false), Presence::Default(0.0268), "temperature-viscosity coefficient, η = η₀·exp(−β(T − T₀))"),
        get: |t| t.lubricant.temperature_viscosity_k_inv,
        set: |t, v| t.lubricant.temperature_viscosity_k_inv = v,
    },
    FieldSpec {
        meta: meta("lubricant.density", "lubricant", "Density ρ₀", Quantity::Density, REAL, (0.0, true), (1e5, false), Presence::Default(990.0), "lubricant density at the inlet"),
        get: |t| t.lubricant.density_kg_m3,
        set: |t, v| t.lubricant.density_kg_m3 = v,
    },
    FieldSpec {
        meta: meta("lubricant.inlet_temperature", "lubricant", "Inlet temperature", Quantity::Temperature, REAL, (223.15, false), (573.15, false), Presence::Default(313.15), "lubricant inlet temperature: the films' and the friction's viscosity"),
        get: |t| t.lubricant.inlet_temperature_k,
        set: |t, v| t.lubricant.inlet_temperature_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.boundary_friction", "lubricant", "Boundary friction µ_b", Quantity::Dimensionless, REAL, (0.0, false), (1.0, false), Presence::Default(0.1), "friction coefficient of the asperity contacts (mixed lubrication)"),
        get: |t| t.lubricant.boundary_friction,
        set: |t, v| t.lubricant.boundary_friction = v,
    },
    FieldSpec {
        meta: meta("lubricant.limiting_shear", "lubricant", "Limiting shear τ₀", Quantity::Pressure, REAL, (0.0, false), (1e9, false), Presence::Default(2.3e6), "atmospheric limiting shear stress, τ_L = τ₀ + γp"),
        get: |t| t.lubricant.limiting_shear_pa,
        set: |t, v| t.lubricant.limiting_shear_pa = v,
    },
    FieldSpec {
        meta: meta("lubricant.limiting_shear_slope", "lubricant", "Limiting shear slope γ", Quantity::Dimensionless, REAL, (0.0, false), (1.0, false), Presence::Default(0.047), "pressure coefficient of the limiting shear τ_L = τ₀ + γp"),
        get: |t| t.lubricant.limiting_shear_slope,
        set: |t, v| t.lubricant.limiting_shear_slope = v,
    },
    FieldSpec {
        meta: meta("lubricant.flange_friction", "lubricant", "Flange friction µ_f", Quantity::Dimensionless, FieldKind::RealOr("film"), (0.0, false), (1.0, false), Presence::Default(f64::NAN), "roller-end/flange friction coefficient, or \"film\" to take it from the flange film (mixed boundary/viscous)"),
        get: |t| t.lubricant.flange_friction,
        set: |t, v| t.lubricant.flange_friction = v,
    },
    FieldSpec {
        meta: meta("surfaces.composite_rms", "surfaces", "Composite roughness σ", Quantity::Roughness, REAL, (0.0, true), (1e-4, false), Presence::Default(0.15e-6), "composite rms roughness of roller and race (and roller end and flange)"),
        get: |t| t.surfaces.composite_rms_m,
        set: |t, v| t.surfaces.composite_rms_m = v,
    },
    FieldSpec {
        meta: meta("surfaces.roughness_parameter", "surfaces", "Roughness parameter ξβσ", Quantity::Dimensionless, REAL, (0.0, true), (10.0, false), Presence::Default(0.055), "Greenwood–Tripp roughness parameter (asperity density × radius × σ)"),
        get: |t| t.surfaces.roughness_parameter,
        set: |t, v| t.surfaces.roughness_parameter = v,
    },
    FieldSpec {
        meta: meta("surfaces.asperity_slope", "surfaces", "Asperity slope σ/β", Quantity::Dimensionless, REAL, (0.0, true), (1.0, false), Presence::Default(1e-3), "roughness over asperity tip radius"),
        get: |t| t.surfaces.asperity_slope,
        set: |t, v| t.surfaces.asperity_slope = v,
    },
    CAGE[0],
    CAGE[1],
    CAGE[2],
    CAGE[3],
    CAGE[4],
];

/// Rules across keys: the roller must fit inside the pitch circle and the flat inside the
/// effective length.
fn cross(t: &TaperedInput, units: Units) -> Vec<(&'static str, String)> {
    let g = &t.geometry;
    let mut v = Vec::new();
    // The cage's losses are part of the friction stage, which runs with a lubricant only.
    if t.cage.is_given() && !t.lubricant.is_given() {
        v.push((
            "cage.drag_factor",
            "and the cage rails need a [lubricant] (lubricant.viscosity a number): the friction stage runs only with one".to_string(),
        ));
    }
    // A land-guided cage needs all its rail keys (one rule: `CageLosses::rail_key_problem`).
    v.extend(t.cage.rail_key_problem());
    // θy is given one way: held at a rotation, or free under a moment (issue 29). Both
    // keys written (even `misalignment_y = 0.0`) are refused by the schema's
    // `one_holding`, with both lines; this value rule covers values set without a deck
    // text (and is not repeated when that one fired).
    if t.operating.applied_moment_nm().is_some() && t.operating.misalignment_rad[1] != 0.0 {
        v.push((
            "operating.moment",
            format!(
                "and operating.misalignment_y ({}) both give the cone's tilt about y: give the moment (θy is then solved) or the rotation (its moment is then reported), not both",
                show(&SCHEMA, t, "operating.misalignment_y", units)
            ),
        ));
    }
    if g.roller_diameter_m >= g.pitch_diameter_m {
        v.push((
            "geometry.roller_diameter",
            format!(
                "must be smaller than the pitch diameter ({})",
                show(&SCHEMA, t, "geometry.pitch_diameter", units)
            ),
        ));
    }
    if g.flat_length_m > g.effective_length_m {
        v.push((
            "geometry.flat_length",
            format!(
                "must not exceed the effective length ({})",
                show(&SCHEMA, t, "geometry.effective_length", units)
            ),
        ));
    }
    if g.crown_gauge_m * 2.0 >= g.effective_length_m {
        v.push((
            "geometry.crown_gauge",
            format!(
                "must lie within half the effective length ({})",
                show(&SCHEMA, t, "geometry.effective_length", units)
            ),
        ));
    }
    v
}

/// The template's `[thermal]` section: a small working network, commented out (remove the
/// leading `# ` of its lines to use it; `decks/trb_afapl_lubricated.toml` has one). Every
/// heat source of the tapered bearing (`inner_contacts`, `outer_contacts`, `rollers`,
/// `flanges`) must go to a node. A test uncomments it and builds it.
pub const THERMAL_NOTE: &str =
    "[thermal]  # optional: a lumped thermal network (seed 000 §10), steady state and
# loss-of-oil transient, fed by the friction by mechanism (needs [lubricant]). A small
# working example follows; uncomment it to use it.
# [thermal]
# units = \"si\"    # °C, J/K, W/K, m, m², kg/s, whatever the deck's units
#
# [[thermal.nodes]]
# name = \"cone\"
# capacity = 400.0            # J/K
# limit = 200.0               # °C: the transient reports when it is reached
# heat = [\"inner_contacts\", \"flanges\"]
#
# [[thermal.nodes]]
# name = \"cup\"
# capacity = 600.0
# heat = [\"outer_contacts\"]
#
# [[thermal.nodes]]
# name = \"rollers\"
# capacity = 150.0
# heat = [\"rollers\"]
#
# [[thermal.nodes]]
# name = \"oil_in\"
# role = \"oil\"
# fixed_temperature = 93.0    # °C
#
# [[thermal.nodes]]
# name = \"oil_cavity\"
# role = \"oil\"
# capacity = 100.0
# air_capacity = 5.0          # J/K once the oil is lost
#
# [[thermal.links]]
# from = \"oil_in\"
# to = \"oil_cavity\"
# kind = \"mass_transport\"
# mass_flow = 0.06            # kg/s
# specific_heat = 2000.0      # J/(kg·K)
#
# [[thermal.links]]
# from = \"oil_cavity\"
# to = \"cone\"
# kind = \"convection\"
# h = 3000.0                  # W/(m²·K)
# area = 0.01                 # m²
# h_loss_of_oil = 60.0
#
# [[thermal.links]]
# from = \"oil_cavity\"
# to = \"cup\"
# kind = \"convection\"
# h = 3000.0
# area = 0.012
# h_loss_of_oil = 60.0
#
# [[thermal.links]]
# from = \"oil_cavity\"
# to = \"rollers\"
# kind = \"convection\"
# h = 3000.0
# area = 0.006
# h_loss_of_oil = 60.0
#
# [thermal.transient]
# duration = 300.0            # s
# step = 0.5
# integrator = \"implicit\"
# scenario = \"loss_of_oil\"
# oil_node = \"oil_cavity\"";

/// The template's comment lines beyond the fields'.
pub const TEMPLATE_NOTES: crate::deck::form::TemplateNotes = crate::deck::form::TemplateNotes {
    name: "",
    group_notes: &[
        ("lubricant", "Optional table. viscosity = \"none\" (the default): no lubricant, so no film, friction or heat. The other values are a MIL-PRF-23699-type turbine oil's (decks/trb_afapl_lubricated.toml cites them)."),
        ("surfaces", "Optional table: roughness for the film parameter Λ and the mixed friction."),
    ],
    opaque_notes: &[("thermal", THERMAL_NOTE)],
};

/// The tapered roller deck's schema.
pub static SCHEMA: Schema<TaperedInput> = Schema {
    system: SYSTEM_ID,
    groups: &["geometry", "materials", "operating", "solver", "pedestal", "lubricant", "surfaces", "cage", "thermal"],
    required_groups: &["geometry", "materials", "operating"],
    fields: &FIELDS,
    material_bodies: &["roller", "cup", "cone"],
    material: Some(MaterialAccess {
        get: |t, i| match i {
            0 => t.materials.roller,
            1 => t.materials.cup,
            _ => t.materials.cone,
        },
        set: |t, i, m| match i {
            0 => t.materials.roller = m,
            1 => t.materials.cup = m,
            _ => t.materials.cone = m,
        },
    }),
    opaque_tables: &["thermal"],
    defaults: TaperedInput::afapl_sample,
    cross_checks: cross,
    one_holding: &[crate::deck::form::OneHolding {
        load: "operating.moment",
        displacement: "operating.misalignment_y",
        dof: "the cone's tilt about y",
    }],
    template_header: "rollbench tapered roller bearing deck (seed 004: AFAPL-TR-78-6 Part III, tapered roller bearing stiffness with centrifugal effects)",
    template_notes: TEMPLATE_NOTES,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deck::form::{template, Form};

    const DECK: &str = include_str!("../../../decks/trb_afapl.toml");

    /// The shipped deck is the seed's §3.1 sample: read back to the SI input exactly as
    /// built in code (1e-12: unit conversion round-off).
    #[test]
    fn shipped_deck_is_the_sample() {
        let f = Form::parse(DECK, "trb_afapl.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        let s = TaperedInput::afapl_sample();
        let (a, b) = (&f.value.geometry, &s.geometry);
        assert_eq!(a.roller_count, 37);
        for (x, y) in [
            (a.roller_diameter_m, b.roller_diameter_m),
            (a.pitch_diameter_m, b.pitch_diameter_m),
            (a.cup_angle_rad, b.cup_angle_rad),
            (a.effective_length_m, b.effective_length_m),
            (crown_radius(a), crown_radius(b)),
            (f.value.operating.axial_load_n, s.operating.axial_load_n),
            (
                f.value.operating.inner_speed_rad_s,
                s.operating.inner_speed_rad_s,
            ),
        ] {
            assert!((x / y - 1.0).abs() < 1e-12, "{x} {y}");
        }
        assert_eq!(f.units, Units::Us);
    }

    /// Both unit systems' templates parse back; unknown keys and out-of-range values are
    /// reported with file:line and the allowed range in the deck's units.
    #[test]
    fn templates_parse_and_bad_decks_are_located() {
        for u in [Units::Us, Units::Si] {
            let t = template(&SCHEMA, u);
            Form::parse(&t, "template.toml", &SCHEMA).unwrap_or_else(|e| panic!("{u:?}: {e}\n{t}"));
        }
        let bad = DECK.replace("roller_count = 37", "roller_count = 37\nroller_cnt = 3");
        let e = Form::parse(&bad, "bad.toml", &SCHEMA)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.contains("bad.toml:") && e.contains("roller_cnt"), "{e}");
        let bad = DECK.replace("roller_count = 37", "roller_count = 2");
        let e = Form::parse(&bad, "bad.toml", &SCHEMA)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(
            e.contains("bad.toml:") && e.contains("3 ≤ value ≤ 500"),
            "{e}"
        );
        let line = DECK
            .lines()
            .position(|l| l.starts_with("roller_count"))
            .map(|i| i + 1)
            .unwrap_or(0);
        assert!(e.contains(&format!("bad.toml:{line}:")), "{e}");
    }

    const LUBRICATED: &str = include_str!("../../../decks/trb_afapl_lubricated.toml");

    /// The template's commented `[thermal]` example works: uncommented, the deck reads,
    /// its network builds and (with a lubricant set) every tapered heat source is bound.
    #[test]
    fn template_thermal_example_is_a_working_network() {
        let t = template(&SCHEMA, Units::Si);
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
        let text = format!("{head}{example}").replace("viscosity = \"none\"", "viscosity = 0.0248");
        let f = Form::parse(&text, "t.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        assert!(f.value.lubricant.is_given());
        let model = f.thermal_model().unwrap_or_else(|e| panic!("{e}"));
        let model = model.expect("a network");
        let heat = crate::thermal::HeatInput::new()
            .with(crate::thermal::HeatSource::InnerContacts, 1.0)
            .with(crate::thermal::HeatSource::OuterContacts, 1.0)
            .with(crate::thermal::HeatSource::Flanges, 1.0);
        model
            .network
            .node_heat_w(&heat)
            .unwrap_or_else(|e| panic!("{e}"));
    }

    /// The lubricant is optional and its absence is kept through a unit conversion: the
    /// template and the published deck have none (viscosity "none"); the lubricated deck
    /// reads to the cited SI values (0.0248 Pa·s, 1.1e-8 1/Pa, 93.3 °C, 0.15 µm: 1e-3, the
    /// deck's four-digit conversions) and survives a US → SI → US round trip (1e-12).
    #[test]
    fn lubricant_is_optional_and_converts() {
        let dry = Form::parse(DECK, "trb_afapl.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        assert!(!dry.value.lubricant.is_given());
        let si = dry.converted(Units::Si);
        let back =
            Form::parse(&si.to_toml_string(), "si.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        assert!(!back.value.lubricant.is_given());
        let t = template(&SCHEMA, Units::Us);
        let f = Form::parse(&t, "template.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        assert!(!f.value.lubricant.is_given());
        let wet = Form::parse(LUBRICATED, "l.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        let l = &wet.value.lubricant;
        for (x, want) in [
            (l.viscosity_pa_s, 0.0248),
            (l.pressure_viscosity_pa_inv, 1.1e-8),
            (l.inlet_temperature_k - 273.15, 93.33),
            (wet.value.surfaces.composite_rms_m, 0.1524e-6),
        ] {
            assert!((x / want - 1.0).abs() < 1e-3, "{x} {want}");
        }
        let si = wet.converted(Units::Si);
        let us = Form::parse(&si.to_toml_string(), "si.toml", &SCHEMA)
            .unwrap_or_else(|e| panic!("{e}"))
            .converted(Units::Us);
        let again =
            Form::parse(&us.to_toml_string(), "us.toml", &SCHEMA).unwrap_or_else(|e| panic!("{e}"));
        let a = &again.value.lubricant;
        assert!((a.viscosity_pa_s / l.viscosity_pa_s - 1.0).abs() < 1e-12);
        assert!((a.inlet_temperature_k / l.inlet_temperature_k - 1.0).abs() < 1e-12);
    }
}
