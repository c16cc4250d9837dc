//! The one place where the TUI reads an [`Analysis`].
//!
//! Every function here turns solver output into plain rows and series (strings with
//! fixed precision, or `f64` pairs for charts) in the chosen display [`Units`]. Panes
//! never touch `Analysis` directly, so when a new pipeline stage lands (stresses, film,
//! spin, heat, thermal) only this module changes: fill the matching `—` cell or the
//! [`ThermalView`].

use crate::bearings::spherical_roller::load_distribution::{LaminaResult, TraceStep};
use crate::bearings::spherical_roller::pipeline::Analysis;
use crate::bearings::view::{Chart, Display, Screen, View};

use crate::units::{Units, FAHRENHEIT_PER_KELVIN};

/// Placeholder for a value that the current pipeline does not compute yet.
pub const DASH: &str = "—";

/// A force in display units (N or lbf).
pub fn force(value_n: f64, u: Units) -> f64 {
    Display::Force.convert(value_n, u)
}

/// Unit label of [`force`].
pub fn force_unit(u: Units) -> &'static str {
    Display::Force.unit(u)
}

/// A load per unit length (a lamina's load over its width) in display units: N/mm or
/// lbf/in.
pub fn line_load(value_n_m: f64, u: Units) -> f64 {
    Display::LineLoad.convert(value_n_m, u)
}

/// Each lamina's load over its width, N/m: the load distribution along the roller. The
/// laminae are not equally wide (cosine slicing puts thin ones at the ends), so their
/// loads alone would draw the thin end laminae low however hard the end is loaded.
fn per_length(loads_n: &[f64], laminae: &[LaminaResult]) -> Vec<f64> {
    loads_n
        .iter()
        .zip(laminae)
        .map(|(&q, l)| if l.width_m > 0.0 { q / l.width_m } else { 0.0 })
        .collect()
}

/// A small length (deflection, approach, lamina offset) in display units: mm or mil
/// (0.001 in), which keep lamina offsets and deflections readable.
pub fn small_length(value_m: f64, u: Units) -> f64 {
    Display::SmallLength.convert(value_m, u)
}

/// Unit label of [`small_length`].
pub fn small_length_unit(u: Units) -> &'static str {
    Display::SmallLength.unit(u)
}

/// `v` with `prec` decimals; a result that rounds to zero prints without a sign, so
/// last-bit noise (−0.00 vs 0.00) never reaches a pane or a snapshot.
pub fn fixed(v: f64, prec: usize) -> String {
    let s = format!("{v:.prec$}");
    if s.chars().all(|c| matches!(c, '-' | '0' | '.')) {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// Like [`fixed`] with an explicit `+` on positive values.
pub fn signed(v: f64, prec: usize) -> String {
    let s = fixed(v, prec);
    if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    }
}

/// A residual in engineering form with sign; below 1e-6 (solver noise) prints `≈0`.
pub fn residual(v: f64) -> String {
    if v.abs() < 1e-6 {
        "≈0".to_string()
    } else {
        format!("{v:+.2e}")
    }
}

/// One column of a pane table: header (with unit) and width in cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Header text, unit included.
    pub header: String,
    /// Column width, cells.
    pub width: u16,
}

/// The screen table of a view in display units `u`: the columns meant for the pane and
/// one row of formatted cells per element (`—` where a stage was not run). Formatting
/// only: the values come from the bearing system's view.
pub fn table_cells(view: &View, u: Units) -> (Vec<Column>, Vec<Vec<String>>) {
    let Some(t) = view.screen_table() else {
        return (Vec::new(), Vec::new());
    };
    let shown: Vec<(usize, Screen)> = t
        .columns
        .iter()
        .enumerate()
        .filter_map(|(i, c)| c.screen.map(|s| (i, s)))
        .collect();
    let cols = shown
        .iter()
        .map(|(_, s)| Column {
            header: s.display.header(s.label, u),
            width: s.width,
        })
        .collect();
    let rows = t
        .rows
        .iter()
        .map(|row| {
            shown
                .iter()
                .map(|&(i, s)| match row.get(i).copied().flatten() {
                    Some(v) => fixed(s.display.convert(v, u), s.precision),
                    None => DASH.to_string(),
                })
                .collect()
        })
        .collect();
    (cols, rows)
}

/// Number of rollers in the solution.
pub fn roller_count(a: &Analysis) -> usize {
    a.load.rollers.len()
}

/// A chart in display units, with its bounds.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ChartSeries {
    /// Chart title.
    pub title: String,
    /// X axis label with unit.
    pub x_label: String,
    /// Y axis label with unit.
    pub y_label: String,
    /// Named series of `(x, y)` points, display units.
    pub series: Vec<(&'static str, Vec<(f64, f64)>)>,
    /// X bounds.
    pub x_bounds: [f64; 2],
    /// Y bounds (0 to a rounded-up maximum).
    pub y_bounds: [f64; 2],
}

/// Rounds a positive maximum up to 1, 2 or 5 × 10ⁿ so axis labels are short and stable.
fn nice_ceiling(v: f64) -> f64 {
    if !(v.is_finite() && v > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(v.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if v <= m * p * (1.0 + 1e-9) {
            return m * p;
        }
    }
    10.0 * p
}

/// A view's chart in display units `u`: fixed bounds where the chart gives them, else y
/// from 0 to a round ceiling of the data and x symmetric about 0.
pub fn chart_series(c: &Chart, u: Units) -> ChartSeries {
    let series: Vec<(&'static str, Vec<(f64, f64)>)> = c
        .series
        .iter()
        .map(|s| {
            let pts = s
                .points
                .iter()
                .map(|&(x, y)| (c.x.display.convert(x, u), c.y.display.convert(y, u)))
                .collect();
            (s.name, pts)
        })
        .collect();
    let ymax = series
        .iter()
        .flat_map(|s| s.1.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    let xmax = series
        .first()
        .map_or(0.0, |s| s.1.iter().map(|p| p.0.abs()).fold(0.0, f64::max));
    let xmax = if xmax > 0.0 { xmax } else { 1.0 };
    ChartSeries {
        title: c.title.clone(),
        x_label: c.x.display.header(c.x.label, u),
        y_label: c.y.display.header(c.y.label, u),
        series,
        x_bounds: c.x.bounds.unwrap_or([-xmax, xmax]),
        y_bounds: c.y.bounds.unwrap_or([0.0, nice_ceiling(ymax)]),
    }
}

/// What the thermal pane shows. Built by [`thermal_view`]; `None` means the deck has
/// no thermal model (or the thermal stage has not landed yet).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThermalView {
    /// Steady-state temperatures: node name and temperature in display units.
    pub steady: Vec<(String, f64)>,
    /// Temperature unit label (°C or °F).
    pub temperature_unit: String,
    /// Name of the node whose transient is plotted (the hottest by default).
    pub series_name: String,
    /// Transient temperature samples of that node, display units, evenly spaced in time.
    pub series: Vec<f64>,
    /// Time span of `series`, s.
    pub series_span_s: f64,
    /// Time for that node to reach its limit, s (`None`: not reached or no limit).
    pub time_to_limit_s: Option<f64>,
}

/// The thermal pane's data; `node` picks the node whose transient is plotted (`None`
/// or out of range: the hottest).
pub fn thermal_view(a: &Analysis, u: Units, node: Option<usize>) -> Option<ThermalView> {
    let th = a.thermal.as_ref()?;
    let (conv, unit): (fn(f64) -> f64, &str) = match u {
        Units::Si => (|c| c, "°C"),
        Units::Us => (|c| c * FAHRENHEIT_PER_KELVIN + 32.0, "°F"),
    };
    let steady: Vec<(String, f64)> = th
        .steady
        .nodes
        .iter()
        .map(|n| (n.name.clone(), conv(n.temperature_c)))
        .collect();
    let mut view = ThermalView {
        steady,
        temperature_unit: unit.to_string(),
        ..ThermalView::default()
    };
    if let Some(tr) = &th.transient {
        // Default: the node hottest at the end of the transient.
        let hottest = tr
            .nodes
            .iter()
            .enumerate()
            .max_by(|x, y| {
                let lx = x.1.temperature_c.last().copied().unwrap_or(f64::MIN);
                let ly = y.1.temperature_c.last().copied().unwrap_or(f64::MIN);
                lx.total_cmp(&ly)
            })
            .map(|(i, _)| i);
        let pick = node.filter(|&i| i < tr.nodes.len()).or(hottest);
        if let Some(n) = pick.and_then(|i| tr.nodes.get(i)) {
            view.series_name = n.name.clone();
            view.series = n.temperature_c.iter().map(|c| conv(*c)).collect();
            view.series_span_s = tr.time_s.last().copied().unwrap_or(0.0)
                - tr.time_s.first().copied().unwrap_or(0.0);
            view.time_to_limit_s = n.time_to_limit_s;
        }
    }
    Some(view)
}

/// Solver work counters for the status bar.
#[derive(Debug, Clone, PartialEq)]
pub struct SolveSummary {
    /// Ring (outer Newton) iterations.
    pub iterations: usize,
    /// Roller Newton iterations.
    pub roller_iterations: usize,
    /// Lamina contact evaluations.
    pub lamina_evaluations: usize,
    /// Wall time, ms.
    pub wall_ms: f64,
    /// True if the load distribution converged.
    pub converged: bool,
}

/// Counters of a solve.
pub fn solve_summary(a: &Analysis) -> SolveSummary {
    let s = &a.load.stats;
    SolveSummary {
        iterations: s.iterations,
        roller_iterations: s.roller_iterations,
        lamina_evaluations: s.lamina_evaluations,
        wall_ms: s.wall_time_s * 1e3,
        converged: a.load.converged,
    }
}

/// Bearing-level results as label/value lines (ring deflections, residuals).
pub fn bearing_lines(a: &Analysis, u: Units) -> Vec<(String, String)> {
    let l = &a.load;
    let su = small_length_unit(u);
    let fu = force_unit(u);
    vec![
        (
            format!("axial deflection {su}"),
            fixed(small_length(l.axial_deflection_m, u), 4),
        ),
        (
            format!("radial deflection {su}"),
            fixed(small_length(l.radial_deflection_m, u), 4),
        ),
        (
            format!("residual radial {fu}"),
            residual(force(l.residuals.bearing_radial_n, u)),
        ),
        (
            format!("residual axial {fu}"),
            residual(force(l.residuals.bearing_axial_n, u)),
        ),
    ]
}

/// One step of the roller stepper, formatted.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepView {
    /// Label/value lines: iteration numbers, displacements, residuals.
    pub lines: Vec<(String, String)>,
    /// Inner lamina loads per unit length, display units (for the bar row).
    pub inner_load: Vec<f64>,
    /// Outer lamina loads per unit length, display units.
    pub outer_load: Vec<f64>,
    /// Inner lamina approaches, display small-length units.
    pub inner_approach: Vec<f64>,
    /// Outer lamina approaches, display small-length units.
    pub outer_approach: Vec<f64>,
    /// Load-per-length unit label of the bar rows.
    pub load_unit: String,
    /// Approach unit label.
    pub approach_unit: String,
}

/// Number of recorded trace steps.
pub fn trace_len(a: &Analysis) -> usize {
    a.trace.len()
}

/// One line per recorded step for the stepper's history list: step number (1-based),
/// ring/roller iteration and the three residuals (axial N or lbf, radial, moment N·m).
pub fn trace_rows(a: &Analysis, u: Units) -> Vec<String> {
    a.trace
        .iter()
        .enumerate()
        .map(|(i, t)| {
            format!(
                "{:>3}  {:>2}/{:<2}  {:>10} {:>10} {:>10}",
                i + 1,
                t.ring_iteration,
                t.roller_iteration,
                residual(force(t.residual[0], u)),
                residual(force(t.residual[1], u)),
                residual(t.residual[2])
            )
        })
        .collect()
}

/// Header of [`trace_rows`].
pub fn trace_header(u: Units) -> String {
    let f = force_unit(u);
    format!(
        "{:>3}  {:<5}  {:>10} {:>10} {:>10}",
        "#",
        "it",
        format!("ax {f}"),
        format!("rad {f}"),
        "mom N·m"
    )
}

/// Formats trace step `step` (0-based); `None` when out of range or nothing recorded.
pub fn trace_step(a: &Analysis, step: usize, u: Units) -> Option<StepView> {
    let t: &TraceStep = a.trace.get(step)?;
    let su = small_length_unit(u);
    let fu = force_unit(u);
    let lines = vec![
        (
            "ring/roller iter".to_string(),
            format!("{} / {}", t.ring_iteration, t.roller_iteration),
        ),
        (
            format!("ring ax,rad {su}"),
            format!(
                "{}, {}",
                signed(small_length(t.ring[0], u), 5),
                signed(small_length(t.ring[1], u), 5)
            ),
        ),
        (
            format!("roller ax,rad {su}"),
            format!(
                "{}, {}",
                signed(small_length(t.roller[0], u), 5),
                signed(small_length(t.roller[1], u), 5)
            ),
        ),
        (
            "roller pitch mrad".to_string(),
            signed(t.roller[2] * 1e3, 5),
        ),
        (
            format!("resid ax,rad {fu}"),
            format!(
                "{}, {}",
                residual(force(t.residual[0], u)),
                residual(force(t.residual[1], u))
            ),
        ),
        ("resid moment N·m".to_string(), residual(t.residual[2])),
    ];
    // The traced roller's laminae (every roller is sliced alike) give the widths.
    let laminae = a
        .load
        .rollers
        .first()
        .map_or(&[][..], |r| r.laminae.as_slice());
    let bars = |loads: &[f64]| -> Vec<f64> {
        per_length(loads, laminae)
            .into_iter()
            .map(|q| line_load(q, u))
            .collect()
    };
    Some(StepView {
        lines,
        inner_load: bars(&t.inner_load_n),
        outer_load: bars(&t.outer_load_n),
        inner_approach: t
            .inner_approach_m
            .iter()
            .map(|&v| small_length(v, u))
            .collect(),
        outer_approach: t
            .outer_approach_m
            .iter()
            .map(|&v| small_length(v, u))
            .collect(),
        load_unit: Display::LineLoad.unit(u).into(),
        approach_unit: su.into(),
    })
}
