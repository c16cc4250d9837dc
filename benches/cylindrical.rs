//! Criterion benchmarks of the cylindrical roller's quasi-static lamina solve (issue 25,
//! speed: ≤ 0.5 ms for 21 slices): the truck bearing of seed 003 (Table A1, ρ = 5 µm,
//! 1 990.5 N with the weight, F_c at the cage speed) cold and warm-started, at 21 and 161
//! slices, and the NASA/TM-2012-217115 210-size bearing with clearance.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::cylindrical_roller::quasi_static::{solve, Profile, QuasiStaticModel};
use rollbench::numerics::cancel::Cancel;
use rollbench::physics::material::Material;

fn truck(slices: usize) -> QuasiStaticModel {
    let r = 6.35e-3;
    let mass = std::f64::consts::PI * r * r * 0.022 * Material::STEEL.density_kg_m3;
    QuasiStaticModel {
        roller_count: 12,
        first_azimuth_rad: 0.0,
        roller_radius_m: r,
        inner_raceway_radius_m: 0.025,
        outer_raceway_radius_m: 0.0377,
        roller_length_m: 0.022,
        profile: Profile::DubOff {
            radius_m: 0.05,
            length_m: 0.003,
        },
        slices,
        radial_interference_m: 5e-6,
        centrifugal_n: mass * 83.26f64.powi(2) * 0.031_35,
        roller: Material::STEEL,
        inner: Material::STEEL,
        outer: Material::STEEL,
        load_n: [-1990.5, 0.0],
        tolerance: 1e-10,
    }
}

fn nasa210() -> QuasiStaticModel {
    QuasiStaticModel {
        roller_count: 14,
        roller_radius_m: 6.5e-3,
        inner_raceway_radius_m: 0.5 * (70.65e-3 - 13e-3),
        outer_raceway_radius_m: 0.5 * (70.65e-3 + 13e-3),
        roller_length_m: 11.05e-3,
        profile: Profile::DubOff {
            radius_m: 1.0,
            length_m: 0.0,
        },
        radial_interference_m: -0.045e-3 / 4.0,
        centrifugal_n: 0.0,
        load_n: [6940.0, 0.0],
        ..truck(21)
    }
}

fn lamina_solve(c: &mut Criterion) {
    for slices in [21, 161] {
        let m = truck(slices);
        c.bench_function(&format!("cylindrical_truck_{slices}_slices"), |b| {
            b.iter(|| {
                solve(std::hint::black_box(&m), None, &Cancel::NONE)
                    .unwrap_or_else(|e| panic!("{e}"))
            })
        });
    }
    let m = truck(21);
    let first = solve(&m, None, &Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
    let mut moved = m.clone();
    moved.load_n[0] *= 1.05;
    c.bench_function("cylindrical_truck_21_slices_warm", |b| {
        b.iter(|| {
            solve(std::hint::black_box(&moved), Some(&first), &Cancel::NONE)
                .unwrap_or_else(|e| panic!("{e}"))
        })
    });
    let m = nasa210();
    c.bench_function("cylindrical_nasa210_21_slices", |b| {
        b.iter(|| {
            solve(std::hint::black_box(&m), None, &Cancel::NONE).unwrap_or_else(|e| panic!("{e}"))
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(std::time::Duration::from_secs(3));
    targets = lamina_solve
}
criterion_main!(benches);
