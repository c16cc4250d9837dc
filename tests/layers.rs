//! The layers run one way (issue 23): front ends → studies / verify / report → bearings →
//! deck → thermal → physics → numerics / units / files / pipeline. No non-test code of a
//! lower layer names a higher one (`crate::X` with X above it), and no bearing system's
//! folder names another system's, except the edges of [`BUILT_ON`]. Test code may reach up for fixtures (a physics test
//! builds the aerospace bearing), so `#[cfg(test)]` modules and `*tests.rs` files are not
//! read.
//!
//! The same graph by hand: `grep -rn "crate::" src --include=*.rs`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A system built on another system's machinery, by design (the one exception to "no
/// system names another"): the double-row spherical roller is the single-row spherical
/// roller's lamina solver with a row layout, as issue 27 asks ("reuse the spherical
/// roller's lamina machinery rather than copying it: where the single-row code is in the
/// way, generalise it"). One direction only: the single-row system never names it.
const BUILT_ON: &[(&str, &str)] = &[("double_row_spherical", "spherical_roller")];

/// Rank of each top-level module of `src/`: a module may name only lower ranks.
const LAYERS: &[(&str, u32)] = &[
    ("units", 0),
    ("numerics", 0),
    ("files", 0),
    ("pipeline", 0),
    ("physics", 1),
    ("thermal", 2),
    ("deck", 3),
    ("bearings", 4),
    ("report", 5),
    ("verify", 5),
    ("studies", 5),
    ("cli", 6),
    ("tui", 7),
    ("main", 8),
    ("lib", 9),
];

fn rank(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|(_, r)| *r)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The non-test code of a file: up to its first `#[cfg(test)]`, comment lines dropped.
fn non_test_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .take_while(|(_, l)| !l.trim_start().starts_with("#[cfg(test)]"))
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .map(|(i, l)| (i + 1, l))
}

/// Every `crate::NAME` (and `crate::bearings::NAME`) named on a line.
fn named_after<'a>(line: &'a str, prefix: &str) -> Vec<&'a str> {
    let mut found = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find(prefix) {
        let tail = &rest[i + prefix.len()..];
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(tail.len());
        found.push(&tail[..end]);
        rest = &tail[end..];
    }
    found
}

#[test]
fn lower_layers_never_name_higher_ones() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    assert!(files.len() > 50, "read {} files", files.len());
    // Each folder under src/bearings/ is a bearing system.
    let systems: Vec<String> = std::fs::read_dir(src.join("bearings"))
        .map(|d| {
            d.flatten()
                .filter(|e| e.path().is_dir())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    assert!(systems.len() >= 3, "{systems:?}");
    let mut wrong: Vec<String> = Vec::new();
    let mut graph: BTreeMap<(String, String), usize> = BTreeMap::new();
    for path in &files {
        let rel = path.strip_prefix(&src).unwrap_or(path);
        let name = rel.to_string_lossy().replace('\\', "/");
        if name.ends_with("tests.rs") || name.contains("/tests/") {
            continue;
        }
        let top = name
            .split('/')
            .next()
            .unwrap_or("")
            .trim_end_matches(".rs")
            .to_string();
        let Some(from) = rank(&top) else {
            wrong.push(format!(
                "{name}: top-level module `{top}` has no layer in LAYERS"
            ));
            continue;
        };
        let system = systems
            .iter()
            .find(|s| name.starts_with(&format!("bearings/{s}/")));
        let text = std::fs::read_to_string(path).unwrap_or_default();
        for (line_no, line) in non_test_lines(&text) {
            for to in named_after(line, "crate::") {
                if to == top || to.starts_with("__") {
                    continue;
                }
                *graph.entry((top.clone(), to.to_string())).or_default() += 1;
                match rank(to) {
                    Some(r) if r < from => {}
                    _ => wrong.push(format!("{name}:{line_no}: {top} names crate::{to}")),
                }
            }
            if let Some(own) = system {
                for other in named_after(line, "bearings::") {
                    let built_on = BUILT_ON.contains(&(own.as_str(), other));
                    if systems.iter().any(|s| s == other) && other != own.as_str() && !built_on {
                        wrong.push(format!("{name}:{line_no}: {own} names bearings::{other}"));
                    }
                }
            }
        }
    }
    let edges: Vec<String> = graph
        .iter()
        .map(|((a, b), n)| format!("{a} -> {b} ({n})"))
        .collect();
    assert!(
        wrong.is_empty(),
        "imports against the layers:\n{}\n\nthe graph:\n{}",
        wrong.join("\n"),
        edges.join("\n")
    );
    // The graph is not empty: the reader found the imports it checks.
    assert!(graph.contains_key(&("bearings".to_string(), "physics".to_string())));
}
