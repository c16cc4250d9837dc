//! Drawing: `impl Widget for &App`. Reads the state only; all solver data goes through
//! [`view_model`]. Named 16-colour palette only, so it looks the same over any SSH link.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{
    Axis, Block, Borders, Cell, Chart, Clear, Dataset, GraphType, Paragraph, Row, StatefulWidget,
    Table, TableState, Widget, Wrap,
};

use super::app::{App, Mode, Pane, PromptKind, SolveState, KEYS, MIN_SIZE};
use super::deck_io;
use super::view_model::{self, DASH};

const ACCENT: Color = Color::Cyan;
const INNER: Color = Color::Cyan;
const OUTER: Color = Color::Yellow;
const DIM: Color = Color::DarkGray;

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
            too_small(area, buf);
            return;
        }
        let [header, body, status, hints] = Layout::vertical([
            Constraint::Length(1),
            Constraint::Min(0),
            Constraint::Length(1),
            Constraint::Length(1),
        ])
        .areas(area);
        render_header(self, header, buf);
        if self.wide() {
            let inputs_w = (body.width * 38 / 100).max(46);
            let [left, right] =
                Layout::horizontal([Constraint::Length(inputs_w), Constraint::Min(0)]).areas(body);
            let [top, bottom] =
                Layout::vertical([Constraint::Percentage(45), Constraint::Min(0)]).areas(right);
            let split = if self.focus == Pane::Stepper { 40 } else { 55 };
            let [chart, side] =
                Layout::horizontal([Constraint::Percentage(split), Constraint::Min(0)])
                    .areas(bottom);
            let panes = self.panes();
            let offered = |p: Pane| panes.contains(&p);
            render_pane(self, Pane::Inputs, left, buf);
            render_pane(self, Pane::Elements, top, buf);
            render_pane(self, self.chart_slot(), chart, buf);
            // The side shows the stepper while it has the focus (or when the system
            // has no thermal pane), else the thermal network.
            if self.focus == Pane::Stepper || !offered(Pane::Thermal) {
                if offered(Pane::Stepper) {
                    render_pane(self, Pane::Stepper, side, buf);
                }
            } else {
                render_pane(self, Pane::Thermal, side, buf);
            }
        } else {
            render_pane(self, self.focus, body, buf);
        }
        render_status(self, status, buf);
        render_hints(self, hints, buf);
        match &self.mode {
            Mode::Help => render_help(self.help_scroll, area, buf),
            Mode::Error => render_error(
                " Error · any key closes, e reopens ",
                self.error.as_deref().unwrap_or(""),
                area,
                buf,
            ),
            Mode::Warnings => {
                let u = self.display_units;
                let text: Vec<String> = self
                    .view
                    .iter()
                    .flat_map(|v| v.warnings.iter().map(|w| format!("⚠ {}", w.text(u))))
                    .collect();
                render_error(" Warnings · any key closes ", &text.join("\n"), area, buf);
            }
            Mode::Prompt { kind, buffer } => render_prompt(*kind, buffer, area, buf),
            Mode::ConfirmQuit => render_confirm(
                "Unsaved changes",
                "s save and quit · y quit without saving · any other key: stay",
                area,
                buf,
            ),
            Mode::ConfirmOverwrite { path } => render_confirm(
                "File exists",
                &format!(
                    "{} exists · y replace it · any other key: choose another name",
                    path.display()
                ),
                area,
                buf,
            ),
            Mode::ConfirmRevert => render_confirm(
                "Revert",
                "y discard unsaved changes and reload the file · any other key: keep",
                area,
                buf,
            ),
            _ => {}
        }
    }
}

fn too_small(area: Rect, buf: &mut Buffer) {
    let text = format!(
        "terminal too small: {}×{}, need {}×{}",
        area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
    );
    Paragraph::new(text)
        .wrap(Wrap { trim: true })
        .style(Style::default().fg(Color::Yellow))
        .render(area, buf);
}

fn render_header(app: &App, area: Rect, buf: &mut Buffer) {
    let wide = area.width >= 100;
    let file = app
        .path
        .as_ref()
        .and_then(|p| p.file_name())
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "(no file)".into());
    // The right side, most to least informative: the first that fits with the full tab
    // labels is drawn; else the tabs shrink to numbers (the focused one keeps its title)
    // so the file, the unsaved mark and the units always show.
    let right = |detail: String| {
        let mut r = vec![Span::raw(file.clone())];
        if app.unsaved() {
            r.push(Span::styled(" [+]", Style::default().fg(Color::Yellow)));
        }
        r.push(Span::raw(detail));
        r.push(Span::styled(
            format!(" {} ", deck_io::units_label(app.display_units)),
            Style::default().fg(Color::Black).bg(Color::Gray),
        ));
        Line::from(r)
    };
    let tabs = |compact: bool| {
        let mut spans = Vec::new();
        if wide && !compact {
            spans.push(Span::styled(
                " rollbench ",
                Style::default()
                    .fg(Color::Black)
                    .bg(ACCENT)
                    .add_modifier(Modifier::BOLD),
            ));
        }
        for (i, p) in app.panes().iter().enumerate() {
            let label = if compact && *p != app.focus {
                format!(" {} ", i + 1)
            } else {
                format!(" {}:{} ", i + 1, app.pane_title(*p))
            };
            let style = if *p == app.focus {
                Style::default().fg(Color::Black).bg(Color::White)
            } else if app.visible(*p) {
                Style::default().fg(Color::White)
            } else {
                Style::default().fg(DIM)
            };
            spans.push(Span::styled(label, style));
        }
        Line::from(spans)
    };
    let mut details = Vec::new();
    if wide {
        details.push(format!(" · {} · {}", app.deck.name(), app.deck.system_id()));
        details.push(format!(" · {}", app.deck.name()));
    }
    details.push(String::new());
    let mut choice = None;
    'outer: for compact in [false, true] {
        let t = tabs(compact);
        for d in &details {
            let r = right(d.clone());
            if t.width() + 1 + r.width() <= area.width as usize {
                choice = Some((t, r));
                break 'outer;
            }
        }
    }
    let (t, r) = choice.unwrap_or_else(|| (tabs(true), Line::default()));
    t.render(area, buf);
    let w = (r.width() as u16).min(area.width);
    if w > 0 {
        let rr = Rect {
            x: area.x + area.width - w,
            width: w,
            ..area
        };
        r.render(rr, buf);
    }
}

fn pane_block(app: &App, pane: Pane, extra: &str) -> Block<'static> {
    let focused = app.focus == pane;
    let style = if focused {
        Style::default().fg(ACCENT).add_modifier(Modifier::BOLD)
    } else {
        Style::default().fg(DIM)
    };
    Block::default()
        .borders(Borders::ALL)
        .border_style(style)
        .title(Span::styled(
            format!(" {}{} ", app.pane_title(pane), extra),
            style,
        ))
}

fn render_pane(app: &App, pane: Pane, area: Rect, buf: &mut Buffer) {
    match pane {
        Pane::Inputs => render_inputs(app, area, buf),
        Pane::Elements => render_rollers(app, area, buf),
        Pane::Chart(n) => render_load(app, n, area, buf),
        Pane::Thermal => render_thermal(app, area, buf),
        Pane::Stepper => render_stepper(app, area, buf),
        Pane::Text(n) => render_text(app, n, area, buf),
        Pane::Sweep(n) => render_sweep(app, n, area, buf),
    }
}

/// A text pane: block `n` of the view's texts in the display units, wrapped (a line
/// wider than the pane moves to the next line; nothing is cut).
fn render_text(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let block = pane_block(app, Pane::Text(n), stale_note(app));
    let inner = block.inner(area);
    block.render(area, buf);
    let Some(view) = app.view.as_deref() else {
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    };
    let lines: Vec<Line> = view
        .texts
        .get(n)
        .map(|t| {
            t.lines(app.display_units)
                .iter()
                .map(|l| Line::raw(l.clone()))
                .collect()
        })
        .unwrap_or_default();
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .render(inner, buf);
}

fn truncate(s: &str, w: usize) -> String {
    if s.chars().count() <= w {
        format!("{s:<w$}")
    } else {
        let mut t: String = s.chars().take(w.saturating_sub(1)).collect();
        t.push('…');
        t
    }
}

fn render_inputs(app: &App, area: Rect, buf: &mut Buffer) {
    let block = pane_block(
        app,
        Pane::Inputs,
        &format!(" [{}]", deck_io::units_label(app.display_units)),
    );
    let inner = block.inner(area);
    block.render(area, buf);
    // The bottom lines say what the selected field is (its help) or what is searched.
    let [inner, about] = Layout::vertical([Constraint::Min(0), Constraint::Length(2)]).areas(inner);
    let w = inner.width as usize;
    let value_w = 10usize;
    // Labels as wide as the longest, as far as the values and units leave room.
    let unit_w = app
        .fields
        .iter()
        .map(|f| app.deck.unit(f.key, app.display_units).chars().count())
        .max()
        .unwrap_or(0);
    let longest = app
        .fields
        .iter()
        .map(|f| f.label.chars().count())
        .max()
        .unwrap_or(8);
    let label_w = longest.min(w.saturating_sub(value_w + unit_w + 3)).max(8);
    let mut lines: Vec<Line> = Vec::new();
    let mut sel_line = 0usize;
    let mut group = "";
    for (i, f) in app.fields.iter().enumerate() {
        if f.group != group {
            group = f.group;
            lines.push(Line::styled(
                format!("[{group}]"),
                Style::default()
                    .fg(Color::Magenta)
                    .add_modifier(Modifier::BOLD),
            ));
        }
        let selected = i == app.input_sel;
        if selected {
            sel_line = lines.len();
        }
        let dirty = app.dirty_keys.contains_key(f.key);
        let marker = Span::styled(
            if dirty { "•" } else { " " },
            Style::default().fg(Color::Yellow),
        );
        let unit = app.deck.unit(f.key, app.display_units);
        let label = Span::raw(truncate(f.label, label_w));
        match (&app.mode, selected && app.focus == Pane::Inputs) {
            (
                Mode::Editing {
                    buffer,
                    cursor,
                    error,
                },
                true,
            ) => {
                let (before, rest) = buffer.split_at(
                    buffer
                        .char_indices()
                        .nth(*cursor)
                        .map_or(buffer.len(), |(b, _)| b),
                );
                let mut rest_chars = rest.chars();
                let at = rest_chars.next().map_or(" ".to_string(), String::from);
                let after: String = rest_chars.collect();
                let edit = Style::default().fg(Color::Black).bg(Color::Yellow);
                let pad = value_w.saturating_sub(buffer.chars().count() + 1);
                lines.push(Line::from(vec![
                    marker,
                    label,
                    Span::raw(" ".repeat(pad + 1)),
                    Span::styled(before.to_string(), edit),
                    Span::styled(at, edit.add_modifier(Modifier::REVERSED)),
                    Span::styled(after, edit),
                    Span::raw(format!(" {unit}")),
                ]));
                let allowed = app.deck.allowed(f.key, app.display_units);
                match error {
                    Some(e) => lines.push(Line::styled(
                        format!("  ✗ {e}"),
                        Style::default().fg(Color::Red),
                    )),
                    None => lines.push(Line::styled(
                        format!("  allowed: {allowed}"),
                        Style::default().fg(DIM),
                    )),
                }
            }
            _ => {
                let value = app.deck.display_value(f.key, app.display_units);
                let style = if selected {
                    let s = Style::default().add_modifier(Modifier::REVERSED);
                    if app.focus == Pane::Inputs {
                        s.fg(ACCENT)
                    } else {
                        s
                    }
                } else {
                    Style::default()
                };
                lines.push(Line::from(vec![
                    marker,
                    Span::styled(
                        format!("{} {:>value_w$} {unit}", truncate(f.label, label_w), value),
                        style,
                    ),
                ]));
            }
        }
    }
    let h = inner.height as usize;
    let want_bottom = sel_line + 2; // keep the edit/allowed line visible too
    let offset = want_bottom.saturating_sub(h);
    Paragraph::new(lines)
        .scroll((offset.min(u16::MAX as usize) as u16, 0))
        .render(inner, buf);
    let text = match &app.mode {
        Mode::Search { buffer, .. } => {
            let found = app.find_field(buffer, 0).is_some();
            format!(
                "/{buffer}▏ {}",
                if found || buffer.is_empty() {
                    "Tab next match · Enter go · Esc back"
                } else {
                    "no field matches"
                }
            )
        }
        _ => app
            .fields
            .get(app.input_sel)
            .map(|f| {
                let allowed = app.deck.allowed(f.key, app.display_units);
                format!("{}: {}. Allowed {allowed}.", f.key, f.help)
            })
            .unwrap_or_default(),
    };
    Paragraph::new(text)
        .style(Style::default().fg(DIM))
        .wrap(Wrap { trim: true })
        .render(about, buf);
}

fn no_solution_text(app: &App) -> String {
    match &app.solve {
        SolveState::Failed(r) => format!("no solution: {r}"),
        _ => "solving…".into(),
    }
}

/// Title note when the panes show an older solution than the deck (last solve failed).
fn stale_note(app: &App) -> &'static str {
    match (&app.solve, &app.view) {
        (SolveState::Failed(_), Some(_)) => " · last good solve",
        _ => "",
    }
}

/// The element table (Rollers pane): the view's screen table, each column in its display
/// unit and precision; `—` where a stage was not run.
fn render_rollers(app: &App, area: Rect, buf: &mut Buffer) {
    let u = app.display_units;
    // The table is laid out for the pane's inner width (2 border cells).
    let cells = app
        .view
        .as_deref()
        .map(|v| view_model::table_cells(v, u, area.width.saturating_sub(2) as usize));
    let hidden = match &cells {
        Some(c) if c.hidden > 0 => format!(" · {} more columns on a wider terminal", c.hidden),
        _ => String::new(),
    };
    let block = pane_block(app, Pane::Elements, &format!("{}{hidden}", stale_note(app)));
    let inner = block.inner(area);
    block.render(area, buf);
    let (Some(view), Some(cells)) = (app.view.as_deref(), cells) else {
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    };
    let [table_area, foot] =
        Layout::vertical([Constraint::Min(0), Constraint::Length(1)]).areas(inner);
    // Numbers are right-aligned, and so are their headers.
    let header = Row::new(
        cells
            .columns
            .iter()
            .map(|c| Cell::from(Line::from(c.header.clone()).right_aligned())),
    )
    .style(Style::default().fg(ACCENT).add_modifier(Modifier::BOLD));
    let gap = cells.gap;
    let rows = cells.rows.into_iter().map(|r| {
        Row::new(r.into_iter().map(|c| {
            let style = if c == DASH {
                Style::default().fg(DIM)
            } else {
                Style::default()
            };
            Cell::from(Line::from(c).right_aligned()).style(style)
        }))
    });
    let widths: Vec<Constraint> = cells
        .columns
        .iter()
        .map(|c| Constraint::Length(c.width))
        .collect();
    let table = Table::new(rows, widths)
        .header(header)
        .column_spacing(gap)
        .flex(ratatui::layout::Flex::Start)
        .row_highlight_style(Style::default().fg(Color::Black).bg(Color::Yellow));
    let mut state = TableState::default().with_selected(Some(app.roller_sel));
    StatefulWidget::render(table, table_area, buf, &mut state);
    let text: Vec<String> = view
        .summary
        .iter()
        .take(2)
        .map(|s| {
            format!(
                "{} {}",
                s.display.header(s.label, u),
                view_model::fixed(s.display.convert(s.value, u), s.precision)
            )
        })
        .collect();
    Paragraph::new(text.join("  "))
        .style(Style::default().fg(DIM))
        .render(foot, buf);
}

/// Decimals that keep an axis's labels distinct: none from 100 up, more below.
fn label_precision(max: f64) -> usize {
    match max.abs() {
        m if m >= 100.0 => 0,
        m if m >= 10.0 => 1,
        m if m >= 1.0 => 2,
        _ => 3,
    }
}

fn axis_labels(b: [f64; 2], prec: usize) -> Vec<Line<'static>> {
    let mid = 0.5 * (b[0] + b[1]);
    [b[0], mid, b[1]]
        .iter()
        .map(|v| Line::from(view_model::fixed(*v, prec)))
        .collect()
}

/// Series colours, in series order.
const SERIES_COLOURS: [Color; 4] = [INNER, OUTER, Color::Green, Color::Magenta];

/// A chart pane: bearing chart `n` of the view (as streamed while the solve runs, when
/// the session streams it), or on the view's `element_chart_pane` with `c` the selected
/// element's chart (a roller's laminae, a ball's motion).
fn render_load(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let pane = Pane::Chart(n);
    // A chart the running solve streams (the ball's skidding search) is drawn as it
    // grows, in place of the last solution's.
    let view = app.view.as_deref();
    let element_mode = app.chart_laminae && view.is_some_and(|v| v.element_chart_pane == n);
    let streamed = app.streamed_chart(n).filter(|_| !element_mode);
    if view.is_none() && streamed.is_none() {
        let block = pane_block(app, pane, "");
        let inner = block.inner(area);
        block.render(area, buf);
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    }
    let chart = match (streamed, view) {
        (Some(c), _) => Some(c),
        (None, Some(view)) if element_mode => view.element_charts.get(app.roller_sel),
        (None, Some(view)) => view.charts.get(n),
        (None, None) => None,
    };
    let Some(c) = chart else {
        pane_block(app, pane, "").render(area, buf);
        return;
    };
    let s = view_model::chart_series(c, app.display_units);
    // The title in what the border leaves (2 corners, 2 spaces, the pane's name, " · "
    // and the stale note), clause by clause: never a cut number.
    let stale = stale_note(app);
    let room = usize::from(area.width)
        .saturating_sub(7 + app.pane_title(pane).chars().count() + stale.chars().count());
    let title = view_model::fit_title(&s.title, room);
    let extra = if title.is_empty() {
        stale.to_string()
    } else {
        format!(" · {title}{stale}")
    };
    let block = pane_block(app, pane, &extra);
    let mut datasets = series_datasets(&s);
    let marked: Vec<(f64, f64)> = if c.per_element {
        s.series
            .iter()
            .filter_map(|(_, v)| v.get(app.roller_sel).copied())
            .collect()
    } else {
        Vec::new()
    };
    if !marked.is_empty() {
        datasets.push(
            Dataset::default()
                .name(format!("{} {}", app.element_name(), app.element_number()))
                .marker(Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(Style::default().fg(Color::White))
                .data(&marked),
        );
    }
    draw_chart(&s, datasets, block, area, buf);
}

/// One line per series of `s`, in the series colours.
fn series_datasets(s: &view_model::ChartSeries) -> Vec<Dataset<'_>> {
    s.series
        .iter()
        .enumerate()
        .map(|(k, (name, points))| {
            Dataset::default()
                .name(name.as_str())
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(Style::default().fg(SERIES_COLOURS.get(k).copied().unwrap_or(Color::White)))
                .data(points)
        })
        .collect()
}

/// Draws `datasets` on `s`'s axes inside `block`.
fn draw_chart(
    s: &view_model::ChartSeries,
    datasets: Vec<Dataset>,
    block: Block,
    area: Rect,
    buf: &mut Buffer,
) {
    // Two decimals on a short x axis (a roller's laminae in mm), none on a long one.
    let x_prec = label_precision(s.x_bounds[1]);
    let chart = Chart::new(datasets)
        .hidden_legend_constraints((Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)))
        .block(block)
        .x_axis(
            Axis::default()
                .title(s.x_label.clone())
                .style(Style::default().fg(DIM))
                .bounds(s.x_bounds)
                .labels(axis_labels(s.x_bounds, x_prec)),
        )
        .y_axis(
            Axis::default()
                .title(s.y_label.clone())
                .style(Style::default().fg(DIM))
                .bounds(s.y_bounds)
                .labels(axis_labels(s.y_bounds, label_precision(s.y_bounds[1]))),
        );
    chart.render(area, buf);
}

/// A sweep pane: the plan's outputs against the swept key as the worker fills them in,
/// the marker (rollers leaving the cone) as a vertical line.
fn render_sweep(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let pane = Pane::Sweep(n);
    let progress = app
        .sweep
        .as_ref()
        .filter(|(_, pane_n, _)| *pane_n == n)
        .map(|(g, _, p)| (*g, p));
    let Some((generation, p)) = progress else {
        let block = pane_block(app, pane, "");
        let inner = block.inner(area);
        block.render(area, buf);
        let text = match app.solve {
            SolveState::Failed(_) => no_solution_text(app),
            _ => "sweeping…".to_string(),
        };
        Paragraph::new(text).render(inner, buf);
        return;
    };
    let (s, marker, note) = view_model::sweep_series(p, app.display_units);
    let stale = if generation == app.generation {
        ""
    } else {
        " · updating"
    };
    // The progress note holds numbers: drop the chart's title rather than cut them.
    let full = format!(" · {} · {note}{stale}", s.title);
    let room = usize::from(area.width).saturating_sub(4 + app.pane_title(pane).chars().count());
    let extra = if full.chars().count() <= room {
        full
    } else {
        format!(" · {note}{stale}")
    };
    let block = pane_block(app, pane, &extra);
    let mut datasets = series_datasets(&s);
    let line: Vec<(f64, f64)> = marker
        .map(|x| vec![(x, s.y_bounds[0]), (x, s.y_bounds[1])])
        .unwrap_or_default();
    if let (Some(_), Some((_, label))) = (marker, p.plan.marker) {
        datasets.push(
            Dataset::default()
                .name(label)
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(Style::default().fg(Color::Red))
                .data(&line),
        );
    }
    draw_chart(&s, datasets, block, area, buf);
}

fn render_thermal(app: &App, area: Rect, buf: &mut Buffer) {
    let block = pane_block(app, Pane::Thermal, "");
    let inner = block.inner(area);
    block.render(area, buf);
    let view = app
        .view
        .as_deref()
        .and_then(|v| v.thermal.as_ref())
        .map(|th| view_model::thermal_view(th, app.display_units, app.thermal_node));
    let Some(t) = view else {
        let msg = match (&app.view, app.deck.has_thermal()) {
            (_, false) => "no thermal model in this deck (see `rollbench template`, [thermal])",
            (None, true) => "solving…",
            (Some(_), true) => "the thermal network was not solved",
        };
        Paragraph::new(msg)
            .style(Style::default().fg(DIM))
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    };
    render_thermal_view(&t, inner, buf);
}

/// The thermal pane's contents (inside the border): what the selected node does (one
/// line), its transient against time with the limit and the moment it is reached, and the
/// node list with the selection highlighted (scrolled to keep it in view).
pub fn render_thermal_view(t: &view_model::ThermalView, inner: Rect, buf: &mut Buffer) {
    let summary = t.summary();
    // The account of the node is read whole: a second line when it is longer than the
    // pane is wide.
    let title_h = if summary.chars().count() > inner.width as usize {
        2
    } else {
        1
    };
    let chart_h = if t.series.is_empty() {
        0
    } else {
        (inner.height.saturating_sub(title_h) / 2).max(5)
    };
    let [title, chart, table] = Layout::vertical([
        Constraint::Length(title_h),
        Constraint::Length(chart_h),
        Constraint::Min(0),
    ])
    .areas(inner);
    Paragraph::new(summary)
        .wrap(Wrap { trim: true })
        .render(title, buf);
    if chart_h > 0 {
        render_thermal_chart(t, chart, buf);
    }
    let u = &t.temperature_unit;
    let rows = t.nodes.iter().map(|n| {
        let num = |v: Option<f64>, p: usize| {
            Cell::from(
                Line::from(v.map_or("—".to_string(), |x| view_model::fixed(x, p))).right_aligned(),
            )
        };
        let name = if n.fixed {
            format!("{} (given)", n.name)
        } else {
            n.name.clone()
        };
        Row::new(vec![
            Cell::from(name),
            num(Some(n.steady), 1),
            num(n.limit, 1),
            num(n.time_to_limit_s, 1),
        ])
    });
    let nodes = Table::new(
        rows,
        [
            Constraint::Min(10),
            Constraint::Length(8),
            Constraint::Length(8),
            Constraint::Length(8),
        ],
    )
    .header(
        Row::new(vec![
            Cell::from("node"),
            Cell::from(Line::from(format!("T {u}")).right_aligned()),
            Cell::from(Line::from(format!("lim {u}")).right_aligned()),
            Cell::from(Line::from("at s").right_aligned()),
        ])
        .style(Style::default().fg(ACCENT)),
    )
    .row_highlight_style(Style::default().fg(Color::Black).bg(Color::Yellow));
    let mut state = TableState::default().with_selected(Some(t.selected));
    StatefulWidget::render(nodes, table, buf, &mut state);
}

/// The selected node's temperature against time, its limit as a line and the time it is
/// reached as a point.
fn render_thermal_chart(t: &view_model::ThermalView, area: Rect, buf: &mut Buffer) {
    let finite = t
        .series
        .iter()
        .filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut lo, mut hi) = finite
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.1), h.max(p.1))
        });
    let t0 = finite.clone().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let t1 = finite.map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite() && t0.is_finite() && t1.is_finite()) {
        return;
    }
    let node = t.node();
    let limit = node.and_then(|n| n.limit);
    if let Some(l) = limit {
        lo = lo.min(l);
        hi = hi.max(l);
    }
    let pad = if hi > lo { 0.05 * (hi - lo) } else { 1.0 };
    let (lo, hi) = (lo - pad, hi + pad);
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    let limit_line: Vec<(f64, f64)> = limit.map_or(Vec::new(), |l| vec![(t0, l), (t1, l)]);
    let reached: Vec<(f64, f64)> = match (limit, node.and_then(|n| n.time_to_limit_s)) {
        (Some(l), Some(at)) => vec![(at, l)],
        _ => Vec::new(),
    };
    let mut datasets = vec![Dataset::default()
        .name(node.map_or(String::new(), |n| n.name.clone()))
        .marker(Marker::Braille)
        .graph_type(GraphType::Line)
        .style(Style::default().fg(Color::Red))
        .data(&t.series)];
    if !limit_line.is_empty() {
        datasets.push(
            Dataset::default()
                .name("limit")
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(Style::default().fg(Color::Yellow))
                .data(&limit_line),
        );
    }
    if !reached.is_empty() {
        datasets.push(
            Dataset::default()
                .name("reached")
                .marker(Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(Style::default().fg(Color::White))
                .data(&reached),
        );
    }
    let u = &t.temperature_unit;
    Chart::new(datasets)
        .hidden_legend_constraints((Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)))
        .x_axis(
            Axis::default()
                .title("t s")
                .style(Style::default().fg(DIM))
                .bounds([t0, t1])
                .labels(axis_labels([t0, t1], 0)),
        )
        .y_axis(
            Axis::default()
                .title(u.clone())
                .style(Style::default().fg(DIM))
                .bounds([lo, hi])
                .labels(axis_labels([lo, hi], 0)),
        )
        .render(area, buf);
}

/// One cell per value, ▁..█ scaled to `max`.
fn bar_row(values: &[f64], max: f64) -> String {
    const BARS: [char; 9] = [' ', '▁', '▂', '▃', '▄', '▅', '▆', '▇', '█'];
    values
        .iter()
        .map(|&v| {
            if max > 0.0 && v > 0.0 {
                let i = ((v / max) * 8.0).round().clamp(1.0, 8.0) as usize;
                BARS.get(i).copied().unwrap_or('█')
            } else {
                '·'
            }
        })
        .collect()
}

fn render_stepper(app: &App, area: Rect, buf: &mut Buffer) {
    let n = app.trace_len();
    let element = app.element_name();
    let extra = if n > 0 {
        format!(
            " · {element} {} · step {}/{}",
            app.element_number(),
            app.step + 1,
            n
        )
    } else {
        format!(" · {element} {}", app.element_number())
    };
    let block = pane_block(app, Pane::Stepper, &extra);
    let inner = block.inner(area);
    block.render(area, buf);
    let trace = app.view.as_deref().and_then(|v| v.trace.as_ref());
    let view = trace.and_then(|t| view_model::trace_step(t, app.step, app.display_units));
    let (Some(trace), Some(v)) = (trace, view) else {
        let msg = match &app.solve {
            SolveState::Failed(r) => format!("no trace: {r}"),
            SolveState::Running => "recording the equilibrium iterations…".into(),
            _ => "no trace recorded (r re-solves)".into(),
        };
        Paragraph::new(msg)
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    };
    // Labels in one column as wide as the longest (units included) and a space.
    let lw = v
        .lines
        .iter()
        .map(|(k, _)| k.chars().count() + 1)
        .chain(v.bars.iter().map(|b| b.label.chars().count() + 1))
        .chain(std::iter::once(18))
        .max()
        .unwrap_or(18);
    let mut lines: Vec<Line> = vec![Line::styled(
        format!("{:<lw$}{}", "steps of", trace.label),
        Style::default().fg(DIM),
    )];
    lines.extend(v.lines.iter().map(|(k, val)| {
        Line::from(vec![
            Span::styled(format!("{k:<lw$}"), Style::default().fg(DIM)),
            Span::raw(val.clone()),
        ])
    }));
    // Each group of bar rows shares one full scale (loads with loads, approaches with
    // approaches), listed after the rows.
    let mut scales: Vec<(usize, f64, usize, &str)> = Vec::new();
    for b in &v.bars {
        let max = b.values.iter().copied().fold(0.0, f64::max);
        match scales.iter_mut().find(|s| s.0 == b.group) {
            Some(s) => s.1 = s.1.max(max),
            None => scales.push((b.group, max, b.precision, b.unit)),
        }
    }
    lines.push(Line::raw(""));
    for b in &v.bars {
        let max = scales.iter().find(|s| s.0 == b.group).map_or(0.0, |s| s.1);
        let colour = if b.side == 0 { INNER } else { OUTER };
        lines.push(Line::from(vec![
            Span::styled(format!("{:<lw$}", b.label), Style::default().fg(DIM)),
            Span::styled(bar_row(&b.values, max), Style::default().fg(colour)),
        ]));
    }
    if !scales.is_empty() {
        let full: Vec<String> = scales
            .iter()
            .map(|(_, max, prec, unit)| format!("{max:.prec$} {unit}"))
            .collect();
        lines.push(Line::styled(
            format!("{:<lw$}{}", "full scale", full.join(" / ")),
            Style::default().fg(DIM),
        ));
    }
    let used = lines.len() as u16 + 1;
    let [top, history] =
        Layout::vertical([Constraint::Length(used), Constraint::Min(0)]).areas(inner);
    Paragraph::new(lines).render(top, buf);
    if history.height < 3 {
        return;
    }
    let rows = view_model::trace_rows(trace, app.display_units);
    let shown = history.height.saturating_sub(1) as usize;
    let first = app
        .step
        .saturating_sub(shown / 2)
        .min(rows.len().saturating_sub(shown));
    let mut hist: Vec<Line> = vec![Line::styled(
        view_model::trace_header(trace, app.display_units),
        Style::default().fg(ACCENT),
    )];
    for (i, r) in rows.iter().enumerate().skip(first).take(shown) {
        let style = if i == app.step {
            Style::default().fg(Color::Black).bg(Color::Yellow)
        } else {
            Style::default()
        };
        hist.push(Line::styled(r.clone(), style));
    }
    Paragraph::new(hist).render(history, buf);
}

fn render_status(app: &App, area: Rect, buf: &mut Buffer) {
    let (text, color) = match &app.solve {
        SolveState::Idle => ("idle".to_string(), DIM),
        SolveState::Running => ("● solving…".to_string(), Color::Yellow),
        SolveState::Solved {
            names,
            iterations,
            roller_iterations,
            wall_ms,
        } => {
            // The longest wording that leaves room for the rest of the line: numbers are
            // never cut, words are dropped first.
            let rest = status_extras_width(app);
            let room = usize::from(area.width).saturating_sub(rest);
            let forms = [
                format!(
                    "✓ solved in {iterations} {} + {roller_iterations} {} iterations, {wall_ms:.1} ms",
                    names[0], names[1]
                ),
                format!("✓ solved: {iterations} + {roller_iterations} iterations, {wall_ms:.1} ms"),
                format!("✓ {iterations}+{roller_iterations} it, {wall_ms:.1} ms"),
            ];
            let pick = forms
                .iter()
                .find(|f| f.chars().count() <= room)
                .unwrap_or(&forms[2])
                .clone();
            (pick, Color::Green)
        }
        SolveState::Failed(r) => (
            format!(
                "✗ failed (e: whole message): {}",
                r.lines().next().unwrap_or("")
            ),
            Color::Red,
        ),
    };
    let mut spans = vec![Span::styled(
        text,
        Style::default().fg(color).add_modifier(Modifier::BOLD),
    )];
    spans.extend(status_extras(app));
    Line::from(spans).render(area, buf);
}

/// Width of [`status_extras`] in cells.
fn status_extras_width(app: &App) -> usize {
    status_extras(app)
        .iter()
        .map(|s| s.content.chars().count())
        .sum()
}

/// The status line after the solver state: warnings, unsaved, edits not solved, message.
fn status_extras(app: &App) -> Vec<Span<'static>> {
    let mut spans = Vec::new();
    let warnings = app.view.as_ref().map_or(0, |v| v.warnings.len());
    if warnings > 0 && matches!(app.solve, SolveState::Solved { .. }) {
        spans.push(Span::styled(
            format!(
                " │ ⚠ {warnings} warning{} (w)",
                if warnings == 1 { "" } else { "s" }
            ),
            Style::default()
                .fg(Color::Yellow)
                .add_modifier(Modifier::BOLD),
        ));
    }
    if app.unsaved() {
        spans.push(Span::styled(
            " │ [+] unsaved",
            Style::default().fg(Color::Yellow),
        ));
    }
    if !app.dirty_keys.is_empty() {
        spans.push(Span::styled(
            format!(" │ • {} edited, not solved", app.dirty_keys.len()),
            Style::default().fg(Color::Yellow),
        ));
    }
    if let Some(m) = &app.message {
        spans.push(Span::raw(format!(" │ {m}")));
    }
    spans
}

/// The footer's hints for the mode and pane, most useful first; the last ones (help,
/// quit) are always shown, the others as far as the width allows.
fn hint_items(app: &App) -> (Vec<String>, Vec<String>) {
    let el = app.element_name();
    let v = |items: &[&str]| items.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    match &app.mode {
        Mode::Editing { .. } => (
            v(&[
                "Enter commit",
                "←→ move",
                "↑↓ cycle choices",
                "Backspace/Del erase",
            ]),
            v(&["Esc cancel"]),
        ),
        Mode::Prompt { .. } => (v(&["type a path", "Enter confirm"]), v(&["Esc cancel"])),
        Mode::ConfirmQuit | Mode::ConfirmRevert | Mode::ConfirmOverwrite { .. } => {
            (v(&["answer the prompt"]), Vec::new())
        }
        Mode::Help => (v(&["any key closes help"]), Vec::new()),
        Mode::Search { .. } => (
            v(&["type part of a name or key", "Tab next match", "Enter go"]),
            v(&["Esc back"]),
        ),
        Mode::Error => (
            v(&["any key closes", "e reopens the last error"]),
            Vec::new(),
        ),
        Mode::Warnings => (v(&["any key closes", "w reopens the warnings"]), Vec::new()),
        Mode::Normal => {
            let mut first = match app.focus {
                Pane::Text(_) | Pane::Sweep(_) => Vec::new(),
                Pane::Inputs => v(&[
                    "jk move",
                    "Enter edit",
                    "/ find",
                    "^z/^y undo/redo",
                    "^s save",
                ]),
                Pane::Elements => vec![format!("jk {el}")],
                Pane::Chart(n) => {
                    let mut h = vec![format!("jk {el}")];
                    if app
                        .view
                        .as_ref()
                        .is_some_and(|v| !v.element_charts.is_empty() && v.element_chart_pane == n)
                    {
                        h.push("c chart".into());
                    }
                    h
                }
                Pane::Stepper => vec!["hl step".into(), "PgUp/PgDn ±10".into(), format!("jk {el}")],
                Pane::Thermal => v(&["jk node", "g/G first/last"]),
            };
            if matches!(app.focus, Pane::Elements | Pane::Chart(_))
                && app.panes().contains(&Pane::Stepper)
            {
                first.push("Enter stepper".into());
            }
            first.push("u units".into());
            first.push("Tab pane".into());
            if app.error.is_some() {
                first.insert(0, "e error".into());
            }
            if app.view.as_ref().is_some_and(|v| !v.warnings.is_empty()) {
                first.insert(0, "w warnings".into());
            }
            (first, v(&["? help", "q quit"]))
        }
    }
}

fn render_hints(app: &App, area: Rect, buf: &mut Buffer) {
    let (mut first, last) = hint_items(app);
    let join = |f: &[String]| {
        f.iter()
            .chain(&last)
            .map(String::as_str)
            .collect::<Vec<_>>()
            .join(" · ")
    };
    while first.len() > 1 && join(&first).chars().count() > area.width as usize {
        first.pop();
    }
    Paragraph::new(join(&first))
        .style(Style::default().fg(Color::Black).bg(Color::Gray))
        .render(area, buf);
}

fn centered(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

/// The last error, whole: one message per line, wrapped to the popup, which takes the
/// room it needs up to the screen.
fn render_error(title: &str, text: &str, area: Rect, buf: &mut Buffer) {
    let width = area.width.saturating_sub(4).max(10);
    let inner_w = width.saturating_sub(2).max(1) as usize;
    let longest = text.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    let w = ((longest + 2) as u16).clamp(30.min(width), width);
    let inner_w = inner_w.min(w.saturating_sub(2) as usize).max(1);
    // Rows each line takes when wrapped.
    let rows: usize = text
        .lines()
        .map(|l| l.chars().count().div_ceil(inner_w).max(1))
        .sum();
    let h = ((rows + 2) as u16)
        .min(area.height.saturating_sub(2))
        .max(3);
    let r = centered(area, w, h);
    Clear.render(r, buf);
    let lines: Vec<Line> = text.lines().map(|l| Line::raw(l.to_string())).collect();
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_style(Style::default().fg(Color::Red))
                .title(title.to_string()),
        )
        .render(r, buf);
}

/// Words of `text` in lines of at most `width` characters (a longer word is cut).
fn wrap_words(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let len = line.chars().count();
        if len > 0 && len + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// The key table: key, where, action (wrapped), scrolled by `scroll` rows when it does
/// not fit; the title says how to scroll then.
fn render_help(scroll: usize, area: Rect, buf: &mut Buffer) {
    let w = area.width.min(80);
    let (key_w, ctx_w) = (17u16, 13u16);
    let action_w = w.saturating_sub(key_w + ctx_w + 4).max(10) as usize;
    let rows: Vec<(Row, u16)> = KEYS
        .iter()
        .map(|(k, ctx, what)| {
            let lines = wrap_words(what, action_w);
            let h = lines.len() as u16;
            let row = Row::new(vec![
                Cell::from(*k).style(Style::default().fg(Color::Yellow)),
                Cell::from(wrap_words(ctx, ctx_w as usize).join("\n"))
                    .style(Style::default().fg(DIM)),
                Cell::from(lines.join("\n")),
            ])
            .height(h.max(ctx.chars().count().div_ceil(ctx_w as usize) as u16));
            (row, h)
        })
        .collect();
    let total: u16 = rows.iter().map(|r| r.1).sum();
    let h = (total + 3).min(area.height);
    let fits = total + 3 <= area.height;
    let scroll = if fits {
        0
    } else {
        scroll.min(rows.len().saturating_sub(1))
    };
    let room = h.saturating_sub(3);
    let mut used = 0u16;
    let shown = rows
        .iter()
        .skip(scroll)
        .take_while(|r| {
            used += r.1;
            used <= room
        })
        .count();
    let title = if fits {
        " Keys (any key closes) ".to_string()
    } else {
        format!(
            " Keys {}–{} of {} · j/k scroll, any other key closes ",
            scroll + 1,
            scroll + shown,
            rows.len()
        )
    };
    let r = centered(area, w, h);
    Clear.render(r, buf);
    let block = Block::default()
        .borders(Borders::ALL)
        .border_style(Style::default().fg(ACCENT))
        .title(title);
    let help = Table::new(
        rows.into_iter().skip(scroll).map(|r| r.0),
        [
            Constraint::Length(key_w),
            Constraint::Length(ctx_w),
            Constraint::Min(10),
        ],
    )
    .header(Row::new(vec!["key", "where", "action"]).style(Style::default().fg(ACCENT)))
    .block(block);
    Widget::render(help, r, buf);
}

fn render_prompt(kind: PromptKind, text: &str, area: Rect, buf: &mut Buffer) {
    let title = match kind {
        PromptKind::SaveAs => " Save deck as (Enter save, Esc cancel) ",
        PromptKind::Open => " Open deck (Enter open, Esc cancel) ",
    };
    let r = centered(area, 64, 3);
    Clear.render(r, buf);
    Paragraph::new(Line::from(vec![
        Span::raw(text.to_string()),
        Span::styled(" ", Style::default().add_modifier(Modifier::REVERSED)),
    ]))
    .block(
        Block::default()
            .borders(Borders::ALL)
            .border_style(Style::default().fg(Color::Yellow))
            .title(title),
    )
    .render(r, buf);
}

fn render_confirm(title: &str, text: &str, area: Rect, buf: &mut Buffer) {
    let r = centered(area, 56, 4);
    Clear.render(r, buf);
    Paragraph::new(text.to_string())
        .wrap(Wrap { trim: true })
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_style(Style::default().fg(Color::Yellow))
                .title(format!(" {title} ")),
        )
        .render(r, buf);
}
