//! Command-line arguments (clap derive).

use crate::study::budget::Budget;
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

use super::common_args::{CaseArgs, FigureArgs};
use super::signals_args::{DatasetArgs, DatasetMergeArgs, SignalsArgs};

#[derive(Debug, Parser)]
#[command(
    name = "gearwear",
    version,
    about = "Dynamic wear prediction of spur gears (Coatings 2022, 12, 1250)"
)]
pub(crate) struct Cli {
    /// Print no results on standard output (errors, warnings and progress still go to
    /// standard error).
    #[arg(long, short, global = true)]
    pub(crate) quiet: bool,
    #[command(subcommand)]
    pub(crate) command: Command,
    /// Multiply the run budget (2 GB of memory, 10 minutes on one core of the reference
    /// machine; docs/RELIABILITY.md) by X, to run a larger case knowingly.
    #[arg(long, global = true, value_name = "X", value_parser = parse_budget_scale)]
    pub(crate) budget_scale: Option<f64>,
    /// Run without the budget check.
    #[arg(long, global = true, conflicts_with = "budget_scale")]
    pub(crate) no_budget: bool,
    /// Replace the results of another command in the output folder (refused otherwise).
    #[arg(long, global = true)]
    pub(crate) replace: bool,
}

fn parse_budget_scale(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_normal() && x > 0.0 && x <= 1e9 => Ok(x),
        _ => Err(format!(
            "--budget-scale {}: expected a number in (0, 1e9]",
            crate::format::clip(text, crate::format::SHOWN_CHARS)
        )),
    }
}

impl Cli {
    /// The budget the flags ask for; None without one.
    pub(crate) fn budget(&self) -> Option<Budget> {
        (!self.no_budget).then(|| Budget::scaled(self.budget_scale.unwrap_or(1.0)))
    }
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Print the default case (the paper's) as commented TOML, or with --new-pair a case
    /// whose bores, masses and inertias follow the geometry.
    Config(ConfigArgs),
    /// Mesh stiffness (potential energy method), ISO 6336 check, load sharing, static TE.
    Stiffness(StiffnessArgs),
    /// One steady-state evaluation of the 8-DOF tribo-dynamic model.
    Dynamics(DynamicsArgs),
    /// One record of what a sensor sees: housing accelerations at named sensors and a
    /// tachometer, with condition indicators and figures.
    Signals(SignalsArgs),
    /// A labelled dataset from a study design: run-to-failure states, fault conditions,
    /// speeds, loads and noise realisations, one record each (shardable, resumable).
    Dataset(DatasetArgs),
    /// Join the shards of a dataset into one, with its index and metadata.
    DatasetMerge(DatasetMergeArgs),
    /// The coupled dynamics-wear study (and its quasi-static twin).
    Wear(WearArgs),
    /// The paper's section 4 study on the case, with a self-contained HTML report (the main job).
    Run(RunArgs),
    /// Run the cross product of varied keys (in parallel; resumable; shardable).
    Sweep(SweepArgs),
    /// Join the tables of sweep shards into one, sorted by case id.
    SweepMerge(SweepMergeArgs),
    /// Posterior of the wear coefficient (and optionally roughness factor, load torque)
    /// given observations of a running gearbox.
    Calibrate(CalibrateArgs),
    /// Monte Carlo prediction of wear, vibration indicators and remaining life.
    Predict(PredictArgs),
    /// Join the shards of a sharded `predict` and write its outputs.
    PredictMerge(PredictMergeArgs),
    /// The load spectrum of a measured torque / speed history (time at level, ISO 6336-6),
    /// for a case's [load_spectrum], with the time-at-level histogram.
    LoadSpectrum(LoadSpectrumArgs),
}

#[derive(Debug, Args)]
pub(crate) struct ConfigArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Print the key reference as Markdown (docs/CONFIG.md) instead.
    #[arg(long, conflicts_with = "new_pair")]
    pub(crate) markdown: bool,
    /// Print a starting case for a pair of one's own: hub bores, masses and inertias of
    /// pinion and gear set to "derived", so they follow the [gear] section.
    #[arg(long)]
    pub(crate) new_pair: bool,
}

#[derive(Debug, Args)]
pub(crate) struct StiffnessArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Output directory.
    #[arg(long, default_value = "results/stiffness")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct DynamicsArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Geometric transmission error to add: CSV `pinion_angle_deg,error_um` over one mesh
    /// period (positive adds to the mesh compression, paper eq. 2).
    #[arg(long, value_name = "FILE")]
    pub(crate) transmission_error: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "results/dynamics")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum WearModeArg {
    Dynamic,
    QuasiStatic,
    Both,
}

#[derive(Debug, Args)]
pub(crate) struct WearArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Which solver feeds the wear model.
    #[arg(long, value_enum, default_value = "both")]
    pub(crate) mode: WearModeArg,
    /// Output directory.
    #[arg(long, default_value = "results/wear")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
    /// Continue from the checkpoints in the output directory.
    #[arg(long)]
    pub(crate) resume: bool,
}

#[derive(Debug, Args)]
pub(crate) struct RunArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Output directory.
    #[arg(long, default_value = "results")]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
    /// Continue the wear studies from the checkpoints in the output directory.
    #[arg(long)]
    pub(crate) resume: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum SweepRunArg {
    Dynamics,
    Wear,
}

/// `--continuation`: which solution branches a one-parameter sweep follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum ContinuationArg {
    Up,
    Down,
    Both,
}

#[derive(Debug, Args)]
pub(crate) struct SweepArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// A varied key: KEY=START:STOP:STEP (STOP included when the range lands on it) or
    /// KEY=v1,v2,... (repeatable; the first --vary varies slowest).
    #[arg(
        long = "vary",
        value_name = "KEY=START:STOP:STEP|KEY=V1,V2,...",
        required = true
    )]
    pub(crate) vary: Vec<String>,
    /// What each case runs: one dynamic evaluation, or the wear study (both modes).
    #[arg(long, value_enum, default_value = "dynamics")]
    pub(crate) run: SweepRunArg,
    /// Output directory (cases/<case_id>.json, sweep.csv, sweep.json, sweep.png).
    #[arg(long, default_value = "results/sweep")]
    pub(crate) out: PathBuf,
    /// Run only shard I of N (1-based; round-robin: case ids with id mod N = I-1);
    /// outputs are then named sweep_shard_I_of_N.*.
    #[arg(long, value_name = "I/N")]
    pub(crate) shard: Option<String>,
    /// Follow solution branches: run the single --vary axis in order (up: rising values,
    /// down: falling, both: the two branches), each point started from the periodic state
    /// of the point before; sweep.csv gets a `branch` column. One --vary, --run dynamics,
    /// no --shard.
    #[arg(long, value_enum, value_name = "BRANCHES")]
    pub(crate) continuation: Option<ContinuationArg>,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct SweepMergeArgs {
    /// Sweep output directories (their sweep.csv and sweep_shard_*_of_*.csv) or CSV files.
    #[arg(required = true, value_name = "DIR_OR_CSV")]
    pub(crate) inputs: Vec<PathBuf>,
    /// Output directory (writes sweep.csv there), or a .csv file path.
    #[arg(long)]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct CalibrateArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Observations CSV: `cycles`, observed quantities (names of the updates CSV, or condition indicators such as `input_rms`), optional
    /// `sigma_<name>` columns (docs/PROGNOSTICS.md).
    #[arg(long, value_name = "FILE")]
    pub(crate) observations: PathBuf,
    /// Output directory.
    #[arg(long, default_value = "results/calibrate")]
    pub(crate) out: PathBuf,
    /// Seed of every random draw: a whole number in [0, 2^53].
    #[arg(long, default_value_t = 1, value_parser = seed_arg)]
    pub(crate) seed: u64,
    /// Posterior samples to write.
    #[arg(long, default_value_t = 2000)]
    pub(crate) samples: usize,
    /// Walkers of the ensemble sampler (three parameters).
    #[arg(long, default_value_t = 32)]
    pub(crate) walkers: usize,
    /// Steps of the ensemble sampler (the first half is burn-in).
    #[arg(long, default_value_t = 2000)]
    pub(crate) steps: usize,
    /// True wear runs to check the surrogate against (at the posterior's 5/50/95 %).
    #[arg(long, default_value_t = 3)]
    pub(crate) check_runs: usize,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum ForwardArg {
    /// Reference runs and the k x N invariance (fast).
    Surrogate,
    /// One true wear study per sample (slow; shard it).
    Exact,
}

#[derive(Debug, Args)]
pub(crate) struct PredictArgs {
    #[command(flatten)]
    pub(crate) case: CaseArgs,
    /// Posterior samples CSV (from `calibrate`); omitted: sample the case's prior.
    #[arg(long, value_name = "FILE")]
    pub(crate) posterior: Option<PathBuf>,
    /// Wear limit on the maximum pinion wear depth, um.
    #[arg(long, value_name = "L")]
    pub(crate) limit_um: f64,
    /// Horizon, pinion cycles.
    #[arg(long, value_name = "N")]
    pub(crate) cycles: f64,
    /// Output directory.
    #[arg(long, default_value = "results/predict")]
    pub(crate) out: PathBuf,
    /// Seed of every random draw: a whole number in [0, 2^53].
    #[arg(long, default_value_t = 1, value_parser = seed_arg)]
    pub(crate) seed: u64,
    /// Ensemble size (default: every posterior row, or 2000 prior draws); with a posterior
    /// of another size its rows are drawn with replacement.
    #[arg(long)]
    pub(crate) samples: Option<usize>,
    /// Cycle counts of the fan charts, from 0 to N.
    #[arg(long, default_value_t = 101)]
    pub(crate) grid_points: usize,
    /// Forward model.
    #[arg(long, value_enum, default_value = "surrogate")]
    pub(crate) forward: ForwardArg,
    /// Run only shard I of N (samples with index mod N = I-1); then join with predict-merge.
    #[arg(long, value_name = "I/N")]
    pub(crate) shard: Option<String>,
    /// True wear runs to check the surrogate against (at the 5/50/95 % of the life).
    #[arg(long, default_value_t = 3)]
    pub(crate) check_runs: usize,
    /// A future duty: a TOML file holding a [load_spectrum] section (as a case file spells
    /// it) that replaces the case's duty from --future-from-cycles on.
    #[arg(long, value_name = "FILE")]
    pub(crate) future_spectrum: Option<PathBuf>,
    /// Pinion cycles from new teeth at which the future spectrum takes over (required
    /// with --future-spectrum), in [0, --cycles).
    #[arg(long, value_name = "N")]
    pub(crate) future_from_cycles: Option<f64>,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Args)]
pub(crate) struct PredictMergeArgs {
    /// Shard files (predict_shard_I_of_N.json) or directories holding them.
    #[arg(required = true, value_name = "DIR_OR_JSON")]
    pub(crate) inputs: Vec<PathBuf>,
    /// Output directory.
    #[arg(long)]
    pub(crate) out: PathBuf,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum InterpolationArg {
    /// Piecewise linear between samples (a ramp counts exactly).
    Linear,
    /// Each sample held until the next (a logger's sample-and-hold).
    Hold,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum LevelArg {
    /// Revolution-weighted mean torque of the cell (keeps the cell's wear).
    Mean,
    /// Upper edge of the torque class (conservative rating).
    Upper,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum ShaftArg {
    Pinion,
    Gear,
}

#[derive(Debug, Args)]
pub(crate) struct LoadSpectrumArgs {
    /// CSV with columns time_s (s), torque_nm (N m) and input_speed_hz (Hz) or
    /// input_speed_rpm (rpm); other columns are ignored.
    #[arg(long, value_name = "CSV")]
    pub(crate) history: PathBuf,
    /// Output directory: spectrum.csv (for load_spectrum.file), load_spectrum.toml (the
    /// section to paste into a case), ldd.csv, the figures and summary.json.
    #[arg(long, default_value = "results/load-spectrum")]
    pub(crate) out: PathBuf,
    /// Equal torque classes over [0, max torque].
    #[arg(long, default_value_t = 10)]
    pub(crate) torque_classes: usize,
    /// Equal speed classes over [0, max speed].
    #[arg(long, default_value_t = 5)]
    pub(crate) speed_classes: usize,
    /// How the history runs between samples.
    #[arg(long, value_enum, default_value = "linear")]
    pub(crate) interpolation: InterpolationArg,
    /// The torque each bin gets.
    #[arg(long, value_enum, default_value = "mean")]
    pub(crate) level: LevelArg,
    /// Shaft the torque was measured on.
    #[arg(long, value_enum, default_value = "pinion")]
    pub(crate) torque_shaft: ShaftArg,
    /// Longest interval accepted between samples, in median intervals (longer: a gap,
    /// an error).
    #[arg(long, default_value_t = 10.0)]
    pub(crate) gap_factor: f64,
    /// Merge bins with less than this share of the revolutions (0.001: 0.1 %) into their
    /// nearest bin, keeping the revolutions, the time and the torque-revolution integral
    /// (the quasi-static wear); 0 keeps every bin.
    #[arg(long, allow_negative_numbers = true, default_value_t = crate::config::spectrum_merge::DEFAULT_MERGE_SHARE)]
    pub(crate) merge_below_share: f64,
    #[command(flatten)]
    pub(crate) figures: FigureArgs,
}

/// `--seed`: a whole number in [0, 2^53], as an integer or a whole float
/// (`gearwear::rng::parse_seed` names the flag, the value and the range).
fn seed_arg(text: &str) -> Result<u64, crate::rng::SeedError> {
    crate::rng::parse_seed("--seed", text)
}
