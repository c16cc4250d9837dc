//! Typed errors of the thermal network: every variant names the node, link or field.

use thiserror::Error;

/// Everything that can go wrong while building, parsing or solving a thermal network.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ThermalError {
    /// The network has no nodes at all.
    #[error("thermal network has no nodes")]
    Empty,
    /// Two nodes share a name.
    #[error("duplicate thermal node name '{name}'")]
    DuplicateNode {
        /// The repeated node name.
        name: String,
    },
    /// Two links share a name.
    #[error("duplicate thermal link name '{name}'")]
    DuplicateLink {
        /// The repeated link name.
        name: String,
    },
    /// A link refers to a node that does not exist.
    #[error("thermal link '{link}': unknown node '{node}'")]
    UnknownNode {
        /// Link name.
        link: String,
        /// The missing node name.
        node: String,
    },
    /// A link connects a node to itself.
    #[error("thermal link '{link}' connects node '{node}' to itself")]
    SelfLink {
        /// Link name.
        link: String,
        /// Node name.
        node: String,
    },
    /// A node number is negative or not finite.
    #[error("thermal node '{node}': {field} must be finite{sign}, got {value}")]
    InvalidNodeValue {
        /// Node name.
        node: String,
        /// Offending field.
        field: &'static str,
        /// " and >= 0" when the field must also be non-negative.
        sign: &'static str,
        /// The value (SI).
        value: f64,
    },
    /// A link coefficient is negative or not finite.
    #[error("thermal link '{link}': {field} must be finite and >= 0, got {value}")]
    InvalidLinkValue {
        /// Link name.
        link: String,
        /// Offending field.
        field: &'static str,
        /// The value (SI).
        value: f64,
    },
    /// A free node (or its connected group) has no path to a fixed-temperature node.
    #[error(
        "thermal node '{node}' is free but has no path to a fixed-temperature node \
         (steady state is singular)"
    )]
    Ungrounded {
        /// First free node of the floating group.
        node: String,
    },
    /// A free node has zero heat capacity, which a transient cannot integrate.
    #[error("thermal node '{node}' is free with zero heat capacity; a transient needs C > 0")]
    ZeroCapacity {
        /// Node name.
        node: String,
    },
    /// A heat source is bound to a fixed-temperature node (its heat would vanish).
    #[error(
        "thermal node '{node}' has a fixed temperature but is bound to heat source '{mechanism}'"
    )]
    HeatOnFixedNode {
        /// Node name.
        node: String,
        /// Heat mechanism name.
        mechanism: &'static str,
    },
    /// Heat is supplied for a mechanism that no node is bound to.
    #[error("heat source '{mechanism}' carries {heat_w} W but no thermal node is bound to it")]
    UnboundHeat {
        /// Heat mechanism name.
        mechanism: &'static str,
        /// The heat that would be lost, W.
        heat_w: f64,
    },
    /// A heat input value is not finite.
    #[error("heat input {field} must be finite, got {value}")]
    InvalidHeat {
        /// Field of `HeatInput`.
        field: &'static str,
        /// The value, W.
        value: f64,
    },
    /// A solver or scenario setting is invalid.
    #[error("invalid thermal setting {field}: {reason}")]
    InvalidSetting {
        /// Setting name.
        field: String,
        /// Why it is invalid.
        reason: String,
    },
    /// The linear system could not be factorised.
    #[error("singular thermal matrix while {context}")]
    Singular {
        /// What was being solved.
        context: &'static str,
    },
    /// A temperature became non-finite during a transient.
    #[error("thermal transient diverged at t = {time_s} s: node '{node}' is not finite")]
    Diverged {
        /// Simulated time, s.
        time_s: f64,
        /// Node name.
        node: String,
    },
    /// The caller cancelled a transient.
    #[error("thermal transient cancelled at t = {time_s} s")]
    Cancelled {
        /// Simulated time reached, s.
        time_s: f64,
    },
    /// A `[thermal]` deck entry is malformed.
    #[error("thermal deck {location}: {message}")]
    Deck {
        /// Where: e.g. `node 'cage' field 'capacity'`.
        location: String,
        /// What is wrong.
        message: String,
    },
}
