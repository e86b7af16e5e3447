//! Command-line arguments (clap derive).

use crate::config::{load_case, Case};
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

use super::CliError;

#[derive(Debug, Parser)]
#[command(name = "gearwear", version, about = "Dynamic wear prediction of spur gears (Coatings 2022, 12, 1250)")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Print the default case (the paper's) as commented TOML.
    Config(ConfigArgs),
}

/// How a case is given: a TOML file and/or `--set` overrides on top of the default.
#[derive(Debug, Clone, Args, Default)]
pub struct CaseArgs {
    /// Case file (TOML). Omitted keys take the paper's defaults.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Override one key, e.g. --set operating.input_speed_hz=45 (repeatable).
    #[arg(long = "set", value_name = "SECTION.KEY=VALUE")]
    pub set: Vec<String>,
}

impl CaseArgs {
    /// Read, merge and validate the case.
    pub fn load(&self) -> Result<Case, CliError> {
        let text = match &self.config {
            Some(p) => std::fs::read_to_string(p).map_err(|e| {
                CliError::input(format!("--config {}: cannot read: {e}", p.display()))
            })?,
            None => String::new(),
        };
        Ok(load_case(&text, &self.set)?)
    }
}

#[derive(Debug, Args)]
pub struct ConfigArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Print the key reference as Markdown (docs/CONFIG.md) instead.
    #[arg(long)]
    pub markdown: bool,
}
