//! Transient temperatures (seed 000 §10.3): the loss-of-oil scenario marched from the
//! steady state, by backward Euler (default) or the seed's explicit eq. 10.7.
//!
//! Both integrators march `C·dT/dt = Q + b − A·T` (eq. 10.4–10.6 in matrix form, see
//! [`super::steady`]).
//!
//! * Implicit (backward Euler): `(C/Δt + A)·T⁺ = C/Δt·T + Q + b`; unconditionally
//!   stable, first order; the matrix is LU-factorised once per distinct step size.
//! * Explicit (eq. 10.7): stable (and positive) only for Δt < C_i/ΣF_ij. **Design choice:
//!   the explicit integrator never refuses**: each requested step Δt is split into
//!   `n = ⌊Δt/Δt_crit⌋ + 1` equal sub-steps so that every sub-step is strictly below the
//!   bound. Output is recorded at the requested steps only; `stats.substeps` counts the
//!   sub-steps taken.
//!
//! Heat from a [`HeatSchedule`] is evaluated at the start of each (sub-)step with the oil
//! node's temperature at that time (explicit, lagged coupling).

use nalgebra::linalg::LU;
use nalgebra::{DVector, Dyn};
use serde::{Deserialize, Serialize};

use super::error::ThermalError;
use std::borrow::Cow;

use super::network::{HeatInput, HeatMechanism, Network, NodeRole};
use super::steady::{SteadyResult, System};

/// Time integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Integrator {
    /// Backward Euler, unconditionally stable (default).
    #[default]
    Implicit,
    /// Forward Euler as in eq. 10.7, automatically sub-stepped below its stability bound.
    Explicit,
}

/// What changes at t = 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Scenario {
    /// Loss of oil (seed 000 §10.3): see [`Network::loss_of_oil`].
    #[default]
    LossOfOil,
    /// Nothing in the network changes; only the heat input may.
    Continued,
}

/// Transient settings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TransientSettings {
    /// Simulated duration, s (> 0).
    pub duration_s: f64,
    /// Output / integration step Δt, s (> 0); the last step is shortened to end at
    /// `duration_s`.
    pub step_s: f64,
    /// Integrator.
    pub integrator: Integrator,
    /// Scenario applied at t = 0.
    pub scenario: Scenario,
    /// Node whose temperature feeds an oil-coupled [`HeatSchedule`]; default: the first
    /// node bound to viscous drag, else the first `Oil` node.
    pub oil_node: Option<String>,
    /// Stop once every node with a limit has reached it (when at least one has a limit).
    pub stop_at_limits: bool,
}

impl Default for TransientSettings {
    fn default() -> Self {
        TransientSettings {
            duration_s: 3600.0,
            step_s: 1.0,
            integrator: Integrator::Implicit,
            scenario: Scenario::LossOfOil,
            oil_node: None,
            stop_at_limits: true,
        }
    }
}

/// Heat supplied during the transient, possibly depending on the oil temperature
/// (viscosity coupling).
pub trait HeatSchedule {
    /// Heat by source, W, at oil temperature `oil_temp_c` (°C); borrowed when it does not
    /// depend on it (no allocation per step).
    fn heat_input(&self, oil_temp_c: f64) -> Cow<'_, HeatInput>;
    /// True when the heat depends on the oil temperature (an oil node is then required).
    fn is_coupled(&self) -> bool {
        true
    }
}

impl HeatSchedule for HeatInput {
    fn heat_input(&self, _oil_temp_c: f64) -> Cow<'_, HeatInput> {
        Cow::Borrowed(self)
    }
    fn is_coupled(&self) -> bool {
        false
    }
}

/// Wraps a closure `Fn(oil_temp_c) -> HeatInput` as a [`HeatSchedule`].
#[derive(Debug, Clone, Copy)]
pub struct OilCoupled<F>(pub F);

impl<F: Fn(f64) -> HeatInput> HeatSchedule for OilCoupled<F> {
    fn heat_input(&self, oil_temp_c: f64) -> Cow<'_, HeatInput> {
        Cow::Owned((self.0)(oil_temp_c))
    }
}

/// Time history of one node.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TransientNode {
    /// Node name.
    pub name: String,
    /// Temperature at each `time_s`, °C.
    pub temperature_c: Vec<f64>,
    /// Temperature limit, °C.
    pub limit_c: Option<f64>,
    /// First time the node reaches its limit, s (linear interpolation between steps);
    /// `None` if never within the run (or no limit).
    pub time_to_limit_s: Option<f64>,
}

/// Integration statistics.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TransientStats {
    /// Output steps taken.
    pub steps: usize,
    /// Integration (sub-)steps taken (= `steps` for the implicit integrator).
    pub substeps: usize,
    /// LU factorisations (implicit only).
    pub factorizations: usize,
    /// Explicit stability bound min_i C_i/ΣF_ij of the scenario network, s (`None` if
    /// no free node has a link).
    pub explicit_bound_s: Option<f64>,
}

/// Transient solution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TransientResult {
    /// Scenario simulated.
    pub scenario: Scenario,
    /// Output times, s (starting at 0).
    pub time_s: Vec<f64>,
    /// Per-node histories in network order.
    pub nodes: Vec<TransientNode>,
    /// Integration statistics.
    pub stats: TransientStats,
    /// Output steps per stored sample: 1 keeps every step; a run longer than
    /// [`MAX_SAMPLES`] steps keeps every k-th step and the last (times to limit are still
    /// found at every step).
    pub sample_every_steps: usize,
}

impl TransientResult {
    /// History of a named node.
    pub fn node(&self, name: &str) -> Option<&TransientNode> {
        self.nodes.iter().find(|n| n.name == name)
    }

    /// Temperatures of all nodes at the last recorded time, °C.
    pub fn final_temperatures_c(&self) -> Vec<f64> {
        self.nodes
            .iter()
            .map(|n| n.temperature_c.last().copied().unwrap_or(f64::NAN))
            .collect()
    }
}

/// The network the transient integrates for `scenario`.
pub fn scenario_network(network: &Network, scenario: Scenario) -> Network {
    match scenario {
        Scenario::LossOfOil => network.loss_of_oil(),
        Scenario::Continued => network.clone(),
    }
}

/// Explicit stability bound of eq. 10.7, min over free nodes of C_i/ΣF_ij, s (`None` when
/// no free node has a link). Computed on the network as given (apply the scenario first).
pub fn explicit_stable_step_s(network: &Network) -> Result<Option<f64>, ThermalError> {
    let resolved = network.resolve()?;
    let sys = System::assemble(network, &resolved);
    Ok(stable_bound(&sys))
}

fn stable_bound(sys: &System) -> Option<f64> {
    (0..sys.free.len())
        .filter(|&k| sys.a[(k, k)] > 0.0)
        .map(|k| sys.capacity[k] / sys.a[(k, k)])
        .reduce(f64::min)
}

/// Explicit substeps between two checks of the cancellation flag.
const CANCEL_CHECK_SUBSTEPS: usize = 256;

/// Most output steps a transient may take (`duration / step`); the deck's `[thermal]`
/// parser rejects more with the allowed range, and [`run_transient_cancellable`] refuses
/// them too.
pub const MAX_STEPS: f64 = 1e6;
/// Most explicit substeps a transient may take in all (`duration / explicit bound`):
/// beyond it the explicit integrator would run for minutes; the implicit one is the answer.
pub const MAX_SUBSTEPS: f64 = 1e8;
/// Most samples stored per node: longer runs keep every k-th step (and the last), and say
/// so in [`TransientResult::sample_every_steps`].
pub const MAX_SAMPLES: usize = 4000;

/// Runs the transient from a steady state (seed 000 §10.3: "the element's steady-state
/// temperature … is used as the initial value at time t = 0").
pub fn run_transient(
    network: &Network,
    initial: &SteadyResult,
    settings: &TransientSettings,
    heat: &dyn HeatSchedule,
) -> Result<TransientResult, ThermalError> {
    run_transient_from(network, &initial.temperatures_c(), settings, heat)
}

/// Runs the transient from arbitrary initial temperatures `initial_c` (°C, one per node,
/// network order; fixed nodes keep their given temperature).
pub fn run_transient_from(
    network: &Network,
    initial_c: &[f64],
    settings: &TransientSettings,
    heat: &dyn HeatSchedule,
) -> Result<TransientResult, ThermalError> {
    run_transient_cancellable(network, initial_c, settings, heat, &|| false)
}

/// As [`run_transient_from`], checking `cancelled()` before every output step and every
/// [`CANCEL_CHECK_SUBSTEPS`] explicit substeps; returns
/// [`ThermalError::Cancelled`] (with the simulated time reached) when it turns true, so a
/// worker thread can abandon a stale run.
pub fn run_transient_cancellable(
    network: &Network,
    initial_c: &[f64],
    settings: &TransientSettings,
    heat: &dyn HeatSchedule,
    cancelled: &dyn Fn() -> bool,
) -> Result<TransientResult, ThermalError> {
    check_settings(settings)?;
    network.validate()?;
    if initial_c.len() != network.nodes.len() {
        return Err(ThermalError::InvalidSetting {
            field: "initial_c".into(),
            reason: format!(
                "{} temperatures for {} nodes",
                initial_c.len(),
                network.nodes.len()
            ),
        });
    }
    if let Some((node, t)) = network
        .nodes
        .iter()
        .zip(initial_c)
        .find(|(_, t)| !t.is_finite())
    {
        return Err(ThermalError::InvalidNodeValue {
            node: node.name.clone(),
            field: "initial temperature",
            sign: "",
            value: *t,
        });
    }
    let net = scenario_network(network, settings.scenario);
    let resolved = net.resolve()?;
    net.check_capacities()?;
    let sys = System::assemble(&net, &resolved);
    let oil = oil_node(network, settings, heat)?;

    // Fixed nodes keep their given temperature whatever `initial_c` says.
    let t_all_init: Vec<f64> = net
        .nodes
        .iter()
        .zip(initial_c)
        .map(|(n, &t0)| n.fixed_c.unwrap_or(t0))
        .collect();
    let mut t_all = t_all_init;
    let mut t = sys.gather(&t_all);
    let bound = stable_bound(&sys);
    let heat_at = |t_all: &[f64]| -> Result<DVector<f64>, ThermalError> {
        let oil_c = oil.map(|i| t_all[i]).unwrap_or(f64::NAN);
        let q = net.node_heat_w(&heat.heat_input(oil_c))?;
        Ok(sys.free_heat(&q) + &sys.b)
    };

    let limits: Vec<Option<f64>> = net.nodes.iter().map(|n| n.limit_c).collect();
    let mut reached: Vec<Option<f64>> = limits
        .iter()
        .zip(&t_all)
        .map(|(l, &t0)| l.filter(|&l| t0 >= l).map(|_| 0.0))
        .collect();
    let any_limit = limits.iter().any(Option::is_some);

    let mut time_s = vec![0.0];
    let mut history: Vec<Vec<f64>> = t_all.iter().map(|&x| vec![x]).collect();
    let mut stats = TransientStats {
        steps: 0,
        substeps: 0,
        factorizations: 0,
        explicit_bound_s: bound,
    };
    let mut lu: Option<(f64, LU<f64, Dyn, Dyn>)> = None;
    // Every conversion of a user number to a count is checked: an absurd duration/step
    // is refused, never wrapped or saturated into a wrong run.
    let steps_f = ((settings.duration_s / settings.step_s) - 1e-9)
        .ceil()
        .max(1.0);
    if steps_f.is_nan() || steps_f > MAX_STEPS {
        return Err(ThermalError::InvalidSetting {
            field: "duration_s / step_s".into(),
            reason: format!(
                "{} steps of {} s for {} s; at most {MAX_STEPS:e} steps",
                fmt_count(steps_f),
                settings.step_s,
                settings.duration_s
            ),
        });
    }
    if settings.integrator == Integrator::Explicit {
        if let Some(b) = bound.filter(|&b| b > 0.0) {
            let total = (settings.duration_s / b).ceil() + steps_f;
            if total.is_nan() || total > MAX_SUBSTEPS {
                return Err(ThermalError::InvalidSetting {
                    field: "integrator".into(),
                    reason: format!(
                        "the explicit integrator would need about {} substeps below its stability bound of {b:.3e} s (at most {MAX_SUBSTEPS:e}); use integrator = \"implicit\"",
                        fmt_count(total)
                    ),
                });
            }
        }
    }
    let n_steps = steps_f as usize;
    let sample_every = n_steps.div_ceil(MAX_SAMPLES).max(1);
    let mut last_t: Vec<f64> = t_all.clone();
    let mut now = 0.0;
    for k in 1..=n_steps {
        if cancelled() {
            return Err(ThermalError::Cancelled { time_s: now });
        }
        let next = if k == n_steps {
            settings.duration_s
        } else {
            k as f64 * settings.step_s
        };
        // The nominal step exactly, so the implicit matrix is factorised once; only a
        // genuinely shorter last step gets its own factorisation.
        let dt = if (next - now - settings.step_s).abs() <= 1e-9 * settings.step_s {
            settings.step_s
        } else {
            next - now
        };
        match settings.integrator {
            Integrator::Implicit => {
                let rhs_q = heat_at(&t_all)?;
                let fresh = match &lu {
                    Some((h, _)) => *h != dt,
                    None => true,
                };
                if fresh {
                    // (C/Δt + A), factorised once per step size.
                    let mut m = sys.a.clone();
                    for i in 0..sys.free.len() {
                        m[(i, i)] += sys.capacity[i] / dt;
                    }
                    lu = Some((dt, m.lu()));
                    stats.factorizations += 1;
                }
                let rhs = sys.capacity.component_mul(&t) / dt + rhs_q;
                if let Some((_, f)) = &lu {
                    t = f.solve(&rhs).ok_or(ThermalError::Singular {
                        context: "stepping the implicit transient",
                    })?;
                }
                stats.substeps += 1;
            }
            Integrator::Explicit => {
                // Bounded above by the MAX_SUBSTEPS check before the loop.
                let n_sub = match bound {
                    Some(b) if dt >= b => ((dt / b).floor() + 1.0).min(MAX_SUBSTEPS) as usize,
                    _ => 1,
                };
                let h = dt / n_sub as f64;
                for sub in 0..n_sub {
                    // A long output step may hold millions of stable substeps: cancellation
                    // is seen within them too, not only between output steps.
                    if sub % CANCEL_CHECK_SUBSTEPS == CANCEL_CHECK_SUBSTEPS - 1 && cancelled() {
                        return Err(ThermalError::Cancelled {
                            time_s: now + sub as f64 * h,
                        });
                    }
                    let qb = heat_at(&t_all)?;
                    // eq. 10.7: T_i⁺ = (Q_i + Σ_j F_ij T_j)·Δt/C_i + [1 − Δt/C_i·Σ_j F_ij]·T_i,
                    // with Σ_j F_ij T_j split into free neighbours (−A_ij) and fixed (b_i).
                    let at = &sys.a * &t;
                    for i in 0..sys.free.len() {
                        let diag = sys.a[(i, i)];
                        let neighbours = diag * t[i] - at[i] + qb[i];
                        t[i] = neighbours * h / sys.capacity[i]
                            + (1.0 - h / sys.capacity[i] * diag) * t[i];
                    }
                    for (kk, &i) in sys.free.iter().enumerate() {
                        t_all[i] = t[kk];
                    }
                    stats.substeps += 1;
                }
            }
        }
        for (kk, &i) in sys.free.iter().enumerate() {
            t_all[i] = t[kk];
        }
        if let Some(i) = sys.free.iter().find(|&&i| !t_all[i].is_finite()) {
            return Err(ThermalError::Diverged {
                time_s: next,
                node: net.nodes[*i].name.clone(),
            });
        }
        stats.steps += 1;
        for (i, limit) in limits.iter().enumerate() {
            if let (Some(l), None) = (limit, reached[i]) {
                let prev = last_t[i];
                if t_all[i] >= *l {
                    let frac = if t_all[i] > prev {
                        ((l - prev) / (t_all[i] - prev)).clamp(0.0, 1.0)
                    } else {
                        1.0
                    };
                    reached[i] = Some(now + frac * dt);
                }
            }
        }
        last_t.clone_from(&t_all);
        now = next;
        let all_reached = limits
            .iter()
            .zip(&reached)
            .all(|(l, r)| l.is_none() || r.is_some());
        let stop = settings.stop_at_limits && any_limit && all_reached;
        if k % sample_every == 0 || k == n_steps || stop {
            time_s.push(next);
            for (h, &x) in history.iter_mut().zip(&t_all) {
                h.push(x);
            }
        }
        if stop {
            break;
        }
    }
    let nodes = net
        .nodes
        .iter()
        .zip(history)
        .zip(reached)
        .map(|((n, temperature_c), time_to_limit_s)| TransientNode {
            name: n.name.clone(),
            temperature_c,
            limit_c: n.limit_c,
            time_to_limit_s,
        })
        .collect();
    Ok(TransientResult {
        scenario: settings.scenario,
        time_s,
        nodes,
        stats,
        sample_every_steps: sample_every,
    })
}

/// A count held in an `f64`, for messages: plain up to 10¹², else in e-notation.
fn fmt_count(x: f64) -> String {
    if x.abs() < 1e12 {
        format!("{x:.0}")
    } else {
        format!("{x:.3e}")
    }
}

fn check_settings(s: &TransientSettings) -> Result<(), ThermalError> {
    for (field, v) in [("duration_s", s.duration_s), ("step_s", s.step_s)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(ThermalError::InvalidSetting {
                field: field.into(),
                reason: format!("must be finite and > 0, got {v}"),
            });
        }
    }
    Ok(())
}

/// Index of the node whose temperature drives an oil-coupled heat schedule.
fn oil_node(
    network: &Network,
    settings: &TransientSettings,
    heat: &dyn HeatSchedule,
) -> Result<Option<usize>, ThermalError> {
    if let Some(name) = &settings.oil_node {
        return network
            .node_index(name)
            .map(Some)
            .ok_or_else(|| ThermalError::InvalidSetting {
                field: "oil_node".into(),
                reason: format!("unknown node '{name}'"),
            });
    }
    let found = network
        .nodes
        .iter()
        .position(|n| n.heat.contains(&HeatMechanism::ViscousDrag))
        .or_else(|| network.nodes.iter().position(|n| n.role == NodeRole::Oil));
    if found.is_none() && heat.is_coupled() {
        return Err(ThermalError::InvalidSetting {
            field: "oil_node".into(),
            reason: "an oil-coupled heat input needs an oil node (none bound to viscous \
                     drag, no oil-role node)"
                .into(),
        });
    }
    Ok(found)
}
