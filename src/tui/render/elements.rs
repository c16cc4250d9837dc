//! The element table (the Rollers or Balls pane): the view's screen table with the
//! selected element highlighted and the first summary values below. Apart because its
//! columns come from the view's table and change with it.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Cell, Paragraph, Row, StatefulWidget, Table, TableState, Widget};

use super::{no_solution_text, pane_block, stale_note, ACCENT, DIM};
use crate::tui::app::{App, Pane};
use crate::tui::view_model::{self, DASH};

/// The element table (Rollers pane): the view's screen table, each column in its display
/// unit and precision; `—` where a stage was not run.
pub(super) fn render_rollers(app: &App, area: Rect, buf: &mut Buffer) {
    let u = app.display_units;
    // The table is laid out for the pane's inner width (2 border cells).
    // Against a baseline (issue 30 item 21): the changes, or why they are not shown.
    let against = app.table_baseline();
    let cells = app.view.as_deref().map(|v| {
        view_model::table_cells_against(
            v,
            against.as_ref().and_then(|a| a.as_ref().ok().copied()),
            u,
            area.width.saturating_sub(2) as usize,
            app.col_scroll,
        )
    });
    // Each note in its long and short form: the short ones when the long ones do not
    // fit the border (at 60 columns "· h l scroll" was cut to "· h l scro").
    let delta = |short: bool| match (&against, short) {
        (None, _) => String::new(),
        (Some(Ok((_, view_model::TableDelta::Percent))), false) => " · Δ % of baseline".into(),
        (Some(Ok((_, view_model::TableDelta::Percent))), true) => " · Δ %".into(),
        (Some(Ok(_)), false) => " · Δ now − baseline".into(),
        (Some(Ok(_)), true) => " · Δ".into(),
        (Some(Err(why)), _) => format!(" · Δ {why}"),
    };
    // What is in view of how many, and how to reach the rest (issue 30 item 15).
    let hidden = |short: bool| match &cells {
        Some(c) if c.hidden > 0 && !short => format!(
            " · columns {}–{} of {} · h l scroll",
            c.range[0], c.range[1], c.total
        ),
        Some(c) if c.hidden > 0 => format!(" · {}–{}/{} h l", c.range[0], c.range[1], c.total),
        _ => String::new(),
    };
    let stale = stale_note(app);
    // Room inside the border: 2 corners and the 2 spaces around the title.
    let room =
        usize::from(area.width).saturating_sub(4 + app.pane_title(Pane::Elements).chars().count());
    let title = [false, true]
        .iter()
        .map(|&short| format!("{}{stale}{}", delta(short), hidden(short)))
        .find(|t| t.chars().count() <= room)
        .unwrap_or_else(|| format!("{}{stale}{}", delta(true), hidden(true)));
    let block = pane_block(app, Pane::Elements, &title);
    let inner = block.inner(area);
    block.render(area, buf);
    let (Some(view), Some(cells)) = (app.view.as_deref(), cells) else {
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    };
    let [table_area, foot] =
        Layout::vertical([Constraint::Min(0), Constraint::Length(1)]).areas(inner);
    // Numbers are right-aligned, and so are their headers.
    let header = Row::new(
        cells
            .columns
            .iter()
            .map(|c| Cell::from(Line::from(c.header.clone()).right_aligned())),
    )
    .style(Style::default().fg(ACCENT).add_modifier(Modifier::BOLD));
    let gap = cells.gap;
    let rows = cells.rows.into_iter().map(|r| {
        Row::new(r.into_iter().map(|c| {
            let style = if c == DASH {
                Style::default().fg(DIM)
            } else {
                Style::default()
            };
            Cell::from(Line::from(c).right_aligned()).style(style)
        }))
    });
    let widths: Vec<Constraint> = cells
        .columns
        .iter()
        .map(|c| Constraint::Length(c.width))
        .collect();
    let table = Table::new(rows, widths)
        .header(header)
        .column_spacing(gap)
        .flex(ratatui::layout::Flex::Start)
        .row_highlight_style(Style::default().fg(Color::Black).bg(Color::Yellow));
    let mut state = TableState::default().with_selected(Some(app.roller_sel));
    StatefulWidget::render(table, table_area, buf, &mut state);
    let text: Vec<String> = view
        .summary
        .iter()
        .take(2)
        .map(|s| {
            format!(
                "{} {}",
                s.display.header(s.label, u),
                view_model::fixed(s.display.convert(s.value, u), s.precision)
            )
        })
        .collect();
    Paragraph::new(text.join("  "))
        .style(Style::default().fg(DIM))
        .render(foot, buf);
}
