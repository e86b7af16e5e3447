//! The run budget: before any work starts, estimate a run's memory and time from its case
//! and its inputs, and refuse a run over budget (issue 13). The whole cost model is here,
//! one module per job family:
//! - [`cost`]: what an estimate is (terms of time and memory with the keys that drive
//!   them), the budget, and the check whose message names what drives the cost;
//! - [`evaluation`]: the reference machine's rates and the counts every estimate is built
//!   from (steps of a dynamic evaluation, wear per cycle, updates of a wear study);
//! - [`case_jobs`]: `stiffness`, `dynamics`, `wear`, `run` and one case of a sweep (the
//!   formulas), and the most a wear checkpoint can hold;
//! - [`steady_states`]: the time of their dynamic evaluations, cold and warm;
//! - [`teeth`]: what a tooth-resolved case adds to them;
//! - [`helical`]: what a helical pair's wear per slice adds to `wear`;
//! - [`sweep`]: `sweep` (sampled, not case by case) and `sweep-merge`;
//! - [`signals`], [`dataset`], [`load_spectrum`]: those commands;
//! - [`prognostics`]: `calibrate`, `predict` and `predict-merge`;
//! - [`output`]: the process's start-up, and the tables and figures of `stiffness`.
//!
//! The model imports nothing above `study`: what prognostics knows (the span of the
//! parameters) is handed down as numbers. The job layer refuses a job over budget before
//! anything is computed and adds the remedy, worded for the front ends (`app::budget`).
//!
//! # Default budget
//!
//! [`Budget::DEFAULT`]: 2 GiB of memory and 600 s (10 minutes) of computing on one core of
//! the reference machine. `--budget-scale X` multiplies both; `--no-budget` drops the
//! check. A sweep checks each case against the budget (its number of cases is the user's
//! explicit choice; it is resumable and shardable).

pub mod case_jobs;
pub mod chains;
pub mod cost;
pub mod dataset;
pub mod evaluation;
pub mod figures;
pub mod helical;
pub mod load_spectrum;
pub mod output;
pub mod planetary;
pub mod prognostics;
pub mod running_in;
pub mod signals;
pub mod steady_states;
pub mod sweep;
pub mod teeth;
pub mod train_prognostics;

pub use case_jobs::{
    estimate, max_checkpoint_bytes, Job, BYTES_PER_SAMPLE, OUTPUT_BYTES_PER_PROFILE_POINT,
    OUTPUT_SECONDS_PER_PROFILE_POINT,
};
pub use cost::{Budget, Estimate, FigureCount, FigureLoad, Term};
pub use dataset::{
    estimate_dataset, estimate_dataset_check, estimate_dataset_resumed, estimate_folder_check,
    trajectory_bytes, KeptRecords, RecordSize,
};
pub use evaluation::{
    adaptive_steps_per_period, nominal_member_wear_per_cycle_m, nominal_wear_per_cycle_m,
    wear_updates, ADAPTIVE_STEPS_AT_DEFAULT_TOLERANCE, DYNAMIC_WEAR_FACTOR,
    PERIODS_TO_SETTLE_PER_DECADE, SECONDS_PER_QUASI_STATIC_STEP, SECONDS_PER_STEP,
    SECONDS_PER_TABLE_POINT,
};
pub use load_spectrum::estimate_history;
pub use prognostics::{estimate_calibration, estimate_merge, CalibrationJob, ParameterSpan};
pub(crate) use prognostics::{estimate_prediction, PredictionJob};
pub use signals::estimate_signals;
pub(crate) use sweep::estimate_sweep;
pub use sweep::{estimate_sweep_merge, BYTES_PER_SWEEP_CASE, SAMPLED_VALUES};
pub use teeth::{excitation_periods_of, RESPONSE_BYTES_PER_SAMPLE};
