//! The quasi-static method (`dynamics.method = "quasi-static"`): a ball's angular
//! velocity (and with the free orbit its orbital speed) at fixed loads with dω/dt = 0,
//! solved by a damped Newton iteration from race control. Apart from the time
//! simulation (`simulate`): a different solve of the same model (`model`).

use nalgebra::{DMatrix, DVector, Vector3};

use super::model::BallModel;
use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::input::Orbit;

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
            let (w, it0, ev0) = quasi_static_state(&held, omega0, ball)?;
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
                "ball {ball}: singular Jacobian of the quasi-static balance at {:?} (rad/s)",
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
                "ball {ball}: quasi-static balance stalled after {it} iterations (|rates| = {:.3e} rad/s², step {:.3e} rad/s)",
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
        "ball {ball}: quasi-static balance did not converge in 100 iterations (|rates| = {:.3e} rad/s²)",
        fw.norm()
    )))
}
