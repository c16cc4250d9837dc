//! The tapered roller bearing's registration: how its decks are read, solved and shown
//! through the system-independent [`BearingSystem`] interface.

use super::analysis::{analyse, analyse_from, Analysis};
use super::bearing::BearingSolution;
use super::deck::SCHEMA;
use super::input::TaperedInput;
use super::SYSTEM_ID;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{
    Case, Detail, Fidelity, FidelityGrid, FormSystem, RunOptions, Session, Solution, SolveError,
    SweepPlan, SystemCase,
};
use crate::deck::form::{Form, Schema};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::thermal::ThermalModel;
use crate::units::{restate_si, Units};

/// The shipped example deck: the seed's §3.1 sample.
pub const EXAMPLE_DECK: &str = include_str!("../../../decks/trb_afapl.toml");

/// The fidelity study (issue 17's `bench`): slices per contact × force tolerance against
/// 321 slices at 10⁻¹⁰.
pub const FIDELITY_GRID: FidelityGrid = FidelityGrid {
    resolution_key: "slices",
    resolution_symbol: "n",
    resolutions: &[5, 7, 11, 15, 21, 31, 41, 61, 81, 121, 161],
    tolerances: &[1e-6, 1e-9],
    reference: Fidelity {
        resolution: 321,
        tolerance: 1e-10,
    },
};

/// The tapered roller bearing system (registered in `crate::bearings::SYSTEMS`).
pub struct TaperedRoller;

/// The registry entry.
pub static SYSTEM: TaperedRoller = TaperedRoller;

impl FormSystem for TaperedRoller {
    type Input = TaperedInput;
    type Derived = Option<ThermalModel>;

    fn registered() -> &'static Self {
        &SYSTEM
    }

    fn schema(&self) -> &'static Schema<TaperedInput> {
        &SCHEMA
    }

    fn title(&self) -> &'static str {
        "tapered roller bearing (stiffness with centrifugal effects)"
    }

    fn method(&self) -> &'static str {
        "flange-guided rollers on Lundberg line-contact slices, 5×5 stiffness (AFAPL-TR-78-6 Part III, 1978)"
    }

    fn element_name(&self) -> &'static str {
        "roller"
    }

    fn session(&self) -> Box<dyn Session> {
        Box::new(TaperedSession::default())
    }

    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        Some(FIDELITY_GRID)
    }

    /// The Sweep pane (issue 17): K_xx, K_zz and K_θxθx against the cone speed, each
    /// divided by its zero-speed value, from 0 to 2.5 × the deck's speed (at least
    /// 10 000 rpm; the sample's 20 000 rpm gives 0–50 000 rpm, past the ≈ 41 200 rpm where
    /// the rollers leave the cone) in 21 points, the first speed with a roller off the
    /// cone marked.
    fn sweep_plan(&self, n: usize, case: &dyn Case) -> Option<SweepPlan> {
        if n != 0 {
            return None;
        }
        Some(SweepPlan {
            title: "stiffness ÷ zero-speed value".to_string(),
            key: "operating.inner_speed",
            values: SweepPlan::span_from_zero(case, "operating.inner_speed", 2.5, 10_000.0, 21),
            outputs: vec![
                "stiffness_xx_n_m",
                "stiffness_zz_n_m",
                "stiffness_thetax_nm_rad",
            ],
            normalise: true,
            marker: Some(("rollers_off_cone", "off cone")),
        })
    }

    fn panes(&self) -> &'static [PaneSpec] {
        const PANES: [PaneSpec; 8] = [
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
                title: "Rollers",
            },
            PaneSpec {
                kind: PaneKind::Chart(0),
                title: "Load",
            },
            PaneSpec {
                kind: PaneKind::Text(0),
                title: "Stiffness",
            },
            PaneSpec {
                kind: PaneKind::Sweep(0),
                title: "Sweep",
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
            "operating.radial_load",
            "operating.axial_load",
            "geometry.roller_diameter",
        ]
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    /// The deck's `[thermal]` network built (errors name node, link and field).
    fn prepare(form: &mut Form<TaperedInput>) -> Result<Option<ThermalModel>, DeckErrors> {
        form.thermal_model()
    }

    fn has_transient(case: &TaperedCase) -> bool {
        case.derived
            .as_ref()
            .is_some_and(|_| case.form.value.lubricant.is_given())
    }

    fn solve(
        case: &TaperedCase,
        options: RunOptions,
        cancel: Cancel,
    ) -> Result<Box<dyn Solution>, String> {
        if cancel.is_cancelled() {
            return Err("cancelled".to_string());
        }
        // The errors are worded in SI deep in the solver; a US deck's user reads them in
        // lbf and inches like the other systems' (issue 24 item 15).
        let mut a = analyse(&case.form.value, &case.form.name)
            .map_err(|e| restate_si(&e.to_string(), case.form.units))?;
        with_thermal(
            &mut a,
            case.derived.as_ref(),
            !options.skip_transient,
            &cancel,
        );
        Ok(Box::new(TaperedSolution(a)))
    }

    fn fidelity(input: &TaperedInput) -> Option<Fidelity> {
        Some(Fidelity {
            resolution: input.solver.slices,
            tolerance: input.solver.force_tolerance,
        })
    }

    fn set_fidelity(input: &mut TaperedInput, f: Fidelity) -> bool {
        input.solver.slices = f.resolution;
        input.solver.force_tolerance = f.tolerance;
        true
    }
}

/// Solve the deck's thermal network on `a` (when the deck has one and a lubricant).
fn with_thermal(a: &mut Analysis, model: Option<&ThermalModel>, transient: bool, cancel: &Cancel) {
    if let Some(m) = model {
        if a.bearing.input.lubricant.is_given() {
            let cancelled = || cancel.is_cancelled();
            a.thermal = Some(super::thermal::solve(a, m, transient, &cancelled));
        } else {
            a.thermal = Some(Err("thermal network: the deck has no lubricant (lubricant.viscosity = \"none\"), so no friction heat to feed it".to_string()));
        }
    }
}

/// A validated tapered roller deck.
pub type TaperedCase = SystemCase<TaperedRoller>;

/// A solved tapered roller bearing.
pub struct TaperedSolution(pub Analysis);

impl Solution for TaperedSolution {
    fn view(&self) -> View {
        super::view::view(&self.0)
    }

    fn json(&self) -> serde_json::Value {
        super::report::json(&self.0)
    }

    fn text(&self, units: Units) -> String {
        super::report::text(&self.0, units)
    }
}

/// The tapered roller's session: it keeps the last converged equilibrium (ring
/// displacements and every roller's (Δ₁, θ₁) and state) and starts the next solve from
/// it, falling back to the cold start when the warm one fails
/// ([`super::analysis::analyse_from`]). A sweep solved point after point through one
/// session is a continuation in the swept parameter.
#[derive(Default)]
pub struct TaperedSession {
    last: Option<BearingSolution>,
}

impl TaperedSession {
    /// The last converged equilibrium, if any.
    pub fn last(&self) -> Option<&BearingSolution> {
        self.last.as_ref()
    }

    /// Solve `input` from the last equilibrium (the typed analysis, for benches and
    /// tests). A failure keeps the last equilibrium as the next start.
    pub fn analyse(
        &mut self,
        input: &TaperedInput,
        name: &str,
    ) -> Result<Analysis, super::bearing::BearingError> {
        let a = analyse_from(input, name, self.last.as_ref())?;
        self.last = Some(a.solution.clone());
        Ok(a)
    }
}

impl Session for TaperedSession {
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError> {
        let case = TaperedCase::of(case)?;
        if cancel.is_cancelled() {
            return Err(SolveError::Cancelled);
        }
        // The same message as `Case::solve`, so a sweep reads alike through either.
        let mut a = self
            .analyse(&case.form.value, &case.form.name)
            .map_err(|e| SolveError::Stage {
                stage: SYSTEM_ID,
                message: restate_si(&e.to_string(), case.form.units),
            })?;
        with_thermal(&mut a, case.derived.as_ref(), detail.transient, cancel);
        Ok(Box::new(TaperedSolution(a)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::BearingSystem;
    use crate::units::{LBF_N, RPM_RAD_S};

    fn lc(rpm: f64, radial_lbf: f64) -> TaperedInput {
        let mut s = TaperedInput::afapl_sample();
        s.operating.inner_speed_rad_s = rpm * RPM_RAD_S;
        s.operating.radial_load_n = radial_lbf * LBF_N;
        s
    }

    /// The session's warm-started answers equal cold starts to the solver tolerance
    /// (both stop on the same force tolerance, 1e-9 of the load by default): reactions to
    /// 1e-8 of the thrust, displacements and the stiffness to 1e-6 relative. Load
    /// Condition 2 over 0–39 800 rpm crosses the switch of single rollers to the
    /// cup-and-flange state (≈ 38 900 rpm); the states agree too. A point without
    /// equilibrium (50 000 rpm) is the typed error and the session carries on from its
    /// last converged point.
    #[test]
    fn session_warm_start_equals_cold_start() {
        let mut session = TaperedSession::default();
        let mut speeds: Vec<f64> = (0..=19).map(|i| 2_000.0 * i as f64).collect();
        speeds.extend([38_900.0, 39_000.0, 39_400.0, 39_800.0, 50_000.0, 20_000.0]);
        for rpm in speeds {
            let s = lc(rpm, 700.0);
            let cold = analyse(&s, "cold");
            let warm = session.analyse(&s, "warm");
            let (cold, warm) = match (cold, warm) {
                (Ok(c), Ok(w)) => (c, w),
                (Err(c), Err(w)) => {
                    assert_eq!(c.to_string(), w.to_string());
                    assert!(rpm > 39_800.0);
                    continue;
                }
                (c, w) => panic!("{rpm}: {c:?} vs {w:?}"),
            };
            let fa = s.operating.axial_load_n;
            let (c, w) = (&cold.solution, &warm.solution);
            for j in 0..3 {
                assert!((c.reaction[j] - w.reaction[j]).abs() < 1e-8 * fa, "{rpm}");
                let scale = c.displacement_m[2].abs();
                assert!((c.displacement_m[j] - w.displacement_m[j]).abs() < 1e-6 * scale);
            }
            let kmax = c.stiffness.abs().max();
            assert!(
                (c.stiffness - w.stiffness).abs().max() < 1e-6 * kmax,
                "{rpm}"
            );
            for (a, b) in c.rollers.iter().zip(&w.rollers) {
                assert_eq!(a.0.state, b.0.state, "{rpm}");
            }
        }
        assert!(session.last().is_some());
    }

    /// Through the `Session` trait: the JSON states name the branch.
    #[test]
    fn session_trait_solves_and_names_states() {
        let case = SYSTEM
            .load(
                EXAMPLE_DECK,
                "trb_afapl.toml",
                &[
                    "operating.radial_load=700".to_string(),
                    "operating.inner_speed=39500".to_string(),
                ],
            )
            .unwrap();
        let mut session = BearingSystem::session(&SYSTEM);
        let sol = session
            .solve(case.as_ref(), Detail::default(), &Cancel::NONE)
            .unwrap();
        let json = sol.json();
        let states: Vec<&str> = json["rollers"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["state"].as_str().unwrap())
            .collect();
        assert!(states.contains(&"both-races") && states.contains(&"cup-and-flange"));
    }

    /// The lubricated deck's network balances: heat out = heat in to 1e-9 (a linear solve
    /// of four free nodes: round-off), and the heat in is the friction's power (every
    /// mechanism is bound to a node).
    #[test]
    fn lubricated_thermal_network_balances() {
        let deck = include_str!("../../../decks/trb_afapl_lubricated.toml");
        let case = SYSTEM.load(deck, "trb_afapl_lubricated.toml", &[]).unwrap();
        let mut session = BearingSystem::session(&SYSTEM);
        let sol = session
            .solve(case.as_ref(), Detail::default(), &Cancel::NONE)
            .unwrap();
        let j = sol.json();
        let th = &j["thermal"]["steady"];
        let qin = th["heat_in_w"].as_f64().unwrap();
        let qout = th["heat_out_w"].as_f64().unwrap();
        assert!((qin - qout).abs() <= 1e-9 * qin, "{qin} {qout}");
        let p = j["friction"]["power_w"].as_f64().unwrap();
        assert!((qin / p - 1.0).abs() < 1e-12, "{qin} {p}");
    }
}
