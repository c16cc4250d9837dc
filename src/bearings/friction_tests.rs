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

/// The ball's sliding mechanisms are its heat by race: Σ sliding = `heat.total_w` =
/// N·`per_ball_w` to 1e-9 (per-ball sums regrouped by race), and with race control the
/// spin heat `race_control_w`; the rolling-resistance mechanisms are the contacts'
/// `rolling_resistance_w` summed by race (1e-12); nothing else without a `[cage]`.
#[test]
fn ball_friction_is_its_heat_and_its_rolling_resistance() {
    for deck in ["chen_a.toml", "chen_b.toml"] {
        let v = json_of(deck);
        let (p, _) = identity(deck, &v);
        let total = num(&v, "/heat/total_w");
        let n = v["balls"].as_array().map_or(0, Vec::len) as f64;
        let race_sum = |ptr: &str| -> f64 {
            v["balls"]
                .as_array()
                .map(|b| b.iter().map(|b| num(b, ptr)).sum())
                .unwrap_or(0.0)
        };
        let rolling = [
            ("inner_rolling_resistance", "/inner/rolling_resistance_w"),
            ("outer_rolling_resistance", "/outer/rolling_resistance_w"),
        ];
        let mut rolling_w = 0.0;
        for (name, ptr) in rolling {
            let m = num(&v, &format!("/friction/by_mechanism/{name}"));
            let want = race_sum(ptr);
            assert!(
                m > 0.0 && (m - want).abs() <= 1e-12 * want,
                "{deck}: {name}"
            );
            rolling_w += m;
        }
        let sliding = p - rolling_w;
        assert!(
            (sliding - total).abs() <= 1e-9 * total,
            "{deck}: {sliding} vs {total}"
        );
        assert!((sliding - n * num(&v, "/heat/per_ball_w")).abs() <= 1e-9 * total);
        if v["dynamics"]["method"] == "race-control" {
            assert!((sliding - num(&v, "/heat/race_control_w")).abs() <= 1e-9 * total);
            assert_eq!(
                num(&v, "/friction/by_mechanism/inner_spin"),
                race_sum("/inner/spin_heat_w")
            );
        }
        let names = v["friction"]["by_mechanism"].as_object().unwrap().len();
        assert_eq!(names, 4, "{deck}: {}", v["friction"]);
    }
}

/// The `[cage]` section adds exactly Palmgren's churning moment M₀ (computed here in its
/// published N·mm form, `palmgren_nm`) as `viscous_drag`, and a land-guided cage's rails
/// exactly Petroff's shear f·ΔΩ·D/2 with f = π·η·W·D²·ΔΩ/dc (seed 000 eqs. 9.3–9.4, by
/// hand) at the cage's slip over the guiding ring; every other mechanism is unchanged
/// (bit for bit): ball (chen_b) and tapered (trb_afapl_lubricated). 1e-12: the same
/// formulas in another order.
#[test]
fn cage_section_adds_palmgren_drag_and_petroff_rails() {
    let cage_keys: &[(&str, &str)] = &[
        ("cage.drag_factor", "2"),
        ("cage.rail_width", "0.01"),
        ("cage.mean_diameter", "0.12"),
        ("cage.diametral_clearance", "5e-4"),
        ("cage.guided_by", "outer"),
    ];
    for (deck, si) in [("chen_b.toml", true), ("trb_afapl_lubricated.toml", false)] {
        let base = json_of(deck);
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("decks")
            .join(deck);
        // US decks take lengths in inches: the same metres written in inches.
        let sets: Vec<String> = cage_keys
            .iter()
            .map(|(k, v)| {
                let length = *k != "cage.drag_factor" && *k != "cage.guided_by";
                match length && !si {
                    true => format!("{k}={}", v.parse::<f64>().unwrap() / crate::units::INCH_M),
                    false => format!("{k}={v}"),
                }
            })
            .collect();
        // Without the deck's thermal network: it has no node for the new heat sources,
        // and the network refuses heat with nowhere to go (tested in `thermal`).
        let text = std::fs::read_to_string(&path).unwrap();
        let text = &text[..text.find("\n[thermal]").unwrap_or(text.len())];
        let case =
            crate::bearings::load_case(text, deck, &sets).unwrap_or_else(|e| panic!("{deck}: {e}"));
        let v = case
            .solve(
                RunOptions {
                    skip_transient: true,
                },
                Cancel::NONE,
            )
            .unwrap_or_else(|e| panic!("{deck}: {e}"))
            .json();
        identity(deck, &v);
        let by = v["friction"]["by_mechanism"].as_object().unwrap();
        for (k, w) in base["friction"]["by_mechanism"].as_object().unwrap() {
            assert_eq!(by.get(k), Some(w), "{deck}: {k} moved");
        }
        let si_of = |k: &str| case.field_si(k).unwrap_or_else(|| panic!("{deck}: {k}"));
        let (w_i, w_o) = (
            si_of("operating.inner_speed"),
            si_of("operating.outer_speed"),
        );
        let rho = si_of("lubricant.density");
        let dm = si_of("geometry.pitch_diameter");
        // The ball runs at the deck's viscosity; the tapered at its inlet temperature's.
        let (eta, cage) = if si {
            (
                si_of("lubricant.viscosity"),
                num(&v, "/speeds/cage_rpm") * std::f64::consts::PI / 30.0,
            )
        } else {
            (
                num(&v, "/film/viscosity_pa_s"),
                num(&v, "/speeds/cage_rad_s"),
            )
        };
        let n_rpm = (w_i - w_o).abs() * 30.0 / std::f64::consts::PI;
        let (m0, _) = palmgren_nm(2.0, eta / rho * 1e6, n_rpm, dm * 1e3, 0.0, 0.0);
        let drag = num(&v, "/friction/by_mechanism/viscous_drag");
        let want = m0 * (w_i - w_o).abs();
        assert!(
            (drag - want).abs() <= 1e-12 * want,
            "{deck}: {drag} vs {want}"
        );
        let slip = (cage - w_o).abs();
        let f = std::f64::consts::PI * eta * 0.01 * 0.12 * 0.12 * slip / 5e-4;
        let rails = num(&v, "/friction/by_mechanism/cage_rails");
        let want = f * slip * 0.06;
        assert!(
            (rails - want).abs() <= 1e-9 * want,
            "{deck}: {rails} vs {want}"
        );
        eprintln!("{deck}: viscous_drag {drag:.2} W, cage_rails {rails:.3} W");
    }
}

/// A land-guided cage with a missing rail key is refused naming the keys it needs.
#[test]
fn cage_rails_need_every_rail_key() {
    for deck in ["chen_b.toml", "trb_afapl_lubricated.toml"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("decks")
            .join(deck);
        let e = load_file(&path, &["cage.rail_width=0.5".to_string()])
            .err()
            .unwrap_or_else(|| panic!("{deck}: accepted"))
            .to_string();
        assert!(
            e.contains("cage.rail_width")
                && e.contains("cage.mean_diameter")
                && e.contains("cage.diametral_clearance"),
            "{deck}: {e}"
        );
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

/// The ball's EHL rolling resistance against Palmgren's load-independent moment M₀ (the
/// published empirical moment whose (ν·n)^(2/3) the Goksem–Hargreaves fit's (η·u)^0.658
/// mirrors): chen_b (SAE 30 at 40 °C, 9 500 rpm, d_m 115 mm) gives a rolling-resistance
/// torque between 0.2 and 1 × M₀ with f₀ = 2 (Harris's oil-bath value for a single-row
/// angular-contact ball bearing; M₀ also holds the churning, so the contacts alone lie
/// below it, and oil mist's f₀ = 1 halves it: the band's bottom). And the fit's own law:
/// doubling the viscosity multiplies each race's rolling power by 2^0.658 (1e-9: race
/// control's loads do not depend on η with the deck's Coulomb traction).
#[test]
fn ball_rolling_resistance_against_palmgren() {
    let v = json_of("chen_b.toml");
    let rolling = num(&v, "/friction/by_mechanism/inner_rolling_resistance")
        + num(&v, "/friction/by_mechanism/outer_rolling_resistance");
    let w = num(&v, "/friction/relative_speed_rad_s");
    let (m0, _) = palmgren_nm(2.0, 0.071 / 800.0 * 1e6, 9500.0, 115.0, 0.0, 0.0);
    let ratio = rolling / w / m0;
    // Measured: 1 161.7 W / 994.84 rad/s = 1.168 N·m against M₀ = 2.71 N·m: 0.43.
    assert!((0.2..=1.0).contains(&ratio), "{ratio}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("decks/chen_b.toml");
    let case = load_file(&path, &["lubricant.viscosity=0.142".to_string()]).unwrap();
    let v2 = case
        .solve(
            RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .unwrap()
        .json();
    for name in ["inner_rolling_resistance", "outer_rolling_resistance"] {
        let ptr = format!("/friction/by_mechanism/{name}");
        let r = num(&v2, &ptr) / num(&v, &ptr);
        assert!((r / 2f64.powf(0.658) - 1.0).abs() < 1e-9, "{name}: {r}");
    }
}
