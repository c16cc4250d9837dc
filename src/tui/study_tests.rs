//! The Study pane (issue 32 item 5): its screens at three sizes, what it asks the worker
//! for, and a read-back of its numbers against `rollbench study --format json` of the
//! same study.

use std::path::PathBuf;
use std::sync::Arc;

use super::app::{AppEvent, Command, Pane, StudyRequest};
use super::tests::{ch, draw, run_sync_tolerant, shipped_app, snap};
use super::App;
use crate::studies::study::workbench::{self, Source, DEFAULT_SAMPLES};

/// The deck `stem` with its Study pane focused and its study run to the end.
fn study_app(stem: &str, w: u16, h: u16) -> App {
    let app = shipped_app(stem, "Study", w, h);
    let (_, p) = app.study.as_ref().expect("the study ran");
    assert!(p.finished, "{stem}: finished");
    assert!(p.error.is_none(), "{stem}: {:?}", p.error);
    app
}

/// The screen's text, one string per row.
fn screen(app: &App, w: u16, h: u16) -> Vec<String> {
    let t = draw(app, w, h);
    let buf = t.backend().buffer().clone();
    (0..h)
        .map(|y| (0..w).map(|x| buf[(x, y)].symbol().to_string()).collect())
        .collect()
}

/// Half a unit of the last digit `token` shows (`12.34` → 0.005, `1.234e9` → 5e5).
fn half_last_digit(token: &str) -> f64 {
    let (mantissa, exp) = match token.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().expect("exponent")),
        None => (token, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    0.5 * 10f64.powi(exp - decimals)
}

/// The numbers after `label ` on the screen's line holding `label `.
fn shown(rows: &[String], label: &str) -> String {
    rows.iter()
        .find_map(|r| {
            let at = r.find(&format!("{label} "))?;
            let rest = &r[at + label.len() + 1..];
            Some(rest.split([' ', '│']).next().unwrap_or("").to_string())
        })
        .unwrap_or_else(|| panic!("no `{label}` on screen:\n{}", rows.join("\n")))
}

#[test]
fn tui_study_pane_snapshots() {
    // The default tolerance study of an SI deck no study file names, at the three
    // sizes; the study files beside two decks (trb_32007's clearance tolerance Monte
    // Carlo, radial_si's speed × load grid). The US deck's default study is drawn by
    // `tui_snapshot_every_pane` (the embedded aerospace deck).
    for (w, h) in [(60, 20), (80, 24), (200, 50)] {
        let app = study_app("aerospace_si", w, h);
        let (_, p) = app.study.as_ref().expect("ran");
        assert_eq!(p.source, Source::Default);
        snap("study_aerospace_si", &app, w, h);
    }
    for (stem, file) in [
        ("trb_32007", "trb_32007_clearance_tolerance.study.toml"),
        ("radial_si", "radial_si_speed_load.study.toml"),
    ] {
        let app = study_app(stem, 80, 24);
        let (_, p) = app.study.as_ref().expect("ran");
        assert!(
            matches!(&p.source, Source::File(f) if f.ends_with(file)),
            "{stem}: {:?}",
            p.source
        );
        snap(&format!("study_{stem}"), &app, 80, 24);
    }
}

/// The numbers on screen for each output against the `summary` of a study's JSON.
fn check_screen_against(app: &mut App, json: &serde_json::Value, w: u16, h: u16) {
    let summary = &json["summary"];
    let (_, p) = app.study.clone().expect("ran");
    let header = &json["study"];
    let names: Vec<String> = header["outputs"]
        .as_array()
        .expect("outputs")
        .iter()
        .map(|o| o.as_str().expect("name").to_string())
        .collect();
    assert_eq!(p.header.outputs, names);
    let u = app.display_units;
    let mut compared = 0;
    for (o, name) in p.header.outputs.iter().enumerate() {
        app.study_output = o;
        let rows = screen(app, w, h);
        let s = &summary["outputs"][name];
        if s.is_null() {
            // No point has this output (the JSON's null): the pane says so.
            assert!(
                rows.iter().any(|r| r.contains("no point has a value")),
                "{name}: no value\n{}",
                rows.join("\n")
            );
            continue;
        }
        let q = p.quantities[o];
        let conv = |v: f64| q.map_or(v, |q| q.from_si(v, u));
        let scale = |v: f64| q.map_or(v, |q| v / q.factor(u));
        let check = |label: &str, want: f64| {
            let tok = shown(&rows, label);
            let got: f64 = tok
                .parse()
                .unwrap_or_else(|_| panic!("{name} {label}: `{tok}`"));
            let tol = half_last_digit(&tok) * (1.0 + 1e-9);
            assert!(
                (got - want).abs() <= tol,
                "{name} {label}: screen {tok}, JSON {want} (± {tol})"
            );
        };
        check("mean", conv(s["mean"].as_f64().expect("mean")));
        check("σ", scale(s["sigma"].as_f64().expect("sigma")));
        check("P5", conv(s["p5"].as_f64().expect("p5")));
        check("P95", conv(s["p95"].as_f64().expect("p95")));
        let failures = summary["failures"].as_u64().expect("failures");
        assert!(
            rows.iter()
                .any(|r| r.contains(&format!(", {failures} failed"))),
            "{name}: failures {failures}"
        );
        // The histogram: its counts line and its ends (when the output spreads).
        let min = s["min"].as_f64().expect("min");
        let max = s["max"].as_f64().expect("max");
        let counts: Vec<u64> = s["histogram"]["counts"]
            .as_array()
            .expect("counts")
            .iter()
            .map(|c| c.as_u64().expect("count"))
            .collect();
        if max > min {
            let line = rows
                .iter()
                .map(|r| r.trim_matches(['│', ' ']))
                .find(|r| {
                    let v: Vec<&str> = r.split_whitespace().collect();
                    v.len() == counts.len() && v.iter().all(|t| t.parse::<u64>().is_ok())
                })
                .unwrap_or_else(|| panic!("{name}: no counts line\n{}", rows.join("\n")));
            let on_screen: Vec<u64> = line
                .split_whitespace()
                .map(|t| t.parse().expect("count"))
                .collect();
            assert_eq!(on_screen, counts, "{name}: histogram counts");
            let ends = rows
                .iter()
                .find(|r| r.contains("equal bins"))
                .expect("the histogram's axis line");
            let toks: Vec<&str> = ends.trim_matches(['│', ' ']).split_whitespace().collect();
            let (lo, hi) = (toks[0], toks[toks.len() - 1]);
            for (tok, want) in [(lo, conv(min)), (hi, conv(max))] {
                let got: f64 = tok.parse().expect("end");
                assert!(
                    (got - want).abs() <= half_last_digit(tok) * (1.0 + 1e-9),
                    "{name}: histogram end {tok} against {want}"
                );
            }
        }
        // The sensitivities: each varied input's ρ to the two decimals shown.
        let sens = summary["sensitivities"][name]
            .as_object()
            .expect("sensitivities");
        assert!(sens.len() >= 2, "{name}: inputs varied: {sens:?}");
        for (input, rho) in sens {
            let row = rows
                .iter()
                .find(|r| r.contains(&format!("{input} ")))
                .unwrap_or_else(|| panic!("{name}: no line for {input}"));
            let tok = row[row.find(input.as_str()).expect("key") + input.len()..]
                .split_whitespace()
                .next()
                .expect("rho")
                .to_string();
            match rho.as_f64() {
                Some(want) => {
                    let got: f64 = tok.parse().unwrap_or_else(|_| panic!("{input}: `{tok}`"));
                    assert!(
                        (got - want).abs() <= 0.005 + 1e-12,
                        "{name} ρ({input}): screen {tok}, JSON {want}"
                    );
                }
                None => assert_eq!(tok, "-", "{name} ρ({input}) undefined"),
            }
        }
        compared += 1;
    }
    assert!(compared >= 3, "outputs compared: {compared}");
}

/// The `rollbench study FILE --format json` of a study file, parsed.
fn study_json(path: &std::path::Path) -> serde_json::Value {
    let prepared = crate::studies::study::prepare(path).expect("prepares");
    let result = prepared.run(false);
    serde_json::from_str(&crate::cli::study_text(
        &result,
        crate::cli::StudyFormat::Json,
    ))
    .expect("json")
}

/// Every number the pane shows for each output — mean, σ, P5, P95, the histogram's ends
/// and counts, the failures, each input's ρ — equals the `summary` of `rollbench study
/// --format json` of the same study, to the last digit shown: the default tolerance
/// study of an SI deck (its text written beside a copy of the deck) and the grid study
/// file beside radial_si. The pane's study goes through `workbench::for_deck` on the
/// deck under edit; the CLI's through `study::prepare` on the files: both must sample,
/// solve and summarise alike.
#[test]
fn tui_study_numbers_on_screen_are_the_study_json_summary() {
    let (w, h) = (80, 24);
    let mut app = study_app("aerospace_si", w, h);
    let dir = std::env::temp_dir().join(format!("rollbench-study-pane-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let case = app.deck.case();
    std::fs::write(dir.join("aerospace_si.toml"), case.text()).expect("deck");
    let text =
        workbench::default_text(&*case, "aerospace_si.toml", DEFAULT_SAMPLES).expect("default");
    let study_path = dir.join("pane.study.toml");
    std::fs::write(&study_path, &text).expect("study");
    let json = study_json(&study_path);
    let _ = std::fs::remove_dir_all(&dir);
    check_screen_against(&mut app, &json, w, h);

    let mut app = study_app("radial_si", w, h);
    let json = study_json(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/decks/studies/radial_si_speed_load.study.toml"
    )));
    check_screen_against(&mut app, &json, w, h);
}

/// Focusing the Study pane asks the worker for the study (the deck's path, the default
/// samples); a progress report of an older solve is dropped; `h`/`l` change the samples
/// within the bound and re-submit; `j`/`k` cycle the output; a re-solve (an edit)
/// forgets the study so far.
#[test]
fn tui_study_pane_asks_for_its_study_and_the_next_solve_drops_it() {
    let mut app = shipped_app("aerospace_si", "Inputs", 80, 24);
    let at = app
        .panes()
        .iter()
        .position(|p| *p == Pane::Study)
        .expect("a Study pane");
    let cmds = app.handle(ch(char::from(b'1' + at as u8)));
    let Some(Command::Solve(job)) = cmds.first() else {
        panic!("focusing the pane solves: {cmds:?}")
    };
    assert_eq!(
        job.study,
        Some(StudyRequest {
            deck_path: Some(PathBuf::from("decks/aerospace_si.toml")),
            samples: DEFAULT_SAMPLES
        })
    );
    run_sync_tolerant(&mut app, cmds);
    let (g, p) = app.study.clone().expect("ran");
    assert_eq!(g, app.generation);
    assert_eq!(p.total, DEFAULT_SAMPLES);
    // An older generation's report is stale.
    app.handle(AppEvent::StudyProgress {
        generation: g - 1,
        progress: Arc::new(workbench::StudyProgress::failed("old".into())),
    });
    assert!(app.study.as_ref().is_some_and(|(_, p)| p.error.is_none()));
    // j/k: the output, cyclically.
    let n = p.header.outputs.len();
    app.handle(ch('k'));
    assert_eq!(app.study_output, n - 1);
    app.handle(ch('j'));
    assert_eq!(app.study_output, 0);
    // l: more samples, a new job; at the bound it stays.
    let cmds = app.handle(ch('l'));
    assert!(app.study.is_none(), "the new solve drops the study so far");
    assert!(
        matches!(cmds.first(), Some(Command::Solve(j)) if j.study.as_ref().is_some_and(|s| s.samples == 128))
    );
    for _ in 0..5 {
        app.handle(ch('l'));
    }
    assert_eq!(app.study_samples, 256);
    for _ in 0..5 {
        app.handle(ch('h'));
    }
    assert_eq!(app.study_samples, 32);
}
