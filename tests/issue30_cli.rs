//! Issue 30 item 17 through the binary: `keys` without `--type` names its system and
//! lists every system's keys grouped; long choice lists are wrapped in their column;
//! `bench` on a deck whose answer does not depend on the grid says so.

use std::process::Command;

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rollbench"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const TYPES: [&str; 5] = [
    "spherical-roller",
    "angular-contact-ball",
    "tapered-roller",
    "cylindrical-roller",
    "double-row-spherical-roller",
];

/// `keys` alone: the first line names the default system; its table follows unchanged
/// (what it printed before), then every other system's table under a line naming it,
/// each equal to `keys --type` of that system.
#[test]
fn keys_without_type_names_and_groups_every_system() {
    let (code, out, _) = run(&["keys"]);
    assert_eq!(code, Some(0));
    let first = out.lines().next().unwrap_or_default();
    assert!(
        first.contains("spherical-roller") && first.contains("default"),
        "{first}"
    );
    let mut parts = out.split("\nkeys of the ");
    let head = parts.next().unwrap_or_default();
    let (_, spherical) = head.split_once('\n').expect("a table after the first line");
    let (_, own, _) = run(&["keys", "--type", "spherical-roller"]);
    assert_eq!(spherical.trim_end(), own.trim_end());
    let mut seen = vec!["spherical-roller"];
    for part in parts {
        let (title, table) = part.split_once('\n').expect("a table");
        let id = title.split_whitespace().next().unwrap_or_default();
        let (_, own, _) = run(&["keys", "--type", id]);
        assert_eq!(table.trim_end(), own.trim_end(), "{id}");
        seen.push(id);
    }
    seen.sort();
    let mut all = TYPES.to_vec();
    all.sort();
    assert_eq!(seen, all);
}

/// Long choice lists stay in their column: no line of any system's table runs its SI
/// column into the US one (the US column starts at character 78 on every line that
/// reaches it), and every choice is still printed, in both columns.
#[test]
fn keys_wraps_long_choice_lists() {
    for t in TYPES {
        let (code, out, _) = run(&["keys", "--type", t]);
        assert_eq!(code, Some(0));
        for line in out.lines() {
            let chars: Vec<char> = line.chars().collect();
            let is_table_row =
                chars.len() > 78 && !line.contains("the [") && !line.starts_with("materials.");
            if is_table_row {
                assert_eq!(chars[77], ' ', "{t}: the SI column runs over:\n{line}");
            }
        }
    }
    // The ball's traction curve: a list longer than the column, every name kept.
    let (_, out, _) = run(&["keys", "--type", "angular-contact-ball"]);
    let block: String = out
        .lines()
        .skip_while(|l| !l.starts_with("traction.curve "))
        .take_while(|l| l.starts_with("traction.curve ") || l.starts_with(' '))
        .collect::<Vec<_>>()
        .join("\n");
    assert!(block.lines().count() > 1, "not wrapped:\n{block}");
    for name in [
        "constant", "curve-1", "curve-2", "curve-3", "table", "rheology",
    ] {
        assert_eq!(block.matches(name).count(), 2, "{name}:\n{block}");
    }
}

/// Ball `bench` on the shipped race-control deck: every error is 0 (race control slices
/// nothing), and the output says so and names the methods that slice, in text and JSON.
#[test]
fn ball_bench_on_race_control_says_it_measures_nothing() {
    let (code, out, err) = run(&["bench", "decks/chen_b.toml", "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let why = v["measures_nothing"].as_str().unwrap_or_default();
    assert!(
        why.contains("race-control") && why.contains("dynamics.method=quasi-static"),
        "{why}"
    );
    for r in v["rows"].as_array().expect("rows") {
        for (k, e) in r.as_object().expect("row") {
            if k.starts_with("err_") {
                assert!(e.as_f64().is_none_or(|x| x == 0.0), "{k} {e}");
            }
        }
    }
    // A method that slices measures something: no such line.
    let (code, out, err) = run(&[
        "bench",
        "decks/chen_b.toml",
        "--set",
        "dynamics.method=quasi-static",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!out.contains("measures nothing"), "{out}");
}
