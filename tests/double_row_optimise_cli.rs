//! `rollbench optimise` through the real binary (issue 27 Model 5): the contract fields in
//! JSON on the shipped deck (a 3 × 3 grid to keep it short), the text and CSV forms, a deck
//! of another system refused by name, a bad `--grid` refused naming it, an infeasible grid.

mod common;

use common::{deck, run};

#[test]
fn optimise_json_has_the_contract_fields() {
    let (code, out, err) = run(&[
        "optimise",
        &deck("srb_22308.toml"),
        "--grid",
        "3",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    let o = &v["optimise"];
    for k in [
        "variables",
        "total_w",
        "improvement_pct",
        "lambda_min",
        "capacity_ratio",
        "binding",
    ] {
        assert!(!o["optimum"][k].is_null(), "optimum.{k}: {out}");
    }
    assert!(o["optimum"]["variables"]["k_ci"].is_f64());
    assert_eq!(o["grid"].as_array().map(Vec::len), Some(9));
    assert!(o["sensitivity_pct_per_0_1pct"]["k_w"].is_f64());
    assert!(o["noise_w"].as_f64().is_some_and(|x| x >= 0.0));
    assert!(o["solves"]["polish"].as_u64().is_some_and(|n| n <= 100));
}

#[test]
fn optimise_text_csv_and_refusals() {
    let d = deck("srb_22308.toml");
    let (code, out, err) = run(&["optimise", &d, "--grid", "3"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("OSCULATION OPTIMISER") && out.contains("binding"),
        "{out}"
    );
    let (code, out, err) = run(&["optimise", &d, "--grid", "3", "--format", "csv"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 10, "{out}");
    assert!(out.starts_with("k_ci,k_w,total_w"), "{out}");
    let (code, _, err) = run(&["optimise", &deck("aerospace.toml")]);
    assert_eq!(code, 1);
    assert!(err.contains("double-row spherical roller decks"), "{err}");
    // An even grid misses the nominal point; on the shipped deck nothing else is feasible:
    // a failed optimisation (exit 2) with the nominal's margins.
    let (code, _, err) = run(&["optimise", &d, "--grid", "2"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("no point of the 4-point grid") && err.contains("p_max margin"),
        "{err}"
    );
    let (code, _, err) = run(&["optimise", &d, "--grid", "1"]);
    assert_eq!(code, 64);
    assert!(err.contains("--grid 1"), "{err}");
}
