//! Diagnostics of a failed or implausible solve: rings that walked apart (no restraint),
//! a roller pitched over in its pocket, and the cause behind a failed roller sweep.

use nalgebra::Vector3;

use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;

/// When the ring Newton fails after the rings have moved more than half a roller diameter
/// apart, the bearing has no equilibrium near its design geometry: typically a pure radial
/// load on an angular-contact bearing whose spherical outer raceway gives no axial restraint
/// (the inner ring walks off axially). Say so, with the numbers, instead of a bare
/// non-convergence.
pub(super) fn unrestrained(b: &Bearing, u: [f64; 2]) -> Option<SolveError> {
    let d = b.geometry.roller_diameter_m;
    if u[0].abs().max(u[1].abs()) <= 0.5 * d {
        return None;
    }
    Some(SolveError::Stage {
        stage: "load distribution (eq. 3.12-3.13)",
        message: format!(
            "no equilibrium near the design geometry: the rings moved {:.3e} m axially and {:.3e} m radially (more than D/2 = {:.3e} m) under F_r = {:.1} N, F_a = {:.1} N at contact angle {:.2} deg; an angular-contact bearing needs an axial load or preload to hold the rings together",
            u[0],
            u[1],
            0.5 * d,
            b.operating.radial_load_n,
            b.operating.axial_load_n,
            b.geometry.contact_angle_rad.to_degrees()
        ),
    })
}

/// Largest roller pitch the model accepts, rad (11.5°). A cage pocket, with clearances of a
/// few tenths of a millimetre over a roller length of centimetres, stops a roller within a
/// few degrees; the model's cage is a soft spring (`solver.cage_stiffness_ratio`) that only
/// positions rollers the raceways leave free. Beyond this pitch a "converged" roller lies
/// across its raceways (contact points at its ends, rolling radii that are no longer a line
/// contact's) and every later stage would report nonsense; found by the stability campaign
/// (an unloaded roller at rest pitched 89°).
const MAX_PITCH_RAD: f64 = 0.2;

/// The typed error for a roller pitched beyond [`MAX_PITCH_RAD`].
pub(super) fn tipped_over(b: &Bearing, qs: &[Vector3<f64>]) -> Option<SolveError> {
    let (j, q) = qs
        .iter()
        .enumerate()
        .max_by(|a, c| a.1[2].abs().total_cmp(&c.1[2].abs()))?;
    pitched(b, j, q)
}

/// The typed error for roller `j` (0-based) at `q` if it is pitched beyond
/// [`MAX_PITCH_RAD`].
fn pitched(b: &Bearing, j: usize, q: &Vector3<f64>) -> Option<SolveError> {
    if q[2].abs() <= MAX_PITCH_RAD {
        return None;
    }
    Some(SolveError::Stage {
        stage: "load distribution (eq. 3.9-3.11)",
        message: format!(
            "roller {} pitched {:.1} deg in its pocket (the model accepts up to {:.1} deg): it is held by neither raceway and the cage, not modelled beyond a soft spring, would stop it; F_r = {:.1} N, F_a = {:.1} N, inner speed {:.1} rpm; a stiffer cage spring (solver.cage_stiffness_ratio, now {:.0e}) may hold it",
            j + 1,
            q[2].to_degrees(),
            MAX_PITCH_RAD.to_degrees(),
            b.operating.radial_load_n,
            b.operating.axial_load_n,
            b.operating.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
            b.solver.cage_stiffness_ratio
        ),
    })
}

/// The cause behind a failed roller sweep at ring deflection `u` with the rollers at `qs`
/// (as the sweep left them): the rings drifted apart (missing restraint), else a roller
/// whose Newton gave up after pitching beyond [`MAX_PITCH_RAD`] — it was lying across its
/// raceways, held by the soft cage spring alone, and that is what the user needs to hear
/// (the campaign's typical "did not converge" roller had pitched 150°) — else `e` itself.
pub(super) fn diagnose(b: &Bearing, u: [f64; 2], qs: &[Vector3<f64>], e: SolveError) -> SolveError {
    if let Some(d) = unrestrained(b, u) {
        return d;
    }
    match e {
        // `roller` is 1-based over the unique rollers, which are rollers 1 … Z/2 + 1.
        SolveError::RollerNotConverged { roller, .. } => roller
            .checked_sub(1)
            .and_then(|j| qs.get(j).map(|q| (j, q)))
            .and_then(|(j, q)| pitched(b, j, q))
            .unwrap_or(e),
        _ => e,
    }
}
