//! The spherical roller bearing's stiffness matrix on the shared type (issue 29 item 3):
//! 5×5 over (x, y, z, θ_x, θ_y), SI, at the operating point with the centrifugal force
//! and gyroscopic moment of the solve (the load distribution's
//! [`stiffness`](super::load_distribution::stiffness) module holds the mechanics).
//!
//! # Why the tilt rows and columns are zero
//! The outer raceway is a sphere centred on the bearing axis: the inner ring with its
//! rollers turns about that centre without changing any contact (the bearing is
//! self-aligning), so a tilt meets no moment and a moment finds no stiffness. A rotor
//! model sees the bearing as a pinned support. The tilts are reported as rows and columns
//! of exact zeros (a 5×5 a rotordynamics user drops into a 5-DOF shaft element unchanged)
//! with that reason in `notes`, and the displacements are referred to the sphere's centre,
//! where the translations and tilts do not couple.

use super::load_distribution::stiffness::{
    assemble_xyz, fd_step, finite_difference, max_rel, plane_stiffnesses,
};
use super::load_distribution::{Layout, LoadDistribution};
use super::Bearing;
use crate::bearings::stiffness::{Dof, Method, StiffnessMatrix};
use crate::bearings::SolveError;

/// Why θ_x and θ_y carry no stiffness (the JSON `notes`, the text's last lines).
pub const TILT_NOTE: &str = "θx, θy: zero stiffness by construction: the outer raceway is a sphere, so the inner ring and rollers turn about its centre without loading any contact (self-aligning; a rotor model sees a pinned support)";

/// Where the displacements are referred to.
pub const REFERENCE_POINT: &str = "centre of the outer raceway's sphere on the bearing axis (x along the radial load, z along the axial load)";

/// The 5×5 of a solved load distribution `ld` of `b` (rows `layout`), by
/// `b.solver.stiffness`.
///
/// # Errors
/// A roller that does not converge at a displaced ring in the finite differences, or
/// `ld` without one state per unique roller ([`SolveError`]).
pub fn stiffness(
    b: &Bearing,
    layout: Layout,
    ld: &LoadDistribution,
) -> Result<StiffnessMatrix, SolveError> {
    let guided = layout.guide.is_some();
    let planes = plane_stiffnesses(b, layout, ld)?;
    let sum = assemble_xyz(&planes);
    // The x–z block as the ring Newton computed it (the same sum, test
    // `xz_block_is_the_ring_jacobian`; with a floating guide ring it also has the guide's
    // offset condensed out, which the sum holds).
    let mut an = sum;
    if let Some(inertial) = &ld.warm.inertial {
        let r = inertial.ring_stiffness_n_m(); // (axial, radial)
        an[(0, 0)] = r[1][1];
        an[(0, 2)] = r[1][0];
        an[(2, 0)] = r[0][1];
        an[(2, 2)] = r[0][0];
    }
    let method = b.solver.stiffness;
    let h = fd_step(ld);
    let fd = if method.wants_fd() {
        Some(finite_difference(b, layout, ld, h)?)
    } else {
        None
    };
    let five = |m: &nalgebra::Matrix3<f64>| -> Vec<f64> {
        let mut k = vec![0.0; 25];
        for i in 0..3 {
            for j in 0..3 {
                k[i * 5 + j] = m[(i, j)];
            }
        }
        k
    };
    let reported = match (method, &fd) {
        (Method::FiniteDifference, Some(f)) => five(f),
        _ => five(&an),
    };
    let mut k = StiffnessMatrix::new(Dof::ALL.to_vec(), reported, method);
    k.reference_point = Some(REFERENCE_POINT.to_string());
    // Conservative (the rollers' contact laws have a potential, the solve minimises it):
    // symmetric to round-off; reported so a reader sees it.
    k.asymmetry_max = Some(asymmetry(&an));
    k.notes.push(TILT_NOTE.to_string());
    if guided {
        k.notes.push(
            "x-z block: the floating guide ring's offset condensed out (the ring solve's Jacobian); y and the finite differences hold it at the operating point (a y displacement does not move it to first order)"
                .to_string(),
        );
    }
    if let Some(f) = &fd {
        k.fd = Some(five(f));
        if method == Method::Both {
            // Against the sum, which holds what the differences hold.
            k.fd_max_rel = Some(max_rel(&sum, f));
        }
        k.notes.push(format!(
            "finite differences: central, step {h:.3e} m (1e-6 of the larger ring deflection), every roller re-solved at its own azimuth"
        ));
    }
    Ok(k)
}

/// Largest |K_ij − K_ji| over √(|K_ii K_jj|).
fn asymmetry(k: &nalgebra::Matrix3<f64>) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..3 {
        for j in 0..i {
            let scale = (k[(i, i)] * k[(j, j)]).abs().sqrt();
            if scale > 0.0 {
                worst = worst.max((k[(i, j)] - k[(j, i)]).abs() / scale);
            }
        }
    }
    worst
}

#[cfg(test)]
#[path = "stiffness_tests.rs"]
mod tests;
