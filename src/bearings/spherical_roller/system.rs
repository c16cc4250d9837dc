//! The spherical roller bearing's registration: how its decks are read, solved and shown
//! through the system-independent [`BearingSystem`] interface.

use super::deck::{name_bearing, DEFAULT_DECK};
use super::deck_schema::SCHEMA;
use super::pipeline::{self, Analysis, Request};
use super::report;
use super::Bearing;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{
    Case, Detail, Fidelity, FidelityGrid, FormSystem, RunOptions, Session, Solution, SolveError,
    SystemCase,
};
use crate::deck::form::{Form, Schema};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::Units;

/// The fidelity study (issue 7): laminae Γ × force tolerance against Γ = 400 at 10⁻¹⁰ (the
/// round-off floor of the equilibria). Odd Γ: a lamina on the roller mid-plane samples the
/// crown apex (see `crate::studies::fidelity`); 400, the reference, is the exception.
pub const FIDELITY_GRID: FidelityGrid = FidelityGrid {
    resolution_key: "laminae",
    resolution_symbol: "Γ",
    resolutions: &[5, 7, 11, 15, 21, 31, 41, 61, 81, 121, 201, 400],
    tolerances: &[1e-4, 1e-6, 1e-9],
    reference: Fidelity {
        resolution: 400,
        tolerance: 1e-10,
    },
};

/// The spherical roller bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct SphericalRoller;

/// The registry entry.
pub static SYSTEM: SphericalRoller = SphericalRoller;

impl FormSystem for SphericalRoller {
    type Input = Bearing;
    /// The deck's `[thermal]` network, if any.
    type Derived = Option<ThermalModel>;

    fn registered() -> &'static Self {
        &SYSTEM
    }

    fn schema(&self) -> &'static Schema<Bearing> {
        &SCHEMA
    }

    fn title(&self) -> &'static str {
        "angular-contact spherical roller bearing"
    }

    fn method(&self) -> &'static str {
        "SASHBEAN lamina method (A. K. Aggarwal, NASA CR-191182, 1993)"
    }

    fn element_name(&self) -> &'static str {
        "roller"
    }

    fn session(&self) -> Box<dyn Session> {
        Box::new(SphericalSession::default())
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 7] = [
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
                kind: PaneKind::Thermal,
                title: "Thermal",
            },
            PaneSpec {
                kind: PaneKind::Stepper,
                title: "Stepper",
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
            "geometry.roller_diameter",
            "geometry.diametral_clearance",
            "operating.radial_load",
            "operating.axial_load",
        ]
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        Some(FIDELITY_GRID)
    }

    fn example_deck(&self) -> &'static str {
        DEFAULT_DECK
    }

    /// The deck's name into the bearing (the reports print it) and its `[thermal]`
    /// network built (errors name node, link and field).
    fn prepare(form: &mut Form<Bearing>) -> Result<Option<ThermalModel>, DeckErrors> {
        name_bearing(form);
        form.thermal_model()
    }

    fn solve(
        case: &SphericalCase,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String> {
        let request = Request {
            thermal_transient: !options.skip_transient,
            ..Request::default()
        };
        pipeline::run_with_thermal(
            &case.form.value,
            case.derived.as_ref(),
            &request,
            cancel.flag(),
        )
        .map(|a| Box::new(SphericalSolution(a)) as Box<dyn Solution>)
        .map_err(|e| e.in_units(case.form.units).to_string())
    }

    fn has_transient(case: &SphericalCase) -> bool {
        case.derived.is_some()
    }

    fn fidelity(input: &Bearing) -> Option<Fidelity> {
        Some(Fidelity {
            resolution: input.solver.laminae,
            tolerance: input.solver.force_tolerance,
        })
    }

    fn set_fidelity(input: &mut Bearing, f: Fidelity) -> bool {
        input.solver.laminae = f.resolution;
        input.solver.force_tolerance = f.tolerance;
        true
    }
}

/// A validated spherical roller deck; `derived` is its thermal network.
pub type SphericalCase = SystemCase<SphericalRoller>;

/// A solved spherical roller bearing.
pub struct SphericalSolution(pub Analysis);

impl Solution for SphericalSolution {
    fn view(&self) -> View {
        super::view::view(&self.0)
    }

    fn json(&self) -> serde_json::Value {
        report::json::to_value(&self.0)
    }

    fn text(&self, units: Units) -> String {
        report::text::to_string(&self.0, units)
    }
}

/// The workbench's spherical roller solver: the staged pipeline with its cache kept
/// between solves, so an edit re-runs only the stages whose inputs it changed.
#[derive(Default)]
pub struct SphericalSession {
    pipeline: pipeline::Pipeline,
}

impl SphericalSession {
    /// Stage run counters since the session began.
    pub fn counters(&self) -> pipeline::StageCounters {
        self.pipeline.counters()
    }
}

impl Session for SphericalSession {
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError> {
        let case = SphericalCase::of(case)?;
        let request = Request {
            trace_roller: detail.trace_element,
            thermal_transient: detail.transient && case.derived.is_some(),
            thermal: case.derived.clone(),
            ..Request::default()
        };
        self.pipeline
            .run(
                &case.form.value,
                case.derived.as_ref(),
                &request,
                cancel.flag(),
            )
            .map(|a| Box::new(SphericalSolution(a)) as Box<dyn Solution>)
            .map_err(|e| e.in_units(case.form.units))
    }
}
