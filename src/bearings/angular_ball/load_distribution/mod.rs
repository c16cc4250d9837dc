//! Quasi-static load distribution with centrifugal force and gyroscopic moment (seed 001
//! eqs. 2-5 … 2-8, 3-1, 3-2: Jones's and Harris's quasi-static model as Chen writes it),
//! iterated with race-control kinematics to a fixed point.
//!
//! # Which friction split is whose (issue 29)
//! The friction that resists the gyroscopic moment is shared between the races
//! (`kinematics.friction_split`, [`FrictionSplit`]):
//! * `proportional` (default) is **Chen's** reading of 2-7: one coefficient
//!   µ = 2M_g/(D(Q_i + Q_o)) at both contacts, each race's friction in proportion to its
//!   normal load. It is *not* Harris's model, as this comment used to say.
//! * `controlling-race` is **Harris's** (Harris & Kotzalas vol. 2 §3.2, λ_i + λ_o = 2;
//!   OpenJones's outer-race control): the whole friction 2M_g/D at the controlling race
//!   (λ = 2), none at the other (λ = 0); with `race_control = "auto"` at the race it picks.
//!   In the equations below µ then differs between the contacts: (I + µ_i R) on the inner
//!   load, (I + µ_o R) on the outer.
//!
//! # Unknowns and geometry (Fig. 3-1)
//! In the plane of a ball at azimuth ψ, (a, r) axial and radial. The outer groove centre
//! O' is fixed. X = B − O' is the ball centre relative to O' (Harris's X₁, X₂). The
//! inner groove centre sits at I − O' = (A sin α₀ + δ_a, A cos α₀ + δ_r cos ψ) (Chen's
//! Z_ib, R_ib for a ring displaced δ_a axially and δ_r radially towards ψ = 0; no tilt).
//! Then (3-1a…d):
//! * outer: L_o = |X|, δ_o = L_o − (f_o − ½)D, (sin α_o, cos α_o) = X/L_o;
//! * inner: v = (I − O') − X, L_i = |v|, δ_i = L_i − (f_i − ½)D, (sin α_i, cos α_i) = v/L_i;
//! * Q = K δ^{3/2} (3-2) with K of App. A at the current contact angle.
//!
//! The angles are whatever the geometry gives, 90° and beyond included: the groove is a
//! full torus here (no shoulder). A contact angle past 90° means the ball centre lies
//! radially beyond the groove centre of curvature; it happens for Bearing B with the
//! preload held as a force at 9 500 rpm (α_i = 90.76°: the centrifugal force pushes the
//! ball out until L_o cos α_o exceeds A cos α₀, which for B's grooves equals (f_o − ½)D;
//! the numbers and why it is not the friction term are in the test
//! `force_held_preload_lets_the_inner_angle_run_up`). A real ring's shoulder would end
//! below such a contact; the displacement-held preload (the default) keeps α_i at 68.9°.
//!
//! # Ball equilibrium (2-5a, b) in vector form
//! The inner race pushes the ball along u_i = v/L_i, the outer along −u_o. The friction
//! that supplies the gyroscopic moment M_g = J ω_m ω_r (along the rolling direction t)
//! acts along the contact tangents: with R = [[0, 1], [−1, 0]] (a quarter turn in the
//! (a, r) plane) the force on the ball is
//!
//! ```text
//! F = (I + µR)(Q_i u_i − Q_o u_o) + (0, m ω_m² R_b),
//! ```
//!
//! µ = 2M_g/(D(Q_i + Q_o)) (2-7), capped at the traction's µ_m ([`Conditions::max_friction`]:
//! beyond it the contacts cannot hold the precession and the ball skids). Its couple about
//! the ball centre is
//! ½µD(Q_i + Q_o) = M_g along +t: this is the physically consistent direction
//! ([`GyroscopicFriction::Resisting`], tested in `friction_couple_supplies_the_precession`).
//! Written out, F_a = Q_i sin α_i − Q_o sin α_o + µ(Q_i cos α_i − Q_o cos α_o): the seed's
//! (2-5a) prints the µ terms with the opposite sign ([`GyroscopicFriction::SeedSign`],
//! which reproduces Chen's ch. 6 numbers).
//!
//! Jacobian (analytic): with G = Q' u uᵀ + (Q/L)(I − u uᵀ), the derivative of Q·u with
//! respect to its vector, J_b = −(I + µR)(G_i + G_o) + diag(0, mω_m²).
//!
//! # Ring equilibrium (2-8)
//! The force P = (I + µR)Q_i u_i of the inner ring on each ball: ΣP_a = F_a, ΣP_r cos ψ = F_r
//! (the friction included: it is a force on the ring; Chen neglects it, and at rest it is
//! zero). The ring Jacobian comes from the implicit function theorem:
//! dP/d(I − O') = M_i (I + J_b⁻¹ M_i), M_i = (I + µR)G_i.
//!
//! # Fixed point
//! Contact stiffness (at the operating angles), orbital speed ω_m and ball spin ω_r
//! (race control, `race_control`) and µ are held during one load solve and updated from
//! its answer until the contact angles change by less than 1e-12 rad and the loads by
//! less than 1e-10 of their sum.
//!
//! # Layout
//! This file holds the conditions and results of a solve and its entry points
//! ([`solve`], [`solve_traced`]); `ball` one ball's equilibrium, `problem` the ring's
//! Newton system over the balls, `driver` the fixed point and the continuation from rest.
//! Every public item keeps its path `load_distribution::…` (re-exported here).

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{FrictionSplit, GyroscopicFriction, RaceControl};
use super::race_control::RaceKinematics;
use crate::numerics::cancel::Cancel;

pub use ball::{solve_ball, solve_ball_with, BallEquilibrium, BallParams, ContactLoad, OuterAlone};
use driver::solve_recorded;
pub use problem::Tilt;

mod ball;
mod driver;
mod problem;

/// How the inner ring is held axially during a load solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axial {
    /// The axial force F_a (N) is given.
    Force(f64),
    /// The axial displacement δ_a (m) is given.
    Displacement(f64),
}

/// Everything that defines one load solve besides the geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    /// Ω_i, rad/s.
    pub inner_speed_rad_s: f64,
    /// Ω_o, rad/s.
    pub outer_speed_rad_s: f64,
    /// Axial condition.
    pub axial: Axial,
    /// F_r, N (towards ψ = 0).
    pub radial_load_n: f64,
    /// How the tilt about the axis across the radial load is held (issue 29).
    pub tilt: Tilt,
    /// Race control.
    pub race_control: RaceControl,
    /// Gyroscopic friction sign.
    pub gyroscopic_friction: GyroscopicFriction,
    /// How that friction is shared between the races.
    pub friction_split: FrictionSplit,
    /// The largest traction coefficient the contacts can give (µ_m of the traction
    /// curve): the gyroscopic friction of 2-7 is capped at it. Beyond, the friction
    /// cannot hold the ball's precession and the ball skids (the skidding condition 2-4);
    /// `f64::INFINITY` applies 2-7 without a cap, as the seed does.
    pub max_friction: f64,
}

/// One ball of the solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallLoad {
    /// ψ, azimuth, rad.
    pub azimuth_rad: f64,
    /// Equilibrium.
    pub equilibrium: BallEquilibrium,
    /// Race-control kinematics at the equilibrium angles.
    pub kinematics: RaceKinematics,
    /// M_g = J ω_m ω_r, N·m.
    pub gyroscopic_moment_nm: f64,
    /// |µ| needed to resist M_g (2-7).
    pub friction_needed: f64,
}

/// Work counters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LoadStats {
    /// Fixed-point iterations (load ↔ kinematics).
    pub fixed_point_iterations: usize,
    /// Ring Newton iterations, summed.
    pub ring_iterations: usize,
    /// Ring evaluations (each solves every distinct ball), summed.
    pub ring_evaluations: usize,
}

/// The solved load distribution.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDistribution {
    /// δ_a, m.
    pub axial_deflection_m: f64,
    /// δ_r, m.
    pub radial_deflection_m: f64,
    /// ΣP_a, the axial force the balls carry, N.
    pub axial_force_n: f64,
    /// ΣP_r cos ψ, N.
    pub radial_force_n: f64,
    /// θ, the inner ring's tilt about the axis across the radial load, rad (held or
    /// solved: [`Conditions::tilt`]).
    pub tilt_rad: f64,
    /// M, the moment the balls carry about that axis, N·m: ℜ_i·Σ(P_a − (f_i D/ℜ_i)µ_i Q_i)
    /// cos ψ (Jones–Harris, pivot in the plane of the inner groove centres).
    pub moment_nm: f64,
    /// Balls in azimuth order (ψ_j = 2πj/Z).
    pub balls: Vec<BallLoad>,
    /// Each ball's quantities the last ring solve held (µ of 2-7, centrifugal
    /// coefficient, Hertz constants), in the same order: the stiffness matrix is the
    /// derivative about them (`stiffness`).
    pub params: Vec<BallParams>,
    /// Largest ring-force residual, N (0 for a held displacement).
    pub ring_residual_n: f64,
    /// Largest ball-force residual, N.
    pub ball_residual_n: f64,
    /// Work counters.
    pub stats: LoadStats,
}

/// Solve the load distribution with race-control kinematics to a fixed point.
///
/// Newton from the unloaded geometry usually converges. When it does not (a preload held
/// as a force under a large radial load at high speed: the inner contacts of some balls
/// open), the solve is continued from rest: speed and radial load are raised from zero to
/// their values in adaptive steps, each warm-started from the last; if a step cannot be
/// made smaller than 1/1000 of the way, the first error is returned.
pub fn solve(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
) -> Result<LoadDistribution, BallError> {
    solve_recorded(geom, cond, cancel, &mut None, true)
}

/// One fixed-point iteration of the load distribution as the workbench's stepper shows it
/// for one ball: the ring Newton's answer for that iteration and the ball's contact state
/// it produced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadStep {
    /// Fixed-point iteration (1-based), counted over every continuation stage.
    pub fixed_point: usize,
    /// Ring Newton iterations of this fixed-point iteration.
    pub ring_iterations: usize,
    /// Ring displacement (axial, radial), m.
    pub ring_m: [f64; 2],
    /// The ring Newton's final force residual, N.
    pub ring_residual_n: f64,
    /// The ball's contact angles (inner, outer), rad.
    pub angles_rad: [f64; 2],
    /// The ball's contact loads (inner, outer), N.
    pub loads_n: [f64; 2],
    /// The friction coefficient of (2-7) this iteration was solved with.
    pub friction: f64,
    /// Largest change of any ball's contact angle over the iteration, rad.
    pub angle_change_rad: f64,
    /// Largest relative change of any ball's contact loads.
    pub load_change: f64,
}

/// [`solve`], recording each fixed-point iteration of ball `ball` (0-based) for the
/// stepper.
pub fn solve_traced(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    ball: usize,
) -> Result<(LoadDistribution, Vec<LoadStep>), BallError> {
    let mut trace = Some((ball, Vec::new()));
    let l = solve_recorded(geom, cond, cancel, &mut trace, true)?;
    Ok((l, trace.map(|t| t.1).unwrap_or_default()))
}

#[cfg(test)]
mod tests;
