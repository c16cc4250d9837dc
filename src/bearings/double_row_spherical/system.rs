//! The double-row spherical roller bearing's registration through the
//! system-independent [`crate::bearings::BearingSystem`] interface.

use super::deck::SCHEMA;
use super::input::DoubleRowInput;
use super::losses::{losses, LossBreakdown};
use super::statics::{analyse, DoubleRowAnalysis};
use crate::bearings::thermal_answer::{self, BearingThermal};
use crate::bearings::view::{JobView, PaneKind, PaneSpec, View};
use crate::bearings::{Case, FormSystem, RunOptions, Solution, SolveError, SystemCase};
use crate::deck::form::{Form, Schema};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::units::{restate_si, Units};

/// The shipped example deck: an illustrative 22308 CC.
pub const EXAMPLE_DECK: &str = include_str!("../../../decks/srb_22308.toml");

/// The double-row spherical roller bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct DoubleRowSpherical;

/// The registry entry.
pub static SYSTEM: DoubleRowSpherical = DoubleRowSpherical;

/// A validated double-row deck.
pub type DoubleRowCase = SystemCase<DoubleRowSpherical>;

impl FormSystem for DoubleRowSpherical {
    type Input = DoubleRowInput;
    /// The deck's `[thermal]` network, if any.
    type Derived = Option<crate::thermal::ThermalModel>;

    fn registered() -> &'static Self {
        &SYSTEM
    }

    fn schema(&self) -> &'static Schema<DoubleRowInput> {
        &SCHEMA
    }

    fn title(&self) -> &'static str {
        "double-row spherical roller bearing (lamina statics of both rows, guide ring)"
    }

    fn method(&self) -> &'static str {
        "two rows of crowned rollers mirrored at ±α⁰ on one outer sphere, lamina contacts, roller equilibrium with centrifugal force and a unilateral guide ring, ring Newton in Δx, Δz (seed 002: Stirbu, Grigoras, Hanganu)"
    }

    fn element_name(&self) -> &'static str {
        "roller"
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 10] = [
            PaneSpec {
                kind: PaneKind::Inputs,
                title: "Inputs",
            },
            PaneSpec {
                kind: PaneKind::Summary,
                title: "Summary",
            },
            PaneSpec {
                kind: PaneKind::Elements,
                title: "Rollers",
            },
            PaneSpec {
                kind: PaneKind::Chart(0),
                title: "Load",
            },
            PaneSpec {
                kind: PaneKind::Text(0),
                title: "Stiffness",
            },
            PaneSpec {
                kind: PaneKind::Text(1),
                title: "Losses",
            },
            PaneSpec {
                kind: PaneKind::Job(0),
                title: "Torque vs load",
            },
            PaneSpec {
                kind: PaneKind::Job(1),
                title: "Optimise",
            },
            PaneSpec {
                kind: PaneKind::Thermal,
                title: "Thermal",
            },
            PaneSpec {
                kind: PaneKind::Study,
                title: "Study",
            },
        ];
        &PANES
    }

    fn study_keys(&self) -> &'static [&'static str] {
        // The Study pane's default tolerance study varies the first three of these
        // the deck gives a non-zero number (the main geometry and operating keys).
        &[
            "operating.radial_load",
            "operating.axial_load",
            "geometry.diametral_clearance",
        ]
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    /// Job 0 the Torque-vs-load sweep, job 1 the optimiser ([`super::jobs`]).
    fn run_job(
        &self,
        n: usize,
        case: &dyn Case,
        cancel: Cancel<'_>,
        report: &mut dyn FnMut(&JobView),
    ) -> Option<Result<JobView, SolveError>> {
        let case = case.as_any().downcast_ref::<DoubleRowCase>()?;
        let (input, name, units) = (&case.form.value, &case.form.name, case.form.units);
        let restate = |e: SolveError| e.in_units(units);
        match n {
            0 => Some(super::jobs::torque_vs_load(input, name, cancel, report).map_err(restate)),
            1 => Some(super::jobs::optimise_job(
                input, name, units, cancel, report,
            )),
            _ => None,
        }
    }

    /// The `[optimise]` table into the input.
    fn prepare(
        form: &mut Form<DoubleRowInput>,
    ) -> Result<Option<crate::thermal::ThermalModel>, DeckErrors> {
        super::deck::optimise_table(form)?;
        form.thermal_model()
    }

    /// The `[thermal]` network's transient.
    fn has_transient(case: &DoubleRowCase) -> bool {
        case.derived.is_some()
    }

    fn solve(
        case: &DoubleRowCase,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String> {
        let a = analyse(&case.form.value, &case.form.name, cancel.flag())
            .map_err(|e| restate_si(&e.to_string(), case.form.units))?;
        // The loss stage is part of the solve: a failure is the solve's error, never a
        // silent zero.
        let l =
            losses(&a).map_err(|e| restate_si(&format!("loss breakdown: {e}"), case.form.units))?;
        // The thermal network under the losses' heat (issue 28), when the deck has one.
        let th = case
            .derived
            .as_ref()
            .map(|tm| {
                thermal_answer::solve(
                    tm,
                    &super::friction::friction(&a, &l),
                    !options.skip_transient,
                    &|| cancel.is_cancelled(),
                )
            })
            .transpose()?;
        Ok(Box::new(DoubleRowSolution(a, l, th)))
    }
}

/// A solved double-row bearing: the statics, its loss breakdown and its thermal
/// network's results (when the deck has one).
pub struct DoubleRowSolution(
    pub DoubleRowAnalysis,
    pub LossBreakdown,
    pub Option<BearingThermal>,
);

impl Solution for DoubleRowSolution {
    fn view(&self) -> View {
        let mut v = super::view::view_with_losses(&self.0, &self.1);
        thermal_answer::add_to_view(&mut v, self.2.as_ref());
        v
    }

    fn json(&self) -> serde_json::Value {
        let mut v = super::report::json(&self.0);
        super::report::add_losses(&mut v, &self.1);
        if let Some(o) = v.as_object_mut() {
            // Issue 28: the losses as the shared friction object.
            o.insert(
                "friction".into(),
                super::friction::friction(&self.0, &self.1).json(),
            );
        }
        thermal_answer::add_to_json(&mut v, self.2.as_ref());
        v
    }

    fn text(&self, units: Units) -> String {
        let mut s = super::report::text_with_losses(&self.0, &self.1, units);
        thermal_answer::add_to_text(&mut s, self.2.as_ref(), units);
        s
    }
}
