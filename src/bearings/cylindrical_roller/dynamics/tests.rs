//! Validation of the 2-DOF dynamics (issue 25, Validation 2–4) and its guards.

use super::*;
use film::ContactLaw;
use std::cell::Cell;
use std::sync::atomic::AtomicBool;

fn frozen(interference_m: f64, duration_s: f64) -> DynamicsModel {
    DynamicsModel {
        cage_speed_rad_s: 0.0,
        span: Span::Duration {
            duration_s,
            settle_s: 0.0,
        },
        ..DynamicsModel::truck(interference_m)
    }
}

fn truck_film(squeeze: Squeeze) -> FilmLaw {
    FilmLaw {
        viscosity_pa_s: 0.0499,
        pressure_viscosity_pa_inv: 1.39e-8,
        reduced_modulus_pa: 210e9 / (1.0 - 0.09),
        reduced_radius_m: 6.35e-3 * 25e-3 / 31.35e-3,
        length_m: 0.022,
        entrainment_speed_m_s: (209.0 - 83.26) * 0.025,
        squeeze,
    }
}

#[test]
fn linearisation_small_release_rings_at_the_linearised_frequency() {
    // Validation 2: cage frozen, released from the static offset displaced by 1e-3 of
    // it along x. 2 s of record: bins of 0.5 Hz; the peak must sit within one bin and
    // 0.5 % of √(K/M)/2π (the release's amplitude shifts the frequency by O(1e-6)).
    let mut model = frozen(5e-6, 2.0);
    let probe = simulate(
        &DynamicsModel {
            span: Span::Duration {
                duration_s: 0.05,
                settle_s: 0.0,
            },
            ..model.clone()
        },
        Cancel::NONE,
    )
    .unwrap();
    let r = probe.static_offset_m;
    model.initial_state = [r[0] * 1.001, r[1], 0.0, 0.0];
    let res = simulate(&model, Cancel::NONE).unwrap();
    let f_lin = res.linearised_frequency_hz;
    let f_fft = res.base_natural_frequency_hz.unwrap();
    let bin = 1.0 / 2.0;
    eprintln!(
        "linearised {f_lin:.4} Hz, FFT peak {f_fft:.4} Hz, K {:?}",
        res.stiffness_n_per_m
    );
    assert!((f_fft - f_lin).abs() <= bin, "{f_fft} vs {f_lin}");
    assert!((f_fft / f_lin - 1.0).abs() <= 5e-3);
    assert!(!res.loss_of_contact);
}

#[test]
fn energy_is_conserved_with_the_cage_frozen_through_contact_loss() {
    // Validation 3a: film off, cage frozen, ρ = 0 (the kinks of δ₊^(10/9) every
    // half-period: events at every loss and regain), released at rest from x = y = 0:
    // E = ½M|v|² + Σ2k δ₊^(n+1)/(n+1) − F·r drifts < 1e-7 of |F·r_s| + V(r_s) over 1 s.
    let model = DynamicsModel {
        rtol: 1e-11,
        ..frozen(0.0, 1.0)
    };
    let res = simulate(&model, Cancel::NONE).unwrap();
    let drift = res.energy_drift_rel.unwrap();
    eprintln!("frozen drift {drift:.3e}, stats {:?}", res.stats);
    assert!(res.stats.events > 0, "contact loss and regain are events");
    assert!(drift < 1e-7, "{drift}");
}

#[test]
fn energy_balance_with_a_turning_cage() {
    // Validation 3b: cage turning, ρ = 0, film off: E(t) − E(0) = ∫∂V/∂t dt (the
    // potential moves with the rollers) to 1e-6 of the static energy scale over 1 s.
    let model = DynamicsModel {
        rtol: 1e-10,
        span: Span::Duration {
            duration_s: 1.0,
            settle_s: 0.2,
        },
        ..DynamicsModel::truck(0.0)
    };
    let res = simulate(&model, Cancel::NONE).unwrap();
    let drift = res.energy_drift_rel.unwrap();
    eprintln!("turning drift {drift:.3e}, stats {:?}", res.stats);
    assert!(drift < 1e-6, "{drift}");
}

fn harmonic(res: &DynamicsResult, k: usize) -> f64 {
    res.roller_load_harmonics[k - 1].amplitude_n
}

fn line(spec: &LabelledSpectrum, label: &str) -> f64 {
    spec.peaks
        .iter()
        .filter(|p| p.label == label)
        .map(|p| p.amplitude)
        .fold(0.0, f64::max)
}

#[test]
fn spectra_as_the_seed_describes_them() {
    // Validation 4 (seed 003 Figs. 3–5), truck bearing, film off, 100 revolutions, the
    // last 80 sampled over whole cage cycles; roller-load harmonics by projection.
    let tight = simulate(&DynamicsModel::truck(5e-6), Cancel::NONE).unwrap();
    let loose = simulate(&DynamicsModel::truck(0.0), Cancel::NONE).unwrap();
    for (name, r) in [("rho 5 um", &tight), ("rho 0", &loose)] {
        let h: Vec<String> = r
            .roller_load_harmonics
            .iter()
            .map(|h| format!("{}:{:.2}", h.order, h.amplitude_n))
            .collect();
        eprintln!(
            "{name}: f_bn {:?} lin {:.2} min W {:.1} loss {} stats {:?}\n  harmonics {}\n  x peaks {:?}\n  W peaks {:?}",
            r.base_natural_frequency_hz,
            r.linearised_frequency_hz,
            r.min_roller_load_n,
            r.loss_of_contact,
            r.stats,
            h.join(" "),
            r.spectrum_x
                .peaks
                .iter()
                .map(|p| format!("{:.2}Hz {:.3e} {}", p.frequency_hz, p.amplitude, p.label))
                .collect::<Vec<_>>(),
            r.spectrum_roller_load
                .peaks
                .iter()
                .map(|p| format!("{:.2}Hz {:.3e} {}", p.frequency_hz, p.amplitude, p.label))
                .collect::<Vec<_>>(),
        );
    }
    // f_c = 83.26/2π = 13.251 Hz.
    assert!((tight.cage_frequency_hz - 13.251).abs() < 1e-3);
    // The roller load shows f_c and f_bn ± f_c (both cases).
    for r in [&tight, &loose] {
        for label in ["f_c", "f_bn-f_c", "f_bn+f_c"] {
            assert!(line(&r.spectrum_roller_load, label) > 0.0, "{label}");
        }
    }
    // ρ = 5 µm: the seed's "only the second harmonic of cage frequency is noted". The
    // model as specified gives 2f_c at 0.50 % of f_c (1.65 N of 331.7 N; SciPy DOP853 on
    // the same model: 1.652 of 331.708), not above 1 %: the line is there and is the only
    // cage harmonic above 0.1 %, but weaker than the threshold. Not bent to fit
    // (see the closing note); pinned here as measured.
    let a1 = harmonic(&tight, 1);
    let a2 = harmonic(&tight, 2) / a1;
    assert!((1e-3..1e-2).contains(&a2), "ρ 5 µm: 2f_c/f_c = {a2}");
    for k in 3..=8 {
        assert!(
            harmonic(&tight, k) < 1e-3 * a1,
            "ρ 5 µm: {k}f_c below 0.1 %"
        );
    }
    assert!(tight.min_roller_load_n > 0.0 && !tight.loss_of_contact);
    // ρ = 0: 2, 3 and 4 f_c each above 1 % (45 %, 2.7 %, 7.8 % measured), 2f_bn in x,
    // W reaches 0.
    let b1 = harmonic(&loose, 1);
    for k in 2..=4 {
        assert!(harmonic(&loose, k) > 0.01 * b1, "ρ 0: {k}f_c above 1 %");
    }
    assert!(line(&loose.spectrum_x, "2f_bn") > 0.0);
    assert!(loose.loss_of_contact && loose.min_roller_load_n == 0.0);
    assert!(tight.base_natural_frequency_hz.unwrap() > loose.base_natural_frequency_hz.unwrap());
    // The x line at the roller pass m·f_c, by projection over the whole cage cycles.
    let pass = |r: &DynamicsResult| {
        amplitude_at(&r.series.x_m, r.series.dt_s, r.roller_pass_frequency_hz).unwrap()
    };
    eprintln!(
        "x at m·f_c: ρ 5 µm {:.3e} m, ρ 0 {:.3e} m",
        pass(&tight),
        pass(&loose)
    );
    assert!(pass(&loose) > pass(&tight));
    // ρ = 0 loses and regains contact (events); ρ = 5 µm never does. (The issue's
    // "ρ = 0 costs about 3× the steps" does not hold here: 126 631 steps against
    // 152 703 at rtol 1e-8, since its f_bn is lower, 604 against 933 Hz.)
    assert!(loose.stats.events > 0 && tight.stats.events == 0);
}

fn film_run(squeeze: Squeeze) -> DynamicsResult {
    let model = DynamicsModel {
        film: Some(truck_film(squeeze)),
        span: Span::Revolutions {
            shaft_speed_rad_s: 209.0,
            revolutions: 20.0,
            settle_revolutions: 10.0,
        },
        ..DynamicsModel::truck(5e-6)
    };
    simulate(&model, Cancel::NONE).unwrap()
}

fn max_load(r: &DynamicsResult) -> f64 {
    r.cycle.roller_load_n.iter().copied().fold(0.0, f64::max)
}

#[test]
fn film_in_the_deflection_runs_and_reads_pan_hamrock() {
    // The steady film (no squeeze term): h(W) alone keeps the model conservative.
    let res = film_run(Squeeze::None);
    let max_w = max_load(&res);
    let at_max = res
        .cycle
        .roller_load_n
        .iter()
        .position(|&w| w == max_w)
        .unwrap();
    let h = res.cycle.film_m[at_max];
    eprintln!(
        "film on (no squeeze): W_max {max_w:.1} N, h there {h:.3e} m, f_bn {:?}, stats {:?}",
        res.base_natural_frequency_hz, res.stats
    );
    assert!((0.25e-6..=0.46e-6).contains(&h), "{h}");
    assert!(!res.loss_of_contact);
    assert!(res.energy_drift_rel.is_none());
}

#[test]
fn the_normalised_squeeze_is_stable_where_the_printed_sense_is_not() {
    // Eq. (4)'s printed factor thins the film on approach: a force −c·ṗ with c > 0,
    // negative damping (c ≈ ½·dW/dδ·∂h/∂w ≈ 140 N·s/m per loaded roller, ζ ≈ −0.0015
    // at 933 Hz): within the 1.5 s simulated the vibration grows until rollers unload
    // (measured with that sense: W_max 23.7 kN against 3.46 kN for the steady film). The
    // default reading (approach thickens, film.rs docs) is positive damping: its orbit
    // stays within the steady film's (≤ 1 % above its largest load), no roller unloads.
    let steady = film_run(Squeeze::None);
    let squeeze = film_run(Squeeze::Normalised);
    eprintln!(
        "W_max steady film {:.1} N, normalised squeeze {:.1} N, losses {}",
        max_load(&steady),
        max_load(&squeeze),
        squeeze.stats.contact_losses_after_settle
    );
    assert!(max_load(&squeeze) <= 1.01 * max_load(&steady));
    assert!(!squeeze.loss_of_contact);
}

#[test]
fn cancellation_and_bounds_are_typed_errors_naming_the_key() {
    let flag = AtomicBool::new(true);
    assert_eq!(
        simulate(&DynamicsModel::truck(5e-6), Cancel::new(&flag)),
        Err(DynamicsError::Cancelled)
    );
    let too_long = DynamicsModel {
        span: Span::Revolutions {
            shaft_speed_rad_s: 209.0,
            revolutions: 1e6,
            settle_revolutions: 1.0,
        },
        ..DynamicsModel::truck(5e-6)
    };
    let e = simulate(&too_long, Cancel::NONE).unwrap_err();
    assert!(e.to_string().contains("dynamics.revolutions"), "{e}");
    let bad_mass = DynamicsModel {
        mass_kg: -1.0,
        ..DynamicsModel::truck(5e-6)
    };
    let e = simulate(&bad_mass, Cancel::NONE).unwrap_err();
    assert!(e.to_string().contains("dynamics.system_mass"), "{e}");
}

#[test]
fn progress_is_reported_up_to_one() {
    let seen = std::sync::Mutex::new(Vec::new());
    let p = |x: f64| seen.lock().map(|mut v| v.push(x)).unwrap_or(());
    let model = DynamicsModel {
        span: Span::Revolutions {
            shaft_speed_rad_s: 209.0,
            revolutions: 5.0,
            settle_revolutions: 1.0,
        },
        ..DynamicsModel::truck(5e-6)
    };
    simulate(&model, Cancel::NONE.with_progress(&p)).unwrap();
    let v = seen.lock().unwrap();
    assert_eq!(v.len(), CHUNKS);
    assert!(v.windows(2).all(|w| w[1] >= w[0]));
    assert!((v[v.len() - 1] - 1.0).abs() < 1e-12);
}

/// A run far past the step bound is refused before integrating, naming the keys: the
/// truck bearing at 1 rpm for 100 revolutions is 6 000 s simulated, ≈ 5.6 M periods of
/// f_lin ≈ 932 Hz, ≈ 5e7 steps against the 5e6 bound. The estimate at the shipped
/// 209 rad/s (3 s simulated, ≈ 26 k steps measured) stays far below it.
#[test]
fn a_run_past_the_step_bound_is_refused_up_front() {
    let mut m = DynamicsModel::truck(5e-6);
    m.span = Span::Revolutions {
        shaft_speed_rad_s: TAU / 60.0,
        revolutions: 100.0,
        settle_revolutions: 20.0,
    };
    // TooLong is the estimate's refusal; stepping into the bound would be TooMuchWork.
    let err = simulate(&m, Cancel::NONE).map(|_| ()).unwrap_err();
    match &err {
        DynamicsError::TooLong {
            estimate, periods, ..
        } => {
            assert!(*estimate > 1e7 && *estimate < 1e8, "{estimate}");
            // f_lin ≈ 932 Hz × 6 000 s.
            assert!((*periods / 5.6e6 - 1.0).abs() < 0.05, "{periods}");
        }
        other => panic!("{other}"),
    }
    let text = err.to_string();
    for key in [
        "dynamics.revolutions",
        "operating.inner_speed",
        "dynamics.tolerance",
    ] {
        assert!(text.contains(key), "{text}");
    }
}

/// The truck bearing's right-hand side (film off, energy integral on) for the
/// integrator comparisons below.
fn truck_rhs(interference_m: f64) -> model::Rhs {
    let m = 12;
    model::Rhs {
        law: ContactLaw {
            stiffness: 2.0e9,
            exponent: 10.0 / 9.0,
            clearance_m: -interference_m,
            film: None,
        },
        mass_kg: 50.0,
        cage_speed_rad_s: 83.26,
        phases: (0..m).map(|i| TAU * i as f64 / m as f64).collect(),
        phase_sin_cos: (0..m)
            .map(|i| (TAU * i as f64 / m as f64).sin_cos())
            .collect(),
        phase_sin: (0..m).map(|i| (TAU * i as f64 / m as f64).sin()).collect(),
        phase_cos: (0..m).map(|i| (TAU * i as f64 / m as f64).cos()).collect(),
        force_n: [-(1500.0 + 50.0 * 9.81), 0.0],
        damping_n_s_m: 0.0,
        energy_integral: true,
        omega_ref: TAU * 932.0,
        energy_ref: 1e-2,
        clamps: Cell::new(0),
        fast_film: None,
        cage_angle: super::angle::AngleTable::new(),
    }
}

/// Issue 25, Speed item 1: the fixed-size DOP853 path is the general DOP853 path with
/// the vectors on the stack, so it must take the same steps and give the same numbers.
/// Over 0.05 s of the truck bearing (≈ 47 periods of f_bn, 600 output times, released at
/// rest from 0) with ρ = 5 µm (no event) and ρ = 0 (run to its first contact-loss
/// event), against `numerics::ode::solve` with one `ContactEvent` per roller: the same
/// accepted and rejected steps, evaluations and termination, and every output state and
/// the final state within 1e-12 relative (the arithmetic is the same in the same order,
/// so the difference measured is 0).
#[test]
fn the_fixed_size_dop853_path_matches_the_general_path() {
    use crate::numerics::ode::{solve, solve_dop853_fixed, Event, Method, OdeOptions, Output};
    for rho in [5e-6, 0.0] {
        let rhs = truck_rhs(rho);
        let opts = OdeOptions {
            rtol: 1e-8,
            atol: 1e-8 * 8e-6,
            method: Method::Dop853,
            ..OdeOptions::default()
        };
        let times: Vec<f64> = (0..600).map(|j| 0.01 + f64::from(j) * 6.5e-5).collect();
        let y0 = [0.0; 5];
        let mut evs: Vec<model::ContactEvent<'_>> = (0..12)
            .map(|i| model::ContactEvent {
                rhs: &rhs,
                roller: i,
                start: None,
            })
            .collect();
        let mut refs: Vec<&mut dyn Event> = evs.iter_mut().map(|e| e as &mut dyn Event).collect();
        let general = solve(
            &rhs,
            0.0,
            &y0,
            0.05,
            &opts,
            &mut refs,
            Output::Times(times.clone()),
            Cancel::NONE,
        )
        .unwrap();
        let events = model::ContactEvents {
            rhs: &rhs,
            forced: Vec::new(),
            t0: 0.0,
        };
        let mut out: Vec<(f64, [f64; 5])> = Vec::new();
        let fixed = solve_dop853_fixed(
            &rhs,
            0.0,
            &y0,
            0.05,
            &opts,
            &events,
            &times,
            &mut |t, y| out.push((t, *y)),
            Cancel::NONE,
        )
        .unwrap();
        eprintln!(
            "rho {rho:e}: general {:?} {:?}, fixed {:?} {:?}",
            general.stats, general.termination, fixed.stats, fixed.termination
        );
        assert_eq!(general.termination, fixed.termination);
        assert_eq!(general.stats.steps, fixed.stats.steps);
        assert_eq!(general.stats.rejected, fixed.stats.rejected);
        assert_eq!(general.stats.rhs_evaluations, fixed.stats.rhs_evaluations);
        assert_eq!(general.t_final, fixed.t_final);
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-12 * scale;
        for (i, (&a, &b)) in general.y_final.iter().zip(&fixed.y_final).enumerate() {
            assert!(close(a, b, a.abs().max(1e-6)), "y_final[{i}] {a} {b}");
        }
        assert_eq!(general.t.len(), out.len());
        let scale: Vec<f64> = (0..5)
            .map(|i| general.y.iter().map(|y| y[i].abs()).fold(1e-12, f64::max))
            .collect();
        let mut worst: f64 = 0.0;
        for ((t, y), (tf, yf)) in general.t.iter().zip(&general.y).zip(&out) {
            assert_eq!(t, tf);
            for i in 0..5 {
                worst = worst.max((y[i] - yf[i]).abs() / scale[i]);
            }
        }
        eprintln!("rho {rho:e}: worst output difference {worst:e}");
        assert!(worst <= 1e-12, "{worst}");
        if rho == 0.0 {
            assert!(matches!(fixed.termination, Termination::Event { .. }));
        } else {
            assert_eq!(fixed.termination, Termination::ReachedEnd);
        }
    }
}

/// What `bench` measures on a run against a reference run: (|Δf_bn| Hz, the largest
/// relative difference of the labelled peak amplitudes of the x and roller-load
/// spectra above 1e-3 of their strongest, of roller 1's load harmonics k·f_c relative
/// to the largest, of the load extrema relative to the largest load).
fn bench_errors(a: &DynamicsResult, r: &DynamicsResult) -> [f64; 4] {
    let peaks = |a: &LabelledSpectrum, r: &LabelledSpectrum| {
        let top = r.peaks.iter().map(|p| p.amplitude).fold(0.0, f64::max);
        r.peaks
            .iter()
            .filter(|p| !p.label.is_empty() && p.amplitude > 1e-3 * top)
            .map(|p| {
                a.peaks
                    .iter()
                    .find(|q| q.label == p.label)
                    .map_or(f64::INFINITY, |q| {
                        (q.amplitude - p.amplitude).abs() / p.amplitude
                    })
            })
            .fold(0.0, f64::max)
    };
    let top = r
        .roller_load_harmonics
        .iter()
        .map(|h| h.amplitude_n)
        .fold(0.0, f64::max);
    let harmonics = a
        .roller_load_harmonics
        .iter()
        .zip(&r.roller_load_harmonics)
        .map(|(x, y)| (x.amplitude_n - y.amplitude_n).abs() / top)
        .fold(0.0, f64::max);
    let w_max = max_load(r);
    let extrema = ((a.min_roller_load_n - r.min_roller_load_n).abs() / w_max)
        .max((max_load(a) - w_max).abs() / w_max);
    let fbn = match (a.base_natural_frequency_hz, r.base_natural_frequency_hz) {
        (Some(x), Some(y)) => (x - y).abs(),
        _ => f64::INFINITY,
    };
    [
        fbn,
        peaks(&a.spectrum_x, &r.spectrum_x)
            .max(peaks(&a.spectrum_roller_load, &r.spectrum_roller_load)),
        harmonics,
        extrema,
    ]
}

#[test]
fn the_nystrom_pair_agrees_with_dop853_on_the_truck_bearing() {
    // Film off, 100 revolutions at the deck's rtol 1e-8. ρ = 5 µm (no contact loss):
    // `simulate` takes the Nyström 8(6) pair (at 100× the tolerance); against DOP853 at
    // 1e-11, what `bench` measures — f_bn, the labelled peaks' amplitudes, the load
    // harmonics, the load extrema — must be at DOP853's own level at 1e-8: within 3×
    // its error (measured 0.3–2.4×) or 1e-6; and fewer evaluations. ρ = 0 (events at
    // every loss and regain): `simulate` keeps DOP853 (the same result); the pair forced
    // there must still be at DOP853's level (its events located by sub-steps).
    let model = DynamicsModel::truck(0.0);
    let forced = simulate_with(
        &model,
        Integrator::Nystrom {
            tolerance_factor: 100.0,
        },
        Cancel::NONE,
    )
    .unwrap();
    let dop = simulate_with(&model, Integrator::Dop853, Cancel::NONE).unwrap();
    assert_eq!(simulate(&model, Cancel::NONE).unwrap(), dop);
    let reference = simulate_with(
        &DynamicsModel {
            rtol: 1e-11,
            ..model.clone()
        },
        Integrator::Dop853,
        Cancel::NONE,
    )
    .unwrap();
    let (e_forced, e_dop) = (
        bench_errors(&forced, &reference),
        bench_errors(&dop, &reference),
    );
    for (j, (a, d)) in e_forced.iter().zip(&e_dop).enumerate() {
        assert!(*a <= (3.0 * d).max(1e-6), "rho 0: row {j}: {a:e} vs {d:e}");
    }
    assert!(forced.stats.events > 0 && forced.loss_of_contact);
    for rho in [5e-6] {
        let model = DynamicsModel::truck(rho);
        let auto = simulate(&model, Cancel::NONE).unwrap();
        let dop = simulate_with(&model, Integrator::Dop853, Cancel::NONE).unwrap();
        let reference = simulate_with(
            &DynamicsModel {
                rtol: 1e-11,
                ..model.clone()
            },
            Integrator::Dop853,
            Cancel::NONE,
        )
        .unwrap();
        let e_auto = bench_errors(&auto, &reference);
        let e_dop = bench_errors(&dop, &reference);
        eprintln!(
            "rho {rho:e}: Nyström {:?} errors {}; DOP853 {:?} errors {}",
            auto.stats,
            e_auto.map(|e| format!("{e:.2e}")).join(" "),
            dop.stats,
            e_dop.map(|e| format!("{e:.2e}")).join(" ")
        );
        for (j, (a, d)) in e_auto.iter().zip(&e_dop).enumerate() {
            assert!(
                *a <= (3.0 * d).max(1e-6),
                "rho {rho}: row {j}: {a:e} vs {d:e}"
            );
        }
        assert_eq!(auto.loss_of_contact, dop.loss_of_contact);
        assert!(
            auto.stats.rhs_evaluations < dop.stats.rhs_evaluations,
            "{:?} vs {:?}",
            auto.stats,
            dop.stats
        );
    }
}

#[test]
#[ignore = "a table for docs/cylindrical.md: cargo test --lib nystrom_tolerance_table -- --ignored --nocapture"]
fn nystrom_tolerance_table() {
    // The Nyström pair at factors × the deck's tolerance against DOP853 at it, both
    // against DOP853 at 1e-11: evaluations and the `bench` rows (see `bench_errors`).
    for rho in [5e-6, 0.0] {
        let model = DynamicsModel::truck(rho);
        let reference = simulate_with(
            &DynamicsModel {
                rtol: 1e-11,
                ..model.clone()
            },
            Integrator::Dop853,
            Cancel::NONE,
        )
        .unwrap();
        eprintln!(
            "rho {rho:e}: reference {:?}, f_bn {:?}",
            reference.stats, reference.base_natural_frequency_hz
        );
        let mut cases = vec![("DOP853".to_string(), Integrator::Dop853)];
        for f in [1.0, 10.0, 30.0, 100.0, 300.0, 1000.0] {
            cases.push((
                format!("RKN {f}x"),
                Integrator::Nystrom {
                    tolerance_factor: f,
                },
            ));
        }
        for (name, integrator) in cases {
            let r = simulate_with(&model, integrator, Cancel::NONE).unwrap();
            let e = bench_errors(&r, &reference);
            eprintln!(
                "  {name:<12} steps {:>7} rejected {:>5} evals {:>8} events {:>5} | d_fbn {:.2e} Hz peaks {:.2e} harmonics {:.2e} extrema {:.2e}",
                r.stats.steps, r.stats.rejected, r.stats.rhs_evaluations, r.stats.events, e[0], e[1], e[2], e[3]
            );
        }
    }
}

#[test]
fn the_nystrom_pair_agrees_with_dop853_with_the_steady_film() {
    // The steady film in the deflection (`Squeeze::None`: the force depends on position
    // and time only, so `simulate` takes the Nyström pair; the criterion bench's film-on
    // case), ρ = 5 µm, 30 revolutions with 10 to settle, rtol 1e-8: the `bench` rows at
    // DOP853's level at 1e-8 against DOP853 at 1e-11 (3× or 1e-6), fewer evaluations. The
    // normalised squeeze needs the velocity: DOP853 whatever the choice (same numbers).
    let model = DynamicsModel {
        film: Some(truck_film(Squeeze::None)),
        span: Span::Revolutions {
            shaft_speed_rad_s: 209.0,
            revolutions: 30.0,
            settle_revolutions: 10.0,
        },
        ..DynamicsModel::truck(5e-6)
    };
    let auto = simulate(&model, Cancel::NONE).unwrap();
    let dop = simulate_with(&model, Integrator::Dop853, Cancel::NONE).unwrap();
    let reference = simulate_with(
        &DynamicsModel {
            rtol: 1e-11,
            ..model.clone()
        },
        Integrator::Dop853,
        Cancel::NONE,
    )
    .unwrap();
    let e_auto = bench_errors(&auto, &reference);
    let e_dop = bench_errors(&dop, &reference);
    eprintln!(
        "steady film: Nyström {:?} errors {}; DOP853 {:?} errors {}",
        auto.stats,
        e_auto.map(|e| format!("{e:.2e}")).join(" "),
        dop.stats,
        e_dop.map(|e| format!("{e:.2e}")).join(" ")
    );
    for (j, (a, d)) in e_auto.iter().zip(&e_dop).enumerate() {
        assert!(*a <= (3.0 * d).max(1e-6), "row {j}: {a:e} vs {d:e}");
    }
    assert!(auto.stats.rhs_evaluations < dop.stats.rhs_evaluations);
    let squeezed = DynamicsModel {
        film: Some(truck_film(Squeeze::Normalised)),
        ..model
    };
    assert_eq!(
        simulate(&squeezed, Cancel::NONE).unwrap(),
        simulate_with(&squeezed, Integrator::Dop853, Cancel::NONE).unwrap()
    );
}
