//! The tapered roller bearing's registration: how its decks are read, solved and shown
//! through the system-independent [`BearingSystem`] interface.

use super::analysis::{analyse, Analysis};
use super::deck::{SCHEMA, SYSTEM_ID};
use super::input::TaperedInput;
use crate::bearings::view::{PaneKind, PaneSpec, View};
use crate::bearings::{
    BearingSystem, Case, Fidelity, FidelityGrid, FormCase, RunOptions, Solution, SweepPlan,
};
use crate::deck::form::{template, Form};
use crate::deck::DeckErrors;
use crate::numerics::cancel::Cancel;
use crate::units::Units;

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

impl BearingSystem for TaperedRoller {
    fn id(&self) -> &'static str {
        SYSTEM_ID
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
        let here = case
            .get("operating.inner_speed")
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(0.0)
            .abs();
        let top = (2.5 * here).max(10_000.0);
        let points = 21;
        let values = (0..points)
            .map(|i| top * i as f64 / (points - 1) as f64)
            .collect();
        Some(SweepPlan {
            title: "stiffness ÷ zero-speed value".to_string(),
            key: "operating.inner_speed",
            values,
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
        const PANES: [PaneSpec; 5] = [
            PaneSpec {
                kind: PaneKind::Inputs,
                title: "Inputs",
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
        ];
        &PANES
    }

    fn keys_table(&self) -> String {
        crate::deck::form::keys_table(&SCHEMA)
    }

    fn template(&self, units: Units) -> String {
        template(&SCHEMA, units)
    }

    fn example_deck(&self) -> &'static str {
        EXAMPLE_DECK
    }

    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors> {
        let mut form = Form::parse(text, source_name, &SCHEMA)?;
        form.apply_assignments(overrides)?;
        Ok(Box::new(TaperedCase { form }))
    }
}

/// A validated tapered roller deck.
pub struct TaperedCase {
    /// The deck (SI input inside).
    pub form: Form<TaperedInput>,
}

impl FormCase for TaperedCase {
    type Input = TaperedInput;

    fn form(&self) -> &Form<TaperedInput> {
        &self.form
    }

    fn with_form(&self, form: Form<TaperedInput>) -> Result<Box<dyn Case>, DeckErrors> {
        Ok(Box::new(TaperedCase { form }))
    }
}

impl Case for TaperedCase {
    fn system(&self) -> &'static dyn BearingSystem {
        &SYSTEM
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }

    fn fidelity(&self) -> Option<Fidelity> {
        let s = &self.form.value.solver;
        Some(Fidelity {
            resolution: s.slices,
            tolerance: s.force_tolerance,
        })
    }

    fn with_fidelity(&self, f: Fidelity) -> Option<Box<dyn Case>> {
        let mut form = self.form.clone();
        form.value.solver.slices = f.resolution;
        form.value.solver.force_tolerance = f.tolerance;
        Some(Box::new(TaperedCase { form }))
    }

    fn units(&self) -> Units {
        self.form.units
    }

    fn solve(&self, _options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String> {
        if cancel.is_cancelled() {
            return Err("cancelled".to_string());
        }
        analyse(&self.form.value, &self.form.name)
            .map(|a| Box::new(TaperedSolution(a)) as Box<dyn Solution>)
            .map_err(|e| e.to_string())
    }
}

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
