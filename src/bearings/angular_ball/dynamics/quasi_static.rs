//! The quasi-static method (`dynamics.method = "quasi-static"`): a ball's angular
//! velocity (and with the free orbit its orbital speed) at fixed loads with dω/dt = 0,
//! solved by a damped Newton iteration from race control. Apart from the time
//! simulation (`simulate`): a different solve of the same model (`model`).

use nalgebra::{DMatrix, DVector, Vector3};

use super::model::BallModel;
use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::input::Orbit;
use crate::bearings::view::element_number;
use crate::physics::lubrication::traction_curve::TractionCurve;

/// The quasi-static angular velocity of a ball at fixed loads: dω/dt = 0 solved by a
/// damped Newton iteration (forward-difference Jacobian) from race control. With
/// [`Orbit::Free`] the orbital balance too (2-14a at rest: Σ rolling traction F_t = 0,
/// solved for ω_m together with ω; the ω_m found is [`quasi_static_state`]'s). Returns
/// ω, the iterations and the right-hand-side evaluations.
pub fn quasi_static_ball(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<([f64; 3], usize, usize), BallError> {
    let (y, it, ev) = quasi_static_state(model, omega0, ball)?;
    Ok(([y[0], y[1], y[2]], it, ev))
}

/// [`quasi_static_ball`]'s whole state: (ω_a, ω_r, ω_t) with the cage's orbit,
/// (ω_a, ω_r, ω_t, ω_m, θ) with the free one (θ the start azimuth, where the loads are).
pub fn quasi_static_state(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<(Vec<f64>, usize, usize), BallError> {
    if let TractionCurve::Constant { mu } = *model.curve {
        return coulomb(model, mu, omega0, ball);
    }
    smooth(model, omega0, ball)
}

/// The first and last regularisation widths u_ε of the Coulomb law, m/s (see
/// [`coulomb`]): Chen's curve 1's 0.2 m/s, and 1e-6 m/s, where a strip inside the band
/// moves the state by about u_ε/R ≈ 2e-4 rad/s of |ω| ≈ 5e3 rad/s.
const COULOMB_WIDTH_START: f64 = 0.2;
const COULOMB_WIDTH_END: f64 = 1e-6;

/// The quasi-static balance with Coulomb friction (`traction.curve = "constant"`).
///
/// With a constant µ each strip's traction −µ·q·s/|s| (2-18) does not depend on how fast
/// it slides, only on the direction, so the moment M(ω) is the negative gradient of the
/// power dissipated, D(ω) = Σ µ q_k |s_k(ω)| (s_k is linear in ω): a convex function
/// with kinks wherever a strip's sliding passes through zero. Newton on M = 0 with the
/// slope dµ/du_s = 0 then sees a Jacobian that is zero in every direction that does not
/// turn a strip's sliding (at race control's start, s_x = 0 on every strip: "singular
/// Jacobian"), and further on jumps across the kinks ("stalled"). The balance still has
/// a solution: the ball settles where the strips' sliding changes sign inside each
/// contact (the rolling bands), so that the friction moments of the two sides, the
/// gyroscopic term of (2-3)/(2-14c, d) and the races balance — the state the time
/// simulation reaches. It is found as the limit of traction laws that rise linearly
/// to µ over a sliding speed u_ε and stay at µ beyond (Chen's curve shapes, Fig. 2-10,
/// with u_m = u_ε): each is a smooth root problem Newton solves, started from the
/// previous width's answer, u_ε falling from 0.2 m/s by a factor 4 (smaller after a
/// width Newton cannot reach) to 1e-6 m/s, or until a width no longer moves the state.
/// Only strips sliding slower than u_ε see a different µ, so the state is that of the
/// constant law to O(u_ε/R) ≈ 2e-4 rad/s (against |ω| ≈ 5e3 rad/s); the heat is the
/// constant law's itself (the caller evaluates the result with the model's own curve).
/// Where µ is large enough the limit is a ball that does not skid sideways (ω_t → 0:
/// the friction holds the gyroscopic moment, 2-4), whose lateral strips stick; the
/// widths then shrink to the end, and with few slices (≤ 11 on Bearing A at µ = 0.2) or
/// µ = 1 Newton stalls at a small width even with shorter steps between widths: that is
/// a typed error naming the width and suggesting the time simulation. Measured against the time simulation's settled
/// answer (40 orbits, 11 slices): heat and ω agree to 1e-9 on Bearing A at µ = 0.054 and
/// Bearing B at 0.054 and 0.2.
///
/// With µ = 0 there is no traction at all: every ω along the axis balances (2-3 with
/// M = 0 leaves J ω̇ = −J ω_m a × ω), and the orbital balance (2-14a) holds at any ω_m.
/// Nothing changes the axial component (J ω̇_a = M_a = 0), so the answer is race
/// control's ω_a with ω_r = ω_t = 0 — the time average of the free precession the time
/// simulation shows — at the cage's speed, with no heat.
fn coulomb(
    model: &BallModel,
    mu: f64,
    omega0: [f64; 3],
    ball: usize,
) -> Result<(Vec<f64>, usize, usize), BallError> {
    let frictionless = [omega0[0], 0.0, 0.0];
    if mu == 0.0 {
        return Ok((model.start_state(frictionless), 0, 0));
    }
    let (mut it, mut ev) = (0, 0);
    let mut omega = omega0;
    let mut orbital = model.cage_rad_s;
    let scale = Vector3::from(omega0).norm().max(1.0);
    let mut width = COULOMB_WIDTH_START;
    // The factor between successive widths: 4, its square root after a width whose
    // Newton fails (started from too far: the law's break point at u_ε sweeps over
    // many strips at once), down to 1.01 before giving up.
    let mut factor: f64 = 4.0;
    let mut solved_once = false;
    loop {
        let curve = TractionCurve::Table {
            points: vec![(0.0, 0.0), (width, mu)],
        };
        // The free orbit starts each width from the previous one's orbital speed.
        let m = BallModel {
            curve: &curve,
            cage_rad_s: match model.orbit {
                Orbit::Cage => model.cage_rad_s,
                Orbit::Free => orbital,
            },
            ..*model
        };
        match smooth(&m, omega, ball) {
            Ok((y, i, e)) => {
                it += i;
                ev += e;
                let moved = (Vector3::new(y[0], y[1], y[2]) - Vector3::from(omega)).norm();
                omega = [y[0], y[1], y[2]];
                if model.orbit == Orbit::Free {
                    orbital = y[3];
                }
                // Done at the last width, or once a width no longer moves the state
                // (every strip then slides faster than u_ε: the constant law's answer
                // itself).
                if width <= COULOMB_WIDTH_END || (solved_once && moved <= 1e-12 * scale) {
                    return Ok((y, it, ev));
                }
                solved_once = true;
                width = (width / factor).max(COULOMB_WIDTH_END);
            }
            Err(BallError::Dynamics(why)) => {
                if !solved_once || factor < 1.01 {
                    return Err(BallError::Dynamics(format!(
                        "{why} (constant traction µ = {mu}, solved as the limit of a law rising to µ over {width:e} m/s; dynamics.method = \"time-simulation\" integrates the same inputs)"
                    )));
                }
                // Back to the last width solved, a smaller step from it.
                let last = width * factor;
                factor = factor.sqrt();
                width = last / factor;
            }
            Err(e) => return Err(e),
        }
    }
}

/// [`quasi_static_state`] for a traction curve with a slope (every curve but the
/// constant one).
fn smooth(
    model: &BallModel,
    omega0: [f64; 3],
    ball: usize,
) -> Result<(Vec<f64>, usize, usize), BallError> {
    match model.orbit {
        Orbit::Cage => {
            let (w, it, ev) = newton(
                |w: &DVector<f64>| {
                    let d = model.omega_dot(0.0, &Vector3::new(w[0], w[1], w[2]));
                    DVector::from_column_slice(d.as_slice())
                },
                DVector::from_column_slice(&omega0),
                ball,
            )?;
            Ok((w.as_slice().to_vec(), it, ev))
        }
        Orbit::Free => {
            // From the held cage's balance (ω at ω_m = the cage's speed), then ω and ω_m
            // together: from race control directly Newton can leave the basin under
            // radial load (Bearing B, 500 N, the most loaded ball: it stalled at a step
            // of 3e6 rad/s).
            let held = BallModel {
                orbit: Orbit::Cage,
                ..*model
            };
            let (w, it0, ev0) = smooth(&held, omega0, ball)?;
            let theta = model.start_azimuth_rad;
            let x0 = DVector::from_column_slice(&[w[0], w[1], w[2], model.cage_rad_s]);
            let (x, it, ev) = newton(
                |x: &DVector<f64>| {
                    let r = model.free_rates(&[x[0], x[1], x[2], x[3], theta]);
                    DVector::from_column_slice(&r[..4])
                },
                x0,
                ball,
            )?;
            Ok((vec![x[0], x[1], x[2], x[3], theta], it0 + it, ev0 + ev))
        }
    }
}

/// Damped Newton on f(x) = 0 (every component a rate in rad/s², so one scale): forward
/// differences of step 1e-7·|x₀|, backtracking on |f| (halving, at most 30 times), done
/// when the step moves x by ≤ 1e-13·|x₀|.
fn newton(
    f: impl Fn(&DVector<f64>) -> DVector<f64>,
    x0: DVector<f64>,
    ball: usize,
) -> Result<(DVector<f64>, usize, usize), BallError> {
    let n = x0.len();
    let mut w = x0;
    let scale = w.norm().max(1.0);
    let mut fw = f(&w);
    let mut evals = 1;
    for it in 1..=100 {
        let mut jac = DMatrix::<f64>::zeros(n, n);
        for c in 0..n {
            let h = 1e-7 * scale;
            let mut wp = w.clone();
            wp[c] += h;
            let fp = f(&wp);
            evals += 1;
            jac.set_column(c, &((fp - &fw) / h));
        }
        let step = jac.lu().solve(&(-&fw)).ok_or_else(|| {
            BallError::Dynamics(format!(
                "ball {}: singular Jacobian of the quasi-static balance at {:?} (rad/s)",
                element_number(ball),
                w.as_slice()
            ))
        })?;
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..30 {
            let wt = &w + lambda * &step;
            let ft = f(&wt);
            evals += 1;
            if ft.norm() < fw.norm() || ft.norm() == 0.0 {
                accepted = Some((wt, ft));
                break;
            }
            lambda *= 0.5;
        }
        let Some((wn, fn_)) = accepted else {
            if (step.norm()) <= 1e-13 * scale {
                return Ok((w, it, evals));
            }
            return Err(BallError::Dynamics(format!(
                "ball {}: quasi-static balance stalled after {it} iterations (|rates| = {:.3e} rad/s², step {:.3e} rad/s)", element_number(ball),
                fw.norm(),
                step.norm()
            )));
        };
        let moved = (&wn - &w).norm();
        w = wn;
        fw = fn_;
        if moved <= 1e-13 * scale {
            return Ok((w, it, evals));
        }
    }
    Err(BallError::Dynamics(format!(
        "ball {}: quasi-static balance did not converge in 100 iterations (|rates| = {:.3e} rad/s²)", element_number(ball),
        fw.norm()
    )))
}
