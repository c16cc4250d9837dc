//! What an Optimise pane draws, front-end free: the heat map over (k_Ci, k_W) as text (one
//! character per grid point) and the seed's Fig. 3 as charts (M_fi, M_fo and C against
//! R′/R, each as a ratio to nominal: one unit on the y axis).

use super::Optimisation;
use crate::bearings::view::{Chart, ChartAxis, Display, Series};

/// The heat map's legend.
pub const HEAT_LEGEND: &str =
    "0-9 loss (0 lowest of the grid), x infeasible, ? not solved, N nominal, O optimum, @ both";

/// The heat map over the first two variables: one line per value of the second (highest
/// first), one character per value of the first. `None` with fewer than two variables.
pub fn heat_map(o: &Optimisation) -> Option<Vec<String>> {
    let (vx, vy) = (*o.variables.first()?, *o.variables.get(1)?);
    let n = o.grid_points_per_variable;
    let finite: Vec<f64> = o.grid.iter().filter_map(|g| g.total_w).collect();
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let axis = |v: &str| -> Vec<f64> {
        let mut a: Vec<f64> = o
            .grid
            .iter()
            .filter_map(|g| g.variables.get(v).copied())
            .collect();
        a.sort_by(f64::total_cmp);
        a.dedup();
        a
    };
    let (xs, ys) = (axis(vx), axis(vy));
    if xs.len() != n || ys.len() != n {
        return None;
    }
    let nearest = |a: &[f64], v: f64| -> usize {
        a.iter()
            .enumerate()
            .min_by(|p, q| (p.1 - v).abs().total_cmp(&(q.1 - v).abs()))
            .map_or(0, |(i, _)| i)
    };
    let opt = (
        nearest(&xs, o.optimum.variables.get(vx).copied().unwrap_or(1.0)),
        nearest(&ys, o.optimum.variables.get(vy).copied().unwrap_or(1.0)),
    );
    let nom = (nearest(&xs, 1.0), nearest(&ys, 1.0));
    let mut cells = vec![vec!['?'; n]; n];
    for g in &o.grid {
        let (Some(x), Some(y)) = (g.variables.get(vx), g.variables.get(vy)) else {
            continue;
        };
        let (i, j) = (nearest(&xs, *x), nearest(&ys, *y));
        cells[j][i] = match g.total_w {
            None => '?',
            Some(_) if !g.feasible => 'x',
            Some(f) => {
                let level = if hi > lo {
                    (9.0 * (f - lo) / (hi - lo)).round()
                } else {
                    0.0
                };
                char::from_digit(level.clamp(0.0, 9.0) as u32, 10).unwrap_or('?')
            }
        };
    }
    cells[nom.1][nom.0] = 'N';
    cells[opt.1][opt.0] = if opt == nom { '@' } else { 'O' };
    Some(cells.iter().rev().map(|r| r.iter().collect()).collect())
}

/// Fig. 3 along variable `v` (index into `o.variables`) with the others at nominal (the
/// grid line through the nominal point): M_fi, M_fo and C as ratios to nominal against
/// R′/R. `None` when the grid has no such line (an even count misses the nominal).
pub fn fig3_chart(o: &Optimisation, v: usize) -> Option<Chart> {
    let name = *o.variables.get(v)?;
    let on_line = |g: &&super::GridEntry| {
        o.variables
            .iter()
            .enumerate()
            .all(|(i, w)| i == v || g.variables.get(w).is_some_and(|k| (k - 1.0).abs() < 1e-12))
    };
    let line: Vec<&super::GridEntry> = o.grid.iter().filter(on_line).collect();
    if line.len() < 2 {
        return None;
    }
    let nom = &o.nominal;
    let mut fi = Vec::new();
    let mut fo = Vec::new();
    let mut c = Vec::new();
    for g in line {
        let Some(k) = g.variables.get(name).copied() else {
            continue;
        };
        if let (Some(a), true) = (
            g.friction_torque_inner_nm,
            nom.friction_torque_inner_nm > 0.0,
        ) {
            fi.push((k, a / nom.friction_torque_inner_nm));
        }
        if let (Some(a), true) = (
            g.friction_torque_outer_nm,
            nom.friction_torque_outer_nm > 0.0,
        ) {
            fo.push((k, a / nom.friction_torque_outer_nm));
        }
        if let Some(r) = g.capacity_ratio {
            c.push((k, r));
        }
    }
    let label = super::Variable::parse(name).map_or(name, |x| x.label());
    Some(Chart {
        title: format!("M_fi, M_fo and C against {label} (ratio to nominal; others nominal)"),
        title_us: None,
        x: ChartAxis {
            label,
            display: Display::Plain,
            bounds: Some([1.0 - o.relative_range, 1.0 + o.relative_range]),
        },
        y: ChartAxis {
            label: "/ nominal",
            display: Display::Plain,
            bounds: None,
        },
        series: vec![
            Series {
                name: "M_fi",
                points: fi,
                display: None,
            },
            Series {
                name: "M_fo",
                points: fo,
                display: None,
            },
            Series {
                name: "C",
                points: c,
                display: None,
            },
        ],
        per_element: false,
        operating: None,
    })
}
