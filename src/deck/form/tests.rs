//! The generic deck machinery on a toy schema: a struct with a required length, a
//! defaulted integer, a choice, a one-of pair and a material body, and one cross rule.

use super::*;
use crate::units::INCH_M;

#[derive(Debug, Clone, PartialEq)]
struct Toy {
    length_m: f64,
    count: usize,
    mode: usize,
    /// The one-of pair: `run.alpha` directly, or `run.beta` = 2·alpha.
    alpha: f64,
    ball: Material,
}

fn toy_defaults() -> Toy {
    Toy {
        length_m: 0.01,
        count: 8,
        mode: 0,
        alpha: 0.25,
        ball: Material::STEEL,
    }
}

const MODES: &[&str] = &["slow", "fast"];
const BALL: [FieldSpec<Toy>; 5] = material_fields!(Toy, "ball", "Ball", |t| t.ball);

static FIELDS: [FieldSpec<Toy>; 10] = [
    FieldSpec {
        meta: FieldMeta::new(
            "shape.length",
            "shape",
            "Length L",
            Quantity::Length,
            FieldKind::Real,
            (0.0, true),
            (1.0, false),
            Presence::Required,
            "overall length",
        ),
        get: |t| t.length_m,
        set: |t, v| t.length_m = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "shape.count",
            "shape",
            "Count Z",
            Quantity::Count,
            FieldKind::Integer,
            (3.0, false),
            (100.0, false),
            Presence::Default(8.0),
            "number of balls",
        ),
        get: |t| t.count as f64,
        set: |t, v| t.count = v as usize,
    },
    BALL[0],
    BALL[1],
    BALL[2],
    BALL[3],
    BALL[4],
    FieldSpec {
        meta: FieldMeta::new(
            "run.mode",
            "run",
            "Mode",
            Quantity::Dimensionless,
            FieldKind::Choice(MODES),
            (0.0, false),
            (1.0, false),
            Presence::Default(0.0),
            "how fast",
        ),
        get: |t| t.mode as f64,
        set: |t, v| t.mode = v as usize,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "run.alpha",
            "run",
            "Alpha",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (1.0, false),
            Presence::OneOf("run.beta"),
            "alpha (give this OR beta)",
        ),
        get: |t| t.alpha,
        set: |t, v| t.alpha = v,
    },
    FieldSpec {
        meta: FieldMeta::new(
            "run.beta",
            "run",
            "Beta = 2·alpha",
            Quantity::Dimensionless,
            FieldKind::Real,
            (0.0, false),
            (2.0, false),
            Presence::OneOf("run.alpha"),
            "beta (give this OR alpha)",
        ),
        get: |t| 2.0 * t.alpha,
        set: |t, v| t.alpha = v / 2.0,
    },
];

fn toy_cross(t: &Toy, units: Units) -> Vec<(&'static str, String)> {
    let mut v = Vec::new();
    // a fast toy must be long enough: 1 mm per ball
    if t.mode == 1 && t.length_m < 1e-3 * t.count as f64 {
        v.push((
            "run.mode",
            format!(
                "\"fast\" needs shape.length ≥ 1 mm per ball ({}, {})",
                show(&TOY, t, "shape.length", units),
                show(&TOY, t, "shape.count", units)
            ),
        ));
    }
    v
}

static TOY: Schema<Toy> = Schema {
    system: "toy-bearing",
    groups: &["shape", "materials", "run", "extra"],
    required_groups: &["shape", "materials", "run"],
    fields: &FIELDS,
    material_bodies: &["ball"],
    material: Some(MaterialAccess {
        get: |t, _| t.ball,
        set: |t, _, m| t.ball = m,
    }),
    opaque_tables: &["extra"],
    defaults: toy_defaults,
    cross_checks: toy_cross,
    one_holding: &[],
    template_header: "toy deck template",
    template_notes: crate::deck::form::TemplateNotes::NONE,
};

const DECK: &str = r#"# a toy deck
type = "toy-bearing"
units = "si"
name = "toy"

[shape]
length = 0.02   # m, measured
count = 10

[materials]
ball = "steel"

[run]
mode = "fast"   # keep fast
alpha = 0.5

[extra]
anything = [1, 2]
"#;

fn parse(text: &str) -> Result<Form<Toy>, String> {
    Form::parse(text, "toy.toml", &TOY).map_err(|e| e.to_string())
}

fn err(text: &str) -> String {
    match parse(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}

#[test]
fn reads_a_valid_deck() {
    let f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.units, Units::Si);
    assert_eq!(f.name, "toy");
    assert_eq!(
        f.value,
        Toy {
            length_m: 0.02,
            count: 10,
            mode: 1,
            alpha: 0.5,
            ball: Material::STEEL
        }
    );
    assert_eq!(
        f.opaque
            .get("extra")
            .and_then(|t| t.get("anything"))
            .and_then(toml::Value::as_array)
            .map(Vec::len),
        Some(2)
    );
    assert_eq!(f.schema().system, "toy-bearing");
    assert_eq!(f.source_name(), "toy.toml");
}

#[test]
fn unknown_key_names_allowed_keys_and_position() {
    let e = err(&DECK.replace("count = 10", "count = 10\ncuont = 3"));
    assert!(
        e.contains("toy.toml:9:1: unknown key `shape.cuont` (allowed in shape: length, count)"),
        "{e}"
    );
    let e = err(&format!("{DECK}\n[bogus]\n"));
    assert!(
        e.contains(
            "unknown key `bogus` (allowed in the top level: type, units, name, shape, materials, run, extra)"
        ),
        "{e}"
    );
    // a material table's properties are checked too
    let e = err(&DECK.replace(
        "ball = \"steel\"",
        "ball = { youngs_modulus = 2e11, poisson_ratio = 0.3, density = 7800.0, specific_heat = 460.0, conductivity = 40.0, colour = 1 }",
    ));
    assert!(
        e.contains("unknown key `materials.ball.colour` (allowed in materials.ball: youngs_modulus, poisson_ratio, density, specific_heat, conductivity)"),
        "{e}"
    );
}

#[test]
fn wrong_types_are_named() {
    let e = err(&DECK.replace("length = 0.02", "length = \"long\""));
    assert!(
        e.contains("toy.toml:7:10: shape.length = \"long\" has the wrong type (expected a number)"),
        "{e}"
    );
    let e = err(&DECK.replace("count = 10", "count = 10.5"));
    assert!(
        e.contains("shape.count = 10.5 has the wrong type (expected an integer)"),
        "{e}"
    );
    let e = err(&DECK.replace("mode = \"fast\"", "mode = 1"));
    assert!(
        e.contains(
            "run.mode = 1 has the wrong type (expected a string, one of \"slow\", \"fast\")"
        ),
        "{e}"
    );
    let e = err(&DECK.replace("mode = \"fast\"", "mode = \"warp\""));
    assert!(
        e.contains("run.mode = \"warp\": expected one of \"slow\", \"fast\""),
        "{e}"
    );
    let e = err(&DECK.replace("ball = \"steel\"", "ball = \"wood\""));
    assert!(e.contains("materials.ball = \"wood\": unknown material preset (expected one of \"steel\", \"silicon-nitride\""), "{e}");
    let e = err(&DECK.replace("ball = \"steel\"", "ball = 3"));
    assert!(
        e.contains(
            "materials.ball = 3 has the wrong type (expected a preset name or an inline table)"
        ),
        "{e}"
    );
}

/// The range is shown in the deck's units: 1 m is 39.370078… in, shown rounded inward
/// as 39.37 so that the printed bound is itself accepted (issue 24 item 15: "39.3701"
/// was refused by the range it printed).
#[test]
fn out_of_range_shows_deck_units() {
    let e = err(&DECK.replace("length = 0.02", "length = 2.0"));
    assert!(
        e.contains("toy.toml:7:10: shape.length = 2.0 is out of range (allowed 0 < value ≤ 1 m)"),
        "{e}"
    );
    let us = DECK
        .replace("units = \"si\"", "units = \"us\"")
        .replace("mode = \"fast\"", "mode = \"slow\"");
    let e = err(&us.replace("length = 0.02", "length = 40"));
    assert!(
        e.contains("shape.length = 40 is out of range (allowed 0 < value ≤ 39.37 in)"),
        "{e}"
    );
    // 0.02 in is valid in a US deck: 0.02·0.0254 m exactly (1e-15, one multiply)
    let f = parse(&us).unwrap_or_else(|e| panic!("{e}"));
    assert!(rel(f.value.length_m, 0.02 * INCH_M) < 1e-15);
    let e = err(&DECK.replace("count = 10", "count = 2"));
    assert!(
        e.contains("shape.count = 2 is out of range (allowed 3 ≤ value ≤ 100)"),
        "{e}"
    );
}

#[test]
fn presence_rules() {
    // missing required key: at its table's header, with help and range
    let e = err(&DECK.replace("length = 0.02   # m, measured\n", ""));
    assert!(
        e.contains(
            "toy.toml:6:1: missing required key `shape.length` (overall length, 0 < value ≤ 1 m)"
        ),
        "{e}"
    );
    // missing required table and units
    let no_run = DECK.replace("[run]\nmode = \"fast\"   # keep fast\nalpha = 0.5\n", "");
    assert!(err(&no_run).contains("missing required key `run` (the [run] table is required)"));
    assert!(err(&DECK.replace("units = \"si\"\n", "")).contains("missing required key `units`"));
    // a default applies when absent
    let f = parse(&DECK.replace("count = 10\n", "")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(f.value.count, 8);
    // one-of: neither, both, the other one
    let e = err(&DECK.replace("alpha = 0.5\n", ""));
    assert!(
        e.contains("missing required key `run.alpha` (or give run.beta instead)"),
        "{e}"
    );
    let e = err(&DECK.replace("alpha = 0.5\n", "alpha = 0.5\nbeta = 1.0\n"));
    assert!(
        e.contains("toy.toml:16:8: run.beta = 1.0: give exactly one of run.alpha and run.beta (the other is at line 15)"),
        "{e}"
    );
    let f = parse(&DECK.replace("alpha = 0.5", "beta = 0.3")).unwrap_or_else(|e| panic!("{e}"));
    assert!(rel(f.value.alpha, 0.15) < 1e-15);
    // a missing material body
    let e = err(&DECK.replace("ball = \"steel\"\n", ""));
    assert!(e.contains("toy.toml:10:1: missing required key `materials.ball` (a preset: \"steel\", \"silicon-nitride\"; or an inline table)"), "{e}");
}

#[test]
fn type_is_required_and_must_match() {
    let e = err(&DECK.replace("type = \"toy-bearing\"\n", ""));
    assert!(
        e.contains("toy.toml:1:1: missing required key `type`"),
        "{e}"
    );
    assert!(e.contains("write type = \"toy-bearing\""), "{e}");
    let e = err(&DECK.replace("type = \"toy-bearing\"", "type = \"spherical-roller\""));
    assert!(
        e.contains("toy.toml:2:8: type = \"spherical-roller\": this deck reader reads \"toy-bearing\" decks"),
        "{e}"
    );
    let e = err(&DECK.replace("type = \"toy-bearing\"", "type = \"nope\""));
    assert!(
        // The registry, not the reader, lists the known systems (`bearings::system_of`).
        e.contains("type = \"nope\": this deck reader reads \"toy-bearing\" decks"),
        "{e}"
    );
}

/// A cross rule is checked on valid values only, at its key's line.
#[test]
fn cross_rules_on_valid_keys_only() {
    let short = DECK.replace("length = 0.02", "length = 0.005");
    let e = err(&short);
    assert!(
        e.contains("toy.toml:14:8: run.mode = \"fast\": \"fast\" needs shape.length ≥ 1 mm per ball (shape.length = 0.005 m, shape.count = 10)"),
        "{e}"
    );
    // an invalid count is the only error: the rule naming it is not checked
    let e = err(&short.replace("count = 10", "count = 1000"));
    assert!(!e.contains("needs"), "{e}");
    assert_eq!(e.lines().count(), 1, "{e}");
}

#[test]
fn errors_are_all_collected_in_file_order() {
    let text = DECK
        .replace("length = 0.02", "length = -1")
        .replace("mode = \"fast\"", "mode = \"warp\"")
        .replace("count = 10", "count = 10\nx = 1");
    let e = Form::parse(&text, "toy.toml", &TOY)
        .err()
        .map(|e| e.0)
        .unwrap_or_default();
    assert_eq!(e.len(), 3);
    let lines: Vec<usize> = e
        .iter()
        .filter_map(|x| x.location())
        .map(|l| l.line)
        .collect();
    assert_eq!(lines, vec![7, 9, 15]);
}

#[test]
fn set_keeps_comments_and_validates() {
    let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    assert!(f.set("shape.length", "0.03").is_ok());
    assert_eq!(f.value.length_m, 0.03);
    let text = f.to_toml_string();
    assert!(text.contains("length = 0.03   # m, measured"), "{text}");
    assert!(text.starts_with("# a toy deck\n"), "{text}");
    assert!(text.contains("mode = \"fast\"   # keep fast"), "{text}");
    assert_eq!(f.get("shape.length").as_deref(), Some("0.03"));
    assert_eq!(f.get("run.mode").as_deref(), Some("fast"));
    // defaults and presets are reported in deck units
    assert_eq!(f.get("run.beta").as_deref(), Some("1.0"));
    assert_eq!(f.get("materials.ball").as_deref(), Some("steel"));
    assert_eq!(f.get("nope"), None);
    // a choice given unquoted is taken as the string
    assert!(f.set("run.mode", "slow").is_ok());
    assert_eq!(f.value.mode, 0);
    // one-of: setting one removes the other
    assert!(f.set("run.beta", "0.8").is_ok());
    assert!(rel(f.value.alpha, 0.4) < 1e-15);
    assert!(!f.to_toml_string().contains("alpha ="));
    // a preset's property turns it into a table
    assert!(f.set("materials.ball.poisson_ratio", "0.29").is_ok());
    assert_eq!(f.value.ball.poisson_ratio, 0.29);
    assert_eq!(f.value.ball.density_kg_m3, Material::STEEL.density_kg_m3);
    assert!(f.to_toml_string().contains("ball = { youngs_modulus ="));
    assert!(f.set("materials.ball", "silicon-nitride").is_ok());
    assert_eq!(f.value.ball, Material::SILICON_NITRIDE);
    assert!(f.set("name", "renamed").is_ok());
    assert_eq!(f.name, "renamed");
    // opaque tables take any key
    assert!(f.set("extra.more", "1").is_ok());
    assert_eq!(
        f.opaque
            .get("extra")
            .and_then(|t| t.get("more"))
            .and_then(toml::Value::as_integer),
        Some(1)
    );
    // errors leave the deck unchanged
    let before = f.to_toml_string();
    let v0 = f.value.clone();
    let e = f.set("shape.length", "5").map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("shape.length = 5 is out of range")),
        "{e:?}"
    );
    let e = f.set("shape.lenght", "0.1").map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("did you mean shape.length?") && m.contains("rollbench keys")),
        "{e:?}"
    );
    assert!(f.set("units", "us").is_err());
    assert_eq!(f.to_toml_string(), before);
    assert_eq!(f.value, v0);
}

/// All assignments are written first, then validated once: a pair valid only together
/// passes in both orders, and an invalid one fails in both.
#[test]
fn assignment_order_never_changes_the_verdict() {
    // short + fast is invalid, short + few balls is valid: only the pair is valid
    let a = "shape.length=0.004".to_string();
    let b = "shape.count=3".to_string();
    for pair in [[a.clone(), b.clone()], [b.clone(), a.clone()]] {
        let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
        assert!(f.apply_assignments(&pair).is_ok(), "{pair:?}");
        assert_eq!(f.value.count, 3);
        assert_eq!(f.value.length_m, 0.004);
    }
    let c = "shape.count=5".to_string();
    for pair in [[a.clone(), c.clone()], [c.clone(), a.clone()]] {
        let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
        let before = f.to_toml_string();
        assert!(f.apply_assignments(&pair).is_err(), "{pair:?}");
        assert_eq!(f.to_toml_string(), before);
    }
    let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    let e = f
        .apply_assignments(&["shape.length".to_string()])
        .map_err(|e| e.to_string());
    assert!(
        matches!(&e, Err(m) if m.contains("expected KEY=VALUE, e.g. --set shape.length=0.02")),
        "{e:?}"
    );
}

/// SI → US → SI gives the same value to 1e-12 relative (two conversions and 15-digit
/// writing, each ≤ 5e-15), and keeps the opaque table and the material.
#[test]
fn converted_round_trips() {
    let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    assert!(f.set("materials.ball.density", "7700.123456789").is_ok());
    let us = f.converted(Units::Us);
    assert_eq!(us.units, Units::Us);
    let text = us.to_toml_string();
    assert!(text.contains("type = \"toy-bearing\""), "{text}");
    assert!(text.contains("units = \"us\""), "{text}");
    let back = parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    let si = parse(&back.converted(Units::Si).to_toml_string()).unwrap_or_else(|e| panic!("{e}"));
    for v in [&back.value, &si.value] {
        assert!(rel(v.length_m, f.value.length_m) < 1e-12);
        assert!(rel(v.alpha, f.value.alpha) < 1e-12);
        assert_eq!((v.count, v.mode), (f.value.count, f.value.mode));
        assert!(rel(v.ball.density_kg_m3, f.value.ball.density_kg_m3) < 1e-12);
        assert!(rel(v.ball.youngs_modulus_pa, f.value.ball.youngs_modulus_pa) < 1e-12);
    }
    assert_eq!(si.opaque, f.opaque);
    assert_eq!(si.name, "toy");
}

#[test]
fn template_parses_back_to_the_defaults() {
    for units in [Units::Si, Units::Us] {
        let text = template(&TOY, units);
        let f = Form::parse(&text, "template", &TOY).unwrap_or_else(|e| panic!("{e}\n{text}"));
        assert_eq!(f.units, units);
        let d = toy_defaults();
        // 15-significant-digit writing: 1e-12 relative is ample
        assert!(rel(f.value.length_m, d.length_m) < 1e-12);
        assert!(rel(f.value.alpha, d.alpha) < 1e-12);
        assert_eq!(
            (f.value.count, f.value.mode, f.value.ball),
            (d.count, d.mode, d.ball)
        );
        assert!(
            text.starts_with("# toy deck template\ntype = \"toy-bearing\""),
            "{text}"
        );
        // every key is in the template with its help and range
        for spec in TOY.fields {
            assert!(text.contains(spec.name()), "{}", spec.key);
        }
        assert!(
            text.contains("# Length L: overall length. Allowed 0 < value ≤"),
            "{text}"
        );
        assert!(
            text.contains("# Mode: how fast. Allowed one of \"slow\", \"fast\". Optional."),
            "{text}"
        );
        assert!(text.contains("# beta = 0.5"), "{text}");
        assert!(text.contains("ball = \"steel\""), "{text}");
        assert!(text.contains("# [extra]"), "{text}");
    }
}

#[test]
fn keys_table_and_close_keys() {
    let t = keys_table(&TOY);
    assert!(t.contains("shape.length"), "{t}");
    assert!(t.contains("0 < value ≤ 1 m"), "{t}");
    assert!(t.contains("0 < value ≤ 39.37 in"), "{t}");
    assert!(t.contains("slow | fast"), "{t}");
    assert!(t.contains("materials.ball"), "{t}");
    assert!(t.contains("steel, silicon-nitride"), "{t}");
    assert!(t.contains("extra.<table>.<key>"), "{t}");
    assert_eq!(
        close_keys(&TOY, "shape.lenth").first(),
        Some(&"shape.length")
    );
    assert_eq!(
        close_keys(&TOY, "materials.bal").first(),
        Some(&"materials.ball")
    );
    let keys = editable_keys(&TOY);
    assert!(
        keys.contains(&"name") && keys.contains(&"run.beta") && keys.contains(&"materials.ball")
    );
}

#[test]
fn save_writes_the_deck() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("toy.toml");
    let mut f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    assert!(f.save(&path).is_ok());
    assert!(f.set("shape.count", "12").is_ok());
    assert!(f.save(&path).is_ok());
    let back = Form::load(&path, &TOY).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.value.count, 12);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("toy.toml.bak"))
            .ok()
            .as_deref(),
        Some(DECK)
    );
}

#[test]
fn names_key_matches_whole_keys() {
    assert!(names_key("needs shape.length = 3", "shape.length"));
    assert!(names_key("see shape.length.", "shape.length"));
    assert!(!names_key("needs shape.length_max = 3", "shape.length"));
    assert!(!names_key("needs xshape.length", "shape.length"));
    assert!(!names_key("needs shape.length.max", "shape.length"));
}

#[test]
fn schemas_are_sound() {
    assert_eq!(schema_problems(&TOY), Vec::<String>::new());
    assert_eq!(
        schema_problems(&crate::bearings::spherical_roller::deck_schema::SCHEMA),
        Vec::<String>::new()
    );
}

/// A schema with an opaque `[thermal]` table gets the thermal network, its errors at
/// their line and column.
#[test]
fn thermal_table_is_read_by_the_thermal_parser() {
    static WARM: Schema<Toy> = Schema {
        system: "toy-bearing",
        groups: &["shape", "materials", "run"],
        required_groups: &["shape", "materials", "run"],
        fields: &FIELDS,
        material_bodies: &["ball"],
        material: None,
        opaque_tables: &["thermal"],
        defaults: toy_defaults,
        cross_checks: toy_cross,
        one_holding: &[],
        template_header: "warm toy",
        template_notes: crate::deck::form::TemplateNotes::NONE,
    };
    let base = DECK.replace("[extra]\nanything = [1, 2]\n", "").replace(
        "ball = \"steel\"",
        "ball = { youngs_modulus = 2e11, poisson_ratio = 0.3, density = 7800.0, specific_heat = 460.0, conductivity = 40.0 }",
    );
    let f = Form::parse(&base, "w.toml", &WARM).unwrap_or_else(|e| panic!("{e}"));
    assert!(matches!(f.thermal_model(), Ok(None)));
    let net = "\n[thermal]\n[[thermal.nodes]]\nname = \"ring\"\ncapacity = 10.0\n\n[[thermal.nodes]]\nname = \"air\"\nrole = \"air\"\nfixed_temperature = 20.0\n\n[[thermal.links]]\nfrom = \"ring\"\nto = \"air\"\nkind = \"conductance\"\nconductance = 1.0\n";
    let text = format!("{base}{net}");
    let f = Form::parse(&text, "w.toml", &WARM).unwrap_or_else(|e| panic!("{e}"));
    let m = f.thermal_model().map_err(|e| e.to_string());
    assert!(matches!(&m, Ok(Some(_))), "{m:?}");
    let bad = text.replace("conductance = 1.0", "conductance = -1.0");
    let f = Form::parse(&bad, "w.toml", &WARM).unwrap_or_else(|e| panic!("{e}"));
    let line = bad
        .lines()
        .position(|l| l == "conductance = -1.0")
        .map_or(0, |i| i + 1);
    let e = f
        .thermal_model()
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        e.starts_with(&format!("w.toml:{line}:15: [thermal]:")),
        "{e}"
    );
    // without a material accessor, a preset name is refused
    let e = Form::parse(
        &DECK.replace("[extra]\nanything = [1, 2]\n", ""),
        "w.toml",
        &WARM,
    )
    .err()
    .map(|e| e.to_string());
    assert!(e.is_some_and(|e| e.contains("materials.ball = \"steel\": this deck takes an inline table")));
}

/// `Form::location_in` (for systems that parse an opaque table themselves): the value
/// of a key, an array element, the table header for a missing key, the file start for a
/// missing table — line and column of the toy deck (`[extra]` at line 161 − 144 = 17).
#[test]
fn location_in_an_opaque_table() {
    use crate::deck::thermal::PathSeg::{Index, Key};
    let f = parse(DECK).unwrap_or_else(|e| panic!("{e}"));
    let at = |path: &[crate::deck::thermal::PathSeg]| f.location_in("extra", path).to_string();
    assert_eq!(at(&[Key("anything".into())]), "toy.toml:18:12");
    assert_eq!(at(&[Key("anything".into()), Index(1)]), "toy.toml:18:16");
    assert!(at(&[Key("nothing".into())]).starts_with("toy.toml:17:"));
    assert!(f
        .location_in("absent", &[])
        .to_string()
        .starts_with("toy.toml:1"));
}

/// Issue 24 item 15: every printed bound is accepted by the range it is printed for
/// (an inclusive bound, or one rounded inward and shown with ≤), in both unit systems,
/// for the toy schema and every registered system's keys.
#[test]
fn printed_bounds_are_accepted() {
    let mut metas: Vec<FieldMeta> = TOY.fields.iter().map(|f| f.meta).collect();
    for sys in crate::bearings::SYSTEMS {
        let case = sys
            .load(sys.example_deck(), "example.toml", &[])
            .unwrap_or_else(|e| panic!("{e}"));
        metas.extend(case.fields().into_iter().copied());
    }
    let mut checked = 0;
    for m in metas {
        if m.kind != FieldKind::Real {
            continue;
        }
        for units in [Units::Si, Units::Us] {
            let a = m.allowed(units);
            let words: Vec<&str> = a.split(' ').collect();
            // "LO OP value OP HI [unit]"
            let (lo, lo_op, hi_op, hi) = (words[0], words[1], words[3], words[4]);
            for (text, op) in [(lo, lo_op), (hi, hi_op)] {
                if op != "≤" {
                    continue;
                }
                let v: f64 = text.parse().unwrap_or_else(|e| panic!("{a}: {e}"));
                assert!(
                    m.in_range(m.to_si(v, units)),
                    "{}: {a}: {text} refused",
                    m.key
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 50, "{checked}");
}
