//! TUI tests: pure transitions, pane snapshots (solved synchronously), tiny sizes,
//! the worker's supersede/panic behaviour, deck save/load through the app, and a
//! scripted run of the whole event loop on `TestBackend`.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use insta::assert_snapshot;
use ratatui::backend::TestBackend;
use ratatui::Terminal;

use super::app::{Mode, PromptKind, SolveState};
use super::*;
use crate::bearings::view::View;
use crate::bearings::{Detail, SolveError};
use crate::numerics::cancel::Cancel;

#[path = "baseline_tests.rs"]
mod baseline;
#[path = "issue30_tests.rs"]
mod issue30;
#[path = "operating_tests.rs"]
mod operating;

fn key(c: KeyCode) -> AppEvent {
    AppEvent::Key(KeyEvent::new(c, KeyModifiers::NONE))
}
pub(super) fn ch(c: char) -> AppEvent {
    key(KeyCode::Char(c))
}
fn ctrl(c: char) -> AppEvent {
    AppEvent::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL))
}

/// Solves a job synchronously, with the wall time zeroed so snapshots are stable.
fn solve_now(job: &app::SolveJob) -> View {
    solve_view(job).expect("the deck solves")
}

/// Solves a job synchronously through its system's session (as the worker does), with
/// the wall time zeroed so snapshots are stable.
fn solve_view(job: &app::SolveJob) -> Result<View, SolveError> {
    let mut session = job.case.system().session();
    let mut v = session.solve(&*job.case, job.detail, &Cancel::NONE)?.view();
    v.stats.wall_time_s = 0.0;
    Ok(v)
}

/// The job's sweep (a Sweep pane on screen), solved inline point by point through one
/// session as the worker does, each point fed back as progress.
fn sweep_sync(app: &mut App, job: &app::SolveJob) {
    let Some(n) = job.sweep else { return };
    let Some(plan) = job.case.system().sweep_plan(n, &*job.case) else {
        return;
    };
    let mut session = job.case.system().session();
    let mut solve = |c: &dyn crate::bearings::Case| {
        session
            .solve(c, crate::bearings::Detail::default(), &Cancel::NONE)
            .map(|s| s.view())
    };
    let mut events = Vec::new();
    let mut report = |p: &crate::studies::sweep::PlanProgress| {
        events.push(AppEvent::SweepProgress {
            generation: job.generation,
            pane: n,
            progress: Arc::new(p.clone()),
        })
    };
    crate::studies::sweep::run_plan(&*job.case, plan, &mut solve, &|| false, &mut report);
    for e in events {
        app.handle(e);
    }
}

/// The job's job pane (a Job pane on screen), run inline to the end as the worker runs it,
/// its last report fed back (its reports before are the same job unfinished). Finished
/// views are kept per deck text and pane, so the snapshots at several sizes run each job
/// once.
fn job_sync(app: &mut App, job: &app::SolveJob) {
    type Done = Vec<(String, usize, Arc<crate::bearings::view::JobView>)>;
    static DONE: std::sync::Mutex<Done> = std::sync::Mutex::new(Vec::new());
    let Some(n) = job.job else { return };
    let text = job.case.text();
    let cached = DONE
        .lock()
        .expect("cache")
        .iter()
        .find(|(t, m, _)| *t == text && *m == n)
        .map(|(_, _, v)| Arc::clone(v));
    let view = cached.unwrap_or_else(|| {
        let v = match job
            .case
            .system()
            .run_job(n, &*job.case, Cancel::NONE, &mut |_| {})
        {
            Some(Ok(v)) => v,
            Some(Err(e)) => crate::bearings::view::JobView::failed(e.to_string()),
            None => return Arc::new(crate::bearings::view::JobView::failed("no job".into())),
        };
        let v = Arc::new(v);
        DONE.lock()
            .expect("cache")
            .push((text.clone(), n, Arc::clone(&v)));
        v
    });
    app.handle(AppEvent::JobProgress {
        generation: job.generation,
        pane: n,
        view,
    });
}

/// The job's Study pane study (the pane on screen), run inline to the end as the worker
/// runs it, its last report fed back; finished studies are kept per deck text and
/// request, so the snapshots at several sizes run each study once.
pub(super) fn study_sync(app: &mut App, job: &app::SolveJob) {
    use crate::studies::study::workbench::{self, StudyProgress};
    type Done = Vec<(String, app::StudyRequest, Arc<StudyProgress>)>;
    static DONE: std::sync::Mutex<Done> = std::sync::Mutex::new(Vec::new());
    let Some(request) = &job.study else { return };
    let text = job.case.text();
    let cached = DONE
        .lock()
        .expect("cache")
        .iter()
        .find(|(t, r, _)| *t == text && r == request)
        .map(|(_, _, p)| Arc::clone(p));
    let progress = cached.unwrap_or_else(|| {
        let never = std::sync::atomic::AtomicBool::new(false);
        let p = match workbench::for_deck(&*job.case, request.deck_path.as_deref(), request.samples)
        {
            Ok(study) => workbench::run(&study, &never, &mut |_| {}).expect("not cancelled"),
            Err(e) => StudyProgress::failed(e),
        };
        let p = Arc::new(p);
        DONE.lock()
            .expect("cache")
            .push((text.clone(), request.clone(), Arc::clone(&p)));
        p
    });
    app.handle(AppEvent::StudyProgress {
        generation: job.generation,
        progress,
    });
}

/// Feeds every solve command back as a result, like the worker would (but inline).
fn run_sync(app: &mut App, cmds: Vec<Command>) -> Vec<Command> {
    let mut other = Vec::new();
    for c in cmds {
        match c {
            Command::Solve(job) => {
                let a = solve_now(&job);
                let more = app.handle(AppEvent::Solved {
                    generation: job.generation,
                    outcome: Ok(Arc::new(a)),
                });
                sweep_sync(app, &job);
                job_sync(app, &job);
                study_sync(app, &job);
                other.extend(run_sync(app, more));
            }
            c => other.push(c),
        }
    }
    other
}

fn deck_app() -> App {
    let deck = DeckDoc::parse(
        crate::bearings::spherical_roller::deck::DEFAULT_DECK,
        "decks/aerospace.toml",
    )
    .expect("deck");
    App::new(deck, Some(PathBuf::from("decks/aerospace.toml")))
}

/// The shipped aerospace deck, solved, at `w`×`h`, focused on `pane`.
fn solved_app(pane: Pane, w: u16, h: u16) -> App {
    let mut app = deck_app();
    app.handle(AppEvent::Resize(w, h));
    let cmds = app.start();
    run_sync(&mut app, cmds);
    app.focus = pane;
    let cmds = app.handle(AppEvent::Resize(w, h)); // re-request what the pane needs
    run_sync(&mut app, cmds);
    app
}

pub(super) fn draw(app: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
    t.draw(|f| f.render_widget(app, f.area())).expect("draw");
    t
}

fn field_index(app: &App, key: &str) -> usize {
    app.fields
        .iter()
        .position(|f| f.key == key)
        .expect("field exists")
}

fn select_field(app: &mut App, key: &str) {
    app.focus = Pane::Inputs;
    app.input_sel = field_index(app, key);
}

fn type_value(app: &mut App, text: &str) -> Vec<Command> {
    app.handle(key(KeyCode::Enter));
    for _ in 0..40 {
        app.handle(key(KeyCode::Backspace));
    }
    for c in text.chars() {
        app.handle(ch(c));
    }
    app.handle(key(KeyCode::Enter))
}

// ---------------------------------------------------------------- transitions

#[test]
fn tui_edit_commits_marks_and_solves() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    select_field(&mut app, "operating.radial_load");
    let cmds = type_value(&mut app, "4000");
    assert_eq!(app.mode, Mode::Normal);
    assert_eq!(
        app.deck.value("operating.radial_load", app.display_units),
        "4000"
    );
    assert!(app.unsaved());
    assert!(app.dirty_keys.contains_key("operating.radial_load"));
    assert!(matches!(app.solve, SolveState::Running));
    let [Command::Solve(job)] = cmds.as_slice() else {
        panic!("expected one solve, got {cmds:?}");
    };
    assert_eq!(job.generation, app.generation);
    let radial = job.case.field_si("operating.radial_load").expect("a field");
    assert!((radial - 4000.0 * crate::units::LBF_N).abs() < 1e-6);
    run_sync(&mut app, cmds);
    assert!(app.dirty_keys.is_empty());
    assert!(matches!(app.solve, SolveState::Solved { .. }));
}

#[test]
fn tui_invalid_edit_shows_allowed_range_and_keeps_deck() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    let before = app.deck.clone();
    select_field(&mut app, "geometry.contact_angle");
    let cmds = type_value(&mut app, "95");
    assert!(cmds.is_empty());
    match &app.mode {
        Mode::Editing { error: Some(e), .. } => assert!(e.contains("value"), "{e}"),
        m => panic!("expected an edit error, got {m:?}"),
    }
    assert_eq!(app.deck, before);
    app.handle(key(KeyCode::Esc));
    assert_eq!(app.mode, Mode::Normal);
    let cmds = type_value(&mut app, "abc");
    assert!(cmds.is_empty());
    assert!(matches!(app.mode, Mode::Editing { error: Some(_), .. }));
}

#[test]
fn tui_unchanged_edit_does_not_solve() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    let g = app.generation;
    app.handle(key(KeyCode::Enter));
    let cmds = app.handle(key(KeyCode::Enter));
    assert!(cmds.is_empty());
    assert_eq!(app.generation, g);
}

#[test]
fn tui_undo_redo() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    let original = app.deck.clone();
    select_field(&mut app, "operating.axial_load");
    let c = type_value(&mut app, "1500");
    run_sync(&mut app, c);
    let edited = app.deck.clone();
    assert_ne!(edited, original);
    let cmds = app.handle(ctrl('z'));
    assert!(matches!(cmds.as_slice(), [Command::Solve(_)]));
    assert_eq!(app.deck, original);
    assert!(!app.unsaved());
    run_sync(&mut app, cmds);
    app.handle(ctrl('y'));
    assert_eq!(app.deck, edited);
    assert!(app.handle(ctrl('y')).is_empty());
    assert_eq!(app.message.as_deref(), Some("nothing to redo"));
}

/// `unsaved()` compares the deck's text with the saved text, as it did when it
/// serialised the deck on every call: on after an edit, off after undoing back to the
/// saved deck (or retyping the saved value), on after redo, off after a save, and on
/// after undoing past that save. At each step it agrees with that old definition.
#[test]
fn tui_unsaved_follows_the_deck_text() {
    let mut app = deck_app();
    let was = |app: &App| app.deck.text() != app.saved_text;
    let check = |app: &App, expected: bool| {
        assert_eq!(app.unsaved(), expected);
        assert_eq!(app.unsaved(), was(app), "agrees with the text comparison");
    };
    check(&app, false);
    select_field(&mut app, "operating.axial_load");
    let original = app.deck.value("operating.axial_load", app.display_units);
    type_value(&mut app, "1500");
    check(&app, true);
    app.handle(ctrl('z'));
    check(&app, false);
    app.handle(ctrl('y'));
    check(&app, true);
    type_value(&mut app, &original);
    check(&app, false);
    type_value(&mut app, "1500");
    check(&app, true);
    app.handle(AppEvent::Saved(Ok(PathBuf::from("saved.toml"))));
    check(&app, false);
    app.handle(ctrl('z'));
    check(&app, true);
    app.handle(ctrl('y'));
    check(&app, false);
}

#[test]
fn tui_units_toggle_and_edit_in_other_units() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    assert_eq!(app.display_units, crate::units::Units::Us);
    app.handle(ch('u'));
    assert_eq!(app.display_units, crate::units::Units::Si);
    assert_eq!(
        app.deck.value("geometry.pitch_diameter", app.display_units),
        "0.08382"
    );
    select_field(&mut app, "geometry.pitch_diameter");
    let c = type_value(&mut app, "0.0889");
    run_sync(&mut app, c);
    // stored in the deck's own units (in): 0.0889 m = 3.5 in
    assert_eq!(
        app.deck
            .value("geometry.pitch_diameter", crate::units::Units::Us),
        "3.5"
    );
}

#[test]
fn tui_save_prompt_and_quit_prompt() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    app.path = None;
    assert_eq!(app.handle(ctrl('s')), vec![]);
    assert!(matches!(
        app.mode,
        Mode::Prompt {
            kind: PromptKind::SaveAs,
            ..
        }
    ));
    for _ in 0..20 {
        app.handle(key(KeyCode::Backspace));
    }
    for c in "out.toml".chars() {
        app.handle(ch(c));
    }
    // another path: the runtime first checks whether it exists; it does not: save
    let cmds = app.handle(key(KeyCode::Enter));
    assert_eq!(
        cmds,
        vec![Command::CheckSaveTarget(PathBuf::from("out.toml"))]
    );
    let cmds = app.handle(AppEvent::SaveTargetChecked {
        path: PathBuf::from("out.toml"),
        exists: false,
    });
    match cmds.as_slice() {
        [Command::Save { path, .. }] => assert_eq!(path, &PathBuf::from("out.toml")),
        c => panic!("expected save, got {c:?}"),
    }
    // quit with unsaved changes asks; any other key stays; y quits
    select_field(&mut app, "operating.axial_load");
    let c = type_value(&mut app, "1200");
    run_sync(&mut app, c);
    assert!(app.handle(ch('q')).is_empty());
    assert_eq!(app.mode, Mode::ConfirmQuit);
    app.handle(ch('n'));
    assert_eq!(app.mode, Mode::Normal);
    assert!(!app.quit);
    // Esc never quits: it only cancels (issue 15); q asks.
    assert!(app.handle(key(KeyCode::Esc)).is_empty());
    assert_eq!(app.mode, Mode::Normal);
    app.handle(ch('q'));
    assert_eq!(app.handle(ch('y')), vec![Command::Quit]);
    assert!(app.quit);
}

#[test]
fn tui_quit_without_changes_is_immediate() {
    let mut app = solved_app(Pane::Elements, 80, 24);
    assert_eq!(app.handle(ch('q')), vec![Command::Quit]);
}

#[test]
fn tui_stepper_navigation() {
    let mut app = solved_app(Pane::Elements, 80, 24);
    app.handle(ch('j'));
    assert_eq!(app.roller_sel, 1);
    let cmds = app.handle(key(KeyCode::Enter));
    assert_eq!(app.focus, Pane::Stepper);
    match cmds.as_slice() {
        [Command::Solve(job)] => assert_eq!(job.detail.trace_element, Some(1)),
        c => panic!("expected a traced solve, got {c:?}"),
    }
    run_sync(&mut app, cmds);
    let n = app.trace_len();
    assert!(n > 2, "trace has {n} steps");
    assert_eq!(app.step, 0);
    app.handle(ch('l'));
    app.handle(key(KeyCode::Right));
    assert_eq!(app.step, 2);
    app.handle(ch('h'));
    assert_eq!(app.step, 1);
    for _ in 0..(n + 5) {
        app.handle(ch('l'));
    }
    assert_eq!(app.step, n - 1);
    app.handle(key(KeyCode::Home));
    assert_eq!(app.step, 0);
    app.handle(key(KeyCode::PageDown));
    assert_eq!(app.step, 10.min(n - 1));
    app.handle(ch('G'));
    assert_eq!(app.step, n - 1);
    app.handle(key(KeyCode::PageUp));
    assert_eq!(app.step, n - 1 - 10.min(n - 1));
    // another roller: new trace requested, step reset
    let cmds = app.handle(ch('j'));
    assert_eq!(app.step, 0);
    assert!(matches!(cmds.as_slice(), [Command::Solve(j)] if j.detail.trace_element == Some(2)));
}

/// The screen's rows as strings.
fn screen_rows(t: &Terminal<TestBackend>) -> Vec<String> {
    let b = t.backend().buffer();
    (0..b.area.height)
        .map(|y| (0..b.area.width).map(|x| b[(x, y)].symbol()).collect())
        .collect()
}

/// Issue 30 item 2: the stepper's bar rows hold every lamina at 60×20, 80×24 and 200×50
/// (resampled to the cells there are, said on screen, never cut), the trace's label is
/// shown whole, and the history keeps at least its header and the current step's row.
#[test]
fn tui_stepper_bars_hold_every_lamina_at_every_size() {
    for (w, h) in [(60, 20), (80, 24), (200, 50)] {
        let app = solved_app(Pane::Stepper, w, h);
        let trace = app
            .view
            .as_deref()
            .and_then(|v| v.trace.clone())
            .expect("a trace");
        let n = trace.steps[0].bars[0].values.len();
        // The stepper pane's columns only (at 200×50 other panes share the rows).
        let all = screen_rows(&draw(&app, w, h));
        let (top, x0) = all
            .iter()
            .enumerate()
            .find_map(|(y, r)| {
                let at = r.find("┌ Stepper")?;
                Some((y, r[..at].chars().count()))
            })
            .expect("the stepper pane");
        let x1 = all[top]
            .chars()
            .skip(x0)
            .position(|c| c == '┐')
            .expect("its corner")
            + x0;
        let rows: Vec<String> = all
            .iter()
            .skip(top)
            .map(|r| r.chars().skip(x0).take(x1 + 1 - x0).collect())
            .take_while(|r: &String| !r.starts_with('└'))
            .collect();
        let bar_row = rows
            .iter()
            .find(|r| r.contains("inner load"))
            .unwrap_or_else(|| panic!("{w}×{h}: no bar row in {rows:#?}"));
        let cells = bar_row
            .chars()
            .filter(|c| ('▁'..='█').contains(c) || *c == '·')
            .count();
        let note = format!("{n} values in {cells} cells, each the max");
        let text = rows.join("\n");
        if cells < n {
            assert!(
                text.contains(&note),
                "{w}×{h}: {cells} of {n} cells unsaid:\n{text}"
            );
        } else {
            assert_eq!(cells, n, "{w}×{h}: one cell per lamina");
            assert!(!text.contains("each the max"), "{w}×{h}: nothing resampled");
        }
        // The bars end at the border: the whole row is used.
        let inner_right = bar_row.chars().rev().nth(1).expect("row");
        assert!(cells == n || inner_right != ' ', "{w}×{h}: {bar_row}");
        let words: String = rows
            .iter()
            .map(|r| r.trim_matches(|c| c == '│' || c == ' ').to_string())
            .collect::<Vec<_>>()
            .join(" ");
        let words = words.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(words.contains(&trace.label), "{w}×{h}: label cut:\n{text}");
        assert!(
            rows.iter().any(|r| r.contains("#  it")),
            "{w}×{h}: no history:\n{text}"
        );
    }
}

/// A shipped deck (`decks/{stem}.toml`, as the snapshots draw it), solved at `w`×`h`
/// and focused on the pane titled `title`.
pub(super) fn shipped_app(stem: &str, title: &str, w: u16, h: u16) -> App {
    let path = PathBuf::from(format!("{}/decks/{stem}.toml", env!("CARGO_MANIFEST_DIR")));
    let deck = shipped_deck_for_snapshots(&path);
    let mut app = App::new(deck, Some(PathBuf::from(format!("decks/{stem}.toml"))));
    app.handle(AppEvent::Resize(w, h));
    let cmds = app.start();
    run_sync_tolerant(&mut app, cmds);
    let pane = app
        .panes()
        .into_iter()
        .find(|&p| app.pane_title(p) == title)
        .unwrap_or_else(|| panic!("{stem}: no pane {title}"));
    let cmds = app.handle(ch(char::from(
        b'1' + app.panes().iter().position(|&p| p == pane).unwrap_or(0) as u8,
    )));
    run_sync_tolerant(&mut app, cmds);
    assert_eq!(app.focus, pane);
    app
}

/// Issue 30 item 9: every system counts its elements from 1 on screen and in text. For
/// one deck of each system the element pane's first row reads `1` under `#`, the view's
/// `#` column runs 1…n, and the JSON's per-element array gives `number` from 1 beside
/// the system's `index` (the ball's still from 0). The ball's stepper names the first
/// ball "ball 1", and its text report's tables start at 1. (The ball's `#` read 0…19.)
#[test]
fn tui_every_system_numbers_its_elements_from_1() {
    for (stem, pane, array) in [
        ("aerospace", "Rollers", "/rollers"),
        ("chen_b", "Balls", "/balls"),
        ("trb_afapl", "Rollers", "/rollers"),
        ("crb_nasa210", "Rollers", "/rollers"),
        ("srb_22308", "Rollers", "/rollers"),
    ] {
        let app = shipped_app(stem, pane, 80, 24);
        let view = app.view.clone().expect("solved");
        let table = view.screen_table().expect("a table");
        let c = table
            .columns
            .iter()
            .position(|c| c.screen.is_some_and(|s| s.label == "#"))
            .unwrap_or_else(|| panic!("{stem}: no # column"));
        // The double-row bearing numbers each row's rollers 1…z beside its `row` column.
        let z = if stem == "srb_22308" {
            table.rows.len() / 2
        } else {
            table.rows.len()
        };
        for (k, row) in table.rows.iter().enumerate() {
            assert_eq!(row[c], Some((k % z + 1) as f64), "{stem}: row {k}");
        }
        let screen = draw(&app, 80, 24).backend().to_string();
        let bare: Vec<String> = screen
            .lines()
            .map(|l| {
                l.trim_matches(|c| c == '"' || c == '│' || c == ' ')
                    .to_string()
            })
            .collect();
        // The header's `#` (after the double-row bearing's `row`) and the first row's
        // cell under it.
        let (header, at) = bare
            .iter()
            .enumerate()
            .find_map(|(i, l)| Some((i, l.split_whitespace().position(|w| w == "#")?)))
            .unwrap_or_else(|| panic!("{stem}: no header:\n{screen}"));
        assert_eq!(
            bare[header + 1].split_whitespace().nth(at),
            Some("1"),
            "{stem}:\n{screen}"
        );
        let path = PathBuf::from(format!("{}/decks/{stem}.toml", env!("CARGO_MANIFEST_DIR")));
        let case = crate::bearings::load_file(&path, &[]).expect("deck loads");
        let solution = case
            .solve(
                crate::bearings::RunOptions {
                    skip_transient: true,
                },
                Cancel::NONE,
            )
            .expect("solves");
        let json = solution.json();
        let elements = json
            .pointer(array)
            .and_then(|a| a.as_array())
            .unwrap_or_else(|| panic!("{stem}: no {array}"));
        assert_eq!(elements[0]["number"], 1, "{stem}");
        for e in elements {
            let (number, index) = (e["number"].as_u64(), e["index"].as_u64());
            let base = if stem == "chen_b" { 1 } else { 0 };
            assert_eq!(number, index.map(|i| i + base), "{stem}: {e}");
        }
        if stem == "chen_b" {
            let text = solution.text(crate::units::Units::Si);
            for table in ["LOAD DISTRIBUTION", "RACE CONTROL"] {
                let mut lines = text.lines().skip_while(|l| !l.starts_with(table));
                let first = lines.nth(2).unwrap_or_default();
                assert!(first.trim_start().starts_with("1 "), "{table}: {first}");
            }
            let stepper = shipped_app(stem, "Stepper", 80, 24);
            let screen = draw(&stepper, 80, 24).backend().to_string();
            assert!(screen.contains("ball 1 ·"), "{screen}");
        }
    }
}

/// Issue 30 item 11: flags are words on screen and in text, codes in CSV. The ball's
/// `skid` and the tapered roller's `edge1`/`edge2` cells read `yes` or `—` (they read 1/0)
/// and agree with the JSON's bools, the tapered `state` reads its name; the text reports
/// use the same words; the CSV keeps 0/1.
#[test]
fn flags_are_words_on_screen_and_in_text() {
    use crate::bearings::view::FLAG_NAMES;
    for (stem, array, flags) in [
        ("chen_b", "/balls", vec![("skid", "skidding")]),
        (
            "trb_afapl",
            "/rollers",
            vec![
                ("edge1", "outer_edge_loaded"),
                ("edge2", "inner_edge_loaded"),
            ],
        ),
    ] {
        let path = PathBuf::from(format!("{}/decks/{stem}.toml", env!("CARGO_MANIFEST_DIR")));
        let case = crate::bearings::load_file(&path, &[]).expect("deck loads");
        let solution = case
            .solve(
                crate::bearings::RunOptions {
                    skip_transient: true,
                },
                Cancel::NONE,
            )
            .expect("solves");
        let (view, json) = (solution.view(), solution.json());
        let cells = view_model::table_cells(&view, crate::units::Units::Si, 1000, 0);
        let elements = json.pointer(array).and_then(|a| a.as_array()).expect(array);
        for (header, key) in flags {
            let c = cells
                .columns
                .iter()
                .position(|c| c.header == header)
                .unwrap_or_else(|| panic!("{stem}: no {header}"));
            for (row, e) in cells.rows.iter().zip(elements) {
                let want = FLAG_NAMES[usize::from(e[key].as_bool().expect(key))];
                assert_eq!(row[c], want, "{stem} {header}");
            }
        }
        if stem == "trb_afapl" {
            let c = cells.columns.iter().position(|c| c.header == "state");
            let c = c.expect("state column");
            for (row, e) in cells.rows.iter().zip(elements) {
                assert_eq!(Some(row[c].as_str()), e["state"].as_str());
            }
        }
        let text = solution.text(case.units());
        let csv = crate::report::csv::to_string(&view);
        let rows: Vec<&str> = match stem {
            "chen_b" => text
                .lines()
                .skip_while(|l| !l.starts_with("LOAD DISTRIBUTION"))
                .skip(2)
                .take(elements.len())
                .collect(),
            _ => text
                .lines()
                .skip_while(|l| !l.starts_with("Rollers ("))
                .skip(2)
                .take(elements.len())
                .collect(),
        };
        assert_eq!(rows.len(), elements.len(), "{text}");
        for r in rows {
            let last = r.split_whitespace().last().unwrap_or_default();
            assert!(FLAG_NAMES.contains(&last), "{stem}: {r}");
            assert!(!r.ends_with(" no"), "{stem}: {r}");
        }
        // CSV: the codes (its columns never change).
        let header: Vec<&str> = csv.lines().next().unwrap_or_default().split(',').collect();
        let key = if stem == "chen_b" {
            "skidding"
        } else {
            "outer_edge_loaded"
        };
        let i = header.iter().position(|h| *h == key).expect(key);
        for line in csv.lines().skip(1) {
            let code = line.split(',').nth(i).unwrap_or_default();
            assert!(code == "0" || code == "1", "{stem}: {line}");
        }
    }
}

/// Issue 30 item 12: one iteration vocabulary. The status line keeps its form at a width
/// whatever stands beside it (it fell to `15+184 it` when a message appeared); the Summary
/// pane words the counts as the status line does; a tapered re-solve of the unchanged
/// deck through the session (what the Sweep pane's job does) counts 0 + 0 from the last
/// answer and says so; and the spherical roller's stepper names the text report's count
/// of dynamic-load iterations.
#[test]
fn iterations_are_counted_in_one_vocabulary() {
    for w in [60, 80, 120] {
        let mut app = solved_app(Pane::Elements, w, 24);
        let status = |app: &App| {
            let t = draw(app, w, 24).backend().to_string();
            let line = t.lines().rev().nth(1).unwrap_or_default().to_string();
            line.trim_matches('"')
                .split(" │")
                .next()
                .unwrap_or_default()
                .trim_end()
                .to_string()
        };
        let before = status(&app);
        app.message = Some("a message that takes room on the status line".into());
        assert_eq!(status(&app), before, "{w}");
        assert!(before.contains("13"), "{w}: {before}");
    }
    let mut app = shipped_app("aerospace", "Summary", 200, 50);
    for _ in 0..20 {
        app.handle(ch('j')); // the solver's line is the Summary's last
    }
    let screen = draw(&app, 200, 50).backend().to_string();
    assert!(
        screen.contains("converged: 13 ring + 96 roller iterations"),
        "{screen}"
    );
    assert!(
        draw(&app, 200, 50)
            .backend()
            .to_string()
            .contains("solved in 13 ring + 96 roller iterations"),
        "{screen}"
    );

    let path = PathBuf::from(format!(
        "{}/decks/trb_afapl.toml",
        env!("CARGO_MANIFEST_DIR")
    ));
    let case = crate::bearings::load_file(&path, &[]).expect("deck loads");
    let mut session = case.system().session();
    let cold = session
        .solve(&*case, Detail::default(), &Cancel::NONE)
        .expect("solves")
        .view();
    let again = session
        .solve(&*case, Detail::default(), &Cancel::NONE)
        .expect("solves")
        .view();
    // (trb_afapl's cold solve takes 0 bearing Newton iterations of its own: its start
    // already balances; the rollers' Newton iterations are the work.)
    assert!(!cold.stats.warm_start && cold.stats.inner_iterations > 0);
    assert!(again.stats.warm_start);
    assert_eq!(
        (again.stats.iterations, again.stats.inner_iterations),
        (0, 0)
    );
    let s = again.stats;
    let words = render::status::counts_text(s.names, 0, 0, s.warm_start, false);
    assert_eq!(
        words,
        "0 bearing Newton + 0 roller Newton iterations from the last answer"
    );

    let case = crate::bearings::load_file(
        &PathBuf::from(format!(
            "{}/decks/aerospace.toml",
            env!("CARGO_MANIFEST_DIR")
        )),
        &[],
    )
    .expect("deck loads");
    let detail = Detail {
        trace_element: Some(0),
        ..Detail::default()
    };
    let solution = case
        .system()
        .session()
        .solve(&*case, detail, &Cancel::NONE)
        .expect("solves");
    let text = solution.text(crate::units::Units::Si);
    let after = text
        .split("speeds after ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .expect("the text's count");
    let label = solution.view().trace.expect("a trace").label;
    assert!(
        label.starts_with(&format!("{after} dynamic-load"))
            || label.contains(&format!(" of {after} dynamic-load")),
        "text {after}, stepper: {label}"
    );
}

/// Issue 30 item 15: at 60×20 and 80×24 the Balls pane hides columns; `l` brings every
/// one of them into view (the first, the ball's number, stays), the title says which
/// are shown, and `h` goes back. At 200×50 the aerospace Rollers table uses the width.
#[test]
fn tui_every_table_column_can_be_scrolled_into_view() {
    for (w, h) in [(60, 20), (80, 24)] {
        let mut app = shipped_app("chen_b", "Balls", w, h);
        let view = app.view.clone().expect("solved");
        let table = view.screen_table().expect("a table");
        let headers: Vec<String> = table
            .columns
            .iter()
            .filter_map(|c| c.screen)
            .map(|s| s.display.header(s.label, app.display_units))
            .collect();
        let mut seen = vec![false; headers.len()];
        let mut titles = Vec::new();
        for _ in 0..headers.len() {
            let rows = screen_rows(&draw(&app, w, h));
            titles.push(rows[1].clone());
            let header_row = &rows[2];
            for (k, hd) in headers.iter().enumerate() {
                let padded = format!(" {hd}");
                if header_row.contains(&padded) || header_row.starts_with(&format!("│{hd}")) {
                    seen[k] = true;
                }
            }
            app.handle(ch('l'));
        }
        let unseen: Vec<&String> = headers
            .iter()
            .zip(&seen)
            .filter(|(_, s)| !**s)
            .map(|(h, _)| h)
            .collect();
        assert!(unseen.is_empty(), "{w}×{h}: never shown: {unseen:?}");
        assert!(
            titles[0].contains("columns 2–")
                && titles[0].contains(&format!("of {}", headers.len())),
            "{w}×{h}: {}",
            titles[0]
        );
        for _ in 0..headers.len() {
            app.handle(ch('h'));
        }
        assert_eq!(app.col_scroll, 0);
    }
    let app = solved_app(Pane::Elements, 200, 50);
    let rows = screen_rows(&draw(&app, 200, 50));
    let used = rows[2].trim_end_matches(['│', ' ']).chars().count();
    assert!(
        used >= 190,
        "the table ends at column {used} of 200:\n{}",
        rows[2]
    );
}

/// Issue 30 item 5: the tapered Stiffness pane at 60×20 shows each line of the block on
/// one row (a matrix row is never wrapped), and `j`/`G` and `l` bring every line and
/// every column into view, the title saying which.
#[test]
fn tui_text_pane_scrolls_instead_of_wrapping() {
    let (w, h) = (60, 20);
    let mut app = shipped_app("trb_afapl", "Stiffness", w, h);
    let view = app.view.clone().expect("solved");
    let n = match app.focus {
        Pane::Text(n) => n,
        p => panic!("Stiffness is a text pane, not {p:?}"),
    };
    let text: Vec<String> = view.texts[n].lines(app.display_units).to_vec();
    let (rows_in, cols) = (usize::from(h) - 5, usize::from(w) - 2);
    let widest_len = text.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    assert!(
        widest_len > cols,
        "the block fits; the test needs one that does not"
    );
    let cut = |l: &str, from: usize| -> String {
        l.chars()
            .skip(from)
            .take(cols)
            .collect::<String>()
            .trim_end()
            .to_string()
    };
    let mut seen = vec![false; text.len()];
    for top in 0..text.len() {
        let rows = screen_rows(&draw(&app, w, h));
        assert_eq!(
            text.len() > rows_in,
            rows[1].contains("lines "),
            "{}",
            rows[1]
        );
        assert!(rows[1].contains("columns 1–"), "{}", rows[1]);
        let first = app.text_scroll.min(text.len().saturating_sub(rows_in));
        for (r, line) in rows[2..2 + rows_in].iter().zip(text.iter().skip(first)) {
            let shown = r.trim_start_matches('│').trim_end_matches('│').trim_end();
            let want = cut(line, 0);
            // Whole words only: the row is the line's start, up to a word boundary.
            assert!(
                want.starts_with(shown)
                    && line
                        .chars()
                        .nth(shown.chars().count())
                        .is_none_or(char::is_whitespace),
                "row {top}: wrapped or cut wrongly: {shown:?} of {line:?}"
            );
        }
        for (k, s) in seen.iter_mut().enumerate() {
            if k >= first && k < first + rows_in {
                *s = true;
            }
        }
        app.handle(ch('j'));
    }
    assert!(seen.iter().all(|s| *s), "a line never shown");
    app.handle(ch('g'));
    assert_eq!(app.text_scroll, 0);
    // The widest line's end, after scrolling right.
    let (at, widest) = text
        .iter()
        .enumerate()
        .max_by_key(|(_, l)| l.chars().count())
        .expect("lines");
    let len = widest.chars().count();
    for _ in 0..at {
        app.handle(ch('j'));
    }
    if len > cols {
        for _ in 0..(len / 8 + 1) {
            app.handle(ch('l'));
        }
        let rows = screen_rows(&draw(&app, w, h));
        let tail: String = widest.chars().skip(len - 10).collect();
        assert!(rows.join("\n").contains(tail.trim()), "{tail} not reached");
    }
}

#[test]
fn tui_stale_result_is_dropped() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    select_field(&mut app, "operating.axial_load");
    let first = type_value(&mut app, "1100");
    let second = type_value(&mut app, "1200");
    let (Some(Command::Solve(j1)), Some(Command::Solve(j2))) = (first.first(), second.first())
    else {
        panic!("expected solves");
    };
    let stale = solve_now(j1);
    app.handle(AppEvent::Solved {
        generation: j1.generation,
        outcome: Ok(Arc::new(stale)),
    });
    assert!(matches!(app.solve, SolveState::Running));
    app.handle(AppEvent::Solved {
        generation: j2.generation,
        outcome: Err("boom".into()),
    });
    assert_eq!(app.solve, SolveState::Failed("boom".into()));
    assert!(app.dirty_keys.contains_key("operating.axial_load"));
}

#[test]
fn tui_thermal_pane_requests_transient_only_when_visible() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    assert!(!app.last_request.transient);
    assert_eq!(app.last_request.trace_element, None);
    // the aerospace deck has no [thermal] table: nothing extra requested
    let cmds = app.handle(ch('5'));
    assert_eq!(app.focus, Pane::Thermal);
    assert_eq!(app.wanted_request().transient, app.deck.has_thermal());
    if !app.deck.has_thermal() {
        assert!(cmds.is_empty());
    }
}

// ---------------------------------------------------------------- decks

#[test]
fn tui_saved_deck_loads_back_equal_and_failed_save_keeps_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("deck.toml");
    std::fs::write(&path, crate::bearings::spherical_roller::deck::DEFAULT_DECK).expect("write");
    let deck = DeckDoc::load(&path).expect("load");
    let mut app = App::new(deck, Some(path.clone()));
    let (tx, _rx) = mpsc::channel();
    let mut worker =
        Worker::spawn(tx, Arc::new(|_, _, _, _| Err(SolveError::Cancelled))).expect("w");
    let cmds = app.start();
    perform(&mut app, cmds, &mut worker);
    select_field(&mut app, "operating.radial_load");
    let cmds = type_value(&mut app, "3500");
    perform(&mut app, cmds, &mut worker);
    assert!(app.unsaved());
    let cmds = app.handle(ctrl('s'));
    perform(&mut app, cmds, &mut worker);
    assert!(!app.unsaved(), "{:?}", app.message);
    let back = DeckDoc::load(&path).expect("reload");
    assert_eq!(back.text(), app.deck.text());
    assert_eq!(back, app.deck);
    assert!(dir.path().join("deck.toml.bak").exists());

    // A failed save (the backup cannot be renamed into place: a non-empty directory
    // holds its name; temporary files have random names now, so none can be blocked)
    // leaves the file intact and the quit that followed it is cancelled.
    let before = std::fs::read_to_string(&path).expect("read");
    let bak = dir.path().join("deck.toml.bak");
    std::fs::remove_file(&bak).expect("remove bak");
    std::fs::create_dir(&bak).expect("block bak");
    std::fs::write(bak.join("x"), "x").expect("fill bak");
    let cmds = type_value(&mut app, "3600");
    perform(&mut app, cmds, &mut worker);
    app.handle(ch('q'));
    let cmds = app.handle(ch('s'));
    assert!(matches!(cmds.first(), Some(Command::Save { .. })));
    perform(&mut app, cmds, &mut worker);
    assert!(!app.quit, "must not quit after a failed save");
    assert!(app.unsaved());
    assert!(app.message.as_deref().unwrap_or("").contains("save failed"));
    assert_eq!(std::fs::read_to_string(&path).expect("read"), before);
}

#[test]
fn tui_open_and_revert() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("a.toml");
    std::fs::write(&path, crate::bearings::spherical_roller::deck::DEFAULT_DECK).expect("write");
    let mut app = deck_app();
    app.handle(ch('o'));
    for c in path.display().to_string().chars() {
        app.handle(ch(c));
    }
    let cmds = app.handle(key(KeyCode::Enter));
    assert_eq!(cmds, vec![Command::Open(path.clone())]);
    let (tx, _rx) = mpsc::channel();
    let mut worker =
        Worker::spawn(tx, Arc::new(|_, _, _, _| Err(SolveError::Cancelled))).expect("w");
    perform(&mut app, cmds, &mut worker);
    assert_eq!(app.path.as_deref(), Some(path.as_path()));
    select_field(&mut app, "operating.axial_load");
    let c = type_value(&mut app, "1300");
    perform(&mut app, c, &mut worker);
    assert!(app.unsaved());
    assert!(app.handle(ch('R')).is_empty());
    assert_eq!(app.mode, Mode::ConfirmRevert);
    let cmds = app.handle(ch('y'));
    perform(&mut app, cmds, &mut worker);
    assert!(!app.unsaved());
    // open of a missing file reports, keeps the deck
    let cmds = vec![Command::Open(dir.path().join("missing.toml"))];
    perform(&mut app, cmds, &mut worker);
    assert!(app.message.as_deref().unwrap_or("").contains("open failed"));
}

// ---------------------------------------------------------------- snapshots

pub(super) fn snap(name: &str, app: &App, w: u16, h: u16) {
    let t = draw(app, w, h);
    assert_snapshot!(format!("{name}_{w}x{h}"), t.backend());
}

#[test]
fn tui_snapshot_every_pane() {
    for (w, h) in [(80, 24), (120, 40)] {
        for pane in deck_app().panes() {
            let app = solved_app(pane, w, h);
            let title = app.pane_title(pane).to_lowercase();
            snap(&format!("pane_{title}"), &app, w, h);
        }
    }
}

#[test]
fn tui_snapshot_overlays_and_modes() {
    for (w, h) in [(80, 24), (120, 40)] {
        let mut app = solved_app(Pane::Inputs, w, h);
        app.handle(ch('?'));
        snap("help", &app, w, h);

        let mut app = solved_app(Pane::Inputs, w, h);
        select_field(&mut app, "geometry.contact_angle");
        type_value(&mut app, "95");
        snap("edit_error", &app, w, h);

        let mut app = solved_app(Pane::Inputs, w, h);
        select_field(&mut app, "operating.radial_load");
        app.handle(key(KeyCode::Enter));
        snap("editing", &app, w, h);

        let mut app = solved_app(Pane::Chart(0), w, h);
        app.handle(ch('j'));
        app.handle(ch('c'));
        snap("lamina_chart", &app, w, h);

        let mut app = solved_app(Pane::Elements, w, h);
        app.handle(ch('u'));
        snap("rollers_si", &app, w, h);

        let mut app = solved_app(Pane::Stepper, w, h);
        for _ in 0..3 {
            app.handle(ch('l'));
        }
        snap("stepper_step4", &app, w, h);
    }
    let mut app = solved_app(Pane::Inputs, 80, 24);
    select_field(&mut app, "operating.axial_load");
    type_value(&mut app, "1234");
    snap("unsolved_edit", &app, 80, 24);
    app.handle(ch('q'));
    snap("quit_prompt", &app, 80, 24);
    let mut app = solved_app(Pane::Inputs, 80, 24);
    app.handle(ch('S'));
    snap("save_as_prompt", &app, 80, 24);
    app.handle(AppEvent::Solved {
        generation: app.generation,
        outcome: Err("solver panicked: deliberate".into()),
    });
    app.handle(key(KeyCode::Esc));
    app.view = None;
    app.view = None;
    app.focus = Pane::Elements;
    snap("failed_solve", &app, 80, 24);
}

#[test]
fn tui_tiny_sizes_do_not_panic() {
    for pane in deck_app().panes() {
        let mut app = solved_app(pane, 80, 24);
        for (w, h) in [
            (1, 1),
            (20, 5),
            (40, 10),
            (59, 15),
            (60, 16),
            (61, 17),
            (119, 35),
        ] {
            app.handle(AppEvent::Resize(w, h));
            let _ = draw(&app, w, h);
            app.handle(ch('?'));
            let _ = draw(&app, w, h);
            app.handle(ch('?'));
        }
    }
    assert_snapshot!("too_small_40x10", draw(&deck_app(), 40, 10).backend());
}

// ---------------------------------------------------------------- worker

/// A job on the aerospace deck, parsed once: submitting a burst of jobs must not take
/// longer than the worker needs to pick one up (the burst tests count the solves).
fn job(generation: u64) -> app::SolveJob {
    static CASE: std::sync::OnceLock<Arc<dyn crate::bearings::Case>> = std::sync::OnceLock::new();
    app::SolveJob {
        generation,
        case: Arc::clone(CASE.get_or_init(|| deck_app().deck.case())),
        detail: Detail::default(),
        sweep: None,
        job: None,
        study: None,
    }
}

#[test]
fn tui_worker_two_quick_edits_yield_one_result_for_the_second() {
    let template = Arc::new(solve_now(&job(0)));
    let t2 = Arc::clone(&template);
    // A slow solver that honours the cancel flag between "iterations".
    let solver: Solver = Arc::new(move |_, _, cancel: &AtomicBool, _| {
        for _ in 0..40 {
            if cancel.load(Ordering::Acquire) {
                return Err(SolveError::Cancelled);
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        Ok((*t2).clone())
    });
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, solver).expect("spawn");
    worker.submit(job(1));
    std::thread::sleep(Duration::from_millis(20)); // first is in flight
    worker.submit(job(2));
    match rx.recv_timeout(Duration::from_secs(10)) {
        Ok(AppEvent::Solved {
            generation,
            outcome,
        }) => {
            assert_eq!(generation, 2);
            assert!(outcome.is_ok());
        }
        other => panic!("expected a result, got {other:?}"),
    }
    assert!(rx.recv_timeout(Duration::from_millis(400)).is_err());
}

#[test]
fn tui_worker_queued_burst_runs_only_newest() {
    let calls = Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let c2 = Arc::clone(&calls);
    let template = Arc::new(solve_now(&job(0)));
    let solver: Solver = Arc::new(move |_, _, _, _| {
        c2.fetch_add(1, Ordering::SeqCst);
        std::thread::sleep(Duration::from_millis(30));
        Ok((*template).clone())
    });
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, solver).expect("spawn");
    for g in 1..=5 {
        worker.submit(job(g));
    }
    let mut got = Vec::new();
    while let Ok(AppEvent::Solved { generation, .. }) = rx.recv_timeout(Duration::from_millis(800))
    {
        got.push(generation);
    }
    assert_eq!(got, vec![5]);
    assert!(calls.load(Ordering::SeqCst) <= 2);
}

#[test]
fn tui_worker_panic_becomes_failed_solve() {
    install_solver_panic_filter(); // keeps the test output quiet, as in the app
    let solver: Solver = Arc::new(|_, _, _, _| panic!("deliberate solver panic"));
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, solver).expect("spawn");
    worker.submit(job(7));
    let ev = rx.recv_timeout(Duration::from_secs(10)).expect("a message");
    let mut app = deck_app();
    app.generation = 7;
    let AppEvent::Solved { outcome, .. } = &ev else {
        panic!("expected Solved, got {ev:?}");
    };
    let msg = outcome.as_ref().err().cloned().unwrap_or_default();
    assert!(msg.contains("deliberate solver panic"), "{msg}");
    app.handle(ev);
    assert!(matches!(app.solve, SolveState::Failed(ref m) if m.contains("panicked")));
    // the worker survives and solves the next job
    let ok: Solver = session_solver();
    drop(worker);
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, ok).expect("spawn");
    worker.submit(job(8));
    assert!(matches!(
        rx.recv_timeout(Duration::from_secs(10)),
        Ok(AppEvent::Solved {
            generation: 8,
            outcome: Ok(_)
        })
    ));
}

#[test]
fn tui_event_loop_end_to_end_on_test_backend() {
    let mut terminal = Terminal::new(TestBackend::new(80, 24)).expect("backend");
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx.clone(), session_solver()).expect("spawn");
    let app = deck_app();
    let script = std::thread::spawn({
        let tx = tx.clone();
        move || {
            std::thread::sleep(Duration::from_millis(200)); // let the first solve land
                                                            // Inputs → Summary → Rollers, then two rollers down.
            for ev in [
                key(KeyCode::Tab),
                key(KeyCode::Tab),
                ch('j'),
                ch('j'),
                ch('q'),
            ] {
                let _ = tx.send(ev);
            }
        }
    });
    let app = run_loop(&mut terminal, app, &rx, &mut worker).expect("loop");
    let _ = script.join();
    assert!(app.quit);
    assert_eq!(app.focus, Pane::Elements);
    assert_eq!(app.roller_sel, 2);
    assert!(app.view.is_some());
    // The loop coalesces queued events before its next frame, so when all five keys
    // arrive at once `q` ends it before Rollers is drawn (timing-dependent): draw the
    // final state once, as the next frame would have.
    terminal
        .draw(|f| f.render_widget(&app, f.area()))
        .expect("draw");
    let screen = terminal.backend().to_string();
    assert!(screen.contains("Rollers"), "{screen}");
}

/// Every shipped deck opens, solves (or shows why not) and draws every pane its system
/// offers at 60×20 and 80×24, and the overview at 200×50 (with the element table focused,
/// and with the stepper).
#[test]
fn tui_snapshot_shipped_decks() {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/decks"))
        .expect("decks dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty());
    for path in paths {
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let deck = shipped_deck_for_snapshots(&path);
        let panes = App::new(deck.clone(), None).panes();
        let mut shots: Vec<(Pane, u16, u16)> = Vec::new();
        // The Study pane runs a study of 64 solves or more: its screens are drawn for a
        // few decks of their own (`study_tests`), not for every deck here.
        for (w, h) in [(60, 20), (80, 24)] {
            shots.extend(
                panes
                    .iter()
                    .filter(|&&p| p != Pane::Study)
                    .map(|&p| (p, w, h)),
            );
        }
        shots.extend(
            [
                Pane::Elements,
                Pane::Stepper,
                Pane::Sweep(0),
                Pane::Job(0),
                Pane::Job(1),
            ]
            .into_iter()
            .filter(|p| panes.contains(p))
            .map(|p| (p, 200, 50)),
        );
        for (pane, w, h) in shots {
            let mut app = App::new(
                deck.clone(),
                Some(PathBuf::from(format!("decks/{stem}.toml"))),
            );
            app.handle(AppEvent::Resize(w, h));
            let cmds = app.start();
            run_sync_tolerant(&mut app, cmds);
            app.focus = pane;
            let cmds = app.handle(AppEvent::Resize(w, h)); // what the pane needs
            run_sync_tolerant(&mut app, cmds);
            snap(
                &format!(
                    "deck_{stem}_{}",
                    app.pane_title(pane).to_lowercase().replace(' ', "_")
                ),
                &app,
                w,
                h,
            );
        }
    }
}

/// A shipped deck as the snapshots draw it: as shipped, except that a cylindrical
/// roller deck's dynamics runs 8 shaft revolutions with 3 to settle instead of 100 and
/// 20 (the panes' layout is the same; the 20 screens of a deck would otherwise each run
/// the full time simulation in a debug build), and the double-row deck's optimiser grid
/// is 5 × 5 instead of 21 × 21 (the Optimise pane's layout is the same; 1 323 grid
/// solves would take minutes in a debug build). The Inputs screens do not reach the
/// `[dynamics]` or `[optimise]` groups at these sizes.
pub(super) fn shipped_deck_for_snapshots(path: &std::path::Path) -> DeckDoc {
    let text = std::fs::read_to_string(path).expect("shipped deck reads");
    if text.contains("type = \"double-row-spherical-roller\"") {
        let text = text.replace("\ngrid = 21", "\ngrid = 5");
        assert!(
            text.contains("\ngrid = 5"),
            "the optimiser's grid line moved"
        );
        return DeckDoc::parse(&text, &path.display().to_string()).expect("shipped deck loads");
    }
    if !text.contains("type = \"cylindrical-roller\"") {
        return DeckDoc::load(path).expect("shipped deck loads");
    }
    let text = text
        .replace("\nrevolutions = 100", "\nrevolutions = 8")
        .replace("\nsettle_revolutions = 20", "\nsettle_revolutions = 3");
    DeckDoc::parse(&text, &path.display().to_string()).expect("shipped deck loads")
}

/// Like [`run_sync`], but a deck that does not solve shows its failure (as the worker
/// would report it) instead of failing the test.
pub(super) fn run_sync_tolerant(app: &mut App, cmds: Vec<Command>) {
    for c in cmds {
        if let Command::Solve(job) = c {
            let outcome = solve_view(&job).map(Arc::new).map_err(|e| e.to_string());
            let solved = outcome.is_ok();
            let more = app.handle(AppEvent::Solved {
                generation: job.generation,
                outcome,
            });
            if solved {
                sweep_sync(app, &job);
                job_sync(app, &job);
                study_sync(app, &job);
            }
            run_sync_tolerant(app, more);
        }
    }
}

#[test]
fn tui_docs_list_every_key() {
    // The key tables of the README and docs/workbench.md are app::keys_markdown() exactly;
    // ROLLBENCH_UPDATE_DOCS=1 rewrites them.
    let table = app::keys_markdown();
    for doc in ["README.md", "docs/workbench.md"] {
        let path = format!("{}/{doc}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("doc");
        if std::env::var_os("ROLLBENCH_UPDATE_DOCS").is_some() {
            let start = text.find("| Key | Where | Action |").expect("a key table");
            let end = text[start..]
                .lines()
                .take_while(|l| l.starts_with('|'))
                .map(|l| l.len() + 1)
                .sum::<usize>()
                + start;
            let updated = format!("{}{table}{}", &text[..start], &text[end..]);
            std::fs::write(&path, updated).expect("write doc");
            continue;
        }
        assert!(text.contains(&table), "{doc}: key table differs from KEYS");
    }
}

#[test]
fn tui_choice_field_cycles_with_arrows() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    select_field(&mut app, "lubricant.film_model");
    assert_eq!(
        app.deck.value("lubricant.film_model", app.display_units),
        "grubin"
    );
    app.handle(key(KeyCode::Enter));
    app.handle(key(KeyCode::Down));
    match &app.mode {
        Mode::Editing { buffer, .. } => assert_eq!(buffer, "dowson-higginson"),
        m => panic!("{m:?}"),
    }
    let cmds = app.handle(key(KeyCode::Enter));
    assert!(matches!(cmds.as_slice(), [Command::Solve(_)]));
    assert_eq!(
        app.deck.value("lubricant.film_model", app.display_units),
        "dowson-higginson"
    );
    // the case behind the deck took it: the choice's index in the film model list
    let film = app.deck.case().field_si("lubricant.film_model");
    let dh = crate::bearings::spherical_roller::deck_schema::FILM_MODELS
        .iter()
        .position(|m| *m == "dowson-higginson");
    assert_eq!(film.map(|f| f as usize), dh);
}

#[test]
fn tui_parsed_deck_text_round_trips_unchanged() {
    // run_workbench_case compares the file text with the deck's text to decide
    // "unsaved": an unmodified deck must give back its file byte for byte.
    let case = crate::bearings::load_case(
        crate::bearings::spherical_roller::deck::DEFAULT_DECK,
        "x",
        &[],
    )
    .expect("deck");
    let doc = DeckDoc::from_case(case);
    assert_eq!(
        doc.text(),
        crate::bearings::spherical_roller::deck::DEFAULT_DECK
    );
}

/// The thermal pane's drawing, with a made-up view (the thermal stage is wired by the
/// lead in `view_model::thermal_view`), plus degenerate series that must not panic.
#[test]
fn tui_thermal_view_renders() {
    use ratatui::buffer::Buffer;
    use ratatui::layout::Rect;
    let row = |name: &str, steady: f64, limit: Option<f64>, at: Option<f64>| view_model::NodeRow {
        name: name.into(),
        steady,
        fixed: false,
        limit,
        time_to_limit_s: at,
    };
    let view = view_model::ThermalView {
        nodes: vec![
            row("inner ring", 121.5, Some(110.0), Some(312.25)),
            row("outer ring", 98.25, None, None),
            row("oil out", 104.0, None, None),
        ],
        selected: 0,
        selected_is_hottest: true,
        temperature_unit: "°C".into(),
        series: (0..40)
            .map(|i| {
                let t = 15.0 * i as f64;
                (t, 40.0 + 80.0 * (1.0 - (-(i as f64) / 10.0).exp()))
            })
            .collect(),
    };
    let area = Rect::new(0, 0, 40, 10);
    let mut buf = Buffer::empty(area);
    render::render_thermal_view(&view, area, &mut buf);
    let text: String = (0..area.height)
        .map(|y| {
            (0..area.width)
                .map(|x| buf[(x, y)].symbol().to_string())
                .collect::<String>()
                + "\n"
        })
        .collect();
    assert_snapshot!("thermal_view_40x10", text);
    // Issue 30 item 13: "hottest" says when, and the line names the chart's limit line
    // and marker (the legend is hidden on small panes).
    assert_eq!(
        view.summary(),
        "inner ring (hottest at the end of the transient): 40.0 → 118.4 °C over 585 s · limit 110.0 °C (── line), reached at 312.2 s (█)"
    );
    let steady = view_model::ThermalView {
        series: Vec::new(),
        ..view.clone()
    };
    assert!(
        steady
            .summary()
            .starts_with("inner ring (hottest in the steady state): steady "),
        "{}",
        steady.summary()
    );
    let series_cases: [Vec<(f64, f64)>; 4] = [
        vec![],
        vec![(0.0, 5.0)],
        vec![(0.0, f64::NAN), (1.0, 1.0)],
        vec![(0.0, 3.0); 10],
    ];
    for series in series_cases {
        let v = view_model::ThermalView {
            series,
            ..view.clone()
        };
        for (w, h) in [(1, 1), (10, 3), (40, 10)] {
            let r = Rect::new(0, 0, w, h);
            let mut b = Buffer::empty(r);
            render::render_thermal_view(&v, r, &mut b);
        }
    }
}

/// The thermal node walk of the issue (`4`, then `j j k k k k G G k Home End`): the
/// selection stays on a node of the list, `G` is the last node, `j`/`k` always move it,
/// and the node list scrolls to keep it in view (issue 15 #2).
#[test]
fn thermal_node_selection_stays_in_the_list() {
    let mut app = solved_app(Pane::Thermal, 80, 24);
    let n = app
        .view
        .as_ref()
        .and_then(|v| v.thermal.as_ref())
        .map(|t| t.steady.len())
        .expect("the aerospace deck has a thermal network");
    assert!(n > 10, "{n} nodes");
    let hottest = app
        .view
        .as_ref()
        .and_then(|v| v.thermal.as_ref())
        .and_then(view_model::hottest_node)
        .expect("a hottest node");
    let mut seen = Vec::new();
    for k in ["j", "j", "k", "k", "k", "k", "G", "G", "k", "Home", "End"] {
        let code = match k {
            "Home" => KeyCode::Home,
            "End" => KeyCode::End,
            c => KeyCode::Char(c.chars().next().unwrap_or('j')),
        };
        app.handle(key(code));
        let sel = app.thermal_node.expect("a node is selected");
        assert!(sel < n, "{k}: {sel} of {n}");
        seen.push(sel);
    }
    let expect_first = (hottest + 2).min(n - 1) - 1;
    assert_eq!(seen[2], expect_first, "k moves back from where j left it");
    assert_eq!(seen[6], n - 1, "G is the last node");
    assert_eq!(seen[8], n - 2, "k after G moves up");
    assert_eq!(seen[9], 0);
    assert_eq!(seen[10], n - 1);
    // The last node is on screen, highlighted.
    let t = draw(&app, 80, 24);
    let last = app
        .view
        .as_ref()
        .and_then(|v| v.thermal.as_ref())
        .and_then(|t| t.steady.last())
        .map(|s| s.name.clone())
        .expect("a last node");
    let screen: String = t
        .backend()
        .buffer()
        .content()
        .iter()
        .map(|c| c.symbol())
        .collect();
    assert!(screen.contains(&last), "{last} not on screen");
}

/// The whole loop with a solver that panics: the frame shows a failed solve and the
/// app keeps handling keys.
#[test]
fn tui_event_loop_survives_solver_panic() {
    install_solver_panic_filter();
    let mut terminal = Terminal::new(TestBackend::new(80, 24)).expect("backend");
    let (tx, rx) = mpsc::channel();
    let solver: Solver = Arc::new(|_, _, _, _| panic!("deliberate solver panic"));
    let mut worker = Worker::spawn(tx.clone(), solver).expect("spawn");
    // Keys arrive well after the first (panicking) solve has been reported.
    let forward = std::thread::spawn({
        let tx = tx.clone();
        move || {
            std::thread::sleep(Duration::from_millis(300));
            for ev in [key(KeyCode::Tab), key(KeyCode::Tab), ch('q')] {
                let _ = tx.send(ev);
            }
        }
    });
    let app = run_loop(&mut terminal, deck_app(), &rx, &mut worker).expect("loop");
    let _ = forward.join();
    drop(worker);
    assert!(app.quit);
    assert_eq!(app.focus, Pane::Elements);
    match &app.solve {
        SolveState::Failed(m) => assert!(m.contains("deliberate solver panic"), "{m}"),
        s => panic!("expected a failed solve, got {s:?}"),
    }
    terminal
        .draw(|f| f.render_widget(&app, f.area()))
        .expect("draw");
    let screen = terminal.backend().to_string();
    assert!(
        screen.contains("failed (e: whole message): solver panicked"),
        "{screen}"
    );
}

#[test]
fn tui_quit_prompt_save_without_file_asks_for_a_name_then_quits() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut app = deck_app();
    app.path = None;
    select_field(&mut app, "operating.axial_load");
    let c = type_value(&mut app, "1250");
    run_sync(&mut app, c);
    app.handle(ch('q'));
    assert_eq!(app.mode, Mode::ConfirmQuit);
    assert!(app.handle(ch('s')).is_empty());
    assert!(matches!(
        app.mode,
        Mode::Prompt {
            kind: PromptKind::SaveAs,
            ..
        }
    ));
    for _ in 0..20 {
        app.handle(key(KeyCode::Backspace));
    }
    let target = dir.path().join("new.toml");
    for c in target.display().to_string().chars() {
        app.handle(ch(c));
    }
    let cmds = app.handle(key(KeyCode::Enter));
    let (tx, _rx) = mpsc::channel();
    let mut worker =
        Worker::spawn(tx, Arc::new(|_, _, _, _| Err(SolveError::Cancelled))).expect("w");
    perform(&mut app, cmds, &mut worker);
    assert!(app.quit, "{:?}", app.message);
    assert!(target.exists());
    assert_eq!(
        DeckDoc::load(&target).expect("load").text(),
        app.deck.text()
    );
}

#[test]
fn load_chart_is_the_load_per_length_along_the_roller() {
    // A straight roller on straight raceways (crown radii 10 km), zero contact angle, pure
    // radial load at rest: every lamina sits at the same approach, so the load per unit
    // length is uniform along the roller (line contact). With cosine slicing the laminae
    // range from thin at the ends to π/2 times the mean width in the middle, so their loads
    // alone would not be: the chart and the stepper's bars must be flat. SI: N/mm.
    let mut b = crate::verify::cases::stribeck_bearing(16);
    let g = &mut b.geometry;
    g.roller_crown_radius_m = 1e4;
    g.inner_crown_radius_m = 1e4;
    g.outer_crown_radius_m = 1e4;
    let req = crate::bearings::spherical_roller::pipeline::Request {
        trace_roller: Some(0),
        ..Default::default()
    };
    let a = crate::bearings::spherical_roller::pipeline::run(&b, &req, None)
        .unwrap_or_else(|e| panic!("{e}"));
    let flat = |v: &[f64], what: &str| {
        let (lo, hi) = v
            .iter()
            .fold((f64::MAX, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
        assert!(lo > 0.0 && hi / lo - 1.0 < 1e-9, "{what}: {lo} … {hi}");
    };
    let v = crate::bearings::spherical_roller::view::view(&a);
    let s = view_model::chart_series(&v.element_charts[0], crate::units::Units::Si);
    assert_eq!(s.y_label, "N/mm");
    let inner = &s.series[0].1;
    flat(&inner.iter().map(|p| p.1).collect::<Vec<_>>(), "chart");
    // The chart's level is the roller's load over its length (Q/L, here in N/mm).
    let r = &a.load.rollers[0];
    let q_over_l = r.laminae.iter().map(|l| l.inner_load_n).sum::<f64>()
        / b.geometry.effective_length_m
        * 1e-3;
    assert!((inner[0].1 / q_over_l - 1.0).abs() < 1e-9);
    let trace = v.trace.as_ref().expect("a trace");
    let last = trace.steps.len() - 1;
    let step = view_model::trace_step(trace, last, crate::units::Units::Si).expect("a step");
    let inner_load = &step.bars.first().expect("bars").values;
    flat(inner_load, "stepper bars");
}

/// While only "terminal too small" is shown, keys do nothing unseen (Tab and `u` used to
/// change the pane and the units); `q` still quits. (Fails on the previous code.)
#[test]
fn too_small_terminal_ignores_keys() {
    let mut app = deck_app();
    app.handle(AppEvent::Resize(40, 10));
    let before = (app.focus, app.display_units, app.mode.clone());
    app.handle(key(KeyCode::Tab));
    app.handle(ch('u'));
    app.handle(ch('S'));
    assert_eq!((app.focus, app.display_units, app.mode.clone()), before);
    app.handle(AppEvent::Resize(100, 30));
    app.handle(ch('u'));
    assert_ne!(app.display_units, before.1);
}

/// `S` (save as) onto a file that exists asks first: `y` replaces it, any other key goes
/// back to the prompt; nothing is written before the answer. Saving as the deck's own
/// file does not ask. (Fails on the previous code: Enter saved at once.)
#[test]
fn save_as_asks_before_replacing_an_existing_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let target = dir.path().join("other.toml");
    std::fs::write(&target, "# someone else's deck\n").expect("write");
    let (tx, _rx) = mpsc::channel();
    let mut worker =
        Worker::spawn(tx, Arc::new(|_, _, _, _| Err(SolveError::Cancelled))).expect("w");
    let mut app = deck_app();
    let type_target = |app: &mut App| {
        app.handle(ch('S'));
        for _ in 0..80 {
            app.handle(key(KeyCode::Backspace));
        }
        for c in target.display().to_string().chars() {
            app.handle(ch(c));
        }
        app.handle(key(KeyCode::Enter))
    };
    // Pure transitions: the existence check is a command for the runtime.
    let cmds = type_target(&mut app);
    assert_eq!(cmds, vec![Command::CheckSaveTarget(target.clone())]);
    let cmds = app.handle(AppEvent::SaveTargetChecked {
        path: target.clone(),
        exists: true,
    });
    assert!(cmds.is_empty(), "{cmds:?}");
    assert_eq!(
        app.mode,
        Mode::ConfirmOverwrite {
            path: target.clone()
        }
    );
    // n: back to the prompt with the name, nothing written
    assert!(app.handle(ch('n')).is_empty());
    assert_eq!(
        app.mode,
        Mode::Prompt {
            kind: PromptKind::SaveAs,
            buffer: target.display().to_string()
        }
    );
    app.handle(key(KeyCode::Esc));
    assert_eq!(app.mode, Mode::Normal);
    // Through the runtime: the file exists, so it asks; y replaces it.
    let cmds = type_target(&mut app);
    perform(&mut app, cmds, &mut worker);
    assert!(matches!(app.mode, Mode::ConfirmOverwrite { .. }));
    assert_eq!(
        std::fs::read_to_string(&target).expect("read"),
        "# someone else's deck\n"
    );
    let cmds = app.handle(ch('y'));
    perform(&mut app, cmds, &mut worker);
    assert_eq!(app.mode, Mode::Normal);
    assert_eq!(app.path.as_deref(), Some(target.as_path()));
    assert_eq!(
        DeckDoc::load(&target).expect("load").text(),
        app.deck.text()
    );
    // Now it is the deck's own file: save as onto it saves without asking.
    let cmds = type_target(&mut app);
    assert!(
        matches!(cmds.as_slice(), [Command::Save { path, .. }] if *path == target),
        "{cmds:?}"
    );
}

#[test]
fn tui_snapshot_confirm_overwrite() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    app.mode = Mode::ConfirmOverwrite {
        path: PathBuf::from("decks/industrial.toml"),
    };
    snap("confirm_overwrite", &app, 80, 24);
}

/// A termination signal quits at once, even with unsaved changes and a prompt open, and
/// the app remembers it (the runtime exits with 128 + signal after restoring the terminal).
#[test]
fn signal_quits_without_asking() {
    let mut app = deck_app();
    select_field(&mut app, "operating.axial_load");
    let c = type_value(&mut app, "1250");
    run_sync(&mut app, c);
    assert!(app.unsaved());
    app.handle(ch('S'));
    let cmds = app.handle(AppEvent::Signal(signal_hook::consts::SIGTERM));
    assert_eq!(cmds, vec![Command::Quit]);
    assert!(app.quit);
    assert_eq!(app.signal, Some(15));
    let i = Interrupted {
        signal: 15,
        unsaved: true,
    };
    assert_eq!(i.exit_code(), 143);
    assert!(i.to_string().contains("SIGTERM"), "{i}");
}

/// The loop leaves on a signal event although the deck is unsaved.
#[test]
fn run_loop_leaves_on_a_signal() {
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(
        tx.clone(),
        Arc::new(|_, _, _, _| Err(SolveError::Cancelled)),
    )
    .expect("w");
    let mut terminal = Terminal::new(TestBackend::new(80, 24)).expect("backend");
    let mut app = deck_app();
    app.saved_text = String::new(); // unsaved
    tx.send(ch('q')).expect("send"); // asks (unsaved)
    tx.send(AppEvent::Signal(signal_hook::consts::SIGHUP))
        .expect("send");
    let app = run_loop(&mut terminal, app, &rx, &mut worker).expect("loop");
    assert!(app.quit);
    assert_eq!(app.signal, Some(signal_hook::consts::SIGHUP));
}

/// Errors are read whole (issue 15 #3): a failed open pops up its whole message (the
/// status line used to show `open failed: nope.toml: ca`), one message per line; any key
/// closes it and `e` brings it back; a failed solve's status line points at `e`.
#[test]
fn errors_are_shown_whole_and_reopen_with_e() {
    let mut app = solved_app(Pane::Inputs, 80, 24);
    assert!(app.handle(ch('e')).is_empty());
    assert_eq!(app.mode, Mode::Normal, "no error yet: e says so");
    assert_eq!(app.message.as_deref(), Some("no error to show"));
    app.handle(ch('o'));
    for c in "nope.toml".chars() {
        app.handle(ch(c));
    }
    let cmds = app.handle(key(KeyCode::Enter));
    let mut worker_less = Vec::new();
    for c in cmds {
        if let Command::Open(p) = c {
            let r = DeckDoc::load(&p).map(|d| (Box::new(d), p));
            worker_less.extend(app.handle(AppEvent::Opened(r)));
        }
    }
    assert!(worker_less.is_empty());
    assert_eq!(app.mode, Mode::Error);
    let whole = app.error.clone().expect("the error is kept");
    assert!(
        whole.contains("nope.toml") && whole.contains("cannot read deck"),
        "{whole}"
    );
    let t = draw(&app, 80, 24);
    let screen = t.backend().to_string();
    for line in whole.lines() {
        for word in line.split_whitespace() {
            assert!(screen.contains(word), "{word:?} of {line:?} not on screen");
        }
    }
    snap("error_popup", &app, 80, 24);
    app.handle(key(KeyCode::Esc));
    assert_eq!(app.mode, Mode::Normal);
    app.handle(ch('e'));
    assert_eq!(app.mode, Mode::Error);
    app.handle(ch('x'));
    assert_eq!(app.mode, Mode::Normal);
    // A long solver failure: the status line points at e, the popup wraps it whole.
    let reason = "no equilibrium near the design geometry: the bearing needs an axial load or preload (axial load 0 N, radial load 0 N, speed 17000 rpm)".to_string();
    app.handle(AppEvent::Solved {
        generation: app.generation,
        outcome: Err(reason.clone()),
    });
    let screen = draw(&app, 60, 20).backend().to_string();
    assert!(screen.contains("✗ failed (e: whole message)"), "{screen}");
    app.handle(ch('e'));
    let screen = draw(&app, 60, 20).backend().to_string();
    for word in reason.split_whitespace() {
        assert!(screen.contains(word), "{word:?} not on screen:\n{screen}");
    }
}

/// The stepper agrees with the results (issue 15): it steps through every outer
/// (dynamic-load) iteration of the real solve (after the same coarse pre-solve), and its
/// last step is that solve's final state, so the
/// ring deflections it shows are the solution's, and tracing changes neither the solution
/// nor the solver counts on the status line. The last step's ring is the solution's ring
/// to 1e-12 relative (the same numbers, passed through; round-off only); counts exactly.
#[test]
fn stepper_ends_at_the_solution_shown() {
    let plain = solved_app(Pane::Elements, 80, 24);
    let traced = solved_app(Pane::Stepper, 80, 24);
    let (pv, tv) = (
        plain.view.clone().expect("solved"),
        traced.view.clone().expect("solved"),
    );
    assert!(pv.trace.is_none());
    let trace = tv.trace.as_ref().expect("the stepper's trace");
    assert!(
        trace.label.contains("dynamic-load iterations"),
        "{}",
        trace.label
    );
    let last = trace.steps.last().expect("steps");
    let first = trace.steps.first().expect("steps");
    assert_eq!(first.iteration[0], 1, "from the first outer iteration");
    assert!(last.iteration[0] > 1, "to the last: {:?}", last.iteration);
    let ring = &last.lines[1].values; // ring ax, rad (m)
    let summary = |v: &crate::bearings::view::View, i: usize| v.summary[i].value;
    for (i, &x) in ring.iter().enumerate() {
        let s = summary(&pv, i);
        assert!(
            (x - s).abs() <= 1e-12 * s.abs(),
            "ring {i}: stepper {x} vs solution {s}"
        );
    }
    assert_eq!(pv.stats.iterations, tv.stats.iterations);
    assert_eq!(pv.stats.inner_iterations, tv.stats.inner_iterations);
    assert_eq!(pv.tables, tv.tables, "tracing changes no result");
}

/// `/` finds an input by name or key (issue 15: 27 presses of j to reach the radial load):
/// typing narrows to the first match, Tab goes to the next, Enter keeps it, Esc goes back.
#[test]
fn slash_finds_a_field_by_name() {
    let mut app = solved_app(Pane::Elements, 80, 24);
    let start = app.input_sel;
    app.handle(ch('/'));
    assert_eq!(app.focus, Pane::Inputs);
    for c in "radial load".chars() {
        app.handle(ch(c));
    }
    let radial = field_index(&app, "operating.radial_load");
    assert_eq!(app.input_sel, radial);
    app.handle(key(KeyCode::Enter));
    assert_eq!(app.mode, Mode::Normal);
    assert_eq!(app.input_sel, radial);
    // Esc goes back to where the search began; Tab walks the matches.
    app.handle(ch('/'));
    for c in "modulus".chars() {
        app.handle(ch(c));
    }
    let first = app.input_sel;
    assert!(
        app.fields[first].label.contains("modulus"),
        "{:?}",
        app.fields[first]
    );
    app.handle(key(KeyCode::Tab));
    assert!(app.input_sel != first && app.fields[app.input_sel].label.contains("modulus"));
    app.handle(key(KeyCode::Esc));
    assert_eq!(app.input_sel, radial);
    assert_ne!(radial, start);
}

/// The help overlay scrolls when it does not fit (issue 15: cut at 60×20): every key is
/// reachable with j, and the title says which rows are shown.
#[test]
fn help_scrolls_to_every_key() {
    let mut app = solved_app(Pane::Inputs, 60, 20);
    app.handle(ch('?'));
    let mut seen = String::new();
    for _ in 0..KEYS.len() {
        seen.push_str(&draw(&app, 60, 20).backend().to_string());
        app.handle(ch('j'));
    }
    assert_eq!(app.mode, Mode::Help, "j scrolls, it does not close");
    for (k, _, _) in KEYS {
        assert!(seen.contains(k), "{k} never shown");
    }
    app.handle(ch('x'));
    assert_eq!(app.mode, Mode::Normal);
}

/// Issue 30 item 16: `?` on the element table says what the pane shows and, for every
/// column of the view's table, its header and what it means (read from the view's own
/// columns); Λ is explained in words. At 60×20 by scrolling, at 80×24 too.
#[test]
fn help_explains_every_column_of_the_table() {
    for (w, h) in [(60, 20), (80, 24)] {
        let mut app = solved_app(Pane::Elements, w, h);
        app.handle(ch('?'));
        let mut seen = String::new();
        for _ in 0..(KEYS.len() + 30) {
            seen.push_str(&draw(&app, w, h).backend().to_string());
            app.handle(ch('j'));
        }
        let view = app.view.clone().expect("solved");
        let table = view.screen_table().expect("table");
        assert!(seen.contains("this pane"), "{w}×{h}");
        for c in &table.columns {
            let Some(s) = c.screen else { continue };
            let header = s.display.header(s.label, app.display_units);
            let help = crate::bearings::view::column_help(c.key);
            let first = help
                .split_whitespace()
                .take(2)
                .collect::<Vec<_>>()
                .join(" ");
            assert!(
                seen.contains(&header),
                "{w}×{h}: column {header} not in the help"
            );
            assert!(
                seen.contains(&first),
                "{w}×{h}: {header}: '{first}' not in the help"
            );
        }
        assert!(seen.contains("film parameter Λ"), "{w}×{h}");
    }
}

/// The screens in README.md and docs/workbench.md are the snapshot tests' frames: each
/// `<!-- screen: NAME -->` marker is followed by a code block holding snapshot NAME's
/// lines exactly. ROLLBENCH_UPDATE_DOCS=1 rewrites the blocks from the snapshots.
#[test]
fn tui_docs_screens_are_the_snapshots() {
    let root = env!("CARGO_MANIFEST_DIR");
    for doc in [
        "README.md",
        "docs/workbench.md",
        "docs/double_row_spherical.md",
    ] {
        let path = format!("{root}/{doc}");
        let text = std::fs::read_to_string(&path).expect("doc");
        let mut out = String::new();
        let mut rest = text.as_str();
        let mut found = 0;
        while let Some(at) = rest.find("<!-- screen: ") {
            let (before, from) = rest.split_at(at);
            out.push_str(before);
            let name_end = from.find(" -->").expect("marker end");
            let name = &from["<!-- screen: ".len()..name_end];
            let snap_path = format!("{root}/src/tui/snapshots/rollbench__tui__tests__{name}.snap");
            let snap = std::fs::read_to_string(&snap_path)
                .unwrap_or_else(|e| panic!("{doc}: {name}: {e}"));
            // The frame: the snapshot's quoted lines, unquoted, trailing blanks cut.
            let frame: String = snap
                .lines()
                .filter(|l| l.starts_with('"') && l.ends_with('"') && l.len() >= 2)
                .map(|l| format!("{}\n", l[1..l.len() - 1].trim_end()))
                .collect();
            let block_start = from.find("```\n").expect("a code block after the marker");
            let body_start = block_start + 4;
            let body_len = from[body_start..].find("```").expect("block end");
            let current = &from[body_start..body_start + body_len];
            if std::env::var_os("ROLLBENCH_UPDATE_DOCS").is_none() {
                assert_eq!(
                    current, frame,
                    "{doc}: screen {name} differs from its snapshot"
                );
            }
            out.push_str(&from[..body_start]);
            out.push_str(&frame);
            rest = &from[body_start + body_len..];
            found += 1;
        }
        out.push_str(rest);
        assert!(found > 0, "{doc} has no screen markers");
        if std::env::var_os("ROLLBENCH_UPDATE_DOCS").is_some() {
            std::fs::write(&path, out).expect("write doc");
        }
    }
}

// ---------------------------------------------------------------- sweep pane

fn tapered_app(w: u16, h: u16) -> App {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/trb_afapl.toml");
    let deck = DeckDoc::load(std::path::Path::new(path)).expect("deck");
    let mut app = App::new(deck, None);
    app.handle(AppEvent::Resize(w, h));
    app
}

#[test]
fn tui_sweep_is_solved_only_while_its_pane_is_on_screen() {
    // "No stage computed that the view does not need": the first solve of the tapered deck
    // on the Inputs pane asks for no sweep; focusing the Sweep pane asks for sweep 0 and
    // re-solves; the points arrive as progress for the current generation, and progress
    // of an older generation is ignored.
    let mut app = tapered_app(80, 24);
    let cmds = app.start();
    let [Command::Solve(first)] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    assert_eq!(first.sweep, None);
    run_sync(&mut app, cmds);
    assert!(app.sweep.is_none());
    let pos = app
        .panes()
        .iter()
        .position(|p| *p == Pane::Sweep(0))
        .expect("a Sweep pane");
    let digit = char::from_digit(pos as u32 + 1, 10).expect("digit");
    let cmds = app.handle(ch(digit));
    let [Command::Solve(job)] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    assert_eq!(job.sweep, Some(0));
    let generation = job.generation;
    run_sync(&mut app, cmds);
    let Some((g, n, p)) = app.sweep.clone() else {
        panic!("no sweep")
    };
    assert_eq!((g, n), (generation, 0));
    assert!(p.done);
    assert_eq!(p.points.len(), p.plan.values.len());
    // Stale progress (an older generation) does not replace it.
    let mut old = (*p).clone();
    old.points.clear();
    app.handle(AppEvent::SweepProgress {
        generation: generation - 1,
        pane: 0,
        progress: Arc::new(old),
    });
    assert_eq!(
        app.sweep.as_ref().map(|s| s.2.points.len()),
        Some(p.points.len())
    );
    // Leaving the pane: the next edit's solve asks for no sweep.
    let cmds = app.handle(ch('1'));
    assert!(cmds.is_empty(), "{cmds:?}");
    assert_eq!(app.wanted_sweep(), None);
}

#[test]
fn tui_sweep_points_are_the_cli_sweep_normalised() {
    // The pane draws each stiffness divided by its zero-speed value: the same numbers as
    // `rollbench sweep` (studies::sweep, cold) over the plan's values, to 1e-7 (warm
    // against cold starts, the solver tolerance).
    let mut app = tapered_app(80, 24);
    let cmds = app.start();
    run_sync(&mut app, cmds);
    let pos = app
        .panes()
        .iter()
        .position(|p| *p == Pane::Sweep(0))
        .expect("pane");
    let cmds = app.handle(ch(char::from_digit(pos as u32 + 1, 10).expect("digit")));
    run_sync(&mut app, cmds);
    let (_, _, p) = app.sweep.clone().expect("sweep");
    let (chart, _, note) = view_model::sweep_series(&p, crate::units::Units::Si);
    assert!(
        note.starts_with(&format!("{0}/{0} points", p.plan.values.len())),
        "{note}"
    );
    let case = app.deck.case();
    for (k, name) in p.plan.outputs.iter().enumerate() {
        let series = &chart.series[k].1;
        let base = p.points[0].output(name).expect("zero-speed value");
        for (pt, &(x, y)) in p
            .points
            .iter()
            .filter(|pt| pt.output(name).is_some())
            .zip(series)
        {
            let cold = case
                .with_value(p.plan.key, &crate::studies::sweep::value_text(pt.value))
                .expect("valid")
                .solve(
                    crate::bearings::RunOptions {
                        skip_transient: true,
                    },
                    Cancel::NONE,
                )
                .expect("solves")
                .view();
            let v = cold
                .key_outputs
                .iter()
                .find(|o| o.name == *name)
                .and_then(|o| o.value)
                .expect("output");
            assert!(
                (x - pt.value).abs() <= 1e-9 * pt.value.abs().max(1.0),
                "{x} {}",
                pt.value
            );
            assert!(
                (y - v / base).abs() <= 1e-7,
                "{name} at {}: {y} vs {}",
                pt.value,
                v / base
            );
        }
    }
}

#[test]
fn tui_sweep_marks_the_first_speed_with_a_roller_off_the_cone() {
    // Load Condition 2 (700 lbf radial) at a deck speed of 15 600 rpm: the pane sweeps
    // 0–39 000 rpm in steps of 1 950; the rollers nearest φ = 180° leave the cone at
    // ≈ 38 900 rpm (tapered_roller tests), so 39 000 is the first point with
    // `rollers_off_cone` > 0 and the marker sits there, 37 050 still has none.
    let app = tapered_app(80, 24);
    let case = app
        .deck
        .case()
        .with_value("operating.radial_load", "700")
        .and_then(|c| c.with_value("operating.inner_speed", "15600"))
        .expect("valid");
    let plan = case
        .system()
        .sweep_plan(0, case.as_ref())
        .expect("a sweep plan");
    let mut session = case.system().session();
    let mut solve = |c: &dyn crate::bearings::Case| {
        session
            .solve(c, Detail::default(), &Cancel::NONE)
            .map(|s| s.view())
    };
    let p =
        crate::studies::sweep::run_plan(case.as_ref(), plan, &mut solve, &|| false, &mut |_| {})
            .expect("not cancelled");
    let off = |v: f64| {
        p.points
            .iter()
            .find(|pt| pt.value == v)
            .and_then(|pt| pt.output("rollers_off_cone"))
    };
    assert_eq!(off(37_050.0), Some(0.0));
    assert!(off(39_000.0).is_some_and(|n| n > 0.0));
    let (_, marker, _) = view_model::sweep_series(&p, crate::units::Units::Us);
    assert_eq!(marker, Some(39_000.0));
}

#[test]
fn system_docs_hold_the_keys_tables() {
    // docs/ball.md and docs/tapered.md quote `rollbench keys --type …` verbatim: a key
    // added, renamed or re-ranged must show up there (regenerate the fenced block from
    // the command's output).
    for (doc, id) in [
        ("docs/ball.md", "angular-contact-ball"),
        ("docs/tapered.md", "tapered-roller"),
    ] {
        let path = format!("{}/{doc}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("doc");
        let table = crate::bearings::system(id).expect("system").keys_table();
        assert!(
            text.contains(table.trim_end()),
            "{doc} does not hold the output of `rollbench keys --type {id}`"
        );
    }
}

/// The ball's Skid pane fills as the worker solves (issue 16: "Skid … filled in
/// progressively by the worker"). With the pane on screen the job asks for chart 0 to be
/// streamed; the real worker sends it after every speed the skidding search solves (the
/// search runs before the ball dynamics) and then the solution. Checked: at least the
/// 30 bracketing speeds arrive, each with one more point than the last, all before the
/// solution; the last streamed chart is the solution's (exact: the same samples); the
/// screen shows the partial chart under a "searching" title while the job runs and the
/// solution's title once it lands; a stale generation's chart is ignored.
#[test]
fn tui_ball_skid_chart_streams_while_the_search_runs() {
    let deck =
        DeckDoc::parse(include_str!("../../decks/chen_b.toml"), "decks/chen_b.toml").expect("deck");
    let mut app = App::new(deck, Some(PathBuf::from("decks/chen_b.toml")));
    app.handle(AppEvent::Resize(80, 24));
    app.focus = Pane::Chart(0);
    let job = app
        .start()
        .into_iter()
        .find_map(|c| match c {
            Command::Solve(j) => Some(*j),
            _ => None,
        })
        .expect("a solve");
    assert_eq!(job.detail.stream_chart, Some(0));
    let generation = job.generation;
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, session_solver()).expect("spawn");
    worker.submit(job);
    let mut partials = Vec::new();
    let solved = loop {
        match rx
            .recv_timeout(Duration::from_secs(30))
            .expect("worker answers")
        {
            AppEvent::ChartProgress {
                generation: g,
                chart_index,
                chart,
            } => {
                assert_eq!((g, chart_index), (generation, 0));
                partials.push(chart);
            }
            e @ AppEvent::Solved { .. } => break e,
            other => panic!("unexpected {other:?}"),
        }
    };
    drop(worker);
    assert!(partials.len() >= 31, "{}", partials.len());
    let sizes: Vec<usize> = partials.iter().map(|c| c.series[0].points.len()).collect();
    // One more point per speed, then the finished chart (as many points as the last).
    for (k, w) in sizes.windows(2).enumerate() {
        let last = k + 2 == sizes.len();
        assert!(w[1] == w[0] + 1 || (last && w[1] == w[0]), "{sizes:?}");
    }
    let AppEvent::Solved {
        outcome: Ok(view), ..
    } = &solved
    else {
        panic!("solve failed: {solved:?}");
    };
    assert_eq!(**partials.last().expect("partials"), view.charts[0]);
    // On screen: the partial chart while the job runs, the solution's afterwards.
    app.handle(AppEvent::ChartProgress {
        generation: generation - 1, // stale: ignored
        chart_index: 0,
        chart: Arc::clone(&partials[3]),
    });
    assert!(app.streamed_chart(0).is_none());
    app.handle(AppEvent::ChartProgress {
        generation,
        chart_index: 0,
        chart: Arc::clone(&partials[5]),
    });
    assert_eq!(app.streamed_chart(0), Some(&*partials[5]));
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(
        screen.contains("searching for the skidding speed"),
        "{screen}"
    );
    app.handle(solved);
    assert!(app.streamed_chart(0).is_none());
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(screen.contains("skidding from"), "{screen}");
}

/// `c` swaps in the selected element's chart only on the pane that owns the element
/// charts (the ball's Dynamics pane, `View::element_chart_pane` = 1): on the Skid pane it
/// does nothing and the footer does not offer it (it used to draw ball 0's motion in the
/// Skid pane). On Dynamics it shows the ball's chart, whose heat curve is in the display
/// unit with the unit in its legend (Btu/hr in US).
#[test]
fn tui_ball_element_chart_lives_on_the_dynamics_pane() {
    let text = include_str!("../../decks/chen_b.toml")
        .replace("method = \"race-control\"", "method = \"time-simulation\"");
    assert!(text.contains("time-simulation"));
    let deck = DeckDoc::parse(&text, "decks/chen_b.toml").expect("deck");
    let mut app = App::new(deck, Some(PathBuf::from("decks/chen_b.toml")));
    app.handle(AppEvent::Resize(80, 24));
    let cmds = app.start();
    run_sync(&mut app, cmds);
    app.focus = Pane::Chart(0);
    app.handle(ch('c'));
    assert!(!app.chart_laminae);
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(
        screen.contains("Skid ·") && !screen.contains("c chart"),
        "{screen}"
    );
    app.focus = Pane::Chart(1);
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(screen.contains("c chart"), "{screen}");
    app.handle(ch('c'));
    assert!(app.chart_laminae);
    // Issue 30 item 1: ω_t (rad/s) and the heat (W) were drawn on one "ω_t rad/s · heat"
    // axis running 0–100 while ω_t ran −354…0: now two panels, one unit each, each axis
    // fitting its own data.
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(!screen.contains("· heat"), "{screen}");
    assert!(screen.contains("heat W"), "{screen}");
    assert!(screen.contains("ω_t rad/s"), "{screen}");
    let view = app.view.as_deref().expect("solved");
    let chart = &view.element_charts[app.roller_sel];
    let panels = view_model::chart_panels(chart, crate::units::Units::Si);
    assert_eq!(panels.len(), 2);
    for p in &panels {
        for (name, pts) in &p.series {
            for &(x, y) in pts {
                assert!(
                    (p.y_bounds[0]..=p.y_bounds[1]).contains(&y)
                        && (p.x_bounds[0]..=p.x_bounds[1]).contains(&x),
                    "{name} ({x}, {y}) outside {:?} × {:?}",
                    p.x_bounds,
                    p.y_bounds
                );
            }
        }
    }
    app.handle(ch('u'));
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(screen.contains("Dynamics · ball 1:"), "{screen}");
    assert!(screen.contains("Btu/hr"), "{screen}");
    assert!(screen.contains("heat Btu/hr"), "{screen}");
}

// ---------------------------------------------------------------- job panes

/// The shipped double-row deck (as the snapshots draw it: a 5 × 5 optimiser grid).
fn srb_app(w: u16, h: u16) -> App {
    let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/decks/srb_22308.toml"));
    let mut app = App::new(
        shipped_deck_for_snapshots(path),
        Some(PathBuf::from("decks/srb_22308.toml")),
    );
    app.handle(AppEvent::Resize(w, h));
    app
}

/// The Torque-vs-load pane's numbers are `load_sweep::torque_point`'s (the `losses`
/// command's) at the same F/C and direction: the series are read back from the drawn
/// charts (display units: N·m, and lbf·in in US, 1 lbf·in = 0.0254 m × 4.4482216152605 N
/// as units.rs defines it) and compared with the function run directly on the deck. The
/// same function on the same input is deterministic, so SI agrees exactly; US to 1e-12
/// (one division and one multiplication). Checked too: 10 points per direction at F/C
/// 0.02..0.2, x = F/C, M_fi and M_fo on one scale, and the line naming C = ISO 281's C_r
/// in kN.
#[test]
fn tui_torque_vs_load_reads_back_load_sweep() {
    use crate::bearings::double_row_spherical::load_sweep::{
        dynamic_rating_n, parse_range, torque_point, Direction,
    };
    use crate::bearings::double_row_spherical::system::DoubleRowCase;
    let mut app = srb_app(80, 24);
    let cmds = app.start();
    run_sync(&mut app, cmds);
    let pos = app
        .panes()
        .iter()
        .position(|p| *p == Pane::Job(0))
        .expect("a Torque vs load pane");
    assert_eq!(app.pane_title(Pane::Job(0)), "Torque vs load");
    let cmds = app.handle(ch(char::from_digit(pos as u32 + 1, 10).expect("digit")));
    let [Command::Solve(job)] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    assert_eq!(job.job, Some(0));
    run_sync(&mut app, cmds);
    let (_, _, v) = app.job.clone().expect("the job reported");
    assert!(v.finished && v.errors.is_empty(), "{:?}", v.errors);
    assert_eq!((v.done, v.total), (30, 30));
    let case = app.deck.case();
    let c = case
        .as_any()
        .downcast_ref::<DoubleRowCase>()
        .expect("double-row case");
    let input = &c.form.value;
    let c_n = dynamic_rating_n(input).expect("rated");
    let values = parse_range("0.02:0.2:0.02").expect("range");
    assert_eq!(values.len(), 10);
    assert!(
        v.notes[0]
            .si
            .contains(&format!("C = {:.1} kN (ISO 281 C_r)", c_n / 1e3)),
        "{:?}",
        v.notes
    );
    let (fi, fo) = (
        view_model::chart_series(&v.charts[0], crate::units::Units::Si),
        view_model::chart_series(&v.charts[1], crate::units::Units::Si),
    );
    let fi_us = view_model::chart_series(&v.charts[0], crate::units::Units::Us);
    assert_eq!(fi.title, "M_fi against F/C");
    assert_eq!(fo.title, "M_fo against F/C");
    assert_eq!(fi.y_label, "M N·m");
    assert_eq!(fi.y_bounds, fo.y_bounds, "one scale for both");
    for (d, dir) in Direction::ALL.iter().enumerate() {
        assert_eq!(fi.series[d].0, dir.name());
        assert_eq!(fi.series[d].1.len(), values.len());
        for (k, &f) in values.iter().enumerate() {
            let p = torque_point(input, &c.form.name, *dir, f, c_n, None).expect("solves");
            assert_eq!(
                fi.series[d].1[k],
                (f, p.friction_torque_inner_nm),
                "{dir:?} {f}"
            );
            assert_eq!(
                fo.series[d].1[k],
                (f, p.friction_torque_outer_nm),
                "{dir:?} {f}"
            );
            let lbf_in = fi_us.series[d].1[k].1;
            assert!(
                (lbf_in * crate::units::INCH_LBF_N_M / p.friction_torque_inner_nm - 1.0).abs()
                    < 1e-12,
                "{lbf_in}"
            );
        }
    }
}

/// An edit cancels the running job: with the Optimise pane on screen the worker runs the
/// optimiser (21 × 21 here: it runs for long) and reports it; an edit submits a new solve,
/// which raises the running job's cancel flag, drops what it reported from the app, and
/// the old job's later reports are ignored; the new job reports for the new generation.
#[test]
fn tui_an_edit_cancels_a_running_job() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/srb_22308.toml");
    let deck = DeckDoc::load(std::path::Path::new(path)).expect("deck");
    let mut app = App::new(deck, None);
    app.handle(AppEvent::Resize(80, 24));
    app.focus = Pane::Job(1);
    let (tx, rx) = mpsc::channel();
    let mut worker = Worker::spawn(tx, session_solver()).expect("spawn");
    let first = app
        .start()
        .into_iter()
        .find_map(|c| match c {
            Command::Solve(j) => Some(*j),
            _ => None,
        })
        .expect("a solve");
    assert_eq!(first.job, Some(1));
    let g1 = first.generation;
    worker.submit(first);
    let flag1 = worker.current_cancel().expect("a flag");
    // Wait for the first report of the job (after the case's own solve).
    let wait_job = |g: u64, app: &mut App| loop {
        let e = rx
            .recv_timeout(Duration::from_secs(120))
            .expect("the worker reports");
        let is_job = matches!(&e, AppEvent::JobProgress { generation, .. } if *generation == g);
        app.handle(e.clone());
        if is_job {
            break e;
        }
    };
    let old = wait_job(g1, &mut app);
    assert!(app.job.is_some());
    assert!(!flag1.load(Ordering::Acquire));
    // An edit on the Inputs pane (the Optimise pane is off screen: its solve asks for
    // no job) cancels the running job and drops its report.
    select_field(&mut app, "operating.radial_load");
    let cmds = type_value(&mut app, "18000");
    let second = cmds
        .into_iter()
        .find_map(|c| match c {
            Command::Solve(j) => Some(*j),
            _ => None,
        })
        .expect("the edit solves");
    assert_eq!(second.job, None);
    assert!(app.job.is_none(), "the old job's report is dropped");
    worker.submit(second);
    assert!(
        flag1.load(Ordering::Acquire),
        "the running job is cancelled"
    );
    // A late report of the old job changes nothing.
    app.handle(old);
    assert!(app.job.is_none());
    // Back on the Optimise pane: the job starts again on the edited deck.
    let pos = app
        .panes()
        .iter()
        .position(|p| *p == Pane::Job(1))
        .expect("an Optimise pane");
    let cmds = app.handle(ch(char::from_digit(pos as u32 + 1, 10).expect("digit")));
    let [Command::Solve(third)] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    assert_eq!(third.job, Some(1));
    assert!(third.case.text().contains("18000"));
    let g3 = third.generation;
    worker.submit((**third).clone());
    let new = wait_job(g3, &mut app);
    let AppEvent::JobProgress { view, .. } = new else {
        unreachable!()
    };
    assert!(!view.finished);
    assert_eq!(app.job.as_ref().map(|j| j.0), Some(g3));
    drop(worker);
}

/// Issue 30 item 16: at 60 columns the tab bar showed bare numbers (` 1  2:Rollers  3  4
/// 5`); now every pane's tab keeps at least the first two characters of its title (the
/// focused one whole) while the file and the units still show, at 60×20 and 80×24.
#[test]
fn tui_tabs_name_every_pane_at_60_columns() {
    for (w, h) in [(60, 20), (80, 24)] {
        let app = solved_app(Pane::Inputs, w, h);
        let screen = draw(&app, w, h).backend().to_string();
        let header = screen.lines().next().unwrap_or("").to_string();
        for (i, p) in app.panes().iter().enumerate() {
            let short: String = app.pane_title(*p).chars().take(2).collect();
            assert!(
                header.contains(&format!("{}:{short}", i + 1)),
                "{w}×{h}: pane {} ({}) unnamed in {header:?}",
                i + 1,
                app.pane_title(*p)
            );
        }
        assert!(
            header.contains("aerospace.toml") && header.contains("US"),
            "{header:?}"
        );
    }
}

/// The cylindrical Contact pane (issue 26) shows what `rollbench contact --format json`
/// gives for the same deck: the shipped truck deck on its quasi-statics
/// (`dynamics.revolutions = 0`) with `contact.inlet = "both"`, the pane's job run as the
/// worker runs it, each Table-3 line of the pane (SI) read back and compared with the
/// JSON entry of the same position and inlet to half a unit of the last digit shown
/// (W 1 N, h 0.001 µm, p 1 MPa, f 0.01 N, µ 1e-4, loss 0.1 W); the charts are of the
/// most loaded position, p and the Hertz pressure from its JSON profile.
#[test]
fn tui_contact_pane_reads_back_contact_json() {
    use crate::cli::{contact_command, ContactInletArg, ContactModelArg, Format};
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/crb_truck.toml");
    let text = std::fs::read_to_string(path)
        .expect("deck")
        .replace("\nrevolutions = 100", "\nrevolutions = 0")
        .replace("\n[contact]\n", "\n[contact]\ninlet = \"both\"\n");
    assert!(text.contains("\nrevolutions = 0") && text.contains("inlet = \"both\""));
    let deck = DeckDoc::parse(&text, "decks/crb_truck.toml").expect("deck loads");
    let mut app = App::new(deck, None);
    app.handle(AppEvent::Resize(200, 50));
    let cmds = app.start();
    run_sync(&mut app, cmds);
    assert_eq!(app.pane_title(Pane::Job(0)), "Contact");
    app.focus = Pane::Job(0);
    let cmds = app.handle(AppEvent::Resize(200, 50));
    run_sync(&mut app, cmds);
    let (_, _, v) = app.job.clone().expect("the Contact job reported");
    assert!(v.finished && v.errors.is_empty(), "{:?}", v.errors);
    let case = app.deck.case();
    let json = contact_command(
        &*case,
        &[],
        ContactInletArg::Both,
        ContactModelArg::LineEhl,
        false,
        Format::Json,
    )
    .expect("contact solves");
    let j: serde_json::Value = serde_json::from_str(&json).expect("json");
    let rows = j["contact"].as_array().expect("rows");
    assert_eq!(rows.len(), 6, "3 positions × 2 inlets");
    let lines: Vec<&str> = v.notes.iter().map(|n| n.si.as_str()).collect();
    assert_eq!(lines.len(), 2 + rows.len(), "{lines:?}");
    assert!(lines[0].contains("film µm") && lines[0].contains("pressure MPa"));
    for (row, line) in rows.iter().zip(&lines[2..]) {
        let t: Vec<&str> = line.split_whitespace().collect();
        let num = |k: usize| t[k].parse::<f64>().expect("a number");
        let f = |key: &str| row[key].as_f64().expect(key);
        // The deck's degrees went through radians: equal to a rounding, shown whole.
        assert!((num(0) - f("position_deg")).abs() <= 0.5, "{line}");
        let inlet = if row["inlet"] == "flooded" {
            "flood"
        } else {
            "tipei"
        };
        assert_eq!(t[1], inlet, "{line}");
        for (k, key, scale, half) in [
            (2, "load_n", 1.0, 0.5),
            (3, "central_film_m", 1e6, 5e-4),
            (4, "min_film_m", 1e6, 5e-4),
            (5, "max_pressure_pa", 1e-6, 0.5),
            (6, "boundary_friction_n", 1.0, 5e-3),
            (7, "viscous_friction_n", 1.0, 5e-3),
            (8, "friction_coefficient", 1.0, 5e-5),
            (9, "power_loss_w", 1.0, 5e-2),
        ] {
            let want = f(key) * scale;
            assert!(
                (num(k) - want).abs() <= half * (1.0 + 1e-9),
                "{key}: shown {} vs json {want} ({line})",
                t[k]
            );
        }
    }
    // The charts: the most loaded position's p (and Hertz) and h, from its profile.
    // The flooded row of the most loaded position (its Tipei row has the same load but
    // its own grid): the charts' first series.
    let top = rows
        .iter()
        .filter(|r| r["inlet"] == "flooded")
        .max_by(|a, b| {
            let w = |r: &serde_json::Value| r["load_n"].as_f64().unwrap_or(f64::NAN);
            w(a).total_cmp(&w(b))
        })
        .expect("a row");
    let profile = &top["profile"];
    let (p, h) = (&v.charts[0], &v.charts[1]);
    assert_eq!(p.series[0].name, "p flooded");
    assert_eq!(p.series[2].name, "Hertz");
    assert_eq!(h.series[1].name, "h Tipei");
    let xs = profile["x_m"].as_array().expect("x");
    assert_eq!(p.series[0].points.len(), xs.len());
    // serde_json's text round trip is exact to an ulp or so: 1e-12 relative.
    let same = |a: f64, b: &serde_json::Value| {
        let b = b.as_f64().expect("a number");
        (a - b).abs() <= 1e-12 * b.abs()
    };
    for (i, (x, pv)) in p.series[0].points.iter().enumerate() {
        assert!(same(*x, &xs[i]), "x {i}");
        assert!(same(*pv, &profile["pressure_pa"][i]), "p {i}");
        assert!(
            same(p.series[2].points[i].1, &profile["hertz_pressure_pa"][i]),
            "p_H {i}"
        );
        assert!(
            same(h.series[0].points[i].1, &profile["film_m"][i]),
            "h {i}"
        );
    }
}
