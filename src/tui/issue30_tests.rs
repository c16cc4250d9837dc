//! Issue 30 items 7, 10, 17 and 19 (session 9): units, names, the `keys`/`bench`/Sweep
//! messages and the operating-point markers, read back from the screen and the text
//! against the JSON. A child of `tui::tests` for its helpers.

use super::*;
use crate::units::{Units, FOOT_M, INCH_M, LBF_N, LBM_KG};

/// The shipped deck `stem` solved once (no transient), as `run` solves it.
fn solved(stem: &str) -> Box<dyn crate::bearings::Solution> {
    let path = PathBuf::from(format!("{}/decks/{stem}.toml", env!("CARGO_MANIFEST_DIR")));
    let case = crate::bearings::load_file(&path, &[]).expect("deck loads");
    case.solve(
        crate::bearings::RunOptions {
            skip_transient: true,
        },
        Cancel::NONE,
    )
    .expect("solves")
}

/// The number after `label` in `text` (the first whitespace-separated word after it).
fn number_after(text: &str, label: &str) -> f64 {
    let at = text
        .find(label)
        .unwrap_or_else(|| panic!("no {label:?} in:\n{text}"));
    text[at + label.len()..]
        .split_whitespace()
        .next()
        .and_then(|w| w.trim_end_matches([',', ';']).parse().ok())
        .unwrap_or_else(|| panic!("no number after {label:?}: {}", &text[at..]))
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol, "{what}: {a} vs {b} (tolerance {tol})");
}

/// Issue 30 item 7: a US deck's text speaks US units. The tapered report's roller mass
/// reads lbm (it read `5.5680e-3 kg`), its rollers' header names only the columns' units
/// (it promised `ksi/MPa` with no stress column), its LIFE lines give forces in lbf (they
/// read `C_r 87137 N`), the rib's speeds ft/s and the thermal balance Btu/hr; every number
/// read back against the JSON to the printed digits. No SI unit is left after a number in
/// any US deck's text.
#[test]
fn us_text_reports_speak_us_units() {
    let s = solved("trb_afapl_lubricated");
    let (text, json) = (s.text(Units::Us), s.json());
    assert!(!text.contains("ksi/MPa"), "{text}");
    let mass = number_after(&text, "mass = ");
    let kg = json["geometry"]["roller_mass_kg"].as_f64().expect("mass");
    close(mass, kg / LBM_KG, 5e-5 * mass, "roller mass lbm");
    assert!(text.contains(&format!("mass = {mass:.4e} lbm")), "{text}");
    let life = &json["life"];
    for (label, key, prec) in [
        ("C_r ", "basic_dynamic_rating_n", 0.5),
        (", P ", "equivalent_load_n", 0.05),
        ("C_0r ", "basic_static_rating_n", 0.5),
    ] {
        let v = number_after(&text, label);
        close(v, life[key].as_f64().expect(key) / LBF_N, prec, key);
    }
    let rib = number_after(&text, "roller end / rib: sliding ");
    let si = json["film"]["flange_sliding_m_s"]
        .as_f64()
        .expect("sliding");
    close(rib, si / FOOT_M, 5e-4, "rib sliding ft/s");
    assert!(text.contains(&format!("sliding {rib:.3} ft/s")), "{text}");
    assert!(text.contains(" Btu/hr)"), "{text}");
    for stem in ["aerospace", "thrust", "trb_afapl", "trb_afapl_lubricated"] {
        let text = solved(stem).text(Units::Us);
        for line in text.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            for w in words.windows(2) {
                let number = w[0].trim_start_matches('=').parse::<f64>().is_ok();
                let unit = w[1].trim_end_matches([',', ';', ')']);
                assert!(
                    !(number
                        && ["N", "kg", "MPa", "Pa", "N·m", "W", "mm", "µm", "m", "m/s", "mil"]
                            .contains(&unit)),
                    "{stem}: SI unit after a number: {line}"
                );
            }
        }
    }
}

/// Issue 30 item 7: ring deflections in one unit on screen and in text (µin on a US
/// deck, µm on an SI one). The aerospace Rollers pane's deflections read what the text
/// report prints (it showed `-0.9529 mil` beside the text's `-952.924 µin`); the tapered
/// Summary's δz reads the text's cone displacement, both the JSON's.
#[test]
fn ring_deflections_read_alike_on_screen_and_in_text() {
    let s = solved("aerospace");
    let text = s.text(Units::Us);
    let axial = number_after(&text, "Ring deflections: axial ");
    let app = shipped_app("aerospace", "Rollers", 120, 40);
    let screen = draw(&app, 120, 40).backend().to_string();
    assert!(
        screen.contains(&format!("axial deflection µin {axial:.3}")),
        "text {axial} µin:\n{screen}"
    );
    let s = solved("trb_afapl");
    let (text, json) = (s.text(Units::Us), s.json());
    let z = number_after(&text, "z = ");
    let z_si = json["rings"]["displacement_m"][2].as_f64().expect("z");
    close(z, z_si / INCH_M * 1e6, 5e-4, "cone displacement µin");
    assert!(text.contains(&format!("z = {z:.3} µin")), "{text}");
    let app = shipped_app("trb_afapl", "Rollers", 120, 40);
    let screen = draw(&app, 120, 40).backend().to_string();
    assert!(
        screen.contains(&format!("δz µin {z:.3}")),
        "text {z} µin:\n{screen}"
    );
}

/// Issue 30 item 7: the ball's race-control table names the roll speeds' unit (it read
/// `roll i  roll o`), in the screen's vocabulary (ω_s, ω_r).
#[test]
fn ball_text_names_the_roll_speeds_unit() {
    let text = solved("chen_b").text(Units::Si);
    assert!(text.contains("ωri rad/s  ωro rad/s"), "{text}");
    assert!(!text.contains("roll i"), "{text}");
}

/// Issue 30 item 7: keys a deck writes in a metric unit in every deck (the oil flow in
/// l/min, β in 1/°C) say so on a US screen and give the US customary value: 0.1 l/min =
/// 0.0264172 gal/min (1 US gal = 3.785411784 l, exact), 0.008 1/°C = 0.00444444 1/°F.
#[test]
fn metric_only_keys_say_so_in_us() {
    let text = crate::bearings::system("angular-contact-ball")
        .expect("ball system")
        .template(Units::Us);
    let deck = DeckDoc::parse(&text, "us.toml").expect("the US template loads");
    let mut checked = 0;
    for f in deck.fields() {
        let q = deck.unit(f.key, Units::Us);
        let note = deck.us_customary_note(f.key, Units::Us);
        match q {
            "l/min (SI)" | "1/°C (SI)" => {
                let note = note.unwrap_or_else(|| panic!("{}: no note", f.key));
                let v: f64 = deck
                    .display_value(f.key, Units::Us)
                    .parse()
                    .expect("a value");
                let (factor, unit) = if q.starts_with("l/min") {
                    (1.0 / 3.785_411_784, "gal/min")
                } else {
                    (5.0 / 9.0, "1/°F")
                };
                let us = crate::tui::deck_io::fmt_num(v * factor);
                assert!(note.contains(&format!("= {us} {unit} (")), "{note}");
                checked += 1;
            }
            _ => assert_eq!(note, None, "{}", f.key),
        }
        // SI screens keep the plain unit.
        assert!(!deck.unit(f.key, Units::Si).contains("(SI)"), "{}", f.key);
    }
    assert!(checked >= 1, "no metric-only key in the ball's US template");
    // On screen: the row's unit and the selected field's help line.
    let mut app = App::new(deck, None);
    app.handle(AppEvent::Resize(80, 24));
    let key = app
        .fields
        .iter()
        .find(|f| app.deck.unit(f.key, Units::Us).ends_with("(SI)"))
        .map(|f| f.key)
        .expect("a metric-only key");
    select_field(&mut app, key);
    let screen = draw(&app, 80, 24).backend().to_string();
    assert!(screen.contains("(SI)"), "{screen}");
    assert!(
        screen.contains(" 1/°F (written") || screen.contains(" gal/min (written"),
        "{screen}"
    );
}

/// Issue 30 item 10: every system's CSV and JSON carry the common names beside their own
/// (`docs/outputs.md`): CSV `number`, `azimuth_deg`, `inner_load_n`, `outer_load_n` (the
/// ball and the spherical roller wrote only `inner_normal_load_n`), equal to the system's
/// own column where it has one; JSON `speeds.cage_rpm` (the tapered roller wrote only
/// `cage_rad_s`) equal to its rad/s twin, and each element's `number`, `azimuth_deg`,
/// `inner_load_n`, `outer_load_n`. The screen names the azimuth `ψ deg` in every system
/// (it read φ, θ or ψ), and the texts use the screen's symbols, not ASCII words.
#[test]
fn every_system_carries_the_common_names() {
    use crate::report::{render, Format};
    let rpm = 30.0 / std::f64::consts::PI;
    for (stem, array) in [
        ("aerospace", "rollers"),
        ("chen_b", "balls"),
        ("trb_afapl", "rollers"),
        ("crb_nasa210", "rollers"),
        ("srb_22308", "rollers"),
    ] {
        let s = solved(stem);
        let csv = render(&*s, Format::Csv, Units::Si);
        let mut lines = csv.lines();
        let header: Vec<&str> = lines.next().expect("header").split(',').collect();
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        let col = |k: &str| header.iter().position(|h| *h == k);
        for k in ["number", "azimuth_deg", "inner_load_n", "outer_load_n"] {
            assert!(col(k).is_some(), "{stem}: CSV lacks {k}: {header:?}");
        }
        let n = col("number").expect("number");
        for (i, r) in rows.iter().enumerate() {
            let z = if stem == "srb_22308" {
                rows.len() / 2
            } else {
                rows.len()
            };
            assert_eq!(r[n], (i % z + 1).to_string(), "{stem}: number");
        }
        for (common, own) in [
            ("inner_load_n", "inner_normal_load_n"),
            ("outer_load_n", "outer_normal_load_n"),
            ("inner_contact_angle_deg", "inner_angle_deg"),
        ] {
            if let (Some(c), Some(o)) = (col(common), col(own)) {
                for r in &rows {
                    assert_eq!(r[c], r[o], "{stem}: {common} vs {own}");
                }
            }
        }
        let json = crate::report::json_with_common_names(&*s);
        let speeds = &json["speeds"];
        let cage = speeds["cage_rpm"]
            .as_f64()
            .unwrap_or_else(|| panic!("{stem}: no speeds.cage_rpm: {speeds}"));
        if let Some(rad) = speeds["cage_rad_s"].as_f64() {
            close(cage, rad * rpm, 1e-9 * cage.abs().max(1.0), "cage_rpm");
        }
        let elements = json[array].as_array().expect("elements");
        for e in elements {
            for k in ["number", "azimuth_deg", "inner_load_n", "outer_load_n"] {
                assert!(e[k].is_number(), "{stem}: {array}[] lacks {k}");
            }
            if let Some(q) = e["inner"]["normal_load_n"].as_f64() {
                assert_eq!(e["inner_load_n"].as_f64(), Some(q), "{stem}");
            }
        }
        // The screen's azimuth column.
        let view = s.view();
        let table = view.screen_table().expect("a table");
        assert!(
            table
                .columns
                .iter()
                .any(|c| c.screen.is_some_and(|sc| sc.label == "ψ deg")),
            "{stem}: no ψ deg column"
        );
        let text = s.text(Units::Us);
        for ascii in [
            " phi ", "phi deg", "theta_x", "theta_y", "tau", "beta ", " alpha ", "Lambda", " mu ",
            "mu =", "bi deg", "Smax",
        ] {
            let hit = text.lines().find(|l| l.contains(ascii));
            assert!(hit.is_none(), "{stem}: {ascii:?} in text: {hit:?}");
        }
    }
}

/// Issue 30 item 17: the tapered Sweep pane says why its points failed (it said
/// "4 failed" only): the first failed point's value and reason under the chart, the
/// reason read back against a plain solve of the deck at that value.
#[test]
fn tui_sweep_pane_says_why_points_failed() {
    let app = shipped_app("trb_afapl", "Sweep", 80, 24);
    let (_, _, p) = app.sweep.as_ref().expect("a sweep");
    let pt = p
        .points
        .iter()
        .find(|pt| pt.failure.is_some())
        .expect("the sample sweep has failed points");
    let case = app
        .deck
        .case()
        .with_value(p.plan.key, &crate::deck::format_short(pt.value))
        .expect("a valid value");
    let direct = match case.solve(
        crate::bearings::RunOptions {
            skip_transient: true,
        },
        Cancel::NONE,
    ) {
        Err(e) => e,
        Ok(_) => panic!("the point solves on its own"),
    };
    let screen = draw(&app, 80, 24).backend().to_string();
    let rows = screen_rows(&draw(&app, 80, 24)).join(" ");
    let flat: String = rows.split_whitespace().collect::<Vec<_>>().join(" ");
    let head: String = direct
        .split_whitespace()
        .take(6)
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        flat.contains(&format!("first failure at {} = ", p.plan.key)),
        "{screen}"
    );
    assert!(flat.contains(&head), "{head:?} not on screen:\n{screen}");
}
