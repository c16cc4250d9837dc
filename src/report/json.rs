//! JSON report (SI; every key names its unit).

use serde_json::{json, Map, Value};

use crate::solve::pipeline::Analysis;

/// The full JSON document of an analysis.
pub fn to_value(a: &Analysis) -> Value {
    let ld = &a.load;
    let rollers: Vec<Value> = ld
        .rollers
        .iter()
        .map(|r| {
            let contact = |c: &crate::solve::load_distribution::RacewayContact| {
                json!({
                    "normal_load_n": c.normal_load_n,
                    "contact_angle_deg": c.contact_angle_deg,
                    "loaded_laminae": c.loaded_laminae,
                })
            };
            let laminae: Vec<Value> = r
                .laminae
                .iter()
                .map(|l| {
                    json!({
                        "offset_m": l.offset_m,
                        "width_m": l.width_m,
                        "inner_load_n": l.inner_load_n,
                        "outer_load_n": l.outer_load_n,
                        "inner_approach_m": l.inner_approach_m,
                        "outer_approach_m": l.outer_approach_m,
                        "inner_angle_deg": l.inner_angle_deg,
                        "outer_angle_deg": l.outer_angle_deg,
                        "inner_point_m": l.inner_point_m,
                        "outer_point_m": l.outer_point_m,
                    })
                })
                .collect();
            json!({
                "index": r.index,
                "azimuth_deg": r.azimuth_deg,
                "axial_displacement_m": r.axial_displacement_m,
                "radial_displacement_m": r.radial_displacement_m,
                "tilt_rad": r.tilt_rad,
                "centrifugal_force_n": r.centrifugal_force_n,
                "gyroscopic_moment_nm": r.gyroscopic_moment_nm,
                "cage_force_n": r.cage_force_n,
                "cage_moment_nm": r.cage_moment_nm,
                "inner": contact(&r.inner),
                "outer": contact(&r.outer),
                "laminae": laminae,
            })
        })
        .collect();
    let mut doc = Map::new();
    doc.insert("input".into(), serde_json::to_value(&a.input).unwrap_or(Value::Null));
    doc.insert("converged".into(), Value::Bool(ld.converged));
    doc.insert(
        "loads".into(),
        json!({"radial_n": a.input.operating.radial_load_n, "axial_n": a.input.operating.axial_load_n}),
    );
    doc.insert(
        "rings".into(),
        json!({"axial_deflection_m": ld.axial_deflection_m, "radial_deflection_m": ld.radial_deflection_m}),
    );
    doc.insert(
        "roller_properties".into(),
        json!({
            "mass_kg": ld.roller_mass.mass_kg,
            "volume_m3": ld.roller_mass.volume_m3,
            "polar_inertia_kg_m2": ld.roller_mass.polar_inertia_kg_m2,
            "transverse_inertia_kg_m2": ld.roller_mass.transverse_inertia_kg_m2,
        }),
    );
    doc.insert(
        "dynamic_speeds".into(),
        json!({"cage_rad_s": ld.speeds.cage_rad_s, "roller_spin_rad_s": ld.speeds.roller_spin_rad_s}),
    );
    doc.insert("rollers".into(), Value::Array(rollers));
    doc.insert(
        "residuals".into(),
        json!({
            "bearing_radial_n": ld.residuals.bearing_radial_n,
            "bearing_axial_n": ld.residuals.bearing_axial_n,
            "roller_force_n": ld.residuals.roller_force_n,
            "roller_moment_nm": ld.residuals.roller_moment_nm,
        }),
    );
    doc.insert(
        "stats".into(),
        json!({
            "iterations": ld.stats.iterations,
            "roller_iterations": ld.stats.roller_iterations,
            "lamina_evaluations": ld.stats.lamina_evaluations,
            "wall_time_s": ld.stats.wall_time_s,
        }),
    );
    Value::Object(doc)
}

/// Pretty JSON text.
pub fn to_string(a: &Analysis) -> String {
    serde_json::to_string_pretty(&to_value(a)).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}
