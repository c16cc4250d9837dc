//! rollbench binary: the workbench by default, headless subcommands otherwise.
#![forbid(unsafe_code)]

use std::process::ExitCode;

use std::path::Path;

use clap::Parser;
use rollbench::bearings::{self, Case, RunOptions};
use rollbench::cli::{exit, Cli, Command, Format, StudyFormat, TableFormat, UnitsArg};
use rollbench::deck::Units;
use rollbench::files::{self, Plan};
use rollbench::numerics::cancel::Cancel;
use rollbench::report;

/// Reads the deck at `path`, finds its bearing system by `type`, and has that system
/// parse it with the `--set` overrides.
fn load_case(path: &Path, overrides: &[String]) -> Result<Box<dyn Case>, String> {
    bearings::load_file(path, overrides).map_err(|e| e.to_string())
}

/// Checks every output (`(flag, path)`, `None`: standard output) before anything is
/// solved, by the rules of [`rollbench::files`]: none is the deck, no two are the same
/// file, each can be written. The exit code to leave with on a refusal (invalid input).
fn plan_outputs(outputs: &[(&str, Option<&Path>)], deck: &Path) -> Result<Plan, ExitCode> {
    // A SIGINT or SIGTERM while the outputs are written leaves no temporary file.
    if let Err(e) = files::remove_temporaries_on_signals() {
        eprintln!("warning: a signal may leave a temporary file beside the outputs: {e}");
    }
    files::plan(outputs, &[("the deck being read", deck)]).map_err(|e| {
        eprintln!("{e}");
        ExitCode::from(exit::INVALID_INPUT)
    })
}

/// Writes the outputs of `plan`, all or nothing (see [`rollbench::files::Plan::commit`]).
fn commit(plan: &Plan, contents: &[&[u8]]) -> ExitCode {
    match plan.commit(contents) {
        Ok(_) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cannot write {e}");
            ExitCode::from(exit::INVALID_INPUT)
        }
    }
}

/// `rollbench stiffness DECK --export FORMAT`: the matrix of the solution's JSON
/// `stiffness` object written for a rotordynamics model, through `plan`.
fn stiffness_export(
    deck: &Path,
    case: &dyn Case,
    solution: &dyn bearings::Solution,
    export: rollbench::cli::StiffnessExport,
    plan: &Plan,
) -> ExitCode {
    use rollbench::report::stiffness_export as se;
    let json = solution.json();
    let Some(k) = json.get("stiffness").and_then(se::matrix_from_json) else {
        eprintln!(
            "{}: the {} has no stiffness matrix yet, nothing to export",
            deck.display(),
            case.system().title()
        );
        return ExitCode::from(exit::INVALID_INPUT);
    };
    let tag = deck
        .file_stem()
        .map_or_else(|| "bearing".into(), |s| s.to_string_lossy().into_owned());
    let src = se::Source {
        tag: &tag,
        system: case.system().title(),
        units: case.units(),
    };
    match se::export(&k, export.into(), src) {
        Ok(text) => commit(plan, &[text.as_bytes()]),
        Err(e) => {
            eprintln!("{}: {e}", deck.display());
            ExitCode::from(exit::INVALID_INPUT)
        }
    }
}

/// A deck's case and its solution.
type Solved = (Box<dyn Case>, Box<dyn bearings::Solution>);

/// Reads the deck with `overrides` and solves it; on failure the message is printed and
/// the exit code returned (invalid input 1, solve failed 2).
fn load_and_solve(
    deck: &Path,
    overrides: &[String],
    options: RunOptions,
) -> Result<Solved, ExitCode> {
    let case = load_case(deck, overrides).map_err(|e| {
        eprintln!("{e}");
        ExitCode::from(exit::INVALID_INPUT)
    })?;
    let bar = progress_bar();
    let progress = |f: f64| bar.report(f);
    let solved = case.solve(options, Cancel::NONE.with_progress(&progress));
    bar.finish();
    let solution = solved.map_err(|e| {
        eprintln!("solve failed: {e}");
        ExitCode::from(exit::SOLVE_FAILED)
    })?;
    Ok((case, solution))
}

/// The progress of a long solve (issue 24 item 7) on standard error when it is a
/// terminal: drawn once the solve has run a second (a quick one shows nothing), never
/// in a pipe or a file (tests, scripts).
struct Bar {
    bar: Option<indicatif::ProgressBar>,
    start: std::time::Instant,
}

impl Bar {
    /// Report `fraction` done (the library's progress callback).
    fn report(&self, fraction: f64) {
        let Some(bar) = &self.bar else { return };
        if bar.is_hidden() && self.start.elapsed() >= std::time::Duration::from_secs(1) {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
        bar.set_position((fraction * 1000.0) as u64);
    }

    /// Clear the bar (the report follows on standard output).
    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// A [`Bar`], drawing only when standard error is a terminal.
fn progress_bar() -> Bar {
    use std::io::IsTerminal;
    let bar = std::io::stderr().is_terminal().then(|| {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(1000),
            indicatif::ProgressDrawTarget::hidden(),
        );
        if let Ok(style) =
            indicatif::ProgressStyle::with_template("solving {bar:40} {percent:>3}% (eta {eta})")
        {
            bar.set_style(style);
        }
        bar
    });
    Bar {
        bar,
        start: std::time::Instant::now(),
    }
}

/// `rollbench diff A B`: both decks solved (`--set` on both, `--set-b` on B), compared
/// by [`report::diff`] in A's deck units, written through the plan (neither deck may be
/// the output).
fn diff(
    a: &Path,
    b: &Path,
    sets: &[String],
    set_b: &[String],
    format: Format,
    output: Option<&Path>,
    no_transient: bool,
) -> ExitCode {
    if let Err(e) = files::remove_temporaries_on_signals() {
        eprintln!("warning: a signal may leave a temporary file beside the output: {e}");
    }
    let plan = match files::plan(&[("--output", output)], &[("deck A", a), ("deck B", b)]) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let options = RunOptions {
        skip_transient: no_transient,
    };
    let (case_a, sol_a) = match load_and_solve(a, sets, options) {
        Ok(x) => x,
        Err(code) => return code,
    };
    let sets_b: Vec<String> = sets.iter().chain(set_b).cloned().collect();
    let (case_b, sol_b) = match load_and_solve(b, &sets_b, options) {
        Ok(x) => x,
        Err(code) => return code,
    };
    let (view_a, view_b) = (sol_a.view(), sol_b.view());
    let name_a = a.display().to_string();
    let name_b = if set_b.is_empty() {
        b.display().to_string()
    } else {
        format!("{} --set-b {}", b.display(), set_b.join(" --set-b "))
    };
    fn side<'a>(
        name: &'a str,
        case: &dyn Case,
        view: &'a bearings::view::View,
    ) -> report::diff::Side<'a> {
        report::diff::Side {
            name,
            system: case.system().title(),
            element: case.system().element_name(),
            view,
        }
    }
    let d = report::diff::compare(
        side(&name_a, case_a.as_ref(), &view_a),
        side(&name_b, case_b.as_ref(), &view_b),
        case_a.units(),
    );
    let text = match format {
        Format::Text => report::diff::to_text(&d),
        Format::Json => {
            serde_json::to_string_pretty(&report::diff::to_json(&d)).unwrap_or_default() + "\n"
        }
        Format::Csv => report::diff::to_csv(&d),
    };
    commit(&plan, &[text.as_bytes()])
}

/// The report format of a CLI format.
fn report_format(format: Format) -> report::Format {
    match format {
        Format::Text => report::Format::Text,
        Format::Json => report::Format::Json,
        Format::Csv => report::Format::Csv,
    }
}

/// The deck at `path`, or the default system's embedded example deck when there is none.
fn load_case_or_default(
    path: Option<&Path>,
    overrides: &[String],
) -> Result<Box<dyn Case>, String> {
    match path {
        Some(p) => load_case(p, overrides),
        None => {
            let system = bearings::system(bearings::DEFAULT_SYSTEM)
                .ok_or_else(|| "no default bearing system registered".to_string())?;
            bearings::load_case(
                system.example_deck(),
                "decks/aerospace.toml (embedded)",
                overrides,
            )
            .map_err(|e| e.to_string())
        }
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            // --help and --version print and succeed; usage errors have their own code.
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() {
                exit::USAGE
            } else {
                exit::OK
            });
        }
    };
    // --set is global (it applies to the workbench, run, check and bench); where it would be
    // silently ignored it is refused.
    if !cli.set.is_empty() {
        let ignored = match &cli.command {
            Some(Command::Template { .. }) => Some("template"),
            Some(Command::Validate { .. }) => Some("validate"),
            Some(Command::Keys { .. }) => Some("keys"),
            // A study's values live in its file, so that its hash says what was run.
            Some(Command::Study { .. }) => Some("study"),
            _ => None,
        };
        if let Some(cmd) = ignored {
            eprintln!(
                "--set {}: `rollbench {cmd}` takes no overrides (use --set with run, check, bench, sweep or the workbench)",
                cli.set.join(" --set ")
            );
            return ExitCode::from(exit::USAGE);
        }
    }
    match cli.command {
        None => {
            let case = match load_case_or_default(cli.deck.as_deref(), &cli.set) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(exit::INVALID_INPUT);
                }
            };
            if let Err(e) = color_eyre::install() {
                eprintln!("{e}");
            }
            match rollbench::tui::run_workbench_case(case, cli.deck.clone()) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    if let Some(i) = e.downcast_ref::<rollbench::tui::Interrupted>() {
                        eprintln!("rollbench: {i}");
                        return ExitCode::from(i.exit_code());
                    }
                    eprintln!("workbench: {e:?}");
                    ExitCode::from(exit::INVALID_INPUT)
                }
            }
        }
        Some(Command::Run {
            deck,
            format,
            output,
            no_transient,
            series,
        }) => {
            let mut outputs = vec![("--output", output.as_deref())];
            if series.is_some() {
                outputs.push(("--series", series.as_deref()));
            }
            let plan = match plan_outputs(&outputs, &deck) {
                Ok(p) => p,
                Err(code) => return code,
            };
            let options = RunOptions {
                skip_transient: no_transient,
            };
            let (case, solution) = match load_and_solve(&deck, &cli.set, options) {
                Ok(x) => x,
                Err(code) => return code,
            };
            // The history first: a run that cannot give what was asked writes nothing.
            let series_csv = match series.as_deref().map(|_| solution.series_csv()) {
                Some(Err(e)) => {
                    eprintln!("--series: {e}");
                    return ExitCode::from(exit::INVALID_INPUT);
                }
                Some(Ok(csv)) => Some(csv),
                None => None,
            };
            let text = report::render(solution.as_ref(), report_format(format), case.units());
            match &series_csv {
                Some(csv) => commit(&plan, &[text.as_bytes(), csv.as_bytes()]),
                None => commit(&plan, &[text.as_bytes()]),
            }
        }
        Some(Command::Stiffness {
            deck,
            check_fd,
            format,
            output,
            export,
        }) => {
            let plan = match plan_outputs(&[("--output", output.as_deref())], &deck) {
                Ok(p) => p,
                Err(code) => return code,
            };
            let mut sets = cli.set.clone();
            if check_fd {
                sets.push("solver.stiffness=both".into());
            }
            let options = RunOptions {
                skip_transient: true,
            };
            let (case, solution) = match load_and_solve(&deck, &sets, options) {
                Ok(x) => x,
                Err(code) => return code,
            };
            let units = case.units();
            if let Some(export) = export {
                return stiffness_export(&deck, case.as_ref(), solution.as_ref(), export, &plan);
            }
            let Some(text) =
                report::stiffness::render(solution.as_ref(), report_format(format), units)
            else {
                // The system's own reason when it gives one (issue 29: a stage that cannot
                // answer says why, with its numbers).
                let reason = solution
                    .json()
                    .get("stiffness")
                    .and_then(|k| k.get("reason"))
                    .and_then(|r| r.as_str().map(str::to_string));
                match reason {
                    Some(r) => eprintln!(
                        "{}: the {} has no stiffness matrix here: {r}",
                        deck.display(),
                        case.system().title()
                    ),
                    None => eprintln!(
                        "{}: the {} has no stiffness matrix",
                        deck.display(),
                        case.system().title()
                    ),
                }
                return ExitCode::from(exit::INVALID_INPUT);
            };
            commit(&plan, &[text.as_bytes()])
        }
        Some(Command::Optimise { deck, grid, format }) => {
            let case = match load_case(&deck, &cli.set) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(exit::INVALID_INPUT);
                }
            };
            let bar = progress_bar();
            let progress = |f: f64| bar.report(f);
            let out = rollbench::cli::optimise(
                case.as_ref(),
                &deck,
                grid,
                format,
                Cancel::NONE.with_progress(&progress),
            );
            bar.finish();
            match out {
                Ok(text) => {
                    print!("{text}");
                    ExitCode::SUCCESS
                }
                Err((code, message)) => {
                    eprintln!("{message}");
                    ExitCode::from(code)
                }
            }
        }
        Some(Command::Diff {
            a,
            b,
            format,
            output,
            set_b,
            no_transient,
        }) => diff(
            &a,
            &b,
            &cli.set,
            &set_b,
            format,
            output.as_deref(),
            no_transient,
        ),
        Some(Command::Check { deck }) => match load_case(&deck, &cli.set) {
            Ok(_) => {
                println!("{}: ok", deck.display());
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("{e}");
                ExitCode::from(exit::INVALID_INPUT)
            }
        },
        Some(Command::Template { units, r#type }) => {
            let u = match units {
                UnitsArg::Si => Units::Si,
                UnitsArg::Us => Units::Us,
            };
            match bearings::system(&r#type) {
                Some(system) => {
                    print!("{}", system.template(u));
                    ExitCode::SUCCESS
                }
                None => {
                    eprintln!(
                        "--type {}: unknown bearing system (known: {})",
                        r#type,
                        bearings::known_types()
                    );
                    // An unknown option value is a usage error (README), like --format xml.
                    ExitCode::from(exit::USAGE)
                }
            }
        }
        Some(Command::Validate { format }) => {
            let cases = rollbench::verify::cases::cases();
            match format {
                TableFormat::Text => print!("{}", rollbench::verify::cases::to_text(&cases)),
                TableFormat::Json => println!("{:#}", rollbench::verify::cases::to_json(&cases)),
            }
            ExitCode::from(if rollbench::verify::cases::all_pass(&cases) {
                exit::OK
            } else {
                exit::VALIDATION_FAILED
            })
        }
        Some(Command::Keys { r#type }) => {
            match bearings::system(r#type.as_deref().unwrap_or(bearings::DEFAULT_SYSTEM)) {
                Some(system) => {
                    if r#type.is_none() {
                        // Issue 30 item 17: the table alone read as if it were every key.
                        eprintln!(
                        "keys of the {} system (no --type given); the others: rollbench keys --type TYPE, TYPE one of {}",
                        system.id(),
                        bearings::known_types()
                    );
                    }
                    let mut out = String::new();
                    if r#type.is_none() {
                        // Issue 30 item 17: the default system's table as before, named in
                        // the first line, then every other system's, each under its name.
                        out.push_str(&format!(
                            "keys of the {} system (the default type), then of every other system; one system: rollbench keys --type TYPE\n",
                            system.id()
                        ));
                        out.push_str(&system.keys_table());
                        for other in bearings::SYSTEMS.iter().filter(|o| o.id() != system.id()) {
                            out.push_str(&format!(
                                "\nkeys of the {} system (--type {})\n",
                                other.id(),
                                other.id()
                            ));
                            out.push_str(&other.keys_table());
                        }
                    } else {
                        out.push_str(&system.keys_table());
                    }
                    // A closed pipe (`keys | head`) ends the listing quietly.
                    let _ = std::io::Write::write_all(&mut std::io::stdout(), out.as_bytes());
                    ExitCode::SUCCESS
                }
                None => {
                    eprintln!(
                        "--type {}: unknown bearing system (known: {})",
                        r#type.as_deref().unwrap_or_default(),
                        bearings::known_types()
                    );
                    ExitCode::from(exit::USAGE)
                }
            }
        }
        Some(Command::Losses {
            deck,
            direction,
            f_over_c,
            format,
        }) => {
            let case = match load_case(&deck, &cli.set) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(exit::INVALID_INPUT);
                }
            };
            match rollbench::cli::losses_command(case.as_ref(), direction, &f_over_c, format) {
                Ok(text) => {
                    print!("{text}");
                    ExitCode::SUCCESS
                }
                Err((code, e)) => {
                    eprintln!("{e}");
                    ExitCode::from(code)
                }
            }
        }
        Some(Command::Contact {
            deck,
            position,
            inlet,
            model,
            thermal,
            format,
        }) => {
            let case = match load_case(&deck, &cli.set) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(exit::INVALID_INPUT);
                }
            };
            match rollbench::cli::contact_command(
                case.as_ref(),
                &position,
                inlet,
                model,
                thermal,
                format,
            ) {
                Ok(text) => {
                    print!("{text}");
                    ExitCode::SUCCESS
                }
                Err((code, e)) => {
                    eprintln!("{e}");
                    ExitCode::from(code)
                }
            }
        }
        Some(Command::Sweep {
            deck,
            set_range,
            cold,
            format,
            output,
        }) => sweep(&deck, &cli.set, &set_range, cold, format, output.as_deref()),
        Some(Command::Study {
            file,
            format,
            output,
            shard,
            shards,
            action,
        }) => match action {
            Some(rollbench::cli::StudyAction::Merge {
                parts,
                format,
                output,
            }) => study_merge(&parts, format, output.as_deref()),
            None => match file {
                Some(file) => match shard {
                    Some(spec) => study_shard(&file, &spec, shards, output.as_deref()),
                    None => study(&file, format, output.as_deref()),
                },
                None => {
                    eprintln!("study: give a study file, or `study merge PART…`");
                    ExitCode::from(exit::USAGE)
                }
            },
        },
        Some(Command::Bench { deck, format }) => {
            match rollbench::studies::fidelity::bench_command(
                deck.as_deref(),
                &cli.set,
                format == TableFormat::Json,
                std::io::IsTerminal::is_terminal(&std::io::stderr()),
            ) {
                Ok(text) => {
                    print!("{text}");
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("{e}");
                    // A deck that cannot be read or parsed is invalid input; a reference
                    // run that fails is a solver failure, as for `run`.
                    ExitCode::from(
                        if e.contains(rollbench::studies::fidelity::REFERENCE_RUN_FAILED) {
                            exit::SOLVE_FAILED
                        } else {
                            exit::INVALID_INPUT
                        },
                    )
                }
            }
        }
    }
}

/// `rollbench sweep`: the deck with `--set` applied, then `--set-range` swept (see
/// [`rollbench::studies::sweep`]). A bad range, key or value exits with
/// [`exit::INVALID_INPUT`] before anything is solved; points that fail to solve are rows
/// with their reason, and only a sweep in which every point failed exits with
/// [`exit::SOLVE_FAILED`].
fn sweep(
    deck: &Path,
    overrides: &[String],
    range: &str,
    cold: bool,
    format: Format,
    output: Option<&Path>,
) -> ExitCode {
    use rollbench::studies::sweep;
    use std::io::IsTerminal;
    let plan = match plan_outputs(&[("--output", output)], deck) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let case = match load_case(deck, overrides) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let result = match sweep::run(
        case.as_ref(),
        range,
        std::io::stderr().is_terminal(),
        if cold {
            sweep::Start::Cold
        } else {
            sweep::Start::Warm
        },
    ) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let text = match format {
        Format::Text => sweep::to_text(&result),
        Format::Json => {
            serde_json::to_string_pretty(&sweep::to_json(&result))
                .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
                + "\n"
        }
        Format::Csv => sweep::to_csv(&result),
    };
    let failed = result.failures();
    if failed == result.points.len() {
        if let Some(path) = output {
            // As `run`: a sweep that solved nothing replaces no file.
            eprintln!(
                "sweep: none of the {failed} points solved; --output {} is not written \
                 (first failure: {})",
                path.display(),
                result
                    .points
                    .iter()
                    .find_map(|p| p.failure.as_deref())
                    .unwrap_or("unknown")
            );
            return ExitCode::from(exit::SOLVE_FAILED);
        }
    }
    let written = commit(&plan, &[text.as_bytes()]);
    if written != ExitCode::SUCCESS {
        return written;
    }
    if failed > 0 {
        eprintln!(
            "sweep: {failed} of {} points failed to solve (their rows give the reason)",
            result.points.len()
        );
    }
    if failed == result.points.len() {
        ExitCode::from(exit::SOLVE_FAILED)
    } else {
        ExitCode::SUCCESS
    }
}

/// The summary on standard error when the result itself goes elsewhere in another format.
fn study_summary_to_stderr(result: &rollbench::studies::study::StudyResult, format: StudyFormat) {
    if format != StudyFormat::Text {
        eprint!("{}", rollbench::studies::study::summary::text(result));
    }
}

/// `rollbench study FILE`: every point locally, in parallel (see
/// [`rollbench::studies::study`]). A bad study file, deck, key or output exits with
/// [`exit::INVALID_INPUT`] before anything is solved; failed points are rows with their
/// reason; a study in which every point failed writes no file and exits
/// [`exit::SOLVE_FAILED`].
fn study(file: &Path, format: StudyFormat, output: Option<&Path>) -> ExitCode {
    use std::io::IsTerminal;
    let plan = match plan_outputs(&[("--output", output)], file) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let prepared = match rollbench::studies::study::prepare(file) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let result = prepared.run(std::io::stderr().is_terminal());
    let failed = result.failures();
    if failed == result.rows.len() {
        eprintln!(
            "study: none of the {failed} points solved{} (first failure: {})",
            output.map_or(String::new(), |p| format!(
                "; --output {} is not written",
                p.display()
            )),
            result
                .rows
                .iter()
                .find_map(|r| r.failure.as_deref())
                .unwrap_or("unknown")
        );
        return ExitCode::from(exit::SOLVE_FAILED);
    }
    let text = rollbench::cli::study_text(&result, format);
    let written = commit(&plan, &[text.as_bytes()]);
    if written != ExitCode::SUCCESS {
        return written;
    }
    study_summary_to_stderr(&result, format);
    ExitCode::SUCCESS
}

/// `rollbench study FILE --shard I/N --output PART`: the shard's points into its part,
/// resumed from it (see [`rollbench::studies::study::part`]). Failed points are rows (the
/// exit code stays 0, so a dependent merge job runs); a refused part or shard exits 1.
fn study_shard(file: &Path, spec: &str, shards: Option<usize>, output: Option<&Path>) -> ExitCode {
    use rollbench::studies::study::{part, progress_bar};
    use std::io::IsTerminal;
    let Some(output) = output.filter(|p| p.as_os_str() != "-") else {
        eprintln!("--shard {spec}: give --output PART (a file: the part is appended to as points finish, and resumed from)");
        return ExitCode::from(exit::USAGE);
    };
    if let Err(code) = plan_outputs(&[("--output", Some(output))], file) {
        return code;
    }
    let shard = match part::Shard::parse(spec, shards, &|k| std::env::var(k).ok()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::USAGE);
        }
    };
    let prepared = match rollbench::studies::study::prepare(file) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let n = shard.indices(prepared.plan.len()).len();
    let bar = progress_bar(
        std::io::stderr().is_terminal(),
        n,
        &format!("{} shard {}", file.display(), shard.label()),
    );
    let run = part::run_shard(&prepared, shard, output, &|| {
        if let Some(b) = &bar {
            b.inc(1);
        }
    });
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    match run {
        Ok(r) => {
            eprintln!(
                "study {} shard {}: {} points ({} resumed from {}{}, {} computed), {} failed",
                file.display(),
                shard.label(),
                r.points,
                r.kept,
                output.display(),
                if r.discarded_torn_line {
                    ", a torn last line discarded"
                } else {
                    ""
                },
                r.computed,
                r.failures
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(exit::INVALID_INPUT)
        }
    }
}

/// `rollbench study merge PART… [--format F] [--output FILE]`.
fn study_merge(
    parts: &[std::path::PathBuf],
    format: StudyFormat,
    output: Option<&Path>,
) -> ExitCode {
    let inputs: Vec<(&str, &Path)> = parts
        .iter()
        .map(|p| ("a part being merged", p.as_path()))
        .collect();
    if let Err(e) = files::remove_temporaries_on_signals() {
        eprintln!("warning: a signal may leave a temporary file beside the outputs: {e}");
    }
    let plan = match files::plan(&[("--output", output)], &inputs) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let mut texts = Vec::with_capacity(parts.len());
    for p in parts {
        match std::fs::read_to_string(p) {
            Ok(t) => texts.push((p.display().to_string(), t)),
            Err(e) => {
                eprintln!("{}: cannot read: {e}", p.display());
                return ExitCode::from(exit::INVALID_INPUT);
            }
        }
    }
    let result = match rollbench::studies::study::part::merge(&texts) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("study merge: {e}");
            return ExitCode::from(exit::INVALID_INPUT);
        }
    };
    let text = rollbench::cli::study_text(&result, format);
    let written = commit(&plan, &[text.as_bytes()]);
    if written != ExitCode::SUCCESS {
        return written;
    }
    study_summary_to_stderr(&result, format);
    ExitCode::SUCCESS
}
