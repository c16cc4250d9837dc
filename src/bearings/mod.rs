//! Bearing systems. Each system is one folder (its input, geometry, solver, solution and
//! view) registered once in [`SYSTEMS`]; what systems share lives below them
//! (`crate::physics`, `crate::numerics`, `crate::thermal`). A deck names its system with
//! the top-level key `type`; an absent `type` means [`DEFAULT_SYSTEM`], so decks written
//! before there was a choice keep working.
//!
//! The front ends (`cli`, `report`, `verify`, `tui`) reach a system only through
//! [`BearingSystem`]: parse a deck, solve it, and draw what it shows from its
//! [`view::View`] (tables and key outputs with their units).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod error;
pub mod spherical_roller;
pub mod tapered_roller;
pub mod view;

pub use error::SolveError;

use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// The `type` of a deck that does not name one.
pub const DEFAULT_SYSTEM: &str = "spherical-roller";

/// Every bearing system rollbench knows, in the order `rollbench template --type` and
/// error messages list them. Adding a system is one line here.
pub static SYSTEMS: &[&dyn BearingSystem] = &[&spherical_roller::SYSTEM, &tapered_roller::SYSTEM];

/// What a run is asked to compute beyond the bearing itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RunOptions {
    /// Skip expensive time simulations (the loss-of-oil transient of a thermal network).
    pub skip_transient: bool,
}

/// A bearing system: how its decks are read, solved and shown.
pub trait BearingSystem: Sync {
    /// The deck's `type`, e.g. `"spherical-roller"`.
    fn id(&self) -> &'static str;
    /// What the system is, for headers and reports.
    fn title(&self) -> &'static str;
    /// The method and its source (seed document).
    fn method(&self) -> &'static str;
    /// The workbench panes this system offers, in switcher order.
    fn panes(&self) -> &'static [view::PaneSpec];
    /// A fully commented deck in `units` that parses back.
    fn template(&self, units: Units) -> String;
    /// The shipped example deck (text), embedded in the binary.
    fn example_deck(&self) -> &'static str;
    /// Parse and validate deck text of this system, apply `key=value` overrides (deck
    /// units) and validate the result once; errors name file, line, key and range.
    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors>;
}

/// One validated deck of a system, ready to solve.
pub trait Case: Send {
    /// The system the deck belongs to.
    fn system(&self) -> &'static dyn BearingSystem;
    /// The unit system the deck is written in (text reports use it).
    fn units(&self) -> Units;
    /// Solve everything a full report shows.
    fn solve(&self, options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String>;
}

/// A solved case: what reports and panes draw from.
pub trait Solution {
    /// Tables, summary lines and key outputs, SI, each with its unit.
    fn view(&self) -> view::View;
    /// The JSON report (SI, units in key names; a contract: fields are added, never
    /// renamed).
    fn json(&self) -> serde_json::Value;
    /// The text report in `units`.
    fn text(&self, units: Units) -> String;
}

/// The system a deck `type` names.
pub fn system(id: &str) -> Option<&'static dyn BearingSystem> {
    SYSTEMS.iter().copied().find(|s| s.id() == id)
}

/// The known `type` values, quoted and comma-separated (for error messages).
pub fn known_types() -> String {
    SYSTEMS
        .iter()
        .map(|s| format!("\"{}\"", s.id()))
        .collect::<Vec<_>>()
        .join(", ")
}
