//! Command line (clap): a thin layer over the library.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};

/// rollbench: high-speed rolling-bearing analysis (SASHBEAN lamina method).
#[derive(Debug, Parser)]
#[command(name = "rollbench", version, about, long_about = None)]
pub struct Cli {
    /// Deck to open in the workbench (default: the embedded aerospace deck).
    pub deck: Option<PathBuf>,
    /// Override a deck value, in the deck's units: --set geometry.pitch_diameter=3.4 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE", global = true)]
    pub set: Vec<String>,
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve a deck and print the report.
    Run {
        /// Deck file (TOML).
        deck: PathBuf,
        /// Report format.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the report to FILE instead of standard output (`-`: standard output).
        /// A regular file is replaced atomically (through a symbolic link); a read-only
        /// file and the deck itself are refused; standard streams (`/dev/stdout`), devices
        /// and FIFOs are written in place (a FIFO's reader is waited for at most 10 s).
        /// Every output is checked before solving, and none is written unless all can be.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Skip the loss-of-oil thermal transient (the steady state is still solved).
        #[arg(long)]
        no_transient: bool,
        /// Also write the time history of a time-domain solution (the ball system's
        /// `dynamics.method = "time-simulation"`) to FILE as CSV, SI, units in the header;
        /// written as `--output` is (atomically, together with it; the deck and a file that
        /// is the `--output` file are refused).
        #[arg(long, value_name = "FILE")]
        series: Option<PathBuf>,
    },
    /// Two designs side by side: the bearing-level answers of decks A and B (and their
    /// per-element tables when both are one system with as many elements), with the
    /// differences B − A, absolute and in %, in A's deck units. Decks of two systems are
    /// compared on the Summary lines both report; the rest is listed as not compared.
    /// `--set` applies to both decks, `--set-b` to B only.
    Diff {
        /// Deck A (TOML): the baseline.
        a: PathBuf,
        /// Deck B (TOML): the design compared with it.
        b: PathBuf,
        /// Report format.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the comparison to FILE instead of standard output (as `run --output`).
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Override a value of deck B only (KEY=VALUE in B's units; repeatable): B is A
        /// edited when both name the same file.
        #[arg(long = "set-b", value_name = "KEY=VALUE")]
        set_b: Vec<String>,
        /// Skip the loss-of-oil thermal transients.
        #[arg(long)]
        no_transient: bool,
    },
    /// Validate a deck; exit 1 with messages if it is invalid.
    Check {
        /// Deck file (TOML).
        deck: PathBuf,
    },
    /// Print a fully commented deck template.
    Template {
        /// Unit system of the template.
        #[arg(long, value_enum, default_value_t = UnitsArg::Us)]
        units: UnitsArg,
        /// Bearing system (the deck's `type`).
        #[arg(long = "type", value_name = "TYPE", default_value = crate::bearings::DEFAULT_SYSTEM)]
        r#type: String,
    },
    /// Run every reference case through the library and print the validation table; exit 3 if any fails.
    Validate {
        /// Table format.
        #[arg(long, value_enum, default_value_t = TableFormat::Text)]
        format: TableFormat,
    },
    /// List every key `--set` accepts, with its units and allowed range.
    Keys {
        /// Bearing system (the deck's `type`); without it, the default system's keys
        /// (spherical-roller), said on standard error.
        #[arg(long = "type", value_name = "TYPE")]
        r#type: Option<String>,
    },
    /// Run time against error over laminae × force tolerance (default: every deck in decks/).
    Bench {
        /// Deck file (TOML); default: every deck in ./decks, or the embedded aerospace deck.
        deck: Option<PathBuf>,
        /// Table format.
        #[arg(long, value_enum, default_value_t = TableFormat::Text)]
        format: TableFormat,
    },
    /// The bearing's stiffness matrix at the operating point, every system (the 5×5 for a rotor model; docs/stiffness.md).
    Stiffness {
        /// Deck file (TOML).
        deck: PathBuf,
        /// Also compute it by finite differences of re-solved equilibria and report the
        /// largest gap (solver.stiffness = "both").
        #[arg(long)]
        check_fd: bool,
        /// Format: text or csv in the deck's units (csv names them in its unit columns),
        /// json in SI.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write to FILE instead of standard output, as `run --output` does.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Export for a rotordynamics model instead of the report: ross (a ROSS
        /// BearingElement TOML, SI, read back by `ross.BearingElement.load`), csv (one
        /// entry a line) or json, both in the deck's units. No system computes damping:
        /// the exports say so (ROSS's c terms are 0).
        #[arg(long, value_enum, value_name = "FORMAT", conflicts_with = "format")]
        export: Option<StiffnessExport>,
    },
    /// Friction torques M_fi, M_fo, M against F/C (C: ISO 281's C_r) of a double-row
    /// spherical roller deck, each point a full solve (seed 002 Fig. 2). Combined load keeps
    /// the deck's F_a/F_r (F_a = 0.25·F_r if the deck lacks either) at F = √(F_r² + F_a²).
    Losses {
        /// Deck file (TOML), `type = "double-row-spherical-roller"`.
        deck: PathBuf,
        /// Load direction.
        #[arg(long, value_enum, default_value_t = LossDirection::Radial)]
        direction: LossDirection,
        /// F/C values A:B:STEP (at most 200 points).
        #[arg(
            long = "f-over-c",
            value_name = "A:B:STEP",
            default_value = "0.02:0.2:0.02"
        )]
        f_over_c: String,
        /// Table format (json: SI).
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
    },
    /// Cylindrical roller decks: the roller–inner race contact solved as line-contact EHL
    /// at cage positions (issue 26, seed 003 Table 3): pressure, film, friction per position.
    Contact {
        /// Deck file (TOML), `type = "cylindrical-roller"`.
        deck: PathBuf,
        /// Cage position, deg (repeatable; default: the deck's contact.positions).
        #[arg(long = "position", value_name = "DEG", allow_negative_numbers = true)]
        position: Vec<f64>,
        /// Inlet: flooded (4.5 Hertz half-widths), tipei (starved meniscus) or both.
        #[arg(long, value_enum, default_value_t = ContactInletArg::Flooded)]
        inlet: ContactInletArg,
        /// Contact model.
        #[arg(long, value_enum, default_value_t = ContactModelArg::LineEhl)]
        model: ContactModelArg,
        /// Solve the film energy equation (seed eqs. 23–34): viscosity at the film's own
        /// temperature, max_temperature_c and the temperature profile; without it the
        /// film is isothermal at the inlet temperature (faster).
        #[arg(long)]
        thermal: bool,
        /// Format: text (Table 3 layout), json (SI, with profiles) or csv (SI).
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
    },
    /// Solve a deck at every value of one key (no transient): one row of key outputs per point.
    Sweep {
        /// Deck file (TOML).
        deck: PathBuf,
        /// The key and its range, in the deck's units: KEY=A:B:STEP (step, A > B sweeps
        /// down) or KEY=A:B:xN (N points, ends included), e.g.
        /// operating.inner_speed=6000:15000:500. At most 10000 points.
        #[arg(long = "set-range", value_name = "KEY=A:B:STEP")]
        set_range: String,
        /// Solve every point from the system's own initial guess, as `run --set` would,
        /// instead of continuing each core's run of points from its previous point.
        #[arg(long)]
        cold: bool,
        /// Table format.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the table to FILE instead of standard output (`-`: standard output), as
        /// `run --output` does; not written when no point solved.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// A design study over one deck (docs/studies.md): a grid of several keys, a Monte
    /// Carlo or Latin-hypercube tolerance sample, or a duty cycle, from a study file
    /// (TOML: `deck`, `outputs`, and one of `[grid]`, `[sample]`, `[duty]`); every point
    /// solved in parallel without the transient; `--shard I/N` for a cluster, then
    /// `rollbench study merge`.
    #[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
    Study {
        /// The study file (TOML), e.g. decks/chen_b.study.toml.
        #[arg(required = true)]
        file: Option<PathBuf>,
        /// Output format: text (the summary), csv, json (rows and summary) or jsonl
        /// (a header line, then one row a line). With csv, json or jsonl the summary goes
        /// to standard error.
        #[arg(long, value_enum, default_value_t = StudyFormat::Text)]
        format: StudyFormat,
        /// Write to FILE instead of standard output, as `run --output` does; with
        /// --shard, the part (JSONL) to create or resume.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Compute only the points i ≡ I (mod N), written as a part (JSONL) to --output
        /// and resumed from it when re-run; `auto` reads SLURM_ARRAY_TASK_ID /
        /// SLURM_ARRAY_TASK_COUNT or JOB_COMPLETION_INDEX (with --shards or ROLLBENCH_SHARDS).
        #[arg(long, value_name = "I/N|auto")]
        shard: Option<String>,
        /// The number of shards for `--shard auto` under a Kubernetes Indexed Job (its
        /// completions), or to override SLURM_ARRAY_TASK_COUNT.
        #[arg(long, value_name = "N", requires = "shard")]
        shards: Option<usize>,
        #[command(subcommand)]
        action: Option<StudyAction>,
    },
    /// Double-row spherical roller decks: the osculation optimiser (issue 27): the relative
    /// radii of `[optimise]` (k_ci = R'_Ci/R_Ci, k_w = R'_W/R_W) that minimise the weighted
    /// total friction loss over its load cases, on a grid then a Nelder–Mead polish.
    Optimise {
        /// Deck file (TOML).
        deck: PathBuf,
        /// Points per variable (2–201; default the deck's optimise.grid).
        #[arg(long, value_name = "N")]
        grid: Option<usize>,
        /// Format: text, json (SI) or csv (the grid, SI).
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
    },
}

/// `rollbench study` subcommands.
#[derive(Debug, Subcommand)]
pub enum StudyAction {
    /// Merge the parts of a sharded study: checks that every index is present exactly
    /// once and that every part comes from the same study (file, deck and version), then
    /// writes the rows in index order and the summary.
    Merge {
        /// The parts (JSONL, from `rollbench study FILE --shard I/N --output PART`).
        #[arg(required = true, value_name = "PART")]
        parts: Vec<PathBuf>,
        /// Output format (as `rollbench study`).
        #[arg(long, value_enum, default_value_t = StudyFormat::Text)]
        format: StudyFormat,
        /// Write to FILE instead of standard output, as `run --output` does.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
}

/// Formats of `rollbench study`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StudyFormat {
    Text,
    Csv,
    Json,
    Jsonl,
}

/// A study's result in `format` (text: the summary).
pub fn study_text(r: &crate::studies::study::StudyResult, format: StudyFormat) -> String {
    use crate::studies::study::{output, summary};
    match format {
        StudyFormat::Text => summary::text(r),
        StudyFormat::Csv => output::csv(r),
        StudyFormat::Json => output::json(r),
        StudyFormat::Jsonl => output::jsonl(r),
    }
}

/// Load direction of `rollbench losses`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LossDirection {
    Radial,
    Axial,
    Combined,
}

/// `rollbench losses`: M_fi, M_fo and M against F/C of a double-row spherical roller deck
/// (seed 002 Fig. 2), each point a full solve with its loss breakdown; progress on
/// standard error. Returns the table, or (exit code, message).
pub fn losses_command(
    case: &dyn crate::bearings::Case,
    direction: LossDirection,
    f_over_c: &str,
    format: Format,
) -> Result<String, (u8, String)> {
    use crate::bearings::double_row_spherical::load_sweep::{
        dynamic_rating_n, parse_range, render, torque_point_from, Direction,
    };
    use crate::bearings::double_row_spherical::system::DoubleRowCase;
    let Some(dr) = case.as_any().downcast_ref::<DoubleRowCase>() else {
        return Err((
            exit::INVALID_INPUT,
            format!(
                "losses: the {} has no loss breakdown (only double-row-spherical-roller decks have one)",
                case.system().title()
            ),
        ));
    };
    let values = parse_range(f_over_c).map_err(|e| (exit::USAGE, e))?;
    let input = &dr.form.value;
    let Some(c) = dynamic_rating_n(input) else {
        return Err((
            exit::INVALID_INPUT,
            "losses: ISO 281's f_c table does not cover this geometry (γ = D_W·cos α/d_m outside 0.01–0.30), so C is not defined".to_string(),
        ));
    };
    let dir = match direction {
        LossDirection::Radial => Direction::Radial,
        LossDirection::Axial => Direction::Axial,
        LossDirection::Combined => Direction::Combined,
    };
    let mut points = Vec::with_capacity(values.len());
    // Each point's statics starts from the previous point's solution (same answers).
    let mut from = None;
    for (k, x) in values.iter().enumerate() {
        eprintln!("losses: point {}/{} F/C = {x:.4}", k + 1, values.len());
        let (p, next) = torque_point_from(input, &dr.form.name, dir, *x, c, from.as_ref(), None)
            .map_err(|e| (exit::SOLVE_FAILED, format!("solve failed: {e}")))?;
        points.push(p);
        from = Some(next);
    }
    Ok(render(
        &points,
        dir,
        c,
        matches!(format, Format::Json),
        matches!(format, Format::Csv),
    ))
}

/// `rollbench contact --inlet`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ContactInletArg {
    Flooded,
    Tipei,
    Both,
}

/// `rollbench contact --model`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ContactModelArg {
    LineEhl,
    FiniteLineEhl,
}

/// `rollbench contact`: the cylindrical case's contact study (library:
/// `bearings::cylindrical_roller::contact`), progress on standard error. Errors carry the
/// exit code: another system's deck is invalid input, a model or inlet not built yet is
/// [`exit::UNSUPPORTED`], a solve without an answer a failed solve.
pub fn contact_command(
    case: &dyn crate::bearings::Case,
    positions_deg: &[f64],
    inlet: ContactInletArg,
    model: ContactModelArg,
    thermal: bool,
    format: Format,
) -> Result<String, (u8, String)> {
    use crate::bearings::cylindrical_roller::contact::{
        contact_study, csv, json, text, ContactError, ContactModel, ContactOptions, InletChoice,
    };
    use crate::bearings::cylindrical_roller::{system::CylindricalCase, SYSTEM_ID};
    let Some(c) = case.as_any().downcast_ref::<CylindricalCase>() else {
        return Err((
            exit::INVALID_INPUT,
            format!(
                "contact: the contact study is for cylindrical roller decks (type = \"{SYSTEM_ID}\"); this deck is a {}",
                case.system().title()
            ),
        ));
    };
    let options = ContactOptions {
        positions_deg: positions_deg.to_vec(),
        inlet: match inlet {
            ContactInletArg::Flooded => InletChoice::Flooded,
            ContactInletArg::Tipei => InletChoice::Tipei,
            ContactInletArg::Both => InletChoice::Both,
        },
        model: match model {
            ContactModelArg::LineEhl => ContactModel::LineEhl,
            ContactModelArg::FiniteLineEhl => ContactModel::FiniteLineEhl,
        },
        thermal,
    };
    let study = contact_study(&c.form.value, &options, |done, total, pos| {
        if done < total && total > 1 {
            eprintln!("contact: position {}/{total} ({pos:.1}°)", done + 1);
        }
    })
    .map_err(|e| {
        let code = match e {
            ContactError::NotBuilt(_) => exit::UNSUPPORTED,
            ContactError::Input(_) => exit::INVALID_INPUT,
            ContactError::Cancelled
            | ContactError::Dynamics(_)
            | ContactError::Solve { .. }
            | ContactError::Thermal { .. }
            | ContactError::Tipei { .. }
            | ContactError::Friction { .. } => exit::SOLVE_FAILED,
        };
        (code, format!("contact: {e}"))
    })?;
    Ok(match format {
        Format::Text => text(&study),
        Format::Json => {
            let mut t = serde_json::to_string_pretty(&json(&study)).unwrap_or_default();
            t.push('\n');
            t
        }
        Format::Csv => csv(&study),
    })
}

/// Formats of the validate and bench tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableFormat {
    Text,
    Json,
}

/// `rollbench stiffness --export` formats (see [`crate::report::stiffness_export`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StiffnessExport {
    /// ROSS's BearingElement TOML (SI).
    Ross,
    /// One entry a line, deck units.
    Csv,
    /// The matrix with its units, deck units.
    Json,
}

impl From<StiffnessExport> for crate::report::stiffness_export::Export {
    fn from(e: StiffnessExport) -> Self {
        use crate::report::stiffness_export::Export;
        match e {
            StiffnessExport::Ross => Export::Ross,
            StiffnessExport::Csv => Export::Csv,
            StiffnessExport::Json => Export::Json,
        }
    }
}

/// Report formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
    Csv,
}

/// Exit codes of the binary, one meaning each (documented in README.md, "Command line").
pub mod exit {
    /// Success.
    pub const OK: u8 = 0;
    /// Invalid input: deck, `--set`, a file that cannot be read or written, or a refused
    /// output (`--output`, `--series`).
    pub const INVALID_INPUT: u8 = 1;
    /// The solver failed (run, bench, stiffness; a sweep where no point solved): the
    /// message names the stage and the numbers.
    pub const SOLVE_FAILED: u8 = 2;
    /// `validate`: a reference case is outside its tolerance.
    pub const VALIDATION_FAILED: u8 = 3;
    /// A model or option this build does not have yet (`contact --model finite-line-ehl`):
    /// the message says what exists.
    pub const UNSUPPORTED: u8 = 4;
    /// Command-line usage error (unknown option or value, `--set` where it means nothing).
    pub const USAGE: u8 = 64;
}

/// Unit systems on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum UnitsArg {
    Si,
    Us,
}

/// `rollbench optimise`: the double-row case's optimiser with `grid` points per variable
/// (`None`: the deck's), rendered in `format`. Errors carry the exit code: a deck of another
/// system or a refused setting is invalid input, an optimisation without a result a failed
/// solve.
pub fn optimise(
    case: &dyn crate::bearings::Case,
    deck: &std::path::Path,
    grid: Option<usize>,
    format: Format,
    cancel: crate::numerics::cancel::Cancel,
) -> Result<String, (u8, String)> {
    use crate::bearings::double_row_spherical::{
        optimise as opt, system::DoubleRowCase, SYSTEM_ID,
    };
    let Some(c) = case.as_any().downcast_ref::<DoubleRowCase>() else {
        return Err((
            exit::INVALID_INPUT,
            format!(
                "{}: `optimise` is for double-row spherical roller decks (type = \"{SYSTEM_ID}\"); this deck is a {}",
                deck.display(),
                case.system().title()
            ),
        ));
    };
    let mut input = c.form.value.clone();
    if let Some(n) = grid {
        if !(2..=201).contains(&n) {
            return Err((
                exit::USAGE,
                format!("--grid {n}: points per variable must be 2 to 201"),
            ));
        }
        input.optimise.grid = n;
    }
    let o = opt::optimise_losses(&input, &c.form.name, cancel).map_err(|e| {
        let code = match e {
            opt::OptimiseError::Refused { .. } => exit::INVALID_INPUT,
            _ => exit::SOLVE_FAILED,
        };
        (code, format!("optimise: {e}"))
    })?;
    Ok(match format {
        Format::Text => opt::report::text(&o, case.units()),
        Format::Json => {
            let mut t = serde_json::to_string_pretty(&opt::report::json(&o)).unwrap_or_default();
            t.push('\n');
            t
        }
        Format::Csv => opt::report::csv(&o),
    })
}
