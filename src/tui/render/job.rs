//! A job pane (`Pane::Job(n)`): what the worker's job has reported so far ([`JobView`]):
//! its result lines on top, its heat maps and charts, its failed points in red at the
//! bottom, and its progress on the border. Apart because it reads the job's reports, not
//! the solution's view.
//!
//! Layout: a lone chart fills the pane (its title on the border), result lines above it;
//! a heat map takes its natural width (at most half the pane) on the left, with the
//! result lines and the charts stacked beside it (its legend there too when it does not
//! fit below the map; charts only as many as have 6 lines), or, when that leaves fewer
//! than 24 columns, the lines, the map and the charts side by side one under the other.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph, Widget, Wrap};

use super::chart::{draw_chart, series_datasets};
use super::heatmap::{legend_lines, natural_size, render_heat_map};
use super::{no_solution_text, pane_block, DIM};
use crate::bearings::view::JobView;
use crate::tui::app::{App, Pane, SolveState};
use crate::tui::view_model;

/// The most lines of failed points shown (the rest counted).
const MAX_ERROR_LINES: usize = 4;

/// The progress note of a job: `"12/30"` with its stage, or its end.
pub(super) fn progress_note(v: &JobView) -> String {
    if v.finished {
        return v.stage.clone();
    }
    let pct = if v.total > 0 {
        100.0 * v.done as f64 / v.total as f64
    } else {
        0.0
    };
    format!("{} {}/{} ({pct:.0} %)", v.stage, v.done, v.total)
}

/// Lines `text` wraps to at `width` (at least 1), word by word as the paragraph wraps
/// it (a word longer than the width takes lines of its own).
fn wrapped_height(text: &str, width: u16) -> u16 {
    let w = usize::from(width.max(1));
    let mut lines = 1;
    let mut col = 0;
    for word in text.split(' ') {
        let n = word.chars().count();
        let need = if col == 0 { n } else { col + 1 + n };
        if need <= w {
            col = need;
        } else if n <= w {
            lines += 1;
            col = n;
        } else {
            lines += (col > 0) as usize + n / w;
            col = n % w;
        }
    }
    lines as u16
}

pub(super) fn render_job(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let pane = Pane::Job(n);
    let report = app
        .job
        .as_ref()
        .filter(|(g, pane_n, _)| *pane_n == n && *g == app.generation)
        .map(|(_, _, v)| v.clone());
    let Some(v) = report else {
        let block = pane_block(app, pane, "");
        let inner = block.inner(area);
        block.render(area, buf);
        let text = match app.solve {
            SolveState::Failed(_) => no_solution_text(app),
            _ => "starting…".to_string(),
        };
        Paragraph::new(text).render(inner, buf);
        return;
    };
    let u = app.display_units;
    let note = progress_note(&v);
    // A lone chart's title goes on the border (clause by clause, never a cut number).
    let lone = v.heat_maps.is_empty() && v.charts.len() == 1;
    let room = usize::from(area.width)
        .saturating_sub(7 + app.pane_title(pane).chars().count() + note.chars().count() + 3);
    let title = if lone {
        view_model::fit_title(v.charts[0].title_in(u), room)
    } else {
        String::new()
    };
    let extra = if title.is_empty() {
        format!(" · {note}")
    } else {
        format!(" · {title} · {note}")
    };
    let block = pane_block(app, pane, &extra);
    let inner = block.inner(area);
    block.render(area, buf);
    // Result lines on top, failed points at the bottom (both wrapped, whole).
    let notes: Vec<&str> = v.notes.iter().map(|w| w.text(u)).collect();
    let notes_h: u16 = notes.iter().map(|t| wrapped_height(t, inner.width)).sum();
    let mut errors: Vec<String> = v.errors.iter().map(|e| format!("⚠ {e}")).collect();
    let mut errors_h: u16 = 0;
    let mut shown = 0;
    for e in &errors {
        let h = wrapped_height(e, inner.width);
        if usize::from(errors_h + h) > MAX_ERROR_LINES.max(usize::from(inner.height / 3)) {
            break;
        }
        errors_h += h;
        shown += 1;
    }
    if shown < errors.len() {
        let more = format!("… {} more failed points", errors.len() - shown);
        errors.truncate(shown);
        errors.push(more);
        errors_h += 1;
    }
    // A job that failed as a whole has only its message: give it the pane.
    let nothing_drawn = v.heat_maps.is_empty() && v.charts.is_empty();
    if nothing_drawn {
        errors_h = inner.height.saturating_sub(notes_h);
    }
    let [main, bottom] = Layout::vertical([
        Constraint::Min(0),
        Constraint::Length(errors_h.min(inner.height)),
    ])
    .areas(inner);
    Paragraph::new(
        errors
            .iter()
            .map(|t| {
                Line::from(Span::styled(
                    t.clone(),
                    Style::default().fg(Color::LightRed),
                ))
            })
            .collect::<Vec<_>>(),
    )
    .wrap(Wrap { trim: false })
    .render(bottom, buf);
    let lines_of = |texts: &[String]| -> Vec<Line<'static>> {
        texts.iter().map(|t| Line::raw(t.clone())).collect()
    };
    let notes: Vec<String> = notes.iter().map(|t| t.to_string()).collect();
    let chart_areas: Vec<Rect> = match v.heat_maps.first() {
        None => {
            let [top, body] = Layout::vertical([
                Constraint::Length(notes_h.min(main.height / 3)),
                Constraint::Min(0),
            ])
            .areas(main);
            Paragraph::new(lines_of(&notes))
                .wrap(Wrap { trim: false })
                .render(top, buf);
            if nothing_drawn {
                return;
            }
            split(body, v.charts.len(), body.width >= 2 * 28)
        }
        Some(m) => {
            // The map gets at most half the width (its 30 columns at least), the rest the
            // result lines and the charts; its legend moves beside it when it does not
            // fit below.
            let budget = Rect {
                width: (main.width / 2).max(30).min(main.width),
                ..main
            };
            let (w, _, full_h) = natural_size(m, u, budget);
            let right_w = main.width.saturating_sub(w + 1);
            if right_w >= 24 {
                let [map_area, _, right] = Layout::horizontal([
                    Constraint::Length(w),
                    Constraint::Length(1),
                    Constraint::Min(0),
                ])
                .areas(main);
                let legend_beside = full_h > main.height;
                render_heat_map(m, u, map_area, buf, !legend_beside);
                let mut text: Vec<Line<'static>> = Vec::new();
                if legend_beside {
                    text.extend(legend_lines(m, u, right.width));
                }
                text.extend(lines_of(&notes));
                let text_h: u16 = if legend_beside {
                    legend_lines(m, u, right.width).len() as u16
                } else {
                    0
                } + notes
                    .iter()
                    .map(|t| wrapped_height(t, right.width))
                    .sum::<u16>();
                let [top, rest] = Layout::vertical([
                    Constraint::Length(text_h.min(right.height)),
                    Constraint::Min(0),
                ])
                .areas(right);
                Paragraph::new(text)
                    .wrap(Wrap { trim: false })
                    .render(top, buf);
                // As many charts as have 6 lines each.
                let fit = v.charts.len().min(usize::from(rest.height / 6));
                split(rest, fit, false)
            } else {
                let [top, map_area, rest] = Layout::vertical([
                    Constraint::Length(notes_h.min(main.height / 3)),
                    Constraint::Length(full_h),
                    Constraint::Min(0),
                ])
                .areas(main);
                Paragraph::new(lines_of(&notes))
                    .wrap(Wrap { trim: false })
                    .render(top, buf);
                render_heat_map(m, u, map_area, buf, true);
                let fit = if rest.height >= 6 { v.charts.len() } else { 0 };
                split(rest, fit, true)
            }
        }
    };
    for (c, a) in v.charts.iter().zip(chart_areas) {
        if a.height < 5 || a.width < 16 {
            continue;
        }
        let s = view_model::chart_series(c, u);
        let block = if lone {
            Block::default()
        } else {
            Block::default()
                .borders(Borders::TOP)
                .border_style(Style::default().fg(DIM))
                .title(Span::styled(
                    view_model::fit_title(&s.title, usize::from(a.width.saturating_sub(2))),
                    Style::default().fg(DIM),
                ))
        };
        draw_chart(&s, series_datasets(&s), block, a, buf);
    }
}

/// `area` cut into `n` equal parts, side by side or stacked.
fn split(area: Rect, n: usize, side_by_side: bool) -> Vec<Rect> {
    if n == 0 {
        return Vec::new();
    }
    let parts = vec![Constraint::Ratio(1, n as u32); n];
    let layout = if side_by_side {
        // A blank column between charts: their labels never run together.
        Layout::horizontal(parts).spacing(1)
    } else {
        Layout::vertical(parts)
    };
    layout.split(area).to_vec()
}
