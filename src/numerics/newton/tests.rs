//! Tests of the Newton machinery on its own, on analytic systems (no bearing).

use super::*;

/// A general system with its evaluation log: F(x, y) = (x² + y² − 4, x·y − 1).
struct Circle {
    residuals: Vec<f64>,
}

impl NewtonSystem<2> for Circle {
    type Eval = (Vector2<f64>, Matrix2<f64>);
    fn evaluate(&mut self, x: &Vector2<f64>) -> Self::Eval {
        let f = Vector2::new(x[0] * x[0] + x[1] * x[1] - 4.0, x[0] * x[1] - 1.0);
        let j = Matrix2::new(2.0 * x[0], 2.0 * x[1], x[1], x[0]);
        (f, j)
    }
    fn residual<'e>(&self, e: &'e Self::Eval) -> &'e Vector2<f64> {
        &e.0
    }
    fn jacobian<'e>(&self, e: &'e Self::Eval) -> &'e Matrix2<f64> {
        &e.1
    }
    fn observe(&mut self, _: usize, _: &Vector2<f64>, e: &Self::Eval) {
        self.residuals.push(e.0.amax());
    }
}

/// Rosenbrock's function as a gradient system: F = ∇f, J = ∇²f, merit f, the step by
/// the shifted Cholesky of the Hessian (indefinite on part of the path).
struct Rosenbrock {
    residuals: Vec<f64>,
}

struct RosenbrockEval {
    f: f64,
    g: Vector2<f64>,
    h: Matrix2<f64>,
}

impl NewtonSystem<2> for Rosenbrock {
    type Eval = RosenbrockEval;
    fn evaluate(&mut self, x: &Vector2<f64>) -> RosenbrockEval {
        let (a, b) = (x[0], x[1]);
        RosenbrockEval {
            f: (1.0 - a).powi(2) + 100.0 * (b - a * a).powi(2),
            g: Vector2::new(
                -2.0 * (1.0 - a) - 400.0 * a * (b - a * a),
                200.0 * (b - a * a),
            ),
            h: Matrix2::new(
                2.0 - 400.0 * (b - 3.0 * a * a),
                -400.0 * a,
                -400.0 * a,
                200.0,
            ),
        }
    }
    fn residual<'e>(&self, e: &'e RosenbrockEval) -> &'e Vector2<f64> {
        &e.g
    }
    fn jacobian<'e>(&self, e: &'e RosenbrockEval) -> &'e Matrix2<f64> {
        &e.h
    }
    fn merit(&self, e: &RosenbrockEval) -> f64 {
        e.f
    }
    fn slope(&self, e: &RosenbrockEval, step: &Vector2<f64>) -> f64 {
        e.g.dot(step)
    }
    fn newton_step(&self, e: &RosenbrockEval) -> Option<Vector2<f64>> {
        Some(scaled_newton_step(&e.h, &e.g, &Vector2::new(1.0, 1.0)))
    }
    fn observe(&mut self, _: usize, _: &Vector2<f64>, e: &RosenbrockEval) {
        self.residuals.push(e.g.amax());
    }
}

fn solver(tolerance: f64, max_iterations: usize) -> Newton {
    Newton {
        max_iterations,
        tolerance,
        trust: TrustRegion::new(1.0, 1e-12, 10.0),
        line_search: Backtracking::default(),
    }
}

/// Quadratic convergence: once the residual is small (below `from`), each iteration's
/// residual is at most `c` times the square of the one before (until round-off).
fn assert_quadratic(r: &[f64], from: f64, c: f64) {
    let tail: Vec<_> = r
        .windows(2)
        .filter(|w| w[0] < from && w[0] > 1e-13)
        .collect();
    assert!(tail.len() >= 2, "too few small-residual steps: {r:?}");
    for w in tail {
        assert!(w[1] <= c * w[0] * w[0], "not quadratic: {r:?}");
    }
}

#[test]
fn converges_quadratically_on_a_polynomial_system() {
    // x² + y² = 4, xy = 1 from (2, 0.3): root x = √(2 + √3), y = 1/x.
    let mut sys = Circle {
        residuals: Vec::new(),
    };
    let mut x = Vector2::new(2.0, 0.3);
    let r = solver(1e-14, 50).solve(&mut sys, &mut x);
    assert!(r.termination.is_converged(), "{:?}", r.termination);
    let root = (2.0 + 3f64.sqrt()).sqrt();
    assert!((x[0] - root).abs() < 1e-14 && (x[1] - 1.0 / root).abs() < 1e-14);
    assert_quadratic(&sys.residuals, 0.1, 1.0);
    // Full steps near the root: one evaluation per iteration from there on.
    assert!(r.stats.iterations <= 8, "{:?}", r.stats);
}

#[test]
fn converges_quadratically_on_rosenbrocks_gradient() {
    // The classic start (−1.2, 1) crosses the region where the Hessian is indefinite;
    // the shifted step and the line search carry it to (1, 1), quadratically at the end.
    let mut sys = Rosenbrock {
        residuals: Vec::new(),
    };
    let mut x = Vector2::new(-1.2, 1.0);
    let r = solver(1e-10, 100).solve(&mut sys, &mut x);
    match r.termination {
        Termination::Converged {
            iterations,
            residual,
        } => {
            assert!(residual <= 1e-10);
            assert_eq!(iterations, r.stats.iterations);
            assert!(iterations < 40, "{iterations}");
        }
        t => panic!("{t:?}"),
    }
    assert!((x - Vector2::new(1.0, 1.0)).amax() < 1e-10, "{x}");
    assert_quadratic(&sys.residuals, 1e-2, 10.0);
    assert!(r.stats.evaluations > r.stats.iterations);
}

#[test]
fn budget_and_tolerance_are_reported() {
    let mut sys = Rosenbrock {
        residuals: Vec::new(),
    };
    let mut x = Vector2::new(-1.2, 1.0);
    let r = solver(1e-10, 3).solve(&mut sys, &mut x);
    match r.termination {
        Termination::NotConverged {
            iterations,
            residual,
            tolerance,
        } => {
            assert_eq!((iterations, tolerance), (3, 1e-10));
            assert_eq!(residual, r.eval.g.amax());
        }
        t => panic!("{t:?}"),
    }
    assert_eq!(r.stats.iterations, 3);
}

#[test]
fn singular_jacobian_is_a_typed_termination() {
    // F = (x² + 1, y) at (0, 1): J = [[0, 0], [0, 1]] is singular and F ≠ 0.
    struct Singular;
    impl NewtonSystem<2> for Singular {
        type Eval = (Vector2<f64>, Matrix2<f64>);
        fn evaluate(&mut self, x: &Vector2<f64>) -> Self::Eval {
            (
                Vector2::new(x[0] * x[0] + 1.0, x[1]),
                Matrix2::new(2.0 * x[0], 0.0, 0.0, 1.0),
            )
        }
        fn residual<'e>(&self, e: &'e Self::Eval) -> &'e Vector2<f64> {
            &e.0
        }
        fn jacobian<'e>(&self, e: &'e Self::Eval) -> &'e Matrix2<f64> {
            &e.1
        }
    }
    let mut x = Vector2::new(0.0, 1.0);
    let r = solver(1e-12, 10).solve(&mut Singular, &mut x);
    assert_eq!(
        r.termination,
        Termination::SingularJacobian { iteration: 0 }
    );
    assert_eq!(x, Vector2::new(0.0, 1.0));
    assert_eq!(r.termination.residual(), None);
}

#[test]
fn stall_non_finite_and_cancel_are_typed() {
    // A step solver that points uphill: no fraction of it is accepted.
    struct Uphill(Rosenbrock);
    impl NewtonSystem<2> for Uphill {
        type Eval = RosenbrockEval;
        fn evaluate(&mut self, x: &Vector2<f64>) -> RosenbrockEval {
            self.0.evaluate(x)
        }
        fn residual<'e>(&self, e: &'e RosenbrockEval) -> &'e Vector2<f64> {
            &e.g
        }
        fn jacobian<'e>(&self, e: &'e RosenbrockEval) -> &'e Matrix2<f64> {
            &e.h
        }
        fn merit(&self, e: &RosenbrockEval) -> f64 {
            e.f
        }
        fn slope(&self, e: &RosenbrockEval, step: &Vector2<f64>) -> f64 {
            e.g.dot(step)
        }
        fn newton_step(&self, e: &RosenbrockEval) -> Option<Vector2<f64>> {
            Some(e.g)
        }
    }
    let mut x = Vector2::new(-1.2, 1.0);
    let r = solver(1e-10, 10).solve(
        &mut Uphill(Rosenbrock {
            residuals: Vec::new(),
        }),
        &mut x,
    );
    let g0 = r.eval.g.amax();
    assert_eq!(
        r.termination,
        Termination::Stalled {
            iterations: 1,
            residual: g0
        }
    );
    assert_eq!(r.stats.evaluations, 1 + Backtracking::default().max_trials);
    assert_eq!(x, Vector2::new(-1.2, 1.0));

    // A NaN residual.
    let mut x = Vector2::new(f64::NAN, 1.0);
    let r = solver(1e-10, 10).solve(
        &mut Circle {
            residuals: Vec::new(),
        },
        &mut x,
    );
    assert_eq!(r.termination, Termination::NonFinite { iteration: 0 });

    // Cancelled before the first iteration.
    struct Stop(Circle);
    impl NewtonSystem<2> for Stop {
        type Eval = (Vector2<f64>, Matrix2<f64>);
        fn evaluate(&mut self, x: &Vector2<f64>) -> Self::Eval {
            self.0.evaluate(x)
        }
        fn residual<'e>(&self, e: &'e Self::Eval) -> &'e Vector2<f64> {
            &e.0
        }
        fn jacobian<'e>(&self, e: &'e Self::Eval) -> &'e Matrix2<f64> {
            &e.1
        }
        fn cancelled(&self) -> bool {
            true
        }
    }
    let mut x = Vector2::new(2.0, 0.3);
    let r = solver(1e-10, 10).solve(
        &mut Stop(Circle {
            residuals: Vec::new(),
        }),
        &mut x,
    );
    assert_eq!(r.termination, Termination::Cancelled { iteration: 0 });
    assert_eq!(r.stats.iterations, 0);
}

#[test]
fn trust_region_caps_grows_and_shrinks_as_documented() {
    let mut t = TrustRegion::new(1.0, 1e-3, 3.0);
    // A step of length 2 is cut to the radius; one of length 0.5 is left alone.
    let (s, capped) = t.cap(Vector2::new(2.0, 0.0), 2.0);
    assert!(capped && s == Vector2::new(1.0, 0.0));
    let (s, capped) = t.cap(Vector2::new(0.0, 0.5), 0.5);
    assert!(!capped && s == Vector2::new(0.0, 0.5));
    // A full uncut step leaves the radius.
    t.update(1.0, 0.5, false);
    assert_eq!(t.radius, 1.0);
    // A full capped step grows it fourfold, then up to the maximum only.
    t.update(1.0, 2.0, true);
    assert_eq!(t.radius, 3.0);
    t.update(1.0, 20.0, true);
    assert_eq!(t.radius, 3.0);
    // A backtracked step shrinks it to the length taken: λ·min(len, radius).
    t.update(0.25, 2.0, false);
    assert_eq!(t.radius, 0.5);
    t.update(0.5, 100.0, true);
    assert_eq!(t.radius, 0.25);
    // ... never below the minimum.
    t.update(1e-6, 0.25, false);
    assert_eq!(t.radius, 1e-3);
}

#[test]
fn backtracking_halves_until_accepted_and_passes_errors() {
    let ls = Backtracking::default();
    let mut tried = Vec::new();
    let r = ls.search(|l| {
        tried.push(l);
        (l <= 0.125).then_some(l * 10.0)
    });
    assert_eq!(r, Some((0.125, 1.25)));
    assert_eq!(tried, [1.0, 0.5, 0.25, 0.125]);
    assert_eq!(ls.search(|_| None::<()>), None);
    let e: Result<Option<(f64, ())>, &str> =
        ls.try_search(|l| if l < 0.6 { Err("x") } else { Ok(None) });
    assert_eq!(e, Err("x"));
    // Armijo or a halved residual.
    assert!(ls.accepts(1.0, -1.0, 1.0, 1.0, 0.99, 1.0));
    assert!(!ls.accepts(1.0, -1.0, 1.0, 1.0, 0.99995, 0.6));
    assert!(ls.accepts(1.0, -1.0, 1.0, 1.0, 2.0, 0.4));
}

#[test]
fn factor3_solves_spd_to_round_off_and_shifts_indefinite() {
    // SPD: A·Aᵀ + I, with the third unknown scaled (an angle against lengths).
    let a = Matrix3::new(2.0, -1.0, 0.5, 0.3, 1.5, -0.7, 0.1, 0.4, 3.0);
    let h = a * a.transpose() + Matrix3::identity();
    let scale = Vector3::new(1.0, 1.0, 1.0 / 0.02);
    let f = Factor3::new(&h, &scale);
    assert!(f.is_factored());
    let b = Vector3::new(1.0, -2.0, 0.5);
    let x = f.solve(&b);
    assert!((h * x - b).amax() <= 1e-14 * b.amax(), "{}", h * x - b);
    // Several right-hand sides at once agree with one at a time.
    let bm = nalgebra::Matrix3x2::from_columns(&[b, Vector3::new(0.0, 1.0, 0.0)]);
    let xm = f.solve(&bm);
    assert_eq!(xm.column(0), x);
    // The Newton step is the same solve, negated.
    assert!((newton_step3(&h, &b, &scale) + x).amax() <= 1e-15 * x.amax());

    // Indefinite: eigenvalues 1, −1, 2. The factor is of H + μI with the first shift
    // (10⁻¹⁰·|tr|·10^k) that is positive definite, so μ ∈ (1, 10]: the solve is of a
    // positive definite matrix (xᵀb > 0), and the Newton step descends.
    let h = Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, 2.0));
    let one = Vector3::new(1.0, 1.0, 1.0);
    let f = Factor3::new(&h, &one);
    assert!(f.is_factored());
    let x = f.solve(&b);
    assert!(x.dot(&b) > 0.0);
    let mu = b[1] / x[1] - (-1.0);
    assert!(mu > 1.0 && mu <= 10.0 + 1e-9, "shift {mu}");
    let g = Vector3::new(0.3, 0.2, -0.1);
    assert!(g.dot(&newton_step3(&h, &g, &one)) < 0.0);
    // Nothing helps a NaN matrix: the factor is absent, solves give zero and the step
    // falls back to steepest descent (here NaN-scaled, so only its shape is checked).
    let f = Factor3::new(&Matrix3::from_element(f64::NAN), &one);
    assert!(!f.is_factored());
    assert_eq!(f.solve(&b), Vector3::zeros());

    // The 2×2 step: exact on SPD, steepest descent over |tr| when nothing helps.
    let k = Matrix2::new(4.0, 1.0, 1.0, 3.0);
    let g2 = Vector2::new(1.0, 2.0);
    assert!((k * newton_step2(&k, &g2) + g2).amax() <= 1e-15);
    let k = Matrix2::new(-1.0, 0.0, 0.0, -1.0);
    let s = newton_step2(&k, &g2);
    assert!(g2.dot(&s) < 0.0, "{s}");
}

/// An iterate reached by the budget's last step that meets the tolerance is converged
/// (issue 24 item 11: the tapered solver reported "did not converge" with a residual
/// 3.56e-10 below its own tolerance 3.62e-10, because the loop ended before testing the
/// last iterate). The circle needs k steps; with a budget of exactly k the verdict must
/// be `Converged` after k steps, and with k − 1 `NotConverged` with a residual above the
/// tolerance.
#[test]
fn the_last_iterate_is_tested_against_the_tolerance() {
    let run = |budget: usize| {
        let mut sys = Circle {
            residuals: Vec::new(),
        };
        let mut x = Vector2::new(2.0, 0.3);
        solver(1e-12, budget).solve(&mut sys, &mut x).termination
    };
    let k = run(50).iterations();
    assert!(k >= 2, "{k}");
    match run(k) {
        Termination::Converged {
            iterations,
            residual,
        } => assert!(iterations == k && residual <= 1e-12),
        t => panic!("{t:?}"),
    }
    match run(k - 1) {
        Termination::NotConverged {
            residual,
            tolerance,
            ..
        } => assert!(residual > tolerance),
        t => panic!("{t:?}"),
    }
}
