//! The Summary pane's lines of a solved double-row spherical roller bearing (issue 28):
//! life, the largest contact stress and thinnest film with the row and roller they occur
//! at, the cage and guide-ring speeds, the friction torque and loss with the largest
//! mechanism (when the losses stage ran: the Losses pane or `run`).

use super::losses::LossBreakdown;
use super::statics::DoubleRowAnalysis;
use crate::bearings::answer::{
    arg_min, largest_mechanism, life_lines, CONTACT, ELEMENTS, FRICTION, SPEEDS,
};
use crate::bearings::spherical_roller::answer::max_stress;
use crate::bearings::view::{AnswerLine, Display};

const RACE: [&str; 2] = ["inner", "outer"];
const NO_LOSSES: &str = "the losses stage has not run (the Losses pane or `run` runs it)";

/// The Summary pane's lines; the friction lines need the losses stage's `losses`.
pub fn answer(a: &DoubleRowAnalysis, losses: Option<&LossBreakdown>) -> Vec<AnswerLine> {
    let life = super::life::life(a);
    let mut out = life_lines(
        a.l10_mrev,
        a.l10_h,
        "infinite: no roller is loaded, or the rings do not turn",
        &life.iso,
    );
    let stress = a
        .rows
        .iter()
        .enumerate()
        .filter_map(|(row, r)| max_stress(r).map(|(i, k, s)| (row, i, k, s)))
        .max_by(|x, y| x.3.total_cmp(&y.3));
    let place = |row: usize, i: usize, k: usize| {
        let no = a.rows[row].load.rollers.get(i).map_or(i + 1, |r| r.index);
        format!("row {}, roller {no}, {}", row + 1, RACE[k])
    };
    out.push(
        AnswerLine::number(
            CONTACT,
            "max contact stress",
            stress.map(|s| s.3),
            Display::Stress,
            0,
            "max /rollers/*/inner/max_stress_pa /rollers/*/outer/max_stress_pa",
            "the stress stage did not run",
        )
        .at(stress.map(|(row, i, k, _)| place(row, i, k))),
    );
    let films: Vec<(usize, usize, usize, f64)> = a
        .rows
        .iter()
        .enumerate()
        .flat_map(|(row, r)| {
            r.films.iter().flat_map(move |f| {
                f.min_film.iter().enumerate().flat_map(move |(i, m)| {
                    (0..2).map(move |k| (row, i, k, m[k].unwrap_or(f64::NAN)))
                })
            })
        })
        .collect();
    let thinnest = arg_min(films.iter().map(|f| f.3)).map(|(j, _)| films[j]);
    out.push(
        AnswerLine::number(
            CONTACT,
            "min film",
            thinnest.map(|f| f.3),
            Display::Film,
            3,
            "min /rollers/*/inner/min_film_m /rollers/*/outer/min_film_m",
            "the film stage did not run",
        )
        .at(thinnest.map(|(row, i, k, _)| place(row, i, k))),
    );
    let (li, lo) = life.lambdas;
    out.push(AnswerLine::number(
        CONTACT,
        "Λ at the min film",
        match (li, lo) {
            (Some(x), Some(y)) => Some(x.min(y)),
            (x, y) => x.or(y),
        },
        Display::Plain,
        2,
        "min /life/lambda_inner /life/lambda_outer",
        "the film stage did not run",
    ));
    match losses {
        Some(l) => {
            let x = &l.losses;
            out.push(AnswerLine::number(
                SPEEDS,
                "cage",
                Some(x.cage_speed_rpm),
                Display::Rpm,
                1,
                "/losses/cage_speed_rpm",
                "",
            ));
            if let Some(g) = &l.guide_ring {
                out.push(AnswerLine::number(
                    SPEEDS,
                    "guide ring",
                    Some(g.speed_rad_s * 30.0 / std::f64::consts::PI),
                    Display::Rpm,
                    1,
                    "/guide_ring/speed_rpm",
                    "",
                ));
            }
            out.push(AnswerLine::number(
                FRICTION,
                "friction torque",
                Some(x.friction_torque_nm),
                Display::Moment,
                4,
                "/losses/friction_torque_nm",
                "",
            ));
            out.push(AnswerLine::number(
                FRICTION,
                "loss",
                Some(x.total_w),
                Display::Power,
                1,
                "/losses/total_w",
                "",
            ));
            if let Some(name) = largest_mechanism(&[
                ("inner raceways", x.raceway_inner_w),
                ("outer raceways", x.raceway_outer_w),
                ("guide ring", x.guide_ring_w),
                ("cage pockets", x.cage_pockets_w),
                ("cage land", x.cage_land_w),
                ("skew", x.skew_w),
                ("drag", x.drag_w),
            ]) {
                out.push(AnswerLine::name(FRICTION, "largest", name));
            }
        }
        None => {
            out.push(AnswerLine::number(
                SPEEDS,
                "cage",
                Some(a.dynamic.cage_rad_s * 30.0 / std::f64::consts::PI),
                Display::Rpm,
                1,
                "/dynamic_speeds/cage_rpm",
                "",
            ));
            out.push(AnswerLine::number(
                FRICTION,
                "friction torque",
                None,
                Display::Moment,
                4,
                "",
                NO_LOSSES,
            ));
        }
    }
    let loaded = a
        .combined
        .rollers
        .iter()
        // The load zone: the inner contact carries load (every outer contact carries at
        // least the roller's centrifugal force at speed).
        .filter(|r| r.inner.normal_load_n > 0.0)
        .count();
    out.push(AnswerLine::name(
        ELEMENTS,
        "in the load zone",
        format!("{loaded} of {} (both rows)", a.combined.rollers.len()),
    ));
    out
}
