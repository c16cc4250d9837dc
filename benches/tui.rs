//! Workbench speed (issue 6): full-frame draw on a 120×40 `TestBackend`, and edit → new
//! frame latency (in-place edit, synchronous pipeline solve, result applied, redraw) on
//! the aerospace deck. Target: under 16 ms.

use std::hint::black_box;
use std::sync::Arc;

use criterion::{criterion_group, criterion_main, Criterion};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::Terminal;

use rollbench::numerics::cancel::Cancel;
use rollbench::tui::{App, AppEvent, Command, DeckDoc, Pane};

fn key(c: KeyCode) -> AppEvent {
    AppEvent::Key(KeyEvent::new(c, KeyModifiers::NONE))
}

/// Runs every solve command inline, as the worker would (a fresh session each time: no
/// stage is reused, as before the sessions kept a cache).
fn solve_inline(app: &mut App, cmds: Vec<Command>) {
    for c in cmds {
        if let Command::Solve(job) = c {
            let outcome = job
                .case
                .system()
                .session()
                .solve(&*job.case, job.detail, &Cancel::NONE)
                .map(|s| Arc::new(s.view()))
                .map_err(|e| e.to_string());
            let more = app.handle(AppEvent::Solved {
                generation: job.generation,
                outcome,
            });
            solve_inline(app, more);
        }
    }
}

fn solved_app(w: u16, h: u16, pane: Pane) -> App {
    let deck = DeckDoc::parse(
        rollbench::bearings::spherical_roller::deck::DEFAULT_DECK,
        "aerospace.toml",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let mut app = App::new(deck, None);
    app.handle(AppEvent::Resize(w, h));
    let cmds = app.start();
    solve_inline(&mut app, cmds);
    app.focus = pane;
    let cmds = app.handle(AppEvent::Resize(w, h));
    solve_inline(&mut app, cmds);
    app
}

fn draw(c: &mut Criterion) {
    let mut group = c.benchmark_group("tui_draw");
    for pane in [Pane::Inputs, Pane::Stepper] {
        let app = solved_app(120, 40, pane);
        let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap_or_else(|e| match e {});
        group.bench_function(format!("full_frame_120x40_{}", app.pane_title(pane)), |b| {
            b.iter(|| {
                terminal
                    .draw(|f| f.render_widget(black_box(&app), f.area()))
                    .unwrap_or_else(|e| match e {});
            })
        });
    }
    group.finish();
}

fn edit_to_frame(c: &mut Criterion) {
    let mut app = solved_app(120, 40, Pane::Inputs);
    app.input_sel = app
        .fields
        .iter()
        .position(|f| f.key == "operating.radial_load")
        .unwrap_or(0);
    let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap_or_else(|e| match e {});
    let mut flip = false;
    c.bench_function("tui_edit_to_new_frame_120x40", |b| {
        b.iter(|| {
            flip = !flip;
            let value = if flip { "3100" } else { "3000" };
            app.handle(key(KeyCode::Enter));
            app.handle(key(KeyCode::End));
            for _ in 0..8 {
                app.handle(key(KeyCode::Backspace));
            }
            for ch in value.chars() {
                app.handle(key(KeyCode::Char(ch)));
            }
            let cmds = app.handle(key(KeyCode::Enter));
            solve_inline(&mut app, cmds);
            terminal
                .draw(|f| f.render_widget(&app, f.area()))
                .unwrap_or_else(|e| match e {});
        })
    });
}

criterion_group!(benches, draw, edit_to_frame);
criterion_main!(benches);
