//! Deck errors: every message names the file, line, column and key a user must fix.

use std::fmt;
use std::path::PathBuf;

/// A position in a deck source: file name, 1-based line and 1-based column (characters).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// Name of the source (file name or a label such as `<set>`).
    pub source_name: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column, counted in characters.
    pub column: usize,
}

impl Location {
    /// Location of byte offset `offset` in `text`.
    pub fn at(source_name: &str, text: &str, offset: usize) -> Location {
        let offset = offset.min(text.len());
        let before = text.get(..offset).unwrap_or(text);
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before.get(line_start..).map_or(0, |s| s.chars().count()) + 1;
        Location {
            source_name: source_name.to_string(),
            line,
            column,
        }
    }

    /// The start of the file (used when a whole required table is missing).
    pub fn start(source_name: &str) -> Location {
        Location {
            source_name: source_name.to_string(),
            line: 1,
            column: 1,
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.source_name, self.line, self.column)
    }
}

/// One problem with a deck.
#[derive(Debug, thiserror::Error)]
pub enum DeckError {
    /// Reading or writing a deck file failed.
    #[error("{}: {action}: {source}", path.display())]
    Io {
        /// File concerned.
        path: PathBuf,
        /// What was being done ("cannot read", "cannot write temporary file", ...).
        action: &'static str,
        /// The OS error.
        #[source]
        source: std::io::Error,
    },
    /// The text is not valid TOML; `message` is the toml parser's own, `snippet` its
    /// source excerpt with a caret.
    #[error("{location}: malformed TOML: {message}\n{snippet}")]
    Syntax {
        /// Where the parser stopped.
        location: Location,
        /// The parser's message.
        message: String,
        /// The offending line with an underline.
        snippet: String,
    },
    /// A key the deck format does not know.
    #[error("{location}: unknown key `{key}`{hint}")]
    UnknownKey {
        /// Where the key is.
        location: Location,
        /// Full key path.
        key: String,
        /// ", expected one of ..." or empty.
        hint: String,
    },
    /// A required key is absent.
    #[error("{location}: missing required key `{key}`{hint}")]
    Missing {
        /// The enclosing table's header, or the file start.
        location: Location,
        /// Full key path.
        key: String,
        /// Extra explanation, or empty.
        hint: String,
    },
    /// The value has the wrong TOML type (e.g. a string where a number is expected).
    #[error("{location}: {key} = {value} has the wrong type (expected {expected})")]
    WrongType {
        /// Where the value is.
        location: Location,
        /// Full key path.
        key: String,
        /// The value as written.
        value: String,
        /// What is expected.
        expected: String,
    },
    /// A number outside its allowed range (range shown in the deck's units).
    #[error("{location}: {key} = {value} is out of range (allowed {allowed})")]
    OutOfRange {
        /// Where the value is.
        location: Location,
        /// Full key path.
        key: String,
        /// The value as written.
        value: String,
        /// The allowed range, e.g. `3 ≤ value ≤ 500`.
        allowed: String,
    },
    /// A value that breaks a rule involving other keys, or a choice not in its list.
    #[error("{location}: {key} = {value}: {rule}")]
    Invalid {
        /// Where the (first involved) key's value is.
        location: Location,
        /// Full key path of the first key involved.
        key: String,
        /// The value as written.
        value: String,
        /// The rule broken, in words.
        rule: String,
    },
    /// The `[thermal]` network is invalid (the message names node, link and field).
    #[error("{location}: [thermal]: {message}")]
    Thermal {
        /// Where the offending field, node or link is (the `[thermal]` header for the
        /// network as a whole).
        location: Location,
        /// What is wrong.
        message: String,
    },
    /// A key path given to `Deck::set`/`Deck::get` that cannot be edited.
    #[error("cannot set `{key}`: {reason}")]
    NotEditable {
        /// Key path given.
        key: String,
        /// Why.
        reason: String,
    },
}

impl DeckError {
    /// The location in the deck text, when the error has one.
    pub fn location(&self) -> Option<&Location> {
        match self {
            DeckError::Syntax { location, .. }
            | DeckError::UnknownKey { location, .. }
            | DeckError::Missing { location, .. }
            | DeckError::WrongType { location, .. }
            | DeckError::OutOfRange { location, .. }
            | DeckError::Invalid { location, .. }
            | DeckError::Thermal { location, .. } => Some(location),
            DeckError::Io { .. } | DeckError::NotEditable { .. } => None,
        }
    }

    /// The key path concerned, when the error is about one key.
    pub fn key(&self) -> Option<&str> {
        match self {
            DeckError::UnknownKey { key, .. }
            | DeckError::Missing { key, .. }
            | DeckError::WrongType { key, .. }
            | DeckError::OutOfRange { key, .. }
            | DeckError::Invalid { key, .. }
            | DeckError::NotEditable { key, .. } => Some(key),
            DeckError::Io { .. } | DeckError::Syntax { .. } | DeckError::Thermal { .. } => None,
        }
    }
}

/// All problems found in one deck, in file order where they have a location.
#[derive(Debug, thiserror::Error)]
#[error("{}", join_lines(.0))]
pub struct DeckErrors(pub Vec<DeckError>);

fn join_lines(errors: &[DeckError]) -> String {
    errors
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("\n")
}

impl DeckErrors {
    /// The individual errors.
    pub fn errors(&self) -> &[DeckError] {
        &self.0
    }

    /// Number of errors.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// True when there is no error (never the case for a returned `Err`).
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl From<DeckError> for DeckErrors {
    fn from(e: DeckError) -> Self {
        DeckErrors(vec![e])
    }
}
