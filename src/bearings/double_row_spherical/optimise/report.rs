//! The `optimise` output as JSON (SI, the contract), text (the deck's units for torques)
//! and CSV (the grid, SI, units in the header).

use super::Optimisation;
use crate::bearings::view::Display;
use crate::units::Units;

/// `{"optimise": {...}}`.
pub fn json(o: &Optimisation) -> serde_json::Value {
    serde_json::json!({ "optimise": o })
}

fn vars_text(v: &std::collections::BTreeMap<&'static str, f64>) -> String {
    v.iter()
        .map(|(k, x)| format!("{k} = {x:.5}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The text report.
pub fn text(o: &Optimisation, units: Units) -> String {
    let m = Display::Moment;
    let mu = m.unit(units);
    let torque = |x: f64| format!("{:.4} {mu}", m.convert(x, units));
    let opt = &o.optimum;
    let nom = &o.nominal;
    let lam = |l: Option<f64>| l.map_or("-".to_string(), |l| format!("{l:.2}"));
    let mut s = String::new();
    s.push_str(&format!(
        "OSCULATION OPTIMISER  variables {} within ±{:.2} %, {} points per variable, {} load case(s), {} laminae\n",
        o.variables.join(", "),
        o.relative_range * 100.0,
        o.grid_points_per_variable,
        o.load_cases.len(),
        o.laminae
    ));
    for (i, c) in o.load_cases.iter().enumerate() {
        s.push_str(&format!(
            "  case {}: F_r = {:.1} N, F_a = {:.1} N, weight {}\n",
            i + 1,
            c.radial_load_n,
            c.axial_load_n,
            c.weight
        ));
    }
    s.push_str(&format!(
        "nominal   total {:.3} W  M_fi {}  M_fo {}  Λ_min {}  p_max {:.0} MPa\n",
        nom.total_w,
        torque(nom.friction_torque_inner_nm),
        torque(nom.friction_torque_outer_nm),
        lam(nom.lambda_min),
        nom.max_stress_pa / 1e6
    ));
    if !nom.violated.is_empty() {
        s.push_str(&format!(
            "          the nominal radii violate: {}\n",
            nom.violated.join(", ")
        ));
    }
    s.push_str(&format!(
        "optimum   {}\n          total {:.3} W ({:+.2} % of nominal: improvement {:.2} %)  M_fi {}  M_fo {}\n          Λ_min {}  capacity ratio {:.4}  p_max ratio {:.4}\n",
        vars_text(&opt.variables),
        opt.total_w,
        -opt.improvement_pct,
        opt.improvement_pct,
        torque(opt.friction_torque_inner_nm),
        torque(opt.friction_torque_outer_nm),
        lam(opt.lambda_min),
        opt.capacity_ratio,
        opt.max_stress_ratio
    ));
    s.push_str(&format!(
        "binding   {}\n",
        if opt.binding.is_empty() {
            "none (an interior minimum)".to_string()
        } else {
            opt.binding.join(", ")
        }
    ));
    if let Some(u) = &o.unconstrained {
        s.push_str(&format!(
            "unconstrained grid minimum  {}: total {:.3} W (improvement {:.2} %), violates {}\n",
            vars_text(&u.variables),
            u.total_w,
            u.improvement_pct,
            if u.violated.is_empty() {
                "nothing".to_string()
            } else {
                u.violated.join(", ")
            }
        ));
    }
    s.push_str(&format!(
        "sensitivity (% of the loss per +0.1 % of the radius): {}\n",
        o.sensitivity_pct_per_0_1pct
            .iter()
            .map(|(k, v)| format!("{k} {v:+.3}"))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    let improvement_w = nom.total_w - opt.total_w;
    s.push_str(&format!(
        "lamina noise (Γ against 2Γ at the optimum) {:.4} W against an improvement of {:.4} W{}\n",
        o.noise_w,
        improvement_w,
        if o.noise_w >= improvement_w.abs() && improvement_w != 0.0 {
            ": the improvement is within the noise"
        } else {
            ""
        }
    ));
    let feasible = o.grid.iter().filter(|g| g.feasible).count();
    s.push_str(&format!(
        "grid      {} of {} points feasible; polish stopped: {}\n",
        feasible,
        o.grid.len(),
        o.polish_stopped
    ));
    s.push_str(&format!(
        "solves    nominal {}, grid {}, polish {}, sensitivity {}, noise {} ({:.2} s)\n",
        o.solves.nominal,
        o.solves.grid,
        o.solves.polish,
        o.solves.sensitivity,
        o.solves.noise,
        o.wall_time_s
    ));
    s
}

/// The grid as CSV (SI; one row per point, the variables first).
pub fn csv(o: &Optimisation) -> String {
    let mut s = String::new();
    let mut head: Vec<String> = o.variables.iter().map(|v| v.to_string()).collect();
    head.extend(
        [
            "total_w",
            "feasible",
            "violated",
            "lambda_min",
            "capacity_ratio",
            "max_stress_ratio",
            "friction_torque_inner_nm",
            "friction_torque_outer_nm",
        ]
        .iter()
        .map(|h| h.to_string()),
    );
    s.push_str(&head.join(","));
    s.push('\n');
    let opt = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:e}"));
    for g in &o.grid {
        let mut row: Vec<String> = o
            .variables
            .iter()
            .map(|v| g.variables.get(v).map_or(String::new(), |x| format!("{x}")))
            .collect();
        row.push(opt(g.total_w));
        row.push(if g.feasible { "1" } else { "0" }.to_string());
        row.push(g.violated.join(";"));
        row.push(opt(g.lambda_min));
        row.push(opt(g.capacity_ratio));
        row.push(opt(g.max_stress_ratio));
        row.push(opt(g.friction_torque_inner_nm));
        row.push(opt(g.friction_torque_outer_nm));
        s.push_str(&row.join(","));
        s.push('\n');
    }
    s
}
