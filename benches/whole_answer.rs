//! Issue 28's speed budget: "the added stages cost ≤ 20 % of each system's pipeline".
//! For every system whose answer issue 28 completed, the pipeline as it stood before
//! (load distribution and the stages that already existed) and each added stage alone on
//! its solved analysis: life, friction by mechanism, the thermal network's steady state.
//! The closing note divides the stage medians by the pipeline's, measured in one run.
//!
//! - ball (`decks/chen_b.toml`, race control, its `[thermal]` network): `analyse`; then
//!   `life`, `friction`, the steady network;
//! - tapered (`decks/trb_afapl_lubricated.toml`): `analyse` without and with the
//!   lubricant (film per slice and at the rib, friction by mechanism: issue 28's added
//!   stages sit inside `analyse`), the film-and-friction stage alone
//!   (`tribology::tribology`), then the steady network;
//! - cylindrical (`decks/crb_truck.toml`): the quasi-statics (`run --skip-transient`'s
//!   pipeline) and the tribodynamics; then `life` and `friction`;
//! - double row (`decks/srb_22308.toml`): statics + losses (the seed's answer, existing);
//!   then `life` and the `friction` repackaging.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::angular_ball::system::BallCase;
use rollbench::bearings::cylindrical_roller::system::CylindricalCase;
use rollbench::bearings::double_row_spherical::system::DoubleRowCase;
use rollbench::bearings::tapered_roller::system::TaperedCase;
use rollbench::bearings::{load_file, thermal_answer, Case};
use rollbench::numerics::cancel::Cancel;
use std::hint::black_box;
use std::path::Path;

fn deck(name: &str, sets: &[&str]) -> Box<dyn Case> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("decks")
        .join(name);
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    load_file(&path, &sets).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn ball(c: &mut Criterion) {
    use rollbench::bearings::angular_ball::{analysis::analyse, friction, life};
    let case = deck("chen_b.toml", &[]);
    let case = case.as_any().downcast_ref::<BallCase>().expect("ball deck");
    let input = &case.form.value;
    let model = case
        .derived
        .as_ref()
        .expect("chen_b ships a [thermal] network");
    let a = analyse(input, Cancel::NONE).expect("chen_b solves");
    let f = friction::friction(&a);
    let mut g = c.benchmark_group("whole_answer_ball_chen_b");
    g.bench_function("pipeline_analyse", |b| {
        b.iter(|| analyse(black_box(input), Cancel::NONE).expect("solves"))
    });
    g.bench_function("added_life", |b| b.iter(|| life::life(black_box(&a))));
    g.bench_function("added_friction", |b| {
        b.iter(|| friction::friction(black_box(&a)))
    });
    g.bench_function("added_thermal_steady", |b| {
        b.iter(|| thermal_answer::solve(model, black_box(&f), false, &|| false).expect("net"))
    });
    g.finish();
}

fn tapered(c: &mut Criterion) {
    use rollbench::bearings::tapered_roller::{analysis::analyse, thermal, tribology};
    let wet_case = deck("trb_afapl_lubricated.toml", &[]);
    let wet_case = wet_case
        .as_any()
        .downcast_ref::<TaperedCase>()
        .expect("tapered deck");
    let dry_case = deck("trb_afapl_lubricated.toml", &["lubricant.viscosity=none"]);
    let dry_case = dry_case
        .as_any()
        .downcast_ref::<TaperedCase>()
        .expect("tapered deck");
    let model = wet_case.derived.as_ref().expect("the deck ships a network");
    let a = analyse(&wet_case.form.value, "bench").expect("solves");
    let mut g = c.benchmark_group("whole_answer_tapered_afapl_lubricated");
    for (name, case) in [
        ("pipeline_dry", dry_case),
        ("pipeline_lubricated", wet_case),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| analyse(black_box(&case.form.value), "bench").expect("solves"))
        });
    }
    g.bench_function("added_tribology", |b| {
        b.iter(|| tribology::tribology(black_box(&a)).expect("lubricated"))
    });
    g.bench_function("added_thermal_steady", |b| {
        b.iter(|| thermal::solve(black_box(&a), model, false, &|| false).expect("net"))
    });
    g.finish();
}

fn cylindrical(c: &mut Criterion) {
    use rollbench::bearings::cylindrical_roller::analysis::{analyse, with_tribodynamics};
    use rollbench::bearings::cylindrical_roller::{friction, life};
    let case = deck("crb_truck.toml", &[]);
    let case = case
        .as_any()
        .downcast_ref::<CylindricalCase>()
        .expect("cylindrical deck");
    let input = &case.form.value;
    let qs = analyse(input, "bench", &Cancel::NONE).expect("solves");
    let a = with_tribodynamics(qs.clone(), Cancel::NONE).expect("tribodynamics");
    let mut g = c.benchmark_group("whole_answer_cylindrical_truck");
    g.sample_size(10);
    g.bench_function("pipeline_quasi_static", |b| {
        b.iter(|| analyse(black_box(input), "bench", &Cancel::NONE).expect("solves"))
    });
    g.bench_function("pipeline_tribodynamics", |b| {
        b.iter(|| with_tribodynamics(black_box(qs.clone()), Cancel::NONE).expect("runs"))
    });
    g.bench_function("added_life", |b| b.iter(|| life::life(black_box(&a))));
    g.bench_function("added_friction", |b| {
        b.iter(|| friction::friction(black_box(&a)))
    });
    g.finish();
}

fn double_row(c: &mut Criterion) {
    use rollbench::bearings::double_row_spherical::losses::losses;
    use rollbench::bearings::double_row_spherical::statics::analyse;
    use rollbench::bearings::double_row_spherical::{friction, life};
    let case = deck("srb_22308.toml", &[]);
    let case = case
        .as_any()
        .downcast_ref::<DoubleRowCase>()
        .expect("double-row deck");
    let input = &case.form.value;
    let a = analyse(input, "bench", None).expect("solves");
    let l = losses(&a).expect("losses");
    let mut g = c.benchmark_group("whole_answer_double_row_22308");
    g.bench_function("pipeline_statics_losses", |b| {
        b.iter(|| {
            let a = analyse(black_box(input), "bench", None).expect("solves");
            losses(&a).expect("losses")
        })
    });
    g.bench_function("added_life", |b| b.iter(|| life::life(black_box(&a))));
    g.bench_function("added_friction", |b| {
        b.iter(|| friction::friction(black_box(&a), black_box(&l)))
    });
    g.finish();
}

criterion_group!(benches, ball, tapered, cylindrical, double_row);
criterion_main!(benches);
