//! The integrators of the cylindrical roller's 2-DOF dynamics side by side (issue 25,
//! Speed): the truck bearing, film off, 100 shaft revolutions, each run's error against
//! a DOP853 reference at rtol 1e-11 on what `bench` measures — the f_bn peak frequency,
//! the spectra's labelled peak amplitudes (x and roller load), roller 1's load
//! harmonics k·f_c and the load extrema — never x(T).
//! Usage: cargo run --release --example crb_dynamics_accuracy [rho_m] [runs]

use rollbench::bearings::cylindrical_roller::dynamics::{
    simulate_with, DynamicsModel, DynamicsResult, Integrator, LabelledSpectrum,
};
use rollbench::numerics::cancel::Cancel;
use std::time::Instant;

fn run(model: &DynamicsModel, integrator: Integrator, runs: usize) -> (DynamicsResult, f64) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let t0 = Instant::now();
        let r = simulate_with(model, integrator, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
        best = best.min(t0.elapsed().as_secs_f64());
        last = Some(r);
    }
    (last.unwrap_or_else(|| panic!("no run")), best)
}

/// Largest relative difference of the labelled peaks' amplitudes (matched by label,
/// peaks above 1e-3 of the strongest) and of their frequencies (Hz).
fn peak_errors(a: &LabelledSpectrum, r: &LabelledSpectrum) -> (f64, f64) {
    let top = r.peaks.iter().map(|p| p.amplitude).fold(0.0, f64::max);
    let (mut da, mut df) = (0.0f64, 0.0f64);
    for p in r
        .peaks
        .iter()
        .filter(|p| !p.label.is_empty() && p.amplitude > 1e-3 * top)
    {
        match a.peaks.iter().find(|q| q.label == p.label) {
            Some(q) => {
                da = da.max((q.amplitude - p.amplitude).abs() / p.amplitude);
                df = df.max((q.frequency_hz - p.frequency_hz).abs());
            }
            None => da = f64::INFINITY,
        }
    }
    (da, df)
}

fn max_load(r: &DynamicsResult) -> f64 {
    r.series
        .roller_load_n
        .iter()
        .flatten()
        .copied()
        .fold(0.0, f64::max)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let rho: f64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(5e-6);
    let runs: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(3).max(1);
    let model = DynamicsModel::truck(rho);
    let reference = DynamicsModel {
        rtol: 1e-11,
        ..model.clone()
    };
    let (r, _) = run(&reference, Integrator::Dop853, 1);
    println!(
        "reference DOP853 rtol 1e-11: {} steps, {} evaluations; f_bn {:?} Hz, W min {:.6} N, max {:.6} N",
        r.stats.steps,
        r.stats.rhs_evaluations,
        r.base_natural_frequency_hz,
        r.min_roller_load_n,
        max_load(&r)
    );
    println!(
        "{:<22} {:>8} {:>8} {:>9} {:>9} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "integrator",
        "steps",
        "rejected",
        "evals",
        "best_s",
        "d_fbn_hz",
        "x_peak_rel",
        "W_peak_rel",
        "harm_rel",
        "Wext_rel"
    );
    let mut cases = vec![("DOP853 1e-8".to_string(), Integrator::Dop853)];
    for f in [1.0, 10.0, 30.0, 100.0, 300.0] {
        cases.push((
            format!("RKN8(6) {f}x"),
            Integrator::Nystrom {
                tolerance_factor: f,
            },
        ));
    }
    for (name, integrator) in cases {
        let (a, secs) = run(&model, integrator, runs);
        let dfbn = match (a.base_natural_frequency_hz, r.base_natural_frequency_hz) {
            (Some(x), Some(y)) => (x - y).abs(),
            _ => f64::INFINITY,
        };
        let (xa, _) = peak_errors(&a.spectrum_x, &r.spectrum_x);
        let (wa, _) = peak_errors(&a.spectrum_roller_load, &r.spectrum_roller_load);
        let top = r
            .roller_load_harmonics
            .iter()
            .map(|h| h.amplitude_n)
            .fold(0.0, f64::max);
        let harm = a
            .roller_load_harmonics
            .iter()
            .zip(&r.roller_load_harmonics)
            .map(|(x, y)| (x.amplitude_n - y.amplitude_n).abs() / top)
            .fold(0.0, f64::max);
        let wmax = max_load(&r);
        let ext = ((a.min_roller_load_n - r.min_roller_load_n).abs() / wmax)
            .max((max_load(&a) - wmax).abs() / wmax);
        println!(
            "{name:<22} {:>8} {:>8} {:>9} {:>9.4} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e}",
            a.stats.steps, a.stats.rejected, a.stats.rhs_evaluations, secs, dfbn, xa, wa, harm, ext
        );
    }
}
