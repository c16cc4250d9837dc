//! Tests of the bearing equilibrium and stiffness against the closed forms,
//! symmetry and re-solved finite differences.

use super::*;
use crate::units::{INCH_M, LBF_N, RPM_RAD_S};

fn sample(rpm: f64, radial_lbf: f64) -> TaperedInput {
    let mut s = TaperedInput::afapl_sample();
    s.operating.inner_speed_rad_s = rpm * RPM_RAD_S;
    s.operating.radial_load_n = radial_lbf * LBF_N;
    s
}

fn solve(s: &TaperedInput) -> (Bearing, BearingSolution) {
    let b = Bearing::new(s).unwrap();
    let sol = b.solve().unwrap();
    (b, sol)
}

/// Pure thrust (Load Condition 1): P₁ = F_a/(n sin β) = 320.23 lbf and the force-balance
/// closed forms for P₂ and P₃ to 1e-6 (the equilibrium is solved to 1e-9 of the load);
/// P₃ = 8.94 lbf at rest and 26.49 lbf at 20 000 rpm (issue's values, given to 3–4
/// digits: 6e-4); the speed part of P₃ grows as the cage speed squared (1e-6).
#[test]
fn pure_thrust_closed_forms() {
    let mut p3 = Vec::new();
    let mut cage = Vec::new();
    for rpm in [0.0, 10_000.0, 20_000.0] {
        let (b, sol) = solve(&sample(rpm, 0.0));
        let g = &b.input.geometry;
        let (beta, t, a, psi) = (
            g.cup_angle_rad,
            b.geometry.half_cone_rad,
            b.geometry.flange_angle_rad,
            b.geometry.axis_angle_rad,
        );
        let fc = b.dynamics.centrifugal_force_n;
        let p1 = b.input.operating.axial_load_n / (g.roller_count as f64 * beta.sin());
        assert!((p1 / LBF_N / 320.23 - 1.0).abs() < 2e-5, "{}", p1 / LBF_N);
        let p2 = (p1 * (a + t).cos() - fc * (psi - a).cos()) / (a - t).cos();
        let p3q = (p1 * (2.0 * t).sin() + fc * (beta - 2.0 * t).sin()) / (a - t).cos();
        for (r, _, _) in &sol.rollers {
            assert_eq!(r.state, RollerState::BothRaces);
            assert!(
                (r.cup.load_n / p1 - 1.0).abs() < 1e-6,
                "{} {p1}",
                r.cup.load_n
            );
            assert!((r.cone.load_n / p2 - 1.0).abs() < 1e-6);
            assert!((r.flange_n / p3q - 1.0).abs() < 1e-6);
        }
        p3.push(sol.rollers[0].0.flange_n / LBF_N);
        cage.push(b.dynamics.cage_rad_s);
        // No radial displacement, no reaction moment (1e-9 of the scale).
        assert!(sol.displacement_m[0].abs() < 1e-9 * sol.displacement_m[2]);
        assert!(sol.reaction[3].abs() < 1e-9 * p1 * b.geometry.moment_radius_m);
    }
    assert!((p3[0] / 8.94 - 1.0).abs() < 6e-4, "{}", p3[0]);
    assert!((p3[2] / 26.49 - 1.0).abs() < 6e-4, "{}", p3[2]);
    let ratio = (p3[2] - p3[0]) / (p3[1] - p3[0]);
    assert!(
        (ratio / (cage[2] / cage[1]).powi(2) - 1.0).abs() < 1e-6,
        "{ratio}"
    );
}

/// Symmetry under pure thrust: all rollers equal (1e-9), K_xx = K_yy and K_θxθx = K_θyθy
/// (1e-9), no x–y, x–z, y–z coupling (1e-9 of K_zz), and K_xx/K_zz = cot²β/2 = 7.299
/// exactly in the analytic matrix (1e-9; 7.299 to its 4 digits).
#[test]
fn pure_thrust_stiffness_symmetry() {
    for rpm in [0.0, 20_000.0] {
        let (b, sol) = solve(&sample(rpm, 0.0));
        let p0 = sol.rollers[0].0.cup.load_n;
        for (r, _, _) in &sol.rollers {
            assert!((r.cup.load_n - p0).abs() < 1e-9 * p0);
        }
        let k = &sol.stiffness;
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(rel(k[(0, 0)], k[(1, 1)]) < 1e-9);
        assert!(rel(k[(3, 3)], k[(4, 4)]) < 1e-9);
        for (i, j) in [(0, 1), (1, 0), (0, 2), (2, 0), (1, 2), (2, 1)] {
            assert!(
                k[(i, j)].abs() < 1e-9 * k[(2, 2)],
                "K[{i}{j}] = {}",
                k[(i, j)]
            );
        }
        let beta = b.input.geometry.cup_angle_rad;
        let cot2 = 1.0 / beta.tan().powi(2) / 2.0;
        assert!(rel(k[(0, 0)] / k[(2, 2)], cot2) < 1e-9);
        assert!((cot2 - 7.299).abs() < 5e-4);
        assert!(k[(2, 2)] > 0.0 && k[(3, 3)] > 0.0);
    }
}

/// Analytic stiffness against central differences of re-solved roller equilibria: 1e-5 of
/// each scaled row's largest entry, at rest and at speed, pure thrust and Load
/// Condition 2 (700 lbf radial), with and without misalignment.
#[test]
fn analytic_stiffness_matches_finite_differences() {
    for (rpm, radial, mis) in [
        (0.0, 0.0, 0.0),
        (20_000.0, 0.0, 0.0),
        (0.0, 700.0, 0.0),
        (20_000.0, 700.0, 0.0),
        (20_000.0, 700.0, 2e-4),
    ] {
        let mut s = sample(rpm, radial);
        s.operating.misalignment_rad = [0.3 * mis, mis];
        let (b, sol) = solve(&s);
        let fd = b.stiffness_fd(&sol).unwrap();
        let diff = fd_difference(&sol.stiffness, &fd, b.geometry.moment_radius_m);
        assert!(
            diff < 1e-5,
            "{rpm} rpm {radial} lbf {mis}: {diff}\n{}\n{fd}",
            sol.stiffness
        );
    }
}

/// Load Condition 2 (700 lbf radial): the pure-thrust equalities break as they should
/// (far beyond the 1e-9 they hold to under pure thrust),
/// the equilibrium balances the loads (1e-9), and the asymmetry |K_ij − K_ji| stays a
/// small fraction (the seed's kinematics are not exactly variational).
#[test]
fn radial_load_breaks_the_symmetry() {
    let (b, sol) = solve(&sample(20_000.0, 700.0));
    let k = &sol.stiffness;
    // Measured: K_xx/K_yy − 1 = −6.0e-4 and K_xz/K_zz = 0.091 (zero under pure thrust).
    assert!((k[(0, 0)] / k[(1, 1)] - 1.0).abs() > 1e-4);
    assert!(k[(0, 2)].abs() > 1e-2 * k[(2, 2)]);
    let op = &b.input.operating;
    assert!((sol.reaction[0] - op.radial_load_n).abs() < 1e-9 * op.axial_load_n);
    assert!((sol.reaction[2] - op.axial_load_n).abs() < 1e-9 * op.axial_load_n);
    assert!(sol.reaction[1].abs() < 1e-9 * op.axial_load_n);
    let asym = asymmetry(k, b.geometry.moment_radius_m);
    assert!(asym < 0.05, "{asym}");
    // The loaded side carries more.
    assert!(sol.rollers[0].0.cup.load_n > sol.rollers[18].0.cup.load_n);
}

/// Typed errors: a non-positive thrust unseats; a radial load beyond F_a·cot β cannot be
/// carried; at 50 000 rpm the flanges carry more than the 3 000 lbf; a 0.002 in
/// effective length leaves Lundberg's validity (L/(2b) ≤ 0.25) and the error names the
/// roller.
#[test]
fn typed_errors() {
    let mut s = sample(0.0, 0.0);
    s.operating.axial_load_n = -100.0;
    assert!(matches!(
        Bearing::new(&s).unwrap().solve(),
        Err(BearingError::Unseated { .. })
    ));
    let s = sample(
        0.0,
        3000.0 / (14.0 + 40.0 / 60.0f64).to_radians().tan() * 1.01,
    );
    assert!(matches!(
        Bearing::new(&s).unwrap().solve(),
        Err(BearingError::RadialExceedsThrust { .. })
    ));
    let s = sample(50_000.0, 0.0);
    let e = Bearing::new(&s).unwrap().solve();
    assert!(
        matches!(e, Err(BearingError::FlangeThrustExceedsLoad { .. })),
        "{e:?}"
    );
    let mut s = sample(0.0, 0.0);
    s.geometry.effective_length_m = 0.002 * INCH_M;
    let e = Bearing::new(&s).unwrap().solve();
    match e {
        Err(BearingError::Roller {
            index,
            source: RollerError::Contact(c),
            ..
        }) => {
            assert!(index >= 1);
            assert!(matches!(
                c.source,
                crate::physics::contact::lundberg::LundbergError::BeyondValidity { .. }
            ));
            let msg = BearingError::Roller {
                index,
                azimuth_deg: 0.0,
                source: RollerError::Contact(c),
            }
            .to_string();
            assert!(msg.contains("roller") && msg.contains("0.25"), "{msg}");
        }
        other => panic!("{other:?}"),
    }
}

/// Symmetry is used: pure thrust solves one roller, a radial load along x the mirror
/// pairs (n = 37: 19 distinct).
#[test]
fn symmetric_rollers_are_solved_once() {
    let (_, sol) = solve(&sample(20_000.0, 0.0));
    assert_eq!(sol.unique_rollers, 1);
    let (_, sol) = solve(&sample(20_000.0, 700.0));
    assert_eq!(sol.unique_rollers, 19);
}

/// The load centre: referred to it, the pure-thrust lineal–angular coupling x–θy and
/// y–θx vanishes (1e-9 of the scale) and K_xx is unchanged; the offset lies within 1 % of
/// R_m/cos β, where the cup's contact normals cross the axis (the contact moments' share
/// of the angular stiffness moves it by 0.7 % for the sample).
#[test]
fn load_centre_removes_the_coupling() {
    let s = sample(20_000.0, 0.0);
    let a = crate::bearings::tapered_roller::analysis::analyse(&s, "t").unwrap();
    let off = a.load_centre_offset_m().unwrap();
    let kc = a.stiffness_at_load_centre().unwrap();
    let k = &a.stiffness;
    let rm = a.bearing.geometry.moment_radius_m;
    assert!(kc[(0, 4)].abs() < 1e-9 * k[(0, 4)].abs());
    assert!(kc[(1, 3)].abs() < 1e-9 * k[(1, 3)].abs());
    assert_eq!(kc[(0, 0)], k[(0, 0)]);
    let cb = s.geometry.cup_angle_rad.cos();
    assert!(
        (off / (rm / cb) - 1.0).abs() < 0.01,
        "{} vs {}",
        off / INCH_M,
        rm / cb / INCH_M
    );
}

/// Slice convergence: at 21 slices δz, K_xx, K_zz and K_θxθx lie within 1e-3 of their
/// 161-slice values (measured 6.0e-4, the moving grid converging as h²), under Load
/// Conditions 1 and 2 at 20 000 rpm.
#[test]
fn twenty_one_slices_within_1e3_of_161() {
    for radial in [0.0, 700.0] {
        let at = |n: usize| {
            let mut s = sample(20_000.0, radial);
            s.solver.slices = n;
            let (_, sol) = solve(&s);
            let k = sol.stiffness;
            [sol.displacement_m[2], k[(0, 0)], k[(2, 2)], k[(3, 3)]]
        };
        let (a, b) = (at(21), at(161));
        for i in 0..4 {
            assert!(
                (a[i] / b[i] - 1.0).abs() < 1e-3,
                "{radial} lbf, item {i}: {} vs {}",
                a[i],
                b[i]
            );
        }
    }
}

/// A 0–50 000 rpm sweep under Load Conditions 1 and 2: the stiffness falls smoothly
/// and monotonically with speed (every step down, K_xx concave in speed), no NaN, and
/// where no
/// equilibrium exists (the flanges' centrifugal thrust leaves too little for the loads:
/// above ≈ 39 000 rpm with 700 lbf radial, ≈ 41 200 rpm with pure thrust) a typed error,
/// never a panic. Pure thrust just below 41 200 rpm keeps every roller on the cone with
/// P₂ → 0 (the switch point).
#[test]
fn speed_sweep_is_smooth_and_ends_in_a_typed_error() {
    for radial in [0.0, 700.0] {
        let mut kxx = Vec::new();
        let mut failed_from = None;
        for i in 0..=50 {
            let rpm = 1000.0 * i as f64;
            match Bearing::new(&sample(rpm, radial)).unwrap().solve() {
                Ok(sol) => {
                    assert!(failed_from.is_none(), "{radial}: solved again at {rpm} rpm");
                    let k = sol.stiffness;
                    assert!(k.iter().all(|v| v.is_finite()));
                    kxx.push(k[(0, 0)]);
                }
                Err(e) => {
                    assert!(
                        matches!(
                            e,
                            BearingError::FlangeThrustExceedsLoad { .. }
                                | BearingError::RadialExceedsThrust { .. }
                        ),
                        "{radial} lbf at {rpm} rpm: {e}"
                    );
                    failed_from.get_or_insert(rpm);
                }
            }
        }
        let last = failed_from.unwrap_or(f64::INFINITY);
        if radial == 0.0 {
            assert_eq!(last, 42_000.0);
        } else {
            assert!((38_000.0..=41_000.0).contains(&last), "{last}");
        }
        for w in kxx.windows(2) {
            assert!(w[1] < w[0]);
        }
        // Smooth: K_xx is concave in speed all the way (each 1 000 rpm step falls
        // further than the one before; slice noise would break this at once, as the
        // fixed grid did).
        for w in kxx.windows(3) {
            assert!(w[2] - 2.0 * w[1] + w[0] < 0.0, "{radial}: {w:?}");
        }
    }
    // Just below the switch: every roller on the cone, P₂ small.
    let (b, sol) = solve(&sample(41_100.0, 0.0));
    let r = &sol.rollers[0].0;
    assert_eq!(r.state, RollerState::BothRaces);
    assert!(r.cone.load_n < 0.01 * r.cup.load_n, "{}", r.cone.load_n);
    assert!(b.dynamics.centrifugal_force_n > 0.0);
}

/// The random property: analytic stiffness against re-solved differences over random
/// bearings. Shared by the fixed-seed run (CI) and the ignored random-seed exploration.
mod property {
    use super::*;
    use crate::bearings::tapered_roller::contact::ContactEval;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
    use std::cell::RefCell;

    prop_compose! {
        fn case()(
            n in 12usize..40,
            d_in in 0.2f64..0.5,
            e_ratio in 10.0f64..25.0,
            beta_deg in 10.0f64..25.0,
            le_ratio in 1.5f64..2.5,
            crown_in in 20.0f64..200.0,
            fa_lbf in 500.0f64..5000.0,
            fr_frac in 0.0f64..0.6,
            rpm in 0.0f64..20_000.0,
            mis in -3e-4f64..3e-4,
        ) -> TaperedInput {
            let mut s = TaperedInput::afapl_sample();
            let g = &mut s.geometry;
            g.roller_count = n;
            g.roller_diameter_m = d_in * INCH_M;
            g.pitch_diameter_m = e_ratio * d_in * INCH_M;
            g.cup_angle_rad = beta_deg.to_radians();
            g.effective_length_m = le_ratio * d_in * INCH_M;
            g.crown = crate::bearings::tapered_roller::input::Crown::Radius(crown_in * INCH_M);
            // Fully crowned: with a flat and misalignment, a contact whose end sits at the
            // flat/crown junction has a kink in its extent (the line's root −Δ/tan θ takes
            // over from the crown's, eq. 54) where differences are no derivative. Flats are
            // covered by the contact's own derivative test away from the junction.
            g.flat_length_m = 0.0;
            g.small_end_break_m = 0.05 * d_in * INCH_M;
            g.big_end_break_m = 0.1 * d_in * INCH_M;
            let op = &mut s.operating;
            op.axial_load_n = fa_lbf * LBF_N;
            op.radial_load_n = fr_frac * fa_lbf * LBF_N / beta_deg.to_radians().tan();
            op.inner_speed_rad_s = rpm * RPM_RAD_S;
            op.misalignment_rad = [0.0, mis];
            s
        }
    }

    /// Where a roller's reactions have a kink: its state (both races, cup and flange,
    /// free: eqs. 121–130 take over when the cone lets go), and per contact (cup, cone)
    /// whether it touches and whether its small/big end is held at the end of the
    /// effective length (eqs. 52–53: the end's ∂X/∂Δ drops to zero there, and with it the
    /// contact length's share ∂p/∂L·∂L/∂Δ of every slice's stiffness: the stiffness
    /// jumps). Between two points with equal signatures every roller's reactions are
    /// smooth (the flat/crown junction, eq. 54, is the one other kink; the property's
    /// rollers are fully crowned).
    type Signature = (RollerState, [bool; 3], [bool; 3]);

    fn signature(b: &Bearing, r: &RollerSolution) -> Signature {
        let half_le = 0.5 * b.input.geometry.effective_length_m;
        let v = b.geometry.crown_drop_m;
        let ends = |e: &ContactEval, theta: f64| {
            // The limits of eqs. 52–53 at the contact's misalignment; an end clamped
            // there equals it to round-off of half the effective length.
            let (s, c) = theta.sin_cos();
            let (lo, hi) = (-half_le * c + v * s, half_le * c + v * s);
            let on = e.load_n > 0.0;
            let at = |x: f64, lim: f64| on && (x - lim).abs() <= 1e-12 * half_le;
            [on, at(e.extent_m[0], lo), at(e.extent_m[1], hi)]
        };
        (
            r.state,
            ends(&r.cup, r.theta1_rad),
            ends(&r.cone, r.theta2_rad),
        )
    }

    /// Differences of re-solved reactions about `sol` with the step h of
    /// [`Bearing::stiffness_fd`] (1e-5 of the largest roller approach, rotations h/R_m).
    struct Differences {
        /// Richardson's extrapolation (4·D(h/2) − D(h))/3 of the central differences D:
        /// their h² truncation cancels, the remainder is O(h⁴).
        richardson: Matrix5,
        /// The plain central difference D(h) (reported: its h² error is what failed).
        central: Matrix5,
        /// Rollers whose [`Signature`] at x ± h differs from the base point's: a kink
        /// inside the step (the half steps lie between), where no difference is a
        /// derivative.
        kinks: Vec<String>,
    }

    fn differences(b: &Bearing, sol: &BearingSolution) -> Result<Differences, BearingError> {
        let dmax = sol.rollers.iter().map(|r| r.1.abs()).fold(1e-9, f64::max);
        let h = 1e-5 * dmax;
        let rm = b.geometry.moment_radius_m;
        let x0 = [
            sol.displacement_m[0],
            sol.displacement_m[1],
            sol.displacement_m[2],
            sol.rotation_rad[0],
            sol.rotation_rad[1],
        ];
        let base: Vec<Signature> = sol.rollers.iter().map(|r| signature(b, &r.0)).collect();
        let mut d = [Matrix5::zeros(), Matrix5::zeros()];
        let mut kinks = Vec::new();
        for j in 0..5 {
            let hj = if j < 3 { h } else { h / rm };
            for (m, step) in [hj, 0.5 * hj].into_iter().enumerate() {
                let (mut xp, mut xm) = (x0, x0);
                xp[j] += step;
                xm[j] -= step;
                let sp = b.state(&xp, Some(&sol.rollers))?;
                let sn = b.state(&xm, Some(&sol.rollers))?;
                if m == 0 {
                    for (side, st) in [("+", &sp), ("−", &sn)] {
                        for (q, r) in st.rollers.iter().enumerate() {
                            let now = signature(b, &r.0);
                            if now != base[q] {
                                kinks.push(format!(
                                    "column {j} {side}h: roller {} {:?} → {now:?}",
                                    q + 1,
                                    base[q]
                                ));
                            }
                        }
                    }
                }
                for i in 0..5 {
                    d[m][(i, j)] = (sp.reaction[i] - sn.reaction[i]) / (2.0 * step);
                }
            }
        }
        Ok(Differences {
            richardson: (d[1] * 4.0 - d[0]) / 3.0,
            central: d[0],
            kinks,
        })
    }

    /// What a run saw (printed with `--nocapture`).
    #[derive(Default)]
    struct Tally {
        solved: usize,
        typed_errors: usize,
        skipped: Vec<String>,
        largest: f64,
        largest_central: f64,
    }

    fn check(s: &TaperedInput, tally: &RefCell<Tally>) -> Result<(), TestCaseError> {
        let b = Bearing::new(s).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let sol = match b.solve() {
            Ok(sol) => sol,
            Err(e) => {
                tally.borrow_mut().typed_errors += 1;
                let msg = e.to_string();
                prop_assert!(!msg.contains("NaN"), "{msg}");
                return Ok(());
            }
        };
        prop_assert!(sol.stiffness.iter().all(|v| v.is_finite()));
        let op = &s.operating;
        prop_assert!((sol.reaction[2] - op.axial_load_n).abs() < 1e-8 * op.axial_load_n);
        prop_assert!((sol.reaction[0] - op.radial_load_n).abs() < 1e-8 * op.axial_load_n);
        let d = differences(&b, &sol).map_err(|e| TestCaseError::fail(e.to_string()))?;
        if let Some(first) = d.kinks.first() {
            tally.borrow_mut().skipped.push(first.clone());
            return Err(TestCaseError::reject(format!(
                "a kink inside the difference step: {first}"
            )));
        }
        let rm = b.geometry.moment_radius_m;
        let gap = fd_difference(&sol.stiffness, &d.richardson, rm);
        let central = fd_difference(&sol.stiffness, &d.central, rm);
        {
            let mut t = tally.borrow_mut();
            t.solved += 1;
            t.largest = t.largest.max(gap);
            t.largest_central = t.largest_central.max(central);
        }
        prop_assert!(gap < 1e-5, "gap {gap} (plain central difference {central})");
        Ok(())
    }

    /// The CI run's seed: a fixed one, so that a run on a fresh machine draws the same
    /// cases as the one that was measured (proptest's default seed is random).
    const SEED: u64 = 0x7a9e_5eed;

    /// `cases` cases from `seed`; `PROPTEST_CASES` and `PROPTEST_RNG_SEED` override them
    /// (to scale a run up or replay a seed). At most 1 in 50 cases (8 at least) may be
    /// skipped for a kink (measured: 14 in 21 374 solved cases, 1 in 1 500): a detector
    /// firing more often than that would be hollowing the property out, and the run
    /// aborts.
    fn config(cases: u32, seed: RngSeed) -> Config {
        let env = Config::default();
        let cases = if std::env::var_os("PROPTEST_CASES").is_some() {
            env.cases
        } else {
            cases
        };
        Config {
            cases,
            rng_seed: match env.rng_seed {
                RngSeed::Fixed(_) => env.rng_seed,
                RngSeed::Random => seed,
            },
            max_global_rejects: (cases / 50).max(8),
            source_file: Some(file!()),
            ..env
        }
    }

    fn run(config: Config) {
        let tally = RefCell::new(Tally::default());
        let seed = config.rng_seed;
        let cases = config.cases;
        let mut runner = TestRunner::new(config);
        let result = runner.run(&case(), |s| check(&s, &tally));
        let t = tally.borrow();
        println!(
            "seed {seed}, {cases} cases: {} solved, {} typed errors, {} skipped for a kink inside the step; largest gap {:.2e} (Richardson), {:.2e} (plain central difference)",
            t.solved,
            t.typed_errors,
            t.skipped.len(),
            t.largest,
            t.largest_central
        );
        for k in &t.skipped {
            println!("  skipped: {k}");
        }
        if let Err(e) = result {
            panic!("{e}");
        }
    }

    /// Over random geometry, load, speed and misalignment: a converged equilibrium
    /// (forces balanced to 1e-8 of the thrust, everything finite) whose analytic
    /// stiffness matches re-solved differences to 1e-5 of each row's scale, or a typed
    /// error; never NaN, never a panic.
    ///
    /// The differences: Richardson's extrapolation of central differences at h and h/2
    /// (h = 1e-5 of the largest roller approach). Its error is the O(h⁴) remainder plus
    /// the rollers' convergence noise (their tolerance, 1e-12 of the force scale, over a
    /// step of 1e-5: ~1e-7 at most); 1e-5 is far above both and far below any modelling
    /// error of the derivatives (leaving out the contact length's term of Lundberg's
    /// logarithm alone gives ~1e-2). A case whose step straddles a kink (a roller
    /// changing state, a contact end reaching or leaving the end of the effective length:
    /// see [`Signature`]) is skipped and counted: there the stiffness itself jumps and no
    /// difference is a derivative.
    ///
    /// Why: the plain central difference D(h) this test used failed about one run in 50.
    /// Over 12 000 cases (seeds 1–4 × 3 000, instrumented) it exceeded 1e-5 in 9 of the
    /// 10 652 solved ones: 7 a contact end crossing the end of the effective length
    /// inside ±h (off by 4e-5 to 1.6e-3), 1 a roller leaving the cone inside ±h (3.4e-5),
    /// 1 smooth but truncation-bound (1.17e-5: a cone contact at 1.1e-5 of its cup load;
    /// the error ∝ h², 1.2e-7 at h/10). The analytic stiffness was never at fault: at
    /// h/10 every case without a kink inside the step matched to 1.2e-7. (The 1 348
    /// typed errors: 793 the flanges' centrifugal thrust exceeding a light thrust at
    /// speed, 551 the radial load beyond what the thrust carries, 4 the ring Newton not
    /// converging within 60 iterations near that radial limit at speed.)
    ///
    /// Measured with this test (`PROPTEST_CASES=3000`, `PROPTEST_RNG_SEED` 1–4): 12 000
    /// cases, 10 722 solved, 1 278 typed errors, 6 skipped (all a contact end at the end
    /// of the effective length); largest gap 3.2e-8 (the plain central difference of the
    /// same cases: up to 7.6e-5).
    ///
    /// Deterministic: the seed is fixed ([`SEED`]). To explore, run the ignored
    /// `analytic_matches_differences_random_seeds` (a fresh seed each run, printed), or
    /// this one with `PROPTEST_RNG_SEED=<u64>` and/or `PROPTEST_CASES=<n>`; each prints
    /// its tally with `--nocapture`.
    #[test]
    fn analytic_matches_differences_or_typed_error() {
        run(config(24, RngSeed::Fixed(SEED)));
    }

    /// The same property from a fresh random seed each run, 2 000 cases (about 10 s):
    /// `cargo test --lib tapered_roller::bearing::tests::property -- --ignored --nocapture`.
    /// The seed is printed (replay it with `PROPTEST_RNG_SEED`); a failure prints the
    /// shrunk case and persists it under `proptest-regressions/`.
    #[test]
    #[ignore = "random exploration; the fixed-seed run is analytic_matches_differences_or_typed_error"]
    fn analytic_matches_differences_random_seeds() {
        use std::hash::{BuildHasher, Hasher};
        // A per-process random number (std's hasher keys are drawn from the OS).
        let seed = std::collections::hash_map::RandomState::new()
            .build_hasher()
            .finish();
        run(config(2_000, RngSeed::Fixed(seed)));
    }

    /// The kink detector is not hollow. Pure thrust with 2e-4 rad misalignment at rest,
    /// fully crowned rollers: raising the thrust, the rollers' contacts grow until one
    /// reaches an end of the effective length. At that thrust (bisected to 1e-13) the
    /// difference step straddles the change and the detector names it; one grid step
    /// (×1.25) below, it sees nothing.
    #[test]
    fn kink_detector_sees_a_contact_end_reach_the_roller_end() {
        let at = |fa_lbf: f64| {
            let mut s = sample(0.0, 0.0);
            s.geometry.crown =
                crate::bearings::tapered_roller::input::Crown::Radius(100.0 * INCH_M);
            s.geometry.flat_length_m = 0.0;
            s.operating.axial_load_n = fa_lbf * LBF_N;
            s.operating.misalignment_rad = [0.0, 2e-4];
            let (b, sol) = solve(&s);
            let sig: Vec<Signature> = sol.rollers.iter().map(|r| signature(&b, &r.0)).collect();
            (b, sol, sig)
        };
        let mut lo = 200.0;
        let first = at(lo).2;
        let mut hi = lo;
        while at(hi).2 == first {
            lo = hi;
            hi *= 1.25;
            assert!(
                hi < 30_000.0,
                "no contact reached a roller end below 30 000 lbf"
            );
        }
        let below = lo;
        let below_sig = at(below).2;
        while hi - lo > 1e-13 * hi {
            let mid = 0.5 * (lo + hi);
            if at(mid).2 == below_sig {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let (b, sol, _) = at(hi);
        let d = differences(&b, &sol).unwrap();
        assert!(!d.kinks.is_empty(), "at {hi} lbf");
        let (b, sol, _) = at(below);
        let d = differences(&b, &sol).unwrap();
        assert!(d.kinks.is_empty(), "at {below} lbf: {:?}", d.kinks);
        let gap = fd_difference(&sol.stiffness, &d.richardson, b.geometry.moment_radius_m);
        assert!(gap < 1e-5, "{gap}");
    }
}
/// A warm start from a neighbouring solution (the previous point of a speed sweep) gives
/// the same equilibrium as a cold start (1e-9 of the thrust in the reactions, 1e-6 of
/// K_xx: both are converged to the tolerance) in fewer ring iterations.
#[test]
fn warm_started_sweep_matches_cold_solves() {
    let mut prev: Option<BearingSolution> = None;
    let (mut warm_its, mut cold_its) = (0, 0);
    for i in 0..=10 {
        let s = sample(2_000.0 * i as f64, 700.0);
        let b = Bearing::new(&s).unwrap();
        let cold = b.solve().unwrap();
        let warm = b.solve_from(prev.as_ref()).unwrap();
        let fa = s.operating.axial_load_n;
        for j in 0..3 {
            assert!((warm.reaction[j] - cold.reaction[j]).abs() < 1e-9 * fa);
        }
        assert!((warm.stiffness[(0, 0)] / cold.stiffness[(0, 0)] - 1.0).abs() < 1e-6);
        warm_its += warm.iterations;
        cold_its += cold.iterations;
        prev = Some(warm);
    }
    assert!(warm_its <= cold_its, "{warm_its} vs {cold_its}");
}

/// Number of rollers off the cone and the stiffness at `rpm` under Load Condition 2.
fn lc2_at(rpm: f64) -> (usize, Matrix5) {
    let (_, sol) = solve(&sample(rpm, 700.0));
    let n = sol
        .rollers
        .iter()
        .filter(|r| r.0.state == RollerState::CupAndFlange)
        .count();
    (n, sol.stiffness)
}

/// Branch switch of single rollers (Load Condition 2, 700 lbf radial): the mirror pair
/// nearest φ = 180° leaves the cone at ≈ 38 900 rpm (found by bisection on the state,
/// to round-off of the speed) and switches to the cup-and-flange state (eqs. 121–130),
/// reported as such. The stiffness is continuous there: a roller's P₂ → 0 at the switch
/// and its cone contact's stiffness with it, so the jump between ω_s(1 − h) and
/// ω_s(1 + h) must shrink with h. Measured: 1.4e-2 at h = 1e-4, 3.7e-3 at 1e-5, 1.1e-3 at
/// 1e-6, 3.3e-4 at 1e-7 of the largest entry (∝ h^½: the contact stiffness vanishes as
/// a power of P₂, P₂ linear in the speed offset). Tolerances: each decade of h at least
/// halves the jump, and at h = 1e-7 it is below 1e-3 (a discontinuity would stay put).
#[test]
fn stiffness_is_continuous_where_a_roller_leaves_the_cone() {
    let (mut lo, mut hi) = (38_000.0, 39_800.0);
    assert_eq!(lc2_at(lo).0, 0);
    assert!(lc2_at(hi).0 > 0);
    while hi - lo > 1e-9 * hi {
        let mid = 0.5 * (lo + hi);
        if lc2_at(mid).0 == 0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    assert!((38_800.0..39_000.0).contains(&lo), "{lo}");
    // The first to leave: the mirror pair opposite the radial load, in the JSON name.
    let (_, sol) = solve(&sample(hi, 700.0));
    let off: Vec<usize> = (0..sol.rollers.len())
        .filter(|&q| sol.rollers[q].0.state == RollerState::CupAndFlange)
        .collect();
    assert_eq!(off, vec![18, 19]);
    assert_eq!(sol.rollers[18].0.state.as_str(), "cup-and-flange");
    let mut last = f64::INFINITY;
    for h in [1e-4, 1e-5, 1e-6, 1e-7] {
        let (na, a) = lc2_at(lo * (1.0 - h));
        let (nb, b) = lc2_at(hi * (1.0 + h));
        assert_eq!((na, nb), (0, 2), "h = {h}");
        let jump = (a - b).abs().max() / a.abs().max();
        assert!(jump < 0.5 * last, "h = {h}: {jump} after {last}");
        last = jump;
    }
    assert!(last < 1e-3, "{last}");
}

/// Why pure thrust has no equilibrium above ≈ 41 200 rpm (Load Condition 1), the proof
/// in numbers. Eliminating P₃ from a roller's force balances (55)–(56) (or (121)–(122)
/// with P₂ = 0) gives, whatever the moments,
///
/// P₁·cos(α + τ/2) = P₂·cos(α − τ/2) + F_c·cos(ψ − α)  ⇒  P₁ ≥ P₁,cf = F_c·cos(ψ − α)/cos(α + τ/2)
///
/// for every roller with P₂ ≥ 0 (a roller touching neither race cannot balance F_c > 0,
/// the model has no cage force). The cup's axial balance is Σ P₁·sin β = F_a. So an
/// equilibrium needs n·P₁,cf·sin β ≤ F_a; F_c ∝ ω² gives the critical speed in closed
/// form, ω* = ω₀·√(F_a/(n·P₁,cf(ω₀)·sin β)) = 41 18x rpm. Checked: the solver's P₁ of
/// the cup-and-flange state is P₁,cf (1e-9), every roller of LC1 and LC2 solutions obeys
/// P₁ ≥ P₁,cf (1e-9), the equilibrium exists at ω*(1 − 1e-4) with every roller still on
/// the cone and P₂ < 1 % of P₁, and at ω*(1 + 1e-4) the solve is the typed error whose
/// thrust exceeds F_a by the ratio (1 + 1e-4)² (1e-9).
#[test]
fn no_equilibrium_above_the_flange_thrust_speed_proof_in_numbers() {
    let s0 = sample(20_000.0, 0.0);
    let b0 = Bearing::new(&s0).unwrap();
    let g = &s0.geometry;
    let (beta, t, a, psi) = (
        g.cup_angle_rad,
        b0.geometry.half_cone_rad,
        b0.geometry.flange_angle_rad,
        b0.geometry.axis_angle_rad,
    );
    let p1cf = |fc: f64| fc * (psi - a).cos() / (a + t).cos();
    let n = g.roller_count as f64;
    let fa = s0.operating.axial_load_n;
    let thrust0 = n * p1cf(b0.dynamics.centrifugal_force_n) * beta.sin();
    let rpm_star = 20_000.0 * (fa / thrust0).sqrt();
    assert!((41_100.0..41_300.0).contains(&rpm_star), "{rpm_star}");
    // The cup-and-flange roller (eqs. 121–130, ring out of reach) carries P₁,cf.
    let free = b0.model.solve(-1.0, 0.0, None).unwrap();
    assert_eq!(free.state, RollerState::CupAndFlange);
    assert!((free.cup.load_n / p1cf(b0.dynamics.centrifugal_force_n) - 1.0).abs() < 1e-9);
    // The bound holds roller by roller in solved cases, both load conditions.
    for (rpm, radial) in [(20_000.0, 0.0), (39_500.0, 700.0), (30_000.0, 700.0)] {
        let (b, sol) = solve(&sample(rpm, radial));
        let lower = p1cf(b.dynamics.centrifugal_force_n);
        for (r, _, _) in &sol.rollers {
            assert!(r.cup.load_n >= lower * (1.0 - 1e-9), "{rpm} {radial}");
        }
    }
    let (_, below) = solve(&sample(rpm_star * (1.0 - 1e-4), 0.0));
    let r = &below.rollers[0].0;
    assert_eq!(r.state, RollerState::BothRaces);
    assert!(r.cone.load_n < 0.01 * r.cup.load_n);
    match Bearing::new(&sample(rpm_star * (1.0 + 1e-4), 0.0))
        .unwrap()
        .solve()
    {
        Err(BearingError::FlangeThrustExceedsLoad {
            axial_load_n,
            flange_thrust_n,
            limit_inner_speed_rpm,
        }) => {
            // The error names the limit: the cone speed where the thrusts are equal.
            assert!((limit_inner_speed_rpm / rpm_star - 1.0).abs() < 1e-9);
            let ratio = flange_thrust_n / axial_load_n;
            assert!(
                (ratio / (1.0 + 1e-4f64).powi(2) - 1.0).abs() < 1e-9,
                "{ratio}"
            );
        }
        other => panic!("{other:?}"),
    }
}

/// Issue 24 item 11: the sample at tiny cone speeds. Before, the cup-and-flange roller
/// (its loads F_c ∝ speed², 8.6e-11 N at 0.01 rpm) was asked for a tolerance of 3.6e-10 N
/// set by the bearing's load and ran out of iterations at scattered speeds between
/// 0.0085 and 0.029 rpm (0.0078 rpm was refused with a residual below its tolerance).
/// Now 200 log-spaced speeds over 1e-4–1 rpm, 0 and the speeds all converge, the
/// ring residual within its tolerance (force_tolerance × F_a, the stated one) and the
/// cup-and-flange roller's within its own (the roller tolerance, floored).
#[test]
fn tiny_speeds_converge_within_the_stated_tolerance() {
    let mut speeds: Vec<f64> = (0..200)
        .map(|i| 1e-4 * 10f64.powf(4.0 * i as f64 / 199.0))
        .collect();
    speeds.extend([0.0, 0.0078, 0.0085, 0.01, 0.029, 0.05]);
    for rpm in speeds {
        let s = sample(rpm, 0.0);
        let b = Bearing::new(&s).unwrap_or_else(|e| panic!("{rpm}: {e}"));
        let sol = b.solve().unwrap_or_else(|e| panic!("{rpm} rpm: {e}"));
        let tol = s.solver.force_tolerance * s.operating.axial_load_n;
        assert!(sol.residual_n <= tol, "{rpm}: {} > {tol}", sol.residual_n);
        if let Ok(cf) = b.model.solve(-1.0, 0.0, None) {
            if cf.state == RollerState::CupAndFlange {
                assert!(cf.residual_n <= b.model.force_floor_n.max(1e-12 * b.model.force_scale));
            }
        }
    }
}

/// Issue 24 item 11: a token thrust (1e-6 lbf at rest) stalled the ring Newton with its
/// residual equal to the load (tolerance 4.4e-15 N). It is refused, naming the smallest
/// thrust solved (every roller at an approach of 1e-10 of its diameter): 0.0182 N
/// (4.1e-3 lbf) on the sample (pinned to 10 %: the floor is an order of magnitude by
/// construction, the test keeps it from drifting unseen). Just above it
/// (×1.05) and at 0.01 lbf the equilibrium converges within its tolerance.
#[test]
fn token_thrust_is_refused_with_the_minimum_load() {
    let mut s = sample(0.0, 0.0);
    s.operating.axial_load_n = 1e-6 * LBF_N;
    let b = Bearing::new(&s).unwrap();
    let min = match b.solve() {
        Err(e @ BearingError::BelowMinimumLoad { minimum_n, .. }) => {
            let m = e.to_string();
            assert!(
                m.contains("raise operating.axial_load") && !m.contains('{'),
                "{m}"
            );
            minimum_n
        }
        other => panic!("{other:?}"),
    };
    assert!((min / 0.0182 - 1.0).abs() < 0.1, "{min}");
    for fa in [1.05 * min, 0.01 * LBF_N] {
        s.operating.axial_load_n = fa;
        let sol = Bearing::new(&s)
            .unwrap()
            .solve()
            .unwrap_or_else(|e| panic!("{fa}: {e}"));
        assert!(sol.residual_n <= 1e-9 * fa, "{fa}: {}", sol.residual_n);
    }
}

/// Issue 24 item 15: a cup angle of 1e-15 rad put the cone apex 6e13 m away; the
/// roller's mass and inertia, differences of two cones, came out with a negative inertia
/// and the roller's balance ended in NaN ("tolerance NaN N"). The geometry is refused,
/// naming the key, with no NaN in the words.
#[test]
fn nearly_cylindrical_roller_is_refused() {
    let mut s = sample(20_000.0, 0.0);
    s.geometry.cup_angle_rad = 1e-15;
    s.solver.slices = 3;
    match Bearing::new(&s) {
        Err(e @ BearingError::Geometry(_)) => {
            let m = e.to_string();
            assert!(
                m.contains("geometry.cup_angle") && !m.contains("NaN"),
                "{m}"
            );
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
    // The shipped angle is far from the limit.
    assert!(Bearing::new(&sample(20_000.0, 0.0)).is_ok());
}

/// Issue 24 item 15: no Rust debug text in a failure ("NotConverged { iterations: 60,
/// … }"): the way Newton stopped is said in words with the forces in N.
#[test]
fn non_convergence_is_worded() {
    let e = BearingError::NotConverged {
        termination: Termination::Stalled {
            iterations: 1,
            residual: 4.4e-6,
        },
        tolerance_n: 4.4e-15,
    };
    let m = e.to_string();
    assert!(!m.contains('{') && !m.contains("Stalled"), "{m}");
    assert!(m.contains("4.400e-6 N") && m.contains("4.400e-15 N"), "{m}");
    let r = RollerError::NotConverged {
        state: "cup-and-flange",
        termination: Termination::NotConverged {
            iterations: 60,
            residual: 4.26e-10,
            tolerance: 3.617e-10,
        },
        tolerance: 3.617e-10,
        delta_m: 0.0,
        theta_rad: 0.0,
    };
    let m = r.to_string();
    assert!(
        !m.contains('{') && m.contains("after 60 iterations") && m.contains("4.260e-10 N"),
        "{m}"
    );
}

/// Issue 29 session 12: the 1-D solve on θy over held-tilt solves (the moment solve's
/// fallback, `Bearing::solve_tilt_1d`) reaches the same equilibrium as the four-unknown
/// Newton wherever both converge: the 32007 deck (crowned and logarithmic) at 267.2, 150,
/// 120 and 100 N·m, started from θy = 0. Tilts agree to 1e-9 rad (each meets the moment
/// tolerance 1e-9·F_r·R_m ≈ 2e-7 N·m; over K_c ≥ 2e3 N·m/rad that is 1e-10 rad), the
/// displacements to 1e-9 of the axial one; the 1-D answer balances F_x, F_z (10× the
/// bearing tolerance, the held solve's acceptance) and M_y (the tolerance at R_m). Fails
/// if the bracket, the condensed K_c or the held solve's warm start were wrong (no
/// convergence, or a different root).
#[test]
fn tilt_1d_solve_matches_the_four_unknown_newton() {
    use crate::bearings::tapered_roller::deck::SCHEMA;
    use crate::deck::form::Form;
    for log in [false, true] {
        for m in [267.2, 150.0, 120.0, 100.0] {
            let deck = include_str!("../../../../decks/trb_32007.toml").replacen(
                "moment = 267.2",
                &format!("moment = {m:?}"),
                1,
            );
            let mut input: TaperedInput = Form::parse(&deck, "trb_32007.toml", &SCHEMA)
                .unwrap_or_else(|e| panic!("{e}"))
                .value;
            if log {
                input.geometry.profile = super::super::input::RollerProfile::Logarithmic;
            }
            let b = Bearing::new(&input).unwrap();
            let newton = b.solve().unwrap();
            let op = &input.operating;
            let tol = input.solver.force_tolerance * op.axial_load_n.max(op.radial_load_n);
            let z0 = Vector3::new(0.0, 0.0, newton.displacement_m[2]);
            let one_d = b.solve_tilt_1d(None, z0, 0.0, m, tol, None).unwrap();
            let rm = b.geometry.moment_radius_m;
            let (t_n, t_1) = (newton.rotation_rad[1], one_d.rotation_rad[1]);
            assert!(
                (t_n - t_1).abs() <= 1e-9,
                "log {log} {m}: θy {t_n} vs {t_1}"
            );
            for i in 0..3 {
                let d = (newton.displacement_m[i] - one_d.displacement_m[i]).abs();
                assert!(
                    d <= 1e-9 * newton.displacement_m[2].abs(),
                    "log {log} {m}: δ{i} {d}"
                );
            }
            assert!((one_d.reaction[0] - op.radial_load_n).abs() <= 10.0 * tol);
            assert!((one_d.reaction[2] - op.axial_load_n).abs() <= 10.0 * tol);
            assert!((one_d.reaction[4] - m).abs() / rm <= tol, "log {log} {m}");
            eprintln!(
                "log {log} {m} N·m: θy {t_1:.6e} rad (Newton {t_n:.6e}), 1-D inner iterations {}",
                one_d.iterations
            );
        }
    }
}
