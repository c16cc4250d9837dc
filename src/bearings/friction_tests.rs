//! Every shipped deck's JSON `friction` (issue 28 item 4): the power identity, the sum of
//! the mechanisms, and each system's own heat or loss total it restates.

use serde_json::Value;

use crate::bearings::{load_file, RunOptions};
use crate::numerics::cancel::Cancel;

fn json_of(deck: &str) -> Value {
    json_with(deck, true)
}

/// The JSON of `deck`; `skip_transient: false` runs the time simulations (the
/// cylindrical roller's friction comes from its tribodynamics, which only runs then).
fn json_with(deck: &str, skip_transient: bool) -> Value {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("decks")
        .join(deck);
    let case = load_file(&path, &[]).unwrap_or_else(|e| panic!("{deck}: {e}"));
    case.solve(RunOptions { skip_transient }, Cancel::NONE)
        .unwrap_or_else(|e| panic!("{deck}: {e}"))
        .json()
}

fn num(v: &Value, ptr: &str) -> f64 {
    v.pointer(ptr)
        .and_then(Value::as_f64)
        .unwrap_or_else(|| panic!("{ptr} missing in {v}"))
}

/// The shared checks: Σ by_mechanism = power_w (1e-12 relative: one sum in another order)
/// and P = M·|ω_i − ω_o| (1e-12: one division).
fn identity(deck: &str, v: &Value) -> (f64, f64) {
    let f = &v["friction"];
    let by: f64 = f["by_mechanism"]
        .as_object()
        .unwrap_or_else(|| panic!("{deck}: no by_mechanism"))
        .values()
        .filter_map(Value::as_f64)
        .sum();
    let p = num(v, "/friction/power_w");
    let m = num(v, "/friction/torque_nm");
    let w = num(v, "/friction/relative_speed_rad_s");
    assert!(p > 0.0 && m > 0.0 && w > 0.0, "{deck}: {f}");
    assert!((by - p).abs() <= 1e-12 * p, "{deck}: Σ {by} vs {p}");
    assert!((m * w - p).abs() <= 1e-12 * p, "{deck}: {m}·{w} vs {p}");
    (p, m)
}

/// The spherical roller's friction restates its `heat` (kept as it was): power and
/// torque to 1e-12 (the same four terms summed in the same order, the same division).
#[test]
fn spherical_friction_is_its_heat() {
    for deck in [
        "aerospace.toml",
        "aerospace_si.toml",
        "industrial.toml",
        "radial_si.toml",
    ] {
        let v = json_of(deck);
        let (p, m) = identity(deck, &v);
        let h = num(&v, "/heat/total_w");
        let t = num(&v, "/heat/friction_torque_nm");
        assert!((p - h).abs() <= 1e-12 * h, "{deck}: {p} vs {h}");
        assert!((m - t).abs() <= 1e-12 * t, "{deck}: {m} vs {t}");
        for k in [
            "inner_contacts",
            "outer_contacts",
            "cage_rails",
            "viscous_drag",
        ] {
            let a = num(&v, &format!("/friction/by_mechanism/{k}"));
            let b = num(&v, &format!("/heat/{k}_w"));
            assert_eq!(a, b, "{deck}: {k}");
        }
    }
}

/// The ball's friction is its heat by race: Σ mechanisms = `heat.total_w` =
/// N·`per_ball_w` to 1e-9 (per-ball sums regrouped by race), and with race control the
/// spin heat `race_control_w`.
#[test]
fn ball_friction_is_its_heat() {
    for deck in ["chen_a.toml", "chen_b.toml"] {
        let v = json_of(deck);
        let (p, _) = identity(deck, &v);
        let total = num(&v, "/heat/total_w");
        let n = v["balls"].as_array().map_or(0, Vec::len) as f64;
        assert!((p - total).abs() <= 1e-9 * total, "{deck}: {p} vs {total}");
        assert!((p - n * num(&v, "/heat/per_ball_w")).abs() <= 1e-9 * total);
        if v["dynamics"]["method"] == "race-control" {
            assert!((p - num(&v, "/heat/race_control_w")).abs() <= 1e-9 * total);
            let inner: f64 = v["balls"]
                .as_array()
                .map(|b| b.iter().map(|b| num(b, "/inner/spin_heat_w")).sum())
                .unwrap_or(0.0);
            assert_eq!(num(&v, "/friction/by_mechanism/inner_spin"), inner);
        }
    }
}

/// The double row's friction is its losses under their names: power and torque to 1e-12
/// (the seven terms in `total_w`'s order, the same division).
#[test]
fn double_row_friction_is_its_losses() {
    let v = json_of("srb_22308.toml");
    let (p, m) = identity("srb_22308", &v);
    assert!((p - num(&v, "/losses/total_w")).abs() <= 1e-12 * p);
    assert!((m - num(&v, "/losses/friction_torque_nm")).abs() <= 1e-12 * m);
    for k in [
        "raceway_inner",
        "raceway_outer",
        "guide_ring",
        "cage_pockets",
        "cage_land",
        "skew",
        "drag",
    ] {
        assert_eq!(
            num(&v, &format!("/friction/by_mechanism/{k}")),
            num(&v, &format!("/losses/{k}_w")),
            "{k}"
        );
    }
}

/// The cylindrical roller's `friction` keeps every key it had (a contract) and gains the
/// shared ones; the boundary mechanisms' powers are in the ratio of the boundary forces
/// (one sliding speed for every contact).
#[test]
fn cylindrical_friction_keeps_its_keys_and_adds_the_mechanisms() {
    // crb_nasa210 runs no tribodynamics (`dynamics.revolutions = 0`): no friction.
    for deck in ["crb_truck.toml"] {
        let v = json_with(deck, false);
        let f = &v["friction"];
        for k in [
            "boundary_n",
            "coefficient",
            "inner_n",
            "outer_n",
            "power_w",
            "total_n",
            "viscous_n",
            "note",
        ] {
            assert!(f.get(k).is_some(), "{deck}: friction.{k} dropped");
        }
        let (p, _) = identity(deck, &v);
        let b = num(&v, "/friction/by_mechanism/inner_boundary")
            + num(&v, "/friction/by_mechanism/outer_boundary");
        let expect = p * num(&v, "/friction/boundary_n") / num(&v, "/friction/total_n");
        assert!((b - expect).abs() <= 1e-12 * p, "{deck}: {b} vs {expect}");
        let inner = num(&v, "/friction/by_mechanism/inner_boundary")
            + num(&v, "/friction/by_mechanism/inner_viscous");
        let expect = p * num(&v, "/friction/inner_n") / num(&v, "/friction/total_n");
        assert!(
            (inner - expect).abs() <= 1e-12 * p,
            "{deck}: {inner} vs {expect}"
        );
    }
}

/// Palmgren's friction moment M = M₀ + M₁, N·m (Harris & Kotzalas, Essential Concepts
/// of Bearing Technology, 5th ed., §12.3): M₀ = 10⁻⁷·f₀·(ν·n)^(2/3)·d_m³ N·mm for
/// ν·n ≥ 2000 (ν cSt, n rpm, d_m mm), M₁ = f₁·P₁·d_m N·mm.
fn palmgren_nm(f0: f64, nu_cst: f64, n_rpm: f64, dm_mm: f64, f1: f64, p1_n: f64) -> (f64, f64) {
    let m0 = 1e-7 * f0 * (nu_cst * n_rpm).powf(2.0 / 3.0) * dm_mm.powi(3);
    let m1 = f1 * p1_n * dm_mm;
    (m0 * 1e-3, m1 * 1e-3)
}

/// The friction torque of `chen_b` and `crb_truck` against Palmgren's empirical moment.
///
/// chen_b (7018 size, 60°, 1000 N axial, 9 500 rpm, SAE 30 at 40 °C: ν = 0.071/800 =
/// 88.75 cSt, d_m = 115 mm): f₀ = 2 (single-row angular-contact ball, Harris Table
/// 12.1 oil bath), f₁ = 0.001·(P₀/C₀)^0.33 with P₀/C₀ ≈ 1000/60 000 (C₀ of a 7018 ≈
/// 60 kN) ⇒ f₁ ≈ 2.6e-4, P₁ = F_a − 0.1·F_r = 1000 N. The model's friction is the
/// spin sliding alone (no hysteresis, no drag: `angular_ball::friction`), so it must lie
/// between a fraction of the load term M₁ and the whole M₀ + M₁.
///
/// crb_truck (d_m = (50 + 75.4)/2 = 62.7 mm, 1 995.8 rpm, inlet 100 °C: η = 0.0499·
/// e^(−0.026·60) Pa·s ⇒ ν = 12.6 cSt, P₁ = F_r + M·g = 1 500 + 490.5 N): f₀ = 2,
/// f₁ = 3e-4 (cylindrical roller with cage, Harris Table 12.2). The seed's friction is
/// at a prescribed slide of 0.589 m/s at every contact (seed 003 Table 3), a gross
/// sliding far beyond a rolling bearing's micro-slip, so its torque is above Palmgren's.
#[test]
fn friction_torque_against_palmgren() {
    let ball = json_of("chen_b.toml");
    let m_ball = num(&ball, "/friction/torque_nm");
    let (m0, m1) = palmgren_nm(
        2.0,
        0.071 / 800.0 * 1e6,
        9500.0,
        115.0,
        0.001 * (1000.0f64 / 60_000.0).powf(0.33),
        1000.0,
    );
    let crb = json_with("crb_truck.toml", false);
    let m_crb = num(&crb, "/friction/torque_nm");
    let nu = 0.0499 * (-0.026f64 * 60.0).exp() / 829.3 * 1e6;
    let (c0, c1) = palmgren_nm(2.0, nu, 1995.8, 62.7, 3e-4, 1990.5);
    // Measured (rollbench-48ae4b8 heat and friction power over ω): chen_b 244.88 W /
    // 994.84 rad/s = 0.246 N·m against M₁ = 0.030 and M₀ + M₁ = 2.74 N·m (oil bath; the
    // deck's 0.1 l/min circulation churns far less, which is why the band's top is the
    // whole M₀ + M₁); crb_truck 660.84 W / 209.0 rad/s = 3.16 N·m against
    // M₀ + M₁ = 0.080 N·m, 40 times: the seed's prescribed 0.589 m/s slide.
    assert!(
        m1 <= m_ball && m_ball <= m0 + m1,
        "chen_b: {m_ball} vs M0 {m0} M1 {m1}"
    );
    let ratio = m_crb / (c0 + c1);
    assert!(
        (10.0..=100.0).contains(&ratio),
        "crb_truck: {m_crb} N·m = {ratio} × Palmgren (M0 {c0}, M1 {c1})"
    );
}
