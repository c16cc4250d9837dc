//! Criterion benchmarks of the cylindrical roller bearing's 2-DOF dynamics (issue 25,
//! Speed): 100 shaft revolutions of the truck bearing (seed 003, ρ = 5 µm, rtol 1e-8)
//! with the film off (target ≤ 30 ms) and in the deflection (≤ 100 ms), ρ = 0 with the
//! film off (contact loss events), and the Hann-windowed FFT of 2^16 points (≤ 0.2 ms;
//! group `fft_2_16`, see [`fft`]). The film-off cases run on the Nyström 8(6) pair, as
//! `simulate` does; `100_rev_rho5_film_off_dop853` is the same run on DOP853 (before).
//! `100_rev_rho5_film_on` is the steady film (`Squeeze::None`, the Nyström pair);
//! `100_rev_rho5_film_on_normalised` the squeeze reading `decks/crb_truck.toml` ships
//! (the force depends on the approach rate: DOP853).

use criterion::{criterion_group, criterion_main, Criterion};
use rollbench::bearings::cylindrical_roller::dynamics::{
    simulate_with, DynamicsModel, FilmLaw, Integrator, Squeeze,
};
use rollbench::numerics::cancel::Cancel;
use rollbench::numerics::spectrum::{amplitude_spectrum, SpectrumPlan};

fn film() -> FilmLaw {
    FilmLaw {
        viscosity_pa_s: 0.0499,
        pressure_viscosity_pa_inv: 1.39e-8,
        reduced_modulus_pa: 210e9 / (1.0 - 0.09),
        reduced_radius_m: 6.35e-3 * 25e-3 / 31.35e-3,
        length_m: 0.022,
        entrainment_speed_m_s: (209.0 - 83.26) * 0.025,
        // The steady film: the seed's squeeze factor is negative damping in this model
        // (see dynamics::tests::the_seed_squeeze_law_is_negative_damping_in_this_model).
        squeeze: Squeeze::None,
    }
}

fn dynamics(c: &mut Criterion) {
    let mut g = c.benchmark_group("crb_dynamics");
    g.sample_size(10);
    let cases = [
        (
            "100_rev_rho5_film_off",
            DynamicsModel::truck(5e-6),
            Integrator::Auto,
        ),
        (
            "100_rev_rho5_film_off_dop853",
            DynamicsModel::truck(5e-6),
            Integrator::Dop853,
        ),
        (
            "100_rev_rho5_film_on",
            DynamicsModel {
                film: Some(film()),
                ..DynamicsModel::truck(5e-6)
            },
            Integrator::Auto,
        ),
        (
            "100_rev_rho5_film_on_normalised",
            DynamicsModel {
                film: Some(FilmLaw {
                    squeeze: Squeeze::Normalised,
                    ..film()
                }),
                ..DynamicsModel::truck(5e-6)
            },
            Integrator::Auto,
        ),
        (
            "100_rev_rho0_film_off",
            DynamicsModel::truck(0.0),
            Integrator::Auto,
        ),
    ];
    for (name, model, integrator) in cases {
        g.bench_function(name, |b| {
            b.iter(|| {
                simulate_with(std::hint::black_box(&model), integrator, Cancel::NONE)
                    .unwrap_or_else(|e| panic!("{e}"))
            })
        });
    }
    g.finish();
}

/// The FFT of 2^16 points (issue 25: ≤ 0.2 ms), piece by piece: `realfft_only` is the
/// planned real transform alone (input copied in, no window, no magnitudes);
/// `hann_fft_amplitude_into` the whole spectrum through a held plan into a reused
/// `Spectrum` (mean removal, Hann window from the plan's table, transform, |X_k|, bin 0
/// and Nyquist): the number the target is about; `hann_fft_amplitude` the same into a
/// fresh `Spectrum` (two 2^15-bin vectors allocated); `amplitude_spectrum_cached` the
/// one-shot function with its per-thread plan cache (what the dynamics calls).
fn fft(c: &mut Criterion) {
    let n = 1 << 16;
    let x: Vec<f64> = (0..n).map(|k| (0.1 * k as f64).sin()).collect();
    let mut g = c.benchmark_group("fft_2_16");
    let real = realfft::RealFftPlanner::<f64>::new().plan_fft_forward(n);
    let (mut input, mut output, mut scratch) = (
        real.make_input_vec(),
        real.make_output_vec(),
        real.make_scratch_vec(),
    );
    g.bench_function("realfft_only", |b| {
        b.iter(|| {
            input.copy_from_slice(std::hint::black_box(&x));
            real.process_with_scratch(&mut input, &mut output, &mut scratch)
                .unwrap_or_else(|e| panic!("{e}"));
            output[1]
        })
    });
    let mut plan = SpectrumPlan::new(n).unwrap_or_else(|e| panic!("{e}"));
    let mut spec = plan.amplitude(&x, 1e-3).unwrap_or_else(|e| panic!("{e}"));
    g.bench_function("hann_fft_amplitude_into", |b| {
        b.iter(|| {
            plan.amplitude_into(std::hint::black_box(&x), 1e-3, &mut spec)
                .unwrap_or_else(|e| panic!("{e}"));
            spec.amplitude[1]
        })
    });
    g.bench_function("hann_fft_amplitude", |b| {
        b.iter(|| {
            plan.amplitude(std::hint::black_box(&x), 1e-3)
                .unwrap_or_else(|e| panic!("{e}"))
        })
    });
    g.bench_function("amplitude_spectrum_cached", |b| {
        b.iter(|| {
            amplitude_spectrum(std::hint::black_box(&x), 1e-3).unwrap_or_else(|e| panic!("{e}"))
        })
    });
    g.finish();
}

criterion_group!(benches, dynamics, fft);
criterion_main!(benches);
