//! The workbench: a live terminal UI over the pipeline (issue 6).
//!
//! Elm-style: [`App`] is plain state, [`App::handle`] a pure transition returning
//! [`Command`]s, and drawing is `impl Widget for &App`. One [`AppEvent`] channel is fed
//! by an input thread and the solver thread ([`worker`]); the loop blocks on it and
//! redraws only after events, so an idle workbench uses no CPU.
//!
//! Modules: [`app`] (state, transitions, key table), [`render`] (panes), [`view_model`]
//! (formatting of a solution's view), [`deck_io`] (the deck under edit, of any bearing
//! system), [`worker`] (solver thread). Nothing here knows a particular bearing system:
//! the panes, their titles and contents come from the deck's system and its view.

pub mod app;
pub mod deck_io;
pub mod export;
pub mod render;
pub mod view_model;
pub mod worker;

#[cfg(test)]
mod export_tests;
#[cfg(test)]
mod study_tests;
#[cfg(test)]
mod summary_tests;
#[cfg(test)]
mod tests;

use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::Once;
use std::thread;
use std::time::Duration;

use color_eyre::eyre::eyre;
use ratatui::backend::Backend;
use ratatui::Terminal;

pub use app::{App, AppEvent, Command, Pane, KEYS};
pub use deck_io::DeckDoc;
pub use worker::{session_solver, Solver, Worker};

/// Opens the workbench on `deck_text` (read from `source_path`, if any) in the current
/// terminal, and restores the terminal on every exit path. `color_eyre::install()` must
/// have been called first (main does), so ratatui's restore hook runs before its report.
pub fn run_workbench(deck_text: &str, source_path: Option<PathBuf>) -> color_eyre::Result<()> {
    let name = source_path
        .as_ref()
        .map(|p| p.display().to_string())
        .unwrap_or_else(|| "default deck".to_string());
    let deck = DeckDoc::parse(deck_text, &name).map_err(|e| eyre!(e))?;
    run_app(App::new(deck, source_path))
}

/// Like [`run_workbench`] for a deck the caller already parsed (the CLI's, with any
/// `--set` overrides). If the deck differs from the file at `source_path` (overrides
/// applied), it starts marked unsaved.
pub fn run_workbench_case(
    case: Box<dyn crate::bearings::Case>,
    source_path: Option<PathBuf>,
) -> color_eyre::Result<()> {
    let on_disk = source_path
        .as_ref()
        .and_then(|p| crate::deck::read_deck_text(p).ok());
    let mut app = App::new(DeckDoc::from_case(case), source_path);
    if let Some(text) = on_disk {
        app.saved_text = text;
    }
    run_app(app)
}

/// The workbench was ended by a termination signal; the terminal has been restored.
/// `main` exits with [`Interrupted::exit_code`] (128 + the signal number, as a shell
/// reports a process killed by that signal).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("stopped by {} (signal {signal}); terminal restored{}", signal_name(*.signal), if *.unsaved { ", unsaved changes lost" } else { "" })]
pub struct Interrupted {
    /// The signal number.
    pub signal: i32,
    /// The deck had unsaved changes.
    pub unsaved: bool,
}

impl Interrupted {
    /// 128 + the signal number.
    pub fn exit_code(&self) -> u8 {
        u8::try_from(128 + self.signal).unwrap_or(u8::MAX)
    }
}

/// The signals that end the workbench (each restores the terminal first).
pub const TERM_SIGNALS: [i32; 4] = [
    signal_hook::consts::SIGTERM,
    signal_hook::consts::SIGINT,
    signal_hook::consts::SIGHUP,
    signal_hook::consts::SIGQUIT,
];

/// How long the loop has to come round after a signal before the signal thread restores
/// the terminal and exits by itself (a save or solve that does not stop in time).
const SIGNAL_GRACE: Duration = Duration::from_secs(2);

fn signal_name(signal: i32) -> &'static str {
    match signal {
        signal_hook::consts::SIGTERM => "SIGTERM",
        signal_hook::consts::SIGINT => "SIGINT",
        signal_hook::consts::SIGHUP => "SIGHUP",
        signal_hook::consts::SIGQUIT => "SIGQUIT",
        _ => "a signal",
    }
}

/// Takes over the terminal, runs the loop, restores the terminal on every exit path,
/// termination signals included ([`Interrupted`]).
fn run_app(app: App) -> color_eyre::Result<()> {
    let (tx, rx) = mpsc::channel();
    // Before the terminal is taken over: a signal from here on is seen by the loop.
    let signals = spawn_signal_thread(tx.clone())?;
    let mut terminal = ratatui::try_init()?;
    install_solver_panic_filter();
    let result = (|| -> color_eyre::Result<App> {
        spawn_input_thread(tx.clone())?;
        let mut worker = Worker::spawn(tx.clone(), session_solver())?;
        run_loop(&mut terminal, app, &rx, &mut worker)
    })();
    let restored = ratatui::try_restore();
    signals.close();
    let app = result?;
    restored?;
    match app.signal {
        Some(signal) => Err(Interrupted {
            signal,
            unsaved: app.unsaved(),
        }
        .into()),
        None => Ok(()),
    }
}

/// Turns SIGTERM, SIGINT, SIGHUP and SIGQUIT into [`AppEvent::Signal`] so that the loop
/// leaves and the terminal is restored. If the loop has not left [`SIGNAL_GRACE`] after
/// the first signal, or a second signal comes, this thread restores the terminal and
/// exits (128 + signal) itself.
fn spawn_signal_thread(tx: Sender<AppEvent>) -> std::io::Result<signal_hook::iterator::Handle> {
    let mut signals = signal_hook::iterator::Signals::new(TERM_SIGNALS)?;
    let handle = signals.handle();
    thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            let mut first = true;
            for signal in signals.forever() {
                if !first {
                    force_exit(signal);
                }
                first = false;
                if tx.send(AppEvent::Signal(signal)).is_err() {
                    force_exit(signal);
                }
                let _ = thread::Builder::new()
                    .name("signal-grace".into())
                    .spawn(move || {
                        thread::sleep(SIGNAL_GRACE);
                        force_exit(signal);
                    });
            }
        })?;
    Ok(handle)
}

/// Last resort after a signal: restore the terminal and leave with 128 + signal.
fn force_exit(signal: i32) -> ! {
    let _ = ratatui::try_restore();
    std::process::exit(128 + signal)
}

/// Panics on the solver thread are caught by the worker and shown as a failed solve;
/// keep them from reaching ratatui's hook, which would restore (leave) the terminal
/// while the UI keeps running. Panics anywhere else go to the previous hooks.
pub fn install_solver_panic_filter() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if thread::current().name() == Some(worker::SOLVER_THREAD) {
                return;
            }
            previous(info);
        }));
    });
}

/// Reads terminal events forever and forwards keys and resizes.
fn spawn_input_thread(tx: Sender<AppEvent>) -> std::io::Result<()> {
    thread::Builder::new().name("input".into()).spawn(move || {
        use crossterm::event::{self, Event};
        while let Ok(ev) = event::read() {
            let msg = match ev {
                Event::Key(k) => AppEvent::Key(k),
                Event::Resize(w, h) => AppEvent::Resize(w, h),
                _ => continue,
            };
            if tx.send(msg).is_err() {
                break;
            }
        }
    })?;
    Ok(())
}

/// The event loop, generic over the backend so tests can run it on `TestBackend`.
/// Draws, then blocks on `rx` (fed by the input thread and the worker); returns the
/// final app state on quit or when every sender is gone.
pub fn run_loop<B: Backend>(
    terminal: &mut Terminal<B>,
    mut app: App,
    rx: &Receiver<AppEvent>,
    worker: &mut Worker,
) -> color_eyre::Result<App>
where
    B::Error: std::error::Error + Send + Sync + 'static,
{
    let size = terminal.size()?;
    app.size = (size.width, size.height);
    let first = app.start();
    perform(&mut app, first, worker);
    loop {
        if app.quit {
            break;
        }
        terminal.draw(|f| f.render_widget(&app, f.area()))?;
        let Ok(ev) = rx.recv() else { break };
        let cmds = app.handle(ev);
        perform(&mut app, cmds, worker);
        // Coalesce whatever else is already queued before the next frame.
        while let Ok(ev) = rx.try_recv() {
            let cmds = app.handle(ev);
            perform(&mut app, cmds, worker);
        }
    }
    Ok(app)
}

/// Carries out commands; file I/O is synchronous (small files) and its outcome is fed
/// back through [`App::handle`].
pub fn perform(app: &mut App, cmds: Vec<Command>, worker: &mut Worker) {
    let mut queue: VecDeque<Command> = cmds.into();
    let mut save_failed = false;
    while let Some(cmd) = queue.pop_front() {
        let more = match cmd {
            Command::Solve(job) => {
                worker.submit(*job);
                Vec::new()
            }
            Command::Save { path, deck } => {
                let r = deck.save(&path);
                save_failed |= r.is_err();
                let how = match &r {
                    Ok(crate::files::Written::Replaced { via: None, .. }) | Err(_) => None,
                    Ok(w) => Some(format!("saved {w}")),
                };
                let more = app.handle(AppEvent::Saved(r.map(|_| path)));
                // Say what happened when it was not a plain replace (through a link,
                // in place to a device).
                if how.is_some() {
                    app.message = how;
                }
                more
            }
            Command::CheckSaveTarget(path) => {
                // symlink_metadata: a dangling link or a FIFO exists too
                let exists = std::fs::symlink_metadata(&path).is_ok();
                app.handle(AppEvent::SaveTargetChecked { path, exists })
            }
            Command::CheckExportTarget { path, what } => {
                let exists = std::fs::symlink_metadata(&path).is_ok();
                app.handle(AppEvent::ExportTargetChecked { path, what, exists })
            }
            Command::WriteExport {
                path,
                contents,
                what,
            } => {
                let r = export::write(&path, app.path.as_deref(), contents.as_bytes())
                    .map(|w| format!("wrote {w}: {what}"));
                app.handle(AppEvent::Exported(r))
            }
            Command::ExportReport { path, deck, format } => {
                worker.export_report(path, deck.case(), format, app.path.clone());
                Vec::new()
            }
            Command::Open(path) => {
                let r = DeckDoc::load(&path).map(|d| (Box::new(d), path));
                app.handle(AppEvent::Opened(r))
            }
            Command::OpenBaseline(path) => {
                worker.open_baseline(path);
                Vec::new()
            }
            Command::Quit => {
                if save_failed && app.signal.is_none() {
                    app.quit = false; // never lose a deck: stay when the save failed
                } else {
                    app.quit = true;
                }
                Vec::new()
            }
        };
        queue.extend(more);
    }
}
