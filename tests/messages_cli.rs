//! Issue 24, items 11 and 14–16, through the real binary (assert_cmd): the tapered sample
//! at tiny speeds and token loads, `--set` of both keys of a one-of pair, messages a
//! user can read, and exit codes as the README documents them.

use assert_cmd::Command;

fn rollbench() -> Command {
    Command::cargo_bin("rollbench").unwrap_or_else(|e| panic!("binary: {e}"))
}

/// Exit code, stdout and stderr of `rollbench ARGS`.
fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = rollbench()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// No Rust debug text: no `Name {` struct dumps, no `NaN` in words.
fn assert_readable(msg: &str) {
    for bad in [
        "NotConverged {",
        "Stalled {",
        "NonFinite {",
        "{ iteration",
        "NaN",
        "Deck::",
    ] {
        assert!(!msg.contains(bad), "{bad:?} in {msg}");
    }
}

/// Item 11: the speeds that failed (0.01 rpm: residual 4.26e-10 over 3.617e-10 after 60
/// iterations; 0.0078 rpm: "did not converge" with a residual below its tolerance) solve.
#[test]
fn tapered_sample_solves_at_tiny_speeds() {
    for rpm in ["0.0078", "0.0085", "0.01", "0.029"] {
        let set = format!("operating.inner_speed={rpm}");
        let (code, out, err) = run(&[
            "run",
            "decks/trb_afapl.toml",
            "--set",
            &set,
            "--format",
            "json",
        ]);
        assert_eq!(code, Some(0), "{rpm}: {err}");
        assert!(out.contains("\"rollers\""), "{rpm}");
    }
}

/// Item 11 and 15: a token thrust (1e-6 lbf at rest) is refused with the smallest thrust
/// solved, in lbf on this US deck (it stalled before with "Stalled { iterations: 1, … }"
/// and a tolerance of 4.4e-15 N); the exit code is the solver's (2).
#[test]
fn token_thrust_is_refused_in_lbf() {
    let (code, _, err) = run(&[
        "run",
        "decks/trb_afapl.toml",
        "--set",
        "operating.inner_speed=0",
        "--set",
        "operating.axial_load=1e-6",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("below the smallest this model resolves")
            && err.contains("lbf")
            && !err.contains(" N")
            && err.contains("operating.axial_load"),
        "{err}"
    );
    assert_readable(&err);
}

/// Item 15: geometry.cup_angle = 1e-15 (° in this deck) with 3 slices ended in
/// "NonFinite { iteration: 0 } (tolerance NaN N)"; it is refused as a geometry that
/// names the key.
#[test]
fn nearly_cylindrical_roller_is_named() {
    let (code, _, err) = run(&[
        "run",
        "decks/trb_afapl.toml",
        "--set",
        "geometry.cup_angle=1e-15",
        "--set",
        "solver.slices=3",
    ]);
    assert_ne!(code, Some(0), "{err}");
    assert!(err.contains("geometry.cup_angle"), "{err}");
    assert_readable(&err);
}

/// Item 14: two `--set` naming both keys of a one-of pair are refused in either order,
/// naming both (before, the last one silently won). Each alone is accepted.
#[test]
fn both_keys_of_a_one_of_pair_are_refused() {
    let cases: [(&str, &str, &str); 4] = [
        (
            "decks/trb_afapl.toml",
            "geometry.diametral_clearance=0.001",
            "geometry.end_play=0.001",
        ),
        (
            "decks/trb_afapl.toml",
            "geometry.crown_radius=100",
            "geometry.crown_drop=0.0003",
        ),
        (
            "decks/chen_a.toml",
            "geometry.free_contact_angle=15",
            "geometry.clearance=0.00002",
        ),
        (
            "decks/aerospace.toml",
            "lubricant.pressure_viscosity=7.6e-5",
            "lubricant.lubricant_parameter=9.9",
        ),
    ];
    for (deck, a, b) in cases {
        for (x, y) in [(a, b), (b, a)] {
            let (code, _, err) = run(&["check", deck, "--set", x, "--set", y]);
            assert_eq!(code, Some(1), "{deck} {x} {y}: {err}");
            let (kx, ky) = (x.split('=').next(), y.split('=').next());
            assert!(
                kx.is_some_and(|k| err.contains(k)) && ky.is_some_and(|k| err.contains(k)),
                "{err}"
            );
            assert!(err.contains("give one OR the other"), "{err}");
        }
        for x in [a, b] {
            let (code, _, err) = run(&["check", deck, "--set", x]);
            assert_eq!(code, Some(0), "{deck} {x}: {err}");
        }
    }
}

/// Item 15: a US range prints a bound the range itself accepts ("allowed ≤ 39.3701 in"
/// refused 39.3701): the printed upper bound of crown_gauge, set, is not out of range.
#[test]
fn printed_bound_is_accepted() {
    let (code, _, err) = run(&[
        "check",
        "decks/trb_afapl.toml",
        "--set",
        "geometry.crown_gauge=39.3702",
    ]);
    assert_eq!(code, Some(1), "{err}");
    let bound = err
        .split("≤ value ≤ ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .unwrap_or_else(|| panic!("{err}"));
    let set = format!("geometry.crown_gauge={bound}");
    let (_, _, err) = run(&["check", "decks/trb_afapl.toml", "--set", &set]);
    assert!(!err.contains("out of range"), "{bound}: {err}");
}

/// Item 15: no internal names ("use Deck::converted") in the refusal of `--set units`.
#[test]
fn units_refusal_names_no_internals() {
    let (code, _, err) = run(&["check", "decks/trb_afapl.toml", "--set", "units=si"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("units") && !err.contains("::"), "{err}");
}

/// Item 15: a sweep over ±1.797e308 neither prints 309-digit numbers nor says "NaN has
/// the wrong type" (B − A overflowed to inf, and the points were NaN).
#[test]
fn huge_sweep_ranges_are_worded() {
    for range in [
        "operating.inner_speed=-1.797e308:1.797e308:x3",
        "operating.inner_speed=-1.797e308:1.797e308:1e307",
        "operating.inner_speed=1e300:2e300:x3",
    ] {
        let (code, _, err) = run(&["sweep", "decks/trb_afapl.toml", "--set-range", range]);
        assert_eq!(code, Some(1), "{range}: {err}");
        assert!(!err.contains("0000000000000000"), "{range}: {err}");
        assert!(!err.contains("wrong type"), "{range}: {err}");
        assert_readable(&err);
        assert!(err.len() < 1000, "{range}: {err}");
    }
}

/// Item 15: a 200 KB line is not echoed whole (the syntax error's snippet, a value as
/// written, a key): at most a window with an ellipsis and the length.
#[test]
fn long_lines_are_clipped() {
    let dir = std::env::temp_dir().join(format!("rollbench-msg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let base = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("decks/trb_afapl.toml"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let long = "x".repeat(200_000);
    let decks = [
        format!("{base}\nbogus = {long}\n"),
        base.replace("name = \"", &format!("name = \"{long}"))
            .replace("radial_load = 0.0", &format!("radial_load = \"{long}\"")),
    ];
    for (i, text) in decks.iter().enumerate() {
        let path = dir.join(format!("long{i}.toml"));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
        let p = path.to_string_lossy().into_owned();
        let (code, _, err) = run(&["check", &p]);
        assert_eq!(code, Some(1), "{i}");
        assert!(err.len() < 2000, "{i}: {} bytes", err.len());
        assert!(err.contains("characters"), "{i}: {err}");
    }
    // One argument is at most 128 KiB on Linux: a 100 000-character key.
    let key = format!("operating.{}=1", &long[..100_000]);
    let (code, _, err) = run(&["check", "decks/trb_afapl.toml", "--set", &key]);
    assert_eq!(code, Some(1));
    assert!(err.len() < 5000, "{} bytes", err.len());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Item 16: an unknown `--type` value is a usage error (64), as the README says and as
/// `--format xml` is.
#[test]
fn unknown_type_is_a_usage_error() {
    for cmd in ["template", "keys"] {
        let (code, _, err) = run(&[cmd, "--type", "foo"]);
        assert_eq!(code, Some(64), "{cmd}: {err}");
        assert!(err.contains("unknown bearing system"), "{err}");
    }
    let (code, _, _) = run(&["run", "decks/chen_a.toml", "--format", "xml"]);
    assert_eq!(code, Some(64));
    let readme =
        std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
            .unwrap_or_else(|e| panic!("{e}"));
    assert!(readme.contains("| 64 | usage error (unknown option or value"));
}

/// Item 16: `stiffness --help` says what the CSV holds: deck units (it said SI), as the
/// CSV's own unit columns show (lbf/in on the US sample).
#[test]
fn stiffness_help_matches_its_csv() {
    let (code, help, _) = run(&["stiffness", "--help"]);
    assert_eq!(code, Some(0));
    assert!(help.contains("csv in the deck's units"), "{help}");
    assert!(!help.contains("csv (SI)"), "{help}");
    let (code, csv, err) = run(&["stiffness", "decks/trb_afapl.toml", "--format", "csv"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(csv.contains("lbf/in"), "{csv}");
}
