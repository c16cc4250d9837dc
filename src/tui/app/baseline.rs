//! Two designs side by side in the workbench (issue 30 item 21): a baseline — the
//! current solution pinned (`b`), or another deck file solved once (`B`) — that the
//! Summary pane compares the current solution with, line by line, by the rule of
//! `rollbench diff` ([`crate::report::diff::compare`], the baseline as A and the current
//! design as B: Δ = current − baseline). An edit re-solves only the current design; the
//! baseline stays as it was until it is pinned again or cleared (`D`).

use std::path::PathBuf;
use std::sync::Arc;

use super::{App, Command, Mode, PromptKind};
use crate::bearings::view::View;
use crate::report::diff::{compare, Diff, Side};
use crate::tui::view_model::{tables_against, TableDelta};

/// A solved design the panes compare with.
#[derive(Debug, Clone)]
pub struct Baseline {
    /// What the status line calls it (the deck's file, `(pinned)` when pinned).
    pub name: String,
    /// Its bearing system's title.
    pub system: &'static str,
    /// What one of its rolling elements is called.
    pub element: &'static str,
    /// Its solution's view, as it was when pinned or opened.
    pub view: Arc<View>,
}

impl Baseline {
    /// The solution `view` of a deck of `system` called `name`.
    pub fn new(name: String, system: &dyn crate::bearings::BearingSystem, view: Arc<View>) -> Self {
        Baseline {
            name,
            system: system.title(),
            element: system.element_name(),
            view,
        }
    }
}

impl App {
    /// `b`: the solution on screen becomes the baseline (again, when one is pinned).
    pub(super) fn pin_baseline(&mut self) -> Vec<Command> {
        let Some(view) = self.view.clone() else {
            self.message = Some("nothing to pin: no solution yet".into());
            return Vec::new();
        };
        let file = self.path.as_ref().map_or_else(
            || self.deck.name().to_string(),
            |p| {
                p.file_name()
                    .map_or_else(|| p.display().to_string(), |f| f.to_string_lossy().into())
            },
        );
        let name = format!("{file} (pinned)");
        self.message = Some(format!("baseline pinned: {name}"));
        self.baseline = Some(Baseline::new(name, self.deck.system(), view));
        Vec::new()
    }

    /// `d`: the element table's values → Δ → Δ% → values (with a baseline).
    pub(super) fn cycle_table_delta(&mut self) -> Vec<Command> {
        if self.baseline.is_none() {
            self.message =
                Some("no baseline: b pins the solution on screen, B opens a deck".into());
            return Vec::new();
        }
        self.table_delta = self.table_delta.next();
        self.message = Some(
            match self.table_delta {
                TableDelta::Values => "element table: values",
                TableDelta::Change => "element table: Δ = now − baseline",
                TableDelta::Percent => "element table: Δ % of the baseline",
            }
            .into(),
        );
        Vec::new()
    }

    /// What the element table is differenced against (issue 30 item 21): `None` when it
    /// shows values (no baseline, or `d` cycled back); else the baseline's view and the
    /// mode, or why the tables do not compare (two systems, element counts).
    pub fn table_baseline(&self) -> Option<Result<(&View, TableDelta), String>> {
        if self.table_delta == TableDelta::Values {
            return None;
        }
        let (b, view) = (self.baseline.as_ref()?, self.view.as_deref()?);
        Some(tables_against(view, &b.view, b.element).map(|()| (&*b.view, self.table_delta)))
    }

    /// `D`: no baseline.
    pub(super) fn clear_baseline(&mut self) -> Vec<Command> {
        self.table_delta = TableDelta::Values;
        self.message = Some(match self.baseline.take() {
            Some(b) => format!("baseline cleared: {}", b.name),
            None => "no baseline to clear".into(),
        });
        Vec::new()
    }

    /// `B`: ask for a deck file to solve as the baseline.
    pub(super) fn open_baseline_prompt(&mut self) -> Vec<Command> {
        self.open_prompt(PromptKind::Baseline);
        Vec::new()
    }

    /// The baseline deck at `path` was read and solved (or why not, whole).
    pub(super) fn baseline_opened(
        &mut self,
        outcome: Result<Baseline, String>,
        path: PathBuf,
    ) -> Vec<Command> {
        match outcome {
            Ok(b) => {
                self.message = Some(format!("baseline: {}", b.name));
                self.baseline = Some(b);
            }
            Err(e) => {
                self.message = Some("baseline failed (e: the whole message)".into());
                self.error = Some(format!("baseline {} failed:\n{e}", path.display()));
                self.mode = Mode::Error;
            }
        }
        Vec::new()
    }

    /// The current solution against the baseline, in the display units (`None`: no
    /// baseline or no solution).
    pub fn baseline_diff(&self) -> Option<Diff> {
        let (b, view) = (self.baseline.as_ref()?, self.view.as_deref()?);
        let here = self
            .path
            .as_ref()
            .map_or_else(|| self.deck.name().to_string(), |p| p.display().to_string());
        let system = self.deck.system();
        Some(compare(
            Side {
                name: &b.name,
                system: b.system,
                element: b.element,
                view: &b.view,
            },
            Side {
                name: &here,
                system: system.title(),
                element: system.element_name(),
                view,
            },
            self.display_units,
        ))
    }
}
