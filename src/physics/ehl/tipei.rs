//! Tipei's counter-flow inlet (seed 003 eqs. 14–22), SI: where the oil meniscus of a
//! line contact sits upstream (the inlet distance m_i) and where the film breaks up
//! downstream (the outlet distance m_o), from the central film h_c, the reduced radius
//! R_zx and the speed ratio k of the two surfaces.
//!
//! # The model, as reconstructed here
//!
//! Near the inlet meniscus (point A of the seed's Figure 8) the gap is locally of height h
//! and the two surfaces move at U₁ (the faster) and U₂ = kU₁ (eq. 15, 0 ≤ k ≤ 1). With
//! the dimensionless pressure gradient G = h² (dp/dx)/(η U₁) the Reynolds velocity
//! profile across the film, ζ = z/h, is
//!
//! u/U₁ = (G/2) ζ² − (G/2 + 1 − k) ζ + 1,
//!
//! and the flow rate per unit length is q = U₁h [(1 + k)/2 − G/12].
//!
//! **Eq. 16, the bounds.** Counter-flow (u < 0 inside the film) exists once the quadratic
//! has its two zeros in (0, 1): G ≥ 2(1 + √k)² (double zero at ζ = 1/(1 + √k)). The net
//! flow is still forward while G < 6(1 + k). So 2(1 + √k)² < f(k) < 6(1 + k). The OCR
//! prints "2(1+ k)^… < f(k) < 6(1+√k)": the square root has slid from the lower bound to
//! the upper one. Both printed bounds are still honoured (6(1+k) ≤ 6(1+√k) on [0, 1],
//! tested), and our reading is the one eq. 20's own coefficients carry:
//! (1/3)(1 + 2√k/(1+k)) = 2(1+√k)²/(6(1+k)) and f(k)/(6(1+k)) are the two gradients over
//! the zero-flow gradient 6(1 + k).
//!
//! **Eq. 14, the compatibility condition (garbled).** The OCR shows products of
//! cotangents of π times "½ − ½√[…f(k)]", i.e. of π times the two zeros
//! ζ₁,₂ = ½ + (1−k)/G ∓ ½√[(1 + 2(1−k)/G)² − 8/G] of the velocity profile: the two
//! dividing streamlines that bound the counter-flow band. Tipei's potential-flow argument:
//! map the film strip near the meniscus onto a half-plane by t = exp(πz/h); a streamline
//! leaving the strip at height ζh becomes a ray at angle πζ. The counter-flow turns round
//! at the meniscus in a stagnation point, and the separatrices of a regular (potential)
//! stagnation point cross at right angles, so the two rays are orthogonal:
//!
//! cot(πζ₁) · cot(πζ₂) = −1 ⇔ ζ₂ − ζ₁ = ½ (eq. 14 as read here):
//!
//! the counter-flow occupies half of the meniscus film. With the profile above this is
//! (3/16)G² − (1 + k)G + (1 − k)² = 0, whose larger root (the smaller one lies below the
//! onset of counter-flow) is
//!
//! f(k) = (8/3) [(1 + k) + √((1 + k)² − ¾(1 − k)²)].
//!
//! It gives f(0) = 4 exactly and f(0.5) = 7.8297 (Table 1: 4 and 7.8, 0.4 %), and
//! f(1) = 32/3 = 10.667: Table 1's "3212" is the OCR of the printed fraction "32/3" (the
//! slash read as a 1, the final 3 as a 2). 10.667 lies inside eq. 16's bounds (8, 12).
//!
//! **Eqs. 17–20, the menisci.** In the gap of a cylinder on a plane, h = h_c(1 + x²/(2R h_c))
//! near the centre; with x = √(2R h_c) sinh ϑ, h = h_c cosh²ϑ (the seed's ϑ: "the ratio of
//! the film thickness … to the central film", through cosh²ϑ). Reynolds integrates to
//! G = 6(1 + k)(1 − h*/h) with h* the film where dp/dx = 0. Tipei's conditions:
//! - inlet meniscus (x_i < 0): G = f(k), so h*/h_i = 1 − a_i, a_i = f(k)/(6(1 + k));
//! - outlet (x_e > 0), film break-up at the onset of counter-flow: G = 2(1 + √k)², so
//!   h*/h_e = 1 − a_e, a_e = (1/3)(1 + 2√k/(1 + k)); dividing the two gives eq. 19,
//!   cosh²ϑ_i / cosh²ϑ_e = (1 − a_e)/(1 − a_i) (the OCR's "1 − (1 + …)" over "1 − …");
//! - ambient pressure at both menisci: ∫ (1/h² − h*/h³) dx = 0 between them, which with
//!   c = h*/h_c = cosh²ϑ_i (1 − a_i) is ∫_{−ϑ_i}^{ϑ_e} (sech³ϑ − c sech⁵ϑ) dϑ = 0. With
//!   ∫sech = gd = arcsin(tanh ϑ) (the arcsin(tanh ϑ) terms of eq. 20) and
//!   ∫sechⁿ = sechⁿ⁻² tanh/(n−1) + (n−2)/(n−1) ∫sechⁿ⁻², this is Φ(ϑ_e) + Φ(ϑ_i) = 0 with
//!   Φ(ϑ) = ½(sech tanh + gd) − c[¼ sech³ tanh + ⅜(sech tanh + gd)]. This is the
//!   condition eq. 20 prints in a rearranged (and garbled) form; we solve it as derived
//!   and check it against a direct quadrature of Reynolds (tested).
//!
//! It fixes ϑ_i and ϑ_e from k alone: the rigid-gap inlet is a shape, scaled by
//! √(2R h_c). Eqs. 17–18 then place the menisci on the cylinder exactly,
//! cos φ = 1 − (h_c/R)(cosh²ϑ − 1), and eqs. 21–22 give m_i = R sin φ_i, m_o = R sin φ_o
//! (≈ √(2R h_c) sinh ϑ for small angles).
//!
//! **The supply.** The seed's inlet needs no supply-layer thickness: the meniscus film is
//! an output, h_i = h_c cosh²ϑ_i, and the quantity that sets the inlet is the central
//! film (seed step 3: the inlet from the estimated h_c, iterated with the solver). A
//! thinner film gives a shorter inlet (m_i ∝ √h_c, tested monotone) and a thick enough
//! film puts the meniscus beyond the flooded 4–5 Hertz half-widths (starvation vanishes,
//! tested). At R_zx ≈ 5 mm, h_c ≈ 0.4 µm, k = 1: m_i ≈ 0.21 mm. The truck contact's
//! solved film is thinner (h_c ≈ 0.16 µm, k = 0.83, b ≈ 95 µm): m_i ≈ 131 µm ≈ 1.4 b.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use thiserror::Error;

/// Largest cosh²ϑ searched for the inlet (h_i/h_c); a root beyond it would put the
/// meniscus 10⁸ central films away, far outside any contact.
pub const MAX_FILM_RATIO: f64 = 1e8;

/// Bisection steps allowed for the inlet root (the bracket shrinks by 2⁻²⁰⁰).
pub const MAX_ITERATIONS: usize = 200;

/// Why Tipei's inlet cannot be placed: the quantity, its value and the allowed range.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TipeiError {
    /// An input outside its allowed range.
    #[error("Tipei inlet: {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The input's name (units in it).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// The pressure condition has no root between the two film ratios searched.
    #[error(
        "Tipei inlet: no inlet meniscus for speed ratio k = {k}: the pressure balance is \
         {residual_low:e} at h_i/h_c = {film_ratio_low:e} and {residual_high:e} at \
         h_i/h_c = {film_ratio_high:e} (same sign)"
    )]
    NoRoot {
        /// The speed ratio k.
        k: f64,
        /// h_i/h_c at the lower end of the search.
        film_ratio_low: f64,
        /// h_i/h_c at the upper end.
        film_ratio_high: f64,
        /// The pressure balance there.
        residual_low: f64,
        /// The pressure balance there.
        residual_high: f64,
    },
    /// The meniscus would lie beyond a quarter turn of the cylinder (cos φ < 0): the film
    /// is not thin against the radius.
    #[error(
        "Tipei inlet: central film {central_film_m:e} m is too thick for radius \
         {radius_m:e} m: the {which} meniscus (h/h_c = {film_ratio:.4}) lies beyond a \
         quarter turn of the roller; the film must be below about R/(2·h/h_c)"
    )]
    BeyondCylinder {
        /// Which meniscus ("inlet" or "outlet").
        which: &'static str,
        /// The central film, m.
        central_film_m: f64,
        /// The reduced radius, m.
        radius_m: f64,
        /// cosh²ϑ there.
        film_ratio: f64,
    },
}

/// Tipei's inlet and outlet of one line contact, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TipeiInlet {
    /// f(k), the dimensionless meniscus pressure gradient h²(dp/dx)/(η U_fast) (eq. 14).
    pub f_k: f64,
    /// m_i = R_zx sin φ_i, distance of the inlet meniscus upstream of the centre, m (eq. 21).
    pub inlet_distance_m: f64,
    /// m_o = R_zx sin φ_o, distance of the film break-up downstream of the centre, m (eq. 22).
    pub outlet_distance_m: f64,
    /// ϑ_i, with cosh²ϑ_i = h_i/h_c at the inlet meniscus, dimensionless.
    pub theta_inlet: f64,
    /// ϑ_e, with cosh²ϑ_e = h_e/h_c at the outlet, dimensionless.
    pub theta_outlet: f64,
    /// h_i, the film at the inlet meniscus, m.
    pub inlet_film_m: f64,
    /// h_e, the film at the outlet, m.
    pub outlet_film_m: f64,
    /// Bisection steps of the inlet root.
    pub iterations: usize,
}

/// k = |u_slow|/|u_fast| of two surface speeds (eq. 15), in [0, 1]; 1 when both are 0.
pub fn speed_ratio(u1_m_s: f64, u2_m_s: f64) -> f64 {
    let (a, b) = (u1_m_s.abs(), u2_m_s.abs());
    let fast = a.max(b);
    if fast > 0.0 {
        a.min(b) / fast
    } else {
        1.0
    }
}

/// f(k) of eq. 14 as reconstructed (module note), dimensionless, for 0 ≤ k ≤ 1:
/// (8/3)[(1 + k) + √((1 + k)² − ¾(1 − k)²)].
pub fn f_of_k(k: f64) -> f64 {
    let s = 1.0 + k;
    let d = 1.0 - k;
    8.0 / 3.0 * (s + (s * s - 0.75 * d * d).sqrt())
}

/// 2(1 + √k)², the dimensionless gradient at which counter-flow starts (eq. 16's lower
/// bound, and Tipei's outlet condition).
pub fn counter_flow_onset(k: f64) -> f64 {
    let r = 1.0 + k.sqrt();
    2.0 * r * r
}

/// 6(1 + k), the dimensionless gradient at which the net flow stops (eq. 16's upper bound).
pub fn zero_flow_gradient(k: f64) -> f64 {
    6.0 * (1.0 + k)
}

/// The zeros ζ₁ ≤ ζ₂ of the velocity profile u/U₁ = (G/2)ζ² − (G/2 + 1 − k)ζ + 1 at the
/// dimensionless gradient `g` (module note): the dividing streamlines of the counter-flow.
/// None when the profile has no pair of zeros inside the film (no counter-flow) or g ≤ 0.
pub fn dividing_streamlines(k: f64, g: f64) -> Option<(f64, f64)> {
    if g <= 0.0 {
        return None;
    }
    let b = 0.5 * g + 1.0 - k;
    let disc = b * b - 2.0 * g;
    if disc < 0.0 {
        return None;
    }
    let r = disc.sqrt();
    let (z1, z2) = ((b - r) / g, (b + r) / g);
    // Zeros outside the film (k = 0 below the onset: ζ = 1 and 2/G > 1) bound no
    // counter-flow inside it; 1e-12 admits the k = 0 zero at the wall.
    if z1 >= -1e-12 && z2 <= 1.0 + 1e-12 {
        Some((z1, z2))
    } else {
        None
    }
}

/// Φ(ϑ) = ∫₀^ϑ (sech³ − c sech⁵) (module note), dimensionless; odd in ϑ.
fn phi(theta: f64, c: f64) -> f64 {
    let s = 1.0 / theta.cosh();
    let t = theta.tanh();
    let gd = t.asin();
    0.5 * (s * t + gd) - c * (0.25 * s * s * s * t + 0.375 * (s * t + gd))
}

/// Tipei's inlet and outlet (eqs. 14–22) for speed ratio `k` (eq. 15, in [0, 1]: use
/// [`speed_ratio`]), central film `central_film_m` h_c (> 0, m) and reduced radius
/// `radius_m` R_zx (> 0, m).
pub fn tipei_inlet(k: f64, central_film_m: f64, radius_m: f64) -> Result<TipeiInlet, TipeiError> {
    let check = |field, value: f64, ok: bool, allowed| {
        if value.is_finite() && ok {
            Ok(())
        } else {
            Err(TipeiError::OutOfRange {
                field,
                value,
                allowed,
            })
        }
    };
    check(
        "speed_ratio",
        k,
        (0.0..=1.0).contains(&k),
        "0 … 1 (slower over faster surface speed)",
    )?;
    check(
        "central_film_m",
        central_film_m,
        central_film_m > 0.0,
        "> 0 m",
    )?;
    check("radius_m", radius_m, radius_m > 0.0, "> 0 m")?;
    let f_k = f_of_k(k);
    let a_i = f_k / zero_flow_gradient(k);
    let a_e = counter_flow_onset(k) / zero_flow_gradient(k);
    // ϑ_e from ϑ_i (eq. 19); the search starts where the outlet sits at the centre.
    let film_ratio_low = (1.0 - a_e) / (1.0 - a_i);
    let residual = |ci2: f64| -> (f64, f64, f64) {
        let c = ci2 * (1.0 - a_i);
        let ce2 = (c / (1.0 - a_e)).max(1.0);
        let ti = ci2.sqrt().acosh();
        let te = ce2.sqrt().acosh();
        (phi(te, c) + phi(ti, c), ti, te)
    };
    // Bisect on ln(cosh²ϑ_i): the scale spans eight decades.
    let (mut lo, mut hi) = (film_ratio_low.ln(), MAX_FILM_RATIO.ln());
    let (r_lo, _, _) = residual(lo.exp());
    let (r_hi, _, _) = residual(hi.exp());
    // Same sign (or NaN) at both ends: no bracketed root.
    if r_lo * r_hi >= 0.0 || r_lo.is_nan() || r_hi.is_nan() {
        return Err(TipeiError::NoRoot {
            k,
            film_ratio_low,
            film_ratio_high: MAX_FILM_RATIO,
            residual_low: r_lo,
            residual_high: r_hi,
        });
    }
    let mut iterations = 0;
    let mut f_lo = r_lo;
    while iterations < MAX_ITERATIONS && hi - lo > 1e-14 * hi.abs().max(1.0) {
        iterations += 1;
        let mid = 0.5 * (lo + hi);
        let (r, _, _) = residual(mid.exp());
        if r == 0.0 {
            lo = mid;
            hi = mid;
            break;
        }
        if (r < 0.0) == (f_lo < 0.0) {
            lo = mid;
            f_lo = r;
        } else {
            hi = mid;
        }
    }
    let ci2 = (0.5 * (lo + hi)).exp();
    let (_, theta_inlet, theta_outlet) = residual(ci2);
    let ce2 = theta_outlet.cosh().powi(2);
    // Eqs. 17–18, 21–22: the menisci on the cylinder.
    let place = |which: &'static str, ratio: f64| {
        let cos_phi = 1.0 - central_film_m / radius_m * (ratio - 1.0);
        if cos_phi < 0.0 {
            return Err(TipeiError::BeyondCylinder {
                which,
                central_film_m,
                radius_m,
                film_ratio: ratio,
            });
        }
        Ok(radius_m * (1.0 - cos_phi * cos_phi).max(0.0).sqrt())
    };
    let inlet_distance_m = place("inlet", ci2)?;
    let outlet_distance_m = place("outlet", ce2)?;
    Ok(TipeiInlet {
        f_k,
        inlet_distance_m,
        outlet_distance_m,
        theta_inlet,
        theta_outlet,
        inlet_film_m: central_film_m * ci2,
        outlet_film_m: central_film_m * ce2,
        iterations,
    })
}

#[cfg(test)]
#[path = "tipei_tests.rs"]
mod tests;
