//! Numerical stability campaign (issue 7): random valid bearings — geometry across its
//! valid ranges, loads from zero to 5× the dynamic capacity, speeds from zero to beyond
//! 3 million DN, clearance and preload, inner/outer/both rings rotating, contact angle
//! 0–30° — must either solve with residuals under tolerance and every number of the JSON
//! report finite, or return a typed `SolveError`; never panic. Time is bounded by the
//! solver's iteration limits (no timing assertions).
//!
//! `random_bearings_are_stable` runs 64 cases in the test profile; the `#[ignore]`d
//! `random_bearings_are_stable_heavy` runs 2000 and prints the counts:
//! `cargo test --release --test stability random_bearings_are_stable_heavy -- --ignored --nocapture`.

use std::panic::{catch_unwind, AssertUnwindSafe};

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rollbench::bearings::spherical_roller::deck::{self as sr_deck, write_bearing};
use rollbench::bearings::spherical_roller::pipeline::{self, Analysis, Request};
use rollbench::bearings::spherical_roller::report;
use rollbench::bearings::spherical_roller::{Bearing, DynamicLoads, Material};
use rollbench::physics::life::{raceway_capacity, Raceway};
use rollbench::units::Units;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// Raw random parameters of one bearing (all dimensionless fractions or plain numbers, so
/// that shrinking moves toward simple cases).
#[derive(Debug, Clone)]
struct Params {
    roller_count: usize,
    roller_diameter_mm: f64,
    /// Pitch diameter as a multiple of the tightest pitch Z·D/π (> 1).
    pitch_factor: f64,
    /// Roller length / D.
    length_ratio: f64,
    /// Effective length / roller length.
    effective_ratio: f64,
    /// log10 of roller crown radius / max(D/2, L_eff/2).
    crown_log: f64,
    /// Inner and outer crown radius / roller crown radius (≥ 1).
    inner_conformity: f64,
    outer_conformity: f64,
    /// Outer race spherical (P/(2 cos β) + D/2) instead of the conformity above.
    spherical_outer: bool,
    contact_angle_deg: f64,
    /// Diametral clearance / D (negative = preload).
    clearance_ratio: f64,
    /// Radial and axial load as multiples of the dynamic capacity estimate.
    radial_capacity: f64,
    axial_capacity: f64,
    /// Speed in DN (mm·rpm) and which ring(s) turn: 0 inner, 1 outer, 2 co-, 3 counter-rotating.
    dn: f64,
    rotation: u8,
    ceramic_rollers: bool,
    laminae: usize,
    estimate_only: bool,
}

fn params() -> impl Strategy<Value = Params> {
    let geometry = (
        6usize..=40,
        3.0f64..40.0,
        1.15f64..3.0,
        0.6f64..2.0,
        0.7f64..=1.0,
        0.0f64..3.0,
        1.0f64..1.2,
        1.0f64..1.2,
        any::<bool>(),
        0.0f64..=30.0,
    );
    let operation = (
        -5e-4f64..2e-3,
        prop_oneof![Just(0.0), 0.0f64..5.0],
        prop_oneof![Just(0.0), 0.0f64..5.0],
        prop_oneof![Just(0.0), 0.0f64..3.5e6],
        0u8..4,
        any::<bool>(),
        5usize..=41,
        any::<bool>(),
    );
    (geometry, operation).prop_map(|(g, o)| Params {
        roller_count: g.0,
        roller_diameter_mm: g.1,
        pitch_factor: g.2,
        length_ratio: g.3,
        effective_ratio: g.4,
        crown_log: g.5,
        inner_conformity: g.6,
        outer_conformity: g.7,
        spherical_outer: g.8,
        contact_angle_deg: g.9,
        clearance_ratio: o.0,
        radial_capacity: o.1,
        axial_capacity: o.2,
        dn: o.3,
        rotation: o.4,
        ceramic_rollers: o.5,
        laminae: o.6,
        estimate_only: o.7,
    })
}

/// The bearing of `p`, built on the aerospace example's lubricant, life and cage values.
fn bearing(p: &Params) -> Bearing {
    let mut b = Bearing::example_aerospace();
    let g = &mut b.geometry;
    let d = p.roller_diameter_mm * 1e-3;
    let z = p.roller_count;
    g.roller_count = z;
    g.roller_diameter_m = d;
    g.pitch_diameter_m = (z as f64 * d / std::f64::consts::PI).max(d) * p.pitch_factor;
    g.roller_length_m = p.length_ratio * d;
    g.effective_length_m = p.effective_ratio * g.roller_length_m;
    g.roller_crown_radius_m = (0.5 * d).max(0.5 * g.effective_length_m) * 10f64.powf(p.crown_log);
    g.inner_crown_radius_m = p.inner_conformity * g.roller_crown_radius_m;
    g.contact_angle_rad = p.contact_angle_deg.to_radians();
    g.outer_crown_radius_m = if p.spherical_outer {
        (g.pitch_diameter_m / (2.0 * g.contact_angle_rad.cos()) + 0.5 * d)
            .max(g.roller_crown_radius_m)
    } else {
        p.outer_conformity * g.roller_crown_radius_m
    };
    g.diametral_clearance_m = p.clearance_ratio * d;
    if p.ceramic_rollers {
        b.materials.roller = Material::SILICON_NITRIDE;
    }
    // Dynamic capacity estimate: Z·Q_c·cos β/(4.08·…) is not needed to this accuracy; the
    // bearing rating of a line contact is ≈ 0.378·Z·Q_c(inner)·cos β (Harris).
    let qc = raceway_capacity(Raceway::Inner, 1.0, &b.geometry.capacity_geometry());
    let c = 0.378 * z as f64 * qc * b.geometry.contact_angle_rad.cos().max(0.3);
    b.operating.radial_load_n = p.radial_capacity * c;
    b.operating.axial_load_n = p.axial_capacity * c;
    let bore_mm = (b.geometry.pitch_diameter_m - b.geometry.roller_diameter_m) * 1e3;
    let w = p.dn / bore_mm.max(1.0) * RPM;
    let (wi, wo) = match p.rotation {
        0 => (w, 0.0),
        1 => (0.0, w),
        2 => (w, 0.5 * w),
        _ => (w, -0.5 * w),
    };
    b.operating.inner_speed_rad_s = wi;
    b.operating.outer_speed_rad_s = wo;
    b.solver.laminae = p.laminae;
    if p.estimate_only {
        b.solver.dynamic_loads = DynamicLoads::Estimate;
    }
    b
}

/// The bearing as a user could write it: through the deck writer and parser, so every
/// range and cross-field rule of `deck::validate` holds. `None` if the deck is invalid
/// (a generator defect, counted).
fn valid(b: &Bearing) -> Option<Bearing> {
    sr_deck::parse(&write_bearing(b, Units::Si), "stability case")
        .ok()
        .map(|d| d.value)
}

/// JSON keys whose value may legitimately be null (Option fields): lives of an unloaded
/// raceway, films of unloaded laminae, the transient that was not requested, the static
/// safety of a bearing with no contact stress (infinite); and ISO 281's numbers (issue
/// 28), each null only with its sentence in `life.reasons` (checked in [`check`]).
const NULLABLE: [&str; 26] = [
    "basic_dynamic_rating_n",
    "basic_static_rating_n",
    "equivalent_load_n",
    "equivalent_load_factors",
    "basic_l10_mrev",
    "basic_l10_h",
    "reference_viscosity_m2_s",
    "kappa",
    "fatigue_load_limit_n",
    "a_iso",
    "modified_l10_mrev",
    "modified_l10_h",
    "infinite_life_reason",
    "l10_inner_mrev",
    "l10_outer_mrev",
    "l10_bearing_mrev",
    "l10_bearing_h",
    "adjusted_l10_inner_mrev",
    "adjusted_l10_outer_mrev",
    "adjusted_l10_bearing_mrev",
    "min_film_m",
    "inner_film_m",
    "outer_film_m",
    "transient",
    "transient_heat_w",
    "static_safety",
];

/// Every number finite and every null at a nullable key (serde_json writes NaN/inf as
/// null, so an unexpected null is how a NaN shows up). Returns the path of the first offender.
fn non_finite(v: &serde_json::Value, path: &str, key: &str) -> Option<String> {
    match v {
        serde_json::Value::Null => (!NULLABLE.contains(&key)).then(|| path.to_string()),
        serde_json::Value::Number(n) => n
            .as_f64()
            .is_none_or(|x| !x.is_finite())
            .then(|| path.to_string()),
        serde_json::Value::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(i, x)| non_finite(x, &format!("{path}[{i}]"), key)),
        serde_json::Value::Object(m) => m
            .iter()
            .find_map(|(k, x)| non_finite(x, &format!("{path}.{k}"), k)),
        _ => None,
    }
}

/// The raw Option<f64> fields behind the nullable keys must be finite when present.
fn options_finite(a: &Analysis) -> Result<(), String> {
    if let Some(l) = &a.life {
        let r = &l.result;
        for (name, x) in [
            ("l10_inner", r.l10_inner_mrev),
            ("l10_outer", r.l10_outer_mrev),
            ("l10_bearing", r.l10_bearing_mrev),
            ("l10_bearing_h", r.l10_bearing_h),
            ("adjusted_inner", r.adjusted_l10_inner_mrev),
            ("adjusted_outer", r.adjusted_l10_outer_mrev),
            ("adjusted_bearing", r.adjusted_l10_bearing_mrev),
        ] {
            if x.is_some_and(|v| !v.is_finite()) {
                return Err(format!("life {name} = {x:?}"));
            }
        }
    }
    if let Some(f) = &a.films {
        let bad = f
            .laminae
            .iter()
            .flatten()
            .flatten()
            .chain(f.min_film.iter().flatten())
            .flatten()
            .any(|h| !h.is_finite());
        if bad {
            return Err("non-finite film".into());
        }
    }
    Ok(())
}

/// What one case did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Outcome {
    Solved,
    TypedError,
}

/// The contract: Ok with residuals under tolerance and finite numbers, or a typed error.
fn check(b: &Bearing) -> Result<Outcome, String> {
    let a = match pipeline::run(b, &Request::default(), None) {
        Ok(a) => a,
        Err(_) => return Ok(Outcome::TypedError),
    };
    let ld = &a.load;
    if !ld.converged {
        return Err("Ok but not converged".into());
    }
    // Converged means converged (issue 14): the bearing and every roller residual meet the
    // deck's tolerance relative to the applied load (round-off floor aside), the same bound
    // the pipeline enforces; checked here independently of that check.
    let bound = rollbench::bearings::spherical_roller::converged::allowed_residual_n(b, ld);
    let r = &ld.residuals;
    let l_ref = 0.5 * b.geometry.effective_length_m;
    for (what, res) in [
        ("bearing axial", r.bearing_axial_n),
        ("bearing radial", r.bearing_radial_n),
        ("roller force", r.roller_force_n),
        ("roller moment / l_ref", r.roller_moment_nm / l_ref),
    ] {
        if res.is_nan() || res > bound {
            return Err(format!(
                "converged but {what} residual {res:e} N above {bound:e} N"
            ));
        }
    }
    let json = report::json::to_value(&a);
    if let Some(p) = non_finite(&json, "$", "") {
        return Err(format!("non-finite or unexpected null at {p}"));
    }
    // An absent ISO number is said: null only with a reason (rating::IsoLife's contract).
    let life = &json["life"];
    let iso_null = [
        "basic_dynamic_rating_n",
        "basic_l10_mrev",
        "a_iso",
        "modified_l10_mrev",
    ]
    .iter()
    .any(|k| life.get(k).is_some_and(|v| v.is_null()));
    if iso_null && life["reasons"].as_array().is_none_or(|r| r.is_empty()) {
        return Err(format!(
            "an ISO 281 number is null without a reason: {life}"
        ));
    }
    options_finite(&a)?;
    Ok(Outcome::Solved)
}

/// `check` with panics turned into failures (message kept).
fn check_no_panic(b: &Bearing) -> Result<Outcome, String> {
    match catch_unwind(AssertUnwindSafe(|| check(b))) {
        Ok(r) => r,
        Err(e) => {
            let msg = e
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()));
            Err(format!("panic: {}", msg.unwrap_or_default()))
        }
    }
}

proptest! {
    #![proptest_config(Config { cases: 64, ..Config::default() })]
    #[test]
    fn random_bearings_are_stable(p in params()) {
        let Some(b) = valid(&bearing(&p)) else {
            return Err(TestCaseError::reject("generator made an invalid deck"));
        };
        if let Err(e) = check_no_panic(&b) {
            return Err(TestCaseError::fail(format!("{e}\n{}", write_bearing(&b, Units::Si))));
        }
    }
}

/// 2000 cases without shrinking, all failures collected and printed with their decks.
#[test]
#[ignore = "heavy: cargo test --release --test stability random_bearings_are_stable_heavy -- --ignored --nocapture"]
fn random_bearings_are_stable_heavy() {
    let mut runner = TestRunner::new(Config {
        cases: 2000,
        ..Config::default()
    });
    let strategy = params();
    let (mut solved, mut typed, mut invalid) = (0usize, 0usize, 0usize);
    let mut failures = Vec::new();
    // Typed errors by feature, to show the solver's weak regions: (feature, errors, cases).
    let mut by_feature: Vec<(&str, usize, usize)> = Vec::new();
    let mut tally = |name: &'static str, hit: bool, err: bool| {
        if !hit {
            return;
        }
        match by_feature.iter_mut().find(|f| f.0 == name) {
            Some(f) => {
                f.1 += usize::from(err);
                f.2 += 1;
            }
            None => by_feature.push((name, usize::from(err), 1)),
        }
    };
    let mut shown = 0;
    // Typed errors by message (digits stripped), to see which stage fails.
    let mut kinds: Vec<(String, usize)> = Vec::new();
    // Slowest case (s) and its parameters: time is bounded by the iteration limits.
    let mut slowest = (0.0f64, String::new());
    for _ in 0..2000 {
        let Ok(tree) = strategy.new_tree(&mut runner) else {
            continue;
        };
        let p = tree.current();
        let Some(b) = valid(&bearing(&p)) else {
            invalid += 1;
            continue;
        };
        let t = std::time::Instant::now();
        let outcome = check_no_panic(&b);
        let dt = t.elapsed().as_secs_f64();
        if dt > slowest.0 {
            slowest = (dt, format!("{p:?}"));
        }
        let err = matches!(outcome, Ok(Outcome::TypedError));
        let speed = p.dn > 0.0;
        let loaded = p.radial_capacity > 0.0 || p.axial_capacity > 0.0;
        let load = p.radial_capacity.max(p.axial_capacity);
        tally("all", true, err);
        tally("zero speed", !speed, err);
        tally("DN > 1.5e6", p.dn > 1.5e6, err);
        tally("unloaded", !loaded, err);
        tally("unloaded at speed", !loaded && speed, err);
        tally("load > 1 C", load > 1.0, err);
        tally("0 < load < 0.1 C", loaded && load < 0.1, err);
        tally("preload", p.clearance_ratio < 0.0, err);
        tally("clearance > 1e-3 D", p.clearance_ratio > 1e-3, err);
        tally("angle < 5 deg", p.contact_angle_deg < 5.0, err);
        tally("angle > 20 deg", p.contact_angle_deg > 20.0, err);
        tally(
            "pure radial",
            p.axial_capacity == 0.0 && p.radial_capacity > 0.0,
            err,
        );
        tally(
            "pure axial",
            p.radial_capacity == 0.0 && p.axial_capacity > 0.0,
            err,
        );
        tally("crown > 100 x", p.crown_log > 2.0, err);
        tally("spherical outer", p.spherical_outer, err);
        tally("outer ring turns", p.rotation > 0, err);
        tally("App. C estimate only", p.estimate_only, err);
        tally("ceramic rollers", p.ceramic_rollers, err);
        match outcome {
            Ok(Outcome::Solved) => solved += 1,
            Ok(Outcome::TypedError) => {
                typed += 1;
                if let Err(e) = pipeline::run(&b, &Request::default(), None) {
                    let kind = format!("{e}")
                        .split(" after")
                        .next()
                        .unwrap_or("")
                        .chars()
                        .filter(|c| !c.is_ascii_digit())
                        .collect::<String>();
                    match kinds
                        .iter_mut()
                        .find(|k: &&mut (String, usize)| k.0 == kind)
                    {
                        Some(k) => k.1 += 1,
                        None => kinds.push((kind, 1)),
                    }
                    if shown < 8 && format!("{e}").starts_with("roller") {
                        shown += 1;
                        println!("typed error: {e}\n{p:?}");
                    }
                }
            }
            Err(e) => failures.push((e, write_bearing(&b, Units::Si))),
        }
    }
    for (k, n) in &kinds {
        println!("{n:5} × {k}");
    }
    for (name, e, n) in &by_feature {
        println!(
            "{name:>22}: {e:>4} typed errors of {n:>4} ({:.0} %)",
            100.0 * *e as f64 / (*n).max(1) as f64
        );
    }
    println!("slowest case: {:.1} ms\n{}", 1e3 * slowest.0, slowest.1);
    println!("stability: 2000 cases, {solved} solved, {typed} typed errors, {invalid} invalid decks, {} failures", failures.len());
    for (e, deck) in &failures {
        println!("---- {e}\n{deck}");
    }
    assert!(failures.is_empty(), "{} failures", failures.len());
}

// ---- regressions: valid bearings that end in a typed non-convergence today -------------
// Not contract violations (the error is typed), but solver robustness targets found by the
// campaign and shrunk by proptest. Ignored until the solver handles them; each asserts a
// successful solve. Run: cargo test --release --test stability regression_ -- --ignored

fn must_solve(b: &Bearing) {
    let b = valid(b).unwrap_or_else(|| panic!("regression deck is invalid"));
    if let Err(e) = pipeline::run(&b, &Request::default(), None) {
        panic!("{e}\n{}", write_bearing(&b, Units::Si));
    }
}

/// The shrunk parameters shared by the regressions (overridden per case).
fn base_params() -> Params {
    Params {
        roller_count: 6,
        roller_diameter_mm: 3.0,
        pitch_factor: 1.15,
        length_ratio: 0.6,
        effective_ratio: 0.7,
        crown_log: 0.0,
        inner_conformity: 1.0,
        outer_conformity: 1.0,
        spherical_outer: false,
        contact_angle_deg: 0.0,
        clearance_ratio: 0.0,
        radial_capacity: 0.0,
        axial_capacity: 0.0,
        dn: 0.0,
        rotation: 0,
        ceramic_rollers: false,
        laminae: 5,
        estimate_only: false,
    }
}

/// Pure radial load at rest on an angular-contact bearing (β = 14.552°, non-conforming
/// crowns): Z = 29, D = 38.113 mm, P_t = 1039.53 mm, L = 22.868 mm, L_eff = 16.007 mm,
/// crowns 952.41 (roller) / 1031.73 (inner) / 1053.0 mm (outer), zero clearance, steel,
/// Γ = 5, F_r = 360.27 kN (0.72 C), F_a = 0. Fails with "roller 1 equilibrium did not
/// converge after 60 iterations (residual 6.5e-1, tolerance 3.6e-4)"; also at F_r = 1 kN,
/// with Γ = 21, and for β = 10–14° (β = 8° fails at 100 kN); β ≤ 5° and F_a = 0.5·F_r
/// solve. The campaign's worst feature: ~70 % of pure radial cases end in a typed error.
/// Resolved as a diagnosis: with F_a = 0 the spherical outer raceway gives no axial
/// restraint and the inner ring walks off (> D/2); the solver now says so with the numbers.
#[test]
fn regression_pure_radial_at_rest_with_contact_angle() {
    let p = Params {
        roller_count: 29,
        roller_diameter_mm: 38.11254230827307,
        pitch_factor: 2.9547446752715514,
        crown_log: 1.6987844240717331,
        inner_conformity: 1.0832874763168918,
        outer_conformity: 1.1056143438598058,
        contact_angle_deg: 14.552005848855146,
        radial_capacity: 0.7234094567017523,
        ..base_params()
    };
    let b = valid(&bearing(&p)).unwrap_or_else(|| panic!("regression deck is invalid"));
    match pipeline::run(&b, &Request::default(), None) {
        Err(e) => assert!(format!("{e}").contains("axial load or preload"), "{e}"),
        Ok(_) => panic!("expected the missing-restraint diagnostic"),
    }
}

/// Found by the 2000-case campaign after the speed work (the same outcome before it): an
/// almost unloaded roller at rest (Z = 31, D = 32.5 mm, β = 5.5°, loads far beyond
/// capacity, Γ = 6) "converged" pitched 96° across its raceways, and the outer contact of
/// one lamina then had no Hertz half-width (null in the JSON). The deck is kept as
/// tests/regressions/roller_tipped_over.toml. Now a typed error that names the roller and
/// its pitch; never a non-finite output.
#[test]
fn regression_roller_tipped_over_is_a_typed_error() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/regressions/roller_tipped_over.toml"
    );
    let b = sr_deck::load(path).unwrap_or_else(|e| panic!("{e}")).value;
    match check_no_panic(&b) {
        Ok(Outcome::TypedError) => match pipeline::run(&b, &Request::default(), None) {
            Err(e) => assert!(format!("{e}").contains("pitched"), "{e}"),
            Ok(_) => unreachable!("typed error above"),
        },
        Ok(Outcome::Solved) => panic!("expected the tipped-over roller diagnostic"),
        Err(e) => panic!("{e}"),
    }
}

/// A spherical roller (crown radius = D/2 = 1.5 mm) in fully conforming raceways (crown
/// radii 1.5 mm): Z = 6, D = 3 mm, L_eff = 1.26 mm, β = 0, zero clearance, at rest, pure
/// radial 2.8 kN (2.27 C; fails from 10 N up). Pitch about the roller centre has no contact
/// stiffness (only the 1e-7 cage spring): Newton converges linearly (residual 1.2e-6 vs
/// 5e-7 after 1000 iterations). Raceway crowns of 1.6 mm solve.
#[test]
#[ignore = "solver robustness: fails today (typed RollerNotConverged)"]
fn regression_conforming_sphere_at_rest() {
    let p = Params {
        radial_capacity: 2.2693179358215456,
        ..base_params()
    };
    must_solve(&bearing(&p));
}

/// Unloaded at 1.2 million DN with clearance, β = 0, conforming crowns (crown 50.1 mm on
/// roller and raceways): Z = 6, D = 3 mm, P_t = 13.1 mm, L = 5.52 mm, L_eff = 4.50 mm,
/// clearance 5.19 µm, inner ring 119 360 rpm, Γ = 5. Fails with "roller 1 equilibrium did
/// not converge after 2 iterations (residual 45, tolerance 2.7e-7)". Persisted by proptest
/// in tests/stability.proptest-regressions (`every_valid_bearing_solves`).
#[test]
fn regression_unloaded_at_speed_conforming() {
    let p = Params {
        pitch_factor: 2.2865215163248815,
        length_ratio: 1.8412920047916337,
        effective_ratio: 0.8137890721726657,
        crown_log: 1.3482609573838493,
        clearance_ratio: 0.0017297871283576492,
        dn: 1205632.0916079418,
        ..base_params()
    };
    must_solve(&bearing(&p));
}

/// The shipped aerospace deck (US units, decks/aerospace.toml) at Γ = 41 with its own
/// tolerance 1e-9 (found by `rollbench bench`): "load distribution did not converge after
/// 100 iterations (residual 1.478e-5 N, tolerance 1.334e-5 N)" — the ring Newton stalls
/// just above tolerance. Γ = 31 and 61 converge, and so does the same bearing from
/// `Bearing::example_aerospace()` or decks/aerospace_si.toml, which differ from the US deck
/// only by unit-conversion round-off: the stall is at round-off level. Fixed: the trust
/// radius no longer grows from the uncapped Newton length after a backtracked step.
#[test]
fn regression_aerospace_41_laminae() {
    let deck = sr_deck::parse(sr_deck::DEFAULT_DECK, "aerospace.toml");
    let mut b = deck.map(|d| d.value).unwrap_or_else(|e| panic!("{e}"));
    b.solver.laminae = 41;
    assert_eq!(b.solver.force_tolerance, 1e-9);
    if let Err(e) = pipeline::run(&b, &Request::default(), None) {
        panic!("{e}");
    }
}

/// The shipped industrial deck (decks/industrial.toml: Z = 22, D = 32 mm, P_t = 300 mm,
/// β = 10°, clearance 0.12 mm, 300 rpm, F_r = 400 kN, F_a = 60 kN) at Γ = 21 or Γ = 5
/// instead of its Γ = 31, tolerance 1e-9 (found by `rollbench bench`): "roller 4
/// equilibrium did not converge after 11 iterations (residual 5.724e0, tolerance
/// 4.000e-4)" — the roller line search gives up after a few iterations. Tolerance 1e-6
/// and Γ = 7, 11, 15, 31 converge. Fixed: an out-of-contact roller's trust radius had
/// grown without bound (now ≤ 0.1·D) so one step threw it metres away.
#[test]
fn regression_industrial_21_laminae() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/decks/industrial.toml");
    let mut b = sr_deck::load(path)
        .map(|d| d.value)
        .unwrap_or_else(|e| panic!("{e}"));
    for laminae in [21, 5] {
        b.solver.laminae = laminae;
        if let Err(e) = pipeline::run(&b, &Request::default(), None) {
            panic!("Γ = {laminae}: {e}");
        }
    }
}

proptest! {
    #![proptest_config(Config { cases: 2000, ..Config::default() })]
    /// Stronger than the contract: every valid bearing should solve. Fails today (about 30 %
    /// of random bearings end in a typed non-convergence); ignored, so that proptest shrinks
    /// new failures into tests/stability.proptest-regressions for the solver work:
    /// `cargo test --release --test stability every_valid -- --ignored`.
    #[test]
    #[ignore = "solver robustness target, fails today: see the regression tests above"]
    fn every_valid_bearing_solves(p in params()) {
        let Some(b) = valid(&bearing(&p)) else {
            return Err(TestCaseError::reject("generator made an invalid deck"));
        };
        let r = pipeline::run(&b, &Request::default(), None);
        prop_assert!(
            r.is_ok(),
            "{}\n{:?}\n{}",
            r.err().map(|e| e.to_string()).unwrap_or_default(),
            p,
            write_bearing(&b, Units::Si)
        );
    }
}

/// Found by the 2000-case campaign: loads far beyond capacity (F_r = 4.7 C, F_a = 4.5 C) on
/// a ceramic-roller bearing at rest with clearance (Z = 20, D = 31.4 mm, β = 8.3°, Γ = 17).
/// Roller 3's Newton wandered for its 60 iterations while the roller pitched through
/// 150°, and the error said only "roller 3 equilibrium did not converge". It now names the
/// cause: the roller pitched beyond what the model accepts, held by neither raceway.
#[test]
fn regression_wandering_roller_is_diagnosed_as_pitched() {
    let p = Params {
        roller_count: 20,
        roller_diameter_mm: 31.448512017137357,
        pitch_factor: 2.7061413029493933,
        length_ratio: 1.5433141316277368,
        effective_ratio: 0.8573024936424176,
        crown_log: 0.05334770674890655,
        inner_conformity: 1.1723588702239325,
        outer_conformity: 1.1176567932634904,
        spherical_outer: true,
        contact_angle_deg: 8.287668722906492,
        clearance_ratio: 0.0011518191190677395,
        radial_capacity: 4.712512941558003,
        axial_capacity: 4.542357492346932,
        rotation: 1,
        ceramic_rollers: true,
        laminae: 17,
        ..base_params()
    };
    let b = valid(&bearing(&p)).unwrap_or_else(|| panic!("regression deck is invalid"));
    match check_no_panic(&b) {
        Ok(Outcome::TypedError) => match pipeline::run(&b, &Request::default(), None) {
            Err(e) => assert!(format!("{e}").contains("roller 3 pitched"), "{e}"),
            Ok(_) => unreachable!("typed error above"),
        },
        Ok(Outcome::Solved) => panic!("expected the pitched-roller diagnostic"),
        Err(e) => panic!("{e}"),
    }
}
