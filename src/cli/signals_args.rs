//! Arguments of `gearwear signals`, `gearwear dataset` and `gearwear dataset-merge`.

use super::common_args::{CaseArgs, FigureArgs};
use clap::Args;
use std::path::PathBuf;

#[derive(Debug, Args)]
pub(crate) struct SignalsArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Transfer path from the bearing forces to the sensors: an FRF table (.csv) or a
    /// modal description (.toml), docs/SIGNALS.md. Default: the built-in generic housing.
    #[arg(long, value_name = "FILE")]
    pub(crate) transfer_path: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "results/signals")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct DatasetArgs {
    /// Study design (TOML): the case, run-to-failure states, fault conditions, speeds,
    /// loads, noise realisations (docs/SIGNALS.md, "Datasets").
    #[arg(long, value_name = "FILE")]
    pub(crate) design: PathBuf,
    /// Run only shard I of N (round-robin over the physical states; merge the shards
    /// with `gearwear dataset-merge`).
    #[arg(long, value_name = "I/N")]
    pub(crate) shard: Option<String>,
    /// Output directory (shards may share one).
    #[arg(long, default_value = "results/dataset")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct DatasetMergeArgs {
    /// Dataset folders of the shards (or one folder they share).
    #[arg(required = true, value_name = "DIR")]
    pub(crate) inputs: Vec<PathBuf>,
    /// Output directory of the merged dataset (may be the shards' shared folder).
    #[arg(long)]
    pub(crate) out: PathBuf,
    /// The transfer-path file the shards' design names (`transfer_path`), needed to
    /// recompute their records: the shards keep only its hash.
    #[arg(long, value_name = "FILE")]
    pub(crate) transfer_path: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}
