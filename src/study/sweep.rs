//! Parameter sweeps: the cross product of `--vary` axes over a base case, run case by
//! case, each case reduced to one row of headline results.
//!
//! Pieces: [`plan`] (axes, case ids, shards), [`case_run`] (one case -> one row, and the
//! record it leaves on disk so a rerun can skip it), [`continuation`] (a one-axis sweep
//! run in order, each point warm-started from the previous one), [`table`] (rows, CSV,
//! merge of shards), [`resonance`] (speeds where a mesh harmonic meets a damped mesh pole),
//! [`in_memory`] (a whole sweep without files, for the Python binding).
//! File handling, parallelism and progress are the CLI's (`gearwear sweep`).

pub mod case_run;
pub mod continuation;
pub mod in_memory;
pub mod plan;
pub mod resonance;
pub mod table;
pub mod verify;

pub use case_run::{run_case, CaseError, CaseRecord, ContinuationLink, SweepRun};
pub use continuation::{Branch, Continuation, ContinuationPlan};
pub use in_memory::{resolve_cases, run_cases, ResolvedCase, SweepOutcome};
pub use plan::{parse_vary, Axis, Shard, SweepPlan};
pub use resonance::{crossings, Crossing};
pub use table::{SweepRow, SweepTable};

/// The varied key of a speed sweep (gets the resonance plot).
pub const SPEED_KEY: &str = "operating.input_speed_hz";
