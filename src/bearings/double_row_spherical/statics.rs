//! The double-row assembly (seed 002 §2, eqs 1–2 reconstructed; issue 27 Model 1).
//!
//! Eq. 1 (lost in the seed) is read as the spherical roller's lamina approach: the distance
//! between a lamina's point and the raceway's centre of curvature minus the raceway radius,
//! through the rigid displacements of rings and roller (the frame transformations), exact
//! and free of cancellation ([`crate::bearings::spherical_roller::geometry`]). Eq. 2 is the
//! inner ring's balance: Σ over both rows and all rollers of the inner contact loads and
//! the guide ring reactions equals (F_r, F_a), solved by Newton in (Δz, Δx) with every
//! roller in its own equilibrium (axial, radial, pitch) — the spherical roller's solver
//! with a two-row [`Layout`](crate::bearings::spherical_roller::load_distribution::Layout):
//! row 2 is row 1 mirrored in the radial plane, both rows share the inner ring and the outer
//! sphere (centred on the axis at the bearing's centre: the deck check d_m = 2(R_CE −
//! D_W/2)·cos α⁰ puts each row's outer crown centre there), and the guide ring on the
//! inner ring's land between the rows stops each roller's inner end (a unilateral Hertz
//! contact). The guide ring floats axially: its offset on the inner ring balances the two
//! rows' end forces, so it passes no axial load to the inner ring
//! (`spherical_roller::load_distribution::float`).
//! Centrifugal force and gyroscopic moment come from the cage speed: measured (the seed's
//! input) or the §7 kinematics iterated with the loads (one cage speed for both rows, the
//! mean over the rollers loaded at both raceways).
//!
//! After the solve each row is a single-row analysis of its own (stresses, film, life as the
//! spherical roller computes them); the bearing's L-10 combines the rows' by
//! L = (Σ L_r^(−9/8))^(−8/9) (Lundberg–Palmgren's Weibull product for line contact).

use std::sync::atomic::AtomicBool;
use std::time::Instant;

use serde::Serialize;

use super::input::{CageSpeedSource, DoubleRowInput};
use crate::bearings::spherical_roller::contacts::RollerContacts;
use crate::bearings::spherical_roller::load_distribution::{
    DynamicSpeeds, LoadDistribution, WarmStart,
};
use crate::bearings::spherical_roller::pipeline::{self, Analysis, Request};
use crate::bearings::spherical_roller::{stages, Bearing};
use crate::bearings::SolveError;
use crate::physics::kinematics::InternalSpeeds;

/// Forces on the guide ring from each row's roller ends, N, and its axial float.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GuideRingForces {
    /// Σ over row 1's rollers of the end force magnitudes.
    pub force_row1_n: f64,
    pub force_row2_n: f64,
    /// Net axial force of both rows on the guide ring, N (bearing frame, + toward row 1):
    /// zero to the solver's tolerance, the floating guide ring's balance.
    pub net_axial_n: f64,
    /// The guide ring's axial offset on the inner ring, m (bearing frame, + toward row 1,
    /// 0 = centred between the rows): where its balance puts it, or, touching neither row,
    /// the centred place clamped to its free travel
    /// (`spherical_roller::load_distribution::float`).
    pub axial_offset_m: f64,
}

/// The solved double-row bearing.
#[derive(Debug, Clone)]
pub struct DoubleRowAnalysis {
    pub input: DoubleRowInput,
    pub name: String,
    /// The single-row description each row was solved with (row 1's frame).
    pub row_bearing: Bearing,
    /// Both rows' load distribution: rollers of row 1, then row 2 (each in its own frame).
    pub combined: LoadDistribution,
    /// Each row as a single-row analysis: its rollers, stresses, film, life, speeds.
    pub rows: Vec<Analysis>,
    /// The cage speed and roller spin the centrifugal force and gyroscopic moment used.
    pub dynamic: DynamicSpeeds,
    pub guide: GuideRingForces,
    /// Ring stiffness ∂F/∂u in (axial, radial) × (axial, radial), N/m.
    pub stiffness_n_m: [[f64; 2]; 2],
    /// The 5×5 on the shared type (issue 29; its x–z block is `stiffness_n_m`), or why
    /// there is none.
    pub stiffness: Result<crate::bearings::stiffness::StiffnessMatrix, String>,
    /// Bearing L-10 from the rows' (Mrev, hours); None when no row is loaded.
    pub l10_mrev: Option<f64>,
    pub l10_h: Option<f64>,
    pub wall_time_s: f64,
}

impl DoubleRowAnalysis {
    /// Radial ring deflection Δx, m.
    pub fn radial_deflection_m(&self) -> f64 {
        self.combined.radial_deflection_m
    }
    /// Axial ring deflection Δz, m.
    pub fn axial_deflection_m(&self) -> f64 {
        self.combined.axial_deflection_m
    }
    /// Largest roller contact load (inner or outer) of either row, N.
    pub fn max_roller_load_n(&self) -> f64 {
        self.combined
            .rollers
            .iter()
            .map(|r| r.inner.normal_load_n.max(r.outer.normal_load_n))
            .fold(0.0, f64::max)
    }
    /// Largest contact stress of either row, Pa.
    pub fn max_stress_pa(&self) -> f64 {
        self.rows
            .iter()
            .filter_map(|a| a.stresses.as_ref())
            .flat_map(|s| s.rollers.iter())
            .flat_map(|r| r.iter().map(|c| c.max_stress_pa))
            .fold(0.0, f64::max)
    }
}

/// The combined L-10 of independent rows (Weibull product, line contact e = 9/8).
pub fn combine_l10(rows: &[Option<f64>]) -> Option<f64> {
    let s: f64 = rows
        .iter()
        .flatten()
        .filter(|l| l.is_finite() && **l > 0.0)
        .map(|l| l.powf(-9.0 / 8.0))
        .sum();
    (s > 0.0).then(|| s.powf(-8.0 / 9.0))
}

/// Rollers `row` (0-based) of a multi-row load distribution as a single-row one.
pub(super) fn split(ld: &LoadDistribution, row: usize, z: usize) -> LoadDistribution {
    let range = row * z..(row + 1) * z;
    let mut out = ld.clone();
    out.rollers = ld.rollers[range.clone()].to_vec();
    out.mirror = ld.mirror[range]
        .iter()
        .map(|m| m.map(|i| i - row * z))
        .collect();
    out.trace = Vec::new();
    out
}

/// A solved bearing's state as the start of a neighbouring solve ([`analyse_from`]): the
/// dynamic speeds its loads were solved with and its unknowns (ring deflection, the guide
/// ring's offset, each roller's axial, radial and pitch displacement, and their response
/// to the inertial loads).
#[derive(Debug, Clone, PartialEq)]
pub struct StaticsStart {
    pub speeds: DynamicSpeeds,
    pub warm: WarmStart,
}

impl DoubleRowAnalysis {
    /// This solution as the start of a neighbour's solve.
    pub fn start(&self) -> StaticsStart {
        StaticsStart {
            speeds: self.dynamic,
            warm: self.combined.warm.clone(),
        }
    }
}

/// Solve the double-row bearing (a cold start: the statics' coarse-roller pre-solve).
pub fn analyse(
    input: &DoubleRowInput,
    name: &str,
    cancel: Option<&AtomicBool>,
) -> Result<DoubleRowAnalysis, SolveError> {
    analyse_from(input, name, None, cancel)
}

/// Solve the double-row bearing from `from`, a neighbouring solution (a sweep's previous
/// point, a grid neighbour): its unknowns and speeds start the fine solve instead of the
/// coarse pre-solve. Only the path changes: the fine solve and the dynamic-load iteration
/// still decide convergence to the deck's tolerances, so the answer is the cold one to the
/// ring tolerance (tested), with fewer lamina evaluations. A start with another roller count
/// is ignored (cold start).
pub fn analyse_from(
    input: &DoubleRowInput,
    name: &str,
    from: Option<&StaticsStart>,
    cancel: Option<&AtomicBool>,
) -> Result<DoubleRowAnalysis, SolveError> {
    let start = Instant::now();
    let b = input.row_bearing(name);
    let z = b.geometry.roller_count;
    let rows = input.geometry.rows.clamp(1, 2);
    let layout = input.layout();
    let dynamic_speeds = match input.cage.speed {
        CageSpeedSource::Measured => {
            let est = DynamicSpeeds::app_c_estimate(&b);
            // The roller spin relative to a cage at the measured speed, rolling without
            // slip on the inner raceway at the free contact angle: App. C's spin scales
            // with the inner ring's speed relative to the cage.
            let w1 = b.operating.inner_speed_rad_s;
            let spin = if w1 != est.cage_rad_s {
                est.roller_spin_rad_s * (w1 - input.cage.measured_speed_rad_s)
                    / (w1 - est.cage_rad_s)
            } else {
                est.roller_spin_rad_s
            };
            Some(DynamicSpeeds {
                cage_rad_s: input.cage.measured_speed_rad_s,
                roller_spin_rad_s: spin,
            })
        }
        CageSpeedSource::Computed => None,
    };
    let request = Request {
        contact: true,
        heat: false,
        layout,
        dynamic_speeds,
        warm_start: from.map(|f| (f.speeds, f.warm.clone())),
        ..Request::default()
    };
    let whole = pipeline::run(&b, &request, cancel)?;
    let combined = whole.load;
    let stiffness_5x5 = whole.stiffness;
    let dynamic = combined.speeds;
    // §7 speeds of the whole (one cage speed for both rows), split per row.
    let speeds: InternalSpeeds = stages::internal_speeds(&b, &combined, &whole.contacts);
    let iterations = whole.speeds.iterations;
    let mut row_analyses = Vec::with_capacity(rows);
    for row in 0..rows {
        let ld = split(&combined, row, z);
        let cts: Vec<RollerContacts> = whole.contacts[row * z..(row + 1) * z].to_vec();
        let sp = InternalSpeeds {
            cage_speed_rad_s: speeds.cage_speed_rad_s,
            controlling_rollers: speeds.controlling_rollers,
            roller_spin_rad_s: speeds
                .roller_spin_rad_s
                .get(row * z..(row + 1) * z)
                .map(<[_]>::to_vec)
                .unwrap_or_default(),
        };
        let st = stages::stresses(&b, &ld, &cts);
        let fi = stages::films(&b, &cts, &sp);
        let li = stages::life(&b, &ld, &fi);
        row_analyses.push(Analysis {
            input: b.clone(),
            load: ld,
            speeds: stages::speeds_report(&b, &sp, iterations),
            contacts: cts,
            stresses: Some(st),
            films: Some(fi),
            life: Some(li),
            friction: None,
            thermal: None,
            // A row has no stiffness of its own: the bearing's is the double row's.
            stiffness: Err("a row of a double-row bearing: its stiffness is the bearing's".into()),
            trace: Vec::new(),
            trace_roller: None,
            trace_outer: 0,
        });
    }
    let force_row = |row: usize| -> f64 {
        combined
            .rollers
            .iter()
            .filter(|r| r.row == row)
            .map(|r| r.guide_force_n)
            .sum()
    };
    // Each row's roller ends push the guide ring along their −a, whose axial component is
    // −cos α⁰ in the row's frame: toward the bearing's centre plane, i.e. −x for row 1 and
    // +x for row 2 in the bearing's frame.
    let ca = input.geometry.contact_angle_rad.cos();
    let (f1, f2) = (force_row(1), force_row(2));
    let guide = GuideRingForces {
        force_row1_n: f1,
        force_row2_n: f2,
        net_axial_n: (f2 - f1) * ca,
        axial_offset_m: combined.guide_offset_m,
    };
    let stiffness = combined
        .warm
        .inertial
        .as_ref()
        .map(|s| s.ring_stiffness_n_m())
        .unwrap_or([[0.0; 2]; 2]);
    let l10_mrev = combine_l10(
        &row_analyses
            .iter()
            .map(|a| a.life.as_ref().and_then(|l| l.result.l10_bearing_mrev))
            .collect::<Vec<_>>(),
    );
    let rev_per_h = input.operating.inner_speed_rad_s.abs() / (2.0 * std::f64::consts::PI) * 3600.0;
    let l10_h = l10_mrev
        .filter(|_| rev_per_h > 0.0)
        .map(|l| l * 1e6 / rev_per_h);
    Ok(DoubleRowAnalysis {
        input: input.clone(),
        name: name.to_string(),
        row_bearing: b,
        combined,
        rows: row_analyses,
        dynamic,
        guide,
        stiffness_n_m: stiffness,
        stiffness: stiffness_5x5,
        l10_mrev,
        l10_h,
        wall_time_s: start.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
#[path = "statics_tests.rs"]
mod tests;
