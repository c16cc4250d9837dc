//! Lamina load distribution with centrifugal force and gyroscopic moment
//! (seed 000 §3, eq. 3.1–3.13, App. C–D).
//!
//! The seed adjusts one unknown at a time in nested loops (Fig. 4). We solve the same
//! equilibria by Newton's method on the system's potential energy:
//!
//! Π(u, q₁…q_Z) = Σ_j [Σ_l U(δ_jl) − f_j·q_j + ½ q_jᵀK_cage q_j] − F·u
//!
//! with u = (axial, radial) ring deflection, q_j = (axial, radial, pitch) of roller j, U the
//! lamina strain energy (∂U/∂δ = Q, eq. 3.3), f_j the inertial loads (centrifugal force
//! along r, eq. 3.10; gyroscopic moment about the pitching axis, eq. 3.11). ∂Π/∂q_j = 0 is
//! each roller's axial, radial and pitching equilibrium (eq. 3.9–3.11); ∂Π/∂u = 0 is the
//! bearing's (eq. 3.12–3.13). For a given u every roller is an independent 3-unknown Newton
//! problem (warm-started); the ring deflection is updated by Newton with the exact
//! condensed stiffness (Schur complement). Each step is safeguarded by a trust radius and
//! an energy line search, so out-of-contact rollers, clearance and zero load neither hang
//! nor produce NaN.
//!
//! "Controlled by the cage" (§7.1): a roller touching one raceway or none has no contact
//! stiffness along its own axis and in pitch (it can roll around a raceway's crown). The
//! cage pocket holds it there, modelled as a soft spring on the roller's axial position and
//! pitch (stiffness = `cage_stiffness_ratio` × the roller's contact stiffness at an approach
//! of 10⁻⁴·D). Its reaction is reported per roller (`cage_force_n`, `cage_moment_nm`); for
//! rollers loaded at both raceways it is a negligible fraction of the contact loads (tested).
//!
//! Layout: this file holds the results and [`solve`]; `problem` the set-up and one roller's
//! energy, gradient and Hessian (the hot loop) and the results' assembly; `driver` the roller
//! and ring Newton iterations and the starts; `diagnostics` the typed errors of a solve that
//! left the model. The Newton machinery itself (step solvers, trust radius, line search,
//! termination, the driver of the roller iteration) is shared: [`crate::numerics::newton`].

mod diagnostics;
mod driver;
mod float;
mod problem;
pub mod stiffness;
#[cfg(test)]
mod tests;

use std::sync::atomic::AtomicBool;
use std::time::Instant;

use nalgebra::Matrix2;
use serde::Serialize;

use crate::bearings::spherical_roller::roller::RollerMass;
use crate::bearings::spherical_roller::Bearing;
use crate::bearings::SolveError;
use crate::numerics::newton::Termination;

use diagnostics::{tipped_over, unrestrained};
use problem::{assemble, Problem};

/// Speeds that set the dynamic loads: cage orbit and roller spin relative to the cage (rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DynamicSpeeds {
    /// Ω_cg, cage angular velocity about the bearing axis, rad/s.
    pub cage_rad_s: f64,
    /// ω_s, roller spin relative to the cage about its axis a = (cos β, −sin β), rad/s.
    pub roller_spin_rad_s: f64,
}

impl DynamicSpeeds {
    /// App. C's first estimate (eq. C.1–C.2): no slip, contact at the design angle.
    pub fn app_c_estimate(b: &Bearing) -> Self {
        use crate::physics::kinematics::{cage_speed_estimate, roller_spin_estimate};
        let theta = b.geometry.theta();
        let (w1, w2) = (b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s);
        DynamicSpeeds {
            cage_rad_s: cage_speed_estimate(w1, w2, theta),
            roller_spin_rad_s: roller_spin_estimate(
                w1,
                w2,
                theta,
                b.geometry.roller_diameter_m,
                b.geometry.pitch_diameter_m,
            ),
        }
    }
}

/// The moment about the pitching axis e_t (N·m) that the raceways must apply to sustain
/// steady precession: M = Ω_cg e_x × H, H = I_p(ω·a)a + I_t(ω − (ω·a)a), ω = Ω_cg e_x + ω_s a.
/// Its magnitude is App. D's eq. D.1 with the polar moment on the spin term.
pub fn gyroscopic_moment(mass: &RollerMass, speeds: &DynamicSpeeds, beta: f64) -> f64 {
    let a = [beta.cos(), -beta.sin()];
    let wc = speeds.cage_rad_s;
    let w = [
        wc + speeds.roller_spin_rad_s * a[0],
        speeds.roller_spin_rad_s * a[1],
    ];
    let wa = w[0] * a[0] + w[1] * a[1];
    let ip = mass.polar_inertia_kg_m2;
    let it = mass.transverse_inertia_kg_m2;
    // H_r; (e_x × H)_t = H_r.
    let h_r = ip * wa * a[1] + it * (w[1] - wa * a[1]);
    wc * h_r
}

/// The guide ring of a double-row bearing as one unilateral contact per roller: the roller's
/// inner end (a sphere of radius r_e centred on the roller axis) against a flat face of the
/// guide ring normal to the row's nominal roller axis. The guide ring sits on the inner ring's
/// land between the rows: radially it moves with the inner ring, axially it floats (a body of
/// its own, free to slide on the land), so it carries no axial load into the inner ring; its
/// axial offset on the ring is the unknown of [`LoadDistribution::guide_offset_m`]. Hertz
/// sphere on plane: F = K·δ^(3/2), K = (4/3)·E*·√r_e (Johnson, Contact Mechanics,
/// eq. 4.22–4.23), δ = −gap, zero force at a positive gap.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GuideContact {
    /// Nominal gap along the roller axis between the roller end and the guide ring face
    /// (rings concentric, roller at its nominal position), m.
    pub gap_m: f64,
    /// K of F = K·δ^(3/2), N/m^(3/2).
    pub hertz_constant: f64,
    /// Distance from the roller centre to the centre of its end sphere along the roller
    /// axis, L/2 − r_e, m (negative when the end radius exceeds half the length).
    pub end_centre_offset_m: f64,
}

/// How many rows share the inner ring and the outer sphere, and the guide ring between them.
/// Row 1 is the single-row bearing's geometry; row 2 its mirror image in the bearing's radial
/// plane (contact angle −β), solved in its own mirrored frame: there the ring deflection reads
/// (−u_axial, u_radial) and its axial ring forces change sign. One row without a guide ring
/// is the single-row bearing exactly (the same arithmetic; tested).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Layout {
    /// Number of rows, 1 or 2.
    pub rows: usize,
    /// The guide ring, if any.
    pub guide: Option<GuideContact>,
}

impl Default for Layout {
    fn default() -> Self {
        Layout {
            rows: 1,
            guide: None,
        }
    }
}

/// Options of one load-distribution solve.
#[derive(Debug, Default, Clone)]
pub struct SolveOptions {
    /// Rows and guide ring (default: the single-row bearing).
    pub layout: Layout,
    /// Warm start: ring deflection (axial, radial) and each unique roller's (axial, radial, pitch).
    pub warm_start: Option<WarmStart>,
    /// Record the Newton iterations of this roller (0-based roller index) for the stepper.
    pub trace_roller: Option<usize>,
    /// Relative force tolerance of this solve instead of the deck's `solver.force_tolerance`
    /// (an intermediate solve of an outer iteration that will be tightened later).
    pub force_tolerance: Option<f64>,
}

/// A previous solution's unknowns.
#[derive(Debug, Clone, PartialEq)]
pub struct WarmStart {
    pub ring: [f64; 2],
    pub rollers: Vec<[f64; 3]>,
    /// The floating guide ring's axial offset, m (0 without a guide ring).
    pub guide_offset_m: f64,
    /// How that solution responds to the inertial loads (absent for hand-made warm starts).
    pub inertial: Option<InertialSensitivity>,
}

/// First-order response of a solved state to the inertial loads: with the centrifugal force
/// changed by ΔCF and the gyroscopic moment by ΔM (new dynamic speeds), the linearised
/// equilibria give the ring deflection change Δu = −K⁻¹·Σ_j m_j·R_j·c and each roller's
/// Δq_j = P_j·c + S_j·Δu, with c = (ΔCF, −ΔM), P_j = H_qq⁻¹[e_r, e_α], R_j = H_uq·P_j,
/// S_j = dq/du and K the condensed ring stiffness. Starting the next dynamic-load
/// iteration there leaves a residual of second order in the speed change.
#[derive(Debug, Clone, PartialEq)]
pub struct InertialSensitivity {
    /// Centrifugal force and gyroscopic moment the solution was solved with, N and N·m.
    pub cf: f64,
    pub gm: f64,
    k: Matrix2<f64>,
    roller: Vec<nalgebra::Matrix3x2<f64>>,
    ring: Vec<Matrix2<f64>>,
    sens: Vec<nalgebra::Matrix3x2<f64>>,
}

impl InertialSensitivity {
    /// The condensed ring stiffness at the solution, N/m, in (axial, radial): the ring
    /// Newton's exact Jacobian ∂(Σ contact forces on the inner ring)/∂u with every roller
    /// kept in equilibrium.
    pub fn ring_stiffness_n_m(&self) -> [[f64; 2]; 2] {
        [
            [self.k[(0, 0)], self.k[(0, 1)]],
            [self.k[(1, 0)], self.k[(1, 1)]],
        ]
    }
}

/// Result for one lamina (seed 000 eq. 3.3–3.5).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LaminaResult {
    pub offset_m: f64,
    pub width_m: f64,
    pub inner_load_n: f64,
    pub outer_load_n: f64,
    /// Approach (positive = interference, negative = gap), m.
    pub inner_approach_m: f64,
    pub outer_approach_m: f64,
    /// Contact point (axial x, radius from bearing axis) at the inner raceway, m.
    pub inner_point_m: [f64; 2],
    /// Contact point (axial x, radius from bearing axis) at the outer raceway, m.
    pub outer_point_m: [f64; 2],
    /// Unit normals (x, r) of the inner and outer contact forces' lines; their angles are
    /// [`LaminaResult::inner_angle_deg`] and [`LaminaResult::outer_angle_deg`].
    #[serde(skip)]
    pub inner_normal: [f64; 2],
    #[serde(skip)]
    pub outer_normal: [f64; 2],
}

impl LaminaResult {
    /// Contact angle of the inner contact's normal from the radial plane, deg.
    pub fn inner_angle_deg(&self) -> f64 {
        angle_from_radial_plane_deg(self.inner_normal)
    }

    /// Contact angle of the outer contact's normal from the radial plane, deg.
    pub fn outer_angle_deg(&self) -> f64 {
        angle_from_radial_plane_deg(self.outer_normal)
    }
}

/// Angle of unit normal n = (n_x, n_r) = (sin θ, cos θ) from the radial plane, deg. Computed on
/// demand (report, most loaded lamina), not in every assembly: two angles per lamina in each
/// of the dynamic-load iteration's assemblies were a fifth of an assembly's cost, for values
/// only the report prints.
fn angle_from_radial_plane_deg(n: [f64; 2]) -> f64 {
    n[0].atan2(n[1]).to_degrees()
}

/// One raceway contact of a roller (seed 000 §4.5).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RacewayContact {
    /// Σ lamina loads projected on the most loaded lamina's normal, N.
    pub normal_load_n: f64,
    /// Contact angle of the most loaded lamina (highest line load), deg (design angle when
    /// unloaded).
    pub contact_angle_deg: f64,
    /// Number of loaded laminae ñ.
    pub loaded_laminae: usize,
    /// Index of the most loaded lamina, the highest line load Q/w (absent when unloaded).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_lamina: Option<usize>,
}

/// One roller's equilibrium.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RollerResult {
    /// Roller number j (1-based, eq. 3.1).
    pub index: usize,
    pub azimuth_deg: f64,
    pub axial_displacement_m: f64,
    pub radial_displacement_m: f64,
    pub tilt_rad: f64,
    pub centrifugal_force_n: f64,
    /// Moment about the pitching axis the raceways supply to sustain precession, N·m.
    pub gyroscopic_moment_nm: f64,
    /// Cage pocket reaction along the roller axis, N, and in pitch, N·m.
    pub cage_force_n: f64,
    pub cage_moment_nm: f64,
    /// Row (1 or 2) of a multi-row layout; 1 for the single-row bearing (not in its JSON).
    #[serde(skip)]
    pub row: usize,
    /// Guide ring force on the roller along its axis, N (≥ 0; zero without a guide ring;
    /// not in the single-row bearing's JSON).
    #[serde(skip)]
    pub guide_force_n: f64,
    pub inner: RacewayContact,
    pub outer: RacewayContact,
    pub laminae: Vec<LaminaResult>,
}

/// Largest equilibrium residuals at the solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct Residuals {
    pub bearing_radial_n: f64,
    pub bearing_axial_n: f64,
    pub roller_force_n: f64,
    pub roller_moment_nm: f64,
}

/// Work counters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct SolveStats {
    /// Ring (outer Newton) iterations.
    pub iterations: usize,
    /// Roller Newton iterations, all rollers and ring iterations together.
    pub roller_iterations: usize,
    /// Lamina contact evaluations.
    pub lamina_evaluations: usize,
    pub wall_time_s: f64,
}

/// One recorded roller Newton iteration (seed Fig. 4's inner loop, made visible).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TraceStep {
    /// The outer (§7 speeds ↔ §3 loads) iteration of the pipeline this solve belongs to
    /// (1-based; 1 when the loads are not iterated). Set by the pipeline.
    pub outer_iteration: usize,
    /// Ring iteration this belongs to and the roller iteration within it.
    pub ring_iteration: usize,
    pub roller_iteration: usize,
    /// Ring deflection (axial, radial), m.
    pub ring: [f64; 2],
    /// Roller (axial, radial, pitch) in m, m, rad.
    pub roller: [f64; 3],
    /// Residual (axial force N, radial force N, moment N·m).
    pub residual: [f64; 3],
    pub inner_approach_m: Vec<f64>,
    pub outer_approach_m: Vec<f64>,
    pub inner_load_n: Vec<f64>,
    pub outer_load_n: Vec<f64>,
}

/// The solved load distribution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadDistribution {
    pub converged: bool,
    pub axial_deflection_m: f64,
    pub radial_deflection_m: f64,
    pub speeds: DynamicSpeeds,
    /// The floating guide ring's axial offset s on the inner ring, m, bearing frame (+ toward
    /// row 1; 0 = centred between the rows; 0 without a guide ring). Not in the single-row
    /// bearing's JSON.
    #[serde(skip)]
    pub guide_offset_m: f64,
    pub roller_mass: RollerMass,
    pub rollers: Vec<RollerResult>,
    /// `mirror[j] = Some(i)` (i < j) when roller j's state is identical to roller i's: the
    /// load lies in the plane through roller 1, so rollers j and Z−j mirror each other.
    /// Later per-roller stages copy such rollers instead of recomputing them.
    #[serde(skip)]
    pub mirror: Vec<Option<usize>>,
    pub residuals: Residuals,
    pub stats: SolveStats,
    #[serde(skip)]
    pub warm: WarmStart,
    #[serde(skip)]
    pub trace: Vec<TraceStep>,
}

/// Solve the load distribution of `b` with dynamic loads from `speeds`.
pub fn solve(
    b: &Bearing,
    speeds: &DynamicSpeeds,
    options: &SolveOptions,
    cancel: Option<&AtomicBool>,
) -> Result<LoadDistribution, SolveError> {
    let start = Instant::now();
    let p = Problem::with_layout(
        b,
        speeds,
        options.force_tolerance.unwrap_or(b.solver.force_tolerance),
        options.layout,
    );
    let (mut u, mut qs) = p.start(b, options);
    let mut trace = options.trace_roller.map(|r| (p.unique_of(r), Vec::new()));
    let mut stats = SolveStats::default();
    let state = if p.guide.is_some() {
        // The floating guide ring: its offset a third unknown of the ring Newton (starting
        // from the warm start's).
        p.guide_offset.set(
            options
                .warm_start
                .as_ref()
                .map_or(0.0, |w| w.guide_offset_m),
        );
        p.float_guide(b, &mut u, &mut qs, &mut stats, &mut trace, cancel)?
    } else {
        p.ring_equilibrium(b, &mut u, &mut qs, &mut stats, &mut trace, cancel)?
    };
    // A converged state with the rings more than D/2 apart is outside the model (the rings
    // have separated): report it rather than print nonsense geometry.
    if let Some(e) = unrestrained(b, u) {
        return Err(e);
    }
    // Likewise a roller that has pitched over in its pocket.
    if let Some(e) = tipped_over(b, &qs) {
        return Err(e);
    }
    stats.lamina_evaluations = p.evals.get();
    let g = state.g;
    let residuals = Residuals {
        bearing_axial_n: g[0].abs(),
        bearing_radial_n: g[1].abs(),
        roller_force_n: 0.0,
        roller_moment_nm: 0.0,
    };
    let mut out = assemble(b, &p, u, &qs, residuals, speeds);
    out.warm.inertial = Some(InertialSensitivity {
        cf: p.cf,
        gm: p.gm,
        k: state.k,
        roller: state.inertial_roller,
        ring: state.inertial_ring,
        sens: state.sens,
    });
    out.stats = stats;
    out.stats.wall_time_s = start.elapsed().as_secs_f64();
    out.trace = trace.map(|t| t.1).unwrap_or_default();
    Ok(out)
}

/// Re-solve every roller of a solved load distribution `ld` with an extra generalised load
/// on it, the ring deflection and the floating guide ring's offset held at `ld`'s: the
/// roller balance of the double row's self-guided skew (issue 27; `double_row_spherical`'s
/// `losses::kellstrom`). `extra[r]` is roller r's load (all rows, `ld.rollers`' order) in its
/// row's frame: (axial force N, radial force N, pitch moment N·m), the pitch moment positive
/// where it turns the roller axis as a positive `tilt_rad` does. It is held constant during
/// the roller's Newton (energy −e·q), so the caller iterates it with the state it depends on.
/// A roller whose load is exactly zero keeps `ld`'s state bit for bit (no solve). Mirrored
/// rollers (`ld.mirror`) take their representative's state: their loads must mirror too,
/// and only the representative's is read. The single-row bearing never calls this.
///
/// # Errors
/// [`SolveError::RollerNotConverged`] naming the roller (1-based over all rows), its
/// residual and the tolerance; [`SolveError::NonFinite`]; [`SolveError::Stage`] when
/// `extra` does not hold one load per roller of `ld`.
pub fn resolve_rollers_with_loads(
    b: &Bearing,
    layout: Layout,
    ld: &LoadDistribution,
    extra: &[[f64; 3]],
) -> Result<LoadDistribution, SolveError> {
    let p = Problem::with_layout(b, &ld.speeds, b.solver.force_tolerance, layout);
    p.guide_offset.set(ld.guide_offset_m);
    let z = b.geometry.roller_count;
    let u = [ld.axial_deflection_m, ld.radial_deflection_m];
    let mut qs: Vec<nalgebra::Vector3<f64>> = ld
        .warm
        .rollers
        .iter()
        .map(|q| nalgebra::Vector3::new(q[0], q[1], q[2]))
        .collect();
    if qs.len() != p.unique.len() || extra.len() != ld.rollers.len() {
        return Err(SolveError::Stage {
            stage: "roller re-solve with tractions",
            message: format!(
                "{} loads given for {} rollers ({} unique states for {} in the problem)",
                extra.len(),
                ld.rollers.len(),
                qs.len(),
                p.unique.len()
            ),
        });
    }
    let (_, per_row) = p.per_row;
    let mut iterations = 0;
    let mut worst_force = ld.residuals.roller_force_n;
    let mut worst_moment = ld.residuals.roller_moment_nm;
    for (ku, q) in qs.iter_mut().enumerate() {
        // The representative of unique roller ku: row ku / n, roller j = ku % n (unique_index
        // maps j ≤ Z/2 to itself).
        let r = (ku / per_row) * z + ku % per_row;
        let e = extra[r];
        if e == [0.0; 3] {
            continue;
        }
        p.extra_load
            .set(Some(nalgebra::Vector3::new(e[0], e[1], e[2])));
        p.roller_tol.set(p.tol);
        let cphi = p.unique[ku].0;
        let solved = p.solve_roller(ku, cphi, p.local_u(ku, u), q, &mut iterations, None);
        p.extra_load.set(None);
        let ev = solved.map_err(|e| match e {
            SolveError::RollerNotConverged {
                iterations,
                residual,
                tolerance,
                ..
            } => SolveError::RollerNotConverged {
                roller: r + 1,
                iterations,
                residual,
                tolerance,
            },
            other => other,
        })?;
        worst_force = worst_force.max(ev.g_q[0].abs().max(ev.g_q[1].abs()));
        worst_moment = worst_moment.max(ev.g_q[2].abs());
    }
    let mut out = assemble(b, &p, u, &qs, ld.residuals, &ld.speeds);
    // assemble's roller residuals leave the extra loads out: the solves' own residuals.
    out.residuals.roller_force_n = worst_force;
    out.residuals.roller_moment_nm = worst_moment;
    // Rollers whose load was zero keep ld's results exactly (assemble recomputes them from
    // the same state, which is the same arithmetic; copied to be certain).
    for (k, r) in out.rollers.iter_mut().enumerate() {
        let rep = ld.mirror.get(k).copied().flatten().unwrap_or(k);
        if extra.get(rep).is_some_and(|e| *e == [0.0; 3]) {
            *r = ld.rollers[k].clone();
        }
    }
    out.mirror = ld.mirror.clone();
    out.stats = ld.stats;
    out.stats.roller_iterations += iterations;
    out.stats.lamina_evaluations += p.evals.get();
    out.warm.inertial = ld.warm.inertial.clone();
    Ok(out)
}

impl Problem {
    /// The ring equilibrium (eq. 3.12–3.13) at the problem's current guide ring offset:
    /// [`Problem::solve_ring`] with its ending read as converged or as a typed error.
    fn ring_equilibrium(
        &self,
        b: &Bearing,
        u: &mut [f64; 2],
        qs: &mut Vec<nalgebra::Vector3<f64>>,
        stats: &mut SolveStats,
        trace: &mut Option<(usize, Vec<TraceStep>)>,
        cancel: Option<&AtomicBool>,
    ) -> Result<driver::RingState, SolveError> {
        let (termination, state) = self.solve_ring(b, u, qs, stats, trace, cancel)?;
        let u = *u;
        let not_converged = |iterations, residual_n| {
            unrestrained(b, u).unwrap_or(SolveError::NotConverged {
                iterations,
                residual_n,
                tolerance_n: self.tol,
            })
        };
        match termination {
            Termination::Converged { .. } => {}
            Termination::Cancelled { .. } => return Err(SolveError::Cancelled),
            Termination::NonFinite { .. } => {
                return Err(SolveError::NonFinite {
                    stage: "ring equilibrium",
                    what: "ring force residual".into(),
                })
            }
            // No acceptable ring step: converged when the residual is within 10³ of the
            // tolerance (round-off), else the rings have no equilibrium we can reach.
            Termination::Stalled {
                iterations,
                residual,
            } => {
                if residual > 1e3 * self.tol {
                    return Err(not_converged(iterations, residual));
                }
            }
            // Out of iterations: accepted within the tolerance. The test is `>`, as it always
            // was: a NaN residual here would pass (it takes a last accepted ring state with a
            // finite, decreased energy and a NaN force).
            Termination::NotConverged {
                iterations,
                residual,
                ..
            } => {
                if residual > self.tol {
                    return Err(not_converged(iterations, residual));
                }
            }
            // The shifted Cholesky step always exists: not reached, and not converged if it
            // were.
            Termination::SingularJacobian { iteration } => {
                let g = state.g;
                return Err(not_converged(iteration + 1, g[0].abs().max(g[1].abs())));
            }
        }
        Ok(state)
    }
}

/// Test fixture: the aerospace bearing with no load, no speed and no clearance, solved —
/// every roller and lamina at its nominal geometry.
#[cfg(test)]
pub(crate) fn solved_at_rest() -> (Bearing, LoadDistribution) {
    let mut b = Bearing::example_aerospace();
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 0.0;
    b.operating.inner_speed_rad_s = 0.0;
    b.geometry.diametral_clearance_m = 0.0;
    let ld = solve(
        &b,
        &DynamicSpeeds::app_c_estimate(&b),
        &SolveOptions::default(),
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    (b, ld)
}
