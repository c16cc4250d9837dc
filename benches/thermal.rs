//! Thermal network timings on the shipped rig (`decks/aerospace.toml`): the steady solve
//! and one simulated hour of the loss-of-oil transient with each integrator.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::thermal::{
    parse_thermal, run_transient, solve_steady, HeatInput, Integrator, ThermalModel,
    TransientSettings,
};
use rollbench::units::Units;

fn rig() -> ThermalModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/aerospace.toml");
    let text = std::fs::read_to_string(path).expect("shipped thermal deck");
    let table: toml::Table = toml::from_str(&text).expect("valid TOML");
    parse_thermal(&table, Units::Si).expect("valid [thermal] section")
}

const HEAT: HeatInput = HeatInput {
    inner_contacts_w: 900.0,
    outer_contacts_w: 700.0,
    cage_rails_w: 150.0,
    viscous_drag_w: 350.0,
};

const LOSS_HEAT: HeatInput = HeatInput {
    inner_contacts_w: 1100.0,
    outer_contacts_w: 900.0,
    cage_rails_w: 250.0,
    viscous_drag_w: 20.0,
};

fn bench_thermal(c: &mut Criterion) {
    let model = rig();
    c.bench_function("thermal/steady_rig", |b| {
        b.iter(|| solve_steady(black_box(&model.network), black_box(&HEAT)).unwrap())
    });
    let steady = solve_steady(&model.network, &HEAT).unwrap();
    for (label, integrator) in [
        ("implicit", Integrator::Implicit),
        ("explicit", Integrator::Explicit),
    ] {
        // One simulated hour at Δt = 1 s, not stopped at the limits.
        let settings = TransientSettings {
            duration_s: 3600.0,
            step_s: 1.0,
            integrator,
            stop_at_limits: false,
            ..model.transient.clone()
        };
        c.bench_function(&format!("thermal/loss_of_oil_1h_{label}"), |b| {
            b.iter(|| {
                run_transient(
                    black_box(&model.network),
                    &steady,
                    &settings,
                    black_box(&LOSS_HEAT),
                )
                .unwrap()
            })
        });
    }
}

criterion_group!(benches, bench_thermal);
criterion_main!(benches);
