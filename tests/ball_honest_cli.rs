//! The ball bearing's results are honest (issue 24, items 8, 9, 10, 12, 13), through the
//! real binary: a non-finite result is an error naming its inputs, an absurd one a
//! warning that names it, a failed skid search a `skid.reason`, and the quasi-static
//! method solves constant traction.

mod common;
use common::deck;

/// `rollbench run DECK ARGS…`: (exit code, stdout, stderr).
fn run(name: &str, extra: &[&str]) -> (i32, String, String) {
    let d = deck(name);
    let mut args = vec!["run", d.as_str()];
    args.extend_from_slice(extra);
    common::run(&args)
}

fn json(name: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["--format", "json"];
    args.extend_from_slice(extra);
    let (code, out, err) = run(name, &args);
    assert_eq!(code, 0, "{err}");
    match serde_json::from_str(&out) {
        Ok(v) => v,
        Err(e) => panic!("{e}: {out}"),
    }
}

fn warnings(v: &serde_json::Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|w| w.as_str().map(str::to_string))
                .collect()
        })
        .unwrap_or_default()
}

/// Item 8: a density so small that ρ·c_p·Q underflows made the bulk temperature
/// infinite (JSON null, "inf °C", exit 0); now the run fails naming the keys. 1e-30 kg/m³
/// gave 1.8e34 °C as a result; now it is a warning on the JSON and the text report.
#[test]
fn non_finite_or_absurd_bulk_temperature_is_not_a_quiet_result() {
    let (code, out, err) = run("chen_a.toml", &["--set", "lubricant.density=5e-324"]);
    assert_ne!(code, 0, "{out}");
    assert!(err.contains("not finite"), "{err}");
    assert!(err.contains("lubricant.density = 5e-324"), "{err}");
    assert!(err.contains("lubricant.flow_rate_l_min"), "{err}");
    assert!(!out.contains("inf"), "{out}");

    let v = json("chen_a.toml", &["--set", "lubricant.density=1e-30"]);
    let w = warnings(&v);
    assert!(
        w.iter()
            .any(|w| w.starts_with("bulk temperature") && w.contains("exceeds 400 °C")),
        "{w:?}"
    );
    let (code, text, _) = run("chen_a.toml", &["--set", "lubricant.density=1e-30"]);
    assert_eq!(code, 0);
    assert!(text.contains("exceeds 400 °C"), "{text}");
    // The shipped deck stays below the bound: no warning.
    assert!(warnings(&json("chen_a.toml", &[])).is_empty());
}

/// Item 9: a time simulation that has not settled says so, with the amplitude and the
/// orbits it would need (`dynamics.orbits`); under a radial load it tells the transient
/// from the periodic response.
#[test]
fn unsettled_time_simulation_is_warned() {
    let ts = [
        "--set",
        "dynamics.method=time-simulation",
        "--set",
        "dynamics.orbits=3",
        "--set",
        "dynamics.slices=5",
    ];
    let v = json("chen_b.toml", &ts);
    assert_eq!(v["dynamics"]["steady"], false);
    let w = warnings(&v);
    let s = w
        .iter()
        .find(|w| w.starts_with("time simulation not settled after 3 orbits"))
        .unwrap_or_else(|| panic!("{w:?}"));
    assert!(s.contains("oscillates by"), "{s}");
    assert!(s.contains("dynamics.orbits"), "{s}");
    assert!(s.contains("needs about"), "{s}");

    let mut radial = ts.to_vec();
    radial.extend(["--set", "operating.radial_load=500"]);
    let w = warnings(&json("chen_b.toml", &radial));
    let s = w
        .iter()
        .find(|w| w.starts_with("time simulation not settled"))
        .unwrap_or_else(|| panic!("{w:?}"));
    assert!(s.contains("periodic response to the radial load"), "{s}");
}

/// Item 10: a negative contact angle and a cage turning against the shaft are named.
#[test]
fn absurd_kinematics_are_warned() {
    let v = json(
        "chen_a.toml",
        &[
            "--set",
            "operating.radial_load=500",
            "--set",
            "operating.inner_speed=200000",
            "--set",
            "kinematics.race_control=inner",
        ],
    );
    let w = warnings(&v);
    assert!(
        w.iter()
            .any(|w| w.starts_with("outer contact angle -3.") && w.contains("below 0°")),
        "{w:?}"
    );

    let v = json(
        "chen_b.toml",
        &[
            "--set",
            "operating.inner_speed=30000",
            "--set",
            "operating.radial_load=500",
            "--set",
            "operating.preload_mode=force",
            "--set",
            "kinematics.race_control=inner",
            "--set",
            "geometry.ball_count=7",
        ],
    );
    let w = warnings(&v);
    let cage = v["balls"]
        .as_array()
        .map(|b| {
            b.iter()
                .filter_map(|b| b["cage_rpm"].as_f64())
                .fold(f64::INFINITY, f64::min)
        })
        .unwrap_or(0.0);
    assert!(cage < 0.0, "{cage}");
    assert!(
        w.iter().any(|w| w.starts_with("cage speed -")
            && w.contains("turning against the shaft")
            && w.contains("kinematics.race_control")),
        "{w:?}"
    );
    // Its heat is beyond what the oil carries away: said too.
    assert!(w.iter().any(|w| w.starts_with("bulk temperature")), "{w:?}");
}

/// Item 12: the quasi-static method with constant traction solves on both decks at
/// µ = 0, 0.054 and 0.2 (it failed with "singular Jacobian" or "stalled"); µ = 0 makes
/// no heat.
#[test]
fn quasi_static_solves_constant_traction() {
    for d in ["chen_a.toml", "chen_b.toml"] {
        for mu in ["0", "0.054", "0.2"] {
            let m = format!("traction.mu={mu}");
            let v = json(
                d,
                &[
                    "--set",
                    "dynamics.method=quasi-static",
                    "--set",
                    "traction.curve=constant",
                    "--set",
                    &m,
                ],
            );
            let h = v["heat"]["total_w"].as_f64().unwrap_or(f64::NAN);
            assert!(h.is_finite() && h >= 0.0, "{d} µ {mu}: {h}");
            if mu == "0" {
                assert_eq!(h, 0.0, "{d}");
            } else {
                assert!(h > 0.0, "{d} µ {mu}");
            }
        }
    }
}

/// Item 13: a skid search whose load solve fails (a token force-held preload at rest:
/// no equilibrium at 500 rpm) no longer fails the run: `skid.reason` says it, in the
/// JSON and the text report.
#[test]
fn failed_skid_search_is_a_reason_not_a_failure() {
    let args = [
        "--set",
        "operating.axial_load=1e-6",
        "--set",
        "operating.inner_speed=0",
        "--set",
        "operating.preload_mode=force",
    ];
    let v = json("chen_b.toml", &args);
    assert!(v["skid"]["threshold_rpm"].is_null());
    let r = v["skid"]["reason"].as_str().unwrap_or("");
    assert!(r.starts_with("the search failed"), "{r}");
    assert!(r.contains("500.0000 rpm"), "{r}");
    let (code, text, err) = run("chen_b.toml", &args);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.contains("SKIDDING THRESHOLD  not found: the search failed"),
        "{text}"
    );
}

/// A lubricant without a pressure–viscosity coefficient has no Hamrock–Dowson film: the
/// run says so in `warnings` instead of leaving `film_temperature_rise_c: null` unexplained
/// (found by benches/hostile.py on chen_b).
#[test]
fn zero_pressure_viscosity_is_warned() {
    let (code, out, err) = run(
        "chen_b.toml",
        &[
            "--format",
            "json",
            "--set",
            "lubricant.pressure_viscosity=0",
        ],
    );
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap_or_default();
    assert!(
        j["balls"][0]["inner"]["film_temperature_rise_c"].is_null(),
        "{out}"
    );
    let w = j["warnings"].to_string();
    assert!(
        w.contains("no EHD film") && w.contains("lubricant.pressure_viscosity"),
        "{w}"
    );
    // The shipped deck's α gives a film and no such warning.
    let (code, out, err) = run("chen_b.toml", &["--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("no EHD film"));
}
