//! Load distribution on each shipped deck (seed 000 §3), the full pipeline without the
//! transient on each deck (issue 7's 0.2 ms target is about that number), and the
//! cylindrical-like radial case of the comparison with the Python `tribology` package, and
//! the workbench's per-edit latency by edit kind (the stage-cached pipeline re-runs only the
//! stages an edit touches).
use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::spherical_roller::deck::{self as sr_deck, Deck};
use rollbench::bearings::spherical_roller::load_distribution::{
    solve, DynamicSpeeds, SolveOptions,
};
use rollbench::bearings::spherical_roller::pipeline::{run, Pipeline, Request};

fn decks() -> Vec<(String, Deck)> {
    let mut out = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/decks"))
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).collect())
        .unwrap_or_default();
    paths.sort();
    for p in paths {
        if p.extension().is_some_and(|e| e == "toml") {
            if let Ok(d) = sr_deck::load(&p) {
                let name = p
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                out.push((name, d));
            }
        }
    }
    out
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("load_distribution");
    for (name, deck) in decks() {
        let b = deck.value.clone();
        let s = DynamicSpeeds::app_c_estimate(&b);
        g.bench_function(&name, |bch| {
            bch.iter(|| solve(&b, &s, &SolveOptions::default(), None))
        });
    }
    g.finish();
    let mut g = c.benchmark_group("pipeline_no_transient");
    for (name, deck) in decks() {
        let b = deck.value.clone();
        g.bench_function(&name, |bch| bch.iter(|| run(&b, &Request::default(), None)));
    }
    g.finish();
    let mut g = c.benchmark_group("cylindrical_radial");
    if let Some((_, radial)) = decks().into_iter().find(|(n, _)| n == "radial_si") {
        for laminae in [21, 61] {
            let mut b = radial.value.clone();
            rollbench::verify::cases::make_cylindrical_radial(&mut b, laminae);
            let s = DynamicSpeeds::app_c_estimate(&b);
            g.bench_function(format!("gamma_{laminae}"), |bch| {
                bch.iter(|| solve(&b, &s, &SolveOptions::default(), None))
            });
        }
    }
    g.finish();
}

/// Edit → results on the aerospace deck with its thermal network (steady state, no
/// transient: what the workbench computes unless the thermal pane shows the transient).
/// Each iteration flips one input between two values, so the stages it feeds re-run.
fn edit_latency(c: &mut Criterion) {
    let Some((_, deck)) = decks().into_iter().find(|(n, _)| n == "aerospace") else {
        return;
    };
    let Ok(Some(tm)) = deck.thermal_model() else {
        return;
    };
    type Edit = fn(
        &mut rollbench::bearings::spherical_roller::Bearing,
        &mut rollbench::thermal::ThermalModel,
        bool,
    );
    let edits: [(&str, Edit); 4] = [
        ("load", |b, _, f| {
            b.operating.radial_load_n *= if f { 1.05 } else { 1.0 / 1.05 }
        }),
        ("lubricant", |b, _, f| {
            b.lubricant.viscosity_pa_s *= if f { 1.05 } else { 1.0 / 1.05 }
        }),
        ("cage", |b, _, f| {
            b.cage.diametral_clearance_m *= if f { 1.05 } else { 1.0 / 1.05 }
        }),
        ("thermal", |_, t, f| {
            t.transient.duration_s *= if f { 1.05 } else { 1.0 / 1.05 }
        }),
    ];
    let mut g = c.benchmark_group("edit_latency");
    for (name, edit) in edits {
        let mut p = Pipeline::new();
        let mut b = deck.value.clone();
        let mut t = tm.clone();
        let _ = p.run(&b, Some(&t), &Request::default(), None);
        let mut flip = false;
        g.bench_function(name, |bch| {
            bch.iter(|| {
                flip = !flip;
                edit(&mut b, &mut t, flip);
                p.run(&b, Some(&t), &Request::default(), None)
            })
        });
    }
    g.finish();
}

/// Issue 31: the aerospace deck's pipeline (its default fidelity, thermal steady, no
/// transient) and each of its stages alone on the solved analysis, so the closing note can
/// say where the time goes: the load stage (coarse pre-solve, fine solve, dynamic-load
/// iteration, contact geometry, §7 speeds), the stiffness matrix every analysis carries,
/// stresses, film, life, sliding and heat (§8–9), the thermal steady state. The number of
/// loaded lamina contacts (what the friction stage's cost is per) is printed once.
fn stages(c: &mut Criterion) {
    use rollbench::bearings::spherical_roller::pipeline::run_with_thermal;
    use rollbench::bearings::spherical_roller::{contacts, stages, stiffness};
    use rollbench::thermal::{solve_steady, HeatInput, HeatSource};
    let Some((_, deck)) = decks().into_iter().find(|(n, _)| n == "aerospace") else {
        return;
    };
    let b = deck.value.clone();
    let tm = deck.thermal_model().ok().flatten();
    let req = Request::default();
    let a = run_with_thermal(&b, tm.as_ref(), &req, None).expect("aerospace solves");
    let sp = stages::internal_speeds(&b, &a.load, &a.contacts);
    let st = a.stresses.clone().expect("stresses");
    let fi = a.films.clone().expect("films");
    let fr = a.friction.clone().expect("friction");
    let loaded: usize = a
        .contacts
        .iter()
        .zip(&a.load.mirror)
        .filter(|(_, m)| m.is_none())
        .map(|(rc, _)| rc.iter().flatten().filter(|c| c.load_n > 0.0).count())
        .sum();
    eprintln!(
        "aerospace: {} laminae, {loaded} loaded lamina contacts (unique rollers), {} lamina evaluations",
        b.solver.laminae, a.load.stats.lamina_evaluations
    );
    let load_only = Request {
        contact: false,
        heat: false,
        ..Request::default()
    };
    let heat = HeatInput::new()
        .with(HeatSource::InnerContacts, fr.heat.inner_contacts_w)
        .with(HeatSource::OuterContacts, fr.heat.outer_contacts_w)
        .with(HeatSource::CageRails, fr.heat.cage_rails_w)
        .with(HeatSource::ViscousDrag, fr.heat.viscous_drag_w);
    let mut g = c.benchmark_group("stages_aerospace");
    g.bench_function("pipeline_thermal_steady", |bch| {
        bch.iter(|| run_with_thermal(&b, tm.as_ref(), &req, None))
    });
    g.bench_function("load_stage_and_stiffness", |bch| {
        bch.iter(|| run(&b, &load_only, None))
    });
    g.bench_function("stiffness", |bch| {
        bch.iter(|| stiffness::stiffness(&b, Default::default(), &a.load))
    });
    g.bench_function("contacts", |bch| {
        bch.iter(|| contacts::contacts(&b, &a.load))
    });
    g.bench_function("stresses", |bch| {
        bch.iter(|| stages::stresses(&b, &a.load, &a.contacts))
    });
    g.bench_function("films", |bch| {
        bch.iter(|| stages::films(&b, &a.contacts, &sp))
    });
    g.bench_function("life", |bch| bch.iter(|| stages::life(&b, &a.load, &fi)));
    g.bench_function("friction", |bch| {
        bch.iter(|| stages::friction(&b, &a.load, &a.contacts, &st, &fi, &sp, false))
    });
    if let Some(tm) = &tm {
        g.bench_function("thermal_steady", |bch| {
            bch.iter(|| solve_steady(&tm.network, &heat))
        });
    }
    g.finish();
}

criterion_group!(benches, bench, edit_latency, stages);
criterion_main!(benches);
