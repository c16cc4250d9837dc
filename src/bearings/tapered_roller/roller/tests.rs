//! Tests of one roller's equilibrium: closed forms of the force balance, branch
//! switching, and the implicit derivatives against re-solved differences.

use super::*;
use crate::bearings::tapered_roller::contact::Race;
use crate::bearings::tapered_roller::input::{GyroInertia, TaperedInput};
use crate::units::{LBF_N, RPM_RAD_S};

fn model(rpm: f64) -> (TaperedInput, RollerGeometry, Dynamics, RollerModel) {
    let mut s = TaperedInput::afapl_sample();
    s.operating.inner_speed_rad_s = rpm * RPM_RAD_S;
    let g = &s.geometry;
    let rg = RollerGeometry::new(g, &s.materials.roller).unwrap();
    let dy = Dynamics::new(g, &rg, &s.operating, GyroInertia::Polar);
    let cup = RaceContact::new(Race::Cup, g, &rg, &s.materials, 21).unwrap();
    let cone = RaceContact::new(Race::Cone, g, &rg, &s.materials, 21).unwrap();
    let m = RollerModel::new(g, &rg, cup, cone, &dy, 1000.0, 1e-12, 60);
    (s, rg, dy, m)
}

/// The force balance alone fixes P₂ and P₃ from P₁ (issue's closed forms, independent
/// of the slice law): P₂ = [P₁cos(α+τ/2) − F_c cos(ψ−α)]/cos(α−τ/2),
/// P₃ = [P₁ sin τ + F_c sin(β−τ)]/cos(α−τ/2). Tolerance 1e-9 relative: the roller is
/// solved to 1e-12 of a 1000 N scale.
#[test]
fn force_balance_closed_forms() {
    for rpm in [0.0, 20_000.0] {
        let (s, rg, dy, m) = model(rpm);
        for (delta, theta) in [(1.5e-5, 0.0), (2.5e-5, 3e-4), (1.0e-5, -2e-4)] {
            let r = m.solve(delta, theta, None).unwrap();
            assert_eq!(r.state, RollerState::BothRaces);
            let (t, a) = (rg.half_cone_rad, rg.flange_angle_rad);
            let beta = s.geometry.cup_angle_rad;
            let psi = rg.axis_angle_rad;
            let fc = dy.centrifugal_force_n;
            let p1 = r.cup.load_n;
            let p2 = (p1 * (a + t).cos() - fc * (psi - a).cos()) / (a - t).cos();
            let p3 = (p1 * (2.0 * t).sin() + fc * (beta - 2.0 * t).sin()) / (a - t).cos();
            assert!(
                (r.cone.load_n / p2 - 1.0).abs() < 1e-9,
                "{rpm} {} {p2}",
                r.cone.load_n
            );
            assert!(
                (r.flange_n / p3 - 1.0).abs() < 1e-9,
                "{rpm} {} {p3}",
                r.flange_n
            );
            assert!(r.residual_n <= 1e-9);
        }
    }
}

/// dP₁/dΔ, dP₁/dΘ, dM₁/dΔ, dM₁/dΘ (eqs. 88–91) against central differences of
/// re-solved equilibria: 1e-6 relative to the entry's scale (h = 1e-6 of Δ; the roller
/// is solved to 1e-12 of the force scale).
#[test]
fn implicit_derivatives_match_resolved_differences() {
    for rpm in [0.0, 20_000.0] {
        let (s, _, _, m) = model(rpm);
        let half = 0.5 * s.geometry.effective_length_m;
        for (delta, theta) in [(1.5e-5, 0.0), (2.5e-5, 3e-4)] {
            let r = m.solve(delta, theta, None).unwrap();
            let hd = 1e-6 * delta;
            let ht = hd / half;
            let at = |d: f64, t: f64| m.solve(d, t, Some((r.delta1_m, r.theta1_rad))).unwrap();
            let (a, b) = (at(delta + hd, theta), at(delta - hd, theta));
            let dp_d = (a.cup.load_n - b.cup.load_n) / (2.0 * hd);
            let dm_d = (a.cup.moment_nm - b.cup.moment_nm) / (2.0 * hd);
            let (a, b) = (at(delta, theta + ht), at(delta, theta - ht));
            let dp_t = (a.cup.load_n - b.cup.load_n) / (2.0 * ht);
            let dm_t = (a.cup.moment_nm - b.cup.moment_nm) / (2.0 * ht);
            let sp = r.dp1[0].abs().max(r.dp1[1].abs() / half);
            let sm = r.dm1[0].abs().max(r.dm1[1].abs() / half);
            assert!(
                (dp_d - r.dp1[0]).abs() < 1e-6 * sp,
                "{rpm} dP/dΔ {dp_d} {}",
                r.dp1[0]
            );
            assert!(
                (dp_t - r.dp1[1]).abs() / half < 1e-6 * sp,
                "{rpm} dP/dΘ {dp_t} {}",
                r.dp1[1]
            );
            assert!(
                (dm_d - r.dm1[0]).abs() < 1e-6 * sm,
                "{rpm} dM/dΔ {dm_d} {}",
                r.dm1[0]
            );
            assert!(
                (dm_t - r.dm1[1]).abs() / half < 1e-6 * sm,
                "{rpm} dM/dΘ {dm_t} {}",
                r.dm1[1]
            );
        }
    }
}

/// With speed and too little ring approach the roller leaves the cone and rests on cup
/// and flange: P₁ = F_c·cos(ψ−α)/cos(τ/2+α) from eqs. 121–122 alone (1e-9), nothing to
/// the stiffness. Without speed and no approach it is free.
#[test]
fn branches_cup_and_flange_and_free() {
    let (_, rg, dy, m) = model(20_000.0);
    let r = m.solve(-1e-5, 0.0, None).unwrap();
    assert_eq!(r.state, RollerState::CupAndFlange);
    let (t, a, psi) = (rg.half_cone_rad, rg.flange_angle_rad, rg.axis_angle_rad);
    let p1 = dy.centrifugal_force_n * (psi - a).cos() / (t + a).cos();
    assert!(
        (r.cup.load_n / p1 - 1.0).abs() < 1e-9,
        "{} {p1}",
        r.cup.load_n
    );
    assert_eq!(r.cone.load_n, 0.0);
    assert_eq!(r.dp1, [0.0; 2]);
    assert!(r.flange_n > 0.0);
    let (_, _, _, m0) = model(0.0);
    let r = m0.solve(-1e-6, 0.0, None).unwrap();
    assert_eq!(r.state, RollerState::Free);
    assert_eq!(r.cup.load_n + r.cone.load_n + r.flange_n, 0.0);
    let _ = LBF_N;
}

/// Across the switch the cup load is continuous: bisecting the ring approach to the
/// switch (to 1e-15 m), the loads on the two sides differ by less than 1e-6 of F_c.
#[test]
fn cone_contact_switch_is_continuous() {
    let (_, _, dy, m) = model(20_000.0);
    let cf = m.solve(-1e-4, 0.0, None).unwrap();
    let (mut lo, mut hi) = (cf.delta1_m - 1e-6, cf.delta1_m + 1e-6);
    assert_eq!(
        m.solve(lo, 0.0, None).unwrap().state,
        RollerState::CupAndFlange
    );
    assert_eq!(
        m.solve(hi, 0.0, None).unwrap().state,
        RollerState::BothRaces
    );
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if m.solve(mid, 0.0, None).unwrap().state == RollerState::BothRaces {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    assert!(hi - lo < 1e-15);
    let (a, b) = (
        m.solve(lo, 0.0, None).unwrap(),
        m.solve(hi, 0.0, None).unwrap(),
    );
    assert_eq!(a.state, RollerState::CupAndFlange);
    assert!((a.cup.load_n - b.cup.load_n).abs() < 1e-6 * dy.centrifugal_force_n);
    assert!(b.cone.load_n < 1e-6 * dy.centrifugal_force_n);
}

/// The rollers of decks/trb_32007.toml (crowned, or with the logarithmic profile), as the
/// bearing builds them.
fn model_32007(log: bool) -> RollerModel {
    use crate::bearings::tapered_roller::bearing::Bearing;
    use crate::bearings::tapered_roller::deck::SCHEMA;
    use crate::deck::form::Form;
    let deck = include_str!("../../../../decks/trb_32007.toml");
    let mut input: TaperedInput = Form::parse(deck, "trb_32007.toml", &SCHEMA)
        .unwrap_or_else(|e| panic!("{e}"))
        .value;
    if log {
        input.geometry.profile = crate::bearings::tapered_roller::input::RollerProfile::Logarithmic;
    }
    Bearing::new(&input).unwrap().model
}

/// Issue 29 session 12: rollers of the 32007 deck at ring states where an edge contact
/// starts or stops (taken from the held-tilt scan `diag_moment_against_held_tilt`, whose
/// solves failed there in session 11; barely touching rollers at the load zone's edge,
/// 1e-6 to 0.3 N, their contact starting near an end of the roller): Newton from the cold
/// start alone does not converge (it stalls or runs out of iterations), and the
/// continuation from the aligned roller (`RollerModel::continuation`) reaches an
/// equilibrium that is an ordinary converged Newton solve: the force residual meets the
/// roller tolerance (or 100× it after a stall, the acceptance of `newton_solve`), the
/// cone carries load, and re-solving from the answer returns it to 1e-12 of the load.
#[test]
fn continuation_solves_rollers_at_an_edge_contacts_onset() {
    for (log, delta, theta) in [
        (false, -1.6948e-5, -4.280e-3),
        (false, -4.0398e-5, 1.011e-2),
        (false, -5.1295e-5, 1.284e-2),
        (true, -7.6005e-5, 1.427e-2),
        (true, -8.3869e-5, 1.617e-2),
    ] {
        let m = model_32007(log);
        let split = m.k * delta / (1.0 + m.k);
        let cold = m.newton_solve(delta, theta, true, Vector2::new(split, 0.5 * theta));
        assert!(
            cold.is_err(),
            "log {log} ({delta}, {theta}): cold start converged"
        );
        let r = m
            .solve(delta, theta, None)
            .unwrap_or_else(|e| panic!("log {log} ({delta}, {theta}): {e}"));
        assert_eq!(r.state, RollerState::BothRaces);
        assert!(r.cone.load_n > 0.0 && r.cup.load_n > 0.0);
        assert!(
            r.residual_n <= 100.0 * m.tolerance,
            "log {log}: residual {} N (tolerance {} N)",
            r.residual_n,
            m.tolerance
        );
        let again = m
            .newton_solve(delta, theta, true, Vector2::new(r.delta1_m, r.theta1_rad))
            .unwrap();
        assert!((again.cup.load_n - r.cup.load_n).abs() <= 1e-12 * r.cup.load_n.max(1.0));
        eprintln!(
            "log {log} Δ {delta:.4e} Θ {theta:.3e}: P₁ {:.4} N, P₂ {:.4} N, edge {}/{}",
            r.cup.load_n, r.cone.load_n, r.cup.edge_loaded, r.cone.edge_loaded
        );
    }
}
