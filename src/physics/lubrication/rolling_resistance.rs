//! EHL rolling resistance: the force the pressure build-up in a lubricated contact's
//! inlet opposes to rolling, and the power it dissipates, SI.
//!
//! - **Line contact** (Goksem & Hargreaves 1978, as quoted by Harris & Kotzalas,
//!   *Rolling Bearing Analysis*, 5th ed., vol. 2, §5 on friction):
//!   F_R = 4.318·(G·U)^0.658·W^0.0126·R·l/α with U = η₀|u|/(E′R), G = αE′,
//!   W = w/(E′R) (w the load per unit length, R the reduced radius in the rolling
//!   direction). The power is F_R·|u| (u the entrainment speed: the inlet's pressure
//!   field moves with the rolling, the surfaces through it).
//! - **Point contact by strips**: the Hertz ellipse (transverse semi-axis a, rolling
//!   semi-axis b, p₀) cut into strips dy across the transverse direction. A strip at y
//!   carries w(y) = ∫p dx = (π/2)·p₀·b·(1 − y²/a²) = w₀·(1 − y²/a²), w₀ = 3Q/(4a)
//!   (∫w dy = Q, tested), and has the contact's R_x and u; each strip is a line contact,
//!   so F_R = F_R,line(w₀, l = 1)·a·∫₋₁¹(1 − s²)^0.0126 ds, the integral in closed form
//!   √π·Γ(1.0126)/Γ(1.5126) (checked against a quadrature). This is the strip theory
//!   of the line formula; side leakage, which the line formula lacks, is not modelled
//!   (it lowers the inlet pressure of a short ellipse: an upper estimate for k < 3).
//!
//! The formula needs α > 0 (it divides by α: the fit's G ranges over real oils); with
//! α = 0, no rolling speed or no load there is no resistance to compute and the
//! functions answer `None`, never a made-up zero.

use super::film::FilmInputs;

/// Goksem–Hargreaves exponent of the load group W.
const LOAD_EXPONENT: f64 = 0.0126;

/// Goksem–Hargreaves EHL rolling resistance of a line contact of length `length_m`, N:
/// F_R = 4.318·(G·U)^0.658·W^0.0126·R·l/α. `None` for an unloaded, non-rolling or
/// invalid contact, or α ≤ 0 (outside the fit).
pub fn line_force_n(inputs: &FilmInputs, length_m: f64) -> Option<f64> {
    let g = inputs.groups()?;
    let gu = g.material * g.speed;
    let alpha = inputs.pressure_viscosity_pa_inv;
    if !(gu > 0.0 && alpha > 0.0 && length_m >= 0.0) {
        return None;
    }
    Some(
        4.318 * gu.powf(0.658) * g.load.powf(LOAD_EXPONENT) * inputs.reduced_radius_m * length_m
            / alpha,
    )
}

/// ∫₋₁¹(1 − s²)^m ds = √π·Γ(m + 1)/Γ(m + 3/2): the strip load law's weight.
fn strip_integral(m: f64) -> f64 {
    std::f64::consts::PI.sqrt() * libm::tgamma(m + 1.0) / libm::tgamma(m + 1.5)
}

/// EHL rolling resistance of an elliptical (point) contact by strips of the line
/// formula, N (module docs): `inputs` carry η₀, α, the entrainment speed, R_x and E′
/// with `load_per_length_n_m` ignored; `load_n` Q and `transverse_semi_axis_m` a give
/// the strips' loads w(y) = 3Q/(4a)·(1 − y²/a²). `None` as [`line_force_n`].
pub fn point_force_n(inputs: &FilmInputs, load_n: f64, transverse_semi_axis_m: f64) -> Option<f64> {
    let a = transverse_semi_axis_m;
    if !(a > 0.0 && a.is_finite() && load_n > 0.0) {
        return None;
    }
    let centre = FilmInputs {
        load_per_length_n_m: 0.75 * load_n / a,
        ..*inputs
    };
    Some(line_force_n(&centre, 1.0)? * a * strip_integral(LOAD_EXPONENT))
}

/// Power of a rolling resistance force `force_n` at the entrainment speed, W: F_R·|u|.
pub fn power_w(force_n: f64, entrainment_speed_m_s: f64) -> f64 {
    force_n * entrainment_speed_m_s.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    fn inputs() -> FilmInputs {
        // A ball–inner-race contact of a 7018-size bearing at 9 500 rpm in SAE 30.
        FilmInputs {
            viscosity_pa_s: 0.071,
            pressure_viscosity_pa_inv: 1.5e-8,
            entrainment_speed_m_s: 25.0,
            reduced_radius_m: 6e-3,
            load_per_length_n_m: 0.0,
            effective_modulus_pa: 2.3e11,
        }
    }

    /// The closed form of the strip weight against a midpoint quadrature of
    /// ∫cos^(2m+1)θ dθ (s = sin θ removes the end singularity of the derivative),
    /// 200 000 nodes: agreement to 1e-10; and the known values m = 0 → 2, m = 1 → 4/3.
    #[test]
    fn strip_integral_closed_form() {
        let n = 200_000;
        let h = std::f64::consts::PI / n as f64;
        let q: f64 = (0..n)
            .map(|i| {
                let t = -std::f64::consts::FRAC_PI_2 + (i as f64 + 0.5) * h;
                t.cos().powf(2.0 * LOAD_EXPONENT + 1.0) * h
            })
            .sum();
        assert!(rel(strip_integral(LOAD_EXPONENT), q) < 1e-10);
        assert!(rel(strip_integral(0.0), 2.0) < 1e-14);
        assert!(rel(strip_integral(1.0), 4.0 / 3.0) < 1e-14);
    }

    /// Strip theory by brute force: 4 000 strips each given the line formula with its own
    /// w(y) = 3Q/(4a)(1 − y²/a²) (∫w dy = Q to 1e-6, the quadrature's error) add up to
    /// the closed form within 1e-5 (midpoint error at the ends where w → 0).
    #[test]
    fn point_force_is_the_sum_of_its_strips() {
        let (q, a) = (1500.0, 1.8e-3);
        let n = 4000;
        let dy = 2.0 * a / n as f64;
        let (mut f, mut load) = (0.0, 0.0);
        for i in 0..n {
            let y = -a + (i as f64 + 0.5) * dy;
            let w = 0.75 * q / a * (1.0 - (y / a).powi(2));
            load += w * dy;
            let strip = FilmInputs {
                load_per_length_n_m: w,
                ..inputs()
            };
            f += line_force_n(&strip, dy).unwrap();
        }
        assert!(rel(load, q) < 1e-6, "{load}");
        let closed = point_force_n(&inputs(), q, a).unwrap();
        assert!(rel(f, closed) < 1e-5, "{f} vs {closed}");
    }

    /// The fit's scalings: F_R ∝ η₀^0.658·u^0.658 (doubling each multiplies by
    /// 2^0.658), ∝ Q^0.0126 at a fixed a, and the power F_R·|u| ∝ u^1.658.
    #[test]
    fn scalings_of_the_fit() {
        let (q, a) = (1500.0, 1.8e-3);
        let f = point_force_n(&inputs(), q, a).unwrap();
        let eta2 = FilmInputs {
            viscosity_pa_s: 2.0 * inputs().viscosity_pa_s,
            ..inputs()
        };
        assert!(rel(point_force_n(&eta2, q, a).unwrap() / f, 2f64.powf(0.658)) < 1e-12);
        let u2 = FilmInputs {
            entrainment_speed_m_s: 2.0 * inputs().entrainment_speed_m_s,
            ..inputs()
        };
        let f2 = point_force_n(&u2, q, a).unwrap();
        assert!(rel(power_w(f2, 50.0) / power_w(f, 25.0), 2f64.powf(1.658)) < 1e-12);
        assert!(
            rel(
                point_force_n(&inputs(), 2.0 * q, a).unwrap() / f,
                2f64.powf(0.0126)
            ) < 1e-12
        );
    }

    /// No load, no rolling or α = 0: nothing to compute, `None` (never a zero made up).
    #[test]
    fn outside_the_fit_is_none() {
        assert!(point_force_n(&inputs(), 0.0, 1e-3).is_none());
        let still = FilmInputs {
            entrainment_speed_m_s: 0.0,
            ..inputs()
        };
        assert!(point_force_n(&still, 100.0, 1e-3).is_none());
        let no_alpha = FilmInputs {
            pressure_viscosity_pa_inv: 0.0,
            ..inputs()
        };
        assert!(point_force_n(&no_alpha, 100.0, 1e-3).is_none());
    }
}
