//! The ball load distribution against OpenJones (issue 29, "Validation"): its LE-7
//! turbopump example (`decks/le7_turbopump.toml` says where each number comes from) run
//! side by side in Octave 7.3 by `benches/le7_openjones.sh` on OpenJones commit 81d4a4e
//! (github.com/Rikki-Tikki-Tavi-12/OpenJones), reading its solution vector (its printed
//! Q and α are wrong when f_i ≠ f_o: the script says why). Ball 0 (on the load line; all
//! balls alike under the pure axial load), measured 2026-11-27:
//!
//! | OpenJones          | α_i (deg)  | α_o (deg)  | Q_i (N)    | Q_o (N)    |
//! |--------------------|------------|------------|------------|------------|
//! | friction off (λ 0) | 25.877277  | 20.115933  | 611.760928 | 776.341469 |
//! | full (λ_o 2, λ_i 0)| 26.232633  | 18.605438  | 604.049415 | 768.816735 |
//!
//! OpenJones's fsolve stops at a residual of 2–5e-13 (forces in N, groove geometry in
//! m²): its approaches are good to ~2e-5, so the agreement asked, 0.02 %, is what the two
//! independent codes can show; both use exact Hertz constants at the loaded angles and
//! Harris's outer-race-control kinematics.

use super::analysis::analyse;
use super::deck::SCHEMA;
use super::geometry::BallGeometry;
use super::input::{BallInput, FrictionSplit};
use super::load_conditions::{axial_condition, conditions};
use super::load_distribution;
use crate::deck::form::Form;
use crate::numerics::cancel::Cancel;

fn le7() -> BallInput {
    let text = include_str!("../../../decks/le7_turbopump.toml");
    match Form::parse(text, "le7_turbopump.toml", &SCHEMA) {
        Ok(f) => f.value,
        Err(e) => panic!("{e}"),
    }
}

/// (α_i deg, α_o deg, Q_i N, Q_o N) of ball 0.
fn ball0(l: &load_distribution::LoadDistribution) -> [f64; 4] {
    let e = &l.balls[0].equilibrium;
    [
        e.inner.angle_rad.to_degrees(),
        e.outer.angle_rad.to_degrees(),
        e.inner.load_n,
        e.outer.load_n,
    ]
}

fn assert_close(got: [f64; 4], want: [f64; 4], rel: f64, what: &str) {
    for (k, (g, w)) in ["α_i", "α_o", "Q_i", "Q_o"]
        .iter()
        .zip(got.iter().zip(want))
    {
        assert!(
            (g - w).abs() <= rel * w.abs(),
            "{what} {k}: rollbench {g} vs OpenJones {w} ({:.2e})",
            (g - w) / w
        );
    }
}

/// Gyroscopic friction off in both (OpenJones λ_o = 0; here the friction cap µ_max = 0,
/// so 2-7 gives none), centrifugal force on: ball 0's angles and loads within 0.02 %.
#[test]
fn le7_without_gyroscopic_friction_matches_openjones() {
    let i = le7();
    let g = BallGeometry::new(&i).unwrap();
    let (axial, _) = axial_condition(&i, &g, Cancel::NONE).unwrap();
    let mut c = conditions(&i, axial, 1.0);
    c.max_friction = 0.0;
    let l = load_distribution::solve(&g, &c, Cancel::NONE).unwrap();
    assert_close(
        ball0(&l),
        [25.877277, 20.115933, 611.760928, 776.341469],
        2e-4,
        "friction off",
    );
}

/// The deck as shipped (`friction_split = "controlling-race"`: Harris's λ_o = 2, λ_i = 0,
/// OpenJones's outer race control) through the whole analysis: within 0.03 % of
/// OpenJones's full model (measured: α_i +4e-5, α_o −2.1e-4, Q_i −3.7e-5, Q_o +1.5e-4);
/// the proportional split (Chen's, the default) moves Q_i by more than 0.1 %, so the
/// comparison tells the two apart.
///
/// The 2e-4 on α_o is traced (session 9): OpenJones puts the ball centre on the pitch
/// circle, d_m/2, in its race-control speeds (γ′ = D/d_m) and in its centrifugal force
/// (½ m d_m ω_m²); here both use the loaded ball's own centre radius R_b, 19.2605 mm
/// against 19.25 (+5.5e-4), so ω_m is +1.3e-4, F_c +8.1e-4 and M_g +6.1e-4 above
/// OpenJones's (which prints M_g 0.090917 N·m, ω_m 2 143.29 rad/s, F_c 179.49 N). With
/// R_b replaced by d_m/2 in a scratch build, the four gaps fell to ≤ 2.7e-6 (kinematics
/// alone at d_m/2: α_o −1.0e-4, so each term is about half). It shows with the friction
/// on because M_g turns α_o by 1.5°; R_b is the more exact reading, so it is kept.
#[test]
fn le7_full_model_matches_openjones() {
    let want = [26.232633, 18.605438, 604.049415, 768.816735];
    let i = le7();
    assert_eq!(i.kinematics.friction_split, FrictionSplit::ControllingRace);
    let a = analyse(&i, Cancel::NONE).unwrap();
    assert_close(ball0(&a.load), want, 3e-4, "full");
    let mut p = i.clone();
    p.kinematics.friction_split = FrictionSplit::Proportional;
    let q = ball0(&analyse(&p, Cancel::NONE).unwrap().load)[2];
    assert!((q - want[2]).abs() > 1e-3 * want[2], "proportional Q_i {q}");
}
