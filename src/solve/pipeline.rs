//! The staged SASHBEAN pipeline: load distribution → stresses → film → life → speeds →
//! sliding/heat → thermal. Each stage runs only when a view or report asks for it
//! ([`Request`]); [`StageCounters`] count what ran.

use std::sync::atomic::AtomicBool;

use serde::Serialize;

use super::contacts::{self, RollerContacts};
use super::load_distribution::{self, DynamicSpeeds, LoadDistribution, SolveOptions, TraceStep};
use super::stages::{self, Films, Friction, Life, Speeds, Stresses};
use super::SolveError;
use crate::model::kinematics::InternalSpeeds;
use crate::model::{Bearing, DynamicLoads};
use crate::thermal::{self, HeatInput, SteadyResult, ThermalModel, TransientResult};

/// What the caller needs computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// Record the equilibrium iterations of this roller (0-based) for the stepper.
    pub trace_roller: Option<usize>,
    /// Stresses, film, life (§4–6).
    pub contact: bool,
    /// Sliding and heat (§8–9).
    pub heat: bool,
    /// Run the thermal transient (expensive; only when shown or reported).
    pub thermal_transient: bool,
}

impl Default for Request {
    fn default() -> Self {
        Request { trace_roller: None, contact: true, heat: true, thermal_transient: false }
    }
}

/// Everything computed for one bearing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Analysis {
    /// The resolved input, SI, exactly as solved.
    pub input: Bearing,
    /// Load distribution (seed 000 §3).
    pub load: LoadDistribution,
    /// Internal speeds (§7).
    pub speeds: Speeds,
    /// Per-lamina contact geometry (radii, distances).
    #[serde(skip)]
    pub contacts: Vec<RollerContacts>,
    /// §4 stresses.
    pub stresses: Option<Stresses>,
    /// §5 film.
    pub films: Option<Films>,
    /// §6 life.
    pub life: Option<Life>,
    /// §8–9 sliding and heat.
    pub friction: Option<Friction>,
    /// §10 thermal network (when the deck has one).
    pub thermal: Option<ThermalOut>,
    /// Stepper trace of the requested roller (empty unless requested).
    #[serde(skip)]
    pub trace: Vec<TraceStep>,
}

/// §10 results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ThermalOut {
    pub steady: SteadyResult,
    /// Loss-of-oil transient, when requested.
    pub transient: Option<TransientResult>,
    /// Heat fed to the transient (lost-lubrication traction), W.
    pub transient_heat_w: Option<f64>,
}

fn heat_input(f: &Friction) -> HeatInput {
    HeatInput {
        inner_contacts_w: f.heat.inner_contacts_w,
        outer_contacts_w: f.heat.outer_contacts_w,
        cage_rails_w: f.heat.cage_rails_w,
        viscous_drag_w: f.heat.viscous_drag_w,
    }
}

fn thermal_err(e: thermal::ThermalError) -> SolveError {
    SolveError::Stage { stage: "thermal network (§10)", message: e.to_string() }
}

/// Relative tolerance of the dynamic-load iteration on the cage speed and roller spin.
const DYNAMIC_TOL: f64 = 1e-9;
/// Iteration limit of the dynamic-load iteration.
const DYNAMIC_MAX: usize = 30;

/// Run the pipeline on `bearing` (no thermal network).
pub fn run(bearing: &Bearing, request: &Request, cancel: Option<&AtomicBool>) -> Result<Analysis, SolveError> {
    run_with_thermal(bearing, None, request, cancel)
}

/// Run the pipeline on `bearing` with an optional thermal network (§10): steady state with
/// the pipeline's heat by mechanism; with `request.thermal_transient`, the loss-of-oil
/// transient from that steady state with the lost-lubrication heat.
pub fn run_with_thermal(
    bearing: &Bearing,
    thermal_model: Option<&ThermalModel>,
    request: &Request,
    cancel: Option<&AtomicBool>,
) -> Result<Analysis, SolveError> {
    let estimate = DynamicSpeeds::app_c_estimate(bearing);
    let mut opts = SolveOptions { warm_start: None, trace_roller: request.trace_roller };
    let mut load = load_distribution::solve(bearing, &estimate, &opts, cancel)?;
    let mut cts = contacts::contacts(bearing, &load);
    let mut speeds = stages::internal_speeds(bearing, &load, &cts);
    let mut iterations = 1;
    let mut stats = load.stats;
    if bearing.solver.dynamic_loads == DynamicLoads::Iterated {
        let mut current = estimate;
        loop {
            let next = dynamic_from(&speeds, &current);
            let scale = |x: f64| x.abs().max(1e-9);
            let change = ((next.cage_rad_s - current.cage_rad_s).abs() / scale(current.cage_rad_s))
                .max((next.roller_spin_rad_s - current.roller_spin_rad_s).abs() / scale(current.roller_spin_rad_s));
            if change <= DYNAMIC_TOL {
                break;
            }
            if iterations >= DYNAMIC_MAX {
                return Err(SolveError::Stage {
                    stage: "dynamic-load iteration (§7 speeds ↔ §3 loads)",
                    message: format!("not converged after {iterations} iterations (relative change {change:.3e}, tolerance {DYNAMIC_TOL:.0e})"),
                });
            }
            opts.warm_start = Some(load.warm.clone());
            load = load_distribution::solve(bearing, &next, &opts, cancel)?;
            stats.iterations += load.stats.iterations;
            stats.roller_iterations += load.stats.roller_iterations;
            stats.lamina_evaluations += load.stats.lamina_evaluations;
            stats.wall_time_s += load.stats.wall_time_s;
            cts = contacts::contacts(bearing, &load);
            speeds = stages::internal_speeds(bearing, &load, &cts);
            current = next;
            iterations += 1;
        }
    }
    load.stats = stats;
    let trace = std::mem::take(&mut load.trace);
    let speeds_report = stages::speeds_report(bearing, &speeds, iterations);
    let (stresses, films, life) = if request.contact || request.heat {
        let st = stages::stresses(bearing, &cts);
        let fi = stages::films(bearing, &cts, &speeds);
        let li = stages::life(bearing, &load, &fi);
        (Some(st), Some(fi), Some(li))
    } else {
        (None, None, None)
    };
    let friction = match (&stresses, &films) {
        (Some(st), Some(fi)) if request.heat => Some(stages::friction(bearing, &load, &cts, st, fi, &speeds, false)?),
        _ => None,
    };
    let thermal = match (thermal_model, &friction, &stresses, &films) {
        (Some(tm), Some(fr), Some(st), Some(fi)) => {
            let steady = thermal::solve_steady(&tm.network, &heat_input(fr)).map_err(thermal_err)?;
            let (transient, transient_heat_w) = if request.thermal_transient {
                let lost = stages::friction(bearing, &load, &cts, st, fi, &speeds, true)?;
                let h = heat_input(&lost);
                let tr = thermal::run_transient(&tm.network, &steady, &tm.transient, &h).map_err(thermal_err)?;
                (Some(tr), Some(lost.heat.total_w))
            } else {
                (None, None)
            };
            Some(ThermalOut { steady, transient, transient_heat_w })
        }
        _ => None,
    };
    Ok(Analysis {
        input: bearing.clone(),
        thermal,
        load,
        speeds: speeds_report,
        contacts: cts,
        stresses,
        films,
        life,
        friction,
        trace,
    })
}

/// Dynamic speeds for the next iteration: §7's cage speed and the mean spin of the
/// controlling rollers (App. D assumes one spin for all rollers). Without controlling
/// rollers the current speeds are kept.
fn dynamic_from(s: &InternalSpeeds, current: &DynamicSpeeds) -> DynamicSpeeds {
    if s.controlling_rollers == 0 {
        return *current;
    }
    let spins: Vec<f64> = s.roller_spin_rad_s.iter().flatten().copied().collect();
    let spin = if spins.is_empty() { current.roller_spin_rad_s } else { spins.iter().sum::<f64>() / spins.len() as f64 };
    DynamicSpeeds { cage_rad_s: s.cage_speed_rad_s, roller_spin_rad_s: spin }
}
