//! The `gearwear` binary; all logic lives in the library (`gearwear::cli`).

fn main() -> std::process::ExitCode {
    gearwear::cli::main()
}
