//! Criterion benchmarks of the angular-contact ball system (issue 16, "Speed and
//! stability"): the axisymmetric load distribution with race control on Chen's Bearing A
//! (target < 20 µs); the whole race-control analysis with the skid search on A (no
//! target of its own); the quasi-static ball dynamics on Bearing B at 9 500 rpm (target
//! < 2 ms); the time simulation of B under 500 N radial load, 20 balls × 5 orbits
//! (target < 100 ms; also with the free orbit, no target of its own); A's load distribution under 500 N radial load (target < 0.3 ms);
//! a 19-speed skid sweep of B with the quasi-static dynamics (target < 50 ms); A's ring
//! in five DOF under a radial load and a moment, its tilt solved, with the analytic 5×5
//! stiffness (issue 29: ≤ 2 × the radial solve's 144 µs, so < 288 µs). The
//! dynamics benches time `dynamics::run` alone, from a race-control analysis solved once
//! outside the loop.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::angular_ball::analysis::{analyse, BallAnalysis};
use rollbench::bearings::angular_ball::dynamics;
use rollbench::bearings::angular_ball::geometry::BallGeometry;
use rollbench::bearings::angular_ball::input::{Method, Orbit, PreloadMode};
use rollbench::bearings::angular_ball::load_distribution::{self, Axial, Conditions, Tilt};
use rollbench::bearings::angular_ball::stiffness::{self, StiffnessMethod};
use rollbench::bearings::angular_ball::BallInput;
use rollbench::numerics::cancel::Cancel;

/// The load-solve conditions of `input`, as `analysis` builds them (the preload held as
/// the rest displacement when the deck says so: that rest solve is done here, once).
fn conditions(input: &BallInput, geom: &BallGeometry) -> Conditions {
    let op = &input.operating;
    let mut c = Conditions {
        inner_speed_rad_s: op.inner_speed_rad_s,
        outer_speed_rad_s: op.outer_speed_rad_s,
        axial: Axial::Force(op.axial_load_n),
        radial_load_n: op.radial_load_n,
        tilt: Tilt::Held(0.0),
        race_control: input.kinematics.race_control,
        gyroscopic_friction: input.kinematics.gyroscopic_friction,
        friction_split: input.kinematics.friction_split,
        max_friction: input.traction.curve().max_mu(),
    };
    if op.preload_mode == PreloadMode::Displacement {
        let rest = Conditions {
            inner_speed_rad_s: 0.0,
            outer_speed_rad_s: 0.0,
            radial_load_n: 0.0,
            ..c
        };
        let d = load_distribution::solve(geom, &rest, Cancel::NONE)
            .unwrap_or_else(|e| panic!("{e}"))
            .axial_deflection_m;
        c.axial = Axial::Displacement(d);
    }
    c
}

fn solved(input: &BallInput) -> BallAnalysis {
    analyse(input, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"))
}

fn bearing_a(c: &mut Criterion) {
    let input = BallInput::chen_a();
    let geom = BallGeometry::new(&input).unwrap_or_else(|e| panic!("{e}"));
    let cond = conditions(&input, &geom);
    c.bench_function("ball_a_load_distribution_race_control", |b| {
        b.iter(|| {
            load_distribution::solve(&geom, std::hint::black_box(&cond), Cancel::NONE)
                .unwrap_or_else(|e| panic!("{e}"))
        })
    });
    c.bench_function("ball_a_analysis_with_skid_search", |b| {
        b.iter(|| solved(std::hint::black_box(&input)))
    });

    // Under radial load (issue 16: < 0.3 ms): A with 500 N radial on its preload, every
    // ball its own loads (ring equilibrium in axial and radial).
    let mut radial = BallInput::chen_a();
    radial.operating.radial_load_n = 500.0;
    let cond = conditions(&radial, &geom);
    c.bench_function("ball_a_load_distribution_race_control_radial_500_n", |b| {
        b.iter(|| {
            load_distribution::solve(&geom, std::hint::black_box(&cond), Cancel::NONE)
                .unwrap_or_else(|e| panic!("{e}"))
        })
    });
}

/// Issue 29's speed target (≤ 2 × the radial solve's 144 µs): Bearing A at its
/// 10 000 rpm under a 2 000 N radial load and a 30 N·m moment (the case of
/// `dof_tests::moment_and_tilt_round_trip`), the ring's tilt solved against the moment,
/// then the analytic 5×5 stiffness at that point.
fn bearing_a_five_dof(c: &mut Criterion) {
    let mut input = BallInput::chen_a();
    input.operating.radial_load_n = 2_000.0;
    let geom = BallGeometry::new(&input).unwrap_or_else(|e| panic!("{e}"));
    let cond = Conditions {
        tilt: Tilt::Moment(30.0),
        ..conditions(&input, &geom)
    };
    c.bench_function(
        "ball_a_five_dof_radial_2000_n_moment_30_nm_with_stiffness",
        |b| {
            b.iter(|| {
                let load =
                    load_distribution::solve(&geom, std::hint::black_box(&cond), Cancel::NONE)
                        .unwrap_or_else(|e| panic!("{e}"));
                let k = stiffness::stiffness(&geom, &load, StiffnessMethod::Analytic)
                    .unwrap_or_else(|e| panic!("{e}"));
                (load, k)
            })
        },
    );
}

/// The 19-speed skid sweep with dynamics (issue 16: < 50 ms): Bearing B from 6 000 to
/// 15 000 rpm by 500 (the issue's `--set-range operating.inner_speed=6000:15000:500`),
/// each point the whole analysis (load distribution, race control, skid threshold) with
/// the quasi-static ball dynamics, one after the other (the CLI's sweep runs the points
/// in parallel; this is the serial cost).
fn skid_sweep(c: &mut Criterion) {
    let inputs: Vec<BallInput> = (0..19)
        .map(|k| {
            let mut i = BallInput::chen_b();
            i.operating.inner_speed_rad_s =
                (6_000.0 + 500.0 * k as f64) * std::f64::consts::PI / 30.0;
            i.dynamics.method = Method::QuasiStatic;
            i
        })
        .collect();
    let mut g = c.benchmark_group("ball_b_skid_sweep");
    g.sample_size(20);
    g.bench_function("19_speeds_quasi_static", |b| {
        b.iter(|| {
            inputs
                .iter()
                .map(|i| solved(std::hint::black_box(i)).total_heat_w)
                .sum::<f64>()
        })
    });
    g.finish();
}

fn bearing_b_dynamics(c: &mut Criterion) {
    let mut input = BallInput::chen_b();
    let a = solved(&input);
    input.dynamics.method = Method::QuasiStatic;
    c.bench_function("ball_b_quasi_static_9500_rpm", |b| {
        b.iter(|| {
            dynamics::run(
                std::hint::black_box(&input),
                &a.geometry,
                &a.balls,
                Cancel::NONE,
            )
            .unwrap_or_else(|e| panic!("{e}"))
        })
    });

    let mut input = BallInput::chen_b();
    input.operating.radial_load_n = 500.0;
    let a = solved(&input);
    input.dynamics.method = Method::TimeSimulation;
    input.dynamics.orbits = 5.0;
    assert_eq!(a.balls.len(), 20);
    let mut g = c.benchmark_group("ball_b_time_simulation");
    g.sample_size(10);
    // The target (< 100 ms) on the default model, the free orbit (seed 2-14a per
    // ball, integrated piecewise between predicted load-track kinks); beside it the
    // orbital speed held at race control's cage speed (kinks at known times).
    assert_eq!(input.dynamics.orbit, Orbit::Free);
    for (orbit, name) in [
        (Orbit::Free, "radial_500_n_20_balls_5_orbits"),
        (Orbit::Cage, "radial_500_n_20_balls_5_orbits_held_cage"),
    ] {
        input.dynamics.orbit = orbit;
        g.bench_function(name, |b| {
            b.iter(|| {
                dynamics::run(
                    std::hint::black_box(&input),
                    &a.geometry,
                    &a.balls,
                    Cancel::NONE,
                )
                .unwrap_or_else(|e| panic!("{e}"))
            })
        });
    }
    g.finish();
}

criterion_group!(
    benches,
    bearing_a,
    bearing_a_five_dof,
    bearing_b_dynamics,
    skid_sweep
);
criterion_main!(benches);
