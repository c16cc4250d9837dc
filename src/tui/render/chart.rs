//! The chart panes (`Pane::Chart(n)`: the rollers' load, the ball's skid, dynamics and
//! traction): one of the view's charts, the streamed one while a solve fills it, or the
//! selected element's chart; and the chart drawing the sweep and thermal panes share
//! (series colours, axes, labels).

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Line;
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, LegendPosition, Paragraph, Widget};

use super::{no_solution_text, pane_block, stale_note, DIM, SERIES_COLOURS};
use crate::tui::app::{App, Pane};
use crate::tui::view_model;

/// The colour of the deck's operating marker (no series has it; the selected element's
/// marks are white blocks, not a line).
pub(super) const OPERATING: Color = Color::White;

/// Decimals that keep an axis's labels distinct: none from 100 up, more below, and at
/// least enough that the three labels (ends and middle) differ in their last two digits
/// (±1 mm/s at three decimals of m/s would read 0.001, 0.000, -0.001).
fn label_precision(b: [f64; 2]) -> usize {
    // The larger end's size: an axis of −500…0 needs no decimals (it printed −500.000
    // when only the upper end, 0, was looked at).
    let by_size = match b[0].abs().max(b[1].abs()) {
        m if m >= 100.0 => 0,
        m if m >= 10.0 => 1,
        m if m >= 1.0 => 2,
        _ => 3,
    };
    let step = 0.5 * (b[1] - b[0]).abs();
    let by_step = if step.is_finite() && step > 0.0 {
        (-step.log10()).ceil().clamp(-1.0, 8.0) as i64 + 1
    } else {
        0
    };
    by_size.max(usize::try_from(by_step).unwrap_or(0))
}

pub(super) fn axis_labels(b: [f64; 2], prec: usize) -> Vec<Line<'static>> {
    let mid = 0.5 * (b[0] + b[1]);
    [b[0], mid, b[1]]
        .iter()
        .map(|v| Line::from(view_model::fixed(*v, prec)))
        .collect()
}

/// A chart pane: bearing chart `n` of the view (as streamed while the solve runs, when
/// the session streams it), or on the view's `element_chart_pane` with `c` the selected
/// element's chart (a roller's laminae, a ball's motion).
pub(super) fn render_load(app: &App, n: usize, area: Rect, buf: &mut Buffer) {
    let pane = Pane::Chart(n);
    // A chart the running solve streams (the ball's skidding search) is drawn as it
    // grows, in place of the last solution's.
    let view = app.view.as_deref();
    let element_mode = app.chart_laminae && view.is_some_and(|v| v.element_chart_pane == n);
    let streamed = app.streamed_chart(n).filter(|_| !element_mode);
    if view.is_none() && streamed.is_none() {
        let block = pane_block(app, pane, "");
        let inner = block.inner(area);
        block.render(area, buf);
        Paragraph::new(no_solution_text(app)).render(inner, buf);
        return;
    }
    let chart = match (streamed, view) {
        (Some(c), _) => Some(c),
        (None, Some(view)) if element_mode => view.element_charts.get(app.roller_sel),
        (None, Some(view)) => view.charts.get(n),
        (None, None) => None,
    };
    let Some(c) = chart else {
        pane_block(app, pane, "").render(area, buf);
        return;
    };
    // The baseline's same chart, overlaid dimmed (issue 30 item 21): a design of the
    // same system, its chart `n` or the same element's chart.
    let base = app
        .baseline
        .as_ref()
        .filter(|b| view.is_some_and(|v| v.system == b.view.system))
        .and_then(|b| {
            if element_mode {
                let same_count =
                    view.is_some_and(|v| v.element_charts.len() == b.view.element_charts.len());
                same_count
                    .then(|| b.view.element_charts.get(app.roller_sel))
                    .flatten()
            } else {
                b.view.charts.get(n)
            }
        });
    // One panel per y unit (issue 30 item 1), stacked on one x axis.
    let panels = view_model::chart_panels_against(c, base, app.display_units);
    let Some(s) = panels.first() else {
        pane_block(app, pane, "").render(area, buf);
        return;
    };
    // The title in what the border leaves (2 corners, 2 spaces, the pane's name, " · "
    // and the stale note), clause by clause: never a cut number.
    let stale = stale_note(app);
    let room = usize::from(area.width)
        .saturating_sub(7 + app.pane_title(pane).chars().count() + stale.chars().count());
    let title = view_model::fit_title(&s.title, room);
    let extra = if title.is_empty() {
        stale.to_string()
    } else {
        format!(" · {title}{stale}")
    };
    let block = pane_block(app, pane, &extra);
    let marked: Vec<Vec<(f64, f64)>> = panels
        .iter()
        .map(|p| {
            if c.per_element {
                p.series
                    .iter()
                    .filter_map(|(_, v)| v.get(app.roller_sel).copied())
                    .collect()
            } else {
                Vec::new()
            }
        })
        .collect();
    let mark_name = format!("{} {}", app.element_name(), app.element_number());
    if panels.len() == 1 {
        draw_chart(s, with_marks(s, &marked[0], &mark_name), block, area, buf);
        return;
    }
    // Several units: the pane's border once, the panels stacked inside it, each with its
    // own y axis and legend; the series keep their colours across panels.
    let inner = block.inner(area);
    block.render(area, buf);
    let rows = Layout::vertical(vec![Constraint::Fill(1); panels.len()]).split(inner);
    let mut colour = 0;
    for ((p, m), r) in panels.iter().zip(&marked).zip(rows.iter()) {
        // The dimmed baseline comes first, then the panel's series, then the marks.
        let own = p.baseline.len()..p.baseline.len() + p.series.len();
        let datasets = with_marks(p, m, &mark_name)
            .into_iter()
            .enumerate()
            .map(|(k, d)| {
                if own.contains(&k) {
                    d.style(
                        Style::default().fg(SERIES_COLOURS
                            .get(colour + k - own.start)
                            .copied()
                            .unwrap_or(Color::White)),
                    )
                } else {
                    d
                }
            })
            .collect();
        colour += p.series.len();
        draw_chart(p, datasets, Block::default(), *r, buf);
    }
}

/// `p`'s series and, when `m` holds points, the selected element's marks named `name`.
fn with_marks<'a>(
    p: &'a view_model::ChartSeries,
    m: &'a [(f64, f64)],
    name: &str,
) -> Vec<Dataset<'a>> {
    let mut datasets = series_datasets(p);
    if !m.is_empty() {
        datasets.push(
            Dataset::default()
                .name(name.to_string())
                .marker(Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(Style::default().fg(Color::White))
                .data(m),
        );
    }
    datasets
}

/// One line per series of `s`, in the series colours, over the baseline's series
/// (drawn first, dimmed, one legend entry `baseline (dim)` for them all).
pub(super) fn series_datasets(s: &view_model::ChartSeries) -> Vec<Dataset<'_>> {
    let baseline = s.baseline.iter().enumerate().map(|(k, (_, points))| {
        let d = Dataset::default()
            .marker(Marker::Braille)
            .graph_type(GraphType::Line)
            .style(Style::default().fg(DIM))
            .data(points);
        if k == 0 {
            d.name(BASELINE_LEGEND)
        } else {
            d
        }
    });
    let own = s.series.iter().enumerate().map(|(k, (name, points))| {
        Dataset::default()
            .name(name.as_str())
            .marker(Marker::Braille)
            .graph_type(GraphType::Line)
            .style(Style::default().fg(SERIES_COLOURS.get(k).copied().unwrap_or(Color::White)))
            .data(points)
    });
    baseline.chain(own).collect()
}

/// The legend's name for the baseline's series overlaid on a chart.
pub(super) const BASELINE_LEGEND: &str = "baseline (dim)";

/// Draws `datasets` on `s`'s axes inside `block`. Nothing is drawn over the data
/// (issue 30 item 3): the axis titles go on a row of their own above the plot (`▲ y`
/// at the left, `x ▶` at the right; ratatui would write them inside the plot, over its
/// first row and over the row above the x axis), and the legend goes in the corner of
/// the plot where no data is (top right when that corner is free, else the first free
/// one of top left, bottom right, bottom left), or, when every corner holds data, in a
/// strip right of the plot. Measured, not guessed: the chart is drawn once without a
/// legend and once per corner into scratch buffers; the cells a legend changes are its
/// box, and the bare chart's non-blank cells inside that box are what it would hide.
pub(super) fn draw_chart(
    s: &view_model::ChartSeries,
    datasets: Vec<Dataset>,
    block: Block,
    area: Rect,
    buf: &mut Buffer,
) {
    let inner = block.inner(area);
    block.render(area, buf);
    // The deck's operating value (issue 30 item 19): a vertical line across the plot
    // when it lies on the x axis (the title says so when it does not), in the legend
    // with its value, so the legend placement below keeps it clear of the data too.
    let mut datasets = datasets;
    let marker: Vec<(f64, f64)> = s
        .operating
        .as_ref()
        .filter(|o| o.within(s.x_bounds))
        .map(|o| vec![(o.x, s.y_bounds[0]), (o.x, s.y_bounds[1])])
        .unwrap_or_default();
    if let (Some(o), false) = (&s.operating, marker.is_empty()) {
        datasets.push(
            Dataset::default()
                .name(o.name.clone())
                .marker(Marker::Braille)
                .graph_type(GraphType::Line)
                .style(Style::default().fg(OPERATING))
                .data(&marker),
        );
    }
    // Two decimals on a short x axis (a roller's laminae in mm), none on a long one.
    let x_prec = label_precision(s.x_bounds);
    let make = |legend: Option<LegendPosition>| {
        Chart::new(datasets.clone())
            .legend_position(legend)
            .hidden_legend_constraints((Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)))
            .x_axis(
                Axis::default()
                    .style(Style::default().fg(DIM))
                    .bounds(s.x_bounds)
                    .labels(axis_labels(s.x_bounds, x_prec)),
            )
            .y_axis(
                Axis::default()
                    .style(Style::default().fg(DIM))
                    .bounds(s.y_bounds)
                    .labels(axis_labels(s.y_bounds, label_precision(s.y_bounds))),
            )
    };
    let plot = axis_titles(s, inner, buf);
    match legend_corner(plot, &make) {
        None => make(None).render(plot, buf),
        Some((0, corner)) => make(Some(corner)).render(plot, buf),
        Some(_) => legend_beside(plot, &make, buf),
    }
}

/// Writes the axis titles on the first row of `area` (two rows when they do not fit on
/// one) and returns what is left for the plot; all of `area` when it is too short to
/// spare a row.
fn axis_titles(s: &view_model::ChartSeries, area: Rect, buf: &mut Buffer) -> Rect {
    let y = format!("▲ {}", s.y_label);
    let x = format!("{} ▶", s.x_label);
    let (yw, xw) = (y.chars().count() as u16, x.chars().count() as u16);
    let rows = if yw + 2 + xw <= area.width { 1 } else { 2 };
    if area.height < rows + 4 {
        return area;
    }
    let style = Style::default().fg(DIM);
    buf.set_stringn(area.x, area.y, &y, usize::from(area.width), style);
    let xrow = area.y + rows - 1;
    let xx = area.x + area.width.saturating_sub(xw);
    buf.set_stringn(xx, xrow, &x, usize::from(area.width), style);
    Rect {
        y: area.y + rows,
        height: area.height - rows,
        ..area
    }
}

/// Draws the chart `make` builds with its legend in a strip right of the plot: the
/// legend box as ratatui draws it (found by drawing it in the top right of a scratch
/// buffer), the plot narrowed by its width.
fn legend_beside<'a>(
    area: Rect,
    make: &impl Fn(Option<LegendPosition>) -> Chart<'a>,
    buf: &mut Buffer,
) {
    let mut bare = Buffer::empty(area);
    make(None).render(area, &mut bare);
    let mut with = Buffer::empty(area);
    make(Some(LegendPosition::TopRight)).render(area, &mut with);
    let Some(boxed) = changed_box(&bare, &with, area) else {
        make(None).render(area, buf);
        return;
    };
    let plot = Rect {
        width: area.width.saturating_sub(boxed.width + 1),
        ..area
    };
    make(None).render(plot, buf);
    let left = area.right() - boxed.width;
    for dy in 0..boxed.height {
        for dx in 0..boxed.width {
            let cell = with[(boxed.x + dx, boxed.y + dy)].clone();
            buf[(left + dx, area.y + dy)] = cell;
        }
    }
}

/// The legend corner that hides the fewest non-blank cells of the chart `make(None)`
/// draws (see [`draw_chart`]), with the count; `None` when no corner has room for a
/// legend.
fn legend_corner<'a>(
    area: Rect,
    make: &impl Fn(Option<LegendPosition>) -> Chart<'a>,
) -> Option<(usize, LegendPosition)> {
    let mut bare = Buffer::empty(area);
    make(None).render(area, &mut bare);
    let mut best: Option<(usize, LegendPosition)> = None;
    for corner in [
        LegendPosition::TopRight,
        LegendPosition::TopLeft,
        LegendPosition::BottomRight,
        LegendPosition::BottomLeft,
    ] {
        let mut with = Buffer::empty(area);
        make(Some(corner)).render(area, &mut with);
        let Some(boxed) = changed_box(&bare, &with, area) else {
            // No room for a legend at all: every corner is alike.
            return None;
        };
        let hidden = non_blank_cells(&bare, boxed);
        if best.is_none_or(|(h, _)| hidden < h) {
            best = Some((hidden, corner));
        }
        if hidden == 0 {
            break;
        }
    }
    best
}

/// The smallest rectangle holding every cell where `a` and `b` differ.
fn changed_box(a: &Buffer, b: &Buffer, area: Rect) -> Option<Rect> {
    let mut lo: Option<(u16, u16)> = None;
    let mut hi = (0u16, 0u16);
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            if a[(x, y)] != b[(x, y)] {
                let l = lo.get_or_insert((x, y));
                *l = (l.0.min(x), l.1.min(y));
                hi = (hi.0.max(x), hi.1.max(y));
            }
        }
    }
    lo.map(|(x, y)| Rect::new(x, y, hi.0 - x + 1, hi.1 - y + 1))
}

/// Cells of `buf` inside `r` that show something.
fn non_blank_cells(buf: &Buffer, r: Rect) -> usize {
    (r.top()..r.bottom())
        .flat_map(|y| (r.left()..r.right()).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            // U+2800 is the empty braille pattern: nothing drawn.
            let sym = buf[(x, y)].symbol();
            !sym.trim().is_empty() && sym != "\u{2800}"
        })
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn series(points: Vec<(f64, f64)>) -> view_model::ChartSeries {
        view_model::ChartSeries {
            title: String::new(),
            x_label: "x m".into(),
            y_label: "y N".into(),
            series: vec![
                ("first series".into(), points.clone()),
                ("second".into(), points),
            ],
            x_bounds: [0.0, 1.0],
            y_bounds: [0.0, 1.0],
            operating: None,
            baseline: Vec::new(),
        }
    }

    fn line(f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
        (0..=400)
            .map(|i| f64::from(i) / 400.0)
            .map(|x| (x, f(x)))
            .collect()
    }

    /// The cells the legend box covers and the bare chart's non-blank cells under it.
    fn hidden_under_legend(s: &view_model::ChartSeries, area: Rect) -> (Rect, usize) {
        let mut bare_s = s.clone();
        for (name, _) in &mut bare_s.series {
            name.clear();
        }
        let mut bare = Buffer::empty(area);
        draw_chart(
            &bare_s,
            series_datasets(&bare_s),
            Block::bordered(),
            area,
            &mut bare,
        );
        let mut drawn = Buffer::empty(area);
        draw_chart(s, series_datasets(s), Block::bordered(), area, &mut drawn);
        let boxed = changed_box(&bare, &drawn, area).expect("a legend is drawn");
        (boxed, non_blank_cells(&bare, boxed))
    }

    /// A rising line fills the top-right corner (ratatui's default legend place), so the
    /// legend moves to a free corner and hides nothing; a falling line leaves the top
    /// right free and the legend stays there (issue 30, item 3: legends go where no data
    /// is). Both at 60×20 and 80×24.
    #[test]
    fn the_legend_goes_where_no_data_is() {
        for (w, h) in [(60, 20), (80, 24)] {
            let area = Rect::new(0, 0, w, h);
            let (boxed, hidden) = hidden_under_legend(&series(line(|x| x)), area);
            assert_eq!(hidden, 0, "rising line, {w}×{h}: legend at {boxed:?}");
            assert!(
                boxed.x < w / 2,
                "rising line: the legend left the right side, {boxed:?}"
            );
            let (boxed, hidden) = hidden_under_legend(&series(line(|x| 1.0 - x)), area);
            assert_eq!(hidden, 0, "falling line, {w}×{h}: legend at {boxed:?}");
            assert!(
                boxed.x > w / 2 && boxed.y < h / 2,
                "falling line: top right, {boxed:?}"
            );
        }
    }

    /// Labels differ: a ±0.0011 axis gets four decimals, a 0–360 axis none, a 0–1.05
    /// axis two (as before).
    #[test]
    fn axis_labels_are_distinct() {
        assert_eq!(label_precision([-0.0011, 0.0011]), 4);
        assert_eq!(label_precision([0.0, 360.0]), 0);
        assert_eq!(label_precision([0.0, 1.05]), 2);
        // The larger end (1.212) sets two decimals: −1.21, −1.08, −0.96 stay distinct.
        assert_eq!(label_precision([-1.212, -0.956]), 2);
        assert_eq!(label_precision([0.0, 0.0]), 3);
        assert_eq!(label_precision([-500.0, 0.0]), 0);
        assert_eq!(label_precision([-5.0, 0.0]), 2);
    }

    /// Issue 30 item 3: with data in every cell of the plot (no free corner), the axis
    /// titles and the legend are still shown, and none of them is inside the plot: the
    /// rectangle right of the y axis and above the x axis (up to the legend strip) holds
    /// no letter and no box line, at 60×20, 80×24 and 200×50. Before, the y title was
    /// written over the plot's first row and the legend over its top-right corner.
    #[test]
    fn nothing_is_drawn_over_the_data() {
        let zigzag: Vec<(f64, f64)> = (0..=4000)
            .map(|i| {
                let x = f64::from(i) / 4000.0;
                (x, (x * 600.0).sin().abs())
            })
            .collect();
        let s = series(zigzag);
        for (w, h) in [(60, 20), (80, 24), (200, 50)] {
            let area = Rect::new(0, 0, w, h);
            let mut drawn = Buffer::empty(area);
            draw_chart(&s, series_datasets(&s), Block::bordered(), area, &mut drawn);
            let sym = |x: u16, y: u16| drawn[(x, y)].symbol().to_string();
            let rows: Vec<String> = (0..h)
                .map(|y| (0..w).map(|x| sym(x, y)).collect())
                .collect();
            let text = rows.join("\n");
            for name in ["first series", "second", "▲ y N", "x m ▶"] {
                assert!(text.contains(name), "{w}×{h}: {name} missing:\n{text}");
            }
            // The axes' corner (not the border's).
            let (cx, cy) = (1..w - 1)
                .flat_map(|x| (1..h - 1).map(move |y| (x, y)))
                .find(|&(x, y)| sym(x, y) == "└")
                .expect("axes drawn");
            // The legend strip's left edge, if the legend is beside the plot.
            let right = (cx + 1..w - 1)
                .find(|&x| (1..cy).any(|y| sym(x, y) == "┌"))
                .unwrap_or(w - 1);
            // The plot starts under the titles (the y title's row in the old layout).
            let titles = rows
                .iter()
                .position(|r| r.contains("▲ y N"))
                .expect("y title");
            assert_eq!(titles, 1, "{w}×{h}: the titles are the first row:\n{text}");
            let top = 1 + rows
                .iter()
                .position(|r| r.contains("x m ▶"))
                .expect("x title") as u16;
            for y in top..cy {
                for x in cx + 1..right {
                    let c = sym(x, y);
                    assert!(
                        !c.chars()
                            .any(|ch| ch.is_alphanumeric() || ('─'..='╿').contains(&ch)),
                        "{w}×{h}: {c:?} at ({x}, {y}) over the data:\n{text}"
                    );
                }
            }
            // The plot holds data (it was not squeezed out).
            assert!(
                (top..cy).any(|y| (cx + 1..right)
                    .any(|x| ('⠁'..='⣿').contains(&sym(x, y).chars().next().unwrap_or(' ')))),
                "{w}×{h}:\n{text}"
            );
        }
    }

    /// With data everywhere the legend still shows, in the corner hiding the least.
    #[test]
    fn a_full_chart_still_has_its_legend() {
        let area = Rect::new(0, 0, 60, 20);
        let zigzag: Vec<(f64, f64)> = (0..=2000)
            .map(|i| {
                let x = f64::from(i) / 2000.0;
                (x, (x * 300.0).sin().abs())
            })
            .collect();
        let s = series(zigzag);
        let mut drawn = Buffer::empty(area);
        draw_chart(&s, series_datasets(&s), Block::bordered(), area, &mut drawn);
        let text: String = (0..area.height)
            .flat_map(|y| (0..area.width).map(move |x| (x, y)))
            .map(|(x, y)| drawn[(x, y)].symbol().to_string())
            .collect();
        assert!(text.contains("first series"), "{text}");
    }
}
