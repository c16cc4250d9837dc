//! `rollbench validate` and `rollbench bench` through the real binary (assert_cmd).

use assert_cmd::Command;

fn rollbench() -> Command {
    Command::cargo_bin("rollbench").unwrap_or_else(|e| panic!("binary: {e}"))
}

#[test]
fn validate_passes_and_prints_the_table() {
    let out = rollbench()
        .arg("validate")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    // Two lines a case: "pass  <quantity>", then "<computed> vs <reference> (<source>):
    // rel. err …, tolerance …"; every line within 100 columns.
    for needle in [
        "pass  Stribeck number",
        " vs ",
        "rel. err",
        "tolerance",
        "NASA/TM-2012-217115",
        " 0 failed",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
    assert!(!text.contains("FAIL"), "{text}");
    let widest = text.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    assert!(widest <= 100, "{widest} columns wide");
}

#[test]
fn validate_json_has_every_column_and_no_failure() {
    let out = rollbench()
        .args(["validate", "--format", "json"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(v["failed"], 0);
    let cases = v["cases"].as_array().cloned().unwrap_or_default();
    assert!(cases.len() >= 40, "{}", cases.len());
    for c in &cases {
        for k in [
            "quantity",
            "reference",
            "source",
            "computed",
            "relative_error",
            "tolerance",
            "pass",
        ] {
            assert!(c.get(k).is_some(), "{k} missing in {c}");
        }
        assert_eq!(c["pass"], true, "{c}");
    }
}

#[test]
fn bench_rejects_a_bad_deck_with_exit_1() {
    let out = rollbench()
        .args(["bench", "no/such/deck.toml"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out.status.code(), Some(1));
    assert!(!out.stderr.is_empty());
}

#[test]
fn help_lists_validate_and_bench() {
    let out = rollbench()
        .arg("--help")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("validate") && text.contains("bench"),
        "{text}"
    );
}

/// `template --type` prints the named system's template (the default is the spherical
/// roller) and refuses an unknown type, listing the known ones.
#[test]
fn template_type_selects_the_bearing_system() {
    let default = rollbench()
        .arg("template")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let typed = rollbench()
        .args(["template", "--type", "spherical-roller"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(typed.status.code(), Some(0));
    assert_eq!(default.stdout, typed.stdout);
    let bad = rollbench()
        .args(["template", "--type", "ball"])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    // An unknown option value is a usage error (64, README's exit codes; issue 24 item 16).
    assert_eq!(bad.status.code(), Some(64));
    let msg = String::from_utf8_lossy(&bad.stderr);
    assert!(
        msg.contains("unknown bearing system (known: \"spherical-roller\"")
            && msg.contains("\"angular-contact-ball\""),
        "{msg}"
    );
}

/// The CSV report is the view's roller table: its header names the JSON roller fields,
/// and every cell equals the JSON value of that roller (an independent path: JSON is the
/// system's own report, CSV the system-independent table).
#[test]
fn csv_rows_equal_the_json_rollers() {
    let run = |format: &str| {
        let out = rollbench()
            .args([
                "run",
                "decks/thrust.toml",
                "--no-transient",
                "--format",
                format,
            ])
            .output()
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(out.status.code(), Some(0));
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let json: serde_json::Value =
        serde_json::from_str(&run("json")).unwrap_or_else(|e| panic!("{e}"));
    let csv = run("csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let rollers = json["rollers"].as_array().cloned().unwrap_or_default();
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), rollers.len());
    for (row, r) in rows.iter().zip(&rollers) {
        for (key, cell) in header.iter().zip(row.split(',')) {
            // A column named as the roller's own JSON key (the common names of issue 30
            // item 10, e.g. `inner_load_n`, `number`) reads that key; the others read
            // the race object (`inner_x` → `inner.x`).
            let v = match (r.get(*key), key.split_once('_')) {
                (Some(v), _) => v,
                (None, Some((race @ ("inner" | "outer"), field))) => &r[race][field],
                (None, _) => &r[*key],
            };
            let want = v.as_f64().unwrap_or_else(|| panic!("{key}: {v}"));
            let got: f64 = cell.parse().unwrap_or_else(|e| panic!("{key} {cell}: {e}"));
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "{key}: {got} vs {want}"
            );
        }
    }
}

/// A solver failure on a US deck is read in US units (issue 15: it printed
/// `F_r = 13344.7 N … 1.785e-2 m`): the rings' walk in inches and the loads in lbf.
#[test]
fn solver_failure_on_a_us_deck_speaks_us_units() {
    let out = rollbench()
        .args([
            "run",
            "decks/aerospace.toml",
            "--set",
            "operating.axial_load=0",
            "--set",
            "geometry.contact_angle=20",
        ])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("F_r = 3000.0 lbf, F_a = 0.0 lbf"), "{err}");
    assert!(err.contains(" in axially"), "{err}");
    assert!(!err.contains(" N,") && !err.contains(" m axially"), "{err}");
}
