//! What a solved bearing shows, independent of the system: tables of SI values with
//! their columns' units, and the key outputs the fidelity bench compares. Reports and
//! panes draw from a [`View`]; none of them re-joins a system's per-element arrays.

use crate::units::{
    Quantity, Units, BTU_PER_HOUR_PER_WATT, FOOT_M, INCH_LBF_N_M, INCH_M, LBF_N, PSI_PA,
};

/// How a value is shown on screen: the display unit an engineer reads it in, per unit
/// system (contact stress in MPa or ksi, film in µm or µin, deflections in mm or mil).
/// Reports keep SI with the unit in the key; this is only for panes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Display {
    /// Shown as computed, no unit in the header (counts, ratios, angles in degrees,
    /// speeds in rpm, heat in W).
    Plain,
    /// N or lbf.
    Force,
    /// Load per unit length: N/mm or lbf/in.
    LineLoad,
    /// Positions along a roller or a contact, semi-axes, offsets: mm or mil (0.001 in).
    SmallLength,
    /// Ring and element deflections and approaches: µm or µin, as the text reports print
    /// them (issue 30 item 7: the workbench showed mil where the text said µin).
    Deflection,
    /// Film thickness: µm or µin.
    Film,
    /// Contact stress: MPa or ksi.
    Stress,
    /// Small angles (tilts, misalignments): mrad in both systems.
    SmallAngle,
    /// Heat rates: W or Btu/hr.
    Power,
    /// Moments: N·m or lbf·in.
    Moment,
    /// Surface and sliding speeds: m/s or ft/s.
    Speed,
    /// Small velocities (a shaft's vibration velocity): mm/s or in/s.
    SmallSpeed,
    /// Load ratings and large forces: kN or kip (1000 lbf).
    LargeForce,
    /// Rotational speeds: rpm in both systems.
    Rpm,
    /// Frequencies: Hz in both systems.
    Frequency,
    /// Lives in millions of revolutions: Mrev in both systems.
    Mrev,
    /// Lives in hours: h in both systems.
    Hours,
    /// Temperatures, given in °C (as the key outputs keep them): °C or °F.
    Temperature,
    /// Durations: s in both systems.
    Seconds,
    /// A state stored as its index into these names (the tapered roller's
    /// `both-races`/`cup-and-flange`/`free`): the pane shows the name, CSV the index.
    Choice(&'static [&'static str]),
}

impl Display {
    /// The SI value `v` in display units.
    pub fn convert(self, v: f64, u: Units) -> f64 {
        match (self, u) {
            (Display::Plain | Display::Choice(_), _) => v,
            (Display::Force, Units::Si) => v,
            (Display::Force, Units::Us) => v / LBF_N,
            (Display::LineLoad, Units::Si) => v * 1e-3,
            (Display::LineLoad, Units::Us) => v / LBF_N * INCH_M,
            (Display::SmallLength, Units::Si) => v * 1e3,
            (Display::SmallLength, Units::Us) => v / INCH_M * 1e3,
            (Display::Film | Display::Deflection, Units::Si) => v * 1e6,
            (Display::Film | Display::Deflection, Units::Us) => v / INCH_M * 1e6,
            (Display::Stress, Units::Si) => v / 1e6,
            (Display::Stress, Units::Us) => v / PSI_PA / 1e3,
            (Display::SmallAngle, _) => v * 1e3,
            (Display::Power, Units::Si) => v,
            (Display::Power, Units::Us) => v * BTU_PER_HOUR_PER_WATT,
            (Display::Moment, Units::Si) => v,
            (Display::Moment, Units::Us) => v / INCH_LBF_N_M,
            (Display::Speed, Units::Si) => v,
            (Display::Speed, Units::Us) => v / FOOT_M,
            (Display::SmallSpeed, Units::Si) => v * 1e3,
            (Display::SmallSpeed, Units::Us) => v / INCH_M,
            (Display::LargeForce, Units::Si) => v * 1e-3,
            (Display::LargeForce, Units::Us) => v / LBF_N * 1e-3,
            (
                Display::Rpm
                | Display::Frequency
                | Display::Mrev
                | Display::Hours
                | Display::Seconds,
                _,
            ) => v,
            (Display::Temperature, Units::Si) => v,
            (Display::Temperature, Units::Us) => v * 1.8 + 32.0,
        }
    }

    /// The display unit's label (empty for [`Display::Plain`]).
    pub fn unit(self, u: Units) -> &'static str {
        match (self, u) {
            (Display::Plain | Display::Choice(_), _) => "",
            (Display::Force, Units::Si) => "N",
            (Display::Force, Units::Us) => "lbf",
            (Display::LineLoad, Units::Si) => "N/mm",
            (Display::LineLoad, Units::Us) => "lbf/in",
            (Display::SmallLength, Units::Si) => "mm",
            (Display::SmallLength, Units::Us) => "mil",
            (Display::Film | Display::Deflection, Units::Si) => "µm",
            (Display::Film | Display::Deflection, Units::Us) => "µin",
            (Display::Stress, Units::Si) => "MPa",
            (Display::Stress, Units::Us) => "ksi",
            (Display::SmallAngle, _) => "mrad",
            (Display::Power, Units::Si) => "W",
            (Display::Power, Units::Us) => "Btu/hr",
            (Display::Moment, Units::Si) => "N·m",
            (Display::Moment, Units::Us) => "lbf·in",
            (Display::Speed, Units::Si) => "m/s",
            (Display::Speed, Units::Us) => "ft/s",
            (Display::SmallSpeed, Units::Si) => "mm/s",
            (Display::SmallSpeed, Units::Us) => "in/s",
            (Display::LargeForce, Units::Si) => "kN",
            (Display::LargeForce, Units::Us) => "kip",
            (Display::Rpm, _) => "rpm",
            (Display::Frequency, _) => "Hz",
            (Display::Mrev, _) => "Mrev",
            (Display::Hours, _) => "h",
            (Display::Seconds, _) => "s",
            (Display::Temperature, Units::Si) => "°C",
            (Display::Temperature, Units::Us) => "°F",
        }
    }

    /// The name a [`Display::Choice`] value stands for (`None` for other kinds, or an
    /// index out of range).
    pub fn choice(self, v: f64) -> Option<&'static str> {
        match self {
            Display::Choice(names) if v >= 0.0 && v.fract() == 0.0 => {
                names.get(v as usize).copied()
            }
            _ => None,
        }
    }

    /// `label` followed by the display unit, if any (`"Qi lbf"`).
    pub fn header(self, label: &str, u: Units) -> String {
        match (label, self.unit(u)) {
            (l, "") => l.to_string(),
            ("", unit) => unit.to_string(),
            (l, unit) => format!("{l} {unit}"),
        }
    }
}

/// How a column appears in a pane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screen {
    /// Header label without the unit (`"Qi"`); the display unit is appended.
    pub label: &'static str,
    /// Display unit.
    pub display: Display,
    /// Decimals shown.
    pub precision: usize,
    /// Column width, cells.
    pub width: u16,
}

/// How a column's values are written to CSV (kept per column so the CSV of an existing
/// system never changes: counts and angles plain, physical values in `{:e}`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CsvStyle {
    /// A whole number.
    Integer,
    /// Shortest round-trip decimal (`{}`).
    Plain,
    /// Shortest round-trip scientific (`{:e}`).
    Scientific,
}

/// One column of a table: written to CSV, shown in a pane, or both.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Machine name with its SI unit, as in JSON and CSV (`inner_normal_load_n`).
    pub key: &'static str,
    /// What the values are (SI unit of the key).
    pub quantity: Quantity,
    /// CSV formatting; `None`: not a CSV column.
    pub csv: Option<CsvStyle>,
    /// Pane formatting; `None`: not shown in the pane.
    pub screen: Option<Screen>,
}

impl Column {
    /// A CSV-only column of `quantity` values.
    pub const fn new(key: &'static str, quantity: Quantity, csv: CsvStyle) -> Column {
        Column {
            key,
            quantity,
            csv: Some(csv),
            screen: None,
        }
    }

    /// This column shown in a pane too.
    pub const fn shown(
        mut self,
        label: &'static str,
        display: Display,
        precision: usize,
        width: u16,
    ) -> Column {
        self.screen = Some(Screen {
            label,
            display,
            precision,
            width,
        });
        self
    }

    /// The column's header in a file written in display units `u` (an export, a diff):
    /// a column the pane shows under its pane header (`Qi lbf`), a yes/no or state column
    /// with its codes' names (`skid (0 —; 1 yes)`); a CSV-only column under its machine
    /// key, whose last word names its SI unit (`inner_normal_load_n`).
    pub fn header_in(&self, u: Units) -> String {
        match self.screen {
            Some(Screen {
                label,
                display: Display::Choice(names),
                ..
            }) => {
                let legend: Vec<String> = names
                    .iter()
                    .enumerate()
                    .map(|(i, n)| format!("{i} {n}"))
                    .collect();
                format!("{label} ({})", legend.join("; "))
            }
            Some(s) => s.display.header(s.label, u),
            None => self.key.to_string(),
        }
    }

    /// A value of this column as written under [`Column::header_in`]: in the pane's
    /// display unit `u` when the pane shows it, else SI as its key says.
    pub fn value_in(&self, v: f64, u: Units) -> f64 {
        match self.screen {
            Some(s) => s.display.convert(v, u),
            None => v,
        }
    }

    /// A pane-only column.
    pub const fn screen_only(key: &'static str, quantity: Quantity, screen: Screen) -> Column {
        Column {
            key,
            quantity,
            csv: None,
            screen: Some(screen),
        }
    }
}

/// The words a yes/no flag is shown by on screen and in text (issue 30 item 11): `—` for
/// no, so the rows that hold the flag stand out; CSV keeps the code 0/1 (legend in
/// `docs/workbench.md`).
pub const FLAG_NAMES: [&str; 2] = ["—", "yes"];

/// A yes/no column (the ball's `skidding`, the tapered roller's edge flags): code 0 or 1,
/// shown as [`FLAG_NAMES`].
pub const FLAG: Display = Display::Choice(&FLAG_NAMES);

/// A flag as a word, for text reports (the same words as the panes').
pub const fn flag_word(set: bool) -> &'static str {
    FLAG_NAMES[set as usize]
}

/// An element's number on screen and in text from its position around the bearing
/// (0-based): every system counts its elements from 1 (issue 30 item 9; the seeds' and
/// the engineer's habit). JSON keeps each system's `index` (the ball's from 0) and gives
/// this as `number` beside it.
pub const fn element_number(position: usize) -> usize {
    position + 1
}

/// The element table's `#` column: [`element_number`] of each row, on screen only (a
/// system whose CSV `index` already counts from 1 shows that column as `#` instead).
pub const NUMBER_COLUMN: Column = Column::screen_only(
    "number",
    Quantity::Count,
    Screen {
        label: "#",
        display: Display::Plain,
        precision: 0,
        width: 3,
    },
);

/// A table: one row per rolling element (or per point of a sweep), SI values; `None`
/// where a stage was not run.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Machine name (`rollers`, `balls`).
    pub id: &'static str,
    /// Columns, in order.
    pub columns: Vec<Column>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<Option<f64>>>,
}

/// Issue 30 item 10: the names every system's per-element CSV (and JSON element) carries
/// for the same quantity, beside the system's own names (never renamed or dropped):
/// (common name, the system's names it stands for, CSV style). `docs/outputs.md` holds the
/// table across systems; `report::common_json_names` applies the JSON half.
pub const COMMON_COLUMNS: [(&str, &[&str], CsvStyle); 5] = [
    // The element's number from 1: the ball's `#` (its `index` counts from 0), the
    // rollers' `index` (from 1), as JSON's `number` (issue 30 item 9).
    ("number", &["number", "index"], CsvStyle::Integer),
    (
        "inner_load_n",
        &["inner_normal_load_n"],
        CsvStyle::Scientific,
    ),
    (
        "outer_load_n",
        &["outer_normal_load_n"],
        CsvStyle::Scientific,
    ),
    (
        "inner_contact_angle_deg",
        &["inner_angle_deg"],
        CsvStyle::Plain,
    ),
    (
        "outer_contact_angle_deg",
        &["outer_angle_deg"],
        CsvStyle::Plain,
    ),
];

impl Table {
    /// This table with a CSV column appended for each [`COMMON_COLUMNS`] name it lacks as
    /// a CSV column but holds under a system name (the ball's `inner_normal_load_n` gains
    /// `inner_load_n`; the screen-only `#` gains the CSV's `number`, from 1). Appended at
    /// the end: the existing columns keep their places.
    pub fn with_common_names(&self) -> Table {
        let mut t = self.clone();
        for (common, names, style) in COMMON_COLUMNS {
            if t.columns.iter().any(|c| c.key == common && c.csv.is_some()) {
                continue;
            }
            // The first of `names` (in their order of preference) the table holds.
            let Some(i) = names
                .iter()
                .find_map(|n| t.columns.iter().position(|c| c.key == *n))
            else {
                continue;
            };
            let quantity = t.columns[i].quantity;
            t.columns.push(Column::new(common, quantity, style));
            for row in &mut t.rows {
                let v = row.get(i).copied().flatten();
                row.push(v);
            }
        }
        t
    }
}

/// Whether a key output decides the recommended fidelity or only guards it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyRole {
    /// Must meet the accuracy target (e.g. max contact stress, life).
    Target,
    /// Must stay within the looser guard band (e.g. heat, cage speed).
    Guard,
    /// Reported (sweeps, the Sweep pane's marker), not judged by the fidelity bench
    /// (a count of rollers off the cone has no relative error).
    Info,
}

/// One scalar a user judges a design by. Its value is in the unit its name ends with
/// (SI, except temperatures in °C with [`Quantity::Temperature`]: their relative errors
/// are taken in kelvin).
#[derive(Debug, Clone, PartialEq)]
pub struct KeyOutput {
    /// Machine name with unit (`max_stress_pa`).
    pub name: &'static str,
    /// Short column label for text tables (`"σmax"`).
    pub label: &'static str,
    /// SI value; `None` when it does not exist (an unloaded bearing's life).
    pub value: Option<f64>,
    /// What it is (display unit).
    pub quantity: Quantity,
    /// Its role in the fidelity bench.
    pub role: KeyRole,
}

/// One axis of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartAxis {
    /// Label without the unit (`"ψ deg"`, `"x"`); the display unit is appended.
    pub label: &'static str,
    /// Display unit of the values.
    pub display: Display,
    /// Fixed bounds in display units (e.g. 0–360°); `None`: from the data (0 to a round
    /// ceiling for y, symmetric about 0 for x).
    pub bounds: Option<[f64; 2]>,
}

/// A named series of SI (x, y) points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend name.
    pub name: &'static str,
    /// Points, SI.
    pub points: Vec<(f64, f64)>,
    /// The series' own display kind when its y differs from the chart's y axis (a heat
    /// curve on an angular-speed axis): its values are converted by it and its legend
    /// names the unit. `None`: the axis's.
    pub display: Option<Display>,
}

/// A chart: series against a common x axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// Title (with any number it holds in SI).
    pub title: String,
    /// The title in US customary units, when it holds a number whose unit differs (a
    /// heat in W is in Btu/hr there); `None` when [`Chart::title`] serves both.
    pub title_us: Option<String>,
    /// X axis.
    pub x: ChartAxis,
    /// Y axis.
    pub y: ChartAxis,
    /// Series.
    pub series: Vec<Series>,
    /// True when point `i` of every series belongs to element `i` (the pane marks the
    /// selected element).
    pub per_element: bool,
    /// The deck's operating value on the x axis (issue 30 item 19: the ball's speed on
    /// its Skid chart), drawn as a vertical marker; `None`: the chart has none.
    pub operating: Option<OperatingPoint>,
}

/// The deck's own value of a chart's x quantity, marked on the chart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// The value, SI in the chart's x quantity (converted by the x axis's display).
    pub x: f64,
    /// What it is, for the legend (`"deck"`): the value and unit are appended.
    pub label: &'static str,
}

impl Chart {
    /// The title in display units `u`.
    pub fn title_in(&self, u: Units) -> &str {
        match (u, &self.title_us) {
            (Units::Us, Some(t)) => t,
            _ => &self.title,
        }
    }
}

/// A labelled scalar for a pane's summary line.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// Label without the unit.
    pub label: &'static str,
    /// SI value.
    pub value: f64,
    /// Display unit.
    pub display: Display,
    /// Decimals shown.
    pub precision: usize,
}

/// What a workbench pane shows (the front end has one renderer per kind).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PaneKind {
    /// The deck's inputs, editable.
    Inputs,
    /// The bearing-level answer at a glance ([`View::answer`]).
    Summary,
    /// The element table ([`View::screen_table`]).
    Elements,
    /// Bearing chart `n` of [`View::charts`]; chart 0 also has, per element, its detail
    /// chart ([`View::element_charts`], `c` toggles).
    Chart(usize),
    /// Text block `n` of [`View::texts`] (a matrix, a short account), in display units.
    Text(usize),
    /// Sweep `n` of the system ([`crate::bearings::BearingSystem::sweep_plan`]): key
    /// outputs against one deck key, solved point by point by the worker while the pane
    /// is on screen.
    Sweep(usize),
    /// The thermal network.
    Thermal,
    /// The equilibrium stepper.
    Stepper,
    /// Job `n` of the system ([`crate::bearings::BearingSystem::run_job`]): a long study
    /// (a load sweep, an optimisation) run by the worker while the pane is on screen,
    /// drawn from the [`JobView`]s it reports as it goes; the next edit cancels it.
    Job(usize),
    /// A small design study of the open deck (a study file beside the decks that names
    /// it, else a ±1 % tolerance Monte Carlo of the system's
    /// [`crate::bearings::BearingSystem::study_keys`]), run by the worker while the pane
    /// is on screen: the histogram of one output and the sensitivities; the next edit
    /// cancels it. Every system offers it.
    Study,
}

/// A pane a bearing system offers: its kind and the title it goes by ("Rollers", "Balls").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PaneSpec {
    /// What it shows.
    pub kind: PaneKind,
    /// Its title in the pane switcher and on its border.
    pub title: &'static str,
}

/// How a stepper line's values are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceFormat {
    /// Whole numbers joined by ` / ` (outer / inner iteration).
    Counts,
    /// Signed decimals (`+0.01234`), this many decimals, in the line's display unit.
    Signed(usize),
    /// Residuals: engineering form with sign, `≈0` below solver noise (1e-6).
    Residual,
}

/// One label/value line of a stepper step (values SI, comma-joined on screen).
#[derive(Debug, Clone, PartialEq)]
pub struct TraceLine {
    /// Label without the unit; the display unit is appended.
    pub label: &'static str,
    /// Display unit of the values.
    pub display: Display,
    /// How the values are written.
    pub format: TraceFormat,
    /// The values, SI.
    pub values: Vec<f64>,
}

impl TraceLine {
    /// A line of `values` (SI) shown in `display` units as `format` says.
    pub fn new(
        label: &'static str,
        display: Display,
        format: TraceFormat,
        values: Vec<f64>,
    ) -> TraceLine {
        TraceLine {
            label,
            display,
            format,
            values,
        }
    }
}

/// A row of bars across an element (one per lamina or slice), scaled with the other rows
/// of its group.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceBars {
    /// Row label (`"inner load"`).
    pub label: &'static str,
    /// Display unit of the values.
    pub display: Display,
    /// Rows of one group share a full scale.
    pub group: usize,
    /// Colour slot: 0 the inner race's colour, 1 the outer's.
    pub side: usize,
    /// Decimals of the group's full-scale value.
    pub precision: usize,
    /// The values, SI.
    pub values: Vec<f64>,
}

/// One recorded iteration of an element's equilibrium solve.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceStep {
    /// Iteration numbers, outermost first (spherical roller: dynamic-load, ring,
    /// roller), as named by [`Trace::iterations`].
    pub iteration: Vec<usize>,
    /// Residuals, SI, one per [`Trace::residuals`] column.
    pub residuals: Vec<f64>,
    /// Label/value lines.
    pub lines: Vec<TraceLine>,
    /// Bar rows.
    pub bars: Vec<TraceBars>,
}

/// A residual column of the stepper's history list.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceColumn {
    /// Label without the unit (`"ax"`); the display unit is appended.
    pub label: &'static str,
    /// Display unit.
    pub display: Display,
}

/// The equilibrium iterations of one element, as the stepper steps through them.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    /// The traced element (0-based).
    pub element: usize,
    /// Which solves the steps are from (`"5 dynamic-load iterations"`).
    pub label: String,
    /// The names of the iteration levels (`["dyn", "ring", "roller"]`).
    pub iterations: Vec<&'static str>,
    /// Residual columns of the history list.
    pub residuals: Vec<TraceColumn>,
    /// The steps, in order.
    pub steps: Vec<TraceStep>,
}

/// One node's transient temperatures.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeSeries {
    /// Node name.
    pub name: String,
    /// Temperatures, °C, at [`Transient::time_s`].
    pub temperature_c: Vec<f64>,
    /// The node's temperature limit, °C, if it has one.
    pub limit_c: Option<f64>,
    /// Time to reach the node's limit, s (`None`: not reached or no limit).
    pub time_to_limit_s: Option<f64>,
}

/// One node's steady temperature.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyNode {
    /// Node name.
    pub name: String,
    /// Temperature, °C.
    pub temperature_c: f64,
    /// True when the temperature is given (a boundary), not solved.
    pub fixed: bool,
}

/// A thermal transient.
#[derive(Debug, Clone, PartialEq)]
pub struct Transient {
    /// Sample times, s.
    pub time_s: Vec<f64>,
    /// One series per node.
    pub nodes: Vec<NodeSeries>,
}

/// A thermal network's results.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalResults {
    /// Steady-state temperature of each node, in network order.
    pub steady: Vec<SteadyNode>,
    /// The transient, when it was run.
    pub transient: Option<Transient>,
}

/// Solver work counters of a solve (the status bar).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveStats {
    /// Outer iterations (spherical roller: ring).
    pub iterations: usize,
    /// Inner iterations, all elements (spherical roller: roller).
    pub inner_iterations: usize,
    /// What the outer and inner iterations are (`["ring", "roller"]`), for the status line.
    pub names: [&'static str; 2],
    /// Wall time of the solve, s.
    pub wall_time_s: f64,
    /// True when the solve started from the session's last answer (a warm start): its
    /// counts are from there, 0 when nothing changed (the tapered roller re-solved for
    /// its Sweep pane), and the status line says so.
    pub warm_start: bool,
}

/// Everything a solved bearing shows.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The system's deck `type`.
    pub system: &'static str,
    /// Per-element tables; the first with CSV columns is the CSV report, the first with
    /// screen columns the element pane.
    pub tables: Vec<Table>,
    /// Bearing-level charts (the first is the load pane's).
    pub charts: Vec<Chart>,
    /// One chart per element (the load pane's detail view of the selected element).
    pub element_charts: Vec<Chart>,
    /// The chart pane (`PaneKind::Chart(n)`) whose `c` key swaps in the selected
    /// element's chart (the rollers' Load pane: 0; the balls' Dynamics pane: 1).
    pub element_chart_pane: usize,
    /// Bearing-level scalars shown under the element table.
    pub summary: Vec<Summary>,
    /// Key outputs.
    pub key_outputs: Vec<KeyOutput>,
    /// The stepper's trace of the requested element, when one was requested.
    pub trace: Option<Trace>,
    /// The thermal network's results, when the deck has one.
    pub thermal: Option<ThermalResults>,
    /// Solver work counters.
    pub stats: SolveStats,
    /// Results beyond the validity of the model, each a sentence with its numbers and
    /// bound (empty: none); the reports carry them too.
    pub warnings: Vec<Warning>,
    /// Preformatted blocks (e.g. a stiffness matrix with its units), in each unit system.
    pub texts: Vec<TextBlock>,
    /// The bearing-level answer the Summary pane shows, in order.
    pub answer: Vec<AnswerLine>,
}

/// What an [`AnswerLine`] holds.
#[derive(Debug, Clone, PartialEq)]
pub enum AnswerValue {
    /// A number, SI (temperatures in °C), in the line's display unit on screen.
    Number(f64),
    /// A name (the largest friction mechanism).
    Name(String),
    /// Not computed or not defined here, and why (shown in place of the number).
    Absent(String),
}

/// One line of the Summary pane: a bearing-level result, where it occurs, and where the
/// JSON report holds it, so a test reads every line on screen back against the report.
#[derive(Debug, Clone, PartialEq)]
pub struct AnswerLine {
    /// The group it is shown under (`"Life"`, `"Contact"`).
    pub section: &'static str,
    /// Label without the unit (`"L10 reference"`).
    pub label: &'static str,
    /// The value.
    pub value: AnswerValue,
    /// Display unit of a number.
    pub display: Display,
    /// Decimals shown (significant figures for [`Display::Mrev`] and [`Display::Hours`],
    /// whose values span decades).
    pub precision: usize,
    /// Where it occurs (`"roller 3, inner"`), if it is one element's.
    pub place: Option<String>,
    /// The JSON report's field it is read from: a pointer (`/life/l10_bearing_mrev`), or
    /// `max`/`min` of pointers with `*` over an array's entries
    /// (`max /rollers/*/inner/max_stress_pa /rollers/*/outer/max_stress_pa`); a scale
    /// factor after `×` when the report's unit differs (`/speeds/cage_rad_s ×9.549…`).
    /// Empty: shown only (a name).
    pub json: &'static str,
}

impl AnswerLine {
    /// A number (or, when `value` is `None`, absent for `why`).
    pub fn number(
        section: &'static str,
        label: &'static str,
        value: Option<f64>,
        display: Display,
        precision: usize,
        json: &'static str,
        why: &str,
    ) -> AnswerLine {
        AnswerLine {
            section,
            label,
            value: match value {
                Some(v) if v.is_finite() => AnswerValue::Number(v),
                Some(_) => AnswerValue::Absent("not finite".into()),
                None => AnswerValue::Absent(why.to_string()),
            },
            display,
            precision,
            place: None,
            json,
        }
    }

    /// A name.
    pub fn name(section: &'static str, label: &'static str, name: String) -> AnswerLine {
        AnswerLine {
            section,
            label,
            value: AnswerValue::Name(name),
            display: Display::Plain,
            precision: 0,
            place: None,
            json: "",
        }
    }

    /// This line, said to occur at `place`.
    pub fn at(mut self, place: Option<String>) -> AnswerLine {
        self.place = place;
        self
    }

    /// The value as shown in `units`: the number with its unit, the name, or
    /// `— (why)`.
    pub fn shown(&self, units: Units) -> String {
        match &self.value {
            AnswerValue::Number(v) => {
                let x = self.display.convert(*v, units);
                let text = match self.display {
                    Display::Mrev | Display::Hours => significant(x, self.precision),
                    _ => format!("{x:.*}", self.precision),
                };
                match self.display.unit(units) {
                    "" => text,
                    u => format!("{text} {u}"),
                }
            }
            AnswerValue::Name(n) => n.clone(),
            AnswerValue::Absent(why) => format!("— ({why})"),
        }
    }
}

/// `v` with `prec` decimals; a result that rounds to zero prints without a sign, so
/// last-bit noise (−0.00 vs 0.00) never reaches a pane or a snapshot.
pub fn fixed(v: f64, prec: usize) -> String {
    let s = format!("{v:.prec$}");
    if s.chars().all(|c| matches!(c, '-' | '0' | '.')) {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// `x` to `digits` significant figures, without an exponent (lives of 0.02 to 10⁷ Mrev).
pub fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor() as i64;
    let decimals = (digits as i64 - 1 - magnitude).max(0) as usize;
    format!("{x:.decimals$}")
}

/// Lines a system formats itself, once per unit system (a matrix whose cells have
/// different units does not fit the table's one-unit-per-column).
#[derive(Debug, Clone, PartialEq)]
pub struct TextBlock {
    /// What it is.
    pub title: &'static str,
    /// The lines in SI units.
    pub si: Vec<String>,
    /// The lines in US customary units.
    pub us: Vec<String>,
}

impl TextBlock {
    /// The lines in `units`.
    pub fn lines(&self, units: Units) -> &[String] {
        match units {
            Units::Si => &self.si,
            Units::Us => &self.us,
        }
    }
}

/// A result beyond the validity of the model, said in each unit system.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// In SI units.
    pub si: String,
    /// In US customary units.
    pub us: String,
}

impl Warning {
    /// The sentence in `units`.
    pub fn text(&self, units: Units) -> &str {
        match units {
            Units::Si => &self.si,
            Units::Us => &self.us,
        }
    }
}

/// What a cell of a [`HeatMap`] holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HeatCell {
    /// Not computed yet.
    Pending,
    /// A value, SI (the map's [`HeatMap::value`] unit).
    Value(f64),
    /// Excluded (an infeasible design point): index into [`HeatMap::excluded`], which
    /// gives its glyph and why, and its value if it has one (drawn behind the glyph).
    Excluded(usize, Option<f64>),
}

/// A marked cell of a [`HeatMap`] (the nominal point, the optimum).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMark {
    /// Column (index into [`HeatMap::xs`]).
    pub i: usize,
    /// Row (index into [`HeatMap::ys`]).
    pub j: usize,
    /// Its glyph.
    pub glyph: char,
    /// What it is (`"nominal"`).
    pub label: &'static str,
}

/// A map of a value over a grid of two variables, with excluded cells and marked points
/// (the optimiser's objective over (k_Ci, k_W)).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMap {
    /// Title.
    pub title: String,
    /// The first variable (columns), its values in [`HeatMap::xs`], SI.
    pub x: ChartAxis,
    /// The second variable (rows, the first row at `ys[0]`, drawn at the bottom).
    pub y: ChartAxis,
    /// Column values, ascending.
    pub xs: Vec<f64>,
    /// Row values, ascending.
    pub ys: Vec<f64>,
    /// The value's label and display unit (`("loss", Display::Power)`), and its decimals.
    pub value: (&'static str, Display, usize),
    /// Cells, row by row: `cells[j * xs.len() + i]`.
    pub cells: Vec<HeatCell>,
    /// Why cells are excluded: (glyph, reason), indexed by [`HeatCell::Excluded`].
    pub excluded: Vec<(char, String)>,
    /// Marked cells, drawn over their cell.
    pub marks: Vec<HeatMark>,
}

impl HeatMap {
    /// The cell at column `i`, row `j`.
    pub fn cell(&self, i: usize, j: usize) -> HeatCell {
        self.cells
            .get(j * self.xs.len() + i)
            .copied()
            .unwrap_or(HeatCell::Pending)
    }
}

/// What a running or finished job ([`PaneKind::Job`]) shows: its progress, maps, charts
/// and lines of text, in SI like the rest of the view.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct JobView {
    /// Work done and planned (solves), for the progress note.
    pub done: usize,
    /// Planned.
    pub total: usize,
    /// True once the job has finished (all its results in).
    pub finished: bool,
    /// What it is doing now (`"grid"`, `"polish"`), or how it ended.
    pub stage: String,
    /// Heat maps.
    pub heat_maps: Vec<HeatMap>,
    /// Charts.
    pub charts: Vec<Chart>,
    /// Result lines (the improvement, what binds), in each unit system.
    pub notes: Vec<Warning>,
    /// Points that failed, each a sentence naming the point (never silently skipped), or
    /// why the job as a whole failed.
    pub errors: Vec<String>,
}

impl JobView {
    /// A job that failed as a whole, with why.
    pub fn failed(message: String) -> JobView {
        JobView {
            finished: true,
            stage: "failed".into(),
            errors: vec![message],
            ..JobView::default()
        }
    }
}

impl View {
    /// The key output called `name`.
    pub fn key(&self, name: &str) -> Option<&KeyOutput> {
        self.key_outputs.iter().find(|k| k.name == name)
    }

    /// The table called `id`.
    pub fn table(&self, id: &str) -> Option<&Table> {
        self.tables.iter().find(|t| t.id == id)
    }

    /// The element pane's table with every column the view has for its elements: the
    /// screen table's, then those of another table of the same rows (a system that keeps
    /// its CSV report's columns apart, as the spherical roller does) whose keys it lacks.
    /// What an export or a diff of the elements holds.
    pub fn element_table(&self) -> Option<Table> {
        let screen = self.screen_table()?;
        let mut t = screen.clone();
        for other in &self.tables {
            if other.id == screen.id || other.rows.len() != screen.rows.len() {
                continue;
            }
            for (c, col) in other.columns.iter().enumerate() {
                if col.csv.is_none() || t.columns.iter().any(|k| k.key == col.key) {
                    continue;
                }
                t.columns.push(col.clone());
                for (row, from) in t.rows.iter_mut().zip(&other.rows) {
                    row.push(from.get(c).copied().flatten());
                }
            }
        }
        Some(t)
    }

    /// The table a pane shows: the first with columns meant for the screen.
    pub fn screen_table(&self) -> Option<&Table> {
        self.tables
            .iter()
            .find(|t| t.columns.iter().any(|c| c.screen.is_some()))
    }
}

/// What a column holds, for the workbench's help (issue 30 item 16): looked up by the
/// column's own machine key, so the help follows the table. The common quantities are
/// said in words (what Λ, s/r, h_c, M_r, an edge flag mean); any other key is read out
/// from its name (`inner_load_n`: "inner load, N"), so no column is left unexplained.
pub fn column_help(key: &str) -> String {
    let known = match key {
        // Every system counts its elements from 1 on screen (issue 30 item 9).
        "index" | "number" => {
            "the element's number around the bearing, counting from 1 (the JSON's number)"
        }
        "azimuth_deg" => "angular position ψ of the element around the bearing",
        "inner_normal_load_n" | "inner_load_n" => "normal load on the inner raceway contact",
        "outer_normal_load_n" | "outer_load_n" => "normal load on the outer raceway contact",
        "inner_contact_angle_deg" | "inner_angle_deg" => "contact angle α at the inner race",
        "outer_contact_angle_deg" | "outer_angle_deg" => "contact angle α at the outer race",
        "max_stress_pa" => "largest Hertz contact stress of the element, both races, edge laminae included",
        "inner_max_pressure_pa" => "largest Hertz pressure p at the inner contact",
        "outer_max_pressure_pa" => "largest Hertz pressure p at the outer contact",
        "min_film_m" => "thinnest lubricant film h of the element's contacts",
        "inner_central_film_m" => "central film thickness h_c at the inner contact (EHL)",
        "outer_central_film_m" => "central film thickness h_c at the outer contact (EHL)",
        "lambda" => "film parameter Λ = h / composite roughness: below 1 boundary, 1–3 mixed, above 3 full film",
        "spin_rpm" => "the element's spin about its own axis relative to the cage",
        "inner_spin_rad_s" => "spin ω_s of the ball relative to the inner race, about the contact normal",
        "outer_spin_rad_s" => "spin ω_s of the ball relative to the outer race, about the contact normal",
        "inner_spin_to_roll" => "s/r: spin-to-roll ratio at the inner contact (large: spin heats the contact)",
        "outer_spin_to_roll" => "s/r: spin-to-roll ratio at the outer contact",
        "inner_semi_major_m" => "semi-major axis a of the inner contact ellipse",
        "outer_semi_major_m" => "semi-major axis a of the outer contact ellipse",
        "centrifugal_force_n" => "centrifugal force F_c of the element at its orbit speed",
        "gyroscopic_moment_nm" => "gyroscopic moment M_g the contacts must resist",
        "resisting_moment_nm" => "M_r: the friction moment the contacts can resist; below M_g the ball skids",
        "skidding" | "skid" => "yes when the element skids (gyroscopic moment above what friction resists), — when not",
        "heat_w" => "heat generated at the element's contacts",
        "flange_load_n" => "load on the flange (rib) contact",
        "edge" | "inner_edge" | "outer_edge" | "outer_edge_loaded" | "inner_edge_loaded" => {
            "edge loading: yes when the contact reaches the end of the roller, — when not"
        }
        "state" => "how the roller is held: both-races, cup-and-flange (off the cone) or free",
        _ => "",
    };
    if !known.is_empty() {
        return known.to_string();
    }
    // The SI unit is the key's last word (`_n`, `_pa`, `_m`, `_deg`, …).
    let (words, unit) = match key.rsplit_once('_') {
        Some((w, u)) => match u {
            "n" => (w, "N"),
            "m" => (w, "m"),
            "pa" => (w, "Pa"),
            "w" => (w, "W"),
            "nm" => (w, "N·m"),
            "deg" => (w, "°"),
            "rpm" => (w, "rpm"),
            "s" if w.ends_with("_rad") => (w.trim_end_matches("_rad"), "rad/s"),
            _ => (key, ""),
        },
        None => (key, ""),
    };
    let words = words.replace('_', " ");
    if unit.is_empty() {
        words
    } else {
        format!("{words}, {unit} in SI")
    }
}

#[cfg(test)]
mod choice_tests {
    use super::*;

    /// A `Choice` column shows its code's name and nothing for codes it has no name for
    /// (a fraction, a negative or an out-of-range code are not states), has no unit and
    /// passes the code through unconverted; other kinds have no names.
    #[test]
    fn choice_names_its_codes() {
        const NAMES: [&str; 3] = ["both-races", "cup-and-flange", "free"];
        let d = Display::Choice(&NAMES);
        assert_eq!(d.choice(0.0), Some("both-races"));
        assert_eq!(d.choice(2.0), Some("free"));
        for bad in [3.0, 0.5, -1.0, f64::NAN] {
            assert_eq!(d.choice(bad), None, "{bad}");
        }
        assert_eq!(d.unit(Units::Us), "");
        assert_eq!(d.convert(1.0, Units::Us), 1.0);
        assert_eq!(Display::Force.choice(0.0), None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::{INCH_M, LBF_N, PSI_PA};

    /// Every column is explained: the common ones in words, the others read from their
    /// key with its SI unit.
    #[test]
    fn every_column_has_help() {
        assert!(column_help("lambda").contains("Λ"));
        assert!(column_help("outer_spin_to_roll").starts_with("s/r"));
        assert_eq!(column_help("cage_slip_n"), "cage slip, N in SI");
        assert_eq!(column_help("cage_rad_s"), "cage, rad/s in SI");
        assert_eq!(column_help("heat_state"), "heat state");
    }

    /// Display units against their definitions (exact factors of units.rs): 1 lbf, 1 ksi,
    /// 1 mil, 1 µin, 1 lbf/in shown as 1 in US units; SI shows N, MPa, mm, µm, N/mm.
    #[test]
    fn display_units_are_their_definitions() {
        let us = |d: Display, si: f64| d.convert(si, Units::Us);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
        assert!(close(us(Display::Force, LBF_N), 1.0));
        assert!(close(us(Display::Stress, 1e3 * PSI_PA), 1.0));
        assert!(close(us(Display::SmallLength, 1e-3 * INCH_M), 1.0));
        assert!(close(us(Display::Film, 1e-6 * INCH_M), 1.0));
        assert!(close(us(Display::LineLoad, LBF_N / INCH_M), 1.0));
        assert!(close(Display::Stress.convert(2.5e6, Units::Si), 2.5));
        assert!(close(Display::SmallLength.convert(2.5e-3, Units::Si), 2.5));
        assert!(close(Display::LineLoad.convert(2.5e3, Units::Si), 2.5));
        assert_eq!(Display::Plain.convert(7.0, Units::Us), 7.0);
        assert!(close(us(Display::Moment, INCH_LBF_N_M), 1.0));
        assert!(close(us(Display::Speed, FOOT_M), 1.0));
        assert!(close(us(Display::SmallSpeed, INCH_M), 1.0));
        // BTU_PER_HOUR_PER_WATT is given to 10 digits (units.rs checks it to 1e-10).
        let btu_per_hour = us(Display::Power, crate::units::BTU_J / crate::units::HOUR_S);
        assert!((btu_per_hour - 1.0).abs() < 1e-9);
        assert_eq!(Display::Force.header("Qi", Units::Us), "Qi lbf");
        assert_eq!(Display::Force.header("", Units::Si), "N");
        assert_eq!(Display::Plain.header("ψ deg", Units::Us), "ψ deg");
    }
}
