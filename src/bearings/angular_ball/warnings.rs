//! Results beyond the validity of the ball model, said as warnings (as the roller systems
//! do, issue 15): a solve can converge to numbers no real bearing reaches, and "✓ solved"
//! alone would let them pass. The JSON (`warnings`), the text report and the workbench's
//! status line carry them; each names the number, the bound and why the bound matters.

use super::analysis::{BallAnalysis, BallResult, ContactResult};
use super::dynamics;
use super::input::{Method, PreloadMode};
use crate::bearings::view::{element_number, Display, Warning};
use crate::units::Units;

/// Contact stress above which the elastic (Hertz) contact no longer holds for bearing
/// steel, Pa: 4 200 MPa, the stress at which ISO 76 sets the static load rating of ball
/// bearings (a permanent deformation of 10⁻⁴ of the ball diameter).
pub const STRESS_LIMIT_PA: f64 = 4.2e9;

/// Contact angle beyond which a contact runs off a real ring, rad: 90°. The model's
/// groove is a whole torus (seed 001, 2-5…2-8 take the groove curvature only), so an
/// angle past 90° solves; on a real ring the groove ends at a shoulder, below 90°.
pub const ANGLE_LIMIT_RAD: f64 = std::f64::consts::FRAC_PI_2;

/// Bulk temperature above which the model is void, °C: seed 001 ch. 7, conclusion 1 —
/// "the AISI M series steels (the common bearing materials) begin to soften at 400 °C,
/// it can be expected that large deformation of the balls can be caused by the
/// compressions between the balls and races when the temperature is above this value"
/// (Chen's Bearing B at 9 500 rpm reaches 435 °C there, his explanation of its seizure).
/// The bulk temperature of (4-1) is the heat over the oil's heat capacity flow, so the
/// bound is also a bound on the power: H ≤ ρ·c_p·Q̇·(400 °C − T_supply), the most the oil
/// flow carries away before the steel softens.
pub const BULK_TEMPERATURE_LIMIT_C: f64 = 400.0;

/// The warnings of an analysis, worst first (a contact off the ring, a cage outside the
/// ring speeds, the bulk temperature, then the stress and an unsettled time simulation);
/// empty when every result is within the model. Each is written in both unit systems.
pub fn warnings(a: &BallAnalysis) -> Vec<Warning> {
    let mut w = Vec::new();
    undetermined(a, &mut w);
    angles(a, &mut w);
    cage(a, &mut w);
    bulk(a, &mut w);
    stress(a, &mut w);
    settling(a, &mut w);
    film(a, &mut w);
    w
}

/// Neither an axial nor a radial load: nothing fixes the inner ring's axial place within
/// the bearing's play (at rest the balls are loose; at speed the centrifugal force holds
/// them on the outer race and the inner ring floats), so the solve holds it
/// (`load_conditions::axial_condition`): a displacement-held preload at δ_a = 0, the
/// balls just touching both grooves at α₀ (at speed the balls' growth then loads it, as
/// a rigidly held spindle pair); a force-held one centred in its play, δ_a = −A sin α₀,
/// where no ball is pressed. Said, because that place is the model's choice, not an
/// answer of the loads (issue 29).
fn undetermined(a: &BallAnalysis, w: &mut Vec<Warning>) {
    let op = &a.input.operating;
    if op.axial_load_n == 0.0 && op.radial_load_n == 0.0 {
        let place = match op.preload_mode {
            PreloadMode::Displacement => "held at δ_a = 0 (operating.preload_mode = \"displacement\": the balls just touching both grooves at the free contact angle, as a rigidly held spindle pair with no preload)",
            PreloadMode::Force => "held centred in its play, δ_a = −A·sin α₀ (operating.preload_mode = \"force\": no ball is pressed by the inner ring there)",
        };
        let text = format!("no load: with operating.axial_load = 0 and operating.radial_load = 0 nothing fixes the inner ring's axial place within the play; it is {place}, a choice of the model, not an answer of the loads");
        w.push(Warning {
            si: text.clone(),
            us: text,
        });
    }
}

/// A loaded contact with no EHD film because the lubricant has no pressure–viscosity
/// coefficient: the Hamrock–Dowson films (seed 001 eqs. 4-10, 4-11) scale as G^0.49 and
/// G^0.53 with G = α·E′, so `lubricant.pressure_viscosity = 0` gives a zero film, outside
/// the regression behind the formulas, and the spinning contact's film temperature
/// (ch. 6) is not computed (`film_temperature_rise_c: null`). An isoviscous lubricant
/// needs an isoviscous-elastic film law the seed does not give.
fn film(a: &BallAnalysis, w: &mut Vec<Warning>) {
    let loaded_without_film = a.balls.iter().any(|b| {
        [&b.inner, &b.outer]
            .iter()
            .any(|c| c.load_n > 0.0 && c.central_film_m == Some(0.0))
    });
    if loaded_without_film && a.input.lubricant.pressure_viscosity_pa_inv == 0.0 {
        let text = "no EHD film: lubricant.pressure_viscosity = 0 makes the Hamrock–Dowson film (seed eqs. 4-10, 4-11, ∝ (αE′)^0.53) zero, outside the formulas' range; the films are 0 and the contacts' film temperatures are not computed (null): give the oil's pressure–viscosity coefficient".to_string();
        w.push(Warning {
            si: text.clone(),
            us: text,
        });
    }
}

/// A contact angle past 90° (off the shoulder) or below 0° (the contact has crossed the
/// groove bottom to the side an angular-contact ring does not have).
fn angles(a: &BallAnalysis, w: &mut Vec<Warning>) {
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
                    "{race} contact angle {:.1}° (ball {}; {n} ball{} beyond 90°): the model's groove is a whole torus, but a real ring's groove ends at its shoulder below 90°, so the contact would run off the land; a force-held preload lets the angle run up at speed (operating.preload_mode = \"displacement\" holds it)",
                    alpha.to_degrees(),
                    element_number(j),
                    if n == 1 { "" } else { "s" }
                );
                w.push(Warning {
                    si: text.clone(),
                    us: text,
                });
            }
        }
        // Below 0° the contact has crossed the groove bottom: an angular-contact ring's
        // groove is cut away on that side (the counterbore of the outer ring, the low
        // shoulder of the inner), so the ball would ride on the edge of the land. The
        // torus of the model solves it (centrifugal force at 200 000 rpm pushes the
        // outer contact of Bearing A to −3.1°); a warning, as past 90°: the load
        // distribution is still the model's answer, the ring it needs is not the one
        // the deck describes.
        let lowest = a
            .balls
            .iter()
            .enumerate()
            .filter(|(_, b)| pick(b).load_n > 0.0)
            .min_by(|x, y| pick(x.1).angle_rad.total_cmp(&pick(y.1).angle_rad));
        if let Some((j, b)) = lowest {
            let alpha = pick(b).angle_rad;
            if alpha < 0.0 {
                let n = a
                    .balls
                    .iter()
                    .filter(|b| pick(b).load_n > 0.0 && pick(b).angle_rad < 0.0)
                    .count();
                let text = format!(
                    "{race} contact angle {:.2}° (ball {}; {n} ball{} below 0°): the contact has crossed the groove bottom to the side an angular-contact ring cuts away (counterbore, low shoulder), so the ball would run on the edge of the land; the model's groove is a whole torus and solves it, a real ring does not carry it",
                    alpha.to_degrees(),
                    element_number(j),
                    if n == 1 { "" } else { "s" }
                );
                w.push(Warning {
                    si: text.clone(),
                    us: text,
                });
            }
        }
    }
}

/// A cage speed outside the interval of the ring speeds. A ball rolling without gross
/// sliding has its centre moving between the two raceways' surface speeds, so its orbit
/// (the cage) turns between the rings' speeds: race control (2-9) gives such a cage
/// whenever the contact angles are those of a working bearing. Outside that interval
/// (e.g. Bearing B at 60 000 rpm, force-held preload, 500 N radial, inner control: −18 504
/// rpm) the no-slip equations have been met only by a ball spinning against its orbit,
/// which no bearing does; the kinematics, spin heat and skid numbers built on them are
/// then not physical. A warning rather than an error: the load distribution and the
/// stresses are still the model's, and a sweep through the region keeps its other points.
fn cage(a: &BallAnalysis, w: &mut Vec<Warning>) {
    let op = &a.input.operating;
    let (lo, hi) = (
        op.inner_speed_rad_s.min(op.outer_speed_rad_s),
        op.inner_speed_rad_s.max(op.outer_speed_rad_s),
    );
    // Round-off of the 3×3 race-control solve: 1e-9 of the faster ring.
    let tol = 1e-9 * lo.abs().max(hi.abs());
    let off = |c: f64| c < lo - tol || c > hi + tol;
    let worst = a
        .balls
        .iter()
        .enumerate()
        .filter(|(_, b)| off(b.cage_rad_s))
        .max_by(|x, y| {
            let d = |c: f64| (lo - c).max(c - hi);
            d(x.1.cage_rad_s).total_cmp(&d(y.1.cage_rad_s))
        });
    if let Some((j, b)) = worst {
        let rpm = 30.0 / std::f64::consts::PI;
        let n = a.balls.iter().filter(|b| off(b.cage_rad_s)).count();
        let text = format!(
            "cage speed {:.0} rpm (ball {}; {n} ball{}) lies outside the ring speeds ({:.0} … {:.0} rpm){}: a rolling ball's orbit turns between its rings, so race control (kinematics.race_control = \"{}\") is met here only by a ball turning against its orbit; the speeds, spin heat and skidding threshold are not physical",
            b.cage_rad_s * rpm,
            element_number(j),
            if n == 1 { "" } else { "s" },
            lo * rpm,
            hi * rpm,
            if b.cage_rad_s * op.inner_speed_rad_s < 0.0 {
                ", turning against the shaft"
            } else {
                ""
            },
            a.input.kinematics.race_control.name(),
        );
        w.push(Warning {
            si: text.clone(),
            us: text,
        });
    }
}

/// A bulk temperature (4-1) above [`BULK_TEMPERATURE_LIMIT_C`], naming the heat and what
/// the oil flow carries away at that bound.
fn bulk(a: &BallAnalysis, w: &mut Vec<Warning>) {
    let t_c = a.bulk_temperature_k - 273.15;
    // (Finite: a non-finite bulk temperature is an error of the analysis.)
    if t_c <= BULK_TEMPERATURE_LIMIT_C {
        return;
    }
    let l = &a.input.lubricant;
    let capacity = l.density_kg_m3 * l.specific_heat_j_kg_k * l.flow_rate_m3_s;
    let supply_c = l.supply_temperature_k - 273.15;
    let carried = capacity * (BULK_TEMPERATURE_LIMIT_C - supply_c).max(0.0);
    let f = |u: Units| {
        let (t, unit_t): (fn(f64) -> f64, _) = match u {
            Units::Si => (|c| c, "°C"),
            Units::Us => (|c| c * 1.8 + 32.0, "°F"),
        };
        let p = |v: f64| Display::Power.convert(v, u);
        let unit_p = Display::Power.unit(u);
        format!(
            "bulk temperature {:.4} {unit_t} exceeds {:.0} {unit_t}, where bearing steel softens and the balls deform (seed 001 ch. 7): the heat {:.4} {unit_p} is more than the oil flow carries away below that, ρ·c_p·Q·(T_limit − T_supply) = {:.4} {unit_p}; the model no longer holds (raise lubricant.flow_rate_l_min, or lower the speed or the load)",
            t(t_c),
            t(BULK_TEMPERATURE_LIMIT_C),
            p(a.total_heat_w),
            p(carried)
        )
    };
    w.push(Warning {
        si: f(Units::Si),
        us: f(Units::Us),
    });
}

/// A time simulation that has not reached its steady answer (`dynamics::settling`).
fn settling(a: &BallAnalysis, w: &mut Vec<Warning>) {
    let Some(d) = &a.dynamics else {
        return;
    };
    if d.method != Method::TimeSimulation {
        return;
    }
    let periodic = a.input.operating.radial_load_n != 0.0 && a.balls.len() > 1;
    let Some(s) = dynamics::settling(d, periodic, a.input.dynamics.orbits) else {
        return;
    };
    if s.settled {
        return;
    }
    let g = |x: f64| format!("{x:.3}");
    let what = if s.periodic {
        format!(
            "ball {}'s angular velocity averaged over an orbit still changes by {} rad/s from one orbit to the next (settled: ≤ 1e-6·|ω| = {} rad/s); its swing of {} rad/s around the orbit is the periodic response to the radial load, not the transient",
            element_number(s.ball),
            g(s.transient_rad_s),
            g(s.bound_rad_s),
            g(s.amplitude_rad_s)
        )
    } else {
        format!(
            "the balls' angular velocity still oscillates by {} rad/s (steady: ≤ 1e-6·|ω| = {} rad/s)",
            g(s.amplitude_rad_s),
            g(s.bound_rad_s)
        )
    };
    let need = match (s.orbits_needed(), s.decay_per_orbit) {
        (Some(n), Some(r)) => format!(
            "it shrinks by a factor {r:.2} per orbit, so a steady answer needs about {n:.0} orbits{}",
            if n > MAX_ORBITS {
                format!(" (more than dynamics.orbits allows, {MAX_ORBITS:.0})")
            } else {
                String::new()
            }
        ),
        (_, Some(r)) => format!(
            "it does not shrink from one orbit to the next (factor {r:.2}), so a steady answer needs more than {} orbits, if it settles at all",
            s.orbits
        ),
        _ => format!(
            "too few orbits to see it decay, so a steady answer needs more than {} orbits",
            s.orbits
        ),
    };
    let text = format!(
        "time simulation not settled after {} orbits: {what}; {need}: raise dynamics.orbits (the heat and speeds reported are the last orbit's means)",
        s.orbits
    );
    w.push(Warning {
        si: text.clone(),
        us: text,
    });
}

/// The largest `dynamics.orbits` a deck may ask for (`deck.rs`'s range).
const MAX_ORBITS: f64 = 1000.0;

/// A contact stress past the static limit.
fn stress(a: &BallAnalysis, w: &mut Vec<Warning>) {
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
