//! Bearing equilibrium (seed 004 eqs. 40–42, 92–106) and the 5×5 stiffness matrix
//! (eqs. 107–120).
//!
//! The cone (inner ring) is displaced by x = (δx, δy, δz) and held at the prescribed
//! rotations (θx, θy) (the deck's misalignment); the cup is fixed. At roller q (azimuth
//! φ_q = 2π(q − 1)/n from x) the ring approach along the cup normal and the
//! misalignment are (eqs. 40, 42)
//!
//! Δ_q = δz·sin β + (δx cos φ + δy sin φ − P_D/2)·cos β + R_m(θx sin φ + θy cos φ),
//! Θ_q = θx sin φ + θy cos φ,    R_m = ½(E sin β + d sin(τ/2)),
//!
//! (initial displacements added to x). The bearing's reactions on the cone, positive
//! opposite to the displacements (eqs. 92–96), are
//!
//! F′ = (cos β Σ P₁ cos φ, cos β Σ P₁ sin φ, sin β Σ P₁),
//! M′ = (Σ (R_m P₁ + M₁) sin φ, Σ (R_m P₁ + M₁) cos φ),
//!
//! and equilibrium is F′ = F_applied for the three forces (eqs. 97–99; the applied radial
//! load along x, no load along y, the thrust along z). M′ is the moment that holds the
//! prescribed rotations, reported. The stiffness K_ij = ∂(F′, M′)_i/∂(x, θ)_j follows
//! from each roller's dP₁/d(Δ, Θ) and dM₁/d(Δ, Θ) (eqs. 107–120); its x–y–z block is the
//! Newton Jacobian of the equilibrium (eqs. 100–106).
//!
//! Rollers with equal (Δ, Θ) to the last bit are solved once (pure thrust: one roller;
//! a radial load in x with no θx: the mirror pairs φ, −φ, whose cosines are taken equal
//! by construction).

use nalgebra::{Matrix3, Matrix4, SMatrix, Vector3, Vector4};
use thiserror::Error;

use super::contact::{ContactError, Race, RaceContact};
use super::geometry::{Dynamics, GeometryError, RollerGeometry};
use super::input::TaperedInput;
use super::roller::{RollerError, RollerModel, RollerSolution, RollerState};
use crate::numerics::newton::{Backtracking, Newton, NewtonSystem, Termination, TrustRegion};

/// 5×5 matrix (x, y, z, θx, θy).
pub type Matrix5 = SMatrix<f64, 5, 5>;

/// The largest tilt |θy| (rad) the moment solve gives: the ring kinematics (eqs. 40, 42)
/// are linear in the rotations, and the second-order term they drop, R_m·θ²/2 in the
/// approach, is 1.25e-3·R_m at 0.05 rad (8.8 µm on the 32007-X-XL, R_m ≈ 7 mm: as large as
/// its roller approaches), so tilts beyond it are outside the model. A moment that would
/// need more is refused ([`BearingError::MomentBeyondModel`]).
pub const MAX_TILT_RAD: f64 = 0.05;

/// Why a bearing has no equilibrium.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BearingError {
    /// Impossible geometry.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// A contact could not be set up.
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// Thrust not positive: a single tapered roller bearing cannot carry it.
    #[error("axial load {axial_load_n:.4e} N is not positive: a single tapered roller bearing carries thrust in one direction only, and this thrust unseats it (the cone would lift off the rollers)")]
    Unseated {
        /// F_z, N.
        axial_load_n: f64,
    },
    /// Thrust so small that every roller's approach is below what the slices resolve.
    #[error("axial load {axial_load_n:.4e} N is below the smallest this model resolves, {minimum_n:.4e} N: each roller's approach would be under 1e-10 of its diameter ({approach_m:.1e} m), where the slices' loads are round-off of the geometry and the equilibrium has no usable stiffness (raise operating.axial_load)")]
    BelowMinimumLoad {
        /// F_z, N.
        axial_load_n: f64,
        /// The smallest thrust solved, N.
        minimum_n: f64,
        /// The approach 1e-10·d, m.
        approach_m: f64,
    },
    /// Radial load too large for the thrust: no roller set can balance it.
    #[error("radial load {radial_load_n:.4e} N needs a thrust above F_r·tan β plus the flanges' centrifugal thrust, {needed_n:.4e} N (axial load {axial_load_n:.4e} N): with less, even one roller carrying all of it on the cone cannot balance it and the bearing unseats")]
    RadialExceedsThrust {
        /// F_r, N.
        radial_load_n: f64,
        /// F_z, N.
        axial_load_n: f64,
        /// F_r·tan β + n·P₁,cf·sin β, N.
        needed_n: f64,
    },
    /// At this speed the flanges alone carry more thrust than applied: every roller
    /// leaves the cone and the cone has no equilibrium. Proof: eliminating P₃ from a
    /// roller's force balances (55)–(56) gives P₁·cos(α + τ/2) = P₂·cos(α − τ/2) +
    /// F_c·cos(ψ − α), so every roller with P₂ ≥ 0 has P₁ ≥ P₁,cf, the cup-and-flange load
    /// of (121)–(122); a roller touching nothing cannot balance F_c; and the cup's axial
    /// balance is Σ P₁·sin β = F_a. Hence n·P₁,cf·sin β ≤ F_a is necessary (test
    /// `no_equilibrium_above_the_flange_thrust_speed_proof_in_numbers`).
    #[error("the rollers' centrifugal load on the flanges already carries n·P₁·sin β = {flange_thrust_n:.4e} N of thrust, more than the axial load {axial_load_n:.4e} N: every roller leaves the cone and no equilibrium exists (every roller's cup load is at least its cup-and-flange load, eqs. 55–56 and 121–122, and the cup's axial balance needs n·P₁·sin β = F_a); the limit is at a cone speed of {limit_inner_speed_rpm:.0} rpm with the cup speed scaled alike (raise the thrust or lower the speed)")]
    FlangeThrustExceedsLoad {
        /// F_z, N.
        axial_load_n: f64,
        /// Thrust of the cup-and-flange rollers, N.
        flange_thrust_n: f64,
        /// The cone speed (rpm) at which the flanges' thrust equals F_a, both ring speeds
        /// scaled by √(F_a/thrust) (F_c grows as the cage speed squared, eq. 38).
        limit_inner_speed_rpm: f64,
    },
    /// The applied moment cannot be balanced at any tilt (a necessary condition of
    /// equilibrium fails; see [`Bearing::solve_with_moment`]).
    #[error("applied moment {moment_nm:.4e} N·m about y cannot be balanced at any tilt: the roller loads that carry the radial load give R_m·F_r/cos β = {radial_moment_nm:.4e} N·m about the reference point, and the rollers' own contact moments can add at most ±{contact_limit_nm:.4e} N·m (every roller's cup load F_a/(n sin β) on average, all of it at an end of the effective length, eqs. 96–99): the cone tips; hold the tilt (operating.moment = \"held\") or give a moment within {low_nm:.4e}…{high_nm:.4e} N·m")]
    MomentBeyondReach {
        /// M_y applied, N·m.
        moment_nm: f64,
        /// R_m·F_r/cos β, N·m.
        radial_moment_nm: f64,
        /// √((l_e/2)² + V²)·F_a/sin β, N·m.
        contact_limit_nm: f64,
        /// The necessary range's lower end, N·m.
        low_nm: f64,
        /// Its upper end, N·m.
        high_nm: f64,
    },
    /// The applied moment lies outside the moments this model balances: the outer
    /// solve on θy (see [`Bearing::solve_with_moment`]) reached the end of its range
    /// (|θy| = [`MAX_TILT_RAD`], a fold K_c ≤ 0, or a tilt where the held-tilt solve has
    /// no equilibrium) with the moment still beyond reach.
    #[error("applied moment {moment_nm:.4e} N·m about y is beyond what this model balances: the cone's moment M′y at a held tilt is monotone in the tilt (K_c = dM′y/dθy > 0) and reaches {limit_nm:.4e} N·m at θy = {limit_tilt_rad:.4e} rad, where {reason}; give operating.moment {bound} {limit_nm:.4e} N·m, or hold the tilt (operating.moment = \"held\", operating.misalignment)")]
    MomentBeyondModel {
        /// M_y applied, N·m.
        moment_nm: f64,
        /// The moment at the end of the reachable range, N·m.
        limit_nm: f64,
        /// The tilt there, rad.
        limit_tilt_rad: f64,
        /// "at least" (the limit is the smallest moment reached) or "at most".
        bound: &'static str,
        /// Why the range ends there.
        reason: String,
    },
    /// A roller has no equilibrium.
    #[error("roller {index} (azimuth {azimuth_deg:.2}°): {source}")]
    Roller {
        /// Roller index q (1-based).
        index: usize,
        /// Its azimuth, degrees.
        azimuth_deg: f64,
        /// Why.
        source: RollerError,
    },
    /// The bearing Newton iteration did not converge.
    #[error(
        "bearing equilibrium did not converge: {} (tolerance {tolerance_n:.3e} N)", super::roller::stopped(.termination)
    )]
    NotConverged {
        /// How it stopped.
        termination: Termination,
        /// Tolerance, N.
        tolerance_n: f64,
    },
}

/// A prepared bearing: geometry, speeds, the roller model and the azimuths.
#[derive(Debug, Clone)]
pub struct Bearing {
    /// The input.
    pub input: TaperedInput,
    /// Roller geometry.
    pub geometry: RollerGeometry,
    /// Speeds and inertia loads.
    pub dynamics: Dynamics,
    /// The roller model.
    pub model: RollerModel,
    /// (cos φ, sin φ) per roller, mirror pairs with bit-equal cosines.
    pub azimuth: Vec<(f64, f64)>,
}

/// One bearing equilibrium, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingSolution {
    /// Working displacements (δx, δy, δz), m (initial displacements not included).
    pub displacement_m: [f64; 3],
    /// Prescribed rotations (θx, θy), rad.
    pub rotation_rad: [f64; 2],
    /// Reactions (F′x, F′y, F′z) N and (M′x, M′y) N·m (eqs. 92–96).
    pub reaction: [f64; 5],
    /// Per roller: its equilibrium, ring approach Δ_q (m) and misalignment Θ_q (rad).
    pub rollers: Vec<(RollerSolution, f64, f64)>,
    /// Analytic stiffness K (eqs. 107–120), SI: N/m, N/rad, N·m/m, N·m/rad.
    pub stiffness: Matrix5,
    /// Bearing Newton iterations.
    pub iterations: usize,
    /// Largest force residual of the equilibrium, N.
    pub residual_n: f64,
    /// Distinct roller solves at the solution (symmetry).
    pub unique_rollers: usize,
}

/// Reactions, stiffness and rollers at one ring position.
#[derive(Debug, Clone)]
struct State {
    reaction: [f64; 5],
    k: Matrix5,
    rollers: Vec<(RollerSolution, f64, f64)>,
    unique: usize,
}

impl Bearing {
    /// Prepare the bearing of `input`.
    pub fn new(input: &TaperedInput) -> Result<Bearing, BearingError> {
        let g = &input.geometry;
        let rg = RollerGeometry::new(g, &input.materials.roller)?;
        let dy = Dynamics::new(g, &rg, &input.operating, input.solver.gyroscopic_inertia);
        let n = input.solver.slices;
        let cup = RaceContact::new(Race::Cup, g, &rg, &input.materials, n)?;
        let cone = RaceContact::new(Race::Cone, g, &rg, &input.materials, n)?;
        let op = &input.operating;
        let z = g.roller_count as f64;
        let force_scale = (op.axial_load_n.abs() + op.radial_load_n.abs()) / z
            + dy.centrifugal_force_n.abs()
            + 1.0;
        // Rollers to 1e-3 of the bearing tolerance: their errors then stay below it.
        let rel = (1e-3 * input.solver.force_tolerance).max(1e-14);
        let model = RollerModel::new(
            g,
            &rg,
            cup,
            cone,
            &dy,
            force_scale,
            rel,
            input.solver.max_roller_iterations,
        );
        let nz = g.roller_count;
        let mut azimuth = vec![(1.0, 0.0); nz];
        for q in 1..=nz / 2 {
            let phi = 2.0 * std::f64::consts::PI * q as f64 / z;
            let (s, c) = phi.sin_cos();
            azimuth[q] = (c, s);
            azimuth[nz - q] = (c, -s);
        }
        if nz.is_multiple_of(2) {
            azimuth[nz / 2] = (-1.0, 0.0);
        }
        Ok(Bearing {
            input: *input,
            geometry: rg,
            dynamics: dy,
            model,
            azimuth,
        })
    }

    /// ∂Δ_q/∂(x, θ) and ∂Θ_q/∂(x, θ) of roller at (cos φ, sin φ) (eqs. 114–120).
    fn lever(&self, (c, s): (f64, f64)) -> ([f64; 5], [f64; 5]) {
        let beta = self.input.geometry.cup_angle_rad;
        let (sb, cb) = beta.sin_cos();
        let rm = self.geometry.moment_radius_m;
        ([cb * c, cb * s, sb, rm * s, rm * c], [0.0, 0.0, 0.0, s, c])
    }

    /// Rollers, reactions and analytic stiffness at ring position `x` (working
    /// displacements and rotations), warm-started from `warm`.
    fn state(
        &self,
        x: &[f64; 5],
        warm: Option<&[(RollerSolution, f64, f64)]>,
    ) -> Result<State, BearingError> {
        let op = &self.input.operating;
        let g = &self.input.geometry;
        let d0 = op.initial_displacement_m;
        let pos = [x[0] + d0[0], x[1] + d0[1], x[2] + d0[2], x[3], x[4]];
        let beta = g.cup_angle_rad;
        let cb = beta.cos();
        let clearance = 0.5 * g.diametral_clearance_m() * cb;
        let mut rollers: Vec<(RollerSolution, f64, f64)> = Vec::with_capacity(self.azimuth.len());
        let mut keys: Vec<(u64, u64, usize)> = Vec::new();
        let mut reaction = [0.0; 5];
        let mut k = Matrix5::zeros();
        let rm = self.geometry.moment_radius_m;
        for (q, &(c, s)) in self.azimuth.iter().enumerate() {
            let (a, b) = self.lever((c, s));
            let delta = a.iter().zip(&pos).map(|(ai, pi)| ai * pi).sum::<f64>() - clearance;
            // + 0.0 turns −0.0 into +0.0, so that equal rollers have equal bits.
            let delta = delta + 0.0;
            let theta = b[3] * pos[3] + b[4] * pos[4] + 0.0;
            let key = (delta.to_bits(), theta.to_bits());
            let sol = if let Some(&(_, _, i)) = keys.iter().find(|k| (k.0, k.1) == key) {
                rollers[i].0
            } else {
                // Warm start on the tangent of the neighbouring solution (its exact
                // ∂(Δ₁, θ₁)/∂(Δ, Θ) of eqs. 88–91): the start is then second-order close
                // and Newton saves an iteration per roller.
                let w = warm
                    .and_then(|w| w.get(q))
                    .filter(|w| w.0.state == RollerState::BothRaces)
                    .map(|(w, d0, t0)| {
                        let (dd, dt) = (delta - d0, theta - t0);
                        (
                            w.delta1_m + w.du[0][0] * dd + w.du[0][1] * dt,
                            w.theta1_rad + w.du[1][0] * dd + w.du[1][1] * dt,
                        )
                    });
                let r =
                    self.model
                        .solve(delta, theta, w)
                        .map_err(|source| BearingError::Roller {
                            index: q + 1,
                            azimuth_deg: s.atan2(c).to_degrees(),
                            source,
                        })?;
                keys.push((key.0, key.1, q));
                r
            };
            let p1 = sol.cup.load_n;
            let m1 = sol.cup.moment_nm;
            let row = [cb * c, cb * s, beta.sin()];
            for i in 0..3 {
                reaction[i] += row[i] * p1;
            }
            reaction[3] += (rm * p1 + m1) * s;
            reaction[4] += (rm * p1 + m1) * c;
            for j in 0..5 {
                let dp = sol.dp1[0] * a[j] + sol.dp1[1] * b[j];
                let dm = sol.dm1[0] * a[j] + sol.dm1[1] * b[j];
                for i in 0..3 {
                    k[(i, j)] += row[i] * dp;
                }
                k[(3, j)] += (rm * dp + dm) * s;
                k[(4, j)] += (rm * dp + dm) * c;
            }
            rollers.push((sol, delta, theta));
        }
        Ok(State {
            reaction,
            k,
            rollers,
            unique: keys.len(),
        })
    }

    /// Reactions at ring position `x` with every roller re-solved (for differences).
    pub fn reactions_at(&self, x: &[f64; 5]) -> Result<[f64; 5], BearingError> {
        Ok(self.state(x, None)?.reaction)
    }

    /// The bearing equilibrium (eqs. 97–106).
    pub fn solve(&self) -> Result<BearingSolution, BearingError> {
        self.solve_from(None)
    }

    /// The bearing equilibrium started from `start` (a neighbouring solution, e.g. the
    /// previous point of a sweep: its ring displacement and every roller's (Δ₁, θ₁)), or
    /// from the pure-thrust estimate without one.
    pub fn solve_from(
        &self,
        start: Option<&BearingSolution>,
    ) -> Result<BearingSolution, BearingError> {
        let op = &self.input.operating;
        let beta = self.input.geometry.cup_angle_rad;
        let z = self.input.geometry.roller_count as f64;
        if !(op.axial_load_n > 0.0) {
            return Err(BearingError::Unseated {
                axial_load_n: op.axial_load_n,
            });
        }
        // The smallest thrust: every roller at an approach of 1e-10 of its diameter, 1e5
        // times the force floor (1e-15 of the diameter). Below it the slices' loads are
        // round-off and the ring Newton stalled with its residual equal to the load (1e-6
        // lbf on the sample, issue 24 item 11); 0.0182 N (4.1e-3 lbf) on the sample.
        let minimum = z * beta.sin() * 1e5 * self.model.force_floor_n;
        if op.axial_load_n < minimum {
            return Err(BearingError::BelowMinimumLoad {
                axial_load_n: op.axial_load_n,
                minimum_n: minimum,
                approach_m: 1e-10 * self.input.geometry.roller_diameter_m,
            });
        }
        // The cup-and-flange roller's thrust (zero without speed).
        let free = self
            .model
            .solve(-1.0, 0.0, None)
            .map_err(|source| BearingError::Roller {
                index: 1,
                azimuth_deg: 0.0,
                source,
            })?;
        let flange_thrust = z * free.cup.load_n * beta.sin();
        if flange_thrust >= op.axial_load_n {
            return Err(BearingError::FlangeThrustExceedsLoad {
                axial_load_n: op.axial_load_n,
                flange_thrust_n: flange_thrust,
                limit_inner_speed_rpm: op.inner_speed_rad_s
                    * (op.axial_load_n / flange_thrust).sqrt()
                    / crate::units::RPM_RAD_S,
            });
        }
        // Every roller carries at least the cup-and-flange load P₁,cf (whose radial
        // components cancel around the bearing); the radial load is carried by the excess
        // ΔP ≥ 0 of the rollers on the cone, so F_r ≤ cot β·Σ ΔP·sin β = cot β·(F_a − n·P₁,cf·sin β).
        let needed = op.radial_load_n.abs() * beta.tan();
        if needed >= op.axial_load_n - flange_thrust {
            return Err(BearingError::RadialExceedsThrust {
                radial_load_n: op.radial_load_n,
                axial_load_n: op.axial_load_n,
                needed_n: needed + flange_thrust,
            });
        }
        let rot = op.misalignment_rad;
        let mut x = if start.is_some() {
            Vector3::zeros()
        } else {
            self.thrust_estimate()
        };
        if let Some(st) = start {
            x = Vector3::new(
                st.displacement_m[0],
                st.displacement_m[1],
                st.displacement_m[2],
            );
        }
        let f_ref = op.axial_load_n.abs().max(op.radial_load_n.abs());
        let tolerance = self.input.solver.force_tolerance * f_ref;
        if let Some(moment) = op.applied_moment_nm() {
            let theta0 = start.map_or(0.0, |st| st.rotation_rad[1]);
            return self.solve_with_moment(start, x, theta0, moment, tolerance);
        }
        self.solve_held(start, x, rot, tolerance)
    }

    /// The cold start of the ring: every roller at the pure-thrust share
    /// P₁ = F_a/(n sin β), its Δ by a few Newton steps on one roller, as the axial
    /// displacement (δx = δy = 0).
    fn thrust_estimate(&self) -> Vector3<f64> {
        let op = &self.input.operating;
        let beta = self.input.geometry.cup_angle_rad;
        let z = self.input.geometry.roller_count as f64;
        let target = op.axial_load_n / (z * beta.sin());
        let mut delta = 1e-6;
        let mut warm = None;
        for _ in 0..40 {
            // A failure here only ends the estimate: the equilibrium names the roller.
            let Ok(r) = self.model.solve(delta, 0.0, warm) else {
                break;
            };
            let step = if r.dp1[0] > 0.0 {
                (target - r.cup.load_n) / r.dp1[0]
            } else {
                delta
            };
            warm = (r.state == RollerState::BothRaces).then_some((r.delta1_m, r.theta1_rad));
            delta += step.clamp(-0.5 * delta.abs().max(1e-7), 2.0 * delta.abs().max(1e-7));
            if step.abs() < 1e-6 * delta.abs() {
                break;
            }
        }
        let clearance = 0.5 * self.input.geometry.diametral_clearance_m() * beta.cos();
        let d0 = op.initial_displacement_m;
        Vector3::new(0.0, 0.0, (delta + clearance) / beta.sin() - d0[2])
    }

    /// The equilibrium with the rotations held at `rot` (the three forces solved, eqs.
    /// 97–106), started from ring position `x` and `start`'s rollers.
    fn solve_held(
        &self,
        start: Option<&BearingSolution>,
        mut x: Vector3<f64>,
        rot: [f64; 2],
        tolerance: f64,
    ) -> Result<BearingSolution, BearingError> {
        let op = &self.input.operating;
        let mut sys = RingSystem {
            bearing: self,
            rot,
            load: Vector3::new(op.radial_load_n, 0.0, op.axial_load_n),
            warm: start
                .filter(|st| st.rollers.len() == self.azimuth.len())
                .map(|st| st.rollers.clone()),
            error: None,
            mirror: rot[0] == 0.0 && op.initial_displacement_m[1] == 0.0,
        };
        let newton = Newton {
            max_iterations: self.input.solver.max_iterations,
            tolerance,
            trust: TrustRegion::new(20.0, 1e-9, 1e4),
            line_search: Backtracking::default(),
        };
        let res = newton.solve(&mut sys, &mut x);
        let ok = match res.termination {
            Termination::Converged { .. } => true,
            Termination::Stalled { residual, .. } => residual <= 10.0 * tolerance,
            _ => false,
        };
        if !ok {
            // See `RingSystem::evaluate`: a roller failure is reported only when it
            // stopped the iteration.
            if let Some(e) = sys.error {
                return Err(e);
            }
            return Err(BearingError::NotConverged {
                termination: res.termination,
                tolerance_n: tolerance,
            });
        }
        let st = res.eval.state;
        Ok(BearingSolution {
            displacement_m: [x[0], x[1], x[2]],
            rotation_rad: rot,
            reaction: st.reaction,
            residual_n: res.eval.r.amax(),
            rollers: st.rollers,
            stiffness: st.k,
            iterations: res.termination.iterations(),
            unique_rollers: st.unique,
        })
    }

    /// The equilibrium under an applied moment M_y (issue 29): four unknowns (δx, δy, δz,
    /// θy), θx held at the deck's misalignment. Equilibrium is F′ = F_applied (eqs.
    /// 97–99) and M′_y = M_y, M′_y = Σ (R_m P₁ + M₁) cos φ (eq. 96). The tilt enters as
    /// the arc length u = R_m·θy and the moment residual as the force (M_y − M′_y)/R_m at
    /// R_m, so one tolerance in newtons serves all four rows; the Jacobian is the
    /// analytic K's (x, y, z, θy) block scaled alike (eqs. 107–120).
    fn solve_with_moment(
        &self,
        start: Option<&BearingSolution>,
        x3: Vector3<f64>,
        theta0: f64,
        moment: f64,
        tolerance: f64,
    ) -> Result<BearingSolution, BearingError> {
        let op = &self.input.operating;
        let rm = self.geometry.moment_radius_m;
        // A necessary condition, checked before iterating (without it a moment no tilt can
        // balance ended in a slice error of some far Newton trial). At any equilibrium
        // Σ P₁ cos φ = F_x/cos β (eq. 97) and Σ P₁ = F_z/sin β (eq. 99, P₁ ≥ 0), and each
        // roller's cup moment about its midpoint is |M₁| ≤ P₁·max|X|, its contact lying
        // within the effective length (eqs. 52–53: |X| ≤ (l_e/2) cos θ + V sin θ ≤
        // √((l_e/2)² + V²)). By eq. 96, M_y − R_m·F_x/cos β = Σ M₁ cos φ, so
        // |M_y − R_m·F_x/cos β| ≤ √((l_e/2)² + V²)·F_z/sin β. (32007-X-XL: 219.5 ± 216.5
        // N·m; the reachable range is narrower still, the rollers not all at φ = 0, π.)
        let beta = self.input.geometry.cup_angle_rad;
        let radial_moment = rm * op.radial_load_n / beta.cos();
        let half_le = 0.5 * self.input.geometry.effective_length_m;
        let contact_limit =
            half_le.hypot(self.geometry.crown_drop_m) * op.axial_load_n / beta.sin();
        if (moment - radial_moment).abs() > contact_limit {
            return Err(BearingError::MomentBeyondReach {
                moment_nm: moment,
                radial_moment_nm: radial_moment,
                contact_limit_nm: contact_limit,
                low_nm: radial_moment - contact_limit,
                high_nm: radial_moment + contact_limit,
            });
        }
        let mut sys = MomentSystem {
            bearing: self,
            theta_x: op.misalignment_rad[0],
            load: Vector4::new(op.radial_load_n, 0.0, op.axial_load_n, moment / rm),
            rm,
            warm: start
                .filter(|st| st.rollers.len() == self.azimuth.len())
                .map(|st| st.rollers.clone()),
            error: None,
            mirror: op.misalignment_rad[0] == 0.0 && op.initial_displacement_m[1] == 0.0,
        };
        let newton = Newton {
            max_iterations: self.input.solver.max_iterations,
            tolerance,
            trust: TrustRegion::new(20.0, 1e-9, 1e4),
            line_search: Backtracking::default(),
        };
        let mut x = Vector4::new(x3[0], x3[1], x3[2], rm * theta0);
        let res = newton.solve(&mut sys, &mut x);
        let ok = match res.termination {
            Termination::Converged { .. } => true,
            Termination::Stalled { residual, .. } => residual <= 10.0 * tolerance,
            _ => false,
        };
        if ok && (x[3] / rm).abs() <= MAX_TILT_RAD {
            let st = res.eval.state;
            return Ok(BearingSolution {
                displacement_m: [x[0], x[1], x[2]],
                rotation_rad: [op.misalignment_rad[0], x[3] / rm],
                reaction: st.reaction,
                residual_n: res.eval.r.amax(),
                rollers: st.rollers,
                stiffness: st.k,
                iterations: res.termination.iterations(),
                unique_rollers: st.unique,
            });
        }
        // The four-unknown Newton failed (or left the tilt range): the bracketed 1-D solve
        // on θy over held-tilt solves decides, and names the limit if there is one.
        let newton_error = if ok {
            None
        } else if let Some(e) = sys.error {
            Some(e)
        } else {
            Some(BearingError::NotConverged {
                termination: res.termination,
                tolerance_n: tolerance,
            })
        };
        self.solve_tilt_1d(start, x3, theta0, moment, tolerance, newton_error)
    }

    /// The equilibrium under an applied moment by a 1-D solve on the tilt θy (outer) with
    /// the three forces solved at each held tilt (inner, [`Bearing::solve_held`], warm
    /// started from the previous tilt's solution): g(θ) = M′y(θ) − M_y, g′ = K_c =
    /// K_θθ − K_θx·K_xx⁻¹·K_xθ, the condensed tilt stiffness of the analytic K (eqs.
    /// 107–120, forces held). Newton steps on g, safeguarded: before a sign change, a step
    /// whose held solve fails is halved toward the last solved tilt; after one, the root is
    /// bracketed and a step leaving the bracket is replaced by bisection. Converged when
    /// |g|/R_m meets the bearing tolerance (the moment row's scaling of the 4-unknown
    /// Newton), the forces meeting it by the inner solve. The tilt is kept within
    /// ±[`MAX_TILT_RAD`]; a moment beyond the end of the solvable range (that bound, a fold
    /// K_c ≤ 0, or a tilt whose held solve fails however short the step) is refused with
    /// [`BearingError::MomentBeyondModel`], naming the moment reached there. `newton_error`
    /// (the 4-unknown Newton's failure) is returned only if the first held solve fails.
    fn solve_tilt_1d(
        &self,
        start: Option<&BearingSolution>,
        x3: Vector3<f64>,
        theta0: f64,
        moment: f64,
        tolerance: f64,
        newton_error: Option<BearingError>,
    ) -> Result<BearingSolution, BearingError> {
        let op = &self.input.operating;
        let rm = self.geometry.moment_radius_m;
        let rot = |t: f64| [op.misalignment_rad[0], t];
        let condensed = |k: &Matrix5| {
            let a = k.fixed_view::<3, 3>(0, 0).into_owned();
            let b = k.fixed_view::<3, 1>(0, 4).into_owned();
            let c = k.fixed_view::<1, 3>(4, 0).into_owned();
            a.try_inverse()
                .map_or(f64::NAN, |inv| k[(4, 4)] - (c * inv * b)[(0, 0)])
        };
        let theta_start = theta0.clamp(-MAX_TILT_RAD, MAX_TILT_RAD);
        let first = self
            .solve_held(start, x3, rot(theta_start), tolerance)
            .or_else(|_| self.solve_held(None, self.thrust_estimate(), rot(0.0), tolerance));
        let mut good = match first {
            Ok(sol) => sol,
            Err(e) => return Err(newton_error.unwrap_or(e)),
        };
        let g_of = |sol: &BearingSolution| sol.reaction[4] - moment;
        let mut g_good = g_of(&good);
        // The bracket [lo, hi] on θ (g(lo) < 0 < g(hi)) once found.
        let mut bracket: Option<(f64, f64)> = None;
        let mut inner = good.iterations;
        let beyond = |good: &BearingSolution, reason: String| {
            let limit = good.reaction[4];
            BearingError::MomentBeyondModel {
                moment_nm: moment,
                limit_nm: limit,
                limit_tilt_rad: good.rotation_rad[1],
                bound: if moment < limit {
                    "at least"
                } else {
                    "at most"
                },
                reason,
            }
        };
        for _ in 0..200 {
            if (g_good / rm).abs() <= tolerance {
                return Ok(BearingSolution {
                    iterations: inner,
                    ..good
                });
            }
            let theta = good.rotation_rad[1];
            let kc = condensed(&good.stiffness);
            let mut target = if kc > 0.0 {
                theta - g_good / kc
            } else {
                f64::NAN
            };
            match bracket {
                Some((lo, hi)) => {
                    if !(target > lo && target < hi) {
                        target = 0.5 * (lo + hi);
                    }
                }
                None => {
                    if !(kc > 0.0) {
                        return Err(beyond(
                            &good,
                            format!("the condensed tilt stiffness is {kc:.4e} N·m/rad (a fold: the cone tips)"),
                        ));
                    }
                    let at_bound = theta.abs() >= MAX_TILT_RAD;
                    target = target.clamp(-MAX_TILT_RAD, MAX_TILT_RAD);
                    if at_bound && (target - theta).abs() < f64::EPSILON {
                        return Err(beyond(
                            &good,
                            format!("the tilt reaches its bound |θy| = {MAX_TILT_RAD} rad (the ring kinematics, eqs. 40 and 42, are linear in the rotations)"),
                        ));
                    }
                }
            }
            // Held solve at the target, halving the step toward the solved tilt on failure.
            let mut step = target - theta;
            let mut last_err = None;
            let mut next = None;
            for _ in 0..40 {
                let x = Vector3::new(
                    good.displacement_m[0],
                    good.displacement_m[1],
                    good.displacement_m[2],
                );
                match self.solve_held(Some(&good), x, rot(theta + step), tolerance) {
                    Ok(sol) => {
                        next = Some(sol);
                        break;
                    }
                    Err(e) => {
                        last_err = Some(e);
                        step *= 0.5;
                        if step.abs() < 1e-9 {
                            break;
                        }
                    }
                }
            }
            let Some(sol) = next else {
                let reason = last_err.map_or_else(String::new, |e| e.to_string());
                return Err(beyond(
                    &good,
                    format!("the held-tilt equilibrium a step further has none: {reason}"),
                ));
            };
            inner += sol.iterations;
            let g = g_of(&sol);
            let t = sol.rotation_rad[1];
            bracket = match bracket {
                Some((lo, hi)) => Some(if g < 0.0 { (t, hi) } else { (lo, t) }),
                None if g.signum() != g_good.signum() => {
                    Some(if g < 0.0 { (t, theta) } else { (theta, t) })
                }
                None => None,
            };
            good = sol;
            g_good = g;
        }
        Err(BearingError::NotConverged {
            termination: Termination::NotConverged {
                iterations: 200,
                residual: (g_good / rm).abs(),
                tolerance,
            },
            tolerance_n: tolerance,
        })
    }

    /// Stiffness by central differences of re-solved roller equilibria about the
    /// solution `sol` (steps 1e-5 of the largest roller approach, rotations by that over
    /// R_m).
    pub fn stiffness_fd(&self, sol: &BearingSolution) -> Result<Matrix5, BearingError> {
        let dmax = sol.rollers.iter().map(|r| r.1.abs()).fold(1e-9, f64::max);
        let h = 1e-5 * dmax;
        let rm = self.geometry.moment_radius_m;
        let x0 = [
            sol.displacement_m[0],
            sol.displacement_m[1],
            sol.displacement_m[2],
            sol.rotation_rad[0],
            sol.rotation_rad[1],
        ];
        let mut k = Matrix5::zeros();
        for j in 0..5 {
            let hj = if j < 3 { h } else { h / rm };
            let (mut xp, mut xm) = (x0, x0);
            xp[j] += hj;
            xm[j] -= hj;
            let rp = self.state(&xp, Some(&sol.rollers))?.reaction;
            let rn = self.state(&xm, Some(&sol.rollers))?.reaction;
            for i in 0..5 {
                k[(i, j)] = (rp[i] - rn[i]) / (2.0 * hj);
            }
        }
        Ok(k)
    }
}

/// The stiffness in units comparable across rows and columns: rotations as arc length
/// at R_m and moments as forces at R_m, S·K·S with S = diag(1, 1, 1, 1/R_m, 1/R_m), N/m.
pub fn scaled(k: &Matrix5, rm: f64) -> Matrix5 {
    let s = SMatrix::<f64, 5, 1>::from_column_slice(&[1.0, 1.0, 1.0, 1.0 / rm, 1.0 / rm]);
    let d = Matrix5::from_diagonal(&s);
    d * k * d
}

/// Largest |K_ij − K_ji| of the scaled matrix over its largest diagonal entry.
pub fn asymmetry(k: &Matrix5, rm: f64) -> f64 {
    let s = scaled(k, rm);
    let diag = (0..5).map(|i| s[(i, i)].abs()).fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    for i in 0..5 {
        for j in (i + 1)..5 {
            worst = worst.max((s[(i, j)] - s[(j, i)]).abs());
        }
    }
    if diag > 0.0 {
        worst / diag
    } else {
        0.0
    }
}

/// Largest |K_an − K_fd| over each scaled row's largest entry.
pub fn fd_difference(an: &Matrix5, fd: &Matrix5, rm: f64) -> f64 {
    let (a, f) = (scaled(an, rm), scaled(fd, rm));
    let mut worst: f64 = 0.0;
    for i in 0..5 {
        let scale = (0..5).map(|j| a[(i, j)].abs()).fold(0.0, f64::max);
        if scale == 0.0 {
            continue;
        }
        for j in 0..5 {
            worst = worst.max((a[(i, j)] - f[(i, j)]).abs() / scale);
        }
    }
    worst
}

struct RingEval {
    r: Vector3<f64>,
    j: Matrix3<f64>,
    state: State,
}

struct RingSystem<'a> {
    bearing: &'a Bearing,
    rot: [f64; 2],
    load: Vector3<f64>,
    warm: Option<Vec<(RollerSolution, f64, f64)>>,
    error: Option<BearingError>,
    /// Mirror symmetry about the x–z plane (no θx, no initial δy, no load along y): δy
    /// stays exactly 0 and the y residual is exactly 0 (its sum of ± pairs is round-off).
    mirror: bool,
}

impl NewtonSystem<3> for RingSystem<'_> {
    type Eval = RingEval;

    fn evaluate(&mut self, x: &Vector3<f64>) -> RingEval {
        let pos = [x[0], x[1], x[2], self.rot[0], self.rot[1]];
        match self.bearing.state(&pos, self.warm.as_deref()) {
            Ok(st) => {
                let ry = if self.mirror {
                    0.0
                } else {
                    self.load[1] - st.reaction[1]
                };
                let r = Vector3::new(
                    self.load[0] - st.reaction[0],
                    ry,
                    self.load[2] - st.reaction[2],
                );
                let j = -st.k.fixed_view::<3, 3>(0, 0).into_owned();
                self.warm = Some(st.rollers.clone());
                RingEval { r, j, state: st }
            }
            Err(e) => {
                // A ring trial where some roller has no equilibrium (a slice beyond
                // Lundberg's range, eq. 71, or a roller Newton that failed) is a NaN
                // residual: the line search backtracks toward the accepted ring position.
                // The latest failure is kept as the reason should the solve not converge.
                self.error = Some(e);
                RingEval {
                    r: Vector3::repeat(f64::NAN),
                    j: Matrix3::zeros(),
                    state: State {
                        reaction: [f64::NAN; 5],
                        k: Matrix5::zeros(),
                        rollers: Vec::new(),
                        unique: 0,
                    },
                }
            }
        }
    }

    fn residual<'e>(&self, e: &'e RingEval) -> &'e Vector3<f64> {
        &e.r
    }

    fn jacobian<'e>(&self, e: &'e RingEval) -> &'e Matrix3<f64> {
        &e.j
    }

    fn step_length(&self, step: &Vector3<f64>) -> f64 {
        step.norm() / 1e-7
    }

    fn newton_step(&self, e: &RingEval) -> Option<Vector3<f64>> {
        // A ring position where no roller touches the cone has a singular Jacobian in the
        // unloaded directions (y under a pure x load): solve in the least-squares sense
        // by a pseudo-inverse, which leaves those directions alone.
        let j = &e.j;
        let step = match j.try_inverse() {
            Some(inv) => Some(-(inv * e.r)),
            None => j.pseudo_inverse(1e-12 * j.amax()).ok().map(|p| -(p * e.r)),
        };
        step.map(|mut s| {
            if self.mirror {
                s[1] = 0.0;
            }
            s
        })
    }
}

/// Ring unknowns (δx, δy, δz, R_m·θy) under an applied moment (see
/// [`Bearing::solve_with_moment`]).
struct MomentEval {
    r: Vector4<f64>,
    j: Matrix4<f64>,
    state: State,
}

struct MomentSystem<'a> {
    bearing: &'a Bearing,
    theta_x: f64,
    /// (F_x, F_y, F_z, M_y/R_m), N.
    load: Vector4<f64>,
    rm: f64,
    warm: Option<Vec<(RollerSolution, f64, f64)>>,
    error: Option<BearingError>,
    /// Mirror symmetry about the x–z plane (θy and the moment about y keep it).
    mirror: bool,
}

impl NewtonSystem<4> for MomentSystem<'_> {
    type Eval = MomentEval;

    fn evaluate(&mut self, x: &Vector4<f64>) -> MomentEval {
        let pos = [x[0], x[1], x[2], self.theta_x, x[3] / self.rm];
        match self.bearing.state(&pos, self.warm.as_deref()) {
            Ok(st) => {
                let ry = if self.mirror {
                    0.0
                } else {
                    self.load[1] - st.reaction[1]
                };
                let r = Vector4::new(
                    self.load[0] - st.reaction[0],
                    ry,
                    self.load[2] - st.reaction[2],
                    self.load[3] - st.reaction[4] / self.rm,
                );
                // Rows F_x, F_y, F_z, M_y/R_m; columns δx, δy, δz, R_m·θy.
                let idx = [0usize, 1, 2, 4];
                let mut j = Matrix4::zeros();
                for (a, &ia) in idx.iter().enumerate() {
                    for (b, &ib) in idx.iter().enumerate() {
                        let row = if a == 3 { 1.0 / self.rm } else { 1.0 };
                        let col = if b == 3 { 1.0 / self.rm } else { 1.0 };
                        j[(a, b)] = -st.k[(ia, ib)] * row * col;
                    }
                }
                self.warm = Some(st.rollers.clone());
                MomentEval { r, j, state: st }
            }
            Err(e) => {
                // A ring trial where some roller has no equilibrium (a slice beyond
                // Lundberg's range, eq. 71, or a roller Newton that failed) is a NaN
                // residual: the line search backtracks toward the accepted ring position.
                // The latest failure is kept as the reason should the solve not converge.
                self.error = Some(e);
                MomentEval {
                    r: Vector4::repeat(f64::NAN),
                    j: Matrix4::zeros(),
                    state: State {
                        reaction: [f64::NAN; 5],
                        k: Matrix5::zeros(),
                        rollers: Vec::new(),
                        unique: 0,
                    },
                }
            }
        }
    }

    fn residual<'e>(&self, e: &'e MomentEval) -> &'e Vector4<f64> {
        &e.r
    }

    fn jacobian<'e>(&self, e: &'e MomentEval) -> &'e Matrix4<f64> {
        &e.j
    }

    fn step_length(&self, step: &Vector4<f64>) -> f64 {
        step.norm() / 1e-7
    }

    fn newton_step(&self, e: &MomentEval) -> Option<Vector4<f64>> {
        // As the 3-DOF ring: a pseudo-inverse leaves unloaded directions alone.
        let j = &e.j;
        let step = match j.try_inverse() {
            Some(inv) => Some(-(inv * e.r)),
            None => j.pseudo_inverse(1e-12 * j.amax()).ok().map(|p| -(p * e.r)),
        };
        step.map(|mut s| {
            if self.mirror {
                s[1] = 0.0;
            }
            s
        })
    }
}

#[cfg(test)]
mod tests;
