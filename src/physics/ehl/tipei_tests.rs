use super::*;
use crate::physics::contact::line::line_contact_reduced;
use std::f64::consts::PI;

#[test]
fn table_1_values() {
    // Issue 26 Validation 3: f(0) = 4 and f(0.5) = 7.8 within 1 % (Table 1). Measured:
    // f(0) = 4 to rounding, f(0.5) = 7.8297 (0.38 % above the table's two digits), and
    // f(1) = 32/3 (the table's garbled "3212", module note) to rounding.
    assert!((f_of_k(0.0) - 4.0).abs() < 1e-12, "{}", f_of_k(0.0));
    let f05 = f_of_k(0.5);
    assert!((f05 / 7.8 - 1.0).abs() < 0.01, "{f05}");
    assert!((f05 - 7.8297).abs() < 1e-4, "{f05}");
    assert!((f_of_k(1.0) - 32.0 / 3.0).abs() < 1e-12, "{}", f_of_k(1.0));
}

#[test]
fn eq_14_counter_flow_is_half_the_film() {
    // Eq. 14 as read: the dividing streamlines of the meniscus profile are a half film
    // apart (cot πζ₁ · cot πζ₂ = −1). Checked on the velocity profile itself, not on the
    // closed form: 1e-12 (rounding of the quadratic's roots), both zeros inside [0, 1].
    for i in 0..=100 {
        let k = i as f64 / 100.0;
        let g = f_of_k(k);
        let (z1, z2) = dividing_streamlines(k, g).expect("counter-flow at f(k)");
        assert!(
            (0.0..=1.0 + 1e-12).contains(&z1) && z2 <= 1.0 + 1e-12,
            "k={k}"
        );
        assert!((z2 - z1 - 0.5).abs() < 1e-12, "k={k}: {z1} {z2}");
        // The profile really is zero there (u/U₁ at the roots, 1e-12).
        let u = |z: f64| 0.5 * g * z * z - (0.5 * g + 1.0 - k) * z + 1.0;
        assert!(u(z1).abs() < 1e-12 && u(z2).abs() < 1e-12, "k={k}");
        // And reversed between them.
        assert!(u(0.5 * (z1 + z2)) < 0.0, "k={k}");
        if k > 0.01 {
            let prod = (PI * z1).tan().recip() * (PI * z2).tan().recip();
            assert!((prod + 1.0).abs() < 1e-9, "k={k}: {prod}");
        }
    }
}

#[test]
fn eq_16_bounds_hold_on_zero_to_one() {
    // 2(1+√k)² < f(k) < 6(1+k) ≤ 6(1+√k) (the printed upper bound) for k in [0, 1]; and
    // at the lower bound the profile has a double zero (onset of counter-flow).
    for i in 0..=200 {
        let k = i as f64 / 200.0;
        let f = f_of_k(k);
        assert!(counter_flow_onset(k) < f, "k={k}: {f}");
        assert!(f < zero_flow_gradient(k), "k={k}: {f}");
        assert!(
            zero_flow_gradient(k) <= 6.0 * (1.0 + k.sqrt()) + 1e-12,
            "k={k}"
        );
        let (z1, z2) =
            dividing_streamlines(k, counter_flow_onset(k) * (1.0 + 1e-12)).expect("double zero");
        assert!((z2 - z1).abs() < 1e-5, "k={k}: {z1} {z2}");
        assert!(dividing_streamlines(k, counter_flow_onset(k) * 0.99).is_none());
    }
}

#[test]
fn menisci_satisfy_reynolds_by_quadrature() {
    // The dimensionless Reynolds gradient dp/ds ∝ 1/(1+s²)² − c/(1+s²)³ integrated by
    // Simpson, independent of the sech antiderivatives the solver uses.
    // For k = 0, 0.5, 1: p(outlet) = 0 by a 20 000-panel Simpson quadrature of Reynolds in
    // the parabolic gap, to 1e-9 of ∫|dp/ds| (Simpson error ~ (Δs)⁴ ≈ 1e-14 here); and the
    // dimensionless gradients at the menisci are f(k) and 2(1+√k)² (1e-10).
    let hc = 0.4e-6;
    let r = 5.06e-3;
    for k in [0.0, 0.5, 1.0] {
        let t = tipei_inlet(k, hc, r).expect("inlet");
        let a_i = t.f_k / zero_flow_gradient(k);
        let c = t.inlet_film_m / hc * (1.0 - a_i);
        let s_i = -t.theta_inlet.sinh();
        let s_e = t.theta_outlet.sinh();
        let n = 20_000;
        let ds = (s_e - s_i) / n as f64;
        let g = |s: f64| {
            let q = 1.0 + s * s;
            1.0 / (q * q) - c / (q * q * q)
        };
        let (mut sum, mut abs) = (0.0, 0.0);
        for j in 0..=n {
            let s = s_i + ds * j as f64;
            let w = if j == 0 || j == n {
                1.0
            } else if j % 2 == 1 {
                4.0
            } else {
                2.0
            };
            sum += w * g(s);
            abs += w * g(s).abs();
        }
        assert!(sum.abs() < 1e-9 * abs, "k={k}: {sum} of {abs}");
        // G = 6(1+k)(1 − h*/h) at each meniscus, h*/h_c = c.
        let grad = |ratio: f64| zero_flow_gradient(k) * (1.0 - c / ratio);
        let gi = grad(t.inlet_film_m / hc);
        let ge = grad(t.outlet_film_m / hc);
        assert!((gi - f_of_k(k)).abs() < 1e-10 * gi, "k={k}: {gi}");
        assert!(
            (ge - counter_flow_onset(k)).abs() < 1e-10 * ge,
            "k={k}: {ge}"
        );
        assert!(t.iterations > 0 && t.iterations <= MAX_ITERATIONS);
    }
}

#[test]
fn distances_scale_with_film_and_starvation_vanishes() {
    // Truck bearing roller–inner race (Table A1): R_zx = (1/6.35 mm + 1/25 mm)⁻¹, E* of
    // steel (210 GPa, ν 0.3), 700 N over 16 mm: b from Hertz. Small-angle check:
    // m_i = √(2R h_c) sinh ϑ_i within 2e-3 (the ratio is cos(φ/2), φ ≤ 0.1 rad here).
    let r = 1.0 / (1.0 / 6.35e-3 + 1.0 / 25e-3);
    let e_star = 210e9 / (2.0 * (1.0 - 0.09));
    let b = line_contact_reduced(700.0 / 16e-3, r, e_star).half_width_m;
    let mut last = 0.0;
    for i in 0..=40 {
        let hc = 0.05e-6 * 1.1f64.powi(i);
        let t = tipei_inlet(1.0, hc, r).expect("inlet");
        let sh = t.theta_inlet.sinh();
        let small = (2.0 * r * hc).sqrt() * sh;
        assert!((t.inlet_distance_m / small - 1.0).abs() < 2e-3, "{hc}");
        // Exactly: R sin φ = √(2R h_c) sinh ϑ · cos(φ/2), cos(φ/2) = √(1 − h_c sinh²ϑ/(2R)).
        let exact = small * (1.0 - hc * sh * sh / (2.0 * r)).sqrt();
        assert!((t.inlet_distance_m / exact - 1.0).abs() < 1e-12, "{hc}");
        // A thinner film gives a shorter inlet: strictly monotone.
        assert!(t.inlet_distance_m > last, "hc={hc}");
        last = t.inlet_distance_m;
        // The outlet is downstream and closer than the inlet.
        assert!(t.outlet_distance_m > 0.0 && t.outlet_distance_m < t.inlet_distance_m);
    }
    // A thick film: the meniscus lies beyond the flooded 5 b (starvation vanishes), a
    // thin one well inside 4 b (starved).
    let thick = tipei_inlet(1.0, 2e-6, r).expect("inlet");
    assert!(
        thick.inlet_distance_m > 5.0 * b,
        "{} vs b {b}",
        thick.inlet_distance_m
    );
    let thin = tipei_inlet(1.0, 0.05e-6, r).expect("inlet");
    assert!(
        thin.inlet_distance_m < 4.0 * b,
        "{} vs b {b}",
        thin.inlet_distance_m
    );
    // The inlet shape does not depend on h_c: ϑ_i is the same.
    assert!((thick.theta_inlet - thin.theta_inlet).abs() < 1e-10);
}

#[test]
fn inlet_grows_towards_pure_rolling() {
    // More counter-flow at the meniscus (larger f(k)) means the meniscus sits further out:
    // ϑ_i increases with k (measured 1.263 at k = 0, 1.814 at 0.5, 1.899 at 1).
    let mut last = 0.0;
    for i in 0..=20 {
        let k = i as f64 / 20.0;
        let t = tipei_inlet(k, 0.4e-6, 5e-3).expect("inlet");
        assert!(t.theta_inlet > last, "k={k}");
        last = t.theta_inlet;
    }
    let t0 = tipei_inlet(0.0, 0.4e-6, 5e-3).expect("inlet");
    assert!((t0.theta_inlet - 1.2627).abs() < 1e-3, "{}", t0.theta_inlet);
}

#[test]
fn errors_name_the_input() {
    let e = tipei_inlet(1.5, 0.4e-6, 5e-3).unwrap_err().to_string();
    assert!(e.contains("speed_ratio") && e.contains("0 … 1"), "{e}");
    let e = tipei_inlet(0.5, -1.0, 5e-3).unwrap_err().to_string();
    assert!(e.contains("central_film_m"), "{e}");
    let e = tipei_inlet(0.5, 0.4e-6, f64::NAN).unwrap_err().to_string();
    assert!(e.contains("radius_m"), "{e}");
    // A film comparable to the radius puts the meniscus past a quarter turn.
    let e = tipei_inlet(1.0, 1e-3, 5e-3).unwrap_err().to_string();
    assert!(e.contains("too thick") && e.contains("inlet"), "{e}");
    assert_eq!(speed_ratio(2.0, -1.0), 0.5);
    assert_eq!(speed_ratio(0.0, 0.0), 1.0);
}
