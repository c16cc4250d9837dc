//! Long work is bounded, estimated and says so (issue 24 item 7), through the binary:
//! a time simulation past its work bound is refused up front naming the keys, a long
//! history is decimated to its bound and says so in the CSV and the JSON, no progress
//! bar is drawn when standard error is not a terminal, and a deck's arrays are bounded
//! in length. Every case here is refused or short (< 2 s in a debug build).

mod common;
use common::{deck, run};

/// The 43-s run (chen_b, 500 N radial, 1 000 orbits) and 45-s run (50 orbits ×
/// 2 001 slices) are refused before any ball is integrated, with the estimate, the bound
/// and the keys with their values; nothing is written to `--series`.
#[test]
fn a_time_simulation_past_its_bound_is_refused_up_front_naming_the_keys() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let series = dir.path().join("s.csv");
    let s = series.to_string_lossy().into_owned();
    let d = deck("chen_b.toml");
    for extra in [
        [
            "--set",
            "dynamics.orbits=1000",
            "--set",
            "dynamics.slices=41",
        ],
        [
            "--set",
            "dynamics.orbits=50",
            "--set",
            "dynamics.slices=2001",
        ],
    ] {
        let t = std::time::Instant::now();
        let mut args = vec![
            "run",
            d.as_str(),
            "--set",
            "dynamics.method=time-simulation",
            "--set",
            "operating.radial_load=500",
            "--series",
            s.as_str(),
        ];
        args.extend_from_slice(&extra);
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{err}");
        assert!(out.is_empty(), "{out}");
        assert!(t.elapsed().as_secs_f64() < 5.0, "{:?}", t.elapsed());
        for want in [
            "this time simulation would take about",
            "slice evaluations",
            "the bound is 2e9",
            "dynamics.orbits (now",
            "dynamics.slices (now",
            "geometry.ball_count (now 20",
        ] {
            assert!(err.contains(want), "{want:?} not in {err}");
        }
        assert!(!series.exists());
    }
}

/// A long axisymmetric history (chen_b, 120 orbits: 20 balls × 10 801 samples = 216 020
/// rows undecimated, a cheap run since one ball is integrated) is decimated to at most
/// 100 000 rows: the CSV starts with a comment saying so, each ball's last orbit is
/// whole (91 rows 1/90 orbit apart), and the JSON reports `series_decimation`. The
/// shipped 5 orbits are not decimated (no comment, `sample_every` 1).
#[test]
fn a_long_series_is_decimated_to_its_bound_and_says_so() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let series = dir.path().join("s.csv");
    let s = series.to_string_lossy().into_owned();
    let d = deck("chen_b.toml");
    let (code, out, err) = run(&[
        "run",
        &d,
        "--format",
        "json",
        "--set",
        "dynamics.method=time-simulation",
        "--set",
        "dynamics.orbits=120",
        "--series",
        &s,
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    let dec = &j["dynamics"]["series_decimation"];
    let every = dec["sample_every"].as_u64().unwrap_or(0);
    assert!(every > 1, "{dec}");
    assert_eq!(dec["max_rows"], 100_000);
    assert_eq!(dec["last_orbit_whole"], true);
    let csv = std::fs::read_to_string(&series).unwrap_or_else(|e| panic!("{e}"));
    let mut lines = csv.lines();
    let note = lines.next().unwrap_or("");
    assert!(note.starts_with("# decimated: 1 sample in "), "{note}");
    assert!(note.contains(&format!("1 sample in {every} ")), "{note}");
    assert!(lines.next().unwrap_or("").starts_with("time_s,ball,"));
    let rows: Vec<(f64, usize)> = lines
        .map(|l| {
            let mut f = l.split(',');
            let t = f.next().and_then(|x| x.parse().ok()).unwrap_or(f64::NAN);
            let b = f.next().and_then(|x| x.parse().ok()).unwrap_or(usize::MAX);
            (t, b)
        })
        .collect();
    assert!(rows.len() <= 100_000 + 20 * 91, "{}", rows.len());
    assert!(rows.len() > 50_000, "{}", rows.len());
    // Ball 0's last 91 rows: equally spaced (the undecimated spacing), and before them a
    // gap `every` times as large.
    let b0: Vec<f64> = rows.iter().filter(|r| r.1 == 0).map(|r| r.0).collect();
    let n = b0.len();
    let dt = b0[n - 1] - b0[n - 2];
    for w in b0[n - 91..].windows(2) {
        assert!(((w[1] - w[0]) / dt - 1.0).abs() < 1e-6, "{w:?} {dt}");
    }
    let early = b0[1] - b0[0];
    assert!(
        (early / dt - every as f64).abs() < 1e-6 * every as f64,
        "{early} {dt}"
    );

    let (code, out, err) = run(&[
        "run",
        &d,
        "--format",
        "json",
        "--set",
        "dynamics.method=time-simulation",
        "--series",
        &s,
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(j["dynamics"]["series_decimation"]["sample_every"], 1);
    let csv = std::fs::read_to_string(&series).unwrap_or_else(|e| panic!("{e}"));
    assert!(csv.starts_with("time_s,ball,"));
    assert_eq!(csv.lines().count(), 1 + 20 * 451);
    // Standard error is a pipe here: no progress bar is drawn on it.
    assert!(err.is_empty(), "{err}");
}

/// A deck's array holds at most 10 000 elements: a traction table of 10 001 points is
/// refused at its key and the line of the element past the bound, before any document
/// is built (the 4 MiB deck of 700 000 points peaked at 1.63 GB in `check`); a thermal
/// network of 10 001 `[[thermal.nodes]]` likewise. 10 000 points pass the bound (and
/// then meet the table's own checks).
#[test]
fn a_decks_arrays_are_bounded_in_length() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let base = std::fs::read_to_string(deck("chen_b.toml")).unwrap_or_else(|e| panic!("{e}"));
    let head_lines = base.lines().count();
    let table = |n: usize| {
        let pts: Vec<String> = (0..n)
            .map(|k| format!("[{}, 0.05]", k as f64 * 1e-3))
            .collect();
        format!(
            "{base}\n[traction_table]\npoints = [\n{}\n]\n",
            pts.join(",\n")
        )
    };
    let p = dir.path().join("big.toml");
    std::fs::write(&p, table(10_001)).unwrap_or_else(|e| panic!("{e}"));
    let ps = p.to_string_lossy().into_owned();
    let (code, _, err) = run(&["check", &ps]);
    assert_eq!(code, 1, "{err}");
    let line = head_lines + 3 + 10_001;
    assert!(err.contains(&format!("big.toml:{line}:")), "{err}");
    assert!(err.contains("traction_table.points"), "{err}");
    assert!(err.contains("at most 10000"), "{err}");
    assert!(err.len() < 400, "{err}");

    std::fs::write(&p, table(10_000)).unwrap_or_else(|e| panic!("{e}"));
    let (code, out, err) = run(&["check", &ps]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("ok"), "{out}");

    let nodes = "[[thermal.nodes]]\nname = \"n\"\n".repeat(10_001);
    std::fs::write(&p, format!("{base}\n{nodes}")).unwrap_or_else(|e| panic!("{e}"));
    let (code, _, err) = run(&["check", &ps]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("thermal.nodes"), "{err}");
    assert!(err.contains("at most 10000"), "{err}");
}
