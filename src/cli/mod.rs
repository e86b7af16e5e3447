//! The `gearwear` command line. Thin: each command parses its arguments into a job of
//! the application layer (`crate::app`), runs it with a terminal observer (progress bars,
//! warnings on standard error) and prints its headline; errors are worded with the
//! command line's flags (`error::flag`).

mod args;
mod calibrate_cmd;
mod config_cmd;
mod dataset_cmd;
mod dynamics_cmd;
mod error;
mod load_spectrum_cmd;
mod output;
mod predict_cmd;
mod progress;
mod run_cmd;
mod signals_args;
mod signals_cmd;
mod stiffness_cmd;
mod sweep_cmd;
mod wear_cmd;

pub use args::{CaseArgs, Cli, Command};
pub use error::{flag, CliError};
pub use progress::Terminal;

use clap::Parser;
use std::process::ExitCode;

/// Entry point of the binary. Exit code 2 for bad input, 1 for a failed run.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    output::set_quiet(cli.quiet);
    let budget = cli.budget();
    let result = match &cli.command {
        Command::Config(a) => config_cmd::run(a),
        Command::Stiffness(a) => stiffness_cmd::run(a, budget),
        Command::Dynamics(a) => dynamics_cmd::run(a, budget),
        Command::Signals(a) => signals_cmd::run(a, budget),
        Command::Dataset(a) => dataset_cmd::run(a),
        Command::DatasetMerge(a) => dataset_cmd::merge(a),
        Command::Wear(a) => wear_cmd::run(a, budget),
        Command::Run(a) => run_cmd::run(a, budget),
        Command::Sweep(a) => sweep_cmd::run(a, budget),
        Command::SweepMerge(a) => sweep_cmd::merge(a),
        Command::Calibrate(a) => calibrate_cmd::run(a, budget),
        Command::Predict(a) => predict_cmd::run(a, budget),
        Command::PredictMerge(a) => predict_cmd::merge(a),
        Command::LoadSpectrum(a) => load_spectrum_cmd::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
