//! The spherical roller bearing's registration: how its decks are read, solved and shown
//! through the system-independent [`BearingSystem`] interface.

use super::pipeline::{self, Analysis, Request};
use super::report;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{BearingSystem, Case, RunOptions, Solution};
use crate::deck::{Deck, DeckErrors};
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::Units;

/// The deck `type` of this system.
pub const SYSTEM_ID: &str = "spherical-roller";

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
                kind: PaneKind::Chart,
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
        .map_err(|e| e.to_string())
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
