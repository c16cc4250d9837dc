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
//! [`crate::deck::DEFAULT_TYPE`] deck may omit it), `units` (`"us"` | `"si"`,
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
    /// A real number (as [`FieldKind::Real`], range-checked), or this one word, which
    /// stands for "computed instead" (the cylindrical roller's `contact_stiffness =
    /// "lamina"`, `cage_speed = "kinematic"`); the word's SI value is NaN (outside every
    /// range, so no number can be mistaken for it), and a `Presence::Default(f64::NAN)`
    /// makes the word the default.
    RealOr(&'static str),
}

/// The choice list of a yes/no key: `FieldKind::Choice(BOOL)` reads a TOML boolean
/// (`gravity = true`; the strings "true"/"false" too) and writes a bare boolean; the SI
/// value is 0 for false, 1 for true.
pub const BOOL: &[&str] = &["false", "true"];

/// True for the yes/no choice list [`BOOL`].
pub fn is_bool(list: &[&str]) -> bool {
    list == BOOL
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

    /// The allowed range in deck units, e.g. `0 < value ≤ 39.37 in`. Each printed bound
    /// is itself accepted: a bound that does not convert to a short number exactly is
    /// rounded inward (39.370078… in is shown as 39.37, not as 39.3701, which the check
    /// refuses) and then shown with `≤`, since the printed value lies inside the range.
    pub fn allowed(&self, units: Units) -> String {
        let (lo, lo_op) = self.bound_text(self.min, self.min_exclusive, false, units);
        let (hi, hi_op) = self.bound_text(self.max, self.max_exclusive, true, units);
        let unit = self.unit(units);
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        format!("{lo} {lo_op} value {hi_op} {hi}{unit}")
    }

    /// One bound in deck units and its operator: the short form when it is the bound
    /// exactly (or, for an inclusive bound, when it is accepted), else the bound rounded
    /// toward the inside of the range at 6, 7, … significant digits until the printed
    /// number is accepted, with `≤`.
    fn bound_text(
        &self,
        si: f64,
        exclusive: bool,
        upper: bool,
        units: Units,
    ) -> (String, &'static str) {
        let op = if exclusive { "<" } else { "≤" };
        let x = self.from_si(si, units);
        let short = format_short(x);
        let back = |t: &str| t.parse::<f64>().ok().map(|v| self.to_si(v, units));
        match back(&short) {
            Some(v) if v == si => return (short, op),
            Some(v) if !exclusive && self.in_range(v) => return (short, op),
            _ => {}
        }
        if !x.is_finite() || x == 0.0 {
            return (short, op);
        }
        for digits in 6..=17 {
            // x·10^e rounded to an integer, then divided back by the exact power of ten
            // (or multiplied, for e < 0): the quotient is the double nearest the decimal.
            let e = digits - 1 - x.abs().log10().floor() as i32;
            let round = |m: f64| if upper { m.floor() } else { m.ceil() };
            let inward = if e >= 0 {
                let p = 10f64.powi(e);
                round(x * p) / p
            } else {
                let p = 10f64.powi(-e);
                round(x / p) * p
            };
            let short = format_short(inward);
            let text = if short.parse::<f64>().ok() == Some(inward) {
                short
            } else if (1e-4..1e7).contains(&inward.abs()) {
                format!("{inward}")
            } else {
                format!("{inward:e}")
            };
            if back(&text).is_some_and(|v| self.in_range(v)) {
                return (text, "≤");
            }
        }
        (short, op)
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

/// Two keys giving one ring degree of freedom two ways ([`Schema::one_holding`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OneHolding {
    /// The key applying a load (force or moment). A [`FieldKind::RealOr`] key written
    /// as its word (`"held"`) applies none.
    pub load: &'static str,
    /// The key holding a displacement (or rotation).
    pub displacement: &'static str,
    /// The degree of freedom, for the message ("the ring's tilt about y").
    pub dof: &'static str,
}

/// What one bearing system's deck looks like.
pub struct Schema<T: 'static> {
    /// The deck's `type`. Only [`crate::deck::DEFAULT_TYPE`] decks may omit it.
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
    /// Pairs of keys that hold the same ring degree of freedom, one by a load, the other
    /// by a displacement (issue 29: a deck gives each degree of freedom one way): a deck
    /// writing both is refused, naming both keys and their lines.
    pub one_holding: &'static [OneHolding],
    /// The first comment lines of [`template`] (without `# `).
    pub template_header: &'static str,
    /// Comment lines of the template (and of a unit-converted deck) beyond the field
    /// lines: the template's `name`, notes under table headers, the stand-ins for absent
    /// opaque tables.
    pub template_notes: TemplateNotes,
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
        let si = f.get_si(value);
        if let (FieldKind::RealOr(word), true) = (f.kind, si.is_nan()) {
            return format!("{key} = \"{word}\"");
        }
        let v = f.from_si(si, units);
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
            Presence::Default(v) if v.is_nan() && matches!(f.kind, FieldKind::RealOr(_)) => {}
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

mod edit;
mod keys;
mod validate;
pub(crate) use validate::syntax_error;
mod write;

pub(crate) use edit::*;
pub use keys::*;
pub(crate) use validate::*;
pub use write::*;

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
                notes: &self.schema.template_notes,
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

    /// Where `path` (keys and array indices) inside the top-level table `table` stands
    /// in the deck text: the deepest node found (a value, its entry, else the table's
    /// header; the file start when the table is absent). For a system that parses one of
    /// its opaque tables itself and reports errors at file:line.
    pub fn location_in(&self, table: &str, path: &[crate::deck::thermal::PathSeg]) -> Location {
        location_in_table(&self.doc, &self.source_name, table, path)
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
