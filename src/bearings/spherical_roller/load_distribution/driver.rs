//! The Newton driver of the load distribution: each roller's 3-unknown equilibrium at a
//! given ring deflection, the sweep over the unique rollers with the condensed ring
//! stiffness (Schur complement), the cold start from the rigid-roller estimate and the
//! inertial prediction of a warm start.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

use super::diagnostics::diagnose;
use super::float::GuideTerms;
use super::problem::{Problem, RollerEval};
use super::{InertialSensitivity, SolveOptions, SolveStats, TraceStep};
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;
use crate::numerics::newton::{
    cap_step, newton_step2, newton_step3, Backtracking, Factor3, Newton, NewtonSystem, Termination,
    TrustRegion,
};

impl Problem {
    /// Solve one roller's equilibrium at ring deflection u, starting from q: the shared
    /// damped Newton ([`Newton`]) on [`RollerSystem`]. A line search that stalls with the
    /// residual within 10³ of the tolerance, or a budget that runs out within it, still
    /// counts as converged; `q` is left where Newton left it either way.
    pub(super) fn solve_roller(
        &self,
        index: usize,
        cphi: f64,
        u: [f64; 2],
        q: &mut Vector3<f64>,
        iterations: &mut usize,
        trace: Option<(&mut Vec<TraceStep>, usize)>,
    ) -> Result<RollerEval, SolveError> {
        let scale_t = 1e-3 * 2.0 * self.l_ref; // initial trust radius in translation, m
        let newton = Newton {
            max_iterations: self.max_roller_it,
            tolerance: self.roller_tol.get(),
            // Grow the trust radius, but never beyond a tenth of the roller diameter:
            // a roller out of contact has no stiffness along its normal, and an
            // unbounded radius lets one Newton step throw it metres away.
            trust: TrustRegion::new(scale_t, 1e-9 * scale_t, self.max_step),
            line_search: Backtracking::default(),
        };
        let mut system = RollerSystem {
            p: self,
            sign: self.signs[index],
            cphi,
            u,
            trace,
        };
        let solved = newton.solve(&mut system, q);
        *iterations += solved.stats.iterations;
        let not_converged = |iterations, residual| SolveError::RollerNotConverged {
            roller: index + 1,
            iterations,
            residual,
            tolerance: self.tol,
        };
        match solved.termination {
            Termination::Converged { .. } => Ok(solved.eval),
            Termination::NonFinite { .. } => Err(SolveError::NonFinite {
                stage: "roller equilibrium",
                what: format!("roller {} residual", index + 1),
            }),
            // No descent even at 2⁻⁴⁰ of the step: the residual is at round-off level.
            Termination::Stalled {
                iterations,
                residual,
            } => {
                if residual <= 1e3 * self.tol {
                    Ok(solved.eval)
                } else {
                    Err(not_converged(iterations, residual))
                }
            }
            Termination::NotConverged {
                iterations,
                residual,
                ..
            } => {
                if residual <= self.tol {
                    Ok(solved.eval)
                } else {
                    Err(not_converged(iterations, residual))
                }
            }
            // Neither happens (the shifted Cholesky step always exists, nothing cancels a
            // roller); should they, the roller did not converge.
            Termination::SingularJacobian { iteration } | Termination::Cancelled { iteration } => {
                Err(not_converged(
                    iteration + 1,
                    self.roller_residual(&solved.eval.g_q),
                ))
            }
        }
    }

    /// Solve all unique rollers at u; returns Σ energy, condensed gradient and stiffness.
    pub(super) fn solve_rollers(
        &self,
        u: [f64; 2],
        qs: &mut [Vector3<f64>],
        roller_its: &mut usize,
        trace: &mut Option<(usize, Vec<TraceStep>)>,
        ring_it: usize,
    ) -> Result<RingState, SolveError> {
        let mut sens = Vec::with_capacity(qs.len());
        let mut inertial_roller = Vec::with_capacity(qs.len());
        let mut inertial_ring = Vec::with_capacity(qs.len());
        let mut energy = -(self.load[0] * u[0] + self.load[1] * u[1]);
        let mut g = Vector2::new(-self.load[0], -self.load[1]);
        let mut k = Matrix2::zeros();
        let mut worst = 0.0f64;
        // The floating guide ring's terms (its third unknown; nothing without a guide ring,
        // so the single-row bearing's arithmetic is untouched).
        let mut guide = self.guide.as_ref().map(|_| GuideTerms::new(qs.len()));
        for (j, (&(cphi, mult), q)) in self.unique.iter().zip(qs.iter_mut()).enumerate() {
            let tr = match trace {
                Some((idx, steps)) if *idx == j => Some((steps, ring_it)),
                _ => None,
            };
            let mut ev = self.solve_roller(j, cphi, self.local_u(j, u), q, roller_its, tr)?;
            if self.signs[j] < 0.0 {
                // Back from the mirrored row's frame to the bearing's: the axial ring
                // unknown changes sign (S = diag(−1, 1): g_u → S·g_u, H_uu → S·H_uu·S,
                // H_uq → S·H_uq).
                ev.g_u[0] = -ev.g_u[0];
                ev.h_uu[(0, 1)] = -ev.h_uu[(0, 1)];
                ev.h_uu[(1, 0)] = -ev.h_uu[(1, 0)];
                for c in 0..3 {
                    ev.h_uq[(0, c)] = -ev.h_uq[(0, c)];
                }
            }
            worst = worst.max(self.roller_residual(&ev.g_q));
            // Condensed stiffness: H_uu − H_uq H_qq⁻¹ H_qu (exact Jacobian of the ring forces
            // with every roller kept in equilibrium).
            let hqu = ev.h_uq.transpose();
            // H_qq factored once (scaled and, if need be, shifted to positive definite like
            // the Newton step) for the condensation's three solves; when no shift helps, every
            // solve gives zero.
            let factor = Factor3::new(&ev.h_qq, &self.scale);
            let x = factor.solve(&hqu);
            k += mult * (ev.h_uu - ev.h_uq * x);
            // The roller stopped at a residual r ≤ roller_tol; left as is, Z such residuals add
            // up to a ring-force error of order Z·r, a noise floor that can sit above the
            // ring tolerance and stall the ring line search. One more Newton step from the
            // Hessian already at hand, dq = −H_qq⁻¹g_q, carried to the ring force
            // (g_u + H_uq·dq) and the energy (+½g_qᵀdq), leaves an error of order r²
            // instead. The roller moves by dq too, so later warm starts inherit it; the
            // residuals reported at the end are re-evaluated, never taken from this.
            // The step is trusted only while it is tiny against the contact approaches
            // (10⁻⁶·D): a roller held in a soft direction by the cage spring alone can turn
            // a small residual into a long step the quadratic model does not cover.
            let mut dq = factor.solve(&ev.g_q);
            let len = (dq[0].powi(2) + dq[1].powi(2) + (dq[2] * self.l_ref).powi(2)).sqrt();
            if len.is_nan() || len > 1e-5 * self.max_step {
                dq = Vector3::zeros();
            }
            *q -= dq;
            energy += mult * (ev.energy - 0.5 * ev.g_q.dot(&dq));
            g += mult * (ev.g_u - ev.h_uq * dq);
            // dq/du = −H_qq⁻¹ H_qu: predicts each roller's equilibrium at a trial ring step.
            if let Some(gt) = guide.as_mut() {
                self.add_guide_terms(gt, j, cphi, mult, u, q, &factor, &(-x));
            }
            sens.push(-x);
            // Response to the inertial loads (radial force, pitching moment).
            let e = nalgebra::Matrix3x2::new(0.0, 0.0, 1.0, 0.0, 0.0, 1.0);
            let pf = factor.solve(&e);
            inertial_ring.push(mult * (ev.h_uq * pf));
            inertial_roller.push(pf);
        }
        Ok(RingState {
            energy,
            g,
            k,
            sens,
            inertial_roller,
            inertial_ring,
            worst,
            guide,
        })
    }

    /// A cold start from the rigid-roller estimate: each roller replaced by one nonlinear
    /// spring along the nominal contact normal n, its inner and outer contacts in series with
    /// every lamina at the same approach (Q = K·δ^(10/9), K = Γ·k per raceway, so the pair
    /// gives Q = [Δ/(K_i^(−0.9) + K_o^(−0.9))]^(10/9) for a total approach Δ), and the ring
    /// deflection u that balances the applied loads found by Newton on that 2-unknown convex
    /// energy: Δ_j = n_x·u_a + n_r·u_r·cos φ_j − c/2·cos β (the diametral clearance c opens
    /// at the outer raceway). Each roller then starts where it splits Δ_j between its two
    /// contacts at equal load. It ignores crowning, tilt and the inertial loads, so it is
    /// only a starting point: the solve itself is unchanged (tested). When the estimate has no
    /// meaning (no load, no equilibrium within D/10, or a singular direction with load on
    /// it) the start stays at zero, as before.
    pub(super) fn cold_start(&self, b: &Bearing) -> ([f64; 2], Vec<Vector3<f64>>) {
        let zero = ([0.0, 0.0], vec![Vector3::zeros(); self.unique.len()]);
        if self.load[0] == 0.0 && self.load[1] == 0.0 {
            return zero;
        }
        let n = self.geom.normal;
        // A lamina whose crown normal is tilted from n by θ_l sees the approach e·cos θ_l and
        // pushes back along its own normal: Σ_l w_l·cos^(19/9) θ_l laminae-equivalents
        // (cos θ_l = h_l/R for conforming crowns, where this makes the estimate exact).
        let tilt_sum = |inner: bool| -> f64 {
            self.geom
                .laminae
                .iter()
                .map(|l| {
                    let rest = crate::bearings::spherical_roller::geometry::Pitch {
                        sin: 0.0,
                        cos_minus_one: 0.0,
                    };
                    let a = self.geom.approach_with(l, inner, [0.0; 3], [0.0; 2], rest);
                    let c = (a.normal[0] * n[0] + a.normal[1] * n[1]).abs();
                    // c^(19/9) = c²·c^(1/9): the hot loop's root instead of a pow call.
                    l.weight * c * c * crate::physics::contact::lamina_law::ninth_root(c)
                })
                .sum()
        };
        let (ki, ko) = (
            tilt_sum(true) * self.law_in.stiffness,
            tilt_sum(false) * self.law_out.stiffness,
        );
        let ci = ki.powf(-0.9);
        let co = ko.powf(-0.9);
        let c_pair = ci + co;
        let gap = 0.5 * b.geometry.diametral_clearance_m * n[1];
        // Energy, gradient and Hessian of the rigid-roller model at u.
        let model = |u: [f64; 2]| {
            let mut e = -(self.load[0] * u[0] + self.load[1] * u[1]);
            let mut g = Vector2::new(-self.load[0], -self.load[1]);
            let mut h = Matrix2::zeros();
            for (&(cphi, mult), &sign) in self.unique.iter().zip(&self.signs) {
                let m = Vector2::new(sign * n[0], n[1] * cphi);
                let d = m.dot(&Vector2::new(u[0], u[1])) - gap;
                if d > 0.0 {
                    let x = d / c_pair;
                    let x19 = crate::physics::contact::lamina_law::ninth_root(x);
                    let q = x * x19;
                    let dq = (10.0 / 9.0) * x19 / c_pair;
                    e += mult * (9.0 / 19.0) * q * d;
                    g += mult * q * m;
                    h += mult * dq * m * m.transpose();
                }
            }
            (e, g, h)
        };
        let d = b.geometry.roller_diameter_m;
        let mut u = [0.0, 0.0];
        let (mut e, mut g, mut h) = model(u);
        let f_ref = self.load[0].abs().max(self.load[1].abs());
        // Solved to the solve's own force tolerance where it can be (quadratic convergence:
        // one or two steps past 1e-6): where the estimate is exact (conforming crowns) the
        // first sweep then already meets the ring tolerance. Steps that round-off stops
        // (no energy decrease, no halving of the force) end the search; the estimate counts
        // as solved when it got within 1e-6 of the load.
        let mut solved = false;
        for _ in 0..60 {
            if g.amax() <= 0.1 * self.tol {
                solved = true;
                break;
            }
            // Newton with a floor on the stiffness so that a ring with no roller in contact
            // yet moves (by at most D/100 per step) toward contact.
            let step = newton_step2(&h, &g);
            let (step, _) = cap_step(step, step.amax(), 0.01 * d);
            let line_search = Backtracking {
                max_trials: 30,
                ..Backtracking::default()
            };
            let moved = line_search.search(|lambda| {
                let trial = [u[0] + lambda * step[0], u[1] + lambda * step[1]];
                let (e2, g2, h2) = model(trial);
                (e2 < e || g2.amax() < 0.5 * g.amax()).then_some((trial, e2, g2, h2))
            });
            let Some((_, next)) = moved else {
                solved = g.amax() <= 1e-6 * f_ref;
                break;
            };
            (u, e, g, h) = next;
            if u[0].abs().max(u[1].abs()) > 0.1 * d {
                return zero;
            }
        }
        if !solved {
            return zero;
        }
        let qs = self
            .unique
            .iter()
            .zip(&self.signs)
            .map(|(&(cphi, _), &sign)| {
                let dj = sign * n[0] * u[0] + n[1] * u[1] * cphi;
                let total = dj - gap;
                let s = if total > 0.0 {
                    // Equal load Q: δ_i = Q^0.9·K_i^(−0.9) = Δ·c_i/(c_i + c_o).
                    dj - total * ci / c_pair
                } else {
                    dj.clamp(0.0, gap.max(0.0))
                };
                Vector3::new(s * n[0], s * n[1], 0.0)
            })
            .collect();
        (u, qs)
    }

    /// Move a warm start by the first-order response to the change of inertial loads from
    /// the warm solution's to this problem's (see [`InertialSensitivity`]). The ring move is
    /// skipped when it would exceed the initial ring trust radius (10⁻³·D), and a roller's
    /// move when it exceeds the roller trust cap (10⁻²·D; a roller touching one raceway is
    /// held only by the soft cage spring, where the linear response is no guide): such
    /// rollers start from their old position and Newton takes them from there.
    pub(super) fn predict_inertial(
        &self,
        w: &InertialSensitivity,
        u: &mut [f64; 2],
        qs: &mut [Vector3<f64>],
    ) {
        if w.roller.len() != qs.len() {
            return;
        }
        let c = Vector2::new(self.cf - w.cf, -(self.gm - w.gm));
        if c[0] == 0.0 && c[1] == 0.0 {
            return;
        }
        let r: Vector2<f64> = w.ring.iter().map(|m| m * c).sum();
        let du = -newton_step2(&w.k, &(-r));
        let du_len = du[0].abs().max(du[1].abs());
        if du_len.is_nan() || du_len > 0.01 * self.max_step {
            return;
        }
        u[0] += du[0];
        u[1] += du[1];
        for ((q, p), s) in qs.iter_mut().zip(&w.roller).zip(&w.sens) {
            let d = p * c + s * du;
            if d[0].abs().max(d[1].abs()).max((d[2] * self.l_ref).abs()) <= 0.1 * self.max_step {
                *q += d;
            }
        }
    }

    /// The start of a solve: the warm start when it fits this bearing's rollers, else the
    /// cold start ([`Problem::cold_start`]); moved by the inertial prediction when the warm
    /// start carries its sensitivities ([`Problem::predict_inertial`]).
    pub(super) fn start(
        &self,
        b: &Bearing,
        options: &SolveOptions,
    ) -> ([f64; 2], Vec<Vector3<f64>>) {
        let n_unique = self.unique.len();
        let (mut u, mut qs) = match &options.warm_start {
            Some(w) if w.rollers.len() == n_unique => (
                w.ring,
                w.rollers
                    .iter()
                    .map(|r| Vector3::new(r[0], r[1], r[2]))
                    .collect::<Vec<_>>(),
            ),
            _ => self.cold_start(b),
        };
        if let Some(w) = options
            .warm_start
            .as_ref()
            .and_then(|w| w.inertial.as_ref())
        {
            self.predict_inertial(w, &mut u, &mut qs);
        }
        (u, qs)
    }

    /// The bearing's (ring) equilibrium, eq. 3.12–3.13: Newton on the ring deflection u with
    /// the condensed stiffness of [`RingState`], each trial ring deflection re-solving every
    /// roller from its first-order prediction, inexact (the rollers' tolerance follows the
    /// ring residual), with the shared trust radius and line search. It stays a loop of its
    /// own rather than a [`NewtonSystem`]: its evaluation (a roller sweep) can fail, starts
    /// from the current state's sensitivities, and a converged ring with loose rollers is
    /// re-swept at the same deflection. `u` and `qs` are left at the last accepted iterate and
    /// its state is returned with how the iteration ended; a failed roller sweep is returned
    /// as its diagnosed error.
    pub(super) fn solve_ring(
        &self,
        b: &Bearing,
        u: &mut [f64; 2],
        qs: &mut Vec<Vector3<f64>>,
        stats: &mut SolveStats,
        trace: &mut Option<(usize, Vec<TraceStep>)>,
        cancel: Option<&AtomicBool>,
    ) -> Result<(Termination, RingState), SolveError> {
        let d = b.geometry.roller_diameter_m;
        let mut trust = TrustRegion::new(1e-3 * d, 1e-12 * d, 0.1 * d);
        let line_search = Backtracking::default();
        let max_it = b.solver.max_iterations.max(1);
        // The first roller solves, before any ring residual is known, only need to be good enough
        // to measure it: 10⁻³ of the reference force (inexact Newton; the tolerance tightens with
        // the ring residual and is the deck's at convergence).
        self.roller_tol.set(self.tol.max(1e-3 * self.f_ref));
        let mut state = self
            .solve_rollers(*u, qs, &mut stats.roller_iterations, trace, 0)
            .map_err(|e| diagnose(b, *u, qs, e))?;
        for it in 0..max_it {
            if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                return Ok((Termination::Cancelled { iteration: it }, state));
            }
            let (energy, g, k) = (state.energy, state.g, state.k);
            let ring_res = g[0].abs().max(g[1].abs());
            if !ring_res.is_finite() {
                return Ok((Termination::NonFinite { iteration: it }, state));
            }
            if ring_res <= self.tol {
                // Converged when every roller also met the deck's tolerance, whatever tolerance
                // it was asked for (a good start often gives that in the first sweep).
                if self.roller_tol.get() <= self.tol || state.worst <= self.tol {
                    let converged = Termination::Converged {
                        iterations: it,
                        residual: ring_res,
                    };
                    return Ok((converged, state));
                }
                // Converged with loose rollers: tighten them at this ring deflection and re-check.
                self.roller_tol.set(self.tol);
                state = self
                    .solve_rollers(*u, qs, &mut stats.roller_iterations, trace, it)
                    .map_err(|e| diagnose(b, *u, qs, e))?;
                continue;
            }
            // Inexact Newton: rollers to 1e-3 of the ring residual (never below the tolerance).
            self.roller_tol.set(self.tol.max(1e-3 * ring_res));
            stats.iterations = it + 1;
            let step = newton_step2(&k, &g);
            let len = (step[0].powi(2) + step[1].powi(2)).sqrt();
            let (step, capped) = trust.cap(step, len);
            let slope = g.dot(&step);
            let accepted = line_search.try_search(|lambda| {
                let trial = [u[0] + lambda * step[0], u[1] + lambda * step[1]];
                // Predict each roller at the trial from its sensitivity (first-order warm start).
                let du = Vector2::new(trial[0] - u[0], trial[1] - u[1]);
                let mut qt: Vec<Vector3<f64>> = qs
                    .iter()
                    .zip(&state.sens)
                    .map(|(q, x)| q + x * du)
                    .collect();
                // A roller that fails while the rings have already drifted beyond D/2 is a
                // symptom of the missing restraint: report that.
                let st = self
                    .solve_rollers(trial, &mut qt, &mut stats.roller_iterations, trace, it + 1)
                    .map_err(|e| diagnose(b, trial, &qt, e))?;
                let res = st.g[0].abs().max(st.g[1].abs());
                let ok = line_search.accepts(energy, slope, ring_res, lambda, st.energy, res);
                Ok(ok.then_some((trial, qt, st)))
            })?;
            let Some((lambda, (trial, qt, st))) = accepted else {
                let stalled = Termination::Stalled {
                    iterations: it + 1,
                    residual: ring_res,
                };
                return Ok((stalled, state));
            };
            *u = trial;
            *qs = qt;
            state = st;
            trust.update(lambda, len, capped);
        }
        let g = state.g;
        let not_converged = Termination::NotConverged {
            iterations: max_it,
            residual: g[0].abs().max(g[1].abs()),
            tolerance: self.tol,
        };
        Ok((not_converged, state))
    }
}

/// The ring-level state at one ring deflection: energy, ring force residual, condensed
/// stiffness and each roller's sensitivity dq/du.
pub(super) struct RingState {
    pub(super) energy: f64,
    pub(super) g: Vector2<f64>,
    pub(super) k: Matrix2<f64>,
    pub(super) sens: Vec<nalgebra::Matrix3x2<f64>>,
    /// H_qq⁻¹[e_r, e_α] per roller and its ring-force image m·H_uq·H_qq⁻¹[e_r, e_α].
    pub(super) inertial_roller: Vec<nalgebra::Matrix3x2<f64>>,
    pub(super) inertial_ring: Vec<Matrix2<f64>>,
    /// Largest scaled roller residual, before the one-step Newton correction of
    /// `solve_rollers` (which only shrinks it).
    pub(super) worst: f64,
    /// The floating guide ring's terms (None without a guide ring).
    pub(super) guide: Option<GuideTerms>,
}

/// One roller's equilibrium at a fixed ring deflection as a [`NewtonSystem`]: the gradient
/// of its potential energy in q = (axial, radial, pitch) (eq. 3.9–3.11), its Hessian H_qq,
/// the energy as the line search's merit.
struct RollerSystem<'a> {
    p: &'a Problem,
    /// The row's frame sign (+1 row 1, −1 the mirrored row 2).
    sign: f64,
    cphi: f64,
    u: [f64; 2],
    /// The stepper's record of this roller's iterations and the ring iteration they belong to.
    trace: Option<(&'a mut Vec<TraceStep>, usize)>,
}

impl NewtonSystem<3> for RollerSystem<'_> {
    type Eval = RollerEval;

    /// The accepted trial of the line search is evaluated with its Hessian, so it is the
    /// next iterate's evaluation: one contact sweep per Newton iteration, not two.
    #[inline]
    fn evaluate(&mut self, q: &Vector3<f64>) -> RollerEval {
        self.p.eval_row(self.sign, self.cphi, self.u, q, true)
    }

    #[inline]
    fn residual<'e>(&self, e: &'e RollerEval) -> &'e Vector3<f64> {
        &e.g_q
    }

    #[inline]
    fn jacobian<'e>(&self, e: &'e RollerEval) -> &'e Matrix3<f64> {
        &e.h_qq
    }

    #[inline]
    fn residual_norm(&self, g: &Vector3<f64>) -> f64 {
        self.p.roller_residual(g)
    }

    /// Armijo on the energy without round-off slack: near convergence energy differences
    /// drown in round-off and the gradient test decides.
    #[inline]
    fn merit(&self, e: &RollerEval) -> f64 {
        e.energy
    }

    #[inline]
    fn slope(&self, e: &RollerEval, step: &Vector3<f64>) -> f64 {
        e.g_q.dot(step)
    }

    #[inline]
    fn newton_step(&self, e: &RollerEval) -> Option<Vector3<f64>> {
        Some(newton_step3(&e.h_qq, &e.g_q, &self.p.scale))
    }

    /// Trust region in the scaled norm (translation m, pitch × l_ref).
    #[inline]
    fn step_length(&self, step: &Vector3<f64>) -> f64 {
        (step[0].powi(2) + step[1].powi(2) + (step[2] * self.p.l_ref).powi(2)).sqrt()
    }

    fn observe(&mut self, it: usize, q: &Vector3<f64>, e: &RollerEval) {
        if let Some((steps, ring_it)) = self.trace.as_mut() {
            steps.push(
                self.p
                    .trace_step(*ring_it, it, self.cphi, self.u, q, &e.g_q),
            );
        }
    }
}
