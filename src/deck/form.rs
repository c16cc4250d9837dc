//! The deck machinery shared by every bearing system: a [`Schema`] describes one system's
//! deck (its tables, its editable scalar keys as [`FieldSpec`]s over the system's input
//! type `T`, its material bodies, its opaque tables and its cross-field rules), and
//! [`Form`] reads, validates, edits, converts and saves decks of that schema.
//!
//! What every deck gets from here, with file:line:col on every error:
//! unknown keys (with the keys allowed where they stand), wrong TOML types, required /
//! defaulted / one-of-two keys, per-field ranges shown in the deck's units, choices,
//! material bodies given as a preset name (`"steel"`, …) or a table, `--set` assignments
//! written all first and validated once, in-place edits keeping comments (toml_edit),
//! conversion between unit systems, atomic saves, a commented template, the
//! `rollbench keys` table and close-key suggestions.
//!
//! Top-level keys every deck may have: `type` (must equal [`Schema::system`]; only a
//! [`crate::bearings::DEFAULT_SYSTEM`] deck may omit it), `units` (`"us"` | `"si"`,
//! required) and `name` (a string, default `"unnamed"`).
//!
//! Cross-field rules ([`Schema::cross_checks`]) run on the value built from the valid
//! fields; a rule's error is reported only when its key and every field key its text
//! names are individually valid (so a rule never speaks of a value the deck does not
//! have: name the other keys in the rule, e.g. with [`show`]).

use std::collections::{BTreeMap, HashMap};
use std::ops::{Deref, Range};
use std::path::Path;

use toml_edit::{DocumentMut, Item, TableLike, Value};

use super::error::{DeckError, DeckErrors, Location};
use crate::physics::material::Material;
use crate::units::{Quantity, Units};

/// What TOML value a field takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FieldKind {
    /// A real number (TOML float or integer).
    Real,
    /// A whole number (TOML integer); the SI value is the number itself.
    Integer,
    /// A string from a fixed list; the "SI value" is the index in the list.
    Choice(&'static [&'static str]),
}

/// Whether a key must be given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Presence {
    /// Must be present.
    Required,
    /// May be omitted; then this SI value (or choice index) is used.
    Default(f64),
    /// Exactly one of this key and the named other key (full path, same table) must be
    /// present. Both keys carry `OneOf` naming each other; the template writes the first
    /// (in field order) and shows the second commented out.
    OneOf(&'static str),
}

/// Non-generic metadata of one editable scalar deck key.
#[derive(Debug, Clone, Copy)]
pub struct FieldMeta {
    /// Full key path, e.g. `geometry.roller_count`.
    pub key: &'static str,
    /// Table the key lives in, e.g. `geometry` (or `materials.roller`).
    pub group: &'static str,
    /// Short human label, with the symbol used in the seed report.
    pub label: &'static str,
    /// Physical quantity (decides units and conversion).
    pub quantity: Quantity,
    /// TOML value kind.
    pub kind: FieldKind,
    /// Lower bound, SI.
    pub min: f64,
    /// True if `min` itself is not allowed.
    pub min_exclusive: bool,
    /// Upper bound, SI.
    pub max: f64,
    /// True if `max` itself is not allowed.
    pub max_exclusive: bool,
    /// Required, defaulted, or one of two alternatives.
    pub presence: Presence,
    /// One-line explanation for templates and help.
    pub help: &'static str,
    /// Unit display string in SI decks.
    pub unit_si: &'static str,
    /// Unit display string in US decks.
    pub unit_us: &'static str,
}

impl FieldMeta {
    /// A field's metadata with the unit strings taken from `quantity`. `min`/`max` are
    /// `(bound in SI, exclusive)`; for a choice give `(0.0, false)` and
    /// `(list.len() - 1, false)`.
    #[allow(clippy::too_many_arguments)]
    pub const fn new(
        key: &'static str,
        group: &'static str,
        label: &'static str,
        quantity: Quantity,
        kind: FieldKind,
        min: (f64, bool),
        max: (f64, bool),
        presence: Presence,
        help: &'static str,
    ) -> FieldMeta {
        FieldMeta {
            key,
            group,
            label,
            quantity,
            kind,
            min: min.0,
            min_exclusive: min.1,
            max: max.0,
            max_exclusive: max.1,
            presence,
            help,
            unit_si: quantity.unit(Units::Si),
            unit_us: quantity.unit(Units::Us),
        }
    }

    /// Unit display string in `units`.
    pub fn unit(&self, units: Units) -> &'static str {
        match units {
            Units::Si => self.unit_si,
            Units::Us => self.unit_us,
        }
    }

    /// Converts a value in deck `units` to SI.
    pub fn to_si(&self, value: f64, units: Units) -> f64 {
        self.quantity.to_si(value, units)
    }

    /// Converts an SI value to deck `units`.
    pub fn from_si(&self, value_si: f64, units: Units) -> f64 {
        self.quantity.from_si(value_si, units)
    }

    /// True if the SI value lies in the allowed range (and is finite).
    pub fn in_range(&self, value_si: f64) -> bool {
        if !value_si.is_finite() {
            return false;
        }
        let lo = if self.min_exclusive {
            value_si > self.min
        } else {
            value_si >= self.min
        };
        let hi = if self.max_exclusive {
            value_si < self.max
        } else {
            value_si <= self.max
        };
        lo && hi
    }

    /// The allowed range in deck units, e.g. `0 < value ≤ 39.3701 in`.
    pub fn allowed(&self, units: Units) -> String {
        let lo = format_short(self.from_si(self.min, units));
        let hi = format_short(self.from_si(self.max, units));
        let lo_op = if self.min_exclusive { "<" } else { "≤" };
        let hi_op = if self.max_exclusive { "<" } else { "≤" };
        let unit = self.unit(units);
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        format!("{lo} {lo_op} value {hi_op} {hi}{unit}")
    }

    /// The last path segment (the key inside its table).
    pub fn name(&self) -> &'static str {
        self.key.rsplit('.').next().unwrap_or(self.key)
    }

    /// The top-level table of the key (`materials` for `materials.roller.density`).
    pub fn top_group(&self) -> &'static str {
        self.group.split('.').next().unwrap_or(self.group)
    }
}

/// One editable scalar key of a `T` deck: its metadata and how it maps onto `T` (SI
/// value; the index in the list for a choice).
pub struct FieldSpec<T: 'static> {
    /// Key, table, unit, range, presence, help.
    pub meta: FieldMeta,
    /// Reads the SI value from `T`.
    pub get: fn(&T) -> f64,
    /// Writes an SI value (already range-checked) into `T`.
    pub set: fn(&mut T, f64),
}

// Manual impls: a derive would require `T: Clone`/`Copy`/`Debug`, which the fn pointers
// do not need.
impl<T> Clone for FieldSpec<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for FieldSpec<T> {}
impl<T> std::fmt::Debug for FieldSpec<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FieldSpec")
            .field("meta", &self.meta)
            .finish_non_exhaustive()
    }
}

impl<T> Deref for FieldSpec<T> {
    type Target = FieldMeta;
    fn deref(&self) -> &FieldMeta {
        &self.meta
    }
}

impl<T> FieldSpec<T> {
    /// Reads this field's SI value (choice index for choices).
    pub fn get_si(&self, value: &T) -> f64 {
        (self.get)(value)
    }

    /// Writes an SI value (already range-checked).
    pub fn set_si(&self, value: &mut T, value_si: f64) {
        (self.set)(value, value_si)
    }
}

/// How a schema reads and writes the [`Material`] of its body number `i` (the index in
/// [`Schema::material_bodies`]); used for presets.
pub struct MaterialAccess<T: 'static> {
    /// The material of body `i`.
    pub get: fn(&T, usize) -> Material,
    /// Sets the material of body `i`.
    pub set: fn(&mut T, usize, Material),
}
impl<T> Clone for MaterialAccess<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for MaterialAccess<T> {}

/// Material presets accepted as `materials.<body> = "<name>"`.
pub const MATERIAL_PRESETS: &[(&str, Material)] = &[
    ("steel", Material::STEEL),
    ("silicon-nitride", Material::SILICON_NITRIDE),
];

/// Preset material by name.
pub fn material_preset(name: &str) -> Option<Material> {
    MATERIAL_PRESETS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, m)| *m)
}

/// Name of the preset equal to `m`, if any.
pub fn preset_name(m: &Material) -> Option<&'static str> {
    MATERIAL_PRESETS
        .iter()
        .find(|(_, p)| p == m)
        .map(|(n, _)| *n)
}

/// What one bearing system's deck looks like.
pub struct Schema<T: 'static> {
    /// The deck's `type`. Only [`crate::bearings::DEFAULT_SYSTEM`] decks may omit it.
    pub system: &'static str,
    /// Allowed top-level tables, in template order (may include the opaque ones).
    pub groups: &'static [&'static str],
    /// Top-level tables every deck must have.
    pub required_groups: &'static [&'static str],
    /// Every editable scalar key, grouped by table in [`Schema::groups`] order. A
    /// material body's properties are fields of group `materials.<body>` (see
    /// [`material_fields!`](crate::deck::form::material_fields)).
    pub fields: &'static [FieldSpec<T>],
    /// The bodies under `[materials]`: each `materials.<body>` is a preset name or a
    /// table of its `materials.<body>.*` fields. Empty: no `[materials]` bodies.
    pub material_bodies: &'static [&'static str],
    /// Get/set of a body's [`Material`] by body index (for presets).
    pub material: Option<MaterialAccess<T>>,
    /// Top-level tables kept as raw TOML for their own parser (not validated here).
    pub opaque_tables: &'static [&'static str],
    /// The value before the deck's fields are applied.
    pub defaults: fn() -> T,
    /// Rules involving several keys, on the value built from the valid fields:
    /// `(key, rule)` pairs; see the module documentation for when they are reported.
    pub cross_checks: fn(&T, Units) -> Vec<(&'static str, String)>,
    /// The first comment lines of [`template`] (without `# `).
    pub template_header: &'static str,
}

impl<T> Schema<T> {
    /// The field with full key path `key`.
    pub fn field(&self, key: &str) -> Option<&'static FieldSpec<T>> {
        let fields: &'static [FieldSpec<T>] = self.fields;
        fields.iter().find(|f| f.key == key)
    }

    /// Every top-level table: [`Schema::groups`], then opaque tables not listed there.
    fn all_groups(&self) -> Vec<&'static str> {
        let mut g = self.groups.to_vec();
        for t in self.opaque_tables {
            if !g.contains(t) {
                g.push(t);
            }
        }
        g
    }

    fn is_opaque(&self, table: &str) -> bool {
        self.opaque_tables.contains(&table)
    }
}

/// Builds the five [`FieldSpec`]s of one material body (`materials.<body>.youngs_modulus`,
/// `poisson_ratio`, `density`, `specific_heat`, `conductivity`), given how to reach the
/// body's [`Material`] in `T`:
///
/// ```ignore
/// const MAT_BALL: [FieldSpec<Ball>; 5] =
///     material_fields!(Ball, "ball", "Ball", |b| b.materials.ball);
/// ```
#[macro_export]
#[doc(hidden)]
macro_rules! __deck_material_fields {
    ($T:ty, $body:literal, $label:literal, |$b:ident| $path:expr) => {{
        use $crate::deck::form::{FieldKind, FieldMeta, FieldSpec, Presence};
        use $crate::units::Quantity;
        const fn meta(
            key: &'static str,
            label: &'static str,
            q: Quantity,
            min: (f64, bool),
            max: (f64, bool),
            help: &'static str,
        ) -> FieldMeta {
            FieldMeta::new(
                key,
                concat!("materials.", $body),
                label,
                q,
                FieldKind::Real,
                min,
                max,
                Presence::Required,
                help,
            )
        }
        [
            FieldSpec::<$T> {
                meta: meta(
                    concat!("materials.", $body, ".youngs_modulus"),
                    concat!($label, " Young's modulus E"),
                    Quantity::Pressure,
                    (0.0, true),
                    (1e13, false),
                    "Young's modulus",
                ),
                get: |$b: &$T| $path.youngs_modulus_pa,
                set: |$b: &mut $T, v| $path.youngs_modulus_pa = v,
            },
            FieldSpec::<$T> {
                meta: meta(
                    concat!("materials.", $body, ".poisson_ratio"),
                    concat!($label, " Poisson's ratio ν"),
                    Quantity::Dimensionless,
                    (0.0, false),
                    (0.5, true),
                    "Poisson's ratio",
                ),
                get: |$b: &$T| $path.poisson_ratio,
                set: |$b: &mut $T, v| $path.poisson_ratio = v,
            },
            FieldSpec::<$T> {
                meta: meta(
                    concat!("materials.", $body, ".density"),
                    concat!($label, " density ρ"),
                    Quantity::Density,
                    (0.0, true),
                    (1e5, false),
                    "mass density",
                ),
                get: |$b: &$T| $path.density_kg_m3,
                set: |$b: &mut $T, v| $path.density_kg_m3 = v,
            },
            FieldSpec::<$T> {
                meta: meta(
                    concat!("materials.", $body, ".specific_heat"),
                    concat!($label, " specific heat c"),
                    Quantity::SpecificHeat,
                    (0.0, true),
                    (1e5, false),
                    "specific heat capacity",
                ),
                get: |$b: &$T| $path.specific_heat_j_kg_k,
                set: |$b: &mut $T, v| $path.specific_heat_j_kg_k = v,
            },
            FieldSpec::<$T> {
                meta: meta(
                    concat!("materials.", $body, ".conductivity"),
                    concat!($label, " conductivity k"),
                    Quantity::Conductivity,
                    (0.0, true),
                    (1e4, false),
                    "thermal conductivity",
                ),
                get: |$b: &$T| $path.conductivity_w_m_k,
                set: |$b: &mut $T, v| $path.conductivity_w_m_k = v,
            },
        ]
    }};
}
pub use crate::__deck_material_fields as material_fields;

/// Formats a number to 6 significant digits without trailing zeros (for messages).
pub fn format_short(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-4..1e7).contains(&a) {
        let digits = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.digits$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{v:.5e}");
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                format!("{m}e{e}")
            }
            None => s,
        }
    }
}

/// Formats a real for a deck: rounded to 15 significant digits (hides last-bit noise
/// from unit conversion, 5e-16 relative), then the shortest TOML-valid representation.
pub(crate) fn fmt_real(v: f64) -> String {
    let rounded: f64 = format!("{v:.14e}").parse().unwrap_or(v);
    // Debug gives "17000.0", "1e-9", "2.5e16": all valid TOML floats.
    format!("{rounded:?}")
}

/// `key = value unit` in deck units, for cross-check rules naming another key's value,
/// e.g. `geometry.roller_diameter = 0.5 in`. Empty for an unknown key.
pub fn show<T>(schema: &Schema<T>, value: &T, key: &str, units: Units) -> String {
    schema.field(key).map_or_else(String::new, |f| {
        let v = f.from_si(f.get_si(value), units);
        let unit = f.unit(units);
        if unit.is_empty() {
            format!("{key} = {}", format_short(v))
        } else {
            format!("{key} = {} {unit}", format_short(v))
        }
    })
}

/// What is inconsistent in a schema (empty when it is sound): duplicate keys, a key
/// outside its group or its group not a table of the schema, an empty or inverted range,
/// a choice whose range is not its list, a one-of key whose partner does not name it
/// back, a material body without fields or presets, a default out of range, or a field
/// whose `set` then `get` does not give back the value of [`Schema::defaults`] (1e-12
/// relative). Call it in a system's tests.
pub fn schema_problems<T>(schema: &Schema<T>) -> Vec<String> {
    let mut p = Vec::new();
    let groups = schema.all_groups();
    for (i, f) in schema.fields.iter().enumerate() {
        if schema.fields[..i].iter().any(|g| g.key == f.key) {
            p.push(format!("{}: duplicate key", f.key));
        }
        if f.key != format!("{}.{}", f.group, f.name()) {
            p.push(format!("{}: not `{}.<name>`", f.key, f.group));
        }
        if !groups.contains(&f.top_group()) || schema.is_opaque(f.top_group()) {
            p.push(format!(
                "{}: table `{}` is not in groups",
                f.key,
                f.top_group()
            ));
        }
        if let Some(body) = f.group.strip_prefix("materials.") {
            if !schema.material_bodies.contains(&body) {
                p.push(format!("{}: `{body}` is not a material body", f.key));
            }
        }
        if f.min.partial_cmp(&f.max) != Some(std::cmp::Ordering::Less) {
            p.push(format!("{}: empty range", f.key));
        }
        if let FieldKind::Choice(list) = f.kind {
            if f.min != 0.0 || f.max != (list.len() as f64 - 1.0) {
                p.push(format!(
                    "{}: choice range is not 0..={}",
                    f.key,
                    list.len() - 1
                ));
            }
        }
        match f.presence {
            Presence::Default(v) if !f.in_range(v) => {
                p.push(format!("{}: default {v} out of range", f.key));
            }
            Presence::OneOf(other) => match schema.field(other) {
                Some(o) if o.presence == Presence::OneOf(f.key) && o.group == f.group => {}
                _ => p.push(format!(
                    "{}: one-of partner `{other}` does not name it back in the same table",
                    f.key
                )),
            },
            _ => {}
        }
        let d = (schema.defaults)();
        let v = f.get_si(&d);
        let mut c = (schema.defaults)();
        f.set_si(&mut c, v);
        let back = f.get_si(&c);
        if (back - v).abs() > 1e-12 * v.abs() {
            p.push(format!("{}: set then get gives {back}, not {v}", f.key));
        }
    }
    for b in schema.material_bodies {
        let group = format!("materials.{b}");
        let n = schema.fields.iter().filter(|f| f.group == group).count();
        if n == 0 && schema.material.is_none() {
            p.push(format!(
                "materials.{b}: neither fields nor presets (Schema::material)"
            ));
        }
    }
    if !schema.material_bodies.is_empty() && !groups.contains(&"materials") {
        p.push("material bodies without a `materials` group".into());
    }
    for g in schema.required_groups {
        if !groups.contains(g) {
            p.push(format!("required table `{g}` is not in groups"));
        }
    }
    p
}

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

struct Ctx<'a> {
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

fn preset_list() -> String {
    choice_list(&MATERIAL_PRESETS.iter().map(|p| p.0).collect::<Vec<_>>())
}

/// True if `text` names `key` as a whole key (not as the prefix of a longer key).
fn names_key(text: &str, key: &str) -> bool {
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

    // `type`: this schema's decks only; another system's deck (or an unknown system) is
    // refused at its line, naming the known systems.
    let id = schema.system;
    match root.get("type") {
        Some(item) if item.as_str() != Some(id) => {
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
        None if id != crate::bearings::DEFAULT_SYSTEM => {
            ctx.errors.push(DeckError::Missing {
                location: Location::start(source),
                key: "type".into(),
                hint: format!(
                    " (a deck without `type` is a \"{}\" deck; write type = \"{id}\")",
                    crate::bearings::DEFAULT_SYSTEM
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

    // cross-field rules, on valid keys only
    let invalid: Vec<&str> = schema
        .fields
        .iter()
        .map(|f| f.key)
        .filter(|k| !ctx.valid.contains_key(k))
        .collect();
    for (key, rule) in (schema.cross_checks)(&value, units) {
        if !ctx.valid.contains_key(key) || invalid.iter().any(|k| names_key(&rule, k)) {
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

/// Parses the editable document (comments kept) of already validated text.
pub(crate) fn parse_doc(text: &str, source: &str) -> Result<DocumentMut, DeckErrors> {
    text.parse::<DocumentMut>()
        .map_err(|e| DeckErrors::from(syntax_error(&e, text, source)))
}

// ---------------------------------------------------------------------------------
// Keys: the editable list, close matches, the `rollbench keys` table
// ---------------------------------------------------------------------------------

/// The editable keys inside an opaque table that its parser knows (for suggestions).
fn opaque_keys(table: &str) -> &'static [&'static str] {
    match table {
        "thermal" => super::thermal::EDITABLE_KEYS,
        _ => &[],
    }
}

/// A `&'static str` for a key built at run time (the `materials.<body>` keys): each
/// distinct string is leaked once, so the total is bounded by the schemas' bodies.
fn intern(s: String) -> &'static str {
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
            _ => f.allowed(u),
        };
        let _ = writeln!(
            s,
            "{:<40} {:<36} {}",
            f.key,
            allowed(Units::Si),
            allowed(Units::Us)
        );
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

/// Levenshtein distance of two short keys (characters).
fn edit_distance(a: &str, b: &str) -> usize {
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
fn unknown_key_hint<T>(schema: &Schema<T>, key: &str) -> String {
    let close = close_keys(schema, key);
    let list = "`rollbench keys` lists every editable key with its allowed range";
    if close.is_empty() {
        format!("unknown key ({list})")
    } else {
        format!("unknown key; did you mean {}? ({list})", close.join(", "))
    }
}

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
            key: key_path.to_string(),
            reason: reason.to_string(),
        })
    };
    if key_path == "units" {
        return Err(not_editable(
            "the unit system changes the meaning of every number; use Deck::converted",
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
        || spec.is_some_and(|s| matches!(s.kind, FieldKind::Choice(_)));
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
    for a in assignments {
        let Some((k, v)) = a.split_once('=') else {
            return Err(DeckError::NotEditable {
                key: a.to_string(),
                reason: format!("expected KEY=VALUE, e.g. --set {example}"),
            }
            .into());
        };
        edit(schema, &mut doc, value, units, k.trim(), v.trim())?;
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
        FieldKind::Real => fmt_real(spec.from_si(si, units)),
    })
}

/// Line and column of the deepest node of `path` inside the top-level table `table`
/// found in `doc`'s text: the field's value, else its entry, else the table's header.
pub(crate) fn location_in_table(
    doc: &DocumentMut,
    source: &str,
    table: &str,
    path: &[super::thermal::PathSeg],
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
        use super::thermal::PathSeg::{Index, Key};
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
    super::thermal::parse_thermal_located(t, units)
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

fn fmt_field<T>(spec: &FieldSpec<T>, v: &T, units: Units) -> String {
    let si = spec.get_si(v);
    match spec.kind {
        FieldKind::Real => fmt_real(spec.from_si(si, units)),
        FieldKind::Integer => format!("{}", si.round() as i64),
        FieldKind::Choice(list) => {
            format!("\"{}\"", list.get(si as usize).copied().unwrap_or(""))
        }
    }
}

fn unit_comment(spec: &FieldMeta, units: Units) -> String {
    let u = spec.unit(units);
    if u.is_empty() {
        String::new()
    } else {
        format!("  # {u}")
    }
}

/// True for the second key (in field order) of a one-of pair: written commented out.
fn is_second_of_pair<T>(schema: &Schema<T>, index: usize) -> bool {
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
/// [`crate::bearings::DEFAULT_SYSTEM`].
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
    } else if schema.system != crate::bearings::DEFAULT_SYSTEM {
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
    template_with(schema, units, &TemplateNotes::default())
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

// ---------------------------------------------------------------------------------
// Form
// ---------------------------------------------------------------------------------

/// A parsed, validated deck of one [`Schema`]: its unit system, the resolved SI value,
/// its opaque tables, and the source document (comments kept) for edits and saving.
#[derive(Clone)]
pub struct Form<T: 'static> {
    /// Unit system the deck is written in.
    pub units: Units,
    /// The resolved value, SI units.
    pub value: T,
    /// The deck's `name` (`"unnamed"` when absent).
    pub name: String,
    /// The opaque tables present in the deck, as written.
    pub opaque: BTreeMap<String, toml::Table>,
    source_name: String,
    doc: DocumentMut,
    schema: &'static Schema<T>,
}

impl<T: std::fmt::Debug> std::fmt::Debug for Form<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Form")
            .field("system", &self.schema.system)
            .field("units", &self.units)
            .field("name", &self.name)
            .field("value", &self.value)
            .field("source_name", &self.source_name)
            .finish_non_exhaustive()
    }
}

impl<T: Clone> Form<T> {
    /// Parses and validates deck text; `source_name` (e.g. a file name) prefixes every
    /// error location. All errors found are returned together.
    pub fn parse(
        text: &str,
        source_name: &str,
        schema: &'static Schema<T>,
    ) -> Result<Self, DeckErrors> {
        let parsed = validate(text, source_name, schema)?;
        let doc = parse_doc(text, source_name)?;
        Ok(Form {
            units: parsed.units,
            value: parsed.value,
            name: parsed.name,
            opaque: parsed.opaque,
            source_name: source_name.to_string(),
            doc,
            schema,
        })
    }

    /// Reads and parses a deck file (at most [`super::MAX_DECK_BYTES`]); errors name
    /// the file.
    pub fn load(path: &Path, schema: &'static Schema<T>) -> Result<Self, DeckErrors> {
        let text = super::read_deck_text(path)?;
        Form::parse(&text, &path.display().to_string(), schema)
    }

    fn revalidate(&mut self, doc: DocumentMut) -> Result<(), DeckErrors> {
        let parsed = validate(&doc.to_string(), &self.source_name, self.schema)?;
        self.units = parsed.units;
        self.value = parsed.value;
        self.name = parsed.name;
        self.opaque = parsed.opaque;
        self.doc = doc;
        Ok(())
    }

    /// Applies `key.path=value` assignments (as for `--set`, deck units): every one is
    /// written into the deck first, then the result is validated once, so the order of
    /// the assignments never changes the verdict. On any error the deck is unchanged.
    pub fn apply_assignments(&mut self, assignments: &[String]) -> Result<(), DeckErrors> {
        if assignments.is_empty() {
            return Ok(());
        }
        let example = self
            .schema
            .fields
            .iter()
            .find(|f| f.kind == FieldKind::Real)
            .map_or_else(
                || "name=example".to_string(),
                |f| {
                    format!(
                        "{}={}",
                        f.key,
                        format_short(f.from_si(f.get_si(&self.value), self.units))
                    )
                },
            );
        let doc = write_assignments(
            self.schema,
            &self.doc,
            &self.value,
            self.units,
            assignments,
            &example,
        )?;
        self.revalidate(doc)
    }

    /// Sets one value, written in the deck's own units. Comments are kept; the whole
    /// deck is re-validated. On error the deck is unchanged.
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), DeckErrors> {
        let mut doc = self.doc.clone();
        edit(self.schema, &mut doc, &self.value, self.units, key, value)?;
        self.revalidate(doc)
    }

    /// The value of `key` as written in the deck (deck units; strings unquoted), or for
    /// a field not written the value in effect. `None` for unknown keys.
    pub fn get(&self, key: &str) -> Option<String> {
        get(self.schema, &self.doc, &self.value, self.units, key)
    }

    /// The deck as TOML text, comments and layout preserved.
    pub fn to_toml_string(&self) -> String {
        self.doc.to_string()
    }

    /// The same deck written in `units`: a clean regenerated deck (comments other than
    /// unit hints are not carried over; opaque tables are).
    pub fn converted(&self, units: Units) -> Self {
        let header = converted_header(&self.name, self.units);
        let text = write_deck(
            self.schema,
            &DeckText {
                value: &self.value,
                units,
                name: &self.name,
                opaque: &self.opaque,
                header: &header,
                commented: false,
                notes: &TemplateNotes::default(),
            },
        );
        let doc = text.parse::<DocumentMut>().unwrap_or_default();
        Form {
            units,
            value: self.value.clone(),
            name: self.name.clone(),
            opaque: self.opaque.clone(),
            source_name: self.source_name.clone(),
            doc,
            schema: self.schema,
        }
    }

    /// Saves the deck atomically: temporary file in the same directory, fsync, the
    /// previous file kept as `<file name>.bak`, then rename (see [`crate::files`]).
    pub fn save(&self, path: &Path) -> Result<crate::files::Written, DeckErrors> {
        save_text(path, &self.to_toml_string())
    }

    /// The thermal network of the deck's `[thermal]` table, for a schema that lists
    /// `"thermal"` in [`Schema::opaque_tables`] (`None` when the deck has none); errors
    /// name node, link and field, with their line and column.
    pub fn thermal_model(&self) -> Result<Option<crate::thermal::ThermalModel>, DeckErrors> {
        thermal_model_of(
            &self.doc,
            &self.source_name,
            self.opaque.get("thermal"),
            self.units,
        )
    }

    /// The source name given to [`Form::parse`].
    pub fn source_name(&self) -> &str {
        &self.source_name
    }

    /// The schema this deck was read with.
    pub fn schema(&self) -> &'static Schema<T> {
        self.schema
    }
}

#[cfg(test)]
mod tests;
