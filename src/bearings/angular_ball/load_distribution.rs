//! Quasi-static load distribution with centrifugal force and gyroscopic moment (seed 001
//! eqs. 2-5 … 2-8, 3-1, 3-2; Harris's model), iterated with race-control kinematics to a
//! fixed point.
//!
//! # Unknowns and geometry (Fig. 3-1)
//! In the plane of a ball at azimuth ψ, (a, r) axial and radial. The outer groove centre
//! O' is fixed. X = B − O' is the ball centre relative to O' (Harris's X₁, X₂). The
//! inner groove centre sits at I − O' = (A sin α₀ + δ_a, A cos α₀ + δ_r cos ψ) (Chen's
//! Z_ib, R_ib for a ring displaced δ_a axially and δ_r radially towards ψ = 0; no tilt).
//! Then (3-1a…d):
//! * outer: L_o = |X|, δ_o = L_o − (f_o − ½)D, (sin α_o, cos α_o) = X/L_o;
//! * inner: v = (I − O') − X, L_i = |v|, δ_i = L_i − (f_i − ½)D, (sin α_i, cos α_i) = v/L_i;
//! * Q = K δ^{3/2} (3-2) with K of App. A at the current contact angle.
//!
//! The angles are whatever the geometry gives, 90° and beyond included: the groove is a
//! full torus here (no shoulder). A contact angle past 90° means the ball centre lies
//! radially beyond the groove centre of curvature; it happens for Bearing B with the
//! preload held as a force at 9 500 rpm (α_i = 90.76°: the centrifugal force pushes the
//! ball out until L_o cos α_o exceeds A cos α₀, which for B's grooves equals (f_o − ½)D;
//! the numbers and why it is not the friction term are in the test
//! `force_held_preload_lets_the_inner_angle_run_up`). A real ring's shoulder would end
//! below such a contact; the displacement-held preload (the default) keeps α_i at 68.9°.
//!
//! # Ball equilibrium (2-5a, b) in vector form
//! The inner race pushes the ball along u_i = v/L_i, the outer along −u_o. The friction
//! that supplies the gyroscopic moment M_g = J ω_m ω_r (along the rolling direction t)
//! acts along the contact tangents: with R = [[0, 1], [−1, 0]] (a quarter turn in the
//! (a, r) plane) the force on the ball is
//!
//! ```text
//! F = (I + µR)(Q_i u_i − Q_o u_o) + (0, m ω_m² R_b),
//! ```
//!
//! µ = 2M_g/(D(Q_i + Q_o)) (2-7), capped at the traction's µ_m ([`Conditions::max_friction`]:
//! beyond it the contacts cannot hold the precession and the ball skids). Its couple about
//! the ball centre is
//! ½µD(Q_i + Q_o) = M_g along +t: this is the physically consistent direction
//! ([`GyroscopicFriction::Resisting`], tested in `friction_couple_supplies_the_precession`).
//! Written out, F_a = Q_i sin α_i − Q_o sin α_o + µ(Q_i cos α_i − Q_o cos α_o): the seed's
//! (2-5a) prints the µ terms with the opposite sign ([`GyroscopicFriction::SeedSign`],
//! which reproduces Chen's ch. 6 numbers).
//!
//! Jacobian (analytic): with G = Q' u uᵀ + (Q/L)(I − u uᵀ), the derivative of Q·u with
//! respect to its vector, J_b = −(I + µR)(G_i + G_o) + diag(0, mω_m²).
//!
//! # Ring equilibrium (2-8)
//! The force P = (I + µR)Q_i u_i of the inner ring on each ball: ΣP_a = F_a, ΣP_r cos ψ = F_r
//! (the friction included: it is a force on the ring; Chen neglects it, and at rest it is
//! zero). The ring Jacobian comes from the implicit function theorem:
//! dP/d(I − O') = M_i (I + J_b⁻¹ M_i), M_i = (I + µR)G_i.
//!
//! # Fixed point
//! Contact stiffness (at the operating angles), orbital speed ω_m and ball spin ω_r
//! (race control, `race_control`) and µ are held during one load solve and updated from
//! its answer until the contact angles change by less than 1e-12 rad and the loads by
//! less than 1e-10 of their sum.

use nalgebra::{Matrix2, Vector2};

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{GyroscopicFriction, RaceControl};
use super::race_control::{controlling_race, race_control, KinematicsInput, RaceKinematics};
use crate::numerics::cancel::Cancel;
use crate::numerics::newton::{Backtracking, Newton, NewtonSystem, Termination, TrustRegion};
use crate::physics::contact::point::{HertzPointContact, Race};

/// Per-ball quantities held fixed during one load solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallParams {
    /// Signed friction coefficient µ of (I + µR) (sign: the gyroscopic convention).
    pub friction: f64,
    /// m·ω_m², N/m: the centrifugal force is this times the ball-centre radius.
    pub centrifugal_coeff: f64,
    /// K of the inner contact, N/m^1.5.
    pub inner_stiffness: f64,
    /// K of the outer contact, N/m^1.5.
    pub outer_stiffness: f64,
}

/// One contact of a ball in equilibrium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLoad {
    /// Q, N.
    pub load_n: f64,
    /// dQ/dδ, N/m.
    pub stiffness_n_per_m: f64,
    /// α, rad.
    pub angle_rad: f64,
    /// δ, elastic approach, m (negative: the contact is open).
    pub deflection_m: f64,
    /// Unit vector (sin α, cos α) along which the race pushes the ball (inner) or the
    /// ball pushes the race (outer).
    unit: Vector2<f64>,
    /// Distance between the ball centre and the groove centre, m.
    length: f64,
}

impl ContactLoad {
    /// The contact for the centre-to-centre vector `v`, its angle left NaN: the ball
    /// Newton evaluates this many times and needs only `unit`; the angle (an atan2, a
    /// tenth of the load solve's time) is set once on the answer by [`Self::with_angle`].
    fn new(v: Vector2<f64>, offset: f64, stiffness: f64) -> Self {
        let length = v.norm();
        let unit = v / length;
        let deflection = length - offset;
        let d = deflection.max(0.0);
        ContactLoad {
            load_n: stiffness * d * d.sqrt(),
            stiffness_n_per_m: 1.5 * stiffness * d.sqrt(),
            angle_rad: f64::NAN,
            deflection_m: deflection,
            unit,
            length,
        }
    }

    /// This contact with its angle α = atan2(sin α, cos α) of the unit vector.
    fn with_angle(self) -> Self {
        ContactLoad {
            angle_rad: self.unit[0].atan2(self.unit[1]),
            ..self
        }
    }

    /// d(Q·u)/dv = Q' u uᵀ + (Q/L)(I − u uᵀ).
    fn g(&self) -> Matrix2<f64> {
        let uu = self.unit * self.unit.transpose();
        uu * self.stiffness_n_per_m + (Matrix2::identity() - uu) * (self.load_n / self.length)
    }
}

/// (I + µR), R the quarter turn [[0, 1], [−1, 0]].
fn friction_matrix(mu: f64) -> Matrix2<f64> {
    Matrix2::new(1.0, mu, -mu, 1.0)
}

/// One ball in equilibrium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallEquilibrium {
    /// X = B − O', m.
    pub position: Vector2<f64>,
    /// Inner contact.
    pub inner: ContactLoad,
    /// Outer contact.
    pub outer: ContactLoad,
    /// Centrifugal force, N (2-6).
    pub centrifugal_n: f64,
    /// Radius of the ball centre, m.
    pub centre_radius_m: f64,
    /// Force of the inner ring on the ball, (axial, radial), N.
    pub ring_force: Vector2<f64>,
    /// d(ring_force)/d(I − O'), N/m.
    pub ring_stiffness: Matrix2<f64>,
    /// Largest force residual, N.
    pub residual_n: f64,
    /// Newton iterations.
    pub iterations: usize,
}

struct BallProblem<'a> {
    geom: &'a BallGeometry,
    centres: Vector2<f64>,
    p: BallParams,
}

struct BallEval {
    f: Vector2<f64>,
    j: Matrix2<f64>,
    inner: ContactLoad,
    outer: ContactLoad,
}

impl BallProblem<'_> {
    fn eval(&self, x: &Vector2<f64>) -> BallEval {
        let g = self.geom;
        let outer = ContactLoad::new(*x, g.outer_offset_m, self.p.outer_stiffness);
        let inner = ContactLoad::new(self.centres - x, g.inner_offset_m, self.p.inner_stiffness);
        let fm = friction_matrix(self.p.friction);
        let c = self.p.centrifugal_coeff;
        let f = fm * (inner.unit * inner.load_n - outer.unit * outer.load_n)
            + Vector2::new(0.0, c * (g.outer_centre_radius_m + x[1]));
        let j = -(fm * (inner.g() + outer.g())) + Matrix2::new(0.0, 0.0, 0.0, c);
        BallEval { f, j, inner, outer }
    }
}

impl NewtonSystem<2> for BallProblem<'_> {
    type Eval = BallEval;
    fn evaluate(&mut self, x: &Vector2<f64>) -> BallEval {
        self.eval(x)
    }
    fn residual<'e>(&self, e: &'e BallEval) -> &'e Vector2<f64> {
        &e.f
    }
    fn jacobian<'e>(&self, e: &'e BallEval) -> &'e Matrix2<f64> {
        &e.j
    }
}

/// Why a Newton solve stopped, in words (for error messages).
fn reason(t: &Termination) -> &'static str {
    match t {
        Termination::Converged { .. } => "converged",
        Termination::NotConverged { .. } => "iteration budget spent",
        Termination::Stalled { .. } => "line search stalled",
        Termination::SingularJacobian { .. } => "singular Jacobian",
        Termination::NonFinite { .. } => "non-finite residual",
        Termination::Cancelled { .. } => "cancelled",
    }
}

/// The ball resting on the outer race alone, its inner contact open: the outer contact
/// force balances the centrifugal force through (I + µR), Q_o u_o = F_c (I + µR)⁻¹ e_r, a
/// fixed direction, so only the approach δ_o is unknown and K δ_o^{3/2} =
/// m·c·(R_O' + (f_o − ½)D + δ_o)·d_r is solved by substitution (its right side hardly
/// depends on δ_o). Exact, and the only robust way: Newton sees a ball held by a nearly
/// tangential-free contact as nearly singular. It depends on the ball's parameters alone,
/// not on where the inner ring is, so the ring solve forms it once per fixed-point
/// iteration rather than in every ball solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OuterAlone {
    /// X = B − O', m.
    position: Vector2<f64>,
    /// δ_o, m.
    approach_m: f64,
}

impl OuterAlone {
    /// `None` without centrifugal force (nothing holds the ball on the outer race) or
    /// when (I + µR) is singular.
    pub fn new(geom: &BallGeometry, p: &BallParams) -> Option<Self> {
        // (Written so that a NaN coefficient, too, gives None.)
        if !matches!(
            p.centrifugal_coeff.partial_cmp(&0.0),
            Some(std::cmp::Ordering::Greater)
        ) {
            return None;
        }
        let inv = friction_matrix(p.friction).try_inverse()?;
        let w = inv * Vector2::new(0.0, 1.0);
        let (m, dir) = (w.norm(), w / w.norm());
        let mut d_o = 0.0f64;
        for _ in 0..60 {
            let fc = p.centrifugal_coeff
                * (geom.outer_centre_radius_m + (geom.outer_offset_m + d_o) * dir[1]);
            let next = (m * fc / p.outer_stiffness).max(0.0).powf(2.0 / 3.0);
            let done = (next - d_o).abs() <= 1e-15 * next;
            d_o = next;
            if done {
                break;
            }
        }
        Some(OuterAlone {
            position: dir * (geom.outer_offset_m + d_o),
            approach_m: d_o,
        })
    }
}

/// Solve one ball's equilibrium (2-5a, b) for the groove-centre vector `centres`
/// (I − O', m), from `warm` if given. `tolerance_n` on the largest force residual.
pub fn solve_ball(
    geom: &BallGeometry,
    centres: Vector2<f64>,
    p: BallParams,
    warm: Option<Vector2<f64>>,
    tolerance_n: f64,
    ball: usize,
) -> Result<BallEquilibrium, BallError> {
    let alone = OuterAlone::new(geom, &p);
    solve_ball_with(geom, centres, p, alone, warm, tolerance_n, ball)
}

/// [`solve_ball`] with the outer-race-alone state of `p` formed by the caller
/// ([`OuterAlone::new`]).
pub fn solve_ball_with(
    geom: &BallGeometry,
    centres: Vector2<f64>,
    p: BallParams,
    alone: Option<OuterAlone>,
    warm: Option<Vector2<f64>>,
    tolerance_n: f64,
    ball: usize,
) -> Result<BallEquilibrium, BallError> {
    let gap = centres.norm() - geom.inner_offset_m - geom.outer_offset_m;
    let along = centres / centres.norm();
    let problem = BallProblem { geom, centres, p };
    let finish = |x: Vector2<f64>, e: BallEval, residual: f64, iterations: usize| {
        let fm = friction_matrix(p.friction);
        let mi = fm * e.inner.g();
        let mo = fm * e.outer.g();
        let jb = -(mi + mo) + Matrix2::new(0.0, 0.0, 0.0, p.centrifugal_coeff);
        let ring_stiffness = match jb.try_inverse() {
            Some(inv) => mi * (Matrix2::identity() + inv * mi),
            None => Matrix2::zeros(),
        };
        let radius = geom.outer_centre_radius_m + x[1];
        BallEquilibrium {
            position: x,
            inner: e.inner.with_angle(),
            outer: e.outer.with_angle(),
            centrifugal_n: p.centrifugal_coeff * radius,
            centre_radius_m: radius,
            ring_force: fm * e.inner.unit * e.inner.load_n,
            ring_stiffness,
            residual_n: residual,
            iterations,
        }
    };
    if p.centrifugal_coeff == 0.0 && gap <= 0.0 {
        // A loose ball at rest: it touches neither race with force (its position along
        // the line of centres is undetermined; put it midway).
        let x = along * (geom.outer_offset_m + 0.5 * gap);
        let e = problem.eval(&x);
        return Ok(finish(x, e, 0.0, 0));
    }
    // A ball the inner race does not reach rests on the outer race alone (see
    // [`OuterAlone`]): accepted when the inner contact is open there. Only the inner
    // deflection |(I − O') − X| − (f_i − ½)D is formed for the test (as `eval` forms it),
    // the whole evaluation only for a ball that passes.
    if let Some(alone) = alone {
        let x = alone.position;
        if alone.approach_m > 0.0 && (centres - x).norm() - geom.inner_offset_m <= 0.0 {
            let e = problem.eval(&x);
            let residual = e.f.amax();
            return Ok(finish(x, e, residual, 0));
        }
    }
    // Start on the line of centres with the overlap shared between the contacts; when the
    // races do not reach each other (gap ≤ 0) the centrifugal force presses the ball on the
    // outer race alone: start there, radially, with the Hertz approach F_c gives.
    let mut x = warm.unwrap_or_else(|| {
        if gap > 1e-9 * geom.ball_diameter_m {
            along * (geom.outer_offset_m + 0.5 * gap)
        } else {
            let fc = p.centrifugal_coeff * (geom.outer_centre_radius_m + geom.outer_offset_m);
            let approach = (fc / p.outer_stiffness).powf(2.0 / 3.0);
            Vector2::new(
                0.0,
                geom.outer_offset_m + approach.max(1e-9 * geom.ball_diameter_m),
            )
        }
    });
    let newton = Newton {
        max_iterations: 100,
        tolerance: tolerance_n,
        trust: TrustRegion::new(1e-5, 1e-15, 1e-3),
        line_search: Backtracking::default(),
    };
    let mut sys = problem;
    let mut run = |x: &mut Vector2<f64>| {
        let r = newton.solve(&mut sys, x);
        match r.termination {
            Termination::Converged {
                iterations,
                residual,
            } => Ok(finish(*x, r.eval, residual, iterations)),
            // The line search found no decrease: accepted only when the residual is at the
            // round-off level of the forces that make it (1e-12 of Q_i + Q_o + F_c).
            Termination::Stalled {
                iterations,
                residual,
            } if residual
                <= 1e-12
                    * (r.eval.inner.load_n
                        + r.eval.outer.load_n
                        + p.centrifugal_coeff * (geom.outer_centre_radius_m + x[1])) =>
            {
                Ok(finish(*x, r.eval, residual, iterations))
            }
            t => Err(BallError::BallNotConverged {
                ball,
                reason: reason(&t),
                iterations: t.iterations(),
                residual_n: r.eval.f.amax(),
                tolerance_n,
            }),
        }
    };
    let first = match run(&mut x) {
        Ok(b) => return Ok(b),
        Err(e) => e,
    };
    // A loose ball (gap ≤ 0) held by a small centrifugal force, whose outer-race-alone
    // position the inner race blocks: it is wedged between the two grooves with loads of
    // the order of F_c (micronewtons at the skid search's lowest speeds). From a start a
    // few nanometres off the wedge, Newton crawls: the inner contact is open there, the
    // outer contact's tangential stiffness Q_o/L_o is ~0.04 N/m, and a step that closes the
    // inner contact by more than ~1e-11 m overshoots the residual, so the trust radius
    // stays below 1e-9 m (issue 16: ball 9 of Bearing B, force-held preload, 500 N radial,
    // ω_i = 0.10 rad/s, 100 iterations closed 5.4 of the 8.0 nm). Retried once from the
    // wedge itself ([`wedged_start`]); only after a failure, so that every answer the
    // first attempt gives is unchanged.
    match wedged_start(geom, centres, &p, gap) {
        Some(mut x) => run(&mut x).map_err(|_| first),
        None => Err(first),
    }
}

/// The position of a loose ball (gap ≤ 0) wedged between the grooves by its centrifugal
/// force: the outer intersection of the circles |X| = (f_o − ½)D + δ_o and
/// |(I − O') − X| = (f_i − ½)D + δ_i, with δ = (Q/K)^{2/3} of the loads that balance
/// F_c at the rigid wedge through (2-5a, b), (I + µR)(Q_i u_i − Q_o u_o) = −F_c e_r (two
/// passes: the loads at the rigid wedge, then at the wedge they deflect). `None` when the
/// circles do not meet, the balance needs a negative (tensile) load, or there is no
/// centrifugal force: then there is no wedged equilibrium to start from.
fn wedged_start(
    geom: &BallGeometry,
    centres: Vector2<f64>,
    p: &BallParams,
    gap: f64,
) -> Option<Vector2<f64>> {
    // (Written so that a NaN gap or coefficient, too, gives None.)
    (gap <= 0.0 && p.centrifugal_coeff > 0.0).then_some(())?;
    let d = centres.norm();
    let e = centres / d;
    // The normal of the line of centres pointing outwards (radially).
    let n = if e[0] >= 0.0 {
        Vector2::new(-e[1], e[0])
    } else {
        Vector2::new(e[1], -e[0])
    };
    // The outer intersection of the circles about O' and I − O' of radii r_o, r_i.
    let wedge = |d_i: f64, d_o: f64| {
        let (r_o, r_i) = (geom.outer_offset_m + d_o, geom.inner_offset_m + d_i);
        let a = (d * d + r_o * r_o - r_i * r_i) / (2.0 * d);
        let h2 = r_o * r_o - a * a;
        (h2 > 0.0).then(|| e * a + n * h2.sqrt())
    };
    let fm = friction_matrix(p.friction);
    let mut x = wedge(0.0, 0.0)?;
    for _ in 0..2 {
        let u_o = x / x.norm();
        let u_i = (centres - x) / (centres - x).norm();
        let m = fm * Matrix2::from_columns(&[u_i, -u_o]);
        let fc = p.centrifugal_coeff * (geom.outer_centre_radius_m + x[1]);
        let q = m.try_inverse()? * Vector2::new(0.0, -fc);
        (q[0] > 0.0 && q[1] > 0.0).then_some(())?;
        x = wedge(
            (q[0] / p.inner_stiffness).powf(2.0 / 3.0),
            (q[1] / p.outer_stiffness).powf(2.0 / 3.0),
        )?;
    }
    Some(x)
}

/// How the inner ring is held axially during a load solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Axial {
    /// The axial force F_a (N) is given.
    Force(f64),
    /// The axial displacement δ_a (m) is given.
    Displacement(f64),
}

/// Everything that defines one load solve besides the geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    /// Ω_i, rad/s.
    pub inner_speed_rad_s: f64,
    /// Ω_o, rad/s.
    pub outer_speed_rad_s: f64,
    /// Axial condition.
    pub axial: Axial,
    /// F_r, N (towards ψ = 0).
    pub radial_load_n: f64,
    /// Race control.
    pub race_control: RaceControl,
    /// Gyroscopic friction sign.
    pub gyroscopic_friction: GyroscopicFriction,
    /// The largest traction coefficient the contacts can give (µ_m of the traction
    /// curve): the gyroscopic friction of 2-7 is capped at it. Beyond, the friction
    /// cannot hold the ball's precession and the ball skids (the skidding condition 2-4);
    /// `f64::INFINITY` applies 2-7 without a cap, as the seed does.
    pub max_friction: f64,
}

/// One ball of the solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallLoad {
    /// ψ, azimuth, rad.
    pub azimuth_rad: f64,
    /// Equilibrium.
    pub equilibrium: BallEquilibrium,
    /// Race-control kinematics at the equilibrium angles.
    pub kinematics: RaceKinematics,
    /// M_g = J ω_m ω_r, N·m.
    pub gyroscopic_moment_nm: f64,
    /// |µ| needed to resist M_g (2-7).
    pub friction_needed: f64,
}

/// Work counters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LoadStats {
    /// Fixed-point iterations (load ↔ kinematics).
    pub fixed_point_iterations: usize,
    /// Ring Newton iterations, summed.
    pub ring_iterations: usize,
    /// Ring evaluations (each solves every distinct ball), summed.
    pub ring_evaluations: usize,
}

/// The solved load distribution.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDistribution {
    /// δ_a, m.
    pub axial_deflection_m: f64,
    /// δ_r, m.
    pub radial_deflection_m: f64,
    /// ΣP_a, the axial force the balls carry, N.
    pub axial_force_n: f64,
    /// ΣP_r cos ψ, N.
    pub radial_force_n: f64,
    /// Balls in azimuth order (ψ_j = 2πj/Z).
    pub balls: Vec<BallLoad>,
    /// Largest ring-force residual, N (0 for a held displacement).
    pub ring_residual_n: f64,
    /// Largest ball-force residual, N.
    pub ball_residual_n: f64,
    /// Work counters.
    pub stats: LoadStats,
}

/// Which balls a load solve computes, and which balls each of them stands for.
///
/// With no radial load every ball is the same: ball 0 is solved for all (weights Z,
/// Σcos ψ, Σcos² ψ). Under a radial load towards ψ = 0 (and no tilt: the model has none)
/// the inner groove centre of the ball at ψ sits at (A sin α₀ + δ_a, A cos α₀ + δ_r cos ψ),
/// which depends on ψ through cos ψ alone, and so does everything else of the ball (its
/// angles, loads, radius, hence its stiffness, kinematics and friction): the balls at ψ
/// and −ψ (j and Z − j) are mirror images with the same answer. Balls 0 … ⌊Z/2⌋ are
/// solved, each standing for itself and its mirror (weight 2, or 1 for ψ = 0 and, Z even,
/// ψ = π). This is exact, not an approximation: it leaves out the rounding differences
/// between cos(2πj/Z) and cos(2π(Z − j)/Z) only (test
/// `mirror_symmetry_equals_the_full_solve`).
struct Layout {
    /// cos ψ of each distinct ball (ball index k = its place here).
    cos: Vec<f64>,
    /// (Σ1, Σcos ψ, Σcos² ψ) over the balls each distinct ball stands for.
    weights: Vec<(f64, f64, f64)>,
    /// For every ball j of the bearing, the distinct ball that stands for it.
    of: Vec<usize>,
}

impl Layout {
    fn new(azimuths: &[f64], axisymmetric: bool, mirror: bool) -> Self {
        let z = azimuths.len();
        if axisymmetric {
            let c = azimuths.iter().map(|p| p.cos());
            let (sc, scc) = c.fold((0.0, 0.0), |(a, b), x| (a + x, b + x * x));
            return Layout {
                cos: vec![azimuths[0].cos()],
                weights: vec![(z as f64, sc, scc)],
                of: vec![0; z],
            };
        }
        let distinct = if mirror { z / 2 + 1 } else { z };
        let (mut cos, mut weights) = (Vec::with_capacity(distinct), Vec::new());
        for (k, psi) in azimuths.iter().take(distinct).enumerate() {
            let cp = psi.cos();
            let w = if !mirror || k == 0 || 2 * k == z {
                1.0
            } else {
                2.0
            };
            cos.push(cp);
            weights.push((w, w * cp, w * cp * cp));
        }
        let of = (0..z)
            .map(|j| if mirror { j.min(z - j) } else { j })
            .collect();
        Layout { cos, weights, of }
    }

    fn len(&self) -> usize {
        self.cos.len()
    }

    /// `v` (one entry per distinct ball, or more) for every ball of the bearing.
    fn expand<T: Copy>(&self, v: &[T]) -> Vec<T> {
        self.of.iter().map(|&k| v[k]).collect()
    }
}

struct RingProblem<'a> {
    geom: &'a BallGeometry,
    params: &'a [BallParams],
    alone: &'a [Option<OuterAlone>],
    layout: &'a Layout,
    axial: Axial,
    radial: Option<f64>,
    ball_tolerance: f64,
    warm: Vec<Option<Vector2<f64>>>,
    error: Option<BallError>,
}

struct RingEval {
    f: Vector2<f64>,
    j: Matrix2<f64>,
    balls: Vec<BallEquilibrium>,
    force: Vector2<f64>,
}

impl NewtonSystem<2> for RingProblem<'_> {
    type Eval = RingEval;
    fn evaluate(&mut self, x: &Vector2<f64>) -> RingEval {
        let g = self.geom;
        let a0 = g.free_contact_angle_rad;
        let n = self.layout.len();
        let mut balls = Vec::with_capacity(n);
        let mut force = Vector2::zeros();
        let mut jac = Matrix2::zeros();
        let nan = || RingEval {
            f: Vector2::new(f64::NAN, f64::NAN),
            j: Matrix2::zeros(),
            balls: Vec::new(),
            force: Vector2::zeros(),
        };
        for k in 0..n {
            let cp = self.layout.cos[k];
            let centres = Vector2::new(
                g.centre_distance_m * a0.sin() + x[0],
                g.centre_distance_m * a0.cos() + x[1] * cp,
            );
            let b = match solve_ball_with(
                g,
                centres,
                self.params[k],
                self.alone[k],
                self.warm[k],
                self.ball_tolerance,
                k,
            ) {
                Ok(b) => b,
                Err(e) => {
                    // A NaN residual: the line search rejects this trial; the error is
                    // reported only if the ring solve fails in the end.
                    self.error = Some(e);
                    return nan();
                }
            };
            self.warm[k] = Some(b.position);
            let (w, wc, wcc) = self.layout.weights[k];
            let kk = b.ring_stiffness;
            force += Vector2::new(b.ring_force[0] * w, b.ring_force[1] * wc);
            jac += Matrix2::new(
                kk[(0, 0)] * w,
                kk[(0, 1)] * wc,
                kk[(1, 0)] * wc,
                kk[(1, 1)] * wcc,
            );
            balls.push(b);
        }
        let mut f = Vector2::zeros();
        let mut j = Matrix2::zeros();
        match self.axial {
            Axial::Force(fa) => {
                f[0] = force[0] - fa;
                j[(0, 0)] = jac[(0, 0)];
                j[(0, 1)] = jac[(0, 1)];
            }
            Axial::Displacement(d) => {
                f[0] = x[0] - d;
                j[(0, 0)] = 1.0;
            }
        }
        match self.radial {
            Some(fr) => {
                f[1] = force[1] - fr;
                j[(1, 0)] = jac[(1, 0)];
                j[(1, 1)] = jac[(1, 1)];
            }
            None => {
                f[1] = x[1];
                j[(1, 1)] = 1.0;
            }
        }
        RingEval { f, j, balls, force }
    }
    fn residual<'e>(&self, e: &'e RingEval) -> &'e Vector2<f64> {
        &e.f
    }
    fn jacobian<'e>(&self, e: &'e RingEval) -> &'e Matrix2<f64> {
        &e.j
    }
}

/// A first axial displacement for a force-held ring: the approach that puts F_a/(Z sin α₀)
/// on each ball (or F_a/Z at α₀ = 0), turned into δ_a through the geometry.
fn axial_guess(geom: &BallGeometry, fa: f64, stiff: (f64, f64)) -> f64 {
    let z = geom.ball_count as f64;
    let a0 = geom.free_contact_angle_rad;
    let q = (fa.abs() / (z * a0.sin().max(0.1))).max(1e-3);
    let total = (q / stiff.0).powf(2.0 / 3.0) + (q / stiff.1).powf(2.0 / 3.0);
    let a = geom.centre_distance_m;
    let ac = a * a0.cos();
    ((a + total).powi(2) - ac * ac).sqrt() - a * a0.sin()
}

/// The state a load solve starts from and leaves: ring displacement, ball positions,
/// contact angles, loads and ball-centre radii (for warm starts along a continuation).
#[derive(Debug, Clone, PartialEq)]
struct Warm {
    x: Vector2<f64>,
    balls: Vec<Option<Vector2<f64>>>,
    angles: Vec<(f64, f64)>,
    loads: Vec<(f64, f64)>,
    radii: Vec<f64>,
}

/// Solve the load distribution with race-control kinematics to a fixed point.
///
/// Newton from the unloaded geometry usually converges. When it does not (a preload held
/// as a force under a large radial load at high speed: the inner contacts of some balls
/// open), the solve is continued from rest: speed and radial load are raised from zero to
/// their values in adaptive steps, each warm-started from the last; if a step cannot be
/// made smaller than 1/1000 of the way, the first error is returned.
pub fn solve(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
) -> Result<LoadDistribution, BallError> {
    solve_recorded(geom, cond, cancel, &mut None, true)
}

/// One fixed-point iteration of the load distribution as the workbench's stepper shows it
/// for one ball: the ring Newton's answer for that iteration and the ball's contact state
/// it produced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadStep {
    /// Fixed-point iteration (1-based), counted over every continuation stage.
    pub fixed_point: usize,
    /// Ring Newton iterations of this fixed-point iteration.
    pub ring_iterations: usize,
    /// Ring displacement (axial, radial), m.
    pub ring_m: [f64; 2],
    /// The ring Newton's final force residual, N.
    pub ring_residual_n: f64,
    /// The ball's contact angles (inner, outer), rad.
    pub angles_rad: [f64; 2],
    /// The ball's contact loads (inner, outer), N.
    pub loads_n: [f64; 2],
    /// The friction coefficient of (2-7) this iteration was solved with.
    pub friction: f64,
    /// Largest change of any ball's contact angle over the iteration, rad.
    pub angle_change_rad: f64,
    /// Largest relative change of any ball's contact loads.
    pub load_change: f64,
}

/// [`solve`], recording each fixed-point iteration of ball `ball` (0-based) for the
/// stepper.
pub fn solve_traced(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    ball: usize,
) -> Result<(LoadDistribution, Vec<LoadStep>), BallError> {
    let mut trace = Some((ball, Vec::new()));
    let l = solve_recorded(geom, cond, cancel, &mut trace, true)?;
    Ok((l, trace.map(|t| t.1).unwrap_or_default()))
}

/// `mirror`: solve the balls at ψ ≤ π only under a radial load ([`Layout`]); always true
/// but in the test that proves it exact.
fn solve_recorded(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    trace: &mut Option<(usize, Vec<LoadStep>)>,
    mirror: bool,
) -> Result<LoadDistribution, BallError> {
    let first = match solve_warm(geom, cond, cancel, None, trace, mirror) {
        Ok((l, _)) => return Ok(l),
        Err(
            e @ (BallError::Cancelled
            | BallError::InvalidInput(_)
            | BallError::Contact { .. }
            | BallError::SingularKinematics { .. }),
        ) => return Err(e),
        Err(e) => e,
    };
    let at = |s: f64| Conditions {
        inner_speed_rad_s: cond.inner_speed_rad_s * s,
        outer_speed_rad_s: cond.outer_speed_rad_s * s,
        radial_load_n: cond.radial_load_n * s,
        ..*cond
    };
    // Rest, axial load only (always axisymmetric); then the way up.
    let (mut done, mut state) = match solve_warm(geom, &at(0.0), cancel, None, trace, mirror) {
        Ok(r) => r,
        Err(_) => return Err(first),
    };
    let mut stats = done.stats;
    let (mut s, mut h) = (0.0f64, 0.25f64);
    while s < 1.0 {
        let next = (s + h).min(1.0);
        match solve_warm(geom, &at(next), cancel, Some(&state), trace, mirror) {
            Ok((l, w)) => {
                stats.fixed_point_iterations += l.stats.fixed_point_iterations;
                stats.ring_iterations += l.stats.ring_iterations;
                stats.ring_evaluations += l.stats.ring_evaluations;
                done = l;
                state = w;
                s = next;
                h = (2.0 * h).min(0.5);
            }
            Err(BallError::Cancelled) => return Err(BallError::Cancelled),
            Err(_) => {
                h *= 0.25;
                if h < 1e-3 {
                    return Err(first);
                }
            }
        }
    }
    done.stats = stats;
    Ok(done)
}

fn solve_warm(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    start: Option<&Warm>,
    trace: &mut Option<(usize, Vec<LoadStep>)>,
    mirror: bool,
) -> Result<(LoadDistribution, Warm), BallError> {
    let z = geom.ball_count;
    let a0 = geom.free_contact_angle_rad;
    let axisymmetric = cond.radial_load_n == 0.0;
    let azimuths: Vec<f64> = (0..z)
        .map(|j| 2.0 * std::f64::consts::PI * j as f64 / z as f64)
        .collect();
    let sign = match cond.gyroscopic_friction {
        GyroscopicFriction::Resisting => 1.0,
        GyroscopicFriction::SeedSign => -1.0,
    };
    let layout = Layout::new(&azimuths, axisymmetric, mirror);
    // Initial state: free angles, no load, kinematics at the free angle on the pitch circle.
    let mut angles = start.map_or_else(|| vec![(a0, a0); z], |w| w.angles.clone());
    let mut loads = start.map_or_else(|| vec![(0.0, 0.0); z], |w| w.loads.clone());
    let mut radii = start.map_or_else(|| vec![0.5 * geom.pitch_diameter_m; z], |w| w.radii.clone());
    let stiff0 = (
        geom.contact(Race::Inner, a0)?.stiffness_n_per_m1_5(),
        geom.contact(Race::Outer, a0)?.stiffness_n_per_m1_5(),
    );
    let wm_est = 0.5 * (cond.inner_speed_rad_s.abs() + cond.outer_speed_rad_s.abs());
    let f_ref = cond
        .radial_load_n
        .abs()
        .max(match cond.axial {
            Axial::Force(f) => f.abs(),
            // The load the held displacement puts on the balls (both contacts in series,
            // on the line of centres).
            Axial::Displacement(d) => {
                let a = geom.centre_distance_m;
                let overlap = (a * a0.sin() + d).hypot(a * a0.cos()) - a;
                let k = (stiff0.0.powf(-2.0 / 3.0) + stiff0.1.powf(-2.0 / 3.0)).powf(-1.5);
                z as f64 * k * overlap.max(0.0).powf(1.5)
            }
        })
        .max(z as f64 * geom.ball_mass_kg * wm_est * wm_est * 0.5 * geom.pitch_diameter_m)
        .max(1.0);
    let ball_tolerance = 1e-11 * f_ref / z as f64;
    let ring_tolerance = 1e-10 * f_ref;
    let mut x = match start {
        Some(w) => w.x,
        None => Vector2::new(
            match cond.axial {
                Axial::Force(fa) => axial_guess(geom, fa, stiff0),
                Axial::Displacement(d) => d,
            },
            0.0,
        ),
    };
    if let Axial::Displacement(d) = cond.axial {
        x[0] = d;
    }
    if axisymmetric {
        x[1] = 0.0;
    }
    let mut warm: Vec<Option<Vector2<f64>>> =
        start.map_or_else(|| vec![None; z], |w| w.balls.clone());
    let mut stats = LoadStats::default();
    // Each distinct ball's Hertz contacts of the last fixed-point iteration.
    let mut contacts: Vec<Option<(HertzPointContact, HertzPointContact)>> =
        vec![None; layout.len()];
    const MAX_FIXED_POINT: usize = 200;
    let mut change = f64::INFINITY;
    for it in 0..MAX_FIXED_POINT {
        if cancel.is_cancelled() {
            return Err(BallError::Cancelled);
        }
        let n = layout.len();
        let mut params = Vec::with_capacity(n);
        let mut last: Option<((f64, f64), (HertzPointContact, HertzPointContact))> = None;
        for k in 0..n {
            let (ai, ao) = angles[k];
            // The Hertz contacts at this iteration's angles. The same angles as the last
            // ball's (every ball of a fresh solve starts at α₀): the same contacts.
            // Otherwise the κ iteration starts from this ball's κ of the last fixed-point
            // iteration (or the last ball's): the same contact to round-off, in one or
            // two Newton steps instead of five or six (`EllipseShape::solve_near`).
            let (ci, co) = match (last, contacts[k]) {
                (Some((a, c)), _) if a == (ai, ao) => c,
                (_, Some((pi, po))) | (Some((_, (pi, po))), None) => (
                    geom.contact_near(Race::Inner, ai, &pi)?,
                    geom.contact_near(Race::Outer, ao, &po)?,
                ),
                (None, None) => (
                    geom.contact(Race::Inner, ai)?,
                    geom.contact(Race::Outer, ao)?,
                ),
            };
            contacts[k] = Some((ci, co));
            last = Some(((ai, ao), (ci, co)));
            let (qi, qo) = loads[k];
            let control = match cond.race_control {
                RaceControl::Outer => Race::Outer,
                RaceControl::Inner => Race::Inner,
                RaceControl::Auto if qi > 0.0 && qo > 0.0 => {
                    let pi = ci.solve(qi).map_err(|source| BallError::Contact {
                        race: "inner",
                        source,
                    })?;
                    let po = co.solve(qo).map_err(|source| BallError::Contact {
                        race: "outer",
                        source,
                    })?;
                    controlling_race(
                        (qi, pi.semi_major_m, ci.shape().second_kind),
                        (qo, po.semi_major_m, co.shape().second_kind),
                        ai,
                        ao,
                    )
                }
                RaceControl::Auto => Race::Outer,
            };
            let kin = race_control(
                &KinematicsInput {
                    ball_diameter_m: geom.ball_diameter_m,
                    ball_centre_radius_m: radii[k],
                    inner_angle_rad: ai,
                    outer_angle_rad: ao,
                    inner_speed_rad_s: cond.inner_speed_rad_s,
                    outer_speed_rad_s: cond.outer_speed_rad_s,
                },
                control,
            )?;
            let mg = kin.gyroscopic_moment_nm(geom.ball_inertia_kg_m2);
            let friction = if qi + qo > 0.0 {
                sign * (2.0 * mg / (geom.ball_diameter_m * (qi + qo)))
                    .clamp(-cond.max_friction, cond.max_friction)
            } else {
                0.0
            };
            params.push(BallParams {
                friction,
                centrifugal_coeff: geom.ball_mass_kg * kin.cage_rad_s * kin.cage_rad_s,
                inner_stiffness: ci.stiffness_n_per_m1_5(),
                outer_stiffness: co.stiffness_n_per_m1_5(),
            });
        }
        let alone: Vec<Option<OuterAlone>> =
            params.iter().map(|p| OuterAlone::new(geom, p)).collect();
        let mut ring = RingProblem {
            geom,
            params: &params,
            alone: &alone,
            layout: &layout,
            axial: cond.axial,
            radial: if axisymmetric {
                None
            } else {
                Some(cond.radial_load_n)
            },
            ball_tolerance,
            warm: std::mem::take(&mut warm),
            error: None,
        };
        let newton = Newton {
            max_iterations: 100,
            tolerance: ring_tolerance,
            trust: TrustRegion::new(1e-5, 1e-15, 1e-3),
            line_search: Backtracking::default(),
        };
        let r = newton.solve(&mut ring, &mut x);
        stats.ring_iterations += r.stats.iterations;
        stats.ring_evaluations += r.stats.evaluations;
        let ring_residual = match r.termination {
            Termination::Converged { residual, .. } => residual,
            t => {
                if let Some(e) = ring.error.take() {
                    return Err(e);
                }
                return Err(BallError::RingNotConverged {
                    reason: reason(&t),
                    iterations: t.iterations(),
                    residual_n: r.eval.f.amax(),
                    tolerance_n: ring_tolerance,
                });
            }
        };
        warm = ring.warm;
        let balls = &r.eval.balls;
        // Converged when the angles (hence stiffness and kinematics) and the loads (hence
        // µ of 2-7) are those this solve was made with.
        change = 0.0;
        let mut load_change: f64 = 0.0;
        for (k, b) in balls.iter().enumerate() {
            change = change
                .max((b.inner.angle_rad - angles[k].0).abs())
                .max((b.outer.angle_rad - angles[k].1).abs());
            let s = (b.inner.load_n + b.outer.load_n).max(1e-300);
            load_change = load_change
                .max((b.inner.load_n - loads[k].0).abs() / s)
                .max((b.outer.load_n - loads[k].1).abs() / s);
            // Plain substitution first; under-relaxed (½) after 30 iterations, for the
            // strongly coupled cases (high speed, soft contacts) where it oscillates.
            let w = if it < 30 { 1.0 } else { 0.5 };
            let mix = |old: f64, new: f64| old + w * (new - old);
            angles[k] = (
                mix(angles[k].0, b.inner.angle_rad),
                mix(angles[k].1, b.outer.angle_rad),
            );
            loads[k] = (
                mix(loads[k].0, b.inner.load_n),
                mix(loads[k].1, b.outer.load_n),
            );
            radii[k] = mix(radii[k], b.centre_radius_m);
        }
        stats.fixed_point_iterations = it + 1;
        if let Some((ball, steps)) = trace.as_mut() {
            // The distinct ball that stands for this one (ball 0 for all when axisymmetric).
            let k = layout.of[(*ball).min(z.saturating_sub(1))];
            if let (Some(b), Some(p)) = (balls.get(k), params.get(k)) {
                steps.push(LoadStep {
                    fixed_point: steps.last().map_or(1, |s: &LoadStep| s.fixed_point + 1),
                    ring_iterations: r.stats.iterations,
                    ring_m: [x[0], x[1]],
                    ring_residual_n: ring_residual,
                    angles_rad: [b.inner.angle_rad, b.outer.angle_rad],
                    loads_n: [b.inner.load_n, b.outer.load_n],
                    friction: p.friction,
                    angle_change_rad: change,
                    load_change,
                });
            }
        }
        if it > 0 && change < 1e-12 && load_change < 1e-10 {
            let l = finish(
                geom,
                cond,
                &azimuths,
                &layout,
                balls,
                x,
                r.eval.force,
                ring_residual,
                stats,
            )?;
            // Warm state for every ball, each from the distinct ball standing for it.
            let w = Warm {
                x,
                balls: layout.expand(&warm),
                angles: layout.expand(&angles),
                loads: layout.expand(&loads),
                radii: layout.expand(&radii),
            };
            return Ok((l, w));
        }
    }
    Err(BallError::FixedPointNotConverged {
        iterations: MAX_FIXED_POINT,
        change,
    })
}

#[allow(clippy::too_many_arguments)]
fn finish(
    geom: &BallGeometry,
    cond: &Conditions,
    azimuths: &[f64],
    layout: &Layout,
    balls: &[BallEquilibrium],
    x: Vector2<f64>,
    force: Vector2<f64>,
    ring_residual: f64,
    stats: LoadStats,
) -> Result<LoadDistribution, BallError> {
    // Race control of each distinct ball, then every ball from the one standing for it.
    let mut distinct = Vec::with_capacity(balls.len());
    let mut ball_residual: f64 = 0.0;
    for &b in balls {
        ball_residual = ball_residual.max(b.residual_n);
        let (ai, ao) = (b.inner.angle_rad, b.outer.angle_rad);
        let control = match cond.race_control {
            RaceControl::Outer => Race::Outer,
            RaceControl::Inner => Race::Inner,
            RaceControl::Auto => {
                let ci = geom.contact(Race::Inner, ai)?;
                let co = geom.contact(Race::Outer, ao)?;
                let semi = |c: &HertzPointContact, q: f64| {
                    c.solve(q).map(|p| p.semi_major_m).unwrap_or(0.0)
                };
                controlling_race(
                    (
                        b.inner.load_n,
                        semi(&ci, b.inner.load_n),
                        ci.shape().second_kind,
                    ),
                    (
                        b.outer.load_n,
                        semi(&co, b.outer.load_n),
                        co.shape().second_kind,
                    ),
                    ai,
                    ao,
                )
            }
        };
        let kin = race_control(
            &KinematicsInput {
                ball_diameter_m: geom.ball_diameter_m,
                ball_centre_radius_m: b.centre_radius_m,
                inner_angle_rad: ai,
                outer_angle_rad: ao,
                inner_speed_rad_s: cond.inner_speed_rad_s,
                outer_speed_rad_s: cond.outer_speed_rad_s,
            },
            control,
        )?;
        let mg = kin.gyroscopic_moment_nm(geom.ball_inertia_kg_m2);
        let s = b.inner.load_n + b.outer.load_n;
        distinct.push(BallLoad {
            azimuth_rad: f64::NAN,
            equilibrium: b,
            kinematics: kin,
            gyroscopic_moment_nm: mg,
            friction_needed: if s > 0.0 {
                2.0 * mg.abs() / (geom.ball_diameter_m * s)
            } else {
                0.0
            },
        });
    }
    let out = azimuths
        .iter()
        .zip(&layout.of)
        .map(|(&psi, &k)| BallLoad {
            azimuth_rad: psi,
            ..distinct[k]
        })
        .collect();
    Ok(LoadDistribution {
        axial_deflection_m: x[0],
        radial_deflection_m: x[1],
        axial_force_n: force[0],
        radial_force_n: force[1],
        balls: out,
        ring_residual_n: ring_residual,
        ball_residual_n: ball_residual,
        stats,
    })
}

#[cfg(test)]
mod tests;
