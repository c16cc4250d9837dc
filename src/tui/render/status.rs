//! The two bottom lines: the status line (solver state, warnings, unsaved mark, edits not
//! yet solved, the last message) and the key hints for the mode and focused pane. Apart
//! because both shrink to the width by their own rules, and the hints change with the key
//! map (`app::KEYS`).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use super::DIM;
use crate::tui::app::{App, Mode, Pane, SolveState};

pub(super) fn render_status(app: &App, area: Rect, buf: &mut Buffer) {
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
                Pane::Text(_) => v(&["jk/hl scroll"]),
                Pane::Sweep(_) | Pane::Job(_) => Vec::new(),
                Pane::Inputs => v(&[
                    "jk move",
                    "Enter edit",
                    "/ find",
                    "^z/^y undo/redo",
                    "^s save",
                ]),
                Pane::Elements => vec![format!("jk {el}"), "hl columns".into()],
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
                Pane::Summary => v(&["jk scroll"]),
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

pub(super) fn render_hints(app: &App, area: Rect, buf: &mut Buffer) {
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
