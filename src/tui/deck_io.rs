//! Thin adapter between the TUI and the deck module: the only TUI file that knows how a
//! deck is parsed, edited, converted and saved.
//!
//! STUB until branch `deck` is merged: the deck is a TOML serialisation of [`Bearing`]
//! and a small field table stands in for `deck::fields()`.

use std::path::Path;

use crate::model::Bearing;

/// Unit system for display and for deck values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Units {
    /// SI.
    #[default]
    Si,
    /// US customary.
    Us,
}

impl Units {
    /// `"SI"` or `"US"`.
    pub fn label(self) -> &'static str {
        match self {
            Units::Si => "SI",
            Units::Us => "US",
        }
    }
}

/// Flips SI ↔ US.
pub fn other_units(u: Units) -> Units {
    match u {
        Units::Si => Units::Us,
        Units::Us => Units::Si,
    }
}

#[derive(Clone, Copy)]
enum Q {
    Length,
    Angle,
    Speed,
    Force,
    Count,
    Plain,
}

impl Q {
    fn factor(self, u: Units) -> f64 {
        match (self, u) {
            (Q::Length, Units::Si) => 1.0,
            (Q::Length, Units::Us) => 0.0254,
            (Q::Angle, _) => std::f64::consts::PI / 180.0,
            (Q::Speed, _) => std::f64::consts::PI / 30.0,
            (Q::Force, Units::Si) => 1.0,
            (Q::Force, Units::Us) => 4.448_221_615_260_5,
            (Q::Count | Q::Plain, _) => 1.0,
        }
    }
    fn unit(self, u: Units) -> &'static str {
        match (self, u) {
            (Q::Length, Units::Si) => "m",
            (Q::Length, Units::Us) => "in",
            (Q::Angle, _) => "deg",
            (Q::Speed, _) => "rpm",
            (Q::Force, Units::Si) => "N",
            (Q::Force, Units::Us) => "lbf",
            (Q::Count | Q::Plain, _) => "",
        }
    }
}

struct Spec {
    key: &'static str,
    group: &'static str,
    label: &'static str,
    q: Q,
    min: f64,
    max: f64,
    get: fn(&Bearing) -> f64,
    set: fn(&mut Bearing, f64),
}

const SPECS: &[Spec] = &[
    Spec {
        key: "geometry.roller_count",
        group: "geometry",
        label: "Z rollers",
        q: Q::Count,
        min: 3.0,
        max: 200.0,
        get: |b| b.geometry.roller_count as f64,
        set: |b, v| b.geometry.roller_count = v.round() as usize,
    },
    Spec {
        key: "geometry.roller_diameter",
        group: "geometry",
        label: "D roller dia.",
        q: Q::Length,
        min: 1e-4,
        max: 1.0,
        get: |b| b.geometry.roller_diameter_m,
        set: |b, v| b.geometry.roller_diameter_m = v,
    },
    Spec {
        key: "geometry.effective_length",
        group: "geometry",
        label: "L_eff eff. length",
        q: Q::Length,
        min: 1e-4,
        max: 1.0,
        get: |b| b.geometry.effective_length_m,
        set: |b, v| b.geometry.effective_length_m = v,
    },
    Spec {
        key: "geometry.pitch_diameter",
        group: "geometry",
        label: "P_t pitch dia.",
        q: Q::Length,
        min: 1e-3,
        max: 5.0,
        get: |b| b.geometry.pitch_diameter_m,
        set: |b, v| b.geometry.pitch_diameter_m = v,
    },
    Spec {
        key: "geometry.contact_angle",
        group: "geometry",
        label: "β contact angle",
        q: Q::Angle,
        min: 0.0,
        max: 45.0_f64 * 0.017_453_292_519_943_295,
        get: |b| b.geometry.contact_angle_rad,
        set: |b, v| b.geometry.contact_angle_rad = v,
    },
    Spec {
        key: "geometry.diametral_clearance",
        group: "geometry",
        label: "diametral clearance",
        q: Q::Length,
        min: -1e-3,
        max: 1e-3,
        get: |b| b.geometry.diametral_clearance_m,
        set: |b, v| b.geometry.diametral_clearance_m = v,
    },
    Spec {
        key: "operating.inner_speed",
        group: "operating",
        label: "Ω₁ inner speed",
        q: Q::Speed,
        min: -1e5,
        max: 1e5,
        get: |b| b.operating.inner_speed_rad_s,
        set: |b, v| b.operating.inner_speed_rad_s = v,
    },
    Spec {
        key: "operating.outer_speed",
        group: "operating",
        label: "Ω₂ outer speed",
        q: Q::Speed,
        min: -1e5,
        max: 1e5,
        get: |b| b.operating.outer_speed_rad_s,
        set: |b, v| b.operating.outer_speed_rad_s = v,
    },
    Spec {
        key: "operating.radial_load",
        group: "operating",
        label: "F_r radial load",
        q: Q::Force,
        min: 0.0,
        max: 1e7,
        get: |b| b.operating.radial_load_n,
        set: |b, v| b.operating.radial_load_n = v,
    },
    Spec {
        key: "operating.axial_load",
        group: "operating",
        label: "F_a axial load",
        q: Q::Force,
        min: -1e7,
        max: 1e7,
        get: |b| b.operating.axial_load_n,
        set: |b, v| b.operating.axial_load_n = v,
    },
    Spec {
        key: "solver.laminae",
        group: "solver",
        label: "Γ laminae",
        q: Q::Count,
        min: 1.0,
        max: 2000.0,
        get: |b| b.solver.laminae as f64,
        set: |b, v| b.solver.laminae = v.round() as usize,
    },
    Spec {
        key: "solver.max_iterations",
        group: "solver",
        label: "max iterations",
        q: Q::Count,
        min: 1.0,
        max: 1e5,
        get: |b| b.solver.max_iterations as f64,
        set: |b, v| b.solver.max_iterations = v.round() as usize,
    },
    Spec {
        key: "solver.force_tolerance",
        group: "solver",
        label: "force tolerance",
        q: Q::Plain,
        min: 1e-16,
        max: 0.1,
        get: |b| b.solver.force_tolerance,
        set: |b, v| b.solver.force_tolerance = v,
    },
];

fn spec(key: &str) -> Option<&'static Spec> {
    SPECS.iter().find(|s| s.key == key)
}

/// One editable deck field as the inputs pane lists it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldInfo {
    /// Full key path, e.g. `geometry.pitch_diameter`.
    pub key: &'static str,
    /// Group (deck table) the key lives in.
    pub group: &'static str,
    /// Short label with the seed's symbol.
    pub label: &'static str,
}

/// Every editable field, in deck order.
pub fn field_list() -> Vec<FieldInfo> {
    SPECS
        .iter()
        .map(|s| FieldInfo {
            key: s.key,
            group: s.group,
            label: s.label,
        })
        .collect()
}

/// Unit label of `key` in `units` (empty for dimensionless).
pub fn unit(key: &str, units: Units) -> &'static str {
    spec(key).map(|s| s.q.unit(units)).unwrap_or("")
}

/// Allowed range of `key` in `units`, for inline validation messages.
pub fn allowed(key: &str, units: Units) -> String {
    match spec(key) {
        Some(s) => {
            let f = s.q.factor(units);
            let u = s.q.unit(units);
            format!(
                "{} ≤ value ≤ {} {u}",
                fmt_num(s.min / f),
                fmt_num(s.max / f)
            )
            .trim_end()
            .to_string()
        }
        None => String::new(),
    }
}

fn fmt_num(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".into()
    } else if (1e-3..1e6).contains(&a) {
        let s = format!("{v:.6}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.4e}")
    }
}

/// Default deck text (the aerospace example).
pub fn default_text() -> String {
    toml::to_string(&Bearing::example_aerospace()).unwrap_or_default()
}

/// A deck under edit.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckDoc {
    units: Units,
    bearing: Bearing,
    source_name: String,
}

impl DeckDoc {
    /// Parses and validates deck text; errors are one readable message.
    pub fn parse(text: &str, source_name: &str) -> Result<DeckDoc, String> {
        let bearing: Bearing = toml::from_str(text).map_err(|e| format!("{source_name}: {e}"))?;
        Ok(DeckDoc {
            units: Units::Us,
            bearing,
            source_name: source_name.to_string(),
        })
    }

    /// Reads and parses a deck file.
    pub fn load(path: &Path) -> Result<DeckDoc, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        DeckDoc::parse(&text, &path.display().to_string())
    }

    /// Saves atomically (temporary file then rename; previous file kept as `.bak`).
    pub fn save(&self, path: &Path) -> Result<(), String> {
        let tmp = path.with_extension("toml.tmp");
        std::fs::write(&tmp, self.text())
            .map_err(|e| format!("cannot write {}: {e}", tmp.display()))?;
        if path.exists() {
            let _ = std::fs::copy(path, path.with_extension("toml.bak"));
        }
        std::fs::rename(&tmp, path).map_err(|e| format!("cannot save {}: {e}", path.display()))
    }

    /// Unit system the deck is written in.
    pub fn units(&self) -> Units {
        self.units
    }

    /// The resolved SI bearing.
    pub fn bearing(&self) -> &Bearing {
        &self.bearing
    }

    /// Bearing name.
    pub fn name(&self) -> &str {
        &self.bearing.name
    }

    /// True if the deck has a thermal model.
    pub fn has_thermal(&self) -> bool {
        false
    }

    /// The deck as text (what a save writes).
    pub fn text(&self) -> String {
        toml::to_string(&self.bearing).unwrap_or_default()
    }

    /// The value of `key` formatted in `display` units (`—` for unknown keys).
    pub fn value(&self, key: &str, display: Units) -> String {
        match spec(key) {
            Some(s) => {
                let v = (s.get)(&self.bearing) / s.q.factor(display);
                match s.q {
                    Q::Count => format!("{}", v.round() as i64),
                    _ => fmt_num(v),
                }
            }
            None => "—".into(),
        }
    }

    /// Sets `key` from `text` written in `display` units. Validates; on error the deck
    /// is unchanged and the message includes the allowed range.
    pub fn set_value(&mut self, key: &str, text: &str, display: Units) -> Result<(), String> {
        let s = spec(key).ok_or_else(|| format!("{key}: not editable"))?;
        let v: f64 = text
            .trim()
            .parse()
            .map_err(|_| format!("not a number: {:?}", text.trim()))?;
        let si = v * s.q.factor(display);
        if !(si.is_finite() && si >= s.min && si <= s.max) {
            return Err(format!("out of range: {}", allowed(key, display)));
        }
        (s.set)(&mut self.bearing, si);
        Ok(())
    }
}
