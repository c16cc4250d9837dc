//! The Summary pane's lines of a solved angular-contact ball bearing (issue 28): life,
//! the largest contact pressure and thinnest film with the ball they occur at, the cage
//! speed, the skid threshold, the heat and the bulk temperature.

use super::analysis::BallAnalysis;
use super::life::BallLife;
use super::view::cage_rpm;
use crate::bearings::answer::{
    arg_max, arg_min, life_lines, CONTACT, ELEMENTS, FRICTION, SPEEDS, TEMPERATURE,
};
use crate::bearings::view::{element_number, AnswerLine, Display};

const RACE: [&str; 2] = ["inner", "outer"];

/// The Summary pane's lines (`life` is the analysis's life stage, already formed for the
/// key outputs).
pub fn answer(a: &BallAnalysis, life: &BallLife) -> Vec<AnswerLine> {
    let (l10, l10_h, why) = match &life.reference {
        Ok(r) => (
            r.l10_bearing_mrev,
            r.l10_bearing_h,
            "infinite: no ball is loaded",
        ),
        Err(e) => (None, None, e.as_str()),
    };
    let mut out = life_lines(l10, l10_h, why, &life.iso);
    let place = |i: usize| format!("ball {}, {}", element_number(i / 2), RACE[i % 2]);
    let max_p = arg_max(
        a.balls
            .iter()
            .flat_map(|b| [b.inner.hertz.max_pressure_pa, b.outer.hertz.max_pressure_pa]),
    );
    out.push(
        AnswerLine::number(
            CONTACT,
            "max contact pressure",
            max_p.map(|m| m.1),
            Display::Stress,
            0,
            "max /balls/*/inner/max_pressure_pa /balls/*/outer/max_pressure_pa",
            "no ball",
        )
        .at(max_p.map(|m| place(m.0))),
    );
    let thinnest = arg_min(
        a.balls
            .iter()
            .flat_map(|b| [b.inner.min_film_m, b.outer.min_film_m].map(|h| h.unwrap_or(f64::NAN))),
    );
    out.push(
        AnswerLine::number(
            CONTACT,
            "min film",
            thinnest.map(|m| m.1),
            Display::Film,
            3,
            "min /balls/*/inner/min_film_m /balls/*/outer/min_film_m",
            "no loaded contact has a film",
        )
        .at(thinnest.map(|m| place(m.0))),
    );
    // Λ = h_min/σ at the thinnest film's contact (issue 28 item 3), where the deck gives σ.
    if let Some(sigma) = a.input.surfaces.composite_rms_m {
        out.push(AnswerLine::number(
            CONTACT,
            "Λ at the min film",
            thinnest.map(|m| m.1 / sigma),
            Display::Plain,
            2,
            "min /balls/*/inner/lambda /balls/*/outer/lambda",
            "no loaded contact has a film",
        ));
    }
    out.push(AnswerLine::number(
        SPEEDS,
        "cage",
        Some(cage_rpm(a)),
        Display::Rpm,
        1,
        "/speeds/cage_rpm",
        "",
    ));
    out.push(AnswerLine::number(
        ELEMENTS,
        "skid threshold",
        a.skid.speed_rad_s.map(|w| w * 30.0 / std::f64::consts::PI),
        Display::Rpm,
        0,
        "/skid/threshold_rpm",
        a.skid
            .reason
            .as_deref()
            .unwrap_or("no threshold below the search limit"),
    ));
    let skidding = a.balls.iter().filter(|b| b.skidding).count();
    out.push(AnswerLine::name(
        ELEMENTS,
        "skidding balls",
        format!("{skidding} of {}", a.balls.len()),
    ));
    // "heat" is the whole friction power, as on every system's Summary; the seed's
    // sliding heat (spin or slice traction, the H of the bulk temperature 4-1) is its own
    // line, so neither is mistaken for the other.
    let fb = super::friction::friction(a);
    out.push(AnswerLine::number(
        FRICTION,
        "heat",
        Some(fb.power_w()),
        Display::Power,
        2,
        "/friction/power_w",
        "",
    ));
    out.push(AnswerLine::number(
        FRICTION,
        "sliding heat",
        Some(a.total_heat_w),
        Display::Power,
        2,
        "/heat/total_w",
        "",
    ));
    out.push(AnswerLine::number(
        FRICTION,
        "friction torque",
        Some(fb.torque_nm),
        Display::Moment,
        4,
        "/friction/torque_nm",
        "",
    ));
    if let Some(name) = crate::bearings::answer::largest_mechanism(&fb.pairs()) {
        out.push(AnswerLine::name(FRICTION, "largest", name));
    }
    out.push(AnswerLine::number(
        TEMPERATURE,
        "bulk oil",
        Some(a.bulk_temperature_k - 273.15),
        Display::Temperature,
        1,
        "/heat/bulk_temperature_c",
        "",
    ));
    out
}
