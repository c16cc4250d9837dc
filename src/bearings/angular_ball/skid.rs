//! The skidding threshold (2-4): the lowest relative ring speed at which some ball's
//! gyroscopic moment reaches the friction torque its contacts can supply, found as a
//! root over load solves at other speeds. Apart from the driver (`analysis`): it is a
//! search of its own, with its own samples for the Skid pane.

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::BallInput;
use super::load_conditions::conditions;
use super::load_distribution::{self, Axial, BallLoad, LoadDistribution};
use super::results::{SkidSample, SkidThreshold};
use crate::numerics::cancel::Cancel;

pub(super) fn resisting(mu: f64, geom: &BallGeometry, b: &BallLoad) -> f64 {
    0.5 * mu * geom.ball_diameter_m * (b.equilibrium.inner.load_n + b.equilibrium.outer.load_n)
}

/// Largest |M_g| − resisting moment over the balls, N·m.
#[cfg(test)]
pub(super) fn skid_margin(mu: f64, geom: &BallGeometry, l: &LoadDistribution) -> f64 {
    worst(mu, geom, l).0
}

/// (|M_g| − M_r, |M_g|, M_r) of the ball nearest to skidding, among the balls gripped by
/// both races (Q_i > 0 and Q_o > 0).
///
/// The skidding condition 2-4 compares a ball's gyroscopic moment with the friction
/// torque its two contacts can supply; it is meaningful only for a ball held between
/// the races. Under radial load the balls on the far side may carry no load at rest:
/// there M_g = 0 and M_r = 0, and counting them made the margin 0 ≥ 0 at rest, i.e. a
/// threshold of 0 rpm. A ball with no load is not skidding in the sense of 2-4 (no
/// contact drives it; it is dragged by the cage), and a ball that has lost its inner
/// contact at speed is not in race control either; both are left out. When no ball is
/// held by both races the margin is −∞ (no skidding by 2-4).
fn worst(mu: f64, geom: &BallGeometry, l: &LoadDistribution) -> (f64, f64, f64) {
    l.balls
        .iter()
        .filter(|b| b.equilibrium.inner.load_n > 0.0 && b.equilibrium.outer.load_n > 0.0)
        .map(|b| {
            let (mg, mr) = (b.gyroscopic_moment_nm.abs(), resisting(mu, geom, b));
            (mg - mr, mg, mr)
        })
        .fold(
            (f64::NEG_INFINITY, 0.0, 0.0),
            |a, x| if x.0 > a.0 { x } else { a },
        )
}

/// The relative ring speed of the input, rad/s, and the ring speeds per unit of it.
fn speed_basis(input: &BallInput) -> (f64, f64, f64) {
    let op = &input.operating;
    let rel = (op.inner_speed_rad_s - op.outer_speed_rad_s).abs();
    if rel > 0.0 {
        (rel, op.inner_speed_rad_s / rel, op.outer_speed_rad_s / rel)
    } else {
        (0.0, 1.0, 0.0)
    }
}

/// The skidding threshold (2-4): the lowest relative ring speed at which some ball's
/// gyroscopic moment reaches the resisting torque 0.5·µ_m·D·(Q_i + Q_o), as a root.
///
/// The margin g(n) = max_j(|M_g| − M_r) over the loaded balls (see [`worst`]) is
/// negative at rest; it is sampled every 1/30 of
/// the search limit only to bracket its first sign change, and the root is then solved
/// by the Illinois (modified regula falsi) method to 1e-9 relative in speed. With the
/// preload held as displacement the rest displacement is kept at every speed.
pub fn skid_threshold(
    input: &BallInput,
    geom: &BallGeometry,
    axial: Axial,
    cancel: Cancel,
) -> Result<SkidThreshold, BallError> {
    skid_threshold_streaming(input, geom, axial, cancel, &mut |_| {})
}

/// [`skid_threshold`], calling `on_sample` with every speed solved so far (ascending, as
/// [`SkidThreshold::samples`]) after each load solve: the workbench's Skid pane grows
/// with it. Only reads: the threshold is the same.
pub fn skid_threshold_streaming(
    input: &BallInput,
    geom: &BallGeometry,
    axial: Axial,
    cancel: Cancel,
    on_sample: &mut dyn FnMut(&[SkidSample]),
) -> Result<SkidThreshold, BallError> {
    let mu = input.traction.curve().max_mu();
    let limit = input.dynamics.skid_search_limit_rad_s;
    let mut samples = Vec::new();
    // A search that fails (a load solve at a sampled speed, or a root it cannot isolate)
    // is said in `reason`, never fails the run: the operating point itself solved, and
    // its answer does not depend on the threshold (issue 24, item 13; e.g. a token
    // force-held preload at rest, whose load solve at 500 rpm has no equilibrium).
    // Cancelling still stops the run.
    match search(input, geom, axial, cancel, on_sample, mu, &mut samples) {
        Ok(Found::At(root)) => Ok(SkidThreshold {
            speed_rad_s: Some(root),
            reason: None,
            search_failed: false,
            limit_rad_s: limit,
            evaluations: samples.len(),
            samples,
        }),
        Ok(Found::None) => Ok(SkidThreshold {
            speed_rad_s: None,
            reason: Some(format!(
                "the gyroscopic moment stays below the resisting torque 0.5·µ·D·(Qi+Qo) (µ = {mu}) up to the search limit {:.0} rpm",
                limit * 30.0 / std::f64::consts::PI
            )),
            search_failed: false,
            limit_rad_s: limit,
            evaluations: samples.len(),
            samples,
        }),
        Err(BallError::Cancelled) => Err(BallError::Cancelled),
        Err(e) => Ok(SkidThreshold {
            speed_rad_s: None,
            reason: Some(format!(
                "the search failed, so no threshold is known ({} speeds solved up to the failure; the operating point's results stand): {e}",
                samples.len()
            )),
            search_failed: true,
            limit_rad_s: limit,
            evaluations: samples.len(),
            samples,
        }),
    }
}

const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

/// What the search found: a crossing, or none below the limit.
enum Found {
    At(f64),
    None,
}

/// The search of [`skid_threshold_streaming`], pushing every speed it solves into
/// `samples` (ascending) so that they survive a failure.
fn search(
    input: &BallInput,
    geom: &BallGeometry,
    axial: Axial,
    cancel: Cancel,
    on_sample: &mut dyn FnMut(&[SkidSample]),
    mu: f64,
    samples: &mut Vec<SkidSample>,
) -> Result<Found, BallError> {
    let limit = input.dynamics.skid_search_limit_rad_s;
    let (_, wi, wo) = speed_basis(input);
    let mut g = |n: f64| -> Result<f64, BallError> {
        let mut c = conditions(input, axial, 1.0);
        c.inner_speed_rad_s = wi * n;
        c.outer_speed_rad_s = wo * n;
        // A failed load solve says that it was the search's, and at which speed (the
        // operating point itself solved; the user needs to know which solve did not).
        let l = load_distribution::solve(geom, &c, cancel).map_err(|e| match e {
            BallError::Cancelled => BallError::Cancelled,
            e => BallError::Skid(format!(
                "the load solve at {:.4} rpm (a speed the search sampled) failed: {e}",
                n * 30.0 / std::f64::consts::PI
            )),
        })?;
        let (margin, mg, mr) = worst(mu, geom, &l);
        // Kept ascending in speed as they come (the bracket's samples ascend; the root's
        // iterates fall inside the last bracket): inserted in place, no copy or sort.
        let at = samples.partition_point(|s: &SkidSample| s.0 <= n);
        samples.insert(at, (n, mg, mr));
        on_sample(samples);
        Ok(margin)
    };
    const SAMPLES: usize = 30;
    let mut lo = 0.0;
    let mut g_lo = g(lo)?;
    if g_lo >= 0.0 {
        return Ok(Found::At(0.0));
    }
    for k in 1..=SAMPLES {
        let hi = limit * k as f64 / SAMPLES as f64;
        let g_hi = g(hi)?;
        if g_hi >= 0.0 {
            // Illinois iteration on [lo, hi].
            let (mut a, mut fa, mut b, mut fb) = (lo, g_lo, hi, g_hi);
            let mut side = 0;
            for _ in 0..100 {
                let c = (a * fb - b * fa) / (fb - fa);
                let fc = g(c)?;
                if fc == 0.0 || (b - a).abs() <= 1e-9 * b.abs() {
                    a = c;
                    b = c;
                    break;
                }
                if (fc > 0.0) == (fb > 0.0) {
                    b = c;
                    fb = fc;
                    if side == -1 {
                        fa *= 0.5;
                    }
                    side = -1;
                } else {
                    a = c;
                    fa = fc;
                    if side == 1 {
                        fb *= 0.5;
                    }
                    side = 1;
                }
            }
            let root = 0.5 * (a + b);
            if (b - a).abs() > 1e-6 * root.abs().max(1.0) {
                return Err(BallError::Skid(format!(
                    "root not isolated: bracket [{:.3}, {:.3}] rpm after 100 steps",
                    a * RPM_PER_RAD_S,
                    b * RPM_PER_RAD_S
                )));
            }
            return Ok(Found::At(root));
        }
        lo = hi;
        g_lo = g_hi;
    }
    Ok(Found::None)
}
