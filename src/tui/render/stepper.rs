//! The Stepper pane: one step of the recorded equilibrium iterations of the selected
//! element (values, bar rows on shared scales) and the step history around it. Apart
//! because it reads the trace only and moves with the stepper keys.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{pane_block, ACCENT, DIM, INNER, OUTER};
use crate::tui::app::{App, Pane, SolveState};
use crate::tui::view_model;

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

pub(super) fn render_stepper(app: &App, area: Rect, buf: &mut Buffer) {
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
