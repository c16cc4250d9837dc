//! The Study pane (`Pane::Study`): a small design study of the open deck as the worker
//! fills it in ([`StudyProgress`]): what is varied on top, then the chosen output's
//! mean, σ, P5 and P95, its histogram (ten equal bins from min to max, the counts under
//! the bars), and one bar per varied input for its Spearman rank correlation with the
//! output. Every number comes from the study summary's own functions
//! ([`summary::stats`], [`summary::spearman`]) — those `rollbench study --format json`
//! writes — converted to the display units.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::{no_solution_text, pane_block, DIM};
use crate::studies::study::summary;
use crate::studies::study::workbench::{Source, StudyProgress};
use crate::tui::app::{App, Pane, SolveState};
use crate::units::Units;

/// `v` with `digits` significant digits: fixed between 1e-3 and 1e6, else `1.234e9`.
pub(crate) fn sig(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return "-".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..6).contains(&e) {
        let d = (digits as i32 - 1 - e).max(0) as usize;
        format!("{v:.d$}")
    } else {
        let d = digits.saturating_sub(1);
        format!("{v:.d$e}")
    }
}

/// Lines `text` takes wrapped at `width` (a rough word wrap, as the paragraph does).
fn height_of(text: &str, width: u16) -> u16 {
    let w = usize::from(width.max(1));
    let mut lines = 1u16;
    let mut col = 0usize;
    for word in text.split(' ') {
        let n = word.chars().count();
        let need = if col == 0 { n } else { col + 1 + n };
        if need <= w {
            col = need;
        } else {
            lines += 1 + (n / w) as u16;
            col = n % w;
        }
    }
    lines
}

/// What the pane's lines say, before layout: for tests and the renderer alike.
pub(crate) struct StudyScreen {
    /// The design and its varied keys.
    pub varied: Vec<String>,
    /// The output line: name, unit, which of how many, solved and failed.
    pub output: String,
    /// mean, σ, P5, P95 in display units.
    pub stats: String,
    /// Histogram counts and its ends in display units (none before two distinct values).
    pub histogram: Option<(Vec<usize>, String, String)>,
    /// (input key, ρ) per varied input.
    pub sensitivities: Vec<(String, Option<f64>)>,
}

/// The screen of `p` for output `o` in display units `u`.
pub(crate) fn screen(p: &StudyProgress, o: usize, u: Units, samples_key: bool) -> StudyScreen {
    let r = p.result();
    let h = &r.header;
    let o = o.min(h.outputs.len().saturating_sub(1));
    let name = h.outputs.get(o).cloned().unwrap_or_default();
    let q = p.quantities.get(o).copied().flatten();
    let conv = |v: f64| q.map_or(v, |q| q.from_si(v, u));
    let unit = q.map_or("", |q| q.unit(u));
    let col: Vec<Option<f64>> = r
        .rows
        .iter()
        .map(|row| row.outputs.get(o).copied().flatten())
        .collect();
    let st = summary::stats(&col);
    let mut varied = Vec::new();
    let mut first = p.varied.first().cloned().unwrap_or_default();
    match &p.source {
        Source::File(path) => {
            let f = path.file_name().map_or_else(
                || path.display().to_string(),
                |f| f.to_string_lossy().into(),
            );
            first = format!("{f}: {first}");
        }
        Source::Default => {
            first = format!("±1 % tolerance study: {first}");
            if samples_key {
                first.push_str(" (h l: samples)");
            }
        }
    }
    varied.push(first);
    varied.extend(p.varied.iter().skip(1).cloned());
    varied.extend(p.notes.iter().cloned());
    let unit_note = if unit.is_empty() {
        String::new()
    } else {
        format!(" [{unit}]")
    };
    let output = format!(
        "{name}{unit_note} · output {}/{} (j k) · {} of {} solved, {} failed",
        o + 1,
        h.outputs.len(),
        r.rows.len() - r.failures(),
        p.total,
        r.failures()
    );
    let stats = match &st {
        Some(s) => format!(
            "mean {} · σ {} · P5 {} · P95 {}",
            sig(conv(s.mean), 5),
            sig(q.map_or(s.sigma, |q| s.sigma / q.factor(u)), 4),
            sig(conv(s.p5), 5),
            sig(conv(s.p95), 5)
        ),
        None => "no point has a value yet".into(),
    };
    let histogram = st.as_ref().filter(|s| s.max > s.min).map(|s| {
        (
            s.histogram.clone(),
            sig(conv(s.min), 5),
            sig(conv(s.max), 5),
        )
    });
    let sensitivities = if h.design == "duty" || r.rows.len() < 3 {
        Vec::new()
    } else {
        summary::varied_inputs(&r)
            .into_iter()
            .map(|i| (h.inputs[i].clone(), summary::spearman(&r.rows, i, o)))
            .collect()
    };
    StudyScreen {
        varied,
        output,
        stats,
        histogram,
        sensitivities,
    }
}

/// Draws the histogram bars: ten columns of `█` (eighths on top) scaled to the highest
/// count, the counts on the line under them, the ends of the range under that.
fn draw_histogram(counts: &[usize], lo: &str, hi: &str, unit: &str, area: Rect, buf: &mut Buffer) {
    if area.height < 3 || area.width < 20 {
        return;
    }
    let bins = counts.len().max(1) as u16;
    // Bin b spans columns [b·W/bins, (b+1)·W/bins): the bars fill the width, so the
    // ends printed under the first and last bars are the range's.
    let bar_w = (area.width / bins).max(2) - 1;
    let rows = area.height - 2;
    let top = counts.iter().copied().max().unwrap_or(1).max(1);
    const EIGHTHS: [&str; 9] = [" ", "▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"];
    let style = Style::default().fg(Color::Cyan);
    for (b, &c) in counts.iter().enumerate() {
        let x0 = area.x + (b as u16 * area.width) / bins;
        // Height in eighths of a row, at least one eighth for a non-empty bin.
        let eighths = (c * usize::from(rows) * 8)
            .div_ceil(top)
            .max(usize::from(c > 0));
        for r in 0..rows {
            let y = area.y + rows - 1 - r;
            let fill = eighths.saturating_sub(usize::from(r) * 8).min(8);
            if fill == 0 {
                continue;
            }
            for dx in 0..bar_w {
                if x0 + dx < area.right() {
                    buf[(x0 + dx, y)].set_symbol(EIGHTHS[fill]).set_style(style);
                }
            }
        }
        let label = c.to_string();
        let lx = x0 + bar_w.saturating_sub(label.len() as u16) / 2;
        if lx + (label.len() as u16) <= area.right() {
            buf.set_string(lx, area.y + rows, &label, Style::default());
        }
    }
    let y = area.y + rows + 1;
    let mid = if unit.is_empty() {
        "equal bins, min … max".to_string()
    } else {
        format!("equal bins, min … max, {unit}")
    };
    let w = usize::from(area.width);
    buf.set_string(area.x, y, lo, Style::default().fg(DIM));
    let hx = area.right().saturating_sub(hi.chars().count() as u16);
    buf.set_string(hx, y, hi, Style::default().fg(DIM));
    if lo.chars().count() + hi.chars().count() + mid.chars().count() + 4 <= w {
        let mx = area.x + ((w - mid.chars().count()) / 2) as u16;
        buf.set_string(mx, y, &mid, Style::default().fg(DIM));
    }
}

/// The Study pane.
pub(super) fn render_study(app: &App, area: Rect, buf: &mut Buffer) {
    let pane = Pane::Study;
    let Some((generation, p)) = app.study.as_ref() else {
        let block = pane_block(app, pane, "");
        let inner = block.inner(area);
        block.render(area, buf);
        let text = match app.solve {
            SolveState::Failed(_) => no_solution_text(app),
            _ => "solving the deck, then its study…".to_string(),
        };
        Paragraph::new(text)
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    };
    if let Some(e) = &p.error {
        let block = pane_block(app, pane, " · no study");
        let inner = block.inner(area);
        block.render(area, buf);
        Paragraph::new(e.as_str())
            .style(Style::default().fg(Color::Red))
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    }
    let stale = if *generation == app.generation {
        ""
    } else {
        " · updating"
    };
    let progress = if p.finished {
        format!(" · {} points{stale}", p.total)
    } else {
        format!(" · {}/{} points{stale}", p.rows.len(), p.total)
    };
    let block = pane_block(app, pane, &progress);
    let inner = block.inner(area);
    block.render(area, buf);
    let u = app.display_units;
    let s = screen(p, app.study_output, u, p.source == Source::Default);
    let o = app
        .study_output
        .min(p.header.outputs.len().saturating_sub(1));
    let unit = p
        .quantities
        .get(o)
        .copied()
        .flatten()
        .map_or("", |q| q.unit(u));
    let w = inner.width;
    // Room: the output and stats lines and the sensitivities first, then the histogram
    // (at least 4 lines), then as much of the description as is left.
    let sens_h = s.sensitivities.len() as u16 + u16::from(!s.sensitivities.is_empty());
    let out_h = height_of(&s.output, w) + height_of(&s.stats, w);
    let hist_min = 5u16;
    let mut desc: Vec<&String> = Vec::new();
    let mut desc_h = 0u16;
    let spare = inner.height.saturating_sub(out_h + sens_h + hist_min);
    for line in &s.varied {
        let h = height_of(line, w);
        if desc_h + h > spare {
            break;
        }
        desc_h += h;
        desc.push(line);
    }
    let mut y = inner.y;
    let para = |text: Line<'_>, h: u16, y: u16, buf: &mut Buffer| {
        let h = h.min(inner.bottom().saturating_sub(y));
        if h > 0 {
            Paragraph::new(text)
                .wrap(Wrap { trim: true })
                .render(Rect::new(inner.x, y, w, h), buf);
        }
    };
    for line in desc {
        let h = height_of(line, w);
        para(
            Line::styled(line.as_str(), Style::default().fg(DIM)),
            h,
            y,
            buf,
        );
        y += h;
    }
    let h = height_of(&s.output, w);
    para(Line::from(s.output.as_str()), h, y, buf);
    y += h;
    let h = height_of(&s.stats, w);
    para(Line::from(s.stats.as_str()), h, y, buf);
    y += h;
    let hist_h = inner.bottom().saturating_sub(y + sens_h);
    let hist_area = Rect::new(inner.x, y, w, hist_h);
    match &s.histogram {
        Some((counts, lo, hi)) => draw_histogram(counts, lo, hi, unit, hist_area, buf),
        None if hist_h > 0 => {
            Paragraph::new("no spread to draw: every solved point has the same value")
                .style(Style::default().fg(DIM))
                .wrap(Wrap { trim: true })
                .render(hist_area, buf);
        }
        None => {}
    }
    y += hist_h;
    if s.sensitivities.is_empty() || y >= inner.bottom() {
        return;
    }
    buf.set_stringn(
        inner.x,
        y,
        "sensitivity: Spearman rank correlation ρ of each input with this output",
        usize::from(w),
        Style::default().fg(DIM),
    );
    y += 1;
    let kw = s
        .sensitivities
        .iter()
        .map(|(k, _)| k.chars().count())
        .max()
        .unwrap_or(0)
        .min(usize::from(w) / 2);
    for (k, rho) in &s.sensitivities {
        if y >= inner.bottom() {
            break;
        }
        let cell = rho.map_or("    -".to_string(), |r| format!("{r:+.2}"));
        let key: String = k.chars().take(kw).collect();
        let head = format!("{key:<kw$} {cell:>5} ");
        let room = usize::from(w).saturating_sub(head.chars().count());
        let bar_len = rho.map_or(0, |r| (r.abs() * room as f64).round() as usize);
        let colour = if rho.is_some_and(|r| r < 0.0) {
            Color::Red
        } else {
            Color::Green
        };
        let line = Line::from(vec![
            Span::raw(head),
            Span::styled("█".repeat(bar_len.min(room)), Style::default().fg(colour)),
        ]);
        buf.set_line(inner.x, y, &line, w);
        y += 1;
    }
}
