//! `rollbench stiffness DECK --export ross|csv|json` through the real binary (issue 29
//! item 4): the ROSS file's terms are the JSON report's stiffness terms exactly, the
//! writer refuses to overwrite, and `--export` with `--format` is refused.

use assert_cmd::Command;

fn deck(name: &str) -> String {
    format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = match Command::cargo_bin("rollbench").map(|mut c| c.args(args).output()) {
        Ok(Ok(o)) => o,
        Ok(Err(e)) => panic!("{e}"),
        Err(e) => panic!("{e}"),
    };
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The JSON `stiffness` object of `rollbench stiffness DECK --format json`, its
/// `matrix` re-read from the text with `str::parse` (correctly rounded: serde_json's
/// default float parser may miss the last bit, which an exact comparison would see).
fn stiffness_json(d: &str) -> serde_json::Value {
    let (code, out, err) = run(&["stiffness", d, "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let mut v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    let n = v["stiffness"]["columns"].as_array().map_or(0, Vec::len);
    let at = out.find("\"matrix\"").unwrap_or_else(|| panic!("{out}"));
    let numbers: Vec<f64> = out[at + 8..]
        .split(|c: char| !(c.is_ascii_digit() || "eE+-.".contains(c)))
        .filter(|t| !t.is_empty())
        .take(n * n)
        .map(|t| t.parse().unwrap_or_else(|e| panic!("{t}: {e}")))
        .collect();
    assert_eq!(numbers.len(), n * n);
    for (k, x) in numbers.into_iter().enumerate() {
        v["stiffness"]["matrix"][k / n][k % n] = serde_json::json!(x);
    }
    v["stiffness"].clone()
}

/// K of the `stiffness` object, rows `a` columns `b` by name.
fn term(k: &serde_json::Value, a: &str, b: &str) -> f64 {
    let cols: Vec<&str> = k["columns"]
        .as_array()
        .unwrap_or_else(|| panic!("{k}"))
        .iter()
        .filter_map(|c| c.as_str())
        .collect();
    let (i, j) = (
        cols.iter()
            .position(|c| *c == a)
            .unwrap_or_else(|| panic!("{a}")),
        cols.iter()
            .position(|c| *c == b)
            .unwrap_or_else(|| panic!("{b}")),
    );
    k["matrix"][i][j].as_f64().unwrap_or_else(|| panic!("{k}"))
}

/// On the ball (chen_a, 1 000 N preload at 10 000 rpm) and the tapered (trb_32007, with
/// its moment) decks, `--export ross --output FILE` writes a TOML whose one table
/// `BearingElement_<deck>` holds kxx, kyy, kxy, kyx, kzz equal to the JSON's K_xx,
/// K_yy, K_xy, K_yx, K_zz bit for bit (same solve, shortest round-trip floats), every
/// damping term 0; `--output` naming the deck being read is refused by the project's
/// writer and leaves the deck unchanged.
#[test]
fn ross_export_is_the_json_stiffness_exactly() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    for name in ["chen_a", "trb_32007"] {
        let d = deck(&format!("{name}.toml"));
        let k = stiffness_json(&d);
        let file = dir.path().join(format!("{name}.toml"));
        let f = file.to_string_lossy().into_owned();
        let (code, _, err) = run(&["stiffness", &d, "--export", "ross", "--output", &f]);
        assert_eq!(code, Some(0), "{err}");
        let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{e}"));
        let t: toml::Table = toml::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
        let b = t[&format!("BearingElement_{name}")]
            .as_table()
            .unwrap_or_else(|| panic!("{text}"));
        let one = |key: &str| -> f64 {
            let a = b[key].as_array().unwrap_or_else(|| panic!("{key}"));
            assert_eq!(a.len(), 1, "{key}");
            a[0].as_float().unwrap_or_else(|| panic!("{key}"))
        };
        for (key, r, c) in [
            ("kxx", "x", "x"),
            ("kyy", "y", "y"),
            ("kxy", "x", "y"),
            ("kyx", "y", "x"),
            ("kzz", "z", "z"),
        ] {
            assert_eq!(one(key).to_bits(), term(&k, r, c).to_bits(), "{name} {key}");
        }
        assert!(term(&k, "x", "x") > 0.0 && term(&k, "z", "z") > 0.0);
        for key in ["cxx", "cyy", "cxy", "cyx", "czz"] {
            assert_eq!(one(key), 0.0, "{key}");
        }
        assert!(text.contains("no damping"), "{text}");
        // Through the project's writer: the deck being read is never an output.
        let copy = dir.path().join(format!("{name}_deck.toml"));
        std::fs::copy(&d, &copy).unwrap_or_else(|e| panic!("{e}"));
        let c = copy.to_string_lossy().into_owned();
        let (code, _, err) = run(&["stiffness", &c, "--export", "ross", "--output", &c]);
        assert_eq!(code, Some(1), "writing over the deck was not refused");
        assert!(err.contains("deck"), "{err}");
        assert_eq!(
            std::fs::read(&copy).unwrap_or_else(|e| panic!("{e}")),
            std::fs::read(&d).unwrap_or_else(|e| panic!("{e}"))
        );
    }
}

/// `--export json` on the US tapered deck (trb_afapl): the matrix in lbf/in …
/// in·lbf/rad, each the JSON's SI term over the independent factor (lbf = 4.4482216152605
/// N, in = 0.0254 m) to 1e-12; `--export csv` gives the same numbers a line each.
#[test]
fn csv_and_json_exports_in_deck_units() {
    let d = deck("trb_afapl.toml");
    let k = stiffness_json(&d);
    let (code, out, err) = run(&["stiffness", &d, "--export", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    let (code, csv, err) = run(&["stiffness", &d, "--export", "csv"]);
    assert_eq!(code, Some(0), "{err}");
    let lbf = 4.448_221_615_260_5;
    let inch = 0.0254;
    let cols = ["x", "y", "z", "theta_x", "theta_y"];
    assert_eq!(j["unit_system"], "US");
    assert_eq!(j["damping"], serde_json::Value::Null);
    let lines: Vec<&str> = csv.lines().skip(1).collect();
    for (i, r) in cols.iter().enumerate() {
        for (jj, c) in cols.iter().enumerate() {
            let f = match (i >= 3, jj >= 3) {
                (false, false) => lbf / inch,
                (false, true) | (true, false) => lbf,
                (true, true) => lbf * inch,
            };
            let want = term(&k, r, c) / f;
            let got = j["stiffness"][i][jj].as_f64().unwrap_or(f64::NAN);
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "{r}{c}: {got} vs {want}"
            );
            let cells: Vec<&str> = lines[i * 5 + jj].split(',').collect();
            assert_eq!(cells[1], *c);
            let v: f64 = cells[2].parse().unwrap_or(f64::NAN);
            assert!(
                (v - want).abs() <= 1e-12 * want.abs(),
                "{cells:?} vs {want}"
            );
        }
    }
    assert_eq!(j["units"][0][0], "lbf/in");
}

/// `--export` and `--format` together are refused as a usage error (exit 64), naming
/// both flags.
#[test]
fn export_with_format_is_refused() {
    let d = deck("chen_a.toml");
    let (code, _, err) = run(&["stiffness", &d, "--export", "ross", "--format", "csv"]);
    assert_eq!(code, Some(64), "{err}");
    assert!(
        err.contains("--export") && err.contains("--format"),
        "{err}"
    );
}
