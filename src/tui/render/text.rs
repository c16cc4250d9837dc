//! A text pane (`Pane::Text(n)`): one of the view's text blocks in the display units.
//! Apart because it is the one pane that is plain text.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

use super::{no_solution_text, pane_block, stale_note};
use crate::tui::app::{App, Pane};

/// A text pane: block `n` of the view's texts in the display units, each line on one
/// row (a matrix row wrapped onto two is misread: issue 30 item 5), scrolled with
/// `j`/`k`/`g`/`G` and `h`/`l` when it does not fit; the title says which lines and
/// columns are in view.
pub(super) fn render_text(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let text: &[String] = app
        .view
        .as_deref()
        .and_then(|v| v.texts.get(n))
        .map_or(&[], |t| t.lines(app.display_units));
    let (rows, cols) = (
        usize::from(area.height.saturating_sub(2)),
        usize::from(area.width.saturating_sub(2)),
    );
    let widest = text.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    let top = app.text_scroll.min(text.len().saturating_sub(rows));
    let left = app.col_scroll.min(widest.saturating_sub(cols));
    let mut note = String::new();
    if text.len() > rows && rows > 0 {
        let last = (top + rows).min(text.len());
        note.push_str(&format!(
            " · lines {}–{last} of {} · j k",
            top + 1,
            text.len()
        ));
    }
    if widest > cols && cols > 0 {
        let last = (left + cols).min(widest);
        note.push_str(&format!(" · columns {}–{last} of {widest} · h l", left + 1));
    }
    let block = pane_block(app, Pane::Text(n), &format!("{}{note}", stale_note(app)));
    let inner = block.inner(area);
    block.render(area, buf);
    if app.view.is_none() {
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    }
    let lines: Vec<Line> = text
        .iter()
        .skip(top)
        .take(rows)
        .map(|l| Line::raw(window(l, left, cols)))
        .collect();
    Paragraph::new(lines).render(inner, buf);
}

/// Characters `left .. left + cols` of `line`, with a word cut by either edge blanked: a
/// number is shown whole or not at all (`-7.2947e-21` cut to `-7.29` would misread).
pub(super) fn window(line: &str, left: usize, cols: usize) -> String {
    let chars: Vec<char> = line.chars().collect();
    let end = (left + cols).min(chars.len());
    let mut shown: Vec<char> = chars.get(left..end).unwrap_or(&[]).to_vec();
    let word = |c: Option<&char>| c.is_some_and(|c| !c.is_whitespace());
    if word(chars.get(end)) {
        for c in shown.iter_mut().rev().take_while(|c| !c.is_whitespace()) {
            *c = ' ';
        }
    }
    if left > 0 && word(chars.get(left - 1)) {
        for c in shown.iter_mut().take_while(|c| !c.is_whitespace()) {
            *c = ' ';
        }
    }
    shown.into_iter().collect::<String>().trim_end().to_string()
}

#[cfg(test)]
mod tests {
    use super::window;

    /// A number cut by an edge is blanked, never shown in part.
    #[test]
    fn a_cut_number_is_not_shown() {
        let line = "  M_y  9.9907e6  -7.2947e-21";
        assert_eq!(window(line, 0, 24), "  M_y  9.9907e6");
        assert_eq!(window(line, 0, 28), line);
        assert_eq!(window(line, 9, 19), "        -7.2947e-21");
    }
}
