//! Hydrodynamic roller/cage-pocket and cage/land films (seed 002 §3: "the roller/cage and
//! cage/inner ring contacts are lubricated in HD mode"), SI.
//!
//! # Roller / pocket: Martin's rigid-isoviscous line contact
//! The seed treats the pocket after Houpert (1985), whose piezoviscous-rigid formulas
//! extend Martin's; Houpert's paper could not be sourced, so only the rigid-isoviscous
//! limit is used, which is what the pocket's low pressures (a few MPa: α·p ≪ 1) call for.
//! A cylinder of radius R (the roller, the pocket face flat in the cross-section: "the cage
//! pocket aspect is similar to that of the roller longitudinal section") at the minimum gap
//! h₀ from the pocket, gap h = h₀ + x²/(2R), flooded inlet, Reynolds (Swift–Stieber) outlet
//! p = dp/dx = 0, mean surface speed ū = ½(u₁ + u₂):
//!
//! * load per unit length w = C_w·η·ū·R/h₀ with C_w = 4.8950 (Martin 1916; Hamrock,
//!   *Fundamentals of Fluid Film Lubrication*, quotes 4.896), so the film under the pocket
//!   force F over the length L is h₀ = C_w·η·ū·R·L/F, capped at the pocket's half play
//!   c_p/2 (a roller centred in its pocket; a lightly loaded roller cannot lift further);
//! * drag on the moving surface (the roller, speed u_s relative to the cage; the pocket is
//!   at rest in the cage frame, so ū = u_s/2) per unit length: the Couette part
//!   η·u_s·∫dx/h = η·u_s·√(2R/h₀)·(π/2 + γ_e) and the pressure-induced (rolling) part
//!   ∫(h/2)·dp/dx dx = C_r·η·ū·√(R/h₀), C_r = 4.6011; the cavitated outlet region is
//!   neglected.
//!
//! In x = √(2Rh₀)·tan γ the outlet is γ_e = 0.443 554 334 (tan γ_e = 0.475 13), the root of
//! ∫_{−π/2}^{γ_e}(cos²t − cos⁴t/cos²γ_e) dt = 0; C_w = 24·∫P·sec²γ dγ and
//! C_r = −12·√2·∫P·tan γ·sec²γ dγ with P the bracketed integral (evaluated once in 50-digit
//! quadrature; checked against a direct finite-difference solution of Reynolds' equation
//! in the tests). Loss = drag × u_s (the film's dissipation: only the roller surface moves
//! in the cage frame).
//!
//! # Roller / pocket: the skew (yaw) reaction
//! A roller's raceway tractions have a moment M about its skew axis (the normal to the
//! roller axis in the meridian plane: it turns the roller axis out of that plane). The
//! window pocket holds the roller against it (Harris & Kotzalas, *Advanced Concepts of
//! Bearing Technology*, 5th ed., roller skewing: the skewing moment is reacted by the cage
//! pockets and the guide flange / ring). The pocket's reaction is a couple with no
//! resultant, taken as the linear line load of a rigid roller along its pocket contact of
//! length L, w(y) = 12·M·y/L³: each half presses the opposite pocket face with
//! F_s = 3|M|/(2L) (its centroid L/3 from the centre, arm 2L/3 between the two). Each half
//! is a Martin film of length L/2 under F_s at the roller's surface speed, and the skew
//! loss is what the couple adds to the two halves' unloaded films (h₀ = c_p/2 there):
//! ΔP = Σ_halves [P(F_s, L/2) − P(0, L/2)] ≥ 0, zero at M = 0 and rising with |M|
//! ([`pocket_skew_reaction`]). The net circumferential force's film ([`pocket_film`]) is
//! computed on its own and the two are superposed (each as if alone: Martin's drag is not
//! linear in the load, so where the couple's half loads and the net force are comparable
//! the superposition is approximate).
//!
//! # Cage / land: Petroff
//! The cage piloted on a land (the guide ring or the inner ring) is a journal of radius R,
//! width L and radial clearance c: T = 2π·η·R³·L·Δω/c (Petroff), loss T·|Δω|. It is
//! `heat::cage_rail_power_w` (F = π·η·W·D²·|Δω|/dc, P = F·|Δω|·D/2) with D = 2R, dc = 2c:
//! reused.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::physics::heat::cage_rail_power_w;

/// Martin's load coefficient C_w of w = C_w·η·ū·R/h₀ (module notes).
pub const MARTIN_LOAD_COEFFICIENT: f64 = 4.894_968_5;
/// Outlet angle γ_e of the Swift–Stieber condition, rad.
pub const MARTIN_OUTLET_ANGLE_RAD: f64 = 0.443_554_334_2;
/// Rolling (pressure) friction coefficient C_r of ∫(h/2)dp/dx dx = C_r·η·ū·√(R/h₀).
pub const MARTIN_ROLLING_FRICTION_COEFFICIENT: f64 = 4.601_076_9;

/// Why a cage film cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum CageFilmError {
    /// An input is outside its range.
    #[error("cage {name} = {value} is not usable: it must be {allowed}")]
    BadInput {
        /// The field.
        name: &'static str,
        /// Its value (SI).
        value: f64,
        /// The allowed range.
        allowed: &'static str,
    },
}

fn positive(name: &'static str, value: f64) -> Result<f64, CageFilmError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(CageFilmError::BadInput {
            name,
            value,
            allowed: "positive and finite",
        })
    }
}

/// Martin's load per unit length w = C_w·η·ū·R/h₀, N/m (η Pa·s, ū m/s, R m, h₀ m).
pub fn martin_load_per_length_n_m(
    viscosity_pa_s: f64,
    mean_speed_m_s: f64,
    radius_m: f64,
    min_film_m: f64,
) -> f64 {
    MARTIN_LOAD_COEFFICIENT * viscosity_pa_s * mean_speed_m_s.abs() * radius_m / min_film_m
}

/// Geometry of a roller in its pocket, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PocketGeometry {
    /// R, roller radius at the pocket contact, m.
    pub roller_radius_m: f64,
    /// L, length of the pocket contact along the roller, m.
    pub length_m: f64,
    /// c_p, circumferential play of the roller in its pocket (total), m.
    pub pocket_clearance_m: f64,
}

/// One roller's pocket film.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct PocketFilm {
    /// h₀, minimum film, m.
    pub min_film_m: f64,
    /// Drag on the roller opposing its surface motion, N.
    pub drag_n: f64,
    /// Drag × surface speed, W.
    pub power_w: f64,
}

/// The pocket film of a roller pressed with `pocket_force_n` (N, sign ignored) whose
/// surface moves at `surface_speed_m_s` (m/s, relative to the cage), in oil of viscosity
/// `viscosity_pa_s` (module notes).
///
/// # Errors
/// [`CageFilmError::BadInput`] for a non-positive geometry, a negative viscosity or
/// non-finite force or speed.
pub fn pocket_film(
    geometry: &PocketGeometry,
    viscosity_pa_s: f64,
    pocket_force_n: f64,
    surface_speed_m_s: f64,
) -> Result<PocketFilm, CageFilmError> {
    let r = positive("roller_radius_m", geometry.roller_radius_m)?;
    let l = positive("length_m", geometry.length_m)?;
    let cp = positive("pocket_clearance_m", geometry.pocket_clearance_m)?;
    if !(viscosity_pa_s.is_finite() && viscosity_pa_s >= 0.0) {
        return Err(CageFilmError::BadInput {
            name: "viscosity_pa_s",
            value: viscosity_pa_s,
            allowed: "finite and not negative",
        });
    }
    for (name, value) in [
        ("pocket_force_n", pocket_force_n),
        ("surface_speed_m_s", surface_speed_m_s),
    ] {
        if !value.is_finite() {
            return Err(CageFilmError::BadInput {
                name,
                value,
                allowed: "finite",
            });
        }
    }
    let us = surface_speed_m_s.abs();
    let ubar = 0.5 * us;
    let f = pocket_force_n.abs();
    let h_cap = 0.5 * cp;
    let h_martin = if f > 0.0 {
        MARTIN_LOAD_COEFFICIENT * viscosity_pa_s * ubar * r * l / f
    } else {
        f64::INFINITY
    };
    let h0 = h_martin.min(h_cap);
    if us == 0.0 || viscosity_pa_s == 0.0 || h0 <= 0.0 {
        return Ok(PocketFilm {
            min_film_m: h0.max(0.0),
            ..PocketFilm::default()
        });
    }
    let couette = viscosity_pa_s
        * us
        * (2.0 * r / h0).sqrt()
        * (std::f64::consts::FRAC_PI_2 + MARTIN_OUTLET_ANGLE_RAD);
    let rolling = MARTIN_ROLLING_FRICTION_COEFFICIENT * viscosity_pa_s * ubar * (r / h0).sqrt();
    let drag = (couette + rolling) * l;
    Ok(PocketFilm {
        min_film_m: h0,
        drag_n: drag,
        power_w: drag * us,
    })
}

/// The pocket's reaction to a roller's skew (yaw) moment (module notes).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct PocketSkewReaction {
    /// F_s = 3|M|/(2L), each half's resultant on its pocket face, N.
    pub half_force_n: f64,
    /// The drag the couple adds on the roller (both halves, opposing its surface motion), N.
    pub drag_n: f64,
    /// The dissipation the couple adds, drag × surface speed, W.
    pub power_w: f64,
}

/// The skew reaction of a roller in its pocket: the yaw moment `yaw_moment_nm` (N·m, sign
/// ignored) reacted as the linear couple w(y) = 12·M·y/L³ along the pocket contact, each half
/// (length L/2, resultant F_s = 3|M|/(2L)) a Martin film at the roller's surface speed
/// `surface_speed_m_s` (m/s, relative to the cage); the drag and loss it adds over the two
/// halves' unloaded films (module notes).
///
/// # Errors
/// As [`pocket_film`]; a non-finite moment is refused.
pub fn pocket_skew_reaction(
    geometry: &PocketGeometry,
    viscosity_pa_s: f64,
    yaw_moment_nm: f64,
    surface_speed_m_s: f64,
) -> Result<PocketSkewReaction, CageFilmError> {
    if !yaw_moment_nm.is_finite() {
        return Err(CageFilmError::BadInput {
            name: "yaw_moment_nm",
            value: yaw_moment_nm,
            allowed: "finite",
        });
    }
    let l = positive("length_m", geometry.length_m)?;
    let half = PocketGeometry {
        length_m: 0.5 * l,
        ..*geometry
    };
    let fs = 1.5 * yaw_moment_nm.abs() / l;
    let loaded = pocket_film(&half, viscosity_pa_s, fs, surface_speed_m_s)?;
    let idle = pocket_film(&half, viscosity_pa_s, 0.0, surface_speed_m_s)?;
    // Martin's drag rises with the load (h₀ ∝ 1/F): the difference is not negative; the
    // max only guards round-off at F_s → 0.
    let drag = 2.0 * (loaded.drag_n - idle.drag_n).max(0.0);
    Ok(PocketSkewReaction {
        half_force_n: fs,
        drag_n: drag,
        power_w: drag * surface_speed_m_s.abs(),
    })
}

/// Petroff power of the cage on its land, W: T·|Δω| with T = 2π·η·R³·L·|Δω|/c
/// (η Pa·s, R land radius m, L land width m, c radial clearance m, Δω rad/s), through
/// `heat::cage_rail_power_w`. η = 0 or Δω = 0 give 0.
///
/// # Errors
/// [`CageFilmError::BadInput`] for a non-positive radius, width or clearance.
pub fn land_power_w(
    viscosity_pa_s: f64,
    radius_m: f64,
    width_m: f64,
    radial_clearance_m: f64,
    relative_speed_rad_s: f64,
) -> Result<f64, CageFilmError> {
    let r = positive("land radius_m", radius_m)?;
    let w = positive("land width_m", width_m)?;
    let c = positive("land clearance_m", radial_clearance_m)?;
    if viscosity_pa_s == 0.0 || relative_speed_rad_s == 0.0 {
        return Ok(0.0);
    }
    cage_rail_power_w(viscosity_pa_s, w, 2.0 * r, 2.0 * c, relative_speed_rad_s).map_err(|_| {
        CageFilmError::BadInput {
            name: "viscosity_pa_s",
            value: viscosity_pa_s,
            allowed: "positive and finite",
        }
    })
}

/// Petroff torque of the land film on the cage, N·m, signed to oppose Δω = ω_c − ω_land:
/// −2π·η·R³·L·Δω/c (same arguments as [`land_power_w`]).
///
/// # Errors
/// As [`land_power_w`].
pub fn land_torque_on_cage_nm(
    viscosity_pa_s: f64,
    radius_m: f64,
    width_m: f64,
    radial_clearance_m: f64,
    relative_speed_rad_s: f64,
) -> Result<f64, CageFilmError> {
    let p = land_power_w(
        viscosity_pa_s,
        radius_m,
        width_m,
        radial_clearance_m,
        relative_speed_rad_s,
    )?;
    Ok(if relative_speed_rad_s == 0.0 {
        0.0
    } else {
        -p / relative_speed_rad_s
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The constants against an independent solution: Reynolds' equation
    /// dp/dx = 12ηū(h − h_e)/h³ integrated by the trapezoidal rule on a fine x grid from a
    /// far inlet to the outlet x_e = √(2Rh₀)·tan γ_e. Criteria: p(x_e) = 0 (the outlet
    /// angle) to 1e-4 of p_max, the load to 2e-4 of C_w (quoted 4.896 by Hamrock: within
    /// 0.03 %), the rolling friction to 1 % (its integrand decays like 1/x², so the
    /// truncated inlet at −400·√(2Rh₀) costs ~0.3 %).
    #[test]
    fn martin_constants_against_reynolds() {
        let (eta, ubar, r, h0): (f64, f64, f64, f64) = (0.05, 2.0, 0.01, 1e-6);
        let s = (2.0 * r * h0).sqrt();
        let xe = s * MARTIN_OUTLET_ANGLE_RAD.tan();
        let he = h0 + xe * xe / (2.0 * r);
        let n = 400_000usize;
        let x0 = -400.0 * s;
        let dx = (xe - x0) / n as f64;
        let dpdx = |x: f64| {
            let h = h0 + x * x / (2.0 * r);
            12.0 * eta * ubar * (h - he) / (h * h * h)
        };
        let (mut p, mut w, mut fr, mut pmax) = (0.0, 0.0, 0.0, 0.0f64);
        let mut prev = dpdx(x0);
        for i in 0..n {
            let x1 = x0 + (i + 1) as f64 * dx;
            let d1 = dpdx(x1);
            let p1 = p + 0.5 * (prev + d1) * dx;
            w += 0.5 * (p + p1) * dx;
            let hm = |x: f64| h0 + x * x / (2.0 * r);
            fr += 0.5 * (hm(x1 - dx) / 2.0 * prev + hm(x1) / 2.0 * d1) * dx;
            p = p1;
            pmax = pmax.max(p);
            prev = d1;
        }
        assert!(p.abs() < 1e-4 * pmax, "outlet {p} of {pmax}");
        let cw = w / (eta * ubar * r / h0);
        assert!((cw / MARTIN_LOAD_COEFFICIENT - 1.0).abs() < 2e-4, "{cw}");
        assert!((cw / 4.896 - 1.0).abs() < 5e-4, "{cw}");
        let cr = fr / (eta * ubar * (r / h0).sqrt());
        assert!(
            (cr / MARTIN_ROLLING_FRICTION_COEFFICIENT - 1.0).abs() < 0.01,
            "{cr}"
        );
    }

    /// Martin's w formula typed out (1e-15), and the pocket film recovers the gap whose
    /// Martin load is the pocket force (round trip 1e-13); the drag by hand.
    #[test]
    fn martin_formula_and_pocket_round_trip() {
        let w = martin_load_per_length_n_m(0.02, 3.0, 0.006, 2e-6);
        assert!((w - 4.894_968_5 * 0.02 * 3.0 * 0.006 / 2e-6).abs() < 1e-15 * w);
        let g = PocketGeometry {
            roller_radius_m: 0.006,
            length_m: 0.012,
            pocket_clearance_m: 4e-4,
        };
        let us = 6.0; // ū = 3 m/s
        let force = w * 0.012;
        let f = pocket_film(&g, 0.02, force, us).expect("valid");
        assert!(
            (f.min_film_m / 2e-6 - 1.0).abs() < 1e-13,
            "{}",
            f.min_film_m
        );
        let per_len = 0.02
            * 6.0
            * (2.0 * 0.006 / 2e-6f64).sqrt()
            * (std::f64::consts::FRAC_PI_2 + 0.443_554_334_2)
            + 4.601_076_9 * 0.02 * 3.0 * (0.006 / 2e-6f64).sqrt();
        assert!((f.drag_n / (per_len * 0.012) - 1.0).abs() < 1e-13);
        assert!((f.power_w - f.drag_n * us).abs() < 1e-13 * f.power_w);
        // Unloaded: the film is the half play; no speed or no oil: no loss.
        let f0 = pocket_film(&g, 0.02, 0.0, us).expect("valid");
        assert_eq!(f0.min_film_m, 2e-4);
        assert!(f0.power_w > 0.0);
        assert_eq!(
            pocket_film(&g, 0.02, force, 0.0).expect("valid").power_w,
            0.0
        );
        assert_eq!(pocket_film(&g, 0.0, force, us).expect("valid").power_w, 0.0);
    }

    /// The skew reaction by hand: F_s = 3|M|/(2L); each half a Martin film of length L/2
    /// (h₀ = C_w·η·ū·R·(L/2)/F_s) less the half play's film, twice; power = drag·u_s
    /// (1e-12). M = 0 adds nothing; a larger |M| adds more (monotone); the sign of M does
    /// not matter.
    #[test]
    fn pocket_skew_reaction_by_hand() {
        let g = PocketGeometry {
            roller_radius_m: 0.006,
            length_m: 0.012,
            pocket_clearance_m: 4e-4,
        };
        let (eta, us, m) = (0.02, 5.0, 0.12);
        let r = pocket_skew_reaction(&g, eta, m, us).expect("valid");
        let fs = 1.5 * 0.12 / 0.012;
        assert!((r.half_force_n - fs).abs() < 1e-12 * fs);
        let per_len = |h0: f64| {
            eta * us
                * (2.0 * 0.006 / h0).sqrt()
                * (std::f64::consts::FRAC_PI_2 + MARTIN_OUTLET_ANGLE_RAD)
                + MARTIN_ROLLING_FRICTION_COEFFICIENT * eta * 0.5 * us * (0.006 / h0).sqrt()
        };
        let h0 = MARTIN_LOAD_COEFFICIENT * eta * 0.5 * us * 0.006 * 0.006 / fs;
        assert!(h0 < 2e-4, "{h0}: the Martin film, not the half play");
        let drag = 2.0 * (per_len(h0) - per_len(2e-4)) * 0.006;
        assert!(
            (r.drag_n - drag).abs() < 1e-12 * drag,
            "{} {drag}",
            r.drag_n
        );
        assert!((r.power_w - drag * us).abs() < 1e-12 * r.power_w);
        let zero = pocket_skew_reaction(&g, eta, 0.0, us).expect("valid");
        assert_eq!((zero.drag_n, zero.power_w), (0.0, 0.0));
        let neg = pocket_skew_reaction(&g, eta, -m, us).expect("valid");
        assert_eq!(neg, r);
        let more = pocket_skew_reaction(&g, eta, 2.0 * m, us).expect("valid");
        assert!(more.power_w > r.power_w);
        assert!(pocket_skew_reaction(&g, eta, f64::NAN, us).is_err());
    }

    /// Land Petroff: T = 2π·η·R³·L·ω/c typed out (1e-13); power = T·ω; torque opposes Δω.
    #[test]
    fn land_petroff_formula() {
        let (eta, r, l, c, dw): (f64, f64, f64, f64, f64) = (0.017, 0.03, 0.005, 1.5e-4, 120.0);
        let t = 2.0 * std::f64::consts::PI * eta * r.powi(3) * l * dw / c;
        let p = land_power_w(eta, r, l, c, dw).expect("valid");
        assert!((p - t * dw).abs() < 1e-13 * p, "{p} vs {}", t * dw);
        let tq = land_torque_on_cage_nm(eta, r, l, c, -dw).expect("valid");
        assert!((tq - t).abs() < 1e-13 * t);
        assert_eq!(land_power_w(0.0, r, l, c, dw), Ok(0.0));
        assert!(land_power_w(eta, r, l, 0.0, dw).is_err());
    }
}
