//! "Converged means converged" (issue 14): the checks run on a load distribution after the
//! solver has declared it converged, and the rewording of its messages where the solver's
//! generic text does not describe the case.
//!
//! The load-distribution solver scales its tolerance by a reference force that includes
//! Z·CF and M/l_ref and accepts up to 10³ times it when its line search stalls; at high
//! speed or with a loose `solver.force_tolerance` that can leave a ring residual as large
//! as the applied load. [`check_residuals`] holds every solve to the deck's tolerance
//! *relative to the applied load*, with a floor at round-off level of the solver's
//! reference force.

use super::load_distribution::LoadDistribution;
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;

/// Round-off floor of the residual check, relative to the solver's reference force (the
/// largest of the applied loads, Z·CF and M/l_ref): a residual below it is round-off of
/// forces that large, whatever the tolerance asked.
pub const ROUND_OFF: f64 = 1e-10;

/// The applied load a residual is judged against: the larger of |F_a| and |F_r|, at
/// least 1 N.
pub fn applied_load_n(b: &Bearing) -> f64 {
    b.operating
        .axial_load_n
        .abs()
        .max(b.operating.radial_load_n.abs())
        .max(1.0)
}

/// The largest residual a converged solve of `b` may leave, N: the deck's relative
/// tolerance times the applied load, or the round-off floor when larger.
pub fn allowed_residual_n(b: &Bearing, ld: &LoadDistribution) -> f64 {
    let l_ref = 0.5 * b.geometry.effective_length_m;
    let (cf, gm) = ld.rollers.first().map_or((0.0, 0.0), |r| {
        (r.centrifugal_force_n, r.gyroscopic_moment_nm)
    });
    let f_ref = applied_load_n(b)
        // Every roller of every row (a multi-row layout lists them all).
        .max(ld.rollers.len().max(b.geometry.roller_count) as f64 * cf.abs())
        .max(if l_ref > 0.0 { gm.abs() / l_ref } else { 0.0 });
    (b.solver.force_tolerance * applied_load_n(b)).max(ROUND_OFF * f_ref)
}

/// Checks that a solve the solver declared converged meets the deck's tolerance on the
/// bearing (axial and radial ring force) and on every roller (forces, and moment over half
/// the effective length), relative to the applied load. A larger residual, or a solve not
/// marked converged, is a [`SolveError::ResidualAboveTolerance`] with the numbers.
pub fn check_residuals(b: &Bearing, ld: &LoadDistribution) -> Result<(), SolveError> {
    let allowed = allowed_residual_n(b, ld);
    let l_ref = (0.5 * b.geometry.effective_length_m).max(f64::MIN_POSITIVE);
    let r = &ld.residuals;
    let checks = [
        ("bearing axial force", r.bearing_axial_n),
        ("bearing radial force", r.bearing_radial_n),
        ("roller force", r.roller_force_n),
        ("roller moment / (l/2)", r.roller_moment_nm / l_ref),
    ];
    for (what, residual_n) in checks {
        if residual_n.is_nan() || residual_n > allowed || !ld.converged {
            return Err(SolveError::ResidualAboveTolerance {
                what,
                residual_n,
                allowed_n: allowed,
                applied_n: applied_load_n(b),
                force_tolerance: b.solver.force_tolerance,
            });
        }
    }
    Ok(())
}

/// The solver's "no equilibrium near the design geometry" message ends with advice for an
/// angular-contact bearing without axial load; for a zero-contact-angle bearing carrying
/// an axial load the case is the opposite. Rewords it to describe the actual case.
pub fn describe_case(b: &Bearing, e: SolveError) -> SolveError {
    const ADVICE: &str =
        "an angular-contact bearing needs an axial load or preload to hold the rings together";
    match e {
        SolveError::Stage { stage, message } if message.contains(ADVICE) => {
            let alpha = b.geometry.contact_angle_rad;
            let fa = b.operating.axial_load_n;
            let advice = if alpha.abs() < 1e-6 && fa.abs() > 0.0 {
                format!(
                    "a bearing with zero contact angle cannot carry the axial load of {fa:.1} N \
                     (its raceways give it no axial restraint): reduce the axial load or give \
                     the bearing a contact angle"
                )
            } else if fa.abs() > 0.0 {
                format!(
                    "an angular-contact bearing needs more axial load or preload than \
                     {fa:.1} N to hold the rings together under these loads and speed"
                )
            } else {
                ADVICE.to_string()
            };
            SolveError::Stage {
                stage,
                message: message.replace(ADVICE, &advice),
            }
        }
        other => other,
    }
}
