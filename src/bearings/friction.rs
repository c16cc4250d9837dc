//! A bearing's friction by mechanism, the same object for every system (issue 28 item 4):
//! JSON `friction` {`torque_nm`, `power_w`, `by_mechanism` {name: W}} and the heat sources
//! the thermal network receives.
//!
//! The power identity is the check every system's friction must pass: the mechanisms'
//! powers add up to the total, and the total is the friction torque times the rings'
//! relative speed, `P = M·|ω_i − ω_o|` (a bearing's friction torque is *defined* as the
//! torque whose power at the relative speed equals the dissipated power).

use serde_json::{json, Map, Value};

use crate::thermal::{HeatInput, HeatSource};

/// One friction mechanism's dissipated power.
#[derive(Debug, Clone, PartialEq)]
pub struct Mechanism {
    /// JSON key under `by_mechanism` (snake_case, a contract once shipped), e.g.
    /// `"inner_raceway_rolling"`, `"flange_sliding"`, `"spin"`, `"viscous_drag"`.
    pub name: &'static str,
    /// Dissipated power, W (≥ 0).
    pub power_w: f64,
    /// Where the thermal network releases this heat; `None`: not bound to a node kind
    /// (the system says why in its docs).
    pub heat: Option<HeatSource>,
}

/// A bearing's friction: the torque at the rings' relative speed and its mechanisms.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionBreakdown {
    /// Friction torque, N·m: total power / |ω_i − ω_o|.
    pub torque_nm: f64,
    /// |ω_i − ω_o|, rad/s (the speed the torque is referred to).
    pub relative_speed_rad_s: f64,
    /// The mechanisms, in the order the system lists them (the JSON keeps that order).
    pub mechanisms: Vec<Mechanism>,
}

impl FrictionBreakdown {
    /// The breakdown of `mechanisms` at the relative speed `relative_speed_rad_s`; the
    /// torque follows from the power identity (0 N·m at standstill).
    pub fn from_mechanisms(relative_speed_rad_s: f64, mechanisms: Vec<Mechanism>) -> Self {
        let speed = relative_speed_rad_s.abs();
        let power: f64 = mechanisms.iter().map(|m| m.power_w).sum();
        let torque_nm = if speed > 0.0 { power / speed } else { 0.0 };
        Self {
            torque_nm,
            relative_speed_rad_s: speed,
            mechanisms,
        }
    }

    /// The breakdown at the rings' speeds `inner_rad_s`, `outer_rad_s` with the torque
    /// convention of [`crate::physics::heat::HeatBreakdown`]: torque = Σ P/|ω_i − ω_o|, 0 N·m
    /// when |ω_i − ω_o| is below [`crate::physics::heat::MIN_RELATIVE_SPEED_RAD_S`] or not
    /// finite (no relative rotation, no torque defined). Σ P is summed in the mechanisms'
    /// order, so a system that lists them in its own total's order gets the same bits.
    pub fn at_ring_speeds(inner_rad_s: f64, outer_rad_s: f64, mechanisms: Vec<Mechanism>) -> Self {
        let rel = (inner_rad_s - outer_rad_s).abs();
        let mut f = Self::from_mechanisms(if rel.is_finite() { rel } else { 0.0 }, mechanisms);
        if !(rel.is_finite() && rel >= crate::physics::heat::MIN_RELATIVE_SPEED_RAD_S) {
            f.torque_nm = 0.0;
        }
        f
    }

    /// Total dissipated power, W: the sum of the mechanisms.
    pub fn power_w(&self) -> f64 {
        self.mechanisms.iter().map(|m| m.power_w).sum()
    }

    /// Power of the mechanism named `name`, W (0 if absent).
    pub fn mechanism_w(&self, name: &str) -> f64 {
        self.mechanisms
            .iter()
            .filter(|m| m.name == name)
            .map(|m| m.power_w)
            .sum()
    }

    /// `(name, W)` pairs, for [`super::answer::largest_mechanism`].
    pub fn pairs(&self) -> Vec<(&'static str, f64)> {
        self.mechanisms
            .iter()
            .map(|m| (m.name, m.power_w))
            .collect()
    }

    /// Relative residual of the power identity |Σ P − M·Δω| / max(Σ P, tiny).
    pub fn power_identity_residual(&self) -> f64 {
        let p = self.power_w();
        let scale = p.abs().max(f64::MIN_POSITIVE);
        if self.relative_speed_rad_s > 0.0 {
            (p - self.torque_nm * self.relative_speed_rad_s).abs() / scale
        } else {
            0.0
        }
    }

    /// The heat the thermal network receives: each bound mechanism's power at its source.
    pub fn heat_input(&self) -> HeatInput {
        self.mechanisms
            .iter()
            .filter_map(|m| m.heat.map(|s| (s, m.power_w)))
            .fold(HeatInput::new(), |h, (s, w)| h.with(s, w))
    }

    /// JSON `friction`: {`torque_nm`, `power_w`, `relative_speed_rad_s`, `by_mechanism`}.
    pub fn json(&self) -> Value {
        let mut by = Map::new();
        for m in &self.mechanisms {
            let w = by.get(m.name).and_then(Value::as_f64).unwrap_or(0.0) + m.power_w;
            by.insert(m.name.to_string(), json!(w));
        }
        json!({
            "torque_nm": self.torque_nm,
            "power_w": self.power_w(),
            "relative_speed_rad_s": self.relative_speed_rad_s,
            "by_mechanism": Value::Object(by),
        })
    }
}

/// The optional `[cage]` section of the ball and tapered decks (issue 28 item 4), with the
/// spherical roller's keys and laws (seed 000 §9.3–9.4), so every system names its cage and
/// churning losses the same way:
/// - `cage.drag_factor` f₀: Palmgren's load-independent viscous moment
///   M₀ = 10⁻⁷·f₀·(ν·n)^(2/3)·d_m³ N·mm (eq. 9.5) at the rings' relative speed, mechanism
///   `viscous_drag` (heat into the oil). Palmgren's published f₀ (Harris & Kotzalas,
///   *Essential Concepts of Bearing Technology*, 5th ed., Table 12.1) are for the whole M₀,
///   which in his fit also holds the contacts' hydrodynamic rolling loss: with the EHL
///   rolling resistance computed per contact, f₀ stands for the churning alone, and the
///   table's value is an upper estimate (docs/friction.md says so).
/// - `cage.rail_width`, `cage.mean_diameter`, `cage.diametral_clearance`, `cage.guided_by`:
///   a land-guided cage's rails, Petroff shear at the cage's slip over the guiding ring
///   (eqs. 9.3–9.4), mechanism `cage_rails`. A cage guided by its rolling elements (the
///   usual pressed-steel tapered cage) has no rails: leave `rail_width` out; its pocket
///   forces in steady running only balance its own drag, which f₀ covers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageLosses {
    /// f₀, dimensionless; NaN: no `cage.drag_factor` (no `viscous_drag` mechanism).
    pub drag_factor: f64,
    /// W_cr, total rail width, m; NaN: no rails (no `cage_rails` mechanism).
    pub rail_width_m: f64,
    /// D_cr, mean rail/land diameter, m (NaN: not given).
    pub mean_diameter_m: f64,
    /// dc_cr, diametral rail clearance, m (NaN: not given).
    pub diametral_clearance_m: f64,
    /// The ring whose land guides the cage.
    pub guided_by: crate::physics::heat::GuidingRing,
}

impl Default for CageLosses {
    fn default() -> Self {
        Self {
            drag_factor: f64::NAN,
            rail_width_m: f64::NAN,
            mean_diameter_m: f64::NAN,
            diametral_clearance_m: f64::NAN,
            guided_by: crate::physics::heat::GuidingRing::Outer,
        }
    }
}

/// The five `[cage]` field specs of a deck type whose [`CageLosses`] is reached by
/// `|b| b.cage` (the ball and tapered decks; the spherical roller's keys and ranges):
///
/// ```ignore
/// const CAGE: [FieldSpec<BallInput>; 5] = cage_loss_fields!(BallInput, |b| b.cage);
/// ```
#[macro_export]
#[doc(hidden)]
macro_rules! __cage_loss_fields {
    ($T:ty, |$b:ident| $path:expr) => {{
        use $crate::deck::form::{FieldKind, FieldMeta, FieldSpec, Presence};
        use $crate::physics::heat::GuidingRing;
        use $crate::units::Quantity;
        const fn optional(
            key: &'static str,
            label: &'static str,
            q: Quantity,
            min: (f64, bool),
            max: (f64, bool),
            help: &'static str,
        ) -> FieldMeta {
            FieldMeta::new(
                key,
                "cage",
                label,
                q,
                FieldKind::RealOr("none"),
                min,
                max,
                Presence::Default(f64::NAN),
                help,
            )
        }
        [
            FieldSpec::<$T> {
                meta: optional(
                    "cage.drag_factor",
                    "Drag factor f₀",
                    Quantity::Dimensionless,
                    (0.0, false),
                    (100.0, false),
                    "Palmgren's f₀ of the churning (viscous drag) moment M₀ = 1e-7·f₀·(ν·n)^(2/3)·d_m³ N·mm (seed 000 eq. 9.5), mechanism viscous_drag; \"none\" (the default): no drag",
                ),
                get: |$b: &$T| $path.drag_factor,
                set: |$b: &mut $T, v| $path.drag_factor = v,
            },
            FieldSpec::<$T> {
                meta: optional(
                    "cage.rail_width",
                    "Cage rail width W_cr",
                    Quantity::Length,
                    (0.0, true),
                    (1.0, false),
                    "total width of a land-guided cage's rails for their Petroff shear (seed 000 eqs. 9.3–9.4), mechanism cage_rails; \"none\" (the default): the cage is guided by its rolling elements, no rails",
                ),
                get: |$b: &$T| $path.rail_width_m,
                set: |$b: &mut $T, v| $path.rail_width_m = v,
            },
            FieldSpec::<$T> {
                meta: optional(
                    "cage.mean_diameter",
                    "Cage rail diameter D_cr",
                    Quantity::Length,
                    (0.0, true),
                    (10.0, false),
                    "mean diameter of the cage rail/land interface (needed with cage.rail_width)",
                ),
                get: |$b: &$T| $path.mean_diameter_m,
                set: |$b: &mut $T, v| $path.mean_diameter_m = v,
            },
            FieldSpec::<$T> {
                meta: optional(
                    "cage.diametral_clearance",
                    "Cage rail clearance",
                    Quantity::Length,
                    (0.0, true),
                    (0.1, false),
                    "diametral clearance between the cage rails and the guiding land (needed with cage.rail_width)",
                ),
                get: |$b: &$T| $path.diametral_clearance_m,
                set: |$b: &mut $T, v| $path.diametral_clearance_m = v,
            },
            FieldSpec::<$T> {
                meta: FieldMeta::new(
                    "cage.guided_by",
                    "cage",
                    "Cage guided by",
                    Quantity::Dimensionless,
                    FieldKind::Choice(&["inner", "outer"]),
                    (0.0, false),
                    (1.0, false),
                    Presence::Default(1.0),
                    "the ring whose land guides the cage (used with cage.rail_width)",
                ),
                get: |$b: &$T| match $path.guided_by {
                    GuidingRing::Inner => 0.0,
                    GuidingRing::Outer => 1.0,
                },
                set: |$b: &mut $T, v| {
                    $path.guided_by = if v as usize == 0 {
                        GuidingRing::Inner
                    } else {
                        GuidingRing::Outer
                    }
                },
            },
        ]
    }};
}
pub use crate::__cage_loss_fields as cage_loss_fields;

/// The operating state [`CageLosses::mechanisms`] needs, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CageState {
    /// η, dynamic viscosity in the bearing, Pa·s.
    pub viscosity_pa_s: f64,
    /// ρ, oil density, kg/m³ (ν = η/ρ for Palmgren's M₀).
    pub density_kg_m3: f64,
    /// Ω₁, Ω₂: inner and outer ring speeds, rad/s.
    pub inner_rad_s: f64,
    /// Outer ring speed, rad/s.
    pub outer_rad_s: f64,
    /// Ω_cg, cage speed, rad/s.
    pub cage_rad_s: f64,
    /// d_m, pitch diameter, m.
    pub pitch_diameter_m: f64,
}

impl CageLosses {
    /// True when the deck gives any cage-loss key.
    pub fn is_given(&self) -> bool {
        self.drag_factor.is_finite() || self.rail_width_m.is_finite()
    }

    /// Which rail keys are missing when `rail_width` is given (a person-readable list).
    pub fn missing_rail_keys(&self) -> Vec<&'static str> {
        if !self.rail_width_m.is_finite() {
            return Vec::new();
        }
        let mut v = Vec::new();
        if !self.mean_diameter_m.is_finite() {
            v.push("cage.mean_diameter");
        }
        if !self.diametral_clearance_m.is_finite() {
            v.push("cage.diametral_clearance");
        }
        v
    }

    /// The deck rule both systems with a `[cage]` section check (issue 28): a land-guided
    /// cage (`cage.rail_width` given) needs all its rail keys. The field to name and the
    /// message, or `None` when the rails are whole or absent.
    pub fn rail_key_problem(&self) -> Option<(&'static str, String)> {
        let missing = self.missing_rail_keys();
        (!missing.is_empty()).then(|| {
            (
                "cage.rail_width",
                format!(
                    "is given, so the cage is land-guided: give {} too (or leave cage.rail_width out for a cage guided by its rolling elements)",
                    missing.join(" and ")
                ),
            )
        })
    }

    /// The `viscous_drag` and `cage_rails` mechanisms the deck asks for, in that order
    /// (none when neither is given). Errors (phrased for a person) when a rail key is
    /// missing or the Petroff law refuses its inputs (zero clearance).
    pub fn mechanisms(&self, s: &CageState) -> Result<Vec<Mechanism>, String> {
        use crate::physics::heat;
        let mut out = Vec::new();
        if self.drag_factor.is_finite() {
            let nu = if s.density_kg_m3 > 0.0 {
                s.viscosity_pa_s / s.density_kg_m3
            } else {
                return Err(format!(
                    "cage.drag_factor needs the oil's density for ν = η/ρ (got {} kg/m³)",
                    s.density_kg_m3
                ));
            };
            out.push(Mechanism {
                name: "viscous_drag",
                power_w: heat::viscous_drag_power_w(
                    self.drag_factor,
                    nu,
                    s.inner_rad_s - s.outer_rad_s,
                    s.pitch_diameter_m,
                ),
                heat: Some(HeatSource::ViscousDrag),
            });
        }
        if self.rail_width_m.is_finite() {
            let missing = self.missing_rail_keys();
            if !missing.is_empty() {
                return Err(format!(
                    "cage.rail_width is given, so the cage is land-guided: give {} too (or leave cage.rail_width out for a cage guided by its rolling elements)",
                    missing.join(" and ")
                ));
            }
            let guide = match self.guided_by {
                heat::GuidingRing::Inner => s.inner_rad_s,
                heat::GuidingRing::Outer => s.outer_rad_s,
            };
            let p = heat::cage_rail_power_w(
                s.viscosity_pa_s,
                self.rail_width_m,
                self.mean_diameter_m,
                self.diametral_clearance_m,
                s.cage_rad_s - guide,
            )
            .map_err(|e| format!("cage rails: {e}"))?;
            out.push(Mechanism {
                name: "cage_rails",
                power_w: p,
                heat: Some(HeatSource::CageRails),
            });
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> FrictionBreakdown {
        FrictionBreakdown::from_mechanisms(
            -100.0,
            vec![
                Mechanism {
                    name: "inner_raceway",
                    power_w: 30.0,
                    heat: Some(HeatSource::InnerContacts),
                },
                Mechanism {
                    name: "outer_raceway",
                    power_w: 50.0,
                    heat: Some(HeatSource::OuterContacts),
                },
                Mechanism {
                    name: "viscous_drag",
                    power_w: 20.0,
                    heat: None,
                },
            ],
        )
    }

    #[test]
    fn the_torque_is_the_power_over_the_relative_speed() {
        let f = sample();
        // 100 W at |−100| rad/s: 1 N·m exactly (binary-exact operands).
        assert_eq!(f.power_w(), 100.0);
        assert_eq!(f.torque_nm, 1.0);
        assert_eq!(f.power_identity_residual(), 0.0);
        let rest = FrictionBreakdown::from_mechanisms(0.0, f.mechanisms.clone());
        assert_eq!(rest.torque_nm, 0.0);
    }

    #[test]
    fn the_json_and_the_heat_carry_every_bound_mechanism() {
        let f = sample();
        let j = f.json();
        assert_eq!(j["by_mechanism"]["outer_raceway"], 50.0);
        assert_eq!(j["power_w"], 100.0);
        let h = f.heat_input();
        // The unbound drag is not released anywhere: 80 W of 100 W reach the network.
        assert_eq!(h.total_w(), 80.0);
        assert_eq!(h.watts(HeatSource::OuterContacts), 50.0);
    }
}

#[cfg(test)]
#[path = "friction_tests.rs"]
mod deck_tests;
