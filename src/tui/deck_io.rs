//! Thin adapter between the TUI and a bearing system's deck ([`Case`]): the only TUI file
//! that knows how a deck is parsed, edited and saved.
//!
//! Values are shown and typed in *display* units, which the `u` key flips between SI
//! and US without touching the deck: an edit typed in the other system is converted to
//! the deck's own units before [`Case::with_value`] validates and applies it.

use std::path::Path;
use std::sync::Arc;

use crate::bearings::{self, BearingSystem, Case};
use crate::deck::{DeckError, DeckErrors, FieldKind, FieldMeta};

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
    /// One-line explanation (what it is, what 0 means where it means something).
    pub help: &'static str,
}

/// Formats a number to 6 significant digits without trailing zeros (the deck's format).
pub fn fmt_num(v: f64) -> String {
    crate::deck::format_short(v)
}

/// Significant digits of a number as written (`24.8449406113489` → 15, `1.3e-6` → 2).
fn significant_digits(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    digits
        .trim_start_matches('0')
        .trim_end_matches('0')
        .len()
        .max(1)
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

/// A deck under edit: a validated case of some bearing system. Immutable and shared: an
/// edit makes a new case, so undo keeps the old one and a solve job holds its own.
#[derive(Clone)]
pub struct DeckDoc {
    case: Arc<dyn Case>,
}

impl std::fmt::Debug for DeckDoc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DeckDoc")
            .field("system", &self.system_id())
            .field("source", &self.case.source_name())
            .finish()
    }
}

impl PartialEq for DeckDoc {
    fn eq(&self, other: &Self) -> bool {
        self.system_id() == other.system_id()
            && self.units() == other.units()
            && self.text() == other.text()
    }
}

impl DeckDoc {
    /// Parses and validates deck text of any system (its `type`); errors are readable
    /// lines with key and line.
    pub fn parse(text: &str, source_name: &str) -> Result<DeckDoc, String> {
        bearings::load_case(text, source_name, &[])
            .map(DeckDoc::from_case)
            .map_err(|e| e.to_string())
    }

    /// Wraps an already loaded case (e.g. the CLI's, with `--set` overrides applied).
    pub fn from_case(case: Box<dyn Case>) -> DeckDoc {
        DeckDoc { case: case.into() }
    }

    /// Reads and parses a deck file.
    pub fn load(path: &Path) -> Result<DeckDoc, String> {
        bearings::load_file(path, &[])
            .map(DeckDoc::from_case)
            .map_err(|e| e.to_string())
    }

    /// Saves atomically (temporary file then rename; previous file kept as `.bak`).
    /// On failure the existing file is untouched. Links are saved through, read-only
    /// decks refused (see [`crate::files`]); the result says how the file was written.
    pub fn save(&self, path: &Path) -> Result<crate::files::Written, String> {
        self.case.save(path).map_err(|e| e.to_string())
    }

    /// Unit system the deck is written in.
    pub fn units(&self) -> Units {
        self.case.units()
    }

    /// The validated case (what the solver takes).
    pub fn case(&self) -> Arc<dyn Case> {
        Arc::clone(&self.case)
    }

    /// The deck's bearing system.
    pub fn system(&self) -> &'static dyn BearingSystem {
        self.case.system()
    }

    /// The deck's bearing system (its `type`).
    pub fn system_id(&self) -> &'static str {
        self.case.system().id()
    }

    /// The deck's name.
    pub fn name(&self) -> &str {
        self.case.name()
    }

    /// True if the deck has a thermal model (with its transient).
    pub fn has_thermal(&self) -> bool {
        self.case.has_transient()
    }

    /// The deck as text (what a save writes).
    pub fn text(&self) -> String {
        self.case.text()
    }

    /// Every editable field, in deck order.
    pub fn fields(&self) -> Vec<FieldInfo> {
        self.case
            .fields()
            .into_iter()
            .map(|s| FieldInfo {
                key: s.key,
                group: s.group,
                label: s.label,
                help: s.help,
            })
            .collect()
    }

    fn field(&self, key: &str) -> Option<&'static FieldMeta> {
        self.case.fields().into_iter().find(|f| f.key == key)
    }

    /// Unit label of `key` in `units` (empty for dimensionless and choices). A key written
    /// in a metric unit in every deck (l/min, 1/°C) is marked so in US: `l/min (SI)`.
    pub fn unit(&self, key: &str, units: Units) -> &'static str {
        match self.field(key) {
            Some(s) if matches!(s.kind, FieldKind::Real | FieldKind::RealOr(_)) => {
                match (units, s.quantity.us_customary()) {
                    (Units::Us, Some(c)) => c.label,
                    _ => s.unit(units),
                }
            }
            _ => "",
        }
    }

    /// For a key written in a metric unit in every deck, shown in US: that it stays metric
    /// and its value in the US customary unit (`0.1 l/min = 0.0264172 gal/min (written
    /// in l/min in every deck, US ones too)`).
    pub fn us_customary_note(&self, key: &str, units: Units) -> Option<String> {
        let spec = self.field(key)?;
        let c = spec.quantity.us_customary()?;
        if units != Units::Us {
            return None;
        }
        let v = spec.from_si(self.case.field_si(key)?, units);
        Some(format!(
            "{} {} = {} {} (written in {} in every deck, US ones too)",
            fmt_num(v),
            spec.unit(units),
            fmt_num(v * c.factor),
            c.unit,
            spec.unit(units),
        ))
    }

    /// The allowed values of a choice field (`None` for numbers).
    pub fn choices(&self, key: &str) -> Option<&'static [&'static str]> {
        match self.field(key)?.kind {
            FieldKind::Choice(list) => Some(list),
            _ => None,
        }
    }

    /// Allowed values of `key` in `units`, for inline validation messages.
    pub fn allowed(&self, key: &str, units: Units) -> String {
        match self.field(key) {
            Some(s) => match s.kind {
                FieldKind::Choice(list) => format!("one of {}", list.join(", ")),
                FieldKind::RealOr(word) => format!("{} or \"{word}\"", s.allowed(units)),
                _ => s.allowed(units),
            },
            None => String::new(),
        }
    }

    /// The value of real field `spec` in `display` units, 6 significant digits.
    fn converted(&self, spec: &FieldMeta, display: Units) -> Option<String> {
        let si = self.case.field_si(spec.key)?;
        Some(fmt_num(spec.from_si(si, display)))
    }

    /// The value of `key` in `display` units: as written when those are the deck's
    /// units, else converted to 6 significant digits. `—` for unknown keys.
    pub fn value(&self, key: &str, display: Units) -> String {
        let Some(spec) = self.field(key) else {
            return "—".into();
        };
        let converted = match spec.kind {
            FieldKind::Real if display != self.units() => self.converted(spec, display),
            _ => None,
        };
        // A value written with conversion noise (a preset's 24.8449406113489, a
        // converted deck's 6.52669819785941e-7) is offered as the list shows it.
        let written = self.case.get(key).map(|w| match spec.kind {
            FieldKind::Real if significant_digits(&w) > 9 => {
                self.converted(spec, display).unwrap_or(w)
            }
            _ => w,
        });
        converted.or(written).unwrap_or_else(|| "—".into())
    }

    /// The value of `key` for the inputs pane: like [`DeckDoc::value`] but reals are
    /// always shown to 6 significant digits so the column lines up.
    pub fn display_value(&self, key: &str, display: Units) -> String {
        match self.field(key) {
            Some(spec) if matches!(spec.kind, FieldKind::Real) => {
                self.converted(spec, display).unwrap_or_else(|| "—".into())
            }
            _ => self.value(key, display),
        }
    }

    /// Sets `key` from `text` written in `display` units. Validates the range and the
    /// whole deck; on error the deck is unchanged and the message names the allowed
    /// range in `display` units.
    pub fn set_value(&mut self, key: &str, text: &str, display: Units) -> Result<(), String> {
        let spec = self
            .field(key)
            .ok_or_else(|| format!("{key}: not editable"))?;
        let text = text.trim();
        let deck_text = match spec.kind {
            FieldKind::Choice(list) => {
                if !list.contains(&text) {
                    return Err(format!("expected one of {}", list.join(", ")));
                }
                text.to_string()
            }
            FieldKind::RealOr(word) if text == word => word.to_string(),
            FieldKind::Integer | FieldKind::Real | FieldKind::RealOr(_) => {
                let v: f64 = text
                    .parse()
                    .map_err(|_| format!("not a number: {text:?}"))?;
                let integer = matches!(spec.kind, FieldKind::Integer);
                if integer && v.fract() != 0.0 {
                    return Err(format!(
                        "expected a whole number; {}",
                        self.allowed(key, display)
                    ));
                }
                let si = if integer { v } else { spec.to_si(v, display) };
                if !spec.in_range(si) {
                    return Err(format!("out of range: {}", self.allowed(key, display)));
                }
                if integer {
                    format!("{}", v as i64)
                } else if display == self.units() {
                    text.to_string()
                } else {
                    // 12 significant digits: drops conversion noise (3.5000000000000004).
                    let v = spec.from_si(si, self.units());
                    let rounded: f64 = format!("{v:.11e}").parse().unwrap_or(v);
                    format!("{rounded:?}")
                }
            }
        };
        let case = self
            .case
            .with_value(key, &deck_text)
            .map_err(|e| describe(&e))?;
        self.case = case.into();
        Ok(())
    }
}
