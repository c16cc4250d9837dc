//! Ball dynamics in EHD traction (seed 001 ch. 2, eqs. 2-3, 2-14…2-18): the ball's
//! angular velocity under the traction of every slice of its two contacts, either as a
//! time simulation over its orbits (integrated by `numerics::ode`, started from race
//! control) or quasi-statically (the moment balance solved at each ball position).
//!
//! # Frame and equations of motion (2-3, 2-14b…d in vector form)
//! The frame (a, r, t) of `race_control` (axis, radially out, orbital direction) at the
//! ball centre turns with the cage at ω_m about a. The ball is a sphere of inertia J, so
//! with ω its absolute angular velocity written in this frame,
//! ```text
//! J·dω/dt = M − J·ω_m a × ω,
//! ```
//! i.e. J ω̇_a = M_a, J ω̇_r = M_r + J ω_m ω_t, J ω̇_t = M_t − J ω_m ω_r: the last term is
//! Chen's gyroscopic term of (2-3)/(2-14c,d). M is the moment of the slice tractions
//! about the ball centre. The orbital speed ω_m (Chen's fourth unknown, 2-14a) is found
//! one of two ways (`dynamics.orbit`):
//!
//! - **cage** (the default): held at race control's cage speed (a cage-guided ball set;
//!   the ball's orbital equation is not integrated — the tangential force it would need
//!   is the cage's, and its power −F_t ω_m R_b enters the ball's energy balance);
//! - **free** (2-14a with F_cage = F_drag = 0): m R_b dω_m/dt = F_t, the resultant
//!   traction along t, and the ball's azimuth θ = ∫ω_m dt is integrated too, so the
//!   state is (ω_a, ω_r, ω_t, ω_m, θ) and the loads are those of the track at the
//!   ball's own θ. The frame now turns at the ball's own ω_m(t); J dω/dt = M − J ω_m a × ω
//!   holds as written (the frame's angular velocity enters only through ω_m a × ω). The
//!   rings' friction power then goes into heat and the ball's kinetic energy
//!   ½J|ω|² + ½m(ω_m R_b)² alone; at a steady state F_t = 0 (the quasi-static method
//!   solves that orbital balance with dω/dt = 0). Under Chen's 500 N radial load on
//!   Bearing B the free orbit brings the peak heat per ball from 176 W (3.0× the axial
//!   case) to 124 W (2.35×), against the seed's ≈ 100 W (≈ 2×): see
//!   `free_orbit_heat_against_the_seed`.
//!
//! # Sliding velocities (derived here: the OCR of 2-15a…c is garbled)
//! A point p of the contact (from the ball centre) moves with the ball at
//! v_b = ω_m R_b t + ω × p, and with race j (speed Ω_j about the axis) at
//! v_j = Ω_j (R_b + p_r) t (p lies in the a–r plane). The sliding of the ball on the race
//! is s = v_b − v_j, taken in the tangent plane of the contact surface. Its rolling
//! component (along t) holds Chen's y-sliding (2-15b, c: spin and creep); its transverse
//! component Chen's x-sliding (2-15a, "caused by the gyroscopic moment").
//!
//! # Slices (2-16, 2-17)
//! Each ellipse (semi-major a across the groove, semi-minor b along t) is cut into N
//! strips across its major axis; strip k carries the Hertz load
//! q_k = Q·¾[ξ − ξ³/3] between its edges ξ = x/a (the exact integral of p₀√(1−ξ²−η²)),
//! and slides with the velocity of its centre line. Only the transverse curvature of
//! the contact surface is kept (the seed: the ellipse is narrow): the surface is the
//! arc of radius R_def = 2/(2/D + 1/(fD)) (2-17, the mean of the ball's and the groove's
//! curvatures), tangent to the undeformed ball at the contact centre.
//!
//! # Traction and heat (2-18)
//! Each strip carries the traction −µ(|s|)·q·s/|s| (µ from the traction curve); the heat
//! is µ·q·|s|, split into its rolling-direction part µ q s_t²/|s| and its lateral part
//! µ q s_x²/|s| (Fig. 6-13's sources; the two add up to the total exactly). Spin
//! slides along the rolling direction (ω_s n × x τ is parallel to t), so spin heat lands
//! in the rolling part; the lateral part is the gyroscopic skid (Chen's 2-15a). This
//! is Chen's split by sliding direction, not a split into "spin" and "rolling" causes.
//!
//! # Layout
//! This file holds [`run`], the driver over the balls; `model` the ball's model and
//! right-hand side (the slices, their tractions and powers), `jacobian` its analytic
//! Jacobian, `simulate` the time simulation of one ball, `quasi_static` the quasi-static
//! solve, `summary` the results (samples, one ball's, every ball's); the tests are in
//! `tests.rs`. Every public item keeps its path `dynamics::…` (re-exported here).

use nalgebra::Vector3;

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, Integrator, Method};
pub use super::load_track::{BallLoads, ContactLoads, LoadTrack};
use super::results::BallResult;
use crate::numerics::cancel::Cancel;
use crate::numerics::ode;

pub use model::{BallModel, ContactPower};
pub use quasi_static::{quasi_static_ball, quasi_static_state};
pub use settle::{settling, Settling};
pub use simulate::{simulate_ball, simulate_ball_limited, simulate_ball_with, Limits};
use summary::sample;
pub use summary::{BallDynamics, DynamicsResult, Sample};

pub mod budget;
mod jacobian;
mod model;
mod quasi_static;
mod settle;
mod simulate;
mod summary;

/// The ball dynamics of a race-control analysis (`method` quasi-static or
/// time-simulation). Under an axisymmetric load (no radial load) every ball sees the
/// same loads at every position, so one ball is solved and its result shared (the balls
/// differ only by their start azimuth).
pub fn run(
    input: &BallInput,
    geom: &BallGeometry,
    balls: &[BallResult],
    cancel: Cancel,
) -> Result<DynamicsResult, BallError> {
    let d = &input.dynamics;
    if d.slices < 1
        || d.orbits.is_nan()
        || d.orbits <= 0.0
        || d.tolerance.is_nan()
        || d.tolerance <= 0.0
    {
        return Err(BallError::InvalidInput(format!(
            "dynamics: need slices ≥ 1, orbits > 0 and tolerance > 0 (got {}, {}, {})",
            d.slices, d.orbits, d.tolerance
        )));
    }
    let curve = input.traction.curve();
    let track = LoadTrack::new(balls);
    let cage = balls.iter().map(|b| b.cage_rad_s).sum::<f64>() / balls.len().max(1) as f64;
    let op = &input.operating;
    let axisymmetric = op.radial_load_n == 0.0;
    // The estimate before anything is integrated: a run past the bound is refused with
    // the keys to change (issue 24 item 7).
    let estimate = budget::estimate(input, balls.len(), axisymmetric);
    if d.method == Method::TimeSimulation {
        budget::check(input, &estimate)?;
    }
    let limits = Limits {
        max_step_attempts: estimate.max_step_attempts,
        max_samples: estimate.samples_per_ball,
    };
    // Progress over every ball simulated: each ball reports its own fraction, which the
    // shared sum (in millionths of a ball, so that parallel balls add without a lock)
    // turns into the whole run's.
    let done_ppm = std::sync::atomic::AtomicU64::new(0);
    let simulated = if axisymmetric || balls.len() < 2 {
        1
    } else {
        balls.len()
    };
    // One ball: its dynamics, steps, RHS evaluations and whether Rodas4 took over.
    let solve_one =
        |j: usize, b: &BallResult| -> Result<(BallDynamics, usize, usize, bool), BallError> {
            let model = BallModel {
                diameter_m: geom.ball_diameter_m,
                centre_radius_m: 0.5 * geom.pitch_diameter_m,
                inertia_kg_m2: geom.ball_inertia_kg_m2,
                // The free orbit starts from the cage's speed too (released at t = 0).
                cage_rad_s: cage,
                orbit: d.orbit,
                mass_kg: geom.ball_mass_kg,
                ring_speeds_rad_s: (op.inner_speed_rad_s, op.outer_speed_rad_s),
                groove_curvatures: (geom.inner_groove_curvature, geom.outer_groove_curvature),
                curve: &curve,
                slices: d.slices,
                track: &track,
                start_azimuth_rad: b.azimuth_rad,
            };
            // Race control: ω = (ω_a, ω_r, 0) (no gyroscopic pivoting).
            let omega0 = [b.ball_axial_rad_s, b.ball_radial_rad_s, 0.0];
            match d.method {
                Method::TimeSimulation => {
                    let method = match d.integrator {
                        Integrator::Auto => ode::Method::Auto,
                        Integrator::Dopri5 => ode::Method::DormandPrince45,
                        Integrator::Rodas4 => ode::Method::Sdirk,
                    };
                    // This ball's fraction, reported as the increment since its last report.
                    let mine = std::sync::atomic::AtomicU64::new(0);
                    let report = |f: f64| {
                        use std::sync::atomic::Ordering::Relaxed;
                        let ppm = (f * 1e6) as u64;
                        let before = mine.swap(ppm, Relaxed);
                        let total = done_ppm.fetch_add(ppm.saturating_sub(before), Relaxed)
                            + ppm.saturating_sub(before);
                        cancel.report(total as f64 / (1e6 * simulated as f64));
                    };
                    let ball_cancel = Cancel::from_option(cancel.flag()).with_progress(&report);
                    let (bd, st) = simulate_ball_limited(
                        &model,
                        omega0,
                        d.orbits,
                        d.tolerance,
                        method,
                        j,
                        ball_cancel,
                        limits,
                    )?;
                    Ok((
                        bd,
                        st.steps,
                        st.rhs_evaluations,
                        st.switched_to_implicit_at.is_some(),
                    ))
                }
                _ => {
                    if cancel.is_cancelled() {
                        return Err(BallError::Cancelled);
                    }
                    let (w, it, ev) = quasi_static_state(&model, omega0, j)?;
                    let s = sample(&model, 0.0, &w);
                    Ok((
                        BallDynamics {
                            start_azimuth_rad: b.azimuth_rad,
                            history: vec![s],
                            heat_w: s.heat_w,
                            lateral_w: s.lateral_w,
                            rolling_w: s.rolling_w,
                            inner_w: s.inner_w,
                            orbital_rad_s: s.orbital_rad_s,
                            oscillation_rad_s: 0.0,
                        },
                        it,
                        ev,
                        false,
                    ))
                }
            }
        };
    let solved: Vec<(BallDynamics, usize, usize, bool)> = if axisymmetric || balls.len() < 2 {
        // Every ball sees the same loads at every position: solve the first, shift its
        // copies to the others' start azimuths.
        let Some(b0) = balls.first() else {
            return Err(BallError::InvalidInput(
                "dynamics: the load distribution has no balls to simulate".to_string(),
            ));
        };
        let first = solve_one(0, b0)?;
        let mut v = Vec::with_capacity(balls.len());
        for b in &balls[1..] {
            let mut copy: BallDynamics = first.0.clone();
            let shift = b.azimuth_rad - copy.start_azimuth_rad;
            copy.start_azimuth_rad = b.azimuth_rad;
            for s in &mut copy.history {
                s.orbit_deg += shift.to_degrees();
            }
            v.push((copy, 0, 0, false));
        }
        v.insert(0, first);
        v
    } else {
        // Given the load track the balls are independent: solved in parallel (the order
        // and every number are those of a serial loop; each ball's integration is
        // deterministic and owns its state).
        use rayon::prelude::*;
        balls
            .par_iter()
            .enumerate()
            .map(|(j, b)| solve_one(j, b))
            .collect::<Result<Vec<_>, _>>()?
    };
    let (mut steps, mut evals, mut switched) = (0, 0, false);
    let mut out = Vec::with_capacity(solved.len());
    for (bd, st, ev, sw) in solved {
        steps += st;
        evals += ev;
        switched |= sw;
        out.push(bd);
    }
    let amp = out.iter().map(|b| b.oscillation_rad_s).fold(0.0, f64::max);
    let scale = out
        .iter()
        .filter_map(|b| b.history.last())
        .map(|s| Vector3::from(s.omega_rad_s).norm())
        .fold(1.0, f64::max);
    Ok(DynamicsResult {
        method: d.method,
        integrator: match (d.method, d.integrator) {
            (Method::TimeSimulation, Integrator::Rodas4) => "rodas4".to_string(),
            (Method::TimeSimulation, _) if switched => "dopri5→rodas4".to_string(),
            (Method::TimeSimulation, _) => "dopri5".to_string(),
            _ => "newton".to_string(),
        },
        steps,
        rhs_evaluations: evals,
        steady: amp <= 1e-6 * scale,
        oscillation_amplitude_rad_s: amp,
        balls: out,
        series_sample_every: match d.method {
            Method::TimeSimulation => {
                budget::Decimation::of_orbits(d.orbits, limits.max_samples).every
            }
            _ => 1,
        },
    })
}

#[cfg(test)]
mod tests;
