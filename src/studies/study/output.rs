//! A study's result written out: CSV (one row per point in index order), JSON (header,
//! rows and summary) or JSONL (the header line, then one row a line: the format of a
//! shard's part, so a local run's JSONL merges like a part). The columns come from the
//! header alone, never from which points solved.

use serde_json::{Map, Value};

use super::{summary, Header, Row, StudyResult};

/// A CSV cell, quoted (RFC 4180) when it holds a comma, quote or line break.
fn csv_cell(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The input columns' headers: the key with its deck unit in brackets.
fn input_headers(h: &Header) -> Vec<String> {
    h.inputs
        .iter()
        .zip(&h.input_units)
        .map(|(k, u)| {
            if u.is_empty() {
                k.clone()
            } else {
                format!("{k} [{u}]")
            }
        })
        .collect()
}

/// CSV: `index`, the inputs (deck units), the outputs (SI, unit in the name), `failure`;
/// numbers in Rust's shortest round-trip form; empty cells where a value is absent.
pub fn csv(r: &StudyResult) -> String {
    let h = &r.header;
    let mut head = vec!["index".to_string()];
    head.extend(input_headers(h).iter().map(|c| csv_cell(c)));
    head.extend(h.outputs.iter().map(|c| csv_cell(c)));
    head.push("failure".into());
    let mut out = head.join(",");
    out.push('\n');
    for row in &r.rows {
        let mut cells = vec![row.index.to_string()];
        cells.extend(row.inputs.iter().map(|c| csv_cell(c)));
        cells.extend(
            row.outputs
                .iter()
                .map(|v| v.map_or_else(String::new, |v| format!("{v}"))),
        );
        cells.push(row.failure.as_deref().map_or_else(String::new, csv_cell));
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}

/// One JSONL line (with its newline) of a row.
pub fn row_line(row: &Row) -> String {
    let mut s = serde_json::to_string(row).unwrap_or_default();
    s.push('\n');
    s
}

/// The header line (with its newline).
pub fn header_line(h: &Header) -> String {
    let mut s = serde_json::to_string(h).unwrap_or_default();
    s.push('\n');
    s
}

/// JSONL: the header line, then one row a line in index order.
pub fn jsonl(r: &StudyResult) -> String {
    let mut out = header_line(&r.header);
    for row in &r.rows {
        out.push_str(&row_line(row));
    }
    out
}

/// JSON: `{"study": header, "rows": [{"index", "inputs": {key: text}, "outputs": {name:
/// number|null}, "failure"}], "summary": …}`.
pub fn json(r: &StudyResult) -> String {
    let h = &r.header;
    let rows: Vec<Value> = r
        .rows
        .iter()
        .map(|row| {
            let mut inputs = Map::new();
            for (k, v) in h.inputs.iter().zip(&row.inputs) {
                inputs.insert(k.clone(), Value::String(v.clone()));
            }
            let mut outputs = Map::new();
            for (k, v) in h.outputs.iter().zip(&row.outputs) {
                outputs.insert(
                    k.clone(),
                    v.and_then(serde_json::Number::from_f64)
                        .map_or(Value::Null, Value::Number),
                );
            }
            let mut m = Map::new();
            m.insert("index".into(), Value::from(row.index));
            m.insert("inputs".into(), Value::Object(inputs));
            m.insert("outputs".into(), Value::Object(outputs));
            m.insert(
                "failure".into(),
                row.failure.clone().map_or(Value::Null, Value::String),
            );
            Value::Object(m)
        })
        .collect();
    let mut m = Map::new();
    m.insert(
        "study".into(),
        serde_json::to_value(h).unwrap_or(Value::Null),
    );
    m.insert("rows".into(), Value::Array(rows));
    m.insert("summary".into(), summary::json(r));
    let mut s = serde_json::to_string_pretty(&Value::Object(m)).unwrap_or_default();
    s.push('\n');
    s
}
