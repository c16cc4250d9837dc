//! The side-by-side partner of `benches/crb_dynamics_scipy.py` (issue 25, Speed): the truck
//! bearing's 2-DOF dynamics, film off, 100 shaft revolutions, rtol 1e-8, printing the
//! wall time (median of 5 runs), the work counters and the same peaks as the SciPy script.
//! Usage: cargo run --release --example crb_dynamics_peaks [rho_m] [film] [runs]
//! (`film`: the steady film in the deflection, as the criterion bench's film-on case).

use rollbench::bearings::cylindrical_roller::dynamics::{
    simulate, DynamicsModel, FilmLaw, Squeeze,
};
use rollbench::numerics::cancel::Cancel;
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let rho: f64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(5e-6);
    let film = args.next().is_some_and(|s| s == "film");
    let runs: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(5).max(1);
    let mut model = DynamicsModel::truck(rho);
    if film {
        // The criterion bench's film-on case (benches/cylindrical_dynamics.rs).
        model.film = Some(FilmLaw {
            viscosity_pa_s: 0.0499,
            pressure_viscosity_pa_inv: 1.39e-8,
            reduced_modulus_pa: 210e9 / (1.0 - 0.09),
            reduced_radius_m: 6.35e-3 * 25e-3 / 31.35e-3,
            length_m: 0.022,
            entrainment_speed_m_s: (209.0 - 83.26) * 0.025,
            squeeze: Squeeze::None,
        });
    }
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs {
        let t0 = Instant::now();
        let r = simulate(&model, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
        times.push(t0.elapsed().as_secs_f64());
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    let Some(r) = last else { return };
    let s = r.stats;
    println!(
        "rollbench: {:.4} s (median of {runs}), {} steps, {} rejected, {} rhs evaluations, \
         {} events, rho {rho:e} m, film {}",
        times[runs / 2],
        s.steps,
        s.rejected,
        s.rhs_evaluations,
        s.events,
        if film { "on" } else { "off" }
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
