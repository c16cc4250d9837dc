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
    // The common names beside the system's own (issue 30 item 10).
    let t = &t.with_common_names();
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
                    (Some(v), CsvStyle::Scientific) => csv_number(v),
                },
            )
            .collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}

/// A physical value for CSV: the shortest decimal that reads back exactly (`308.2205…`,
/// `0.000127`), in scientific form only outside 10⁻⁴…10¹⁵ (`2.1e-19`), where plain
/// decimals would be long runs of zeros. Never Rust's `3.082205321440801e2` for 308.2.
pub fn csv_number(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || (1e-4..1e15).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

#[cfg(test)]
mod csv_number_tests {
    use super::csv_number;

    /// Every form reads back to the same f64 (exact round trip), and the case
    /// prints plainly.
    #[test]
    fn csv_numbers_are_plain_and_exact() {
        assert_eq!(csv_number(308.2205321440801), "308.2205321440801");
        assert_eq!(csv_number(0.0), "0");
        assert_eq!(csv_number(2.1e-19), "2.1e-19");
        for v in [
            308.2205321440801,
            -1.27e-4,
            2.5e9,
            6.02e23,
            -3.3e-12,
            1.0 / 3.0,
        ] {
            assert_eq!(csv_number(v).parse::<f64>(), Ok(v));
        }
    }
}
