//! Hertz point (elliptical) contact between two bodies with principal curvatures in
//! the rolling and transverse directions (seed 001, Chen 1989, Appendix A, eqs.
//! A-1 … A-17), SI units.
//!
//! # Axes
//! The two principal directions are named **`rolling`** (the direction of motion, along
//! which lubricant is entrained) and **`transverse`** (across the raceway groove), never
//! x/y, because the two sources we follow use opposite letters:
//! * Chen (seed 001, App. A and ch. 5) puts **x transverse** (his r_rx = −6.24 mm is the
//!   groove radius, his R_x = 156 mm) and **y in the rolling direction** (r_ry = 51.7 mm,
//!   R_y = 5.376 mm; his Reynolds equation 4-9 runs in y).
//! * Hamrock (Brewe & Hamrock 1977; Hamrock & Dowson 1977) puts **R_x in the rolling
//!   direction** and R_y transverse, so Hamrock's R_y/R_x is Chen's R_x/R_y.
//!
//! # What is computed
//! With curvature sums A (transverse) and B (rolling) (1/m; eq. A-2a, A-2b), Σρ = A + B
//! = 1/R (eq. A-2c) and the reduced modulus E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹:
//! * κ = a/b ≥ 1 (eq. A-14) from eq. A-16,
//!   [(κ²+1)E − 2K]/[(κ²−1)E] = F(ρ) = |A − B|/(A + B),
//!   with K, E the complete elliptic integrals of parameter m = 1 − 1/κ² (eq. A-15).
//!   **Chen's notation: E₁ is K (first kind), E₂ is E (second kind).**
//! * Harris's dimensionless a*, b*, δ* (eq. A-13a–c):
//!   a* = (2κ²E/π)^⅓, b* = (2E/(πκ))^⅓, δ* = (2K/π)·(π/(2κ²E))^⅓.
//! * The semi-axes and approach (eqs. A-8 … A-10), written with Σρ and E*:
//!   a = a*·(3Q/(2ΣρE*))^⅓, b = b*·(3Q/(2ΣρE*))^⅓, δ = δ*·(3Q/(2ΣρE*))^⅔·Σρ/2.
//!   Chen prints the same with E′ = E/(1−ν²) (eq. A-12, identical bodies) and R = 1/Σρ:
//!   a = (3/E′)^⅓·a*·(QR)^⅓ etc.; for dissimilar bodies his E′ generalises to
//!   E′ = 2E* (Hamrock's E′), which is how [`effective_modulus`] defines it.
//! * p₀ = 3Q/(2πab) (eq. A-7) and Q = K_n·δ^{3/2} with
//!   K_n = (E′/3)·2^{3/2}·R^{1/2}/δ*^{3/2} (eq. A-11, the form of eq. 3-2).
//!
//! The major axis a lies along the direction of the *smaller* curvature sum: for a ball
//! in a groove that is the transverse direction (semi-major a across the groove,
//! semi-minor b along rolling). The general case, a major axis along rolling (a wide
//! wheel on a rail), is handled too and reported by [`Axis`].
//!
//! # Methods
//! [`HertzMethod::Exact`] solves eq. A-16 by safeguarded Newton iteration to round-off
//! (κ to ~1e-15 relative) with K and E from the AGM (`elliptic`); the circle
//! (A = B) is exact: κ = a* = b* = δ* = 1. [`HertzMethod::BreweHamrock`] uses the
//! curve fits of eq. A-17 (Brewe & Hamrock 1977), which Chen used for his ch. 5 numbers.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use crate::physics::contact::elliptic::{self, EllipticError};
use std::f64::consts::PI;
use thiserror::Error;

/// Why a pair of surfaces or a load does not form a Hertz point contact.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum PointContactError {
    /// An input is NaN (or an infinite load, modulus or curvature).
    #[error("non-finite input: {0}")]
    NonFinite(&'static str),
    /// A principal curvature sum is zero or negative: the concave body conforms at
    /// least as tightly as the convex one in that direction (conformal or separating
    /// surfaces, or a line contact), so there is no Hertz ellipse.
    #[error(
        "non-positive curvature sum (rolling {rolling_per_m} 1/m, transverse {transverse_per_m} 1/m)"
    )]
    NonPositiveCurvature {
        /// Curvature sum in the rolling direction, 1/m.
        rolling_per_m: f64,
        /// Curvature sum in the transverse direction, 1/m.
        transverse_per_m: f64,
    },
    /// The normal load is negative (a Hertz contact carries no tension), N.
    #[error("negative load {0} N")]
    NegativeLoad(f64),
    /// An input is finite but physically meaningless (zero radius, E ≤ 0, ν outside
    /// (−1, 0.5], groove conformity ≤ ½, curvature ratio beyond 1e100, …).
    #[error("invalid input: {0}")]
    InvalidInput(&'static str),
    /// The elliptic integrals could not be evaluated (not expected for valid input).
    #[error(transparent)]
    Elliptic(#[from] EllipticError),
}

/// A principal direction of the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// The rolling direction (Chen's y, Hamrock's x).
    Rolling,
    /// The transverse direction, across the raceway groove (Chen's x, Hamrock's y).
    Transverse,
}

/// How the ellipticity and elliptic integrals are obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HertzMethod {
    /// Solve eq. A-16 exactly (to round-off) with the AGM elliptic integrals.
    #[default]
    Exact,
    /// Brewe & Hamrock (1977) curve fits, eq. A-17a–c, with α_r the ratio of the
    /// larger to the smaller reduced radius (Hamrock's R_y/R_x, Chen's R_x/R_y):
    /// κ ≈ 1.0339·α_r^0.636, K ≈ 1.5277 + 0.6023·ln α_r, E ≈ 1.0003 + 0.5968/α_r.
    /// Measured against `Exact` over 1 ≤ α_r ≤ 100 (see tests): K within 2.8 %,
    /// E within 1.7 %, κ within 3.4 % up to α_r ≈ 55 but 6.3 % at α_r = 100; in the
    /// ball-bearing range 3 ≤ α_r ≤ 30 all three within 1.5 %. At α_r = 1 it gives
    /// κ = 1.0339, not the exact circle.
    BreweHamrock,
}

/// Principal radii of curvature of one body at the contact point, m: positive convex,
/// negative concave, ±∞ flat.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalRadii {
    /// Radius of curvature in the rolling direction, m.
    pub rolling_m: f64,
    /// Radius of curvature in the transverse direction, m.
    pub transverse_m: f64,
}

/// Principal curvature sums of the two bodies, 1/m (eqs. A-2a, A-2b: 1/R = 1/r₁ + 1/r₂
/// in each direction). Both must be positive for a Hertz ellipse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvatureSum {
    /// Σρ in the rolling direction, 1/m (1/R_x in Hamrock's notation, 1/R_y in Chen's).
    pub rolling_per_m: f64,
    /// Σρ in the transverse direction, 1/m (1/R_y in Hamrock's notation, 1/R_x in
    /// Chen's).
    pub transverse_per_m: f64,
}

/// Curvature 1/r of a radius r (m), 1/m, with ±∞ (flat) giving 0.
fn curvature_of(radius_m: f64) -> Result<f64, PointContactError> {
    if radius_m.is_nan() {
        return Err(PointContactError::NonFinite("radius of curvature"));
    }
    if radius_m == 0.0 {
        return Err(PointContactError::InvalidInput("zero radius of curvature"));
    }
    Ok(1.0 / radius_m)
}

impl CurvatureSum {
    /// Curvature sums from their components, 1/m. Errors unless both are finite and
    /// positive.
    pub fn new(rolling_per_m: f64, transverse_per_m: f64) -> Result<Self, PointContactError> {
        if !(rolling_per_m.is_finite() && transverse_per_m.is_finite()) {
            return Err(PointContactError::NonFinite("curvature sum"));
        }
        if rolling_per_m > 0.0 && transverse_per_m > 0.0 {
            Ok(Self {
                rolling_per_m,
                transverse_per_m,
            })
        } else {
            Err(PointContactError::NonPositiveCurvature {
                rolling_per_m,
                transverse_per_m,
            })
        }
    }

    /// Curvature sums of two bodies from their principal radii (m; concave negative,
    /// ±∞ flat), assuming their principal planes coincide (eqs. A-2a, A-2b).
    pub fn from_radii(
        body1: PrincipalRadii,
        body2: PrincipalRadii,
    ) -> Result<Self, PointContactError> {
        Self::new(
            curvature_of(body1.rolling_m)? + curvature_of(body2.rolling_m)?,
            curvature_of(body1.transverse_m)? + curvature_of(body2.transverse_m)?,
        )
    }

    /// Σρ = A + B, the total curvature sum, 1/m (eq. A-2c: 1/R).
    pub fn total_per_m(&self) -> f64 {
        self.rolling_per_m + self.transverse_per_m
    }

    /// Chen's equivalent radius R = 1/Σρ, m (eq. A-2c).
    pub fn equivalent_radius_m(&self) -> f64 {
        1.0 / self.total_per_m()
    }

    /// Reduced radius in the rolling direction, m (Hamrock's R_x, Chen's R_y): the radius
    /// that makes the EHL groups of `film_point` dimensionless.
    pub fn reduced_radius_rolling_m(&self) -> f64 {
        1.0 / self.rolling_per_m
    }

    /// Reduced radius in the transverse direction, m (Hamrock's R_y, Chen's R_x).
    pub fn reduced_radius_transverse_m(&self) -> f64 {
        1.0 / self.transverse_per_m
    }

    /// F(ρ) = |A − B|/(A + B), the curvature difference of eq. A-16, dimensionless, in
    /// [0, 1).
    pub fn curvature_difference(&self) -> f64 {
        (self.rolling_per_m - self.transverse_per_m).abs() / self.total_per_m()
    }

    /// α_r ≥ 1, the larger curvature sum over the smaller (= larger reduced radius over
    /// the smaller: Hamrock's R_y/R_x for a ball in a groove, Chen's R_x/R_y),
    /// dimensionless. F(ρ) = (α_r − 1)/(α_r + 1).
    pub fn radius_ratio(&self) -> f64 {
        let (small, large) = self.ordered();
        large / small
    }

    /// Direction of the ellipse's major axis: that of the smaller curvature sum. A
    /// circle (equal sums) reports [`Axis::Transverse`].
    pub fn major_axis(&self) -> Axis {
        if self.transverse_per_m <= self.rolling_per_m {
            Axis::Transverse
        } else {
            Axis::Rolling
        }
    }

    /// (smaller, larger) curvature sum, 1/m.
    fn ordered(&self) -> (f64, f64) {
        if self.transverse_per_m <= self.rolling_per_m {
            (self.transverse_per_m, self.rolling_per_m)
        } else {
            (self.rolling_per_m, self.transverse_per_m)
        }
    }
}

/// Which raceway a ball touches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Race {
    /// Inner raceway: convex in the rolling direction.
    Inner,
    /// Outer raceway: concave in the rolling direction.
    Outer,
}

/// Curvature sums (1/m) of a ball of diameter D (m) on a grooved raceway of a bearing of
/// pitch diameter d_m (m) at contact angle α (rad), groove radius f·D (conformity f > ½).
///
/// Ball: radius D/2 in both directions. Raceway, measured in the plane of the contact
/// normal (Harris, *Rolling Bearing Analysis*): rolling radius (d_m − D cos α)/(2 cos α)
/// convex for the inner race, (d_m + D cos α)/(2 cos α) concave for the outer race;
/// transverse radius −f·D (concave groove). The curvature 2 cos α/(d_m ∓ D cos α) is
/// formed directly so that α = 90° (a flat thrust raceway) is exact.
///
/// **Chen's ch. 5 uses (d_m ∓ D cos α)/2 instead** (51.7 mm and 63.3 mm for Bearing A,
/// the raceway radius in the radial plane, without the 1/cos α): at α = 15° that makes
/// his rolling curvature 3.4 % larger for the inner race; see the tests.
pub fn ball_race_curvature(
    race: Race,
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    contact_angle_rad: f64,
    groove_conformity: f64,
) -> Result<CurvatureSum, PointContactError> {
    for (x, name) in [
        (ball_diameter_m, "ball diameter"),
        (pitch_diameter_m, "pitch diameter"),
        (contact_angle_rad, "contact angle"),
        (groove_conformity, "groove conformity"),
    ] {
        if !x.is_finite() {
            return Err(PointContactError::NonFinite(name));
        }
    }
    if ball_diameter_m <= 0.0 || pitch_diameter_m <= ball_diameter_m {
        return Err(PointContactError::InvalidInput(
            "need 0 < ball diameter < pitch diameter",
        ));
    }
    if groove_conformity <= 0.5 {
        return Err(PointContactError::InvalidInput(
            "groove conformity f must exceed 1/2",
        ));
    }
    let cos_a = contact_angle_rad.cos();
    let ball = 2.0 / ball_diameter_m;
    let groove = -1.0 / (groove_conformity * ball_diameter_m);
    let race_rolling = match race {
        Race::Inner => 2.0 * cos_a / (pitch_diameter_m - ball_diameter_m * cos_a),
        Race::Outer => -2.0 * cos_a / (pitch_diameter_m + ball_diameter_m * cos_a),
    };
    CurvatureSum::new(ball + race_rolling, ball + groove)
}

/// Reduced (contact) modulus E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹, Pa, from each body's
/// Young's modulus (Pa) and Poisson's ratio. Errors unless E > 0 and −1 < ν ≤ ½.
pub fn reduced_modulus(
    e1_pa: f64,
    nu1: f64,
    e2_pa: f64,
    nu2: f64,
) -> Result<f64, PointContactError> {
    let mut compliance = 0.0;
    for (e, nu) in [(e1_pa, nu1), (e2_pa, nu2)] {
        if !(e.is_finite() && nu.is_finite()) {
            return Err(PointContactError::NonFinite("elastic constant"));
        }
        if e <= 0.0 {
            return Err(PointContactError::InvalidInput(
                "Young's modulus not positive",
            ));
        }
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(PointContactError::InvalidInput(
                "Poisson's ratio outside (-1, 0.5]",
            ));
        }
        compliance += (1.0 - nu * nu) / e;
    }
    Ok(1.0 / compliance)
}

/// E′ = 2E*, Pa: Hamrock's effective modulus, and Chen's E′ = E/(1−ν²) (eq. A-12) for two
/// bodies of the same material. Same inputs and errors as [`reduced_modulus`].
pub fn effective_modulus(
    e1_pa: f64,
    nu1: f64,
    e2_pa: f64,
    nu2: f64,
) -> Result<f64, PointContactError> {
    reduced_modulus(e1_pa, nu1, e2_pa, nu2).map(|e| 2.0 * e)
}

/// The load-independent shape of the contact ellipse (all dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipseShape {
    /// κ = a/b ≥ 1, ellipticity ratio (eq. A-14).
    pub ellipticity: f64,
    /// K, complete elliptic integral of the first kind of m = 1 − 1/κ² (Chen's E₁,
    /// eq. A-15a), or its Brewe–Hamrock estimate (eq. A-17b).
    pub first_kind: f64,
    /// E, complete elliptic integral of the second kind (Chen's E₂, eq. A-15b), or its
    /// Brewe–Hamrock estimate (eq. A-17c).
    pub second_kind: f64,
    /// a* = (2κ²E/π)^⅓ (eq. A-13a).
    pub a_star: f64,
    /// b* = (2E/(πκ))^⅓ (eq. A-13b).
    pub b_star: f64,
    /// δ* = (2K/π)·(π/(2κ²E))^⅓ (eq. A-13c).
    pub delta_star: f64,
    /// Direction of the major axis a.
    pub major_axis: Axis,
    /// How κ, K and E were obtained.
    pub method: HertzMethod,
}

/// Largest α_r accepted: κ ≈ 5e50 there, far beyond any bearing, and the complementary
/// parameter 1/κ² stays a normal f64.
const MAX_RADIUS_RATIO: f64 = 1e100;

impl EllipseShape {
    /// Solve the shape of the contact ellipse for these curvature sums (eqs. A-13 …
    ///
    pub fn solve(curvature: CurvatureSum, method: HertzMethod) -> Result<Self, PointContactError> {
        Self::solve_from(curvature, method, None)
    }

    /// [`Self::solve`] with the exact method's Newton iteration on ln κ (eq. A-16) started
    /// from `ellipticity_guess` (clamped into the bracket; the Brewe–Hamrock value when it
    /// is not a finite number > 1) instead of the Brewe–Hamrock value. For a sequence of
    /// nearly equal contacts (a load solve's fixed point, where the contact angle moves
    /// by 10⁻³ … 10⁻¹² rad between iterations) the previous κ makes the iteration one or
    /// two steps instead of five or six. The answer is the same root to round-off (the
    /// iteration stops on a step of 4 ulps); the Brewe–Hamrock method ignores the guess.
    pub fn solve_near(
        curvature: CurvatureSum,
        method: HertzMethod,
        ellipticity_guess: f64,
    ) -> Result<Self, PointContactError> {
        Self::solve_from(curvature, method, Some(ellipticity_guess))
    }

    fn solve_from(
        curvature: CurvatureSum,
        method: HertzMethod,
        ellipticity_guess: Option<f64>,
    ) -> Result<Self, PointContactError> {
        // Re-validate: the fields are public and may have been set directly.
        let curvature = CurvatureSum::new(curvature.rolling_per_m, curvature.transverse_per_m)?;
        let alpha_r = curvature.radius_ratio();
        // alpha_r is finite here or infinite on overflow (never NaN: both sums > 0).
        if alpha_r > MAX_RADIUS_RATIO {
            return Err(PointContactError::InvalidInput(
                "curvature ratio above 1e100",
            ));
        }
        let major_axis = curvature.major_axis();
        let (kappa, k, e) = match method {
            HertzMethod::Exact => {
                if alpha_r == 1.0 {
                    // The circle, exactly: κ = 1, K = E = π/2 ⇒ a* = b* = δ* = 1.
                    return Ok(Self {
                        ellipticity: 1.0,
                        first_kind: std::f64::consts::FRAC_PI_2,
                        second_kind: std::f64::consts::FRAC_PI_2,
                        a_star: 1.0,
                        b_star: 1.0,
                        delta_star: 1.0,
                        major_axis,
                        method,
                    });
                }
                let t = solve_log_ellipticity(alpha_r, ellipticity_guess)?;
                let c = elliptic::complete_integrals_with_complement(
                    -(-2.0 * t).exp_m1(),
                    (-2.0 * t).exp(),
                )?;
                (t.exp(), c.first_kind, c.second_kind)
            }
            HertzMethod::BreweHamrock => (
                1.0339 * alpha_r.powf(0.636),   // eq. A-17a
                1.5277 + 0.6023 * alpha_r.ln(), // eq. A-17b
                1.0003 + 0.5968 / alpha_r,      // eq. A-17c
            ),
        };
        let k2e = kappa * kappa * e;
        Ok(Self {
            ellipticity: kappa,
            first_kind: k,
            second_kind: e,
            a_star: (2.0 * k2e / PI).cbrt(),         // eq. A-13a
            b_star: (2.0 * e / (PI * kappa)).cbrt(), // eq. A-13b
            delta_star: 2.0 * k / PI * (PI / (2.0 * k2e)).cbrt(), // eq. A-13c
            major_axis,
            method,
        })
    }
}

/// ln r(κ) and d ln r/d ln κ at t = ln κ > 0, where r(κ) = B/A is the curvature ratio
/// that produces the ellipticity κ (Johnson, *Contact Mechanics*, 1985, §4.2):
/// r = (κ²E − K)/(K − E) = (E − m₁K)/(m₁(K − E)), m₁ = 1/κ² = e^{−2t}. This is eq. A-16
/// rearranged: F(ρ) = (r − 1)/(r + 1). Both differences come cancellation-free from the
/// AGM, so r is accurate to a few ulps even for κ → 1.
fn log_ratio_and_slope(t: f64) -> Result<(f64, f64), PointContactError> {
    let m1 = (-2.0 * t).exp();
    let m = -(-2.0 * t).exp_m1();
    let c = elliptic::complete_integrals_with_complement(m, m1)?;
    let log_r = c.e_minus_m1_k.ln() - m1.ln() - c.k_minus_e.ln();
    // d ln r/dt = m₁K/(E − m₁K) − (3E − 2K)/(K − E), from dK/dm = (E − m₁K)/(2mm₁) and
    // dE/dm = (E − K)/(2m). Its two terms cancel to 3/2 as m → 0, so below m = 1e-4 use
    // the series 3/2 + O(m) instead: Newton only needs the slope roughly.
    let slope = if m < 1e-4 {
        1.5
    } else {
        m1 * c.first_kind / c.e_minus_m1_k
            - (3.0 * c.second_kind - 2.0 * c.first_kind) / c.k_minus_e
    };
    Ok((log_r, slope))
}

/// t = ln κ solving r(κ) = α_r (eq. A-16), α_r > 1, to round-off.
///
/// Bracket: r(κ) < κ² and r(κ) > κ for every κ > 1 (r ≈ 1 + 3m/4 against κ² = 1/(1−m)
/// near the circle, r ≈ κ²/(ln 4κ − 1) for long ellipses), so ln κ ∈ [½ ln α_r, ln α_r].
/// Newton steps that leave the bracket are replaced by bisection. Started from
/// `ellipticity_guess` (κ) when it is a finite number > 1, else from Brewe–Hamrock.
fn solve_log_ellipticity(
    alpha_r: f64,
    ellipticity_guess: Option<f64>,
) -> Result<f64, PointContactError> {
    log_ellipticity_iterations(alpha_r, ellipticity_guess).map(|(t, _)| t)
}

/// [`solve_log_ellipticity`] and the number of evaluations of r(κ) it took.
fn log_ellipticity_iterations(
    alpha_r: f64,
    ellipticity_guess: Option<f64>,
) -> Result<(f64, usize), PointContactError> {
    let target = alpha_r.ln();
    let (mut lo, mut hi) = (0.5 * target, target);
    // The caller's κ, or Brewe–Hamrock (eq. A-17a), as the first guess, clamped into the
    // bracket.
    let start = match ellipticity_guess {
        Some(k) if k.is_finite() && k > 1.0 => k.ln(),
        _ => 1.0339f64.ln() + 0.636 * target,
    };
    let mut t = start.clamp(lo, hi);
    for n in 1..=200 {
        let (log_r, slope) = log_ratio_and_slope(t)?;
        let f = log_r - target;
        if f == 0.0 {
            return Ok((t, n));
        }
        if f < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - f / slope;
        let next = if newton > lo && newton < hi && slope > 0.0 {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - t).abs() <= 4.0 * f64::EPSILON * t || hi - lo <= 2.0 * f64::EPSILON * hi {
            return Ok((next, n));
        }
        t = next;
    }
    // Not reached in practice (the bracket halves at least every other step); the
    // midpoint of the final bracket is then accurate to far below 1e-15 anyway.
    Ok((0.5 * (lo + hi), 200))
}

/// A Hertz point-contact model: geometry, elastic constants and the solved ellipse
/// shape, ready to answer load ↔ approach questions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzPointContact {
    curvature: CurvatureSum,
    reduced_modulus_pa: f64,
    shape: EllipseShape,
    /// (3/(2ΣρE*))^⅓, m/N^⅓: a = a*·scale·Q^⅓.
    size_scale: f64,
    /// δ = approach_coeff·Q^⅔, m/N^⅔.
    approach_coeff: f64,
    /// K_n = approach_coeff^{−3/2}, N/m^{3/2}.
    stiffness: f64,
}

/// The contact under one load (all SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointContact {
    /// Normal load Q, N.
    pub load_n: f64,
    /// Semi-major axis a, m (eq. A-8), along [`PointContact::major_axis`].
    pub semi_major_m: f64,
    /// Semi-minor axis b, m (eq. A-9).
    pub semi_minor_m: f64,
    /// Direction of the major axis (transverse for a ball in a groove).
    pub major_axis: Axis,
    /// p₀ = 3Q/(2πab), maximum (centre) pressure, Pa (eq. A-7); 0 at zero load.
    pub max_pressure_pa: f64,
    /// Q/(πab) = ⅔p₀, mean pressure, Pa; 0 at zero load.
    pub mean_pressure_pa: f64,
    /// δ, elastic approach of the two bodies' remote points, m (eq. A-10).
    pub approach_m: f64,
    /// dQ/dδ = 1.5·K_n·δ^½ at this load, N/m.
    pub contact_stiffness_n_per_m: f64,
}

impl PointContact {
    /// Semi-axis of the ellipse in the rolling direction, m (b for a ball in a groove).
    pub fn semi_axis_rolling_m(&self) -> f64 {
        match self.major_axis {
            Axis::Rolling => self.semi_major_m,
            Axis::Transverse => self.semi_minor_m,
        }
    }

    /// Semi-axis of the ellipse in the transverse direction, m (a for a ball in a
    /// groove).
    pub fn semi_axis_transverse_m(&self) -> f64 {
        match self.major_axis {
            Axis::Rolling => self.semi_minor_m,
            Axis::Transverse => self.semi_major_m,
        }
    }
}

impl HertzPointContact {
    /// Build the model from curvature sums (1/m), the reduced modulus E* (Pa; see
    /// [`reduced_modulus`]) and the method for κ, K and E.
    pub fn new(
        curvature: CurvatureSum,
        reduced_modulus_pa: f64,
        method: HertzMethod,
    ) -> Result<Self, PointContactError> {
        Self::check_modulus(reduced_modulus_pa)?;
        Self::with_shape(
            curvature,
            reduced_modulus_pa,
            EllipseShape::solve(curvature, method)?,
        )
    }

    /// [`Self::new`] with the ellipse's κ iteration started from `ellipticity_guess`
    /// ([`EllipseShape::solve_near`]): the same contact to round-off, faster when the guess
    /// is close (the κ of a nearby contact angle).
    pub fn new_near(
        curvature: CurvatureSum,
        reduced_modulus_pa: f64,
        method: HertzMethod,
        ellipticity_guess: f64,
    ) -> Result<Self, PointContactError> {
        Self::check_modulus(reduced_modulus_pa)?;
        Self::with_shape(
            curvature,
            reduced_modulus_pa,
            EllipseShape::solve_near(curvature, method, ellipticity_guess)?,
        )
    }

    fn check_modulus(reduced_modulus_pa: f64) -> Result<(), PointContactError> {
        if !reduced_modulus_pa.is_finite() {
            return Err(PointContactError::NonFinite("reduced modulus"));
        }
        if reduced_modulus_pa <= 0.0 {
            return Err(PointContactError::InvalidInput(
                "reduced modulus not positive",
            ));
        }
        Ok(())
    }

    fn with_shape(
        curvature: CurvatureSum,
        reduced_modulus_pa: f64,
        shape: EllipseShape,
    ) -> Result<Self, PointContactError> {
        let sum = curvature.total_per_m();
        let cube = 3.0 / (2.0 * sum * reduced_modulus_pa);
        let size_scale = cube.cbrt();
        // eq. A-10: δ = δ*·(3Q/(2ΣρE*))^⅔·Σρ/2.
        let approach_coeff = shape.delta_star * size_scale * size_scale * sum / 2.0;
        // eq. A-11: Q = K_n·δ^{3/2}.
        let stiffness = approach_coeff.powf(-1.5);
        if !(size_scale.is_finite() && stiffness.is_finite() && stiffness > 0.0) {
            return Err(PointContactError::InvalidInput(
                "curvature or modulus outside the f64 range",
            ));
        }
        Ok(Self {
            curvature,
            reduced_modulus_pa,
            shape,
            size_scale,
            approach_coeff,
            stiffness,
        })
    }

    /// Build the model from the two bodies' principal radii (m; concave negative, ±∞
    /// flat), Young's moduli (Pa) and Poisson's ratios.
    #[allow(clippy::too_many_arguments)]
    pub fn from_radii(
        body1: PrincipalRadii,
        body2: PrincipalRadii,
        e1_pa: f64,
        nu1: f64,
        e2_pa: f64,
        nu2: f64,
        method: HertzMethod,
    ) -> Result<Self, PointContactError> {
        let curvature = CurvatureSum::from_radii(body1, body2)?;
        Self::new(curvature, reduced_modulus(e1_pa, nu1, e2_pa, nu2)?, method)
    }

    /// The curvature sums, 1/m.
    pub fn curvature(&self) -> CurvatureSum {
        self.curvature
    }

    /// The reduced modulus E*, Pa.
    pub fn reduced_modulus_pa(&self) -> f64 {
        self.reduced_modulus_pa
    }

    /// The dimensionless ellipse shape (κ, K, E, a*, b*, δ*).
    pub fn shape(&self) -> EllipseShape {
        self.shape
    }

    /// K_n of Q = K_n·δ^{3/2} (eq. A-11), N/m^{3/2}.
    pub fn stiffness_n_per_m1_5(&self) -> f64 {
        self.stiffness
    }

    /// Approach δ (m) under the load Q (N) (eq. A-10). Errors for negative or NaN load.
    pub fn approach_m(&self, load_n: f64) -> Result<f64, PointContactError> {
        check_load(load_n)?;
        Ok(self.approach_coeff * load_n.powf(2.0 / 3.0))
    }

    /// Load Q = K_n·δ^{3/2} (N) at the approach δ (m) (eq. A-11, the inverse of
    /// [`Self::approach_m`]). A negative approach means the bodies are apart: Q = 0.
    /// Errors for NaN or infinite δ.
    pub fn load_n(&self, approach_m: f64) -> Result<f64, PointContactError> {
        check_approach(approach_m)?;
        Ok(self.stiffness * approach_m.max(0.0).powf(1.5))
    }

    /// dQ/dδ = 1.5·K_n·δ^{1/2}, N/m, at the approach δ (m); 0 for δ ≤ 0. Errors for NaN or
    /// infinite δ.
    pub fn load_derivative_n_per_m(&self, approach_m: f64) -> Result<f64, PointContactError> {
        check_approach(approach_m)?;
        Ok(1.5 * self.stiffness * approach_m.max(0.0).sqrt())
    }

    /// The contact under the normal load Q (N): semi-axes, pressures and approach
    /// (eqs. A-7 … A-10). Zero load gives a zero-size contact with zero pressure.
    pub fn solve(&self, load_n: f64) -> Result<PointContact, PointContactError> {
        check_load(load_n)?;
        let q13 = load_n.cbrt();
        let a = self.shape.a_star * self.size_scale * q13; // eq. A-8
        let b = self.shape.b_star * self.size_scale * q13; // eq. A-9
        let approach = self.approach_coeff * load_n.powf(2.0 / 3.0); // eq. A-10
        let (p0, mean) = if load_n > 0.0 {
            let area = PI * a * b;
            (1.5 * load_n / area, load_n / area) // eq. A-7
        } else {
            (0.0, 0.0)
        };
        // Finite inputs far outside any bearing (a modulus of 1e-147 Pa under 1e303 N)
        // overflow here: a typed error, not an infinite contact.
        if !(a.is_finite() && b.is_finite() && approach.is_finite() && p0.is_finite()) {
            return Err(PointContactError::NonFinite(
                "contact size (inputs overflow)",
            ));
        }
        Ok(PointContact {
            load_n,
            semi_major_m: a,
            semi_minor_m: b,
            major_axis: self.shape.major_axis,
            max_pressure_pa: p0,
            mean_pressure_pa: mean,
            approach_m: approach,
            contact_stiffness_n_per_m: 1.5 * self.stiffness * approach.sqrt(),
        })
    }
}

fn check_load(load_n: f64) -> Result<(), PointContactError> {
    if !load_n.is_finite() {
        Err(PointContactError::NonFinite("load"))
    } else if load_n < 0.0 {
        Err(PointContactError::NegativeLoad(load_n))
    } else {
        Ok(())
    }
}

fn check_approach(approach_m: f64) -> Result<(), PointContactError> {
    if approach_m.is_finite() {
        Ok(())
    } else {
        Err(PointContactError::NonFinite("approach"))
    }
}

#[cfg(test)]
#[path = "point_tests.rs"]
mod tests;
