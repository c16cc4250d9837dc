//! Reports from an [`Analysis`]: JSON (SI, units in key names), text (SASHBEAN-like tables in
//! the deck's unit system) and CSV (one row per roller).
//!
//! The JSON field names are a contract with scripts: fields are added, never renamed.

pub mod csv;
pub mod json;
pub mod text;

/// Unit system of a human-readable report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ReportUnits {
    #[default]
    Si,
    Us,
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
}

impl Disp {
    /// The conversion set of `units`.
    pub fn of(units: ReportUnits) -> Disp {
        match units {
            ReportUnits::Si => Disp {
                len: (1e3, "mm"),
                small_len: (1e6, "µm"),
                force: (1.0, "N"),
                stress: (1e-6, "MPa"),
                moment: (1.0, "N·m"),
                power: (1.0, "W"),
            },
            ReportUnits::Us => Disp {
                len: (1.0 / 0.0254, "in"),
                small_len: (1e6 / 0.0254, "µin"),
                force: (1.0 / 4.448_221_615_260_5, "lbf"),
                stress: (1.0 / 6_894.757_293_168_361 * 1e-3, "ksi"),
                moment: (1.0 / (4.448_221_615_260_5 * 0.0254), "in·lbf"),
                power: (3.412_141_633, "Btu/hr"),
            },
        }
    }
}
