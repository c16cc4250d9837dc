//! The angular-contact ball bearing's registration: decks read through the generic deck
//! form, solved by `analysis`, shown through `view` and `report`.

#[cfg(test)]
use super::analysis::analyse_traced;
use super::analysis::{analyse, analyse_streaming, BallAnalysis};
use super::deck::SCHEMA;
use super::input::BallInput;
use crate::bearings::thermal_answer::{self, BearingThermal};
use crate::bearings::view::{Chart, PaneKind, PaneSpec, View};
use crate::bearings::{
    Case, Detail, Fidelity, FidelityGrid, FormSystem, RunOptions, Session, Solution, SolveError,
    SystemCase,
};
use crate::deck::form::{Form, Schema};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::Units;

use super::SYSTEM_ID;

/// The fidelity study of `rollbench bench` (issue 16: "error against time over slices ×
/// tolerance, against 161 slices at 1e-10").
///
/// Resolution: `dynamics.slices`, the slices across each contact ellipse of the ball
/// dynamics. Tolerance: `dynamics.tolerance`, the ball-dynamics integrator's relative
/// tolerance. The load distribution's force tolerances are not inputs (fixed at 1e-11 of
/// the reference force per ball and 1e-10 on the ring, the round-off floor, in
/// `load_distribution::solve`), so the dynamics tolerance is the only tolerance that can
/// trade accuracy for time; it matters for the time simulation only (the quasi-static
/// moment balance is solved by Newton to 1e-13 whatever it is, so under
/// `dynamics.method = "quasi-static"` the tolerance columns agree). With
/// `dynamics.method = "race-control"` neither knob changes anything: every cell equals
/// the reference. Odd slice counts put a slice on the contact's centre line.
pub const FIDELITY_GRID: FidelityGrid = FidelityGrid {
    resolution_key: "slices",
    resolution_symbol: "n",
    resolutions: &[5, 7, 11, 15, 21, 31, 41, 61, 81, 121],
    tolerances: &[1e-6, 1e-8],
    reference: Fidelity {
        resolution: 161,
        tolerance: 1e-10,
    },
};

/// The angular-contact ball bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct AngularBall;

/// The registry entry.
pub static SYSTEM: AngularBall = AngularBall;

/// The shipped example deck (Chen's Bearing A).
pub const EXAMPLE_DECK: &str = include_str!("../../../decks/chen_a.toml");

impl FormSystem for AngularBall {
    type Input = BallInput;
    /// The deck's `[thermal]` network, if any.
    type Derived = Option<ThermalModel>;

    fn registered() -> &'static Self {
        &SYSTEM
    }

    fn schema(&self) -> &'static Schema<BallInput> {
        &SCHEMA
    }

    fn title(&self) -> &'static str {
        "angular-contact ball bearing"
    }

    fn method(&self) -> &'static str {
        "quasi-static load distribution and race control (S.-H. Chen, Investigation on Ball Skidding and Traction within Elastohydrodynamic Films, 1989)"
    }

    fn element_name(&self) -> &'static str {
        "ball"
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        Some(FIDELITY_GRID)
    }

    /// A session that records the stepper's trace when the Stepper pane asks for it.
    fn session(&self) -> Box<dyn Session> {
        Box::new(BallSession)
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 9] = [
            PaneSpec {
                kind: PaneKind::Inputs,
                title: "Inputs",
            },
            PaneSpec {
                kind: PaneKind::Summary,
                title: "Summary",
            },
            PaneSpec {
                kind: PaneKind::Elements,
                title: "Balls",
            },
            PaneSpec {
                kind: PaneKind::Chart(SKID_CHART),
                title: "Skid",
            },
            PaneSpec {
                kind: PaneKind::Chart(1),
                title: "Dynamics",
            },
            PaneSpec {
                kind: PaneKind::Chart(2),
                title: "Traction",
            },
            PaneSpec {
                kind: PaneKind::Stepper,
                title: "Stepper",
            },
            PaneSpec {
                kind: PaneKind::Thermal,
                title: "Thermal",
            },
            PaneSpec {
                kind: PaneKind::Study,
                title: "Study",
            },
        ];
        &PANES
    }

    fn study_keys(&self) -> &'static [&'static str] {
        // The Study pane's default tolerance study varies the first three of these
        // the deck gives a non-zero number (the main geometry and operating keys).
        &[
            "geometry.free_contact_angle",
            "operating.axial_load",
            "operating.radial_load",
            "operating.inner_speed",
        ]
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    /// The `[traction]` table's measured curve into the input, and the `[thermal]`
    /// network built (errors name node, link and field).
    fn prepare(form: &mut Form<BallInput>) -> Result<Option<ThermalModel>, DeckErrors> {
        super::deck::traction_table(form)?;
        form.thermal_model()
    }

    fn solve(
        case: &BallCase,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String> {
        let a = analyse(&case.form.value, cancel).map_err(|e| e.to_string())?;
        let th = thermal_of(&a, case, !options.skip_transient, &cancel)?;
        Ok(Box::new(BallSolution(a, th)))
    }

    /// The `[thermal]` network's loss-of-oil transient.
    fn has_transient(case: &BallCase) -> bool {
        case.derived.is_some()
    }

    fn fidelity(input: &BallInput) -> Option<Fidelity> {
        Some(Fidelity {
            resolution: input.dynamics.slices,
            tolerance: input.dynamics.tolerance,
        })
    }

    fn set_fidelity(input: &mut BallInput, f: Fidelity) -> bool {
        input.dynamics.slices = f.resolution;
        input.dynamics.tolerance = f.tolerance;
        true
    }

    /// Race control (the default method) solves the load distribution with no slices and
    /// no use of `dynamics.tolerance`: every cell of the grid is the reference's answer.
    fn fidelity_unused(input: &BallInput) -> Option<String> {
        (input.dynamics.method == super::input::Method::RaceControl).then(|| {
            "dynamics.method = \"race-control\" slices no contact and uses no dynamics.tolerance, so every cell equals the reference and the grid measures nothing here; bench a method that slices the contacts: --set dynamics.method=quasi-static (or time-simulation)".to_string()
        })
    }
}

/// A validated ball bearing deck.
pub type BallCase = SystemCase<AngularBall>;

/// The workbench's solver of ball cases: a whole solve, with the load distribution's
/// iterations of the ball the Stepper pane shows recorded when it is on screen.
pub struct BallSession;

impl Session for BallSession {
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError> {
        self.solve_streaming(case, detail, cancel, &mut |_, _| {})
    }

    /// The Skid chart (chart 0) grows as the skidding search solves its speeds: with the
    /// Skid pane on screen every speed solved is sent at once, before the ball dynamics
    /// (which may take a tenth of a second under radial load) end.
    fn solve_streaming(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
        on_chart: &mut dyn FnMut(usize, Chart),
    ) -> Result<Box<dyn Solution>, SolveError> {
        let ball = BallCase::of(case)?;
        let stream = detail.stream_chart == Some(SKID_CHART);
        analyse_streaming(
            &ball.form.value,
            Cancel::from_option(cancel.flag()),
            detail.trace_element,
            &mut |samples| {
                if stream {
                    on_chart(SKID_CHART, super::view::skid_chart_partial(samples));
                }
            },
        )
        .map_err(|e| match e {
            super::error::BallError::Cancelled => SolveError::Cancelled,
            e => SolveError::Stage {
                stage: SYSTEM_ID,
                message: e.to_string(),
            },
        })
        .and_then(|a| {
            if stream {
                // The finished chart, as the solution's view draws it.
                on_chart(SKID_CHART, super::view::skid_chart(&a));
            }
            let th = thermal_of(&a, ball, detail.transient, cancel).map_err(|message| {
                if cancel.is_cancelled() {
                    SolveError::Cancelled
                } else {
                    SolveError::Stage {
                        stage: SYSTEM_ID,
                        message,
                    }
                }
            })?;
            Ok(Box::new(BallSolution(a, th)) as Box<dyn Solution>)
        })
    }
}

/// The deck's thermal network under the friction's heat (steady, and the transient when
/// `transient`); `None` without `[thermal]`.
fn thermal_of(
    a: &BallAnalysis,
    case: &BallCase,
    transient: bool,
    cancel: &Cancel,
) -> Result<Option<BearingThermal>, String> {
    case.derived
        .as_ref()
        .map(|tm| {
            thermal_answer::solve(tm, &super::friction::friction(a), transient, &|| {
                cancel.is_cancelled()
            })
        })
        .transpose()
}

/// The Skid pane's chart: `PaneKind::Chart(SKID_CHART)`, the first of the view's charts.
pub const SKID_CHART: usize = 0;

/// A solved ball bearing and its thermal network's results (when the deck has one).
pub struct BallSolution(pub BallAnalysis, pub Option<BearingThermal>);

impl Solution for BallSolution {
    fn view(&self) -> View {
        let mut v = super::view::view(&self.0);
        thermal_answer::add_to_view(&mut v, self.1.as_ref());
        v
    }

    fn json(&self) -> serde_json::Value {
        let mut v = super::report::json(&self.0);
        thermal_answer::add_to_json(&mut v, self.1.as_ref());
        v
    }

    fn text(&self, units: Units) -> String {
        let mut s = super::report::text(&self.0, units);
        thermal_answer::add_to_text(&mut s, self.1.as_ref(), units);
        s
    }

    fn series_csv(&self) -> Result<String, String> {
        super::report::series_csv(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::BearingSystem;

    /// The stepper's trace of the load distribution (issue 16: "stepper (the
    /// load-distribution Newton)"): recording only reads, so the traced analysis's report
    /// equals the plain one exactly; there is one step per fixed-point iteration; the
    /// last step's angles and loads of the traced ball are the solution's (the fixed
    /// point stops when they change by < 1e-12 rad and < 1e-10 relative: 1e-9 relative
    /// here) and its changes meet those tolerances. Bearing B under 500 N radial load
    /// (every ball different), ball 11 (ψ = 198°).
    #[test]
    fn stepper_trace_ends_at_the_solution() {
        let case = SYSTEM
            .load(
                include_str!("../../../decks/chen_b.toml"),
                "chen_b",
                &["operating.radial_load=500".to_string()],
            )
            .unwrap();
        let input = &case.as_any().downcast_ref::<BallCase>().unwrap().form.value;
        let plain = analyse(input, Cancel::NONE).unwrap();
        let traced = analyse_traced(input, Cancel::NONE, Some(10)).unwrap();
        assert_eq!(
            super::super::report::json(&plain),
            super::super::report::json(&traced)
        );
        let (ball, steps) = traced.load_trace.as_ref().unwrap();
        assert_eq!(*ball, 10);
        assert_eq!(steps.len(), traced.load.stats.fixed_point_iterations);
        let last = steps.last().unwrap();
        let b = &traced.balls[10];
        let rel = |x: f64, y: f64| (x / y - 1.0).abs();
        assert!(rel(last.angles_rad[0], b.inner.angle_rad) < 1e-9);
        assert!(rel(last.angles_rad[1], b.outer.angle_rad) < 1e-9);
        assert!(rel(last.loads_n[0], b.inner.load_n) < 1e-9);
        assert!(rel(last.loads_n[1], b.outer.load_n) < 1e-9);
        assert!(last.angle_change_rad < 1e-12 && last.load_change < 1e-10);
        // The view carries it for the stepper, one step per iteration.
        let n = steps.len();
        let view = BallSolution(traced, None).view();
        let t = view.trace.unwrap();
        assert_eq!((t.element, t.steps.len()), (10, n));
    }

    /// `with_fidelity` sets exactly the two knobs `fidelity` reads (exact), leaves the
    /// rest of the deck alone, and the quasi-static heat converges at second order in the
    /// slice count: the error against 161 slices falls by 4 ± 0.5 from 21 to 41 slices
    /// (midpoint slices, error ∝ n⁻²; measured 1.092e-3 → 2.73e-4, ratio 4.0).
    #[test]
    fn fidelity_round_trip_and_heat_convergence() {
        let case = SYSTEM
            .load(
                include_str!("../../../decks/chen_b.toml"),
                "chen_b",
                &["dynamics.method=quasi-static".to_string()],
            )
            .unwrap();
        let f = Fidelity {
            resolution: 21,
            tolerance: 1e-6,
        };
        let c21 = case.with_fidelity(f).unwrap();
        assert_eq!(c21.fidelity(), Some(f));
        let heat = |c: &dyn Case| {
            let b = c.as_any().downcast_ref::<BallCase>().unwrap();
            analyse(&b.form.value, Cancel::NONE).unwrap().total_heat_w
        };
        let at = |n| {
            heat(
                case.with_fidelity(Fidelity {
                    resolution: n,
                    tolerance: 1e-10,
                })
                .unwrap()
                .as_ref(),
            )
        };
        let reference = at(161);
        let e21 = (heat(c21.as_ref()) / reference - 1.0).abs();
        let e41 = (at(41) / reference - 1.0).abs();
        assert!((e21 / e41 - 4.0).abs() < 0.5, "{e21} {e41}");
        assert_eq!(
            c21.as_any()
                .downcast_ref::<BallCase>()
                .unwrap()
                .form
                .value
                .operating,
            case.as_any()
                .downcast_ref::<BallCase>()
                .unwrap()
                .form
                .value
                .operating
        );
    }

    /// Streaming the Skid chart changes no number (the search only reports what it
    /// solved; moving it before the dynamics changes no input of either): the solution
    /// streamed is the plain one to the last digit (JSON equal), with a time simulation
    /// under radial load (every ball different); the stream sends one chart per speed
    /// the search solved plus the finished one, and nothing when the pane is not asked
    /// for.
    #[test]
    fn streaming_the_skid_chart_changes_no_number() {
        let case = SYSTEM
            .load(
                include_str!("../../../decks/chen_b.toml"),
                "chen_b",
                &[
                    "operating.radial_load=500".to_string(),
                    "dynamics.method=time-simulation".to_string(),
                    "dynamics.orbits=1".to_string(),
                ],
            )
            .unwrap();
        let plain = BallSession
            .solve(case.as_ref(), Detail::default(), &Cancel::NONE)
            .unwrap();
        let mut charts = Vec::new();
        let streamed = BallSession
            .solve_streaming(
                case.as_ref(),
                Detail {
                    stream_chart: Some(SKID_CHART),
                    ..Detail::default()
                },
                &Cancel::NONE,
                &mut |n, c| charts.push((n, c)),
            )
            .unwrap();
        assert_eq!(plain.json(), streamed.json());
        let samples = streamed.json()["skid"]["curve"].as_array().unwrap().len();
        assert!(samples > 10, "{samples}"); // 22: the crossing at 5 116 rpm
        assert_eq!(charts.len(), samples + 1);
        assert!(charts.iter().all(|(n, _)| *n == SKID_CHART));
        assert_eq!(charts.last().unwrap().1, streamed.view().charts[SKID_CHART]);
        let mut none = 0;
        BallSession
            .solve_streaming(
                case.as_ref(),
                Detail::default(),
                &Cancel::NONE,
                &mut |_, _| none += 1,
            )
            .unwrap();
        assert_eq!(none, 0);
    }
}
