//! Writing decks from a [`Bearing`]: the commented template and clean regenerated files.

use std::fmt::Write as _;

use super::schema::{fields, preset_name, FieldKind, FieldSpec, Presence, MATERIAL_BODIES};
use crate::bearings::spherical_roller::{Bearing, Material};
use crate::units::{Quantity, Units};

/// Formats a real for a deck: rounded to 15 significant digits (hides last-bit noise
/// from unit conversion, 5e-16 relative), then the shortest TOML-valid representation.
pub(crate) fn fmt_real(v: f64) -> String {
    let rounded: f64 = format!("{v:.14e}").parse().unwrap_or(v);
    let s = format!("{rounded:?}");
    // Debug gives "17000.0", "1e-9", "2.5e16": all valid TOML floats.
    s
}

fn fmt_field(spec: &FieldSpec, b: &Bearing, units: Units) -> String {
    let si = spec.get_si(b);
    match spec.kind {
        FieldKind::Real => fmt_real(spec.from_si(si, units)),
        FieldKind::Integer => format!("{}", si.round() as i64),
        FieldKind::Choice(list) => {
            format!("\"{}\"", list.get(si as usize).copied().unwrap_or(""))
        }
    }
}

fn unit_comment(spec: &FieldSpec, units: Units) -> String {
    let u = spec.unit(units);
    if u.is_empty() {
        String::new()
    } else {
        format!("  # {u}")
    }
}

fn material_of<'a>(b: &'a Bearing, body: &str) -> &'a Material {
    match body {
        "roller" => &b.materials.roller,
        "inner_ring" => &b.materials.inner_ring,
        _ => &b.materials.outer_ring,
    }
}

/// Writes `b` as a deck in `units`. With `commented`, every key gets a comment line with
/// its meaning, unit and allowed range (the template); otherwise only unit comments.
pub(crate) fn write_deck(
    b: &Bearing,
    units: Units,
    thermal: Option<&toml::Table>,
    header: &str,
    commented: bool,
) -> String {
    let mut out = String::new();
    for line in header.lines() {
        let _ = writeln!(out, "# {line}");
    }
    let _ = writeln!(
        out,
        "units = \"{}\"  # \"us\" (in, lbf, psi, rpm, reyn, lbm, °F) or \"si\" (m, N, Pa, rpm, Pa·s, kg, °C)",
        units.as_str()
    );
    let name = toml_edit::Value::from(b.name.as_str()).to_string();
    let _ = writeln!(out, "name = {}", name.trim());
    let mut group = "";
    for spec in fields() {
        let top = spec.group.split('.').next().unwrap_or("");
        if top != group {
            group = top;
            let _ = writeln!(out, "\n[{group}]");
            if commented {
                match group {
                    "materials" => {
                        let _ = writeln!(
                            out,
                            "# Each body: a preset, \"steel\" or \"silicon-nitride\", or an inline table\n# {{ youngs_modulus ({}), poisson_ratio, density ({}), specific_heat ({}), conductivity ({}) }}",
                            Quantity::Pressure.unit(units),
                            Quantity::Density.unit(units),
                            Quantity::SpecificHeat.unit(units),
                            Quantity::Conductivity.unit(units)
                        );
                    }
                    "solver" => {
                        let _ = writeln!(out, "# Optional table: numerical settings.");
                    }
                    _ => {}
                }
            }
            if group == "materials" {
                for body in MATERIAL_BODIES {
                    let m = material_of(b, body);
                    match preset_name(m) {
                        Some(p) => {
                            let _ = writeln!(out, "{body} = \"{p}\"");
                        }
                        None => {
                            let parts: Vec<String> = fields()
                                .iter()
                                .filter(|f| {
                                    f.group.ends_with(body) && f.group.starts_with("materials.")
                                })
                                .map(|f| format!("{} = {}", f.name(), fmt_field(f, b, units)))
                                .collect();
                            let _ = writeln!(out, "{body} = {{ {} }}", parts.join(", "));
                        }
                    }
                }
            }
        }
        if spec.group.starts_with("materials") {
            continue;
        }
        if spec.key == "lubricant.lubricant_parameter" {
            if commented {
                let _ = writeln!(
                    out,
                    "# {}: {}. Allowed {}.\n# lubricant_parameter = {}",
                    spec.label,
                    spec.help,
                    spec.allowed(units),
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
                FieldKind::Choice(list) => format!(
                    "one of {}",
                    list.iter()
                        .map(|c| format!("\"{c}\""))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
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
    if let Some(t) = thermal {
        let mut wrapper = toml::Table::new();
        wrapper.insert("thermal".into(), toml::Value::Table(t.clone()));
        if let Ok(s) = toml::to_string(&wrapper) {
            let _ = write!(out, "\n{s}");
        }
    } else if commented {
        let _ = writeln!(
            out,
            "\n# [thermal]  # optional: lumped thermal network, interpreted by the thermal module"
        );
    }
    out
}

/// A fully commented deck in `units`: every key with its meaning, unit and allowed
/// range, filled with the aerospace example bearing. It parses back as it is.
pub fn template(units: Units) -> String {
    let mut b = Bearing::example_aerospace();
    b.name = "template (aerospace example bearing)".into();
    write_deck(
        &b,
        units,
        None,
        "rollbench deck template: every key, its unit and allowed range.\nValues are the aerospace example bearing (decks/aerospace.toml).",
        true,
    )
}
