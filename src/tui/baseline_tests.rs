//! Issue 30 item 21: the workbench's baseline — pinned (`b`) or a second deck file
//! (`B`) — and the Summary's deltas, read back against the two JSON reports. A child of
//! `tui::tests` for its helpers.

use super::*;
use crate::bearings::view::AnswerValue;
use crate::tui::summary_tests::resolve;

/// `stem`'s shipped deck solved as `rollbench run` solves it, its JSON report.
fn json_of(case: &dyn crate::bearings::Case) -> serde_json::Value {
    case.solve(
        crate::bearings::RunOptions {
            skip_transient: true,
        },
        Cancel::NONE,
    )
    .expect("solves")
    .json()
}

/// The shipped ball deck chen_b solved, pinned as the baseline (`b`), then its axial
/// load edited 1000 → 1200 N and re-solved (the baseline kept), at `w`×`h` on the Summary.
fn pinned_and_edited(w: u16, h: u16) -> App {
    let mut app = shipped_app("chen_b", "Summary", w, h);
    app.handle(ch('b'));
    assert!(app.baseline.is_some(), "b pins");
    select_field(&mut app, "operating.axial_load");
    let cmds = type_value(&mut app, "1200");
    run_sync_tolerant(&mut app, cmds);
    app.focus = Pane::Summary;
    let cmds = app.handle(AppEvent::Resize(w, h));
    run_sync_tolerant(&mut app, cmds);
    app
}

#[test]
fn tui_snapshot_summary_with_a_baseline() {
    for (w, h) in [(80, 24), (60, 20)] {
        let app = pinned_and_edited(w, h);
        snap("baseline_chen_b_summary", &app, w, h);
    }
}

/// Every Δ line the Summary shows (at 80 columns, tall enough that nothing scrolls) is
/// the current design's JSON value minus the baseline's, converted to the display unit,
/// to half a unit of its last digit; its % is 100·Δ/|baseline| to half a unit of its
/// last digit (0.05 %). Checked for a pinned baseline and an edit (SI, ball), and for a
/// second deck of the same system opened as the baseline (US, tapered).
#[test]
fn summary_deltas_read_back_as_the_two_json_reports() {
    let mut checked = 0;
    // Pinned: chen_b before and after its axial load was raised.
    let app = pinned_and_edited(80, 200);
    let before = app
        .deck
        .case()
        .with_value("operating.axial_load", "1000")
        .expect("valid");
    checked += check_deltas(&app, &json_of(before.as_ref()), &json_of(&*app.deck.case()));
    // A second deck as the baseline: trb_afapl_lubricated against trb_afapl.
    let mut app = shipped_app("trb_afapl", "Summary", 80, 200);
    let other = PathBuf::from(format!(
        "{}/decks/trb_afapl_lubricated.toml",
        env!("CARGO_MANIFEST_DIR")
    ));
    let outcome = crate::tui::worker::baseline_of(&other);
    app.handle(AppEvent::BaselineOpened {
        path: other.clone(),
        outcome,
    });
    assert!(app.baseline.is_some(), "{:?}", app.error);
    // At 60 columns the status line names the baseline's file whole (not a path cut
    // after its directory); the Summary's Baseline section gives the path.
    let status = screen_rows(&draw(&app, 60, 20)).join("\n");
    assert!(
        status.contains("baseline: trb_afapl_lubricated.toml"),
        "{status}"
    );
    let base = crate::bearings::load_file(&other, &[]).expect("loads");
    checked += check_deltas(&app, &json_of(base.as_ref()), &json_of(&*app.deck.case()));
    assert!(checked >= 20, "only {checked} deltas checked");
}

/// The number right after `label` in `text`.
fn after(text: &str, label: &str) -> Option<f64> {
    let at = text.find(label)? + label.len();
    text[at..].split_whitespace().next()?.parse().ok()
}

fn check_deltas(app: &App, base: &serde_json::Value, now: &serde_json::Value) -> usize {
    let u = app.display_units;
    let t = draw(app, app.size.0, app.size.1);
    let rows = screen_rows(&t);
    let text = rows.join("\n");
    assert!(text.contains("Baseline"), "{text}");
    let view = app.view.as_deref().expect("solved");
    let mut cursor = 0;
    let mut checked = 0;
    for a in &view.answer {
        let AnswerValue::Number(_) = a.value else {
            continue;
        };
        let Some(at) = rows[cursor..]
            .iter()
            .position(|r| r.contains(&format!(" {} ", a.label)))
        else {
            continue;
        };
        cursor += at + 1;
        // The Δ line follows the value (a place line may come between).
        let Some(delta_row) = rows[cursor..]
            .iter()
            .take(3)
            .find(|r| r.contains("Δ ") && !r.contains("Δ ="))
        else {
            continue;
        };
        let (Some(b), Some(c)) = (resolve(base, a.json), resolve(now, a.json)) else {
            continue;
        };
        let (b, c) = (a.display.convert(b, u), a.display.convert(c, u));
        let shown = after(delta_row, "Δ ").unwrap_or_else(|| panic!("{delta_row}"));
        let token = delta_row
            .split("Δ ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .expect("Δ token");
        let decimals = token.split_once('.').map_or(0, |(_, f)| f.len());
        let half = 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9) + 1e-12;
        assert!(
            (shown - (c - b)).abs() <= half,
            "{} · {}: Δ shown {shown}, JSON {c} − {b} = {} (±{half}):\n{text}",
            a.section,
            a.label,
            c - b
        );
        if b != 0.0 {
            let pct = after(delta_row, "(").expect("Δ %");
            assert!(
                (pct - 100.0 * (c - b) / b.abs()).abs() <= 0.05 + 1e-9,
                "{}: {pct} % vs {}",
                a.label,
                100.0 * (c - b) / b.abs()
            );
        }
        checked += 1;
    }
    assert!(checked > 0, "no Δ read:\n{text}");
    checked
}

/// A baseline of another system: the Summary says so, and gives a Δ only on the lines
/// both systems report (the `diff` command's rule); `D` clears it and the Δ lines go.
#[test]
fn a_baseline_of_another_system_compares_only_shared_lines() {
    let mut app = shipped_app("chen_b", "Summary", 80, 200);
    let other = PathBuf::from(format!(
        "{}/decks/trb_afapl.toml",
        env!("CARGO_MANIFEST_DIR")
    ));
    let outcome = crate::tui::worker::baseline_of(&other);
    app.handle(AppEvent::BaselineOpened {
        path: other,
        outcome,
    });
    let d = app.baseline_diff().expect("a baseline");
    let shared = d
        .outputs
        .iter()
        .filter(|r| r.a.is_some() && r.b.is_some())
        .count();
    assert!(shared > 0 && !d.only_b.is_empty(), "{d:?}");
    let text = screen_rows(&draw(&app, 80, 200)).join("\n");
    assert!(text.contains("another system"), "{text}");
    assert!(text.contains("baseline: "), "status line: {text}");
    let deltas = text.matches("Δ ").count() - text.matches("Δ =").count();
    assert_eq!(deltas, shared, "{text}");
    app.handle(ch('D'));
    assert!(app.baseline.is_none());
    let text = screen_rows(&draw(&app, 80, 200)).join("\n");
    assert!(!text.contains("Δ "), "{text}");
    assert!(!text.contains("baseline: "), "{text}");
}

/// A deck that does not load is refused whole (its line and key), the baseline kept.
#[test]
fn a_baseline_deck_that_does_not_load_is_shown_whole() {
    let mut app = shipped_app("chen_b", "Summary", 80, 24);
    app.handle(ch('b'));
    let dir = std::env::temp_dir().join(format!("rollbench-baseline-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "type = \"angular-contact-ball\"\n[operating]\naxial_load = -5\n",
    )
    .expect("write");
    let outcome = crate::tui::worker::baseline_of(&bad);
    assert!(outcome.is_err());
    app.handle(AppEvent::BaselineOpened { path: bad, outcome });
    let _ = std::fs::remove_dir_all(&dir);
    let err = app.error.clone().expect("error kept");
    assert!(err.contains("bad.toml"), "{err}");
    assert!(matches!(app.mode, Mode::Error));
    assert!(
        app.baseline
            .as_ref()
            .is_some_and(|b| b.name.contains("pinned")),
        "the pinned baseline stays"
    );
}
