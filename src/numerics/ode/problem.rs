//! The problem side of an ODE solve: the system, the options, the requested output and
//! the events.

use nalgebra::DMatrix;

/// A system of first-order ODEs `y' = f(t, y)` of fixed dimension.
pub trait OdeSystem {
    /// Number of state components; `y0`, `y` and `dydt` all have this length.
    fn dim(&self) -> usize;

    /// Write `f(t, y)` into `dydt`. Non-finite output is detected by the solver.
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]);

    /// Write the dense Jacobian `∂f/∂y` at `(t, y)` into the `dim × dim` matrix
    /// `jac` (pre-zeroed) and return `true`; the default returns `false`, meaning
    /// "not provided", and the implicit method falls back to forward differences
    /// (`dim` extra right-hand-side evaluations per Jacobian).
    fn jacobian(&self, _t: f64, _y: &[f64], _jac: &mut DMatrix<f64>) -> bool {
        false
    }
}

/// An [`OdeSystem`] defined by a closure `f(t, y, dydt)` (no analytic Jacobian).
#[derive(Debug, Clone)]
pub struct FnSystem<F> {
    dim: usize,
    f: F,
}

impl<F: Fn(f64, &[f64], &mut [f64])> FnSystem<F> {
    /// Wrap the closure `f` as a system of dimension `dim`.
    pub fn new(dim: usize, f: F) -> Self {
        FnSystem { dim, f }
    }
}

impl<F: Fn(f64, &[f64], &mut [f64])> OdeSystem for FnSystem<F> {
    fn dim(&self) -> usize {
        self.dim
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        (self.f)(t, y, dydt)
    }
}

/// Which integrator [`solve`] uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Explicit Dormand–Prince 5(4) ("DOPRI5", as in MATLAB's `ode45`): six
    /// right-hand-side evaluations per step, fifth-order solution, fourth-order
    /// dense output. Efficient while the step size is limited by accuracy; on stiff
    /// problems it is limited by stability instead and crawls.
    DormandPrince45,
    /// Hairer's explicit DOP853: order 8 with a 5(3) error estimate and a seventh-order
    /// dense output (Hairer, Nørsett & Wanner I, §II.5–II.6; SciPy's `DOP853`): twelve
    /// right-hand-side evaluations per step, three more for the dense output of a step
    /// that holds an output time or an event. Far fewer steps than DOPRI5 at tight
    /// tolerances on smooth non-stiff problems; no stiffness switch.
    Dop853,
    /// The implicit method for stiff problems: **Rodas4** (Hairer & Wanner, *Solving
    /// ODE II*, §IV.7), a 6-stage Rosenbrock method of order 4 with an embedded
    /// order-3 error estimate. All stages share one diagonal coefficient γ = 1/4
    /// (hence the name: it is the linearly implicit relative of an SDIRK method).
    ///
    /// Chosen over an ESDIRK and over ROS3P because it is L-stable *and* stiffly
    /// accurate (fast transients are damped completely, as Robertson-type kinetics
    /// and contact stiffness need; ROS3P is only A-stable), it reaches order 4 with
    /// one LU decomposition and six linear solves per step, and it needs no Newton
    /// iteration, so there is no convergence failure to handle and no iteration
    /// tolerance to tune. The price is that it wants an accurate Jacobian at every
    /// step (analytic via [`OdeSystem::jacobian`], or forward differences). Dense
    /// output is the cubic Hermite interpolant between steps.
    Sdirk,
    /// Start with [`Method::DormandPrince45`] and switch to [`Method::Sdirk`] when
    /// Hairer's DOPRI5 stiffness test fires: the estimate `h·ρ` of step size times
    /// dominant Jacobian eigenvalue exceeds 3.25 (DOPRI5's stability boundary on the
    /// negative real axis is ≈ −3.3) on 15 accepted steps, counted from the last
    /// run of 6 consecutive non-stiff steps. The switch is one-way and its time is
    /// recorded in [`OdeStats::switched_to_implicit_at`].
    #[default]
    Auto,
}

/// Tolerances, step-size limits and method choice for [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct OdeOptions {
    /// Relative tolerance; must be finite and ≥ 10·ε (≈ 2.2e-15).
    pub rtol: f64,
    /// Absolute tolerance; must be finite and > 0. Component `i` of the local error
    /// is measured against `atol + rtol·max(|y_i|, |y_new_i|)` and the step is
    /// accepted when the RMS of these ratios is ≤ 1.
    pub atol: f64,
    /// Initial step size magnitude; `None` selects it automatically from `f(t0, y0)`
    /// and one Euler probe (Hairer's `HINIT`).
    pub h0: Option<f64>,
    /// Largest step size magnitude (`f64::INFINITY` = only limited by the interval).
    pub h_max: f64,
    /// Hard bound on step attempts (accepted plus rejected); exceeding it returns
    /// [`OdeError::MaxSteps`].
    pub max_steps: usize,
    /// Integrator.
    pub method: Method,
    /// `Some(h)`: take steps of exactly `h` (the last one shortened to land on
    /// `t_end`), without error control, ignoring `h0` and `h_max`. For convergence
    /// studies and reproducible cost; a non-finite trial is then an error.
    pub fixed_step: Option<f64>,
}

impl Default for OdeOptions {
    fn default() -> Self {
        OdeOptions {
            rtol: 1e-6,
            atol: 1e-9,
            h0: None,
            h_max: f64::INFINITY,
            max_steps: 1_000_000,
            method: Method::Auto,
            fixed_step: None,
        }
    }
}

/// Which states [`solve`] records in [`OdeSolution::t`] / [`OdeSolution::y`].
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// Only the state where integration stopped (`t_end` or a terminal event).
    Final,
    /// The states at these times, evaluated from the dense output of the step that
    /// contains them (the step sequence is not altered). Times must be finite, lie
    /// in `[t0, t_end]` and be ordered in the direction of integration; those after
    /// a terminal event are not produced.
    Times(Vec<f64>),
    /// The initial state and the state after every accepted step (the last entry is
    /// the event state if a terminal event stopped the integration).
    Steps,
}

/// Which sign changes of an event function count, judged along the direction of
/// integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// From negative to non-negative.
    Rising,
    /// From positive to non-positive.
    Falling,
    /// Either.
    #[default]
    Both,
}

/// A scalar function `g(t, y)` whose zeros are located during integration.
///
/// A crossing is detected when `g` changes sign between two consecutive accepted
/// steps (a zero at the initial point is not a crossing), then located on the dense
/// output by Brent's method to ~1e-13 relative in `t`. Two crossings within a
/// single step cancel out and go unnoticed; cap [`OdeOptions::h_max`] if `g` can
/// oscillate faster than the solution's natural step size.
pub trait Event {
    /// The event function `g(t, y)`.
    fn value(&self, t: f64, y: &[f64]) -> f64;
    /// Which crossings count; default both.
    fn direction(&self) -> Direction {
        Direction::Both
    }
    /// Whether integration stops at the (first) crossing; default `false`.
    fn terminal(&self) -> bool {
        false
    }
}

/// An [`Event`] defined by a closure `g(t, y)`.
#[derive(Debug, Clone)]
pub struct FnEvent<F> {
    g: F,
    direction: Direction,
    terminal: bool,
}

impl<F: Fn(f64, &[f64]) -> f64> FnEvent<F> {
    /// A non-terminal event counting crossings in both directions.
    pub fn new(g: F) -> Self {
        FnEvent {
            g,
            direction: Direction::Both,
            terminal: false,
        }
    }
    /// Count only crossings in `direction`.
    pub fn with_direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }
    /// Stop integration at the crossing if `terminal`.
    pub fn with_terminal(mut self, terminal: bool) -> Self {
        self.terminal = terminal;
        self
    }
}

impl<F: Fn(f64, &[f64]) -> f64> Event for FnEvent<F> {
    fn value(&self, t: f64, y: &[f64]) -> f64 {
        (self.g)(t, y)
    }
    fn direction(&self) -> Direction {
        self.direction
    }
    fn terminal(&self) -> bool {
        self.terminal
    }
}
