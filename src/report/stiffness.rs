//! `rollbench stiffness`: the bearing's stiffness matrix alone, from any system whose
//! solution has one (the tapered roller's 5×5): the view's "stiffness" text block in the
//! deck's units, the JSON report's `stiffness` object, or its matrix as CSV (SI).

use crate::bearings::Solution;
use crate::units::Units;

use super::Format;

/// The stiffness report of `solution` in `format` (text in `units`); `None` when the
/// solution has no stiffness matrix.
pub fn render(solution: &dyn Solution, format: Format, units: Units) -> Option<String> {
    let view = solution.view();
    let block = view.texts.iter().find(|t| t.title == "stiffness")?;
    match format {
        Format::Text => Some(block.lines(units).join("\n") + "\n"),
        Format::Json => {
            let json = solution.json();
            let doc = serde_json::json!({
                "type": json.get("type").cloned().unwrap_or(serde_json::Value::Null),
                "stiffness": json.get("stiffness")?.clone(),
            });
            serde_json::to_string_pretty(&doc).ok().map(|s| s + "\n")
        }
        Format::Csv => {
            let json = solution.json();
            let k = json.get("stiffness")?;
            let rows = k.get("rows")?.as_array()?;
            let cols = k.get("columns")?.as_array()?;
            let matrix = k.get("matrix")?.as_array()?;
            let name = |v: &serde_json::Value| v.as_str().unwrap_or("").to_string();
            // SI: N/m, N/rad (forces), N·m/m, N·m/rad (moments).
            let mut s = format!(
                "row,{}\n",
                cols.iter().map(name).collect::<Vec<_>>().join(",")
            );
            for (r, row) in rows.iter().zip(matrix) {
                let cells: Vec<String> = row
                    .as_array()?
                    .iter()
                    .map(|c| c.as_f64().map_or(String::new(), super::csv::csv_number))
                    .collect();
                s.push_str(&format!("{},{}\n", name(r), cells.join(",")));
            }
            Some(s)
        }
    }
}
