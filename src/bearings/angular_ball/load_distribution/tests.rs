use super::ball::BallProblem;
use super::driver::solve_recorded;
use super::*;
use crate::bearings::angular_ball::input::{rpm, BallInput};
use crate::numerics::newton::{Backtracking, Newton, TrustRegion};
use crate::physics::contact::point::Race;
use nalgebra::Vector2;

fn geom(input: &BallInput) -> BallGeometry {
    BallGeometry::new(input).unwrap()
}

fn conditions(speed_rpm: f64, axial: Axial, radial: f64, sign: GyroscopicFriction) -> Conditions {
    Conditions {
        inner_speed_rad_s: rpm(speed_rpm),
        outer_speed_rad_s: 0.0,
        axial,
        radial_load_n: radial,
        tilt: Tilt::Held(0.0),
        race_control: RaceControl::Outer,
        gyroscopic_friction: sign,
        friction_split: crate::bearings::angular_ball::input::FrictionSplit::Proportional,
        max_friction: 0.054,
    }
}

/// The preload held as displacement: the axial displacement 1000 N produces at rest.
fn rest_displacement(g: &BallGeometry) -> f64 {
    let c = conditions(
        0.0,
        Axial::Force(1000.0),
        0.0,
        GyroscopicFriction::Resisting,
    );
    solve(g, &c, Cancel::NONE).unwrap().axial_deflection_m
}

fn deg(x: f64) -> f64 {
    x.to_degrees()
}

/// Zero speed, pure axial load: all balls equal and Z·Q·sin α = F_a to 1e-9 (relative;
/// the ring tolerance is 1e-11 of the load), for both bearings; Q_i = Q_o and α_i = α_o
/// (no centrifugal force: the ball sits on the line of centres, 1e-12).
#[test]
fn zero_speed_axial_load_balances_exactly() {
    for input in [BallInput::chen_a(), BallInput::chen_b()] {
        let g = geom(&input);
        let c = conditions(
            0.0,
            Axial::Force(1000.0),
            0.0,
            GyroscopicFriction::Resisting,
        );
        let s = solve(&g, &c, Cancel::NONE).unwrap();
        let b0 = s.balls[0].equilibrium;
        for b in &s.balls {
            assert_eq!(b.equilibrium.inner.load_n, b0.inner.load_n);
        }
        let sum = 20.0 * b0.inner.load_n * b0.inner.angle_rad.sin();
        assert!((sum / 1000.0 - 1.0).abs() < 1e-9, "{sum}");
        assert!((b0.inner.load_n / b0.outer.load_n - 1.0).abs() < 1e-12);
        assert!((b0.inner.angle_rad - b0.outer.angle_rad).abs() < 1e-12);
        assert!(b0.inner.angle_rad > g.free_contact_angle_rad);
    }
}

/// The seed's ch. 6 load distribution (pp. 68–69), reproduced with the seed's printed
/// sign of the gyroscopic friction in (2-5): Bearing A at 10 000 rpm α_i 21.06°,
/// α_o 13.96°, Q_i 163.7 N, Q_o 251.6 N; Bearing B at 9 500 rpm 68.73°, 51.70°, 247.5 N,
/// 300.9 N; preload 1000 N held as the displacement it produces at rest. Tolerances: angles
/// ±0.2°, loads ±1.5 % (the brief's; Chen's Brewe–Hamrock fits and his radial-plane
/// raceway radius differ from our exact Hertz by that order). Measured: A 20.94°, 13.93°,
/// 164.7 N, 252.5 N; B 68.71°, 51.71°, 248.7 N, 302.0 N.
#[test]
fn chen_load_distribution_with_the_seed_sign() {
    for (input, n, want) in [
        (BallInput::chen_a(), 10_000.0, [21.06, 13.96, 163.7, 251.6]),
        (BallInput::chen_b(), 9_500.0, [68.73, 51.70, 247.5, 300.9]),
    ] {
        let g = geom(&input);
        let d = rest_displacement(&g);
        let c = conditions(n, Axial::Displacement(d), 0.0, GyroscopicFriction::SeedSign);
        let s = solve(&g, &c, Cancel::NONE).unwrap();
        let b = s.balls[0].equilibrium;
        let got = [
            deg(b.inner.angle_rad),
            deg(b.outer.angle_rad),
            b.inner.load_n,
            b.outer.load_n,
        ];
        assert!((got[0] - want[0]).abs() < 0.2, "{got:?}");
        assert!((got[1] - want[1]).abs() < 0.2, "{got:?}");
        assert!((got[2] / want[2] - 1.0).abs() < 0.015, "{got:?}");
        assert!((got[3] / want[3] - 1.0).abs() < 0.015, "{got:?}");
    }
}

/// With the physically consistent friction direction (the default) the gyroscopic
/// friction pushes the other way: Bearing A at 10 000 rpm gives α_i ≈ 21.29°,
/// α_o ≈ 13.59°, Q_i ≈ 173.6 N, Q_o ≈ 260.5 N (6 % and 3.5 % above the seed's print),
/// Bearing B at 9 500 rpm 68.90°, 51.51°, 265.3 N, 309.6 N. Regression values of this
/// implementation (cross-checked by an independent Python script with finite-difference
/// Newton, 1e-3), tolerance 0.05° and 0.2 %.
#[test]
fn load_distribution_with_resisting_friction() {
    for (input, n, want) in [
        (
            BallInput::chen_a(),
            10_000.0,
            [21.288, 13.590, 173.58, 260.49],
        ),
        (
            BallInput::chen_b(),
            9_500.0,
            [68.902, 51.514, 265.32, 309.64],
        ),
    ] {
        let g = geom(&input);
        let d = rest_displacement(&g);
        let c = conditions(
            n,
            Axial::Displacement(d),
            0.0,
            GyroscopicFriction::Resisting,
        );
        let s = solve(&g, &c, Cancel::NONE).unwrap();
        let b = s.balls[0].equilibrium;
        assert!((deg(b.inner.angle_rad) - want[0]).abs() < 0.05, "{b:?}");
        assert!((deg(b.outer.angle_rad) - want[1]).abs() < 0.05, "{b:?}");
        assert!((b.inner.load_n / want[2] - 1.0).abs() < 2e-3, "{b:?}");
        assert!((b.outer.load_n / want[3] - 1.0).abs() < 2e-3, "{b:?}");
    }
}

/// At the solution the contact forces balance the centrifugal force (the ball residual is
/// below its tolerance) and, with the resisting convention, the friction couple about the
/// ball centre, computed from the contact points and forces as vectors, equals the
/// precession moment J·ω_m·ω_r along the rolling direction t = a × r (1e-9 relative).
#[test]
fn friction_couple_supplies_the_precession() {
    let input = BallInput::chen_b();
    let g = geom(&input);
    let d = rest_displacement(&g);
    let c = conditions(
        9_500.0,
        Axial::Displacement(d),
        0.0,
        GyroscopicFriction::Resisting,
    );
    let s = solve(&g, &c, Cancel::NONE).unwrap();
    let b = s.balls[0];
    let e = b.equilibrium;
    let h = 0.5 * g.ball_diameter_m;
    let (si, ci) = e.inner.angle_rad.sin_cos();
    let (so, co) = e.outer.angle_rad.sin_cos();
    // Contact points relative to the ball centre and the friction forces on the ball.
    let p_i = [-h * si, -h * ci];
    let p_o = [h * so, h * co];
    let mu = 2.0 * b.gyroscopic_moment_nm / (g.ball_diameter_m * (e.inner.load_n + e.outer.load_n));
    let f_i = [mu * e.inner.load_n * ci, -mu * e.inner.load_n * si];
    let f_o = [-mu * e.outer.load_n * co, mu * e.outer.load_n * so];
    // (p × F)_t = p_a F_r − p_r F_a in the right-handed (a, r, t) frame.
    let couple = p_i[0] * f_i[1] - p_i[1] * f_i[0] + p_o[0] * f_o[1] - p_o[1] * f_o[0];
    let precession =
        g.ball_inertia_kg_m2 * b.kinematics.cage_rad_s * b.kinematics.ball_radial_rad_s;
    assert!(precession > 0.0);
    assert!(
        (couple / precession - 1.0).abs() < 1e-9,
        "{couple} vs {precession}"
    );
    // And the whole force balance with these friction forces closes.
    let fa = e.inner.load_n * si - e.outer.load_n * so + f_i[0] + f_o[0];
    let fr = e.inner.load_n * ci - e.outer.load_n * co + f_i[1] + f_o[1] + e.centrifugal_n;
    assert!(fa.abs() < 1e-8 && fr.abs() < 1e-8, "{fa} {fr}");
}

/// The analytic ball Jacobian and the ring stiffness dP/d(I − O') against central finite
/// differences (step 1e-9 m; agreement 1e-5 relative to the largest entry).
#[test]
fn analytic_jacobians_match_finite_differences() {
    let input = BallInput::chen_b();
    let g = geom(&input);
    let p = BallParams {
        friction: 0.04,
        outer_friction: 0.04,
        centrifugal_coeff: 0.007 * 500.0 * 500.0,
        inner_stiffness: g.contact(Race::Inner, 1.2).unwrap().stiffness_n_per_m1_5(),
        outer_stiffness: g.contact(Race::Outer, 0.9).unwrap().stiffness_n_per_m1_5(),
    };
    let a0 = g.free_contact_angle_rad;
    let centres = Vector2::new(
        g.centre_distance_m * a0.sin() + 40e-6,
        g.centre_distance_m * a0.cos(),
    );
    let prob = BallProblem {
        geom: &g,
        centres,
        p,
    };
    let x = Vector2::new(0.25e-3, 0.14e-3);
    let e = prob.eval(&x);
    let h = 1e-9;
    let scale = e.j.amax();
    for k in 0..2 {
        let mut dx = Vector2::zeros();
        dx[k] = h;
        let fd = (prob.eval(&(x + dx)).f - prob.eval(&(x - dx)).f) / (2.0 * h);
        for r in 0..2 {
            assert!(
                (fd[r] - e.j[(r, k)]).abs() < 1e-5 * scale,
                "J[{r},{k}] {} vs {}",
                e.j[(r, k)],
                fd[r]
            );
        }
    }
    // Ring stiffness: re-solve the ball for perturbed centres.
    let b = solve_ball(&g, centres, p, None, 1e-9, 0).unwrap();
    let kscale = b.ring_stiffness.amax();
    for k in 0..2 {
        let mut dc = Vector2::zeros();
        dc[k] = h;
        let plus = solve_ball(&g, centres + dc, p, Some(b.position), 1e-9, 0).unwrap();
        let minus = solve_ball(&g, centres - dc, p, Some(b.position), 1e-9, 0).unwrap();
        let fd = (plus.ring_force - minus.ring_force) / (2.0 * h);
        for r in 0..2 {
            assert!(
                (fd[r] - b.ring_stiffness[(r, k)]).abs() < 1e-5 * kscale,
                "K[{r},{k}] {} vs {}",
                b.ring_stiffness[(r, k)],
                fd[r]
            );
        }
    }
}

/// Under a radial load (Bearing B, 1000 N preload as displacement, 500 N radial, 9 500
/// rpm, the seed's Fig. 6-9 case) the ring balances F_r to the ring tolerance, the load
/// distribution is symmetric about ψ = 0 (balls j and Z − j equal to 1e-9 relative) and
/// the ball at ψ = 0 carries the most inner load.
#[test]
fn radial_load_balances_and_is_symmetric() {
    let input = BallInput::chen_b();
    let g = geom(&input);
    let d = rest_displacement(&g);
    let c = conditions(
        9_500.0,
        Axial::Displacement(d),
        500.0,
        GyroscopicFriction::Resisting,
    );
    let s = solve(&g, &c, Cancel::NONE).unwrap();
    assert!(
        (s.radial_force_n - 500.0).abs() < 1e-6,
        "{}",
        s.radial_force_n
    );
    let q: Vec<f64> = s.balls.iter().map(|b| b.equilibrium.inner.load_n).collect();
    for j in 1..20 {
        assert!((q[j] / q[20 - j] - 1.0).abs() < 1e-9, "{q:?}");
    }
    let max = q.iter().cloned().fold(0.0, f64::max);
    assert_eq!(max, q[0]);
    assert!(q[10] < q[0]);
    // Held as a force instead (at 3 000 rpm, Bearing A): the axial force is the load.
    let g = geom(&BallInput::chen_a());
    let c = conditions(
        3_000.0,
        Axial::Force(1000.0),
        500.0,
        GyroscopicFriction::Resisting,
    );
    let s = solve(&g, &c, Cancel::NONE).unwrap();
    assert!((s.axial_force_n - 1000.0).abs() < 1e-6);
    assert!((s.radial_force_n - 500.0).abs() < 1e-6);
}

/// The preload held as a force (not the seed's reading): at 9 500 rpm Bearing B's inner
/// contact angle runs past 90° (the issue quotes ≈ 88°), the axial force still 1000 N.
///
/// Why past 90°, and why that is the model's physics and not a defect (numbers printed
/// by this test):
/// * Geometry. Bearing B's grooves (f_i = f_o = 0.52, α₀ = 60°) put the inner groove
///   centre at the radius A cos α₀ = 0.04·12 mm·½ = 0.240 mm above the outer groove
///   centre O', exactly the outer groove offset (f_o − ½)D = 0.240 mm. The ball centre
///   sits at L_o cos α_o above O', L_o = (f_o − ½)D + δ_o; so α_i > 90° (the inner
///   contact normal pointing radially inwards) exactly when (0.240 mm + δ_o) cos α_o >
///   0.240 mm. Held as a force, the preload leaves each ball only F_a/Z = 50 N axially,
///   against 300–335 N of centrifugal force: the outer contact turns almost radial
///   (α_o = 6.35°) and its approach δ_o = 4.7 µm lifts the ball centre 3.2 µm above the
///   inner groove centre, while the inner groove centre lies 241 µm axially from it:
///   α_i = 90° + atan(3.2/241) = 90.76°. The margin is the 4.7 µm of δ_o: with a rigid
///   outer contact (δ_o = 0) the same angles would put α_i at 89.65°. The seed has no
///   force-held case (no 88° in it); the issue's ≈ 88° is an estimate this model does
///   not reproduce (the nearest: 89.21° with the seed's printed friction sign).
/// * Not the friction term (2-7) nor its sign: with µ = 0 α_i is 90.25°; the resisting
///   friction (the default) gives 90.76°, the seed's printed sign 89.21° (the friction
///   couple changes α_o, hence the cage speed and the centrifugal force, by a few %).
/// * Inner race control gives 79.5° (another cage speed): the angle is set by the
///   centrifugal load on the outer race, as above.
///
/// A real inner ring's shoulder ends well below the ball centre, so a contact at 90.8° is
/// off the ring there (the model's groove is a full torus and has no shoulder); the
/// displacement-held preload (the default, the seed's reading) keeps α_i at 68.9°.
///
/// Tolerances: α_i = 90.76° ± 0.01° (the value of this model, a regression pin: the
/// solve converges to 1e-12 rad, the band leaves room for nothing but changes in the
/// model); the geometric identity (the ball-centre radius L_o cos α_o against A cos α₀
/// decides the side of 90°) to 1e-12 m of the positions and the sign; ΣP_a = 1000 N to
/// 1e-6 N; µ = 0 above 90° and below the resisting-friction angle.
#[test]
fn force_held_preload_lets_the_inner_angle_run_up() {
    let input = BallInput::chen_b();
    let g = geom(&input);
    let run = |max_friction: f64, sign: GyroscopicFriction| {
        let mut c = conditions(9_500.0, Axial::Force(1000.0), 0.0, sign);
        c.max_friction = max_friction;
        solve(&g, &c, Cancel::NONE).unwrap()
    };
    let s = run(0.054, GyroscopicFriction::Resisting);
    let b = s.balls[0].equilibrium;
    assert!((s.axial_force_n - 1000.0).abs() < 1e-6);
    let (ai, ao) = (deg(b.inner.angle_rad), deg(b.outer.angle_rad));
    assert!((ai - 90.76).abs() < 0.01, "{ai}");
    // The geometry: the ball centre X = L_o (sin α_o, cos α_o) from O' with L_o the outer
    // groove offset plus the approach, the inner groove centre at A cos α₀ radially.
    let l_o = g.outer_offset_m + b.outer.deflection_m;
    let x_r = l_o * b.outer.angle_rad.cos();
    assert!((x_r - b.position[1]).abs() < 1e-12 * l_o);
    let i_r = g.centre_distance_m * g.free_contact_angle_rad.cos();
    assert!(
        (i_r - g.outer_offset_m).abs() < 1e-15,
        "Bearing B's coincidence"
    );
    assert_eq!(b.inner.angle_rad > std::f64::consts::FRAC_PI_2, x_r > i_r);
    eprintln!(
        "force-held B: α_i {ai:.3}°, α_o {ao:.3}°, Q_i {:.2} N, Q_o {:.2} N, δ_o {:.2} µm, \
         ball centre {:.2} µm above the inner groove centre, F_c {:.1} N",
        b.inner.load_n,
        b.outer.load_n,
        b.outer.deflection_m * 1e6,
        (x_r - i_r) * 1e6,
        b.centrifugal_n
    );
    // Without friction (µ capped at 0) still past 90°: the friction is not the cause.
    let free = deg(run(0.0, GyroscopicFriction::Resisting).balls[0]
        .equilibrium
        .inner
        .angle_rad);
    assert!(free > 90.0 && free < ai, "{free}");
    let seed = deg(run(0.054, GyroscopicFriction::SeedSign).balls[0]
        .equilibrium
        .inner
        .angle_rad);
    eprintln!("µ = 0: α_i {free:.3}°; seed sign: α_i {seed:.3}°");
    assert!(seed < free, "{seed}");
}

/// The mirror symmetry of [`Layout`] is exact: solving only the balls at ψ ≤ π (each
/// standing for its mirror at −ψ) gives every ball's contact loads, angles, centre radius
/// and race-control speeds, and the ring's displacement and forces, as solving all Z
/// balls does, to 1e-12 relative (the two differ only by the rounding of cos(2πj/Z)
/// against cos(2π(Z − j)/Z) and the order of the ring sums: round-off, amplified by the
/// fixed point's 1e-10 load criterion at most to this), with the same number of
/// fixed-point iterations. Cases: Bearing B at 9 500 rpm with 500 N radial (preload held
/// as displacement), Bearing A at 3 000 rpm with 1000 N axial force and 500 N radial, and
/// Bearing A at 12 000 rpm with 3 000 N radial on 1000 N axial force, where the inner
/// contacts of the balls opposite the load open (the outer-race-alone path).
#[test]
fn mirror_symmetry_equals_the_full_solve() {
    let b = geom(&BallInput::chen_b());
    let a = geom(&BallInput::chen_a());
    let cases = [
        (
            &b,
            conditions(
                9_500.0,
                Axial::Displacement(rest_displacement(&b)),
                500.0,
                GyroscopicFriction::Resisting,
            ),
        ),
        (
            &a,
            conditions(
                3_000.0,
                Axial::Force(1000.0),
                500.0,
                GyroscopicFriction::Resisting,
            ),
        ),
        (
            &a,
            conditions(
                12_000.0,
                Axial::Force(1000.0),
                3000.0,
                GyroscopicFriction::Resisting,
            ),
        ),
    ];
    let mut opened = false;
    for (g, c) in cases {
        let half = solve(g, &c, Cancel::NONE).unwrap();
        let full = solve_recorded(g, &c, Cancel::NONE, &mut None, false).unwrap();
        let rel = |x: f64, y: f64, scale: f64| (x - y).abs() / scale.max(1e-300);
        let fscale = c.radial_load_n.max(1000.0);
        assert!(
            rel(
                half.axial_deflection_m,
                full.axial_deflection_m,
                full.axial_deflection_m.abs()
            ) < 1e-12
        );
        assert!(
            rel(
                half.radial_deflection_m,
                full.radial_deflection_m,
                full.radial_deflection_m.abs()
            ) < 1e-12
        );
        assert!(rel(half.axial_force_n, full.axial_force_n, fscale) < 1e-12);
        assert!(rel(half.radial_force_n, full.radial_force_n, fscale) < 1e-12);
        assert_eq!(
            half.stats.fixed_point_iterations,
            full.stats.fixed_point_iterations
        );
        assert_eq!(half.balls.len(), 20);
        let qmax = full
            .balls
            .iter()
            .map(|b| b.equilibrium.inner.load_n.max(b.equilibrium.outer.load_n))
            .fold(0.0, f64::max);
        for (h, f) in half.balls.iter().zip(&full.balls) {
            let (he, fe) = (h.equilibrium, f.equilibrium);
            assert_eq!(h.azimuth_rad, f.azimuth_rad);
            opened |= fe.inner.load_n == 0.0;
            for (x, y) in [
                (he.inner.load_n, fe.inner.load_n),
                (he.outer.load_n, fe.outer.load_n),
            ] {
                assert!(rel(x, y, qmax) < 1e-12, "{x} vs {y}");
            }
            for (x, y) in [
                (he.inner.angle_rad, fe.inner.angle_rad),
                (he.outer.angle_rad, fe.outer.angle_rad),
            ] {
                assert!((x - y).abs() < 1e-12, "{x} vs {y}");
            }
            assert!(rel(he.centre_radius_m, fe.centre_radius_m, fe.centre_radius_m) < 1e-12);
            assert!(
                rel(
                    h.kinematics.cage_rad_s,
                    f.kinematics.cage_rad_s,
                    f.kinematics.cage_rad_s.abs()
                ) < 1e-12
            );
            assert!(
                rel(
                    h.gyroscopic_moment_nm,
                    f.gyroscopic_moment_nm,
                    f.gyroscopic_moment_nm.abs().max(1e-30)
                ) < 1e-12
            );
        }
    }
    assert!(opened, "no case opened an inner contact");
}

/// Issue 16: a loose ball (the races do not pinch it: gap −0.49 µm) held by a tiny
/// centrifugal force (ball 9 of Bearing B, force-held preload, 500 N radial, at the skid
/// search's ω_i = 0.10 rad/s: F_c = 0.94 µN) is wedged between the grooves with loads of
/// ~9 µN. From the fixed point's warm start (inner contact open by 8.0 nm) Newton crawls
/// ~55 pm a step (the inner contact's stiffness caps the trust radius) and spends its 100
/// iterations (residual 8.0e-6 N, tolerance 5e-10 N); the wedged start converges at once.
/// Checked independently: both contacts carry load, the force residual F of (2-5a, b)
/// re-evaluated at the answer is within the 5e-10 N tolerance (the solver's), and the
/// answer is the outer intersection of the two deflected groove circles (|X| = (f_o − ½)D
/// + δ_o, |(I − O') − X| = (f_i − ½)D + δ_i) to 1e-15 m (round-off of 2.4e-4 m).
#[test]
fn loose_ball_wedged_by_a_small_centrifugal_force_converges() {
    let g = geom(&BallInput::chen_b());
    let centres = Vector2::new(4.1893146544959254e-4, 2.332927877710085e-4);
    let p = BallParams {
        friction: 0.0,
        outer_friction: 0.0,
        centrifugal_coeff: 1.63486071801454e-5,
        inner_stiffness: 32198757603.963516,
        outer_stiffness: 32676339438.850777,
    };
    let warm = Vector2::new(0.00020423331989505514, 0.0001260506721391007);
    let gap = centres.norm() - g.inner_offset_m - g.outer_offset_m;
    assert!(gap < -4e-7 && gap > -6e-7, "{gap}");
    // The plain Newton from the warm start does not make it (what the issue saw).
    let newton = Newton {
        max_iterations: 100,
        tolerance: 5e-10,
        trust: TrustRegion::new(1e-5, 1e-15, 1e-3),
        line_search: Backtracking::default(),
    };
    let mut sys = BallProblem {
        geom: &g,
        centres,
        p,
    };
    let mut x = warm;
    assert!(!newton.solve(&mut sys, &mut x).termination.is_converged());
    let b = solve_ball(&g, centres, p, Some(warm), 5e-10, 9).unwrap();
    assert!(b.residual_n <= 5e-10, "{}", b.residual_n);
    assert!(sys.eval(&b.position).f.amax() <= 5e-10);
    let (qi, qo) = (b.inner.load_n, b.outer.load_n);
    assert!(qi > 5e-6 && qo > 5e-6, "{qi} {qo}");
    let r_o = g.outer_offset_m + b.outer.deflection_m;
    let r_i = g.inner_offset_m + b.inner.deflection_m;
    assert!((b.position.norm() - r_o).abs() < 1e-15);
    assert!(((centres - b.position).norm() - r_i).abs() < 1e-15);
    // The outer of the two intersections: radially beyond the line of centres.
    let e = centres / centres.norm();
    assert!(e[0] * b.position[1] - e[1] * b.position[0] > 0.0);
}

/// Issue 16, the whole case: Bearing B, 1000 N preload held as a force, 500 N radial, at
/// the deck's 9 500 rpm and at the skid search's lowest sample (ω_i = 0.1016 rad/s, where
/// the balls opposite the load are loose and failed before). Every ball's force residual
/// is within the solve's ball tolerance, and the ring balance (2-8) holds to its
/// tolerance when re-summed from the balls: F_a = Σ P_a and F_r = Σ P_r cos ψ with P the
/// inner ring's force on each ball (friction included; see the module doc), and Chen's
/// frictionless F_r = Σ Q_i cos α_i cos ψ to the friction's share. Tolerances: the
/// solver's own (per ball 1e-11·F_ref/Z, or a stall at 1e-12 of the ball's forces, their
/// round-off; 1e-10·F_ref for the ring; F_ref as the solver forms it), plus 1e-9 N for
/// re-summing.
#[test]
fn force_held_preload_under_radial_load_solves() {
    let input = BallInput::chen_b();
    let g = geom(&input);
    for speed in [rpm(9_500.0), 0.10156012715088496] {
        let mut c = conditions(
            0.0,
            Axial::Force(1000.0),
            500.0,
            GyroscopicFriction::Resisting,
        );
        c.inner_speed_rad_s = speed;
        c.max_friction = input.traction.curve().max_mu();
        let l = solve(&g, &c, Cancel::NONE).unwrap();
        let z = g.ball_count as f64;
        // The solver's force scale: the largest of the loads and Z times the centrifugal
        // force at half the inner speed on the pitch circle (`solve_warm`).
        let wm = 0.5 * speed;
        let f_ref = (1000.0f64).max(z * g.ball_mass_kg * wm * wm * 0.5 * g.pitch_diameter_m);
        assert!(l.ring_residual_n <= 1e-10 * f_ref, "{}", l.ring_residual_n);
        let (mut fa, mut fr, mut fr_chen, mut fric) = (0.0, 0.0, 0.0, 0.0);
        for b in &l.balls {
            let e = b.equilibrium;
            // The ball solve's acceptance: its tolerance, or a line-search stall at the
            // round-off of the forces that make the residual (1e-12 of Q_i + Q_o + F_c).
            let roundoff = 1e-12 * (e.inner.load_n + e.outer.load_n + e.centrifugal_n);
            assert!(
                e.residual_n <= (1e-11 * f_ref / z).max(roundoff),
                "{} {roundoff}",
                e.residual_n
            );
            fa += e.ring_force[0];
            fr += e.ring_force[1] * b.azimuth_rad.cos();
            fr_chen += e.inner.load_n * e.inner.angle_rad.cos() * b.azimuth_rad.cos();
            fric += (e.ring_force[1] - e.inner.load_n * e.inner.angle_rad.cos()).abs();
        }
        assert!((fa - 1000.0).abs() <= 1e-10 * f_ref + 1e-9, "{fa}");
        assert!((fr - 500.0).abs() <= 1e-10 * f_ref + 1e-9, "{fr}");
        assert!((l.radial_force_n - 500.0).abs() <= 1e-10 * f_ref + 1e-9);
        assert!((fr_chen - 500.0).abs() <= fric + 1e-9, "{fr_chen} {fric}");
        eprintln!(
            "ω_i {speed:.4} rad/s: F_a {fa:.9} N, F_r {fr:.9} N, Σ Q_i cos α_i cos ψ {fr_chen:.6} N, \
             ball residual {:.2e} N, ball 9 Q_i {:.3} N",
            l.ball_residual_n, l.balls[9].equilibrium.inner.load_n
        );
    }
}

/// Issue 16 as the CLI ran it (`run decks/chen_b.toml --set operating.radial_load=500
/// --set operating.preload_mode=force`): the whole analysis (skid search included, whose
/// lowest speeds made the loose balls) completes.
#[test]
fn force_held_preload_analysis_completes_under_radial_load() {
    use crate::bearings::angular_ball::analysis::analyse;
    use crate::bearings::angular_ball::input::PreloadMode;
    let mut input = BallInput::chen_b();
    input.operating.preload_mode = PreloadMode::Force;
    for radial in [500.0, 800.0] {
        input.operating.radial_load_n = radial;
        let a = analyse(&input, Cancel::NONE).unwrap();
        assert!((a.load.radial_force_n - radial).abs() < 1e-6);
    }
}
