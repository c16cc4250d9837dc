//! Load distribution on each shipped deck (seed 000 §3), the full pipeline without the
//! transient on each deck (issue 7's 0.2 ms target is about that number), and the
//! cylindrical-like radial case of the comparison with the Python `tribology` package.
use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::deck::Deck;
use rollbench::solve::load_distribution::{solve, DynamicSpeeds, SolveOptions};
use rollbench::solve::pipeline::{run, Request};

fn decks() -> Vec<(String, Deck)> {
    let mut out = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/decks"))
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).collect())
        .unwrap_or_default();
    paths.sort();
    for p in paths {
        if p.extension().is_some_and(|e| e == "toml") {
            if let Ok(d) = Deck::load(&p) {
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
        let b = deck.bearing.clone();
        let s = DynamicSpeeds::app_c_estimate(&b);
        g.bench_function(&name, |bch| {
            bch.iter(|| solve(&b, &s, &SolveOptions::default(), None))
        });
    }
    g.finish();
    let mut g = c.benchmark_group("pipeline_no_transient");
    for (name, deck) in decks() {
        let b = deck.bearing.clone();
        g.bench_function(&name, |bch| bch.iter(|| run(&b, &Request::default(), None)));
    }
    g.finish();
    let mut g = c.benchmark_group("cylindrical_radial");
    if let Some((_, radial)) = decks().into_iter().find(|(n, _)| n == "radial_si") {
        for laminae in [21, 61] {
            let mut b = radial.bearing.clone();
            rollbench::validate::make_cylindrical_radial(&mut b, laminae);
            let s = DynamicSpeeds::app_c_estimate(&b);
            g.bench_function(format!("gamma_{laminae}"), |bch| {
                bch.iter(|| solve(&b, &s, &SolveOptions::default(), None))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
