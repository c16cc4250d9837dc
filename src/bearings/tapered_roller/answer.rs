//! The Summary pane's lines of a solved tapered roller bearing (issue 28): life, the
//! largest contact stress and flange load with the roller they occur at, the cage speed,
//! the rollers off both races; with a lubricant the thinnest film and its Λ, the friction
//! torque and power with the largest mechanism, the hottest node of the network. Without
//! one, film, friction and temperature are said to be absent, not made up.

use super::analysis::Analysis;
use super::life::TaperedLife;
use super::roller::RollerState;
use crate::bearings::answer::{
    arg_max, largest_mechanism, life_lines, thermal_lines, CONTACT, ELEMENTS, FRICTION, SPEEDS,
};
use crate::bearings::view::{AnswerLine, Display};

const NO_LUBRICANT: &str = "the deck gives no lubricant";

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
    let trib = a.tribology.as_ref();
    let why = match trib {
        None => NO_LUBRICANT.to_string(),
        Some(Err(e)) => e.to_string(),
        Some(Ok(_)) => "no loaded contact".to_string(),
    };
    let t = trib.and_then(|t| t.as_ref().ok());
    let min = t.and_then(|t| t.min);
    out.push(
        AnswerLine::number(
            CONTACT,
            "min film",
            min.map(|m| m.film_m),
            Display::Film,
            3,
            if t.is_some() { "/film/min_film_m" } else { "" },
            &why,
        )
        .at(min.map(|m| format!("roller {}, {}", m.roller + 1, m.contact))),
    );
    if t.is_some() {
        out.push(AnswerLine::number(
            CONTACT,
            "Λ at the min film",
            min.map(|m| m.lambda),
            Display::Plain,
            2,
            "/film/min_lambda",
            &why,
        ));
    }
    out.push(AnswerLine::number(
        SPEEDS,
        "cage",
        Some(a.bearing.dynamics.cage_rad_s * 30.0 / std::f64::consts::PI),
        Display::Rpm,
        1,
        "/speeds/cage_rad_s ×9.549296585513721",
        "",
    ));
    let f = t.map(|t| &t.friction);
    out.push(AnswerLine::number(
        FRICTION,
        "friction torque",
        f.map(|f| f.torque_nm),
        Display::Moment,
        4,
        if f.is_some() {
            "/friction/torque_nm"
        } else {
            ""
        },
        &why,
    ));
    if let Some(f) = f {
        out.push(AnswerLine::number(
            FRICTION,
            "heat",
            Some(f.power_w()),
            Display::Power,
            1,
            "/friction/power_w",
            "",
        ));
        let names: Vec<(&str, f64)> = f.mechanisms.iter().map(|m| (m.name, m.power_w)).collect();
        if let Some(name) = largest_mechanism(&names) {
            out.push(AnswerLine::name(
                FRICTION,
                "largest",
                name.replace('_', " "),
            ));
        }
    }
    match &a.thermal {
        Some(Ok(th)) => out.extend(thermal_lines(&th.view())),
        Some(Err(e)) => out.push(AnswerLine::number(
            crate::bearings::answer::TEMPERATURE,
            "hottest, steady",
            None,
            Display::Temperature,
            1,
            "",
            e,
        )),
        None => {}
    }
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
