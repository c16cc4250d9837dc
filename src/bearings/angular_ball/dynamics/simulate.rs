//! The time simulation of one ball over its orbits (`dynamics.method =
//! "time-simulation"`): the integration piecewise between the kinks of the load track
//! (known times with the held cage, predicted ones with the free orbit, [`FreeKinks`]),
//! the recorded history and the last orbit's mean heat and oscillation amplitude. Apart
//! from the model (`model`) it integrates and the quasi-static solve (`quasi_static`).

use nalgebra::Vector3;

use super::budget::Decimation;
use super::model::BallModel;
use super::summary::{sample, BallDynamics, Sample};
use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::input::Orbit;
use crate::bearings::view::element_number;
use crate::numerics::cancel::Cancel;
use crate::numerics::ode::{self, OdeError, OdeOptions, Output};

fn ode_error(ball: usize, e: OdeError) -> BallError {
    match e {
        OdeError::Cancelled { .. } => BallError::Cancelled,
        e => BallError::Dynamics(format!("ball {}: {e}", element_number(ball))),
    }
}

/// The bounds of one ball's simulation ([`super::budget`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Step attempts allowed over the whole simulation (accepted plus rejected).
    pub max_step_attempts: usize,
    /// The most samples kept in the history (the last orbit always whole).
    pub max_samples: usize,
}

impl Limits {
    /// No bound beyond the integrator's former 2 000 000 attempts per piece, every
    /// sample kept (the benches and tests that call [`simulate_ball`] directly).
    pub const UNBOUNDED: Limits = Limits {
        max_step_attempts: usize::MAX,
        max_samples: usize::MAX,
    };
}

/// Simulate one ball over `orbits` orbits from ω₀ with the automatic integrator
/// (DOPRI5, switching to Rodas4 when the stiffness test fires); returns the dynamics and
/// the ODE stats.
pub fn simulate_ball(
    model: &BallModel,
    omega0: [f64; 3],
    orbits: f64,
    rtol: f64,
    ball: usize,
    cancel: Cancel,
) -> Result<(BallDynamics, ode::OdeStats), BallError> {
    simulate_ball_with(model, omega0, orbits, rtol, ode::Method::Auto, ball, cancel)
}

/// [`simulate_ball`] with a chosen integrator (benches and the one-ball example compare
/// them).
pub fn simulate_ball_with(
    model: &BallModel,
    omega0: [f64; 3],
    orbits: f64,
    rtol: f64,
    method: ode::Method,
    ball: usize,
    cancel: Cancel,
) -> Result<(BallDynamics, ode::OdeStats), BallError> {
    simulate_ball_limited(
        model,
        omega0,
        orbits,
        rtol,
        method,
        ball,
        cancel,
        Limits::UNBOUNDED,
    )
}

/// [`simulate_ball_with`] within `limits`: fails once the step attempts exceed
/// `limits.max_step_attempts` (naming the likely cause and the keys), keeps at most
/// `limits.max_samples` samples (decimating the history before the last orbit, see
/// [`Decimation`]), and reports its progress (the fraction of the orbits done) through
/// `cancel`.
#[allow(clippy::too_many_arguments)] // simulate_ball_with's, plus the limits
pub fn simulate_ball_limited(
    model: &BallModel,
    omega0: [f64; 3],
    orbits: f64,
    rtol: f64,
    method: ode::Method,
    ball: usize,
    cancel: Cancel,
    limits: Limits,
) -> Result<(BallDynamics, ode::OdeStats), BallError> {
    let wm = model.cage_rad_s.abs();
    if wm.is_nan() || wm <= 0.0 {
        return Err(BallError::Dynamics(format!(
            "ball {}: the cage does not turn (ω_m = {} rad/s): nothing to simulate",
            element_number(ball),
            model.cage_rad_s
        )));
    }
    let period = std::f64::consts::TAU / wm;
    let t_end = orbits * period;
    // The samples of the last orbit (see the summary below), kept whole; the ones before
    // decimated to fit `limits.max_samples` (issue 24: 1 000 orbits of 20 balls kept
    // 1.8 M samples, 515 MB with the CSV). The sample times are generated as the pieces
    // need them, never all at once. Clamped: t_end·k/n can round above t_end, which the
    // ODE solver refuses.
    let decimation = Decimation::of_orbits(orbits, limits.max_samples);
    let (n, per_last) = (decimation.n, decimation.per_last());
    let time_of = |k: usize| (t_end * k as f64 / n as f64).min(t_end);
    let kept = (0..=n).filter(|&k| decimation.keeps(k)).count();
    let scale = Vector3::from(omega0).norm().max(1.0);
    let opts = OdeOptions {
        rtol,
        atol: rtol * scale,
        max_steps: 2_000_000,
        method,
        ..OdeOptions::default()
    };
    let kinky = !model.track.is_uniform();
    let mut cage_bounds = Vec::new();
    if model.orbit == Orbit::Cage && kinky {
        cage_bounds = kink_times(model, t_end);
    }
    cage_bounds.push(t_end);
    let mut cage_bounds = cage_bounds.into_iter();
    let mut free_kinks = FreeKinks::new(model, period, t_end);
    let (mut out_t, mut out_y) = (Vec::with_capacity(kept), Vec::with_capacity(kept));
    let mut stats = ode::OdeStats::default();
    let mut y = model.start_state(omega0);
    let mut seg_opts = opts.clone();
    let mut next = 0;
    let mut a = 0.0;
    // Step attempts so far (accepted and rejected), against `limits.max_step_attempts`.
    let mut attempts = 0usize;
    // The progress reported last, in hundredths (reported when it moves by one).
    let mut reported = 0usize;
    while a < t_end {
        let b = match model.orbit {
            Orbit::Free if kinky => free_kinks.next_end(a, &y),
            _ => cage_bounds.next().unwrap_or(t_end),
        };
        let mut seg_times = Vec::new();
        while next <= n {
            let tr = time_of(next);
            if tr > b {
                break;
            }
            if decimation.keeps(next) {
                seg_times.push(tr.max(a));
            }
            next += 1;
        }
        let left = limits.max_step_attempts.saturating_sub(attempts);
        seg_opts.max_steps = opts.max_steps.min(left.max(1));
        let sol = ode::solve(
            model,
            a,
            &y,
            b,
            &seg_opts,
            &mut [],
            Output::Times(seg_times),
            cancel,
        )
        .map_err(|e| match e {
            OdeError::MaxSteps { t, .. } if seg_opts.max_steps < opts.max_steps => {
                too_many_steps(ball, limits.max_step_attempts, t / period, orbits)
            }
            e => ode_error(ball, e),
        })?;
        let st = sol.stats;
        attempts += st.steps + st.rejected;
        stats.steps += st.steps;
        stats.rejected += st.rejected;
        stats.rhs_evaluations += st.rhs_evaluations;
        stats.jacobian_evaluations += st.jacobian_evaluations;
        stats.lu_decompositions += st.lu_decompositions;
        if let (None, Some(ts)) = (stats.switched_to_implicit_at, st.switched_to_implicit_at) {
            stats.switched_to_implicit_at = Some(ts);
            seg_opts.method = ode::Method::Sdirk;
        }
        // The next piece's first step: this piece's mean step (with the free orbit not
        // from a piece shorter than the step already set, a sliver left by a missed
        // point, whose one step says nothing of the step size the error control allows).
        let sliver = model.orbit == Orbit::Free && seg_opts.h0.is_some_and(|h| b - a < h);
        if st.steps > 0 && b > a && !sliver {
            seg_opts.h0 = Some((b - a) / st.steps as f64);
        }
        out_t.extend(sol.t);
        out_y.extend(sol.y);
        free_kinks.piece_done(a, &y, b, &sol.y_final);
        y = sol.y_final;
        a = b;
        let done = (100.0 * a / t_end) as usize;
        if done > reported {
            reported = done;
            cancel.report(a / t_end);
        }
    }
    let history: Vec<Sample> = out_t
        .iter()
        .zip(&out_y)
        .map(|(&t, y)| sample(model, t, y))
        .collect();
    // The last orbit: mean heat, oscillation amplitude, over its samples chosen by index,
    // half-open (t_end − period, t_end]: the orbit's start is the same position as its
    // end and is not counted twice. (A filter `t ≥ t_end − period` counted it or not as
    // t_end·k/n rounded, which moved a ball's mean under radial load by 1.6 %: the
    // equally spaced samples of one period, each once, are the rectangle rule, exact for
    // a periodic signal up to its aliasing.)
    let last: Vec<&Sample> = history
        .iter()
        .skip(history.len().saturating_sub(per_last))
        .collect();
    let m = last.len().max(1) as f64;
    let mean = |f: fn(&Sample) -> f64| last.iter().map(|s| f(s)).sum::<f64>() / m;
    let mut amp: f64 = 0.0;
    let comp = |s: &Sample, c: usize| {
        if c < 3 {
            s.omega_rad_s[c]
        } else {
            s.orbital_rad_s
        }
    };
    // ω's components, and ω_m when it is integrated.
    for c in 0..model.state_dim().min(4) {
        let (lo, hi) = last
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, s| {
                (a.0.min(comp(s, c)), a.1.max(comp(s, c)))
            });
        amp = amp.max(0.5 * (hi - lo));
    }
    let (heat_w, lateral_w, rolling_w, orbital_rad_s) = (
        mean(|s| s.heat_w),
        mean(|s| s.lateral_w),
        mean(|s| s.rolling_w),
        mean(|s| s.orbital_rad_s),
    );
    let inner_w = [mean(|s| s.inner_w[0]), mean(|s| s.inner_w[1])];
    Ok((
        BallDynamics {
            start_azimuth_rad: model.start_azimuth_rad,
            history,
            heat_w,
            lateral_w,
            rolling_w,
            inner_w,
            orbital_rad_s,
            oscillation_rad_s: amp,
        },
        stats,
    ))
}

/// The failure of a ball whose integration took more than `max` step attempts, at
/// `reached` of `orbits` orbits: the cause (a stiff ball: a steep traction curve, e.g. a
/// constant µ near 1) and the keys that change it.
fn too_many_steps(ball: usize, max: usize, reached: f64, orbits: f64) -> BallError {
    BallError::Dynamics(format!(
        "ball {}: the integration took more than {max} step attempts (20× what the shipped decks need per orbit) and reached only {reached:.3} of {orbits} orbits: the ball's motion is too stiff for the integrator (a steep traction curve, e.g. traction.curve = \"constant\" with a large traction.mu); use a gentler traction curve, a looser dynamics.tolerance, fewer dynamics.orbits or dynamics.method = \"race-control\"", element_number(ball)
    ))
}

/// The free orbit's pieces (see [`simulate_ball_with`]): each ends when the ball is
/// predicted to reach the next point θ_k of the load track. From the piece's start
/// state (θ, ω_m) and the orbital acceleration α (the secant of the previous piece, no
/// extra evaluation: ω_m changes by < 1 % per orbit, so α's lag of one piece moves
/// the predicted end by little: measured misses ≤ 4e-4 rad of 0.314 rad pieces),
/// θ_k − θ = ω_m τ + ½ α τ² gives the
/// piece's length τ = 2Δθ/(ω_m + √(ω_m² + 2αΔθ)) (the root that tends to Δθ/ω_m, free
/// of cancellation), for either sense of rotation (ω_m and α taken along it).
struct FreeKinks<'m, 'a> {
    model: &'m BallModel<'a>,
    t_end: f64,
    /// Pieces closer than this to t_end are merged into the last piece, s.
    merge_s: f64,
    /// α, rad/s², from the previous piece (0 before the first).
    accel: f64,
    /// A track point closer than this ahead is not aimed at: the previous piece's end
    /// missed it by that much, rad. 1 % of the mean spacing of the track's points
    /// (2π/n). Measured on Bearing B under 500 N radial load (20 points, 0.314 rad
    /// apart), the misses are ≤ 4e-4 rad = 0.13 % of a piece; aiming at them again
    /// costs a piece of one step (7 evaluations) and then a first step grown from that
    /// sliver: with a gap of 1e-5 rad the ball took 933 steps and 5 838 evaluations,
    /// with 1e-3 rad or more 683 and 4 319. A point left ≤ 1 % of a piece ahead lies
    /// inside the next piece's first step (or the last of this one), whose polynomial
    /// misfits the right-hand side only over the miss: a local error of the order of
    /// the slope jump times the miss squared, which the error control absorbs (19
    /// rejected steps per 5 orbits against 180 integrating in one piece).
    min_gap_rad: f64,
}

impl<'m, 'a> FreeKinks<'m, 'a> {
    fn new(model: &'m BallModel<'a>, period: f64, t_end: f64) -> Self {
        FreeKinks {
            model,
            t_end,
            merge_s: 1e-9 * period,
            accel: 0.0,
            min_gap_rad: 1e-2 * std::f64::consts::TAU
                / model.track.azimuths().count().max(1) as f64,
        }
    }

    /// The end of the piece starting at time `a` in state `y` (ω, ω_m, θ): the predicted
    /// time of the next track point, or t_end when that is nearer (or within
    /// `merge_s` of it), or when the ball does not move along its orbit (ω_m = 0 or the
    /// prediction is not finite: no point will be reached, nothing to split).
    fn next_end(&self, a: f64, y: &[f64]) -> f64 {
        let (wm, theta) = (y[3], y[4]);
        let forward = wm >= 0.0;
        let Some(dtheta) = self
            .model
            .track
            .angle_to_next_point(theta, forward, self.min_gap_rad)
        else {
            return self.t_end;
        };
        let (w, acc) = if forward {
            (wm, self.accel)
        } else {
            (-wm, -self.accel)
        };
        let disc = w * w + 2.0 * acc * dtheta;
        let tau = 2.0 * dtheta / (w + disc.max(0.0).sqrt());
        let b = a + tau;
        // (`b > a` also guards against a piece lost to rounding, which would not advance.)
        if !(tau.is_finite() && b > a) || b >= self.t_end - self.merge_s {
            self.t_end
        } else {
            b
        }
    }

    /// Record the piece from (`a`, `y_a`) to (`b`, `y_b`): its mean orbital
    /// acceleration predicts the next one.
    fn piece_done(&mut self, a: f64, y_a: &[f64], b: f64, y_b: &[f64]) {
        if self.model.orbit == Orbit::Free && b > a {
            let acc = (y_b[3] - y_a[3]) / (b - a);
            if acc.is_finite() {
                self.accel = acc;
            }
        }
    }
}

/// The times in (0, t_end) at which the ball passes a point of the load track, ascending
/// (closer than 1e-9 of an orbit to each other or to the ends dropped).
fn kink_times(model: &BallModel, t_end: f64) -> Vec<f64> {
    let wm = model.cage_rad_s;
    let period = std::f64::consts::TAU / wm.abs();
    let eps = 1e-9 * period;
    let mut out = Vec::new();
    for psi in model.track.azimuths() {
        let mut t = ((psi - model.start_azimuth_rad) / wm).rem_euclid(period);
        while t < t_end - eps {
            if t > eps {
                out.push(t);
            }
            t += period;
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup_by(|b, a| *b - *a <= eps);
    out
}
