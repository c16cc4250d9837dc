//! Error norms and the step-size controller shared by the fixed-size DOP853 driver
//! ([`super::solve_dop853_fixed`]) and the Runge–Kutta–Nyström 8(6) pair
//! ([`super::solve_rkn86`]) (issue 25: one controller, not two copies).
//!
//! Both follow Hairer's `dop853.f`: the error of a trial step is a weighted norm with
//! the weights sk = atol + rtol·max(|y|, |y_new|); a step with err ≤ 1 is accepted and
//! the next one is h/fac with fac = err^(1/(p̂+1))/0.9 kept in [1/6, 3] (FAC2, FAC1);
//! a rejected step shrinks by at most 5 and never grows; a step accepted right after a
//! rejection does not grow (no ping-pong); a non-finite trial shrinks the step by 4, at
//! most `MAX_NONFINITE_STREAK` times in a row. The arithmetic is the general path's
//! ([`super::Controller`] for [`super::Method::Dop853`]) operation for operation, so the
//! fixed-size DOP853 path keeps its last bit.

use super::{
    OdeError, MAX_DECREASE, MAX_DECREASE_DOP853, MAX_INCREASE_DOP853, MAX_NONFINITE_STREAK,
    NONFINITE_SHRINK, SAFETY,
};

/// The error weight sk = atol + rtol·max(|a|, |b|) of a component that was `a` at the
/// step's start and is `b` at its end.
#[inline(always)]
pub(super) fn weight(atol: f64, rtol: f64, a: f64, b: f64) -> f64 {
    atol + rtol * a.abs().max(b.abs())
}

/// The weighted RMS norm √(Σ (e_i/sk_i)² / n), accumulated component by component (in
/// the order the components are added).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct RmsNorm {
    sum: f64,
    count: usize,
}

impl RmsNorm {
    /// Add the error `e` of a component with weight `sk`.
    #[inline(always)]
    pub(super) fn add(&mut self, e: f64, sk: f64) {
        let r = e / sk;
        self.sum += r * r;
        self.count += 1;
    }

    /// The norm (0 with no component).
    #[inline(always)]
    pub(super) fn value(&self) -> f64 {
        if self.count > 0 {
            (self.sum / self.count as f64).sqrt()
        } else {
            0.0
        }
    }
}

/// DOP853's "stretched" 5(3) error: with ‖e5‖², ‖e3‖² the sk-weighted sums of squares
/// over the `n` components, err = |h|·‖e5‖² / √(n (‖e5‖² + 0.01 ‖e3‖²)) (Hairer,
/// `dop853.f`), which behaves like h⁸.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct StretchedNorm {
    e5: f64,
    e3: f64,
}

impl StretchedNorm {
    /// Add a component's fifth- and third-order error estimates with weight `sk`.
    #[inline(always)]
    pub(super) fn add(&mut self, r5: f64, r3: f64, sk: f64) {
        self.e5 += (r5 / sk) * (r5 / sk);
        self.e3 += (r3 / sk) * (r3 / sk);
    }

    /// The error of a step `h` over `n` components.
    #[inline(always)]
    pub(super) fn value(&self, h: f64, n: usize) -> f64 {
        let denom = self.e5 + 0.01 * self.e3;
        if denom > 0.0 {
            h.abs() * self.e5 / (denom * n as f64).sqrt()
        } else {
            0.0
        }
    }
}

/// How the accepted step's successor is written: the same quantity, two roundings.
/// Each integrator keeps the one its answers were produced with (one form for both
/// moves the Nyström pair's step sequence by rounding and its film-off outputs by up to
/// 1.9e-7 relative on `decks/crb_truck.toml`, measured: inside its 1e-6 tolerance, but
/// not a refactor).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Proposal {
    /// h/fac with fac = err^exponent/0.9 clamped to [1/6, 3] (`dop853.f`; the general
    /// path's DOP853).
    Quotient,
    /// 0.9·h·err^(−exponent) clamped to [h/3, 6·base] (the Nyström pair).
    Product,
}

/// The step-size controller's state between attempts (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct StepControl {
    /// 1/(p̂ + 1), p̂ the order of the error estimate.
    exponent: f64,
    /// The rounding of the proposal.
    form: Proposal,
    /// Whether the last attempt was rejected (the next accepted step must not grow).
    rejected_last: bool,
    /// Non-finite trials in a row.
    nonfinite_streak: usize,
    /// Whether the last failure was a non-finite trial (names the error when the step
    /// becomes too small).
    last_failure_nonfinite: bool,
}

impl StepControl {
    /// A controller for an error estimate behaving like h^(1/exponent).
    pub(super) fn new(exponent: f64, form: Proposal) -> Self {
        StepControl {
            exponent,
            form,
            rejected_last: false,
            nonfinite_streak: 0,
            last_failure_nonfinite: false,
        }
    }

    /// The step after rejecting step `h` with error `err > 1`.
    #[inline]
    pub(super) fn rejected(&mut self, h: f64, err: f64) -> f64 {
        self.last_failure_nonfinite = false;
        self.rejected_last = true;
        let fac = (err.powf(self.exponent) / SAFETY).min(MAX_DECREASE);
        h / fac.max(1.0)
    }

    /// The step after a trial at `t` with step `h` that was not finite, or the error
    /// that ends the integration (a fixed step cannot shrink; too many in a row).
    #[inline]
    pub(super) fn nonfinite(&mut self, t: f64, h: f64, fixed: bool) -> Result<f64, OdeError> {
        self.nonfinite_streak += 1;
        if fixed || self.nonfinite_streak > MAX_NONFINITE_STREAK {
            return Err(OdeError::NonFinite { t });
        }
        self.last_failure_nonfinite = true;
        self.rejected_last = true;
        Ok(h * NONFINITE_SHRINK)
    }

    /// Record an accepted step.
    #[inline]
    pub(super) fn accepted(&mut self) {
        self.nonfinite_streak = 0;
        self.last_failure_nonfinite = false;
    }

    /// The next step's magnitude after accepting a step of magnitude `step` with error
    /// `err ≤ 1`: step/fac, fac = err^exponent/0.9 in [1/6, 3], growth bounded against
    /// `base ≥ step` (`base = step` but for a step shortened to land on an output time:
    /// the controller's own step there) and none right after a rejection. With
    /// `base = step` and [`Proposal::Quotient`] this is `dop853.f`'s h/fac with fac
    /// clamped, bit for bit.
    #[inline]
    pub(super) fn proposal(&self, step: f64, base: f64, err: f64) -> f64 {
        let h_new = match self.form {
            Proposal::Quotient => {
                let fac = err.powf(self.exponent) / SAFETY;
                let lo = 1.0 / MAX_INCREASE_DOP853;
                if fac < lo {
                    base / lo
                } else {
                    step / fac.min(MAX_DECREASE_DOP853)
                }
            }
            Proposal::Product => (SAFETY * step * err.powf(-self.exponent))
                .clamp(step / MAX_DECREASE_DOP853, base * MAX_INCREASE_DOP853),
        };
        if self.rejected_last && h_new > step {
            step
        } else {
            h_new
        }
    }

    /// The next attempt follows an accepted step.
    #[inline]
    pub(super) fn advanced(&mut self) {
        self.rejected_last = false;
    }

    /// The error when the step `h` at `t` has become too small to change `t`.
    pub(super) fn too_small(&self, t: f64, h: f64) -> OdeError {
        if self.last_failure_nonfinite {
            OdeError::NonFinite { t }
        } else {
            OdeError::StepTooSmall { t, h }
        }
    }
}

/// Check output times for a driver from `t0` to `t_end` (either direction): finite,
/// inside the interval and ordered in the direction of integration.
pub(super) fn check_times(times: &[f64], t0: f64, t_end: f64) -> Result<(), OdeError> {
    let dir = if t_end >= t0 { 1.0 } else { -1.0 };
    if let Some(&tr) = times
        .iter()
        .find(|&&tr| !tr.is_finite() || dir * (tr - t0) < 0.0 || dir * (tr - t_end) > 0.0)
    {
        return Err(OdeError::InvalidInput {
            what: format!("output time {tr} is outside the integration interval [{t0}, {t_end}]"),
        });
    }
    if times.windows(2).any(|w| dir * (w[1] - w[0]) < 0.0) {
        return Err(OdeError::InvalidInput {
            what: "output times must be ordered in the direction of integration".into(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_proposal_is_dop853_f_with_its_clamp() {
        // Against the general path's formula h/fac, fac = (err^(1/8)/0.9) clamped to
        // [1/6, 3], over errors from 1e-30 to 1 (both clamps and the middle): equal to
        // the last bit; after a rejection no growth; a landing step's growth bounded by
        // its base.
        let mut c = StepControl::new(0.125, Proposal::Quotient);
        for j in 0..=3000 {
            let err = 10f64.powf(-30.0 + 30.0 * f64::from(j) / 3000.0);
            for h in [1e-6, 3.7e-4, 0.25] {
                let fac = (err.powf(0.125) / SAFETY)
                    .clamp(1.0 / MAX_INCREASE_DOP853, MAX_DECREASE_DOP853);
                assert_eq!(c.proposal(h, h, err).to_bits(), (h / fac).to_bits());
            }
        }
        assert_eq!(c.proposal(1.0, 10.0, 1e-30), 60.0);
        // The Nyström pair's rounding of the same proposal: within a few ulps.
        let p = StepControl::new(0.125, Proposal::Product);
        for err in [1e-30, 1e-9, 0.3, 1.0] {
            let (a, b) = (c.proposal(0.25, 0.25, err), p.proposal(0.25, 0.25, err));
            assert!((a / b - 1.0).abs() <= 4.0 * f64::EPSILON, "{err}: {a} {b}");
        }
        assert_eq!(p.proposal(1.0, 10.0, 1e-30), 60.0);
        let _ = c.rejected(1.0, 2.0);
        assert_eq!(c.proposal(1.0, 1.0, 1e-30), 1.0);
        c.advanced();
        assert_eq!(c.proposal(1.0, 1.0, 1e-30), 6.0);
    }

    #[test]
    fn rejections_shrink_and_non_finite_trials_are_bounded() {
        let mut c = StepControl::new(0.125, Proposal::Quotient);
        // err^(1/8)/0.9 capped at 5: never below h/5, never above h.
        assert_eq!(c.rejected(1.0, 1e30), 0.2);
        assert!(c.rejected(1.0, 1.0 + 1e-12) <= 1.0);
        assert!(matches!(
            c.too_small(1.0, 0.0),
            OdeError::StepTooSmall { .. }
        ));
        let mut h = 1.0;
        for _ in 0..MAX_NONFINITE_STREAK {
            h = c.nonfinite(0.5, h, false).unwrap_or_else(|e| panic!("{e}"));
        }
        assert!(matches!(c.too_small(1.0, h), OdeError::NonFinite { .. }));
        assert!(matches!(
            c.nonfinite(0.5, h, false),
            Err(OdeError::NonFinite { .. })
        ));
        let mut d = StepControl::new(0.125, Proposal::Quotient);
        assert!(matches!(
            d.nonfinite(0.5, 1.0, true),
            Err(OdeError::NonFinite { .. })
        ));
    }
}
