//! TOML input decks: parse (US customary or SI) into the SI [`Bearing`], validate with
//! key/line/column diagnostics, edit values in place keeping comments, convert between
//! unit systems, and save atomically.
//!
//! The key layout is a contract (see [`template`] for every key, its unit and range):
//! top-level `units` ("us" | "si") and `name`, then the tables `[geometry]`,
//! `[materials]`, `[operating]`, `[lubricant]`, `[surfaces]`, `[life]`, `[cage]`,
//! optional `[solver]`, and an optional `[thermal]` table kept opaque for the thermal
//! module. Every editable scalar is described once in [`fields()`]: parsing,
//! validation, the template, [`Deck::get`]/[`Deck::set`] and the TUI read that table.
#![warn(missing_docs)]
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

mod error;
pub mod form;
mod schema;
mod template;
pub mod thermal;
mod validate;

pub use crate::units::Units;
pub use error::{DeckError, DeckErrors, Location};
pub use form::{FieldMeta, Form, MaterialAccess, Schema, TemplateNotes};
pub use schema::{
    field, fields, format_short, material_preset, FieldKind, FieldSpec, Presence, FILM_MODELS,
    GROUPS, GUIDING_RINGS, LIFE_METHODS, MATERIAL_BODIES, MATERIAL_PRESETS,
};
pub use template::template;

use std::path::Path;

use toml_edit::{DocumentMut, Item, Value};

use crate::bearings::spherical_roller::Bearing;

/// The aerospace example deck (US units), shipped as `decks/aerospace.toml`.
pub const DEFAULT_DECK: &str = include_str!("../../decks/aerospace.toml");

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
        let parsed = validate::parse_text(text, source_name)?;
        let doc = text
            .parse::<DocumentMut>()
            .map_err(|e| validate::syntax_error(&e, text, source_name))?;
        Ok(Deck {
            units: parsed.units,
            bearing: parsed.bearing,
            thermal: parsed.thermal,
            source_name: source_name.to_string(),
            doc,
        })
    }

    /// Reads and parses a deck file; errors name the file.
    pub fn load(path: impl AsRef<Path>) -> Result<Deck, DeckErrors> {
        let path = path.as_ref();
        let text = read_deck_text(path)?;
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
        let mut doc = self.doc.clone();
        for a in assignments {
            let Some((k, v)) = a.split_once('=') else {
                return Err(DeckError::NotEditable {
                    key: a.to_string(),
                    reason: "expected KEY=VALUE, e.g. --set geometry.pitch_diameter=3.4".into(),
                }
                .into());
            };
            self.edit(&mut doc, k.trim(), v.trim())?;
        }
        let parsed = validate::parse_text(&doc.to_string(), &self.source_name)?;
        self.units = parsed.units;
        self.bearing = parsed.bearing;
        self.thermal = parsed.thermal;
        self.doc = doc;
        Ok(())
    }

    /// The thermal network of the deck's `[thermal]` section, if any (errors name node,
    /// link and field).
    pub fn thermal_model(&self) -> Result<Option<crate::thermal::ThermalModel>, DeckErrors> {
        match &self.thermal {
            None => Ok(None),
            Some(t) => thermal::parse_thermal_located(t, self.units)
                .map(Some)
                .map_err(|e| {
                    let message = match &e.error {
                        crate::thermal::ThermalError::Deck { location, message } => {
                            format!("{location}: {message}")
                        }
                        other => other.to_string(),
                    };
                    DeckError::Thermal {
                        location: self.thermal_location(&e.path),
                        message,
                    }
                    .into()
                }),
        }
    }

    /// Line and column of the deepest node of `path` (inside `[thermal]`) found in the
    /// deck's text: the field's value, else its entry, else the `[thermal]` header.
    fn thermal_location(&self, path: &[thermal::PathSeg]) -> Location {
        let text = self.doc.to_string();
        let Ok(doc) = toml_edit::Document::parse(text.as_str()) else {
            return Location::start(&self.source_name);
        };
        fn span_of(item: &Item) -> Option<std::ops::Range<usize>> {
            match item {
                Item::Value(v) => v.span(),
                Item::Table(t) => t.span(),
                Item::ArrayOfTables(a) => a.span(),
                Item::None => None,
            }
        }
        // Walk items (tables, arrays of tables), their tables and values (inline
        // tables, arrays).
        #[derive(Clone, Copy)]
        enum Node<'a> {
            Item(&'a Item),
            Table(&'a toml_edit::Table),
            Value(&'a Value),
        }
        let Some(root) = doc.as_table().get("thermal") else {
            return Location::start(&self.source_name);
        };
        let mut best = span_of(root);
        let mut node = Node::Item(root);
        for seg in path {
            use thermal::PathSeg::{Index, Key};
            let value = match node {
                Node::Item(Item::Value(v)) | Node::Value(v) => Some(v),
                _ => None,
            };
            let next = match (node, value, seg) {
                (Node::Item(Item::Table(t)), _, Key(k)) | (Node::Table(t), _, Key(k)) => {
                    t.get(k).map(Node::Item)
                }
                (Node::Item(Item::ArrayOfTables(a)), _, Index(i)) => a.get(*i).map(Node::Table),
                (_, Some(Value::InlineTable(t)), Key(k)) => t.get(k).map(Node::Value),
                (_, Some(Value::Array(a)), Index(i)) => a.get(*i).map(Node::Value),
                _ => None,
            };
            let Some(n) = next else { break };
            let span = match n {
                Node::Item(i) => span_of(i),
                Node::Table(t) => t.span(),
                Node::Value(v) => v.span(),
            };
            if span.is_some() {
                best = span;
            }
            node = n;
        }
        let offset = best.map_or(0, |s| s.start);
        Location::at(&self.source_name, &text, offset)
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
        self.edit(&mut doc, key_path, value)?;
        let text = doc.to_string();
        let parsed = validate::parse_text(&text, &self.source_name)?;
        self.units = parsed.units;
        self.bearing = parsed.bearing;
        self.thermal = parsed.thermal;
        self.doc = doc;
        Ok(())
    }

    /// Writes one value into `doc` (a copy of this deck's document) without validating;
    /// see [`Deck::set`].
    fn edit(&self, doc: &mut DocumentMut, key_path: &str, value: &str) -> Result<(), DeckErrors> {
        let not_editable = |reason: &str| {
            DeckErrors::from(DeckError::NotEditable {
                key: key_path.to_string(),
                reason: reason.to_string(),
            })
        };
        if key_path == "units" {
            return Err(not_editable(
                "the unit system changes the meaning of every number; use Deck::converted",
            ));
        }
        let parts: Vec<&str> = key_path.split('.').collect();
        if parts.iter().any(|p| p.is_empty()) {
            return Err(not_editable("empty key segment"));
        }
        let spec = field(key_path);
        let is_body = parts.len() == 2
            && parts.first() == Some(&"materials")
            && parts.get(1).is_some_and(|b| MATERIAL_BODIES.contains(b));
        let is_thermal = parts.len() > 1 && parts.first() == Some(&"thermal");
        if !(key_path == "name" || spec.is_some() || is_body || is_thermal) {
            return Err(not_editable(&unknown_key_hint(key_path)));
        }
        let wants_string = key_path == "name"
            || is_body
            || spec.is_some_and(|s| matches!(s.kind, FieldKind::Choice(_)));
        // The two ways of giving α are exclusive: setting one removes the other.
        let exclusive_other = match spec.map(|s| s.presence) {
            Some(Presence::OneOf(other)) => Some(other),
            _ => None,
        };
        let trimmed = value.trim();
        let mut new_value = match trimmed.parse::<Value>() {
            Ok(v) if !wants_string || v.is_str() => v,
            _ => Value::from(trimmed),
        };

        // A material given as a preset name becomes an inline table before one of its
        // properties is edited.
        if parts.len() == 3 && parts.first() == Some(&"materials") {
            let body = parts.get(1).copied().unwrap_or("");
            let is_preset = doc
                .get("materials")
                .and_then(|m| m.get(body))
                .is_some_and(Item::is_str);
            if is_preset {
                let mut t = toml_edit::InlineTable::new();
                for f in fields()
                    .iter()
                    .filter(|f| f.group == format!("materials.{body}"))
                {
                    // 15 significant digits: hides the last-bit noise of the conversion
                    let v = f.from_si(f.get_si(&self.bearing), self.units);
                    let v: f64 = template::fmt_real(v).parse().unwrap_or(v);
                    t.insert(f.name(), Value::from(v));
                }
                if let Some(slot) = doc.get_mut("materials").and_then(|m| m.get_mut(body)) {
                    let decor = slot.as_value().map(|v| v.decor().clone());
                    let mut v = Value::InlineTable(t);
                    if let Some(d) = decor {
                        *v.decor_mut() = d;
                    }
                    *slot = Item::Value(v);
                }
            }
        }
        let mut item: &mut Item = doc.as_item_mut();
        let (last, path) = match parts.split_last() {
            Some(x) => x,
            None => return Err(not_editable("empty key")),
        };
        for p in path {
            let Some(t) = item.as_table_like_mut() else {
                return Err(not_editable("a parent of this key is not a table"));
            };
            item = t.entry(p).or_insert(Item::Table(toml_edit::Table::new()));
        }
        let Some(t) = item.as_table_like_mut() else {
            return Err(not_editable("the parent of this key is not a table"));
        };
        match t.get_mut(last) {
            Some(Item::Value(old)) => {
                *new_value.decor_mut() = old.decor().clone();
                *old = new_value;
            }
            Some(other) => *other = Item::Value(new_value),
            None => {
                t.insert(last, Item::Value(new_value));
            }
        }
        if let Some(other) = exclusive_other {
            let mut it = other.split('.');
            if let (Some(g), Some(k)) = (it.next(), it.next()) {
                if let Some(t) = doc.get_mut(g).and_then(Item::as_table_like_mut) {
                    t.remove(k);
                }
            }
        }
        Ok(())
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
        let mut item: &Item = self.doc.as_item();
        let mut found = true;
        for p in key_path.split('.') {
            match item.get(p) {
                Some(i) => item = i,
                None => {
                    found = false;
                    break;
                }
            }
        }
        if found {
            if let Some(v) = item.as_value() {
                return Some(match v.as_str() {
                    Some(s) => s.to_string(),
                    None => {
                        let mut v = v.clone();
                        v.decor_mut().clear();
                        v.to_string()
                    }
                });
            }
        }
        let spec = field(key_path)?;
        let si = spec.get_si(&self.bearing);
        Some(match spec.kind {
            FieldKind::Choice(list) => list.get(si as usize).copied().unwrap_or("").to_string(),
            FieldKind::Integer => format!("{}", si.round() as i64),
            FieldKind::Real => template::fmt_real(spec.from_si(si, self.units)),
        })
    }

    /// The same bearing written in `units`: a clean regenerated deck (comments other
    /// than unit hints are not carried over; `[thermal]` is).
    pub fn converted(&self, units: Units) -> Deck {
        let header = format!(
            "{}\nConverted by rollbench from a deck in {} units.",
            self.bearing.name,
            self.units.as_str()
        );
        let text =
            template::write_deck(&self.bearing, units, self.thermal.as_ref(), &header, false);
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
        crate::files::save_with_backup(path.as_ref(), &self.to_toml_string()).map_err(|e| {
            DeckErrors::from(DeckError::Io {
                path: e.path,
                action: e.action,
                source: e.source,
            })
        })
    }
}

/// Largest deck file read, bytes (4 MiB: a deck is a few kB; this bounds what an endless
/// stream such as `/dev/zero` can make the reader hold).
pub const MAX_DECK_BYTES: u64 = 4 << 20;

/// Reads a deck file's text, at most [`MAX_DECK_BYTES`]; errors name the file, and for a
/// file that is not UTF-8 the byte offset, line and column of the first invalid byte.
pub fn read_deck_text(path: &Path) -> Result<String, DeckErrors> {
    use std::io::Read;
    let io_err = |source: std::io::Error| -> DeckErrors {
        DeckError::Io {
            path: path.to_path_buf(),
            action: "cannot read deck",
            source,
        }
        .into()
    };
    let file = std::fs::File::open(path).map_err(io_err)?;
    let mut bytes = Vec::new();
    file.take(MAX_DECK_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io_err)?;
    if bytes.len() as u64 > MAX_DECK_BYTES {
        return Err(io_err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "larger than the deck size limit of {} MiB ({MAX_DECK_BYTES} bytes); reading stopped there",
                MAX_DECK_BYTES >> 20
            ),
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let before = bytes.get(..offset).unwrap_or(bytes);
        let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
        let line_start = before.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        let column = String::from_utf8_lossy(before.get(line_start..).unwrap_or(&[]))
            .chars()
            .count()
            + 1;
        let byte = bytes.get(offset).copied().unwrap_or(0);
        io_err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "not UTF-8 text: invalid byte 0x{byte:02x} at byte offset {offset} (line {line}, column {column}); save the deck as UTF-8"
            ),
        ))
    })
}

/// The bearing system a deck's top-level `type` names; a deck without `type` is a
/// [`crate::bearings::DEFAULT_SYSTEM`] deck. A deck that is not valid TOML is handed to
/// the default system's parser, whose message locates the syntax error.
pub fn system_of(
    text: &str,
    source_name: &str,
) -> Result<&'static dyn crate::bearings::BearingSystem, DeckErrors> {
    use crate::bearings::{known_types, system, DEFAULT_SYSTEM};
    let default = || {
        system(DEFAULT_SYSTEM).ok_or_else(|| {
            DeckErrors::from(DeckError::NotEditable {
                key: "type".into(),
                reason: "no default bearing system registered".into(),
            })
        })
    };
    let Ok(doc) = toml_edit::Document::parse(text) else {
        return default();
    };
    let Some(item) = doc.as_table().get("type") else {
        return default();
    };
    let location = item
        .as_value()
        .and_then(toml_edit::Value::span)
        .map_or_else(
            || Location::start(source_name),
            |sp| Location::at(source_name, text, sp.start),
        );
    let value = item.as_value().map_or_else(
        || "(a table)".to_string(),
        |v| v.to_string().trim().to_string(),
    );
    match item.as_str() {
        None => Err(DeckError::WrongType {
            location,
            key: "type".into(),
            value,
            expected: format!("a string, one of {}", known_types()),
        }
        .into()),
        Some(id) => system(id).ok_or_else(|| {
            DeckError::Invalid {
                location,
                key: "type".into(),
                value,
                rule: format!("unknown bearing system (known: {})", known_types()),
            }
            .into()
        }),
    }
}

/// Every key `--set` and [`Deck::set`] accept: `name`, each field of [`fields()`], the
/// material bodies (a preset name or a table), and `thermal.…` (any key of the
/// `[thermal]` table, checked by the thermal section's parser).
pub fn editable_keys() -> Vec<&'static str> {
    let mut keys = vec!["name"];
    keys.extend(fields().iter().map(|f| f.key));
    // One per MATERIAL_BODIES entry (a preset name or an inline table).
    keys.extend([
        "materials.roller",
        "materials.inner_ring",
        "materials.outer_ring",
    ]);
    keys.push("thermal.transient.duration");
    keys.push("thermal.transient.step");
    keys.push("thermal.transient.integrator");
    keys.push("thermal.transient.scenario");
    keys.push("thermal.transient.split_fraction");
    keys.push("thermal.transient.oil_node");
    keys.push("thermal.transient.stop_at_limits");
    keys.dedup();
    keys
}

/// The table `rollbench keys` prints: every editable key with its units and allowed range
/// in SI and US units, then `name`, the material bodies and the `[thermal]` keys.
pub fn keys_table() -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let _ = writeln!(s, "{:<40} {:<36} allowed (us)", "key", "allowed (si)");
    for f in fields() {
        let allowed = |u: Units| match f.kind {
            FieldKind::Choice(list) => list.join(" | "),
            _ => f.allowed(u),
        };
        let _ = writeln!(
            s,
            "{:<40} {:<36} {}",
            f.key,
            allowed(Units::Si),
            allowed(Units::Us)
        );
    }
    let _ = writeln!(s, "{:<40} any string", "name");
    for k in [
        "materials.roller",
        "materials.inner_ring",
        "materials.outer_ring",
    ] {
        let presets: Vec<&str> = MATERIAL_PRESETS.iter().map(|(n, _)| *n).collect();
        let _ = writeln!(s, "{:<40} one of {}", k, presets.join(", "));
    }
    let _ = writeln!(
        s,
        "{:<40} the [thermal] section (see `rollbench template`); e.g. thermal.transient.duration",
        "thermal.<table>.<key>"
    );
    s
}

/// Levenshtein distance of two short keys (characters).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev.get(j).copied().unwrap_or(0) + usize::from(ca != *cb);
            let del = prev.get(j + 1).copied().unwrap_or(0) + 1;
            let ins = cur.get(j).copied().unwrap_or(0) + 1;
            if let Some(c) = cur.get_mut(j + 1) {
                *c = sub.min(del).min(ins);
            }
        }
        prev = cur;
    }
    prev.last().copied().unwrap_or(0)
}

/// The editable keys closest to `key` (typos, a wrong table, a missing table): at most
/// five, closest first.
pub fn close_keys(key: &str) -> Vec<&'static str> {
    let leaf = key.rsplit('.').next().unwrap_or(key);
    let mut scored: Vec<(usize, &'static str)> = editable_keys()
        .into_iter()
        .filter_map(|k| {
            let k_leaf = k.rsplit('.').next().unwrap_or(k);
            let d = edit_distance(key, k).min(edit_distance(leaf, k_leaf) + 1);
            let limit = (key.len() / 3).clamp(2, 6);
            (d <= limit || (leaf.len() >= 4 && k_leaf.contains(leaf))).then_some((d, k))
        })
        .collect();
    scored.sort();
    scored.into_iter().take(5).map(|(_, k)| k).collect()
}

/// The message for an unknown `--set` key: the close matches and where the full list is.
fn unknown_key_hint(key: &str) -> String {
    let close = close_keys(key);
    let list = "`rollbench keys` lists every editable key with its allowed range";
    if close.is_empty() {
        format!("unknown key ({list})")
    } else {
        format!("unknown key; did you mean {}? ({list})", close.join(", "))
    }
}

/// Writes `bearing` as a clean deck in `units` (unit comments only). Parsing it gives
/// back the same bearing to round-off (about 1e-15 relative).
pub fn write_bearing(bearing: &Bearing, units: Units) -> String {
    template::write_deck(bearing, units, None, &bearing.name, false)
}

#[cfg(test)]
mod tests;
