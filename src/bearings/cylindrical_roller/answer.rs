//! The Summary pane's lines of a solved cylindrical roller bearing (issue 28): life, the
//! largest contact pressure and thinnest film with the roller they occur at, the cage
//! speed and the base natural frequency, the mixed-regime friction over a cage cycle.

use super::analysis::CylindricalAnalysis;
use super::life::CylindricalLife;
use crate::bearings::answer::{
    arg_max, arg_min, life_lines, CONTACT, ELEMENTS, FRICTION, SPEEDS, TEMPERATURE,
};
use crate::bearings::view::{AnswerLine, Display};

const NO_DYNAMICS: &str = "the tribodynamics did not run (dynamics.revolutions = 0)";

/// The Summary pane's lines (`life` is the analysis's life stage, already formed for the
/// key outputs).
pub fn answer(a: &CylindricalAnalysis, life: &CylindricalLife) -> Vec<AnswerLine> {
    let r = &life.reference;
    let mut out = life_lines(
        r.l10_bearing_mrev,
        r.l10_bearing_h,
        "infinite: no roller is loaded, or the rings do not turn",
        &life.iso,
    );
    let roller = |i: usize| Some(format!("roller {}", i + 1));
    let p = arg_max(a.films.iter().map(|f| f.max_pressure_pa));
    out.push(
        AnswerLine::number(
            CONTACT,
            "max contact pressure",
            p.map(|p| p.1),
            Display::Stress,
            0,
            "/max_pressure_pa",
            "no roller",
        )
        .at(p.and_then(|p| roller(p.0))),
    );
    let h = arg_min(a.films.iter().map(|f| f.min_film_m.unwrap_or(f64::NAN)));
    out.push(
        AnswerLine::number(
            CONTACT,
            "min film",
            h.map(|h| h.1),
            Display::Film,
            3,
            "/min_film_m",
            "no loaded slice",
        )
        .at(h.and_then(|h| roller(h.0))),
    );
    let lambda = arg_min(a.films.iter().map(|f| f.lambda.unwrap_or(f64::NAN)));
    out.push(
        AnswerLine::number(
            CONTACT,
            "min Λ",
            lambda.map(|l| l.1),
            Display::Plain,
            3,
            "min /rollers/*/lambda",
            "no loaded slice",
        )
        .at(lambda.and_then(|l| roller(l.0))),
    );
    out.push(AnswerLine::number(
        SPEEDS,
        "cage",
        Some(a.derived.cage_speed_rad_s * 30.0 / std::f64::consts::PI),
        Display::Rpm,
        1,
        "/speeds/cage_rad_s ×9.549296585513721",
        "",
    ));
    let t = a.tribo.as_ref();
    out.push(AnswerLine::number(
        SPEEDS,
        "base natural frequency",
        t.and_then(|t| t.dynamics.base_natural_frequency_hz),
        Display::Frequency,
        1,
        "/dynamics/base_natural_frequency_hz",
        NO_DYNAMICS,
    ));
    out.push(AnswerLine::number(
        FRICTION,
        "friction power",
        t.map(|t| t.friction.power_w),
        Display::Power,
        1,
        "/friction/power_w",
        NO_DYNAMICS,
    ));
    let fb = super::friction::friction(a);
    out.push(AnswerLine::number(
        FRICTION,
        "friction torque",
        fb.as_ref().map(|f| f.torque_nm),
        Display::Moment,
        4,
        "/friction/torque_nm",
        NO_DYNAMICS,
    ));
    if let Some(name) = fb
        .as_ref()
        .and_then(|f| crate::bearings::answer::largest_mechanism(&f.pairs()))
    {
        out.push(AnswerLine::name(FRICTION, "largest", name));
    }
    out.push(AnswerLine::number(
        FRICTION,
        "friction coefficient",
        t.map(|t| t.friction.coefficient),
        Display::Plain,
        4,
        "/friction/coefficient",
        NO_DYNAMICS,
    ));
    if let Some(t) = t {
        let f = &t.friction;
        let share = if f.total_n > 0.0 {
            100.0 * f.boundary_n / f.total_n
        } else {
            0.0
        };
        out.push(AnswerLine::name(
            FRICTION,
            "boundary share",
            format!("{share:.0} % of the friction force (Greenwood–Tripp)"),
        ));
        out.push(AnswerLine::number(
            ELEMENTS,
            "min roller load",
            Some(t.dynamics.min_roller_load_n),
            Display::Force,
            1,
            "/dynamics/min_roller_load_n",
            "",
        ));
    }
    out.push(AnswerLine::number(
        TEMPERATURE,
        "contact",
        None,
        Display::Temperature,
        1,
        "",
        "isothermal at the inlet temperature (the thermal contact model is issue 26)",
    ));
    out
}
