//! Full solve (no transient) of each shipped deck whose bearing system has a fidelity study,
//! at the deck's default fidelity and at the recommended one (cheapest grid cell with the
//! target key outputs within 0.1 % and the other key outputs within 1 %, from
//! `rollbench::studies::fidelity::measure_grid`, measured once in the set-up).
use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::{self, Case};
use rollbench::studies::fidelity;

fn decks() -> Vec<(String, Box<dyn Case>)> {
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
            bearings::load_file(&p, &[]).ok().map(|c| (name, c))
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("pipeline_fidelity");
    for (name, case) in decks() {
        let (Some(grid), Some(default)) = (case.system().fidelity_grid(), case.fidelity()) else {
            continue;
        };
        let mut points = vec![("default", default)];
        if let Some(r) = fidelity::measure_grid(&name, &*case)
            .ok()
            .and_then(|t| t.recommended)
        {
            points.push(("recommended", r.fidelity));
        }
        for (label, f) in points {
            let Some(at) = case.with_fidelity(f) else {
                continue;
            };
            // The spherical roller's ids keep their names ("G81_tol1e-9").
            let sym = if grid.resolution_key == "laminae" {
                "G"
            } else {
                "n"
            };
            let id = format!(
                "{name}/{label}/{sym}{}_tol{:.0e}",
                f.resolution, f.tolerance
            );
            g.bench_function(&id, |bch| bch.iter(|| fidelity::run_once(&*at)));
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
