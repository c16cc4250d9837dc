//! The popups drawn over the frame: the key help table, the error and warnings popup, the
//! path prompt and the yes/no confirmations. Apart because they depend on the mode, not on
//! a pane, and share only their centring.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Cell, Clear, Paragraph, Row, Table, Widget, Wrap};

use super::{ACCENT, DIM};
use crate::bearings::view::column_help;
use crate::tui::app::{App, ExportWhat, Pane, PromptKind, KEYS};

fn centered(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

/// The last error, whole: one message per line, wrapped to the popup, which takes the
/// room it needs up to the screen.
pub(super) fn render_error(title: &str, text: &str, area: Rect, buf: &mut Buffer) {
    let width = area.width.saturating_sub(4).max(10);
    let inner_w = width.saturating_sub(2).max(1) as usize;
    let longest = text.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    let w = ((longest + 2) as u16).clamp(30.min(width), width);
    let inner_w = inner_w.min(w.saturating_sub(2) as usize).max(1);
    // Rows each line takes when wrapped.
    let rows: usize = text
        .lines()
        .map(|l| l.chars().count().div_ceil(inner_w).max(1))
        .sum();
    let h = ((rows + 2) as u16)
        .min(area.height.saturating_sub(2))
        .max(3);
    let r = centered(area, w, h);
    Clear.render(r, buf);
    let lines: Vec<Line> = text.lines().map(|l| Line::raw(l.to_string())).collect();
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_style(Style::default().fg(Color::Red))
                .title(title.to_string()),
        )
        .render(r, buf);
}

/// Words of `text` in lines of at most `width` characters (a longer word is cut).
fn wrap_words(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let len = line.chars().count();
        if len > 0 && len + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// What the focused pane shows, as the help's first rows: the pane, then (for the element
/// table) each column's header in the display units and what it means, from the view's
/// own columns ([`column_help`] of each column's key), so the help cannot drift from the
/// table.
pub(super) fn pane_help(app: &App) -> Vec<(String, String, String)> {
    let view = app.view.as_deref();
    let el = app.element_name();
    let what: String = match app.focus {
        Pane::Inputs => "the deck's fields in the display units; Enter edits one, the deck re-solves".into(),
        Pane::Summary => "the bearing-level answer: life, contact, film, friction, heat, each with where it occurs".into(),
        Pane::Elements => format!("one row per {el}, its columns below"),
        Pane::Chart(n) => match view.and_then(|v| v.charts.get(n)) {
            Some(c) => format!("chart: {}", c.title_in(app.display_units)),
            None => "a chart of the solution".into(),
        },
        Pane::Text(n) => match view.and_then(|v| v.texts.get(n)) {
            Some(t) => t.title.to_string(),
            None => "a block of text of the solution".into(),
        },
        Pane::Sweep(_) => "key outputs against one deck key, solved point by point while the pane is on screen".into(),
        Pane::Thermal => "the thermal network: each node's steady temperature, the transient of the chosen node".into(),
        Pane::Stepper => format!("the equilibrium iterations of the selected {el}, step by step: displacements, residuals, loads along it"),
        Pane::Job(_) => "a long study, run while the pane is on screen (the next edit cancels it)".into(),
        Pane::Study => "a small design study of this deck (a study file naming it, else ±1 % tolerances of its main keys), run while the pane is on screen: one output's histogram, mean/σ/P5/P95, the inputs' rank correlations with it; the next edit cancels it".into(),
    };
    let mut rows = vec![(
        app.pane_title(app.focus).to_string(),
        "this pane".to_string(),
        what,
    )];
    if app.focus == Pane::Elements {
        if let Some(t) = view.and_then(|v| v.screen_table()) {
            rows.extend(t.columns.iter().filter_map(|c| {
                let s = c.screen?;
                Some((
                    s.display.header(s.label, app.display_units),
                    "column".to_string(),
                    column_help(c.key),
                ))
            }));
        }
    }
    rows
}

/// The help: first what the focused pane shows and, for a table, what each of its
/// columns means (`pane`: (name, where, what) rows, from the view's own columns; issue
/// 30 item 16), then the key table: key, where, action (wrapped), scrolled by `scroll`
/// rows when it does not fit; the title says how to scroll then.
pub(super) fn render_help(
    scroll: usize,
    pane: &[(String, String, String)],
    area: Rect,
    buf: &mut Buffer,
) {
    let w = area.width.min(80);
    let (key_w, ctx_w) = (17u16, 13u16);
    let action_w = w.saturating_sub(key_w + ctx_w + 4).max(10) as usize;
    let all = pane
        .iter()
        .map(|(k, c, a)| (k.as_str(), c.as_str(), a.as_str(), true))
        .chain(KEYS.iter().map(|(k, c, a)| (*k, *c, *a, false)));
    let rows: Vec<(Row, u16)> = all
        .map(|(k, ctx, what, about)| {
            let lines = wrap_words(what, action_w);
            let h = lines
                .len()
                .max(ctx.chars().count().div_ceil(ctx_w as usize))
                .max(k.chars().count().div_ceil(key_w as usize)) as u16;
            let key_style = if about { ACCENT } else { Color::Yellow };
            let row = Row::new(vec![
                Cell::from(wrap_words(k, key_w as usize).join("\n"))
                    .style(Style::default().fg(key_style)),
                Cell::from(wrap_words(ctx, ctx_w as usize).join("\n"))
                    .style(Style::default().fg(DIM)),
                Cell::from(lines.join("\n")),
            ])
            .height(h);
            (row, h)
        })
        .collect();
    let total: u16 = rows.iter().map(|r| r.1).sum();
    let h = (total + 3).min(area.height);
    let fits = total + 3 <= area.height;
    let scroll = if fits {
        0
    } else {
        scroll.min(rows.len().saturating_sub(1))
    };
    let room = h.saturating_sub(3);
    let mut used = 0u16;
    let shown = rows
        .iter()
        .skip(scroll)
        .take_while(|r| {
            used += r.1;
            used <= room
        })
        .count();
    let title = if fits {
        " Help (any key closes) ".to_string()
    } else {
        format!(
            " Help {}–{} of {} · j/k scroll, any other key closes ",
            scroll + 1,
            scroll + shown,
            rows.len()
        )
    };
    let r = centered(area, w, h);
    Clear.render(r, buf);
    let block = Block::default()
        .borders(Borders::ALL)
        .border_style(Style::default().fg(ACCENT))
        .title(title);
    let help = Table::new(
        rows.into_iter().skip(scroll).map(|r| r.0),
        [
            Constraint::Length(key_w),
            Constraint::Length(ctx_w),
            Constraint::Min(10),
        ],
    )
    .header(Row::new(vec!["key", "where", "action"]).style(Style::default().fg(ACCENT)))
    .block(block);
    Widget::render(help, r, buf);
}

pub(super) fn render_prompt(kind: PromptKind, text: &str, area: Rect, buf: &mut Buffer) {
    let title = match kind {
        PromptKind::SaveAs => " Save deck as (Enter save, Esc cancel) ",
        PromptKind::Open => " Open deck (Enter open, Esc cancel) ",
        PromptKind::Baseline => " Baseline deck (Enter solve it, Esc cancel) ",
        PromptKind::Export(ExportWhat::Pane) => " Export the pane to (Enter write, Esc cancel) ",
        PromptKind::Export(ExportWhat::Report) => {
            " Report to (.json, .csv, else text; Enter write) "
        }
    };
    let r = centered(area, 64, 3);
    Clear.render(r, buf);
    Paragraph::new(Line::from(vec![
        Span::raw(text.to_string()),
        Span::styled(" ", Style::default().add_modifier(Modifier::REVERSED)),
    ]))
    .block(
        Block::default()
            .borders(Borders::ALL)
            .border_style(Style::default().fg(Color::Yellow))
            .title(title),
    )
    .render(r, buf);
}

pub(super) fn render_confirm(title: &str, text: &str, area: Rect, buf: &mut Buffer) {
    let r = centered(area, 56, 4);
    Clear.render(r, buf);
    Paragraph::new(text.to_string())
        .wrap(Wrap { trim: true })
        .block(
            Block::default()
                .borders(Borders::ALL)
                .border_style(Style::default().fg(Color::Yellow))
                .title(format!(" {title} ")),
        )
        .render(r, buf);
}
