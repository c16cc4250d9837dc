//! The lumped-capacity thermal network (seed 000 §10.1): nodes, links and heat bindings.
//!
//! Temperatures are °C at this boundary (the equations only use differences, so the
//! linear system is the same in K); capacities J/K, conductances W/K, heat W.

use std::collections::HashMap;

use serde::{Deserialize, Serialize};

use super::error::ThermalError;

/// What a node physically is; the loss-of-oil scenario turns `Oil` nodes into `Air` nodes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NodeRole {
    /// A solid element (ring, roller, cage, shaft, housing, cover).
    #[default]
    Solid,
    /// Lubricating oil: replaced by air when the oil is lost (seed 000 §10.3).
    Oil,
    /// Air (ambient, cavity air).
    Air,
}

/// A heat-generating mechanism of the pipeline to which a node can be bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HeatMechanism {
    /// Raceway share `(1 − f)` of the inner-contact heat (f = roller fraction).
    InnerContacts,
    /// Raceway share `(1 − f)` of the outer-contact heat.
    OuterContacts,
    /// Roller share `f` of inner plus outer contact heat.
    Rollers,
    /// Cage rail / pocket friction heat.
    CageRails,
    /// Viscous drag (churning) heat, released in the oil.
    ViscousDrag,
    /// Roller-end / flange (rib) sliding heat (tapered and cylindrical rollers).
    Flanges,
    /// Guide-ring heat (the double-row spherical roller's floating guide ring).
    GuideRing,
}

impl HeatMechanism {
    /// All mechanisms, in a fixed order.
    pub const ALL: [HeatMechanism; 7] = [
        HeatMechanism::InnerContacts,
        HeatMechanism::OuterContacts,
        HeatMechanism::Rollers,
        HeatMechanism::CageRails,
        HeatMechanism::ViscousDrag,
        HeatMechanism::Flanges,
        HeatMechanism::GuideRing,
    ];

    /// The deck / message spelling.
    pub fn as_str(self) -> &'static str {
        match self {
            HeatMechanism::InnerContacts => "inner_contacts",
            HeatMechanism::OuterContacts => "outer_contacts",
            HeatMechanism::Rollers => "rollers",
            HeatMechanism::CageRails => "cage_rails",
            HeatMechanism::ViscousDrag => "viscous_drag",
            HeatMechanism::Flanges => "flanges",
            HeatMechanism::GuideRing => "guide_ring",
        }
    }
}

/// Where a bearing generates heat. Each source is released into the nodes bound to its
/// [`HeatMechanism`]; contact heat is shared with the rolling elements by the network's
/// roller fraction. A new friction mechanism (a flange, a guide ring) is one more source
/// here and one more entry in a system's [`HeatInput`], not a new field in every struct.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HeatSource {
    /// All inner-raceway contacts.
    InnerContacts,
    /// All outer-raceway contacts.
    OuterContacts,
    /// Cage rails / pockets.
    CageRails,
    /// Viscous drag (churning), released in the oil (eq. 9.6).
    ViscousDrag,
    /// Roller-end / flange (rib) sliding contacts.
    Flanges,
    /// The guide ring's contacts (roller ends, ring bore).
    GuideRing,
}

impl HeatSource {
    /// The name used in messages (`inner_contacts_w`).
    pub fn as_str(self) -> &'static str {
        match self {
            HeatSource::InnerContacts => "inner_contacts_w",
            HeatSource::OuterContacts => "outer_contacts_w",
            HeatSource::CageRails => "cage_rails_w",
            HeatSource::ViscousDrag => "viscous_drag_w",
            HeatSource::Flanges => "flanges_w",
            HeatSource::GuideRing => "guide_ring_w",
        }
    }

    /// The mechanism whose nodes receive this heat (the raceway's share, for contacts).
    pub fn mechanism(self) -> HeatMechanism {
        match self {
            HeatSource::InnerContacts => HeatMechanism::InnerContacts,
            HeatSource::OuterContacts => HeatMechanism::OuterContacts,
            HeatSource::CageRails => HeatMechanism::CageRails,
            HeatSource::ViscousDrag => HeatMechanism::ViscousDrag,
            HeatSource::Flanges => HeatMechanism::Flanges,
            HeatSource::GuideRing => HeatMechanism::GuideRing,
        }
    }

    /// True for contact heat, of which the roller fraction goes into the rolling
    /// elements ([`HeatMechanism::Rollers`]).
    pub fn shared_with_rollers(self) -> bool {
        matches!(self, HeatSource::InnerContacts | HeatSource::OuterContacts)
    }
}

/// A bearing's heat generation as a list of sources, W (seed 000 §9: contact, cage, drag
/// heat).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct HeatInput {
    /// Heat by source, W, in the order the system lists them.
    pub sources: Vec<(HeatSource, f64)>,
}

impl HeatInput {
    /// No heat.
    pub fn new() -> Self {
        Self::default()
    }

    /// With `watts` more from `source`.
    pub fn with(mut self, source: HeatSource, watts: f64) -> Self {
        self.sources.push((source, watts));
        self
    }

    /// Heat from `source`, W.
    pub fn watts(&self, source: HeatSource) -> f64 {
        self.sources
            .iter()
            .filter(|(s, _)| *s == source)
            .fold(0.0, |acc, (_, w)| acc + w)
    }

    /// Total heat, W.
    pub fn total_w(&self) -> f64 {
        self.sources.iter().fold(0.0, |acc, (_, w)| acc + w)
    }

    /// Heat carried by one mechanism, W, with `roller_fraction` of each contact heat
    /// going to the rollers instead of the raceway.
    pub fn mechanism_w(&self, mechanism: HeatMechanism, roller_fraction: f64) -> f64 {
        if mechanism == HeatMechanism::Rollers {
            let contacts = self
                .sources
                .iter()
                .filter(|(s, _)| s.shared_with_rollers())
                .fold(0.0, |acc, (_, w)| acc + w);
            return roller_fraction * contacts;
        }
        self.sources
            .iter()
            .filter(|(s, _)| s.mechanism() == mechanism)
            .fold(0.0, |acc, &(s, w)| {
                acc + if s.shared_with_rollers() {
                    (1.0 - roller_fraction) * w
                } else {
                    w
                }
            })
    }

    fn check(&self) -> Result<(), ThermalError> {
        for &(source, value) in &self.sources {
            if !value.is_finite() {
                return Err(ThermalError::InvalidHeat {
                    field: source.as_str(),
                    value,
                });
            }
        }
        Ok(())
    }
}

/// Thermal capacity ρ·c·V of an element, J/K (eq. 10.4: C_i = c_i ρ_i v_i).
pub fn capacity_from_material(
    density_kg_m3: f64,
    specific_heat_j_kg_k: f64,
    volume_m3: f64,
) -> f64 {
    density_kg_m3 * specific_heat_j_kg_k * volume_m3
}

/// One lumped element: its capacity sits at its node (seed 000 §10.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Node {
    /// Unique name.
    pub name: String,
    /// Thermal capacity C = ρ·c·V, J/K (ignored for fixed nodes).
    pub capacity_j_k: f64,
    /// Fixed (given) temperature, °C; `None` for a free node.
    pub fixed_c: Option<f64>,
    /// Temperature limit, °C, whose crossing time the transient reports.
    pub limit_c: Option<f64>,
    /// Physical role (loss-of-oil switches `Oil` to `Air`).
    pub role: NodeRole,
    /// Capacity once the oil is lost (air plus residual oil film), J/K; `Oil` nodes only.
    /// `None` keeps `capacity_j_k`.
    pub air_capacity_j_k: Option<f64>,
    /// Heat mechanisms released in this node (shared equally between nodes bound to the
    /// same mechanism).
    pub heat: Vec<HeatMechanism>,
}

impl Node {
    /// A free node of capacity `capacity_j_k` (J/K), solid, no limit, no heat.
    pub fn free(name: impl Into<String>, capacity_j_k: f64) -> Self {
        Node {
            name: name.into(),
            capacity_j_k,
            fixed_c: None,
            limit_c: None,
            role: NodeRole::Solid,
            air_capacity_j_k: None,
            heat: Vec::new(),
        }
    }

    /// A fixed-temperature node at `temperature_c` (°C).
    pub fn fixed(name: impl Into<String>, temperature_c: f64) -> Self {
        Node {
            fixed_c: Some(temperature_c),
            ..Node::free(name, 0.0)
        }
    }

    /// Sets the role.
    pub fn with_role(mut self, role: NodeRole) -> Self {
        self.role = role;
        self
    }

    /// Sets the temperature limit, °C.
    pub fn with_limit(mut self, limit_c: f64) -> Self {
        self.limit_c = Some(limit_c);
        self
    }

    /// Binds a heat mechanism.
    pub fn with_heat(mut self, mechanism: HeatMechanism) -> Self {
        self.heat.push(mechanism);
        self
    }

    /// Sets the loss-of-oil (air) capacity, J/K.
    pub fn with_air_capacity(mut self, capacity_j_k: f64) -> Self {
        self.air_capacity_j_k = Some(capacity_j_k);
        self
    }

    /// True when the node has a given temperature.
    pub fn is_fixed(&self) -> bool {
        self.fixed_c.is_some()
    }
}

/// The heat-transfer law of a link (the f₁…f₄ of eq. 10.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LinkKind {
    /// Conduction, G = k·A/L.
    Conduction {
        /// Thermal conductivity k, W/(m·K).
        conductivity_w_m_k: f64,
        /// Cross-section A, m².
        area_m2: f64,
        /// Conduction length L, m (> 0).
        length_m: f64,
    },
    /// Free or forced convection, G = h·A.
    Convection {
        /// Film coefficient h, W/(m²·K).
        h_w_m2_k: f64,
        /// Wetted area A, m².
        area_m2: f64,
        /// Film coefficient once the oil is lost (air), W/(m²·K); `None` keeps `h_w_m2_k`.
        h_loss_of_oil_w_m2_k: Option<f64>,
    },
    /// Mass transport by the oil, ṁ·c, directed from `from` (upstream) to `to`
    /// (downstream): the downstream node gains ṁc(T_up − T_down); the upstream node
    /// is not affected by this link. Removed when the oil is lost.
    MassTransport {
        /// Capacity rate ṁ·c, W/K.
        mdot_c_w_k: f64,
    },
    /// A plain conductance G, W/K (contact conductance, lumped paths).
    Conductance {
        /// G, W/K.
        g_w_k: f64,
    },
}

/// A heat path between two named nodes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Link {
    /// Unique name (used in error messages).
    pub name: String,
    /// First node (upstream for mass transport).
    pub from: String,
    /// Second node (downstream for mass transport).
    pub to: String,
    /// Heat-transfer law.
    pub kind: LinkKind,
}

impl Link {
    /// A link named `"from-to"`.
    pub fn new(from: impl Into<String>, to: impl Into<String>, kind: LinkKind) -> Self {
        let from = from.into();
        let to = to.into();
        Link {
            name: format!("{from}-{to}"),
            from,
            to,
            kind,
        }
    }

    /// A plain conductance link, G in W/K.
    pub fn conductance(from: impl Into<String>, to: impl Into<String>, g_w_k: f64) -> Self {
        Link::new(from, to, LinkKind::Conductance { g_w_k })
    }

    /// A mass-transport link from upstream to downstream, ṁ·c in W/K.
    pub fn mass_transport(
        upstream: impl Into<String>,
        downstream: impl Into<String>,
        mdot_c_w_k: f64,
    ) -> Self {
        Link::new(upstream, downstream, LinkKind::MassTransport { mdot_c_w_k })
    }

    /// The link coefficient F, W/K (eq. 10.3 term): k·A/L, h·A, ṁ·c or G.
    pub fn coefficient_w_k(&self) -> f64 {
        match self.kind {
            LinkKind::Conduction {
                conductivity_w_m_k,
                area_m2,
                length_m,
            } => conductivity_w_m_k * area_m2 / length_m,
            LinkKind::Convection {
                h_w_m2_k, area_m2, ..
            } => h_w_m2_k * area_m2,
            LinkKind::MassTransport { mdot_c_w_k } => mdot_c_w_k,
            LinkKind::Conductance { g_w_k } => g_w_k,
        }
    }

    /// True for the directed oil mass-transport link.
    pub fn is_mass_transport(&self) -> bool {
        matches!(self.kind, LinkKind::MassTransport { .. })
    }
}

/// Default fraction of each contact's heat that goes to the roller node.
pub const DEFAULT_ROLLER_HEAT_FRACTION: f64 = 0.5;

/// A lumped-capacity thermal network. No node-count limit (the seed's 20 is not kept);
/// the solvers use dense LU, comfortable up to a few hundred nodes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Network {
    /// Nodes (elements).
    pub nodes: Vec<Node>,
    /// Links between nodes.
    pub links: Vec<Link>,
    /// Fraction f ∈ [0, 1] of each contact's heat released in the roller node instead of
    /// the raceway node (default 0.5).
    pub roller_heat_fraction: f64,
}

/// Link end points resolved to node indices.
#[derive(Debug, Clone)]
pub(crate) struct Resolved {
    pub ends: Vec<(usize, usize)>,
}

impl Network {
    /// A network with the default roller heat fraction.
    pub fn new(nodes: Vec<Node>, links: Vec<Link>) -> Self {
        Network {
            nodes,
            links,
            roller_heat_fraction: DEFAULT_ROLLER_HEAT_FRACTION,
        }
    }

    /// Index of a node by name.
    pub fn node_index(&self, name: &str) -> Option<usize> {
        self.nodes.iter().position(|n| n.name == name)
    }

    /// Checks names, link end points and the sign and finiteness of every number.
    /// Does not check grounding (see [`Network::check_grounded`]).
    pub fn validate(&self) -> Result<(), ThermalError> {
        self.resolve().map(|_| ())
    }

    pub(crate) fn resolve(&self) -> Result<Resolved, ThermalError> {
        if self.nodes.is_empty() {
            return Err(ThermalError::Empty);
        }
        if !(0.0..=1.0).contains(&self.roller_heat_fraction) {
            return Err(ThermalError::InvalidSetting {
                field: "roller_heat_fraction".into(),
                reason: format!("must be in [0, 1], got {}", self.roller_heat_fraction),
            });
        }
        let mut index: HashMap<&str, usize> = HashMap::with_capacity(self.nodes.len());
        for (i, node) in self.nodes.iter().enumerate() {
            if index.insert(node.name.as_str(), i).is_some() {
                return Err(ThermalError::DuplicateNode {
                    name: node.name.clone(),
                });
            }
            let bad = |field: &'static str, sign: &'static str, value: f64| {
                Err(ThermalError::InvalidNodeValue {
                    node: node.name.clone(),
                    field,
                    sign,
                    value,
                })
            };
            let nonneg = " and >= 0";
            if !(node.capacity_j_k.is_finite() && node.capacity_j_k >= 0.0) {
                return bad("capacity_j_k", nonneg, node.capacity_j_k);
            }
            if let Some(c) = node.air_capacity_j_k {
                if !(c.is_finite() && c >= 0.0) {
                    return bad("air_capacity_j_k", nonneg, c);
                }
            }
            if let Some(t) = node.fixed_c {
                if !t.is_finite() {
                    return bad("fixed_c", "", t);
                }
                if let Some(m) = node.heat.first() {
                    return Err(ThermalError::HeatOnFixedNode {
                        node: node.name.clone(),
                        mechanism: m.as_str(),
                    });
                }
            }
            if let Some(t) = node.limit_c {
                if !t.is_finite() {
                    return bad("limit_c", "", t);
                }
            }
        }
        let mut link_names: HashMap<&str, ()> = HashMap::with_capacity(self.links.len());
        let mut ends = Vec::with_capacity(self.links.len());
        for link in &self.links {
            if link_names.insert(link.name.as_str(), ()).is_some() {
                return Err(ThermalError::DuplicateLink {
                    name: link.name.clone(),
                });
            }
            let lookup = |n: &str| {
                index
                    .get(n)
                    .copied()
                    .ok_or_else(|| ThermalError::UnknownNode {
                        link: link.name.clone(),
                        node: n.to_string(),
                    })
            };
            let a = lookup(&link.from)?;
            let b = lookup(&link.to)?;
            if a == b {
                return Err(ThermalError::SelfLink {
                    link: link.name.clone(),
                    node: link.from.clone(),
                });
            }
            let mut fields: Vec<(&'static str, f64)> = Vec::with_capacity(3);
            match link.kind {
                LinkKind::Conduction {
                    conductivity_w_m_k,
                    area_m2,
                    length_m,
                } => {
                    fields.push(("conductivity_w_m_k", conductivity_w_m_k));
                    fields.push(("area_m2", area_m2));
                    if !(length_m.is_finite() && length_m > 0.0) {
                        return Err(ThermalError::InvalidLinkValue {
                            link: link.name.clone(),
                            field: "length_m (> 0)",
                            value: length_m,
                        });
                    }
                }
                LinkKind::Convection {
                    h_w_m2_k,
                    area_m2,
                    h_loss_of_oil_w_m2_k,
                } => {
                    fields.push(("h_w_m2_k", h_w_m2_k));
                    fields.push(("area_m2", area_m2));
                    if let Some(h) = h_loss_of_oil_w_m2_k {
                        fields.push(("h_loss_of_oil_w_m2_k", h));
                    }
                }
                LinkKind::MassTransport { mdot_c_w_k } => fields.push(("mdot_c_w_k", mdot_c_w_k)),
                LinkKind::Conductance { g_w_k } => fields.push(("g_w_k", g_w_k)),
            }
            for (field, value) in fields {
                if !(value.is_finite() && value >= 0.0) {
                    return Err(ThermalError::InvalidLinkValue {
                        link: link.name.clone(),
                        field,
                        value,
                    });
                }
            }
            ends.push((a, b));
        }
        Ok(Resolved { ends })
    }

    /// Checks that every free node has a path to a fixed-temperature node through links
    /// that enter its heat balance (eq. 10.2): conductive links both ways, a mass-transport
    /// link only from the downstream node to its upstream node. Otherwise the steady-state
    /// matrix is singular; the error names the first floating node.
    pub fn check_grounded(&self) -> Result<(), ThermalError> {
        let resolved = self.resolve()?;
        self.check_grounded_resolved(&resolved)
    }

    pub(crate) fn check_grounded_resolved(&self, resolved: &Resolved) -> Result<(), ThermalError> {
        let mut grounded: Vec<bool> = self.nodes.iter().map(Node::is_fixed).collect();
        // Fixed-point propagation; O(nodes·links), fine for lumped networks.
        loop {
            let mut changed = false;
            for (link, &(a, b)) in self.links.iter().zip(&resolved.ends) {
                if link.coefficient_w_k() <= 0.0 {
                    continue;
                }
                if grounded[a] && !grounded[b] {
                    grounded[b] = true;
                    changed = true;
                }
                if !link.is_mass_transport() && grounded[b] && !grounded[a] {
                    grounded[a] = true;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        match grounded.iter().position(|g| !g) {
            Some(i) => Err(ThermalError::Ungrounded {
                node: self.nodes[i].name.clone(),
            }),
            None => Ok(()),
        }
    }

    /// Checks that every free node has a positive capacity (needed by a transient).
    pub fn check_capacities(&self) -> Result<(), ThermalError> {
        match self
            .nodes
            .iter()
            .find(|n| !n.is_fixed() && n.capacity_j_k <= 0.0)
        {
            Some(n) => Err(ThermalError::ZeroCapacity {
                node: n.name.clone(),
            }),
            None => Ok(()),
        }
    }

    /// Heat released in each node, W, from the pipeline's heat by mechanism. Each
    /// mechanism's heat is shared equally between the nodes bound to it; heat for a
    /// mechanism no node is bound to is an error (it would vanish from the balance).
    pub fn node_heat_w(&self, heat: &HeatInput) -> Result<Vec<f64>, ThermalError> {
        heat.check()?;
        let mut q = vec![0.0; self.nodes.len()];
        for mechanism in HeatMechanism::ALL {
            let total = heat.mechanism_w(mechanism, self.roller_heat_fraction);
            let bound: Vec<usize> = self
                .nodes
                .iter()
                .enumerate()
                .filter(|(_, n)| n.heat.contains(&mechanism))
                .map(|(i, _)| i)
                .collect();
            if bound.is_empty() {
                if total != 0.0 {
                    return Err(ThermalError::UnboundHeat {
                        mechanism: mechanism.as_str(),
                        heat_w: total,
                    });
                }
                continue;
            }
            let share = total / bound.len() as f64;
            for i in bound {
                q[i] += share;
            }
        }
        Ok(q)
    }

    /// The network after a loss of oil (seed 000 §10.3): mass-transport links removed,
    /// `Oil` nodes become `Air` nodes (with their air capacity if given), convection links
    /// switch to their loss-of-oil film coefficient if given.
    pub fn loss_of_oil(&self) -> Network {
        let nodes = self
            .nodes
            .iter()
            .map(|n| {
                let mut n = n.clone();
                if n.role == NodeRole::Oil {
                    n.role = NodeRole::Air;
                    if let Some(c) = n.air_capacity_j_k {
                        n.capacity_j_k = c;
                    }
                }
                n
            })
            .collect();
        let links = self
            .links
            .iter()
            .filter(|l| !l.is_mass_transport())
            .map(|l| {
                let mut l = l.clone();
                if let LinkKind::Convection {
                    ref mut h_w_m2_k,
                    h_loss_of_oil_w_m2_k: Some(h_air),
                    ..
                } = l.kind
                {
                    *h_w_m2_k = h_air;
                }
                l
            })
            .collect();
        Network {
            nodes,
            links,
            roller_heat_fraction: self.roller_heat_fraction,
        }
    }
}
