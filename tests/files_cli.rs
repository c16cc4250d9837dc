//! A user's files are never lost or silently replaced (issue 24, items 1–6), through the
//! real binary: outputs naming a standard stream, two outputs that are one file, planted
//! links, half-done writes and signals, FIFOs without a reader, failed runs.
#![cfg(unix)]

use std::fs::{self, File, OpenOptions};
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn exe() -> PathBuf {
    assert_cmd::cargo::cargo_bin("rollbench")
}

fn deck(name: &str) -> String {
    format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_default()
}

fn write(path: &Path, text: &str) {
    fs::write(path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

/// Temporary files left in `dir` (any name holding `.tmp`).
fn temporaries(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .map(|r| {
            r.filter_map(Result::ok)
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.contains(".tmp"))
                .collect()
        })
        .unwrap_or_default()
}

/// Runs the binary in `dir` with `args`, standard output appended to `stdout` (as a
/// shell's `>>`) or truncating it (`>`), and standard error captured: (exit code, stderr).
fn run_redirected(dir: &Path, args: &[&str], stdout: &Path, append: bool) -> (i32, String) {
    let mut opts = OpenOptions::new();
    if append {
        opts.append(true);
    } else {
        opts.write(true).truncate(true).create(true);
    }
    let out = opts.open(stdout).unwrap_or_else(|e| panic!("{e}"));
    let o = Command::new(exe())
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::from(out))
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Runs the binary in `dir`: (exit code, stdout, stderr).
fn run_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let o = Command::new(exe())
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Bearing B's time simulation over one orbit: a short `--series` (20 balls × 91 rows).
const SERIES_SETS: [&str; 4] = [
    "--set",
    "dynamics.method=time-simulation",
    "--set",
    "dynamics.orbits=1",
];

/// Item 1: `--output` naming standard output (`/dev/stdout`, `/dev/fd/1`,
/// `/proc/self/fd/1`, a link to `/dev/stdout`, the appended file itself) while the shell
/// appends standard output to `log.txt`: the file keeps `keep` and gets the CSV after it,
/// and it is still the same file (same inode: never replaced by a rename). Same for
/// `stiffness`, `sweep` and `--series`, and for `/dev/stderr` with standard error
/// appended. (Before: `log.txt` held only the CSV.)
#[test]
fn output_to_a_standard_stream_appends_to_it() {
    use std::os::unix::fs::MetadataExt;
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let log = dir.path().join("log.txt");
    let link = dir.path().join("to-stdout");
    std::os::unix::fs::symlink("/dev/stdout", &link).unwrap_or_else(|e| panic!("{e}"));
    let (a, t) = (deck("chen_a.toml"), deck("trb_afapl.toml"));
    let (link, log_s) = (link.to_string_lossy(), log.to_string_lossy());
    let mut cases: Vec<(Vec<&str>, &str)> = Vec::new();
    for out in ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1", &link, &log_s] {
        cases.push((vec!["run", &a, "--format", "csv", "--output", out], ""));
    }
    cases.push((
        vec![
            "stiffness",
            &t,
            "--format",
            "csv",
            "--output",
            "/dev/stdout",
        ],
        "",
    ));
    cases.push((
        vec![
            "sweep",
            &t,
            "--set-range",
            "operating.inner_speed=1000:2000:x2",
            "--format",
            "csv",
            "--output",
            "/dev/fd/1",
        ],
        "",
    ));
    let b = deck("chen_b.toml");
    let mut series = vec!["run", b.as_str(), "--output", "/dev/null"];
    series.extend(SERIES_SETS);
    series.extend(["--series", "/dev/stdout"]);
    cases.push((series, "time_s,ball,"));
    // Each command's output as printed with no --output (an empty `head`), or the
    // series' header.
    let plain = |args: &[&str]| {
        let args: Vec<&str> = match args.iter().position(|a| *a == "--output") {
            Some(at) => [&args[..at], &args[at + 2..]].concat(),
            None => args.to_vec(),
        };
        let (code, out, err) = run_in(dir.path(), &args);
        assert_eq!(code, 0, "{err}");
        out
    };
    for (args, head) in &cases {
        let expected = if head.is_empty() {
            plain(args)
        } else {
            head.to_string()
        };
        write(&log, "keep\n");
        let ino = fs::metadata(&log).map(|m| m.ino()).ok();
        let (code, err) = run_redirected(dir.path(), args, &log, true);
        assert_eq!(code, 0, "{args:?}: {err}");
        let text = read(&log);
        assert!(text.starts_with("keep\n"), "{args:?}: {text:.200}");
        assert!(text.lines().count() > 2, "{args:?}: {text:.200}");
        assert!(
            text["keep\n".len()..].starts_with(&expected),
            "{args:?}: {text:.200}"
        );
        assert_eq!(fs::metadata(&log).map(|m| m.ino()).ok(), ino, "{args:?}");
        assert!(temporaries(dir.path()).is_empty());
    }

    // Standard error appended to err.log, the report written to /dev/stderr.
    let errlog = dir.path().join("err.log");
    write(&errlog, "keep\n");
    let err = OpenOptions::new()
        .append(true)
        .open(&errlog)
        .unwrap_or_else(|e| panic!("{e}"));
    let o = Command::new(exe())
        .args(["run", &a, "--format", "csv", "--output", "/dev/stderr"])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::from(err))
        .status()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(o.success());
    let text = read(&errlog);
    let expected = plain(&["run", &a, "--format", "csv"]);
    assert_eq!(text, format!("keep\n{expected}"));

    // `run … --series /dev/stdout > out.txt`: the JSON report, then the series.
    let out = dir.path().join("out.txt");
    let mut args = vec!["run", b.as_str(), "--format", "json"];
    args.extend(SERIES_SETS);
    args.extend(["--series", "/dev/stdout"]);
    let (code, err) = run_redirected(dir.path(), &args, &out, false);
    assert_eq!(code, 0, "{err}");
    let text = read(&out);
    assert!(text.starts_with('{'), "{text:.200}");
    let at = text.find("time_s,ball,").unwrap_or(0);
    assert!(at > 0, "{text:.200}");
    let report: Result<serde_json::Value, _> = serde_json::from_str(&text[..at]);
    assert!(report.is_ok(), "{report:?}");
}

/// Item 2: two outputs that are one file, whether or not it exists yet (relative and
/// `./`, absolute, a link to the file not created yet), are refused before anything is
/// solved or written: exit 1, naming both, nothing created. (Before: exit 0 with the
/// series in `new.json`.)
#[test]
fn two_outputs_that_are_one_file_are_refused() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let b = deck("chen_b.toml");
    let abs = dir.path().join("new.json");
    std::os::unix::fs::symlink("new.json", dir.path().join("link.json"))
        .unwrap_or_else(|e| panic!("{e}"));
    let abs = abs.to_string_lossy();
    for series in ["./new.json", &abs, "link.json"] {
        let mut args = vec![
            "run",
            b.as_str(),
            "--format",
            "json",
            "--output",
            "new.json",
        ];
        args.extend(SERIES_SETS);
        args.extend(["--series", series]);
        let (code, _, err) = run_in(dir.path(), &args);
        assert_eq!(code, 1, "{series}: {err}");
        assert!(
            err.contains(&format!(
                "--series {series}: is the same file as --output new.json"
            )),
            "{err}"
        );
        assert!(!dir.path().join("new.json").exists());
    }
    // The deck by another name (a hard link) as --series.
    let copy = dir.path().join("deck.toml");
    write(&copy, &read(Path::new(&b)));
    fs::hard_link(&copy, dir.path().join("hard.toml")).unwrap_or_else(|e| panic!("{e}"));
    let (code, _, err) = run_in(dir.path(), &["run", "deck.toml", "--series", "hard.toml"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("deck being read"), "{err}");
    assert_eq!(read(&copy), read(Path::new(&b)));
}

/// Item 3: a link planted at the old temporary name `.out.json.tmp-PID` (the shell's
/// `exec` keeps the PID) is never followed: `victim.txt` keeps its text and `out.json`
/// gets the report. (Before: the report went into `victim.txt`.)
#[test]
fn a_planted_temporary_link_is_not_followed() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    write(&dir.path().join("victim.txt"), "victim\n");
    let script = format!(
        "ln -s victim.txt .out.json.tmp-$$ && exec '{}' run '{}' --output out.json",
        exe().display(),
        deck("chen_a.toml")
    );
    let o = Command::new("sh")
        .current_dir(dir.path())
        .args(["-c", &script])
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(read(&dir.path().join("victim.txt")), "victim\n");
    assert!(read(&dir.path().join("out.json")).contains("Chen"));
}

/// Item 4: `--output rep.json` with a `--series` that cannot be written (a missing
/// directory: refused before solving; `/dev/full`: fails on the write) exits 1 with
/// `rep.json` untouched and no temporary file left. (Before: `rep.json` was replaced.)
#[test]
fn a_failing_output_leaves_the_others_untouched() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let rep = dir.path().join("rep.json");
    write(&rep, "old\n");
    let b = deck("chen_b.toml");
    let mut cases = vec![("/nonexistent/s.csv", "does not exist")];
    if Path::new("/dev/full").exists() {
        cases.push(("/dev/full", "nothing was written"));
    }
    for (series, why) in cases {
        let mut args = vec![
            "run",
            b.as_str(),
            "--format",
            "json",
            "--output",
            "rep.json",
        ];
        args.extend(SERIES_SETS);
        args.extend(["--series", series]);
        let (code, _, err) = run_in(dir.path(), &args);
        assert_eq!(code, 1, "{err}");
        assert!(err.contains(&format!("--series {series}")), "{err}");
        assert!(err.contains(why), "{err}");
        assert_eq!(read(&rep), "old\n");
        assert!(temporaries(dir.path()).is_empty());
    }
}

/// Item 4, signals: SIGINT while the outputs are being written removes the temporary
/// files. Deterministic: `--series` is a FIFO whose reader never reads, so the write
/// blocks once the pipe is full (the series is ~300 KB, a pipe holds 64 KB) after the
/// report's temporary file is written (temporaries first, then in place, then renames);
/// the test sees that temporary file, sends SIGINT, and the process ends by the signal
/// with no temporary file and no `rep.json`.
#[test]
fn a_signal_while_writing_leaves_no_temporary_file() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let fifo = dir.path().join("series.fifo");
    let made = Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    // The reader opens (so the writer's open succeeds) and holds the pipe unread.
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || {
            let mut f = File::open(fifo).unwrap_or_else(|e| panic!("{e}"));
            std::thread::sleep(Duration::from_secs(30));
            let mut s = Vec::new();
            let _ = f.read_to_end(&mut s);
        })
    };
    let b = deck("chen_b.toml");
    let mut child = Command::new(exe())
        .current_dir(dir.path())
        .args(["run", &b, "--output", "rep.json"])
        .args(SERIES_SETS)
        .args(["--series", "series.fifo"])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    let start = Instant::now();
    let seen = loop {
        let t = temporaries(dir.path());
        if !t.is_empty() || start.elapsed() > Duration::from_secs(20) {
            break t;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    assert!(seen.iter().any(|n| n.starts_with(".rep.json.")), "{seen:?}");
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    assert!(killed.is_ok_and(|s| s.success()));
    let status = child.wait().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(status.signal(), Some(2), "{status:?}");
    assert!(
        temporaries(dir.path()).is_empty(),
        "{:?}",
        temporaries(dir.path())
    );
    assert!(!dir.path().join("rep.json").exists());
    drop(reader); // detached: it ends on its own
}

/// Item 5: `--output FIFO` with no reader does not block forever: it says on standard
/// error that it waits for a reader, and writes the report when one comes.
#[test]
fn output_to_a_fifo_waits_for_a_reader_and_says_so() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let fifo = dir.path().join("out.fifo");
    let made = Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let mut child = Command::new(exe())
        .args(["run", &deck("chen_a.toml"), "--format", "csv", "--output"])
        .arg(&fifo)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    let mut err = BufReader::new(child.stderr.take().unwrap_or_else(|| panic!("stderr")));
    let mut line = String::new();
    let _ = err.read_line(&mut line);
    assert!(
        line.starts_with(&format!("waiting for a reader on FIFO {}", fifo.display())),
        "{line}"
    );
    let text = read(&fifo);
    let status = child.wait().unwrap_or_else(|e| panic!("{e}"));
    assert!(status.success());
    assert!(text.starts_with("index,azimuth_deg,"), "{text:.200}");
}

/// Item 6: a sweep in which no point solves exits 2 and leaves an existing `--output`
/// file as it was, as `run` does; so does a `stiffness` whose solve fails, or whose deck
/// has no stiffness matrix. (Before: the sweep replaced `f.csv` with its failed rows.)
#[test]
fn a_failed_command_leaves_its_output_untouched() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let f = dir.path().join("f.csv");
    write(&f, "keep\n");
    let t = deck("trb_afapl.toml");
    let (code, _, err) = run_in(
        dir.path(),
        &[
            "sweep",
            &t,
            "--set-range",
            "operating.axial_load=-3000:-1000:1000",
            "--output",
            "f.csv",
        ],
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("f.csv is not written"), "{err}");
    assert_eq!(read(&f), "keep\n");
    for args in [
        vec![
            "stiffness",
            t.as_str(),
            "--set",
            "operating.axial_load=-3000",
            "--output",
            "f.csv",
        ],
        vec![
            "stiffness",
            "DECK_A",
            "--set",
            "operating.radial_load=8576",
            "--set",
            "operating.axial_load=100",
            "--output",
            "f.csv",
        ],
    ] {
        // A solve that fails (every system has a stiffness matrix now, issue 29 item 3):
        // 38 kN radial on 445 N axial separates the rings of the angular spherical roller
        // bearing (the solve says so).
        let a = deck("aerospace.toml");
        let args: Vec<&str> = args
            .iter()
            .map(|x| if *x == "DECK_A" { a.as_str() } else { x })
            .collect();
        let (code, _, err) = run_in(dir.path(), &args);
        assert_ne!(code, 0, "{args:?}: {err}");
        assert_eq!(read(&f), "keep\n", "{args:?}");
    }
    assert!(temporaries(dir.path()).is_empty());
}
