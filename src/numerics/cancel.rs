//! Cooperative cancellation, checked by solvers between iterations and between time
//! steps: the workbench's worker sets the flag when a newer edit supersedes a solve.

use std::sync::atomic::{AtomicBool, Ordering};

/// A cancellation flag that may be absent (one-shot CLI runs cannot be cancelled).
#[derive(Debug, Clone, Copy, Default)]
pub struct Cancel<'a>(Option<&'a AtomicBool>);

impl<'a> Cancel<'a> {
    /// Never cancelled.
    pub const NONE: Cancel<'static> = Cancel(None);

    /// Cancelled when `flag` is set.
    pub fn new(flag: &'a AtomicBool) -> Self {
        Cancel(Some(flag))
    }

    /// From an optional flag (the form the solvers' signatures used before).
    pub fn from_option(flag: Option<&'a AtomicBool>) -> Self {
        Cancel(flag)
    }

    /// The flag, if any.
    pub fn flag(&self) -> Option<&'a AtomicBool> {
        self.0
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
}
