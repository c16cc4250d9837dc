//! Full pipeline (no transient) on each shipped deck at the deck's default fidelity and at
//! the recommended one (cheapest grid cell with max-stress and L-10 errors below 0.1 % and
//! the other key outputs within 1 %, from `rollbench::verify::fidelity::measure_grid`, measured once
//! in the set-up).
use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::deck::Deck;
use rollbench::verify::fidelity::{self, Fidelity};

fn decks() -> Vec<(String, Deck)> {
    let mut paths: Vec<_> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/decks"))
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).collect())
        .unwrap_or_default();
    paths.sort();
    paths
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .filter_map(|p| {
            let name = p
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            Deck::load(&p).ok().map(|d| (name, d))
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("pipeline_fidelity");
    for (name, deck) in decks() {
        let thermal = deck.thermal_model().ok().flatten();
        let b = deck.bearing.clone();
        let default = Fidelity::of(&b);
        let mut points = vec![("default", default)];
        if let Some(r) = fidelity::measure_grid(&name, &b, thermal.as_ref())
            .ok()
            .and_then(|t| t.recommended)
        {
            points.push((
                "recommended",
                Fidelity {
                    laminae: r.laminae,
                    tolerance: r.tolerance,
                },
            ));
        }
        for (label, f) in points {
            let bf = f.apply(&b);
            let id = format!("{name}/{label}/G{}_tol{:.0e}", f.laminae, f.tolerance);
            g.bench_function(&id, |bch| {
                bch.iter(|| fidelity::run_once(&bf, thermal.as_ref()))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
