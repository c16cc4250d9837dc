//! Cooperative cancellation, checked by solvers between iterations and between time
//! steps: the workbench's worker sets the flag when a newer edit supersedes a solve.
//! It also carries an optional progress report (issue 24 item 7): long work (the ball's
//! time simulation) says how far it got through the same handle that may stop it, so
//! the layers in between (the analysis, the systems) pass it on without knowing who
//! draws it (the binary's progress bar on a terminal).

use std::sync::atomic::{AtomicBool, Ordering};

/// A progress report: the fraction of the work done, in [0, 1], called from any thread
/// (the ball time simulation solves its balls in parallel).
pub type Progress<'a> = &'a (dyn Fn(f64) + Sync);

/// A cancellation flag that may be absent (one-shot CLI runs cannot be cancelled), and
/// a progress report that may be absent.
#[derive(Clone, Copy, Default)]
pub struct Cancel<'a>(Option<&'a AtomicBool>, Option<Progress<'a>>);

impl std::fmt::Debug for Cancel<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Cancel")
            .field("flag", &self.0)
            .field("progress", &self.1.is_some())
            .finish()
    }
}

impl<'a> Cancel<'a> {
    /// Never cancelled.
    pub const NONE: Cancel<'static> = Cancel(None, None);

    /// Cancelled when `flag` is set.
    pub fn new(flag: &'a AtomicBool) -> Self {
        Cancel(Some(flag), None)
    }

    /// From an optional flag (the form the solvers' signatures used before).
    pub fn from_option(flag: Option<&'a AtomicBool>) -> Self {
        Cancel(flag, None)
    }

    /// This flag with `progress` told of the work done.
    pub fn with_progress(self, progress: Progress<'a>) -> Self {
        Cancel(self.0, Some(progress))
    }

    /// The flag, if any.
    pub fn flag(&self) -> Option<&'a AtomicBool> {
        self.0
    }

    /// The progress report, if any.
    pub fn progress(&self) -> Option<Progress<'a>> {
        self.1
    }

    /// Report `fraction` of the work done (clamped to [0, 1]; nothing without a report).
    pub fn report(&self, fraction: f64) {
        if let Some(p) = self.1 {
            p(if fraction.is_nan() {
                0.0
            } else {
                fraction.clamp(0.0, 1.0)
            });
        }
    }

    /// True once the flag is set. A relaxed load: the flag only ever goes false → true
    /// and the solver checks it again at its next step.
    pub fn is_cancelled(&self) -> bool {
        self.0.is_some_and(|f| f.load(Ordering::Relaxed))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flag_is_seen() {
        let f = AtomicBool::new(false);
        let c = Cancel::new(&f);
        assert!(!c.is_cancelled());
        f.store(true, Ordering::Relaxed);
        assert!(c.is_cancelled());
        assert!(!Cancel::NONE.is_cancelled());
        assert!(Cancel::from_option(Some(&f)).is_cancelled());
    }

    #[test]
    fn progress_is_reported_clamped_and_keeps_the_flag() {
        let f = AtomicBool::new(false);
        let seen = std::sync::Mutex::new(Vec::new());
        let p = |x: f64| seen.lock().map(|mut v| v.push(x)).unwrap_or(());
        let c = Cancel::new(&f).with_progress(&p);
        c.report(0.25);
        c.report(1.5);
        c.report(f64::NAN);
        Cancel::NONE.report(0.5);
        f.store(true, Ordering::Relaxed);
        assert!(c.is_cancelled());
        assert_eq!(*seen.lock().unwrap(), vec![0.25, 1.0, 0.0]);
    }
}
