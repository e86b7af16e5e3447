//! Arguments of `gearwear signals`, `gearwear dataset` and `gearwear dataset-merge`.

use super::args::CaseArgs;
use clap::Args;
use std::path::PathBuf;

#[derive(Debug, Args)]
pub struct SignalsArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Transfer path from the bearing forces to the sensors: an FRF table (.csv) or a
    /// modal description (.toml), docs/SIGNALS.md. Default: the built-in generic housing.
    #[arg(long, value_name = "FILE")]
    pub transfer_path: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "results/signals")]
    pub out: PathBuf,
}
