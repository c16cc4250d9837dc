//! The generic piece of a staged pipeline: a [`Stage`] caches its output together with
//! the inputs it read (its key) and counts its runs. A bearing system's pipeline is a chain
//! of stages; an edit that changes none of a stage's inputs reuses its output, and a stage
//! no view needs is never asked for. Invalidation downstream is the chain's business
//! ([`Stage::invalidate`]): a stage whose upstream re-ran must run again.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

/// One cached stage: the output computed from the inputs `K` it declares.
#[derive(Debug, Clone)]
pub struct Stage<K, V> {
    cached: Option<(K, V)>,
    runs: usize,
}

impl<K, V> Default for Stage<K, V> {
    fn default() -> Self {
        Stage {
            cached: None,
            runs: 0,
        }
    }
}

impl<K: PartialEq, V> Stage<K, V> {
    /// True when the cached output was computed from exactly `key`.
    pub fn is_fresh(&self, key: &K) -> bool {
        matches!(&self.cached, Some((k, _)) if k == key)
    }

    /// Brings the stage up to date with `key`: runs `compute` (and counts the run) unless
    /// the cached output was computed from the same inputs. Returns whether it ran; on an
    /// error the stage is left empty.
    pub fn update<E>(&mut self, key: K, compute: impl FnOnce() -> Result<V, E>) -> Result<bool, E> {
        if self.is_fresh(&key) {
            return Ok(false);
        }
        self.cached = None;
        let v = compute()?;
        self.runs += 1;
        self.cached = Some((key, v));
        Ok(true)
    }

    /// Stores an output derived without a full run (e.g. a cheap re-derivation of part of
    /// it); not counted as a run.
    pub fn store(&mut self, key: K, value: V) {
        self.cached = Some((key, value));
    }
}

impl<K, V> Stage<K, V> {
    /// The cached output, if any.
    pub fn output(&self) -> Option<&V> {
        self.cached.as_ref().map(|c| &c.1)
    }

    /// The cached inputs and output, if any.
    pub fn entry(&self) -> Option<&(K, V)> {
        self.cached.as_ref()
    }

    /// The cached output, moved out.
    pub fn into_output(self) -> Option<V> {
        self.cached.map(|c| c.1)
    }

    /// Forgets the output (an upstream stage re-ran).
    pub fn invalidate(&mut self) {
        self.cached = None;
    }

    /// How many times the stage has run.
    pub fn runs(&self) -> usize {
        self.runs
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_only_when_its_inputs_change() {
        let mut s: Stage<(f64, u32), f64> = Stage::default();
        let ran = s.update((1.0, 2), || Ok::<_, ()>(3.0));
        assert_eq!(ran, Ok(true));
        assert_eq!(s.update((1.0, 2), || Ok::<_, ()>(99.0)), Ok(false));
        assert_eq!(s.output(), Some(&3.0));
        assert_eq!(s.runs(), 1);
        assert_eq!(s.update((1.5, 2), || Ok::<_, ()>(4.0)), Ok(true));
        assert_eq!((s.output(), s.runs()), (Some(&4.0), 2));
        s.invalidate();
        assert_eq!(s.output(), None);
        assert_eq!(s.update((1.5, 2), || Ok::<_, ()>(5.0)), Ok(true));
        assert_eq!(s.runs(), 3);
    }

    #[test]
    fn a_failed_run_leaves_the_stage_empty_and_uncounted() {
        let mut s: Stage<u8, f64> = Stage::default();
        assert_eq!(s.update(1, || Ok::<_, &str>(1.0)), Ok(true));
        assert_eq!(s.update(2, || Err("no")), Err("no"));
        assert_eq!((s.output(), s.runs()), (None, 1));
        s.store(3, 7.0);
        assert_eq!((s.output(), s.runs()), (Some(&7.0), 1));
        assert!(s.is_fresh(&3));
    }
}
