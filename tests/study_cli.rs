//! `rollbench study` through the real binary (issue 32): a study file run locally, the same
//! study as shards merged back byte for byte, the merge's refusals (exit 1, naming the
//! part), a bad study file refused at its line, and the shipped example studies' files
//! read and checked against their decks.

use assert_cmd::Command;
use std::path::Path;

/// (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    let out = match Command::cargo_bin("rollbench") {
        Ok(mut c) => c.args(args).output(),
        Err(e) => panic!("{e}"),
    };
    let out = match out {
        Ok(o) => o,
        Err(e) => panic!("{e}"),
    };
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn write_study(dir: &Path) -> String {
    let deck = format!("{}/decks/trb_afapl.toml", env!("CARGO_MANIFEST_DIR"));
    let path = dir.join("t.study.toml");
    let text = format!(
        "deck = \"{deck}\"\noutputs = [\"max_stress_pa\", \"l10_bearing_mrev\"]\n\
         [sample]\nmethod = \"latin-hypercube\"\nsamples = 12\nseed = 9\n\
         operating.radial_load = {{ uniform = [0.0, 800.0] }}\n\
         operating.axial_load = {{ tolerance = [3000.0, 150.0], shape = \"truncated-normal\" }}\n"
    );
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    path.display().to_string()
}

#[test]
fn study_runs_locally_and_sharded_parts_merge_to_the_same_csv() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let study = write_study(dir.path());
    let (code, csv, err) = run(&["study", &study, "--format", "csv"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(csv.lines().count(), 13, "{csv}");
    assert!(csv.starts_with(
        "index,operating.radial_load [lbf],operating.axial_load [lbf],max_stress_pa,l10_bearing_mrev,failure\n"
    ));
    // The summary went to standard error.
    assert!(err.contains("sensitivities"), "{err}");
    let mut parts = Vec::new();
    for i in 0..3 {
        let part = dir
            .path()
            .join(format!("part-{i}.jsonl"))
            .display()
            .to_string();
        let (code, _, err) = run(&[
            "study",
            &study,
            "--shard",
            &format!("{i}/3"),
            "--output",
            &part,
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(err.contains(&format!("shard {i}/3: 4 points")), "{err}");
        parts.push(part);
    }
    let out = dir.path().join("merged.csv").display().to_string();
    let mut args = vec!["study", "merge"];
    args.extend(parts.iter().map(String::as_str));
    args.extend(["--format", "csv", "--output", &out]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&out).unwrap_or_default(), csv);
    // A part missing: refused, naming the missing indices, nothing written.
    let (code, _, err) = run(&["study", "merge", &parts[0], &parts[1], "--format", "csv"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("4 of 12 indices are missing: 2, 5, 8, 11"),
        "{err}"
    );
}

#[test]
fn a_bad_study_file_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("bad.study.toml");
    std::fs::write(&path, "deck = \"x.toml\"\n[grid]\na = [1]\n[grd]\n")
        .unwrap_or_else(|e| panic!("{e}"));
    let (code, _, err) = run(&["study", &path.display().to_string()]);
    assert_eq!(code, 1);
    assert!(
        err.contains("bad.study.toml:4:2: unknown key `grd`"),
        "{err}"
    );
    let (code, _, err) = run(&[
        "study",
        &path.display().to_string(),
        "--shard",
        "3/3",
        "--output",
        "p.jsonl",
    ]);
    assert_eq!(code, 64, "{err}");
}

#[test]
fn shipped_example_studies_read_against_their_decks() {
    // Every example names real keys and outputs of its deck (checked by one solve of the
    // deck each, not by running the study).
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("decks/studies");
    let mut systems = std::collections::BTreeSet::new();
    let mut designs = std::collections::BTreeSet::new();
    for e in std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{e}"))
        .flatten()
    {
        let p = e.path();
        let s = rollbench::studies::study::prepare(&p)
            .unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        assert!(s.plan.len() <= 100, "{}: keep examples small", p.display());
        systems.insert(s.header.system.clone());
        designs.insert(s.header.design.clone());
    }
    assert_eq!(
        systems.len(),
        rollbench::bearings::SYSTEMS.len(),
        "{systems:?}"
    );
    assert_eq!(designs.len(), 3, "{designs:?}");
}
