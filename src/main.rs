//! The `gearwear` binary: the command line (`gearwear::cli`) over the library.

fn main() -> std::process::ExitCode {
    gearwear::cli::main()
}
