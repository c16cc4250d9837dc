//! The friction torques against load (seed 002 Fig. 2: M_fi and M_fo against F/C under
//! radial, axial and combined load), each point a full solve: the `losses` command and the
//! Torque-vs-load pane.
//!
//! # C
//! C is ISO 281:2007's basic dynamic radial load rating of a roller bearing (eq. 9):
//! C_r = b_m·f_c·(i·L_we·cos α)^{7/9}·Z^{3/4}·D_we^{29/27} (N, mm), b_m = 1.15 for spherical
//! roller bearings (Table 8), f_c from Table 7 at γ = D_we·cos α/D_pw (linear between its
//! rows), i the rows, L_we the effective length. It ignores the raceway radii (the
//! optimiser's capacity is Lundberg–Palmgren's); here it only scales the load axis, as the
//! seed's "C – dynamic catalogue capacity" does. The illustrative 22308 gives 114.6 kN
//! (the catalogue's 22308 E, with larger rollers, is rated 150 kN).
//!
//! # Directions
//! F is the load's magnitude: radial F_r = F·C, F_a = 0; axial F_a = F·C, F_r = 0; combined
//! keeps the deck's F_a/F_r ratio (or F_a = 0.25·F_r when the deck has no radial load or no
//! axial load) with F = √(F_r² + F_a²).

use serde::Serialize;

use super::input::DoubleRowInput;
use super::losses::losses;
use super::statics::{analyse, analyse_from, StaticsStart};
use crate::bearings::SolveError;

/// The most points one `losses` run accepts (each is a full solve).
pub const MAX_POINTS: usize = 200;

/// ISO 281's C_r of the deck's bearing, N (module notes). `None` outside Table 7's γ range.
pub fn dynamic_rating_n(input: &DoubleRowInput) -> Option<f64> {
    let g = &input.geometry;
    crate::physics::rating::iso_radial_rating_roller(
        crate::physics::rating::B_M_SPHERICAL_ROLLER,
        &crate::physics::rating::RollerRatingGeometry {
            rows: g.rows,
            roller_count: g.roller_count,
            roller_diameter_m: g.roller_diameter_m,
            effective_length_m: g.effective_length_m,
            pitch_diameter_m: g.pitch_diameter_m,
            contact_angle_rad: g.contact_angle_rad,
        },
    )
}

/// Load direction of the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Direction {
    Radial,
    Axial,
    Combined,
}

impl Direction {
    /// The three, in the pane's order.
    pub const ALL: [Direction; 3] = [Direction::Radial, Direction::Axial, Direction::Combined];

    /// Its name on the command line and in the reports.
    pub fn name(self) -> &'static str {
        match self {
            Direction::Radial => "radial",
            Direction::Axial => "axial",
            Direction::Combined => "combined",
        }
    }

    /// (F_r, F_a) of magnitude `f_n` in this direction for `input` (module notes), N.
    pub fn loads(self, input: &DoubleRowInput, f_n: f64) -> (f64, f64) {
        match self {
            Direction::Radial => (f_n, 0.0),
            Direction::Axial => (0.0, f_n),
            Direction::Combined => {
                let (fr, fa) = (
                    input.operating.radial_load_n.abs(),
                    input.operating.axial_load_n.abs(),
                );
                let ratio = if fr > 0.0 && fa > 0.0 { fa / fr } else { 0.25 };
                let r = f_n / (1.0 + ratio * ratio).sqrt();
                (r, ratio * r)
            }
        }
    }
}

/// One point of the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TorquePoint {
    pub f_over_c: f64,
    pub radial_load_n: f64,
    pub axial_load_n: f64,
    pub friction_torque_inner_nm: f64,
    pub friction_torque_outer_nm: f64,
    pub friction_torque_nm: f64,
    pub total_w: f64,
}

/// Solve `input` at F = `f_over_c`·C in `direction` and return its torques.
///
/// # Errors
/// The statics' or the loss stage's message, naming the point.
pub fn torque_point(
    input: &DoubleRowInput,
    name: &str,
    direction: Direction,
    f_over_c: f64,
    c_n: f64,
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<TorquePoint, String> {
    torque_point_from(input, name, direction, f_over_c, c_n, None, cancel).map(|(p, _)| p)
}

/// [`torque_point`] with the statics started from `from` (a neighbouring point's solution,
/// [`analyse_from`]); returns the point's own solution as the next one's start. Only the
/// path changes: a warm start the statics cannot take from there is retried cold (the
/// cold solve's outcome, success or error, is the point's), so a sweep answers what cold
/// solves answer.
///
/// # Errors
/// The statics' or the loss stage's message, naming the point.
pub fn torque_point_from(
    input: &DoubleRowInput,
    name: &str,
    direction: Direction,
    f_over_c: f64,
    c_n: f64,
    from: Option<&StaticsStart>,
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<(TorquePoint, StaticsStart), String> {
    let (fr, fa) = direction.loads(input, f_over_c * c_n);
    let mut i = input.clone();
    i.operating.radial_load_n = fr;
    i.operating.axial_load_n = fa;
    let at = || format!("{} load at F/C = {f_over_c}", direction.name());
    let a = match analyse_from(&i, name, from, cancel) {
        Err(e) if from.is_some() && e != SolveError::Cancelled => analyse(&i, name, cancel),
        other => other,
    }
    .map_err(|e| format!("{}: {e}", at()))?;
    let l = losses(&a).map_err(|e| format!("{}: loss breakdown: {e}", at()))?;
    let point = TorquePoint {
        f_over_c,
        radial_load_n: fr,
        axial_load_n: fa,
        friction_torque_inner_nm: l.losses.friction_torque_inner_nm,
        friction_torque_outer_nm: l.losses.friction_torque_outer_nm,
        friction_torque_nm: l.losses.friction_torque_nm,
        total_w: l.losses.total_w,
    };
    Ok((point, a.start()))
}

/// The torques at each F/C of `values` in `direction`, in order, each point's statics
/// started from the previous point's solution ([`torque_point_from`]): the same answers as
/// [`torque_point`] at each value, to the ring tolerance, for fewer lamina evaluations.
///
/// # Errors
/// The first failing point's message.
pub fn torque_sweep(
    input: &DoubleRowInput,
    name: &str,
    direction: Direction,
    values: &[f64],
    c_n: f64,
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<Vec<TorquePoint>, String> {
    let mut from: Option<StaticsStart> = None;
    let mut out = Vec::with_capacity(values.len());
    for x in values {
        let (p, next) = torque_point_from(input, name, direction, *x, c_n, from.as_ref(), cancel)?;
        out.push(p);
        from = Some(next);
    }
    Ok(out)
}

/// The F/C values of `A:B:STEP` (A ≤ B, STEP > 0, ends included to 1e-9 of the step).
///
/// # Errors
/// A sentence naming `--f-over-c`, the value and the allowed form or bound.
pub fn parse_range(text: &str) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = text.split(':').collect();
    let bad = |why: &str| format!("--f-over-c {text}: {why}");
    let [a, b, s] = parts.as_slice() else {
        return Err(bad("expected A:B:STEP, e.g. 0.02:0.2:0.02"));
    };
    let num = |x: &str| {
        x.trim()
            .parse::<f64>()
            .map_err(|_| bad(&format!("{x} is not a number")))
    };
    let (a, b, s) = (num(a)?, num(b)?, num(s)?);
    if !(a.is_finite() && b.is_finite() && s.is_finite() && a > 0.0 && b >= a && s > 0.0) {
        return Err(bad("need 0 < A ≤ B and STEP > 0"));
    }
    let n = ((b - a) / s + 1e-9).floor() + 1.0;
    if n > MAX_POINTS as f64 {
        return Err(bad(&format!(
            "{n} points, more than the {MAX_POINTS} allowed (each is a full solve): use a larger STEP"
        )));
    }
    Ok((0..n as usize).map(|k| a + s * k as f64).collect())
}

/// The sweep as a table: text (aligned columns), CSV (units in the header) or JSON
/// (`{"direction", "dynamic_rating_n", "points": [...]}`, SI).
pub fn render(
    points: &[TorquePoint],
    direction: Direction,
    c_n: f64,
    json: bool,
    csv: bool,
) -> String {
    if json {
        let v = serde_json::json!({
            "direction": direction.name(),
            "dynamic_rating_n": c_n,
            "points": points,
        });
        return format!("{v:#}\n");
    }
    let mut s = String::new();
    if csv {
        s.push_str("f_over_c,radial_load_n,axial_load_n,friction_torque_inner_nm,friction_torque_outer_nm,friction_torque_nm,total_w\n");
        for p in points {
            s.push_str(&format!(
                "{},{:e},{:e},{:e},{:e},{:e},{:e}\n",
                p.f_over_c,
                p.radial_load_n,
                p.axial_load_n,
                p.friction_torque_inner_nm,
                p.friction_torque_outer_nm,
                p.friction_torque_nm,
                p.total_w
            ));
        }
        return s;
    }
    s.push_str(&format!(
        "Friction torque against load, {} (C = {:.0} N, ISO 281 C_r)\n",
        direction.name(),
        c_n
    ));
    s.push_str(&format!(
        "{:>7} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n",
        "F/C", "F_r N", "F_a N", "M_fi N·m", "M_fo N·m", "M N·m", "P W"
    ));
    for p in points {
        s.push_str(&format!(
            "{:>7.4} {:>10.1} {:>10.1} {:>10.5} {:>10.5} {:>10.5} {:>10.3}\n",
            p.f_over_c,
            p.radial_load_n,
            p.axial_load_n,
            p.friction_torque_inner_nm,
            p.friction_torque_outer_nm,
            p.friction_torque_nm,
            p.total_w
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// C_r of the illustrative 22308 by hand (ISO 281 eq. 9): γ = 12.5·cos 12°/65 =
    /// 0.18811, f_c = 88.8 (Table 7: 88.8 at 0.18 and 0.19), C = 1.15·88.8·(2·11·cos 12°)^{7/9}
    /// ·13^{3/4}·12.5^{29/27}; tolerance 1e-12 (the same arithmetic typed out).
    #[test]
    fn iso_rating_of_the_example() {
        let b = DoubleRowInput::example_22308();
        let c = dynamic_rating_n(&b).expect("in table");
        let ca = 12.0_f64.to_radians().cos();
        let want = 1.15
            * 88.8
            * (2.0 * 11.0 * ca).powf(7.0 / 9.0)
            * 13f64.powf(0.75)
            * 12.5f64.powf(29.0 / 27.0);
        assert!((c / want - 1.0).abs() < 1e-12, "{c} {want}");
        assert!((100e3..130e3).contains(&c), "{c}");
    }

    /// The range form, its ends and the refusal past the bound naming the option.
    #[test]
    fn ranges() {
        let v = parse_range("0.02:0.2:0.02").expect("valid");
        assert_eq!(v.len(), 10);
        assert!((v[9] - 0.2).abs() < 1e-12);
        let e = parse_range("0.0001:1:0.0001").expect_err("too many");
        assert!(e.contains("--f-over-c") && e.contains("200"), "{e}");
        assert!(parse_range("0.2:0.1:0.01").is_err());
        // Combined keeps the deck's ratio 2000/20000 and the magnitude.
        let b = DoubleRowInput::example_22308();
        let (fr, fa) = Direction::Combined.loads(&b, 1000.0);
        assert!((fa / fr - 0.1).abs() < 1e-12 && (fr.hypot(fa) - 1000.0).abs() < 1e-9);
    }
}
