//! Where each wear run of a command starts (afresh, or with `--resume` from its
//! checkpoint, checked before anything is computed), and the checkpoint logs appended to
//! after every update.

use super::CliError;
use crate::io::checkpoint::{checkpoint_name, load_checkpoint, CheckpointLog, LoadedCheckpoint};
use crate::io::OutputDir;
use crate::study::wear_check::check_wear_run;
use crate::study::wear_loop::{WearMode, WearRun};
use crate::study::Model;
use std::path::Path;
use std::sync::Mutex;

/// The start of one mode's run.
pub struct Start {
    pub run: WearRun,
    loaded: Option<LoadedCheckpoint>,
}

/// The starting runs of `modes`. With `resume`, each mode continues from its checkpoint in
/// `dir`, which must belong to this case and mode and hold a run this model could have
/// produced (`study::wear_check`); every checkpoint is checked before anything runs. A
/// mode without a checkpoint (or with only its header: killed before its first update)
/// starts afresh, but finding none at all is an error: the user asked to resume something
/// that is not there.
pub fn starting_runs(
    dir: &Path,
    modes: &[WearMode],
    resume: bool,
    case_sha256: &str,
    model: &Model,
) -> Result<Vec<Start>, CliError> {
    let fresh = |m: WearMode| Start {
        run: WearRun::new(m),
        loaded: None,
    };
    if !resume {
        return Ok(modes.iter().map(|m| fresh(*m)).collect());
    }
    let mut starts = Vec::new();
    for m in modes {
        let path = dir.join(checkpoint_name(*m));
        match load_checkpoint(&path, *m, case_sha256)? {
            Some(l) if !l.run.records.is_empty() => {
                check_wear_run(&l.run, model).map_err(|e| {
                    CliError::input(format!(
                        "--resume: {}: {e}; it cannot be resumed: rerun without --resume",
                        path.display()
                    ))
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
        return Err(CliError::input(format!(
            "--resume: no checkpoint to resume from in {} (looked for {}); run without --resume to start afresh",
            dir.display(),
            names.join(", ")
        )));
    }
    for s in starts.iter().filter(|s| s.loaded.is_none()) {
        eprintln!(
            "note: no {} checkpoint: that run starts afresh",
            s.run.mode.label()
        );
    }
    Ok(starts)
}

/// The checkpoint logs of a command's runs, one per mode.
pub struct Checkpoints {
    logs: Vec<(WearMode, Mutex<CheckpointLog>)>,
}

impl Checkpoints {
    /// Open (resumed) or start (fresh) the checkpoint of every start in `out`.
    pub fn open(
        out: &mut OutputDir,
        starts: &[Start],
        case_sha256: &str,
    ) -> Result<Self, CliError> {
        let mut logs = Vec::new();
        for s in starts {
            let path = out.state_path(&checkpoint_name(s.run.mode))?;
            let log = match &s.loaded {
                Some(l) => CheckpointLog::resume(&path, l)?,
                None => CheckpointLog::create(&path, case_sha256, &s.run)?,
            };
            logs.push((s.run.mode, Mutex::new(log)));
        }
        Ok(Self { logs })
    }

    /// Append the new updates of `run`.
    pub fn record(&self, run: &WearRun) -> anyhow::Result<()> {
        if let Some((_, log)) = self.logs.iter().find(|(m, _)| *m == run.mode) {
            log.lock()
                .map_err(|_| anyhow::anyhow!("checkpoint writer poisoned"))?
                .append_new(run)?;
        }
        Ok(())
    }
}
