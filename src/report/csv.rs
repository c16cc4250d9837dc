//! CSV report: one row per roller, SI units in the header.

use crate::bearings::spherical_roller::pipeline::Analysis;

/// CSV text with a header line.
pub fn to_string(a: &Analysis) -> String {
    let mut s = String::from(
        "index,azimuth_deg,axial_displacement_m,radial_displacement_m,tilt_rad,centrifugal_force_n,gyroscopic_moment_nm,inner_normal_load_n,inner_contact_angle_deg,inner_loaded_laminae,outer_normal_load_n,outer_contact_angle_deg,outer_loaded_laminae\n",
    );
    for r in &a.load.rollers {
        s.push_str(&format!(
            "{},{},{:e},{:e},{:e},{:e},{:e},{:e},{},{},{:e},{},{}\n",
            r.index,
            r.azimuth_deg,
            r.axial_displacement_m,
            r.radial_displacement_m,
            r.tilt_rad,
            r.centrifugal_force_n,
            r.gyroscopic_moment_nm,
            r.inner.normal_load_n,
            r.inner.contact_angle_deg,
            r.inner.loaded_laminae,
            r.outer.normal_load_n,
            r.outer.contact_angle_deg,
            r.outer.loaded_laminae
        ));
    }
    s
}
