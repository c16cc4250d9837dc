//! The cylindrical roller bearing's registration: how its decks are read, solved and
//! shown through the system-independent [`crate::bearings::BearingSystem`] interface.

use super::analysis::{analyse_from, with_tribodynamics, CylindricalAnalysis};
use super::deck::SCHEMA;
use super::input::CylindricalInput;
use super::quasi_static::{QuasiStatic, QuasiStaticError};
use super::SYSTEM_ID;
use crate::bearings::thermal_answer::{self, BearingThermal};
use crate::bearings::view::{JobView, PaneKind, PaneSpec, View};
use crate::bearings::{
    Case, Detail, Fidelity, FidelityGrid, FormSystem, RunOptions, Session, Solution, SolveError,
    SweepPlan, SystemCase,
};
use crate::deck::form::{Form, Schema};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::{restate_si, Units};

/// The shipped example deck: the seed's truck-transmission bearing.
pub const EXAMPLE_DECK: &str = include_str!("../../../decks/crb_truck.toml");

/// The fidelity study (`rollbench bench`): slices per roller × force tolerance against
/// 321 slices at 10⁻¹⁰.
pub const FIDELITY_GRID: FidelityGrid = FidelityGrid {
    resolution_key: "slices",
    resolution_symbol: "n",
    resolutions: &[5, 7, 11, 15, 21, 31, 41, 61, 81, 121, 161],
    tolerances: &[1e-6, 1e-9],
    reference: Fidelity {
        resolution: 321,
        tolerance: 1e-10,
    },
};

/// The cylindrical roller bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct CylindricalRoller;

/// The registry entry.
pub static SYSTEM: CylindricalRoller = CylindricalRoller;

/// A validated cylindrical roller deck.
pub type CylindricalCase = SystemCase<CylindricalRoller>;

impl FormSystem for CylindricalRoller {
    type Input = CylindricalInput;
    /// The deck's `[thermal]` network, if any.
    type Derived = Option<ThermalModel>;

    fn registered() -> &'static Self {
        &SYSTEM
    }

    fn schema(&self) -> &'static Schema<CylindricalInput> {
        &SCHEMA
    }

    fn title(&self) -> &'static str {
        "cylindrical roller bearing (lamina load distribution, tribodynamics)"
    }

    fn method(&self) -> &'static str {
        "lamina (slice) load distribution of radially loaded rollers with dub-off or logarithmic profiles, 2×2 ring stiffness (seed 003: tribodynamics of cylindrical roller bearings in a truck transmission)"
    }

    fn element_name(&self) -> &'static str {
        "roller"
    }

    fn session(&self) -> Box<dyn Session> {
        Box::new(CylindricalSession::default())
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        Some(FIDELITY_GRID)
    }

    /// The Sweep pane: the largest roller load and K_xx against the radial load, from 0
    /// to 2.5 × the deck's (at least 1 000 N) in 21 points, each divided by its value at
    /// the first point (gravity and interference keep it loaded).
    fn sweep_plan(&self, n: usize, case: &dyn Case) -> Option<SweepPlan> {
        if n != 0 {
            return None;
        }
        Some(SweepPlan {
            title: "W_max and K_xx ÷ value at zero radial load".to_string(),
            key: "operating.radial_load",
            values: SweepPlan::span_from_zero(case, "operating.radial_load", 2.5, 1000.0, 21),
            outputs: vec!["max_roller_load_n", "stiffness_xx_n_m"],
            normalise: true,
            marker: None,
        })
    }

    /// Job 0 the Contact pane ([`super::contact_job`]): the line-EHL contact study of the
    /// deck's `contact.positions` and `contact.inlet`.
    fn run_job(
        &self,
        n: usize,
        case: &dyn Case,
        cancel: Cancel<'_>,
        report: &mut dyn FnMut(&JobView),
    ) -> Option<Result<JobView, SolveError>> {
        let case = case.as_any().downcast_ref::<CylindricalCase>()?;
        match n {
            0 => Some(
                super::contact_job::contact_job(&case.form.value, cancel, report)
                    .map_err(|e| e.in_units(case.form.units)),
            ),
            _ => None,
        }
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 13] = [
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
                kind: PaneKind::Chart(1),
                title: "Orbit",
            },
            PaneSpec {
                kind: PaneKind::Chart(2),
                title: "Spectrum",
            },
            PaneSpec {
                kind: PaneKind::Chart(3),
                title: "Load spectrum",
            },
            PaneSpec {
                kind: PaneKind::Chart(4),
                title: "Cycle",
            },
            PaneSpec {
                kind: PaneKind::Text(0),
                title: "Stiffness",
            },
            PaneSpec {
                kind: PaneKind::Sweep(0),
                title: "Sweep",
            },
            PaneSpec {
                kind: PaneKind::Job(0),
                title: "Contact",
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
            "geometry.radial_interference",
            "geometry.roller_diameter",
        ]
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    /// The `[contact]` table (sliding speed, cage angles) into the input, and the
    /// `[thermal]` network built (errors name node, link and field).
    fn prepare(form: &mut Form<CylindricalInput>) -> Result<Option<ThermalModel>, DeckErrors> {
        super::deck::contact_table(form)?;
        form.thermal_model()
    }

    fn solve(
        case: &CylindricalCase,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String> {
        // The errors are worded in SI deep in the solver; a US deck's user reads them in
        // lbf and inches like the other systems'.
        let a = analyse_from(&case.form.value, &case.form.name, None, &cancel)
            .map_err(|e| restate_si(&e.to_string(), case.form.units))?;
        let a = if options.skip_transient {
            a
        } else {
            with_tribodynamics(a, cancel)
                .map_err(|e| restate_si(&e.to_string(), case.form.units))?
        };
        let th = thermal_of(&a, case, true, &cancel)?;
        Ok(Box::new(CylindricalSolution(a, th)))
    }

    /// The 2-DOF dynamics is this system's time simulation: run unless the deck says
    /// `dynamics.revolutions = 0`.
    fn has_transient(case: &CylindricalCase) -> bool {
        case.form.value.dynamics.revolutions > 0
    }

    fn fidelity(input: &CylindricalInput) -> Option<Fidelity> {
        Some(Fidelity {
            resolution: input.solver.slices,
            tolerance: input.solver.force_tolerance,
        })
    }

    fn set_fidelity(input: &mut CylindricalInput, f: Fidelity) -> bool {
        input.solver.slices = f.resolution;
        input.solver.force_tolerance = f.tolerance;
        true
    }
}

/// The deck's thermal network under the friction's heat (steady, and the transient when
/// `transient`); `None` without `[thermal]` or without the friction (the tribodynamics
/// did not run: `rollbench run --skip-transient`, a sweep's points).
fn thermal_of(
    a: &CylindricalAnalysis,
    case: &CylindricalCase,
    transient: bool,
    cancel: &Cancel,
) -> Result<Option<BearingThermal>, String> {
    match (case.derived.as_ref(), super::friction::friction(a)) {
        (Some(tm), Some(f)) => {
            thermal_answer::solve(tm, &f, transient, &|| cancel.is_cancelled()).map(Some)
        }
        _ => Ok(None),
    }
}

/// A solved cylindrical roller bearing and its thermal network's results (when the deck
/// has one and the friction ran).
pub struct CylindricalSolution(pub CylindricalAnalysis, pub Option<BearingThermal>);

impl Solution for CylindricalSolution {
    fn view(&self) -> View {
        let mut v = super::view::view(&self.0);
        thermal_answer::add_to_view(&mut v, self.1.as_ref());
        v
    }

    fn json(&self) -> serde_json::Value {
        let mut v = super::report::json(&self.0);
        thermal_answer::add_to_json(&mut v, self.1.as_ref());
        v
    }

    fn text(&self, units: Units) -> String {
        let mut s = super::report::text(&self.0, units);
        thermal_answer::add_to_text(&mut s, self.1.as_ref(), units);
        s
    }

    fn series_csv(&self) -> Result<String, String> {
        super::report::series_csv(&self.0)
    }
}

/// The session: it keeps the last converged equilibrium and starts the next solve from
/// it (a sweep through one session is a continuation), falling back to rest.
#[derive(Default)]
pub struct CylindricalSession {
    last: Option<QuasiStatic>,
}

impl Session for CylindricalSession {
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError> {
        let case = CylindricalCase::of(case)?;
        let stage = |message: String| SolveError::Stage {
            stage: SYSTEM_ID,
            message: restate_si(&message, case.form.units),
        };
        let a = match analyse_from(
            &case.form.value,
            &case.form.name,
            self.last.as_ref(),
            cancel,
        ) {
            Ok(a) => a,
            Err(QuasiStaticError::Cancelled) => return Err(SolveError::Cancelled),
            Err(e) => return Err(stage(e.to_string())),
        };
        self.last = Some(a.statics.clone());
        // The dynamics only when the panes ask for the time simulation (the workbench
        // does for this system; sweeps do not).
        let a = if detail.transient {
            let c = Cancel::from_option(cancel.flag());
            let c = match cancel.progress() {
                Some(p) => c.with_progress(p),
                None => c,
            };
            with_tribodynamics(a, c).map_err(|e| {
                if cancel.is_cancelled() {
                    SolveError::Cancelled
                } else {
                    stage(e.to_string())
                }
            })?
        } else {
            a
        };
        let th = thermal_of(&a, case, detail.transient, cancel).map_err(|m| {
            if cancel.is_cancelled() {
                SolveError::Cancelled
            } else {
                stage(m)
            }
        })?;
        Ok(Box::new(CylindricalSolution(a, th)))
    }
}
