//! In-module tests of the deck layer: parsing, each validation rule, set/get,
//! template round trip, conversion and atomic save.

use super::*;
use crate::bearings::spherical_roller::{Bearing, LifeMethod, Material};
use crate::deck::{read_deck_text, DeckError, Location, MAX_DECK_BYTES};

/// Relative difference, safe at zero.
fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

#[path = "../../../tests/common/serde_diff.rs"]
mod serde_diff;

/// Field-by-field comparison of two bearings through their serde representation
/// (independent of the registry). Returns the paths that differ.
pub(crate) fn bearing_diff(a: &Bearing, b: &Bearing, tol: f64) -> Vec<String> {
    serde_diff::serde_diff("bearing", a, b, tol)
}

/// The registry covers every field of `Bearing` except `name`: one registry entry per
/// serde leaf, plus the derived lubricant parameter.
#[test]
fn registry_covers_every_bearing_field() {
    fn leaves(v: &serde_json::Value) -> usize {
        match v {
            serde_json::Value::Object(m) => m.values().map(leaves).sum(),
            _ => 1,
        }
    }
    let json = serde_json::to_value(Bearing::example_aerospace()).unwrap_or_default();
    assert_eq!(leaves(&json) - 1, fields().len() - 1);
}

fn load_deck(name: &str) -> Deck {
    let path = format!("{}/decks/{name}", env!("CARGO_MANIFEST_DIR"));
    match load(&path) {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    }
}

fn err_text(text: &str) -> String {
    match parse(text, "t.toml") {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

/// The aerospace deck is `example_aerospace()` to 1e-12 relative: the deck writes the
/// converted values with 15 significant digits (≤ 5e-15 rounding) and conversion adds
/// a few ulps.
#[test]
fn aerospace_deck_is_example_bearing() {
    let d = parse(DEFAULT_DECK, "aerospace.toml").map_err(|e| e.to_string());
    let d = match d {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    };
    let ex = Bearing::example_aerospace();
    assert_eq!(d.units, Units::Us);
    assert_eq!(d.value.name, ex.name);
    assert_eq!(d.value.materials, ex.materials);
    assert_eq!(d.value.solver, ex.solver);
    assert_eq!(bearing_diff(&d.value, &ex, 1e-12), Vec::<String>::new());
}

/// SI and US spellings of the aerospace bearing agree to 1e-9 relative (both files
/// carry 15 significant digits; 1e-9 is the brief's round-trip tolerance).
#[test]
fn aerospace_si_matches_us() {
    let us = load_deck("aerospace.toml");
    let si = load_deck("aerospace_si.toml");
    assert_eq!(si.units, Units::Si);
    assert_eq!(
        bearing_diff(&us.value, &si.value, 1e-9),
        Vec::<String>::new()
    );
}

#[test]
fn template_round_trips_both_units() {
    for units in [Units::Us, Units::Si] {
        let text = template(units);
        let d = match parse(&text, "template.toml") {
            Ok(d) => d,
            Err(e) => panic!("{units}: {e}"),
        };
        assert_eq!(d.units, units);
        // 15-significant-digit writing: 1e-12 relative is ample.
        let mut ex = Bearing::example_aerospace();
        ex.name = "template (aerospace example bearing)".into();
        let diffs = bearing_diff(&d.value, &ex, 1e-12);
        assert!(diffs.is_empty(), "{diffs:?}");
        // every registry key is mentioned in the template
        for f in fields() {
            assert!(text.contains(f.name()), "{}", f.key);
        }
        // the template names its bearing system (redesign issue 13: every template
        // carries `type`; an absent `type` still reads as a spherical roller deck)
        let type_line = text.lines().find(|l| l.starts_with("type"));
        assert_eq!(
            type_line,
            Some("type = \"spherical-roller\"  # the bearing system this deck describes")
        );
    }
}

#[test]
fn converted_round_trips() {
    let d = load_deck("industrial.toml");
    let us = d.converted(Units::Us);
    let back = match parse(&us.to_toml_string(), "us.toml") {
        Ok(b) => b,
        Err(e) => panic!("{e}"),
    };
    assert_eq!(back.units, Units::Us);
    // 1e-12: one conversion each way plus 15-digit writing.
    assert!(bearing_diff(&back.value, &d.value, 1e-12).is_empty());
    let si = back.converted(Units::Si);
    let again = match parse(&si.to_toml_string(), "si.toml") {
        Ok(b) => b,
        Err(e) => panic!("{e}"),
    };
    assert!(bearing_diff(&again.value, &d.value, 1e-12).is_empty());
    assert_eq!(again.value.life.method, LifeMethod::Iso281);
}

#[test]
fn thermal_table_is_kept_opaque() {
    // A deck without its own [thermal] section (the default deck carries the rig network).
    let base = include_str!("../../../decks/aerospace_si.toml");
    let text =
        format!("{base}\n[thermal]\nambient = 20.0\n[thermal.nodes.inner]\ncapacity = 1.5 # J/K\n");
    let d = match parse(&text, "t.toml") {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    };
    let th = d.opaque.get("thermal").cloned().unwrap_or_default();
    assert_eq!(
        th.get("ambient").and_then(toml::Value::as_float),
        Some(20.0)
    );
    assert!(d.to_toml_string().contains("capacity = 1.5 # J/K"));
    let c = d.converted(Units::Si);
    assert_eq!(c.opaque.get("thermal"), d.opaque.get("thermal"));
    let back = parse(&c.to_toml_string(), "c.toml").map(|d| d.opaque.get("thermal").cloned());
    assert_eq!(back.ok().flatten(), d.opaque.get("thermal").cloned());
}

#[test]
fn malformed_toml_has_line_and_column() {
    let e = err_text("units = \"us\"\nname = \n");
    assert!(e.starts_with("t.toml:2:"), "{e}");
    assert!(e.contains("malformed TOML"), "{e}");
}

#[test]
fn unknown_keys_are_named_with_line() {
    let text = DEFAULT_DECK.replace("roller_count = 16", "roller_count = 16\nroller_cont = 3");
    let e = err_text(&text);
    assert!(
        e.contains("t.toml:12:1: unknown key `geometry.roller_cont`"),
        "{e}"
    );
    let text = format!("{DEFAULT_DECK}\n[extra]\na = 1\n");
    assert!(err_text(&text).contains("unknown key `extra`"));
}

#[test]
fn roller_count_range_message() {
    let text = DEFAULT_DECK.replace("roller_count = 16", "roller_count = 0");
    let e = err_text(&text);
    assert!(
        e.contains(
            "t.toml:11:16: geometry.roller_count = 0 is out of range (allowed 3 ≤ value ≤ 500)"
        ),
        "{e}"
    );
}

/// Each single-field rule: the message names key, value and range.
#[test]
fn each_range_rule_rejects() {
    let cases = [
        (
            "roller_diameter = 0.5 ",
            "roller_diameter = -0.5 ",
            "geometry.roller_diameter = -0.5 is out of range",
        ),
        (
            "contact_angle = 12.0",
            "contact_angle = 45.0",
            "geometry.contact_angle = 45.0 is out of range (allowed 0 ≤ value < 45 deg)",
        ),
        (
            "capacity_reduction = 0.75",
            "capacity_reduction = 0.2",
            "life.capacity_reduction = 0.2 is out of range (allowed 0.3 ≤ value ≤ 1)",
        ),
        (
            "edge_stress_factor = 1.5",
            "edge_stress_factor = 0.9",
            "life.edge_stress_factor = 0.9 is out of range",
        ),
        (
            "laminae = 81",
            "laminae = 0",
            "solver.laminae = 0 is out of range (allowed 1 ≤ value ≤ 2000)",
        ),
        (
            "laminae = 81",
            "laminae = 2001",
            "solver.laminae = 2001 is out of range",
        ),
        (
            "viscosity = 6.52669819785941e-7",
            "viscosity = 0",
            "lubricant.viscosity = 0 is out of range",
        ),
        (
            "roller_count = 16",
            "roller_count = 16.5",
            "geometry.roller_count = 16.5 has the wrong type (expected an integer)",
        ),
        (
            "film_model = \"grubin\"",
            "film_model = \"magic\"",
            "lubricant.film_model = \"magic\": expected one of",
        ),
        (
            "roller = \"steel\"",
            "roller = \"wood\"",
            "materials.roller = \"wood\": unknown material preset",
        ),
        (
            "radial_load = 3000",
            "radial_load = \"heavy\"",
            "operating.radial_load = \"heavy\" has the wrong type",
        ),
    ];
    for (from, to, want) in cases {
        assert!(DEFAULT_DECK.contains(from), "{from}");
        let e = err_text(&DEFAULT_DECK.replacen(from, to, 1));
        assert!(e.contains(want), "{want}\n got: {e}");
    }
    // Poisson's ratio inside an inline material table
    let text = DEFAULT_DECK.replace(
        "inner_ring = \"steel\"",
        "inner_ring = { youngs_modulus = 29e6, poisson_ratio = 0.5, density = 0.283, specific_heat = 0.11, conductivity = 25.0 }",
    );
    assert!(err_text(&text).contains(
        "materials.inner_ring.poisson_ratio = 0.5 is out of range (allowed 0 ≤ value < 0.5)"
    ));
}

/// Each cross-field rule, at the line of the first key involved.
#[test]
fn each_cross_rule_rejects() {
    let cases = [
        ("pitch_diameter = 3.3 ", "pitch_diameter = 0.4 ", "geometry.pitch_diameter = 0.4: must be greater than"),
        ("roller_crown_radius = 1.90", "roller_crown_radius = 0.2", "geometry.roller_crown_radius = 0.2: must be at least half"),
        ("inner_crown_radius = 1.95", "inner_crown_radius = 1.8", "t.toml:16:22: geometry.inner_crown_radius = 1.8: must be at least geometry.roller_crown_radius = 1.9 in"),
        ("outer_crown_radius = 1.9368619815273", "outer_crown_radius = 1.5", "geometry.outer_crown_radius = 1.5: must be at least"),
        ("effective_length = 0.46", "effective_length = 0.6", "geometry.effective_length = 0.6: must not exceed geometry.roller_length"),
        ("roller_count = 16", "roller_count = 21", "geometry.roller_count = 21: rollers do not fit"),
        ("method = \"asme\"", "method = \"iso281\"\n", ""),
    ];
    for (from, to, want) in cases {
        assert!(DEFAULT_DECK.contains(from), "{from}");
        let r = parse(&DEFAULT_DECK.replacen(from, to, 1), "t.toml");
        if want.is_empty() {
            assert!(r.is_ok(), "{from}");
            continue;
        }
        let e = match r {
            Ok(_) => panic!("{to} accepted"),
            Err(e) => e.to_string(),
        };
        assert!(e.contains(want), "{want}\n got: {e}");
    }
    // L_eff ≤ 2·R_o with a very short crown radius (also trips R_o ≥ D/2 on a small roller)
    let text = DEFAULT_DECK
        .replace("roller_crown_radius = 1.90", "roller_crown_radius = 0.26")
        .replace("effective_length = 0.46", "effective_length = 0.55")
        .replace("roller_length = 0.5 ", "roller_length = 0.6 ");
    assert!(err_text(&text).contains("must not exceed twice geometry.roller_crown_radius"));
    // |clearance| < D, on a small roller (the range alone allows ±0.39 in)
    let text = DEFAULT_DECK
        .replace("diametral_clearance = 0.0008", "diametral_clearance = -0.3")
        .replace("roller_diameter = 0.5 ", "roller_diameter = 0.2 ");
    let e = err_text(&text);
    assert!(e.contains("geometry.diametral_clearance = -0.3: |clearance| must be less than geometry.roller_diameter = 0.2 in"), "{e}");
    // iso281 needs a fatigue load limit
    let text = DEFAULT_DECK
        .replace("method = \"asme\"", "method = \"iso281\"")
        .replace(
            "iso_fatigue_load_limit = 1348.85365859826",
            "iso_fatigue_load_limit = 0",
        );
    assert!(err_text(&text).contains("life.method = \"iso281\": method \"iso281\" needs"));
}

#[test]
fn pressure_viscosity_xor_lubricant_parameter() {
    let both = DEFAULT_DECK.replace("film_model", "lubricant_parameter = 4.95\nfilm_model");
    let e = err_text(&both);
    assert!(
        e.contains("lubricant.lubricant_parameter = 4.95: give exactly one of"),
        "{e}"
    );
    let neither = DEFAULT_DECK.replace("pressure_viscosity = 7.5842330224852e-5", "");
    let e = err_text(&neither);
    assert!(
        e.contains("missing required key `lubricant.pressure_viscosity`"),
        "{e}"
    );
    // LP alone gives α = LP/(1e11·η): 1e-12 relative (one division).
    let lp = DEFAULT_DECK.replace(
        "pressure_viscosity = 7.5842330224852e-5",
        "lubricant_parameter = 4.95",
    );
    let d = parse(&lp, "t.toml").map_err(|e| e.to_string());
    let alpha = d.map(|d| d.value.lubricant.pressure_viscosity_pa_inv);
    assert!(
        matches!(alpha, Ok(a) if rel(a, 1.1e-8) < 1e-12),
        "{alpha:?}"
    );
}

#[test]
fn all_errors_are_collected_in_file_order() {
    let text = DEFAULT_DECK
        .replace("roller_count = 16", "roller_count = 0")
        .replace("laminae = 81", "laminae = -1")
        .replace("mass = 0.330693393277316", "mass = -1\nbogus = 2");
    let e = match parse(&text, "t.toml") {
        Ok(_) => panic!("accepted"),
        Err(e) => e,
    };
    assert_eq!(e.len(), 4, "{e}");
    let lines: Vec<usize> = e
        .errors()
        .iter()
        .filter_map(|x| x.location())
        .map(|l| l.line)
        .collect();
    let mut sorted = lines.clone();
    sorted.sort_unstable();
    assert_eq!(lines, sorted);
}

#[test]
fn missing_required_key_and_table() {
    let e = err_text(&DEFAULT_DECK.replace("roller_diameter = 0.5 ", "# none "));
    assert!(
        e.contains("t.toml:10:1: missing required key `geometry.roller_diameter`"),
        "{e}"
    );
    let start = DEFAULT_DECK.find("[surfaces]").unwrap_or(0);
    let end = DEFAULT_DECK.find("[life]").unwrap_or(0);
    let text = format!("{}{}", &DEFAULT_DECK[..start], &DEFAULT_DECK[end..]);
    assert!(err_text(&text).contains("missing required key `surfaces`"));
    assert!(err_text("name = \"x\"").contains("missing required key `units`"));
}

#[test]
fn optional_keys_take_defaults() {
    let d = load_deck("radial_si.toml");
    let b = &d.value;
    assert_eq!(
        b.solver,
        crate::bearings::spherical_roller::SolverSettings::default()
    );
    assert_eq!(b.cage.drag_factor, 5.0);
    assert_eq!(b.life.iso_contamination_factor, 1.0);
    assert_eq!(b.lubricant.limiting_traction_coefficient, 0.06);
    // LP = 18 with η = 0.01 Pa·s → α = 1.8e-8 1/Pa (1e-12: one division).
    assert!(rel(b.lubricant.pressure_viscosity_pa_inv, 1.8e-8) < 1e-12);
}

#[test]
fn set_and_get_keep_comments() {
    let mut d = load_deck("aerospace.toml");
    assert_eq!(d.get("geometry.pitch_diameter").as_deref(), Some("3.3"));
    assert_eq!(d.get("life.method").as_deref(), Some("asme"));
    assert_eq!(d.get("materials.roller").as_deref(), Some("steel"));
    assert_eq!(d.get("nope.key"), None);
    let r = d.set("geometry.pitch_diameter", "3.4");
    assert!(r.is_ok(), "{r:?}");
    // 3.4 in exactly in SI: 1e-15 relative (one multiply).
    assert!(
        rel(
            d.value.geometry.pitch_diameter_m,
            3.4 * crate::units::INCH_M
        ) < 1e-15
    );
    let text = d.to_toml_string();
    assert!(
        text.contains("pitch_diameter = 3.4              # in"),
        "{text}"
    );
    assert!(text.starts_with("# Aerospace angular-contact"));
    assert!(d.set("life.method", "iso281").is_ok());
    assert_eq!(d.value.life.method, LifeMethod::Iso281);
    assert_eq!(d.get("life.method").as_deref(), Some("iso281"));
    // defaults/presets are reported in deck units
    let e = d.get("materials.roller.youngs_modulus");
    assert_eq!(e.as_deref(), Some("29000000.0"));
    // editing a preset's property turns it into an inline table
    assert!(d.set("materials.roller.poisson_ratio", "0.28").is_ok());
    assert!(d
        .to_toml_string()
        .contains("roller = { youngs_modulus = 29000000.0, poisson_ratio = 0.28,"));
    assert_eq!(d.value.materials.roller.poisson_ratio, 0.28);
    assert!(
        rel(
            d.value.materials.roller.youngs_modulus_pa,
            Material::STEEL.youngs_modulus_pa
        ) < 1e-15
    );
    assert!(d.set("materials.roller", "silicon-nitride").is_ok());
    assert_eq!(d.value.materials.roller, Material::SILICON_NITRIDE);
    // α and LP are exclusive: setting one replaces the other (LP = 1e11·η·α; 1e-12
    // relative, one division)
    assert!(d.set("lubricant.lubricant_parameter", "9.9").is_ok());
    assert!(rel(d.value.lubricant.pressure_viscosity_pa_inv, 2.2e-8) < 1e-12);
    assert!(!d.to_toml_string().contains("pressure_viscosity ="));
    assert!(d.set("lubricant.pressure_viscosity", "7.6e-5").is_ok());
    assert!(!d.to_toml_string().contains("lubricant_parameter ="));
    assert!(d.set("operating.radial_load", "2500").is_ok());
    assert_eq!(d.get("operating.radial_load").as_deref(), Some("2500"));
    assert!(d
        .apply_assignments(&["operating.radial_load".to_string()])
        .is_err());
    assert!(d.set("name", "test rig #2").is_ok());
    assert_eq!(d.name, "test rig #2");
    assert_eq!(d.get("name").as_deref(), Some("test rig #2"));
    // an optional key not in the file is inserted
    let mut r = load_deck("radial_si.toml");
    assert!(r.set("cage.drag_factor", "3").is_ok());
    assert_eq!(r.value.cage.drag_factor, 3.0);
    assert!(r.set("solver.laminae", "41").is_ok());
    assert_eq!(r.value.solver.laminae, 41);
}

#[test]
fn set_errors_leave_deck_unchanged() {
    let mut d = load_deck("aerospace.toml");
    let before = d.to_toml_string();
    let b0 = d.value.clone();
    let e = d
        .set("geometry.roller_count", "0")
        .map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("geometry.roller_count = 0 is out of range")),
        "{e:?}"
    );
    assert!(d.set("geometry.inner_crown_radius", "1.0").is_err());
    assert!(d.set("geometry.bogus", "1.0").is_err());
    assert!(d.set("units", "si").is_err());
    assert!(d.set("life.method", "magic").is_err());
    assert_eq!(d.to_toml_string(), before);
    assert_eq!(d.value, b0);
}

#[test]
fn save_is_atomic_and_keeps_backup() {
    let dir = match tempfile::tempdir() {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    };
    let path = dir.path().join("deck.toml");
    let mut d = load_deck("aerospace.toml");
    assert!(d.save(&path).is_ok());
    assert!(d.set("operating.inner_speed", "12000").is_ok());
    assert!(d.save(&path).is_ok());
    let saved = std::fs::read_to_string(&path).unwrap_or_default();
    let bak = std::fs::read_to_string(dir.path().join("deck.toml.bak")).unwrap_or_default();
    assert!(saved.contains("inner_speed = 12000"));
    assert_eq!(bak, DEFAULT_DECK);
    assert!(load(&path).is_ok());
    // (failures leaving the file untouched: crate::files tests)

    // saving into a directory that does not exist fails cleanly, as a deck I/O error
    let e = d.save(&dir.path().join("no/such/dir/deck.toml"));
    assert!(
        matches!(&e, Err(x) if x.to_string().contains("no/such/dir does not exist")),
        "{e:?}"
    );
    // load of a missing file is an I/O error naming it
    let e = load(dir.path().join("missing.toml")).map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("missing.toml: cannot read deck")),
        "{e:?}"
    );
}

/// Overrides are all applied, then validated once: the order never changes the verdict
/// (before, each was validated alone, so a pair that is only valid together failed in one
/// order and passed in the other).
#[test]
fn overrides_validate_once_whatever_the_order() {
    let base = || parse(DEFAULT_DECK, "aerospace").unwrap_or_else(|e| panic!("{e}"));
    // Pitch diameter and roller count must fit together: shrink both.
    let a = "geometry.roller_count=6".to_string();
    let find = |k: &str| base().get(k).unwrap_or_default();
    let pd: f64 = find("geometry.pitch_diameter").parse().unwrap_or(0.0);
    let b = format!("geometry.pitch_diameter={}", pd * 0.45);
    let mut one = base();
    let mut two = base();
    let r1 = one.apply_assignments(&[a.clone(), b.clone()]).is_ok();
    let r2 = two.apply_assignments(&[b.clone(), a.clone()]).is_ok();
    assert_eq!(r1, r2, "order changed the verdict");
    let e = base()
        .apply_assignments(&["operating.inner_spd=5".to_string()])
        .map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("operating.inner_speed") && m.contains("rollbench keys")),
        "{e:?}"
    );
}

/// A deck larger than the limit is refused with the limit named, without reading it all;
/// a non-UTF-8 deck names the byte offset, line and column. (Before: /dev/zero was read
/// up to 4 GB; the UTF-8 error had no position.)
#[test]
fn reading_is_bounded_and_locates_bad_bytes() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let big = dir.path().join("big.toml");
    std::fs::write(&big, vec![b'#'; (MAX_DECK_BYTES + 10) as usize])
        .unwrap_or_else(|e| panic!("{e}"));
    let e = read_deck_text(&big).map_err(|e| e.to_string());
    assert!(matches!(&e, Err(m) if m.contains("4 MiB")), "{e:?}");
    #[cfg(unix)]
    {
        let e = read_deck_text(Path::new("/dev/zero")).map_err(|e| e.to_string());
        assert!(matches!(&e, Err(m) if m.contains("size limit")), "{e:?}");
    }
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, b"units = \"si\"\nname = \"a\xff\"\n").unwrap_or_else(|e| panic!("{e}"));
    let e = load(&bad).map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("byte offset 22") && m.contains("line 2, column 10")),
        "{e:?}"
    );
}

/// `[thermal]`: absurd durations and steps are refused at validation with the allowed
/// range; a non-finite temperature is named by its deck key.
#[test]
fn thermal_bounds_at_validation() {
    for (set, want) in [
        (vec!["thermal.transient.duration=1e20"], "duration ≤ 1e7"),
        (
            vec![
                "thermal.transient.duration=1e6",
                "thermal.transient.step=1e-3",
            ],
            "duration / step ≤ 1e6",
        ),
        (vec!["thermal.transient.step=1e-308"], "duration / step"),
    ] {
        let set: Vec<String> = set.into_iter().map(String::from).collect();
        let mut d = parse(DEFAULT_DECK, "aerospace").unwrap_or_else(|e| panic!("{e}"));
        let r = d
            .apply_assignments(&set)
            .map_err(|e| e.to_string())
            .and_then(|()| d.thermal_model().map(drop).map_err(|e| e.to_string()));
        assert!(matches!(&r, Err(m) if m.contains(want)), "{set:?}: {r:?}");
    }
    let text = DEFAULT_DECK.replacen("fixed_temperature = 80.0", "fixed_temperature = inf", 1);
    assert_ne!(text, DEFAULT_DECK);
    {
        let d = parse(&text, "aerospace");
        let r = d
            .map_err(|e| e.to_string())
            .and_then(|d| d.thermal_model().map(drop).map_err(|e| e.to_string()));
        assert!(
            matches!(&r, Err(m) if m.contains("fixed_temperature")),
            "{r:?}"
        );
    }
}

/// `[thermal]` errors give the file, line and column of the offending field (like the
/// rest of the deck) and use the deck's key names. (Fails on the previous code: the
/// message was `t.toml: [thermal]: …` with no line or column.)
#[test]
fn thermal_errors_have_line_and_column() {
    let line_col = |text: &str, needle: &str| -> (usize, usize) {
        let at = text.find(needle).expect("needle in deck");
        let eq = text[at..].find('=').expect("=") + at;
        let value = eq + 1 + text[eq + 1..].len() - text[eq + 1..].trim_start().len();
        let l = Location::at("t.toml", text, value);
        (l.line, l.column)
    };
    let thermal_err = |text: &str| -> DeckError {
        let deck = parse(text, "t.toml").expect("the bearing part is valid");
        let mut errs = deck.thermal_model().expect_err("bad [thermal]").0;
        assert_eq!(errs.len(), 1);
        errs.remove(0)
    };
    let base = DEFAULT_DECK;
    // a node field
    let text = base.replacen("fixed_temperature = 80.0", "fixed_temperature = inf", 1);
    let e = thermal_err(&text);
    let (line, col) = line_col(&text, "fixed_temperature = inf");
    let msg = e.to_string();
    assert!(
        msg.starts_with(&format!("t.toml:{line}:{col}: [thermal]:")),
        "{msg}"
    );
    assert!(
        msg.contains("node 'oil_in' field 'fixed_temperature'"),
        "{msg}"
    );
    assert!(!msg.contains("fixed_c"), "{msg}");
    assert_eq!(e.location().map(|l| l.line), Some(line));
    // a link field
    let text = base.replacen("mass_flow = 0.05", "mass_flow = -0.05", 1);
    let msg = thermal_err(&text).to_string();
    let (line, col) = line_col(&text, "mass_flow = -0.05");
    assert!(msg.starts_with(&format!("t.toml:{line}:{col}:")), "{msg}");
    assert!(msg.contains("field 'mass_flow'"), "{msg}");
    // a transient field
    let text = base.replacen("duration = 3600.0", "duration = -1.0", 1);
    let msg = thermal_err(&text).to_string();
    let (line, col) = line_col(&text, "duration = -1.0");
    assert!(msg.starts_with(&format!("t.toml:{line}:{col}:")), "{msg}");
    assert!(msg.contains("'duration'"), "{msg}");
    // a network error (a link to a node that does not exist): the link's `to`
    let text = base.replacen("to = \"oil_cavity\"", "to = \"oil_cavty\"", 1);
    let msg = thermal_err(&text).to_string();
    let (line, col) = line_col(&text, "to = \"oil_cavty\"");
    assert!(msg.starts_with(&format!("t.toml:{line}:{col}:")), "{msg}");
    assert!(msg.contains("unknown node 'oil_cavty'"), "{msg}");
    // a field a node does not have: the node's header line
    let text = base.replacen(
        "name = \"oil_in\"\n",
        "name = \"oil_in\"\ncolour = 1.0\n",
        1,
    );
    let msg = thermal_err(&text).to_string();
    let header = text[..text.find("name = \"oil_in\"").expect("oil_in")]
        .rfind("[[thermal.nodes]]")
        .expect("header");
    let l = Location::at("t.toml", &text, header);
    assert!(
        msg.starts_with(&format!("t.toml:{}:{}:", l.line, l.column)),
        "{msg}"
    );
}

/// Saving keeps the comments but not a stale value (issue 15): after an edit,
/// `viscosity = …   # reyn (= 0.0045 Pa·s)` keeps its unit and drops the old conversion;
/// comments without a conversion are kept whole.
#[test]
fn edited_values_lose_their_stale_conversions() {
    let mut d = parse(DEFAULT_DECK, "a.toml").unwrap_or_else(|e| panic!("{e}"));
    d.set("lubricant.viscosity", "1.3e-6")
        .unwrap_or_else(|e| panic!("{e}"));
    let text = d.to_toml_string();
    let line = text
        .lines()
        .find(|l| l.starts_with("viscosity"))
        .unwrap_or_default();
    assert!(line.starts_with("viscosity = 1.3e-6"), "{line}");
    assert!(line.ends_with("# reyn"), "{line}");
    assert!(!text.contains("0.0045 Pa·s"), "stale conversion kept");
    // An untouched line keeps its conversion.
    assert!(text.contains("(= 950 kg/m³)"));
}
