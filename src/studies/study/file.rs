//! The study file (`decks/NAME.study.toml`): which deck, which outputs, and one design —
//! a `[grid]`, a `[sample]` or a `[duty]` cycle. Read with toml_edit so every refusal
//! names the file, line and column, as a deck's do ([`DeckError`]); unknown keys are
//! refused, never ignored.
//!
//! Deck keys inside a design may be written dotted (`operating.inner_speed = …`) or
//! quoted (`"operating.inner_speed" = …`): both are flattened to the deck key path.

use std::path::{Path, PathBuf};

use toml_edit::{Item, TableLike, Value};

use super::super::sweep::{value_text, Range};
use crate::deck::{DeckError, Location};

/// Points a study may have unless the file raises `max_points`.
pub const DEFAULT_MAX_POINTS: usize = 10_000;
/// The most `max_points` may be raised to.
pub const MAX_POINTS_LIMIT: usize = 1_000_000;

/// A parsed study file.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyFile {
    /// The study file's name as given (for messages and reports).
    pub source: String,
    /// The deck, resolved relative to the study file's directory.
    pub deck: PathBuf,
    /// Outputs to keep: key-output names, or JSON pointers (`/life/l10_bearing_mrev`) into
    /// the run's JSON report; empty: every key output of the deck's solution.
    pub outputs: Vec<String>,
    /// The most points the study may have.
    pub max_points: usize,
    /// What is varied.
    pub design: Design,
}

/// What a study varies.
#[derive(Debug, Clone, PartialEq)]
pub enum Design {
    /// Full factorial over several keys, the last key fastest.
    Grid(Vec<Axis>),
    /// Random or Latin-hypercube sample.
    Sample(Sample),
    /// Load cases with time shares.
    Duty(Duty),
}

impl Design {
    /// `"grid"`, `"sample"` or `"duty"`.
    pub fn kind(&self) -> &'static str {
        match self {
            Design::Grid(_) => "grid",
            Design::Sample(_) => "sample",
            Design::Duty(_) => "duty",
        }
    }
}

/// One key of a grid and its values as written into the deck.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Deck key.
    pub key: String,
    /// Values (deck units), as text the deck receives.
    pub values: Vec<String>,
}

/// How a sample is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Independent draws.
    MonteCarlo,
    /// One draw in each of `samples` equal-probability strata per key.
    LatinHypercube,
}

impl Method {
    /// The name written in the study file.
    pub fn name(self) -> &'static str {
        match self {
            Method::MonteCarlo => "monte-carlo",
            Method::LatinHypercube => "latin-hypercube",
        }
    }
}

/// Shape of a tolerance band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Uniform over nominal ± band.
    Uniform,
    /// Normal with σ = band/`sigmas`, truncated at ± band.
    TruncatedNormal {
        /// Band in standard deviations (3 unless written).
        sigmas: f64,
    },
}

/// A key's distribution (deck units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// Normal with mean and standard deviation (σ ≥ 0).
    Normal {
        /// Mean.
        mean: f64,
        /// Standard deviation.
        sigma: f64,
    },
    /// Uniform between lo and hi.
    Uniform {
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
    /// A tolerance band nominal ± band.
    Tolerance {
        /// Nominal value.
        nominal: f64,
        /// Half-width of the band.
        band: f64,
        /// Shape inside the band.
        shape: Shape,
    },
}

/// A sampled design.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Monte Carlo or Latin hypercube.
    pub method: Method,
    /// Number of points.
    pub samples: usize,
    /// Seed of every stream.
    pub seed: u64,
    /// Keys and their distributions, in file order.
    pub keys: Vec<(String, Distribution)>,
}

/// One load case of a duty cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct DutyCase {
    /// Time share (0 < share ≤ 1; the shares sum to 1).
    pub share: f64,
    /// Deck keys set for this case, values as text (deck units).
    pub set: Vec<(String, String)>,
}

/// A duty cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Duty {
    /// The key output holding each case's life (`l10_bearing_mrev`, `l10_h`).
    pub life: String,
    /// The key output holding each case's power loss (`heat_w`), averaged by share.
    pub power: Option<String>,
    /// The cases.
    pub cases: Vec<DutyCase>,
}

/// Collects refusals with their locations.
struct Reader<'a> {
    text: &'a str,
    source: &'a str,
    errors: Vec<DeckError>,
}

impl Reader<'_> {
    fn loc(&self, span: Option<std::ops::Range<usize>>) -> Location {
        span.map_or_else(
            || Location::start(self.source),
            |s| Location::at(self.source, self.text, s.start),
        )
    }

    fn invalid(
        &mut self,
        span: Option<std::ops::Range<usize>>,
        key: &str,
        value: &str,
        rule: String,
    ) {
        let location = self.loc(span);
        self.errors.push(DeckError::Invalid {
            location,
            key: key.to_string(),
            value: value.to_string(),
            rule,
        });
    }

    fn wrong_type(&mut self, item: &Item, key: &str, expected: &str) {
        let location = self.loc(item.span());
        self.errors.push(DeckError::WrongType {
            location,
            key: key.to_string(),
            value: written(item),
            expected: expected.to_string(),
        });
    }

    /// Refuses every key of `table` not in `known`, naming it and its line.
    fn known_keys(&mut self, table: &dyn TableLike, prefix: &str, known: &[&str]) {
        for (k, _) in table.iter() {
            if !known.contains(&k) {
                let span = table.key(k).and_then(|k| k.span());
                let location = self.loc(span);
                self.errors.push(DeckError::UnknownKey {
                    location,
                    key: format!("{prefix}{k}"),
                    hint: format!(", expected one of: {}", known.join(", ")),
                });
            }
        }
    }

    fn number(&mut self, item: &Item, key: &str) -> Option<f64> {
        match item.as_value() {
            Some(Value::Float(f)) if f.value().is_finite() => Some(*f.value()),
            Some(Value::Integer(i)) => Some(*i.value() as f64),
            _ => {
                self.wrong_type(item, key, "a finite number");
                None
            }
        }
    }

    fn pair(&mut self, item: &Item, key: &str) -> Option<(f64, f64)> {
        let expected = "an array of two numbers [a, b]";
        let Some(a) = item.as_array() else {
            self.wrong_type(item, key, expected);
            return None;
        };
        let v: Vec<Option<f64>> = a
            .iter()
            .map(|v| match v {
                Value::Float(f) if f.value().is_finite() => Some(*f.value()),
                Value::Integer(i) => Some(*i.value() as f64),
                _ => None,
            })
            .collect();
        match v.as_slice() {
            [Some(x), Some(y)] => Some((*x, *y)),
            _ => {
                self.wrong_type(item, key, expected);
                None
            }
        }
    }
}

/// A value as written (trimmed), for messages.
fn written(item: &Item) -> String {
    match item {
        Item::Value(v) => v.to_string().trim().to_string(),
        Item::Table(_) | Item::ArrayOfTables(_) => "(a table)".to_string(),
        Item::None => String::new(),
    }
}

/// A deck value (number or string) as the text `--set` would take.
fn deck_text(v: &Value) -> Option<String> {
    match v {
        Value::Float(f) if f.value().is_finite() => Some(value_text(*f.value())),
        Value::Integer(i) => Some(i.value().to_string()),
        Value::String(s) => Some(s.value().clone()),
        Value::Boolean(b) => Some(b.value().to_string()),
        _ => None,
    }
}

/// The leaves of a design table as (dotted deck key, item): nested tables (dotted keys)
/// are descended into unless `is_leaf` says the table is itself a value.
fn flatten<'a>(
    table: &'a dyn TableLike,
    prefix: &str,
    is_leaf: &dyn Fn(&Item) -> bool,
    out: &mut Vec<(String, &'a Item)>,
) {
    for (k, item) in table.iter() {
        let key = if prefix.is_empty() {
            k.to_string()
        } else {
            format!("{prefix}.{k}")
        };
        match item.as_table_like() {
            Some(t) if !is_leaf(item) => flatten(t, &key, is_leaf, out),
            _ => out.push((key, item)),
        }
    }
}

/// Reads a study file's text. `path` is where it was read from: the deck is resolved
/// against its directory. All refusals are returned together, each with its location.
pub fn parse(text: &str, path: &Path) -> Result<StudyFile, Vec<DeckError>> {
    let source = path.display().to_string();
    let doc = toml_edit::Document::parse(text)
        .map_err(|e| vec![crate::deck::syntax_error_of(&e, text, &source)])?;
    let root = doc.as_table();
    let mut r = Reader {
        text,
        source: &source,
        errors: Vec::new(),
    };
    r.known_keys(
        root,
        "",
        &["deck", "outputs", "max_points", "grid", "sample", "duty"],
    );

    let deck = match root.get("deck") {
        None => {
            r.errors.push(DeckError::Missing {
                location: Location::start(&source),
                key: "deck".into(),
                hint: " (the deck's path, relative to the study file)".into(),
            });
            None
        }
        Some(item) => match item.as_str() {
            Some(s) if !s.trim().is_empty() => {
                let dir = path.parent().unwrap_or_else(|| Path::new(""));
                Some(dir.join(s))
            }
            _ => {
                r.wrong_type(item, "deck", "a path string");
                None
            }
        },
    };

    let mut outputs = Vec::new();
    if let Some(item) = root.get("outputs") {
        match item.as_array() {
            Some(a) if a.iter().all(|v| v.as_str().is_some()) => {
                outputs = a
                    .iter()
                    .filter_map(|v| v.as_str().map(str::to_string))
                    .collect();
                let mut seen = std::collections::HashSet::new();
                for o in &outputs {
                    if !seen.insert(o.clone()) {
                        r.invalid(item.span(), "outputs", o, "named twice".into());
                    }
                }
            }
            _ => r.wrong_type(
                item,
                "outputs",
                "an array of key-output names or JSON pointers",
            ),
        }
    }

    let mut max_points = DEFAULT_MAX_POINTS;
    if let Some(item) = root.get("max_points") {
        match item.as_integer() {
            Some(n) if n >= 1 && n as u64 <= MAX_POINTS_LIMIT as u64 => max_points = n as usize,
            _ => r.invalid(
                item.span(),
                "max_points",
                &written(item),
                format!("a whole number from 1 to {MAX_POINTS_LIMIT}"),
            ),
        }
    }

    let designs: Vec<&str> = ["grid", "sample", "duty"]
        .into_iter()
        .filter(|k| root.contains_key(k))
        .collect();
    let design = match designs.as_slice() {
        ["grid"] => grid(&mut r, &root["grid"], max_points).map(Design::Grid),
        ["sample"] => sample(&mut r, &root["sample"], max_points).map(Design::Sample),
        ["duty"] => duty(&mut r, &root["duty"]).map(Design::Duty),
        [] => {
            r.errors.push(DeckError::Missing {
                location: Location::start(&source),
                key: "grid".into(),
                hint: " (a study needs exactly one of [grid], [sample] or [duty])".into(),
            });
            None
        }
        more => {
            let span = root.get(more[1]).and_then(Item::span);
            r.invalid(
                span,
                more[1],
                "",
                format!(
                    "a study has exactly one of [grid], [sample] or [duty]; this file has {}",
                    more.join(" and ")
                ),
            );
            None
        }
    };
    match (deck, design, r.errors.is_empty()) {
        (Some(deck), Some(design), true) => Ok(StudyFile {
            source,
            deck,
            outputs,
            max_points,
            design,
        }),
        _ => Err(r.errors),
    }
}

fn grid(r: &mut Reader, item: &Item, max_points: usize) -> Option<Vec<Axis>> {
    let Some(t) = item.as_table_like() else {
        r.wrong_type(item, "grid", "a table of deck keys");
        return None;
    };
    let mut leaves = Vec::new();
    flatten(t, "", &|_| false, &mut leaves);
    if leaves.is_empty() {
        r.invalid(
            item.span(),
            "grid",
            "",
            "names no key (write KEY = \"A:B:STEP\", \"A:B:xN\" or a list)".into(),
        );
        return None;
    }
    let mut axes = Vec::new();
    let mut total: usize = 1;
    for (key, leaf) in leaves {
        let name = format!("grid.{key}");
        let values = match leaf.as_value() {
            Some(Value::String(s)) => {
                match Range::parse(&format!("{key}={}", s.value())).and_then(|range| range.values())
                {
                    Ok(v) => v.into_iter().map(value_text).collect(),
                    Err(e) => {
                        let e = e.trim_start_matches("--set-range ").to_string();
                        r.invalid(leaf.span(), &name, &written(leaf), e);
                        continue;
                    }
                }
            }
            Some(Value::Array(a)) => {
                let v: Option<Vec<String>> = a.iter().map(deck_text).collect();
                match v {
                    Some(v) if !v.is_empty() => v,
                    _ => {
                        r.wrong_type(leaf, &name, "a non-empty list of numbers or strings");
                        continue;
                    }
                }
            }
            _ => {
                r.wrong_type(leaf, &name, "\"A:B:STEP\", \"A:B:xN\" or a list of values");
                continue;
            }
        };
        total = total.saturating_mul(values.len());
        axes.push(Axis { key, values });
    }
    if total > max_points {
        let sizes: Vec<String> = axes
            .iter()
            .map(|a| format!("{} ({})", a.key, a.values.len()))
            .collect();
        r.invalid(
            item.span(),
            "grid",
            "",
            format!(
                "{total} points ({}) is more than max_points = {max_points} (raise max_points in the study file, at most {MAX_POINTS_LIMIT})",
                sizes.join(" × ")
            ),
        );
        return None;
    }
    Some(axes)
}

fn sample(r: &mut Reader, item: &Item, max_points: usize) -> Option<Sample> {
    let Some(t) = item.as_table_like() else {
        r.wrong_type(item, "sample", "a table");
        return None;
    };
    let method = match t.get("method").map(|m| (m, m.as_str())) {
        None => Method::MonteCarlo,
        Some((_, Some("monte-carlo"))) => Method::MonteCarlo,
        Some((_, Some("latin-hypercube"))) => Method::LatinHypercube,
        Some((m, _)) => {
            r.invalid(
                m.span(),
                "sample.method",
                &written(m),
                "one of \"monte-carlo\", \"latin-hypercube\"".into(),
            );
            Method::MonteCarlo
        }
    };
    let samples = match t.get("samples") {
        None => {
            r.errors.push(DeckError::Missing {
                location: r.loc(item.span()),
                key: "sample.samples".into(),
                hint: " (the number of points)".into(),
            });
            0
        }
        Some(s) => match s.as_integer() {
            Some(n) if n >= 1 && n as u64 <= max_points as u64 => n as usize,
            Some(n) if n >= 1 => {
                r.invalid(
                    s.span(),
                    "sample.samples",
                    &written(s),
                    format!("{n} points is more than max_points = {max_points} (raise max_points in the study file, at most {MAX_POINTS_LIMIT})"),
                );
                0
            }
            _ => {
                r.invalid(
                    s.span(),
                    "sample.samples",
                    &written(s),
                    "a whole number ≥ 1".into(),
                );
                0
            }
        },
    };
    let seed = match t.get("seed") {
        None => 0,
        Some(s) => match s.as_integer() {
            Some(n) if n >= 0 => n as u64,
            _ => {
                r.invalid(
                    s.span(),
                    "sample.seed",
                    &written(s),
                    "a whole number ≥ 0".into(),
                );
                0
            }
        },
    };
    let is_dist = |i: &Item| {
        i.as_table_like().is_some_and(|t| {
            ["normal", "uniform", "tolerance"]
                .iter()
                .any(|k| t.contains_key(k))
        })
    };
    let mut leaves = Vec::new();
    flatten(t, "", &is_dist, &mut leaves);
    let mut keys = Vec::new();
    for (key, leaf) in leaves {
        if ["method", "samples", "seed"].contains(&key.as_str()) {
            continue;
        }
        let name = format!("sample.{key}");
        if let Some(d) = distribution(r, leaf, &name) {
            keys.push((key, d));
        }
    }
    if keys.is_empty() && r.errors.is_empty() {
        r.invalid(item.span(), "sample", "", "names no key (write KEY = { normal = [mean, sigma] }, { uniform = [lo, hi] } or { tolerance = [nominal, plus_minus] })".into());
    }
    Some(Sample {
        method,
        samples,
        seed,
        keys,
    })
}

fn distribution(r: &mut Reader, item: &Item, name: &str) -> Option<Distribution> {
    let expected = "{ normal = [mean, sigma] }, { uniform = [lo, hi] } or { tolerance = [nominal, plus_minus], shape = \"uniform\" | \"truncated-normal\" }";
    let Some(t) = item.as_table_like() else {
        r.wrong_type(item, name, expected);
        return None;
    };
    let kinds: Vec<&str> = ["normal", "uniform", "tolerance"]
        .into_iter()
        .filter(|k| t.contains_key(k))
        .collect();
    match kinds.as_slice() {
        ["normal"] => {
            r.known_keys(t, &format!("{name}."), &["normal"]);
            let normal_item = t.get("normal")?;
            let (mean, sigma) = r.pair(normal_item, &format!("{name}.normal"))?;
            if sigma < 0.0 {
                r.invalid(
                    normal_item.span(),
                    &format!("{name}.normal"),
                    &written(normal_item),
                    "σ must be ≥ 0".into(),
                );
                return None;
            }
            Some(Distribution::Normal { mean, sigma })
        }
        ["uniform"] => {
            r.known_keys(t, &format!("{name}."), &["uniform"]);
            let uniform_item = t.get("uniform")?;
            let (lo, hi) = r.pair(uniform_item, &format!("{name}.uniform"))?;
            if lo > hi {
                r.invalid(
                    uniform_item.span(),
                    &format!("{name}.uniform"),
                    &written(uniform_item),
                    "lo must be ≤ hi".into(),
                );
                return None;
            }
            Some(Distribution::Uniform { lo, hi })
        }
        ["tolerance"] => {
            r.known_keys(t, &format!("{name}."), &["tolerance", "shape", "sigmas"]);
            let tolerance_item = t.get("tolerance")?;
            let (nominal, band) = r.pair(tolerance_item, &format!("{name}.tolerance"))?;
            if band < 0.0 {
                r.invalid(
                    tolerance_item.span(),
                    &format!("{name}.tolerance"),
                    &written(tolerance_item),
                    "the ± band must be ≥ 0".into(),
                );
                return None;
            }
            let sigmas = match t.get("sigmas") {
                None => 3.0,
                Some(s) => match r.number(s, &format!("{name}.sigmas")) {
                    Some(k) if k > 0.0 => k,
                    Some(_) => {
                        r.invalid(
                            s.span(),
                            &format!("{name}.sigmas"),
                            &written(s),
                            "must be > 0".into(),
                        );
                        return None;
                    }
                    None => return None,
                },
            };
            let shape = match t.get("shape").map(|s| (s, s.as_str())) {
                None | Some((_, Some("uniform"))) => {
                    if let Some(s) = t.get("sigmas") {
                        r.invalid(
                            s.span(),
                            &format!("{name}.sigmas"),
                            &written(s),
                            "only a truncated-normal band has sigmas".into(),
                        );
                    }
                    Shape::Uniform
                }
                Some((_, Some("truncated-normal"))) => Shape::TruncatedNormal { sigmas },
                Some((s, _)) => {
                    r.invalid(
                        s.span(),
                        &format!("{name}.shape"),
                        &written(s),
                        "one of \"uniform\", \"truncated-normal\"".into(),
                    );
                    return None;
                }
            };
            Some(Distribution::Tolerance {
                nominal,
                band,
                shape,
            })
        }
        _ => {
            r.wrong_type(item, name, &format!("exactly one of {expected}"));
            None
        }
    }
}

fn duty(r: &mut Reader, item: &Item) -> Option<Duty> {
    let Some(t) = item.as_table_like() else {
        r.wrong_type(item, "duty", "a table");
        return None;
    };
    r.known_keys(t, "duty.", &["life", "power", "cases"]);
    let output = |r: &mut Reader, k: &str| -> Option<String> {
        let i = t.get(k)?;
        match i.as_str() {
            Some(s) if !s.is_empty() => Some(s.to_string()),
            _ => {
                r.wrong_type(i, &format!("duty.{k}"), "a key-output name");
                None
            }
        }
    };
    let life = output(r, "life");
    if t.get("life").is_none() {
        r.errors.push(DeckError::Missing {
            location: r.loc(item.span()),
            key: "duty.life".into(),
            hint: " (the key output holding each case's life, e.g. \"l10_bearing_mrev\")".into(),
        });
    }
    let power = output(r, "power");
    let Some(cases_item) = t.get("cases") else {
        r.errors.push(DeckError::Missing {
            location: r.loc(item.span()),
            key: "duty.cases".into(),
            hint: " (a list of { share = …, set = { KEY = VALUE } })".into(),
        });
        return None;
    };
    let tables: Vec<&dyn TableLike> = match cases_item {
        Item::ArrayOfTables(a) => a.iter().map(|t| t as &dyn TableLike).collect(),
        Item::Value(Value::Array(a)) => {
            let v: Option<Vec<&dyn TableLike>> = a
                .iter()
                .map(|v| v.as_inline_table().map(|t| t as &dyn TableLike))
                .collect();
            match v {
                Some(v) => v,
                None => {
                    r.wrong_type(
                        cases_item,
                        "duty.cases",
                        "a list of { share = …, set = { KEY = VALUE } }",
                    );
                    return None;
                }
            }
        }
        _ => {
            r.wrong_type(
                cases_item,
                "duty.cases",
                "a list of { share = …, set = { KEY = VALUE } }",
            );
            return None;
        }
    };
    let mut cases = Vec::new();
    let mut sum = 0.0;
    for (n, c) in tables.iter().enumerate() {
        let prefix = format!("duty.cases[{n}]");
        r.known_keys(*c, &format!("{prefix}."), &["share", "set"]);
        let share = match c.get("share") {
            Some(s) => match r.number(s, &format!("{prefix}.share")) {
                Some(x) if x > 0.0 && x <= 1.0 => x,
                Some(_) => {
                    r.invalid(
                        s.span(),
                        &format!("{prefix}.share"),
                        &written(s),
                        "a time share in (0, 1]".into(),
                    );
                    continue;
                }
                None => continue,
            },
            None => {
                r.errors.push(DeckError::Missing {
                    location: r.loc(cases_item.span()),
                    key: format!("{prefix}.share"),
                    hint: String::new(),
                });
                continue;
            }
        };
        sum += share;
        let mut set = Vec::new();
        if let Some(s) = c.get("set") {
            match s.as_table_like() {
                Some(st) => {
                    let mut leaves = Vec::new();
                    flatten(st, "", &|_| false, &mut leaves);
                    for (key, leaf) in leaves {
                        match leaf.as_value().and_then(deck_text) {
                            Some(v) => set.push((key, v)),
                            None => r.wrong_type(
                                leaf,
                                &format!("{prefix}.set.{key}"),
                                "a number or a string",
                            ),
                        }
                    }
                }
                None => r.wrong_type(s, &format!("{prefix}.set"), "a table { KEY = VALUE }"),
            }
        }
        cases.push(DutyCase { share, set });
    }
    if cases.is_empty() && r.errors.is_empty() {
        r.invalid(cases_item.span(), "duty.cases", "", "no case".into());
    }
    if !cases.is_empty() && (sum - 1.0).abs() > 1e-9 {
        r.invalid(
            cases_item.span(),
            "duty.cases",
            "",
            format!("the shares sum to {sum}; they must sum to 1 (to 1e-9)"),
        );
    }
    Some(Duty {
        life: life?,
        power,
        cases,
    })
}
