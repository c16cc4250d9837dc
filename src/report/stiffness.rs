//! `rollbench stiffness`: the bearing's stiffness matrix alone, from any system whose
//! solution has one (the tapered roller's 5×5): the view's "stiffness" text block in the
//! deck's units, the JSON report's `stiffness` object (SI), or its matrix as CSV in the
//! deck's units.

use crate::bearings::Solution;
use crate::units::{Quantity, Units};

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
            // In the deck's units (issue 17: "Text and CSV in the deck's units"): rows of
            // forces then moments, columns of displacements then rotations; each row
            // says its units (lineal columns, angular columns).
            let (f, l, m) = (Quantity::Force, Quantity::Length, Quantity::Moment);
            // A row or column is angular by its name (M_x, theta_y), so matrices over any
            // subset of the DOFs (the cylindrical roller's x, y) get their units right.
            let angular = |names: &[serde_json::Value], i: usize| {
                names
                    .get(i)
                    .and_then(|v| v.as_str())
                    .is_some_and(|n| n.starts_with("M_") || n.starts_with("theta"))
            };
            let per = |i: usize, angular_column: bool| -> (f64, String) {
                let (num, nu) = if !angular(rows, i) {
                    (f.factor(units), f.unit(units))
                } else {
                    (m.factor(units), m.unit(units))
                };
                if !angular_column {
                    (num / l.factor(units), format!("{nu}/{}", l.unit(units)))
                } else {
                    (num, format!("{nu}/rad"))
                }
            };
            let mut s = format!(
                "row,{},unit_lineal,unit_angular\n",
                cols.iter().map(name).collect::<Vec<_>>().join(",")
            );
            for (i, (r, row)) in rows.iter().zip(matrix).enumerate() {
                let cells: Vec<String> = row
                    .as_array()?
                    .iter()
                    .enumerate()
                    .map(|(j, c)| {
                        c.as_f64().map_or(String::new(), |v| {
                            super::csv::csv_number(v / per(i, angular(cols, j)).0)
                        })
                    })
                    .collect();
                s.push_str(&format!(
                    "{},{},{},{}\n",
                    name(r),
                    cells.join(","),
                    per(i, false).1,
                    per(i, true).1
                ));
            }
            Some(s)
        }
    }
}
