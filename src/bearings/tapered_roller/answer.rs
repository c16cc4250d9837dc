//! The Summary pane's lines of a solved tapered roller bearing (issue 28): life, the
//! largest contact stress and flange load with the roller they occur at, the cage speed,
//! the rollers off both races. No lubricant inputs yet: film, friction and temperature
//! are said to be absent, not made up.

use super::analysis::Analysis;
use super::life::TaperedLife;
use super::roller::RollerState;
use crate::bearings::answer::{arg_max, life_lines, CONTACT, ELEMENTS, FRICTION, SPEEDS};
use crate::bearings::view::{AnswerLine, Display};

const NO_LUBRICANT: &str = "the tapered deck has no lubricant inputs yet";

/// The Summary pane's lines (`life` is the analysis's life stage, already formed for the
/// key outputs).
pub fn answer(a: &Analysis, life: &TaperedLife) -> Vec<AnswerLine> {
    let r = &life.reference;
    let mut out = life_lines(
        r.l10_bearing_mrev,
        r.l10_bearing_h,
        "infinite: no roller is loaded, or the rings do not turn",
        &life.iso,
    );
    let rollers = &a.solution.rollers;
    let stress = arg_max(
        rollers
            .iter()
            .flat_map(|(r, _, _)| [r.cone.max_stress_pa, r.cup.max_stress_pa]),
    );
    out.push(
        AnswerLine::number(
            CONTACT,
            "max contact stress",
            stress.map(|s| s.1),
            Display::Stress,
            0,
            "max /rollers/*/max_stress_inner_pa /rollers/*/max_stress_outer_pa",
            "no roller",
        )
        .at(stress.map(|(i, _)| {
            let race = if i % 2 == 0 { "cone" } else { "cup" };
            format!("roller {}, {race}", i / 2 + 1)
        })),
    );
    let flange = arg_max(rollers.iter().map(|(r, _, _)| r.flange_n));
    out.push(
        AnswerLine::number(
            CONTACT,
            "max flange load",
            flange.map(|f| f.1),
            Display::Force,
            1,
            "max /rollers/*/flange_load_n",
            "no roller",
        )
        .at(flange.map(|(i, _)| format!("roller {}", i + 1))),
    );
    out.push(AnswerLine::number(
        CONTACT,
        "min film",
        None,
        Display::Film,
        3,
        "",
        NO_LUBRICANT,
    ));
    out.push(AnswerLine::number(
        SPEEDS,
        "cage",
        Some(a.bearing.dynamics.cage_rad_s * 30.0 / std::f64::consts::PI),
        Display::Rpm,
        1,
        "/speeds/cage_rad_s ×9.549296585513721",
        "",
    ));
    out.push(AnswerLine::number(
        FRICTION,
        "friction torque",
        None,
        Display::Moment,
        4,
        "",
        NO_LUBRICANT,
    ));
    let off = rollers
        .iter()
        .filter(|(r, _, _)| r.state != RollerState::BothRaces)
        .count();
    out.push(AnswerLine::name(
        ELEMENTS,
        "rollers off a race",
        format!("{off} of {}", rollers.len()),
    ));
    out
}
