//! The double-row spherical roller system through the real binary: `check` on the shipped
//! deck and the templates, `keys`, a bad value named with its key and range, `run` in JSON
//! and text, `stiffness` (issue 27).

mod common;

use common::{deck, run};

fn temp(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rollbench-drsrb-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap_or_else(|e| panic!("{e}"));
    p
}

/// The shipped deck and both templates check clean; `keys` lists the groups.
#[test]
fn deck_templates_and_keys() {
    let (code, _, err) = run(&["check", &deck("srb_22308.toml")]);
    assert_eq!(code, 0, "{err}");
    for units in ["si", "us"] {
        let (code, t, err) = run(&[
            "template",
            "--type",
            "double-row-spherical-roller",
            "--units",
            units,
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(t.contains("type = \"double-row-spherical-roller\""), "{t}");
        let p = temp(&format!("t_{units}.toml"), &t);
        let (code, _, err) = run(&["check", &p.display().to_string()]);
        assert_eq!(code, 0, "{units}: {err}");
    }
    let (code, k, err) = run(&["keys", "--type", "double-row-spherical-roller"]);
    assert_eq!(code, 0, "{err}");
    for key in [
        "geometry.rows",
        "geometry.outer_sphere_radius",
        "guide_ring.width",
        "cage.measured_speed",
        "lubricant.viscosity_40",
        "lubricant.traction",
    ] {
        assert!(k.contains(key), "{key}: {k}");
    }
}

/// A pitch diameter off the outer sphere is refused naming the key and the rule.
#[test]
fn bad_pitch_is_refused() {
    let (code, _, err) = run(&[
        "check",
        &deck("srb_22308.toml"),
        "--set",
        "geometry.pitch_diameter=0.066",
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("geometry.pitch_diameter") && err.contains("cos α⁰"),
        "{err}"
    );
}

/// The optimiser's k_CE in a deck: R_CE changed alone by 0.2 % (the seed's Fig. 3 step)
/// breaks d_m = 2(R_CE − D_W/2)·cos α⁰ by 0.22 %, beyond the check's 1e-4, and is refused
/// naming the checked key and the three keys it is derived from (the optimiser varies R_CE
/// in the input instead: see `DrGeometry::outer_sphere_radius_m`).
#[test]
fn outer_sphere_radius_alone_is_refused() {
    let (code, _, err) = run(&[
        "check",
        &deck("srb_22308.toml"),
        "--set",
        "geometry.outer_sphere_radius=0.03955",
    ]);
    assert_eq!(code, 1, "{err}");
    for key in [
        "geometry.pitch_diameter",
        "geometry.outer_sphere_radius",
        "geometry.roller_diameter",
        "geometry.contact_angle",
    ] {
        assert!(err.contains(key), "{key}: {err}");
    }
}

/// The floating guide ring's offset is in the JSON beside the row forces; under pure axial
/// load its net axial force is zero to the ring tolerance (1e-9 of F_a).
#[test]
fn guide_ring_axial_offset_in_json() {
    let (code, out, err) = run(&[
        "run",
        &deck("srb_22308.toml"),
        "--set",
        "operating.radial_load=0",
        "--set",
        "operating.axial_load=5000",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    let g = &v["guide_ring"];
    for k in [
        "axial_offset_m",
        "force_row1_n",
        "force_row2_n",
        "net_axial_force_n",
    ] {
        assert!(g[k].is_f64(), "{k}: {g}");
    }
    assert!(g["axial_offset_m"].as_f64().unwrap_or(0.0) < 0.0, "{g}");
    assert!(
        g["net_axial_force_n"].as_f64().unwrap_or(1.0).abs() <= 5e-6,
        "{g}"
    );
}

/// `run --format json`: both rows' rollers with `row` and `guide_ring_load_n`, the rings,
/// the guide ring and the life; the text report names both rows; `stiffness` prints the
/// 2×2.
#[test]
fn run_json_text_and_stiffness() {
    let (code, out, err) = run(&["run", &deck("srb_22308.toml"), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(v["type"], "double-row-spherical-roller");
    let rollers = v["rollers"].as_array().cloned().unwrap_or_default();
    assert_eq!(rollers.len(), 26);
    assert_eq!(rollers[0]["row"], 1);
    assert_eq!(rollers[13]["row"], 2);
    for r in &rollers {
        assert!(r["guide_ring_load_n"].as_f64().is_some_and(|g| g >= 0.0));
        assert!(r["inner"]["normal_load_n"].as_f64().is_some());
    }
    assert!(v["rings"]["radial_deflection_m"]
        .as_f64()
        .is_some_and(|x| x > 0.0));
    assert!(v["guide_ring"]["force_row1_n"].as_f64().is_some());
    assert!(v["life"]["l10_bearing_h"].as_f64().is_some_and(|x| x > 0.0));
    assert_eq!(v["life"]["rows"].as_array().map(Vec::len), Some(2));
    let (code, text, err) = run(&["run", &deck("srb_22308.toml")]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("Row 1") && text.contains("Row 2"), "{text}");
    let (code, k, err) = run(&["stiffness", &deck("srb_22308.toml")]);
    assert_eq!(code, 0, "{err}");
    assert!(k.contains("F_x") && k.contains("F_z"), "{k}");
}
