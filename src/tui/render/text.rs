//! A text pane (`Pane::Text(n)`): one of the view's text blocks in the display units,
//! wrapped. Apart because it is the one pane that is plain text.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{no_solution_text, pane_block, stale_note};
use crate::tui::app::{App, Pane};

/// A text pane: block `n` of the view's texts in the display units, wrapped (a line
/// wider than the pane moves to the next line; nothing is cut).
pub(super) fn render_text(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let block = pane_block(app, Pane::Text(n), stale_note(app));
    let inner = block.inner(area);
    block.render(area, buf);
    let Some(view) = app.view.as_deref() else {
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    };
    let lines: Vec<Line> = view
        .texts
        .get(n)
        .map(|t| {
            t.lines(app.display_units)
                .iter()
                .map(|l| Line::raw(l.clone()))
                .collect()
        })
        .unwrap_or_default();
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .render(inner, buf);
}
