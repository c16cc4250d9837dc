//! `rollbench stiffness` on every shipped deck (issue 29 item 3): every system has a
//! stiffness matrix on the shared type, in text, JSON and CSV, and `--check-fd` reports
//! its finite-difference gap where the system has the check.

mod common;

use common::{deck, run, toml_files};

/// Every shipped deck: `stiffness` succeeds in text (the shared header), JSON (`matrix`
/// square over `rows` × `columns`, `units`, `method`) and CSV (a header and one line per
/// row); no deck is refused (each system's physics has a stiffness).
#[test]
fn every_shipped_deck_has_a_stiffness() {
    let decks = toml_files("decks");
    assert!(decks.len() >= 13, "{decks:?}");
    for d in decks {
        let d = d.display().to_string();
        let (code, text, err) = run(&["stiffness", &d]);
        assert_eq!(code, 0, "{d}: {err}");
        assert!(
            text.starts_with("Stiffness matrix (rows F_x"),
            "{d}: {text}"
        );
        let (code, json, err) = run(&["stiffness", &d, "--format", "json"]);
        assert_eq!(code, 0, "{d}: {err}");
        let v: serde_json::Value =
            serde_json::from_str(&json).unwrap_or_else(|e| panic!("{d}: {e}"));
        let k = &v["stiffness"];
        let n = k["rows"].as_array().map_or(0, Vec::len);
        assert!(n >= 2, "{d}: {k}");
        assert_eq!(k["columns"].as_array().map(Vec::len), Some(n), "{d}");
        let m = k["matrix"].as_array().cloned().unwrap_or_default();
        assert_eq!(m.len(), n, "{d}");
        assert!(
            m.iter().all(|r| r.as_array().map(Vec::len) == Some(n)),
            "{d}"
        );
        // The x diagonal is a positive stiffness in every system.
        assert!(m[0][0].as_f64().is_some_and(|x| x > 0.0), "{d}: {k}");
        assert!(k["method"].as_str().is_some(), "{d}");
        let (code, csv, err) = run(&["stiffness", &d, "--format", "csv"]);
        assert_eq!(code, 0, "{d}: {err}");
        assert_eq!(csv.lines().count(), n + 1, "{d}: {csv}");
    }
}

/// `--check-fd` on a spherical roller deck (issue 29: "`rollbench stiffness
/// decks/aerospace.toml` works; `--check-fd` reports `finite_difference_max_rel`"), on the
/// double row and a cylindrical deck: the gap is below the 1e-6.
#[test]
fn check_fd_reports_the_gap() {
    for name in ["aerospace.toml", "srb_22308.toml", "crb_nasa210.toml"] {
        let (code, json, err) = run(&["stiffness", &deck(name), "--check-fd", "--format", "json"]);
        assert_eq!(code, 0, "{name}: {err}");
        let v: serde_json::Value =
            serde_json::from_str(&json).unwrap_or_else(|e| panic!("{name}: {e}"));
        let gap = v["stiffness"]["finite_difference_max_rel"].as_f64();
        assert!(gap.is_some_and(|g| g < 1e-6), "{name}: {gap:?}");
        assert_eq!(v["stiffness"]["method"], "both", "{name}");
    }
}

/// The spherical roller's text says why its tilts are free, and its US text is in lbf/in.
#[test]
fn spherical_roller_says_why_tilt_is_free() {
    let (code, text, err) = run(&["stiffness", &deck("aerospace.toml")]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("outer raceway is a sphere"), "{text}");
    assert!(text.contains("lbf/in"), "{text}");
}
