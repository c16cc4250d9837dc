//! JSON report (SI; every key names its unit).

use serde_json::{json, Map, Value};

use crate::bearings::friction::{FrictionBreakdown, Mechanism};
use crate::bearings::spherical_roller::pipeline::Analysis;
use crate::bearings::spherical_roller::view::{self, ContactView, LaminaView};
use crate::thermal::HeatSource;

/// One raceway contact of a roller (§3 load, §4 stresses, §5 film, §6 P_e, §9 heat).
fn contact(c: &ContactView) -> Value {
    let mut v = json!({
        "normal_load_n": c.load.normal_load_n,
        "contact_angle_deg": c.load.contact_angle_deg,
        "loaded_laminae": c.load.loaded_laminae,
    });
    let Some(m) = v.as_object_mut() else {
        return v;
    };
    if let Some(rs) = c.stress {
        m.insert("max_stress_pa".into(), json!(rs.max_stress_pa));
        m.insert("mean_stress_pa".into(), json!(rs.mean_stress_pa));
        m.insert(
            "contact_major_axis_m".into(),
            json!(rs.contact_major_axis_m),
        );
        m.insert(
            "contact_minor_axis_m".into(),
            json!(rs.contact_minor_axis_m),
        );
        m.insert("eccentricity_m".into(), json!(rs.eccentricity_m));
        m.insert("subsurface_shear_pa".into(), json!(rs.subsurface_shear_pa));
        m.insert("subsurface_depth_m".into(), json!(rs.subsurface_depth_m));
        m.insert("orthogonal_shear_pa".into(), json!(rs.orthogonal_shear_pa));
        m.insert(
            "orthogonal_shear_depth_m".into(),
            json!(rs.orthogonal_depth_m),
        );
        m.insert("von_mises_pa".into(), json!(rs.von_mises_pa));
        m.insert("von_mises_depth_m".into(), json!(rs.von_mises_depth_m));
    }
    if let Some(h) = c.min_film_m {
        m.insert("min_film_m".into(), json!(h));
    }
    if let Some(p) = c.equivalent_load_n {
        m.insert("equivalent_load_n".into(), json!(p));
    }
    if let Some(h) = c.heat_w {
        m.insert("heat_w".into(), json!(h));
    }
    v
}

/// One lamina of a roller.
fn lamina(lv: &LaminaView) -> Value {
    let l = lv.load;
    let mut v = json!({
        "offset_m": l.offset_m,
        "width_m": l.width_m,
        "inner_load_n": l.inner_load_n,
        "outer_load_n": l.outer_load_n,
        "inner_approach_m": l.inner_approach_m,
        "outer_approach_m": l.outer_approach_m,
        "inner_angle_deg": l.inner_angle_deg(),
        "outer_angle_deg": l.outer_angle_deg(),
        "inner_point_m": l.inner_point_m,
        "outer_point_m": l.outer_point_m,
    });
    let Some(m) = v.as_object_mut() else {
        return v;
    };
    if let Some(h) = lv.hertz {
        m.insert("inner_half_width_m".into(), json!(h[0].half_width_m));
        m.insert("outer_half_width_m".into(), json!(h[1].half_width_m));
        m.insert("inner_stress_pa".into(), json!(h[0].max_pressure_pa));
        m.insert("outer_stress_pa".into(), json!(h[1].max_pressure_pa));
        m.insert("inner_mean_stress_pa".into(), json!(h[0].mean_pressure_pa));
        m.insert("outer_mean_stress_pa".into(), json!(h[1].mean_pressure_pa));
    }
    if let Some(f) = lv.film_m {
        m.insert("inner_film_m".into(), json!(f[0]));
        m.insert("outer_film_m".into(), json!(f[1]));
    }
    if let Some(f) = lv.friction {
        m.insert("inner_sliding_m_s".into(), json!(f[0].sliding_m_s));
        m.insert("outer_sliding_m_s".into(), json!(f[1].sliding_m_s));
        m.insert("inner_traction_n".into(), json!(f[0].traction_n));
        m.insert("outer_traction_n".into(), json!(f[1].traction_n));
        m.insert("inner_heat_w".into(), json!(f[0].heat_w));
        m.insert("outer_heat_w".into(), json!(f[1].heat_w));
    }
    v
}

/// The full JSON document of an analysis.
pub fn to_value(a: &Analysis) -> Value {
    let ld = &a.load;
    let rollers: Vec<Value> = view::rollers(a)
        .iter()
        .map(|rv| {
            let r = rv.roller;
            json!({
                "index": r.index,
                // Rollers count from 1 here already (issue 30 item 9).
                "number": r.index,
                "azimuth_deg": r.azimuth_deg,
                "axial_displacement_m": r.axial_displacement_m,
                "radial_displacement_m": r.radial_displacement_m,
                "tilt_rad": r.tilt_rad,
                "centrifugal_force_n": r.centrifugal_force_n,
                "gyroscopic_moment_nm": r.gyroscopic_moment_nm,
                "cage_force_n": r.cage_force_n,
                "cage_moment_nm": r.cage_moment_nm,
                "spin_rpm": rv.spin_rpm.unwrap_or(0.0),
                "inner": contact(&rv.contacts[0]),
                "outer": contact(&rv.contacts[1]),
                "laminae": rv.laminae.iter().map(lamina).collect::<Vec<_>>(),
            })
        })
        .collect();
    let mut doc = Map::new();
    doc.insert(
        "input".into(),
        serde_json::to_value(&a.input).unwrap_or(Value::Null),
    );
    doc.insert("converged".into(), Value::Bool(ld.converged));
    // Results beyond the validity of the model (issue 15): sentences with their numbers.
    doc.insert(
        "warnings".into(),
        Value::Array(
            super::super::warnings::warnings(a)
                .into_iter()
                .map(|w| Value::String(w.si))
                .collect(),
        ),
    );
    doc.insert(
        "loads".into(),
        json!({"radial_n": a.input.operating.radial_load_n, "axial_n": a.input.operating.axial_load_n}),
    );
    // Issue 29: the 5×5 stiffness on the shared type, or why there is none.
    doc.insert(
        "stiffness".into(),
        match &a.stiffness {
            Ok(k) => k.json(),
            Err(reason) => json!({ "reason": reason }),
        },
    );
    doc.insert(
        "rings".into(),
        // Issue 29: self-aligning (spherical outer raceway), so the ring's tilt is free
        // and it carries no moment: moment_nm is 0 by that geometry, tilt_free says so.
        json!({
            "axial_deflection_m": ld.axial_deflection_m,
            "radial_deflection_m": ld.radial_deflection_m,
            "moment_nm": 0.0,
            "tilt_free": true,
        }),
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
    doc.insert(
        "speeds".into(),
        serde_json::to_value(&a.speeds).unwrap_or(Value::Null),
    );
    doc.insert("rollers".into(), Value::Array(rollers));
    if let Some(li) = &a.life {
        let mut life = serde_json::to_value(li.result).unwrap_or(Value::Null);
        // ISO 76's s0 from the largest contact stress (issue 28), beside seed 000's lives.
        if let Value::Object(m) = &mut life {
            m.insert(
                "static_safety".into(),
                json!(super::super::answer::static_safety_of(a)),
            );
        }
        // Issue 28: ISO 281's basic and modified lives beside seed 000's (added fields).
        super::super::iso_life::extend_json(a, &mut life);
        doc.insert("life".into(), life);
    }
    if let Some(th) = &a.thermal {
        doc.insert(
            "thermal".into(),
            json!({
                "steady": serde_json::to_value(&th.steady).unwrap_or(Value::Null),
                "transient": th.transient.as_ref().map(|t| serde_json::to_value(t).unwrap_or(Value::Null)),
                "transient_heat_w": th.transient_heat_w,
            }),
        );
    }
    if let Some(fr) = &a.friction {
        let mut h = serde_json::to_value(fr.heat).unwrap_or(Value::Null);
        if let Some(m) = h.as_object_mut() {
            m.insert(
                "total_btu_per_hr".into(),
                json!(fr.heat.total_btu_per_hour()),
            );
            m.insert("lost_lubrication".into(), json!(fr.lost_lubrication));
        }
        doc.insert("heat".into(), h);
        // Issue 28: the same heat by mechanism as every system's `friction` (the `heat`
        // object above stays as it was, a contract).
        doc.insert("friction".into(), friction(a, fr).json());
    }
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

/// §9's heat by mechanism as the shared friction breakdown (issue 28): contact sliding
/// at the inner and outer raceways (eqs. 9.1–9.2; the lamina traction does not separate
/// rolling from sliding: its heat is τ·Δu, the sliding part only), cage rails (9.3–9.4)
/// and viscous drag (9.4), listed in the order [`HeatBreakdown::new`] sums them, at the
/// rings' speeds, so `power_w` and `torque_nm` are `heat.total_w` and
/// `heat.friction_torque_nm` to the bit.
///
/// [`HeatBreakdown::new`]: crate::physics::heat::HeatBreakdown::new
pub fn friction(
    a: &Analysis,
    fr: &crate::bearings::spherical_roller::stages::Friction,
) -> FrictionBreakdown {
    let h = &fr.heat;
    let m = |name, power_w, heat| Mechanism {
        name,
        power_w,
        heat: Some(heat),
    };
    FrictionBreakdown::at_ring_speeds(
        a.input.operating.inner_speed_rad_s,
        a.input.operating.outer_speed_rad_s,
        vec![
            m(
                "inner_contacts",
                h.inner_contacts_w,
                HeatSource::InnerContacts,
            ),
            m(
                "outer_contacts",
                h.outer_contacts_w,
                HeatSource::OuterContacts,
            ),
            m("cage_rails", h.cage_rails_w, HeatSource::CageRails),
            m("viscous_drag", h.viscous_drag_w, HeatSource::ViscousDrag),
        ],
    )
}

/// Pretty JSON text.
pub fn to_string(a: &Analysis) -> String {
    serde_json::to_string_pretty(&to_value(a)).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}
