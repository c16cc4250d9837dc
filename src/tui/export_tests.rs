//! Export from the workbench (issue 30 item 20), read back: a pane's CSV parsed and its
//! numbers compared with the JSON report's (converted to the display unit), for one deck
//! of every bearing system; and an existing file never replaced without the user's yes.

use std::path::PathBuf;
use std::sync::Arc;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use serde_json::Value;

use super::app::{App, AppEvent, Command, ExportWhat, Mode, Pane, PromptKind};
use super::export::{csv_field, pane_export};
use super::summary_tests::resolve;
use crate::bearings::view::AnswerValue;
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// Parses CSV as [`csv_field`] writes it (quoted fields with doubled quotes).
fn parse_csv(text: &str) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    for line in text.lines() {
        let mut cells = Vec::new();
        let mut cell = String::new();
        let mut quoted = false;
        let mut chars = line.chars().peekable();
        while let Some(c) = chars.next() {
            match (c, quoted) {
                ('"', true) if chars.peek() == Some(&'"') => {
                    cell.push('"');
                    chars.next();
                }
                ('"', _) => quoted = !quoted,
                (',', false) => cells.push(std::mem::take(&mut cell)),
                (c, _) => cell.push(c),
            }
        }
        cells.push(cell);
        rows.push(cells);
    }
    rows
}

/// The app on a shipped deck, solved (synchronously), with the JSON report of the same
/// solution; in `units`.
fn solved(deck: &str, units: Units) -> (App, Value) {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/decks")).join(deck);
    let mut app = App::new(super::tests::shipped_deck_for_snapshots(&path), None);
    app.handle(AppEvent::Resize(80, 24));
    let mut json = None;
    let mut pending = app.start();
    while let Some(c) = pending.pop() {
        if let Command::Solve(job) = c {
            let mut session = job.case.system().session();
            let sol = session
                .solve(&*job.case, job.detail, &Cancel::NONE)
                .unwrap_or_else(|e| panic!("{deck}: {e}"));
            json = Some(sol.json());
            pending.extend(app.handle(AppEvent::Solved {
                generation: job.generation,
                outcome: Ok(Arc::new(sol.view())),
            }));
        }
    }
    app.display_units = units;
    (app, json.expect("solved"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs().max(1e-12)
}

/// The JSON value of table column `key` for element `i`: `/<table>/i/<key>`, or for an
/// `inner_`/`outer_` key the contact's object (`/balls/i/inner/normal_load_n`).
fn element_json(doc: &Value, table: &str, i: usize, key: &str) -> Option<f64> {
    // The spherical roller's pane table is `rollers_pane`; its JSON array `rollers`.
    let e = doc
        .get(table)
        .or_else(|| doc.get(table.trim_end_matches("_pane")))?
        .get(i)?;
    e.get(key).and_then(Value::as_f64).or_else(|| {
        let (side, rest) = key.split_once('_')?;
        matches!(side, "inner" | "outer")
            .then(|| e.get(side)?.get(rest)?.as_f64())
            .flatten()
    })
}

/// For one deck of every bearing system, in both unit systems: the Summary pane's CSV
/// holds every line, each number the JSON field its line names converted to the display
/// unit (1e-9: the file is written at full precision); the element table's CSV holds
/// every column of the view's table, and every cell the JSON report has (by the column's
/// key) reads back as that JSON value converted by the column's display unit.
#[test]
fn pane_csv_reads_back_as_the_json_report() {
    for deck in [
        "aerospace.toml",
        "chen_b.toml",
        "trb_afapl.toml",
        "crb_truck.toml",
        "srb_22308.toml",
    ] {
        for units in [Units::Si, Units::Us] {
            let (mut app, doc) = solved(deck, units);
            let view = app.view.clone().expect("a view");
            // Summary.
            app.focus = Pane::Summary;
            let e = pane_export(&app).expect("summary exports");
            let rows = parse_csv(&e.contents);
            assert_eq!(rows[0][..4], ["section", "quantity", "value", "unit"]);
            assert_eq!(rows.len(), view.answer.len() + 1, "{deck}");
            let mut numbers = 0;
            for (a, row) in view.answer.iter().zip(&rows[1..]) {
                assert_eq!(row[1], a.label, "{deck}");
                let AnswerValue::Number(_) = a.value else {
                    continue;
                };
                assert_eq!(row[3], a.display.unit(units), "{deck} {}", a.label);
                if a.json.is_empty() {
                    continue;
                }
                let j = resolve(&doc, a.json)
                    .unwrap_or_else(|| panic!("{deck}: JSON {} not found", a.json));
                let got: f64 = row[2].parse().expect("a number");
                let want = a.display.convert(j, units);
                assert!(close(got, want), "{deck} {}: {got} vs JSON {want}", a.label);
                numbers += 1;
            }
            assert!(numbers >= 5, "{deck}: {numbers} summary numbers read back");
            // The element table.
            app.focus = Pane::Elements;
            let t = view.element_table().expect("a table");
            assert!(t.columns.len() >= view.screen_table().expect("one").columns.len());
            let e = pane_export(&app).expect("table exports");
            let rows = parse_csv(&e.contents);
            assert_eq!(rows[0].len(), t.columns.len(), "{deck}: every column");
            assert_eq!(rows.len(), t.rows.len() + 1, "{deck}: every row");
            let mut cells = 0;
            for (c, col) in t.columns.iter().enumerate() {
                for (i, row) in rows[1..].iter().enumerate() {
                    let Some(j) = element_json(&doc, t.id, i, col.key) else {
                        continue;
                    };
                    let want = match col.screen {
                        Some(s) => s.display.convert(j, units),
                        None => j,
                    };
                    let got: f64 = row[c].parse().unwrap_or(f64::NAN);
                    assert!(
                        close(got, want),
                        "{deck} {} row {i}: {got} vs JSON {want}",
                        rows[0][c]
                    );
                    cells += 1;
                }
            }
            assert!(cells >= 2 * t.rows.len(), "{deck}: {cells} cells read back");
        }
    }
}

/// A chart's CSV holds every series point of the chart drawn, in display units, with the
/// axes' units in the header (the ball's skid chart: speed in rpm against moments in
/// N·m or lbf·in).
#[test]
fn chart_csv_holds_every_point_in_display_units() {
    let (mut app, _) = solved("chen_b.toml", Units::Us);
    let view = app.view.clone().expect("a view");
    let (n, chart) = view
        .charts
        .iter()
        .enumerate()
        .find(|(_, c)| c.series.len() > 1)
        .expect("a chart with series");
    app.focus = Pane::Chart(n);
    let rows = parse_csv(&pane_export(&app).expect("exports").contents);
    let points: usize = chart
        .series
        .iter()
        .map(|s| s.points.len())
        .max()
        .unwrap_or(0);
    assert_eq!(rows.len(), points + 1);
    let x_unit = chart.x.display.unit(Units::Us);
    assert!(rows[0][0].contains(x_unit), "{:?}", rows[0]);
    // The first series' first point, converted as the pane converts it.
    let s = &chart.series[0];
    let yd = s.display.unwrap_or(chart.y.display);
    let (x, y) = s.points[0];
    // The first series is the first y column (after the shared x, or its own x).
    assert!(rows[0][1].starts_with(s.name), "{:?}", rows[0]);
    let got_y: f64 = rows[1][1].parse().expect("a number");
    assert!(close(got_y, yd.convert(y, Units::Us)));
    let x_col = 0;
    let got_x: f64 = rows[1][x_col].parse().expect("a number");
    assert!(close(got_x, chart.x.display.convert(x, Units::Us)));
}

fn key(c: char) -> AppEvent {
    AppEvent::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
}

fn enter() -> AppEvent {
    AppEvent::Key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE))
}

/// Runs the runtime's part of the commands that touch no worker (checks and pane
/// writes), as `tui::perform` does, until none is left.
fn perform(app: &mut App, cmds: Vec<Command>) {
    let mut queue = cmds;
    while let Some(c) = queue.pop() {
        let more = match c {
            Command::CheckExportTarget { path, what } => {
                let exists = std::fs::symlink_metadata(&path).is_ok();
                app.handle(AppEvent::ExportTargetChecked { path, what, exists })
            }
            Command::WriteExport {
                path,
                contents,
                what,
            } => {
                let r = super::export::write(&path, app.path.as_deref(), contents.as_bytes())
                    .map(|w| format!("wrote {w}: {what}"));
                app.handle(AppEvent::Exported(r))
            }
            other => panic!("unexpected {other:?}"),
        };
        queue.extend(more);
    }
}

/// `x` offers a file beside the deck; an existing file is replaced only after `y` (any
/// other key goes back to the prompt, the file untouched); the status line says what was
/// written where; the deck itself is never an export target.
#[test]
fn export_never_replaces_a_file_without_consent() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (mut app, _) = solved("chen_b.toml", Units::Si);
    let deck_path = dir.path().join("chen_b.toml");
    std::fs::write(&deck_path, app.deck.text()).expect("deck written");
    app.path = Some(deck_path.clone());
    app.focus = Pane::Elements;
    app.handle(key('x'));
    let target = dir.path().join("chen_b_balls.csv");
    assert_eq!(
        app.mode,
        Mode::Prompt {
            kind: PromptKind::Export(ExportWhat::Pane),
            buffer: target.display().to_string(),
        }
    );
    // A new file: written at once.
    let cmds = app.handle(enter());
    perform(&mut app, cmds);
    let first = std::fs::read_to_string(&target).expect("written");
    assert!(first.starts_with("#,index,ψ deg,"), "{first}");
    let msg = app.message.clone().unwrap_or_default();
    assert!(
        msg.starts_with(&format!("wrote {}: Balls table", target.display())),
        "{msg}"
    );
    // It exists now: asked, and a no leaves it as it was.
    std::fs::write(&target, "keep me\n").expect("planted");
    app.handle(key('x'));
    let cmds = app.handle(enter());
    perform(&mut app, cmds);
    assert!(
        matches!(app.mode, Mode::ConfirmExport { .. }),
        "{:?}",
        app.mode
    );
    let cmds = app.handle(key('n'));
    assert!(cmds.is_empty());
    assert!(matches!(
        app.mode,
        Mode::Prompt {
            kind: PromptKind::Export(_),
            ..
        }
    ));
    assert_eq!(
        std::fs::read_to_string(&target).expect("reads"),
        "keep me\n"
    );
    // Asked again, and a yes replaces it.
    let cmds = app.handle(enter());
    perform(&mut app, cmds);
    assert!(matches!(app.mode, Mode::ConfirmExport { .. }));
    let cmds = app.handle(key('y'));
    perform(&mut app, cmds);
    assert_eq!(std::fs::read_to_string(&target).expect("reads"), first);
    // The deck itself: refused even after a yes, the deck untouched.
    let deck_text = std::fs::read_to_string(&deck_path).expect("deck");
    app.mode = Mode::Prompt {
        kind: PromptKind::Export(ExportWhat::Pane),
        buffer: deck_path.display().to_string(),
    };
    let cmds = app.handle(enter());
    perform(&mut app, cmds);
    let cmds = app.handle(key('y'));
    perform(&mut app, cmds);
    assert_eq!(app.mode, Mode::Error);
    assert!(app
        .error
        .as_deref()
        .unwrap_or("")
        .contains("the deck being edited"));
    assert_eq!(
        std::fs::read_to_string(&deck_path).expect("deck"),
        deck_text
    );
}

/// `X` offers `<deck>_report.json` and asks for the report in the format of the path's
/// extension, with the deck as it is now.
#[test]
fn report_export_asks_for_the_run_report() {
    let (mut app, _) = solved("chen_b.toml", Units::Si);
    app.path = Some(PathBuf::from("decks/chen_b.toml"));
    app.handle(key('X'));
    let Mode::Prompt { kind, buffer } = app.mode.clone() else {
        panic!("{:?}", app.mode)
    };
    assert_eq!(kind, PromptKind::Export(ExportWhat::Report));
    assert_eq!(buffer, "decks/chen_b_report.json");
    let dir = tempfile::tempdir().expect("temp dir");
    let target = dir.path().join("r.txt");
    app.mode = Mode::Prompt {
        kind,
        buffer: target.display().to_string(),
    };
    let cmds = app.handle(enter());
    let [Command::CheckExportTarget { path, what }] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    let cmds = app.handle(AppEvent::ExportTargetChecked {
        path: path.clone(),
        what: *what,
        exists: false,
    });
    match cmds.as_slice() {
        [Command::ExportReport { format, deck, .. }] => {
            assert_eq!(*format, crate::report::Format::Text);
            assert_eq!(deck.text(), app.deck.text());
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn csv_fields_are_quoted_when_needed() {
    assert_eq!(csv_field("Qi lbf"), "Qi lbf");
    assert_eq!(csv_field("skid (0 —; 1 yes)"), "skid (0 —; 1 yes)");
    assert_eq!(csv_field("a, b"), "\"a, b\"");
    assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    assert_eq!(
        parse_csv("\"a, b\",c\n"),
        vec![vec!["a, b".to_string(), "c".into()]]
    );
}

/// `X` writes the report as `rollbench run` writes it: the worker's report thread solves
/// the deck with the run's defaults and writes the same JSON (the solve's statistics,
/// which hold its wall time, aside), then says what it wrote where.
#[test]
fn report_export_writes_what_run_writes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let target = dir.path().join("radial_report.json");
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/decks/radial_si.toml"));
    let deck = super::DeckDoc::load(&path).expect("deck loads");
    let (tx, rx) = std::sync::mpsc::channel();
    let worker = super::Worker::spawn(tx, super::session_solver()).expect("worker");
    worker.export_report(
        target.clone(),
        deck.case(),
        crate::report::Format::Json,
        Some(path.clone()),
    );
    let msg = match rx.recv_timeout(std::time::Duration::from_secs(120)) {
        Ok(AppEvent::Exported(Ok(m))) => m,
        other => panic!("{other:?}"),
    };
    assert!(
        msg.contains("JSON report") && msg.contains("radial_report.json"),
        "{msg}"
    );
    let run = crate::report::render(
        deck.case()
            .solve(crate::bearings::RunOptions::default(), Cancel::NONE)
            .expect("solves")
            .as_ref(),
        crate::report::Format::Json,
        deck.units(),
    );
    let strip = |text: &str| {
        let mut v: Value = serde_json::from_str(text).expect("JSON");
        v.as_object_mut().expect("an object").remove("stats");
        v
    };
    let written = std::fs::read_to_string(&target).expect("written");
    assert_eq!(strip(&written), strip(&run));
}
