//! The header line: the pane tabs (numbered, the focused one highlighted, the hidden ones
//! dim) and, on the right, the deck's file, its unsaved mark and the display units. Apart
//! because its fitting rules (which details to drop, when the tabs close up to one space,
//! when they shrink to numbers) are its own.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::{ACCENT, DIM};
use crate::tui::app::App;
use crate::tui::deck_io;

pub(super) fn render_header(app: &App, area: Rect, buf: &mut Buffer) {
    let wide = area.width >= 100;
    let file = app
        .path
        .as_ref()
        .and_then(|p| p.file_name())
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "(no file)".into());
    // The right side, most to least informative: the first that fits with the full tab
    // labels is drawn; else the tabs shrink to numbers (the focused one keeps its title)
    // so the file, the unsaved mark and the units always show.
    let right = |detail: String| {
        let mut r = vec![Span::raw(file.clone())];
        if app.unsaved() {
            r.push(Span::styled(" [+]", Style::default().fg(Color::Yellow)));
        }
        r.push(Span::raw(detail));
        r.push(Span::styled(
            format!(" {} ", deck_io::units_label(app.display_units)),
            Style::default().fg(Color::Black).bg(Color::Gray),
        ));
        Line::from(r)
    };
    // Tightness 0: full labels; 1: full labels one space apart; 2: numbers (the focused
    // one titled). `abbrev` = Some(k) shortens the other titles to their first k
    // characters (issue 30 item 16: at 60 columns the tabs were bare numbers, ` 1  2:Rollers
    // 3  4  5`, and no pane said what it was).
    let tabs = |tightness: u8, abbrev: Option<usize>| {
        let compact = tightness == 2;
        let mut spans = Vec::new();
        if tightness == 1 {
            spans.push(Span::raw(" "));
        }
        if wide && !compact && abbrev.is_none() {
            spans.push(Span::styled(
                " rollbench ",
                Style::default()
                    .fg(Color::Black)
                    .bg(ACCENT)
                    .add_modifier(Modifier::BOLD),
            ));
        }
        for (i, p) in app.panes().iter().enumerate() {
            let title = app.pane_title(*p);
            let label = if compact && *p != app.focus {
                format!(" {} ", i + 1)
            } else if let (Some(k), false) = (abbrev, *p == app.focus) {
                format!("{}:{} ", i + 1, title.chars().take(k).collect::<String>())
            } else if tightness == 1 {
                format!("{}:{title} ", i + 1)
            } else {
                format!(" {}:{title} ", i + 1)
            };
            let style = if *p == app.focus {
                Style::default().fg(Color::Black).bg(Color::White)
            } else if app.visible(*p) {
                Style::default().fg(Color::White)
            } else {
                Style::default().fg(DIM)
            };
            spans.push(Span::styled(label, style));
        }
        Line::from(spans)
    };
    let mut details = Vec::new();
    if wide {
        details.push(format!(" · {} · {}", app.deck.name(), app.deck.system_id()));
        details.push(format!(" · {}", app.deck.name()));
    }
    details.push(String::new());
    let mut choice = None;
    // Full labels, then one space apart, then the others' titles cut to 6…2 characters,
    // then numbers.
    let modes = [(0, None), (1, None)]
        .into_iter()
        .chain((2..=6).rev().map(|k| (1, Some(k))))
        .chain(std::iter::once((2, None)));
    'outer: for (tightness, abbrev) in modes {
        let t = tabs(tightness, abbrev);
        for d in &details {
            let r = right(d.clone());
            if t.width() + 1 + r.width() <= area.width as usize {
                choice = Some((t, r));
                break 'outer;
            }
        }
    }
    let (t, r) = choice.unwrap_or_else(|| (tabs(2, None), Line::default()));
    t.render(area, buf);
    let w = (r.width() as u16).min(area.width);
    if w > 0 {
        let rr = Rect {
            x: area.x + area.width - w,
            width: w,
            ..area
        };
        r.render(rr, buf);
    }
}
