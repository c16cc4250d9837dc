//! What a solved cylindrical roller bearing shows: the `rollers` table (CSV and the
//! Rollers pane), roller loads against azimuth, each roller's slice loads with its
//! dub-off marked, summary lines and the key outputs.

use super::analysis::CylindricalAnalysis;
use super::report::azimuth_deg;
use crate::bearings::view::{
    Chart, ChartAxis, Column, CsvStyle, Display, KeyOutput, KeyRole, Screen, Series, SolveStats,
    Summary, Table, TextBlock, View, Warning,
};
use crate::units::{Quantity, Units};

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

/// Columns of the `rollers` table (issue 25's per-roller fields).
pub const ROLLER_COLUMNS: [Column; 7] = [
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
        "inner_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "W_i",
        Display::Force,
        1,
        9,
    ),
    col(
        "outer_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "W_o",
        Display::Force,
        1,
        9,
    ),
    col(
        "film_m",
        Quantity::Length,
        CsvStyle::Scientific,
        "h_min",
        Display::Film,
        3,
        8,
    ),
    col(
        "lambda",
        Quantity::Dimensionless,
        CsvStyle::Plain,
        "Λ",
        Display::Plain,
        2,
        6,
    ),
    col(
        "max_pressure_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
        "p_max",
        Display::Stress,
        0,
        8,
    ),
];

/// The view of a solved case.
pub fn view(a: &CylindricalAnalysis) -> View {
    let q = &a.statics;
    let rows: Vec<Vec<Option<f64>>> = q
        .rollers
        .iter()
        .zip(&a.films)
        .enumerate()
        .map(|(i, (r, f))| {
            vec![
                Some((i + 1) as f64),
                Some(azimuth_deg(r.azimuth_rad)),
                Some(r.inner_load_n),
                Some(r.outer_load_n),
                f.min_film_m,
                f.lambda,
                Some(f.max_pressure_pa),
            ]
        })
        .collect();
    let series =
        |name: &'static str, f: &dyn Fn(&super::quasi_static::RollerState) -> f64| Series {
            display: None,
            name,
            points: q
                .rollers
                .iter()
                .map(|r| (azimuth_deg(r.azimuth_rad), f(r)))
                .collect(),
        };
    let load_chart = Chart {
        title: "Roller loads against azimuth (load zone: W > 0)".to_string(),
        title_us: None,
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
            series("inner W_i", &|r| r.inner_load_n),
            series("outer W_o", &|r| r.outer_load_n),
        ],
        per_element: true,
        operating: None,
    };
    // The flat ends where the dub-off starts, ±(l/2 − l_d) from the roller's middle.
    let g = &a.input.geometry;
    let flat_half = 0.5 * a.derived.effective_length_m;
    let dub_off = g.profile == super::input::ProfileKind::DubOff && g.dub_off_length_m > 0.0;
    let element_charts = q
        .rollers
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let top = r
                .slices
                .iter()
                .map(|s| s.inner_load_n.max(s.outer_load_n))
                .fold(0.0, f64::max);
            let mut series = vec![
                Series {
                    display: None,
                    name: "inner",
                    points: r
                        .slices
                        .iter()
                        .map(|s| (s.axial_m, s.inner_load_n))
                        .collect(),
                },
                Series {
                    display: None,
                    name: "outer",
                    points: r
                        .slices
                        .iter()
                        .map(|s| (s.axial_m, s.outer_load_n))
                        .collect(),
                },
            ];
            if dub_off {
                series.push(Series {
                    display: None,
                    name: "dub-off starts",
                    points: vec![
                        (-flat_half, 0.0),
                        (-flat_half, top),
                        (flat_half, top),
                        (flat_half, 0.0),
                    ],
                });
            }
            Chart {
                title: format!("Roller {} slice loads along its length", i + 1),
                title_us: None,
                x: ChartAxis {
                    label: "axial",
                    display: Display::SmallLength,
                    bounds: None,
                },
                y: ChartAxis {
                    label: "slice load",
                    display: Display::Force,
                    bounds: None,
                },
                series,
                per_element: false,
                operating: None,
            }
        })
        .collect();
    let k = q.stiffness_n_m;
    let min_film = a.min_film_m();
    let min_lambda = a.films.iter().filter_map(|f| f.lambda).reduce(f64::min);
    let summary = vec![
        Summary {
            label: "x",
            value: q.displacement_m[0],
            // µm (µin): the ring moves about a micrometre, which mm at four
            // decimals shows as -0.0010.
            display: Display::Film,
            precision: 4,
        },
        Summary {
            label: "y",
            value: q.displacement_m[1],
            // µm (µin): the ring moves about a micrometre, which mm at four
            // decimals shows as -0.0010.
            display: Display::Film,
            precision: 4,
        },
        Summary {
            label: "W_max",
            value: a.max_roller_load_n(),
            display: Display::Force,
            precision: 1,
        },
        Summary {
            label: "F_c",
            value: a.derived.centrifugal_n,
            display: Display::Force,
            precision: 3,
        },
        Summary {
            label: "h_min",
            value: min_film.unwrap_or(0.0),
            display: Display::Film,
            precision: 3,
        },
    ];
    let life = super::life::life(a);
    let key = |name, label, value: Option<f64>, quantity, role| KeyOutput {
        name,
        label,
        value,
        quantity,
        role,
    };
    let key_outputs = vec![
        key(
            "max_roller_load_n",
            "W_max",
            Some(a.max_roller_load_n()),
            Quantity::Force,
            KeyRole::Target,
        ),
        key(
            "stiffness_xx_n_m",
            "Kxx",
            Some(k[0][0]),
            Quantity::LinearStiffness,
            KeyRole::Target,
        ),
        key(
            "stiffness_yy_n_m",
            "Kyy",
            Some(k[1][1]),
            Quantity::LinearStiffness,
            KeyRole::Target,
        ),
        // Issue 29: K_zz where ribs carry axial load (absent otherwise: the raceways
        // carry none, so there is no axial stiffness in the model).
        key(
            "stiffness_zz_n_m",
            "Kzz",
            q.stiffness_xyz_n_m.map(|k| k[2][2]),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
        key(
            "displacement_x_m",
            "x",
            Some(q.displacement_m[0]),
            Quantity::Length,
            KeyRole::Target,
        ),
        key(
            "min_film_m",
            "h_min",
            min_film,
            Quantity::Length,
            KeyRole::Info,
        ),
        key(
            "min_lambda",
            "Λmin",
            min_lambda,
            Quantity::Dimensionless,
            KeyRole::Info,
        ),
        key(
            "max_pressure_pa",
            "p_max",
            Some(a.max_pressure_pa()),
            Quantity::Pressure,
            KeyRole::Guard,
        ),
        // Issue 28: the reference life and ISO 76's s0.
        key(
            "l10_bearing_mrev",
            "L10",
            life.reference.l10_bearing_mrev,
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
        key(
            "static_safety",
            "s0",
            life.iso.static_safety,
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
    ];
    // The tribodynamics' headline numbers (absent without a dynamics run; sweeps run
    // without it).
    let mut key_outputs = key_outputs;
    if let Some(t) = &a.tribo {
        key_outputs.extend([
            key(
                "base_natural_frequency_hz",
                "f_bn Hz",
                t.dynamics.base_natural_frequency_hz,
                Quantity::Dimensionless,
                KeyRole::Info,
            ),
            key(
                "friction_total_n",
                "friction",
                Some(t.friction.total_n),
                Quantity::Force,
                KeyRole::Info,
            ),
            key(
                "friction_coefficient",
                "µ",
                Some(t.friction.coefficient),
                Quantity::Dimensionless,
                KeyRole::Info,
            ),
            key(
                "power_loss_w",
                "power",
                Some(t.friction.power_w),
                Quantity::Power,
                KeyRole::Info,
            ),
            // Issue 28: the friction torque, power over ω_i.
            key(
                "friction_torque_nm",
                "M",
                super::friction::friction(a).map(|f| f.torque_nm),
                Quantity::Moment,
                KeyRole::Info,
            ),
        ]);
    }
    View {
        system: super::SYSTEM_ID,
        tables: vec![Table {
            id: "rollers",
            columns: ROLLER_COLUMNS.to_vec(),
            rows,
        }],
        charts: std::iter::once(load_chart)
            .chain(super::view_tribo::charts(a.tribo.as_ref()))
            .collect(),
        element_charts,
        element_chart_pane: 0,
        summary,
        key_outputs,
        trace: None,
        thermal: None,
        stats: SolveStats {
            iterations: q.iterations,
            // The dynamics' accepted steps beside the ring Newton's iterations.
            inner_iterations: a.tribo.as_ref().map_or(0, |t| t.dynamics.stats.steps),
            names: ["ring Newton", "dynamics steps"],
            wall_time_s: a.wall_time_s,
            warm_start: false,
        },
        warnings: a
            .warnings
            .iter()
            .cloned()
            .chain(crate::physics::rating::static_safety_warning(
                crate::physics::rating::ContactKind::Roller,
                a.max_pressure_pa(),
            ))
            .map(|w| Warning {
                si: w.clone(),
                us: w,
            })
            .collect(),
        texts: vec![TextBlock {
            title: "stiffness",
            si: super::report::stiffness_lines(a, Units::Si),
            us: super::report::stiffness_lines(a, Units::Us),
        }],
        answer: super::answer::answer(a, &life),
    }
}
