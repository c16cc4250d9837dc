//! `rollbench sweep`: a generic parameter sweep, usable by every bearing system (issues 16
//! and 17). One deck key is set, in the deck's units, to each value of a range; every point
//! is a whole new case built and validated by the deck itself
//! ([`CaseDeck::with_value`], the same path as `run --set`), solved without the thermal
//! transient, and reduced to the key outputs of its view ([`View::key_outputs`]: SI, the
//! unit in each name, as `bench` shows them). A point that fails to solve is a row with its reason, not an abort.
//!
//! Ranges (`KEY=RANGE`, values in deck units):
//! - `A:B:STEP`: from A towards B in steps of STEP (> 0), both ends included when STEP
//!   divides the range (to 1e-9 of a step); otherwise the last point is the last step
//!   before B. A > B sweeps downwards. Issue 17's `0:20000:21` is read this way (a step of
//!   21 rpm): a bare number is always a step.
//! - `A:B:xN`: N points evenly spaced from A to B, both included (`0:20000:x21` gives
//!   0, 1000, …, 20000).
//!
//! Points are computed as A + i·STEP (not accumulated), snapped to B at the end of an
//! exact range and rounded to the decimals written in A, B and STEP, so `0:1:0.1` gives
//! 0.1, 0.2, 0.3 and not 0.30000000000000004: the deck receives the number a user would
//! have typed with `--set`. At most [`MAX_POINTS`] points.
//!
//! Points are solved in parallel over the cores (rayon); rows stay in sweep order.
//!
//! Warm start (the default): the points are cut into as many contiguous runs as there are
//! cores, and each run is solved in sweep order through one [`Session`] of the system
//! ([`BearingSystem::session`], the same object the workbench re-solves edits with). A
//! system whose session keeps its last converged state (the tapered roller's ring
//! displacements and roller states) starts each point from its neighbour's answer: faster,
//! and a branch followed by continuation (rollers leaving the cone). A session that keeps
//! nothing ([`crate::bearings::WholeSolve`]) gives exactly the cold answers. Sessions
//! promise the cold answer to their solver tolerance, never a different root; `--cold`
//! ([`Start::Cold`]) solves every point as `run --set KEY=VALUE` would, independently.
//!
//! [`CaseDeck::with_value`]: crate::bearings::CaseDeck::with_value
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
#![warn(missing_docs)]

use std::fmt::Write as _;

use rayon::prelude::*;

use crate::bearings::view::{KeyOutput, View};
use crate::bearings::{Case, Detail, RunOptions, Session, SolveError, SweepPlan};
use crate::numerics::cancel::Cancel;

/// Most points a sweep may have.
pub const MAX_POINTS: usize = 10_000;

/// Relative slack (of one step) within which B counts as reached: `0:1:0.1` is 10.000…02
/// steps in floating point and must still end at 1.
const END_SLACK: f64 = 1e-9;

/// How the points of a range are spaced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spacing {
    /// A step in deck units (> 0).
    Step(f64),
    /// A number of points, both ends included.
    Count(usize),
}

/// A parsed `KEY=A:B:STEP` or `KEY=A:B:xN`.
#[derive(Debug, Clone, PartialEq)]
pub struct Range {
    /// The deck key swept (`operating.inner_speed`).
    pub key: String,
    /// First value (deck units).
    pub start: f64,
    /// Last value, or the bound the steps stop at (deck units).
    pub end: f64,
    /// Step or count.
    pub spacing: Spacing,
    /// Decimals written in A, B and STEP (the most of them); `None` when one uses an
    /// exponent or the spacing is a count (no rounding then).
    decimals: Option<usize>,
}

/// Digits after the decimal point of a number as written; `None` with an exponent.
fn written_decimals(s: &str) -> Option<usize> {
    if s.contains(['e', 'E']) {
        return None;
    }
    Some(s.split_once('.').map_or(0, |(_, frac)| frac.len()))
}

impl Range {
    /// Parses `KEY=A:B:STEP` or `KEY=A:B:xN`. Errors name the key and what is wrong.
    pub fn parse(arg: &str) -> Result<Range, String> {
        let Some((key, spec)) = arg.split_once('=') else {
            return Err(format!(
                "--set-range {arg}: expected KEY=A:B:STEP or KEY=A:B:xN (e.g. operating.inner_speed=6000:15000:500)"
            ));
        };
        let key = key.trim();
        if key.is_empty() {
            return Err(format!("--set-range {arg}: the key is empty"));
        }
        let parts: Vec<&str> = spec.split(':').map(str::trim).collect();
        let [a, b, s] = parts.as_slice() else {
            return Err(format!(
                "--set-range {key}={spec}: expected A:B:STEP or A:B:xN (three fields separated by ':', got {})",
                parts.len()
            ));
        };
        let number = |what: &str, t: &str| -> Result<f64, String> {
            match t.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(format!(
                    "--set-range {key}={spec}: {what} `{t}` is not a finite number"
                )),
            }
        };
        let start = number("A", a)?;
        let end = number("B", b)?;
        let (spacing, decimals) = if let Some(n) = s.strip_prefix(['x', 'X']) {
            let n: usize = n.parse().map_err(|_| {
                format!("--set-range {key}={spec}: the count `{s}` must be x followed by a whole number of points (e.g. x21)")
            })?;
            (Spacing::Count(n), None)
        } else {
            let step = number("STEP", s)?;
            if step <= 0.0 {
                return Err(format!(
                    "--set-range {key}={spec}: STEP must be > 0 (got {s}; A > B sweeps downwards with a positive STEP)"
                ));
            }
            let d = [a, b, s]
                .iter()
                .map(|t| written_decimals(t))
                .try_fold(0usize, |m, d| d.map(|d| m.max(d)));
            (Spacing::Step(step), d)
        };
        Ok(Range {
            key: key.to_string(),
            start,
            end,
            spacing,
            decimals,
        })
    }

    /// The values of the range, in sweep order (deck units). Errors name the key.
    pub fn values(&self) -> Result<Vec<f64>, String> {
        let (a, b, key) = (self.start, self.end, &self.key);
        let span = b - a;
        let values: Vec<f64> = match self.spacing {
            Spacing::Count(n) => {
                if n == 0 {
                    return Err(format!("--set-range {key}: x0 gives no points"));
                }
                if n > MAX_POINTS {
                    return Err(format!(
                        "--set-range {key}: {n} points; at most {MAX_POINTS}"
                    ));
                }
                if n == 1 {
                    if a != b {
                        return Err(format!(
                            "--set-range {key}: x1 gives one point, so A and B must be equal (got {} and {})",
                            value_text(a),
                            value_text(b)
                        ));
                    }
                    vec![a]
                } else {
                    let last = (n - 1) as f64;
                    // To 12 significant digits: A + (B − A)·i/(N − 1) carries floating-point
                    // noise (14000.000000000002) that the deck would receive as written.
                    let clean = |v: f64| -> f64 { format!("{v:.11e}").parse().unwrap_or(v) };
                    (0..n)
                        .map(|i| {
                            if i == n - 1 {
                                b
                            } else if span.is_finite() {
                                clean(a + span * (i as f64 / last))
                            } else {
                                // B − A overflows (−1.797e308:1.797e308): interpolate
                                // without it, else every inner point is NaN.
                                let t = i as f64 / last;
                                clean(a * (1.0 - t) + b * t)
                            }
                        })
                        .collect()
                }
            }
            Spacing::Step(step) => {
                let q = span.abs() / step;
                if !q.is_finite() || q >= MAX_POINTS as f64 {
                    return Err(format!(
                        "--set-range {key}: {} to {} in steps of {} is more than {MAX_POINTS} points",
                        value_text(a),
                        value_text(b),
                        value_text(step)
                    ));
                }
                let exact = (q - q.round()).abs() <= END_SLACK * q.max(1.0);
                let steps = if exact { q.round() } else { q.floor() };
                // `steps` < MAX_POINTS, a small whole number: the cast is exact.
                let steps = steps as usize;
                let dir = if span < 0.0 { -1.0 } else { 1.0 };
                (0..=steps)
                    .map(|i| {
                        if exact && i == steps {
                            b
                        } else {
                            a + dir * step * i as f64
                        }
                    })
                    .map(|v| self.round(v))
                    .collect()
            }
        };
        if values.len() > MAX_POINTS {
            return Err(format!(
                "--set-range {key}: {} points; at most {MAX_POINTS}",
                values.len()
            ));
        }
        Ok(values)
    }

    /// `v` rounded to the decimals written in the range (floating-point noise of A + i·STEP
    /// removed); unchanged when they are unknown.
    fn round(&self, v: f64) -> f64 {
        match self.decimals {
            Some(d) if d <= 15 => format!("{v:.d$}").parse().unwrap_or(v),
            _ => v,
        }
    }
}

/// The text a point's value is written into the deck with (shortest round-trip decimal;
/// `-0` written as `0`; in exponent form from 1e16 and below 1e-100, so that 1.797e308 is
/// not written with 309 digits, which the deck would read as an integer too large).
pub fn value_text(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else if v.is_finite() && (v.abs() >= 1e16 || v.abs() < 1e-100) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// How each point of a sweep starts its solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// From the previous point of its run, through one session of the system.
    Warm,
    /// From the system's own initial guess, as `run --set` does.
    Cold,
}

impl Start {
    /// The name the JSON writes (`"warm"`, `"cold"`).
    pub fn name(self) -> &'static str {
        match self {
            Start::Warm => "warm",
            Start::Cold => "cold",
        }
    }
}

/// One point of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// The swept key's value (deck units).
    pub value: f64,
    /// The value as written into the deck.
    pub text: String,
    /// The view's key outputs (empty when the solve failed).
    pub outputs: Vec<KeyOutput>,
    /// Why the solve failed, if it did.
    pub failure: Option<String>,
}

/// A finished sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// The key swept.
    pub key: String,
    /// Its unit in the deck (empty when the key has no scalar field, e.g. `thermal.*`, or
    /// is dimensionless).
    pub unit: String,
    /// The bearing system (`type`).
    pub system: &'static str,
    /// The deck's name.
    pub deck: String,
    /// The points, in sweep order.
    pub points: Vec<Point>,
    /// How the points were started.
    pub start: Start,
    /// The key outputs of the unmodified deck, solved once only when every point failed,
    /// so that the columns do not depend on which points solved (issue 30 item 6); empty
    /// otherwise, or when the deck itself fails too.
    pub base_columns: Vec<&'static str>,
}

impl Sweep {
    /// The key-output columns: every name any point has, in the order the first solved
    /// point lists them (all points of one system list the same names); when no point
    /// solved, the unmodified deck's ([`Sweep::base_columns`]).
    pub fn columns(&self) -> Vec<&'static str> {
        let mut names: Vec<&'static str> = self.base_columns.clone();
        for p in &self.points {
            for o in &p.outputs {
                if !names.contains(&o.name) {
                    names.push(o.name);
                }
            }
        }
        names
    }

    /// Number of points whose solve failed.
    pub fn failures(&self) -> usize {
        self.points.iter().filter(|p| p.failure.is_some()).count()
    }

    /// The swept column's header: the key with its deck unit in brackets.
    fn value_header(&self) -> String {
        if self.unit.is_empty() {
            self.key.clone()
        } else {
            format!("{} [{}]", self.key, self.unit)
        }
    }
}

impl Point {
    /// The value of key output `name` (SI; `None` when absent or failed).
    pub fn output(&self, name: &str) -> Option<f64> {
        self.outputs
            .iter()
            .find(|o| o.name == name)
            .and_then(|o| o.value)
    }
}

/// The allowed range of `key` in the case's deck units (`None` for keys that are not
/// scalar fields), for error messages.
fn allowed(case: &dyn Case, key: &str) -> Option<String> {
    case.fields()
        .into_iter()
        .find(|f| f.key == key)
        .map(|f| f.allowed(case.units()))
}

/// `message` with the key's allowed range appended, when the key is a field.
fn with_allowed(case: &dyn Case, key: &str, message: String) -> String {
    match allowed(case, key) {
        Some(a) => format!("{message} ({key}: allowed {a})"),
        None => message,
    }
}

/// One point's case, built and validated, not yet solved.
pub struct PointCase {
    /// The swept key's value (deck units).
    pub value: f64,
    /// The value as written into the deck.
    pub text: String,
    /// The deck with the key set to `text`.
    pub case: Box<dyn Case>,
}

/// The range parsed and its points built against `case`: each point a new case with the
/// key set (deck units) and the whole deck validated, as `run --set` does. The first
/// invalid point stops the sweep before anything is solved; the error names the key, the
/// point and (from the deck's own validation) the allowed range.
pub fn build(case: &dyn Case, range_arg: &str) -> Result<(Range, Vec<PointCase>), String> {
    let range = Range::parse(range_arg).map_err(|e| {
        let key = range_arg.split_once('=').map_or("", |(k, _)| k.trim());
        with_allowed(case, key, e)
    })?;
    let values = range
        .values()
        .map_err(|e| with_allowed(case, &range.key, e))?;
    let n = values.len();
    // A key the deck does not know is wrong for every point: say so once, without a point.
    if case.get(&range.key).is_none() {
        if let Some(&v) = values.first() {
            if let Err(e) = case.with_value(&range.key, &value_text(v)) {
                return Err(format!("--set-range {range_arg}: {e}"));
            }
        }
    }
    let built: Vec<Result<PointCase, String>> = values
        .par_iter()
        .enumerate()
        .map(|(i, &v)| {
            let text = value_text(v);
            case.with_value(&range.key, &text)
                .map(|case| PointCase {
                    value: v,
                    text: text.clone(),
                    case,
                })
                .map_err(|e| {
                    format!(
                        "--set-range {}: point {} of {n} ({} = {text}): {e}",
                        range.key,
                        i + 1,
                        range.key
                    )
                })
        })
        .collect();
    let cases = built.into_iter().collect::<Result<Vec<_>, String>>()?;
    Ok((range, cases))
}

/// Solves one point: a full solve without the transient, reduced to its key outputs;
/// through `session` (warm) when given, else [`Case::solve`] (cold). A panic inside a
/// solver (a bug, but one a sweep into extreme corners is the likeliest to find) becomes
/// the point's failure instead of ending the sweep; the session is then dropped, since its
/// state may be half-updated, and the rest of the run starts cold.
fn solve_point(
    value: f64,
    text: String,
    case: &dyn Case,
    session: &mut Option<Box<dyn Session>>,
) -> Point {
    let options = RunOptions {
        skip_transient: true,
    };
    let detail = Detail::default();
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| match session {
        Some(s) => s
            .solve(case, detail, &Cancel::NONE)
            .map(|s| s.view())
            .map_err(|e| match e {
                // `WholeSolve` wraps `Case::solve`'s message in the system's name: give the
                // row the message `run` prints.
                SolveError::Stage { stage, message } if stage == case.system().id() => message,
                e => e.to_string(),
            }),
        None => case.solve(options, Cancel::NONE).map(|s| s.view()),
    }));
    let (outputs, failure) = match run {
        Ok(Ok(View { key_outputs, .. })) => (key_outputs, None),
        Ok(Err(e)) => (Vec::new(), Some(e)),
        Err(p) => {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_string());
            if session.is_some() {
                *session = Some(case.system().session());
            }
            (Vec::new(), Some(format!("solver panicked: {msg}")))
        }
    };
    Point {
        value,
        text,
        outputs,
        failure,
    }
}

/// Runs the sweep `range_arg` (`KEY=A:B:STEP` or `KEY=A:B:xN`) over `case`, in parallel
/// (contiguous runs of points, one per core, each in sweep order when `start` is
/// [`Start::Warm`]); a progress bar on standard error when `progress`. Errors (bad range,
/// unknown key, a value out of the key's range) come before any solve.
pub fn run(
    case: &dyn Case,
    range_arg: &str,
    progress: bool,
    start: Start,
) -> Result<Sweep, String> {
    let (range, cases) = build(case, range_arg)?;
    let unit = case
        .fields()
        .into_iter()
        .find(|f| f.key == range.key)
        .map_or(String::new(), |f| f.unit(case.units()).to_string());
    let bar = if progress {
        let bar = indicatif::ProgressBar::new(cases.len() as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "sweep {msg} {wide_bar} {pos}/{len} points, {elapsed} (eta {eta})",
        ) {
            bar.set_style(style);
        }
        bar.set_message(range.key.clone());
        Some(bar)
    } else {
        None
    };
    let solve = |pc: PointCase, session: &mut Option<Box<dyn Session>>| {
        let p = solve_point(pc.value, pc.text, pc.case.as_ref(), session);
        if let Some(b) = &bar {
            b.inc(1);
        }
        p
    };
    let points: Vec<Point> = match start {
        Start::Cold => cases
            .into_par_iter()
            .map(|pc| solve(pc, &mut None))
            .collect(),
        Start::Warm => {
            // One contiguous run per core: each run continues from its own previous point.
            let runs = rayon::current_num_threads().max(1);
            let per_run = cases.len().div_ceil(runs).max(1);
            let mut chunks: Vec<Vec<PointCase>> = Vec::new();
            let mut it = cases.into_iter().peekable();
            while it.peek().is_some() {
                chunks.push(it.by_ref().take(per_run).collect());
            }
            let solved: Vec<Vec<Point>> = chunks
                .into_par_iter()
                .map(|chunk| {
                    let mut session = Some(case.system().session());
                    chunk
                        .into_iter()
                        .map(|pc| solve(pc, &mut session))
                        .collect()
                })
                .collect();
            solved.into_iter().flatten().collect()
        }
    };
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    // Every point failed: the columns come from the deck as given (one more solve, the
    // cost of one point), so a script reading the CSV or JSON sees the same columns as
    // on any other day, empty or null in every row.
    let base_columns = if points.iter().all(|p| p.outputs.is_empty()) {
        solve_point(f64::NAN, String::new(), case, &mut None)
            .outputs
            .iter()
            .map(|o| o.name)
            .collect()
    } else {
        Vec::new()
    };
    Ok(Sweep {
        key: range.key,
        unit,
        system: case.system().id(),
        deck: case.name().to_string(),
        points,
        start,
        base_columns,
    })
}

/// One solved point of a pane's sweep ([`run_plan`]).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanPoint {
    /// The swept key's value (deck units).
    pub value: f64,
    /// The same value in SI (the field's value in effect), for display in any units.
    pub x_si: f64,
    /// The view's key outputs (empty when the solve failed).
    pub outputs: Vec<KeyOutput>,
    /// Why the solve failed, if it did.
    pub failure: Option<String>,
}

impl PlanPoint {
    /// The value of key output `name` (SI; `None` when absent or failed).
    pub fn output(&self, name: &str) -> Option<f64> {
        self.outputs
            .iter()
            .find(|o| o.name == name)
            .and_then(|o| o.value)
    }
}

/// A workbench pane's sweep ([`SweepPlan`]) as far as it has been solved.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanProgress {
    /// What is swept.
    pub plan: SweepPlan,
    /// The swept key's quantity (`None` when it is not a scalar field).
    pub x_quantity: Option<crate::units::Quantity>,
    /// The swept key's label in the deck's inputs.
    pub x_label: &'static str,
    /// The swept key's unit in SI and US decks (empty when dimensionless).
    pub x_unit: [&'static str; 2],
    /// The units the plan's values are written in (the deck's).
    pub deck_units: crate::units::Units,
    /// The deck's own value of the swept key, in deck units and SI (the Sweep chart's
    /// operating marker); `None` when the key holds no number.
    pub deck_value: Option<(f64, f64)>,
    /// The points solved so far, in sweep order.
    pub points: Vec<PlanPoint>,
    /// Every point has been solved (or failed).
    pub done: bool,
}

/// Solves `plan` over `case` point by point in sweep order through `solve` (the
/// workbench's session: warm-started), reporting after each point through `on_point`;
/// stops early (returning `None`) when `cancelled` says so, as a newer edit makes the
/// sweep stale. A point whose value the deck refuses is a failed point, not an abort.
pub fn run_plan(
    case: &dyn Case,
    plan: SweepPlan,
    solve: &mut dyn FnMut(&dyn Case) -> Result<View, SolveError>,
    cancelled: &dyn Fn() -> bool,
    on_point: &mut dyn FnMut(&PlanProgress),
) -> Option<PlanProgress> {
    let meta = case.fields().into_iter().find(|f| f.key == plan.key);
    let mut progress = PlanProgress {
        x_quantity: meta.map(|m| m.quantity),
        x_label: meta.map_or(plan.key, |m| m.label),
        x_unit: meta.map_or(["", ""], |m| [m.unit_si, m.unit_us]),
        deck_units: case.units(),
        deck_value: case
            .get(plan.key)
            .and_then(|t| t.trim().parse::<f64>().ok())
            .map(|v| (v, case.field_si(plan.key).unwrap_or(v))),
        points: Vec::with_capacity(plan.values.len()),
        done: plan.values.is_empty(),
        plan,
    };
    let values = progress.plan.values.clone();
    for (i, v) in values.iter().copied().enumerate() {
        if cancelled() {
            return None;
        }
        let text = value_text(v);
        let point = match case.with_value(progress.plan.key, &text) {
            Err(e) => PlanPoint {
                value: v,
                x_si: v,
                outputs: Vec::new(),
                failure: Some(e.to_string()),
            },
            Ok(c) => {
                let x_si = c.field_si(progress.plan.key).unwrap_or(v);
                match solve(c.as_ref()) {
                    Ok(view) => PlanPoint {
                        value: v,
                        x_si,
                        outputs: view.key_outputs,
                        failure: None,
                    },
                    Err(SolveError::Cancelled) => return None,
                    Err(e) => PlanPoint {
                        value: v,
                        x_si,
                        outputs: Vec::new(),
                        failure: Some(e.to_string()),
                    },
                }
            }
        };
        progress.points.push(point);
        progress.done = i + 1 == values.len();
        on_point(&progress);
    }
    Some(progress)
}

/// A key output's value for text: six significant digits, fixed where that is readable,
/// scientific otherwise.
fn text_number(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".to_string()
    } else if (1e-3..1e7).contains(&a) {
        // a ∈ [1e-3, 1e7): log10 ∈ [-3, 7), so the decimals are 0…8.
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.5e}")
    }
}

/// The sweep as an aligned text table: the swept value (deck units) then each key output
/// (SI, the unit in its name), a failure column when any point failed.
pub fn to_text(s: &Sweep) -> String {
    let cols = s.columns();
    let any_failure = s.failures() > 0;
    let mut header: Vec<String> = vec![s.value_header()];
    header.extend(cols.iter().map(|c| c.to_string()));
    let mut rows: Vec<Vec<String>> = s
        .points
        .iter()
        .map(|p| {
            let mut r = vec![p.text.clone()];
            r.extend(cols.iter().map(|c| {
                let count = p
                    .outputs
                    .iter()
                    .any(|o| o.name == *c && o.quantity == crate::units::Quantity::Count);
                match p.output(c) {
                    // Counts (rollers off the cone) as whole numbers.
                    Some(v) if count && v.fract() == 0.0 => format!("{v:.0}"),
                    Some(v) => text_number(v),
                    None => "-".to_string(),
                }
            }));
            r
        })
        .collect();
    let widths: Vec<usize> = (0..header.len())
        .map(|i| {
            rows.iter()
                .map(|r| r[i].chars().count())
                .chain(std::iter::once(header[i].chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "sweep of {} over {} points: {} ({}), no transient, {} start{}",
        s.key,
        s.points.len(),
        s.deck,
        s.system,
        s.start.name(),
        if any_failure {
            format!(", {} failed", s.failures())
        } else {
            String::new()
        }
    );
    let line = |cells: &[String], out: &mut String, failure: Option<&str>| {
        let body: Vec<String> = cells
            .iter()
            .zip(&widths)
            .map(|(c, &w)| format!("{c:>w$}"))
            .collect();
        let mut l = body.join("  ");
        if let Some(f) = failure {
            l.push_str("  ");
            l.push_str(f);
        }
        let _ = writeln!(out, "{}", l.trim_end());
    };
    line(&header, &mut out, any_failure.then_some("failure"));
    for (p, r) in s.points.iter().zip(rows.iter_mut()) {
        line(
            r,
            &mut out,
            p.failure.as_deref().map(|f| f.lines().next().unwrap_or(f)),
        );
    }
    out
}

/// JSON number or null.
fn opt(v: Option<f64>) -> serde_json::Value {
    v.and_then(|x| serde_json::Number::from_f64(x).map(serde_json::Value::Number))
        .unwrap_or(serde_json::Value::Null)
}

/// The sweep as JSON: `{"key", "unit", "type", "deck", "start", "points": [{"value", <key output
/// name>…, "failure"}]}`; every point has every column (null where absent or failed).
pub fn to_json(s: &Sweep) -> serde_json::Value {
    use serde_json::{Map, Value};
    let cols = s.columns();
    let points: Vec<Value> = s
        .points
        .iter()
        .map(|p| {
            let mut m = Map::new();
            m.insert("value".into(), opt(Some(p.value)));
            for c in &cols {
                m.insert((*c).into(), opt(p.output(c)));
            }
            m.insert(
                "failure".into(),
                p.failure.clone().map_or(Value::Null, Value::String),
            );
            Value::Object(m)
        })
        .collect();
    let mut m = Map::new();
    m.insert("key".into(), Value::String(s.key.clone()));
    m.insert("unit".into(), Value::String(s.unit.clone()));
    m.insert("type".into(), Value::String(s.system.to_string()));
    m.insert("deck".into(), Value::String(s.deck.clone()));
    m.insert("start".into(), Value::String(s.start.name().to_string()));
    m.insert("points".into(), Value::Array(points));
    Value::Object(m)
}

/// A CSV cell, quoted (RFC 4180) when it holds a comma, quote or line break.
fn csv_cell(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The sweep as CSV: a header row (the key with its deck unit, the key outputs' names,
/// `failure`) then one row per point; empty cells where a value is absent.
pub fn to_csv(s: &Sweep) -> String {
    let cols = s.columns();
    let mut header = vec![csv_cell(&s.value_header())];
    header.extend(cols.iter().map(|c| csv_cell(c)));
    header.push("failure".to_string());
    let mut out = header.join(",");
    out.push('\n');
    for p in &s.points {
        let mut r = vec![csv_cell(&p.text)];
        r.extend(
            cols.iter()
                .map(|c| p.output(c).map_or_else(String::new, |v| format!("{v}"))),
        );
        r.push(p.failure.as_deref().map_or_else(String::new, csv_cell));
        out.push_str(&r.join(","));
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(arg: &str) -> Vec<f64> {
        Range::parse(arg).unwrap().values().unwrap()
    }

    fn err(arg: &str) -> String {
        match Range::parse(arg).and_then(|r| r.values()) {
            Ok(v) => panic!("{arg} parsed to {} points", v.len()),
            Err(e) => e,
        }
    }

    #[test]
    fn step_range_includes_both_ends() {
        let v = values("operating.inner_speed=6000:15000:500");
        assert_eq!(v.len(), 19);
        assert_eq!(v[0], 6000.0);
        assert_eq!(v[18], 15000.0);
        // Exact: 6000 + 500·i is representable, so equality is the right test.
        assert!(v.windows(2).all(|w| w[1] - w[0] == 500.0));
    }

    #[test]
    fn float_steps_do_not_accumulate() {
        // 0:1:0.1 is 10.000…02 steps in floating point: still 11 points, ends included
        // to 1e-9, and each point the decimal a user would type (0.3, not 0.30000000000000004).
        let v = values("k=0:1:0.1");
        assert_eq!(v.len(), 11);
        assert!((v[0] - 0.0).abs() < 1e-9);
        assert!((v[10] - 1.0).abs() < 1e-9);
        for (i, x) in v.iter().enumerate() {
            assert!((x - i as f64 / 10.0).abs() < 1e-12, "point {i}: {x}");
        }
        assert_eq!(value_text(v[3]), "0.3");
        // A step that puts B a hair past 30 steps (0.7/0.1·3 style noise) still ends at B.
        let v = values("k=0.1:3.1:0.1");
        assert_eq!(v.len(), 31);
        assert_eq!(v[30], 3.1);
    }

    #[test]
    fn exponent_written_values_are_not_rounded() {
        let v = values("k=1e-6:5e-6:1e-6");
        assert_eq!(v.len(), 5);
        assert!((v[4] - 5e-6).abs() < 1e-9 * 1e-6);
    }

    #[test]
    fn step_that_does_not_divide_stops_before_b() {
        // Issue 17's literal `0:20000:21` is a step of 21 rpm: 953 points, last 19 992.
        let v = values("operating.inner_speed=0:20000:21");
        assert_eq!(v.len(), 953);
        assert_eq!(*v.last().unwrap(), 19992.0);
        let v = values("k=0:1:0.3");
        assert_eq!(v, vec![0.0, 0.3, 0.6, 0.9]);
    }

    #[test]
    fn count_range_spaces_n_points() {
        let v = values("operating.inner_speed=0:20000:x21");
        assert_eq!(v.len(), 21);
        assert_eq!(v[0], 0.0);
        assert_eq!(v[20], 20000.0);
        assert!((v[7] - 7000.0).abs() < 1e-9);
        assert_eq!(values("k=5:5:x1"), vec![5.0]);
    }

    #[test]
    fn descending_and_single_point() {
        assert_eq!(values("k=3:1:1"), vec![3.0, 2.0, 1.0]);
        assert_eq!(values("k=2:2:1"), vec![2.0]);
        assert_eq!(values("k=-1:1:x3"), vec![-1.0, 0.0, 1.0]);
    }

    #[test]
    fn bad_ranges_name_the_key() {
        for (arg, what) in [
            ("operating.inner_speed=a:2:1", "`a` is not a finite number"),
            ("operating.inner_speed=0:2:0", "STEP must be > 0"),
            ("operating.inner_speed=0:2:-1", "STEP must be > 0"),
            ("operating.inner_speed=0:2", "three fields"),
            ("operating.inner_speed=0:inf:1", "not a finite number"),
            ("operating.inner_speed=0:20000:1", "more than 10000 points"),
            ("operating.inner_speed=0:1:x10001", "at most 10000"),
            ("operating.inner_speed=0:1:x0", "no points"),
            ("operating.inner_speed=0:1:x1", "must be equal"),
            ("operating.inner_speed=0:1:x2.5", "whole number"),
        ] {
            let e = err(arg);
            assert!(e.contains("operating.inner_speed"), "{arg}: {e}");
            assert!(e.contains(what), "{arg}: {e}");
        }
        assert!(err("0:1:1").contains("KEY=A:B:STEP"));
        // Exactly MAX_POINTS is allowed.
        assert_eq!(values("k=1:10000:1").len(), MAX_POINTS);
    }

    #[test]
    fn count_ranges_carry_no_floating_point_noise() {
        // 0:50000:x26 steps by 2000; 6000:15000:x19 by 500: every point is the number a
        // user would type (exact), not 14000.000000000002.
        for (arg, step) in [("k=0:50000:x26", 2000.0), ("k=6000:15000:x19", 500.0)] {
            let v = values(arg);
            for (i, x) in v.iter().enumerate() {
                assert_eq!(*x, v[0] + step * i as f64, "{arg}: {x}");
            }
        }
        // Spacing that is not a short decimal keeps 12 significant digits.
        let v = values("k=0:1:x4");
        assert!((v[1] - 1.0 / 3.0).abs() < 1e-12);
    }

    #[test]
    fn csv_cells_are_quoted() {
        assert_eq!(csv_cell("a,b"), "\"a,b\"");
        assert_eq!(csv_cell("say \"x\""), "\"say \"\"x\"\"\"");
        assert_eq!(csv_cell("plain"), "plain");
    }

    #[test]
    fn text_numbers_keep_six_digits() {
        assert_eq!(text_number(1234.5678), "1234.57");
        assert_eq!(text_number(0.0123456), "0.0123456");
        assert_eq!(text_number(2.5e9), "2.50000e9");
        assert_eq!(text_number(0.0), "0");
    }

    fn synthetic() -> Sweep {
        use crate::bearings::view::KeyRole;
        use crate::units::Quantity;
        let out = |v: Option<f64>| KeyOutput {
            name: "heat_w",
            label: "heat",
            value: v,
            quantity: Quantity::Power,
            role: KeyRole::Guard,
        };
        Sweep {
            key: "operating.inner_speed".into(),
            unit: "rpm".into(),
            system: "test",
            deck: "deck".into(),
            start: Start::Warm,
            base_columns: Vec::new(),
            points: vec![
                Point {
                    value: 1000.0,
                    text: "1000".into(),
                    outputs: vec![out(Some(12.5))],
                    failure: None,
                },
                Point {
                    value: 2000.0,
                    text: "2000".into(),
                    outputs: vec![out(None)],
                    failure: None,
                },
                Point {
                    value: 3000.0,
                    text: "3000".into(),
                    outputs: Vec::new(),
                    failure: Some("no equilibrium, 3 iterations".into()),
                },
            ],
        }
    }

    #[test]
    fn writers_keep_order_and_mark_absent_values() {
        let s = synthetic();
        let csv = to_csv(&s);
        assert_eq!(
            csv,
            "operating.inner_speed [rpm],heat_w,failure\n1000,12.5,\n2000,,\n3000,,\"no equilibrium, 3 iterations\"\n"
        );
        let j = to_json(&s);
        assert_eq!(j["key"], "operating.inner_speed");
        assert_eq!(j["points"][0]["value"], 1000.0);
        assert_eq!(j["points"][0]["heat_w"], 12.5);
        assert!(j["points"][1]["heat_w"].is_null());
        assert!(j["points"][1]["failure"].is_null());
        assert!(j["points"][2]["heat_w"].is_null());
        assert_eq!(j["points"][2]["failure"], "no equilibrium, 3 iterations");
        let text = to_text(&s);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 5, "{text}");
        assert!(lines[0].contains("1 failed"), "{text}");
        assert!(
            lines[1] == "operating.inner_speed [rpm]   heat_w  failure",
            "{text}"
        );
        // Right-aligned columns, two spaces apart; the failure, left-aligned, last.
        assert_eq!(lines[2], format!("{:>27}  {:>7}", "1000", "12.5000"));
        assert_eq!(lines[3], format!("{:>27}  {:>7}", "2000", "-"));
        assert_eq!(
            lines[4],
            format!("{:>27}  {:>7}  no equilibrium, 3 iterations", "3000", "-")
        );
    }
}
