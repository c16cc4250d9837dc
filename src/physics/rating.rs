//! ISO 281:2007 ratings and lives shared by every bearing system (issue 28 items 1–2):
//! the basic dynamic radial load rating C_r of roller bearings (the ball form is in
//! [`super::life_point`]), the ISO 76 static radial rating C_0r of roller bearings and of
//! ball bearings (from the contact stress that defines it), the fatigue load limit C_u,
//! the equivalent dynamic load P (X, Y, e), the basic rating life L10 = (C/P)^p, the life
//! modification factor a_ISO of ball and roller bearings, and the static safety s0 from the
//! computed maximum contact stress. No bearing system is known here; SI in, SI out.
//!
//! Sources (equation forms; every table is marked where it could not be checked against
//! the primary text):
//! - ISO 281:2007 §6.1.1 eq. (9) C_r of radial roller bearings, Table 7 f_c, Table 8 b_m
//!   (cylindrical 1.1, tapered 1.1, spherical 1.15); §5.1 / §6.1 equivalent loads with
//!   Table 3 (radial ball) and Table 9 (radial roller: e = 1.5·tan α, X = 0.4,
//!   Y = 0.4·cot α single row; X = 1, Y = 0.45·cot α / X = 0.67, Y = 0.67·cot α double
//!   row); §9 a_ISO (eqs. of Table 13 for radial ball and radial roller bearings).
//! - ISO 281:2007 Annex B.3.2 (simplified C_u): C_u = C_0/22 (ball) and C_0/8.2 (roller)
//!   for D_pw ≤ 100 mm, multiplied by (100/D_pw)^0.5 (ball) and (100/D_pw)^0.3 (roller)
//!   above. **Not checked against the primary text** (recalled; consistent with C_u's
//!   definition, the load at which the contact stress reaches 1 500 MPa: for point
//!   contact (1500/4200)³ = 1/21.95, for line contact (1500/4000)² = 1/7.1, ISO's 8.2
//!   including its profile allowance). Each system's JSON states which value it used.
//! - ISO 76:2006 C_0r of radial roller bearings, 44·(1 − D_we·cos α/D_pw)·i·Z·L_we·D_we·cos α
//!   (N, mm); the reference stresses 4 200 MPa (ball) and 4 000 MPa (roller).
//!
//! **f_c and the Table 3 values are not checked against the primary text** (no copy was
//! at hand): Table 7 as it was typed into the double-row spherical system (moved here),
//! Table 3 as printed in bearing catalogues that reproduce it (NSK, SKF). The
//! continuity of the a_ISO constants at κ = 0.4 and κ = 1 is tested (a typo would break
//! it).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use serde::Serialize;

/// b_m of cylindrical roller bearings (ISO 281:2007 Table 8), dimensionless.
pub const B_M_CYLINDRICAL_ROLLER: f64 = 1.1;
/// b_m of tapered roller bearings (ISO 281:2007 Table 8), dimensionless.
pub const B_M_TAPERED_ROLLER: f64 = 1.1;
/// b_m of spherical roller bearings (ISO 281:2007 Table 8), dimensionless.
pub const B_M_SPHERICAL_ROLLER: f64 = 1.15;

/// Life exponent p of ball bearings in L10 = (C/P)^p (ISO 281 eq. 15).
pub const LIFE_EXPONENT_BALL: f64 = 3.0;
/// Life exponent p of roller bearings in L10 = (C/P)^p (ISO 281 eq. 16).
pub const LIFE_EXPONENT_ROLLER: f64 = 10.0 / 3.0;

/// ISO 76 reference contact stress of ball bearings at C_0, Pa.
pub const ISO76_BALL_STRESS_PA: f64 = 4.2e9;
/// ISO 76 reference contact stress of roller bearings at C_0, Pa.
pub const ISO76_ROLLER_STRESS_PA: f64 = 4.0e9;

/// ISO 281:2007 Table 7, roller bearings: (γ = D_we·cos α/D_pw, f_c in N·mm^(−29/27)…).
const ROLLER_FC_TABLE: [(f64, f64); 30] = [
    (0.01, 52.1),
    (0.02, 60.8),
    (0.03, 66.5),
    (0.04, 70.7),
    (0.05, 74.1),
    (0.06, 76.9),
    (0.07, 79.2),
    (0.08, 81.2),
    (0.09, 82.8),
    (0.10, 84.2),
    (0.11, 85.4),
    (0.12, 86.4),
    (0.13, 87.1),
    (0.14, 87.7),
    (0.15, 88.2),
    (0.16, 88.5),
    (0.17, 88.7),
    (0.18, 88.8),
    (0.19, 88.8),
    (0.20, 88.7),
    (0.21, 88.5),
    (0.22, 88.2),
    (0.23, 87.9),
    (0.24, 87.5),
    (0.25, 87.0),
    (0.26, 86.4),
    (0.27, 85.8),
    (0.28, 85.2),
    (0.29, 84.5),
    (0.30, 83.8),
];

/// f_c of ISO 281:2007 Table 7 (radial roller bearings) at γ = D_we·cos α/D_pw, linear
/// between its rows; `None` outside 0.01 ≤ γ ≤ 0.30.
pub fn iso_fc_radial_roller(gamma: f64) -> Option<f64> {
    ROLLER_FC_TABLE.windows(2).find_map(|w| {
        let ((g0, f0), (g1, f1)) = (w[0], w[1]);
        (gamma >= g0 && gamma <= g1).then(|| f0 + (f1 - f0) * (gamma - g0) / (g1 - g0))
    })
}

/// λ, ISO/TR 1281-1's reduction factor of line contact (edge stresses, non-uniform
/// lamina loads), dimensionless: Table 7's f_c is 0.830 times the Lundberg–Palmgren closed
/// form [`iso_fc_radial_roller_closed_form`] at every row (0.8297–0.8304, tested). The
/// roller systems' reference lives take Lundberg–Palmgren's 552 times b_m·λ, the same
/// factors ISO 281's C_r carries, so that both methods rate an ideal bearing alike.
pub const ISO_LINE_CONTACT_REDUCTION: f64 = 0.83;

/// The Lundberg–Palmgren closed form behind ISO 281 Table 7 without λ, N, mm units
/// (ISO/TR 1281-1): 207.9·γ^(2/9)·(1−γ)^(29/27)/(1+γ)^(1/4)·{1 + [1.04·((1−γ)/(1+γ))^(143/108)]^(9/2)}^(−2/9),
/// with 207.9 = 552·J_r(½)/J_1(½) for line contact (0.2453/0.6515).
pub fn iso_fc_radial_roller_closed_form(gamma: f64) -> f64 {
    let r = 1.04 * ((1.0 - gamma) / (1.0 + gamma)).powf(143.0 / 108.0);
    207.9 * gamma.powf(2.0 / 9.0) * (1.0 - gamma).powf(29.0 / 27.0) / (1.0 + gamma).powf(0.25)
        * (1.0 + r.powf(4.5)).powf(-2.0 / 9.0)
}

/// Roller-set data of the ISO 281 / ISO 76 roller ratings, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerRatingGeometry {
    /// i, number of roller rows.
    pub rows: usize,
    /// Z, rollers per row.
    pub roller_count: usize,
    /// D_we, roller diameter (mean diameter of a tapered roller), m.
    pub roller_diameter_m: f64,
    /// L_we, effective roller length, m.
    pub effective_length_m: f64,
    /// D_pw, pitch diameter, m.
    pub pitch_diameter_m: f64,
    /// α, nominal contact angle from the radial plane, rad.
    pub contact_angle_rad: f64,
}

impl RollerRatingGeometry {
    /// γ = D_we·cos α/D_pw, dimensionless.
    pub fn gamma(&self) -> f64 {
        // In mm, as the rating formula (the same rounding as before it moved here).
        (self.roller_diameter_m * 1e3) * self.contact_angle_rad.cos()
            / (self.pitch_diameter_m * 1e3)
    }
}

/// ISO 281:2007 eq. (9), basic dynamic radial load rating of a radial roller bearing, N:
/// C_r = b_m·f_c·(i·L_we·cos α)^(7/9)·Z^(3/4)·D_we^(29/27) (N, mm). `None` outside
/// Table 7's γ range or for a degenerate geometry.
pub fn iso_radial_rating_roller(b_m: f64, g: &RollerRatingGeometry) -> Option<f64> {
    let (d_mm, l_mm) = (g.roller_diameter_m * 1e3, g.effective_length_m * 1e3);
    let ca = g.contact_angle_rad.cos();
    if !(d_mm > 0.0 && l_mm > 0.0 && ca > 0.0 && g.rows > 0 && g.roller_count > 0) {
        return None;
    }
    let fc = iso_fc_radial_roller(g.gamma())?;
    let c = b_m
        * fc
        * (g.rows as f64 * l_mm * ca).powf(7.0 / 9.0)
        * (g.roller_count as f64).powf(0.75)
        * d_mm.powf(29.0 / 27.0);
    (c.is_finite() && c > 0.0).then_some(c)
}

/// ISO 76:2006 basic static radial load rating of a radial roller bearing, N:
/// C_0r = 44·(1 − D_we·cos α/D_pw)·i·Z·L_we·D_we·cos α (N, mm).
pub fn iso_static_radial_rating_roller(g: &RollerRatingGeometry) -> f64 {
    let ca = g.contact_angle_rad.cos();
    44.0 * (1.0 - g.gamma())
        * g.rows as f64
        * g.roller_count as f64
        * (g.effective_length_m * 1e3)
        * (g.roller_diameter_m * 1e3)
        * ca
}

/// Q_0, the ball load that brings a point contact to ISO 76's 4 200 MPa, N, from the
/// caller's Hertz p₀ at one ball load Q₁ (`(Q₁ N, p₀ Pa)`): p₀ ∝ Q^(1/3), so
/// Q_0 = Q₁·(4200 MPa/p₀)³. `None` when Q₁ or p₀ is not positive. The radial and the thrust
/// (`thrust_ball_rating`) static ratings both start from it.
pub fn ball_load_at_iso76_stress(pressure_per_load: (f64, f64)) -> Option<f64> {
    let (q1, p1) = pressure_per_load;
    (q1 > 0.0 && p1 > 0.0).then(|| q1 * (ISO76_BALL_STRESS_PA / p1).powi(3))
}

/// ISO 76's C_0r of a radial or angular-contact ball bearing from the contact stress that
/// defines it, N: C_0r = Z·i·Q_0·cos α/5, Q_0 the ball load giving 4 200 MPa at the inner
/// contact (Stribeck's Q_max = 5·F_r/(Z·cos α), ISO 76's basis). `inner_pressure_per_load`
/// is the caller's Hertz p₀ at one ball load Q₁ as (Q₁ N, p₀ Pa): p₀ ∝ Q^(1/3), so
/// Q_0 = Q₁·(4200 MPa/p₀)³. Computed from the bearing's own conformity instead of ISO 76's
/// f_0 table (f_0 = C_0r/(i·Z·D_w²·cos α) follows from it).
pub fn static_radial_rating_ball(
    rows: usize,
    ball_count: usize,
    contact_angle_rad: f64,
    inner_pressure_per_load: (f64, f64),
) -> Option<f64> {
    let q0 = ball_load_at_iso76_stress(inner_pressure_per_load)?;
    let c0 = (rows * ball_count) as f64 * q0 * contact_angle_rad.cos() / 5.0;
    (c0.is_finite() && c0 > 0.0).then_some(c0)
}

/// Which ISO 281 family a bearing belongs to (exponents, a_ISO constants, C_u rule).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKind {
    /// Ball bearings: point contact.
    Ball,
    /// Roller bearings: line contact.
    Roller,
}

impl ContactKind {
    /// p of L10 = (C/P)^p.
    pub fn life_exponent(self) -> f64 {
        match self {
            ContactKind::Ball => LIFE_EXPONENT_BALL,
            ContactKind::Roller => LIFE_EXPONENT_ROLLER,
        }
    }

    /// ISO 76's reference contact stress at C_0, Pa.
    pub fn reference_stress_pa(self) -> f64 {
        match self {
            ContactKind::Ball => ISO76_BALL_STRESS_PA,
            ContactKind::Roller => ISO76_ROLLER_STRESS_PA,
        }
    }

    /// k of load ∝ σ^k: 3 for point contact (p₀ ∝ Q^(1/3)), 2 for line contact
    /// (p₀ ∝ w^(1/2)).
    pub fn stress_load_exponent(self) -> f64 {
        match self {
            ContactKind::Ball => 3.0,
            ContactKind::Roller => 2.0,
        }
    }
}

/// ISO 281 Annex B.3.2's simplified fatigue load limit from C_0, N (module notes):
/// C_0/22 (ball) or C_0/8.2 (roller), times (100/D_pw)^0.5 (ball) or (100/D_pw)^0.3
/// (roller) when D_pw > 100 mm.
pub fn fatigue_load_limit_n(kind: ContactKind, static_rating_n: f64, pitch_diameter_m: f64) -> f64 {
    let dpw_mm = pitch_diameter_m * 1e3;
    let (div, exp) = match kind {
        ContactKind::Ball => (22.0, 0.5),
        ContactKind::Roller => (8.2, 0.3),
    };
    let size = if dpw_mm > 100.0 {
        (100.0 / dpw_mm).powf(exp)
    } else {
        1.0
    };
    static_rating_n / div * size
}

/// Static safety factor from the computed maximum contact stress, dimensionless.
///
/// ISO 76 defines s0 = C_0/P_0 with C_0 the load at which the most heavily loaded contact
/// reaches σ_ref (4 200 MPa ball, 4 000 MPa roller). At a given internal load distribution
/// the contact stress grows as load^(1/3) in point contact and load^(1/2) in line contact,
/// so the load that would bring the computed σ_max to σ_ref is (σ_ref/σ_max)^k times the
/// applied one: s0 = (σ_ref/σ_max)^k with k = 3 (point) or 2 (line). (The brief's "(σ_ref/
/// p_max)²" is the line-contact case; a ball bearing takes the cube.) `None` when nothing
/// is loaded (σ_max ≤ 0).
pub fn static_safety(kind: ContactKind, max_contact_stress_pa: f64) -> Option<f64> {
    (max_contact_stress_pa > 0.0 && max_contact_stress_pa.is_finite()).then(|| {
        (kind.reference_stress_pa() / max_contact_stress_pa).powf(kind.stress_load_exponent())
    })
}

/// Basic rating life L10 = (C/P)^p, Mrev (ISO 281 eqs. 15–16). `None` when P ≤ 0.
pub fn basic_l10_mrev(kind: ContactKind, rating_n: f64, equivalent_load_n: f64) -> Option<f64> {
    (equivalent_load_n > 0.0 && rating_n > 0.0)
        .then(|| (rating_n / equivalent_load_n).powf(kind.life_exponent()))
        .filter(|l| l.is_finite())
}

/// The equivalent dynamic load and the factors that made it (ISO 281 §5.1, §6.1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EquivalentLoad {
    /// P, N.
    pub load_n: f64,
    /// X, radial factor.
    pub x: f64,
    /// Y, axial factor.
    pub y: f64,
    /// e, the limiting F_a/F_r.
    pub e: f64,
}

fn xy_load(fr: f64, fa: f64, e: f64, low: (f64, f64), high: (f64, f64)) -> EquivalentLoad {
    // F_a/F_r ≤ e takes the first pair; F_r = 0 with F_a > 0 is "above e".
    let above = if fr > 0.0 { fa / fr > e } else { fa > 0.0 };
    let (x, y) = if above { high } else { low };
    EquivalentLoad {
        load_n: x * fr + y * fa,
        x,
        y,
        e,
    }
}

/// ISO 281 §6.1 equivalent dynamic radial load of a radial roller bearing, N, with α the
/// nominal contact angle and `rows` 1 or 2 (Table 9, module notes). α = 0: P = F_r (the
/// standard's radial roller bearing with α = 0 carries no axial load in its rating; an
/// axial load on ribs is not counted — the caller says so). `None` for rows > 2.
pub fn equivalent_load_radial_roller(
    radial_n: f64,
    axial_n: f64,
    contact_angle_rad: f64,
    rows: usize,
) -> Option<EquivalentLoad> {
    let (fr, fa, a) = (radial_n.abs(), axial_n.abs(), contact_angle_rad);
    if a <= 0.0 {
        return Some(EquivalentLoad {
            load_n: fr,
            x: 1.0,
            y: 0.0,
            e: 0.0,
        });
    }
    let e = 1.5 * a.tan();
    let cot = 1.0 / a.tan();
    match rows {
        1 => Some(xy_load(fr, fa, e, (1.0, 0.0), (0.4, 0.4 * cot))),
        2 => Some(xy_load(fr, fa, e, (1.0, 0.45 * cot), (0.67, 0.67 * cot))),
        _ => None,
    }
}

/// f_0·F_a/C_0r abscissa of ISO 281 Table 3 (single row), N/mm² (= F_a/(i·Z·D_w²·cos α)).
const BALL_T3_X: [f64; 9] = [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89];
/// α = 0 (radial contact): e and Y (X = 0.56).
const BALL_T3_E0: [f64; 9] = [0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44];
const BALL_T3_Y0: [f64; 9] = [2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00];
/// α = 15°: e and Y (X = 0.44).
const BALL_T3_E15: [f64; 9] = [0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56];
const BALL_T3_Y15: [f64; 9] = [1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00];
/// α = 20° … 45° single row (F_a/F_r > e): (α°, e, X, Y).
const BALL_T3_ANGULAR: [(f64, f64, f64, f64); 6] = [
    (20.0, 0.57, 0.43, 1.00),
    (25.0, 0.68, 0.41, 0.87),
    (30.0, 0.80, 0.39, 0.76),
    (35.0, 0.95, 0.37, 0.66),
    (40.0, 1.14, 0.35, 0.57),
    (45.0, 1.34, 0.33, 0.50),
];

fn interp(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    // Clamped at the ends: ISO's first and last rows apply beyond them.
    let n = xs.len();
    if x <= xs[0] {
        return ys[0];
    }
    if x >= xs[n - 1] {
        return ys[n - 1];
    }
    let k = xs.windows(2).position(|w| x <= w[1]).unwrap_or(n - 2);
    let t = (x - xs[k]) / (xs[k + 1] - xs[k]);
    ys[k] + t * (ys[k + 1] - ys[k])
}

/// (e, X, Y above e) of a single-row ball bearing at α (deg) and f_0·F_a/C_0r (N/mm²).
fn ball_table3(alpha_deg: f64, ratio: f64) -> Option<(f64, f64, f64)> {
    let row15 = || {
        (
            interp(&BALL_T3_X, &BALL_T3_E15, ratio),
            0.44,
            interp(&BALL_T3_X, &BALL_T3_Y15, ratio),
        )
    };
    if alpha_deg.abs() < 1e-9 {
        return Some((
            interp(&BALL_T3_X, &BALL_T3_E0, ratio),
            0.56,
            interp(&BALL_T3_X, &BALL_T3_Y0, ratio),
        ));
    }
    if !(15.0..=45.0).contains(&alpha_deg) {
        return None;
    }
    // Between tabulated angles: linear in α (the rows are smooth in α).
    let mut rows: Vec<(f64, f64, f64, f64)> = Vec::with_capacity(7);
    let (e15, x15, y15) = row15();
    rows.push((15.0, e15, x15, y15));
    rows.extend(BALL_T3_ANGULAR);
    let k = rows
        .windows(2)
        .position(|w| alpha_deg <= w[1].0)
        .unwrap_or(rows.len() - 2);
    let (a, b) = (rows[k], rows[k + 1]);
    let t = (alpha_deg - a.0) / (b.0 - a.0);
    Some((
        a.1 + t * (b.1 - a.1),
        a.2 + t * (b.2 - a.2),
        a.3 + t * (b.3 - a.3),
    ))
}

/// ISO 281 §5.1 equivalent dynamic radial load of a single-row radial or angular-contact
/// ball bearing, N (Table 3, module notes): P = F_r for F_a/F_r ≤ e, X·F_r + Y·F_a above;
/// for α = 0 and 15° e and Y depend on f_0·F_a/C_0r = F_a/(Z·D_w²·cos α) (N/mm², D_w in mm),
/// for 20°–45° they are constant; angles between the tabulated ones are interpolated
/// linearly. `Err` (a sentence) for 0 < α < 15° (Table 3's 5° and 10° rows are not
/// transcribed) and for α > 45° (a thrust ball bearing, rated by C_a, not covered).
pub fn equivalent_load_radial_ball(
    radial_n: f64,
    axial_n: f64,
    contact_angle_rad: f64,
    ball_count: usize,
    ball_diameter_m: f64,
) -> Result<EquivalentLoad, String> {
    let (fr, fa) = (radial_n.abs(), axial_n.abs());
    let deg = contact_angle_rad.to_degrees();
    // 15°·π/180 back to degrees is 14.999…: snap within 1e-9° to the whole degree.
    let deg = if (deg - deg.round()).abs() < 1e-9 {
        deg.round()
    } else {
        deg
    };
    let dw_mm = ball_diameter_m * 1e3;
    let ratio = fa / (ball_count as f64 * dw_mm * dw_mm * contact_angle_rad.cos());
    let (e, x, y) = ball_table3(deg, ratio).ok_or_else(|| {
        if deg > 45.0 {
            format!(
                "nominal contact angle {deg:.1}° > 45°: ISO 281 rates this as a thrust ball bearing (C_a, Table 4), not implemented"
            )
        } else {
            format!(
                "nominal contact angle {deg:.1}° is between 0° and 15°: ISO 281 Table 3's 5° and 10° rows are not transcribed"
            )
        }
    })?;
    Ok(xy_load(fr, fa, e, (1.0, 0.0), (x, y)))
}

/// ISO 281:2007 life modification factor a_ISO of radial ball bearings, dimensionless:
/// a_ISO = 0.1·[1 − (2.5671 − c/κ^q)·(e_C·C_u/P)^0.83]^(−9.3) with (c, q) = (2.2649,
/// 0.054381) for 0.1 ≤ κ < 0.4, (1.9987, 0.19087) for 0.4 ≤ κ < 1, (1.9987, 0.071739)
/// for 1 ≤ κ ≤ 4; κ clamped to [0.1, 4], result capped at 50 (as the roller form,
/// [`super::life::a_iso_radial_roller`]). `load_ratio` is e_C·C_u/P.
pub fn a_iso_radial_ball(kappa: f64, load_ratio: f64) -> f64 {
    let kappa = if kappa.is_nan() {
        0.1
    } else {
        kappa.clamp(0.1, 4.0)
    };
    if load_ratio.is_nan() {
        return super::life::A_ISO_MAX;
    }
    let x = load_ratio.max(0.0);
    let (c, q) = if kappa < 0.4 {
        (2.2649, 0.054381)
    } else if kappa < 1.0 {
        (1.9987, 0.19087)
    } else {
        (1.9987, 0.071739)
    };
    let bracket = 1.0 - (2.5671 - c / kappa.powf(q)) * x.powf(0.83);
    if bracket <= 0.0 {
        return super::life::A_ISO_MAX;
    }
    (0.1 * bracket.powf(-9.3)).min(super::life::A_ISO_MAX)
}

/// a_ISO for the bearing family ([`a_iso_radial_ball`] or the roller form).
pub fn a_iso(kind: ContactKind, kappa: f64, load_ratio: f64) -> f64 {
    match kind {
        ContactKind::Ball => a_iso_radial_ball(kappa, load_ratio),
        ContactKind::Roller => super::life::a_iso_radial_roller(kappa, load_ratio),
    }
}

/// ISO 281's contamination factor e_C used where a deck gives none: 0.5, the middle of
/// Table 11's "normal cleanliness" band (0.4–0.6 below d_m = 100 mm; 0.6–0.8 above, 0.5
/// is conservative there). Every system reports the value it used.
pub const DEFAULT_CONTAMINATION_FACTOR: f64 = 0.5;

/// Everything [`iso_life`] reads.
#[derive(Debug, Clone)]
pub struct IsoLifeInputs {
    /// Ball or roller.
    pub kind: ContactKind,
    /// Radial or axial (thrust) ratings: names the ratings in the outputs.
    pub rating_direction: RatingDirection,
    /// C (C_r), N, or why there is none.
    pub rating: Result<f64, String>,
    /// P and its factors, or why there is none.
    pub equivalent_load: Result<EquivalentLoad, String>,
    /// C_0, N (for C_u), or why there is none.
    pub static_rating: Result<f64, String>,
    /// D_pw, m (ν₁ and C_u's size factor).
    pub pitch_diameter_m: f64,
    /// |n_i − n_o|, rpm (ν₁ and hours).
    pub relative_speed_rpm: f64,
    /// ν at the operating temperature, m²/s, or why the system has none (a_ISO absent).
    pub kinematic_viscosity_m2_s: Result<f64, String>,
    /// e_C.
    pub contamination_factor: f64,
    /// The largest contact stress of the solve, Pa (s0).
    pub max_contact_stress_pa: f64,
}

/// Whether the ISO ratings are radial (C_r, C_0r, P_r) or axial (C_a, C_0a, P_a: thrust
/// bearings, ISO 281 §6.2, α > 45° for ball bearings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum RatingDirection {
    /// C_r, C_0r, P_r.
    #[default]
    Radial,
    /// C_a, C_0a, P_a.
    Axial,
}

impl RatingDirection {
    /// The rating's subscript in the text ("r" or "a").
    pub fn subscript(self) -> &'static str {
        match self {
            RatingDirection::Radial => "r",
            RatingDirection::Axial => "a",
        }
    }
}

/// ISO 281 / ISO 76 outputs of one solve (JSON names are a contract). Absent numbers are
/// `None` (null) with a sentence in `reasons`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IsoLife {
    /// Radial (C_r, C_0r, P_r) or axial (C_a, C_0a, P_a) ratings; JSON `rating_direction`.
    pub rating_direction: RatingDirection,
    /// C_r (or C_a where `rating_direction` is axial), N.
    pub basic_dynamic_rating_n: Option<f64>,
    /// C_0r (or C_0a), N.
    pub basic_static_rating_n: Option<f64>,
    /// P, N.
    pub equivalent_load_n: Option<f64>,
    /// X, Y, e of P.
    pub equivalent_load_factors: Option<EquivalentLoad>,
    /// L10 = (C/P)^p, Mrev.
    pub basic_l10_mrev: Option<f64>,
    /// L10 in hours at the relative ring speed, h.
    pub basic_l10_h: Option<f64>,
    /// ν₁ (ISO 281 reference viscosity), m²/s.
    pub reference_viscosity_m2_s: Option<f64>,
    /// κ = ν/ν₁ clamped to [0.1, 4] (the value a_ISO used).
    pub kappa: Option<f64>,
    /// e_C used.
    pub contamination_factor: f64,
    /// C_u, N (ISO 281 Annex B.3.2's simplified form from C_0).
    pub fatigue_load_limit_n: Option<f64>,
    /// a_ISO.
    pub a_iso: Option<f64>,
    /// L10m = a_ISO·L10, Mrev.
    pub modified_l10_mrev: Option<f64>,
    /// L10m in hours, h.
    pub modified_l10_h: Option<f64>,
    /// s0 from the maximum contact stress ([`static_safety`]).
    pub static_safety: Option<f64>,
    /// Why a value above is absent, one sentence each.
    pub reasons: Vec<String>,
}

/// Hours of a life in Mrev at a speed in rpm: 10⁶·L/(60·n). `None` at rest.
pub fn hours(life_mrev: Option<f64>, speed_rpm: f64) -> Option<f64> {
    let n = speed_rpm.abs();
    life_mrev
        .filter(|_| n > 0.0 && n.is_finite())
        .map(|l| l * 1e6 / (60.0 * n))
}

/// Chains the ratings, P, L10, κ, C_u, a_ISO and s0 of [`IsoLifeInputs`].
pub fn iso_life(inp: &IsoLifeInputs) -> IsoLife {
    let mut reasons = Vec::new();
    let c = inp.rating.clone().map_err(|e| reasons.push(e)).ok();
    let p = inp
        .equivalent_load
        .clone()
        .map_err(|e| reasons.push(e))
        .ok();
    let c0 = inp.static_rating.clone().map_err(|e| reasons.push(e)).ok();
    let basic = match (c, p) {
        (Some(c), Some(p)) => basic_l10_mrev(inp.kind, c, p.load_n),
        _ => None,
    };
    if basic.is_none() && c.is_some() && p.is_some() {
        reasons.push("no equivalent load (P = 0): the basic life is unbounded".into());
    }
    let nu1 =
        super::life::iso_reference_viscosity_m2_s(inp.relative_speed_rpm, inp.pitch_diameter_m);
    let nu1 = nu1.is_finite().then_some(nu1);
    let cu = c0.map(|c0| fatigue_load_limit_n(inp.kind, c0, inp.pitch_diameter_m));
    let (kappa, a) = match (&inp.kinematic_viscosity_m2_s, nu1) {
        (Ok(nu), Some(nu1)) => {
            let k = super::life::iso_viscosity_ratio(*nu, nu1);
            let a = match (cu, p) {
                (Some(cu), Some(p)) if p.load_n > 0.0 => {
                    Some(a_iso(inp.kind, k, inp.contamination_factor * cu / p.load_n))
                }
                _ => None,
            };
            (Some(k), a)
        }
        (Err(e), _) => {
            reasons.push(e.clone());
            (None, None)
        }
        (Ok(_), None) => {
            reasons.push("the rings do not turn relative to each other: no κ, no a_ISO".into());
            (None, None)
        }
    };
    let modified = basic.zip(a).map(|(l, a)| l * a);
    IsoLife {
        rating_direction: inp.rating_direction,
        basic_dynamic_rating_n: c,
        basic_static_rating_n: c0,
        equivalent_load_n: p.map(|p| p.load_n),
        equivalent_load_factors: p,
        basic_l10_mrev: basic,
        basic_l10_h: hours(basic, inp.relative_speed_rpm),
        reference_viscosity_m2_s: nu1,
        kappa,
        contamination_factor: inp.contamination_factor,
        fatigue_load_limit_n: cu,
        a_iso: a,
        modified_l10_mrev: modified,
        modified_l10_h: hours(modified, inp.relative_speed_rpm),
        static_safety: static_safety(inp.kind, inp.max_contact_stress_pa),
        reasons,
    }
}

/// The static-safety warning (s0 < 1), a sentence with its numbers, or `None`.
pub fn static_safety_warning(kind: ContactKind, max_contact_stress_pa: f64) -> Option<String> {
    let s0 = static_safety(kind, max_contact_stress_pa)?;
    (s0 < 1.0).then(|| {
        format!(
            "static safety s0 = {s0:.3} < 1: the maximum contact stress {:.0} MPa exceeds ISO 76's {:.0} MPa for {} contacts (permanent deformation of the raceways)",
            max_contact_stress_pa * 1e-6,
            kind.reference_stress_pa() * 1e-6,
            match kind {
                ContactKind::Ball => "ball",
                ContactKind::Roller => "roller",
            }
        )
    })
}

/// The load-distribution (reference) life under the spherical roller's JSON names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct ReferenceLifeNumbers {
    /// Inner raceway capacity, N.
    pub capacity_inner_n: Option<f64>,
    /// Outer raceway capacity, N.
    pub capacity_outer_n: Option<f64>,
    /// Inner raceway L10, Mrev (`None`: unloaded).
    pub l10_inner_mrev: Option<f64>,
    /// Outer raceway L10, Mrev.
    pub l10_outer_mrev: Option<f64>,
    /// Bearing L10 (product law), Mrev.
    pub l10_bearing_mrev: Option<f64>,
    /// Bearing L10, h.
    pub l10_bearing_h: Option<f64>,
}

/// Everything [`roller_reference_life`] reads.
#[derive(Debug, Clone, Copy)]
pub struct RollerLifeInputs<'a> {
    /// Per roller, the equivalent load at the inner raceway (eq. 6.1 over its laminae,
    /// [`super::life::equivalent_roller_load_widths`]), N — all Z rollers.
    pub inner_equivalent_loads_n: &'a [f64],
    /// The same at the outer raceway, N.
    pub outer_equivalent_loads_n: &'a [f64],
    /// Capacity geometry of the inner raceway (its own contact angle); L_eff is the length
    /// the laminae span (the product law counts every lamina of it).
    pub inner_geometry: super::life::CapacityGeometry,
    /// Capacity geometry of the outer raceway.
    pub outer_geometry: super::life::CapacityGeometry,
    /// Factor on Lundberg–Palmgren's 552 (ξ of seed 000 eq. 6.2; the systems pass ISO 281's
    /// b_m, see their life modules).
    pub capacity_factor: f64,
    /// Whether the inner raceway rotates relative to the load (eq. 6.3 for it, 6.4 for the
    /// other).
    pub inner_rotating: bool,
    /// |Ω_i − Ω_o|, rad/s (hours).
    pub relative_speed_rad_s: f64,
}

/// The load-distribution (reference) life of a roller bearing from its lamina loads:
/// Lundberg–Palmgren line contact as the spherical roller computes it (seed 000 eqs.
/// 6.1–6.6: capacities [`super::life::raceway_capacity`], quartic mean for the rotating and
/// 4.5 mean for the stationary raceway, L = (P_c/P_m)⁴, product law with e = 9/8).
pub fn roller_reference_life(inp: &RollerLifeInputs) -> ReferenceLifeNumbers {
    use super::life::{
        bearing_l10, life_hours, mean_load_rotating, mean_load_stationary, raceway_capacity,
        raceway_l10, Raceway,
    };
    let ci = raceway_capacity(Raceway::Inner, inp.capacity_factor, &inp.inner_geometry);
    let co = raceway_capacity(Raceway::Outer, inp.capacity_factor, &inp.outer_geometry);
    let (mi, mo) = if inp.inner_rotating {
        (
            mean_load_rotating(inp.inner_equivalent_loads_n),
            mean_load_stationary(inp.outer_equivalent_loads_n),
        )
    } else {
        (
            mean_load_stationary(inp.inner_equivalent_loads_n),
            mean_load_rotating(inp.outer_equivalent_loads_n),
        )
    };
    let (li, lo) = (raceway_l10(ci, mi), raceway_l10(co, mo));
    let lb = bearing_l10(li, lo);
    ReferenceLifeNumbers {
        capacity_inner_n: Some(ci),
        capacity_outer_n: Some(co),
        l10_inner_mrev: li,
        l10_outer_mrev: lo,
        l10_bearing_mrev: lb,
        l10_bearing_h: life_hours(lb, inp.relative_speed_rad_s),
    }
}

/// The JSON `life` object every system writes (issue 28; names are a contract):
/// the reference life's numbers (or `reference_reason`), `lambda_inner`/`lambda_outer`
/// (or `lambda_reason` where the system has no film), then [`IsoLife`]'s fields
/// (`basic_dynamic_rating_n`, `basic_l10_mrev`, `modified_l10_mrev`, `a_iso`, `kappa`,
/// `static_safety`, …, `reasons`). `static_safety` lives here, not at the top level.
pub fn life_json(
    reference: &Result<ReferenceLifeNumbers, String>,
    lambdas: &Result<(Option<f64>, Option<f64>), String>,
    iso: &IsoLife,
) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    match reference {
        Ok(r) => {
            if let Ok(serde_json::Value::Object(o)) = serde_json::to_value(r) {
                m.extend(o);
            }
        }
        Err(e) => {
            for k in [
                "capacity_inner_n",
                "capacity_outer_n",
                "l10_inner_mrev",
                "l10_outer_mrev",
                "l10_bearing_mrev",
                "l10_bearing_h",
            ] {
                m.insert(k.into(), serde_json::Value::Null);
            }
            m.insert("reference_reason".into(), serde_json::json!(e));
        }
    }
    match lambdas {
        Ok((i, o)) => {
            m.insert("lambda_inner".into(), serde_json::json!(i));
            m.insert("lambda_outer".into(), serde_json::json!(o));
        }
        Err(e) => {
            m.insert("lambda_reason".into(), serde_json::json!(e));
        }
    }
    if let Ok(serde_json::Value::Object(o)) = serde_json::to_value(iso) {
        m.extend(o);
    }
    serde_json::Value::Object(m)
}

/// The text report's LIFE lines shared by the systems: lives in Mrev and h, forces
/// (capacities, ratings, the equivalent load, the fatigue limit) in the deck's unit (N or
/// lbf; issue 30 item 7: a US deck read `C_r 87137 N`).
pub fn life_text(
    reference: &Result<ReferenceLifeNumbers, String>,
    iso: &IsoLife,
    units: crate::units::Units,
) -> String {
    use crate::units::Quantity;
    use std::fmt::Write;
    let f = |x: Option<f64>, prec: usize| match x {
        Some(v) => format!("{v:.prec$}"),
        None => "—".to_string(),
    };
    let force = |x: Option<f64>| x.map(|v| Quantity::Force.from_si(v, units));
    let n = Quantity::Force.unit(units);
    let mut s = String::from("\nLIFE\n");
    let d = iso.rating_direction.subscript();
    // Radial lines read as they always have ("P"); a thrust bearing's load is P_a.
    let p_name = match iso.rating_direction {
        RatingDirection::Radial => "P",
        RatingDirection::Axial => "P_a",
    };
    match reference {
        Ok(r) => {
            let _ = writeln!(
                s,
                "  reference (load distribution): L10 inner {} Mrev, outer {} Mrev, bearing {} Mrev = {} h; capacities {} / {} {n}",
                f(r.l10_inner_mrev, 2),
                f(r.l10_outer_mrev, 2),
                f(r.l10_bearing_mrev, 2),
                f(r.l10_bearing_h, 1),
                f(force(r.capacity_inner_n), 0),
                f(force(r.capacity_outer_n), 0)
            );
        }
        Err(e) => {
            let _ = writeln!(s, "  reference (load distribution): none ({e})");
        }
    }
    let _ = writeln!(
        s,
        "  ISO 281: C_{d} {} {n}, {p_name} {} {n}, L10 {} Mrev = {} h; κ {}, e_C {}, C_u {} {n}, a_ISO {}, L10m {} Mrev = {} h",
        f(force(iso.basic_dynamic_rating_n), 0),
        f(force(iso.equivalent_load_n), 1),
        f(iso.basic_l10_mrev, 2),
        f(iso.basic_l10_h, 1),
        f(iso.kappa, 3),
        iso.contamination_factor,
        f(force(iso.fatigue_load_limit_n), 0),
        f(iso.a_iso, 3),
        f(iso.modified_l10_mrev, 2),
        f(iso.modified_l10_h, 1)
    );
    let _ = writeln!(
        s,
        "  ISO 76: C_0{d} {} {n}, static safety s0 {}",
        f(force(iso.basic_static_rating_n), 0),
        f(iso.static_safety, 3)
    );
    for r in &iso.reasons {
        let _ = writeln!(s, "  note: {r}");
    }
    s
}

#[cfg(test)]
#[path = "rating_tests.rs"]
mod tests;
