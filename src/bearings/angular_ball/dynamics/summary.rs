//! What the ball dynamics reports: a sample of a ball's history (the powers of its two
//! contacts at one state, [`sample`]), one ball's dynamics and every ball's, with their
//! heat totals. Shared by both methods' drivers (`simulate`, `quasi_static` through
//! `run`), so it sits below them.

use super::model::BallModel;
use crate::bearings::angular_ball::input::Method;
// Only the docs name it here.
#[cfg(doc)]
use crate::bearings::angular_ball::input::Orbit;

/// One sample of a ball's history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// t, s.
    pub time_s: f64,
    /// Orbit position travelled plus the start azimuth (unwrapped), degrees.
    pub orbit_deg: f64,
    /// ω (a, r, t), rad/s.
    pub omega_rad_s: [f64; 3],
    /// ω_m, the orbital speed, rad/s (the cage's with [`Orbit::Cage`]).
    pub orbital_rad_s: f64,
    /// Heat of both contacts, W.
    pub heat_w: f64,
    /// Its lateral part, W.
    pub lateral_w: f64,
    /// Its rolling-direction part, W.
    pub rolling_w: f64,
    /// The inner contact's part: [lateral, rolling-direction], W (the outer's is the
    /// rest; the friction breakdown by race, issue 28).
    pub inner_w: [f64; 2],
}

/// One ball's dynamics.
#[derive(Debug, Clone, PartialEq)]
pub struct BallDynamics {
    /// Start azimuth, rad.
    pub start_azimuth_rad: f64,
    /// History (one sample for the quasi-static method).
    pub history: Vec<Sample>,
    /// Heat averaged over the last orbit (time simulation) or at the position, W.
    pub heat_w: f64,
    /// Its lateral part, W.
    pub lateral_w: f64,
    /// Its rolling part, W.
    pub rolling_w: f64,
    /// The inner contact's part of the heat, [lateral, rolling-direction], averaged as
    /// `heat_w`, W.
    pub inner_w: [f64; 2],
    /// The orbital speed ω_m averaged over the last orbit (time simulation) or at the
    /// position, rad/s (the cage's with [`Orbit::Cage`]).
    pub orbital_rad_s: f64,
    /// Half the peak-to-peak of the largest-varying ω component over the last orbit,
    /// rad/s (0 for quasi-static).
    pub oscillation_rad_s: f64,
}

/// The dynamics of every ball.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsResult {
    /// The method.
    pub method: Method,
    /// "dopri5", "dopri5→rodas4" (automatic switch) or "newton" (quasi-static).
    pub integrator: String,
    /// Accepted steps (Newton iterations), summed over the balls simulated.
    pub steps: usize,
    /// Right-hand-side evaluations, summed.
    pub rhs_evaluations: usize,
    /// Whether every ball reached a steady state (amplitude ≤ 1e-6·|ω| over the last
    /// orbit).
    pub steady: bool,
    /// Largest oscillation amplitude over the balls, rad/s.
    pub oscillation_amplitude_rad_s: f64,
    /// Per ball (in the analysis' ball order).
    pub balls: Vec<BallDynamics>,
    /// Every how many samples one is kept in each ball's history before its last orbit
    /// (1: every sample; more when the history would exceed
    /// [`super::budget::MAX_SERIES_ROWS`] rows over the balls; the last orbit is always
    /// whole).
    pub series_sample_every: usize,
}

impl DynamicsResult {
    /// Total heat, W.
    pub fn total_w(&self) -> f64 {
        self.balls.iter().map(|b| b.heat_w).sum()
    }
    /// Total lateral heat, W.
    pub fn lateral_w(&self) -> f64 {
        self.balls.iter().map(|b| b.lateral_w).sum()
    }
    /// Total rolling heat, W.
    pub fn rolling_w(&self) -> f64 {
        self.balls.iter().map(|b| b.rolling_w).sum()
    }
    /// The inner contacts' total [lateral, rolling-direction] heat, W.
    pub fn inner_w(&self) -> [f64; 2] {
        self.balls.iter().fold([0.0, 0.0], |a, b| {
            [a[0] + b.inner_w[0], a[1] + b.inner_w[1]]
        })
    }
}

pub(super) fn sample(model: &BallModel, t: f64, w: &[f64]) -> Sample {
    let (omega, wm, theta) = model.unpack(t, w);
    let l = model.track.at(theta);
    let i = model.contact_at(true, &l.inner, &omega, wm);
    let o = model.contact_at(false, &l.outer, &omega, wm);
    let (lat, roll) = (i.lateral_w + o.lateral_w, i.rolling_w + o.rolling_w);
    Sample {
        time_s: t,
        orbit_deg: theta.to_degrees(),
        omega_rad_s: [w[0], w[1], w[2]],
        orbital_rad_s: wm,
        heat_w: lat + roll,
        lateral_w: lat,
        rolling_w: roll,
        inner_w: [i.lateral_w, i.rolling_w],
    }
}
