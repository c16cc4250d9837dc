//! ISO 281:2007 ratings of single-direction thrust ball bearings (nominal contact angle
//! α > 45°, issue 28 item 1): the basic dynamic axial load rating C_a (§6.2, f_c of
//! Table 4), the equivalent dynamic axial load P_a (Table 5), and ISO 76's basic static
//! axial rating C_0a from the contact stress that defines it. ISO 281 rates a bearing with
//! α ≤ 45° as radial (C_r, [`super::life_point::iso_radial_rating`]) and one with α > 45°
//! as a thrust bearing, whatever its rings look like.
//!
//! **f_c.** Table 4 lists f_c at α = 45°, 60°, 75° (against D_w·cos α/D_pw) and 90°
//! (against D_w/D_pw) only. Every entry of it is, to its printed rounding, the closed form
//! of ISO/TR 1281-1 for thrust ball bearings
//!
//! - α ≠ 90°: f_c = 270·η·γ^0.3·(1 − γ)^1.39·(1 + γ)^(−1/3)·{1 + [(1 − γ)/(1 + γ)]^(1.72·10/3)}^(−0.3),
//!   γ = D_w·cos α/D_pw,
//! - α = 90°:  f_c = 270·η·γ^0.3·2^(−0.3), γ = D_w/D_pw (both washers alike),
//!
//! with η = 1 − (sin α)/3, the reduction for a thrust bearing's contact angle (the α ≠ 90°
//! form's (1 − γ)/(1 + γ) terms are Lundberg–Palmgren's inner/outer conformity of the two
//! washers, the 1.72 exponent the radial ball form's 1.39 + 1/3). The tests check all 94
//! entries of Table 4 against this form (within 0.15 %, the table's 0.1 rounding at its
//! smallest entries), so the form is the table where the table has a column and the same
//! law between its columns, where the standard gives no number. γ outside Table 4's
//! 0.01–0.35 is refused (the standard gives no f_c there).
//!
//! **P_a, Table 5** (single direction): P_a = X·F_r + Y·F_a for F_a/F_r > e with
//! X = 1.25·tan α·(1 − (2/3)·sin α), Y = 1, e = 1.25·tan α (the table's 45°–85° rows are
//! these formulas rounded; tested); the table gives no factors for F_a/F_r ≤ e (a
//! single-direction thrust bearing is not suited to that load) and α = 90° carries no radial
//! load (P_a = F_a): both are refused with a sentence.
//!
//! **C_0a, ISO 76** for α ≠ 90°: C_0a = Z·Q_0·sin α, Q_0 the ball load that brings the
//! more heavily stressed (shaft-washer) contact to 4 200 MPa: under a centric axial load
//! every ball carries F_a/(Z·sin α), so the bearing reaches 4 200 MPa at F_a = Z·Q_0·sin α.
//! Computed from the bearing's own conformity, as the radial ball's C_0r is.
//!
//! **Not checked against the primary text** (no copy at hand): Table 4 and Table 5 were
//! typed from secondary sources (a public transcription of Table 4, bearing catalogues for
//! Table 5) and agree with the forms above, which is what the tests pin.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use super::life_point::{iso_axial_rating_with, LifePointError};
use super::rating::EquivalentLoad;

/// b_m of thrust ball bearings (ISO 281:2007 Table 1), dimensionless.
pub const ISO_BM_THRUST_BALL: f64 = 1.3;

/// The smallest and largest γ of ISO 281 Table 4 (over its columns).
pub const TABLE4_GAMMA_RANGE: (f64, f64) = (0.01, 0.35);

/// α within this of 90° uses the α = 90° forms, rad.
const RIGHT_ANGLE_TOL_RAD: f64 = 1e-9;

fn is_right_angle(contact_angle_rad: f64) -> bool {
    (std::f64::consts::FRAC_PI_2 - contact_angle_rad).abs() <= RIGHT_ANGLE_TOL_RAD
}

/// A thrust ball bearing's contact angle: (45°, 90°]. ISO 281 rates α ≤ 45° as radial.
fn check_thrust_angle(contact_angle_rad: f64) -> Result<f64, String> {
    let deg = contact_angle_rad.to_degrees();
    if contact_angle_rad.is_finite()
        && deg > 45.0
        && contact_angle_rad <= std::f64::consts::FRAC_PI_2 + RIGHT_ANGLE_TOL_RAD
    {
        Ok(contact_angle_rad)
    } else {
        Err(format!(
            "nominal contact angle {deg:.3}° is not a thrust ball bearing's (45° < α ≤ 90°, ISO 281 §6.2)"
        ))
    }
}

/// Table 4's abscissa γ: D_w·cos α/D_pw, or D_w/D_pw at α = 90°, dimensionless.
pub fn table4_gamma(contact_angle_rad: f64, ball_diameter_m: f64, pitch_diameter_m: f64) -> f64 {
    let c = if is_right_angle(contact_angle_rad) {
        1.0
    } else {
        contact_angle_rad.cos()
    };
    ball_diameter_m * c / pitch_diameter_m
}

/// f_c of ISO 281 Table 4 (single-row thrust ball bearings), N·mm^(−1.8), by the closed
/// form behind the table (module notes) at the contact angle α (rad, 45° < α ≤ 90°) and
/// Table 4's γ ([`table4_gamma`]). `Err` (a sentence with the numbers) outside the table.
pub fn iso_fc_thrust_ball(contact_angle_rad: f64, gamma: f64) -> Result<f64, String> {
    let a = check_thrust_angle(contact_angle_rad)?;
    let (lo, hi) = TABLE4_GAMMA_RANGE;
    if !(gamma.is_finite() && gamma >= lo - 1e-12 && gamma <= hi + 1e-12) {
        return Err(format!(
            "D_w·cos α/D_pw = {gamma:.4} is outside ISO 281 Table 4 ({lo}–{hi}): no f_c"
        ));
    }
    let eta = 1.0 - a.sin() / 3.0;
    let shape = if is_right_angle(a) {
        2f64.powf(-0.3)
    } else {
        let ratio = (1.0 - gamma) / (1.0 + gamma);
        (1.0 - gamma).powf(1.39)
            * (1.0 + gamma).powf(-1.0 / 3.0)
            * (1.0 + ratio.powf(1.72 * 10.0 / 3.0)).powf(-0.3)
    };
    Ok(270.0 * eta * gamma.powf(0.3) * shape)
}

/// ISO 281 §6.2 basic dynamic axial load rating C_a of a single-row, single-direction
/// thrust ball bearing, N: b_m = 1.3, f_c of Table 4 ([`iso_fc_thrust_ball`]) and
/// [`iso_axial_rating_with`]'s formula (Z balls of diameter D_w, m; D_pw, m; α, rad).
pub fn iso_thrust_rating(
    contact_angle_rad: f64,
    ball_count: usize,
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
) -> Result<f64, String> {
    let gamma = table4_gamma(contact_angle_rad, ball_diameter_m, pitch_diameter_m);
    let fc = iso_fc_thrust_ball(contact_angle_rad, gamma)?;
    // α within 1e-9 of 90° is 90°: iso_axial_rating_with takes the α = 90° form only within
    // 1e-12, so pass exactly π/2 there.
    let a = if is_right_angle(contact_angle_rad) {
        std::f64::consts::FRAC_PI_2
    } else {
        contact_angle_rad
    };
    iso_axial_rating_with(ISO_BM_THRUST_BALL, fc, a, ball_count, ball_diameter_m)
        .map_err(|e: LifePointError| format!("ISO 281 C_a: {e}"))
}

/// ISO 281 §6.2 equivalent dynamic axial load P_a of a single-direction thrust ball
/// bearing, N (Table 5, module notes). `Err` (a sentence with the numbers) where the
/// standard gives no factors: F_a/F_r ≤ e, or a radial load on an α = 90° bearing.
pub fn equivalent_load_thrust_ball(
    radial_n: f64,
    axial_n: f64,
    contact_angle_rad: f64,
) -> Result<EquivalentLoad, String> {
    let a = check_thrust_angle(contact_angle_rad)?;
    let fa = axial_n.abs();
    // A solved equilibrium's radial force under a pure axial load is round-off (≈ 1e-12 of
    // F_a), not a radial load: below 1e-9·F_a it counts as none.
    let fr = if radial_n.abs() <= 1e-9 * fa {
        0.0
    } else {
        radial_n.abs()
    };
    if is_right_angle(a) {
        if fr > 0.0 {
            return Err(format!(
                "a thrust ball bearing with α = 90° carries no radial load (F_r = {fr:.1} N): ISO 281 gives no P_a"
            ));
        }
        return Ok(EquivalentLoad {
            load_n: fa,
            x: 0.0,
            y: 1.0,
            e: f64::INFINITY,
        });
    }
    let e = 1.25 * a.tan();
    let x = e * (1.0 - 2.0 / 3.0 * a.sin());
    let above = if fr > 0.0 { fa / fr > e } else { fa > 0.0 };
    if !above && fr > 0.0 {
        return Err(format!(
            "F_a/F_r = {:.3} ≤ e = {e:.3}: ISO 281 Table 5 gives no factors for a single-direction thrust ball bearing under this load (it is not suited to it)",
            fa / fr
        ));
    }
    Ok(EquivalentLoad {
        load_n: x * fr + fa,
        x,
        y: 1.0,
        e,
    })
}

/// ISO 76's basic static axial rating C_0a of a single-direction thrust ball bearing from
/// the contact stress that defines it, N: Z·Q_0·sin α with Q_0 = Q₁·(4 200 MPa/p₀)³ from the
/// caller's Hertz pressure p₀ at one ball load Q₁ (`inner_pressure_per_load` = (Q₁ N,
/// p₀ Pa)) at the more heavily stressed contact. `None` when that pressure is not positive.
pub fn static_axial_rating_ball(
    ball_count: usize,
    contact_angle_rad: f64,
    inner_pressure_per_load: (f64, f64),
) -> Option<f64> {
    let q0 = super::rating::ball_load_at_iso76_stress(inner_pressure_per_load)?;
    let c0 = ball_count as f64 * q0 * contact_angle_rad.sin();
    (c0.is_finite() && c0 > 0.0).then_some(c0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ISO 281:2007 Table 4, f_c of single-row thrust ball bearings, column by column:
    /// (α°, values at γ = 0.01, 0.02, … in steps of 0.01). Typed from a public
    /// transcription and from memory of the standard, which agree (module notes).
    const TABLE4: [(f64, &[f64]); 4] = [
        (
            45.0,
            &[
                42.1, 51.7, 58.2, 63.3, 67.3, 70.7, 73.5, 75.9, 78.0, 79.7, 81.1, 82.3, 83.3, 84.1,
                84.7, 85.1, 85.4, 85.5, 85.5, 85.4, 85.2, 84.9, 84.5, 84.0, 83.4, 82.8, 82.0, 81.3,
                80.4, 79.6,
            ],
        ),
        (
            60.0,
            &[
                39.2, 48.1, 54.2, 58.9, 62.6, 65.8, 68.4, 70.7, 72.6, 74.2, 75.5, 76.6, 77.5, 78.3,
                78.8, 79.2, 79.5, 79.6, 79.6, 79.5,
            ],
        ),
        (
            75.0,
            &[37.3, 45.9, 51.7, 56.1, 59.7, 62.7, 65.2, 67.3, 69.2, 70.7],
        ),
        (
            90.0,
            &[
                36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3, 75.4, 77.4, 79.3, 81.1,
                82.7, 84.4, 85.9, 87.4, 88.8, 90.2, 91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8,
                100.8, 101.9, 102.9, 103.9, 104.8, 105.8,
            ],
        ),
    ];

    /// The closed form reproduces all 94 entries of Table 4 to the table's rounding: half a
    /// unit of its last digit (0.05) plus 0.05 % (the form's fitted constants), so a typo
    /// in the transcription or in the form fails here. 45° is a thrust column of Table 4
    /// although the rating code refuses α = 45° (radial by §6.1): checked through the form
    /// at 45° + 1e-9.
    #[test]
    fn closed_form_reproduces_every_entry_of_table_4() {
        let mut worst: f64 = 0.0;
        for (deg, col) in TABLE4 {
            let a = (deg + if deg == 45.0 { 1e-9 } else { 0.0 }).to_radians();
            for (k, &tab) in col.iter().enumerate() {
                let g = 0.01 * (k + 1) as f64;
                let f = iso_fc_thrust_ball(a, g).unwrap();
                let err = (f - tab).abs();
                assert!(
                    err <= 0.05 + 5e-4 * tab,
                    "α {deg}°, γ {g:.2}: form {f:.3} vs Table 4 {tab}"
                );
                worst = worst.max(err / tab);
            }
        }
        // The form is not loose either: its worst entry is within 0.15 %.
        assert!(worst < 1.5e-3, "worst {worst}");
    }

    /// Table 5 (single direction, F_a/F_r > e), as printed in bearing catalogues:
    /// (α°, X, e). The formulas reproduce each to its printed rounding.
    #[test]
    fn table_5_factors_are_the_formulas() {
        let rows = [
            (50.0, 0.73, 1.49),
            (55.0, 0.81, 1.79),
            (60.0, 0.92, 2.17),
            (65.0, 1.06, 2.68),
            (70.0, 1.28, 3.43),
            (75.0, 1.66, 4.67),
            (80.0, 2.43, 7.09),
            (85.0, 4.80, 14.29),
        ];
        for (deg, x_tab, e_tab) in rows {
            let p = equivalent_load_thrust_ball(1.0, 1e6, f64::to_radians(deg)).unwrap();
            assert!(
                (p.x - x_tab).abs() <= 0.0051,
                "α {deg}: X {} vs {x_tab}",
                p.x
            );
            assert!(
                (p.e - e_tab).abs() <= 0.0051,
                "α {deg}: e {} vs {e_tab}",
                p.e
            );
            assert_eq!(p.y, 1.0);
            assert!((p.load_n - (p.x + 1e6)).abs() < 1e-6);
        }
    }

    #[test]
    fn thrust_loads_outside_table_5_are_refused_with_numbers() {
        let a60 = 60f64.to_radians();
        let e = equivalent_load_thrust_ball(1000.0, 1000.0, a60).unwrap_err();
        assert!(e.contains("1.000") && e.contains("2.165"), "{e}");
        let e = equivalent_load_thrust_ball(10.0, 1000.0, std::f64::consts::FRAC_PI_2).unwrap_err();
        assert!(e.contains("90°") && e.contains("10.0 N"), "{e}");
        // Pure axial: P_a = F_a at every thrust angle.
        for deg in [50.0, 60.0, 90.0] {
            let p = equivalent_load_thrust_ball(0.0, 1234.5, f64::to_radians(deg)).unwrap();
            assert_eq!(p.load_n, 1234.5);
            // An equilibrium's round-off radial force is no radial load.
            let p = equivalent_load_thrust_ball(1e-9, 1234.5, f64::to_radians(deg)).unwrap();
            assert_eq!(p.load_n, 1234.5);
        }
        // α ≤ 45° is radial.
        assert!(equivalent_load_thrust_ball(0.0, 1.0, 45f64.to_radians()).is_err());
    }

    /// C_a by hand for Chen's Bearing B geometry (Z 20, D_w 12 mm, D_pw 115 mm, α 60°):
    /// γ = 12·cos 60°/115 = 0.052174, f_c by Table 4 linear between 0.05 (62.6) and 0.06
    /// (65.8) = 63.296; C_a = 1.3·63.296·0.5^0.7·tan 60°·20^(2/3)·12^1.8 = 56 629 N. The form
    /// gives 63.37 there (56 698 N): linear interpolation between two rows cuts under a
    /// concave f_c(γ) by up to 0.12 % over a 0.01 step plus the table's rounding, hence 2e-3.
    #[test]
    fn chen_b_rating_by_hand() {
        let a = 60f64.to_radians();
        let ca = iso_thrust_rating(a, 20, 0.012, 0.115).unwrap();
        let g: f64 = 12.0 * 0.5 / 115.0;
        let fc_tab = 62.6 + (g - 0.05) / 0.01 * (65.8 - 62.6);
        let by_hand =
            1.3 * fc_tab * 0.5f64.powf(0.7) * a.tan() * 20f64.powf(2.0 / 3.0) * 12f64.powf(1.8);
        assert!((ca - by_hand).abs() / by_hand < 2e-3, "{ca} vs {by_hand}");
        assert!((by_hand - 56_629.0).abs() < 1.0, "{by_hand}");
    }

    /// At α = 90° the 90° form (no cos α): C_a = b_m·f_c·Z^(2/3)·D_w^1.8 with γ = D_w/D_pw,
    /// and the α → 90° limit of the general form is continuous in f_c·(cos α)^0.7·tan α only
    /// through Table 4's change of abscissa, so the two are checked separately: here the 90°
    /// value against the table (γ = 0.10: 73.3).
    #[test]
    fn right_angle_uses_the_90_degree_form() {
        let ca = iso_thrust_rating(std::f64::consts::FRAC_PI_2, 15, 0.010, 0.100).unwrap();
        let by_hand = 1.3 * 73.3 * 15f64.powf(2.0 / 3.0) * 10f64.powf(1.8);
        assert!((ca - by_hand).abs() / by_hand < 1e-3, "{ca} vs {by_hand}");
    }

    #[test]
    fn outside_the_table_is_refused() {
        let a = 60f64.to_radians();
        assert!(iso_fc_thrust_ball(a, 0.005)
            .unwrap_err()
            .contains("Table 4"));
        assert!(iso_fc_thrust_ball(a, 0.5).is_err());
        assert!(iso_fc_thrust_ball(30f64.to_radians(), 0.05).is_err());
        assert!(iso_fc_thrust_ball(f64::NAN, 0.05).is_err());
    }

    /// C_0a = Z·Q_0·sin α: at the load F_a = C_0a every ball carries Q_0 (pure axial), whose
    /// stress is 4 200 MPa by construction (p ∝ Q^(1/3)).
    #[test]
    fn static_rating_brings_the_contact_to_4200_mpa() {
        let (q1, p1) = (1000.0, 2.0e9);
        let a = 60f64.to_radians();
        let c0 = static_axial_rating_ball(20, a, (q1, p1)).unwrap();
        let q = c0 / (20.0 * a.sin());
        let p = p1 * (q / q1).powf(1.0 / 3.0);
        assert!((p - 4.2e9).abs() / 4.2e9 < 1e-12);
        assert!(static_axial_rating_ball(20, a, (0.0, p1)).is_none());
    }
}
