//! The key map: what each key does in each mode ([`App::on_key`], the normal mode's keys)
//! and [`KEYS`], the table the help overlay, the README and `docs/workbench.md` show.
//! Together because a key added to one belongs in the other.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::{App, Command, ExportWhat, Mode, Pane, PromptKind, PAGE};
use crate::tui::deck_io;

impl App {
    pub(super) fn on_key(&mut self, key: KeyEvent) -> Vec<Command> {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        match self.mode.clone() {
            Mode::Help => {
                match key.code {
                    KeyCode::Char('j') | KeyCode::Down => self.help_scroll += 1,
                    KeyCode::Char('k') | KeyCode::Up => {
                        self.help_scroll = self.help_scroll.saturating_sub(1)
                    }
                    KeyCode::PageDown => self.help_scroll += PAGE,
                    KeyCode::PageUp => self.help_scroll = self.help_scroll.saturating_sub(PAGE),
                    _ => {
                        self.mode = Mode::Normal;
                        self.help_scroll = 0;
                    }
                }
                Vec::new()
            }
            Mode::Error | Mode::Warnings => {
                self.mode = Mode::Normal;
                Vec::new()
            }
            Mode::ConfirmQuit => match key.code {
                KeyCode::Char('y') | KeyCode::Char('Y') => {
                    self.quit = true;
                    vec![Command::Quit]
                }
                KeyCode::Char('s') | KeyCode::Char('S') => {
                    self.mode = Mode::Normal;
                    match &self.path {
                        Some(p) => {
                            self.quit = true;
                            vec![
                                Command::Save {
                                    path: p.clone(),
                                    deck: Box::new(self.deck.clone()),
                                },
                                Command::Quit,
                            ]
                        }
                        None => {
                            self.open_prompt(PromptKind::SaveAs);
                            self.quit_after_save = true;
                            Vec::new()
                        }
                    }
                }
                _ => {
                    self.mode = Mode::Normal;
                    Vec::new()
                }
            },
            Mode::ConfirmOverwrite { path } => match key.code {
                KeyCode::Char('y') | KeyCode::Char('Y') => {
                    self.mode = Mode::Normal;
                    vec![Command::Save {
                        path,
                        deck: Box::new(self.deck.clone()),
                    }]
                }
                _ => {
                    // back to the prompt to choose another name (Esc there cancels)
                    self.mode = Mode::Prompt {
                        kind: PromptKind::SaveAs,
                        buffer: path.display().to_string(),
                    };
                    Vec::new()
                }
            },
            Mode::ConfirmExport { path, what } => {
                let yes = matches!(key.code, KeyCode::Char('y') | KeyCode::Char('Y'));
                self.on_confirm_export(yes, path, what)
            }
            Mode::ConfirmRevert => {
                self.mode = Mode::Normal;
                match (key.code, &self.path) {
                    (KeyCode::Char('y') | KeyCode::Char('Y'), Some(p)) => {
                        vec![Command::Open(p.clone())]
                    }
                    _ => Vec::new(),
                }
            }
            Mode::Prompt { kind, buffer } => self.on_prompt_key(key, kind, buffer),
            Mode::Search { buffer, from } => self.on_search_key(key, buffer, from),
            Mode::Editing {
                buffer,
                cursor,
                error,
            } => self.on_edit_key(key, buffer, cursor, error),
            Mode::Normal => self.on_normal_key(key, ctrl),
        }
    }

    fn on_normal_key(&mut self, key: KeyEvent, ctrl: bool) -> Vec<Command> {
        self.message = None;
        match key.code {
            KeyCode::Char('c') if ctrl => self.request_quit(),
            // Esc only ever cancels or goes back (a prompt, an edit, a popup); q quits.
            KeyCode::Char('q') => self.request_quit(),
            KeyCode::Esc => Vec::new(),
            KeyCode::Char('w') => {
                if self.view.as_ref().is_some_and(|v| !v.warnings.is_empty()) {
                    self.mode = Mode::Warnings;
                } else {
                    self.message = Some("no warnings".into());
                }
                Vec::new()
            }
            KeyCode::Char('e') => {
                if self.error.is_some() {
                    self.mode = Mode::Error;
                } else {
                    self.message = Some("no error to show".into());
                }
                Vec::new()
            }
            KeyCode::Char('s') if ctrl => match &self.path {
                Some(p) => vec![Command::Save {
                    path: p.clone(),
                    deck: Box::new(self.deck.clone()),
                }],
                None => {
                    self.open_prompt(PromptKind::SaveAs);
                    Vec::new()
                }
            },
            KeyCode::Char('z') if ctrl => self.undo_edit(),
            KeyCode::Char('y') | KeyCode::Char('r') if ctrl => self.redo_edit(),
            KeyCode::Char('S') => {
                self.open_prompt(PromptKind::SaveAs);
                Vec::new()
            }
            KeyCode::Char('o') => {
                self.open_prompt(PromptKind::Open);
                Vec::new()
            }
            KeyCode::Char('x') => {
                self.open_export_prompt(ExportWhat::Pane);
                Vec::new()
            }
            KeyCode::Char('X') => {
                self.open_export_prompt(ExportWhat::Report);
                Vec::new()
            }
            KeyCode::Char('R') => match &self.path {
                None => {
                    self.message = Some("nothing to revert to: the deck has no file".into());
                    Vec::new()
                }
                Some(p) if !self.unsaved() => vec![Command::Open(p.clone())],
                Some(_) => {
                    self.mode = Mode::ConfirmRevert;
                    Vec::new()
                }
            },
            KeyCode::Char('b') => self.pin_baseline(),
            KeyCode::Char('B') => self.open_baseline_prompt(),
            KeyCode::Char('D') => self.clear_baseline(),
            KeyCode::Char('d') => self.cycle_table_delta(),
            KeyCode::Char('?') => {
                self.mode = Mode::Help;
                Vec::new()
            }
            KeyCode::Char('/') => {
                self.focus = Pane::Inputs;
                self.mode = Mode::Search {
                    buffer: String::new(),
                    from: self.input_sel,
                };
                Vec::new()
            }
            KeyCode::Char('u') => {
                self.display_units = deck_io::other_units(self.display_units);
                Vec::new()
            }
            KeyCode::Char('r') => vec![self.submit()],
            // The chart pane's mode: shown there, so only acted on where it is seen.
            KeyCode::Char('c')
                if self.view.as_ref().is_some_and(|v| {
                    !v.element_charts.is_empty() && self.visible(Pane::Chart(v.element_chart_pane))
                }) =>
            {
                self.chart_laminae = !self.chart_laminae;
                Vec::new()
            }
            KeyCode::Tab => self.focus_to(self.pane_offset(1)),
            KeyCode::BackTab => self.focus_to(self.pane_offset(-1)),
            KeyCode::Char(d @ '1'..='9') => {
                let i = (d as usize).saturating_sub('1' as usize);
                match self.panes().get(i) {
                    Some(p) => self.focus_to(*p),
                    None => Vec::new(),
                }
            }
            KeyCode::PageDown if self.focus == Pane::Stepper => self.sideways(PAGE as isize),
            KeyCode::PageUp if self.focus == Pane::Stepper => self.sideways(-(PAGE as isize)),
            KeyCode::Home | KeyCode::Char('g') if self.focus == Pane::Stepper => {
                self.sideways(isize::MIN / 2)
            }
            KeyCode::End | KeyCode::Char('G') if self.focus == Pane::Stepper => {
                self.sideways(isize::MAX / 2)
            }
            KeyCode::Down | KeyCode::Char('j') => self.move_sel(1),
            KeyCode::Up | KeyCode::Char('k') => self.move_sel(-1),
            KeyCode::PageDown => self.move_sel(PAGE as isize),
            KeyCode::PageUp => self.move_sel(-(PAGE as isize)),
            KeyCode::Home | KeyCode::Char('g') => self.move_sel(isize::MIN / 2),
            KeyCode::End | KeyCode::Char('G') => self.move_sel(isize::MAX / 2),
            KeyCode::Right | KeyCode::Char('l') => self.sideways(1),
            KeyCode::Left | KeyCode::Char('h') => self.sideways(-1),
            KeyCode::Enter => self.enter(),
            _ => Vec::new(),
        }
    }

    fn request_quit(&mut self) -> Vec<Command> {
        if self.unsaved() {
            self.mode = Mode::ConfirmQuit;
            Vec::new()
        } else {
            self.quit = true;
            vec![Command::Quit]
        }
    }
}

/// Every key binding, for the help overlay and the README: (keys, context, action).
pub const KEYS: &[(&str, &str, &str)] = &[
    ("Tab / Shift-Tab", "any", "next / previous pane"),
    ("1..9", "any", "jump to a pane (numbers in the tab bar)"),
    ("j k / ↓ ↑", "any", "move selection (field or roller)"),
    (
        "PgDn PgUp",
        "any",
        "move selection by 10 (Stepper: 10 steps)",
    ),
    (
        "g G / Home End",
        "any",
        "first / last (Stepper: first / last step)",
    ),
    (
        "j k / ↓ ↑",
        "Thermal",
        "plotted node (the hottest until one is picked)",
    ),
    ("Enter", "Inputs", "edit field; Enter commits, Esc cancels"),
    (
        "/",
        "any",
        "find an input by name or key (Tab next match, Enter go, Esc back)",
    ),
    (
        "Enter",
        "Rollers, Load",
        "open the stepper on the selected roller",
    ),
    (
        "h l / ← →",
        "Stepper",
        "step back / forward through iterations",
    ),
    ("h l / ← →", "Load", "previous / next roller"),
    (
        "h l / ← →",
        "Rollers, Balls",
        "scroll the columns (the first stays; the title says which are shown)",
    ),
    (
        "j k g G / h l",
        "Stiffness (text panes)",
        "scroll the lines / the columns when they do not fit",
    ),
    (
        "c",
        "Load (when shown)",
        "load chart: roller loads ↔ load per length along the roller",
    ),
    (
        "j k / ↓ ↑",
        "Study",
        "output shown: its histogram, mean, σ, P5, P95 and sensitivities",
    ),
    (
        "h l / ← →",
        "Study",
        "samples of the default tolerance study: 32, 64, 128, 256 (re-runs it)",
    ),
    ("u", "any", "display units SI ↔ US"),
    ("r", "any", "re-solve now"),
    ("Ctrl-z / Ctrl-y", "any", "undo / redo an edit"),
    ("Ctrl-s", "any", "save (atomic, keeps .bak)"),
    ("S", "any", "save as…"),
    ("o", "any", "open a deck…"),
    (
        "x",
        "any",
        "export the pane's data as CSV: every column or series, display units…",
    ),
    (
        "X",
        "any",
        "export the report as `run` writes it (.json, .csv, else text)…",
    ),
    ("R", "any", "revert to the saved file"),
    (
        "b",
        "any",
        "pin the solution on screen as the baseline: Summary shows Δ = now − baseline",
    ),
    (
        "B",
        "any",
        "open a deck file as the baseline (solved once; another system: shared lines only)…",
    ),
    (
        "d",
        "any (with a baseline)",
        "element table: values → Δ = now − baseline → Δ % of the baseline → values",
    ),
    ("D", "any", "drop (clear) the baseline"),
    ("e", "any", "the last error, whole (any key closes)"),
    (
        "w",
        "any",
        "the solution's warnings: results beyond the model's validity",
    ),
    ("?", "any", "this help (j/k scroll, any other key closes)"),
    ("Esc", "any", "cancel: an edit, a prompt, a popup"),
    ("q / Ctrl-c", "any", "quit (asks if unsaved)"),
];

/// [`KEYS`] as the Markdown table of the README and `docs/workbench.md` (a test keeps
/// both in step with the program).
pub fn keys_markdown() -> String {
    let mut s = String::from("| Key | Where | Action |\n|---|---|---|\n");
    for (k, ctx, what) in KEYS {
        s.push_str(&format!("| `{k}` | {ctx} | {what} |\n"));
    }
    s
}
