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
            serde_json::to_string_pretty(&json_with_common_names(solution))
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

/// The solution's JSON with the names common to every system added beside its own
/// (issue 30 item 10; nothing renamed or dropped; `docs/outputs.md`):
/// - `speeds`: every `X_rad_s` gains `X_rpm` (the tapered `cage_rad_s` gains `cage_rpm`,
///   as the spherical and ball systems write it);
/// - each element of `rollers` / `balls`: `inner_load_n`, `outer_load_n`,
///   `inner_contact_angle_deg`, `outer_contact_angle_deg` from its `inner` / `outer`
///   object's `normal_load_n` and `contact_angle_deg` where it nests them.
pub fn json_with_common_names(solution: &dyn Solution) -> serde_json::Value {
    let mut v = solution.json();
    add_common_names(&mut v);
    v
}

fn add_common_names(v: &mut serde_json::Value) {
    use serde_json::{json, Value};
    const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;
    if let Some(speeds) = v.get_mut("speeds").and_then(Value::as_object_mut) {
        let twins: Vec<(String, Value)> = speeds
            .iter()
            .filter_map(|(k, x)| {
                let stem = k.strip_suffix("_rad_s")?;
                let rpm = format!("{stem}_rpm");
                let x = x.as_f64()?;
                (!speeds.contains_key(&rpm)).then(|| (rpm, json!(x * RPM_PER_RAD_S)))
            })
            .collect();
        speeds.extend(twins);
    }
    for array in ["rollers", "balls"] {
        let Some(elements) = v.get_mut(array).and_then(Value::as_array_mut) else {
            continue;
        };
        for e in elements.iter_mut().filter_map(Value::as_object_mut) {
            for race in ["inner", "outer"] {
                for (nested, common) in [
                    ("normal_load_n", format!("{race}_load_n")),
                    ("contact_angle_deg", format!("{race}_contact_angle_deg")),
                ] {
                    let x = e.get(race).and_then(|r| r.get(nested)).cloned();
                    if let (false, Some(x)) = (e.contains_key(&common), x) {
                        e.insert(common, x);
                    }
                }
            }
        }
    }
}
