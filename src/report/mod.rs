//! Reports drawn from a solved bearing: JSON and text come from the bearing system
//! (`Solution::json`, `Solution::text`, each built on the system's view), CSV from the
//! system-independent [`View`] table. [`Disp`] holds the display units of a text report.

pub mod csv;
pub mod stiffness;

use crate::bearings::view::View;
use crate::bearings::Solution;
use crate::units::{Units, BTU_PER_HOUR_PER_WATT, INCH_LBF_N_M, INCH_M, LBF_N, LBM_KG, PSI_PA};

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

/// Display conversions for reports: (factor from SI, label).
#[derive(Debug, Clone, Copy)]
pub struct Disp {
    pub len: (f64, &'static str),
    pub small_len: (f64, &'static str),
    pub force: (f64, &'static str),
    pub stress: (f64, &'static str),
    pub moment: (f64, &'static str),
    pub power: (f64, &'static str),
    pub mass: (f64, &'static str),
}

impl Disp {
    /// The conversion set of `units`.
    pub fn of(units: Units) -> Disp {
        match units {
            Units::Si => Disp {
                len: (1e3, "mm"),
                small_len: (1e6, "µm"),
                force: (1.0, "N"),
                stress: (1e-6, "MPa"),
                moment: (1.0, "N·m"),
                power: (1.0, "W"),
                mass: (1.0, "kg"),
            },
            Units::Us => Disp {
                len: (1.0 / INCH_M, "in"),
                small_len: (1e6 / INCH_M, "µin"),
                force: (1.0 / LBF_N, "lbf"),
                stress: (1.0 / PSI_PA * 1e-3, "ksi"),
                moment: (1.0 / INCH_LBF_N_M, "in·lbf"),
                power: (BTU_PER_HOUR_PER_WATT, "Btu/hr"),
                mass: (1.0 / LBM_KG, "lbm"),
            },
        }
    }
}
