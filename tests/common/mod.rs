//! Helpers shared by the integration tests. Each test crate uses a part of them.
#![allow(dead_code)]

pub mod serde_diff;

use std::path::{Path, PathBuf};

/// The `.toml` files of `dir` (relative to the crate root), sorted.
pub fn toml_files(dir: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|rd| {
            rd.filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

/// A shipped deck's path (`decks/NAME`), for the CLI tests.
pub fn deck(name: &str) -> String {
    format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// `rollbench ARGS…` through the built binary: (exit code, -1 for a signal; stdout;
/// stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let mut cmd = match assert_cmd::Command::cargo_bin("rollbench") {
        Ok(c) => c,
        Err(e) => panic!("{e}"),
    };
    let out = match cmd.args(args).output() {
        Ok(o) => o,
        Err(e) => panic!("{e}"),
    };
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
