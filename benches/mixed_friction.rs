//! Criterion benchmarks of the mixed line-contact friction ("formula" tier, seed 003
//! eqs. 35–42; issue 25 Speed): one contact evaluation of the truck bearing's inner
//! contact at 41 nodes (target ≤ 2 µs: 25 ms per cage cycle of 1 000 samples × 12
//! rollers), one cage cycle of 12 000 contacts with a load that varies, and the
//! Greenwood–Tripp functions alone.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::physics::lubrication::greenwood_tripp::{f_2, f_5_2, Roughness};
use rollbench::physics::lubrication::houpert::Houpert;
use rollbench::physics::lubrication::mixed_friction::{
    mixed_friction, MixedContact, DEFAULT_NODES,
};
use std::hint::black_box;

/// The contact of the `table_3_band` test (see mixed_friction_tests.rs).
fn truck() -> MixedContact {
    MixedContact {
        load_n: 3000.0,
        effective_length_m: 0.016,
        reduced_radius_m: 6.35e-3 * 25e-3 / 31.35e-3,
        reduced_modulus_pa: 210e9 / (2.0 * (1.0 - 0.09)),
        film_m: 0.4e-6,
        roughness: Roughness {
            composite_rms_m: 0.6e-6,
            roughness_parameter: 0.055,
            asperity_slope: 1e-3,
        },
        lubricant: Houpert {
            viscosity_pa_s: 0.0499,
            pressure_viscosity_pa_inv: 1.39e-8,
            temperature_viscosity_per_k: 0.026,
            reference_temperature_k: 313.15,
            density_kg_m3: 829.3,
        },
        temperature_k: 273.15 + 40.0,
        limiting_shear_stress_pa: 2.3e6,
        limiting_shear_slope: 0.047,
        sliding_speed_m_s: 0.589,
        rolling_speed_m_s: (209.0 - 83.26) * 0.025,
        nodes: DEFAULT_NODES,
    }
}

fn contact(c: &mut Criterion) {
    let input = truck();
    c.bench_function("mixed_friction_contact_41_nodes", |b| {
        b.iter(|| mixed_friction(black_box(&input)).unwrap_or_else(|e| panic!("{e}")))
    });
    // One cage cycle: 1 000 samples × 12 rollers, loads over a load zone (0 outside it,
    // as the unloaded rollers of a real cycle), films 0.25–0.45 µm.
    let cases: Vec<MixedContact> = (0..12_000)
        .map(|i| {
            let mut c = truck();
            let angle = (i as f64) * std::f64::consts::TAU / 1000.0;
            c.load_n = (3000.0 * angle.cos()).max(0.0);
            c.film_m = 0.25e-6 + 0.2e-6 * (0.5 + 0.5 * (3.0 * angle).sin());
            c
        })
        .collect();
    c.bench_function("mixed_friction_cage_cycle_12000_contacts", |b| {
        b.iter(|| {
            let mut total = 0.0;
            for c in &cases {
                total += mixed_friction(black_box(c))
                    .unwrap_or_else(|e| panic!("{e}"))
                    .total_n;
            }
            total
        })
    });
    c.bench_function("greenwood_tripp_f_5_2", |b| {
        b.iter(|| f_5_2(black_box(0.67)))
    });
    c.bench_function("greenwood_tripp_f_2", |b| b.iter(|| f_2(black_box(0.67))));
}

criterion_group!(benches, contact);
criterion_main!(benches);
