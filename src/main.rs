//! The `gearwear` binary: the command line (`src/cli/`) over the library.

#![warn(unreachable_pub)]

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
