//! The double-row bearing's reports: JSON (SI, units in key names; fields are added, never
//! renamed) and text in the deck's units. Each row's rollers, life and speeds are the
//! spherical roller's report of that row ([`crate::bearings::spherical_roller::report`]),
//! with the row and the guide ring added.

use serde_json::{json, Value};

use super::input::CageSpeedSource;
use super::losses::LossBreakdown;
use super::statics::DoubleRowAnalysis;
use super::SYSTEM_ID;
use crate::bearings::spherical_roller::report::{json as sr_json, text as sr_text};
use crate::units::{Quantity, Units};

/// The stiffness matrix in the bearing's (radial x, axial z) order, N/m.
pub fn stiffness_xz(a: &DoubleRowAnalysis) -> [[f64; 2]; 2] {
    // The solver's order is (axial, radial).
    let k = a.stiffness_n_m;
    [[k[1][1], k[1][0]], [k[0][1], k[0][0]]]
}

/// The JSON report.
pub fn json(a: &DoubleRowAnalysis) -> Value {
    let mut rollers = Vec::new();
    let mut rows = Vec::new();
    for (i, row) in a.rows.iter().enumerate() {
        let v = sr_json::to_value(row);
        let z = row.load.rollers.len();
        for (j, r) in v
            .get("rollers")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default()
            .into_iter()
            .enumerate()
        {
            let mut r = r;
            if let Some(m) = r.as_object_mut() {
                m.insert("row".into(), json!(i + 1));
                let g = a
                    .combined
                    .rollers
                    .get(i * z + j)
                    .map_or(0.0, |x| x.guide_force_n);
                m.insert("guide_ring_load_n".into(), json!(g));
            }
            rollers.push(r);
        }
        rows.push(json!({
            "row": i + 1,
            "life": v.get("life").cloned().unwrap_or(Value::Null),
            "speeds": v.get("speeds").cloned().unwrap_or(Value::Null),
            "max_roller_load_n": row.load.rollers.iter().map(|r| r.inner.normal_load_n.max(r.outer.normal_load_n)).fold(0.0, f64::max),
        }));
    }
    let k = stiffness_xz(a);
    let ld = &a.combined;
    let mut life = json!({
        "l10_bearing_mrev": a.l10_mrev,
        "l10_bearing_h": a.l10_h,
        "rows": rows.iter().map(|r| r["life"].clone()).collect::<Vec<_>>(),
    });
    // Issue 28: ISO 281 ratings, raceway lives, a_ISO, s0 (added beside, none moved).
    super::life::life(a).extend_json(&mut life);
    json!({
        "type": SYSTEM_ID,
        "name": a.name,
        "input": serde_json::to_value(&a.input).unwrap_or(Value::Null),
        "converged": ld.converged,
        "loads": {"radial_n": a.input.operating.radial_load_n, "axial_n": a.input.operating.axial_load_n},
        // Issue 29: self-aligning (the outer raceway is a sphere about the bearing
        // centre), so the ring's tilt is free and it carries no moment: moment_nm is 0
        // by that geometry, not computed, and tilt_free says so.
        "rings": {
            "axial_deflection_m": a.axial_deflection_m(),
            "radial_deflection_m": a.radial_deflection_m(),
            "moment_nm": 0.0,
            "tilt_free": true,
        },
        "stiffness": stiffness_json(a, k),
        "dynamic_speeds": {
            "source": a.input.cage.speed,
            "cage_rad_s": a.dynamic.cage_rad_s,
            "cage_rpm": a.dynamic.cage_rad_s * 30.0 / std::f64::consts::PI,
            "roller_spin_rad_s": a.dynamic.roller_spin_rad_s,
        },
        "guide_ring": {
            "force_row1_n": a.guide.force_row1_n,
            "force_row2_n": a.guide.force_row2_n,
            "net_axial_force_n": a.guide.net_axial_n,
            "axial_offset_m": a.guide.axial_offset_m,
            "nominal_gap_m": a.input.guide_gap_m(),
        },
        "roller_properties": {
            "mass_kg": ld.roller_mass.mass_kg,
            "polar_inertia_kg_m2": ld.roller_mass.polar_inertia_kg_m2,
            "transverse_inertia_kg_m2": ld.roller_mass.transverse_inertia_kg_m2,
        },
        "speeds": a.rows.first().map(|r| serde_json::to_value(&r.speeds).unwrap_or(Value::Null)),
        "life": life,
        "rows": rows,
        "rollers": rollers,
        "max_roller_load_n": a.max_roller_load_n(),
        "max_stress_pa": a.max_stress_pa(),
        "residuals": {
            "bearing_radial_n": ld.residuals.bearing_radial_n,
            "bearing_axial_n": ld.residuals.bearing_axial_n,
            "roller_force_n": ld.residuals.roller_force_n,
            "roller_moment_nm": ld.residuals.roller_moment_nm,
        },
        "stats": {
            "iterations": ld.stats.iterations,
            "roller_iterations": ld.stats.roller_iterations,
            "lamina_evaluations": ld.stats.lamina_evaluations,
            "wall_time_s": a.wall_time_s,
        },
    })
}

/// The JSON `stiffness` object (issue 29): the shared 5×5 (x, y, z, θ_x, θ_y; its x–z
/// block is the ring solve's 2×2 `k`, the tilts zero: self-aligning) with the `unit` key
/// the 2×2 had; the 2×2 itself, as it was, when the 5×5 could not be computed, with the
/// reason.
fn stiffness_json(a: &DoubleRowAnalysis, k: [[f64; 2]; 2]) -> Value {
    match &a.stiffness {
        Ok(m) => {
            let mut v = m.json();
            if let Some(o) = v.as_object_mut() {
                o.insert("unit".into(), json!("N/m"));
                // Before issue 29 `matrix` was this 2×2 (rows F_x F_z, columns x z); the
                // shared 5×5 (issue 29: `matrix` with `rows`/`columns` names) replaced it,
                // so the old layout stays readable under its own name.
                o.insert("matrix_xz".into(), json!(k));
            }
            v
        }
        Err(reason) => json!({
            "rows": ["F_x", "F_z"],
            "columns": ["x", "z"],
            "matrix": k,
            "unit": "N/m",
            "reason": reason,
        }),
    }
}

/// The ring stiffness (the shared 5×5 block, or the 2×2 when that is missing) and the
/// ring deflection in `units`.
pub fn stiffness_lines(a: &DoubleRowAnalysis, units: Units) -> Vec<String> {
    let ks = Quantity::LinearStiffness;
    let mut v = match &a.stiffness {
        Ok(m) => m.lines(units),
        Err(reason) => {
            let k = stiffness_xz(a);
            let mut v = vec![format!(
                "Ring stiffness (rows F_x F_z; columns x z), {}",
                ks.unit(units)
            )];
            for (name, row) in ["F_x", "F_z"].iter().zip(k) {
                v.push(format!(
                    "  {name:<4} {:>12.4e} {:>12.4e}",
                    ks.from_si(row[0], units),
                    ks.from_si(row[1], units)
                ));
            }
            v.push(format!("  no 5x5: {reason}"));
            v
        }
    };
    // µm / µin, as the Summary pane and every system's text show ring deflections
    // (issue 30 item 7).
    let defl = crate::bearings::view::Display::Deflection;
    v.push(format!(
        "Inner ring deflection  x (radial) = {:.3}  z (axial) = {:.3} {}",
        defl.convert(a.radial_deflection_m(), units),
        defl.convert(a.axial_deflection_m(), units),
        defl.unit(units)
    ));
    v
}

/// The text report in `units`: the bearing's lines, then each row as the spherical
/// roller's report of that row.
pub fn text(a: &DoubleRowAnalysis, units: Units) -> String {
    let f = Quantity::Force;
    let mut s = format!(
        "rollbench {} — {}\nDouble-row spherical roller bearing: {} rows × {} rollers (seed 002)\n\n",
        SYSTEM_ID,
        a.name,
        a.input.geometry.rows,
        a.input.geometry.roller_count
    );
    for line in stiffness_lines(a, units) {
        s.push_str(&line);
        s.push('\n');
    }
    s.push_str(&format!(
        "Cage speed ({}) {:.1} rpm; guide ring: row 1 {:.3} {u}, row 2 {:.3} {u}, net axial {:.3} {u}, axial offset {:.4} {l}\n",
        match a.input.cage.speed {
            super::input::CageSpeedSource::Measured => "measured",
            super::input::CageSpeedSource::Computed => "computed",
        },
        a.dynamic.cage_rad_s * 30.0 / std::f64::consts::PI,
        f.from_si(a.guide.force_row1_n, units),
        f.from_si(a.guide.force_row2_n, units),
        f.from_si(a.guide.net_axial_n, units),
        Quantity::Length.from_si(a.guide.axial_offset_m, units),
        u = f.unit(units),
        l = Quantity::Length.unit(units)
    ));
    match (a.l10_mrev, a.l10_h) {
        (Some(m), Some(h)) => s.push_str(&format!("Bearing L-10: {m:.4e} Mrev, {h:.4e} h\n")),
        (Some(m), None) => s.push_str(&format!("Bearing L-10: {m:.4e} Mrev\n")),
        _ => s.push_str("Bearing L-10: no row loaded\n"),
    }
    s.push_str(&super::life::life(a).text(units));
    for (i, row) in a.rows.iter().enumerate() {
        s.push_str(&format!(
            "\n==================== Row {} ====================\n",
            i + 1
        ));
        let row_text = sr_text::to_string(row, units);
        match (a.input.cage.speed, row_text.find("\nLoads:")) {
            // The single-row report's speeds line says which speeds its own solver would
            // have used; here the centrifugal forces and gyroscopic moments came from the
            // measured cage speed, so say so right under it rather than let it mislead.
            (CageSpeedSource::Measured, Some(k)) => {
                s.push_str(&row_text[..k]);
                s.push_str(&format!(
                    "\nDynamic loads from the measured cage speed {:.1} rpm (cage.measured_speed); the §7 cage speed above is what the kinematics alone gives, and the film uses it",
                    a.input.cage.measured_speed_rad_s * 30.0 / std::f64::consts::PI
                ));
                s.push_str(&row_text[k..]);
            }
            _ => s.push_str(&row_text),
        }
    }
    s
}

/// rad/s to rpm.
const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

/// The loss breakdown into the JSON report `v` (issue 27 "Outputs"): `losses` {…},
/// `guide_ring.speed_rpm` (the ring's torque balance; absent without a guide ring) and,
/// per roller (both rows, in the report's order), `guide_ring_load_n`, `pocket_force_n`
/// (the roller's force on its pocket along +θ, N), `skew_moment_nm` and `spin_rad_s` (the
/// spin of the roller's moment balance about its axis, relative to the cage).
pub fn add_losses(v: &mut Value, l: &LossBreakdown) {
    let Some(m) = v.as_object_mut() else {
        return;
    };
    m.insert(
        "losses".into(),
        serde_json::to_value(l.losses).unwrap_or(Value::Null),
    );
    if let (Some(g), Some(gr)) = (
        m.get_mut("guide_ring").and_then(Value::as_object_mut),
        l.guide_ring.as_ref(),
    ) {
        g.insert("speed_rpm".into(), json!(gr.speed_rad_s * RPM_PER_RAD_S));
    }
    if let Some(rs) = m.get_mut("rollers").and_then(Value::as_array_mut) {
        for (r, rl) in rs.iter_mut().zip(&l.rollers) {
            if let Some(o) = r.as_object_mut() {
                o.insert("guide_ring_load_n".into(), json!(rl.guide_ring_load_n));
                o.insert("pocket_force_n".into(), json!(rl.pocket_force_n));
                o.insert("skew_moment_nm".into(), json!(rl.skew_moment_nm));
                o.insert("spin_rad_s".into(), json!(rl.spin_rad_s));
            }
        }
    }
}

/// The LOSSES table in `units`: each mechanism in W and % of the total, M_fi, M_fo, M and
/// the cage's torque imbalance, and the guide ring's speed.
pub fn loss_lines(l: &LossBreakdown, units: Units) -> Vec<String> {
    let x = &l.losses;
    let s = &x.shares_pct;
    let t = Quantity::Moment;
    let tu = t.unit(units);
    let mut v = vec![
        "LOSSES".to_string(),
        format!("  {:<24} {:>12} {:>8}", "mechanism", "W", "%"),
    ];
    for (name, w, p) in [
        ("raceways, inner", x.raceway_inner_w, s.raceway_inner),
        ("raceways, outer", x.raceway_outer_w, s.raceway_outer),
        ("guide ring", x.guide_ring_w, s.guide_ring),
        ("cage pockets", x.cage_pockets_w, s.cage_pockets),
        ("cage land", x.cage_land_w, s.cage_land),
        ("skew", x.skew_w, s.skew),
        ("drag (off)", x.drag_w, s.drag),
    ] {
        v.push(format!("  {name:<24} {w:>12.4} {p:>8.2}"));
    }
    let all = if x.total_w != 0.0 { 100.0 } else { 0.0 };
    v.push(format!("  {:<24} {:>12.4} {all:>8.2}", "total", x.total_w));
    v.push(format!(
        "  M_fi = {:.5} {tu}  M_fo = {:.5} {tu}  M = {:.5} {tu}  cage imbalance = {:.5} {tu}",
        t.from_si(x.friction_torque_inner_nm, units),
        t.from_si(x.friction_torque_outer_nm, units),
        t.from_si(x.friction_torque_nm, units),
        t.from_si(x.cage_torque_imbalance_nm, units),
    ));
    v.push(format!(
        "  cage speed {:.1} rpm ({}), slip {:.2} % against the kinematic speed",
        x.cage_speed_rpm,
        if l.cage_speed_computed {
            "the cage's torque balance"
        } else {
            "measured"
        },
        x.cage_slip_pct
    ));
    if l.cage_speed_computed {
        v.push(format!(
            "  the statics' centrifugal loads used {:.1} rpm (the §7 estimate)",
            l.centrifugal_cage_speed_rpm
        ));
    }
    if let Some(g) = &l.guide_ring {
        v.push(format!(
            "  guide ring speed {:.1} rpm (its torque balance)",
            g.speed_rad_s * RPM_PER_RAD_S
        ));
    }
    v
}

/// The text report with the LOSSES table after the bearing's lines, before the rows.
pub fn text_with_losses(a: &DoubleRowAnalysis, l: &LossBreakdown, units: Units) -> String {
    let base = text(a, units);
    let mut table = String::from("\n");
    for line in loss_lines(l, units) {
        table.push_str(&line);
        table.push('\n');
    }
    match base.find("\n====================") {
        Some(i) => format!("{}{}{}", &base[..i], table, &base[i..]),
        None => base + &table,
    }
}
