//! One solved tapered roller case: the equilibrium, the stiffness as the deck asks for
//! it, and each roller's slices at the solution.

use super::bearing::{asymmetry, fd_difference, Bearing, BearingError, BearingSolution, Matrix5};
use super::contact::SliceResult;
use super::input::{StiffnessMethod, TaperedInput};
use crate::bearings::stiffness::{Dof, Method, StiffnessMatrix};

/// Stiffness rows and columns (x, y, z, θx, θy).
pub const AXES: [&str; 5] = ["x", "y", "z", "theta_x", "theta_y"];

/// A solved case, SI.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The deck's name.
    pub name: String,
    /// The prepared bearing (input, geometry, speeds).
    pub bearing: Bearing,
    /// The equilibrium.
    pub solution: BearingSolution,
    /// The reported stiffness (analytic, or by differences when the deck asks only for
    /// those).
    pub stiffness: Matrix5,
    /// The stiffness by differences of re-solved equilibria, when computed.
    pub stiffness_fd: Option<Matrix5>,
    /// Per roller, the cup and cone slices at the solution.
    pub slices: Vec<[Vec<SliceResult>; 2]>,
    /// Wall time of the solve, s.
    pub wall_time_s: f64,
    /// Film, Λ and friction by mechanism (issue 28 items 3–4): `None` without a lubricant.
    pub tribology: Option<Result<super::tribology::Tribology, super::tribology::TribologyError>>,
    /// The thermal network's answer, when the deck has a `[thermal]` and a lubricant.
    pub thermal: Option<Result<super::thermal::ThermalOut, String>>,
    /// True when the equilibrium started from a session's last one (its iteration counts
    /// are then those from there: 0 when the deck is the last one solved).
    pub warm_started: bool,
}

impl Analysis {
    /// Largest asymmetry |K_ij − K_ji| of the reported matrix, scaled (see
    /// [`super::bearing::asymmetry`]).
    pub fn asymmetry_max(&self) -> f64 {
        asymmetry(&self.stiffness, self.bearing.geometry.moment_radius_m)
    }

    /// The load centre's axial offset from the reference point, m: the a that removes
    /// the lineal–angular coupling, a = (K_xθy + K_yθx)/(K_xx + K_yy), in the seed's sign
    /// convention for θ (eq. 40: θy adds R_m·θy·cos φ to the roller approach where δx adds
    /// cos β·δx·cos φ). Were the cup loads alone to act, a would be R_m/cos β, where the
    /// cup's contact normals cross the bearing axis; the contact moments move it a little.
    /// `None` without lateral stiffness.
    pub fn load_centre_offset_m(&self) -> Option<f64> {
        let k = &self.stiffness;
        let den = k[(0, 0)] + k[(1, 1)];
        (den > 0.0).then(|| (k[(0, 4)] + k[(1, 3)]) / den)
    }

    /// The effective support stiffness with the deck's pedestal in series, seed 004
    /// eq. (9): K_eff = (K_b⁻¹ + K_p⁻¹)⁻¹ with K_p = diag(k_x, k_y, k_z, k_θx, k_θy) and a
    /// rigid coordinate (k = 0 in the deck) adding no compliance. `None` when the pedestal
    /// is rigid throughout; an error when the bearing's matrix cannot be inverted (a
    /// coordinate it does not restrain, so the series combination is undefined).
    pub fn stiffness_with_pedestal(&self) -> Option<Result<Matrix5, String>> {
        let p = &self.bearing.input.pedestal;
        if !p.is_compliant() {
            return None;
        }
        let Some(cb) = self.stiffness.try_inverse() else {
            return Some(Err(
                "the bearing's 5×5 stiffness is singular: the series combination with the pedestal (eq. 9) is undefined".to_string(),
            ));
        };
        let mut c = cb;
        for (i, &k) in p.stiffness.iter().enumerate() {
            if k > 0.0 {
                c[(i, i)] += 1.0 / k;
            }
        }
        Some(
            c.try_inverse()
                .ok_or_else(|| "the combined compliance is singular (eq. 9)".to_string()),
        )
    }

    /// The stiffness referred to the load centre: K′ = TᵀKT with δx_O = δx_C − a·θy and
    /// δy_O = δy_C − a·θx (T = I but T₀₄ = T₁₃ = −a), the change of reference point of a
    /// rigid ring's small motion; K′_xθy = K_xθy − a·K_xx vanishes by the choice of a.
    pub fn stiffness_at_load_centre(&self) -> Option<Matrix5> {
        let a = self.load_centre_offset_m()?;
        let mut t = Matrix5::identity();
        t[(0, 4)] = -a;
        t[(1, 3)] = -a;
        Some(t.transpose() * self.stiffness * t)
    }

    /// The reported stiffness as the shared type (its JSON `stiffness` keys and text
    /// block): the 5×5 over (x, y, z, θx, θy) at the seed's reference point, with the
    /// finite-difference matrix and gap when computed.
    pub fn stiffness_matrix(&self) -> StiffnessMatrix {
        let flat = |m: &Matrix5| -> Vec<f64> {
            (0..5)
                .flat_map(|i| (0..5).map(move |j| m[(i, j)]))
                .collect()
        };
        let method = match self.bearing.input.solver.stiffness {
            StiffnessMethod::Analytic => Method::Analytic,
            StiffnessMethod::FiniteDifference => Method::FiniteDifference,
            StiffnessMethod::Both => Method::Both,
        };
        let mut k = StiffnessMatrix::new(Dof::ALL.to_vec(), flat(&self.stiffness), method);
        k.reference_point = Some(
            "cone centre at the rollers' central plane (the seed's ring reference point)"
                .to_string(),
        );
        k.asymmetry_max = Some(self.asymmetry_max());
        k.fd = self.stiffness_fd.as_ref().map(flat);
        k.fd_max_rel = self.finite_difference_max_rel();
        k
    }

    /// Largest analytic–difference gap over each row's scale, when both exist.
    pub fn finite_difference_max_rel(&self) -> Option<f64> {
        self.stiffness_fd.map(|fd| {
            fd_difference(
                &self.solution.stiffness,
                &fd,
                self.bearing.geometry.moment_radius_m,
            )
        })
    }
}

/// Solve `input` (named `name`).
pub fn analyse(input: &TaperedInput, name: &str) -> Result<Analysis, BearingError> {
    analyse_from(input, name, None)
}

/// Solve `input` (named `name`) with the bearing equilibrium started from `start` (a
/// neighbouring solution: a previous point of a sweep, the workbench's last solve), and
/// from the cold pure-thrust start if that fails. Either way Newton stops on the same
/// force tolerance, so the answer equals the cold start's to that tolerance
/// (test `session_warm_start_equals_cold_start`).
pub fn analyse_from(
    input: &TaperedInput,
    name: &str,
    start: Option<&BearingSolution>,
) -> Result<Analysis, BearingError> {
    let t0 = std::time::Instant::now();
    let bearing = Bearing::new(input)?;
    let (solution, warm_started) = match start {
        Some(st) => match bearing.solve_from(Some(st)) {
            Ok(sol) => (sol, true),
            Err(_) => (bearing.solve()?, false),
        },
        None => (bearing.solve()?, false),
    };
    let stiffness_fd = match input.solver.stiffness {
        StiffnessMethod::Analytic => None,
        _ => Some(bearing.stiffness_fd(&solution)?),
    };
    let stiffness = match (input.solver.stiffness, stiffness_fd) {
        (StiffnessMethod::FiniteDifference, Some(fd)) => fd,
        _ => solution.stiffness,
    };
    let m = &bearing.model;
    let mut slices: Vec<[Vec<SliceResult>; 2]> = Vec::with_capacity(solution.rollers.len());
    // Rollers with bit-equal approaches and misalignments (the symmetry the equilibrium
    // uses: mirror pairs, every roller under pure thrust) have the same slices: copied.
    let key = |r: &super::roller::RollerSolution| {
        [r.delta1_m, r.theta1_rad, r.delta2_m, r.theta2_rad].map(f64::to_bits)
    };
    for (q, (r, _, _)) in solution.rollers.iter().enumerate() {
        let same = solution.rollers[..q]
            .iter()
            .position(|(o, _, _)| key(o) == key(r));
        if let Some(i) = same {
            let copy = slices[i].clone();
            slices.push(copy);
            continue;
        }
        let (mut cup, mut cone) = (Vec::new(), Vec::new());
        m.cup.eval(r.delta1_m, r.theta1_rad, Some(&mut cup))?;
        m.cone.eval(r.delta2_m, r.theta2_rad, Some(&mut cone))?;
        slices.push([cup, cone]);
    }
    let mut a = Analysis {
        name: name.to_string(),
        bearing,
        solution,
        stiffness,
        stiffness_fd,
        slices,
        wall_time_s: 0.0,
        tribology: None,
        thermal: None,
        warm_started,
    };
    a.tribology = super::tribology::tribology(&a);
    a.wall_time_s = t0.elapsed().as_secs_f64();
    Ok(a)
}

#[cfg(test)]
mod pedestal_tests {
    use super::*;

    /// Seed 004 eq. (9), bearing and pedestal in series: the combined compliance is the
    /// bearing's plus the pedestal's, K_eff⁻¹ − K_b⁻¹ = diag(1/k) exactly (1e-9 of the
    /// pedestal compliance: two 5×5 inversions); a rigid coordinate (k = 0) adds nothing;
    /// a pedestal 10⁶ times stiffer than the bearing leaves K_xx within 1e-5 of the
    /// bearing's; no pedestal, no combined matrix. Under Load Condition 2 (radial load:
    /// a fully coupled matrix).
    #[test]
    fn series_combination_of_eq_9() {
        let mut input = TaperedInput::afapl_sample();
        input.operating.radial_load_n = 700.0 * crate::units::LBF_N;
        let bare = analyse(&input, "lc2").unwrap();
        assert!(bare.stiffness_with_pedestal().is_none());
        let kb = bare.stiffness;
        let p = [1e8, 2e8, 0.0, 3e5, 0.0];
        input.pedestal.stiffness = p;
        let a = analyse(&input, "lc2 + pedestal").unwrap();
        assert_eq!(a.stiffness, kb, "the bearing itself is unchanged");
        let keff = a.stiffness_with_pedestal().unwrap().unwrap();
        let added = keff.try_inverse().unwrap() - kb.try_inverse().unwrap();
        for i in 0..5 {
            for j in 0..5 {
                let want = if i == j && p[i] > 0.0 {
                    1.0 / p[i]
                } else {
                    0.0
                };
                let scale = if p[i] > 0.0 {
                    1.0 / p[i]
                } else {
                    1.0 / kb[(i, i)]
                };
                assert!(
                    (added[(i, j)] - want).abs() <= 1e-9 * scale,
                    "{i},{j}: {} vs {want}",
                    added[(i, j)]
                );
            }
        }
        // Softer than either alone in every compliant coordinate.
        assert!(keff[(0, 0)] < kb[(0, 0)] && keff[(0, 0)] < p[0]);
        input.pedestal.stiffness = [1e6 * kb[(0, 0)], 0.0, 0.0, 0.0, 0.0];
        let stiff = analyse(&input, "stiff pedestal").unwrap();
        let k = stiff.stiffness_with_pedestal().unwrap().unwrap();
        assert!((k[(0, 0)] / kb[(0, 0)] - 1.0).abs() < 1e-5);
    }
}
