//! The `gearwear` command line, compiled into the binary only (the library and the Python
//! wheel build neither clap nor indicatif). Thin: each command parses its arguments into a job of
//! the application layer (`gearwear::app`), runs it with a terminal observer (progress bars,
//! warnings on standard error) and prints its headline; errors are worded with the
//! command line's flags (`error::flag`).
//!
//! Exit codes: 0 success; 1 a run that failed on valid input (a solver); 2 bad input (the
//! case, a file argument, the output folder, the budget); 3 the command ran to its end
//! but standard output or standard error could not be written (`io::console`).

// In the command line, `println!` and `eprintln!` are these: they never panic when a
// stream fails (`/dev/full`, a closed pipe); `io::console` remembers the failure and the
// command says so once at its end. Defined before the modules so that they see them.
#[allow(unused_macros)]
macro_rules! println {
    ($($t:tt)*) => { gearwear::io::console::out_line(&format!($($t)*)) };
}
macro_rules! eprintln {
    ($($t:tt)*) => { gearwear::io::console::err_line(&format!($($t)*)) };
}

mod args;
mod calibrate_cmd;
mod common_args;
mod config_cmd;
mod dataset_cmd;
mod dynamics_cmd;
mod error;
mod flag;
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

use args::{Cli, Command};

use clap::Parser;
use std::process::ExitCode;

/// Entry point of the binary (exit codes: see the module docs).
pub(crate) fn main() -> ExitCode {
    gearwear::io::runtime::catch_file_size_signal();
    let cli = Cli::parse();
    output::set_quiet(cli.quiet);
    output::set_replace(cli.replace);
    let pool = match gearwear::io::runtime::thread_pool() {
        Ok((pool, note)) => {
            if let Some(n) = note {
                eprintln!("note: {n}");
            }
            pool
        }
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(gearwear::io::console::finish().unwrap_or(1));
        }
    };
    // Every parallel loop of the command runs on this pool.
    let code = pool.install(|| run(&cli));
    ExitCode::from(gearwear::io::console::finish().unwrap_or(code))
}

/// Run the command `cli` names; its exit code.
fn run(cli: &Cli) -> u8 {
    let budget = cli.budget();
    let result = match &cli.command {
        Command::Config(a) => config_cmd::run(a),
        Command::Stiffness(a) => stiffness_cmd::run(a, budget),
        Command::Dynamics(a) => dynamics_cmd::run(a, budget),
        Command::Signals(a) => signals_cmd::run(a, budget),
        Command::Dataset(a) => dataset_cmd::run(a, budget),
        Command::DatasetMerge(a) => dataset_cmd::merge(a),
        Command::Wear(a) => wear_cmd::run(a, budget),
        Command::Run(a) => run_cmd::run(a, budget),
        Command::Sweep(a) => sweep_cmd::run(a, budget),
        Command::SweepMerge(a) => sweep_cmd::merge(a, budget),
        Command::Calibrate(a) => calibrate_cmd::run(a, budget),
        Command::Predict(a) => predict_cmd::run(a, budget),
        Command::PredictMerge(a) => predict_cmd::merge(a, budget),
        Command::LoadSpectrum(a) => load_spectrum_cmd::run(a, budget),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}
