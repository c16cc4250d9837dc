//! The editable keys, close matches, the `rollbench keys` table.

use super::*;
// ---------------------------------------------------------------------------------
// Keys: the editable list, close matches, the `rollbench keys` table
// ---------------------------------------------------------------------------------

/// The editable keys inside an opaque table that its parser knows (for suggestions).
pub(super) fn opaque_keys(table: &str) -> &'static [&'static str] {
    match table {
        "thermal" => crate::deck::thermal::EDITABLE_KEYS,
        // The angular-contact ball bearing's traction table (its own parser:
        // `bearings::angular_ball::deck::traction_table`).
        "traction_table" => &["points"],
        // The cylindrical roller's contact report (`bearings::cylindrical_roller::deck::
        // contact_table`).
        "contact" => &["sliding_speed", "positions"],
        _ => &[],
    }
}

/// A `&'static str` for a key built at run time (the `materials.<body>` keys): each
/// distinct string is leaked once, so the total is bounded by the schemas' bodies.
pub(super) fn intern(s: String) -> &'static str {
    use std::collections::BTreeSet;
    use std::sync::{Mutex, OnceLock};
    static KEYS: OnceLock<Mutex<BTreeSet<&'static str>>> = OnceLock::new();
    let set = KEYS.get_or_init(|| Mutex::new(BTreeSet::new()));
    let mut set = set
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some(k) = set.get(s.as_str()) {
        return k;
    }
    let k: &'static str = Box::leak(s.into_boxed_str());
    set.insert(k);
    k
}

/// Every key [`Form::set`] and `--set` accept: `name`, each field, the material bodies
/// (a preset name or a table), and the known keys of the opaque tables (any key of an
/// opaque table is accepted and checked by its own parser).
pub fn editable_keys<T>(schema: &Schema<T>) -> Vec<&'static str> {
    let mut keys = vec!["name"];
    keys.extend(schema.fields.iter().map(|f| f.key));
    keys.extend(
        schema
            .material_bodies
            .iter()
            .map(|b| intern(format!("materials.{b}"))),
    );
    for t in schema.opaque_tables {
        keys.extend_from_slice(opaque_keys(t));
    }
    keys.dedup();
    keys
}

/// The table `rollbench keys` prints: every editable key with its allowed range in SI
/// and US units, then `name`, the material bodies and the opaque tables.
pub fn keys_table<T>(schema: &'static Schema<T>) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let _ = writeln!(s, "{:<40} {:<36} allowed (us)", "key", "allowed (si)");
    for f in schema.fields {
        let allowed = |u: Units| match f.kind {
            FieldKind::Choice(list) => list.join(" | "),
            FieldKind::RealOr(word) => format!("{} | \"{word}\"", f.allowed(u)),
            _ => f.allowed(u),
        };
        // An entry wider than its column (a long choice list, a range with its word) is
        // wrapped at its `|`s in both columns (issue 30 item 17: long lists pushed the US
        // column out); an entry that fits prints as it always has.
        if allowed(Units::Si).chars().count() <= ALLOWED_WIDTH {
            let _ = writeln!(
                s,
                "{:<40} {:<36} {}",
                f.key,
                allowed(Units::Si),
                allowed(Units::Us)
            );
            continue;
        }
        let pieces = |u: Units| -> Vec<String> {
            match f.kind {
                FieldKind::Choice(list) => list.iter().map(|c| c.to_string()).collect(),
                FieldKind::RealOr(word) => vec![f.allowed(u), format!("\"{word}\"")],
                _ => vec![f.allowed(u)],
            }
        };
        let (si, us) = (
            wrap_choices(&pieces(Units::Si), ALLOWED_WIDTH),
            wrap_choices(&pieces(Units::Us), ALLOWED_WIDTH),
        );
        for i in 0..si.len().max(us.len()) {
            let key = if i == 0 { f.key } else { "" };
            let a = si.get(i).map_or("", String::as_str);
            let b = us.get(i).map_or("", String::as_str);
            let line = format!("{key:<40} {a:<ALLOWED_WIDTH$} {b}");
            let _ = writeln!(s, "{}", line.trim_end());
        }
    }
    let _ = writeln!(s, "{:<40} any string", "name");
    let presets: Vec<&str> = MATERIAL_PRESETS.iter().map(|(n, _)| *n).collect();
    for b in schema.material_bodies {
        let _ = writeln!(
            s,
            "{:<40} one of {}",
            format!("materials.{b}"),
            presets.join(", ")
        );
    }
    for t in schema.opaque_tables {
        let example = opaque_keys(t)
            .first()
            .map_or_else(String::new, |k| format!("; e.g. {k}"));
        let _ = writeln!(
            s,
            "{:<40} the [{t}] section (see `rollbench template`){example}",
            format!("{t}.<table>.<key>")
        );
    }
    s
}

/// Width of the `allowed (si)` column of [`keys_table`].
const ALLOWED_WIDTH: usize = 36;

/// `list` joined by ` | ` in lines of at most `width` characters (a single longer choice
/// on a line of its own), each line but the last ending in ` |`.
fn wrap_choices(list: &[String], width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for (i, c) in list.iter().enumerate() {
        let last = i + 1 == list.len();
        let piece = if last {
            c.to_string()
        } else {
            format!("{c} |")
        };
        let sep = usize::from(!line.is_empty());
        if !line.is_empty() && line.chars().count() + sep + piece.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(&piece);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// Levenshtein distance of two short keys (characters).
pub(super) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev.get(j).copied().unwrap_or(0) + usize::from(ca != *cb);
            let del = prev.get(j + 1).copied().unwrap_or(0) + 1;
            let ins = cur.get(j).copied().unwrap_or(0) + 1;
            if let Some(c) = cur.get_mut(j + 1) {
                *c = sub.min(del).min(ins);
            }
        }
        prev = cur;
    }
    prev.last().copied().unwrap_or(0)
}

/// The editable keys closest to `key` (typos, a wrong table, a missing table): at most
/// five, closest first.
pub fn close_keys<T>(schema: &Schema<T>, key: &str) -> Vec<&'static str> {
    // No key is near 200 characters: a longer one is close to none (and the edit
    // distances of a 100 000-character key took seconds, issue 24 item 15).
    if key.chars().count() > 200 {
        return Vec::new();
    }
    let leaf = key.rsplit('.').next().unwrap_or(key);
    let mut scored: Vec<(usize, &'static str)> = editable_keys(schema)
        .into_iter()
        .filter_map(|k| {
            let k_leaf = k.rsplit('.').next().unwrap_or(k);
            let d = edit_distance(key, k).min(edit_distance(leaf, k_leaf) + 1);
            let limit = (key.len() / 3).clamp(2, 6);
            (d <= limit || (leaf.len() >= 4 && k_leaf.contains(leaf))).then_some((d, k))
        })
        .collect();
    scored.sort();
    scored.into_iter().take(5).map(|(_, k)| k).collect()
}

/// The message for an unknown `--set` key: the close matches and where the full list is.
pub(super) fn unknown_key_hint<T>(schema: &Schema<T>, key: &str) -> String {
    let close = close_keys(schema, key);
    // The default system's list is `rollbench keys`; another system's needs its type.
    let command = if schema.system == crate::deck::DEFAULT_TYPE {
        "rollbench keys".to_string()
    } else {
        format!("rollbench keys --type {}", schema.system)
    };
    let list = format!("`{command}` lists every editable key with its allowed range");
    if close.is_empty() {
        format!("unknown key ({list})")
    } else {
        format!("unknown key; did you mean {}? ({list})", close.join(", "))
    }
}
