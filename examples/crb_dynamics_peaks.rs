//! The side-by-side partner of `benches/crb_dynamics_scipy.py` (issue 25, Speed): the truck
//! bearing's 2-DOF dynamics, film off, 100 shaft revolutions, rtol 1e-8, printing the
//! wall time (median of 5 runs) and the same peaks as the SciPy script.
//! Usage: cargo run --release --example crb_dynamics_peaks [rho_m]

use rollbench::bearings::cylindrical_roller::dynamics::{simulate, DynamicsModel};
use rollbench::numerics::cancel::Cancel;
use std::time::Instant;

fn main() {
    let rho: f64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(5e-6);
    let model = DynamicsModel::truck(rho);
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..5 {
        let t0 = Instant::now();
        let r = simulate(&model, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
        times.push(t0.elapsed().as_secs_f64());
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    let Some(r) = last else { return };
    println!(
        "rollbench DOPRI5: {:.4} s (median of 5), {} rhs evaluations, {} events, rho {rho:e} m",
        times[2], r.stats.rhs_evaluations, r.stats.events
    );
    println!("static offset x {:.6e} m", r.static_offset_m[0]);
    match r.base_natural_frequency_hz {
        Some(f) => println!("f_bn {f:.4} Hz"),
        None => println!("f_bn none"),
    }
    let h: Vec<String> = r
        .roller_load_harmonics
        .iter()
        .map(|h| format!("{}:{:.4}", h.order, h.amplitude_n))
        .collect();
    println!("roller-1 load harmonics N: {}", h.join(" "));
}
