//! Drawing: `impl Widget for &App`. Reads the state only; all solver data goes through
//! [`view_model`](super::view_model). Named 16-colour palette only, so it looks the same
//! over any SSH link.
//!
//! This file holds the frame (header, body, status and hint lines, and the overlays on
//! top; the wide layout's slots), the palette and what every pane shares (its bordered
//! block and title, the notes for a missing or stale solution). Each pane is drawn in
//! its own file, the chrome around them in theirs, so that a change to one pane touches
//! one file: `inputs`, `elements`, `chart`, `sweep`, `job` (with `heatmap`), `thermal`,
//! `stepper`, `text`;
//! `header`, `status`, `overlays`.

mod chart;
mod elements;
mod header;
mod heatmap;
mod inputs;
mod job;
mod overlays;
pub(crate) mod status;
mod stepper;
mod study;
mod summary;
mod sweep;
mod text;
mod thermal;

pub use thermal::render_thermal_view;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::Span;
use ratatui::widgets::{Block, Borders, Paragraph, Widget, Wrap};

use super::app::{App, Mode, Pane, SolveState, MIN_SIZE};
use chart::render_load;
use elements::render_rollers;
use header::render_header;
use inputs::render_inputs;
use overlays::{pane_help, render_confirm, render_error, render_help, render_prompt};
use status::{render_hints, render_status};
use stepper::render_stepper;
use sweep::render_sweep;
use text::render_text;
use thermal::render_thermal;

const ACCENT: Color = Color::Cyan;
const INNER: Color = Color::Cyan;
const OUTER: Color = Color::Yellow;
const DIM: Color = Color::DarkGray;

/// Series colours, in series order.
const SERIES_COLOURS: [Color; 6] = [
    INNER,
    OUTER,
    Color::Green,
    Color::Magenta,
    Color::LightRed,
    Color::LightBlue,
];

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
            too_small(area, buf);
            return;
        }
        let [header, body, status, hints] = Layout::vertical([
            Constraint::Length(1),
            Constraint::Min(0),
            Constraint::Length(1),
            Constraint::Length(1),
        ])
        .areas(area);
        render_header(self, header, buf);
        if self.wide() {
            let inputs_w = (body.width * 38 / 100).max(46);
            let [left, right] =
                Layout::horizontal([Constraint::Length(inputs_w), Constraint::Min(0)]).areas(body);
            let [top, bottom] =
                Layout::vertical([Constraint::Percentage(45), Constraint::Min(0)]).areas(right);
            let split = if self.focus == Pane::Stepper { 40 } else { 55 };
            let [chart, side] =
                Layout::horizontal([Constraint::Percentage(split), Constraint::Min(0)])
                    .areas(bottom);
            let panes = self.panes();
            let offered = |p: Pane| panes.contains(&p);
            render_pane(self, Pane::Inputs, left, buf);
            render_pane(self, Pane::Elements, top, buf);
            render_pane(self, self.chart_slot(), chart, buf);
            // The side shows the stepper while it has the focus (or when the system
            // has no thermal pane), else the thermal network.
            if self.focus == Pane::Stepper || !offered(Pane::Thermal) {
                if offered(Pane::Stepper) {
                    render_pane(self, Pane::Stepper, side, buf);
                }
            } else {
                render_pane(self, Pane::Thermal, side, buf);
            }
        } else {
            render_pane(self, self.focus, body, buf);
        }
        render_status(self, status, buf);
        render_hints(self, hints, buf);
        match &self.mode {
            Mode::Help => render_help(self.help_scroll, &pane_help(self), area, buf),
            Mode::Error => render_error(
                " Error · any key closes, e reopens ",
                self.error.as_deref().unwrap_or(""),
                area,
                buf,
            ),
            Mode::Warnings => {
                let u = self.display_units;
                let text: Vec<String> = self
                    .view
                    .iter()
                    .flat_map(|v| v.warnings.iter().map(|w| format!("⚠ {}", w.text(u))))
                    .collect();
                render_error(" Warnings · any key closes ", &text.join("\n"), area, buf);
            }
            Mode::Prompt { kind, buffer } => render_prompt(*kind, buffer, area, buf),
            Mode::ConfirmQuit => render_confirm(
                "Unsaved changes",
                "s save and quit · y quit without saving · any other key: stay",
                area,
                buf,
            ),
            Mode::ConfirmOverwrite { path } => render_confirm(
                "File exists",
                &format!(
                    "{} exists · y replace it · any other key: choose another name",
                    path.display()
                ),
                area,
                buf,
            ),
            Mode::ConfirmExport { path, .. } => render_confirm(
                "File exists",
                &format!(
                    "{} exists · y replace it · any other key: choose another name",
                    path.display()
                ),
                area,
                buf,
            ),
            Mode::ConfirmRevert => render_confirm(
                "Revert",
                "y discard unsaved changes and reload the file · any other key: keep",
                area,
                buf,
            ),
            _ => {}
        }
    }
}

fn too_small(area: Rect, buf: &mut Buffer) {
    let text = format!(
        "terminal too small: {}×{}, need {}×{}",
        area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
    );
    Paragraph::new(text)
        .wrap(Wrap { trim: true })
        .style(Style::default().fg(Color::Yellow))
        .render(area, buf);
}

fn pane_block(app: &App, pane: Pane, extra: &str) -> Block<'static> {
    let focused = app.focus == pane;
    let style = if focused {
        Style::default().fg(ACCENT).add_modifier(Modifier::BOLD)
    } else {
        Style::default().fg(DIM)
    };
    Block::default()
        .borders(Borders::ALL)
        .border_style(style)
        .title(Span::styled(
            format!(" {}{} ", app.pane_title(pane), extra),
            style,
        ))
}

fn render_pane(app: &App, pane: Pane, area: Rect, buf: &mut Buffer) {
    match pane {
        Pane::Inputs => render_inputs(app, area, buf),
        Pane::Elements => render_rollers(app, area, buf),
        Pane::Chart(n) => render_load(app, n, area, buf),
        Pane::Thermal => render_thermal(app, area, buf),
        Pane::Summary => summary::render_summary(app, area, buf),
        Pane::Stepper => render_stepper(app, area, buf),
        Pane::Text(n) => render_text(app, n, area, buf),
        Pane::Sweep(n) => render_sweep(app, n, area, buf),
        Pane::Job(n) => job::render_job(app, n, area, buf),
        Pane::Study => study::render_study(app, area, buf),
    }
}

fn no_solution_text(app: &App) -> String {
    match &app.solve {
        SolveState::Failed(r) => format!("no solution: {r}"),
        _ => "solving…".into(),
    }
}

/// Title note when the panes show an older solution than the deck (last solve failed).
fn stale_note(app: &App) -> &'static str {
    match (&app.solve, &app.view) {
        (SolveState::Failed(_), Some(_)) => " · last good solve",
        _ => "",
    }
}
