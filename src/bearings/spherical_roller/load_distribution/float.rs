//! The floating guide ring of a double-row bearing (issue 27 Model 1; seed 002 §2).
//!
//! The guide ring sits on the inner ring's land between the rows: radially the land carries
//! it, axially nothing holds it but the roller ends of the two rows (its bore slides on the
//! land; the seed names no shoulder, and the land is taken as wide enough that the ring
//! never reaches its edges). Its axial offset s on the inner ring (bearing frame, + toward
//! row 1, 0 = centred) is therefore an unknown with one equation: the net axial force of
//! both rows' roller ends on it vanishes,
//!
//!   R(s) = cos α⁰ · (Σ_row 2 F_j − Σ_row 1 F_j) = 0,
//!
//! so it passes no axial load to the inner ring. R = −∂Π/∂s: the guide ring is a free body
//! with no load of its own, so its balance is the stationarity of the same potential energy
//! Π(u, q; s) whose u-gradient is the ring balance (eq. 3.12–3.13; the end contacts'
//! energy U = (2/5)·K·δ^(5/2) is the only term holding s). It is solved *with* the ring:
//! s is a third unknown of the ring Newton, (Δx, Δz, s), residuals (∂Π/∂u, ∂Π/∂s), Jacobian
//! the condensed 3 × 3 stiffness
//!
//!   | K     k_us |        K    = the ring's (rollers condensed, s held),
//!   | k_su  k_ss |,       k_ss = Σ m·(h_ss − h_sq·H_qq⁻¹·h_qs), k_su = Σ m·(h_su − h_sq·H_qq⁻¹·h_qu),
//!
//! assembled in the roller sweep from the factors the ring's condensation already has
//! ([`Problem::add_guide_terms`]); the energy is the line search's merit as in the ring
//! Newton. Each trial moves every roller by its first-order prediction
//! dq = (dq/du)·Δu + (dq/ds)·Δs. (Before, s had a loop of its own around the whole ring
//! Newton: about five ring solves per bearing solve.)
//!
//! Where only one row presses it, R ∝ δ^(3/2) near the release and Newton's step in s is
//! 2/3 of the way there: that step is taken 1.5× (exact for a pure 3/2 law), the ring
//! deflection re-balanced for it (du = −K⁻¹·(g_u + k_us·Δs)); past the release the ring is
//! free and the rule below holds.
//!
//! Where no roller touches it, s is indeterminate within the free travel [s_lo, s_hi] (the
//! offsets at which the first end of row 2, respectively row 1, would touch, the rollers
//! and rings staying where they are: without a contact they do not depend on s), and the
//! Newton step is the ring's own 2 × 2 with s held. The rule: s = clamp(0, s_lo, s_hi), the
//! centred place where it is free, else the nearest end of the free travel (a drag-free
//! ring stays where the inner ring carried it, which is the least motion from centred). A
//! guide ring that touches neither row at s = 0 thus stays centred.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

use super::diagnostics::{diagnose, unrestrained};
use super::driver::RingState;
use super::problem::Problem;
use super::{SolveStats, TraceStep};
use crate::bearings::spherical_roller::geometry::Pitch;
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;
use crate::numerics::newton::{newton_step2, newton_step3, Backtracking, Factor3, TrustRegion};

/// The guide ring's terms at one ring state, summed in the roller sweep: the forces of each
/// row's ends on it, its stiffnesses with the rollers condensed, each roller's dq/ds and the
/// free travel (when no end touches it).
#[derive(Debug, Clone)]
pub(super) struct GuideTerms {
    /// Σ over each row's rollers of the end force magnitudes, N.
    pub(super) row_force_n: [f64; 2],
    /// k_ss, N/m, and k_su (axial, radial), N/m: the condensed stiffness's guide row.
    pub(super) k_ss: f64,
    pub(super) k_su: Vector2<f64>,
    /// Each unique roller's dq/ds = −H_qq⁻¹·h_qs with the ring held (zero off the ring).
    pub(super) dq_ds: Vec<Vector3<f64>>,
    /// Offsets between which no roller end touches the ring, rollers and rings held, m.
    pub(super) free: (f64, f64),
}

impl GuideTerms {
    pub(super) fn new(rollers: usize) -> Self {
        GuideTerms {
            row_force_n: [0.0; 2],
            k_ss: 0.0,
            k_su: Vector2::zeros(),
            dq_ds: Vec::with_capacity(rollers),
            free: (f64::NEG_INFINITY, f64::INFINITY),
        }
    }

    /// Whether any roller end touches the guide ring.
    fn contact(&self) -> bool {
        self.row_force_n != [0.0, 0.0]
    }

    /// Whether exactly one row touches it.
    fn one_sided(&self) -> bool {
        self.contact() && (self.row_force_n[0] == 0.0 || self.row_force_n[1] == 0.0)
    }
}

impl Problem {
    /// Add unique roller `k`'s guide ring terms (its multiplicity `mult`, cos φ `cphi`) at ring
    /// deflection `u` (bearing frame), the roller at `q`, with its factored H_qq and its
    /// dq/du = `sens` (bearing frame) from the ring's condensation. Only the end contact
    /// depends on s: ∂g/∂s = −sign·cos α⁰ (the same as ∂g/∂u_a in the bearing frame).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn add_guide_terms(
        &self,
        gt: &mut GuideTerms,
        k: usize,
        cphi: f64,
        mult: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        factor: &Factor3,
        sens: &nalgebra::Matrix3x2<f64>,
    ) {
        let Some(guide) = &self.guide else {
            return;
        };
        let a0 = self.geom.axis[0];
        let s = self.guide_offset.get();
        let sign = self.signs[k];
        let row = usize::from(sign < 0.0);
        let (gap, dq, _, du) =
            self.guide_gap(guide, sign, cphi, self.local_u(k, u), q, Pitch::new(q[2]));
        // ∂g/∂s = −sign·cos α⁰: row 1's gap closes as s grows, row 2's opens.
        if row == 0 {
            gt.free.1 = gt.free.1.min(s + gap / a0);
        } else {
            gt.free.0 = gt.free.0.max(s - gap / a0);
        }
        if gap >= 0.0 {
            gt.dq_ds.push(Vector3::zeros());
            return;
        }
        let root = (-gap).sqrt();
        gt.row_force_n[row] += mult * guide.hertz_constant * (-gap) * root;
        let df = 1.5 * guide.hertz_constant * root;
        let ds = -sign * a0;
        let du_b = Vector2::new(sign * du[0], du[1]);
        let h_sq = df * ds * dq;
        let x = factor.solve(&h_sq);
        gt.k_ss += mult * (df * ds * ds - h_sq.dot(&x));
        gt.k_su += mult * (df * ds * du_b + (h_sq.transpose() * sens).transpose());
        gt.dq_ds.push(-x);
    }

    /// ∂Π/∂s at a ring state: −R = cos α⁰·(Σ_row 1 F − Σ_row 2 F), N (0 without a guide ring).
    fn guide_gradient(&self, state: &RingState) -> f64 {
        state.guide.as_ref().map_or(0.0, |gt| {
            self.geom.axis[0] * (gt.row_force_n[0] - gt.row_force_n[1])
        })
    }

    /// The ring equilibrium with the guide ring floating: Newton in (Δx, Δz, s) on the
    /// potential energy (module doc), inexact in the rollers as the ring Newton is, until the
    /// ring forces and the guide ring's net axial force are within the ring tolerance. Leaves
    /// the offset in `guide_offset` (by the rule of the module doc when no end touches it)
    /// and, in the returned state's K, the ring stiffness with s condensed
    /// ([`float_stiffness`]).
    pub(super) fn float_guide(
        &self,
        b: &Bearing,
        u: &mut [f64; 2],
        qs: &mut Vec<Vector3<f64>>,
        stats: &mut SolveStats,
        trace: &mut Option<(usize, Vec<TraceStep>)>,
        cancel: Option<&AtomicBool>,
    ) -> Result<RingState, SolveError> {
        let d = b.geometry.roller_diameter_m;
        let mut s = self.guide_offset.get();
        let mut trust = TrustRegion::new(1e-3 * d, 1e-12 * d, 0.1 * d);
        let line_search = Backtracking::default();
        let max_it = b.solver.max_iterations.max(1);
        // As the ring Newton: the first sweep only measures the residual (10⁻³ of the
        // reference force); the rollers' tolerance then follows the residual.
        self.roller_tol.set(self.tol.max(1e-3 * self.f_ref));
        let mut state = self
            .solve_rollers(*u, qs, &mut stats.roller_iterations, trace, 0)
            .map_err(|e| diagnose(b, *u, qs, e))?;
        for it in 0..max_it {
            if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                return Err(SolveError::Cancelled);
            }
            let g = state.g;
            let g_s = self.guide_gradient(&state);
            let ring_res = g[0].abs().max(g[1].abs());
            let res = ring_res.max(g_s.abs());
            if !res.is_finite() {
                return Err(SolveError::NonFinite {
                    stage: "ring equilibrium",
                    what: "ring or guide ring force residual".into(),
                });
            }
            if res <= self.tol {
                if self.roller_tol.get() <= self.tol || state.worst <= self.tol {
                    return Ok(self.float_finish(state));
                }
                // Converged with loose rollers: tighten them here and re-check.
                self.roller_tol.set(self.tol);
                state = self
                    .solve_rollers(*u, qs, &mut stats.roller_iterations, trace, it)
                    .map_err(|e| diagnose(b, *u, qs, e))?;
                continue;
            }
            self.roller_tol.set(self.tol.max(1e-3 * res));
            stats.iterations = it + 1;
            let (du, ds) = float_step(&state, g_s);
            let step = Vector3::new(du[0], du[1], ds);
            let len = step.norm();
            let (step, capped) = trust.cap(step, len);
            let slope = g[0] * step[0] + g[1] * step[1] + g_s * step[2];
            let energy = state.energy;
            let no_dq = Vec::new();
            let dq_ds = state.guide.as_ref().map_or(&no_dq, |gt| &gt.dq_ds);
            let accepted = line_search.try_search(|lambda| {
                let trial = [u[0] + lambda * step[0], u[1] + lambda * step[1]];
                let s_trial = s + lambda * step[2];
                self.guide_offset.set(s_trial);
                let du = Vector2::new(trial[0] - u[0], trial[1] - u[1]);
                let dst = s_trial - s;
                let mut qt: Vec<Vector3<f64>> = qs
                    .iter()
                    .zip(&state.sens)
                    .enumerate()
                    .map(|(k, (q, x))| {
                        q + x * du + dq_ds.get(k).map_or(Vector3::zeros(), |v| v * dst)
                    })
                    .collect();
                let st = self
                    .solve_rollers(trial, &mut qt, &mut stats.roller_iterations, trace, it + 1)
                    .map_err(|e| diagnose(b, trial, &qt, e))?;
                let r = st.g[0]
                    .abs()
                    .max(st.g[1].abs())
                    .max(self.guide_gradient(&st).abs());
                let ok = line_search.accepts(energy, slope, res, lambda, st.energy, r);
                Ok(ok.then_some((trial, s_trial, qt, st)))
            });
            let accepted = match accepted {
                Ok(a) => a,
                Err(e) => {
                    self.guide_offset.set(s);
                    return Err(e);
                }
            };
            let Some((lambda, (trial, s_trial, qt, st))) = accepted else {
                self.guide_offset.set(s);
                // No acceptable step: converged when within 10³ of the tolerance
                // (round-off), as the ring Newton; else say which balance failed.
                if res <= 1e3 * self.tol {
                    return Ok(self.float_finish(state));
                }
                return Err(self.float_failure(
                    b,
                    *u,
                    it + 1,
                    s,
                    g,
                    g_s,
                    "no step reduced the residual",
                ));
            };
            *u = trial;
            *qs = qt;
            s = s_trial;
            state = st;
            trust.update(lambda, len, capped);
            if !s.is_finite() || s.abs() > 0.5 * d {
                return Err(self.float_error(
                    s,
                    self.guide_gradient(&state),
                    "it left ±D/2 of its centred place",
                ));
            }
        }
        let g_s = self.guide_gradient(&state);
        Err(self.float_failure(
            b,
            *u,
            max_it,
            s,
            state.g,
            g_s,
            "the iteration budget ran out",
        ))
    }

    /// The converged state: without an end contact s is set by the rule of the module doc
    /// (the rollers do not depend on it there); with one, K becomes the floating stiffness.
    fn float_finish(&self, mut state: RingState) -> RingState {
        let s = self.guide_offset.get();
        if let Some(gt) = &state.guide {
            if gt.contact() {
                let (k_ss, k_su) = (gt.k_ss, gt.k_su);
                float_stiffness(&mut state, k_ss, k_su);
            } else {
                let (lo, hi) = gt.free;
                let s_rule = if lo <= hi { 0.0f64.max(lo).min(hi) } else { s };
                self.guide_offset.set(s_rule);
            }
        }
        state
    }

    /// The error of a floating solve that did not converge: the guide ring's when its
    /// balance is the larger residual, else the ring's (or the rings' separation).
    #[allow(clippy::too_many_arguments)]
    fn float_failure(
        &self,
        b: &Bearing,
        u: [f64; 2],
        iterations: usize,
        s: f64,
        g: Vector2<f64>,
        g_s: f64,
        why: &str,
    ) -> SolveError {
        let ring_res = g[0].abs().max(g[1].abs());
        if g_s.abs() > ring_res {
            return self.float_error(s, -g_s, why);
        }
        unrestrained(b, u).unwrap_or(SolveError::NotConverged {
            iterations,
            residual_n: ring_res,
            tolerance_n: self.tol,
        })
    }

    fn float_error(&self, s: f64, r: f64, why: &str) -> SolveError {
        SolveError::Stage {
            stage: "guide ring balance (issue 27 Model 1)",
            message: format!(
                "the floating guide ring found no axial balance ({why}): at offset {s:.4e} m the roller ends still push it with a net {r:.4e} N (tolerance {:.3e} N)",
                self.tol
            ),
        }
    }
}

/// The Newton step (Δu, Δs) of the floating ring at `state` (∂Π/∂s = `g_s`): the exact
/// 3 × 3 step with an end contact (one-sided: Δs × 1.5 and Δu re-balanced, module doc), the
/// ring's 2 × 2 step with s held without one.
fn float_step(state: &RingState, g_s: f64) -> (Vector2<f64>, f64) {
    let k = state.k;
    let g = state.g;
    let Some(gt) = state.guide.as_ref().filter(|gt| gt.contact()) else {
        return (newton_step2(&k, &g), 0.0);
    };
    let h = Matrix3::new(
        k[(0, 0)],
        k[(0, 1)],
        gt.k_su[0],
        k[(1, 0)],
        k[(1, 1)],
        gt.k_su[1],
        gt.k_su[0],
        gt.k_su[1],
        gt.k_ss,
    );
    let step = newton_step3(
        &h,
        &Vector3::new(g[0], g[1], g_s),
        &Vector3::new(1.0, 1.0, 1.0),
    );
    let (mut du, mut ds) = (Vector2::new(step[0], step[1]), step[2]);
    if gt.one_sided() {
        // Δu' = Δu − K⁻¹·k_us·(Δs' − Δs) with Δs' = 1.5·Δs.
        du += newton_step2(&k, &(gt.k_su * (0.5 * ds)));
        ds *= 1.5;
    }
    (du, ds)
}

/// The ring stiffness with the guide ring floating: the ring solve's condensed stiffness K
/// (guide ring held at s) with s condensed out as well, K_float = K − k_us·k_su/k_ss.
/// Without an end contact k_ss = 0 and K is unchanged.
fn float_stiffness(state: &mut RingState, k_ss: f64, k_su: Vector2<f64>) {
    if k_ss > 0.0 && k_ss.is_finite() {
        let corr: Matrix2<f64> = k_su * k_su.transpose() / k_ss;
        state.k -= corr;
    }
}
