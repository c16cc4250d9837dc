//! The race-control analysis of one case: preload at rest, load distribution at speed,
//! Hertz contacts, spin heat (2-13), EHD film (4-10, 4-11), the skidding condition (2-4)
//! per ball and the speed at which it is first violated, and the bulk temperature (4-1).
//!
//! The driver: the stages run in order here; each contact's evaluation and the rheology
//! curve are in `contacts`, the skid search in `skid`, the load conditions in
//! `load_conditions`, the result types in `results` (re-exported here, their public
//! path), and the tests in `analysis_tests.rs`.

use super::contacts::{contact_result, semi_axes};
use super::dynamics::DynamicsResult;
use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, Method};
use super::load_conditions::{axial_condition, conditions};
use super::load_distribution::{self, LoadDistribution};
use super::race_control::ContactKinematics;
use super::skid::resisting;
use crate::numerics::cancel::Cancel;
use crate::physics::contact::point::Race;

pub use super::contacts::{film_thermal, resolve_traction};
pub use super::results::{BallResult, ContactResult, RheologyContact, SkidSample, SkidThreshold};
pub use super::skid::{skid_threshold, skid_threshold_streaming};

/// A solved case.
#[derive(Debug, Clone, PartialEq)]
pub struct BallAnalysis {
    /// The input.
    pub input: BallInput,
    /// Derived geometry.
    pub geometry: BallGeometry,
    /// The axial displacement at rest that holds the preload, m (displacement mode).
    pub rest_axial_deflection_m: Option<f64>,
    /// The load distribution.
    pub load: LoadDistribution,
    /// Per ball.
    pub balls: Vec<BallResult>,
    /// The 5×5 stiffness matrix at the operating point (issue 29).
    pub stiffness: super::stiffness::BallStiffness,
    /// The skidding threshold.
    pub skid: SkidThreshold,
    /// Total heat, W: race control's spin heat, or the ball dynamics' slice heat when
    /// `dynamics.method` asks for it.
    pub total_heat_w: f64,
    /// Race control's spin heat (2-13b) summed over the balls, W.
    pub race_control_heat_w: f64,
    /// The ball dynamics (quasi-static or time simulation), when asked for.
    pub dynamics: Option<DynamicsResult>,
    /// Bulk temperature T_oil + H/(ρ c Q̇), K (4-1), with H = `total_heat_w` (the
    /// seed's sliding heat; the friction's other mechanisms are not in eq. 4-1).
    pub bulk_temperature_k: f64,
    /// The `[cage]` section's mechanisms (`viscous_drag`, `cage_rails`), at the inlet
    /// viscosity and the balls' mean race-control cage speed; empty without the section.
    pub cage_losses: Vec<crate::bearings::friction::Mechanism>,
    /// For `traction.curve = "rheology"`: the contact the curve was tabulated at.
    pub rheology_contact: Option<RheologyContact>,
    /// The load distribution's fixed-point iterations for one ball (the workbench's
    /// stepper), when asked for: (ball, steps).
    pub load_trace: Option<(usize, Vec<load_distribution::LoadStep>)>,
}

/// The sliding-speed band of the contacts, m/s: min and max of the slice sliding speeds
/// |ω_s·x_k| over every loaded contact of every ball, the slices at
/// x_k = −a + (k+½)·2a/n across the transverse axis (n = `dynamics.slices`, as the ball
/// dynamics cuts them) with race control's spin; `None` when no contact is loaded. The
/// Traction pane shades it on the curve.
pub fn sliding_band(a: &BallAnalysis) -> Option<(f64, f64)> {
    let n = a.input.dynamics.slices.max(1);
    let mut band: Option<(f64, f64)> = None;
    for b in &a.balls {
        for c in [&b.inner, &b.outer] {
            if c.load_n <= 0.0 {
                continue;
            }
            let (ax, _) = semi_axes(&c.hertz);
            for k in 0..n {
                let x = -ax + (k as f64 + 0.5) * 2.0 * ax / n as f64;
                let u = (c.kinematics.spin_rad_s * x).abs();
                band = Some(match band {
                    None => (u, u),
                    Some((lo, hi)) => (lo.min(u), hi.max(u)),
                });
            }
        }
    }
    band
}

/// The bearing bulk temperature of eq. 4-1: all heat H (W) carried off by the oil flow
/// Q̇ (m³/s) of density ρ (kg/m³) and specific heat c (J/(kg·K)) supplied at T_oil (K): K.
pub fn bulk_temperature_k(
    heat_w: f64,
    density_kg_m3: f64,
    specific_heat_j_kg_k: f64,
    flow_m3_s: f64,
    supply_k: f64,
) -> f64 {
    supply_k + heat_w / (density_kg_m3 * specific_heat_j_kg_k * flow_m3_s)
}

/// The error of a bulk temperature (4-1) that is not finite, naming the inputs that made
/// it: the heat, when it is itself not finite, or else the lubricant's heat capacity flow
/// ρ·c_p·Q̇, which in-range but extreme inputs (`lubricant.density = 5e-324`) can make
/// zero or so small that H/(ρ·c_p·Q̇) overflows. A JSON `null` and "inf °C" with exit 0
/// reported it as a result (issue 24, item 8).
fn not_finite_bulk(input: &BallInput, heat_w: f64) -> BallError {
    let l = &input.lubricant;
    let capacity = l.density_kg_m3 * l.specific_heat_j_kg_k * l.flow_rate_m3_s;
    let inputs = format!(
        "lubricant.density = {:e} kg/m³, lubricant.specific_heat = {:e} J/(kg·K), lubricant.flow_rate_l_min = {:e} l/min",
        l.density_kg_m3,
        l.specific_heat_j_kg_k,
        l.flow_rate_m3_s * 60_000.0
    );
    if heat_w.is_finite() {
        BallError::NotFinite(format!(
            "bulk temperature (4-1) is not finite: the lubricant's heat capacity flow ρ·c_p·Q = {capacity:e} W/K is too small to carry the heat {heat_w:.4e} W ({inputs})"
        ))
    } else {
        BallError::NotFinite(format!(
            "the bearing's heat is not finite ({heat_w} W), so neither is the bulk temperature (4-1); the heat follows from the speeds, loads and traction (operating.inner_speed = {} rpm, operating.outer_speed = {} rpm, traction.curve = \"{}\"); lubricant: {inputs}",
            input.operating.inner_speed_rad_s * 30.0 / std::f64::consts::PI,
            input.operating.outer_speed_rad_s * 30.0 / std::f64::consts::PI,
            input.traction.preset.name()
        ))
    }
}

impl BallAnalysis {
    /// The largest Hertz pressure p₀ over every contact of every ball, Pa (the key
    /// output `max_pressure_pa` and the stress warning).
    pub fn max_pressure_pa(&self) -> f64 {
        self.balls
            .iter()
            .flat_map(|b| [b.inner.hertz.max_pressure_pa, b.outer.hertz.max_pressure_pa])
            .fold(0.0, f64::max)
    }
}

/// Solve a case by the race-control method.
pub fn analyse(input: &BallInput, cancel: Cancel) -> Result<BallAnalysis, BallError> {
    analyse_traced(input, cancel, None)
}

/// [`analyse`], recording the load distribution's iterations of ball `trace_ball`
/// (0-based) for the stepper when given (the answer is the same: recording only reads).
pub fn analyse_traced(
    input: &BallInput,
    cancel: Cancel,
    trace_ball: Option<usize>,
) -> Result<BallAnalysis, BallError> {
    analyse_streaming(input, cancel, trace_ball, &mut |_| {})
}

/// [`analyse_traced`], calling `on_skid_sample` with the skidding search's speeds solved
/// so far after each of them ([`skid_threshold_streaming`]; the workbench's Skid pane).
/// The search runs before the ball dynamics, which it does not depend on, so the pane
/// fills before a long time simulation ends. The analysis is the same.
pub fn analyse_streaming(
    input: &BallInput,
    cancel: Cancel,
    trace_ball: Option<usize>,
    on_skid_sample: &mut dyn FnMut(&[SkidSample]),
) -> Result<BallAnalysis, BallError> {
    let (input, rheology_contact) = resolve_traction(input, cancel)?;
    let input: &BallInput = &input;
    input
        .traction
        .curve()
        .validate()
        .map_err(|e| BallError::InvalidInput(format!("traction: {e}")))?;
    let op = &input.operating;
    // Zero is allowed (issue 29): a pure radial load, or a bearing at rest with nothing
    // on it; `axial_condition` says what holds the ring axially then.
    if !(op.axial_load_n.is_finite() && op.axial_load_n >= 0.0) {
        return Err(BallError::InvalidInput(format!(
            "operating.axial_load = {} N: it must be a finite force ≥ 0 N (0 for a pure radial load)",
            op.axial_load_n
        )));
    }
    let geom = BallGeometry::new(input)?;
    let (axial, rest) = axial_condition(input, &geom, cancel)?;
    let (load, load_trace) = match trace_ball {
        None => (
            load_distribution::solve(&geom, &conditions(input, axial, 1.0), cancel)?,
            None,
        ),
        Some(j) => {
            let (l, steps) =
                load_distribution::solve_traced(&geom, &conditions(input, axial, 1.0), cancel, j)?;
            (l, Some((j, steps)))
        }
    };
    let stiffness = super::stiffness::stiffness(&geom, &load, input.solver.stiffness)?;
    let mu = input.traction.curve().max_mu();
    let mut balls = Vec::with_capacity(load.balls.len());
    // A contact's result depends only on its load state and kinematics: balls in the
    // same state (every ball under an axial load) share it instead of recomputing the
    // film temperature (exact: the same inputs give the same numbers).
    let mut done: Vec<(
        Race,
        load_distribution::ContactLoad,
        ContactKinematics,
        ContactResult,
    )> = Vec::new();
    let mut contact = |race: Race, l: &load_distribution::ContactLoad, k: ContactKinematics| {
        if let Some(c) = done
            .iter()
            .find(|d| d.0 == race && d.1 == *l && d.2 == k)
            .map(|d| d.3)
        {
            return Ok(c);
        }
        let c = contact_result(input, &geom, race, l, k)?;
        done.push((race, *l, k, c));
        Ok::<_, BallError>(c)
    };
    for b in &load.balls {
        let k = &b.kinematics;
        let inner = contact(Race::Inner, &b.equilibrium.inner, k.inner)?;
        let outer = contact(Race::Outer, &b.equilibrium.outer, k.outer)?;
        let res = resisting(mu, &geom, b);
        balls.push(BallResult {
            azimuth_rad: b.azimuth_rad,
            centrifugal_n: b.equilibrium.centrifugal_n,
            gyroscopic_moment_nm: b.gyroscopic_moment_nm,
            resisting_moment_nm: res,
            // As in the threshold search ([`worst`]): only a ball gripped by both races
            // can skid in the sense of 2-4.
            skidding: b.equilibrium.inner.load_n > 0.0
                && b.equilibrium.outer.load_n > 0.0
                && b.gyroscopic_moment_nm.abs() > res,
            heat_w: inner.spin_heat_w + outer.spin_heat_w,
            cage_rad_s: k.cage_rad_s,
            ball_spin_rad_s: k.ball_spin_rad_s,
            ball_axial_rad_s: k.ball_axial_rad_s,
            ball_radial_rad_s: k.ball_radial_rad_s,
            control: k.control,
            inner,
            outer,
        });
    }
    let race_control_heat: f64 = balls.iter().map(|b| b.heat_w).sum();
    let skid = skid_threshold_streaming(input, &geom, axial, cancel, on_skid_sample)?;
    let dynamics = match input.dynamics.method {
        Method::RaceControl => None,
        Method::QuasiStatic | Method::TimeSimulation => {
            let d = super::dynamics::run(input, &geom, &balls, cancel)?;
            for (b, bd) in balls.iter_mut().zip(&d.balls) {
                b.heat_w = bd.heat_w;
            }
            Some(d)
        }
    };
    let total: f64 = balls.iter().map(|b| b.heat_w).sum();
    let lub = &input.lubricant;
    let bulk = bulk_temperature_k(
        total,
        lub.density_kg_m3,
        lub.specific_heat_j_kg_k,
        lub.flow_rate_m3_s,
        lub.supply_temperature_k,
    );
    if !bulk.is_finite() {
        return Err(not_finite_bulk(input, total));
    }
    let cage_losses = cage_losses(input, &balls)?;
    Ok(BallAnalysis {
        cage_losses,
        input: input.clone(),
        geometry: geom,
        rest_axial_deflection_m: rest,
        load,
        balls,
        stiffness,
        skid,
        total_heat_w: total,
        race_control_heat_w: race_control_heat,
        dynamics,
        bulk_temperature_k: bulk,
        rheology_contact,
        load_trace,
    })
}

/// The `[cage]` section's losses (issue 28; `bearings::friction::CageLosses`): the cage
/// turns at the balls' mean race-control orbital speed (one cage, one speed).
fn cage_losses(
    input: &BallInput,
    balls: &[BallResult],
) -> Result<Vec<crate::bearings::friction::Mechanism>, BallError> {
    if !input.cage.is_given() {
        return Ok(Vec::new());
    }
    let cage = balls.iter().map(|b| b.cage_rad_s).sum::<f64>() / balls.len().max(1) as f64;
    let op = &input.operating;
    input
        .cage
        .mechanisms(&crate::bearings::friction::CageState {
            viscosity_pa_s: input.lubricant.viscosity_pa_s,
            density_kg_m3: input.lubricant.density_kg_m3,
            inner_rad_s: op.inner_speed_rad_s,
            outer_rad_s: op.outer_speed_rad_s,
            cage_rad_s: cage,
            pitch_diameter_m: input.geometry.pitch_diameter_m,
        })
        .map_err(BallError::InvalidInput)
}

#[cfg(test)]
#[path = "analysis_tests.rs"]
mod tests;
