//! The tapered roller's thermal network (issue 28 item 5): the deck's `[thermal]`
//! (`crate::deck::thermal`, the spherical roller's network) fed with the friction by
//! mechanism (`tribology`): steady state and, when asked, the loss-of-oil transient.
//!
//! **Loss of oil.** Once the film is gone the contacts run at boundary friction: the
//! transient's heat is the steady heat with each rib's film friction replaced by
//! µ_b·P₃·|Δu| (the asperities carry the whole rib load); the raceways' rolling
//! resistance is kept as it was (the kinematic model has no raceway sliding to turn into
//! boundary friction). **No viscosity feedback**: the films and the friction use the
//! inlet temperature; the network's temperatures are reported, not fed back (the
//! tapered solve has no outer iteration to carry them, and one more solve per network
//! iteration would break the speed budget) — said in the docs and the Summary.

use super::analysis::Analysis;
use super::tribology::{Tribology, FLANGE_SLIDING};
use crate::bearings::view::{NodeSeries, SteadyNode, ThermalResults, Transient};
use crate::thermal::{self, HeatInput, HeatSource, SteadyResult, ThermalModel, TransientResult};

/// The network's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalOut {
    /// Steady state with the friction's heat.
    pub steady: SteadyResult,
    /// Heat into the network, W.
    pub heat_w: f64,
    /// The loss-of-oil transient, when run.
    pub transient: Option<TransientResult>,
    /// Heat fed to the transient, W.
    pub transient_heat_w: Option<f64>,
}

/// The loss-of-oil heat: the ribs at boundary friction, the rest as in steady running.
pub fn lost_oil_heat(a: &Analysis, t: &Tribology) -> HeatInput {
    let mu_b = a.bearing.input.lubricant.boundary_friction;
    let ribs: f64 = t
        .rollers
        .iter()
        .map(|r| mu_b * r.flange.load_n * r.flange.sliding_m_s.abs())
        .sum();
    t.friction
        .mechanisms
        .iter()
        .filter(|m| m.name != FLANGE_SLIDING)
        .filter_map(|m| m.heat.map(|s| (s, m.power_w)))
        .fold(HeatInput::new(), |h, (s, w)| h.with(s, w))
        .with(HeatSource::Flanges, ribs)
}

/// Solve `model` with the heat of `a` (which must have its tribology); the transient when
/// `transient`.
pub fn solve(
    a: &Analysis,
    model: &ThermalModel,
    transient: bool,
    cancelled: &dyn Fn() -> bool,
) -> Result<ThermalOut, String> {
    let t = match &a.tribology {
        Some(Ok(t)) => t,
        Some(Err(e)) => return Err(format!("thermal network: no heat, the friction failed: {e}")),
        None => {
            return Err(
                "thermal network: the deck has no lubricant (lubricant.viscosity = \"none\"), so no friction heat to feed it"
                    .to_string(),
            )
        }
    };
    let heat = t.friction.heat_input();
    let steady = thermal::solve_steady(&model.network, &heat).map_err(|e| e.to_string())?;
    let (transient, transient_heat_w) = if transient {
        let lost = lost_oil_heat(a, t);
        let tr = thermal::run_transient_cancellable(
            &model.network,
            &steady.temperatures_c(),
            &model.transient,
            &lost,
            cancelled,
        )
        .map_err(|e| e.to_string())?;
        (Some(tr), Some(lost.total_w()))
    } else {
        (None, None)
    };
    Ok(ThermalOut {
        steady,
        heat_w: heat.total_w(),
        transient,
        transient_heat_w,
    })
}

impl ThermalOut {
    /// The Thermal pane's data (the spherical roller's render).
    pub fn view(&self) -> ThermalResults {
        ThermalResults {
            steady: self
                .steady
                .nodes
                .iter()
                .map(|n| SteadyNode {
                    name: n.name.clone(),
                    temperature_c: n.temperature_c,
                    fixed: n.fixed,
                })
                .collect(),
            transient: self.transient.as_ref().map(|tr| Transient {
                time_s: tr.time_s.clone(),
                nodes: tr
                    .nodes
                    .iter()
                    .map(|n| NodeSeries {
                        name: n.name.clone(),
                        temperature_c: n.temperature_c.clone(),
                        limit_c: n.limit_c,
                        time_to_limit_s: n.time_to_limit_s,
                    })
                    .collect(),
            }),
        }
    }

    /// The hottest steady node: (name, °C).
    pub fn hottest(&self) -> Option<(&str, f64)> {
        self.steady
            .nodes
            .iter()
            .map(|n| (n.name.as_str(), n.temperature_c))
            .fold(None, |m: Option<(&str, f64)>, c| match m {
                Some(b) if b.1 >= c.1 => Some(b),
                _ => Some(c),
            })
    }

    /// JSON `thermal`.
    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "heat_in_w": self.heat_w,
            "steady": self.steady,
            "transient": self.transient,
            "transient_heat_w": self.transient_heat_w,
        })
    }
}
