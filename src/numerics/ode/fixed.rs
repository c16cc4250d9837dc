//! DOP853 for small systems of a dimension known at compile time (issue 25, Speed).
//!
//! The same method, step-size controller, dense output and event location as
//! [`super::solve`] with [`super::Method::Dop853`], and the same arithmetic in the same
//! order (so the same steps and the same numbers to the last bit), but every vector is
//! a `[f64; N]` on the stack: no heap buffer per stage, no dynamic-length loop, no
//! `Vec` per recorded output (a callback takes each output state), and the event
//! functions are asked as one set per step ([`EventSet::values`]), so that a set with a
//! cheap common bound (the cylindrical roller's contacts while the interference holds
//! every roller loaded) costs one test per step rather than one call per event.
//!
//! The general path ([`super::solve`]) stays for everything else (any dimension, the
//! other methods, `Output::Steps`, non-terminal events).

use super::control::{check_times, weight, Proposal, StepControl, StretchedNorm};
use super::dense::brent;
use super::dop853::{A, C, D, E3, E5, ERROR_EXPONENT};
use super::{
    initial_step, validate, Counted, OdeError, OdeOptions, OdeStats, OdeSystem, Output,
    Termination, Tol,
};
use crate::numerics::cancel::Cancel;

/// A system `y' = f(t, y)` of dimension `N`.
pub trait FixedSystem<const N: usize> {
    /// f(t, y).
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N];
}

/// A set of terminal event functions g_i(t, y), i < [`EventSet::len`], each counting
/// sign changes in both directions (as [`super::Event`] with `Direction::Both` and
/// `terminal() = true`): integration stops at the first crossing located.
pub trait EventSet<const N: usize> {
    /// Number of event functions.
    fn len(&self) -> usize;
    /// Whether the set is empty.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// All g_i(t, y) into `out` (`out.len() == self.len()`).
    fn values(&self, t: f64, y: &[f64; N], out: &mut [f64]);
    /// g_i(t, y) alone (for locating a crossing).
    fn value(&self, i: usize, t: f64, y: &[f64; N]) -> f64;
}

/// No events.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoEvents;

impl<const N: usize> EventSet<N> for NoEvents {
    fn len(&self) -> usize {
        0
    }
    fn values(&self, _t: f64, _y: &[f64; N], _out: &mut [f64]) {}
    fn value(&self, _i: usize, _t: f64, _y: &[f64; N]) -> f64 {
        1.0
    }
}

/// What [`solve_dop853_fixed`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct FixedSolution<const N: usize> {
    /// Where integration stopped (`t_end` or the event time).
    pub t_final: f64,
    /// The state there.
    pub y_final: [f64; N],
    /// Work counters.
    pub stats: OdeStats,
    /// Why integration stopped.
    pub termination: Termination,
    /// The step the controller proposed after the last accepted step (magnitude): a
    /// restart's first step (the step that straddled an event, or the last one, was
    /// accepted at this accuracy, so a restart need not search from a small `h0`).
    pub h_next: f64,
}

/// Adapter so that the general path's input checks and initial-step estimate serve.
struct AsDyn<'s, S, const N: usize>(&'s S);

impl<const N: usize, S: FixedSystem<N>> OdeSystem for AsDyn<'_, S, N> {
    fn dim(&self) -> usize {
        N
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let mut a = [0.0; N];
        a.copy_from_slice(y);
        dydt.copy_from_slice(&self.0.rhs(t, &a));
    }
}

/// f(t, y) into `out`; `true` if finite.
#[inline(always)]
fn eval<const N: usize, S: FixedSystem<N>>(
    sys: &S,
    count: &mut usize,
    t: f64,
    y: &[f64; N],
    out: &mut [f64; N],
) -> bool {
    *count += 1;
    *out = sys.rhs(t, y);
    out.iter().all(|v| v.is_finite())
}

/// `y + h·Σ_{j<s} A[s][j]·k_j`, summed over ascending j with zero coefficients skipped
/// (the general path's `Dop853::stage_point`, the same roundings).
#[inline(always)]
fn stage_point<const N: usize>(k: &[[f64; N]; 16], y: &[f64; N], h: f64, s: usize) -> [f64; N] {
    let mut acc = [0.0; N];
    for (j, &a) in A[s].iter().enumerate().take(s) {
        if a != 0.0 {
            for (acc_i, &kji) in acc.iter_mut().zip(&k[j]) {
                *acc_i += a * kji;
            }
        }
    }
    let mut out = [0.0; N];
    for ((o, &yi), &ai) in out.iter_mut().zip(y).zip(&acc) {
        *o = yi + h * ai;
    }
    out
}

/// Stage `S` of a step: its point by [`stage_point`] with `S` known at compile time (the
/// tableau row a constant, its zero entries dropped and the loops unrolled; the same
/// operations in the same order), `f` there into `k[S]`; `false` if not finite.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the step's state, each distinct
fn stage<const N: usize, const S: usize, Sys: FixedSystem<N>>(
    sys: &Sys,
    evals: &mut usize,
    k: &mut [[f64; N]; 16],
    y: &[f64; N],
    h: f64,
    t: f64,
    t_new: f64,
) -> bool {
    let point = stage_point(k, y, h, S);
    let ts = if S == 11 { t_new } else { t + C[S] * h };
    let mut out = [0.0; N];
    if !eval(sys, evals, ts, &point, &mut out) {
        return false;
    }
    k[S] = out;
    true
}

/// The seventh-order continuous extension of one step (the general path's
/// `Interpolant` with DOP853's `r1..r8`).
#[derive(Debug, Clone, Copy)]
struct Dense<const N: usize> {
    t: f64,
    h: f64,
    r: [[f64; N]; 8],
}

impl<const N: usize> Dense<N> {
    #[inline]
    fn eval(&self, t_out: f64) -> [f64; N] {
        let theta = if self.h == 0.0 {
            0.0
        } else {
            (t_out - self.t) / self.h
        };
        let theta1 = 1.0 - theta;
        let r = &self.r;
        std::array::from_fn(|i| {
            let tail = r[4][i] + theta * (r[5][i] + theta1 * (r[6][i] + theta * r[7][i]));
            r[0][i] + theta * (r[1][i] + theta1 * (r[2][i] + theta * (r[3][i] + theta1 * tail)))
        })
    }
}

/// Integrate `sys` from `(t0, y0)` to `t_end` by DOP853 with the controller and
/// options of [`super::solve`] (`opts.method` is ignored; `opts.fixed_step` is
/// honoured), stopping at the first crossing of an event of `events`. `record(t, y)` is
/// called for every time of `times` (ordered, inside the interval) up to where the
/// integration stops, with the state from the dense output. Cancellation is polled
/// before every step attempt. Never panics.
#[allow(clippy::too_many_arguments)] // the general path's arguments, each distinct
pub fn solve_dop853_fixed<const N: usize, S: FixedSystem<N>, E: EventSet<N>>(
    sys: &S,
    t0: f64,
    y0: &[f64; N],
    t_end: f64,
    opts: &OdeOptions,
    events: &E,
    times: &[f64],
    record: &mut dyn FnMut(f64, &[f64; N]),
    cancel: Cancel<'_>,
) -> Result<FixedSolution<N>, OdeError> {
    let adapter: AsDyn<'_, S, N> = AsDyn(sys);
    validate(&adapter, t0, y0, t_end, opts, &Output::Final)?;
    let dir = if t_end >= t0 { 1.0 } else { -1.0 };
    check_times(times, t0, t_end)?;
    if cancel.is_cancelled() {
        return Err(OdeError::Cancelled { t: t0 });
    }
    let tol = Tol {
        rtol: opts.rtol,
        atol: opts.atol,
    };
    let h_max = opts.h_max.min((t_end - t0).abs());
    let fixed = opts.fixed_step;
    let mut evals = 0usize;
    let mut stats = OdeStats::default();

    let mut t = t0;
    let mut y = *y0;
    let mut k = [[0.0; N]; 16];
    if !eval(sys, &mut evals, t0, &y, &mut k[0]) {
        return Err(OdeError::NonFinite { t: t0 });
    }
    let mut next_time = 0;
    while let Some(&tr) = times.get(next_time) {
        if tr != t0 {
            break;
        }
        record(tr, &y);
        next_time += 1;
    }
    let m = events.len();
    let mut g_prev = vec![0.0; m];
    let mut g_new = vec![0.0; m];
    events.values(t0, &y, &mut g_prev);
    let done = |evals: usize, mut stats: OdeStats, t: f64, y: [f64; N], term, h_next| {
        stats.rhs_evaluations = evals;
        Ok(FixedSolution {
            t_final: t,
            y_final: y,
            stats,
            termination: term,
            h_next,
        })
    };
    if t0 == t_end {
        return done(evals, stats, t0, y, Termination::ReachedEnd, 0.0);
    }
    let mut h = match (fixed, opts.h0) {
        (Some(hf), _) => hf,
        (None, Some(h0)) => h0.min(h_max),
        (None, None) => {
            let mut counted = Counted::new(&adapter);
            let f0 = k[0];
            let h = initial_step(&mut counted, t0, &y, &f0, dir, h_max, 8.0, tol);
            evals += counted.rhs_evals;
            h
        }
    } * dir;

    let mut control = StepControl::new(ERROR_EXPONENT, Proposal::Quotient);
    let mut attempts = 0usize;
    let mut hits: Vec<(f64, usize)> = Vec::new();
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
        let last = dir * (t + 1.01 * h - t_end) >= 0.0;
        if last {
            h = t_end - t;
        }
        let t_new = if last { t_end } else { t + h };
        if t_new == t || (!last && h.abs() <= 16.0 * f64::EPSILON * t.abs()) {
            return Err(control.too_small(t, h));
        }
        attempts += 1;

        // ---- The trial step (the general path's `Dop853::step`).
        // Stages 1..=11, each with its row known at compile time; the first that is not
        // finite ends the trial (as the general path's loop breaks there).
        let e = &mut evals;
        let mut finite = stage::<N, 1, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 2, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 3, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 4, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 5, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 6, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 7, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 8, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 9, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 10, S>(sys, e, &mut k, &y, h, t, t_new)
            && stage::<N, 11, S>(sys, e, &mut k, &y, h, t, t_new);
        let mut y_new = [0.0; N];
        let mut err = f64::NAN;
        if finite {
            y_new = stage_point(&k, &y, h, 12);
            let mut norm = StretchedNorm::default();
            for i in 0..N {
                let (a, b) = (y[i], y_new[i]);
                if !b.is_finite() {
                    finite = false;
                    break;
                }
                let (mut r5, mut r3) = (0.0, 0.0);
                for j in 0..12 {
                    let kji = k[j][i];
                    r5 += E5[j] * kji;
                    r3 += E3[j] * kji;
                }
                norm.add(r5, r3, weight(tol.atol, tol.rtol, a, b));
            }
            if finite {
                err = norm.value(h, N);
                finite = err.is_finite();
            }
        }
        if finite && (fixed.is_some() || err <= 1.0) {
            let mut f_new = [0.0; N];
            if eval(sys, &mut evals, t_new, &y_new, &mut f_new) {
                k[12] = f_new;
            } else {
                finite = false;
            }
        }
        if !finite {
            stats.rejected += 1;
            h = control.nonfinite(t, h, fixed.is_some())?;
            continue;
        }
        if fixed.is_none() && err > 1.0 {
            stats.rejected += 1;
            h = control.rejected(h, err);
            continue;
        }

        // ---- Accepted.
        stats.steps += 1;
        control.accepted();
        let mut dense: Option<Dense<N>> = None;
        let make_dense = |k: &mut [[f64; N]; 16], evals: &mut usize| -> Option<Dense<N>> {
            // Stages 13..=15 (C[S] < 1, so `t_new` is not taken).
            let ok = stage::<N, 13, S>(sys, evals, k, &y, h, t, t_new)
                && stage::<N, 14, S>(sys, evals, k, &y, h, t, t_new)
                && stage::<N, 15, S>(sys, evals, k, &y, h, t, t_new);
            if !ok {
                return None;
            }
            let mut r = [[0.0; N]; 8];
            for i in 0..N {
                let (a, b, fa, fb) = (y[i], y_new[i], k[0][i], k[12][i]);
                let dy = b - a;
                let bspl = h * fa - dy;
                r[0][i] = a;
                r[1][i] = dy;
                r[2][i] = bspl;
                r[3][i] = dy - h * fb - bspl;
                let mut acc = [0.0; 4];
                for (j, kj) in k.iter().enumerate() {
                    let kji = kj[i];
                    for (row, out) in D.iter().zip(acc.iter_mut()) {
                        *out += row[j] * kji;
                    }
                }
                r[4][i] = h * acc[0];
                r[5][i] = h * acc[1];
                r[6][i] = h * acc[2];
                r[7][i] = h * acc[3];
            }
            Some(Dense { t, h, r })
        };

        // Events: sign changes over the step, located on the dense output.
        let mut stop: Option<(usize, f64, [f64; N])> = None;
        if m > 0 {
            events.values(t_new, &y_new, &mut g_new);
            hits.clear();
            for (index, (&go, &gn)) in g_prev.iter().zip(&g_new).enumerate() {
                let crossed = (go < 0.0 && gn >= 0.0) || (go > 0.0 && gn <= 0.0);
                if !crossed {
                    continue;
                }
                if dense.is_none() {
                    dense = make_dense(&mut k, &mut evals);
                    if dense.is_none() {
                        return Err(OdeError::NonFinite { t });
                    }
                }
                let tr = match &dense {
                    Some(ip) if gn != 0.0 => {
                        brent(|s| events.value(index, s, &ip.eval(s)), t, t_new, go, gn)
                    }
                    _ => t_new,
                };
                hits.push((tr, index));
            }
            hits.sort_by(|a, b| (dir * a.0).total_cmp(&(dir * b.0)).then(a.1.cmp(&b.1)));
            if let Some(&(tr, index)) = hits.first() {
                let yr = match &dense {
                    Some(ip) if tr != t_new => ip.eval(tr),
                    _ => y_new,
                };
                stop = Some((index, tr, yr));
            }
        }
        let (t_stop, y_stop) = match &stop {
            Some((_, te, ye)) => (*te, *ye),
            None => (t_new, y_new),
        };
        // Output times in the step (up to the stop).
        if dense.is_none()
            && times
                .get(next_time)
                .is_some_and(|&tr| dir * (tr - t_new) < 0.0)
        {
            dense = make_dense(&mut k, &mut evals);
            if dense.is_none() {
                return Err(OdeError::NonFinite { t });
            }
        }
        while let Some(&tr) = times.get(next_time) {
            if dir * (tr - t_stop) > 0.0 {
                break;
            }
            match (&dense, tr != t_stop) {
                (Some(ip), true) => record(tr, &ip.eval(tr)),
                _ => record(tr, &y_stop),
            }
            next_time += 1;
        }
        // The controller's next step (also the restart's after an event).
        let h_next = if fixed.is_some() {
            h.abs()
        } else {
            // The magnitude from the shared controller, the direction restored (h/fac
            // of a negative h is −(|h|/fac) exactly).
            dir * control.proposal(h.abs(), h.abs(), err)
        };
        if let Some((index, te, ye)) = stop {
            return done(
                evals,
                stats,
                te,
                ye,
                Termination::Event { index, t: te },
                h_next.abs(),
            );
        }

        // Advance.
        k[0] = k[12];
        y = y_new;
        t = t_new;
        std::mem::swap(&mut g_prev, &mut g_new);
        if last {
            return done(evals, stats, t, y, Termination::ReachedEnd, h_next.abs());
        }
        control.advanced();
        h = if let Some(hf) = fixed {
            dir * hf
        } else {
            h_next
        };
    }
}
