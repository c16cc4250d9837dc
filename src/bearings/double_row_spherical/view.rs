//! What a solved double-row bearing shows: the `rollers` table of both rows (row and
//! guide-ring columns), the roller loads against azimuth per row, summary lines, key
//! outputs and the stiffness block.

use super::losses::LossBreakdown;
use super::report::{stiffness_lines, stiffness_xz};
use super::statics::DoubleRowAnalysis;
use crate::bearings::view::{
    Chart, ChartAxis, Column, CsvStyle, Display, KeyOutput, KeyRole, Screen, Series, SolveStats,
    Summary, Table, TextBlock, View,
};
use crate::units::{Quantity, Units};

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

/// Columns of the `rollers` table.
pub const ROLLER_COLUMNS: [Column; 9] = [
    col(
        "row",
        Quantity::Count,
        CsvStyle::Integer,
        "row",
        Display::Plain,
        0,
        3,
    ),
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
        "Q_i",
        Display::Force,
        1,
        9,
    ),
    col(
        "outer_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "Q_o",
        Display::Force,
        1,
        9,
    ),
    col(
        "inner_angle_deg",
        Quantity::Angle,
        CsvStyle::Plain,
        "α_i deg",
        Display::Plain,
        2,
        8,
    ),
    col(
        "outer_angle_deg",
        Quantity::Angle,
        CsvStyle::Plain,
        "α_o deg",
        Display::Plain,
        2,
        8,
    ),
    col(
        "guide_ring_load_n",
        Quantity::Force,
        CsvStyle::Scientific,
        "F_g",
        Display::Force,
        2,
        9,
    ),
    col(
        "max_stress_pa",
        Quantity::Pressure,
        CsvStyle::Scientific,
        "σ_max",
        Display::Stress,
        0,
        8,
    ),
];

/// The view of a solved case.
pub fn view(a: &DoubleRowAnalysis) -> View {
    let mut rows = Vec::new();
    for (i, ra) in a.rows.iter().enumerate() {
        let z = ra.load.rollers.len();
        for (j, r) in ra.load.rollers.iter().enumerate() {
            let stress = ra
                .stresses
                .as_ref()
                .and_then(|s| s.rollers.get(j))
                .map(|s| s[0].max_stress_pa.max(s[1].max_stress_pa));
            let g = a.combined.rollers.get(i * z + j).map(|x| x.guide_force_n);
            rows.push(vec![
                Some((i + 1) as f64),
                Some(r.index as f64),
                Some(r.azimuth_deg),
                Some(r.inner.normal_load_n),
                Some(r.outer.normal_load_n),
                Some(r.inner.contact_angle_deg),
                Some(r.outer.contact_angle_deg),
                g,
                stress,
            ]);
        }
    }
    let names: [[&'static str; 2]; 2] = [
        ["row 1 inner", "row 1 outer"],
        ["row 2 inner", "row 2 outer"],
    ];
    let mut series = Vec::new();
    for (i, ra) in a.rows.iter().enumerate() {
        for (k, name) in names[i.min(1)].iter().enumerate() {
            series.push(Series {
                display: None,
                name,
                points: ra
                    .load
                    .rollers
                    .iter()
                    .map(|r| {
                        let c = if k == 0 { &r.inner } else { &r.outer };
                        (r.azimuth_deg, c.normal_load_n)
                    })
                    .collect(),
            });
        }
    }
    let load_chart = Chart {
        title: "Roller loads against azimuth per row (load zone: Q > 0)".to_string(),
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
        series,
        per_element: true,
        operating: None,
    };
    let k = stiffness_xz(a);
    let summary = vec![
        Summary {
            label: "Δx",
            value: a.radial_deflection_m(),
            display: Display::Deflection,
            precision: 3,
        },
        Summary {
            label: "Δz",
            value: a.axial_deflection_m(),
            display: Display::Deflection,
            precision: 3,
        },
        Summary {
            label: "Q_max",
            value: a.max_roller_load_n(),
            display: Display::Force,
            precision: 1,
        },
        Summary {
            label: "F_g row 1",
            value: a.guide.force_row1_n,
            display: Display::Force,
            precision: 2,
        },
        Summary {
            label: "F_g row 2",
            value: a.guide.force_row2_n,
            display: Display::Force,
            precision: 2,
        },
    ];
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
            "Q_max",
            Some(a.max_roller_load_n()),
            Quantity::Force,
            KeyRole::Target,
        ),
        key(
            "max_stress_pa",
            "σ_max",
            Some(a.max_stress_pa()),
            Quantity::Pressure,
            KeyRole::Target,
        ),
        key(
            "radial_deflection_m",
            "Δx",
            Some(a.radial_deflection_m()),
            Quantity::Length,
            KeyRole::Target,
        ),
        key(
            "axial_deflection_m",
            "Δz",
            Some(a.axial_deflection_m()),
            Quantity::Length,
            KeyRole::Info,
        ),
        key(
            "stiffness_xx_n_m",
            "Kxx",
            Some(k[0][0]),
            Quantity::LinearStiffness,
            KeyRole::Target,
        ),
        key(
            "stiffness_zz_n_m",
            "Kzz",
            Some(k[1][1]),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
        // Issue 29: the 5×5's y diagonal (θ_x, θ_y are zero: self-aligning).
        key(
            "stiffness_yy_n_m",
            "Kyy",
            a.stiffness
                .as_ref()
                .ok()
                .and_then(|m| m.diagonal(crate::bearings::stiffness::Dof::Y)),
            Quantity::LinearStiffness,
            KeyRole::Info,
        ),
        key(
            "guide_ring_row1_n",
            "F_g1",
            Some(a.guide.force_row1_n),
            Quantity::Force,
            KeyRole::Info,
        ),
        key(
            "l10_h",
            "L10 h",
            a.l10_h,
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
        // Issue 28: the load-distribution life in Mrev and ISO 76's s0.
        key(
            "l10_bearing_mrev",
            "L10",
            a.l10_mrev,
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
        key(
            "static_safety",
            "s0",
            crate::physics::rating::static_safety(
                crate::physics::rating::ContactKind::Roller,
                a.max_stress_pa(),
            ),
            Quantity::Dimensionless,
            KeyRole::Guard,
        ),
    ];
    let st = &a.combined.stats;
    View {
        system: super::SYSTEM_ID,
        tables: vec![Table {
            id: "rollers",
            columns: ROLLER_COLUMNS.to_vec(),
            rows,
        }],
        charts: vec![load_chart],
        element_charts: Vec::new(),
        element_chart_pane: 0,
        summary,
        key_outputs,
        trace: None,
        thermal: None,
        stats: SolveStats {
            iterations: st.iterations,
            inner_iterations: st.roller_iterations,
            names: ["ring Newton", "roller Newton"],
            wall_time_s: a.wall_time_s,
            warm_start: false,
        },
        warnings: crate::physics::rating::static_safety_warning(
            crate::physics::rating::ContactKind::Roller,
            a.max_stress_pa(),
        )
        .into_iter()
        .map(|w| crate::bearings::view::Warning {
            si: w.clone(),
            us: w,
        })
        .collect(),
        texts: vec![TextBlock {
            title: "stiffness",
            si: stiffness_lines(a, Units::Si),
            us: stiffness_lines(a, Units::Us),
        }],
        answer: super::answer::answer(a, None),
    }
}

/// The Losses pane's lines in `units`: one bar per mechanism (length ∝ its share of the
/// total, 20 cells for the largest), its W and %, then M_fi, M_fo, M, the cage's speed
/// (measured or balanced), its slip and torque imbalance, and the guide ring's speed.
pub fn loss_bars(l: &LossBreakdown, units: Units) -> Vec<String> {
    let x = &l.losses;
    let s = &x.shares_pct;
    let rows = [
        ("raceway in", x.raceway_inner_w, s.raceway_inner),
        ("raceway out", x.raceway_outer_w, s.raceway_outer),
        ("guide ring", x.guide_ring_w, s.guide_ring),
        ("pockets", x.cage_pockets_w, s.cage_pockets),
        ("cage land", x.cage_land_w, s.cage_land),
        ("skew", x.skew_w, s.skew),
        ("drag (off)", x.drag_w, s.drag),
    ];
    let top = rows.iter().map(|r| r.2.abs()).fold(0.0, f64::max);
    let mut v = vec![format!("Loss by mechanism, total {:.3} W", x.total_w)];
    for (name, w, p) in rows {
        let n = if top > 0.0 {
            (20.0 * p.abs() / top).round() as usize
        } else {
            0
        };
        v.push(format!(
            "{name:<11} {w:>9.3} W {p:>6.2} % {}",
            "█".repeat(n.min(20))
        ));
    }
    let t = Quantity::Moment;
    let u = t.unit(units);
    v.push(String::new());
    v.push(format!(
        "M_fi {:.4} {u}   M_fo {:.4} {u}   M {:.4} {u}",
        t.from_si(x.friction_torque_inner_nm, units),
        t.from_si(x.friction_torque_outer_nm, units),
        t.from_si(x.friction_torque_nm, units)
    ));
    v.push(format!(
        "cage {:.1} rpm ({}), slip {:.2} %",
        x.cage_speed_rpm,
        if l.cage_speed_computed {
            "balanced"
        } else {
            "measured"
        },
        x.cage_slip_pct,
    ));
    v.push(format!(
        "cage imbalance {} {u}",
        crate::bearings::view::fixed(t.from_si(x.cage_torque_imbalance_nm, units), 4)
    ));
    if let Some(g) = &l.guide_ring {
        v.push(format!(
            "guide ring {:.1} rpm",
            g.speed_rad_s * 30.0 / std::f64::consts::PI
        ));
    }
    v
}

/// [`view`] with the Losses pane's text block (`texts[1]`).
pub fn view_with_losses(a: &DoubleRowAnalysis, l: &LossBreakdown) -> View {
    let mut v = view(a);
    v.texts.push(TextBlock {
        title: "losses",
        si: loss_bars(l, Units::Si),
        us: loss_bars(l, Units::Us),
    });
    v.answer = super::answer::answer(a, Some(l));
    // Issue 28: the bearing's friction torque and loss as key outputs (sweeps, bench).
    for (name, label, value, quantity) in [
        (
            "friction_torque_nm",
            "M",
            l.losses.friction_torque_nm,
            Quantity::Moment,
        ),
        ("total_loss_w", "loss", l.losses.total_w, Quantity::Power),
    ] {
        v.key_outputs.push(KeyOutput {
            name,
            label,
            value: Some(value),
            quantity,
            role: KeyRole::Guard,
        });
    }
    v
}
