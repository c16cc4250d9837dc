//! Issue 30 item 19: the deck's operating value marked on the Skid and Sweep charts,
//! read back from the screen. A child of `tui::tests` for its helpers.

use super::*;
use ratatui::style::Color;

/// The drawn screen's symbols and foreground colours, row by row.
fn cells(t: &Terminal<TestBackend>) -> Vec<Vec<(String, Color)>> {
    let buf = t.backend().buffer();
    (0..buf.area.height)
        .map(|y| {
            (0..buf.area.width)
                .map(|x| {
                    let c = &buf[(x, y)];
                    (c.symbol().to_string(), c.fg)
                })
                .collect()
        })
        .collect()
}

fn is_braille(s: &str) -> bool {
    s.chars()
        .next()
        .is_some_and(|c| ('\u{2801}'..='\u{28ff}').contains(&c))
}

/// The x value the operating marker's column stands for, and one cell's width in x,
/// read off the screen: the plot runs from the column right of the axes' corner `└` to
/// the x axis's last `─`; its ends are the x axis's first and last labels (the row under
/// the axis); the marker is the one column of white braille cells above the axis.
fn marker_reading(t: &Terminal<TestBackend>) -> (f64, f64) {
    let rows = cells(t);
    let text = screen_rows(t).join("\n");
    // The axes' corner: of the `└` inside the pane (a legend box has one too), the one
    // with the longest `─` run to its right.
    let run = |y: usize, x: usize| {
        (x + 1..rows[y].len())
            .take_while(|&k| rows[y][k].0 == "─")
            .count()
    };
    let (cy, cx) = (1..rows.len() - 1)
        .flat_map(|y| (1..rows[y].len() - 1).map(move |x| (y, x)))
        .filter(|&(y, x)| rows[y][x].0 == "└")
        .max_by_key(|&(y, x)| run(y, x))
        .unwrap_or_else(|| panic!("no axes:\n{text}"));
    let last = cx + run(cy, cx);
    assert!(last > cx + 10, "no x axis:\n{text}");
    let (left, width) = (cx + 1, last - cx);
    let labels: Vec<f64> = rows[cy + 1]
        .iter()
        .map(|c| c.0.as_str())
        .collect::<String>()
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|w| w.parse().ok())
        .collect();
    let (x0, x1) = (labels[0], *labels.last().expect("x labels"));
    let mut columns: Vec<usize> = (1..cy)
        .flat_map(|y| (left..=last).map(move |x| (x, y)))
        .filter(|&(x, y)| rows[y][x].1 == Color::White && is_braille(&rows[y][x].0))
        .map(|(x, _)| x)
        .collect();
    columns.sort_unstable();
    columns.dedup();
    assert_eq!(columns.len(), 1, "one marker column, {columns:?}:\n{text}");
    let cell = (x1 - x0) / width as f64;
    (x0 + (columns[0] - left) as f64 * cell + 0.5 * cell, cell)
}

fn deck_number(app: &App, key: &str) -> f64 {
    app.deck
        .case()
        .get(key)
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("{key} holds no number"))
}

/// The marker's column, mapped back through the axis labels, is the deck's value within
/// one cell, on the ball's Skid chart (the relative ring speed, rpm) and on the tapered
/// roller's Sweep chart (inner speed, rpm), at 80×24 and 60×20. (The cylindrical
/// roller's Sweep, its radial load, is the tenth pane: the digit keys do not reach it;
/// its snapshots show the marker.)
#[test]
fn the_operating_marker_sits_at_the_deck_value() {
    for (w, h) in [(80, 24), (60, 20)] {
        for (stem, pane, deck) in [
            (
                "chen_b",
                "Skid",
                &(|a: &App| {
                    deck_number(a, "operating.inner_speed")
                        - deck_number(a, "operating.outer_speed")
                }) as &dyn Fn(&App) -> f64,
            ),
            ("trb_afapl", "Sweep", &|a: &App| {
                deck_number(a, "operating.inner_speed")
            }),
        ] {
            let app = shipped_app(stem, pane, w, h);
            let t = draw(&app, w, h);
            let (x, cell) = marker_reading(&t);
            let want = deck(&app).abs();
            assert!(
                (x - want).abs() <= cell,
                "{stem} {pane} {w}×{h}: marker at {x} (cell {cell}), deck {want}:\n{}",
                screen_rows(&t).join("\n")
            );
            // The legend (ratatui hides it when it would take over half the plot, as on
            // the 60×20 Sweep) names the deck's value at 80×24.
            assert!(
                w < 80 || screen_rows(&t).join("\n").contains("deck "),
                "{stem} {pane} {w}×{h}: the legend names the deck's value"
            );
        }
    }
}

/// The Skid title gives the threshold, the deck's speed and the margin
/// (deck − threshold)/threshold, each read back against the JSON's `skid.threshold_rpm`
/// and the deck's speeds to the printed digit.
#[test]
fn the_skid_title_gives_the_margin_to_the_deck_speed() {
    let app = shipped_app("chen_b", "Skid", 80, 24);
    let t = draw(&app, 80, 24);
    let title = screen_rows(&t)
        .into_iter()
        .find(|r| r.contains("skidding from"))
        .expect("skid title");
    let after = |label: &str| -> f64 {
        let at = title
            .find(label)
            .unwrap_or_else(|| panic!("{label}: {title}"))
            + label.len();
        title[at..]
            .split_whitespace()
            .next()
            .and_then(|w| w.parse().ok())
            .unwrap_or_else(|| panic!("{label}: {title}"))
    };
    let case = app.deck.case();
    let json = case
        .solve(
            crate::bearings::RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .expect("solves")
        .json();
    let threshold = json["skid"]["threshold_rpm"].as_f64().expect("threshold");
    let deck =
        deck_number(&app, "operating.inner_speed") - deck_number(&app, "operating.outer_speed");
    assert!(
        (after("skidding from ") - threshold).abs() <= 0.5,
        "{title}"
    );
    assert!((after("deck ") - deck).abs() <= 0.5, "{title}");
    let margin = 100.0 * (deck - threshold) / threshold;
    assert!(
        (after("margin ") - margin).abs() <= 0.5,
        "{title} vs {margin}"
    );
}
