//! Whether a time simulation has settled, and how many orbits a steady answer would need
//! (issue 24, item 9): read from the balls' recorded histories after the run, so the
//! integration (`simulate`) is untouched.
//!
//! Two kinds of motion look alike in the last orbit's amplitude:
//! - **the transient** from race control's start, which decays from orbit to orbit (the
//!   free orbit's ω_m settles slowly: Bearing B at 9 500 rpm shrinks by ≈ 0.62 per orbit);
//! - **the periodic response** under a radial load: each ball's loads follow its azimuth
//!   (`load_track`), so its ω swings around the orbit for ever (Bearing B, 500 N radial:
//!   ±309 rad/s after 40 orbits), which is the answer, not an unsettled one.
//!
//! Without a radial load the steady response is constant, so the amplitude over an orbit
//! *is* the transient. Under a radial load the transient is what changes from one orbit
//! to the next: the mean of each ω component over an orbit of the ball's own azimuth θ
//! (not of time: a free ball orbits 0.5–7 % faster than the cage, and a window of the
//! cage's period then covers a different arc each orbit, whose means differ by the
//! periodic swing times that mismatch; measured on Bearing B at 500 N radial, 12 orbits:
//! time windows' means still moved by 4 rad/s between the last orbits where θ windows'
//! moved by 0.2 rad/s and shrank by 0.5 per orbit down to a floor of 2e-4 rad/s, the
//! windows' quadrature).
//!
//! The per-orbit measure e_k decays geometrically once the transient is a single mode, so
//! the factor r = e_last/e_prev estimates the orbits still needed to bring e below the
//! steady bound: ln(bound/e_last)/ln r more.

use nalgebra::Vector3;

use super::summary::{DynamicsResult, Sample};

/// Bound of a settled answer relative to |ω|: the same 1e-6 as `DynamicsResult::steady`.
pub const SETTLED_RELATIVE: f64 = 1e-6;

/// How far a time simulation is from its steady answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settling {
    /// Orbits simulated (`dynamics.orbits`).
    pub orbits: f64,
    /// Whether the steady answer is periodic around the orbit (a radial load) rather than
    /// constant.
    pub periodic: bool,
    /// The ball farthest from settled (0-based).
    pub ball: usize,
    /// The transient left in the last orbit, rad/s: the amplitude (constant steady
    /// answer) or the change of the orbit means from the orbit before (periodic).
    pub transient_rad_s: f64,
    /// The largest amplitude over the last orbit, rad/s (the JSON's
    /// `dynamics.oscillation_amplitude_rad_s`).
    pub amplitude_rad_s: f64,
    /// The transient below which the answer counts as settled, rad/s: 1e-6·|ω|.
    pub bound_rad_s: f64,
    /// The transient's factor per orbit over the last two orbits, when they exist.
    pub decay_per_orbit: Option<f64>,
    /// Whether the answer has settled.
    pub settled: bool,
}

impl Settling {
    /// The orbits a steady answer needs in all, estimated from the decay per orbit:
    /// `None` when the transient does not shrink (or too few orbits were simulated to
    /// tell), then "more than [`Self::orbits`]".
    pub fn orbits_needed(&self) -> Option<f64> {
        let r = self.decay_per_orbit?;
        if self.settled {
            return Some(self.orbits);
        }
        if !(r > 0.0 && r < 1.0) || self.transient_rad_s <= 0.0 {
            return None;
        }
        let more = (self.bound_rad_s / self.transient_rad_s).ln() / r.ln();
        more.is_finite()
            .then(|| self.orbits.ceil() + more.ceil().max(1.0))
    }
}

/// Mean and half peak-to-peak of each component (ω_a, ω_r, ω_t, ω_m) over the window
/// [a, b] of the ball's travelled azimuth φ (degrees from its start, along its sense of
/// travel): the samples joined by straight lines, clipped to the window (trapezoid rule;
/// the ends interpolated). `None` when the history does not cover the window.
fn window(h: &[(f64, [f64; 4])], a: f64, b: f64) -> Option<([f64; 4], [f64; 4])> {
    let first = h.first()?.0;
    let last = h.last()?.0;
    if !(first <= a && last >= b && b > a) {
        return None;
    }
    let mut area = [0.0; 4];
    let mut lo = [f64::INFINITY; 4];
    let mut hi = [f64::NEG_INFINITY; 4];
    for p in h.windows(2) {
        let ((x0, v0), (x1, v1)) = (p[0], p[1]);
        if x1 <= x0 {
            continue;
        }
        let (c0, c1) = (x0.max(a), x1.min(b));
        if c1 < c0 {
            continue;
        }
        for c in 0..4 {
            let at = |x: f64| v0[c] + (v1[c] - v0[c]) * (x - x0) / (x1 - x0);
            let (y0, y1) = (at(c0), at(c1));
            area[c] += 0.5 * (y0 + y1) * (c1 - c0);
            lo[c] = lo[c].min(y0.min(y1));
            hi[c] = hi[c].max(y0.max(y1));
        }
    }
    let mut mean = [0.0; 4];
    let mut amp = [0.0; 4];
    for c in 0..4 {
        mean[c] = area[c] / (b - a);
        amp[c] = 0.5 * (hi[c] - lo[c]);
    }
    Some((mean, amp))
}

/// The per-orbit transient of one ball over its last orbits of travelled azimuth, last
/// first: amplitudes (constant steady answer) or changes of the orbit means (periodic).
fn transients(history: &[Sample], periodic: bool) -> Vec<f64> {
    let (Some(s0), Some(s1)) = (history.first(), history.last()) else {
        return Vec::new();
    };
    let sense = if s1.orbit_deg >= s0.orbit_deg {
        1.0
    } else {
        -1.0
    };
    let h: Vec<(f64, [f64; 4])> = history
        .iter()
        .map(|s| {
            (
                sense * (s.orbit_deg - s0.orbit_deg),
                [
                    s.omega_rad_s[0],
                    s.omega_rad_s[1],
                    s.omega_rad_s[2],
                    s.orbital_rad_s,
                ],
            )
        })
        .collect();
    let end = h.last().map_or(0.0, |p| p.0);
    // The last three orbits at most: two transients each way.
    let wins: Vec<([f64; 4], [f64; 4])> = (0..3)
        .map_while(|k| window(&h, end - 360.0 * (k + 1) as f64, end - 360.0 * k as f64))
        .collect();
    let max = |v: [f64; 4]| v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if periodic {
        wins.windows(2)
            .map(|w| max([0, 1, 2, 3].map(|c| w[0].0[c] - w[1].0[c])))
            .collect()
    } else {
        wins.iter().take(2).map(|w| max(w.1)).collect()
    }
}

/// How far the time simulation `d` of `orbits` orbits is from its steady answer;
/// `periodic` when the loads vary around the orbit (a radial load). `None` when there is
/// no history to read (the quasi-static method, or no balls).
pub fn settling(d: &DynamicsResult, periodic: bool, orbits: f64) -> Option<Settling> {
    if d.balls.iter().all(|b| b.history.len() < 2) {
        return None;
    }
    let scale = d
        .balls
        .iter()
        .filter_map(|b| b.history.last())
        .map(|s| Vector3::from(s.omega_rad_s).norm())
        .fold(1.0, f64::max);
    let bound = SETTLED_RELATIVE * scale;
    // The ball farthest from settled by its last orbit's transient (a ball whose history
    // covers no whole orbit of azimuth counts as unsettled, with no estimate).
    let mut worst: Option<(usize, Vec<f64>)> = None;
    for (j, b) in d.balls.iter().enumerate() {
        let e = transients(&b.history, periodic);
        let key = |e: &Vec<f64>| e.first().copied().unwrap_or(f64::INFINITY);
        if worst.as_ref().is_none_or(|(_, w)| key(&e) > key(w)) {
            worst = Some((j, e));
        }
    }
    let (ball, e) = worst?;
    let transient = e.first().copied().unwrap_or(d.oscillation_amplitude_rad_s);
    let settled = if periodic {
        e.first().is_some_and(|&x| x <= bound)
    } else {
        // As the JSON's `steady` (its amplitude over the last orbit of time).
        d.steady
    };
    let decay = match (e.first(), e.get(1)) {
        (Some(&a), Some(&b)) if b > 0.0 => Some(a / b),
        _ => None,
    };
    Some(Settling {
        orbits,
        periodic,
        ball,
        transient_rad_s: transient,
        amplitude_rad_s: d.oscillation_amplitude_rad_s,
        bound_rad_s: bound,
        decay_per_orbit: decay,
        settled,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::angular_ball::dynamics::BallDynamics;
    use crate::bearings::angular_ball::input::Method;

    /// A history of `orbits` cage orbits, 90 samples each, of a ball orbiting `speedup`
    /// times faster than the cage (a free ball), with ω_a = −4000 + swing·sin(θ) (the
    /// periodic response, a function of the ball's own azimuth θ) + a transient drift
    /// `t0`·r^(θ/360°) decaying by r per orbit of θ (as the free orbit's ω_m creeps to
    /// its balance).
    fn ball(orbits: usize, speedup: f64, swing: f64, t0: f64, r: f64) -> BallDynamics {
        let n = orbits * 90;
        let history: Vec<Sample> = (0..=n)
            .map(|k| {
                let theta = speedup * 360.0 * k as f64 / 90.0;
                let th = theta.to_radians();
                let decay = r.powf(theta / 360.0);
                let wa = -4000.0 + swing * th.sin() + t0 * decay;
                Sample {
                    time_s: k as f64,
                    orbit_deg: theta,
                    omega_rad_s: [wa, 3000.0, 0.0],
                    orbital_rad_s: 500.0,
                    heat_w: 0.0,
                    lateral_w: 0.0,
                    rolling_w: 0.0,
                    inner_w: [0.0, 0.0],
                }
            })
            .collect();
        BallDynamics {
            start_azimuth_rad: 0.0,
            history,
            heat_w: 0.0,
            lateral_w: 0.0,
            rolling_w: 0.0,
            inner_w: [0.0, 0.0],
            orbital_rad_s: 500.0,
            oscillation_rad_s: swing + t0,
        }
    }

    fn result(b: BallDynamics, steady: bool) -> DynamicsResult {
        DynamicsResult {
            method: Method::TimeSimulation,
            integrator: "dopri5".into(),
            steps: 0,
            rhs_evaluations: 0,
            steady,
            oscillation_amplitude_rad_s: b.oscillation_rad_s,
            series_sample_every: 1,
            balls: vec![b],
        }
    }

    /// The periodic response alone (a 300 rad/s swing, the ball 5 % faster than the
    /// cage) is settled; the same with a transient of 50 rad/s shrinking by 0.5 per orbit
    /// is not, with the factor found to 1e-2 (the trapezoid rule's error on 90 samples
    /// per orbit, the window ends interpolated) and the orbits a 1e-6·|ω| bound needs
    /// estimated from it; without a radial load the amplitude is the transient, and a
    /// transient that does not shrink gives no estimate.
    #[test]
    fn tells_the_transient_from_the_periodic_response() {
        let s = settling(&result(ball(12, 1.05, 300.0, 0.0, 0.5), false), true, 12.0);
        let s = s.unwrap_or_else(|| panic!("no settling"));
        assert!(s.settled, "{s:?}");
        assert!(s.transient_rad_s < 1e-3, "{s:?}");

        let s = settling(&result(ball(6, 1.05, 300.0, 50.0, 0.5), false), true, 6.0);
        let s = s.unwrap_or_else(|| panic!("no settling"));
        assert!(!s.settled, "{s:?}");
        let r = s.decay_per_orbit.unwrap_or(0.0);
        assert!((r - 0.5).abs() < 1e-2, "{s:?}");
        // |ω| = |(ω_a, 3000, 0)| of the last sample, 4 000…5 500 rad/s.
        assert!(s.bound_rad_s > 4e-3 && s.bound_rad_s < 5.5e-3, "{s:?}");
        let need = s.orbits_needed().unwrap_or(0.0);
        let expect = 6.0 + ((s.bound_rad_s / s.transient_rad_s).ln() / r.ln()).ceil();
        assert_eq!(need, expect, "{s:?}");
        assert!(need > 6.0 && need < 40.0, "{need}");

        let s = settling(&result(ball(6, 1.0, 0.0, 50.0, 0.6), false), false, 6.0);
        let s = s.unwrap_or_else(|| panic!("no settling"));
        assert!(!s.settled);
        let r = s.decay_per_orbit.unwrap_or(0.0);
        assert!((r - 0.6).abs() < 1e-2, "{s:?}");
        assert!(s.orbits_needed().is_some_and(|n| n > 6.0));

        let s = settling(&result(ball(6, 1.0, 0.0, 50.0, 1.0), false), false, 6.0);
        let s = s.unwrap_or_else(|| panic!("no settling"));
        assert_eq!(s.orbits_needed(), None, "{s:?}");
    }
}
