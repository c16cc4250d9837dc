//! The loaded rollers' skew and the guide-ring load it drives (issue 27 Model 2 "skew
//! moments … reacted at the pockets and the guide ring"; seed 002 §6), SI.
//!
//! # Kinematics of a skewed roller (derived here; Harris & Kotzalas, *Advanced Concepts of
//! Bearing Technology*, 5th ed., roller skewing)
//! In a row's frame let a be the roller axis, ê_θ the bearing's rotation direction at the
//! roller and n = a × ê_θ the skew (yaw) axis. A skew ψ about n turns the axis to
//! a′ = a + ψ·(n × a) = a + ψ·ê_θ (first order; (a × ê_θ) × a = ê_θ). A point of the roller
//! at p − c = y·a + d (d ⊥ a) then moves, relative to the cage, at
//! ω_s·a′ × (p − c) = ω_s·a × d + ψ·ω_s·ê_θ × (y·a + d). With m = (a × d)·ê_θ (the
//! spin arm of `losses.rs`: ω_s·m is the roller surface's circumferential speed) the
//! tangential part of the extra term is −ψ·ω_s·m·a (ê_θ × d = −m·a for d in the meridian
//! plane; its y part, y·ê_θ × a = −y·n, is along the contact normal and does not slide). The
//! rings move along ê_θ only, so a skewed roller's raceway contact slides **axially** at
//!
//! v_a = ψ·ω_s·m (ring minus roller, along +a)
//!
//! beside its circumferential sliding v_θ (unchanged to first order). The inner and outer
//! contacts have opposite m, so their axial slidings are opposite: the axial tractions form
//! a couple about ê_θ (a pitch moment) and their **difference** is a net force N along the
//! roller axis.
//!
//! # Traction at a lamina
//! The lubricant's shear law is isotropic (eq. 3's Newtonian branch and the ATZ limiting
//! shear act on the local shear stress's magnitude along the sliding): the lamina's
//! traction has the magnitude F(|v|) of the law at the sliding speed |v| = √(v_θ² + v_a²)
//! and the direction of v: F_θ = F·v_θ/|v|, F_a = F·v_a/|v| ([`skewed_lamina`]). Its
//! dissipation F·|v| = F_θ·v_θ + F_a·v_a splits exactly into the rolling-direction part
//! (booked to the raceway) and the skew's part (booked to `skew_w`).
//!
//! # Moments about the skew axis n through the roller centre
//! * the raceways: M_s(ψ) = Σ y_k·F_θ,k(ψ) (the axial tractions are parallel to a: no yaw).
//!   Under a saturating law |F_θ| falls as v_a grows (the traction turns axial): that is the
//!   raceways' restoring; on a Newtonian lamina F_θ = k·v_θ does not depend on ψ (none);
//! * the guide ring: a roller's end is a sphere of radius r_e centred L/2 − r_e from the
//!   roller centre along −a′; it touches the ring's flat face (normal a⁰, fixed) at
//!   c − (L/2)·a + (r_e − L/2)·ψ·ê_θ: **off the roller axis by δ = (r_e − L/2)·ψ** along ê_θ.
//!   Its normal force Q·a on the roller has the yaw moment M_g = −(r_e − L/2)·ψ·Q (restoring
//!   for r_e > L/2, the usual end-sphere design). The ring is at the roller's −a end: it is
//!   pressed by N when N < 0, with Q = max(0, −N) (unilateral; N > 0 pushes the roller
//!   away from the ring, into its raceway groove);
//! * the pocket: a roller skews freely inside its pocket play up to ψ_max = c_p/L (the two
//!   ends meet opposite pocket faces); there the pocket reacts the rest as a couple.
//!
//! # The skew angle ([`roller_skew`])
//! ψ has the sign of the unskewed yaw moment M_s(0) (the moment turns the roller); its size
//! solves h(ψ) = M_s(ψ) + M_g(ψ) = 0 on (0, ψ_max], else ψ = ψ_max and the pocket takes
//! h(ψ_max). M_s(0) = 0 (a roller rolling without a yaw moment) gives ψ = 0, and ψ = 0
//! gives exactly the unskewed tractions (no axial sliding): today's answers.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};

use crate::physics::lubrication::lamina_friction::{
    lamina_friction, FilmRheology, LaminaFrictionError, LaminaSlice, RacewayTractionLaw,
};

/// One lamina's traction with an axial sliding (module notes "Traction at a lamina").
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct SkewedLamina {
    /// F_θ, traction on the roller along +θ, N.
    pub circumferential_n: f64,
    /// F_a, traction on the roller along the roller axis +a, N.
    pub axial_n: f64,
    /// F_θ·v_θ ≥ 0, W.
    pub rolling_power_w: f64,
    /// F_a·v_a ≥ 0, W.
    pub skew_power_w: f64,
    /// True when the printed eq. 3 gives μ > 0.2 at |v|.
    pub flagged: bool,
}

/// The traction of lamina `slice` (its `sliding_speed_m_s` the circumferential sliding
/// v_θ) with the axial sliding `axial_sliding_m_s` v_a: the law's force at |v| along v
/// (module notes). v_a = 0 is exactly [`lamina_friction`].
///
/// # Errors
/// As [`lamina_friction`].
pub fn skewed_lamina(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    slice: &LaminaSlice,
    axial_sliding_m_s: f64,
) -> Result<SkewedLamina, LaminaFrictionError> {
    let (vt, va) = (slice.sliding_speed_m_s, axial_sliding_m_s);
    if va == 0.0 {
        let f = lamina_friction(law, rheology, slice)?;
        return Ok(SkewedLamina {
            circumferential_n: f.force_n,
            axial_n: 0.0,
            rolling_power_w: f.power_w,
            skew_power_w: 0.0,
            flagged: f.exceeds_newtonian_bound,
        });
    }
    if !va.is_finite() {
        return Err(LaminaFrictionError::BadInput {
            name: "axial sliding speed",
            value: va,
            allowed: "any sign",
        });
    }
    let s = vt.hypot(va);
    let f = lamina_friction(
        law,
        rheology,
        &LaminaSlice {
            sliding_speed_m_s: s,
            ..*slice
        },
    )?;
    let (ft, fa) = (f.force_n * vt / s, f.force_n * va / s);
    Ok(SkewedLamina {
        circumferential_n: ft,
        axial_n: fa,
        rolling_power_w: ft * vt,
        skew_power_w: fa * va,
        flagged: f.exceeds_newtonian_bound,
    })
}

/// What bounds and reacts a roller's skew, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SkewGeometry {
    /// ψ_max = c_p/L, the skew the pocket play allows, rad (≥ 0; 0 turns skew off).
    pub max_skew_rad: f64,
    /// r_e − L/2, the end contact's offset from the roller axis per unit skew, m; `None`
    /// without a guide ring (the pocket alone reacts the skew).
    pub end_offset_per_rad_m: Option<f64>,
}

/// One raceway contact of a roller at its skew: sums over its laminae.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct SkewedContact {
    /// Σ F_θ·v_θ, W.
    pub rolling_power_w: f64,
    /// Σ F_a·v_a, W.
    pub skew_power_w: f64,
    /// Σ y·F_θ, N·m.
    pub yaw_moment_nm: f64,
    /// Σ F_θ, N.
    pub circumferential_n: f64,
    /// Σ F_a, N.
    pub axial_n: f64,
    /// Laminae flagged by the printed eq. 3.
    pub flagged: usize,
}

/// A roller at its skew (module notes "The skew angle").
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RollerSkew {
    /// ψ, rad (sign of the unskewed yaw moment).
    pub skew_rad: f64,
    /// M_s(0), the raceways' yaw moment of the unskewed roller, N·m.
    pub unskewed_yaw_moment_nm: f64,
    /// M_g, the guide ring's yaw moment on the roller, N·m.
    pub ring_moment_nm: f64,
    /// h = M_s(ψ) + M_g, what the pocket reacts (0 unless ψ = ±ψ_max), N·m.
    pub pocket_moment_nm: f64,
    /// N, the raceways' net axial traction on the roller along +a, N.
    pub axial_traction_n: f64,
    /// Q = max(0, −N) with a guide ring (else 0), the skew's end load on the ring, N.
    pub guide_ring_load_n: f64,
    /// Inner raceway.
    pub inner: SkewedContact,
    /// Outer raceway.
    pub outer: SkewedContact,
    /// True when the pocket stops the skew (ψ = ±ψ_max).
    pub pocket_limited: bool,
    /// Evaluations of the roller's laminae in the search.
    pub evaluations: usize,
}

impl RollerSkew {
    /// M_s(ψ) = Σ y·F_θ over both raceways, N·m.
    pub fn yaw_moment_nm(&self) -> f64 {
        self.inner.yaw_moment_nm + self.outer.yaw_moment_nm
    }
}

/// A lamina the skew search could not evaluate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SkewLaminaError {
    /// 0 inner, 1 outer.
    pub raceway: usize,
    /// Lamina index.
    pub lamina: usize,
    /// The lamina's error.
    pub source: LaminaFrictionError,
}

/// Both raceways of a roller at skew ψ: `laminae[k]` with `roller_speeds[k]` (ω_s·m per
/// lamina, m/s), v_a = ψ·ω_s·m.
fn contacts_at(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    laminae: [&[LaminaSlice]; 2],
    roller_speeds: [&[f64]; 2],
    psi: f64,
) -> Result<[SkewedContact; 2], SkewLaminaError> {
    let mut out = [SkewedContact::default(); 2];
    for (k, c) in out.iter_mut().enumerate() {
        for (j, s) in laminae[k].iter().enumerate() {
            let u = roller_speeds[k].get(j).copied().unwrap_or(0.0);
            let t = skewed_lamina(law, rheology, s, psi * u).map_err(|source| SkewLaminaError {
                raceway: k,
                lamina: j,
                source,
            })?;
            c.rolling_power_w += t.rolling_power_w;
            c.skew_power_w += t.skew_power_w;
            c.yaw_moment_nm += s.axial_offset_m * t.circumferential_n;
            c.circumferential_n += t.circumferential_n;
            c.axial_n += t.axial_n;
            c.flagged += usize::from(t.flagged);
        }
    }
    Ok(out)
}

/// The roller at skew ψ from its two raceways' sums at ψ (`contacts_at`): the axial
/// traction's end load and the ring's yaw moment.
fn skew_of_contacts(
    geometry: &SkewGeometry,
    psi: f64,
    inner: SkewedContact,
    outer: SkewedContact,
) -> RollerSkew {
    let n = inner.axial_n + outer.axial_n;
    let (q, mg) = match geometry.end_offset_per_rad_m {
        Some(off) => {
            let q = (-n).max(0.0);
            (q, -off * psi * q)
        }
        None => (0.0, 0.0),
    };
    RollerSkew {
        skew_rad: psi,
        unskewed_yaw_moment_nm: 0.0,
        ring_moment_nm: mg,
        pocket_moment_nm: inner.yaw_moment_nm + outer.yaw_moment_nm + mg,
        axial_traction_n: n,
        guide_ring_load_n: q,
        inner,
        outer,
        pocket_limited: false,
        evaluations: 0,
    }
}

/// The roller at ψ = 0 as [`roller_skew`] reports it before (or without) a search.
fn unskewed(mut r0: RollerSkew) -> RollerSkew {
    r0.unskewed_yaw_moment_nm = r0.pocket_moment_nm;
    r0.evaluations = 1;
    r0
}

/// [`roller_skew`] of a roller that does not skew (`geometry.max_skew_rad` = 0, the
/// default losses) from its raceways' sums at ψ = 0 (`contacts`, [inner, outer], each as
/// `contacts_at` forms it: Σ F·v, Σ y·F, Σ F, the flagged count; no axial terms): the same
/// [`RollerSkew`] bit for bit, without integrating the laminae again (the double-row cage
/// balance has the sums from each roller's spin solve).
pub fn unskewed_from_contacts(geometry: &SkewGeometry, contacts: [SkewedContact; 2]) -> RollerSkew {
    let [inner, outer] = contacts;
    unskewed(skew_of_contacts(geometry, 0.0, inner, outer))
}

/// The skew of one roller (module notes): `laminae` = [inner, outer] with their
/// circumferential sliding, `roller_speeds` the roller surface's circumferential speed ω_s·m
/// at each lamina (m/s, same lengths; a missing entry counts as 0).
///
/// # Errors
/// [`SkewLaminaError`] naming the raceway and lamina whose traction failed.
pub fn roller_skew(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    geometry: &SkewGeometry,
    laminae: [&[LaminaSlice]; 2],
    roller_speeds: [&[f64]; 2],
) -> Result<RollerSkew, SkewLaminaError> {
    let eval = |psi: f64| -> Result<RollerSkew, SkewLaminaError> {
        let [inner, outer] = contacts_at(law, rheology, laminae, roller_speeds, psi)?;
        Ok(skew_of_contacts(geometry, psi, inner, outer))
    };
    let r0 = unskewed(eval(0.0)?);
    let m0 = r0.pocket_moment_nm;
    let psi_max = geometry.max_skew_rad;
    if m0 == 0.0 || !(psi_max.is_finite() && psi_max > 0.0) {
        return Ok(r0);
    }
    let sigma = m0.signum();
    // h along the turning direction: σ·h(σ·t), positive at t = 0.
    let mut count = 1usize;
    let mut at = |t: f64| -> Result<(f64, RollerSkew), SkewLaminaError> {
        count += 1;
        let r = eval(sigma * t)?;
        Ok((sigma * r.pocket_moment_nm, r))
    };
    let (g_hi, mut r_hi) = at(psi_max)?;
    if g_hi >= 0.0 {
        // The raceways and the ring cannot hold it: the pocket stops it at ψ_max.
        r_hi.pocket_limited = true;
        r_hi.unskewed_yaw_moment_nm = m0;
        r_hi.evaluations = count;
        return Ok(r_hi);
    }
    // Illinois false position on (0, ψ_max]: g(0) = |M_s(0)| > 0 > g(ψ_max).
    let (mut a, mut fa, mut b, mut fb) = (0.0, sigma * m0, psi_max, g_hi);
    let mut best = r_hi;
    let mut side = 0i8;
    for _ in 0..100 {
        let mut t = (a * fb - b * fa) / (fb - fa);
        if !(t.is_finite() && t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let (g, r) = at(t)?;
        best = r;
        if g.abs() <= SKEW_MOMENT_TOLERANCE * m0.abs() || b - a <= 1e-12 * psi_max {
            break;
        }
        if g > 0.0 {
            a = t;
            fa = g;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        } else {
            b = t;
            fb = g;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        }
    }
    // The ring holds it: the pocket reacts nothing beyond the search's residual.
    best.unskewed_yaw_moment_nm = m0;
    best.evaluations = count;
    Ok(best)
}

/// A roller at a given skew ψ (solved elsewhere with its loads: `[cage] skew =
/// "self-guided"`, `losses::kellstrom`): the tractions at ψ, the guide ring's yaw moment
/// M_g = −(r_e − L/2)·ψ·Q with Q = `end_load_n` (the statics' end load, which already holds
/// the axial tractions' push), and the pocket's share h = M_s(ψ) + M_g (the yaw balance's
/// residual inside the play; what the pocket stops at |ψ| = ψ_max). `unskewed_yaw_moment_nm`
/// is M_s at ψ = 0 on the same laminae; `guide_ring_load_n` is 0 (no end load beyond the
/// statics'). ψ = 0 is exactly the unskewed roller.
///
/// # Errors
/// [`SkewLaminaError`] naming the raceway and lamina whose traction failed.
pub fn roller_skew_at(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    geometry: &SkewGeometry,
    laminae: [&[LaminaSlice]; 2],
    roller_speeds: [&[f64]; 2],
    psi: f64,
    end_load_n: f64,
) -> Result<RollerSkew, SkewLaminaError> {
    let [i0, o0] = contacts_at(law, rheology, laminae, roller_speeds, 0.0)?;
    let m0 = i0.yaw_moment_nm + o0.yaw_moment_nm;
    let [inner, outer] = if psi == 0.0 {
        [i0, o0]
    } else {
        contacts_at(law, rheology, laminae, roller_speeds, psi)?
    };
    let mg = geometry
        .end_offset_per_rad_m
        .map_or(0.0, |off| -off * psi * end_load_n.max(0.0));
    let psi_max = geometry.max_skew_rad;
    Ok(RollerSkew {
        skew_rad: psi,
        unskewed_yaw_moment_nm: m0,
        ring_moment_nm: mg,
        pocket_moment_nm: inner.yaw_moment_nm + outer.yaw_moment_nm + mg,
        axial_traction_n: inner.axial_n + outer.axial_n,
        guide_ring_load_n: 0.0,
        inner,
        outer,
        pocket_limited: psi_max > 0.0 && psi.abs() >= psi_max * (1.0 - 1e-12),
        evaluations: if psi == 0.0 { 1 } else { 2 },
    })
}

/// The skew search stops when |h(ψ)| ≤ this × |M_s(0)| (or the bracket is below 1e-12 of
/// ψ_max).
pub const SKEW_MOMENT_TOLERANCE: f64 = 1e-9;

#[cfg(test)]
mod tests {
    use super::*;

    fn oil() -> FilmRheology {
        FilmRheology {
            viscosity_pa_s: 0.02,
            pressure_viscosity_pa_inv: 2.0e-8,
            transition_shear_stress_pa: 5.0e6,
            limiting_traction_coefficient: 0.06,
        }
    }

    fn lamina(q: f64, v: f64, y: f64) -> LaminaSlice {
        let (b, l) = (1.5e-4, 2.5e-4);
        LaminaSlice {
            load_n: q,
            half_width_m: b,
            length_m: l,
            peak_pressure_pa: 2.0 * q / (std::f64::consts::PI * b * l),
            rolling_speed_m_s: 5.0,
            sliding_speed_m_s: v,
            film_m: 3e-7,
            axial_offset_m: y,
        }
    }

    /// A roller with Heathcote-like sliding: the inner contact slides forward at its ends
    /// and back in its middle, the outer the other way, with a net yaw moment.
    fn roller(vscale: f64) -> (Vec<LaminaSlice>, Vec<LaminaSlice>, Vec<f64>, Vec<f64>) {
        let ys: Vec<f64> = (0..11).map(|j| (j as f64 - 5.0) * 1e-3).collect();
        let inner: Vec<_> = ys
            .iter()
            .map(|&y| lamina(300.0, vscale * (0.02 + 8e3 * y * y + 5.0 * y), y))
            .collect();
        let outer: Vec<_> = ys
            .iter()
            .map(|&y| lamina(320.0, vscale * (-0.02 - 6e3 * y * y + 2.0 * y), y))
            .collect();
        // ω_s·m: the inner contact's roller surface moves backward (m < 0), the outer forward.
        (inner, outer, vec![-5.0; 11], vec![5.0; 11])
    }

    /// The lamina traction at skew: |F| is the law's force at |v| (checked against
    /// `lamina_friction` at √(v_θ² + v_a²)), its direction v/|v|, the power splits exactly
    /// (F_θ·v_θ + F_a·v_a = F·|v|, 1e-13); v_a = 0 is `lamina_friction` bit for bit.
    #[test]
    fn skewed_lamina_is_the_law_along_the_sliding() {
        for law in [RacewayTractionLaw::Atz, RacewayTractionLaw::NewtonianEq3] {
            let s = lamina(300.0, 0.03, 1e-3);
            let t = skewed_lamina(law, &oil(), &s, -0.04).expect("lamina");
            let f = lamina_friction(
                law,
                &oil(),
                &LaminaSlice {
                    sliding_speed_m_s: 0.05,
                    ..s
                },
            )
            .expect("lamina");
            let mag = t.circumferential_n.hypot(t.axial_n);
            assert!((mag - f.force_n).abs() <= 1e-13 * f.force_n, "{law:?}");
            assert!((t.circumferential_n / t.axial_n - 0.03 / -0.04).abs() < 1e-13);
            let p = t.rolling_power_w + t.skew_power_w;
            assert!((p - f.power_w).abs() <= 1e-13 * p);
            assert!(t.rolling_power_w > 0.0 && t.skew_power_w > 0.0);
            let z = skewed_lamina(law, &oil(), &s, 0.0).expect("lamina");
            let f0 = lamina_friction(law, &oil(), &s).expect("lamina");
            assert_eq!(z.circumferential_n, f0.force_n);
            assert_eq!((z.axial_n, z.skew_power_w), (0.0, 0.0));
            assert_eq!(z.rolling_power_w, f0.power_w);
        }
    }

    /// ψ_max = 0 (no pocket play) ⇒ ψ = 0, no axial traction, no end load, and the sums are
    /// the unskewed laminae's (today's answers, bit for bit); a roller without a yaw moment
    /// (every lamina at rolling, v_θ = 0: pure rolling) does not skew even with play.
    #[test]
    fn no_play_or_no_yaw_means_no_skew() {
        let (i, o, ui, uo) = roller(1.0);
        let g0 = SkewGeometry {
            max_skew_rad: 0.0,
            end_offset_per_rad_m: Some(0.024),
        };
        let r =
            roller_skew(RacewayTractionLaw::Atz, &oil(), &g0, [&i, &o], [&ui, &uo]).expect("skew");
        assert_eq!(r.skew_rad, 0.0);
        assert_eq!((r.axial_traction_n, r.guide_ring_load_n), (0.0, 0.0));
        let (mut p, mut m) = (0.0, 0.0);
        for s in i.iter().chain(&o) {
            let f = lamina_friction(RacewayTractionLaw::Atz, &oil(), s).expect("lamina");
            p += f.power_w;
            m += f.skew_moment_nm;
        }
        let got = r.inner.rolling_power_w + r.outer.rolling_power_w;
        assert!((got - p).abs() <= 1e-14 * p);
        assert!((r.yaw_moment_nm() - m).abs() <= 1e-14 * m.abs());
        assert!(m != 0.0, "the test roller has a yaw moment");
        let (i0, o0, _, _) = roller(0.0);
        let g = SkewGeometry {
            max_skew_rad: 0.0167,
            end_offset_per_rad_m: Some(0.024),
        };
        let r =
            roller_skew(RacewayTractionLaw::Atz, &oil(), &g, [&i0, &o0], [&ui, &uo]).expect("skew");
        assert_eq!((r.skew_rad, r.unskewed_yaw_moment_nm), (0.0, 0.0));
        assert_eq!(r.inner.skew_power_w + r.outer.skew_power_w, 0.0);
    }

    /// Without a guide ring, on this roller the raceways alone do not stop the skew: the
    /// pocket does, at ψ = ±ψ_max with the sign of M_s(0), and it reacts h = M_s(ψ_max) of
    /// that sign. With the ring the balance h(ψ) = 0 holds to the tolerance inside
    /// (0, ψ_max) where the ring's moment reaches the yaw moment, and M_g = −δ·ψ·Q exactly.
    #[test]
    fn pocket_or_ring_stops_the_skew() {
        let (i, o, ui, uo) = roller(1.0);
        let law = RacewayTractionLaw::Atz;
        let free = SkewGeometry {
            max_skew_rad: 0.0167,
            end_offset_per_rad_m: None,
        };
        let r = roller_skew(law, &oil(), &free, [&i, &o], [&ui, &uo]).expect("skew");
        let m0 = r.unskewed_yaw_moment_nm;
        assert!(r.pocket_limited);
        assert_eq!(r.skew_rad, 0.0167 * m0.signum());
        assert_eq!(r.ring_moment_nm, 0.0);
        // (Its size may exceed |M_s(0)|: the laminae's moments have both signs, and the
        // saturated ones lose more of theirs than the Newtonian ones.)
        assert!(r.pocket_moment_nm * m0 > 0.0, "{r:?}");
        assert!(r.inner.skew_power_w > 0.0 && r.outer.skew_power_w > 0.0);
        // Opposite axial slidings at the two raceways: opposite axial tractions.
        assert!(r.inner.axial_n * r.outer.axial_n < 0.0);
        // Make the net axial traction press the ring (the ring is at the roller's −a end):
        // reversing both rollers' surface speeds reverses both axial slidings, so N.
        let (ui, uo) = if r.axial_traction_n > 0.0 {
            (
                ui.iter().map(|x| -x).collect(),
                uo.iter().map(|x| -x).collect(),
            )
        } else {
            (ui, uo)
        };
        let ring = SkewGeometry {
            max_skew_rad: 0.0167,
            end_offset_per_rad_m: Some(5.0),
        };
        let r = roller_skew(law, &oil(), &ring, [&i, &o], [&ui, &uo]).expect("skew");
        assert!(r.guide_ring_load_n > 0.0, "{r:?}");
        assert!(!r.pocket_limited, "{r:?}");
        assert!(r.skew_rad.abs() < 0.0167 && r.skew_rad * m0 > 0.0);
        assert!(r.pocket_moment_nm.abs() <= 1e-8 * m0.abs(), "{r:?}");
        let mg = -5.0 * r.skew_rad * r.guide_ring_load_n;
        assert!((r.ring_moment_nm - mg).abs() <= 1e-15 * mg.abs());
        // The same ring on the other side (N pushing the roller away) takes nothing.
        let away: [Vec<f64>; 2] = [
            ui.iter().map(|x| -x).collect(),
            uo.iter().map(|x| -x).collect(),
        ];
        let r = roller_skew(law, &oil(), &ring, [&i, &o], [&away[0], &away[1]]).expect("skew");
        assert!(r.pocket_limited && r.guide_ring_load_n == 0.0, "{r:?}");
        assert!(r.axial_traction_n > 0.0);
    }
}
