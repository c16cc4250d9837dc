//! Reports drawn from a solved bearing: JSON and text come from the bearing system
//! (`Solution::json`, `Solution::text`, each built on the system's view), CSV from the
//! system-independent [`View`] table. [`Disp`] holds the display units of a text report.

pub mod csv;
pub mod diff;
pub mod stiffness;
pub mod stiffness_export;

use crate::bearings::view::View;
use crate::bearings::Solution;
use crate::units::Units;

/// Report formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Human-readable tables in the deck's unit system.
    Text,
    /// SI, units in key names.
    Json,
    /// One row per rolling element, SI units in the header.
    Csv,
}

/// The report of `solution` in `format`; text in `units`.
pub fn render(solution: &dyn Solution, format: Format, units: Units) -> String {
    match format {
        Format::Text => solution.text(units),
        Format::Json => {
            serde_json::to_string_pretty(&solution.json())
                .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
                + "\n"
        }
        Format::Csv => csv::to_string(&solution.view()),
    }
}

/// CSV of a view (see [`csv::to_string`]).
pub fn csv_of(view: &View) -> String {
    csv::to_string(view)
}

pub use crate::units::Disp;
