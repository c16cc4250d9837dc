//! The cylindrical roller bearing's 2-DOF tribodynamics and spectra (seed 003 eqs. 1–5,
//! Figs. 2–5; issue 25 Model items 2–3).
//!
//! State (x, y, ẋ, ẏ) of the shaft centre; roller i at θ_i = ω_c t + θ₁ + 2π(i−1)/m;
//! W_i = k_n δ_i^n (eq. 2) with 2δ_i = 2(h_i − C) + x cos θ_i + y sin θ_i (eq. 3), W = 0
//! for δ ≤ 0; the film h_i of eq. (4) (read as documented in [`film`]) with the squeeze
//! velocity w_i = −½ d/dt(x cos θ_i + y sin θ_i): in the right-hand side and for the
//! sampled outputs (load, film, squeeze velocity per roller) from a table of the film
//! solve built once per run ([`film_table`], < 1e-13 from the safeguarded Newton solve,
//! which remains where the table does not reach). Integrated from
//! x = y = 0 at rest (the seed's start) by the shared DOP853 (measured: 26 k steps and
//! 0.34 M evaluations for 100 revolutions of the truck bearing at rtol 1e-8 against
//! DOPRI5's 153 k and 0.92 M), or, where the force depends on position and time only
//! (film off or the steady film, no damper), by the Runge–Kutta–Nyström 8(6) pair
//! ([`crate::numerics::ode::solve_rkn86`]: eight evaluations a step, steps landing on
//! the sampling grid instead of a dense output; see [`Integrator`]),
//! with a terminal event at every contact loss and regain (δ^(10/9) is not smooth there)
//! after which the integration restarts, so no step straddles a kink.
//!
//! No damping in the seed: without the film's squeeze term (or `damping_ratio`) the
//! oscillation after release never decays, and
//! `settle_revolutions` is a count of shaft revolutions skipped before sampling, not a
//! convergence test (the result's `note` says so).

mod angle;
pub mod film;
mod film_table;
mod kernel;
mod model;
mod spectra;
#[cfg(test)]
mod tests;

pub use film::{FilmLaw, Squeeze, LOAD_FLOOR_N};
pub use spectra::{LabelledPeak, LabelledSpectrum};

use crate::numerics::cancel::Cancel;
use crate::numerics::ode::{
    solve_dop853_fixed, solve_rkn86, FixedSolution, FixedSystem, Method, NystromOptions, OdeError,
    OdeOptions, Termination,
};
use crate::numerics::spectrum::{amplitude_at, SpectrumError};
use film::ContactLaw;
use film_table::FastFilm;
use model::{static_equilibrium, ContactEvents, NystromContactEvents, Rhs};
use std::cell::Cell;
use std::f64::consts::TAU;

/// How long to integrate and where sampling starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Span {
    /// Shaft revolutions at the shaft speed (the deck's `dynamics.revolutions` and
    /// `dynamics.settle_revolutions`).
    Revolutions {
        /// Shaft speed, rad/s.
        shaft_speed_rad_s: f64,
        /// Revolutions integrated in all.
        revolutions: f64,
        /// Revolutions skipped before sampling (a count, not a convergence test).
        settle_revolutions: f64,
    },
    /// A duration (validation runs with the cage frozen).
    Duration {
        /// Integrated time, s.
        duration_s: f64,
        /// Time skipped before sampling, s.
        settle_s: f64,
    },
}

/// The 2-DOF model's inputs, SI (the lead maps the deck onto it).
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsModel {
    /// M, the supported mass, kg.
    pub mass_kg: f64,
    /// m, the number of rollers.
    pub roller_count: usize,
    /// k_n, N/m^n (eq. 2).
    pub contact_stiffness: f64,
    /// n (10/9).
    pub load_exponent: f64,
    /// C, the radial clearance, m; C = −ρ for an interference ρ (eq. 3).
    pub clearance_m: f64,
    /// ω_c, rad/s (0 freezes the cage).
    pub cage_speed_rad_s: f64,
    /// θ₁ at t = 0, rad.
    pub first_azimuth_rad: f64,
    /// (F_x, F_y), applied plus gravity, N (the seed: −(1 500 + 50·9.81) N along x).
    pub force_n: [f64; 2],
    /// The film in the deflection (eq. 4); `None`: dry, h = 0.
    pub film: Option<FilmLaw>,
    /// ζ of a viscous damper c = 2ζ√(K_xx M) on both axes (0: the seed has none).
    pub damping_ratio: f64,
    /// Duration and settling.
    pub span: Span,
    /// Relative tolerance of the integrator (absolute: rtol × the static offset scale).
    pub rtol: f64,
    /// Sampling rate, Hz; rounded so that each cage cycle holds a whole number of samples.
    pub sample_rate_hz: f64,
    /// (x, y, ẋ, ẏ) at t = 0, SI; the seed's start is zeros.
    pub initial_state: [f64; 4],
}

impl DynamicsModel {
    /// The seed's truck bearing (Tables A1/A2): m = 12, M = 50 kg, k_n = 2.0e9
    /// N/m^(10/9) (the slice-law value, trap 3), n = 10/9, ρ = `interference_m`,
    /// ω_c = 83.26 rad/s, shaft 209 rad/s, F = 1 500 N + 50·9.81 N along −x, film off,
    /// 100 revolutions with 20 to settle, rtol 1e-8.
    pub fn truck(interference_m: f64) -> Self {
        DynamicsModel {
            mass_kg: 50.0,
            roller_count: 12,
            contact_stiffness: 2.0e9,
            load_exponent: 10.0 / 9.0,
            clearance_m: -interference_m,
            cage_speed_rad_s: 83.26,
            first_azimuth_rad: 0.0,
            force_n: [-(1500.0 + 50.0 * 9.81), 0.0],
            film: None,
            damping_ratio: 0.0,
            span: Span::Revolutions {
                shaft_speed_rad_s: 209.0,
                revolutions: 100.0,
                settle_revolutions: 20.0,
            },
            rtol: 1e-8,
            sample_rate_hz: 4096.0,
            initial_state: [0.0; 4],
        }
    }
}

/// Uniformly sampled series after settling, over whole cage cycles.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Sampling step, s.
    pub dt_s: f64,
    /// Times, s.
    pub t_s: Vec<f64>,
    /// x, m.
    pub x_m: Vec<f64>,
    /// y, m.
    pub y_m: Vec<f64>,
    /// ẋ, m/s.
    pub vx_m_s: Vec<f64>,
    /// ẏ, m/s.
    pub vy_m_s: Vec<f64>,
    /// W_i per roller (outer index: roller), N.
    pub roller_load_n: Vec<Vec<f64>>,
    /// h_i per roller, m.
    pub film_m: Vec<Vec<f64>>,
    /// w_i per roller, m/s.
    pub squeeze_velocity_m_s: Vec<Vec<f64>>,
}

/// Roller 1 over the last whole cage cycle.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cycle {
    /// θ₁ mod 360°, deg.
    pub cage_angle_deg: Vec<f64>,
    /// W₁, N.
    pub roller_load_n: Vec<f64>,
    /// h₁, m.
    pub film_m: Vec<f64>,
    /// w₁, m/s.
    pub squeeze_velocity_m_s: Vec<f64>,
}

/// One harmonic of roller 1's load, by projection over whole cage cycles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    /// k in k·f_c.
    pub order: usize,
    /// k·f_c, Hz.
    pub frequency_hz: f64,
    /// Amplitude, N.
    pub amplitude_n: f64,
}

/// Work counters.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DynamicsStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evaluations: usize,
    /// Contact losses and regains located (each a restart).
    pub events: usize,
    /// Contact losses after settling.
    pub contact_losses_after_settle: usize,
    /// Film clamps at h = 0 (printed reading, or normalised at w/U < −0.22).
    pub film_clamps: usize,
}

/// What [`simulate`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsResult {
    /// Static offset (x, y) with the cage frozen at t = 0, m.
    pub static_offset_m: [f64; 2],
    /// Stiffness ∂(ΣW)/∂(x, y) there, N/m.
    pub stiffness_n_per_m: [[f64; 2]; 2],
    /// √(λ/M)/2π for the eigenvalue of K whose eigenvector is closest to x, Hz.
    pub linearised_frequency_hz: f64,
    /// The x spectrum's dominant peak away from the cage harmonics, Hz.
    pub base_natural_frequency_hz: Option<f64>,
    /// f_c = ω_c/2π, Hz.
    pub cage_frequency_hz: f64,
    /// m·f_c, Hz.
    pub roller_pass_frequency_hz: f64,
    /// The smallest sampled roller load after settling, N.
    pub min_roller_load_n: f64,
    /// Whether any contact was lost after settling (event or a zero sample).
    pub loss_of_contact: bool,
    /// max |E(t) − E(0) − ∫∂V/∂t dt| / (|F·r_s| + V(r_s)) over the samples (film off
    /// and no damping only).
    pub energy_drift_rel: Option<f64>,
    /// The sampled series.
    pub series: Series,
    /// Spectrum of x.
    pub spectrum_x: LabelledSpectrum,
    /// Spectrum of roller 1's load.
    pub spectrum_roller_load: LabelledSpectrum,
    /// Roller 1's load harmonics k·f_c, k = 1..=8, by projection (empty with the cage
    /// frozen).
    pub roller_load_harmonics: Vec<Harmonic>,
    /// Roller 1 over the last cage cycle.
    pub cycle: Cycle,
    /// Work.
    pub stats: DynamicsStats,
    /// What the numbers mean.
    pub note: String,
}

/// Why a simulation was refused or failed. Messages name the deck key.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// An input is out of range.
    #[error("{key} = {value} is out of range: {allowed}")]
    Input {
        /// Deck key.
        key: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range.
        allowed: &'static str,
    },
    /// Too little simulated after settling for one whole cage cycle (the spectra and the
    /// friction cycle are taken over whole cage cycles).
    #[error(
        "dynamics.revolutions = {revolutions} leaves {after:.3} shaft revolutions after \
         dynamics.settle_revolutions = {settle}, less than one whole cage cycle \
         ({per_cycle:.3} shaft revolutions at this cage speed): raise dynamics.revolutions \
         to at least {needed} or lower dynamics.settle_revolutions"
    )]
    ShorterThanACageCycle {
        /// Shaft revolutions simulated (the deck's value).
        revolutions: f64,
        /// Shaft revolutions skipped.
        settle: f64,
        /// Shaft revolutions left after settling.
        after: f64,
        /// Shaft revolutions per cage cycle.
        per_cycle: f64,
        /// The smallest whole number of revolutions that gives one cage cycle.
        needed: f64,
    },
    /// The work estimated before integrating passes the bound.
    #[error(
        "the dynamics would take about {estimate:.2e} integration steps ({periods:.3e} \
         periods of the {frequency_hz:.1} Hz base frequency over {duration_s:.4e} s \
         simulated), past the bound of {bound} steps: lower dynamics.revolutions, raise \
         operating.inner_speed (the simulated time is revolutions ÷ shaft speed) or loosen \
         dynamics.tolerance"
    )]
    TooLong {
        /// Steps estimated.
        estimate: f64,
        /// Periods of the linearised base frequency in the simulated time.
        periods: f64,
        /// The linearised base frequency, Hz.
        frequency_hz: f64,
        /// Simulated time, s.
        duration_s: f64,
        /// The step bound.
        bound: usize,
    },
    /// The work bound was reached.
    #[error(
        "the dynamics took more than {steps} integration steps by t = {t_s:.4} s; lower \
         dynamics.revolutions or loosen dynamics.tolerance"
    )]
    TooMuchWork {
        /// Steps attempted.
        steps: usize,
        /// Time reached, s.
        t_s: f64,
    },
    /// No static equilibrium with the cage frozen.
    #[error(
        "no static equilibrium: the rollers leave {residual_n:.3e} N of the {load_n:.1} N \
         load unbalanced (check dynamics.contact_stiffness and the load)"
    )]
    NoEquilibrium {
        /// Residual force, N.
        residual_n: f64,
        /// Load, N.
        load_n: f64,
    },
    /// The integrator failed.
    #[error("the dynamics integration failed at t = {t_s:.6} s: {reason}")]
    Integration {
        /// Time reached, s.
        t_s: f64,
        /// Why.
        reason: String,
    },
    /// Cancelled by a newer request.
    #[error("cancelled")]
    Cancelled,
    /// The spectrum could not be formed.
    #[error("spectrum: {0}")]
    Spectrum(#[from] SpectrumError),
}

/// Step attempts allowed in one simulation (about 50× what 100 revolutions at
/// rtol 1e-10 with ρ = 0 take): past it the run is refused, naming the key.
const MAX_STEPS: usize = 5_000_000;
/// Samples kept at most (memory: 40 floats each).
const MAX_SAMPLES: usize = 4_000_000;
/// The Nyström pair's tolerance over the deck's (`dynamics.tolerance`, which names
/// DOP853's accuracy): the pair controls its sixth-order estimate while it keeps the
/// eighth-order solution, so at one tolerance its error is far below DOP853's. Measured
/// on the truck bearing, film off, ρ = 5 µm, rtol 1e-8, against DOP853 at 1e-11
/// (`tests::nystrom_tolerance_table`): at 1× the pair's `bench` rows are 100× closer
/// than DOP853's and it takes 1.12× its evaluations; at 30× every row is still closer
/// (0.83× the evaluations); at 100× f_bn is closer (5.7e-7 against 1.7e-6 Hz) and the
/// peak amplitudes, harmonics and load extrema 1.7–2.4× farther (3.5e-5 against 1.4e-5
/// relative on the peaks), the same level, for 0.59× the evaluations.
const NYSTROM_TOLERANCE_FACTOR: f64 = 100.0;
/// Progress reports (and restarts) per simulation.
const CHUNKS: usize = 50;

fn input(
    key: &'static str,
    value: f64,
    ok: bool,
    allowed: &'static str,
) -> Result<(), DynamicsError> {
    if ok {
        Ok(())
    } else {
        Err(DynamicsError::Input {
            key,
            value,
            allowed,
        })
    }
}

/// (duration, settle) in seconds.
fn span_seconds(model: &DynamicsModel) -> Result<(f64, f64), DynamicsError> {
    match model.span {
        Span::Revolutions {
            shaft_speed_rad_s,
            revolutions,
            settle_revolutions,
        } => {
            input(
                "operating.inner_speed",
                shaft_speed_rad_s,
                shaft_speed_rad_s.is_finite() && shaft_speed_rad_s > 0.0,
                "a finite speed > 0",
            )?;
            input(
                "dynamics.revolutions",
                revolutions,
                revolutions.is_finite() && revolutions > 0.0 && revolutions <= 10_000.0,
                "0 < revolutions ≤ 10000",
            )?;
            input(
                "dynamics.settle_revolutions",
                settle_revolutions,
                settle_revolutions.is_finite()
                    && settle_revolutions >= 0.0
                    && settle_revolutions < revolutions,
                "0 ≤ settle_revolutions < revolutions",
            )?;
            let rev = TAU / shaft_speed_rad_s;
            Ok((revolutions * rev, settle_revolutions * rev))
        }
        Span::Duration {
            duration_s,
            settle_s,
        } => {
            input(
                "dynamics.revolutions",
                duration_s,
                duration_s.is_finite() && duration_s > 0.0 && duration_s <= 1000.0,
                "a duration 0 < T ≤ 1000 s",
            )?;
            input(
                "dynamics.settle_revolutions",
                settle_s,
                settle_s.is_finite() && settle_s >= 0.0 && settle_s < duration_s,
                "0 ≤ settle < duration",
            )?;
            Ok((duration_s, settle_s))
        }
    }
}

fn validate(model: &DynamicsModel) -> Result<(), DynamicsError> {
    input(
        "dynamics.system_mass",
        model.mass_kg,
        model.mass_kg.is_finite() && model.mass_kg > 0.0,
        "a finite mass > 0 kg",
    )?;
    input(
        "geometry.roller_count",
        model.roller_count as f64,
        (1..=1000).contains(&model.roller_count),
        "1 to 1000 rollers",
    )?;
    input(
        "dynamics.contact_stiffness",
        model.contact_stiffness,
        model.contact_stiffness.is_finite() && model.contact_stiffness > 0.0,
        "a finite k_n > 0 N/m^n",
    )?;
    input(
        "dynamics.load_exponent",
        model.load_exponent,
        (1.0..=3.0).contains(&model.load_exponent),
        "1 ≤ n ≤ 3",
    )?;
    input(
        "geometry.radial_interference",
        -model.clearance_m,
        model.clearance_m.is_finite() && model.clearance_m.abs() < 1e-3,
        "|ρ| < 1 mm",
    )?;
    input(
        "operating.cage_speed",
        model.cage_speed_rad_s,
        model.cage_speed_rad_s.is_finite() && model.cage_speed_rad_s >= 0.0,
        "a finite speed ≥ 0",
    )?;
    input(
        "operating.load_angle",
        model.first_azimuth_rad,
        model.first_azimuth_rad.is_finite(),
        "a finite angle",
    )?;
    for f in model.force_n {
        input(
            "operating.radial_load",
            f,
            f.is_finite() && f.abs() < 1e9,
            "a finite load below 1e9 N",
        )?;
    }
    input(
        "dynamics.damping_ratio",
        model.damping_ratio,
        (0.0..=10.0).contains(&model.damping_ratio),
        "0 ≤ ζ ≤ 10",
    )?;
    input(
        "dynamics.tolerance",
        model.rtol,
        (1e-13..=1e-2).contains(&model.rtol),
        "1e-13 ≤ tolerance ≤ 1e-2",
    )?;
    input(
        "dynamics.sample_rate",
        model.sample_rate_hz,
        model.sample_rate_hz.is_finite() && model.sample_rate_hz >= 16.0,
        "a rate ≥ 16 Hz",
    )?;
    for v in model.initial_state {
        input("dynamics.initial_state", v, v.is_finite(), "finite numbers")?;
    }
    if let Some(f) = &model.film {
        for (key, v) in [
            ("lubricant.viscosity", f.viscosity_pa_s),
            ("lubricant.pressure_viscosity", f.pressure_viscosity_pa_inv),
            ("materials.modulus", f.reduced_modulus_pa),
            ("geometry.roller_diameter", f.reduced_radius_m),
            ("geometry.roller_length", f.length_m),
            ("operating.inner_speed", f.entrainment_speed_m_s),
        ] {
            input(key, v, v.is_finite() && v > 0.0, "a finite value > 0")?;
        }
    }
    Ok(())
}

/// Which integrator [`simulate_with`] uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Integrator {
    /// What [`simulate`] uses: the Nyström 8(6) pair where the force depends on
    /// position and time only (film off or the steady film `Squeeze::None`, no damping)
    /// and the rings are interference-fitted (C < 0: contacts seldom open, and each
    /// opening costs the pair a located event), at `NYSTROM_TOLERANCE_FACTOR` × the
    /// deck's tolerance; DOP853 otherwise.
    Auto,
    /// DOP853 always (the reference of the comparisons).
    Dop853,
    /// The Nyström pair at this factor × the deck's tolerance where it applies (see
    /// [`Integrator::Auto`]), DOP853 otherwise.
    Nystrom {
        /// Its tolerance over `dynamics.tolerance`.
        tolerance_factor: f64,
    },
}

/// Run the 2-DOF dynamics (see the module docs). Cancellation is polled before every
/// step; progress goes to `cancel.report` as the fraction of simulated time.
pub fn simulate(
    model: &DynamicsModel,
    cancel: Cancel<'_>,
) -> Result<DynamicsResult, DynamicsError> {
    simulate_with(model, Integrator::Auto, cancel)
}

/// [`simulate`] with the integrator chosen (comparisons and benches).
pub fn simulate_with(
    model: &DynamicsModel,
    integrator: Integrator,
    cancel: Cancel<'_>,
) -> Result<DynamicsResult, DynamicsError> {
    validate(model)?;
    let (duration, settle) = span_seconds(model)?;
    let film = match &model.film {
        Some(f) => Some(f.coefficients().ok_or(DynamicsError::Input {
            key: "lubricant.viscosity",
            value: f.viscosity_pa_s,
            allowed: "inputs that give a positive Pan–Hamrock film",
        })?),
        None => None,
    };
    let m = model.roller_count;
    let mut rhs = Rhs {
        law: ContactLaw {
            stiffness: model.contact_stiffness,
            exponent: model.load_exponent,
            clearance_m: model.clearance_m,
            film,
        },
        mass_kg: model.mass_kg,
        cage_speed_rad_s: model.cage_speed_rad_s,
        phases: (0..m)
            .map(|i| model.first_azimuth_rad + TAU * i as f64 / m as f64)
            .collect(),
        phase_sin_cos: (0..m)
            .map(|i| (model.first_azimuth_rad + TAU * i as f64 / m as f64).sin_cos())
            .collect(),
        phase_sin: Vec::new(),
        phase_cos: Vec::new(),
        force_n: model.force_n,
        damping_n_s_m: 0.0,
        energy_integral: film.is_none(),
        omega_ref: 1.0,
        energy_ref: 1.0,
        clamps: Cell::new(0),
        fast_film: None,
        cage_angle: angle::AngleTable::new(),
    };

    (rhs.phase_sin, rhs.phase_cos) = rhs.phase_sin_cos.iter().copied().unzip();
    // The film solve tabulated for loads up to 1 000× the applied force (beyond, and
    // wherever the table does not reach, the Newton solve).
    let load_hi = 1e3 * model.force_n[0].hypot(model.force_n[1]).max(LOAD_FLOOR_N);
    rhs.fast_film = FastFilm::new(&rhs.law, load_hi);

    // Statics with the cage frozen at t = 0, and the linearised frequency.
    let (offset, k) = static_equilibrium(&rhs)?;
    let (lambda_x, _) = x_eigen(&k);
    let linearised_frequency_hz = (lambda_x.max(0.0) / model.mass_kg).sqrt() / TAU;
    rhs.damping_n_s_m = 2.0 * model.damping_ratio * (lambda_x.max(0.0) * model.mass_kg).sqrt();
    let omega = TAU * linearised_frequency_hz;
    // Work estimate before integrating (bounded time): DOP853 takes about 9 steps per
    // period of the base frequency at rtol 1e-8 (measured: 26 k steps for the truck
    // bearing's 2 900 periods), growing as rtol^(-1/8) for an 8th-order method. A run
    // whose estimate passes MAX_STEPS is refused now, not after minutes of stepping
    // (1 rpm for 100 revolutions is 6 000 s simulated: ≈ 5e7 steps).
    let periods = linearised_frequency_hz * duration;
    let estimate = 9.0 * (1e-8 / model.rtol).powf(1.0 / 8.0) * periods;
    if estimate.is_finite() && estimate > MAX_STEPS as f64 {
        return Err(DynamicsError::TooLong {
            estimate,
            periods,
            frequency_hz: linearised_frequency_hz,
            duration_s: duration,
            bound: MAX_STEPS,
        });
    }
    rhs.omega_ref = if omega.is_finite() && omega > 0.0 {
        omega
    } else {
        1.0
    };
    let energy_scale = (model.force_n[0] * offset[0] + model.force_n[1] * offset[1]).abs()
        + rhs.potential(0.0, offset[0], offset[1]);
    rhs.energy_ref = if energy_scale > 0.0 {
        energy_scale
    } else {
        1.0
    };

    // Sampling grid: whole cage cycles after settling, a whole number of samples each.
    let fc = model.cage_speed_rad_s / TAU;
    let (dt, count, per_cycle) = if fc > 0.0 {
        let per_cycle = (model.sample_rate_hz / fc).round().max(8.0);
        let cycles = ((duration - settle) * fc + 1e-9).floor();
        if cycles < 1.0 {
            // Name the deck's own numbers (shaft revolutions), not cage cycles.
            let (revolutions, settle_rev, shaft_rev_s) = match model.span {
                Span::Revolutions {
                    shaft_speed_rad_s,
                    revolutions,
                    settle_revolutions,
                } => (revolutions, settle_revolutions, TAU / shaft_speed_rad_s),
                // Validation runs in seconds: report seconds as "revolutions" of 1 s.
                Span::Duration { .. } => (duration, settle, 1.0),
            };
            let per_cycle = 1.0 / (fc * shaft_rev_s);
            return Err(DynamicsError::ShorterThanACageCycle {
                revolutions,
                settle: settle_rev,
                after: (duration - settle) / shaft_rev_s,
                per_cycle,
                needed: (settle_rev + per_cycle).ceil(),
            });
        }
        (
            1.0 / (fc * per_cycle),
            (cycles * per_cycle) as usize,
            per_cycle as usize,
        )
    } else {
        let dt = 1.0 / model.sample_rate_hz;
        (dt, ((duration - settle) / dt).floor() as usize, 0)
    };
    input(
        "dynamics.revolutions",
        count as f64,
        (16..=MAX_SAMPLES).contains(&count),
        "enough revolutions after settling for 16 samples and at most 4e6",
    )?;
    // The last sample may fall a rounding past `duration`: integrate to it.
    let t_end = (settle + (count - 1) as f64 * dt).max(duration);
    let times: Vec<f64> = (0..count).map(|j| settle + j as f64 * dt).collect();

    let r_scale = offset[0].hypot(offset[1]).max(1e-9);
    let opts_base = OdeOptions {
        rtol: model.rtol,
        atol: model.rtol * r_scale,
        method: Method::Dop853,
        ..OdeOptions::default()
    };

    // Where the force depends on position and time only (film off or steady, no
    // damper) the Runge–Kutta–Nyström 8(6) pair integrates eq. (1) directly (fewer
    // evaluations than DOP853 at the same accuracy; see `NYSTROM_TOLERANCE_FACTOR`).
    // The squeeze term and the damper need the velocity: DOP853.
    // Auto: the pair only with an interference (C < 0). It locates a contact loss or
    // regain by sub-steps (about 70 evaluations each, against DOP853's dense output),
    // so where contacts open and close every roller pass (ρ = 0: 13 k events in 100
    // revolutions of the truck bearing) DOP853 is cheaper: 0.80 M evaluations against
    // the pair's 1.1 M (measured, `nystrom_tolerance_table`).
    let factor = match integrator {
        Integrator::Auto => Some(NYSTROM_TOLERANCE_FACTOR).filter(|_| rhs.law.clearance_m < 0.0),
        Integrator::Dop853 => None,
        Integrator::Nystrom { tolerance_factor } => Some(tolerance_factor),
    }
    .filter(|f| f.is_finite() && *f > 0.0);
    // The force depends on position and time only: no damper, and no film or the
    // steady one (its squeeze factor is 1 whatever the approach rate).
    let position_only = rhs.damping_n_s_m == 0.0
        && rhs
            .law
            .film
            .as_ref()
            .is_none_or(|f| f.squeeze == Squeeze::None);
    let nystrom = factor.filter(|_| position_only).map(|factor| {
        let rtol = (model.rtol * factor).min(1e-2);
        let atol = rtol * r_scale;
        NystromOptions {
            rtol,
            atol_position: [atol, atol, f64::INFINITY],
            atol_velocity: [
                atol * rhs.omega_ref,
                atol * rhs.omega_ref,
                if rhs.energy_integral {
                    atol
                } else {
                    f64::INFINITY
                },
            ],
            h0: None,
            h_max: f64::INFINITY,
            max_steps: MAX_STEPS,
            fixed_step: None,
        }
    });
    let s0 = model.initial_state;
    let (vx0, vy0) = (s0[2] / rhs.omega_ref, s0[3] / rhs.omega_ref);
    let mut stats = DynamicsStats::default();
    let (samples, e0) = if rhs.energy_integral {
        let y0 = [s0[0], s0[1], vx0, vy0, 0.0];
        let e0 = rhs.energy(0.0, &y0);
        let run = Run {
            rhs: &rhs,
            t_end,
            settle,
            times: &times,
            opts: &opts_base,
            nystrom: nystrom.clone(),
            cancel,
        };
        (run.integrate(y0, &mut stats, |y| *y)?, Some(e0))
    } else {
        let y0 = [s0[0], s0[1], vx0, vy0];
        let run = Run {
            rhs: &rhs,
            t_end,
            settle,
            times: &times,
            opts: &opts_base,
            nystrom,
            cancel,
        };
        (
            run.integrate(y0, &mut stats, |y| [y[0], y[1], y[2], y[3], 0.0])?,
            None,
        )
    };
    stats.film_clamps = rhs.clamps.get();
    let samples: Vec<(f64, [f64; 5])> = times.iter().copied().zip(samples).collect();

    assemble(
        model,
        &rhs,
        Assembly {
            offset,
            k,
            linearised_frequency_hz,
            fc,
            dt,
            per_cycle,
            samples,
            e0,
            stats,
        },
    )
}

/// One simulation's integration: the fixed-size DOP853 path over `CHUNKS` progress
/// chunks, restarted at every contact loss and regain.
struct Run<'a> {
    rhs: &'a Rhs,
    t_end: f64,
    settle: f64,
    times: &'a [f64],
    opts: &'a OdeOptions,
    /// `Some`: a position-only force by the Nyström 8(6) pair with these options
    /// (`h0` and `max_steps` set per segment); `None`: DOP853 with `opts`.
    nystrom: Option<NystromOptions<3>>,
    cancel: Cancel<'a>,
}

impl Run<'_> {
    /// One segment by [`solve_rkn86`] on the state (x, y, ẋ/ω_ref, ẏ/ω_ref[, q]) as
    /// (q, v) = ((x, y, 0), (ẋ, ẏ, q)), returned in the DOP853 path's form.
    #[allow(clippy::too_many_arguments)] // the segment's inputs, each distinct
    fn nystrom_segment<const N: usize>(
        &self,
        y: &[f64; N],
        t: f64,
        t_end: f64,
        opts: NystromOptions<3>,
        events: &ContactEvents<'_>,
        times: &[f64],
        record: &mut dyn FnMut(&[f64; N]),
    ) -> Result<FixedSolution<N>, OdeError> {
        let w = self.rhs.omega_ref;
        let energy = |y: &[f64; N]| y.get(4).copied().unwrap_or(0.0);
        let to_state = |q: &[f64; 3], v: &[f64; 3]| -> [f64; N] {
            std::array::from_fn(|i| match i {
                0 => q[0],
                1 => q[1],
                2 => v[0] / w,
                3 => v[1] / w,
                _ => v[2],
            })
        };
        let q0 = [y[0], y[1], 0.0];
        let v0 = [y[2] * w, y[3] * w, energy(y)];
        let sol = solve_rkn86(
            self.rhs,
            t,
            &q0,
            &v0,
            t_end,
            &opts,
            &NystromContactEvents(events),
            times,
            &mut |_, q, v| record(&to_state(q, v)),
            self.cancel,
        )?;
        Ok(FixedSolution {
            t_final: sol.t_final,
            y_final: to_state(&sol.q_final, &sol.v_final),
            stats: sol.stats,
            termination: sol.termination,
            h_next: sol.h_next,
        })
    }

    /// Integrate from `y0` at t = 0 to `t_end`, returning the states at `times`
    /// (mapped by `keep` to the stored form) and adding the work to `stats`.
    fn integrate<const N: usize>(
        &self,
        y0: [f64; N],
        stats: &mut DynamicsStats,
        keep: impl Fn(&[f64; N]) -> [f64; 5],
    ) -> Result<Vec<[f64; 5]>, DynamicsError>
    where
        Rhs: FixedSystem<N>,
    {
        let (rhs, t_end, times) = (self.rhs, self.t_end, self.times);
        let mut y = y0;
        let mut t = 0.0;
        let mut samples: Vec<[f64; 5]> = Vec::with_capacity(times.len());
        // Rollers whose event fired at `events.t0`, with the side each crossed to
        // (several cross at one instant when the load is symmetric about a roller pair).
        let mut events = ContactEvents {
            rhs,
            forced: Vec::new(),
            t0: f64::NAN,
        };
        let mut h0: Option<f64> = None;
        for chunk in 1..=CHUNKS {
            let chunk_end = if chunk == CHUNKS {
                t_end
            } else {
                t_end * chunk as f64 / CHUNKS as f64
            };
            while t < chunk_end {
                // Every sample before t is recorded (a segment records all those up to
                // where it stops), so the next ones start at samples.len().
                let first = samples.len();
                let mut last = first;
                while last < times.len() && times[last] <= chunk_end {
                    last += 1;
                }
                let max_steps = MAX_STEPS
                    .saturating_sub(stats.steps + stats.rejected)
                    .max(1);
                events.t0 = t;
                let sol = match &self.nystrom {
                    Some(nopts) => self.nystrom_segment(
                        &y,
                        t,
                        chunk_end,
                        NystromOptions {
                            h0,
                            max_steps,
                            ..nopts.clone()
                        },
                        &events,
                        &times[first..last],
                        &mut |y| samples.push(keep(y)),
                    ),
                    None => solve_dop853_fixed(
                        rhs,
                        t,
                        &y,
                        chunk_end,
                        &OdeOptions {
                            h0,
                            max_steps,
                            ..self.opts.clone()
                        },
                        &events,
                        &times[first..last],
                        &mut |_, y| samples.push(keep(y)),
                        self.cancel,
                    ),
                }
                .map_err(|e| match e {
                    OdeError::Cancelled { .. } => DynamicsError::Cancelled,
                    OdeError::MaxSteps { t, .. } => DynamicsError::TooMuchWork {
                        steps: MAX_STEPS,
                        t_s: t,
                    },
                    other => DynamicsError::Integration {
                        t_s: t,
                        reason: other.to_string(),
                    },
                })?;
                stats.steps += sol.stats.steps;
                stats.rejected += sol.stats.rejected;
                stats.rhs_evaluations += sol.stats.rhs_evaluations;
                let h_mean = (sol.t_final - t) / sol.stats.steps.max(1) as f64;
                if h_mean > 0.0 {
                    h0 = Some(h_mean);
                }
                match sol.termination {
                    Termination::Event { index, t: te } => {
                        stats.events += 1;
                        // Restart with the step the controller proposed after the step
                        // that straddled the crossing (accepted at this accuracy), not
                        // the segment's mean nor a fresh search from a small h0.
                        if sol.h_next > 0.0 && sol.h_next.is_finite() {
                            h0 = Some(sol.h_next);
                        }
                        // The side the gap crossed to: the other one than at the
                        // segment's start (as forced there, or as evaluated).
                        let was = events
                            .forced
                            .iter()
                            .find(|(j, _)| *j == index)
                            .map_or_else(|| rhs.gap(index, t, &y), |&(_, s)| s);
                        let sign = if was > 0.0 { -1.0 } else { 1.0 };
                        if sign < 0.0 && te >= self.settle {
                            stats.contact_losses_after_settle += 1;
                        }
                        // Simultaneous crossings (within Brent's location error) keep
                        // the earlier ones forced too.
                        if !((te - events.t0).abs() <= 1e-9 * te.abs().max(1.0))
                            || events.forced.is_empty()
                        {
                            events.forced.clear();
                        }
                        events.forced.retain(|(j, _)| *j != index);
                        events.forced.push((index, sign));
                        t = te;
                        y = sol.y_final;
                    }
                    Termination::ReachedEnd => {
                        events.forced.clear();
                        t = chunk_end;
                        y = sol.y_final;
                    }
                }
            }
            self.cancel.report(t / t_end);
        }
        samples.truncate(times.len());
        Ok(samples)
    }
}

/// The eigenvalue of the symmetric 2×2 `k` whose eigenvector is closest to x, and the
/// other.
fn x_eigen(k: &[[f64; 2]; 2]) -> (f64, f64) {
    let (a, b, d) = (k[0][0], k[0][1], k[1][1]);
    let mean = 0.5 * (a + d);
    let rad = (0.25 * (a - d) * (a - d) + b * b).sqrt();
    let (hi, lo) = (mean + rad, mean - rad);
    // The x-closer eigenvector belongs to the eigenvalue on a's side of the mean.
    if a >= d {
        (hi, lo)
    } else {
        (lo, hi)
    }
}

struct Assembly {
    offset: [f64; 2],
    k: [[f64; 2]; 2],
    linearised_frequency_hz: f64,
    fc: f64,
    dt: f64,
    per_cycle: usize,
    /// (t, (x, y, ẋ/ω_ref, ẏ/ω_ref, q)) with q = 0 without the energy integral.
    samples: Vec<(f64, [f64; 5])>,
    e0: Option<f64>,
    stats: DynamicsStats,
}

fn assemble(
    model: &DynamicsModel,
    rhs: &Rhs,
    a: Assembly,
) -> Result<DynamicsResult, DynamicsError> {
    let m = model.roller_count;
    let n = a.samples.len();
    let mut series = Series {
        dt_s: a.dt,
        t_s: Vec::with_capacity(n),
        x_m: Vec::with_capacity(n),
        y_m: Vec::with_capacity(n),
        vx_m_s: Vec::with_capacity(n),
        vy_m_s: Vec::with_capacity(n),
        roller_load_n: vec![Vec::with_capacity(n); m],
        film_m: vec![Vec::with_capacity(n); m],
        squeeze_velocity_m_s: vec![Vec::with_capacity(n); m],
    };
    let mut min_load = f64::INFINITY;
    let mut drift: f64 = 0.0;
    let energy_scale = {
        let (x, y) = (a.offset[0], a.offset[1]);
        (model.force_n[0] * x + model.force_n[1] * y).abs() + rhs.potential(0.0, x, y)
    };
    for (t, y) in &a.samples {
        series.t_s.push(*t);
        series.x_m.push(y[0]);
        series.y_m.push(y[1]);
        series.vx_m_s.push(y[2] * rhs.omega_ref);
        series.vy_m_s.push(y[3] * rhs.omega_ref);
        rhs.rollers(*t, y, |i, c| {
            min_load = min_load.min(c.load_n);
            series.roller_load_n[i].push(c.load_n);
            series.film_m[i].push(c.film_m);
            series.squeeze_velocity_m_s[i].push(if c.load_n > 0.0 { c.squeeze_m_s } else { 0.0 });
        });
        if let Some(e0) = a.e0 {
            drift = drift.max((rhs.energy(*t, y) - e0 - y[4] * rhs.energy_ref).abs());
        }
    }
    let energy_drift_rel = (a.e0.is_some() && model.damping_ratio == 0.0 && energy_scale > 0.0)
        .then_some(drift / energy_scale);

    let spectra = spectra::spectra(&series, a.fc, m)?;
    let mut harmonics = Vec::new();
    if a.fc > 0.0 {
        if let Some(load) = series.roller_load_n.first() {
            for order in 1..=8 {
                let f = order as f64 * a.fc;
                harmonics.push(Harmonic {
                    order,
                    frequency_hz: f,
                    amplitude_n: amplitude_at(load, a.dt, f)?,
                });
            }
        }
    }
    let cycle = if a.per_cycle > 0 && n >= a.per_cycle {
        let from = n - a.per_cycle;
        Cycle {
            cage_angle_deg: series.t_s[from..]
                .iter()
                .map(|&t| rhs.angle(0, t).to_degrees().rem_euclid(360.0))
                .collect(),
            roller_load_n: series.roller_load_n[0][from..].to_vec(),
            film_m: series.film_m[0][from..].to_vec(),
            squeeze_velocity_m_s: series.squeeze_velocity_m_s[0][from..].to_vec(),
        }
    } else {
        Cycle::default()
    };
    let loss_of_contact = a.stats.contact_losses_after_settle > 0 || min_load <= 0.0;
    Ok(DynamicsResult {
        static_offset_m: a.offset,
        stiffness_n_per_m: a.k,
        linearised_frequency_hz: a.linearised_frequency_hz,
        base_natural_frequency_hz: spectra.base_natural_frequency_hz,
        cage_frequency_hz: a.fc,
        roller_pass_frequency_hz: m as f64 * a.fc,
        min_roller_load_n: if min_load.is_finite() { min_load } else { 0.0 },
        loss_of_contact,
        energy_drift_rel,
        series,
        spectrum_x: spectra.x,
        spectrum_roller_load: spectra.roller_load,
        roller_load_harmonics: harmonics,
        cycle,
        stats: a.stats,
        note: match (&model.film, model.damping_ratio > 0.0) {
            (None, false) => "settle_revolutions is a count of shaft revolutions skipped \
                before sampling, not a convergence test: without a film or damping the \
                model is undamped, so the oscillation after release never decays"
                .to_string(),
            _ => "settle_revolutions is a count of shaft revolutions skipped before \
                sampling, not a convergence test: the release oscillation decays only \
                through the squeeze term or dynamics.damping_ratio, and what is left of it \
                shows in the spectra as the f_bn line"
                .to_string(),
        },
    })
}
