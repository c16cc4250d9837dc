//! One ball of Chen's Bearing B (seed 001 ch. 6) in the time simulation, for the
//! integrator comparison and the SciPy side by side (`benches/ball_side_by_side.sh`).
//!
//! `cargo run --release --example ball_one -- [radial_N] [orbits] [rtol] [auto|dopri5|rodas4] [model.json|-] [cage|free]`
//!
//! Solves the race-control analysis of Bearing B at 9 500 rpm with curve 1 under the
//! given radial load (default 500 N), then simulates ball 0 from race control over the
//! given orbits (default 5) at the given relative tolerance (default 1e-8, the deck's).
//! Prints one line `key=value …` (wall time of the simulation alone, best of 5; the
//! mean heat over the last orbit; the final ω; steps and RHS evaluations). With a file
//! name, writes the model's inputs there as JSON (geometry, speeds, curve points, the
//! load track sampled at every ball, ω₀) so that another implementation can integrate
//! the same equations (the held cage's model only: the SciPy script integrates that).
//! The last argument picks the orbit (`dynamics.orbit`; default cage); with `free` the
//! line also gives the mean orbital speed over the last orbit (`omega_m`).
use rollbench::bearings::angular_ball::analysis::analyse;
use rollbench::bearings::angular_ball::dynamics::{simulate_ball_with, BallModel, LoadTrack};
use rollbench::bearings::angular_ball::input::{Method, Orbit};
use rollbench::bearings::angular_ball::BallInput;
use rollbench::numerics::cancel::Cancel;
use rollbench::numerics::ode;
use rollbench::physics::lubrication::traction_curve::TractionCurve;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |k: usize, d: f64| -> Result<f64, Box<dyn std::error::Error>> {
        Ok(match args.get(k) {
            Some(s) => s.parse()?,
            None => d,
        })
    };
    let radial = arg(0, 500.0)?;
    let orbits = arg(1, 5.0)?;
    let rtol = arg(2, 1e-8)?;
    let method = match args.get(3).map(String::as_str) {
        None | Some("auto") => ode::Method::Auto,
        Some("dopri5") => ode::Method::DormandPrince45,
        Some("rodas4") => ode::Method::Sdirk,
        Some(m) => return Err(format!("integrator {m}: auto, dopri5 or rodas4").into()),
    };
    let orbit = match args.get(5).map(String::as_str) {
        None | Some("cage") => Orbit::Cage,
        Some("free") => Orbit::Free,
        Some(o) => return Err(format!("orbit {o}: cage or free").into()),
    };
    let json = args.get(4).filter(|p| p.as_str() != "-");
    if orbit == Orbit::Free && json.is_some() {
        return Err("the model file describes the held cage's model only".into());
    }
    let mut input = BallInput::chen_b();
    input.operating.radial_load_n = radial;
    input.dynamics.method = Method::RaceControl;
    let a = analyse(&input, Cancel::NONE)?;
    let curve = input.traction.curve();
    let track = LoadTrack::new(&a.balls);
    let b = &a.balls[0];
    let g = &a.geometry;
    let model = BallModel {
        diameter_m: g.ball_diameter_m,
        centre_radius_m: 0.5 * g.pitch_diameter_m,
        inertia_kg_m2: g.ball_inertia_kg_m2,
        cage_rad_s: b.cage_rad_s,
        orbit,
        mass_kg: g.ball_mass_kg,
        ring_speeds_rad_s: (
            input.operating.inner_speed_rad_s,
            input.operating.outer_speed_rad_s,
        ),
        groove_curvatures: (g.inner_groove_curvature, g.outer_groove_curvature),
        curve: &curve,
        slices: input.dynamics.slices,
        track: &track,
        start_azimuth_rad: b.azimuth_rad,
    };
    let omega0 = [b.ball_axial_rad_s, b.ball_radial_rad_s, 0.0];
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..5 {
        let t = std::time::Instant::now();
        let r = simulate_ball_with(&model, omega0, orbits, rtol, method, 0, Cancel::NONE)?;
        best = best.min(t.elapsed().as_secs_f64());
        last = Some(r);
    }
    let (d, st) = last.ok_or("no run")?;
    let w = d.history.last().ok_or("empty history")?.omega_rad_s;
    println!(
        "time_s={best:.6e} heat_w={:.10e} omega_a={:.10e} omega_r={:.10e} omega_t={:.10e} omega_m={:.10e} steps={} rejected={} rhs={} switched_at={:?}",
        d.heat_w, w[0], w[1], w[2], d.orbital_rad_s, st.steps, st.rejected, st.rhs_evaluations, st.switched_to_implicit_at
    );
    if let Some(path) = json {
        let points = match &curve {
            TractionCurve::Table { points } => points.clone(),
            TractionCurve::Constant { mu } => vec![(0.0, *mu)],
        };
        let track_pts: Vec<serde_json::Value> = a
            .balls
            .iter()
            .map(|b| {
                serde_json::json!({
                    "azimuth_rad": b.azimuth_rad,
                    "inner": [b.inner.load_n, b.inner.angle_rad, b.inner.hertz.semi_major_m],
                    "outer": [b.outer.load_n, b.outer.angle_rad, b.outer.hertz.semi_major_m],
                })
            })
            .collect();
        let j = serde_json::json!({
            "diameter_m": model.diameter_m,
            "centre_radius_m": model.centre_radius_m,
            "inertia_kg_m2": model.inertia_kg_m2,
            "cage_rad_s": model.cage_rad_s,
            "ring_speeds_rad_s": [model.ring_speeds_rad_s.0, model.ring_speeds_rad_s.1],
            "groove_curvatures": [model.groove_curvatures.0, model.groove_curvatures.1],
            "curve_points": points,
            "slices": model.slices,
            "start_azimuth_rad": model.start_azimuth_rad,
            "track": track_pts,
            "omega0": omega0,
            "orbits": orbits,
            "rtol": rtol,
        });
        std::fs::write(path, serde_json::to_string_pretty(&j)?)?;
    }
    Ok(())
}
