//! Tests of the ball dynamics (each states its tolerance and why).

use super::*;
use crate::bearings::angular_ball::analysis::analyse;
use crate::bearings::angular_ball::input::{rpm, Orbit};
use crate::numerics::ode::{OdeOptions, Output};
use crate::physics::lubrication::traction_curve::TractionCurve;
use nalgebra::Matrix3;

/// Bearing B at `rpm_` with the orbital speed held at race control's cage speed
/// (`dynamics.orbit = "cage"`): the tests of the held-cage model. The default, the
/// free orbit of 2-14a, has its own set below ([`free_case`]).
fn case(rpm_: f64, method: Method) -> BallInput {
    let mut i = BallInput::chen_b();
    i.operating.inner_speed_rad_s = rpm(rpm_);
    i.dynamics.method = method;
    i.dynamics.orbit = Orbit::Cage;
    i
}

/// A model of ball 0 of a solved race-control case with the given curve.
fn with_model<R>(
    input: &BallInput,
    curve: &TractionCurve,
    f: impl FnOnce(&BallModel, [f64; 3]) -> R,
) -> R {
    with_orbit_model(input, curve, Orbit::Cage, f)
}

/// [`with_model`] with the given orbit (the free orbit starts at ball 0's race-control
/// cage speed).
fn with_orbit_model<R>(
    input: &BallInput,
    curve: &TractionCurve,
    orbit: Orbit,
    f: impl FnOnce(&BallModel, [f64; 3]) -> R,
) -> R {
    let mut rc = input.clone();
    rc.dynamics.method = Method::RaceControl;
    let a = analyse(&rc, Cancel::NONE).unwrap();
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
        curve,
        slices: input.dynamics.slices,
        track: &track,
        start_azimuth_rad: b.azimuth_rad,
    };
    f(&model, [b.ball_axial_rad_s, b.ball_radial_rad_s, 0.0])
}

/// A frictionless ball (µ = 0) only precesses in the turning cage frame: its kinetic
/// energy ½J|ω|² and |ω| are invariants. Over 20 orbits at rtol 1e-12 every sample keeps
/// |ω| and the energy to 1e-9 relative (the brief's bound; the integrator's global
/// error at this tolerance is ~1e-11), and ω_a (the axis component, untouched by the
/// frame rotation) stays at its start value to the same tolerance.
#[test]
fn frictionless_ball_conserves_energy_and_speed() {
    let input = case(9_500.0, Method::TimeSimulation);
    let curve = TractionCurve::Constant { mu: 0.0 };
    with_model(&input, &curve, |m, w0| {
        // Start off race control's plane so that the precession is visible.
        let w0 = [w0[0], w0[1], 0.3 * w0[1]];
        let (d, _) = simulate_ball(m, w0, 20.0, 1e-12, 0, Cancel::NONE).unwrap();
        let n0 = Vector3::from(w0).norm();
        let e0 = 0.5 * m.inertia_kg_m2 * n0 * n0;
        let mut moved: f64 = 0.0;
        for s in &d.history {
            let w = Vector3::from(s.omega_rad_s);
            let e = 0.5 * m.inertia_kg_m2 * w.norm_squared();
            assert!((w.norm() / n0 - 1.0).abs() < 1e-9, "{} vs {n0}", w.norm());
            assert!((e / e0 - 1.0).abs() < 1e-9);
            assert!((s.omega_rad_s[0] / w0[0] - 1.0).abs() < 1e-9);
            moved = moved.max((s.omega_rad_s[1] - w0[1]).abs());
            assert_eq!(s.heat_w, 0.0);
        }
        // The (r, t) part really turns (by 2π per orbit in the cage frame).
        assert!(moved > w0[1]);
    });
}

/// At a steady state (the quasi-static ω, where dω/dt = 0) the heat of the slices equals
/// the friction power taken from the rings plus the power of the held cage
/// (−F_t·ω_m·R_b, the orbital equation 2-14a that a cage-guided ball does not integrate),
/// because M·ω = J·ω·(ω_m a × ω) = 0 there. Exact identity up to the Newton residual:
/// 1e-6 relative (the brief). Also with the time simulation's final state.
#[test]
fn steady_heat_equals_power_from_rings() {
    for method in [Method::QuasiStatic, Method::TimeSimulation] {
        let input = case(9_500.0, method);
        let curve = input.traction.curve();
        with_model(&input, &curve, |m, w0| {
            let w = match method {
                Method::QuasiStatic => quasi_static_ball(m, w0, 0).unwrap().0,
                _ => {
                    let (d, _) = simulate_ball(m, w0, 5.0, 1e-10, 0, Cancel::NONE).unwrap();
                    d.history.last().unwrap().omega_rad_s
                }
            };
            let w = Vector3::from(w);
            let (i, o) = m.contacts(0.0, &w);
            let heat = i.lateral_w + i.rolling_w + o.lateral_w + o.rolling_w;
            let rings = i.ring_power_w + o.ring_power_w;
            let cage = -(i.force[2] + o.force[2]) * m.cage_rad_s * m.centre_radius_m;
            let mw = (i.moment + o.moment).dot(&w);
            eprintln!("{method:?}: heat {heat} W, rings {rings} W, cage {cage} W, M·ω {mw} W");
            assert!(
                ((rings + cage) / heat - 1.0).abs() < 1e-6,
                "{heat} vs {rings} + {cage}"
            );
            assert!(mw.abs() < 1e-6 * heat);
        });
    }
}

/// Under an axisymmetric load the time simulation, started from race control, settles
/// to the quasi-static answer (the seed, ch. 6: "the time-simulation and quasi-static
/// method results are the same"): final ω within 1e-6 of |ω| and the heat within 1e-6
/// relative (the brief), and the steady state is detected.
#[test]
fn axisymmetric_time_simulation_settles_to_quasi_static() {
    let ts = analyse(&case(8_500.0, Method::TimeSimulation), Cancel::NONE).unwrap();
    let qs = analyse(&case(8_500.0, Method::QuasiStatic), Cancel::NONE).unwrap();
    let (dt, dq) = (ts.dynamics.unwrap(), qs.dynamics.unwrap());
    assert!(dt.steady, "amplitude {}", dt.oscillation_amplitude_rad_s);
    let wt = Vector3::from(dt.balls[0].history.last().unwrap().omega_rad_s);
    let wq = Vector3::from(dq.balls[0].history[0].omega_rad_s);
    assert!((wt - wq).norm() < 1e-6 * wq.norm(), "{wt} vs {wq}");
    assert!((dt.balls[0].heat_w / dq.balls[0].heat_w - 1.0).abs() < 1e-6);
    assert_eq!(dq.integrator, "newton");
}

/// Seed ch. 6, Fig. 6-6: Bearing B with curve 1 makes ≈ 57 W per ball at 9 500 rpm and
/// ≈ 32 W at 8 500 rpm in the time simulation (figures read, ±20 %); it is about five
/// times race control's heat at 9 500 rpm (text: "five times", checked 4–6×), and at
/// 7 500 rpm the simulated heat already exceeds race control's. Not tuned: we get
/// 59.4 W (+4 %) and 28.8 W (−10 %).
#[test]
fn bearing_b_heat_matches_the_seed() {
    for (n, want) in [(9_500.0, 57.0), (8_500.0, 32.0)] {
        let a = analyse(&case(n, Method::TimeSimulation), Cancel::NONE).unwrap();
        let per_ball = a.total_heat_w / 20.0;
        assert!(
            (per_ball / want - 1.0).abs() < 0.2,
            "{n}: {per_ball} W vs {want}"
        );
        let d = a.dynamics.as_ref().unwrap();
        assert!((d.lateral_w() + d.rolling_w()) / d.total_w() - 1.0 < 1e-12);
        if n == 9_500.0 {
            let ratio = a.total_heat_w / a.race_control_heat_w;
            assert!((4.0..6.0).contains(&ratio), "{ratio}");
        }
    }
    let a = analyse(&case(7_500.0, Method::TimeSimulation), Cancel::NONE).unwrap();
    assert!(a.total_heat_w > a.race_control_heat_w);
}

/// A traction curve 40× steeper than curve 1 (µ = 0.054 reached at 5 mm/s) makes the
/// ball equations stiff (the slices near pure rolling give ∂M/∂ω ~ µ'·q·r²/J, of order
/// −10⁶ 1/s): the automatic choice must end on the implicit Rodas4, and after 5 orbits
/// the answer must still be the quasi-static one (1e-6 of |ω|).
#[test]
fn steep_curve_switches_to_the_implicit_integrator() {
    let mut input = case(8_500.0, Method::TimeSimulation);
    input.dynamics.orbits = 2.0;
    let curve = TractionCurve::Table {
        points: vec![(0.0, 0.0), (0.005, 0.054)],
    };
    with_model(&input, &curve, |m, w0| {
        let (d, st) = simulate_ball(m, w0, 5.0, 1e-8, 0, Cancel::NONE).unwrap();
        assert!(st.switched_to_implicit_at.is_some(), "{st:?}");
        let (wq, _, _) = quasi_static_ball(m, w0, 0).unwrap();
        let wt = Vector3::from(d.history.last().unwrap().omega_rad_s);
        assert!((wt - Vector3::from(wq)).norm() < 1e-6 * wt.norm());
    });
}

/// Under Chen's 500 N radial load (Figs. 6-9…6-12) the loads follow the orbit: the
/// track reproduces every ball's loads at its azimuth exactly (1e-12), the simulated
/// heat varies around the orbit and the oscillation is reported (not steady).
#[test]
fn radial_load_makes_the_ball_motion_oscillate() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    input.dynamics.orbits = 2.0;
    input.geometry.ball_count = 8;
    let a = analyse(&input, Cancel::NONE).unwrap();
    let track = LoadTrack::new(&a.balls);
    for b in &a.balls {
        let l = track.at(b.azimuth_rad);
        assert!((l.inner.load_n / b.inner.load_n - 1.0).abs() < 1e-12);
        assert!((l.outer.angle_rad - b.outer.angle_rad).abs() < 1e-12);
    }
    let d = a.dynamics.as_ref().unwrap();
    assert_eq!(d.balls.len(), 8);
    assert!(!d.steady);
    assert!(
        d.oscillation_amplitude_rad_s > 1.0,
        "{}",
        d.oscillation_amplitude_rad_s
    );
    let h = &d.balls[0].history;
    let (lo, hi) = h.iter().fold((f64::INFINITY, 0.0f64), |a, s| {
        (a.0.min(s.heat_w), a.1.max(s.heat_w))
    });
    assert!(hi > 1.1 * lo, "{lo} {hi}");
    eprintln!(
        "radial: heat {lo:.2}–{hi:.2} W, amplitude {:.2} rad/s, {} steps",
        d.oscillation_amplitude_rad_s, d.steps
    );
}

/// Bad dynamics options are typed errors, and a cancelled run says so.
#[test]
fn bad_options_and_cancel() {
    let mut i = case(9_500.0, Method::TimeSimulation);
    i.dynamics.orbits = 0.0;
    assert!(matches!(
        analyse(&i, Cancel::NONE),
        Err(BallError::InvalidInput(_))
    ));
    let flag = std::sync::atomic::AtomicBool::new(true);
    let i = case(9_500.0, Method::TimeSimulation);
    assert!(analyse(&i, Cancel::new(&flag)).is_err());
}

/// The workbench: the ball system offers a "Dynamics" pane on chart 1, chart 1 is the
/// heat per ball against azimuth (race control and the simulation, one point per ball)
/// and there is one element chart per ball with its history (ω_t and heat against the
/// orbit position, 90 samples per orbit + 1).
#[test]
fn view_has_the_dynamics_charts() {
    use crate::bearings::view::PaneKind;
    use crate::bearings::BearingSystem;
    let panes = crate::bearings::angular_ball::system::SYSTEM.panes();
    assert!(panes
        .iter()
        .any(|p| p.kind == PaneKind::Chart(1) && p.title == "Dynamics"));
    let a = analyse(&case(9_500.0, Method::TimeSimulation), Cancel::NONE).unwrap();
    let v = crate::bearings::angular_ball::view::view(&a);
    assert_eq!(v.charts.len(), 3); // Skid, Dynamics, Traction
    let c = &v.charts[1];
    assert_eq!(c.series.len(), 2);
    assert!(c.series.iter().all(|s| s.points.len() == 20));
    assert_eq!(v.element_charts.len(), 20);
    assert_eq!(v.element_charts[3].series[1].points.len(), 5 * 90 + 1);
    // Ball 3's history starts at its own azimuth (18° per ball).
    assert!((v.element_charts[3].series[0].points[0].0 - 54.0).abs() < 1e-9);
    let rc = analyse(&case(9_500.0, Method::RaceControl), Cancel::NONE).unwrap();
    let v = crate::bearings::angular_ball::view::view(&rc);
    assert!(v.element_charts.is_empty());
    assert_eq!(v.charts[1].series.len(), 1);
}

/// Under radial load the Dynamics chart shows the heat where each ball is (its own
/// azimuth in the last orbit), which varies around the bearing (Fig. 6-11: peaks and
/// valleys with the load), while every ball's last-orbit mean is nearly the same track
/// average (1 % between balls: the start transient, different for each start
/// position, decays slowly under gross sliding; after 2 orbits the means still differed
/// by 1.1 %, so 5 orbits are run).
#[test]
fn radial_load_chart_varies_with_azimuth() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    input.dynamics.orbits = 5.0;
    input.geometry.ball_count = 6;
    let a = analyse(&input, Cancel::NONE).unwrap();
    let v = crate::bearings::angular_ball::view::view(&a);
    let pts = &v.charts[1].series[1].points;
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, 0.0f64), |a, p| (a.0.min(p.1), a.1.max(p.1)));
    assert!(hi > 1.02 * lo, "{pts:?}");
    let d = a.dynamics.as_ref().unwrap();
    let m0 = d.balls[0].heat_w;
    for b in &d.balls {
        assert!((b.heat_w / m0 - 1.0).abs() < 1e-2, "{} vs {m0}", b.heat_w);
    }
}

/// Over a spread of speeds, curves, radial loads, slice counts, both methods and both
/// orbits (a fixed
/// pseudo-random sample, reproducible): every run is a finished answer with finite,
/// non-negative heats whose lateral and rolling parts add up to the total (1e-9), or a
/// typed error — never NaN, never a panic.
#[test]
fn random_cases_are_finite_or_typed_errors() {
    use crate::bearings::angular_ball::input::TractionPreset;
    let mut state: u64 = 0x2412_6498_69bb_2023;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in 0..12 {
        let method = if k % 2 == 0 {
            Method::TimeSimulation
        } else {
            Method::QuasiStatic
        };
        let mut i = case(2_000.0 + 13_000.0 * next(), method);
        i.traction.preset = [
            TractionPreset::Curve1,
            TractionPreset::Curve2,
            TractionPreset::Curve3,
        ][k % 3];
        i.operating.radial_load_n = if next() < 0.5 { 0.0 } else { 600.0 * next() };
        i.geometry.ball_count = 5 + (next() * 10.0) as usize;
        i.geometry.free_contact_angle_rad = (15.0 + 45.0 * next()).to_radians();
        i.dynamics.slices = 5 + (next() * 40.0) as usize;
        i.dynamics.orbits = 1.0 + next();
        // Both orbits: the held cage and the free one (2-14a).
        i.dynamics.orbit = if k % 4 < 2 { Orbit::Cage } else { Orbit::Free };
        match analyse(&i, Cancel::NONE) {
            Ok(a) => {
                let d = a.dynamics.as_ref().unwrap();
                for b in &d.balls {
                    assert!(b.heat_w.is_finite() && b.heat_w >= 0.0, "{k}: {}", b.heat_w);
                    assert!(
                        ((b.lateral_w + b.rolling_w) - b.heat_w).abs() <= 1e-9 * b.heat_w.max(1.0)
                    );
                    for s in &b.history {
                        assert!(s.omega_rad_s.iter().all(|w| w.is_finite()));
                    }
                }
            }
            Err(e) => eprintln!("case {k}: typed error {e}"),
        }
    }
}

/// The analytic Jacobian ∂(dω/dt)/∂ω that Rodas4 uses equals central differences of the
/// right-hand side (step 1e-6 of |ω|; 1e-5 of the Jacobian's norm: the difference
/// error, with slices crossing no break point of curve 1 at this state), at race
/// control's start state and at a perturbed one, for curve 1 and the steep curve.
#[test]
fn analytic_jacobian_matches_differences() {
    let input = case(9_500.0, Method::TimeSimulation);
    for curve in [
        input.traction.curve(),
        TractionCurve::Table {
            points: vec![(0.0, 0.0), (0.005, 0.054)],
        },
    ] {
        with_model(&input, &curve, |m, w0| {
            for w in [Vector3::from(w0), Vector3::new(w0[0] * 1.01, w0[1], 37.0)] {
                let j = m.omega_jacobian(1e-4, &w);
                let h = 1e-6 * w.norm();
                let mut fd = Matrix3::zeros();
                for c in 0..3 {
                    let mut wp = w;
                    let mut wm = w;
                    wp[c] += h;
                    wm[c] -= h;
                    fd.set_column(
                        c,
                        &((m.omega_dot(1e-4, &wp) - m.omega_dot(1e-4, &wm)) / (2.0 * h)),
                    );
                }
                assert!((j - fd).norm() < 1e-5 * fd.norm(), "{j} vs {fd}");
            }
        });
    }
}

/// Issue 16's radial anomaly, settled as physics: under Chen's 500 N radial load
/// (Bearing B, 9 500 rpm, curve 1) the time simulation makes far more heat than race
/// control and does not settle. The energy of the ball is accounted for over its whole
/// first orbit (from race control, the hardest transient): the friction power taken
/// from the rings plus the held cage's power (−F_t ω_m R_b, see
/// `steady_heat_equals_power_from_rings`) equals the slices' heat plus d(½J|ω|²)/dt, so
/// ∫(rings + cage − heat) dt over the orbit equals ΔKE. Integrated by Simpson's rule on
/// 20 001 dense-output points at rtol 1e-10: 1e-6 of ∫heat dt (the quadrature error at
/// the load track's 20 kinks per orbit is ~1e-8 of it; measured below). A unit slip, a
/// wrong frame or a chattering load switch would break this balance; it holds, so the
/// heat is supplied by the rings and is not an artefact of the integration.
#[test]
fn radial_load_energy_balance_over_an_orbit() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let curve = input.traction.curve();
    with_model(&input, &curve, |m, w0| {
        let period = std::f64::consts::TAU / m.cage_rad_s.abs();
        let n = 20_000;
        let times: Vec<f64> = (0..=n)
            .map(|k| (period * k as f64 / n as f64).min(period))
            .collect();
        let opts = OdeOptions {
            rtol: 1e-10,
            atol: 1e-10 * Vector3::from(w0).norm(),
            max_steps: 2_000_000,
            ..OdeOptions::default()
        };
        let sol = ode::solve(
            m,
            0.0,
            &w0,
            period,
            &opts,
            &mut [],
            Output::Times(times),
            Cancel::NONE,
        )
        .unwrap();
        let (mut gap, mut heat) = (Vec::new(), Vec::new());
        for (&t, y) in sol.t.iter().zip(&sol.y) {
            let w = Vector3::new(y[0], y[1], y[2]);
            let (i, o) = m.contacts(t, &w);
            let h = i.lateral_w + i.rolling_w + o.lateral_w + o.rolling_w;
            let rings = i.ring_power_w + o.ring_power_w;
            let cage = -(i.force[2] + o.force[2]) * m.cage_rad_s * m.centre_radius_m;
            gap.push(rings + cage - h);
            heat.push(h);
        }
        let dt = period / n as f64;
        let simpson = |f: &[f64]| {
            let inner: f64 = f[1..n]
                .iter()
                .enumerate()
                .map(|(k, x)| if k % 2 == 0 { 4.0 } else { 2.0 } * x)
                .sum();
            (f[0] + f[n] + inner) * dt / 3.0
        };
        let ke = |y: &[f64]| 0.5 * m.inertia_kg_m2 * Vector3::new(y[0], y[1], y[2]).norm_squared();
        let d_ke = ke(&sol.y[n]) - ke(&sol.y[0]);
        let (g, q) = (simpson(&gap), simpson(&heat));
        eprintln!(
            "radial orbit: ∫heat {q:.6e} J (mean {:.3} W), ∫(rings+cage−heat) {g:.6e} J, ΔKE {d_ke:.6e} J, rel {:.2e}",
            q / period,
            (g - d_ke).abs() / q
        );
        assert!((g - d_ke).abs() < 1e-6 * q, "{g} vs {d_ke} (heat {q})");
    });
}

/// Seed ch. 6, Figs. 6-11/6-12 (Bearing B, 1 000 N preload, 500 N radial, 9 500 rpm, five
/// orbits): "a radial load can significantly increase the magnitude of the ball
/// skidding. The maximum heat generation rate reaches 100 Watts (at the final state)
/// which is twice the heat generated in the pure axial load case"; "the peaks of the
/// time-simulated curve correspond to the lowest loaded position"; the quasi-static
/// results are "much smaller than the time-simulation results" (the friction torque
/// cannot turn the spin axis as fast as the loads change: the motion has a history).
/// Checked qualitatively: the peak per-ball heat over the last orbit is at least 1.6× the
/// axial-only simulated heat, it lies on the low-load half of the orbit (90°…270°, the
/// lowest load being at 180°; it lags it by the ball's history), the simulated total
/// exceeds the quasi-static total, and the run is reported as not steady.
/// NOT reproduced quantitatively: we get a peak of 176 W per ball (seed ≈ 100 W read off
/// the figure, ≈ 2× the axial case; we are 3.0× our axial 59.4 W) and a mean of 90 W per
/// ball (1 804 W for the bearing). The energy balance of
/// `radial_load_energy_balance_over_an_orbit` holds to 3e-8, so the excess is in the
/// model, not the integration; the held cage speed is most of it: with the orbit free
/// (Chen integrates 2-14a per ball, `free_orbit_heat_against_the_seed`) the peak is
/// 124 W = 2.35× the axial case — the bound below is the held cage's measured value
/// +10 %, a regression guard, not agreement with the seed.
#[test]
fn radial_load_heat_matches_the_seed() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let ts = analyse(&input, Cancel::NONE).unwrap();
    let d = ts.dynamics.as_ref().unwrap();
    let track = LoadTrack::new(&ts.balls);
    // Peak heat over every ball's last orbit, and the azimuth where it occurs.
    let (mut peak, mut peak_deg): (f64, f64) = (0.0, 0.0);
    for b in &d.balls {
        let end = b.history.last().unwrap().orbit_deg;
        for s in b.history.iter().filter(|s| s.orbit_deg >= end - 360.0) {
            if s.heat_w > peak {
                (peak, peak_deg) = (s.heat_w, s.orbit_deg.rem_euclid(360.0));
            }
        }
    }
    // The lowest- and highest-loaded positions (inner contact) of the load track.
    let load = |deg: f64| track.at(deg.to_radians()).inner.load_n;
    let grid: Vec<f64> = (0..360).map(f64::from).collect();
    let lowest = grid
        .iter()
        .copied()
        .fold(0.0, |m, x| if load(x) < load(m) { x } else { m });
    let highest = grid
        .iter()
        .copied()
        .fold(0.0, |m, x| if load(x) > load(m) { x } else { m });
    eprintln!(
        "peak at {peak_deg:.0}°, lowest load {:.1} N at {lowest}°, highest {:.1} N at {highest}°",
        load(lowest),
        load(highest)
    );
    let axial = analyse(&case(9_500.0, Method::TimeSimulation), Cancel::NONE).unwrap();
    let axial_w = axial.dynamics.as_ref().unwrap().balls[0].heat_w;
    input.dynamics.method = Method::QuasiStatic;
    let qs = analyse(&input, Cancel::NONE).unwrap();
    let dq = qs.dynamics.as_ref().unwrap();
    eprintln!(
        "radial: peak {peak:.1} W/ball, axial {axial_w:.1} W/ball, total {:.10e} W, quasi-static total {:.10e} W, amplitude {:.1} rad/s",
        d.total_w(),
        dq.total_w(),
        d.oscillation_amplitude_rad_s
    );
    assert!(peak > 1.6 * axial_w, "{peak} / {axial_w}");
    assert!(
        peak < 1.1 * 176.1,
        "{peak}: above the measured value, see the doc"
    );
    assert!((90.0..270.0).contains(&peak_deg), "{peak_deg}");
    assert!(load(lowest) < load(highest));
    assert!(
        d.total_w() > dq.total_w(),
        "{} vs {}",
        d.total_w(),
        dq.total_w()
    );
    assert!(!d.steady);
    // Pinned before the speed-up (slice recurrence, parallel balls, moment-only RHS,
    // integration piecewise between the load track's kinks): 1 803.9709 W then,
    // 1 803.9739 W after (1.7e-6: the step sequence moves within rtol 1e-8; a Rodas4
    // run agrees with the piecewise one to 2e-8); 1e-4 relative is the brief's bound
    // for a change that is not a fix.
    assert!(
        (d.total_w() / 1_803.971 - 1.0).abs() < 1e-4,
        "{}",
        d.total_w()
    );
}

/// The right-hand side's moment-only path equals the full contact's moment (1e-12 of its
/// norm: the same sums in a different association) at race control's state and at a
/// perturbed one, both contacts, under radial load.
#[test]
fn moment_only_path_matches_the_full_contact() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let curve = input.traction.curve();
    with_model(&input, &curve, |m, w0| {
        for w in [
            Vector3::from(w0),
            Vector3::new(w0[0], 1.1 * w0[1], 0.2 * w0[1]),
        ] {
            for t in [0.0, 1e-3, 7e-3] {
                let l = m.track.at(m.azimuth(t));
                for (inner, c) in [(true, &l.inner), (false, &l.outer)] {
                    let full = m.contact(inner, c, &w).moment;
                    let fast = m.contact_moment(inner, c, &w);
                    assert!(
                        (full - fast).norm() <= 1e-12 * full.norm(),
                        "{full} vs {fast}"
                    );
                }
            }
        }
    });
}

// ---- The free orbit (seed 2-14a integrated per ball; `dynamics.orbit = "free"`) ----

fn free_case(rpm_: f64, method: Method) -> BallInput {
    let mut i = case(rpm_, method);
    i.dynamics.orbit = Orbit::Free;
    i
}

/// Free orbit, frictionless ball (µ = 0): no traction, so ω_m stays at its start value,
/// θ advances by ω_m t, and the ball only precesses in the frame turning at ω_m: |ω| and
/// the kinetic energy ½J|ω|² + ½m(ω_m R_b)² are invariants. 20 orbits at rtol 1e-12,
/// every sample to 1e-9 relative (the brief's bound).
#[test]
fn free_orbit_frictionless_ball_conserves_energy_and_speed() {
    let input = free_case(9_500.0, Method::TimeSimulation);
    let curve = TractionCurve::Constant { mu: 0.0 };
    with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
        let w0 = [w0[0], w0[1], 0.3 * w0[1]];
        let (d, _) = simulate_ball(m, w0, 20.0, 1e-12, 0, Cancel::NONE).unwrap();
        let n0 = Vector3::from(w0).norm();
        let v0 = m.cage_rad_s * m.centre_radius_m;
        let ke = |w: f64, wm: f64| {
            0.5 * m.inertia_kg_m2 * w * w + 0.5 * m.mass_kg * (wm * m.centre_radius_m).powi(2)
        };
        let e0 = ke(n0, m.cage_rad_s);
        let mut moved: f64 = 0.0;
        for s in &d.history {
            let w = Vector3::from(s.omega_rad_s);
            assert!((w.norm() / n0 - 1.0).abs() < 1e-9, "{} vs {n0}", w.norm());
            assert!((ke(w.norm(), s.orbital_rad_s) / e0 - 1.0).abs() < 1e-9);
            assert!((s.orbital_rad_s * m.centre_radius_m / v0 - 1.0).abs() < 1e-9);
            let theta = m.start_azimuth_rad + m.cage_rad_s * s.time_s;
            assert!((s.orbit_deg.to_radians() - theta).abs() < 1e-9 * theta.abs().max(1.0));
            assert!((s.omega_rad_s[0] / w0[0] - 1.0).abs() < 1e-9);
            moved = moved.max((s.omega_rad_s[1] - w0[1]).abs());
            assert_eq!(s.heat_w, 0.0);
        }
        assert!(moved > w0[1]);
    });
}

/// Free orbit at a steady state (the quasi-static state: dω/dt = 0 and Σ F_t = 0, so
/// M·ω = 0 and the traction does no work on the orbit): the slices' heat equals the
/// friction power taken from the rings alone (no cage), 1e-6 relative (the brief); the
/// orbital balance |Σ F_t| below 1e-9 of Σ µq (the Newton residual). Also with the time
/// simulation's final state after 40 orbits (the orbital mode decays slowly: at 9 500
/// rpm the amplitude is 18 rad/s after 5 orbits, 9e-7 after 40).
#[test]
fn free_orbit_steady_heat_equals_power_from_rings() {
    for method in [Method::QuasiStatic, Method::TimeSimulation] {
        let input = free_case(9_500.0, method);
        let curve = input.traction.curve();
        with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
            let y = match method {
                Method::QuasiStatic => quasi_static_state(m, w0, 0).unwrap().0,
                _ => {
                    let (d, _) = simulate_ball(m, w0, 40.0, 1e-10, 0, Cancel::NONE).unwrap();
                    let s = d.history.last().unwrap();
                    vec![
                        s.omega_rad_s[0],
                        s.omega_rad_s[1],
                        s.omega_rad_s[2],
                        s.orbital_rad_s,
                        s.orbit_deg.to_radians(),
                    ]
                }
            };
            let w = Vector3::new(y[0], y[1], y[2]);
            let l = m.track.at(y[4]);
            let i = m.contact_at(true, &l.inner, &w, y[3]);
            let o = m.contact_at(false, &l.outer, &w, y[3]);
            let heat = i.lateral_w + i.rolling_w + o.lateral_w + o.rolling_w;
            let rings = i.ring_power_w + o.ring_power_w;
            let ft = i.force[2] + o.force[2];
            let mw = (i.moment + o.moment).dot(&w);
            eprintln!(
                "free {method:?}: heat {heat} W, rings {rings} W, F_t {ft:e} N, M·ω {mw:e} W, ω_m {} (cage {})",
                y[3], m.cage_rad_s
            );
            assert!((rings / heat - 1.0).abs() < 1e-6, "{heat} vs {rings}");
            assert!(mw.abs() < 1e-6 * heat);
            assert!(ft.abs() * y[3].abs() * m.centre_radius_m < 1e-6 * heat);
        });
    }
}

/// Free orbit, axisymmetric load: the time simulation settles to the quasi-static
/// answer with the orbital balance (ω and ω_m within 1e-6 of |ω|, heat within 1e-6
/// relative, steady detected). 8 500 rpm, 30 orbits (amplitude 7e-7 rad/s there).
#[test]
fn free_orbit_axisymmetric_time_simulation_settles_to_quasi_static() {
    let mut ti = free_case(8_500.0, Method::TimeSimulation);
    ti.dynamics.orbits = 30.0;
    let ts = analyse(&ti, Cancel::NONE).unwrap();
    let qs = analyse(&free_case(8_500.0, Method::QuasiStatic), Cancel::NONE).unwrap();
    let (dt, dq) = (ts.dynamics.unwrap(), qs.dynamics.unwrap());
    assert!(dt.steady, "amplitude {}", dt.oscillation_amplitude_rad_s);
    let st = dt.balls[0].history.last().unwrap();
    let sq = dq.balls[0].history[0];
    let (wt, wq) = (Vector3::from(st.omega_rad_s), Vector3::from(sq.omega_rad_s));
    assert!((wt - wq).norm() < 1e-6 * wq.norm(), "{wt} vs {wq}");
    assert!((st.orbital_rad_s - sq.orbital_rad_s).abs() < 1e-6 * wq.norm());
    assert!((dt.balls[0].heat_w / dq.balls[0].heat_w - 1.0).abs() < 1e-6);
    // The free ball orbits at its own speed, not race control's cage speed.
    let cage = ts.balls[0].cage_rad_s;
    eprintln!(
        "free 8 500 rpm: ω_m {} rad/s vs cage {cage} rad/s, heat {} W",
        sq.orbital_rad_s, dq.balls[0].heat_w
    );
    assert!((sq.orbital_rad_s / cage - 1.0).abs() > 1e-6);
}

/// The free orbit's analytic Jacobian (ω, ω_m block; θ column by its own central
/// difference of 1e-6 rad) equals central differences of the right-hand side (step
/// 1e-8 of |ω| for ω and ω_m — the steep curve's break at 5 mm/s is straddled by some
/// strip at 1e-6 of |ω|, which then measures a secant, 10 % off; 1e-7 rad for θ;
/// 1e-5 of the Jacobian's norm, the differences' error), under radial load between two
/// track points, for curve 1 and the steep curve.
#[test]
fn free_orbit_jacobian_matches_differences() {
    let mut input = free_case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    for curve in [
        input.traction.curve(),
        TractionCurve::Table {
            points: vec![(0.0, 0.0), (0.005, 0.054)],
        },
    ] {
        with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
            let theta = m.start_azimuth_rad + 0.05;
            for y in [
                [w0[0], w0[1], w0[2], m.cage_rad_s, theta],
                [w0[0] * 1.01, w0[1], 37.0, 0.98 * m.cage_rad_s, theta + 1.0],
            ] {
                let j = m.free_jacobian(&y);
                let scale = Vector3::new(y[0], y[1], y[2]).norm();
                let mut fd = nalgebra::SMatrix::<f64, 5, 5>::zeros();
                for c in 0..5 {
                    let h = if c < 4 { 1e-8 * scale } else { 1e-7 };
                    let (mut yp, mut ym) = (y, y);
                    yp[c] += h;
                    ym[c] -= h;
                    let (fp, fm) = (m.free_rates(&yp), m.free_rates(&ym));
                    for r in 0..5 {
                        fd[(r, c)] = (fp[r] - fm[r]) / (2.0 * h);
                    }
                }
                assert!((j - fd).norm() < 1e-5 * fd.norm(), "{j} vs {fd}");
                // The orbital row really couples (ω_m's own rate is not zero).
                assert!(j[(3, 3)] < 0.0);
            }
        });
    }
}

/// Free orbit under 500 N radial load: over the first orbit the friction power taken
/// from the rings equals the slices' heat plus the change of the ball's kinetic energy,
/// now with the orbital part ½m(ω_m R_b)² and no cage: ∫(rings − heat) dt = ΔKE to
/// 1e-6 of ∫heat dt (Simpson on 20 001 dense-output points at rtol 1e-10, as the held
/// orbit's balance test).
#[test]
fn free_orbit_radial_energy_balance_over_an_orbit() {
    let mut input = free_case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let curve = input.traction.curve();
    with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
        let period = std::f64::consts::TAU / m.cage_rad_s.abs();
        let n = 20_000;
        let times: Vec<f64> = (0..=n)
            .map(|k| (period * k as f64 / n as f64).min(period))
            .collect();
        let y0 = m.start_state(w0);
        let opts = OdeOptions {
            rtol: 1e-10,
            atol: 1e-10 * Vector3::from(w0).norm(),
            max_steps: 2_000_000,
            ..OdeOptions::default()
        };
        let sol = ode::solve(
            m,
            0.0,
            &y0,
            period,
            &opts,
            &mut [],
            Output::Times(times),
            Cancel::NONE,
        )
        .unwrap();
        let (mut gap, mut heat) = (Vec::new(), Vec::new());
        for y in &sol.y {
            let w = Vector3::new(y[0], y[1], y[2]);
            let l = m.track.at(y[4]);
            let i = m.contact_at(true, &l.inner, &w, y[3]);
            let o = m.contact_at(false, &l.outer, &w, y[3]);
            let h = i.lateral_w + i.rolling_w + o.lateral_w + o.rolling_w;
            gap.push(i.ring_power_w + o.ring_power_w - h);
            heat.push(h);
        }
        let dt = period / n as f64;
        let simpson = |f: &[f64]| {
            let inner: f64 = f[1..n]
                .iter()
                .enumerate()
                .map(|(k, x)| if k % 2 == 0 { 4.0 } else { 2.0 } * x)
                .sum();
            (f[0] + f[n] + inner) * dt / 3.0
        };
        let ke = |y: &[f64]| {
            0.5 * m.inertia_kg_m2 * Vector3::new(y[0], y[1], y[2]).norm_squared()
                + 0.5 * m.mass_kg * (y[3] * m.centre_radius_m).powi(2)
        };
        let d_ke = ke(&sol.y[n]) - ke(&sol.y[0]);
        let (g, q) = (simpson(&gap), simpson(&heat));
        eprintln!(
            "free radial orbit: ∫heat {q:.6e} J, ∫(rings−heat) {g:.6e} J, ΔKE {d_ke:.6e} J, rel {:.2e}",
            (g - d_ke).abs() / q
        );
        assert!((g - d_ke).abs() < 1e-6 * q, "{g} vs {d_ke} (heat {q})");
    });
}

/// The free orbit against the seed (ch. 6): axial Bearing B ≈ 57 W per ball at 9 500 rpm
/// and ≈ 32 W at 8 500 rpm (figures read, ±20 %), and under 500 N radial load "the
/// maximum heat generation rate reaches 100 Watts (at the final state) which is twice
/// the heat generated in the pure axial load case". Measured (5 orbits, as the seed):
/// axial 52.9 W (9 500; 52.60 W once settled) and 28.5 W (8 500); radial peak over the
/// last orbit 124.05 W = 2.35× the axial case (the held cage gives 176 W = 3.0×), mean
/// 73.5 W per ball; the balls' last-orbit mean orbital speeds spread by the printed
/// amount. Checked: axial within ±20 %, the radial peak between 1.6× and 2.6× the
/// axial heat and below the held cage's peak; the peak pinned to ±1 % (a regression
/// guard for this model, not agreement with the seed's 100 W, which it exceeds by
/// ~24 %).
#[test]
fn free_orbit_heat_against_the_seed() {
    let mut axial = 0.0;
    for (n, want) in [(9_500.0, 57.0), (8_500.0, 32.0)] {
        let a = analyse(&free_case(n, Method::TimeSimulation), Cancel::NONE).unwrap();
        let per_ball = a.total_heat_w / 20.0;
        eprintln!("free axial {n} rpm: {per_ball:.4} W per ball (seed {want})");
        assert!(
            (per_ball / want - 1.0).abs() < 0.2,
            "{n}: {per_ball} W vs {want}"
        );
        if n == 9_500.0 {
            axial = per_ball;
        }
    }
    let mut input = free_case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let ts = analyse(&input, Cancel::NONE).unwrap();
    let d = ts.dynamics.as_ref().unwrap();
    let mut peak: f64 = 0.0;
    for b in &d.balls {
        let end = b.history.last().unwrap().time_s;
        let period = end / input.dynamics.orbits;
        for s in b
            .history
            .iter()
            .filter(|s| s.time_s >= end - period * (1.0 + 1e-9))
        {
            peak = peak.max(s.heat_w);
        }
    }
    let wm: Vec<f64> = d.balls.iter().map(|b| b.orbital_rad_s).collect();
    let (lo, hi) = wm.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, &x| {
        (a.0.min(x), a.1.max(x))
    });
    let cage = ts.balls[0].cage_rad_s;
    eprintln!(
        "free radial: peak {peak:.2} W/ball ({:.2}× axial {axial:.2} W), mean {:.2} W/ball, ω_m {lo:.4}…{hi:.4} rad/s (spread {:.2e} relative; race control's cage {cage:.4})",
        peak / axial,
        d.total_w() / d.balls.len() as f64,
        (hi - lo) / hi
    );
    assert!((1.6..2.6).contains(&(peak / axial)), "{peak} / {axial}");
    assert!(peak < 176.1);
    // The quasi-static free orbit under the same load solves at every ball (from the
    // held cage's balance; from race control the most loaded ball stalled) and is "much
    // smaller than the time-simulation results" (seed ch. 6): 44.9 W per ball.
    input.dynamics.method = Method::QuasiStatic;
    let qs = analyse(&input, Cancel::NONE).unwrap();
    let qs_w = qs.dynamics.as_ref().unwrap().total_w() / 20.0;
    eprintln!("free radial quasi-static: {qs_w:.4} W per ball");
    assert!(qs_w < 0.8 * d.total_w() / 20.0, "{qs_w}");
    assert!((peak / 124.05 - 1.0).abs() < 0.01, "{peak}");
}

/// The strips handed out centre-first in mirror pairs are those of the direct
/// definition (strip k between ξ = −1 + kw and −1 + (k+1)w, w = 2/N, load
/// Q(c(ξ₁) − c(ξ₀)) with c = ¾ξ − ¼ξ³, normal at φ = ξ_c a/R_def by explicit
/// trigonometry): every strip matched to 1e-12 (the recurrence's rounding), the loads
/// adding up to Q to 1e-12, for odd and even N and both contacts.
#[test]
fn mirrored_strips_are_the_direct_ones() {
    let input = case(9_500.0, Method::TimeSimulation);
    let curve = input.traction.curve();
    with_model(&input, &curve, |m0, _| {
        for nsl in [1usize, 2, 7, 8, 41] {
            let m = BallModel { slices: nsl, ..*m0 };
            let l = m.track.at(0.3);
            for (inner, c) in [(true, &l.inner), (false, &l.outer)] {
                let mut got = Vec::new();
                m.for_each_slice(inner, c, |s| got.push(*s));
                assert_eq!(got.len(), nsl);
                let total: f64 = got.iter().map(|s| s.q).sum();
                assert!((total / c.load_n - 1.0).abs() < 1e-12);
                let (s, co) = c.angle_rad.sin_cos();
                let n = if inner { [-s, -co] } else { [s, co] };
                let tau = [n[1], -n[0]];
                let f = if inner {
                    m.groove_curvatures.0
                } else {
                    m.groove_curvatures.1
                };
                let r_def = 2.0 / (2.0 / m.diameter_m + 1.0 / (f * m.diameter_m));
                let w = 2.0 / nsl as f64;
                let cum = |x: f64| 0.75 * (x - x * x * x / 3.0);
                for k in 0..nsl {
                    let (x0, x1) = (-1.0 + w * k as f64, -1.0 + w * (k + 1) as f64);
                    let (sp, cp) = (0.5 * (x0 + x1) * c.semi_major_m / r_def).sin_cos();
                    let nu = [cp * n[0] + sp * tau[0], cp * n[1] + sp * tau[1]];
                    let q = c.load_n * (cum(x1) - cum(x0));
                    let hit = got.iter().any(|g| {
                        (g.nu[0] - nu[0]).abs() < 1e-12
                            && (g.nu[1] - nu[1]).abs() < 1e-12
                            && (g.q - q).abs() < 1e-12 * c.load_n
                            && (g.d - ((0.5 * m.diameter_m - r_def) * cp + r_def)).abs()
                                < 1e-12 * m.diameter_m
                    });
                    assert!(hit, "N = {nsl}, strip {k}");
                }
            }
        }
    });
}

/// Free orbit with the steep curve of `steep_curve_switches_to_the_implicit_integrator`:
/// Rodas4 on the 5-state system (its 5×5 Jacobian: the analytic ω, ω_m block and the θ
/// column) agrees after 2 orbits with the automatic choice (final ω and ω_m within 1e-6
/// of |ω|, two rtol-1e-9 solutions). Measured: the automatic choice does not switch
/// here (121 DOPRI5 steps for 2 orbits): the free ball settles where most strips slide
/// beyond the curve's 5 mm/s break, so the held cage's stiffness does not arise.
#[test]
fn free_orbit_steep_curve_rodas4_agrees_with_auto() {
    let input = free_case(8_500.0, Method::TimeSimulation);
    let curve = TractionCurve::Table {
        points: vec![(0.0, 0.0), (0.005, 0.054)],
    };
    with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
        let (da, st) = simulate_ball(m, w0, 2.0, 1e-9, 0, Cancel::NONE).unwrap();
        let (dr, sr) =
            simulate_ball_with(m, w0, 2.0, 1e-9, ode::Method::Sdirk, 0, Cancel::NONE).unwrap();
        let (a, r) = (da.history.last().unwrap(), dr.history.last().unwrap());
        let scale = Vector3::from(r.omega_rad_s).norm();
        let diff = (Vector3::from(a.omega_rad_s) - Vector3::from(r.omega_rad_s)).norm();
        eprintln!(
            "free steep: auto/rodas4 ω diff {diff:e}, ω_m {} vs {}; {st:?}; {sr:?}",
            a.orbital_rad_s, r.orbital_rad_s
        );
        assert!(sr.jacobian_evaluations > 0);
        assert!(diff < 1e-6 * scale);
        assert!((a.orbital_rad_s - r.orbital_rad_s).abs() < 1e-6 * scale);
    });
}

/// The angle to the next track point ([`LoadTrack::angle_to_next_point`]), on the track
/// of Bearing B under 500 N radial load (20 balls, 18° apart), against the points'
/// azimuths directly: from a point the next is one spacing on, forward and backward;
/// from just past a point (within the gap) the one after; across 2π the wrap. Exact
/// arithmetic on the stored azimuths, so to 1e-12 rad (rem_euclid's rounding).
#[test]
fn track_angle_to_next_point() {
    let mut input = free_case(9_500.0, Method::RaceControl);
    input.operating.radial_load_n = 500.0;
    let a = analyse(&input, Cancel::NONE).unwrap();
    let track = LoadTrack::new(&a.balls);
    let pts: Vec<f64> = track.azimuths().collect();
    assert_eq!(pts.len(), 20);
    let sp = std::f64::consts::TAU / 20.0;
    let gap = 1e-3;
    for &p in &pts {
        for fwd in [true, false] {
            let d = track.angle_to_next_point(p, fwd, gap).unwrap();
            assert!((d - sp).abs() < 1e-12, "{p} {fwd}: {d}");
            // A miss within the gap: the point just passed (or just short of) is not aimed at.
            let s = if fwd { 1.0 } else { -1.0 };
            let d = track
                .angle_to_next_point(p - s * 0.5 * gap, fwd, gap)
                .unwrap();
            assert!((d - (sp + 0.5 * gap)).abs() < 1e-12, "{p} {fwd}: {d}");
            let d = track
                .angle_to_next_point(p + s * 2.0 * gap, fwd, gap)
                .unwrap();
            assert!((d - (sp - 2.0 * gap)).abs() < 1e-12, "{p} {fwd}: {d}");
        }
    }
    // Any azimuth, unwrapped: the same as its value in [0, 2π).
    let last = pts[19];
    let d = track
        .angle_to_next_point(last + 0.1 + 3.0 * std::f64::consts::TAU, true, gap)
        .unwrap();
    assert!((d - (pts[0] + std::f64::consts::TAU - last - 0.1)).abs() < 1e-9);
}

/// The free orbit integrated piecewise between its predicted track points (issue 16):
/// under 500 N radial load, ball 0 over 5 orbits at the deck's rtol 1e-8 against the same
/// ball at rtol 1e-11 (the reference, ~1000× tighter): the last orbit's mean heat to
/// 1e-6 relative and the final ω, ω_m to 1e-6 of |ω| (measured 3.4e-7 over all 20
/// balls; integrated in one piece, straddling the kinks, the balls' heat was off by up
/// to 1.0e-5, ball 0's by 5.6e-6). And the kinks no longer cost rejected steps: ≤ 40
/// (measured 19; 180 in one piece), the held cage's 13 being the floor.
#[test]
fn free_orbit_pieces_between_kinks_are_accurate_and_cheap() {
    let mut input = free_case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    let curve = input.traction.curve();
    with_orbit_model(&input, &curve, Orbit::Free, |m, w0| {
        let (d, st) = simulate_ball(m, w0, 5.0, 1e-8, 0, Cancel::NONE).unwrap();
        let (r, sr) = simulate_ball(m, w0, 5.0, 1e-11, 0, Cancel::NONE).unwrap();
        let (a, b) = (d.history.last().unwrap(), r.history.last().unwrap());
        let scale = Vector3::from(b.omega_rad_s).norm();
        let dw = (Vector3::from(a.omega_rad_s) - Vector3::from(b.omega_rad_s)).norm();
        let rel = (d.heat_w / r.heat_w - 1.0).abs();
        eprintln!(
            "free pieces: heat {} vs {} W (rel {rel:.2e}), ω diff {dw:.2e} rad/s; {st:?}; {sr:?}",
            d.heat_w, r.heat_w
        );
        assert!(rel < 1e-6, "{rel}");
        assert!(dw < 1e-6 * scale);
        assert!((a.orbital_rad_s - b.orbital_rad_s).abs() < 1e-6 * scale);
        assert!(st.rejected <= 40, "{st:?}");
        // Every sample time kept, in order (the pieces' ends fall between them).
        assert_eq!(d.history.len(), r.history.len());
        assert!(d.history.windows(2).all(|w| w[0].time_s < w[1].time_s));
    });
}

/// Issue 24 item 7: a ball whose integration needs far more steps than a settled one
/// fails at its step bound with the cause and the keys, not after 2 000 000 attempts
/// (chen_b, constant µ = 1 under 500 N radial: 42 s). Here 8 slices keep it fast in a
/// debug build and the bound is 300 attempts: the failure must name the bound, the
/// stiffness and `traction.mu`/`dynamics.tolerance`/`dynamics.orbits`.
#[test]
fn step_bound_stops_a_stiff_ball_with_the_cause_and_the_keys() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    input.dynamics.slices = 8;
    let curve = TractionCurve::Constant { mu: 1.0 };
    with_model(&input, &curve, |m, w0| {
        let limits = Limits {
            max_step_attempts: 300,
            max_samples: usize::MAX,
        };
        let e = simulate_ball_limited(m, w0, 5.0, 1e-8, ode::Method::Auto, 3, Cancel::NONE, limits)
            .unwrap_err()
            .to_string();
        // Ball index 3 is ball 4 in the message: text counts from 1 (issue 30 item 9).
        for want in [
            "ball 4",
            "more than 300 step attempts",
            "too stiff",
            "traction.mu",
            "dynamics.tolerance",
            "dynamics.orbits",
        ] {
            assert!(e.contains(want), "{want:?} not in {e}");
        }
    });
    // The bound `run` sets: 20× the measured steps per orbit, at least 20 000.
    let e = budget::estimate(&input, 20, false);
    assert_eq!(e.max_step_attempts, 25_000);
    assert_eq!(budget::estimate(&input, 20, true).max_step_attempts, 20_000);
}

/// The decimated history (a bound of 200 samples for 5 orbits of 451) keeps the last
/// orbit whole, so the summary (last-orbit means, amplitude) is the undecimated one
/// exactly (same steps: the output times do not move the integrator's steps; the
/// values at the kept times are the same dense-output evaluations, to 1e-12 relative),
/// the history is at most the bound, and progress is reported up to 1 while the flag,
/// set, still cancels.
#[test]
fn decimated_history_keeps_the_summary_and_reports_progress() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    input.dynamics.slices = 11;
    let curve = input.traction.curve();
    with_model(&input, &curve, |m, w0| {
        let (full, sf) = simulate_ball(m, w0, 5.0, 1e-8, 0, Cancel::NONE).unwrap();
        let seen = std::sync::Mutex::new(Vec::new());
        let p = |f: f64| seen.lock().unwrap().push(f);
        let limits = Limits {
            max_step_attempts: usize::MAX,
            max_samples: 200,
        };
        let (dec, sd) = simulate_ball_limited(
            m,
            w0,
            5.0,
            1e-8,
            ode::Method::Auto,
            0,
            Cancel::NONE.with_progress(&p),
            limits,
        )
        .unwrap();
        assert_eq!(full.history.len(), 451);
        assert!(dec.history.len() <= 200, "{}", dec.history.len());
        assert_eq!(sf.steps, sd.steps);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300);
        assert!(
            close(full.heat_w, dec.heat_w),
            "{} {}",
            full.heat_w,
            dec.heat_w
        );
        assert!(close(full.oscillation_rad_s, dec.oscillation_rad_s));
        assert!(close(full.orbital_rad_s, dec.orbital_rad_s));
        // The last orbit (91 samples) is the undecimated one, sample for sample.
        let n = dec.history.len();
        for (a, b) in full.history[451 - 91..].iter().zip(&dec.history[n - 91..]) {
            assert_eq!(a.time_s, b.time_s);
            assert!(close(a.heat_w, b.heat_w));
        }
        let seen = seen.lock().unwrap();
        assert!(seen.len() >= 10, "{seen:?}");
        assert!(seen.windows(2).all(|w| w[0] <= w[1]));
        assert_eq!(seen.last(), Some(&1.0));
        // Cancelled before it starts: the progress report does not hide the flag.
        let flag = std::sync::atomic::AtomicBool::new(true);
        let r = simulate_ball_limited(
            m,
            w0,
            5.0,
            1e-8,
            ode::Method::Auto,
            0,
            Cancel::new(&flag).with_progress(&p),
            limits,
        );
        assert!(matches!(r, Err(BallError::Cancelled)), "{r:?}");
    });
}

/// `run` refuses a time simulation past its work bound before integrating anything
/// (fast: the refusal is up front), naming the keys; race control with the same
/// orbits and slices is not refused (nothing is simulated).
#[test]
fn run_refuses_a_simulation_past_its_bound_up_front() {
    let mut input = case(9_500.0, Method::TimeSimulation);
    input.operating.radial_load_n = 500.0;
    input.dynamics.orbits = 1000.0;
    let mut rc = input.clone();
    rc.dynamics.method = Method::RaceControl;
    let a = analyse(&rc, Cancel::NONE).unwrap();
    let t = std::time::Instant::now();
    let e = run(&input, &a.geometry, &a.balls, Cancel::NONE)
        .unwrap_err()
        .to_string();
    assert!(t.elapsed().as_secs_f64() < 0.5, "{:?}", t.elapsed());
    assert!(e.contains("dynamics.orbits (now 1000)"), "{e}");
    assert!(e.contains("geometry.ball_count (now 20"), "{e}");
}

/// Issue 30 item 4: the text report's RACE CONTROL table shows race control's heat per
/// ball (its spin heat, eq. 2-7) even when a time simulation replaced the ball's heat by
/// its own (the column read the simulated 52.863 W where race control gives 12.244 W).
/// Read back from the text: the table's `H W` column sums to `race_control_heat_w`
/// within the printed rounding (20 balls × 0.0005 W).
#[test]
fn race_control_table_shows_race_control_heat() {
    let a = analyse(&case(9_500.0, Method::TimeSimulation), Cancel::NONE).unwrap();
    let text = crate::bearings::angular_ball::report::text(&a, crate::units::Units::Si);
    let table = text
        .split("RACE CONTROL")
        .nth(1)
        .expect("a RACE CONTROL table");
    let mut lines = table.lines().skip(1);
    let header = lines.next().expect("header");
    assert!(header.contains(" H W "), "{header}");
    // The heat is the 11th number of each row (#, cage, ωsi, ωso, ωri, ωro, s/r i,
    // s/r o, u i, u o, H).
    let heat: f64 = lines
        .take(a.balls.len())
        .map(|l| {
            let cells: Vec<f64> = l
                .split_whitespace()
                .map(|c| c.parse::<f64>().expect("a number"))
                .collect();
            cells[10]
        })
        .sum();
    assert!(
        (heat - a.race_control_heat_w).abs() <= 0.0005 * a.balls.len() as f64,
        "table {heat} W vs race control {} W (simulated {} W)",
        a.race_control_heat_w,
        a.total_heat_w
    );
    assert!(a.total_heat_w > 2.0 * a.race_control_heat_w);
}
