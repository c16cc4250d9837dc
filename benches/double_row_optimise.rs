//! Criterion benchmark of the double-row osculation optimiser (issue 27 "Speed": a 21 × 21
//! grid × 2 load cases, ≈ 900 solves, < 3 s on 2 cores; the polish ≤ 100 solves): the
//! illustrative 22308 CC (`decks/srb_22308.toml`'s bearing) with the loss objective, the
//! pure radial and pure axial cases of its `[optimise]` table, everything the `optimise`
//! command does (nominal, grid, polish, sensitivity, lamina noise).

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::double_row_spherical::input::{DoubleRowInput, LoadCase};
use rollbench::bearings::double_row_spherical::optimise::optimise_losses;
use rollbench::numerics::cancel::Cancel;

fn bench(c: &mut Criterion) {
    let mut b = DoubleRowInput::example_22308();
    b.optimise.grid = 21;
    b.optimise.min_lambda = 2.5;
    b.optimise.load_cases = vec![
        LoadCase {
            radial_load_n: 20_000.0,
            axial_load_n: 0.0,
            weight: 1.0,
        },
        LoadCase {
            radial_load_n: 0.0,
            axial_load_n: 6_000.0,
            weight: 1.0,
        },
    ];
    let mut g = c.benchmark_group("double_row_optimise");
    g.sample_size(10);
    g.bench_function("grid_21x21_2_cases_and_polish", |bench| {
        bench.iter(|| optimise_losses(&b, "bench", Cancel::NONE).map(|o| o.solves))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
