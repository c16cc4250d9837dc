//! The cylindrical roller deck (`type = "cylindrical-roller"`): its keys as a
//! [`crate::deck::form::Schema`] over [`CylindricalInput`]. Key names are a contract
//! (issue 25 "Deck"). `[contact]` (the contact report's sliding speed and cage angles)
//! holds an array, so it is an opaque table read by [`contact_table`].

use super::input::{CylindricalInput, ProfileKind, Ribs, Squeeze};
use super::SYSTEM_ID;
use crate::deck::form::{
    material_fields, show, FieldKind, FieldMeta, FieldSpec, Form, MaterialAccess, Presence, Schema,
    TemplateNotes, BOOL,
};
use crate::deck::thermal::PathSeg;
use crate::deck::{DeckError, DeckErrors};
use crate::units::{Quantity, Units};

const PROFILES: &[&str] = &["dub-off", "logarithmic"];
const RIBS: &[&str] = &["none", "inner", "outer", "both"];
const SQUEEZE: &[&str] = &["normalised", "printed", "none"];

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
const fn flag(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}

const ROLLER: [FieldSpec<CylindricalInput>; 5] =
    material_fields!(CylindricalInput, "roller", "Roller", |t| t.materials.roller);
const INNER: [FieldSpec<CylindricalInput>; 5] =
    material_fields!(CylindricalInput, "inner", "Inner ring", |t| t
        .materials
        .inner);
const OUTER: [FieldSpec<CylindricalInput>; 5] =
    material_fields!(CylindricalInput, "outer", "Outer ring", |t| t
        .materials
        .outer);

static FIELDS: [FieldSpec<CylindricalInput>; 58] = [
    // [geometry] (seed 003 Table A1)
    FieldSpec {
        meta: meta("geometry.roller_count", "geometry", "Rollers m", Quantity::Count, INT, (3.0, false), (500.0, false), REQ, "number of rollers"),
        get: |t| t.geometry.roller_count as f64,
        set: |t, v| t.geometry.roller_count = v as usize,
    },
    FieldSpec {
        meta: meta("geometry.roller_diameter", "geometry", "Roller diameter d", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "roller diameter"),
        get: |t| t.geometry.roller_diameter_m,
        set: |t, v| t.geometry.roller_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.roller_length", "geometry", "Roller length l", Quantity::Length, REAL, (0.0, true), (1.0, false), REQ, "roller length end to end"),
        get: |t| t.geometry.roller_length_m,
        set: |t, v| t.geometry.roller_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.inner_raceway_diameter", "geometry", "Inner raceway diameter", Quantity::Length, REAL, (0.0, true), (10.0, false), REQ, "inner ring raceway diameter (nominal: the play goes in radial_interference)"),
        get: |t| t.geometry.inner_raceway_diameter_m,
        set: |t, v| t.geometry.inner_raceway_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.outer_raceway_diameter", "geometry", "Outer raceway diameter", Quantity::Length, REAL, (0.0, true), (10.0, false), REQ, "outer ring raceway diameter (nominal: inner raceway diameter + 2 roller diameters)"),
        get: |t| t.geometry.outer_raceway_diameter_m,
        set: |t, v| t.geometry.outer_raceway_diameter_m = v,
    },
    FieldSpec {
        meta: meta("geometry.dub_off_radius", "geometry", "Dub-off radius R_d", Quantity::Length, REAL, (0.0, true), (1000.0, false), def(0.05), "radius of the circular dub-off at each roller end (eq. 7)"),
        get: |t| t.geometry.dub_off_radius_m,
        set: |t, v| t.geometry.dub_off_radius_m = v,
    },
    FieldSpec {
        meta: meta("geometry.dub_off_length", "geometry", "Dub-off length l_d", Quantity::Length, REAL, (0.0, false), (1.0, false), def(0.0), "length of the dub-off at each roller end (eq. 7); 0: a straight roller"),
        get: |t| t.geometry.dub_off_length_m,
        set: |t, v| t.geometry.dub_off_length_m = v,
    },
    FieldSpec {
        meta: meta("geometry.radial_interference", "geometry", "Radial interference ρ", Quantity::Length, REAL, (-0.001, false), (0.001, false), def(0.0), "interference per contact (seed 003 eq. 3: 2δ = 2ρ + x·cos θ + y·sin θ, so a roller's two contacts take 2ρ); negative is a clearance, C = −ρ; a diametral clearance P_d is ρ = −P_d/4"),
        get: |t| t.geometry.radial_interference_m,
        set: |t, v| t.geometry.radial_interference_m = v,
    },
    FieldSpec {
        meta: meta("geometry.profile", "geometry", "Roller profile", Quantity::Dimensionless, FieldKind::Choice(PROFILES), (0.0, false), (1.0, false), def(0.0), "flat with a circular dub-off (eq. 7) or the ISO/TS 16281 logarithmic profile"),
        get: |t| match t.geometry.profile {
            ProfileKind::DubOff => 0.0,
            ProfileKind::Logarithmic => 1.0,
        },
        set: |t, v| {
            t.geometry.profile = if v as usize == 1 {
                ProfileKind::Logarithmic
            } else {
                ProfileKind::DubOff
            }
        },
    },
    FieldSpec {
        meta: meta("geometry.ribs", "geometry", "Ribs", Quantity::Dimensionless, FieldKind::Choice(RIBS), (0.0, false), (3.0, false), def(0.0), "ring ribs: \"both\" (NJ/NUP) carries operating.axial_load through the roller ends (inner rib → roller → outer rib), tilting the rollers; \"inner\" or \"outer\" alone (N, NU) locates the rollers but carries no axial load"),
        get: |t| match t.geometry.ribs {
            Ribs::None => 0.0,
            Ribs::Inner => 1.0,
            Ribs::Outer => 2.0,
            Ribs::Both => 3.0,
        },
        set: |t, v| {
            t.geometry.ribs = match v as usize {
                1 => Ribs::Inner,
                2 => Ribs::Outer,
                3 => Ribs::Both,
                _ => Ribs::None,
            }
        },
    },
    FieldSpec {
        meta: meta("geometry.rib_angle", "geometry", "Rib angle φ", Quantity::Angle, REAL, (0.0, true), (45.0 * DEG, false), def(super::input::DEFAULT_RIB_ANGLE_RAD), "lay-back of the rib faces from the radial plane (the roller end–rib contact normal's angle to the axis); with the contact height it sets the roller end's sphere radius (r − h)/sin φ"),
        get: |t| t.geometry.rib_angle_rad,
        set: |t, v| t.geometry.rib_angle_rad = v,
    },
    FieldSpec {
        meta: meta("geometry.rib_contact_height", "geometry", "Rib contact height h", Quantity::Length, FieldKind::RealOr("auto"), (0.0, true), (1.0, false), def(f64::NAN), "height of the roller end–rib contact above the raceway, below the roller axis; \"auto\": a quarter of the roller diameter"),
        get: |t| t.geometry.rib_contact_height_m.unwrap_or(f64::NAN),
        set: |t, v| t.geometry.rib_contact_height_m = (!v.is_nan()).then_some(v),
    },
    ROLLER[0], ROLLER[1], ROLLER[2], ROLLER[3], ROLLER[4],
    INNER[0], INNER[1], INNER[2], INNER[3], INNER[4],
    OUTER[0], OUTER[1], OUTER[2], OUTER[3], OUTER[4],
    // [operating]
    FieldSpec {
        meta: meta("operating.inner_speed", "operating", "Shaft speed ω_i", Quantity::Speed, REAL, (-200_000.0 * RPM, false), (200_000.0 * RPM, false), REQ, "inner ring (shaft) speed; the outer ring is fixed"),
        get: |t| t.operating.inner_speed_rad_s,
        set: |t, v| t.operating.inner_speed_rad_s = v,
    },
    FieldSpec {
        meta: meta("operating.cage_speed", "operating", "Cage speed ω_c", Quantity::Speed, FieldKind::RealOr("kinematic"), (-200_000.0 * RPM, false), (200_000.0 * RPM, false), def(f64::NAN), "cage speed, or \"kinematic\" for ω_i·r_i/(r_i + r_o) (stationary outer ring, pure rolling)"),
        get: |t| t.operating.cage_speed_rad_s.unwrap_or(f64::NAN),
        set: |t, v| t.operating.cage_speed_rad_s = (!v.is_nan()).then_some(v),
    },
    FieldSpec {
        meta: meta("operating.radial_load", "operating", "Radial load F", Quantity::Force, REAL, (0.0, false), (1e8, false), REQ, "applied radial load on the inner ring"),
        get: |t| t.operating.radial_load_n,
        set: |t, v| t.operating.radial_load_n = v,
    },
    FieldSpec {
        meta: meta("operating.load_angle", "operating", "Load angle φ_F", Quantity::Angle, REAL, (-360.0 * DEG, false), (360.0 * DEG, false), def(std::f64::consts::PI), "direction of the radial load from +x; 180 deg adds it to gravity (−x), the seed's 1 990.5 N"),
        get: |t| t.operating.load_angle_rad,
        set: |t, v| t.operating.load_angle_rad = v,
    },
    FieldSpec {
        meta: meta("operating.gravity", "operating", "Gravity", Quantity::Dimensionless, FieldKind::Choice(BOOL), (0.0, false), (1.0, false), def(1.0), "add the rotor's weight system_mass·9.81 m/s² along −x (9.81: the seed's 1 990.5 N)"),
        get: |t| flag(t.operating.gravity),
        set: |t, v| t.operating.gravity = v >= 0.5,
    },
    FieldSpec {
        meta: meta("operating.axial_load", "operating", "Axial load", Quantity::Force, REAL, (-1e8, false), (1e8, false), def(0.0), "axial load; carried by ribs only, so 0 while geometry.ribs = \"none\""),
        get: |t| t.operating.axial_load_n,
        set: |t, v| t.operating.axial_load_n = v,
    },
    // [dynamics] (seed 003 eqs. 1–5)
    FieldSpec {
        meta: meta("dynamics.system_mass", "dynamics", "System mass M", Quantity::Mass, REAL, (0.0, true), (1e6, false), REQ, "mass supported by the bearing (shaft and rotor)"),
        get: |t| t.dynamics.system_mass_kg,
        set: |t, v| t.dynamics.system_mass_kg = v,
    },
    FieldSpec {
        meta: meta("dynamics.contact_stiffness", "dynamics", "Contact stiffness k_n", Quantity::Dimensionless, FieldKind::RealOr("lamina"), (0.0, true), (1e16, false), def(f64::NAN), "roller load-deflection constant in N/m^n (SI in both unit systems), or \"lamina\" to take it from the slice law (default: the seed's 5e8 gives µ ≈ 0.04, the slice law ≈ 2e9 and µ ≈ 0.013)"),
        get: |t| t.dynamics.contact_stiffness.unwrap_or(f64::NAN),
        set: |t, v| t.dynamics.contact_stiffness = (!v.is_nan()).then_some(v),
    },
    FieldSpec {
        meta: meta("dynamics.load_exponent", "dynamics", "Load exponent n", Quantity::Dimensionless, REAL, (1.0, false), (2.0, false), def(10.0 / 9.0), "exponent of W = k_n·δ^n (10/9 for line contact)"),
        get: |t| t.dynamics.load_exponent,
        set: |t, v| t.dynamics.load_exponent = v,
    },
    FieldSpec {
        meta: meta("dynamics.film_in_deflection", "dynamics", "Film in deflection", Quantity::Dimensionless, FieldKind::Choice(BOOL), (0.0, false), (1.0, false), def(1.0), "include the film h_i in the contact deflection (eq. 3)"),
        get: |t| flag(t.dynamics.film_in_deflection),
        set: |t, v| t.dynamics.film_in_deflection = v >= 0.5,
    },
    FieldSpec {
        meta: meta("dynamics.squeeze", "dynamics", "Squeeze term", Quantity::Dimensionless, FieldKind::Choice(SQUEEZE), (0.0, false), (2.0, false), def(0.0), "squeeze term of the film law (eq. 4): normalised (the steady film at zero squeeze, default), printed (eq. 4 as printed) or none"),
        get: |t| match t.dynamics.squeeze {
            Squeeze::Normalised => 0.0,
            Squeeze::Printed => 1.0,
            Squeeze::None => 2.0,
        },
        set: |t, v| {
            t.dynamics.squeeze = match v as usize {
                1 => Squeeze::Printed,
                2 => Squeeze::None,
                _ => Squeeze::Normalised,
            }
        },
    },
    FieldSpec {
        meta: meta("dynamics.damping_ratio", "dynamics", "Damping ratio ζ", Quantity::Dimensionless, REAL, (0.0, false), (1.0, true), def(0.0), "viscous damping ratio of the shaft (0: the seed has none)"),
        get: |t| t.dynamics.damping_ratio,
        set: |t, v| t.dynamics.damping_ratio = v,
    },
    FieldSpec {
        meta: meta("dynamics.revolutions", "dynamics", "Shaft revolutions", Quantity::Count, INT, (0.0, false), (100_000.0, false), def(100.0), "shaft revolutions simulated (0: the quasi-statics only, no dynamics)"),
        get: |t| t.dynamics.revolutions as f64,
        set: |t, v| t.dynamics.revolutions = v as usize,
    },
    FieldSpec {
        meta: meta("dynamics.settle_revolutions", "dynamics", "Settle revolutions", Quantity::Count, INT, (0.0, false), (100_000.0, false), def(20.0), "shaft revolutions dropped before the spectra (a count, not a convergence test)"),
        get: |t| t.dynamics.settle_revolutions as f64,
        set: |t, v| t.dynamics.settle_revolutions = v as usize,
    },
    FieldSpec {
        meta: meta("dynamics.tolerance", "dynamics", "Integrator tolerance", Quantity::Dimensionless, REAL, (0.0, true), (1e-3, false), def(1e-8), "relative tolerance of the adaptive integrator"),
        get: |t| t.dynamics.tolerance,
        set: |t, v| t.dynamics.tolerance = v,
    },
    // [lubricant] (seed 003 Table A2; its conductivity and heat capacity units are swapped
    // in print: 0.14 W/(m·K), 2 000 J/(kg·K))
    FieldSpec {
        meta: meta("lubricant.viscosity", "lubricant", "Viscosity η₀", Quantity::Viscosity, REAL, (0.0, true), (1e3, false), REQ, "dynamic viscosity at the inlet temperature and ambient pressure"),
        get: |t| t.lubricant.viscosity_pa_s,
        set: |t, v| t.lubricant.viscosity_pa_s = v,
    },
    FieldSpec {
        meta: meta("lubricant.pressure_viscosity", "lubricant", "Pressure-viscosity α", Quantity::PressureViscosity, REAL, (0.0, false), (1e-6, false), REQ, "pressure-viscosity coefficient"),
        get: |t| t.lubricant.pressure_viscosity_pa_inv,
        set: |t, v| t.lubricant.pressure_viscosity_pa_inv = v,
    },
    FieldSpec {
        meta: meta("lubricant.temperature_viscosity", "lubricant", "Temperature-viscosity β", Quantity::PerDegreeCelsius, REAL, (0.0, false), (1.0, false), def(0.026), "temperature-viscosity coefficient (1/K = 1/°C)"),
        get: |t| t.lubricant.temperature_viscosity_k_inv,
        set: |t, v| t.lubricant.temperature_viscosity_k_inv = v,
    },
    FieldSpec {
        meta: meta("lubricant.density", "lubricant", "Density ρ₀", Quantity::Density, REAL, (0.0, true), (1e5, false), def(829.3), "lubricant density at the inlet"),
        get: |t| t.lubricant.density_kg_m3,
        set: |t, v| t.lubricant.density_kg_m3 = v,
    },
    FieldSpec {
        meta: meta("lubricant.conductivity", "lubricant", "Conductivity k", Quantity::Conductivity, REAL, (0.0, true), (1e3, false), def(0.14), "lubricant thermal conductivity"),
        get: |t| t.lubricant.conductivity_w_m_k,
        set: |t, v| t.lubricant.conductivity_w_m_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.specific_heat", "lubricant", "Specific heat c", Quantity::SpecificHeat, REAL, (0.0, true), (1e5, false), def(2000.0), "lubricant specific heat"),
        get: |t| t.lubricant.specific_heat_j_kg_k,
        set: |t, v| t.lubricant.specific_heat_j_kg_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.limiting_shear", "lubricant", "Limiting shear τ₀", Quantity::Pressure, REAL, (0.0, false), (1e9, false), def(2.3e6), "atmospheric limiting shear stress (Table 2)"),
        get: |t| t.lubricant.limiting_shear_pa,
        set: |t, v| t.lubricant.limiting_shear_pa = v,
    },
    FieldSpec {
        meta: meta("lubricant.limiting_shear_slope", "lubricant", "Limiting shear slope γ", Quantity::Dimensionless, REAL, (0.0, false), (1.0, false), def(0.047), "pressure coefficient of the limiting shear τ_L = τ₀ + γp (Table 2)"),
        get: |t| t.lubricant.limiting_shear_slope,
        set: |t, v| t.lubricant.limiting_shear_slope = v,
    },
    FieldSpec {
        meta: meta("lubricant.inlet_temperature", "lubricant", "Inlet temperature", Quantity::Temperature, REAL, (223.15, false), (573.15, false), def(super::input::DEFAULT_INLET_TEMPERATURE_K), "lubricant inlet temperature (the seed gives none: 40 °C by default)"),
        get: |t| t.lubricant.inlet_temperature_k,
        set: |t, v| t.lubricant.inlet_temperature_k = v,
    },
    FieldSpec {
        meta: meta("lubricant.reference_temperature", "lubricant", "Reference temperature T₀", Quantity::Temperature, REAL, (223.15, false), (573.15, false), def(super::input::DEFAULT_REFERENCE_TEMPERATURE_K), "temperature at which lubricant.viscosity is given (T₀ of eq. 10; the seed gives none: 40 °C, the ISO grades' reference)"),
        get: |t| t.lubricant.reference_temperature_k,
        set: |t, v| t.lubricant.reference_temperature_k = v,
    },
    // [surfaces] (seed 003 Table 2)
    FieldSpec {
        meta: meta("surfaces.composite_rms", "surfaces", "Composite roughness σ", Quantity::Roughness, REAL, (0.0, true), (1e-4, false), def(0.6e-6), "composite rms roughness of roller and race"),
        get: |t| t.surfaces.composite_rms_m,
        set: |t, v| t.surfaces.composite_rms_m = v,
    },
    FieldSpec {
        meta: meta("surfaces.roughness_parameter", "surfaces", "Roughness parameter ξβσ", Quantity::Dimensionless, REAL, (0.0, true), (10.0, false), def(0.055), "Greenwood–Tripp roughness parameter (asperity density × radius × σ)"),
        get: |t| t.surfaces.roughness_parameter,
        set: |t, v| t.surfaces.roughness_parameter = v,
    },
    FieldSpec {
        meta: meta("surfaces.asperity_slope", "surfaces", "Asperity slope σ/β", Quantity::Dimensionless, REAL, (0.0, true), (1.0, false), def(1e-3), "roughness over asperity tip radius (the seed's exponent is unclear: 1e-3 by default)"),
        get: |t| t.surfaces.asperity_slope,
        set: |t, v| t.surfaces.asperity_slope = v,
    },
    // [solver]
    FieldSpec {
        meta: meta("solver.slices", "solver", "Slices", Quantity::Count, INT, (1.0, false), (1001.0, false), def(21.0), "slices (laminae) per roller along its length"),
        get: |t| t.solver.slices as f64,
        set: |t, v| t.solver.slices = v as usize,
    },
    FieldSpec {
        meta: meta("solver.force_tolerance", "solver", "Force tolerance", Quantity::Dimensionless, REAL, (0.0, true), (1e-4, false), def(1e-9), "ring equilibrium force residual relative to the load"),
        get: |t| t.solver.force_tolerance,
        set: |t, v| t.solver.force_tolerance = v,
    },
    FieldSpec {
        meta: meta("solver.stiffness", "solver", "Stiffness method", Quantity::Dimensionless, FieldKind::Choice(crate::bearings::stiffness::METHODS), (0.0, false), (2.0, false), def(0.0), "the ring stiffness: \"analytic\" (the ring Newton's Jacobian), \"finite-difference\" (central differences of the re-solved rollers; x, y only) or \"both\" (analytic, checked: finite_difference_max_rel)"),
        get: |t| t.solver.stiffness.index(),
        set: |t, v| t.solver.stiffness = crate::bearings::stiffness::Method::from_index(v),
    },
];

/// Rules across keys: nominal raceways (the play is `radial_interference`), a dub-off
/// inside half the roller, axial load only with ribs on both rings and the rib contact
/// below the roller axis, the settling inside the run.
fn cross(t: &CylindricalInput, units: Units) -> Vec<(&'static str, String)> {
    let g = &t.geometry;
    let mut v = Vec::new();
    // (D_o − D_i)/2 is the room for one roller: the lamina solve takes the raceways for
    // curvature and pitch and the play from ρ alone, so they must agree within 1 % of d.
    let room = 0.5 * (g.outer_raceway_diameter_m - g.inner_raceway_diameter_m);
    if (room - g.roller_diameter_m).abs() > 0.01 * g.roller_diameter_m {
        v.push((
            "geometry.outer_raceway_diameter",
            format!(
                "must be the inner raceway diameter plus two roller diameters within 1 % of the roller diameter ({}, {}); give the play in geometry.radial_interference",
                show(&SCHEMA, t, "geometry.inner_raceway_diameter", units),
                show(&SCHEMA, t, "geometry.roller_diameter", units)
            ),
        ));
    }
    if g.profile == ProfileKind::DubOff && 2.0 * g.dub_off_length_m >= g.roller_length_m {
        v.push((
            "geometry.dub_off_length",
            format!(
                "must be less than half the roller length ({})",
                show(&SCHEMA, t, "geometry.roller_length", units)
            ),
        ));
    }
    if t.operating.axial_load_n != 0.0 && g.ribs != Ribs::Both {
        let ribs = match g.ribs {
            Ribs::None => "none",
            Ribs::Inner => "inner",
            Ribs::Outer => "outer",
            Ribs::Both => "both",
        };
        v.push((
            "operating.axial_load",
            format!(
                "must be 0 unless geometry.ribs = \"both\": with geometry.ribs = \"{ribs}\" no rib pair passes axial load from the inner ring through the rollers to the outer ring"
            ),
        ));
    }
    let h = g.rib_contact_height();
    if g.ribs != Ribs::None && !(h < 0.5 * g.roller_diameter_m) {
        v.push((
            "geometry.rib_contact_height",
            format!(
                "must be less than the roller radius (half of {}): the contact lies between the raceway and the roller axis",
                show(&SCHEMA, t, "geometry.roller_diameter", units)
            ),
        ));
    }
    if t.dynamics.revolutions > 0 && t.dynamics.settle_revolutions >= t.dynamics.revolutions {
        v.push((
            "dynamics.settle_revolutions",
            format!(
                "must be less than the revolutions simulated ({})",
                show(&SCHEMA, t, "dynamics.revolutions", units)
            ),
        ));
    }
    v
}

/// The cylindrical roller deck's schema.
pub static SCHEMA: Schema<CylindricalInput> = Schema {
    system: SYSTEM_ID,
    groups: &[
        "geometry",
        "materials",
        "operating",
        "dynamics",
        "lubricant",
        "surfaces",
        "contact",
        "solver",
    ],
    required_groups: &["geometry", "materials", "operating", "dynamics", "lubricant"],
    fields: &FIELDS,
    material_bodies: &["roller", "inner", "outer"],
    material: Some(MaterialAccess {
        get: |t, i| match i {
            0 => t.materials.roller,
            1 => t.materials.inner,
            _ => t.materials.outer,
        },
        set: |t, i, m| match i {
            0 => t.materials.roller = m,
            1 => t.materials.inner = m,
            _ => t.materials.outer = m,
        },
    }),
    opaque_tables: &["contact", "thermal"],
    defaults: CylindricalInput::truck,
    cross_checks: cross,
    one_holding: &[],
    template_header: "rollbench cylindrical roller bearing deck (seed 003: tribodynamics of cylindrical roller bearings in a heavy-duty truck transmission)\nQuasi-static lamina load distribution, 2-DOF dynamics with the film in the deflection,\nspectra and mixed-regime friction per roller.",
    template_notes: TemplateNotes {
        name: "",
        group_notes: &[],
        opaque_notes: &[
            (
                "contact",
                "[contact] (optional): sliding_speed = 0.589 (m/s in both unit systems; default: Table 3's 23.95 W / 40.67 N), positions = [0, 30, 60] (cage angles in deg for the contact report), inlet = \"flooded\" (the Contact pane's inlets: flooded, tipei or both)",
            ),
            (
                "thermal",
                crate::bearings::thermal_answer::thermal_template_note!(
                    "\"inner_contacts\", \"outer_contacts\", \"rollers\""
                ),
            ),
        ],
    },
};

/// The keys of `[contact]`.
pub const CONTACT_KEYS: &[&str] = &["sliding_speed", "positions", "inlet"];

/// Reads the deck's `[contact]` table into `form.value.contact`: `sliding_speed` (ΔU,
/// m/s in both unit systems, 0 ≤ ΔU ≤ 1 000; default Table 3's power over force, 23.95 W /
/// 40.67 N = 0.589 m/s) and `positions` (cage angles in deg, 1–360 finite numbers,
/// default [0, 30, 60]) and `inlet` (the Contact pane's: "flooded", "tipei" or "both",
/// default flooded). Errors name the key with file:line.
pub fn contact_table(form: &mut Form<CylindricalInput>) -> Result<(), DeckErrors> {
    let defaults = CylindricalInput::truck().contact;
    let Some(table) = form.opaque.get("contact").cloned() else {
        form.value.contact = defaults;
        return Ok(());
    };
    let loc = |form: &Form<CylindricalInput>, key: &str| {
        form.location_in("contact", &[PathSeg::Key(key.into())])
    };
    if let Some(other) = table.keys().find(|k| !CONTACT_KEYS.contains(&k.as_str())) {
        return Err(DeckError::UnknownKey {
            location: loc(form, other),
            key: format!("contact.{other}"),
            hint: " (allowed: sliding_speed, positions, inlet)".into(),
        }
        .into());
    }
    let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|n| n as f64));
    let mut contact = defaults;
    if let Some(raw) = table.get("sliding_speed") {
        let Some(u) = num(raw) else {
            return Err(DeckError::WrongType {
                location: loc(form, "sliding_speed"),
                key: "contact.sliding_speed".into(),
                value: raw.to_string(),
                expected: "a number (m/s)".into(),
            }
            .into());
        };
        if !(u.is_finite() && (0.0..=1000.0).contains(&u)) {
            return Err(DeckError::OutOfRange {
                location: loc(form, "sliding_speed"),
                key: "contact.sliding_speed".into(),
                value: raw.to_string(),
                allowed: "0 ≤ value ≤ 1000 m/s".into(),
            }
            .into());
        }
        contact.sliding_speed_m_s = u;
    }
    if let Some(raw) = table.get("positions") {
        let list: Option<Vec<f64>> = raw.as_array().and_then(|a| a.iter().map(num).collect());
        let Some(list) = list else {
            return Err(DeckError::WrongType {
                location: loc(form, "positions"),
                key: "contact.positions".into(),
                value: raw.to_string(),
                expected: "an array of cage angles in deg".into(),
            }
            .into());
        };
        if list.is_empty()
            || list.len() > 360
            || list.iter().any(|a| !(a.is_finite() && a.abs() <= 360.0))
        {
            return Err(DeckError::Invalid {
                location: loc(form, "positions"),
                key: "contact.positions".into(),
                value: raw.to_string(),
                rule: "1 to 360 cage angles, each −360 ≤ angle ≤ 360 deg".into(),
            }
            .into());
        }
        contact.positions_rad = list.iter().map(|a| a.to_radians()).collect();
    }
    if let Some(raw) = table.get("inlet") {
        use super::contact::InletChoice;
        contact.inlet = match raw.as_str() {
            Some("flooded") => InletChoice::Flooded,
            Some("tipei") => InletChoice::Tipei,
            Some("both") => InletChoice::Both,
            _ => {
                return Err(DeckError::WrongType {
                    location: loc(form, "inlet"),
                    key: "contact.inlet".into(),
                    value: raw.to_string(),
                    expected: "\"flooded\", \"tipei\" or \"both\" (the Contact pane's inlets)"
                        .into(),
                }
                .into())
            }
        };
    }
    form.value.contact = contact;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deck::form::{schema_problems, template};

    const DECK: &str = include_str!("../../../decks/crb_truck.toml");

    fn parse(text: &str) -> Result<Form<CylindricalInput>, String> {
        let mut f = Form::parse(text, "d.toml", &SCHEMA).map_err(|e| e.to_string())?;
        contact_table(&mut f).map_err(|e| e.to_string())?;
        Ok(f)
    }

    #[test]
    fn schema_is_sound() {
        assert_eq!(schema_problems(&SCHEMA), Vec::<String>::new());
    }

    /// The shipped deck is the seed's truck bearing as built in code (1e-12: unit
    /// conversion round-off; the speeds are given in rpm, 1995.8 rpm = 209.0 rad/s to
    /// 1e-5, and 795.07 rpm = 83.26 rad/s to 1e-5).
    #[test]
    fn shipped_deck_is_the_truck() {
        let f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
        let (a, b) = (&f.value, &CylindricalInput::truck());
        assert_eq!(a.geometry, b.geometry);
        assert_eq!(a.materials, b.materials);
        assert_eq!(a.lubricant, b.lubricant);
        assert_eq!(a.surfaces, b.surfaces);
        assert_eq!(a.dynamics, b.dynamics);
        assert!((a.operating.inner_speed_rad_s / 209.0 - 1.0).abs() < 1e-5);
        let cage = a.operating.cage_speed_rad_s.unwrap_or(0.0);
        assert!((cage / 83.26 - 1.0).abs() < 1e-5, "{cage}");
        assert_eq!(a.load_vector_n(), b.load_vector_n());
        assert_eq!(a.contact.positions_rad.len(), 3);
        assert!((a.contact.sliding_speed_m_s - 0.589).abs() < 1e-3);
    }

    /// "lamina" and "kinematic" read as the computed-instead words, a number as a
    /// number; another word is refused naming both choices.
    #[test]
    fn words_and_numbers() {
        let t = DECK.replace("cage_speed = 795.07", "cage_speed = \"kinematic\"");
        let f = parse(&t).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(f.value.operating.cage_speed_rad_s, None);
        let t = DECK.replace("contact_stiffness = \"lamina\"", "contact_stiffness = 5e8");
        let f = parse(&t).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(f.value.dynamics.contact_stiffness, Some(5e8));
        assert_eq!(f.get("dynamics.contact_stiffness").as_deref(), Some("5e8"));
        let t = DECK.replace(
            "contact_stiffness = \"lamina\"",
            "contact_stiffness = \"slices\"",
        );
        let e = parse(&t).err().unwrap_or_default();
        assert!(
            e.contains("contact_stiffness") && e.contains("\"lamina\""),
            "{e}"
        );
        let t = DECK.replace("gravity = true", "gravity = false");
        assert!(
            !parse(&t)
                .unwrap_or_else(|e| panic!("{e}"))
                .value
                .operating
                .gravity
        );
    }

    /// Both unit systems' templates parse back to the defaults' choices; the ranges and
    /// cross checks name the key and the rule.
    #[test]
    fn templates_and_bad_values() {
        for u in [Units::Us, Units::Si] {
            let t = template(&SCHEMA, u);
            let f = parse(&t).unwrap_or_else(|e| panic!("{u:?}: {e}\n{t}"));
            assert_eq!(f.value.dynamics.contact_stiffness, None);
            assert!(f.value.operating.gravity);
        }
        for (from, to, want) in [
            (
                "axial_load = 0",
                "axial_load = 100",
                "geometry.ribs = \"both\"",
            ),
            (
                "dub_off_length = 0.003",
                "dub_off_length = 0.011",
                "half the roller length",
            ),
            (
                "outer_raceway_diameter = 0.0754",
                "outer_raceway_diameter = 0.08",
                "two roller diameters",
            ),
            ("roller_count = 12", "roller_count = 2", "3 ≤ value ≤ 500"),
            (
                "settle_revolutions = 20",
                "settle_revolutions = 100",
                "less than the revolutions",
            ),
        ] {
            assert!(DECK.contains(from), "{from}");
            let e = parse(&DECK.replace(from, to)).err().unwrap_or_default();
            let key = from.split(' ').next().unwrap_or("");
            assert!(e.contains(key) && e.contains(want), "{to}: {e}");
        }
        let e = parse(&format!("{DECK}\n"))
            .ok()
            .map(|_| String::new())
            .unwrap_or_default();
        assert!(e.is_empty());
        let bad = DECK.replace("positions = [0, 30, 60]", "positions = [0, \"x\"]");
        let e = parse(&bad).err().unwrap_or_default();
        assert!(
            e.contains("contact.positions") && e.contains("d.toml:"),
            "{e}"
        );
    }
}
