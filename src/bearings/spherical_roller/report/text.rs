//! Text report: SASHBEAN-like tables, units in the headers.

use std::fmt::Write;

use crate::bearings::spherical_roller::pipeline::Analysis;
use crate::bearings::spherical_roller::view;
use crate::units::Disp;
use crate::units::{Units, FAHRENHEIT_PER_KELVIN};

/// The dynamic-load iterations in the words the stepper uses (issue 30 item 12): all of
/// them, and when a coarse presolve ran first, how many were on it and how many on the
/// deck's laminae (the stepper traces only the latter).
pub fn dynamic_iterations(a: &Analysis) -> String {
    let all = a.speeds.iterations;
    let fine = a.trace_outer.min(all);
    let word = |n: usize| if n == 1 { "iteration" } else { "iterations" };
    if fine == all {
        format!("{all} dynamic-load {}", word(all))
    } else {
        format!(
            "{all} dynamic-load {} ({} coarse on a presolve, {fine} on the deck's laminae)",
            word(all),
            all - fine
        )
    }
}

/// Human-readable report in `units`.
pub fn to_string(a: &Analysis, units: Units) -> String {
    let d = Disp::of(units);
    let ld = &a.load;
    let b = &a.input;
    let mut s = String::new();
    let _ = writeln!(s, "ROLLBENCH — SASHBEAN lamina analysis: {}", b.name);
    for w in super::super::warnings::warnings(a) {
        let _ = writeln!(s, "WARNING: {}", w.text(units));
    }
    let _ = writeln!(
        s,
        "Z = {}  D = {:.4} {}  P_t = {:.4} {}  β = {:.2} deg  laminae = {}",
        b.geometry.roller_count,
        b.geometry.roller_diameter_m * d.len.0,
        d.len.1,
        b.geometry.pitch_diameter_m * d.len.0,
        d.len.1,
        b.geometry.contact_angle_rad.to_degrees(),
        b.solver.laminae
    );
    let rpm = 30.0 / std::f64::consts::PI;
    let _ = writeln!(
        s,
        "Speeds: inner {:.0} rpm, outer {:.0} rpm; cage {:.1} rpm (§7, {} controlling rollers; App. C estimate {:.1} rpm, {:+.2} %); dynamic loads from {:?} speeds after {}",
        b.operating.inner_speed_rad_s * rpm,
        b.operating.outer_speed_rad_s * rpm,
        a.speeds.cage_rpm,
        a.speeds.controlling_rollers,
        a.speeds.cage_rpm_estimate,
        100.0 * a.speeds.cage_difference,
        match b.solver.dynamic_loads {
            super::super::DynamicLoads::Iterated => "iterated (§7)",
            super::super::DynamicLoads::Estimate => "App. C estimated",
        },
        dynamic_iterations(a)
    );
    let _ = rpm;
    let _ = writeln!(
        s,
        "Loads: radial {:.1} {f}, axial {:.1} {f}",
        b.operating.radial_load_n * d.force.0,
        b.operating.axial_load_n * d.force.0,
        f = d.force.1
    );
    let _ = writeln!(
        s,
        "Ring deflections: axial {:.3} {u}, radial {:.3} {u}",
        ld.axial_deflection_m * d.small_len.0,
        ld.radial_deflection_m * d.small_len.0,
        u = d.small_len.1
    );
    let _ = writeln!(
        s,
        "Roller: mass {:.4} {}, centrifugal force {:.2} {}, gyroscopic moment {:.4} {}",
        ld.roller_mass.mass_kg * d.mass.0,
        d.mass.1,
        ld.rollers.first().map_or(0.0, |r| r.centrifugal_force_n) * d.force.0,
        d.force.1,
        ld.rollers.first().map_or(0.0, |r| r.gyroscopic_moment_nm) * d.moment.0,
        d.moment.1
    );
    let _ = writeln!(s);
    let _ = writeln!(s, "ROLLER LOAD DISTRIBUTION");
    let _ = writeln!(
        s,
        "{:>3} {:>7} {:>10} {:>10} {:>10} {:>10} {:>7} {:>7} {:>4} {:>4}",
        "#",
        "ψ deg",
        format!("e_a {}", d.small_len.1),
        format!("e_r {}", d.small_len.1),
        format!("Qi {}", d.force.1),
        format!("Qo {}", d.force.1),
        "αi °",
        "αo °",
        "ni",
        "no"
    );
    for r in &ld.rollers {
        let _ = writeln!(
            s,
            "{:>3} {:>7.1} {:>10.3} {:>10.3} {:>10.1} {:>10.1} {:>7.2} {:>7.2} {:>4} {:>4}",
            r.index,
            r.azimuth_deg,
            r.axial_displacement_m * d.small_len.0,
            r.radial_displacement_m * d.small_len.0,
            r.inner.normal_load_n * d.force.0,
            r.outer.normal_load_n * d.force.0,
            r.inner.contact_angle_deg,
            r.outer.contact_angle_deg,
            r.inner.loaded_laminae,
            r.outer.loaded_laminae
        );
    }
    if a.stresses.is_some() {
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "CONTACT STRESSES, ELLIPSE, SUBSURFACE SHEAR, FILM (§4-5; edge laminae x {:.2})",
            b.life.edge_stress_factor
        );
        let _ = writeln!(
            s,
            "{:>3} {:>4} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
            "#",
            "race",
            format!("σmax {}", d.stress.1),
            format!("σmean {}", d.stress.1),
            format!("2a {}", d.len.1),
            format!("2b {}", d.len.1),
            format!("ecc {}", d.len.1),
            format!("τ {}", d.stress.1),
            format!("z {}", d.small_len.1),
            format!("h {}", d.small_len.1),
            format!("Pe {}", d.force.1)
        );
        for (j, rv) in view::rollers(a).iter().enumerate() {
            for (c, race) in rv.contacts.iter().zip(["in", "out"]) {
                let Some(rs) = c.stress else { continue };
                let h = c
                    .min_film_m
                    .flatten()
                    .map_or("-".to_string(), |h| format!("{:.3}", h * d.small_len.0));
                let pe = c.equivalent_load_n.unwrap_or(0.0);
                let _ = writeln!(
                    s,
                    "{:>3} {:>4} {:>9.1} {:>9.1} {:>9.4} {:>9.5} {:>9.4} {:>9.1} {:>9.1} {:>9} {:>9.1}",
                    j + 1,
                    race,
                    rs.max_stress_pa * d.stress.0,
                    rs.mean_stress_pa * d.stress.0,
                    rs.contact_major_axis_m * d.len.0,
                    rs.contact_minor_axis_m * d.len.0,
                    rs.eccentricity_m * d.len.0,
                    rs.subsurface_shear_pa * d.stress.0,
                    rs.subsurface_depth_m * d.small_len.0,
                    h,
                    pe * d.force.0
                );
            }
        }
        let _ = writeln!(s, "(τ = max principal (Tresca) subsurface shear under the equivalent Hertz ellipse, z its depth)");
    }
    if let Some(l) = &a.life {
        let r = &l.result;
        let opt = |x: Option<f64>| x.map_or("unloaded".to_string(), |v| format!("{v:.4e}"));
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "FATIGUE LIFE (§6, {} lubrication factor)",
            match b.life.method {
                super::super::LifeMethod::Asme => "ASME",
                super::super::LifeMethod::Iso281 => "ISO 281",
            }
        );
        let _ = writeln!(s, "  capacity inner {:.1} {f}, outer {:.1} {f}; mean load inner {:.1} {f}, outer {:.1} {f}", r.capacity_inner_n * d.force.0, r.capacity_outer_n * d.force.0, r.mean_load_inner_n * d.force.0, r.mean_load_outer_n * d.force.0, f = d.force.1);
        let _ = writeln!(
            s,
            "  L-10 inner {} Mrev, outer {} Mrev, bearing {} Mrev ({})",
            opt(r.l10_inner_mrev),
            opt(r.l10_outer_mrev),
            opt(r.l10_bearing_mrev),
            match (r.l10_bearing_h, r.infinite_life_reason) {
                (Some(h), _) => format!("{h:.4e} h"),
                // A loaded bearing whose rings do not turn relative to each other is not
                // "unloaded": its life in hours is infinite, and the report says why.
                (None, Some(why)) => format!("hours {why}"),
                (None, None) => "unloaded h".to_string(),
            }
        );
        let _ = writeln!(s, "  film parameter inner {:.3}, outer {:.3}; lubrication factor inner {:.3}, outer {:.3}; material factor {:.2}", r.lambda_inner, r.lambda_outer, r.lubrication_factor_inner, r.lubrication_factor_outer, r.material_factor);
        let _ = writeln!(
            s,
            "  adjusted L-10 inner {} Mrev, outer {} Mrev, bearing {} Mrev",
            opt(r.adjusted_l10_inner_mrev),
            opt(r.adjusted_l10_outer_mrev),
            opt(r.adjusted_l10_bearing_mrev)
        );
        // Issue 28: ISO 281's numbers beside seed 000's (deck units; `iso_life`).
        let iso = super::super::iso_life::iso_life(a);
        let num =
            |x: Option<f64>, k: f64| x.map_or("—".to_string(), |v| format!("{:.4e}", v * k));
        let _ = writeln!(
            s,
            "  ISO 281: C_r {} {f}, P {} {f}, basic L-10 {} Mrev; kappa {}, e_C {}, a_ISO {}, modified L-10 {} Mrev; ISO 76 C_0r {} {f}",
            num(iso.basic_dynamic_rating_n, d.force.0),
            num(iso.equivalent_load_n, d.force.0),
            num(iso.basic_l10_mrev, 1.0),
            num(iso.kappa, 1.0),
            iso.contamination_factor,
            num(iso.a_iso, 1.0),
            num(iso.modified_l10_mrev, 1.0),
            num(iso.basic_static_rating_n, d.force.0),
            f = d.force.1
        );
        for r in &iso.reasons {
            let _ = writeln!(s, "  note: {r}");
        }
    }
    if let Some(fr) = &a.friction {
        let h = &fr.heat;
        let _ = writeln!(s);
        let _ = writeln!(s, "HEAT GENERATION (§9)");
        let _ = writeln!(
            s,
            "  inner contacts {:.1} {p}, outer contacts {:.1} {p}, cage rails {:.1} {p}, viscous drag {:.1} {p}; total {:.1} {p}; friction torque {:.4} {m}",
            h.inner_contacts_w * d.power.0,
            h.outer_contacts_w * d.power.0,
            h.cage_rails_w * d.power.0,
            h.viscous_drag_w * d.power.0,
            h.total_w * d.power.0,
            h.friction_torque_nm * d.moment.0,
            p = d.power.1,
            m = d.moment.1
        );
    }
    if let Some(th) = &a.thermal {
        let temp = |c: f64| match units {
            Units::Si => format!("{c:.1} °C"),
            Units::Us => format!("{:.1} °F", c * FAHRENHEIT_PER_KELVIN + 32.0),
        };
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "THERMAL NETWORK, STEADY STATE (§10.2): heat in {:.1} {p}, out {:.1} {p}, balance {:.2e} {p}",
            th.steady.heat_in_w * d.power.0,
            th.steady.heat_out_w * d.power.0,
            th.steady.balance_w * d.power.0,
            p = d.power.1
        );
        for n in &th.steady.nodes {
            let _ = writeln!(
                s,
                "  {:<18} {:>10}{}",
                n.name,
                temp(n.temperature_c),
                if n.fixed { "  (fixed)" } else { "" }
            );
        }
        if let Some(tr) = &th.transient {
            let _ = writeln!(
                s,
                "LOSS-OF-OIL TRANSIENT (§10.3): {:.1} {} lost-lubrication heat, {:.0} s simulated",
                th.transient_heat_w.unwrap_or(0.0) * d.power.0,
                d.power.1,
                tr.time_s.last().copied().unwrap_or(0.0)
            );
            for n in tr.nodes.iter().filter(|n| n.limit_c.is_some()) {
                let t = n
                    .time_to_limit_s
                    .map_or("not reached".to_string(), |t| format!("{t:.1} s"));
                let _ = writeln!(
                    s,
                    "  {:<18} limit {:>10}: {}",
                    n.name,
                    temp(n.limit_c.unwrap_or(0.0)),
                    t
                );
            }
        }
    }
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "Residuals: bearing radial {:.2e} {f}, axial {:.2e} {f}; roller force {:.2e} {f}, moment {:.2e} {m}",
        ld.residuals.bearing_radial_n * d.force.0,
        ld.residuals.bearing_axial_n * d.force.0,
        ld.residuals.roller_force_n * d.force.0,
        ld.residuals.roller_moment_nm * d.moment.0,
        f = d.force.1,
        m = d.moment.1
    );
    let _ = writeln!(
        s,
        "Solver: {} ring iterations, {} roller iterations, {} lamina evaluations, {:.3} ms",
        ld.stats.iterations,
        ld.stats.roller_iterations,
        ld.stats.lamina_evaluations,
        ld.stats.wall_time_s * 1e3
    );
    s
}
