//! Thin adapter between the TUI and [`crate::deck`]: the only TUI file that knows how a
//! deck is parsed, edited, converted and saved.
//!
//! Values are shown and typed in *display* units, which the `u` key flips between SI
//! and US without touching the deck: an edit typed in the other system is converted to
//! the deck's own units before [`Deck::set`] validates and applies it.

use std::path::Path;

use crate::bearings::spherical_roller::Bearing;
use crate::deck::{self, Deck, DeckError, DeckErrors, FieldKind, FieldSpec};

use crate::units::Units;

/// `"SI"` or `"US"`.
pub fn units_label(u: Units) -> &'static str {
    match u {
        Units::Si => "SI",
        Units::Us => "US",
    }
}

/// Flips SI ↔ US.
pub fn other_units(u: Units) -> Units {
    match u {
        Units::Si => Units::Us,
        Units::Us => Units::Si,
    }
}

/// One editable deck field as the inputs pane lists it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldInfo {
    /// Full key path, e.g. `geometry.pitch_diameter`.
    pub key: &'static str,
    /// Group (deck table) the key lives in.
    pub group: &'static str,
    /// Short label with the seed's symbol.
    pub label: &'static str,
}

/// Every editable field, in deck order.
pub fn field_list() -> Vec<FieldInfo> {
    deck::fields()
        .iter()
        .map(|s| FieldInfo {
            key: s.key,
            group: s.group,
            label: s.label,
        })
        .collect()
}

/// Unit label of `key` in `units` (empty for dimensionless and choices).
pub fn unit(key: &str, units: Units) -> &'static str {
    match deck::field(key) {
        Some(s) if matches!(s.kind, FieldKind::Real) => s.unit(units),
        _ => "",
    }
}

/// The allowed values of a choice field (`None` for numbers).
pub fn choices(key: &str) -> Option<&'static [&'static str]> {
    match deck::field(key)?.kind {
        FieldKind::Choice(list) => Some(list),
        _ => None,
    }
}

/// Allowed values of `key` in `units`, for inline validation messages.
pub fn allowed(key: &str, units: Units) -> String {
    match deck::field(key) {
        Some(FieldSpec {
            kind: FieldKind::Choice(list),
            ..
        }) => format!("one of {}", list.join(", ")),
        Some(s) => s.allowed(units),
        None => String::new(),
    }
}

/// Formats a number to 6 significant digits without trailing zeros (the deck's format).
pub fn fmt_num(v: f64) -> String {
    crate::deck::format_short(v)
}

/// Default deck text (the shipped aerospace deck).
pub fn default_text() -> String {
    deck::DEFAULT_DECK.to_string()
}

/// One compact line per error, for the status bar and the inline edit error.
fn describe(errors: &DeckErrors) -> String {
    errors
        .errors()
        .iter()
        .map(|e| match e {
            DeckError::OutOfRange { allowed, .. } => format!("out of range: {allowed}"),
            DeckError::Invalid { rule, .. } => rule.clone(),
            DeckError::WrongType { expected, .. } => format!("expected {expected}"),
            other => other.to_string(),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// A deck under edit.
#[derive(Debug, Clone)]
pub struct DeckDoc {
    deck: Deck,
}

impl PartialEq for DeckDoc {
    fn eq(&self, other: &Self) -> bool {
        self.deck.units == other.deck.units && self.text() == other.text()
    }
}

impl DeckDoc {
    /// Parses and validates deck text; errors are readable lines with key and line.
    pub fn parse(text: &str, source_name: &str) -> Result<DeckDoc, String> {
        Deck::parse(text, source_name)
            .map(|deck| DeckDoc { deck })
            .map_err(|e| e.to_string())
    }

    /// Wraps an already parsed deck (e.g. the CLI's, with `--set` overrides applied).
    pub fn from_deck(deck: Deck) -> DeckDoc {
        DeckDoc { deck }
    }

    /// Reads and parses a deck file.
    pub fn load(path: &Path) -> Result<DeckDoc, String> {
        Deck::load(path)
            .map(|deck| DeckDoc { deck })
            .map_err(|e| e.to_string())
    }

    /// Saves atomically (temporary file then rename; previous file kept as `.bak`).
    /// On failure the existing file is untouched. Links are saved through, read-only
    /// decks refused (see [`crate::files`]); the result says how the file was written.
    pub fn save(&self, path: &Path) -> Result<crate::files::Written, String> {
        self.deck.save(path).map_err(|e| e.to_string())
    }

    /// Unit system the deck is written in.
    pub fn units(&self) -> Units {
        self.deck.units
    }

    /// The resolved SI bearing.
    pub fn bearing(&self) -> &Bearing {
        &self.deck.bearing
    }

    /// The wrapped deck.
    pub fn deck(&self) -> &Deck {
        &self.deck
    }

    /// The deck's bearing system (its `type`).
    pub fn system_id(&self) -> &'static str {
        crate::bearings::spherical_roller::SYSTEM_ID
    }

    /// The deck's name.
    pub fn name(&self) -> &str {
        &self.deck.bearing.name
    }

    /// True if the deck has a `[thermal]` model.
    pub fn has_thermal(&self) -> bool {
        self.deck.thermal.is_some()
    }

    /// The deck's thermal network (None when absent or invalid; `check` reports why).
    pub fn thermal_model(&self) -> Option<crate::thermal::ThermalModel> {
        self.deck.thermal_model().ok().flatten()
    }

    /// The deck as text (what a save writes).
    pub fn text(&self) -> String {
        self.deck.to_toml_string()
    }

    /// The value of `key` in `display` units: as written when those are the deck's
    /// units, else converted to 6 significant digits. `—` for unknown keys.
    pub fn value(&self, key: &str, display: Units) -> String {
        let Some(spec) = deck::field(key) else {
            return "—".into();
        };
        match spec.kind {
            FieldKind::Real if display != self.deck.units => {
                fmt_num(spec.from_si(spec.get_si(&self.deck.bearing), display))
            }
            _ => self.deck.get(key).unwrap_or_else(|| "—".into()),
        }
    }

    /// The value of `key` for the inputs pane: like [`DeckDoc::value`] but reals are
    /// always shown to 6 significant digits so the column lines up.
    pub fn display_value(&self, key: &str, display: Units) -> String {
        match deck::field(key) {
            Some(spec) if matches!(spec.kind, FieldKind::Real) => {
                fmt_num(spec.from_si(spec.get_si(&self.deck.bearing), display))
            }
            _ => self.value(key, display),
        }
    }

    /// Sets `key` from `text` written in `display` units. Validates the range and the
    /// whole deck; on error the deck is unchanged and the message names the allowed
    /// range in `display` units.
    pub fn set_value(&mut self, key: &str, text: &str, display: Units) -> Result<(), String> {
        let spec = deck::field(key).ok_or_else(|| format!("{key}: not editable"))?;
        let text = text.trim();
        let deck_text = match spec.kind {
            FieldKind::Choice(list) => {
                if !list.contains(&text) {
                    return Err(format!("expected one of {}", list.join(", ")));
                }
                text.to_string()
            }
            FieldKind::Integer | FieldKind::Real => {
                let v: f64 = text
                    .parse()
                    .map_err(|_| format!("not a number: {text:?}"))?;
                let integer = matches!(spec.kind, FieldKind::Integer);
                if integer && v.fract() != 0.0 {
                    return Err(format!(
                        "expected a whole number; {}",
                        allowed(key, display)
                    ));
                }
                let si = if integer { v } else { spec.to_si(v, display) };
                if !spec.in_range(si) {
                    return Err(format!("out of range: {}", allowed(key, display)));
                }
                if integer {
                    format!("{}", v as i64)
                } else if display == self.deck.units {
                    text.to_string()
                } else {
                    // 12 significant digits: drops conversion noise (3.5000000000000004).
                    let v = spec.from_si(si, self.deck.units);
                    let rounded: f64 = format!("{v:.11e}").parse().unwrap_or(v);
                    format!("{rounded:?}")
                }
            }
        };
        self.deck.set(key, &deck_text).map_err(|e| describe(&e))
    }
}
