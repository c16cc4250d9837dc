//! Two designs side by side (issue 30 item 21): `rollbench diff A B` compares two solved
//! decks' bearing-level answers (the Summary pane's lines) and, when both decks are of
//! one system with as many elements, their element tables cell by cell: A's value, B's,
//! the difference Δ = B − A and Δ% = 100·Δ/|A|, all in A's deck units.
//!
//! Lines are matched by what they are — their section, their quantity's name and their
//! display unit (`Life · L10 reference · Mrev`) — so two decks of different systems are
//! compared on the lines both report (lives, static safety, max contact stress, min
//! film, cage speed, friction torque, …); the lines only one of them reports are listed
//! as such, never compared.

use crate::bearings::view::{AnswerLine, AnswerValue, Display, Table, View};
use crate::report::csv::csv_number;
use crate::units::Units;

/// One design of the comparison.
#[derive(Debug, Clone, Copy)]
pub struct Side<'a> {
    /// What the user named it (the deck's path).
    pub name: &'a str,
    /// Its bearing system's title.
    pub system: &'a str,
    /// What one rolling element is called (`ball`, `roller`).
    pub element: &'a str,
    /// Its solution's view.
    pub view: &'a View,
}

/// One compared quantity, in display units.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Section (`Life`), or the element (`ball 3`).
    pub section: String,
    /// What it is (`L10 reference`, `Qi N`).
    pub quantity: String,
    /// Its unit (empty for a pure number).
    pub unit: String,
    /// A's value (`None`: A has none: absent, not computed).
    pub a: Option<f64>,
    /// B's value.
    pub b: Option<f64>,
}

impl Row {
    /// Δ = B − A.
    pub fn delta(&self) -> Option<f64> {
        change(self.a, self.b)
    }

    /// Δ% = 100·(B − A)/|A|; 0 when both are 0, none when only A is.
    pub fn percent(&self) -> Option<f64> {
        percent_change(self.a, self.b)
    }
}

/// Δ = B − A; none when either is absent.
pub fn change(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(b? - a?)
}

/// Δ% = 100·(B − A)/|A|; 0 when both are 0, none when only A is (or either is absent).
pub fn percent_change(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    let (a, b) = (a?, b?);
    if a == 0.0 {
        (b == 0.0).then_some(0.0)
    } else {
        Some(100.0 * (b - a) / a.abs())
    }
}

/// The comparison of two solved designs.
#[derive(Debug, Clone, PartialEq)]
pub struct Diff {
    /// A's and B's names and systems.
    pub a: (String, String),
    /// B's name and system.
    pub b: (String, String),
    /// The display units (A's deck's).
    pub units: Units,
    /// The bearing-level lines both report.
    pub outputs: Vec<Row>,
    /// Lines only A reports (`Life · L10 reference h`).
    pub only_a: Vec<String>,
    /// Lines only B reports.
    pub only_b: Vec<String>,
    /// Per-element rows (`ball 3 · Qi N`), when the element tables compare; else why not.
    pub elements: Result<Vec<Row>, String>,
}

/// What a Summary line is, to match it across designs.
fn identity(l: &AnswerLine, u: Units) -> (String, String, &'static str) {
    (
        l.section.to_string(),
        l.label.to_string(),
        l.display.unit(u),
    )
}

fn number(l: &AnswerLine, u: Units) -> Option<f64> {
    match l.value {
        AnswerValue::Number(v) => Some(l.display.convert(v, u)),
        _ => None,
    }
}

fn name(l: &AnswerLine, u: Units) -> String {
    match l.display.unit(u) {
        "" => format!("{} · {}", l.section, l.label),
        unit => format!("{} · {} {unit}", l.section, l.label),
    }
}

/// Compares `a` and `b` in units `u` (A's deck's).
pub fn compare(a: Side, b: Side, u: Units) -> Diff {
    // Numbers only: a name (the largest mechanism) has no difference.
    let numeric = |l: &&AnswerLine| !matches!(l.value, AnswerValue::Name(_));
    let lines_b: Vec<&AnswerLine> = b.view.answer.iter().filter(numeric).collect();
    let mut used = vec![false; lines_b.len()];
    let mut outputs = Vec::new();
    let mut only_a = Vec::new();
    for la in a.view.answer.iter().filter(numeric) {
        let id = identity(la, u);
        let found = lines_b
            .iter()
            .enumerate()
            .find(|(j, lb)| !used[*j] && identity(lb, u) == id);
        match found {
            Some((j, lb)) => {
                used[j] = true;
                outputs.push(Row {
                    section: la.section.to_string(),
                    quantity: la.label.to_string(),
                    unit: la.display.unit(u).to_string(),
                    a: number(la, u),
                    b: number(lb, u),
                });
            }
            None => only_a.push(name(la, u)),
        }
    }
    let only_b = lines_b
        .iter()
        .zip(&used)
        .filter(|(_, taken)| !**taken)
        .map(|(l, _)| name(l, u))
        .collect();
    Diff {
        a: (a.name.to_string(), a.system.to_string()),
        b: (b.name.to_string(), b.system.to_string()),
        units: u,
        outputs,
        only_a,
        only_b,
        elements: element_rows(a, b, u),
    }
}

/// The element tables cell by cell (every column, as an export writes them), or why
/// they do not compare.
fn element_rows(a: Side, b: Side, u: Units) -> Result<Vec<Row>, String> {
    if a.view.system != b.view.system {
        return Err(format!(
            "not compared: two systems (A: {}; B: {})",
            a.system, b.system
        ));
    }
    let (Some(ta), Some(tb)) = (a.view.element_table(), b.view.element_table()) else {
        return Err("not compared: no element table".into());
    };
    tables_compare(&ta, &tb, a.element)?;
    let matched = matching_columns(&ta, &tb);
    let mut rows = Vec::new();
    for (i, (ra, rb)) in ta.rows.iter().zip(&tb.rows).enumerate() {
        for ((c, col), jb) in ta.columns.iter().enumerate().zip(&matched) {
            // The element's number and position are the row's name, not a result; a
            // column only A has (a film B's deck does not compute) is not compared.
            let Some(jb) = *jb else {
                continue;
            };
            if names_the_row(col.key) {
                continue;
            }
            let (unit, quantity) = match col.screen {
                Some(s) if !matches!(s.display, Display::Choice(_)) => {
                    (s.display.unit(u).to_string(), s.label.to_string())
                }
                _ => (String::new(), col.header_in(u)),
            };
            let cell = |r: &Vec<Option<f64>>, k: usize| {
                r.get(k).copied().flatten().map(|v| col.value_in(v, u))
            };
            rows.push(Row {
                section: format!("{} {}", a.element, crate::bearings::view::element_number(i)),
                quantity,
                unit,
                a: cell(ra, c),
                b: cell(rb, jb),
            });
        }
    }
    Ok(rows)
}

/// Whether two element tables of one system compare element by element — as many
/// `element`s — or why not (the workbench's element table says it in its title). Their
/// columns are matched by key ([`matching_columns`]): two decks of one system may
/// differ in what they compute (a film only where a lubricant is given).
pub fn tables_compare(ta: &Table, tb: &Table, element: &str) -> Result<(), String> {
    if ta.rows.len() != tb.rows.len() {
        return Err(format!(
            "not compared: A has {} {element}s, B {}",
            ta.rows.len(),
            tb.rows.len()
        ));
    }
    Ok(())
}

/// For each column of `ta`, the index of `tb`'s column holding the same quantity (the
/// same machine key); `None` where `tb` has no such column.
pub fn matching_columns(ta: &Table, tb: &Table) -> Vec<Option<usize>> {
    ta.columns
        .iter()
        .map(|c| tb.columns.iter().position(|d| d.key == c.key))
        .collect()
}

/// Whether column `key` names the row (the element's number or position) rather than
/// holding a result: never differenced.
pub fn names_the_row(key: &str) -> bool {
    matches!(key, "number" | "index")
}

fn units_name(u: Units) -> &'static str {
    match u {
        Units::Si => "SI",
        Units::Us => "US customary",
    }
}

/// A value for text: 6 significant figures, `—` when absent.
fn short(v: Option<f64>) -> String {
    v.map_or_else(|| "—".into(), crate::deck::format_short)
}

/// The comparison as text: both designs, the units, the lines both report with A, B, Δ
/// and Δ%, the lines only one reports, and per element column the largest change.
pub fn to_text(d: &Diff) -> String {
    let mut s = format!(
        "A: {} ({})\nB: {} ({})\nvalues in A's deck units ({}); Δ = B − A, Δ% = 100·Δ/|A|\n\n",
        d.a.0,
        d.a.1,
        d.b.0,
        d.b.1,
        units_name(d.units)
    );
    let cells: Vec<[String; 6]> = d
        .outputs
        .iter()
        .map(|r| {
            [
                format!("{} · {}", r.section, r.quantity),
                r.unit.clone(),
                short(r.a),
                short(r.b),
                r.delta()
                    .map_or("—".into(), |x| format!("{:+}", Shortened(x))),
                r.percent().map_or("—".into(), |p| format!("{p:+.2}%")),
            ]
        })
        .collect();
    let head = ["output", "unit", "A", "B", "Δ", "Δ%"].map(String::from);
    let widths: Vec<usize> = (0..6)
        .map(|k| {
            cells
                .iter()
                .chain(std::iter::once(&head))
                .map(|c| c[k].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |c: &[String; 6]| {
        let mut l = String::new();
        for (k, cell) in c.iter().enumerate() {
            let pad = widths[k].saturating_sub(cell.chars().count());
            if k < 2 {
                l.push_str(cell);
                l.push_str(&" ".repeat(pad + 2));
            } else {
                l.push_str(&" ".repeat(pad));
                l.push_str(cell);
                l.push_str("  ");
            }
        }
        l.trim_end().to_string() + "\n"
    };
    s.push_str(&line(&head));
    for c in &cells {
        s.push_str(&line(c));
    }
    if !d.only_a.is_empty() || !d.only_b.is_empty() {
        s.push_str("\nnot compared (one design only):\n");
        for n in &d.only_a {
            s.push_str(&format!("  A only: {n}\n"));
        }
        for n in &d.only_b {
            s.push_str(&format!("  B only: {n}\n"));
        }
    }
    match &d.elements {
        Err(why) => s.push_str(&format!("\nper-element tables: {why}\n")),
        Ok(rows) => s.push_str(&element_text(rows)),
    }
    s
}

/// Per element column the largest change, where it is and from what to what; the columns no
/// cell of which changed are named on one line (a zero "largest change at roller 37" would
/// point at an arbitrary element), and two identical tables say so in one line.
fn element_text(rows: &[Row]) -> String {
    let mut columns: Vec<(String, String)> = Vec::new();
    let mut elements: Vec<&str> = Vec::new();
    for r in rows {
        if !columns.iter().any(|(q, _)| *q == r.quantity) {
            columns.push((r.quantity.clone(), r.unit.clone()));
        }
        if !elements.contains(&r.section.as_str()) {
            elements.push(&r.section);
        }
    }
    let mut changed = String::new();
    let mut unchanged: Vec<String> = Vec::new();
    for (q, unit) in &columns {
        let head = if unit.is_empty() {
            q.clone()
        } else {
            format!("{q} {unit}")
        };
        let worst = rows
            .iter()
            .filter(|r| r.quantity == *q)
            .filter_map(|r| r.delta().map(|x| (x, r)))
            .max_by(|x, y| x.0.abs().total_cmp(&y.0.abs()));
        match worst {
            Some((0.0, _)) => unchanged.push(head),
            Some((x, r)) => changed.push_str(&format!(
                "  {head}: {} at {} ({} → {}{})\n",
                format_args!("{:+}", Shortened(x)),
                r.section,
                short(r.a),
                short(r.b),
                r.percent().map_or(String::new(), |p| format!(", {p:+.2}%")),
            )),
            None => changed.push_str(&format!("  {head}: —\n")),
        }
    }
    if changed.is_empty() {
        return format!(
            "\nper-element tables: every cell is identical ({} columns, {} elements)\n",
            columns.len(),
            elements.len()
        );
    }
    let mut s = String::from(
        "\nper-element tables: the largest change of each column (every cell: --format csv or json)\n",
    );
    s.push_str(&changed);
    if !unchanged.is_empty() {
        s.push_str(&format!(
            "  unchanged in every element: {}\n",
            unchanged.join(", ")
        ));
    }
    s
}

/// A signed number at 6 significant figures (`{:+}`), as [`crate::deck::format_short`].
struct Shortened(f64);

impl std::fmt::Display for Shortened {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = crate::deck::format_short(self.0);
        if f.sign_plus() && self.0 >= 0.0 {
            write!(f, "+{t}")
        } else {
            write!(f, "{t}")
        }
    }
}

fn json_row(r: &Row) -> serde_json::Value {
    let num = |v: Option<f64>| {
        v.filter(|x| x.is_finite())
            .map_or(serde_json::Value::Null, serde_json::Value::from)
    };
    serde_json::json!({
        "section": r.section,
        "quantity": r.quantity,
        "unit": r.unit,
        "a": num(r.a),
        "b": num(r.b),
        "delta": num(r.delta()),
        "delta_percent": num(r.percent()),
    })
}

/// The comparison as JSON: `units` (A's deck's, every value in it), `a` and `b` (name,
/// system), `outputs` and `elements` (each row: section, quantity, unit, a, b, delta,
/// delta_percent; null where absent), `only_in_a`, `only_in_b`, and `elements_note` when
/// the element tables do not compare.
pub fn to_json(d: &Diff) -> serde_json::Value {
    let units = match d.units {
        Units::Si => "si",
        Units::Us => "us",
    };
    let mut v = serde_json::json!({
        "units": units,
        "a": {"deck": d.a.0, "system": d.a.1},
        "b": {"deck": d.b.0, "system": d.b.1},
        "outputs": d.outputs.iter().map(json_row).collect::<Vec<_>>(),
        "only_in_a": d.only_a,
        "only_in_b": d.only_b,
    });
    match &d.elements {
        Ok(rows) => v["elements"] = rows.iter().map(json_row).collect::<Vec<_>>().into(),
        Err(why) => {
            v["elements"] = serde_json::Value::Array(Vec::new());
            v["elements_note"] = why.clone().into();
        }
    }
    v
}

/// The comparison as CSV, one row per compared quantity (the bearing-level lines, then
/// every element cell): `section,quantity,unit,a,b,delta,delta_percent`, in A's deck
/// units; empty cells where a value is absent.
pub fn to_csv(d: &Diff) -> String {
    let mut s = String::from("section,quantity,unit,a,b,delta,delta_percent\n");
    let field = |t: &str| {
        if t.contains([',', '"', '\n']) {
            format!("\"{}\"", t.replace('"', "\"\""))
        } else {
            t.to_string()
        }
    };
    let num = |v: Option<f64>| {
        v.filter(|x| x.is_finite())
            .map_or(String::new(), csv_number)
    };
    let elements = d.elements.as_deref().unwrap_or(&[]);
    for r in d.outputs.iter().chain(elements) {
        s.push_str(&format!(
            "{},{},{},{},{},{},{}\n",
            field(&r.section),
            field(&r.quantity),
            field(&r.unit),
            num(r.a),
            num(r.b),
            num(r.delta()),
            num(r.percent())
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::Row;

    fn row(a: Option<f64>, b: Option<f64>) -> Row {
        Row {
            section: "S".into(),
            quantity: "q".into(),
            unit: String::new(),
            a,
            b,
        }
    }

    /// Δ = B − A; Δ% against |A| (a negative A that grows toward 0 is an increase); 0 % when
    /// both are 0, none when only A is 0 or either is absent.
    #[test]
    fn deltas_and_percentages() {
        let r = row(Some(200.0), Some(150.0));
        assert_eq!(r.delta(), Some(-50.0));
        assert_eq!(r.percent(), Some(-25.0));
        assert_eq!(row(Some(-4.0), Some(-2.0)).percent(), Some(50.0));
        assert_eq!(row(Some(0.0), Some(0.0)).percent(), Some(0.0));
        assert_eq!(row(Some(0.0), Some(1.0)).percent(), None);
        assert_eq!(row(None, Some(1.0)).delta(), None);
    }

    fn cell(element: &str, q: &str, a: f64, b: f64) -> Row {
        Row {
            section: element.into(),
            quantity: q.into(),
            unit: "N".into(),
            a: Some(a),
            b: Some(b),
        }
    }

    /// A column whose every cell is equal has no "largest change at" an element: it is
    /// named among the unchanged; two identical tables are one line.
    #[test]
    fn unchanged_columns_name_no_element() {
        let same = [
            cell("roller 1", "Q", 10.0, 10.0),
            cell("roller 2", "Q", 20.0, 20.0),
            cell("roller 1", "W", 1.0, 1.0),
            cell("roller 2", "W", 2.0, 2.0),
        ];
        assert_eq!(
            super::element_text(&same),
            "\nper-element tables: every cell is identical (2 columns, 2 elements)\n"
        );
        let mut moved = same.to_vec();
        moved[1].b = Some(21.0);
        let text = super::element_text(&moved);
        assert!(
            text.contains("  Q N: +1 at roller 2 (20 → 21, +5.00%)\n"),
            "{text}"
        );
        assert!(
            text.contains("  unchanged in every element: W N\n"),
            "{text}"
        );
        assert!(!text.contains("W N: +0"), "{text}");
    }
}
