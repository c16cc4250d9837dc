//! Formatting of a solution's [`View`] for the panes: every function here turns the
//! view's SI tables, charts, trace and thermal results into plain rows and series
//! (strings with fixed precision, or `f64` pairs for charts) in the chosen display
//! [`Units`]. The view comes from the bearing system; nothing here knows which one.

use crate::bearings::view::{
    significant, AnswerLine, AnswerValue, Chart, Display, Screen, ThermalResults, Trace,
    TraceFormat, View,
};
use crate::report::diff::{
    change, matching_columns, names_the_row, percent_change, Diff, Row as DiffRow,
};

use crate::studies::sweep::{PlanPoint, PlanProgress};
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

/// A small length (deflection, approach, lamina offset) in display units: mm or mil
/// (0.001 in), which keep lamina offsets and deflections readable.
pub fn small_length(value_m: f64, u: Units) -> f64 {
    Display::SmallLength.convert(value_m, u)
}

/// Unit label of [`small_length`].
pub fn small_length_unit(u: Units) -> &'static str {
    Display::SmallLength.unit(u)
}

pub use crate::bearings::view::fixed;

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

/// A number in at most `width` characters that reads back as `v` to within the precision
/// it shows, or `…` when nothing that honest fits. Tried in order: `prec` decimals, fewer
/// decimals, a k/M/G/T multiplier (`171.3k`), scientific (`1.7e5`). Never a number with
/// digits or its sign dropped: a cut `171333.6` reads as `71333.6`.
pub fn fit_number(v: f64, prec: usize, width: usize) -> String {
    let fits = |s: &str| s.chars().count() <= width;
    if !v.is_finite() {
        let s = format!("{v}");
        return if fits(&s) { s } else { "…".into() };
    }
    for p in (0..=prec).rev() {
        let s = fixed(v, p);
        if fits(&s) {
            return s;
        }
    }
    for (scale, suffix) in [(1e3, "k"), (1e6, "M"), (1e9, "G"), (1e12, "T")] {
        if v.abs() >= 0.9995 * scale {
            for p in (0..=3).rev() {
                let mantissa = fixed(v / scale, p);
                // 999.96k rounds to "1000.0k": the next multiplier says it better
                let int_digits = mantissa
                    .trim_start_matches('-')
                    .split('.')
                    .next()
                    .map_or(0, str::len);
                let s = format!("{mantissa}{suffix}");
                if int_digits <= 3 && fits(&s) {
                    return s;
                }
            }
        }
    }
    for p in (0..=3).rev() {
        let s = format!("{v:.p$e}");
        if fits(&s) {
            return s;
        }
    }
    "…".into()
}

/// One column of a pane table: header (with unit) and width in cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Header text, unit included.
    pub header: String,
    /// Column width, cells.
    pub width: u16,
}

/// A view's element table laid out for a pane `width` cells wide.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TableCells {
    /// The columns shown, each as wide as its widest cell (or narrower when the pane is
    /// narrow: then its numbers switch to fewer decimals, k/M or scientific form).
    pub columns: Vec<Column>,
    /// One row of formatted cells per element (`—` where a stage was not run).
    pub rows: Vec<Vec<String>>,
    /// Columns left out because even at their narrowest they do not fit (or are
    /// scrolled off to the left).
    pub hidden: usize,
    /// Spaces between columns.
    pub gap: u16,
    /// Columns of the table in all (shown and hidden).
    pub total: usize,
    /// The 1-based numbers of the first and last columns shown after the pinned first
    /// one (`columns 2–9 of 17`).
    pub range: [usize; 2],
    /// The scroll offset used: how many columns after the first are scrolled off
    /// (the requested offset, clamped to keep at least one column in view).
    pub first: usize,
}

/// Narrowest a number column gets: room for `-1.2k` or `1.2e5`.
const MIN_NUMBER_WIDTH: usize = 5;

/// Most cells a column of a table narrower than its pane is widened by.
pub const MAX_SPREAD: usize = 4;

/// The screen table of a view in display units `u`, for a pane `width` cells wide
/// (columns separated by two spaces, or one when room is short). Columns take the width of their widest cell and
/// header; when that does not fit, the widest give way first, down to their header or
/// [`MIN_NUMBER_WIDTH`], and their numbers are refitted ([`fit_number`]); columns that
/// still do not fit are left out (counted in [`TableCells::hidden`]), never cut.
/// `first` scrolls (issue 30 item 15): the first column (the element's number) stays,
/// the `first` columns after it are left out, so every column can be brought into view;
/// a table narrower than the pane spreads its columns over it (up to
/// [`MAX_SPREAD`] more cells each) instead of leaving the right of the pane blank.
/// Formatting only: the values come from the bearing system's view.
pub fn table_cells(view: &View, u: Units, width: usize, first: usize) -> TableCells {
    table_cells_against(view, None, u, width, first)
}

/// What the element table shows against a baseline (issue 30 item 21): its values, or
/// for every result column the change from the baseline's same element, absolute
/// (`ΔQi N`, in the column's unit and decimals) or relative (`ΔQi %`, one decimal).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TableDelta {
    /// The values (no baseline, or `d` cycled back).
    #[default]
    Values,
    /// Δ = now − baseline, in the column's unit.
    Change,
    /// Δ% = 100·(now − baseline)/|baseline|.
    Percent,
}

impl TableDelta {
    /// The next mode `d` cycles to.
    pub fn next(self) -> TableDelta {
        match self {
            TableDelta::Values => TableDelta::Change,
            TableDelta::Change => TableDelta::Percent,
            TableDelta::Percent => TableDelta::Values,
        }
    }
}

/// Whether `base`'s element table compares with `view`'s cell by cell (one system, as
/// many elements called `element`, the same columns), or why not, as `rollbench diff`
/// says it.
pub fn tables_against(view: &View, base: &View, element: &str) -> Result<(), String> {
    if view.system != base.system {
        return Err(format!(
            "not compared: two systems ({} now, {} as the baseline)",
            view.system, base.system
        ));
    }
    match (view.screen_table(), base.screen_table()) {
        (Some(t), Some(b)) => crate::report::diff::tables_compare(b, t, element),
        _ => Err("not compared: no element table".into()),
    }
}

/// A change as a table cell: signed (`+1.25`, `-0.40`), no sign on one that rounds to
/// nothing, as [`fit_number`] fits it to `width`.
fn fit_change(v: f64, prec: usize, width: usize) -> String {
    let plain = fit_number(v, prec, width);
    let rounds_to_zero = !plain.chars().any(|c| matches!(c, '1'..='9'));
    if v > 0.0 && !rounds_to_zero {
        let s = fit_number(v, prec, width.saturating_sub(1));
        format!("+{s}")
    } else {
        plain
    }
}

/// [`table_cells`] with, when `against` holds a baseline's view and a mode other than
/// [`TableDelta::Values`], each result cell the change from the baseline's same cell
/// (the element's number stays; a state column shows the current state; `—` where
/// either side has no number, or for Δ% where the baseline's is 0 and the current's not).
/// The caller checks the tables compare ([`tables_against`]); columns are matched by
/// key, and a column (or row) the baseline lacks shows `—`.
pub fn table_cells_against(
    view: &View,
    against: Option<(&View, TableDelta)>,
    u: Units,
    width: usize,
    first: usize,
) -> TableCells {
    let Some(t) = view.screen_table() else {
        return TableCells::default();
    };
    let against = against
        .filter(|(_, m)| *m != TableDelta::Values)
        .and_then(|(b, m)| Some((b.screen_table()?, m)));
    // The baseline's column of each of this table's (by key; `None`: it has none).
    let matched = against.map_or_else(Vec::new, |(b, _)| matching_columns(t, b));
    let shown: Vec<(usize, Screen)> = t
        .columns
        .iter()
        .enumerate()
        .filter_map(|(i, c)| c.screen.map(|s| (i, s)))
        .collect();
    let total_columns = shown.len();
    let first = first.min(total_columns.saturating_sub(2));
    let shown: Vec<(usize, Screen)> = shown
        .iter()
        .take(1)
        .chain(shown.iter().skip(1 + first))
        .copied()
        .collect();
    // The columns differenced against the baseline: results, not the row's name or a
    // state.
    let differenced: Vec<bool> = shown
        .iter()
        .map(|&(i, s)| {
            against.is_some()
                && !matches!(s.display, Display::Choice(_))
                && t.columns.get(i).is_some_and(|c| !names_the_row(c.key))
        })
        .collect();
    let values: Vec<Vec<Option<f64>>> = t
        .rows
        .iter()
        .enumerate()
        .map(|(r, row)| {
            shown
                .iter()
                .zip(&differenced)
                .map(|(&(i, s), &diff)| {
                    let at = |row: &Vec<Option<f64>>, k: usize| {
                        row.get(k)
                            .copied()
                            .flatten()
                            .map(|v| s.display.convert(v, u))
                    };
                    let now = at(row, i);
                    match against {
                        Some((b, mode)) if diff => {
                            let base = matched
                                .get(i)
                                .copied()
                                .flatten()
                                .and_then(|k| at(b.rows.get(r)?, k));
                            match mode {
                                TableDelta::Percent => percent_change(base, now),
                                _ => change(base, now),
                            }
                        }
                        _ => now,
                    }
                })
                .collect()
        })
        .collect();
    // A column's decimals: a percentage has one.
    let precision = |c: usize, s: &Screen| match against {
        Some((_, TableDelta::Percent)) if differenced[c] => 1,
        _ => s.precision,
    };
    let headers: Vec<String> = shown
        .iter()
        .enumerate()
        .map(|(c, (_, s))| match against {
            Some((_, TableDelta::Percent)) if differenced[c] => format!("Δ{} %", s.label),
            Some(_) if differenced[c] => format!("Δ{}", s.display.header(s.label, u)),
            _ => s.display.header(s.label, u),
        })
        .collect();
    // A change is signed; a value is not.
    let format_cell = |c: usize, v: f64, prec: usize, w: usize| {
        if differenced[c] {
            fit_change(v, prec, w)
        } else {
            fit_number(v, prec, w)
        }
    };
    let natural: Vec<usize> = shown
        .iter()
        .enumerate()
        .map(|(c, (_, s))| {
            let cells = values.iter().map(|r| match r.get(c).copied().flatten() {
                Some(v) => match s.display.choice(v) {
                    Some(name) => name.chars().count(),
                    None => format_cell(c, v, precision(c, s), usize::MAX)
                        .chars()
                        .count(),
                },
                None => DASH.chars().count(),
            });
            cells
                .chain(std::iter::once(
                    headers.get(c).map_or(0, |h| h.chars().count()),
                ))
                .max()
                .unwrap_or(0)
        })
        .collect();
    // A state name is never shortened: its floor is its natural width.
    let floor: Vec<usize> = headers
        .iter()
        .zip(&natural)
        .zip(&shown)
        .map(|((h, &n), (_, s))| match s.display {
            crate::bearings::view::Display::Choice(_) => n,
            _ => h.chars().count().max(MIN_NUMBER_WIDTH).min(n),
        })
        .collect();
    let mut widths = natural.clone();
    // Two spaces between columns when the natural widths allow it, else one.
    let gap = if natural.iter().sum::<usize>() + 2 * natural.len().saturating_sub(1) <= width {
        2
    } else {
        1
    };
    let total = |w: &[usize]| w.iter().sum::<usize>() + gap * w.len().saturating_sub(1);
    // The widest (above its floor) gives way first, one cell at a time.
    while total(&widths) > width {
        let slack = widths
            .iter()
            .zip(&floor)
            .enumerate()
            .filter(|(_, (w, f))| w > f)
            .max_by_key(|(_, (w, f))| **w - **f)
            .map(|(i, _)| i);
        match slack.and_then(|i| widths.get_mut(i)) {
            Some(w) => *w -= 1,
            None => break,
        }
    }
    let mut n = widths.len();
    while n > 0 && total(&widths[..n]) > width {
        n -= 1;
    }
    // Room to spare: spread the columns over the pane (numbers are right-aligned, so the
    // extra cells go before them).
    if n == widths.len() && n > 0 {
        let spare = width.saturating_sub(total(&widths)) / n;
        for w in &mut widths {
            *w += spare.min(MAX_SPREAD);
        }
    }
    let columns = headers
        .iter()
        .zip(&widths)
        .take(n)
        .map(|(h, &w)| Column {
            header: h.clone(),
            width: w as u16,
        })
        .collect();
    let rows = values
        .iter()
        .map(|row| {
            shown
                .iter()
                .zip(&widths)
                .take(n)
                .enumerate()
                .map(|(c, ((_, s), &w))| match row.get(c).copied().flatten() {
                    Some(v) => match s.display.choice(v) {
                        Some(name) => name.to_string(),
                        None => format_cell(c, v, precision(c, s), w),
                    },
                    None => DASH.to_string(),
                })
                .collect()
        })
        .collect();
    TableCells {
        columns,
        rows,
        hidden: total_columns - n,
        gap: gap as u16,
        total: total_columns,
        range: [
            if n > 1 { 2 + first } else { 1 },
            if n > 1 { 1 + first + (n - 1) } else { n },
        ],
        first,
    }
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
    pub series: Vec<(String, Vec<(f64, f64)>)>,
    /// X bounds.
    pub x_bounds: [f64; 2],
    /// Y bounds (0 to a rounded-up maximum).
    pub y_bounds: [f64; 2],
    /// The deck's operating value on the x axis, drawn as a vertical marker when it lies
    /// within [`ChartSeries::x_bounds`] (issue 30 item 19).
    pub operating: Option<Operating>,
    /// The baseline's same series (issue 30 item 21), drawn dimmed under
    /// [`ChartSeries::series`]; empty: no baseline, or its chart is not this one.
    pub baseline: Vec<(String, Vec<(f64, f64)>)>,
}

/// The deck's operating value on a chart's x axis, in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct Operating {
    /// The value, display units of the x axis.
    pub x: f64,
    /// The legend's name with the value and unit (`deck 12000 rpm`).
    pub name: String,
}

impl Operating {
    /// The marker named `label` at `x` (display units, unit `unit`), with as many
    /// decimals as its size needs to read back to about 0.1 %.
    pub fn new(label: &str, x: f64, unit: &str) -> Operating {
        let prec = match x.abs() {
            m if m >= 100.0 || m == 0.0 => 0,
            m if m >= 10.0 => 1,
            m if m >= 1.0 => 2,
            _ => 4,
        };
        let value = fixed(x, prec);
        let name = if unit.is_empty() {
            format!("{label} {value}")
        } else {
            format!("{label} {value} {unit}")
        };
        Operating { x, name }
    }

    /// True when the marker lies on an axis spanning `b`.
    pub fn within(&self, b: [f64; 2]) -> bool {
        self.x >= b[0].min(b[1]) && self.x <= b[0].max(b[1])
    }
}

/// `title` with the note that the operating marker is off an x axis spanning `b`
/// (issue 30 item 19: say so when the deck's value is not in the range drawn).
fn note_off_axis(title: String, op: Option<&Operating>, b: [f64; 2]) -> String {
    match op {
        Some(o) if !o.within(b) => {
            let note = format!("{} off the axis", o.name);
            if title.is_empty() {
                note
            } else {
                format!("{title} · {note}")
            }
        }
        _ => title,
    }
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

/// A chart title that fits `room` characters without cutting anything: the whole title,
/// else its longest leading run of clauses (ending before a ", ", " (" or " · ", with
/// its parentheses balanced) that fits, else (a title without digits) its leading
/// whole words and "…", else nothing. A clause holds a number with its
/// unit ("contacts slide 0.00–2.18 m/s"), so a title is never cut inside one: the pane
/// border cut "… 2.18 m/s" to "… 2.18 m" at 60 columns.
pub fn fit_title(title: &str, room: usize) -> String {
    if title.chars().count() <= room {
        return title.to_string();
    }
    let mut best = "";
    for sep in [", ", " (", " · "] {
        for (at, _) in title.match_indices(sep) {
            let head = &title[..at];
            let balanced = head.matches('(').count() == head.matches(')').count();
            if balanced && head.chars().count() <= room && head.len() > best.len() {
                best = head;
            }
        }
    }
    if best.is_empty() && !title.chars().any(|c| c.is_ascii_digit()) {
        // Words only (no number to cut): as many whole words as fit, then "…".
        let mut head = String::new();
        for w in title.split_whitespace() {
            let next = if head.is_empty() {
                w.to_string()
            } else {
                format!("{head} {w}")
            };
            if next.chars().count() + 1 > room {
                break;
            }
            head = next;
        }
        return if head.is_empty() {
            head
        } else {
            format!("{head}…")
        };
    }
    best.to_string()
}

/// A view's chart in display units `u`: fixed bounds where the chart gives them, else y
/// from 0 (or a round floor of data below 0) to a round ceiling of the data, and x from 0
/// (data on one side of 0) or symmetric about 0.
pub fn chart_series(c: &Chart, u: Units) -> ChartSeries {
    let series: Vec<(String, Vec<(f64, f64)>)> = c
        .series
        .iter()
        .map(|s| {
            let yd = s.display.unwrap_or(c.y.display);
            let pts = s
                .points
                .iter()
                .map(|&(x, y)| (c.x.display.convert(x, u), yd.convert(y, u)))
                .collect();
            // A series in its own unit names it in the legend.
            let name = match s.display {
                Some(d) if !d.unit(u).is_empty() => format!("{} {}", s.name, d.unit(u)),
                _ => s.name.to_string(),
            };
            (name, pts)
        })
        .collect();
    let ymax = series
        .iter()
        .flat_map(|s| s.1.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    // Data below zero (a velocity in a phase plane, a torque that changes sign) gets a
    // round floor too: the axis fits what is drawn (issue 30 item 1's rule).
    let ymin = series
        .iter()
        .flat_map(|s| s.1.iter().map(|p| p.1))
        .filter(|y| y.is_finite())
        .fold(0.0, f64::min);
    let y_floor = if ymin < 0.0 {
        -nice_ceiling(-ymin)
    } else {
        0.0
    };
    let y_top = if ymax > 0.0 || ymin >= 0.0 {
        nice_ceiling(ymax)
    } else {
        0.0
    };
    let xs = || series.iter().flat_map(|s| s.1.iter().map(|p| p.0));
    let xmax = xs().map(f64::abs).fold(0.0, f64::max);
    let xmax = if xmax > 0.0 { xmax } else { 1.0 };
    // Data on one side of zero (speeds, times) from 0; else symmetric about 0.
    let x_auto = if xs().all(|x| x >= 0.0) {
        [0.0, nice_ceiling(xmax)]
    } else {
        [-xmax, xmax]
    };
    // Bounds are given in SI, like the points.
    let x_bounds =
        c.x.bounds
            .map_or(x_auto, |b| b.map(|v| c.x.display.convert(v, u)));
    let operating = c
        .operating
        .map(|o| Operating::new(o.label, c.x.display.convert(o.x, u), c.x.display.unit(u)));
    ChartSeries {
        title: note_off_axis(c.title_in(u).to_string(), operating.as_ref(), x_bounds),
        x_label: c.x.display.header(c.x.label, u),
        y_label: c.y.display.header(c.y.label, u),
        series,
        x_bounds,
        y_bounds: c
            .y
            .bounds
            .map_or([y_floor, y_top], |b| b.map(|v| c.y.display.convert(v, u))),
        operating,
        baseline: Vec::new(),
    }
}

/// Whether `b` draws what `c` draws — the same axes (quantity and unit) and series — so
/// one can be laid over the other. Titles may differ: they carry each design's numbers.
fn same_chart(c: &Chart, b: &Chart) -> bool {
    let axis = |a: &crate::bearings::view::ChartAxis| (a.label, a.display);
    let names = |c: &Chart| {
        c.series
            .iter()
            .map(|s| (s.name, s.display))
            .collect::<Vec<_>>()
    };
    axis(&c.x) == axis(&b.x) && axis(&c.y) == axis(&b.y) && names(c) == names(b)
}

/// [`chart_panels`] with, when `base` is the baseline's same chart ([`same_chart`]), its
/// series in each panel's [`ChartSeries::baseline`] and the panel's bounds widened to
/// hold both designs (issue 30 item 21: charts overlay the baseline, dimmed). A chart
/// of another kind gets no overlay.
pub fn chart_panels_against(c: &Chart, base: Option<&Chart>, u: Units) -> Vec<ChartSeries> {
    let mut panels = chart_panels(c, u);
    let Some(b) = base.filter(|b| same_chart(c, b)) else {
        return panels;
    };
    let theirs = chart_panels(b, u);
    if theirs.len() != panels.len() {
        return panels;
    }
    let union = |a: [f64; 2], b: [f64; 2]| [a[0].min(b[0]), a[1].max(b[1])];
    for (p, t) in panels.iter_mut().zip(theirs) {
        p.x_bounds = union(p.x_bounds, t.x_bounds);
        p.y_bounds = union(p.y_bounds, t.y_bounds);
        p.baseline = t.series;
    }
    panels
}

/// Chart `c` in display units `u` as panels sharing one x axis, one per y unit (issue 30
/// item 1: one unit per axis): the axis's own series first, then each series carrying
/// its own [`Display`] (the ball's heat beside its ω_t) in a panel whose y axis is that
/// series' quantity and unit. Every panel's x bounds are the whole chart's, so the
/// panels line up; a chart with one unit is one panel, equal to [`chart_series`].
pub fn chart_panels(c: &Chart, u: Units) -> Vec<ChartSeries> {
    let whole = chart_series(c, u);
    let mut groups: Vec<Option<Display>> = Vec::new();
    for s in &c.series {
        // A series whose own display is the axis's is on the axis.
        let key = s.display.filter(|d| *d != c.y.display);
        if !groups.contains(&key) {
            groups.push(key);
        }
    }
    if groups.len() <= 1 {
        return vec![whole];
    }
    groups
        .iter()
        .enumerate()
        .map(|(k, key)| {
            let members = c
                .series
                .iter()
                .filter(|s| s.display.filter(|d| *d != c.y.display) == *key);
            let sub = Chart {
                title: String::new(),
                title_us: None,
                x: c.x.clone(),
                y: match key {
                    None => c.y.clone(),
                    // The panel's axis is named after its (first) series, in its unit.
                    Some(d) => crate::bearings::view::ChartAxis {
                        label: members.clone().next().map_or("", |s| s.name),
                        display: *d,
                        bounds: None,
                    },
                },
                series: members
                    .map(|s| crate::bearings::view::Series {
                        display: None,
                        ..s.clone()
                    })
                    .collect(),
                per_element: c.per_element,
                operating: c.operating,
            };
            let mut p = chart_series(&sub, u);
            p.x_bounds = whole.x_bounds;
            if k == 0 {
                p.title = whole.title.clone();
            }
            p
        })
        .collect()
}

/// A sweep pane's chart in display units `u`: each output against the swept key (the
/// key's own unit), divided by its value at the first solved point when the plan
/// normalises; with the x of the plan's marker (the first point where the marker output
/// is positive) and a progress note (`"12/21 points"`, failures counted).
pub fn sweep_series(p: &PlanProgress, u: Units) -> (ChartSeries, Option<f64>, String) {
    let x_of = |pt: &PlanPoint| p.x_quantity.map_or(pt.value, |q| q.from_si(pt.x_si, u));
    let series: Vec<(&'static str, Vec<(f64, f64)>)> = p
        .plan
        .outputs
        .iter()
        .map(|&name| {
            let label = p
                .points
                .iter()
                .flat_map(|pt| pt.outputs.iter())
                .find(|o| o.name == name)
                .map_or(name, |o| o.label);
            let base = p
                .points
                .iter()
                .find_map(|pt| pt.output(name))
                .filter(|b| *b != 0.0 && b.is_finite());
            let pts = p
                .points
                .iter()
                .filter_map(|pt| {
                    let o = pt.outputs.iter().find(|o| o.name == name)?;
                    let v = o.value?;
                    let y = match (p.plan.normalise, base) {
                        (true, Some(b)) => v / b,
                        (true, None) => return None,
                        (false, _) => o.quantity.from_si(v, u),
                    };
                    y.is_finite().then_some((x_of(pt), y))
                })
                .collect();
            (label, pts)
        })
        .collect();
    let marker = p.plan.marker.and_then(|(name, _)| {
        p.points
            .iter()
            .find(|pt| pt.output(name).is_some_and(|v| v > 0.0))
            .map(x_of)
    });
    let xs: Vec<f64> = p
        .plan
        .values
        .iter()
        .map(|&v| {
            // The planned values in display units (points not solved yet included), so
            // the axis does not jump while the sweep fills in.
            p.x_quantity
                .map_or(v, |q| q.from_si(q.to_si(v, p.deck_units), u))
        })
        .collect();
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let x_bounds = if lo.is_finite() && hi > lo {
        [lo, hi]
    } else {
        [0.0, 1.0]
    };
    let ys = || series.iter().flat_map(|s| s.1.iter().map(|q| q.1));
    let ymax = ys().fold(0.0, f64::max);
    // Normalised curves sit near 1: frame them in steps of 0.05 around their range so a
    // 10 % fall is visible; absolute ones from 0.
    let y_bounds = if p.plan.normalise {
        let lo = ys().fold(f64::INFINITY, f64::min);
        let (lo, hi) = if lo.is_finite() {
            ((lo * 20.0).floor() / 20.0, (ymax * 20.0).ceil() / 20.0)
        } else {
            (0.0, 1.0)
        };
        if hi > lo {
            [lo, hi]
        } else {
            [lo - 0.05, hi + 0.05]
        }
    } else {
        [0.0, nice_ceiling(ymax * 1.05)]
    };
    let unit = p.x_unit[usize::from(u == Units::Us)];
    let x_label = if unit.is_empty() {
        p.x_label.to_string()
    } else {
        format!("{} {unit}", p.x_label)
    };
    let y_label = if p.plan.normalise {
        "÷ first point".to_string()
    } else {
        "value".to_string()
    };
    // The deck's own value of the swept key (issue 30 item 19), converted as the plan's
    // values are.
    let operating = p.deck_value.map(|(v, si)| {
        let x = p.x_quantity.map_or(v, |q| q.from_si(si, u));
        Operating::new("deck", x, unit)
    });
    let failed = p.points.iter().filter(|pt| pt.failure.is_some()).count();
    let mut note = format!("{}/{} points", p.points.len(), p.plan.values.len());
    if failed > 0 {
        note.push_str(&format!(", {failed} failed"));
    }
    (
        ChartSeries {
            title: note_off_axis(p.plan.title.clone(), operating.as_ref(), x_bounds),
            x_label,
            y_label,
            series: series
                .into_iter()
                .map(|(n, v)| (n.to_string(), v))
                .collect(),
            x_bounds,
            y_bounds,
            operating,
            baseline: Vec::new(),
        },
        marker,
        note,
    )
}

/// The first failed point of a sweep and why, the swept value in display units
/// (`first failure at 42500 rpm: …`), as the CLI's row gives it; `None` when none failed
/// (issue 30 item 17: the pane said "4 failed" without the reason).
pub fn sweep_first_failure(p: &PlanProgress, u: Units) -> Option<String> {
    let pt = p.points.iter().find(|pt| pt.failure.is_some())?;
    let x = p.x_quantity.map_or(pt.value, |q| q.from_si(pt.x_si, u));
    let unit = p.x_unit[usize::from(u == Units::Us)];
    let value = crate::deck::format_short(x);
    let at = if unit.is_empty() {
        value
    } else {
        format!("{value} {unit}")
    };
    Some(format!(
        "first failure at {} = {at}: {}",
        p.plan.key,
        pt.failure.as_deref().unwrap_or_default()
    ))
}

/// One node of the thermal pane's list, display units.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct NodeRow {
    /// Node name.
    pub name: String,
    /// Steady temperature.
    pub steady: f64,
    /// True for a boundary (given) temperature.
    pub fixed: bool,
    /// The node's limit, if any.
    pub limit: Option<f64>,
    /// Time to reach it in the transient, s.
    pub time_to_limit_s: Option<f64>,
}

/// What the thermal pane shows, display units. Built by [`thermal_view`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThermalView {
    /// Every node, network order.
    pub nodes: Vec<NodeRow>,
    /// The selected node (index into `nodes`): the plotted one.
    pub selected: usize,
    /// True when the selection is the default, the node hottest at the end of the
    /// transient (or in the steady state without one).
    pub selected_is_hottest: bool,
    /// Temperature unit label (°C or °F).
    pub temperature_unit: String,
    /// The selected node's transient: (time s, temperature); empty without a transient.
    pub series: Vec<(f64, f64)>,
}

impl ThermalView {
    /// The selected node.
    pub fn node(&self) -> Option<&NodeRow> {
        self.nodes.get(self.selected)
    }

    /// The one-line account of the selected node's transient: start and end temperature,
    /// the span, and its limit (reached when, or not).
    pub fn summary(&self) -> String {
        let Some(n) = self.node() else {
            return "no nodes".into();
        };
        let u = &self.temperature_unit;
        // "Hottest" says when (issue 30 item 13): the default node is the hottest at the
        // end of the transient, which need not be the hottest in the steady-state table.
        let which = match (self.selected_is_hottest, self.series.is_empty()) {
            (false, _) => "",
            (true, false) => " (hottest at the end of the transient)",
            (true, true) => " (hottest in the steady state)",
        };
        // The chart's legend is hidden on small panes: the line names the limit line's
        // and the marker's glyphs (issue 30 item 13).
        let limit = match (n.limit, n.time_to_limit_s) {
            (Some(l), Some(t)) => format!(
                " · limit {} {u} (── line), reached at {} s (█)",
                fixed(l, 1),
                fixed(t, 1)
            ),
            (Some(l), None) => format!(" · limit {} {u} (── line) not reached", fixed(l, 1)),
            (None, _) => " · no limit".into(),
        };
        match (self.series.first(), self.series.last()) {
            (Some(&(t0, a)), Some(&(t1, b))) => format!(
                "{}{which}: {} → {} {u} over {} s{limit}",
                n.name,
                fixed(a, 1),
                fixed(b, 1),
                fixed(t1 - t0, 0)
            ),
            _ => format!(
                "{}{which}: steady {} {u}{limit} (no transient)",
                n.name,
                fixed(n.steady, 1)
            ),
        }
    }
}

/// The index of the node hottest at the end of the transient, else in the steady state.
pub fn hottest_node(th: &ThermalResults) -> Option<usize> {
    let last = |i: usize| -> f64 {
        th.transient
            .as_ref()
            .and_then(|tr| tr.nodes.get(i))
            .and_then(|n| n.temperature_c.last().copied())
            .or_else(|| th.steady.get(i).map(|n| n.temperature_c))
            .unwrap_or(f64::MIN)
    };
    (0..th.steady.len()).max_by(|&a, &b| last(a).total_cmp(&last(b)))
}

/// The thermal pane's data; `node` picks the plotted node (`None`: the hottest; out of
/// range: the last).
pub fn thermal_view(th: &ThermalResults, u: Units, node: Option<usize>) -> ThermalView {
    let (conv, unit): (fn(f64) -> f64, &str) = match u {
        Units::Si => (|c| c, "°C"),
        Units::Us => (|c| c * FAHRENHEIT_PER_KELVIN + 32.0, "°F"),
    };
    let transient = |i: usize| th.transient.as_ref().and_then(|tr| tr.nodes.get(i));
    let nodes: Vec<NodeRow> = th
        .steady
        .iter()
        .enumerate()
        .map(|(i, n)| NodeRow {
            name: n.name.clone(),
            steady: conv(n.temperature_c),
            fixed: n.fixed,
            limit: transient(i).and_then(|t| t.limit_c).map(conv),
            time_to_limit_s: transient(i).and_then(|t| t.time_to_limit_s),
        })
        .collect();
    let hottest = hottest_node(th).unwrap_or(0);
    let selected = node.map_or(hottest, |i| i.min(nodes.len().saturating_sub(1)));
    let series = match (&th.transient, transient(selected)) {
        (Some(tr), Some(n)) => tr
            .time_s
            .iter()
            .zip(&n.temperature_c)
            .map(|(&t, &c)| (t, conv(c)))
            .collect(),
        _ => Vec::new(),
    };
    ThermalView {
        nodes,
        selected,
        selected_is_hottest: node.is_none(),
        temperature_unit: unit.to_string(),
        series,
    }
}

/// One row of bars of a stepper step, display units.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BarRow {
    /// Row label.
    pub label: &'static str,
    /// Rows of one group share a full scale.
    pub group: usize,
    /// Colour slot (0 inner, 1 outer).
    pub side: usize,
    /// Decimals of the group's full-scale value.
    pub precision: usize,
    /// Unit label.
    pub unit: &'static str,
    /// Values, display units.
    pub values: Vec<f64>,
}

/// One step of the element stepper, formatted.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepView {
    /// Label/value lines: iteration numbers, displacements, residuals.
    pub lines: Vec<(String, String)>,
    /// Bar rows (loads and approaches along the element).
    pub bars: Vec<BarRow>,
}

/// One line per recorded step for the stepper's history list: step number (1-based),
/// outer/inner iteration and the residuals in their display units.
pub fn trace_rows(t: &Trace, u: Units) -> Vec<String> {
    t.steps
        .iter()
        .enumerate()
        .map(|(i, step)| {
            let its: Vec<String> = step.iteration.iter().map(|n| format!("{n:>2}")).collect();
            let mut row = format!("{:>3}  {} ", i + 1, its.join("/"));
            for (c, v) in t.residuals.iter().zip(&step.residuals) {
                row.push_str(&format!(" {:>10}", residual(c.display.convert(*v, u))));
            }
            row
        })
        .collect()
}

/// Header of [`trace_rows`].
pub fn trace_header(t: &Trace, u: Units) -> String {
    let width = 3 * t.iterations.len().max(1) - 1;
    let mut h = format!("{:>3}  {:<width$} ", "#", "it");
    for c in &t.residuals {
        h.push_str(&format!(" {:>10}", c.display.header(c.label, u)));
    }
    h
}

/// Formats trace step `step` (0-based); `None` when out of range.
pub fn trace_step(t: &Trace, step: usize, u: Units) -> Option<StepView> {
    let s = t.steps.get(step)?;
    let lines = s
        .lines
        .iter()
        .map(|l| {
            let values: Vec<String> = l
                .values
                .iter()
                .map(|&v| match l.format {
                    TraceFormat::Counts => format!("{}", v.round() as i64),
                    TraceFormat::Signed(prec) => signed(l.display.convert(v, u), prec),
                    TraceFormat::Residual => residual(l.display.convert(v, u)),
                })
                .collect();
            let sep = match l.format {
                TraceFormat::Counts => " / ",
                _ => ", ",
            };
            (l.display.header(l.label, u), values.join(sep))
        })
        .collect();
    let bars = s
        .bars
        .iter()
        .map(|b| BarRow {
            label: b.label,
            group: b.group,
            side: b.side,
            precision: b.precision,
            unit: b.display.unit(u),
            values: b.values.iter().map(|&v| b.display.convert(v, u)).collect(),
        })
        .collect();
    Some(StepView { lines, bars })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The value a cell says, and half its last digit's place (the precision it claims):
    /// `171.3k` → (171300, 50); `1.7e5` → (170000, 5000); `-12` → (−12, 0.5).
    fn read_back(cell: &str) -> Option<(f64, f64)> {
        let (body, mult) = match cell.chars().last()? {
            'k' => (&cell[..cell.len() - 1], 1e3),
            'M' => (&cell[..cell.len() - 1], 1e6),
            'G' => (&cell[..cell.len() - 1], 1e9),
            'T' => (&cell[..cell.len() - 1], 1e12),
            _ => (cell, 1.0),
        };
        let (mantissa, exp) = match body.split_once('e') {
            Some((m, e)) => (m, e.parse::<i32>().ok()?),
            None => (body, 0),
        };
        let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
        let value = body.parse::<f64>().ok()? * mult;
        let half_ulp = 0.5 * 10f64.powi(exp - decimals) * mult;
        Some((value, half_ulp))
    }

    proptest! {
        /// Every cell fits its width and reads back as its value within the precision it
        /// shows, or is marked `…`: never a number with digits or its sign dropped.
        #[test]
        fn cells_read_back_or_are_marked(
            mantissa in -1.0f64..1.0,
            exp in -8i32..16,
            prec in 0usize..5,
            width in 1usize..12,
        ) {
            let v = mantissa * 10f64.powi(exp);
            let cell = fit_number(v, prec, width);
            prop_assert!(cell.chars().count() <= width, "{cell:?} wider than {width}");
            if cell != "…" {
                let (x, half_ulp) = read_back(&cell)
                    .ok_or_else(|| TestCaseError::fail(format!("{cell:?} unreadable")))?;
                prop_assert!(
                    (x - v).abs() <= half_ulp * (1.0 + 1e-9) + 1e-300,
                    "{v} shown as {cell:?} (reads {x} ± {half_ulp})"
                );
            }
        }
    }

    /// The issue's cases: the industrial roller 1's 171333.6 N in a 7-wide column, and
    /// −55324 at 60 columns: the digits and the sign survive.
    #[test]
    fn cut_numbers_of_the_issue() {
        assert_eq!(fit_number(171_333.6, 1, 8), "171333.6");
        assert_eq!(fit_number(171_333.6, 1, 7), "171334");
        assert_eq!(fit_number(171_333.6, 1, 5), "171k");
        assert_eq!(fit_number(-55_324.0, 0, 5), "-55k");
        assert_eq!(fit_number(-55_324.0, 0, 4), "-55k");
        assert_eq!(fit_number(-55_324.0, 0, 3), "…");
        assert_eq!(fit_number(999_960.0, 0, 5), "1.00M");
        assert_eq!(fit_number(999_960.0, 0, 4), "1.0M");
        assert_eq!(fit_number(1051.8, 1, 4), "1052");
    }
}

#[cfg(test)]
mod fit_title_tests {
    use super::fit_title;

    /// Whole when it fits; else the longest balanced run of clauses that fits; else
    /// nothing: never a number or unit cut in two.
    #[test]
    fn titles_drop_clauses_not_numbers() {
        let t = "curve-1: µ_max 0.0540, contacts slide 0.00–2.18 m/s";
        assert_eq!(fit_title(t, 80), t);
        assert_eq!(fit_title(t, t.chars().count()), t);
        assert_eq!(fit_title(t, t.chars().count() - 1), "curve-1: µ_max 0.0540");
        assert_eq!(fit_title(t, 10), "");
        let d = "heat per ball: 96.30 W mean (time-simulation, oscillating)";
        // The ", oscillating)" cut would leave "(time-simulation" open: skipped.
        assert_eq!(fit_title(d, 55), "heat per ball: 96.30 W mean");
        assert_eq!(fit_title("no separators at all here", 5), "no…");
        assert_eq!(fit_title("no separators at all here", 2), "");
        assert_eq!(fit_title("no separators at all here", 16), "no separators…");
        assert_eq!(fit_title("roller 12 of many", 12), "");
    }
}

#[cfg(test)]
mod series_display_tests {
    use super::{chart_panels, chart_series};
    use crate::bearings::view::{Chart, ChartAxis, Display, Series};
    use crate::units::{Units, BTU_PER_HOUR_PER_WATT};

    /// The y axis fits data below zero: a round floor under the lowest value, a round
    /// ceiling over the highest (0 when every value is negative); data at or above zero
    /// keeps the axis from 0 (every existing chart's look).
    #[test]
    fn the_y_axis_fits_data_below_zero() {
        let chart = |ys: &[f64]| Chart {
            title: "t".into(),
            title_us: None,
            x: ChartAxis {
                label: "x",
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: "y",
                display: Display::Plain,
                bounds: None,
            },
            series: vec![Series {
                name: "s",
                points: ys.iter().map(|&y| (1.0, y)).collect(),
                display: None,
            }],
            per_element: false,
            operating: None,
        };
        let b = |ys: &[f64]| chart_series(&chart(ys), Units::Si).y_bounds;
        assert_eq!(b(&[-354.0, 0.0]), [-500.0, 0.0]);
        assert_eq!(b(&[-3.0, 7.0]), [-5.0, 10.0]);
        assert_eq!(b(&[0.0, 7.0]), [0.0, 10.0]);
        assert_eq!(b(&[1.0, 7.0]), [0.0, 10.0]);
    }

    /// A series with its own display kind (the ball's heat on an ω_t axis) converts by
    /// it and names its unit in the legend; the axis's series and the bounds convert by
    /// the axis (exact arithmetic: one multiplication each).
    #[test]
    fn a_series_in_its_own_unit_converts_and_names_it() {
        let c = Chart {
            title: "t".into(),
            title_us: None,
            x: ChartAxis {
                label: "x",
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: "y",
                display: Display::Plain,
                bounds: None,
            },
            series: vec![
                Series {
                    name: "ω_t rad/s",
                    points: vec![(1.0, 100.0)],
                    display: None,
                },
                Series {
                    name: "heat",
                    points: vec![(1.0, 10.0)],
                    display: Some(Display::Power),
                },
            ],
            per_element: false,
            operating: None,
        };
        let si = chart_series(&c, Units::Si);
        assert_eq!(si.series[1].0, "heat W");
        assert_eq!(si.series[1].1, vec![(1.0, 10.0)]);
        let us = chart_series(&c, Units::Us);
        assert_eq!(us.series[0], ("ω_t rad/s".to_string(), vec![(1.0, 100.0)]));
        assert_eq!(us.series[1].0, "heat Btu/hr");
        assert_eq!(us.series[1].1, vec![(1.0, 10.0 * BTU_PER_HOUR_PER_WATT)]);
    }

    /// Two units make two panels on one x axis (issue 30 item 1): the ω_t panel's axis
    /// is the chart's (−500…0 fits −354), the heat panel's axis is "heat W" (0…50 fits
    /// 40), each holds only its own series, both span the whole chart's x (0…2000 for
    /// data to 1839); one unit stays one panel equal to `chart_series`.
    #[test]
    fn two_units_are_two_panels_on_one_x_axis() {
        let c = Chart {
            title: "t".into(),
            title_us: None,
            x: ChartAxis {
                label: "orbit deg",
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: "ω_t rad/s",
                display: Display::Plain,
                bounds: None,
            },
            series: vec![
                Series {
                    name: "ω_t rad/s",
                    points: vec![(0.0, 0.0), (1839.0, -354.0)],
                    display: None,
                },
                Series {
                    name: "heat",
                    points: vec![(0.0, 0.0), (900.0, 40.0)],
                    display: Some(Display::Power),
                },
            ],
            per_element: false,
            operating: None,
        };
        let p = chart_panels(&c, Units::Si);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].y_label, "ω_t rad/s");
        assert_eq!(p[0].y_bounds, [-500.0, 0.0]);
        assert_eq!(p[0].series.len(), 1);
        assert_eq!(p[0].title, "t");
        assert_eq!(p[1].y_label, "heat W");
        assert_eq!(p[1].y_bounds, [0.0, 50.0]);
        assert_eq!(
            p[1].series,
            vec![("heat".to_string(), vec![(0.0, 0.0), (900.0, 40.0)])]
        );
        assert_eq!(p[0].x_bounds, [0.0, 2000.0]);
        assert_eq!(p[1].x_bounds, [0.0, 2000.0]);
        let us = chart_panels(&c, Units::Us);
        assert_eq!(us[1].y_label, "heat Btu/hr");
        let mut one = c.clone();
        one.series.truncate(1);
        assert_eq!(
            chart_panels(&one, Units::Si),
            vec![chart_series(&one, Units::Si)]
        );
    }
}

/// Issue 30 item 21: for each line of `view.answer` (the current design, B of `d`), its
/// row of the comparison with the baseline (A), matched as `rollbench diff` matches them
/// (section, label and unit, in order); `None` for a name or a line the baseline lacks.
pub fn answer_deltas<'a>(d: &'a Diff, view: &View, u: Units) -> Vec<Option<&'a DiffRow>> {
    let mut used = vec![false; d.outputs.len()];
    view.answer
        .iter()
        .map(|l| {
            if matches!(l.value, AnswerValue::Name(_)) {
                return None;
            }
            let unit = l.display.unit(u);
            let k = d.outputs.iter().enumerate().position(|(k, r)| {
                !used[k] && r.section == l.section && r.quantity == l.label && r.unit == unit
            })?;
            used[k] = true;
            d.outputs.get(k)
        })
        .collect()
}

/// A comparison row as the Summary shows it under a line: `Δ +12.3 N (+4.5 %)`, the
/// difference current − baseline with as many decimals as the line's value shows, and
/// the change relative to the baseline; `None` when either side has no number.
pub fn delta_text(r: &DiffRow, line: &AnswerLine) -> Option<String> {
    let (d, now) = (r.delta()?, r.b?);
    let decimals = match line.display {
        Display::Mrev | Display::Hours => {
            let digits = significant(now, line.precision);
            digits.split_once('.').map_or(0, |(_, f)| f.len())
        }
        _ => line.precision,
    };
    let unit = if r.unit.is_empty() {
        String::new()
    } else {
        format!(" {}", r.unit)
    };
    // No sign on a change that rounds to nothing (`Δ 0.000 (0.0 %)`).
    let sign = |v: f64, prec: usize| {
        let s = fixed(v, prec);
        if s.chars().all(|c| matches!(c, '0' | '.')) {
            s
        } else {
            signed(v, prec)
        }
    };
    let pct = match r.percent() {
        Some(p) => format!("{} %", sign(p, 1)),
        None => "baseline 0".to_string(),
    };
    Some(format!("Δ {}{unit} ({pct})", sign(d, decimals)))
}
