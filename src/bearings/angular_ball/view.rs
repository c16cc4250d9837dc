//! What a solved ball bearing shows: the `balls` table (CSV and the Balls pane) and the
//! key outputs of the fidelity bench, SI (angles in degrees as their keys say).

use super::analysis::{BallAnalysis, BallResult, ContactResult};
use crate::bearings::view::{
    element_number, Chart, ChartAxis, Column, CsvStyle, Display, KeyOutput, KeyRole,
    OperatingPoint, Series, SolveStats, Summary, Table, Trace, TraceColumn, TraceFormat, TraceLine,
    TraceStep, View, FLAG, NUMBER_COLUMN,
};
use crate::units::{Quantity, Units};

const RPM_PER_RAD_S: f64 = 30.0 / std::f64::consts::PI;

/// Columns of the `balls` table.
/// The screen's `#` counts from 1 ([`NUMBER_COLUMN`]); the CSV's `index` keeps the JSON's
/// base, 0 (a shipped contract).
pub const COLUMNS: [Column; 22] = [
    NUMBER_COLUMN,
    Column::new("index", Quantity::Count, CsvStyle::Integer),
    Column::new("azimuth_deg", Quantity::Angle, CsvStyle::Plain).shown(
        "ψ deg",
        Display::Plain,
        1,
        6,
    ),
    Column::new("centrifugal_force_n", Quantity::Force, CsvStyle::Scientific).shown(
        "Fc",
        Display::Force,
        1,
        7,
    ),
    Column::new(
        "gyroscopic_moment_nm",
        Quantity::Moment,
        CsvStyle::Scientific,
    )
    .shown("Mg", Display::Moment, 4, 8),
    Column::new(
        "resisting_moment_nm",
        Quantity::Moment,
        CsvStyle::Scientific,
    )
    .shown("Mr", Display::Moment, 4, 8),
    Column::new("skidding", Quantity::Count, CsvStyle::Integer).shown("skid", FLAG, 0, 4),
    Column::new("heat_w", Quantity::Power, CsvStyle::Scientific).shown("H", Display::Power, 3, 7),
    Column::new("inner_normal_load_n", Quantity::Force, CsvStyle::Scientific).shown(
        "Qi",
        Display::Force,
        1,
        7,
    ),
    Column::new("inner_contact_angle_deg", Quantity::Angle, CsvStyle::Plain).shown(
        "αi °",
        Display::Plain,
        2,
        6,
    ),
    Column::new("inner_semi_major_m", Quantity::Length, CsvStyle::Scientific).shown(
        "ai",
        Display::SmallLength,
        4,
        7,
    ),
    Column::new(
        "inner_max_pressure_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
    )
    .shown("pi", Display::Stress, 0, 6),
    Column::new(
        "inner_spin_rad_s",
        Quantity::Dimensionless,
        CsvStyle::Scientific,
    )
    .shown("ωsi rad/s", Display::Plain, 1, 9),
    Column::new(
        "inner_spin_to_roll",
        Quantity::Dimensionless,
        CsvStyle::Scientific,
    )
    .shown("s/r i", Display::Plain, 3, 6),
    Column::new(
        "inner_central_film_m",
        Quantity::Length,
        CsvStyle::Scientific,
    )
    .shown("hci", Display::Film, 2, 6),
    Column::new("outer_normal_load_n", Quantity::Force, CsvStyle::Scientific).shown(
        "Qo",
        Display::Force,
        1,
        7,
    ),
    Column::new("outer_contact_angle_deg", Quantity::Angle, CsvStyle::Plain).shown(
        "αo °",
        Display::Plain,
        2,
        6,
    ),
    Column::new("outer_semi_major_m", Quantity::Length, CsvStyle::Scientific).shown(
        "ao",
        Display::SmallLength,
        4,
        7,
    ),
    Column::new(
        "outer_max_pressure_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
    )
    .shown("po", Display::Stress, 0, 6),
    Column::new(
        "outer_spin_rad_s",
        Quantity::Dimensionless,
        CsvStyle::Scientific,
    )
    .shown("ωso rad/s", Display::Plain, 1, 9),
    Column::new(
        "outer_spin_to_roll",
        Quantity::Dimensionless,
        CsvStyle::Scientific,
    )
    .shown("s/r o", Display::Plain, 3, 6),
    Column::new(
        "outer_central_film_m",
        Quantity::Length,
        CsvStyle::Scientific,
    )
    .shown("hco", Display::Film, 2, 6),
];

fn contact_cells(c: &ContactResult) -> [Option<f64>; 7] {
    [
        Some(c.load_n),
        Some(c.angle_rad.to_degrees()),
        Some(c.hertz.semi_major_m),
        Some(c.hertz.max_pressure_pa),
        Some(c.kinematics.spin_rad_s),
        Some(c.kinematics.spin_to_roll),
        c.central_film_m,
    ]
}

fn row(j: usize, b: &BallResult) -> Vec<Option<f64>> {
    let mut r = vec![
        Some(element_number(j) as f64),
        Some(j as f64),
        Some(b.azimuth_rad.to_degrees()),
        Some(b.centrifugal_n),
        Some(b.gyroscopic_moment_nm),
        Some(b.resisting_moment_nm),
        Some(if b.skidding { 1.0 } else { 0.0 }),
        Some(b.heat_w),
    ];
    r.extend(contact_cells(&b.inner));
    r.extend(contact_cells(&b.outer));
    r
}

/// Mean cage speed over the balls, rpm.
pub fn cage_rpm(a: &BallAnalysis) -> f64 {
    a.balls.iter().map(|b| b.cage_rad_s).sum::<f64>() / a.balls.len().max(1) as f64 * RPM_PER_RAD_S
}

/// The view of a solved case.
pub fn view(a: &BallAnalysis) -> View {
    let rows = a.balls.iter().enumerate().map(|(j, b)| row(j, b)).collect();
    let max_p = a.max_pressure_pa();
    let max_q = a
        .balls
        .iter()
        .map(|b| b.inner.load_n.max(b.outer.load_n))
        .fold(0.0, f64::max);
    let life = super::life::life(a);
    let k = |name, value, quantity, role| KeyOutput {
        name,
        label: short_label(name),
        value,
        quantity,
        role,
    };
    View {
        system: super::SYSTEM_ID,
        tables: vec![Table {
            id: "balls",
            columns: COLUMNS.to_vec(),
            rows,
        }],
        charts: vec![skid_chart(a), dynamics_chart(a), traction_chart(a)],
        element_charts: ball_charts(a),
        element_chart_pane: 1,
        summary: vec![
            Summary {
                label: "cage rpm",
                value: cage_rpm(a),
                display: Display::Plain,
                precision: 1,
            },
            Summary {
                label: "heat",
                value: a.total_heat_w,
                display: Display::Power,
                precision: 2,
            },
            Summary {
                label: "axial force",
                value: a.load.axial_force_n,
                display: Display::Force,
                precision: 1,
            },
        ],
        key_outputs: vec![
            k(
                "max_ball_load_n",
                Some(max_q),
                Quantity::Force,
                KeyRole::Guard,
            ),
            k(
                "max_pressure_pa",
                Some(max_p),
                Quantity::Pressure,
                KeyRole::Target,
            ),
            k(
                "cage_speed_rpm",
                Some(cage_rpm(a)),
                Quantity::Dimensionless,
                KeyRole::Guard,
            ),
            // The heat is the only key output the fidelity study's knobs (dynamics slices
            // and tolerance, see `system::FIDELITY_GRID`) change, and only when the ball
            // dynamics computes it: then it is the target that decides the recommended
            // slice count (the load distribution, pressure and skid threshold do not
            // depend on slices and are met exactly). With race control it is a guard.
            k(
                "heat_w",
                Some(a.total_heat_w),
                Quantity::Power,
                if a.dynamics.is_some() {
                    KeyRole::Target
                } else {
                    KeyRole::Guard
                },
            ),
            // Issue 28: the friction torque, the heat over |ω_i − ω_o| (follows the
            // heat: a guard).
            k(
                "friction_torque_nm",
                Some(super::friction::friction(a).torque_nm),
                Quantity::Moment,
                KeyRole::Guard,
            ),
            k(
                "skid_threshold_rpm",
                a.skid.speed_rad_s.map(|s| s * RPM_PER_RAD_S),
                Quantity::Dimensionless,
                KeyRole::Target,
            ),
            // Issue 28: the reference (load-distribution) life and ISO 76's s0, guards:
            // they follow from the loads, which the fidelity knobs do not change.
            k(
                "l10_bearing_mrev",
                life.reference
                    .as_ref()
                    .ok()
                    .and_then(|r| r.l10_bearing_mrev),
                Quantity::Dimensionless,
                KeyRole::Guard,
            ),
            k(
                "static_safety",
                life.iso.static_safety,
                Quantity::Dimensionless,
                KeyRole::Guard,
            ),
            // The stiffness diagonals (issue 29; the tapered system's names). SI values:
            // the unit table has no stiffness quantity, so they are dimensionless.
            k(
                "stiffness_xx_n_m",
                Some(a.stiffness.matrix[(0, 0)]),
                Quantity::Dimensionless,
                KeyRole::Target,
            ),
            k(
                "stiffness_zz_n_m",
                Some(a.stiffness.matrix[(2, 2)]),
                Quantity::Dimensionless,
                KeyRole::Target,
            ),
            k(
                "stiffness_thetax_nm_rad",
                Some(a.stiffness.matrix[(3, 3)]),
                Quantity::Dimensionless,
                KeyRole::Target,
            ),
        ],
        trace: trace(a),
        thermal: None,
        stats: SolveStats {
            iterations: a.load.stats.fixed_point_iterations,
            inner_iterations: a.load.stats.ring_iterations,
            names: ["fixed-point", "ring Newton"],
            wall_time_s: 0.0,
            warm_start: false,
        },
        warnings: super::warnings::warnings(a),
        texts: vec![crate::bearings::view::TextBlock {
            title: "stiffness",
            si: super::report::stiffness_lines(a, crate::units::Units::Si),
            us: super::report::stiffness_lines(a, crate::units::Units::Us),
        }],
        answer: super::answer::answer(a, &life),
    }
}

/// The short column label of a key output in `bench`'s text table.
fn short_label(name: &str) -> &'static str {
    match name {
        "max_ball_load_n" => "Qmax",
        "max_pressure_pa" => "pmax",
        "cage_speed_rpm" => "cage",
        "heat_w" => "heat",
        "friction_torque_nm" => "M",
        "skid_threshold_rpm" => "skid",
        "l10_bearing_mrev" => "L10",
        "static_safety" => "s0",
        "stiffness_xx_n_m" => "Kxx",
        "stiffness_zz_n_m" => "Kzz",
        "stiffness_thetax_nm_rad" => "Kθθ",
        _ => "?",
    }
}

/// The Skid chart (Figs. 6-4/6-5): |M_g| and the resisting torque 0.5·µ·D·(Q_i + Q_o)
/// against the relative ring speed (rpm) at the speeds the threshold search solved; the
/// crossing is the threshold.
pub fn skid_chart(a: &BallAnalysis) -> Chart {
    // The deck's relative ring speed, the chart's x quantity (issue 30 item 19), and the
    // threshold's margin to it: (deck − threshold)/threshold, + when the deck runs
    // above the threshold (its balls skid by 2-4), − when below.
    let op = &a.input.operating;
    let deck_rpm = (op.inner_speed_rad_s - op.outer_speed_rad_s).abs() * RPM_PER_RAD_S;
    let title = match a.skid.speed_rad_s {
        Some(n) if n > 0.0 => {
            let threshold = n * RPM_PER_RAD_S;
            format!(
                "skidding from {threshold:.0} rpm · deck {deck_rpm:.0} rpm · margin {:+.0} %",
                100.0 * (deck_rpm - threshold) / threshold
            )
        }
        Some(n) => format!("skidding from {:.0} rpm", n * RPM_PER_RAD_S),
        // A failed search is not "no skidding": the pane says so and why (the reason
        // names the speed whose load solve failed).
        None if a.skid.search_failed => format!(
            "skidding search failed: {}",
            a.skid.reason.as_deref().unwrap_or("")
        ),
        None => format!(
            "no skidding below the search limit · deck {deck_rpm:.0} rpm, limit {:.0} rpm",
            a.skid.limit_rad_s * RPM_PER_RAD_S
        ),
    };
    let mut chart = skid_chart_of(&a.skid.samples, title);
    chart.operating = Some(OperatingPoint {
        x: deck_rpm,
        label: "deck",
    });
    // The crossing marked: a vertical line at the threshold (the root, not a sample),
    // from 0 to the larger moment there.
    if let Some(n) = a.skid.speed_rad_s {
        let top = a
            .skid
            .samples
            .iter()
            .map(|s| s.1.max(s.2))
            .fold(0.0, f64::max);
        let x = n * RPM_PER_RAD_S;
        chart.series.push(Series {
            display: None,
            name: "threshold",
            points: vec![(x, 0.0), (x, top)],
        });
    }
    chart
}

/// The Skid chart while the search is under way (the workbench's worker sends it after
/// every speed solved, [`super::analysis::skid_threshold_streaming`]): the samples so far
/// under a title that says the search is not finished.
pub fn skid_chart_partial(samples: &[(f64, f64, f64)]) -> Chart {
    let title = format!(
        "searching for the skidding speed: {} speeds solved",
        samples.len()
    );
    skid_chart_of(samples, title)
}

fn skid_chart_of(samples: &[(f64, f64, f64)], title: String) -> Chart {
    let pts = |f: fn(&(f64, f64, f64)) -> f64| {
        samples
            .iter()
            .map(|s| (s.0 * RPM_PER_RAD_S, f(s)))
            .collect::<Vec<_>>()
    };
    Chart {
        title,
        // Display::Rpm (rpm in both systems, as Plain) so the operating marker's legend
        // names the unit; the header still reads "speed rpm".
        x: ChartAxis {
            label: "speed",
            display: Display::Rpm,
            bounds: None,
        },
        y: ChartAxis {
            label: "moment",
            display: Display::Moment,
            bounds: None,
        },
        series: vec![
            Series {
                display: None,
                name: "gyroscopic moment",
                points: pts(|s| s.1),
            },
            Series {
                display: None,
                name: "resisting torque",
                points: pts(|s| s.2),
            },
        ],
        title_us: None,
        per_element: false,
        operating: None,
    }
}

/// The Traction chart (Figs. 2-10, 6-19, 6-20): µ against the sliding speed from the
/// deck's curve (the constant, a seed curve, the table, or the tabulated rheology
/// curve), with the contacts' sliding band (`analysis::sliding_band`: the slices'
/// sliding speeds under race control's spin) marked as a box from µ = 0 to above the
/// curve. The x range covers the band (×1.5) and the curve's corners up to 5 m/s.
pub fn traction_chart(a: &BallAnalysis) -> Chart {
    use crate::physics::lubrication::traction_curve::TractionCurve;
    let curve = a.input.traction.curve();
    let band = super::analysis::sliding_band(a);
    let corners: Vec<f64> = match &curve {
        TractionCurve::Constant { .. } => Vec::new(),
        TractionCurve::Table { points } => points.iter().map(|p| p.0).collect(),
    };
    let corner_max = corners
        .iter()
        .copied()
        .filter(|&u| u <= 5.0)
        .fold(0.0, f64::max);
    let x_max = (band.map_or(0.0, |b| 1.5 * b.1))
        .max(1.2 * corner_max)
        .max(0.5);
    // Piecewise linear: the corners inside the range and the range's end draw it
    // exactly; a few evenly spaced points keep a constant curve visible.
    let mut xs: Vec<f64> = (0..=20).map(|k| x_max * k as f64 / 20.0).collect();
    xs.extend(corners.iter().copied().filter(|&u| u < x_max));
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let points: Vec<(f64, f64)> = xs.iter().map(|&u| (u, curve.mu(u))).collect();
    let top = curve.max_mu().max(1e-3) * 1.1;
    let mut series = vec![Series {
        display: None,
        name: "µ(u_s)",
        points,
    }];
    if let Some((lo, hi)) = band {
        series.push(Series {
            display: None,
            name: "sliding band",
            points: vec![(lo, 0.0), (lo, top), (hi, top), (hi, 0.0)],
        });
    }
    let title = |u: Units| {
        let name = a.input.traction.preset.name();
        match band {
            Some((lo, hi)) => {
                let sp = Display::Speed;
                format!(
                    "{name}: µ_max {:.4}, contacts slide {:.2}–{:.2} {}",
                    curve.max_mu(),
                    sp.convert(lo, u),
                    sp.convert(hi, u),
                    sp.unit(u)
                )
            }
            None => format!("{name}: µ_max {:.4}", curve.max_mu()),
        }
    };
    Chart {
        title: title(Units::Si),
        title_us: Some(title(Units::Us)),
        x: ChartAxis {
            label: "sliding",
            display: Display::Speed,
            bounds: Some([0.0, x_max]),
        },
        y: ChartAxis {
            label: "µ",
            display: Display::Plain,
            bounds: Some([0.0, top * 1.05]),
        },
        series,
        per_element: false,
        operating: None,
    }
}

/// The heat of a ball when, in its last simulated orbit, it passes its own start
/// azimuth (the sample nearest to it; under radial load this is the heat at that
/// position of the bearing, where the orbit mean would be the same for every ball), W.
fn heat_at_own_azimuth(bd: &super::dynamics::BallDynamics) -> f64 {
    let Some(last) = bd.history.last() else {
        return bd.heat_w;
    };
    let start = bd.start_azimuth_rad.to_degrees();
    bd.history
        .iter()
        .filter(|s| s.orbit_deg >= last.orbit_deg - 360.0 - 1e-9)
        .map(|s| {
            let d = (s.orbit_deg - start).rem_euclid(360.0);
            (d.min(360.0 - d), s.heat_w)
        })
        .fold(
            (f64::INFINITY, bd.heat_w),
            |a, x| if x.0 < a.0 { x } else { a },
        )
        .1
}

/// The Dynamics chart (Figs. 6-8, 6-11): heat per ball against its azimuth, race
/// control's spin heat and, when `dynamics.method` asks for it, the ball dynamics' heat
/// (time simulation: at the ball's own azimuth during the last orbit). Point i is
/// ball i.
pub fn dynamics_chart(a: &BallAnalysis) -> Chart {
    let deg = |b: &BallResult| b.azimuth_rad.to_degrees();
    let mut series = vec![Series {
        display: None,
        name: "race control",
        points: a
            .balls
            .iter()
            .map(|b| (deg(b), b.inner.spin_heat_w + b.outer.spin_heat_w))
            .collect(),
    }];
    let title = match &a.dynamics {
        Some(d) => {
            series.push(Series {
                display: None,
                name: match d.method {
                    super::input::Method::TimeSimulation => "time simulation",
                    _ => "quasi-static",
                },
                points: a
                    .balls
                    .iter()
                    .zip(&d.balls)
                    .map(|(b, bd)| (deg(b), heat_at_own_azimuth(bd)))
                    .collect(),
            });
            let mean = d.total_w() / a.balls.len().max(1) as f64;
            let state = if d.steady { "steady" } else { "oscillating" };
            let t = |u: Units| {
                let p = Display::Power;
                format!(
                    "heat per ball: {:.2} {} mean ({}, {state})",
                    p.convert(mean, u),
                    p.unit(u),
                    d.method.name(),
                )
            };
            [t(Units::Si), t(Units::Us)]
        }
        None => {
            let t = "race-control heat per ball (set dynamics.method)";
            [t.to_string(), t.to_string()]
        }
    };
    let [title, title_us] = title;
    Chart {
        title,
        title_us: Some(title_us),
        x: ChartAxis {
            label: "ψ deg",
            display: Display::Plain,
            bounds: Some([0.0, 360.0]),
        },
        y: ChartAxis {
            label: "heat",
            display: Display::Power,
            bounds: None,
        },
        series,
        per_element: true,
        operating: None,
    }
}

/// One chart per ball (Figs. 6-6, 6-7): its pivoting speed ω_t (zero under race
/// control: its departure is the skid) and its heat against the orbit position
/// travelled (degrees, unwrapped: position stands for time). Empty without dynamics.
pub fn ball_charts(a: &BallAnalysis) -> Vec<Chart> {
    let Some(d) = &a.dynamics else {
        return Vec::new();
    };
    d.balls
        .iter()
        .enumerate()
        .map(|(j, bd)| Chart {
            // Ball j + 1, as the Balls table's # and the JSON's `number` count it.
            title: per_ball_title(j, bd, Units::Si),
            title_us: Some(per_ball_title(j, bd, Units::Us)),
            x: ChartAxis {
                label: "orbit deg",
                display: Display::Plain,
                bounds: None,
            },
            y: ChartAxis {
                label: "ω_t rad/s",
                display: Display::Plain,
                bounds: None,
            },
            series: vec![
                Series {
                    display: None,
                    name: "ω_t rad/s",
                    points: bd
                        .history
                        .iter()
                        .map(|s| (s.orbit_deg, s.omega_rad_s[2]))
                        .collect(),
                },
                Series {
                    display: Some(Display::Power),
                    name: "heat",
                    points: bd.history.iter().map(|s| (s.orbit_deg, s.heat_w)).collect(),
                },
            ],
            per_element: false,
            operating: None,
        })
        .collect()
}

/// The title of ball `j`'s chart: its heat and the heat's lateral and rolling parts in
/// display units `u` (the heat curve below is in the display unit too, named in its
/// legend: `Series::display`).
fn per_ball_title(j: usize, bd: &super::dynamics::BallDynamics, u: Units) -> String {
    let p = Display::Power;
    format!(
        "ball {}: {:.2} {} ({:.2} lateral, {:.2} rolling)",
        element_number(j),
        p.convert(bd.heat_w, u),
        p.unit(u),
        p.convert(bd.lateral_w, u),
        p.convert(bd.rolling_w, u)
    )
}

/// The stepper's trace: one step per fixed-point iteration of the load distribution
/// (race control and the friction of (2-7) updated, then the ring Newton solved), showing
/// the traced ball's contact angles, loads and friction and the ring's displacement, with
/// the changes that decide convergence (angles to 1e-12 rad, loads to 1e-10).
fn trace(a: &BallAnalysis) -> Option<Trace> {
    let (ball, steps) = a.load_trace.as_ref()?;
    let line = TraceLine::new;
    let steps = steps
        .iter()
        .map(|t| TraceStep {
            iteration: vec![t.fixed_point, t.ring_iterations],
            residuals: vec![t.angle_change_rad, t.ring_residual_n],
            lines: vec![
                line(
                    "fixed point/ring",
                    Display::Plain,
                    TraceFormat::Counts,
                    vec![t.fixed_point as f64, t.ring_iterations as f64],
                ),
                line(
                    "ring ax,rad",
                    Display::Deflection,
                    TraceFormat::Signed(3),
                    t.ring_m.to_vec(),
                ),
                line(
                    "αi,αo deg",
                    Display::Plain,
                    TraceFormat::Signed(3),
                    t.angles_rad.iter().map(|r| r.to_degrees()).collect(),
                ),
                line(
                    "Qi,Qo",
                    Display::Force,
                    TraceFormat::Signed(2),
                    t.loads_n.to_vec(),
                ),
                line(
                    "µ (2-7)",
                    Display::Plain,
                    TraceFormat::Signed(5),
                    vec![t.friction],
                ),
                line(
                    "Δα max",
                    Display::SmallAngle,
                    TraceFormat::Residual,
                    vec![t.angle_change_rad],
                ),
                line(
                    "ΔQ/Q max",
                    Display::Plain,
                    TraceFormat::Residual,
                    vec![t.load_change],
                ),
                line(
                    "ring resid",
                    Display::Force,
                    TraceFormat::Residual,
                    vec![t.ring_residual_n],
                ),
            ],
            bars: Vec::new(),
        })
        .collect();
    Some(Trace {
        element: *ball,
        label: "load distribution fixed point".to_string(),
        iterations: vec!["fp", "ring"],
        residuals: vec![
            TraceColumn {
                label: "Δα",
                display: Display::SmallAngle,
            },
            TraceColumn {
                label: "ring",
                display: Display::Force,
            },
        ],
        steps,
    })
}

#[cfg(test)]
mod display_tests {
    use super::*;
    use crate::units::Units;

    /// The Balls pane's moments and heat follow the display units (they were plain SI
    /// even on a US display): N·m/lbf·in and W/Btu/hr, with the SI headers unchanged
    /// ("Mg N·m", "H W"); 1 N·m = 8.850746 lbf·in and 1 W = 3.412142 Btu/hr (1e-6).
    #[test]
    fn ball_moments_and_heat_use_display_units() {
        let col = |key: &str| {
            COLUMNS
                .iter()
                .find(|c| c.key == key)
                .and_then(|c| c.screen)
                .unwrap_or_else(|| panic!("{key}"))
        };
        for (key, si, us, per_si) in [
            ("gyroscopic_moment_nm", "Mg N·m", "Mg lbf·in", 8.850746),
            ("resisting_moment_nm", "Mr N·m", "Mr lbf·in", 8.850746),
            ("heat_w", "H W", "H Btu/hr", 3.412142),
        ] {
            let s = col(key);
            assert_eq!(s.display.header(s.label, Units::Si), si);
            assert_eq!(s.display.header(s.label, Units::Us), us);
            assert!((s.display.convert(1.0, Units::Us) / per_si - 1.0).abs() < 1e-6);
            assert_eq!(s.display.convert(1.0, Units::Si), 1.0);
        }
    }
}
