//! The Summary pane read back against the JSON report (issue 28): for every shipped deck,
//! every number the pane shows is found on screen at 60×20, 80×24 and 200×50 (scrolling
//! where the pane is shorter than its lines), parsed back, and compared with the JSON
//! field its line names, converted to the display unit, to half a unit of the last digit
//! shown. The line's own value is the JSON field's to 1e-12 (one state, two surfaces).

use std::path::PathBuf;
use std::sync::Arc;

use ratatui::backend::TestBackend;
use ratatui::Terminal;
use serde_json::Value;

use super::app::{App, AppEvent, Command, Pane};
use crate::bearings::view::{AnswerLine, AnswerValue, Display};
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// The value a [`AnswerLine::json`] spec names in `doc` (see its doc for the syntax).
pub(super) fn resolve(doc: &Value, spec: &str) -> Option<f64> {
    let (spec, scale) = match spec.split_once(" ×") {
        Some((s, k)) => (s, k.trim().parse::<f64>().ok()?),
        None => (spec, 1.0),
    };
    let mut words = spec.split_whitespace().peekable();
    let agg = match words.peek() {
        Some(&"max") | Some(&"min") => words.next(),
        _ => None,
    };
    let mut values = Vec::new();
    for path in words {
        let segs: Vec<&str> = path.trim_start_matches('/').split('/').collect();
        collect(doc, &segs, &mut values);
    }
    let v = match agg {
        Some("max") => values.into_iter().reduce(f64::max),
        Some("min") => values.into_iter().reduce(f64::min),
        _ => (values.len() == 1).then(|| values[0]),
    }?;
    Some(v * scale)
}

fn collect(v: &Value, segs: &[&str], out: &mut Vec<f64>) {
    match segs.split_first() {
        None => out.extend(v.as_f64()),
        Some((&"*", rest)) => {
            for x in v.as_array().into_iter().flatten() {
                collect(x, rest, out);
            }
        }
        Some((s, rest)) => {
            if let Some(x) = v.get(*s) {
                collect(x, rest, out);
            }
        }
    }
}

/// Every line of the Summary pane over all its scroll positions at `w`×`h`.
fn screen_lines(app: &mut App, w: u16, h: u16) -> Vec<String> {
    app.handle(AppEvent::Resize(w, h));
    app.focus = Pane::Summary;
    app.summary_scroll = 0;
    let mut all = Vec::new();
    for _ in 0..200 {
        let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
        t.draw(|f| f.render_widget(&*app, f.area())).expect("draw");
        let buf = t.backend().buffer().clone();
        let rows: Vec<String> = (0..h)
            .map(|y| (0..w).map(|x| buf[(x, y)].symbol().to_string()).collect())
            .collect();
        let more = rows
            .iter()
            .any(|r| r.contains(" more (j)") || r.contains(" more ─"));
        all.extend(rows);
        if !more {
            break;
        }
        app.summary_scroll += 1;
    }
    all
}

/// The number shown after `label` on a screen line that also holds `unit`.
fn shown_number(lines: &[String], label: &str, unit: &str) -> Option<f64> {
    lines.iter().find_map(|l| {
        let at = l.find(&format!(" {label} "))?;
        let rest = &l[at + label.len() + 1..];
        if !unit.is_empty() && !rest.contains(&format!(" {unit}")) {
            return None;
        }
        let token = rest.split_whitespace().next()?;
        token.parse::<f64>().ok()
    })
}

/// Half a unit of the last digit shown of `x` (precision decimals, or significant
/// figures for lives).
fn half_digit(a: &AnswerLine, x: f64) -> f64 {
    match a.display {
        Display::Mrev | Display::Hours => {
            let mag = x.abs().max(1e-300).log10().floor() as i32;
            let decimals = (a.precision as i32 - 1 - mag).max(0);
            0.5 * 10f64.powi(-decimals)
        }
        _ => 0.5 * 10f64.powi(-(a.precision as i32)),
    }
}

#[test]
fn summary_pane_reads_back_as_the_json_report() {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/decks"))
        .expect("decks dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut checked = 0;
    for path in paths {
        let deck = super::tests::shipped_deck_for_snapshots(&path);
        let mut app = App::new(deck, None);
        app.handle(AppEvent::Resize(200, 50));
        let mut json = None;
        let mut pending = app.start();
        while let Some(c) = pending.pop() {
            if let Command::Solve(job) = c {
                let mut session = job.case.system().session();
                let sol = session
                    .solve(&*job.case, job.detail, &Cancel::NONE)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                json = Some(sol.json());
                let view = sol.view();
                pending.extend(app.handle(AppEvent::Solved {
                    generation: job.generation,
                    outcome: Ok(Arc::new(view)),
                }));
            }
        }
        let doc = json.expect("solved");
        let view = app.view.clone().expect("a view");
        assert!(
            app.panes().get(1) == Some(&Pane::Summary),
            "{}",
            path.display()
        );
        let units = app.display_units;
        for (w, h) in [(60, 20), (80, 24), (200, 50)] {
            let lines = screen_lines(&mut app, w, h);
            for a in &view.answer {
                let what = format!("{} {w}×{h}: {} ({:?})", path.display(), a.label, a.display);
                match &a.value {
                    AnswerValue::Number(v) => {
                        let unit = a.display.unit(units);
                        let on_screen = shown_number(&lines, a.label, unit).unwrap_or_else(|| {
                            panic!("{what}: not on screen:\n{}", lines.join("\n"))
                        });
                        if a.json.is_empty() {
                            continue;
                        }
                        let j = resolve(&doc, a.json)
                            .unwrap_or_else(|| panic!("{what}: JSON {} not found", a.json));
                        assert!(
                            (v - j).abs() <= 1e-12 * j.abs().max(1e-300),
                            "{what}: line {v} against JSON {j}"
                        );
                        let x = a.display.convert(j, units);
                        assert!(
                            (on_screen - x).abs() <= half_digit(a, x) * (1.0 + 1e-9),
                            "{what}: screen {on_screen} against JSON {x} {unit}"
                        );
                        checked += 1;
                    }
                    AnswerValue::Name(n) => {
                        let first = n.split_whitespace().next().unwrap_or("");
                        assert!(lines.iter().any(|l| l.contains(first)), "{what}: {n}");
                    }
                    AnswerValue::Absent(_) => {
                        assert!(
                            lines
                                .iter()
                                .any(|l| l.contains(&format!(" {} ", a.label)) && l.contains('—')),
                            "{what}: absent value not said"
                        );
                    }
                }
            }
        }
    }
    assert!(checked > 100, "{checked} numbers read back");
}

/// In US customary units a temperature shows in °F and a stress in ksi: the same state,
/// converted, never mixed with SI on one screen.
#[test]
fn summary_lines_convert_to_us_units() {
    let a = AnswerLine::number(
        "T",
        "bulk oil",
        Some(100.0),
        Display::Temperature,
        1,
        "",
        "",
    );
    assert_eq!(a.shown(Units::Us), "212.0 °F");
    assert_eq!(a.shown(Units::Si), "100.0 °C");
    let l = AnswerLine::number("L", "L10", Some(137.2208), Display::Mrev, 4, "", "");
    assert_eq!(l.shown(Units::Si), "137.2 Mrev");
    let l = AnswerLine::number("L", "L10", Some(254282.3), Display::Mrev, 4, "", "");
    assert_eq!(l.shown(Units::Si), "254282 Mrev");
    let l = AnswerLine::number("L", "L10", Some(0.012345), Display::Mrev, 4, "", "");
    assert_eq!(l.shown(Units::Si), "0.01235 Mrev");
    let n = AnswerLine::number("L", "L10", None, Display::Mrev, 4, "", "infinite");
    assert_eq!(n.shown(Units::Us), "— (infinite)");
}
