//! The problem of one load-distribution solve: the precomputed data ([`Problem`]), one
//! roller's energy, gradient and Hessian blocks at a ring deflection (the hot loop), and the
//! per-roller results assembled at the solution (seed 000 eq. 3.3–3.11, §4.5).

use nalgebra::{Matrix2, Matrix2x3, Matrix3, Vector2, Vector3};

use super::{
    gyroscopic_moment, DynamicSpeeds, GuideContact, LaminaResult, Layout, LoadDistribution,
    RacewayContact, Residuals, RollerResult, SolveStats, TraceStep, WarmStart,
};
use crate::bearings::spherical_roller::geometry::{Approach, LaminaGeometry};
use crate::bearings::spherical_roller::roller::roller_mass;
use crate::bearings::spherical_roller::Bearing;
use crate::physics::contact::lamina_law::LaminaLaw;

/// Precomputed problem data.
pub(super) struct Problem {
    pub(super) geom: LaminaGeometry,
    pub(super) law_in: LaminaLaw,
    pub(super) law_out: LaminaLaw,
    pub(super) cf: f64,
    pub(super) gm: f64,
    pub(super) k_cage: f64,
    pub(super) k_tilt: f64,
    pub(super) load: [f64; 2],
    pub(super) l_ref: f64,
    /// Reference force (largest of the loads, Z·CF and M/l_ref), N.
    pub(super) f_ref: f64,
    pub(super) tol: f64,
    pub(super) max_roller_it: usize,
    /// cos φ of each unique roller and its multiplicity, row after row.
    pub(super) unique: Vec<(f64, f64)>,
    /// Row sign of each unique roller: +1 for row 1, −1 for the mirrored row 2 (its frame's
    /// axial direction is the bearing's reversed).
    pub(super) signs: Vec<f64>,
    /// Rollers per row Z and unique rollers per row.
    pub(super) per_row: (usize, usize),
    /// The guide ring contact, if any.
    pub(super) guide: Option<GuideContact>,
    /// The guide ring's axial offset s from its centred place on the inner ring, m, bearing
    /// frame (+ toward row 1): the floating guide ring's unknown, held fixed during one ring
    /// solve and found by the outer balance of [`Problem::float_guide`].
    pub(super) guide_offset: std::cell::Cell<f64>,
    pub(super) evals: std::cell::Cell<usize>,
    /// Roller tolerance of the current ring iteration (inexact Newton: loose while the ring
    /// residual is large, the full tolerance at the end).
    pub(super) roller_tol: std::cell::Cell<f64>,
    /// Largest roller step (trust radius), m: 0.1·D.
    pub(super) max_step: f64,
    /// Scale of the roller unknowns (axial, radial, pitch) in the Newton step: pitch by
    /// l_ref so the three unknowns have comparable units.
    pub(super) scale: Vector3<f64>,
    /// An extra generalised load (axial, radial, pitch) on the roller being solved, N, N, N·m:
    /// the raceway tractions of a skewed roller ([`super::resolve_rollers_with_loads`]).
    /// `None` in every load-distribution solve, so their arithmetic is untouched.
    pub(super) extra_load: std::cell::Cell<Option<Vector3<f64>>>,
}

/// Scalar sums of one roller's energy, gradient and Hessian blocks (upper triangles).
#[derive(Default)]
struct Accumulator {
    energy: f64,
    g: [f64; 3],
    /// h00, h01, h02, h11, h12, h22 of H_qq.
    h: [f64; 6],
    gu: [f64; 2],
    /// h00, h01, h11 of H_uu.
    huu: [f64; 3],
    huq: [[f64; 3]; 2],
}

impl Accumulator {
    /// Add one contact at approach state `a` ([`LaminaGeometry::approach_with`]) with lamina
    /// law constant `stiffness` (k·weight, N/m^(10/9)). INNER contacts also load the inner
    /// ring (u-coupling). Returns the contact's load, N.
    #[inline(always)]
    fn add<const INNER: bool>(
        &mut self,
        a: &Approach,
        stiffness: f64,
        cphi: f64,
        hessian: bool,
    ) -> f64 {
        let delta = a.delta;
        if delta <= 0.0 {
            return 0.0;
        }
        let (n, p) = (a.normal, a.point);
        let inv = a.inv_rho;
        // Lamina law Q = k·δ^(10/9), dQ/dδ, U = 9/19·Q·δ (eq. 3.3).
        let d19 = crate::physics::contact::lamina_law::ninth_root(delta);
        let qq = stiffness * delta * d19;
        let dq = stiffness * (10.0 / 9.0) * d19;
        self.energy += qq * delta * (9.0 / 19.0);
        // ∂P/∂α = e_t × p = (−p_r, p_x)
        let t = [-p[1], p[0]];
        let gd2 = n[0] * t[0] + n[1] * t[1];
        self.g[0] += qq * n[0];
        self.g[1] += qq * n[1];
        self.g[2] += qq * gd2;
        if INNER {
            self.gu[0] -= qq * n[0];
            self.gu[1] -= qq * n[1] * cphi;
        }
        if !hessian {
            return qq;
        }
        // Projector (I − n nᵀ)/ρ: curvature of |P − C|.
        let pm = [
            (1.0 - n[0] * n[0]) * inv,
            -n[0] * n[1] * inv,
            (1.0 - n[1] * n[1]) * inv,
        ];
        let pmt = [pm[0] * t[0] + pm[1] * t[1], pm[1] * t[0] + pm[2] * t[1]];
        self.h[0] += dq * n[0] * n[0] + qq * pm[0];
        self.h[1] += dq * n[0] * n[1] + qq * pm[1];
        self.h[2] += dq * n[0] * gd2 + qq * pmt[0];
        self.h[3] += dq * n[1] * n[1] + qq * pm[2];
        self.h[4] += dq * n[1] * gd2 + qq * pmt[1];
        // ∂²P/∂α² = −p adds −Q·(n·p).
        self.h[5] += dq * gd2 * gd2 + qq * (t[0] * pmt[0] + t[1] * pmt[1])
            - qq * (n[0] * p[0] + n[1] * p[1]);
        if INNER {
            let c2 = cphi * cphi;
            self.huu[0] += dq * n[0] * n[0] + qq * pm[0];
            self.huu[1] += (dq * n[0] * n[1] + qq * pm[1]) * cphi;
            self.huu[2] += (dq * n[1] * n[1] + qq * pm[2]) * c2;
            let gd = [n[0], n[1], gd2];
            let row0 = [pm[0], pm[1], pmt[0]];
            let row1 = [pm[1], pm[2], pmt[1]];
            for b in 0..3 {
                self.huq[0][b] -= dq * n[0] * gd[b] + qq * row0[b];
                self.huq[1][b] -= (dq * n[1] * gd[b] + qq * row1[b]) * cphi;
            }
        }
        qq
    }

    fn finish(self, hessian: bool) -> RollerEval {
        let h = self.h;
        let (h_qq, h_uu, h_uq) = if hessian {
            (
                Matrix3::new(h[0], h[1], h[2], h[1], h[3], h[4], h[2], h[4], h[5]),
                Matrix2::new(self.huu[0], self.huu[1], self.huu[1], self.huu[2]),
                Matrix2x3::new(
                    self.huq[0][0],
                    self.huq[0][1],
                    self.huq[0][2],
                    self.huq[1][0],
                    self.huq[1][1],
                    self.huq[1][2],
                ),
            )
        } else {
            (Matrix3::zeros(), Matrix2::zeros(), Matrix2x3::zeros())
        };
        RollerEval {
            energy: self.energy,
            g_q: Vector3::new(self.g[0], self.g[1], self.g[2]),
            h_qq,
            g_u: Vector2::new(self.gu[0], self.gu[1]),
            h_uq,
            h_uu,
        }
    }
}

/// Everything one roller contributes at (u, q).
pub(super) struct RollerEval {
    pub(super) energy: f64,
    pub(super) g_q: Vector3<f64>,
    pub(super) h_qq: Matrix3<f64>,
    pub(super) g_u: Vector2<f64>,
    pub(super) h_uq: Matrix2x3<f64>,
    pub(super) h_uu: Matrix2<f64>,
}

impl Problem {
    /// The single-row problem (tests).
    #[cfg(test)]
    pub(super) fn new(b: &Bearing, speeds: &DynamicSpeeds, force_tolerance: f64) -> Self {
        Self::with_layout(b, speeds, force_tolerance, Layout::default())
    }

    /// The problem of `layout.rows` rows of `b`'s rollers (row 2 mirrored) with the guide ring.
    pub(super) fn with_layout(
        b: &Bearing,
        speeds: &DynamicSpeeds,
        force_tolerance: f64,
        layout: Layout,
    ) -> Self {
        let g = &b.geometry;
        let laminae = b.solver.laminae.max(1);
        let geom = LaminaGeometry::with_slicing(g, laminae, b.solver.slicing);
        let w = g.effective_length_m / laminae as f64;
        let law_in = LaminaLaw::new(
            w,
            g.effective_length_m,
            &b.materials.roller,
            &b.materials.inner_ring,
        );
        let law_out = LaminaLaw::new(
            w,
            g.effective_length_m,
            &b.materials.roller,
            &b.materials.outer_ring,
        );
        let mass = roller_mass(g, b.materials.roller.density_kg_m3);
        // CF at the pitch radius with the cage orbit speed (eq. 3.10, App. C).
        let cf = mass.mass_kg * speeds.cage_rad_s.powi(2) * 0.5 * g.pitch_diameter_m;
        let gm = gyroscopic_moment(&mass, speeds, g.contact_angle_rad);
        // Reference roller stiffness at δ = 1e-4·D.
        let d_ref = 1e-4 * g.roller_diameter_m;
        let k_roller = laminae as f64 * law_out.eval(d_ref).1;
        let k_cage = b.solver.cage_stiffness_ratio * k_roller;
        let l_ref = 0.5 * g.effective_length_m;
        let z = g.roller_count;
        let row_unique: Vec<(f64, f64)> = (0..=z / 2)
            .map(|j| {
                let phi = 2.0 * std::f64::consts::PI * j as f64 / z as f64; // eq. 3.1
                let mult = if j == 0 || 2 * j == z { 1.0 } else { 2.0 };
                (phi.cos(), mult)
            })
            .collect();
        let rows = layout.rows.max(1);
        let per_row = (z, row_unique.len());
        let unique: Vec<(f64, f64)> = (0..rows).flat_map(|_| row_unique.clone()).collect();
        let signs = (0..rows)
            .flat_map(|r| std::iter::repeat_n(if r == 0 { 1.0 } else { -1.0 }, per_row.1))
            .collect();
        let load = [b.operating.axial_load_n, b.operating.radial_load_n];
        let f_ref = load[0]
            .abs()
            .max(load[1].abs())
            .max((rows * z) as f64 * cf)
            .max(gm.abs() / l_ref)
            .max(1.0);
        Problem {
            geom,
            law_in,
            law_out,
            cf,
            gm,
            k_cage,
            k_tilt: k_cage * l_ref * l_ref,
            load,
            l_ref,
            f_ref,
            tol: force_tolerance.max(1e-14) * f_ref,
            max_roller_it: b.solver.max_roller_iterations.max(1),
            unique,
            signs,
            per_row,
            guide: layout.guide,
            guide_offset: std::cell::Cell::new(0.0),
            evals: std::cell::Cell::new(0),
            roller_tol: std::cell::Cell::new(0.0),
            max_step: 0.1 * g.roller_diameter_m,
            scale: Vector3::new(1.0, 1.0, 1.0 / l_ref),
            extra_load: std::cell::Cell::new(None),
        }
    }

    /// Inertial generalised load on a roller: (axial, radial, pitch).
    #[inline]
    pub(super) fn f_ext(&self) -> Vector3<f64> {
        // Σ contact + inertial = 0 with inertial = (0, +CF, −M_req) (App. D: the raceways
        // must supply M_req, so the roller "loads" them with −M_req).
        Vector3::new(0.0, self.cf, -self.gm)
    }

    /// Energy, gradient and Hessian of one roller at ring deflection `u` (cos φ = `cphi`).
    ///
    /// The hot loop of the whole program, written out in scalars: the same terms as the
    /// matrix form of [`Problem::eval_reference`] (kept for the tests, which compare the two
    /// to round-off), with the symmetric blocks accumulated once, the inner and outer
    /// contacts specialised at compile time, and δ^(1/9) by the law's own
    /// [`crate::physics::contact::lamina_law::ninth_root`]. Inlined into its callers in
    /// the driver (another codegen unit), where `hessian` is a constant.
    #[inline]
    #[cfg(test)]
    pub(super) fn eval(
        &self,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        hessian: bool,
    ) -> RollerEval {
        self.eval_row(1.0, cphi, u, q, hessian)
    }

    /// [`Problem::eval`] for a roller of the row with frame sign `sign` (+1 row 1, −1 the
    /// mirrored row 2), which only the guide ring's offset reads.
    #[inline]
    pub(super) fn eval_row(
        &self,
        sign: f64,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        hessian: bool,
    ) -> RollerEval {
        let g = &self.geom;
        self.evals.set(self.evals.get() + 2 * g.laminae.len());
        let pitch = crate::bearings::spherical_roller::geometry::Pitch::new(q[2]);
        let mut acc = Accumulator::default();
        let qa = [q[0], q[1], q[2]];
        let shift = [u[0], u[1] * cphi];
        let (k_in, k_out) = (self.law_in.stiffness, self.law_out.stiffness);
        for lam in &g.laminae {
            let ai = g.approach_with(lam, true, qa, shift, pitch);
            acc.add::<true>(&ai, k_in * lam.weight, cphi, hessian);
            let ao = g.approach_with(lam, false, qa, shift, pitch);
            acc.add::<false>(&ao, k_out * lam.weight, cphi, hessian);
        }
        let mut ev = acc.finish(hessian);
        self.add_inertia_and_cage(&mut ev, q, hessian);
        self.add_guide(&mut ev, sign, cphi, u, q, pitch, hessian);
        ev
    }

    /// Unique roller (index into `unique`) of roller `r` (0-based over all rows).
    pub(super) fn unique_of(&self, r: usize) -> usize {
        let (z, n) = self.per_row;
        let row = (r / z.max(1)).min(self.signs.len() / n.max(1) - 1);
        row * n + unique_index(r % z.max(1), z)
    }

    /// Ring deflection u (bearing frame) as unique roller `k`'s row frame sees it.
    #[inline]
    pub(super) fn local_u(&self, k: usize, u: [f64; 2]) -> [f64; 2] {
        [self.signs[k] * u[0], u[1]]
    }

    /// The guide ring's gap g, its derivatives along (axial, radial, pitch) of the roller, the
    /// second derivative in pitch and the derivatives along the ring deflection (axial,
    /// radial) at cos φ = `cphi`, u in the row's frame (sign `sign`). g = g₀ + (q − s)·a −
    /// c·(cos α − 1) with s = (u_a + sign·s_g, u_r·cos φ) the guide ring's shift at the
    /// roller: the inner ring's, plus the guide ring's own axial offset s_g on it (radially
    /// it sits on the inner ring's land), a the roller axis and c = L/2 − r_e; the force
    /// F = K·(−g)^(3/2) acts on the roller along +a (away from the bearing's centre plane,
    /// which lies on the roller's −a side). Within one ring solve s_g is fixed, so the ring
    /// derivatives are the inner ring's.
    #[inline]
    pub(super) fn guide_gap(
        &self,
        guide: &GuideContact,
        sign: f64,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        pitch: crate::bearings::spherical_roller::geometry::Pitch,
    ) -> (f64, Vector3<f64>, f64, Vector2<f64>) {
        let a = self.geom.axis;
        let c = guide.end_centre_offset_m;
        let ga = u[0] + sign * self.guide_offset.get();
        let s = (q[0] - ga) * a[0] + (q[1] - u[1] * cphi) * a[1];
        let gap = guide.gap_m + s - c * pitch.cos_minus_one;
        let cos = 1.0 + pitch.cos_minus_one;
        (
            gap,
            Vector3::new(a[0], a[1], c * pitch.sin),
            c * cos,
            Vector2::new(-a[0], -a[1] * cphi),
        )
    }

    /// The guide ring's contact force on the roller, N (≥ 0), u in the row's frame.
    pub(super) fn guide_force(&self, sign: f64, cphi: f64, u: [f64; 2], q: &Vector3<f64>) -> f64 {
        let Some(guide) = &self.guide else {
            return 0.0;
        };
        let pitch = crate::bearings::spherical_roller::geometry::Pitch::new(q[2]);
        let (gap, ..) = self.guide_gap(guide, sign, cphi, u, q, pitch);
        if gap >= 0.0 {
            0.0
        } else {
            guide.hertz_constant * (-gap).powf(1.5)
        }
    }

    /// The guide ring's energy U = (2/5)·K·δ^(5/2) (δ = −g > 0), its gradient and Hessian in
    /// the roller's and the ring's unknowns (u in the row's frame). Nothing without a guide
    /// ring, so the single-row bearing's arithmetic is untouched.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn add_guide(
        &self,
        ev: &mut RollerEval,
        sign: f64,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        pitch: crate::bearings::spherical_roller::geometry::Pitch,
        hessian: bool,
    ) {
        let Some(guide) = &self.guide else {
            return;
        };
        let (gap, dq, d2, du) = self.guide_gap(guide, sign, cphi, u, q, pitch);
        if gap >= 0.0 {
            return;
        }
        let delta = -gap;
        let root = delta.sqrt();
        let f = guide.hertz_constant * delta * root;
        let df = 1.5 * guide.hertz_constant * root;
        ev.energy += 0.4 * f * delta;
        // ∂U/∂x = F·∂δ/∂x = −F·∂g/∂x.
        ev.g_q -= f * dq;
        ev.g_u -= f * du;
        if hessian {
            ev.h_qq += df * dq * dq.transpose();
            ev.h_qq[(2, 2)] -= f * d2;
            ev.h_uu += df * du * du.transpose();
            ev.h_uq += df * du * dq.transpose();
        }
    }

    /// Inertial loads and the cage pocket springs (shared by both evaluations).
    #[inline]
    pub(super) fn add_inertia_and_cage(
        &self,
        ev: &mut RollerEval,
        q: &Vector3<f64>,
        hessian: bool,
    ) {
        let f = self.f_ext();
        ev.energy -= f.dot(q);
        ev.g_q -= f;
        if let Some(e) = self.extra_load.get() {
            // A constant load: energy −e·q (the tractions held fixed within one solve).
            ev.energy -= e.dot(q);
            ev.g_q -= e;
        }
        // Cage pocket: springs on the position along the roller axis and on pitch.
        let a = self.geom.axis;
        let s = q[0] * a[0] + q[1] * a[1];
        ev.energy += 0.5 * self.k_cage * s * s + 0.5 * self.k_tilt * q[2] * q[2];
        ev.g_q += Vector3::new(
            self.k_cage * s * a[0],
            self.k_cage * s * a[1],
            self.k_tilt * q[2],
        );
        if hessian {
            ev.h_qq[(0, 0)] += self.k_cage * a[0] * a[0];
            ev.h_qq[(0, 1)] += self.k_cage * a[0] * a[1];
            ev.h_qq[(1, 0)] += self.k_cage * a[0] * a[1];
            ev.h_qq[(1, 1)] += self.k_cage * a[1] * a[1];
            ev.h_qq[(2, 2)] += self.k_tilt;
        }
    }

    /// The matrix form of [`Problem::eval`], term by term as derived (tests only).
    #[cfg(test)]
    pub(super) fn eval_reference(
        &self,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        hessian: bool,
    ) -> RollerEval {
        let mut ev = RollerEval {
            energy: 0.0,
            g_q: Vector3::zeros(),
            h_qq: Matrix3::zeros(),
            g_u: Vector2::zeros(),
            h_uq: Matrix2x3::zeros(),
            h_uu: Matrix2::zeros(),
        };
        let g = &self.geom;
        let shift = [u[0], u[1] * cphi];
        let qa = [q[0], q[1], q[2]];
        let pitch = crate::bearings::spherical_roller::geometry::Pitch::new(q[2]);
        self.evals.set(self.evals.get() + 2 * g.laminae.len());
        for lam in &g.laminae {
            for inner in [true, false] {
                let law = if inner { &self.law_in } else { &self.law_out };
                let ap = g.approach_with(lam, inner, qa, shift, pitch);
                let (delta, rho, p) = (ap.delta, ap.rho, ap.point);
                if delta <= 0.0 {
                    continue;
                }
                let (qq, dq, uu) = law.eval(delta);
                let (qq, dq, uu) = (qq * lam.weight, dq * lam.weight, uu * lam.weight);
                let nh = ap.normal;
                // ∂P/∂α = e_t × p = (−p_r, p_x)
                let t = [-p[1], p[0]];
                let gd = Vector3::new(nh[0], nh[1], nh[0] * t[0] + nh[1] * t[1]);
                ev.energy += uu;
                ev.g_q += qq * gd;
                let gdu = Vector2::new(-nh[0], -nh[1] * cphi);
                if inner {
                    ev.g_u += qq * gdu;
                }
                if !hessian {
                    continue;
                }
                // Projector (I − n nᵀ)/ρ: curvature of |P − C|.
                let pm = Matrix2::new(
                    1.0 - nh[0] * nh[0],
                    -nh[0] * nh[1],
                    -nh[0] * nh[1],
                    1.0 - nh[1] * nh[1],
                ) / rho;
                let j = Matrix2x3::new(1.0, 0.0, t[0], 0.0, 1.0, t[1]);
                let mut hq = dq * gd * gd.transpose() + qq * (j.transpose() * pm * j);
                // ∂²P/∂α² = −p
                hq[(2, 2)] += qq * (-(nh[0] * p[0] + nh[1] * p[1]));
                ev.h_qq += hq;
                if inner {
                    let s = Matrix2::new(1.0, 0.0, 0.0, cphi);
                    ev.h_uu += dq * gdu * gdu.transpose() + qq * (s.transpose() * pm * s);
                    ev.h_uq += dq * gdu * gd.transpose() - qq * (s.transpose() * pm * j);
                }
            }
        }
        self.add_inertia_and_cage(&mut ev, q, hessian);
        self.add_guide(&mut ev, 1.0, cphi, u, q, pitch, hessian);
        ev
    }

    /// Scaled residual norm of a roller gradient (forces in N, moment over l_ref).
    #[inline]
    pub(super) fn roller_residual(&self, g: &Vector3<f64>) -> f64 {
        g[0].abs().max(g[1].abs()).max(g[2].abs() / self.l_ref)
    }

    pub(super) fn trace_step(
        &self,
        ring_it: usize,
        it: usize,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
        g: &Vector3<f64>,
    ) -> TraceStep {
        let (ia, oa, il, ol) = self.lamina_state(cphi, u, q);
        TraceStep {
            outer_iteration: 1,
            ring_iteration: ring_it,
            roller_iteration: it,
            ring: u,
            roller: [q[0], q[1], q[2]],
            residual: [g[0], g[1], g[2]],
            inner_approach_m: ia,
            outer_approach_m: oa,
            inner_load_n: il,
            outer_load_n: ol,
        }
    }

    /// Approaches and loads of every lamina (inner and outer).
    #[allow(clippy::type_complexity)]
    pub(super) fn lamina_state(
        &self,
        cphi: f64,
        u: [f64; 2],
        q: &Vector3<f64>,
    ) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) {
        let g = &self.geom;
        let shift = [u[0], u[1] * cphi];
        let qa = [q[0], q[1], q[2]];
        let n = g.laminae.len();
        let (mut ia, mut oa, mut il, mut ol) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for lam in &g.laminae {
            let di = g.approach(lam, true, qa, shift).delta;
            let d_o = g.approach(lam, false, qa, shift).delta;
            ia.push(di);
            oa.push(d_o);
            il.push(self.law_in.eval(di).0 * lam.weight);
            ol.push(self.law_out.eval(d_o).0 * lam.weight);
        }
        (ia, oa, il, ol)
    }
}

pub(super) fn assemble(
    b: &Bearing,
    p: &Problem,
    u: [f64; 2],
    qs: &[Vector3<f64>],
    mut residuals: Residuals,
    speeds: &DynamicSpeeds,
) -> LoadDistribution {
    let z = b.geometry.roller_count;
    let g = &p.geom;
    let beta_deg = b.geometry.contact_angle_rad.to_degrees();
    let rows = p.signs.len() / p.per_row.1.max(1);
    let mut rollers: Vec<RollerResult> = Vec::with_capacity(rows * z);
    for k in 0..rows * z {
        let (row, j) = (k / z, k % z);
        let uj = unique_index(j, z);
        if uj != j {
            // Roller Z−j mirrors roller j about the load plane (same cos φ): same state.
            let mut r = rollers[row * z + uj].clone();
            r.index = j + 1;
            r.azimuth_deg = 360.0 * j as f64 / z as f64;
            rollers.push(r);
            continue;
        }
        let ku = row * p.per_row.1 + uj;
        let (cphi, _) = p.unique[ku];
        let q = qs[ku];
        // The row's own frame (row 2 mirrored).
        let u = p.local_u(ku, u);
        // One pass gives the lamina results and the roller's residual (the same evaluation
        // as the solver's, through the same accumulator).
        let shift = [u[0], u[1] * cphi];
        let qa = [q[0], q[1], q[2]];
        let pitch = crate::bearings::spherical_roller::geometry::Pitch::new(q[2]);
        let mut acc = Accumulator::default();
        p.evals.set(p.evals.get() + 2 * g.laminae.len());
        let laminae: Vec<LaminaResult> = g
            .laminae
            .iter()
            .map(|lam| {
                let ai = g.approach_with(lam, true, qa, shift, pitch);
                let inner_load = acc.add::<true>(&ai, p.law_in.stiffness * lam.weight, cphi, false);
                let ao = g.approach_with(lam, false, qa, shift, pitch);
                let outer_load =
                    acc.add::<false>(&ao, p.law_out.stiffness * lam.weight, cphi, false);
                let pin = [q[0] + ai.point[0], q[1] + ai.point[1]];
                let pout = [q[0] + ao.point[0], q[1] + ao.point[1]];
                let (di, d_o) = (ai.delta, ao.delta);
                // Inner: force on the roller along (C − P), i.e. −normal; outer: the normal
                // itself points outward. Angles from the radial plane.
                let ni = [-ai.normal[0], -ai.normal[1]];
                let no = ao.normal;
                LaminaResult {
                    offset_m: lam.offset_m,
                    width_m: lam.width_m,
                    inner_load_n: inner_load,
                    outer_load_n: outer_load,
                    inner_approach_m: di,
                    outer_approach_m: d_o,
                    inner_point_m: [pin[0], pin[1] + g.pitch_radius_m],
                    outer_point_m: [pout[0], pout[1] + g.pitch_radius_m],
                    inner_normal: ni,
                    outer_normal: no,
                }
            })
            .collect();
        let mut ev = acc.finish(false);
        p.add_inertia_and_cage(&mut ev, &q, false);
        let sign = p.signs[ku];
        p.add_guide(&mut ev, sign, cphi, u, &q, pitch, false);
        residuals.roller_force_n = residuals
            .roller_force_n
            .max(ev.g_q[0].abs().max(ev.g_q[1].abs()));
        residuals.roller_moment_nm = residuals.roller_moment_nm.max(ev.g_q[2].abs());
        let inner = raceway_contact(&laminae, true, beta_deg);
        let outer = raceway_contact(&laminae, false, beta_deg);
        let s = q[0] * g.axis[0] + q[1] * g.axis[1];
        rollers.push(RollerResult {
            index: j + 1,
            azimuth_deg: 360.0 * j as f64 / z as f64,
            axial_displacement_m: q[0],
            radial_displacement_m: q[1],
            tilt_rad: q[2],
            centrifugal_force_n: p.cf,
            gyroscopic_moment_nm: p.gm,
            cage_force_n: -p.k_cage * s,
            cage_moment_nm: -p.k_tilt * q[2],
            row: row + 1,
            guide_force_n: p.guide_force(sign, cphi, u, &q),
            inner,
            outer,
            laminae,
        });
    }
    LoadDistribution {
        converged: true,
        axial_deflection_m: u[0],
        radial_deflection_m: u[1],
        speeds: *speeds,
        guide_offset_m: p.guide_offset.get(),
        roller_mass: roller_mass(&b.geometry, b.materials.roller.density_kg_m3),
        mirror: (0..rows * z)
            .map(|k| {
                let (row, j) = (k / z, k % z);
                Some(row * z + unique_index(j, z)).filter(|&i| i != k)
            })
            .collect(),
        rollers,
        residuals,
        stats: SolveStats::default(),
        warm: WarmStart {
            ring: u,
            rollers: qs.iter().map(|q| [q[0], q[1], q[2]]).collect(),
            guide_offset_m: p.guide_offset.get(),
            inertial: None,
        },
        trace: Vec::new(),
    }
}

/// §4.5: normal load = Σ lamina loads projected on the most loaded lamina's normal.
fn raceway_contact(laminae: &[LaminaResult], inner: bool, beta_deg: f64) -> RacewayContact {
    let load = |l: &LaminaResult| {
        if inner {
            l.inner_load_n
        } else {
            l.outer_load_n
        }
    };
    let angle = |l: &LaminaResult| {
        if inner {
            l.inner_angle_deg()
        } else {
            l.outer_angle_deg()
        }
    };
    let loaded = laminae.iter().filter(|l| load(l) > 0.0).count();
    // The most heavily loaded lamina is the one with the highest line load Q/w: with the
    // seed's equal laminae that is the largest Q, but with cosine slicing the central
    // laminae are up to π/2 times the mean width and the end ones far thinner, so the
    // largest Q favoured a wide central lamina over a thin edge-loaded one (on the thrust
    // deck the §7 cage speed was 0.06 % off at every Γ from it).
    let line = |l: &LaminaResult| load(l) / l.width_m;
    let max = laminae
        .iter()
        .enumerate()
        .filter(|(_, l)| load(l) > 0.0 && l.width_m > 0.0)
        .max_by(|a, b| line(a.1).total_cmp(&line(b.1)))
        .map(|(i, _)| i);
    match max {
        None => RacewayContact {
            normal_load_n: 0.0,
            contact_angle_deg: beta_deg,
            loaded_laminae: 0,
            max_lamina: None,
        },
        Some(m) => {
            // cos(α_l − α_m) as the dot product of the two unit normals.
            let normal = |l: &LaminaResult| {
                if inner {
                    l.inner_normal
                } else {
                    l.outer_normal
                }
            };
            let nm = normal(&laminae[m]);
            let total = laminae
                .iter()
                .map(|l| {
                    let n = normal(l);
                    load(l) * (n[0] * nm[0] + n[1] * nm[1])
                })
                .sum();
            RacewayContact {
                normal_load_n: total,
                contact_angle_deg: angle(&laminae[m]),
                loaded_laminae: loaded,
                max_lamina: Some(m),
            }
        }
    }
}

/// Unique (symmetry) index of roller `r` (0-based): rollers j and Z−j mirror each other.
pub(super) fn unique_index(r: usize, z: usize) -> usize {
    let r = r % z.max(1);
    r.min(z - r)
}
