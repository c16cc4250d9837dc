//! Fatigue life and static safety of the ball bearing (issue 28 items 1–2), from the
//! solved ball loads.
//!
//! **Reference life (ISO/TS 16281 reading).** Each ball j carries Q_ij on the inner and
//! Q_oj on the outer raceway at its own contact angles α_ij, α_oj. The contact's dynamic
//! capacity is Lundberg–Palmgren's Q_c from the groove conformity
//! ([`life_point::raceway_capacity`], 98.1·(2f/(2f−1))^0.41·(1∓γ)^1.39/(1±γ)^(1/3)·
//! (γ/cos α)^0.3·D^1.8·Z^(−1/3), γ = D·cos α/d_m) at that ball's angle, times ISO 281's
//! b_m = 1.3: the constant 98.1 is the rating basis *without* b_m (its closed form is the
//! 39.9 of ISO/TR 1281-1 behind Table 2's f_c), so without it the reference life would be
//! 1.3³ = 2.2 times shorter than ISO 281's basic life of the same ideal bearing. (ISO/TS
//! 16281's text was not at hand; this is the reading that keeps the two comparable, stated
//! here and in the JSON's `capacity_factor`.) With contact angles that differ from ball to
//! ball the raceway life generalises Lundberg–Palmgren's mean loads to the power mean of
//! Q_j/Q_cj: L = [Σ(Q_j/Q_cj)^p/Z]^(−3/p), p = 3 for the raceway rotating relative to the
//! load, 3e = 10/3 for the stationary one (equal Q_cj gives back (Q_c/Q_e)³ exactly). The
//! bearing life is the product law with e = 10/9 ([`life_point::bearing_l10`]).
//! `capacity_inner_n`/`capacity_outer_n` report the raceway's *effective* capacity
//! Q_e·L^(1/3) (= Q_c when every ball has the same angle).
//!
//! **ISO 281.** For α₀ ≤ 45°, C_r from [`life_point::iso_radial_rating`] at the free
//! contact angle α₀; P from the forces the bearing carries at the solution (the axial force
//! of the equilibrium at speed, the radial load) by Table 3
//! ([`rating::equivalent_load_radial_ball`]); C_0r from ISO 76's 4 200 MPa at the inner
//! contact of α₀ ([`rating::static_radial_rating_ball`]). For α₀ > 45° ISO 281 rates the
//! bearing as a single-direction thrust ball bearing: C_a (Table 4), P_a (Table 5) and C_0a
//! ([`thrust_ball_rating`]), with JSON `rating_direction = "axial"`; a_ISO and C_u take the
//! ball forms (ISO 281 uses them for thrust ball bearings too).
//! κ from the lubricant's viscosity at the bulk temperature of eq. 4-1 (Barus/Roelands with
//! the deck's temperature–viscosity coefficient) over its density; e_C =
//! [`rating::DEFAULT_CONTAMINATION_FACTOR`] (the deck has no key for it yet).
//!
//! **Static safety** s0 = (4 200 MPa/p_max)³ from the largest Hertz pressure
//! ([`rating::static_safety`]); s0 < 1 is the existing "exceeds ISO 76" warning.

use serde::Serialize;

use super::analysis::BallAnalysis;
use crate::physics::contact::point::{ball_race_curvature, HertzPointContact, Race};
use crate::physics::life_point::{
    self, bearing_l10, life_hours, power_mean_load, raceway_capacity, raceway_l10, Life, Raceway,
    ISO_BM_RADIAL_BALL, LIFE_EXPONENT_POINT, WEIBULL_SLOPE_POINT,
};
use crate::physics::rating::{self, ContactKind, IsoLife, IsoLifeInputs, RatingDirection};
use crate::physics::thrust_ball_rating;

/// Revolutions per minute per rad/s.
const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

/// The load-distribution (reference) life of the ball set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReferenceLife {
    /// Effective dynamic capacity of the inner raceway, N (module notes).
    pub capacity_inner_n: Option<f64>,
    /// Effective dynamic capacity of the outer raceway, N.
    pub capacity_outer_n: Option<f64>,
    /// Inner raceway L10, Mrev (`None`: unloaded).
    pub l10_inner_mrev: Option<f64>,
    /// Outer raceway L10, Mrev.
    pub l10_outer_mrev: Option<f64>,
    /// Bearing L10 by the product law, Mrev.
    pub l10_bearing_mrev: Option<f64>,
    /// The same in hours at the relative ring speed, h.
    pub l10_bearing_h: Option<f64>,
    /// The factor on Lundberg–Palmgren's Q_c (ISO 281's b_m, module notes).
    pub capacity_factor: f64,
    /// Whether the inner ring is taken as rotating relative to the load.
    pub inner_rotating: bool,
}

impl ReferenceLife {
    /// The numbers under the shared JSON names.
    pub fn numbers(&self) -> rating::ReferenceLifeNumbers {
        rating::ReferenceLifeNumbers {
            capacity_inner_n: self.capacity_inner_n,
            capacity_outer_n: self.capacity_outer_n,
            l10_inner_mrev: self.l10_inner_mrev,
            l10_outer_mrev: self.l10_outer_mrev,
            l10_bearing_mrev: self.l10_bearing_mrev,
            l10_bearing_h: self.l10_bearing_h,
        }
    }
}

/// Everything the life stage adds to a ball analysis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BallLife {
    /// The reference life, or why it could not be formed (a sentence).
    pub reference: Result<ReferenceLife, String>,
    /// ISO 281 / ISO 76 numbers.
    pub iso: IsoLife,
    /// The most loaded contact's Hertz pressure, Pa (s0's input).
    pub max_contact_stress_pa: f64,
    /// The thinnest Λ = h_min/σ over the balls at the inner and the outer raceway (JSON
    /// `lambda_inner`/`lambda_outer`), or why there is none.
    pub lambdas: Result<(Option<f64>, Option<f64>), String>,
}

/// The thinnest Λ over the balls at each raceway (`None` at a raceway with no film), or
/// why the deck gives none.
pub fn raceway_lambdas(a: &BallAnalysis) -> Result<(Option<f64>, Option<f64>), String> {
    let s = &a.input.surfaces;
    if s.composite_rms_m.is_none() {
        return Err(
            "the deck gives no surfaces.composite_rms: no Λ (the films are in balls[].inner/outer)"
                .into(),
        );
    }
    let min = |xs: &mut dyn Iterator<Item = Option<f64>>| {
        xs.flatten()
            .fold(None, |m: Option<f64>, l| Some(m.map_or(l, |m| m.min(l))))
    };
    Ok((
        min(&mut a.balls.iter().map(|b| s.lambda(b.inner.min_film_m))),
        min(&mut a.balls.iter().map(|b| s.lambda(b.outer.min_film_m))),
    ))
}

/// The per-ball raceway life: L = [Σ(Q_j/Q_cj)^p/Z]^(−3/p) (module notes); `Infinite`
/// when no ball is loaded.
fn raceway_life(ratios: &[f64], rotating: bool) -> Result<Life, String> {
    let p = if rotating {
        LIFE_EXPONENT_POINT
    } else {
        LIFE_EXPONENT_POINT * WEIBULL_SLOPE_POINT
    };
    let m = power_mean_load(ratios, p).map_err(|e| e.to_string())?;
    // (1/m)³ with the library's unloaded/overflow handling.
    raceway_l10(1.0, m).map_err(|e| e.to_string())
}

/// The reference life of `a` (module notes).
pub fn reference_life(a: &BallAnalysis) -> Result<ReferenceLife, String> {
    let g = &a.geometry;
    let z = a.balls.len();
    let (wi, wo) = (
        a.input.operating.inner_speed_rad_s,
        a.input.operating.outer_speed_rad_s,
    );
    let inner_rotating = wi.abs() >= wo.abs();
    let capacity = |race: Raceway, f: f64, alpha: f64| {
        raceway_capacity(
            race,
            f,
            &life_point::BallGeometry {
                ball_diameter_m: g.ball_diameter_m,
                pitch_diameter_m: g.pitch_diameter_m,
                contact_angle_rad: alpha.abs(),
                ball_count: z,
            },
        )
        .map(|q| ISO_BM_RADIAL_BALL * q)
        .map_err(|e| format!("ball raceway capacity: {e}"))
    };
    let mut ri = Vec::with_capacity(z);
    let mut ro = Vec::with_capacity(z);
    let (mut qi, mut qo) = (Vec::with_capacity(z), Vec::with_capacity(z));
    for b in &a.balls {
        let (li, lo) = (b.inner.load_n.max(0.0), b.outer.load_n.max(0.0));
        ri.push(li / capacity(Raceway::Inner, g.inner_groove_curvature, b.inner.angle_rad)?);
        ro.push(lo / capacity(Raceway::Outer, g.outer_groove_curvature, b.outer.angle_rad)?);
        qi.push(li);
        qo.push(lo);
    }
    let li = raceway_life(&ri, inner_rotating)?;
    let lo = raceway_life(&ro, !inner_rotating)?;
    let lb = bearing_l10(li, lo).map_err(|e| e.to_string())?;
    let h = life_hours(lb, wi - wo).map_err(|e| e.to_string())?;
    // Effective capacity Q_e·L^(1/3), Q_e the raceway's mean ball load.
    let effective = |loads: &[f64], life: Life, rotating: bool| -> Option<f64> {
        let p = if rotating {
            LIFE_EXPONENT_POINT
        } else {
            LIFE_EXPONENT_POINT * WEIBULL_SLOPE_POINT
        };
        let qe = power_mean_load(loads, p).ok()?;
        life.finite().map(|l| qe * l.cbrt())
    };
    Ok(ReferenceLife {
        capacity_inner_n: effective(&qi, li, inner_rotating),
        capacity_outer_n: effective(&qo, lo, !inner_rotating),
        l10_inner_mrev: li.finite(),
        l10_outer_mrev: lo.finite(),
        l10_bearing_mrev: lb.finite(),
        l10_bearing_h: h.finite(),
        capacity_factor: ISO_BM_RADIAL_BALL,
        inner_rotating,
    })
}

/// ν at the bulk temperature of eq. 4-1, m²/s.
pub fn operating_kinematic_viscosity_m2_s(a: &BallAnalysis) -> Result<f64, String> {
    let l = &a.input.lubricant;
    let eta = l.rheology().viscosity_pa_s(0.0, a.bulk_temperature_k);
    let nu = eta / l.density_kg_m3;
    if nu.is_finite() && nu > 0.0 {
        Ok(nu)
    } else {
        Err(format!(
            "the lubricant's kinematic viscosity at the bulk temperature {:.1} °C is not positive ({nu:e} m²/s): no κ, no a_ISO",
            a.bulk_temperature_k - 273.15
        ))
    }
}

/// The life stage of `a`: reference life, ISO 281 and ISO 76 numbers.
pub fn life(a: &BallAnalysis) -> BallLife {
    let g = &a.geometry;
    let alpha0 = g.free_contact_angle_rad;
    let iso_brg = life_point::IsoBallBearing {
        rows: 1,
        balls_per_row: g.ball_count,
        ball_diameter_m: g.ball_diameter_m,
        pitch_diameter_m: g.pitch_diameter_m,
        contact_angle_rad: alpha0,
    };
    // ISO 281 rates α ≤ 45° as a radial bearing (C_r, Table 3) and α > 45° as a
    // single-direction thrust bearing (C_a, Tables 4–5; `thrust_ball_rating`).
    let thrust = alpha0.to_degrees() > 45.0;
    let direction = if thrust {
        RatingDirection::Axial
    } else {
        RatingDirection::Radial
    };
    let rating = if thrust {
        thrust_ball_rating::iso_thrust_rating(
            alpha0,
            g.ball_count,
            g.ball_diameter_m,
            g.pitch_diameter_m,
        )
    } else {
        life_point::iso_radial_rating(&iso_brg).map_err(|e| format!("ISO 281 C_r: {e}"))
    };
    let c0_name = if thrust { "C_0a" } else { "C_0r" };
    let static_rating = ball_race_curvature(
        Race::Inner,
        g.ball_diameter_m,
        g.pitch_diameter_m,
        alpha0,
        g.inner_groove_curvature,
    )
    .and_then(|c| HertzPointContact::new(c, g.reduced_modulus_pa, g.hertz_method))
    .and_then(|h| h.solve(1000.0))
    .map_err(|e| format!("ISO 76 {c0_name}: {e}"))
    .and_then(|pc| {
        let per_load = (1000.0, pc.max_pressure_pa);
        if thrust {
            thrust_ball_rating::static_axial_rating_ball(g.ball_count, alpha0, per_load)
        } else {
            rating::static_radial_rating_ball(1, g.ball_count, alpha0, per_load)
        }
        .ok_or_else(|| format!("ISO 76 {c0_name}: no contact pressure at the reference load"))
    });
    let equivalent_load = if thrust {
        thrust_ball_rating::equivalent_load_thrust_ball(
            a.load.radial_force_n,
            a.load.axial_force_n,
            alpha0,
        )
        .map_err(|e| format!("ISO 281 P_a: {e}"))
    } else {
        rating::equivalent_load_radial_ball(
            a.load.radial_force_n,
            a.load.axial_force_n,
            alpha0,
            g.ball_count,
            g.ball_diameter_m,
        )
        .map_err(|e| format!("ISO 281 P: {e}"))
    };
    let op = &a.input.operating;
    let max_p = a.max_pressure_pa();
    let iso = rating::iso_life(&IsoLifeInputs {
        kind: ContactKind::Ball,
        rating_direction: direction,
        rating,
        equivalent_load,
        static_rating,
        pitch_diameter_m: g.pitch_diameter_m,
        relative_speed_rpm: (op.inner_speed_rad_s - op.outer_speed_rad_s).abs() * RPM_PER_RAD_S,
        kinematic_viscosity_m2_s: operating_kinematic_viscosity_m2_s(a),
        contamination_factor: rating::DEFAULT_CONTAMINATION_FACTOR,
        max_contact_stress_pa: max_p,
    });
    BallLife {
        lambdas: raceway_lambdas(a),
        reference: reference_life(a),
        iso,
        max_contact_stress_pa: max_p,
    }
}

impl BallLife {
    /// The JSON `life` object ([`rating::life_json`]); Λ is absent with its reason when
    /// the deck gives no `surfaces.composite_rms`.
    pub fn json(&self) -> serde_json::Value {
        let mut v = rating::life_json(
            &self
                .reference
                .as_ref()
                .map(|r| r.numbers())
                .map_err(Clone::clone),
            &self.lambdas,
            &self.iso,
        );
        if let (Some(m), Ok(r)) = (v.as_object_mut(), &self.reference) {
            m.insert(
                "capacity_factor".into(),
                serde_json::json!(r.capacity_factor),
            );
        }
        v
    }

    /// The text report's LIFE section, in SI as the rest of the ball's text report
    /// (which says "values in SI" on a US deck).
    pub fn text(&self) -> String {
        rating::life_text(
            &self
                .reference
                .as_ref()
                .map(|r| r.numbers())
                .map_err(Clone::clone),
            &self.iso,
            crate::units::Units::Si,
        )
    }
}

#[cfg(test)]
#[path = "life_tests.rs"]
mod tests;
