//! The Summary pane (issue 28): the bearing-level answer at a glance — the system's
//! [`View::answer`] lines grouped by section, then the solver's state and the warnings,
//! in the display units. Lines wider than the pane wrap (a number is never cut); a list
//! taller than the pane scrolls (`j`/`k`) and the title says what is below.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use super::{no_solution_text, pane_block, stale_note, ACCENT, DIM};
use crate::bearings::view::{AnswerValue, View};
use crate::report::diff::Diff;
use crate::tui::app::{App, Pane, SolveState};
use crate::tui::view_model;
use crate::units::Units;

/// The colour of a line giving the change from the baseline.
const DELTA: ratatui::style::Color = ratatui::style::Color::Magenta;

/// How a line of the pane is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// A section's name.
    Section,
    /// A label and its value.
    Value,
    /// Where a value occurs, or the continuation of a wrapped line.
    Note,
    /// The change of the value above from the baseline's.
    Delta,
}

/// The pane's lines for `view` in `units`, wrapped to `width` cells (the labels in a
/// column as wide as the longest that fits).
pub(crate) fn summary_lines(
    view: &View,
    solver: &str,
    units: Units,
    width: usize,
    baseline: Option<&Diff>,
) -> Vec<(Kind, String)> {
    let width = width.max(20);
    let label_w = view
        .answer
        .iter()
        .map(|a| a.label.chars().count())
        .max()
        .unwrap_or(0)
        .min(width / 2);
    let mut out = Vec::new();
    // Issue 30 item 21: what the deltas are against, first; of another system, that
    // only the lines both report are compared (the `diff` command's rule).
    let deltas = baseline.map(|d| view_model::answer_deltas(d, view, units));
    if let Some(d) = baseline {
        out.push((Kind::Section, "Baseline".to_string()));
        let head = format!(" {} ({})", d.a.0, d.a.1);
        push_wrapped(&mut out, Kind::Value, "", &head, 2, width);
        let note = if d.a.1 == d.b.1 {
            "Δ = now − baseline, % of the baseline".to_string()
        } else {
            format!(
                "another system: only the {} lines both report are compared; Δ = now − \
                 baseline",
                d.outputs.len()
            )
        };
        push_wrapped(&mut out, Kind::Note, " ", &note, 2, width);
    }
    let mut section = "";
    let mut said: Vec<&str> = Vec::new();
    for (i, a) in view.answer.iter().enumerate() {
        if a.section != section {
            section = a.section;
            out.push((Kind::Section, section.to_string()));
        }
        // A reason already given is not repeated in full (ISO 281's P missing takes the
        // basic and modified lives and a_ISO with it).
        let value = match &a.value {
            AnswerValue::Absent(why) if said.contains(&why.as_str()) => "— (as above)".into(),
            AnswerValue::Absent(why) => {
                said.push(why);
                a.shown(units)
            }
            _ => a.shown(units),
        };
        let head = format!(" {:<label_w$}  ", a.label);
        let place = a.place.as_deref().map(|p| format!("at {p}"));
        let joined = match &place {
            Some(p) => format!("{head}{value}  {p}"),
            None => format!("{head}{value}"),
        };
        let indent = head.chars().count().min(width / 2);
        if joined.chars().count() <= width {
            out.push((Kind::Value, joined));
        } else {
            // Too wide: the value wraps under its own column, the place on a line of its
            // own.
            push_wrapped(&mut out, Kind::Value, &head, &value, indent, width);
            if let Some(p) = place {
                push_wrapped(&mut out, Kind::Note, &" ".repeat(indent), &p, indent, width);
            }
        }
        // The change from the baseline on a line of its own under the value (a column
        // would not fit 60 columns), wrapped, never cut.
        let delta = deltas
            .as_ref()
            .and_then(|d| d.get(i).copied().flatten())
            .and_then(|r| view_model::delta_text(r, a));
        if let Some(t) = delta {
            push_wrapped(
                &mut out,
                Kind::Delta,
                &" ".repeat(indent),
                &t,
                indent,
                width,
            );
        }
    }
    out.push((Kind::Section, "Solver".into()));
    push_wrapped(&mut out, Kind::Value, " ", solver, 2, width);
    out.push((Kind::Section, "Warnings".into()));
    if view.warnings.is_empty() {
        out.push((Kind::Value, " none".into()));
    }
    for w in &view.warnings {
        push_wrapped(&mut out, Kind::Value, " • ", w.text(units), 3, width);
    }
    out
}

/// `text` after `head`, wrapped at spaces to `width`, continuation lines indented by
/// `indent`; a word longer than the line is split (never cut).
fn push_wrapped(
    out: &mut Vec<(Kind, String)>,
    kind: Kind,
    head: &str,
    text: &str,
    indent: usize,
    width: usize,
) {
    let mut line = head.to_string();
    let mut first = true;
    let mut empty = true;
    for word in text.split(' ') {
        let len = line.chars().count();
        let wl = word.chars().count();
        if !empty && len + 1 + wl > width {
            out.push((if first { kind } else { Kind::Note }, line));
            first = false;
            line = " ".repeat(indent);
            empty = true;
        }
        if !empty {
            line.push(' ');
        }
        let mut w: String = word.to_string();
        while line.chars().count() + w.chars().count() > width && w.chars().count() > 1 {
            let room = width.saturating_sub(line.chars().count()).max(1);
            let (a, b) = split_at_char(&w, room);
            line.push_str(&a);
            out.push((if first { kind } else { Kind::Note }, line));
            first = false;
            line = " ".repeat(indent);
            w = b;
        }
        line.push_str(&w);
        empty = false;
    }
    out.push((if first { kind } else { Kind::Note }, line));
}

fn split_at_char(s: &str, n: usize) -> (String, String) {
    let a: String = s.chars().take(n).collect();
    let b: String = s.chars().skip(n).collect();
    (a, b)
}

/// The solver's state in words: converged with its iterations and time, or why the last
/// solve failed (the panes then show the last good solution).
pub(crate) fn solver_state(app: &App) -> String {
    match &app.solve {
        SolveState::Solved {
            names,
            iterations,
            roller_iterations,
            wall_ms,
            warm,
        } => format!(
            "converged: {}, {wall_ms:.1} ms",
            super::status::counts_text(*names, *iterations, *roller_iterations, *warm, false)
        ),
        SolveState::Running => "solving…".into(),
        SolveState::Idle => "not solved yet".into(),
        SolveState::Failed(r) => format!("last solve failed (showing the last good one): {r}"),
    }
}

/// The Summary pane.
pub(super) fn render_summary(app: &App, area: Rect, buf: &mut Buffer) {
    let Some(view) = app.view.as_deref() else {
        let block = pane_block(app, Pane::Summary, stale_note(app));
        let inner = block.inner(area);
        block.render(area, buf);
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    };
    let inner_w = area.width.saturating_sub(2) as usize;
    let inner_h = area.height.saturating_sub(2) as usize;
    let diff = app.baseline_diff();
    let lines = summary_lines(
        view,
        &solver_state(app),
        app.display_units,
        inner_w,
        diff.as_ref(),
    );
    let max_scroll = lines.len().saturating_sub(inner_h);
    let scroll = app.summary_scroll.min(max_scroll);
    let below = lines.len().saturating_sub(scroll + inner_h);
    let note = match (scroll, below) {
        (0, 0) => String::new(),
        (_, 0) => format!(" · {scroll} above (k)"),
        (0, b) => format!(" · {b} more (j)"),
        (a, b) => format!(" · {a} above, {b} more"),
    };
    let block = pane_block(app, Pane::Summary, &format!("{}{note}", stale_note(app)));
    let inner = block.inner(area);
    block.render(area, buf);
    let drawn: Vec<Line> = lines
        .into_iter()
        .skip(scroll)
        .take(inner_h)
        .map(|(kind, text)| match kind {
            Kind::Section => Line::from(Span::styled(
                text,
                Style::default().fg(ACCENT).add_modifier(Modifier::BOLD),
            )),
            Kind::Value => Line::raw(text),
            Kind::Note => Line::from(Span::styled(text, Style::default().fg(DIM))),
            Kind::Delta => Line::from(Span::styled(text, Style::default().fg(DELTA))),
        })
        .collect();
    Paragraph::new(drawn).render(inner, buf);
}
