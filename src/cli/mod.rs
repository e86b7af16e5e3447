//! The `gearwear` command line. Thin: parses arguments, builds the model objects from a
//! validated case, calls the solvers, hands results to the writers.

mod args;
mod calibrate_cmd;
mod config_cmd;
mod dataset_cmd;
mod dynamics_cmd;
mod error;
mod output;
mod predict_cmd;
mod progress;
mod resume;
mod run_cmd;
mod signals_args;
mod signals_cmd;
mod stiffness_cmd;
mod stops;
mod sweep_cmd;
mod sweep_continuation;
mod sweep_merge_cmd;
mod sweep_records;
mod wear_cmd;

pub use args::{CaseArgs, Cli, Command};
pub use error::CliError;

use clap::Parser;
use std::process::ExitCode;

/// Entry point of the binary. Exit code 2 for bad input, 1 for a failed run.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    output::set_quiet(cli.quiet);
    let budget = match cli.budget() {
        Some(b) => cli.check_budget(&b),
        None => Ok(()),
    };
    let result = budget.and_then(|()| match &cli.command {
        Command::Config(a) => config_cmd::run(a),
        Command::Stiffness(a) => stiffness_cmd::run(a),
        Command::Dynamics(a) => dynamics_cmd::run(a),
        Command::Signals(a) => signals_cmd::run(a),
        Command::Dataset(a) => dataset_cmd::run(a),
        Command::DatasetMerge(a) => dataset_cmd::merge(a),
        Command::Wear(a) => wear_cmd::run(a),
        Command::Run(a) => run_cmd::run(a),
        Command::Sweep(a) => sweep_cmd::run(a),
        Command::SweepMerge(a) => sweep_merge_cmd::merge(a),
        Command::Calibrate(a) => calibrate_cmd::run(a),
        Command::Predict(a) => predict_cmd::run(a),
        Command::PredictMerge(a) => predict_cmd::merge(a),
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
