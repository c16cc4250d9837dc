//! TOML input decks: parse (US customary or SI) into a bearing system's SI input,
//! validate with key/line/column diagnostics, edit values in place keeping comments,
//! convert between unit systems, and save atomically.
//!
//! The machinery is generic over the bearing system ([`form`]: a [`Schema`] per system,
//! read into a [`Form`]); this module adds what is not per system (reading a deck file,
//! [`system_of`], errors, the `[thermal]` section's parser) and re-exports the spherical
//! roller's deck ([`Deck`], [`fields()`], [`template`], …, defined in
//! `bearings::spherical_roller::{deck, deck_schema}`), the default system.
//!
//! The spherical roller's key layout is a contract (see [`template`] for every key, its
//! unit and range): top-level `type` (optional, `"spherical-roller"`), `units` ("us" |
//! "si") and `name`, then the tables `[geometry]`, `[materials]`, `[operating]`,
//! `[lubricant]`, `[surfaces]`, `[life]`, `[cage]`, optional `[solver]`, and an optional
//! `[thermal]` table kept opaque for the thermal module.
#![warn(missing_docs)]
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

mod error;
pub mod form;
pub mod thermal;

pub use crate::bearings::spherical_roller::deck::{
    close_keys, editable_keys, field, fields, keys_table, template, write_bearing, Deck,
    DEFAULT_DECK,
};
pub use crate::bearings::spherical_roller::deck_schema::{
    FILM_MODELS, GROUPS, GUIDING_RINGS, LIFE_METHODS, MATERIAL_BODIES,
};
pub use crate::units::Units;
pub use error::{DeckError, DeckErrors, Location};
pub use form::{
    format_short, material_preset, FieldKind, FieldMeta, FieldSpec, Form, MaterialAccess, Presence,
    Schema, TemplateNotes, MATERIAL_PRESETS,
};

use std::path::Path;

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

#[cfg(test)]
mod tests;
