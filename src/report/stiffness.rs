//! `rollbench stiffness`: the bearing's stiffness matrix alone, from any system whose
//! solution has one (the tapered roller's 5×5): the view's "stiffness" text block in the
//! deck's units, the JSON report's `stiffness` object (SI), or its matrix as CSV in the
//! deck's units.

use crate::bearings::Solution;
use crate::units::{Quantity, Units};

use super::Format;

/// Relative size below which a stiffness entry is round-off of the solve, not data: an
/// off-diagonal K_ij with |K_ij| < 1e-9·√(|K_ii·K_jj|) (the geometric mean of its two
/// diagonals has K_ij's unit in every block, so one threshold serves lineal, coupling and
/// angular terms). 1e-9 is the ring Newton's relative force tolerance: what lies below it
/// moves from solve to solve (the CLI and a warm-started workbench printed different
/// −4e-11 beside 1.5e7; issue 30 item 14).
pub const ROUND_OFF_REL: f64 = 1e-9;

/// `k[i][j]` for display: 0 where it is below [`ROUND_OFF_REL`] of its diagonals' scale.
/// Diagonals, and entries whose diagonals are not both positive and finite, are shown as
/// computed. JSON and CSV keep the computed values.
pub fn shown(k: impl Fn(usize, usize) -> f64, i: usize, j: usize) -> f64 {
    let v = k(i, j);
    if i == j {
        return v;
    }
    let scale = (k(i, i) * k(j, j)).abs().sqrt();
    if scale.is_finite() && scale > 0.0 && v.abs() < ROUND_OFF_REL * scale {
        0.0
    } else {
        v
    }
}

/// The note every stiffness text carries under its matrix.
pub fn round_off_note() -> String {
    format!(
        "  entries below {ROUND_OFF_REL:.0e} of sqrt(|K_ii K_jj|) are round-off and shown as 0 (JSON keeps them)"
    )
}

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
            let per = |i: usize, j: usize| -> (f64, String) {
                let (num, nu) = if i < 3 {
                    (f.factor(units), f.unit(units))
                } else {
                    (m.factor(units), m.unit(units))
                };
                if j < 3 {
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
                        c.as_f64()
                            .map_or(String::new(), |v| super::csv::csv_number(v / per(i, j).0))
                    })
                    .collect();
                s.push_str(&format!(
                    "{},{},{},{}\n",
                    name(r),
                    cells.join(","),
                    per(i, 0).1,
                    per(i, 3).1
                ));
            }
            Some(s)
        }
    }
}

#[cfg(test)]
mod round_off_tests {
    use super::*;

    /// A coupling 1e-18 of its diagonals' scale is shown as 0 (issue 30 item 14's
    /// −4.25e-11 N/m beside 1.53e7 N/m is 2.8e-18 of it); one 1e-6 of it is data and kept;
    /// diagonals are never zeroed, nor entries whose diagonal is zero (a held DOF).
    #[test]
    fn round_off_is_shown_as_zero_and_data_is_kept() {
        let m = [
            [1.5254e7, -4.2544e-11, 3.0],
            [-4.2544e-11, 2.0e7, 0.0],
            [3.0, 0.0, 0.0],
        ];
        let k = |i: usize, j: usize| m[i][j];
        assert_eq!(shown(k, 0, 1), 0.0);
        assert_eq!(shown(k, 1, 0), 0.0);
        assert_eq!(shown(k, 0, 0), 1.5254e7);
        // Row 2's diagonal is 0: nothing to compare with, shown as computed.
        assert_eq!(shown(k, 0, 2), 3.0);
        let n = [[1.0e7, 10.0], [10.0, 1.0e7]];
        assert_eq!(shown(|i, j| n[i][j], 0, 1), 10.0);
    }
}
