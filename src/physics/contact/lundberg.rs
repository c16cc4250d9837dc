//! Lundberg's approach of a line contact under a Hertzian (elliptical) pressure strip of
//! finite length (seed 004 eqs. 62–71; G. Lundberg, *Elastische Berührung zweier
//! Halbräume*, Forschung Ing.-Wes. 10, 1939), SI units.
//!
//! A strip of length `L` (along the contact line) and half-width `b` carries the load `p`
//! per unit length. The two bodies approach by
//!
//! δ = c·p·[1.8864 + ln(L/(2b))],  c = (η_R + η_r)/(2π),  η = 4(1 − ν²)/E   (eqs. 62–63)
//!
//! with the Hertz half-width b = √(c·p·dₓ·(1 + C·γ)) (eq. 64: dₓ the roller diameter
//! normal to the contact line, C = +1 on a concave outer race, −1 on a convex inner one).
//!
//! Reading of the OCR: eq. 62 prints the factor as "(η_R + η_r)/π"; eq. 71 (its derivative)
//! and eq. 64 print "2π". The 2π form is the one that makes b the Hertz half-width
//! (b² = 4qR/(πE*) with R = dₓ(1 + Cγ)/2 and 4/E* = η_R + η_r) and δ the half-space
//! result: the centre displacement of one half-space under the elliptical strip is
//! 2q(1 − ν²)/(πE)·[½ + ln 4 + ln(L/(2b))] for L ≫ b (tested by quadrature below), so the
//! two bodies together give c·p·[…] with c = Ση/(2π); Lundberg's 1.8864 is ½ + ln 4 to
//! four decimals and the 1.3864 of eq. 71 is ln 4, which is why the inverse exists only for
//! L/(2b) > e^(−ln 4) = 0.25 (the condition the seed states with eq. 71).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]
// `!(x < max)` is used on purpose: it rejects NaN along with the out-of-range values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use thiserror::Error;

use crate::physics::material::Material;

/// Lundberg's constant of eq. 62 as printed (½ + ln 4 = 1.886294 to four decimals).
pub const LUNDBERG_CONSTANT: f64 = 1.8864;

/// η = 4(1 − ν²)/E of one body, 1/Pa (eq. 63).
pub fn elastic_constant(m: &Material) -> f64 {
    4.0 * (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus_pa
}

/// c = (η_R + η_r)/(2π) of a roller–race pair, 1/Pa (the factor of eqs. 62, 64, 71).
pub fn compliance(roller: &Material, race: &Material) -> f64 {
    (elastic_constant(roller) + elastic_constant(race)) / (2.0 * std::f64::consts::PI)
}

/// Why Lundberg's relation could not be inverted.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LundbergError {
    /// The approach exceeds the largest one the relation gives for this length: the load
    /// would need L/(2b) ≤ 0.25, outside the validity of eq. 71.
    #[error("approach {approach_m:.3e} m exceeds Lundberg's maximum {max_approach_m:.3e} m for contact length {length_m:.3e} m (needs L/(2b) > 0.25, eq. 71)")]
    BeyondValidity {
        /// The approach asked for, m.
        approach_m: f64,
        /// The largest approach of the relation at this length (reached at L/(2b) = 0.25), m.
        max_approach_m: f64,
        /// The contact length, m.
        length_m: f64,
    },
    /// A length, compliance or diameter is not positive and finite.
    #[error("invalid input: {0}")]
    InvalidInput(&'static str),
}

/// One slice's load p (N/m) at a given approach, with the derivatives the Jacobians need.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliceLoad {
    /// p, load per unit length, N/m (zero when the approach is not positive).
    pub load_n_m: f64,
    /// ∂p/∂δ at fixed length, N/m² (eq. 71 inverted).
    pub dload_dapproach: f64,
    /// ∂p/∂L at fixed approach, N/m² (the contact length in the logarithm).
    pub dload_dlength: f64,
    /// b, Hertz half-width, m (eq. 64).
    pub half_width_m: f64,
}

/// Lundberg's law of one slice: the compliance c and the half-width factor
/// b² = `width_factor`·p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LundbergSlice {
    /// c = (η_R + η_r)/(2π), 1/Pa.
    pub compliance: f64,
    /// c·dₓ·(1 + C·γ), m²/(N/m): b² per unit load per length (eq. 64).
    pub width_factor: f64,
}

impl LundbergSlice {
    /// The law of a slice of roller diameter `d_x_m` (normal to the contact line) with the
    /// conformity factor 1 + C·γ (`conformity`), between bodies of compliance `compliance`.
    pub fn new(compliance: f64, d_x_m: f64, conformity: f64) -> Result<Self, LundbergError> {
        let ok = |x: f64| x > 0.0 && x.is_finite();
        if !(ok(compliance) && ok(d_x_m) && ok(conformity)) {
            return Err(LundbergError::InvalidInput(
                "compliance, diameter and conformity must be positive",
            ));
        }
        Ok(LundbergSlice {
            compliance,
            width_factor: compliance * d_x_m * conformity,
        })
    }

    /// b = √(width_factor·p), m (eq. 64).
    pub fn half_width(&self, p_n_m: f64) -> f64 {
        (self.width_factor * p_n_m.max(0.0)).sqrt()
    }

    /// The approach δ (m) for load per length `p` over contact length `length` (eq. 62),
    /// with ∂δ/∂p (eq. 71) and ∂δ/∂L. Zero load gives zero approach and infinite ∂δ/∂p is
    /// avoided by returning the limit's finite stand-in only for p > 0.
    pub fn approach(&self, p_n_m: f64, length_m: f64) -> (f64, f64, f64) {
        if p_n_m <= 0.0 {
            return (0.0, f64::INFINITY, 0.0);
        }
        let c = self.compliance;
        let log = (length_m / (2.0 * self.half_width(p_n_m))).ln();
        let delta = c * p_n_m * (LUNDBERG_CONSTANT + log);
        // ∂/∂p of p·ln(1/√p) is ln(…) − ½: eq. 71's 1.3864 = 1.8864 − ½.
        let d_dp = c * (LUNDBERG_CONSTANT - 0.5 + log);
        (delta, d_dp, c * p_n_m / length_m)
    }

    /// Largest approach the relation gives at this length (at L/(2b) = e^{−(K−½)} ≈ 0.25,
    /// where ∂δ/∂p of eq. 71 vanishes),
    /// m, and the load per length there, N/m.
    pub fn max_approach(&self, length_m: f64) -> (f64, f64) {
        let b = 0.5 * length_m * (LUNDBERG_CONSTANT - 0.5).exp();
        let p = b * b / self.width_factor;
        (self.compliance * p * 0.5, p)
    }

    /// The load per length p (N/m) that gives approach `delta` over contact length
    /// `length` (eqs. 69–71). Not positive `delta`: zero load. Beyond the valid branch: a
    /// typed error.
    ///
    /// Solved for the logarithmic factor t = K + ln(L/(2b)) rather than for p (the
    /// tapered roller's solve spends most of its time here): with p = D/t, D = δ/c and
    /// b² = w·p, eq. 62 becomes t − ½·ln t = C₀ = K + ½·ln(L²/(4wD)), one scalar equation
    /// whose g(t) = t − ½ ln t is smooth and convex with g′ = 1 − 1/(2t) ≥ ⅔ where this path
    /// is taken (t ≥ 1.5, far from the validity limit t = ½ where g′ = 0). Start
    /// t₀ = C₀ + ½ ln C₀ (one fixed-point step, within a few per cent), then Halley's
    /// cubic iteration: once a step is below 1e-5·t the next error is below 1e-17 and
    /// the loop stops. Then ∂δ/∂p = c(t − ½) (eq. 71) exactly at the root. Near the
    /// validity limit, the Newton iteration in p below ([`Self::load_by_p`]) decides; the
    /// two agree to round-off (test `t_form_matches_p_form`).
    pub fn load(&self, delta_m: f64, length_m: f64) -> Result<SliceLoad, LundbergError> {
        if !(length_m > 0.0 && length_m.is_finite()) {
            return Err(LundbergError::InvalidInput(
                "contact length must be positive",
            ));
        }
        if delta_m <= 0.0 {
            return Ok(SliceLoad::default());
        }
        let c = self.compliance;
        let d = delta_m / c;
        let c0 =
            LUNDBERG_CONSTANT + 0.5 * (length_m * length_m / (4.0 * self.width_factor * d)).ln();
        // g(1.5) = 1.5 − ½ ln 1.5 = 1.2973: C₀ above it puts the root at t > 1.5.
        if !(c0 > 1.3 && c0.is_finite()) {
            return self.load_by_p(delta_m, length_m);
        }
        let mut t = c0 + 0.5 * c0.ln();
        for _ in 0..20 {
            let g = t - 0.5 * t.ln() - c0;
            let g1 = 1.0 - 0.5 / t;
            let g2 = 0.5 / (t * t);
            let step = -2.0 * g * g1 / (2.0 * g1 * g1 - g * g2);
            t += step;
            if step.abs() <= 1e-5 * t {
                break;
            }
        }
        let p = d / t;
        let slope = c * (t - 0.5);
        Ok(SliceLoad {
            load_n_m: p,
            dload_dapproach: 1.0 / slope,
            dload_dlength: -(c * p / length_m) / slope,
            half_width_m: self.half_width(p),
        })
    }

    /// [`Self::load`] by Newton's iteration (70) in p from below: δ(p) is increasing and
    /// concave on the valid branch, so iterates started under the root rise monotonically
    /// to it. Used near the validity limit.
    pub fn load_by_p(&self, delta_m: f64, length_m: f64) -> Result<SliceLoad, LundbergError> {
        if !(length_m > 0.0 && length_m.is_finite()) {
            return Err(LundbergError::InvalidInput(
                "contact length must be positive",
            ));
        }
        if delta_m <= 0.0 {
            return Ok(SliceLoad::default());
        }
        let (max_delta, p_max) = self.max_approach(length_m);
        if !(delta_m < max_delta) {
            return Err(LundbergError::BeyondValidity {
                approach_m: delta_m,
                max_approach_m: max_delta,
                length_m,
            });
        }
        let c = self.compliance;
        // Two fixed-point sweeps p ← δ/(c·A(p)), A(p) = K + ln(L/2b) decreasing in p: from
        // any p under the root they stay under it and come close (A varies as ln p/2).
        let mut p = delta_m / (c * (LUNDBERG_CONSTANT + 60.0));
        for _ in 0..2 {
            let a = LUNDBERG_CONSTANT + (length_m / (2.0 * self.half_width(p))).ln();
            p = (delta_m / (c * a)).min(p_max);
        }
        // Newton converges quadratically with a constant below 1 in relative terms
        // (p·δ''/δ' = −½/(ln(L/2b) + ln 4) ≥ −1 on the valid branch), so once a step is
        // under 1e-8 of p the iterate after it is exact to round-off: stop there.
        let mut d_dp = 0.0;
        for _ in 0..60 {
            let (d, slope, _) = self.approach(p, length_m);
            d_dp = slope;
            let step = (delta_m - d) / slope;
            p += step;
            if step.abs() <= 1e-8 * p {
                break;
            }
        }
        let (_, slope, d_dl) = self.approach(p, length_m);
        if slope > 0.0 {
            d_dp = slope;
        }
        Ok(SliceLoad {
            load_n_m: p,
            dload_dapproach: 1.0 / d_dp,
            dload_dlength: -d_dl / d_dp,
            half_width_m: self.half_width(p),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::contact::lamina_law::palmgren_si;
    use crate::units::{INCH_M, LBF_N};

    fn steel_slice(d: f64) -> LundbergSlice {
        let s = Material::STEEL;
        LundbergSlice::new(compliance(&s, &s), d, 1.0).unwrap()
    }

    /// The half-space reference: the centre displacement of one elastic half-space under
    /// the Hertz strip p(x) = p₀√(1 − x²/b²), |y| < L/2, by Boussinesq's kernel
    /// w = (1 − ν²)/(πE)·∬ p/r dA integrated over y exactly (2·asinh(L/2|x|)) and over x
    /// by the midpoint rule in x = b·sin t (smooth integrand). Two bodies of the same
    /// material give twice this; Lundberg's (62) must agree to the rounding of its
    /// constant (1.8864 vs ½ + ln 4: 1e-4 of the bracket) plus O((b/L)²).
    #[test]
    fn lundberg_matches_half_space_quadrature() {
        let s = Material::STEEL;
        let slice = steel_slice(7.4e-3);
        let (q, l) = (2.0e5, 15e-3);
        let b = slice.half_width(q);
        assert!(l / b > 100.0);
        let p0 = 2.0 * q / (std::f64::consts::PI * b);
        let n = 200_000;
        let mut integral = 0.0;
        for i in 0..n {
            // x = b sin t, t ∈ (−π/2, π/2): dx = b cos t dt, √(1 − x²/b²) = cos t.
            let t =
                -std::f64::consts::FRAC_PI_2 + (i as f64 + 0.5) * std::f64::consts::PI / n as f64;
            let x = b * t.sin();
            let dx = b * t.cos() * std::f64::consts::PI / n as f64;
            integral += p0 * t.cos() * 2.0 * (l / (2.0 * x.abs())).asinh() * dx;
        }
        let w_one = (1.0 - s.poisson_ratio.powi(2)) / (std::f64::consts::PI * s.youngs_modulus_pa)
            * integral;
        let (delta, _, _) = slice.approach(q, l);
        let rel = (2.0 * w_one / delta - 1.0).abs();
        assert!(
            rel < 2e-5,
            "quadrature {} vs Lundberg {delta}: {rel}",
            2.0 * w_one
        );
        // The constant itself: ½ + ln 4 rounds to the printed 1.8864 (4 decimals).
        assert!((0.5 + 4f64.ln() - LUNDBERG_CONSTANT).abs() < 1.1e-4);
    }

    /// The inverse reproduces the forward relation to round-off and its derivatives are
    /// the implicit-function ones; checked by finite differences (1e-6 relative).
    #[test]
    fn inverse_round_trips_with_derivatives() {
        let slice = steel_slice(7.4e-3);
        for (p, l) in [(1e3, 5e-3), (1e5, 15e-3), (1e6, 15e-3), (3e6, 4e-3)] {
            let (delta, _, _) = slice.approach(p, l);
            let r = slice.load(delta, l).unwrap();
            assert!(
                (r.load_n_m / p - 1.0).abs() < 1e-12,
                "{p} {l}: {}",
                r.load_n_m
            );
            let h = 1e-6 * delta;
            let fd = (slice.load(delta + h, l).unwrap().load_n_m
                - slice.load(delta - h, l).unwrap().load_n_m)
                / (2.0 * h);
            assert!((fd / r.dload_dapproach - 1.0).abs() < 1e-6);
            let hl = 1e-6 * l;
            let fdl = (slice.load(delta, l + hl).unwrap().load_n_m
                - slice.load(delta, l - hl).unwrap().load_n_m)
                / (2.0 * hl);
            assert!((fdl / r.dload_dlength - 1.0).abs() < 1e-6);
        }
        assert_eq!(slice.load(0.0, 1e-2).unwrap(), SliceLoad::default());
        assert_eq!(slice.load(-1e-6, 1e-2).unwrap(), SliceLoad::default());
    }

    /// Beyond L/(2b) = 0.25 the relation has no inverse: a typed error with the numbers;
    /// just under the maximum it still inverts, with L/(2b) above 0.25.
    #[test]
    fn inverse_refuses_beyond_validity() {
        let slice = steel_slice(7.4e-3);
        let l = 1e-3;
        let (dmax, _) = slice.max_approach(l);
        match slice.load(1.01 * dmax, l) {
            Err(LundbergError::BeyondValidity {
                approach_m,
                max_approach_m,
                length_m,
            }) => {
                assert_eq!(approach_m, 1.01 * dmax);
                assert_eq!(max_approach_m, dmax);
                assert_eq!(length_m, l);
            }
            other => panic!("{other:?}"),
        }
        let r = slice.load(0.99 * dmax, l).unwrap();
        assert!(l / (2.0 * r.half_width_m) > 0.25);
        // e^(−1.3864) is 0.25 to 4 digits: the seed's statement of the limit.
        assert!(((-(LUNDBERG_CONSTANT - 0.5)).exp() - 0.25).abs() < 5e-5);
    }

    /// The t-form of the inversion (the fast path of `load`) and Newton in p agree to
    /// round-off (2e-14 relative in p and its derivatives: both are solved to the last
    /// bits of a 5-digit-magnitude logarithm) from featherweight loads to beyond the
    /// switch to the p-form near the validity limit, and both invert eq. 62 to 1e-13.
    #[test]
    fn t_form_matches_p_form() {
        let d = 0.2913 * INCH_M;
        let slice = steel_slice(d);
        for l in [1e-4, 0.6001 * INCH_M, 0.05] {
            let (dmax, _) = slice.max_approach(l);
            for k in 1..=400 {
                let delta = dmax * (k as f64 / 400.0).powi(6) * 0.999;
                let a = slice.load(delta, l).unwrap();
                let b = slice.load_by_p(delta, l).unwrap();
                let rel = |x: f64, y: f64| (x - y).abs() / y.abs();
                assert!(rel(a.load_n_m, b.load_n_m) < 2e-14, "{l} {k}");
                assert!(rel(a.dload_dapproach, b.dload_dapproach) < 2e-12, "{l} {k}");
                assert!(rel(a.dload_dlength, b.dload_dlength) < 2e-12, "{l} {k}");
                let (back, _, _) = slice.approach(a.load_n_m, l);
                assert!(rel(back, delta) < 1e-13, "{l} {k}");
            }
        }
    }

    /// Lundberg against Palmgren's empirical line-contact law δ = 4.36e-7·Q^0.9/l^0.8
    /// (in, lbf) for steel on steel, the sample's 0.2913 in roller loaded uniformly over its
    /// 0.6001 in length from 100 to 3000 lbf. The two are different laws (logarithmic vs
    /// power) and agree only roughly: measured, Lundberg's approach is 17–26 % larger over
    /// this range, the ratio growing with load (1.168 at 100 lbf, 1.207 at the sample's
    /// 320 lbf, 1.256 at 3000 lbf). The bound states that band (1.15–1.27); the issue's
    /// 10 % holds only below ≈ 20 lbf for this roller (ratio 1.104 at 20 lbf, 1.074 at
    /// 10 lbf), not at the loads the sample carries.
    ///
    /// Checked for a consistent comparison (issue 17 asked for 10 %): units (Palmgren's
    /// in–lbf constant is Harris's per-contact 3.84e-5 mm–N form, δ of one roller–race
    /// contact like eq. 62, and l the effective length: the total length would make the
    /// gap larger, as would counting both races); the race's conformity changes the
    /// logarithm by ½ln(1 ± γ) ≈ ±0.03 (under 1 %); over the loads of Palmgren's fit
    /// (Hertz stresses 0.5–2 GPa) the ratio stays 1.10–1.25 for rollers of 0.3–1 in
    /// diameter and 0.3–1 in length. The two laws differ in form: Lundberg's local
    /// exponent d ln δ/d ln Q = 1 − 1/(2(K + ln(L/2b))) equals Palmgren's 0.9 only at
    /// L/(2b) ≈ 22.5, where their ratio is largest, so no load range of working stresses
    /// brings them within 10 %: the measured band is the test.
    #[test]
    fn lundberg_vs_palmgren() {
        let d = 0.2913 * INCH_M;
        let l = 0.6001 * INCH_M;
        let slice = steel_slice(d);
        let mut last = 0.0;
        for q_lbf in [100.0, 320.23, 1000.0, 3000.0] {
            let q = q_lbf * LBF_N;
            let (lund, _, _) = slice.approach(q / l, l);
            let pal = palmgren_si() * q.powf(0.9) / l.powf(0.8);
            let ratio = lund / pal;
            assert!(ratio > 1.15 && ratio < 1.27, "{q_lbf} lbf: ratio {ratio}");
            assert!(ratio > last);
            last = ratio;
        }
    }
}
