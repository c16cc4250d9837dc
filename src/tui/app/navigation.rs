//! Moving around: focus between panes, the selection in the focused pane (field, element,
//! thermal node), the stepper's steps, and Enter (edit a field, open the stepper). Apart
//! because it changes what is on screen, never the deck.

use super::{App, Command, Mode, Pane};

impl App {
    /// The pane `by` places after (before, if negative) the focused one, cyclically.
    pub(super) fn pane_offset(&self, by: isize) -> Pane {
        let panes = self.panes();
        let n = panes.len().max(1) as isize;
        let here = panes.iter().position(|p| *p == self.focus).unwrap_or(0) as isize;
        let i = (here + by).rem_euclid(n) as usize;
        panes.get(i).copied().unwrap_or(Pane::Inputs)
    }

    pub(super) fn focus_to(&mut self, pane: Pane) -> Vec<Command> {
        if pane != self.focus {
            self.col_scroll = 0;
            self.text_scroll = 0;
        }
        self.focus = pane;
        self.resolve_if_needed()
    }

    pub(super) fn move_sel(&mut self, by: isize) -> Vec<Command> {
        let step = |cur: usize, len: usize| -> usize {
            if len == 0 {
                return 0;
            }
            (cur as isize).saturating_add(by).clamp(0, len as isize - 1) as usize
        };
        match self.focus {
            Pane::Text(_) => {
                // The renderer clamps to what is left below the text's last line.
                self.text_scroll = (self.text_scroll as isize)
                    .saturating_add(by)
                    .clamp(0, 10_000) as usize;
                Vec::new()
            }
            Pane::Sweep(_) | Pane::Job(_) => Vec::new(),
            // The output whose histogram is drawn, cyclically.
            Pane::Study => {
                let n = self
                    .study
                    .as_ref()
                    .map_or(0, |(_, p)| p.header.outputs.len());
                if n > 0 {
                    let by = by.clamp(-(n as isize), n as isize);
                    self.study_output =
                        (self.study_output as isize + by).rem_euclid(n as isize) as usize;
                }
                Vec::new()
            }
            Pane::Summary => {
                // The renderer clamps to what is left below the pane's last line.
                self.summary_scroll = (self.summary_scroll as isize)
                    .saturating_add(by)
                    .clamp(0, 10_000) as usize;
                Vec::new()
            }
            Pane::Inputs => {
                self.input_sel = step(self.input_sel, self.fields.len());
                Vec::new()
            }
            Pane::Elements | Pane::Chart(_) | Pane::Stepper => {
                let before = self.roller_sel;
                self.roller_sel = step(self.roller_sel, self.roller_count());
                if before != self.roller_sel {
                    self.step = 0;
                }
                self.resolve_if_needed()
            }
            Pane::Thermal => {
                // The plotted node: from the one shown (the hottest until one is
                // picked), within the list.
                let th = self.view.as_deref().and_then(|v| v.thermal.as_ref());
                if let Some(th) = th {
                    let hottest = crate::tui::view_model::hottest_node(th).unwrap_or(0);
                    let cur = self.thermal_node.unwrap_or(hottest);
                    self.thermal_node = Some(step(cur, th.steady.len()));
                }
                Vec::new()
            }
        }
    }

    /// Left/right: stepper steps; load chart rollers; the element table's columns and a
    /// text pane's characters.
    pub(super) fn sideways(&mut self, by: isize) -> Vec<Command> {
        match self.focus {
            Pane::Stepper => {
                let n = self.trace_len();
                if n > 0 {
                    self.step = (self.step as isize)
                        .saturating_add(by)
                        .clamp(0, n as isize - 1) as usize;
                }
                Vec::new()
            }
            // The element table scrolls its columns (the first, the element's number,
            // stays); the renderer clamps to keep one column in view.
            Pane::Elements => {
                let n = self
                    .view
                    .as_deref()
                    .and_then(|v| v.screen_table())
                    .map_or(0, |t| {
                        t.columns.iter().filter(|c| c.screen.is_some()).count()
                    });
                self.col_scroll = (self.col_scroll as isize)
                    .saturating_add(by)
                    .clamp(0, n.saturating_sub(2) as isize)
                    as usize;
                Vec::new()
            }
            // A text pane scrolls by 8 characters a step.
            Pane::Text(_) => {
                self.col_scroll = (self.col_scroll as isize)
                    .saturating_add(by.saturating_mul(8))
                    .clamp(0, 10_000) as usize;
                Vec::new()
            }
            Pane::Chart(_) => {
                let n = self.roller_count();
                if n > 0 {
                    self.roller_sel =
                        (self.roller_sel as isize + by).rem_euclid(n as isize) as usize;
                    self.step = 0;
                }
                self.resolve_if_needed()
            }
            // The default study's samples, one choice up or down (bounded: the pane is
            // for a quick look; `rollbench study` runs any size); the study re-runs.
            Pane::Study => {
                use crate::studies::study::workbench::SAMPLE_CHOICES;
                let here = SAMPLE_CHOICES
                    .iter()
                    .position(|&s| s >= self.study_samples)
                    .unwrap_or(SAMPLE_CHOICES.len() - 1) as isize;
                let i = (here + by.signum()).clamp(0, SAMPLE_CHOICES.len() as isize - 1);
                self.study_samples = SAMPLE_CHOICES[i as usize];
                self.resolve_if_needed()
            }
            _ => Vec::new(),
        }
    }

    pub(super) fn enter(&mut self) -> Vec<Command> {
        match self.focus {
            Pane::Inputs => {
                if let Some(f) = self.fields.get(self.input_sel) {
                    let buffer = self.deck.value(f.key, self.display_units);
                    self.mode = Mode::Editing {
                        cursor: buffer.chars().count(),
                        buffer,
                        error: None,
                    };
                }
                Vec::new()
            }
            Pane::Elements | Pane::Chart(_) if self.panes().contains(&Pane::Stepper) => {
                self.step = 0;
                self.focus_to(Pane::Stepper)
            }
            _ => Vec::new(),
        }
    }
}
