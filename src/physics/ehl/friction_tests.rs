use super::*;

fn oil() -> Houpert {
    Houpert {
        viscosity_pa_s: 0.0499,
        pressure_viscosity_pa_inv: 1.39e-8,
        temperature_viscosity_per_k: 0.026,
        reference_temperature_k: 313.15,
        density_kg_m3: 829.3,
    }
}

/// Table 2 (σ = 0.6 µm) with the seed's ξβσ = 0.055 and σ/β = 1e-3.
fn rough() -> Roughness {
    Roughness {
        composite_rms_m: 0.6e-6,
        roughness_parameter: 0.055,
        asperity_slope: 1e-3,
    }
}

/// Steel on steel, E* = E/(2(1 − ν²)).
const E_STAR: f64 = 210e9 / (2.0 * 0.91);

fn input<'a>(x: &'a [f64], p: &'a [f64], h: &'a [f64], t: &'a [f64], du: f64) -> FrictionInput<'a> {
    FrictionInput {
        x_m: x,
        pressure_pa: p,
        film_m: h,
        temperature_k: t,
        lower_speed_m_s: 10.0,
        upper_speed_m_s: 10.0 + du,
        lubricant: oil(),
        roughness: rough(),
        reduced_modulus_pa: E_STAR,
        limiting_shear_stress_pa: SEED_LIMITING_SHEAR_PA,
        limiting_shear_slope: SEED_BOUNDARY_SLOPE,
        effective_length_m: 16e-3,
    }
}

fn grid(n: usize, half: f64) -> Vec<f64> {
    (0..n)
        .map(|i| -half + 2.0 * half * i as f64 / (n - 1) as f64)
        .collect()
}

#[test]
fn dry_limit_is_boundary_friction_only() {
    // h = 0 (no film, no fluid pressure): only the asperities carry and shear. Per node
    // µ = (τ₀ a + γ p_a)/p_a = γ + τ₀ a/p_a with a and p_a at λ = 0: the boundary
    // coefficient, between γ = 0.047 and γ + τ₀A_a/W_a (measured 0.048). 1e-12 relative.
    let n = 21;
    let x = grid(n, 50e-6);
    let p = vec![0.0; n];
    let h = vec![0.0; n];
    let t = vec![313.15; n];
    let f = contact_friction(&input(&x, &p, &h, &t, 0.2)).expect("friction");
    assert_eq!(f.viscous_friction_n, 0.0);
    assert_eq!(f.hydrodynamic_load_n, 0.0);
    let r = rough();
    let pa = r.load_factor_pa(E_STAR) * f_5_2(0.0);
    let a = r.area_factor() * f_2(0.0);
    let mu = SEED_BOUNDARY_SLOPE + SEED_LIMITING_SHEAR_PA * a / pa;
    assert!(
        (f.friction_coefficient / mu - 1.0).abs() < 1e-12,
        "{}",
        f.friction_coefficient
    );
    assert!(f.friction_coefficient > 0.047 && f.friction_coefficient < 0.05);
    // The asperity load is p_a over the strip: 100 µm × 16 mm.
    assert!((f.asperity_load_n / (pa * 100e-6 * 16e-3) - 1.0).abs() < 1e-12);
}

#[test]
fn full_film_has_no_boundary_friction() {
    // λ > 4 everywhere: no asperity load, no boundary friction (the cutoff), all viscous.
    let n = 41;
    let x = grid(n, 50e-6);
    let p: Vec<f64> = x
        .iter()
        .map(|&x| 0.5e9 * (1.0 - (x / 50e-6).powi(2)).max(0.0).sqrt())
        .collect();
    let h = vec![2.5e-6; n];
    let t = vec![333.15; n];
    let f = contact_friction(&input(&x, &p, &h, &t, 0.3)).expect("friction");
    assert_eq!(f.boundary_friction_n, 0.0);
    assert_eq!(f.asperity_load_n, 0.0);
    assert!(f.viscous_friction_n > 0.0);
    // And a thin film (λ ≈ 0.67, the seed's h_c ≈ 0.4 µm over σ = 0.6 µm) has some.
    let thin = vec![0.4e-6; n];
    let g = contact_friction(&input(&x, &p, &thin, &t, 0.3)).expect("friction");
    assert!(g.boundary_friction_n > 0.0 && g.asperity_load_n > 0.0);
}

#[test]
fn newtonian_low_shear_is_eta_du_over_h() {
    // Uniform low pressure and temperature, thick film (λ > 4), small Δu: η Δu/h far
    // below τ₀, so F = η(p, T) Δu/h · 2X · L exactly (the trapezoid of a constant,
    // 1e-12 relative), and the power is F·Δu.
    let n = 11;
    let x = grid(n, 100e-6);
    let p = vec![1e6; n];
    let h = vec![5e-6; n];
    let t = vec![323.15; n];
    let du = 0.05;
    let f = contact_friction(&input(&x, &p, &h, &t, du)).expect("friction");
    // The Δu the function sees: (10 + 0.05) − 10 in floating point.
    let du = (10.0 + du) - 10.0;
    let eta = oil().viscosity_pa_s(1e6, 323.15);
    let want = eta * du / 5e-6 * 200e-6 * 16e-3;
    assert!(
        (f.viscous_friction_n / want - 1.0).abs() < 1e-12,
        "{} vs {want}",
        f.viscous_friction_n
    );
    assert_eq!(f.limited_nodes, 0);
    assert!((f.power_loss_w - f.friction_n * du).abs() <= 1e-15 * f.power_loss_w.abs());
    // Reversed sliding reverses the force, not the power.
    let g = contact_friction(&input(&x, &p, &h, &t, -0.05)).expect("friction");
    assert!((g.friction_n + f.friction_n).abs() < 1e-12 * f.friction_n.abs());
    assert!((g.power_loss_w - f.power_loss_w).abs() < 1e-12 * f.power_loss_w.abs());
}

#[test]
fn limiting_shear_caps_the_hertz_zone() {
    // At 1.5 GPa and 60 °C η ≈ 200 Pa·s (Houpert): with Δu = 5 m/s over 2.5 µm (λ > 4)
    // the Couette stress 4e8 Pa exceeds τ₀ + γp = 7.3e7 Pa and the cap holds, so the
    // fully limited film gives F = L∫(τ₀ + γp) dx (1e-12).
    let n = 41;
    let x = grid(n, 50e-6);
    let p = vec![1.5e9; n];
    let h = vec![2.5e-6; n];
    let t = vec![333.15; n];
    let f = contact_friction(&input(&x, &p, &h, &t, 5.0)).expect("friction");
    assert_eq!(f.limited_nodes, n);
    let want = (SEED_LIMITING_SHEAR_PA + SEED_BOUNDARY_SLOPE * 1.5e9) * 100e-6 * 16e-3;
    assert!((f.viscous_friction_n / want - 1.0).abs() < 1e-12);
    // No sliding, no friction (pure rolling; the Poiseuille part is not counted).
    let g = contact_friction(&input(&x, &p, &h, &t, 0.0)).expect("friction");
    assert_eq!(g.friction_n, 0.0);
    assert_eq!(g.power_loss_w, 0.0);
}

#[test]
fn errors_name_the_input() {
    let x = grid(5, 1e-5);
    let p = vec![0.0; 5];
    let h = vec![1e-6; 4];
    let t = vec![313.15; 5];
    let e = contact_friction(&input(&x, &p, &h, &t, 0.1))
        .unwrap_err()
        .to_string();
    assert!(e.contains("film_m") && e.contains('4'), "{e}");
    let h = vec![-1e-6; 5];
    let e = contact_friction(&input(&x, &p, &h, &t, 0.1))
        .unwrap_err()
        .to_string();
    assert!(e.contains("film_m") && e.contains("≥ 0 m"), "{e}");
    let h = vec![1e-6; 5];
    let t = vec![100.0; 5];
    let e = contact_friction(&input(&x, &p, &h, &t, 0.1))
        .unwrap_err()
        .to_string();
    assert!(e.contains("temperature_k") && e.contains("138"), "{e}");
}
