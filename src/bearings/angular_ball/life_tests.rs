use super::*;
use crate::bearings::angular_ball::analysis::analyse;
use crate::bearings::angular_ball::input::BallInput;
use crate::numerics::cancel::Cancel;

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// Chen's Bearing A with a radial load on top of its preload, so that the ball loads and
/// contact angles differ round the ring.
fn loaded_a() -> BallAnalysis {
    let mut b = BallInput::chen_a();
    b.operating.radial_load_n = 800.0;
    analyse(&b, Cancel::NONE).unwrap()
}

/// The ISO/TS 16281 reading of the module notes evaluated independently from the ball
/// loads: Q_c typed out from the groove conformity (not by calling the library), the
/// rotating ring's cubic mean and the stationary ring's 10/3 mean of Q/Q_c, the product
/// law with e = 10/9 and the hours 10⁶·L/(60·n). Tolerance 1e-9 (the same arithmetic in a
/// different order: powf round-off only).
#[test]
fn ball_life_equals_independent_iso_ts_16281_evaluation() {
    let a = loaded_a();
    let g = &a.geometry;
    let z = a.balls.len() as f64;
    let d_mm = g.ball_diameter_m * 1e3;
    let qc = |f: f64, alpha: f64, inner: bool| {
        let gamma = g.ball_diameter_m * alpha.cos() / g.pitch_diameter_m;
        let (near, far) = if inner {
            (1.0 - gamma, 1.0 + gamma)
        } else {
            (1.0 + gamma, 1.0 - gamma)
        };
        1.3 * 98.1 * (2.0 * f / (2.0 * f - 1.0)).powf(0.41) * near.powf(1.39) / far.powf(1.0 / 3.0)
            * (gamma / alpha.cos()).powf(0.3)
            * d_mm.powf(1.8)
            / z.powf(1.0 / 3.0)
    };
    // Bearing A turns the inner ring: inner rotating (p = 3), outer stationary (10/3).
    assert!(a.input.operating.inner_speed_rad_s.abs() > a.input.operating.outer_speed_rad_s.abs());
    let (mut si, mut so) = (0.0, 0.0);
    for b in &a.balls {
        si += (b.inner.load_n / qc(g.inner_groove_curvature, b.inner.angle_rad, true)).powi(3);
        so += (b.outer.load_n / qc(g.outer_groove_curvature, b.outer.angle_rad, false))
            .powf(10.0 / 3.0);
    }
    let li = (si / z).powf(-1.0);
    let lo = (so / z).powf(-0.9);
    let lb = (li.powf(-10.0 / 9.0) + lo.powf(-10.0 / 9.0)).powf(-0.9);
    let n_rpm = (a.input.operating.inner_speed_rad_s - a.input.operating.outer_speed_rad_s).abs()
        * 30.0
        / std::f64::consts::PI;
    let r = reference_life(&a).unwrap();
    assert!(rel(r.l10_inner_mrev.unwrap(), li) < 1e-9);
    assert!(rel(r.l10_outer_mrev.unwrap(), lo) < 1e-9);
    assert!(rel(r.l10_bearing_mrev.unwrap(), lb) < 1e-9);
    assert!(rel(r.l10_bearing_h.unwrap(), lb * 1e6 / (60.0 * n_rpm)) < 1e-9);
    // The contact angles really differ (the per-ball capacities are exercised).
    let (amin, amax) = a.balls.iter().fold((f64::MAX, f64::MIN), |(lo, hi), b| {
        (lo.min(b.inner.angle_rad), hi.max(b.inner.angle_rad))
    });
    assert!(amax - amin > 1e-3, "{amin} {amax}");
}

/// With every ball at one angle (pure axial load) the per-ball form is Lundberg–Palmgren's
/// (Q_c/Q_e)³ of `life_point::ball_bearing_life` with b_m·Q_c (1e-9), and the effective
/// capacity is then Q_c itself.
#[test]
fn uniform_angles_reduce_to_life_point() {
    let a = analyse(&BallInput::chen_a(), Cancel::NONE).unwrap();
    let g = &a.geometry;
    let r = reference_life(&a).unwrap();
    let qi: Vec<f64> = a.balls.iter().map(|b| b.inner.load_n).collect();
    let qo: Vec<f64> = a.balls.iter().map(|b| b.outer.load_n).collect();
    let lp = life_point::ball_bearing_life(&life_point::PointLifeInputs {
        geometry: life_point::BallGeometry {
            ball_diameter_m: g.ball_diameter_m,
            pitch_diameter_m: g.pitch_diameter_m,
            contact_angle_rad: a.balls[0].inner.angle_rad,
            ball_count: qi.len(),
        },
        inner_groove_curvature: g.inner_groove_curvature,
        outer_groove_curvature: g.outer_groove_curvature,
        inner_ball_loads_n: &qi,
        outer_ball_loads_n: &qo,
        rotating: life_point::RotatingRing::Inner,
        relative_speed_rad_s: 1.0,
    })
    .unwrap();
    // b_m scales every capacity, so every raceway life by b_m³.
    let b3 = 1.3f64.powi(3);
    assert!(
        rel(
            r.l10_inner_mrev.unwrap(),
            b3 * lp.inner_l10_mrev.finite().unwrap()
        ) < 1e-9
    );
    assert!(rel(r.capacity_inner_n.unwrap(), 1.3 * lp.inner_capacity_n) < 1e-9);
}

/// The ISO side on Bearing A (15°): C_r present, P from Table 3, κ from the bulk
/// temperature, a_ISO and the modified life; s0 = (4200 MPa/p_max)³ exactly. Bearing B
/// (60°) has no ISO 281 radial rating: the reason is stated, the reference life stands.
#[test]
fn iso_numbers_and_absences() {
    let a = loaded_a();
    let l = life(&a);
    let iso = &l.iso;
    assert!(
        iso.basic_dynamic_rating_n.is_some() && iso.basic_l10_mrev.is_some(),
        "{:?}",
        iso.reasons
    );
    assert!(
        iso.kappa.is_some() && iso.a_iso.is_some(),
        "{:?}",
        iso.reasons
    );
    assert!(
        rel(
            iso.modified_l10_mrev.unwrap(),
            iso.a_iso.unwrap() * iso.basic_l10_mrev.unwrap()
        ) < 1e-12
    );
    assert!(
        rel(
            iso.static_safety.unwrap(),
            (4.2e9 / a.max_pressure_pa()).powi(3)
        ) < 1e-12
    );
    let b = analyse(&BallInput::chen_b(), Cancel::NONE).unwrap();
    let lb = life(&b);
    assert!(lb.reference.is_ok());
    assert!(lb.iso.basic_l10_mrev.is_none());
    assert!(
        lb.iso.reasons.iter().any(|r| r.contains("45°")),
        "{:?}",
        lb.iso.reasons
    );
}
