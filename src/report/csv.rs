//! CSV report: the first table of a view (one row per rolling element), SI units in the
//! header.

use crate::bearings::view::{CsvStyle, View};

/// CSV text with a header line; empty cells where a stage was not run.
pub fn to_string(view: &View) -> String {
    let Some(t) = view.tables.first() else {
        return String::new();
    };
    let mut s = t
        .columns
        .iter()
        .map(|c| c.key)
        .collect::<Vec<_>>()
        .join(",");
    s.push('\n');
    for row in &t.rows {
        let cells: Vec<String> = t
            .columns
            .iter()
            .zip(row)
            .map(|(c, v)| match (v, c.csv) {
                (None, _) => String::new(),
                (Some(v), CsvStyle::Integer) => format!("{}", v.round() as i64),
                (Some(v), CsvStyle::Plain) => format!("{v}"),
                (Some(v), CsvStyle::Scientific) => format!("{v:e}"),
            })
            .collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}
