//! The application layer: one job per study, below both front ends.
//!
//! The command line (`cli`) and the Python binding (`python/src`) do the same studies, so
//! the order of a study's steps lives here once: validate the options, check the run
//! budget, build the model, open the output folder (and resume from it), run the study
//! with progress, checkpoints and cancellation, build the artifacts, publish them. A front
//! end only turns its arguments into a job, hands it an [`Observer`], runs it and
//! presents what comes back (or the [`JobError`], worded with its own names for the
//! arguments: `crate::remedy`).
//!
//! | job | study | returns |
//! |---|---|---|
//! | [`StiffnessJob`] | mesh stiffness, ISO 6336 check, load sharing, static TE | [`Outcome`] |
//! | [`DynamicsJob`] | one steady-state evaluation | [`Outcome`] |
//! | [`WearJob`] | the wear study (dynamic and/or quasi-static), checkpointed | [`Outcome`] |
//! | [`RunJob`] | the paper's section 4 with its report (on a gear train: every stage's) | [`Outcome`] |
//! | [`SweepJob`] | a parameter sweep (in memory, or to a folder: resumable, sharded, or by continuation) | [`SweepOutput`] |
//! | [`SweepMergeJob`] | the tables of sweep shards joined | [`SweepOutput`] |
//! | [`CalibrateJob`] | posterior of the wear coefficient given observations | [`Outcome`] |
//! | [`PredictJob`] | Monte Carlo prediction of wear, vibration and remaining life | [`Outcome`] |
//! | [`PredictMergeJob`] | the shards of a prediction joined | [`Outcome`] |
//! | [`LoadSpectrumJob`] | a measured torque / speed history -> load duration distribution and spectrum | [`Outcome`] |
//! | [`SignalsJob`] | one record of what a sensor sees, its indicators and figures | [`Outcome`] |
//! | [`DatasetJob`] | a labelled dataset from a study design (sharded, resumable) | [`Outcome`] |
//! | [`DatasetMergeJob`] | the shards of a dataset joined | [`Outcome`] |
//!
//! Every job implements [`Job`]: `run(&self, &dyn Observer)`. A job is plain data (its
//! validated case and typed options), `Send + Sync`, so a front end may run it on any
//! thread; `()` is the observer that wants nothing. Publishing is one call,
//! [`publish::publish`], with the folder opened first ([`publish::open`]) so that
//! checkpoints ([`checkpoints`]) and finished sweep cases can be written into it while
//! the study runs.
//!
//! A new study (sensor signals, datasets, duty cycles) adds one module here with its job
//! struct and `impl Job`, and a thin command and Python function that build it; no other
//! job changes.

pub mod budget;
pub mod calibrate;
pub mod checkpoints;
pub mod dataset;
pub mod duty;
pub mod duty_planetary;
pub mod duty_runs;
pub mod duty_train;
pub mod dynamics;
pub mod error;
pub mod inputs;
pub mod load_spectrum;
pub mod observer;
pub(crate) mod part_checkpoints;
pub(crate) mod planetary_checkpoints;
pub mod predict;
pub mod predict_future;
pub mod predict_merge;
mod predict_train;
pub mod publish;
pub mod run;
pub mod run_helical;
pub mod run_planetary;
pub mod run_train;
pub mod settings;
pub mod signals;
mod signals_planetary;
pub mod stiffness;
pub mod sweep;
pub(crate) mod train_checkpoints;
pub(crate) mod train_prognostics;
pub mod wear;
pub mod wear_planetary;
pub mod wear_runs;
pub mod wear_train;

pub use calibrate::{CalibrateJob, CalibrationOptions};
pub use dataset::{DatasetJob, DatasetMergeJob, DesignSource};
pub use dynamics::{DynamicsJob, TransmissionErrorSource};
pub use error::JobError;
pub use inputs::TableSource;
pub use load_spectrum::LoadSpectrumJob;
pub use observer::{Observer, Task, Unit};
pub use predict::{ForwardModel, PredictJob, PredictOptions};
pub use predict_future::{FutureInput, SpectrumSource};
pub use predict_merge::PredictMergeJob;
pub use run::RunJob;
pub use signals::{SignalsJob, TransferPathSource};
pub use stiffness::StiffnessJob;
pub use sweep::{SweepJob, SweepMergeJob, SweepOutput};
pub use wear::WearJob;

use crate::config::Case;
use crate::report::Artifacts;
use crate::study::Model;
use std::path::PathBuf;

/// A study the front ends run (see the module docs).
pub trait Job: Send + Sync {
    /// What the job hands back.
    type Output: Send + 'static;

    /// The study's name: the command of the command line, `metadata.command` of the
    /// summary.
    fn name(&self) -> &'static str;

    /// Run the study, reporting to `observer`.
    fn run(&self, observer: &dyn Observer) -> Result<Self::Output, JobError>;
}

/// What a job hands back: its artifacts (summary, tables, figures, documents, headline),
/// where they were published, and whether the result is incomplete.
pub struct Outcome {
    /// The summary, tables, figures, documents and headline of the study.
    pub artifacts: Artifacts,
    /// The output folder, when the job was given one.
    pub published: Option<PathBuf>,
    /// A failure found after the outputs were written: a wear run the solver gave up on,
    /// sweep cases that failed. The outputs hold everything up to it; the command line
    /// exits 1.
    pub incomplete: Option<String>,
}

/// Every output of a job holds an [`Outcome`].
impl AsRef<Outcome> for Outcome {
    fn as_ref(&self) -> &Outcome {
        self
    }
}

/// Build the model of `case`; geometry problems are input errors, the model's warnings go
/// to `observer`. A study that takes a single pair only refuses a gear train
/// (`[[stage]]`) here, before any work.
pub fn build_model(case: &Case, observer: &dyn Observer) -> Result<Model, JobError> {
    refuse_train(case)?;
    build_train_model(case, observer)
}

/// The refusal of a gear train (`[[stage]]`) by a study that takes a single pair only:
/// called first, before the budget check (whose estimate is the single pair's).
pub fn refuse_train(case: &Case) -> Result<(), JobError> {
    if case.stage.is_empty() {
        return Ok(());
    }
    Err(JobError::input(crate::remedy::Problem::new(
        TRAIN_STUDIES.to_owned(),
    )))
}

/// What a study that takes a single pair says of a gear train.
pub const TRAIN_STUDIES: &str = "this case is a gear train ([[stage]] tables): on a train, `gearwear dynamics`, `gearwear stiffness`, `gearwear wear`, `gearwear signals`, `gearwear dataset`, `gearwear run`, `gearwear sweep` (of dynamics or wear), `gearwear calibrate` and `gearwear predict` run so far; this study takes a single pair ([gear], without [[stage]])";

/// As [`build_model`], for the studies that take a gear train as well as a single pair.
pub fn build_train_model(case: &Case, observer: &dyn Observer) -> Result<Model, JobError> {
    let m = Model::from_case(case)?;
    for w in &m.warnings {
        observer.warning(w);
    }
    Ok(m)
}

/// As [`build_train_model`], a single helical pair on its planar model with its wear per
/// slice (`Model::wear_study_from_case`, docs/MODEL.md 11.9): for `gearwear calibrate` and
/// `gearwear predict` (`study` names them in a refusal).
pub fn build_wear_study_model(
    case: &Case,
    study: &str,
    observer: &dyn Observer,
) -> Result<Model, JobError> {
    let m = Model::wear_study_from_case(case, study)?;
    for w in &m.warnings {
        observer.warning(w);
    }
    Ok(m)
}

/// As [`build_train_model`] for the wear of a gear train at one operating point
/// (`gearwear wear`, `gearwear run`): a stage's tooth fault taken
/// (`Model::train_wear_from_case`).
pub fn build_train_wear_model(case: &Case, observer: &dyn Observer) -> Result<Model, JobError> {
    let m = Model::train_wear_from_case(case)?;
    for w in &m.warnings {
        observer.warning(w);
    }
    Ok(m)
}

/// As [`build_train_model`], with a helical pair's planar model
/// (`Model::helical_from_case`) where the case has a helix angle: for the studies that
/// take a helical pair through the same solver (`dynamics`, `signals`, `wear`).
pub fn build_dynamics_model(case: &Case, observer: &dyn Observer) -> Result<Model, JobError> {
    let m = Model::dynamics_from_case(case)?;
    for w in &m.warnings {
        observer.warning(w);
    }
    Ok(m)
}

/// The model, the dynamic system built from it and the jobs are shared across threads;
/// this fails to compile if one of them stops being `Send + Sync` (for instance a solver
/// type that gains a `Cell`).
#[allow(dead_code)]
const fn assert_send_sync<T: Send + Sync + ?Sized>() {}
const _: () = {
    assert_send_sync::<Model>();
    assert_send_sync::<crate::dynamics::model::GearSystem<'static>>();
    assert_send_sync::<StiffnessJob>();
    assert_send_sync::<DynamicsJob>();
    assert_send_sync::<WearJob>();
    assert_send_sync::<RunJob>();
    assert_send_sync::<SweepJob>();
    assert_send_sync::<SweepMergeJob>();
    assert_send_sync::<CalibrateJob>();
    assert_send_sync::<PredictJob>();
    assert_send_sync::<PredictMergeJob>();
    assert_send_sync::<SignalsJob>();
    assert_send_sync::<DatasetJob>();
    assert_send_sync::<DatasetMergeJob>();
};
