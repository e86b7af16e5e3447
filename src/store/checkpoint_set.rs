//! The checkpoint logs of a study's wear runs, one per mode, appended to after every
//! update while the runs go on in parallel (the wear commands and the Python binding
//! share it).

use super::checkpoint::CheckpointLog;
use crate::io::{OutputDir, OutputError};
use crate::remedy::{Arg, Problem, Remedy, Words};
use crate::study::wear_loop::{WearMode, WearRun};
use std::sync::Mutex;

/// One append-only checkpoint log per wear mode, in an output set's state files.
pub struct CheckpointSet {
    logs: Vec<(WearMode, Mutex<CheckpointLog>)>,
}

impl CheckpointSet {
    /// Start the log of every run in `out`: a fresh run, or one resumed with the records
    /// it was loaded with (written into a new file: see `checkpoint.rs`).
    pub fn open(
        out: &mut OutputDir,
        runs: &[&WearRun],
        case_sha256: &str,
    ) -> Result<Self, OutputError> {
        let mut logs = Vec::new();
        for run in runs {
            let log = CheckpointLog::create(out, case_sha256, run)?;
            logs.push((run.mode, Mutex::new(log)));
        }
        Ok(Self { logs })
    }

    /// Append the new updates of `run`. A failed write is an `OutputError` inside the
    /// returned error, so callers can tell it from a solver error.
    pub fn record(&self, run: &WearRun) -> anyhow::Result<()> {
        if let Some((_, log)) = self.logs.iter().find(|(m, _)| *m == run.mode) {
            log.lock()
                .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))?
                .append_new(run)?;
        }
        Ok(())
    }
}

/// Where each mode's run starts. Without `resume`, afresh. With it, each mode continues
/// from its checkpoint in `out` (`checkpoint::load_checkpoint`), which must belong to this
/// case and mode, hold a run this model could have produced (`study::wear_check`), and
/// reproduce its last update bit for bit when that update is recomputed; every checkpoint
/// is checked before anything runs. A mode without a checkpoint (or with only its header:
/// killed before its first update) starts afresh, with a note; finding none at all is an
/// error: the user asked to resume something that is not there.
pub(crate) fn starting_runs(
    out: &OutputDir,
    modes: &[WearMode],
    resume: bool,
    case_sha256: &str,
    model: &crate::study::Model,
) -> Result<(Vec<WearRun>, Vec<String>), Problem> {
    use super::checkpoint::{checkpoint_name, load_checkpoint};
    if !resume {
        return Ok((modes.iter().map(|m| WearRun::new(*m)).collect(), Vec::new()));
    }
    let mut runs = Vec::new();
    let mut notes = Vec::new();
    let mut found = false;
    for m in modes {
        let max = crate::study::budget::max_checkpoint_bytes(&model.case, *m);
        match load_checkpoint(out, *m, case_sha256, max).map_err(|e| e.problem())? {
            Some(l) if !l.run.records.is_empty() => {
                let path = out.root().join(&l.rel);
                crate::study::wear_check::verify_resumable(&l.run, model).map_err(|e| {
                    Problem::of(
                        Arg::Resume,
                        format!("{}: {e}; it cannot be resumed", path.display()),
                    )
                    .remedy(Remedy::start_afresh().path(&path))
                })?;
                found = true;
                runs.push(l.run);
            }
            _ => {
                notes.push(format!(
                    "no {} checkpoint: that run starts afresh",
                    m.label()
                ));
                runs.push(WearRun::new(*m));
            }
        }
    }
    if !found {
        let names: Vec<String> = modes.iter().map(|m| checkpoint_name(*m)).collect();
        return Err(Problem::of(
            Arg::Resume,
            format!(
                "no checkpoint to resume from in {} (looked for {} and their .partial files)",
                out.root().display(),
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
            .path(out.root()),
        ));
    }
    Ok((runs, notes))
}
