//! JSON and text reports of a solved ball bearing (SI; every JSON key names its unit).
//! Fields the race-control method does not compute (the ball dynamics' lateral and
//! rolling heat, integrator statistics) are absent, never filled in.

use serde_json::{json, Value};

use super::analysis::{BallAnalysis, ContactResult};
use super::input::Method;
use super::view::cage_rpm;
use crate::bearings::view::{element_number, flag_word};
use crate::physics::contact::point::Race;
use crate::units::Units;

const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

fn race_name(r: Race) -> &'static str {
    match r {
        Race::Inner => "inner",
        Race::Outer => "outer",
    }
}

fn contact(c: &ContactResult, surfaces: &super::input::Surfaces) -> Value {
    json!({
        "normal_load_n": c.load_n,
        "contact_angle_deg": c.angle_rad.to_degrees(),
        "deflection_m": c.deflection_m,
        "semi_major_m": c.hertz.semi_major_m,
        "semi_minor_m": c.hertz.semi_minor_m,
        "max_pressure_pa": c.hertz.max_pressure_pa,
        "spin_rad_s": c.kinematics.spin_rad_s,
        "roll_rad_s": c.kinematics.roll_rad_s,
        "spin_to_roll": c.kinematics.spin_to_roll,
        "rolling_speed_m_s": c.kinematics.rolling_speed_m_s,
        "spin_moment_nm": c.spin_moment_nm,
        "spin_heat_w": c.spin_heat_w,
        "rolling_resistance_n": c.rolling_resistance_n,
        "rolling_resistance_w": c.rolling_resistance_w,
        "central_film_m": c.central_film_m,
        "min_film_m": c.min_film_m,
        // Λ = h_min/σ (null without surfaces.composite_rms or without a film).
        "lambda": surfaces.lambda(c.min_film_m),
        "film_temperature_rise_c": c.film_temperature_rise_k,
        "surface_temperature_rise_c": c.surface_temperature_rise_k,
    })
}

/// The traction law used: its name, µ_m, the table (for a table or the rheology curve),
/// where a rheology curve was tabulated, and the contacts' sliding band.
fn traction(a: &BallAnalysis) -> Value {
    let t = &a.input.traction;
    let mut v = json!({
        "curve": t.preset.name(),
        "max_mu": t.curve().max_mu(),
    });
    let Some(m) = v.as_object_mut() else {
        return v;
    };
    if let crate::physics::lubrication::traction_curve::TractionCurve::Table { points } = t.curve()
    {
        m.insert(
            "points".into(),
            json!(points
                .iter()
                .map(|p| json!({"sliding_m_s": p.0, "mu": p.1}))
                .collect::<Vec<_>>()),
        );
    }
    if let Some((lo, hi)) = super::analysis::sliding_band(a) {
        m.insert("sliding_band_m_s".into(), json!([lo, hi]));
    }
    if let Some(rc) = &a.rheology_contact {
        m.insert(
            "rheology_contact".into(),
            json!({
                "ball": rc.ball,
                "race": race_name(rc.race),
                "max_pressure_pa": rc.strip.max_pressure_pa,
                "rolling_semi_axis_m": rc.strip.semi_width_m,
                "film_m": rc.strip.film_m,
                "rolling_speed_m_s": rc.strip.rolling_speed_m_s,
                "inlet_temperature_c": rc.strip.inlet_temperature_k - 273.15,
            }),
        );
    }
    v
}

/// The JSON report (issue 16's contract).
pub fn json(a: &BallAnalysis) -> Value {
    let balls: Vec<Value> = a
        .balls
        .iter()
        .enumerate()
        .map(|(j, b)| {
            json!({
                "index": j,
                "number": element_number(j),
                "azimuth_deg": b.azimuth_rad.to_degrees(),
                "centrifugal_force_n": b.centrifugal_n,
                "gyroscopic_moment_nm": b.gyroscopic_moment_nm,
                "resisting_moment_nm": b.resisting_moment_nm,
                "skidding": b.skidding,
                "heat_w": b.heat_w,
                "cage_rpm": b.cage_rad_s * RPM_PER_RAD_S,
                "controlling_race": race_name(b.control),
                "inner": contact(&b.inner, &a.input.surfaces),
                "outer": contact(&b.outer, &a.input.surfaces),
            })
        })
        .collect();
    let n = a.balls.len().max(1) as f64;
    let control = a
        .balls
        .first()
        .map(|b| race_name(b.control))
        .unwrap_or("outer");
    let mut skid = json!({
        "threshold_rpm": a.skid.speed_rad_s.map(|s| s * RPM_PER_RAD_S),
        "search_limit_rpm": a.skid.limit_rad_s * RPM_PER_RAD_S,
        "traction_coefficient": a.input.traction.curve().max_mu(),
        "evaluations": a.skid.evaluations,
        "curve": a.skid.samples.iter().map(|s| json!({
            "speed_rpm": s.0 * RPM_PER_RAD_S,
            "gyroscopic_moment_nm": s.1,
            "resisting_moment_nm": s.2,
        })).collect::<Vec<_>>(),
    });
    if let (Some(reason), Some(m)) = (&a.skid.reason, skid.as_object_mut()) {
        m.insert("reason".into(), json!(reason));
    }
    let mut heat = json!({
        "total_w": a.total_heat_w,
        "per_ball_w": a.total_heat_w / n,
        "race_control_w": a.race_control_heat_w,
        "bulk_temperature_c": a.bulk_temperature_k - 273.15,
    });
    let mut dynamics = json!({
        "method": a.input.dynamics.method.name(),
        // How each ball's orbital speed is found: "free" (2-14a integrated) or "cage".
        "orbit": a.input.dynamics.orbit.name(),
    });
    let mut balls = balls;
    if let Some(d) = &a.dynamics {
        if let Some(h) = heat.as_object_mut() {
            h.insert("lateral_w".into(), json!(d.lateral_w()));
            h.insert("rolling_w".into(), json!(d.rolling_w()));
        }
        if let Some(m) = dynamics.as_object_mut() {
            m.insert("integrator".into(), json!(d.integrator));
            m.insert("steps".into(), json!(d.steps));
            m.insert("rhs_evaluations".into(), json!(d.rhs_evaluations));
            m.insert("steady".into(), json!(d.steady));
            // rad/s: half the peak-to-peak of the most varying ω component over the
            // last orbit, largest over the balls.
            m.insert(
                "oscillation_amplitude".into(),
                json!(d.oscillation_amplitude_rad_s),
            );
            m.insert(
                "oscillation_amplitude_rad_s".into(),
                json!(d.oscillation_amplitude_rad_s),
            );
            m.insert("slices".into(), json!(a.input.dynamics.slices));
            m.insert("orbits".into(), json!(a.input.dynamics.orbits));
            if a.input.dynamics.method == Method::TimeSimulation {
                // The history (`run --series`) is bounded (issue 24): before each ball's
                // last orbit one sample in `sample_every` is kept (1: all of them).
                m.insert(
                    "series_decimation".into(),
                    json!({
                        "sample_every": d.series_sample_every,
                        "samples_per_orbit": super::dynamics::budget::SAMPLES_PER_ORBIT,
                        "last_orbit_whole": true,
                        "max_rows": super::dynamics::budget::MAX_SERIES_ROWS,
                    }),
                );
            }
            // The balls' orbital speed (last-orbit mean, averaged over the balls): with
            // the free orbit the speed the cage would follow; held, race control's.
            let wm =
                d.balls.iter().map(|b| b.orbital_rad_s).sum::<f64>() / d.balls.len().max(1) as f64;
            m.insert("mean_orbital_rad_s".into(), json!(wm));
        }
        for (b, bd) in balls.iter_mut().zip(&d.balls) {
            let last = bd.history.last().map(|s| s.omega_rad_s);
            if let Some(m) = b.as_object_mut() {
                m.insert(
                    "dynamics".into(),
                    json!({
                        "heat_w": bd.heat_w,
                        "lateral_w": bd.lateral_w,
                        "rolling_w": bd.rolling_w,
                        "omega_rad_s": last,
                        "oscillation_amplitude_rad_s": bd.oscillation_rad_s,
                        // ω_m: the last orbit's mean (time simulation) or the solved
                        // balance (quasi-static); race control's cage speed when held.
                        "orbital_rad_s": bd.orbital_rad_s,
                    }),
                );
            }
        }
    }
    json!({
        "type": super::SYSTEM_ID,
        "rings": {
            "axial_deflection_m": a.load.axial_deflection_m,
            "radial_deflection_m": a.load.radial_deflection_m,
            "axial_force_n": a.load.axial_force_n,
            "radial_force_n": a.load.radial_force_n,
            "rest_axial_deflection_m": a.rest_axial_deflection_m,
            // Issue 29: the tilt about the axis across the radial load (held at
            // operating.misalignment, or solved against operating.moment) and the moment
            // the balls carry about it. The loads lie in one plane, so the components
            // about the other axis are zero and not written.
            "tilt_rad": a.load.tilt_rad,
            "moment_nm": a.load.moment_nm,
        },
        "stiffness": stiffness_json(a),
        "balls": balls,
        "traction": traction(a),
        "speeds": {
            "cage_rpm": cage_rpm(a),
            "ball_spin_rad_s": a.balls.iter().map(|b| b.ball_spin_rad_s).sum::<f64>() / n,
            "controlling_race": control,
        },
        "skid": skid,
        "heat": heat,
        // Issue 28: the same heat by mechanism and race, with the friction torque.
        "friction": super::friction::friction(a).json(),
        "dynamics": dynamics,
        // Issue 28: reference and ISO 281 lives, static safety (`life.static_safety`).
        "life": super::life::life(a).json(),
        // Results beyond the validity of the model: sentences with their numbers (SI).
        "warnings": super::warnings::warnings(a).into_iter().map(|w| w.si).collect::<Vec<_>>(),
        "residuals": {
            "ring_force_n": a.load.ring_residual_n,
            "ball_force_n": a.load.ball_residual_n,
        },
        "stats": {
            "fixed_point_iterations": a.load.stats.fixed_point_iterations,
            "ring_iterations": a.load.stats.ring_iterations,
            "ring_evaluations": a.load.stats.ring_evaluations,
            "skid_load_solves": a.skid.evaluations,
        },
    })
}

/// The text report, in the seed's terms (SI; US decks get the same SI tables with a note).
pub fn text(a: &BallAnalysis, units: Units) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let g = &a.geometry;
    let op = &a.input.operating;
    let _ = writeln!(
        s,
        "ANGULAR-CONTACT BALL BEARING — race-control analysis (seed 001, Chen 1989)"
    );
    if units == Units::Us {
        let _ = writeln!(s, "(values in SI)");
    }
    for w in super::warnings::warnings(a) {
        let _ = writeln!(s, "WARNING: {}", w.text(Units::Si));
    }
    let _ = writeln!(
        s,
        "Z = {}  D = {:.3} mm  d_m = {:.3} mm  f_i = {}  f_o = {}  α₀ = {:.2}°  P_d = {:.4} mm",
        g.ball_count,
        g.ball_diameter_m * 1e3,
        g.pitch_diameter_m * 1e3,
        g.inner_groove_curvature,
        g.outer_groove_curvature,
        g.free_contact_angle_rad.to_degrees(),
        g.diametral_clearance_m * 1e3
    );
    let _ = writeln!(
        s,
        "inner ring {:.0} rpm, outer ring {:.0} rpm, axial load {:.1} N ({}), radial load {:.1} N",
        op.inner_speed_rad_s * RPM_PER_RAD_S,
        op.outer_speed_rad_s * RPM_PER_RAD_S,
        op.axial_load_n,
        match op.preload_mode {
            super::input::PreloadMode::Displacement => "held as the displacement at rest",
            super::input::PreloadMode::Force => "held as a force",
        },
        op.radial_load_n
    );
    let _ = writeln!(
        s,
        "\nRINGS  δa = {:.4} µm  δr = {:.4} µm  Fa = {:.1} N  Fr = {:.1} N",
        a.load.axial_deflection_m * 1e6,
        a.load.radial_deflection_m * 1e6,
        a.load.axial_force_n,
        a.load.radial_force_n
    );
    if a.load.tilt_rad != 0.0 || a.input.operating.moment_nm.is_some() {
        let _ = writeln!(
            s,
            "       θ = {:.6e} rad  M = {:.3} N·m ({})",
            a.load.tilt_rad,
            a.load.moment_nm,
            if a.input.operating.moment_nm.is_some() {
                "tilt solved against operating.moment"
            } else {
                "tilt held at operating.misalignment"
            }
        );
    }
    let _ = writeln!(
        s,
        "\nLOAD DISTRIBUTION\n  #   ψ°     Qi N    αi°     Qo N    αo°   ai mm   bi mm   ao mm   bo mm   Fc N   Mg N·m   Mr N·m  skid"
    );
    for (j, b) in a.balls.iter().enumerate() {
        let _ = writeln!(
            s,
            "{:3} {:5.1} {:8.2} {:6.2} {:8.2} {:6.2} {:7.4} {:7.4} {:7.4} {:7.4} {:6.2} {:8.4} {:8.4}  {}",
            element_number(j),
            b.azimuth_rad.to_degrees(),
            b.inner.load_n,
            b.inner.angle_rad.to_degrees(),
            b.outer.load_n,
            b.outer.angle_rad.to_degrees(),
            b.inner.hertz.semi_major_m * 1e3,
            b.inner.hertz.semi_minor_m * 1e3,
            b.outer.hertz.semi_major_m * 1e3,
            b.outer.hertz.semi_minor_m * 1e3,
            b.centrifugal_n,
            b.gyroscopic_moment_nm,
            b.resisting_moment_nm,
            flag_word(b.skidding)
        );
    }
    let _ = writeln!(
        s,
        "\nRACE CONTROL ({} race controls)\n  #  cage rpm  ωsi rad/s  ωso rad/s  ωri rad/s  ωro rad/s  s/r i   s/r o   u i m/s  u o m/s  H W   hc,i µm hc,o µm",
        a.balls.first().map(|b| race_name(b.control)).unwrap_or("outer")
    );
    for (j, b) in a.balls.iter().enumerate() {
        let (i, o) = (&b.inner, &b.outer);
        let _ = writeln!(
            s,
            "{:3} {:8.1} {:10.2} {:10.2} {:10.1} {:10.1} {:7.4} {:7.4} {:8.3} {:8.3} {:6.3} {:7.3} {:7.3}",
            element_number(j),
            b.cage_rad_s * RPM_PER_RAD_S,
            i.kinematics.spin_rad_s,
            o.kinematics.spin_rad_s,
            // The roll speeds ω_r (rad/s; issue 30 item 7: the header said "roll i"
            // with no unit).
            i.kinematics.roll_rad_s,
            o.kinematics.roll_rad_s,
            i.kinematics.spin_to_roll,
            o.kinematics.spin_to_roll,
            i.kinematics.rolling_speed_m_s,
            o.kinematics.rolling_speed_m_s,
            // Race control's spin heat (2-7), not `b.heat_w`, which a dynamics method
            // replaces by its own (issue 30 item 4: the column read 52.863 W, the
            // time-simulated heat, where race control gives 12.244 W).
            i.spin_heat_w + o.spin_heat_w,
            i.central_film_m.unwrap_or(0.0) * 1e6,
            o.central_film_m.unwrap_or(0.0) * 1e6,
        );
    }
    let _ = writeln!(
        s,
        "\nHEAT  total {:.2} W, {:.3} W per ball; bulk temperature {:.1} °C (eq. 4-1)",
        a.total_heat_w,
        a.total_heat_w / a.balls.len().max(1) as f64,
        a.bulk_temperature_k - 273.15
    );
    let curve = a.input.traction.curve();
    let hottest = |f: fn(&super::analysis::BallResult) -> Option<f64>| {
        a.balls.iter().filter_map(f).fold(0.0, f64::max)
    };
    let _ = writeln!(
        s,
        "TRACTION  {}: µ_max {:.4}{}; film temperature rise (4-3…4-7) up to {:.1} K inner, {:.1} K outer",
        a.input.traction.preset.name(),
        curve.max_mu(),
        match super::analysis::sliding_band(a) {
            Some((lo, hi)) => format!("; contacts slide {lo:.3}–{hi:.3} m/s"),
            None => String::new(),
        },
        hottest(|b| b.inner.film_temperature_rise_k),
        hottest(|b| b.outer.film_temperature_rise_k),
    );
    if let Some(rc) = &a.rheology_contact {
        let _ = writeln!(
            s,
            "  rheology curve ({:?}) tabulated at ball {} {}: p₀ {:.3} GPa, b {:.4} mm, h {:.3} µm, V {:.2} m/s",
            a.input.lubricant.viscosity_model,
            element_number(rc.ball),
            race_name(rc.race),
            rc.strip.max_pressure_pa * 1e-9,
            rc.strip.semi_width_m * 1e3,
            rc.strip.film_m * 1e6,
            rc.strip.rolling_speed_m_s
        );
    }
    if let Some(d) = &a.dynamics {
        let _ = writeln!(
            s,
            "\nBALL DYNAMICS ({}, {} orbit, {} slices per contact, {}): {} steps, {} rhs evaluations, {}",
            d.method.name(),
            a.input.dynamics.orbit.name(),
            a.input.dynamics.slices,
            d.integrator,
            d.steps,
            d.rhs_evaluations,
            if d.steady {
                "steady".to_string()
            } else {
                format!(
                    "oscillating (amplitude {:.3} rad/s)",
                    d.oscillation_amplitude_rad_s
                )
            }
        );
        let _ = writeln!(
            s,
            "  #   ψ°    ωa rad/s   ωr rad/s   ωt rad/s   H W   lateral W rolling W  race-control W  ωm rad/s"
        );
        for (j, (b, bd)) in a.balls.iter().zip(&d.balls).enumerate() {
            let w = bd.history.last().map(|s| s.omega_rad_s).unwrap_or([0.0; 3]);
            let _ = writeln!(
                s,
                "{:3} {:5.1} {:10.2} {:10.2} {:10.2} {:7.3} {:9.3} {:9.3} {:9.3} {:15.3}",
                element_number(j),
                b.azimuth_rad.to_degrees(),
                w[0],
                w[1],
                w[2],
                bd.heat_w,
                bd.lateral_w,
                bd.rolling_w,
                b.inner.spin_heat_w + b.outer.spin_heat_w,
                bd.orbital_rad_s
            );
        }
        let _ = writeln!(
            s,
            "  heat {:.2} W = {:.2} W lateral + {:.2} W rolling (race control: {:.2} W)",
            d.total_w(),
            d.lateral_w(),
            d.rolling_w(),
            a.race_control_heat_w
        );
    }
    match a.skid.speed_rad_s {
        Some(n) => {
            let _ = writeln!(
                s,
                "SKIDDING THRESHOLD  {:.0} rpm (M_g = 0.5·µ·D·(Qi+Qo))",
                n * RPM_PER_RAD_S
            );
        }
        None => {
            let _ = writeln!(
                s,
                "SKIDDING THRESHOLD  {}: {}",
                if a.skid.search_failed {
                    "not found"
                } else {
                    "none"
                },
                a.skid.reason.as_deref().unwrap_or("")
            );
        }
    }
    s.push_str(&super::life::life(a).text());
    s
}

/// The time history of the time simulation as CSV (`run --series FILE`, issue 16): one
/// row per ball and recorded time (90 per orbit, the dense output of the integrator),
/// SI with the unit in every column name — time, ball (the JSON's `balls[].index`), azimuth (wrapped to [0, 360)° and
/// unwrapped as the orbit travelled), the ball's angular velocity in the cage frame
/// (axial, radial, tangential: the frame of `dynamics`), and the heat of both contacts
/// with its lateral and rolling-direction parts, then (added last, so the columns before
/// keep their places) the ball's orbital speed ω_m. Only the time simulation has a
/// history: any other `dynamics.method` is refused with the key to set. A history
/// decimated to its bound (`dynamics.series_decimation` in the JSON) starts with a `#`
/// comment line saying so; an undecimated one has none.
pub fn series_csv(a: &BallAnalysis) -> Result<String, String> {
    let method = a.input.dynamics.method;
    let d = match (&a.dynamics, method) {
        (Some(d), Method::TimeSimulation) => d,
        _ => {
            return Err(format!(
                "no time history: dynamics.method = \"{}\" does not simulate the balls in time; set dynamics.method = \"time-simulation\" (e.g. --set dynamics.method=time-simulation)",
                method.name()
            ))
        }
    };
    let mut out = String::new();
    if d.series_sample_every > 1 {
        out.push_str(&format!(
            "# decimated: 1 sample in {} (of {} per orbit) kept before each ball's last orbit (whole), to keep at most {} rows; dynamics.series_decimation in the JSON report\n",
            d.series_sample_every,
            super::dynamics::budget::SAMPLES_PER_ORBIT,
            super::dynamics::budget::MAX_SERIES_ROWS
        ));
    }
    out.push_str(
        "time_s,ball,azimuth_deg,orbit_deg,omega_axial_rad_s,omega_radial_rad_s,omega_tangential_rad_s,heat_w,lateral_heat_w,rolling_heat_w,omega_orbital_rad_s\n",
    );
    for (j, b) in d.balls.iter().enumerate() {
        for s in &b.history {
            let w = s.omega_rad_s;
            out.push_str(&format!(
                "{:e},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e}\n",
                s.time_s,
                j,
                s.orbit_deg.rem_euclid(360.0),
                s.orbit_deg,
                w[0],
                w[1],
                w[2],
                s.heat_w,
                s.lateral_w,
                s.rolling_w,
                s.orbital_rad_s
            ));
        }
    }
    Ok(out)
}

/// The JSON `stiffness` object on the shared type (issue 29): `matrix` (rows of `rows`,
/// columns of `columns`, SI), `units`, `method`, `reference_point`, and with
/// `solver.stiffness = "both"` the finite-difference matrix and
/// `finite_difference_max_rel`; the ball's own `held` beside them.
fn stiffness_json(a: &BallAnalysis) -> Value {
    let mut v = a.stiffness.shared().json();
    if let Some(o) = v.as_object_mut() {
        o.insert("held".into(), json!(super::stiffness::HELD));
    }
    v
}

/// The stiffness matrix in `units` (rows F_x … M_y, columns x … θ_y) and the
/// finite-difference check: the view's "stiffness" text block (`rollbench stiffness`),
/// the shared printer's.
pub fn stiffness_lines(a: &BallAnalysis, units: Units) -> Vec<String> {
    a.stiffness.shared().lines(units)
}
