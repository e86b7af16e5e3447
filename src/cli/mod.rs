//! The `gearwear` command line. Thin: parses arguments, builds the model objects from a
//! validated case, calls the solvers, hands results to the writers.
//!
//! Exit codes: 0 success; 1 a run that failed on valid input (a solver); 2 bad input (the
//! case, a file argument, the output folder, the budget); 3 the command ran to its end
//! but standard output or standard error could not be written (`io::console`).

// In the command line, `println!` and `eprintln!` are these: they never panic when a
// stream fails (`/dev/full`, a closed pipe); `io::console` remembers the failure and the
// command says so once at its end. Defined before the modules so that they see them.
#[allow(unused_macros)]
macro_rules! println {
    ($($t:tt)*) => { $crate::io::console::out_line(&format!($($t)*)) };
}
macro_rules! eprintln {
    ($($t:tt)*) => { $crate::io::console::err_line(&format!($($t)*)) };
}

mod args;
mod calibrate_cmd;
mod config_cmd;
mod dynamics_cmd;
mod error;
mod output;
mod predict_cmd;
mod progress;
mod resume;
mod run_cmd;
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

/// Entry point of the binary (exit codes: see the module docs).
pub fn main() -> ExitCode {
    crate::io::runtime::catch_file_size_signal();
    let cli = Cli::parse();
    output::set_quiet(cli.quiet);
    output::set_replace(cli.replace);
    output::set_budget(cli.budget());
    let pool = match crate::io::runtime::thread_pool() {
        Ok((pool, note)) => {
            if let Some(n) = note {
                eprintln!("note: {n}");
            }
            pool
        }
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(crate::io::console::finish().unwrap_or(1));
        }
    };
    // Every parallel loop of the command runs on this pool.
    let code = pool.install(|| run(&cli));
    ExitCode::from(crate::io::console::finish().unwrap_or(code))
}

/// Run the command `cli` names; its exit code.
fn run(cli: &Cli) -> u8 {
    let budget = match cli.budget() {
        Some(b) => cli.check_budget(&b),
        None => Ok(()),
    };
    let result = budget.and_then(|()| match &cli.command {
        Command::Config(a) => config_cmd::run(a),
        Command::Stiffness(a) => stiffness_cmd::run(a),
        Command::Dynamics(a) => dynamics_cmd::run(a),
        Command::Wear(a) => wear_cmd::run(a),
        Command::Run(a) => run_cmd::run(a),
        Command::Sweep(a) => sweep_cmd::run(a),
        Command::SweepMerge(a) => sweep_merge_cmd::merge(a),
        Command::Calibrate(a) => calibrate_cmd::run(a),
        Command::Predict(a) => predict_cmd::run(a),
        Command::PredictMerge(a) => predict_cmd::merge(a),
    });
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}
