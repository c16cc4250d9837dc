//! The Inputs pane: the deck's fields by group, their values and units, the field under
//! edit with its cursor and error, and the help or search line below. The only pane that
//! edits; apart because editing's drawing changes with the edit keys, not with the
//! solution.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{pane_block, ACCENT, DIM};
use crate::tui::app::{App, Mode, Pane};
use crate::tui::deck_io;

fn truncate(s: &str, w: usize) -> String {
    if s.chars().count() <= w {
        format!("{s:<w$}")
    } else {
        let mut t: String = s.chars().take(w.saturating_sub(1)).collect();
        t.push('…');
        t
    }
}

pub(super) fn render_inputs(app: &App, area: Rect, buf: &mut Buffer) {
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
                // First, so the two lines never cut it (issue 30 item 7).
                let note = app
                    .deck
                    .us_customary_note(f.key, app.display_units)
                    .map(|n| format!("{n}. "))
                    .unwrap_or_default();
                format!("{}: {note}{}. Allowed {allowed}.", f.key, f.help)
            })
            .unwrap_or_default(),
    };
    Paragraph::new(text)
        .style(Style::default().fg(DIM))
        .wrap(Wrap { trim: true })
        .render(about, buf);
}
