//! Writing decks: templates, clean decks from a value, converted decks.

use super::*;
// ---------------------------------------------------------------------------------
// Writing decks
// ---------------------------------------------------------------------------------

/// Comment lines of a template beyond the field lines.
#[derive(Debug, Clone, Copy, Default)]
pub struct TemplateNotes {
    /// The deck's `name` in the template (`"template"` when empty).
    pub name: &'static str,
    /// `(table, comment)`: a comment line under a table's header (the default for an
    /// optional table: `Optional table.`).
    pub group_notes: &'static [(&'static str, &'static str)],
    /// `(opaque table, comment)`: the comment line standing for an absent opaque table.
    pub opaque_notes: &'static [(&'static str, &'static str)],
}

impl TemplateNotes {
    /// No notes (a `const` [`Default`]).
    pub const NONE: TemplateNotes = TemplateNotes {
        name: "",
        group_notes: &[],
        opaque_notes: &[],
    };
}

pub(super) fn fmt_field<T>(spec: &FieldSpec<T>, v: &T, units: Units) -> String {
    let si = spec.get_si(v);
    match spec.kind {
        FieldKind::Real => fmt_real(spec.from_si(si, units)),
        FieldKind::RealOr(word) if si.is_nan() => format!("\"{word}\""),
        FieldKind::RealOr(_) => fmt_real(spec.from_si(si, units)),
        FieldKind::Integer => format!("{}", si.round() as i64),
        FieldKind::Choice(list) if is_bool(list) => list
            .get(si as usize)
            .copied()
            .unwrap_or("false")
            .to_string(),
        FieldKind::Choice(list) => {
            format!("\"{}\"", list.get(si as usize).copied().unwrap_or(""))
        }
    }
}

pub(super) fn unit_comment(spec: &FieldMeta, units: Units) -> String {
    let u = spec.unit(units);
    if u.is_empty() {
        String::new()
    } else {
        format!("  # {u}")
    }
}

/// True for the second key (in field order) of a one-of pair: written commented out.
pub(super) fn is_second_of_pair<T>(schema: &Schema<T>, index: usize) -> bool {
    match schema.fields.get(index).map(|f| f.presence) {
        Some(Presence::OneOf(other)) => schema
            .fields
            .iter()
            .position(|f| f.key == other)
            .is_some_and(|j| j < index),
        _ => false,
    }
}

/// What [`write_deck`] writes.
pub(crate) struct DeckText<'a, T> {
    pub value: &'a T,
    pub units: Units,
    pub name: &'a str,
    pub opaque: &'a BTreeMap<String, toml::Table>,
    pub header: &'a str,
    /// The template: every key with a comment line (meaning, unit, allowed range).
    pub commented: bool,
    pub notes: &'a TemplateNotes,
}

/// Writes a deck of `schema`. With `commented`, every key gets a comment line with its
/// meaning, unit and allowed range (the template); otherwise only unit comments. The
/// `type` line is written in the template and in every deck of a system other than
/// [`crate::deck::DEFAULT_TYPE`].
pub(crate) fn write_deck<T>(schema: &Schema<T>, d: &DeckText<'_, T>) -> String {
    use std::fmt::Write as _;
    let (b, units, commented) = (d.value, d.units, d.commented);
    let mut out = String::new();
    for line in d.header.lines() {
        let _ = writeln!(out, "# {line}");
    }
    if commented {
        let _ = writeln!(
            out,
            "type = \"{}\"  # the bearing system this deck describes",
            schema.system
        );
    } else if schema.system != crate::deck::DEFAULT_TYPE {
        let _ = writeln!(out, "type = \"{}\"", schema.system);
    }
    let _ = writeln!(
        out,
        "units = \"{}\"  # \"us\" (in, lbf, psi, rpm, reyn, lbm, °F) or \"si\" (m, N, Pa, rpm, Pa·s, kg, °C)",
        units.as_str()
    );
    let name = toml_edit::Value::from(d.name).to_string();
    let _ = writeln!(out, "name = {}", name.trim());
    for group in schema.groups {
        if schema.is_opaque(group) {
            continue;
        }
        let _ = writeln!(out, "\n[{group}]");
        let is_materials = *group == "materials" && !schema.material_bodies.is_empty();
        if commented {
            let note = d.notes.group_notes.iter().find(|(g, _)| g == group);
            if let Some((_, n)) = note {
                let _ = writeln!(out, "# {n}");
            } else if is_materials {
                let presets: Vec<String> = MATERIAL_PRESETS
                    .iter()
                    .map(|(n, _)| format!("\"{n}\""))
                    .collect();
                let presets = match presets.split_last() {
                    Some((last, [])) => last.clone(),
                    Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
                    None => String::new(),
                };
                let first = schema
                    .material_bodies
                    .first()
                    .map(|b| format!("materials.{b}"))
                    .unwrap_or_default();
                let props: Vec<String> = schema
                    .fields
                    .iter()
                    .filter(|f| f.group == first)
                    .map(|f| match f.unit(units) {
                        "" => f.name().to_string(),
                        u => format!("{} ({u})", f.name()),
                    })
                    .collect();
                if props.is_empty() {
                    let _ = writeln!(out, "# Each body: a preset, {presets}");
                } else {
                    let _ = writeln!(
                        out,
                        "# Each body: a preset, {presets}, or an inline table\n# {{ {} }}",
                        props.join(", ")
                    );
                }
            } else if !schema.required_groups.contains(group) {
                let _ = writeln!(out, "# Optional table.");
            }
        }
        if is_materials {
            for (i, body) in schema.material_bodies.iter().enumerate() {
                let preset = schema.material.and_then(|m| preset_name(&(m.get)(b, i)));
                match preset {
                    Some(p) => {
                        let _ = writeln!(out, "{body} = \"{p}\"");
                    }
                    None => {
                        let group = format!("materials.{body}");
                        let parts: Vec<String> = schema
                            .fields
                            .iter()
                            .filter(|f| f.group == group)
                            .map(|f| format!("{} = {}", f.name(), fmt_field(f, b, units)))
                            .collect();
                        let _ = writeln!(out, "{body} = {{ {} }}", parts.join(", "));
                    }
                }
            }
        }
        for (i, spec) in schema.fields.iter().enumerate() {
            if spec.group != *group {
                continue;
            }
            if is_second_of_pair(schema, i) {
                if commented {
                    let _ = writeln!(
                        out,
                        "# {}: {}. Allowed {}.\n# {} = {}",
                        spec.label,
                        spec.help,
                        spec.allowed(units),
                        spec.name(),
                        fmt_field(spec, b, units)
                    );
                }
                continue;
            }
            if commented {
                let optional = match spec.presence {
                    Presence::Default(_) => " Optional.",
                    _ => "",
                };
                let range = match spec.kind {
                    FieldKind::Choice(list) => format!("one of {}", choice_list(list)),
                    FieldKind::RealOr(word) => format!("{} or \"{word}\"", spec.allowed(units)),
                    _ => spec.allowed(units),
                };
                let _ = writeln!(
                    out,
                    "# {}: {}. Allowed {}.{}",
                    spec.label, spec.help, range, optional
                );
            }
            let _ = writeln!(
                out,
                "{} = {}{}",
                spec.name(),
                fmt_field(spec, b, units),
                unit_comment(spec, units)
            );
        }
    }
    for t in schema.opaque_tables {
        if let Some(table) = d.opaque.get(*t) {
            let mut wrapper = toml::Table::new();
            wrapper.insert((*t).to_string(), toml::Value::Table(table.clone()));
            if let Ok(s) = toml::to_string(&wrapper) {
                let _ = write!(out, "\n{s}");
            }
        } else if commented {
            match d.notes.opaque_notes.iter().find(|(n, _)| n == t) {
                Some((_, note)) => {
                    let _ = writeln!(out, "\n# {note}");
                }
                None => {
                    let _ = writeln!(out, "\n# [{t}]  # optional table, read by its own parser");
                }
            }
        }
    }
    out
}

/// A fully commented deck of `schema` in `units`: every key with its meaning, unit and
/// allowed range, filled with [`Schema::defaults`]. It parses back as it is.
pub fn template<T>(schema: &'static Schema<T>, units: Units) -> String {
    template_with(schema, units, &schema.template_notes)
}

/// [`template`] with extra comment lines and the template's `name`.
pub fn template_with<T>(schema: &'static Schema<T>, units: Units, notes: &TemplateNotes) -> String {
    let value = (schema.defaults)();
    let name = if notes.name.is_empty() {
        "template"
    } else {
        notes.name
    };
    write_deck(
        schema,
        &DeckText {
            value: &value,
            units,
            name,
            opaque: &BTreeMap::new(),
            header: schema.template_header,
            commented: true,
            notes,
        },
    )
}

/// A clean deck of `value` in `units` (unit comments only, no opaque tables). Parsing it
/// gives back the same value to round-off (about 1e-15 relative).
pub fn write_value<T>(schema: &'static Schema<T>, value: &T, name: &str, units: Units) -> String {
    write_deck(
        schema,
        &DeckText {
            value,
            units,
            name,
            opaque: &BTreeMap::new(),
            header: name,
            commented: false,
            notes: &TemplateNotes::default(),
        },
    )
}

/// The header of a converted deck.
pub(crate) fn converted_header(name: &str, from: Units) -> String {
    format!(
        "{name}\nConverted by rollbench from a deck in {} units.",
        from.as_str()
    )
}
