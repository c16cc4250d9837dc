//! TOML input decks: parse (US customary or SI) into a bearing system's SI input,
//! validate with key/line/column diagnostics, edit values in place keeping comments,
//! convert between unit systems, and save atomically.
//!
//! The machinery is generic over the bearing system ([`form`]: a [`Schema`] per system,
//! read into a [`Form`]); this module adds what is not per system (reading a deck file,
//! the deck's `type` ([`deck_type`]), errors, the `[thermal]` section's parser). It knows
//! no bearing system: each system's schema lives in its folder under `crate::bearings`,
//! and `crate::bearings` maps a deck's `type` to its system (input parsing does not
//! know the registry).
//!
//! Every deck starts with the top-level keys `type` (the bearing system; optional only
//! for [`DEFAULT_TYPE`] decks, written before there was a choice), `units` ("us" | "si")
//! and `name`, then the tables of its system's schema.
#![warn(missing_docs)]
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod bounds;
mod error;
pub mod form;
pub mod thermal;

pub use crate::units::Units;
pub use error::{DeckError, DeckErrors, Location};
/// A toml_edit syntax error as a [`DeckError::Syntax`] (file, line, column, the line with a
/// caret): for other TOML files read like decks (study files).
pub(crate) use form::syntax_error as syntax_error_of;
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

/// The `type` of a deck that does not name one: decks written before there was a choice
/// of bearing system are spherical roller decks.
pub const DEFAULT_TYPE: &str = "spherical-roller";

/// A deck's top-level `type` key as written (the registry in `crate::bearings` maps it to
/// a system and names the known ones when it is not).
#[derive(Debug, Clone, PartialEq)]
pub enum DeckType {
    /// No `type` key, or text that is not TOML (the system's reader reports that).
    Absent,
    /// A string: the system's id, where it stands, and the value as written.
    Named {
        /// The string.
        id: String,
        /// Where the value stands.
        location: Location,
        /// The value as written (quoted).
        written: String,
    },
    /// Not a string (a number, a table): where, and what was written.
    NotAString {
        /// Where the value stands.
        location: Location,
        /// The value as written (`(a table)` for a table).
        written: String,
    },
}

/// Reads the top-level `type` of deck text; nothing else is checked here.
pub fn deck_type(text: &str, source_name: &str) -> DeckType {
    let Ok(doc) = toml_edit::Document::parse(text) else {
        return DeckType::Absent;
    };
    let Some(item) = doc.as_table().get("type") else {
        return DeckType::Absent;
    };
    let location = item
        .as_value()
        .and_then(toml_edit::Value::span)
        .map_or_else(
            || Location::start(source_name),
            |sp| Location::at(source_name, text, sp.start),
        );
    let written = item.as_value().map_or_else(
        || "(a table)".to_string(),
        |v| v.to_string().trim().to_string(),
    );
    match item.as_str() {
        Some(id) => DeckType::Named {
            id: id.to_string(),
            location,
            written,
        },
        None => DeckType::NotAString { location, written },
    }
}
