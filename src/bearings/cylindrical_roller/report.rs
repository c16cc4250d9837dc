//! The JSON report (SI, units in key names; issue 25 "Outputs", a contract: fields are
//! added, never renamed) and the text report in the deck's units.

use std::fmt::Write;

use serde_json::{json, Value};

use crate::bearings::stiffness::{Dof, Method, StiffnessMatrix};

use super::analysis::CylindricalAnalysis;
use crate::bearings::view::{element_number, Display};
use crate::units::{Quantity, Units};

/// Azimuth of a roller in [0, 360) deg.
pub fn azimuth_deg(rad: f64) -> f64 {
    rad.to_degrees().rem_euclid(360.0)
}

/// The JSON report.
pub fn json(a: &CylindricalAnalysis) -> Value {
    let life = super::life::life(a);
    let mut warnings = a.warnings.clone();
    warnings.extend(crate::physics::rating::static_safety_warning(
        crate::physics::rating::ContactKind::Roller,
        a.max_pressure_pa(),
    ));
    let d = &a.derived;
    let q = &a.statics;
    let rollers: Vec<Value> = q
        .rollers
        .iter()
        .zip(&a.films)
        .enumerate()
        .map(|(i, (r, f))| {
            let slices: Vec<Value> = r
                .slices
                .iter()
                .zip(&f.slices)
                .map(|(s, h)| {
                    json!({
                        "axial_m": s.axial_m,
                        "profile_drop_m": s.profile_drop_m,
                        "inner_load_n": s.inner_load_n,
                        "outer_load_n": s.outer_load_n,
                        "inner_half_width_m": s.inner_half_width_m,
                        "outer_half_width_m": s.outer_half_width_m,
                        "inner_max_pressure_pa": s.inner_max_pressure_pa,
                        "outer_max_pressure_pa": s.outer_max_pressure_pa,
                        "inner_film_m": h.inner_m,
                        "outer_film_m": h.outer_m,
                    })
                })
                .collect();
            json!({
                "index": i + 1,
                "number": element_number(i),
                "azimuth_deg": azimuth_deg(r.azimuth_rad),
                "inner_load_n": r.inner_load_n,
                "outer_load_n": r.outer_load_n,
                "inner_approach_m": r.inner_approach_m,
                "outer_approach_m": r.outer_approach_m,
                // 0 without ribs carrying axial load (super::quasi_static_ribs).
                "tilt_rad": r.tilt_rad,
                "rib_load_n": r.rib_load_n,
                "inner_rib_load_n": r.inner_rib_load_n,
                "outer_rib_load_n": r.outer_rib_load_n,
                "axial_position_m": r.axial_position_m,
                "film_m": f.min_film_m,
                "lambda": f.lambda,
                "max_pressure_pa": f.max_pressure_pa,
                "slices": slices,
            })
        })
        .collect();
    let k = q.stiffness_n_m;
    let mut v = json!({
        "type": super::SYSTEM_ID,
        "name": a.name,
        "method": "seed 003 (tribodynamics of cylindrical roller bearings): quasi-static lamina load distribution (slice law, inner and outer contacts in series), Pan–Hamrock films per slice",
        "geometry": {
            "pitch_radius_m": d.pitch_radius_m,
            "effective_length_m": d.effective_length_m,
            "inner_reduced_radius_m": d.inner_reduced_radius_m,
            "outer_reduced_radius_m": d.outer_reduced_radius_m,
            "roller_mass_kg": d.roller_mass_kg,
        },
        "speeds": {
            "cage_rad_s": d.cage_speed_rad_s,
            "kinematic_cage_rad_s": d.kinematic_cage_speed_rad_s,
            "entrainment_m_s": d.entrainment_speed_m_s,
            "cage_frequency_hz": d.cage_frequency_hz,
            "roller_pass_frequency_hz": d.roller_pass_frequency_hz,
        },
        "centrifugal_force_n": d.centrifugal_n,
        "load_n": a.model.load_n,
        "rollers": rollers,
        "rings": {
            "displacement_m": q.displacement_m,
            "stiffness_n_per_m": [k[0], k[1]],
            "axial_displacement_m": q.axial_displacement_m,
            "stiffness_xyz_n_per_m": q.stiffness_xyz_n_m,
        },
        "stiffness": stiffness_json(a),
        "axial_load_n": a.input.operating.axial_load_n,
        "ribs": ribs_json(a),
        "contact": {
            "sliding_speed_m_s": a.input.contact.sliding_speed_m_s,
            "positions_deg": a.input.contact.positions_rad.iter().map(|p| p.to_degrees()).collect::<Vec<_>>(),
        },
        "min_film_m": a.min_film_m(),
        "max_roller_load_n": a.max_roller_load_n(),
        "max_pressure_pa": a.max_pressure_pa(),
        // Issue 28: reference and ISO 281 lives, static safety (`life.static_safety`).
        "life": life.json(),
        "warnings": warnings,
        "stats": {
            "iterations": q.iterations,
            "residual_n": q.residual_n,
            "slices": a.input.solver.slices,
            "wall_time_s": a.wall_time_s,
        },
    });
    if let (Some(t), Some(o)) = (&a.tribo, v.as_object_mut()) {
        for (k, block) in super::report_tribo::json_blocks(t) {
            o.insert(k.to_string(), block);
        }
        // Issue 28: the shared friction object's keys beside the existing ones (a
        // contract: `power_w` stays the tribodynamics' own; Σ by_mechanism equals it to
        // round-off).
        if let (Some(fb), Some(Value::Object(f))) =
            (super::friction::friction(a), o.get_mut("friction"))
        {
            if let Value::Object(shared) = fb.json() {
                for (k, v) in shared {
                    f.entry(k).or_insert(v);
                }
            }
        }
    }
    v
}

/// Why the cylindrical roller's matrix has no z without ribs (JSON `notes`).
pub const NO_Z_NOTE: &str = "z: not a degree of freedom here: the raceways are cylinders and carry no axial load, and no ribs are modelled (operating.axial_load = 0 or no rib geometry), so nothing in the model resists an axial displacement";
/// What z means with ribs.
pub const RIB_Z_NOTE: &str = "z: the axial displacement of the inner ring against the outer: only the roller end-rib point contacts resist it (the raceways carry no axial load)";
/// Why there are no tilts.
pub const NO_TILT_NOTE: &str = "θx, θy: not computed: the quasi-static model holds the rings parallel (no misalignment degree of freedom), though a cylindrical roller bearing does resist tilt";

/// The ring stiffness on the shared type (issue 29): (x, y), or (x, y, z) when ribs carry
/// axial load, analytic (the ring Newton's Jacobian), SI, with what z and the tilts mean.
pub fn stiffness_matrix(a: &CylindricalAnalysis) -> StiffnessMatrix {
    let q = &a.statics;
    let mut k = match q.stiffness_xyz_n_m {
        Some(k) => {
            let mut m = StiffnessMatrix::new(
                vec![Dof::X, Dof::Y, Dof::Z],
                k.iter().flatten().copied().collect(),
                Method::Analytic,
            );
            m.notes.push(RIB_Z_NOTE.to_string());
            m
        }
        None => {
            let k = q.stiffness_n_m;
            let method = a.input.solver.stiffness;
            let fd = method
                .wants_fd()
                .then(|| super::quasi_static::finite_difference_stiffness(&a.model, q));
            let flat = |m: [[f64; 2]; 2]| -> Vec<f64> { m.iter().flatten().copied().collect() };
            let mut m = match &fd {
                Some(Ok((f, _))) if method == Method::FiniteDifference => {
                    StiffnessMatrix::new(vec![Dof::X, Dof::Y], flat(*f), method)
                }
                Some(Ok(_)) => StiffnessMatrix::new(vec![Dof::X, Dof::Y], flat(k), method),
                _ => StiffnessMatrix::new(vec![Dof::X, Dof::Y], flat(k), Method::Analytic),
            };
            m.notes.push(NO_Z_NOTE.to_string());
            match fd {
                Some(Ok((f, h))) => {
                    m.fd = Some(flat(f));
                    if method == Method::Both {
                        m.fd_max_rel = Some(fd_max_rel(k, f));
                    }
                    m.notes.push(format!(
                        "finite differences: central, step {h:.3e} m (1e-5 of the ring offset), every roller re-solved"
                    ));
                }
                Some(Err(e)) => m.notes.push(format!(
                    "finite differences asked for but not computed: {e}"
                )),
                None => {}
            }
            m
        }
    };
    if q.stiffness_xyz_n_m.is_some() && a.input.solver.stiffness.wants_fd() {
        k.notes.push(
            "finite differences asked for but not computed: the ribbed 3x3 has only its analytic Jacobian so far (solver.stiffness applies to x, y without ribs)"
                .to_string(),
        );
    }
    k.notes.push(NO_TILT_NOTE.to_string());
    k.reference_point =
        Some("bearing centre (x, y in the radial plane, z along the axis)".to_string());
    k
}

/// Largest |a − b| over each row's largest |a|.
fn fd_max_rel(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> f64 {
    (0..2)
        .map(|r| {
            let scale = a[r][0].abs().max(a[r][1].abs()).max(f64::MIN_POSITIVE);
            (a[r][0] - b[r][0]).abs().max((a[r][1] - b[r][1]).abs()) / scale
        })
        .fold(0.0, f64::max)
}

/// The ring stiffness for `rollbench stiffness` (rows of forces, columns of
/// displacements, SI): the shared type's keys, and the `unit` the 2×2/3×3 had.
fn stiffness_json(a: &CylindricalAnalysis) -> Value {
    let mut v = stiffness_matrix(a).json();
    if let Some(o) = v.as_object_mut() {
        o.insert("unit".into(), json!("N/m"));
    }
    v
}

/// The rib contact's geometry when ribs carry axial load (`null` otherwise).
fn ribs_json(a: &CylindricalAnalysis) -> Value {
    match super::analysis::rib_contact(&a.input) {
        Some(r) => json!({
            "rib_angle_deg": r.angle_rad.to_degrees(),
            "contact_height_m": r.contact_height_m,
            "roller_end_radius_m": r.end_radius_m(a.derived.roller_radius_m),
            "max_rib_load_n": a.statics.rollers.iter().map(|x| x.rib_load_n).fold(0.0, f64::max),
        }),
        None => Value::Null,
    }
}

/// The ring stiffness (the shared printer) and the static offset in `units`: the text
/// report's section and the workbench's Stiffness pane.
pub fn stiffness_lines(a: &CylindricalAnalysis, units: Units) -> Vec<String> {
    let q = &a.statics;
    // Ring deflections in µm / µin, as every system's text and the workbench show them
    // (issue 30 item 7).
    let len = crate::bearings::view::Display::Deflection;
    let mut v = stiffness_matrix(a).lines(units);
    v.push(format!(
        "Static offset of the inner ring  x = {:.4}  y = {:.4} {}",
        len.convert(q.displacement_m[0], units),
        len.convert(q.displacement_m[1], units),
        len.unit(units)
    ));
    if q.stiffness_xyz_n_m.is_some() {
        v.push(format!(
            "Axial displacement of the inner ring  z = {:.4} {}",
            len.convert(q.axial_displacement_m, units),
            len.unit(units)
        ));
    }
    v
}

/// The text report in `units`.
pub fn text(a: &CylindricalAnalysis, units: Units) -> String {
    let g = &a.input.geometry;
    let d = &a.derived;
    let len = |v: f64| Quantity::Length.from_si(v, units);
    let force = |v: f64| Quantity::Force.from_si(v, units);
    let pres = |v: f64| Quantity::Pressure.from_si(v, units);
    let (lu, fu, pu) = (
        Quantity::Length.unit(units),
        Quantity::Force.unit(units),
        Quantity::Pressure.unit(units),
    );
    let mut s = String::new();
    let _ = writeln!(
        s,
        "ROLLBENCH — cylindrical roller bearing (seed 003, lamina quasi-statics): {}",
        a.name
    );
    let _ = writeln!(
        s,
        "m = {}  d = {:.5} {lu}  l = {:.5} {lu}  l_e = {:.5} {lu}  r_m = {:.5} {lu}  rho = {:.4e} {lu}  slices = {}",
        g.roller_count,
        len(g.roller_diameter_m),
        len(g.roller_length_m),
        len(d.effective_length_m),
        len(d.pitch_radius_m),
        len(g.radial_interference_m),
        a.input.solver.slices
    );
    let _ = writeln!(
        s,
        "cage {:.3} rad/s (kinematic {:.3})  f_c = {:.3} Hz  roller pass {:.3} Hz  U = {:.4} m/s  F_c = {:.4} {fu}",
        d.cage_speed_rad_s,
        d.kinematic_cage_speed_rad_s,
        d.cage_frequency_hz,
        d.roller_pass_frequency_hz,
        d.entrainment_speed_m_s,
        force(d.centrifugal_n)
    );
    let _ = writeln!(
        s,
        "load on the inner ring  F_x = {:.2}  F_y = {:.2} {fu}",
        force(a.model.load_n[0]),
        force(a.model.load_n[1])
    );
    let _ = writeln!(s, "\nRollers");
    let _ = writeln!(
        s,
        "  {:>3} {:>7} {:>11} {:>11} {:>11} {:>7} {:>11}",
        "#",
        "ψ deg",
        "W_i",
        "W_o",
        format!("h_min {}", Display::Film.unit(units)),
        "Λ",
        "p_max"
    );
    for (i, (r, f)) in a.statics.rollers.iter().zip(&a.films).enumerate() {
        let h = f.min_film_m.map_or_else(
            || "-".to_string(),
            |h| format!("{:.4}", Display::Film.convert(h, units)),
        );
        let l = f
            .lambda
            .map_or_else(|| "-".to_string(), |l| format!("{l:.3}"));
        let _ = writeln!(
            s,
            "  {:>3} {:>7.2} {:>11.3} {:>11.3} {:>11} {:>7} {:>11.4e}",
            i + 1,
            azimuth_deg(r.azimuth_rad),
            force(r.inner_load_n),
            force(r.outer_load_n),
            h,
            l,
            pres(f.max_pressure_pa)
        );
    }
    let _ = writeln!(s, "  (loads in {fu}, pressure in {pu})\n");
    if let Some(r) = super::analysis::rib_contact(&a.input) {
        let _ = writeln!(
            s,
            "Ribs (both rings): axial load {:.2} {fu}, rib angle {:.3} deg, contact height {:.4e} {lu}, roller end radius {:.4e} {lu}",
            force(a.input.operating.axial_load_n),
            r.angle_rad.to_degrees(),
            len(r.contact_height_m),
            len(r.end_radius_m(d.roller_radius_m))
        );
        let _ = writeln!(
            s,
            "  {:>3} {:>7} {:>11} {:>12}",
            "#", "ψ deg", "rib load", "tilt mrad"
        );
        for (i, r) in a.statics.rollers.iter().enumerate() {
            let _ = writeln!(
                s,
                "  {:>3} {:>7.2} {:>11.3} {:>12.5}",
                i + 1,
                azimuth_deg(r.azimuth_rad),
                force(r.rib_load_n),
                r.tilt_rad * 1e3
            );
        }
        let _ = writeln!(s);
    }
    for line in stiffness_lines(a, units) {
        let _ = writeln!(s, "{line}");
    }
    if let Some(t) = &a.tribo {
        s.push_str(&super::report_tribo::text(t, units));
    }
    s.push_str(&super::life::life(a).text(units));
    for w in &a.warnings {
        let _ = writeln!(s, "\nWarning: {w}");
    }
    if let Some(w) = crate::physics::rating::static_safety_warning(
        crate::physics::rating::ContactKind::Roller,
        a.max_pressure_pa(),
    ) {
        let _ = writeln!(s, "\nWarning: {w}");
    }
    let _ = writeln!(
        s,
        "\nEquilibrium residual {:.3e} {fu} after {} iterations; {:.3} ms",
        force(a.statics.residual_n),
        a.statics.iterations,
        a.wall_time_s * 1e3
    );
    s
}

/// Most rows `run --series` writes (the ball's bound, `angular_ball::dynamics::budget`):
/// a longer history keeps every k-th sample and says so in a `#` line.
pub const MAX_SERIES_ROWS: usize = 100_000;

/// `run --series FILE`: the 2-DOF dynamics' time history after settling (the uniformly
/// sampled series the spectra are taken from) as CSV, SI with units in the header: t, the
/// inner ring's x, y, ẋ, ẏ and each roller's load W_i (eq. 2). A history longer than
/// [`MAX_SERIES_ROWS`] keeps one sample in k and starts with a `# decimated` line; a
/// solve without the dynamics is refused naming `dynamics.revolutions`.
pub fn series_csv(a: &CylindricalAnalysis) -> Result<String, String> {
    let Some(t) = &a.tribo else {
        return Err(format!(
            "no time history: the 2-DOF dynamics was not run (dynamics.revolutions = {}; run --no-transient also skips it); set dynamics.revolutions > 0 (e.g. --set dynamics.revolutions=100)",
            a.input.dynamics.revolutions
        ));
    };
    let s = &t.dynamics.series;
    let n = s.t_s.len();
    let every = n.div_ceil(MAX_SERIES_ROWS).max(1);
    let mut out = String::new();
    if every > 1 {
        let _ = writeln!(
            out,
            "# decimated: 1 sample in {every} of {n} (sampling step {:e} s) kept, to keep at most {MAX_SERIES_ROWS} rows",
            s.dt_s
        );
    }
    out.push_str("time_s,x_m,y_m,vx_m_s,vy_m_s");
    for j in 0..s.roller_load_n.len() {
        let _ = write!(out, ",roller_{}_load_n", j + 1);
    }
    out.push('\n');
    for i in (0..n).step_by(every) {
        let cell = |v: &[f64]| v.get(i).copied().unwrap_or(f64::NAN);
        let _ = write!(
            out,
            "{:e},{:e},{:e},{:e},{:e}",
            s.t_s[i],
            cell(&s.x_m),
            cell(&s.y_m),
            cell(&s.vx_m_s),
            cell(&s.vy_m_s)
        );
        for w in &s.roller_load_n {
            let _ = write!(out, ",{:e}", cell(w));
        }
        out.push('\n');
    }
    Ok(out)
}
