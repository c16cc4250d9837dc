//! The JSON report (SI, units in key names; issue 17's field names are a contract) and
//! the text report in the deck's units.

use std::fmt::Write;

use serde_json::{json, Value};

use super::analysis::Analysis;
use crate::bearings::view::{element_number, flag_word};
use crate::units::{Quantity, Units};

/// The seed's statement on damping (§2.3.2), reported instead of invented numbers.
pub const DAMPING_NOTE: &str = "not computed: the seed (AFAPL-TR-78-6 Part III §2.3.2) found no experimental damping data for tapered roller bearings and includes none";

/// The JSON report.
pub fn json(a: &Analysis) -> Value {
    let life = super::life::life(a);
    let trib = a.tribology.as_ref().and_then(|t| t.as_ref().ok());
    let b = &a.bearing;
    let rg = &b.geometry;
    let dy = &b.dynamics;
    let sol = &a.solution;
    let rollers: Vec<Value> = sol
        .rollers
        .iter()
        .enumerate()
        .map(|(q, (r, delta, theta))| {
            let (c, s) = b.azimuth[q];
            let [cup, cone] = &a.slices[q];
            // Each race's slices lie on its own contact extent.
            let film = trib.map(|t| &t.rollers[q]);
            let films = [film.map(|f| &f.cup[..]), film.map(|f| &f.cone[..])];
            let slices: Vec<Value> = [("outer", cup, films[0]), ("inner", cone, films[1])]
                .iter()
                .flat_map(|(race, list, films)| {
                    list.iter().enumerate().map(move |(k, sl)| {
                        let mut v = json!({
                            "race": race,
                            "x_m": sl.x_m,
                            "intrusion_m": sl.intrusion_m,
                            "load_n_m": sl.load_n_m,
                            "half_width_m": sl.half_width_m,
                            "stress_pa": sl.stress_pa,
                        });
                        // Issue 28 item 2: the slice's film and friction, when lubricated.
                        if let (Some(f), Some(o)) =
                            (films.and_then(|f| f.get(k)), v.as_object_mut())
                        {
                            o.insert("entrainment_m_s".into(), json!(f.entrainment_m_s));
                            o.insert("sliding_m_s".into(), json!(f.sliding_m_s));
                            o.insert("central_film_m".into(), json!(f.central_film_m));
                            o.insert("min_film_m".into(), json!(f.min_film_m));
                            o.insert("lambda".into(), json!(f.lambda));
                            o.insert("rolling_w".into(), json!(f.rolling_w));
                            o.insert("sliding_w".into(), json!(f.sliding_w));
                        }
                        v
                    })
                })
                .collect();
            let mut v = json!({
                "index": q + 1,
                "number": element_number(q),
                "azimuth_deg": s.atan2(c).to_degrees().rem_euclid(360.0),
                "state": r.state.as_str(),
                "outer_load_n": r.cup.load_n,
                "inner_load_n": r.cone.load_n,
                "flange_load_n": r.flange_n,
                "outer_moment_nm": r.cup.moment_nm,
                "inner_moment_nm": r.cone.moment_nm,
                "outer_edge_loaded": r.cup.edge_loaded,
                "inner_edge_loaded": r.cone.edge_loaded,
                "max_stress_outer_pa": r.cup.max_stress_pa,
                "max_stress_inner_pa": r.cone.max_stress_pa,
                "ring_approach_m": delta,
                "ring_misalignment_rad": theta,
                "outer_approach_m": r.delta1_m,
                "outer_misalignment_rad": r.theta1_rad,
                "inner_approach_m": r.delta2_m,
                "inner_misalignment_rad": r.theta2_rad,
                "outer_contact_extent_m": r.cup.extent_m,
                "inner_contact_extent_m": r.cone.extent_m,
                "iterations": r.iterations,
                "residual_n": r.residual_n,
                "slices": slices,
            });
            if let (Some(f), Some(o)) = (film, v.as_object_mut()) {
                let min = |s: &[super::tribology::SliceFilm]| {
                    s.iter()
                        .map(|x| x.min_film_m)
                        .filter(|h| *h > 0.0)
                        .reduce(f64::min)
                };
                o.insert("flange".into(), json!(f.flange));
                o.insert("min_film_outer_m".into(), json!(min(&f.cup)));
                o.insert("min_film_inner_m".into(), json!(min(&f.cone)));
            }
            v
        })
        .collect();
    let matrix = |k: &super::bearing::Matrix5| -> Vec<Vec<f64>> {
        (0..5)
            .map(|i| (0..5).map(|j| k[(i, j)]).collect())
            .collect()
    };
    let mut stiffness = a.stiffness_matrix().json();
    if let (Some(off), Some(kc), Some(obj)) = (
        a.load_centre_offset_m(),
        a.stiffness_at_load_centre(),
        stiffness.as_object_mut(),
    ) {
        obj.insert("load_centre_offset_m".into(), json!(off));
        obj.insert("matrix_at_load_centre".into(), json!(matrix(&kc)));
    }
    if let (Some(with), Some(obj)) = (a.stiffness_with_pedestal(), stiffness.as_object_mut()) {
        let pedestal = json!({
            "stiffness": b.input.pedestal.stiffness,
            "note": "x, y, z in N/m, θx, θy in N·m/rad; 0 = rigid",
        });
        obj.insert("pedestal".into(), pedestal);
        match with {
            Ok(k) => obj.insert("with_pedestal_matrix".into(), json!(matrix(&k))),
            Err(e) => obj.insert("with_pedestal_error".into(), json!(e)),
        };
    }
    let roller_res = sol
        .rollers
        .iter()
        .map(|r| r.0.residual_n)
        .fold(0.0, f64::max);
    let roller_it = sol
        .rollers
        .iter()
        .map(|r| r.0.iterations)
        .max()
        .unwrap_or(0);
    let mut out = json!({
        "type": super::SYSTEM_ID,
        "name": a.name,
        "method": "AFAPL-TR-78-6 Part III (seed 004): flange-guided tapered rollers, Lundberg line-contact slices, centrifugal and gyroscopic loads, 5×5 stiffness",
        "geometry": {
            "cone_half_angle_deg": rg.half_cone_rad.to_degrees(),
            "roller_axis_angle_deg": rg.axis_angle_rad.to_degrees(),
            "apex_to_midpoint_m": rg.h0_m,
            "small_end_radius_m": rg.r1_m,
            "big_end_radius_m": rg.r2_m,
            "crown_radius_m": rg.crown_radius_m,
            "crown_drop_m": rg.crown_drop_m,
            "profile": match b.input.geometry.profile {
                super::input::RollerProfile::Crowned => "crowned",
                super::input::RollerProfile::Logarithmic => "logarithmic",
            },
            "roller_mass_kg": rg.mass_kg,
            "cg_offset_m": rg.cg_offset_m,
            "polar_inertia_kg_m2": rg.polar_inertia_kg_m2,
            "transverse_inertia_kg_m2": rg.transverse_inertia_kg_m2,
            "big_end_sphere_radius_m": rg.big_end_radius_m,
            "flange_contact_radius_m": rg.flange_contact_radius_m,
            "flange_angle_deg": rg.flange_angle_rad.to_degrees(),
            "flange_lever_arm_m": rg.flange_lever_arm_m,
        },
        "speeds": {
            "cage_rad_s": dy.cage_rad_s,
            "roller_spin_rad_s": dy.roller_spin_rad_s,
        },
        "centrifugal_force_n": dy.centrifugal_force_n,
        "gyroscopic_moment_nm": dy.gyroscopic_moment_nm,
        "rings": {
            "displacement_m": sol.displacement_m,
            "rotation_rad": sol.rotation_rad,
            "reaction_force_n": [sol.reaction[0], sol.reaction[1], sol.reaction[2]],
            "reaction_moment_nm": [sol.reaction[3], sol.reaction[4]],
            // Issue 29: the tilt about y (perpendicular to the radial load) and the moment
            // about y: the applied one when the deck gives `operating.moment` (θy solved),
            // else the moment holding the prescribed θy.
            "tilt_rad": sol.rotation_rad[1],
            "moment_nm": sol.reaction[4],
            "tilt_solved": b.input.operating.applied_moment_nm().is_some(),
        },
        "rollers": rollers,
        "stiffness": stiffness,
        "damping": DAMPING_NOTE,
        // Issue 28: reference and ISO 281 lives, static safety (`life.static_safety`),
        // and the s0 < 1 warning (the system's first).
        "life": life.json(),
        "warnings": crate::physics::rating::static_safety_warning(
            crate::physics::rating::ContactKind::Roller,
            life.max_contact_stress_pa,
        )
        .into_iter()
        .collect::<Vec<_>>(),
        "residuals": {
            "equilibrium_n": sol.residual_n,
            "roller_max_n": roller_res,
        },
        "stats": {
            "bearing_iterations": sol.iterations,
            "roller_iterations_max": roller_it,
            "unique_rollers": sol.unique_rollers,
            "slices": b.input.solver.slices,
            "wall_time_s": a.wall_time_s,
        },
    });
    // Issue 29: the tilt about x and its moment beside tilt_rad/moment_nm (about y),
    // written where the deck holds a θx (operating.misalignment_x). Without it the loads
    // lie in the x–z plane and M_x is zero by symmetry (round-off only): not written.
    if sol.rotation_rad[0] != 0.0 {
        if let Some(r) = out.get_mut("rings").and_then(Value::as_object_mut) {
            r.insert("tilt_x_rad".into(), json!(sol.rotation_rad[0]));
            r.insert("moment_x_nm".into(), json!(sol.reaction[3]));
        }
    }
    if let Some(o) = out.as_object_mut() {
        for (k, v) in lubrication_json(a) {
            o.insert(k.into(), v);
        }
    }
    out
}

/// The JSON's `film`, `friction` and `thermal` (issue 28 items 2–5): the numbers when the
/// deck gives a lubricant, else `film.reason` and `friction: null`.
fn lubrication_json(a: &Analysis) -> Vec<(&'static str, Value)> {
    let mut out = Vec::new();
    match &a.tribology {
        None => {
            out.push(("film", json!({ "reason": super::life::NO_LUBRICANT })));
            out.push(("friction", Value::Null));
        }
        Some(Err(e)) => {
            out.push(("film", json!({ "reason": e.to_string() })));
            out.push(("friction", Value::Null));
        }
        Some(Ok(t)) => {
            let at = |m: Option<super::tribology::FilmMin>| {
                m.map(|m| {
                    json!({
                        "min_film_m": m.film_m,
                        "lambda": m.lambda,
                        "roller": m.roller + 1,
                        "contact": m.contact,
                        "slice": m.slice,
                    })
                })
            };
            let flange_mu = t
                .rollers
                .iter()
                .filter(|r| r.flange.load_n > 0.0)
                .map(|r| r.flange.friction_coefficient)
                .reduce(f64::max);
            out.push((
                "film",
                json!({
                    "viscosity_pa_s": t.viscosity_pa_s,
                    "inlet_temperature_k": a.bearing.input.lubricant.inlet_temperature_k,
                    "composite_rms_m": a.bearing.input.surfaces.composite_rms_m,
                    "min_film_m": t.min.map(|m| m.film_m),
                    "min_lambda": t.min.map(|m| m.lambda),
                    "min": at(t.min),
                    "min_inner": at(t.min_race[0]),
                    "min_outer": at(t.min_race[1]),
                    "flange_friction_coefficient_max": flange_mu,
                    "flange_sliding_m_s": t.rollers.first().map(|r| r.flange.sliding_m_s),
                    "flange_entrainment_m_s": t.rollers.first().map(|r| r.flange.entrainment_m_s),
                }),
            ));
            out.push(("friction", t.friction.json()));
        }
    }
    match &a.thermal {
        Some(Ok(th)) => out.push(("thermal", th.json())),
        Some(Err(e)) => out.push(("thermal", json!({ "error": e }))),
        None => {}
    }
    out
}

/// The stiffness matrix in `units` (rows F_x … M_y, columns x … θ_y, each block in its
/// unit), its asymmetry and the finite-difference check: the text report's section and
/// the workbench's Stiffness pane.
pub fn stiffness_lines(a: &Analysis, units: Units) -> Vec<String> {
    let mut out = a.stiffness_matrix().lines(units);
    out.extend(pedestal_lines(a, units));
    out
}

/// The stiffness with the deck's pedestal in series (eq. 9), when the deck has one.
pub fn pedestal_lines(a: &Analysis, units: Units) -> Vec<String> {
    let unit = |i: usize, j: usize| match (i < 3, j < 3) {
        (true, true) => Quantity::Force.factor(units) / Quantity::Length.factor(units),
        (true, false) => Quantity::Force.factor(units),
        (false, true) => Quantity::Moment.factor(units) / Quantity::Length.factor(units),
        (false, false) => Quantity::Moment.factor(units),
    };
    let mut s = String::new();
    match a.stiffness_with_pedestal() {
        None => {}
        Some(Err(e)) => {
            let _ = writeln!(s, "With the pedestal in series (eq. 9): {e}");
        }
        Some(Ok(kp)) => {
            let p = &a.bearing.input.pedestal.stiffness;
            let show = |i: usize| {
                if p[i] > 0.0 {
                    let q = if i < 3 {
                        Quantity::LinearStiffness
                    } else {
                        Quantity::AngularStiffness
                    };
                    format!("{:.4e}", q.from_si(p[i], units))
                } else {
                    "rigid".to_string()
                }
            };
            let _ = writeln!(
                s,
                "With the pedestal in series (eq. 9; pedestal x {} y {} z {} {} · θx {} θy {} {}):",
                show(0),
                show(1),
                show(2),
                Quantity::LinearStiffness.unit(units),
                show(3),
                show(4),
                Quantity::AngularStiffness.unit(units),
            );
            for i in 0..5 {
                let mut line = format!("  {:<4}", ["F_x", "F_y", "F_z", "M_x", "M_y"][i]);
                for j in 0..5 {
                    let f = unit(i, j);
                    let _ = write!(line, " {:>12.4e}", kp[(i, j)] / f);
                }
                let _ = writeln!(s, "{line}");
            }
        }
    }
    s.lines().map(str::to_string).collect()
}

/// The text report in `units` (US: in, lbf, lbf·in, lbf/in, lbf·in/rad).
pub fn text(a: &Analysis, units: Units) -> String {
    let b = &a.bearing;
    let g = &b.input.geometry;
    let rg = &b.geometry;
    let dy = &b.dynamics;
    let sol = &a.solution;
    let len = |v: f64| Quantity::Length.from_si(v, units);
    let force = |v: f64| Quantity::Force.from_si(v, units);
    let moment = |v: f64| Quantity::Moment.from_si(v, units);
    let (lu, fu, mu) = (
        Quantity::Length.unit(units),
        Quantity::Force.unit(units),
        Quantity::Moment.unit(units),
    );
    let mut s = String::new();
    let _ = writeln!(
        s,
        "ROLLBENCH — tapered roller bearing (seed 004, AFAPL-TR-78-6 Part III): {}",
        a.name
    );
    let _ = writeln!(
        s,
        "n = {}  d = {:.4} {lu}  E = {:.4} {lu}  β = {:.4} deg  l_e = {:.4} {lu}  slices = {}",
        g.roller_count,
        len(g.roller_diameter_m),
        len(g.pitch_diameter_m),
        g.cup_angle_rad.to_degrees(),
        len(g.effective_length_m),
        b.input.solver.slices
    );
    let _ = writeln!(s, "\nRoller geometry");
    let _ = writeln!(
        s,
        "  τ/2 = {:.4} deg  R1 = {:.4} {lu}  R2 = {:.4} {lu}  crown R_c = {:.4} {lu}, drop V = {:.3e} {lu}",
        rg.half_cone_rad.to_degrees(),
        len(rg.r1_m),
        len(rg.r2_m),
        len(rg.crown_radius_m),
        len(rg.crown_drop_m)
    );
    if g.profile == super::input::RollerProfile::Logarithmic {
        let _ = writeln!(
            s,
            "  contact profile: logarithmic, ISO/TS 16281 eq. 44 (0.00045·d·ln[1/(1 − (2x/l_e)²)]); the crown shapes only the end faces"
        );
    }
    let _ = writeln!(
        s,
        "  flange angle α = {:.4} deg  lever arm = {:.4} {lu}  mass = {:.4e} {}  cg offset = {:.4e} {lu}",
        rg.flange_angle_rad.to_degrees(),
        len(rg.flange_lever_arm_m),
        Quantity::Mass.from_si(rg.mass_kg, units),
        Quantity::Mass.unit(units),
        len(rg.cg_offset_m)
    );
    let _ = writeln!(s, "\nSpeeds and inertia loads");
    let _ = writeln!(
        s,
        "  cage {:.2} rad/s  roller spin {:.1} rad/s  F_c = {:.3} {fu}  M_G = {:.4} {mu}",
        dy.cage_rad_s,
        dy.roller_spin_rad_s,
        force(dy.centrifugal_force_n),
        moment(dy.gyroscopic_moment_nm)
    );
    // Ring deflections in µm / µin, as every system's text and the workbench show them
    // (issue 30 item 7: the workbench showed mil, this line inches).
    let defl = crate::bearings::view::Display::Deflection;
    let _ = writeln!(
        s,
        "\nCone displacement (working)  x = {:.3}  y = {:.3}  z = {:.3} {}",
        defl.convert(sol.displacement_m[0], units),
        defl.convert(sol.displacement_m[1], units),
        defl.convert(sol.displacement_m[2], units),
        defl.unit(units)
    );
    let _ = writeln!(
        s,
        "Reactions  Fx = {:.2}  Fy = {:.2}  Fz = {:.2} {fu}   Mx = {:.3}  My = {:.3} {mu} (moments holding the prescribed rotations)",
        force(sol.reaction[0]),
        force(sol.reaction[1]),
        force(sol.reaction[2]),
        moment(sol.reaction[3]),
        moment(sol.reaction[4])
    );
    if let Some(m) = b.input.operating.applied_moment_nm() {
        let _ = writeln!(
            s,
            "Applied moment My = {:.3} {mu}: the cone tilts θy = {:.4e} rad (solved; M_y balanced to {:.1e} {mu})",
            moment(m),
            sol.rotation_rad[1],
            moment((sol.reaction[4] - m).abs())
        );
    }
    // The units of the columns shown (no stress column here: the Rollers pane and the
    // JSON carry max_stress_*; issue 30 item 7).
    let _ = writeln!(s, "\nRollers (P in {fu}, M in {mu})");
    let _ = writeln!(
        s,
        "  {:>3} {:>7} {:>15} {:>10} {:>10} {:>9} {:>9} {:>9} {:>5} {:>5}",
        "#", "ψ deg", "state", "P1 cup", "P2 cone", "P3 flg", "M1", "M2", "edg1", "edg2"
    );
    for (q, (r, _, _)) in sol.rollers.iter().enumerate() {
        let (c, sn) = b.azimuth[q];
        let _ = writeln!(
            s,
            "  {:>3} {:>7.2} {:>15} {:>10.3} {:>10.3} {:>9.3} {:>9.4} {:>9.4} {:>5} {:>5}",
            element_number(q),
            sn.atan2(c).to_degrees().rem_euclid(360.0),
            r.state.as_str(),
            force(r.cup.load_n),
            force(r.cone.load_n),
            force(r.flange_n),
            moment(r.cup.moment_nm),
            moment(r.cone.moment_nm),
            flag_word(r.cup.edge_loaded),
            flag_word(r.cone.edge_loaded),
        );
    }
    let _ = writeln!(s);
    for line in stiffness_lines(a, units) {
        let _ = writeln!(s, "{line}");
    }
    let _ = writeln!(s, "\nDamping: {DAMPING_NOTE}.");
    let life = super::life::life(a);
    s.push_str(&life.text(units));
    if let Some(w) = crate::physics::rating::static_safety_warning(
        crate::physics::rating::ContactKind::Roller,
        life.max_contact_stress_pa,
    ) {
        let _ = writeln!(s, "\nWarning: {w}");
    }
    s.push_str(&lubrication_text(a, units));
    let _ = writeln!(
        s,
        "\nEquilibrium residual {:.3e} {fu} {}; {} distinct roller solves; {:.3} ms",
        force(sol.residual_n),
        if sol.iterations == 0 {
            "at the starting point (no bearing Newton step needed)".to_string()
        } else {
            format!("after {} bearing Newton iterations", sol.iterations)
        },
        sol.unique_rollers,
        a.wall_time_s * 1e3
    );
    s
}

/// The text report's FILM, FRICTION and THERMAL sections in `units` (issue 28 item 6).
fn lubrication_text(a: &Analysis, units: Units) -> String {
    let mut s = String::new();
    let t = match &a.tribology {
        None => {
            let _ = writeln!(s, "\nFilm and friction: {}.", super::life::NO_LUBRICANT);
            return s;
        }
        Some(Err(e)) => {
            let _ = writeln!(s, "\nFilm and friction: not computed: {e}.");
            return s;
        }
        Some(Ok(t)) => t,
    };
    let rough = Quantity::Roughness;
    let (ru, mu, pu) = (
        rough.unit(units),
        Quantity::Moment.unit(units),
        Quantity::Power.unit(units),
    );
    let _ = writeln!(
        s,
        "\nFILM (inlet {:.1} {}, viscosity {:.4e} {})",
        Quantity::Temperature.from_si(a.bearing.input.lubricant.inlet_temperature_k, units),
        Quantity::Temperature.unit(units),
        Quantity::Viscosity.from_si(t.viscosity_pa_s, units),
        Quantity::Viscosity.unit(units)
    );
    for (label, m) in [
        ("thinnest", t.min),
        ("cone raceway", t.min_race[0]),
        ("cup raceway", t.min_race[1]),
    ] {
        match m {
            Some(m) => {
                let _ = writeln!(
                    s,
                    "  {label:<13} h_min = {:.3} {ru}  Λ = {:.2}  at roller {}, {}{}",
                    rough.from_si(m.film_m, units),
                    m.lambda,
                    m.roller + 1,
                    m.contact,
                    if m.contact == "flange" {
                        String::new()
                    } else {
                        format!(" slice {}", m.slice + 1)
                    }
                );
            }
            None => {
                let _ = writeln!(s, "  {label:<13} no loaded contact");
            }
        }
    }
    if let Some(r) = t.rollers.iter().find(|r| r.flange.load_n > 0.0) {
        let f = &r.flange;
        let v = crate::bearings::view::Display::Speed;
        let vu = v.unit(units);
        let _ = writeln!(
            s,
            "  roller end / rib: sliding {:.3} {vu}, entraining {:.3} {vu}, h_min = {:.3} {ru}, Λ = {:.2}, µ = {:.4}, k = {:.3}",
            v.convert(f.sliding_m_s, units),
            v.convert(f.entrainment_m_s, units),
            rough.from_si(f.min_film_m, units),
            f.lambda,
            f.friction_coefficient,
            f.ellipticity
        );
    }
    let f = &t.friction;
    let _ = writeln!(
        s,
        "\nFRICTION  torque {:.4} {mu}  power {:.1} {pu}  at {:.1} rad/s",
        Quantity::Moment.from_si(f.torque_nm, units),
        Quantity::Power.from_si(f.power_w(), units),
        f.relative_speed_rad_s
    );
    for m in &f.mechanisms {
        let _ = writeln!(
            s,
            "  {:<24} {:>12.3} {pu}",
            m.name,
            Quantity::Power.from_si(m.power_w, units)
        );
    }
    match &a.thermal {
        Some(Ok(th)) => {
            let tu = Quantity::Temperature.unit(units);
            let _ = writeln!(
                s,
                "\nTHERMAL (steady; heat in {:.1} {pu}, balance {:.2e} {pu})",
                Quantity::Power.from_si(th.steady.heat_in_w, units),
                Quantity::Power.from_si(th.steady.balance_w, units)
            );
            for n in &th.steady.nodes {
                let _ = writeln!(
                    s,
                    "  {:<16} {:>9.2} {tu}{}",
                    n.name,
                    Quantity::Temperature
                        .from_si(n.temperature_c + crate::units::CELSIUS_ZERO_K, units),
                    if n.fixed { " (fixed)" } else { "" }
                );
            }
            if let Some(tr) = &th.transient {
                for n in &tr.nodes {
                    if let Some(tl) = n.time_to_limit_s {
                        let _ = writeln!(
                            s,
                            "  loss of oil: {} reaches its limit after {tl:.1} s",
                            n.name
                        );
                    }
                }
            }
        }
        Some(Err(e)) => {
            let _ = writeln!(s, "\nTHERMAL: {e}");
        }
        None => {}
    }
    s
}
