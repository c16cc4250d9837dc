//! Deck fixtures: every shipped deck parses; every invalid deck fails with a message
//! naming key and line (snapshotted); random bearings survive a write/parse round trip.

mod common;

use std::path::Path;

use common::toml_files;

use proptest::prelude::*;
use rollbench::bearings::spherical_roller::deck::{self as sr_deck, write_bearing, Deck};
use rollbench::bearings::spherical_roller::{
    Bearing, FilmModel, GuidingRing, LifeMethod, Material,
};
use rollbench::units::Units;

#[test]
fn every_shipped_deck_parses() {
    let files = toml_files("decks");
    assert!(files.len() >= 5, "{files:?}");
    for path in files {
        // Each deck through its own system (its `type`).
        let d = rollbench::bearings::load_file(&path, &[]);
        assert!(
            d.is_ok(),
            "{}: {}",
            path.display(),
            d.err().map(|e| e.to_string()).unwrap_or_default()
        );
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            text.starts_with('#'),
            "{}: needs a comment header",
            path.display()
        );
    }
}

#[test]
fn every_invalid_deck_fails_with_key_and_line() {
    let files = toml_files("tests/invalid_decks");
    assert!(files.len() >= 10, "{files:?}");
    for path in files {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        let err = match sr_deck::parse(&text, &name) {
            Ok(_) => panic!("{name} was accepted"),
            Err(e) => e,
        };
        for e in err.errors() {
            let loc = e.location();
            assert!(loc.is_some_and(|l| l.line > 1), "{name}: no line in {e}");
        }
        let msg = err.to_string();
        assert!(msg.starts_with(&format!("{name}:")), "{msg}");
        let snap = name.trim_end_matches(".toml").to_string();
        insta::assert_snapshot!(snap, msg);
    }
}

fn material() -> impl Strategy<Value = Material> {
    prop_oneof![
        Just(Material::STEEL),
        Just(Material::SILICON_NITRIDE),
        (
            1e10..5e11f64,
            0.0..0.49f64,
            1000.0..20000.0f64,
            100.0..2000.0f64,
            1.0..400.0f64
        )
            .prop_map(|(e, nu, rho, c, k)| Material {
                youngs_modulus_pa: e,
                poisson_ratio: nu,
                density_kg_m3: rho,
                specific_heat_j_kg_k: c,
                conductivity_w_m_k: k,
            }),
    ]
}

/// Random bearings that satisfy every range and cross-field rule by construction.
fn bearing() -> impl Strategy<Value = Bearing> {
    let geometry = (
        3usize..60,
        0.002..0.08f64, // D
        0.8..1.5f64,    // L/D
        0.5..1.0f64,    // Leff/L
        0.0..44.9f64,   // β deg
        -0.5..0.5f64,   // clearance / D * 0.02
        1.0..40.0f64,   // roller crown / (D/2)
        1.0..1.1f64,    // raceway crown factors
        1.0..1.1f64,
    );
    let operating = (-5e4..5e4f64, -5e3..5e3f64, 0.0..1e6f64, 0.0..1e6f64);
    let lube = (
        1e-4..1.0f64,
        1e-9..5e-8f64,
        700.0..1100.0f64,
        1000.0..3000.0f64,
        1e5..1e8f64,
        0.0..0.2f64,
        0.0..0.3f64,
        0usize..3,
    );
    let life = (
        0.3..1.0f64,
        0.1..20.0f64,
        1.0..3.0f64,
        any::<bool>(),
        0.0..1.0f64,
        1.0..1e6f64,
        0.0..1e-3f64,
    );
    let cage = (
        1e-3..0.05f64,
        0.0..1e-3f64,
        any::<bool>(),
        0.0..20.0f64,
        0.0..10.0f64,
    );
    let solver = (
        1usize..200,
        1e-14..1e-4f64, // solver.force_tolerance is capped at 1e-4
        1usize..500,
        1usize..500,
        0.0..0.1f64,
    );
    let rough = (1e-8..1e-6f64, 1e-8..1e-6f64, 1e-8..1e-6f64);
    (
        geometry,
        (material(), material(), material()),
        operating,
        lube,
        life,
        cage,
        solver,
        rough,
    )
        .prop_map(|(g, m, o, l, lf, c, s, r)| {
            let mut b = Bearing::example_aerospace();
            let (z, d, lr, effr, beta, cl, rc, fi, fo) = g;
            b.name = "random \"bearing\"".into();
            let geo = &mut b.geometry;
            geo.roller_count = z;
            geo.roller_diameter_m = d;
            geo.roller_length_m = d * lr;
            geo.effective_length_m = d * lr * effr;
            geo.roller_crown_radius_m = rc * d / 2.0 + d; // ≥ D/2 and ≥ L_eff/2
            geo.inner_crown_radius_m = geo.roller_crown_radius_m * fi;
            geo.outer_crown_radius_m = geo.roller_crown_radius_m * fo;
            // pitch circle large enough for Z rollers: Z·D < π·P_t
            geo.pitch_diameter_m = (z as f64 * d / std::f64::consts::PI * 1.2).max(3.0 * d);
            geo.contact_angle_rad = beta.to_radians();
            geo.diametral_clearance_m = cl * d * 0.02;
            b.materials.roller = m.0;
            b.materials.inner_ring = m.1;
            b.materials.outer_ring = m.2;
            b.operating.inner_speed_rad_s = o.0;
            b.operating.outer_speed_rad_s = o.1;
            b.operating.radial_load_n = o.2;
            b.operating.axial_load_n = o.3;
            b.lubricant.viscosity_pa_s = l.0;
            b.lubricant.pressure_viscosity_pa_inv = l.1;
            b.lubricant.density_kg_m3 = l.2;
            b.lubricant.specific_heat_j_kg_k = l.3;
            b.lubricant.transition_shear_stress_pa = l.4;
            b.lubricant.limiting_traction_coefficient = l.5;
            b.lubricant.lost_lubrication_traction_coefficient = l.6;
            b.lubricant.film_model = [
                FilmModel::Grubin,
                FilmModel::DowsonHigginson,
                FilmModel::PanHamrock,
            ][l.7];
            b.life.capacity_reduction = lf.0;
            b.life.material_factor = lf.1;
            b.life.edge_stress_factor = lf.2;
            b.life.method = if lf.3 {
                LifeMethod::Iso281
            } else {
                LifeMethod::Asme
            };
            b.life.iso_contamination_factor = lf.4;
            b.life.iso_fatigue_load_limit_n = lf.5;
            b.life.iso_reference_viscosity_m2_s = lf.6;
            b.cage.rail_width_m = c.0;
            b.cage.mean_diameter_m = b.geometry.pitch_diameter_m * 1.05;
            b.cage.diametral_clearance_m = c.1;
            b.cage.guided_by = if c.2 {
                GuidingRing::Inner
            } else {
                GuidingRing::Outer
            };
            b.cage.drag_factor = c.3;
            b.cage.mass_kg = c.4;
            b.solver.laminae = s.0;
            b.solver.force_tolerance = s.1;
            b.solver.max_iterations = s.2;
            b.solver.max_roller_iterations = s.3;
            b.solver.cage_stiffness_ratio = s.4;
            b.surfaces.roller_rms_m = r.0;
            b.surfaces.inner_rms_m = r.1;
            b.surfaces.outer_rms_m = r.2;
            b
        })
}

/// Field-by-field comparison through the serde representation (independent of the
/// deck registry): numbers within `tol` relative, everything else equal.
fn diff(a: &Bearing, b: &Bearing, tol: f64) -> Vec<String> {
    common::serde_diff::serde_diff("bearing", a, b, tol)
}

fn deck(name: &str) -> Deck {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("decks")
        .join(name);
    match sr_deck::load(&path) {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    }
}

/// The shipped decks are what their headers say (exact where the deck writes the
/// number itself; 1e-5 relative for the spherical outer race written to 6 digits).
#[test]
fn shipped_decks_have_their_stated_character() {
    let spherical = |b: &Bearing| {
        let g = &b.geometry;
        g.pitch_diameter_m / (2.0 * g.contact_angle_rad.cos()) + g.roller_diameter_m / 2.0
    };
    let radial = deck("radial_si.toml");
    assert_eq!(radial.units, Units::Si);
    assert_eq!(radial.value.geometry.contact_angle_rad, 0.0);
    assert_eq!(radial.value.operating.axial_load_n, 0.0);
    assert_eq!(radial.value.geometry.roller_count, 18);
    let thrust = deck("thrust.toml");
    assert_eq!(thrust.value.operating.radial_load_n, 0.0);
    assert!(thrust.value.operating.axial_load_n > 0.0);
    assert!((thrust.value.geometry.contact_angle_rad - 15f64.to_radians()).abs() < 1e-15);
    let r = spherical(&thrust.value) / thrust.value.geometry.outer_crown_radius_m;
    assert!((r - 1.0).abs() < 1e-5, "{r}");
    let ind = deck("industrial.toml");
    assert_eq!(ind.units, Units::Si);
    assert!(ind.value.operating.inner_speed_rad_s < 400.0 * std::f64::consts::PI / 30.0);
    let r = spherical(&ind.value) / ind.value.geometry.outer_crown_radius_m;
    assert!((r - 1.0).abs() < 1e-5, "{r}");
    let aero = deck("aerospace.toml");
    assert!(diff(&aero.value, &Bearing::example_aerospace(), 1e-12).is_empty());
    let aero_si = deck("aerospace_si.toml");
    assert!(diff(&aero_si.value, &aero.value, 1e-9).is_empty());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Write → parse is the identity to 1e-9 relative in both unit systems (the writer
    /// keeps 15 significant digits, so the actual error is ~1e-15; 1e-9 is the brief's
    /// tolerance).
    #[test]
    fn write_parse_round_trip(b in bearing()) {
        for units in [Units::Us, Units::Si] {
            let text = write_bearing(&b, units);
            let d = sr_deck::parse(&text, "prop.toml");
            prop_assert!(d.is_ok(), "{}\n{}", d.err().map(|e| e.to_string()).unwrap_or_default(), text);
            if let Ok(d) = d {
                prop_assert_eq!(&d.value.name, &b.name);
                prop_assert_eq!(d.value.lubricant.film_model, b.lubricant.film_model);
                prop_assert_eq!(d.value.life.method, b.life.method);
                prop_assert_eq!(d.value.cage.guided_by, b.cage.guided_by);
                let dif = diff(&d.value, &b, 1e-9);
                prop_assert!(dif.is_empty(), "{:?}", dif);
                // and through the conversion API
                let other = if units == Units::Us { Units::Si } else { Units::Us };
                let c = d.converted(other);
                let back = sr_deck::parse(&c.to_toml_string(), "conv.toml");
                prop_assert!(back.is_ok());
                if let Ok(back) = back {
                    prop_assert!(diff(&back.value, &b, 1e-9).is_empty());
                }
            }
        }
    }
}
