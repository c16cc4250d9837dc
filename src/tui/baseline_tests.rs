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

/// `view`'s CSV report (`run --format csv`) as columns by name, one value per element.
fn csv_columns(view: &View) -> std::collections::HashMap<String, Vec<f64>> {
    let text = crate::report::csv::to_string(view);
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let mut cols: std::collections::HashMap<String, Vec<f64>> = std::collections::HashMap::new();
    for line in lines {
        for (name, cell) in header.iter().zip(line.split(',')) {
            cols.entry(name.to_string())
                .or_default()
                .push(cell.parse().unwrap_or(f64::NAN));
        }
    }
    cols
}

/// Issue 30 item 21, the element table against a baseline: with chen_b pinned and its
/// axial load raised 1000 → 1200 N, `d` shows for every result column of every ball the
/// change now − baseline, then the change in % of the baseline; each shown cell is the two
/// designs' CSV reports (written independently of the screen) differenced, converted to
/// the column's display unit, to half a unit of the cell's last digit (for %: of 0.1 %,
/// or wider where a narrow cell switched to fewer decimals). The element's number stays
/// a number; `d` a third time shows the values again.
#[test]
fn element_table_deltas_read_back_as_the_two_csv_reports() {
    let mut app = pinned_and_edited(200, 50);
    app.focus = Pane::Elements;
    let before = app
        .deck
        .case()
        .with_value("operating.axial_load", "1000")
        .expect("valid")
        .solve(
            crate::bearings::RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .expect("solves")
        .view();
    let now = app.view.clone().expect("solved");
    let (a, b) = (csv_columns(&before), csv_columns(&now));
    let u = app.display_units;
    let table = now.screen_table().expect("a table");
    let shown: Vec<&crate::bearings::view::Column> = table
        .columns
        .iter()
        .filter(|c| c.screen.is_some())
        .collect();
    let mut checked = 0;
    for (mode, title) in [
        (view_model::TableDelta::Change, "Δ now − baseline"),
        (view_model::TableDelta::Percent, "Δ % of baseline"),
    ] {
        app.handle(ch('d'));
        assert_eq!(app.table_delta, mode);
        let screen = screen_rows(&draw(&app, 200, 50)).join("\n");
        assert!(screen.contains(title), "{screen}");
        let (base, m) = app.table_baseline().expect("on").expect("compares");
        // Every column, as wide as it likes (the screen shows the first 17 of them as
        // these, fitted to the pane).
        let cells = view_model::table_cells_against(&now, Some((base, m)), u, 1000, 0);
        assert_eq!(cells.hidden, 0, "every column in view");
        for h in cells.columns.iter().take(8) {
            assert!(
                screen.contains(&h.header),
                "{} not on screen:\n{screen}",
                h.header
            );
        }
        for (c, col) in shown.iter().enumerate() {
            let header = &cells.columns[c].header;
            let s = col.screen.expect("shown");
            let differenced = !matches!(s.display, crate::bearings::view::Display::Choice(_))
                && !crate::report::diff::names_the_row(col.key);
            assert_eq!(header.starts_with('Δ'), differenced, "{header}");
            let (Some(va), Some(vb)) = (a.get(col.key), b.get(col.key)) else {
                continue;
            };
            for (r, row) in cells.rows.iter().enumerate() {
                let cell = &row[c];
                let Ok(shown_value) = cell.parse::<f64>() else {
                    continue;
                };
                let (x, y) = (s.display.convert(va[r], u), s.display.convert(vb[r], u));
                let expected = if !differenced {
                    y
                } else if m == view_model::TableDelta::Percent {
                    if x == 0.0 {
                        continue;
                    }
                    100.0 * (y - x) / x.abs()
                } else {
                    y - x
                };
                let decimals = cell.split_once('.').map_or(0, |(_, f)| f.len());
                let half = 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9) + 1e-12;
                assert!(
                    (shown_value - expected).abs() <= half,
                    "{} #{}: shown {cell}, CSV {y} vs {x} → {expected} (±{half})",
                    header,
                    r + 1
                );
                if differenced && expected.abs() > half {
                    assert_eq!(cell.starts_with('+'), expected > 0.0, "{header}: {cell}");
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 200, "only {checked} cells checked");
    app.handle(ch('d'));
    assert_eq!(app.table_delta, view_model::TableDelta::Values);
    assert!(app.table_baseline().is_none());
    let screen = screen_rows(&draw(&app, 200, 50)).join("\n");
    assert!(!screen.contains("Δ now"), "{screen}");
}

/// With no baseline `d` says how to get one; with a baseline of another system the
/// element table says why it shows no changes (as `rollbench diff` does), and its
/// values stay.
#[test]
fn element_table_deltas_need_a_comparable_baseline() {
    let mut app = shipped_app("chen_b", "Balls", 80, 24);
    app.handle(ch('d'));
    assert_eq!(app.table_delta, view_model::TableDelta::Values);
    assert!(
        app.message
            .as_deref()
            .is_some_and(|m| m.contains("no baseline")),
        "{:?}",
        app.message
    );
    let other = PathBuf::from(format!(
        "{}/decks/trb_afapl.toml",
        env!("CARGO_MANIFEST_DIR")
    ));
    let outcome = crate::tui::worker::baseline_of(&other);
    app.handle(AppEvent::BaselineOpened {
        path: other,
        outcome,
    });
    app.handle(ch('d'));
    let why = app
        .table_baseline()
        .expect("asked")
        .expect_err("two systems");
    assert!(why.contains("two systems"), "{why}");
    let screen = screen_rows(&draw(&app, 200, 50)).join("\n");
    assert!(screen.contains("Δ not compared: two systems"), "{screen}");
    assert!(!screen.contains("ΔQ"), "{screen}");
}

/// The chart panes overlay the baseline's same chart dimmed (issue 30 item 21): its
/// series are the baseline view's own, the axes hold both designs, the legend names it
/// once, and its braille is drawn in the dim colour; a chart of another kind (or no
/// baseline) gets none.
#[test]
fn charts_overlay_the_baseline_dimmed() {
    let mut app = pinned_and_edited(200, 50);
    let base = app.baseline.clone().expect("pinned");
    let now = app.view.clone().expect("solved");
    let (c, b) = (&now.charts[0], &base.view.charts[0]);
    let u = app.display_units;
    let panels = view_model::chart_panels_against(c, Some(b), u);
    let theirs = view_model::chart_panels(b, u);
    assert_eq!(panels.len(), theirs.len());
    for (p, t) in panels.iter().zip(&theirs) {
        assert_eq!(p.baseline, t.series, "the baseline's own series");
        assert!(p.x_bounds[0] <= t.x_bounds[0] && p.x_bounds[1] >= t.x_bounds[1]);
        assert!(p.y_bounds[0] <= t.y_bounds[0] && p.y_bounds[1] >= t.y_bounds[1]);
        // Points of both designs lie inside the axes.
        for (x, y) in p.series.iter().chain(&p.baseline).flat_map(|s| s.1.iter()) {
            assert!(x >= &p.x_bounds[0] && x <= &p.x_bounds[1], "{x}");
            assert!(y >= &p.y_bounds[0] && y <= &p.y_bounds[1], "{y}");
        }
    }
    // Another chart gets no overlay.
    let other = now.charts.iter().skip(1).find(|o| o.y != c.y);
    if let Some(o) = other {
        assert!(view_model::chart_panels_against(c, Some(o), u)
            .iter()
            .all(|p| p.baseline.is_empty()));
    }
    app.focus = Pane::Chart(0);
    let t = draw(&app, 200, 50);
    let screen = screen_rows(&t).join("\n");
    assert!(screen.contains("baseline (dim)"), "{screen}");
    let buf = t.backend().buffer();
    let dim_braille = (0..buf.area.height)
        .flat_map(|y| (0..buf.area.width).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let cell = &buf[(x, y)];
            cell.fg == ratatui::style::Color::DarkGray
                && cell
                    .symbol()
                    .chars()
                    .any(|c| ('\u{2801}'..='\u{28ff}').contains(&c))
        })
        .count();
    assert!(
        dim_braille > 10,
        "{dim_braille} dim braille cells:\n{screen}"
    );
    app.handle(ch('D'));
    let screen = screen_rows(&draw(&app, 200, 50)).join("\n");
    assert!(!screen.contains("baseline (dim)"), "{screen}");
}

#[test]
fn tui_snapshot_element_table_deltas() {
    for (w, h) in [(80, 24), (60, 20)] {
        let mut app = pinned_and_edited(w, h);
        app.focus = Pane::Elements;
        app.handle(ch('d'));
        snap("baseline_chen_b_balls_delta", &app, w, h);
        // The title's notes fit the border whole, in their short form where they must
        // (at 60 columns "· h l scroll" was cut to "· h l scro").
        let rows = screen_rows(&draw(&app, w, h));
        let top = rows.iter().find(|r| r.contains("┌ Balls")).expect("title");
        assert!(top.contains(" · Δ") && top.contains("h l"), "{top}");
        assert!(top.trim_end().ends_with("─┐"), "{top}");
        app.focus = Pane::Chart(0);
        snap("baseline_chen_b_chart_overlay", &app, w, h);
    }
}

/// Two decks of one system that compute different columns (trb_afapl against its
/// lubricated twin, whose tables add the film) compare on the columns both have, matched
/// by key ("not compared: the tables have different columns" before). A screen column
/// the baseline lacks (here taken out of the baseline's table, shifting the columns after
/// it) shows `—`, and every other column still shows its own change.
#[test]
fn element_tables_of_one_system_compare_on_their_shared_columns() {
    let mut app = shipped_app("trb_afapl_lubricated", "Rollers", 200, 50);
    let other = PathBuf::from(format!(
        "{}/decks/trb_afapl.toml",
        env!("CARGO_MANIFEST_DIR")
    ));
    let outcome = crate::tui::worker::baseline_of(&other);
    app.handle(AppEvent::BaselineOpened {
        path: other,
        outcome,
    });
    app.handle(ch('d'));
    let (base, mode) = app.table_baseline().expect("asked").expect("compares");
    let base = base.clone();
    let now = app.view.clone().expect("solved");
    let all_keys = |v: &View| -> Vec<&'static str> {
        v.tables
            .iter()
            .flat_map(|t| t.columns.iter().map(|c| c.key))
            .collect()
    };
    assert_ne!(
        all_keys(&now),
        all_keys(&base),
        "the decks compute different columns"
    );
    let screen = screen_rows(&draw(&app, 200, 50)).join("\n");
    assert!(screen.contains("Δ now − baseline"), "{screen}");
    // The baseline without one of its middle screen columns.
    let mut thinner = base.clone();
    let t = thinner
        .tables
        .iter_mut()
        .find(|t| t.columns.iter().any(|c| c.screen.is_some()))
        .expect("a screen table");
    let gone = t
        .columns
        .iter()
        .position(|c| c.key == "inner_load_n")
        .expect("inner load column");
    t.columns.remove(gone);
    for row in &mut t.rows {
        row.remove(gone);
    }
    let u = app.display_units;
    let full = view_model::table_cells_against(&now, Some((&base, mode)), u, 1000, 0);
    let thin = view_model::table_cells_against(&now, Some((&thinner, mode)), u, 1000, 0);
    let shown: Vec<&str> = now
        .screen_table()
        .expect("table")
        .columns
        .iter()
        .filter(|c| c.screen.is_some())
        .map(|c| c.key)
        .collect();
    let mut compared = 0;
    for (c, key) in shown.iter().enumerate() {
        for (rf, rt) in full.rows.iter().zip(&thin.rows) {
            if *key == "inner_load_n" {
                assert_eq!(rt[c], view_model::DASH, "{key}");
                assert_ne!(rf[c], view_model::DASH, "{key}");
            } else {
                assert_eq!(rt[c], rf[c], "{key}");
                compared += 1;
            }
        }
    }
    assert!(compared > 50, "{compared}");
}
