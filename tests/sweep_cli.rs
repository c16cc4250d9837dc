//! `rollbench sweep` through the real binary (issues 16 and 17): a generic sweep over a deck
//! key for every bearing system, one row per point in sweep order, each point the same
//! computation as `run --set` of its value, and bad ranges refused with exit 1 naming the
//! key.

use assert_cmd::Command;

fn bin() -> Command {
    match Command::cargo_bin("rollbench") {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    }
}

fn deck(name: &str) -> String {
    format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    let out = match bin().args(args).output() {
        Ok(o) => o,
        Err(e) => panic!("{e}"),
    };
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn parse(text: &str) -> serde_json::Value {
    match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => panic!("{e}: {text}"),
    }
}

fn sweep_json(deck_name: &str, range: &str) -> serde_json::Value {
    let d = deck(deck_name);
    let (code, out, err) = run(&["sweep", &d, "--set-range", range, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    parse(&out)
}

/// `run DECK --set KEY=VALUE --no-transient --format json`.
fn run_json(deck_name: &str, set: &str) -> serde_json::Value {
    let d = deck(deck_name);
    let (code, out, err) = run(&[
        "run",
        &d,
        "--set",
        set,
        "--no-transient",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    parse(&out)
}

fn num(v: &serde_json::Value, what: &str) -> f64 {
    match v.as_f64() {
        Some(x) => x,
        None => panic!("{what} is not a number: {v}"),
    }
}

fn points(v: &serde_json::Value) -> &Vec<serde_json::Value> {
    match v["points"].as_array() {
        Some(p) => p,
        None => panic!("no points: {v}"),
    }
}

/// Relative agreement to 1e-12: a point and a plain run are the same computation on the
/// same deck text, so only the last bits of a differently ordered reduction may differ.
fn assert_same(a: f64, b: f64, what: &str) {
    let scale = a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
    assert!(
        (a - b).abs() <= 1e-12 * scale,
        "{what}: sweep {a} against run {b}"
    );
}

/// The largest `normal_load_n` of the inner and outer contacts of `elements`.
fn max_load(elements: &serde_json::Value) -> f64 {
    let Some(list) = elements.as_array() else {
        panic!("not a list: {elements}")
    };
    list.iter()
        .flat_map(|e| {
            [
                num(&e["inner"]["normal_load_n"], "inner load"),
                num(&e["outer"]["normal_load_n"], "outer load"),
            ]
        })
        .fold(0.0, f64::max)
}

#[test]
fn ball_sweep_has_19_rows_in_order_each_a_plain_run() {
    let v = sweep_json("chen_b.toml", "operating.inner_speed=6000:15000:500");
    assert_eq!(v["key"], "operating.inner_speed");
    assert_eq!(v["unit"], "rpm");
    assert_eq!(v["type"], "angular-contact-ball");
    let p = points(&v);
    assert_eq!(p.len(), 19);
    for (i, point) in p.iter().enumerate() {
        // Exact: 6000 + 500·i is representable and the deck gets it verbatim.
        assert_eq!(num(&point["value"], "value"), 6000.0 + 500.0 * i as f64);
        assert!(point["failure"].is_null(), "{point}");
    }
    // Point 8 is 10 000 rpm: the same numbers as `run --set operating.inner_speed=10000`.
    let point = &p[8];
    assert_eq!(num(&point["value"], "value"), 10000.0);
    let r = run_json("chen_b.toml", "operating.inner_speed=10000");
    assert_same(
        num(&point["heat_w"], "heat_w"),
        num(&r["heat"]["total_w"], "heat.total_w"),
        "heat",
    );
    assert_same(
        num(&point["cage_speed_rpm"], "cage"),
        num(&r["speeds"]["cage_rpm"], "speeds.cage_rpm"),
        "cage speed",
    );
    assert_same(
        num(&point["max_ball_load_n"], "Qmax"),
        max_load(&r["balls"]),
        "max ball load",
    );
    assert_same(
        num(&point["skid_threshold_rpm"], "skid"),
        num(&r["skid"]["threshold_rpm"], "skid.threshold_rpm"),
        "skid threshold",
    );
    // Heat rises with speed over the whole sweep (a monotone check of row order).
    let heat: Vec<f64> = p.iter().map(|x| num(&x["heat_w"], "heat")).collect();
    assert!(heat.windows(2).all(|w| w[1] > w[0]), "{heat:?}");
}

#[test]
fn spherical_sweep_matches_plain_runs() {
    let v = sweep_json("aerospace.toml", "operating.inner_speed=10000:20000:x3");
    assert_eq!(v["type"], "spherical-roller");
    let p = points(&v);
    let values: Vec<f64> = p.iter().map(|x| num(&x["value"], "value")).collect();
    assert_eq!(values, vec![10000.0, 15000.0, 20000.0]);
    for point in p {
        assert!(point["failure"].is_null(), "{point}");
    }
    let r = run_json("aerospace.toml", "operating.inner_speed=15000");
    let point = &p[1];
    assert_same(
        num(&point["cage_speed_rpm"], "cage"),
        num(&r["speeds"]["cage_rpm"], "speeds.cage_rpm"),
        "cage speed",
    );
    assert_same(
        num(&point["total_heat_w"], "heat"),
        num(&r["heat"]["total_w"], "heat.total_w"),
        "heat",
    );
    assert_same(
        num(&point["l10_mrev"], "L10"),
        num(&r["life"]["l10_bearing_mrev"], "life.l10_bearing_mrev"),
        "L10",
    );
    assert_same(
        num(&point["max_roller_load_n"], "Qmax"),
        max_load(&r["rollers"]),
        "max roller load",
    );
}

#[test]
fn text_and_csv_have_one_row_per_point_with_units() {
    let d = deck("chen_b.toml");
    let (code, out, err) = run(&[
        "sweep",
        &d,
        "--set-range",
        "operating.inner_speed=6000:15000:500",
    ]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    // Title, header, 19 rows.
    assert_eq!(lines.len(), 21, "{out}");
    assert!(lines[1].contains("operating.inner_speed [rpm]"), "{out}");
    assert!(lines[1].contains("heat_w"), "{out}");
    assert!(lines[2].trim_start().starts_with("6000"), "{out}");
    assert!(lines[20].trim_start().starts_with("15000"), "{out}");

    let dir = match tempfile::tempdir() {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    };
    let file = dir.path().join("sweep.csv");
    let f = file.display().to_string();
    let (code, out, err) = run(&[
        "sweep",
        &d,
        "--set-range",
        "operating.inner_speed=0:20000:x21",
        "--format",
        "csv",
        "--output",
        &f,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.is_empty(), "{out}");
    let csv = match std::fs::read_to_string(&file) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    };
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 22, "{csv}");
    assert!(rows[0].starts_with("operating.inner_speed [rpm],"), "{csv}");
    assert!(rows[0].ends_with(",failure"), "{csv}");
    assert!(rows[1].starts_with("0,"), "{csv}");
    assert!(rows[8].starts_with("7000,"), "{csv}");
    assert!(rows[21].starts_with("20000,"), "{csv}");
}

#[test]
fn a_bare_third_number_is_a_step() {
    // Issue 17's `0:20000:21` reads as a step of 21 rpm (953 points; the count is checked
    // in the range parser's unit tests, solving 953 points is not this test's business):
    // here `9000:9100:21` gives 9000, 9021, 9042, 9063, 9084, the last step before B.
    let v = sweep_json("chen_b.toml", "operating.inner_speed=9000:9100:21");
    let values: Vec<f64> = points(&v)
        .iter()
        .map(|x| num(&x["value"], "value"))
        .collect();
    assert_eq!(values, vec![9000.0, 9021.0, 9042.0, 9063.0, 9084.0]);
}

#[test]
fn bad_ranges_exit_1_and_name_the_key() {
    let d = deck("aerospace.toml");
    for (range, expect) in [
        ("operating.inner_speed=a:100:10", "not a finite number"),
        ("operating.inner_speed=0:100:0", "STEP must be > 0"),
        ("operating.inner_speed=0:100:-5", "STEP must be > 0"),
        ("operating.inner_speed=0:20000:1", "more than 10000 points"),
        ("operating.inner_speed=0:2000000:500000", "out of range"),
        ("operating.no_such_key=0:10:1", "unknown key"),
    ] {
        let (code, out, err) = run(&["sweep", &d, "--set-range", range]);
        assert_eq!(code, 1, "{range}: {err}");
        assert!(out.is_empty(), "{range}: {out}");
        let key = range.split('=').next().unwrap_or_default();
        assert!(err.contains(key), "{range}: {err}");
        assert!(err.contains(expect), "{range}: {err}");
        if key == "operating.inner_speed" {
            // The allowed range comes from the deck's own field.
            assert!(
                err.contains("-1000000 ≤ value ≤ 1000000 rpm"),
                "{range}: {err}"
            );
        }
    }
}

#[test]
fn a_failed_point_is_a_row_with_its_reason() {
    // 200 000 rpm is a valid deck value, but the aerospace bearing's rings fly apart there
    // (no equilibrium): that point is a row with the solver's message, the sweep goes on
    // and exits 0 because a point solved; a sweep with no solved point exits 2.
    let v = sweep_json("aerospace.toml", "operating.inner_speed=20000:200000:x2");
    let p = points(&v);
    assert_eq!(p.len(), 2);
    assert!(p[0]["failure"].is_null(), "{}", p[0]);
    assert!(num(&p[0]["total_heat_w"], "heat") > 0.0);
    let reason = p[1]["failure"].as_str().unwrap_or_default();
    assert!(reason.contains("no equilibrium"), "{}", p[1]);
    assert!(p[1]["total_heat_w"].is_null(), "{}", p[1]);

    let d = deck("aerospace.toml");
    let (code, out, err) = run(&[
        "sweep",
        &d,
        "--set-range",
        "operating.inner_speed=200000:300000:x2",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("2 of 2 points failed"), "{err}");
    // The reason holds commas: the CSV cell is quoted.
    assert!(
        out.lines()
            .nth(1)
            .unwrap_or_default()
            .contains(",\"load distribution"),
        "{out}"
    );
}

/// `sweep DECK --set-range RANGE --format json --cold`.
fn sweep_json_cold(deck_name: &str, range: &str) -> serde_json::Value {
    let d = deck(deck_name);
    let (code, out, err) = run(&[
        "sweep",
        &d,
        "--set-range",
        range,
        "--format",
        "json",
        "--cold",
    ]);
    assert_eq!(code, 0, "{err}");
    parse(&out)
}

#[test]
fn warm_start_gives_the_cold_answers_to_the_solver_tolerance() {
    // The default sweep continues each core's run of points from its previous point
    // through the system's session; `--cold` solves each point from scratch. A session
    // promises the cold root to its solver tolerance: 1e-7 relative on every key output
    // (the loosest equilibrium tolerance of the shipped decks is 1e-8 of the load, and
    // stiffness, stress and heat are smooth functions of the equilibrium), never a
    // different branch.
    for (deck_name, range) in [
        ("chen_b.toml", "operating.inner_speed=6000:15000:x7"),
        ("trb_afapl.toml", "operating.inner_speed=0:20000:x7"),
        ("aerospace.toml", "operating.inner_speed=10000:30000:x5"),
    ] {
        let warm = sweep_json(deck_name, range);
        let cold = sweep_json_cold(deck_name, range);
        assert_eq!(warm["start"], "warm", "{deck_name}");
        assert_eq!(cold["start"], "cold", "{deck_name}");
        let (w, c) = (points(&warm), points(&cold));
        assert_eq!(w.len(), c.len(), "{deck_name}");
        for (pw, pc) in w.iter().zip(c) {
            let Some(fields) = pc.as_object() else {
                panic!("{pc}")
            };
            for (k, vc) in fields {
                match (vc.as_f64(), pw[k].as_f64()) {
                    (Some(a), Some(b)) => {
                        let scale = a.abs().max(b.abs()).max(1e-300);
                        assert!(
                            (a - b).abs() <= 1e-7 * scale,
                            "{deck_name} {k} at {}: warm {b} cold {a}",
                            pc["value"]
                        );
                    }
                    _ => assert_eq!(&pw[k], vc, "{deck_name} {k}"),
                }
            }
        }
    }
}

/// Issue 30 item 6: the columns never depend on which points solved. A tapered sweep at
/// 42 500 rpm (every point fails: exit 3) printed `operating.inner_speed [rpm],failure`
/// where a solved sweep has the key outputs too, and its JSON points lost their keys: now
/// the CSV header is the solved sweep's, and the JSON points carry the same keys (null).
#[test]
fn an_all_failed_sweep_keeps_its_columns() {
    let t = deck("trb_afapl.toml");
    let range = |v: &str| format!("operating.inner_speed={v}:{v}:1");
    let (code, ok_csv, err) = run(&[
        "sweep",
        &t,
        "--set-range",
        &range("1000"),
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, bad_csv, err) = run(&[
        "sweep",
        &t,
        "--set-range",
        &range("42500"),
        "--format",
        "csv",
    ]);
    assert_ne!(code, 0, "42 500 rpm solved after all: {bad_csv}");
    let header = |csv: &str| csv.lines().next().unwrap_or("").to_string();
    assert_eq!(header(&bad_csv), header(&ok_csv), "{err}");
    assert!(header(&ok_csv).split(',').count() > 2, "{ok_csv}");
    let (_, ok_json, _) = run(&[
        "sweep",
        &t,
        "--set-range",
        &range("1000"),
        "--format",
        "json",
    ]);
    let (_, bad_json, _) = run(&[
        "sweep",
        &t,
        "--set-range",
        &range("42500"),
        "--format",
        "json",
    ]);
    let keys = |j: &serde_json::Value| -> Vec<String> {
        j["points"][0]
            .as_object()
            .map(|m| m.keys().cloned().collect())
            .unwrap_or_default()
    };
    assert_eq!(keys(&parse(&bad_json)), keys(&parse(&ok_json)));
}
