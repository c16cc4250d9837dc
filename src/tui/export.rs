//! Export from the workbench (issue 30 item 20): the focused pane's data as a file, in
//! the display units the pane shows (SI or US, as `u` chose), with the unit of every
//! column in its header. What a pane holds comes from the same view-model functions
//! its renderer draws from (`view_model::chart_panels`, `sweep_series`, `thermal_view`),
//! so the file and the screen cannot disagree; numbers are written at full precision,
//! not as rounded for the screen.
//!
//! | pane | file |
//! |---|---|
//! | element table | every column of the view's table, shown or not: a column the pane shows in its display unit (`Qi lbf`), a CSV-only column in SI under its machine key (`inner_normal_load_n`); a yes/no or state column as its code, the legend in the header |
//! | chart, sweep, job | every series of the chart drawn (the selected element's with `c`): one x and one y column per series, or one shared x column when every series has the same x |
//! | Summary | one row per line: section, quantity, value, unit, where, note |
//! | Thermal | one row per node: steady temperature, boundary, limit, time to limit, end of transient |
//! | Inputs | one row per field: key, label, value as typed in the display units, unit |
//! | text panes, Stepper | the lines as shown (text) |
//!
//! The whole report (`X`) is written by the worker, as `rollbench run` writes it
//! ([`report_format_for`]).

use std::path::{Path, PathBuf};

use crate::bearings::view::{AnswerValue, Display, Table};
use crate::report::csv::csv_number;
use crate::report::Format;
use crate::units::Units;

use super::app::{App, Pane};
use super::view_model::{self, ChartSeries};

/// What a pane export holds: the file's contents and a short account for the status line.
#[derive(Debug, Clone, PartialEq)]
pub struct PaneExport {
    /// The file's contents.
    pub contents: String,
    /// What it is (`"Balls table, 20 rows × 22 columns, US units"`).
    pub what: String,
    /// The file's natural extension (`csv`, or `txt` for a text pane).
    pub extension: &'static str,
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn csv_line(cells: &[String]) -> String {
    let mut l = cells
        .iter()
        .map(|c| csv_field(c))
        .collect::<Vec<_>>()
        .join(",");
    l.push('\n');
    l
}

fn units_word(u: Units) -> &'static str {
    match u {
        Units::Si => "SI units",
        Units::Us => "US units",
    }
}

/// A table, every column: shown columns in display units `u` under the pane's header
/// (`Qi lbf`), CSV-only columns in SI under their key (its unit is its last word); a
/// [`Display::Choice`] column as its code with the names in the header (`skid (0 —; 1
/// yes)`); empty cells where a stage was not run.
pub fn table_csv(t: &Table, u: Units) -> String {
    let headers: Vec<String> = t.columns.iter().map(|c| c.header_in(u)).collect();
    let mut out = csv_line(&headers);
    for row in &t.rows {
        let cells: Vec<String> = t
            .columns
            .iter()
            .enumerate()
            .map(|(i, c)| {
                row.get(i)
                    .copied()
                    .flatten()
                    .map_or(String::new(), |v| csv_number(c.value_in(v, u)))
            })
            .collect();
        out.push_str(&csv_line(&cells));
    }
    out
}

/// A series of a panel: its name, its panel's y axis label, its points.
type NamedSeries<'a> = (String, &'a str, &'a [(f64, f64)]);

/// A chart's panels (display units, as drawn): one shared x column when every series
/// has the same x values, else an x and a y column per series; a series' y header is
/// its name and its panel's y axis (`ω_t · ω_t rad/s`).
pub fn chart_csv(panels: &[ChartSeries]) -> String {
    let series: Vec<NamedSeries> = panels
        .iter()
        .flat_map(|p| {
            p.series
                .iter()
                .map(move |(name, pts)| (name.clone(), p.y_label.as_str(), pts.as_slice()))
        })
        .collect();
    let x_label = panels.first().map_or("x", |p| p.x_label.as_str());
    let shared = series.windows(2).all(|w| {
        w[0].2.len() == w[1].2.len() && w[0].2.iter().zip(w[1].2).all(|(a, b)| a.0 == b.0)
    });
    let y_header = |name: &str, y: &str| {
        if name == y || y.is_empty() {
            name.to_string()
        } else {
            format!("{name} · {y}")
        }
    };
    let mut headers = Vec::new();
    if shared {
        headers.push(x_label.to_string());
        headers.extend(series.iter().map(|s| y_header(&s.0, s.1)));
    } else {
        for s in &series {
            headers.push(format!("{} · {x_label}", s.0));
            headers.push(y_header(&s.0, s.1));
        }
    }
    let mut out = csv_line(&headers);
    let rows = series.iter().map(|s| s.2.len()).max().unwrap_or(0);
    let num = |v: f64| {
        if v.is_finite() {
            csv_number(v)
        } else {
            String::new()
        }
    };
    for r in 0..rows {
        let mut cells = Vec::new();
        if shared {
            cells.push(
                series
                    .first()
                    .and_then(|s| s.2.get(r))
                    .map_or(String::new(), |p| num(p.0)),
            );
            cells.extend(
                series
                    .iter()
                    .map(|s| s.2.get(r).map_or(String::new(), |p| num(p.1))),
            );
        } else {
            for s in &series {
                match s.2.get(r) {
                    Some(p) => {
                        cells.push(num(p.0));
                        cells.push(num(p.1));
                    }
                    None => cells.extend([String::new(), String::new()]),
                }
            }
        }
        out.push_str(&csv_line(&cells));
    }
    out
}

/// The focused pane's data (see the module documentation), or why there is none.
pub fn pane_export(app: &App) -> Result<PaneExport, String> {
    let u = app.display_units;
    let pane = app.focus;
    let title = app.pane_title(pane);
    let no_solution = || format!("nothing to export from {title}: no solution yet");
    let csv = |contents: String, what: String| PaneExport {
        contents,
        what: format!("{what}, {}", units_word(u)),
        extension: "csv",
    };
    let chart = |panels: Vec<ChartSeries>, what: &str| {
        let n: usize = panels.iter().map(|p| p.series.len()).sum();
        let points: usize = panels
            .iter()
            .flat_map(|p| p.series.iter().map(|s| s.1.len()))
            .max()
            .unwrap_or(0);
        csv(
            chart_csv(&panels),
            format!("{what}, {n} series × {points} points"),
        )
    };
    match pane {
        Pane::Inputs => {
            let mut out = csv_line(&["key", "label", "value", "unit"].map(String::from));
            for f in &app.fields {
                out.push_str(&csv_line(&[
                    f.key.to_string(),
                    f.label.to_string(),
                    app.deck.value(f.key, u),
                    app.deck.unit(f.key, u).to_string(),
                ]));
            }
            Ok(csv(out, format!("{title}, {} fields", app.fields.len())))
        }
        Pane::Elements => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let t = view
                .element_table()
                .ok_or_else(|| format!("{title} has no table"))?;
            Ok(csv(
                table_csv(&t, u),
                format!(
                    "{title} table, {} rows × {} columns",
                    t.rows.len(),
                    t.columns.len()
                ),
            ))
        }
        Pane::Chart(n) => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let element = app.chart_laminae && view.element_chart_pane == n;
            let c = if element {
                view.element_charts.get(app.roller_sel)
            } else {
                view.charts.get(n)
            }
            .ok_or_else(|| format!("{title} has no chart"))?;
            let what = if element {
                format!(
                    "{title} chart of {} {}",
                    app.element_name(),
                    app.element_number()
                )
            } else {
                format!("{title} chart")
            };
            Ok(chart(view_model::chart_panels(c, u), &what))
        }
        Pane::Sweep(n) => {
            let (_, _, p) = app
                .sweep
                .as_ref()
                .filter(|(_, pane_n, _)| *pane_n == n)
                .ok_or_else(|| format!("nothing to export from {title}: no point solved yet"))?;
            let (s, _, note) = view_model::sweep_series(p, u);
            Ok(chart(vec![s], &format!("{title} ({note})")))
        }
        Pane::Study => {
            let (_, p) = app
                .study
                .as_ref()
                .filter(|(g, p)| *g == app.generation && p.error.is_none())
                .ok_or_else(|| format!("nothing to export from {title}: not started"))?;
            Ok(PaneExport {
                contents: crate::studies::study::output::csv(&p.result()),
                what: format!(
                    "{title} rows, {} of {} points, as `rollbench study --format csv` writes them (inputs in deck units, outputs SI)",
                    p.rows.len(),
                    p.total
                ),
                extension: "csv",
            })
        }
        Pane::Job(n) => {
            let (_, _, v) = app
                .job
                .as_ref()
                .filter(|(g, pane_n, _)| *pane_n == n && *g == app.generation)
                .ok_or_else(|| format!("nothing to export from {title}: not started"))?;
            let c = v
                .charts
                .first()
                .ok_or_else(|| format!("{title} has no chart to export yet"))?;
            Ok(chart(
                view_model::chart_panels(c, u),
                &format!("{title} chart"),
            ))
        }
        Pane::Summary => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let mut out = csv_line(
                &["section", "quantity", "value", "unit", "where", "note"].map(String::from),
            );
            for a in &view.answer {
                let (value, unit, note) = match &a.value {
                    AnswerValue::Number(v) => (
                        csv_number(a.display.convert(*v, u)),
                        a.display.unit(u).to_string(),
                        String::new(),
                    ),
                    AnswerValue::Name(n) => (n.clone(), String::new(), String::new()),
                    AnswerValue::Absent(why) => (String::new(), String::new(), why.clone()),
                };
                out.push_str(&csv_line(&[
                    a.section.to_string(),
                    a.label.to_string(),
                    value,
                    unit,
                    a.place.clone().unwrap_or_default(),
                    note,
                ]));
            }
            Ok(csv(out, format!("{title}, {} lines", view.answer.len())))
        }
        Pane::Thermal => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let th = view
                .thermal
                .as_ref()
                .ok_or_else(|| format!("{title}: the deck has no thermal network"))?;
            let tv = view_model::thermal_view(th, u, None);
            let t = &tv.temperature_unit;
            let mut out = csv_line(&[
                "node".into(),
                format!("steady {t}"),
                "boundary".into(),
                format!("limit {t}"),
                "time to limit s".into(),
                format!("end of transient {t}"),
            ]);
            for (i, n) in tv.nodes.iter().enumerate() {
                let end = th
                    .transient
                    .as_ref()
                    .and_then(|tr| tr.nodes.get(i))
                    .and_then(|s| s.temperature_c.last())
                    .map(|c| csv_number(Display::Temperature.convert(*c, u)));
                out.push_str(&csv_line(&[
                    n.name.clone(),
                    csv_number(n.steady),
                    crate::bearings::view::flag_word(n.fixed).into(),
                    n.limit.map(csv_number).unwrap_or_default(),
                    n.time_to_limit_s.map(csv_number).unwrap_or_default(),
                    end.unwrap_or_default(),
                ]));
            }
            Ok(csv(out, format!("{title}, {} nodes", tv.nodes.len())))
        }
        Pane::Text(n) => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let b = view
                .texts
                .get(n)
                .ok_or_else(|| format!("{title} has no text"))?;
            let mut contents = format!("{}\n", b.title);
            for l in b.lines(u) {
                contents.push_str(l);
                contents.push('\n');
            }
            Ok(PaneExport {
                contents,
                what: format!("{title} text, {}", units_word(u)),
                extension: "txt",
            })
        }
        Pane::Stepper => {
            let view = app.view.as_deref().ok_or_else(no_solution)?;
            let t = view
                .trace
                .as_ref()
                .ok_or_else(|| format!("{title}: no iterations recorded yet"))?;
            let mut contents = format!("{}\n{}\n", t.label, view_model::trace_header(t, u));
            for l in view_model::trace_rows(t, u) {
                contents.push_str(&l);
                contents.push('\n');
            }
            Ok(PaneExport {
                contents,
                what: format!(
                    "{title} history, {} steps, {}",
                    t.steps.len(),
                    units_word(u)
                ),
                extension: "txt",
            })
        }
    }
}

/// The path the export prompt offers: beside the deck (or in the working directory),
/// `<deck>_<pane>.<ext>` for a pane, `<deck>_report.json` for the report.
pub fn default_path(app: &App, pane: Option<(Pane, &str)>) -> PathBuf {
    let stem = app.path.as_deref().and_then(Path::file_stem).map_or_else(
        || "bearing".to_string(),
        |s| s.to_string_lossy().into_owned(),
    );
    let dir = app
        .path
        .as_deref()
        .and_then(Path::parent)
        .map(Path::to_path_buf)
        .unwrap_or_default();
    let name = match pane {
        Some((p, ext)) => {
            let title: String = app
                .pane_title(p)
                .to_lowercase()
                .chars()
                .map(|c| if c.is_alphanumeric() { c } else { '_' })
                .collect();
            format!("{stem}_{title}.{ext}")
        }
        None => format!("{stem}_report.json"),
    };
    dir.join(name)
}

/// The report format a path asks for by its extension: `.json` JSON, `.csv` CSV (the
/// element table, SI), anything else text (the deck's units), as `rollbench run`.
pub fn report_format_for(path: &Path) -> Format {
    match path
        .extension()
        .map(|e| e.to_string_lossy().to_lowercase())
        .as_deref()
    {
        Some("json") => Format::Json,
        Some("csv") => Format::Csv,
        _ => Format::Text,
    }
}

/// A format's name for the status line.
pub fn format_name(f: Format) -> &'static str {
    match f {
        Format::Json => "JSON",
        Format::Csv => "CSV",
        Format::Text => "text",
    }
}

/// Writes `contents` to `path` through the project's one writer (`files::plan`:
/// checked first, temporary file and rename, never the deck being edited).
pub fn write(path: &Path, deck: Option<&Path>, contents: &[u8]) -> Result<String, String> {
    let inputs: Vec<(&str, &Path)> = deck
        .map(|d| vec![("the deck being edited", d)])
        .unwrap_or_default();
    let plan = crate::files::plan(&[("export", Some(path))], &inputs).map_err(|e| e.to_string())?;
    let written = plan
        .fifo_wait(std::time::Duration::ZERO)
        .commit(&[contents])
        .map_err(|e| e.to_string())?;
    Ok(written
        .first()
        .map_or_else(|| path.display().to_string(), ToString::to_string))
}
