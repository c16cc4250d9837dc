//! What to ask the solver and when: the detail, sweep and job the visible panes need, a new
//! solve job ([`App::submit`]'s generation bump), re-solving when a pane comes into view
//! that needs more than the last job gave, and the chart the running job streams. Apart
//! because it is the one place that builds a solve job and decides what it asks for.

use super::{App, Command, Pane, SolveJob, SolveState, StudyRequest};
use crate::bearings::Detail;

impl App {
    /// What the visible panes need from the solver: the stepper's trace and the thermal
    /// transient only when their panes are on screen (a time simulation of a system
    /// without a Thermal pane always); the other stages (contact, heat) take `Request`'s
    /// defaults.
    pub fn wanted_request(&self) -> Detail {
        Detail {
            trace_element: self.visible(Pane::Stepper).then_some(self.roller_sel),
            // A system with a Thermal pane runs its transient for that pane only; one
            // without (the cylindrical roller's dynamics, drawn on its chart panes) runs
            // its time simulation with every solve.
            transient: self.deck.has_thermal()
                && (self.visible(Pane::Thermal) || !self.panes().contains(&Pane::Thermal)),
            stream_chart: self.panes().into_iter().find_map(|p| match p {
                Pane::Chart(n) if self.visible(p) => Some(n),
                _ => None,
            }),
        }
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

    /// The job pane on screen, if any (the worker runs a job only for a visible pane).
    pub fn wanted_job(&self) -> Option<usize> {
        self.panes().into_iter().find_map(|p| match p {
            Pane::Job(n) if self.visible(p) => Some(n),
            _ => None,
        })
    }

    /// The Study pane's request when it is on screen (the worker runs a study only for
    /// a visible pane).
    pub fn wanted_study(&self) -> Option<StudyRequest> {
        self.visible(Pane::Study).then(|| StudyRequest {
            deck_path: self.path.clone(),
            samples: self.study_samples,
        })
    }

    pub(super) fn submit(&mut self) -> Command {
        self.generation += 1;
        self.last_request = self.wanted_request();
        self.last_sweep = self.wanted_sweep();
        self.last_job = self.wanted_job();
        self.last_study = self.wanted_study();
        // The worker cancels the running job with this submit: what it reported is of the
        // old deck (or starts over), so it is dropped.
        self.job = None;
        self.study = None;
        self.solve = SolveState::Running;
        Command::Solve(Box::new(SolveJob {
            generation: self.generation,
            case: self.deck.case(),
            detail: self.last_request,
            sweep: self.last_sweep,
            job: self.last_job,
            study: self.last_study.clone(),
        }))
    }

    /// Re-solves if the visible panes now need more than the last request gave.
    pub(super) fn resolve_if_needed(&mut self) -> Vec<Command> {
        let want = self.wanted_request();
        let have = &self.last_request;
        let need_trace = want.trace_element.is_some() && want.trace_element != have.trace_element;
        let need_thermal = want.transient && !have.transient;
        let want_sweep = self.wanted_sweep();
        let need_sweep = want_sweep.is_some() && want_sweep != self.last_sweep;
        let want_job = self.wanted_job();
        let need_job = want_job.is_some() && want_job != self.last_job;
        let want_study = self.wanted_study();
        let need_study = want_study.is_some() && want_study != self.last_study;
        if need_trace || need_thermal || need_sweep || need_job || need_study {
            vec![self.submit()]
        } else {
            Vec::new()
        }
    }
}
