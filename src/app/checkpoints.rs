//! Where each wear run of a job starts (afresh, or resumed from its checkpoint, checked and
//! recomputed before anything else is computed: `store::checkpoint_set`), and the checkpoint
//! logs appended to after every update.

use super::observer::Observer;
use super::JobError;
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::store::checkpoint_set::CheckpointSet;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use std::path::Path;

/// Resuming needs the output folder to exist (checked before opening it would create it).
pub fn require_folder(out: &Path) -> Result<(), JobError> {
    if out.is_dir() {
        return Ok(());
    }
    Err(Problem::of(
        Arg::Resume,
        format!(
            "no checkpoint to resume from in {}: the folder does not exist",
            out.display()
        ),
    )
    .remedy(
        Remedy::new(
            Words::new()
                .text("run without ")
                .arg(Arg::Resume)
                .text(" to start afresh"),
        )
        .path(out),
    )
    .into())
}

/// The starting runs of `modes`: afresh without `resume` (or without a folder), else each
/// from its checkpoint in `out` (`store::checkpoint_set::starting_runs`: it must belong to
/// this case and mode and reproduce its records when they are recomputed). A mode without
/// a checkpoint starts afresh, with a note to `observer`.
pub fn starting_runs(
    out: Option<&OutputDir>,
    modes: &[WearMode],
    resume: bool,
    case_sha256: &str,
    model: &Model,
    observer: &dyn Observer,
) -> Result<Vec<WearRun>, JobError> {
    let Some(out) = out.filter(|_| resume) else {
        return Ok(modes.iter().map(|m| WearRun::new(*m)).collect());
    };
    let (runs, notes) =
        crate::store::checkpoint_set::starting_runs(out, modes, true, case_sha256, model)?;
    for n in notes {
        observer.note(&format!("note: {n}"));
    }
    Ok(runs)
}

/// The checkpoint logs of the runs that start at `runs`, in `out`.
pub fn open_checkpoints(
    out: &mut OutputDir,
    runs: &[WearRun],
    case_sha256: &str,
) -> Result<CheckpointSet, JobError> {
    let refs: Vec<&WearRun> = runs.iter().collect();
    Ok(CheckpointSet::open(out, &refs, case_sha256)?)
}
