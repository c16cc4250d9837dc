//! Issue 29, the ball's degrees of freedom: a pure radial load (`operating.axial_load =
//! 0`), the 0° deep-groove geometry, a bearing with no load at all; the tilt held or
//! solved against `operating.moment`.

use super::analysis::analyse;
use super::geometry::BallGeometry;
use super::input::{rpm, BallInput, PreloadMode};
use super::load_conditions::{axial_condition, conditions};
use super::load_distribution::{Conditions, LoadDistribution};
use super::warnings::warnings;
use crate::numerics::cancel::Cancel;
use crate::physics::contact::point::Race;

/// Ball loads of a pure radial load on a bearing with diametral play P_d, at rest, as
/// Harris & Kotzalas, *Rolling Bearing Analysis* (5th ed., vol. 1, §7.2, eqs. 7.5–7.6)
/// write them: Q_j = K_n (δ_r cos ψ_j − P_d/2)^{3/2} where positive, K_n the two contacts
/// in series at α = 0, (K_i^{−2/3} + K_o^{−2/3})^{−3/2}. An independent closed form: the
/// solver's ring Newton over a torus groove knows nothing of it.
fn harris_radial_loads(geom: &BallGeometry, radial_deflection_m: f64) -> Vec<f64> {
    let ki = geom
        .contact(Race::Inner, 0.0)
        .unwrap()
        .stiffness_n_per_m1_5();
    let ko = geom
        .contact(Race::Outer, 0.0)
        .unwrap()
        .stiffness_n_per_m1_5();
    let kn = (ki.powf(-2.0 / 3.0) + ko.powf(-2.0 / 3.0)).powf(-1.5);
    let z = geom.ball_count;
    (0..z)
        .map(|j| {
            let psi = 2.0 * std::f64::consts::PI * j as f64 / z as f64;
            let d = radial_deflection_m * psi.cos() - 0.5 * geom.diametral_clearance_m;
            kn * d.max(0.0).powf(1.5)
        })
        .collect()
}

/// A pure radial load, force-held F_a = 0, at rest, on Bearing A (15° play): the ring
/// centres itself axially (δ_a = −A sin α₀, the grooves facing each other: by the
/// symmetry of the torus about that plane the axial forces vanish there), every loaded
/// contact sits at α = 0, the balls opposite the load are free, and the loads are
/// Harris's closed form for the solved δ_r to 1e-9 (round-off of the Newton's 1e-10·F
/// force tolerance propagated through Q ∝ δ^{3/2}); ΣQ cos ψ = F_r to 1e-9.
#[test]
fn pure_radial_load_at_rest_is_harris_closed_form() {
    let mut i = BallInput::chen_a();
    i.operating.axial_load_n = 0.0;
    i.operating.preload_mode = PreloadMode::Force;
    i.operating.radial_load_n = 3_000.0;
    i.operating.inner_speed_rad_s = 0.0;
    let a = analyse(&i, Cancel::NONE).unwrap();
    let g = &a.geometry;
    let l = &a.load;
    let expect_axial = -g.centre_distance_m * g.free_contact_angle_rad.sin();
    assert!(
        (l.axial_deflection_m - expect_axial).abs() < 1e-12 * g.centre_distance_m,
        "{} vs {expect_axial}",
        l.axial_deflection_m
    );
    assert!((l.radial_force_n - 3_000.0).abs() < 1e-9 * 3_000.0);
    let q = harris_radial_loads(g, l.radial_deflection_m);
    let qmax = q.iter().cloned().fold(0.0, f64::max);
    let mut sum = 0.0;
    for (b, qh) in l.balls.iter().zip(&q) {
        let e = &b.equilibrium;
        assert!(
            (e.inner.load_n - qh).abs() < 1e-9 * qmax,
            "ψ = {:.1}°: {} vs Harris {qh}",
            b.azimuth_rad.to_degrees(),
            e.inner.load_n
        );
        if e.inner.load_n > 0.0 {
            assert!(e.inner.angle_rad.abs() < 1e-9, "{}", e.inner.angle_rad);
        }
        sum += e.inner.load_n * b.azimuth_rad.cos();
    }
    assert!((sum - 3_000.0).abs() < 1e-9 * 3_000.0, "{sum}");
    // Some balls opposite the load carry nothing (the play is open there).
    assert!(l.balls.iter().any(|b| b.equilibrium.inner.load_n == 0.0));
}

/// The 0° deep-groove geometry (α₀ = 0, no play), F_a = 0 held as a force or as the
/// displacement it gives (0), pure radial load at rest: δ_a = 0, Harris's closed form
/// with P_d = 0 to 1e-9, and both holdings agree to 1e-9 (the force-held ring finds
/// δ_a = 0 by symmetry; the displacement-held one is put there).
#[test]
fn deep_groove_zero_angle_pure_radial() {
    let mut i = BallInput::chen_a();
    i.geometry.free_contact_angle_rad = 0.0;
    i.operating.axial_load_n = 0.0;
    i.operating.radial_load_n = 2_000.0;
    i.operating.inner_speed_rad_s = 0.0;
    let mut answers = Vec::new();
    for mode in [PreloadMode::Force, PreloadMode::Displacement] {
        i.operating.preload_mode = mode;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let l = &a.load;
        assert!(
            l.axial_deflection_m.abs() < 1e-15,
            "{}",
            l.axial_deflection_m
        );
        let q = harris_radial_loads(&a.geometry, l.radial_deflection_m);
        let qmax = q.iter().cloned().fold(0.0, f64::max);
        for (b, qh) in l.balls.iter().zip(&q) {
            assert!((b.equilibrium.inner.load_n - qh).abs() < 1e-9 * qmax);
        }
        answers.push(l.radial_deflection_m);
    }
    assert!(
        (answers[0] - answers[1]).abs() < 1e-9 * answers[0],
        "{answers:?}"
    );
}

/// Pure radial load at speed on Bearing B (60° play, 9 500 rpm), F_a = 0 held as a force:
/// the run succeeds, the ring carries no axial force (1e-9 of F_r: the friction of 2-7
/// has axial components, the ring's axial place balances them), the radial force is F_r
/// to 1e-9, the balls opposite the load ride the outer race alone (their inner contact
/// open, the torus's far side not touching: `ContactLoad::new`), and the skid search did
/// not fail.
#[test]
fn pure_radial_load_at_speed_solves() {
    let mut i = BallInput::chen_b();
    i.operating.axial_load_n = 0.0;
    i.operating.preload_mode = PreloadMode::Force;
    i.operating.radial_load_n = 2_000.0;
    let a = analyse(&i, Cancel::NONE).unwrap();
    let l = &a.load;
    assert!(
        l.axial_force_n.abs() < 1e-9 * 2_000.0,
        "{}",
        l.axial_force_n
    );
    assert!((l.radial_force_n - 2_000.0).abs() < 1e-9 * 2_000.0);
    let opposite = &l.balls[l.balls.len() / 2].equilibrium;
    assert_eq!(opposite.inner.load_n, 0.0);
    assert!(opposite.outer.load_n > 0.0);
    assert!(!a.skid.search_failed, "{:?}", a.skid.reason);
}

/// No load at all: nothing fixes the ring's axial place; it is held (force-held: centred
/// in the play, δ_a = −A sin α₀, every inner contact open at speed; displacement-held:
/// δ_a = 0) and a warning says so. At rest with nothing held every ball is loose.
#[test]
fn no_load_is_held_and_said() {
    for (mode, speed) in [
        (PreloadMode::Force, rpm(9_500.0)),
        (PreloadMode::Force, 0.0),
        (PreloadMode::Displacement, 0.0),
    ] {
        let mut i = BallInput::chen_b();
        i.operating.axial_load_n = 0.0;
        i.operating.preload_mode = mode;
        i.operating.inner_speed_rad_s = speed;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let g = &a.geometry;
        let held = match mode {
            PreloadMode::Force => -g.centre_distance_m * g.free_contact_angle_rad.sin(),
            PreloadMode::Displacement => 0.0,
        };
        assert_eq!(a.load.axial_deflection_m, held);
        for b in &a.load.balls {
            assert_eq!(b.equilibrium.inner.load_n, 0.0, "{mode:?} {speed}");
        }
        let w = warnings(&a);
        assert!(
            w.iter()
                .any(|w| w.si.starts_with("no load:") && w.si.contains("operating.axial_load = 0")),
            "{w:?}"
        );
    }
}

/// The load-solve conditions of `i` as the analysis builds them.
fn conditions_of(i: &BallInput) -> (BallGeometry, Conditions) {
    let g = BallGeometry::new(i).unwrap();
    let (axial, _) = axial_condition(i, &g, Cancel::NONE).unwrap();
    (g, conditions(i, axial, 1.0))
}

/// Σ_j (P_a,j ℜ_i − f_i D µ_j Q_i,j) cos ψ_j over every ball, recomputed from the balls'
/// own ring forces and loads (Jones–Harris's ring moment with the friction couple,
/// Harris & Kotzalas vol. 2 §3.3): the moment the balls carry, N·m.
fn ball_moment(g: &BallGeometry, l: &LoadDistribution, friction: &[f64]) -> f64 {
    let ri = g.outer_centre_radius_m + g.centre_distance_m * g.free_contact_angle_rad.cos();
    let fd = g.inner_offset_m + 0.5 * g.ball_diameter_m;
    l.balls
        .iter()
        .zip(friction)
        .map(|(b, mu)| {
            let e = &b.equilibrium;
            (e.ring_force[0] * ri - fd * mu * e.inner.load_n) * b.azimuth_rad.cos()
        })
        .sum()
}

/// Pure moment on the 0° deep-groove geometry (α₀ = 0, no play) at rest, the ring held
/// axially where the balls just touch: an analytic check. Each inner groove centre sits
/// at (u, A) from the outer one with u = θℜ_i cos ψ; the ball lies on the line of
/// centres with the approach √(A² + u²) − A shared by both contacts in series,
/// Q = K_n(α)·approach^{3/2} at α = atan(u/A), K_n from the Hertz constants of both
/// contacts at α. The moment ℜ_i ΣQ sin α cos ψ of the solved tilt equals the applied
/// 40 N·m to 1e-8 (the ring Newton's force tolerance 1e-10 of the load scale, amplified
/// by the moment's quadratic onset in θ at 0° play), and the balls' moment recomputed
/// from their ring forces matches to 1e-9.
#[test]
fn pure_moment_on_zero_angle_bearing_is_hertz_sum() {
    let mut i = BallInput::chen_a();
    i.geometry.free_contact_angle_rad = 0.0;
    i.operating.axial_load_n = 0.0;
    i.operating.inner_speed_rad_s = 0.0;
    i.operating.moment_nm = Some(40.0);
    let a = analyse(&i, Cancel::NONE).unwrap();
    let g = &a.geometry;
    let l = &a.load;
    assert!(l.tilt_rad > 0.0, "{}", l.tilt_rad);
    let ri = g.outer_centre_radius_m + g.centre_distance_m;
    let big_a = g.centre_distance_m;
    let mut m = 0.0;
    for b in &l.balls {
        let u = l.tilt_rad * ri * b.azimuth_rad.cos();
        let alpha = u.atan2(big_a);
        let ki = g
            .contact(Race::Inner, alpha)
            .unwrap()
            .stiffness_n_per_m1_5();
        let ko = g
            .contact(Race::Outer, alpha)
            .unwrap()
            .stiffness_n_per_m1_5();
        let kn = (ki.powf(-2.0 / 3.0) + ko.powf(-2.0 / 3.0)).powf(-1.5);
        let q = kn * (big_a.hypot(u) - big_a).max(0.0).powf(1.5);
        m += q * alpha.sin() * ri * b.azimuth_rad.cos();
    }
    assert!((m - 40.0).abs() < 1e-8 * 40.0, "Hertz sum {m} N·m");
    assert!((l.moment_nm - 40.0).abs() < 1e-9 * 40.0, "{}", l.moment_nm);
    let zero = vec![0.0; l.balls.len()];
    assert!((ball_moment(g, l, &zero) - 40.0).abs() < 1e-9 * 40.0);
}

/// A held DOF released at the force it held (issue 29): Bearing A at 10 000 rpm under a
/// 2 000 N radial load and a 30 N·m moment solves a tilt θ; holding that θ gives back
/// the moment and every ball load to 1e-9, and the moment the balls carry (recomputed
/// from their ring forces with the friction couple) is the applied one to 1e-9.
#[test]
fn moment_and_tilt_round_trip() {
    let mut i = BallInput::chen_a();
    i.operating.radial_load_n = 2_000.0;
    i.operating.moment_nm = Some(30.0);
    let a = analyse(&i, Cancel::NONE).unwrap();
    assert!((a.load.moment_nm - 30.0).abs() < 1e-9 * 30.0);
    let (g, c) = conditions_of(&i);
    let friction: Vec<f64> = {
        // µ of 2-7 on each ball, as the fixed point ends with it.
        a.load
            .balls
            .iter()
            .map(|b| {
                let q = b.equilibrium.inner.load_n + b.equilibrium.outer.load_n;
                (2.0 * b.gyroscopic_moment_nm / (g.ball_diameter_m * q))
                    .clamp(-c.max_friction, c.max_friction)
            })
            .collect()
    };
    let m = ball_moment(&g, &a.load, &friction);
    assert!((m - 30.0).abs() < 1e-9 * 30.0, "{m}");
    let mut held = i.clone();
    held.operating.moment_nm = None;
    held.operating.misalignment_rad = a.load.tilt_rad;
    let h = analyse(&held, Cancel::NONE).unwrap();
    assert!(
        (h.load.moment_nm - 30.0).abs() < 1e-9 * 30.0,
        "{}",
        h.load.moment_nm
    );
    let qmax = a
        .load
        .balls
        .iter()
        .map(|b| b.equilibrium.inner.load_n)
        .fold(0.0, f64::max);
    for (x, y) in a.load.balls.iter().zip(&h.load.balls) {
        assert!((x.equilibrium.inner.load_n - y.equilibrium.inner.load_n).abs() < 1e-9 * qmax);
    }
    assert!(
        (a.load.radial_deflection_m - h.load.radial_deflection_m).abs()
            < 1e-9 * a.load.radial_deflection_m.abs()
    );
}

/// A moment and a held misalignment both given is refused naming both keys.
#[test]
fn moment_and_misalignment_both_refused() {
    let toml = std::fs::read_to_string("decks/chen_a.toml").unwrap();
    let toml = toml.replace(
        "[operating]",
        "[operating]\nmoment = 10.0\nmisalignment = 0.01",
    );
    let e = crate::deck::form::Form::parse(
        &toml,
        "chen_a.toml",
        &crate::bearings::angular_ball::deck::SCHEMA,
    )
    .err()
    .map(|e| format!("{e:?}"))
    .unwrap_or_default();
    assert!(
        e.contains("operating.moment") && e.contains("operating.misalignment"),
        "{e}"
    );
}

/// The friction split (issue 29): on Chen's Bearing A at 10 000 rpm (1 000 N preload
/// held as the rest displacement, outer race control, resisting friction) the
/// proportional split (Chen's 2-7, the default) gives Q_i = 173.6 N and the
/// controlling-race split (Harris's λ_o = 2, λ_i = 0, as OpenJones) 189.3 N: the two
/// numbers measured side by side with OpenJones in Octave (shared guide, "Ball
/// bearings: cross-checks found and measured"). Within 0.1 % (the guide quotes four
/// digits).
#[test]
fn friction_split_moves_bearing_a_as_measured() {
    use super::input::FrictionSplit;
    for (split, expect) in [
        (FrictionSplit::Proportional, 173.6),
        (FrictionSplit::ControllingRace, 189.3),
    ] {
        let mut i = BallInput::chen_a();
        i.kinematics.friction_split = split;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let qi = a.load.balls[0].equilibrium.inner.load_n;
        assert!(
            (qi - expect).abs() < 1e-3 * expect,
            "{split:?}: Q_i = {qi} N, expected {expect} N"
        );
    }
}

mod stiffness {
    use super::*;
    use crate::bearings::angular_ball::load_distribution;
    use crate::bearings::angular_ball::stiffness::{stiffness, StiffnessMethod};
    use proptest::prelude::*;

    /// Under an axial load alone the bearing is axisymmetric: K_xx = K_yy and
    /// K_θxθx = K_θyθy (Σcos²ψ = Σsin²ψ = Z/2 for Z ≥ 3) to 1e-9, and no x–y coupling
    /// (1e-9 of K_xx: round-off of the sums over ψ). Bearing A at 10 000 rpm.
    #[test]
    fn pure_axial_load_is_axisymmetric() {
        let i = BallInput::chen_a();
        let (g, c) = conditions_of(&i);
        let l = load_distribution::solve(&g, &c, Cancel::NONE).unwrap();
        let k = stiffness(&g, &l, StiffnessMethod::Analytic).unwrap().matrix;
        assert!(k[(0, 0)] > 0.0 && k[(2, 2)] > 0.0 && k[(3, 3)] > 0.0, "{k}");
        assert!((k[(0, 0)] - k[(1, 1)]).abs() < 1e-9 * k[(0, 0)], "{k}");
        assert!((k[(3, 3)] - k[(4, 4)]).abs() < 1e-9 * k[(3, 3)], "{k}");
        assert!(k[(0, 1)].abs() < 1e-9 * k[(0, 0)], "{k}");
        assert!(k[(1, 0)].abs() < 1e-9 * k[(0, 0)], "{k}");
    }

    /// On the shared type (issue 29 item 3) the JSON `stiffness` keeps every key the ball
    /// wrote (`matrix`, `rows`, `columns`, `units`, `method`, `reference_point`, `held`,
    /// and with "both" `finite_difference_matrix`, `finite_difference_max_rel`), with the
    /// ball's own matrix in it bit for bit, and the text block is the shared printer's.
    #[test]
    fn shared_type_keeps_the_ball_json() {
        let mut i = BallInput::chen_b();
        i.solver.stiffness = StiffnessMethod::Both;
        let a = analyse(&i, Cancel::NONE).unwrap();
        let j = crate::bearings::angular_ball::report::json(&a);
        let k = &j["stiffness"];
        for key in [
            "matrix",
            "rows",
            "columns",
            "units",
            "method",
            "reference_point",
            "held",
            "finite_difference_matrix",
            "finite_difference_max_rel",
        ] {
            assert!(k.get(key).is_some(), "{key} missing: {k}");
        }
        assert_eq!(
            k["rows"],
            serde_json::json!(["F_x", "F_y", "F_z", "M_x", "M_y"])
        );
        assert_eq!(
            k["columns"],
            serde_json::json!(["x", "y", "z", "theta_x", "theta_y"])
        );
        assert_eq!(k["method"], "both");
        assert_eq!(k["units"][0][3], "N/rad");
        for r in 0..5 {
            for c in 0..5 {
                assert_eq!(k["matrix"][r][c].as_f64(), Some(a.stiffness.matrix[(r, c)]));
            }
        }
        assert!(k["finite_difference_max_rel"].as_f64().unwrap() < 1e-6);
        let lines =
            crate::bearings::angular_ball::report::stiffness_lines(&a, crate::units::Units::Si);
        assert_eq!(
            lines[0],
            "Stiffness matrix (rows F_x F_y F_z M_x M_y; columns x y z θx θy)"
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 4, ..ProptestConfig::default() })]
        /// The analytic matrix (the ring Newton's Jacobian with the balls condensed)
        /// equals central differences of the re-solved ball equilibria to 1e-6 of each
        /// row's scale (central differences with 1e-9 m steps on ~1e-5 m deflections
        /// leave ~1e-8; the ball solves' 1e-13 tolerance ~1e-8), over random radial
        /// loads, moments and speeds on Bearing A.
        #[test]
        fn analytic_stiffness_is_the_finite_difference(
            radial in 0.0f64..3_000.0,
            moment in -20.0f64..20.0,
            speed in 0.0f64..15_000.0,
        ) {
            let mut i = BallInput::chen_a();
            i.operating.radial_load_n = radial;
            i.operating.moment_nm = Some(moment);
            i.operating.inner_speed_rad_s = rpm(speed);
            let (g, c) = conditions_of(&i);
            let l = load_distribution::solve(&g, &c, Cancel::NONE).unwrap();
            let k = stiffness(&g, &l, StiffnessMethod::Both).unwrap();
            let d = k.finite_difference_max_rel.unwrap();
            prop_assert!(d < 1e-6, "{d}: {}", k.matrix);
        }
    }
}

/// One holding per DOF (issue 29): `operating.moment` and `operating.misalignment` both
/// written, even a misalignment of exactly 0 (the value rule cannot see it), are refused
/// at the later key, naming both keys and both lines, once.
#[test]
fn moment_and_written_zero_misalignment_refused_with_lines() {
    let toml = std::fs::read_to_string("decks/chen_a.toml").unwrap();
    let line = |text: &str, key: &str| {
        1 + text
            .lines()
            .position(|l| l.starts_with(key))
            .unwrap_or_else(|| panic!("{key}"))
    };
    for mis in ["0.0", "0.01"] {
        let t = toml.replace(
            "[operating]",
            &format!("[operating]\nmoment = 10.0\nmisalignment = {mis}"),
        );
        let (lm, la) = (line(&t, "moment ="), line(&t, "misalignment ="));
        let e = crate::deck::form::Form::parse(
            &t,
            "chen_a.toml",
            &crate::bearings::angular_ball::deck::SCHEMA,
        )
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
        assert!(
            e.contains(&format!("operating.moment at line {lm}"))
                && e.contains(&format!("operating.misalignment at line {la}")),
            "{mis}: {e}"
        );
        assert_eq!(e.matches("operating.moment").count(), 1, "{e}");
    }
}
