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
//! so it passes no axial load to the inner ring. It is solved around the ring equilibrium
//! (nested): for each trial s the ring Newton in (Δz, Δx) with every roller in equilibrium
//! (the guide ring held at s), then a Newton step on R(s) with its exact slope (the rollers
//! and the rings condensed). R decreases monotonically in s (moving the ring toward row 1
//! closes row 1's end gaps and opens row 2's), so once the root is bracketed a step that
//! leaves the bracket is replaced by bisection; each ring solve starts from the last.
//!
//! Where only one row touches it, it moves until that row's ends no longer press it: then
//! no roller touches it and s is indeterminate within the free travel [s_lo, s_hi] (the
//! offsets at which the first end of row 2, respectively row 1, would touch, the rollers
//! and rings staying where they are: without a contact they do not depend on s). The rule:
//! s = clamp(0, s_lo, s_hi), the centred place where it is free, else the nearest end of the
//! free travel (a drag-free ring stays where the inner ring carried it, which is the least
//! motion from centred). A guide ring that touches neither row at s = 0 thus stays centred.

use std::sync::atomic::AtomicBool;

use nalgebra::{Matrix2, Vector2, Vector3};

use super::driver::RingState;
use super::problem::Problem;
use super::{SolveStats, TraceStep};
use crate::bearings::spherical_roller::geometry::Pitch;
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;
use crate::numerics::newton::Factor3;

/// Most ring solves the guide ring's balance may take.
const MAX_FLOAT_SOLVES: usize = 60;

/// The guide ring's state at one offset: the forces of each row's ends on it, its net axial
/// force and the free travel (when no end touches it).
#[derive(Debug, Clone, Copy)]
pub(super) struct GuideBalance {
    /// Σ over each row's rollers of the end force magnitudes, N.
    pub(super) row_force_n: [f64; 2],
    /// R, the net axial force of both rows on the guide ring, N (+ toward row 1).
    pub(super) net_n: f64,
    /// −∂R/∂s with rollers and rings held (the end contacts' Hertz stiffness, cos²α⁰·Σ dF/dδ),
    /// N/m: an upper bound of the true −dR/ds, where the rollers also give way.
    pub(super) rigid_stiffness_n_m: f64,
    /// Offsets between which no roller end touches the ring, rollers and rings held, m.
    pub(super) free: (f64, f64),
}

impl Problem {
    /// The guide ring's balance at ring deflection `u` (bearing frame) and rollers `qs`, at the
    /// current offset.
    pub(super) fn guide_balance(&self, u: [f64; 2], qs: &[Vector3<f64>]) -> GuideBalance {
        let mut out = GuideBalance {
            row_force_n: [0.0; 2],
            net_n: 0.0,
            rigid_stiffness_n_m: 0.0,
            free: (f64::NEG_INFINITY, f64::INFINITY),
        };
        let Some(guide) = &self.guide else {
            return out;
        };
        let a0 = self.geom.axis[0];
        let s = self.guide_offset.get();
        for (k, (&(cphi, mult), q)) in self.unique.iter().zip(qs).enumerate() {
            let sign = self.signs[k];
            let row = usize::from(sign < 0.0);
            let (gap, ..) =
                self.guide_gap(guide, sign, cphi, self.local_u(k, u), q, Pitch::new(q[2]));
            if gap < 0.0 {
                let root = (-gap).sqrt();
                out.row_force_n[row] += mult * guide.hertz_constant * (-gap) * root;
                out.rigid_stiffness_n_m += mult * 1.5 * guide.hertz_constant * root * a0 * a0;
            }
            // ∂g/∂s = −sign·cos α⁰: row 1's gap closes as s grows, row 2's opens.
            if row == 0 {
                out.free.1 = out.free.1.min(s + gap / a0);
            } else {
                out.free.0 = out.free.0.max(s - gap / a0);
            }
        }
        out.net_n = a0 * (out.row_force_n[1] - out.row_force_n[0]);
        out
    }

    /// The ring equilibrium with the guide ring floating: the ring solve at trial offsets
    /// until the guide ring's net axial force is within the ring tolerance (or no roller
    /// touches it, then the rule of the module doc). Leaves the offset in `guide_offset`.
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
        let mut state = self.ring_equilibrium(b, u, qs, stats, trace, cancel)?;
        let mut gb = self.guide_balance(*u, qs);
        // Bracket: the offsets with R > 0 (the balance lies at larger s) and with R < 0.
        let mut below: Option<f64> = None;
        let mut above: Option<f64> = None;
        for _ in 0..MAX_FLOAT_SOLVES {
            if gb.row_force_n == [0.0, 0.0] {
                // Free: no end touches it; the rollers and rings do not depend on s within
                // the free travel, so only the reported offset follows the rule.
                let (lo, hi) = gb.free;
                let s_rule = if lo <= hi { 0.0f64.max(lo).min(hi) } else { s };
                self.guide_offset.set(s_rule);
                return Ok(state);
            }
            let r = gb.net_n;
            let (k_ss, k_su, dq_ds) = self.guide_condensed(*u, qs, &state);
            if r.abs() <= self.tol {
                float_stiffness(&mut state, k_ss, k_su);
                return Ok(state);
            }
            if r > 0.0 {
                below = Some(s);
            } else {
                above = Some(s);
            }
            if let (Some(sa), Some(sb)) = (below, above) {
                if (sb - sa).abs() <= 1e-13 * d {
                    // The bracket is at round-off: accept a residual within 10³ of the
                    // tolerance (as the ring Newton does), else say so.
                    if r.abs() <= 1e3 * self.tol {
                        float_stiffness(&mut state, k_ss, k_su);
                        return Ok(state);
                    }
                    return Err(self.float_error(s, r, "its bracket closed"));
                }
            }
            // Newton on R(s) with its exact slope, the rings re-balancing: −dR/ds =
            // k_ss − k_su·K⁻¹·k_us (K the ring stiffness with the guide ring held). Where one
            // row alone presses it, R ∝ δ^(3/2) near the release and Newton's step is 2/3 of
            // the way there: stepped 1.5× (exact for a pure 3/2 law; past the release the
            // ring is free and the rule above ends the iteration).
            let k_inv = state.k.try_inverse();
            let k_eff = match k_inv {
                Some(ki) => k_ss - (k_su.transpose() * ki * k_su)[(0, 0)],
                None => k_ss,
            };
            let k_eff = if k_eff > 0.0 && k_eff.is_finite() {
                k_eff
            } else {
                gb.rigid_stiffness_n_m.max(f64::MIN_POSITIVE)
            };
            let one_sided = gb.row_force_n[0] == 0.0 || gb.row_force_n[1] == 0.0;
            let ds = r / k_eff * if one_sided { 1.5 } else { 1.0 };
            let mut next = s + ds.clamp(-0.05 * d, 0.05 * d);
            // Safeguard: stay inside the bracket (bisect when Newton leaves it).
            if let (Some(sa), Some(sb)) = (below, above) {
                let (lo, hi) = (sa.min(sb), sa.max(sb));
                if !(next > lo && next < hi) {
                    next = 0.5 * (sa + sb);
                }
            }
            if !next.is_finite() || next.abs() > 0.5 * d {
                return Err(self.float_error(s, r, "it left ±D/2 of its centred place"));
            }
            // First-order start of the next ring solve: du = −K⁻¹·k_us·Δs and each roller
            // dq = (dq/du)·du + (dq/ds)·Δs (the linearised equilibria; Newton does the rest).
            if let Some(ki) = k_inv {
                let step = next - s;
                let du = -(ki * k_su) * step;
                if du.amax() <= 1e-3 * d {
                    u[0] += du[0];
                    u[1] += du[1];
                    for ((q, sens), dqs) in qs.iter_mut().zip(&state.sens).zip(&dq_ds) {
                        *q += sens * du + dqs * step;
                    }
                }
            }
            s = next;
            self.guide_offset.set(s);
            state = self.ring_equilibrium(b, u, qs, stats, trace, cancel)?;
            gb = self.guide_balance(*u, qs);
        }
        Err(self.float_error(s, gb.net_n, "the solve budget ran out"))
    }

    /// The guide ring offset's stiffnesses with the rollers condensed (the ring held):
    /// k_ss = Σ m·(h_ss − h_sq·H_qq⁻¹·h_qs) and k_su = Σ m·(h_su + h_sq·dq/du), from the end
    /// contacts' Hertz energy (only they depend on s: ∂g/∂s = −sign·cos α⁰, the same as
    /// ∂g/∂u_a in the bearing frame). Zero without an end contact. Also each roller's
    /// dq/ds = −H_qq⁻¹·h_qs at the ring held.
    fn guide_condensed(
        &self,
        u: [f64; 2],
        qs: &[Vector3<f64>],
        state: &RingState,
    ) -> (f64, Vector2<f64>, Vec<Vector3<f64>>) {
        let mut k_ss = 0.0;
        let mut k_su = Vector2::zeros();
        let mut dq_ds = vec![Vector3::zeros(); qs.len()];
        let Some(guide) = &self.guide else {
            return (k_ss, k_su, dq_ds);
        };
        let a0 = self.geom.axis[0];
        for (k, (&(cphi, mult), q)) in self.unique.iter().zip(qs).enumerate() {
            let sign = self.signs[k];
            let ul = self.local_u(k, u);
            let (gap, dq, _, du) = self.guide_gap(guide, sign, cphi, ul, q, Pitch::new(q[2]));
            if gap >= 0.0 {
                continue;
            }
            let df = 1.5 * guide.hertz_constant * (-gap).sqrt();
            let ds = -sign * a0;
            let du_b = Vector2::new(sign * du[0], du[1]);
            let h_sq = df * ds * dq;
            let ev = self.eval_row(sign, cphi, ul, q, true);
            let x = Factor3::new(&ev.h_qq, &self.scale).solve(&h_sq);
            k_ss += mult * (df * ds * ds - h_sq.dot(&x));
            let sens = state.sens[k];
            k_su += mult * (df * ds * du_b + (h_sq.transpose() * sens).transpose());
            dq_ds[k] = -x;
        }
        (k_ss, k_su, dq_ds)
    }

    fn float_error(&self, s: f64, r: f64, why: &str) -> SolveError {
        SolveError::Stage {
            stage: "guide ring balance (issue 27 Model 1)",
            message: format!(
                "the floating guide ring found no axial balance ({why}): at offset {s:.4e} m the roller ends still push it with a net {r:.4e} N (tolerance {:.3e} N, {MAX_FLOAT_SOLVES} ring solves at most)",
                self.tol
            ),
        }
    }
}

/// The ring stiffness with the guide ring floating: the ring solve's condensed stiffness K
/// (guide ring held at s) with s condensed out as well, K_float = K − k_us·k_su/k_ss
/// ([`Problem::guide_condensed`]). Without an end contact k_ss = 0 and K is unchanged.
fn float_stiffness(state: &mut RingState, k_ss: f64, k_su: Vector2<f64>) {
    if k_ss > 0.0 && k_ss.is_finite() {
        let corr: Matrix2<f64> = k_su * k_su.transpose() / k_ss;
        state.k -= corr;
    }
}
