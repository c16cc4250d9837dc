//! The osculation optimiser (seed 002 §4–6, Fig. 3; issue 27 Model 5): which relative
//! radii k_Ci = R′_Ci/R_Ci, k_W = R′_W/R_W (optionally k_CE = R′_CE/R_CE) within a
//! tolerance band minimise the bearing's weighted total friction loss over the deck's load
//! cases, without losing complete EHD lubrication or dynamic capacity.
//!
//! **Objective**: Σ_c w_c·P_c, P_c the total loss of load case c (a closure over the solved
//! bearing: the system's loss breakdown).
//!
//! **Constraints** (each a relative margin, ≥ 0 satisfied):
//! * `lambda_min`: Λ at the thinnest film of every loaded raceway of both rows ≥
//!   `min_lambda` in every load case ("a complete EHD lubrication", §4);
//! * `capacity_ratio`: the dynamic capacity ≥ `min_capacity_ratio` × nominal in every
//!   case. ISO 281's C_r ignores the radii; the Lundberg–Palmgren raceway capacities of the
//!   life stage do not hold them either (line contact), but the lamina product law (eq. 6.1)
//!   does: a less conforming profile shortens and peaks the contact, raising the
//!   equivalent roller loads. So the capacity is the one the life stage implies,
//!   C = P·L10^(1/4) (L = (C/P)⁴, eq. 6.5), and its ratio to nominal at the same load is
//!   (L10/L10,nominal)^(1/4) — the load rating that keeps the life the life stage computes;
//! * `p_max`: the largest lamina Hertz pressure not above nominal;
//! * `edge_loading`: the largest line load on an edge lamina not above nominal (zero stays
//!   zero);
//! * `r_ci_gt_r_w`, `r_ce_gt_r_w`: R_Ci > R_W and R_CE > R_W (checked before solving).
//!
//! **k_CE**: the deck check d_m = 2(R_CE − D_W/2)·cos α⁰ ties the outer sphere to the
//! pitch circle (the roller centres lie on it). Changing R_CE alone would break it, so with
//! `k_ce` the pitch diameter moves with it, d′_m = d_m + 2(R′_CE − R_CE)·cos α⁰: the
//! rollers ride on the new sphere at the same contact angle (what a larger outer ring
//! grind does), and the check holds exactly. k_CE is off by default (the seed: "the
//! effect of outer raceway osculation modifying can be neglected").
//!
//! **Method**: a grid of `grid` values per variable over [1 − r, 1 + r] (r =
//! `relative_range`), evaluated in parallel (rayon); then Nelder–Mead (argmin) from the
//! best feasible grid point, constraints by an exact penalty, at most
//! [`MAX_POLISH_SOLVES`] solves. Warm starts ([`super::statics::analyse_from`]): the grid
//! is solved in runs along its rows, in parallel, each point from its neighbour's solution
//! (the first of a run from the statics' own coarse pre-solve), and each point of the
//! polish from the nearest point it has solved; the answers are the cold ones to the ring
//! tolerance, for fewer lamina evaluations.
//! At the optimum the lamina noise (the objective with Γ against 2Γ laminae) is reported
//! beside the improvement, and the sensitivity of the objective to a 0.1 % change of each
//! radius (central differences, step 1e-3 relative: above the 1e-4 floor a 0.2 % radius
//! change needs).

pub mod engine;
pub mod report;
pub mod view;

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use serde::Serialize;

use super::input::{DoubleRowInput, LoadCase};
use super::statics::{analyse, analyse_from, DoubleRowAnalysis, StaticsStart};
use crate::bearings::SolveError;
use crate::numerics::cancel::Cancel;
use crate::physics::lubrication::film;
use engine::{Eval, GridPoint, PointError};

/// The most solves a grid may take (grid^variables × load cases): 21² × 3 cases is 1323;
/// 41² × 3 is 5043; a three-variable 21³ × 3 (27 783) is refused.
pub const MAX_GRID_SOLVES: usize = 20_000;

/// The polish's budget of solves (issue 27 "Speed").
pub const MAX_POLISH_SOLVES: usize = 100;

/// Relative step of the sensitivity: 0.1 % of the radius.
pub const SENSITIVITY_STEP: f64 = 1e-3;

/// One of the optimiser's variables.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Variable {
    /// k_Ci = R′_Ci/R_Ci.
    KCi,
    /// k_W = R′_W/R_W.
    KW,
    /// k_CE = R′_CE/R_CE (with d_m moved to keep the deck check).
    KCe,
}

impl Variable {
    /// The deck's name (`optimise.variables`).
    pub fn name(self) -> &'static str {
        match self {
            Variable::KCi => "k_ci",
            Variable::KW => "k_w",
            Variable::KCe => "k_ce",
        }
    }

    /// The variable a deck name means.
    pub fn parse(s: &str) -> Option<Variable> {
        match s {
            "k_ci" => Some(Variable::KCi),
            "k_w" => Some(Variable::KW),
            "k_ce" => Some(Variable::KCe),
            _ => None,
        }
    }

    /// Label on screen: R′/R of which radius.
    pub fn label(self) -> &'static str {
        match self {
            Variable::KCi => "R'Ci/RCi",
            Variable::KW => "R'W/RW",
            Variable::KCe => "R'CE/RCE",
        }
    }
}

/// The bearing with relative radii `k` applied to `vars`.
pub fn apply(base: &DoubleRowInput, vars: &[Variable], k: &[f64]) -> DoubleRowInput {
    let mut b = base.clone();
    let g = &mut b.geometry;
    for (v, k) in vars.iter().zip(k) {
        match v {
            Variable::KCi => g.inner_raceway_radius_m = base.geometry.inner_raceway_radius_m * k,
            Variable::KW => g.roller_crown_radius_m = base.geometry.roller_crown_radius_m * k,
            Variable::KCe => {
                let r0 = base.geometry.outer_sphere_radius_m;
                g.outer_sphere_radius_m = r0 * k;
                g.pitch_diameter_m = base.geometry.pitch_diameter_m
                    + 2.0 * (r0 * k - r0) * base.geometry.contact_angle_rad.cos();
            }
        }
    }
    b
}

/// What the objective gives for one solved load case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct CaseLoss {
    pub total_w: f64,
    /// M_fi, N·m.
    pub friction_torque_inner_nm: f64,
    /// M_fo, N·m.
    pub friction_torque_outer_nm: f64,
}

/// The objective: the loss of one solved bearing, or why it has none.
pub type Objective<'a> = dyn Fn(&DoubleRowAnalysis) -> Result<CaseLoss, String> + Sync + 'a;

/// The system's objective: the loss breakdown of the solved bearing
/// ([`super::losses::losses`]): total loss, M_fi, M_fo.
pub fn loss_objective(a: &DoubleRowAnalysis) -> Result<CaseLoss, String> {
    let l = super::losses::losses(a).map_err(|e| e.to_string())?.losses;
    Ok(CaseLoss {
        total_w: l.total_w,
        friction_torque_inner_nm: l.friction_torque_inner_nm,
        friction_torque_outer_nm: l.friction_torque_outer_nm,
    })
}

/// [`optimise`] with the system's objective, [`loss_objective`].
pub fn optimise_losses(
    input: &DoubleRowInput,
    name: &str,
    cancel: Cancel<'_>,
) -> Result<Optimisation, OptimiseError> {
    optimise(input, name, &loss_objective, cancel)
}

/// What the constraints read from one solved load case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CaseMetrics {
    pub loss: CaseLoss,
    /// Smallest Λ over the loaded raceways of both rows (None: nothing loaded).
    pub lambda_min: Option<f64>,
    pub l10_mrev: Option<f64>,
    pub max_stress_pa: f64,
    /// Largest line load on an edge lamina, N/m.
    pub edge_line_load_n_m: f64,
}

/// The constraint readings of a solved bearing.
pub fn case_metrics(a: &DoubleRowAnalysis, loss: CaseLoss) -> CaseMetrics {
    let s = &a.input.surfaces;
    let mut lambda: Option<f64> = None;
    let mut edge: f64 = 0.0;
    for row in &a.rows {
        if let Some(f) = &row.films {
            for (k, race_rms) in [(0, s.inner_rms_m), (1, s.outer_rms_m)] {
                let h = f
                    .min_film
                    .iter()
                    .filter_map(|m| m[k])
                    .fold(f64::INFINITY, f64::min);
                if h.is_finite() {
                    let l = film::film_parameter(h, s.roller_rms_m, race_rms);
                    lambda = Some(lambda.map_or(l, |m| m.min(l)));
                }
            }
        }
        for rc in &row.contacts {
            for pair in rc.iter().filter(|p| p[0].edge) {
                for c in pair {
                    edge = edge.max(c.line_load_n_m());
                }
            }
        }
    }
    CaseMetrics {
        loss,
        lambda_min: lambda,
        l10_mrev: a.l10_mrev,
        max_stress_pa: a.max_stress_pa(),
        edge_line_load_n_m: edge,
    }
}

/// One point of the design space over all load cases.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointDetail {
    pub cases: Vec<CaseMetrics>,
    /// Σ w·M_fi and Σ w·M_fo over the cases, N·m.
    pub friction_torque_inner_nm: f64,
    pub friction_torque_outer_nm: f64,
    pub lambda_min: Option<f64>,
    /// min over cases of (L10/L10,nominal)^(1/4) (1 at nominal).
    pub capacity_ratio: f64,
    /// max over cases of p_max/p_max,nominal.
    pub max_stress_ratio: f64,
}

/// Why the optimiser gave no result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OptimiseError {
    /// The settings ask for more than allowed.
    #[error("{key}: {message}")]
    Refused { key: &'static str, message: String },
    /// The nominal bearing does not solve.
    #[error("the nominal bearing does not solve at load case {case} (F_r = {radial_n:.1} N, F_a = {axial_n:.1} N): {message}")]
    Nominal {
        case: usize,
        radial_n: f64,
        axial_n: f64,
        message: String,
    },
    /// No grid point satisfies the constraints.
    #[error("no point of the {points}-point grid satisfies the constraints; at the nominal radii: {nominal}")]
    Infeasible { points: usize, nominal: String },
    /// A newer job superseded the run.
    #[error("cancelled")]
    Cancelled,
}

/// The optimum and what binds it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Optimum {
    /// Relative radii by deck name.
    pub variables: BTreeMap<&'static str, f64>,
    pub total_w: f64,
    /// (nominal − optimum)/nominal, %.
    pub improvement_pct: f64,
    pub lambda_min: Option<f64>,
    pub capacity_ratio: f64,
    pub max_stress_ratio: f64,
    pub friction_torque_inner_nm: f64,
    pub friction_torque_outer_nm: f64,
    /// Constraints and bounds that stop the optimum going further (empty: an interior
    /// minimum).
    pub binding: Vec<String>,
}

/// The grid's lowest loss whatever the constraints: what they cost.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Unconstrained {
    pub variables: BTreeMap<&'static str, f64>,
    pub total_w: f64,
    pub improvement_pct: f64,
    /// The constraints it violates.
    pub violated: Vec<&'static str>,
}

/// One grid point in the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GridEntry {
    pub variables: BTreeMap<&'static str, f64>,
    /// None when a load case did not solve (`error` says why).
    pub total_w: Option<f64>,
    pub feasible: bool,
    pub violated: Vec<&'static str>,
    pub lambda_min: Option<f64>,
    pub capacity_ratio: Option<f64>,
    pub max_stress_ratio: Option<f64>,
    pub friction_torque_inner_nm: Option<f64>,
    pub friction_torque_outer_nm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// Solves spent by each phase.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Solves {
    pub nominal: usize,
    pub grid: usize,
    pub polish: usize,
    pub sensitivity: usize,
    pub noise: usize,
}

/// The nominal bearing's values the optimum is measured against.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NominalSummary {
    pub total_w: f64,
    pub friction_torque_inner_nm: f64,
    pub friction_torque_outer_nm: f64,
    pub lambda_min: Option<f64>,
    pub max_stress_pa: f64,
    /// Violated constraints at nominal (only `lambda_min` can be).
    pub violated: Vec<&'static str>,
}

/// The `optimise` output (a contract: fields are added, never renamed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Optimisation {
    pub variables: Vec<&'static str>,
    pub relative_range: f64,
    pub grid_points_per_variable: usize,
    pub load_cases: Vec<LoadCase>,
    pub nominal: NominalSummary,
    pub optimum: Optimum,
    /// The grid point of lowest loss ignoring the constraints (None when no point solved).
    pub unconstrained: Option<Unconstrained>,
    pub grid: Vec<GridEntry>,
    /// Objective change, % of its value at the optimum, per +0.1 % of each radius.
    pub sensitivity_pct_per_0_1pct: BTreeMap<&'static str, f64>,
    /// |objective(2Γ laminae) − objective(Γ)| at the optimum, W.
    pub noise_w: f64,
    pub laminae: usize,
    /// Why the polish stopped.
    pub polish_stopped: String,
    pub solves: Solves,
    pub wall_time_s: f64,
}

/// The load cases of `[optimise]`, or the deck's operating loads as one case of weight 1.
pub fn load_cases(input: &DoubleRowInput) -> Vec<LoadCase> {
    if input.optimise.load_cases.is_empty() {
        vec![LoadCase {
            radial_load_n: input.operating.radial_load_n,
            axial_load_n: input.operating.axial_load_n,
            weight: 1.0,
        }]
    } else {
        input.optimise.load_cases.clone()
    }
}

/// The variables of `[optimise]` (names the deck check already validated).
pub fn variables(input: &DoubleRowInput) -> Vec<Variable> {
    input
        .optimise
        .variables
        .iter()
        .filter_map(|s| Variable::parse(s))
        .collect()
}

/// Everything one design point's evaluation needs.
struct Problem<'a> {
    base: &'a DoubleRowInput,
    name: &'a str,
    vars: Vec<Variable>,
    cases: Vec<LoadCase>,
    objective: &'a Objective<'a>,
    cancel: Cancel<'a>,
    /// Solves so far and planned (progress).
    solves: AtomicUsize,
    planned: usize,
}

impl Problem<'_> {
    fn input_at(&self, k: &[f64], case: &LoadCase, laminae: usize) -> DoubleRowInput {
        let mut b = apply(self.base, &self.vars, k);
        b.operating.radial_load_n = case.radial_load_n;
        b.operating.axial_load_n = case.axial_load_n;
        b.solver.laminae = laminae;
        b
    }

    /// Solve every load case at `k` with `laminae`.
    fn solve_cases(&self, k: &[f64], laminae: usize) -> Result<Vec<CaseMetrics>, PointError> {
        self.solve_cases_from(k, laminae, None).map(|(m, _)| m)
    }

    /// [`Problem::solve_cases`] with each case's statics started from `from` (a
    /// neighbouring point's solutions, one per case, [`analyse_from`]); returns the
    /// solutions too. A warm start the statics cannot take is retried cold, so a point
    /// answers what a cold solve answers.
    fn solve_cases_from(
        &self,
        k: &[f64],
        laminae: usize,
        from: Option<&[StaticsStart]>,
    ) -> Result<(Vec<CaseMetrics>, Vec<StaticsStart>), PointError> {
        let mut out = Vec::with_capacity(self.cases.len());
        let mut starts = Vec::with_capacity(self.cases.len());
        for (c, case) in self.cases.iter().enumerate() {
            if self.cancel.is_cancelled() {
                return Err(PointError::Cancelled);
            }
            let b = self.input_at(k, case, laminae);
            let warm = from.and_then(|f| f.get(c));
            let a = match analyse_from(&b, self.name, warm, self.cancel.flag()) {
                Err(e) if warm.is_some() && e != SolveError::Cancelled => {
                    analyse(&b, self.name, self.cancel.flag())
                }
                other => other,
            };
            let n = self.solves.fetch_add(1, Ordering::Relaxed) + 1;
            self.cancel.report(n as f64 / self.planned.max(1) as f64);
            let a = match a {
                Ok(a) => a,
                Err(SolveError::Cancelled) => return Err(PointError::Cancelled),
                Err(e) => {
                    return Err(PointError::Failed(format!(
                        "F_r = {:.1} N, F_a = {:.1} N: {e}",
                        case.radial_load_n, case.axial_load_n
                    )))
                }
            };
            let loss = (self.objective)(&a).map_err(|e| {
                PointError::Failed(format!(
                    "F_r = {:.1} N, F_a = {:.1} N: losses: {e}",
                    case.radial_load_n, case.axial_load_n
                ))
            })?;
            out.push(case_metrics(&a, loss));
            starts.push(a.start());
        }
        Ok((out, starts))
    }

    fn detail(&self, cases: Vec<CaseMetrics>, nominal: Option<&[CaseMetrics]>) -> PointDetail {
        let w = |i: usize| self.cases.get(i).map_or(1.0, |c| c.weight);
        let sum = |f: &dyn Fn(&CaseMetrics) -> f64| -> f64 {
            cases.iter().enumerate().map(|(i, c)| w(i) * f(c)).sum()
        };
        let lambda_min = cases.iter().filter_map(|c| c.lambda_min).reduce(f64::min);
        let (mut cap, mut stress) = (1.0_f64, 1.0_f64);
        if let Some(nom) = nominal {
            for (c, n) in cases.iter().zip(nom) {
                let r = match (c.l10_mrev, n.l10_mrev) {
                    (Some(l), Some(l0)) if l0 > 0.0 => (l / l0).powf(0.25),
                    (None, Some(_)) => 0.0,
                    _ => 1.0,
                };
                cap = cap.min(r);
                if n.max_stress_pa > 0.0 {
                    stress = stress.max(c.max_stress_pa / n.max_stress_pa);
                }
            }
            if cases.is_empty() {
                cap = 1.0;
            }
        }
        PointDetail {
            friction_torque_inner_nm: sum(&|c| c.loss.friction_torque_inner_nm),
            friction_torque_outer_nm: sum(&|c| c.loss.friction_torque_outer_nm),
            lambda_min,
            capacity_ratio: cap,
            max_stress_ratio: stress,
            cases,
        }
    }
}

/// The constraint margins of `d` against the nominal point `nom`.
fn margins(
    input: &DoubleRowInput,
    d: &PointDetail,
    nom: &[CaseMetrics],
) -> Vec<(&'static str, f64)> {
    let o = &input.optimise;
    let mut m = Vec::with_capacity(4);
    let lam = d.lambda_min.unwrap_or(f64::INFINITY);
    m.push((
        "lambda_min",
        if o.min_lambda > 0.0 {
            (lam / o.min_lambda - 1.0).min(1e3)
        } else {
            1.0
        },
    ));
    m.push((
        "capacity_ratio",
        if o.min_capacity_ratio > 0.0 {
            d.capacity_ratio / o.min_capacity_ratio - 1.0
        } else {
            1.0
        },
    ));
    m.push(("p_max", 1.0 - d.max_stress_ratio));
    // Edge laminae: relative to the nominal edge line load, or (nominal 0) to the
    // nominal largest stress's scale through the line load of the case's most loaded
    // lamina: any edge load is then a violation of its own size.
    let mut edge = f64::INFINITY;
    for (c, n) in d.cases.iter().zip(nom) {
        let e = if n.edge_line_load_n_m > 0.0 {
            1.0 - c.edge_line_load_n_m / n.edge_line_load_n_m
        } else if c.edge_line_load_n_m > 0.0 {
            -1.0
        } else {
            1.0
        };
        edge = edge.min(e);
    }
    m.push(("edge_loading", if edge.is_finite() { edge } else { 1.0 }));
    m
}

/// The geometric order R_Ci > R_W, R_CE > R_W as margins (relative).
fn order_margins(b: &DoubleRowInput) -> [(&'static str, f64); 2] {
    let g = &b.geometry;
    [
        (
            "r_ci_gt_r_w",
            g.inner_raceway_radius_m / g.roller_crown_radius_m - 1.0,
        ),
        (
            "r_ce_gt_r_w",
            g.outer_sphere_radius_m / g.roller_crown_radius_m - 1.0,
        ),
    ]
}

/// Runs the optimiser on `input`'s `[optimise]` with `objective` the loss of one solved
/// case. `cancel` is checked before every solve; its progress is told solves done over
/// solves planned.
pub fn optimise(
    input: &DoubleRowInput,
    name: &str,
    objective: &Objective<'_>,
    cancel: Cancel<'_>,
) -> Result<Optimisation, OptimiseError> {
    let start = Instant::now();
    let vars = variables(input);
    let cases = load_cases(input);
    let o = &input.optimise;
    let n = o.grid.max(2);
    let dims = vars.len().max(1);
    let grid_points = n.checked_pow(dims as u32).unwrap_or(usize::MAX);
    let grid_solves = grid_points.saturating_mul(cases.len());
    if grid_solves > MAX_GRID_SOLVES {
        let max_n = (1..=n)
            .rev()
            .find(|m| m.saturating_pow(dims as u32).saturating_mul(cases.len()) <= MAX_GRID_SOLVES)
            .unwrap_or(1);
        return Err(OptimiseError::Refused {
            key: "optimise.grid",
            message: format!(
                "{n} points per variable over {dims} variables × {} load cases is {grid_solves} solves, above the bound {MAX_GRID_SOLVES}: use at most {max_n} points per variable (or fewer variables or load cases)",
                cases.len()
            ),
        });
    }
    let laminae = input.solver.laminae;
    let sens_solves = 2 * dims * cases.len();
    let planned = cases.len() * 2 + grid_solves + MAX_POLISH_SOLVES + sens_solves;
    let p = Problem {
        base: input,
        name,
        vars: vars.clone(),
        cases: cases.clone(),
        objective,
        cancel,
        solves: AtomicUsize::new(0),
        planned,
    };
    let ones = vec![1.0; vars.len()];
    let nominal_cases = p.solve_cases(&ones, laminae).map_err(|e| match e {
        PointError::Cancelled => OptimiseError::Cancelled,
        PointError::Failed(message) => OptimiseError::Nominal {
            case: 1,
            radial_n: cases.first().map_or(0.0, |c| c.radial_load_n),
            axial_n: cases.first().map_or(0.0, |c| c.axial_load_n),
            message,
        },
    })?;
    let nominal_solves = p.solves.load(Ordering::Relaxed);
    let nom_detail = p.detail(nominal_cases.clone(), Some(&nominal_cases));
    let weighted = |cs: &[CaseMetrics]| -> f64 {
        cs.iter()
            .zip(&cases)
            .map(|(c, l)| l.weight * c.loss.total_w)
            .sum()
    };
    let nominal_total = weighted(&nominal_cases);
    let nom_margins = margins(input, &nom_detail, &nominal_cases);
    let nominal = NominalSummary {
        total_w: nominal_total,
        friction_torque_inner_nm: nom_detail.friction_torque_inner_nm,
        friction_torque_outer_nm: nom_detail.friction_torque_outer_nm,
        lambda_min: nom_detail.lambda_min,
        max_stress_pa: nominal_cases
            .iter()
            .map(|c| c.max_stress_pa)
            .fold(0.0, f64::max),
        violated: nom_margins
            .iter()
            .filter(|(_, m)| *m < -engine::FEASIBILITY_TOLERANCE)
            .map(|(n, _)| *n)
            .collect(),
    };
    // A point's evaluation from its neighbour's solutions (grid rows, the polish), returning
    // its own.
    type Starts = Vec<StaticsStart>;
    let eval_from = |k: &[f64],
                     laminae: usize,
                     from: Option<&Starts>|
     -> Result<(Eval<PointDetail>, Option<Starts>), PointError> {
        let b = apply(input, &vars, k);
        let order = order_margins(&b);
        if order.iter().any(|(_, m)| *m <= 0.0) {
            // Not a bearing: no solve, infinitely bad.
            let mut margins = margins(input, &nom_detail, &nominal_cases);
            margins.extend(order);
            let e = Eval {
                objective: f64::INFINITY,
                margins,
                detail: nom_detail.clone(),
            };
            return Ok((e, None));
        }
        let (cs, starts) = p.solve_cases_from(k, laminae, from.map(Vec::as_slice))?;
        let total = weighted(&cs);
        let d = p.detail(cs, Some(&nominal_cases));
        let mut m = margins(input, &d, &nominal_cases);
        m.extend(order);
        let e = Eval {
            objective: total,
            margins: m,
            detail: d,
        };
        Ok((e, Some(starts)))
    };
    let eval_at = |k: &[f64], laminae: usize| eval_from(k, laminae, None).map(|(e, _)| e);
    // The engine works in u = k − 1 ∈ [−r, r]: the grid's middle point is u = 0 exactly
    // (−r + 2r·½), so an odd grid holds the nominal bearing bit for bit.
    let to_k = |u: &[f64]| -> Vec<f64> { u.iter().map(|x| 1.0 + x).collect() };
    let eval = |u: &[f64]| eval_at(&to_k(u), laminae);
    let eval_warm = |u: &[f64], from: Option<&Starts>| eval_from(&to_k(u), laminae, from);
    let r = o.relative_range;
    let lo = vec![-r; vars.len()];
    let hi = vec![r; vars.len()];
    let points = engine::grid_warm(&lo, &hi, n, &eval_warm, Cancel::from_option(cancel.flag()))
        .map_err(|_| OptimiseError::Cancelled)?;
    let after_grid = p.solves.load(Ordering::Relaxed);
    let Some(best) = engine::best_feasible(&points) else {
        let nominal_text = nom_margins
            .iter()
            .map(|(name, m)| format!("{name} margin {:+.3} %", m * 100.0))
            .collect::<Vec<_>>()
            .join(", ");
        return Err(OptimiseError::Infeasible {
            points: points.len(),
            nominal: format!(
                "{nominal_text} (Λ_min {:.3} against optimise.min_lambda {})",
                nom_detail.lambda_min.unwrap_or(0.0),
                o.min_lambda
            ),
        });
    };
    let mut binding: Vec<String> = engine::binding_at(&points, best)
        .into_iter()
        .map(str::to_string)
        .collect();
    let Ok(best_eval) = points[best].eval.clone() else {
        return Err(OptimiseError::Cancelled);
    };
    let step = (hi[0] - lo[0]) / (n - 1) as f64;
    let budget = MAX_POLISH_SOLVES / cases.len().max(1);
    let pol = engine::polish_warm(
        &points[best].x,
        best_eval,
        None,
        &vec![step; vars.len()],
        &lo,
        &hi,
        budget,
        &eval_warm,
    )
    .map_err(|_| OptimiseError::Cancelled)?;
    let after_polish = p.solves.load(Ordering::Relaxed);
    for (i, upper) in engine::at_bounds(&pol.x, &lo, &hi) {
        binding.push(format!(
            "{} {} bound ({})",
            vars[i].name(),
            if upper { "upper" } else { "lower" },
            1.0 + if upper { hi[i] } else { lo[i] }
        ));
    }
    for (name, m) in &pol.eval.margins {
        if *m < 1e-3 && !binding.iter().any(|b| b == name) {
            binding.push((*name).to_string());
        }
    }
    // Sensitivity at the optimum: central differences, ±0.1 % of each radius.
    let mut sensitivity = BTreeMap::new();
    for (i, v) in vars.iter().enumerate() {
        let mut plus = pol.x.clone();
        let mut minus = pol.x.clone();
        plus[i] += SENSITIVITY_STEP;
        minus[i] -= SENSITIVITY_STEP;
        let f = |k: &[f64]| -> Result<f64, OptimiseError> {
            match eval(k) {
                Ok(e) => Ok(e.objective),
                Err(PointError::Cancelled) => Err(OptimiseError::Cancelled),
                Err(PointError::Failed(_)) => Ok(f64::NAN),
            }
        };
        let (fp, fm) = (f(&plus)?, f(&minus)?);
        sensitivity.insert(
            v.name(),
            (fp - fm) / (2.0 * pol.eval.objective) * 100.0 * (1e-3 / SENSITIVITY_STEP),
        );
    }
    let after_sens = p.solves.load(Ordering::Relaxed);
    // Lamina noise: the optimum with 2Γ laminae.
    let fine = p
        .solve_cases(&to_k(&pol.x), 2 * laminae)
        .map_err(|e| match e {
            PointError::Cancelled => OptimiseError::Cancelled,
            PointError::Failed(message) => OptimiseError::Nominal {
                case: 1,
                radial_n: 0.0,
                axial_n: 0.0,
                message: format!("at the optimum with {} laminae: {message}", 2 * laminae),
            },
        })?;
    let noise_w = (weighted(&fine) - pol.eval.objective).abs();
    let after_noise = p.solves.load(Ordering::Relaxed);
    cancel.report(1.0);
    let named = |x: &[f64]| -> BTreeMap<&'static str, f64> {
        vars.iter().zip(x).map(|(v, k)| (v.name(), *k)).collect()
    };
    let grid = points
        .iter()
        .map(|gp: &GridPoint<PointDetail>| match &gp.eval {
            Ok(e) => GridEntry {
                variables: named(&to_k(&gp.x)),
                total_w: e.objective.is_finite().then_some(e.objective),
                feasible: e.feasible(),
                violated: e.violated(),
                lambda_min: e.detail.lambda_min,
                capacity_ratio: Some(e.detail.capacity_ratio),
                max_stress_ratio: Some(e.detail.max_stress_ratio),
                friction_torque_inner_nm: Some(e.detail.friction_torque_inner_nm),
                friction_torque_outer_nm: Some(e.detail.friction_torque_outer_nm),
                error: None,
            },
            Err(msg) => GridEntry {
                variables: named(&to_k(&gp.x)),
                total_w: None,
                feasible: false,
                violated: vec!["solve failed"],
                lambda_min: None,
                capacity_ratio: None,
                max_stress_ratio: None,
                friction_torque_inner_nm: None,
                friction_torque_outer_nm: None,
                error: Some(msg.clone()),
            },
        })
        .collect();
    let unconstrained = points
        .iter()
        .filter_map(|gp| gp.eval.as_ref().ok().map(|e| (gp, e)))
        .filter(|(_, e)| e.objective.is_finite())
        .min_by(|a, b| a.1.objective.total_cmp(&b.1.objective))
        .map(|(gp, e)| Unconstrained {
            variables: named(&to_k(&gp.x)),
            total_w: e.objective,
            improvement_pct: (nominal_total - e.objective) / nominal_total * 100.0,
            violated: e.violated(),
        });
    let d = &pol.eval.detail;
    Ok(Optimisation {
        unconstrained,
        variables: vars.iter().map(|v| v.name()).collect(),
        relative_range: r,
        grid_points_per_variable: n,
        load_cases: cases,
        optimum: Optimum {
            variables: named(&to_k(&pol.x)),
            total_w: pol.eval.objective,
            improvement_pct: (nominal_total - pol.eval.objective) / nominal_total * 100.0,
            lambda_min: d.lambda_min,
            capacity_ratio: d.capacity_ratio,
            max_stress_ratio: d.max_stress_ratio,
            friction_torque_inner_nm: d.friction_torque_inner_nm,
            friction_torque_outer_nm: d.friction_torque_outer_nm,
            binding,
        },
        nominal,
        grid,
        sensitivity_pct_per_0_1pct: sensitivity,
        noise_w,
        laminae,
        polish_stopped: pol.stopped,
        solves: Solves {
            nominal: nominal_solves,
            grid: after_grid - nominal_solves,
            polish: after_polish - after_grid,
            sensitivity: after_sens - after_polish,
            noise: after_noise - after_sens,
        },
        wall_time_s: start.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests;
