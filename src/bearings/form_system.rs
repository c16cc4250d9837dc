//! The generic half of a bearing system: everything a deck that is a [`Form`] of the
//! system's schema gives (the keys table, the template, loading with `--set`, the
//! [`CaseDeck`] of the workbench's editor, `as_any`, the units), written once here for
//! every system.
//!
//! A system implements [`FormSystem`] (its id, title, panes, session, fidelity grid,
//! schema and solve: what is its own) and gets [`BearingSystem`] from the blanket
//! implementation below; its case is [`SystemCase<S>`]. Why a trait with a blanket
//! implementation rather than a macro or a wrapper struct: the compiler checks each
//! system's half against one signature, a system's `static SYSTEM` stays the registry
//! entry as it is, and what a case derives from its deck (the spherical roller's thermal
//! network, the ball's traction table) is one typed hook, [`FormSystem::prepare`], not
//! code pasted into each system.

use super::view::PaneSpec;
use super::{
    BearingSystem, Case, FidelityGrid, FormCase, RunOptions, Session, Solution, SolveError,
    SweepPlan, WholeSolve,
};
use crate::bearings::Fidelity;
use crate::deck::form::Schema;
use crate::deck::{DeckErrors, Form};
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// A bearing system whose decks are [`Form`]s of its [`Schema`]: what is its own.
/// [`BearingSystem`] comes with it.
pub trait FormSystem: Sync + Sized + 'static {
    /// The system's SI input (the schema's value).
    type Input: Clone + Send + Sync + 'static;
    /// What a case derives from its deck beyond the SI input, once per deck (the
    /// spherical roller's thermal network); `()` for a system that derives nothing.
    type Derived: Clone + Send + Sync + 'static;

    /// The registry entry (`&SYSTEM`), for a case to name its system.
    fn registered() -> &'static Self;
    /// The deck's schema: fields, units, ranges, cross checks, template notes.
    fn schema(&self) -> &'static Schema<Self::Input>;
    /// See [`BearingSystem::id`]; the schema's `system`.
    fn id(&self) -> &'static str {
        self.schema().system
    }
    /// See [`BearingSystem::title`].
    fn title(&self) -> &'static str;
    /// See [`BearingSystem::method`].
    fn method(&self) -> &'static str;
    /// See [`BearingSystem::element_name`].
    fn element_name(&self) -> &'static str;
    /// See [`BearingSystem::panes`].
    fn panes(&self) -> &'static [PaneSpec];
    /// See [`BearingSystem::example_deck`].
    fn example_deck(&self) -> &'static str;
    /// See [`BearingSystem::session`].
    fn session(&self) -> Box<dyn Session> {
        Box::new(WholeSolve)
    }
    /// See [`BearingSystem::sweep_plan`].
    fn sweep_plan(&self, _n: usize, _case: &dyn Case) -> Option<SweepPlan> {
        None
    }
    /// See [`BearingSystem::fidelity_grid`].
    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        None
    }
    /// See [`BearingSystem::study_keys`].
    fn study_keys(&self) -> &'static [&'static str] {
        &[]
    }
    /// See [`BearingSystem::run_job`].
    fn run_job(
        &self,
        _n: usize,
        _case: &dyn Case,
        _cancel: Cancel<'_>,
        _report: &mut dyn FnMut(&super::view::JobView),
    ) -> Option<Result<super::view::JobView, SolveError>> {
        None
    }

    /// Completes a validated deck (whatever the input takes from the deck's opaque
    /// tables or top-level keys) and derives what the case keeps beside it; run on every
    /// load and every edit.
    fn prepare(form: &mut Form<Self::Input>) -> Result<Self::Derived, DeckErrors>;
    /// Solves everything a full report shows.
    fn solve(
        case: &SystemCase<Self>,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String>;
    /// See [`Case::has_transient`].
    fn has_transient(_case: &SystemCase<Self>) -> bool {
        false
    }
    /// The deck's own fidelity ([`Case::fidelity`]); `None` without a fidelity study.
    fn fidelity(_input: &Self::Input) -> Option<Fidelity> {
        None
    }
    /// Sets the fidelity of `input` ([`Case::with_fidelity`]); false when the system has
    /// no fidelity settings.
    fn set_fidelity(_input: &mut Self::Input, _f: Fidelity) -> bool {
        false
    }
    /// Why this deck's answer does not depend on its fidelity settings, when it does not
    /// ([`Case::fidelity_unused`]); `None` by default.
    fn fidelity_unused(_input: &Self::Input) -> Option<String> {
        None
    }
}

impl<S: FormSystem> BearingSystem for S {
    fn id(&self) -> &'static str {
        FormSystem::id(self)
    }

    fn title(&self) -> &'static str {
        FormSystem::title(self)
    }

    fn method(&self) -> &'static str {
        FormSystem::method(self)
    }

    fn element_name(&self) -> &'static str {
        FormSystem::element_name(self)
    }

    fn panes(&self) -> &'static [PaneSpec] {
        FormSystem::panes(self)
    }

    fn session(&self) -> Box<dyn Session> {
        FormSystem::session(self)
    }

    fn sweep_plan(&self, n: usize, case: &dyn Case) -> Option<SweepPlan> {
        FormSystem::sweep_plan(self, n, case)
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        FormSystem::fidelity_grid(self)
    }

    fn study_keys(&self) -> &'static [&'static str] {
        FormSystem::study_keys(self)
    }

    fn run_job(
        &self,
        n: usize,
        case: &dyn Case,
        cancel: Cancel<'_>,
        report: &mut dyn FnMut(&super::view::JobView),
    ) -> Option<Result<super::view::JobView, SolveError>> {
        FormSystem::run_job(self, n, case, cancel, report)
    }

    fn keys_table(&self) -> String {
        crate::deck::form::keys_table(self.schema())
    }

    fn template(&self, units: Units) -> String {
        crate::deck::form::template(self.schema(), units)
    }

    fn example_deck(&self) -> &'static str {
        FormSystem::example_deck(self)
    }

    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors> {
        let mut form = Form::parse(text, source_name, self.schema())?;
        // All overrides first, then one validation: their order never matters.
        form.apply_assignments(overrides)?;
        SystemCase::<S>::new(form).map(|c| Box::new(c) as Box<dyn Case>)
    }
}

/// A validated deck of system `S`, ready to solve: the deck (SI input inside) and what
/// `S` derived from it. Immutable: an edit makes a new case.
pub struct SystemCase<S: FormSystem> {
    /// The deck.
    pub form: Form<S::Input>,
    /// What [`FormSystem::prepare`] derived from it.
    pub derived: S::Derived,
}

impl<S: FormSystem> Clone for SystemCase<S> {
    fn clone(&self) -> Self {
        SystemCase {
            form: self.form.clone(),
            derived: self.derived.clone(),
        }
    }
}

impl<S: FormSystem> SystemCase<S> {
    /// The case of a validated deck: [`FormSystem::prepare`] run on it.
    pub fn new(mut form: Form<S::Input>) -> Result<Self, DeckErrors> {
        let derived = S::prepare(&mut form)?;
        Ok(SystemCase { form, derived })
    }

    /// The SI input.
    pub fn input(&self) -> &S::Input {
        &self.form.value
    }

    /// `case` as a case of this system, for a [`Session`] that needs its concrete
    /// input; another system's case is a typed error naming both.
    pub fn of(case: &dyn Case) -> Result<&Self, SolveError> {
        case.as_any()
            .downcast_ref::<Self>()
            .ok_or_else(|| SolveError::Stage {
                stage: "session",
                message: format!(
                    "a {} deck was given to the {} solver",
                    case.system().id(),
                    FormSystem::id(S::registered())
                ),
            })
    }
}

impl<S: FormSystem> FormCase for SystemCase<S> {
    type Input = S::Input;

    fn form(&self) -> &Form<S::Input> {
        &self.form
    }

    fn with_form(&self, form: Form<S::Input>) -> Result<Box<dyn Case>, DeckErrors> {
        SystemCase::<S>::new(form).map(|c| Box::new(c) as Box<dyn Case>)
    }
}

impl<S: FormSystem> Case for SystemCase<S> {
    fn system(&self) -> &'static dyn BearingSystem {
        S::registered()
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }

    fn units(&self) -> Units {
        self.form.units
    }

    fn solve(&self, options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String> {
        S::solve(self, options, cancel)
    }

    fn has_transient(&self) -> bool {
        S::has_transient(self)
    }

    fn fidelity(&self) -> Option<Fidelity> {
        S::fidelity(&self.form.value)
    }

    fn with_fidelity(&self, f: Fidelity) -> Option<Box<dyn Case>> {
        let mut case = self.clone();
        S::set_fidelity(&mut case.form.value, f).then(|| Box::new(case) as Box<dyn Case>)
    }

    fn fidelity_unused(&self) -> Option<String> {
        S::fidelity_unused(&self.form.value)
    }
}
