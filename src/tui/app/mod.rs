//! Plain application state and its pure transitions (`App::handle`).
//!
//! `handle` never does I/O and never blocks: it mutates the state and returns
//! [`Command`]s (solve, save, open, quit) that the runtime loop in `tui/mod.rs`
//! performs, feeding the outcome back as another [`AppEvent`]. Tests drive it directly.
//!
//! This file holds the state types, [`App`]'s construction, what it answers about itself
//! (panes, layout, selection) and [`App::handle`], which applies every event. The key
//! handling is split by concern: `keys` (the key map of each mode and the [`KEYS`]
//! table that documents it), `edit` (editing a field, undo/redo, search, path prompts),
//! `navigation` (focus, selection, the stepper's steps), `solve` (what to ask the
//! solver and when).

mod baseline;
mod edit;
mod export;
mod keys;
mod navigation;
mod solve;

pub use baseline::Baseline;
pub use keys::{keys_markdown, KEYS};

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;

use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use crate::bearings::view::{PaneKind, View};
use crate::bearings::{Case, Detail};
use crate::studies::study::workbench::StudyProgress;
use crate::studies::sweep::PlanProgress;
use crate::units::Units;

use super::deck_io::{DeckDoc, FieldInfo};

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
    /// The worker's job of pane `Job(pane)` for solve `generation` reported what it has
    /// so far (the whole job so far; `view.finished` once it is done).
    JobProgress {
        /// Job generation.
        generation: u64,
        /// The job pane's index.
        pane: usize,
        /// The job so far.
        view: Arc<crate::bearings::view::JobView>,
    },
    /// The worker's Study pane study for solve `generation` has these rows so far
    /// (`progress.finished` once every point is in).
    StudyProgress {
        /// Job generation.
        generation: u64,
        /// The study so far.
        progress: Arc<StudyProgress>,
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
    /// The runtime looked at an export target ([`Command::CheckExportTarget`]).
    ExportTargetChecked {
        /// The typed path.
        path: PathBuf,
        /// What is exported.
        what: ExportWhat,
        /// Something already exists there.
        exists: bool,
    },
    /// An export finished: what was written where, or why not.
    Exported(Result<String, String>),
    /// The deck at `path` was read and solved as the baseline ([`Command::OpenBaseline`]),
    /// or why not.
    BaselineOpened {
        /// The typed path.
        path: PathBuf,
        /// The solved baseline, or the whole reason it is not.
        outcome: Result<Baseline, String>,
    },
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
    /// The job pane on screen (`PaneKind::Job(n)`), run after the case.
    pub job: Option<usize>,
    /// The Study pane on screen (`PaneKind::Study`): its study, run after the case.
    pub study: Option<StudyRequest>,
}

/// What the Study pane asks the worker to run: the study file beside the deck that
/// names it, else the default tolerance study of `samples` points
/// ([`crate::studies::study::workbench::for_deck`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StudyRequest {
    /// The deck's file (where study files naming it are looked for).
    pub deck_path: Option<PathBuf>,
    /// Samples of the default study.
    pub samples: usize,
}

impl std::fmt::Debug for SolveJob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolveJob")
            .field("generation", &self.generation)
            .field("system", &self.case.system().id())
            .field("detail", &self.detail)
            .field("sweep", &self.sweep)
            .field("job", &self.job)
            .field("study", &self.study)
            .finish()
    }
}

impl PartialEq for SolveJob {
    fn eq(&self, other: &Self) -> bool {
        self.generation == other.generation
            && self.detail == other.detail
            && self.sweep == other.sweep
            && self.job == other.job
            && self.study == other.study
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
    /// Read the deck at this path and solve it (in the background) as the baseline, then
    /// report [`AppEvent::BaselineOpened`].
    OpenBaseline(PathBuf),
    /// Save as: see whether this path already exists, then report
    /// [`AppEvent::SaveTargetChecked`] (the app asks before replacing it).
    CheckSaveTarget(PathBuf),
    /// Export: see whether this path already exists, then report
    /// [`AppEvent::ExportTargetChecked`] (the app asks before replacing it).
    CheckExportTarget {
        /// The typed path.
        path: PathBuf,
        /// What is exported.
        what: ExportWhat,
    },
    /// Write a pane's export ([`super::export::pane_export`]) through the safe writer,
    /// then report [`AppEvent::Exported`].
    WriteExport {
        /// Target path.
        path: PathBuf,
        /// The file's contents.
        contents: String,
        /// What it is, for the status line.
        what: String,
    },
    /// Solve the deck as `rollbench run` does and write its report in `format` (in the
    /// background: the worker's report thread), then report [`AppEvent::Exported`].
    ExportReport {
        /// Target path.
        path: PathBuf,
        /// The deck to report on.
        deck: Box<DeckDoc>,
        /// JSON, CSV or text, by the path's extension.
        format: crate::report::Format,
    },
    /// Leave the workbench.
    Quit,
}

/// What the export prompt writes (issue 30 item 20).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExportWhat {
    /// The focused pane's data (`x`).
    Pane,
    /// The whole report, as `rollbench run` writes it (`X`).
    Report,
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
        /// The solve started from the session's last answer (its counts are from there).
        warm: bool,
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
    /// Export the focused pane or the report to a file.
    Export(ExportWhat),
    /// A deck file to solve as the baseline (issue 30 item 21).
    Baseline,
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
    /// Export over a file that exists.
    ConfirmExport {
        /// The existing target.
        path: PathBuf,
        /// What is exported.
        what: ExportWhat,
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
    /// The job pane the last submitted solve was asked to run.
    pub last_job: Option<usize>,
    /// The newest job report of the current generation: (generation, pane index, the job
    /// so far); dropped when a new solve is submitted (it was of another deck or is
    /// started again).
    pub job: Option<(u64, usize, Arc<crate::bearings::view::JobView>)>,
    /// The Study pane's request of the last submitted solve.
    pub last_study: Option<StudyRequest>,
    /// The newest Study pane progress of the current generation: (generation, the study
    /// so far); dropped when a new solve is submitted.
    pub study: Option<(u64, Arc<StudyProgress>)>,
    /// The Study pane's output shown (an index into the study's outputs).
    pub study_output: usize,
    /// Samples of the Study pane's default tolerance study (`h`/`l`).
    pub study_samples: usize,
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
    /// The Summary pane's first line shown (it scrolls when its lines do not fit).
    pub summary_scroll: usize,
    /// Horizontal scroll (`h`/`l`): the element table's columns scrolled off after its
    /// first (issue 30 item 15); a text pane's characters scrolled off at the left.
    pub col_scroll: usize,
    /// A text pane's first line shown (`j`/`k`/`g`/`G`; issue 30 item 5).
    pub text_scroll: usize,
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
    /// The design the panes compare the current solution with (issue 30 item 21): set
    /// by `b` (pin) or `B` (a deck file), cleared by `D`; never changed by an edit.
    pub baseline: Option<Baseline>,
    /// The element table's values or its changes from the baseline (`d`).
    pub table_delta: crate::tui::view_model::TableDelta,
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
            last_job: None,
            job: None,
            last_study: None,
            study: None,
            study_output: 0,
            study_samples: crate::studies::study::workbench::DEFAULT_SAMPLES,
            streamed: None,
            solve: SolveState::Idle,
            view: None,
            roller_sel: 0,
            chart_laminae: false,
            step: 0,
            thermal_node: None,
            summary_scroll: 0,
            col_scroll: 0,
            text_scroll: 0,
            message: None,
            error: None,
            quit: false,
            quit_after_save: false,
            help_scroll: 0,
            signal: None,
            baseline: None,
            table_delta: Default::default(),
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

    /// The pane the wide layout's chart slot shows: the focused chart, text, sweep or job
    /// pane, else the first chart.
    pub fn chart_slot(&self) -> Pane {
        match self.focus {
            p @ (Pane::Summary
            | Pane::Chart(_)
            | Pane::Text(_)
            | Pane::Sweep(_)
            | Pane::Job(_)
            | Pane::Study) => p,
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
                Pane::Summary
                | Pane::Chart(_)
                | Pane::Text(_)
                | Pane::Sweep(_)
                | Pane::Job(_)
                | Pane::Study => self.chart_slot() == pane,
                _ => true,
            }
        } else {
            self.focus == pane
        }
    }

    /// The selected element's number as the element table's `#` shows it (from 1 in
    /// every system), so the stepper and chart labels name the row the table shows; its
    /// position + 1 when the table has no such column (or before the first solution).
    pub fn element_number(&self) -> usize {
        self.view
            .as_deref()
            .and_then(|v| v.screen_table())
            .and_then(|t| {
                // The screen's `#`: the `number` column (from 1 in every system), else a
                // system's `index` that already counts from 1 (issue 30 item 9).
                let c = ["number", "index"]
                    .iter()
                    .find_map(|k| t.columns.iter().position(|c| c.key == *k))?;
                let v = (*t.rows.get(self.roller_sel)?.get(c)?)?;
                (v.is_finite() && v >= 0.0).then_some(v as usize)
            })
            .unwrap_or(self.roller_sel + 1)
    }

    /// Number of rolling elements in the newest solution (0 before the first).
    pub fn roller_count(&self) -> usize {
        self.view.as_deref().map_or(0, view_element_count)
    }

    /// Number of recorded stepper steps.
    pub fn trace_len(&self) -> usize {
        self.view.as_deref().map_or(0, view_trace_len)
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
                            warm: s.warm_start,
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
            AppEvent::JobProgress {
                generation,
                pane,
                view,
            } => {
                if generation == self.generation {
                    self.job = Some((generation, pane, view));
                }
                Vec::new()
            }
            AppEvent::StudyProgress {
                generation,
                progress,
            } => {
                if generation == self.generation {
                    self.study = Some((generation, progress));
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
            AppEvent::ExportTargetChecked { path, what, exists } => {
                if exists {
                    self.mode = Mode::ConfirmExport { path, what };
                    Vec::new()
                } else {
                    self.export_commands(path, what)
                }
            }
            AppEvent::Exported(Ok(m)) => {
                self.message = Some(m);
                Vec::new()
            }
            AppEvent::Exported(Err(e)) => {
                self.message = Some("export failed (e: the whole message)".into());
                self.error = Some(format!("export failed:\n{e}"));
                self.mode = Mode::Error;
                Vec::new()
            }
            AppEvent::BaselineOpened { path, outcome } => self.baseline_opened(outcome, path),
            AppEvent::Signal(n) => {
                // A signal is not a question: quit even with unsaved changes or a prompt open.
                self.signal = Some(n);
                self.quit = true;
                vec![Command::Quit]
            }
        }
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
