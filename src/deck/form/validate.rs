//! Deck text → validated value: structure, per-field ranges, presets, cross checks.

use super::*;
// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------

/// The result of a successful validation.
pub(crate) struct Parsed<T> {
    pub units: Units,
    pub value: T,
    pub name: String,
    pub opaque: BTreeMap<String, toml::Table>,
}

pub(super) struct Ctx<'a> {
    text: &'a str,
    source: &'a str,
    errors: Vec<DeckError>,
    /// Location and raw text of every field found in the file.
    seen: HashMap<&'static str, (Location, String)>,
    /// Fields that were found (or defaulted, or given by a preset) and valid.
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
            .map(|s| clip(s.trim()))
            .unwrap_or_default()
    }
    /// Where `item` stands in the file and its text as written.
    fn at(&self, item: &Item) -> (Location, String) {
        let span = item_span(item);
        (self.loc(span.clone()), self.raw(span))
    }
}

pub(super) fn item_span(item: &Item) -> Option<Range<usize>> {
    match item {
        Item::Value(v) => v.span(),
        Item::Table(t) => t.span(),
        Item::ArrayOfTables(a) => a.span(),
        Item::None => None,
    }
}

/// Longest value echoed whole in a message, in characters.
const MAX_ECHO: usize = 120;

/// `text` as a message echoes it: whole up to [`MAX_ECHO`] characters, else its start, an
/// ellipsis and its length (a 200 KB value is not printed back whole).
pub(crate) fn clip(text: &str) -> String {
    let n = text.chars().count();
    if n <= MAX_ECHO {
        return text.to_string();
    }
    let head: String = text.chars().take(MAX_ECHO - 40).collect();
    format!("{head}… ({n} characters)")
}

/// Converts a toml_edit syntax error into a [`DeckError::Syntax`].
pub(crate) fn syntax_error(e: &toml_edit::TomlError, text: &str, source: &str) -> DeckError {
    let offset = e.span().map_or(0, |s| s.start);
    let location = Location::at(source, text, offset);
    let line_text = text.lines().nth(location.line - 1).unwrap_or("");
    // A long line is shown as a window around the column (a 200 KB line is not echoed).
    let chars: Vec<char> = line_text.chars().collect();
    let col = location.column.saturating_sub(1).min(chars.len());
    let (from, to) = if chars.len() <= MAX_ECHO {
        (0, chars.len())
    } else {
        let from = col.saturating_sub(MAX_ECHO / 2);
        (from, (from + MAX_ECHO).min(chars.len()))
    };
    let mut shown: String = chars[from..to].iter().collect();
    let mut caret = col - from;
    if from > 0 {
        shown.insert(0, '…');
        caret += 1;
    }
    if to < chars.len() {
        shown.push_str(&format!("… (line of {} characters)", chars.len()));
    }
    let snippet = format!(
        "{:>5} | {}\n      | {}^",
        location.line,
        shown,
        " ".repeat(caret)
    );
    DeckError::Syntax {
        location,
        message: e.message().trim().to_string(),
        snippet,
    }
}

pub(super) fn check_keys(ctx: &mut Ctx<'_>, table: &dyn TableLike, prefix: &str, allowed: &[&str]) {
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

pub(super) fn choice_list(list: &[&str]) -> String {
    list.iter()
        .map(|s| format!("\"{s}\""))
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn preset_list() -> String {
    choice_list(&MATERIAL_PRESETS.iter().map(|p| p.0).collect::<Vec<_>>())
}

/// True if `text` names `key` as a whole key (not as the prefix of a longer key).
pub(super) fn names_key(text: &str, key: &str) -> bool {
    let is_key_char = |c: char| c.is_alphanumeric() || c == '_' || c == '.';
    let mut rest = text;
    while let Some(i) = rest.find(key) {
        let before = rest.get(..i).and_then(|s| s.chars().next_back());
        let after = rest.get(i + key.len()..).and_then(|s| s.chars().next());
        let after_ok = match after {
            None => true,
            // a sentence-ending dot is not part of a key
            Some('.') => rest
                .get(i + key.len() + 1..)
                .and_then(|s| s.chars().next())
                .is_none_or(|c| !is_key_char(c)),
            Some(c) => !is_key_char(c),
        };
        if before.is_none_or(|c| !is_key_char(c)) && after_ok {
            return true;
        }
        rest = rest.get(i + key.len()..).unwrap_or("");
    }
    false
}

/// Parses and validates deck text against `schema`. All errors found are returned
/// together, in file order.
pub(crate) fn validate<T>(
    text: &str,
    source: &str,
    schema: &Schema<T>,
) -> Result<Parsed<T>, DeckErrors> {
    let doc = toml_edit::Document::parse(text).map_err(|e| syntax_error(&e, text, source))?;
    let root = doc.as_table();
    let mut ctx = Ctx {
        text,
        source,
        errors: Vec::new(),
        seen: HashMap::new(),
        valid: HashMap::new(),
    };
    let all_groups = schema.all_groups();

    let mut top: Vec<&str> = vec!["type", "units", "name"];
    top.extend_from_slice(&all_groups);
    check_keys(&mut ctx, root, "", &top);

    // `type`: this schema's decks only; another system's deck is refused at its line.
    // (Which systems exist is the registry's business, `crate::bearings`: a deck read
    // through it reaches this reader only when its `type` names this schema's system,
    // and an unknown `type` is refused there, naming the known ones.)
    let id = schema.system;
    match root.get("type") {
        Some(item) if item.as_str() != Some(id) => {
            let (location, value) = ctx.at(item);
            ctx.errors.push(DeckError::Invalid {
                location,
                key: "type".into(),
                value,
                rule: format!("this deck reader reads \"{id}\" decks"),
            });
        }
        None if id != crate::deck::DEFAULT_TYPE => {
            ctx.errors.push(DeckError::Missing {
                location: Location::start(source),
                key: "type".into(),
                hint: format!(
                    " (a deck without `type` is a \"{}\" deck; write type = \"{id}\")",
                    crate::deck::DEFAULT_TYPE
                ),
            });
        }
        _ => {}
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

    let mut value = (schema.defaults)();
    let name = match root.get("name") {
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
    for g in &all_groups {
        let Some(item) = root.get(g) else { continue };
        match item.as_table_like() {
            Some(t) => {
                groups.insert(g, t);
                if schema.is_opaque(g) {
                    continue;
                }
                let allowed: Vec<&str> = if *g == "materials" && !schema.material_bodies.is_empty()
                {
                    schema.material_bodies.to_vec()
                } else {
                    schema
                        .fields
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
    for g in schema.required_groups {
        if root.get(g).is_none() {
            ctx.errors.push(DeckError::Missing {
                location: Location::start(source),
                key: g.to_string(),
                hint: format!(" (the [{g}] table is required)"),
            });
        }
    }

    // materials: preset names or tables
    let mut material_tables: HashMap<String, &dyn TableLike> = HashMap::new();
    let mut preset_bodies: Vec<String> = Vec::new();
    if let Some(mats) = groups.get("materials").copied() {
        for (index, body) in schema.material_bodies.iter().enumerate() {
            let key = format!("materials.{body}");
            match mats.get(body) {
                None => {
                    let location = header(&ctx, "materials");
                    ctx.errors.push(DeckError::Missing {
                        location,
                        key,
                        hint: format!(" (a preset: {}; or an inline table)", preset_list()),
                    });
                }
                Some(item) => {
                    if let Some(name) = item.as_str() {
                        match (material_preset(name), schema.material) {
                            (Some(m), Some(access)) => {
                                (access.set)(&mut value, index, m);
                                preset_bodies.push(key);
                            }
                            (preset, access) => {
                                let (location, v) = ctx.at(item);
                                let rule = if preset.is_some() && access.is_none() {
                                    "this deck takes an inline table of the material's properties here, not a preset".to_string()
                                } else {
                                    format!(
                                        "unknown material preset (expected one of {} or an inline table)",
                                        preset_list()
                                    )
                                };
                                ctx.errors.push(DeckError::Invalid {
                                    location,
                                    key,
                                    value: v,
                                    rule,
                                });
                            }
                        }
                    } else if let Some(t) = item.as_table_like() {
                        let allowed: Vec<&str> = schema
                            .fields
                            .iter()
                            .filter(|f| f.group == key)
                            .map(|f| f.name())
                            .collect();
                        check_keys(&mut ctx, t, &key, &allowed);
                        material_tables.insert(key, t);
                    } else {
                        let (location, v) = ctx.at(item);
                        ctx.errors.push(DeckError::WrongType {
                            location,
                            key,
                            value: v,
                            expected: "a preset name or an inline table".into(),
                        });
                    }
                }
            }
        }
    }

    // every field
    for spec in schema.fields {
        let table: &dyn TableLike = if spec.group.starts_with("materials.") {
            match material_tables.get(spec.group) {
                Some(t) => *t,
                None => {
                    // a preset gives every property; otherwise already reported
                    if preset_bodies.iter().any(|b| b == spec.group) {
                        ctx.valid.insert(spec.key, ());
                    }
                    continue;
                }
            }
        } else {
            match groups.get(spec.group) {
                Some(t) => *t,
                None => {
                    // whole table missing: reported once above when required;
                    // optional tables take their defaults
                    if let Presence::Default(v) = spec.presence {
                        spec.set_si(&mut value, v);
                        ctx.valid.insert(spec.key, ());
                    }
                    continue;
                }
            }
        };
        match table.get(spec.name()) {
            None => match spec.presence {
                Presence::Required => {
                    let location = header(&ctx, spec.top_group());
                    ctx.errors.push(DeckError::Missing {
                        location,
                        key: spec.key.to_string(),
                        hint: format!(" ({}, {})", spec.help, spec.allowed(units)),
                    });
                }
                Presence::Default(v) => {
                    spec.set_si(&mut value, v);
                    ctx.valid.insert(spec.key, ());
                }
                Presence::OneOf(_) => {}
            },
            Some(item) => {
                let (location, raw) = ctx.at(item);
                ctx.seen.insert(spec.key, (location.clone(), raw.clone()));
                if let Some(si) = read_value(&mut ctx, &spec.meta, item, units, location, raw) {
                    spec.set_si(&mut value, si);
                    ctx.valid.insert(spec.key, ());
                }
            }
        }
    }

    // one-of pairs: exactly one of the two keys
    for (i, spec) in schema.fields.iter().enumerate() {
        let Presence::OneOf(other) = spec.presence else {
            continue;
        };
        // each pair once, from its first key
        let other_index = schema.fields.iter().position(|f| f.key == other);
        if other_index.is_some_and(|j| j < i) {
            continue;
        }
        let present = if spec.group.starts_with("materials.") {
            material_tables.contains_key(spec.group)
        } else {
            groups.contains_key(spec.group)
        };
        if !present {
            continue;
        }
        let a = ctx.seen.get(spec.key).cloned();
        let b = ctx.seen.get(other).cloned();
        match (a, b) {
            (Some(a), Some(b)) => {
                let (first, second, k2) = if a.0.line <= b.0.line {
                    (a, b, other)
                } else {
                    (b, a, spec.key)
                };
                ctx.errors.push(DeckError::Invalid {
                    location: second.0,
                    key: k2.into(),
                    value: second.1,
                    rule: format!(
                        "give exactly one of {} and {other} (the other is at line {})",
                        spec.key, first.0.line
                    ),
                });
            }
            (None, None) => {
                let location = header(&ctx, spec.top_group());
                ctx.errors.push(DeckError::Missing {
                    location,
                    key: spec.key.into(),
                    hint: format!(" (or give {other} instead)"),
                });
            }
            _ => {}
        }
    }

    // one holding per degree of freedom (issue 29): a load and a displacement both
    // written for the same DOF are refused at the later key, naming both and their lines
    // (presence in the deck, not the value: `misalignment = 0.0` beside a moment is two
    // holdings too). The value rule a system may keep for the same pair is then not
    // repeated.
    let mut held_twice: Vec<&str> = Vec::new();
    for pair in schema.one_holding {
        let (Some(load), Some(disp)) = (ctx.seen.get(pair.load), ctx.seen.get(pair.displacement))
        else {
            continue;
        };
        let word = schema.field(pair.load).and_then(|f| match f.kind {
            FieldKind::RealOr(w) => Some(w),
            _ => None,
        });
        if word.is_some_and(|w| load.1.trim_matches(['"', '\'']) == w) {
            continue;
        }
        let (later, later_key) = if load.0.line <= disp.0.line {
            (disp.clone(), pair.displacement)
        } else {
            (load.clone(), pair.load)
        };
        let rule = format!(
            "{} is given two ways: {} at line {} applies a load and {} at line {} holds a displacement; give one of them",
            pair.dof, pair.load, load.0.line, pair.displacement, disp.0.line
        );
        ctx.errors.push(DeckError::Invalid {
            location: later.0,
            key: later_key.into(),
            value: later.1,
            rule,
        });
        held_twice.extend([pair.load, pair.displacement]);
    }

    // cross-field rules, on valid keys only
    let invalid: Vec<&str> = schema
        .fields
        .iter()
        .map(|f| f.key)
        .filter(|k| !ctx.valid.contains_key(k))
        .collect();
    for (key, rule) in (schema.cross_checks)(&value, units) {
        if !ctx.valid.contains_key(key)
            || invalid.iter().any(|k| names_key(&rule, k))
            || (held_twice.contains(&key) && held_twice.iter().any(|k| names_key(&rule, k)))
        {
            continue;
        }
        let (location, v) = match ctx.seen.get(key) {
            Some((l, v)) => (l.clone(), v.clone()),
            None => (Location::start(ctx.source), String::from("(default)")),
        };
        ctx.errors.push(DeckError::Invalid {
            location,
            key: key.to_string(),
            value: v,
            rule,
        });
    }

    // opaque tables, as written
    let mut opaque = BTreeMap::new();
    if schema.opaque_tables.iter().any(|t| groups.contains_key(t)) {
        match toml::from_str::<toml::Table>(text) {
            Ok(mut t) => {
                for name in schema.opaque_tables {
                    if let Some(toml::Value::Table(th)) = t.remove(*name) {
                        opaque.insert((*name).to_string(), th);
                    }
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
            value,
            name,
            opaque,
        })
    } else {
        Err(finish(ctx.errors))
    }
}

pub(super) fn finish(mut errors: Vec<DeckError>) -> DeckErrors {
    errors.sort_by_key(|e| {
        e.location()
            .map_or((usize::MAX, usize::MAX), |l| (l.line, l.column))
    });
    DeckErrors(errors)
}

/// Reads one field's value, checks type and range; returns the SI value.
pub(super) fn read_value(
    ctx: &mut Ctx<'_>,
    spec: &FieldMeta,
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
        FieldKind::RealOr(word) => match value {
            Some(Value::Float(f)) => spec.to_si(*f.value(), units),
            Some(Value::Integer(i)) => spec.to_si(*i.value() as f64, units),
            Some(Value::String(s)) if s.value() == word => return Some(f64::NAN),
            _ => {
                ctx.errors.push(wrong(&format!("a number or \"{word}\"")));
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
        FieldKind::Choice(list) if is_bool(list) && value.is_some_and(Value::is_bool) => {
            return Some(if value.and_then(Value::as_bool) == Some(true) {
                1.0
            } else {
                0.0
            });
        }
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

/// Parses the editable document (comments kept) of already validated text.
pub(crate) fn parse_doc(text: &str, source: &str) -> Result<DocumentMut, DeckErrors> {
    text.parse::<DocumentMut>()
        .map_err(|e| DeckErrors::from(syntax_error(&e, text, source)))
}
