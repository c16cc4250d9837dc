//! Deck text → validated [`Bearing`]: structure (unknown/missing keys, types), per-field
//! ranges from the registry, then cross-field rules. All errors are collected, each with
//! its key path, line and column.

use std::collections::HashMap;
use std::ops::Range;

use toml_edit::{Item, TableLike, Value};

use super::error::{DeckError, DeckErrors, Location};
use super::schema::{
    field, fields, format_short, material_preset, FieldKind, FieldSpec, Presence, GROUPS,
    MATERIAL_BODIES, MATERIAL_PRESETS, REQUIRED_GROUPS,
};
use crate::bearings::spherical_roller::{Bearing, LifeMethod};
use crate::units::Units;

/// The result of a successful parse.
pub(crate) struct Parsed {
    pub units: Units,
    pub bearing: Bearing,
    pub thermal: Option<toml::Table>,
}

struct Ctx<'a> {
    text: &'a str,
    source: &'a str,
    errors: Vec<DeckError>,
    /// Location and raw text of every registry field found in the file.
    seen: HashMap<&'static str, (Location, String)>,
    /// Fields that were found (or defaulted) and valid.
    valid: HashMap<&'static str, ()>,
}

impl Ctx<'_> {
    fn loc(&self, span: Option<Range<usize>>) -> Location {
        match span {
            Some(s) => Location::at(self.source, self.text, s.start),
            None => Location::start(self.source),
        }
    }
    fn raw(&self, span: Option<Range<usize>>) -> String {
        span.and_then(|s| self.text.get(s))
            .map(|s| s.trim().to_string())
            .unwrap_or_default()
    }
    /// Where `item` stands in the file and its text as written.
    fn at(&self, item: &Item) -> (Location, String) {
        let span = item_span(item);
        (self.loc(span.clone()), self.raw(span))
    }
}

fn item_span(item: &Item) -> Option<Range<usize>> {
    match item {
        Item::Value(v) => v.span(),
        Item::Table(t) => t.span(),
        Item::ArrayOfTables(a) => a.span(),
        Item::None => None,
    }
}

/// Converts a toml_edit syntax error into a [`DeckError::Syntax`].
pub(crate) fn syntax_error(e: &toml_edit::TomlError, text: &str, source: &str) -> DeckError {
    let offset = e.span().map_or(0, |s| s.start);
    let location = Location::at(source, text, offset);
    let line_text = text.lines().nth(location.line - 1).unwrap_or("");
    let snippet = format!(
        "{:>5} | {}\n      | {}^",
        location.line,
        line_text,
        " ".repeat(location.column.saturating_sub(1))
    );
    DeckError::Syntax {
        location,
        message: e.message().trim().to_string(),
        snippet,
    }
}

fn check_keys(ctx: &mut Ctx<'_>, table: &dyn TableLike, prefix: &str, allowed: &[&str]) {
    for (k, _) in table.iter() {
        if !allowed.contains(&k) {
            let span = table.key(k).and_then(|key| key.span());
            let location = ctx.loc(span);
            let hint = format!(
                " (allowed in {}: {})",
                if prefix.is_empty() {
                    "the top level"
                } else {
                    prefix
                },
                allowed.join(", ")
            );
            let key = if prefix.is_empty() {
                k.to_string()
            } else {
                format!("{prefix}.{k}")
            };
            ctx.errors.push(DeckError::UnknownKey {
                location,
                key,
                hint,
            });
        }
    }
}

fn choice_list(list: &[&str]) -> String {
    list.iter()
        .map(|s| format!("\"{s}\""))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Parses and validates deck text.
pub(crate) fn parse_text(text: &str, source: &str) -> Result<Parsed, DeckErrors> {
    let doc = toml_edit::Document::parse(text).map_err(|e| syntax_error(&e, text, source))?;
    let root = doc.as_table();
    let mut ctx = Ctx {
        text,
        source,
        errors: Vec::new(),
        seen: HashMap::new(),
        valid: HashMap::new(),
    };

    let mut top: Vec<&str> = vec!["type", "units", "name"];
    top.extend_from_slice(GROUPS);
    check_keys(&mut ctx, root, "", &top);

    // `type`: this reader reads spherical roller decks; another system's deck (or an
    // unknown system) is refused at its line, naming the known systems.
    if let Some(item) = root.get("type") {
        let id = crate::bearings::spherical_roller::SYSTEM_ID;
        if item.as_str() != Some(id) {
            let (location, value) = ctx.at(item);
            let rule = match item.as_str().and_then(crate::bearings::system) {
                Some(_) => format!("this deck reader reads \"{id}\" decks"),
                None => format!(
                    "unknown bearing system (known: {})",
                    crate::bearings::known_types()
                ),
            };
            ctx.errors.push(DeckError::Invalid {
                location,
                key: "type".into(),
                value,
                rule,
            });
        }
    }

    // units
    let units = match root.get("units") {
        None => {
            ctx.errors.push(DeckError::Missing {
                location: Location::start(source),
                key: "units".into(),
                hint: " (\"si\" or \"us\")".into(),
            });
            None
        }
        Some(item) => match item.as_str().map(str::parse::<Units>) {
            Some(Ok(u)) => Some(u),
            _ => {
                let (location, value) = ctx.at(item);
                ctx.errors.push(DeckError::Invalid {
                    location,
                    key: "units".into(),
                    value,
                    rule: "expected \"si\" or \"us\"".into(),
                });
                None
            }
        },
    };

    let mut bearing = Bearing::example_aerospace();
    bearing.name = match root.get("name") {
        None => "unnamed".into(),
        Some(item) => match item.as_str() {
            Some(s) => s.to_string(),
            None => {
                let (location, value) = ctx.at(item);
                ctx.errors.push(DeckError::WrongType {
                    location,
                    key: "name".into(),
                    value,
                    expected: "a string".into(),
                });
                String::new()
            }
        },
    };

    let Some(units) = units else {
        return Err(finish(ctx.errors));
    };

    // group tables
    let mut groups: HashMap<&str, &dyn TableLike> = HashMap::new();
    for g in GROUPS {
        let Some(item) = root.get(g) else { continue };
        match item.as_table_like() {
            Some(t) => {
                groups.insert(g, t);
                if *g == "thermal" {
                    continue;
                }
                let allowed: Vec<&str> = if *g == "materials" {
                    MATERIAL_BODIES.to_vec()
                } else {
                    fields()
                        .iter()
                        .filter(|f| f.group == *g)
                        .map(|f| f.name())
                        .collect()
                };
                check_keys(&mut ctx, t, g, &allowed);
            }
            None => {
                let (location, value) = ctx.at(item);
                ctx.errors.push(DeckError::WrongType {
                    location,
                    key: (*g).to_string(),
                    value,
                    expected: "a table".into(),
                });
            }
        }
    }
    let header = |ctx: &Ctx<'_>, g: &str| -> Location {
        let span = root.get(g).and_then(item_span);
        ctx.loc(span)
    };
    for g in REQUIRED_GROUPS {
        if root.get(g).is_none() {
            ctx.errors.push(DeckError::Missing {
                location: Location::start(source),
                key: g.to_string(),
                hint: format!(" (the [{g}] table is required)"),
            });
        }
    }

    // materials: preset names or inline tables
    let mut material_tables: HashMap<String, &dyn TableLike> = HashMap::new();
    if let Some(mats) = groups.get("materials").copied() {
        for body in MATERIAL_BODIES {
            let key = format!("materials.{body}");
            match mats.get(body) {
                None => {
                    let location = header(&ctx, "materials");
                    ctx.errors.push(DeckError::Missing {
                        location,
                        key,
                        hint: format!(
                            " (a preset: {}; or an inline table)",
                            choice_list(&MATERIAL_PRESETS.iter().map(|p| p.0).collect::<Vec<_>>())
                        ),
                    });
                }
                Some(item) => {
                    if let Some(name) = item.as_str() {
                        match material_preset(name) {
                            Some(m) => match *body {
                                "roller" => bearing.materials.roller = m,
                                "inner_ring" => bearing.materials.inner_ring = m,
                                _ => bearing.materials.outer_ring = m,
                            },
                            None => {
                                let (location, value) = ctx.at(item);
                                ctx.errors.push(DeckError::Invalid {
                                    location,
                                    key,
                                    value,
                                    rule: format!(
                                        "unknown material preset (expected one of {} or an inline table)",
                                        choice_list(
                                            &MATERIAL_PRESETS.iter().map(|p| p.0).collect::<Vec<_>>()
                                        )
                                    ),
                                });
                            }
                        }
                    } else if let Some(t) = item.as_table_like() {
                        let allowed: Vec<&str> = fields()
                            .iter()
                            .filter(|f| f.group == key)
                            .map(|f| f.name())
                            .collect();
                        check_keys(&mut ctx, t, &key, &allowed);
                        material_tables.insert(key, t);
                    } else {
                        let (location, value) = ctx.at(item);
                        ctx.errors.push(DeckError::WrongType {
                            location,
                            key,
                            value,
                            expected: "a preset name or an inline table".into(),
                        });
                    }
                }
            }
        }
    }

    // every registry field
    for spec in fields() {
        let table: Option<&dyn TableLike> = if spec.group.starts_with("materials.") {
            match material_tables.get(spec.group) {
                Some(t) => Some(*t),
                None => continue, // preset, or already reported
            }
        } else {
            match groups.get(spec.group) {
                Some(t) => Some(*t),
                None => {
                    // whole table missing: reported once above when required;
                    // optional tables take their defaults
                    if let Presence::Default(v) = spec.presence {
                        spec.set_si(&mut bearing, v);
                        ctx.valid.insert(spec.key, ());
                    }
                    continue;
                }
            }
        };
        let item = table.and_then(|t| t.get(spec.name()));
        match item {
            None => match spec.presence {
                Presence::Required => {
                    let location = header(&ctx, spec.group.split('.').next().unwrap_or(""));
                    ctx.errors.push(DeckError::Missing {
                        location,
                        key: spec.key.to_string(),
                        hint: format!(" ({}, {})", spec.help, spec.allowed(units)),
                    });
                }
                Presence::Default(v) => {
                    spec.set_si(&mut bearing, v);
                    ctx.valid.insert(spec.key, ());
                }
                Presence::OneOf(_) => {}
            },
            Some(item) => {
                let (location, raw) = ctx.at(item);
                ctx.seen.insert(spec.key, (location.clone(), raw.clone()));
                if let Some(si) = read_value(&mut ctx, spec, item, units, location, raw) {
                    spec.set_si(&mut bearing, si);
                    ctx.valid.insert(spec.key, ());
                }
            }
        }
    }

    // exactly one of pressure_viscosity / lubricant_parameter
    if groups.contains_key("lubricant") {
        let pv = ctx.seen.get("lubricant.pressure_viscosity").cloned();
        let lp = ctx.seen.get("lubricant.lubricant_parameter").cloned();
        match (pv, lp) {
            (Some(a), Some(b)) => {
                let (first, second, k2) = if a.0.line <= b.0.line {
                    (a, b, "lubricant.lubricant_parameter")
                } else {
                    (b, a, "lubricant.pressure_viscosity")
                };
                ctx.errors.push(DeckError::Invalid {
                    location: second.0,
                    key: k2.into(),
                    value: second.1,
                    rule: format!(
                        "give exactly one of lubricant.pressure_viscosity and lubricant.lubricant_parameter (the other is at line {})",
                        first.0.line
                    ),
                });
            }
            (None, None) => {
                let location = header(&ctx, "lubricant");
                ctx.errors.push(DeckError::Missing {
                    location,
                    key: "lubricant.pressure_viscosity".into(),
                    hint: " (or give lubricant.lubricant_parameter instead)".into(),
                });
            }
            _ => {}
        }
    }

    cross_checks(&mut ctx, &bearing, units);

    // thermal: opaque table
    let mut thermal = None;
    if groups.contains_key("thermal") {
        match toml::from_str::<toml::Table>(text) {
            Ok(mut t) => {
                if let Some(toml::Value::Table(th)) = t.remove("thermal") {
                    thermal = Some(th);
                }
            }
            Err(e) => {
                let location = ctx.loc(e.span());
                ctx.errors.push(DeckError::Syntax {
                    location,
                    message: e.message().trim().to_string(),
                    snippet: String::new(),
                });
            }
        }
    }

    if ctx.errors.is_empty() {
        Ok(Parsed {
            units,
            bearing,
            thermal,
        })
    } else {
        Err(finish(ctx.errors))
    }
}

fn finish(mut errors: Vec<DeckError>) -> DeckErrors {
    errors.sort_by_key(|e| {
        e.location()
            .map_or((usize::MAX, usize::MAX), |l| (l.line, l.column))
    });
    DeckErrors(errors)
}

/// Reads one field's value, checks type and range; returns the SI value.
fn read_value(
    ctx: &mut Ctx<'_>,
    spec: &FieldSpec,
    item: &Item,
    units: Units,
    location: Location,
    raw: String,
) -> Option<f64> {
    let value = item.as_value();
    let wrong = |expected: &str| DeckError::WrongType {
        location: location.clone(),
        key: spec.key.to_string(),
        value: raw.clone(),
        expected: expected.to_string(),
    };
    let si = match spec.kind {
        FieldKind::Real => match value {
            Some(Value::Float(f)) => spec.to_si(*f.value(), units),
            Some(Value::Integer(i)) => spec.to_si(*i.value() as f64, units),
            _ => {
                ctx.errors.push(wrong("a number"));
                return None;
            }
        },
        FieldKind::Integer => match value {
            Some(Value::Integer(i)) => *i.value() as f64,
            _ => {
                ctx.errors.push(wrong("an integer"));
                return None;
            }
        },
        FieldKind::Choice(list) => match value.and_then(Value::as_str) {
            Some(s) => match list.iter().position(|c| *c == s) {
                Some(i) => return Some(i as f64),
                None => {
                    ctx.errors.push(DeckError::Invalid {
                        location,
                        key: spec.key.to_string(),
                        value: raw,
                        rule: format!("expected one of {}", choice_list(list)),
                    });
                    return None;
                }
            },
            None => {
                ctx.errors
                    .push(wrong(&format!("a string, one of {}", choice_list(list))));
                return None;
            }
        },
    };
    if spec.in_range(si) {
        Some(si)
    } else {
        ctx.errors.push(DeckError::OutOfRange {
            location,
            key: spec.key.to_string(),
            value: raw,
            allowed: spec.allowed(units),
        });
        None
    }
}

/// Rules that involve more than one key. Each is checked only when all its keys are
/// individually valid; the error points at the first key named.
fn cross_checks(ctx: &mut Ctx<'_>, b: &Bearing, units: Units) {
    let g = &b.geometry;
    let show = |key: &str| -> String {
        field(key).map_or_else(String::new, |f| {
            let v = f.from_si(f.get_si(b), units);
            let unit = f.unit(units);
            if unit.is_empty() {
                format!("{key} = {}", format_short(v))
            } else {
                format!("{key} = {} {unit}", format_short(v))
            }
        })
    };
    let pi = std::f64::consts::PI;
    let rules: Vec<(&[&str], bool, String)> = vec![
        (
            &["geometry.pitch_diameter", "geometry.roller_diameter"],
            g.pitch_diameter_m > g.roller_diameter_m,
            format!("must be greater than {}", show("geometry.roller_diameter")),
        ),
        (
            &["geometry.roller_crown_radius", "geometry.roller_diameter"],
            g.roller_crown_radius_m >= g.roller_diameter_m / 2.0,
            format!(
                "must be at least half of {}",
                show("geometry.roller_diameter")
            ),
        ),
        (
            &[
                "geometry.inner_crown_radius",
                "geometry.roller_crown_radius",
            ],
            g.inner_crown_radius_m >= g.roller_crown_radius_m,
            format!("must be at least {}", show("geometry.roller_crown_radius")),
        ),
        (
            &[
                "geometry.outer_crown_radius",
                "geometry.roller_crown_radius",
            ],
            g.outer_crown_radius_m >= g.roller_crown_radius_m,
            format!("must be at least {}", show("geometry.roller_crown_radius")),
        ),
        (
            &["geometry.effective_length", "geometry.roller_length"],
            g.effective_length_m <= g.roller_length_m,
            format!("must not exceed {}", show("geometry.roller_length")),
        ),
        (
            &["geometry.effective_length", "geometry.roller_crown_radius"],
            g.effective_length_m <= 2.0 * g.roller_crown_radius_m,
            format!(
                "must not exceed twice {}",
                show("geometry.roller_crown_radius")
            ),
        ),
        (
            &[
                "geometry.roller_count",
                "geometry.roller_diameter",
                "geometry.pitch_diameter",
            ],
            (g.roller_count as f64) * g.roller_diameter_m < pi * g.pitch_diameter_m,
            format!(
                "rollers do not fit around the pitch circle: need Z·D < π·P_t with {}, {}",
                show("geometry.roller_diameter"),
                show("geometry.pitch_diameter")
            ),
        ),
        (
            &["geometry.diametral_clearance", "geometry.roller_diameter"],
            g.diametral_clearance_m.abs() < g.roller_diameter_m,
            format!(
                "|clearance| must be less than {}",
                show("geometry.roller_diameter")
            ),
        ),
        (
            &["life.method", "life.iso_fatigue_load_limit"],
            b.life.method != LifeMethod::Iso281 || b.life.iso_fatigue_load_limit_n > 0.0,
            format!(
                "method \"iso281\" needs {} > 0",
                "life.iso_fatigue_load_limit"
            ),
        ),
    ];
    for (keys, ok, rule) in rules {
        if ok || !keys.iter().all(|k| ctx.valid.contains_key(k)) {
            continue;
        }
        let Some(&key) = keys.first() else { continue };
        let (location, value) = match ctx.seen.get(key) {
            Some((l, v)) => (l.clone(), v.clone()),
            None => (Location::start(ctx.source), String::from("(default)")),
        };
        ctx.errors.push(DeckError::Invalid {
            location,
            key: key.to_string(),
            value,
            rule,
        });
    }
}
