//! Parameter sweeps: the cross product of varied keys over a base case, run case by case,
//! each case reduced to one row of headline results.
//!
//! Pieces: [`plan`] (axes with typed values, case ids, shards), [`case_run`] (one case ->
//! one row of [`CaseResults`]), [`case_record`] (the record it leaves on disk so a rerun
//! can skip it), [`continuation`] (a one-axis sweep run in order, each point warm-started
//! from the previous one), [`mesh_row`] (the columns of each mesh of a gear train),
//! [`helical_row`] (the columns a helical pair adds), [`planetary_row`] (those of each
//! mesh and planet of a planetary set; [`planetary_wear_row`] its wear row),
//! [`table`] (rows, CSV, merge of shards), [`resonance`] (speeds
//! where a mesh harmonic meets a damped mesh pole). The sweep itself (cases resolved and checked,
//! run in parallel or along branches, in memory or to a folder with its case records,
//! progress) is the job `app::sweep::SweepJob`, the one path of both front ends.

pub mod case_record;
pub mod case_run;
pub mod continuation;
pub mod helical_row;
pub mod mesh_row;
pub mod plan;
pub mod planetary_row;
pub mod planetary_wear_row;
pub mod resonance;
mod row;
pub mod table;
pub mod verify;

pub use case_record::{CaseRecord, ContinuationLink};
pub use case_run::{
    run_case, wear_results, CaseError, CaseOutcome, CaseResults, DynamicsRow, SweepRun, WearEnd,
};
pub use continuation::{Branch, Continuation, ContinuationPlan};
pub use helical_row::HelicalRow;
pub use mesh_row::MeshRow;
pub use plan::{parse_axis, parse_vary, Axis, AxisValue, Shard, SweepPlan};
pub use resonance::{crossings, Crossing};
pub use table::{SweepRow, SweepTable};

/// The varied key of a speed sweep (gets the resonance plot).
pub const SPEED_KEY: &str = "operating.input_speed_hz";
