//! The Stepper pane: one step of the recorded equilibrium iterations of the selected
//! element (values, bar rows on shared scales) and the step history around it. Apart
//! because it reads the trace only and moves with the stepper keys.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{pane_block, ACCENT, DIM, INNER, OUTER};
use crate::bearings::view::TraceFormat;
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

/// `values` in at most `width` cells: as they are when they fit, else cell `i` the
/// largest of the values `i·n/width .. (i+1)·n/width` it covers, so every value is in
/// some cell and a peak (an edge load) is never averaged away (issue 30 item 2: 81
/// laminae were cut to the 38 cells of a 60-column screen).
pub(super) fn resample_max(values: &[f64], width: usize) -> Vec<f64> {
    let n = values.len();
    if n <= width || width == 0 {
        return values.to_vec();
    }
    (0..width)
        .map(|i| {
            let (a, b) = (i * n / width, ((i + 1) * n / width).max(i * n / width + 1));
            values
                .get(a..b.min(n))
                .unwrap_or(&[])
                .iter()
                .copied()
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .collect()
}

/// `text` broken at spaces into lines of at most `width` characters (a word longer than
/// the width is cut into pieces).
pub(super) fn wrap_words(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let used = line.chars().count();
            let sep = usize::from(used > 0);
            if used + sep + word.len() <= width {
                if sep == 1 {
                    line.push(' ');
                }
                line.extend(word.iter());
                break;
            }
            if used > 0 {
                lines.push(std::mem::take(&mut line));
                continue;
            }
            let rest = word.split_off(width);
            lines.push(word.iter().collect());
            word = rest;
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
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
    // The cells the bars and values have beside the labels; the trace's label wraps in
    // them rather than being cut (60 columns cut "the last ends at the solution").
    let room = usize::from(inner.width).saturating_sub(lw).max(1);
    let mut lines: Vec<Line> = wrap_words(&trace.label, room)
        .into_iter()
        .enumerate()
        .map(|(i, part)| {
            let label = if i == 0 { "steps of" } else { "" };
            Line::styled(format!("{label:<lw$}{part}"), Style::default().fg(DIM))
        })
        .collect();
    // The iteration counts line repeats the history's highlighted row; where the pane is
    // too short for the history's header and that row besides (60×20), it gives way.
    let counts: Vec<bool> = (0..v.lines.len())
        .map(|i| {
            trace
                .steps
                .get(app.step)
                .and_then(|s| s.lines.get(i))
                .is_some_and(|l| l.format == TraceFormat::Counts)
        })
        .collect();
    let bars_over = v.bars.iter().any(|b| b.values.len() > room);
    let top_lines = lines.len()
        + v.lines.len()
        + v.bars.len()
        + usize::from(!v.bars.is_empty())
        + usize::from(bars_over);
    let drop_counts = usize::from(inner.height) < top_lines + 2;
    lines.extend(
        v.lines
            .iter()
            .zip(&counts)
            .filter(|(_, &c)| !(c && drop_counts))
            .map(|((k, val), _)| {
                Line::from(vec![
                    Span::styled(format!("{k:<lw$}"), Style::default().fg(DIM)),
                    Span::raw(val.clone()),
                ])
            }),
    );
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
    // A blank line before the bars and before the history, when the pane has rows to
    // spare for them (at 60×20 the history needs them).
    let spare = |lines: usize| usize::from(inner.height) >= lines + 2 + 3;
    let bar_lines = v.bars.len() + 2;
    if spare(lines.len() + bar_lines + 1) {
        lines.push(Line::raw(""));
    }
    let mut resampled = None;
    for b in &v.bars {
        let max = scales.iter().find(|s| s.0 == b.group).map_or(0.0, |s| s.1);
        let colour = if b.side == 0 { INNER } else { OUTER };
        let cells = resample_max(&b.values, room);
        if cells.len() < b.values.len() {
            resampled = Some((b.values.len(), cells.len()));
        }
        lines.push(Line::from(vec![
            Span::styled(format!("{:<lw$}", b.label), Style::default().fg(DIM)),
            Span::styled(bar_row(&cells, max), Style::default().fg(colour)),
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
    // Said whenever the bars hold more values than cells: which, and how they were
    // reduced.
    if let Some((n, w)) = resampled {
        let note = format!("{n} values in {w} cells, each the max");
        for part in wrap_words(&note, room) {
            lines.push(Line::styled(
                format!("{:<lw$}{part}", ""),
                Style::default().fg(DIM),
            ));
        }
    }
    let used = lines.len() as u16 + u16::from(spare(lines.len()));
    let [top, history] =
        Layout::vertical([Constraint::Length(used), Constraint::Min(0)]).areas(inner);
    Paragraph::new(lines).render(top, buf);
    // The header and at least the current step's row.
    if history.height < 2 {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Resampling keeps the width, keeps every value in some cell (so the largest and
    /// the smallest of the cells' maxima bound the data), and keeps a one-lamina peak.
    #[test]
    fn resampling_fits_the_width_and_keeps_the_peak() {
        let mut v: Vec<f64> = (0..81).map(|i| f64::from(i % 7)).collect();
        v[40] = 100.0;
        for w in [38, 58, 80] {
            let r = resample_max(&v, w);
            assert_eq!(r.len(), w);
            assert!(r.contains(&100.0), "{w}: the peak survives");
            assert!(
                r.iter().all(|x| x.is_finite()),
                "{w}: every cell covers a value"
            );
        }
        assert_eq!(resample_max(&v, 81), v);
        assert_eq!(resample_max(&v, 200), v);
    }

    /// Wrapping breaks at spaces, never exceeds the width, and loses no word.
    #[test]
    fn wrapping_keeps_every_word() {
        let text = "5 dynamic-load iterations, the last ends at the solution";
        let lines = wrap_words(text, 38);
        assert!(lines.iter().all(|l| l.chars().count() <= 38), "{lines:?}");
        assert_eq!(lines.join(" "), text);
        assert_eq!(wrap_words("abcdef", 4), vec!["abcd", "ef"]);
    }
}
