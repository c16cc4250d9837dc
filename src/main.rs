//! rollbench binary: the workbench by default, headless subcommands otherwise.
#![forbid(unsafe_code)]

use std::process::ExitCode;

use std::path::Path;

use clap::Parser;
use rollbench::bearings::{self, Case, RunOptions};
use rollbench::cli::{load_deck, Cli, Command, Format, TableFormat, UnitsArg};
use rollbench::deck::{self, Units};
use rollbench::files::{same_file, write_atomic};
use rollbench::numerics::cancel::Cancel;
use rollbench::report;

/// Reads the deck at `path`, finds its bearing system by `type`, and has that system
/// parse it with the `--set` overrides.
fn load_case(path: &Path, overrides: &[String]) -> Result<Box<dyn Case>, String> {
    let text = deck::read_deck_text(path).map_err(|e| e.to_string())?;
    let name = path.display().to_string();
    let system = deck::system_of(&text, &name).map_err(|e| e.to_string())?;
    system
        .load(&text, &name, overrides)
        .map_err(|e| e.to_string())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        None => {
            let deck = match load_deck(cli.deck.as_deref(), &cli.set) {
                Ok(d) => d,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(1);
                }
            };
            if let Err(e) = color_eyre::install() {
                eprintln!("{e}");
            }
            match rollbench::tui::run_workbench_deck(deck, cli.deck.clone()) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("workbench: {e:?}");
                    ExitCode::from(1)
                }
            }
        }
        Some(Command::Run {
            deck,
            format,
            output,
            no_transient,
        }) => {
            // Never write the report over the deck being read (checked before solving).
            if let Some(out) = &output {
                if same_file(out, &deck) {
                    eprintln!(
                        "--output {}: is the deck being read ({}); refusing to overwrite it",
                        out.display(),
                        deck.display()
                    );
                    return ExitCode::from(1);
                }
            }
            let case = match load_case(&deck, &cli.set) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(1);
                }
            };
            let options = RunOptions {
                skip_transient: no_transient,
            };
            let solution = match case.solve(options, Cancel::NONE) {
                Ok(s) => s,
                Err(e) => {
                    eprintln!("solve failed: {e}");
                    return ExitCode::from(2);
                }
            };
            let format = match format {
                Format::Text => report::Format::Text,
                Format::Json => report::Format::Json,
                Format::Csv => report::Format::Csv,
            };
            let text = report::render(solution.as_ref(), format, case.units());
            match output {
                Some(path) => {
                    if let Err(e) = write_atomic(&path, &text).map(drop) {
                        eprintln!("cannot write {}: {e}", path.display());
                        return ExitCode::from(1);
                    }
                }
                None => print!("{text}"),
            }
            ExitCode::SUCCESS
        }
        Some(Command::Check { deck }) => match load_case(&deck, &cli.set) {
            Ok(_) => {
                println!("{}: ok", deck.display());
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("{e}");
                ExitCode::from(1)
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
                    ExitCode::from(1)
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
                0
            } else {
                1
            })
        }
        Some(Command::Bench { deck, format }) => {
            match rollbench::verify::fidelity::bench_command(
                deck.as_deref(),
                &cli.set,
                format == TableFormat::Json,
            ) {
                Ok(text) => {
                    print!("{text}");
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("{e}");
                    ExitCode::from(1)
                }
            }
        }
    }
}
