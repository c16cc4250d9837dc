use super::*;
use crate::bearings::tapered_roller::analysis::analyse;
use crate::bearings::tapered_roller::input::TaperedInput;

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

fn at_rest(axial_n: f64) -> TaperedInput {
    let mut t = TaperedInput::afapl_sample();
    t.operating.inner_speed_rad_s = 0.0;
    t.operating.outer_speed_rad_s = 0.0;
    t.operating.axial_load_n = axial_n;
    t.operating.radial_load_n = 0.0;
    t
}

/// The AFAPL sample at rest under pure thrust (every roller alike): the raceway
/// capacities are Lundberg–Palmgren's 552·b_m·λ·(1∓θ)^(29/27)/(1±θ)^(1/4)·(θ/cos β)^(2/9)·
/// D^(29/27)·L^(7/9)·Z^(−1/4) typed out here at the cone's β − 2t and the cup's β (1e-12),
/// the raceway lives (P_c/P_e)⁴ with one P_e per raceway (1e-9). Doubling the thrust
/// doubles every roller load (equilibrium) but not P_e: the fully crowned contact
/// lengthens with load (ℓ ∝ Q^m, m ≈ 0.3–0.5), and eq. 6.1 over the fixed Γ gives
/// P_e ∝ Q·ℓ^(−7/9), so the life falls by 2^(4(1−7m/9)), between 2^2.5 and 2⁴ (measured
/// 7.8 ≈ 2^2.96), not the straight roller's 16.
#[test]
fn thrust_life_capacities_and_load_exponent() {
    let t = at_rest(13_344.0);
    let a = analyse(&t, "afapl").unwrap();
    let l = life(&a);
    let g = &t.geometry;
    let half_cone = a.bearing.geometry.half_cone_rad;
    let span = {
        let c = &a.slices[0][0];
        (c[1].x_m - c[0].x_m).abs() * c.len() as f64
    };
    let qc = |angle: f64, inner: bool| {
        let th = g.roller_diameter_m * angle.cos() / g.pitch_diameter_m;
        let (near, far) = if inner {
            (1.0 - th, 1.0 + th)
        } else {
            (1.0 + th, 1.0 - th)
        };
        552.0 * 1.1 * 0.83 * near.powf(29.0 / 27.0) / far.powf(0.25)
            * (th / angle.cos()).powf(2.0 / 9.0)
            * (g.roller_diameter_m * 1e3).powf(29.0 / 27.0)
            * (span * 1e3).powf(7.0 / 9.0)
            * (g.roller_count as f64).powf(-0.25)
    };
    let ci = qc(g.cup_angle_rad - 2.0 * half_cone, true);
    let co = qc(g.cup_angle_rad, false);
    assert!(rel(l.reference.capacity_inner_n.unwrap(), ci) < 1e-12);
    assert!(rel(l.reference.capacity_outer_n.unwrap(), co) < 1e-12);
    // Every roller alike: both means equal the one P_e of each raceway.
    let (cup, cone) = (&a.slices[0][0], &a.slices[0][1]);
    let pe = |s: &[SliceResult]| {
        let w = (s[1].x_m - s[0].x_m).abs();
        let q: Vec<f64> = s.iter().map(|x| x.load_n_m * w).collect();
        let n = q.len() as f64;
        n.powf(7.0 / 9.0)
            * q.iter()
                .map(|x| x.max(0.0).powf(4.5))
                .sum::<f64>()
                .powf(2.0 / 9.0)
    };
    assert!(rel(l.reference.l10_inner_mrev.unwrap(), (ci / pe(cone)).powi(4)) < 1e-9);
    assert!(rel(l.reference.l10_outer_mrev.unwrap(), (co / pe(cup)).powi(4)) < 1e-9);
    let b = analyse(&at_rest(2.0 * 13_344.0), "afapl2").unwrap();
    let ratio =
        l.reference.l10_bearing_mrev.unwrap() / life(&b).reference.l10_bearing_mrev.unwrap();
    assert!(ratio > 2f64.powf(2.5) && ratio < 16.0, "{ratio}");
    // At rest: no hours; no lubricant: κ and a_ISO absent with the reason.
    assert_eq!(l.reference.l10_bearing_h, None);
    assert!(l.iso.kappa.is_none() && l.iso.a_iso.is_none());
    assert!(l.iso.reasons.iter().any(|r| r.contains("no lubricant")));
    assert!(l.json().get("lambda_reason").is_some());
}

/// ISO 281 on the AFAPL geometry: C_r = 1.1·f_c·(L cos α)^(7/9)·Z^(3/4)·D^(29/27) by hand
/// (1e-12, f_c from the table function), P = 0.4·cot α·F_a for pure thrust (above e), the
/// basic life (C/P)^(10/3) and s0 = (4 GPa/p_max)².
#[test]
fn iso_rating_and_static_safety() {
    let t = TaperedInput::afapl_sample();
    let a = analyse(&t, "afapl").unwrap();
    let l = life(&a);
    let g = &t.geometry;
    let ca = g.cup_angle_rad.cos();
    let gamma = g.roller_diameter_m * ca / g.pitch_diameter_m;
    let fc = rating::iso_fc_radial_roller(gamma).unwrap();
    let c = 1.1
        * fc
        * (g.effective_length_m * 1e3 * ca).powf(7.0 / 9.0)
        * (g.roller_count as f64).powf(0.75)
        * (g.roller_diameter_m * 1e3).powf(29.0 / 27.0);
    assert!(rel(l.iso.basic_dynamic_rating_n.unwrap(), c) < 1e-12);
    let p = 0.4 / g.cup_angle_rad.tan() * t.operating.axial_load_n;
    assert!(rel(l.iso.equivalent_load_n.unwrap(), p) < 1e-12);
    assert!(rel(l.iso.basic_l10_mrev.unwrap(), (c / p).powf(10.0 / 3.0)) < 1e-12);
    assert!(
        rel(
            l.iso.static_safety.unwrap(),
            (4e9 / l.max_contact_stress_pa).powi(2)
        ) < 1e-12
    );
    assert!(l.reference.l10_bearing_h.is_some());
}
