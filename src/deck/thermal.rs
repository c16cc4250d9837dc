//! The `[thermal]` deck section: serde types (unknown keys rejected) and their
//! conversion, in SI or US customary units, to a [`Network`] and [`TransientSettings`].
//!
//! ```toml
//! [thermal]
//! [[thermal.nodes]]
//! name = "inner_ring"      # unique
//! role = "solid"           # "solid" (default) | "oil" | "air"
//! capacity = 154.0         # J/K | Btu/°F          — or the three below
//! density = 7833.0         # kg/m³ | lbm/in³
//! specific_heat = 460.0    # J/(kg·K) | Btu/(lbm·°F)
//! volume = 4.27e-5         # m³ | in³
//! fixed_temperature = 80.0 # °C | °F              (makes the node fixed)
//! limit = 230.0            # °C | °F
//! air_capacity = 5.0       # J/K | Btu/°F          (oil nodes after loss of oil)
//! heat = ["inner_contacts"] # inner_contacts | outer_contacts | rollers | cage_rails | viscous_drag | flanges | guide_ring
//!
//! [[thermal.links]]
//! name = "ir-shaft"        # optional, default "from-to"
//! from = "inner_ring"      # upstream for mass transport
//! to = "shaft"
//! kind = "conductance"     # conduction | convection | mass_transport | conductance
//! conductance = 25.0       # W/K | Btu/(hr·°F)                  (conductance)
//! conductivity = 43.0      # W/(m·K) | Btu/(hr·ft·°F)           (conduction)
//! area = 0.005             # m² | in²                           (conduction, convection)
//! length = 0.03            # m | in                             (conduction)
//! h = 1500.0               # W/(m²·K) | Btu/(hr·ft²·°F)         (convection)
//! h_loss_of_oil = 80.0     # idem, optional                     (convection)
//! mass_flow = 0.05         # kg/s | lbm/s                       (mass_transport)
//! specific_heat = 2000.0   # J/(kg·K) | Btu/(lbm·°F)            (mass_transport)
//!
//! [thermal.transient]
//! duration = 3600.0        # s (both unit systems)
//! step = 1.0               # s
//! integrator = "implicit"  # | "explicit"
//! scenario = "loss_of_oil" # | "continued"
//! split_fraction = 0.5     # share of contact heat to the rollers (steady AND transient)
//! oil_node = "oil_cavity"  # optional
//! stop_at_limits = true
//! ```

use serde::{Deserialize, Serialize};

use crate::thermal::error::ThermalError;
use crate::thermal::network::{
    capacity_from_material, HeatMechanism, Link, LinkKind, Network, Node, NodeRole,
    DEFAULT_ROLLER_HEAT_FRACTION,
};
use crate::thermal::transient::{Integrator, Scenario, TransientSettings};
pub use crate::thermal::ThermalModel;
use crate::units::{Units, BTU_J, FAHRENHEIT_PER_KELVIN, FOOT_M, HOUR_S, INCH_M, LBM_KG};

/// The conversions of a `[thermal]` section's values to SI, in the section's
/// [`Units`].
///
/// US customary: temperatures °F, capacities Btu/°F, conductances Btu/(hr·°F),
/// conductivity Btu/(hr·ft·°F), film coefficients Btu/(hr·ft²·°F), lengths in, areas in²,
/// volumes in³, density lbm/in³, specific heat Btu/(lbm·°F), mass flow lbm/s. Times are
/// seconds in both systems. Btu is the International Table Btu (1055.05585262 J).
trait ThermalConversions: Copy {
    fn temperature_c(self, v: f64) -> f64;
    fn scale(self, us_to_si: f64, v: f64) -> f64;
    /// Btu/°F → J/K.
    fn capacity(self, v: f64) -> f64 {
        self.scale(BTU_J * FAHRENHEIT_PER_KELVIN, v)
    }
    /// Btu/(hr·°F) → W/K.
    fn conductance(self, v: f64) -> f64 {
        self.scale(BTU_J * FAHRENHEIT_PER_KELVIN / HOUR_S, v)
    }
    /// Btu/(hr·ft·°F) → W/(m·K).
    fn conductivity(self, v: f64) -> f64 {
        self.scale(BTU_J * FAHRENHEIT_PER_KELVIN / HOUR_S / FOOT_M, v)
    }
    /// Btu/(hr·ft²·°F) → W/(m²·K).
    fn film(self, v: f64) -> f64 {
        self.scale(
            BTU_J * FAHRENHEIT_PER_KELVIN / HOUR_S / (FOOT_M * FOOT_M),
            v,
        )
    }
    fn length(self, v: f64) -> f64 {
        self.scale(INCH_M, v)
    }
    fn area(self, v: f64) -> f64 {
        self.scale(INCH_M * INCH_M, v)
    }
    fn volume(self, v: f64) -> f64 {
        self.scale(INCH_M * INCH_M * INCH_M, v)
    }
    /// lbm/in³ → kg/m³.
    fn density(self, v: f64) -> f64 {
        self.scale(LBM_KG / (INCH_M * INCH_M * INCH_M), v)
    }
    /// Btu/(lbm·°F) → J/(kg·K).
    fn specific_heat(self, v: f64) -> f64 {
        self.scale(BTU_J * FAHRENHEIT_PER_KELVIN / LBM_KG, v)
    }
    /// lbm/s → kg/s.
    fn mass_flow(self, v: f64) -> f64 {
        self.scale(LBM_KG, v)
    }
}

impl ThermalConversions for Units {
    /// °F → °C.
    fn temperature_c(self, v: f64) -> f64 {
        match self {
            Units::Si => v,
            Units::Us => (v - 32.0) / FAHRENHEIT_PER_KELVIN,
        }
    }
    fn scale(self, us_to_si: f64, v: f64) -> f64 {
        match self {
            Units::Si => v,
            Units::Us => v * us_to_si,
        }
    }
}

/// One `[[thermal.nodes]]` entry, in deck units (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NodeDeck {
    /// Unique node name.
    pub name: String,
    /// Role; default solid.
    #[serde(default)]
    pub role: NodeRole,
    /// Capacity, J/K | Btu/°F.
    pub capacity: Option<f64>,
    /// Density, kg/m³ | lbm/in³ (with `specific_heat` and `volume`).
    pub density: Option<f64>,
    /// Specific heat, J/(kg·K) | Btu/(lbm·°F).
    pub specific_heat: Option<f64>,
    /// Volume, m³ | in³.
    pub volume: Option<f64>,
    /// Given temperature, °C | °F.
    pub fixed_temperature: Option<f64>,
    /// Temperature limit, °C | °F.
    pub limit: Option<f64>,
    /// Capacity after loss of oil, J/K | Btu/°F.
    pub air_capacity: Option<f64>,
    /// Heat mechanisms released here.
    #[serde(default)]
    pub heat: Vec<HeatMechanism>,
}

/// Kind of a `[[thermal.links]]` entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LinkKindDeck {
    /// k·A/L.
    Conduction,
    /// h·A.
    Convection,
    /// ṁ·c, directed from → to.
    MassTransport,
    /// G.
    Conductance,
}

/// One `[[thermal.links]]` entry, in deck units (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinkDeck {
    /// Optional unique name; default `"from-to"`.
    pub name: Option<String>,
    /// First (upstream) node.
    pub from: String,
    /// Second (downstream) node.
    pub to: String,
    /// Heat-transfer law.
    pub kind: LinkKindDeck,
    /// W/(m·K) | Btu/(hr·ft·°F).
    pub conductivity: Option<f64>,
    /// m² | in².
    pub area: Option<f64>,
    /// m | in.
    pub length: Option<f64>,
    /// W/(m²·K) | Btu/(hr·ft²·°F).
    pub h: Option<f64>,
    /// W/(m²·K) | Btu/(hr·ft²·°F).
    pub h_loss_of_oil: Option<f64>,
    /// kg/s | lbm/s.
    pub mass_flow: Option<f64>,
    /// J/(kg·K) | Btu/(lbm·°F).
    pub specific_heat: Option<f64>,
    /// W/K | Btu/(hr·°F).
    pub conductance: Option<f64>,
}

/// The `[thermal.transient]` keys `--set` suggests for a close typo (any `thermal.…` key
/// is accepted and checked by this section's parser).
pub const EDITABLE_KEYS: &[&str] = &[
    "thermal.transient.duration",
    "thermal.transient.step",
    "thermal.transient.integrator",
    "thermal.transient.scenario",
    "thermal.transient.split_fraction",
    "thermal.transient.oil_node",
    "thermal.transient.stop_at_limits",
];

/// `[thermal.transient]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransientDeck {
    /// Duration, s.
    pub duration: Option<f64>,
    /// Step, s.
    pub step: Option<f64>,
    /// Integrator; default implicit.
    pub integrator: Option<Integrator>,
    /// Scenario; default loss of oil.
    pub scenario: Option<Scenario>,
    /// Fraction of contact heat to the rollers (steady and transient); default 0.5.
    pub split_fraction: Option<f64>,
    /// Oil node for viscosity coupling.
    pub oil_node: Option<String>,
    /// Stop once all limited nodes reach their limits; default true.
    pub stop_at_limits: Option<bool>,
}

/// `[thermal]`: nodes, links and transient settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalDeck {
    /// Nodes.
    pub nodes: Vec<NodeDeck>,
    /// Links.
    #[serde(default)]
    pub links: Vec<LinkDeck>,
    /// Transient settings.
    pub transient: Option<TransientDeck>,
}

/// Longest transient duration (and step) a deck may ask for, s: 10⁷ s, about 116 days.
pub const MAX_DURATION_S: f64 = 1e7;

fn deck_err(location: impl Into<String>, message: impl Into<String>) -> ThermalError {
    ThermalError::Deck {
        location: location.into(),
        message: message.into(),
    }
}

/// One step of the way from the `[thermal]` table to the entry an error is about.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PathSeg {
    /// A key of a table.
    Key(String),
    /// An element of an array (of tables).
    Index(usize),
}

/// A `[thermal]` error and where it is: the keys and indices from the `[thermal]` table
/// to the offending entry or field (empty: the section as a whole), so that the deck can
/// give its line and column.
#[derive(Debug, Clone)]
pub struct LocatedThermalError {
    /// The error.
    pub error: ThermalError,
    /// Path inside `[thermal]`, e.g. `nodes`, 2, `fixed_temperature`.
    pub path: Vec<PathSeg>,
}

fn key(k: &str) -> PathSeg {
    PathSeg::Key(k.to_string())
}

/// Adds a path to an error (a closure for `map_err`).
fn at(path: Vec<PathSeg>) -> impl FnOnce(ThermalError) -> LocatedThermalError {
    move |error| LocatedThermalError { error, path }
}

/// Prefixes `outer` to the path of an error from inside an entry.
fn within(outer: Vec<PathSeg>) -> impl FnOnce(LocatedThermalError) -> LocatedThermalError {
    move |mut e| {
        let mut path = outer;
        path.append(&mut e.path);
        e.path = path;
        e
    }
}

fn entry_name(v: &toml::Value) -> Option<String> {
    v.get("name").and_then(|n| n.as_str()).map(str::to_string)
}

fn array<'a>(section: &'a toml::Table, key: &str) -> Result<&'a [toml::Value], ThermalError> {
    match section.get(key) {
        None => Ok(&[]),
        Some(toml::Value::Array(a)) => Ok(a.as_slice()),
        Some(_) => Err(deck_err(
            format!("[thermal] key '{key}'"),
            "expected an array of tables",
        )),
    }
}

/// Parses the `[thermal]` section of a deck.
///
/// `table` is the deck root holding a `thermal` table; if it has no `thermal` key but a
/// `nodes` key it is taken to be the section itself. Values are in `units`; the result is SI. Each entry
/// is deserialised on its own so errors name the node or link and the field; the network
/// is then validated (names, signs, grounding).
pub fn parse_thermal(table: &toml::Table, units: Units) -> Result<ThermalModel, ThermalError> {
    parse_thermal_located(table, units).map_err(|e| e.error)
}

/// [`parse_thermal`], with the path inside `[thermal]` of what an error is about.
pub fn parse_thermal_located(
    table: &toml::Table,
    units: Units,
) -> Result<ThermalModel, LocatedThermalError> {
    let section = match table.get("thermal") {
        Some(toml::Value::Table(t)) => t,
        Some(_) => return Err(at(vec![])(deck_err("[thermal]", "expected a table"))),
        None if table.contains_key("nodes") => table,
        None => return Err(at(vec![])(deck_err("[thermal]", "section missing"))),
    };
    for k in section.keys() {
        if !matches!(k.as_str(), "nodes" | "links" | "transient" | "units") {
            return Err(at(vec![key(k)])(deck_err(
                "[thermal]",
                format!("unknown key '{k}' (expected units, nodes, links, transient)"),
            )));
        }
    }
    // `[thermal] units = "si" | "us"` overrides the deck's unit system for this section, so a
    // network written in SI can sit in an inch-unit deck.
    let units = match section.get("units") {
        None => units,
        Some(toml::Value::String(u)) if u == "si" => Units::Si,
        Some(toml::Value::String(u)) if u == "us" => Units::Us,
        Some(other) => {
            return Err(at(vec![key("units")])(deck_err(
                "[thermal] key 'units'",
                format!("{other} is not allowed (allowed: \"si\" or \"us\")"),
            )))
        }
    };
    let mut nodes = Vec::new();
    let nodes_array = array(section, "nodes").map_err(at(vec![key("nodes")]))?;
    for (i, v) in nodes_array.iter().enumerate() {
        let here = vec![key("nodes"), PathSeg::Index(i)];
        let loc = match entry_name(v) {
            Some(n) => format!("node '{n}'"),
            None => format!("node #{}", i + 1),
        };
        let d: NodeDeck = v
            .clone()
            .try_into()
            .map_err(|e: toml::de::Error| deck_err(&loc, e.message().trim().to_string()))
            .map_err(at(here.clone()))?;
        nodes.push(convert_node(&d, units, &loc).map_err(within(here))?);
    }
    let mut links = Vec::new();
    let links_array = array(section, "links").map_err(at(vec![key("links")]))?;
    for (i, v) in links_array.iter().enumerate() {
        let here = vec![key("links"), PathSeg::Index(i)];
        let loc = match (entry_name(v), v.get("from"), v.get("to")) {
            (Some(n), _, _) => format!("link '{n}'"),
            (None, Some(f), Some(t)) => format!(
                "link #{} ({}-{})",
                i + 1,
                f.as_str().unwrap_or("?"),
                t.as_str().unwrap_or("?")
            ),
            _ => format!("link #{}", i + 1),
        };
        let d: LinkDeck = v
            .clone()
            .try_into()
            .map_err(|e: toml::de::Error| deck_err(&loc, e.message().trim().to_string()))
            .map_err(at(here.clone()))?;
        links.push(convert_link(&d, units, &loc).map_err(within(here))?);
    }
    let td: Option<TransientDeck> = match section.get("transient") {
        None => None,
        Some(v) => Some(
            v.clone()
                .try_into()
                .map_err(|e: toml::de::Error| {
                    deck_err("[thermal.transient]", e.message().trim().to_string())
                })
                .map_err(at(vec![key("transient")]))?,
        ),
    };
    let mut network = Network::new(nodes, links);
    let mut transient = TransientSettings::default();
    if let Some(td) = td {
        if let Some(f) = td.split_fraction {
            network.roller_heat_fraction = f;
        }
        if let Some(d) = td.duration {
            transient.duration_s = d;
        }
        if let Some(s) = td.step {
            transient.step_s = s;
        }
        if let Some(i) = td.integrator {
            transient.integrator = i;
        }
        if let Some(s) = td.scenario {
            transient.scenario = s;
        }
        if let Some(b) = td.stop_at_limits {
            transient.stop_at_limits = b;
        }
        transient.oil_node = td.oil_node;
        for (field, v, max) in [
            ("duration", transient.duration_s, MAX_DURATION_S),
            ("step", transient.step_s, MAX_DURATION_S),
        ] {
            if !(v.is_finite() && v > 0.0 && v <= max) {
                return Err(at(vec![key("transient"), key(field)])(deck_err(
                    format!("[thermal.transient] field '{field}'"),
                    format!("allowed 0 < {field} ≤ {max:e} s, got {v:e} s"),
                )));
            }
        }
        let steps = (transient.duration_s / transient.step_s).ceil();
        if steps.is_nan() || steps > crate::thermal::transient::MAX_STEPS {
            return Err(at(vec![key("transient"), key("step")])(deck_err(
                "[thermal.transient] field 'step'",
                format!(
                    "allowed duration / step ≤ {:e} steps, got {steps:e} ({:e} s / {:e} s): lengthen the step",
                    crate::thermal::transient::MAX_STEPS,
                    transient.duration_s,
                    transient.step_s
                ),
            )));
        }
        if !(0.0..=1.0).contains(&network.roller_heat_fraction) {
            return Err(at(vec![key("transient"), key("split_fraction")])(deck_err(
                "[thermal.transient] field 'split_fraction'",
                format!("must be in [0, 1], got {}", network.roller_heat_fraction),
            )));
        }
        if let Some(o) = &transient.oil_node {
            if network.node_index(o).is_none() {
                return Err(at(vec![key("transient"), key("oil_node")])(deck_err(
                    "[thermal.transient] field 'oil_node'",
                    format!("unknown node '{o}'"),
                )));
            }
        }
    } else {
        network.roller_heat_fraction = DEFAULT_ROLLER_HEAT_FRACTION;
    }
    network
        .check_grounded()
        .map_err(|e| at(network_path(&e, nodes_array, links_array))(e))?;
    Ok(ThermalModel { network, transient })
}

/// Where a network error (which names nodes and links, not entries) is: the node or
/// link entry it names, by name (a link without a name is called `from-to`).
fn network_path(e: &ThermalError, nodes: &[toml::Value], links: &[toml::Value]) -> Vec<PathSeg> {
    let node_at = |name: &str| {
        nodes
            .iter()
            .rposition(|v| entry_name(v).as_deref() == Some(name))
            .map(|i| vec![key("nodes"), PathSeg::Index(i)])
    };
    let link_at = |name: &str| {
        links
            .iter()
            .rposition(|v| {
                let s = |k: &str| v.get(k).and_then(|x| x.as_str()).unwrap_or("?").to_string();
                entry_name(v).unwrap_or_else(|| format!("{}-{}", s("from"), s("to"))) == name
            })
            .map(|i| vec![key("links"), PathSeg::Index(i)])
    };
    let path = match e {
        ThermalError::DuplicateNode { name }
        | ThermalError::Ungrounded { node: name }
        | ThermalError::ZeroCapacity { node: name }
        | ThermalError::HeatOnFixedNode { node: name, .. }
        | ThermalError::InvalidNodeValue { node: name, .. } => node_at(name),
        ThermalError::UnknownNode { link, node } | ThermalError::SelfLink { link, node } => {
            link_at(link).map(|mut p| {
                let which = links
                    .get(match p.last() {
                        Some(PathSeg::Index(i)) => *i,
                        _ => usize::MAX,
                    })
                    .and_then(|v| {
                        ["to", "from"]
                            .into_iter()
                            .find(|k| v.get(*k).and_then(|x| x.as_str()) == Some(node))
                    });
                if let Some(k) = which {
                    p.push(key(k));
                }
                p
            })
        }
        ThermalError::DuplicateLink { name }
        | ThermalError::InvalidLinkValue { link: name, .. } => link_at(name),
        _ => None,
    };
    path.unwrap_or_default()
}

fn field_err(loc: &str, field: &str, message: impl Into<String>) -> LocatedThermalError {
    at(vec![key(field)])(deck_err(format!("{loc} field '{field}'"), message))
}

fn convert_node(d: &NodeDeck, u: Units, loc: &str) -> Result<Node, LocatedThermalError> {
    let material = [d.density, d.specific_heat, d.volume];
    let n_material = material.iter().filter(|x| x.is_some()).count();
    let capacity_j_k = match (d.capacity, n_material) {
        (Some(_), 1..) => {
            return Err(field_err(
                loc,
                "capacity",
                "give either capacity or density/specific_heat/volume, not both",
            ))
        }
        (Some(c), 0) => u.capacity(c),
        (None, 3) => capacity_from_material(
            u.density(d.density.unwrap_or(0.0)),
            u.specific_heat(d.specific_heat.unwrap_or(0.0)),
            u.volume(d.volume.unwrap_or(0.0)),
        ),
        (None, 0) => 0.0,
        (None, _) => {
            let missing = ["density", "specific_heat", "volume"]
                .iter()
                .zip(material)
                .filter(|(_, v)| v.is_none())
                .map(|(n, _)| *n)
                .collect::<Vec<_>>()
                .join(", ");
            return Err(field_err(
                loc,
                "capacity",
                format!(
                    "material capacity needs density, specific_heat and volume; missing {missing}"
                ),
            ));
        }
    };
    for (field, v) in [
        ("capacity", d.capacity),
        ("density", d.density),
        ("specific_heat", d.specific_heat),
        ("volume", d.volume),
        ("air_capacity", d.air_capacity),
    ] {
        if let Some(v) = v {
            if !(v.is_finite() && v >= 0.0) {
                return Err(field_err(loc, field, format!("must be >= 0, got {v}")));
            }
        }
    }
    // Temperatures are checked here, under their deck names (the network checks them
    // again under its SI names).
    for (field, v) in [
        ("fixed_temperature", d.fixed_temperature),
        ("limit", d.limit),
    ] {
        if let Some(v) = v {
            if !v.is_finite() {
                return Err(field_err(loc, field, format!("must be finite, got {v}")));
            }
        }
    }
    if d.air_capacity.is_some() && d.role != NodeRole::Oil {
        return Err(field_err(
            loc,
            "air_capacity",
            "only oil nodes become air nodes",
        ));
    }
    Ok(Node {
        name: d.name.clone(),
        capacity_j_k,
        fixed_c: d.fixed_temperature.map(|t| u.temperature_c(t)),
        limit_c: d.limit.map(|t| u.temperature_c(t)),
        role: d.role,
        air_capacity_j_k: d.air_capacity.map(|c| u.capacity(c)),
        heat: d.heat.clone(),
    })
}

fn convert_link(d: &LinkDeck, u: Units, loc: &str) -> Result<Link, LocatedThermalError> {
    let all: [(&str, Option<f64>); 8] = [
        ("conductivity", d.conductivity),
        ("area", d.area),
        ("length", d.length),
        ("h", d.h),
        ("h_loss_of_oil", d.h_loss_of_oil),
        ("mass_flow", d.mass_flow),
        ("specific_heat", d.specific_heat),
        ("conductance", d.conductance),
    ];
    let (kind_name, required, optional): (&str, &[&str], &[&str]) = match d.kind {
        LinkKindDeck::Conduction => ("conduction", &["conductivity", "area", "length"], &[]),
        LinkKindDeck::Convection => ("convection", &["h", "area"], &["h_loss_of_oil"]),
        LinkKindDeck::MassTransport => ("mass_transport", &["mass_flow", "specific_heat"], &[]),
        LinkKindDeck::Conductance => ("conductance", &["conductance"], &[]),
    };
    for (field, v) in all {
        match v {
            Some(v) => {
                if !required.contains(&field) && !optional.contains(&field) {
                    return Err(field_err(
                        loc,
                        field,
                        format!("not used by a {kind_name} link"),
                    ));
                }
                if !(v.is_finite() && v >= 0.0) {
                    return Err(field_err(loc, field, format!("must be >= 0, got {v}")));
                }
            }
            None => {
                if required.contains(&field) {
                    return Err(field_err(
                        loc,
                        field,
                        format!("required by a {kind_name} link"),
                    ));
                }
            }
        }
    }
    let g = |x: Option<f64>| x.unwrap_or(0.0);
    let kind = match d.kind {
        LinkKindDeck::Conduction => {
            let length_m = u.length(g(d.length));
            if length_m <= 0.0 {
                return Err(field_err(loc, "length", "must be > 0"));
            }
            LinkKind::Conduction {
                conductivity_w_m_k: u.conductivity(g(d.conductivity)),
                area_m2: u.area(g(d.area)),
                length_m,
            }
        }
        LinkKindDeck::Convection => LinkKind::Convection {
            h_w_m2_k: u.film(g(d.h)),
            area_m2: u.area(g(d.area)),
            h_loss_of_oil_w_m2_k: d.h_loss_of_oil.map(|h| u.film(h)),
        },
        LinkKindDeck::MassTransport => LinkKind::MassTransport {
            mdot_c_w_k: u.mass_flow(g(d.mass_flow)) * u.specific_heat(g(d.specific_heat)),
        },
        LinkKindDeck::Conductance => LinkKind::Conductance {
            g_w_k: u.conductance(g(d.conductance)),
        },
    };
    Ok(Link {
        name: d
            .name
            .clone()
            .unwrap_or_else(|| format!("{}-{}", d.from, d.to)),
        from: d.from.clone(),
        to: d.to.clone(),
        kind,
    })
}
