//! The staged SASHBEAN pipeline: load distribution → stresses → film → life → speeds →
//! sliding/heat → thermal. Each stage runs only when a view or report asks for it
//! ([`Request`]); [`StageCounters`] count what ran.

use std::sync::atomic::{AtomicBool, Ordering};

use serde::Serialize;

use super::contacts::{self, RollerContacts};
use super::load_distribution::{
    self, DynamicSpeeds, Layout, LoadDistribution, SolveOptions, SolveStats, TraceStep, WarmStart,
};
use super::stages::{self, Films, Friction, Life, Speeds, Stresses};
use crate::bearings::spherical_roller::{Bearing, DynamicLoads};
use crate::bearings::SolveError;
use crate::physics::kinematics::InternalSpeeds;
use crate::pipeline::Stage;
use crate::thermal::{self, HeatInput, HeatSource, SteadyResult, ThermalModel, TransientResult};

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
    /// Pre-solve on a coarse roller and start the fine solve from it (the default: the
    /// same answer for less work). Off, the fine solve starts cold from the App. C speeds:
    /// the reference path of the test that proves the two agree.
    pub presolve: bool,
    /// The deck's thermal network, if any (§10); used by [`run`] and the workbench.
    pub thermal: Option<ThermalModel>,
    /// Rows and guide ring of the load distribution (default: the single-row bearing; the
    /// double-row spherical roller bearing solves both rows here).
    pub layout: Layout,
    /// Dynamic speeds imposed on the load distribution instead of App. C's estimate as the
    /// start (with `solver.dynamic_loads = "estimate"` they are used as given: a measured
    /// cage speed).
    pub dynamic_speeds: Option<DynamicSpeeds>,
    /// Warm start of the load distribution: a previous solution's dynamic speeds and
    /// unknowns (a neighbouring point of a sweep or a grid). The coarse pre-solve is skipped
    /// and the dynamic-load iteration starts there (the speeds yield to `dynamic_speeds`
    /// when those are imposed); the fine solve decides convergence to the deck's tolerances
    /// as from any start. None (the default): the cold path, unchanged.
    pub warm_start: Option<(DynamicSpeeds, WarmStart)>,
}

impl Default for Request {
    fn default() -> Self {
        Request {
            trace_roller: None,
            contact: true,
            heat: true,
            thermal_transient: false,
            presolve: true,
            thermal: None,
            layout: Layout::default(),
            dynamic_speeds: None,
            warm_start: None,
        }
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
    /// The 5×5 stiffness at the operating point (issue 29), or why there is none (a
    /// sentence with numbers: a roller that did not converge at a displaced ring).
    #[serde(skip)]
    pub stiffness: Result<crate::bearings::stiffness::StiffnessMatrix, String>,
    /// Stepper trace of the requested roller (empty unless requested).
    #[serde(skip)]
    pub trace: Vec<TraceStep>,
    /// The roller `trace` follows (0-based), when one was requested.
    #[serde(skip)]
    pub trace_roller: Option<usize>,
    /// The outer (§7 speeds ↔ §3 loads) iteration whose roller solve `trace` records: the
    /// final one, which ends in the solution shown.
    #[serde(skip)]
    pub trace_outer: usize,
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
    HeatInput::new()
        .with(HeatSource::InnerContacts, f.heat.inner_contacts_w)
        .with(HeatSource::OuterContacts, f.heat.outer_contacts_w)
        .with(HeatSource::CageRails, f.heat.cage_rails_w)
        .with(HeatSource::ViscousDrag, f.heat.viscous_drag_w)
}

fn thermal_err(e: thermal::ThermalError) -> SolveError {
    SolveError::Stage {
        stage: "thermal network (§10)",
        message: e.to_string(),
    }
}

/// Relative tolerance of the dynamic-load iteration on the cage speed and roller spin, as a
/// multiple of the deck's force tolerance: CF ∝ Ω², so a relative speed error ε changes the
/// centrifugal force by 2ε·CF, below the equilibrium tolerance for ε = 10 × force_tolerance
/// (Z·CF ≥ 2·CF bounds the reference force).
const DYNAMIC_TOL_FACTOR: f64 = 10.0;
/// Iteration limit of the dynamic-load iteration.
const DYNAMIC_MAX: usize = 30;

/// Run the pipeline on `bearing` with the thermal network of `request.thermal`, if any.
pub fn run(
    bearing: &Bearing,
    request: &Request,
    cancel: Option<&AtomicBool>,
) -> Result<Analysis, SolveError> {
    run_with_thermal(bearing, request.thermal.as_ref(), request, cancel)
}

/// Run the pipeline on `bearing` with an optional thermal network (§10): steady state with
/// the pipeline's heat by mechanism; with `request.thermal_transient`, the loss-of-oil
/// transient from that steady state with the lost-lubrication heat. No caching: see
/// [`Pipeline`] for the incremental version.
pub fn run_with_thermal(
    bearing: &Bearing,
    thermal_model: Option<&ThermalModel>,
    request: &Request,
    cancel: Option<&AtomicBool>,
) -> Result<Analysis, SolveError> {
    let mut p = Pipeline::default();
    p.update(bearing, thermal_model, request, cancel)?;
    p.into_analysis(bearing, thermal_model, request)
}

/// How many times each stage has run (the proof that edits re-run only what they touch).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct StageCounters {
    /// Load distribution with the dynamic-load iteration and §7 speeds.
    pub load_distribution: usize,
    /// Stresses, film and life (§4–6).
    pub contact: usize,
    /// Sliding, traction and heat (§8–9).
    pub friction: usize,
    /// Thermal steady state (§10.2).
    pub thermal_steady: usize,
    /// Loss-of-oil transient (§10.3).
    pub thermal_transient: usize,
}

/// Output of the load stage.
#[derive(Debug, Clone)]
struct LoadStage {
    load: LoadDistribution,
    contacts: Vec<RollerContacts>,
    speeds: InternalSpeeds,
    iterations: usize,
    trace: Vec<TraceStep>,
    /// The roller `trace` follows.
    trace_roller: Option<usize>,
    /// The outer (dynamic-load) iteration the trace records: the last one.
    trace_outer: usize,
}

/// The inputs each stage reads: an edit that changes none of a stage's inputs (nor an
/// upstream stage's) reuses its cached output.
#[derive(Debug, Clone, PartialEq)]
struct LoadKey {
    geometry: crate::bearings::spherical_roller::Geometry,
    materials: crate::bearings::spherical_roller::Materials,
    operating: crate::bearings::spherical_roller::Operating,
    solver: crate::bearings::spherical_roller::SolverSettings,
    trace_roller: Option<usize>,
    presolve: bool,
    layout: Layout,
    dynamic_speeds: Option<DynamicSpeeds>,
}

#[derive(Debug, Clone, PartialEq)]
struct ContactKey {
    lubricant: crate::bearings::spherical_roller::Lubricant,
    surfaces: crate::bearings::spherical_roller::Surfaces,
    life: crate::bearings::spherical_roller::LifeFactors,
}

#[derive(Debug, Clone, PartialEq)]
struct FrictionKey {
    lubricant: crate::bearings::spherical_roller::Lubricant,
    cage: crate::bearings::spherical_roller::Cage,
}

/// An incremental pipeline: each stage ([`crate::pipeline::Stage`]) caches its output with
/// the inputs it declares (its key) and counts its runs.
#[derive(Debug, Default)]
pub struct Pipeline {
    load: Stage<LoadKey, LoadStage>,
    contact: Stage<ContactKey, (Stresses, Films, Life)>,
    friction: Stage<FrictionKey, Friction>,
    steady: Stage<ThermalModel, SteadyResult>,
    transient: Stage<ThermalModel, (TransientResult, f64)>,
}

impl Pipeline {
    /// A pipeline with empty caches.
    pub fn new() -> Self {
        Self::default()
    }

    /// Stage run counters since creation.
    pub fn counters(&self) -> StageCounters {
        StageCounters {
            load_distribution: self.load.runs(),
            contact: self.contact.runs(),
            friction: self.friction.runs(),
            thermal_steady: self.steady.runs(),
            thermal_transient: self.transient.runs(),
        }
    }

    /// Run the stages `request` needs, reusing cached outputs whose inputs did not change.
    pub fn run(
        &mut self,
        bearing: &Bearing,
        thermal_model: Option<&ThermalModel>,
        request: &Request,
        cancel: Option<&AtomicBool>,
    ) -> Result<Analysis, SolveError> {
        self.update(bearing, thermal_model, request, cancel)?;
        // The caches stay for the next edit: the analysis gets copies of what it shows.
        let n = Needs::of(request, thermal_model);
        let parts = Parts {
            load: self.load.output().cloned(),
            contact: self.contact.output().filter(|_| n.contact).cloned(),
            friction: self.friction.output().filter(|_| n.friction).cloned(),
            steady: self.steady.output().filter(|_| n.thermal).cloned(),
            transient: self.transient.output().filter(|_| n.transient).cloned(),
        };
        parts.analysis(bearing, request.layout)
    }

    /// A one-shot pipeline's analysis: the stage outputs are moved, not copied (a copy of
    /// the per-lamina tables was a tenth of a run on the aerospace deck).
    fn into_analysis(
        self,
        bearing: &Bearing,
        thermal_model: Option<&ThermalModel>,
        request: &Request,
    ) -> Result<Analysis, SolveError> {
        let n = Needs::of(request, thermal_model);
        let parts = Parts {
            load: self.load.into_output(),
            contact: self.contact.into_output().filter(|_| n.contact),
            friction: self.friction.into_output().filter(|_| n.friction),
            steady: self.steady.into_output().filter(|_| n.thermal),
            transient: self.transient.into_output().filter(|_| n.transient),
        };
        parts.analysis(bearing, request.layout)
    }

    /// Bring every stage `request` needs up to date with `bearing`.
    fn update(
        &mut self,
        bearing: &Bearing,
        thermal_model: Option<&ThermalModel>,
        request: &Request,
        cancel: Option<&AtomicBool>,
    ) -> Result<(), SolveError> {
        let load_key = LoadKey {
            geometry: bearing.geometry,
            materials: bearing.materials,
            operating: bearing.operating,
            solver: bearing.solver,
            trace_roller: request.trace_roller,
            presolve: request.presolve,
            layout: request.layout,
            dynamic_speeds: request.dynamic_speeds,
        };
        if self
            .load
            .update(load_key, || load_stage(bearing, request, cancel))?
        {
            // Every stage downstream read the old load distribution.
            self.contact.invalidate();
            self.friction.invalidate();
            self.steady.invalidate();
            self.transient.invalidate();
        }
        let Some(ls) = self.load.output() else {
            return Err(SolveError::Stage {
                stage: "pipeline",
                message: "load stage missing".into(),
            });
        };
        let needs = Needs::of(request, thermal_model);
        let contact_key = ContactKey {
            lubricant: bearing.lubricant,
            surfaces: bearing.surfaces,
            life: bearing.life,
        };
        if needs.contact
            && self.contact.update(contact_key, || {
                let st = stages::stresses(bearing, &ls.load, &ls.contacts);
                let fi = stages::films(bearing, &ls.contacts, &ls.speeds);
                let li = stages::life(bearing, &ls.load, &fi);
                Ok::<_, SolveError>((st, fi, li))
            })?
        {
            self.friction.invalidate();
            self.steady.invalidate();
            self.transient.invalidate();
        }
        let friction_key = FrictionKey {
            lubricant: bearing.lubricant,
            cage: bearing.cage,
        };
        if needs.friction && !self.friction.is_fresh(&friction_key) {
            match (self.friction.entry(), self.contact.output()) {
                // Cage-only edit: the lamina traction does not read the cage; only the
                // cage's rail and drag heat are re-derived (not counted as a run).
                (Some((k, fr)), _) if k.lubricant == friction_key.lubricant => {
                    let fr = stages::with_cage(bearing, fr, &ls.speeds)?;
                    self.friction.store(friction_key, fr);
                    self.steady.invalidate();
                    self.transient.invalidate();
                }
                (_, Some((st, fi, _))) => {
                    self.friction
                        .update(friction_key, || friction_stage(bearing, ls, st, fi, false))?;
                    self.steady.invalidate();
                    self.transient.invalidate();
                }
                _ => {}
            }
        }
        if let (Some(tm), Some(fr)) = (thermal_model, self.friction.output()) {
            if self.steady.update(tm.clone(), || {
                thermal::solve_steady(&tm.network, &heat_input(fr)).map_err(thermal_err)
            })? {
                self.transient.invalidate();
            }
            if needs.transient && !self.transient.is_fresh(tm) {
                if let (Some(steady), Some((st, fi, _))) =
                    (self.steady.output(), self.contact.output())
                {
                    self.transient.update(tm.clone(), || {
                        let lost = friction_stage(bearing, ls, st, fi, true)?;
                        let cancelled = || cancel.is_some_and(|c| c.load(Ordering::Relaxed));
                        let tr = thermal::run_transient_cancellable(
                            &tm.network,
                            &steady.temperatures_c(),
                            &tm.transient,
                            &heat_input(&lost),
                            &cancelled,
                        )
                        .map_err(|e| match e {
                            thermal::ThermalError::Cancelled { .. } => SolveError::Cancelled,
                            e => thermal_err(e),
                        })?;
                        Ok::<_, SolveError>((tr, lost.heat.total_w))
                    })?;
                }
            }
        }
        Ok(())
    }
}

/// Which stages a request shows: contact (§4–6) for any view of stresses or heat or a
/// thermal network, friction (§8–9) for heat or a network, the thermal network when one is
/// given, and its transient when asked for too.
#[derive(Debug, Clone, Copy)]
struct Needs {
    contact: bool,
    friction: bool,
    thermal: bool,
    transient: bool,
}

impl Needs {
    fn of(request: &Request, thermal_model: Option<&ThermalModel>) -> Self {
        let thermal = thermal_model.is_some();
        Needs {
            contact: request.contact || request.heat || thermal,
            friction: request.heat || thermal,
            thermal,
            transient: thermal && request.thermal_transient,
        }
    }
}

/// The stage outputs an [`Analysis`] shows, owned: exactly the stages its request needs
/// ([`Needs`]; a cached stage it did not ask for is left out, as if it had not run).
struct Parts {
    load: Option<LoadStage>,
    contact: Option<(Stresses, Films, Life)>,
    friction: Option<Friction>,
    steady: Option<SteadyResult>,
    transient: Option<(TransientResult, f64)>,
}

impl Parts {
    /// The analysis of `bearing` from these outputs.
    fn analysis(self, bearing: &Bearing, layout: Layout) -> Result<Analysis, SolveError> {
        let Some(ls) = self.load else {
            return Err(SolveError::Stage {
                stage: "pipeline",
                message: "load stage missing".into(),
            });
        };
        let (stresses, films, life) = match self.contact {
            Some((st, fi, li)) => (Some(st), Some(fi), Some(li)),
            None => (None, None, None),
        };
        let transient = self.transient;
        let thermal = self.steady.map(|steady| ThermalOut {
            steady,
            transient_heat_w: transient.as_ref().map(|t| t.1),
            transient: transient.map(|t| t.0),
        });
        let stiffness = super::stiffness::stiffness(bearing, layout, &ls.load)
            .map_err(|e| format!("no stiffness matrix: {e}"));
        Ok(Analysis {
            input: bearing.clone(),
            stiffness,
            thermal,
            speeds: stages::speeds_report(bearing, &ls.speeds, ls.iterations),
            load: ls.load,
            contacts: ls.contacts,
            stresses,
            films,
            life,
            friction: self.friction,
            trace: ls.trace,
            trace_roller: ls.trace_roller,
            trace_outer: ls.trace_outer,
        })
    }
}

/// §8–9 on the solved load stage: EHD traction, or with `lost_lubrication` the constant
/// coefficient of the loss-of-oil transient.
fn friction_stage(
    bearing: &Bearing,
    ls: &LoadStage,
    st: &Stresses,
    fi: &Films,
    lost_lubrication: bool,
) -> Result<Friction, SolveError> {
    stages::friction(
        bearing,
        &ls.load,
        &ls.contacts,
        st,
        fi,
        &ls.speeds,
        lost_lubrication,
    )
}

/// Loosest relative force tolerance of an intermediate solve of the dynamic-load iteration.
const INEXACT_TOLERANCE_MAX: f64 = 1e-6;
/// Laminae of the coarse pre-solve (see [`load_stage`]).
const COARSE_LAMINAE: usize = 11;
/// Relative force tolerance of the coarse pre-solve and of its dynamic-load iteration.
const COARSE_TOLERANCE: f64 = 1e-6;

/// §3 load distribution with the dynamic-load iteration (§7 ↔ §3) and the contact geometry.
///
/// Coarse-to-fine continuation: the unknowns (ring deflection; each roller's axial, radial
/// and pitch displacement) do not depend on the slicing, so a cold solve first runs the
/// whole dynamic-load iteration on a coarse roller of [`COARSE_LAMINAE`] laminae (same
/// slicing) to a loose tolerance, and the deck's fine slicing starts from that solution and
/// those speeds. The fine solve and the fine dynamic iteration then decide convergence to
/// the deck's tolerances, so the answer is the fine one (tested against a cold fine solve);
/// only the path is shorter: 5–6 times fewer lamina evaluations on the aerospace deck.
/// Skipped when the deck's slicing is already coarse, or the request says so.
fn load_stage(
    bearing: &Bearing,
    request: &Request,
    cancel: Option<&AtomicBool>,
) -> Result<LoadStage, SolveError> {
    let estimate = request
        .dynamic_speeds
        .unwrap_or_else(|| DynamicSpeeds::app_c_estimate(bearing));
    // The same path with or without a traced roller, so the stepper's final step is the
    // solution the other panes show, and the status line's counts are the same.
    let coarse = request.presolve && bearing.solver.laminae >= 2 * COARSE_LAMINAE;
    let mut stats = SolveStats::default();
    let mut iterations = 0;
    let (start, warm) = if let Some((speeds, w)) = &request.warm_start {
        (request.dynamic_speeds.unwrap_or(*speeds), Some(w.clone()))
    } else if coarse {
        let mut c = bearing.clone();
        c.solver.laminae = COARSE_LAMINAE;
        c.solver.force_tolerance = c.solver.force_tolerance.max(COARSE_TOLERANCE);
        match dynamic_iteration(&c, estimate, None, None, request.layout, cancel) {
            Ok(pre) => {
                add_stats(&mut stats, &pre.load.stats);
                iterations += pre.iterations;
                (pre.current, Some(pre.load.warm))
            }
            Err(SolveError::Cancelled) => return Err(SolveError::Cancelled),
            // Only the path is lost: the fine solve starts cold and reports its own outcome.
            Err(_) => (estimate, None),
        }
    } else {
        (estimate, None)
    };
    let fine = dynamic_iteration(
        bearing,
        start,
        warm,
        request.trace_roller,
        request.layout,
        cancel,
    )
    .map_err(|e| super::converged::describe_case(bearing, e))?;
    // Converged means converged: the deck's tolerance on every residual, relative to the
    // applied load.
    super::converged::check_residuals(bearing, &fine.load)?;
    add_stats(&mut stats, &fine.load.stats);
    let mut load = fine.load;
    load.stats = stats;
    let trace = std::mem::take(&mut load.trace);
    Ok(LoadStage {
        load,
        contacts: fine.contacts,
        speeds: fine.speeds,
        iterations: iterations + fine.iterations,
        trace,
        trace_roller: request.trace_roller,
        trace_outer: fine.iterations,
    })
}

fn add_stats(total: &mut SolveStats, s: &SolveStats) {
    total.iterations += s.iterations;
    total.roller_iterations += s.roller_iterations;
    total.lamina_evaluations += s.lamina_evaluations;
    total.wall_time_s += s.wall_time_s;
}

/// Outcome of one dynamic-load iteration.
struct Dynamic {
    load: LoadDistribution,
    contacts: Vec<RollerContacts>,
    speeds: InternalSpeeds,
    /// The dynamic speeds the final load distribution was solved with.
    current: DynamicSpeeds,
    iterations: usize,
}

/// Load distribution at `start` speeds, then (when the deck iterates dynamic loads) §7
/// speeds → dynamic loads → load distribution until the speeds settle. Stats accumulate
/// over the iterations.
///
/// Inexact outer iteration: while the speeds still change by Δ (relative), the load
/// distribution is solved only to a relative force tolerance of 10⁻³·Δ (never looser than
/// [`INEXACT_TOLERANCE_MAX`], never tighter than the deck's): a force error ε moves the speeds
/// by about ε, far below the change still to come. The iteration ends only when the speeds
/// settle *and* the last solve was at the deck's tolerance, so the answer meets the deck's
/// tolerances exactly as a sequence of tight solves would.
fn dynamic_iteration(
    bearing: &Bearing,
    start: DynamicSpeeds,
    warm: Option<WarmStart>,
    trace_roller: Option<usize>,
    layout: Layout,
    cancel: Option<&AtomicBool>,
) -> Result<Dynamic, SolveError> {
    let deck_tol = bearing.solver.force_tolerance;
    let iterated = bearing.solver.dynamic_loads == DynamicLoads::Iterated;
    // First solve: loose when the speeds will be iterated anyway (a warm start from the
    // coarse pre-solve, or the App. C estimate, is typically 0.1–4 % off).
    let mut tol = if iterated {
        deck_tol.max(INEXACT_TOLERANCE_MAX)
    } else {
        deck_tol
    };
    let mut opts = SolveOptions {
        layout,
        warm_start: warm,
        trace_roller,
        force_tolerance: Some(tol),
    };
    let mut load = load_distribution::solve(bearing, &start, &opts, cancel)?;
    let mut cts = contacts::contacts(bearing, &load);
    let mut speeds = stages::internal_speeds(bearing, &load, &cts);
    let mut iterations = 1;
    let mut stats = load.stats;
    let mut current = start;
    let dynamic_tol = (DYNAMIC_TOL_FACTOR * deck_tol).max(1e-13);
    if iterated {
        loop {
            let next = dynamic_from(&speeds, &current);
            let scale = |x: f64| x.abs().max(1e-9);
            let change = ((next.cage_rad_s - current.cage_rad_s).abs() / scale(current.cage_rad_s))
                .max(
                    (next.roller_spin_rad_s - current.roller_spin_rad_s).abs()
                        / scale(current.roller_spin_rad_s),
                );
            if change <= dynamic_tol && tol <= deck_tol {
                break;
            }
            if iterations >= DYNAMIC_MAX {
                return Err(SolveError::Stage {
                    stage: "dynamic-load iteration (§7 speeds ↔ §3 loads)",
                    message: format!("not converged after {iterations} iterations (relative change {change:.3e}, tolerance {dynamic_tol:.0e})"),
                });
            }
            tol = (1e-3 * change).clamp(deck_tol, deck_tol.max(INEXACT_TOLERANCE_MAX));
            opts.force_tolerance = Some(tol);
            opts.warm_start = Some(load.warm.clone());
            // The stepper shows every outer iteration's roller solve, in order: its last
            // step is the solution the panes show.
            let mut trace = std::mem::take(&mut load.trace);
            load = load_distribution::solve(bearing, &next, &opts, cancel)?;
            for t in &mut load.trace {
                t.outer_iteration = iterations + 1;
            }
            trace.append(&mut load.trace);
            load.trace = trace;
            add_stats(&mut stats, &load.stats);
            cts = contacts::contacts(bearing, &load);
            speeds = stages::internal_speeds(bearing, &load, &cts);
            current = next;
            iterations += 1;
        }
    }
    load.stats = stats;
    Ok(Dynamic {
        load,
        contacts: cts,
        speeds,
        current,
        iterations,
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
    let spin = if spins.is_empty() {
        current.roller_spin_rad_s
    } else {
        spins.iter().sum::<f64>() / spins.len() as f64
    };
    DynamicSpeeds {
        cage_rad_s: s.cage_speed_rad_s,
        roller_spin_rad_s: spin,
    }
}
