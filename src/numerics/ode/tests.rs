//! Tests of the ODE solvers against closed-form solutions and published reference
//! values. Each assertion states its tolerance and why that tolerance is the
//! right one. The suite was mutation-checked: perturbing a DOPRI5 or Rodas4
//! coefficient (a_ij, c_i, d_i, g_ij, error or dense-output weights), the Hermite
//! formula, the event direction rule, the root-finder tolerance, the stiffness
//! threshold, the cancellation check or the finite-difference increment each makes
//! at least one test fail.

use super::*;
use crate::numerics::cancel::Cancel;
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;
use std::f64::consts::{LN_2, PI};
use std::sync::atomic::{AtomicBool, Ordering};

const ALL: [Method; 3] = [Method::DormandPrince45, Method::Sdirk, Method::Auto];

fn opts(method: Method, rtol: f64, atol: f64) -> OdeOptions {
    OdeOptions {
        rtol,
        atol,
        method,
        ..OdeOptions::default()
    }
}

fn run<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    t1: f64,
    o: &OdeOptions,
    output: Output,
) -> OdeSolution {
    solve(sys, t0, y0, t1, o, &mut [], output, Cancel::NONE).unwrap()
}

/// y' = A y with the analytic Jacobian A.
struct Linear {
    a: DMatrix<f64>,
}

impl OdeSystem for Linear {
    fn dim(&self) -> usize {
        self.a.nrows()
    }
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        let v = &self.a * DVector::from_column_slice(y);
        dydt.copy_from_slice(v.as_slice());
    }
    fn jacobian(&self, _t: f64, _y: &[f64], jac: &mut DMatrix<f64>) -> bool {
        jac.copy_from(&self.a);
        true
    }
}

/// y' = y·cos t, y(0) = 1, exact y = exp(sin t): non-autonomous and nonlinear in
/// t, so it exercises the a_ij/c_i of DOPRI5 and the ∂f/∂t terms of Rodas4 beyond
/// what a linear constant-coefficient problem (which only sees the stability
/// polynomial) can detect. `analytic` toggles the Jacobian.
struct ExpSin {
    analytic: bool,
}

impl OdeSystem for ExpSin {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        dydt[0] = y[0] * t.cos();
    }
    fn jacobian(&self, t: f64, _y: &[f64], jac: &mut DMatrix<f64>) -> bool {
        jac[(0, 0)] = t.cos();
        self.analytic
    }
}

fn decay(lambda: f64) -> FnSystem<impl Fn(f64, &[f64], &mut [f64])> {
    FnSystem::new(1, move |_t, y: &[f64], d: &mut [f64]| d[0] = -lambda * y[0])
}

fn oscillator() -> FnSystem<impl Fn(f64, &[f64], &mut [f64])> {
    FnSystem::new(2, |_t, y: &[f64], d: &mut [f64]| {
        d[0] = y[1];
        d[1] = -y[0];
    })
}

// ---------------------------------------------------------------------------
// 1. Exponential decay: accuracy against tolerance, and convergence order.

#[test]
fn decay_error_is_within_tolerance_scale() {
    // y' = -λy on [0, 3] with λ = 2. With atol = rtol·1e-3 the error per step is
    // controlled relative to |y| ≤ 1, and for a contractive problem the global
    // error stays of the order of the local tolerance. Bound: 1·rtol (measured
    // worst case ≈ 0.05·rtol for both methods), and the error must shrink with rtol.
    let lambda = 2.0;
    for method in ALL {
        let mut prev = f64::INFINITY;
        for rtol in [1e-6, 1e-8, 1e-10] {
            let sol = run(
                &decay(lambda),
                0.0,
                &[1.0],
                3.0,
                &opts(method, rtol, rtol * 1e-3),
                Output::Steps,
            );
            let err = sol
                .t
                .iter()
                .zip(&sol.y)
                .map(|(&t, y)| (y[0] - (-lambda * t).exp()).abs())
                .fold(0.0, f64::max);
            eprintln!(
                "decay {method:?} rtol={rtol:e}: err={err:e} ({:.2}·rtol), steps={}",
                err / rtol,
                sol.stats.steps
            );
            assert!(err <= rtol, "{method:?} rtol={rtol}: err={err:e}");
            assert!(err < prev, "{method:?}: error did not decrease with rtol");
            prev = err;
            assert_eq!(sol.termination, Termination::ReachedEnd);
            assert_eq!(sol.t_final, 3.0);
        }
    }
}

/// Largest global error over [0, 2] of fixed-step integration of `sys` with step
/// `h`. The maximum over the trajectory rather than the error at one time, because
/// the error of a nonlinear problem can change sign and nearly vanish at any given
/// time (for exp(sin t) it does near t = 2 with Rodas4), spoiling the ratio.
fn fixed_step_error<S: OdeSystem>(sys: &S, method: Method, h: f64, exact: fn(f64) -> f64) -> f64 {
    let o = OdeOptions {
        fixed_step: Some(h),
        method,
        ..OdeOptions::default()
    };
    let sol = run(sys, 0.0, &[1.0], 2.0, &o, Output::Steps);
    sol.t
        .iter()
        .zip(&sol.y)
        .map(|(&t, y)| (y[0] - exact(t)).abs())
        .fold(0.0, f64::max)
}

fn observed_orders<S: OdeSystem>(
    sys: &S,
    method: Method,
    hs: &[f64],
    exact: fn(f64) -> f64,
) -> Vec<f64> {
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| fixed_step_error(sys, method, h, exact))
        .collect();
    eprintln!("{method:?} errors {errs:?}");
    errs.windows(2)
        .zip(hs.windows(2))
        .map(|(e, h)| (e[0] / e[1]).ln() / (h[0] / h[1]).ln())
        .collect()
}

fn exp_minus(t: f64) -> f64 {
    (-t).exp()
}

fn exp_sin(t: f64) -> f64 {
    t.sin().exp()
}

#[test]
fn dopri5_fixed_step_converges_with_order_5() {
    // Halving h must divide the error by ≈ 2^5. Window [4.6, 5.4]: the observed
    // order approaches 5 from above/below by O(h) terms; a wrong coefficient drops
    // it to ≤ 4 (or lower), which this window rejects.
    let hs = [0.2, 0.1, 0.05];
    for p in observed_orders(&decay(1.0), Method::DormandPrince45, &hs, exp_minus) {
        assert!((4.6..=5.4).contains(&p), "decay order {p}");
    }
    for p in observed_orders(
        &ExpSin { analytic: true },
        Method::DormandPrince45,
        &hs,
        exp_sin,
    ) {
        assert!((4.6..=5.4).contains(&p), "exp(sin) order {p}");
    }
}

#[test]
fn rodas4_fixed_step_converges_with_order_4() {
    // Halving h must divide the error by ≈ 2^4; window [3.6, 4.4] for the same
    // reason as above. Both with the analytic Jacobian and with finite differences
    // (whose O(sqrt(ε)) error is far below the truncation error at these steps).
    let hs = [0.1, 0.05, 0.025];
    for p in observed_orders(&decay(1.0), Method::Sdirk, &hs, exp_minus) {
        assert!((3.6..=4.4).contains(&p), "decay order {p}");
    }
    for analytic in [true, false] {
        for p in observed_orders(&ExpSin { analytic }, Method::Sdirk, &hs, exp_sin) {
            assert!(
                (3.6..=4.4).contains(&p),
                "exp(sin) analytic={analytic} order {p}"
            );
        }
    }
}

#[test]
fn adaptive_error_is_proportional_to_tolerance() {
    // Tolerance proportionality: both methods propagate the higher-order solution
    // while controlling the lower-order estimate (local extrapolation), so the
    // global error scales roughly like rtol. Over two decades of rtol the error
    // ratio must lie in [10, 1000], i.e. a log-log slope of 0.5..1.5 (measured
    // ≈ 94 for DOPRI5 and ≈ 80 for Rodas4).
    let exact = 2f64.sin().exp();
    for method in [Method::DormandPrince45, Method::Sdirk] {
        let err = |rtol: f64| {
            let sol = run(
                &ExpSin { analytic: false },
                0.0,
                &[1.0],
                2.0,
                &opts(method, rtol, rtol),
                Output::Final,
            );
            (sol.y_final[0] - exact).abs()
        };
        let ratio = err(1e-6) / err(1e-8);
        eprintln!("{method:?} proportionality ratio {ratio}");
        assert!(
            (10.0..=1000.0).contains(&ratio),
            "{method:?}: ratio {ratio}"
        );
    }
}

// ---------------------------------------------------------------------------
// 2. Harmonic oscillator: energy drift over 100 periods.

#[test]
fn oscillator_energy_drift_is_bounded_and_proportional_to_tolerance() {
    // E = (y1² + y2²)/2 is conserved exactly; neither method is symplectic, so E
    // drifts by roughly (local error per step) × (steps), which tolerance control
    // keeps ∝ rtol. Over 100 periods the drift must stay below 250·rtol (measured
    // ≈ 56·rtol for DOPRI5, ≈ 1·rtol for Rodas4, whose L-stability damps rather
    // than pumps energy), and tightening rtol by 100× must reduce it by a factor
    // in [20, 2000] (measured ≈ 100 and ≈ 300).
    let t_end = 200.0 * PI;
    for method in [Method::DormandPrince45, Method::Sdirk] {
        let drift = |rtol: f64| {
            let sol = run(
                &oscillator(),
                0.0,
                &[1.0, 0.0],
                t_end,
                &opts(method, rtol, rtol * 1e-3),
                Output::Steps,
            );
            let e = |y: &Vec<f64>| 0.5 * (y[0] * y[0] + y[1] * y[1]);
            let d = sol.y.iter().map(|y| (e(y) - 0.5).abs()).fold(0.0, f64::max);
            // The phase after 100 periods is also a good check of accuracy.
            let phase_err = (sol.y_final[0] - 1.0).abs() + sol.y_final[1].abs();
            eprintln!("{method:?} rtol={rtol:e} drift={d:e} ({:.1}·rtol) phase_err={phase_err:e} steps={}", d / rtol, sol.stats.steps);
            d
        };
        let rtols: &[f64] = match method {
            Method::DormandPrince45 => &[1e-6, 1e-8, 1e-10],
            _ => &[1e-6, 1e-8],
        };
        let drifts: Vec<f64> = rtols.iter().map(|&r| drift(r)).collect();
        for (&r, &d) in rtols.iter().zip(&drifts) {
            assert!(d <= 250.0 * r, "{method:?} rtol={r}: drift {d:e}");
        }
        for w in drifts.windows(2) {
            let ratio = w[0] / w[1];
            assert!(
                (20.0..=2000.0).contains(&ratio),
                "{method:?}: drift ratio {ratio}"
            );
        }
    }
}

// ---------------------------------------------------------------------------
// 3. Stiff problems.

/// Robertson's chemical kinetics (Hairer & Wanner, Solving ODE II, §IV.1, eq. 1.4).
struct Robertson;

impl OdeSystem for Robertson {
    fn dim(&self) -> usize {
        3
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        d[2] = 3e7 * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
}

#[test]
fn robertson_to_1e5_with_rodas4() {
    // Robertson's problem as in Hairer & Wanner II, §IV.1 (eq. 1.4); reference at
    // t = 1e5: y1 ≈ 1.786e-2, y3 ≈ 0.9821 (this run gives 0.0178659 and 0.982134),
    // asserted to 1e-3 relative, which rtol = 1e-6 comfortably resolves. Mass
    // conservation y1 + y2 + y3 = 1 holds to rounding because Rosenbrock methods
    // preserve linear invariants. "Few hundred steps" (measured 183): an explicit
    // method would be held to h ≈ 3.3/|λ_max| ~ 1e-4 over the whole interval.
    let o = opts(Method::Sdirk, 1e-6, 1e-10);
    let sol = run(&Robertson, 0.0, &[1.0, 0.0, 0.0], 1e5, &o, Output::Final);
    let y = &sol.y_final;
    eprintln!("robertson y={y:?} stats={:?}", sol.stats);
    assert!((y[0] / 1.786e-2 - 1.0).abs() < 1e-3, "y1 = {}", y[0]);
    assert!((y[2] / 0.9821 - 1.0).abs() < 1e-3, "y3 = {}", y[2]);
    assert!((y[0] + y[1] + y[2] - 1.0).abs() < 1e-12);
    assert!(sol.stats.steps < 400, "steps {}", sol.stats.steps);
    assert!(sol.stats.lu_decompositions >= sol.stats.steps);
    assert!(sol.stats.jacobian_evaluations >= sol.stats.steps);
}

/// Van der Pol with μ = 1000 in Hairer's time-scaled form (t_scaled = t/μ,
/// ε = 1/μ² = 1e-6): y1' = y2, y2' = ((1 − y1²) y2 − y1)/ε.
struct VanDerPol {
    eps: f64,
}

impl OdeSystem for VanDerPol {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = y[1];
        d[1] = ((1.0 - y[0] * y[0]) * y[1] - y[0]) / self.eps;
    }
}

#[test]
fn van_der_pol_mu_1000_with_rodas4_matches_reference() {
    // Reference from Hairer's test set (vdpol, ε = 1e-6, y0 = (2, 0)) at t = 2:
    // y1 = 1.706167732170483, y2 = -0.8928097010247975. The interval crosses two
    // relaxation jumps, so a 1e-3 relative match checks the step control through
    // the fast transients, not just the slow manifold.
    let o = opts(Method::Sdirk, 1e-6, 1e-6);
    let sol = run(
        &VanDerPol { eps: 1e-6 },
        0.0,
        &[2.0, 0.0],
        2.0,
        &o,
        Output::Final,
    );
    let y = &sol.y_final;
    eprintln!("vdp y={y:?} stats={:?}", sol.stats);
    assert!(
        (y[0] / 1.706167732170483 - 1.0).abs() < 1e-3,
        "y1 = {}",
        y[0]
    );
    assert!(
        (y[1] / -0.8928097010247975 - 1.0).abs() < 1e-3,
        "y2 = {}",
        y[1]
    );
    assert!(sol.stats.steps < 2000, "steps {}", sol.stats.steps);
}

#[test]
fn auto_switches_on_van_der_pol_and_saves_work() {
    // On [0, 0.02] (scaled time) the problem is stiff from the start (λ ≈ −3e6), so
    // DOPRI5 is held at h ≈ 3.3/3e6 by stability: ~2e4 steps. Auto must detect
    // this within a few dozen steps, switch, and then use far fewer evaluations;
    // we require a factor ≥ 50 (measured ≈ 340), and agreement between the two
    // results to 1e-4 relative (both run at rtol 1e-6).
    let sys = VanDerPol { eps: 1e-6 };
    let t_end = 0.02;
    let dp = run(
        &sys,
        0.0,
        &[2.0, 0.0],
        t_end,
        &opts(Method::DormandPrince45, 1e-6, 1e-6),
        Output::Final,
    );
    let auto = run(
        &sys,
        0.0,
        &[2.0, 0.0],
        t_end,
        &opts(Method::Auto, 1e-6, 1e-6),
        Output::Final,
    );
    eprintln!("dopri {:?}\nauto {:?}", dp.stats, auto.stats);
    let switched = auto.stats.switched_to_implicit_at.unwrap();
    assert!(switched > 0.0 && switched < 1e-3, "switched at {switched}");
    assert!(dp.stats.switched_to_implicit_at.is_none());
    let ratio = dp.stats.rhs_evaluations as f64 / auto.stats.rhs_evaluations as f64;
    assert!(ratio >= 50.0, "rhs ratio only {ratio}");
    for (a, b) in auto.y_final.iter().zip(&dp.y_final) {
        assert!((a / b - 1.0).abs() < 1e-4, "{a} vs {b}");
    }
}

#[test]
fn auto_does_not_switch_on_a_non_stiff_problem() {
    // The oscillator has |λ| = 1; h·ρ ≈ h stays far below 3.25 at any sensible
    // tolerance, so a switch would be a false positive of the detector.
    let sol = run(
        &oscillator(),
        0.0,
        &[1.0, 0.0],
        20.0,
        &opts(Method::Auto, 1e-8, 1e-10),
        Output::Final,
    );
    assert_eq!(sol.stats.switched_to_implicit_at, None);
    assert_eq!(sol.stats.lu_decompositions, 0);
}

// ---------------------------------------------------------------------------
// 4. Linear stiff 4×4 system against the matrix exponential.

#[test]
fn linear_stiff_system_matches_matrix_exponential() {
    // A = P·diag(−1, −4e5, −1, −4e5)·P⁻¹ with a non-orthogonal P, so all components
    // mix fast and slow modes. Exact solution y(t) = P·exp(D t)·P⁻¹·y0. The fast
    // modes decay to below 1e-100 after t = 1e-3, so the check is that the method
    // damps them (L-stability) while resolving the slow ones to tolerance:
    // |error| ≤ 10·(rtol·|y| + atol) with rtol = 1e-8.
    let p = DMatrix::from_row_slice(
        4,
        4,
        &[
            1.0, 2.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0, 1.0, 0.0, 1.0,
        ],
    );
    let p_inv = p.clone().try_inverse().unwrap();
    let d = [-1.0, -4e5, -1.0, -4e5];
    let a = &p * DMatrix::from_diagonal(&DVector::from_column_slice(&d)) * &p_inv;
    let y0 = [1.0, -1.0, 0.5, 2.0];
    let exact = |t: f64| {
        let e = DMatrix::from_diagonal(&DVector::from_iterator(4, d.iter().map(|l| (l * t).exp())));
        &p * e * &p_inv * DVector::from_column_slice(&y0)
    };
    let times = vec![1e-6, 1e-5, 1e-3, 0.1, 1.0, 5.0, 10.0];
    let (rtol, atol) = (1e-8, 1e-10);
    for method in [Method::Sdirk, Method::Auto] {
        let sys = Linear { a: a.clone() };
        let sol = run(
            &sys,
            0.0,
            &y0,
            10.0,
            &opts(method, rtol, atol),
            Output::Times(times.clone()),
        );
        eprintln!("linear {method:?} stats {:?}", sol.stats);
        assert_eq!(sol.t, times);
        for (&t, y) in sol.t.iter().zip(&sol.y) {
            let ex = exact(t);
            for (yi, ei) in y.iter().zip(ex.iter()) {
                let bound = 10.0 * (rtol * ei.abs().max(1.0) + atol);
                assert!((yi - ei).abs() <= bound, "{method:?} t={t}: {yi} vs {ei}");
            }
        }
        // An explicit method needs t_end·4e5/3.3 ≈ 1.2e6 steps; Rodas4 a few hundred.
        assert!(
            sol.stats.steps < 1000,
            "{method:?} steps {}",
            sol.stats.steps
        );
    }
}

// ---------------------------------------------------------------------------
// 5. Events.

#[test]
fn event_crossing_half_is_at_ln2() {
    // y = exp(−t) reaches 0.5 at ln 2. At rtol = 1e-12 the dense output is accurate
    // to ~1e-12, and |dy/dt| = 0.5 there, so t is accurate to ~2e-12: assert 1e-10.
    for (method, rtol, tol_t) in [
        (Method::DormandPrince45, 1e-12, 1e-10),
        // Hermite cubic dense output of Rodas4: ~h⁴/384 · |y''''|; at rtol 1e-10 the
        // location error is ~1e-10, so assert 1e-8.
        (Method::Sdirk, 1e-10, 1e-8),
    ] {
        let mut ev = FnEvent::new(|_t, y: &[f64]| y[0] - 0.5);
        let sol = solve(
            &decay(1.0),
            0.0,
            &[1.0],
            2.0,
            &opts(method, rtol, rtol * 1e-2),
            &mut [&mut ev],
            Output::Final,
            Cancel::NONE,
        )
        .unwrap();
        assert_eq!(sol.events.len(), 1);
        let e = &sol.events[0];
        eprintln!("{method:?} event t err {:e}", e.t - LN_2);
        assert_eq!(e.index, 0);
        assert!((e.t - LN_2).abs() < tol_t, "{method:?}: t = {}", e.t);
        assert!((e.y[0] - 0.5).abs() < tol_t);
        // Non-terminal: integration continues to the end.
        assert_eq!(sol.termination, Termination::ReachedEnd);
        assert_eq!(sol.t_final, 2.0);
    }
}

#[test]
fn terminal_event_stops_the_solve() {
    let mut other = FnEvent::new(|t, _y: &[f64]| t - 5.0); // would fire later
    let mut stop = FnEvent::new(|_t, y: &[f64]| y[0] - 0.5).with_terminal(true);
    let sol = solve(
        &decay(1.0),
        0.0,
        &[1.0],
        10.0,
        &opts(Method::DormandPrince45, 1e-10, 1e-12),
        &mut [&mut other, &mut stop],
        Output::Steps,
        Cancel::NONE,
    )
    .unwrap();
    match sol.termination {
        Termination::Event { index, t } => {
            assert_eq!(index, 1);
            assert!((t - LN_2).abs() < 1e-9);
        }
        other => panic!("expected a terminal event, got {other:?}"),
    }
    assert_eq!(sol.events.len(), 1, "the later event must not be reported");
    assert_eq!(sol.t_final, sol.events[0].t);
    assert!((sol.y_final[0] - 0.5).abs() < 1e-9);
    // Every-step output ends at the event, not at the end of the step.
    assert_eq!(*sol.t.last().unwrap(), sol.t_final);
    assert!(sol.t.iter().all(|&t| t <= sol.t_final));
}

#[test]
fn event_direction_filtering() {
    // y1 = cos t on [0, 10]: falling zeros at π/2 and 5π/2, a rising zero at 3π/2.
    let g = |_t: f64, y: &[f64]| y[0];
    let mut both = FnEvent::new(g);
    let mut rising = FnEvent::new(g).with_direction(Direction::Rising);
    let mut falling = FnEvent::new(g).with_direction(Direction::Falling);
    let sol = solve(
        &oscillator(),
        0.0,
        &[1.0, 0.0],
        10.0,
        &opts(Method::DormandPrince45, 1e-10, 1e-12),
        &mut [&mut both, &mut rising, &mut falling],
        Output::Final,
        Cancel::NONE,
    )
    .unwrap();
    let times = |index: usize| -> Vec<f64> {
        sol.events
            .iter()
            .filter(|e| e.index == index)
            .map(|e| e.t)
            .collect()
    };
    let close = |a: &[f64], b: &[f64]| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-8)
    };
    assert!(
        close(&times(0), &[0.5 * PI, 1.5 * PI, 2.5 * PI]),
        "{:?}",
        times(0)
    );
    assert!(close(&times(1), &[1.5 * PI]), "{:?}", times(1));
    assert!(close(&times(2), &[0.5 * PI, 2.5 * PI]), "{:?}", times(2));
    // Events are reported in time order.
    assert!(sol.events.windows(2).all(|w| w[0].t <= w[1].t));
}

#[test]
fn events_work_backwards_and_ignore_a_zero_at_the_start() {
    // Integrate y' = −y backwards from t = 2 (y = e^-2) to 0: y rises through 0.5
    // at ln 2 ("rising" along the direction of integration). A second event that is
    // exactly zero at t0 must not fire.
    let mut half = FnEvent::new(|_t, y: &[f64]| y[0] - 0.5).with_direction(Direction::Rising);
    let mut at_start = FnEvent::new(|t, _y: &[f64]| t - 2.0);
    let sol = solve(
        &decay(1.0),
        2.0,
        &[(-2.0f64).exp()],
        0.0,
        &opts(Method::DormandPrince45, 1e-12, 1e-14),
        &mut [&mut half, &mut at_start],
        Output::Final,
        Cancel::NONE,
    )
    .unwrap();
    assert_eq!(sol.events.len(), 1, "{:?}", sol.events);
    assert!((sol.events[0].t - LN_2).abs() < 1e-10);
    assert!(
        (sol.y_final[0] - 1.0).abs() < 1e-10,
        "y(0) = {}",
        sol.y_final[0]
    );
}

// ---------------------------------------------------------------------------
// 6. Dense output.

#[test]
fn dense_output_matches_exact_solution_without_extra_steps() {
    // 201 output times over ~3 periods of the oscillator. The
    // interpolants are one order lower than the step (4 for DOPRI5, 3 for the
    // Hermite cubic), so allow 20·rtol. Requesting outputs must not change the
    // step sequence: the step count equals that of a Final-only run.
    let times: Vec<f64> = (0..=200).map(|i| f64::from(i) * 0.1).collect();
    for method in [Method::DormandPrince45, Method::Sdirk] {
        let rtol = 1e-8;
        let o = opts(method, rtol, rtol * 1e-2);
        let sol = run(
            &oscillator(),
            0.0,
            &[1.0, 0.0],
            20.0,
            &o,
            Output::Times(times.clone()),
        );
        let plain = run(&oscillator(), 0.0, &[1.0, 0.0], 20.0, &o, Output::Final);
        assert_eq!(sol.stats.steps, plain.stats.steps);
        assert_eq!(sol.t, times);
        let worst = sol
            .t
            .iter()
            .zip(&sol.y)
            .map(|(&t, y)| (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs()))
            .fold(0.0, f64::max);
        eprintln!(
            "dense {method:?}: worst {worst:e} ({:.1}·rtol)",
            worst / rtol
        );
        assert!(
            worst < 20.0 * rtol,
            "{method:?}: worst dense error {worst:e}"
        );
    }
}

// ---------------------------------------------------------------------------
// 7. Failure modes.

#[test]
fn preset_cancel_flag_returns_cancelled() {
    let flag = AtomicBool::new(true);
    let r = solve(
        &decay(1.0),
        0.0,
        &[1.0],
        1.0,
        &OdeOptions::default(),
        &mut [],
        Output::Final,
        Cancel::new(&flag),
    );
    assert_eq!(r, Err(OdeError::Cancelled { t: 0.0 }));
}

#[test]
fn cancel_during_integration_stops_at_the_next_step() {
    // The rhs raises the flag once t passes 1; the solver must stop within a step.
    let flag = AtomicBool::new(false);
    let sys = FnSystem::new(1, |t, y: &[f64], d: &mut [f64]| {
        if t > 1.0 {
            flag.store(true, Ordering::Relaxed);
        }
        d[0] = -y[0];
    });
    let o = OdeOptions {
        h_max: 0.01,
        ..OdeOptions::default()
    };
    match solve(
        &sys,
        0.0,
        &[1.0],
        100.0,
        &o,
        &mut [],
        Output::Final,
        Cancel::new(&flag),
    ) {
        Err(OdeError::Cancelled { t }) => assert!((1.0..=1.02).contains(&t), "t = {t}"),
        other => panic!("expected Cancelled, got {other:?}"),
    }
}

#[test]
fn max_steps_reports_the_numbers() {
    let o = OdeOptions {
        max_steps: 10,
        method: Method::DormandPrince45,
        ..OdeOptions::default()
    };
    match solve(
        &oscillator(),
        0.0,
        &[1.0, 0.0],
        1000.0,
        &o,
        &mut [],
        Output::Final,
        Cancel::NONE,
    ) {
        Err(OdeError::MaxSteps { steps, t }) => {
            assert_eq!(steps, 10);
            assert!(t > 0.0 && t < 1000.0, "t = {t}");
        }
        other => panic!("expected MaxSteps, got {other:?}"),
    }
}

#[test]
fn nan_rhs_returns_non_finite() {
    // NaN everywhere: detected at the very first evaluation.
    let nan = FnSystem::new(1, |_t, _y: &[f64], d: &mut [f64]| d[0] = f64::NAN);
    for method in ALL {
        let r = solve(
            &nan,
            0.0,
            &[1.0],
            1.0,
            &opts(method, 1e-6, 1e-9),
            &mut [],
            Output::Final,
            Cancel::NONE,
        );
        assert_eq!(r, Err(OdeError::NonFinite { t: 0.0 }), "{method:?}");
    }
    // NaN beyond t = 0.5: the solver shrinks the step towards 0.5, then reports
    // NonFinite (not StepTooSmall) right there.
    let late = FnSystem::new(1, |t, y: &[f64], d: &mut [f64]| {
        d[0] = if t > 0.5 { f64::NAN } else { -y[0] }
    });
    for method in ALL {
        match solve(
            &late,
            0.0,
            &[1.0],
            1.0,
            &opts(method, 1e-6, 1e-9),
            &mut [],
            Output::Final,
            Cancel::NONE,
        ) {
            Err(OdeError::NonFinite { t }) => {
                assert!((0.5 - 1e-6..=0.5).contains(&t), "{method:?}: t = {t}")
            }
            other => panic!("{method:?}: expected NonFinite, got {other:?}"),
        }
    }
}

#[test]
fn blow_up_returns_step_too_small() {
    // y' = y², y(0) = 1 has the solution 1/(1 − t), singular at t = 1. The step
    // size collapses to ~16 ulps of t near the singularity (the numerical
    // solution blows up within ~1e-6 of it), which must be StepTooSmall at t ≈ 1
    // with the offending h, not a hang or a NonFinite.
    let sys = FnSystem::new(1, |_t, y: &[f64], d: &mut [f64]| d[0] = y[0] * y[0]);
    for method in [Method::DormandPrince45, Method::Sdirk] {
        match solve(
            &sys,
            0.0,
            &[1.0],
            2.0,
            &opts(method, 1e-6, 1e-9),
            &mut [],
            Output::Final,
            Cancel::NONE,
        ) {
            Err(OdeError::StepTooSmall { t, h }) => {
                assert!((t - 1.0).abs() < 1e-3, "{method:?}: t = {t}");
                assert!(
                    h.abs() <= 16.0 * f64::EPSILON * t.abs(),
                    "{method:?}: h = {h}"
                );
            }
            other => panic!("{method:?}: expected StepTooSmall, got {other:?}"),
        }
    }
}

#[test]
fn singular_iteration_matrix() {
    // y' = 8y with the exact Jacobian 8: Rodas4's matrix 1/(hγ) − J vanishes
    // exactly for h = 0.5 (γ = 1/4). With a fixed step that is an error carrying
    // t and h; adaptively the solver halves h once and carries on, reaching
    // e^8 to tolerance (rtol 1e-8 → 1e-6 relative, allowing for error growth of
    // an unstable problem).
    let sys = Linear {
        a: DMatrix::from_element(1, 1, 8.0),
    };
    let fixed = OdeOptions {
        fixed_step: Some(0.5),
        method: Method::Sdirk,
        ..OdeOptions::default()
    };
    let r = solve(
        &sys,
        0.0,
        &[1.0],
        1.0,
        &fixed,
        &mut [],
        Output::Final,
        Cancel::NONE,
    );
    assert_eq!(r, Err(OdeError::SingularMatrix { t: 0.0, h: 0.5 }));
    let adaptive = OdeOptions {
        h0: Some(0.5),
        ..opts(Method::Sdirk, 1e-8, 1e-8)
    };
    let sol = run(&sys, 0.0, &[1.0], 1.0, &adaptive, Output::Final);
    assert!(sol.stats.rejected >= 1);
    assert!(
        (sol.y_final[0] / 8f64.exp() - 1.0).abs() < 1e-6,
        "{}",
        sol.y_final[0]
    );
}

#[test]
fn jacobian_of_wrong_shape_is_invalid_input() {
    // A system whose jacobian() replaces the matrix must not make the solver panic.
    struct Resizes;
    impl OdeSystem for Resizes {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
            d[0] = -y[0];
            d[1] = -y[1];
        }
        fn jacobian(&self, _t: f64, _y: &[f64], jac: &mut DMatrix<f64>) -> bool {
            *jac = DMatrix::identity(3, 3);
            true
        }
    }
    let r = solve(
        &Resizes,
        0.0,
        &[1.0, 1.0],
        1.0,
        &opts(Method::Sdirk, 1e-6, 1e-9),
        &mut [],
        Output::Final,
        Cancel::NONE,
    );
    assert!(
        matches!(r, Err(OdeError::InvalidInput { ref what }) if what.contains("3×3")),
        "{r:?}"
    );
}

#[test]
fn step_output_is_monotone_and_complete() {
    for (t0, t1) in [(0.0f64, 5.0f64), (5.0, 0.0)] {
        let y0 = [(-t0).exp()];
        let sol = run(
            &decay(1.0),
            t0,
            &y0,
            t1,
            &opts(Method::Auto, 1e-8, 1e-10),
            Output::Steps,
        );
        assert_eq!(sol.t.len(), sol.stats.steps + 1);
        assert_eq!(sol.t[0], t0);
        assert_eq!(*sol.t.last().unwrap(), t1);
        let dir = (t1 - t0).signum();
        assert!(sol.t.windows(2).all(|w| dir * (w[1] - w[0]) > 0.0));
        assert_eq!(sol.y.last().unwrap(), &sol.y_final);
        assert!((sol.y_final[0] / (-t1).exp() - 1.0).abs() < 1e-7);
    }
}

#[test]
fn invalid_inputs_are_rejected() {
    let sys = decay(1.0);
    let d = OdeOptions::default();
    let bad = |r: Result<OdeSolution, OdeError>| matches!(r, Err(OdeError::InvalidInput { .. }));
    let s = |t0: f64, y0: &[f64], t1: f64, o: &OdeOptions, out: Output| {
        solve(&sys, t0, y0, t1, o, &mut [], out, Cancel::NONE)
    };
    assert!(bad(s(0.0, &[1.0], f64::NAN, &d, Output::Final)));
    assert!(bad(s(0.0, &[1.0], f64::INFINITY, &d, Output::Final)));
    assert!(bad(s(f64::NAN, &[1.0], 1.0, &d, Output::Final)));
    assert!(bad(s(0.0, &[1.0, 2.0], 1.0, &d, Output::Final)));
    assert!(bad(s(0.0, &[f64::NAN], 1.0, &d, Output::Final)));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            rtol: 0.0,
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            rtol: -1e-6,
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            atol: 0.0,
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            h_max: 0.0,
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            h0: Some(f64::NAN),
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(
        0.0,
        &[1.0],
        1.0,
        &OdeOptions {
            fixed_step: Some(0.0),
            ..d.clone()
        },
        Output::Final
    )));
    assert!(bad(s(0.0, &[1.0], 1.0, &d, Output::Times(vec![0.5, 0.2]))));
    assert!(bad(s(0.0, &[1.0], 1.0, &d, Output::Times(vec![0.5, 1.5]))));
    assert!(bad(s(0.0, &[1.0], 1.0, &d, Output::Times(vec![f64::NAN]))));
    let empty = FnSystem::new(0, |_t, _y: &[f64], _d: &mut [f64]| {});
    assert!(bad(solve(
        &empty,
        0.0,
        &[],
        1.0,
        &d,
        &mut [],
        Output::Final,
        Cancel::NONE
    )));
    // The message names the problem.
    let msg = s(0.0, &[1.0], f64::INFINITY, &d, Output::Final)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("t_end"), "{msg}");
}

#[test]
fn zero_length_interval_returns_the_initial_state() {
    let sol = run(
        &decay(1.0),
        1.0,
        &[3.0],
        1.0,
        &OdeOptions::default(),
        Output::Times(vec![1.0]),
    );
    assert_eq!(sol.t, vec![1.0]);
    assert_eq!(sol.y, vec![vec![3.0]]);
    assert_eq!(sol.stats.steps, 0);
}

// ---------------------------------------------------------------------------
// 8. Property test: random decaying 2×2 linear systems.

/// exp(A t) for a 2×2 matrix via Cayley–Hamilton: with τ = tr A / 2 and
/// s² = τ² − det A, exp(At) = e^{τt}[c·I + σ·(A − τI)], where c = cosh(st) and
/// σ = sinh(st)/s (or cos/sin for s² < 0, and c = 1, σ = t for s = 0).
fn expm2(a: [[f64; 2]; 2], t: f64) -> [[f64; 2]; 2] {
    let tau = 0.5 * (a[0][0] + a[1][1]);
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let s2 = tau * tau - det;
    let (c, sigma) = if s2 > 1e-12 {
        let s = s2.sqrt();
        ((s * t).cosh(), (s * t).sinh() / s)
    } else if s2 < -1e-12 {
        let s = (-s2).sqrt();
        ((s * t).cos(), (s * t).sin() / s)
    } else {
        (1.0, t)
    };
    let e = (tau * t).exp();
    [
        [e * (c + sigma * (a[0][0] - tau)), e * sigma * a[0][1]],
        [e * sigma * a[1][0], e * (c + sigma * (a[1][1] - tau))],
    ]
}

#[test]
fn expm2_matches_series() {
    let a = [[-1.0, 2.0], [-3.0, -0.5]];
    let t = 0.7;
    // Taylor series to 40 terms converges to rounding for ‖At‖ ≈ 2.
    let mut term = [[1.0, 0.0], [0.0, 1.0]];
    let mut sum = term;
    for k in 1..40 {
        let mut next = [[0.0; 2]; 2];
        for i in 0..2 {
            for j in 0..2 {
                next[i][j] = (a[i][0] * term[0][j] + a[i][1] * term[1][j]) * t / f64::from(k);
            }
        }
        term = next;
        for i in 0..2 {
            for j in 0..2 {
                sum[i][j] += term[i][j];
            }
        }
    }
    let e = expm2(a, t);
    for i in 0..2 {
        for j in 0..2 {
            assert!((e[i][j] - sum[i][j]).abs() < 1e-13);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// A = −S + K with S symmetric positive definite and K skew, so ‖y‖₂ decays
    /// monotonically and every mode is damped. The global error of a contractive
    /// problem under error-per-step control stays within a small multiple of the
    /// tolerance scale rtol·‖y0‖∞ + atol; the property demands 100×.
    #[test]
    fn random_decaying_linear_systems(
        s1 in 0.1f64..5.0,
        s2 in 0.1f64..5.0,
        corr in -0.9f64..0.9,
        k in -5.0f64..5.0,
        y0 in prop::array::uniform2(-10.0f64..10.0),
        t_end in 0.1f64..10.0,
        log_rtol in -10.0f64..-4.0,
        atol_factor in 0.001f64..1.0,
        method_ix in 0usize..3,
    ) {
        let s12 = corr * (s1 * s2).sqrt();
        let a = [[-s1, -s12 + k], [-s12 - k, -s2]];
        let rtol = 10f64.powf(log_rtol);
        let atol = rtol * atol_factor;
        let sys = Linear { a: DMatrix::from_row_slice(2, 2, &[a[0][0], a[0][1], a[1][0], a[1][1]]) };
        let o = opts(ALL[method_ix], rtol, atol);
        let sol = solve(&sys, 0.0, &y0, t_end, &o, &mut [], Output::Final, Cancel::NONE);
        prop_assert!(sol.is_ok(), "{:?}", sol);
        let sol = sol.unwrap();
        let e = expm2(a, t_end);
        let exact = [e[0][0] * y0[0] + e[0][1] * y0[1], e[1][0] * y0[0] + e[1][1] * y0[1]];
        let scale = rtol * y0[0].abs().max(y0[1].abs()) + atol;
        for (yi, ei) in sol.y_final.iter().zip(exact) {
            prop_assert!((yi - ei).abs() <= 100.0 * scale, "{:?}: {} vs {} (scale {:e})", ALL[method_ix], yi, ei, scale);
        }
    }
}

// ---------------------------------------------------------------------------
// DOP853.

/// Largest error of fixed-step DOP853 on the harmonic oscillator y'' = −y from (1, 0)
/// over [0, 10] (about 1.6 periods), against (cos t, −sin t).
fn oscillator_fixed_step_error(method: Method, h: f64) -> f64 {
    let o = OdeOptions {
        fixed_step: Some(h),
        method,
        ..OdeOptions::default()
    };
    let sol = run(&oscillator(), 0.0, &[1.0, 0.0], 10.0, &o, Output::Steps);
    sol.t
        .iter()
        .zip(&sol.y)
        .map(|(&t, y)| (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs()))
        .fold(0.0, f64::max)
}

#[test]
fn dop853_fixed_step_converges_with_order_8() {
    // Halving h must divide the error by ≈ 2^8. Window [7.4, 8.6]: steps large enough
    // that the errors (1e-7 … 1e-10) stay far above rounding; a wrong coefficient in
    // the tableau drops the order to ≤ 7 (most to ≤ 5), which the window rejects.
    let hs = [0.8, 0.4, 0.2];
    for p in observed_orders(&decay(1.0), Method::Dop853, &hs, exp_minus) {
        assert!((7.4..=8.6).contains(&p), "decay order {p}");
    }
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| oscillator_fixed_step_error(Method::Dop853, h))
        .collect();
    eprintln!("oscillator errors {errs:?}");
    for e in errs.windows(2) {
        let p = (e[0] / e[1]).log2();
        assert!((7.4..=8.6).contains(&p), "oscillator order {p}");
    }
}

#[test]
fn dop853_dense_output_matches_the_exact_solution() {
    // 201 output times over ~3 periods. The extension is of order 7 against the step's
    // 8, so allow 20·rtol as for DOPRI5; outputs build the dense output lazily and must
    // not change the step sequence.
    let times: Vec<f64> = (0..=200).map(|i| f64::from(i) * 0.1).collect();
    for rtol in [1e-6, 1e-9, 1e-12] {
        let o = opts(Method::Dop853, rtol, rtol * 1e-2);
        let sol = run(
            &oscillator(),
            0.0,
            &[1.0, 0.0],
            20.0,
            &o,
            Output::Times(times.clone()),
        );
        let plain = run(&oscillator(), 0.0, &[1.0, 0.0], 20.0, &o, Output::Final);
        assert_eq!(sol.stats.steps, plain.stats.steps);
        assert_eq!(sol.t, times);
        let worst = sol
            .t
            .iter()
            .zip(&sol.y)
            .map(|(&t, y)| (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs()))
            .fold(0.0, f64::max);
        eprintln!("dense DOP853 rtol {rtol:e}: worst {worst:e}");
        assert!(
            worst < 20.0 * rtol,
            "rtol {rtol:e}: worst dense error {worst:e}"
        );
    }
}

#[test]
fn dop853_locates_events_as_dopri5_does() {
    // exp(−t) = 0.5 at ln 2 (non-terminal), and the oscillator's cos t = 0 at π/2
    // (terminal). At rtol 1e-12 both methods' dense outputs are accurate to ~1e-12
    // and the slopes are 0.5 and 1, so the times are within 1e-10 of the exact ones
    // and of each other.
    for method in [Method::DormandPrince45, Method::Dop853] {
        let mut ev = FnEvent::new(|_t, y: &[f64]| y[0] - 0.5);
        let sol = solve(
            &decay(1.0),
            0.0,
            &[1.0],
            2.0,
            &opts(method, 1e-12, 1e-14),
            &mut [&mut ev],
            Output::Final,
            Cancel::NONE,
        )
        .unwrap();
        assert_eq!(sol.events.len(), 1);
        assert!((sol.events[0].t - LN_2).abs() < 1e-10, "{method:?}");
        assert_eq!(sol.termination, Termination::ReachedEnd);

        let mut ev = FnEvent::new(|_t, y: &[f64]| y[0]).with_terminal(true);
        let sol = solve(
            &oscillator(),
            0.0,
            &[1.0, 0.0],
            5.0,
            &opts(method, 1e-12, 1e-14),
            &mut [&mut ev],
            Output::Final,
            Cancel::NONE,
        )
        .unwrap();
        let Termination::Event { t, .. } = sol.termination else {
            panic!("{method:?}: no terminal event");
        };
        assert!((t - PI / 2.0).abs() < 1e-10, "{method:?}: {t}");
        assert!((sol.y_final[1] + 1.0).abs() < 1e-10);
    }
}

#[test]
fn dop853_agrees_with_dopri5_at_tight_tolerance_with_less_work() {
    // A nonlinear problem without a closed form: the Van der Pol oscillator (µ = 1)
    // over [0, 10]. At rtol 1e-12 both are accurate to ~1e-10 (global error ≈ a few
    // hundred rtol over ~1.5 periods), so they agree to 1e-9; DOP853 needs fewer
    // right-hand-side evaluations there (the point of an eighth-order method).
    let vdp = FnSystem::new(2, |_t, y: &[f64], d: &mut [f64]| {
        d[0] = y[1];
        d[1] = (1.0 - y[0] * y[0]) * y[1] - y[0];
    });
    let a = run(
        &vdp,
        0.0,
        &[2.0, 0.0],
        10.0,
        &opts(Method::DormandPrince45, 1e-12, 1e-14),
        Output::Final,
    );
    let b = run(
        &vdp,
        0.0,
        &[2.0, 0.0],
        10.0,
        &opts(Method::Dop853, 1e-12, 1e-14),
        Output::Final,
    );
    let diff = (a.y_final[0] - b.y_final[0])
        .abs()
        .max((a.y_final[1] - b.y_final[1]).abs());
    eprintln!(
        "vdp: diff {diff:e}, evaluations DOPRI5 {} DOP853 {}",
        a.stats.rhs_evaluations, b.stats.rhs_evaluations
    );
    assert!(diff < 1e-9, "{diff:e}");
    assert!(b.stats.rhs_evaluations < a.stats.rhs_evaluations);
}
