//! The ring's Newton system (2-8): the ring displacement (δ_a, δ_r) as unknowns, every
//! distinct ball solved at it (`ball`), their ring forces summed against the held axial
//! force or displacement and the radial load, with the ring Jacobian from the balls'
//! stiffness; and [`Layout`], which balls a solve computes (one when axisymmetric, the
//! balls at ψ ≤ π under radial load). Apart from the fixed point that drives it
//! (`driver`).

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

use super::ball::{solve_ball_with, BallEquilibrium, BallParams, OuterAlone};
use super::Axial;
use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::geometry::BallGeometry;
use crate::numerics::newton::NewtonSystem;

/// Which balls a load solve computes, and which balls each of them stands for.
///
/// With no radial load every ball is the same: ball 0 is solved for all (weights Z,
/// Σcos ψ, Σcos² ψ). Under a radial load towards ψ = 0 (and a tilt about the axis across it)
/// the inner groove centre of the ball at ψ sits at (A sin α₀ + δ_a + θℜ_i cos ψ, A cos α₀ + δ_r cos ψ),
/// which depends on ψ through cos ψ alone, and so does everything else of the ball (its
/// angles, loads, radius, hence its stiffness, kinematics and friction): the balls at ψ
/// and −ψ (j and Z − j) are mirror images with the same answer. Balls 0 … ⌊Z/2⌋ are
/// solved, each standing for itself and its mirror (weight 2, or 1 for ψ = 0 and, Z even,
/// ψ = π). This is exact, not an approximation: it leaves out the rounding differences
/// between cos(2πj/Z) and cos(2π(Z − j)/Z) only (test
/// `mirror_symmetry_equals_the_full_solve`).
pub(super) struct Layout {
    /// cos ψ of each distinct ball (ball index k = its place here).
    pub(super) cos: Vec<f64>,
    /// (Σ1, Σcos ψ, Σcos² ψ) over the balls each distinct ball stands for.
    pub(super) weights: Vec<(f64, f64, f64)>,
    /// For every ball j of the bearing, the distinct ball that stands for it.
    pub(super) of: Vec<usize>,
}

impl Layout {
    pub(super) fn new(azimuths: &[f64], axisymmetric: bool, mirror: bool) -> Self {
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

    pub(super) fn len(&self) -> usize {
        self.cos.len()
    }

    /// `v` (one entry per distinct ball, or more) for every ball of the bearing.
    pub(super) fn expand<T: Copy>(&self, v: &[T]) -> Vec<T> {
        self.of.iter().map(|&k| v[k]).collect()
    }
}

/// How the inner ring's tilt θ (about the axis perpendicular to the radial load, positive
/// where it moves the inner groove centre at ψ = 0 towards +a) is held during a load
/// solve (issue 29).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tilt {
    /// θ is given (rad): the misalignment; 0 is the model before issue 29.
    Held(f64),
    /// The moment M (N·m) the ring carries is given; θ is solved.
    Moment(f64),
}

/// ℜ_i, the radius of the inner groove centres in the unloaded bearing, m.
pub(super) fn inner_centre_radius(g: &BallGeometry) -> f64 {
    g.outer_centre_radius_m + g.centre_distance_m * g.free_contact_angle_rad.cos()
}

pub(super) struct RingProblem<'a> {
    pub(super) geom: &'a BallGeometry,
    pub(super) params: &'a [BallParams],
    pub(super) alone: &'a [Option<OuterAlone>],
    pub(super) layout: &'a Layout,
    pub(super) axial: Axial,
    pub(super) radial: Option<f64>,
    pub(super) ball_tolerance: f64,
    pub(super) warm: Vec<Option<Vector2<f64>>>,
    pub(super) error: Option<BallError>,
    /// φ = θ·ℜ_i, m: the held tilt (NewtonSystem<2>) or the last one tried (<3>).
    pub(super) phi: f64,
    /// The moment a tilt-solving ring must carry, as a force on φ: M/ℜ_i, N.
    pub(super) moment_force: f64,
}

pub(super) struct RingEval {
    pub(super) f: Vector2<f64>,
    pub(super) j: Matrix2<f64>,
    pub(super) balls: Vec<BallEquilibrium>,
    pub(super) force: Vector2<f64>,
    /// The generalised force of the balls on φ, ΣP_φ cos ψ, N (moment M = ℜ_i·this).
    pub(super) force_phi: f64,
    /// Residual and Jacobian of the three-unknown system (δ_a, δ_r, φ).
    pub(super) f3: Vector3<f64>,
    pub(super) j3: Matrix3<f64>,
}

impl RingProblem<'_> {
    /// Every distinct ball at the ring displacement (δ_a, δ_r) and tilt φ = θ·ℜ_i.
    ///
    /// The tilt (Jones–Harris; Harris & Kotzalas vol. 2 §3.3 with ℜ_i the radius of the
    /// inner groove centres) moves the inner groove centre of the ball at ψ axially by
    /// θ·ℜ_i·cos ψ; its radial move −θ·a is of the second order (a, the groove centre's
    /// axial distance from the tilt's pivot, is of the order of the deflections) and left
    /// out, as there. The centres depend on ψ through cos ψ alone, so the mirror layout
    /// stays exact. The balls' generalised force on φ, by virtual work with that map, is
    /// Σ (P_a − (f_i D/ℜ_i)·µ_i Q_i) cos ψ: the axial force at ℜ_i plus the couple the
    /// inner contact's friction makes about the groove centre (Harris's λ_i f_i M_g
    /// term; derived in `ball::BallEquilibrium::inner_load_gradient`).
    fn eval3(&mut self, x: &Vector2<f64>, phi: f64) -> Option<RingEval> {
        let g = self.geom;
        let a0 = g.free_contact_angle_rad;
        let n = self.layout.len();
        let mut balls = Vec::with_capacity(n);
        let mut force = Vector2::zeros();
        let mut jac = Matrix2::zeros();
        // ∂(force_a, force_r)/∂φ, and the φ row.
        let mut col_phi = Vector2::zeros();
        let mut force_phi = 0.0;
        let mut row_phi = Vector3::zeros();
        // f_i D / ℜ_i: the inner groove radius over the radius of the groove centres
        // (ℜ_i = R_O' + A cos α₀ = d_m/2 + (f_i − ½)D cos α₀).
        let rho = (g.inner_offset_m + 0.5 * g.ball_diameter_m) / inner_centre_radius(g);
        for k in 0..n {
            let cp = self.layout.cos[k];
            let centres = Vector2::new(
                g.centre_distance_m * a0.sin() + x[0] + phi * cp,
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
                    return None;
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
            col_phi += Vector2::new(kk[(0, 0)] * wc, kk[(1, 0)] * wcc);
            let mu = self.params[k].friction;
            let gq = b.inner_load_gradient * mu;
            force_phi += (b.ring_force[0] - rho * mu * b.inner.load_n) * wc;
            row_phi += Vector3::new(
                (kk[(0, 0)] - rho * gq[0]) * wc,
                (kk[(0, 1)] - rho * gq[1]) * wcc,
                (kk[(0, 0)] - rho * gq[0]) * wcc,
            );
            balls.push(b);
        }
        let mut f = Vector2::zeros();
        let mut j = Matrix2::zeros();
        let mut f3 = Vector3::zeros();
        let mut j3 = Matrix3::zeros();
        match self.axial {
            Axial::Force(fa) => {
                f[0] = force[0] - fa;
                j[(0, 0)] = jac[(0, 0)];
                j[(0, 1)] = jac[(0, 1)];
                j3[(0, 2)] = col_phi[0];
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
                j3[(1, 2)] = col_phi[1];
            }
            None => {
                f[1] = x[1];
                j[(1, 1)] = 1.0;
            }
        }
        j3.fixed_view_mut::<2, 2>(0, 0).copy_from(&j);
        f3[0] = f[0];
        f3[1] = f[1];
        f3[2] = force_phi - self.moment_force;
        j3[(2, 0)] = row_phi[0];
        j3[(2, 1)] = row_phi[1];
        j3[(2, 2)] = row_phi[2];
        Some(RingEval {
            f,
            j,
            balls,
            force,
            force_phi,
            f3,
            j3,
        })
    }

    fn nan() -> RingEval {
        RingEval {
            f: Vector2::new(f64::NAN, f64::NAN),
            j: Matrix2::zeros(),
            balls: Vec::new(),
            force: Vector2::zeros(),
            force_phi: f64::NAN,
            f3: Vector3::new(f64::NAN, f64::NAN, f64::NAN),
            j3: Matrix3::zeros(),
        }
    }
}

/// The ring with its tilt held (φ fixed): the two unknowns (δ_a, δ_r) as before issue 29.
/// The (a, r) entries are formed by the same arithmetic as then, and φ = 0 adds an exact
/// zero to each centre, so a held zero tilt gives every answer of before to the bit.
impl NewtonSystem<2> for RingProblem<'_> {
    type Eval = RingEval;
    fn evaluate(&mut self, x: &Vector2<f64>) -> RingEval {
        let phi = self.phi;
        self.eval3(x, phi).unwrap_or_else(Self::nan)
    }
    fn residual<'e>(&self, e: &'e RingEval) -> &'e Vector2<f64> {
        &e.f
    }
    fn jacobian<'e>(&self, e: &'e RingEval) -> &'e Matrix2<f64> {
        &e.j
    }
}

/// The ring with its tilt solved against a given moment: unknowns (δ_a, δ_r, φ).
impl NewtonSystem<3> for RingProblem<'_> {
    type Eval = RingEval;
    fn evaluate(&mut self, x: &Vector3<f64>) -> RingEval {
        self.phi = x[2];
        self.eval3(&Vector2::new(x[0], x[1]), x[2])
            .unwrap_or_else(Self::nan)
    }
    fn residual<'e>(&self, e: &'e RingEval) -> &'e Vector3<f64> {
        &e.f3
    }
    fn jacobian<'e>(&self, e: &'e RingEval) -> &'e Matrix3<f64> {
        &e.j3
    }
}
