//! Text report: SASHBEAN-like tables, units in the headers.

use std::fmt::Write;

use super::{Disp, ReportUnits};
use crate::solve::pipeline::Analysis;

/// Human-readable report in `units`.
pub fn to_string(a: &Analysis, units: ReportUnits) -> String {
    let d = Disp::of(units);
    let ld = &a.load;
    let b = &a.input;
    let mut s = String::new();
    let _ = writeln!(s, "ROLLBENCH — SASHBEAN lamina analysis: {}", b.name);
    let _ = writeln!(
        s,
        "Z = {}  D = {:.4} {}  P_t = {:.4} {}  beta = {:.2} deg  laminae = {}",
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
        "Speeds: inner {:.0} rpm, outer {:.0} rpm, cage (App. C) {:.0} rpm, roller spin {:.0} rpm",
        b.operating.inner_speed_rad_s * rpm,
        b.operating.outer_speed_rad_s * rpm,
        ld.speeds.cage_rad_s * rpm,
        ld.speeds.roller_spin_rad_s * rpm
    );
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
        "Roller: mass {:.4} kg, centrifugal force {:.2} {}, gyroscopic moment {:.4} {}",
        ld.roller_mass.mass_kg,
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
        "j",
        "phi",
        format!("e_a {}", d.small_len.1),
        format!("e_r {}", d.small_len.1),
        format!("Qi {}", d.force.1),
        format!("Qo {}", d.force.1),
        "bi deg",
        "bo deg",
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
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "Residuals: bearing radial {:.2e} N, axial {:.2e} N; roller force {:.2e} N, moment {:.2e} N·m",
        ld.residuals.bearing_radial_n, ld.residuals.bearing_axial_n, ld.residuals.roller_force_n, ld.residuals.roller_moment_nm
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
