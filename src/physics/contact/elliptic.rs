//! Complete elliptic integrals of the first and second kind, K(m) and E(m), by the
//! arithmetic–geometric mean (AGM), to machine precision.
//!
//! Parameter convention: `m = k²` (the *parameter*, not the modulus k), so
//!
//! K(m) = ∫₀^{π/2} dθ / √(1 − m·sin²θ),  E(m) = ∫₀^{π/2} √(1 − m·sin²θ) dθ.
//!
//! For a Hertz contact ellipse of semi-axes a ≥ b, m = 1 − b²/a² = 1 − 1/κ² (seed 001,
//! eqs. A-15a and A-15b, where Chen writes **E₁ for K** and **E₂ for E**).
//!
//! Method (Abramowitz & Stegun, *Handbook of Mathematical Functions*, §17.6): start with
//! a₀ = 1, b₀ = √(1 − m), c₀ = √m and iterate aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙbₙ),
//! cₙ₊₁ = (aₙ − bₙ)/2 until cₙ vanishes; then K = π/(2a_N) and
//! E = K·(1 − S) with S = ½c₀² + Σₙ≥₁ 2ⁿ⁻¹cₙ². Here cₙ₊₁ is formed as cₙ²/(4aₙ₊₁)
//! (identical algebraically, since aₙ² − bₙ² = cₙ²) so it never suffers cancellation,
//! and the differences K − E = K·S and E − (1−m)K = K·(m − S) are returned directly,
//! because the Hertz ellipticity equation (eq. A-16) is a ratio of exactly those two
//! small quantities when the contact is nearly circular.
//!
//! Callers that know the complementary parameter m₁ = 1 − m more accurately than m (an
//! elongated ellipse, m₁ = 1/κ²) use [`complete_integrals_with_complement`].

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use thiserror::Error;

/// Why a complete elliptic integral cannot be evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum EllipticError {
    /// The parameter m is NaN, or m > 1 (the integrals are complex there), or the
    /// complementary parameter m₁ = 1 − m is negative or NaN.
    #[error("elliptic parameter out of domain: m = {m}, m1 = {m1} (need m ≤ 1, m1 = 1 − m ≥ 0)")]
    OutOfDomain {
        /// The parameter m = k² as given.
        m: f64,
        /// The complementary parameter m₁ = 1 − m as given or formed.
        m1: f64,
    },
}

/// K(m), E(m) and two cancellation-free combinations of them (all dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompleteEllipticIntegrals {
    /// K(m), complete elliptic integral of the first kind (Chen's E₁, eq. A-15a).
    /// `f64::INFINITY` at m = 1.
    pub first_kind: f64,
    /// E(m), complete elliptic integral of the second kind (Chen's E₂, eq. A-15b).
    pub second_kind: f64,
    /// K(m) − E(m), formed without subtracting the two (≈ πm/4 for small m).
    pub k_minus_e: f64,
    /// E(m) − (1 − m)·K(m), formed without subtracting the two (≈ πm/4 for small m).
    pub e_minus_m1_k: f64,
}

/// K(m) and E(m) for a parameter m ≤ 1 (m = k²; negative m is allowed).
///
/// At m = 1, K = +∞ and E = 1. Errors for NaN or m > 1.
pub fn complete_integrals(m: f64) -> Result<CompleteEllipticIntegrals, EllipticError> {
    complete_integrals_with_complement(m, 1.0 - m)
}

/// K(m), complete elliptic integral of the first kind, m = k² ≤ 1.
pub fn first_kind(m: f64) -> Result<f64, EllipticError> {
    complete_integrals(m).map(|c| c.first_kind)
}

/// E(m), complete elliptic integral of the second kind, m = k² ≤ 1.
pub fn second_kind(m: f64) -> Result<f64, EllipticError> {
    complete_integrals(m).map(|c| c.second_kind)
}

/// K and E from the parameter m and its complement m₁ = 1 − m given separately, so
/// that each is accurate where it is small (m₁ = 1/κ² for a long ellipse, m = −expm1(−2t)
/// for a nearly round one). The caller guarantees m + m₁ = 1 up to rounding; only
/// m₁ enters b₀ = √m₁ and only m enters c₀² = m.
///
/// Errors for NaN, m > 1 or m₁ < 0.
pub fn complete_integrals_with_complement(
    m: f64,
    m1: f64,
) -> Result<CompleteEllipticIntegrals, EllipticError> {
    if m.is_nan() || m1.is_nan() || m.is_infinite() || m > 1.0 || m1 < 0.0 {
        return Err(EllipticError::OutOfDomain { m, m1 });
    }
    if m1 == 0.0 {
        // Logarithmic singularity of K at m = 1; E(1) = 1 exactly.
        return Ok(CompleteEllipticIntegrals {
            first_kind: f64::INFINITY,
            second_kind: 1.0,
            k_minus_e: f64::INFINITY,
            e_minus_m1_k: 1.0,
        });
    }
    let mut a = 1.0_f64;
    let mut b = m1.sqrt();
    // c₀² = m enters S as ½m (m may be negative: the AGM identities still hold).
    let half_m = 0.5 * m;
    // Σₙ≥₁ 2ⁿ⁻¹cₙ², kept apart from ½m so that m − S = ½m − tail stays accurate.
    let mut tail = 0.0_f64;
    // Weight 2ⁿ⁻¹ of the term cₙ² being added.
    let mut weight = 1.0_f64;
    // c₁ = (a₀ − b₀)/2 = m/(2(1 + √m₁)), without cancellation.
    let mut c = m / (2.0 * (1.0 + b));
    for _ in 0..64 {
        tail += weight * c * c;
        let a_next = 0.5 * (a + b);
        let b_next = (a * b).sqrt();
        a = a_next;
        b = b_next;
        // cₙ = (aₙ₋₁ − bₙ₋₁)/2 negligible ⇒ aₙ is the AGM to round-off and every later
        // term 2ⁿcₙ₊₁² ~ 2ⁿcₙ⁴/(16a²) is far below round-off of S (quadratic convergence).
        if c.abs() <= 1e-17 * a {
            break;
        }
        // cₙ₊₁ = cₙ²/(4aₙ₊₁) with aₙ₊₁ = (aₙ + bₙ)/2: cancellation-free (aₙ − bₙ)/2.
        c = c * c / (2.0 * (a + b));
        weight *= 2.0;
    }
    let k = std::f64::consts::PI / (2.0 * a);
    let s = half_m + tail;
    let k_minus_e = k * s;
    let e_minus_m1_k = k * (half_m - tail);
    Ok(CompleteEllipticIntegrals {
        first_kind: k,
        second_kind: k - k_minus_e,
        k_minus_e,
        e_minus_m1_k,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    /// Relative difference |x/y − 1|.
    fn rel(x: f64, y: f64) -> f64 {
        (x / y - 1.0).abs()
    }

    #[test]
    fn circle_value_is_half_pi() {
        // K(0) = E(0) = π/2 exactly (A&S 17.3.11–12); the AGM stops at once. 1e-16 rel.
        let c = complete_integrals(0.0).unwrap();
        assert!(rel(c.first_kind, FRAC_PI_2) < 1e-16, "{c:?}");
        assert!(rel(c.second_kind, FRAC_PI_2) < 1e-16, "{c:?}");
        assert_eq!(c.k_minus_e, 0.0);
        assert_eq!(c.e_minus_m1_k, 0.0);
    }

    #[test]
    fn tabulated_values() {
        // Reference values from mpmath 1.3 (ellipk, ellipe) at 30 significant digits,
        // evaluated at the f64 nearest each decimal m (for m = 0.999999 that matters:
        // its m₁ is 1.0000000000287557e-6, which moves K by 1.4e-11). K(0.5), E(0.5)
        // are also the brief's values (A&S Table 17.1). Tolerance 2e-15 relative (a few
        // ulps: the AGM is exact up to round-off).
        let table = [
            (0.1, 1.612_441_348_720_219_4, 1.530_757_636_897_763_2),
            (0.5, 1.854_074_677_301_372, 1.350_643_881_047_675_5),
            (0.9, 2.578_092_113_348_173_3, 1.104_774_732_704_073_3),
            (0.99, 3.695_637_362_989_874, 1.015_993_545_025_224),
            (0.999_999, 8.294_051_463_601_062, 1.000_003_897_026_172_2),
            (1e-10, 1.570_796_326_834_166_5, 1.570_796_326_755_626_7),
        ];
        for (m, k_ref, e_ref) in table {
            let c = complete_integrals(m).unwrap();
            assert!(
                rel(c.first_kind, k_ref) < 2e-15,
                "K({m}) = {}",
                c.first_kind
            );
            assert!(
                rel(c.second_kind, e_ref) < 2e-15,
                "E({m}) = {}",
                c.second_kind
            );
            assert_eq!(first_kind(m).unwrap(), c.first_kind);
            assert_eq!(second_kind(m).unwrap(), c.second_kind);
        }
    }

    #[test]
    fn near_one_logarithmic_behaviour() {
        // As m → 1, K(m) = ln(4/√m₁) + O(m₁ ln m₁) and E(m) = 1 + O(m₁ ln m₁)
        // (A&S 17.3.26, 17.3.36). With m₁ = 1e-12 the remainder is ≈ 1e-11 ·ln: test
        // to 1e-9 absolute. Passing m₁ directly keeps it exact (1 − 1e-12 would round).
        let m1 = 1e-12;
        let c = complete_integrals_with_complement(1.0 - m1, m1).unwrap();
        let k_asym = (4.0 / m1.sqrt()).ln();
        assert!((c.first_kind - k_asym).abs() < 1e-9, "K = {}", c.first_kind);
        assert!((c.second_kind - 1.0).abs() < 1e-9, "E = {}", c.second_kind);
        // K grows without bound, E decreases to 1: strict monotonicity towards m = 1.
        let mut last = complete_integrals(0.9).unwrap();
        for m1 in [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-14, 1e-200] {
            let c = complete_integrals_with_complement(1.0 - m1, m1).unwrap();
            assert!(c.first_kind > last.first_kind && c.second_kind < last.second_kind);
            assert!(c.first_kind.is_finite() && c.second_kind >= 1.0);
            last = c;
        }
        // m = 1 itself: K = ∞, E = 1 (A&S 17.3.13 limit).
        let one = complete_integrals(1.0).unwrap();
        assert!(one.first_kind.is_infinite() && one.second_kind == 1.0);
    }

    #[test]
    fn legendre_relation() {
        // Legendre: E(m)K(m₁) + E(m₁)K(m) − K(m)K(m₁) = π/2 (A&S 17.3.13), 1e-13 absolute
        // (the terms are up to K² ≈ 50 near the ends, so this checks ~15 digits).
        for i in 1..200 {
            let m = i as f64 / 200.0;
            let c = complete_integrals(m).unwrap();
            let d = complete_integrals(1.0 - m).unwrap();
            let lhs = c.second_kind * d.first_kind + d.second_kind * c.first_kind
                - c.first_kind * d.first_kind;
            assert!((lhs - FRAC_PI_2).abs() < 1e-13, "m = {m}: {lhs}");
        }
        for m in [1e-6, 1e-3, 0.999, 0.999_999] {
            let c = complete_integrals(m).unwrap();
            let d = complete_integrals(1.0 - m).unwrap();
            let lhs = c.second_kind * d.first_kind + d.second_kind * c.first_kind
                - c.first_kind * d.first_kind;
            assert!((lhs - FRAC_PI_2).abs() < 1e-13, "m = {m}: {lhs}");
        }
    }

    #[test]
    fn differences_are_cancellation_free() {
        // Small-m series (A&S 17.3.11–12): K − E = (π/2)(m/2 + 3m²/16 + …) and
        // E − (1−m)K = (π/2)(m/2 + m²/16 + …). At m = 1e-9 the next terms are 1e-18
        // relative, so the series is exact to round-off: test 1e-14 relative (a naive
        // K − E would lose 9 digits here and fail).
        let m: f64 = 1e-9;
        let c = complete_integrals(m).unwrap();
        let kme = FRAC_PI_2 * (m / 2.0 + 3.0 * m * m / 16.0);
        let emk = FRAC_PI_2 * (m / 2.0 + m * m / 16.0);
        assert!(rel(c.k_minus_e, kme) < 1e-14, "{}", c.k_minus_e);
        assert!(rel(c.e_minus_m1_k, emk) < 1e-14, "{}", c.e_minus_m1_k);
        // Mid-range: they agree with the plain differences to round-off (1e-14 abs).
        let c = complete_integrals(0.7).unwrap();
        assert!((c.k_minus_e - (c.first_kind - c.second_kind)).abs() < 1e-14);
        assert!((c.e_minus_m1_k - (c.second_kind - 0.3 * c.first_kind)).abs() < 1e-14);
    }

    #[test]
    fn negative_parameter_is_allowed() {
        // Imaginary-modulus transformation (A&S 17.4.17–18) with m = −1:
        // K(−1) = K(1/2)/√2, E(−1) = √2·E(1/2). 2e-15 relative.
        let c = complete_integrals(-1.0).unwrap();
        let h = complete_integrals(0.5).unwrap();
        assert!(rel(c.first_kind, h.first_kind / 2f64.sqrt()) < 2e-15);
        assert!(rel(c.second_kind, h.second_kind * 2f64.sqrt()) < 2e-15);
        // Circumference of an ellipse, 4aE(1 − b²/a²): a = b = 1 gives 2π. 1e-15 rel.
        assert!(rel(4.0 * second_kind(0.0).unwrap(), 2.0 * PI) < 1e-15);
    }

    #[test]
    fn out_of_domain_is_an_error_not_a_panic() {
        for m in [1.5, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert!(matches!(
                complete_integrals(m),
                Err(EllipticError::OutOfDomain { .. })
            ));
        }
        assert!(complete_integrals_with_complement(0.5, -0.5).is_err());
        assert!(complete_integrals_with_complement(0.5, f64::NAN).is_err());
    }
}
