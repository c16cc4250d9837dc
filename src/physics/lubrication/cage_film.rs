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
