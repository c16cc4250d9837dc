//! The spherical roller's deck: a [`Form`] of [`deck_schema::SCHEMA`](super::deck_schema::SCHEMA)
//! like every system's, with the helpers its tests, benches and examples use. The deck's
//! `name` is copied into [`Bearing::name`] (the reports print it).

use std::path::Path;

use super::deck_schema::{FIELDS, SCHEMA};
use super::Bearing;
use crate::deck::form::{self, Form};
use crate::deck::DeckErrors;
use crate::units::Units;

/// The aerospace example deck (US units), shipped as `decks/aerospace.toml`.
pub const DEFAULT_DECK: &str = include_str!("../../../decks/aerospace.toml");

/// A spherical roller deck: the bearing (SI) in `value`, its `[thermal]` table among
/// the opaque tables.
pub type Deck = Form<Bearing>;

/// Copies the deck's `name` into the bearing (what [`super::system`]'s `prepare` does
/// for every case).
pub fn name_bearing(deck: &mut Deck) {
    deck.value.name.clone_from(&deck.name);
}

/// Parses and validates deck text; `source_name` (e.g. a file name) prefixes every error
/// location. All errors found are returned together.
pub fn parse(text: &str, source_name: &str) -> Result<Deck, DeckErrors> {
    let mut deck = Form::parse(text, source_name, &SCHEMA)?;
    name_bearing(&mut deck);
    Ok(deck)
}

/// Reads and parses a deck file; errors name the file.
pub fn load(path: impl AsRef<Path>) -> Result<Deck, DeckErrors> {
    let mut deck = Form::load(path.as_ref(), &SCHEMA)?;
    name_bearing(&mut deck);
    Ok(deck)
}

/// Applies `key=value` assignments (as `--set`, deck units) and validates once; the
/// bearing keeps the deck's name.
pub fn apply(deck: &mut Deck, assignments: &[String]) -> Result<(), DeckErrors> {
    deck.apply_assignments(assignments)?;
    name_bearing(deck);
    Ok(())
}

/// The registry of editable scalar deck fields, in file order.
pub fn fields() -> &'static [form::FieldSpec<Bearing>] {
    &FIELDS
}

/// Looks a field up by its full key path.
pub fn field(key: &str) -> Option<&'static form::FieldSpec<Bearing>> {
    fields().iter().find(|f| f.key == key)
}

/// A fully commented deck in `units`: every key with its meaning, unit and allowed
/// range, filled with the aerospace example bearing. It parses back as it is.
pub fn template(units: Units) -> String {
    form::template(&SCHEMA, units)
}

/// Writes `bearing` as a clean deck in `units` (unit comments only). Parsing it gives
/// back the same bearing to round-off (about 1e-15 relative).
pub fn write_bearing(bearing: &Bearing, units: Units) -> String {
    form::write_value(&SCHEMA, bearing, &bearing.name, units)
}

#[cfg(test)]
#[path = "deck_tests.rs"]
mod tests;
