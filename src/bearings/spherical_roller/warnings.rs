//! Results beyond the validity of the model, said as warnings (issue 15): a solve can
//! converge to numbers no bearing survives, and "✓ solved" alone would let them pass.
//! Every report and the workbench's status line carry these; each names the number, the
//! bound and why the bound matters.

use super::pipeline::Analysis;
use crate::bearings::view::{Display, Warning};
use crate::units::Units;

/// Contact stress above which the elastic (Hertz) contact no longer holds for bearing
/// steel, Pa: 4000 MPa, the stress at which ISO 76 sets the static load rating of roller
/// bearings (a permanent deformation of 10⁻⁴ of the roller diameter).
pub const STRESS_LIMIT_PA: f64 = 4.0e9;

/// Ring deflection, as a fraction of the roller diameter, beyond which the
/// small-displacement contact geometry of §3 is no longer a fair model: 5 % (the shipped
/// decks at their design loads deflect 0.3–1 % of D).
pub const DEFLECTION_LIMIT_OF_D: f64 = 0.05;

/// The warnings of an analysis, worst first; empty when every result is within the model.
/// Each is written in both unit systems.
pub fn warnings(a: &Analysis) -> Vec<Warning> {
    let both = |f: &dyn Fn(Units) -> String| Warning {
        si: f(Units::Si),
        us: f(Units::Us),
    };
    let mut w = Vec::new();
    let max_stress = a.stresses.as_ref().map_or(0.0, |s| {
        s.rollers
            .iter()
            .flat_map(|r| r.iter().map(|c| c.max_stress_pa))
            .fold(0.0, f64::max)
    });
    if max_stress > STRESS_LIMIT_PA {
        w.push(both(&|u| {
            let p = |v: f64| Display::Stress.convert(v, u);
            let unit = Display::Stress.unit(u);
            format!(
                "max contact stress {:.0} {unit} exceeds {:.0} {unit} (ISO 76 static limit for roller bearings): the raceways deform permanently and the elastic contact model no longer holds",
                p(max_stress),
                p(STRESS_LIMIT_PA)
            )
        }));
    }
    let d = a.input.geometry.roller_diameter_m;
    for (what, x) in [
        ("axial", a.load.axial_deflection_m),
        ("radial", a.load.radial_deflection_m),
    ] {
        if d > 0.0 && x.abs() > DEFLECTION_LIMIT_OF_D * d {
            w.push(both(&|u| {
                let l = |v: f64| Display::SmallLength.convert(v, u);
                let unit = Display::SmallLength.unit(u);
                format!(
                    "{what} ring deflection {:.2} {unit} is {:.0} % of the roller diameter ({:.1} {unit}; the model assumes deflections well below {:.0} %): check the loads and the clearance",
                    l(x),
                    100.0 * x.abs() / d,
                    l(d),
                    100.0 * DEFLECTION_LIMIT_OF_D
                )
            }));
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::pipeline::{run, Request};
    use crate::bearings::spherical_roller::Bearing;

    /// The aerospace design point is within the model; 4500 lbf radial (−85 mil axial,
    /// 17 % of D, the case) is not; each bound just above and below.
    #[test]
    fn warnings_flag_what_the_model_cannot_carry() {
        let b = Bearing::example_aerospace();
        let a = run(&b, &Request::default(), None).unwrap_or_else(|e| panic!("{e}"));
        assert!(warnings(&a).is_empty(), "{:?}", warnings(&a));
        let mut heavy = b.clone();
        heavy.operating.radial_load_n = 4500.0 * crate::units::LBF_N;
        let a = run(&heavy, &Request::default(), None).unwrap_or_else(|e| panic!("{e}"));
        let w = warnings(&a);
        assert!(
            w.iter()
                .any(|m| m.si.starts_with("axial ring deflection -2.17 mm")),
            "{w:?}"
        );
        assert!(
            w.iter()
                .any(|m| m.us.starts_with("axial ring deflection -85.47 mil")),
            "{w:?}"
        );
        // The bounds themselves: move the result across them.
        let mut a = run(&b, &Request::default(), None).unwrap_or_else(|e| panic!("{e}"));
        let d = a.input.geometry.roller_diameter_m;
        a.load.radial_deflection_m = 0.99 * DEFLECTION_LIMIT_OF_D * d;
        assert!(warnings(&a).is_empty());
        a.load.radial_deflection_m = 1.01 * DEFLECTION_LIMIT_OF_D * d;
        assert_eq!(warnings(&a).len(), 1);
        a.load.radial_deflection_m = 0.0;
        if let Some(s) = a.stresses.as_mut() {
            if let Some(c) = s.rollers.first_mut().and_then(|r| r.first_mut()) {
                c.max_stress_pa = 1.01 * STRESS_LIMIT_PA;
            }
        }
        let w = warnings(&a);
        assert!(
            w.len() == 1 && w[0].si.starts_with("max contact stress 4040 MPa"),
            "{w:?}"
        );
        assert!(
            w[0].us
                .starts_with("max contact stress 586 ksi exceeds 580 ksi"),
            "{w:?}"
        );
    }
}
