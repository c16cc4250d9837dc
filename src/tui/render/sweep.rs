//! A sweep pane (`Pane::Sweep(n)`): the plan's outputs against the swept key as the
//! worker fills them in, with its marker line. Apart because it reads the sweep progress,
//! not the solution's view.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::widgets::{Dataset, GraphType, Paragraph, Widget, Wrap};

use super::chart::{draw_chart, series_datasets};
use super::{no_solution_text, pane_block};
use crate::tui::app::{App, Pane, SolveState};
use crate::tui::view_model;

/// A sweep pane: the plan's outputs against the swept key as the worker fills them in,
/// the marker (rollers leaving the cone) as a vertical line.
pub(super) fn render_sweep(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
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
    // The first failure's reason under the chart, wrapped, as the CLI gives it (issue 30
    // item 17); the chart keeps the rest of the pane.
    let area = match view_model::sweep_first_failure(p, app.display_units) {
        Some(why) if area.height > 8 => {
            let [chart, below] =
                Layout::vertical([Constraint::Min(0), Constraint::Length(2)]).areas(area);
            Paragraph::new(why)
                .style(Style::default().fg(Color::Red))
                .wrap(Wrap { trim: true })
                .render(below, buf);
            chart
        }
        _ => area,
    };
    draw_chart(&s, datasets, block, area, buf);
}
