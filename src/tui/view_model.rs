//! The one place where the TUI reads an [`Analysis`].
//!
//! Every function here turns solver output into plain rows and series (strings with
//! fixed precision, or `f64` pairs for charts) in the chosen display [`Units`]. Panes
//! never touch `Analysis` directly, so when a new pipeline stage lands (stresses, film,
//! spin, heat, thermal) only this module changes: fill the matching `—` cell or the
//! [`ThermalView`].

use crate::bearings::spherical_roller::load_distribution::{LaminaResult, TraceStep};
use crate::bearings::spherical_roller::pipeline::Analysis;

use crate::units::{Units, FAHRENHEIT_PER_KELVIN, INCH_M as IN_M, LBF_N, PSI_PA};

/// Placeholder for a value that the current pipeline does not compute yet.
pub const DASH: &str = "—";

/// A force in display units (N or lbf).
pub fn force(value_n: f64, u: Units) -> f64 {
    match u {
        Units::Si => value_n,
        Units::Us => value_n / LBF_N,
    }
}

/// Unit label of [`force`].
pub fn force_unit(u: Units) -> &'static str {
    match u {
        Units::Si => "N",
        Units::Us => "lbf",
    }
}

/// A load per unit length (a lamina's load over its width) in display units: N/mm or
/// lbf/in.
pub fn line_load(value_n_m: f64, u: Units) -> f64 {
    match u {
        Units::Si => value_n_m * 1e-3,
        Units::Us => value_n_m / LBF_N * IN_M,
    }
}

/// Unit label of [`line_load`].
pub fn line_load_unit(u: Units) -> &'static str {
    match u {
        Units::Si => "N/mm",
        Units::Us => "lbf/in",
    }
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
    match u {
        Units::Si => value_m * 1e3,
        Units::Us => value_m / IN_M * 1e3,
    }
}

/// Film thickness in display units (µm or µin).
pub fn film_thickness(value_m: f64, u: Units) -> f64 {
    match u {
        Units::Si => value_m * 1e6,
        Units::Us => value_m / IN_M * 1e6,
    }
}

/// Unit label of [`small_length`].
pub fn small_length_unit(u: Units) -> &'static str {
    match u {
        Units::Si => "mm",
        Units::Us => "mil",
    }
}

/// Unit label of contact stress (MPa or ksi).
pub fn stress_unit(u: Units) -> &'static str {
    match u {
        Units::Si => "MPa",
        Units::Us => "ksi",
    }
}

/// A contact stress in display units (MPa or ksi).
pub fn stress(value_pa: f64, u: Units) -> f64 {
    match u {
        Units::Si => value_pa / 1e6,
        Units::Us => value_pa / PSI_PA / 1e3,
    }
}

/// Unit label of film thickness (µm or µin).
pub fn film_unit(u: Units) -> &'static str {
    match u {
        Units::Si => "µm",
        Units::Us => "µin",
    }
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

/// One column of the rollers table: header (with unit) and width in cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Header text, unit included.
    pub header: String,
    /// Column width, cells.
    pub width: u16,
}

/// Columns of the rollers table, in display units.
///
/// Order: index, azimuth, inner and outer normal load, inner and outer contact angle,
/// max stress, film, Λ, spin speed, heat. [`roller_rows`] fills the same order.
pub fn roller_columns(u: Units) -> Vec<Column> {
    let f = force_unit(u);
    let col = |h: String, w: u16| Column {
        header: h,
        width: w,
    };
    vec![
        col("#".into(), 3),
        col("ψ deg".into(), 5),
        col(format!("Qi {f}"), 7),
        col(format!("Qo {f}"), 7),
        col("αi °".into(), 5),
        col("αo °".into(), 5),
        col(format!("σ {}", stress_unit(u)), 6),
        col(format!("h {}", film_unit(u)), 6),
        col("Λ".into(), 4),
        col("spin rpm".into(), 8),
        col("heat W".into(), 6),
    ]
}

/// One row per roller, same order as [`roller_columns`]; `—` for stages not yet solved.
/// The values come joined per roller from the system's view
/// ([`crate::bearings::spherical_roller::view::rollers`]); nothing is computed here.
pub fn roller_rows(a: &Analysis, u: Units) -> Vec<Vec<String>> {
    let opt = |v: Option<f64>, f: &dyn Fn(f64) -> String| v.map_or(DASH.to_string(), f);
    crate::bearings::spherical_roller::view::rollers(a)
        .iter()
        .map(|rv| {
            let r = rv.roller;
            vec![
                format!("{}", r.index),
                fixed(r.azimuth_deg, 1),
                fixed(force(r.inner.normal_load_n, u), 1),
                fixed(force(r.outer.normal_load_n, u), 1),
                fixed(r.inner.contact_angle_deg, 2),
                fixed(r.outer.contact_angle_deg, 2),
                // max of the two raceways' max Hertz stress (§4)
                opt(rv.max_stress_pa(), &|m| fixed(stress(m, u), 0)),
                // thinnest lamina film of the roller (§5)
                opt(rv.min_film_m(), &|h| fixed(film_thickness(h, u), 2)),
                // Λ of that film (eq. 6.8, conservative composite roughness)
                opt(rv.lambda, &|l| fixed(l, 2)),
                // roller spin relative to the cage (§7)
                opt(rv.spin_rpm, &|x| fixed(x, 0)),
                // contact heat of the roller, both raceways (§9)
                opt(rv.heat_w(), &|h| fixed(h, 1)),
            ]
        })
        .collect()
}

/// Number of rollers in the solution.
pub fn roller_count(a: &Analysis) -> usize {
    a.load.rollers.len()
}

/// Series for the load chart: `(x, y)` pairs, display units.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadSeries {
    /// Chart title.
    pub title: String,
    /// X axis label with unit.
    pub x_label: String,
    /// Y axis label with unit.
    pub y_label: String,
    /// Inner-raceway series.
    pub inner: Vec<(f64, f64)>,
    /// Outer-raceway series.
    pub outer: Vec<(f64, f64)>,
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

/// Roller normal loads (inner and outer) against azimuth, 0–360°.
pub fn load_vs_azimuth(a: &Analysis, u: Units) -> LoadSeries {
    let inner: Vec<(f64, f64)> = a
        .load
        .rollers
        .iter()
        .map(|r| (r.azimuth_deg, force(r.inner.normal_load_n, u)))
        .collect();
    let outer: Vec<(f64, f64)> = a
        .load
        .rollers
        .iter()
        .map(|r| (r.azimuth_deg, force(r.outer.normal_load_n, u)))
        .collect();
    let ymax = inner.iter().chain(&outer).map(|p| p.1).fold(0.0, f64::max);
    LoadSeries {
        title: "roller load vs azimuth".into(),
        x_label: "ψ deg".into(),
        y_label: force_unit(u).into(),
        inner,
        outer,
        x_bounds: [0.0, 360.0],
        y_bounds: [0.0, nice_ceiling(ymax)],
    }
}

/// The load distribution along roller `roller` (0-based): each lamina's load per unit
/// length against its offset from the roller centre; edge loading shows as a rise at the
/// ends. `None` if there is no such roller.
pub fn lamina_loads(a: &Analysis, roller: usize, u: Units) -> Option<LoadSeries> {
    let r = a.load.rollers.get(roller)?;
    let series = |loads: Vec<f64>| -> Vec<(f64, f64)> {
        per_length(&loads, &r.laminae)
            .into_iter()
            .zip(&r.laminae)
            .map(|(q, l)| (small_length(l.offset_m, u), line_load(q, u)))
            .collect()
    };
    let inner = series(r.laminae.iter().map(|l| l.inner_load_n).collect());
    let outer = series(r.laminae.iter().map(|l| l.outer_load_n).collect());
    let ymax = inner.iter().chain(&outer).map(|p| p.1).fold(0.0, f64::max);
    let xmax = inner.iter().map(|p| p.0.abs()).fold(0.0, f64::max);
    let xmax = if xmax > 0.0 { xmax } else { 1.0 };
    Some(LoadSeries {
        title: format!("load along roller {}", r.index),
        x_label: format!("x {}", small_length_unit(u)),
        y_label: line_load_unit(u).into(),
        inner,
        outer,
        x_bounds: [-xmax, xmax],
        y_bounds: [0.0, nice_ceiling(ymax)],
    })
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
        load_unit: line_load_unit(u).into(),
        approach_unit: su.into(),
    })
}
