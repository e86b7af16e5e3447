//! Where each wear run of a job starts (afresh, or resumed from its checkpoint, checked
//! before anything is computed), and the checkpoint logs appended to after every update.

use super::observer::Observer;
use super::JobError;
use crate::io::checkpoint::{checkpoint_name, load_checkpoint, LoadedCheckpoint};
use crate::io::checkpoint_set::CheckpointSet;
use crate::io::OutputDir;
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::wear_check::check_wear_run;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use std::path::Path;

/// The start of one mode's run.
pub struct Start {
    pub run: WearRun,
    loaded: Option<LoadedCheckpoint>,
}

/// The starting runs of `modes`. Resuming (`resume_from`: the output folder), each mode
/// continues from its checkpoint there, which must belong to this case and mode and hold
/// a run this model could have produced (`study::wear_check`); every checkpoint is checked
/// before anything runs. A mode without a checkpoint (or with only its header: killed
/// before its first update) starts afresh, but finding none at all is an error: the user
/// asked to resume something that is not there.
pub fn starting_runs(
    modes: &[WearMode],
    resume_from: Option<&Path>,
    case_sha256: &str,
    model: &Model,
    observer: &dyn Observer,
) -> Result<Vec<Start>, JobError> {
    let fresh = |m: WearMode| Start {
        run: WearRun::new(m),
        loaded: None,
    };
    let Some(dir) = resume_from else {
        return Ok(modes.iter().map(|m| fresh(*m)).collect());
    };
    let mut starts = Vec::new();
    for m in modes {
        let path = dir.join(checkpoint_name(*m));
        match load_checkpoint(&path, *m, case_sha256)? {
            Some(l) if !l.run.records.is_empty() => {
                check_wear_run(&l.run, model).map_err(|e| {
                    Problem::of(
                        Arg::Resume,
                        format!("{}: {e}; it cannot be resumed", path.display()),
                    )
                    .remedy(Remedy::start_afresh().path(&path))
                })?;
                starts.push(Start {
                    run: l.run.clone(),
                    loaded: Some(l),
                });
            }
            _ => starts.push(fresh(*m)),
        }
    }
    if starts.iter().all(|s| s.loaded.is_none()) {
        let names: Vec<String> = modes.iter().map(|m| checkpoint_name(*m)).collect();
        return Err(Problem::of(
            Arg::Resume,
            format!(
                "no checkpoint to resume from in {} (looked for {})",
                dir.display(),
                names.join(", ")
            ),
        )
        .remedy(
            Remedy::new(
                Words::new()
                    .text("run without ")
                    .arg(Arg::Resume)
                    .text(" to start afresh"),
            )
            .path(dir),
        )
        .into());
    }
    for s in starts.iter().filter(|s| s.loaded.is_none()) {
        observer.note(&format!(
            "note: no {} checkpoint: that run starts afresh",
            s.run.mode.label()
        ));
    }
    Ok(starts)
}

/// The checkpoint logs of the runs that start at `starts`, in `out`.
pub fn open_checkpoints(
    out: &mut OutputDir,
    starts: &[Start],
    case_sha256: &str,
) -> Result<CheckpointSet, JobError> {
    let runs: Vec<_> = starts.iter().map(|s| (&s.run, s.loaded.as_ref())).collect();
    Ok(CheckpointSet::open(out, &runs, case_sha256)?)
}
