//! The spherical roller bearing's view: every stage's per-roller results joined once, by
//! roller, here. The JSON, text and CSV reports and the workbench's panes read these rows
//! and never index the stages' arrays themselves.

use super::load_distribution::{LaminaResult, RacewayContact, RollerResult};
use super::pipeline::Analysis;
use super::stages::{LaminaFriction, RacewayStress};
use crate::bearings::stiffness::Dof;
use crate::bearings::view::{
    Chart, ChartAxis, Column, CsvStyle, Display, KeyOutput, KeyRole, NodeSeries, Screen, Series,
    SolveStats, SteadyNode, Summary, Table, ThermalResults, Trace, TraceBars, TraceColumn,
    TraceFormat, TraceLine, TraceStep, Transient, View,
};
use crate::physics::contact::line::LineContact;
use crate::physics::lubrication::film;
use crate::units::Quantity;

/// One raceway contact of one roller with what each stage found there (`None`: the stage
/// was not run for this analysis).
#[derive(Debug, Clone, Copy)]
pub struct ContactView<'a> {
    /// §3 load, angle and loaded laminae.
    pub load: &'a RacewayContact,
    /// §4 stresses, ellipse and subsurface shear.
    pub stress: Option<&'a RacewayStress>,
    /// §5 thinnest lamina film, m (`Some(None)`: no lamina loaded).
    pub min_film_m: Option<Option<f64>>,
    /// §6 equivalent roller load P_e (eq. 6.1), N.
    pub equivalent_load_n: Option<f64>,
    /// §9 contact heat, W.
    pub heat_w: Option<f64>,
}

/// One lamina of one roller with what each stage found there.
#[derive(Debug, Clone, Copy)]
pub struct LaminaView<'a> {
    /// §3 lamina loads, approaches and contact points.
    pub load: &'a LaminaResult,
    /// §4 Hertz strip per raceway `[inner, outer]`.
    pub hertz: Option<&'a [LineContact; 2]>,
    /// §5 film per raceway, m.
    pub film_m: Option<[Option<f64>; 2]>,
    /// §8–9 sliding, traction and heat per raceway.
    pub friction: Option<&'a [LaminaFriction; 2]>,
}

/// One roller: its equilibrium and every stage's results at its two contacts.
#[derive(Debug, Clone)]
pub struct RollerView<'a> {
    /// §3 displacements, forces and moments.
    pub roller: &'a RollerResult,
    /// Spin relative to the cage, rpm (§7).
    pub spin_rpm: Option<f64>,
    /// Inner and outer raceway contacts.
    pub contacts: [ContactView<'a>; 2],
    /// Λ of the roller's thinnest film against the rougher raceway (eq. 6.8, composite
    /// roughness of the roller and that raceway); `None` without a film stage or a
    /// loaded lamina.
    pub lambda: Option<f64>,
    /// Laminae, in order along the roller.
    pub laminae: Vec<LaminaView<'a>>,
}

impl RollerView<'_> {
    /// The larger of the two raceways' max contact stress (edge laminae included), Pa.
    pub fn max_stress_pa(&self) -> Option<f64> {
        let [i, o] = &self.contacts;
        Some(i.stress?.max_stress_pa.max(o.stress?.max_stress_pa))
    }

    /// The roller's thinnest film at either raceway, m.
    pub fn min_film_m(&self) -> Option<f64> {
        let [i, o] = &self.contacts;
        match (i.min_film_m?, o.min_film_m?) {
            (Some(x), Some(y)) => Some(x.min(y)),
            (x, y) => x.or(y),
        }
    }

    /// Contact heat of the roller at both raceways, W.
    pub fn heat_w(&self) -> Option<f64> {
        let [i, o] = &self.contacts;
        Some(i.heat_w? + o.heat_w?)
    }
}

/// The rows of every roller of `a`: the one place the stages' per-roller arrays are joined.
pub fn rollers(a: &Analysis) -> Vec<RollerView<'_>> {
    a.load
        .rollers
        .iter()
        .enumerate()
        .map(|(j, r)| {
            let contact = |k: usize| ContactView {
                load: if k == 0 { &r.inner } else { &r.outer },
                stress: a
                    .stresses
                    .as_ref()
                    .and_then(|s| s.rollers.get(j))
                    .map(|s| &s[k]),
                min_film_m: a
                    .films
                    .as_ref()
                    .and_then(|f| f.min_film.get(j))
                    .map(|f| f[k]),
                equivalent_load_n: a
                    .life
                    .as_ref()
                    .and_then(|l| l.equivalent_loads_n.get(j))
                    .map(|p| p[k]),
                heat_w: a
                    .friction
                    .as_ref()
                    .and_then(|f| f.roller_heat_w.get(j))
                    .map(|h| h[k]),
            };
            let laminae = r
                .laminae
                .iter()
                .enumerate()
                .map(|(i, l)| LaminaView {
                    load: l,
                    hertz: a
                        .stresses
                        .as_ref()
                        .and_then(|s| s.laminae.get(j))
                        .and_then(|h| h.get(i)),
                    film_m: a
                        .films
                        .as_ref()
                        .and_then(|f| f.laminae.get(j))
                        .and_then(|f| f.get(i))
                        .copied(),
                    friction: a
                        .friction
                        .as_ref()
                        .and_then(|f| f.laminae.get(j))
                        .and_then(|f| f.get(i)),
                })
                .collect();
            let mut v = RollerView {
                roller: r,
                spin_rpm: a.speeds.spin_rpm.get(j).copied(),
                contacts: [contact(0), contact(1)],
                lambda: None,
                laminae,
            };
            if a.films.is_some() {
                let s = &a.input.surfaces;
                v.lambda = v.min_film_m().map(|h| {
                    film::film_parameter(h, s.roller_rms_m, s.inner_rms_m)
                        .min(film::film_parameter(h, s.roller_rms_m, s.outer_rms_m))
                });
            }
            v
        })
        .collect()
}

/// Columns of the `rollers` table (the CSV report's columns, in its order).
const ROLLER_COLUMNS: [Column; 13] = [
    Column::new("index", Quantity::Count, CsvStyle::Integer),
    Column::new("azimuth_deg", Quantity::Angle, CsvStyle::Plain),
    Column::new(
        "axial_displacement_m",
        Quantity::Length,
        CsvStyle::Scientific,
    ),
    Column::new(
        "radial_displacement_m",
        Quantity::Length,
        CsvStyle::Scientific,
    ),
    Column::new("tilt_rad", Quantity::Dimensionless, CsvStyle::Scientific),
    Column::new("centrifugal_force_n", Quantity::Force, CsvStyle::Scientific),
    Column::new(
        "gyroscopic_moment_nm",
        Quantity::Moment,
        CsvStyle::Scientific,
    ),
    Column::new("inner_normal_load_n", Quantity::Force, CsvStyle::Scientific),
    Column::new("inner_contact_angle_deg", Quantity::Angle, CsvStyle::Plain),
    Column::new("inner_loaded_laminae", Quantity::Count, CsvStyle::Integer),
    Column::new("outer_normal_load_n", Quantity::Force, CsvStyle::Scientific),
    Column::new("outer_contact_angle_deg", Quantity::Angle, CsvStyle::Plain),
    Column::new("outer_loaded_laminae", Quantity::Count, CsvStyle::Integer),
];

/// A pane-only column.
const fn pane(
    key: &'static str,
    q: Quantity,
    label: &'static str,
    d: Display,
    p: usize,
    w: u16,
) -> Column {
    Column::screen_only(
        key,
        q,
        Screen {
            label,
            display: d,
            precision: p,
            width: w,
        },
    )
}

/// Columns of the Rollers pane: index, azimuth, inner and outer normal load, inner and
/// outer contact angle, max stress (both raceways, edge laminae included), thinnest film,
/// its Λ, spin relative to the cage, contact heat of both raceways.
const PANE_COLUMNS: [Column; 11] = [
    pane("index", Quantity::Count, "#", Display::Plain, 0, 3),
    pane(
        "azimuth_deg",
        Quantity::Angle,
        "ψ deg",
        Display::Plain,
        1,
        5,
    ),
    pane(
        "inner_normal_load_n",
        Quantity::Force,
        "Qi",
        Display::Force,
        1,
        7,
    ),
    pane(
        "outer_normal_load_n",
        Quantity::Force,
        "Qo",
        Display::Force,
        1,
        7,
    ),
    pane(
        "inner_contact_angle_deg",
        Quantity::Angle,
        "αi °",
        Display::Plain,
        2,
        5,
    ),
    pane(
        "outer_contact_angle_deg",
        Quantity::Angle,
        "αo °",
        Display::Plain,
        2,
        5,
    ),
    pane(
        "max_stress_pa",
        Quantity::Pressure,
        "σmax",
        Display::Stress,
        0,
        6,
    ),
    pane("min_film_m", Quantity::Length, "h", Display::Film, 2, 6),
    pane("lambda", Quantity::Dimensionless, "Λ", Display::Plain, 2, 4),
    pane(
        "spin_rpm",
        Quantity::Speed,
        "spin rpm",
        Display::Plain,
        0,
        8,
    ),
    pane("heat_w", Quantity::Power, "heat", Display::Power, 1, 6),
];

/// The system-independent view of an analysis: the per-roller tables (CSV and pane),
/// the load charts, the ring deflections and the key outputs.
pub fn view(a: &Analysis) -> View {
    let rows = a
        .load
        .rollers
        .iter()
        .map(|r| {
            [
                r.index as f64,
                r.azimuth_deg,
                r.axial_displacement_m,
                r.radial_displacement_m,
                r.tilt_rad,
                r.centrifugal_force_n,
                r.gyroscopic_moment_nm,
                r.inner.normal_load_n,
                r.inner.contact_angle_deg,
                r.inner.loaded_laminae as f64,
                r.outer.normal_load_n,
                r.outer.contact_angle_deg,
                r.outer.loaded_laminae as f64,
            ]
            .into_iter()
            .map(Some)
            .collect()
        })
        .collect();
    let rollers = rollers(a);
    let pane_rows = rollers
        .iter()
        .map(|rv| {
            let r = rv.roller;
            vec![
                Some(r.index as f64),
                Some(r.azimuth_deg),
                Some(r.inner.normal_load_n),
                Some(r.outer.normal_load_n),
                Some(r.inner.contact_angle_deg),
                Some(r.outer.contact_angle_deg),
                rv.max_stress_pa(),
                rv.min_film_m(),
                rv.lambda,
                rv.spin_rpm,
                rv.heat_w(),
            ]
        })
        .collect();
    let load = |f: fn(&RollerResult) -> f64| -> Vec<(f64, f64)> {
        a.load
            .rollers
            .iter()
            .map(|r| (r.azimuth_deg, f(r)))
            .collect()
    };
    let load_chart = Chart {
        title: "roller load vs azimuth".into(),
        x: ChartAxis {
            label: "ψ deg",
            display: Display::Plain,
            bounds: Some([0.0, 360.0]),
        },
        y: ChartAxis {
            label: "",
            display: Display::Force,
            bounds: None,
        },
        series: vec![
            Series {
                display: None,
                name: "inner",
                points: load(|r| r.inner.normal_load_n),
            },
            Series {
                display: None,
                name: "outer",
                points: load(|r| r.outer.normal_load_n),
            },
        ],
        title_us: None,
        per_element: true,
        operating: None,
    };
    View {
        system: super::SYSTEM_ID,
        tables: vec![
            Table {
                id: "rollers",
                columns: ROLLER_COLUMNS.to_vec(),
                rows,
            },
            Table {
                id: "rollers_pane",
                columns: PANE_COLUMNS.to_vec(),
                rows: pane_rows,
            },
        ],
        charts: vec![load_chart],
        element_charts: a.load.rollers.iter().map(lamina_chart).collect(),
        element_chart_pane: 0,
        summary: vec![
            Summary {
                label: "axial deflection",
                value: a.load.axial_deflection_m,
                display: Display::Deflection,
                precision: 3,
            },
            Summary {
                label: "radial deflection",
                value: a.load.radial_deflection_m,
                display: Display::Deflection,
                precision: 3,
            },
        ],
        key_outputs: key_outputs(a),
        trace: trace(a),
        thermal: thermal(a),
        stats: SolveStats {
            iterations: a.load.stats.iterations,
            inner_iterations: a.load.stats.roller_iterations,
            names: ["ring", "roller"],
            wall_time_s: a.load.stats.wall_time_s,
            warm_start: false,
        },
        warnings: super::warnings::warnings(a),
        // Issue 29: the stiffness block (`rollbench stiffness`, the Stiffness pane).
        texts: a
            .stiffness
            .as_ref()
            .map(|k| vec![k.text_block(|_| Vec::new())])
            .unwrap_or_default(),
        answer: super::answer::answer(a),
    }
}

/// The stepper's trace of the requested roller: ring and roller displacements, the
/// roller's three residuals, and per lamina the loads per unit length and approaches.
/// Per unit length because cosine slicing makes the end laminae thin (see
/// [`lamina_chart`]); every roller is sliced alike, so roller 1 gives the widths.
fn trace(a: &Analysis) -> Option<Trace> {
    if a.trace.is_empty() {
        return None;
    }
    let element = a.trace_roller?;
    let widths: Vec<f64> = a
        .load
        .rollers
        .first()
        .map(|r| r.laminae.iter().map(|l| l.width_m).collect())
        .unwrap_or_default();
    let per_length = |loads: &[f64]| -> Vec<f64> {
        loads
            .iter()
            .zip(&widths)
            .map(|(&q, &w)| if w > 0.0 { q / w } else { 0.0 })
            .collect()
    };
    let line = TraceLine::new;
    let bars = |label, display, group, side, precision, values| TraceBars {
        label,
        display,
        group,
        side,
        precision,
        values,
    };
    let steps = a
        .trace
        .iter()
        .map(|t| TraceStep {
            iteration: vec![t.outer_iteration, t.ring_iteration, t.roller_iteration],
            residuals: t.residual.to_vec(),
            lines: vec![
                line(
                    "dyn/ring/roller",
                    Display::Plain,
                    TraceFormat::Counts,
                    vec![
                        t.outer_iteration as f64,
                        t.ring_iteration as f64,
                        t.roller_iteration as f64,
                    ],
                ),
                line(
                    "ring ax,rad",
                    Display::Deflection,
                    TraceFormat::Signed(2),
                    t.ring.to_vec(),
                ),
                line(
                    "roller ax,rad",
                    Display::Deflection,
                    TraceFormat::Signed(2),
                    t.roller[..2].to_vec(),
                ),
                line(
                    "roller pitch",
                    Display::SmallAngle,
                    TraceFormat::Signed(5),
                    vec![t.roller[2]],
                ),
                line(
                    "resid ax,rad",
                    Display::Force,
                    TraceFormat::Residual,
                    t.residual[..2].to_vec(),
                ),
                line(
                    "resid moment",
                    Display::Moment,
                    TraceFormat::Residual,
                    vec![t.residual[2]],
                ),
            ],
            bars: vec![
                bars(
                    "inner load",
                    Display::LineLoad,
                    0,
                    0,
                    1,
                    per_length(&t.inner_load_n),
                ),
                bars(
                    "outer load",
                    Display::LineLoad,
                    0,
                    1,
                    1,
                    per_length(&t.outer_load_n),
                ),
                bars(
                    "inner approach",
                    Display::Deflection,
                    1,
                    0,
                    2,
                    t.inner_approach_m.clone(),
                ),
                bars(
                    "outer approach",
                    Display::Deflection,
                    1,
                    1,
                    2,
                    t.outer_approach_m.clone(),
                ),
            ],
        })
        .collect();
    let label = if a.input.solver.dynamic_loads == super::DynamicLoads::Iterated {
        // The text report counts the coarse presolve's iterations too: name both
        // (issue 30 item 12: "5 dynamic-load iterations" here, "9" there).
        let all = a.speeds.iterations;
        if a.trace_outer < all {
            format!(
                "{} of {all} dynamic-load iterations ({} coarse), the last ends at the solution",
                a.trace_outer,
                all - a.trace_outer
            )
        } else {
            format!(
                "{} dynamic-load iterations, the last ends at the solution",
                a.trace_outer
            )
        }
    } else {
        "the load distribution solve".to_string()
    };
    Some(Trace {
        element,
        label,
        iterations: vec!["dyn", "ring", "roller"],
        residuals: vec![
            TraceColumn {
                label: "ax",
                display: Display::Force,
            },
            TraceColumn {
                label: "rad",
                display: Display::Force,
            },
            TraceColumn {
                label: "mom",
                display: Display::Moment,
            },
        ],
        steps,
    })
}

/// The §10 network's temperatures, when the deck has one.
pub(super) fn thermal(a: &Analysis) -> Option<ThermalResults> {
    let th = a.thermal.as_ref()?;
    Some(ThermalResults {
        steady: th
            .steady
            .nodes
            .iter()
            .map(|n| SteadyNode {
                name: n.name.clone(),
                temperature_c: n.temperature_c,
                fixed: n.fixed,
            })
            .collect(),
        transient: th.transient.as_ref().map(|tr| Transient {
            time_s: tr.time_s.clone(),
            nodes: tr
                .nodes
                .iter()
                .map(|n| NodeSeries {
                    name: n.name.clone(),
                    temperature_c: n.temperature_c.clone(),
                    limit_c: n.limit_c,
                    time_to_limit_s: n.time_to_limit_s,
                })
                .collect(),
        }),
    })
}

/// The load distribution along a roller: each lamina's load per unit length against its
/// offset from the roller centre, so edge loading shows as a rise at the ends. Per unit
/// length because cosine slicing makes the end laminae thin: their loads alone would draw
/// a hard-loaded end low.
fn lamina_chart(r: &RollerResult) -> Chart {
    let series = |name, load: fn(&LaminaResult) -> f64| Series {
        display: None,
        name,
        points: r
            .laminae
            .iter()
            .map(|l| {
                let q = if l.width_m > 0.0 {
                    load(l) / l.width_m
                } else {
                    0.0
                };
                (l.offset_m, q)
            })
            .collect(),
    };
    Chart {
        title: format!("load along roller {}", r.index),
        x: ChartAxis {
            label: "x",
            display: Display::SmallLength,
            bounds: None,
        },
        y: ChartAxis {
            label: "",
            display: Display::LineLoad,
            bounds: None,
        },
        series: vec![
            series("inner", |l| l.inner_load_n),
            series("outer", |l| l.outer_load_n),
        ],
        title_us: None,
        per_element: false,
        operating: None,
    }
}

/// Key outputs (the fidelity bench's targets and guards).
fn key_outputs(a: &Analysis) -> Vec<KeyOutput> {
    let max_roller_load_n = a
        .load
        .rollers
        .iter()
        .map(|r| r.inner.normal_load_n.max(r.outer.normal_load_n))
        .fold(0.0, f64::max);
    let max_stress_pa = a.stresses.as_ref().map_or(0.0, |s| {
        s.rollers
            .iter()
            .flat_map(|r| r.iter().map(|c| c.max_stress_pa))
            .fold(0.0, f64::max)
    });
    let hottest_temperature_c = a.thermal.as_ref().and_then(|t| {
        t.steady
            .nodes
            .iter()
            .filter(|n| !n.fixed)
            .map(|n| n.temperature_c)
            .reduce(f64::max)
    });
    let diagonal = |d: Dof| a.stiffness.as_ref().ok().and_then(|k| k.diagonal(d));
    let k = |name, label, value, quantity, role| KeyOutput {
        name,
        label,
        value,
        quantity,
        role,
    };
    vec![
        k(
            "max_roller_load_n",
            "Qmax",
            Some(max_roller_load_n),
            Quantity::Force,
            KeyRole::Guard,
        ),
        k(
            "max_stress_pa",
            "σmax",
            Some(max_stress_pa),
            Quantity::Pressure,
            KeyRole::Target,
        ),
        k(
            "l10_mrev",
            "L10",
            a.life.as_ref().and_then(|l| l.result.l10_bearing_mrev),
            Quantity::Dimensionless,
            KeyRole::Target,
        ),
        k(
            "cage_speed_rpm",
            "cage",
            Some(a.speeds.cage_rpm),
            Quantity::Speed,
            KeyRole::Guard,
        ),
        k(
            "total_heat_w",
            "heat",
            Some(a.friction.as_ref().map_or(0.0, |f| f.heat.total_w)),
            Quantity::Power,
            KeyRole::Guard,
        ),
        k(
            "hottest_temperature_c",
            "Thot",
            hottest_temperature_c,
            Quantity::Temperature,
            KeyRole::Guard,
        ),
        // Issue 28: the friction torque (heat over the relative speed: judged with it)
        // and ISO 76's static safety beside the life.
        k(
            "friction_torque_nm",
            "M",
            a.friction.as_ref().map(|f| f.heat.friction_torque_nm),
            Quantity::Moment,
            KeyRole::Guard,
        ),
        k(
            "static_safety",
            "s0",
            super::answer::static_safety_of(a),
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
        // Issue 29: the stiffness diagonals, the other systems' names (θ_x, θ_y are zero
        // by construction: self-aligning, so they are not key outputs). Info: reported
        // by `sweep` and `bench`, not judged, so the fidelity recommendation (judged on
        // stress, life and the guards above) stays what it was.
        k(
            "stiffness_xx_n_m",
            "Kxx",
            diagonal(Dof::X),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
        k(
            "stiffness_yy_n_m",
            "Kyy",
            diagonal(Dof::Y),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
        k(
            "stiffness_zz_n_m",
            "Kzz",
            diagonal(Dof::Z),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
    ]
}
