//! Results beyond the validity of the ball model, said as warnings (as the roller systems
//! do, issue 15): a solve can converge to numbers no real bearing reaches, and "✓ solved"
//! alone would let them pass. The JSON (`warnings`), the text report and the workbench's
//! status line carry them; each names the number, the bound and why the bound matters.

use super::analysis::{BallAnalysis, BallResult, ContactResult};
use crate::bearings::view::{Display, Warning};
use crate::units::Units;

/// Contact stress above which the elastic (Hertz) contact no longer holds for bearing
/// steel, Pa: 4 200 MPa, the stress at which ISO 76 sets the static load rating of ball
/// bearings (a permanent deformation of 10⁻⁴ of the ball diameter).
pub const STRESS_LIMIT_PA: f64 = 4.2e9;

/// Contact angle beyond which a contact runs off a real ring, rad: 90°. The model's
/// groove is a whole torus (seed 001, 2-5…2-8 take the groove curvature only), so an
/// angle past 90° solves; on a real ring the groove ends at a shoulder, below 90°.
pub const ANGLE_LIMIT_RAD: f64 = std::f64::consts::FRAC_PI_2;

/// The warnings of an analysis, worst first (a contact off the ring, then the stress);
/// empty when every result is within the model. Each is written in both unit systems.
pub fn warnings(a: &BallAnalysis) -> Vec<Warning> {
    let mut w = Vec::new();
    fn inner(b: &BallResult) -> &ContactResult {
        &b.inner
    }
    fn outer(b: &BallResult) -> &ContactResult {
        &b.outer
    }
    type Pick = fn(&BallResult) -> &ContactResult;
    for (race, pick) in [("inner", inner as Pick), ("outer", outer as Pick)] {
        let worst = a
            .balls
            .iter()
            .enumerate()
            .filter(|(_, b)| pick(b).load_n > 0.0)
            .max_by(|x, y| pick(x.1).angle_rad.total_cmp(&pick(y.1).angle_rad));
        if let Some((j, b)) = worst {
            let alpha = pick(b).angle_rad;
            if alpha > ANGLE_LIMIT_RAD {
                let n = a
                    .balls
                    .iter()
                    .filter(|b| pick(b).load_n > 0.0 && pick(b).angle_rad > ANGLE_LIMIT_RAD)
                    .count();
                let text = format!(
                    "{race} contact angle {:.1}° (ball {j}; {n} ball{} beyond 90°): the model's groove is a whole torus, but a real ring's groove ends at its shoulder below 90°, so the contact would run off the land; a force-held preload lets the angle run up at speed (operating.preload_mode = \"displacement\" holds it)",
                    alpha.to_degrees(),
                    if n == 1 { "" } else { "s" }
                );
                w.push(Warning {
                    si: text.clone(),
                    us: text,
                });
            }
        }
    }
    let max_p = a.max_pressure_pa();
    if max_p > STRESS_LIMIT_PA {
        let f = |u: Units| {
            let p = |v: f64| Display::Stress.convert(v, u);
            let unit = Display::Stress.unit(u);
            format!(
                "max contact stress {:.0} {unit} exceeds {:.0} {unit} (ISO 76 static limit for ball bearings): the raceways deform permanently and the elastic contact model no longer holds",
                p(max_p),
                p(STRESS_LIMIT_PA)
            )
        };
        w.push(Warning {
            si: f(Units::Si),
            us: f(Units::Us),
        });
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::angular_ball::analysis::analyse;
    use crate::bearings::angular_ball::input::{BallInput, PreloadMode};
    use crate::numerics::cancel::Cancel;

    /// Chen's decks as shipped are within the model (no warning); the force-held preload
    /// under 500 N radial load runs inner angles to 121° (a warning naming the angle and
    /// the count); a 150 kN preload (p₀ 4.7 GPa) warns of the stress; the bounds
    /// are what the constants say (90°, 4 200 MPa).
    #[test]
    fn warnings_flag_what_the_model_cannot_carry() {
        for i in [BallInput::chen_a(), BallInput::chen_b()] {
            assert!(warnings(&analyse(&i, Cancel::NONE).unwrap()).is_empty());
        }
        let mut i = BallInput::chen_b();
        i.operating.preload_mode = PreloadMode::Force;
        i.operating.radial_load_n = 500.0;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let w = warnings(&a);
        let over = a
            .balls
            .iter()
            .filter(|b| b.inner.load_n > 0.0 && b.inner.angle_rad > ANGLE_LIMIT_RAD)
            .count();
        assert!(over > 0);
        assert!(
            w[0].si.starts_with("inner contact angle 121."),
            "{}",
            w[0].si
        );
        assert!(
            w[0].si.contains(&format!("{over} balls beyond 90°")),
            "{}",
            w[0].si
        );
        let mut i = BallInput::chen_a();
        i.operating.axial_load_n = 150_000.0;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let p = a.max_pressure_pa();
        assert!(p > STRESS_LIMIT_PA, "{p}");
        let w = warnings(&a);
        assert!(w
            .iter()
            .any(|w| w.si.contains("ISO 76") && w.us.contains("ksi")));
        assert_eq!(STRESS_LIMIT_PA, 4.2e9);
        assert_eq!(ANGLE_LIMIT_RAD.to_degrees(), 90.0);
    }
}
