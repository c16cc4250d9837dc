//! The chart panes (`Pane::Chart(n)`: the rollers' load, the ball's skid, dynamics and
//! traction): one of the view's charts, the streamed one while a solve fills it, or the
//! selected element's chart; and the chart drawing the sweep and thermal panes share
//! (series colours, axes, labels).

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Line;
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, Paragraph, Widget};

use super::{no_solution_text, pane_block, stale_note, DIM, SERIES_COLOURS};
use crate::tui::app::{App, Pane};
use crate::tui::view_model;

/// Decimals that keep an axis's labels distinct: none from 100 up, more below.
fn label_precision(max: f64) -> usize {
    match max.abs() {
        m if m >= 100.0 => 0,
        m if m >= 10.0 => 1,
        m if m >= 1.0 => 2,
        _ => 3,
    }
}

pub(super) fn axis_labels(b: [f64; 2], prec: usize) -> Vec<Line<'static>> {
    let mid = 0.5 * (b[0] + b[1]);
    [b[0], mid, b[1]]
        .iter()
        .map(|v| Line::from(view_model::fixed(*v, prec)))
        .collect()
}

/// A chart pane: bearing chart `n` of the view (as streamed while the solve runs, when
/// the session streams it), or on the view's `element_chart_pane` with `c` the selected
/// element's chart (a roller's laminae, a ball's motion).
pub(super) fn render_load(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
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
pub(super) fn series_datasets(s: &view_model::ChartSeries) -> Vec<Dataset<'_>> {
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
pub(super) fn draw_chart(
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
