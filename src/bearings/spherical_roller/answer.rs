//! The Summary pane's lines of a solved spherical roller bearing (issue 28): life, the
//! largest contact stress and thinnest film with the roller they occur at, the cage speed,
//! the friction torque and heat by mechanism, the hottest node of the thermal network.

use super::pipeline::Analysis;
use super::view::rollers;
use crate::bearings::answer::{self, arg_max, arg_min, CONTACT, ELEMENTS, FRICTION, LIFE, SPEEDS};
use crate::bearings::view::{AnswerLine, Display};
use crate::physics::rating::{static_safety, ContactKind};

/// The largest contact stress of any roller at either raceway, with its roller (0-based)
/// and raceway (0 inner, 1 outer), Pa.
pub fn max_stress(a: &Analysis) -> Option<(usize, usize, f64)> {
    let s = a.stresses.as_ref()?;
    let flat = s
        .rollers
        .iter()
        .flat_map(|r| [r[0].max_stress_pa, r[1].max_stress_pa]);
    arg_max(flat).map(|(i, v)| (i / 2, i % 2, v))
}

/// ISO 76's static safety from the largest contact stress (line contact).
pub fn static_safety_of(a: &Analysis) -> Option<f64> {
    max_stress(a).and_then(|(_, _, s)| static_safety(ContactKind::Roller, s))
}

const RACE: [&str; 2] = ["inner", "outer"];

/// The Summary pane's lines.
pub fn answer(a: &Analysis) -> Vec<AnswerLine> {
    let life = a.life.as_ref().map(|l| &l.result);
    let no_life = life
        .and_then(|l| l.infinite_life_reason)
        .unwrap_or("the life stage did not run");
    let mut out = vec![
        AnswerLine::number(
            LIFE,
            "L10 reference",
            life.and_then(|l| l.l10_bearing_mrev),
            Display::Mrev,
            4,
            "/life/l10_bearing_mrev",
            no_life,
        ),
        AnswerLine::number(
            LIFE,
            "L10 reference",
            life.and_then(|l| l.l10_bearing_h),
            Display::Hours,
            4,
            "/life/l10_bearing_h",
            no_life,
        ),
        AnswerLine::number(
            LIFE,
            "L10 adjusted",
            life.and_then(|l| l.adjusted_l10_bearing_mrev),
            Display::Mrev,
            4,
            "/life/adjusted_l10_bearing_mrev",
            no_life,
        ),
    ];
    // ISO 281's numbers beside seed 000's (issue 28), as every system shows them.
    out.extend(crate::bearings::answer::iso_lines(
        &super::iso_life::iso_life(a),
    ));
    out.push(AnswerLine::number(
        LIFE,
        "static safety s0",
        static_safety_of(a),
        Display::Plain,
        2,
        "/life/static_safety",
        "no contact stress",
    ));
    let (idx, race, stress) = match max_stress(a) {
        Some((i, k, s)) => (Some(i), Some(k), Some(s)),
        None => (None, None, None),
    };
    let roller_no = |i: usize| a.load.rollers.get(i).map_or(i + 1, |r| r.index);
    out.push(
        AnswerLine::number(
            CONTACT,
            "max contact stress",
            stress,
            Display::Stress,
            0,
            "max /rollers/*/inner/max_stress_pa /rollers/*/outer/max_stress_pa",
            "the stress stage did not run",
        )
        .at(idx
            .zip(race)
            .map(|(i, k)| format!("roller {}, {}", roller_no(i), RACE[k]))),
    );
    let films: Vec<f64> = rollers(a)
        .iter()
        .flat_map(|r| {
            r.contacts
                .iter()
                .map(|c| c.min_film_m.flatten().unwrap_or(f64::NAN))
                .collect::<Vec<_>>()
        })
        .collect();
    let thinnest = arg_min(films);
    out.push(
        AnswerLine::number(
            CONTACT,
            "min film",
            thinnest.map(|t| t.1),
            Display::Film,
            3,
            "min /rollers/*/inner/min_film_m /rollers/*/outer/min_film_m",
            "the film stage did not run",
        )
        .at(thinnest.map(|(i, _)| format!("roller {}, {}", roller_no(i / 2), RACE[i % 2]))),
    );
    out.push(AnswerLine::number(
        CONTACT,
        "Λ at the min film",
        a.films.as_ref().map(|f| f.lambda_inner.min(f.lambda_outer)),
        Display::Plain,
        2,
        "min /life/lambda_inner /life/lambda_outer",
        "the film stage did not run",
    ));
    out.push(AnswerLine::number(
        SPEEDS,
        "cage",
        Some(a.speeds.cage_rpm),
        Display::Rpm,
        1,
        "/speeds/cage_rpm",
        "",
    ));
    let heat = a.friction.as_ref().map(|f| &f.heat);
    out.push(AnswerLine::number(
        FRICTION,
        "friction torque",
        heat.map(|h| h.friction_torque_nm),
        Display::Moment,
        4,
        "/heat/friction_torque_nm",
        "the heat stage did not run",
    ));
    out.push(AnswerLine::number(
        FRICTION,
        "heat",
        heat.map(|h| h.total_w),
        Display::Power,
        1,
        "/heat/total_w",
        "the heat stage did not run",
    ));
    if let Some(name) = heat.and_then(|h| {
        answer::largest_mechanism(&[
            ("inner contacts", h.inner_contacts_w),
            ("outer contacts", h.outer_contacts_w),
            ("cage rails", h.cage_rails_w),
            ("viscous drag", h.viscous_drag_w),
        ])
    }) {
        out.push(AnswerLine::name(FRICTION, "largest", name));
    }
    if let Some(th) = super::view::thermal(a) {
        out.extend(answer::thermal_lines(&th));
    }
    let loaded = a
        .load
        .rollers
        .iter()
        // The load zone: the inner contact carries load (every outer contact carries at
        // least the roller's centrifugal force at speed).
        .filter(|r| r.inner.normal_load_n > 0.0)
        .count();
    out.push(AnswerLine::name(
        ELEMENTS,
        "in the load zone",
        format!("{loaded} of {}", a.load.rollers.len()),
    ));
    out
}
