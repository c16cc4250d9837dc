//! One ball's equilibrium (2-5a, b) at a given position of the inner groove centre: the
//! contact loads (3-1, 3-2), the ball's Newton system with its analytic Jacobian, the
//! ball resting on the outer race alone and the wedged start of a loose ball, and the
//! ring force and stiffness the ball passes up to the ring's Newton system (`problem`).
//! The innermost solve of the load distribution, apart from the ring's (`problem`) and
//! the fixed point around both (`driver`).

use nalgebra::{Matrix2, Vector2};

use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::geometry::BallGeometry;
use crate::numerics::newton::{Backtracking, Newton, NewtonSystem, Termination, TrustRegion};

/// Per-ball quantities held fixed during one load solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallParams {
    /// Signed friction coefficient µ_i of (I + µR) at the inner contact (sign: the
    /// gyroscopic convention).
    pub friction: f64,
    /// µ_o at the outer contact: equal to µ_i for the proportional split (Chen's 2-7),
    /// zero or 2M_g/(D Q_o) for the controlling-race split (Harris's λ_o = 0 or 2).
    pub outer_friction: f64,
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
        // The groove is a whole torus in this model, so that contacts past 90° (off the
        // shoulder, warned) still solve. Its far half is no ring at all: a line of centres
        // turned past 135° from the race's radial direction (cos α < cos 135°) meets the
        // torus on the side facing away from the ring. It happens under a pure radial
        // load with a large play (issue 29: Bearing B's 60° play, F_a = 0, at speed):
        // opposite the load the inner groove centre passes radially inside the outer one,
        // and the ball flung outwards would "touch" the inner torus at ~180°. Such a
        // contact is open. The cut sits between the largest angle the model has given a
        // loaded contact (121.4°, Bearing B force-held under 500 N radial at 9 500 rpm,
        // docs/ball.md, warned) and the phantom's 180°; no case that solved before has a
        // contact beyond it, so no answer moves (json-diff of that case: none).
        let d = if unit[1] < -std::f64::consts::FRAC_1_SQRT_2 {
            0.0
        } else {
            deflection.max(0.0)
        };
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
    /// dQ_i/d(I − O'), N/m (the ball's position following through its equilibrium).
    pub inner_load_gradient: Vector2<f64>,
    /// Largest force residual, N.
    pub residual_n: f64,
    /// Newton iterations.
    pub iterations: usize,
}

pub(super) struct BallProblem<'a> {
    pub(super) geom: &'a BallGeometry,
    pub(super) centres: Vector2<f64>,
    pub(super) p: BallParams,
}

pub(super) struct BallEval {
    pub(super) f: Vector2<f64>,
    pub(super) j: Matrix2<f64>,
    pub(super) inner: ContactLoad,
    pub(super) outer: ContactLoad,
}

impl BallProblem<'_> {
    pub(super) fn eval(&self, x: &Vector2<f64>) -> BallEval {
        let g = self.geom;
        let outer = ContactLoad::new(*x, g.outer_offset_m, self.p.outer_stiffness);
        let inner = ContactLoad::new(self.centres - x, g.inner_offset_m, self.p.inner_stiffness);
        let fm = friction_matrix(self.p.friction);
        let c = self.p.centrifugal_coeff;
        let radial = Vector2::new(0.0, c * (g.outer_centre_radius_m + x[1]));
        let (f, j) = if self.p.outer_friction == self.p.friction {
            // One µ at both contacts (Chen's split): written as before the split existed,
            // so that its answers do not move by a rounding.
            (
                fm * (inner.unit * inner.load_n - outer.unit * outer.load_n) + radial,
                -(fm * (inner.g() + outer.g())) + Matrix2::new(0.0, 0.0, 0.0, c),
            )
        } else {
            let fo = friction_matrix(self.p.outer_friction);
            (
                fm * inner.unit * inner.load_n - fo * outer.unit * outer.load_n + radial,
                -(fm * inner.g() + fo * outer.g()) + Matrix2::new(0.0, 0.0, 0.0, c),
            )
        };
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
pub(super) fn reason(t: &Termination) -> &'static str {
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
        let inv = friction_matrix(p.outer_friction).try_inverse()?;
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
        let mo = friction_matrix(p.outer_friction) * e.outer.g();
        let jb = -(mi + mo) + Matrix2::new(0.0, 0.0, 0.0, p.centrifugal_coeff);
        // dv/dc = I + J_b⁻¹ M_i (v = c − X, dX/dc = −J_b⁻¹ M_i by the implicit function
        // theorem on the ball residual): the ring stiffness M_i·dv/dc and the gradient of
        // the inner load dQ_i/dc = Q_i' u_iᵀ dv/dc (the tilt's friction couple needs it).
        let (ring_stiffness, inner_load_gradient) = match jb.try_inverse() {
            Some(inv) => {
                let dv = Matrix2::identity() + inv * mi;
                (
                    mi * dv,
                    (e.inner.unit.transpose() * dv).transpose() * e.inner.stiffness_n_per_m,
                )
            }
            None => (Matrix2::zeros(), Vector2::zeros()),
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
            inner_load_gradient,
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
    let fo = friction_matrix(p.outer_friction);
    let mut x = wedge(0.0, 0.0)?;
    for _ in 0..2 {
        let u_o = x / x.norm();
        let u_i = (centres - x) / (centres - x).norm();
        let m = if p.outer_friction == p.friction {
            fm * Matrix2::from_columns(&[u_i, -u_o])
        } else {
            Matrix2::from_columns(&[fm * u_i, -(fo * u_o)])
        };
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
