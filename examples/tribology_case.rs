//! The cylindrical-like radial case of issue 7's comparison with the Python `tribology`
//! package's lamina solver (`benches/tribology_compare.py` runs both and compares).
//!
//! decks/radial_si.toml made cylindrical: conforming 1 m crowns on roller and raceways (every
//! lamina at the same approach: a straight roller), zero clearance, zero speed, pure radial
//! load, Γ uniform laminae (the package slices uniformly). Prints one JSON line: the median
//! wall time of a cold `load_distribution::solve` (the lamina solver, dynamic loads zero at
//! rest), the same for the full pipeline, and the roller loads.
//!
//! `cargo run --release --example tribology_case -- [LAMINAE]` (default 21).
use rollbench::bearings::spherical_roller::deck as sr_deck;
use rollbench::bearings::spherical_roller::load_distribution::{self, DynamicSpeeds, SolveOptions};
use rollbench::bearings::spherical_roller::pipeline::{run, Request};

fn median<F: FnMut()>(n: usize, mut f: F) -> f64 {
    let mut t: Vec<f64> = (0..n)
        .map(|_| {
            let s = std::time::Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(|a, b| a.total_cmp(b));
    t[n / 2]
}

fn main() {
    let laminae: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(21);
    let mut b = sr_deck::load(concat!(env!("CARGO_MANIFEST_DIR"), "/decks/radial_si.toml"))
        .expect("deck")
        .value;
    rollbench::verify::cases::make_cylindrical_radial(&mut b, laminae);
    let speeds = DynamicSpeeds::app_c_estimate(&b);
    let solve = || load_distribution::solve(&b, &speeds, &SolveOptions::default(), None);
    let ld = solve().expect("solve");
    let t_solver = median(400, || {
        std::hint::black_box(solve().ok());
    });
    let t_pipeline = median(200, || {
        std::hint::black_box(run(&b, &Request::default(), None).ok());
    });
    let loads: Vec<String> = ld
        .rollers
        .iter()
        .map(|r| format!("{:.6}", r.inner.normal_load_n))
        .collect();
    println!(
        "{{\"laminae\": {laminae}, \"solver_median_s\": {t_solver:.4e}, \"pipeline_median_s\": {t_pipeline:.4e}, \"lamina_evaluations\": {}, \"ring_iterations\": {}, \"roller_count\": {}, \"roller_length_m\": {}, \"radial_load_n\": {}, \"loads_n\": [{}]}}",
        ld.stats.lamina_evaluations,
        ld.stats.iterations,
        b.geometry.roller_count,
        b.geometry.effective_length_m,
        b.operating.radial_load_n,
        loads.join(", ")
    );
}
