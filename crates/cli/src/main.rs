//! `gaitlab`: the command-line face of gaitlab (DESIGN.md "Contracts"): list and
//! validate presets, run the She 2006 motions headless with metrics, BVH and CSV
//! output, follow recorded targets, report the performance figures, and tune
//! a physics gait's gains.

mod bench;
mod drive;
mod export;
mod fail;
mod load;
mod options;
mod params;
mod print;
mod run;
mod schedule;
mod sink;
mod stdout;
mod track;
mod tune;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// gaitlab — legged figures animated by inverse kinematics (She 2006), PODA
/// gait synthesis and Raibert–Hodgins dynamics.
#[derive(Parser, Debug)]
#[command(name = "gaitlab", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// One line per bundled preset: name, engine, joints, legs.
    Presets,
    /// Check a preset file; exit 0 with a summary, or 2 with `error: <json path>: <reason>`.
    Validate {
        /// Path to a preset JSON file (or the name of a bundled preset).
        file: String,
    },
    /// Run a preset headless and report metrics.
    Run(run::RunArgs),
    /// Follow recorded effector targets from a CSV file.
    Track(track::TrackArgs),
    /// Performance figures: µs per IK iteration per method and preset, physics steps per second.
    Bench(bench::BenchArgs),
    /// Write a physics creature as a MuJoCo model (`--format mjcf`).
    Export(export::ExportArgs),
    /// Tune a physics gait's gains by CMA-ES against an objective; writes the tuned preset.
    Tune(tune::TuneArgs),
    /// The parameter table: every settable value, its unit, range, reference and origin.
    Params(params::ParamsArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let outcome = match cli.command {
        Command::Presets => {
            load::print_presets();
            Ok(())
        }
        Command::Validate { file } => load::validate(&file),
        Command::Run(args) => run::run(&args),
        Command::Track(args) => track::track(&args),
        Command::Bench(args) => bench::bench(&args),
        Command::Export(args) => export::export(&args),
        Command::Tune(args) => tune::tune(&args),
        Command::Params(args) => params::params(&args),
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            eprintln!("error: {}", failure.message);
            ExitCode::from(failure.code)
        }
    }
}
