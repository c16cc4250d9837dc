//! Adaptive solvers for initial-value problems `y' = f(t, y)`, `y(t0) = y0`.
//!
//! The problem ([`OdeSystem`]), the configuration ([`OdeOptions`], [`Output`],
//! [`Event`]) and the result ([`OdeSolution`] or [`OdeError`]) are separate types,
//! and a single entry point, [`solve`], runs one of two integrators:
//!
//! * [`Method::DormandPrince45`]: the explicit Dormand–Prince 5(4) pair with its
//!   fourth-order dense output — cheapest for non-stiff problems at loose tolerances;
//! * [`Method::Dop853`]: Hairer's explicit 8(5,3) pair with its seventh-order dense
//!   output — fewer evaluations at tight tolerances on smooth problems;
//! * [`Method::Sdirk`]: Rodas4, an L-stable linearly implicit (Rosenbrock) method of
//!   order 4(3) for stiff problems;
//! * [`Method::Auto`]: starts with DOPRI5 and switches, once and for good, to Rodas4
//!   when Hairer's stiffness test fires.
//!
//! Every loop is bounded (by [`OdeOptions::max_steps`] or a fixed iteration cap),
//! failures are reported as [`OdeError`] values carrying the numbers that explain
//! them, and cancellation is polled before every step attempt.

mod control;
mod dense;
mod dop853;
mod explicit;
mod fixed;
mod implicit;
mod problem;
mod rkn;
mod solution;
#[cfg(test)]
mod tests;

use crate::numerics::cancel::Cancel;
use dense::{brent, Interpolant};
use dop853::Dop853;
use explicit::Dopri5;
pub use fixed::{solve_dop853_fixed, EventSet, FixedSolution, FixedSystem, NoEvents};
use implicit::Rodas4;
pub use problem::{Direction, Event, FnEvent, FnSystem, Method, OdeOptions, OdeSystem, Output};
pub use rkn::{
    solve_rkn86, NoNystromEvents, NystromEvents, NystromOptions, NystromSolution, NystromSystem,
};
pub use solution::{EventRecord, OdeError, OdeSolution, OdeStats, Termination};

/// A system plus the work counters every evaluation must update.
struct Counted<'s, S: ?Sized> {
    sys: &'s S,
    rhs_evals: usize,
    jac_evals: usize,
    lu_decompositions: usize,
}

impl<'s, S: OdeSystem + ?Sized> Counted<'s, S> {
    fn new(sys: &'s S) -> Self {
        Counted {
            sys,
            rhs_evals: 0,
            jac_evals: 0,
            lu_decompositions: 0,
        }
    }

    /// Evaluate `f(t, y)` into `out`; `true` if every component is finite.
    fn eval(&mut self, t: f64, y: &[f64], out: &mut [f64]) -> bool {
        self.rhs_evals += 1;
        self.sys.rhs(t, y, out);
        out.iter().all(|v| v.is_finite())
    }
}

/// Error tolerances; `norm` is the weighted RMS norm used for step control.
#[derive(Debug, Clone, Copy)]
struct Tol {
    rtol: f64,
    atol: f64,
}

impl Tol {
    /// `sqrt(mean((e_i / (atol + rtol·max(|y_i|, |y_new_i|)))²))`, or NaN if the
    /// new state is not finite.
    fn norm(&self, y: &[f64], y_new: &[f64], e: &[f64]) -> f64 {
        let mut sum = 0.0;
        let mut count = 0.0;
        for ((&a, &b), &ei) in y.iter().zip(y_new).zip(e) {
            if !b.is_finite() {
                return f64::NAN;
            }
            let r = ei / (self.atol + self.rtol * a.abs().max(b.abs()));
            sum += r * r;
            count += 1.0;
        }
        if count > 0.0 {
            (sum / count).sqrt()
        } else {
            0.0
        }
    }
}

/// Why a trial step produced no usable error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum TrialError {
    /// A stage value, the new state or the Jacobian was NaN or infinite.
    NonFinite,
    /// The Rosenbrock matrix was singular.
    Singular,
    /// [`OdeSystem::jacobian`] left a matrix of the wrong shape.
    JacobianShape { rows: usize, cols: usize },
}

/// `out = y + h·Σ c_j k_j`.
fn lincomb(out: &mut [f64], y: &[f64], h: f64, terms: &[(f64, &[f64])]) {
    for (o, &yi) in out.iter_mut().zip(y) {
        *o = yi;
    }
    add_terms(out, h, terms);
}

/// `out = h·Σ c_j k_j`.
fn scaled_sum(out: &mut [f64], h: f64, terms: &[(f64, &[f64])]) {
    out.iter_mut().for_each(|o| *o = 0.0);
    add_terms(out, h, terms);
}

fn add_terms(out: &mut [f64], h: f64, terms: &[(f64, &[f64])]) {
    for &(c, k) in terms {
        let hc = h * c;
        for (o, &ki) in out.iter_mut().zip(k) {
            *o += hc * ki;
        }
    }
}

fn copy_into(dst: &mut [f64], src: &[f64]) {
    for (d, &s) in dst.iter_mut().zip(src) {
        *d = s;
    }
}

// ---------------------------------------------------------------------------
// Step-size control.

/// Safety factor on the predicted optimal step (Hairer's 0.9).
const SAFETY: f64 = 0.9;
/// Weight of the previous error in DOPRI5's PI controller (Hairer's β = 0.04):
/// damps the step-size oscillation a pure I-controller shows near stability limits.
const PI_BETA: f64 = 0.04;
/// Largest step decrease per attempt (h_new ≥ h/5) for both methods. (All
/// `clamp` bounds below are constants with min < max, so `clamp` cannot panic.)
const MAX_DECREASE: f64 = 5.0;
/// Largest step increase after an accepted step: 10 for DOPRI5, 6 for Rodas4
/// (Hairer's defaults; the implicit method's error estimate is less reliable far
/// from its last Jacobian, so it grows more cautiously).
const MAX_INCREASE_EXPLICIT: f64 = 10.0;
const MAX_INCREASE_IMPLICIT: f64 = 6.0;
/// DOP853's step-change bounds (Hairer's FAC1 = 0.333, FAC2 = 6).
const MAX_INCREASE_DOP853: f64 = 6.0;
const MAX_DECREASE_DOP853: f64 = 3.0;
/// Step reduction after a non-finite trial: harsher than an error rejection because
/// the error estimate, which would say by how much, does not exist.
const NONFINITE_SHRINK: f64 = 0.25;
/// Consecutive non-finite trials tolerated before giving up (0.25^50 ≈ 1e-30).
const MAX_NONFINITE_STREAK: usize = 50;
/// Step reduction after a singular Rosenbrock matrix, and how often to retry: the
/// matrix `(1/(hγ))I − J` is singular only when `1/(hγ)` hits an eigenvalue of `J`,
/// which a smaller step moves away from.
const SINGULAR_SHRINK: f64 = 0.5;
const MAX_SINGULAR_STREAK: usize = 10;
/// Hairer's stiffness test parameters (see [`Method::Auto`]).
const STIFF_HRHO: f64 = 3.25;
const STIFF_HITS: usize = 15;
const NONSTIFF_RESET: usize = 6;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Active {
    Explicit,
    /// DOP853.
    Explicit8,
    Implicit,
}

impl Active {
    fn error_exponent(self) -> f64 {
        match self {
            Active::Explicit => explicit::ERROR_EXPONENT,
            Active::Explicit8 => dop853::ERROR_EXPONENT,
            Active::Implicit => implicit::ERROR_EXPONENT,
        }
    }
}

/// Step-size controller state for the active method.
#[derive(Debug, Clone, Copy)]
struct Controller {
    active: Active,
    /// Previous accepted error (DOPRI5's PI controller).
    facold: f64,
    /// Previous accepted (h, err) for Gustafsson's predictive controller (Rodas4).
    previous: Option<(f64, f64)>,
    /// After a rejection the next accepted step must not grow (avoids ping-pong).
    rejected_last: bool,
}

impl Controller {
    fn new(active: Active) -> Self {
        Controller {
            active,
            facold: 1e-4,
            previous: None,
            rejected_last: false,
        }
    }

    /// Next step after accepting a step `h` with error norm `err ≤ 1`.
    fn accepted(&mut self, h: f64, err: f64) -> f64 {
        let fac = match self.active {
            Active::Explicit => {
                let fac11 = err.powf(explicit::ERROR_EXPONENT - 0.75 * PI_BETA);
                let fac = fac11 / self.facold.powf(PI_BETA) / SAFETY;
                self.facold = err.max(1e-4);
                fac.clamp(1.0 / MAX_INCREASE_EXPLICIT, MAX_DECREASE)
            }
            // Hairer's dop853.f defaults: no PI term (β = 0), h_new/h in [1/3, 6].
            Active::Explicit8 => (err.powf(dop853::ERROR_EXPONENT) / SAFETY)
                .clamp(1.0 / MAX_INCREASE_DOP853, MAX_DECREASE_DOP853),
            Active::Implicit => {
                let mut fac = (err.powf(implicit::ERROR_EXPONENT) / SAFETY)
                    .clamp(1.0 / MAX_INCREASE_IMPLICIT, MAX_DECREASE);
                // Gustafsson's predictive controller (Hairer & Wanner II, IV.8.22):
                // uses the error trend of the last two steps, which avoids the
                // repeated rejections a plain controller suffers on stiff problems.
                if let Some((h_prev, err_prev)) = self.previous {
                    let gus = (h_prev / h) * (err * err / err_prev).powf(implicit::ERROR_EXPONENT)
                        / SAFETY;
                    fac = fac.max(gus.clamp(1.0 / MAX_INCREASE_IMPLICIT, MAX_DECREASE));
                }
                self.previous = Some((h, err.max(1e-2)));
                fac
            }
        };
        let mut h_new = h / fac;
        if self.rejected_last && h_new.abs() > h.abs() {
            h_new = h;
        }
        self.rejected_last = false;
        h_new
    }

    /// Next step after rejecting a step `h` with error norm `err > 1`.
    fn rejected(&mut self, h: f64, err: f64) -> f64 {
        self.rejected_last = true;
        let fac = (err.powf(self.active.error_exponent()) / SAFETY).min(MAX_DECREASE);
        h / fac.max(1.0)
    }

    /// Record a rejection that had no error estimate.
    fn failed(&mut self) {
        self.rejected_last = true;
    }
}

/// Hairer's DOPRI5 stiffness counter.
#[derive(Debug, Clone, Copy, Default)]
struct StiffnessDetector {
    stiff_hits: usize,
    nonstiff_run: usize,
}

impl StiffnessDetector {
    /// Feed the indicator of an accepted step; `true` when the problem is judged stiff.
    fn update(&mut self, hrho: f64) -> bool {
        if hrho > STIFF_HRHO {
            self.nonstiff_run = 0;
            self.stiff_hits += 1;
            self.stiff_hits >= STIFF_HITS
        } else {
            self.nonstiff_run += 1;
            if self.nonstiff_run >= NONSTIFF_RESET {
                self.stiff_hits = 0;
            }
            false
        }
    }
}

/// Initial step size magnitude (Hairer's `HINIT`): make the first Euler step's
/// increment about 1% of the solution scale, then limit it so that the estimated
/// local error of a method of `order` is ~0.01 relative to tolerance, using one
/// extra evaluation to estimate `y''`.
#[allow(clippy::too_many_arguments)] // all are distinct inputs of the estimate
fn initial_step<S: OdeSystem + ?Sized>(
    rhs: &mut Counted<'_, S>,
    t0: f64,
    y0: &[f64],
    f0: &[f64],
    dir: f64,
    h_max: f64,
    order: f64,
    tol: Tol,
) -> f64 {
    let n = y0.len();
    let scale = |y: f64| tol.atol + tol.rtol * y.abs();
    let mut dnf = 0.0;
    let mut dny = 0.0;
    for (&y, &f) in y0.iter().zip(f0) {
        dnf += (f / scale(y)).powi(2);
        dny += (y / scale(y)).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        0.01 * (dny / dnf).sqrt()
    };
    h = h.min(h_max);
    let mut y1 = vec![0.0; n];
    let mut f1 = vec![0.0; n];
    lincomb(&mut y1, y0, dir * h, &[(1.0, f0)]);
    if !rhs.eval(t0 + dir * h, &y1, &mut f1) {
        // The probe left the domain of f: start very cautiously and let the
        // controller find its way.
        return (h * 1e-3).min(h_max);
    }
    let mut der2 = 0.0;
    for ((&a, &b), &y) in f1.iter().zip(f0).zip(y0) {
        der2 += ((a - b) / scale(y)).powi(2);
    }
    let count = y0.len().max(1) as f64;
    let der2 = (der2 / count).sqrt() / h;
    let der12 = der2.max((dnf / count).sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / order)
    };
    (100.0 * h).min(h1).min(h_max)
}

// ---------------------------------------------------------------------------
// Output collection.

struct Recorder {
    mode: Output,
    next_time: usize,
    t: Vec<f64>,
    y: Vec<Vec<f64>>,
}

impl Recorder {
    fn new(mode: Output) -> Self {
        Recorder {
            mode,
            next_time: 0,
            t: Vec::new(),
            y: Vec::new(),
        }
    }

    fn start(&mut self, t0: f64, y0: &[f64]) {
        match &self.mode {
            Output::Final => {}
            Output::Steps => {
                self.t.push(t0);
                self.y.push(y0.to_vec());
            }
            Output::Times(times) => {
                while let Some(&tr) = times.get(self.next_time) {
                    if tr != t0 {
                        break;
                    }
                    self.t.push(tr);
                    self.y.push(y0.to_vec());
                    self.next_time += 1;
                }
            }
        }
    }

    /// Whether a step ending at `t_stop` holds an output time other than `t_stop`
    /// (which needs the dense output).
    fn wants_dense(&self, t_stop: f64, dir: f64) -> bool {
        match &self.mode {
            Output::Times(times) => times
                .get(self.next_time)
                .is_some_and(|&tr| dir * (tr - t_stop) < 0.0),
            Output::Final | Output::Steps => false,
        }
    }

    /// Record what falls into the accepted step ending (possibly early, at a
    /// terminal event) at `t_stop` with state `y_stop`.
    fn step(&mut self, ip: &Interpolant, t_stop: f64, y_stop: &[f64], dir: f64) {
        match &self.mode {
            Output::Final => {}
            Output::Steps => {
                self.t.push(t_stop);
                self.y.push(y_stop.to_vec());
            }
            Output::Times(times) => {
                while let Some(&tr) = times.get(self.next_time) {
                    if dir * (tr - t_stop) > 0.0 {
                        break;
                    }
                    let mut yr = y_stop.to_vec();
                    if tr != t_stop {
                        ip.eval(tr, &mut yr);
                    }
                    self.t.push(tr);
                    self.y.push(yr);
                    self.next_time += 1;
                }
            }
        }
    }

    fn finish(
        mut self,
        t_final: f64,
        y_final: Vec<f64>,
        events: Vec<EventRecord>,
        stats: OdeStats,
        termination: Termination,
    ) -> OdeSolution {
        if self.mode == Output::Final {
            self.t.push(t_final);
            self.y.push(y_final.clone());
        }
        OdeSolution {
            t: self.t,
            y: self.y,
            t_final,
            y_final,
            events,
            stats,
            termination,
        }
    }
}

// ---------------------------------------------------------------------------
// Validation.

fn invalid<T>(what: String) -> Result<T, OdeError> {
    Err(OdeError::InvalidInput { what })
}

/// Check everything that can be checked before integrating; returns the dimension.
fn validate<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    t_end: f64,
    opts: &OdeOptions,
    output: &Output,
) -> Result<usize, OdeError> {
    let n = sys.dim();
    if n == 0 {
        return invalid("the system dimension is 0".into());
    }
    if y0.len() != n {
        return invalid(format!(
            "y0 has {} components but the system dimension is {n}",
            y0.len()
        ));
    }
    if !t0.is_finite() {
        return invalid(format!("t0 = {t0} is not finite"));
    }
    if !t_end.is_finite() {
        return invalid(format!("t_end = {t_end} is not finite"));
    }
    if let Some((i, v)) = y0.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return invalid(format!("y0[{i}] = {v} is not finite"));
    }
    let min_rtol = 10.0 * f64::EPSILON;
    if !(opts.rtol.is_finite() && opts.rtol >= min_rtol) {
        return invalid(format!(
            "rtol = {} must be finite and at least 10 machine epsilons ({min_rtol:e})",
            opts.rtol
        ));
    }
    if !(opts.atol.is_finite() && opts.atol > 0.0) {
        return invalid(format!("atol = {} must be finite and > 0", opts.atol));
    }
    if opts.h_max.is_nan() || opts.h_max <= 0.0 {
        return invalid(format!("h_max = {} must be > 0", opts.h_max));
    }
    if let Some(h0) = opts.h0 {
        if !(h0.is_finite() && h0 > 0.0) {
            return invalid(format!("h0 = {h0} must be finite and > 0"));
        }
    }
    if let Some(h) = opts.fixed_step {
        if !(h.is_finite() && h > 0.0) {
            return invalid(format!("fixed_step = {h} must be finite and > 0"));
        }
    }
    if let Output::Times(times) = output {
        let dir = if t_end >= t0 { 1.0 } else { -1.0 };
        if let Some(&tr) = times
            .iter()
            .find(|&&tr| !tr.is_finite() || dir * (tr - t0) < 0.0 || dir * (tr - t_end) > 0.0)
        {
            return invalid(format!(
                "output time {tr} is outside the integration interval [{t0}, {t_end}]"
            ));
        }
        if let Some(w) = times.windows(2).find(|w| match w {
            [a, b] => dir * (b - a) < 0.0,
            _ => false,
        }) {
            return invalid(format!(
                "output times must be ordered in the direction of integration ({:?})",
                w
            ));
        }
    }
    Ok(n)
}

fn crosses(direction: Direction, g_old: f64, g_new: f64) -> bool {
    let rising = g_old < 0.0 && g_new >= 0.0;
    let falling = g_old > 0.0 && g_new <= 0.0;
    match direction {
        Direction::Rising => rising,
        Direction::Falling => falling,
        Direction::Both => rising || falling,
    }
}

// ---------------------------------------------------------------------------
// The driver.

/// Assemble the solution, copying the work counters into the statistics.
fn finish<S: ?Sized>(
    rec: Recorder,
    rhs: &Counted<'_, S>,
    mut stats: OdeStats,
    found: Vec<EventRecord>,
    t_final: f64,
    y_final: Vec<f64>,
    termination: Termination,
) -> OdeSolution {
    stats.rhs_evaluations = rhs.rhs_evals;
    stats.jacobian_evaluations = rhs.jac_evals;
    stats.lu_decompositions = rhs.lu_decompositions;
    rec.finish(t_final, y_final, found, stats, termination)
}

/// Integrate `sys` from `(t0, y0)` to `t_end` (which may be less than `t0`) and
/// return the requested [`Output`], the located `events` and work statistics.
///
/// Stops early, successfully, at the first terminal event. Fails with an
/// [`OdeError`] on malformed input (nothing is integrated), when `cancel` is set
/// (checked before every step attempt), after [`OdeOptions::max_steps`] attempts,
/// or when the step size or the problem's values break down. Never panics.
///
/// `events` is a mutable slice of mutable references only so that stateful events
/// can be added later without changing this signature; [`Event`]'s methods take
/// `&self` today. Event indices in the result refer to positions in this slice.
#[allow(clippy::too_many_arguments)] // the project-wide signature; each argument is distinct
pub fn solve<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    t_end: f64,
    opts: &OdeOptions,
    events: &mut [&mut dyn Event],
    output: Output,
    cancel: Cancel<'_>,
) -> Result<OdeSolution, OdeError> {
    let n = validate(sys, t0, y0, t_end, opts, &output)?;
    if cancel.is_cancelled() {
        return Err(OdeError::Cancelled { t: t0 });
    }
    let tol = Tol {
        rtol: opts.rtol,
        atol: opts.atol,
    };
    let dir = if t_end >= t0 { 1.0 } else { -1.0 };
    let h_max = opts.h_max.min((t_end - t0).abs());
    let fixed = opts.fixed_step;

    let mut rhs = Counted::new(sys);
    let mut stats = OdeStats::default();
    let mut found: Vec<EventRecord> = Vec::new();
    let mut rec = Recorder::new(output);

    let mut t = t0;
    let mut y = y0.to_vec();
    let mut f0 = vec![0.0; n];
    if !rhs.eval(t0, &y, &mut f0) {
        return Err(OdeError::NonFinite { t: t0 });
    }
    rec.start(t0, &y);
    let mut g_prev: Vec<f64> = events.iter().map(|e| e.value(t0, &y)).collect();

    if t0 == t_end {
        return Ok(finish(
            rec,
            &rhs,
            stats,
            found,
            t0,
            y,
            Termination::ReachedEnd,
        ));
    }

    let mut active = match opts.method {
        Method::DormandPrince45 | Method::Auto => Active::Explicit,
        Method::Dop853 => Active::Explicit8,
        Method::Sdirk => Active::Implicit,
    };
    let mut h = match (fixed, opts.h0) {
        (Some(hf), _) => hf,
        (None, Some(h0)) => h0.min(h_max),
        (None, None) => {
            let order = match active {
                Active::Explicit => 5.0,
                Active::Explicit8 => 8.0,
                Active::Implicit => 4.0,
            };
            initial_step(&mut rhs, t0, &y, &f0, dir, h_max, order, tol)
        }
    } * dir;

    let mut ctl = Controller::new(active);
    let mut stiffness = StiffnessDetector::default();
    let mut dopri = Dopri5::new(n);
    let mut dop853: Option<Dop853> = match active {
        Active::Explicit8 => Some(Dop853::new(n)),
        _ => None,
    };
    // The n×n storage of the implicit method is only allocated when needed.
    let mut rodas: Option<Rodas4> = match active {
        Active::Implicit => Some(Rodas4::new(n)),
        Active::Explicit | Active::Explicit8 => None,
    };
    let mut ip = Interpolant::new(n);
    let mut y_new = vec![0.0; n];
    let mut y_buf = vec![0.0; n];
    let mut g_new = vec![0.0; events.len()];
    let mut hits: Vec<(f64, usize)> = Vec::new();

    let mut attempts: usize = 0;
    let mut nonfinite_streak: usize = 0;
    let mut singular_streak: usize = 0;
    let mut last_failure_nonfinite = false;

    enum Verdict {
        Accept(f64),
        Reject(f64),
        NonFinite,
        Singular,
        JacobianShape(usize, usize),
    }

    loop {
        if attempts >= opts.max_steps {
            return Err(OdeError::MaxSteps { steps: attempts, t });
        }
        if cancel.is_cancelled() {
            return Err(OdeError::Cancelled { t });
        }
        if fixed.is_none() {
            h = dir * h.abs().min(h_max);
        }
        // Stretch the step to t_end if it would otherwise leave a sliver of less
        // than 1% of h (Hairer's rule), and land on t_end exactly.
        let last = dir * (t + 1.01 * h - t_end) >= 0.0;
        if last {
            h = t_end - t;
        }
        let t_new = if last { t_end } else { t + h };
        if t_new == t || (!last && h.abs() <= 16.0 * f64::EPSILON * t.abs()) {
            return Err(if last_failure_nonfinite {
                OdeError::NonFinite { t }
            } else {
                OdeError::StepTooSmall { t, h }
            });
        }
        attempts += 1;

        let trial = match active {
            Active::Explicit => dopri.step(&mut rhs, t, &y, &f0, h, t_new, &mut y_new, tol),
            Active::Explicit8 => dop853
                .get_or_insert_with(|| Dop853::new(n))
                .step(&mut rhs, t, &y, &f0, h, t_new, &mut y_new, tol),
            Active::Implicit => rodas
                .get_or_insert_with(|| Rodas4::new(n))
                .step(&mut rhs, t, &y, &f0, h, t_new, &mut y_new, tol),
        };
        let mut verdict = match trial {
            Ok(err) if fixed.is_some() || err <= 1.0 => Verdict::Accept(err),
            Ok(err) => Verdict::Reject(err),
            Err(TrialError::NonFinite) => Verdict::NonFinite,
            Err(TrialError::Singular) => Verdict::Singular,
            Err(TrialError::JacobianShape { rows, cols }) => Verdict::JacobianShape(rows, cols),
        };
        // The implicit method needs f at the new point before the step can be used
        // (dense output, next step); DOPRI5 already has it as its last stage.
        if let (Verdict::Accept(_), Active::Implicit, Some(r)) = (&verdict, active, rodas.as_mut())
        {
            if !r.finish(&mut rhs, t_new, &y_new) {
                verdict = Verdict::NonFinite;
            }
        }
        // DOP853 likewise (its error estimate does not use the FSAL stage, so a
        // rejected step saves the evaluation).
        if let (Verdict::Accept(_), Active::Explicit8, Some(d)) =
            (&verdict, active, dop853.as_mut())
        {
            if !d.finish(&mut rhs, t_new, &y_new) {
                verdict = Verdict::NonFinite;
            }
        }

        let err = match verdict {
            Verdict::Accept(err) => err,
            Verdict::Reject(err) => {
                stats.rejected += 1;
                last_failure_nonfinite = false;
                h = ctl.rejected(h, err);
                continue;
            }
            Verdict::NonFinite => {
                stats.rejected += 1;
                nonfinite_streak += 1;
                if fixed.is_some() || nonfinite_streak > MAX_NONFINITE_STREAK {
                    return Err(OdeError::NonFinite { t });
                }
                last_failure_nonfinite = true;
                ctl.failed();
                h *= NONFINITE_SHRINK;
                continue;
            }
            Verdict::JacobianShape(rows, cols) => {
                return invalid(format!(
                    "OdeSystem::jacobian left a {rows}×{cols} matrix; it must stay {n}×{n}"
                ));
            }
            Verdict::Singular => {
                stats.rejected += 1;
                singular_streak += 1;
                if fixed.is_some() || singular_streak > MAX_SINGULAR_STREAK {
                    return Err(OdeError::SingularMatrix { t, h });
                }
                last_failure_nonfinite = false;
                ctl.failed();
                h *= SINGULAR_SHRINK;
                continue;
            }
        };

        // ---- The step is accepted.
        stats.steps += 1;
        nonfinite_streak = 0;
        singular_streak = 0;
        last_failure_nonfinite = false;
        // DOP853's dense output costs three evaluations: built below only if the step
        // holds an output time or an event crossing.
        let mut dense_ready = true;
        match active {
            Active::Explicit => dopri.dense(&mut ip, t, h, &y, &y_new, &f0),
            Active::Implicit => {
                if let Some(r) = rodas.as_ref() {
                    ip.set_hermite(t, h, &y, &y_new, &f0, r.f_new());
                }
            }
            Active::Explicit8 => dense_ready = false,
        }

        let switch_now = opts.method == Method::Auto
            && active == Active::Explicit
            && dopri
                .stiffness_indicator(h, &y_new)
                .is_some_and(|hrho| stiffness.update(hrho));

        // Events: detect sign changes over the step, locate each on the dense
        // output, then handle them in time order up to the first terminal one.
        hits.clear();
        for (index, ((ev, &go), gn)) in events.iter().zip(&g_prev).zip(g_new.iter_mut()).enumerate()
        {
            *gn = ev.value(t_new, &y_new);
            if crosses(ev.direction(), go, *gn) {
                if !dense_ready {
                    if let Some(d) = dop853.as_mut() {
                        if !d.dense(&mut rhs, &mut ip, t, h, &y, &y_new) {
                            return Err(OdeError::NonFinite { t });
                        }
                    }
                    dense_ready = true;
                }
                let tr = if *gn == 0.0 {
                    t_new
                } else {
                    brent(
                        |s| {
                            ip.eval(s, &mut y_buf);
                            ev.value(s, &y_buf)
                        },
                        t,
                        t_new,
                        go,
                        *gn,
                    )
                };
                hits.push((tr, index));
            }
        }
        hits.sort_by(|a, b| (dir * a.0).total_cmp(&(dir * b.0)).then(a.1.cmp(&b.1)));
        let mut stop: Option<(usize, f64, Vec<f64>)> = None;
        for &(tr, index) in &hits {
            let mut yr = y_new.clone();
            if tr != t_new {
                ip.eval(tr, &mut yr);
            }
            found.push(EventRecord {
                index,
                t: tr,
                y: yr.clone(),
            });
            if events.get(index).is_some_and(|e| e.terminal()) {
                stop = Some((index, tr, yr));
                break;
            }
        }

        if !dense_ready && rec.wants_dense(t_new, dir) {
            if let Some(d) = dop853.as_mut() {
                if !d.dense(&mut rhs, &mut ip, t, h, &y, &y_new) {
                    return Err(OdeError::NonFinite { t });
                }
            }
        }
        if let Some((index, te, ye)) = stop {
            rec.step(&ip, te, &ye, dir);
            return Ok(finish(
                rec,
                &rhs,
                stats,
                found,
                te,
                ye,
                Termination::Event { index, t: te },
            ));
        }
        rec.step(&ip, t_new, &y_new, dir);

        // Advance.
        let f_new: &[f64] = match (active, rodas.as_ref(), dop853.as_ref()) {
            (Active::Implicit, Some(r), _) => r.f_new(),
            (Active::Explicit8, _, Some(d)) => d.f_new(),
            _ => dopri.f_new(),
        };
        copy_into(&mut f0, f_new);
        std::mem::swap(&mut y, &mut y_new);
        t = t_new;
        copy_into(&mut g_prev, &g_new);
        if let Some(r) = rodas.as_mut() {
            r.invalidate_jacobian();
        }
        if last {
            return Ok(finish(
                rec,
                &rhs,
                stats,
                found,
                t,
                y,
                Termination::ReachedEnd,
            ));
        }
        if let Some(hf) = fixed {
            h = dir * hf;
        } else {
            h = ctl.accepted(h, err);
        }
        if switch_now {
            active = Active::Implicit;
            ctl = Controller::new(active);
            stats.switched_to_implicit_at = Some(t);
            rodas.get_or_insert_with(|| Rodas4::new(n));
        }
    }
}
