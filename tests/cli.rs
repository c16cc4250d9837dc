//! The command line through the real binary (assert_cmd).

use assert_cmd::Command;

fn bin() -> Command {
    match Command::cargo_bin("rollbench") {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    }
}

fn root() -> &'static str {
    env!("CARGO_MANIFEST_DIR")
}

#[test]
fn run_json_has_the_contract_fields() {
    let out = bin()
        .args([
            "run",
            &format!("{}/decks/aerospace.toml", root()),
            "--format",
            "json",
            "--no-transient",
        ])
        .output();
    let out = match out {
        Ok(o) => o,
        Err(e) => panic!("{e}"),
    };
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_default();
    for k in [
        "input",
        "converged",
        "loads",
        "rings",
        "rollers",
        "residuals",
        "stats",
        "life",
        "speeds",
        "heat",
        "thermal",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    for k in ["radial_n", "axial_n"] {
        assert!(v["loads"][k].is_number(), "loads.{k}");
    }
    for k in ["axial_deflection_m", "radial_deflection_m"] {
        assert!(v["rings"][k].is_number(), "rings.{k}");
    }
    let r = &v["rollers"][0];
    for k in [
        "index",
        "azimuth_deg",
        "axial_displacement_m",
        "radial_displacement_m",
        "tilt_rad",
        "centrifugal_force_n",
        "gyroscopic_moment_nm",
        "spin_rpm",
    ] {
        assert!(r[k].is_number(), "rollers[0].{k}");
    }
    for side in ["inner", "outer"] {
        for k in [
            "normal_load_n",
            "contact_angle_deg",
            "loaded_laminae",
            "max_stress_pa",
            "mean_stress_pa",
            "contact_major_axis_m",
            "contact_minor_axis_m",
            "eccentricity_m",
            "subsurface_shear_pa",
            "subsurface_depth_m",
            "min_film_m",
            "equivalent_load_n",
        ] {
            assert!(r[side][k].is_number(), "rollers[0].{side}.{k}");
        }
    }
    let l = &r["laminae"][0];
    for k in [
        "offset_m",
        "width_m",
        "inner_load_n",
        "outer_load_n",
        "inner_approach_m",
        "outer_approach_m",
        "inner_angle_deg",
        "outer_angle_deg",
        "inner_half_width_m",
        "outer_half_width_m",
        "inner_stress_pa",
        "outer_stress_pa",
        "inner_sliding_m_s",
        "outer_sliding_m_s",
        "inner_traction_n",
        "outer_traction_n",
        "inner_heat_w",
        "outer_heat_w",
    ] {
        assert!(l.get(k).is_some(), "laminae[0].{k}");
    }
    for k in [
        "bearing_radial_n",
        "bearing_axial_n",
        "roller_force_n",
        "roller_moment_nm",
    ] {
        assert!(v["residuals"][k].is_number(), "residuals.{k}");
    }
    for k in [
        "capacity_inner_n",
        "capacity_outer_n",
        "mean_load_inner_n",
        "mean_load_outer_n",
        "l10_inner_mrev",
        "l10_outer_mrev",
        "l10_bearing_mrev",
        "l10_bearing_h",
        "lambda_inner",
        "lambda_outer",
        "lubrication_factor_inner",
        "lubrication_factor_outer",
        "material_factor",
        "adjusted_l10_inner_mrev",
        "adjusted_l10_outer_mrev",
        "adjusted_l10_bearing_mrev",
    ] {
        assert!(v["life"][k].is_number(), "life.{k}");
    }
    for k in ["inner_rpm", "outer_rpm", "cage_rpm", "cage_rpm_estimate"] {
        assert!(v["speeds"][k].is_number(), "speeds.{k}");
    }
    for k in [
        "inner_contacts_w",
        "outer_contacts_w",
        "cage_rails_w",
        "viscous_drag_w",
        "total_w",
        "friction_torque_nm",
    ] {
        assert!(v["heat"][k].is_number(), "heat.{k}");
    }
    for k in ["heat_in_w", "heat_out_w", "balance_w"] {
        assert!(v["thermal"]["steady"][k].is_number(), "thermal.steady.{k}");
    }
    assert_eq!(v["converged"], serde_json::Value::Bool(true));
}

#[test]
fn transient_is_reported_when_asked() {
    let out = bin()
        .args([
            "run",
            &format!("{}/decks/aerospace.toml", root()),
            "--format",
            "json",
        ])
        .output();
    let Ok(out) = out else { panic!("spawn") };
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_default();
    let t = &v["thermal"]["transient"];
    assert!(t["scenario"].is_string());
    assert!(t["time_s"].as_array().is_some_and(|a| a.len() > 1));
    let nodes = t["nodes"].as_array().cloned().unwrap_or_default();
    assert!(nodes.iter().all(|n| n["name"].is_string()
        && n["temperature_c"].is_array()
        && n.get("time_to_limit_s").is_some()));
}

#[test]
fn check_rejects_every_invalid_deck_with_exit_1() {
    let dir = format!("{}/tests/invalid_decks", root());
    let mut n = 0;
    for e in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
        let p = e.path();
        let out = bin().args(["check", &p.to_string_lossy()]).output();
        let Ok(out) = out else { panic!("spawn") };
        assert_eq!(out.status.code(), Some(1), "{}", p.display());
        let msg = String::from_utf8_lossy(&out.stderr);
        let name = p
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default();
        assert!(msg.contains(&name), "{name}: message names the file: {msg}");
        n += 1;
    }
    assert!(n >= 10, "{n} invalid decks");
}

#[test]
fn template_parses_back_in_both_units() {
    for units in ["si", "us"] {
        let Ok(out) = bin().args(["template", "--units", units]).output() else {
            panic!("spawn")
        };
        assert!(out.status.success());
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let path = dir.path().join("t.toml");
        std::fs::write(&path, &out.stdout).unwrap_or_else(|e| panic!("{e}"));
        let Ok(chk) = bin().args(["check", &path.to_string_lossy()]).output() else {
            panic!("spawn")
        };
        assert!(
            chk.status.success(),
            "{units}: {}",
            String::from_utf8_lossy(&chk.stderr)
        );
    }
}

#[test]
fn set_overrides_and_output_file() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let out_path = dir.path().join("r.csv");
    let deck = format!("{}/decks/radial_si.toml", root());
    let status = bin()
        .args([
            "run",
            &deck,
            "--format",
            "csv",
            "--output",
            &out_path.to_string_lossy(),
            "--set",
            "operating.radial_load=30000",
        ])
        .output();
    let Ok(status) = status else { panic!("spawn") };
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let csv = std::fs::read_to_string(&out_path).unwrap_or_default();
    assert_eq!(csv.lines().count(), 1 + 18, "header + one row per roller");
    // A bad override names the key and its allowed range, exit 1.
    let Ok(bad) = bin()
        .args(["run", &deck, "--set", "geometry.roller_count=0"])
        .output()
    else {
        panic!("spawn")
    };
    assert_eq!(bad.status.code(), Some(1));
    let msg = String::from_utf8_lossy(&bad.stderr);
    assert!(
        msg.contains("geometry.roller_count") && msg.contains("allowed"),
        "{msg}"
    );
}

#[test]
fn help_lists_the_commands() {
    let Ok(out) = bin().arg("--help").output() else {
        panic!("spawn")
    };
    let s = String::from_utf8_lossy(&out.stdout);
    for c in ["run", "check", "template"] {
        assert!(s.contains(c), "{c}");
    }
}

/// `run --output` never writes the report over the deck it reads (by its own path,
/// through a symbolic link or a hard link): exit 1, deck untouched. `--output -` is
/// standard output. (Before: the deck was replaced by the CSV report.)
#[test]
fn output_never_overwrites_the_deck() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let deck = dir.path().join("deck.toml");
    let text = std::fs::read_to_string(format!("{}/decks/radial_si.toml", root()))
        .unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(&deck, &text).unwrap_or_else(|e| panic!("{e}"));
    let link = dir.path().join("link.toml");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&deck, &link).unwrap_or_else(|e| panic!("{e}"));
    for out in [deck.clone(), link.clone()] {
        let Ok(r) = bin()
            .args([
                "run",
                &deck.to_string_lossy(),
                "--format",
                "csv",
                "--output",
            ])
            .arg(&out)
            .output()
        else {
            panic!("spawn")
        };
        let msg = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(1), "{msg}");
        assert!(msg.contains("deck being read"), "{msg}");
        assert_eq!(
            std::fs::read_to_string(&deck).ok().as_deref(),
            Some(text.as_str())
        );
    }
    let Ok(r) = bin()
        .args([
            "run",
            &deck.to_string_lossy(),
            "--format",
            "csv",
            "--output",
            "-",
        ])
        .output()
    else {
        panic!("spawn")
    };
    assert_eq!(r.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&r.stdout).lines().count(), 1 + 18);
    assert!(!dir.path().join("-").exists());
}

fn run_args(args: &[&str]) -> (Option<i32>, String, String) {
    let Ok(o) = bin().args(args).output() else {
        panic!("spawn")
    };
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// One meaning per exit code (README "Command line"): 0 ok, 1 invalid input, 2 solver
/// failure, 3 validate failed (not exercised: every case passes), 64 usage. Before,
/// usage errors shared 2 with solver failures and `template --set` / `validate --set`
/// silently ignored the overrides.
#[test]
fn exit_codes_have_one_meaning_each() {
    let aero = format!("{}/decks/aerospace.toml", root());
    let radial = format!("{}/decks/radial_si.toml", root());
    assert_eq!(run_args(&["run", &aero, "--format", "xml"]).0, Some(64));
    let (code, _, err) = run_args(&["template", "--set", "operating.axial_load=1"]);
    assert_eq!(code, Some(64), "{err}");
    assert!(err.contains("takes no overrides"), "{err}");
    assert_eq!(run_args(&["validate", "--set", "a=1"]).0, Some(64));
    assert_eq!(run_args(&["check", "/no/such/deck.toml"]).0, Some(1));
    let (code, _, err) = run_args(&["check", &aero, "--set", "operating.inner_spd=1"]);
    assert_eq!(code, Some(1));
    assert!(err.contains("did you mean operating.inner_speed"), "{err}");
    // A zero-contact-angle bearing under a large axial load: a solver failure (2) whose
    // message describes that case, not an angular-contact bearing without axial load.
    let (code, _, err) = run_args(&["run", &radial, "--set", "operating.axial_load=68430"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("zero contact angle cannot carry the axial load"),
        "{err}"
    );
    assert!(!err.contains("needs an axial load"), "{err}");
    let (code, out, err) = run_args(&["keys"]);
    assert_eq!(code, Some(0));
    assert!(
        out.contains("solver.force_tolerance") && out.contains("thermal."),
        "{out}"
    );
    // Issue 30 item 17: without --type it says whose keys these are and how to get the
    // others (on standard error: the table on standard output is unchanged for scripts).
    assert!(
        err.contains("spherical-roller")
            && err.contains("--type")
            && err.contains("tapered-roller"),
        "{err}"
    );
    let (code, _, err) = run_args(&["keys", "--type", "spherical-roller"]);
    assert_eq!(code, Some(0));
    assert!(err.is_empty(), "{err}");
}

/// A loaded bearing whose rings do not turn relative to each other has an infinite life
/// in hours, said so in JSON (`life.infinite_life_reason`) and text; never "unloaded".
#[test]
fn life_is_infinite_not_unloaded_without_relative_speed() {
    let aero = format!("{}/decks/aerospace.toml", root());
    let same = [
        "--set",
        "operating.inner_speed=0",
        "--set",
        "operating.outer_speed=0",
    ];
    let mut args = vec!["run", aero.as_str(), "--no-transient"];
    args.extend(same);
    let (code, text, err) = run_args(&args);
    assert_eq!(code, Some(0), "{err}");
    assert!(!text.contains("unloaded"), "{text}");
    assert!(text.contains("infinite"), "{text}");
    args.extend(["--format", "json"]);
    let (_, json, _) = run_args(&args);
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
    assert!(v["life"]["l10_bearing_mrev"].is_number(), "{}", v["life"]);
    assert!(
        v["life"]["infinite_life_reason"]
            .as_str()
            .is_some_and(|s| s.contains("do not turn")),
        "{}",
        v["life"]
    );
}

/// Converged means converged: a tolerance above the cap is refused; the thrust deck at
/// an absurd speed no longer reports zero roller loads as a converged answer.
#[test]
fn loose_tolerance_refused_and_residuals_checked() {
    let aero = format!("{}/decks/aerospace.toml", root());
    let (code, _, err) = run_args(&["check", &aero, "--set", "solver.force_tolerance=0.1"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("solver.force_tolerance"), "{err}");
    let thrust = format!("{}/decks/thrust.toml", root());
    let (code, _, err) = run_args(&[
        "run",
        &thrust,
        "--no-transient",
        "--format",
        "json",
        "--set",
        "operating.inner_speed=1000000",
        "--set",
        "solver.force_tolerance=1e-4",
    ]);
    assert_ne!(code, Some(0), "converged?\n{err}");
}

/// The thermal transient never aborts or writes hundreds of MB: a 10⁶-step run keeps at
/// most 4000 samples and says so; absurd durations are refused (exit 1) with the range.
#[test]
fn transient_is_bounded() {
    let aero = format!("{}/decks/aerospace.toml", root());
    let (code, json, err) = run_args(&[
        "run",
        &aero,
        "--format",
        "json",
        "--set",
        "thermal.transient.duration=1e6",
        "--set",
        "thermal.transient.scenario=continued",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(json.len() < 20_000_000, "{}", json.len());
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
    let t = &v["thermal"]["transient"];
    assert_eq!(t["sample_every_steps"], 250);
    assert!(t["time_s"].as_array().map_or(0, Vec::len) <= 4001);
    for (d, s) in [("1e20", "1e20"), ("1e308", "1e-308"), ("1e9", "1e9")] {
        let (code, _, err) = run_args(&[
            "run",
            &aero,
            "--set",
            &format!("thermal.transient.duration={d}"),
            "--set",
            &format!("thermal.transient.step={s}"),
            "--set",
            "thermal.transient.integrator=explicit",
        ]);
        assert_eq!(code, Some(1), "{d}/{s}: {err}");
        assert!(err.contains("allowed"), "{err}");
    }
}
