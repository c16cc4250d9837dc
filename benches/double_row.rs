//! Criterion benchmarks of the double-row spherical roller bearing (issue 27 "Speed"): the
//! pipeline on the illustrative 22308 CC (`decks/srb_22308.toml`'s bearing: 2 rows × 13
//! rollers × 81 laminae, floating guide ring, cages) under radial, axial and combined load,
//! the statics alone and with the loss breakdown (target < 2 ms), the losses stage alone
//! with the cage speed measured and computed (target < 10 ms); and a 30-point load sweep
//! of the Torque-vs-load pane (F/C = 0.01 … 0.30, radial; target < 60 ms), cold (every
//! point from the statics' own start) and warm (each point from its neighbour's solution).

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::double_row_spherical::input::{CageSpeedSource, DoubleRowInput};
use rollbench::bearings::double_row_spherical::load_sweep::{
    dynamic_rating_n, torque_point, torque_sweep, Direction,
};
use rollbench::bearings::double_row_spherical::losses::losses;
use rollbench::bearings::double_row_spherical::statics::analyse;

/// The shipped deck's bearing under (F_r, F_a).
fn at(fr: f64, fa: f64) -> DoubleRowInput {
    let mut b = DoubleRowInput::example_22308();
    b.operating.radial_load_n = fr;
    b.operating.axial_load_n = fa;
    b
}

fn bench(c: &mut Criterion) {
    let cases = [
        ("radial", at(20_000.0, 0.0)),
        ("axial", at(0.0, 6_000.0)),
        ("combined", at(20_000.0, 2_000.0)),
    ];
    let mut g = c.benchmark_group("double_row_statics");
    for (name, b) in &cases {
        g.bench_function(*name, |bch| bch.iter(|| analyse(b, "bench", None)));
    }
    g.finish();
    let mut g = c.benchmark_group("double_row_pipeline");
    for (name, b) in &cases {
        g.bench_function(*name, |bch| {
            bch.iter(|| analyse(b, "bench", None).map(|a| losses(&a).map(|l| l.losses.total_w)))
        });
    }
    g.finish();
    // The losses stage alone (statics solved once, outside the timing), the cage speed
    // measured (the example's) and computed (the shipped deck's: the cage's torque balance,
    // every roller's spin re-solved per cage iterate; target < 10 ms).
    let mut g = c.benchmark_group("double_row_losses");
    for (name, b) in &cases {
        for cage in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
            let mut b = b.clone();
            b.cage.speed = cage;
            let Ok(a) = analyse(&b, "bench", None) else {
                continue;
            };
            let tag = match cage {
                CageSpeedSource::Measured => "measured",
                CageSpeedSource::Computed => "computed",
            };
            g.bench_function(format!("{name}_{tag}_cage"), |bch| {
                bch.iter(|| losses(&a).map(|l| l.losses.total_w))
            });
        }
    }
    g.finish();
    let b = DoubleRowInput::example_22308();
    let c_n = dynamic_rating_n(&b).unwrap_or(100e3);
    let values: Vec<f64> = (1..=30).map(|k| 0.01 * k as f64).collect();
    let mut g = c.benchmark_group("double_row_sweep_30");
    g.sample_size(10);
    g.bench_function("radial_cold", |bch| {
        bch.iter(|| {
            values
                .iter()
                .map(|x| torque_point(&b, "bench", Direction::Radial, *x, c_n, None))
                .collect::<Vec<_>>()
        })
    });
    g.bench_function("radial_warm", |bch| {
        bch.iter(|| torque_sweep(&b, "bench", Direction::Radial, &values, c_n, None))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
