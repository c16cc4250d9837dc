//! Roller end / guide ring EHD point contact and the guide ring's speed (seed 002 §3: "The
//! roller/guiding ring contact is also an EHD contact"), SI.
//!
//! # The end contact
//! The roller's spherical end (radius R_e) touches the guide ring's flat face: a Hertz
//! circle (curvature sums 1/R_e in both directions; `contact::point`, exact for A = B),
//! under the load Q from the roller's axial balance. Film: Hamrock–Dowson central film
//! (`film_point`, k = 1) at the entrainment speed u_e = ½(u_ring + u_roller), both surface
//! speeds taken in the frame that carries the contact (the cage). Traction: the same law
//! as the raceways ([`RacewayTractionLaw`]) integrated over the circle: the circle is cut
//! into strips across the sliding direction; the strip at y = a·sin θ is a Hertz strip of
//! half-width a·cos θ and peak p₀·cos θ, integrated in x by `TractionModel::lamina_traction`
//! (reused), and in θ by 8-point Gauss–Legendre (∫ cos³θ is integrated to round-off, so a
//! constant μ gives F = μ·Q; tested). The printed eq. 3 uses the mean pressure Q/(πa²) on
//! the whole circle, as on a raceway slice. Spin inside the end contact (the contact point
//! lies close to the roller axis) is not modelled.
//!
//! # The guide ring's speed
//! The ring floats on the inner ring (a hydrodynamic bore, a Petroff journal of radius R_b,
//! width L_b and radial clearance c: T = 2π·η·R_b³·L_b·(ω_g − ω_i)/c, the form of
//! `heat::cage_rail_friction_force_n`, reused) and is driven by the roller ends. Its
//! steady speed ω_g solves G(ω_g) = T_ends(ω_g) + T_bore(ω_g) = 0 with
//! T_ends = −Σ F_roller·r_g (the ring receives the opposite of the roller's traction) and
//! v_k = ω_g·r_g − (ω_c·r_g + u_k) (ring minus roller end, along the bearing's rotation).
//! G ≥ 0 at ω_lo = min(ω_i, ω_k*) and G ≤ 0 at ω_hi = max(ω_i, ω_k*), ω_k* = ω_c + u_k/r_g
//! (every torque pushes the ring towards the bracket), so the root is bracketed; it is
//! found by the Illinois variant of regula falsi, and a failure is a typed error with the
//! bracket and residuals.
//!
//! # The cage's land on the ring
//! Where the cage is piloted on the guide ring (deck `land = "guide-ring"`) the land film
//! between them is a second Petroff journal (`cage_film::land_torque_on_cage_nm`): its
//! torque brakes the cage toward the ring's speed and, by Newton's third law, drives the
//! ring toward the cage's, T_land = −2π·η·R_l³·L_l·(ω_g − ω_c)/c_l. It enters the ring's
//! balance G(ω_g) = T_ends + T_bore + T_land = 0 ([`guide_ring_balance_with_land`]); ω_c is
//! added to the bracket (the land, too, pushes the ring towards it). Without it (srb-loss
//! to srb-kellstrom) the cage received the land torque and the ring did not: the two
//! bodies' torques did not cancel (srb10).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::physics::contact::point::PointContact;
use crate::physics::contact::point::{CurvatureSum, HertzMethod, HertzPointContact};
use crate::physics::heat::{cage_rail_friction_force_n, HeatError};
use crate::physics::lubrication::cage_film::land_torque_on_cage_nm;
use crate::physics::lubrication::film_point::PointFilmInputs;
use crate::physics::lubrication::lamina_friction::{FilmRheology, RacewayTractionLaw};
use crate::physics::lubrication::traction::{HertzStrip, PreparedTraction, TractionModel};

/// 8-point Gauss–Legendre on [0, π/2] for the strips of a circle: nodes θ and weights
/// (already scaled by π/4), from the [−1, 1] rule.
fn gl8_quarter() -> [(f64, f64); 8] {
    const X: [f64; 4] = [
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_3,
    ];
    const W: [f64; 4] = [
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];
    let h = std::f64::consts::FRAC_PI_4;
    let mut out = [(0.0, 0.0); 8];
    for i in 0..4 {
        out[2 * i] = (h * (1.0 - X[i]), h * W[i]);
        out[2 * i + 1] = (h * (1.0 + X[i]), h * W[i]);
    }
    out
}

/// Traction force, N, of a circular Hertz contact (radius `radius_m` a, peak pressure
/// `peak_pressure_pa` p₀) under `model` at sliding speed `sliding_m_s` (sign kept) and
/// film `film_m`: F = ∫∫τ(p) dA by strips (module notes).
pub fn circular_contact_traction_n(
    model: &TractionModel,
    radius_m: f64,
    peak_pressure_pa: f64,
    sliding_m_s: f64,
    film_m: f64,
) -> f64 {
    circular_traction(
        &CircleRule::new(model),
        radius_m,
        peak_pressure_pa,
        sliding_m_s,
        film_m,
    )
}

/// The circle's strip rule with what does not depend on the contact: the law prepared
/// ([`TractionModel::prepared`]) and the nodes' cos θ with their weights, computed once per
/// guide-ring balance instead of once per end contact and ring speed (the same numbers, so
/// [`circular_contact_traction_n`] bit for bit).
struct CircleRule {
    law: PreparedTraction,
    /// (cos θ, weight) per node of [`gl8_quarter`].
    nodes: [(f64, f64); 8],
}

impl CircleRule {
    fn new(model: &TractionModel) -> Self {
        CircleRule {
            law: model.prepared(),
            nodes: gl8_quarter().map(|(theta, w)| (theta.cos(), w)),
        }
    }
}

fn circular_traction(
    rule: &CircleRule,
    radius_m: f64,
    peak_pressure_pa: f64,
    sliding_m_s: f64,
    film_m: f64,
) -> f64 {
    if !(radius_m > 0.0 && peak_pressure_pa > 0.0) || sliding_m_s == 0.0 {
        return 0.0;
    }
    let a = radius_m;
    let mut sum = 0.0;
    for &(c, w) in &rule.nodes {
        let b = a * c;
        // Strip of unit width with peak p₀·cos θ: q = π·b·p/2 per metre of width.
        let strip = HertzStrip {
            load_n: std::f64::consts::FRAC_PI_2 * b * peak_pressure_pa * c,
            half_width_m: b,
            width_m: 1.0,
        };
        let f = rule
            .law
            .lamina_traction(&strip, sliding_m_s, film_m)
            .force_n;
        sum += w * f * a * c; // dy = a·cos θ dθ
    }
    2.0 * sum
}

/// The guide ring and its end contacts, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GuideRingGeometry {
    /// R_e, radius of the roller's spherical end, m.
    pub roller_end_radius_m: f64,
    /// E*, reduced modulus of roller and ring, Pa.
    pub reduced_modulus_pa: f64,
    /// r_g, distance of the end contacts from the bearing axis, m.
    pub contact_radius_m: f64,
    /// R_b, bore radius of the guide ring (on the inner ring), m.
    pub bore_radius_m: f64,
    /// L_b, width of the bore film, m.
    pub width_m: f64,
    /// c, radial clearance of the bore, m.
    pub bore_clearance_m: f64,
}

/// One roller's end contact as the guide ring sees it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EndContactInput {
    /// Q, normal load of the roller end on the ring (from the roller's axial balance), N.
    pub load_n: f64,
    /// u, speed of the roller end's contact point relative to the cage, along the bearing's
    /// rotation (ω_R × offset from the roller axis), m/s.
    pub roller_end_speed_m_s: f64,
    /// ω_c, the roller's orbital (cage) speed, rad/s.
    pub orbital_speed_rad_s: f64,
    /// The roller end's sliding across the ring's face, normal to the circumferential
    /// direction, m/s (a skewed roller's end touches the ring off its axis by δ and its
    /// spin sweeps that point radially at ω_s·δ; 0 for a contact on the axis). The traction
    /// acts along the whole sliding vector (module notes "Off-axis contact").
    #[serde(default)]
    pub radial_sliding_m_s: f64,
}

/// The cage's land film on the guide ring's outer surface (deck `land = "guide-ring"`),
/// SI: a Petroff journal whose torque acts on the cage and, opposite, on the ring (module
/// notes "The cage's land on the ring").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CageLandOnRing {
    /// R_l, land radius, m.
    pub radius_m: f64,
    /// L_l, land width, m.
    pub width_m: f64,
    /// c_l, radial clearance of the land, m.
    pub radial_clearance_m: f64,
    /// ω_c, the cage's speed, rad/s.
    pub cage_speed_rad_s: f64,
}

impl CageLandOnRing {
    /// The land film's torque on the ring at ring speed ω_g, N·m, opposing ω_g − ω_c:
    /// −2π·η·R_l³·L_l·(ω_g − ω_c)/c_l (`cage_film::land_torque_on_cage_nm` with the
    /// ring as the moving body).
    ///
    /// # Errors
    /// [`GuideRingError::BadInput`] for a non-positive radius, width or clearance.
    pub fn torque_on_ring_nm(
        &self,
        viscosity_pa_s: f64,
        ring_speed_rad_s: f64,
    ) -> Result<f64, GuideRingError> {
        land_torque_on_cage_nm(
            viscosity_pa_s,
            self.radius_m,
            self.width_m,
            self.radial_clearance_m,
            ring_speed_rad_s - self.cage_speed_rad_s,
        )
        .map_err(|_| GuideRingError::BadInput {
            name: "cage land on the guide ring (radius, width, clearance)",
            value: self.radial_clearance_m,
            allowed: "positive and finite",
        })
    }
}

/// Result of one end contact at a given ring speed.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct EndContact {
    /// a, Hertz radius, m.
    pub radius_m: f64,
    /// p₀, peak pressure, Pa.
    pub max_pressure_pa: f64,
    /// Central film, m.
    pub film_m: f64,
    /// Ring minus roller end speed, m/s (circumferential).
    pub sliding_speed_m_s: f64,
    /// The sliding across the face (the input's `radial_sliding_m_s`), m/s.
    #[serde(default)]
    pub radial_sliding_m_s: f64,
    /// Traction on the roller along the bearing's rotation, N.
    pub force_on_roller_n: f64,
    /// |F|·|v| over the whole sliding vector (circumferential and radial), W.
    pub power_w: f64,
}

/// The guide ring at its torque balance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GuideRingSolution {
    /// ω_g, rad/s.
    pub speed_rad_s: f64,
    /// Per roller, in input order.
    pub contacts: Vec<EndContact>,
    /// Σ end-contact power, W.
    pub ends_power_w: f64,
    /// Petroff power of the bore film, |T|·|ω_g − ω_i|, W.
    pub bore_power_w: f64,
    /// Bore torque on the ring (signed, about the bearing axis), N·m.
    pub bore_torque_nm: f64,
    /// The cage land's torque on the ring (signed; 0 unless the cage is piloted on it),
    /// N·m.
    #[serde(default)]
    pub land_torque_nm: f64,
    /// Torque balance residual at ω_g, N·m.
    pub residual_nm: f64,
}

/// Why the end contacts or the guide ring's balance cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum GuideRingError {
    /// A geometry or lubricant value is outside its range.
    #[error("guide ring {name} = {value} is not usable: it must be {allowed}")]
    BadInput {
        /// The field.
        name: &'static str,
        /// Its value (SI).
        value: f64,
        /// The allowed range.
        allowed: &'static str,
    },
    /// The printed eq. 3 at a loaded, sliding end contact without a film is infinite.
    #[error(
        "the roller end contact slides at {sliding_m_s} m/s without an EHD film (entrainment 0): eq. 3 as printed gives an infinite force; use traction = \"atz\""
    )]
    NoFilm {
        /// The sliding speed, m/s.
        sliding_m_s: f64,
    },
    /// The torque balance did not converge inside its bracket.
    #[error(
        "the guide ring speed did not converge between {lo_rad_s} and {hi_rad_s} rad/s (torque residuals {g_lo_nm} and {g_hi_nm} N·m)"
    )]
    NoBalance {
        /// Lower end of the bracket, rad/s.
        lo_rad_s: f64,
        /// Upper end, rad/s.
        hi_rad_s: f64,
        /// Residual at the lower end, N·m.
        g_lo_nm: f64,
        /// Residual at the upper end, N·m.
        g_hi_nm: f64,
    },
}

fn positive(name: &'static str, value: f64) -> Result<f64, GuideRingError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(GuideRingError::BadInput {
            name,
            value,
            allowed: "positive and finite",
        })
    }
}

impl GuideRingGeometry {
    fn validate(&self) -> Result<(), GuideRingError> {
        positive("roller_end_radius_m", self.roller_end_radius_m)?;
        positive("reduced_modulus_pa", self.reduced_modulus_pa)?;
        positive("contact_radius_m", self.contact_radius_m)?;
        positive("bore_radius_m", self.bore_radius_m)?;
        positive("width_m", self.width_m)?;
        positive("bore_clearance_m", self.bore_clearance_m)?;
        Ok(())
    }

    /// Petroff torque of the bore film on the ring, N·m (signed: it opposes ω_g − ω_i):
    /// T = −2π·η·R_b³·L_b·(ω_g − ω_i)/c, through `heat::cage_rail_friction_force_n`
    /// (F = π·η·W·D²·|Δω|/dc with D = 2R_b, dc = 2c) times R_b.
    ///
    /// # Errors
    /// [`GuideRingError::BadInput`] for a non-positive bore radius, width or clearance, or
    /// a negative viscosity.
    pub fn bore_torque_nm(
        &self,
        viscosity_pa_s: f64,
        ring_speed_rad_s: f64,
        inner_speed_rad_s: f64,
    ) -> Result<f64, GuideRingError> {
        let dw = ring_speed_rad_s - inner_speed_rad_s;
        if viscosity_pa_s == 0.0 || dw == 0.0 {
            return Ok(0.0);
        }
        let f = cage_rail_friction_force_n(
            viscosity_pa_s,
            self.width_m,
            2.0 * self.bore_radius_m,
            2.0 * self.bore_clearance_m,
            dw,
        )
        .map_err(|e| match e {
            HeatError::NotPositive { value, .. } => GuideRingError::BadInput {
                name: "bore geometry or viscosity",
                value,
                allowed: "positive and finite",
            },
        })?;
        Ok(-f * self.bore_radius_m * dw.signum())
    }
}

/// One end contact at the ring speed `ring_speed_rad_s`.
///
/// # Errors
/// [`GuideRingError::BadInput`] for a negative or non-finite load, [`GuideRingError::NoFilm`]
/// for the printed eq. 3 at a sliding contact without film.
pub fn end_contact(
    geometry: &GuideRingGeometry,
    hertz: &HertzPointContact,
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    input: &EndContactInput,
    ring_speed_rad_s: f64,
) -> Result<EndContact, GuideRingError> {
    let rule = CircleRule::new(&rheology.atz());
    end_contact_in(
        geometry,
        hertz,
        law,
        rheology,
        &rule,
        None,
        input,
        ring_speed_rad_s,
    )
}

/// The Hertz circle of an end contact under its load (`hertz.solve(Q)`): it does not
/// depend on the ring speed, so a balance solves it once per roller.
fn end_circle(hertz: &HertzPointContact, load_n: f64) -> Result<PointContact, GuideRingError> {
    hertz.solve(load_n).map_err(|_| GuideRingError::BadInput {
        name: "guide_ring_load_n",
        value: load_n,
        allowed: "a load the Hertz circle accepts",
    })
}

/// [`end_contact`] with the strip rule prepared and, for a loaded end, its Hertz circle
/// solved by the caller (`circle`, [`end_circle`] of the input's load; `None`: solved
/// here). The same arithmetic, so the same answer bit for bit.
#[allow(clippy::too_many_arguments)]
fn end_contact_in(
    geometry: &GuideRingGeometry,
    hertz: &HertzPointContact,
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    rule: &CircleRule,
    circle: Option<&PointContact>,
    input: &EndContactInput,
    ring_speed_rad_s: f64,
) -> Result<EndContact, GuideRingError> {
    let q = input.load_n;
    if !(q.is_finite() && q >= 0.0) {
        return Err(GuideRingError::BadInput {
            name: "guide_ring_load_n",
            value: q,
            allowed: "finite and not negative",
        });
    }
    let r = geometry.contact_radius_m;
    // Surface speeds in the cage frame, along the bearing's rotation.
    let u_ring = (ring_speed_rad_s - input.orbital_speed_rad_s) * r;
    let u_roller = input.roller_end_speed_m_s;
    let v = u_ring - u_roller;
    let vr = input.radial_sliding_m_s;
    if !vr.is_finite() {
        return Err(GuideRingError::BadInput {
            name: "radial_sliding_m_s",
            value: vr,
            allowed: "finite",
        });
    }
    // The traction's magnitude is the law's at |v| (isotropic shear), along v; on the axis
    // (v_r = 0) the signed circumferential speed itself, exactly as before the skew.
    let speed = if vr == 0.0 { v } else { v.hypot(vr) };
    if q == 0.0 {
        return Ok(EndContact {
            sliding_speed_m_s: v,
            radial_sliding_m_s: vr,
            ..EndContact::default()
        });
    }
    let c = match circle {
        Some(c) => *c,
        None => end_circle(hertz, q)?,
    };
    let a = c.semi_major_m;
    let p0 = c.max_pressure_pa;
    let u_e = 0.5 * (u_ring + u_roller);
    let film = PointFilmInputs::from_contact(
        hertz,
        q,
        rheology.viscosity_pa_s,
        rheology.pressure_viscosity_pa_inv,
        u_e,
    )
    .central_film_thickness_m()
    .map_err(|_| GuideRingError::BadInput {
        name: "viscosity or pressure-viscosity coefficient of the end-contact film",
        value: rheology.pressure_viscosity_pa_inv,
        allowed: "finite and not negative",
    })?;
    let magnitude = if rheology.viscosity_pa_s <= 0.0 || speed == 0.0 {
        0.0
    } else {
        match law {
            RacewayTractionLaw::Atz => circular_traction(rule, a, p0, speed, film),
            RacewayTractionLaw::NewtonianEq3 => {
                if film <= 0.0 {
                    return Err(GuideRingError::NoFilm { sliding_m_s: speed });
                }
                let area = std::f64::consts::PI * a * a;
                rheology.viscosity_pa_s
                    * (rheology.pressure_viscosity_pa_inv * q / area).exp()
                    * speed
                    / film
                    * area
            }
        }
    };
    // Its circumferential component (on the axis the force itself, sign included).
    let force = if vr == 0.0 || speed == 0.0 {
        magnitude
    } else {
        magnitude * v / speed
    };
    Ok(EndContact {
        radius_m: a,
        max_pressure_pa: p0,
        film_m: film,
        sliding_speed_m_s: v,
        radial_sliding_m_s: vr,
        force_on_roller_n: force,
        power_w: (magnitude * speed).abs(),
    })
}

/// The Hertz model of the end contact: a sphere of radius R_e on a flat.
///
/// # Errors
/// [`GuideRingError::BadInput`] for an unusable geometry.
pub fn end_contact_model(
    geometry: &GuideRingGeometry,
) -> Result<HertzPointContact, GuideRingError> {
    geometry.validate()?;
    let k = 1.0 / geometry.roller_end_radius_m;
    let curvature = CurvatureSum::new(k, k).map_err(|_| GuideRingError::BadInput {
        name: "roller_end_radius_m",
        value: geometry.roller_end_radius_m,
        allowed: "positive and finite",
    })?;
    HertzPointContact::new(curvature, geometry.reduced_modulus_pa, HertzMethod::Exact).map_err(
        |_| GuideRingError::BadInput {
            name: "reduced_modulus_pa",
            value: geometry.reduced_modulus_pa,
            allowed: "positive and finite",
        },
    )
}

/// The guide ring's speed from its torque balance, and its losses (module notes).
///
/// # Errors
/// [`GuideRingError::BadInput`] for an unusable geometry, viscosity or roller input,
/// [`GuideRingError::NoFilm`] (printed eq. 3 only), [`GuideRingError::NoBalance`] if the
/// bracketed search fails.
pub fn guide_ring_balance(
    geometry: &GuideRingGeometry,
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    inner_speed_rad_s: f64,
    rollers: &[EndContactInput],
) -> Result<GuideRingSolution, GuideRingError> {
    guide_ring_balance_with_land(geometry, law, rheology, inner_speed_rad_s, rollers, None)
}

/// As [`guide_ring_balance`], with the cage's land film on the ring (`land`, module notes
/// "The cage's land on the ring") in the ring's torque balance.
///
/// # Errors
/// As [`guide_ring_balance`]; [`GuideRingError::BadInput`] for an unusable land.
pub fn guide_ring_balance_with_land(
    geometry: &GuideRingGeometry,
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    inner_speed_rad_s: f64,
    rollers: &[EndContactInput],
    land: Option<&CageLandOnRing>,
) -> Result<GuideRingSolution, GuideRingError> {
    guide_ring_balance_near(
        geometry,
        law,
        rheology,
        inner_speed_rad_s,
        rollers,
        land,
        None,
    )
}

/// Where [`guide_ring_balance_near`] starts: a guess of the ring speed and the first
/// bracketing step, rad/s (a previous, nearby balance's speed: the double-row cage
/// balance's last iterates, `double_row_spherical::losses`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingSpeedGuess {
    /// The guess, rad/s (clamped into the balance's bracket).
    pub speed_rad_s: f64,
    /// The first step from it toward the root, rad/s (doubled until the residual changes
    /// sign; at least 1e-12 of the bracket's speed scale).
    pub step_rad_s: f64,
}

/// The ring speed's tolerance: the search stops once the root is bracketed to this
/// fraction of the bracket's speed scale max(|ω_lo|, |ω_hi|) (or the residual is 0).
pub const RING_SPEED_TOLERANCE: f64 = 1e-13;

/// [`guide_ring_balance_with_land`] from a guess (`near`): the residual G(ω_g) is evaluated
/// at the guess and then at steps toward its root (doubling) until it changes sign, inside
/// the balance's bracket [ω_lo, ω_hi] (module notes), and the Illinois search closes that
/// bracket to the same [`RING_SPEED_TOLERANCE`]; a guess whose search reaches the bracket's
/// end without a sign change falls back to the bracket itself. Two to four residuals
/// instead of the full bracket's ten or more when the guess is within a step of the root.
/// `None`: the full bracket (the answer of [`guide_ring_balance_with_land`]). The Hertz
/// circle of each loaded end and the strip rule are solved once per call (neither depends
/// on the ring speed).
///
/// # Errors
/// As [`guide_ring_balance_with_land`].
pub fn guide_ring_balance_near(
    geometry: &GuideRingGeometry,
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    inner_speed_rad_s: f64,
    rollers: &[EndContactInput],
    land: Option<&CageLandOnRing>,
    near: Option<RingSpeedGuess>,
) -> Result<GuideRingSolution, GuideRingError> {
    let hertz = end_contact_model(geometry)?;
    let eta = rheology.viscosity_pa_s;
    if !(eta.is_finite() && eta >= 0.0) {
        return Err(GuideRingError::BadInput {
            name: "viscosity_pa_s",
            value: eta,
            allowed: "finite and not negative",
        });
    }
    if !inner_speed_rad_s.is_finite() {
        return Err(GuideRingError::BadInput {
            name: "inner_speed_rad_s",
            value: inner_speed_rad_s,
            allowed: "finite",
        });
    }
    let r = geometry.contact_radius_m;
    let (mut lo, mut hi) = (inner_speed_rad_s, inner_speed_rad_s);
    for k in rollers {
        if !(k.roller_end_speed_m_s.is_finite() && k.orbital_speed_rad_s.is_finite()) {
            return Err(GuideRingError::BadInput {
                name: "roller end or orbital speed",
                value: if k.roller_end_speed_m_s.is_finite() {
                    k.orbital_speed_rad_s
                } else {
                    k.roller_end_speed_m_s
                },
                allowed: "finite",
            });
        }
        let w = k.orbital_speed_rad_s + k.roller_end_speed_m_s / r;
        lo = lo.min(w);
        hi = hi.max(w);
    }
    if let Some(c) = land {
        if !c.cage_speed_rad_s.is_finite() {
            return Err(GuideRingError::BadInput {
                name: "cage_speed_rad_s",
                value: c.cage_speed_rad_s,
                allowed: "finite",
            });
        }
        lo = lo.min(c.cage_speed_rad_s);
        hi = hi.max(c.cage_speed_rad_s);
    }
    let rule = CircleRule::new(&rheology.atz());
    // A loaded end's circle once (an unusable load is left to the contact, which reports
    // it where it always did).
    let circles: Vec<Option<PointContact>> = rollers
        .iter()
        .map(|k| {
            (k.load_n.is_finite() && k.load_n > 0.0)
                .then(|| end_circle(&hertz, k.load_n).ok())
                .flatten()
        })
        .collect();
    let contact = |k: &EndContactInput, c: &Option<PointContact>, w: f64| {
        end_contact_in(geometry, &hertz, law, rheology, &rule, c.as_ref(), k, w)
    };
    let land_torque = |w: f64| -> Result<f64, GuideRingError> {
        land.map_or(Ok(0.0), |c| c.torque_on_ring_nm(eta, w))
    };
    let residual = |w: f64| -> Result<f64, GuideRingError> {
        let mut t = geometry.bore_torque_nm(eta, w, inner_speed_rad_s)? + land_torque(w)?;
        for (k, c) in rollers.iter().zip(&circles) {
            t -= contact(k, c, w)?.force_on_roller_n * r;
        }
        Ok(t)
    };
    let scale = lo.abs().max(hi.abs()).max(1e-9);
    let full = || -> Result<f64, GuideRingError> {
        let (g_lo, g_hi) = (residual(lo)?, residual(hi)?);
        if g_lo == 0.0 || hi == lo {
            Ok(lo)
        } else if g_hi == 0.0 {
            Ok(hi)
        } else if g_lo > 0.0 && g_hi < 0.0 {
            illinois(&residual, (lo, g_lo), (hi, g_hi), scale)
        } else {
            Err(GuideRingError::NoBalance {
                lo_rad_s: lo,
                hi_rad_s: hi,
                g_lo_nm: g_lo,
                g_hi_nm: g_hi,
            })
        }
    };
    let speed = match near {
        Some(g) if hi > lo && g.speed_rad_s.is_finite() && g.step_rad_s.is_finite() => {
            match near_root(&residual, g, (lo, hi), scale)? {
                Some(x) => x,
                None => full()?,
            }
        }
        _ => full()?,
    };
    let contacts = rollers
        .iter()
        .zip(&circles)
        .map(|(k, c)| contact(k, c, speed))
        .collect::<Result<Vec<_>, _>>()?;
    let bore_torque_nm = geometry.bore_torque_nm(eta, speed, inner_speed_rad_s)?;
    let land_torque_nm = land_torque(speed)?;
    let ends_power_w: f64 = contacts.iter().map(|c| c.power_w).sum();
    let residual_nm = bore_torque_nm + land_torque_nm
        - contacts
            .iter()
            .map(|c| c.force_on_roller_n * r)
            .sum::<f64>();
    Ok(GuideRingSolution {
        speed_rad_s: speed,
        contacts,
        ends_power_w,
        bore_power_w: (bore_torque_nm * (speed - inner_speed_rad_s)).abs(),
        bore_torque_nm,
        land_torque_nm,
        residual_nm,
    })
}

/// The ring's root from a guess ([`guide_ring_balance_near`]): G falls with ω_g (every
/// torque pushes the ring toward its bracket), so G > 0 means the root lies above. Steps
/// from the guess toward it, doubling, inside [lo, hi]; `None` when a step reaches the
/// bracket's end without a sign change (the caller then searches the whole bracket).
fn near_root(
    g: &dyn Fn(f64) -> Result<f64, GuideRingError>,
    guess: RingSpeedGuess,
    (lo, hi): (f64, f64),
    scale: f64,
) -> Result<Option<f64>, GuideRingError> {
    let x0 = guess.speed_rad_s.clamp(lo, hi);
    let f0 = g(x0)?;
    if f0 == 0.0 {
        return Ok(Some(x0));
    }
    let dir = if f0 > 0.0 { 1.0 } else { -1.0 };
    let mut h = guess.step_rad_s.abs().max(1e-12 * scale);
    let (mut a, mut fa) = (x0, f0);
    for _ in 0..60 {
        if (dir > 0.0 && a >= hi) || (dir < 0.0 && a <= lo) {
            return Ok(None);
        }
        let b = (a + dir * h).clamp(lo, hi);
        let fb = g(b)?;
        if fb == 0.0 {
            return Ok(Some(b));
        }
        if (fb > 0.0) != (fa > 0.0) {
            return illinois(g, (a, fa), (b, fb), scale).map(Some);
        }
        (a, fa) = (b, fb);
        h *= 2.0;
    }
    Ok(None)
}

/// Illinois regula falsi on a bracket with g(a)·g(b) < 0; stops when the bracket is
/// below [`RING_SPEED_TOLERANCE`] of the speed scale `scale` or the residual is 0.
fn illinois(
    g: &dyn Fn(f64) -> Result<f64, GuideRingError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    scale: f64,
) -> Result<f64, GuideRingError> {
    let (lo0, hi0, g_lo0, g_hi0) = (a, b, fa, fb);
    let mut side = 0i8;
    for _ in 0..200 {
        let x = (a * fb - b * fa) / (fb - fa);
        let x = if x.is_finite() && x > a.min(b) && x < a.max(b) {
            x
        } else {
            0.5 * (a + b)
        };
        let fx = g(x)?;
        if fx == 0.0 || (b - a).abs() < RING_SPEED_TOLERANCE * scale {
            return Ok(x);
        }
        if (fx > 0.0) == (fa > 0.0) {
            a = x;
            fa = fx;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            b = x;
            fb = fx;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
    }
    Err(GuideRingError::NoBalance {
        lo_rad_s: lo0,
        hi_rad_s: hi0,
        g_lo_nm: g_lo0,
        g_hi_nm: g_hi0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring() -> GuideRingGeometry {
        GuideRingGeometry {
            roller_end_radius_m: 0.03,
            reduced_modulus_pa: 2.3e11 / 2.0 / (1.0 - 0.09), // steel on steel
            contact_radius_m: 0.031,
            bore_radius_m: 0.026,
            width_m: 0.006,
            bore_clearance_m: 1e-4,
        }
    }

    fn oil() -> FilmRheology {
        FilmRheology {
            viscosity_pa_s: 0.017,
            pressure_viscosity_pa_inv: 2.0e-8,
            transition_shear_stress_pa: 5.0e6,
            limiting_traction_coefficient: 0.06,
        }
    }

    /// A constant μ over the circle gives F = μ·Q (∫∫μp dA), to 1e-13: the strip
    /// quadrature integrates the Hertz circle's cos³θ to round-off. A constant viscous
    /// stress (α = 0, no limit) gives η·v/h·πa² to 1e-13.
    #[test]
    fn circle_quadrature_is_exact_for_the_limits() {
        let (a, p0) = (2e-4, 1.2e9);
        let q = 2.0 / 3.0 * std::f64::consts::PI * a * a * p0;
        let f =
            circular_contact_traction_n(&TractionModel::Constant { mu: 0.07 }, a, p0, -0.3, 1e-7);
        assert!((f + 0.07 * q).abs() < 1e-13 * q, "{f} vs {}", -0.07 * q);
        let m = TractionModel::Ehd {
            viscosity_pa_s: 0.02,
            pressure_viscosity_pa_inv: 0.0,
            transition_shear_stress_pa: 1e15,
            limiting_traction_coefficient: 0.0,
        };
        let f = circular_contact_traction_n(&m, a, p0, 0.3, 1e-7);
        let want = 0.02 * 0.3 / 1e-7 * std::f64::consts::PI * a * a;
        assert!((f / want - 1.0).abs() < 1e-13, "{f} vs {want}");
    }

    /// Bore torque is Petroff's T = 2π·η·R³·L·ω/c, typed out independently (1e-13).
    #[test]
    fn bore_torque_is_petroff() {
        let g = ring();
        let t = g.bore_torque_nm(0.017, 250.0, 400.0).expect("valid");
        let want = 2.0 * std::f64::consts::PI * 0.017 * 0.026f64.powi(3) * 0.006 * 150.0 / 1e-4;
        assert!((t - want).abs() < 1e-13 * want, "{t} vs {want}");
        assert_eq!(g.bore_torque_nm(0.0, 250.0, 400.0), Ok(0.0));
    }

    /// Balance with unloaded roller ends: the ring runs with the inner ring and loses
    /// nothing. With loaded ends it settles strictly between the inner ring's speed and
    /// the roller ends' speed, the torques balance (residual below 1e-9 of the bore torque),
    /// and each side's power is positive.
    /// Two Petroff films in series (srb10): a ring touched by no roller end, between the
    /// bore on the inner ring (k_b = 2π·η·R_b³·L_b/c_b) and the cage's land on its outer
    /// surface (k_l = 2π·η·R_l³·L_l/c_l), runs where the two torques cancel,
    /// ω_g = (k_b·ω_i + k_l·ω_c)/(k_b + k_l), and the two films dissipate
    /// k_b·k_l/(k_b + k_l)·(ω_i − ω_c)² — the closed form, computed here from the Petroff
    /// coefficients directly, to 1e-12 (the Illinois search's tolerance is 1e-13 of the
    /// speed). Without the land the ring would run with the inner ring (0 W): the land's
    /// reaction is what the balance must carry. With loaded ends the land still enters the
    /// balance (the residual, with the land's torque, ≤ 1e-9 of it) and slows the ring.
    #[test]
    fn cage_land_on_the_ring_is_in_its_balance() {
        let (wi, wc) = (400.0, 160.0);
        let g = ring();
        let eta = oil().viscosity_pa_s;
        let land = CageLandOnRing {
            radius_m: 0.031,
            width_m: 0.004,
            radial_clearance_m: 2e-4,
            cage_speed_rad_s: wc,
        };
        let k = |r: f64, l: f64, c: f64| 2.0 * std::f64::consts::PI * eta * r.powi(3) * l / c;
        let kb = k(g.bore_radius_m, g.width_m, g.bore_clearance_m);
        let kl = k(land.radius_m, land.width_m, land.radial_clearance_m);
        let free = vec![
            EndContactInput {
                load_n: 0.0,
                roller_end_speed_m_s: 0.0,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            };
            13
        ];
        let law = RacewayTractionLaw::Atz;
        let s =
            guide_ring_balance_with_land(&g, law, &oil(), wi, &free, Some(&land)).expect("balance");
        let w = (kb * wi + kl * wc) / (kb + kl);
        assert!(
            (s.speed_rad_s - w).abs() <= 1e-12 * wi,
            "{} vs {w}",
            s.speed_rad_s
        );
        let p = kb * kl / (kb + kl) * (wi - wc).powi(2);
        let land_w = s.land_torque_nm.abs() * (s.speed_rad_s - wc).abs();
        assert!((s.bore_power_w + land_w - p).abs() <= 1e-10 * p);
        assert!((s.land_torque_nm + kl * (s.speed_rad_s - wc)).abs() <= 1e-10 * kl * wi);
        let loaded: Vec<_> = (0..13)
            .map(|k| EndContactInput {
                load_n: 1.0 + 0.1 * k as f64,
                roller_end_speed_m_s: 0.0,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            })
            .collect();
        let without = guide_ring_balance(&g, law, &oil(), wi, &loaded).expect("balance");
        let with = guide_ring_balance_with_land(&g, law, &oil(), wi, &loaded, Some(&land))
            .expect("balance");
        assert!(with.speed_rad_s < without.speed_rad_s);
        assert!(with.residual_nm.abs() <= 1e-9 * with.bore_torque_nm.abs());
        assert_eq!(without.land_torque_nm, 0.0);
    }

    #[test]
    fn balance_bracket_and_residual() {
        let (wi, wc) = (400.0, 160.0);
        let free = vec![
            EndContactInput {
                load_n: 0.0,
                roller_end_speed_m_s: 0.0,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            };
            13
        ];
        let s = guide_ring_balance(&ring(), RacewayTractionLaw::Atz, &oil(), wi, &free)
            .expect("balance");
        assert_eq!(s.speed_rad_s, wi);
        assert_eq!(s.ends_power_w + s.bore_power_w, 0.0);
        let loaded: Vec<_> = (0..13)
            .map(|k| EndContactInput {
                load_n: 50.0 + 10.0 * k as f64,
                roller_end_speed_m_s: 0.05,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            })
            .collect();
        let s = guide_ring_balance(&ring(), RacewayTractionLaw::Atz, &oil(), wi, &loaded)
            .expect("balance");
        let w_end = wc + 0.05 / 0.031;
        assert!(
            s.speed_rad_s > w_end && s.speed_rad_s < wi,
            "{}",
            s.speed_rad_s
        );
        assert!(
            s.residual_nm.abs() < 1e-9 * s.bore_torque_nm.abs(),
            "{}",
            s.residual_nm
        );
        assert!(s.ends_power_w > 0.0 && s.bore_power_w > 0.0);
        // Power check: Σ|F v| over the ends equals Σ F·v (every end slides the same way).
        let by_hand: f64 = s
            .contacts
            .iter()
            .map(|c| c.force_on_roller_n * c.sliding_speed_m_s)
            .sum();
        assert!((by_hand - s.ends_power_w).abs() < 1e-12 * s.ends_power_w);
    }

    /// A balance started from a guess (`guide_ring_balance_near`, srb12: the double-row
    /// cage balance's warm start) finds the full bracket's ring speed to its tolerance
    /// (both are bracketed to 1e-13 of the speed scale: agreement to 2e-13 relative; the
    /// end forces themselves can be steep in ω_g, so they are checked bit for bit against
    /// the public `end_contact` at the found speed), from guesses below, above and at the root,
    /// with steps smaller and larger than the distance, inside and clamped at the bracket's
    /// ends; with and without the cage's land on the ring.
    #[test]
    fn balance_from_a_guess_is_the_bracketed_balance() {
        let (wi, wc) = (400.0, 160.0);
        let loaded: Vec<_> = (0..13)
            .map(|k| EndContactInput {
                load_n: if k % 3 == 0 {
                    0.0
                } else {
                    50.0 + 10.0 * k as f64
                },
                roller_end_speed_m_s: 0.05,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            })
            .collect();
        let land = CageLandOnRing {
            radius_m: 0.033,
            width_m: 0.004,
            radial_clearance_m: 2e-4,
            cage_speed_rad_s: wc,
        };
        for on_ring in [None, Some(&land)] {
            let full = guide_ring_balance_with_land(
                &ring(),
                RacewayTractionLaw::Atz,
                &oil(),
                wi,
                &loaded,
                on_ring,
            )
            .expect("balance");
            let w = full.speed_rad_s;
            for (guess, step) in [
                (w, 1e-3),
                (w - 5.0, 0.01),
                (w + 5.0, 20.0),
                (w * (1.0 + 1e-9), 1e-12),
                (0.0, 1.0),
                (1e4, 1.0),
            ] {
                let near = guide_ring_balance_near(
                    &ring(),
                    RacewayTractionLaw::Atz,
                    &oil(),
                    wi,
                    &loaded,
                    on_ring,
                    Some(RingSpeedGuess {
                        speed_rad_s: guess,
                        step_rad_s: step,
                    }),
                )
                .expect("balance");
                assert!(
                    (near.speed_rad_s - w).abs() <= 2e-13 * wi,
                    "guess {guess}: {} vs {w}",
                    near.speed_rad_s
                );
                // The hoisted circle and strip rule are the public end contact's numbers.
                let h = end_contact_model(&ring()).expect("model");
                for (c, k) in near.contacts.iter().zip(&loaded) {
                    let by_hand = end_contact(
                        &ring(),
                        &h,
                        RacewayTractionLaw::Atz,
                        &oil(),
                        k,
                        near.speed_rad_s,
                    )
                    .expect("contact");
                    assert_eq!(*c, by_hand);
                }
            }
        }
    }

    /// The end contact's film is the Hamrock–Dowson central film of a sphere on a flat
    /// (k = 1, R_x = R_e) at u_e = ½(u_ring + u_roller), recomputed here from the groups
    /// (1e-12).
    #[test]
    fn end_film_is_hamrock_dowson() {
        let g = ring();
        let h = end_contact_model(&g).expect("model");
        let inp = EndContactInput {
            load_n: 120.0,
            roller_end_speed_m_s: 0.2,
            orbital_speed_rad_s: 150.0,
            radial_sliding_m_s: 0.0,
        };
        let c = end_contact(&g, &h, RacewayTractionLaw::Atz, &oil(), &inp, 300.0).expect("contact");
        let u_ring = 150.0 * 0.031;
        let ue = 0.5 * (u_ring + 0.2);
        let e = 2.0 * g.reduced_modulus_pa;
        let (u, gg, w) = (
            0.017 * ue / (e * 0.03),
            2.0e-8 * e,
            120.0 / (e * 0.03 * 0.03),
        );
        let hc = 0.03
            * 2.69
            * u.powf(0.67)
            * gg.powf(0.53)
            * w.powf(-0.067)
            * (1.0 - 0.61 * f64::exp(-0.73));
        assert!((c.film_m / hc - 1.0).abs() < 1e-12, "{} {hc}", c.film_m);
        assert!((c.sliding_speed_m_s - (u_ring - 0.2)).abs() < 1e-15);
        // Hertz circle: a = (3QR/(4E*))^⅓.
        let a = (3.0 * 120.0 * 0.03 / (4.0 * g.reduced_modulus_pa)).cbrt();
        assert!((c.radius_m / a - 1.0).abs() < 1e-12);
    }

    /// The other limit: a bore film that barely brakes (clearance 1 m) lets the ring run
    /// with the roller ends, ω_g → ω_c + u/r_g; the gap to that speed is below 1e-3 of the
    /// gap between the inner ring and it (the bore torque is ~10⁻⁸ of the ends' slope).
    #[test]
    fn free_ring_follows_the_roller_ends() {
        let mut g = ring();
        g.bore_clearance_m = 1.0;
        let (wi, wc, u) = (400.0, 160.0, 0.05);
        let inp = vec![
            EndContactInput {
                load_n: 60.0,
                roller_end_speed_m_s: u,
                orbital_speed_rad_s: wc,
                radial_sliding_m_s: 0.0,
            };
            13
        ];
        let s = guide_ring_balance(&g, RacewayTractionLaw::Atz, &oil(), wi, &inp).expect("balance");
        let w_end = wc + u / 0.031;
        assert!(s.speed_rad_s >= w_end, "{}", s.speed_rad_s);
        assert!(
            s.speed_rad_s - w_end < 1e-3 * (wi - w_end),
            "{} vs {w_end}",
            s.speed_rad_s
        );
    }

    /// Off the roller axis (a skewed roller's end, module notes "Off-axis contact"): the
    /// traction is the circle's at the whole sliding speed |v| = √(v_θ² + v_r²) (built here
    /// from `circular_contact_traction_n` on the on-axis contact's own radius, pressure
    /// and film, which v_r does not change), its circumferential component F·v_θ/|v|, and
    /// the power F·|v| (1e-13). A radial sliding adds loss and lowers the circumferential
    /// force (the saturating law shares its magnitude).
    #[test]
    fn off_axis_end_slides_along_the_whole_vector() {
        let g = ring();
        let h = end_contact_model(&g).expect("model");
        let on = EndContactInput {
            load_n: 60.0,
            roller_end_speed_m_s: 0.0,
            orbital_speed_rad_s: 150.0,
            radial_sliding_m_s: 0.0,
        };
        let off = EndContactInput {
            radial_sliding_m_s: -0.3,
            ..on
        };
        let c0 = end_contact(&g, &h, RacewayTractionLaw::Atz, &oil(), &on, 160.0).expect("on");
        let c1 = end_contact(&g, &h, RacewayTractionLaw::Atz, &oil(), &off, 160.0).expect("off");
        let v = 10.0 * 0.031;
        assert!((c0.sliding_speed_m_s - v).abs() < 1e-15);
        assert_eq!(c0.film_m, c1.film_m);
        let s = v.hypot(0.3);
        let mag = circular_contact_traction_n(
            &oil().atz(),
            c0.radius_m,
            c0.max_pressure_pa,
            s,
            c0.film_m,
        );
        assert!((c1.force_on_roller_n - mag * v / s).abs() <= 1e-13 * mag);
        assert!((c1.power_w - mag * s).abs() <= 1e-13 * c1.power_w);
        assert!(c1.power_w > c0.power_w && c1.force_on_roller_n < c0.force_on_roller_n);
        assert!(c1.force_on_roller_n > 0.0);
    }

    /// η = 0: no traction, no bore torque, no loss (and no error).
    #[test]
    fn inviscid_is_lossless() {
        let mut o = oil();
        o.viscosity_pa_s = 0.0;
        let inp = vec![
            EndContactInput {
                load_n: 80.0,
                roller_end_speed_m_s: 0.1,
                orbital_speed_rad_s: 150.0,
                radial_sliding_m_s: 0.0,
            };
            4
        ];
        let s =
            guide_ring_balance(&ring(), RacewayTractionLaw::Atz, &o, 400.0, &inp).expect("balance");
        assert_eq!(s.ends_power_w + s.bore_power_w, 0.0);
    }
}
