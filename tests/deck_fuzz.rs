//! Deck fuzzer (issue 7): random bytes and random mutations of the shipped deck texts —
//! deleted, duplicated and swapped lines, numbers replaced by extreme, negative, NaN and
//! infinite strings, random keys — must never make `Deck::parse` (nor the `[thermal]`
//! parser behind `rollbench check`) panic: the result is Ok or an error with a message.
//! Through the binary, `rollbench check` on mutated files exits 0 or 1, never 101.
//!
//! Case counts: 512 random-byte cases, 1024 mutation cases (each up to 6 mutations), 2000
//! seeded mutants classified (accepted ones also solved), and 24 mutated files through
//! `rollbench check`. Run once by hand at 10 000 random-byte and 20 000 mutation cases:
//! no panic.

mod common;

use proptest::prelude::*;
use proptest::test_runner::Config;
use rollbench::bearings::spherical_roller::deck as sr_deck;

fn shipped() -> Vec<(String, String)> {
    let files = common::toml_files("decks");
    files
        .into_iter()
        .map(|p| {
            (
                p.display().to_string(),
                std::fs::read_to_string(&p).unwrap_or_default(),
            )
        })
        .collect()
}

/// Replacement values for a number: extreme, negative, non-finite, malformed.
const WEIRD: [&str; 22] = [
    "0",
    "-0",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "+inf",
    "NaN",
    "1e999",
    "9999999999999999999999",
    "-9223372036854775809",
    "0x10",
    "1_000",
    "\"12\"",
    "[1, 2]",
    "{ a = 1 }",
    "",
];

/// Random keys to insert.
const KEYS: [&str; 8] = [
    "laminae",
    "geometry.roller_count",
    "zzz",
    "units",
    "[solver]",
    "[[thermal.nodes]]",
    "[geometry]",
    "thermal.transient.duration",
];

#[derive(Debug, Clone)]
enum Mutation {
    Delete(usize),
    Duplicate(usize),
    Swap(usize, usize),
    /// Replace the value after `=` on a line with a weird value.
    Number(usize, usize),
    /// Insert `key = value` (or a table header) before a line.
    Key(usize, usize, usize),
    /// Flip one byte of the text to a random ASCII character.
    Byte(usize, u8),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::Delete),
        any::<usize>().prop_map(Mutation::Duplicate),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::Swap(a, b)),
        (any::<usize>(), 0..WEIRD.len()).prop_map(|(a, b)| Mutation::Number(a, b)),
        (any::<usize>(), 0..KEYS.len(), 0..WEIRD.len())
            .prop_map(|(a, b, c)| Mutation::Key(a, b, c)),
        (any::<usize>(), 0u8..128).prop_map(|(a, b)| Mutation::Byte(a, b)),
    ]
}

fn apply(text: &str, muts: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for m in muts {
        let n = lines.len().max(1);
        match *m {
            Mutation::Delete(i) => {
                if !lines.is_empty() {
                    lines.remove(i % n);
                }
            }
            Mutation::Duplicate(i) => {
                if let Some(l) = lines.get(i % n).cloned() {
                    lines.insert(i % n, l);
                }
            }
            Mutation::Swap(a, b) => {
                if !lines.is_empty() {
                    lines.swap(a % n, b % n);
                }
            }
            Mutation::Number(i, w) => {
                if let Some(l) = lines.get_mut(i % n) {
                    if let Some((k, _)) = l.split_once('=') {
                        *l = format!("{k}= {}", WEIRD[w]);
                    }
                }
            }
            Mutation::Key(i, k, w) => {
                let key = KEYS[k];
                let line = if key.starts_with('[') {
                    key.to_string()
                } else {
                    format!("{key} = {}", WEIRD[w])
                };
                lines.insert(i % (lines.len() + 1), line);
            }
            Mutation::Byte(i, b) => {
                let mut bytes = lines.join("\n").into_bytes();
                if !bytes.is_empty() {
                    let k = i % bytes.len();
                    bytes[k] = b;
                }
                lines = String::from_utf8_lossy(&bytes)
                    .lines()
                    .map(str::to_string)
                    .collect();
            }
        }
    }
    lines.join("\n")
}

/// What `rollbench check` does, in-process: parse, then the `[thermal]` section.
fn check_in_process(text: &str) -> Result<(), String> {
    let deck = sr_deck::parse(text, "fuzz.toml").map_err(|e| e.to_string())?;
    deck.thermal_model().map(|_| ()).map_err(|e| e.to_string())
}

/// As [`check_in_process`] for a deck of any system (its `type` picks the reader; every
/// system builds its `[thermal]` network when it loads the deck).
fn check_any_in_process(text: &str) -> Result<(), String> {
    rollbench::bearings::load_case(text, "fuzz.toml", &[])
        .map(|_| ())
        .map_err(|e| e.to_string())
}

proptest! {
    #![proptest_config(Config { cases: 512, ..Config::default() })]
    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..2048)) {
        let text = String::from_utf8_lossy(&bytes);
        // Ok or an error with a non-empty message.
        if let Err(e) = check_in_process(&text) {
            prop_assert!(!e.is_empty());
        }
    }
}

proptest! {
    #![proptest_config(Config { cases: 1024, ..Config::default() })]
    #[test]
    fn mutated_decks_never_panic(deck in 0usize..64, muts in proptest::collection::vec(mutation(), 1..=6)) {
        let decks = shipped();
        prop_assume!(!decks.is_empty());
        let (_, text) = &decks[deck % decks.len()];
        let mutated = apply(text, &muts);
        match check_in_process(&mutated) {
            Ok(()) => {}
            Err(e) => prop_assert!(e.contains("fuzz.toml") || !e.is_empty(), "{e}"),
        }
    }
}

#[test]
fn mutations_change_the_text() {
    // The mutator must actually mutate, or the fuzzer tests nothing: a Number mutation on
    // a key line changes it, and an invalid value is rejected with a message naming the key.
    let text = "units = \"si\"\nname = \"x\"";
    let m = apply(text, &[Mutation::Number(1, 7)]);
    assert_eq!(m, "units = \"si\"\nname = nan");
    let decks = shipped();
    let (_, aero) = decks
        .iter()
        .find(|(n, _)| n.ends_with("aerospace.toml"))
        .cloned()
        .unwrap_or_default();
    let line = aero
        .lines()
        .position(|l| l.starts_with("roller_count"))
        .unwrap_or(0);
    let bad = apply(&aero, &[Mutation::Number(line, 7)]);
    let err = check_in_process(&bad).err().unwrap_or_default();
    assert!(err.contains("roller_count"), "{err}");
}

#[test]
fn check_exits_0_or_1_on_mutated_files() {
    use assert_cmd::Command;
    use proptest::strategy::ValueTree;
    let decks = shipped();
    assert!(!decks.is_empty());
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("tempdir: {e}"));
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = proptest::collection::vec(mutation(), 1..=4);
    let mut codes = [0usize; 2];
    for i in 0..24 {
        let muts = strategy
            .new_tree(&mut runner)
            .map(|t| t.current())
            .unwrap_or_default();
        let (_, text) = &decks[i % decks.len()];
        let path = dir.path().join(format!("fuzz{i}.toml"));
        std::fs::write(&path, apply(text, &muts)).unwrap_or_else(|e| panic!("write: {e}"));
        let out = Command::cargo_bin("rollbench")
            .unwrap_or_else(|e| panic!("binary: {e}"))
            .arg("check")
            .arg(&path)
            .output()
            .unwrap_or_else(|e| panic!("run: {e}"));
        let code = out.status.code();
        assert!(
            matches!(code, Some(0) | Some(1)),
            "exit {code:?} on {}: {}",
            path.display(),
            String::from_utf8_lossy(&out.stderr)
        );
        if code == Some(1) {
            assert!(!out.stderr.is_empty(), "exit 1 without a message");
        }
        codes[usize::from(code == Some(1))] += 1;
    }
    // Both outcomes occur in 24 mutated decks (seeded runner: deterministic).
    println!(
        "rollbench check on 24 mutated files: {} ok, {} rejected",
        codes[0], codes[1]
    );
}

#[test]
fn mutation_outcome_mix() {
    // The fuzzer must reach past the TOML parser: of 2000 seeded mutants, some are accepted,
    // some fail TOML syntax and some fail the deck rules (types, ranges, keys, cross-field,
    // thermal). Accepted mutants are solved and must not panic. Counts are printed for the
    // record (--nocapture).
    use proptest::strategy::ValueTree;
    let decks = shipped();
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = (0usize..64, proptest::collection::vec(mutation(), 1..=6));
    let (mut ok, mut syntax, mut rules) = (0usize, 0usize, 0usize);
    for _ in 0..2000 {
        let Ok(tree) = strategy.new_tree(&mut runner) else {
            continue;
        };
        let (d, muts) = tree.current();
        let (_, text) = &decks[d % decks.len()];
        match check_in_process(&apply(text, &muts)) {
            Ok(()) => {
                ok += 1;
                // An accepted mutant is a valid deck: the solver must not panic on it
                // (Ok or a typed error).
                let text = apply(text, &muts);
                let solved = std::panic::catch_unwind(|| {
                    sr_deck::parse(&text, "fuzz.toml").map(|d| {
                        rollbench::bearings::spherical_roller::pipeline::run(
                            &d.value,
                            &Default::default(),
                            None,
                        )
                        .is_ok()
                    })
                });
                assert!(
                    solved.is_ok(),
                    "solver panicked on an accepted mutant:\n{text}"
                );
            }
            Err(e) if e.contains("malformed TOML") => syntax += 1,
            Err(_) => rules += 1,
        }
    }
    println!(
        "2000 mutants: {ok} accepted, {syntax} malformed TOML, {rules} rejected by deck rules"
    );
    assert!(ok > 0 && syntax > 0 && rules > 0, "{ok} {syntax} {rules}");
}

// ------------------------------------------------------------ --set combinations

/// Keys `--set` is tried on, each with values that pass and values that do not
/// (`geometry.roller_count` must be an integer in range, crown radii interact through the
/// cross-field rules, `thermal.…` is checked by the `[thermal]` parser), plus keys that do
/// not exist and an assignment without `=`.
const SET_KEYS: [(&str, &[&str]); 12] = [
    (
        "geometry.roller_count",
        &["16", "18", "0", "-3", "2.5", "100000"],
    ),
    ("geometry.roller_crown_radius", &["20", "0.2", "0", "-1"]),
    ("geometry.inner_crown_radius", &["20", "0.2", "nan"]),
    ("geometry.outer_crown_radius", &["20", "0.2", "inf"]),
    ("operating.inner_speed", &["10000", "0", "-5", "1e12"]),
    ("operating.axial_load", &["500", "0", "-1", "\"x\""]),
    ("solver.force_tolerance", &["1e-6", "1e-4", "0.05", "0"]),
    ("thermal.transient.duration", &["600", "-1", "1e20", "nan"]),
    ("thermal.transient.step", &["1", "0", "1e-12"]),
    ("geometry.roler_count", &["16"]),
    ("zzz.unknown", &["1"]),
    ("no-equals-sign", &[""]),
];

/// A `--set` list: distinct keys (so that order could only matter through validation),
/// each with one of its values, in random order.
fn set_list() -> impl Strategy<Value = Vec<String>> {
    proptest::sample::subsequence((0..SET_KEYS.len()).collect::<Vec<_>>(), 1..=5)
        .prop_flat_map(|keys| {
            let values: Vec<_> = keys
                .iter()
                .map(|&k| (Just(k), 0..SET_KEYS[k].1.len()))
                .collect();
            values
        })
        .prop_map(|kv| {
            kv.into_iter()
                .map(|(k, v)| {
                    let (key, values) = SET_KEYS[k];
                    if key == "no-equals-sign" {
                        key.to_string()
                    } else {
                        format!("{key}={}", values[v])
                    }
                })
                .collect::<Vec<_>>()
        })
        .prop_shuffle()
}

/// Applies `sets` to the aerospace deck, then builds its `[thermal]` model (what `run`
/// does): the resulting bearing and thermal table, or the error text.
fn apply_sets(sets: &[String]) -> Result<String, String> {
    let mut deck = sr_deck::parse(sr_deck::DEFAULT_DECK, "aero.toml").map_err(|e| e.to_string())?;
    sr_deck::apply(&mut deck, sets).map_err(|e| e.to_string())?;
    deck.thermal_model().map_err(|e| e.to_string())?;
    Ok(format!(
        "{:?}\n{:?}",
        deck.value,
        deck.opaque.get("thermal")
    ))
}

proptest! {
    #![proptest_config(Config { cases: 192, ..Config::default() })]
    /// Random `--set` lists never panic; a rejected list names one of its keys (or the
    /// `[thermal]` field); and the verdict, and an accepted deck, do not depend on the
    /// order of the assignments.
    #[test]
    fn set_combinations_never_panic_and_ignore_order(sets in set_list()) {
        let forward = apply_sets(&sets);
        let mut reversed = sets.clone();
        reversed.reverse();
        let backward = apply_sets(&reversed);
        match (&forward, &backward) {
            (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
            (Err(e), Err(_)) => {
                let named = sets.iter().any(|s| {
                    let key = s.split_once('=').map_or(s.as_str(), |(k, _)| k);
                    let last = key.rsplit('.').next().unwrap_or(key);
                    e.contains(key) || e.contains(&format!("'{last}'"))
                });
                prop_assert!(named, "{sets:?}: {e}");
            }
            _ => prop_assert!(false, "order changed the verdict: {sets:?}\n{forward:?}\n{backward:?}"),
        }
    }
}

// ------------------------------------------------------------ [thermal] fields

/// Numbers tried in every numeric field of the shipped `[thermal]` sections.
const THERMAL_WEIRD: [&str; 9] = [
    "0", "-0", "-1", "-1e-300", "1e308", "5e-324", "nan", "inf", "-inf",
];

/// Every numeric field of every shipped `[thermal]` section, set to each weird number:
/// `[thermal]` never panics, and a field the parser rejects is named with its line.
#[test]
fn thermal_fields_mutated_never_panic_and_are_named() {
    let (mut tried, mut rejected) = (0usize, 0usize);
    for (name, text) in shipped() {
        let lines: Vec<&str> = text.lines().collect();
        let Some(start) = lines.iter().position(|l| l.trim() == "[thermal]") else {
            continue;
        };
        for (i, line) in lines.iter().enumerate().skip(start) {
            let Some((key, value)) = line.split_once('=') else {
                continue;
            };
            let value = value.split('#').next().unwrap_or("").trim();
            if value.parse::<f64>().is_err() {
                continue; // strings, arrays, booleans
            }
            let field = key.trim();
            for weird in THERMAL_WEIRD {
                let mut mutated = lines.clone();
                let new_line = format!("{field} = {weird}");
                mutated[i] = &new_line;
                let mutated = mutated.join("\n");
                tried += 1;
                // Every system's deck now carries a network (chen_b, the lubricated
                // tapered deck): read each by its own system.
                let outcome = std::panic::catch_unwind(|| check_any_in_process(&mutated));
                let Ok(result) = outcome else {
                    panic!("{name}: {field} = {weird} (line {}) panicked", i + 1);
                };
                let Err(e) = result else { continue };
                rejected += 1;
                // A bad number is named as the field it is in, at its line; a legal number
                // that makes the network invalid names the node or link.
                let bad = weird
                    .parse::<f64>()
                    .map_or(true, |v| !(v.is_finite() && v >= 0.0));
                if e.contains(&format!("'{field}'")) {
                    assert!(
                        e.contains(&format!("fuzz.toml:{}:", i + 1))
                            || e.contains("duration / step"),
                        "{name}: {field} = {weird}: error not at line {}: {e}",
                        i + 1
                    );
                } else {
                    assert!(
                        !bad || field == "duration",
                        "{name}: {field} = {weird}: field not named: {e}"
                    );
                    assert!(
                        e.contains("node") || e.contains("link") || e.contains("step"),
                        "{name}: {field} = {weird}: {e}"
                    );
                }
            }
        }
    }
    println!("[thermal] fields: {tried} mutants, {rejected} rejected");
    assert!(tried > 100 && rejected > 0, "{tried} {rejected}");
}
