//! `rollbench contact`: the roller–inner race contact solved in detail at cage positions
//! (issue 26, seed 003 §Contact model, its Table 3), flooded and isothermal in this
//! round.
//!
//! Orchestration: positions → problems → solutions → rows.
//! * **Load and its history**: roller 1's inner contact load W_i at the cage angle from
//!   the 2-DOF dynamics' last steady cage cycle (`super::tribodynamics`, nearest sample),
//!   when the deck runs the dynamics (`dynamics.revolutions > 0`); otherwise the
//!   quasi-static lamina distribution (the load of the roller at that azimuth, linear
//!   between rollers) with no squeeze. `load_source` says which.
//! * **Squeeze** (dynamics only): the film's transient is one backward-Euler step of
//!   eq. 5's ∂(ρh)/∂t over the dynamics' sample interval Δt, from the steady solution at
//!   the previous sample's load to this sample's load. The film's memory is its transit
//!   time b/ū (≈ 2·10⁻⁵ s for the truck bearing), far below Δt (2.4·10⁻⁴ s at 4 096 Hz),
//!   so one step from the steady previous state carries the whole history.
//! * **Kinematics**: ū = the deck's entrainment speed, Δu = `contact.sliding_speed`.
//! * **Lubricant**: Houpert (eq. 10) and Dowson–Higginson (eq. 11) at the inlet
//!   temperature T_in uniformly (isothermal: `max_temperature_c` is T_in; the thermal
//!   solve is ehl-thermal's, not merged yet).
//! * **Inlet**: flooded, 4.5 Hertz half-widths upstream (seed 003: "4–5"), outlet at
//!   1.5 half-widths (the film has cavitated well before).
//! * **Friction**: viscous = ∫ min(η|Δu|/h, τ₀ + γ_L p) dx × effective length on the EHL
//!   profile ([`viscous_friction_isothermal`]); boundary and asperity load from the
//!   system's Greenwood–Tripp (eqs. 35–40, `mixed_friction`) at Λ = h_c/σ of the EHL
//!   central film. µ = (boundary + viscous)/W_i; power = friction × Δu.
//!
//! `--inlet tipei` and `--model finite-line-ehl` are refused as not built yet.

use serde_json::{json, Value};
use std::fmt::Write;

use super::analysis::analyse;
use super::geometry::{derive, Derived};
use super::input::CylindricalInput;
use super::tribodynamics::{houpert, tribodynamics, TribodynamicsError};
use crate::numerics::cancel::Cancel;
use crate::physics::contact::line::{reduced_modulus, Elastic};
use crate::physics::ehl::line::{
    solve_line_ehl, viscous_friction_isothermal, LineEhlError, LineEhlProblem, LineEhlSolution,
};
use crate::physics::lubrication::greenwood_tripp::Roughness;
use crate::physics::lubrication::mixed_friction::{mixed_friction, MixedContact, DEFAULT_NODES};

/// Nodes of the line-EHL grid (401: h_c within 1 % of 801 nodes, tested).
pub const CONTACT_NODES: usize = 401;
/// Flooded inlet distance in Hertz half-widths (seed 003: "4–5").
pub const FLOODED_INLET_HALF_WIDTHS: f64 = 4.5;
/// Outlet distance in Hertz half-widths.
pub const OUTLET_HALF_WIDTHS: f64 = 1.5;
const CELSIUS_ZERO_K: f64 = 273.15;

/// Which inlet(s) to solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InletChoice {
    /// 4.5 Hertz half-widths upstream.
    Flooded,
    /// Tipei's meniscus (eqs. 14–22): not built yet.
    Tipei,
    /// Both, one row each.
    Both,
}

/// Which contact model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactModel {
    /// 1-D line-contact EHL.
    LineEhl,
    /// 2-D finite-line EHL with the dub-off ends: not built yet.
    FiniteLineEhl,
}

/// What to solve.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactOptions {
    /// Cage positions, deg; empty: the deck's `contact.positions`.
    pub positions_deg: Vec<f64>,
    /// Inlet(s).
    pub inlet: InletChoice,
    /// Model.
    pub model: ContactModel,
}

/// Why `contact` has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// A model or inlet this build does not have.
    #[error("{0} is not built yet (issue 26: flooded isothermal line-ehl is what exists)")]
    NotBuilt(&'static str),
    /// Nothing to solve or an input out of range.
    #[error("{0}")]
    Input(String),
    /// The dynamics failed.
    #[error("contact: the dynamics failed: {0}")]
    Dynamics(#[from] TribodynamicsError),
    /// The EHL solve failed at a position.
    #[error("contact at cage position {position_deg}°: {source}")]
    Solve {
        /// The cage position, deg.
        position_deg: f64,
        /// The solver's error.
        source: LineEhlError,
    },
}

/// One row of Table 3: a position × inlet.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRow {
    /// Cage position, deg.
    pub position_deg: f64,
    /// "flooded" | "tipei".
    pub inlet: &'static str,
    /// "line-ehl".
    pub model: &'static str,
    /// W_i, N.
    pub load_n: f64,
    /// Mutual approach speed of the dynamics at this sample, m/s (0 quasi-static).
    pub approach_speed_m_s: f64,
    /// Inlet distance from the contact centre, m.
    pub inlet_distance_m: f64,
    /// Λ = h_c/σ.
    pub lambda: f64,
    /// W_a, N.
    pub asperity_load_n: f64,
    /// f_b, N.
    pub boundary_friction_n: f64,
    /// f_v, N.
    pub viscous_friction_n: f64,
    /// µ.
    pub friction_coefficient: f64,
    /// (f_b + f_v)·Δu, W.
    pub power_loss_w: f64,
    /// max T, °C.
    pub max_temperature_c: f64,
    /// The EHL solution.
    pub solution: LineEhlSolution,
    /// T per node, °C.
    pub temperature_c: Vec<f64>,
}

/// The study.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactStudy {
    /// "dynamics" or "quasi-static".
    pub load_source: &'static str,
    /// ū, m/s.
    pub entrainment_m_s: f64,
    /// Δu, m/s.
    pub sliding_m_s: f64,
    /// R of the inner contact, m.
    pub reduced_radius_m: f64,
    /// Effective roller length, m.
    pub effective_length_m: f64,
    /// Rows.
    pub rows: Vec<ContactRow>,
}

/// One position's load (N), approach speed (m/s) and, when transient, the previous
/// sample's load (N) with the sample interval (s).
type PositionLoad = (f64, f64, Option<(f64, f64)>);

/// Load, approach speed and (dynamics) the previous sample's load at each position.
struct Loads {
    source: &'static str,
    /// (load N, approach m/s, previous load N and Δt s when transient).
    at: Vec<PositionLoad>,
}

fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

fn loads(
    input: &CylindricalInput,
    derived: &Derived,
    positions: &[f64],
) -> Result<Loads, ContactError> {
    if input.dynamics.revolutions > 0 {
        let t = tribodynamics(input, derived, Cancel::NONE)?;
        let s = &t.dynamics.series;
        let dt = s.dt_s;
        let n = s.t_s.len();
        let (Some(load_1), Some(speed_1)) =
            (s.roller_load_n.first(), s.squeeze_velocity_m_s.first())
        else {
            return Err(ContactError::Input(
                "the dynamics recorded no roller".to_string(),
            ));
        };
        // Roller 1's last steady cage cycle, every sample of the series.
        let per_cycle = if derived.cage_speed_rad_s > 0.0 && dt > 0.0 {
            ((std::f64::consts::TAU / derived.cage_speed_rad_s) / dt).ceil() as usize
        } else {
            n
        };
        let start = n.saturating_sub(per_cycle.max(1)).max(1);
        let angle = |k: usize| {
            (derived.cage_speed_rad_s * s.t_s[k])
                .to_degrees()
                .rem_euclid(360.0)
        };
        let mut at = Vec::new();
        for &p in positions {
            let want = p.rem_euclid(360.0);
            let k = (start..n)
                .min_by(|a, b| angle_gap(angle(*a), want).total_cmp(&angle_gap(angle(*b), want)))
                .filter(|k| *k < load_1.len() && *k < speed_1.len())
                .ok_or_else(|| {
                    ContactError::Input(
                        "the dynamics recorded no steady cage cycle: raise dynamics.revolutions above dynamics.settle_revolutions".to_string(),
                    )
                })?;
            at.push((load_1[k], speed_1[k], Some((load_1[k - 1], dt))));
        }
        Ok(Loads {
            source: "dynamics",
            at,
        })
    } else {
        let a = analyse(input, "contact", &Cancel::NONE)
            .map_err(|e| ContactError::Input(format!("contact: the quasi-statics failed: {e}")))?;
        let rollers = &a.statics.rollers;
        if rollers.is_empty() {
            return Err(ContactError::Input("no rollers".to_string()));
        }
        let mut at = Vec::new();
        for &p in positions {
            let want = p.rem_euclid(360.0);
            // Linear between the two rollers bracketing the azimuth (periodic).
            let mut az: Vec<(f64, f64)> = rollers
                .iter()
                .map(|r| (r.azimuth_rad.to_degrees().rem_euclid(360.0), r.inner_load_n))
                .collect();
            az.sort_by(|a, b| a.0.total_cmp(&b.0));
            let m = az.len();
            let mut load = az[0].1;
            for i in 0..m {
                let (a0, l0) = az[i];
                let (mut a1, l1) = az[(i + 1) % m];
                if a1 <= a0 {
                    a1 += 360.0;
                }
                let w = if want < a0 { want + 360.0 } else { want };
                if w >= a0 && w <= a1 {
                    let t = if a1 > a0 { (w - a0) / (a1 - a0) } else { 0.0 };
                    load = l0 + t * (l1 - l0);
                    break;
                }
            }
            at.push((load.max(0.0), 0.0, None));
        }
        Ok(Loads {
            source: "quasi-static",
            at,
        })
    }
}

fn elastic(m: &crate::physics::material::Material) -> Elastic {
    Elastic {
        youngs_modulus_pa: m.youngs_modulus_pa,
        poisson_ratio: m.poisson_ratio,
    }
}

/// Solve the contact at each position (progress on `progress(done, total)`).
pub fn contact_study(
    input: &CylindricalInput,
    options: &ContactOptions,
    mut progress: impl FnMut(usize, usize, f64),
) -> Result<ContactStudy, ContactError> {
    if options.model == ContactModel::FiniteLineEhl {
        return Err(ContactError::NotBuilt("--model finite-line-ehl"));
    }
    if matches!(options.inlet, InletChoice::Tipei | InletChoice::Both) {
        return Err(ContactError::NotBuilt("--inlet tipei"));
    }
    let positions: Vec<f64> = if options.positions_deg.is_empty() {
        input
            .contact
            .positions_rad
            .iter()
            .map(|p| p.to_degrees())
            .collect()
    } else {
        options.positions_deg.clone()
    };
    if positions.is_empty() {
        return Err(ContactError::Input(
            "contact: no positions (give --position DEG or the deck's contact.positions)"
                .to_string(),
        ));
    }
    if let Some(bad) = positions.iter().find(|p| !p.is_finite()) {
        return Err(ContactError::Input(format!(
            "--position {bad}: a cage angle must be a finite number of degrees"
        )));
    }
    let derived = derive(input);
    let loads = loads(input, &derived, &positions)?;
    let m = &input.materials;
    let e_star = reduced_modulus(elastic(&m.roller), elastic(&m.inner));
    let r = derived.inner_reduced_radius_m;
    let length = derived.effective_length_m;
    let u = derived.entrainment_speed_m_s;
    let du = input.contact.sliding_speed_m_s;
    let t_in = input.lubricant.inlet_temperature_k;
    let rheology = houpert(input);
    let l = &input.lubricant;
    let s = &input.surfaces;
    let mut rows = Vec::with_capacity(positions.len());
    let mut warm: Option<LineEhlSolution> = None;
    let total = positions.len();
    for (k, (&pos, &(load, approach, previous))) in positions.iter().zip(&loads.at).enumerate() {
        progress(k, total, pos);
        if !(load > 0.0) {
            return Err(ContactError::Input(format!(
                "contact at cage position {pos}°: the roller is unloaded (W_i = {load:.3} N); no EHL contact to solve"
            )));
        }
        // The domain is fixed in metres by the current load's Hertz half-width.
        let b = (8.0 * (load / length) * r / (std::f64::consts::PI * 2.0 * e_star)).sqrt();
        let problem = |w_n: f64| LineEhlProblem {
            radius_m: r,
            reduced_modulus_pa: e_star,
            entrainment_m_s: u,
            sliding_m_s: du,
            load_per_length_n_m: w_n / length,
            rheology,
            x_inlet_m: -FLOODED_INLET_HALF_WIDTHS * b,
            x_outlet_m: OUTLET_HALF_WIDTHS * b,
            nodes: CONTACT_NODES,
            squeeze: None,
            temperature_k: Some(vec![t_in; CONTACT_NODES]),
            max_iterations: 100,
            tolerance: 1e-8,
        };
        let fail = |source| ContactError::Solve {
            position_deg: pos,
            source,
        };
        let solution = match previous {
            Some((prev_load, dt)) if prev_load > 0.0 && dt > 0.0 => {
                let before = solve_line_ehl(&problem(prev_load), warm.as_ref()).map_err(fail)?;
                let mut p = problem(load);
                p.squeeze = Some(before.squeeze_history(dt));
                solve_line_ehl(&p, Some(&before)).map_err(fail)?
            }
            _ => solve_line_ehl(&problem(load), warm.as_ref()).map_err(fail)?,
        };
        let viscous = length
            * viscous_friction_isothermal(&solution, du, |p| {
                l.limiting_shear_pa + l.limiting_shear_slope * p
            });
        let gt = mixed_friction(&MixedContact {
            load_n: load,
            effective_length_m: length,
            reduced_radius_m: r,
            reduced_modulus_pa: e_star,
            film_m: solution.central_film_m,
            roughness: Roughness {
                composite_rms_m: s.composite_rms_m,
                roughness_parameter: s.roughness_parameter,
                asperity_slope: s.asperity_slope,
            },
            lubricant: rheology,
            temperature_k: t_in,
            limiting_shear_stress_pa: l.limiting_shear_pa,
            limiting_shear_slope: l.limiting_shear_slope,
            sliding_speed_m_s: du,
            rolling_speed_m_s: u,
            nodes: DEFAULT_NODES,
        })
        .map_err(|e| ContactError::Input(format!("contact at cage position {pos}°: {e}")))?;
        let friction = gt.boundary_n + viscous;
        let t_c = t_in - CELSIUS_ZERO_K;
        rows.push(ContactRow {
            position_deg: pos,
            inlet: "flooded",
            model: "line-ehl",
            load_n: load,
            approach_speed_m_s: approach,
            inlet_distance_m: FLOODED_INLET_HALF_WIDTHS * b,
            lambda: if s.composite_rms_m > 0.0 {
                solution.central_film_m / s.composite_rms_m
            } else {
                f64::INFINITY
            },
            asperity_load_n: gt.asperity_load_n,
            boundary_friction_n: gt.boundary_n,
            viscous_friction_n: viscous,
            friction_coefficient: friction / load,
            power_loss_w: friction * du.abs(),
            max_temperature_c: t_c,
            temperature_c: vec![t_c; solution.x_m.len()],
            solution,
        });
        warm = rows.last().map(|r| r.solution.clone());
    }
    progress(total, total, f64::NAN);
    Ok(ContactStudy {
        load_source: loads.source,
        entrainment_m_s: u,
        sliding_m_s: du,
        reduced_radius_m: r,
        effective_length_m: length,
        rows,
    })
}

/// JSON: `{ load_source, entrainment_m_s, sliding_m_s, contact: [...] }` (issue 26's
/// contract fields per entry, SI).
pub fn json(study: &ContactStudy) -> Value {
    let rows: Vec<Value> = study
        .rows
        .iter()
        .map(|r| {
            let s = &r.solution;
            json!({
                "position_deg": r.position_deg,
                "inlet": r.inlet,
                "model": r.model,
                "load_n": r.load_n,
                "approach_speed_m_s": r.approach_speed_m_s,
                "inlet_distance_m": r.inlet_distance_m,
                "central_film_m": s.central_film_m,
                "min_film_m": s.min_film_m,
                "lambda": finite_or_null(r.lambda),
                "max_pressure_pa": s.max_pressure_pa,
                "hertz_max_pressure_pa": s.hertz_max_pressure_pa,
                "hertz_half_width_m": s.hertz_half_width_m,
                "asperity_load_n": r.asperity_load_n,
                "boundary_friction_n": r.boundary_friction_n,
                "viscous_friction_n": r.viscous_friction_n,
                "friction_coefficient": r.friction_coefficient,
                "power_loss_w": r.power_loss_w,
                "max_temperature_c": r.max_temperature_c,
                "iterations": s.iterations,
                "load_balance_residual": s.load_balance_residual,
                "film_clamps": s.clamps,
                "profile": {
                    "x_m": s.x_m,
                    "pressure_pa": s.pressure_pa,
                    "hertz_pressure_pa": s.hertz_pressure_pa,
                    "film_m": s.film_m,
                    "temperature_c": r.temperature_c,
                },
            })
        })
        .collect();
    json!({
        "load_source": study.load_source,
        "thermal": "isothermal (inlet temperature)",
        "entrainment_m_s": study.entrainment_m_s,
        "sliding_m_s": study.sliding_m_s,
        "reduced_radius_m": study.reduced_radius_m,
        "effective_length_m": study.effective_length_m,
        "contact": rows,
    })
}

fn finite_or_null(v: f64) -> Value {
    if v.is_finite() {
        json!(v)
    } else {
        Value::Null
    }
}

const CSV_HEADER: &str = "position_deg,inlet,model,load_n,inlet_distance_m,central_film_m,min_film_m,lambda,max_pressure_pa,asperity_load_n,boundary_friction_n,viscous_friction_n,friction_coefficient,power_loss_w,max_temperature_c,iterations,load_balance_residual";

/// CSV: one line per row, the contract's scalar fields, SI.
pub fn csv(study: &ContactStudy) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push('\n');
    for r in &study.rows {
        let s = &r.solution;
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.position_deg,
            r.inlet,
            r.model,
            r.load_n,
            r.inlet_distance_m,
            s.central_film_m,
            s.min_film_m,
            r.lambda,
            s.max_pressure_pa,
            r.asperity_load_n,
            r.boundary_friction_n,
            r.viscous_friction_n,
            r.friction_coefficient,
            r.power_loss_w,
            r.max_temperature_c,
            s.iterations,
            s.load_balance_residual
        );
    }
    out
}

/// Text in the layout of seed 003's Table 3: one row per position and inlet.
pub fn text(study: &ContactStudy) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Contact (roller–inner race, line-ehl, isothermal at the inlet temperature; loads from the {}; ū = {:.3} m/s, Δu = {:.3} m/s)",
        study.load_source, study.entrainment_m_s, study.sliding_m_s
    );
    let _ = writeln!(
        out,
        "{:>8} {:>8} {:>9} {:>9} {:>9} {:>9} {:>6} {:>9} {:>9} {:>9} {:>9} {:>7} {:>8} {:>7} {:>5}",
        "pos deg",
        "inlet",
        "load N",
        "inlet µm",
        "h_c µm",
        "h_min µm",
        "λ",
        "p_max MPa",
        "W_a N",
        "f_b N",
        "f_v N",
        "µ",
        "power W",
        "T_max C",
        "iter"
    );
    for r in &study.rows {
        let s = &r.solution;
        let _ = writeln!(
            out,
            "{:>8.1} {:>8} {:>9.1} {:>9.1} {:>9.4} {:>9.4} {:>6.2} {:>9.1} {:>9.3} {:>9.3} {:>9.3} {:>7.4} {:>8.2} {:>7.1} {:>5}",
            r.position_deg,
            r.inlet,
            r.load_n,
            r.inlet_distance_m * 1e6,
            s.central_film_m * 1e6,
            s.min_film_m * 1e6,
            r.lambda,
            s.max_pressure_pa * 1e-6,
            r.asperity_load_n,
            r.boundary_friction_n,
            r.viscous_friction_n,
            r.friction_coefficient,
            r.power_loss_w,
            r.max_temperature_c,
            s.iterations
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn options(positions: &[f64]) -> ContactOptions {
        ContactOptions {
            positions_deg: positions.to_vec(),
            inlet: InletChoice::Flooded,
            model: ContactModel::LineEhl,
        }
    }

    /// Tipei and finite-line are refused as not built, never answered with a number.
    #[test]
    fn unbuilt_models_are_refused() {
        let input = CylindricalInput::truck();
        for (inlet, model) in [
            (InletChoice::Tipei, ContactModel::LineEhl),
            (InletChoice::Both, ContactModel::LineEhl),
            (InletChoice::Flooded, ContactModel::FiniteLineEhl),
        ] {
            let o = ContactOptions {
                inlet,
                model,
                ..options(&[0.0])
            };
            let e = contact_study(&input, &o, |_, _, _| {}).unwrap_err();
            assert!(matches!(e, ContactError::NotBuilt(_)), "{e}");
            assert!(e.to_string().contains("not built yet"));
        }
    }

    /// The truck bearing from its quasi-statics (dynamics off): the roller at the load
    /// line carries the largest load; its contact is an EHL film with the load balanced,
    /// a pressure peak near Hertz (p_max/p_H within 0.8–1.3: a piezoviscous contact at
    /// ≈ 1 GPa), a film between 0.01 and 10 µm, and the seed's friction band's order
    /// (µ below 0.1); the JSON carries the contract's fields and a profile per node.
    #[test]
    fn truck_contact_from_the_quasi_statics() {
        let mut input = CylindricalInput::truck();
        input.dynamics.revolutions = 0;
        let s = contact_study(&input, &options(&[0.0]), |_, _, _| {}).unwrap();
        assert_eq!(s.load_source, "quasi-static");
        let r = &s.rows[0];
        assert!(r.load_n > 0.0);
        let sol = &r.solution;
        assert!(sol.load_balance_residual.abs() <= 0.005);
        let ratio = sol.max_pressure_pa / sol.hertz_max_pressure_pa;
        assert!((0.8..1.3).contains(&ratio), "p_max/p_H {ratio}");
        assert!(sol.central_film_m > 1e-8 && sol.central_film_m < 1e-5);
        assert!(r.friction_coefficient > 0.0 && r.friction_coefficient < 0.1);
        assert!(
            (r.power_loss_w - (r.boundary_friction_n + r.viscous_friction_n) * s.sliding_m_s.abs())
                .abs()
                < 1e-9 * r.power_loss_w.max(1.0)
        );
        let v = json(&s);
        for key in [
            "position_deg",
            "inlet",
            "model",
            "load_n",
            "inlet_distance_m",
            "central_film_m",
            "min_film_m",
            "lambda",
            "max_pressure_pa",
            "asperity_load_n",
            "boundary_friction_n",
            "viscous_friction_n",
            "friction_coefficient",
            "power_loss_w",
            "max_temperature_c",
            "iterations",
            "load_balance_residual",
        ] {
            assert!(v["contact"][0].get(key).is_some(), "{key}");
        }
        for key in [
            "x_m",
            "pressure_pa",
            "hertz_pressure_pa",
            "film_m",
            "temperature_c",
        ] {
            assert_eq!(
                v["contact"][0]["profile"][key].as_array().map(|a| a.len()),
                Some(CONTACT_NODES),
                "{key}"
            );
        }
    }
}
