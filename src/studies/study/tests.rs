//! Issue 32's validation list: grids against `sweep`, a degenerate sample against `run`,
//! shards against the local run on every system, merge refusals, resumption, Monte Carlo
//! convergence, Latin-hypercube strata, Palmgren–Miner.

use std::path::{Path, PathBuf};

use super::file::Distribution;
use super::part::{merge, read_part, run_shard, Shard};
use super::*;
use crate::bearings::view::KeyOutput;
use crate::studies::sweep;

fn deck(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("decks")
        .join(name)
}

/// A cheap deck of every system, with the key a test grid varies and a range of five
/// values of it (deck units). The double-row deck is made cheaper (11 laminae, the measured cage
/// speed): these tests check the study machinery, not that system's numbers.
fn cheap_decks(dir: &Path) -> Vec<(&'static str, PathBuf, &'static str, &'static str)> {
    let srb = crate::bearings::load_file(&deck("srb_22308.toml"), &[]).unwrap();
    let srb = srb
        .with_values(&["solver.laminae=11".into(), "cage.speed=measured".into()])
        .unwrap();
    let srb_path = dir.join("srb_cheap.toml");
    std::fs::write(&srb_path, srb.text()).unwrap();
    vec![
        (
            "spherical-roller",
            deck("radial_si.toml"),
            "operating.radial_load",
            "10000:30000:x5",
        ),
        (
            "angular-contact-ball",
            deck("chen_b.toml"),
            "operating.radial_load",
            "0:400:x5",
        ),
        (
            "tapered-roller",
            deck("trb_afapl.toml"),
            "operating.radial_load",
            "0:1000:x5",
        ),
        (
            "cylindrical-roller",
            deck("crb_nasa210.toml"),
            "operating.radial_load",
            "1000:5000:x5",
        ),
        (
            "double-row-spherical-roller",
            srb_path,
            "operating.radial_load",
            "8000:16000:x5",
        ),
    ]
}

/// Writes a study file into `dir` and prepares it.
fn study(dir: &Path, name: &str, text: &str) -> Prepared {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    prepare(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn toml_path(p: &Path) -> String {
    p.display().to_string().replace('\\', "/")
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

#[test]
fn grid_of_one_key_equals_sweep_row_for_row() {
    // The same key over the same values, study grid against `rollbench sweep --cold`
    // (both solve each point from the deck's own initial guess, so the answers must agree
    // to rounding: 1e-12 relative, the bound).
    let dir = tempfile::tempdir().unwrap();
    for (system, deck, key, range) in cheap_decks(dir.path()) {
        let s = study(
            dir.path(),
            "g.study.toml",
            &format!(
                "deck = \"{}\"\n[grid]\n\"{key}\" = \"{range}\"\n",
                toml_path(&deck)
            ),
        );
        let r = s.run(false);
        assert_eq!(r.failures(), 0, "{system}: {:?}", r.rows);
        let case = crate::bearings::load_file(&deck, &[]).unwrap();
        let sw = sweep::run(
            case.as_ref(),
            &format!("{key}={range}"),
            false,
            sweep::Start::Cold,
        )
        .unwrap();
        assert_eq!(r.rows.len(), sw.points.len(), "{system}");
        for (row, p) in r.rows.iter().zip(&sw.points) {
            assert_eq!(row.inputs[0], p.text, "{system}");
            assert_eq!(
                row.failure.is_some(),
                p.failure.is_some(),
                "{system}: {:?} {:?}",
                row.failure,
                p.failure
            );
            for (name, v) in r.header.outputs.iter().zip(&row.outputs) {
                match (v, p.output(name)) {
                    (Some(a), Some(b)) => {
                        assert!(close(*a, b, 1e-12), "{system} {name}: {a} vs {b}")
                    }
                    (a, b) => assert_eq!(*a, b.filter(|x| x.is_finite()), "{system} {name}"),
                }
            }
        }
    }
}

#[test]
fn sample_of_one_with_zero_sigma_equals_run() {
    // σ = 0: the one point is the mean, written as the deck has it; its outputs are the
    // deck's own (`run`), bit for bit.
    let dir = tempfile::tempdir().unwrap();
    let deck = deck("chen_b.toml");
    let s = study(
        dir.path(),
        "s.study.toml",
        &format!(
            "deck = \"{}\"\n[sample]\nsamples = 1\nseed = 3\noperating.axial_load = {{ normal = [1000.0, 0.0] }}\n",
            toml_path(&deck)
        ),
    );
    let r = s.run(false);
    let case = crate::bearings::load_file(&deck, &[]).unwrap();
    let run: Vec<KeyOutput> = case
        .solve(
            RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .unwrap()
        .view()
        .key_outputs;
    assert_eq!(r.rows[0].inputs, vec!["1000".to_string()]);
    assert_eq!(r.header.outputs.len(), run.len());
    for (name, v) in r.header.outputs.iter().zip(&r.rows[0].outputs) {
        let want = run.iter().find(|k| k.name == name).and_then(|k| k.value);
        assert_eq!(*v, want, "{name}");
    }
}

/// The CSV of merging shards I/N, I = 0…N−1, each run into its own part.
fn sharded_csv(s: &Prepared, dir: &Path, n: usize) -> String {
    let mut parts = Vec::new();
    for i in 0..n {
        let path = dir.join(format!("part-{i}-of-{n}.jsonl"));
        run_shard(s, Shard { index: i, count: n }, &path, &|| {}).unwrap();
        parts.push((
            path.display().to_string(),
            std::fs::read_to_string(&path).unwrap(),
        ));
    }
    // Merge order must not matter: give them reversed.
    parts.reverse();
    output::csv(&merge(&parts).unwrap())
}

#[test]
fn sharded_equals_unsharded_on_every_system() {
    // N = 1, 3, 7 over five points (N = 7 leaves two shards empty): the merged CSV is
    // byte-identical to the local run's, on every system.
    let dir = tempfile::tempdir().unwrap();
    for (system, deck, key, values) in cheap_decks(dir.path()) {
        let s = study(
            dir.path(),
            "sh.study.toml",
            &format!(
                "deck = \"{}\"\n[grid]\n\"{key}\" = \"{values}\"\n",
                toml_path(&deck)
            ),
        );
        let whole = s.run(false);
        // Every point solves: the comparison is of numbers, not of failure messages.
        assert_eq!(whole.failures(), 0, "{system}: {:?}", whole.rows);
        let local = output::csv(&whole);
        assert_eq!(local.lines().count(), 6, "{system}");
        let parts = dir.path().join(system);
        std::fs::create_dir(&parts).unwrap();
        for n in [1, 3, 7] {
            assert_eq!(sharded_csv(&s, &parts, n), local, "{system}: N = {n}");
        }
    }
}

/// A synthetic part: header of a study of `points` points with hash `hash`, and rows.
fn part_text(hash: &str, shard: &str, points: usize, indices: &[usize]) -> String {
    let h = Header {
        format: PART_FORMAT.into(),
        study_hash: hash.into(),
        study: "x.study.toml".into(),
        deck: "d".into(),
        system: "tapered-roller".into(),
        design: "grid".into(),
        points,
        shard: Some(shard.into()),
        inputs: vec!["operating.radial_load".into()],
        input_units: vec!["N".into()],
        outputs: vec!["l10_bearing_mrev".into()],
        duty: None,
        version: "0".into(),
    };
    let mut t = output::header_line(&h);
    for &i in indices {
        t.push_str(&output::row_line(&Row {
            index: i,
            inputs: vec![format!("{}", 1000 * i)],
            outputs: vec![Some(1.5 * i as f64)],
            failure: None,
        }));
    }
    t
}

#[test]
fn merge_refuses_missing_duplicate_and_foreign_parts_naming_them() {
    let a = (
        "part-0.jsonl".to_string(),
        part_text("aaaa", "0/2", 4, &[0, 2]),
    );
    let b = (
        "part-1.jsonl".to_string(),
        part_text("aaaa", "1/2", 4, &[1, 3]),
    );
    assert_eq!(merge(&[a.clone(), b.clone()]).unwrap().rows.len(), 4);
    let e = merge(std::slice::from_ref(&a)).unwrap_err();
    assert!(e.contains("2 of 4 indices are missing: 1, 3"), "{e}");
    let e = merge(&[a.clone(), b.clone(), a.clone()]).unwrap_err();
    assert!(
        e.contains("index 0 is present twice: in part-0.jsonl and in part-0.jsonl"),
        "{e}"
    );
    let c = (
        "other.jsonl".to_string(),
        part_text("bbbb", "1/2", 4, &[1, 3]),
    );
    let e = merge(&[a.clone(), c]).unwrap_err();
    assert!(
        e.contains("other.jsonl is a part of another study: hash bbbb")
            && e.contains("part-0.jsonl has aaaa"),
        "{e}"
    );
    let torn = ("torn.jsonl".to_string(), b.1[..b.1.len() - 5].to_string());
    let e = merge(&[a.clone(), torn]).unwrap_err();
    assert!(e.contains("torn.jsonl:3: the part is incomplete"), "{e}");
    let e = merge(&[("x.csv".to_string(), "index,a\n".to_string())]).unwrap_err();
    assert!(e.contains("x.csv is not a rollbench study part"), "{e}");
}

#[test]
fn a_killed_shard_resumes_to_the_same_part() {
    let dir = tempfile::tempdir().unwrap();
    let s = study(
        dir.path(),
        "r.study.toml",
        &format!(
            "deck = \"{}\"\n[grid]\noperating.radial_load = \"0:800:x9\"\noperating.axial_load = [3000, 3500]\n",
            toml_path(&deck("trb_afapl.toml"))
        ),
    );
    let shard = Shard { index: 1, count: 2 };
    let path = dir.path().join("part.jsonl");
    let first = run_shard(&s, shard, &path, &|| {}).unwrap();
    assert_eq!((first.points, first.kept, first.computed), (9, 0, 9));
    let whole = std::fs::read_to_string(&path).unwrap();
    // A kill after four rows, in the middle of the fifth: the journal's rows are in
    // completion order, so keep rows out of order too (second, fourth…) to be sure.
    let lines: Vec<&str> = whole.lines().collect();
    let mut cut = format!("{}\n", lines[0]);
    for l in [lines[5], lines[2], lines[8], lines[1]] {
        cut.push_str(l);
        cut.push('\n');
    }
    cut.push_str(&lines[3][..lines[3].len() / 2]);
    std::fs::write(&path, &cut).unwrap();
    let again = run_shard(&s, shard, &path, &|| {}).unwrap();
    assert_eq!((again.kept, again.computed), (4, 5));
    assert!(again.discarded_torn_line);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), whole);
    // A finished part re-run computes nothing and stays the same.
    let done = run_shard(&s, shard, &path, &|| {}).unwrap();
    assert_eq!((done.kept, done.computed), (9, 0));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), whole);
    // Another shard's part, or another study's, is refused and left alone.
    let e = run_shard(&s, Shard { index: 0, count: 2 }, &path, &|| {}).unwrap_err();
    assert!(e.contains("is shard 1/2 of this study, not 0/2"), "{e}");
    let p = read_part(&whole, "part").unwrap();
    assert_eq!(p.rows.len(), 9);
    assert!(p.rows.windows(2).all(|w| w[0].index < w[1].index));
}

/// Sample means and standard deviations of the plan's values of key `k`.
fn moments(plan: &Plan, n: usize, k: usize) -> (f64, f64) {
    let v: Vec<f64> = (0..n).map(|i| plan.sample_values(i)[k]).collect();
    let m = v.iter().sum::<f64>() / n as f64;
    let s = (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
    (m, s)
}

fn sample_plan(text: &str) -> Plan {
    Plan::new(&file::parse(text, Path::new("t.study.toml")).unwrap())
}

#[test]
fn monte_carlo_mean_and_sigma_converge_at_one_over_root_n() {
    // The sampled input itself is the linear output (what a deck echoes): its sample mean
    // is within 4 σ/√n of the mean and its sample σ within 4 σ/√(2n) of σ (the standard
    // errors of a normal sample), at every n from 10² to 10⁵. Each bound fails with
    // probability ≈ 6e-5 for a fair generator; the seed makes the test repeatable, and a
    // generator or Φ⁻¹ with a bias of more than a few standard errors at 10⁵ fails it.
    // The truncated-normal and uniform bands are checked against their exact moments:
    // Var = σ²(1 − 2kφ(k)/(2Φ(k) − 1)) for a normal truncated at ±kσ, band²/3 for uniform.
    let plan = sample_plan(
        "deck = \"d.toml\"\nmax_points = 100000\n[sample]\nsamples = 100000\nseed = 11\n\
         a = { normal = [5.0, 2.0] }\n\
         b = { tolerance = [1.0, 0.3], shape = \"truncated-normal\" }\n\
         c = { tolerance = [-2.0, 0.5] }\n",
    );
    let k = 3.0_f64;
    let phi = (-0.5 * k * k).exp() / (2.0 * std::f64::consts::PI).sqrt();
    let trunc_sd = 0.1 * (1.0 - 2.0 * k * phi / (2.0 * random::normal_cdf(k) - 1.0)).sqrt();
    let uniform_sd = 0.5 / 3f64.sqrt();
    for (key, mean, sd) in [(0, 5.0, 2.0), (1, 1.0, trunc_sd), (2, -2.0, uniform_sd)] {
        let mut errors = Vec::new();
        for n in [100, 1000, 10_000, 100_000] {
            let (m, s) = moments(&plan, n, key);
            let se = sd / (n as f64).sqrt();
            assert!(
                (m - mean).abs() < 4.0 * se,
                "key {key}, n {n}: mean {m} vs {mean} (se {se})"
            );
            assert!(
                (s - sd).abs() < 4.0 * sd / (2.0 * n as f64).sqrt() + 1e-15,
                "key {key}, n {n}: σ {s} vs {sd}"
            );
            errors.push((m - mean).abs());
        }
        // 1/√n: the error at 10⁵ is far below the error bound at 10².
        assert!(
            errors[3] < 4.0 * sd / 100f64.sqrt() / 10.0,
            "key {key}: {errors:?}"
        );
    }
    // Bands stay inside their tolerance.
    for i in 0..2000 {
        let v = plan.sample_values(i);
        assert!(
            (v[1] - 1.0).abs() <= 0.3 && (v[2] + 2.0).abs() <= 0.5,
            "{v:?}"
        );
    }
}

#[test]
fn latin_hypercube_hits_each_stratum_once() {
    let n = 1000;
    let plan = sample_plan(&format!(
        "deck = \"d.toml\"\n[sample]\nmethod = \"latin-hypercube\"\nsamples = {n}\nseed = 5\n\
         x = {{ uniform = [0.0, 1.0] }}\ny = {{ uniform = [0.0, 1.0] }}\nz = {{ normal = [0.0, 1.0] }}\n"
    ));
    for key in 0..3 {
        let mut hit = vec![0; n];
        for i in 0..n {
            let v = plan.sample_values(i)[key];
            let u = if key == 2 { random::normal_cdf(v) } else { v };
            hit[((u * n as f64).floor() as usize).min(n - 1)] += 1;
        }
        assert!(
            hit.iter().all(|&h| h == 1),
            "key {key}: strata hit {:?}",
            hit.iter().filter(|&&h| h != 1).count()
        );
    }
    // Each point is a pure function of (seed, index): recomputed alone, the same.
    let again = sample_plan(&format!(
        "deck = \"d.toml\"\n[sample]\nmethod = \"latin-hypercube\"\nsamples = {n}\nseed = 5\n\
         x = {{ uniform = [0.0, 1.0] }}\ny = {{ uniform = [0.0, 1.0] }}\nz = {{ normal = [0.0, 1.0] }}\n"
    ));
    assert_eq!(plan.point(417), again.point(417));
}

#[test]
fn duty_of_two_equal_halves_is_the_single_case_life() {
    // 1/(½/L + ½/L) = L: exact in binary but for the two reciprocals (1 ulp each).
    let dir = tempfile::tempdir().unwrap();
    let deck = deck("crb_nasa210.toml");
    let s = study(
        dir.path(),
        "d.study.toml",
        &format!(
            "deck = \"{}\"\n[duty]\nlife = \"l10_bearing_mrev\"\ncases = [\n\
             {{ share = 0.5, set = {{ operating.radial_load = 3000.0 }} }},\n\
             {{ share = 0.5, set = {{ operating.radial_load = 3000.0 }} }},\n]\n",
            toml_path(&deck)
        ),
    );
    let r = s.run(false);
    let single = crate::bearings::load_file(&deck, &["operating.radial_load=3000".into()])
        .unwrap()
        .solve(
            RunOptions {
                skip_transient: true,
            },
            Cancel::NONE,
        )
        .unwrap()
        .view()
        .key_outputs
        .iter()
        .find(|k| k.name == "l10_bearing_mrev")
        .and_then(|k| k.value)
        .unwrap();
    let life = summary::duty(&r.header, &r.rows).unwrap().life.unwrap();
    assert!(
        close(life, single, 4.0 * f64::EPSILON),
        "{life} vs {single}"
    );
}

#[test]
fn palmgren_miner_by_hand_on_three_cases() {
    // Shares ½, 0.3, 0.2 at lives 100, 50, 20: 1/L = 0.005 + 0.006 + 0.01 = 0.021,
    // L = 47.619…; mean power 0.5·10 + 0.3·20 + 0.2·40 = 19.
    let header = Header {
        format: PART_FORMAT.into(),
        study_hash: "h".into(),
        study: "s".into(),
        deck: "d".into(),
        system: "x".into(),
        design: "duty".into(),
        points: 3,
        shard: None,
        inputs: vec![],
        input_units: vec![],
        outputs: vec!["life".into(), "power".into()],
        duty: Some(DutyMeta {
            shares: vec![0.5, 0.3, 0.2],
            life: "life".into(),
            power: Some("power".into()),
        }),
        version: "0".into(),
    };
    let row = |i: usize, l: f64, p: f64| Row {
        index: i,
        inputs: vec![],
        outputs: vec![Some(l), Some(p)],
        failure: None,
    };
    let rows = vec![row(0, 100.0, 10.0), row(1, 50.0, 20.0), row(2, 20.0, 40.0)];
    let d = summary::duty(&header, &rows).unwrap();
    assert!(close(d.life.unwrap(), 1.0 / 0.021, 1e-15));
    assert!(close(d.power.unwrap().unwrap(), 19.0, 1e-15));
    // A failed case: no combined life, saying which case.
    let mut failed = rows.clone();
    failed[1].outputs = vec![None, None];
    failed[1].failure = Some("no equilibrium".into());
    let e = summary::duty(&header, &failed).unwrap().life.unwrap_err();
    assert!(e.contains("case 1 has no life (no equilibrium)"), "{e}");
}

#[test]
fn study_file_refusals_name_field_and_line() {
    let err = |text: &str| -> String {
        file::parse(text, Path::new("s.study.toml"))
            .unwrap_err()
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n")
    };
    let e = err("deck = \"d.toml\"\nsamples = 3\n[grid]\na = [1, 2]\n");
    assert!(e.contains("s.study.toml:2:1: unknown key `samples`"), "{e}");
    let e = err(
        "deck = \"d.toml\"\n[grid]\na = [1]\n[duty]\nlife = \"l\"\ncases = [{ share = 1.0 }]\n",
    );
    assert!(
        e.contains("exactly one of [grid], [sample] or [duty]"),
        "{e}"
    );
    let e = err("deck = \"d.toml\"\n[grid]\na = \"1:100:1\"\nb = \"1:200:1\"\n");
    assert!(
        e.contains("20000 points (a (100) × b (200)) is more than max_points = 10000"),
        "{e}"
    );
    let e = err("deck = \"d.toml\"\n[sample]\nsamples = 10\nx = { normal = [1, 2], sigma = 3 }\n");
    assert!(
        e.contains("s.study.toml:4:") && e.contains("unknown key `sample.x.sigma`"),
        "{e}"
    );
    let e = err(
        "deck = \"d.toml\"\n[duty]\nlife = \"l\"\ncases = [{ share = 0.5 }, { share = 0.4 }]\n",
    );
    assert!(
        e.contains("s.study.toml:4:") && e.contains("the shares sum to 0.9"),
        "{e}"
    );
    let e = err(
        "deck = \"d.toml\"\n[sample]\nmethod = \"sobol\"\nsamples = 3\nx = { uniform = [0, 1] }\n",
    );
    assert!(
        e.contains("s.study.toml:3:10: sample.method = \"sobol\""),
        "{e}"
    );
    // Quoted and dotted keys are the same deck key.
    let f = file::parse(
        "deck = \"d.toml\"\n[grid]\n\"operating.inner_speed\" = [1]\noperating.radial_load = [2, 3]\n",
        Path::new("s.study.toml"),
    )
    .unwrap();
    let Design::Grid(axes) = f.design else {
        panic!()
    };
    assert_eq!(axes[0].key, "operating.inner_speed");
    assert_eq!(axes[1].key, "operating.radial_load");
}

#[test]
fn unknown_deck_keys_and_outputs_are_refused_before_solving_points() {
    let dir = tempfile::tempdir().unwrap();
    let d = toml_path(&deck("trb_afapl.toml"));
    let write = |text: String| {
        let p = dir.path().join("u.study.toml");
        std::fs::write(&p, text).unwrap();
        prepare(&p).err().unwrap()
    };
    let e = write(format!(
        "deck = \"{d}\"\n[grid]\noperating.radial_lod = [1, 2]\n"
    ));
    assert!(
        e.contains("operating.radial_lod") && e.contains("operating.radial_load"),
        "{e}"
    );
    let e = write(format!(
        "deck = \"{d}\"\noutputs = [\"l10_life\"]\n[grid]\noperating.radial_load = [1, 2]\n"
    ));
    assert!(
        e.contains("`l10_life` is not a key output") && e.contains("l10_bearing_mrev"),
        "{e}"
    );
    let e = write(format!(
        "deck = \"{d}\"\noutputs = [\"/no/such\"]\n[grid]\noperating.radial_load = [1, 2]\n"
    ));
    assert!(
        e.contains("`/no/such` is not a number in the deck's JSON report"),
        "{e}"
    );
}

#[test]
fn grid_points_run_last_key_fastest_and_a_refused_value_is_a_row() {
    let dir = tempfile::tempdir().unwrap();
    let s = study(
        dir.path(),
        "o.study.toml",
        &format!(
            "deck = \"{}\"\noutputs = [\"l10_bearing_mrev\"]\n[grid]\noperating.axial_load = [9000, 10000]\noperating.radial_load = [20000, -5]\n",
            toml_path(&deck("trb_afapl.toml"))
        ),
    );
    let inputs: Vec<Vec<String>> = (0..4)
        .map(|i| s.plan.point(i).into_iter().flatten().collect())
        .collect();
    assert_eq!(inputs[1], ["9000", "-5"]);
    assert_eq!(inputs[2], ["10000", "20000"]);
    let r = s.run(false);
    assert!(r.rows[0].failure.is_none());
    let f = r.rows[1].failure.as_deref().unwrap();
    assert!(
        f.contains("operating.radial_load") && f.contains("out of range"),
        "{f}"
    );
    // The failed row keeps its cells: the CSV has the same columns on every row.
    let csv = output::csv(&r);
    assert!(
        csv.lines()
            .all(|l| l.starts_with("index") || l.split(',').count() >= 5),
        "{csv}"
    );
}

#[test]
fn shard_specs_from_the_command_line_and_the_schedulers() {
    let none = |_: &str| None;
    assert_eq!(
        Shard::parse("2/7", None, &none).unwrap(),
        Shard { index: 2, count: 7 }
    );
    assert!(Shard::parse("7/7", None, &none)
        .unwrap_err()
        .contains("0 ≤ I < N"));
    assert!(Shard::parse("auto", None, &none)
        .unwrap_err()
        .contains("neither SLURM_ARRAY_TASK_ID"));
    let slurm = |k: &str| match k {
        "SLURM_ARRAY_TASK_ID" => Some("4".to_string()),
        "SLURM_ARRAY_TASK_MIN" => Some("1".to_string()),
        "SLURM_ARRAY_TASK_COUNT" => Some("4".to_string()),
        _ => None,
    };
    assert_eq!(
        Shard::parse("auto", None, &slurm).unwrap(),
        Shard { index: 3, count: 4 }
    );
    let k8s = |k: &str| (k == "JOB_COMPLETION_INDEX").then(|| "0".to_string());
    assert!(Shard::parse("auto", None, &k8s)
        .unwrap_err()
        .contains("--shards N"));
    assert_eq!(
        Shard::parse("auto", Some(5), &k8s).unwrap(),
        Shard { index: 0, count: 5 }
    );
    assert_eq!(Shard { index: 1, count: 3 }.indices(8), vec![1, 4, 7]);
}

#[test]
fn distributions_map_probabilities_to_values() {
    let n = Distribution::Normal {
        mean: 10.0,
        sigma: 2.0,
    };
    assert!(close(
        n.quantile(0.975),
        10.0 + 2.0 * 1.959_963_984_540_054,
        1e-14
    ));
    let u = Distribution::Uniform { lo: 1.0, hi: 3.0 };
    assert_eq!(u.quantile(0.25), 1.5);
}
