//! Criterion benchmarks of the tapered roller system (issue 17): one load case
//! (equilibrium + analytic 5×5 stiffness) of the seed's sample at 21 and 41 slices, under
//! Load Condition 1 (pure thrust: one distinct roller) and 2 (700 lbf radial: 19 distinct
//! rollers), 20 000 rpm; and the finite-difference check of one case. Under applied
//! moments (issue 29: ≤ 2 ms at 21 slices): Load Condition 2 with 120 N·m, and
//! Nguyen-Schäfer's 32007-X-XL (`decks/trb_32007.toml`), the tilt solved.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::tapered_roller::bearing::Bearing;
use rollbench::bearings::tapered_roller::deck::SCHEMA;
use rollbench::bearings::tapered_roller::input::{StiffnessMethod, TaperedInput};
use rollbench::bearings::tapered_roller::system::TaperedSession;
use rollbench::deck::form::Form;
use rollbench::units::LBF_N;

fn case(slices: usize, radial_lbf: f64) -> TaperedInput {
    let mut s = TaperedInput::afapl_sample();
    s.solver.slices = slices;
    s.operating.radial_load_n = radial_lbf * LBF_N;
    s
}

fn load_case(c: &mut Criterion) {
    for (name, radial) in [("lc1", 0.0), ("lc2", 700.0)] {
        for slices in [21, 41] {
            let input = case(slices, radial);
            c.bench_function(&format!("tapered_{name}_{slices}_slices"), |b| {
                b.iter(|| {
                    let bearing = Bearing::new(std::hint::black_box(&input))
                        .unwrap_or_else(|e| panic!("{e}"));
                    bearing.solve().unwrap_or_else(|e| panic!("{e}"))
                })
            });
        }
    }
    let input = case(21, 700.0);
    let bearing = Bearing::new(&input).unwrap_or_else(|e| panic!("{e}"));
    let sol = bearing.solve().unwrap_or_else(|e| panic!("{e}"));
    c.bench_function("tapered_lc2_21_slices_finite_difference", |b| {
        b.iter(|| bearing.stiffness_fd(std::hint::black_box(&sol)))
    });
}

/// Issue 29's speed target for moments (≤ 2 ms at 21 slices): equilibrium with the tilt
/// solved against the moment, and the analytic 5×5 stiffness at the tilted ring.
fn moment_case(c: &mut Criterion) {
    let mut lc2 = case(21, 700.0);
    lc2.operating.moment_nm = 120.0;
    let deck = include_str!("../decks/trb_32007.toml");
    let n32007 = Form::parse(deck, "trb_32007.toml", &SCHEMA)
        .unwrap_or_else(|e| panic!("{e}"))
        .value;
    assert_eq!(n32007.solver.slices, 21);
    for (name, input) in [
        ("tapered_lc2_moment_120_nm_21_slices", lc2),
        ("tapered_32007_moment_21_slices", n32007),
    ] {
        c.bench_function(name, |b| {
            b.iter(|| {
                let bearing =
                    Bearing::new(std::hint::black_box(&input)).unwrap_or_else(|e| panic!("{e}"));
                bearing.solve().unwrap_or_else(|e| panic!("{e}"))
            })
        });
    }
}

/// A 21-point speed sweep (0–20 000 rpm, Load Condition 2, 21 slices), each point
/// warm-started from the previous one.
fn speed_sweep(c: &mut Criterion) {
    let inputs: Vec<TaperedInput> = (0..21)
        .map(|i| {
            let mut s = case(21, 700.0);
            s.operating.inner_speed_rad_s = 1000.0 * i as f64 * std::f64::consts::PI / 30.0;
            s
        })
        .collect();
    c.bench_function("tapered_lc2_sweep_21_points_warm", |b| {
        b.iter(|| {
            let mut prev = None;
            for s in &inputs {
                let bearing = Bearing::new(s).unwrap_or_else(|e| panic!("{e}"));
                prev = Some(
                    bearing
                        .solve_from(prev.as_ref())
                        .unwrap_or_else(|e| panic!("{e}")),
                );
            }
            prev
        })
    });
}

/// The same 21 speeds through the system's session (`TaperedSession`, what the generic
/// sweep and the workbench use): each point warm-started from the session's last
/// equilibrium, the whole analysis (equilibrium, analytic stiffness, slices) per point.
fn session_sweep(c: &mut Criterion) {
    let inputs: Vec<TaperedInput> = (0..21)
        .map(|i| {
            let mut s = case(21, 700.0);
            s.operating.inner_speed_rad_s = 1000.0 * i as f64 * std::f64::consts::PI / 30.0;
            s.solver.stiffness = StiffnessMethod::Analytic;
            s
        })
        .collect();
    c.bench_function("tapered_lc2_session_sweep_21_points", |b| {
        b.iter(|| {
            let mut session = TaperedSession::default();
            for s in &inputs {
                session
                    .analyse(std::hint::black_box(s), "bench")
                    .unwrap_or_else(|e| panic!("{e}"));
            }
            session
        })
    });
}

/// Issue 28's speed budget: the whole analysis of Load Condition 2 (21 slices, 19 distinct
/// rollers) without and with a lubricant (film per slice and at the rib, friction by
/// mechanism): the ratio of the two medians is the added stages' cost.
fn lubrication(c: &mut Criterion) {
    let dry = case(21, 700.0);
    let mut wet = dry;
    wet.lubricant.viscosity_pa_s = 0.0248;
    wet.lubricant.inlet_temperature_k = 366.48;
    for (name, input) in [("dry", dry), ("lubricated", wet)] {
        c.bench_function(&format!("tapered_lc2_analysis_{name}"), |b| {
            b.iter(|| {
                rollbench::bearings::tapered_roller::analysis::analyse(
                    std::hint::black_box(&input),
                    "bench",
                )
                .unwrap_or_else(|e| panic!("{e}"))
            })
        });
    }
}

criterion_group!(
    benches,
    load_case,
    moment_case,
    speed_sweep,
    session_sweep,
    lubrication
);
criterion_main!(benches);
