//! What a job tells its caller while it runs, and how the caller stops it: one trait,
//! [`Observer`], every method with a default that does nothing, and `()` as the observer
//! that wants nothing (as rapier's `EventHandler` with `()`). The command line draws
//! progress bars and prints warnings to standard error (`cli::progress`); the Python
//! binding sends progress to a callback, turns warnings into `GearwearWarning`s and asks
//! a job to stop on Ctrl-C.
//!
//! Every method may be called from any thread of the job (the wear runs of a study and
//! the cases of a sweep run in parallel), hence `Sync`.

use std::path::Path;

/// A counted part of a job: the wear run of one mode (in load cycles), the cases of a
/// sweep, the reference runs of a surrogate, the samples of a prediction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Task {
    /// Stable name for programs: `dynamic`, `quasi_static`, `sweep`, `reference_runs`,
    /// `posterior`, `samples`, `check_runs`.
    pub id: &'static str,
    /// Short words for people: `quasi-static`, `sweep cases`, `reference runs`.
    pub label: &'static str,
    /// Units of work in all.
    pub total: f64,
    /// What a unit is.
    pub unit: Unit,
}

/// The unit of a task's progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// Pinion load cycles (a wear run).
    Cycles,
    /// Whole items (cases, runs, samples, sampler steps).
    Items,
}

impl Task {
    /// A task of `total` items.
    pub fn items(id: &'static str, label: &'static str, total: usize) -> Self {
        Self {
            id,
            label,
            total: total as f64,
            unit: Unit::Items,
        }
    }
}

/// See the module docs.
pub trait Observer: Sync {
    /// A task starts.
    fn start(&self, _task: &Task) {}

    /// A task has done `done` of its total units; `status` says where it stands ("3
    /// updates, max pinion wear 0.512 um"), or is empty.
    fn advance(&self, _task: &Task, _done: f64, _status: &str) {}

    /// A task ended (finished, or the job stopped).
    fn finish(&self, _task: &Task) {}

    /// A line about what the job does ("sweep: 10 cases in all, ...").
    fn note(&self, _text: &str) {}

    /// A finding that does not stop the job (undercut, a formula outside its fitted
    /// range, a wear run that stopped early, an unmixed sampler).
    fn warning(&self, _text: &str) {}

    /// The state of a long job was saved at `path` (a wear run's checkpoint after an
    /// update, a finished sweep case): what an interrupted run resumes from.
    fn checkpoint(&self, _path: &Path) {}

    /// Whether the job should stop at its next chance (asked after every wear update,
    /// before every sweep case and prediction sample); it then ends with
    /// `JobError::Cancelled`.
    fn cancelled(&self) -> bool {
        false
    }
}

/// The observer that wants nothing.
impl Observer for () {}

/// Ask `observer` whether to stop; an error to return from a study's callback if so.
pub fn keep_going(observer: &dyn Observer) -> anyhow::Result<()> {
    if observer.cancelled() {
        Err(super::error::Cancelled.into())
    } else {
        Ok(())
    }
}
