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

/// A solve's iteration counts in the one vocabulary the status line and the Summary pane
/// share (issue 30 item 12): both counts named by what they count (`13 ring + 96 roller
/// iterations`), and said to start from the last answer after a warm start (a tapered
/// re-solve of an unchanged deck for its Sweep pane counts 0 + 0 from there). `short`
/// drops the names' word "iterations" for "it".
pub(crate) fn counts_text(
    names: [&str; 2],
    iterations: usize,
    inner: usize,
    warm: bool,
    short: bool,
) -> String {
    let what = if short { "it" } else { "iterations" };
    let warm = match (warm, short) {
        (false, _) => "",
        (true, false) => " from the last answer",
        (true, true) => " (warm)",
    };
    format!(
        "{iterations} {} + {inner} {} {what}{warm}",
        names[0], names[1]
    )
}

pub(super) fn render_status(app: &App, area: Rect, buf: &mut Buffer) {
    let (text, color) = match &app.solve {
        SolveState::Idle => ("idle".to_string(), DIM),
        SolveState::Running => ("● solving…".to_string(), Color::Yellow),
        SolveState::Solved {
            names,
            iterations,
            roller_iterations,
            wall_ms,
            warm,
        } => {
            // One form per terminal width, whatever else the line holds (issue 30 item
            // 12: the form used to change with the warnings and messages beside it,
            // `solved in 13 ring + 96 roller iterations` → `15+184 it`).
            let c = |short| counts_text(*names, *iterations, *roller_iterations, *warm, short);
            let text = match area.width {
                120.. => format!("✓ solved in {}, {wall_ms:.1} ms", c(false)),
                80.. => format!("✓ {}, {wall_ms:.1} ms", c(true)),
                _ => format!(
                    "✓ {}+{} it{}, {wall_ms:.1} ms",
                    iterations,
                    roller_iterations,
                    if *warm { " (warm)" } else { "" }
                ),
            };
            (text, Color::Green)
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

/// The status line after the solver state: the baseline, warnings, unsaved, edits not
/// solved, message.
fn status_extras(app: &App) -> Vec<Span<'static>> {
    let mut spans = Vec::new();
    // First: what the Summary's Δ are against (issue 30 item 21).
    // The file name only: the status line is one row (a deck path cut at 60 columns said
    // nothing); the Summary's Baseline section gives the whole path.
    if let Some(b) = &app.baseline {
        let name = std::path::Path::new(&b.name)
            .file_name()
            .map_or_else(|| b.name.clone(), |n| n.to_string_lossy().into_owned());
        spans.push(Span::styled(
            format!(" │ baseline: {name}"),
            Style::default().fg(Color::Magenta),
        ));
    }
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
        Mode::ConfirmQuit
        | Mode::ConfirmRevert
        | Mode::ConfirmOverwrite { .. }
        | Mode::ConfirmExport { .. } => (v(&["answer the prompt"]), Vec::new()),
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
                Pane::Study => v(&["jk output", "hl samples"]),
                Pane::Inputs => v(&[
                    "jk move",
                    "Enter edit",
                    "/ find",
                    "^z/^y undo/redo",
                    "^s save",
                ]),
                Pane::Elements => {
                    let mut h = vec![format!("jk {el}"), "hl columns".into()];
                    // With a baseline, how to see the table's changes from it.
                    if app.baseline.is_some() {
                        h.push("d Δ".into());
                    }
                    h
                }
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
            first.push("x export".into());
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
