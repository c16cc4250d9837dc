//! Tests of the load distribution: the hot loop against its matrix form and finite
//! differences, the starts, published distributions, balances and degenerate cases.

use nalgebra::Vector3;

use super::problem::Problem;
use super::*;
use crate::bearings::spherical_roller::roller::roller_mass;
use crate::bearings::spherical_roller::Bearing;

// The Stribeck bearing and NASA/TM-2012-217115's table live with the validation report.
use crate::verify::cases::{stribeck_bearing, STRIBECK_TABLE};

fn run(b: &Bearing) -> LoadDistribution {
    let s = DynamicSpeeds::app_c_estimate(b);
    match solve(b, &s, &SolveOptions::default(), None) {
        Ok(r) => r,
        Err(e) => panic!("solve failed: {e}"),
    }
}

#[test]
fn scalar_evaluation_equals_the_matrix_form() {
    // The hot loop against the term-by-term matrix form, over roller states that put
    // every lamina in, out of and at the edge of contact at both raceways, with and
    // without ring deflection and pitch. Tolerance 1e-12 of each block's largest entry:
    // the same arithmetic reordered.
    for b in [Bearing::example_aerospace(), stribeck_bearing(12)] {
        let p = Problem::new(
            &b,
            &DynamicSpeeds::app_c_estimate(&b),
            b.solver.force_tolerance,
        );
        let d = b.geometry.roller_diameter_m;
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut loaded = 0;
        for _ in 0..200 {
            let q = Vector3::new(2e-4 * d * rnd(), 2e-3 * d * rnd(), 2e-3 * rnd());
            let u = [1e-3 * d * rnd(), 1e-3 * d * rnd()];
            let cphi = rnd();
            let a = p.eval(cphi, u, &q, true);
            let r = p.eval_reference(cphi, u, &q, true);
            let close = |x: &[f64], y: &[f64], what: &str| {
                let scale = y.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
                for (xi, yi) in x.iter().zip(y) {
                    assert!((xi - yi).abs() <= 1e-12 * scale, "{what}: {xi} vs {yi}");
                }
            };
            close(&[a.energy], &[r.energy], "energy");
            close(a.g_q.as_slice(), r.g_q.as_slice(), "g_q");
            close(a.h_qq.as_slice(), r.h_qq.as_slice(), "h_qq");
            close(a.g_u.as_slice(), r.g_u.as_slice(), "g_u");
            close(a.h_uq.as_slice(), r.h_uq.as_slice(), "h_uq");
            close(a.h_uu.as_slice(), r.h_uu.as_slice(), "h_uu");
            loaded += usize::from(r.g_u.norm() > 0.0);
        }
        // The states exercise the contact terms, not just the cage spring.
        assert!(
            loaded > 50,
            "only {loaded} of 200 states touch the inner raceway"
        );
    }
}

#[test]
fn lamina_angles_are_the_design_angle_at_rest() {
    // At rest with no load and no clearance the mid lamina's normals are the nominal
    // contact normal: both angles equal the design contact angle β (round-off, 1e-12 deg),
    // and the outer and inner normals are the same line.
    let (b, ld) = solved_at_rest();
    let mid = &ld.rollers[0].laminae[b.solver.laminae / 2];
    let beta = b.geometry.contact_angle_rad.to_degrees();
    assert!(
        (mid.inner_angle_deg() - beta).abs() < 1e-12,
        "{}",
        mid.inner_angle_deg()
    );
    assert!(
        (mid.outer_angle_deg() - beta).abs() < 1e-12,
        "{}",
        mid.outer_angle_deg()
    );
}

#[test]
fn cold_start_is_exact_for_conforming_rollers() {
    // Conforming crowns (roller = raceway crown, the Stribeck bearing) put every lamina at
    // the same approach (times cos θ_l, the tilt of each lamina's crown normal, which the
    // estimate includes), where the rigid-roller estimate is the model itself: its ring
    // deflection equals the solved one to the e²d²/R³ remainder (~1e-6, see
    // stribeck_distribution): 1e-5.
    for z in [8, 13, 20] {
        let b = stribeck_bearing(z);
        let p = Problem::new(
            &b,
            &DynamicSpeeds::app_c_estimate(&b),
            b.solver.force_tolerance,
        );
        let (u, _) = p.cold_start(&b);
        let r = run(&b);
        assert!(
            (u[1] / r.radial_deflection_m - 1.0).abs() < 1e-5,
            "Z={z}: {} vs {}",
            u[1],
            r.radial_deflection_m
        );
    }
}

#[test]
fn straight_rollers_converge_in_the_first_sweep() {
    // Straight rollers (the issue-7 comparison case): the estimate, solved to the force
    // tolerance, is exact to the solver's tolerance, so the first roller sweep meets the
    // ring tolerance and no ring Newton step is taken. Fails if the estimate stops early
    // (it used to stop at 1e-6 of the load, which cost a ring step and a sweep), or if it
    // stops being exact for straight rollers.
    for laminae in [5, 21, 61] {
        let deck = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/radial_si.toml");
        let mut b = crate::bearings::spherical_roller::deck::load(deck)
            .expect("shipped deck")
            .value;
        crate::verify::cases::make_cylindrical_radial(&mut b, laminae);
        let r = run(&b);
        assert_eq!(r.stats.iterations, 0, "Γ = {laminae}");
        assert!(r.residuals.bearing_radial_n <= 1e-9 * b.operating.radial_load_n);
    }
}

#[test]
fn cold_start_saves_work_and_changes_nothing() {
    // Against the old start at zero (a zero warm start), on the shipped aerospace bearing
    // and a thrust-loaded one: fewer lamina evaluations, the same equilibrium to 1e-7
    // of the larger deflection (both stop at the 1e-9 force tolerance).
    let mut thrust = Bearing::example_aerospace();
    thrust.operating.radial_load_n = 0.0;
    for b in [Bearing::example_aerospace(), thrust] {
        let s = DynamicSpeeds::app_c_estimate(&b);
        let n = b.geometry.roller_count / 2 + 1;
        let zero = SolveOptions {
            warm_start: Some(WarmStart {
                ring: [0.0; 2],
                rollers: vec![[0.0; 3]; n],
                guide_offset_m: 0.0,
                inertial: None,
            }),
            ..SolveOptions::default()
        };
        let a = solve(&b, &s, &SolveOptions::default(), None).expect("estimate start");
        let z = solve(&b, &s, &zero, None).expect("zero start");
        assert!(
            a.stats.lamina_evaluations < z.stats.lamina_evaluations,
            "{} vs {}",
            a.stats.lamina_evaluations,
            z.stats.lamina_evaluations
        );
        let scale = z.axial_deflection_m.abs().max(z.radial_deflection_m.abs());
        for (x, y) in [
            (a.axial_deflection_m, z.axial_deflection_m),
            (a.radial_deflection_m, z.radial_deflection_m),
        ] {
            assert!((x - y).abs() <= 1e-7 * scale, "{x} vs {y}");
        }
    }
}

#[test]
fn inertial_prediction_lands_near_the_new_equilibrium() {
    // Solve the aerospace bearing, then raise the cage speed by 1 % (CF +2 %, the
    // gyroscopic moment with it). Warm-started with the inertial sensitivities, the new
    // solve starts within second order of its equilibrium: it needs fewer lamina
    // evaluations than the same warm start without them, and both reach the cold answer
    // (ring deflection to 1e-7 relative: both stop at the 1e-9 force tolerance).
    let b = Bearing::example_aerospace();
    let s0 = DynamicSpeeds::app_c_estimate(&b);
    let first = solve(&b, &s0, &SolveOptions::default(), None).expect("first solve");
    let s1 = DynamicSpeeds {
        cage_rad_s: 1.01 * s0.cage_rad_s,
        ..s0
    };
    let with = SolveOptions {
        warm_start: Some(first.warm.clone()),
        ..SolveOptions::default()
    };
    let mut plain_warm = first.warm.clone();
    plain_warm.inertial = None;
    let without = SolveOptions {
        warm_start: Some(plain_warm),
        ..SolveOptions::default()
    };
    let a = solve(&b, &s1, &with, None).expect("predicted");
    let c = solve(&b, &s1, &without, None).expect("warm");
    let cold = solve(&b, &s1, &SolveOptions::default(), None).expect("cold");
    assert!(
        a.stats.lamina_evaluations < c.stats.lamina_evaluations,
        "{} vs {}",
        a.stats.lamina_evaluations,
        c.stats.lamina_evaluations
    );
    for r in [&a, &c] {
        for (x, y) in [
            (r.axial_deflection_m, cold.axial_deflection_m),
            (r.radial_deflection_m, cold.radial_deflection_m),
        ] {
            assert!((x - y).abs() <= 1e-7 * y.abs(), "{x} vs {y}");
        }
    }
}

#[test]
fn stribeck_distribution() {
    // NASA/TM-2012-217115 Table I (exponent 10/9), roller at ψ = 0.
    for (z, st) in STRIBECK_TABLE {
        let b = stribeck_bearing(z);
        let r = run(&b);
        let q: Vec<f64> = r.rollers.iter().map(|x| x.inner.normal_load_n).collect();
        let qmax = q[0];
        // Discrete sum with the 10/9 law: F_r = Q_max Σ cos^(19/9) φ_j over cos φ_j > 0.
        let sum: f64 = (0..z)
            .map(|j| (2.0 * std::f64::consts::PI * j as f64 / z as f64).cos())
            .filter(|c| *c > 0.0)
            .map(|c| c.powf(19.0 / 9.0))
            .sum();
        let exact = z as f64 / sum;
        let got = z as f64 * qmax / b.operating.radial_load_n;
        // The exact geometry's approach of an off-centre lamina is e·h/R + O(e²d²/R³), so the
        // roller law is e^(10/9) to ~1e-6 relative (not exactly): 1e-5 tolerance.
        assert!(
            (got / exact - 1.0).abs() < 1e-5,
            "Z={z}: {got} vs exact {exact}"
        );
        // Published table: 4 digits (0.2 % band, references.md).
        assert!((got / st - 1.0).abs() < 2e-3, "Z={z}: {got} vs table {st}");
        // Each roller follows Q_max cos^(10/9) φ (1e-5 relative, same reason).
        for (j, qj) in q.iter().enumerate() {
            let c = (2.0 * std::f64::consts::PI * j as f64 / z as f64).cos();
            let expect = if c > 0.0 {
                qmax * c.powf(10.0 / 9.0)
            } else {
                0.0
            };
            assert!(
                (qj - expect).abs() < 1e-5 * qmax,
                "Z={z} j={j}: {qj} vs {expect}"
            );
        }
    }
}

#[test]
fn pure_axial_zero_speed() {
    let mut b = Bearing::example_aerospace();
    b.operating.inner_speed_rad_s = 0.0;
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 5_000.0;
    let r = run(&b);
    let q0 = r.rollers[0].inner.normal_load_n;
    let mut fa = 0.0;
    for x in &r.rollers {
        // All rollers equal: symmetric problem, 1e-9 relative.
        assert!((x.inner.normal_load_n / q0 - 1.0).abs() < 1e-9);
        fa += x
            .laminae
            .iter()
            .map(|l| l.inner_load_n * l.inner_angle_deg().to_radians().sin())
            .sum::<f64>();
    }
    // Axial components sum to F_a (equilibrium to the solver tolerance, 1e-8).
    assert!((fa / 5_000.0 - 1.0).abs() < 1e-8, "{fa}");
    // Q ≈ F_a/(Z sin β): the operating angle differs from β by the deflection only (1 %).
    let beta = b.geometry.contact_angle_rad;
    let expect = 5_000.0 / (16.0 * beta.sin());
    assert!((q0 / expect - 1.0).abs() < 0.01, "{q0} vs {expect}");
}

#[test]
fn speed_loads_outer_raceway() {
    let b = Bearing::example_aerospace();
    let r = run(&b);
    let cf = r.rollers[0].centrifugal_force_n;
    assert!(cf > 100.0, "CF {cf}");
    for x in &r.rollers {
        if x.inner.loaded_laminae == 0 {
            continue;
        }
        // Radial balance along r: Q_o cos β_o − Q_i cos β_i = CF (the pitch moment and
        // the cage spring change this only through the small cage reaction: 1e-3·CF).
        let fo: f64 = x
            .laminae
            .iter()
            .map(|l| l.outer_load_n * l.outer_angle_deg().to_radians().cos())
            .sum();
        let fi: f64 = x
            .laminae
            .iter()
            .map(|l| l.inner_load_n * l.inner_angle_deg().to_radians().cos())
            .sum();
        // The cage force acts along the roller axis a = (cos β, −sin β).
        let cage_r = -x.cage_force_n * b.geometry.contact_angle_rad.sin();
        assert!(
            (fo - fi - cf - cage_r).abs() < 1e-6 * cf.max(fo),
            "roller {}: {fo} {fi} {cf}",
            x.index
        );
        assert!(x.outer.normal_load_n > x.inner.normal_load_n);
        // The cage carries a negligible share of a two-sided roller (default ratio 1e-7:
        // below 1e-3 of the roller load).
        assert!(
            x.cage_force_n.abs() < 1e-3 * x.inner.normal_load_n,
            "cage {} vs {}",
            x.cage_force_n,
            x.inner.normal_load_n
        );
    }
}

#[test]
fn gyroscopic_moment_balanced_by_lamina_loads() {
    // The raceways' lamina forces supply the precession moment M = Ω_cg e_x × H (App. D):
    // Σ (p × F)_t + cage moment = −(−M) at each roller, to the solver tolerance.
    let b = Bearing::example_aerospace();
    let r = run(&b);
    let gm = r.rollers[0].gyroscopic_moment_nm;
    assert!(gm.abs() > 1e-3, "gm {gm}");
    for x in &r.rollers {
        let c = [
            x.axial_displacement_m,
            x.radial_displacement_m + 0.5 * b.geometry.pitch_diameter_m,
        ];
        let mut m = 0.0;
        for l in &x.laminae {
            for (pt, q, ang) in [
                (l.inner_point_m, l.inner_load_n, l.inner_angle_deg()),
                (l.outer_point_m, -l.outer_load_n, l.outer_angle_deg()),
            ] {
                let a = ang.to_radians();
                let f = [q * a.sin(), q * a.cos()];
                let p = [pt[0] - c[0], pt[1] - c[1]];
                m += p[0] * f[1] - p[1] * f[0];
            }
        }
        let err = m + x.cage_moment_nm - gm;
        assert!(
            err.abs() < 1e-6 * (gm.abs() + 1.0),
            "roller {}: {m} + {} vs {gm}",
            x.index,
            x.cage_moment_nm
        );
    }
}

#[test]
fn gyroscopic_moment_matches_eq_d1() {
    // Eq. D.1 with the polar moment on the spin term: GM = [I_p(ω_s + Ω cos β) − I_t Ω cos β] Ω sin β,
    // and our vector form gives −GM about e_t (sign of the frame); round-off tolerance.
    let b = Bearing::example_aerospace();
    let m = roller_mass(&b.geometry, b.materials.roller.density_kg_m3);
    let s = DynamicSpeeds::app_c_estimate(&b);
    let beta = b.geometry.contact_angle_rad;
    let d1 = (m.polar_inertia_kg_m2 * (s.roller_spin_rad_s + s.cage_rad_s * beta.cos())
        - m.transverse_inertia_kg_m2 * s.cage_rad_s * beta.cos())
        * s.cage_rad_s
        * beta.sin();
    let v = gyroscopic_moment(&m, &s, beta);
    assert!((v + d1).abs() < 1e-12 * d1.abs(), "{v} vs {d1}");
}

#[test]
fn analytic_derivatives_match_finite_differences() {
    // Central differences with h = 1e-9 m (1e-7 rad): truncation ~h², round-off ~1e-16/h;
    // 1e-5 relative to the largest entry is a safe band for both.
    let mut b = Bearing::example_aerospace();
    b.geometry.diametral_clearance_m = -2e-5; // preload: all laminae loaded
    let p = Problem::new(
        &b,
        &DynamicSpeeds::app_c_estimate(&b),
        b.solver.force_tolerance,
    );
    let u = [1e-6, 2e-6];
    let q = Vector3::new(1e-6, -5e-7, 2e-4);
    let cphi = 0.7;
    let ev = p.eval(cphi, u, &q, true);
    let hs = [1e-9, 1e-9, 1e-7];
    for k in 0..3 {
        let mut qp = q;
        let mut qm = q;
        qp[k] += hs[k];
        qm[k] -= hs[k];
        let (ep, em) = (p.eval(cphi, u, &qp, true), p.eval(cphi, u, &qm, true));
        let fd_g = (ep.energy - em.energy) / (2.0 * hs[k]);
        assert!(
            (fd_g - ev.g_q[k]).abs() < 1e-5 * ev.g_q.amax().max(1.0),
            "g_q[{k}] {fd_g} vs {}",
            ev.g_q[k]
        );
        for i in 0..3 {
            let fd = (ep.g_q[i] - em.g_q[i]) / (2.0 * hs[k]);
            assert!(
                (fd - ev.h_qq[(i, k)]).abs() < 1e-5 * ev.h_qq.amax(),
                "h_qq[{i},{k}] {fd} vs {}",
                ev.h_qq[(i, k)]
            );
        }
        for i in 0..2 {
            let fd = (ep.g_u[i] - em.g_u[i]) / (2.0 * hs[k]);
            assert!(
                (fd - ev.h_uq[(i, k)]).abs() < 1e-5 * ev.h_uq.amax(),
                "h_uq[{i},{k}] {fd} vs {}",
                ev.h_uq[(i, k)]
            );
        }
    }
    for k in 0..2 {
        let mut up = u;
        let mut um = u;
        up[k] += 1e-9;
        um[k] -= 1e-9;
        let (ep, em) = (p.eval(cphi, up, &q, true), p.eval(cphi, um, &q, true));
        let fd_g = (ep.energy - em.energy) / 2e-9;
        assert!((fd_g - ev.g_u[k]).abs() < 1e-5 * ev.g_u.amax(), "g_u[{k}]");
        for i in 0..2 {
            let fd = (ep.g_u[i] - em.g_u[i]) / 2e-9;
            assert!(
                (fd - ev.h_uu[(i, k)]).abs() < 1e-5 * ev.h_uu.amax(),
                "h_uu[{i},{k}] {fd} vs {}",
                ev.h_uu[(i, k)]
            );
        }
    }
}

#[test]
fn degenerate_cases_do_not_fail() {
    let base = Bearing::example_aerospace();
    let mut cases = Vec::new();
    let mut b = base.clone();
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 0.0;
    cases.push(("zero load at speed", b.clone()));
    b.operating.inner_speed_rad_s = 0.0;
    cases.push(("zero load, zero speed", b.clone()));
    let mut b = base.clone();
    b.operating.axial_load_n = 0.0;
    b.geometry.diametral_clearance_m = 1e-4;
    cases.push(("pure radial, big clearance", b.clone()));
    let mut b = base.clone();
    b.geometry.diametral_clearance_m = -3e-5;
    cases.push(("preload", b.clone()));
    let mut b = base.clone();
    b.operating.outer_speed_rad_s = -b.operating.inner_speed_rad_s;
    cases.push(("counter-rotating", b.clone()));
    let mut b = base.clone();
    b.operating.inner_speed_rad_s *= 3.0;
    b.operating.radial_load_n *= 0.05;
    cases.push(("3.3 MDN light load", b));
    for (name, b) in cases {
        let s = DynamicSpeeds::app_c_estimate(&b);
        let r = match solve(&b, &s, &SolveOptions::default(), None) {
            Ok(r) => r,
            // Pure radial load on this angular-contact bearing has no axial restraint:
            // the typed diagnostic is the right answer there, never NaN or a panic.
            Err(SolveError::Stage { message, .. }) if message.contains("axial load or preload") => {
                continue
            }
            Err(e) => panic!("{name}: {e}"),
        };
        let json = serde_json::to_string(&r).unwrap_or_default();
        assert!(!json.contains("NaN") && !json.contains("null"), "{name}");
        assert!(r.residuals.bearing_radial_n.is_finite(), "{name}");
    }
}

#[test]
fn mirrored_rollers_equal() {
    let r = run(&Bearing::example_aerospace());
    let z = r.rollers.len();
    for j in 1..z {
        let (a, b) = (&r.rollers[j], &r.rollers[z - j]);
        assert_eq!(a.inner.normal_load_n, b.inner.normal_load_n);
        assert_eq!(a.outer.normal_load_n, b.outer.normal_load_n);
    }
}

mod restraint_tests {
    use super::*;

    #[test]
    fn pure_radial_on_angular_contact_is_diagnosed() {
        // β = 12°, spherical outer raceway, F_a = 0: nothing holds the inner ring axially, so
        // it walks off by several roller diameters (seen: ~18 mm for D = 12.7 mm). The solver
        // must say so with its numbers, not return that geometry as an answer.
        let mut b = Bearing::example_aerospace();
        b.operating.axial_load_n = 0.0;
        let s = DynamicSpeeds::app_c_estimate(&b);
        match solve(&b, &s, &SolveOptions::default(), None) {
            Err(SolveError::Stage { message, .. }) => {
                assert!(message.contains("axial load or preload"), "{message}");
            }
            other => panic!("expected the restraint diagnostic, got {other:?}"),
        }
        // With F_a/F_r near 1.5·tan β (0.32, ISO 281's e) the same bearing solves near its
        // design geometry (below that the rings shift axially, the contact angle drops until
        // the load ratio matches it, and beyond D/2 of shift the diagnostic above applies).
        b.operating.axial_load_n = 0.3 * b.operating.radial_load_n;
        let r = solve(&b, &s, &SolveOptions::default(), None);
        assert!(r.is_ok_and(|r| r.axial_deflection_m.abs() < 0.5 * b.geometry.roller_diameter_m));
    }
}
