//! The solver thread: newest job wins.
//!
//! Jobs carry a generation and their own cancel flag. Submitting a job raises the
//! previous job's flag (the pipeline checks it between iterations), the thread drains
//! its queue down to the newest job, results of cancelled jobs are dropped, and a panic
//! inside the solver is caught and reported as a failed solve.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::Arc;
use std::thread::{self, JoinHandle};

use crate::bearings::view::{Chart, JobView, View};
use crate::bearings::{Case, Detail, Session, SolveError};
use crate::numerics::cancel::Cancel;
use crate::studies::sweep::run_plan;

use super::app::{AppEvent, SolveJob};

/// Name of the solver thread (the panic filter in `tui/mod.rs` keys on it).
pub const SOLVER_THREAD: &str = "solver";

/// The function the worker calls: the deck's system's session in the app, anything in
/// tests. It returns the solution's view (built on the solver thread, so the UI thread
/// only draws).
///
/// The last argument receives chart `detail.stream_chart` as it grows
/// ([`Session::solve_streaming`]); a solver that streams nothing never calls it.
pub type Solver = Arc<
    dyn Fn(&dyn Case, Detail, &AtomicBool, &mut dyn FnMut(usize, Chart)) -> Result<View, SolveError>
        + Send
        + Sync,
>;

/// The real solvers: one [`Session`] per bearing system, kept across jobs so an edit
/// re-runs only the stages whose inputs it changed (only the solver thread calls it; the
/// mutex is uncontended, and a panic inside a solve poisons nothing we rely on: a
/// poisoned set of sessions is replaced by an empty one).
pub fn session_solver() -> Solver {
    type Sessions = Vec<(&'static str, Box<dyn Session>)>;
    let sessions: Arc<std::sync::Mutex<Sessions>> = Arc::default();
    Arc::new(move |case, detail, cancel, on_chart| {
        let mut guard = match sessions.lock() {
            Ok(g) => g,
            Err(poisoned) => {
                let mut g = poisoned.into_inner();
                g.clear();
                g
            }
        };
        let system = case.system();
        let index = match guard.iter().position(|(id, _)| *id == system.id()) {
            Some(i) => i,
            None => {
                guard.push((system.id(), system.session()));
                guard.len() - 1
            }
        };
        let Some((_, session)) = guard.get_mut(index) else {
            return Err(SolveError::Stage {
                stage: "session",
                message: format!("no session for {}", system.id()),
            });
        };
        // The status line's time is the solve as the user waited for it, measured here
        // for every system alike (a system's own counters may not time themselves).
        let start = std::time::Instant::now();
        session
            .solve_streaming(case, detail, &Cancel::new(cancel), on_chart)
            .map(|s| {
                let mut view = s.view();
                view.stats.wall_time_s = start.elapsed().as_secs_f64();
                view
            })
    })
}

struct Job {
    job: SolveJob,
    cancel: Arc<AtomicBool>,
}

/// Handle to the solver thread, owned by the UI loop.
pub struct Worker {
    jobs: Option<Sender<Job>>,
    /// The UI's channel, for the report exports' threads.
    events: Sender<AppEvent>,
    last_cancel: Option<Arc<AtomicBool>>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the solver thread; results arrive on `events` as [`AppEvent::Solved`].
    pub fn spawn(events: Sender<AppEvent>, solver: Solver) -> std::io::Result<Worker> {
        let (tx, rx) = mpsc::channel::<Job>();
        let ui = events.clone();
        let handle = thread::Builder::new()
            .name(SOLVER_THREAD.into())
            .spawn(move || worker_loop(rx, events, solver))?;
        Ok(Worker {
            jobs: Some(tx),
            events: ui,
            last_cancel: None,
            handle: Some(handle),
        })
    }

    /// Queues `job`, cancelling whatever is in flight or queued.
    pub fn submit(&mut self, job: SolveJob) {
        if let Some(c) = self.last_cancel.take() {
            c.store(true, Ordering::Release);
        }
        let cancel = Arc::new(AtomicBool::new(false));
        self.last_cancel = Some(Arc::clone(&cancel));
        if let Some(tx) = &self.jobs {
            let _ = tx.send(Job { job, cancel });
        }
    }
}

impl Worker {
    /// Writes `case`'s report to `path` in `format` as `rollbench run` does (its own
    /// solve with the run's defaults, the deck's units, through the safe writer; never
    /// over the deck at `deck_path`), on a thread of its own so the workbench stays live;
    /// the outcome comes back as [`AppEvent::Exported`]. A panic is reported, not raised.
    pub fn export_report(
        &self,
        path: std::path::PathBuf,
        case: Arc<dyn Case>,
        format: crate::report::Format,
        deck_path: Option<std::path::PathBuf>,
    ) {
        let events = self.events.clone();
        let spawned = thread::Builder::new()
            .name(SOLVER_THREAD.into())
            .spawn(move || {
                let outcome = catch_unwind(AssertUnwindSafe(|| {
                    report_to(&path, &*case, format, deck_path.as_deref())
                }))
                .unwrap_or_else(|p| {
                    Err(format!("the report panicked: {}", panic_text(p.as_ref())))
                });
                let _ = events.send(AppEvent::Exported(outcome));
            });
        if let Err(e) = spawned {
            let _ = self.events.send(AppEvent::Exported(Err(format!(
                "cannot start the report: {e}"
            ))));
        }
    }
}

impl Worker {
    /// Reads the deck at `path` and solves it as `rollbench run` does (no transient: the
    /// comparison reads no time history) on a thread of its own, then reports
    /// [`AppEvent::BaselineOpened`]: the baseline, or the whole reason (the deck's
    /// errors with their lines, the solver's failure).
    pub fn open_baseline(&self, path: std::path::PathBuf) {
        let events = self.events.clone();
        let for_thread = path.clone();
        let spawned = thread::Builder::new()
            .name(SOLVER_THREAD.into())
            .spawn(move || {
                let path = for_thread;
                let outcome =
                    catch_unwind(AssertUnwindSafe(|| baseline_of(&path))).unwrap_or_else(|p| {
                        Err(format!("the solve panicked: {}", panic_text(p.as_ref())))
                    });
                let _ = events.send(AppEvent::BaselineOpened { path, outcome });
            });
        if let Err(e) = spawned {
            let _ = self.events.send(AppEvent::BaselineOpened {
                path,
                outcome: Err(format!("cannot start the solve: {e}")),
            });
        }
    }
}

/// The deck at `path` read (through the deck reader: bounded, UTF-8, validated) and
/// solved; see [`Worker::open_baseline`].
pub fn baseline_of(path: &std::path::Path) -> Result<super::app::Baseline, String> {
    let deck = super::deck_io::DeckDoc::load(path)?;
    let case = deck.case();
    let solution = case
        .solve(
            crate::bearings::RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .map_err(|e| format!("solve failed: {e}"))?;
    Ok(super::app::Baseline::new(
        path.display().to_string(),
        deck.system(),
        Arc::new(solution.view()),
    ))
}

/// Solves `case` as `rollbench run` does and writes its report (see
/// [`Worker::export_report`]); the status line's sentence, or why not.
fn report_to(
    path: &std::path::Path,
    case: &dyn Case,
    format: crate::report::Format,
    deck_path: Option<&std::path::Path>,
) -> Result<String, String> {
    let solution = case
        .solve(crate::bearings::RunOptions::default(), Cancel::NONE)
        .map_err(|e| format!("solve failed: {e}"))?;
    let text = crate::report::render(solution.as_ref(), format, case.units());
    let written = super::export::write(path, deck_path, text.as_bytes())?;
    Ok(format!(
        "wrote {written}: the {} report, as `run` writes it",
        super::export::format_name(format)
    ))
}

#[cfg(test)]
impl Worker {
    /// The newest job's cancel flag (tests: a submit raises the previous one).
    pub fn current_cancel(&self) -> Option<Arc<AtomicBool>> {
        self.last_cancel.clone()
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        if let Some(c) = self.last_cancel.take() {
            c.store(true, Ordering::Release);
        }
        self.jobs.take(); // closes the channel: the thread's recv() fails and it exits
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// Text of a panic payload.
pub fn panic_text(p: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

fn worker_loop(rx: Receiver<Job>, events: Sender<AppEvent>, solver: Solver) {
    while let Ok(mut job) = rx.recv() {
        while let Ok(newer) = rx.try_recv() {
            job = newer; // drain to the newest (older ones were cancelled on submit)
        }
        if job.cancel.load(Ordering::Acquire) {
            continue;
        }
        let SolveJob {
            generation,
            case,
            detail,
            sweep,
            job: pane_job,
            study,
        } = &job.job;
        // A chart the session streams (the ball's Skid chart) goes to the UI as it grows;
        // a send to a closed UI is noticed after the solve.
        let mut on_chart = |n: usize, chart: Chart| {
            let _ = events.send(AppEvent::ChartProgress {
                generation: *generation,
                chart_index: n,
                chart: Arc::new(chart),
            });
        };
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            solver(&**case, *detail, &job.cancel, &mut on_chart)
        }));
        if job.cancel.load(Ordering::Acquire) {
            continue; // superseded while solving: stale
        }
        let outcome = match outcome {
            Ok(Ok(view)) => Ok(Arc::new(view)),
            Ok(Err(SolveError::Cancelled)) => continue,
            Ok(Err(e)) => Err(e.to_string()),
            Err(p) => Err(format!("solver panicked: {}", panic_text(p.as_ref()))),
        };
        let solved = outcome.is_ok();
        let msg = AppEvent::Solved {
            generation: *generation,
            outcome,
        };
        if events.send(msg).is_err() {
            break; // UI gone
        }
        // The Sweep pane on screen: its points, one by one after the case itself, each
        // sent as it is solved; a newer job cancels the rest.
        let plan = sweep.and_then(|n| case.system().sweep_plan(n, &**case));
        if let (true, Some(n), Some(plan)) = (solved, *sweep, plan) {
            let mut solve = |c: &dyn Case| match catch_unwind(AssertUnwindSafe(|| {
                solver(c, Detail::default(), &job.cancel, &mut |_, _| {})
            })) {
                Ok(r) => r,
                Err(p) => Err(SolveError::Stage {
                    stage: "sweep",
                    message: format!("solver panicked: {}", panic_text(p.as_ref())),
                }),
            };
            // Every submit raises the previous job's flag: a newer edit stops the sweep.
            let cancelled = || job.cancel.load(Ordering::Acquire);
            let mut gone = false;
            let mut report = |p: &crate::studies::sweep::PlanProgress| {
                let msg = AppEvent::SweepProgress {
                    generation: *generation,
                    pane: n,
                    progress: Arc::new(p.clone()),
                };
                gone |= events.send(msg).is_err();
            };
            run_plan(&**case, plan, &mut solve, &cancelled, &mut report);
            if gone {
                break;
            }
        }
        // The job pane on screen: the system's job, its reports sent as they come (at most
        // one per 50 ms, the last always), its end as a last report; a newer job's submit
        // raises the flag and the job stops at its next check.
        if let (true, Some(n)) = (solved, *pane_job) {
            if run_job(&**case, n, *generation, &job.cancel, &events) {
                break;
            }
        }
        // The Study pane on screen: its study, the rows so far sent after each batch;
        // a newer job's submit raises the flag and the study stops.
        if let (true, Some(request)) = (solved, study) {
            if run_study(&**case, request, *generation, &job.cancel, &events) {
                break;
            }
        }
    }
}

/// Runs the Study pane's study of `case` for solve `generation`, sending the rows so far
/// as [`AppEvent::StudyProgress`] (at most one per 50 ms, the last always); true when the
/// UI is gone.
fn run_study(
    case: &dyn Case,
    request: &super::app::StudyRequest,
    generation: u64,
    cancel: &AtomicBool,
    events: &Sender<AppEvent>,
) -> bool {
    use crate::studies::study::workbench::{self, StudyProgress};
    let send = |p: StudyProgress| {
        events
            .send(AppEvent::StudyProgress {
                generation,
                progress: Arc::new(p),
            })
            .is_err()
    };
    let mut gone = false;
    let mut last: Option<std::time::Instant> = None;
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let study = workbench::for_deck(case, request.deck_path.as_deref(), request.samples)?;
        Ok::<_, String>(workbench::run(&study, cancel, &mut |p| {
            let due = last.is_none_or(|t| t.elapsed() >= std::time::Duration::from_millis(50));
            if (due || p.finished) && !cancel.load(Ordering::Acquire) {
                gone |= send(p.clone());
                last = Some(std::time::Instant::now());
            }
        }))
    }));
    if gone || cancel.load(Ordering::Acquire) {
        return gone; // superseded: its rows are stale
    }
    match outcome {
        Ok(Ok(Some(done))) => send(done),
        Ok(Ok(None)) => false,
        Ok(Err(e)) => send(StudyProgress::failed(e)),
        Err(p) => send(StudyProgress::failed(format!(
            "the study panicked: {}",
            panic_text(p.as_ref())
        ))),
    }
}

/// Runs job `n` of `case`'s system for solve `generation`, sending its reports as
/// [`AppEvent::JobProgress`]; true when the UI is gone.
fn run_job(
    case: &dyn Case,
    n: usize,
    generation: u64,
    cancel: &AtomicBool,
    events: &Sender<AppEvent>,
) -> bool {
    let send = |view: JobView| {
        events
            .send(AppEvent::JobProgress {
                generation,
                pane: n,
                view: Arc::new(view),
            })
            .is_err()
    };
    let mut gone = false;
    let mut last: Option<std::time::Instant> = None;
    let mut report = |v: &JobView| {
        let due = last.is_none_or(|t| t.elapsed() >= std::time::Duration::from_millis(50));
        if (due || v.finished) && !cancel.load(Ordering::Acquire) {
            gone |= send(v.clone());
            last = Some(std::time::Instant::now());
        }
    };
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        case.system()
            .run_job(n, case, Cancel::new(cancel), &mut report)
    }));
    if gone || cancel.load(Ordering::Acquire) {
        return gone; // superseded: its results are stale
    }
    let last_view = match outcome {
        Ok(None) => return false,
        Ok(Some(Ok(view))) => view,
        Ok(Some(Err(SolveError::Cancelled))) => return false,
        Ok(Some(Err(e))) => JobView::failed(e.to_string()),
        Err(p) => JobView::failed(format!("the job panicked: {}", panic_text(p.as_ref()))),
    };
    send(last_view)
}
