//! The Thermal pane: the selected node's account, its transient against time with the
//! limit, and the node table. Apart because it reads the thermal network only; the tests
//! draw its contents ([`render_thermal_view`]) on their own.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Line;
use ratatui::widgets::{
    Axis, Cell, Chart, Dataset, GraphType, Paragraph, Row, StatefulWidget, Table, TableState,
    Widget, Wrap,
};

use super::chart::axis_labels;
use super::{pane_block, ACCENT, DIM};
use crate::tui::app::{App, Pane};
use crate::tui::view_model;

pub(super) fn render_thermal(app: &App, area: Rect, buf: &mut Buffer) {
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

/// How many lines `text` takes when its words are wrapped to `width` cells (a word longer
/// than the width takes lines of its own).
fn wrapped_lines(text: &str, width: usize) -> usize {
    let width = width.max(1);
    let (mut lines, mut used) = (1, 0);
    for word in text.split_whitespace() {
        let n = word.chars().count();
        let need = if used == 0 { n } else { used + 1 + n };
        if need <= width {
            used = need;
        } else {
            lines += usize::from(used > 0) + (n - 1) / width;
            used = (n - 1) % width + 1;
        }
    }
    lines
}

/// The thermal pane's contents (inside the border): what the selected node does (one
/// line), its transient against time with the limit and the moment it is reached, and the
/// node list with the selection highlighted (scrolled to keep it in view).
pub fn render_thermal_view(t: &view_model::ThermalView, inner: Rect, buf: &mut Buffer) {
    let summary = t.summary();
    // The account of the node is read whole: as many lines as its words wrap to (at
    // most 3; it names the limit line's and marker's glyphs too, issue 30 item 13).
    let title_h = wrapped_lines(&summary, inner.width as usize).clamp(1, 3) as u16;
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
