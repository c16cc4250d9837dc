//! The ball bearing's 5×5 stiffness matrix at the operating point (issue 29): rows
//! F_x, F_y, F_z, M_x, M_y, columns x, y, z, θ_x, θ_y, SI; x along the radial load
//! (ψ = 0), z the axis (positive as δ_a), right-handed.
//!
//! # Analytic (the ring Newton's Jacobian, the balls condensed)
//! A ring displacement q = (x, y, z, θ_x, θ_y) moves the inner groove centre of the ball
//! at ψ by T_ψ q, T_ψ = [[0, 0, 1, ℜ_i sin ψ, −ℜ_i cos ψ], [cos ψ, sin ψ, 0, 0, 0]] in
//! its (axial, radial) plane (Jones–Harris, as the ring Newton: the tilt's radial move is
//! of the second order). The balls carry F = Σ_ψ (T_ψᵀ P_ψ + h_ψ µ_i Q_i), P the inner
//! ring's force on the ball and h_ψ = f_i D (0, 0, 0, −sin ψ, cos ψ) the arm of the
//! inner friction couple (the moment row of the ring Newton, `load_distribution`). Its
//! total derivative with every ball's position following through its own equilibrium
//! (the balls' internal DOFs condensed out, K = J_rr − J_rb J_bb⁻¹ J_br, which is what
//! each ball's `ring_stiffness` dP/dc = M_i(I + J_b⁻¹M_i) and `inner_load_gradient` are):
//!
//! ```text
//! K = Σ_ψ T_ψᵀ (dP/dc) T_ψ + h_ψ µ_i (dQ_i/dc) T_ψ.
//! ```
//!
//! The centrifugal force (m ω_m² R_b, with R_b following the ball) and the gyroscopic
//! friction enter through each ball's equilibrium. What is held at the operating point,
//! as within one ring solve of the fixed point: the orbital and spin speeds of race
//! control, the Hertz constants at the operating angles and µ of 2-7 (a stiffness is a
//! small-displacement derivative about the running state; those follow the load through
//! the kinematics only, a second-order effect the seed's fixed point has in its outer
//! loop). y and θ_x are not DOFs the (planar) load solve moves, but every ball is
//! summed at its own ψ here, so their rows and columns are the bearing's.
//!
//! # Finite difference (`solver.stiffness = "both"`, `rollbench stiffness --check-fd`)
//! Central differences of F re-solved with every ball's equilibrium at q ± h e_k (steps
//! 1e-9 m and 1e-9 m/ℜ_i rad), the same held quantities: the check of the analytic
//! matrix, `finite_difference_max_rel` the largest |K_an − K_fd| over each row's
//! largest entry, with angles measured as ℜ_i θ and moments as M/ℜ_i so that a row's
//! entries share a unit.

use nalgebra::{Matrix2x5, SMatrix, SVector, Vector2};

use super::error::BallError;
use super::geometry::BallGeometry;
pub use super::input::StiffnessMethod;
use super::load_distribution::{solve_ball_with, LoadDistribution, OuterAlone};
use crate::bearings::stiffness::{Dof, Method, StiffnessMatrix};

/// A 5×5 matrix, rows F_x … M_y, columns x … θ_y.
pub type Matrix5 = SMatrix<f64, 5, 5>;
type Vector5 = SVector<f64, 5>;

/// What the matrix holds fixed (JSON `stiffness.held`).
pub const HELD: &str = "race-control speeds, Hertz constants and the gyroscopic friction µ at the operating point; each ball's position follows its equilibrium";

/// Where the displacements and moments are referred to (JSON
/// `stiffness.reference_point`).
pub const REFERENCE_POINT: &str = "inner ring centre in the plane of its groove centres (x along the radial load, z along the axial load)";

/// The stiffness of a solved case.
#[derive(Debug, Clone, PartialEq)]
pub struct BallStiffness {
    /// The matrix reported (analytic, or the finite differences when only they are
    /// asked for), SI.
    pub matrix: Matrix5,
    /// How.
    pub method: StiffnessMethod,
    /// The finite-difference matrix, when computed.
    pub finite_difference: Option<Matrix5>,
    /// Largest |K_an − K_fd| over its row's scale, when both are computed.
    pub finite_difference_max_rel: Option<f64>,
}

impl BallStiffness {
    /// The matrix on the shared type (its JSON `stiffness` keys and text block): the 5×5
    /// over (x, y, z, θ_x, θ_y), the method, the reference point, and the
    /// finite-difference matrix and gap when computed.
    pub fn shared(&self) -> StiffnessMatrix {
        let flat = |m: &Matrix5| -> Vec<f64> {
            (0..5)
                .flat_map(|i| (0..5).map(move |j| m[(i, j)]))
                .collect()
        };
        let method = match self.method {
            StiffnessMethod::Analytic => Method::Analytic,
            StiffnessMethod::FiniteDifference => Method::FiniteDifference,
            StiffnessMethod::Both => Method::Both,
        };
        let mut k = StiffnessMatrix::new(Dof::ALL.to_vec(), flat(&self.matrix), method);
        k.reference_point = Some(REFERENCE_POINT.to_string());
        k.fd = self.finite_difference.as_ref().map(flat);
        k.fd_max_rel = self.finite_difference_max_rel;
        k
    }
}

/// ℜ_i, the radius of the inner groove centres, m.
fn inner_centre_radius(g: &BallGeometry) -> f64 {
    g.outer_centre_radius_m + g.centre_distance_m * g.free_contact_angle_rad.cos()
}

/// T_ψ and h_ψ of the ball at `psi`.
fn maps(g: &BallGeometry, psi: f64) -> (Matrix2x5<f64>, Vector5) {
    let ri = inner_centre_radius(g);
    let (s, c) = psi.sin_cos();
    let t = Matrix2x5::new(0.0, 0.0, 1.0, ri * s, -ri * c, c, s, 0.0, 0.0, 0.0);
    let fd = g.inner_offset_m + 0.5 * g.ball_diameter_m;
    (t, Vector5::new(0.0, 0.0, 0.0, -fd * s, fd * c))
}

/// The analytic matrix (module doc).
pub fn analytic(g: &BallGeometry, load: &LoadDistribution) -> Matrix5 {
    let mut k = Matrix5::zeros();
    for (b, p) in load.balls.iter().zip(&load.params) {
        let (t, h) = maps(g, b.azimuth_rad);
        let e = &b.equilibrium;
        k += t.transpose() * e.ring_stiffness * t
            + h * ((e.inner_load_gradient * p.friction).transpose() * t);
    }
    k
}

/// The balls' forces and moments on the ring displaced by `q` from the operating point,
/// every ball re-solved with the operating point's held quantities.
fn forces(g: &BallGeometry, load: &LoadDistribution, q: &Vector5) -> Result<Vector5, BallError> {
    let a0 = g.free_contact_angle_rad;
    let phi = load.tilt_rad * inner_centre_radius(g);
    let qmax = load
        .balls
        .iter()
        .map(|b| b.equilibrium.inner.load_n.max(b.equilibrium.outer.load_n))
        .fold(1.0, f64::max);
    let mut f = Vector5::zeros();
    for (j, (b, p)) in load.balls.iter().zip(&load.params).enumerate() {
        let (t, h) = maps(g, b.azimuth_rad);
        let cp = b.azimuth_rad.cos();
        let c0 = Vector2::new(
            g.centre_distance_m * a0.sin() + load.axial_deflection_m + phi * cp,
            g.centre_distance_m * a0.cos() + load.radial_deflection_m * cp,
        );
        let e = solve_ball_with(
            g,
            c0 + t * q,
            *p,
            OuterAlone::new(g, p),
            Some(b.equilibrium.position),
            1e-13 * qmax,
            j,
        )?;
        f += t.transpose() * e.ring_force + h * (p.friction * e.inner.load_n);
    }
    Ok(f)
}

/// Central finite differences of [`forces`] (module doc).
pub fn finite_difference(g: &BallGeometry, load: &LoadDistribution) -> Result<Matrix5, BallError> {
    let ri = inner_centre_radius(g);
    let mut k = Matrix5::zeros();
    for col in 0..5 {
        let step = if col < 3 { 1e-9 } else { 1e-9 / ri };
        let mut q = Vector5::zeros();
        q[col] = step;
        let fp = forces(g, load, &q)?;
        let fm = forces(g, load, &(-q))?;
        k.set_column(col, &((fp - fm) / (2.0 * step)));
    }
    Ok(k)
}

/// Largest |a − b| over each row's largest entry of `a`, angles as ℜ_i θ and moments as
/// M/ℜ_i (so a row's entries share a unit).
pub fn max_rel(g: &BallGeometry, a: &Matrix5, b: &Matrix5) -> f64 {
    let ri = inner_centre_radius(g);
    let s = Vector5::new(1.0, 1.0, 1.0, 1.0 / ri, 1.0 / ri);
    let scale = |m: &Matrix5| Matrix5::from_fn(|r, c| m[(r, c)] * s[r] * s[c]);
    let (a, b) = (scale(a), scale(b));
    (0..5)
        .map(|r| {
            let row = a.row(r).amax().max(f64::MIN_POSITIVE);
            (a.row(r) - b.row(r)).amax() / row
        })
        .fold(0.0, f64::max)
}

/// The stiffness of a solved case by `method`.
pub fn stiffness(
    g: &BallGeometry,
    load: &LoadDistribution,
    method: StiffnessMethod,
) -> Result<BallStiffness, BallError> {
    let an = analytic(g, load);
    let fd = match method {
        StiffnessMethod::Analytic => None,
        _ => Some(finite_difference(g, load)?),
    };
    Ok(BallStiffness {
        matrix: match (method, fd) {
            (StiffnessMethod::FiniteDifference, Some(f)) => f,
            _ => an,
        },
        method,
        finite_difference_max_rel: match (method, fd) {
            (StiffnessMethod::Both, Some(f)) => Some(max_rel(g, &an, &f)),
            _ => None,
        },
        finite_difference: fd,
    })
}
