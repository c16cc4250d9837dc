//! The double-row workbench's long jobs ([`crate::bearings::view::PaneKind::Job`]), as
//! front-end-free [`JobView`]s reported while they run:
//!
//! * job 0, **Torque vs load** (seed 002 Fig. 2): M_fi and M_fo against F/C for radial,
//!   axial and combined load, each point [`load_sweep::torque_point`] (the `losses`
//!   command's), F/C = 0.02:0.2:0.02 ([`TORQUE_F_OVER_C`]), one point reported at a time;
//!   a point that fails is a line naming its direction and F/C, never skipped silently;
//! * job 1, **Optimise** (seed §4–6, Fig. 3): [`optimise::optimise`] with the system's loss
//!   objective on the deck's `[optimise]`, its grid drawn as a heat map of the weighted
//!   total loss as the grid's points are solved, then the infeasible cells (named by the
//!   first constraint they violate), the nominal and optimum points, the improvement and
//!   what binds; beside it the seed's Fig. 3 along the first variable (the others
//!   nominal): M_fi, M_fo in N·m and C in kN on its own chart (one unit per axis).
//!
//! The optimiser reports only a fraction while it runs; the heat map fills in from the
//! objective, which sees every solved bearing: its relative radii are read back from the
//! solved input (R′/R to 1e-9 of a grid value, at the deck's laminae: the polish's and the
//! lamina-noise solves off the grid are not cells), its load case from its loads. Which
//! cells are infeasible is the optimiser's own verdict, drawn when it finishes (the
//! margins are its code, not repeated here).

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::Duration;

use super::input::DoubleRowInput;
use super::load_sweep::{self, Direction, TorquePoint};
use super::optimise::{self, engine, CaseLoss, Optimisation, Variable};
use super::statics::DoubleRowAnalysis;
use crate::bearings::view::{
    Chart, ChartAxis, Display, HeatCell, HeatMap, HeatMark, JobView, Series, Warning,
};
use crate::bearings::SolveError;
use crate::numerics::cancel::Cancel;
use crate::units::{restate_si, Units};

/// The Torque-vs-load pane's F/C values: the seed's Fig. 2 range, the `losses` command's
/// form (`--f-over-c`), 10 points per direction.
pub const TORQUE_F_OVER_C: &str = "0.02:0.2:0.02";

/// The smallest of 1, 2, 2.5, 5 × 10^k at or above `x` (> 0): a round top for an axis.
fn round_up(x: f64) -> f64 {
    if !(x > 0.0 && x.is_finite()) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * p)
        .find(|v| *v >= x * (1.0 - 1e-12))
        .unwrap_or(10.0 * p)
}

/// The Torque-vs-load charts of the points solved so far (`points[d]`: direction `d` of
/// [`Direction::ALL`]): M_fi and M_fo each against F/C on its own chart, one series per
/// direction, both on the same y axis (0 to a round top of all the torques drawn), so
/// the two compare at a glance and each chart's legend has room.
pub fn torque_charts(points: &[Vec<TorquePoint>], f_max: f64) -> Vec<Chart> {
    let top = round_up(
        points
            .iter()
            .flatten()
            .flat_map(|p| [p.friction_torque_inner_nm, p.friction_torque_outer_nm])
            .fold(0.0, f64::max),
    );
    let chart = |title: &str, m: fn(&TorquePoint) -> f64| Chart {
        title: title.to_string(),
        title_us: None,
        x: ChartAxis {
            label: "F/C",
            display: Display::Plain,
            bounds: Some([0.0, f_max]),
        },
        y: ChartAxis {
            label: "M",
            display: Display::Moment,
            bounds: Some([0.0, top]),
        },
        series: Direction::ALL
            .iter()
            .enumerate()
            .map(|(d, dir)| Series {
                name: dir.name(),
                points: points
                    .get(d)
                    .map_or(&[][..], Vec::as_slice)
                    .iter()
                    .map(|p| (p.f_over_c, m(p)))
                    .collect(),
                display: None,
            })
            .collect(),
        per_element: false,
        operating: None,
    };
    vec![
        chart("M_fi against F/C", |p| p.friction_torque_inner_nm),
        chart("M_fo against F/C", |p| p.friction_torque_outer_nm),
    ]
}

/// The Torque-vs-load pane's line: C (ISO 281's C_r) and what the directions are.
fn torque_note(input: &DoubleRowInput, c_n: f64) -> Warning {
    let (fr, fa) = Direction::Combined.loads(input, 1.0);
    let c = Display::LargeForce;
    let line = |u: Units| {
        format!(
            "C = {:.1} {} (ISO 281 C_r), F = F/C × C; combined load at F_a/F_r = {:.3}",
            c.convert(c_n, u),
            c.unit(u),
            fa / fr
        )
    };
    Warning {
        si: line(Units::Si),
        us: line(Units::Us),
    }
}

/// Job 0: M_fi and M_fo against F/C in the three directions, each point reported as it
/// is solved.
///
/// # Errors
/// Cancelled; or the deck has no ISO 281 rating (γ outside Table 7).
pub fn torque_vs_load(
    input: &DoubleRowInput,
    name: &str,
    cancel: Cancel<'_>,
    report: &mut dyn FnMut(&JobView),
) -> Result<JobView, SolveError> {
    let stage = "torque vs load";
    let values = load_sweep::parse_range(TORQUE_F_OVER_C)
        .map_err(|message| SolveError::Stage { stage, message })?;
    let c_n = load_sweep::dynamic_rating_n(input).ok_or_else(|| SolveError::Stage {
        stage,
        message: "ISO 281's C_r needs γ = D·cos α/d_m within Table 7's 0.01–0.30; this deck's geometry is outside it, so F/C has no C".into(),
    })?;
    let f_max = values.iter().copied().fold(0.0, f64::max);
    let total = values.len() * Direction::ALL.len();
    let mut points: Vec<Vec<TorquePoint>> = vec![Vec::new(); Direction::ALL.len()];
    let mut errors = Vec::new();
    let mut done = 0;
    let view = |points: &[Vec<TorquePoint>], errors: &[String], done: usize| JobView {
        done,
        total,
        finished: done == total,
        stage: if done == total {
            "done".into()
        } else {
            "solving".into()
        },
        heat_maps: Vec::new(),
        charts: torque_charts(points, f_max),
        notes: vec![torque_note(input, c_n)],
        errors: errors.to_vec(),
    };
    report(&view(&points, &errors, 0));
    for (d, dir) in Direction::ALL.iter().enumerate() {
        for &fc in &values {
            if cancel.is_cancelled() {
                return Err(SolveError::Cancelled);
            }
            match load_sweep::torque_point(input, name, *dir, fc, c_n, cancel.flag()) {
                Ok(p) => points[d].push(p),
                Err(_) if cancel.is_cancelled() => return Err(SolveError::Cancelled),
                Err(e) => errors.push(e),
            }
            done += 1;
            report(&view(&points, &errors, done));
        }
    }
    Ok(view(&points, &errors, done))
}

/// Glyph of an infeasible cell by the first constraint it violates (the optimiser's
/// names), and a failed solve.
const EXCLUDED: [(&str, char); 7] = [
    ("lambda_min", 'l'),
    ("capacity_ratio", 'c'),
    ("p_max", 'p'),
    ("edge_loading", 'e'),
    ("r_ci_gt_r_w", 'r'),
    ("r_ce_gt_r_w", 'r'),
    ("solve failed", '!'),
];

/// What each excluded glyph means for `input`'s limits.
fn excluded_legend(input: &DoubleRowInput) -> Vec<(char, String)> {
    let o = &input.optimise;
    vec![
        ('l', format!("Λ_min < {}", o.min_lambda)),
        (
            'c',
            format!("capacity < {} × nominal", o.min_capacity_ratio),
        ),
        ('p', "p_max above nominal".into()),
        ('e', "edge load above nominal".into()),
        ('r', "R_W not below R_Ci, R_CE".into()),
        ('!', "solve failed".into()),
    ]
}

fn excluded_index(legend: &[(char, String)], constraint: &str) -> usize {
    let glyph = EXCLUDED
        .iter()
        .find(|(n, _)| *n == constraint)
        .map_or('!', |(_, g)| *g);
    legend.iter().position(|(g, _)| *g == glyph).unwrap_or(0)
}

/// The grid's axes in k = R′/R (the optimiser's: 1 + the engine's axis over [−r, r]).
fn grid_axis(input: &DoubleRowInput) -> Vec<f64> {
    let r = input.optimise.relative_range;
    engine::axis(-r, r, input.optimise.grid.max(2))
        .into_iter()
        .map(|u| 1.0 + u)
        .collect()
}

/// k of `v` in a solved input against the deck's.
fn k_of(v: Variable, base: &DoubleRowInput, solved: &DoubleRowInput) -> f64 {
    let (b, s) = (&base.geometry, &solved.geometry);
    match v {
        Variable::KCi => s.inner_raceway_radius_m / b.inner_raceway_radius_m,
        Variable::KW => s.roller_crown_radius_m / b.roller_crown_radius_m,
        Variable::KCe => s.outer_sphere_radius_m / b.outer_sphere_radius_m,
    }
}

/// The grid index of `k` on `axis` (to 1e-9), if it is a grid value.
fn on_axis(axis: &[f64], k: f64) -> Option<usize> {
    axis.iter().position(|a| (a - k).abs() <= 1e-9)
}

/// What the objective has seen of the grid so far: per grid point, per load case.
#[derive(Default)]
struct Seen {
    /// Grid index (all variables) → per load case its loss.
    points: BTreeMap<Vec<usize>, Vec<Option<CaseLoss>>>,
    /// Solves so far.
    solves: usize,
}

/// The grid cells of the first two variables whose other variables are nominal, from
/// what the objective has seen: (i, j) → (weighted total, weighted M_fi, weighted M_fo),
/// only where every load case is in.
fn seen_cells(
    seen: &Seen,
    weights: &[f64],
    mid: usize,
    dims: usize,
) -> BTreeMap<(usize, usize), CaseLoss> {
    let mut out = BTreeMap::new();
    for (idx, cases) in &seen.points {
        if idx.iter().skip(2).any(|i| *i != mid) || idx.len() != dims {
            continue;
        }
        let (Some(&i), j) = (idx.first(), idx.get(1).copied().unwrap_or(mid)) else {
            continue;
        };
        if cases.iter().any(Option::is_none) {
            continue;
        }
        let mut s = CaseLoss::default();
        for (c, w) in cases.iter().flatten().zip(weights) {
            s.total_w += w * c.total_w;
            s.friction_torque_inner_nm += w * c.friction_torque_inner_nm;
            s.friction_torque_outer_nm += w * c.friction_torque_outer_nm;
        }
        out.insert((i, j), s);
    }
    out
}

/// Bounds fitted to `ys` (5 % of the span either side; ±1 % of the value when flat).
fn fitted(ys: impl Iterator<Item = f64>) -> Option<[f64; 2]> {
    let (lo, hi) = ys
        .filter(|y| y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    if !lo.is_finite() {
        return None;
    }
    let pad = if hi > lo {
        0.05 * (hi - lo)
    } else {
        0.01 * lo.abs().max(f64::MIN_POSITIVE)
    };
    Some([lo - pad, hi + pad])
}

/// Fig. 3's two charts along the first variable (others nominal): M_fi, M_fo (N·m,
/// weighted over the load cases) and C (kN): C = ISO 281's C_r × the optimiser's capacity
/// ratio (L10/L10,nominal)^¼ (see `optimise`'s notes: the ratio is the life stage's, C_r
/// its scale).
fn fig3_charts(
    label: &'static str,
    axis: &[f64],
    torques: &[(f64, f64, f64)],
    capacity: &[(f64, f64)],
) -> Vec<Chart> {
    let xb = Some([
        axis.first().copied().unwrap_or(0.995),
        axis.last().copied().unwrap_or(1.005),
    ]);
    let fi: Vec<(f64, f64)> = torques.iter().map(|t| (t.0, t.1)).collect();
    let fo: Vec<(f64, f64)> = torques.iter().map(|t| (t.0, t.2)).collect();
    let m = Chart {
        title: "Fig. 3: M_fi, M_fo against R'/R (Σ weighted cases)".into(),
        title_us: None,
        x: ChartAxis {
            label,
            display: Display::Plain,
            bounds: xb,
        },
        y: ChartAxis {
            label: "M",
            display: Display::Moment,
            bounds: fitted(torques.iter().flat_map(|t| [t.1, t.2])),
        },
        series: vec![
            Series {
                name: "M_fi",
                points: fi,
                display: None,
            },
            Series {
                name: "M_fo",
                points: fo,
                display: None,
            },
        ],
        per_element: false,
        operating: None,
    };
    let c = Chart {
        title: "C = C_r × (L10/L10 nominal)^¼".into(),
        title_us: None,
        x: ChartAxis {
            label,
            display: Display::Plain,
            bounds: xb,
        },
        y: ChartAxis {
            label: "C",
            display: Display::LargeForce,
            bounds: fitted(capacity.iter().map(|c| c.1)),
        },
        series: vec![Series {
            name: "C",
            points: capacity.to_vec(),
            display: None,
        }],
        per_element: false,
        operating: None,
    };
    vec![m, c]
}

/// The Optimise pane's view: the heat map (from what the objective has seen, or the
/// finished optimisation's grid), Fig. 3 and the result lines.
fn optimise_view(
    input: &DoubleRowInput,
    seen: &Seen,
    planned: usize,
    done: Option<&Optimisation>,
) -> JobView {
    let vars = optimise::variables(input);
    let cases = optimise::load_cases(input);
    let weights: Vec<f64> = cases.iter().map(|c| c.weight).collect();
    let axis = grid_axis(input);
    let n = axis.len();
    let mid = on_axis(&axis, 1.0).unwrap_or(n / 2);
    let legend = excluded_legend(input);
    let label = |v: Option<&Variable>| v.map_or("k", |v| v.label());
    let mut cells = vec![HeatCell::Pending; n * n];
    let mut torques: Vec<(f64, f64, f64)> = Vec::new();
    let mut capacity: Vec<(f64, f64)> = Vec::new();
    let c_r = load_sweep::dynamic_rating_n(input);
    let mut notes = Vec::new();
    let mut errors = Vec::new();
    let mut marks = Vec::new();
    match done {
        None => {
            for ((i, j), s) in seen_cells(seen, &weights, mid, vars.len()) {
                if let Some(c) = cells.get_mut(j * n + i) {
                    *c = HeatCell::Value(s.total_w);
                }
                if j == mid {
                    torques.push((
                        axis[i],
                        s.friction_torque_inner_nm,
                        s.friction_torque_outer_nm,
                    ));
                }
            }
        }
        Some(o) => {
            let (vx, vy) = (
                vars.first().map(|v| v.name()),
                vars.get(1).map(|v| v.name()),
            );
            for g in &o.grid {
                let at = |v: Option<&str>| {
                    v.and_then(|v| g.variables.get(v))
                        .map_or(Some(mid), |k| on_axis(&axis, *k))
                };
                let others_nominal = g.variables.iter().all(|(name, k)| {
                    Some(*name) == vx || Some(*name) == vy || (k - 1.0).abs() < 1e-12
                });
                let (Some(i), Some(j), true) = (at(vx), at(vy), others_nominal) else {
                    continue;
                };
                // An infeasible cell keeps its loss (the map shows the objective
                // everywhere; the glyph says which constraint the cell breaks first).
                let cell = match (g.total_w, g.feasible) {
                    (Some(w), true) => HeatCell::Value(w),
                    (None, _) => HeatCell::Excluded(excluded_index(&legend, "solve failed"), None),
                    (Some(w), false) => HeatCell::Excluded(
                        excluded_index(
                            &legend,
                            g.violated.first().copied().unwrap_or("solve failed"),
                        ),
                        Some(w),
                    ),
                };
                if let Some(c) = cells.get_mut(j * n + i) {
                    *c = cell;
                }
                if j == mid {
                    if let (Some(fi), Some(fo)) =
                        (g.friction_torque_inner_nm, g.friction_torque_outer_nm)
                    {
                        torques.push((axis[i], fi, fo));
                    }
                    if let (Some(r), Some(c)) = (g.capacity_ratio, c_r) {
                        capacity.push((axis[i], r * c));
                    }
                }
                if let Some(e) = &g.error {
                    errors.push(format!(
                        "{}: {e}",
                        g.variables
                            .iter()
                            .map(|(k, v)| format!("{k} = {v:.5}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ));
                }
            }
            let opt_at = |v: Option<&str>| {
                let k = v.and_then(|v| o.optimum.variables.get(v)).copied();
                k.map_or(mid, |k| {
                    axis.iter()
                        .enumerate()
                        .min_by(|a, b| (a.1 - k).abs().total_cmp(&(b.1 - k).abs()))
                        .map_or(mid, |(i, _)| i)
                })
            };
            let opt = (opt_at(vx), opt_at(vy));
            if opt == (mid, mid) {
                marks.push(HeatMark {
                    i: mid,
                    j: mid,
                    glyph: '@',
                    label: "nominal = optimum",
                });
            } else {
                marks.push(HeatMark {
                    i: mid,
                    j: mid,
                    glyph: 'N',
                    label: "nominal",
                });
                marks.push(HeatMark {
                    i: opt.0,
                    j: opt.1,
                    glyph: 'O',
                    label: "optimum",
                });
            }
            let p = Display::Power;
            let vars_text = o
                .optimum
                .variables
                .iter()
                .map(|(k, v)| format!("{k} {v:.4}"))
                .collect::<Vec<_>>()
                .join(", ");
            let line = |u: Units| {
                let binding = if o.optimum.binding.is_empty() {
                    "none".to_string()
                } else {
                    o.optimum.binding.join(", ")
                };
                format!(
                    "optimum {vars_text}: {:.1} {} against {:.1} nominal, improvement {:.2} % · binding: {binding}",
                    p.convert(o.optimum.total_w, u),
                    p.unit(u),
                    p.convert(o.nominal.total_w, u),
                    o.optimum.improvement_pct,
                )
            };
            notes.push(Warning {
                si: line(Units::Si),
                us: line(Units::Us),
            });
            if let Some(un) = &o.unconstrained {
                let t = format!(
                    "unconstrained grid minimum {}: improvement {:.2} %, violates {}",
                    un.variables
                        .iter()
                        .map(|(k, v)| format!("{k} {v:.4}"))
                        .collect::<Vec<_>>()
                        .join(", "),
                    un.improvement_pct,
                    if un.violated.is_empty() {
                        "nothing".to_string()
                    } else {
                        un.violated.join(", ")
                    }
                );
                notes.push(Warning {
                    si: t.clone(),
                    us: t,
                });
            }
        }
    }
    torques.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut heat_maps = Vec::new();
    if vars.len() >= 2 {
        heat_maps.push(HeatMap {
            title: "total loss over the grid".into(),
            x: ChartAxis {
                label: label(vars.first()),
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: label(vars.get(1)),
                display: Display::Plain,
                bounds: None,
            },
            xs: axis.clone(),
            ys: axis.clone(),
            value: ("loss", Display::Power, 1),
            cells,
            excluded: legend,
            marks,
        });
    } else {
        notes.push(Warning {
            si: "one variable: no map (the chart is the grid)".into(),
            us: "one variable: no map (the chart is the grid)".into(),
        });
    }
    let finished = done.is_some();
    let solves = if finished {
        seen.solves.max(planned)
    } else {
        seen.solves.min(planned)
    };
    let grid_done = cells_done(seen, &weights, mid, vars.len(), n);
    JobView {
        done: solves,
        total: planned,
        finished,
        stage: match (finished, grid_done) {
            (true, _) => "done".into(),
            (false, true) => "polish".into(),
            (false, false) => "grid".into(),
        },
        heat_maps,
        charts: fig3_charts(label(vars.first()), &axis, &torques, &capacity),
        notes,
        errors,
    }
}

/// True once every cell of the map (or of the line, with one variable) is in.
fn cells_done(seen: &Seen, weights: &[f64], mid: usize, dims: usize, n: usize) -> bool {
    let want = if dims >= 2 { n * n } else { n };
    seen_cells(seen, weights, mid, dims).len() >= want
}

/// Solves the optimiser plans (its own count: nominal twice over, grid, polish budget,
/// sensitivity).
fn planned_solves(input: &DoubleRowInput) -> usize {
    let dims = optimise::variables(input).len().max(1);
    let cases = optimise::load_cases(input).len();
    let n = input.optimise.grid.max(2);
    cases * 2
        + n.saturating_pow(dims as u32).saturating_mul(cases)
        + optimise::MAX_POLISH_SOLVES
        + 2 * dims * cases
}

/// Job 1: the optimiser on the deck's `[optimise]`, reported every 100 ms while it runs
/// (the optimiser in a scoped thread, its grid in parallel; this thread only reads what
/// the objective recorded).
///
/// # Errors
/// Cancelled; a grid over the bound (`optimise.grid`, the refusal whole); the nominal
/// bearing not solving; no feasible grid point (each the optimiser's message).
pub fn optimise_job(
    input: &DoubleRowInput,
    name: &str,
    units: Units,
    cancel: Cancel<'_>,
    report: &mut dyn FnMut(&JobView),
) -> Result<JobView, SolveError> {
    let vars = optimise::variables(input);
    let cases = optimise::load_cases(input);
    let axis = grid_axis(input);
    let laminae = input.solver.laminae;
    let planned = planned_solves(input);
    let seen = Mutex::new(Seen::default());
    // The system's objective, recording each grid solve of the deck's fidelity.
    let objective = |a: &DoubleRowAnalysis| -> Result<CaseLoss, String> {
        let r = optimise::loss_objective(a);
        if let Ok(mut s) = seen.lock() {
            s.solves += 1;
            let idx: Option<Vec<usize>> = vars
                .iter()
                .map(|v| on_axis(&axis, k_of(*v, input, &a.input)))
                .collect();
            let case = cases.iter().position(|c| {
                c.radial_load_n == a.input.operating.radial_load_n
                    && c.axial_load_n == a.input.operating.axial_load_n
            });
            if let (Some(idx), Some(case), Ok(loss), true) =
                (idx, case, &r, a.input.solver.laminae == laminae)
            {
                let slot = s
                    .points
                    .entry(idx)
                    .or_insert_with(|| vec![None; cases.len()]);
                if let Some(x) = slot.get_mut(case) {
                    *x = Some(*loss);
                }
            }
        }
        r
    };
    let snapshot = |done: Option<&Optimisation>| match seen.lock() {
        Ok(s) => optimise_view(input, &s, planned, done),
        Err(_) => JobView::failed("the optimiser's progress record was lost (a panic)".into()),
    };
    report(&snapshot(None));
    let result = std::thread::scope(|scope| {
        let run = scope.spawn(|| optimise::optimise(input, name, &objective, cancel));
        while !run.is_finished() {
            std::thread::sleep(Duration::from_millis(100));
            if cancel.is_cancelled() {
                continue; // the run stops at its next solve
            }
            report(&snapshot(None));
        }
        run.join()
    });
    let result = result.map_err(|p| SolveError::Stage {
        stage: "optimise",
        message: format!(
            "the optimiser panicked: {}",
            p.downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default()
        ),
    })?;
    match result {
        Ok(o) => Ok(snapshot(Some(&o))),
        Err(optimise::OptimiseError::Cancelled) => Err(SolveError::Cancelled),
        Err(e) => Err(SolveError::Stage {
            stage: "optimise",
            message: restate_si(&e.to_string(), units),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(m: &HeatMap) -> Vec<Option<f64>> {
        m.cells
            .iter()
            .map(|c| match c {
                HeatCell::Value(v) | HeatCell::Excluded(_, Some(v)) => Some(*v),
                _ => None,
            })
            .collect()
    }

    /// The Optimise pane's map fills in from the objective while the optimiser runs, and
    /// what it shows of a cell is the optimiser's own weighted total for that grid point:
    /// every report's cells are the finished grid's values exactly (the same solves,
    /// summed over the cases in the same order), cells are never taken back, and the
    /// finished map holds every grid point of the optimisation's grid, the nominal point
    /// marked at the middle. A 3 × 3 grid (the shipped deck's cases) keeps it short.
    /// The shipped deck with its `[optimise]` table (three load cases, Λ_min ≥ 2.5).
    fn shipped() -> DoubleRowInput {
        use crate::deck::form::Form;
        let mut f = Form::parse(
            super::super::system::EXAMPLE_DECK,
            "srb_22308.toml",
            &super::super::deck::SCHEMA,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        super::super::deck::optimise_table(&mut f).unwrap_or_else(|e| panic!("{e}"));
        f.value
    }

    #[test]
    fn the_optimise_map_fills_in_with_the_optimisers_values() {
        let mut b = shipped();
        b.optimise.grid = 3;
        // The measured cage, as the optimiser's own tests: with the computed cage a warm
        // start may land the cage balance elsewhere in its torque step (see
        // `losses::CAGE_SPEED_RESOLUTION`), so a polish re-solve of a grid point need not
        // repeat the grid's value to the last digit.
        b.cage.speed = super::super::input::CageSpeedSource::Measured;
        let mut reports = Vec::new();
        let done = optimise_job(&b, "t", Units::Si, Cancel::NONE, &mut |v| {
            reports.push(v.clone())
        })
        .expect("optimises");
        assert!(done.finished && !reports.is_empty());
        // The finished map is drawn from the optimisation's own grid entries.
        let last = &done.heat_maps[0];
        let want: Vec<Option<f64>> = values(last);
        assert_eq!(want.len(), 9);
        assert!(want.iter().all(Option::is_some), "{want:?}");
        let mut filled = 0;
        for r in &reports {
            let got = values(&r.heat_maps[0]);
            for (g, w) in got.iter().zip(&want) {
                if let (Some(g), Some(w)) = (g, w) {
                    // The same point solved warm (the grid, from its neighbour) and again by
                    // the polish (from the nearest solved point) agrees to the losses'
                    // sensitivity to the statics' last digits: 2.1e-4 measured before the
                    // ATZ law was regularised at its rolling point (`lamina_friction`), a
                    // 1e-8 load change now moving every loss term by ≤ 3.7e-7
                    // (`statics::tests::loss_terms_follow_a_tiny_load_change`). 1e-6.
                    assert!((g - w).abs() <= 1e-6 * w.abs(), "{g} vs {w}");
                } else {
                    assert!(g.is_none() || w.is_some(), "{g:?} vs {w:?}");
                }
            }
            let n = got.iter().flatten().count();
            assert!(n >= filled, "cells taken back: {n} after {filled}");
            filled = n;
        }
        assert!(last.marks.iter().any(|m| (m.i, m.j) == (1, 1)));
        assert!(done.notes[0].si.contains("improvement"), "{:?}", done.notes);
    }

    /// A grid over the optimiser's bound is refused whole, naming `optimise.grid`.
    #[test]
    fn an_oversized_grid_is_refused_whole() {
        let mut b = shipped();
        b.optimise.grid = 99; // 99² × 3 cases = 29 403 solves
        let e = optimise_job(&b, "t", Units::Si, Cancel::NONE, &mut |_| {}).expect_err("refused");
        let text = e.to_string();
        assert!(
            text.contains("optimise.grid") && text.contains("20000"),
            "{text}"
        );
    }

    /// Round tops: 1, 2, 2.5, 5 × 10^k.
    #[test]
    fn round_tops() {
        assert_eq!(round_up(4.2), 5.0);
        assert_eq!(round_up(0.61), 1.0);
        assert_eq!(round_up(2.0), 2.0);
        assert_eq!(round_up(0.0), 1.0);
        assert!((round_up(0.22) - 0.25).abs() < 1e-15);
    }
}
