//! The cylindrical workbench's **Contact** pane (issue 26 Interfaces, a
//! [`crate::bearings::view::PaneKind::Job`]): `rollbench contact` on the deck — roller 1's
//! inner contact at the deck's `contact.positions`, the inlet(s) of `contact.inlet`,
//! isothermal, line-ehl — run by the worker while the pane is on screen and cancelled by
//! the next edit, reported position by position as a front-end-free [`JobView`]:
//!
//! * a line per position × inlet in the layout of the seed's Table 3 (W, h_c, h_min, p_max,
//!   f_b, f_v, µ, power loss), the numbers of `contact --format json` in display units;
//! * two charts of the most loaded position solved so far (one unit per axis): p(x)
//!   against the Hertz pressure of the same load, and h(x); each inlet a series.
//!
//! The position drawn is the most loaded one (the contact that matters for the film and
//! the friction); the deck's `contact.positions` choose which positions are solved.

use super::contact::{
    contact_study_cancellable, ContactError, ContactModel, ContactOptions, ContactRow,
};
use super::input::CylindricalInput;
use crate::bearings::view::{Chart, ChartAxis, Display, JobView, Series, Warning};
use crate::bearings::SolveError;
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// The units line, the Table-3 header and one line per row, in `u` (58 columns: the
/// pane's inner width at 60 columns).
fn table_lines(rows: &[ContactRow], u: Units) -> Vec<String> {
    let (f, h, p, w) = (
        Display::Force,
        Display::Film,
        Display::Stress,
        Display::Power,
    );
    let mut out = vec![
        format!(
            "film {} · pressure {} · force {} · loss {}",
            h.unit(u),
            p.unit(u),
            f.unit(u),
            w.unit(u)
        ),
        format!(
            "{:>3} {:>5} {:>5} {:>5} {:>5} {:>5} {:>5} {:>5} {:>6} {:>5}",
            "pos", "inlet", "W", "h_c", "h_min", "p_max", "f_b", "f_v", "µ", "loss"
        ),
    ];
    for r in rows {
        let s = &r.solution;
        out.push(format!(
            "{:>3.0} {:>5} {:>5.0} {:>5.3} {:>5.3} {:>5.0} {:>5.2} {:>5.2} {:>6.4} {:>5.1}",
            r.position_deg,
            if r.inlet == "flooded" {
                "flood"
            } else {
                "tipei"
            },
            f.convert(r.load_n, u),
            h.convert(s.central_film_m, u),
            h.convert(s.min_film_m, u),
            p.convert(s.max_pressure_pa, u),
            f.convert(r.boundary_friction_n, u),
            f.convert(r.viscous_friction_n, u),
            r.friction_coefficient,
            w.convert(r.power_loss_w, u),
        ));
    }
    out
}

/// The charts of the most loaded position in `rows` (its flooded and Tipei rows): p and
/// the Hertz pressure against x, and h against x.
fn profile_charts(rows: &[ContactRow]) -> Vec<Chart> {
    let Some(top) = rows
        .iter()
        .max_by(|a, b| a.load_n.total_cmp(&b.load_n))
        .map(|r| r.position_deg)
    else {
        return Vec::new();
    };
    let at: Vec<&ContactRow> = rows.iter().filter(|r| r.position_deg == top).collect();
    let name = |r: &ContactRow, flooded: &'static str, tipei: &'static str| {
        if r.inlet == "flooded" {
            flooded
        } else {
            tipei
        }
    };
    let x_axis = ChartAxis {
        label: "x",
        display: Display::SmallLength,
        bounds: None,
    };
    let mut pressure: Vec<Series> = at
        .iter()
        .map(|r| Series {
            name: name(r, "p flooded", "p Tipei"),
            points: r
                .solution
                .x_m
                .iter()
                .zip(&r.solution.pressure_pa)
                .map(|(x, p)| (*x, *p))
                .collect(),
            display: None,
        })
        .collect();
    if let Some(r) = at.first() {
        pressure.push(Series {
            name: "Hertz",
            points: r
                .solution
                .x_m
                .iter()
                .zip(&r.solution.hertz_pressure_pa)
                .map(|(x, p)| (*x, *p))
                .collect(),
            display: None,
        });
    }
    let film: Vec<Series> = at
        .iter()
        .map(|r| Series {
            name: name(r, "h flooded", "h Tipei"),
            points: r
                .solution
                .x_m
                .iter()
                .zip(&r.solution.film_m)
                .map(|(x, h)| (*x, *h))
                .collect(),
            display: None,
        })
        .collect();
    vec![
        Chart {
            title: format!("p against x at {top:.0}° (most loaded)"),
            title_us: None,
            x: x_axis.clone(),
            y: ChartAxis {
                label: "p",
                display: Display::Stress,
                bounds: None,
            },
            series: pressure,
            per_element: false,
            operating: None,
        },
        Chart {
            title: format!("h against x at {top:.0}°"),
            title_us: None,
            x: x_axis,
            y: ChartAxis {
                label: "h",
                display: Display::Film,
                bounds: None,
            },
            series: film,
            per_element: false,
            operating: None,
        },
    ]
}

/// The view of the rows solved so far.
fn view(rows: &[ContactRow], done: usize, total: usize, finished: bool) -> JobView {
    JobView {
        done,
        total,
        finished,
        stage: if finished {
            "done".into()
        } else {
            "solving".into()
        },
        heat_maps: Vec::new(),
        charts: profile_charts(rows),
        notes: table_lines(rows, Units::Si)
            .into_iter()
            .zip(table_lines(rows, Units::Us))
            .map(|(si, us)| Warning { si, us })
            .collect(),
        errors: Vec::new(),
    }
}

/// Job 0 of the cylindrical system: the contact study of the deck's positions and inlet,
/// isothermal line-ehl, reported before each position and when done.
///
/// # Errors
/// Cancelled; a position without an answer (the study's error, naming the position).
pub fn contact_job(
    input: &CylindricalInput,
    cancel: Cancel<'_>,
    report: &mut dyn FnMut(&JobView),
) -> Result<JobView, SolveError> {
    let options = ContactOptions {
        positions_deg: Vec::new(),
        inlet: input.contact.inlet,
        model: ContactModel::LineEhl,
        thermal: false,
    };
    let study = contact_study_cancellable(input, &options, cancel, &mut |done, total, _, rows| {
        if done < total {
            report(&view(rows, done, total, false));
        }
    })
    .map_err(|e| match e {
        ContactError::Cancelled => SolveError::Cancelled,
        e => SolveError::Stage {
            stage: "contact",
            message: e.to_string(),
        },
    })?;
    let n = input.contact.positions_rad.len();
    Ok(view(&study.rows, n, n, true))
}

#[cfg(test)]
mod tests {
    use super::super::contact::InletChoice;
    use super::super::deck::{contact_table, SCHEMA};
    use super::super::input::CylindricalInput;
    use crate::deck::form::Form;

    const DECK: &str = include_str!("../../../decks/crb_truck.toml");

    fn with_inlet(line: &str) -> Result<CylindricalInput, String> {
        let text = DECK.replace("\n[contact]\n", &format!("\n[contact]\n{line}\n"));
        let mut f = Form::parse(&text, "d.toml", &SCHEMA).map_err(|e| e.to_string())?;
        contact_table(&mut f).map_err(|e| e.to_string())?;
        Ok(f.value)
    }

    /// `contact.inlet` picks the Contact pane's inlets (default flooded, the shipped
    /// deck's); anything but flooded, tipei or both is refused naming the key and the
    /// words it takes.
    #[test]
    fn contact_inlet_key_is_read_and_checked() {
        assert_eq!(with_inlet("").unwrap().contact.inlet, InletChoice::Flooded);
        for (word, want) in [
            ("flooded", InletChoice::Flooded),
            ("tipei", InletChoice::Tipei),
            ("both", InletChoice::Both),
        ] {
            let input = with_inlet(&format!("inlet = \"{word}\"")).unwrap();
            assert_eq!(input.contact.inlet, want, "{word}");
        }
        for bad in ["inlet = \"starved\"", "inlet = 1"] {
            let e = with_inlet(bad).unwrap_err();
            assert!(
                e.contains("contact.inlet") && e.contains("\"flooded\", \"tipei\" or \"both\""),
                "{e}"
            );
        }
    }
}
