//! rollbench binary: the workbench by default, headless subcommands otherwise.
#![forbid(unsafe_code)]

use std::process::ExitCode;

use clap::Parser;
use rollbench::bearings::spherical_roller::pipeline::{self, Request};
use rollbench::cli::{
    load_deck, thermal_model, write_atomic, Cli, Command, Format, TableFormat, UnitsArg,
};
use rollbench::deck::Units;
use rollbench::report::{self, ReportUnits};

fn report_units(u: Units) -> ReportUnits {
    match u {
        Units::Si => ReportUnits::Si,
        Units::Us => ReportUnits::Us,
    }
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
            let (deck, thermal) = match load_deck(Some(&deck), &cli.set)
                .and_then(|d| thermal_model(&d).map(|t| (d, t)))
            {
                Ok(d) => d,
                Err(e) => {
                    eprintln!("{e}");
                    return ExitCode::from(1);
                }
            };
            let request = Request {
                thermal_transient: !no_transient,
                ..Request::default()
            };
            let analysis =
                match pipeline::run_with_thermal(&deck.bearing, thermal.as_ref(), &request, None) {
                    Ok(a) => a,
                    Err(e) => {
                        eprintln!("solve failed: {e}");
                        return ExitCode::from(2);
                    }
                };
            let text = match format {
                Format::Text => report::text::to_string(&analysis, report_units(deck.units)),
                Format::Json => report::json::to_string(&analysis) + "\n",
                Format::Csv => report::csv::to_string(&analysis),
            };
            match output {
                Some(path) => {
                    if let Err(e) = write_atomic(&path, &text) {
                        eprintln!("cannot write {}: {e}", path.display());
                        return ExitCode::from(1);
                    }
                }
                None => print!("{text}"),
            }
            ExitCode::SUCCESS
        }
        Some(Command::Check { deck }) => {
            match load_deck(Some(&deck), &cli.set).and_then(|d| thermal_model(&d)) {
                Ok(_) => {
                    println!("{}: ok", deck.display());
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("{e}");
                    ExitCode::from(1)
                }
            }
        }
        Some(Command::Template { units }) => {
            let u = match units {
                UnitsArg::Si => Units::Si,
                UnitsArg::Us => Units::Us,
            };
            print!("{}", rollbench::deck::template(u));
            ExitCode::SUCCESS
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
