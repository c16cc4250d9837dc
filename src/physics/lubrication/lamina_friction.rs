//! Roller/raceway traction of one lamina of a spherical roller (seed 002 §3, eq. 3):
//! force, power and the moment about the contact normal (skew), SI.
//!
//! # Eq. 3 and the two laws
//! The seed slices the roller ("for each slice the sliding speed and the contact pressure
//! is constant") and writes the elementary friction force of a Newtonian, Barus film
//!
//! dF = η·e^{α·p}·v_sl/h_EHD·dA                                   (seed 002 eq. 3)
//!
//! * [`RacewayTractionLaw::NewtonianEq3`] (`"newtonian-eq3"`) keeps eq. 3 *as printed*:
//!   on one slice p is constant, so dA is the whole strip 2b·L and p is the pressure that
//!   makes the slice carry its load, the mean Hertz pressure p̄ = q/(2bL) = π·p₀/4. The
//!   reading "p constant" is the seed's; choosing the mean (not the peak) keeps ∫p dA = q.
//!   F = η·e^{α·p̄}·v/h·2bL, exactly linear in v. At bearing pressures e^{α·p̄} is huge
//!   (α = 2·10⁻⁸ 1/Pa at 2 GPa: e⁴⁰ ≈ 10¹⁷), so the law gives traction coefficients far
//!   above anything an oil can transmit: the result is flagged
//!   ([`LaminaFriction::exceeds_newtonian_bound`]) whenever μ = |F|/q > 0.2.
//! * [`RacewayTractionLaw::Atz`] (`"atz"`, the default) reads eq. 3 as the Newtonian branch
//!   of the limiting-shear law already used for every other system: the Allen–Townsend–
//!   Zaretsky law of [`crate::physics::lubrication::traction`] (τ = min(τ_N, max(τ_tr, μ_fl·p))
//!   with τ_N the integrand of eq. 3), integrated over the Hertz semi-ellipse of the strip
//!   by `TractionModel::lamina_traction` (reused, not copied).
//!
//! # Sign and moment
//! v_sl is the raceway's surface speed minus the roller's in the rolling direction t (the
//! convention of `kinematics::sliding_velocity`); the force on the *roller* acts along +v.
//! With a the roller axis and n = a × t the contact normal, a lamina at axial offset y
//! (along a, from the roller's centre plane) carrying the force F·t has the moment
//! y·a × F·t = y·F·n about the normal through the roller centre: [`LaminaFriction::skew_moment_nm`].
//! Power = F·v ≥ 0 (the film dissipates it).
//!
//! # Regularisation at the rolling point (ATZ)
//! At bearing pressures the ATZ law's Newtonian stretch is vanishingly narrow: at
//! p = 2 GPa, α = 2e-8 1/Pa, e^{αp} ≈ 2e17 and τ_N = η·e^{αp}·|v|/h reaches the limit
//! max(τ_tr, μ_fl·p) by |v| ≈ 1e-12 m/s, so a lamina's force is a step ±F_lim across its
//! rolling point. A roller's spin balance that sits on such a lamina (the double-row
//! losses) is then resolved only to the spin's floating-point resolution (v ≈ 5e-12 m/s
//! across the spin solver's final bracket), and the force the lamina passes on — and the
//! pocket force, the skew/pocket split, the cage torque — is fixed only to that step: a
//! 7.5e-9 change of the loads moved a pocket force by 1.2 %. So below
//! v_reg = [`ATZ_REGULARISATION_SLIDING_M_S`] (1e-6 m/s) the stress is regularised:
//!
//! τ = min(τ_N, max(τ_tr, μ_fl·p)·min(1, |v|/v_reg))·sign v,
//!
//! i.e. the limit ramps in over |v| < v_reg. Below v_reg both τ_N and the ramped limit are
//! ∝ |v|, so τ(v) = τ(v_reg)·|v|/v_reg pointwise, and the lamina force is the chord
//! F(v) = F(v_reg)·v/v_reg (no extra quadrature); at |v| ≥ v_reg the law is untouched
//! (bit-identical). Continuous, odd, non-decreasing in v like the law itself. Its cost to
//! the physics: a lamina with |v| < v_reg carries at most F(v_reg) ≤ F_lim either way and
//! dissipates at most F(v_reg)·v_reg (≤ 1e-5 W for a 10 N lamina), and every other
//! lamina's sliding moves by less than v_reg when the spin balance re-seats. v_reg is
//! 500× below the slowest physical sliding scale of an EHD film (a real oil's linear
//! traction range, slide/roll ~1e-4 at 5 m/s = 5e-4 m/s) and 2e5× above the spin's
//! resolution (tested in `regularised_law_is_the_chord_and_the_law_above_v_reg`).
//! The single-row systems read `TractionModel::lamina_traction` directly: untouched.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::{Deserialize, Serialize};
use thiserror::Error;

use std::cell::Cell;

use crate::physics::lubrication::traction::{
    HertzStrip, KinkHint, PreparedTraction, TractionModel,
};

/// Traction coefficient above which the printed eq. 3 is flagged: no lubricant film
/// transmits more than about 0.1 in EHD (limiting traction coefficients of bearing oils are
/// 0.05–0.1), so 0.2 is already twice the physical ceiling.
pub const EQ3_MU_FLAG: f64 = 0.2;

/// v_reg, m/s: below this sliding speed the ATZ law's limiting stress ramps in linearly
/// (module notes "Regularisation"); the lamina force is the law's chord F(v_reg)·v/v_reg.
pub const ATZ_REGULARISATION_SLIDING_M_S: f64 = 1e-6;

/// Which law turns eq. 3's film shear into a lamina force (deck `traction`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum RacewayTractionLaw {
    /// Eq. 3 as the Newtonian branch of the Allen–Townsend–Zaretsky limiting-shear law.
    #[default]
    Atz,
    /// Eq. 3 as printed: Newtonian, Barus, constant (mean) pressure on the slice.
    NewtonianEq3,
}

/// Lubricant properties the raceway traction reads, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FilmRheology {
    /// η₀, dynamic viscosity at the measured temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// α, Barus pressure–viscosity coefficient, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// τ_tr, ATZ transition shear stress, Pa.
    pub transition_shear_stress_pa: f64,
    /// μ_fl, ATZ limiting traction coefficient, dimensionless.
    pub limiting_traction_coefficient: f64,
}

impl FilmRheology {
    /// The shared ATZ model with these constants.
    pub fn atz(&self) -> TractionModel {
        TractionModel::Ehd {
            viscosity_pa_s: self.viscosity_pa_s,
            pressure_viscosity_pa_inv: self.pressure_viscosity_pa_inv,
            transition_shear_stress_pa: self.transition_shear_stress_pa,
            limiting_traction_coefficient: self.limiting_traction_coefficient,
        }
    }
}

/// One lamina contact of a roller with a raceway, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LaminaSlice {
    /// q, normal load of the lamina, N (0 for an unloaded lamina).
    pub load_n: f64,
    /// b, Hertz half-width in the rolling direction, m.
    pub half_width_m: f64,
    /// L, lamina length along the roller axis, m.
    pub length_m: f64,
    /// p₀, peak Hertz pressure, Pa; must equal 2q/(π·b·L) (checked to 1e-6 relative):
    /// the traction integrates the Hertz semi-ellipse of this strip.
    pub peak_pressure_pa: f64,
    /// Mean rolling (entrainment) speed, m/s (reported as the slide/roll ratio).
    pub rolling_speed_m_s: f64,
    /// v_sl, raceway minus roller surface speed along the rolling direction, m/s.
    pub sliding_speed_m_s: f64,
    /// h, EHD film thickness of the lamina, m.
    pub film_m: f64,
    /// y, axial offset of the lamina from the roller's centre plane, m.
    pub axial_offset_m: f64,
}

/// Traction result of one lamina.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LaminaFriction {
    /// Traction on the roller along the rolling direction (sign of v_sl), N.
    pub force_n: f64,
    /// F·v_sl ≥ 0, W.
    pub power_w: f64,
    /// y·F about the contact normal through the roller centre, N·m.
    pub skew_moment_nm: f64,
    /// |F|/q, dimensionless (0 for an unloaded lamina).
    pub traction_coefficient: f64,
    /// v_sl/u_roll (0 when the rolling speed is 0), dimensionless.
    pub slide_roll_ratio: f64,
    /// True when the printed eq. 3 gives μ > [`EQ3_MU_FLAG`] (never set by `"atz"`).
    pub exceeds_newtonian_bound: bool,
}

/// Why a lamina cannot be evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LaminaFrictionError {
    /// An input is negative where it must not be, or not finite.
    #[error("lamina {name} = {value} is not usable: it must be finite and {allowed}")]
    BadInput {
        /// The field.
        name: &'static str,
        /// Its value (SI).
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// The peak pressure does not belong to the strip's load and size.
    #[error(
        "lamina peak_pressure_pa = {given} Pa does not match its Hertz strip: 2q/(π·b·L) = {expected} Pa"
    )]
    InconsistentPressure {
        /// The given peak pressure, Pa.
        given: f64,
        /// 2q/(π·b·L), Pa.
        expected: f64,
    },
}

fn check(name: &'static str, value: f64, allow_negative: bool) -> Result<f64, LaminaFrictionError> {
    if value.is_finite() && (allow_negative || value >= 0.0) {
        Ok(value)
    } else {
        Err(LaminaFrictionError::BadInput {
            name,
            value,
            allowed: if allow_negative {
                "any sign"
            } else {
                "not negative"
            },
        })
    }
}

/// Eq. 3 as printed on one slice, N: F = η·e^{α·p̄}·v/h·A with p̄ = q/A and A = 2b·L.
/// Returns 0 for an unloaded slice or v = 0; h ≤ 0 gives an infinite force (no film).
pub fn eq3_slice_force_n(rheology: &FilmRheology, slice: &LaminaSlice) -> f64 {
    let area = 2.0 * slice.half_width_m * slice.length_m;
    if slice.load_n <= 0.0 || area <= 0.0 || slice.sliding_speed_m_s == 0.0 {
        return 0.0;
    }
    let p_mean = slice.load_n / area;
    rheology.viscosity_pa_s
        * (rheology.pressure_viscosity_pa_inv * p_mean).exp()
        * slice.sliding_speed_m_s
        / slice.film_m
        * area
}

/// Traction, power and skew moment of one lamina under `law`.
///
/// # Errors
/// [`LaminaFrictionError::BadInput`] for non-finite inputs or negative load, half-width,
/// length, film or pressure; [`LaminaFrictionError::InconsistentPressure`] when p₀ is not
/// the Hertz peak of the strip.
pub fn lamina_friction(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    slice: &LaminaSlice,
) -> Result<LaminaFriction, LaminaFrictionError> {
    friction_and_slope(law, rheology, slice, false).map(|(f, _)| f)
}

/// [`lamina_friction`] and the slope ∂F/∂v_sl of its force, N/(m/s), at the same slice
/// (the sliding speed's derivative, everything else held). Eq. 3 as printed is linear in
/// v: the slope is η·e^{α·p̄}·A/h. Under ATZ only the Newtonian pieces of the strip depend
/// on v, linearly (`TractionModel::lamina_traction_and_slope`). The spin balance of the
/// double-row losses uses it for its Newton step.
///
/// # Errors
/// As [`lamina_friction`].
pub fn lamina_friction_and_slope(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    slice: &LaminaSlice,
) -> Result<(LaminaFriction, f64), LaminaFrictionError> {
    friction_and_slope(law, rheology, slice, true)
}

/// [`lamina_friction_and_slope`] with the ATZ law prepared by the caller
/// (`rheology.atz().prepared()`, [`PreparedTraction`]): a caller evaluating many laminae with
/// one rheology saves the law's four logarithms per lamina. The same arithmetic, so the same
/// answer bit for bit; `prepared` must be `rheology.atz().prepared()`.
///
/// # Errors
/// As [`lamina_friction`].
pub fn lamina_friction_and_slope_prepared(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    prepared: &PreparedTraction,
    slice: &LaminaSlice,
    want_slope: bool,
) -> Result<(LaminaFriction, f64), LaminaFrictionError> {
    friction_and_slope_with(law, rheology, Some(prepared), slice, want_slope, None)
}

/// [`lamina_friction_and_slope_prepared`] with the ATZ kink search hinted by what a
/// previous call on the same lamina found (`hint`, updated;
/// `PreparedTraction::lamina_traction_and_slope_hinted`): for a caller that evaluates one
/// lamina at many nearby sliding speeds. The same force to round-off (not bit for bit).
///
/// # Errors
/// As [`lamina_friction`].
pub fn lamina_friction_and_slope_hinted(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    prepared: &PreparedTraction,
    slice: &LaminaSlice,
    want_slope: bool,
    hint: &Cell<KinkHint>,
) -> Result<(LaminaFriction, f64), LaminaFrictionError> {
    friction_and_slope_with(law, rheology, Some(prepared), slice, want_slope, Some(hint))
}

fn friction_and_slope(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    slice: &LaminaSlice,
    want_slope: bool,
) -> Result<(LaminaFriction, f64), LaminaFrictionError> {
    friction_and_slope_with(law, rheology, None, slice, want_slope, None)
}

fn friction_and_slope_with(
    law: RacewayTractionLaw,
    rheology: &FilmRheology,
    prepared: Option<&PreparedTraction>,
    slice: &LaminaSlice,
    want_slope: bool,
    hint: Option<&Cell<KinkHint>>,
) -> Result<(LaminaFriction, f64), LaminaFrictionError> {
    let q = check("load_n", slice.load_n, false)?;
    let b = check("half_width_m", slice.half_width_m, false)?;
    let l = check("length_m", slice.length_m, false)?;
    let p0 = check("peak_pressure_pa", slice.peak_pressure_pa, false)?;
    let u = check("rolling_speed_m_s", slice.rolling_speed_m_s, true)?;
    let v = check("sliding_speed_m_s", slice.sliding_speed_m_s, true)?;
    let h = check("film_m", slice.film_m, false)?;
    let y = check("axial_offset_m", slice.axial_offset_m, true)?;
    let strip = HertzStrip {
        load_n: q,
        half_width_m: b,
        width_m: l,
    };
    let expected = strip.peak_pressure_pa();
    if (p0 - expected).abs() > 1e-6 * expected.max(p0) {
        return Err(LaminaFrictionError::InconsistentPressure {
            given: p0,
            expected,
        });
    }
    // An unloaded lamina, or an inviscid oil: the limiting-shear law caps a viscous
    // stress, and with η = 0 there is none to cap (without this the ATZ branch would read
    // a zero film as "no film, limited stress").
    if expected == 0.0 || rheology.viscosity_pa_s == 0.0 {
        return Ok((LaminaFriction::default(), 0.0));
    }
    if law == RacewayTractionLaw::NewtonianEq3 && h == 0.0 && v != 0.0 {
        // Eq. 3 divides by the film: a sliding lamina without one has no finite force.
        return Err(LaminaFrictionError::BadInput {
            name: "film_m",
            value: h,
            allowed:
                "positive for the printed eq. 3 (traction = \"newtonian-eq3\") at a sliding lamina",
        });
    }
    let atz = || {
        prepared
            .copied()
            .unwrap_or_else(|| rheology.atz().prepared())
    };
    let (force, slope) = match law {
        RacewayTractionLaw::NewtonianEq3 => {
            let unit = LaminaSlice {
                sliding_speed_m_s: 1.0,
                ..*slice
            };
            let slope = if want_slope {
                eq3_slice_force_n(rheology, &unit)
            } else {
                0.0
            };
            (eq3_slice_force_n(rheology, slice), slope)
        }
        RacewayTractionLaw::Atz if v.abs() < ATZ_REGULARISATION_SLIDING_M_S => {
            // The chord of the law below v_reg (module notes "Regularisation"): F is odd in
            // v, F(v) = F(v_reg)·v/v_reg, slope F(v_reg)/v_reg.
            let at = atz()
                .lamina_traction(&strip, ATZ_REGULARISATION_SLIDING_M_S, h)
                .force_n;
            let slope = at / ATZ_REGULARISATION_SLIDING_M_S;
            (slope * v, if want_slope { slope } else { 0.0 })
        }
        RacewayTractionLaw::Atz if want_slope => {
            let (t, slope) = match hint {
                Some(k) => atz().lamina_traction_and_slope_hinted(&strip, v, h, k),
                None => atz().lamina_traction_and_slope(&strip, v, h),
            };
            (t.force_n, slope)
        }
        RacewayTractionLaw::Atz => (atz().lamina_traction(&strip, v, h).force_n, 0.0),
    };
    let mu = force.abs() / q;
    let friction = LaminaFriction {
        force_n: force,
        power_w: force * v,
        skew_moment_nm: y * force,
        traction_coefficient: mu,
        slide_roll_ratio: if u != 0.0 { v / u } else { 0.0 },
        exceeds_newtonian_bound: law == RacewayTractionLaw::NewtonianEq3
            && (mu > EQ3_MU_FLAG || mu.is_nan()),
    };
    Ok((friction, slope))
}

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

    fn slice(q: f64, v: f64) -> LaminaSlice {
        let (b, l) = (1.5e-4, 2.0e-4);
        LaminaSlice {
            load_n: q,
            half_width_m: b,
            length_m: l,
            peak_pressure_pa: 2.0 * q / (std::f64::consts::PI * b * l),
            rolling_speed_m_s: 10.0,
            sliding_speed_m_s: v,
            film_m: 3.0e-7,
            axial_offset_m: 4.0e-3,
        }
    }

    /// Eq. 3 on one slice, by hand: q = 20 N on 2·1.5e-4·2e-4 m² → p̄ = 333.3 MPa,
    /// α·p̄ = 6.667, F = 0.02·e^{6.667}·0.01/3e-7·6e-8 m² = 0.031431 N.
    /// Tolerance 1e-13 against the expression typed out independently; exactly linear in
    /// v (ratio 1e-15); power = F·v, skew = y·F.
    #[test]
    fn eq3_one_slice_by_hand_and_linear() {
        let s = slice(20.0, 0.01);
        let r = lamina_friction(RacewayTractionLaw::NewtonianEq3, &oil(), &s).expect("valid");
        let area = 2.0 * 1.5e-4 * 2.0e-4;
        let want = 0.02 * f64::exp(2.0e-8 * 20.0 / area) * 0.01 / 3.0e-7 * area;
        assert!(
            (r.force_n - want).abs() < 1e-13 * want,
            "{} {want}",
            r.force_n
        );
        assert!((want - 0.031_430_9).abs() < 1e-6, "{want}");
        assert!((r.power_w - want * 0.01).abs() < 1e-15);
        assert!((r.skew_moment_nm - 4.0e-3 * want).abs() < 1e-18);
        for k in [-3.0, 0.5, 7.0] {
            let rk = lamina_friction(
                RacewayTractionLaw::NewtonianEq3,
                &oil(),
                &slice(20.0, 0.01 * k),
            )
            .expect("valid");
            assert!((rk.force_n / (k * r.force_n) - 1.0).abs() < 1e-14);
        }
        assert!(!r.exceeds_newtonian_bound, "μ = {}", r.traction_coefficient);
    }

    /// At a bearing's 1.5 GPa the printed eq. 3 gives μ ≫ 0.2 and is flagged; the ATZ law
    /// on the same slice stays at or below its limit max(τ_tr, μ_fl·p) integrated over the
    /// strip, i.e. μ ≤ μ_fl + τ_tr·2bL/q (independent bound).
    #[test]
    fn eq3_flag_and_atz_bound() {
        let b = 1.5e-4;
        let l = 2.0e-4;
        let q = 1.5e9 * std::f64::consts::PI * b * l / 2.0; // p₀ = 1.5 GPa, q = 70.7 N
        let s = slice(q, 0.5);
        let e = lamina_friction(RacewayTractionLaw::NewtonianEq3, &oil(), &s).expect("valid");
        assert!(
            e.exceeds_newtonian_bound && e.traction_coefficient > 100.0,
            "{e:?}"
        );
        let a = lamina_friction(RacewayTractionLaw::Atz, &oil(), &s).expect("valid");
        assert!(!a.exceeds_newtonian_bound);
        let bound = 0.06 + 5.0e6 * 2.0 * b * l / q;
        assert!(a.traction_coefficient > 0.0 && a.traction_coefficient <= bound + 1e-12);
        // Here the whole strip but its fringe is limited: μ close to μ_fl.
        assert!(
            a.traction_coefficient > 0.5 * 0.06,
            "{}",
            a.traction_coefficient
        );
    }

    /// The ATZ branch at α = 0 and a high limit is Newtonian with a constant viscosity:
    /// F = η·v/h·2bL exactly (the integral of a constant stress over the strip), which is
    /// also eq. 3 at α = 0: the two laws meet where they must.
    #[test]
    fn atz_newtonian_limit_is_eq3() {
        let mut o = oil();
        o.pressure_viscosity_pa_inv = 0.0;
        o.transition_shear_stress_pa = 1e12;
        let s = slice(50.0, 0.2);
        let a = lamina_friction(RacewayTractionLaw::Atz, &o, &s).expect("valid");
        let e = lamina_friction(RacewayTractionLaw::NewtonianEq3, &o, &s).expect("valid");
        let want = 0.02 * 0.2 / 3.0e-7 * 2.0 * 1.5e-4 * 2.0e-4;
        assert!((a.force_n / want - 1.0).abs() < 1e-12, "{}", a.force_n);
        assert!((e.force_n / want - 1.0).abs() < 1e-14);
    }

    /// Zero sliding, zero viscosity or an unloaded lamina: no force, no power, no moment.
    #[test]
    fn zero_limits() {
        for law in [RacewayTractionLaw::Atz, RacewayTractionLaw::NewtonianEq3] {
            let r = lamina_friction(law, &oil(), &slice(20.0, 0.0)).expect("valid");
            assert_eq!((r.force_n, r.power_w, r.skew_moment_nm), (0.0, 0.0, 0.0));
            let r = lamina_friction(law, &oil(), &slice(0.0, 0.3)).expect("valid");
            assert_eq!((r.force_n, r.power_w), (0.0, 0.0));
            let mut dry = oil();
            dry.viscosity_pa_s = 0.0;
            let r = lamina_friction(law, &dry, &slice(20.0, 0.3)).expect("valid");
            assert_eq!(r.power_w, 0.0);
        }
    }

    /// A peak pressure that is not the strip's Hertz peak, or a negative film, is refused
    /// with the field named.
    #[test]
    fn rejects_inconsistent_input() {
        let mut s = slice(20.0, 0.1);
        s.peak_pressure_pa *= 1.01;
        let e = lamina_friction(RacewayTractionLaw::Atz, &oil(), &s).expect_err("inconsistent");
        assert!(e.to_string().contains("peak_pressure_pa"), "{e}");
        let mut s = slice(20.0, 0.1);
        s.film_m = -1.0;
        let e = lamina_friction(RacewayTractionLaw::Atz, &oil(), &s).expect_err("negative");
        assert!(e.to_string().contains("film_m"), "{e}");
    }

    /// Serde names of the deck's `traction` key.
    /// The slope against a central difference of the force, for both laws on a lamina
    /// whose strip is Newtonian (20 N, α·p₀ = 8.5) and mixed (100 N, α·p₀ = 42: limited
    /// centre, Newtonian edges):
    /// step 1e-6 relative, so the difference's truncation (∝ h², the law smooth away from
    /// a kink crossing) and round-off (1e-16/1e-6) sit near 1e-9; tolerance 1e-6 relative.
    /// At v = 0 the slope is the Newtonian limit, checked against a small-v difference.
    #[test]
    fn slope_matches_central_difference() {
        let rh = oil();
        for law in [RacewayTractionLaw::Atz, RacewayTractionLaw::NewtonianEq3] {
            for (q, v) in [
                (20.0, 1e-5),
                (20.0, -1.5),
                (100.0, -3e-4),
                (100.0, 0.01),
                (100.0, 0.2),
            ] {
                let s = slice(q, v);
                let (f, slope) = lamina_friction_and_slope(law, &rh, &s).unwrap();
                assert_eq!(f, lamina_friction(law, &rh, &s).unwrap());
                let d = 1e-6 * v.abs();
                let at = |x: f64| lamina_friction(law, &rh, &slice(q, x)).unwrap().force_n;
                let fd = (at(v + d) - at(v - d)) / (2.0 * d);
                assert!(
                    (slope - fd).abs() <= 1e-6 * fd.abs().max(1e-12),
                    "{law:?} v {v}: slope {slope} vs central difference {fd}"
                );
            }
            let (_, s0) = lamina_friction_and_slope(law, &rh, &slice(20.0, 0.0)).unwrap();
            let tiny = 1e-9;
            let f = lamina_friction(law, &rh, &slice(20.0, tiny))
                .unwrap()
                .force_n;
            assert!(
                (s0 - f / tiny).abs() <= 1e-6 * s0,
                "{law:?}: {s0} vs {}",
                f / tiny
            );
        }
    }

    /// The regularisation (module notes) against the unregularised ATZ law, on laminae
    /// from 0.3 to 2.5 GPa (α·p₀ = 6…50) and films 0.1–1 µm:
    /// * |v| ≥ v_reg: bit-identical to `TractionModel::lamina_traction` (force and slope);
    /// * |v| < v_reg: the stress-level regularisation τ = min(τ_N, τ_lim·|v|/v_reg)
    ///   integrated independently (the ATZ model with τ_tr and μ_fl scaled by |v|/v_reg, at
    ///   the true v, its own kinks and quadrature) to 1e-12 relative — the chord is that
    ///   law, not a fit; the force differs from the unregularised one by at most F(v_reg)
    ///   and the power by at most F(v_reg)·v_reg;
    /// * continuous at ±v_reg (1e-12) and non-decreasing in v across it.
    #[test]
    fn regularised_law_is_the_chord_and_the_law_above_v_reg() {
        let vr = ATZ_REGULARISATION_SLIDING_M_S;
        let rh = oil();
        let (b, l) = (1.5e-4, 2.0e-4);
        let mut checked_low = 0;
        for (i, p0) in [3e8, 9e8, 1.4e9, 2.0e9, 2.5e9].into_iter().enumerate() {
            for h in [1e-7, 3e-7, 1e-6] {
                let q = p0 * std::f64::consts::PI * b * l / 2.0;
                let at = |v: f64| LaminaSlice {
                    load_n: q,
                    film_m: h,
                    sliding_speed_m_s: v,
                    ..slice(q, v)
                };
                let strip = HertzStrip {
                    load_n: q,
                    half_width_m: b,
                    width_m: l,
                };
                for v in [1e-6, -1e-6, 2e-6, -3e-5, 1e-3, 0.4, -2.0] {
                    let (f, sl) =
                        lamina_friction_and_slope(RacewayTractionLaw::Atz, &rh, &at(v)).unwrap();
                    let (t, sl0) = rh.atz().lamina_traction_and_slope(&strip, v, h);
                    assert_eq!((f.force_n, sl), (t.force_n, sl0), "p0 {p0} h {h} v {v}");
                }
                let f_reg = rh.atz().lamina_traction(&strip, vr, h).force_n;
                for k in 0..12 {
                    // Spread over |v| < v_reg, both signs, down to 1e-12 m/s.
                    let v = vr
                        * 10f64.powf(-(k as f64) * 0.5 - 0.013 * i as f64)
                        * if k % 2 == 0 { 1.0 } else { -1.0 };
                    let f = lamina_friction(RacewayTractionLaw::Atz, &rh, &at(v)).unwrap();
                    let s = v.abs() / vr;
                    let scaled = FilmRheology {
                        transition_shear_stress_pa: rh.transition_shear_stress_pa * s,
                        limiting_traction_coefficient: rh.limiting_traction_coefficient * s,
                        ..rh
                    };
                    let want = scaled.atz().lamina_traction(&strip, v, h).force_n;
                    assert!(
                        (f.force_n - want).abs() <= 1e-12 * want.abs(),
                        "p0 {p0} h {h} v {v}: chord {} vs regularised stress {want}",
                        f.force_n
                    );
                    let raw = rh.atz().lamina_traction(&strip, v, h).force_n;
                    assert!((f.force_n - raw).abs() <= f_reg * (1.0 + 1e-12));
                    assert!((f.power_w - raw * v).abs() <= f_reg * vr);
                    checked_low += 1;
                }
                let below = lamina_friction(RacewayTractionLaw::Atz, &rh, &at(vr * (1.0 - 1e-13)))
                    .unwrap()
                    .force_n;
                assert!((below - f_reg).abs() <= 1e-12 * f_reg, "{below} {f_reg}");
                assert!(below <= f_reg * (1.0 + 1e-15));
            }
        }
        assert_eq!(checked_low, 5 * 3 * 12);
        // At 2 GPa the unregularised law is a step: it reaches its limit far below v_reg
        // (the reason for the regularisation), so the chord does change something there.
        let q = 2.0e9 * std::f64::consts::PI * b * l / 2.0;
        let strip = HertzStrip {
            load_n: q,
            half_width_m: b,
            width_m: l,
        };
        let raw = rh.atz().lamina_traction(&strip, 1e-9, 3e-7).force_n;
        let reg = lamina_friction(
            RacewayTractionLaw::Atz,
            &rh,
            &LaminaSlice {
                film_m: 3e-7,
                ..slice(q, 1e-9)
            },
        )
        .unwrap()
        .force_n;
        assert!(raw > 100.0 * reg, "{raw} {reg}");
    }

    #[test]
    fn law_names() {
        let s = serde_json::to_string(&RacewayTractionLaw::NewtonianEq3).expect("ser");
        assert_eq!(s, "\"newtonian-eq3\"");
        let s = serde_json::to_string(&RacewayTractionLaw::Atz).expect("ser");
        assert_eq!(s, "\"atz\"");
    }
}
