//! The tribodynamics' part of the reports: the JSON `dynamics`, `friction` and
//! `contact_positions` blocks (issue 25 "Outputs", a contract) and the text sections.

use std::fmt::Write;

use serde_json::{json, Value};

use super::dynamics::LabelledSpectrum;
use super::tribodynamics::Tribodynamics;
use crate::physics::lubrication::mixed_friction::MixedFriction;
use crate::units::{Quantity, Units};

fn spectrum(s: &LabelledSpectrum) -> Value {
    json!({
        "frequency_hz": s.frequency_hz,
        "amplitude": s.amplitude,
        "peaks": s.peaks.iter().map(|p| json!({
            "frequency_hz": p.frequency_hz,
            "amplitude": p.amplitude,
            "label": p.label,
        })).collect::<Vec<_>>(),
    })
}

fn breakdown(f: &MixedFriction) -> Value {
    json!({
        "lambda": f.film_parameter,
        "half_width_m": f.half_width_m,
        "max_pressure_pa": f.max_pressure_pa,
        "asperity_load_n": f.asperity_load_n,
        "asperity_area_m2": f.asperity_area_m2,
        "boundary_n": f.boundary_n,
        "viscous_n": f.viscous_n,
        "total_n": f.total_n,
        "coefficient": f.coefficient,
        "power_w": f.power_w,
        "limited_nodes": f.limited_nodes,
    })
}

/// `dynamics`, `friction` and `contact_positions`, to merge into the report's object.
pub fn json_blocks(t: &Tribodynamics) -> [(&'static str, Value); 3] {
    let d = &t.dynamics;
    let c = &t.cycle;
    let f = &t.friction;
    let dynamics = json!({
        "contact_stiffness": t.contact_stiffness,
        "contact_stiffness_source": t.contact_stiffness_source,
        "inlet_viscosity_pa_s": t.inlet_viscosity_pa_s,
        "static_offset_m": d.static_offset_m,
        "stiffness_n_per_m": d.stiffness_n_per_m,
        "linearised_frequency_hz": d.linearised_frequency_hz,
        "base_natural_frequency_hz": d.base_natural_frequency_hz,
        "cage_frequency_hz": d.cage_frequency_hz,
        "roller_pass_frequency_hz": d.roller_pass_frequency_hz,
        "min_roller_load_n": d.min_roller_load_n,
        "loss_of_contact": d.loss_of_contact,
        "energy_drift_rel": d.energy_drift_rel,
        "spectrum_x": spectrum(&d.spectrum_x),
        "spectrum_roller_load": spectrum(&d.spectrum_roller_load),
        "roller_load_harmonics": d.roller_load_harmonics.iter().map(|h| json!({
            "order": h.order,
            "frequency_hz": h.frequency_hz,
            "amplitude_n": h.amplitude_n,
        })).collect::<Vec<_>>(),
        "cycle": {
            "cage_angle_deg": c.cage_angle_deg,
            "roller_load_n": c.roller_load_n,
            "film_m": c.film_m,
            "squeeze_velocity_m_s": c.squeeze_velocity_m_s,
            "boundary_friction_n": c.boundary_friction_n,
            "viscous_friction_n": c.viscous_friction_n,
            "power_w": c.power_w,
            "lambda": c.lambda,
            "outer_friction_n": c.outer_friction_n,
        },
        "stats": {
            "steps": d.stats.steps,
            "rejected": d.stats.rejected,
            "rhs_evaluations": d.stats.rhs_evaluations,
            "events": d.stats.events,
            "contact_losses_after_settle": d.stats.contact_losses_after_settle,
            "film_clamps": d.stats.film_clamps,
            "samples": d.series.t_s.len(),
        },
        "note": d.note,
    });
    let friction = json!({
        "total_n": f.total_n,
        "boundary_n": f.boundary_n,
        "viscous_n": f.viscous_n,
        "coefficient": f.coefficient,
        "power_w": f.power_w,
        "inner_n": f.inner_n,
        "outer_n": f.outer_n,
        "note": "mean over the last cage cycle of every roller's inner and outer contacts, isothermal at the inlet temperature (formula tier: Greenwood–Tripp boundary + limited viscous shear, seed 003 eqs. 35–42)",
    });
    let positions: Vec<Value> = t
        .positions
        .iter()
        .map(|p| {
            let mut v = breakdown(&p.friction);
            if let Some(o) = v.as_object_mut() {
                o.insert("cage_angle_deg".into(), json!(p.cage_angle_deg));
                o.insert("load_n".into(), json!(p.load_n));
            }
            v
        })
        .collect();
    [
        ("dynamics", dynamics),
        ("friction", friction),
        ("contact_positions", Value::Array(positions)),
    ]
}

/// The text sections, in `units`.
pub fn text(t: &Tribodynamics, units: Units) -> String {
    let d = &t.dynamics;
    let f = &t.friction;
    let force = |v: f64| Quantity::Force.from_si(v, units);
    let fu = Quantity::Force.unit(units);
    let len = |v: f64| Quantity::Length.from_si(v, units);
    let lu = Quantity::Length.unit(units);
    let pu = Quantity::Power.unit(units);
    let power = |v: f64| Quantity::Power.from_si(v, units);
    let mut s = String::new();
    let _ = writeln!(s, "\nDynamics (2-DOF, seed 003 eqs. 1-5)");
    let _ = writeln!(
        s,
        "  k_n = {:.4e} N/m^n ({})  static offset x = {:.4e} {lu}  y = {:.4e} {lu}",
        t.contact_stiffness,
        t.contact_stiffness_source,
        len(d.static_offset_m[0]),
        len(d.static_offset_m[1]),
    );
    let fbn = d
        .base_natural_frequency_hz
        .map_or_else(|| "-".to_string(), |v| format!("{v:.2}"));
    let _ = writeln!(
        s,
        "  f_c = {:.3} Hz  roller pass = {:.3} Hz  f_bn = {fbn} Hz  linearised sqrt(K/M)/2pi = {:.2} Hz",
        d.cage_frequency_hz, d.roller_pass_frequency_hz, d.linearised_frequency_hz
    );
    let _ = writeln!(
        s,
        "  smallest roller load {:.2} {fu}  loss of contact: {}",
        force(d.min_roller_load_n),
        if d.loss_of_contact { "yes" } else { "no" }
    );
    let peaks = |sp: &LabelledSpectrum| {
        sp.peaks
            .iter()
            .take(6)
            .map(|p| {
                let l = if p.label.is_empty() { "?" } else { &p.label };
                format!("{l} {:.2} Hz", p.frequency_hz)
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let _ = writeln!(s, "  x spectrum peaks: {}", peaks(&d.spectrum_x));
    let _ = writeln!(s, "  roller-load peaks: {}", peaks(&d.spectrum_roller_load));
    let _ = writeln!(
        s,
        "  {} steps, {} rhs evaluations, {} contact events",
        d.stats.steps, d.stats.rhs_evaluations, d.stats.events
    );
    let _ = writeln!(s, "  {}", d.note);
    let _ = writeln!(
        s,
        "\nFriction (mean over the last cage cycle, all rollers, both contacts; isothermal at the inlet)"
    );
    let _ = writeln!(
        s,
        "  total {:.3} {fu}  boundary {:.3} {fu}  viscous {:.3} {fu}  µ = {:.5}  power {:.3} {pu}",
        force(f.total_n),
        force(f.boundary_n),
        force(f.viscous_n),
        f.coefficient,
        power(f.power_w)
    );
    if !t.positions.is_empty() {
        let _ = writeln!(
            s,
            "  roller 1, inner contact:  {:>8} {:>10} {:>8} {:>10} {:>10} {:>10} {:>8} {:>9}",
            "cage deg", "W", "Λ", "boundary", "viscous", "total", "µ", "power"
        );
        for p in &t.positions {
            let m = &p.friction;
            let _ = writeln!(
                s,
                "                            {:>8.1} {:>10.2} {:>8.3} {:>10.3} {:>10.3} {:>10.3} {:>8.5} {:>9.3}",
                p.cage_angle_deg,
                force(p.load_n),
                m.film_parameter,
                force(m.boundary_n),
                force(m.viscous_n),
                force(m.total_n),
                m.coefficient,
                power(m.power_w)
            );
        }
        let _ = writeln!(s, "  (forces in {fu}, power in {pu})");
    }
    s
}
