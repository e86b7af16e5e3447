//! The `gearwear` command line: the binary's `main`, and the `gearwear` console script of the
//! Python wheel (one build gives both; a library built without the `cli` feature has
//! neither clap nor indicatif). Thin: each command parses its arguments into a job of
//! the application layer (`crate::app`), runs it with a terminal observer (progress bars,
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
    ($($t:tt)*) => { crate::io::console::out_line(&format!($($t)*)) };
}
macro_rules! eprintln {
    ($($t:tt)*) => { crate::io::console::err_line(&format!($($t)*)) };
}

mod args;
mod calibrate_cmd;
mod common_args;
mod config_cmd;
mod dataset_cmd;
mod dynamics_cmd;
mod error;
pub mod flag;
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

/// Entry point of the binary: the process's own arguments (exit codes: see the module docs).
pub fn main() -> ExitCode {
    ExitCode::from(main_from(std::env::args_os()))
}

/// The command line run on `args` (the program's name first, as `std::env::args_os`
/// gives it); its exit code (see the module docs). `--help`, `--version` and a malformed
/// command line end the process as the binary does (clap's exit codes 0 and 2). For the
/// Python console script, which passes `sys.argv`.
pub fn main_from<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    crate::io::runtime::catch_file_size_signal();
    let cli = Cli::parse_from(args);
    output::set_quiet(cli.quiet);
    output::set_replace(cli.replace);
    let pool = match crate::io::runtime::thread_pool() {
        Ok((pool, note)) => {
            if let Some(n) = note {
                eprintln!("note: {n}");
            }
            pool
        }
        Err(e) => {
            eprintln!("error: {e}");
            return crate::io::console::finish().unwrap_or(1);
        }
    };
    // Every parallel loop of the command runs on this pool.
    let code = pool.install(|| run(&cli));
    crate::io::console::finish().unwrap_or(code)
}

/// The figure options of `command`, if it draws figures (counted by its budget).
fn figure_args(command: &Command) -> Option<&common_args::FigureArgs> {
    Some(match command {
        Command::Config(_) => return None,
        Command::Stiffness(a) => &a.figures,
        Command::Dynamics(a) => &a.figures,
        Command::Signals(a) => &a.figures,
        Command::Dataset(a) => &a.figures,
        Command::DatasetMerge(a) => &a.figures,
        Command::Wear(a) => &a.figures,
        Command::Run(a) => &a.figures,
        Command::Sweep(a) => &a.figures,
        Command::SweepMerge(a) => &a.figures,
        Command::Calibrate(a) => &a.figures,
        Command::Predict(a) => &a.figures,
        Command::PredictMerge(a) => &a.figures,
        Command::LoadSpectrum(a) => &a.figures,
    })
}

/// Run the command `cli` names; its exit code.
fn run(cli: &Cli) -> u8 {
    let budget = match figure_args(&cli.command) {
        Some(f) => crate::app::budget::with_figures(cli.budget(), &f.request()),
        None => cli.budget(),
    };
    let result = match &cli.command {
        Command::Config(a) => config_cmd::run(a),
        Command::Stiffness(a) => stiffness_cmd::run(a, budget),
        Command::Dynamics(a) => dynamics_cmd::run(a, budget),
        Command::Signals(a) => signals_cmd::run(a, budget),
        Command::Dataset(a) => dataset_cmd::run(a, budget),
        Command::DatasetMerge(a) => dataset_cmd::merge(a, budget),
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
