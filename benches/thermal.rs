//! Thermal network timings on the shipped rig (`decks/aerospace.toml`): the steady solve
//! and one simulated hour of the loss-of-oil transient with each integrator.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::deck::thermal::parse_thermal;
use rollbench::thermal::{
    run_transient, solve_steady, HeatInput, HeatSource, Integrator, ThermalModel, TransientSettings,
};
use rollbench::units::Units;

fn rig() -> ThermalModel {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/aerospace.toml");
    let text = std::fs::read_to_string(path).expect("shipped thermal deck");
    let table: toml::Table = toml::from_str(&text).expect("valid TOML");
    parse_thermal(&table, Units::Si).expect("valid [thermal] section")
}

fn heat() -> HeatInput {
    HeatInput::new()
        .with(HeatSource::InnerContacts, 900.0)
        .with(HeatSource::OuterContacts, 700.0)
        .with(HeatSource::CageRails, 150.0)
        .with(HeatSource::ViscousDrag, 350.0)
}

fn loss_heat() -> HeatInput {
    HeatInput::new()
        .with(HeatSource::InnerContacts, 1100.0)
        .with(HeatSource::OuterContacts, 900.0)
        .with(HeatSource::CageRails, 250.0)
        .with(HeatSource::ViscousDrag, 20.0)
}

fn bench_thermal(c: &mut Criterion) {
    let model = rig();
    let heat = heat();
    let loss = loss_heat();
    c.bench_function("thermal/steady_rig", |b| {
        b.iter(|| solve_steady(black_box(&model.network), black_box(&heat)).unwrap())
    });
    let steady = solve_steady(&model.network, &heat).unwrap();
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
                    black_box(&loss),
                )
                .unwrap()
            })
        });
    }
}

criterion_group!(benches, bench_thermal);
criterion_main!(benches);
