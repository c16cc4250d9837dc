//! What a solved tapered roller bearing shows: the `rollers` table (CSV and the Rollers
//! pane), the load chart against azimuth, each roller's line load, summary lines and the
//! key outputs of the fidelity bench.

use super::analysis::Analysis;
use crate::bearings::view::{
    Chart, ChartAxis, Column, CsvStyle, Display, KeyOutput, KeyRole, Screen, Series, SolveStats,
    Summary, Table, View, FLAG,
};
use crate::units::Quantity;

/// A column in the CSV and the pane.
const fn col(
    key: &'static str,
    q: Quantity,
    csv: CsvStyle,
    label: &'static str,
    d: Display,
    p: usize,
    w: u16,
) -> Column {
    Column {
        key,
        quantity: q,
        csv: Some(csv),
        screen: Some(Screen {
            label,
            display: d,
            precision: p,
            width: w,
        }),
    }
}

/// Columns of the `rollers` table (issue 17's per-roller fields; the state as a code:
/// 0 both races, 1 cup and flange, 2 free; edge flags 0/1 in CSV, words on screen).
pub const ROLLER_COLUMNS: [Column; 12] = [
    col(
        "index",
        Quantity::Count,
        CsvStyle::Integer,
        "#",
        Display::Plain,
        0,
        3,
    ),
    col(
        "azimuth_deg",
        Quantity::Angle,
        CsvStyle::Plain,
        "ψ deg",
        Display::Plain,
        1,
        6,
    ),
    col(
        "state",
        Quantity::Count,
        CsvStyle::Integer,
        "state",
        Display::Choice(&STATE_NAMES),
        0,
        14,
    ),
    col(
        "outer_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "P1 cup",
        Display::Force,
        1,
        9,
    ),
    col(
        "inner_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "P2 cone",
        Display::Force,
        1,
        9,
    ),
    col(
        "flange_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "P3 flange",
        Display::Force,
        2,
        10,
    ),
    col(
        "outer_moment_nm",
        Quantity::Moment,
        CsvStyle::Scientific,
        "M1",
        Display::Moment,
        4,
        9,
    ),
    col(
        "inner_moment_nm",
        Quantity::Moment,
        CsvStyle::Scientific,
        "M2",
        Display::Moment,
        4,
        9,
    ),
    col(
        "outer_edge_loaded",
        Quantity::Count,
        CsvStyle::Integer,
        "edge1",
        FLAG,
        0,
        5,
    ),
    col(
        "inner_edge_loaded",
        Quantity::Count,
        CsvStyle::Integer,
        "edge2",
        FLAG,
        0,
        5,
    ),
    col(
        "max_stress_outer_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
        "σ1",
        Display::Stress,
        1,
        8,
    ),
    col(
        "max_stress_inner_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
        "σ2",
        Display::Stress,
        1,
        8,
    ),
];

/// A CSV-only column (the Rollers pane keeps its width).
const fn csv_col(key: &'static str, q: Quantity) -> Column {
    Column {
        key,
        quantity: q,
        csv: Some(CsvStyle::Scientific),
        screen: None,
    }
}

/// Columns added to the `rollers` table when the deck gives a lubricant (issue 28): the
/// thinnest loaded slice film on each raceway, and the rib contact's film, µ and power.
pub const FILM_COLUMNS: [Column; 5] = [
    csv_col("min_film_outer_m", Quantity::Length),
    csv_col("min_film_inner_m", Quantity::Length),
    csv_col("flange_min_film_m", Quantity::Length),
    csv_col("flange_friction_coefficient", Quantity::Dimensionless),
    csv_col("flange_power_w", Quantity::Dimensionless),
];

/// The states' names, by code (the JSON's `rollers[].state`).
pub const STATE_NAMES: [&str; 3] = ["both-races", "cup-and-flange", "free"];

/// The state code of the table.
fn state_code(s: super::roller::RollerState) -> f64 {
    match s {
        super::roller::RollerState::BothRaces => 0.0,
        super::roller::RollerState::CupAndFlange => 1.0,
        super::roller::RollerState::Free => 2.0,
    }
}

/// The view of a solved case.
pub fn view(a: &Analysis) -> View {
    let sol = &a.solution;
    let trib = a.tribology.as_ref().and_then(|t| t.as_ref().ok());
    let rows: Vec<Vec<Option<f64>>> = sol
        .rollers
        .iter()
        .enumerate()
        .map(|(q, (r, _, _))| {
            let (c, s) = a.bearing.azimuth[q];
            let flag = |b: bool| if b { 1.0 } else { 0.0 };
            [
                (q + 1) as f64,
                s.atan2(c).to_degrees().rem_euclid(360.0),
                state_code(r.state),
                r.cup.load_n,
                r.cone.load_n,
                r.flange_n,
                r.cup.moment_nm,
                r.cone.moment_nm,
                flag(r.cup.edge_loaded),
                flag(r.cone.edge_loaded),
                r.cup.max_stress_pa,
                r.cone.max_stress_pa,
            ]
            .into_iter()
            .map(Some)
            .chain(trib.into_iter().flat_map(|t| {
                let f = &t.rollers[q];
                let min = |s: &[super::tribology::SliceFilm]| {
                    s.iter()
                        .map(|x| x.min_film_m)
                        .filter(|h| *h > 0.0)
                        .reduce(f64::min)
                };
                let loaded = f.flange.load_n > 0.0;
                [
                    min(&f.cup),
                    min(&f.cone),
                    loaded.then_some(f.flange.min_film_m),
                    loaded.then_some(f.flange.friction_coefficient),
                    Some(f.flange.power_w),
                ]
            }))
            .collect()
        })
        .collect();
    let mut columns = ROLLER_COLUMNS.to_vec();
    if trib.is_some() {
        columns.extend(FILM_COLUMNS);
    }
    let azimuth = |q: usize| {
        let (c, s) = a.bearing.azimuth[q];
        s.atan2(c).to_degrees().rem_euclid(360.0)
    };
    let series = |name: &'static str, f: &dyn Fn(&super::roller::RollerSolution) -> f64| Series {
        display: None,
        name,
        points: sol
            .rollers
            .iter()
            .enumerate()
            .map(|(q, (r, _, _))| (azimuth(q), f(r)))
            .collect(),
    };
    let load_chart = Chart {
        title: "Roller loads against azimuth".to_string(),
        x: ChartAxis {
            label: "ψ deg",
            display: Display::Plain,
            bounds: Some([0.0, 360.0]),
        },
        y: ChartAxis {
            label: "load",
            display: Display::Force,
            bounds: None,
        },
        series: vec![
            series("cup P1", &|r| r.cup.load_n),
            series("cone P2", &|r| r.cone.load_n),
            series("flange P3", &|r| r.flange_n),
        ],
        title_us: None,
        per_element: true,
        operating: None,
    };
    let element_charts = a
        .slices
        .iter()
        .enumerate()
        .map(|(q, [cup, cone])| Chart {
            title: format!("Roller {} line load along the effective length", q + 1),
            x: ChartAxis {
                label: "X",
                display: Display::SmallLength,
                bounds: None,
            },
            y: ChartAxis {
                label: "p",
                display: Display::LineLoad,
                bounds: None,
            },
            series: vec![
                Series {
                    display: None,
                    name: "cup",
                    points: cup.iter().map(|s| (s.x_m, s.load_n_m)).collect(),
                },
                Series {
                    display: None,
                    name: "cone",
                    points: cone.iter().map(|s| (s.x_m, s.load_n_m)).collect(),
                },
            ],
            title_us: None,
            per_element: false,
            operating: None,
        })
        .collect();
    let k = &a.stiffness;
    let max_of = |f: &dyn Fn(&super::roller::RollerSolution) -> f64| {
        sol.rollers.iter().map(|(r, _, _)| f(r)).fold(0.0, f64::max)
    };
    let max_stress = max_of(&|r| r.cup.max_stress_pa.max(r.cone.max_stress_pa));
    let max_flange = max_of(&|r| r.flange_n);
    let summary = vec![
        Summary {
            label: "δz",
            value: sol.displacement_m[2],
            display: Display::Deflection,
            precision: 3,
        },
        Summary {
            label: "δx",
            value: sol.displacement_m[0],
            display: Display::Deflection,
            precision: 3,
        },
        Summary {
            label: "F_c",
            value: a.bearing.dynamics.centrifugal_force_n,
            display: Display::Force,
            precision: 2,
        },
        Summary {
            label: "max P3",
            value: max_flange,
            display: Display::Force,
            precision: 2,
        },
        Summary {
            label: "σmax",
            value: max_stress,
            display: Display::Stress,
            precision: 1,
        },
    ];
    // Stiffness key outputs carry N/m, N·m/rad in their names; the unit table has no
    // stiffness quantity yet, so they are marked dimensionless (values SI).
    let life = super::life::life(a);
    let key = |name, value: f64, quantity, role| KeyOutput {
        name,
        label: match name {
            "axial_displacement_m" => "δz",
            "stiffness_xx_n_m" => "Kxx",
            "stiffness_zz_n_m" => "Kzz",
            "stiffness_thetax_nm_rad" => "Kθθ",
            "max_flange_load_n" => "Pfl",
            "max_stress_pa" => "σmax",
            "rollers_off_cone" => "off cone",
            _ => "?",
        },
        value: Some(value),
        quantity,
        role,
    };
    let mut key_outputs = vec![
        key(
            "axial_displacement_m",
            sol.displacement_m[2],
            Quantity::Length,
            KeyRole::Target,
        ),
        key(
            "stiffness_xx_n_m",
            k[(0, 0)],
            Quantity::Dimensionless,
            KeyRole::Target,
        ),
        key(
            "stiffness_zz_n_m",
            k[(2, 2)],
            Quantity::Dimensionless,
            KeyRole::Target,
        ),
        key(
            "stiffness_thetax_nm_rad",
            k[(3, 3)],
            Quantity::Dimensionless,
            KeyRole::Target,
        ),
        key(
            "max_flange_load_n",
            max_flange,
            Quantity::Force,
            KeyRole::Target,
        ),
        key(
            "max_stress_pa",
            max_stress,
            Quantity::Pressure,
            KeyRole::Guard,
        ),
        // Rollers that have left the cone (cup-and-flange or free): the Sweep pane
        // marks the first speed where this becomes positive.
        key(
            "rollers_off_cone",
            a.solution
                .rollers
                .iter()
                .filter(|r| r.0.state != super::roller::RollerState::BothRaces)
                .count() as f64,
            Quantity::Count,
            KeyRole::Info,
        ),
        // Issue 28: the reference life and ISO 76's s0 (absent values stay absent).
        KeyOutput {
            name: "l10_bearing_mrev",
            label: "L10",
            value: life.reference.l10_bearing_mrev,
            quantity: Quantity::Dimensionless,
            role: KeyRole::Guard,
        },
        KeyOutput {
            name: "static_safety",
            label: "s0",
            value: life.iso.static_safety,
            quantity: Quantity::Dimensionless,
            role: KeyRole::Guard,
        },
    ];
    // Issue 28: the friction torque, judged by `bench` (only with a lubricant).
    if let Some(t) = trib {
        key_outputs.push(KeyOutput {
            name: "friction_torque_nm",
            label: "M",
            value: Some(t.friction.torque_nm),
            quantity: Quantity::Moment,
            role: KeyRole::Target,
        });
    }
    View {
        system: super::SYSTEM_ID,
        tables: vec![Table {
            id: "rollers",
            columns,
            rows,
        }],
        charts: vec![load_chart],
        element_charts,
        element_chart_pane: 0,
        summary,
        key_outputs,
        trace: None,
        thermal: match &a.thermal {
            Some(Ok(th)) => Some(th.view()),
            _ => None,
        },
        stats: SolveStats {
            iterations: sol.iterations,
            // The final roller solves (each a Newton on its contact approaches).
            inner_iterations: sol.rollers.iter().map(|r| r.0.iterations).sum(),
            names: ["bearing Newton", "roller Newton"],
            wall_time_s: a.wall_time_s,
            warm_start: a.warm_started,
        },
        warnings: crate::physics::rating::static_safety_warning(
            crate::physics::rating::ContactKind::Roller,
            life.max_contact_stress_pa,
        )
        .into_iter()
        .map(|w| crate::bearings::view::Warning {
            si: w.clone(),
            us: w,
        })
        .collect(),
        texts: vec![a
            .stiffness_matrix()
            .text_block(|units| super::report::pedestal_lines(a, units))],
        answer: super::answer::answer(a, &life),
    }
}
