//! Isothermal EHL film thickness of an elliptical (point) contact: the Hamrock–Dowson
//! (1977) central and minimum film formulas, seed 001 (Chen 1989) eqs. 4-10 and 4-11,
//! SI units.
//!
//! H_min = h_min/R_x = 3.63·U^0.68·G^0.49·W^−0.073·(1 − e^{−0.68k})        (eq. 4-10)
//! H_c   = h_c/R_x   = 2.69·U^0.67·G^0.53·W^−0.067·(1 − 0.61·e^{−0.73k})   (eq. 4-11)
//!
//! with U = η₀u/(E′R_x), G = αE′, W = Q/(E′R_x²) (Chen prints U = η₀(u₁+u₂)/(2E′R),
//! i.e. u is the mean entrainment speed), E′ = 2E* = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] (Chen's
//! E/(1−ν²) for one material, eq. A-12), R_x the reduced radius **in the rolling
//! direction** and k = a_transverse/b_rolling the ellipticity ratio (κ for a ball in a
//! groove).
//!
//! # Reading of the seed
//! * Eq. 4-10 as scanned shows the load exponent as "0.063"; Hamrock & Dowson (1977)
//!   have −0.073, the value used here (the OCR also drops every minus sign in these
//!   exponents). Eq. 4-11 as scanned lacks the ellipticity factor; it is the
//!   Hamrock–Dowson (1 − 0.61e^{−0.73k}), which Chen's list of parameters
//!   ("G, R, U, W and k") implies.
//! * Chen defines the groups on "R: equivalent radius (defined in Appendix A)", whose
//!   only overall radius is 1/R = 1/R_x + 1/R_y (eq. A-2c). Hamrock & Dowson
//!   non-dimensionalise on the rolling-direction radius (Hamrock's R_x = Chen's R_y),
//!   which is what is used here; for Bearing A's inner race the two differ by 3.4 %
//!   (5.376 against 5.197 mm), which changes h by R^0.46, about 1.6 %.
//! * **No thermal or sliding correction is given by the seed.** Chapter 4 ("Effects of
//!   Sliding on Film Thickness and Pressure Spike") argues from Cheng & Sternlicht that
//!   sliding, spin included, has only a modest effect and keeps the isothermal formulas
//!   with the *inlet* viscosity η₀; sliding enters only through the entrainment speed
//!   u = (u₁ + u₂)/2 ([`entrainment_speed_m_s`]). No inlet-heating factor is applied.
//!
//! The regression behind the formulas covered 1 ≤ k ≤ 8 (Hamrock & Dowson 1977, Part
//! III); values outside are extrapolation. The formulas describe the piezoviscous-
//! elastic regime: with α = 0 or u = 0 they return h = 0, which is the formula's value,
//! not a film prediction.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use crate::physics::contact::point::{Axis, HertzPointContact};
use thiserror::Error;

/// Why a set of EHL inputs does not describe a loaded lubricated point contact.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum FilmError {
    /// An input is NaN or infinite.
    #[error("non-finite input: {0}")]
    NonFinite(&'static str),
    /// An input is out of its physical range (negative viscosity or pressure–viscosity
    /// coefficient; zero or negative radius, modulus, ellipticity or load).
    #[error("invalid input: {0}")]
    InvalidInput(&'static str),
}

/// Inputs of the point-contact film formulas, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointFilmInputs {
    /// η₀, absolute viscosity at the inlet temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// α, pressure–viscosity coefficient, 1/Pa (Chen: "generally between 0.01 and
    /// 0.02 mm²/N", i.e. 1e-8 … 2e-8 1/Pa).
    pub pressure_viscosity_pa_inv: f64,
    /// u = (u₁ + u₂)/2, entrainment speed in the rolling direction, m/s (its sign does
    /// not matter: the magnitude is used).
    pub entrainment_speed_m_s: f64,
    /// R_x, reduced radius in the rolling direction, m (Hamrock's R_x, Chen's R_y;
    /// `CurvatureSum::reduced_radius_rolling_m`).
    pub reduced_radius_rolling_m: f64,
    /// Q, normal load on the contact, N.
    pub load_n: f64,
    /// E′ = 2E*, Pa (`point::effective_modulus`).
    pub effective_modulus_pa: f64,
    /// k = a_transverse/b_rolling, ellipticity ratio, dimensionless (κ when the major
    /// axis is transverse, 1/κ when it lies along rolling).
    pub ellipticity: f64,
}

/// The dimensionless groups of Hamrock–Dowson point-contact EHL.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointEhlGroups {
    /// U = η₀|u|/(E′R_x), speed parameter.
    pub speed: f64,
    /// G = αE′, materials parameter.
    pub material: f64,
    /// W = Q/(E′R_x²), load parameter.
    pub load: f64,
    /// k = a_transverse/b_rolling, ellipticity ratio.
    pub ellipticity: f64,
}

/// Entrainment (mean rolling) speed u = (u₁ + u₂)/2, m/s, from the two surface speeds in
/// the rolling direction (m/s) — the only way sliding enters the seed's film formulas.
pub fn entrainment_speed_m_s(u1_m_s: f64, u2_m_s: f64) -> f64 {
    0.5 * (u1_m_s + u2_m_s)
}

/// Hamrock & Dowson's own approximation of the ellipticity, k ≈ 1.03·(R_y/R_x)^0.64
/// (R_x rolling, R_y transverse reduced radii, m), dimensionless: for use without a
/// Hertz solution. Against the exact κ of `point` it is within 2.4 % for
/// 3 ≤ R_y/R_x ≤ 30 and within 8 % for 1 ≤ R_y/R_x ≤ 100 (worst at the ends).
pub fn hamrock_dowson_ellipticity(
    reduced_radius_rolling_m: f64,
    reduced_radius_transverse_m: f64,
) -> Result<f64, FilmError> {
    let (rx, ry) = (reduced_radius_rolling_m, reduced_radius_transverse_m);
    if !(rx.is_finite() && ry.is_finite()) {
        return Err(FilmError::NonFinite("reduced radius"));
    }
    if rx <= 0.0 || ry <= 0.0 {
        return Err(FilmError::InvalidInput("reduced radius not positive"));
    }
    Ok(1.03 * (ry / rx).powf(0.64))
}

/// H_c = h_c/R_x of eq. 4-11 from the groups, dimensionless.
pub fn dimensionless_central(groups: PointEhlGroups) -> f64 {
    let PointEhlGroups {
        speed: u,
        material: g,
        load: w,
        ellipticity: k,
    } = groups;
    2.69 * u.powf(0.67) * g.powf(0.53) * w.powf(-0.067) * (1.0 - 0.61 * (-0.73 * k).exp())
}

/// H_min = h_min/R_x of eq. 4-10 from the groups, dimensionless.
pub fn dimensionless_minimum(groups: PointEhlGroups) -> f64 {
    let PointEhlGroups {
        speed: u,
        material: g,
        load: w,
        ellipticity: k,
    } = groups;
    3.63 * u.powf(0.68) * g.powf(0.49) * w.powf(-0.073) * (1.0 - (-0.68 * k).exp())
}

impl PointFilmInputs {
    /// Inputs for the contact `contact` under the load Q (N), with inlet viscosity η₀
    /// (Pa·s), pressure–viscosity coefficient α (1/Pa) and entrainment speed u (m/s):
    /// R_x, E′ = 2E* and k are taken from the Hertz model (k = κ or 1/κ according to the
    /// major-axis direction).
    pub fn from_contact(
        contact: &HertzPointContact,
        load_n: f64,
        viscosity_pa_s: f64,
        pressure_viscosity_pa_inv: f64,
        entrainment_speed_m_s: f64,
    ) -> Self {
        let shape = contact.shape();
        let ellipticity = match shape.major_axis {
            Axis::Transverse => shape.ellipticity,
            Axis::Rolling => 1.0 / shape.ellipticity,
        };
        Self {
            viscosity_pa_s,
            pressure_viscosity_pa_inv,
            entrainment_speed_m_s,
            reduced_radius_rolling_m: contact.curvature().reduced_radius_rolling_m(),
            load_n,
            effective_modulus_pa: 2.0 * contact.reduced_modulus_pa(),
            ellipticity,
        }
    }

    /// The dimensionless groups U, G, W, k of these inputs. Errors for non-finite
    /// inputs, negative η₀ or α, and non-positive R_x, E′, Q or k.
    pub fn groups(&self) -> Result<PointEhlGroups, FilmError> {
        let fields = [
            (self.viscosity_pa_s, "viscosity"),
            (
                self.pressure_viscosity_pa_inv,
                "pressure-viscosity coefficient",
            ),
            (self.entrainment_speed_m_s, "entrainment speed"),
            (self.reduced_radius_rolling_m, "reduced radius"),
            (self.load_n, "load"),
            (self.effective_modulus_pa, "effective modulus"),
            (self.ellipticity, "ellipticity"),
        ];
        for (x, name) in fields {
            if !x.is_finite() {
                return Err(FilmError::NonFinite(name));
            }
        }
        if self.viscosity_pa_s < 0.0 || self.pressure_viscosity_pa_inv < 0.0 {
            return Err(FilmError::InvalidInput(
                "negative viscosity or pressure-viscosity coefficient",
            ));
        }
        if self.reduced_radius_rolling_m <= 0.0
            || self.effective_modulus_pa <= 0.0
            || self.ellipticity <= 0.0
        {
            return Err(FilmError::InvalidInput(
                "reduced radius, modulus or ellipticity not positive",
            ));
        }
        // W → 0 sends W^−0.07 to infinity: an unloaded contact has no EHL film.
        if self.load_n <= 0.0 {
            return Err(FilmError::InvalidInput("load not positive"));
        }
        let (r, e) = (self.reduced_radius_rolling_m, self.effective_modulus_pa);
        Ok(PointEhlGroups {
            speed: self.viscosity_pa_s * self.entrainment_speed_m_s.abs() / (e * r),
            material: self.pressure_viscosity_pa_inv * e,
            load: self.load_n / (e * r * r),
            ellipticity: self.ellipticity,
        })
    }

    /// Central film thickness h_c = R_x·H_c, m (eq. 4-11).
    pub fn central_film_thickness_m(&self) -> Result<f64, FilmError> {
        Ok(self.reduced_radius_rolling_m * dimensionless_central(self.groups()?))
    }

    /// Minimum film thickness h_min = R_x·H_min, m (eq. 4-10).
    pub fn minimum_film_thickness_m(&self) -> Result<f64, FilmError> {
        Ok(self.reduced_radius_rolling_m * dimensionless_minimum(self.groups()?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::contact::point::{
        reduced_modulus, CurvatureSum, HertzMethod, PrincipalRadii,
    };
    use proptest::prelude::*;

    fn rel(x: f64, y: f64) -> f64 {
        (x / y - 1.0).abs()
    }

    /// The hand-worked case: E′ = 2·10¹¹ Pa, R_x = 0.01 m, η₀ = 0.04 Pa·s, u = 5 m/s,
    /// α = 2.5·10⁻⁸ 1/Pa, Q = 20 N, k = 5.
    fn hand_case() -> PointFilmInputs {
        PointFilmInputs {
            viscosity_pa_s: 0.04,
            pressure_viscosity_pa_inv: 2.5e-8,
            entrainment_speed_m_s: 5.0,
            reduced_radius_rolling_m: 0.01,
            load_n: 20.0,
            effective_modulus_pa: 2e11,
            ellipticity: 5.0,
        }
    }

    #[test]
    fn hamrock_dowson_by_hand() {
        // U = 0.04·5/(2e11·0.01) = 1e-10, G = 2.5e-8·2e11 = 5000,
        // W = 20/(2e11·0.01²) = 1e-6, k = 5.
        // Central (eq. 4-11): U^0.67 = 10^−6.7 = 1.99526e-7; G^0.53 = e^{0.53·ln 5000}
        //   = e^{4.51411} = 91.2965; W^−0.067 = 10^0.402 = 2.52348;
        //   1 − 0.61·e^{−3.65} = 1 − 0.61·0.025991 = 0.984145;
        //   H_c = 2.69·1.99526e-7·91.2965·2.52348·0.984145 = 1.21693e-4 → h_c = 1.21693 µm.
        // Minimum (eq. 4-10): U^0.68 = 10^−6.8 = 1.58489e-7; G^0.49 = e^{4.17342}
        //   = 64.9375; W^−0.073 = 10^0.438 = 2.74157; 1 − e^{−3.4} = 0.966627;
        //   H_min = 3.63·1.58489e-7·64.9375·2.74157·0.966627 = 9.90058e-5 → 0.990058 µm.
        // (Cross-checked with mpmath at 20 digits: 1.2169302 µm and 0.99005821 µm.)
        // Tolerance 1e-5 relative (six figures carried by hand).
        let f = hand_case();
        let g = f.groups().unwrap();
        assert!(rel(g.speed, 1e-10) < 1e-14);
        assert!(rel(g.material, 5000.0) < 1e-14);
        assert!(rel(g.load, 1e-6) < 1e-14);
        let hc = f.central_film_thickness_m().unwrap();
        let hm = f.minimum_film_thickness_m().unwrap();
        assert!(rel(hc, 1.21693e-6) < 1e-5, "h_c = {hc}");
        assert!(rel(hm, 0.990058e-6) < 1e-5, "h_min = {hm}");
        // The 20-digit values, to 1e-13.
        assert!(rel(hc, 1.216_930_158_824_005e-6) < 1e-13);
        assert!(rel(hm, 0.990_058_205_782_191e-6) < 1e-13);
        // Minimum film below central, as it must be (exit constriction).
        assert!(hm < hc);
    }

    #[test]
    fn trends_speed_load_ellipticity() {
        // h ∝ u^0.67 (central) and u^0.68 (minimum): strictly rising with speed;
        // doubling u multiplies h_c by 2^0.67 = 1.5911 exactly (1e-13).
        let base = hand_case();
        let h0 = base.central_film_thickness_m().unwrap();
        let fast = PointFilmInputs {
            entrainment_speed_m_s: 10.0,
            ..base
        };
        let h1 = fast.central_film_thickness_m().unwrap();
        assert!(rel(h1 / h0, 2f64.powf(0.67)) < 1e-13);
        assert!(
            fast.minimum_film_thickness_m().unwrap() > base.minimum_film_thickness_m().unwrap()
        );
        // Load: weak decrease, h ∝ Q^−0.067 (central) and Q^−0.073 (minimum): doubling Q
        // costs 4.5 % and 4.9 % (1e-13 on the ratios).
        let heavy = PointFilmInputs {
            load_n: 40.0,
            ..base
        };
        let r_c = heavy.central_film_thickness_m().unwrap() / h0;
        let r_m =
            heavy.minimum_film_thickness_m().unwrap() / base.minimum_film_thickness_m().unwrap();
        assert!(r_c < 1.0 && r_c > 0.95);
        assert!(rel(r_c, 2f64.powf(-0.067)) < 1e-13);
        assert!(rel(r_m, 2f64.powf(-0.073)) < 1e-13);
        // Sign of the speed is irrelevant; zero speed gives zero film.
        let back = PointFilmInputs {
            entrainment_speed_m_s: -5.0,
            ..base
        };
        assert_eq!(back.central_film_thickness_m().unwrap(), h0);
        let still = PointFilmInputs {
            entrainment_speed_m_s: 0.0,
            ..base
        };
        assert_eq!(still.central_film_thickness_m().unwrap(), 0.0);
        // Wider contacts (larger k) leak less sideways: h rises with k towards the
        // k → ∞ factor 1.
        let mut last = 0.0;
        for k in [1.0, 2.0, 4.0, 8.0, 100.0] {
            let f = PointFilmInputs {
                ellipticity: k,
                ..base
            };
            let h = f.minimum_film_thickness_m().unwrap();
            assert!(h > last);
            last = h;
        }
        // Entrainment speed is the mean of the surface speeds (Chen's U).
        assert_eq!(entrainment_speed_m_s(29.8, 29.8), 29.8);
        assert_eq!(entrainment_speed_m_s(30.0, 10.0), 20.0);
    }

    #[test]
    fn chen_bearing_a_inner_film_at_10000_rpm() {
        // Seed 001 ch. 6 "Temperature Rise Inside the Contact …": inner race of Bearing A
        // at 10 000 rpm, Q = 163.7 N, rolling speed u = 29.8 m/s, h = 2.6 µm, with
        // η₀ = 0.08 Pa·s and the central formula (eq. 4-11); the printed α is
        // "2.0 × 10⁻⁸ 1/Pa". Geometry: ch. 5 radii (R_rolling = 5.376 mm, R_transverse
        // = 156 mm), steel E = 208 GPa, ν = 0.3; exact κ = 8.6986.
        let e_star = reduced_modulus(2.08e11, 0.3, 2.08e11, 0.3).unwrap();
        let c = CurvatureSum::new(1.0 / 5.376e-3, 1.0 / 156e-3).unwrap();
        let h = HertzPointContact::new(c, e_star, HertzMethod::Exact).unwrap();
        let film = |alpha: f64| {
            PointFilmInputs::from_contact(&h, 163.7, 0.08, alpha, 29.8)
                .central_film_thickness_m()
                .unwrap()
        };
        let f = PointFilmInputs::from_contact(&h, 163.7, 0.08, 2e-8, 29.8);
        assert_eq!(f.reduced_radius_rolling_m, 1.0 / c.rolling_per_m);
        assert!(rel(f.ellipticity, 8.6986) < 1e-4);
        // By hand with α = 2e-8: E′ = 2.28571e11, U = 0.08·29.8/(2.28571e11·5.376e-3)
        // = 1.94010e-9, G = 4571.43, W = 163.7/(2.28571e11·5.376e-3²) = 2.47804e-5,
        // H_c = 2.69·U^0.67·G^0.53·W^−0.067·(1 − 0.61e^{−6.35}) = 6.9275e-4
        // → h_c = 3.724 µm (0.1 %).
        let h2 = film(2e-8);
        assert!(rel(h2, 3.724e-6) < 1e-3, "h_c = {h2}");
        // The printed 2.6 µm is matched only with α = 1.0e-8 1/Pa (G = 2286): 2.579 µm,
        // within 1 % of 2.6 (printed to two figures: test 2 %). With the printed
        // α = 2.0e-8 the formula gives 43 % more. So either the α of the film
        // calculation was 1e-8 (the low end of Chen's own 0.01–0.02 mm²/N) or the "2.0"
        // is a misprint; we cannot tell which from the text.
        let h1 = film(1e-8);
        assert!(rel(h1, 2.6e-6) < 0.02, "h_c = {h1}");
        assert!(h2 / 2.6e-6 > 1.4);
    }

    #[test]
    fn hamrock_dowson_ellipticity_close_to_exact() {
        // k ≈ 1.03·(R_y/R_x)^0.64 against the exact κ of `point`: measured worst (here
        // and with mpmath) 2.32 % over 3 ≤ R_y/R_x ≤ 30 and 7.91 % over 1 … 100, both at
        // the upper end. Bands 2.4 % and 8 %.
        for (lo, hi, band) in [(3.0f64, 30.0, 0.024), (1.0, 100.0, 0.08)] {
            let mut worst = 0.0f64;
            for i in 0..=100 {
                let ratio = lo * (hi / lo).powf(i as f64 / 100.0);
                let c = CurvatureSum::new(ratio, 1.0).unwrap();
                let h = HertzPointContact::new(c, 1e11, HertzMethod::Exact).unwrap();
                let k = hamrock_dowson_ellipticity(1.0, ratio).unwrap();
                worst = worst.max(rel(k, h.shape().ellipticity));
            }
            assert!(
                worst < band && worst > band - 0.005,
                "[{lo}, {hi}]: {worst}"
            );
        }
        assert!(hamrock_dowson_ellipticity(0.0, 1.0).is_err());
        assert!(hamrock_dowson_ellipticity(f64::NAN, 1.0).is_err());
    }

    #[test]
    fn from_contact_with_major_axis_along_rolling() {
        // A wide wheel: major axis along rolling ⇒ k = a_transverse/b_rolling = 1/κ < 1.
        let wheel = PrincipalRadii {
            rolling_m: 0.4,
            transverse_m: 0.05,
        };
        let rail = PrincipalRadii {
            rolling_m: f64::INFINITY,
            transverse_m: 0.3,
        };
        let h = HertzPointContact::from_radii(
            wheel,
            rail,
            2.1e11,
            0.3,
            2.1e11,
            0.3,
            HertzMethod::Exact,
        )
        .unwrap();
        let f = PointFilmInputs::from_contact(&h, 1e5, 0.05, 2e-8, 10.0);
        assert!(f.ellipticity < 1.0);
        assert!(rel(f.ellipticity * h.shape().ellipticity, 1.0) < 1e-15);
        assert!(rel(f.reduced_radius_rolling_m, 0.4) < 1e-15);
        assert!(f.central_film_thickness_m().unwrap() > 0.0);
    }

    #[test]
    fn invalid_inputs_are_typed_errors() {
        let base = hand_case();
        let cases = [
            PointFilmInputs {
                load_n: 0.0,
                ..base
            },
            PointFilmInputs {
                load_n: -1.0,
                ..base
            },
            PointFilmInputs {
                viscosity_pa_s: -1.0,
                ..base
            },
            PointFilmInputs {
                reduced_radius_rolling_m: 0.0,
                ..base
            },
            PointFilmInputs {
                ellipticity: 0.0,
                ..base
            },
            PointFilmInputs {
                effective_modulus_pa: -2e11,
                ..base
            },
        ];
        for c in cases {
            assert!(matches!(
                c.central_film_thickness_m(),
                Err(FilmError::InvalidInput(_))
            ));
        }
        let nan = PointFilmInputs {
            pressure_viscosity_pa_inv: f64::NAN,
            ..base
        };
        assert!(matches!(
            nan.minimum_film_thickness_m(),
            Err(FilmError::NonFinite(_))
        ));
    }

    proptest! {
        #[test]
        fn film_is_finite_positive_and_monotone(
            eta in 1e-3f64..1.0,
            alpha in 5e-9f64..4e-8,
            u in 0.01f64..50.0,
            rx in 1e-3f64..0.1,
            q in 1.0f64..1e5,
            k in 1.0f64..8.0,
        ) {
            let f = PointFilmInputs {
                viscosity_pa_s: eta,
                pressure_viscosity_pa_inv: alpha,
                entrainment_speed_m_s: u,
                reduced_radius_rolling_m: rx,
                load_n: q,
                effective_modulus_pa: 2.2e11,
                ellipticity: k,
            };
            let (hc, hm) = (f.central_film_thickness_m().unwrap(), f.minimum_film_thickness_m().unwrap());
            prop_assert!(hc.is_finite() && hc > 0.0 && hm.is_finite() && hm > 0.0);
            let faster = PointFilmInputs { entrainment_speed_m_s: 1.1 * u, ..f };
            let heavier = PointFilmInputs { load_n: 1.1 * q, ..f };
            prop_assert!(faster.central_film_thickness_m().unwrap() > hc);
            prop_assert!(heavier.central_film_thickness_m().unwrap() < hc);
            prop_assert!(heavier.minimum_film_thickness_m().unwrap() < hm);
        }

        #[test]
        fn arbitrary_film_inputs_never_panic(x in proptest::array::uniform7(any::<f64>())) {
            let f = PointFilmInputs {
                viscosity_pa_s: x[0],
                pressure_viscosity_pa_inv: x[1],
                entrainment_speed_m_s: x[2],
                reduced_radius_rolling_m: x[3],
                load_n: x[4],
                effective_modulus_pa: x[5],
                ellipticity: x[6],
            };
            let _ = f.central_film_thickness_m();
            let _ = f.minimum_film_thickness_m();
        }
    }
}
