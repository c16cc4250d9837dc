//! Warm starts of the double-row statics ([`super::analyse_from`]): the same answers as a
//! cold solve to the ring tolerance, for fewer lamina evaluations.

use super::{analyse, analyse_from, DoubleRowAnalysis};
use crate::bearings::double_row_spherical::input::DoubleRowInput;
use crate::bearings::double_row_spherical::load_sweep::{
    dynamic_rating_n, torque_point, torque_sweep, Direction,
};
use crate::bearings::double_row_spherical::losses::losses;

fn at(fr: f64, fa: f64) -> DoubleRowInput {
    let mut b = DoubleRowInput::example_22308();
    b.operating.radial_load_n = fr;
    b.operating.axial_load_n = fa;
    b
}

/// `warm` agrees with `cold` to the ring tolerance. The solve stops at a ring force
/// residual of 1e-9 of the reference force F (the deck's `force_tolerance`), so two solves
/// from different starts differ by up to ~2e-9·F in the ring forces and by that over the
/// ring stiffness in the deflections; the bounds below are 1e-6 relative (a thousand times
/// that, far below anything the reports print, and far above round-off) on the ring
/// deflections, every roller's contact loads, the guide ring's forces and offset, and the
/// loss.
fn assert_same(cold: &DoubleRowAnalysis, warm: &DoubleRowAnalysis, what: &str) {
    let rel = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-6 * scale;
    let u = cold
        .axial_deflection_m()
        .abs()
        .max(cold.radial_deflection_m().abs());
    assert!(
        rel(cold.axial_deflection_m(), warm.axial_deflection_m(), u)
            && rel(cold.radial_deflection_m(), warm.radial_deflection_m(), u),
        "{what}: deflections {:?} vs {:?}",
        (cold.axial_deflection_m(), cold.radial_deflection_m()),
        (warm.axial_deflection_m(), warm.radial_deflection_m())
    );
    let q = cold.max_roller_load_n();
    for (c, w) in cold.combined.rollers.iter().zip(&warm.combined.rollers) {
        assert!(
            rel(c.inner.normal_load_n, w.inner.normal_load_n, q)
                && rel(c.outer.normal_load_n, w.outer.normal_load_n, q)
                && rel(c.guide_force_n, w.guide_force_n, q),
            "{what}: row {} roller {}: {:?} vs {:?}",
            c.row,
            c.index,
            (
                c.inner.normal_load_n,
                c.outer.normal_load_n,
                c.guide_force_n
            ),
            (
                w.inner.normal_load_n,
                w.outer.normal_load_n,
                w.guide_force_n
            )
        );
    }
    let g = cold.guide.force_row1_n.max(cold.guide.force_row2_n).max(q);
    assert!(
        rel(cold.guide.force_row1_n, warm.guide.force_row1_n, g)
            && rel(cold.guide.force_row2_n, warm.guide.force_row2_n, g)
            && rel(
                cold.guide.axial_offset_m,
                warm.guide.axial_offset_m,
                cold.guide.axial_offset_m.abs().max(u)
            ),
        "{what}: guide ring {:?} vs {:?}",
        cold.guide,
        warm.guide
    );
    let (lc, lw) = (
        losses(cold).expect("cold losses").losses,
        losses(warm).expect("warm losses").losses,
    );
    assert!(
        rel(
            lc.friction_torque_inner_nm,
            lw.friction_torque_inner_nm,
            lc.friction_torque_inner_nm
        ) && rel(
            lc.friction_torque_outer_nm,
            lw.friction_torque_outer_nm,
            lc.friction_torque_outer_nm
        ),
        "{what}: M_fi, M_fo {:?} vs {:?}",
        (lc.friction_torque_inner_nm, lc.friction_torque_outer_nm),
        (lw.friction_torque_inner_nm, lw.friction_torque_outer_nm)
    );
    assert!(
        (lc.total_w - lw.total_w).abs() <= LOSS_SPLIT_NOISE * lc.total_w,
        "{what}: total loss {} vs {} W",
        lc.total_w,
        lw.total_w
    );
}

/// The loss stage's total against the statics moving by 1e-9 (the same bearing solved from
/// two starts). Before the ATZ law was regularised at its rolling point (`lamina_friction`
/// module notes) the pocket / skew split jumped with the loads' last digits (roller 1's
/// pocket force 355.6 N from one start, 359.8 N from the other, loads equal to 7.5e-9;
/// totals 3.7e-4 and 8.6e-4 apart) and this was 1e-3. Now every loss term follows a 1e-8
/// load change to 3.7e-7 (`loss_terms_follow_a_tiny_load_change`, the computed cage's
/// balance tolerance of 1e-6 of its torque scale the largest part): 1e-6 bounds it.
const LOSS_SPLIT_NOISE: f64 = 1e-6;

/// Every loss term follows a 1e-8 relative change of the loads to 1e-6 relative (issue 27
/// sensitivity; before the ATZ law was regularised at its rolling point,
/// `lamina_friction` module notes, a 7.5e-9 change moved a pocket force by 1.2 %): the
/// shipped deck's three cases, the cage speed measured and computed; each mechanism, the
/// total, the cage speed and every roller's pocket force (against the largest), the
/// largest relative change printed. A 1e-8 change of the loads is a 1e-8 change of the
/// physics (the terms' own response is O(1e-8)) plus the statics' residual (1e-9 of the
/// reference force) and the cage balance's tolerance (1e-6 of its torque scale, below
/// which the computed cage speed is not fixed): 1e-6 bounds them with room.
#[test]
fn loss_terms_follow_a_tiny_load_change() {
    use crate::bearings::double_row_spherical::input::CageSpeedSource;
    let mut worst = 0.0f64;
    for (fr, fa) in [(20_000.0, 2_000.0), (20_000.0, 0.0), (0.0, 6_000.0)] {
        for cage in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
            let run = |k: f64| {
                let mut b = at(fr * k, fa * k);
                b.cage.speed = cage;
                let a = analyse(&b, "test", None).expect("solves");
                losses(&a).expect("losses")
            };
            let (x, y) = (run(1.0), run(1.0 + 1e-8));
            let (lx, ly) = (&x.losses, &y.losses);
            let terms = [
                ("raceway_inner_w", lx.raceway_inner_w, ly.raceway_inner_w),
                ("raceway_outer_w", lx.raceway_outer_w, ly.raceway_outer_w),
                ("guide_ring_w", lx.guide_ring_w, ly.guide_ring_w),
                ("cage_pockets_w", lx.cage_pockets_w, ly.cage_pockets_w),
                ("cage_land_w", lx.cage_land_w, ly.cage_land_w),
                ("skew_w", lx.skew_w, ly.skew_w),
                ("total_w", lx.total_w, ly.total_w),
                ("cage_speed_rpm", lx.cage_speed_rpm, ly.cage_speed_rpm),
            ];
            for (name, a, b) in terms {
                let rel = (a - b).abs() / a.abs().max(1e-300);
                worst = worst.max(rel);
                assert!(
                    rel <= 1e-6,
                    "({fr}, {fa}) {cage:?}: {name} {a} -> {b} ({rel:.2e})"
                );
            }
            let fmax = x
                .rollers
                .iter()
                .map(|r| r.pocket_force_n.abs())
                .fold(0.0, f64::max);
            for (k, (r, s)) in x.rollers.iter().zip(&y.rollers).enumerate() {
                let rel = (r.pocket_force_n - s.pocket_force_n).abs() / fmax;
                worst = worst.max(rel);
                assert!(
                    rel <= 1e-6,
                    "({fr}, {fa}) {cage:?} roller {k}: pocket force {} -> {} N ({rel:.2e} of {fmax} N)",
                    r.pocket_force_n,
                    s.pocket_force_n
                );
            }
        }
    }
    eprintln!("largest relative change of a loss term under a 1e-8 load change: {worst:.2e}");
}

/// A solve started from a neighbouring load's solution (10–20 % away, the step of a
/// sweep or a few grid cells) gives the cold answer (`assert_same`) for fewer lamina
/// evaluations: combined, radial, and axial load (where both rows press the floating guide
/// ring); and a neighbouring geometry (R_Ci + 0.1 %, an optimiser grid step).
#[test]
fn warm_start_gives_the_cold_answer_for_fewer_evaluations() {
    let mut geometry = at(20_000.0, 2_000.0);
    geometry.geometry.inner_raceway_radius_m *= 1.001;
    let cases = [
        ("combined", at(20_000.0, 2_000.0), at(22_000.0, 2_200.0)),
        ("radial", at(20_000.0, 0.0), at(24_000.0, 0.0)),
        ("axial", at(0.0, 5_000.0), at(0.0, 6_000.0)),
        ("geometry", at(20_000.0, 2_000.0), geometry),
    ];
    for (what, from, to) in cases {
        let prev = analyse(&from, "from", None).expect("neighbour solves");
        let cold = analyse(&to, "cold", None).expect("cold solves");
        let warm = analyse_from(&to, "warm", Some(&prev.start()), None).expect("warm solves");
        assert_same(&cold, &warm, what);
        let (ec, ew) = (
            cold.combined.stats.lamina_evaluations,
            warm.combined.stats.lamina_evaluations,
        );
        eprintln!("{what}: lamina evaluations cold {ec}, warm {ew}");
        assert!(ew < ec, "{what}: warm {ew} not below cold {ec}");
    }
}

/// The warm-started sweep (each point from the previous one) answers what independent cold
/// points answer: M_fi and M_fo to 1e-6 relative, M and the total loss to the loss stage's
/// split noise ([`LOSS_SPLIT_NOISE`]), as `assert_same`.
#[test]
fn warm_sweep_is_the_cold_sweep() {
    let b = DoubleRowInput::example_22308();
    let c = dynamic_rating_n(&b).expect("rating");
    let values = [0.05, 0.1, 0.15];
    for dir in [Direction::Radial, Direction::Axial] {
        let warm = torque_sweep(&b, "warm", dir, &values, c, None).expect("sweep");
        for (x, w) in values.iter().zip(&warm) {
            let cold = torque_point(&b, "cold", dir, *x, c, None).expect("point");
            for (a, b, tol) in [
                (
                    cold.friction_torque_inner_nm,
                    w.friction_torque_inner_nm,
                    1e-6,
                ),
                (
                    cold.friction_torque_outer_nm,
                    w.friction_torque_outer_nm,
                    1e-6,
                ),
                (
                    cold.friction_torque_nm,
                    w.friction_torque_nm,
                    LOSS_SPLIT_NOISE,
                ),
                (cold.total_w, w.total_w, LOSS_SPLIT_NOISE),
            ] {
                assert!(
                    (a - b).abs() <= tol * a.abs(),
                    "{} F/C {x}: {cold:?} vs {w:?}",
                    dir.name()
                );
            }
        }
    }
}
