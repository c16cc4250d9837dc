//! CSV report: the first table of a view (one row per rolling element), SI units in the
//! header.

use crate::bearings::view::{CsvStyle, View};

/// CSV text with a header line (the CSV columns of the view's first table that has any);
/// empty cells where a stage was not run.
pub fn to_string(view: &View) -> String {
    let Some(t) = view
        .tables
        .iter()
        .find(|t| t.columns.iter().any(|c| c.csv.is_some()))
    else {
        return String::new();
    };
    let columns: Vec<(usize, CsvStyle, &str)> = t
        .columns
        .iter()
        .enumerate()
        .filter_map(|(i, c)| c.csv.map(|style| (i, style, c.key)))
        .collect();
    let mut s = columns.iter().map(|c| c.2).collect::<Vec<_>>().join(",");
    s.push('\n');
    for row in &t.rows {
        let cells: Vec<String> = columns
            .iter()
            .map(
                |&(i, style, _)| match (row.get(i).copied().flatten(), style) {
                    (None, _) => String::new(),
                    (Some(v), CsvStyle::Integer) => format!("{}", v.round() as i64),
                    (Some(v), CsvStyle::Plain) => format!("{v}"),
                    (Some(v), CsvStyle::Scientific) => format!("{v:e}"),
                },
            )
            .collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}
