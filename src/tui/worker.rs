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

use crate::bearings::spherical_roller::pipeline::{self, Analysis, Request};
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;

use super::app::{AppEvent, SolveJob};

/// Name of the solver thread (the panic filter in `tui/mod.rs` keys on it).
pub const SOLVER_THREAD: &str = "solver";

/// The function the worker calls: `pipeline::run` in the app, anything in tests.
pub type Solver =
    Arc<dyn Fn(&Bearing, &Request, &AtomicBool) -> Result<Analysis, SolveError> + Send + Sync>;

/// The real pipeline, with its stage cache kept across jobs: an edit re-runs only the
/// stages whose inputs it changed (only the solver thread calls it; the mutex is
/// uncontended, and a panic inside a solve poisons nothing we rely on: a poisoned cache is
/// replaced by an empty one).
pub fn pipeline_solver() -> Solver {
    let cache = Arc::new(std::sync::Mutex::new(pipeline::Pipeline::new()));
    Arc::new(move |b, r, cancel| {
        let mut guard = match cache.lock() {
            Ok(g) => g,
            Err(poisoned) => {
                let mut g = poisoned.into_inner();
                *g = pipeline::Pipeline::new();
                g
            }
        };
        guard.run(b, r.thermal.as_ref(), r, Some(cancel))
    })
}

struct Job {
    job: SolveJob,
    cancel: Arc<AtomicBool>,
}

/// Handle to the solver thread, owned by the UI loop.
pub struct Worker {
    jobs: Option<Sender<Job>>,
    last_cancel: Option<Arc<AtomicBool>>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the solver thread; results arrive on `events` as [`AppEvent::Solved`].
    pub fn spawn(events: Sender<AppEvent>, solver: Solver) -> std::io::Result<Worker> {
        let (tx, rx) = mpsc::channel::<Job>();
        let handle = thread::Builder::new()
            .name(SOLVER_THREAD.into())
            .spawn(move || worker_loop(rx, events, solver))?;
        Ok(Worker {
            jobs: Some(tx),
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
            bearing,
            request,
        } = &job.job;
        let outcome = catch_unwind(AssertUnwindSafe(|| solver(bearing, request, &job.cancel)));
        if job.cancel.load(Ordering::Acquire) {
            continue; // superseded while solving: stale
        }
        let outcome = match outcome {
            Ok(Ok(a)) => Ok(Arc::new(a)),
            Ok(Err(SolveError::Cancelled)) => continue,
            Ok(Err(e)) => Err(e.to_string()),
            Err(p) => Err(format!("solver panicked: {}", panic_text(p.as_ref()))),
        };
        let msg = AppEvent::Solved {
            generation: *generation,
            outcome,
        };
        if events.send(msg).is_err() {
            break; // UI gone
        }
    }
}
