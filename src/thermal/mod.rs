//! Lumped-capacity thermal network (seed 000 §10): steady state (eq. 10.1–10.3), the
//! loss-of-oil transient (eq. 10.4–10.7). The `[thermal]` deck section's parser is
//! input, in `crate::deck::thermal` (it builds a [`ThermalModel`]).
//!
//! Independent of the rest of the pipeline: it consumes a [`HeatInput`] (W by mechanism)
//! and returns JSON-ready [`SteadyResult`] / [`TransientResult`].

#![deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
#![deny(missing_docs)]

pub mod error;
pub mod network;
pub mod steady;
pub mod transient;

pub use error::ThermalError;
pub use network::{
    capacity_from_material, HeatInput, HeatMechanism, HeatSource, Link, LinkKind, Network, Node,
    NodeRole, DEFAULT_ROLLER_HEAT_FRACTION,
};
pub use steady::{solve_steady, SteadyNode, SteadyResult};
pub use transient::{
    explicit_stable_step_s, run_transient, run_transient_cancellable, run_transient_from,
    scenario_network, HeatSchedule, Integrator, OilCoupled, Scenario, TransientNode,
    TransientResult, TransientSettings, TransientStats,
};

/// A parsed, validated thermal model in SI.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ThermalModel {
    /// The network (validated, including grounding).
    pub network: Network,
    /// Transient settings.
    pub transient: TransientSettings,
}

#[cfg(test)]
mod tests;
