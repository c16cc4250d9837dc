//! A heat map ([`HeatMap`]): a grid of values over two variables in six colours (low
//! blue to high red), excluded cells as their glyph, marked cells as theirs, the axes'
//! end and middle values, and a legend saying what each colour, glyph and mark means.
//! Generic: nothing here knows what the variables are.
//!
//! A cell is two columns wide when the width allows, else one; one grid row per line
//! when the height allows, else two per line in half blocks (`▀`, the upper cell's colour
//! over the lower's): a 21 × 21 grid fits 80×24 and 60×20. In half blocks a line holding
//! an excluded or marked cell shows its glyph (the other cell's colour behind it).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::DIM;
use crate::bearings::view::{HeatCell, HeatMap};
use crate::tui::view_model;
use crate::units::Units;

/// The value colours, lowest first.
const LEVELS: [Color; 6] = [
    Color::Blue,
    Color::Cyan,
    Color::Green,
    Color::Yellow,
    Color::LightRed,
    Color::Red,
];

/// How the map is laid out in an area.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Fit {
    /// Columns per cell (1 or 2).
    cell_w: u16,
    /// Grid rows per line (1 or 2).
    rows_per_line: usize,
    /// Width of the y labels.
    label_w: u16,
}

fn fit(m: &HeatMap, u: Units, area: Rect) -> Fit {
    let label_w = y_labels(m, u)
        .iter()
        .map(|s| s.chars().count())
        .max()
        .unwrap_or(0) as u16
        + 1;
    let nx = m.xs.len() as u16;
    let cell_w = if label_w + 2 * nx <= area.width { 2 } else { 1 };
    // Head line, x labels and at least two legend lines besides the grid.
    let rows_per_line = if m.ys.len() + 4 <= usize::from(area.height) {
        1
    } else {
        2
    };
    Fit {
        cell_w,
        rows_per_line,
        label_w,
    }
}

/// The width the map wants inside `area` (its grid and labels, at least 30 columns for
/// its legend; at most the area's), and its height without and with its legend at that
/// width (which may exceed the area's).
pub(super) fn natural_size(m: &HeatMap, u: Units, area: Rect) -> (u16, u16, u16) {
    let f = fit(m, u, area);
    let grid_w = f.label_w + f.cell_w * m.xs.len() as u16;
    let w = grid_w.max(30).min(area.width);
    // Head line, grid lines, x labels.
    let bare = m.ys.len().div_ceil(f.rows_per_line) as u16 + 2;
    let legend = legend_lines(m, u, w).len() as u16;
    (w, bare, bare + legend)
}

fn y_labels(m: &HeatMap, u: Units) -> [String; 3] {
    let (lo, hi) = (
        m.ys.first().copied().unwrap_or(0.0),
        m.ys.last().copied().unwrap_or(0.0),
    );
    let prec = axis_precision(lo, hi, m.ys.len());
    let c = |v: f64| view_model::fixed(m.y.display.convert(v, u), prec);
    [c(hi), c(0.5 * (lo + hi)), c(lo)]
}

/// Decimals that tell neighbouring grid values apart.
fn axis_precision(lo: f64, hi: f64, n: usize) -> usize {
    let step = (hi - lo).abs() / (n.max(2) - 1) as f64;
    if step > 0.0 && step.is_finite() {
        (-step.log10()).ceil().clamp(0.0, 8.0) as usize
    } else {
        2
    }
}

/// The value range of the map's values, if any.
fn range(m: &HeatMap) -> Option<(f64, f64)> {
    let (lo, hi) = m
        .cells
        .iter()
        .filter_map(|c| match c {
            HeatCell::Value(v) | HeatCell::Excluded(_, Some(v)) if v.is_finite() => Some(*v),
            _ => None,
        })
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    lo.is_finite().then_some((lo, hi))
}

fn level(v: f64, (lo, hi): (f64, f64)) -> Color {
    let k = if hi > lo {
        ((v - lo) / (hi - lo) * LEVELS.len() as f64).floor() as usize
    } else {
        0
    };
    LEVELS[k.min(LEVELS.len() - 1)]
}

/// The legend: the colour scale with its range, the excluded glyphs present, the marks
/// (packed into lines of `width`, an item never split).
pub(super) fn legend_lines(m: &HeatMap, u: Units, width: u16) -> Vec<Line<'static>> {
    let (label, display, prec) = m.value;
    let mut spans: Vec<Span<'static>> = Vec::new();
    match range(m) {
        Some((lo, hi)) => {
            spans.push(Span::raw(format!(
                "{label} {} ",
                view_model::fixed(display.convert(lo, u), prec)
            )));
            for c in LEVELS {
                spans.push(Span::styled("█", Style::default().fg(c)));
            }
            spans.push(Span::raw(format!(
                " {} {}",
                view_model::fixed(display.convert(hi, u), prec),
                display.unit(u)
            )));
        }
        None => spans.push(Span::styled(
            format!("{label}: none solved yet"),
            Style::default().fg(DIM),
        )),
    }
    let mut items: Vec<String> = Vec::new();
    if m.cells.contains(&HeatCell::Pending) {
        items.push("· pending".into());
    }
    for (k, (glyph, why)) in m.excluded.iter().enumerate() {
        if m.cells
            .iter()
            .any(|c| matches!(c, HeatCell::Excluded(e, _) if *e == k))
        {
            items.push(format!("{glyph} {why}"));
        }
    }
    for mk in &m.marks {
        items.push(format!("{} {}", mk.glyph, mk.label));
    }
    let mut lines = vec![Line::from(spans)];
    // The items packed into lines of the width (an item never split).
    let mut cur = String::new();
    for it in items {
        let sep = if cur.is_empty() { "" } else { " · " };
        if !cur.is_empty()
            && cur.chars().count() + sep.len() + it.chars().count() > usize::from(width)
        {
            lines.push(Line::raw(std::mem::take(&mut cur)));
            cur = it;
        } else {
            cur.push_str(sep);
            cur.push_str(&it);
        }
    }
    if !cur.is_empty() {
        lines.push(Line::raw(cur));
    }
    lines
}

/// Draws `m` in `area`: a head line (its title and which variable runs along which
/// axis), the grid with its y labels, the x labels and, `with_legend`, the legend below
/// (else the caller draws [`legend_lines`] where there is room).
pub(super) fn render_heat_map(
    m: &HeatMap,
    u: Units,
    area: Rect,
    buf: &mut Buffer,
    with_legend: bool,
) {
    if area.width < 8 || area.height < 4 {
        return;
    }
    let f = fit(m, u, area);
    let nx = m.xs.len();
    let ny = m.ys.len();
    let lines = ny.div_ceil(f.rows_per_line);
    let mut y = area.y;
    let bottom = area.bottom();
    let put = |buf: &mut Buffer, x: u16, y: u16, s: &str, st: Style| {
        if y < bottom && x < area.right() {
            buf.set_stringn(x, y, s, usize::from(area.right() - x), st);
        }
    };
    let names = format!(
        "→ {}  ↑ {}",
        m.x.display.header(m.x.label, u),
        m.y.display.header(m.y.label, u)
    );
    let head = format!("{} {names}", m.title);
    let head = if head.chars().count() <= usize::from(area.width) {
        head
    } else {
        names
    };
    put(buf, area.x, y, &head, Style::default());
    y += 1;
    let ylab = y_labels(m, u);
    let r = range(m);
    let mark_at = |i: usize, j: usize| m.marks.iter().find(|k| k.i == i && k.j == j);
    let colour = |c: HeatCell| match (c, r) {
        (HeatCell::Value(v) | HeatCell::Excluded(_, Some(v)), Some(r)) => Some(level(v, r)),
        _ => None,
    };
    for line in 0..lines {
        if y >= bottom {
            return;
        }
        // Grid rows of this line, top first (row ny-1 at the top).
        let top = ny - 1 - line * f.rows_per_line;
        let low = (f.rows_per_line == 2 && top >= 1).then(|| top - 1);
        let label = if line == 0 {
            Some(&ylab[0])
        } else if line == lines - 1 {
            Some(&ylab[2])
        } else if line == (lines - 1) / 2 {
            Some(&ylab[1])
        } else {
            None
        };
        if let Some(l) = label {
            let pad = usize::from(f.label_w - 1).saturating_sub(l.chars().count());
            put(
                buf,
                area.x,
                y,
                &format!("{}{l}", " ".repeat(pad)),
                Style::default().fg(DIM),
            );
        }
        for i in 0..nx {
            let x = area.x + f.label_w + f.cell_w * i as u16;
            if x + f.cell_w > area.right() {
                break;
            }
            let upper = m.cell(i, top);
            let lower = low.map(|j| m.cell(i, j));
            let mark = mark_at(i, top).or_else(|| low.and_then(|j| mark_at(i, j)));
            let glyph_of = |c: HeatCell| match c {
                HeatCell::Excluded(k, _) => m.excluded.get(k).map(|e| e.0),
                _ => None,
            };
            let excluded = glyph_of(upper).or_else(|| lower.and_then(glyph_of));
            let (sym, st) = if let Some(mk) = mark {
                (
                    mk.glyph.to_string(),
                    Style::default()
                        .fg(Color::White)
                        .add_modifier(Modifier::BOLD),
                )
            } else if let Some(g) = excluded {
                // The excluded cell's value (or the other cell's) behind its glyph.
                let behind = match (glyph_of(upper), lower) {
                    (Some(_), _) => colour(upper).or_else(|| lower.and_then(colour)),
                    (None, Some(l)) => colour(l).or_else(|| colour(upper)),
                    (None, None) => None,
                };
                let mut st = Style::default().fg(Color::White);
                if let Some(b) = behind {
                    st = st.bg(b).fg(Color::Black);
                }
                (g.to_string(), st)
            } else {
                match (colour(upper), lower.map(colour)) {
                    (Some(a), Some(Some(b))) => ("▀".to_string(), Style::default().fg(a).bg(b)),
                    (Some(a), None) => ("█".to_string(), Style::default().fg(a)),
                    (Some(a), Some(None)) => ("▀".to_string(), Style::default().fg(a)),
                    (None, Some(Some(b))) => ("▄".to_string(), Style::default().fg(b)),
                    _ => ("·".to_string(), Style::default().fg(DIM)),
                }
            };
            let fill = if f.cell_w == 2 {
                // A value's block fills both columns; a glyph has a blank beside it (in
                // the cell's colour).
                if sym == "█" || sym == "▀" || sym == "▄" {
                    sym.repeat(2)
                } else {
                    format!("{sym} ")
                }
            } else {
                sym
            };
            put(buf, x, y, &fill, st);
        }
        y += 1;
    }
    // x labels: the ends and the middle under their cells.
    if y < bottom && nx > 0 {
        let (lo, hi) = (m.xs[0], m.xs[nx - 1]);
        let prec = axis_precision(lo, hi, nx);
        let c = |v: f64| view_model::fixed(m.x.display.convert(v, u), prec);
        let x0 = area.x + f.label_w;
        let span = f.cell_w * nx as u16;
        let left = c(lo);
        let mid = c(0.5 * (lo + hi));
        let right = c(hi);
        put(buf, x0, y, &left, Style::default().fg(DIM));
        let mx = (x0 + span / 2).saturating_sub(mid.chars().count() as u16 / 2);
        if mx > x0 + left.chars().count() as u16 {
            put(buf, mx, y, &mid, Style::default().fg(DIM));
        }
        let rx = (x0 + span).saturating_sub(right.chars().count() as u16);
        if rx > mx + mid.chars().count() as u16 {
            put(buf, rx, y, &right, Style::default().fg(DIM));
        }
        y += 1;
    }
    if with_legend && y < bottom {
        let rest = Rect::new(area.x, y, area.width, bottom - y);
        Paragraph::new(legend_lines(m, u, area.width))
            .wrap(Wrap { trim: false })
            .render(rest, buf);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::view::{ChartAxis, Display, HeatMark};

    fn map(n: usize) -> HeatMap {
        let axis: Vec<f64> = (0..n)
            .map(|i| 0.995 + 0.01 * i as f64 / (n - 1) as f64)
            .collect();
        let mut cells = Vec::new();
        for j in 0..n {
            for i in 0..n {
                cells.push(if i + j > 2 * n - 4 {
                    HeatCell::Excluded(0, Some((i + j) as f64))
                } else {
                    HeatCell::Value((i + j) as f64)
                });
            }
        }
        HeatMap {
            title: "loss".into(),
            x: ChartAxis {
                label: "kx",
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: "ky",
                display: Display::Plain,
                bounds: None,
            },
            xs: axis.clone(),
            ys: axis,
            value: ("loss", Display::Power, 1),
            cells,
            excluded: vec![('c', "capacity below nominal".into())],
            marks: vec![HeatMark {
                i: n / 2,
                j: n / 2,
                glyph: 'N',
                label: "nominal",
            }],
        }
    }

    fn text(buf: &Buffer) -> String {
        let a = buf.area;
        (a.top()..a.bottom())
            .map(|y| {
                (a.left()..a.right())
                    .map(|x| buf[(x, y)].symbol().to_string())
                    .collect::<String>()
            })
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// A 21 × 21 map fits in 18 lines (two grid rows per line) at 50 columns (two per
    /// cell) and in 17 at 30 (one per cell, the legend on more lines); every excluded
    /// cell's glyph, the mark and the legend naming both show; the axes' ends are
    /// labelled and named. With room for one row per line (50 lines), every grid row
    /// has its own line: the glyph count is the excluded cell count.
    #[test]
    fn a_grid_fits_and_says_what_its_glyphs_mean() {
        let m = map(21);
        let excluded = m
            .cells
            .iter()
            .filter(|c| matches!(c, HeatCell::Excluded(..)))
            .count();
        for (w, h) in [(50, 18), (30, 17)] {
            let area = Rect::new(0, 0, w, h);
            let mut buf = Buffer::empty(area);
            render_heat_map(&m, Units::Si, area, &mut buf, true);
            let t = text(&buf);
            assert!(t.contains('N') && t.contains("N nominal"), "{t}");
            assert!(t.contains("c capacity below nominal"), "{t}");
            assert!(t.contains("0.995") && t.contains("1.005"), "{t}");
            assert!(t.contains("W") && t.contains("→ kx  ↑ ky"), "{t}");
        }
        let area = Rect::new(0, 0, 60, 50);
        let mut buf = Buffer::empty(area);
        render_heat_map(&m, Units::Si, area, &mut buf, true);
        let t = text(&buf);
        let grid: String = t.lines().skip(1).take(21).collect();
        assert_eq!(grid.matches('c').count(), excluded, "{t}");
        assert_eq!(fit(&m, Units::Si, area).rows_per_line, 1);
    }
}
