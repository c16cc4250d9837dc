//! The angular-contact ball bearing's registration: decks read through the generic deck
//! form, solved by `analysis`, shown through `view` and `report`.

use super::analysis::{analyse, BallAnalysis};
use super::deck::SCHEMA;
use super::input::BallInput;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{BearingSystem, Case, FormCase, RunOptions, Solution};
use crate::deck::form::Form;
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// The deck `type` of this system.
pub const SYSTEM_ID: &str = "angular-contact-ball";

/// The angular-contact ball bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct AngularBall;

/// The registry entry.
pub static SYSTEM: AngularBall = AngularBall;

/// The shipped example deck (Chen's Bearing A).
pub const EXAMPLE_DECK: &str = include_str!("../../../decks/chen_a.toml");

impl BearingSystem for AngularBall {
    fn id(&self) -> &'static str {
        SYSTEM_ID
    }

    fn title(&self) -> &'static str {
        "angular-contact ball bearing"
    }

    fn method(&self) -> &'static str {
        "quasi-static load distribution and race control (S.-H. Chen, Investigation on Ball Skidding and Traction within Elastohydrodynamic Films, 1989)"
    }

    fn element_name(&self) -> &'static str {
        "ball"
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 4] = [
            PaneSpec {
                kind: PaneKind::Inputs,
                title: "Inputs",
            },
            PaneSpec {
                kind: PaneKind::Elements,
                title: "Balls",
            },
            PaneSpec {
                kind: PaneKind::Chart(0),
                title: "Skid",
            },
            PaneSpec {
                kind: PaneKind::Chart(1),
                title: "Dynamics",
            },
        ];
        &PANES
    }

    fn keys_table(&self) -> String {
        crate::deck::form::keys_table(&SCHEMA)
    }

    fn template(&self, units: Units) -> String {
        crate::deck::form::template(&SCHEMA, units)
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors> {
        let mut form = Form::parse(text, source_name, &SCHEMA)?;
        form.apply_assignments(overrides)?;
        Ok(Box::new(BallCase { form }))
    }
}

/// A validated ball bearing deck.
pub struct BallCase {
    /// The deck (SI input inside).
    pub form: Form<BallInput>,
}

impl FormCase for BallCase {
    type Input = BallInput;

    fn form(&self) -> &Form<BallInput> {
        &self.form
    }

    fn with_form(&self, form: Form<BallInput>) -> Result<Box<dyn Case>, DeckErrors> {
        Ok(Box::new(BallCase { form }))
    }
}

impl Case for BallCase {
    fn system(&self) -> &'static dyn BearingSystem {
        &SYSTEM
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }

    fn units(&self) -> Units {
        self.form.units
    }

    fn solve(&self, _options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String> {
        analyse(&self.form.value, cancel)
            .map(|a| Box::new(BallSolution(a)) as Box<dyn Solution>)
            .map_err(|e| e.to_string())
    }
}

/// A solved ball bearing.
pub struct BallSolution(pub BallAnalysis);

impl Solution for BallSolution {
    fn view(&self) -> View {
        super::view::view(&self.0)
    }

    fn json(&self) -> serde_json::Value {
        super::report::json(&self.0)
    }

    fn text(&self, units: Units) -> String {
        super::report::text(&self.0, units)
    }
}
