//! The cylindrical roller bearing with ribs on both rings (NJ/NUP) under radial and axial
//! load: ring displacements (x, y, z), per roller its radial position, axial position and
//! tilt, the roller end–rib point contacts, and the analytic 3×3 ring stiffness (issue 25,
//! model item 1: "ribs carry axial load through roller-end contact … roller tilt where
//! the slice loads are uneven").
//!
//! # The model (Harris & Kotzalas, Advanced Concepts of Bearing Technology, ch. 1 on
//! cylindrical roller bearings under combined load: "roller skewing/tilting and flange
//! load"; chosen and documented here, the seed carries no ribs)
//!
//! * **Rib contact.** The roller ends are spheres of radius R_E with their poles on the
//!   roller axis at ±l/2 (l end to end); the rib faces are cones laid back by the rib
//!   angle φ from the radial plane. The contact normal passes through the end sphere's
//!   centre and makes φ with the bearing axis, so the contact sits e = R_E·sin φ from the
//!   roller axis: the deck gives φ (`geometry.rib_angle`) and the contact height
//!   h = r − e above the raceway (`geometry.rib_contact_height`), which fix R_E = e/sin φ
//!   (a third key would over-determine the contact). Each contact is a Hertz point
//!   contact ([`HertzPointContact`], exact ellipse) of the end sphere (1/R_E both ways)
//!   with the cone, whose only curvature is the circumferential sin φ/ρ (Meusnier; ρ its
//!   distance from the bearing axis): convex on the inner ring's rib (+), concave on the
//!   outer's (−).
//! * **Load path.** An axial load F_a on the inner ring (sign σ) pushes its rib on the
//!   −σ end of every roller; the outer ring's rib on the +σ end holds it (an NUP
//!   arrangement: both rings ribbed on both sides, so either sign is carried; the end
//!   play is not modelled, the axial displacement counts from first rib contact). The
//!   rib forces on the roller are Q_i·(sin φ, σ cos φ) and Q_o·(−sin φ, −σ cos φ) in
//!   (radial, axial); the roller's axial balance makes Q_i = Q_o, their radial parts
//!   cancel, and their lines (through the sphere centres at ∓σ(l/2 − R_E) on the axis)
//!   form the couple 2Q·(e − (l/2)·sin φ) that tilts the roller: the raceway slices
//!   balance it with uneven loads (the inner contact heavier at the inner rib's end).
//! * **Kinematics** (small displacements, rigid rings; seed 003 eq. 3 with C = −ρ). Ring
//!   (x, y, z), roller j at ψ_j with p = x cos ψ + y sin ψ; roller radial position s,
//!   axial position u and tilt θ (rotation in the radial–axial plane, a point at axial y
//!   moving radially by −θ·y). At axial y with profile drop d(y):
//!   δ_i = p + ρ − s + θ·y − d, δ_o = s + ρ − θ·y − d;
//!   δ_ri = (p − s + θ·z₁)·sin φ + σ(z − u)·cos φ, δ_ro = (s − θ·z₂)·sin φ + σu·cos φ
//!   with z₁ = −σ(l/2 − R_E), z₂ = −z₁ the sphere centres.
//! * **Equilibrium** as the minimum of the elastic energy: the slices carry the project's
//!   lamina law (inner and outer, the same laws as the radial solve) and the rib contacts
//!   Q = K·δ^(3/2) (energy 2/5·K·δ^(5/2)), less F_c·s and the work of the load
//!   F·(x, y, z). The energy is convex (each contact's energy is a convex function of a
//!   linear combination of the unknowns), so each roller's (s, u, θ) is found by Newton
//!   with a line search at a fixed ring, and the ring by Newton on the partial minimum
//!   with the exact Jacobian: the Schur complement K = Σ Tᵀ(A − B·C⁻¹·Bᵀ)T of each
//!   roller's 5×5 Hessian in (p, z | s, u, θ) — which is also the reported 3×3 stiffness.
//!   Its gradient gives back the balances: Σ(W_i + Q·sin φ)(cos ψ, sin ψ) = (F_x, F_y),
//!   ΣQ·cos φ = |F_a|, and per roller W_o = W_i + F_c, Q_i = Q_o and
//!   Σ y·(q_o − q_i) = 2Q·σ(e − (l/2)·sin φ) (tested).
//! * **Slices.** A tilted roller's approach varies linearly along it, so the radial
//!   solve's closed-form segments (one approach per segment pair) do not apply: each of
//!   the [`SUB_LAMINAE`] sub-laminae of a slice (drop interpolated linearly between its
//!   ends, as the radial solve does) is integrated by 2-point Gauss–Legendre. The discrete
//!   model is then C¹ with exact derivatives; it differs from the radial solve's exact
//!   segments only where a sub-lamina straddles the end of the loaded length (measured
//!   in the tests: 2e-6 relative on W_max for the truck bearing).
//!
//! A deck without ribs or without axial load never comes here: the radial solve
//! ([`super::quasi_static::solve`]) runs unchanged, bit for bit.

// The 3×3 and 5×5 algebra below reads as the matrices are written: indices, not iterators.
#![allow(clippy::needless_range_loop)]

use super::quasi_static::{
    validate, QuasiStatic, QuasiStaticError, QuasiStaticModel, RollerState, SliceState, SUB_LAMINAE,
};
use crate::numerics::cancel::Cancel;
use crate::physics::contact::lamina_law::{ninth_root, LaminaLaw};
use crate::physics::contact::line::{line_contact_reduced, reduced_modulus, Elastic};
use crate::physics::contact::point::{CurvatureSum, HertzMethod, HertzPointContact};
use crate::physics::material::Material;

/// The roller end–rib contacts of a bearing ribbed on both rings, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RibContact {
    /// φ, the rib face's lay-back from the radial plane (the contact normal's angle to
    /// the bearing axis), rad, in (0, π/4].
    pub angle_rad: f64,
    /// h, the contact's height above the raceway, m, in (0, r).
    pub contact_height_m: f64,
    /// F_a, the axial load on the inner ring, N (either sign: ribs on both sides).
    pub axial_load_n: f64,
}

impl RibContact {
    /// R_E = (r − h)/sin φ, the roller end sphere's radius that puts the contact at the
    /// height h on a rib laid back by φ, m.
    pub fn end_radius_m(&self, roller_radius_m: f64) -> f64 {
        (roller_radius_m - self.contact_height_m) / self.angle_rad.sin()
    }
}

/// The solve a deck asks for: the radial solve ([`super::quasi_static::solve`],
/// unchanged) without ribs or without axial load, else [`solve_ribbed`].
pub fn solve_with(
    model: &QuasiStaticModel,
    ribs: Option<&RibContact>,
    start: Option<&QuasiStatic>,
    cancel: &Cancel,
) -> Result<QuasiStatic, QuasiStaticError> {
    match ribs {
        Some(r) if r.axial_load_n != 0.0 => solve_ribbed(model, r, start, cancel),
        _ => super::quasi_static::solve(
            model,
            start.filter(|s| s.stiffness_xyz_n_m.is_none()),
            cancel,
        ),
    }
}

/// Newton iterations of the ring before [`QuasiStaticError::NotConverged`].
const MAX_RING_ITERATIONS: usize = 100;
/// Newton iterations of one roller's (s, u, θ).
const MAX_ROLLER_ITERATIONS: usize = 200;

/// Gauss–Legendre 2-point abscissae on [0, 1]: ½ ∓ 1/(2√3).
const GAUSS: [f64; 2] = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];

/// One contact's energy, load and stiffness at approach `d` for the law `k·d₊^n`
/// (n = 10/9 lamina, 3/2 Hertz), returned as (energy, load, dload/dδ).
#[inline]
fn lamina(k: f64, d: f64) -> (f64, f64, f64) {
    if !(d > 0.0) {
        return (0.0, 0.0, 0.0);
    }
    let r = ninth_root(d);
    let q = k * d * r;
    (q * d * (9.0 / 19.0), q, k * r * (10.0 / 9.0))
}

#[inline]
fn hertz(k: f64, d: f64) -> (f64, f64, f64) {
    if !(d > 0.0) {
        return (0.0, 0.0, 0.0);
    }
    let s = d.sqrt();
    let q = k * d * s;
    (0.4 * q * d, q, 1.5 * k * s)
}

/// The fixed data of the ribbed solve.
struct Ribbed {
    cos: Vec<f64>,
    sin: Vec<f64>,
    /// Quadrature points along the roller: axial y, drop d, and the slice each belongs to.
    points: Vec<(f64, f64, usize)>,
    /// Slice centres and their drops (reported).
    slice_axial: Vec<f64>,
    slice_drop: Vec<f64>,
    width: f64,
    /// The lamina law per quadrature point (a sub-lamina's law, weight ½), inner/outer.
    k_in: f64,
    k_out: f64,
    law_stiffness_min: f64,
    rho: f64,
    fc: f64,
    /// sin φ, cos φ, σ = sign F_a, |F_a|.
    sin_phi: f64,
    cos_phi: f64,
    sigma: f64,
    axial: f64,
    /// Sphere centres z₁ (inner rib's end), z₂ = −z₁, m.
    z1: f64,
    z2: f64,
    /// Hertz K of the inner and outer rib contacts, N/m^1.5.
    k_ri: f64,
    k_ro: f64,
    rib_in: HertzPointContact,
    rib_out: HertzPointContact,
    /// A length scale for moments (l/2), m.
    lever: f64,
}

/// One roller's state at a ring position: its unknowns, the 5×5 energy gradient and
/// Hessian over (p, z, s, u, θ), the energy and its contact loads.
#[derive(Debug, Clone, Copy, Default)]
struct RollerSolve {
    v: [f64; 3],
    grad: [f64; 5],
    hess: [[f64; 5]; 5],
    energy: f64,
    w_in: f64,
    w_out: f64,
    q_ri: f64,
    q_ro: f64,
}

impl Ribbed {
    fn new(m: &QuasiStaticModel, ribs: &RibContact) -> Result<Self, QuasiStaticError> {
        let r = m.roller_radius_m;
        let phi = ribs.angle_rad;
        if !(phi > 0.0 && phi <= std::f64::consts::FRAC_PI_4) {
            return Err(QuasiStaticError::Invalid(format!(
                "the rib angle (geometry.rib_angle) must lie in (0, 45] deg, got {} deg",
                phi.to_degrees()
            )));
        }
        let h = ribs.contact_height_m;
        if !(h > 0.0 && h < r) {
            return Err(QuasiStaticError::Invalid(format!(
                "the rib contact height (geometry.rib_contact_height) must lie in (0, {r:e}) m (above the raceway, below the roller axis), got {h:e} m"
            )));
        }
        if !(ribs.axial_load_n.is_finite() && ribs.axial_load_n != 0.0) {
            return Err(QuasiStaticError::Invalid(format!(
                "the ribbed solve needs a non-zero finite axial load (operating.axial_load), got {} N",
                ribs.axial_load_n
            )));
        }
        let z = m.roller_count;
        let step = std::f64::consts::TAU / z as f64;
        let (sin, cos): (Vec<f64>, Vec<f64>) = (0..z)
            .map(|j| (m.first_azimuth_rad + step * j as f64).sin_cos())
            .unzip();
        let n = m.slices;
        let l = m.roller_length_m;
        let width = l / n as f64;
        let drop_at = |y: f64| {
            let d = m.profile.drop_m(y, l, r);
            if d >= 0.0 {
                Ok(d)
            } else {
                Err(QuasiStaticError::Invalid(format!(
                    "the roller profile's drop at {y:.4e} m from the middle is {d} m: not a finite relief"
                )))
            }
        };
        let mut points = Vec::with_capacity(n * SUB_LAMINAE * 2);
        let mut slice_axial = Vec::with_capacity(n);
        let mut slice_drop = Vec::with_capacity(n);
        for k in 0..n {
            let y0 = -0.5 * l + k as f64 * width;
            for i in 0..SUB_LAMINAE {
                let ya = y0 + width * i as f64 / SUB_LAMINAE as f64;
                let yb = y0 + width * (i + 1) as f64 / SUB_LAMINAE as f64;
                let (da, db) = (drop_at(ya)?, drop_at(yb)?);
                for t in GAUSS {
                    let d = if da.is_finite() && db.is_finite() {
                        da + t * (db - da)
                    } else {
                        f64::INFINITY
                    };
                    points.push((ya + t * (yb - ya), d, k));
                }
            }
            let yc = y0 + 0.5 * width;
            slice_axial.push(yc);
            slice_drop.push(drop_at(yc)?);
        }
        let l_eff = m.effective_length_m();
        let sub = width / SUB_LAMINAE as f64;
        let law_in = LaminaLaw::new(sub, l_eff, &m.roller, &m.inner);
        let law_out = LaminaLaw::new(sub, l_eff, &m.roller, &m.outer);
        let e = r - h;
        let end_radius = ribs.end_radius_m(r);
        let sigma = ribs.axial_load_n.signum();
        let z1 = -sigma * (0.5 * l - end_radius);
        let r_m = 0.5 * (m.inner_raceway_radius_m + m.outer_raceway_radius_m);
        let rib = |mat: &Material, rho_c: f64, sign: f64| {
            let curvature = CurvatureSum::new(
                1.0 / end_radius + sign * phi.sin() / rho_c,
                1.0 / end_radius,
            )
            .and_then(|c| {
                let e_star = crate::physics::contact::point::reduced_modulus(
                    m.roller.youngs_modulus_pa,
                    m.roller.poisson_ratio,
                    mat.youngs_modulus_pa,
                    mat.poisson_ratio,
                )?;
                HertzPointContact::new(c, e_star, HertzMethod::Exact)
            });
            curvature.map_err(|err| {
                QuasiStaticError::Invalid(format!(
                    "the roller end–rib contact (end sphere radius {end_radius:.4e} m from geometry.rib_angle and geometry.rib_contact_height) is not a Hertz contact: {err}"
                ))
            })
        };
        let rib_in = rib(&m.inner, r_m - e, 1.0)?;
        let rib_out = rib(&m.outer, r_m + e, -1.0)?;
        Ok(Ribbed {
            cos,
            sin,
            points,
            slice_axial,
            slice_drop,
            width,
            k_in: 0.5 * law_in.stiffness,
            k_out: 0.5 * law_out.stiffness,
            law_stiffness_min: law_in.stiffness.min(law_out.stiffness),
            rho: m.radial_interference_m,
            fc: m.centrifugal_n,
            sin_phi: phi.sin(),
            cos_phi: phi.cos(),
            sigma,
            axial: ribs.axial_load_n.abs(),
            z1,
            z2: -z1,
            k_ri: rib_in.stiffness_n_per_m1_5(),
            k_ro: rib_out.stiffness_n_per_m1_5(),
            rib_in,
            rib_out,
            lever: 0.5 * l,
        })
    }

    /// The rib approaches (inner, outer) at (p, z) and roller (s, u, θ).
    fn rib_approaches(&self, p: f64, z: f64, v: [f64; 3]) -> (f64, f64) {
        let [s, u, th] = v;
        let (sp, cp, sg) = (self.sin_phi, self.cos_phi, self.sigma);
        (
            (p - s + th * self.z1) * sp + sg * (z - u) * cp,
            (s - th * self.z2) * sp + sg * u * cp,
        )
    }

    /// Energy, gradient and Hessian of one roller over X = (p, z, s, u, θ).
    fn eval(&self, p: f64, z: f64, v: [f64; 3]) -> RollerSolve {
        let [s, _, th] = v;
        let mut out = RollerSolve {
            v,
            ..RollerSolve::default()
        };
        let base_in = p + self.rho - s;
        let base_out = s + self.rho;
        // Slices: inner a = (1, 0, −1, 0, y), outer a = (0, 0, 1, 0, −y). Accumulate the
        // moments Σf, Σf·y, Σk, Σk·y, Σk·y² per contact and expand once.
        let (mut ei, mut fi, mut fiy, mut ki, mut kiy, mut kiyy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        let (mut eo, mut fo, mut foy, mut ko, mut koy, mut koyy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        for &(y, d, _) in &self.points {
            let (e, f, k) = lamina(self.k_in, base_in + th * y - d);
            ei += e;
            fi += f;
            fiy += f * y;
            ki += k;
            kiy += k * y;
            kiyy += k * y * y;
            let (e, f, k) = lamina(self.k_out, base_out - th * y - d);
            eo += e;
            fo += f;
            foy += f * y;
            ko += k;
            koy += k * y;
            koyy += k * y * y;
        }
        let g = &mut out.grad;
        let hm = &mut out.hess;
        // Inner: ∂/∂p = f, ∂/∂s = −f, ∂/∂θ = f·y.
        g[0] += fi;
        g[2] -= fi;
        g[4] += fiy;
        hm[0][0] += ki;
        hm[0][2] -= ki;
        hm[0][4] += kiy;
        hm[2][2] += ki;
        hm[2][4] -= kiy;
        hm[4][4] += kiyy;
        // Outer: ∂/∂s = f, ∂/∂θ = −f·y.
        g[2] += fo;
        g[4] -= foy;
        hm[2][2] += ko;
        hm[2][4] -= koy;
        hm[4][4] += koyy;
        // Ribs.
        let (sp, cp, sg) = (self.sin_phi, self.cos_phi, self.sigma);
        let (dri, dro) = self.rib_approaches(p, z, v);
        let (eri, qri, kri) = hertz(self.k_ri, dri);
        let (ero, qro, kro) = hertz(self.k_ro, dro);
        let a_ri = [sp, sg * cp, -sp, -sg * cp, self.z1 * sp];
        let a_ro = [0.0, 0.0, sp, sg * cp, -self.z2 * sp];
        for (q, k, a) in [(qri, kri, a_ri), (qro, kro, a_ro)] {
            for i in 0..5 {
                g[i] += q * a[i];
                for jj in i..5 {
                    hm[i][jj] += k * a[i] * a[jj];
                }
            }
        }
        // Centrifugal force pushes the roller outward: energy −F_c·s.
        g[2] -= self.fc;
        for i in 0..5 {
            for jj in 0..i {
                hm[i][jj] = hm[jj][i];
            }
        }
        out.energy = ei + eo + eri + ero - self.fc * s;
        out.w_in = fi;
        out.w_out = fo;
        out.q_ri = qri;
        out.q_ro = qro;
        out
    }

    /// A roller's residual in N (moments over l/2).
    fn roller_residual(&self, r: &RollerSolve) -> f64 {
        r.grad[2]
            .abs()
            .max(r.grad[3].abs())
            .max(r.grad[4].abs() / self.lever)
    }

    /// One roller's equilibrium (s, u, θ) at the ring's (p, z), Newton with a line
    /// search on its (convex) energy from `guess`.
    fn roller(&self, p: f64, z: f64, guess: [f64; 3]) -> RollerSolve {
        let mut cur = self.eval(p, z, guess);
        for _ in 0..MAX_ROLLER_ITERATIONS {
            let scale = cur.w_in + cur.w_out + cur.q_ri + cur.q_ro + self.fc;
            let res = self.roller_residual(&cur);
            if res <= 1e-13 * scale.max(1e-300) || res == 0.0 {
                break;
            }
            let c = sub3(&cur.hess);
            let g = [cur.grad[2], cur.grad[3], cur.grad[4]];
            let Some(mut dv) = solve3(regularise(c), [-g[0], -g[1], -g[2]]) else {
                break;
            };
            // An unloaded direction (a floating roller pushed by F_c alone) has no
            // curvature: cap the step at a few contact approaches.
            let cap = 1e-3 * self.lever;
            let len = dv[0].abs().max(dv[1].abs()).max(dv[2].abs() * self.lever);
            if !(len.is_finite()) {
                break;
            }
            if len > cap {
                for x in &mut dv {
                    *x *= cap / len;
                }
            }
            let slope = g[0] * dv[0] + g[1] * dv[1] + g[2] * dv[2];
            let mut alpha = 1.0;
            let mut next = None;
            for _ in 0..60 {
                let v = [
                    cur.v[0] + alpha * dv[0],
                    cur.v[1] + alpha * dv[1],
                    cur.v[2] + alpha * dv[2],
                ];
                let e = self.eval(p, z, v);
                if e.energy <= cur.energy + 1e-4 * alpha * slope
                    || self.roller_residual(&e) < 0.5 * res
                {
                    next = Some(e);
                    break;
                }
                alpha *= 0.5;
            }
            match next {
                Some(e) if e.v != cur.v => cur = e,
                _ => break,
            }
        }
        cur
    }
}

/// The roller block C (over s, u, θ) of a 5×5 Hessian.
fn sub3(h: &[[f64; 5]; 5]) -> [[f64; 3]; 3] {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = h[i + 2][j + 2];
        }
    }
    c
}

/// C with its diagonal raised by 1e-12 of itself (a unit where it is zero: a direction
/// no contact holds, whose gradient is then zero too or capped by the caller).
fn regularise(mut c: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    for (i, row) in c.iter_mut().enumerate() {
        let d = row[i];
        row[i] = if d > 0.0 { d * (1.0 + 1e-12) } else { 1.0 };
    }
    c
}

/// Solves a 3×3 system by Gaussian elimination with partial pivoting.
fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> Option<[f64; 3]> {
    for col in 0..3 {
        let piv = (col..3).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if !(a[piv][col].abs() > 0.0) {
            return None;
        }
        a.swap(col, piv);
        b.swap(col, piv);
        for row in col + 1..3 {
            let f = a[row][col] / a[col][col];
            for k in col..3 {
                a[row][k] -= f * a[col][k];
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 3];
    for i in (0..3).rev() {
        let mut s = b[i];
        for k in i + 1..3 {
            s -= a[i][k] * x[k];
        }
        x[i] = s / a[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The inverse of a 3×3 matrix, column by column.
fn inverse3(a: [[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    let mut inv = [[0.0; 3]; 3];
    for c in 0..3 {
        let mut e = [0.0; 3];
        e[c] = 1.0;
        let x = solve3(a, e)?;
        for r in 0..3 {
            inv[r][c] = x[r];
        }
    }
    Some(inv)
}

/// The ring at (x, y, z) with every roller in equilibrium: the contact force on the
/// inner ring, its exact Jacobian (the 3×3 stiffness), the potential and the rollers.
struct RingEval {
    rollers: Vec<RollerSolve>,
    force: [f64; 3],
    stiffness: [[f64; 3]; 3],
    potential: f64,
    roller_residual: f64,
}

fn evaluate(rb: &Ribbed, load: [f64; 3], xyz: [f64; 3], guesses: &[[f64; 3]]) -> RingEval {
    let mut force = [0.0; 3];
    let mut k = [[0.0; 3]; 3];
    let mut potential = -(load[0] * xyz[0] + load[1] * xyz[1] + load[2] * xyz[2]);
    let mut roller_residual: f64 = 0.0;
    let rollers: Vec<RollerSolve> = (0..rb.cos.len())
        .map(|j| {
            let (c, s) = (rb.cos[j], rb.sin[j]);
            let p = xyz[0] * c + xyz[1] * s;
            let r = rb.roller(p, xyz[2], guesses[j]);
            roller_residual = roller_residual.max(rb.roller_residual(&r));
            // (p, z) force and the Schur complement A − B·C⁻¹·Bᵀ (2×2 over p, z).
            let h = &r.hess;
            let schur = match inverse3(regularise(sub3(h))) {
                Some(ci) => {
                    let mut m = [[h[0][0], h[0][1]], [h[1][0], h[1][1]]];
                    for a in 0..2 {
                        for b in 0..2 {
                            let mut sum = 0.0;
                            for i in 0..3 {
                                for jj in 0..3 {
                                    sum += h[a][i + 2] * ci[i][jj] * h[b][jj + 2];
                                }
                            }
                            m[a][b] -= sum;
                        }
                    }
                    m
                }
                None => [[0.0; 2]; 2],
            };
            let t = [[c, s, 0.0], [0.0, 0.0, 1.0]];
            for a in 0..3 {
                force[a] += t[0][a] * r.grad[0] + t[1][a] * r.grad[1];
                for b in 0..3 {
                    let mut sum = 0.0;
                    for i in 0..2 {
                        for jj in 0..2 {
                            sum += t[i][a] * schur[i][jj] * t[jj][b];
                        }
                    }
                    k[a][b] += sum;
                }
            }
            potential += r.energy;
            r
        })
        .collect();
    // Symmetric by construction up to round-off: make it exactly so.
    for a in 0..3 {
        for b in 0..a {
            let m = 0.5 * (k[a][b] + k[b][a]);
            k[a][b] = m;
            k[b][a] = m;
        }
    }
    RingEval {
        rollers,
        force,
        stiffness: k,
        potential,
        roller_residual,
    }
}

fn norm3(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Solves the ring equilibrium of a bearing ribbed on both rings under the model's
/// radial load and `ribs.axial_load_n`, from `start` (a previous ribbed solution) or
/// from the radial solve's equilibrium with the ribs engaged evenly. Converged when the
/// ring's force residual and every roller's (moments over l/2) are at most
/// tolerance·max(|F|, 1 N) (F = (F_x, F_y, F_a)).
pub fn solve_ribbed(
    model: &QuasiStaticModel,
    ribs: &RibContact,
    start: Option<&QuasiStatic>,
    cancel: &Cancel,
) -> Result<QuasiStatic, QuasiStaticError> {
    validate(model)?;
    let rb = Ribbed::new(model, ribs)?;
    let z = model.roller_count;
    let load = [model.load_n[0], model.load_n[1], rb.sigma * rb.axial];
    let tol_n = model.tolerance * norm3(load).max(1.0);
    // Start: the radial equilibrium (or the given ribbed one); each roller's rib contacts
    // at the approach δ₀ of an even share |F_a|/(Z cos φ), z so that every roller reaches
    // 2δ₀ in all, u splitting it evenly.
    let (mut xyz, mut guesses): ([f64; 3], Vec<[f64; 3]>) = match start {
        Some(s)
            if s.rollers.len() == z
                && s.stiffness_xyz_n_m.is_some()
                && s.displacement_m.iter().all(|v| v.is_finite())
                && s.axial_displacement_m.is_finite() =>
        {
            let g = s
                .rollers
                .iter()
                .enumerate()
                .map(|(j, r)| {
                    let p = s.displacement_m[0] * rb.cos[j] + s.displacement_m[1] * rb.sin[j];
                    [
                        p + rb.rho - r.inner_approach_m,
                        r.axial_position_m,
                        r.tilt_rad,
                    ]
                })
                .collect();
            (
                [
                    s.displacement_m[0],
                    s.displacement_m[1],
                    s.axial_displacement_m,
                ],
                g,
            )
        }
        _ => {
            let radial = super::quasi_static::solve(model, None, cancel)?;
            let xy = radial.displacement_m;
            let q0 = rb.axial / (z as f64 * rb.cos_phi);
            let d0 = (q0 / rb.k_ri.min(rb.k_ro)).powf(2.0 / 3.0);
            let ps: Vec<f64> = (0..z)
                .map(|j| xy[0] * rb.cos[j] + xy[1] * rb.sin[j])
                .collect();
            let p_min = ps.iter().copied().fold(f64::INFINITY, f64::min);
            // δ_ri + δ_ro = p·sin φ + σz·cos φ at zero tilt.
            let zz = rb.sigma * (2.0 * d0 - p_min * rb.sin_phi) / rb.cos_phi;
            let g = radial
                .rollers
                .iter()
                .zip(&ps)
                .map(|(r, &p)| {
                    let s = p + rb.rho - r.inner_approach_m;
                    let total = p * rb.sin_phi + rb.sigma * zz * rb.cos_phi;
                    // δ_ro = s·sin φ + σu·cos φ = total/2.
                    let u = rb.sigma * (0.5 * total - s * rb.sin_phi) / rb.cos_phi;
                    [s, u, 0.0]
                })
                .collect();
            ([xy[0], xy[1], zz], g)
        }
    };
    let n_points = rb.points.len() as f64;
    let k_roller = n_points * 0.5 * rb.law_stiffness_min;
    let delta_ref = (4.1 * norm3(load) / z as f64 / k_roller).powf(0.9);
    let step_cap = 10.0 * (delta_ref + rb.rho.abs() + 1e-9);
    let mut ring = evaluate(&rb, load, xyz, &guesses);
    let mut iterations = 0;
    loop {
        let residual = [
            ring.force[0] - load[0],
            ring.force[1] - load[1],
            ring.force[2] - load[2],
        ];
        let r = norm3(residual);
        let floor = 1e-13 * ring.rollers.iter().map(|e| e.w_in + e.q_ri).sum::<f64>();
        if r <= tol_n.max(floor) && ring.roller_residual <= tol_n.max(floor) {
            break;
        }
        if iterations >= MAX_RING_ITERATIONS {
            return Err(QuasiStaticError::NotConverged {
                iterations,
                residual_n: r.max(ring.roller_residual),
                tolerance_n: tol_n,
            });
        }
        if cancel.is_cancelled() {
            return Err(QuasiStaticError::Cancelled);
        }
        iterations += 1;
        let mut k = ring.stiffness;
        let trace = k[0][0] + k[1][1] + k[2][2];
        for (i, row) in k.iter_mut().enumerate() {
            row[i] += 1e-12 * trace.max(1e-300);
        }
        let mut dir = solve3(k, [-residual[0], -residual[1], -residual[2]]).unwrap_or([
            -residual[0] / r * step_cap,
            -residual[1] / r * step_cap,
            -residual[2] / r * step_cap,
        ]);
        let len = norm3(dir);
        if !(len.is_finite()) || len > step_cap {
            let f = if len.is_finite() { step_cap / len } else { 0.0 };
            for d in &mut dir {
                *d *= f;
            }
        }
        let slope = residual[0] * dir[0] + residual[1] * dir[1] + residual[2] * dir[2];
        for (g, roller) in guesses.iter_mut().zip(&ring.rollers) {
            *g = roller.v;
        }
        let mut alpha = 1.0;
        let mut accepted = None;
        for _ in 0..60 {
            let trial = [
                xyz[0] + alpha * dir[0],
                xyz[1] + alpha * dir[1],
                xyz[2] + alpha * dir[2],
            ];
            let e = evaluate(&rb, load, trial, &guesses);
            let res = norm3([
                e.force[0] - load[0],
                e.force[1] - load[1],
                e.force[2] - load[2],
            ]);
            if e.potential <= ring.potential + 1e-4 * alpha * slope || res < 0.5 * r {
                accepted = Some((trial, e));
                break;
            }
            alpha *= 0.5;
        }
        match accepted {
            Some((trial, e)) => {
                xyz = trial;
                ring = e;
            }
            None => {
                return Err(QuasiStaticError::NotConverged {
                    iterations,
                    residual_n: r,
                    tolerance_n: tol_n,
                })
            }
        }
    }
    // The rib contact must stay on the rib: its ellipse's radial (transverse) semi-axis
    // below the contact height, else it runs into the raceway's corner and the Hertz
    // contact no longer describes it.
    let mut worst: Option<(usize, f64, f64)> = None;
    for (j, r) in ring.rollers.iter().enumerate() {
        for (q, c) in [(r.q_ri, &rb.rib_in), (r.q_ro, &rb.rib_out)] {
            if let Ok(pc) = c.solve(q) {
                let a = pc.semi_axis_transverse_m();
                if a >= ribs.contact_height_m && worst.is_none_or(|w| a > w.2) {
                    worst = Some((j, q, a));
                }
            }
        }
    }
    if let Some((j, q, a)) = worst {
        return Err(QuasiStaticError::Invalid(format!(
            "operating.axial_load = {} N is more than the ribs can carry: roller {} presses its rib with {q:.4e} N, a contact ellipse {a:.4e} m high, reaching past the contact height geometry.rib_contact_height = {:.4e} m into the raceway's corner (lower the axial load or raise the contact height)",
            ribs.axial_load_n,
            j + 1,
            ribs.contact_height_m
        )));
    }
    let residual_n = norm3([
        ring.force[0] - load[0],
        ring.force[1] - load[1],
        ring.force[2] - load[2],
    ]);
    Ok(report(model, &rb, xyz, &ring, iterations, residual_n))
}

/// The contact force (F_x, F_y, F_z) on the inner ring at (x, y, z) with every roller in
/// equilibrium, and the analytic stiffness there (for the finite-difference test).
#[cfg(test)]
pub(super) fn ribbed_force(
    model: &QuasiStaticModel,
    ribs: &RibContact,
    xyz: [f64; 3],
    guesses: &[[f64; 3]],
) -> ([f64; 3], [[f64; 3]; 3]) {
    let rb = match Ribbed::new(model, ribs) {
        Ok(rb) => rb,
        Err(e) => panic!("{e}"),
    };
    let e = evaluate(&rb, [0.0; 3], xyz, guesses);
    (e.force, e.stiffness)
}

fn report(
    model: &QuasiStaticModel,
    rb: &Ribbed,
    xyz: [f64; 3],
    ring: &RingEval,
    iterations: usize,
    residual_n: f64,
) -> QuasiStatic {
    let elastic = |m: &Material| Elastic {
        youngs_modulus_pa: m.youngs_modulus_pa,
        poisson_ratio: m.poisson_ratio,
    };
    let r = model.roller_radius_m;
    let radius_in = 1.0 / (1.0 / r + 1.0 / model.inner_raceway_radius_m);
    let radius_out = 1.0 / (1.0 / r - 1.0 / model.outer_raceway_radius_m);
    let e_in = reduced_modulus(elastic(&model.roller), elastic(&model.inner));
    let e_out = reduced_modulus(elastic(&model.roller), elastic(&model.outer));
    let step = std::f64::consts::TAU / model.roller_count as f64;
    let w = rb.width;
    let n = rb.slice_axial.len();
    let rollers = ring
        .rollers
        .iter()
        .enumerate()
        .map(|(j, eq)| {
            let p = xyz[0] * rb.cos[j] + xyz[1] * rb.sin[j];
            let [s, u, th] = eq.v;
            let base_in = p + rb.rho - s;
            let base_out = s + rb.rho;
            let mut qi = vec![0.0; n];
            let mut qo = vec![0.0; n];
            for &(y, d, k) in &rb.points {
                qi[k] += lamina(rb.k_in, base_in + th * y - d).1;
                qo[k] += lamina(rb.k_out, base_out - th * y - d).1;
            }
            let slices = (0..n)
                .map(|k| {
                    let ci = line_contact_reduced(qi[k] / w, radius_in, e_in);
                    let co = line_contact_reduced(qo[k] / w, radius_out, e_out);
                    SliceState {
                        axial_m: rb.slice_axial[k],
                        profile_drop_m: rb.slice_drop[k],
                        inner_load_n: qi[k],
                        outer_load_n: qo[k],
                        inner_half_width_m: ci.half_width_m,
                        outer_half_width_m: co.half_width_m,
                        inner_max_pressure_pa: ci.max_pressure_pa,
                        outer_max_pressure_pa: co.max_pressure_pa,
                    }
                })
                .collect();
            RollerState {
                azimuth_rad: model.first_azimuth_rad + step * j as f64,
                inner_load_n: eq.w_in,
                outer_load_n: eq.w_out,
                inner_approach_m: base_in,
                outer_approach_m: base_out,
                slices,
                tilt_rad: th,
                axial_position_m: u,
                inner_rib_load_n: eq.q_ri,
                outer_rib_load_n: eq.q_ro,
                rib_load_n: 0.5 * (eq.q_ri + eq.q_ro),
            }
        })
        .collect();
    let k = ring.stiffness;
    QuasiStatic {
        displacement_m: [xyz[0], xyz[1]],
        rollers,
        stiffness_n_m: [[k[0][0], k[0][1]], [k[1][0], k[1][1]]],
        iterations,
        residual_n,
        axial_displacement_m: xyz[2],
        stiffness_xyz_n_m: Some(k),
    }
}
