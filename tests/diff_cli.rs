//! `rollbench diff A B` through the real binary (issue 30 item 21): a deck against
//! itself differs by nothing, in every system; a `--set-b` edit shows exactly its effect
//! (a cone speed halved halves the tapered roller's cage speed, the kinematic ratio
//! ω_c/ω_i = (1 − D·cos α/d_m)/2 being independent of speed); two systems are compared
//! only on the lines both report, in A's units.

use assert_cmd::Command;
use serde_json::Value;

fn deck(name: &str) -> String {
    format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    let out = match Command::cargo_bin("rollbench").map(|mut c| c.args(args).output()) {
        Ok(Ok(o)) => o,
        other => panic!("{other:?}"),
    };
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn diff_json(args: &[&str]) -> Value {
    let mut all = vec!["diff"];
    all.extend_from_slice(args);
    all.extend(["--format", "json", "--no-transient"]);
    let (code, out, err) = run(&all);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"))
}

fn rows(v: &Value, key: &str) -> Vec<Value> {
    v[key].as_array().cloned().unwrap_or_default()
}

fn find<'a>(rows: &'a [Value], section: &str, quantity: &str) -> &'a Value {
    rows.iter()
        .find(|r| r["section"] == section && r["quantity"] == quantity)
        .unwrap_or_else(|| panic!("{section} · {quantity} not in {rows:?}"))
}

/// Every difference of a deck with itself is exactly 0 (the solves are deterministic),
/// for one deck of every system, bearing-level lines and element cells alike; nothing is
/// left uncompared.
#[test]
fn a_deck_against_itself_differs_by_nothing() {
    for name in [
        "aerospace.toml",
        "chen_b.toml",
        "trb_afapl.toml",
        "crb_truck.toml",
        "srb_22308.toml",
    ] {
        let d = deck(name);
        let v = diff_json(&[&d, &d]);
        let outputs = rows(&v, "outputs");
        let elements = rows(&v, "elements");
        assert!(outputs.len() >= 5, "{name}: {} outputs", outputs.len());
        assert!(!elements.is_empty(), "{name}: {:?}", v["elements_note"]);
        for r in outputs.iter().chain(&elements) {
            if r["a"].is_null() {
                assert!(r["b"].is_null(), "{name}: {r}");
                continue;
            }
            assert_eq!(r["a"], r["b"], "{name}: {r}");
            assert_eq!(r["delta"].as_f64(), Some(0.0), "{name}: {r}");
            assert_eq!(r["delta_percent"].as_f64(), Some(0.0), "{name}: {r}");
        }
        assert_eq!(v["only_in_a"], Value::Array(vec![]), "{name}");
        assert_eq!(v["only_in_b"], Value::Array(vec![]), "{name}");
    }
}

/// Halving the cone speed of the AFAPL tapered roller (20 000 → 10 000 rpm) halves its
/// cage speed: Δ% = −50 to 1e-7 (the cage's kinematic ratio does not depend on speed),
/// Δ = B − A; B is named with its edit; the values are in A's (US) units.
#[test]
fn a_speed_edit_moves_the_cage_by_the_kinematic_ratio() {
    let d = deck("trb_afapl.toml");
    let v = diff_json(&[&d, &d, "--set-b", "operating.inner_speed=10000"]);
    let outputs = rows(&v, "outputs");
    let cage = find(&outputs, "Speeds", "cage");
    assert_eq!(cage["unit"], "rpm");
    let (a, b) = (
        cage["a"].as_f64().unwrap_or(0.0),
        cage["b"].as_f64().unwrap_or(0.0),
    );
    assert!(a > 0.0);
    assert!((b / a - 0.5).abs() < 1e-9, "cage {a} → {b}");
    let p = cage["delta_percent"].as_f64().unwrap_or(0.0);
    assert!((p + 50.0).abs() < 1e-7, "{p}");
    assert!(
        (cage["delta"].as_f64().unwrap_or(0.0) - (b - a)).abs() <= 1e-9 * a,
        "{cage}"
    );
    // B is named with its edit.
    assert!(v["b"]["deck"]
        .as_str()
        .unwrap_or("")
        .ends_with("--set-b operating.inner_speed=10000"));
    // The US deck's units: forces in lbf.
    assert_eq!(v["units"], "us");
}

/// Two systems: only the lines both report are compared (lives, cage speed, …), every
/// other is listed by design; no element table is compared, and the text says why and
/// in whose units.
#[test]
fn two_systems_compare_only_what_they_share() {
    let (a, b) = (deck("chen_b.toml"), deck("trb_afapl.toml"));
    let v = diff_json(&[&a, &b]);
    let outputs = rows(&v, "outputs");
    find(&outputs, "Life", "L10 basic ISO 281");
    find(&outputs, "Speeds", "cage");
    assert_eq!(v["units"], "si", "A's units");
    assert!(rows(&v, "elements").is_empty());
    assert!(v["elements_note"]
        .as_str()
        .unwrap_or("")
        .starts_with("not compared"));
    assert!(!rows(&v, "only_in_a").is_empty() || !rows(&v, "only_in_b").is_empty());
    let (code, text, err) = run(&["diff", &a, &b, "--no-transient"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("values in A's deck units (SI)"), "{text}");
    assert!(
        text.contains("per-element tables: not compared: two systems (A: angular-contact"),
        "{text}"
    );
    assert!(text.contains("Speeds · cage"), "{text}");
    // CSV: one header, one row per compared quantity.
    let (code, csv, err) = run(&["diff", &a, &b, "--no-transient", "--format", "csv"]);
    assert_eq!(code, 0, "{err}");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("section,quantity,unit,a,b,delta,delta_percent")
    );
    assert_eq!(lines.count(), outputs.len());
}

/// Neither deck may be the output, and a deck that does not load exits 1.
#[test]
fn diff_refuses_to_overwrite_a_deck() {
    let a = deck("chen_b.toml");
    let (code, _, err) = run(&["diff", &a, &a, "--output", &a]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("deck A"), "{err}");
    let (code, _, err) = run(&["diff", &a, "no_such_deck.toml"]);
    assert_eq!(code, 1, "{err}");
}
