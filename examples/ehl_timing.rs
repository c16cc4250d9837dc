//! Timing of the line-EHL solver on references.md's isothermal case at 401 nodes (issue 26
//! Speed), steadier than criterion on a shared machine: the minimum and median wall time
//! of many cold solves and warm steps (the minimum is the run nobody preempted), with the
//! Newton iterations and factorisations each needs.
//! `cargo run --release --example ehl_timing [runs]`
use rollbench::physics::ehl::line::{solve_line_ehl_with, LineEhlProblem, NewtonStrategy};
use rollbench::physics::lubrication::houpert::Houpert;
use std::time::Instant;

/// references.md: E′ 2.21e11 Pa, η₀ 0.02 Pa·s, ū 1.5 m/s, w 5e4 N/m, R 0.02 m, G 5000
/// (as `benches/line_ehl.rs`).
fn reference(nodes: usize, w: f64) -> LineEhlProblem {
    let e_prime = 2.21e11;
    let r = 0.02;
    let b = (8.0 * w * r / (std::f64::consts::PI * e_prime)).sqrt();
    LineEhlProblem {
        radius_m: r,
        reduced_modulus_pa: 0.5 * e_prime,
        entrainment_m_s: 1.5,
        sliding_m_s: 0.0,
        load_per_length_n_m: w,
        rheology: Houpert {
            viscosity_pa_s: 0.02,
            pressure_viscosity_pa_inv: 5000.0 / e_prime,
            temperature_viscosity_per_k: 0.0,
            reference_temperature_k: 313.15,
            density_kg_m3: 870.0,
        },
        x_inlet_m: -4.5 * b,
        x_outlet_m: 1.5 * b,
        nodes,
        squeeze: None,
        temperature_k: None,
        max_iterations: 100,
        tolerance: 1e-8,
    }
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(30);
    let cold = reference(401, 5e4);
    let next = reference(401, 5.1e4);
    for (name, strategy) in [
        ("krylov", NewtonStrategy::Krylov),
        ("chord", NewtonStrategy::Chord),
        ("full", NewtonStrategy::Full),
    ] {
        let first = solve_line_ehl_with(&cold, None, strategy).expect("cold solve");
        for (what, warm) in [("cold", None), ("warm", Some(&first))] {
            let problem = if warm.is_some() { &next } else { &cold };
            let mut t = Vec::with_capacity(runs);
            let mut last = None;
            for _ in 0..runs {
                let s = Instant::now();
                last = Some(solve_line_ehl_with(problem, warm, strategy).expect("solve"));
                t.push(s.elapsed().as_secs_f64() * 1e3);
            }
            t.sort_by(f64::total_cmp);
            let l = last.expect("ran");
            println!(
                "{name:6} {what}: min {:7.2} ms, median {:7.2} ms; {} iterations, {} factorisations, h_c {:.6e} m",
                t[0],
                t[runs / 2],
                l.iterations,
                l.factorisations,
                l.central_film_m
            );
        }
    }
}
