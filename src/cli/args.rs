//! Command-line arguments (clap derive).

use crate::config::{load_case, Case};
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

use super::CliError;

#[derive(Debug, Parser)]
#[command(
    name = "gearwear",
    version,
    about = "Dynamic wear prediction of spur gears (Coatings 2022, 12, 1250)"
)]
pub struct Cli {
    /// Print no results on standard output (errors, warnings and progress still go to
    /// standard error).
    #[arg(long, short, global = true)]
    pub quiet: bool,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Print the default case (the paper's) as commented TOML.
    Config(ConfigArgs),
    /// Mesh stiffness (potential energy method), ISO 6336 check, load sharing, static TE.
    Stiffness(StiffnessArgs),
    /// One steady-state evaluation of the 8-DOF tribo-dynamic model.
    Dynamics(DynamicsArgs),
    /// The coupled dynamics-wear study (and its quasi-static twin).
    Wear(WearArgs),
    /// The paper's section 4 study on the case, with a self-contained HTML report (the main job).
    Run(RunArgs),
    /// Run the cross product of varied keys (in parallel; resumable; shardable).
    Sweep(SweepArgs),
    /// Join the tables of sweep shards into one, sorted by case id.
    SweepMerge(SweepMergeArgs),
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

#[derive(Debug, Args)]
pub struct StiffnessArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Output directory.
    #[arg(long, default_value = "results/stiffness")]
    pub out: PathBuf,
}

#[derive(Debug, Args)]
pub struct DynamicsArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Geometric transmission error to add: CSV `pinion_angle_deg,error_um` over one mesh
    /// period (positive adds to the mesh compression, paper eq. 2).
    #[arg(long, value_name = "FILE")]
    pub transmission_error: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "results/dynamics")]
    pub out: PathBuf,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum WearModeArg {
    Dynamic,
    QuasiStatic,
    Both,
}

#[derive(Debug, Args)]
pub struct WearArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Which solver feeds the wear model.
    #[arg(long, value_enum, default_value = "both")]
    pub mode: WearModeArg,
    /// Output directory.
    #[arg(long, default_value = "results/wear")]
    pub out: PathBuf,
    /// Continue from the checkpoints in the output directory.
    #[arg(long)]
    pub resume: bool,
}

#[derive(Debug, Args)]
pub struct RunArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// Output directory.
    #[arg(long, default_value = "results")]
    pub out: PathBuf,
    /// Continue the wear studies from the checkpoints in the output directory.
    #[arg(long)]
    pub resume: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SweepRunArg {
    Dynamics,
    Wear,
}

/// `--continuation`: which solution branches a one-parameter sweep follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ContinuationArg {
    Up,
    Down,
    Both,
}

#[derive(Debug, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub case: CaseArgs,
    /// A varied key: KEY=START:STOP:STEP (STOP included when the range lands on it) or
    /// KEY=v1,v2,... (repeatable; the first --vary varies slowest).
    #[arg(
        long = "vary",
        value_name = "KEY=START:STOP:STEP|KEY=V1,V2,...",
        required = true
    )]
    pub vary: Vec<String>,
    /// What each case runs: one dynamic evaluation, or the wear study (both modes).
    #[arg(long, value_enum, default_value = "dynamics")]
    pub run: SweepRunArg,
    /// Output directory (cases/<case_id>.json, sweep.csv, sweep.json, sweep.png).
    #[arg(long, default_value = "results/sweep")]
    pub out: PathBuf,
    /// Run only shard I of N (1-based; round-robin: case ids with id mod N = I-1);
    /// outputs are then named sweep_shard_I_of_N.*.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// Follow solution branches: run the single --vary axis in order (up: rising values,
    /// down: falling, both: the two branches), each point started from the periodic state
    /// of the point before; sweep.csv gets a `branch` column. One --vary, --run dynamics,
    /// no --shard.
    #[arg(long, value_enum, value_name = "BRANCHES")]
    pub continuation: Option<ContinuationArg>,
}

#[derive(Debug, Args)]
pub struct SweepMergeArgs {
    /// Sweep output directories (their sweep.csv and sweep_shard_*_of_*.csv) or CSV files.
    #[arg(required = true, value_name = "DIR_OR_CSV")]
    pub inputs: Vec<PathBuf>,
    /// Output directory (writes sweep.csv there), or a .csv file path.
    #[arg(long)]
    pub out: PathBuf,
}
