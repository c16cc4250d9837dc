//! The tapered roller system through the real binary (assert_cmd): `run` in text, JSON
//! and CSV on the shipped sample deck, `--set` overrides, typed failures, `check` on bad
//! decks and the template.

use assert_cmd::Command;

fn bin() -> Command {
    match Command::cargo_bin("rollbench") {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    }
}

fn deck() -> String {
    format!("{}/decks/trb_afapl.toml", env!("CARGO_MANIFEST_DIR"))
}

const LBF_N: f64 = 4.448_221_615_260_5;
const INCH_M: f64 = 0.0254;

fn run_json(extra: &[&str]) -> serde_json::Value {
    let d = deck();
    let mut args = vec!["run", d.as_str(), "--format", "json"];
    args.extend_from_slice(extra);
    let out = bin().args(&args).output().unwrap_or_else(|e| panic!("{e}"));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}"))
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

/// The JSON contract fields of issue 17 and the sample's reference values: τ/2 = 0.800°,
/// cage 988 rad/s, F_c = 77.6 lbf (1e-3), P₁ = 320.23 lbf on all 37 rollers (2e-5: the
/// reference's rounding), K_xx/K_zz = cot²β/2 = 7.299 (5e-4), the finite-difference check
/// within 1e-5 of the row scale.
#[test]
fn run_json_has_the_contract_fields_and_the_sample_values() {
    let v = run_json(&[]);
    assert_eq!(v["type"], "tapered-roller");
    let g = &v["geometry"];
    for k in [
        "cone_half_angle_deg",
        "roller_mass_kg",
        "polar_inertia_kg_m2",
        "transverse_inertia_kg_m2",
        "flange_lever_arm_m",
    ] {
        assert!(num(&g[k]).is_finite(), "geometry.{k}");
    }
    assert!((num(&g["cone_half_angle_deg"]) / 0.8 - 1.0).abs() < 1e-3);
    assert!((num(&v["speeds"]["cage_rad_s"]) / 988.0 - 1.0).abs() < 1e-3);
    assert!(num(&v["speeds"]["roller_spin_rad_s"]).is_finite());
    assert!((num(&v["centrifugal_force_n"]) / LBF_N / 77.6 - 1.0).abs() < 1e-3);
    assert!(num(&v["gyroscopic_moment_nm"]).is_finite());
    let rings = &v["rings"];
    assert_eq!(rings["displacement_m"].as_array().map(|a| a.len()), Some(3));
    assert_eq!(rings["rotation_rad"].as_array().map(|a| a.len()), Some(2));
    assert_eq!(
        rings["reaction_moment_nm"].as_array().map(|a| a.len()),
        Some(2)
    );
    let rollers = v["rollers"].as_array().cloned().unwrap_or_default();
    assert_eq!(rollers.len(), 37);
    for r in &rollers {
        for k in [
            "index",
            "azimuth_deg",
            "outer_load_n",
            "inner_load_n",
            "flange_load_n",
            "outer_moment_nm",
            "inner_moment_nm",
            "max_stress_outer_pa",
            "max_stress_inner_pa",
        ] {
            assert!(num(&r[k]).is_finite(), "rollers[].{k}");
        }
        assert_eq!(r["state"], "both-races");
        assert!(r["outer_edge_loaded"].is_boolean() && r["inner_edge_loaded"].is_boolean());
        // 21 slices on each race's contact extent.
        assert_eq!(r["slices"].as_array().map(|a| a.len()), Some(42));
        assert!((num(&r["outer_load_n"]) / LBF_N / 320.23 - 1.0).abs() < 2e-5);
    }
    let s = &v["stiffness"];
    let k = |i: usize, j: usize| num(&s["matrix"][i][j]);
    assert_eq!(s["rows"].as_array().map(|a| a.len()), Some(5));
    assert_eq!(s["columns"].as_array().map(|a| a.len()), Some(5));
    assert!((k(0, 0) / k(2, 2) / 7.299 - 1.0).abs() < 5e-4);
    assert!(num(&s["finite_difference_max_rel"]) < 1e-5);
    assert!(num(&s["asymmetry_max"]) < 0.01);
    assert!(num(&s["load_centre_offset_m"]) / INCH_M > 0.6);
    assert!(v["residuals"].is_object() && v["stats"].is_object());
}

/// Load Condition 2 by `--set` (deck units): the radial load breaks the thrust symmetry
/// (K_xx ≠ K_yy, x–z coupling) and is balanced (1e-6 of the load).
#[test]
fn radial_load_by_set() {
    let v = run_json(&["--set", "operating.radial_load=700"]);
    let s = &v["stiffness"]["matrix"];
    // Measured: K_xx/K_yy − 1 = −6e-4 and K_xz/K_zz = 0.09 (1e-9 and 0 under pure thrust).
    assert!((num(&s[0][0]) / num(&s[1][1]) - 1.0).abs() > 1e-4);
    assert!(num(&s[0][2]).abs() > 1e-2 * num(&s[2][2]));
    let fx = num(&v["rings"]["reaction_force_n"][0]) / LBF_N;
    assert!((fx - 700.0).abs() < 1e-6 * 3000.0, "{fx}");
}

/// The text report is in the deck's units: lbf, in, lbf/in, in·lbf/rad.
#[test]
fn run_text_in_deck_units() {
    let out = bin()
        .args(["run", &deck()])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for needle in [
        "tapered roller",
        "320.232",
        "lbf/in",
        "in·lbf/rad",
        "both-races",
        "Stiffness matrix",
        "Damping: not computed",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
}

/// CSV: the `rollers` table, one row per roller.
#[test]
fn run_csv_rollers_table() {
    let out = bin()
        .args(["run", &deck(), "--format", "csv"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        // The shipped columns unchanged, then the common `number` (issue 30 item 10).
        Some("index,azimuth_deg,state,outer_load_n,inner_load_n,flange_load_n,outer_moment_nm,inner_moment_nm,outer_edge_loaded,inner_edge_loaded,max_stress_outer_pa,max_stress_inner_pa,number")
    );
    assert_eq!(lines.count(), 37);
}

/// A negative thrust unseats the bearing: the run fails with a message that says so.
#[test]
fn negative_thrust_is_a_typed_failure() {
    let out = bin()
        .args(["run", &deck(), "--set", "operating.axial_load=-10"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(!out.status.success());
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(msg.contains("unseats"), "{msg}");
}

/// `check` on bad decks: an unknown key and an out-of-range value, each with the file,
/// line and (for the range) the allowed range in deck units; exit 1.
#[test]
fn check_rejects_bad_decks_with_location() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let text = std::fs::read_to_string(deck()).unwrap_or_default();
    let line = text
        .lines()
        .position(|l| l.starts_with("roller_count"))
        .map(|i| i + 1)
        .unwrap_or(0);
    for (name, bad, needle) in [
        (
            "unknown.toml",
            text.replace(
                "roller_count = 37",
                "roller_count = 37\nrollr_diameter = 0.3",
            ),
            "rollr_diameter".to_string(),
        ),
        (
            "range.toml",
            text.replace("roller_count = 37", "roller_count = 2"),
            format!("range.toml:{line}:"),
        ),
    ] {
        let p = dir.path().join(name);
        std::fs::write(&p, bad).unwrap_or_else(|e| panic!("{e}"));
        let out = bin()
            .args(["check", &p.to_string_lossy()])
            .output()
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(out.status.code(), Some(1), "{name}");
        let msg = String::from_utf8_lossy(&out.stderr);
        assert!(msg.contains(name) && msg.contains(&needle), "{name}: {msg}");
    }
}

/// The template of the system parses back through `check`.
#[test]
fn template_checks_clean() {
    let out = bin()
        .args(["template", "--type", "tapered-roller", "--units", "si"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(out.status.success());
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let p = dir.path().join("t.toml");
    std::fs::write(&p, &out.stdout).unwrap_or_else(|e| panic!("{e}"));
    let out = bin()
        .args(["check", &p.to_string_lossy()])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `rollbench stiffness` (issue 17): the matrix alone, in the deck's units as text, the
/// JSON `stiffness` object, or a 5×5 CSV in SI; `--check-fd` adds the finite-difference
/// gap (below 1e-5 of the row scale, the bound); a deck without a stiffness
/// matrix is refused with exit 1.
#[test]
fn stiffness_subcommand() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_rollbench"))
            .args(args)
            .output()
            .expect("runs")
    };
    let out = run(&["stiffness", "decks/trb_afapl.toml"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("Stiffness matrix") && text.contains("lbf/in"),
        "{text}"
    );
    let out = run(&[
        "stiffness",
        "decks/trb_afapl.toml",
        "--check-fd",
        "--format",
        "json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["type"], "tapered-roller");
    let m = v["stiffness"]["matrix"].as_array().expect("matrix");
    assert_eq!(m.len(), 5);
    assert!(m.iter().all(|r| r.as_array().is_some_and(|r| r.len() == 5)));
    let fd = v["stiffness"]["finite_difference_max_rel"]
        .as_f64()
        .expect("the finite-difference gap");
    assert!(fd < 1e-5, "{fd}");
    let out = run(&["stiffness", "decks/trb_afapl.toml", "--format", "csv"]);
    let csv = String::from_utf8_lossy(&out.stdout);
    assert_eq!(csv.lines().count(), 6, "{csv}");
    assert!(
        csv.starts_with("row,x,y,z,theta_x,theta_y,unit_lineal,unit_angular\nF_x,"),
        "{csv}"
    );
    // In the deck's units (issue 17): K_xx in lbf/in = the JSON's N/m ÷ (4.4482216152605
    // N/lbf ÷ 0.0254 m/in), to the CSV's shortest round-trip digits (1e-12).
    let kxx_si = m[0][0].as_f64().expect("K_xx");
    let kxx_us: f64 = csv
        .lines()
        .nth(1)
        .and_then(|l| l.split(',').nth(1))
        .and_then(|c| c.parse().ok())
        .expect("F_x,x");
    let want = kxx_si / (4.4482216152605 / 0.0254);
    assert!((kxx_us / want - 1.0).abs() < 1e-12, "{kxx_us} vs {want}");
    assert!(
        csv.lines()
            .nth(1)
            .is_some_and(|l| l.ends_with(",lbf/in,lbf/rad")),
        "{csv}"
    );
    assert!(
        csv.lines()
            .nth(4)
            .is_some_and(|l| l.ends_with(",in·lbf/in,in·lbf/rad")),
        "{csv}"
    );
    // Every system has a stiffness matrix now (issue 29 item 3): the spherical roller's
    // says why its tilts are free.
    let out = run(&["stiffness", "decks/aerospace.toml"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("outer raceway is a sphere"));
}

/// Issue 17's sweep `--set-range operating.inner_speed=0:50000:x26` under Load Condition 1:
/// a row for every point, no NaN anywhere; the 21 points up to 40 000 rpm solve (every
/// roller on the cone) and the 5 above the limit are the typed no-equilibrium error,
/// which names the limiting cone speed (41 143 rpm: the flanges' centrifugal thrust
/// equals the 3 000 lbf there; proof in `BearingError::FlangeThrustExceedsLoad`).
#[test]
fn speed_sweep_to_50000_rpm_has_rows_everywhere() {
    let d = deck();
    let out = bin()
        .args([
            "sweep",
            d.as_str(),
            "--set-range",
            "operating.inner_speed=0:50000:x26",
        ])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(!text.contains("NaN") && !text.contains("nan"), "{text}");
    let limit_rows = text
        .lines()
        .filter(|l| l.contains("no equilibrium exists") && l.contains("41143 rpm"))
        .count();
    assert_eq!(limit_rows, 5, "{text}");
    assert!(text.contains("5 of 26 points failed"), "{text}");
}
