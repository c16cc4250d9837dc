//! Plain application state and its pure transitions (`App::handle`).
//!
//! `handle` never does I/O and never blocks: it mutates the state and returns
//! [`Command`]s (solve, save, open, quit) that the runtime loop in `tui/mod.rs`
//! performs, feeding the outcome back as another [`AppEvent`]. Tests drive it directly.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;

use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use crate::bearings::view::{PaneKind, View};
use crate::bearings::{Case, Detail};
use crate::studies::sweep::PlanProgress;
use crate::units::Units;

use super::deck_io::{self, DeckDoc, FieldInfo};

/// A workbench pane: what it shows. The panes on offer, their order and their titles
/// ("Rollers", "Balls") come from the deck's bearing system ([`App::panes`]).
pub type Pane = PaneKind;

/// Outcome of a solve as delivered to the UI: the solution's view.
pub type SolveOutcome = Result<Arc<View>, String>;

/// Everything that can happen to the app.
#[derive(Debug, Clone)]
pub enum AppEvent {
    /// A key press.
    Key(KeyEvent),
    /// The terminal was resized to (width, height).
    Resize(u16, u16),
    /// The solver finished job `generation` (stale generations are ignored).
    Solved {
        /// Job generation.
        generation: u64,
        /// Result or failure reason.
        outcome: SolveOutcome,
    },
    /// The worker solved one more point of the sweep of pane `Sweep(pane)` for job
    /// `generation` (the whole sweep so far).
    SweepProgress {
        /// Job generation.
        generation: u64,
        /// The sweep pane's index.
        pane: usize,
        /// The points solved so far.
        progress: Arc<PlanProgress>,
    },
    /// The solver sent chart `chart_index` of job `generation` as it grows (a stage
    /// still running, e.g. the ball's skidding search; [`crate::bearings::Session::solve_streaming`]).
    ChartProgress {
        /// Job generation.
        generation: u64,
        /// The chart's index (`PaneKind::Chart(chart_index)`).
        chart_index: usize,
        /// The chart so far.
        chart: Arc<crate::bearings::view::Chart>,
    },
    /// A save finished.
    Saved(Result<PathBuf, String>),
    /// An open (or revert) finished.
    Opened(Result<(Box<DeckDoc>, PathBuf), String>),
    /// The process received this termination signal (SIGTERM, SIGINT, SIGHUP, SIGQUIT):
    /// leave at once, without asking (the runtime restores the terminal and exits with
    /// 128 + the signal number).
    Signal(i32),
    /// The runtime looked at a save-as target ([`Command::CheckSaveTarget`]).
    SaveTargetChecked {
        /// The typed path.
        path: PathBuf,
        /// Something (file, link, directory, device) already exists there.
        exists: bool,
    },
}

/// One solve request for the worker.
#[derive(Clone)]
pub struct SolveJob {
    /// Generation; the newest wins.
    pub generation: u64,
    /// The deck to solve.
    pub case: Arc<dyn Case>,
    /// What the panes on screen need beyond the defaults (stepper trace, transient).
    pub detail: Detail,
    /// The sweep pane on screen (`PaneKind::Sweep(n)`), solved after the case.
    pub sweep: Option<usize>,
}

impl std::fmt::Debug for SolveJob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolveJob")
            .field("generation", &self.generation)
            .field("system", &self.case.system().id())
            .field("detail", &self.detail)
            .field("sweep", &self.sweep)
            .finish()
    }
}

impl PartialEq for SolveJob {
    fn eq(&self, other: &Self) -> bool {
        self.generation == other.generation
            && self.detail == other.detail
            && self.sweep == other.sweep
            && self.case.system().id() == other.case.system().id()
            && self.case.text() == other.case.text()
    }
}

/// Side effects requested by [`App::handle`].
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// Submit a solve to the worker.
    Solve(Box<SolveJob>),
    /// Save this deck to this path (atomic), then report [`AppEvent::Saved`].
    Save {
        /// Target path.
        path: PathBuf,
        /// The deck to write.
        deck: Box<DeckDoc>,
    },
    /// Load a deck from this path, then report [`AppEvent::Opened`].
    Open(PathBuf),
    /// Save as: see whether this path already exists, then report
    /// [`AppEvent::SaveTargetChecked`] (the app asks before replacing it).
    CheckSaveTarget(PathBuf),
    /// Leave the workbench.
    Quit,
}

/// State of the solver as shown in the status bar.
#[derive(Debug, Clone, PartialEq)]
pub enum SolveState {
    /// Nothing requested yet.
    Idle,
    /// A solve of this generation is in flight.
    Running,
    /// Last solve succeeded.
    Solved {
        /// What the outer and inner iterations are.
        names: [&'static str; 2],
        /// Ring iterations.
        iterations: usize,
        /// Roller Newton iterations (all rollers, all ring iterations).
        roller_iterations: usize,
        /// Wall time, ms.
        wall_ms: f64,
    },
    /// Last solve failed.
    Failed(String),
}

/// What a text prompt is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PromptKind {
    /// Save under a new path.
    SaveAs,
    /// Open a deck file.
    Open,
}

/// Input mode (which keys mean what).
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    /// Navigation.
    Normal,
    /// Editing the selected input field in place.
    Editing {
        /// Text typed so far.
        buffer: String,
        /// Cursor position (chars).
        cursor: usize,
        /// Validation error of the last commit attempt.
        error: Option<String>,
    },
    /// A path prompt.
    Prompt {
        /// Purpose.
        kind: PromptKind,
        /// Text typed so far.
        buffer: String,
    },
    /// Quit requested with unsaved changes.
    ConfirmQuit,
    /// Revert requested with unsaved changes.
    ConfirmRevert,
    /// Save as over a file that exists.
    ConfirmOverwrite {
        /// The existing target.
        path: PathBuf,
    },
    /// Help overlay.
    Help,
    /// Searching the inputs for a field by label or key (`/`).
    Search {
        /// Text typed so far.
        buffer: String,
        /// The selection before the search (Esc goes back to it).
        from: usize,
    },
    /// The last error, whole, in a popup (`e` reopens it).
    Error,
    /// The solution's warnings (results beyond the model), in a popup (`w`).
    Warnings,
}

/// The whole UI state. Rendering reads it through `&App`; nothing is locked.
#[derive(Debug, Clone)]
pub struct App {
    /// The deck under edit. Changed only through [`App::handle`] (which keeps
    /// `deck_text` in step); read it freely.
    pub deck: DeckDoc,
    /// `deck.text()`, refreshed whenever the deck changes, so that [`App::unsaved`]
    /// (asked every frame) does not serialise the deck.
    deck_text: String,
    /// File the deck came from / is saved to.
    pub path: Option<PathBuf>,
    /// Deck text at the last open/save (unsaved = the deck's text differs).
    pub saved_text: String,
    /// Units used to display and type values.
    pub display_units: Units,
    /// Focused pane.
    pub focus: Pane,
    /// Terminal size (width, height).
    pub size: (u16, u16),
    /// Editable fields (cached list).
    pub fields: Vec<FieldInfo>,
    /// Selected field index.
    pub input_sel: usize,
    /// Input mode.
    pub mode: Mode,
    /// Keys edited but not yet reflected in a solution, with the generation that will.
    pub dirty_keys: BTreeMap<&'static str, u64>,
    /// Undo stack: deck before each edit, and the key edited.
    pub undo: Vec<(DeckDoc, Option<&'static str>)>,
    /// Redo stack.
    pub redo: Vec<(DeckDoc, Option<&'static str>)>,
    /// Last submitted solve generation.
    pub generation: u64,
    /// What the last submitted solve was asked for.
    pub last_request: Detail,
    /// The sweep pane the last submitted solve was asked to sweep.
    pub last_sweep: Option<usize>,
    /// The newest sweep progress: (generation, pane index, points so far).
    pub sweep: Option<(u64, usize, Arc<PlanProgress>)>,
    /// The chart the running solve is filling: (generation, chart index, chart so far);
    /// drawn in place of the last solution's while that solve runs.
    pub streamed: Option<(u64, usize, Arc<crate::bearings::view::Chart>)>,
    /// Solver state.
    pub solve: SolveState,
    /// The newest accepted solution's view (tables, charts, trace, thermal).
    pub view: Option<Arc<View>>,
    /// Selected roller (0-based).
    pub roller_sel: usize,
    /// Load chart shows the load along the selected roller (per unit length) instead of the
    /// roller loads.
    pub chart_laminae: bool,
    /// Stepper position (0-based trace step).
    pub step: usize,
    /// Thermal node chosen for the sparkline (`None`: the hottest).
    pub thermal_node: Option<usize>,
    /// One-line message for the status bar (saved, errors).
    pub message: Option<String>,
    /// The last error (a failed open, save or solve), whole, one message per line: the
    /// status line shows its start, the error popup (`e`) all of it.
    pub error: Option<String>,
    /// Set when the app should exit.
    pub quit: bool,
    /// Quit once the pending save-as succeeds (quit prompt → save, deck had no file).
    pub quit_after_save: bool,
    /// First row of the help overlay shown (j/k scroll it when it does not fit).
    pub help_scroll: usize,
    /// The termination signal that ended the app, if any ([`AppEvent::Signal`]).
    pub signal: Option<i32>,
}

/// Terminal size at or above which all panes are shown together.
pub const WIDE: (u16, u16) = (120, 36);
/// Below this the app shows only a "terminal too small" message.
pub const MIN_SIZE: (u16, u16) = (60, 16);
/// Rows moved by PgUp/PgDn.
const PAGE: usize = 10;

impl App {
    /// A new app on `deck` (from `path` if given). Call [`App::start`] for the first solve.
    pub fn new(deck: DeckDoc, path: Option<PathBuf>) -> App {
        let deck_text = deck.text();
        let display_units = deck.units();
        let fields = deck.fields();
        App {
            deck,
            path,
            saved_text: deck_text.clone(),
            deck_text,
            display_units,
            focus: Pane::Inputs,
            size: (80, 24),
            fields,
            input_sel: 0,
            mode: Mode::Normal,
            dirty_keys: BTreeMap::new(),
            undo: Vec::new(),
            redo: Vec::new(),
            generation: 0,
            last_request: Detail::default(),
            last_sweep: None,
            sweep: None,
            streamed: None,
            solve: SolveState::Idle,
            view: None,
            roller_sel: 0,
            chart_laminae: false,
            step: 0,
            thermal_node: None,
            message: None,
            error: None,
            quit: false,
            quit_after_save: false,
            help_scroll: 0,
            signal: None,
        }
    }

    /// The first solve.
    pub fn start(&mut self) -> Vec<Command> {
        vec![self.submit()]
    }

    /// The panes the deck's bearing system offers, in Tab order.
    pub fn panes(&self) -> Vec<Pane> {
        self.deck.system().panes().iter().map(|p| p.kind).collect()
    }

    /// A pane's title as the deck's bearing system names it ("Rollers", "Balls").
    pub fn pane_title(&self, pane: Pane) -> &'static str {
        self.deck
            .system()
            .panes()
            .iter()
            .find(|p| p.kind == pane)
            .map_or("", |p| p.title)
    }

    /// The pane `by` places after (before, if negative) the focused one, cyclically.
    fn pane_offset(&self, by: isize) -> Pane {
        let panes = self.panes();
        let n = panes.len().max(1) as isize;
        let here = panes.iter().position(|p| *p == self.focus).unwrap_or(0) as isize;
        let i = (here + by).rem_euclid(n) as usize;
        panes.get(i).copied().unwrap_or(Pane::Inputs)
    }

    /// What one rolling element is called ("roller", "ball").
    pub fn element_name(&self) -> &'static str {
        self.deck.system().element_name()
    }

    /// True if the deck's text differs from the last saved/opened text (so undoing back
    /// to the saved deck clears it). A string comparison: the deck's text is kept
    /// up to date when the deck changes, not serialised here.
    pub fn unsaved(&self) -> bool {
        self.deck_text != self.saved_text
    }

    /// Replaces the deck (keeping its text in step) and returns the previous one.
    fn replace_deck(&mut self, deck: DeckDoc) -> DeckDoc {
        self.deck_text = deck.text();
        std::mem::replace(&mut self.deck, deck)
    }

    /// True if all panes are laid out together at the current size.
    pub fn wide(&self) -> bool {
        self.size.0 >= WIDE.0 && self.size.1 >= WIDE.1
    }

    /// The pane the wide layout's chart slot shows: the focused chart, text or sweep
    /// pane, else the first chart.
    pub fn chart_slot(&self) -> Pane {
        match self.focus {
            p @ (Pane::Chart(_) | Pane::Text(_) | Pane::Sweep(_)) => p,
            _ => Pane::Chart(0),
        }
    }

    /// True if `pane` is on screen at the current size and focus.
    pub fn visible(&self, pane: Pane) -> bool {
        if self.wide() {
            match pane {
                Pane::Thermal => self.focus != Pane::Stepper,
                // The side slot shows the stepper while it has the focus, or always when
                // the system has no thermal pane (the renderer's rule).
                Pane::Stepper => {
                    self.focus == Pane::Stepper || !self.panes().contains(&Pane::Thermal)
                }
                Pane::Chart(_) | Pane::Text(_) | Pane::Sweep(_) => self.chart_slot() == pane,
                _ => true,
            }
        } else {
            self.focus == pane
        }
    }

    /// What the visible panes need from the solver: the stepper's trace and the thermal
    /// transient only when their panes are on screen; the other stages (contact, heat)
    /// take `Request`'s defaults.
    pub fn wanted_request(&self) -> Detail {
        Detail {
            trace_element: self.visible(Pane::Stepper).then_some(self.roller_sel),
            transient: self.visible(Pane::Thermal) && self.deck.has_thermal(),
            stream_chart: self.panes().into_iter().find_map(|p| match p {
                Pane::Chart(n) if self.visible(p) => Some(n),
                _ => None,
            }),
        }
    }

    /// The selected element's number as the element table shows it (its `index`
    /// column: the balls count from 0, like their JSON and CSV; the rollers from 1), so
    /// the stepper and chart labels name the row the table shows; its position + 1 when
    /// the table has no such column (or before the first solution).
    pub fn element_number(&self) -> usize {
        self.view
            .as_deref()
            .and_then(|v| v.screen_table())
            .and_then(|t| {
                let c = t.columns.iter().position(|c| c.key == "index")?;
                let v = (*t.rows.get(self.roller_sel)?.get(c)?)?;
                (v.is_finite() && v >= 0.0).then_some(v as usize)
            })
            .unwrap_or(self.roller_sel + 1)
    }

    /// Chart `n` as the running solve has streamed it so far, if it streams that chart
    /// (only while the newest job runs: its solution's chart replaces it).
    pub fn streamed_chart(&self, n: usize) -> Option<&crate::bearings::view::Chart> {
        match (&self.solve, &self.streamed) {
            (SolveState::Running, Some((g, i, c))) if *g == self.generation && *i == n => Some(c),
            _ => None,
        }
    }

    /// The sweep pane on screen, if any (the worker sweeps only for a visible pane).
    pub fn wanted_sweep(&self) -> Option<usize> {
        self.panes().into_iter().find_map(|p| match p {
            Pane::Sweep(n) if self.visible(p) => Some(n),
            _ => None,
        })
    }

    /// Number of rolling elements in the newest solution (0 before the first).
    pub fn roller_count(&self) -> usize {
        self.view.as_deref().map_or(0, view_element_count)
    }

    /// Number of recorded stepper steps.
    pub fn trace_len(&self) -> usize {
        self.view.as_deref().map_or(0, view_trace_len)
    }

    fn submit(&mut self) -> Command {
        self.generation += 1;
        self.last_request = self.wanted_request();
        self.last_sweep = self.wanted_sweep();
        self.solve = SolveState::Running;
        Command::Solve(Box::new(SolveJob {
            generation: self.generation,
            case: self.deck.case(),
            detail: self.last_request,
            sweep: self.last_sweep,
        }))
    }

    /// Re-solves if the visible panes now need more than the last request gave.
    fn resolve_if_needed(&mut self) -> Vec<Command> {
        let want = self.wanted_request();
        let have = &self.last_request;
        let need_trace = want.trace_element.is_some() && want.trace_element != have.trace_element;
        let need_thermal = want.transient && !have.transient;
        let want_sweep = self.wanted_sweep();
        let need_sweep = want_sweep.is_some() && want_sweep != self.last_sweep;
        if need_trace || need_thermal || need_sweep {
            vec![self.submit()]
        } else {
            Vec::new()
        }
    }

    /// Applies one event; returns the side effects to perform.
    pub fn handle(&mut self, event: AppEvent) -> Vec<Command> {
        match event {
            AppEvent::Key(key) => {
                if key.kind == KeyEventKind::Release {
                    return Vec::new();
                }
                // While only "terminal too small" is shown, keys would act unseen: ignore
                // all but quitting (q, Ctrl-c).
                let too_small = self.size.0 < MIN_SIZE.0 || self.size.1 < MIN_SIZE.1;
                let quit = matches!(key.code, KeyCode::Char('q'))
                    || (matches!(key.code, KeyCode::Char('c'))
                        && key.modifiers.contains(KeyModifiers::CONTROL));
                if too_small && !quit {
                    return Vec::new();
                }
                self.on_key(key)
            }
            AppEvent::Resize(w, h) => {
                self.size = (w, h);
                self.resolve_if_needed()
            }
            AppEvent::Solved {
                generation,
                outcome,
            } => {
                if generation != self.generation {
                    return Vec::new(); // stale: a newer job is pending
                }
                self.streamed = None; // the solution's own charts take over
                match outcome {
                    Ok(view) => {
                        let s = view.stats;
                        self.solve = SolveState::Solved {
                            names: s.names,
                            iterations: s.iterations,
                            roller_iterations: s.inner_iterations,
                            wall_ms: s.wall_time_s * 1e3,
                        };
                        self.roller_sel = self
                            .roller_sel
                            .min(view_element_count(&view).saturating_sub(1));
                        self.step = self.step.min(view_trace_len(&view).saturating_sub(1));
                        self.view = Some(view);
                        // these edits are now reflected in the results
                        self.dirty_keys.retain(|_, g| *g > generation);
                    }
                    // a failed solve leaves the edits unsolved (still marked)
                    Err(reason) => {
                        self.error = Some(reason.clone());
                        self.solve = SolveState::Failed(reason);
                    }
                }
                Vec::new()
            }
            AppEvent::ChartProgress {
                generation,
                chart_index,
                chart,
            } => {
                if generation == self.generation {
                    self.streamed = Some((generation, chart_index, chart));
                }
                Vec::new()
            }
            AppEvent::SweepProgress {
                generation,
                pane,
                progress,
            } => {
                if generation == self.generation {
                    self.sweep = Some((generation, pane, progress));
                }
                Vec::new()
            }
            AppEvent::Saved(Ok(path)) => {
                self.message = Some(format!("saved {}", path.display()));
                self.saved_text = self.deck_text.clone();
                self.path = Some(path);
                if std::mem::take(&mut self.quit_after_save) {
                    self.quit = true;
                    return vec![Command::Quit];
                }
                Vec::new()
            }
            AppEvent::Saved(Err(e)) => {
                self.message = Some("save failed (e: the whole message)".into());
                self.error = Some(format!("save failed:\n{e}"));
                self.mode = Mode::Error;
                self.quit_after_save = false;
                Vec::new()
            }
            AppEvent::Opened(Ok((deck, path))) => {
                let before = self.replace_deck(*deck);
                if self.path.as_ref() == Some(&path) {
                    self.undo.push((before, None)); // revert: undoable
                } else {
                    self.undo.clear(); // another file: old edits do not apply to it
                }
                self.redo.clear();
                self.saved_text = self.deck_text.clone();
                self.display_units = self.deck.units();
                self.message = Some(format!("opened {}", path.display()));
                self.path = Some(path);
                self.dirty_keys.clear();
                self.input_sel = 0;
                // another deck may be another bearing system: its fields and panes; its
                // elements and nodes start from the first (the hottest)
                self.fields = self.deck.fields();
                self.roller_sel = 0;
                self.step = 0;
                self.thermal_node = None;
                if !self.panes().contains(&self.focus) {
                    self.focus = Pane::Inputs;
                }
                vec![self.submit()]
            }
            AppEvent::Opened(Err(e)) => {
                self.message = Some("open failed (e: the whole message)".into());
                self.error = Some(format!("open failed:\n{e}"));
                self.mode = Mode::Error;
                Vec::new()
            }
            AppEvent::SaveTargetChecked { path, exists } => {
                if exists {
                    self.mode = Mode::ConfirmOverwrite { path };
                    Vec::new()
                } else {
                    vec![Command::Save {
                        path,
                        deck: Box::new(self.deck.clone()),
                    }]
                }
            }
            AppEvent::Signal(n) => {
                // A signal is not a question: quit even with unsaved changes or a prompt open.
                self.signal = Some(n);
                self.quit = true;
                vec![Command::Quit]
            }
        }
    }

    fn on_key(&mut self, key: KeyEvent) -> Vec<Command> {
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

    fn open_prompt(&mut self, kind: PromptKind) {
        let buffer = match (kind, &self.path) {
            (PromptKind::SaveAs, Some(p)) => p.display().to_string(),
            (PromptKind::SaveAs, None) => "deck.toml".to_string(),
            (PromptKind::Open, _) => String::new(),
        };
        self.mode = Mode::Prompt { kind, buffer };
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

    fn focus_to(&mut self, pane: Pane) -> Vec<Command> {
        self.focus = pane;
        self.resolve_if_needed()
    }

    fn move_sel(&mut self, by: isize) -> Vec<Command> {
        let step = |cur: usize, len: usize| -> usize {
            if len == 0 {
                return 0;
            }
            (cur as isize).saturating_add(by).clamp(0, len as isize - 1) as usize
        };
        match self.focus {
            Pane::Text(_) | Pane::Sweep(_) => Vec::new(),
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
                    let hottest = super::view_model::hottest_node(th).unwrap_or(0);
                    let cur = self.thermal_node.unwrap_or(hottest);
                    self.thermal_node = Some(step(cur, th.steady.len()));
                }
                Vec::new()
            }
        }
    }

    /// Left/right: stepper steps; load chart rollers.
    fn sideways(&mut self, by: isize) -> Vec<Command> {
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
            Pane::Chart(_) | Pane::Elements => {
                let n = self.roller_count();
                if n > 0 {
                    self.roller_sel =
                        (self.roller_sel as isize + by).rem_euclid(n as isize) as usize;
                    self.step = 0;
                }
                self.resolve_if_needed()
            }
            _ => Vec::new(),
        }
    }

    fn enter(&mut self) -> Vec<Command> {
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

    fn on_edit_key(
        &mut self,
        key: KeyEvent,
        mut buffer: String,
        mut cursor: usize,
        error: Option<String>,
    ) -> Vec<Command> {
        let byte_at = |s: &str, c: usize| s.char_indices().nth(c).map_or(s.len(), |(i, _)| i);
        match key.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Enter => return self.commit_edit(buffer),
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => {
                let at = byte_at(&buffer, cursor);
                buffer.insert(at, ch);
                cursor += 1;
            }
            KeyCode::Backspace if cursor > 0 => {
                let at = byte_at(&buffer, cursor - 1);
                buffer.remove(at);
                cursor -= 1;
            }
            KeyCode::Delete if cursor < buffer.chars().count() => {
                let at = byte_at(&buffer, cursor);
                buffer.remove(at);
            }
            KeyCode::Up | KeyCode::Down => {
                // choice fields: cycle through the allowed values
                let key_path = self.fields.get(self.input_sel).map(|f| f.key);
                if let Some(list) = key_path.and_then(|k| self.deck.choices(k)) {
                    let n = list.len();
                    if n > 0 {
                        let cur = list.iter().position(|c| *c == buffer.trim());
                        let next = match (cur, key.code) {
                            (Some(i), KeyCode::Down) => (i + 1) % n,
                            (Some(i), _) => (i + n - 1) % n,
                            (None, _) => 0,
                        };
                        buffer = list.get(next).map(|c| c.to_string()).unwrap_or_default();
                        cursor = buffer.chars().count();
                    }
                }
            }
            KeyCode::Left => cursor = cursor.saturating_sub(1),
            KeyCode::Right => cursor = (cursor + 1).min(buffer.chars().count()),
            KeyCode::Home => cursor = 0,
            KeyCode::End => cursor = buffer.chars().count(),
            _ => {}
        }
        self.mode = Mode::Editing {
            buffer,
            cursor,
            error,
        };
        Vec::new()
    }

    fn commit_edit(&mut self, buffer: String) -> Vec<Command> {
        let Some(field) = self.fields.get(self.input_sel).copied() else {
            self.mode = Mode::Normal;
            return Vec::new();
        };
        if buffer.trim() == self.deck.value(field.key, self.display_units) {
            self.mode = Mode::Normal; // unchanged: no edit, no solve
            return Vec::new();
        }
        let mut next = self.deck.clone();
        match next.set_value(field.key, &buffer, self.display_units) {
            Ok(()) => {
                let before = self.replace_deck(next);
                self.undo.push((before, Some(field.key)));
                self.redo.clear();
                self.mode = Mode::Normal;
                let cmd = self.submit();
                self.dirty_keys.insert(field.key, self.generation);
                vec![cmd]
            }
            Err(e) => {
                let cursor = buffer.chars().count();
                self.mode = Mode::Editing {
                    buffer,
                    cursor,
                    error: Some(e),
                };
                Vec::new()
            }
        }
    }

    fn undo_edit(&mut self) -> Vec<Command> {
        match self.undo.pop() {
            Some((deck, key)) => {
                let cur = self.replace_deck(deck);
                self.redo.push((cur, key));
                let cmd = self.submit();
                if let Some(k) = key {
                    self.dirty_keys.insert(k, self.generation);
                }
                self.message = Some(format!(
                    "undo{}",
                    key.map(|k| format!(" {k}")).unwrap_or_default()
                ));
                vec![cmd]
            }
            None => {
                self.message = Some("nothing to undo".into());
                Vec::new()
            }
        }
    }

    fn redo_edit(&mut self) -> Vec<Command> {
        match self.redo.pop() {
            Some((deck, key)) => {
                let cur = self.replace_deck(deck);
                self.undo.push((cur, key));
                let cmd = self.submit();
                if let Some(k) = key {
                    self.dirty_keys.insert(k, self.generation);
                }
                self.message = Some(format!(
                    "redo{}",
                    key.map(|k| format!(" {k}")).unwrap_or_default()
                ));
                vec![cmd]
            }
            None => {
                self.message = Some("nothing to redo".into());
                Vec::new()
            }
        }
    }

    /// The first field from `start` on (cyclically) whose label or key contains `text`
    /// (case-insensitive).
    pub fn find_field(&self, text: &str, start: usize) -> Option<usize> {
        let t = text.to_lowercase();
        let n = self.fields.len();
        (0..n).map(|k| (start + k) % n.max(1)).find(|&i| {
            self.fields.get(i).is_some_and(|f| {
                f.label.to_lowercase().contains(&t) || f.key.to_lowercase().contains(&t)
            })
        })
    }

    fn on_search_key(&mut self, key: KeyEvent, mut buffer: String, from: usize) -> Vec<Command> {
        match key.code {
            KeyCode::Esc => {
                self.input_sel = from;
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Enter => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            // Tab: the next match after the one shown.
            KeyCode::Tab | KeyCode::Down => {
                if let Some(i) = self.find_field(&buffer, self.input_sel + 1) {
                    self.input_sel = i;
                }
            }
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => {
                buffer.push(ch);
                if let Some(i) = self.find_field(&buffer, from) {
                    self.input_sel = i;
                }
            }
            KeyCode::Backspace => {
                buffer.pop();
                self.input_sel = self.find_field(&buffer, from).unwrap_or(from);
            }
            _ => {}
        }
        self.mode = Mode::Search { buffer, from };
        Vec::new()
    }

    fn on_prompt_key(
        &mut self,
        key: KeyEvent,
        kind: PromptKind,
        mut buffer: String,
    ) -> Vec<Command> {
        match key.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                self.quit_after_save = false;
                return Vec::new();
            }
            KeyCode::Enter => {
                self.mode = Mode::Normal;
                let path = PathBuf::from(buffer.trim());
                if buffer.trim().is_empty() {
                    return Vec::new();
                }
                return match kind {
                    // the deck's own file: a plain save (no question, like Ctrl-s)
                    PromptKind::SaveAs if self.path.as_ref() == Some(&path) => {
                        vec![Command::Save {
                            path,
                            deck: Box::new(self.deck.clone()),
                        }]
                    }
                    // another path: ask first if it exists (checked by the runtime)
                    PromptKind::SaveAs => vec![Command::CheckSaveTarget(path)],
                    PromptKind::Open => vec![Command::Open(path)],
                };
            }
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => buffer.push(ch),
            KeyCode::Backspace => {
                buffer.pop();
            }
            _ => {}
        }
        self.mode = Mode::Prompt { kind, buffer };
        Vec::new()
    }
}

/// Rows of the view's element table.
fn view_element_count(view: &View) -> usize {
    view.screen_table().map_or(0, |t| t.rows.len())
}

/// Steps of the view's stepper trace.
fn view_trace_len(view: &View) -> usize {
    view.trace.as_ref().map_or(0, |t| t.steps.len())
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
    ("h l / ← →", "Rollers, Load", "previous / next roller"),
    (
        "c",
        "Load (when shown)",
        "load chart: roller loads ↔ load per length along the roller",
    ),
    ("u", "any", "display units SI ↔ US"),
    ("r", "any", "re-solve now"),
    ("Ctrl-z / Ctrl-y", "any", "undo / redo an edit"),
    ("Ctrl-s", "any", "save (atomic, keeps .bak)"),
    ("S", "any", "save as…"),
    ("o", "any", "open a deck…"),
    ("R", "any", "revert to the saved file"),
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
