//! Editing a deck in place (comments kept), reading values back, locations, saving.

use super::*;
// ---------------------------------------------------------------------------------
// Editing
// ---------------------------------------------------------------------------------

/// Writes one value into `doc` (deck units) without validating: the key must be `name`,
/// a field, a material body or inside an opaque table. A one-of key removes its
/// alternative; a property of a preset material turns the preset into an inline table of
/// the preset's values first (from `value`, in `units`).
pub(crate) fn edit<T>(
    schema: &Schema<T>,
    doc: &mut DocumentMut,
    value: &T,
    units: Units,
    key_path: &str,
    new: &str,
) -> Result<(), DeckErrors> {
    let not_editable = |reason: &str| {
        DeckErrors::from(DeckError::NotEditable {
            key: super::validate::clip(key_path),
            reason: reason.to_string(),
        })
    };
    if key_path == "units" {
        return Err(not_editable(
            "the unit system changes the meaning of every number, so it cannot be overridden: edit `units` and every value in the deck file (`rollbench template --units si|us` shows a deck in either system)",
        ));
    }
    let parts: Vec<&str> = key_path.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err(not_editable("empty key segment"));
    }
    let spec = schema.field(key_path);
    let is_body = parts.len() == 2
        && parts.first() == Some(&"materials")
        && parts
            .get(1)
            .is_some_and(|b| schema.material_bodies.contains(b));
    let is_opaque = parts.len() > 1 && parts.first().is_some_and(|t| schema.is_opaque(t));
    if !(key_path == "name" || spec.is_some() || is_body || is_opaque) {
        return Err(not_editable(&unknown_key_hint(schema, key_path)));
    }
    let wants_string = key_path == "name"
        || is_body
        || spec.is_some_and(|s| matches!(s.kind, FieldKind::Choice(l) if !is_bool(l)));
    // The two ways of giving a one-of value are exclusive: setting one removes the other.
    let exclusive_other = match spec.map(|s| s.presence) {
        Some(Presence::OneOf(other)) => Some(other),
        _ => None,
    };
    let trimmed = new.trim();
    let mut new_value = match trimmed.parse::<Value>() {
        Ok(v) if !wants_string || v.is_str() => v,
        _ => Value::from(trimmed),
    };

    // A material given as a preset name becomes an inline table before one of its
    // properties is edited.
    if parts.len() == 3 && parts.first() == Some(&"materials") {
        let body = parts.get(1).copied().unwrap_or("");
        let is_preset = doc
            .get("materials")
            .and_then(|m| m.get(body))
            .is_some_and(Item::is_str);
        if is_preset {
            let mut t = toml_edit::InlineTable::new();
            let group = format!("materials.{body}");
            for f in schema.fields.iter().filter(|f| f.group == group) {
                // 15 significant digits: hides the last-bit noise of the conversion
                let v = f.from_si(f.get_si(value), units);
                let v: f64 = fmt_real(v).parse().unwrap_or(v);
                t.insert(f.name(), Value::from(v));
            }
            if let Some(slot) = doc.get_mut("materials").and_then(|m| m.get_mut(body)) {
                let decor = slot.as_value().map(|v| v.decor().clone());
                let mut v = Value::InlineTable(t);
                if let Some(d) = decor {
                    *v.decor_mut() = d;
                }
                *slot = Item::Value(v);
            }
        }
    }
    let mut item: &mut Item = doc.as_item_mut();
    let (last, path) = match parts.split_last() {
        Some(x) => x,
        None => return Err(not_editable("empty key")),
    };
    for p in path {
        let Some(t) = item.as_table_like_mut() else {
            return Err(not_editable("a parent of this key is not a table"));
        };
        item = t.entry(p).or_insert(Item::Table(toml_edit::Table::new()));
    }
    let Some(t) = item.as_table_like_mut() else {
        return Err(not_editable("the parent of this key is not a table"));
    };
    match t.get_mut(last) {
        Some(Item::Value(old)) => {
            let mut decor = old.decor().clone();
            // A comment that shows the old value in other units ("# reyn (= 0.0045 Pa·s)")
            // would now be wrong: it is cut at its "(=" (the unit before it is kept).
            if let Some(comment) = decor.suffix().and_then(|r| r.as_str()) {
                if let Some(at) = comment.find("(=") {
                    let kept = comment[..at].trim_end().trim_end_matches([';', ',']);
                    decor.set_suffix(kept.to_string());
                }
            }
            *new_value.decor_mut() = decor;
            *old = new_value;
        }
        Some(other) => *other = Item::Value(new_value),
        None => {
            t.insert(last, Item::Value(new_value));
        }
    }
    if let Some(other) = exclusive_other {
        let mut it = other.split('.');
        if let (Some(g), Some(k)) = (it.next(), it.next()) {
            if let Some(t) = doc.get_mut(g).and_then(Item::as_table_like_mut) {
                t.remove(k);
            }
        }
    }
    Ok(())
}

/// Writes every `key=value` assignment into a copy of `doc` (see [`edit`]) and returns
/// it, not validated. `example` completes the message for a malformed assignment.
pub(crate) fn write_assignments<T>(
    schema: &Schema<T>,
    doc: &DocumentMut,
    value: &T,
    units: Units,
    assignments: &[String],
    example: &str,
) -> Result<DocumentMut, DeckErrors> {
    let mut doc = doc.clone();
    let mut pairs = Vec::with_capacity(assignments.len());
    for a in assignments {
        let Some((k, v)) = a.split_once('=') else {
            return Err(DeckError::NotEditable {
                key: a.to_string(),
                reason: format!("expected KEY=VALUE, e.g. --set {example}"),
            }
            .into());
        };
        pairs.push((k.trim(), v.trim()));
    }
    // Writing one key of a one-of pair removes the other (the editor's behaviour), so two
    // overrides naming both keys would let the last one win silently, and their order
    // would decide the deck: refuse them, as a deck holding both is refused.
    for (k, _) in &pairs {
        if let Some(Presence::OneOf(other)) = schema.field(k).map(|s| s.presence) {
            if pairs.iter().any(|(k2, _)| *k2 == other) {
                return Err(DeckError::NotEditable {
                    key: (*k).to_string(),
                    reason: format!(
                        "`{k}` and `{other}` are two ways of giving the same value (give one OR the other), and both are given by --set: keep only one of them"
                    ),
                }
                .into());
            }
        }
    }
    for (k, v) in pairs {
        edit(schema, &mut doc, value, units, k, v)?;
    }
    Ok(doc)
}

/// The value of `key_path` as written in `doc` (deck units; strings unquoted); for a
/// field not written (defaults, material presets) the value in effect, in deck units.
pub(crate) fn get<T>(
    schema: &Schema<T>,
    doc: &DocumentMut,
    value: &T,
    units: Units,
    key_path: &str,
) -> Option<String> {
    let mut item: &Item = doc.as_item();
    let mut found = true;
    for p in key_path.split('.') {
        match item.get(p) {
            Some(i) => item = i,
            None => {
                found = false;
                break;
            }
        }
    }
    if found {
        if let Some(v) = item.as_value() {
            return Some(match v.as_str() {
                Some(s) => s.to_string(),
                None => {
                    let mut v = v.clone();
                    v.decor_mut().clear();
                    v.to_string()
                }
            });
        }
    }
    let spec = schema.field(key_path)?;
    let si = spec.get_si(value);
    Some(match spec.kind {
        FieldKind::Choice(list) => list.get(si as usize).copied().unwrap_or("").to_string(),
        FieldKind::Integer => format!("{}", si.round() as i64),
        FieldKind::RealOr(word) if si.is_nan() => word.to_string(),
        FieldKind::Real | FieldKind::RealOr(_) => fmt_real(spec.from_si(si, units)),
    })
}

/// Line and column of the deepest node of `path` inside the top-level table `table`
/// found in `doc`'s text: the field's value, else its entry, else the table's header.
pub(crate) fn location_in_table(
    doc: &DocumentMut,
    source: &str,
    table: &str,
    path: &[crate::deck::thermal::PathSeg],
) -> Location {
    let text = doc.to_string();
    let Ok(doc) = toml_edit::Document::parse(text.as_str()) else {
        return Location::start(source);
    };
    // Walk items (tables, arrays of tables), their tables and values (inline tables,
    // arrays).
    #[derive(Clone, Copy)]
    enum Node<'a> {
        Item(&'a Item),
        Table(&'a toml_edit::Table),
        Value(&'a Value),
    }
    let Some(root) = doc.as_table().get(table) else {
        return Location::start(source);
    };
    let mut best = item_span(root);
    let mut node = Node::Item(root);
    for seg in path {
        use crate::deck::thermal::PathSeg::{Index, Key};
        let value = match node {
            Node::Item(Item::Value(v)) | Node::Value(v) => Some(v),
            _ => None,
        };
        let next = match (node, value, seg) {
            (Node::Item(Item::Table(t)), _, Key(k)) | (Node::Table(t), _, Key(k)) => {
                t.get(k).map(Node::Item)
            }
            (Node::Item(Item::ArrayOfTables(a)), _, Index(i)) => a.get(*i).map(Node::Table),
            (_, Some(Value::InlineTable(t)), Key(k)) => t.get(k).map(Node::Value),
            (_, Some(Value::Array(a)), Index(i)) => a.get(*i).map(Node::Value),
            _ => None,
        };
        let Some(n) = next else { break };
        let span = match n {
            Node::Item(i) => item_span(i),
            Node::Table(t) => t.span(),
            Node::Value(v) => v.span(),
        };
        if span.is_some() {
            best = span;
        }
        node = n;
    }
    let offset = best.map_or(0, |s| s.start);
    Location::at(source, &text, offset)
}

/// The thermal network of a deck's `[thermal]` table (`None` when the deck has none);
/// errors name node, link and field, at their line and column in `doc`.
pub(crate) fn thermal_model_of(
    doc: &DocumentMut,
    source: &str,
    table: Option<&toml::Table>,
    units: Units,
) -> Result<Option<crate::thermal::ThermalModel>, DeckErrors> {
    let Some(t) = table else { return Ok(None) };
    crate::deck::thermal::parse_thermal_located(t, units)
        .map(Some)
        .map_err(|e| {
            let message = match &e.error {
                crate::thermal::ThermalError::Deck { location, message } => {
                    format!("{location}: {message}")
                }
                other => other.to_string(),
            };
            DeckError::Thermal {
                location: location_in_table(doc, source, "thermal", &e.path),
                message,
            }
            .into()
        })
}

/// Saves `text` atomically (see [`crate::files::save_with_backup`]).
pub(crate) fn save_text(path: &Path, text: &str) -> Result<crate::files::Written, DeckErrors> {
    crate::files::save_with_backup(path, text).map_err(|e| {
        DeckErrors::from(DeckError::Io {
            path: e.path,
            action: e.action,
            source: e.source,
        })
    })
}
