//! Bearing systems. Each system is one folder (its input, geometry, solver, solution and
//! view) registered once in [`SYSTEMS`]; what systems share lives below them
//! (`crate::physics`, `crate::numerics`, `crate::thermal`). A deck names its system with
//! the top-level key `type`; an absent `type` means [`DEFAULT_SYSTEM`], so decks written
//! before there was a choice keep working.
//!
//! The front ends (`cli`, `report`, `verify`, `tui`) reach a system only through
//! [`BearingSystem`]: parse a deck, solve it, and draw what it shows from its
//! [`view::View`] (tables and key outputs with their units).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod angular_ball;
pub mod answer;
pub mod cylindrical_roller;
pub mod double_row_spherical;
pub mod error;
pub mod form_system;
pub mod friction;
pub mod spherical_roller;
pub mod stiffness;
pub mod stiffness_text;
pub mod tapered_roller;
pub mod thermal_answer;
pub mod view;

pub use error::SolveError;
pub use form_system::{FormSystem, SystemCase};

use crate::deck::{DeckError, DeckErrors, DeckType, FieldMeta, Form, Location};
use crate::numerics::cancel::Cancel;
use crate::units::Units;

/// The `type` of a deck that does not name one (the deck format's rule,
/// [`crate::deck::DEFAULT_TYPE`]).
pub const DEFAULT_SYSTEM: &str = crate::deck::DEFAULT_TYPE;

/// Every bearing system rollbench knows, in the order `rollbench template --type` and
/// error messages list them. Adding a system is one line here.
pub static SYSTEMS: &[&dyn BearingSystem] = &[
    &spherical_roller::SYSTEM,
    &angular_ball::system::SYSTEM,
    &tapered_roller::SYSTEM,
    &cylindrical_roller::SYSTEM,
    &double_row_spherical::SYSTEM,
];

/// What a run is asked to compute beyond the bearing itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RunOptions {
    /// Skip expensive time simulations (the loss-of-oil transient of a thermal network).
    pub skip_transient: bool,
}

/// What the workbench asks of a solve beyond the report's defaults: only what the panes on
/// screen show is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Detail {
    /// Record the equilibrium iterations of this element (0-based) for the stepper.
    pub trace_element: Option<usize>,
    /// Run the expensive time simulations (the thermal transient).
    pub transient: bool,
    /// The chart pane (`view::PaneKind::Chart(n)`) on screen: a system whose session
    /// fills that chart stage by stage sends it as it grows
    /// ([`Session::solve_streaming`]); others ignore it.
    pub stream_chart: Option<usize>,
}

/// A sweep a workbench pane draws: key outputs of the case re-solved at each value of one
/// deck key (the same path as `rollbench sweep`, warm-started along the values).
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPlan {
    /// Chart title.
    pub title: String,
    /// The deck key swept (`operating.inner_speed`).
    pub key: &'static str,
    /// Its values in sweep order, deck units.
    pub values: Vec<f64>,
    /// The key outputs drawn ([`view::KeyOutput::name`]).
    pub outputs: Vec<&'static str>,
    /// Draw each output divided by its value at the first solved point (stiffness against
    /// its zero-speed value) instead of in its unit.
    pub normalise: bool,
    /// Mark the first value at which this key output becomes positive (rollers leaving
    /// the cone), with this label.
    pub marker: Option<(&'static str, &'static str)>,
}

impl SweepPlan {
    /// `points` values from 0 to `factor` × the case's own value of `key` (its magnitude),
    /// at least to `floor`, evenly spaced: the workbench's default span around a deck.
    pub fn span_from_zero(
        case: &dyn Case,
        key: &str,
        factor: f64,
        floor: f64,
        points: usize,
    ) -> Vec<f64> {
        let here = case
            .get(key)
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(0.0)
            .abs();
        let top = (factor * here).max(floor);
        let last = points.saturating_sub(1).max(1) as f64;
        (0..points).map(|i| top * i as f64 / last).collect()
    }
}

/// A fidelity setting of a case: how finely its elements are discretised (laminae,
/// slices) and how tightly its equilibria are solved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fidelity {
    /// Laminae or slices per element.
    pub resolution: usize,
    /// Force tolerance of the equilibria, relative (dimensionless).
    pub tolerance: f64,
}

/// A system's run-time-against-error study (`rollbench bench`): the grid of fidelities and
/// the reference they are compared with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FidelityGrid {
    /// The JSON name of the resolution (`"laminae"`, `"slices"`).
    pub resolution_key: &'static str,
    /// Its symbol in text tables (`"Γ"`).
    pub resolution_symbol: &'static str,
    /// Resolutions of the grid, ascending.
    pub resolutions: &'static [usize],
    /// Tolerances of the grid, loosest first.
    pub tolerances: &'static [f64],
    /// The high-fidelity reference.
    pub reference: Fidelity,
}

/// A bearing system: how its decks are read, solved and shown.
pub trait BearingSystem: Sync {
    /// The deck's `type`, e.g. `"spherical-roller"`.
    fn id(&self) -> &'static str;
    /// What the system is, for headers and reports.
    fn title(&self) -> &'static str;
    /// The method and its source (seed document).
    fn method(&self) -> &'static str;
    /// What one rolling element is called (`"roller"`, `"ball"`), for the stepper and
    /// status lines.
    fn element_name(&self) -> &'static str;
    /// The workbench panes this system offers, in switcher order.
    fn panes(&self) -> &'static [view::PaneSpec];
    /// A solver for the workbench that keeps what it computed between solves, so an edit
    /// re-runs only the stages whose inputs it changed. By default each solve is whole
    /// ([`WholeSolve`]).
    fn session(&self) -> Box<dyn Session> {
        Box::new(WholeSolve)
    }
    /// Sweep `n` of a [`view::PaneKind::Sweep`] pane over `case`: which deck key, which
    /// values, which key outputs; `None` when the system has no such sweep.
    fn sweep_plan(&self, _n: usize, _case: &dyn Case) -> Option<SweepPlan> {
        None
    }
    /// Runs job `n` of a [`view::PaneKind::Job`] pane on `case` (a long study: a load
    /// sweep, an optimisation), telling `report` what it has so far as it goes (each call
    /// the whole job so far) and returning the finished view; `cancel` stops it (then
    /// [`SolveError::Cancelled`]). `None` when the system has no such job.
    fn run_job(
        &self,
        _n: usize,
        _case: &dyn Case,
        _cancel: Cancel<'_>,
        _report: &mut dyn FnMut(&view::JobView),
    ) -> Option<Result<view::JobView, SolveError>> {
        None
    }
    /// The fidelity study of `rollbench bench`; `None` when the system has none.
    fn fidelity_grid(&self) -> Option<FidelityGrid> {
        None
    }
    /// The deck keys the workbench's Study pane tolerances by default (±1 %, uniform),
    /// in order of preference: the system's main geometry and operating keys. The pane
    /// takes the first three the deck gives a non-zero number; empty: the system names
    /// none (the pane then needs a study file).
    fn study_keys(&self) -> &'static [&'static str] {
        &[]
    }
    /// The table `rollbench keys --type` prints: every key `--set` accepts, with units and
    /// allowed range.
    fn keys_table(&self) -> String;
    /// A fully commented deck in `units` that parses back.
    fn template(&self, units: Units) -> String;
    /// The shipped example deck (text), embedded in the binary.
    fn example_deck(&self) -> &'static str;
    /// Parse and validate deck text of this system, apply `key=value` overrides (deck
    /// units) and validate the result once; errors name file, line, key and range.
    fn load(
        &self,
        text: &str,
        source_name: &str,
        overrides: &[String],
    ) -> Result<Box<dyn Case>, DeckErrors>;
}

/// The deck behind a [`Case`], for the workbench's editor (values in deck units). A case
/// whose deck is a [`Form`] gets all of it from [`FormCase`].
pub trait CaseDeck {
    /// The deck's `name`.
    fn name(&self) -> &str;
    /// Where the deck was read from (errors name it).
    fn source_name(&self) -> &str;
    /// The deck's editable scalar fields, in deck order.
    fn fields(&self) -> Vec<&'static FieldMeta>;
    /// The SI value of field `key` in effect (choice index for choices); `None` for keys
    /// that are not fields.
    fn field_si(&self, key: &str) -> Option<f64>;
    /// The value of `key` as written in the deck (deck units; strings unquoted), or in
    /// effect where the deck omits it.
    fn get(&self, key: &str) -> Option<String>;
    /// The case with `key` set to `value` (deck units), the whole deck re-validated;
    /// comments and layout kept.
    fn with_value(&self, key: &str, value: &str) -> Result<Box<dyn Case>, DeckErrors>;
    /// The case with every `key=value` assignment set (deck units), then validated once,
    /// as `--set` does: the order of the assignments never changes the verdict, and a pair
    /// of keys that must change together (speed and cage speed) is never judged half-set.
    /// A study's point with several keys is built this way.
    fn with_values(&self, assignments: &[String]) -> Result<Box<dyn Case>, DeckErrors>;
    /// The deck's text (what a save writes).
    fn text(&self) -> String;
    /// Saves the deck (atomic, previous file kept as `.bak`; see [`crate::files`]).
    fn save(&self, path: &std::path::Path) -> Result<crate::files::Written, DeckErrors>;
}

/// A case whose deck is a [`Form`] of its system's schema (every system's, through
/// [`SystemCase`]): the [`CaseDeck`] half of the case comes with it.
pub trait FormCase: Sized {
    /// The system's SI input.
    type Input: Clone + 'static;
    /// The case's deck.
    fn form(&self) -> &Form<Self::Input>;
    /// The case of an edited deck (whatever the case derives from its deck, derived
    /// again), boxed.
    fn with_form(&self, form: Form<Self::Input>) -> Result<Box<dyn Case>, DeckErrors>;
}

impl<C: FormCase> CaseDeck for C {
    fn name(&self) -> &str {
        &self.form().name
    }

    fn source_name(&self) -> &str {
        self.form().source_name()
    }

    fn fields(&self) -> Vec<&'static FieldMeta> {
        self.form()
            .schema()
            .fields
            .iter()
            .map(|f| &f.meta)
            .collect()
    }

    fn field_si(&self, key: &str) -> Option<f64> {
        let form = self.form();
        form.schema().field(key).map(|f| f.get_si(&form.value))
    }

    fn get(&self, key: &str) -> Option<String> {
        self.form().get(key)
    }

    fn with_value(&self, key: &str, value: &str) -> Result<Box<dyn Case>, DeckErrors> {
        let mut form = self.form().clone();
        form.set(key, value)?;
        self.with_form(form)
    }

    fn with_values(&self, assignments: &[String]) -> Result<Box<dyn Case>, DeckErrors> {
        let mut form = self.form().clone();
        form.apply_assignments(assignments)?;
        self.with_form(form)
    }

    fn text(&self) -> String {
        self.form().to_toml_string()
    }

    fn save(&self, path: &std::path::Path) -> Result<crate::files::Written, DeckErrors> {
        self.form().save(path)
    }
}

/// One validated deck of a system, ready to solve.
pub trait Case: CaseDeck + Send + Sync {
    /// The system the deck belongs to.
    fn system(&self) -> &'static dyn BearingSystem;
    /// For the system's own [`Session`] to reach its concrete case.
    fn as_any(&self) -> &dyn std::any::Any;
    /// The unit system the deck is written in (text reports use it).
    fn units(&self) -> Units;
    /// Solve everything a full report shows.
    fn solve(&self, options: RunOptions, cancel: Cancel) -> Result<Box<dyn Solution>, String>;

    /// True if the deck has a time simulation that [`Detail::transient`] turns on.
    fn has_transient(&self) -> bool {
        false
    }
    /// The deck's own fidelity, when the system has a fidelity study.
    fn fidelity(&self) -> Option<Fidelity> {
        None
    }
    /// The case at fidelity `f` (every other input unchanged); `None` when the system has
    /// no fidelity settings.
    fn with_fidelity(&self, f: Fidelity) -> Option<Box<dyn Case>> {
        let _ = f;
        None
    }
    /// Why this deck's answer does not depend on its fidelity settings (the ball's race
    /// control solves no slices), said by `rollbench bench` instead of a table of zero
    /// errors that recommends the coarsest cell (issue 30 item 17); `None` when it does.
    fn fidelity_unused(&self) -> Option<String> {
        None
    }
}

/// Reads deck text of any system: its `type` picks the system, which parses, applies the
/// `key=value` overrides (deck units) and validates.
pub fn load_case(
    text: &str,
    source_name: &str,
    overrides: &[String],
) -> Result<Box<dyn Case>, DeckErrors> {
    system_of(text, source_name)?.load(text, source_name, overrides)
}

/// Reads a deck file of any system (bounded read; see [`crate::deck::read_deck_text`]).
pub fn load_file(
    path: &std::path::Path,
    overrides: &[String],
) -> Result<Box<dyn Case>, DeckErrors> {
    let text = crate::deck::read_deck_text(path)?;
    load_case(&text, &path.display().to_string(), overrides)
}

/// The workbench's solver of one system's cases; see [`BearingSystem::session`].
pub trait Session: Send {
    /// Solves `case` (a case of this session's system) with the extra `detail` the panes
    /// on screen need. `cancel` is checked between iterations: a cancelled solve returns
    /// [`SolveError::Cancelled`].
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError>;

    /// [`Session::solve`], sending chart `detail.stream_chart` through `on_chart` as it
    /// grows (the ball's Skid chart: one call per speed the skidding search solves) for a
    /// system that builds that chart stage by stage. The solution is the same as
    /// [`Session::solve`]'s; the last chart sent equals its view's. By default nothing
    /// is streamed.
    fn solve_streaming(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
        on_chart: &mut dyn FnMut(usize, view::Chart),
    ) -> Result<Box<dyn Solution>, SolveError> {
        let _ = on_chart;
        self.solve(case, detail, cancel)
    }
}

/// The session of a system that caches nothing: every solve is [`Case::solve`], with the
/// transient when the panes ask for it (a system without a stepper trace ignores
/// [`Detail::trace_element`]).
pub struct WholeSolve;

impl Session for WholeSolve {
    fn solve(
        &mut self,
        case: &dyn Case,
        detail: Detail,
        cancel: &Cancel,
    ) -> Result<Box<dyn Solution>, SolveError> {
        let options = RunOptions {
            skip_transient: !detail.transient,
        };
        case.solve(options, Cancel::from_option(cancel.flag()))
            .map_err(|message| SolveError::Stage {
                stage: case.system().id(),
                message,
            })
    }
}

/// A solved case: what reports and panes draw from.
pub trait Solution: Send + Sync {
    /// Tables, summary lines and key outputs, SI, each with its unit.
    fn view(&self) -> view::View;
    /// The JSON report (SI, units in key names; a contract: fields are added, never
    /// renamed).
    fn json(&self) -> serde_json::Value;
    /// The text report in `units`.
    fn text(&self, units: Units) -> String;
    /// The time history of a time-domain solution as CSV (SI, units in the header; the
    /// CLI's `run --series FILE`), or why there is none, naming the deck key that would
    /// give one. Systems without a time history keep this default.
    fn series_csv(&self) -> Result<String, String> {
        Err("this bearing system records no time history".to_string())
    }
}

/// The system a deck `type` names.
pub fn system(id: &str) -> Option<&'static dyn BearingSystem> {
    SYSTEMS.iter().copied().find(|s| s.id() == id)
}

/// The known `type` values, quoted and comma-separated (for error messages).
pub fn known_types() -> String {
    SYSTEMS
        .iter()
        .map(|s| format!("\"{}\"", s.id()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The system deck text belongs to, by its top-level `type` (absent: [`DEFAULT_SYSTEM`]);
/// an unknown system is refused at its line, listing the known ones, and a `type` that is
/// not a string is a type error. A deck whose arrays exceed their bound
/// ([`crate::deck::bounds`]) is refused first.
pub fn system_of(text: &str, source_name: &str) -> Result<&'static dyn BearingSystem, DeckErrors> {
    // Before any document is built: a deck's arrays are bounded (issue 24).
    crate::deck::bounds::check_arrays(text, source_name)?;
    let (id, location, value) = match crate::deck::deck_type(text, source_name) {
        DeckType::Absent => (
            DEFAULT_SYSTEM.to_string(),
            Location::start(source_name),
            String::new(),
        ),
        DeckType::Named {
            id,
            location,
            written,
        } => (id, location, written),
        DeckType::NotAString { location, written } => {
            return Err(DeckError::WrongType {
                location,
                key: "type".into(),
                value: written,
                expected: format!("a string, one of {}", known_types()),
            }
            .into())
        }
    };
    system(&id).ok_or_else(|| {
        DeckError::Invalid {
            location,
            key: "type".into(),
            value,
            rule: format!("unknown bearing system (known: {})", known_types()),
        }
        .into()
    })
}

#[cfg(test)]
mod tests;
