//! Greenwood–Tripp asperity contact of two rough surfaces (seed 003 eqs. 35–38), SI:
//! the statistical functions F_n(λ) of a Gaussian asperity height distribution, the
//! load carried by the asperities and their real contact area.
//!
//! # The statistical functions, exactly
//!
//! F_n(λ) = (2π)^(−½) ∫_λ^∞ (s − λ)^n e^(−s²/2) ds (Greenwood & Tripp 1970). The seed
//! prints fifth-degree polynomials for F_5/2 (eq. 36) and F_2 (eq. 38), cut to 0 past
//! λ = 3; they are fits on about [0, 1.5] and misbehave beyond (F_2's polynomial turns
//! negative at λ = 1.90, issue 25 Model item 4), so they are kept only as
//! [`f_5_2_polynomial`] and [`f_2_polynomial`], for a test.
//!
//! - **F_2** in closed form. With Q(λ) = ½ erfc(λ/√2) the Gaussian upper tail and
//!   φ(λ) = e^(−λ²/2)/√(2π), integrating by parts gives the recurrence
//!   F_(n+1) = n F_(n−1) − λ F_n (n ≥ 1), F_0 = Q, F_1 = φ − λQ, hence
//!   F_2 = (1 + λ²) Q − λ φ. For large λ the two terms cancel (F_2 ≈ 2φ/λ³; measured
//!   2.8e-10 relative at λ = 11.7), so past λ = [`CLOSED_FORM_MAX`] = 3 (cancellation
//!   below 70×, error < 1e-14) F_2 is taken from the quadrature below instead.
//! - **F_5/2** has no elementary closed form (it is Γ(7/2) e^(−λ²/4) D_(−7/2)(λ)/√(2π),
//!   a parabolic-cylinder function). With s = λ + u² the integrand loses its √ branch
//!   point: F_n(λ) = (2π)^(−½) ∫_0^∞ 2u^(2n+1) e^(−(λ+u²)²/2) du, an entire integrand
//!   that decays like e^(−u⁴/2). It is cut where the exponent has fallen by
//!   [`CUT_EXPONENT`] below its largest value (the tail beyond is below e^(−60) of the
//!   peak) and integrated by one [`NODES`]-point Gauss–Legendre rule. Error: below 1e-12
//!   relative for λ ∈ [−3, 12] against a 12 × 64-point composite rule (tested), and
//!   F_5/2(0) = 2^(3/4) Γ(7/4)/√(2π) to 1e-13. Cost: one exp per node (~1 µs).
//!
//! # F_5/2 fast
//!
//! Every friction model calls F_5/2 once per contact per evaluation (the tapered roller's
//! friction by mechanism: 800 slices, 1 µs each, a quarter of its pipeline: issue 28's
//! speed budget). ln F_5/2 is analytic (F_5/2 is an entire, positive function) and close
//! to −λ²/2 − (7/2) ln λ for large λ, so [`f_5_2`] interpolates g = ln F_5/2 + λ²/2
//! (of order 10, where ln F_5/2 reaches −650 and its rounding alone would cost 1e-13) by
//! Chebyshev series of degree 14 on pieces 0.5 wide over λ ∈ [−3, 36] (past 36, F_5/2 < 1e-283 and the
//! quadrature is used as before), each piece built from 15 quadratures on its first use.
//! Error against the quadrature: below 2e-13 relative (tested on 7 800 points), i.e. the
//! quadrature's own accuracy; cost ≈ 30 ns (one exp).
//!
//! # Asperity load and area, and the modulus (trap 4)
//!
//! W_a = (16√2/15) π (ξβσ)² √(σ/β) E′ A F_5/2(λ) (eq. 35) and
//! A_a = π² (ξβσ)² A F_2(λ) (eq. 37), with ξβσ the roughness parameter, σ/β the
//! asperity slope measure and A the apparent (Hertz) contact area. The seed prints
//! E′ = ½E_r where E_r is its reduced modulus of the elasticity integral (eq. 9), which
//! in this group's papers is E_r = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] = 2E*. So E′ = E*, the
//! composite modulus of Greenwood–Tripp's own paper, which carries the 16√2π/15
//! prefactor. The functions here take E* (`line::reduced_modulus`); passing the EHL
//! modulus 2E* (`line::effective_modulus`, the seed's E_r) would double W_a (tested).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::sync::OnceLock;

/// 1/√(2π).
const INV_SQRT_2PI: f64 = 0.398_942_280_401_432_7;

/// Gauss–Legendre nodes of the F_n quadrature.
pub const NODES: usize = 40;

/// The quadrature stops where the exponent (λ + u²)²/2 exceeds its smallest value by
/// this much: the neglected tail is below e^(−60) ≈ 1e-26 of the integrand's scale
/// (times a power of u that cannot make up 20 decades).
pub const CUT_EXPONENT: f64 = 60.0;

/// Past this λ, e^(−λ²/2) < 1e-347 underflows and every F_n is 0 in f64 (and λ² would
/// overflow for huge λ, turning 0·∞ into NaN).
const UNDERFLOW_LAMBDA: f64 = 40.0;

/// F_2 by its closed form up to this λ, by quadrature beyond (module note).
pub const CLOSED_FORM_MAX: f64 = 3.0;

/// Gaussian upper tail Q(λ) = ½ erfc(λ/√2), dimensionless.
fn upper_tail(lambda: f64) -> f64 {
    0.5 * libm::erfc(lambda * FRAC_1_SQRT_2)
}

/// Standard normal density φ(λ) = e^(−λ²/2)/√(2π), dimensionless.
fn density(lambda: f64) -> f64 {
    INV_SQRT_2PI * (-0.5 * lambda * lambda).exp()
}

/// F_2(λ) = (1 + λ²) Q(λ) − λ φ(λ) for λ ≤ 3, the quadrature beyond (module note),
/// dimensionless, within 1e-13 relative; λ is the Stribeck film ratio h/σ. Never
/// negative; NaN in gives NaN out.
pub fn f_2(lambda: f64) -> f64 {
    if lambda.is_nan() {
        return f64::NAN;
    }
    if lambda > CLOSED_FORM_MAX {
        return f_n_quadrature(2.0, lambda);
    }
    ((1.0 + lambda * lambda) * upper_tail(lambda) - lambda * density(lambda)).max(0.0)
}

/// Nodes on [0, 1] and weights of the Gauss–Legendre rule (Newton on P_n from the
/// Tricomi start; converged to 1e-15), computed once.
fn rule() -> &'static [(f64, f64); NODES] {
    static RULE: OnceLock<[(f64, f64); NODES]> = OnceLock::new();
    RULE.get_or_init(gauss_legendre_unit::<NODES>)
}

/// The n-point Gauss–Legendre rule mapped to [0, 1]: (node, weight) pairs.
fn gauss_legendre_unit<const N: usize>() -> [(f64, f64); N] {
    let mut out = [(0.0, 0.0); N];
    let n = N as f64;
    for (i, slot) in out.iter_mut().enumerate() {
        let mut x = (PI * (i as f64 + 0.75) / (n + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=N {
                let jf = j as f64;
                let p2 = ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        *slot = (0.5 * (1.0 + x), 0.5 * w);
    }
    out
}

/// The upper limit u_max of the substituted integral ∫_0^∞ 2u^(2n+1) e^(−(λ+u²)²/2) du:
/// where (λ + u²)²/2 exceeds its minimum over u ≥ 0 by [`CUT_EXPONENT`].
fn upper_limit(lambda: f64) -> f64 {
    // Minimum of (λ+u²)²/2 over u ≥ 0: λ²/2 at u = 0 for λ ≥ 0, 0 at u² = −λ for λ < 0.
    let reach = if lambda >= 0.0 {
        (lambda * lambda + 2.0 * CUT_EXPONENT).sqrt()
    } else {
        (2.0 * CUT_EXPONENT).sqrt()
    };
    (reach - lambda).max(0.0).sqrt()
}

/// F_n(λ) for any real n > −1 by the substituted Gauss–Legendre quadrature of the module
/// note, dimensionless. Used for F_5/2 (and, in tests, for F_2 against its closed form).
pub fn f_n_quadrature(n: f64, lambda: f64) -> f64 {
    if lambda.is_nan() || n.is_nan() {
        return f64::NAN;
    }
    if lambda > UNDERFLOW_LAMBDA {
        return 0.0;
    }
    let u_max = upper_limit(lambda);
    // Factor e^(−λ²/2) out for λ ≥ 0 so that the sum is of order one and underflows
    // only with the whole result: (λ+u²)²/2 = λ²/2 + λu² + u⁴/2.
    let (outside, shift) = if lambda >= 0.0 {
        (-0.5 * lambda * lambda, true)
    } else {
        (0.0, false)
    };
    let power = 2.0 * n + 1.0;
    let mut sum = 0.0;
    for &(v, w) in rule() {
        let u = u_max * v;
        let u2 = u * u;
        let exponent = if shift {
            -(lambda * u2 + 0.5 * u2 * u2)
        } else {
            -0.5 * (lambda + u2) * (lambda + u2)
        };
        let up = if n == 2.5 {
            u2 * u2 * u2
        } else {
            u.powf(power)
        };
        sum += w * up * exponent.exp();
    }
    (2.0 * INV_SQRT_2PI * u_max * sum * outside.exp()).max(0.0)
}

/// F_5/2(λ), dimensionless: the quadrature [`f_n_quadrature`] tabulated (module note
/// "F_5/2 fast"), within 2e-13 relative of it for λ ∈ [−3, 36]; the quadrature itself
/// outside that range.
pub fn f_5_2(lambda: f64) -> f64 {
    if !(TABLE_MIN..TABLE_MAX).contains(&lambda) {
        return f_n_quadrature(2.5, lambda);
    }
    let x = (lambda - TABLE_MIN) / TABLE_WIDTH;
    // `x` lies in [0, PIECES) here; the `min` guards the last piece against round-off.
    let piece = (x as usize).min(TABLE_PIECES - 1);
    let c = table_piece(piece);
    // Clenshaw's recurrence for Σ' c_j T_j(t), t ∈ [−1, 1] across the piece.
    let t = 2.0 * (x - piece as f64) - 1.0;
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cj in c[1..].iter().rev() {
        let b0 = 2.0 * t * b1 - b2 + cj;
        b2 = b1;
        b1 = b0;
    }
    // g = ln F + λ²/2; e^(−λ²/2) factored as the quadrature factors it.
    (t * b1 - b2 + 0.5 * c[0]).exp() * (-0.5 * lambda * lambda).exp()
}

/// The tabulated range of [`f_5_2`] and its pieces (module note "F_5/2 fast").
const TABLE_MIN: f64 = -3.0;
const TABLE_MAX: f64 = 36.0;
const TABLE_WIDTH: f64 = 0.5;
const TABLE_PIECES: usize = 78;
/// Chebyshev degree of ln F_5/2 + λ²/2 on each piece.
const TABLE_DEGREE: usize = 14;

/// The Chebyshev coefficients of g = ln F_5/2 + λ²/2 on piece `k` (λ ∈ [TABLE_MIN + k·w, … + w]),
/// computed from the quadrature on first use of that piece (17 quadratures, ≈ 15 µs)
/// and kept for the process.
fn table_piece(k: usize) -> &'static [f64; TABLE_DEGREE + 1] {
    static TABLE: [OnceLock<[f64; TABLE_DEGREE + 1]>; TABLE_PIECES] =
        [const { OnceLock::new() }; TABLE_PIECES];
    TABLE[k].get_or_init(|| {
        const N: usize = TABLE_DEGREE + 1;
        let a = TABLE_MIN + k as f64 * TABLE_WIDTH;
        let mut values = [0.0; N];
        for (i, v) in values.iter_mut().enumerate() {
            let t = (PI * (i as f64 + 0.5) / N as f64).cos();
            let l = a + 0.5 * TABLE_WIDTH * (t + 1.0);
            *v = f_n_quadrature(2.5, l).ln() + 0.5 * l * l;
        }
        let mut c = [0.0; N];
        for (j, cj) in c.iter_mut().enumerate() {
            *cj = 2.0 / N as f64
                * values
                    .iter()
                    .enumerate()
                    .map(|(i, v)| v * (PI * j as f64 * (i as f64 + 0.5) / N as f64).cos())
                    .sum::<f64>();
        }
        c
    })
}

/// The seed's polynomial fit of F_5/2 (eq. 36), 0 for λ > 3. Kept for comparison only.
pub fn f_5_2_polynomial(lambda: f64) -> f64 {
    if lambda > 3.0 {
        return 0.0;
    }
    let l = lambda;
    ((((-0.004 * l + 0.057) * l - 0.296) * l + 0.784) * l - 1.078) * l + 0.617
}

/// The seed's polynomial fit of F_2 (eq. 38), 0 for λ > 3. Kept for comparison only.
pub fn f_2_polynomial(lambda: f64) -> f64 {
    if lambda > 3.0 {
        return 0.0;
    }
    let l = lambda;
    ((((-0.002 * l + 0.028) * l - 0.173) * l + 0.526) * l - 0.804) * l + 0.5
}

/// Topography of the two rough surfaces as Greenwood–Tripp reads it (seed 003 Table 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roughness {
    /// σ, composite RMS roughness √(σ₁² + σ₂²), m.
    pub composite_rms_m: f64,
    /// ξβσ, the roughness parameter (asperity density × summit radius × σ),
    /// dimensionless; 0.03–0.07 for steel (seed: 0.055).
    pub roughness_parameter: f64,
    /// σ/β, the asperity slope measure (σ over the summit radius), dimensionless;
    /// 1e-4–1e-2 (seed: 1e-3, its exponent lost in the print).
    pub asperity_slope: f64,
}

impl Roughness {
    /// The asperity load W_a of eq. 35, N: (16√2/15) π (ξβσ)² √(σ/β) E* A F_5/2(λ),
    /// with `reduced_modulus_pa` E* = [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]⁻¹ (the seed's E′ = ½E_r,
    /// module note), `area_m2` A the apparent contact area and `lambda` λ = h/σ.
    pub fn asperity_load_n(&self, reduced_modulus_pa: f64, area_m2: f64, lambda: f64) -> f64 {
        self.load_factor_pa(reduced_modulus_pa) * area_m2 * f_5_2(lambda)
    }

    /// (16√2/15) π (ξβσ)² √(σ/β) E*, Pa: W_a per unit area per unit F_5/2.
    pub fn load_factor_pa(&self, reduced_modulus_pa: f64) -> f64 {
        let k = self.roughness_parameter;
        16.0 * std::f64::consts::SQRT_2 / 15.0
            * PI
            * k
            * k
            * self.asperity_slope.sqrt()
            * reduced_modulus_pa
    }

    /// The asperity contact area A_a of eq. 37, m²: π² (ξβσ)² A F_2(λ), with `area_m2`
    /// A the apparent contact area and `lambda` λ = h/σ.
    pub fn asperity_area_m2(&self, area_m2: f64, lambda: f64) -> f64 {
        self.area_factor() * area_m2 * f_2(lambda)
    }

    /// π² (ξβσ)², dimensionless: A_a per unit apparent area per unit F_2.
    pub fn area_factor(&self) -> f64 {
        PI * PI * self.roughness_parameter * self.roughness_parameter
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Reference F_n: a 12-panel × 64-point composite Gauss–Legendre rule over the same
    /// substituted integrand, to a wider cut (exponent 90): independent of the node count
    /// and of the cut of the production rule.
    fn reference(n: f64, lambda: f64) -> f64 {
        let gl = gauss_legendre_unit::<64>();
        let reach = if lambda >= 0.0 {
            (lambda * lambda + 180.0).sqrt()
        } else {
            180.0_f64.sqrt()
        };
        let u_max = (reach - lambda).sqrt();
        let panels = 12;
        let mut sum = 0.0;
        for k in 0..panels {
            let a = u_max * k as f64 / panels as f64;
            let h = u_max / panels as f64;
            for &(v, w) in &gl {
                let u = a + h * v;
                let e = if lambda >= 0.0 {
                    -(lambda * u * u + 0.5 * u.powi(4))
                } else {
                    -0.5 * (lambda + u * u).powi(2)
                };
                sum += h * w * 2.0 * u.powf(2.0 * n + 1.0) * e.exp();
            }
        }
        let outside = if lambda >= 0.0 {
            (-0.5 * lambda * lambda).exp()
        } else {
            1.0
        };
        INV_SQRT_2PI * sum * outside
    }

    #[test]
    fn values_at_zero() {
        // Issue 25 Validation 5: F_5/2(0) = 0.6167, F_2(0) = 0.5 to 1e-4; and the exact
        // F_n(0) = 2^((n−1)/2) Γ((n+1)/2)/√(2π) to 1e-13 (rounding of the sums).
        assert!((f_2(0.0) - 0.5).abs() < 1e-15);
        assert!((f_5_2(0.0) - 0.6167).abs() < 1e-4, "{}", f_5_2(0.0));
        let exact = 2f64.powf(0.75) * libm::tgamma(1.75) * INV_SQRT_2PI;
        assert!(
            (f_5_2(0.0) - exact).abs() < 1e-13 * exact,
            "{} vs {exact}",
            f_5_2(0.0)
        );
    }

    #[test]
    fn quadrature_matches_closed_form_and_reference() {
        // The quadrature with n = 2 against the erfc closed form where the latter does
        // not cancel (λ ≤ 3), and F_5/2 and F_2 against the composite reference:
        // 1e-13 relative (measured 1e-14 against a 40-digit integration) on λ ∈ [−3, 12].
        let mut worst: f64 = 0.0;
        for i in 0..=150 {
            let l = -3.0 + 0.1 * i as f64;
            let e2 = f_2(l);
            if l <= CLOSED_FORM_MAX {
                let closed = (1.0 + l * l) * upper_tail(l) - l * density(l);
                worst = worst.max((f_n_quadrature(2.0, l) - closed).abs() / closed);
            }
            let r = reference(2.5, l);
            worst = worst
                .max((f_5_2(l) - r).abs() / r)
                .max((reference(2.0, l) - e2).abs() / e2);
        }
        assert!(worst < 1e-13, "worst relative error {worst:e}");
    }

    /// The tabulated F_5/2 against the quadrature it interpolates, 100 points per piece
    /// and at every piece boundary: 2e-13 relative (measured 1.1e-13: the quadrature's
    /// own noise, it is itself 1e-13 from the composite reference; the test above holds
    /// the table to 1e-13 of that reference on [−3, 12]; no reported digit moves). Catches a wrong
    /// Chebyshev node, coefficient or piece index (each gives errors ≥ 1e-3).
    #[test]
    fn tabulated_f_5_2_matches_the_quadrature() {
        let mut worst: f64 = 0.0;
        for i in 0..=7_800 {
            let l = TABLE_MIN + (TABLE_MAX - TABLE_MIN) * i as f64 / 7_800.0;
            let (fast, slow) = (f_5_2(l), f_n_quadrature(2.5, l));
            assert!(slow > 0.0 && fast.is_finite(), "λ = {l}: {fast} vs {slow}");
            worst = worst.max((fast - slow).abs() / slow);
        }
        assert!(worst < 2e-13, "worst relative error {worst:e}");
        // Outside the table the quadrature answers: equal bit for bit.
        for l in [-5.0, -3.000_001, 36.0, 39.0, 41.0] {
            assert_eq!(f_5_2(l), f_n_quadrature(2.5, l), "λ = {l}");
        }
    }

    #[test]
    fn derivative_identity() {
        // dF_n/dλ = −n F_(n−1): a central difference of F_5/2 against −(5/2) F_3/2, and
        // of F_2 against −2 F_1 = −2(φ − λQ); 1e-7 relative (difference step 1e-4,
        // truncation ~h² F''' ≈ 1e-8).
        for l in [0.0, 0.3, 1.0, 2.0, 3.5] {
            let h = 1e-4;
            let d = (f_5_2(l + h) - f_5_2(l - h)) / (2.0 * h);
            let want = -2.5 * f_n_quadrature(1.5, l);
            assert!((d - want).abs() < 1e-7 * want.abs(), "λ={l}: {d} vs {want}");
            let d2 = (f_2(l + h) - f_2(l - h)) / (2.0 * h);
            let want2 = -2.0 * (density(l) - l * upper_tail(l));
            assert!(
                (d2 - want2).abs() < 1e-7 * want2.abs(),
                "λ={l}: {d2} vs {want2}"
            );
        }
    }

    #[test]
    fn seed_polynomials_agree_on_their_range() {
        // Issue 25 Validation 5 asks 2e-3 on [0, 1.5]. Measured: F_5/2's print 6.2e-4;
        // F_2's print 2.66e-3 at λ = 1.5, because its λ⁵ coefficient is rounded to
        // −0.002 (the four-digit fit −0.0018λ⁵ + 0.0281λ⁴ − 0.1728λ³ + 0.5258λ² −
        // 0.8043λ + 0.5003 is within 5.6e-4; the rounding alone is 1.5e-3 at 1.5). So:
        // F_5/2 print and the four-digit F_2 within 2e-3, F_2's print within 3e-3.
        let four_digit = |l: f64| {
            ((((-0.0018 * l + 0.0281) * l - 0.1728) * l + 0.5258) * l - 0.8043) * l + 0.5003
        };
        let (mut w52, mut w2, mut w2_print): (f64, f64, f64) = (0.0, 0.0, 0.0);
        for i in 0..=150 {
            let l = 0.01 * i as f64;
            w52 = w52.max((f_5_2(l) - f_5_2_polynomial(l)).abs());
            w2 = w2.max((f_2(l) - four_digit(l)).abs());
            w2_print = w2_print.max((f_2(l) - f_2_polynomial(l)).abs());
        }
        assert!(w52 < 2e-3 && w2 < 2e-3, "{w52} {w2}");
        assert!(w2_print < 3e-3 && w2_print > 2e-3, "{w2_print}");
        // Past λ ≈ 1.9 the printed F_2 fit turns negative while the exact function stays
        // positive: why the exact integrals are used.
        assert!(f_2_polynomial(2.0) < 0.0 && f_2(2.0) > 0.0);
    }

    #[test]
    fn tails_are_small_past_four() {
        // Issue 25 Validation 5: F_n < 1e-5 for λ ≥ 4.
        for i in 0..200 {
            let l = 4.0 + 0.2 * i as f64;
            assert!(f_5_2(l) < 1e-5 && f_2(l) < 1e-5, "λ={l}");
        }
        assert!(f_5_2(4.0) > 0.0 && f_2(4.0) > 0.0);
        assert_eq!(f_5_2(1e6), 0.0);
        assert_eq!(f_2(1e6), 0.0);
    }

    #[test]
    fn modulus_is_e_star_not_e_r() {
        // Trap 4: W_a with E* for steel (210 GPa, ν 0.3): by hand (16√2/15)π·0.055²·
        // √1e-3 = 4.5335e-4, × 115.38 GPa × 1 mm² × F_5/2(0) = 32.26 N; the seed's E_r
        // (= 2E*) would give twice that.
        let r = Roughness {
            composite_rms_m: 0.6e-6,
            roughness_parameter: 0.055,
            asperity_slope: 1e-3,
        };
        let e_star = 210e9 / (2.0 * (1.0 - 0.09));
        let w = r.asperity_load_n(e_star, 1e-6, 0.0);
        let by_hand = 16.0 * 2f64.sqrt() / 15.0 * PI * 0.055 * 0.055 * 1e-3f64.sqrt();
        assert!((by_hand - 4.5335e-4).abs() < 1e-7);
        assert!((w - by_hand * e_star * 1e-6 * 0.616_64).abs() < 1e-3, "{w}");
        let e_r = 2.0 * e_star;
        assert!((r.asperity_load_n(e_r, 1e-6, 0.0) / w - 2.0).abs() < 1e-14);
        // A_a at λ = 0: π²·0.055²·A·½.
        let a = r.asperity_area_m2(1e-6, 0.0);
        assert!((a - PI * PI * 0.055 * 0.055 * 1e-6 * 0.5).abs() < 1e-20);
    }

    proptest! {
        #[test]
        fn nonnegative_and_decreasing(a in -3.0f64..40.0, d in 0.0f64..5.0) {
            let (l1, l2) = (a, a + d);
            prop_assert!(f_5_2(l1) >= 0.0 && f_2(l1) >= 0.0);
            prop_assert!(f_5_2(l2) <= f_5_2(l1));
            prop_assert!(f_2(l2) <= f_2(l1));
            prop_assert!(f_5_2(l1).is_finite() && f_2(l1).is_finite());
        }

        #[test]
        fn never_nan_for_finite_input(l in proptest::num::f64::NORMAL) {
            // Far negative λ (not a physical film) still gives a finite, positive number.
            prop_assume!(l > -1e3);
            prop_assert!(f_2(l).is_finite() && f_2(l) >= 0.0);
            prop_assert!(f_5_2(l).is_finite() && f_5_2(l) >= 0.0);
        }
    }
}
