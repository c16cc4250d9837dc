//! The optimiser's engine, free of bearings: a full grid over a box evaluated in parallel
//! (rayon), then a Nelder–Mead polish (argmin on `Vec<f64>`) from the best feasible grid
//! point with the constraints as an exact penalty. The objective is non-smooth (laminae and
//! rollers enter and leave the load zone as the radii change), hence the grid first: it
//! finds the basin and the feasible region without derivatives; the polish only refines
//! inside one grid cell or two.
//!
//! A point's constraints are margins, each ≥ 0 when satisfied and scaled to be relative
//! (−0.01 is 1 % past its limit), so one penalty weight serves all of them.

use std::cell::RefCell;
use std::sync::atomic::{AtomicUsize, Ordering};

use argmin::core::{CostFunction, Executor};
use argmin::solver::neldermead::NelderMead;
use rayon::prelude::*;

use crate::numerics::cancel::Cancel;

/// A margin this far below zero still counts as satisfied: solver noise (the statics'
/// force tolerance is 1e-9 of the load; margins are relative, and the p_max and edge
/// limits are the nominal point's own values, which it must meet).
pub const FEASIBILITY_TOLERANCE: f64 = 1e-6;

/// Penalty weight of the polish: objective scale × this × Σ relative violations. An exact
/// (L1) penalty: any weight above the objective's relative slope at the constraint makes
/// the constrained optimum the penalised one; the objective moves by < 10 % for a 1 %
/// change of a radius, so 100 is far above it.
pub const PENALTY: f64 = 100.0;

/// One evaluated point: objective, named constraint margins, and whatever the caller keeps.
#[derive(Debug, Clone, PartialEq)]
pub struct Eval<D> {
    pub objective: f64,
    /// (constraint name, relative margin): ≥ 0 satisfied.
    pub margins: Vec<(&'static str, f64)>,
    pub detail: D,
}

impl<D> Eval<D> {
    /// All margins ≥ −[`FEASIBILITY_TOLERANCE`] and a finite objective.
    pub fn feasible(&self) -> bool {
        self.objective.is_finite()
            && self
                .margins
                .iter()
                .all(|(_, m)| *m >= -FEASIBILITY_TOLERANCE)
    }

    /// Σ of the relative violations (0 when feasible).
    pub fn violation(&self) -> f64 {
        self.margins.iter().map(|(_, m)| (-m).max(0.0)).sum()
    }

    /// Names of the violated constraints.
    pub fn violated(&self) -> Vec<&'static str> {
        self.margins
            .iter()
            .filter(|(_, m)| *m < -FEASIBILITY_TOLERANCE)
            .map(|(n, _)| *n)
            .collect()
    }
}

/// Why a point has no evaluation.
#[derive(Debug, Clone, PartialEq)]
pub enum PointError {
    /// The run was cancelled: the whole optimisation stops.
    Cancelled,
    /// This point failed (a solve did not converge): it counts as infeasible, with the
    /// message kept for the report.
    Failed(String),
}

/// The evaluator: variables → evaluation, and how many solves it spent (the bound).
pub type Evaluator<'a, D> = dyn Fn(&[f64]) -> Result<Eval<D>, PointError> + Sync + 'a;

/// One grid point.
#[derive(Debug, Clone, PartialEq)]
pub struct GridPoint<D> {
    /// Grid indices per variable.
    pub index: Vec<usize>,
    pub x: Vec<f64>,
    pub eval: Result<Eval<D>, String>,
}

impl<D> GridPoint<D> {
    pub fn feasible(&self) -> bool {
        self.eval.as_ref().is_ok_and(Eval::feasible)
    }
    pub fn objective(&self) -> Option<f64> {
        self.eval.as_ref().ok().map(|e| e.objective)
    }
}

/// The `n` values of a variable on [lo, hi], ends included (`n` ≥ 2; one point at the
/// middle for `n` = 1).
pub fn axis(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n <= 1 {
        return vec![0.5 * (lo + hi)];
    }
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

/// An evaluator that starts from a neighbour's state `W` (its solution) when given one and
/// returns the point's own (None when it solved nothing, e.g. a point that is no bearing).
pub type WarmEvaluator<'a, D, W> =
    dyn Fn(&[f64], Option<&W>) -> Result<(Eval<D>, Option<W>), PointError> + Sync + 'a;

/// [`grid_warm`] with warm starts along the grid's rows: the grid is cut into runs along
/// the last variable (whole rows, or pieces of them when there are fewer rows than twice
/// the worker threads), the runs are evaluated in parallel, and within a run each point
/// starts from its neighbour's state (the first cold). The points and their order are
/// [`grid`]'s; only the evaluator's starts differ.
pub fn grid_warm<D: Send, W: Send>(
    lo: &[f64],
    hi: &[f64],
    n: usize,
    eval: &WarmEvaluator<'_, D, W>,
    cancel: Cancel,
) -> Result<Vec<GridPoint<D>>, PointError> {
    let axes: Vec<Vec<f64>> = lo.iter().zip(hi).map(|(a, b)| axis(*a, *b, n)).collect();
    let dims = axes.len();
    let total = axes.iter().map(Vec::len).product::<usize>();
    let last = axes.last().map_or(1, Vec::len).max(1);
    let rows = total / last;
    let threads = rayon::current_num_threads().max(1);
    let pieces = (2 * threads).div_ceil(rows.max(1)).clamp(1, last);
    let run = last.div_ceil(pieces);
    let runs: Vec<(usize, usize)> = (0..rows)
        .flat_map(|r| {
            (0..last)
                .step_by(run)
                .map(move |a| (r * last + a, (r * last + a + run).min((r + 1) * last)))
        })
        .collect();
    let done = AtomicUsize::new(0);
    let point = |flat: usize, warm: Option<&W>| -> Result<(GridPoint<D>, Option<W>), PointError> {
        if cancel.is_cancelled() {
            return Err(PointError::Cancelled);
        }
        let mut index = vec![0; dims];
        let mut rest = flat;
        for d in (0..dims).rev() {
            index[d] = rest % axes[d].len();
            rest /= axes[d].len();
        }
        let x: Vec<f64> = index.iter().zip(&axes).map(|(i, a)| a[*i]).collect();
        let (e, state) = match eval(&x, warm) {
            Ok((e, w)) => (Ok(e), w),
            Err(PointError::Failed(m)) => (Err(m), None),
            Err(PointError::Cancelled) => return Err(PointError::Cancelled),
        };
        let k = done.fetch_add(1, Ordering::Relaxed) + 1;
        cancel.report(k as f64 / total as f64);
        Ok((GridPoint { index, x, eval: e }, state))
    };
    let runs: Vec<Result<Vec<GridPoint<D>>, PointError>> = runs
        .into_par_iter()
        .map(|(a, b)| {
            let mut warm: Option<W> = None;
            let mut out = Vec::with_capacity(b - a);
            for flat in a..b {
                let (p, state) = point(flat, warm.as_ref())?;
                // A point without a state (failed, or no bearing) leaves the last one.
                if state.is_some() {
                    warm = state;
                }
                out.push(p);
            }
            Ok(out)
        })
        .collect();
    let mut points = Vec::with_capacity(total);
    for r in runs {
        points.extend(r?);
    }
    Ok(points)
}

/// Every point of the grid of `n` values per variable over the box [lo, hi], in row-major
/// order (the last variable fastest), evaluated in parallel; `cancel`'s progress is told
/// the fraction done. Each point is evaluated on its own (see [`grid_warm`] for the
/// warm-started grid).
pub fn grid<D: Send>(
    lo: &[f64],
    hi: &[f64],
    n: usize,
    eval: &Evaluator<'_, D>,
    cancel: Cancel,
) -> Result<Vec<GridPoint<D>>, PointError> {
    let axes: Vec<Vec<f64>> = lo.iter().zip(hi).map(|(a, b)| axis(*a, *b, n)).collect();
    let dims = axes.len();
    let total = axes.iter().map(Vec::len).product::<usize>();
    let done = AtomicUsize::new(0);
    let points: Vec<Result<GridPoint<D>, PointError>> = (0..total)
        .into_par_iter()
        .map(|flat| {
            if cancel.is_cancelled() {
                return Err(PointError::Cancelled);
            }
            let mut index = vec![0; dims];
            let mut rest = flat;
            for d in (0..dims).rev() {
                index[d] = rest % axes[d].len();
                rest /= axes[d].len();
            }
            let x: Vec<f64> = index.iter().zip(&axes).map(|(i, a)| a[*i]).collect();
            let e = match eval(&x) {
                Ok(e) => Ok(e),
                Err(PointError::Failed(m)) => Err(m),
                Err(PointError::Cancelled) => return Err(PointError::Cancelled),
            };
            let k = done.fetch_add(1, Ordering::Relaxed) + 1;
            cancel.report(k as f64 / total as f64);
            Ok(GridPoint { index, x, eval: e })
        })
        .collect();
    points.into_iter().collect()
}

/// The best feasible grid point (lowest objective), if any.
pub fn best_feasible<D>(points: &[GridPoint<D>]) -> Option<usize> {
    points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.feasible())
        .filter_map(|(i, p)| p.objective().map(|f| (i, f)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Constraints that stop the grid's optimum from going further: those violated at a grid
/// neighbour (±1 in one index) whose objective is lower. A neighbour that failed to solve
/// is named `"solve failed"`; a lower neighbour out of the box cannot exist, so the box is
/// named by the caller (see [`at_bounds`]).
pub fn binding_at<D>(points: &[GridPoint<D>], best: usize) -> Vec<&'static str> {
    let Some(b) = points.get(best) else {
        return Vec::new();
    };
    let Some(f0) = b.objective() else {
        return Vec::new();
    };
    let mut out: Vec<&'static str> = Vec::new();
    for p in points {
        let dist: usize = p
            .index
            .iter()
            .zip(&b.index)
            .map(|(a, c)| a.abs_diff(*c))
            .sum();
        if dist != 1 {
            continue;
        }
        match &p.eval {
            Ok(e) if e.objective < f0 && !e.feasible() => {
                for v in e.violated() {
                    if !out.contains(&v) {
                        out.push(v);
                    }
                }
            }
            Err(_) if !out.contains(&"solve failed") => out.push("solve failed"),
            _ => {}
        }
    }
    out
}

/// Which variables sit on a bound of the box (within 1e-3 of its width): `(variable
/// index, upper?)`.
pub fn at_bounds(x: &[f64], lo: &[f64], hi: &[f64]) -> Vec<(usize, bool)> {
    let mut out = Vec::new();
    for (i, ((v, a), b)) in x.iter().zip(lo).zip(hi).enumerate() {
        let tol = 1e-3 * (b - a).abs();
        if (v - b).abs() <= tol {
            out.push((i, true));
        } else if (v - a).abs() <= tol {
            out.push((i, false));
        }
    }
    out
}

/// The polish's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct Polished<D> {
    /// The best feasible point seen (the start if nothing better was).
    pub x: Vec<f64>,
    pub eval: Eval<D>,
    /// Evaluations made by the polish (the start's not counted: it came from the grid).
    pub evaluations: usize,
    /// Why it stopped: "converged", "budget" (the evaluation bound), or argmin's reason.
    pub stopped: String,
}

struct Penalised<'a, 'b, D, W> {
    eval: &'a WarmEvaluator<'b, D, W>,
    lo: &'a [f64],
    hi: &'a [f64],
    scale: f64,
    max_evals: usize,
    log: RefCell<Log<D, W>>,
}

struct Log<D, W> {
    evaluations: usize,
    best: Option<(Vec<f64>, Eval<D>)>,
    cancelled: bool,
    /// The states of the points evaluated so far: each new point starts from the nearest's
    /// (box-relative distance).
    states: Vec<(Vec<f64>, W)>,
}

impl<D, W> Penalised<'_, '_, D, W> {
    /// Index of the evaluated point nearest `x` that left a state.
    fn nearest(&self, log: &Log<D, W>, x: &[f64]) -> Option<usize> {
        let dist = |y: &[f64]| -> f64 {
            x.iter()
                .zip(y)
                .zip(self.lo.iter().zip(self.hi))
                .map(|((a, b), (l, h))| ((a - b) / (h - l).abs().max(f64::MIN_POSITIVE)).powi(2))
                .sum()
        };
        log.states
            .iter()
            .enumerate()
            .min_by(|a, b| dist(&a.1 .0).total_cmp(&dist(&b.1 .0)))
            .map(|(i, _)| i)
    }
}

impl<D: Clone, W> CostFunction for Penalised<'_, '_, D, W> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, p: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        // Outside the box: evaluate at the nearest point inside, penalised by the distance
        // (relative to the box's width), so the simplex is pushed back in.
        let mut out = 0.0;
        let x: Vec<f64> = p
            .iter()
            .zip(self.lo.iter().zip(self.hi))
            .map(|(v, (a, b))| {
                let c = v.clamp(*a, *b);
                out += (v - c).abs() / (b - a).abs().max(f64::MIN_POSITIVE);
                c
            })
            .collect();
        let e = {
            let log = self.log.borrow();
            if log.evaluations >= self.max_evals {
                return Err(argmin::core::Error::msg("budget"));
            }
            let near = self.nearest(&log, &x).map(|i| &log.states[i].1);
            (self.eval)(&x, near)
        };
        let mut log = self.log.borrow_mut();
        log.evaluations += 1;
        match e {
            Ok((e, state)) => {
                if let Some(w) = state {
                    log.states.push((x.clone(), w));
                }
                let cost = e.objective + self.scale * PENALTY * (e.violation() + out);
                let better = log
                    .best
                    .as_ref()
                    .is_none_or(|(_, b)| e.objective < b.objective);
                if e.feasible() && better {
                    log.best = Some((x, e));
                }
                Ok(cost)
            }
            // A point that does not solve is treated as far infeasible.
            Err(PointError::Failed(_)) => Ok(self.scale * (1.0 + PENALTY)),
            Err(PointError::Cancelled) => {
                log.cancelled = true;
                Err(argmin::core::Error::msg("cancelled"))
            }
        }
    }
}

/// Nelder–Mead from `start` (feasible, already evaluated as `start_eval`) with an initial
/// simplex of `step` along each variable (toward the box's inside), at most `max_evals`
/// evaluations; the penalty's scale is |start objective|. Returns the best feasible point
/// seen. Each point is evaluated on its own (see [`polish_warm`]).
pub fn polish<D: Clone>(
    start: &[f64],
    start_eval: Eval<D>,
    step: &[f64],
    lo: &[f64],
    hi: &[f64],
    max_evals: usize,
    eval: &Evaluator<'_, D>,
) -> Result<Polished<D>, PointError> {
    let warm = |x: &[f64], _: Option<&()>| eval(x).map(|e| (e, None));
    polish_warm(start, start_eval, None, step, lo, hi, max_evals, &warm)
}

/// [`polish`] with warm starts: each point the simplex visits starts from the state of the
/// nearest point evaluated so far (`start_state` the start's, if the caller has it).
#[allow(clippy::too_many_arguments)]
pub fn polish_warm<D: Clone, W>(
    start: &[f64],
    start_eval: Eval<D>,
    start_state: Option<W>,
    step: &[f64],
    lo: &[f64],
    hi: &[f64],
    max_evals: usize,
    eval: &WarmEvaluator<'_, D, W>,
) -> Result<Polished<D>, PointError> {
    let scale = start_eval.objective.abs().max(f64::MIN_POSITIVE);
    let mut simplex = vec![start.to_vec()];
    for i in 0..start.len() {
        let mut p = start.to_vec();
        let s = step.get(i).copied().unwrap_or(0.0);
        // Step toward the larger side of the box so the vertex lies inside.
        p[i] += if hi[i] - start[i] >= start[i] - lo[i] {
            s
        } else {
            -s
        };
        simplex.push(p);
    }
    let problem = Penalised {
        eval,
        lo,
        hi,
        scale,
        max_evals,
        log: RefCell::new(Log {
            evaluations: 0,
            best: Some((start.to_vec(), start_eval.clone())),
            cancelled: false,
            states: start_state
                .map(|w| (start.to_vec(), w))
                .into_iter()
                .collect(),
        }),
    };
    // sd tolerance: the simplex's spread of cost 1e-7 of the objective (below the lamina
    // noise the report gives beside it).
    let stopped = match NelderMead::new(simplex).with_sd_tolerance(1e-7 * scale) {
        Ok(solver) => match Executor::new(&problem, solver)
            .configure(|s| s.max_iters(max_evals as u64))
            .run()
        {
            Ok(r) => format!("{}", r.state.termination_status),
            Err(e) => e.to_string(),
        },
        Err(e) => e.to_string(),
    };
    let log = problem.log.into_inner();
    if log.cancelled {
        return Err(PointError::Cancelled);
    }
    let (x, e) = log
        .best
        .unwrap_or_else(|| (start.to_vec(), start_eval.clone()));
    Ok(Polished {
        x,
        eval: e,
        evaluations: log.evaluations,
        stopped,
    })
}

impl<D: Clone, W> CostFunction for &Penalised<'_, '_, D, W> {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, p: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        (**self).cost(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = (x − 0.3)² + (y + 0.2)² on [−1, 1]², with the constraint x + y ≤ −0.1
    /// (margin −0.1 − x − y). The unconstrained minimum (0.3, −0.2) has x + y = 0.1:
    /// infeasible; the constrained one is the projection onto x + y = −0.1:
    /// (0.2, −0.3), f = 0.02. The grid (21 points, step 0.1) holds it exactly; the polish
    /// from a grid point must stay within 1e-3 of it and name the constraint binding.
    fn problem(x: &[f64]) -> Result<Eval<()>, PointError> {
        let f = (x[0] - 0.3).powi(2) + (x[1] + 0.2).powi(2);
        Ok(Eval {
            objective: f,
            margins: vec![("sum", -0.1 - x[0] - x[1])],
            detail: (),
        })
    }

    #[test]
    fn grid_and_polish_find_a_constrained_minimum_and_name_the_constraint() {
        let (lo, hi) = ([-1.0, -1.0], [1.0, 1.0]);
        let pts = grid(&lo, &hi, 21, &problem, Cancel::NONE).unwrap();
        assert_eq!(pts.len(), 441);
        let b = best_feasible(&pts).unwrap();
        let x = &pts[b].x;
        assert!(
            (x[0] - 0.2).abs() < 1e-12 && (x[1] + 0.3).abs() < 1e-12,
            "{x:?}"
        );
        assert_eq!(binding_at(&pts, b), vec!["sum"]);
        // Polish from an off-optimum feasible grid point (0.1, −0.4): Nelder–Mead slides
        // along the active constraint toward (0.2, −0.3).
        let start = [0.1, -0.4];
        let e0 = problem(&start).unwrap();
        let p = polish(&start, e0, &[0.1, 0.1], &lo, &hi, 100, &problem).unwrap();
        assert!(p.evaluations <= 100);
        assert!(p.eval.feasible());
        assert!(
            (p.x[0] - 0.2).abs() < 1e-3 && (p.x[1] + 0.3).abs() < 1e-3,
            "{:?} after {} evaluations ({})",
            p.x,
            p.evaluations,
            p.stopped
        );
        assert!((p.eval.objective - 0.02).abs() < 1e-4);
    }

    /// An interior minimum: no constraint binding, none on a bound; the polish refines a
    /// grid cell to 1e-4 (f = (x − 0.123)² + 2(y − 0.0456)², grid step 0.1).
    #[test]
    fn polish_refines_an_interior_minimum() {
        let f = |x: &[f64]| -> Result<Eval<()>, PointError> {
            Ok(Eval {
                objective: (x[0] - 0.123).powi(2) + 2.0 * (x[1] - 0.0456).powi(2),
                margins: vec![],
                detail: (),
            })
        };
        let (lo, hi) = ([-1.0, -1.0], [1.0, 1.0]);
        let pts = grid(&lo, &hi, 21, &f, Cancel::NONE).unwrap();
        let b = best_feasible(&pts).unwrap();
        assert!(binding_at(&pts, b).is_empty());
        assert!(at_bounds(&pts[b].x, &lo, &hi).is_empty());
        let e0 = pts[b].eval.clone().unwrap();
        let p = polish(&pts[b].x, e0, &[0.1, 0.1], &lo, &hi, 100, &f).unwrap();
        assert!(
            (p.x[0] - 0.123).abs() < 1e-4 && (p.x[1] - 0.0456).abs() < 1e-4,
            "{:?}",
            p.x
        );
    }

    /// Cancellation stops the grid; failures are kept as infeasible points.
    #[test]
    fn cancel_and_failures() {
        let flag = std::sync::atomic::AtomicBool::new(true);
        let r = grid(&[0.0], &[1.0], 5, &problem1, Cancel::new(&flag));
        assert_eq!(r, Err(PointError::Cancelled));
        let fail = |x: &[f64]| -> Result<Eval<()>, PointError> {
            if x[0] > 0.5 {
                Err(PointError::Failed("no".into()))
            } else {
                problem1(x)
            }
        };
        let pts = grid(&[0.0], &[1.0], 5, &fail, Cancel::NONE).unwrap();
        assert_eq!(pts.iter().filter(|p| p.eval.is_err()).count(), 2);
        assert_eq!(best_feasible(&pts), Some(2));
        assert_eq!(binding_at(&pts, 2), vec!["solve failed"]);
    }

    /// The warm grid: the same points in the same order as the plain grid, and each point
    /// after the first of its run starts from its left neighbour's state (the state here
    /// is the point's x, so the neighbour is checked exactly); runs never cross a row.
    #[test]
    fn warm_grid_starts_each_point_from_its_left_neighbour() {
        let (lo, hi) = ([-1.0, -1.0], [1.0, 1.0]);
        let cold = grid(&lo, &hi, 7, &problem, Cancel::NONE).unwrap();
        let warm_uses = AtomicUsize::new(0);
        let step = 2.0 / 6.0;
        let warm = |x: &[f64], from: Option<&Vec<f64>>| {
            if let Some(f) = from {
                assert!(
                    (f[0] - x[0]).abs() < 1e-12 && (x[1] - f[1] - step).abs() < 1e-12,
                    "{x:?} started from {f:?}"
                );
                warm_uses.fetch_add(1, Ordering::Relaxed);
            }
            problem(x).map(|e| (e, Some(x.to_vec())))
        };
        let pts = grid_warm(&lo, &hi, 7, &warm, Cancel::NONE).unwrap();
        assert_eq!(pts, cold);
        // 7 rows of 7, each cut into runs of ⌈7/pieces⌉ (pieces: 2 × threads over 7 rows);
        // every point but a run's first is warm.
        let used = warm_uses.load(Ordering::Relaxed);
        let pieces = (2 * rayon::current_num_threads()).div_ceil(7).clamp(1, 7);
        let runs_per_row = 7usize.div_ceil(7usize.div_ceil(pieces));
        assert_eq!(used, 49 - 7 * runs_per_row, "{used} warm starts");
        assert!(used >= 21, "{used} warm starts");
    }

    fn problem1(x: &[f64]) -> Result<Eval<()>, PointError> {
        Ok(Eval {
            objective: -x[0],
            margins: vec![],
            detail: (),
        })
    }
}
