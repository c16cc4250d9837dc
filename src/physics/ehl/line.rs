//! The 1-D transient line-contact EHL solver (seed 003 eqs. 5–9, 11, 13; the load
//! balance eq. 46), isothermal or on a given temperature field.
//!
//! **Equations** (dimensional, x along the entraining motion, side leakage neglected as
//! the seed does for its roller contacts):
//!
//!   d/dx(ρh³/(12η) dp/dx) = ū d(ρh)/dx + ∂(ρh)/∂t                          (eq. 5)
//!   h(x) = h₀ + x²/(2R) + Δ(x),  Δ by the line kernel (`kernel`)        (eqs. 6–9)
//!   η = Houpert (eq. 10), ρ = Dowson–Higginson (eq. 11), p ≥ 0 with the Swift–Stieber
//!   complementarity (eq. 13, printed as "(23)"), ∫p dx = w (eq. 46, ε_W = 0.005).
//!
//! **Scaling** (Hertz): X = x/b, P = p/p_H, H = hR/b², ρ̄ = ρ/ρ₀, η̄ = η/η₀ with b, p_H
//! the Hertz half-width and peak pressure of the load w. Then
//!
//!   d/dX(ε dP/dX) − d(ρ̄H)/dX − σ(ρ̄H − ρ̄H_prev) = 0,
//!   ε = ρ̄H³/(η̄λ),  λ = 12η₀ūR²/(b³p_H),  σ = b/(ū·Δt),
//!   H = H₀ + X²/2 + Σ_j K_{|i−j|} P_j,  Σ_j P_j ΔX = π/2.
//!
//! The squeeze term is the backward-Euler ∂(ρh)/∂t from a previous step's ρh and Δt:
//! σ → 0 (Δt → ∞) is the steady problem exactly.
//!
//! **Discretisation**: uniform grid; Poiseuille term by central differences with ε at
//! the mid-points (mean of the nodes), the wedge term by second-order upwind differences
//! (first-order at the first interior node): the upwind bias keeps the Hertz zone, where
//! ε → 0 and the equation is a pure transport, free of odd–even oscillation. p = 0 at
//! both ends.
//!
//! **Solver**: semismooth Newton on the complementarity form min(P_i, −r_i) = 0 of the
//! Swift–Stieber condition (P ≥ 0, the Reynolds residual r ≤ 0, P·r = 0: a node cavitates
//! where holding P = 0 leaves the flow wanting a negative pressure), with H₀ as the extra
//! unknown closed by the load balance. The Jacobian is exact: the Reynolds rows carry the
//! dependence on every pressure through ε(H) and ρ̄H with H through the dense kernel.
//! Dense LU with partial pivoting (blocked: `numerics::dense_lu`); a backtracking line
//! search on the residual norm. By default (the fastest, measured) the chord path
//! ([`NewtonStrategy::Chord`], Shamanskii) reuses an LU as the Newton matrix while its
//! steps contract the residual, and the LU is carried to a warm start on the same scaled
//! grid. The exact Jacobian factorised at every iteration ([`NewtonStrategy::Full`]) is
//! the reference path; Newton–Krylov ([`NewtonStrategy::Krylov`]) assembles the exact
//! Jacobian at every iteration and finds its step by GMRES preconditioned with the last
//! LU.
//! Cold start: Hertz pressure with a small outlet tail and H₀ from Pan–Hamrock's central
//! film; warm start: a previous solution interpolated in Hertz-scaled X.
//!
//! The film is clamped at h ≥ 0 where an iterate would make it negative (ε and ρh then
//! use 0, their derivative with H is dropped), and the clamps are counted.

use super::kernel::{deflection_symmetric, line_kernel, symmetric_row};
use crate::numerics::dense_lu::{dot, lu_factor, lu_solve};
use crate::numerics::gmres::{gmres, GmresWork};
use crate::physics::contact::line::line_contact_reduced;
use crate::physics::lubrication::film::{pan_hamrock_central, FilmInputs};
use crate::physics::lubrication::houpert::{Houpert, Isothermal};
use std::f64::consts::PI;
use std::sync::Arc;
use thiserror::Error;

/// Largest grid the dense Newton accepts (`nodes`): its LU is O(n³), about 1.4·10⁹ flops
/// per iteration at 1601 nodes.
pub const MAX_NODES: usize = 1601;
/// Smallest grid (`nodes`) that resolves a Hertz zone at all.
pub const MIN_NODES: usize = 41;
/// ε_W of eq. 46: the relative load-balance tolerance.
pub const LOAD_BALANCE_TOLERANCE: f64 = 0.005;

/// The squeeze term's history: the previous step's ρh and the time step.
#[derive(Debug, Clone, PartialEq)]
pub struct LineEhlSqueeze {
    /// Δt from the previous step, s (> 0; +∞ is the steady problem).
    pub time_step_s: f64,
    /// x of the previous step's nodes, m, increasing.
    pub previous_x_m: Vec<f64>,
    /// ρh at those nodes, kg/m² (outside their span ρh is extended by its end values
    /// plus the rigid parabola's growth, see [`LineEhlSqueeze::rho_h_at`]).
    pub previous_rho_h_kg_m2: Vec<f64>,
}

impl LineEhlSqueeze {
    /// ρh of the previous step at x (m), linear between its nodes; beyond its ends the
    /// end value (the caller keeps the domain fixed along a cycle, so this is only the
    /// first/last node's neighbourhood).
    fn rho_h_at(&self, x: f64) -> f64 {
        interpolate(&self.previous_x_m, &self.previous_rho_h_kg_m2, x)
    }
}

/// A line-contact EHL problem, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct LineEhlProblem {
    /// R, reduced radius in the entraining direction, m.
    pub radius_m: f64,
    /// E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹, Pa (E′ = 2E*).
    pub reduced_modulus_pa: f64,
    /// ū = (u₁ + u₂)/2, entrainment speed, m/s (> 0, in +x).
    pub entrainment_m_s: f64,
    /// Δu = u₁ − u₂, sliding speed, m/s (for friction and heating; the isothermal
    /// Reynolds equation does not use it).
    pub sliding_m_s: f64,
    /// w, load per unit length, N/m.
    pub load_per_length_n_m: f64,
    /// The lubricant (eqs. 10, 11); η₀ and ρ₀ at its reference temperature.
    pub rheology: Houpert,
    /// Inlet end of the domain, m (< 0; flooded: 4–5 Hertz half-widths upstream).
    pub x_inlet_m: f64,
    /// Outlet end of the domain, m (> 0).
    pub x_outlet_m: f64,
    /// Number of nodes.
    pub nodes: usize,
    /// The squeeze term's history; `None` is the steady problem.
    pub squeeze: Option<LineEhlSqueeze>,
    /// Temperature per node, K (the thermal coupling's input); `None` is isothermal at the
    /// lubricant's reference temperature.
    pub temperature_k: Option<Vec<f64>>,
    /// Newton iterations allowed.
    pub max_iterations: usize,
    /// Convergence: the largest Newton pressure update relative to p_H, and the film
    /// constant's update relative to the central film.
    pub tolerance: f64,
}

/// A converged line-contact EHL solution, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct LineEhlSolution {
    /// Node positions, m.
    pub x_m: Vec<f64>,
    /// p, Pa.
    pub pressure_pa: Vec<f64>,
    /// The dry Hertz pressure of the same load, Pa.
    pub hertz_pressure_pa: Vec<f64>,
    /// h, m.
    pub film_m: Vec<f64>,
    /// η at each node, Pa·s.
    pub viscosity_pa_s: Vec<f64>,
    /// ρ at each node, kg/m³.
    pub density_kg_m3: Vec<f64>,
    /// h at x = 0 (linear interpolation), m.
    pub central_film_m: f64,
    /// min h over the domain, m.
    pub min_film_m: f64,
    /// max p, Pa.
    pub max_pressure_pa: f64,
    /// Hertz peak pressure p_H, Pa.
    pub hertz_max_pressure_pa: f64,
    /// Hertz half-width b, m.
    pub hertz_half_width_m: f64,
    /// The film constant h₀ of eq. 6 with the kernel's reference absorbed in it, m.
    pub h0_m: f64,
    /// Newton iterations taken (full and chord steps).
    pub iterations: usize,
    /// Jacobians assembled and factorised (≤ `iterations`; 0 when a warm start's
    /// factorisation carried the whole solve).
    pub factorisations: usize,
    /// (∫p dx − w)/w.
    pub load_balance_residual: f64,
    /// Nodes whose film an iterate made negative (clamped to 0), summed over iterations.
    pub clamps: usize,
    /// The last LU factorisation of the Newton matrix, for a warm start on the same grid
    /// (a cache, not part of the answer: it compares equal to any other).
    pub factorisation: Option<Arc<Factorisation>>,
}

/// The LU factors of a Newton matrix and the Hertz-scaled grid they belong to (a later
/// solve on the same grid reuses them as its chord matrix: [`NewtonStrategy::Chord`]).
#[derive(Clone)]
pub struct Factorisation {
    n: usize,
    x0: f64,
    dx: f64,
    lu: Vec<f64>,
    piv: Vec<usize>,
}

impl Factorisation {
    /// Whether these factors belong to the scaled grid (n nodes from X₀ in steps ΔX).
    fn fits(&self, n: usize, x0: f64, dx: f64) -> bool {
        self.n == n && (self.x0 - x0).abs() <= 1e-9 * x0.abs() && (self.dx - dx).abs() <= 1e-9 * dx
    }
}

impl std::fmt::Debug for Factorisation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "Factorisation {{ n: {}, x0: {}, dx: {} }}",
            self.n, self.x0, self.dx
        )
    }
}

/// A cache: two solutions with the same numbers are equal whatever factors they carry.
impl PartialEq for Factorisation {
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

/// How the Newton iteration uses its matrix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NewtonStrategy {
    /// The exact Jacobian assembled and factorised at every iteration, with the
    /// backtracking line search (the reference path).
    Full,
    /// Shamanskii's chord method: one factorisation reused (from a warm start's solution
    /// on the same grid too) while each chord step cuts the residual by at least
    /// [`CHORD_CONTRACTION`]; a step that does not is discarded and the exact Jacobian
    /// refactorised (then a full, line-searched Newton step). Converges to the same root
    /// (the residual is the same; only the matrix that finds the step differs).
    Chord,
    /// Newton–Krylov (inexact Newton, Dembo–Eisenstat–Steihaug 1982): the exact Jacobian
    /// assembled at every iteration (cheap: O(n²)) and its Newton step found by GMRES
    /// preconditioned with the last factorised Newton matrix (of this solve or, on the
    /// same grid, of the warm start), to a residual [`KRYLOV_TOLERANCE`] of ‖Φ‖; when
    /// GMRES needs more than [`KRYLOV_ITERATIONS`] products the current Jacobian is
    /// factorised instead (O(n³)) and becomes the preconditioner. The steps are Newton's
    /// to that tolerance, line-searched as [`NewtonStrategy::Full`]'s, so the iterates
    /// follow the reference path and reach the same root with few factorisations.
    Krylov,
}

/// The cold start's outlet pressure tail at X = 1, in p_H (see `solve_line_ehl_with`):
/// large enough to put the start's meniscus beyond the solution's (1.1–1.3 half-widths on
/// the test grid), small against the Hertz pressure it is added to.
pub const COLD_START_TAIL: f64 = 0.02;

/// GMRES's relative residual for a Newton–Krylov step: the forcing term of the inexact
/// Newton method (a step this accurate converges as the exact Newton step does until
/// ‖Φ‖ is 10⁻⁶ of its start, far beyond the step tolerance 10⁻⁸ the solves use).
pub const KRYLOV_TOLERANCE: f64 = 1e-6;

/// GMRES products allowed before the Jacobian is factorised instead: at 401 nodes a
/// product with the dense matrix and a solve with the old factors cost about 1/25 of a
/// factorisation (measured, `benches/line_ehl.rs`), so beyond about a dozen a fresh
/// factorisation is cheaper, and the preconditioner has drifted too far to be kept.
pub const KRYLOV_ITERATIONS: usize = 12;

/// A chord step is kept when it cuts the merit ‖Φ‖ to at most this fraction (linear
/// convergence at rate ≤ 0.5 bounds the remaining error by the last step, so the
/// convergence test on the step stays valid).
pub const CHORD_CONTRACTION: f64 = 0.5;

impl LineEhlSolution {
    /// ρh per node, kg/m²: the next step's squeeze history.
    pub fn rho_h_kg_m2(&self) -> Vec<f64> {
        self.density_kg_m3
            .iter()
            .zip(&self.film_m)
            .map(|(r, h)| r * h)
            .collect()
    }

    /// This solution as the squeeze history of a step Δt later.
    pub fn squeeze_history(&self, time_step_s: f64) -> LineEhlSqueeze {
        LineEhlSqueeze {
            time_step_s,
            previous_x_m: self.x_m.clone(),
            previous_rho_h_kg_m2: self.rho_h_kg_m2(),
        }
    }
}

/// Why a line-contact EHL solve has no answer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LineEhlError {
    /// An input outside its range.
    #[error("line EHL input {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The field (units in its name).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: String,
    },
    /// Newton did not converge.
    #[error(
        "line EHL did not converge in {iterations} iterations: last pressure update \
         {step:.3e} of p_H (tolerance {tolerance:.1e}), Reynolds residual {residual:.3e}, \
         load balance {load_balance:.3e} (ε_W {eps_w}); the contact: w = {load_n_m:.4e} N/m, \
         p_H = {hertz_pa:.4e} Pa, b = {half_width_m:.4e} m, ū = {speed_m_s:.4e} m/s"
    )]
    NotConverged {
        /// Iterations taken.
        iterations: usize,
        /// The last pressure update relative to p_H.
        step: f64,
        /// The tolerance asked.
        tolerance: f64,
        /// The last residual norm (scaled).
        residual: f64,
        /// The last load balance residual.
        load_balance: f64,
        /// ε_W.
        eps_w: f64,
        /// w, N/m.
        load_n_m: f64,
        /// p_H, Pa.
        hertz_pa: f64,
        /// b, m.
        half_width_m: f64,
        /// ū, m/s.
        speed_m_s: f64,
    },
    /// The Newton matrix was singular (or an iterate not finite).
    #[error(
        "line EHL Newton matrix singular or not finite at iteration {iteration} \
         (w = {load_n_m:.4e} N/m, p_H = {hertz_pa:.4e} Pa, ū = {speed_m_s:.4e} m/s)"
    )]
    Singular {
        /// The iteration.
        iteration: usize,
        /// w, N/m.
        load_n_m: f64,
        /// p_H, Pa.
        hertz_pa: f64,
        /// ū, m/s.
        speed_m_s: f64,
    },
}

fn out_of_range(field: &'static str, value: f64, allowed: impl Into<String>) -> LineEhlError {
    LineEhlError::OutOfRange {
        field,
        value,
        allowed: allowed.into(),
    }
}

fn positive(x: f64) -> bool {
    x > 0.0 && x.is_finite()
}

impl LineEhlProblem {
    /// Check every input; the message names the field and its allowed range.
    pub fn validate(&self) -> Result<(), LineEhlError> {
        let pos = |field, v: f64| {
            if positive(v) {
                Ok(())
            } else {
                Err(out_of_range(field, v, "finite and > 0"))
            }
        };
        pos("radius_m", self.radius_m)?;
        pos("reduced_modulus_pa", self.reduced_modulus_pa)?;
        pos("entrainment_m_s", self.entrainment_m_s)?;
        pos("load_per_length_n_m", self.load_per_length_n_m)?;
        pos("tolerance", self.tolerance)?;
        if !self.sliding_m_s.is_finite() {
            return Err(out_of_range("sliding_m_s", self.sliding_m_s, "finite"));
        }
        self.rheology
            .validate()
            .map_err(|e| out_of_range("rheology", f64::NAN, e.to_string()))?;
        if !(self.x_inlet_m < 0.0 && self.x_inlet_m.is_finite()) {
            return Err(out_of_range("x_inlet_m", self.x_inlet_m, "finite and < 0"));
        }
        if !positive(self.x_outlet_m) {
            return Err(out_of_range(
                "x_outlet_m",
                self.x_outlet_m,
                "finite and > 0",
            ));
        }
        if !(MIN_NODES..=MAX_NODES).contains(&self.nodes) {
            return Err(out_of_range(
                "nodes",
                self.nodes as f64,
                format!("{MIN_NODES} to {MAX_NODES} (the dense Newton's work bound)"),
            ));
        }
        if self.max_iterations == 0 {
            return Err(out_of_range("max_iterations", 0.0, "≥ 1"));
        }
        if let Some(t) = &self.temperature_k {
            if t.len() != self.nodes {
                return Err(out_of_range(
                    "temperature_k",
                    t.len() as f64,
                    format!("one temperature per node ({} values)", self.nodes),
                ));
            }
            if let Some(bad) = t.iter().find(|t| !(**t > 138.0 && t.is_finite())) {
                return Err(out_of_range(
                    "temperature_k",
                    *bad,
                    "finite and above 138 K (Roelands's pole)",
                ));
            }
        }
        if let Some(s) = &self.squeeze {
            if !(s.time_step_s > 0.0) {
                return Err(out_of_range(
                    "squeeze.time_step_s",
                    s.time_step_s,
                    "> 0 (+∞ is the steady problem)",
                ));
            }
            if s.previous_x_m.len() != s.previous_rho_h_kg_m2.len() || s.previous_x_m.len() < 2 {
                return Err(out_of_range(
                    "squeeze.previous_rho_h_kg_m2",
                    s.previous_rho_h_kg_m2.len() as f64,
                    "as many values as previous_x_m, at least 2",
                ));
            }
            if s.previous_x_m.windows(2).any(|w| !(w[1] > w[0]))
                || s.previous_rho_h_kg_m2.iter().any(|v| !v.is_finite())
            {
                return Err(out_of_range(
                    "squeeze.previous_x_m",
                    f64::NAN,
                    "increasing positions with finite ρh",
                ));
            }
        }
        Ok(())
    }
}

/// Linear interpolation of (xs, ys) at x, clamped to the end values outside.
fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    if n == 0 {
        return 0.0;
    }
    if x <= xs[0] {
        return ys[0];
    }
    if x >= xs[n - 1] {
        return ys[n - 1];
    }
    let k = xs.partition_point(|&v| v <= x).clamp(1, n - 1);
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    ys[k - 1] + t * (ys[k] - ys[k - 1])
}

/// dρ/dp of eq. 11 (Dowson–Higginson), kg/m³/Pa: ρ₀·0.6·10⁻⁹/(1 + 1.7·10⁻⁹p)² times the
/// thermal factor; 0 for p < 0 (where ρ is held at its ambient value).
fn density_slope(rheology: &Houpert, p: f64, t: f64) -> f64 {
    if p < 0.0 {
        return 0.0;
    }
    let d = 1.0 + 1.7e-9 * p;
    rheology.density_kg_m3 * 0.6e-9 / (d * d)
        * (1.0 - 0.65e-3 * (t - rheology.reference_temperature_k))
}

/// Per-node fluid state in scaled variables.
struct Fluid {
    rho: Vec<f64>,
    rho_p: Vec<f64>,
    eta: Vec<f64>,
    /// (dη/dP)/η.
    eta_log_p: Vec<f64>,
}

/// The scaled problem.
struct Scaled<'a> {
    n: usize,
    dx: f64,
    x: Vec<f64>,
    /// The kernel row written out both ways ([`symmetric_row`]): row i of the kernel
    /// matrix is `kernel[n − 1 − i .. 2n − 1 − i]`.
    kernel: Vec<f64>,
    lambda: f64,
    sigma: f64,
    /// ρ̄H of the previous step per node (0 without squeeze).
    prev: Vec<f64>,
    laws: Vec<Isothermal>,
    temps: Vec<f64>,
    rheology: &'a Houpert,
    p_h: f64,
    rho0: f64,
    eta0: f64,
}

impl Scaled<'_> {
    fn fluid(&self, p: &[f64], f: &mut Fluid) {
        for i in 0..self.n {
            let pd = self.p_h * p[i];
            let t = self.temps[i];
            f.rho[i] = self.rheology.density_kg_m3(pd, t) / self.rho0;
            f.rho_p[i] = density_slope(self.rheology, pd, t) * self.p_h / self.rho0;
            let law = &self.laws[i];
            let eta = law.viscosity_pa_s(pd);
            f.eta[i] = eta / self.eta0;
            f.eta_log_p[i] = if pd < 0.0 {
                0.0
            } else {
                law.viscosity_slope_pa_s_per_pa(pd) / eta * self.p_h
            };
        }
    }

    /// Film H, its clamp mask and count.
    fn film(&self, p: &[f64], h0: f64, h: &mut [f64], clamped: &mut [bool]) -> usize {
        deflection_symmetric(&self.kernel, p, h);
        let mut count = 0;
        for i in 0..self.n {
            let v = h0 + 0.5 * self.x[i] * self.x[i] + h[i];
            if v < 0.0 {
                h[i] = 0.0;
                clamped[i] = true;
                count += 1;
            } else {
                h[i] = v;
                clamped[i] = false;
            }
        }
        count
    }

    /// The complementarity residual Φ (n + 1 values: nodes, then the load balance) and,
    /// when `jac` is given, its Jacobian (row-major (n+1)²). Returns (‖Φ‖₂, load residual,
    /// clamps).
    fn residual(
        &self,
        p: &[f64],
        h0: f64,
        phi: &mut [f64],
        mut jac: Option<&mut [f64]>,
        ws: &mut Work,
    ) -> (f64, f64, usize) {
        let n = self.n;
        let m = n + 1;
        let dx = self.dx;
        self.fluid(p, &mut ws.fluid);
        let clamps = self.film(p, h0, &mut ws.h, &mut ws.clamped);
        let f = &ws.fluid;
        let h = &ws.h;
        for i in 0..n {
            ws.eps[i] = f.rho[i] * h[i].powi(3) / (f.eta[i] * self.lambda);
            ws.q[i] = f.rho[i] * h[i];
        }
        if let Some(j) = jac.as_deref_mut() {
            j.iter_mut().for_each(|v| *v = 0.0);
        }
        let inv_dx2 = 1.0 / (dx * dx);
        // The Reynolds residual r_i, scaled by ΔX so that its wedge part is a ρ̄H
        // difference (order H) like the other rows' order-one entries.
        for i in 0..n {
            if i == 0 || i == n - 1 {
                phi[i] = p[i];
                if let Some(j) = jac.as_deref_mut() {
                    j[i * m + i] = 1.0;
                }
                continue;
            }
            let e_plus = 0.5 * (ws.eps[i] + ws.eps[i + 1]);
            let e_minus = 0.5 * (ws.eps[i - 1] + ws.eps[i]);
            let pois = (e_plus * (p[i + 1] - p[i]) - e_minus * (p[i] - p[i - 1])) * inv_dx2;
            // Upwind wedge coefficients on q_k = ρ̄H_k.
            let (wk, wc): (&[usize], [f64; 3]) = if i >= 2 {
                (&[i, i - 1, i - 2][..], [1.5 / dx, -2.0 / dx, 0.5 / dx])
            } else {
                (&[i, i - 1][..], [1.0 / dx, -1.0 / dx, 0.0])
            };
            let mut wedge = 0.0;
            for (k, c) in wk.iter().zip(wc) {
                wedge += c * ws.q[*k];
            }
            let squeeze = self.sigma * (ws.q[i] - self.prev[i]);
            // Row scale: the Poiseuille diagonal (ε₊ + ε₋)/ΔX brought to order one, so
            // that the merit ‖Φ‖ weighs the inlet's rows like the Hertz zone's (the
            // Newton step is invariant to it; its derivative is left out of the
            // Jacobian, exact at the solution where r = 0).
            let c = 1.0 / (1.0 + (e_plus + e_minus) / dx);
            let r = (pois - wedge - squeeze) * dx * c;
            // Swift–Stieber complementarity: min(P, −r).
            let cavitated = p[i] < -r;
            phi[i] = if cavitated { p[i] } else { -r };
            let Some(j) = jac.as_deref_mut() else {
                continue;
            };
            let row = &mut j[i * m..(i + 1) * m];
            if cavitated {
                row[i] = 1.0;
                continue;
            }
            // −∂r/∂(P, H₀), all scaled by ΔX.
            let s = -dx * c;
            // Direct Poiseuille dependence on P.
            row[i + 1] += s * e_plus * inv_dx2;
            row[i] -= s * (e_plus + e_minus) * inv_dx2;
            row[i - 1] += s * e_minus * inv_dx2;
            // Through ε_k (k = i−1, i, i+1) and q_k (k = i−2 … i).
            let g = 0.5 * (p[i + 1] - p[i]) * inv_dx2;
            let fm = 0.5 * (p[i] - p[i - 1]) * inv_dx2;
            let mut coef_eps = [(i - 1, -fm), (i, g - fm), (i + 1, g)];
            let mut coef_q: [(usize, f64); 3] = [(i, 0.0), (i - 1, 0.0), (i - 1, 0.0)];
            for (slot, (k, c)) in wk.iter().zip(wc).enumerate() {
                coef_q[slot] = (*k, -c);
            }
            coef_q[0].1 -= self.sigma;
            if i < 2 {
                coef_q[2].1 = 0.0;
            }
            // Local (diagonal) parts: ∂ε_k/∂P_k = ε_k(ρ'/ρ − η'/η), ∂q_k/∂P_k = ρ'H.
            for (k, c) in coef_eps.iter() {
                let d_eps = ws.eps[*k] * (f.rho_p[*k] / f.rho[*k] - f.eta_log_p[*k]);
                row[*k] += s * c * d_eps;
            }
            for (k, c) in coef_q.iter() {
                row[*k] += s * c * f.rho_p[*k] * h[*k];
            }
            // Through H_k: ∂ε_k/∂H_k = 3ε_k/H_k, ∂q_k/∂H_k = ρ̄_k; ∂H_k/∂P_j = K_{|k−j|},
            // ∂H_k/∂H₀ = 1 (none where the film is clamped).
            for e in coef_eps.iter_mut() {
                let k = e.0;
                e.1 = if ws.clamped[k] || h[k] <= 0.0 {
                    0.0
                } else {
                    e.1 * 3.0 * ws.eps[k] / h[k]
                };
            }
            // ρ̄H is linear in H: its slope ρ̄ is kept at a clamped node too (the
            // one-sided derivative), which keeps the Newton matrix regular when an
            // iterate closes the film.
            for e in coef_q.iter_mut() {
                e.1 *= f.rho[e.0];
            }
            // The coefficients of H_k summed per node k (i−2 … i+1), then one pass of the
            // kernel row per k: a contiguous run of the symmetric row (it vectorises).
            let mut through_h = [0.0; 4];
            for (k, c) in coef_eps.iter().chain(coef_q.iter()) {
                through_h[*k + 2 - i] += s * c;
            }
            for (slot, a) in through_h.iter().enumerate() {
                let a = *a;
                if a == 0.0 || slot + i < 2 {
                    continue;
                }
                let k = slot + i - 2;
                for (v, kk) in row[..n].iter_mut().zip(&self.kernel[n - 1 - k..]) {
                    *v += a * kk;
                }
                row[n] += a;
            }
        }
        // Load balance (eq. 46) in Hertz units: Σ P ΔX = π/2 (w = π b p_H / 2).
        let load: f64 = p.iter().sum::<f64>() * dx;
        let load_residual = load / (0.5 * PI) - 1.0;
        phi[n] = load_residual;
        if let Some(j) = jac {
            for jj in 0..n {
                j[n * m + jj] = dx / (0.5 * PI);
            }
        }
        let norm = phi.iter().map(|v| v * v).sum::<f64>().sqrt();
        (norm, load_residual, clamps)
    }
}

/// Scratch arrays of one solve.
struct Work {
    fluid: Fluid,
    h: Vec<f64>,
    clamped: Vec<bool>,
    eps: Vec<f64>,
    q: Vec<f64>,
}

impl Work {
    fn new(n: usize) -> Self {
        Work {
            fluid: Fluid {
                rho: vec![0.0; n],
                rho_p: vec![0.0; n],
                eta: vec![0.0; n],
                eta_log_p: vec![0.0; n],
            },
            h: vec![0.0; n],
            clamped: vec![false; n],
            eps: vec![0.0; n],
            q: vec![0.0; n],
        }
    }
}

/// out = A v for the row-major m × m matrix A.
fn dense_product(a: &[f64], v: &[f64], out: &mut [f64], m: usize) {
    for (o, row) in out.iter_mut().zip(a.chunks_exact(m)) {
        *o = dot(row, v);
    }
}

/// Solve a line-contact EHL problem, optionally warm-started from a previous solution
/// (its pressure is carried over in Hertz-scaled X, its film constant in film units and,
/// on the same scaled grid, its factorised Newton matrix): the chord path
/// ([`NewtonStrategy::Chord`]). Measured with `examples/ehl_timing.rs` on a quiet machine
/// (references.md's case, 401 nodes, medians): cold 28.5 ms against Krylov's 38.0 and
/// Full's 31.2; a warm step 7.9 ms against 10.1 and 12.6 (the targets 50 and
/// 10 ms). Every path reaches the same root: tests `chord_path_agrees_with_the_reference_
/// path*` and `krylov_path_agrees_with_the_reference_path`.
pub fn solve_line_ehl(
    problem: &LineEhlProblem,
    warm: Option<&LineEhlSolution>,
) -> Result<LineEhlSolution, LineEhlError> {
    solve_line_ehl_with(problem, warm, NewtonStrategy::Chord)
}

/// [`solve_line_ehl`] with the Newton strategy chosen ([`NewtonStrategy::Full`] is the
/// reference path the chord path is tested against).
pub fn solve_line_ehl_with(
    problem: &LineEhlProblem,
    warm: Option<&LineEhlSolution>,
    strategy: NewtonStrategy,
) -> Result<LineEhlSolution, LineEhlError> {
    problem.validate()?;
    let e_star = problem.reduced_modulus_pa;
    let r = problem.radius_m;
    let w = problem.load_per_length_n_m;
    let u = problem.entrainment_m_s;
    let hertz = line_contact_reduced(w, r, e_star);
    let (b, p_h) = (hertz.half_width_m, hertz.max_pressure_pa);
    let n = problem.nodes;
    let x0 = problem.x_inlet_m / b;
    let x1 = problem.x_outlet_m / b;
    let dx = (x1 - x0) / (n - 1) as f64;
    let x: Vec<f64> = (0..n).map(|i| x0 + i as f64 * dx).collect();
    let rh = &problem.rheology;
    let t_ref = rh.reference_temperature_k;
    let temps: Vec<f64> = match &problem.temperature_k {
        Some(t) => t.clone(),
        None => vec![t_ref; n],
    };
    let eta0 = rh.viscosity_pa_s;
    let rho0 = rh.density_kg_m3;
    let film_scale = b * b / r;
    let (sigma, prev) = match &problem.squeeze {
        Some(s) if s.time_step_s.is_finite() => {
            let prev = x
                .iter()
                .map(|xi| s.rho_h_at(xi * b) / (rho0 * film_scale))
                .collect();
            (b / (u * s.time_step_s), prev)
        }
        _ => (0.0, vec![0.0; n]),
    };
    let scaled = Scaled {
        n,
        dx,
        kernel: symmetric_row(&line_kernel(n, dx)),
        lambda: 12.0 * eta0 * u * r * r / (b * b * b * p_h),
        sigma,
        prev,
        laws: temps.iter().map(|&t| rh.at_temperature(t)).collect(),
        temps,
        rheology: rh,
        p_h,
        rho0,
        eta0,
        x,
    };

    // Start: a warm solution's pressure in scaled X, or Hertz.
    let mut p: Vec<f64> = match warm {
        Some(s) if !s.x_m.is_empty() && s.hertz_max_pressure_pa > 0.0 => {
            let xs: Vec<f64> = s.x_m.iter().map(|v| v / s.hertz_half_width_m).collect();
            let ps: Vec<f64> = s
                .pressure_pa
                .iter()
                .map(|v| v / s.hertz_max_pressure_pa)
                .collect();
            scaled
                .x
                .iter()
                .map(|&xi| interpolate(&xs, &ps, xi).max(0.0))
                .collect()
        }
        _ => {
            // Hertz, with a small pressure tail over the outlet (COLD_START_TAIL of p_H at
            // X = 1 falling linearly to 0 at the domain's end): the semismooth Newton
            // moves the cavitation boundary by one node per iteration where nodes leave
            // the cavitated set, but drops any number of them into it at once, so the
            // start errs on the pressurised side of the outlet meniscus (measured on
            // references.md's case at 401 nodes: 17 → 12 Newton iterations; the root is
            // the same, the start only).
            let x_end = scaled.x[n - 1];
            scaled
                .x
                .iter()
                .map(|&xi| {
                    if xi > 1.0 && x_end > 1.0 {
                        COLD_START_TAIL * (1.0 - (xi - 1.0) / (x_end - 1.0)).max(0.0)
                    } else {
                        (1.0 - xi * xi).max(0.0).sqrt()
                    }
                })
                .collect()
        }
    };
    p[0] = 0.0;
    p[n - 1] = 0.0;
    // Rescale so that the start carries the load exactly.
    let load: f64 = p.iter().sum::<f64>() * dx;
    if load > 0.0 {
        p.iter_mut().for_each(|v| *v *= 0.5 * PI / load);
    }
    // H₀: from the warm solution's central film, else Pan–Hamrock's, with the start's
    // deflection at the centre.
    let central_guess = match warm {
        Some(s) if s.central_film_m > 0.0 => s.central_film_m,
        _ => pan_hamrock_central(&FilmInputs {
            viscosity_pa_s: scaled.laws[0].viscosity_pa_s(0.0),
            pressure_viscosity_pa_inv: rh.pressure_viscosity_pa_inv,
            entrainment_speed_m_s: u,
            reduced_radius_m: r,
            load_per_length_n_m: w,
            effective_modulus_pa: 2.0 * e_star,
        })
        .unwrap_or(0.0),
    };
    let mut d = vec![0.0; n];
    deflection_symmetric(&scaled.kernel, &p, &mut d);
    let centre = interpolate(&scaled.x, &d, 0.0);
    let mut h0 = central_guess / film_scale - centre;

    let m = n + 1;
    let mut ws = Work::new(n);
    let mut phi = vec![0.0; m];
    // The Jacobian as assembled (the Krylov path's operator) and the LU factors in use.
    let mut jac = vec![0.0; m * m];
    let mut lu = vec![0.0; m * m];
    let mut piv = vec![0usize; m];
    let mut gmres_work = GmresWork::default();
    let mut rhs = vec![0.0; m];
    // The chord and Krylov paths start from a warm solution's factors when they belong to
    // this grid.
    let mut have_factor = false;
    if strategy != NewtonStrategy::Full {
        if let Some(f) = warm
            .and_then(|s| s.factorisation.as_deref())
            .filter(|f| f.fits(n, x0, dx))
        {
            lu.copy_from_slice(&f.lu);
            piv.copy_from_slice(&f.piv);
            have_factor = true;
        }
    }
    let krylov = strategy == NewtonStrategy::Krylov;
    let mut trial_p = vec![0.0; n];
    let mut trial_phi = vec![0.0; m];
    let mut clamps_total = 0;
    let mut factorisations = 0;
    let singular = |iteration| LineEhlError::Singular {
        iteration,
        load_n_m: w,
        hertz_pa: p_h,
        speed_m_s: u,
    };
    let mut last_step = f64::INFINITY;
    let mut last_norm = f64::INFINITY;
    let mut last_load = f64::INFINITY;
    let mut delta = vec![0.0; m];
    for iteration in 1..=problem.max_iterations {
        let mut refactor = strategy == NewtonStrategy::Full || !have_factor;
        let (norm, _, clamps) = scaled.residual(
            &p,
            h0,
            &mut phi,
            (refactor || krylov).then_some(jac.as_mut_slice()),
            &mut ws,
        );
        clamps_total += clamps;
        if !norm.is_finite() {
            return Err(singular(iteration));
        }
        rhs.iter_mut().zip(&phi).for_each(|(d, v)| *d = -v);
        if krylov && !refactor {
            // The exact Newton step by GMRES on the assembled Jacobian, preconditioned
            // with the factors in hand; refactorised when that does not converge soon.
            let outcome = gmres(
                |v, out| dense_product(&jac, v, out, m),
                |v| lu_solve(&lu, &piv, v, m),
                &rhs,
                &mut delta,
                KRYLOV_TOLERANCE,
                KRYLOV_ITERATIONS,
                &mut gmres_work,
            );
            refactor = !outcome.converged;
        }
        if refactor {
            lu.copy_from_slice(&jac);
            lu_factor(&mut lu, &mut piv, m).ok_or_else(|| singular(iteration))?;
            factorisations += 1;
            have_factor = true;
        }
        if refactor || !krylov {
            delta.copy_from_slice(&rhs);
            lu_solve(&lu, &piv, &mut delta, m).ok_or_else(|| singular(iteration))?;
        }
        // The step was an exact (or GMRES-accurate) Newton step unless it is a chord
        // step with stale factors.
        let newton_step = refactor || krylov;
        // Damping: backtracking until ‖Φ‖ decreases (Armijo), from a first step that
        // moves no pressure by more than p_H (a trust bound against the viscosity's
        // exponential growth). The Reynolds rows are scaled (see `residual`) so that the
        // merit weighs the inlet like the Hertz zone: without it the merit stalled at
        // α ≈ 10⁻³ for tens of iterations (measured: a warm step 36 → 5 iterations,
        // the cold reference case 32 → 17 at 401 nodes).
        let largest = delta[..n].iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let mut alpha = if largest > 1.0 { 1.0 / largest } else { 1.0 };
        let h_c_now = interpolate(&scaled.x, &ws.h, 0.0).max(1e-12);
        let mut accepted = None;
        if !newton_step {
            // A chord step (a stale matrix): kept whole only if it contracts the residual
            // by CHORD_CONTRACTION (or, at round-off, is below the tolerance and does not
            // raise it); otherwise discarded and the exact Jacobian factorised next.
            for i in 0..n {
                trial_p[i] = p[i] + alpha * delta[i];
            }
            let trial_h0 = h0 + alpha * delta[n];
            let (tn, tl, _) = scaled.residual(&trial_p, trial_h0, &mut trial_phi, None, &mut ws);
            let chord_step = largest.max(delta[n].abs() / h_c_now);
            let contracts =
                tn <= CHORD_CONTRACTION * norm || (chord_step < problem.tolerance && tn <= norm);
            if !(tn.is_finite() && contracts) {
                have_factor = false;
                last_norm = norm;
                continue;
            }
            accepted = Some((trial_h0, tn, tl));
        } else {
            for _ in 0..12 {
                for i in 0..n {
                    trial_p[i] = p[i] + alpha * delta[i];
                }
                let trial_h0 = h0 + alpha * delta[n];
                let (tn, tl, _) =
                    scaled.residual(&trial_p, trial_h0, &mut trial_phi, None, &mut ws);
                if tn.is_finite() && tn < (1.0 - 1e-4 * alpha) * norm {
                    accepted = Some((trial_h0, tn, tl));
                    break;
                }
                alpha *= 0.5;
            }
        }
        // No acceptable step along the Newton direction: take the short step anyway and
        // let the iteration count bound it.
        let (new_h0, new_norm, new_load) = match accepted {
            Some(v) => v,
            None => {
                for i in 0..n {
                    trial_p[i] = p[i] + alpha * delta[i];
                }
                let th = h0 + alpha * delta[n];
                let (tn, tl, _) = scaled.residual(&trial_p, th, &mut trial_phi, None, &mut ws);
                (th, tn, tl)
            }
        };
        let step_p = delta[..n]
            .iter()
            .fold(0.0f64, |a, v| a.max((alpha * v).abs()));
        // The film scale of the step test: the accepted trial's central film (the last
        // residual evaluated), as before the chord path.
        let h_c_scaled = interpolate(&scaled.x, &ws.h, 0.0).max(1e-12);
        let step_h0 = (alpha * delta[n]).abs() / h_c_scaled;
        std::mem::swap(&mut p, &mut trial_p);
        h0 = new_h0;
        last_step = step_p.max(step_h0);
        last_norm = new_norm;
        last_load = new_load;
        if !(new_norm.is_finite() && h0.is_finite()) {
            return Err(singular(iteration));
        }
        // Converged when the full Newton (or kept chord) step (not the damped one: a
        // short damped step proves nothing) is below the tolerance.
        let full_step = largest.max(delta[n].abs() / h_c_scaled);
        if full_step < problem.tolerance && new_load.abs() <= LOAD_BALANCE_TOLERANCE {
            let factor = (strategy != NewtonStrategy::Full)
                .then(|| Arc::new(Factorisation { n, x0, dx, lu, piv }));
            return Ok(finish(
                problem,
                &scaled,
                &p,
                h0,
                (iteration, factorisations, factor),
                new_load,
                clamps_total,
                &mut ws,
                (b, p_h, film_scale),
            ));
        }
    }
    Err(LineEhlError::NotConverged {
        iterations: problem.max_iterations,
        step: last_step,
        tolerance: problem.tolerance,
        residual: last_norm,
        load_balance: last_load,
        eps_w: LOAD_BALANCE_TOLERANCE,
        load_n_m: w,
        hertz_pa: p_h,
        half_width_m: b,
        speed_m_s: u,
    })
}

/// The dimensional solution of a converged iterate.
#[allow(clippy::too_many_arguments)]
fn finish(
    problem: &LineEhlProblem,
    scaled: &Scaled<'_>,
    p: &[f64],
    h0: f64,
    (iterations, factorisations, factorisation): (usize, usize, Option<Arc<Factorisation>>),
    load_balance_residual: f64,
    clamps: usize,
    ws: &mut Work,
    (b, p_h, film_scale): (f64, f64, f64),
) -> LineEhlSolution {
    let n = scaled.n;
    let clamped_now = scaled.film(p, h0, &mut ws.h, &mut ws.clamped);
    let x_m: Vec<f64> = scaled.x.iter().map(|v| v * b).collect();
    // Converged cavitated nodes hold P = 0 exactly; a round-off negative is shown as 0.
    let pressure_pa: Vec<f64> = p.iter().map(|v| (v * p_h).max(0.0)).collect();
    let film_m: Vec<f64> = ws.h.iter().map(|v| v * film_scale).collect();
    let rh = &problem.rheology;
    let viscosity_pa_s = (0..n)
        .map(|i| scaled.laws[i].viscosity_pa_s(pressure_pa[i]))
        .collect();
    let density_kg_m3 = (0..n)
        .map(|i| rh.density_kg_m3(pressure_pa[i], scaled.temps[i]))
        .collect();
    let hertz_pressure_pa = scaled
        .x
        .iter()
        .map(|v| p_h * (1.0 - v * v).max(0.0).sqrt())
        .collect();
    LineEhlSolution {
        central_film_m: interpolate(&x_m, &film_m, 0.0),
        min_film_m: film_m.iter().fold(f64::INFINITY, |a, v| a.min(*v)),
        max_pressure_pa: pressure_pa.iter().fold(0.0, |a, v| a.max(*v)),
        hertz_max_pressure_pa: p_h,
        hertz_half_width_m: b,
        h0_m: h0 * film_scale,
        iterations,
        factorisations,
        load_balance_residual,
        clamps: clamps + clamped_now,
        factorisation,
        x_m,
        pressure_pa,
        hertz_pressure_pa,
        film_m,
        viscosity_pa_s,
        density_kg_m3,
    }
}

#[cfg(test)]
#[path = "line_tests.rs"]
mod tests;
