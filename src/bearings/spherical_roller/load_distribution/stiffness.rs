//! The spherical roller bearing's ring stiffness over (x, y, z) at a solved load
//! distribution (issue 29 item 3): x along the radial load (ψ = 0), y perpendicular to it
//! in the radial plane, z the bearing axis (the solver's axial direction), SI.
//!
//! # Analytic (each roller condensed in its own meridian plane)
//! The roller at azimuth ψ sees the inner ring move by (u_a, u_r) = (z, x cos ψ + y sin ψ)
//! in its (axial, radial) plane; the ring solve's unknown u = (u_a, u_r along the load)
//! reaches it as (u_a, u_r cos ψ), the same map with y = 0 (`Problem::eval_row`'s `shift`).
//! Its condensed stiffness in that plane, k_ψ = H_uu − H_uq H_qq⁻¹ H_qu evaluated with
//! the radial shift taken as the roller's own (cos ψ = 1 in the derivative), gives the
//! bearing's K = Σ_ψ T_ψᵀ k_ψ T_ψ with T_ψ = [[0, 0, 1], [cos ψ, sin ψ, 0]] (rows axial,
//! radial; columns x, y, z). The rollers at ±ψ are mirror images about the load plane (the
//! solve's unique rollers carry them with multiplicity 2), so K_xy = K_yz = 0 exactly and
//! K_yy = Σ m k_rr sin² ψ. Its x–z block is the ring Newton's own Jacobian
//! (`InertialSensitivity::ring_stiffness_n_m`): Σ m S k_ψ S with S = diag(1, cos ψ), the
//! same sum (test `xz_block_is_the_ring_jacobian`).
//!
//! Held at the operating point, as within one ring solve: the dynamic speeds (centrifugal
//! force and gyroscopic moment of each roller) and, in a double row, the floating guide
//! ring's offset in the y terms (a y displacement is antisymmetric about the load plane,
//! so the guide ring, one axial unknown, does not move to first order).
//!
//! # Finite difference (`solver.stiffness = "both"`, `rollbench stiffness --check-fd`)
//! Central differences of the ring force with every roller re-solved (all Z of them, each
//! at its own ψ, no mirror symmetry assumed) at the ring displaced by ±h along x, y and z.
//! Step rule: h = 1e-6 × the larger ring deflection |u_a|, |u_r| (floor 1e-12 m), each
//! roller solved to 1e-3 of the solve's force tolerance. The lamina law Q ∝ δ^(10/9) has
//! Q‴ ∝ δ^(−17/9): a roller (or lamina) whose approach is within a few steps of first
//! contact makes the differences' truncation large, so the step is small: measured on a
//! random load, 1.8e-3 at 1e-5·δ against 4.9e-8 at a third of it. The roller residuals
//! (≤ 1e-12 of the load, in practice far less: Newton converges quadratically) keep the
//! round-off below ~5e-7 of K at this step (test `finite_difference_step_rule`).

use nalgebra::{Matrix2, Matrix3, Vector3};

use super::problem::Problem;
use super::{Layout, LoadDistribution};
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;
use crate::numerics::newton::Factor3;

/// One unique roller's condensed stiffness in its meridian plane, bearing frame: cos ψ,
/// its multiplicity, and k (rows and columns axial, radial), N/m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneStiffness {
    /// cos ψ of the roller.
    pub cos_psi: f64,
    /// Rollers it stands for (1 on the load line and opposite it, 2 elsewhere).
    pub multiplicity: f64,
    /// ∂(axial, radial ring force)/∂(axial, radial ring shift at the roller), N/m.
    pub k: Matrix2<f64>,
}

/// The problem of a solved `ld` and its ring deflection (axial, radial), m.
fn problem_of(b: &Bearing, layout: Layout, ld: &LoadDistribution) -> (Problem, [f64; 2]) {
    let p = Problem::with_layout(b, &ld.speeds, b.solver.force_tolerance, layout);
    p.guide_offset.set(ld.warm.guide_offset_m);
    (p, ld.warm.ring)
}

/// The solved rollers' states, one per unique roller.
fn states(p: &Problem, ld: &LoadDistribution) -> Result<Vec<Vector3<f64>>, SolveError> {
    let qs: Vec<Vector3<f64>> = ld
        .warm
        .rollers
        .iter()
        .map(|q| Vector3::new(q[0], q[1], q[2]))
        .collect();
    if qs.len() != p.unique.len() {
        return Err(SolveError::Stage {
            stage: "stiffness",
            message: format!(
                "{} roller states for {} unique rollers in the problem",
                qs.len(),
                p.unique.len()
            ),
        });
    }
    Ok(qs)
}

/// Every unique roller's condensed meridian-plane stiffness (module doc).
///
/// # Errors
/// [`SolveError::Stage`] when `ld` does not hold one state per unique roller.
pub fn plane_stiffnesses(
    b: &Bearing,
    layout: Layout,
    ld: &LoadDistribution,
) -> Result<Vec<PlaneStiffness>, SolveError> {
    let (p, u) = problem_of(b, layout, ld);
    let qs = states(&p, ld)?;
    let mut out = Vec::with_capacity(qs.len());
    for (ku, q) in qs.iter().enumerate() {
        let (cphi, mult) = p.unique[ku];
        let sign = p.signs[ku];
        // The roller's own radial shift u_r cos ψ, differentiated as its own (cos ψ = 1).
        let mut ev = p.eval_row(sign, 1.0, p.local_u(ku, [u[0], u[1] * cphi]), q, true);
        if sign < 0.0 {
            // The mirrored row's frame back to the bearing's, as the ring solve does.
            ev.h_uu[(0, 1)] = -ev.h_uu[(0, 1)];
            ev.h_uu[(1, 0)] = -ev.h_uu[(1, 0)];
            for c in 0..3 {
                ev.h_uq[(0, c)] = -ev.h_uq[(0, c)];
            }
        }
        let factor = Factor3::new(&ev.h_qq, &p.scale);
        let x = factor.solve(&ev.h_uq.transpose());
        out.push(PlaneStiffness {
            cos_psi: cphi,
            multiplicity: mult,
            k: ev.h_uu - ev.h_uq * x,
        });
    }
    Ok(out)
}

/// K over (x, y, z) from the rollers' plane stiffnesses (module doc), N/m.
pub fn assemble_xyz(planes: &[PlaneStiffness]) -> Matrix3<f64> {
    let mut k = Matrix3::zeros();
    for s in planes {
        let (c, m) = (s.cos_psi, s.multiplicity);
        let s2 = (1.0 - c * c).max(0.0);
        k[(0, 0)] += m * c * c * s.k[(1, 1)];
        k[(1, 1)] += m * s2 * s.k[(1, 1)];
        k[(2, 2)] += m * s.k[(0, 0)];
        k[(0, 2)] += m * c * s.k[(1, 0)];
        k[(2, 0)] += m * c * s.k[(0, 1)];
    }
    k
}

/// The finite-difference step of the module doc's rule, m.
pub fn fd_step(ld: &LoadDistribution) -> f64 {
    let u = ld.warm.ring;
    (1e-6 * u[0].abs().max(u[1].abs())).max(1e-12)
}

/// The ring force (x, y, z) on the inner ring displaced by `d` (x, y, z) from `ld`'s
/// solution, every roller of every row re-solved at its own azimuth, N (the solver's
/// sign: ∂U/∂u, the rollers' push on the ring taken positive against the displacement).
fn ring_force(
    p: &Problem,
    u: [f64; 2],
    qs: &[Vector3<f64>],
    d: [f64; 3],
) -> Result<Vector3<f64>, SolveError> {
    let (z, _) = p.per_row;
    let rows = p.signs.len() / p.per_row.1.max(1);
    let mut f = Vector3::zeros();
    let mut iterations = 0;
    for r in 0..rows * z {
        let ku = p.unique_of(r);
        let psi = 2.0 * std::f64::consts::PI * (r % z) as f64 / z as f64; // eq. 3.1
        let (s, c) = psi.sin_cos();
        let ua = u[0] + d[2];
        let ur = u[1] * c + d[0] * c + d[1] * s;
        let mut q = qs[ku];
        let ev = p.solve_roller(
            ku,
            1.0,
            p.local_u(ku, [ua, ur]),
            &mut q,
            &mut iterations,
            None,
        )?;
        let ga = if p.signs[ku] < 0.0 {
            -ev.g_u[0]
        } else {
            ev.g_u[0]
        };
        f += Vector3::new(ev.g_u[1] * c, ev.g_u[1] * s, ga);
    }
    Ok(f)
}

/// Central finite differences of the re-solved ring force (module doc), N/m, with the
/// step used.
///
/// # Errors
/// A roller that does not converge at a displaced ring ([`SolveError`]), or `ld` without
/// one state per unique roller.
pub fn finite_difference(
    b: &Bearing,
    layout: Layout,
    ld: &LoadDistribution,
    h: f64,
) -> Result<Matrix3<f64>, SolveError> {
    let (p, u) = problem_of(b, layout, ld);
    let qs = states(&p, ld)?;
    p.roller_tol.set(1e-3 * p.tol);
    let mut k = Matrix3::zeros();
    for col in 0..3 {
        let mut d = [0.0; 3];
        d[col] = h;
        let fp = ring_force(&p, u, &qs, d)?;
        d[col] = -h;
        let fm = ring_force(&p, u, &qs, d)?;
        k.set_column(col, &((fp - fm) / (2.0 * h)));
    }
    Ok(k)
}

/// Largest |a − b| over each row's largest |a|.
pub fn max_rel(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (0..3)
        .map(|r| {
            let row = a.row(r).amax().max(f64::MIN_POSITIVE);
            (a.row(r) - b.row(r)).amax() / row
        })
        .fold(0.0, f64::max)
}
