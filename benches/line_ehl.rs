//! Criterion benchmarks of the line-contact EHL solver (issue 26 Speed): a cold solve of
//! references.md's isothermal case at 401 nodes (target ≤ 50 ms) and a warm step along a
//! cage cycle — the same contact at a 2 % higher load started from the previous
//! solution (target ≤ 10 ms); each by the Newton–Krylov path (GMRES
//! preconditioned with the last LU), the chord path and the reference path (Newton with
//! the exact Jacobian factorised at every iteration). The same case in NumPy/SciPy (the
//! reference path's algorithm, LAPACK's LU): `benches/line_ehl_scipy.py`.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::physics::ehl::line::{solve_line_ehl_with, LineEhlProblem, NewtonStrategy};
use rollbench::physics::lubrication::houpert::Houpert;
use std::hint::black_box;

/// references.md: E′ 2.21e11 Pa, η₀ 0.02 Pa·s, ū 1.5 m/s, w 5e4 N/m, R 0.02 m, G 5000.
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

fn benches(c: &mut Criterion) {
    let cold = reference(401, 5e4);
    let next = reference(401, 5.1e4);
    // The Krylov path, the chord path (the solver's default) and the reference path (the
    // exact Jacobian factorised every iteration) side by side: the ratios are the
    // speed-ups, measured in one run on a shared machine.
    for (name, strategy) in [
        ("chord", NewtonStrategy::Chord),
        ("full", NewtonStrategy::Full),
        ("krylov", NewtonStrategy::Krylov),
    ] {
        c.bench_function(&format!("line_ehl_cold_401_{name}"), |b| {
            b.iter(|| solve_line_ehl_with(black_box(&cold), None, strategy))
        });
        let before = solve_line_ehl_with(&cold, None, strategy).ok();
        c.bench_function(&format!("line_ehl_warm_step_401_{name}"), |b| {
            b.iter(|| solve_line_ehl_with(black_box(&next), before.as_ref(), strategy))
        });
    }
}

criterion_group! {
    name = group;
    config = Criterion::default().sample_size(10);
    targets = benches
}
criterion_main!(group);
