//! The spherical roller bearing's registration: how its decks are read, solved and shown
//! through the system-independent [`BearingSystem`] interface.

use super::pipeline::{self, Analysis, Request};
use super::report;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{
    BearingSystem, Case, CaseDeck, Detail, Fidelity, FidelityGrid, RunOptions, Session, Solution,
    SolveError,
};
use crate::deck::{Deck, DeckErrors, FieldMeta};
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::Units;

/// The deck `type` of this system.
pub const SYSTEM_ID: &str = "spherical-roller";

/// The fidelity study (issue 7): laminae Γ × force tolerance against Γ = 400 at 10⁻¹⁰ (the
/// round-off floor of the equilibria). Odd Γ: a lamina on the roller mid-plane samples the
/// crown apex (see `crate::verify::fidelity`); 400, the reference, is the exception.
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

impl BearingSystem for SphericalRoller {
    fn id(&self) -> &'static str {
        SYSTEM_ID
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
        const PANES: [PaneSpec; 5] = [
            PaneSpec {
                kind: PaneKind::Inputs,
                title: "Inputs",
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
        ];
        &PANES
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        Some(FIDELITY_GRID)
    }

    fn keys_table(&self) -> String {
        crate::deck::keys_table()
    }

    fn template(&self, units: Units) -> String {
        crate::deck::template(units)
    }

    fn example_deck(&self) -> &'static str {
        crate::deck::DEFAULT_DECK
    }

    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors> {
        let mut deck = Deck::parse(text, source_name)?;
        // All overrides first, then one validation: their order never matters.
        deck.apply_assignments(overrides)?;
        let thermal = deck.thermal_model()?;
        Ok(Box::new(SphericalCase { deck, thermal }))
    }
}

/// A validated spherical roller deck with its thermal network.
pub struct SphericalCase {
    /// The deck (SI bearing inside).
    pub deck: Deck,
    /// Its `[thermal]` network, if any.
    pub thermal: Option<ThermalModel>,
}

impl Case for SphericalCase {
    fn system(&self) -> &'static dyn BearingSystem {
        &SYSTEM
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }

    fn units(&self) -> Units {
        self.deck.units
    }

    fn solve(&self, options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String> {
        let request = Request {
            thermal_transient: !options.skip_transient,
            ..Request::default()
        };
        pipeline::run_with_thermal(
            &self.deck.bearing,
            self.thermal.as_ref(),
            &request,
            cancel.flag(),
        )
        .map(|a| Box::new(SphericalSolution(a)) as Box<dyn Solution>)
        .map_err(|e| e.in_units(self.deck.units).to_string())
    }

    fn has_transient(&self) -> bool {
        self.thermal.is_some()
    }

    fn fidelity(&self) -> Option<Fidelity> {
        let s = &self.deck.bearing.solver;
        Some(Fidelity {
            resolution: s.laminae,
            tolerance: s.force_tolerance,
        })
    }

    fn with_fidelity(&self, f: Fidelity) -> Option<Box<dyn Case>> {
        let mut deck = self.deck.clone();
        deck.bearing.solver.laminae = f.resolution;
        deck.bearing.solver.force_tolerance = f.tolerance;
        Some(Box::new(SphericalCase {
            deck,
            thermal: self.thermal.clone(),
        }))
    }
}

impl CaseDeck for SphericalCase {
    fn name(&self) -> &str {
        &self.deck.bearing.name
    }

    fn source_name(&self) -> &str {
        self.deck.source_name()
    }

    fn fields(&self) -> Vec<&'static FieldMeta> {
        crate::deck::fields().iter().map(|f| &f.meta).collect()
    }

    fn field_si(&self, key: &str) -> Option<f64> {
        crate::deck::field(key).map(|f| f.get_si(&self.deck.bearing))
    }

    fn get(&self, key: &str) -> Option<String> {
        self.deck.get(key)
    }

    fn with_value(&self, key: &str, value: &str) -> Result<Box<dyn Case>, DeckErrors> {
        let mut deck = self.deck.clone();
        deck.set(key, value)?;
        let thermal = deck.thermal_model()?;
        Ok(Box::new(SphericalCase { deck, thermal }))
    }

    fn text(&self) -> String {
        self.deck.to_toml_string()
    }

    fn save(&self, path: &std::path::Path) -> Result<crate::files::Written, DeckErrors> {
        self.deck.save(path)
    }
}

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
        let Some(case) = case.as_any().downcast_ref::<SphericalCase>() else {
            return Err(SolveError::Stage {
                stage: "session",
                message: format!(
                    "a {} deck was given to the {} solver",
                    case.system().id(),
                    SYSTEM_ID
                ),
            });
        };
        let request = Request {
            trace_roller: detail.trace_element,
            thermal_transient: detail.transient && case.thermal.is_some(),
            thermal: case.thermal.clone(),
            ..Request::default()
        };
        self.pipeline
            .run(
                &case.deck.bearing,
                case.thermal.as_ref(),
                &request,
                cancel.flag(),
            )
            .map(|a| Box::new(SphericalSolution(a)) as Box<dyn Solution>)
            .map_err(|e| e.in_units(case.deck.units))
    }
}
