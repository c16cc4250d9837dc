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
    for needle in [
        "quantity",
        "reference",
        "source",
        "computed",
        "tolerance",
        "NASA/TM-2012-217115",
        " 0 failed",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
    assert!(!text.contains("FAIL"), "{text}");
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
