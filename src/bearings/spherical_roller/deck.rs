//! The spherical roller's deck: [`Deck`] (the parsed, validated deck of a [`Bearing`],
//! with its `[thermal]` table) and the registry functions the rest of the program reads
//! (`crate::deck::{fields, field, template, keys_table, …}` are re-exports of these).
//! Every check and edit is the generic [`crate::deck::form`]'s, run on
//! [`deck_schema::SCHEMA`](super::deck_schema::SCHEMA).

use std::collections::BTreeMap;
use std::path::Path;

use toml_edit::DocumentMut;

use super::deck_schema::{FIELDS, SCHEMA, TEMPLATE_NOTES};
use super::Bearing;
use crate::deck::form::{self, DeckText};
use crate::deck::{DeckError, DeckErrors};
use crate::units::Units;

/// The aerospace example deck (US units), shipped as `decks/aerospace.toml`.
pub const DEFAULT_DECK: &str = include_str!("../../../decks/aerospace.toml");

/// A parsed, validated deck: its unit system, the resolved SI [`Bearing`], the opaque
/// `[thermal]` table, and the source document (comments kept) for edits and saving.
#[derive(Debug, Clone)]
pub struct Deck {
    /// Unit system the deck is written in.
    pub units: Units,
    /// The resolved bearing, SI units.
    pub bearing: Bearing,
    /// The `[thermal]` table as written, not interpreted here.
    pub thermal: Option<toml::Table>,
    source_name: String,
    doc: DocumentMut,
}

impl Deck {
    /// Parses and validates deck text; `source_name` (e.g. a file name) prefixes every
    /// error location. All errors found are returned together.
    pub fn parse(text: &str, source_name: &str) -> Result<Deck, DeckErrors> {
        let parsed = form::validate(text, source_name, &SCHEMA)?;
        let doc = form::parse_doc(text, source_name)?;
        let mut deck = Deck {
            units: parsed.units,
            bearing: parsed.value,
            thermal: None,
            source_name: source_name.to_string(),
            doc,
        };
        deck.take(parsed.name, parsed.opaque);
        Ok(deck)
    }

    /// The deck's name into the bearing, `[thermal]` out of the opaque tables.
    fn take(&mut self, name: String, mut opaque: BTreeMap<String, toml::Table>) {
        self.bearing.name = name;
        self.thermal = opaque.remove("thermal");
    }

    /// Validates `doc` (this deck's document, edited) and takes it on success.
    fn revalidate(&mut self, doc: DocumentMut) -> Result<(), DeckErrors> {
        let parsed = form::validate(&doc.to_string(), &self.source_name, &SCHEMA)?;
        self.units = parsed.units;
        self.bearing = parsed.value;
        self.doc = doc;
        self.take(parsed.name, parsed.opaque);
        Ok(())
    }

    /// Reads and parses a deck file; errors name the file.
    pub fn load(path: impl AsRef<Path>) -> Result<Deck, DeckErrors> {
        let path = path.as_ref();
        let text = crate::deck::read_deck_text(path)?;
        let name = path.display().to_string();
        Deck::parse(&text, &name)
    }

    /// The deck at `path`, or the embedded aerospace deck when `path` is `None`, with the
    /// command line's `key=value` overrides applied in order (deck units).
    pub fn load_with_overrides(path: Option<&Path>, overrides: &[String]) -> Result<Deck, String> {
        let mut deck = match path {
            Some(p) => Deck::load(p).map_err(|e| e.to_string())?,
            None => Deck::parse(DEFAULT_DECK, "decks/aerospace.toml (embedded)")
                .map_err(|e| e.to_string())?,
        };
        deck.apply_overrides(overrides)?;
        Ok(deck)
    }

    /// Applies the command line's `key=value` overrides (deck units); see
    /// [`Deck::apply_assignments`]. The error is the messages as text.
    pub fn apply_overrides(&mut self, overrides: &[String]) -> Result<(), String> {
        self.apply_assignments(overrides).map_err(|e| e.to_string())
    }

    /// Applies `key.path=value` assignments (as for `--set`, deck units): every one is
    /// written into the deck first, then the result is validated once, so the order of
    /// the assignments never changes the verdict. A malformed assignment or an unknown
    /// key (with the close matches) is reported as such; on any error the deck is
    /// unchanged.
    pub fn apply_assignments(&mut self, assignments: &[String]) -> Result<(), DeckErrors> {
        if assignments.is_empty() {
            return Ok(());
        }
        let doc = form::write_assignments(
            &SCHEMA,
            &self.doc,
            &self.bearing,
            self.units,
            assignments,
            "geometry.pitch_diameter=3.4",
        )?;
        self.revalidate(doc)
    }

    /// The thermal network of the deck's `[thermal]` section, if any (errors name node,
    /// link and field).
    pub fn thermal_model(&self) -> Result<Option<crate::thermal::ThermalModel>, DeckErrors> {
        form::thermal_model_of(
            &self.doc,
            &self.source_name,
            self.thermal.as_ref(),
            self.units,
        )
    }

    /// The source name given to [`Deck::parse`] (file path for [`Deck::load`]).
    pub fn source_name(&self) -> &str {
        &self.source_name
    }

    /// The deck as TOML text, comments and layout preserved.
    pub fn to_toml_string(&self) -> String {
        self.doc.to_string()
    }

    /// Sets one value, written in the deck's own units (`"3.4"` for
    /// `geometry.pitch_diameter` in inches in a US deck; `"iso281"` for `life.method`).
    /// Comments are kept; the whole deck is re-validated and `bearing` updated. On error
    /// the deck is unchanged.
    pub fn set(&mut self, key_path: &str, value: &str) -> Result<(), DeckErrors> {
        let mut doc = self.doc.clone();
        form::edit(
            &SCHEMA,
            &mut doc,
            &self.bearing,
            self.units,
            key_path,
            value,
        )?;
        self.revalidate(doc)
    }

    /// Applies a command-line assignment `key.path=value` (as for `--set`), in deck
    /// units; see [`Deck::set`].
    pub fn set_assignment(&mut self, assignment: &str) -> Result<(), DeckErrors> {
        match assignment.split_once('=') {
            Some((k, v)) => self.set(k.trim(), v),
            None => Err(DeckError::NotEditable {
                key: assignment.to_string(),
                reason: "expected key.path=value".into(),
            }
            .into()),
        }
    }

    /// The value of `key_path` as written in the deck (deck units; strings unquoted).
    /// For registry fields not written in the file (defaults, material presets) the
    /// value in effect is returned, formatted in deck units. `None` for unknown keys.
    pub fn get(&self, key_path: &str) -> Option<String> {
        form::get(&SCHEMA, &self.doc, &self.bearing, self.units, key_path)
    }

    /// The same bearing written in `units`: a clean regenerated deck (comments other
    /// than unit hints are not carried over; `[thermal]` is).
    pub fn converted(&self, units: Units) -> Deck {
        let header = form::converted_header(&self.bearing.name, self.units);
        let mut opaque = BTreeMap::new();
        if let Some(t) = &self.thermal {
            opaque.insert("thermal".to_string(), t.clone());
        }
        let text = form::write_deck(
            &SCHEMA,
            &DeckText {
                value: &self.bearing,
                units,
                name: &self.bearing.name,
                opaque: &opaque,
                header: &header,
                commented: false,
                notes: &TEMPLATE_NOTES,
            },
        );
        let doc = text.parse::<DocumentMut>().unwrap_or_default();
        Deck {
            units,
            bearing: self.bearing.clone(),
            thermal: self.thermal.clone(),
            source_name: self.source_name.clone(),
            doc,
        }
    }

    /// Saves the deck atomically: temporary file in the same directory, fsync, the
    /// previous file kept as `<file name>.bak`, then rename. A failure leaves the
    /// existing file untouched. A symbolic link is saved through (the file it points to
    /// is replaced), a read-only deck is refused; see [`crate::files`]. Returns how the
    /// file was written, for the caller to say so.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<crate::files::Written, DeckErrors> {
        form::save_text(path.as_ref(), &self.to_toml_string())
    }
}

/// The registry of editable scalar deck fields, in file order.
pub fn fields() -> &'static [form::FieldSpec<Bearing>] {
    &FIELDS
}

/// Looks a field up by its full key path.
pub fn field(key: &str) -> Option<&'static form::FieldSpec<Bearing>> {
    fields().iter().find(|f| f.key == key)
}

/// Every key `--set` and [`Deck::set`] accept: `name`, each field of [`fields()`], the
/// material bodies (a preset name or a table), and `thermal.…` (any key of the
/// `[thermal]` table, checked by the thermal section's parser).
pub fn editable_keys() -> Vec<&'static str> {
    form::editable_keys(&SCHEMA)
}

/// The table `rollbench keys` prints: every editable key with its units and allowed range
/// in SI and US units, then `name`, the material bodies and the `[thermal]` keys.
pub fn keys_table() -> String {
    form::keys_table(&SCHEMA)
}

/// The editable keys closest to `key` (typos, a wrong table, a missing table): at most
/// five, closest first.
pub fn close_keys(key: &str) -> Vec<&'static str> {
    form::close_keys(&SCHEMA, key)
}

/// A fully commented deck in `units`: every key with its meaning, unit and allowed
/// range, filled with the aerospace example bearing. It parses back as it is.
pub fn template(units: Units) -> String {
    form::template_with(&SCHEMA, units, &TEMPLATE_NOTES)
}

/// Writes `bearing` as a clean deck in `units` (unit comments only). Parsing it gives
/// back the same bearing to round-off (about 1e-15 relative).
pub fn write_bearing(bearing: &Bearing, units: Units) -> String {
    form::write_value(&SCHEMA, bearing, &bearing.name, units)
}
